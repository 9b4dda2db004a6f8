/*
 * test_contact.c - the mortar contact solve (issue: the paper's method, solved exactly).
 *
 * - contact patch test on non-matching meshes: mortar and dual mortar transmit a uniform
 *   pressure exactly; node-to-segment does not (its error is measured and reported);
 * - matching meshes: the three methods coincide (the mortar cone is then pointwise);
 * - KKT conditions and the equilibrium of each body on several scenes;
 * - no contact when loads pull apart or the gap is wider than the deformation: exactly zero;
 * - gap offsets (mc_set_gap_offset): a clearance or an interference, exact on a layered scene;
 * - floating bodies: held by contact alone, or MC_ERROR_SINGULAR with an explanation;
 * - the Hertz scene: self-convergence of p0 and its error against Hertz at the finest mesh.
 */
#include "hertz_scene.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OK(call) ck_assert_msg((call) == MC_OK, "%s: %s", #call, mc_errmsg(m))

/* Two stacked blocks: body 1 = [0,1]x[0,h1y] on body 2 = [0,1]x[-0.5,0] (plus an initial
   vertical gap `gap` between them), nx1 and nx2 cells along the interface. Body 2 clamped
   at the bottom in y and at x = 0 in x; body 1 has u_x = 0 on x = 0 and floats vertically
   unless `clamp_top`. */
typedef struct blocks {
  sc_mesh mesh[2];
  mc_model *m;
} blocks;

static void blocks_build(blocks *s, int npc, int nx1, int nx2, double gap, double e1, double e2, int method) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  s->m = m;
  ck_assert_int_eq(sc_mesh_rect(&s->mesh[0], npc, nx1, 4, 0, gap, 1, 0.5, 0, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&s->mesh[1], npc, nx2, 3, 0, -0.5, 1, 0.5, 0, 2), 0);
  for (int b = 0; b < 2; ++b) OK(sc_set_mesh(m, b + 1, &s->mesh[b], 0));
  OK(mc_set_material(m, 1, e1, 0.3));
  OK(mc_set_material(m, 2, e2, 0.3));
  OK(sc_fix_side(m, 1, &s->mesh[0], SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &s->mesh[1], SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &s->mesh[1], SC_BOTTOM, MC_Y, 0));
  OK(mc_set_contact(m, 1, s->mesh[0].n_side_edges[SC_BOTTOM], s->mesh[0].side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, s->mesh[1].n_side_edges[SC_TOP], s->mesh[1].side_edges[SC_TOP]));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
}

static void blocks_free(blocks *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->mesh[0]);
  sc_mesh_free(&s->mesh[1]);
}

static double *contact_array(mc_model *m, mc_status (*get)(const mc_model *, double *), int *n) {
  mc_int count = 0;
  ck_assert_int_eq(mc_get_contact_count(m, &count), MC_OK);
  double *v = malloc(sizeof(double) * 2 * (count + 1));
  ck_assert_int_eq(get(m, v), MC_OK);
  *n = count;
  return v;
}

/* The KKT conditions of (3.5) on the returned arrays, and equilibrium of both bodies:
   reactions + applied loads + contact forces = 0 for each body (applied loads passed in). */
static void check_kkt_and_equilibrium(blocks *s, const double load1[2], const double load2[2]) {
  mc_model *m = s->m;
  int n;
  double *f = contact_array(m, mc_get_contact_force, &n), *g = contact_array(m, mc_get_contact_gap, &n);
  double *normal = malloc(sizeof(double) * 2 * n);
  OK(mc_get_contact_normal(m, normal));
  /* gaps are measured against the size of the displacements (they are round-off when all
     nodes are active) */
  double fmax = 1e-300, gmax = 1e-300;
  for (int b = 0; b < 2; ++b) {
    double *u = malloc(sizeof(double) * 2 * s->mesh[b].n_nodes);
    OK(mc_get_displacement(m, b + 1, u));
    for (mc_int i = 0; i < 2 * s->mesh[b].n_nodes; ++i) gmax = gmax > fabs(u[i]) ? gmax : fabs(u[i]);
    free(u);
  }
  for (int j = 0; j < n; ++j) {
    fmax = fmax > fabs(f[j]) ? fmax : fabs(f[j]);
    if (isfinite(g[j])) gmax = gmax > fabs(g[j]) ? gmax : fabs(g[j]);
  }
  double contact[2] = {0, 0};
  for (int j = 0; j < n; ++j) {
    ck_assert_msg(f[j] >= 0, "lambda_%d = %g < 0", j, f[j]);
    if (isfinite(g[j])) {
      ck_assert_msg(g[j] >= -1e-10 * gmax, "gap_%d = %g < 0", j, g[j]);
      ck_assert_msg(fabs(f[j] * g[j]) <= 1e-10 * fmax * gmax, "lambda*gap at %d = %g", j, f[j] * g[j]);
    } else {
      ck_assert_msg(f[j] == 0, "node %d sees no mortar surface but carries %g", j, f[j]);
    }
    contact[0] -= f[j] * normal[2 * j], contact[1] -= f[j] * normal[2 * j + 1];
  }
  double scale = fabs(load1[0]) + fabs(load1[1]) + fabs(load2[0]) + fabs(load2[1]) + fmax;
  for (int b = 0; b < 2; ++b) {
    double *r = malloc(sizeof(double) * 2 * s->mesh[b].n_nodes), sum[2] = {0, 0};
    OK(mc_get_reaction(m, b + 1, r));
    for (mc_int i = 0; i < s->mesh[b].n_nodes; ++i) sum[0] += r[2 * i], sum[1] += r[2 * i + 1];
    const double *load = b == 0 ? load1 : load2;
    double sign = b == 0 ? 1 : -1; /* body 2 receives the opposite contact force */
    for (int c = 0; c < 2; ++c)
      ck_assert_msg(fabs(sum[c] + load[c] + sign * contact[c]) <= 1e-10 * scale, "body %d component %d: %g", b + 1, c,
                    sum[c] + load[c] + sign * contact[c]);
    free(r);
  }
  double equilibrium, complementarity;
  OK(mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium));
  OK(mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity));
  ck_assert_msg(equilibrium < 1e-10, "equilibrium residual %g", equilibrium);
  ck_assert_msg(complementarity < 1e-10, "complementarity %g", complementarity);
  free(f), free(g), free(normal);
}

/* ---- patch test --------------------------------------------------------- */

/* Uniform pressure p on the top of body 1 (E1) over body 2 (E2), plane strain: exact
   solution sigma_yy = -p, sigma_xx = 0 in both, u_x = nu (1+nu) p x / E, u_y linear. Returns
   the largest relative pressure error; asserts displacements when `exact`. */
static double patch_test_with(int npc, int method, int nx1, int nx2, int exact, int solver) {
  const double p = 0.3, nu = 0.3, e1 = 2, e2 = 5;
  blocks s;
  blocks_build(&s, npc, nx1, nx2, 0, e1, e2, method);
  mc_model *m = s.m;
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver));
  const sc_mesh *top = &s.mesh[0];
  double *pr = malloc(sizeof(double) * top->n_side_edges[SC_TOP]);
  for (int e = 0; e < top->n_side_edges[SC_TOP]; ++e) pr[e] = p;
  OK(mc_add_pressure(m, 1, top->n_side_edges[SC_TOP], top->side_edges[SC_TOP], pr));
  free(pr);
  OK(mc_solve(m));
  int n;
  double *pressure = contact_array(m, mc_get_contact_pressure, &n), worst = 0;
  for (int j = 0; j < n; ++j) worst = fmax(worst, fabs(pressure[j] - p) / p);
  free(pressure);
  double load1[2] = {0, -p * 1.0}, load2[2] = {0, 0};
  check_kkt_and_equilibrium(&s, load1, load2);
  if (exact) {
    double ey[2] = {-(1 - nu * nu) * p / e1, -(1 - nu * nu) * p / e2};
    double ex[2] = {nu * (1 + nu) * p / e1, nu * (1 + nu) * p / e2};
    for (int b = 0; b < 2; ++b) {
      double *u = malloc(sizeof(double) * 2 * s.mesh[b].n_nodes);
      OK(mc_get_displacement(m, b + 1, u));
      for (mc_int i = 0; i < s.mesh[b].n_nodes; ++i) {
        double x = s.mesh[b].xy[2 * i], y = s.mesh[b].xy[2 * i + 1];
        double uy = b == 1 ? ey[1] * (y + 0.5) : ey[0] * y + ey[1] * 0.5;
        ck_assert_msg(fabs(u[2 * i] - ex[b] * x) <= 1e-12 * fabs(ey[0]), "body %d node %d u_x %g vs %g", b + 1, i, u[2 * i], ex[b] * x);
        ck_assert_msg(fabs(u[2 * i + 1] - uy) <= 1e-12 * fabs(ey[0]), "body %d node %d u_y %g vs %g", b + 1, i, u[2 * i + 1], uy);
      }
      free(u);
    }
  }
  if (solver != MC_INTERFACE_AUTO) {
    int64_t ran = 0, factorizations = -1;
    OK(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &ran));
    ck_assert_int_eq(ran, solver);
    /* a re-solve at twice the load: the same active set, no new factorization, pressures 2p */
    double *more = malloc(sizeof(double) * top->n_side_edges[SC_TOP]);
    for (int e = 0; e < top->n_side_edges[SC_TOP]; ++e) more[e] = p;
    OK(mc_add_pressure(m, 1, top->n_side_edges[SC_TOP], top->side_edges[SC_TOP], more));
    free(more);
    OK(mc_solve(m));
    OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &factorizations));
    ck_assert_int_eq(factorizations, 0);
    double *twice = contact_array(m, mc_get_contact_pressure, &n);
    for (int j = 0; j < n; ++j) worst = fmax(worst, fabs(twice[j] - 2 * p) / (2 * p));
    free(twice);
  }
  blocks_free(&s);
  return worst;
}

static double patch_test(int npc, int method, int nx1, int nx2, int exact) {
  return patch_test_with(npc, method, nx1, nx2, exact, MC_INTERFACE_AUTO);
}

/* The same patch test through each interface solver forced (MC_OPTION_INTERFACE_SOLVER): exact
   on both, and a re-solve with a new load reuses the factorizations. Keeps the sparse path under
   valgrind too (test_interface_solvers compares the two paths on every scene, natively and
   under AddressSanitizer). */
START_TEST(patch_test_exact_on_both_interface_solvers) {
  const int solvers[2] = {MC_INTERFACE_CONDENSED, MC_INTERFACE_SPARSE};
  const int methods[2] = {MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR};
  for (int k = 0; k < 2; ++k)
    for (int npc = 3; npc <= 4; ++npc)
      for (int mth = 0; mth < 2; ++mth) {
        const double worst = patch_test_with(npc, methods[mth], 7, 5, 1, solvers[k]);
        ck_assert_msg(worst < 1e-12, "solver %d npc %d method %d: pressure error %g", solvers[k], npc, methods[mth], worst);
      }
}
END_TEST

START_TEST(patch_test_mortar_methods_exact) {
  int methods[2] = {MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR};
  for (int k = 0; k < 2; ++k)
    for (int npc = 3; npc <= 4; ++npc) {
      double err = patch_test(npc, methods[k], 7, 5, 1);
      ck_assert_msg(err < 1e-12, "method %d npc %d pressure error %g", methods[k], npc, err);
      err = patch_test(npc, methods[k], 5, 13, 1);
      ck_assert_msg(err < 1e-12, "method %d npc %d (finer body 2) pressure error %g", methods[k], npc, err);
    }
}
END_TEST

START_TEST(patch_test_node_to_segment_fails_measurably) {
  /* Node-to-segment is known not to pass the patch test on non-matching meshes; its
     error is reported here, and it must still satisfy KKT and equilibrium (checked inside). */
  double err = patch_test(3, MC_METHOD_NODE_TO_SEGMENT, 7, 5, 0);
  printf("node-to-segment patch test: largest relative pressure error %.3e (7 vs 5 cells)\n", err);
  ck_assert_msg(err > 1e-3 && err < 0.2, "pressure error %g", err);
  /* on matching meshes it passes */
  ck_assert_msg(patch_test(3, MC_METHOD_NODE_TO_SEGMENT, 6, 6, 1) < 1e-12, "matching meshes");
}
END_TEST

/* ---- matching meshes: the methods coincide ------------------------------ */

/* A partly open contact: p = 2 on the left half of body 1's top, -0.5 (pull) on the right. */
static void load_partial(blocks *s, double *load1) {
  mc_model *m = s->m;
  const sc_mesh *top = &s->mesh[0];
  int ne = top->n_side_edges[SC_TOP];
  double *pr = malloc(sizeof(double) * ne);
  load1[0] = load1[1] = 0;
  for (int e = 0; e < ne; ++e) {
    const mc_int *ed = top->side_edges[SC_TOP] + 2 * e;
    double xa = top->xy[2 * ed[0]], xb = top->xy[2 * ed[1]];
    pr[e] = 0.5 * (xa + xb) < 0.5 ? 2.0 : -0.5;
    load1[1] -= pr[e] * fabs(xb - xa);
  }
  OK(mc_add_pressure(m, 1, ne, top->side_edges[SC_TOP], pr));
  free(pr);
}

START_TEST(matching_meshes_methods_agree) {
  for (int npc = 3; npc <= 4; ++npc) {
    double *u_ref = NULL, *f_ref = NULL;
    int n_ref = 0;
    for (int method = 0; method < 3; ++method) {
      blocks s;
      blocks_build(&s, npc, 10, 10, 0, 1, 3, method);
      mc_model *m = s.m;
      double load1[2], load2[2] = {0, 0};
      load_partial(&s, load1);
      OK(mc_solve(m));
      check_kkt_and_equilibrium(&s, load1, load2);
      int n;
      double *f = contact_array(m, mc_get_contact_force, &n);
      double *u = malloc(sizeof(double) * 2 * s.mesh[0].n_nodes);
      OK(mc_get_displacement(m, 1, u));
      int64_t active;
      OK(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active));
      ck_assert_msg(active > 2 && active < n, "partial contact expected, %lld of %d active", (long long)active, n);
      if (!u_ref) {
        u_ref = u, f_ref = f, n_ref = n;
      } else {
        double umax = 0, lmax = 0;
        for (int i = 0; i < 2 * s.mesh[0].n_nodes; ++i) umax = fmax(umax, fabs(u_ref[i]));
        for (int j = 0; j < n; ++j) lmax = fmax(lmax, fabs(f_ref[j]));
        ck_assert_int_eq(n, n_ref);
        for (int i = 0; i < 2 * s.mesh[0].n_nodes; ++i)
          ck_assert_msg(fabs(u[i] - u_ref[i]) <= 1e-10 * umax, "method %d u[%d] %g vs %g", method, i, u[i], u_ref[i]);
        for (int j = 0; j < n; ++j)
          ck_assert_msg(fabs(f[j] - f_ref[j]) <= 1e-10 * lmax, "method %d lambda[%d] %g vs %g", method, j, f[j], f_ref[j]);
        free(u), free(f);
      }
      blocks_free(&s);
    }
    free(u_ref), free(f_ref);
  }
}
END_TEST

START_TEST(kkt_and_equilibrium_non_matching) {
  for (int method = 0; method < 3; ++method)
    for (int npc = 3; npc <= 4; ++npc) {
      blocks s;
      blocks_build(&s, npc, 13, 9, 0, 1, 10, method);
      mc_model *m = s.m;
      double load1[2], load2[2] = {0, 0};
      load_partial(&s, load1);
      /* also a body force on body 2 and a side traction on body 1 */
      OK(mc_set_body_force(m, 2, 0.1, -0.2));
      load2[0] += 0.1 * 0.5, load2[1] += -0.2 * 0.5;
      OK(sc_traction_side(m, 1, &s.mesh[0], SC_RIGHT, -0.05, 0, 0));
      load1[0] += -0.05 * 0.5;
      OK(mc_solve(m));
      check_kkt_and_equilibrium(&s, load1, load2);
      blocks_free(&s);
    }
}
END_TEST

/* ---- no contact: exactly zero ------------------------------------------- */

START_TEST(no_contact_is_exactly_zero) {
  /* (a) a gap wider than the deformation: body 1 clamped at its top, small push. */
  for (int method = 0; method < 3; ++method) {
    blocks s;
    blocks_build(&s, 3, 7, 5, 1e-3, 1, 1, method);
    mc_model *m = s.m;
    OK(sc_fix_side(m, 1, &s.mesh[0], SC_TOP, MC_XY, 0));
    OK(mc_set_body_force(m, 1, 0, -1e-3));
    OK(mc_solve(m));
    int n;
    double *p = contact_array(m, mc_get_contact_pressure, &n), *g0 = contact_array(m, mc_get_contact_initial_gap, &n);
    for (int j = 0; j < n; ++j) {
      ck_assert_msg(p[j] == 0.0, "pressure %g at %d", p[j], j);
      ck_assert_msg(fabs(g0[j] - 1e-3) < 1e-15, "g0 %g at %d", g0[j], j);
    }
    /* (b) loads that pull the bodies apart */
    OK(mc_set_body_force(m, 1, 0, +1.0));
    OK(mc_solve(m));
    free(p);
    p = contact_array(m, mc_get_contact_pressure, &n);
    for (int j = 0; j < n; ++j) ck_assert_msg(p[j] == 0.0, "pressure %g at %d", p[j], j);
    int64_t active, factorizations;
    OK(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active));
    OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &factorizations));
    ck_assert_int_eq(active, 0);
    ck_assert_int_eq(factorizations, 0); /* only the load changed: the factorization is reused */
    /* (c) a larger push closes the gap: contact, and the gap is used exactly */
    OK(mc_set_body_force(m, 1, 0, -1.0));
    OK(mc_solve(m));
    OK(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active));
    ck_assert_int_gt(active, 0);
    double *gap = contact_array(m, mc_get_contact_gap, &n), *u = malloc(sizeof(double) * 2 * s.mesh[0].n_nodes);
    OK(mc_get_displacement(m, 1, u));
    for (int j = 0; j < n; ++j) ck_assert(gap[j] >= -1e-13);
    free(p), free(g0), free(gap), free(u);
    blocks_free(&s);
  }
}
END_TEST

/* ---- gap offsets -------------------------------------------------------- */

/* Body 1's top pressed down by a prescribed u_y = -push (body 1 then has no free rigid mode). */
static void press_top(blocks *s, double push) {
  const sc_mesh *b1 = &s->mesh[0];
  mc_int n = b1->n_side_nodes[SC_TOP];
  double *values = malloc(sizeof(double) * 2 * n);
  for (mc_int i = 0; i < n; ++i) values[2 * i] = 0, values[2 * i + 1] = -push;
  ck_assert_int_eq(mc_fix(s->m, 1, n, b1->side_nodes[SC_TOP], MC_Y, values), MC_OK);
  free(values);
}

/* Largest difference between two models' body-2 displacements and contact forces. */
static double max_difference(mc_model *a, mc_model *b, mc_int n2) {
  double *ua = malloc(sizeof(double) * 2 * n2), *ub = malloc(sizeof(double) * 2 * n2), worst = 0;
  ck_assert_int_eq(mc_get_displacement(a, 2, ua), MC_OK);
  ck_assert_int_eq(mc_get_displacement(b, 2, ub), MC_OK);
  for (mc_int i = 0; i < 2 * n2; ++i) worst = fmax(worst, fabs(ua[i] - ub[i]));
  int na, nb;
  double *fa = contact_array(a, mc_get_contact_force, &na), *fb = contact_array(b, mc_get_contact_force, &nb);
  ck_assert_int_eq(na, nb);
  for (int j = 0; j < na; ++j) worst = fmax(worst, fabs(fa[j] - fb[j]));
  free(ua), free(ub), free(fa), free(fb);
  return worst;
}

/* A clearance c added by mc_set_gap_offset acts exactly like pressing c less (the layers are
   uniformly compressed, so both solutions are exact and must agree to round-off); a negative
   offset (interference) acts like pressing more. Changing offsets reuses the factorization. */
START_TEST(gap_offset_is_a_clearance_or_an_interference) {
  const double push = 1e-2, c = 4e-3;
  for (int method = 0; method < 3; ++method) {
    blocks s, ref;
    blocks_build(&s, 3, 7, 5, 0, 1, 3, method);
    mc_model *m = s.m;
    press_top(&s, push);
    OK(mc_solve(m));
    int n;
    double *g0 = contact_array(m, mc_get_contact_initial_gap, &n);
    mc_int *nodes = malloc(sizeof(mc_int) * n);
    double *offset = malloc(sizeof(double) * n);
    OK(mc_get_contact_nodes(m, nodes));
    for (double sign = 1; sign >= -1; sign -= 2) {
      for (int j = 0; j < n; ++j) offset[j] = sign * c;
      OK(mc_set_gap_offset(m, n, nodes, offset));
      OK(mc_solve(m));
      int64_t factorizations;
      OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &factorizations));
      ck_assert_int_eq(factorizations, 0);
      double *g0_offset = contact_array(m, mc_get_contact_initial_gap, &n);
      for (int j = 0; j < n; ++j) ck_assert_msg(g0_offset[j] == g0[j] + sign * c, "g0 %d: %g", j, g0_offset[j]);
      free(g0_offset);
      blocks_build(&ref, 3, 7, 5, 0, 1, 3, method);
      press_top(&ref, push - sign * c);
      ck_assert_int_eq(mc_solve(ref.m), MC_OK);
      double diff = max_difference(m, ref.m, s.mesh[1].n_nodes);
      ck_assert_msg(diff < 1e-12 * push, "method %d offset %g: differs by %g", method, sign * c, diff);
      double load[2] = {0, 0};
      check_kkt_and_equilibrium(&s, load, load);
      blocks_free(&ref);
    }
    /* bad input: a node off the contact surface, a non-finite offset; the model stays usable */
    mc_int interior = sc_node(&s.mesh[0], 3, 2);
    double one = 1;
    ck_assert_int_eq(mc_set_gap_offset(m, 1, &interior, &one), MC_ERROR_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "nodes[0]"));
    double bad = NAN;
    ck_assert_int_eq(mc_set_gap_offset(m, 1, nodes, &bad), MC_ERROR_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "offset"));
    OK(mc_solve(m));
    free(g0), free(nodes), free(offset);
    blocks_free(&s);
  }
}
END_TEST

/* Found by the fuzz corpus (tests/fuzz/corpus/new_features): body 1 free to sink and to tilt
   (u_x held at one node), one gap opened and its neighbour's closed by offsets. The primal-dual
   iteration loses the floating body, and the primal active-set fallback then passes through a
   set whose rows hold only some of the modes; it must still reach the solution. */
START_TEST(gap_offsets_tilting_a_floating_body) {
  const double offsets[4] = {0.01, 0.05, 0.125, 0.3};
  for (int method = 0; method < 3; ++method)
    for (int k = 0; k < 4; ++k) {
      blocks s;
      mc_model *m = NULL;
      ck_assert_int_eq(mc_create(&m), MC_OK);
      s.m = m;
      ck_assert_int_eq(sc_mesh_rect(&s.mesh[0], 3, 6, 3, 0, 0, 1, 0.5, 0, 1), 0);
      ck_assert_int_eq(sc_mesh_rect(&s.mesh[1], 4, 8, 4, 0, -0.5, 1, 0.5, 0, 2), 0);
      for (int b = 0; b < 2; ++b) OK(sc_set_mesh(m, b + 1, &s.mesh[b], 0));
      OK(mc_set_material(m, 1, 100, 0.3));
      OK(mc_set_material(m, 2, 200, 0.3));
      OK(sc_fix_side(m, 2, &s.mesh[1], SC_BOTTOM, MC_XY, 0));
      mc_int top_middle = sc_node(&s.mesh[0], 3, 3);
      OK(mc_fix(m, 1, 1, &top_middle, MC_X, NULL));
      const sc_mesh *b1 = &s.mesh[0];
      double *t = malloc(sizeof(double) * 2 * b1->n_side_edges[SC_TOP]);
      for (int e = 0; e < b1->n_side_edges[SC_TOP]; ++e) t[2 * e] = 0, t[2 * e + 1] = -1;
      OK(mc_add_traction(m, 1, b1->n_side_edges[SC_TOP], b1->side_edges[SC_TOP], t));
      free(t);
      OK(mc_set_contact(m, 1, b1->n_side_edges[SC_BOTTOM], b1->side_edges[SC_BOTTOM]));
      OK(mc_set_contact(m, 2, s.mesh[1].n_side_edges[SC_TOP], s.mesh[1].side_edges[SC_TOP]));
      OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
      OK(mc_solve(m));
      mc_int nodes[2] = {sc_node(b1, 1, 0), sc_node(b1, 2, 0)};
      double offset[2] = {offsets[k], -offsets[k]};
      OK(mc_set_gap_offset(m, 2, nodes, offset));
      OK(mc_solve(m));
      double load1[2] = {0, -1}, load2[2] = {0, 0};
      check_kkt_and_equilibrium(&s, load1, load2);
      blocks_free(&s);
    }
}
END_TEST

/* ---- floating bodies ---------------------------------------------------- */

START_TEST(floating_body_pulled_away_is_singular) {
  blocks s;
  blocks_build(&s, 3, 7, 5, 0, 1, 1, MC_METHOD_MORTAR);
  mc_model *m = s.m;
  OK(mc_set_body_force(m, 1, 0, +0.5)); /* body 1 floats vertically and is pulled up */
  ck_assert_int_eq(mc_solve(m), MC_ERROR_SINGULAR);
  ck_assert_msg(strstr(mc_errmsg(m), "cannot be balanced") != NULL, "%s", mc_errmsg(m));
  /* the handle stays usable: push instead */
  OK(mc_set_body_force(m, 1, 0, -0.5));
  OK(mc_solve(m));
  double load1[2] = {0, -0.5 * 0.5}, load2[2] = {0, 0};
  check_kkt_and_equilibrium(&s, load1, load2);
  blocks_free(&s);
}
END_TEST

START_TEST(floating_in_all_modes_without_contact_is_singular) {
  mc_model *m = NULL;
  sc_mesh mesh;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  ck_assert_int_eq(sc_mesh_rect(&mesh, 3, 4, 4, 0, 0, 1, 1, 0, 1), 0);
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  ck_assert_int_eq(mc_solve(m), MC_ERROR_SINGULAR);
  ck_assert_msg(strstr(mc_errmsg(m), "body 1") && strstr(mc_errmsg(m), "rotation"), "%s", mc_errmsg(m));
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- partial overlap ---------------------------------------------------- */

/* Body 1 = [-0.25,1.25]x[0,0.5] is wider than body 2 = [0,1]x[-0.5,0]: its contact nodes
   beyond body 2's ends see no mortar surface and drop out (zero force, gap +infinity); the
   rest carries the load, with KKT and equilibrium. */
START_TEST(partial_overlap_drops_unseen_nodes) {
  for (int method = 0; method < 3; ++method) {
    blocks s;
    mc_model *m = NULL;
    ck_assert_int_eq(mc_create(&m), MC_OK);
    s.m = m;
    ck_assert_int_eq(sc_mesh_rect(&s.mesh[0], 3, 12, 4, -0.25, 0, 1.5, 0.5, 0, 1), 0);
    ck_assert_int_eq(sc_mesh_rect(&s.mesh[1], 3, 7, 3, 0, -0.5, 1, 0.5, 0, 2), 0);
    for (int b = 0; b < 2; ++b) OK(sc_set_mesh(m, b + 1, &s.mesh[b], 0)), OK(mc_set_material(m, b + 1, 1, 0.3));
    OK(sc_fix_side(m, 1, &s.mesh[0], SC_LEFT, MC_X, 0));
    OK(sc_fix_side(m, 2, &s.mesh[1], SC_LEFT, MC_X, 0));
    OK(sc_fix_side(m, 2, &s.mesh[1], SC_BOTTOM, MC_Y, 0));
    OK(mc_set_contact(m, 1, s.mesh[0].n_side_edges[SC_BOTTOM], s.mesh[0].side_edges[SC_BOTTOM]));
    OK(mc_set_contact(m, 2, s.mesh[1].n_side_edges[SC_TOP], s.mesh[1].side_edges[SC_TOP]));
    OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
    OK(mc_set_body_force(m, 1, 0, -1.0));
    OK(mc_solve(m));
    double load1[2] = {0, -1.0 * 1.5 * 0.5}, load2[2] = {0, 0};
    check_kkt_and_equilibrium(&s, load1, load2);
    int n;
    double *f = contact_array(m, mc_get_contact_force, &n), *g = contact_array(m, mc_get_contact_gap, &n);
    mc_int *nodes = malloc(sizeof(mc_int) * n);
    OK(mc_get_contact_nodes(m, nodes));
    int unseen = 0, loaded = 0;
    for (int j = 0; j < n; ++j) {
      double x = s.mesh[0].xy[2 * nodes[j]];
      if (x < -1e-12 || x > 1 + 1e-12) {
        ck_assert_msg(isinf(g[j]) && f[j] == 0.0, "node at x = %g: gap %g force %g", x, g[j], f[j]);
        ++unseen;
      } else {
        ck_assert_msg(isfinite(g[j]), "node at x = %g sees body 2", x);
        loaded += f[j] > 0;
      }
    }
    ck_assert_int_eq(unseen, 4);
    ck_assert_int_gt(loaded, 2);
    free(f), free(g), free(nodes);
    blocks_free(&s);
  }
}
END_TEST

/* ---- Hertz -------------------------------------------------------------- */

typedef struct hertz_result {
  double p0, a, vertical_force;
  long dofs;
} hertz_result;

static hertz_result solve_hertz(double h1, int normal) {
  hertz_scene scene;
  ck_assert_int_eq(hertz_scene_build(&scene, h1, 1.37 * h1, 0), 0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  for (int b = 0; b < 2; ++b) {
    OK(mc_set_mesh(m, b + 1, scene.body[b].n_nodes, scene.body[b].xy, scene.body[b].n_cells, 3, scene.body[b].cells));
    OK(mc_set_material(m, b + 1, 1, 0.3));
  }
  OK(mc_fix(m, 1, scene.n_axis_nodes, scene.axis_nodes, MC_X, NULL));
  OK(mc_fix(m, 2, scene.n_bottom_nodes, scene.bottom_nodes, MC_XY, NULL));
  double *t = malloc(sizeof(double) * 2 * scene.n_top_edges);
  for (int e = 0; e < scene.n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -0.01 / 2;
  OK(mc_add_traction(m, 1, scene.n_top_edges, scene.top_edges, t));
  OK(mc_set_contact(m, 1, scene.n_contact_edges[0], scene.contact_edges[0]));
  OK(mc_set_contact(m, 2, scene.n_contact_edges[1], scene.contact_edges[1]));
  OK(mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, normal));
  OK(mc_solve(m));
  int n;
  double *p = contact_array(m, mc_get_contact_pressure, &n), *f = contact_array(m, mc_get_contact_force, &n);
  double *normals = malloc(sizeof(double) * 2 * n);
  mc_int *nodes = malloc(sizeof(mc_int) * n);
  OK(mc_get_contact_normal(m, normals));
  OK(mc_get_contact_nodes(m, nodes));
  hertz_result r = {0, 0, 0, 0};
  double left = 0, right = 0;
  for (int j = 0; j < n; ++j) {
    double x = scene.body[0].xy[2 * nodes[j]];
    r.p0 = fmax(r.p0, p[j]);
    r.vertical_force -= f[j] * normals[2 * j + 1];
    if (p[j] > 0) left = fmin(left, x), right = fmax(right, x);
  }
  r.a = 0.5 * (right - left); /* outermost loaded nodes: a is known to within the spacing h1 */
  int64_t dofs;
  OK(mc_get_info_int(m, MC_INFO_DOFS, &dofs));
  r.dofs = (long)dofs;
  free(p), free(f), free(normals), free(nodes), free(t);
  mc_destroy(m);
  hertz_scene_free(&scene);
  return r;
}

/* Mesh study (docs/contact.md): with body 1's normals p0 converges to +0.75 % of Hertz (the
   O((a/R)^2) effect of measuring the gap along the disc's radial normals instead of Hertz's
   vertical parabola); with body 2's normals to -0.18 % (the finite bodies). p0 differences
   between levels fall below 0.05 % from h1 = 0.01 on. */
START_TEST(hertz_self_convergence_and_error) {
  double a_hertz, p0_hertz;
  hertz_analytic(&a_hertz, &p0_hertz);
  const double h[3] = {0.02, 0.01, 0.005};
  for (int normal = 0; normal < 2; ++normal) {
    hertz_result r[3];
    for (int k = 0; k < 3; ++k) {
      r[k] = solve_hertz(h[k], normal);
      printf("Hertz %s normals h1 = %.3f: DOFs %ld p0 %.6g (%+.3f %%) a %.5g (%+.2f %%)\n",
             normal ? "mortar" : "non-mortar", h[k], r[k].dofs, r[k].p0, 100 * (r[k].p0 / p0_hertz - 1), r[k].a,
             100 * (r[k].a / a_hertz - 1));
      ck_assert_msg(fabs(r[k].vertical_force - 0.01) < 1e-12, "vertical contact force %.15g", r[k].vertical_force);
      ck_assert_msg(fabs(r[k].a - a_hertz) <= 1.5 * h[k], "a = %g vs %g at h1 %g", r[k].a, a_hertz, h[k]);
    }
    double d1 = fabs(r[1].p0 - r[0].p0), d2 = fabs(r[2].p0 - r[1].p0);
    ck_assert_msg(d2 < 5e-4 * p0_hertz, "p0 not self-converged: %g", d2 / p0_hertz);
    ck_assert_msg(d2 <= d1 + 1e-4 * p0_hertz, "p0 differences do not shrink: %g then %g", d1, d2);
    double err = r[2].p0 / p0_hertz - 1;
    if (normal == MC_NORMAL_NONMORTAR) ck_assert_msg(err > 0.005 && err < 0.010, "p0 error %g", err);
    else ck_assert_msg(fabs(err) < 0.004, "p0 error %g", err);
  }
}
END_TEST

int main(void) {
  Suite *suite = suite_create("contact");
  TCase *tc = tcase_create("contact");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, patch_test_mortar_methods_exact);
  tcase_add_test(tc, patch_test_exact_on_both_interface_solvers);
  tcase_add_test(tc, patch_test_node_to_segment_fails_measurably);
  tcase_add_test(tc, matching_meshes_methods_agree);
  tcase_add_test(tc, kkt_and_equilibrium_non_matching);
  tcase_add_test(tc, no_contact_is_exactly_zero);
  tcase_add_test(tc, gap_offset_is_a_clearance_or_an_interference);
  tcase_add_test(tc, gap_offsets_tilting_a_floating_body);
  tcase_add_test(tc, floating_body_pulled_away_is_singular);
  tcase_add_test(tc, floating_in_all_modes_without_contact_is_singular);
  tcase_add_test(tc, partial_overlap_drops_unseen_nodes);
  tcase_add_test(tc, hertz_self_convergence_and_error);
  suite_add_tcase(suite, tc);
  return sc_run_suite(suite);
}
