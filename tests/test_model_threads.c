/*
 * test_model_threads.c - two models solved at once from two threads give the results of
 * serial solves (the library keeps no global mutable state; each model owns its CHOLMOD
 * workspace).
 */
#include "hertz_scene.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>

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

int main(void) {
  Suite *suite = suite_create("model_threads");
  TCase *tc = tcase_create("threads");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, two_threads_match_serial);
  suite_add_tcase(suite, tc);
  return sc_run_suite(suite);
}
