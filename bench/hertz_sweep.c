/*
 * hertz_sweep.c - speed against error on the Hertz scene (docs/benchmarks.md, issue "Speed").
 *
 * The Hertz scene of examples/scenes/hertz_scene.h (P1, graded meshes, h2 = ratio * h1) is
 * solved at each h1 given, in one child process per (size, case) so that the peak RSS is that
 * case's own. The cases, all on the same meshes:
 *   plain    the two bodies without contact: same load, body 1 held instead by u_y = 0 at its
 *            arc nodes with |x| < a_Hertz (where contact would hold it) - the baseline cost of
 *            one sparse factorization per body;
 *   mortar, dual, nts   the contact solve with each method (MC_METHOD_*).
 * Per case: DOFs, contact nodes, active nodes, active-set iterations, the library's phase
 * times, the wall time from mc_create to the results (median of --repeat runs), peak RSS, p0
 * and a against Hertz, the H1 norm of the solution (compared by the driver against the finest
 * solution), and for contact cases the wall time of a re-solve after a load change (which
 * reuses the factorizations and the interface operator) with its factorization count.
 *
 * Estimators (the same as bench/getfem_hertz.py, so that both codes are measured alike):
 *   p0        max over the contact nodes of the lumped pressure (mc_get_contact_pressure);
 *   a         per side, p^2 extrapolated linearly in x^2 to zero through the last two loaded
 *             nodes, clamped between the last loaded node and the next; mean of both sides;
 *   a_moment  2 sqrt(sum f_j x_j^2 / sum f_j) from the nodal contact forces (exact for the
 *             elliptical Hertz distribution).
 *
 * Each contact case runs once per interface solver of --solvers (MC_OPTION_INTERFACE_SOLVER):
 * auto (the option not set: the library's choice), condensed, sparse (each forced). Every row
 * says which ran (MC_INFO_INTERFACE_SOLVER: 1 condensed, 2 sparse; 0 from a library that does
 * not set it); the driver (bench/hertz_benchmark.py --solvers) puts them side by side.
 *
 * usage: hertz_sweep [--ratio r] [--repeat n] [--normal nonmortar|mortar] [--threads n]
 *                    [--cases plain,mortar,dual,nts] [--solvers auto,condensed,sparse]
 *                    [--json file] h1 [h1 ...]
 * (--threads: MC_OPTION_THREADS for every solve; default: the library's, automatic;
 *  --solvers: default auto, as before the option existed; the plain case runs once whatever
 *  the list, it has no interface; HERTZ_SWEEP_LOG=1: the contact solves' log messages on stderr)
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "contact_half_width.h"
#include "hertz_model.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

enum { CASE_PLAIN = -1 };
#define MAX_REPEAT 15

typedef struct result {
  int ok;
  long dofs, contact_nodes, active, iterations, factor_nnz;
  double t_assembly, t_analysis, t_factor, t_solve, t_contact, t_library, t_wall;
  double t_resolve;
  long resolve_factorizations;
  int solver_ran; /* MC_INFO_INTERFACE_SOLVER of the first solve */
  double peak_rss_mib;
  double p0, a, a_moment, force_sum, h1_norm, energy;
  char message[256];
} result;

static double peak_rss_mib(void) {
  FILE *f = fopen("/proc/self/status", "r");
  char line[256];
  long kib = -1;
  while (f && fgets(line, sizeof line, f))
    if (strncmp(line, "VmHWM:", 6) == 0) kib = atol(line + 6);
  if (f) fclose(f);
  return kib / 1024.0;
}

/* ||u||_H1^2 = int |grad u|^2 + |u|^2 over a P1 mesh, exactly (constant gradients; the P1
   mass matrix area/12 (1 + delta_ij)). */
static double h1_norm_squared(const hertz_mesh *mesh, const double *u) {
  double sum = 0;
  for (int c = 0; c < mesh->n_cells; ++c) {
    const int *v = mesh->cells + 3 * c;
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) x[k] = mesh->xy[2 * v[k]], y[k] = mesh->xy[2 * v[k] + 1];
    double det = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]), area = 0.5 * det;
    /* gradients of the barycentric coordinates */
    double gx[3] = {(y[1] - y[2]) / det, (y[2] - y[0]) / det, (y[0] - y[1]) / det};
    double gy[3] = {(x[2] - x[1]) / det, (x[0] - x[2]) / det, (x[1] - x[0]) / det};
    for (int comp = 0; comp < 2; ++comp) {
      double dx = 0, dy = 0, mass = 0;
      for (int k = 0; k < 3; ++k) dx += u[2 * v[k] + comp] * gx[k], dy += u[2 * v[k] + comp] * gy[k];
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) mass += u[2 * v[k] + comp] * u[2 * v[l] + comp] * (k == l ? 2.0 : 1.0);
      sum += area * (dx * dx + dy * dy) + area / 12.0 * mass;
    }
  }
  return sum;
}

/* contact_half_width(): bench/contact_half_width.h (the file header says what it estimates). */

#define TRY(call)                                                                              \
  do {                                                                                         \
    if ((call) != MC_OK) {                                                                     \
      snprintf(r->message, sizeof r->message, "%s: %s", #call, m ? mc_errmsg(m) : "no model"); \
      mc_destroy(m);                                                                           \
      return;                                                                                  \
    }                                                                                          \
  } while (0)

/* One solve of the scene (setup included in t_wall); fills r on the last repeat. */
static int threads_option = -1; /* --threads: MC_OPTION_THREADS, or -1 for the library's default */

/* HERTZ_SWEEP_LOG=1: every contact solve's log messages on stderr (bench/interface_choice.py
   reads the automatic choice's estimates from them). */
static void echo_log(void *user, mc_log_level level, const char *message) {
  (void)user, (void)level;
  fprintf(stderr, "  log: %s\n", message);
}

static void run_once(const hertz_scene *s, int method, int normal, int solver, int last, result *r, double *t_wall) {
  mc_model *m = NULL;
  double start = bench_wall();
  TRY(mc_create(&m));
  if (threads_option >= 0) TRY(mc_set_option_int(m, MC_OPTION_THREADS, threads_option));
  TRY(hertz_model_bodies(m, s));
  double a_hertz, p0_hertz;
  hertz_analytic(&a_hertz, &p0_hertz);
  if (method == CASE_PLAIN) {
    /* body 1 held where contact would hold it: its arc nodes with |x| < a_Hertz, y < 0.1 */
    int n = 0, *held = malloc(sizeof(int) * s->body[0].n_nodes);
    for (int i = 0; i < s->body[0].n_nodes; ++i) {
      double x = s->body[0].xy[2 * i], y = s->body[0].xy[2 * i + 1];
      if (fabs(x) < a_hertz && y < 0.1 && fabs(hypot(x, y - 1) - 1) < 1e-12) held[n++] = i;
    }
    mc_status status = mc_fix(m, 1, n, held, MC_Y, NULL);
    free(held);
    TRY(status);
  } else {
    TRY(mc_set_contact(m, 1, s->n_contact_edges[0], s->contact_edges[0]));
    TRY(mc_set_contact(m, 2, s->n_contact_edges[1], s->contact_edges[1]));
    TRY(mc_set_option_int(m, MC_OPTION_METHOD, method));
    TRY(mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, normal));
    /* auto: the option left at the library's default, as a host that does not set it */
    if (solver != MC_INTERFACE_AUTO) TRY(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver));
    if (getenv("HERTZ_SWEEP_LOG")) TRY(mc_set_log_callback(m, echo_log, NULL));
  }
  TRY(mc_solve(m));
  /* results read back, as a host would */
  double *u[2];
  for (int b = 0; b < 2; ++b) {
    u[b] = malloc(sizeof(double) * 2 * s->body[b].n_nodes);
    TRY(mc_get_displacement(m, b + 1, u[b]));
  }
  mc_int n = 0;
  double *pressure = NULL, *force = NULL, *x = NULL;
  if (method != CASE_PLAIN) {
    TRY(mc_get_contact_count(m, &n));
    mc_int *nodes = malloc(sizeof(mc_int) * n);
    pressure = malloc(sizeof(double) * n), force = malloc(sizeof(double) * n), x = malloc(sizeof(double) * n);
    TRY(mc_get_contact_nodes(m, nodes));
    TRY(mc_get_contact_pressure(m, pressure));
    TRY(mc_get_contact_force(m, force));
    for (mc_int j = 0; j < n; ++j) x[j] = s->body[0].xy[2 * nodes[j]];
    free(nodes);
  }
  *t_wall = bench_wall() - start;
  if (last) {
    int64_t v;
    mc_get_info_int(m, MC_INFO_DOFS, &v), r->dofs = v;
    mc_get_info_int(m, MC_INFO_FACTOR_NNZ, &v), r->factor_nnz = v;
    mc_get_info_int(m, MC_INFO_ITERATIONS, &v), r->iterations = v;
    mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &v), r->active = v;
    mc_get_info_int(m, MC_INFO_CONTACT_NODES, &v), r->contact_nodes = v;
    v = 0;
    mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &v), r->solver_ran = (int)v;
    mc_get_info_real(m, MC_INFO_TIME_ASSEMBLY, &r->t_assembly);
    mc_get_info_real(m, MC_INFO_TIME_ANALYSIS, &r->t_analysis);
    mc_get_info_real(m, MC_INFO_TIME_FACTORIZATION, &r->t_factor);
    mc_get_info_real(m, MC_INFO_TIME_SOLVE, &r->t_solve);
    mc_get_info_real(m, MC_INFO_TIME_CONTACT, &r->t_contact);
    mc_get_info_real(m, MC_INFO_TIME_TOTAL, &r->t_library);
    mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &r->energy);
    r->h1_norm = sqrt(h1_norm_squared(&s->body[0], u[0]) + h1_norm_squared(&s->body[1], u[1]));
    if (method != CASE_PLAIN) {
      double moment = 0, sum = 0;
      r->p0 = 0;
      for (mc_int j = 0; j < n; ++j) r->p0 = fmax(r->p0, pressure[j]), sum += force[j], moment += force[j] * x[j] * x[j];
      r->force_sum = sum; /* the normals are nearly vertical: the balance is checked by the tests */
      r->a_moment = 2 * sqrt(moment / sum);
      r->a = contact_half_width(n, x, pressure);
      /* a host stepping its load: change only the load, solve again */
      TRY(hertz_model_load(m, s, 1.5));
      double t = bench_wall();
      TRY(mc_solve(m));
      double *p2 = malloc(sizeof(double) * n);
      TRY(mc_get_contact_pressure(m, p2));
      r->t_resolve = bench_wall() - t;
      free(p2);
      mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v), r->resolve_factorizations = v;
    }
    r->ok = 1;
  }
  free(u[0]), free(u[1]), free(pressure), free(force), free(x);
  mc_destroy(m);
}

/* A case in a child process: repeat runs, median wall time, peak RSS of the child. */
static result run_case(const hertz_scene *s, int method, int normal, int solver, int repeat) {
  result r;
  memset(&r, 0, sizeof r);
  int fd[2];
  if (pipe(fd) != 0) return r;
  pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    double times[MAX_REPEAT];
    for (int k = 0; k < repeat; ++k) {
      run_once(s, method, normal, solver, k == repeat - 1, &r, &times[k]);
      if (r.message[0]) break;
    }
    if (r.ok) r.t_wall = bench_median(times, repeat);
    r.peak_rss_mib = peak_rss_mib();
    ssize_t written = write(fd[1], &r, sizeof r);
    _exit(written == (ssize_t)sizeof r ? 0 : 1);
  }
  close(fd[1]);
  ssize_t got = read(fd[0], &r, sizeof r);
  close(fd[0]);
  waitpid(pid, NULL, 0);
  if (got != (ssize_t)sizeof r) memset(&r, 0, sizeof r), strcpy(r.message, "the child process failed");
  return r;
}

static const char *solver_name(int solver) {
  return solver == MC_INTERFACE_CONDENSED ? "condensed" : solver == MC_INTERFACE_SPARSE ? "sparse" : "auto";
}

/* MC_INFO_INTERFACE_SOLVER as read (0: no contact, or a library that does not set it). */
static const char *ran_name(int ran) {
  return ran == MC_INTERFACE_CONDENSED ? "condensed" : ran == MC_INTERFACE_SPARSE ? "sparse" : "-";
}

static const char *case_name(int method) {
  return method == CASE_PLAIN ? "plain" : method == MC_METHOD_MORTAR ? "mortar" : method == MC_METHOD_DUAL_MORTAR ? "dual" : "nts";
}

int main(int argc, char **argv) {
  double ratio = 1.37;
  int repeat = 3, normal = MC_NORMAL_NONMORTAR;
  const char *json_path = NULL, *cases = "plain,mortar,dual,nts", *solvers_list = "auto";
  double h1s[64];
  int n_sizes = 0;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--ratio") && i + 1 < argc) ratio = atof(argv[++i]);
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--json") && i + 1 < argc) json_path = argv[++i];
    else if (!strcmp(argv[i], "--cases") && i + 1 < argc) cases = argv[++i];
    else if (!strcmp(argv[i], "--solvers") && i + 1 < argc) solvers_list = argv[++i];
    else if (!strcmp(argv[i], "--threads") && i + 1 < argc) threads_option = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--normal") && i + 1 < argc)
      normal = !strcmp(argv[++i], "mortar") ? MC_NORMAL_MORTAR : MC_NORMAL_NONMORTAR;
    else if (n_sizes < 64 && atof(argv[i]) > 0) h1s[n_sizes++] = atof(argv[i]);
    else {
      fprintf(stderr,
              "usage: %s [--ratio r] [--repeat n] [--normal nonmortar|mortar] [--threads n] [--cases list] "
              "[--solvers auto,condensed,sparse] [--json file] h1...\n",
              argv[0]);
      return 2;
    }
  }
  if (repeat < 1 || repeat > MAX_REPEAT || n_sizes == 0) {
    fprintf(stderr, "need 1 <= repeat <= %d and at least one h1\n", MAX_REPEAT);
    return 2;
  }
  int methods[4], n_methods = 0;
  const int all[4] = {CASE_PLAIN, MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR, MC_METHOD_NODE_TO_SEGMENT};
  for (int k = 0; k < 4; ++k)
    if (strstr(cases, case_name(all[k]))) methods[n_methods++] = all[k];
  int solvers[3], n_solvers = 0;
  const int all_solvers[3] = {MC_INTERFACE_AUTO, MC_INTERFACE_CONDENSED, MC_INTERFACE_SPARSE};
  for (int k = 0; k < 3; ++k)
    if (strstr(solvers_list, solver_name(all_solvers[k]))) solvers[n_solvers++] = all_solvers[k];
  if (n_solvers == 0) {
    fprintf(stderr, "--solvers: a list of auto, condensed, sparse\n");
    return 2;
  }
  double a_hertz, p0_hertz;
  hertz_analytic(&a_hertz, &p0_hertz);
  FILE *json = json_path ? fopen(json_path, "w") : NULL;
  if (json) fprintf(json, "[\n");
  printf("Hertz scene, P1, h2 = %g h1, %s normals, OPENBLAS_NUM_THREADS=%s, %ld cores, wall time median of %d\n", ratio,
         normal == MC_NORMAL_MORTAR ? "mortar" : "non-mortar", getenv("OPENBLAS_NUM_THREADS") ? getenv("OPENBLAS_NUM_THREADS") : "unset",
         sysconf(_SC_NPROCESSORS_ONLN), repeat);
  printf("%-6s %8s %9s %6s %6s %4s %7s %7s %7s %7s %7s %8s %8s %8s %9s %9s %9s %-9s %-9s\n", "case", "h1", "DOFs",
         "cnodes", "active", "it", "asm_s", "anal_s", "fact_s", "cont_s", "lib_s", "wall_s", "resolve", "RSS_MiB", "err_p0",
         "err_a", "err_amom", "solver", "ran");
  int first = 1, failed = 0;
  for (int i = 0; i < n_sizes; ++i) {
    hertz_scene s;
    if (hertz_scene_build(&s, h1s[i], ratio * h1s[i], 0) != 0) {
      fprintf(stderr, "cannot build h1 = %g\n", h1s[i]);
      return 1;
    }
    for (int k = 0; k < n_methods; ++k)
      for (int v = 0; v < (methods[k] == CASE_PLAIN ? 1 : n_solvers); ++v) {
        const int solver = methods[k] == CASE_PLAIN ? MC_INTERFACE_AUTO : solvers[v];
        result r = run_case(&s, methods[k], normal, solver, repeat);
        if (!r.ok) {
          printf("%-6s %8.5f FAILED (%s): %s\n", case_name(methods[k]), h1s[i], solver_name(solver), r.message);
          failed = 1;
          continue;
        }
        int contact = methods[k] != CASE_PLAIN;
        printf("%-6s %8.5f %9ld %6ld %6ld %4ld %7.3f %7.3f %7.3f %7.3f %7.3f %8.3f %8.4f %8.0f %+9.2e %+9.2e %+9.2e %-9s %-9s\n",
               case_name(methods[k]), h1s[i], r.dofs, r.contact_nodes, r.active, r.iterations, r.t_assembly, r.t_analysis,
               r.t_factor, r.t_contact, r.t_library, r.t_wall, r.t_resolve, r.peak_rss_mib,
               contact ? r.p0 / p0_hertz - 1 : 0, contact ? r.a / a_hertz - 1 : 0, contact ? r.a_moment / a_hertz - 1 : 0,
               contact ? solver_name(solver) : "-", contact ? ran_name(r.solver_ran) : "-");
        fflush(stdout);
        if (json) {
          fprintf(json,
                  "%s {\"case\": \"%s\", \"solver\": \"%s\", \"solver_ran\": %d, \"h1\": %.17g, \"h2\": %.17g, "
                  "\"dofs\": %ld, \"factor_nnz\": %ld, "
                  "\"contact_nodes\": %ld, \"active_nodes\": %ld, \"iterations\": %ld, \"time_assembly\": %.6g, "
                  "\"time_analysis\": %.6g, \"time_factorization\": %.6g, \"time_solve\": %.6g, \"time_contact\": %.6g, "
                  "\"time_library\": %.6g, \"time\": %.6g, \"time_resolve\": %.6g, \"resolve_factorizations\": %ld, "
                  "\"peak_rss_mib\": %.1f, \"p0\": %.17g, \"a\": %.17g, \"a_moment\": %.17g, \"force_sum\": %.17g, "
                  "\"h1_norm\": %.17g, \"energy\": %.17g, \"p0_hertz\": %.17g, \"a_hertz\": %.17g, \"repeat\": %d}",
                  first ? "" : ",\n", case_name(methods[k]), solver_name(solver), r.solver_ran, h1s[i], ratio * h1s[i],
                  r.dofs, r.factor_nnz, r.contact_nodes, r.active, r.iterations, r.t_assembly, r.t_analysis, r.t_factor,
                  r.t_solve, r.t_contact, r.t_library, r.t_wall, r.t_resolve, r.resolve_factorizations, r.peak_rss_mib,
                  r.p0, r.a, r.a_moment, r.force_sum, r.h1_norm, r.energy, p0_hertz, a_hertz, repeat);
          fflush(json);
          first = 0;
        }
      }
    hertz_scene_free(&s);
  }
  if (json) fprintf(json, "\n]\n"), fclose(json);
  return failed;
}
