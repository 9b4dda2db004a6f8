/*
 * hertz.c - the Hertz contact scene solved with the paper's mortar method.
 *
 * A half-disc (radius 1, E = 1, nu = 0.3) is pressed with a total force P = 0.01 onto a block
 * [-4,4]x[-4,0] of the same material (plane strain). The disc is held vertically by contact
 * alone (only u_x = 0 on its axis). The meshes are independent (h2 = 1.37 h1 by default) and
 * graded towards the contact point. Prints DOFs, iterations, time, the peak pressure p0 and the
 * half-width a against Hertz's analytic values, and writes the pressure profile with the
 * analytic one to a CSV file.
 *
 * usage: hertz [h1] [method: mortar|dual|nts] [csv path] [normal: nonmortar|mortar]
 */
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK(call)                                                                  \
  do {                                                                               \
    mc_status status_ = (call);                                                      \
    if (status_ != MC_OK) {                                                          \
      fprintf(stderr, "%s failed: %s: %s\n", #call, mc_status_string(status_), mc_errmsg(model)); \
      return 1;                                                                      \
    }                                                                                \
  } while (0)

int main(int argc, char **argv) {
  double h1 = argc > 1 ? atof(argv[1]) : 0.004;
  const char *method_name = argc > 2 ? argv[2] : "mortar";
  const char *csv_path = argc > 3 ? argv[3] : "hertz_pressure.csv";
  const char *normal_name = argc > 4 ? argv[4] : "nonmortar";
  int normal = strcmp(normal_name, "mortar") == 0 ? MC_NORMAL_MORTAR : MC_NORMAL_NONMORTAR;
  int method = strcmp(method_name, "dual") == 0 ? MC_METHOD_DUAL_MORTAR
               : strcmp(method_name, "nts") == 0 ? MC_METHOD_NODE_TO_SEGMENT : MC_METHOD_MORTAR;

  /* 1. The meshes: two independent graded meshes of the scene. */
  hertz_scene scene;
  if (hertz_scene_build(&scene, h1, 1.37 * h1, 0) != 0) {
    fprintf(stderr, "could not build the Hertz meshes for h1 = %g\n", h1);
    return 1;
  }

  /* 2. The model: meshes, materials, supports, the load and the contact surfaces. */
  mc_model *model = NULL;
  if (mc_create(&model) != MC_OK) return 1;
  for (int b = 0; b < 2; ++b) {
    const hertz_mesh *mesh = &scene.body[b];
    CHECK(mc_set_mesh(model, b + 1, mesh->n_nodes, mesh->xy, mesh->n_cells, mesh->nodes_per_cell, mesh->cells));
    CHECK(mc_set_material(model, b + 1, 1.0, 0.3));
  }
  CHECK(mc_fix(model, 1, scene.n_axis_nodes, scene.axis_nodes, MC_X, NULL));
  CHECK(mc_fix(model, 2, scene.n_bottom_nodes, scene.bottom_nodes, MC_XY, NULL));
  const double total_force = 0.01, top_length = 2.0;
  double *traction = malloc(sizeof(double) * 2 * scene.n_top_edges);
  for (int e = 0; e < scene.n_top_edges; ++e) traction[2 * e] = 0, traction[2 * e + 1] = -total_force / top_length;
  CHECK(mc_add_traction(model, 1, scene.n_top_edges, scene.top_edges, traction));
  CHECK(mc_set_contact(model, 1, scene.n_contact_edges[0], scene.contact_edges[0]));
  CHECK(mc_set_contact(model, 2, scene.n_contact_edges[1], scene.contact_edges[1]));
  CHECK(mc_set_option_int(model, MC_OPTION_METHOD, method));
  CHECK(mc_set_option_int(model, MC_OPTION_CONTACT_NORMAL, normal));

  /* 3. The solve. */
  CHECK(mc_solve(model));

  /* 4. Results: pressure along Gamma_c, p0 = its peak, a = where it drops to zero. */
  mc_int n = 0;
  CHECK(mc_get_contact_count(model, &n));
  mc_int *nodes = malloc(sizeof(mc_int) * n);
  double *pressure = malloc(sizeof(double) * n), *force = malloc(sizeof(double) * n);
  double *normals = malloc(sizeof(double) * 2 * n);
  CHECK(mc_get_contact_normal(model, normals));
  CHECK(mc_get_contact_nodes(model, nodes));
  CHECK(mc_get_contact_pressure(model, pressure));
  CHECK(mc_get_contact_force(model, force));
  const double *xy = scene.body[0].xy;
  double p0 = 0, a = 0, sum = 0;
  for (mc_int j = 0; j < n; ++j) {
    p0 = fmax(p0, pressure[j]);
    sum -= force[j] * normals[2 * j + 1]; /* body 1 is pushed along -n: its upward part */
  }
  /* half-width: midway between the outermost loaded node and its unloaded neighbour, each side */
  for (int side = -1; side <= 1; side += 2) {
    double last = 0, next = 0;
    for (mc_int j = 0; j < n; ++j) {
      double x = xy[2 * nodes[j]] * side;
      if (x < 0) continue;
      if (pressure[j] > 0 && x > last) last = x;
    }
    next = 1e300;
    for (mc_int j = 0; j < n; ++j) {
      double x = xy[2 * nodes[j]] * side;
      if (x > last && x < next) next = x;
    }
    a += 0.5 * (last + (next < 1e300 ? next : last)) / 2;
  }
  double a_hertz, p0_hertz;
  hertz_analytic(&a_hertz, &p0_hertz);
  int64_t dofs, iterations, active;
  double total, factor, contact;
  mc_get_info_int(model, MC_INFO_DOFS, &dofs);
  mc_get_info_int(model, MC_INFO_ITERATIONS, &iterations);
  mc_get_info_int(model, MC_INFO_ACTIVE_NODES, &active);
  mc_get_info_real(model, MC_INFO_TIME_TOTAL, &total);
  mc_get_info_real(model, MC_INFO_TIME_FACTORIZATION, &factor);
  mc_get_info_real(model, MC_INFO_TIME_CONTACT, &contact);
  printf("Hertz scene, %s method, %s normals, h1 = %g, h2 = %g (non-matching meshes)\n", method_name, normal_name, h1,
         1.37 * h1);
  printf("  DOFs %lld, contact nodes %d, active %lld, active-set iterations %lld\n", (long long)dofs, (int)n,
         (long long)active, (long long)iterations);
  printf("  time %.3f s (factorization %.3f s, contact %.3f s)\n", total, factor, contact);
  printf("  p0 = %.6g   Hertz %.6g   relative error %+.2e\n", p0, p0_hertz, (p0 - p0_hertz) / p0_hertz);
  printf("  a  = %.6g   Hertz %.6g   relative error %+.2e\n", a, a_hertz, (a - a_hertz) / a_hertz);
  printf("  vertical contact force %.12g (applied load %.12g)\n", sum, total_force);

  /* 5. The pressure profile beside Hertz's p0 sqrt(1 - x^2/a^2). */
  FILE *csv = fopen(csv_path, "w");
  if (csv) {
    fprintf(csv, "x,pressure,hertz\n");
    for (mc_int j = 0; j < n; ++j) {
      double x = xy[2 * nodes[j]], s = 1 - x * x / (a_hertz * a_hertz);
      fprintf(csv, "%.10g,%.10g,%.10g\n", x, pressure[j], s > 0 ? p0_hertz * sqrt(s) : 0.0);
    }
    fclose(csv);
    printf("  pressure profile written to %s\n", csv_path);
  }
  free(nodes), free(pressure), free(force), free(normals), free(traction);
  mc_destroy(model);
  hertz_scene_free(&scene);
  return 0;
}
