/*
 * tutorial_hertz.c - the program of docs/tutorial_c.md: the Hertz contact scene, step by step.
 *
 * A half-disc of radius R = 1 is pressed with a total force P = 0.01 onto a block; both are
 * linear elastic (E = 1, nu = 0.3, plane strain) and meshed independently. The program solves
 * the contact problem with the paper's mortar method, compares the peak pressure p0 and the
 * half-width a of the contact zone with Hertz's formulas, writes the solution for ParaView,
 * then doubles the load and solves again, reusing the factorization.
 *
 * usage: tutorial_hertz [h1] [output.pvd]
 *   h1: mesh size of the disc at the contact point (default 0.01; the block gets 1.37 h1)
 *   output.pvd: where to write the ParaView files (default tutorial_hertz.pvd)
 *
 * Exit status 0 only if every check of steps 11 and 13 passes (ctest runs it: tutorial_c).
 */
#include "hertz_scene.h"
#include <mortarcontact.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Every mc_ call returns a status; on failure mc_errmsg names the argument and index. */
#define CHECK(call)                                                                      \
  do {                                                                                   \
    mc_status status_ = (call);                                                          \
    if (status_ != MC_OK) {                                                              \
      fprintf(stderr, "%s: %s: %s\n", #call, mc_status_string(status_), mc_errmsg(model)); \
      return 1;                                                                          \
    }                                                                                    \
  } while (0)

/* The progress messages of mc_solve (step 8): print the phases, skip the iterations. */
static void print_phase(void *user_data, mc_log_level level, const char *message) {
  (void)user_data;
  if (level == MC_LOG_PHASE) printf("  [mc] %s\n", message);
}

/* Half-width of the contact zone: on each side of x = 0, midway between the outermost node
   that carries pressure and the next node out; the mean of the two sides. */
static double half_width(mc_int n, const double *x, const double *p) {
  double a = 0;
  for (int side = -1; side <= 1; side += 2) {
    double last = 0, next = INFINITY;
    for (mc_int j = 0; j < n; ++j)
      if (side * x[j] >= 0 && p[j] > 0 && side * x[j] > last) last = side * x[j];
    for (mc_int j = 0; j < n; ++j)
      if (side * x[j] > last && side * x[j] < next) next = side * x[j];
    a += 0.25 * (last + (isfinite(next) ? next : last));
  }
  return a;
}

int main(int argc, char **argv) {
  const double h1 = argc > 1 ? atof(argv[1]) : 0.01;
  const char *output = argc > 2 ? argv[2] : "tutorial_hertz.pvd";
  mc_model *model = NULL;
  int failures = 0;

  /* ---- step 1: the problem and its analytic answer ---- */
  const double R = 1.0, E = 1.0, nu = 0.3, P = 0.01, pi = 3.14159265358979323846;
  const double e_star = E / (2.0 * (1.0 - nu * nu)); /* two equal bodies, plane strain */
  const double a_hertz = sqrt(4.0 * P * R / (pi * e_star));
  const double p0_hertz = 2.0 * P / (pi * a_hertz);
  printf("Hertz: a = %.6f, p0 = %.6f\n", a_hertz, p0_hertz);

  /* ---- step 2: two independent meshes ---- */
  hertz_scene scene;
  if (hertz_scene_build(&scene, h1, 1.37 * h1, 0) != 0) {
    fprintf(stderr, "cannot build the Hertz meshes for h1 = %g\n", h1);
    return 1;
  }
  const hertz_mesh *disc = &scene.body[0], *block = &scene.body[1];
  printf("meshes: disc %d nodes, %d triangles; block %d nodes, %d triangles\n", disc->n_nodes,
         disc->n_cells, block->n_nodes, block->n_cells);

  /* ---- step 3: the model and its two bodies ---- */
  if (mc_create(&model) != MC_OK) return 1;
  CHECK(mc_set_plane(model, MC_PLANE_STRAIN, 1.0));
  CHECK(mc_set_mesh(model, 1, disc->n_nodes, disc->xy, disc->n_cells, disc->nodes_per_cell, disc->cells));
  CHECK(mc_set_mesh(model, 2, block->n_nodes, block->xy, block->n_cells, block->nodes_per_cell, block->cells));

  /* ---- step 4: materials ---- */
  CHECK(mc_set_material(model, 1, E, nu));
  CHECK(mc_set_material(model, 2, E, nu));

  /* ---- step 5: supports ---- */
  CHECK(mc_fix(model, 1, scene.n_axis_nodes, scene.axis_nodes, MC_X, NULL));        /* u_x = 0 on x = 0 */
  CHECK(mc_fix(model, 2, scene.n_bottom_nodes, scene.bottom_nodes, MC_XY, NULL));   /* clamped at y = -4 */

  /* ---- step 6: the load ---- */
  double *traction = malloc(sizeof(double) * 2 * scene.n_top_edges);
  for (int e = 0; e < scene.n_top_edges; ++e) {
    traction[2 * e] = 0.0;
    traction[2 * e + 1] = -P / (2.0 * R); /* force per unit length on the top, |x| <= R */
  }
  CHECK(mc_add_traction(model, 1, scene.n_top_edges, scene.top_edges, traction));

  /* ---- step 7: the contact surfaces ---- */
  CHECK(mc_set_contact(model, 1, scene.n_contact_edges[0], scene.contact_edges[0])); /* non-mortar */
  CHECK(mc_set_contact(model, 2, scene.n_contact_edges[1], scene.contact_edges[1])); /* mortar */

  /* ---- step 8: method options and progress messages ---- */
  CHECK(mc_set_option_int(model, MC_OPTION_METHOD, MC_METHOD_MORTAR));
  CHECK(mc_set_option_int(model, MC_OPTION_CONTACT_NORMAL, MC_NORMAL_MORTAR));
  CHECK(mc_set_log_callback(model, print_phase, NULL));

  /* ---- step 9: solve ---- */
  CHECK(mc_solve(model));
  int64_t dofs, iterations, active, rows;
  double seconds;
  CHECK(mc_get_info_int(model, MC_INFO_DOFS, &dofs));
  CHECK(mc_get_info_int(model, MC_INFO_ITERATIONS, &iterations));
  CHECK(mc_get_info_int(model, MC_INFO_ACTIVE_NODES, &active));
  CHECK(mc_get_info_int(model, MC_INFO_CONTACT_NODES, &rows));
  CHECK(mc_get_info_real(model, MC_INFO_TIME_TOTAL, &seconds));
  printf("solved: %lld unknowns, %lld active of %lld contact nodes, %lld active-set iterations\n",
         (long long)dofs, (long long)active, (long long)rows, (long long)iterations);

  /* ---- step 10: read the results ---- */
  mc_int n;
  CHECK(mc_get_contact_count(model, &n));
  mc_int *nodes = malloc(sizeof(mc_int) * n);
  double *x = malloc(sizeof(double) * n), *pressure = malloc(sizeof(double) * n);
  double *force = malloc(sizeof(double) * n), *gap = malloc(sizeof(double) * n);
  double *normal = malloc(sizeof(double) * 2 * n);
  CHECK(mc_get_contact_nodes(model, nodes));
  CHECK(mc_get_contact_pressure(model, pressure));
  CHECK(mc_get_contact_force(model, force));
  CHECK(mc_get_contact_gap(model, gap));
  CHECK(mc_get_contact_normal(model, normal));
  for (mc_int j = 0; j < n; ++j) x[j] = disc->xy[2 * nodes[j]]; /* ids are 0-based */
  double *u1 = malloc(sizeof(double) * 2 * disc->n_nodes);
  CHECK(mc_get_displacement(model, 1, u1));
  double sink = 0;
  for (int i = 0; i < disc->n_nodes; ++i) sink = fmin(sink, u1[2 * i + 1]);
  printf("the disc moved down by %.6f (largest -u_y of body 1)\n", -sink);

  /* ---- step 11: check against Hertz ---- */
  double p0 = 0, lift = 0, worst = 0;
  for (mc_int j = 0; j < n; ++j) {
    p0 = fmax(p0, pressure[j]);
    lift += force[j] * -normal[2 * j + 1]; /* lambda_j pushes body 1 along -n_j */
    if (isfinite(gap[j])) worst = fmax(worst, fabs(force[j] * gap[j])); /* force * gap = 0 */
  }
  const double a = half_width(n, x, pressure);
  const double p0_error = p0 / p0_hertz - 1, a_error = a - a_hertz;
  printf("p0 = %.6f (Hertz %.6f, %+.2f %%)\n", p0, p0_hertz, 100 * p0_error);
  printf("a  = %.6f (Hertz %.6f, %+.2f h1)\n", a, a_hertz, a_error / h1);
  printf("contact force %.10f (load %.10f), max |force * gap| %.1e\n", lift, P, worst);
  if (fabs(p0_error) > 0.005) printf("FAIL: p0 is not within 0.5 %% of Hertz\n"), ++failures;
  if (fabs(a_error) > 1.5 * h1) printf("FAIL: a is not within 1.5 h1 of Hertz\n"), ++failures;
  if (fabs(lift - P) > 1e-9 * P) printf("FAIL: the contact force does not balance the load\n"), ++failures;

  /* ---- step 12: write the solution for ParaView ---- */
  CHECK(mc_write_vtu(model, output));
  printf("wrote %s\n", output);

  /* ---- step 13: double the load and solve again ---- */
  for (int e = 0; e < scene.n_top_edges; ++e) traction[2 * e + 1] *= 2.0;
  CHECK(mc_clear_loads(model, 1));
  CHECK(mc_add_traction(model, 1, scene.n_top_edges, scene.top_edges, traction));
  double first_seconds = seconds;
  int64_t factorizations;
  CHECK(mc_solve(model));
  CHECK(mc_get_info_int(model, MC_INFO_FACTORIZATIONS, &factorizations));
  CHECK(mc_get_info_real(model, MC_INFO_TIME_TOTAL, &seconds));
  CHECK(mc_get_contact_pressure(model, pressure));
  double p0_doubled = 0;
  for (mc_int j = 0; j < n; ++j) p0_doubled = fmax(p0_doubled, pressure[j]);
  printf("load 2P: p0 = %.6f, p0(2P)/p0(P) = %.4f (Hertz: sqrt 2 = %.4f), %lld factorizations\n",
         p0_doubled, p0_doubled / p0, sqrt(2.0), (long long)factorizations);
  printf("time: first solve %.3f s, re-solve %.3f s\n", first_seconds, seconds);
  if (factorizations != 0) printf("FAIL: the re-solve factorized again\n"), ++failures;
  if (fabs(p0_doubled / p0 / sqrt(2.0) - 1) > 0.01) printf("FAIL: p0 does not scale as sqrt(P)\n"), ++failures;

  /* ---- step 14: clean up ---- */
  mc_destroy(model);
  hertz_scene_free(&scene);
  free(traction), free(nodes), free(x), free(pressure), free(force), free(gap), free(normal), free(u1);
  if (failures) printf("tutorial: %d checks failed\n", failures);
  else printf("tutorial: all checks passed\n");
  return failures ? 1 : 0;
}
