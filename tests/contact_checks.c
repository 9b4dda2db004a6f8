/* contact_checks.c - contact results, KKT and balance checks, the Hertz scene in any role; see
   contact_checks.h. */
#include "contact_checks.h"

#include "check_helpers.h"

#include <check.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

double max_d(double a, double b) { return a > b ? a : b; }

/* ---- results at the body-1 contact nodes, KKT and equilibrium ------------------------------ */

contact_data contact_get(mc_model *m) {
  contact_data c;
  OK(mc_get_contact_count(m, &c.n));
  size_t n = (size_t)c.n + 1;
  c.nodes = malloc(n * sizeof *c.nodes);
  c.force = malloc(n * sizeof(double));
  c.gap = malloc(n * sizeof(double));
  c.g0 = malloc(n * sizeof(double));
  c.pressure = malloc(n * sizeof(double));
  c.normal = malloc(2 * n * sizeof(double));
  OK(mc_get_contact_nodes(m, c.nodes));
  OK(mc_get_contact_force(m, c.force));
  OK(mc_get_contact_gap(m, c.gap));
  OK(mc_get_contact_initial_gap(m, c.g0));
  OK(mc_get_contact_pressure(m, c.pressure));
  OK(mc_get_contact_normal(m, c.normal));
  return c;
}

void contact_free(contact_data *c) {
  free(c->nodes), free(c->force), free(c->gap), free(c->g0), free(c->pressure), free(c->normal);
}

double *displacement(mc_model *m, int body, mc_int n_nodes) {
  double *u = malloc(sizeof(double) * 2 * (size_t)n_nodes);
  OK(mc_get_displacement(m, body, u));
  return u;
}

double max_abs(const double *v, size_t n) {
  double s = 0;
  for (size_t i = 0; i < n; ++i) s = max_d(s, fabs(v[i]));
  return s;
}

/* KKT of (3.5) from the returned arrays: lambda >= 0, gap >= 0, lambda gap = 0 (relative to the
   largest force and to length_scale, the size of the displacements and initial gaps); plus
   the library's own residual infos. */
void assert_kkt(mc_model *m, const contact_data *c, double length_scale) {
  double fmax = max_d(max_abs(c->force, (size_t)c->n), 1e-300);
  for (mc_int j = 0; j < c->n; ++j) {
    ck_assert_msg(c->force[j] >= 0, "lambda_%d = %g < 0", (int)j, c->force[j]);
    if (isfinite(c->gap[j])) {
      ck_assert_msg(c->gap[j] >= -1e-10 * length_scale, "gap_%d = %g < 0 (scale %g)", (int)j, c->gap[j], length_scale);
      /* complementarity per node, except next to a node that sees no mortar surface: Gamma_c
         then ends inside the segment between them, and the row there (touching, gap 0) passes a
         share of its force to this node, whose own gap may be open */
      const int next_to_end = (j > 0 && !isfinite(c->gap[j - 1])) || (j + 1 < c->n && !isfinite(c->gap[j + 1]));
      if (!next_to_end)
        ck_assert_msg(fabs(c->force[j] * c->gap[j]) <= 1e-10 * fmax * length_scale, "lambda gap at %d = %g", (int)j,
                      c->force[j] * c->gap[j]);
    }
    /* a node that sees no mortar surface may still carry force: its share of the row at the
       end of Gamma_c inside its partly covered segment */
  }
  double equilibrium, complementarity;
  OK(mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium));
  OK(mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity));
  ck_assert_msg(equilibrium < 1e-10, "equilibrium residual %g", equilibrium);
  ck_assert_msg(complementarity < 1e-10, "complementarity %g", complementarity);
  double gap_residual;
  OK(mc_get_info_real(m, MC_INFO_GAP_RESIDUAL, &gap_residual));
  ck_assert_msg(gap_residual < 1e-10, "gap residual of the returned displacements %g", gap_residual);
}

/* Largest |displacement| of both bodies and |g0| of the seeing nodes: the length scale of the
   gap checks. */
double length_scale_of(mc_model *m, const mc_int n_nodes[2], const contact_data *c) {
  double s = 1e-300;
  for (int b = 0; b < 2; ++b) {
    double *u = displacement(m, b + 1, n_nodes[b]);
    s = max_d(s, max_abs(u, 2 * (size_t)n_nodes[b]));
    free(u);
  }
  for (mc_int j = 0; j < c->n; ++j)
    if (isfinite(c->g0[j])) s = max_d(s, fabs(c->g0[j]));
  return s;
}

/* Force balance of each body from returned data: support reactions + applied loads (their
   resultants load[b]) + contact forces = 0; body 1 receives -lambda_j n_j, body 2 the opposite. */
void assert_force_balance(mc_model *m, const contact_data *c, const mc_int n_nodes[2], const double load1[2],
                                 const double load2[2]) {
  double contact[2] = {0, 0}, fmax = 0;
  for (mc_int j = 0; j < c->n; ++j) {
    contact[0] -= c->force[j] * c->normal[2 * j], contact[1] -= c->force[j] * c->normal[2 * j + 1];
    fmax = max_d(fmax, c->force[j]);
  }
  for (int b = 0; b < 2; ++b) {
    double *r = malloc(sizeof(double) * 2 * (size_t)n_nodes[b]), sum[2] = {0, 0}, rmax = 0;
    OK(mc_get_reaction(m, b + 1, r));
    for (mc_int i = 0; i < n_nodes[b]; ++i) {
      sum[0] += r[2 * i], sum[1] += r[2 * i + 1];
      rmax = max_d(rmax, max_d(fabs(r[2 * i]), fabs(r[2 * i + 1])));
    }
    const double *load = b == 0 ? load1 : load2;
    const double sign = b == 0 ? 1 : -1;
    const double scale =
        max_d(fabs(load[0]) + fabs(load[1]) + fabs(contact[0]) + fabs(contact[1]) + fmax + rmax, 1e-300);
    for (int k = 0; k < 2; ++k)
      ck_assert_msg(fabs(sum[k] + load[k] + sign * contact[k]) <= 1e-10 * scale,
                    "body %d component %d: reactions %g + loads %g + contact %g != 0", b + 1, k, sum[k], load[k],
                    sign * contact[k]);
    free(r);
  }
}

void assert_kkt_and_balance(mc_model *m, const mc_int n_nodes[2], const double load1[2], const double load2[2]) {
  contact_data c = contact_get(m);
  assert_kkt(m, &c, length_scale_of(m, n_nodes, &c));
  assert_force_balance(m, &c, n_nodes, load1, load2);
  contact_free(&c);
}

long info_int(mc_model *m, int info) {
  int64_t v = 0;
  OK(mc_get_info_int(m, info, &v));
  return (long)v;
}

/* ---- the Hertz scene in any role and unit system -------------------------------------------- */

void hertz_build(hertz_run *r, const hertz_setup *hs) {
  mc_model *m = NULL;
  memset(r, 0, sizeof *r);
  ck_assert_int_eq(hertz_scene_build(&r->scene, hs->h_disc, hs->h_block, 0), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  r->m = m;
  const int disc = hs->disc_body, block = 3 - disc;
  for (int s = 0; s < 2; ++s) { /* s = 0 the disc, s = 1 the block */
    const hertz_mesh *hm = &r->scene.body[s];
    const int body = s == 0 ? disc : block;
    double *xy = malloc(sizeof(double) * 2 * (size_t)hm->n_nodes);
    for (int i = 0; i < 2 * hm->n_nodes; ++i) xy[i] = hs->length * hm->xy[i];
    OK(mc_set_mesh(m, body, hm->n_nodes, xy, hm->n_cells, 3, hm->cells));
    OK(mc_set_material(m, body, hs->young * 1.0, 0.3));
    OK(mc_set_contact(m, body, r->scene.n_contact_edges[s], r->scene.contact_edges[s]));
    r->n_nodes[body - 1] = hm->n_nodes;
    r->mesh[body - 1] = hm;
    if (body == 1) r->xy1 = xy;
    else free(xy);
  }
  OK(mc_set_plane(m, MC_PLANE_STRAIN, hs->length));
  OK(mc_fix(m, disc, r->scene.n_axis_nodes, r->scene.axis_nodes, MC_X, NULL));
  OK(mc_fix(m, block, r->scene.n_bottom_nodes, r->scene.bottom_nodes, MC_XY, NULL));
  /* P = 0.01 (per unit thickness, E = 1) on the flat top of width 2 */
  const double traction = -0.01 / 2 * hs->young;
  double *t = malloc(sizeof(double) * 2 * (size_t)r->scene.n_top_edges);
  for (int e = 0; e < r->scene.n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = traction;
  OK(mc_add_traction(m, disc, r->scene.n_top_edges, r->scene.top_edges, t));
  free(t);
  r->load_total = 0.01 * hs->young * hs->length * hs->length;
  OK(mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, hs->normal));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, hs->method));
  OK(mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, hs->surface));
}

void hertz_free(hertz_run *r) {
  mc_destroy(r->m);
  free(r->xy1);
  hertz_scene_free(&r->scene);
}

/* The loads on each body (resultants) for the balance check. */
void hertz_loads(const hertz_run *r, const hertz_setup *hs, double load1[2], double load2[2]) {
  load1[0] = load1[1] = load2[0] = load2[1] = 0;
  (hs->disc_body == 1 ? load1 : load2)[1] = -r->load_total;
}

/* Two estimates free of the mesh-spacing quantization of the loaded-node count: p^2 is linear
   in x^2 for the Hertz profile, so a least-squares line through the nodes with p > 0.3 p0 (away
   from the ends, where the lumped pressure of a partly loaded node is not the point value)
   gives p0; the half-width comes from the second moment of the nodal forces, an integral that
   does not see a nodal ripple: sum lambda x^2 / sum lambda = a^2/4 for a Hertz profile. */
hertz_measure hertz_profile_of(const contact_data *cd, const double *xy1, double length) {
  const contact_data c = *cd;
  hertz_measure h;
  memset(&h, 0, sizeof h);
  double left = 0, right = 0, gap_left = -INFINITY, gap_right = INFINITY;
  for (mc_int j = 0; j < c.n; ++j) h.p0 = max_d(h.p0, c.pressure[j]);
  double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0, m0 = 0, m2 = 0;
  for (mc_int j = 0; j < c.n; ++j) {
    const double x = xy1[2 * c.nodes[j]] / length, p = c.pressure[j];
    h.vertical -= c.force[j] * c.normal[2 * j + 1];
    m0 += c.force[j], m2 += c.force[j] * x * x;
    if (p > 0) left = fmin(left, x), right = fmax(right, x);
    else if (isfinite(c.gap[j])) {
      if (x < 0) gap_left = fmax(gap_left, x);
      else gap_right = fmin(gap_right, x);
    }
    if (p > 0.3 * h.p0) {
      const double X = x * x, Y = p * p;
      s0 += 1, s1 += X, s2 += X * X, t0 += Y, t1 += X * Y;
    }
  }
  const double slope = (s0 * t1 - s1 * t0) / (s0 * s2 - s1 * s1), intercept = (t0 - slope * s1) / s0;
  h.p0_fit = sqrt(intercept);
  h.a_fit = 2 * sqrt(m2 / m0);
  h.a_nodes = 0.5 * (right - left);
  h.gap_edge = 0.5 * (gap_right - gap_left);
  return h;
}

hertz_measure hertz_measure_of(const hertz_run *r, double length) {
  contact_data c = contact_get(r->m);
  hertz_measure h = hertz_profile_of(&c, r->xy1, length);
  h.iterations = info_int(r->m, MC_INFO_ITERATIONS);
  h.active = info_int(r->m, MC_INFO_ACTIVE_NODES);
  contact_free(&c);
  return h;
}

hertz_measure hertz_solve(const hertz_setup *hs) {
  hertz_run r;
  hertz_build(&r, hs);
  mc_model *m = r.m;
  OK(mc_solve(m));
  double load1[2], load2[2];
  hertz_loads(&r, hs, load1, load2);
  assert_kkt_and_balance(m, r.n_nodes, load1, load2);
  hertz_measure h = hertz_measure_of(&r, hs->length);
  h.p0 /= hs->young;
  h.p0_fit /= hs->young;
  /* the upward force on the disc: body 1 receives -lambda n, body 2 the opposite */
  h.vertical *= (hs->disc_body == 1 ? 1 : -1) / (hs->young * hs->length * hs->length);
  hertz_free(&r);
  return h;
}