/* sphere_on_flat.c - see sphere_on_flat.h. */
#include "sphere_on_flat.h"
#include "hertz_scene.h"
#include "mortarcontact.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Least-squares line through (r_j^2, p_j^2) over the loaded nodes off the axis and short of the
   outermost loaded one (where the lumped pressure of a half-loaded node drops): the Hertz
   profile p^2 = p0^2 - (p0^2 / a^2) r^2 is such a line. */
static void fit_profile(int n, const double *r, const double *p, double *p0, double *a) {
  double r_last = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  int j, k = 0;
  for (j = 0; j < n; ++j)
    if (p[j] > 0 && r[j] > r_last) r_last = r[j];
  for (j = 0; j < n; ++j) {
    double x = r[j] * r[j], y = p[j] * p[j];
    if (!(p[j] > 0) || r[j] <= 0 || r[j] >= r_last) continue;
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++k;
  }
  double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx), intercept = (sy - slope * sx) / k;
  *p0 = sqrt(intercept);
  *a = sqrt(-intercept / slope);
}

int sphere_on_flat_solve_cells(double h, int nodes_per_cell, int method, int normal, int plane, int multiplier,
                               sphere_result *res) {
  hertz_scene s;
  mc_model *m = NULL;
  int st, b, j;
  memset(res, 0, sizeof *res);
  if (hertz_scene_axisymmetric_cells(&s, h, SPHERE_H2_RATIO * h, nodes_per_cell)) return -1;
  if (mc_create(&m) != MC_OK) {
    hertz_scene_free(&s);
    return MC_ERROR_MEMORY;
  }
  res->load = SPHERE_LOAD;
  hertz_analytic_sphere(SPHERE_LOAD, &res->a_hertz, &res->p0_hertz, NULL);
  double *top = malloc(sizeof(double) * (size_t)s.n_top_edges);
  for (j = 0; j < s.n_top_edges; ++j) top[j] = SPHERE_LOAD / M_PI; /* on the disc r <= 1 */
#define TRY(call) \
  if ((st = (call)) != MC_OK) goto done
  TRY(mc_set_plane(m, plane, 1.0));
  for (b = 0; b < 2; ++b) {
    TRY(mc_set_mesh(m, b + 1, s.body[b].n_nodes, s.body[b].xy, s.body[b].n_cells, s.body[b].nodes_per_cell,
                    s.body[b].cells));
    TRY(mc_set_material(m, b + 1, 1.0, 0.3));
    TRY(mc_set_contact(m, b + 1, s.n_contact_edges[b], s.contact_edges[b]));
  }
  TRY(mc_fix(m, 2, s.n_bottom_nodes, s.bottom_nodes, MC_XY, NULL));
  if (plane != MC_AXISYMMETRIC) { /* the symmetry plane x = 0 of the plane half-scene */
    int *axis2 = malloc(sizeof(int) * (size_t)s.body[1].n_nodes), n2 = 0;
    for (j = 0; j < s.body[1].n_nodes; ++j)
      if (s.body[1].xy[2 * j] == 0.0) axis2[n2++] = j;
    st = mc_fix(m, 1, s.n_axis_nodes, s.axis_nodes, MC_X, NULL);
    if (st == MC_OK) st = mc_fix(m, 2, n2, axis2, MC_X, NULL);
    free(axis2);
    if (st != MC_OK) goto done;
  }
  TRY(mc_add_pressure(m, 1, s.n_top_edges, s.top_edges, top));
  TRY(mc_set_option_int(m, MC_OPTION_METHOD, method));
  TRY(mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, normal));
  TRY(mc_set_option_int(m, MC_OPTION_MULTIPLIER, multiplier));
  TRY(mc_solve(m));
  {
    int64_t dofs = 0, active = 0;
    mc_int n = 0;
    mc_get_info_int(m, MC_INFO_DOFS, &dofs);
    mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active);
    mc_get_info_real(m, MC_INFO_TIME_TOTAL, &res->seconds);
    mc_get_info_real(m, MC_INFO_TIME_ASSEMBLY, &res->seconds_assembly);
    mc_get_info_real(m, MC_INFO_TIME_FACTORIZATION, &res->seconds_factorization);
    mc_get_info_real(m, MC_INFO_TIME_CONTACT, &res->seconds_contact);
    res->dofs = (long)dofs, res->active = (int)active;
    mc_get_info_int(m, MC_INFO_ITERATIONS, &dofs), res->iterations = (int)dofs;
    mc_get_contact_count(m, &n);
    mc_int *nodes = malloc(sizeof(mc_int) * (size_t)n);
    double *p = malloc(sizeof(double) * (size_t)n), *f = malloc(sizeof(double) * (size_t)n),
           *normals = malloc(sizeof(double) * 2 * (size_t)n), *r = malloc(sizeof(double) * (size_t)n);
    mc_get_contact_nodes(m, nodes);
    mc_get_contact_pressure(m, p);
    mc_get_contact_force(m, f);
    mc_get_contact_normal(m, normals);
    /* a quadratic body 1 with linear multipliers: the profile on the corners (the multiplier's
       nodes) only; otherwise every position carries a multiplier value */
    char *corner = calloc((size_t)s.body[0].n_nodes, 1);
    if (multiplier == MC_MULTIPLIER_LINEAR && method != MC_METHOD_DUAL_MORTAR && nodes_per_cell > 4)
      for (j = 0; j < 2 * s.n_contact_edges[0]; ++j) corner[s.contact_edges[0][j]] = 1;
    else
      for (j = 0; j < s.body[0].n_nodes; ++j) corner[j] = 1;
    double r_last = 0, r_next = INFINITY, *rc = malloc(sizeof(double) * (size_t)n), *pc = malloc(sizeof(double) * (size_t)n);
    int nc = 0;
    double moment = 0;
    for (j = 0; j < n; ++j) {
      r[j] = s.body[0].xy[2 * nodes[j]];
      res->total_force -= f[j] * normals[2 * j + 1]; /* axial share; the normals point down */
      moment -= f[j] * normals[2 * j + 1] * r[j] * r[j];
      if (p[j] > res->p_max) res->p_max = p[j];
      if (!corner[nodes[j]]) continue;
      rc[nc] = r[j], pc[nc++] = p[j];
      if (r[j] == 0.0) res->axis_pressure = p[j];
      if (p[j] > 0 && r[j] > r_last) r_last = r[j];
    }
    for (j = 0; j < nc; ++j)
      if (rc[j] > r_last && rc[j] < r_next) r_next = rc[j];
    res->a_nodes = 0.5 * (r_last + r_next);
    res->a_moment = res->total_force > 0 ? sqrt(2.5 * moment / res->total_force) : 0;
    fit_profile(nc, rc, pc, &res->p0, &res->a);
    free(nodes), free(p), free(f), free(normals), free(r), free(corner), free(rc), free(pc);
  }
done:
#undef TRY
  free(top);
  mc_destroy(m);
  hertz_scene_free(&s);
  return st;
}

int sphere_on_flat_solve(double h, int quads, int method, int normal, int plane, sphere_result *r) {
  if (quads != 0 && quads != 1) {
    memset(r, 0, sizeof *r);
    return -1;
  }
  return sphere_on_flat_solve_cells(h, quads ? 4 : 3, method, normal, plane, MC_MULTIPLIER_LINEAR, r);
}

int sphere_on_flat(double h, int quads, int method, sphere_result *r) {
  return sphere_on_flat_solve(h, quads, method, MC_NORMAL_MORTAR, MC_AXISYMMETRIC, r);
}
