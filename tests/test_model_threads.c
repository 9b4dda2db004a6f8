/*
 * test_model_threads.c - two models solved at once from two threads give the results of
 * serial solves (the library keeps no global mutable state; each model owns its CHOLMOD
 * workspace).
 * - the library never oversubscribes the cores: while models solve, the process runs no threads
 *   besides the host's own and OpenBLAS's pool (one per core, the caller's thread included);
 *   in particular CHOLMOD's fixed 4-thread OpenMP team is kept at one thread
 *   (lib/sparse_cholesky.cpp).
 */
#define _GNU_SOURCE
#include "hertz_scene.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <dirent.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct job {
  double h1;
  int method;
  mc_status status;
  int n;
  double pressure[4096];
} job;

static void *solve_hertz(void *arg) {
  job *j = arg;
  hertz_scene scene;
  j->status = MC_ERROR_INTERNAL;
  if (hertz_scene_build(&scene, j->h1, 1.37 * j->h1, 0)) return NULL;
  mc_model *m = NULL;
  mc_create(&m);
  mc_status s = MC_OK;
  for (int b = 0; b < 2 && !s; ++b) {
    s = mc_set_mesh(m, b + 1, scene.body[b].n_nodes, scene.body[b].xy, scene.body[b].n_cells, 3, scene.body[b].cells);
    if (!s) s = mc_set_material(m, b + 1, 1, 0.3);
  }
  double *t = malloc(sizeof(double) * 2 * scene.n_top_edges);
  for (int e = 0; e < scene.n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -0.005;
  if (!s) s = mc_fix(m, 1, scene.n_axis_nodes, scene.axis_nodes, MC_X, NULL);
  if (!s) s = mc_fix(m, 2, scene.n_bottom_nodes, scene.bottom_nodes, MC_XY, NULL);
  if (!s) s = mc_add_traction(m, 1, scene.n_top_edges, scene.top_edges, t);
  if (!s) s = mc_set_contact(m, 1, scene.n_contact_edges[0], scene.contact_edges[0]);
  if (!s) s = mc_set_contact(m, 2, scene.n_contact_edges[1], scene.contact_edges[1]);
  if (!s) s = mc_set_option_int(m, MC_OPTION_METHOD, j->method);
  if (!s) s = mc_solve(m);
  mc_int n = 0;
  if (!s) s = mc_get_contact_count(m, &n);
  if (!s && n <= 4096) s = mc_get_contact_pressure(m, j->pressure);
  j->n = n;
  j->status = s;
  free(t);
  mc_destroy(m);
  hertz_scene_free(&scene);
  return NULL;
}

START_TEST(two_threads_match_serial) {
  job serial[2] = {{.h1 = 0.01, .method = MC_METHOD_MORTAR}, {.h1 = 0.014, .method = MC_METHOD_DUAL_MORTAR}};
  job parallel[2] = {serial[0], serial[1]};
  for (int k = 0; k < 2; ++k) solve_hertz(&serial[k]);
  pthread_t threads[2];
  for (int k = 0; k < 2; ++k) ck_assert_int_eq(pthread_create(&threads[k], NULL, solve_hertz, &parallel[k]), 0);
  for (int k = 0; k < 2; ++k) pthread_join(threads[k], NULL);
  for (int k = 0; k < 2; ++k) {
    ck_assert_int_eq(serial[k].status, MC_OK);
    ck_assert_int_eq(parallel[k].status, MC_OK);
    ck_assert_int_eq(serial[k].n, parallel[k].n);
    double pmax = 0;
    for (int i = 0; i < serial[k].n; ++i) pmax = fmax(pmax, serial[k].pressure[i]);
    ck_assert(pmax > 0);
    for (int i = 0; i < serial[k].n; ++i)
      ck_assert_msg(fabs(serial[k].pressure[i] - parallel[k].pressure[i]) <= 1e-12 * pmax, "model %d node %d: %.17g vs %.17g",
                    k, i, serial[k].pressure[i], parallel[k].pressure[i]);
  }
}
END_TEST

/* ---- threads against cores ------------------------------------------------ */

static int threads_of_this_process(void) {
  DIR *dir = opendir("/proc/self/task");
  int n = 0;
  for (struct dirent *e; dir && (e = readdir(dir));)
    if (e->d_name[0] != '.') n++;
  if (dir) closedir(dir);
  return n;
}

typedef struct sampler {
  atomic_int stop;
  int most;
} sampler;

static void *sample_threads(void *arg) {
  sampler *s = arg;
  while (!atomic_load(&s->stop)) {
    int n = threads_of_this_process();
    if (n > s->most) s->most = n;
    usleep(100);
  }
  return NULL;
}

/* OpenBLAS's pool: OPENBLAS_NUM_THREADS if set, else the cores this process may run on. */
static int openblas_threads(void) {
  const char *env = getenv("OPENBLAS_NUM_THREADS");
  if (env && atoi(env) > 0) return atoi(env);
  cpu_set_t set;
  return sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : (int)sysconf(_SC_NPROCESSORS_ONLN);
}

START_TEST(threads_stay_within_the_cores) {
  /* One model in this thread, then two models in two host threads. Allowed: this thread, the
     sampler, the host threads, and OpenBLAS's workers (its pool minus the calling thread). */
  for (int hosts = 0; hosts <= 2; hosts += 2) {
    sampler s = {.most = 0};
    atomic_init(&s.stop, 0);
    pthread_t watcher, threads[2];
    ck_assert_int_eq(pthread_create(&watcher, NULL, sample_threads, &s), 0);
    job jobs[2] = {{.h1 = 0.005, .method = MC_METHOD_MORTAR}, {.h1 = 0.006, .method = MC_METHOD_DUAL_MORTAR}};
    if (hosts == 0) solve_hertz(&jobs[0]);
    for (int k = 0; k < hosts; ++k) ck_assert_int_eq(pthread_create(&threads[k], NULL, solve_hertz, &jobs[k]), 0);
    for (int k = 0; k < hosts; ++k) pthread_join(threads[k], NULL);
    atomic_store(&s.stop, 1);
    pthread_join(watcher, NULL);
    ck_assert_int_eq(jobs[0].status, MC_OK);
    int allowed = 2 + hosts + (openblas_threads() - 1);
    printf("host threads %d: at most %d threads seen (allowed %d: OpenBLAS pool of %d)\n", hosts, s.most, allowed,
           openblas_threads());
    ck_assert_msg(s.most <= allowed, "%d threads ran, more than %d", s.most, allowed);
  }
}
END_TEST

int main(void) {
  Suite *suite = suite_create("model_threads");
  TCase *tc = tcase_create("threads");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, two_threads_match_serial);
  tcase_add_test(tc, threads_stay_within_the_cores);
  suite_add_tcase(suite, tc);
  return sc_run_suite(suite);
}
