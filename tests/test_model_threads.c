/*
 * test_model_threads.c - threads and mc_solve (include/mortarcontact.h, MC_OPTION_THREADS;
 * docs/benchmarks.md, "Threads").
 * - The results do not depend on MC_OPTION_THREADS: a solve and a re-solve with the two bodies
 *   on two threads (the Hertz scene, and long strips whose solve is refined) give the serial solve's displacements, stresses, reactions and contact
 *   results bit for bit when both make their BLAS calls with the same OpenBLAS thread count
 *   (OPENBLAS_NUM_THREADS=1: ctest runs this program once that way), and to round-off otherwise
 *   (OpenBLAS's sums depend on its thread count; with two body threads each body's BLAS calls
 *   get half the cores).
 * - The threads are those the header promises: with MC_OPTION_THREADS = 1 the library starts
 *   none; with 2 exactly one at a time per solve (named "mc-body2"); none is left when mc_solve
 *   returns; automatic stays serial for a small scene; OpenBLAS's thread count is what it was
 *   before the solve.
 * - Two models solved at once from two host threads (each with its own body thread) still match
 *   serial results; the library never oversubscribes: the process runs no threads besides the
 *   host's, the body threads and OpenBLAS's pool (CHOLMOD's fixed 4-thread OpenMP team is kept
 *   at one thread, lib/linalg/sparse_cholesky.cpp).
 * - An error on body 2's thread reaches the caller as a status with the serial message, and the
 *   model stays usable; the log callback is only called from the calling thread, in the serial
 *   order.
 */
#define _GNU_SOURCE
#include "check_helpers.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int openblas_get_num_threads(void); /* OpenBLAS, which the library links (test blas_is_openblas) */
int openblas_get_parallel(void);    /* 0 sequential, 1 pthread build, 2 OpenMP build */

/* ---- threads of this process -------------------------------------------- */

/* Threads of this process, and how many of them carry the name of the library's body thread. */
static int threads_of_this_process(int *body_threads) {
  DIR *dir = opendir("/proc/self/task");
  int n = 0, named = 0;
  for (struct dirent *e; dir && (e = readdir(dir));) {
    if (e->d_name[0] == '.') continue;
    n++;
    char path[320], comm[32] = "";
    snprintf(path, sizeof path, "/proc/self/task/%s/comm", e->d_name);
    FILE *f = fopen(path, "r");
    if (f && fgets(comm, sizeof comm, f) && strncmp(comm, "mc-body2", 8) == 0) named++;
    if (f) fclose(f);
  }
  if (dir) closedir(dir);
  if (body_threads) *body_threads = named;
  return n;
}

typedef struct sampler {
  pthread_t thread;
  atomic_int stop;
  int most, most_body;
} sampler;

static void *sample_threads(void *arg) {
  sampler *s = arg;
  while (!atomic_load(&s->stop)) {
    int body, n = threads_of_this_process(&body);
    if (n > s->most) s->most = n;
    if (body > s->most_body) s->most_body = body;
    usleep(100);
  }
  return NULL;
}

static void sampler_start(sampler *s) {
  s->most = s->most_body = 0;
  atomic_init(&s->stop, 0);
  ck_assert_int_eq(pthread_create(&s->thread, NULL, sample_threads, s), 0);
}

static void sampler_stop(sampler *s) {
  atomic_store(&s->stop, 1);
  pthread_join(s->thread, NULL);
}

/* OpenBLAS's pool: OPENBLAS_NUM_THREADS if set, else the cores this process may run on. */
static int openblas_threads(void) {
  const char *env = getenv("OPENBLAS_NUM_THREADS");
  if (env && atoi(env) > 0) return atoi(env);
  cpu_set_t set;
  return sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : (int)sysconf(_SC_NPROCESSORS_ONLN);
}

/* ---- scenes -------------------------------------------------------------- */

/* Everything a solve gives back, for comparisons. */
typedef struct results {
  mc_status status;
  char message[512];
  mc_int n_contact;
  double *u[2], *stress[2], *reaction[2], *pressure, *gap;
  size_t n_u[2], n_stress[2];
  double energy;
} results;

static void results_free(results *r) {
  for (int b = 0; b < 2; ++b) free(r->u[b]), free(r->stress[b]), free(r->reaction[b]);
  free(r->pressure), free(r->gap);
  memset(r, 0, sizeof *r);
}

static mc_status read_results(mc_model *m, mc_int nodes[2], mc_int cells[2], results *r) {
  mc_status s = MC_OK;
  for (int b = 0; b < 2 && !s; ++b) {
    r->n_u[b] = 2 * (size_t)nodes[b], r->n_stress[b] = 4 * (size_t)cells[b];
    free(r->u[b]), free(r->stress[b]), free(r->reaction[b]);
    r->u[b] = malloc(sizeof(double) * r->n_u[b]), r->reaction[b] = malloc(sizeof(double) * r->n_u[b]);
    r->stress[b] = malloc(sizeof(double) * r->n_stress[b]);
    s = mc_get_displacement(m, b + 1, r->u[b]);
    if (!s) s = mc_get_reaction(m, b + 1, r->reaction[b]);
    if (!s) s = mc_get_stress(m, b + 1, r->stress[b]);
  }
  if (!s) s = mc_get_contact_count(m, &r->n_contact);
  free(r->pressure), free(r->gap);
  r->pressure = malloc(sizeof(double) * (r->n_contact + 1)), r->gap = malloc(sizeof(double) * (r->n_contact + 1));
  if (!s) s = mc_get_contact_pressure(m, r->pressure);
  if (!s) s = mc_get_contact_gap(m, r->gap);
  if (!s) s = mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &r->energy);
  return s;
}

/* The Hertz scene (P1, graded meshes): body 1 the half-disc, held by contact vertically. */
static mc_model *hertz_model(const hertz_scene *scene, int method, int threads) {
  mc_model *m = NULL;
  mc_create(&m);
  mc_status s = MC_OK;
  for (int b = 0; b < 2 && !s; ++b) {
    s = mc_set_mesh(m, b + 1, scene->body[b].n_nodes, scene->body[b].xy, scene->body[b].n_cells, 3, scene->body[b].cells);
    if (!s) s = mc_set_material(m, b + 1, 1, 0.3);
  }
  double *t = malloc(sizeof(double) * 2 * scene->n_top_edges);
  for (int e = 0; e < scene->n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -0.005;
  if (!s) s = mc_fix(m, 1, scene->n_axis_nodes, scene->axis_nodes, MC_X, NULL);
  if (!s) s = mc_fix(m, 2, scene->n_bottom_nodes, scene->bottom_nodes, MC_XY, NULL);
  if (!s) s = mc_add_traction(m, 1, scene->n_top_edges, scene->top_edges, t);
  if (!s) s = mc_set_contact(m, 1, scene->n_contact_edges[0], scene->contact_edges[0]);
  if (!s) s = mc_set_contact(m, 2, scene->n_contact_edges[1], scene->contact_edges[1]);
  if (!s) s = mc_set_option_int(m, MC_OPTION_METHOD, method);
  if (!s) s = mc_set_option_int(m, MC_OPTION_THREADS, threads);
  free(t);
  ck_assert_msg(s == MC_OK, "%s", mc_errmsg(m));
  return m;
}

typedef struct job {
  double h1;
  int method, threads;
  int resolve;  /* also a re-solve after a load change (results of the re-solve) */
  int nx;       /* the strips' cells along their length (solve_strips; 0: 250) */
  int split;    /* what the strips' log said of the split (note_split_solves) */
  int sparse;   /* Hertz: the sparse interface solver forced, its log read as the strips' */
  int64_t ran;  /* Hertz: MC_INFO_INTERFACE_SOLVER after the (last) solve */
  results r;
} job;

static void note_split_solves(void *user, mc_log_level level, const char *message);

static void *solve_hertz(void *arg) {
  job *j = arg;
  hertz_scene scene;
  j->r.status = MC_ERROR_INTERNAL;
  if (hertz_scene_build(&scene, j->h1, 1.37 * j->h1, 0)) return NULL;
  mc_model *m = hertz_model(&scene, j->method, j->threads);
  if (j->sparse) {
    mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, MC_INTERFACE_SPARSE);
    mc_set_log_callback(m, note_split_solves, &j->split);
  }
  mc_int nodes[2] = {scene.body[0].n_nodes, scene.body[1].n_nodes}, cells[2] = {scene.body[0].n_cells, scene.body[1].n_cells};
  mc_status s = mc_solve(m);
  if (!s && j->resolve) {
    double *t = malloc(sizeof(double) * 2 * scene.n_top_edges);
    for (int e = 0; e < scene.n_top_edges; ++e) t[2 * e] = 0.001, t[2 * e + 1] = -0.008;
    s = mc_clear_loads(m, 1);
    if (!s) s = mc_add_traction(m, 1, scene.n_top_edges, scene.top_edges, t);
    if (!s) s = mc_solve(m);
    free(t);
  }
  if (!s) s = read_results(m, nodes, cells, &j->r);
  if (!s) s = mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &j->ran);
  snprintf(j->r.message, sizeof j->r.message, "%s", mc_errmsg(m));
  j->r.status = s;
  mc_destroy(m);
  hertz_scene_free(&scene);
  return NULL;
}

/* The log's account of the sparse path's split (lib/linalg/subtree_solve.hpp): 1 when its solves
   were split in two halves, 2 when a factorization also ran by halves on two threads. */
static void note_split_solves(void *user, mc_log_level level, const char *message) {
  (void)level;
  int *split = user;
  if (!strstr(message, "solves split in two halves")) return;
  const char *at = strstr(message, " factorizations by halves on 2 threads");
  while (at && at > message && at[-1] >= '0' && at[-1] <= '9') --at;
  const int factorizations = at ? atoi(at) : 0;
  if (*split < (factorizations > 0 ? 2 : 1)) *split = factorizations > 0 ? 2 : 1;
}

/* Two strips in contact along their whole length (bench/long_interface.c, nx = 250): a scene
   whose solve is refined (Model::refine_solution: its recovered gaps, 3e-11 of the largest
   displacement, are above round-off), which adds phases run on both threads. The re-solve
   changes the pressure. At nx = 2500 the sparse path's matrix (61000 unknowns) is ordered in two
   halves and its solves split between two threads (SparseCholesky::solve). */
static void solve_strips(job *j) {
  const int nx = j->nx ? j->nx : 250;
  sc_mesh mesh[2];
  j->r.status = MC_ERROR_INTERNAL;
  if (sc_mesh_rect(&mesh[0], 3, nx, 4, 0, 0, 0.1 * nx, 0.4, 0, 1) ||
      sc_mesh_rect(&mesh[1], 3, (int)lround(1.37 * nx), 4, 0, -0.4, 0.1 * nx, 0.4, 0, 2))
    return;
  mc_model *m = NULL;
  mc_create(&m);
  mc_status s = MC_OK;
  for (int b = 0; b < 2 && !s; ++b) {
    s = sc_set_mesh(m, b + 1, &mesh[b], 0);
    if (!s) s = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  if (!s) s = sc_fix_side(m, 2, &mesh[1], SC_BOTTOM, MC_Y, 0);
  if (!s) s = mc_fix(m, 2, 1, &mesh[1].side_nodes[SC_LEFT][0], MC_X, NULL);
  if (!s) s = mc_fix(m, 1, 1, &mesh[0].side_nodes[SC_LEFT][0], MC_X, NULL);
  const mc_int n_top = mesh[0].n_side_edges[SC_TOP];
  double *p = malloc(sizeof(double) * (size_t)n_top);
  for (mc_int e = 0; e < n_top; ++e) p[e] = 0.01;
  if (!s) s = mc_add_pressure(m, 1, n_top, mesh[0].side_edges[SC_TOP], p);
  if (!s) s = mc_set_contact(m, 1, mesh[0].n_side_edges[SC_BOTTOM], mesh[0].side_edges[SC_BOTTOM]);
  if (!s) s = mc_set_contact(m, 2, mesh[1].n_side_edges[SC_TOP], mesh[1].side_edges[SC_TOP]);
  if (!s) s = mc_set_option_int(m, MC_OPTION_THREADS, j->threads);
  if (!s) s = mc_set_log_callback(m, note_split_solves, &j->split);
  if (!s) s = mc_solve(m);
  if (!s && j->resolve) {
    for (mc_int e = 0; e < n_top; ++e) p[e] = 0.02 + 0.01 * e / n_top;
    s = mc_clear_loads(m, 1);
    if (!s) s = mc_add_pressure(m, 1, n_top, mesh[0].side_edges[SC_TOP], p);
    if (!s) s = mc_solve(m);
  }
  double gap_residual = 1;
  if (!s) s = mc_get_info_real(m, MC_INFO_GAP_RESIDUAL, &gap_residual);
  if (!s && !(gap_residual <= 1e-13)) s = MC_ERROR_INTERNAL;  /* refined to round-off */
  mc_int nodes[2] = {mesh[0].n_nodes, mesh[1].n_nodes}, cells[2] = {mesh[0].n_cells, mesh[1].n_cells};
  if (!s) s = read_results(m, nodes, cells, &j->r);
  snprintf(j->r.message, sizeof j->r.message, "%s (gap residual %g)", mc_errmsg(m), gap_residual);
  j->r.status = s;
  free(p);
  mc_destroy(m);
  sc_mesh_free(&mesh[0]), sc_mesh_free(&mesh[1]);
}

/* Largest |a - b| over the largest |a| (0 if both are zero). */
static double relative_difference(const double *a, const double *b, size_t n) {
  double scale = 0, diff = 0;
  for (size_t i = 0; i < n; ++i) scale = fmax(scale, fabs(a[i])), diff = fmax(diff, fabs(a[i] - b[i]));
  return scale > 0 ? diff / scale : diff;
}

/* With the same BLAS thread count per call (OPENBLAS_NUM_THREADS=1) the results are bit for bit
   the serial ones. Otherwise only OpenBLAS's summation order differs: round-off, far below the
   solver's own tolerance (1e-10). */
static void assert_same_results(const results *serial, const results *threaded, const char *what) {
  const int bitwise = openblas_get_num_threads() == 1;
  const double allowed = bitwise ? 0.0 : 1e-11;
  ck_assert_msg(serial->status == MC_OK, "%s: serial: %s", what, serial->message);
  ck_assert_msg(threaded->status == MC_OK, "%s: threaded: %s", what, threaded->message);
  ck_assert_int_eq(serial->n_contact, threaded->n_contact);
  ck_assert_int_gt(serial->n_contact, 0);
  double pmax = 0;
  for (mc_int i = 0; i < serial->n_contact; ++i) pmax = fmax(pmax, serial->pressure[i]);
  ck_assert(pmax > 0);
  for (int b = 0; b < 2; ++b) {
    ck_assert(serial->n_u[b] == threaded->n_u[b] && serial->n_stress[b] == threaded->n_stress[b]);
    if (bitwise) {
      ck_assert_msg(memcmp(serial->u[b], threaded->u[b], sizeof(double) * serial->n_u[b]) == 0, "%s: body %d u", what, b + 1);
      ck_assert_msg(memcmp(serial->reaction[b], threaded->reaction[b], sizeof(double) * serial->n_u[b]) == 0, "%s: body %d reaction", what, b + 1);
      ck_assert_msg(memcmp(serial->stress[b], threaded->stress[b], sizeof(double) * serial->n_stress[b]) == 0, "%s: body %d stress", what, b + 1);
    } else {
      double du = relative_difference(serial->u[b], threaded->u[b], serial->n_u[b]);
      double ds = relative_difference(serial->stress[b], threaded->stress[b], serial->n_stress[b]);
      printf("%s: body %d: u differs by %.2g, stress by %.2g (relative to the largest)\n", what, b + 1, du, ds);
      ck_assert_msg(du <= allowed && ds <= allowed, "%s: body %d: u differs by %.3g, stress by %.3g (relative)", what, b + 1, du, ds);
    }
  }
  if (bitwise) {
    ck_assert_msg(memcmp(serial->pressure, threaded->pressure, sizeof(double) * serial->n_contact) == 0, "%s: pressure", what);
    ck_assert_msg(memcmp(serial->gap, threaded->gap, sizeof(double) * serial->n_contact) == 0, "%s: gap", what);
    ck_assert_msg(serial->energy == threaded->energy, "%s: energy %.17g vs %.17g", what, serial->energy, threaded->energy);
  } else {
    for (mc_int i = 0; i < serial->n_contact; ++i)
      ck_assert_msg(fabs(serial->pressure[i] - threaded->pressure[i]) <= allowed * pmax, "%s: node %d: %.17g vs %.17g", what,
                    (int)i, serial->pressure[i], threaded->pressure[i]);
    ck_assert(fabs(serial->energy - threaded->energy) <= allowed * fabs(serial->energy));
  }
}

/* ---- tests ----------------------------------------------------------------- */

START_TEST(results_do_not_depend_on_threads) {
  /* every method, first solve and re-solve, with two body threads against serial */
  for (int method = MC_METHOD_MORTAR; method <= MC_METHOD_NODE_TO_SEGMENT; ++method)
    for (int resolve = 0; resolve <= 1; ++resolve) {
      job serial = {.h1 = 0.014, .method = method, .threads = 1, .resolve = resolve};
      job threaded = {.h1 = 0.014, .method = method, .threads = 2, .resolve = resolve};
      solve_hertz(&serial), solve_hertz(&threaded);
      char what[64];
      snprintf(what, sizeof what, "method %d%s", method, resolve ? ", re-solve" : "");
      assert_same_results(&serial.r, &threaded.r, what);
      results_free(&serial.r), results_free(&threaded.r);
    }
}
END_TEST

START_TEST(refined_results_do_not_depend_on_threads) {
  for (int resolve = 0; resolve <= 1; ++resolve) {
    job serial = {.threads = 1, .resolve = resolve}, threaded = {.threads = 2, .resolve = resolve};
    solve_strips(&serial), solve_strips(&threaded);
    assert_same_results(&serial.r, &threaded.r, resolve ? "refined strips, re-solve" : "refined strips");
    results_free(&serial.r), results_free(&threaded.r);
  }
}
END_TEST

/* The sparse path's solves split by subtrees of the elimination tree: the halves on two threads or
   in turn, the same arithmetic (subtree_solve.hpp); with two threads its factorizations also run
   by halves (cholmod_rowfac on each half's rows, SparseCholesky::factorize_ordered), which
   compute every row as the serial factorization does: the same results, bit for bit. */
START_TEST(split_solves_do_not_depend_on_threads) {
  /* a first solve only: a re-solve here doubled this test's time under the sanitizers (.ci/run);
     re-solves with the split factor, modified in place, are test_interface_solvers'
     load_steps_modify_the_factor_in_place (4001 contact nodes, against a fresh model) */
  job serial = {.threads = 1, .nx = 2500}, threaded = {.threads = 2, .nx = 2500};
  solve_strips(&serial), solve_strips(&threaded);
  /* split solves on both; factorizations by halves with two threads only (the same rows) */
  ck_assert_msg(serial.split == 1 && threaded.split == 2, "the solves were not split as expected (serial %d, threaded %d)",
                serial.split, threaded.split);
  if (serial.r.status == MC_OK) {
    /* and right: under a uniform pressure p the contact pressure is p at every node (a patch
       test, bench/long_interface.c: 8.5e-10 of p at 4001 contact nodes) */
    double worst = 0;
    for (mc_int i = 0; i < serial.r.n_contact; ++i) worst = fmax(worst, fabs(serial.r.pressure[i] - 0.01) / 0.01);
    printf("split strips: contact pressure within %.2g of p at %d nodes\n", worst, (int)serial.r.n_contact);
    ck_assert_msg(worst <= 1e-7, "split strips: contact pressure %.3g of p from p", worst);
  }
  assert_same_results(&serial.r, &threaded.r, "split strips");
  results_free(&serial.r), results_free(&threaded.r);
}
END_TEST

/* The same for a supernodal factor (lib/linalg/supernodal_solve.hpp): Hertz forced onto the
   sparse path, whose H_P CHOLMOD factors supernodal; its solves split by subtrees of the
   supernodal tree on one thread or two, a re-solve through low-rank updates of the factor too. */
START_TEST(split_supernodal_solves_do_not_depend_on_threads) {
  job serial = {.h1 = 0.01, .method = MC_METHOD_MORTAR, .threads = 1, .resolve = 1, .sparse = 1};
  job threaded = serial;
  threaded.threads = 2;
  solve_hertz(&serial), solve_hertz(&threaded);
  ck_assert_msg(serial.r.status == MC_OK && threaded.r.status == MC_OK, "%s / %s", serial.r.message, threaded.r.message);
  ck_assert_msg(serial.split == 1 && threaded.split == 1, "the supernodal solves were not split (serial %d, threaded %d)",
                serial.split, threaded.split);
  /* (the sparse path's own answers: not the condensed path's, which takes over where the sparse
     path's iteration fails) */
  ck_assert_msg(serial.ran == MC_INTERFACE_SPARSE && threaded.ran == MC_INTERFACE_SPARSE,
                "the sparse path handed over (serial ran %d, threaded %d)", (int)serial.ran, (int)threaded.ran);
  assert_same_results(&serial.r, &threaded.r, "split supernodal Hertz");
  /* and right: the condensed path's answer (its own factorizations and solves, CHOLMOD's) */
  job condensed = {.h1 = 0.01, .method = MC_METHOD_MORTAR, .threads = 1, .resolve = 1};
  solve_hertz(&condensed);
  ck_assert_msg(condensed.r.status == MC_OK && condensed.r.n_contact == serial.r.n_contact, "%s", condensed.r.message);
  double pmax = 0, dp = 0;
  for (mc_int i = 0; i < serial.r.n_contact; ++i) pmax = fmax(pmax, fabs(condensed.r.pressure[i]));
  for (mc_int i = 0; i < serial.r.n_contact; ++i) dp = fmax(dp, fabs(serial.r.pressure[i] - condensed.r.pressure[i]) / pmax);
  const double du = relative_difference(serial.r.u[0], condensed.r.u[0], serial.r.n_u[0]);
  printf("split supernodal Hertz (h1 = 0.01, re-solve): the same results on 1 and 2 threads; against the condensed "
         "path: pressure %.2g, body 1's u %.2g (relative)\n", dp, du);
  ck_assert_msg(dp <= 1e-9 && du <= 1e-9, "split supernodal Hertz against the condensed path: pressure %.3g, u %.3g", dp, du);
  results_free(&serial.r), results_free(&threaded.r), results_free(&condensed.r);
}
END_TEST

START_TEST(two_host_threads_match_serial) {
  /* two models from two host threads at once, each with its body thread, against serial solves */
  job serial[2] = {{.h1 = 0.01, .method = MC_METHOD_MORTAR, .threads = 1},
                   {.h1 = 0.014, .method = MC_METHOD_DUAL_MORTAR, .threads = 1, .resolve = 1}};
  job parallel[2] = {serial[0], serial[1]};
  for (int k = 0; k < 2; ++k) solve_hertz(&serial[k]), parallel[k].threads = 2;
  pthread_t threads[2];
  for (int k = 0; k < 2; ++k) ck_assert_int_eq(pthread_create(&threads[k], NULL, solve_hertz, &parallel[k]), 0);
  for (int k = 0; k < 2; ++k) pthread_join(threads[k], NULL);
  for (int k = 0; k < 2; ++k) {
    assert_same_results(&serial[k].r, &parallel[k].r, k ? "model 2" : "model 1");
    results_free(&serial[k].r), results_free(&parallel[k].r);
  }
}
END_TEST

START_TEST(threads_are_those_the_header_promises) {
  const int blas_before = openblas_get_num_threads();
  /* MC_OPTION_THREADS = 1: no thread of the library; 2: one body thread; automatic: none on a
     small scene (the smaller body has fewer than 30000 unknowns: h1 = 0.025, 2000 and 4000), one
     on a larger one (h1 = 0.0045: 45000 and 37000) if this process may run on two cores */
  cpu_set_t set;
  const int cores = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
  const int options[] = {1, 2, 0, 0}, expected[] = {0, 1, 0, cores >= 2};
  const double h1[] = {0.012, 0.012, 0.025, 0.0045};
  for (int k = 0; k < 4; ++k) {
    sampler s;
    sampler_start(&s);
    job j = {.h1 = h1[k], .method = MC_METHOD_MORTAR, .threads = options[k], .resolve = 1};
    solve_hertz(&j);
    sampler_stop(&s);
    ck_assert_msg(j.r.status == MC_OK, "%s", j.r.message);
    printf("MC_OPTION_THREADS %d: at most %d body threads, %d threads in all\n", options[k], s.most_body, s.most);
    ck_assert_msg(s.most_body == expected[k], "MC_OPTION_THREADS %d: %d body threads seen, expected %d", options[k],
                  s.most_body, expected[k]);
    int left;
    threads_of_this_process(&left);
    ck_assert_msg(left == 0, "%d body threads outlived mc_solve", left);
    /* the host's BLAS setting is what it was */
    ck_assert_int_eq(openblas_get_num_threads(), blas_before);
    results_free(&j.r);
  }
}
END_TEST

/* OpenBLAS's process-wide count, as the log callback (on the calling thread) sees it during a
   solve: at the start message, and the least and most at every later one. */
typedef struct blas_seen {
  int at_start, least_after, most_after, messages;
} blas_seen;

static void note_blas_count(void *user, mc_log_level level, const char *message) {
  (void)level;
  blas_seen *seen = user;
  const int n = openblas_get_num_threads();
  if (strstr(message, "solve: start")) {
    seen->at_start = n;
    return;
  }
  seen->least_after = seen->messages ? (n < seen->least_after ? n : seen->least_after) : n;
  seen->most_after = seen->messages ? (n > seen->most_after ? n : seen->most_after) : n;
  seen->messages++;
}

START_TEST(blas_count_is_one_through_a_two_thread_solve) {
  /* The header: an mc_solve on two threads runs OpenBLAS's pthread build at one thread per call
     from its start (its first log message included) to its end (the active-set solve between the
     body phases included), and puts the host's count back before it returns; on one thread it
     never touches the count. */
  const int host = openblas_get_num_threads(), pthread_build = openblas_get_parallel() == 1;
  for (int threads = 1; threads <= 2; ++threads)
    for (int resolve = 0; resolve <= 1; ++resolve) {
      hertz_scene scene;
      ck_assert_int_eq(hertz_scene_build(&scene, 0.012, 1.37 * 0.012, 0), 0);
      mc_model *m = hertz_model(&scene, MC_METHOD_MORTAR, threads);
      blas_seen seen = {0, 0, 0, 0};
      if (resolve) OK(mc_solve(m)); /* then the re-solve is the one watched */
      OK(mc_set_log_callback(m, note_blas_count, &seen));
      if (resolve) {
        const mc_int node = 0;
        const double force[2] = {0.0, -1e-4};
        OK(mc_add_nodal_force(m, 1, 1, &node, force));
      }
      OK(mc_solve(m));
      mc_destroy(m);
      hertz_scene_free(&scene);
      const int inside = threads == 2 && pthread_build ? 1 : host;
      printf("MC_OPTION_THREADS %d, %s: OpenBLAS count %d at the start, %d to %d after (host %d)\n", threads,
             resolve ? "re-solve" : "first solve", seen.at_start, seen.least_after, seen.most_after, host);
      ck_assert_int_ge(seen.messages, resolve ? 4 : 10);
      ck_assert_int_eq(seen.at_start, inside);
      ck_assert_int_eq(seen.least_after, inside);
      ck_assert_int_eq(seen.most_after, inside);
      ck_assert_int_eq(openblas_get_num_threads(), host);
    }
}
END_TEST

START_TEST(threads_stay_within_the_cores) {
  /* One model in this thread, then two models in two host threads, each solving its bodies on
     two threads. Allowed: the threads running now (this one, OpenBLAS's workers if already
     started, a sanitizer's own), or at least this thread and OpenBLAS's workers (its pool minus
     the calling thread); plus the sampler, the host threads and one body thread per solve. */
  const int before = threads_of_this_process(NULL);
  const int running = before > openblas_threads() ? before : openblas_threads();
  for (int hosts = 0; hosts <= 2; hosts += 2) {
    sampler s;
    sampler_start(&s);
    pthread_t threads[2];
    job jobs[2] = {{.h1 = 0.005, .method = MC_METHOD_MORTAR, .threads = 2}, {.h1 = 0.006, .method = MC_METHOD_DUAL_MORTAR, .threads = 2}};
    if (hosts == 0) solve_hertz(&jobs[0]);
    for (int k = 0; k < hosts; ++k) ck_assert_int_eq(pthread_create(&threads[k], NULL, solve_hertz, &jobs[k]), 0);
    for (int k = 0; k < hosts; ++k) pthread_join(threads[k], NULL);
    sampler_stop(&s);
    ck_assert_msg(jobs[0].r.status == MC_OK, "%s", jobs[0].r.message);
    if (hosts) ck_assert_msg(jobs[1].r.status == MC_OK, "%s", jobs[1].r.message);
    const int solves = hosts ? hosts : 1;
    int allowed = running + 1 + hosts + solves;
    printf("host threads %d: at most %d threads seen, %d body threads (allowed %d: OpenBLAS pool of %d)\n", hosts, s.most,
           s.most_body, allowed, openblas_threads());
    ck_assert_msg(s.most <= allowed, "%d threads ran, more than %d", s.most, allowed);
    ck_assert_msg(s.most_body <= solves, "%d body threads for %d solves", s.most_body, solves);
    for (int k = 0; k < 2; ++k) results_free(&jobs[k].r);
  }
}
END_TEST

/* ---- errors and the log on body threads -------------------------------------- */

typedef struct log_record {
  pthread_t caller;
  int other_thread, start_threads;
  char text[8192];
} log_record;

static void record(void *user, mc_log_level level, const char *message) {
  (void)level;
  log_record *r = user;
  if (!pthread_equal(pthread_self(), r->caller)) r->other_thread++;
  if (strstr(message, "solve: start") && strstr(message, "on 2 threads")) r->start_threads = 2;
  /* each message up to its first comma: the phase and its body, not its times */
  size_t used = strlen(r->text), len = strcspn(message, ",");
  if (used + len + 2 < sizeof r->text) memcpy(r->text + used, message, len), memcpy(r->text + used + len, "\n", 2);
}

/* Two unit squares, body 2 clamped at its bottom; body 1 on rollers on its left side. No contact:
   body 1 is then free vertically, which a solve reports (from body 1's work). */
static mc_model *squares(sc_mesh mesh[2], int threads) {
  mc_model *m = NULL;
  OK(mc_create(&m));
  for (int b = 0; b < 2; ++b) {
    ck_assert_int_eq(sc_mesh_rect(&mesh[b], 3, 12, 12, 0, b == 0 ? 0 : -1, 1, 1, 0, 1), 0);
    OK(sc_set_mesh(m, b + 1, &mesh[b], 0));
    OK(mc_set_material(m, b + 1, 1, 0.3));
  }
  OK(sc_fix_side(m, 1, &mesh[0], SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &mesh[1], SC_BOTTOM, MC_XY, 0));
  OK(sc_traction_side(m, 1, &mesh[0], SC_TOP, 0, -0.01, 0));
  OK(mc_set_option_int(m, MC_OPTION_THREADS, threads));
  return m;
}

START_TEST(errors_on_body_threads_reach_the_caller) {
  char messages[2][3][512];
  for (int threads = 1; threads <= 2; ++threads) {
    sc_mesh mesh[2];
    mc_model *m = squares(mesh, threads);
    /* body 1 is not held (no contact): the error comes from body 1's work */
    FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 1 is not held");
    snprintf(messages[threads - 1][0], sizeof messages[0][0], "%s", mc_errmsg(m));
    /* neither body held (body 2's supports go with its new mesh): body 1 is reported, as serially */
    OK(sc_set_mesh(m, 2, &mesh[1], 0));
    OK(mc_set_material(m, 2, 1, 0.3));
    FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 1 is not held");
    snprintf(messages[threads - 1][1], sizeof messages[0][1], "%s", mc_errmsg(m));
    /* only body 2 not held: with two threads the error is raised on body 2's thread */
    OK(sc_fix_side(m, 1, &mesh[0], SC_BOTTOM, MC_Y, 0));
    FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 2 is not held");
    snprintf(messages[threads - 1][2], sizeof messages[0][2], "%s", mc_errmsg(m));
    /* the model is still usable: support body 2, and the solve succeeds */
    OK(sc_fix_side(m, 2, &mesh[1], SC_BOTTOM, MC_XY, 0));
    SUCCEEDS(mc_solve(m));
    double u[2 * 13 * 13];
    OK(mc_get_displacement(m, 1, u));
    ck_assert(u[2 * sc_node(&mesh[0], 12, 12) + 1] < 0);
    mc_destroy(m);
    for (int b = 0; b < 2; ++b) sc_mesh_free(&mesh[b]);
  }
  for (int k = 0; k < 3; ++k) ck_assert_str_eq(messages[0][k], messages[1][k]);
}
END_TEST

START_TEST(log_comes_from_the_calling_thread_in_serial_order) {
  log_record rec[2];
  for (int threads = 1; threads <= 2; ++threads) {
    log_record *r = &rec[threads - 1];
    memset(r, 0, sizeof *r);
    r->caller = pthread_self();
    job j = {.h1 = 0.01, .method = MC_METHOD_MORTAR, .threads = threads};
    hertz_scene scene;
    ck_assert_int_eq(hertz_scene_build(&scene, j.h1, 1.37 * j.h1, 0), 0);
    mc_model *m = hertz_model(&scene, j.method, threads);
    OK(mc_set_log_callback(m, record, r));
    r->start_threads = 0;
    OK(mc_solve(m));
    mc_destroy(m);
    hertz_scene_free(&scene);
    ck_assert_int_eq(r->other_thread, 0);
    ck_assert_int_eq(r->start_threads, threads == 2 ? 2 : 0);
  }
  /* the same messages in the same order (the start message differs after its first comma: it
     names the threads) */
  const char *a = rec[0].text, *b = rec[1].text;
  ck_assert_int_gt((int)strlen(a), 200);
  ck_assert_msg(a && b && strcmp(a, b) == 0, "serial:\n%s\nthreaded:\n%s", rec[0].text, rec[1].text);
}
END_TEST

START_TEST(option_threads_is_checked) {
  mc_model *m = NULL;
  OK(mc_create(&m));
  FAILS(mc_set_option_int(m, MC_OPTION_THREADS, -1), MC_ERROR_ARGUMENT, "MC_OPTION_THREADS");
  FAILS(mc_set_option_int(m, MC_OPTION_THREADS, 1025), MC_ERROR_ARGUMENT, "MC_OPTION_THREADS");
  FAILS(mc_set_option_real(m, MC_OPTION_THREADS, 2.0), MC_ERROR_ARGUMENT, "integer-valued");
  for (int v = 0; v <= 3; ++v) OK(mc_set_option_int(m, MC_OPTION_THREADS, v));
  mc_destroy(m);
}
END_TEST

int main(void) {
  Suite *suite = suite_create("model_threads");
  TCase *tc = tcase_create("threads");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, results_do_not_depend_on_threads);
  tcase_add_test(tc, refined_results_do_not_depend_on_threads);
  tcase_add_test(tc, two_host_threads_match_serial);
  tcase_add_test(tc, threads_are_those_the_header_promises);
  tcase_add_test(tc, split_solves_do_not_depend_on_threads);
  tcase_add_test(tc, split_supernodal_solves_do_not_depend_on_threads);
  tcase_add_test(tc, threads_stay_within_the_cores);
  tcase_add_test(tc, blas_count_is_one_through_a_two_thread_solve);
  tcase_add_test(tc, errors_on_body_threads_reach_the_caller);
  tcase_add_test(tc, log_comes_from_the_calling_thread_in_serial_order);
  tcase_add_test(tc, option_threads_is_checked);
  suite_add_tcase(suite, tc);
  return sc_run_suite(suite);
}
