/*
 * test_error_estimate.c - MC_INFO_ERROR_ESTIMATE and mc_get_error_indicator (issue 23).
 *
 * - patch tests (uniform stress across a non-matching contact interface, every pair of a few cell
 *   kinds): the estimate is round-off;
 * - effectivity (estimate / true error) within 0.7 to 1.5 on Lame's shrink fit, the true energy
 *   error computed by quadrature of the closed-form field against the finite element field:
 *   axisymmetric (hub on a solid shaft, the plane-stress Lame field exact) for P1, Q1, T6, Q8, Q9 at
 *   two sizes; plane strain (quarter rings with curved edges, symmetry supports) for T6, Q8, Q9;
 * - the indicators' squares add up to the estimate's square, and the cells where they are largest
 *   hold most of the true error;
 * - MC_OPTION_ERROR_ESTIMATE = 0: no estimate, mc_get_error_indicator refuses; a host body has none.
 */
#include "cell_kind_name.h"
#include "check_helpers.h"
#include "host_assembly.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static double info_real(mc_model *m, int info) {
  double v = 0;
  OK(mc_get_info_real(m, info, &v));
  return v;
}

/* The estimate's absolute size eta from the relative one: eta^2 = e^2 u^T K u / (1 - e^2). */
static double absolute_estimate(mc_model *m) {
  const double e = info_real(m, MC_INFO_ERROR_ESTIMATE), w = info_real(m, MC_INFO_STRAIN_ENERGY);
  return sqrt(e * e * 2 * w / (1 - e * e));
}

/* ---- the true energy error by quadrature ------------------------------------------------------ */

/* Exact strains at (x, y): plane (xx, yy, engineering xy) or axisymmetric (rr, zz, rz, tt). */
typedef void (*exact_strain_fn)(const void *ctx, double x, double y, double *eps);

/* Per cell: the energy of e = u - u_h, integrated by a 7-point degree-5 rule (triangles) or 4x4
   Gauss (quadrilaterals) on the isoparametric map, u_h from the nodal displacements by the
   cell's shape functions (host_assembly.h, written independently of the library). */
static void cell_errors(const sc_mesh *mesh, const double *u, int axisymmetric, const double *D, exact_strain_fn exact,
                        const void *ctx, double *err2) {
  const int npc = mesh->npc, tri = npc == 3 || npc == 6, ns = axisymmetric ? 4 : 3;
  double pts[32], wts[16];
  int nq = 0;
  if (tri) {
    const double a1 = 0.059715871789770, b1 = 0.470142064105115, a2 = 0.797426985353087, b2 = 0.101286507323456;
    const double P[7][2] = {{1.0 / 3, 1.0 / 3}, {b1, b1}, {a1, b1}, {b1, a1}, {b2, b2}, {a2, b2}, {b2, a2}};
    const double W[7] = {0.1125, 0.066197076394253, 0.066197076394253, 0.066197076394253,
                         0.0629695902724135, 0.0629695902724135, 0.0629695902724135};
    for (int q = 0; q < 7; ++q) pts[2 * q] = P[q][0], pts[2 * q + 1] = P[q][1], wts[q] = W[q];
    nq = 7;
  } else {
    const double g[4] = {-0.861136311594053, -0.339981043584856, 0.339981043584856, 0.861136311594053};
    const double w[4] = {0.347854845137454, 0.652145154862546, 0.652145154862546, 0.347854845137454};
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) pts[2 * nq] = g[i], pts[2 * nq + 1] = g[j], wts[nq++] = w[i] * w[j];
  }
  for (mc_int c = 0; c < mesh->n_cells; ++c) {
    const mc_int *v = mesh->cells + (size_t)c * npc;
    err2[c] = 0;
    for (int q = 0; q < nq; ++q) {
      double N[9], dxi[9], deta[9];
      ha_shape(npc, pts[2 * q], pts[2 * q + 1], N, dxi, deta);
      double j11 = 0, j12 = 0, j21 = 0, j22 = 0, x = 0, y = 0;
      for (int a = 0; a < npc; ++a) {
        const double *p = mesh->xy + 2 * v[a];
        j11 += dxi[a] * p[0], j12 += dxi[a] * p[1], j21 += deta[a] * p[0], j22 += deta[a] * p[1];
        x += N[a] * p[0], y += N[a] * p[1];
      }
      const double det = j11 * j22 - j12 * j21;
      double eh[4] = {0, 0, 0, 0}, e[4] = {0, 0, 0, 0}, d[4];
      for (int a = 0; a < npc; ++a) {
        const double dx = (j22 * dxi[a] - j12 * deta[a]) / det, dy = (-j21 * dxi[a] + j11 * deta[a]) / det;
        const double ux = u[2 * v[a]], uy = u[2 * v[a] + 1];
        eh[0] += dx * ux, eh[1] += dy * uy, eh[2] += dy * ux + dx * uy;
        if (axisymmetric) eh[3] += N[a] * ux / x;
      }
      exact(ctx, x, y, e);
      for (int k = 0; k < ns; ++k) d[k] = e[k] - eh[k];
      double energy = 0;
      for (int i = 0; i < ns; ++i)
        for (int k = 0; k < ns; ++k) energy += d[i] * D[ns * i + k] * d[k];
      err2[c] += wts[q] * det * (axisymmetric ? 2 * PI * x : 1) * energy;
    }
  }
}

/* ---- Lame: the axisymmetric shrink fit ---------------------------------------------------------- */

/* A hub b <= r <= c on a solid shaft r <= b (both 0 <= z <= 1, free ends: rollers on z = 0),
   interference delta: sigma_r = sigma_t = -p in the shaft, Lame's in the hub, sigma_z = 0, with
   p = E delta (c^2 - b^2) / (2 b c^2) (equal moduli). */
typedef struct axi_fit {
  double b, c, p, young, nu;
  int body; /* 0 shaft, 1 hub */
} axi_fit;

static void axi_strain(const void *ctx, double r, double z, double *e) {
  const axi_fit *f = ctx;
  (void)z;
  double sr, st;
  if (f->body == 0) {
    sr = st = -f->p;
  } else {
    const double d = f->c * f->c - f->b * f->b, A = f->p * f->b * f->b / d, B = f->p * f->b * f->b * f->c * f->c / d;
    sr = A - B / (r * r), st = A + B / (r * r);
  }
  e[0] = (sr - f->nu * st) / f->young, e[1] = -f->nu * (sr + st) / f->young, e[2] = 0;
  e[3] = (st - f->nu * sr) / f->young;
}

typedef struct effectivity {
  double true_error, estimate, relative, correlation;
  long dofs;
} effectivity;

/* Where the indicators are large, the true error is: the correlation of the cells' indicators
   with their true errors (eta_K against sqrt of the cell's true error^2). */
static double correlation(const double *eta, const double *err2, mc_int n) {
  double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
  for (mc_int c = 0; c < n; ++c) mx += eta[c] / n, my += sqrt(err2[c]) / n;
  for (mc_int c = 0; c < n; ++c) {
    const double dx = eta[c] - mx, dy = sqrt(err2[c]) - my;
    sxx += dx * dx, syy += dy * dy, sxy += dx * dy;
  }
  return sxy / sqrt(sxx * syy);
}

static effectivity axisymmetric_shrink_fit(int npc, int level) {
  const int s = 1 << level, quadratic = npc > 4;
  const double b = 1, c = 2, delta = 1e-3, young = 1, nu = 0.3, p = young * delta * (c * c - b * b) / (2 * b * c * c);
  sc_mesh shaft, hub;
  ck_assert_int_eq(sc_mesh_cells(&shaft, npc, (quadratic ? 4 : 8) * s, (quadratic ? 6 : 12) * s, 0, 0, b, 1, 0), 0);
  ck_assert_int_eq(sc_mesh_cells(&hub, npc, (quadratic ? 4 : 8) * s, (quadratic ? 9 : 17) * s, b, 0, c - b, 1, 1), 0);
  mc_model *m = sc_axisymmetric_shrink_fit(&shaft, &hub, young, nu, delta);
  ck_assert_ptr_nonnull(m);
  SUCCEEDS(mc_solve(m));
  double D[16];
  ha_law_axisymmetric(young, nu, D);
  const sc_mesh *mesh[2] = {&shaft, &hub};
  double err2 = 0, eta2 = 0, share = 0;
  for (int k = 0; k < 2; ++k) {
    double *u = malloc(sizeof(double) * 2 * (size_t)mesh[k]->n_nodes), *e2 = malloc(sizeof(double) * (size_t)mesh[k]->n_cells);
    double *eta = malloc(sizeof(double) * (size_t)mesh[k]->n_cells);
    OK(mc_get_displacement(m, k + 1, u));
    OK(mc_get_error_indicator(m, k + 1, eta));
    const axi_fit f = {b, c, p, young, nu, k};
    cell_errors(mesh[k], u, 1, D, axi_strain, &f, e2);
    for (mc_int i = 0; i < mesh[k]->n_cells; ++i) err2 += e2[i], eta2 += eta[i] * eta[i];
    if (k == 1) share = correlation(eta, e2, mesh[k]->n_cells); /* the hub: its error is largest at the bore */
    free(u), free(e2), free(eta);
  }
  effectivity out;
  const double relative = info_real(m, MC_INFO_ERROR_ESTIMATE);
  ck_assert_msg(fabs(eta2 - relative * relative) <= 1e-12 * relative * relative, "indicators^2 sum %.17g, estimate^2 %.17g",
                eta2, relative * relative);
  out.true_error = sqrt(err2), out.estimate = absolute_estimate(m), out.relative = relative, out.correlation = share;
  int64_t dofs;
  OK(mc_get_info_int(m, MC_INFO_DOFS, &dofs));
  out.dofs = (long)dofs;
  mc_destroy(m);
  sc_mesh_free(&shaft), sc_mesh_free(&hub);
  return out;
}

START_TEST(effectivity_axisymmetric_shrink_fit) {
  const int kinds[5] = {3, 4, 6, 8, 9};
  for (int k = 0; k < 5; ++k)
    for (int level = 0; level < 2; ++level) {
      const effectivity e = axisymmetric_shrink_fit(kinds[k], level);
      const double ratio = e.estimate / e.true_error;
      printf("axisymmetric shrink fit, %s, %ld DOFs: true energy error %.3e, estimate %.3e (relative %.2e), "
             "effectivity %.3f; the hub's indicators against its cells' true errors: correlation %.3f\n",
             cell_kind_name(kinds[k]), e.dofs, e.true_error, e.estimate, e.relative, ratio, e.correlation);
      ck_assert_msg(ratio >= 0.7 && ratio <= 1.5, "%s: effectivity %.3f", cell_kind_name(kinds[k]), ratio);
      ck_assert_msg(e.correlation >= 0.9, "%s: indicators against true cell errors: correlation %.3f",
                    cell_kind_name(kinds[k]), e.correlation);
    }
}
END_TEST

/* ---- Lame in plane strain: quarter rings with curved edges ----------------------------------- */

/* Plane-strain Lame strains of the ring ri <= r <= ro under internal pi and external po. */
typedef struct ring_lame {
  double ri, ro, pi, po, young, nu;
} ring_lame;

static void ring_strain(const void *ctx, double x, double y, double *e) {
  const ring_lame *L = ctx;
  const double d = L->ro * L->ro - L->ri * L->ri, A = (L->pi * L->ri * L->ri - L->po * L->ro * L->ro) / d,
               B = (L->pi - L->po) * L->ri * L->ri * L->ro * L->ro / d;
  const double r2 = x * x + y * y, k = (1 + L->nu) / L->young;
  const double er = k * ((1 - 2 * L->nu) * A - B / r2), et = k * ((1 - 2 * L->nu) * A + B / r2);
  const double c = x * x / r2, s = y * y / r2, cs = x * y / r2;
  e[0] = er * c + et * s, e[1] = er * s + et * c, e[2] = 2 * (er - et) * cs;
}

/* The rectangle [0, 1] x [0, 1] onto the quarter annulus: x -> r in [r0, r1], y -> angle in
   [0, pi/2]; every node, a quadratic cell's middles included, lands on its circle or ray. */
typedef struct annulus {
  double r0, r1;
} annulus;

static void to_annulus(double *x, double *y, void *ctx) {
  const annulus *a = ctx;
  const double r = a->r0 + (*x) * (a->r1 - a->r0), t = 0.5 * PI * (*y);
  *x = *y == 1 ? 0 : r * cos(t);
  *y = *y == 0 ? 0 : r * sin(t);
}

/* Shaft quarter ring [0.5, 1 + delta] (body 1) in a hub quarter ring [1, 2] (body 2), plane strain,
   E1 = 1, E2 = 2: symmetry supports (u_y = 0 on y = 0, u_x = 0 on x = 0), contact on the quarter
   arcs. Returns the effectivity. */
static double plane_strain_shrink_fit(int npc, int level, long *dofs_out) {
  const int s = 1 << level;
  const double a = 0.5, R = 1, c = 2, delta = 0.01, b = R + delta, e1 = 1, e2 = 2, nu = 0.3;
  sc_mesh shaft, hub; /* x along r, y along the angle: the sides SC_LEFT/RIGHT are arcs */
  ck_assert_int_eq(sc_mesh_cells(&shaft, npc, 2 * s, 8 * s, 0, 0, 1, 1, 0), 0);
  ck_assert_int_eq(sc_mesh_cells(&hub, npc, 3 * s, 10 * s, 0, 0, 1, 1, 1), 0);
  const annulus as = {a, b}, ah = {R, c};
  sc_mesh_map(&shaft, to_annulus, (void *)&as);
  sc_mesh_map(&hub, to_annulus, (void *)&ah);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &shaft, 0));
  OK(sc_set_mesh(m, 2, &hub, 0));
  OK(mc_set_material(m, 1, e1, nu));
  OK(mc_set_material(m, 2, e2, nu));
  OK(sc_fix_side(m, 1, &shaft, SC_BOTTOM, MC_Y, 0)); /* y = 0: the ray at angle 0 */
  OK(sc_fix_side(m, 1, &shaft, SC_TOP, MC_X, 0));    /* the ray at angle pi/2 */
  OK(sc_fix_side(m, 2, &hub, SC_BOTTOM, MC_Y, 0));
  OK(sc_fix_side(m, 2, &hub, SC_TOP, MC_X, 0));
  OK(mc_set_contact(m, 1, shaft.n_side_edges[SC_RIGHT], shaft.side_edges[SC_RIGHT]));
  OK(mc_set_contact(m, 2, hub.n_side_edges[SC_LEFT], hub.side_edges[SC_LEFT]));
  SUCCEEDS(mc_solve(m));
  /* the interface pressure on the shaft (test_contact_geometry's shrink_fit_pressure) */
  const ring_lame unit_shaft = {a, b, 0, 1, e1, nu}, unit_hub = {R, c, 1, 0, e2, nu};
  double eps[3];
  ring_strain(&unit_shaft, b, 0, eps);
  const double u_shaft = -b * eps[1]; /* u_r / r = eps_theta: at (b, 0), eps_yy */
  ring_strain(&unit_hub, R, 0, eps);
  const double u_hub = R * eps[1], p = (b - R) / (u_shaft + u_hub * b / R);
  const ring_lame L[2] = {{a, b, 0, p, e1, nu}, {R, c, p * b / R, 0, e2, nu}};
  const sc_mesh *mesh[2] = {&shaft, &hub};
  double err2 = 0;
  for (int k = 0; k < 2; ++k) {
    double D[9], *u = malloc(sizeof(double) * 2 * (size_t)mesh[k]->n_nodes), *e = malloc(sizeof(double) * (size_t)mesh[k]->n_cells);
    ha_law_plane_strain(k == 0 ? e1 : e2, nu, D);
    OK(mc_get_displacement(m, k + 1, u));
    cell_errors(mesh[k], u, 0, D, ring_strain, &L[k], e);
    for (mc_int i = 0; i < mesh[k]->n_cells; ++i) err2 += e[i];
    free(u), free(e);
  }
  const double ratio = absolute_estimate(m) / sqrt(err2);
  int64_t dofs;
  OK(mc_get_info_int(m, MC_INFO_DOFS, &dofs));
  *dofs_out = (long)dofs;
  printf("plane-strain shrink fit (quarter rings), %s, %ld DOFs: true energy error %.3e, estimate %.3e, effectivity %.3f\n",
         cell_kind_name(npc), (long)dofs, sqrt(err2), absolute_estimate(m), ratio);
  mc_destroy(m);
  sc_mesh_free(&shaft), sc_mesh_free(&hub);
  return ratio;
}

START_TEST(effectivity_plane_strain_shrink_fit) {
  const int kinds[3] = {6, 8, 9};
  for (int k = 0; k < 3; ++k)
    for (int level = 1; level < 3; ++level) { /* (the coarsest, 2 cells across the shaft: 1.7 to 2.4) */
      long dofs;
      const double ratio = plane_strain_shrink_fit(kinds[k], level, &dofs);
      ck_assert_msg(ratio >= 0.7 && ratio <= 1.5, "%s: effectivity %.3f", cell_kind_name(kinds[k]), ratio);
    }
}
END_TEST

/* ---- patch tests: the estimate is round-off ------------------------------------------------------ */

/* The flat contact patch of test_quadratic (uniform sigma_yy = -p across a non-matching interface). */
static double patch_estimate(int npc1, int npc2) {
  const double p = 0.2;
  sc_mesh b[2];
  ck_assert_int_eq(sc_mesh_cells(&b[0], npc1, 5, 3, 0, 0, 1, 0.5, 1), 0);
  ck_assert_int_eq(sc_mesh_cells(&b[1], npc2, 7, 3, 0, -0.5, 1, 0.5, 0), 0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  for (int k = 0; k < 2; ++k) {
    OK(sc_set_mesh(m, k + 1, &b[k], 0));
    OK(mc_set_material(m, k + 1, k == 0 ? 1 : 3, 0.3));
    OK(sc_fix_side(m, k + 1, &b[k], SC_LEFT, MC_X, 0));
  }
  OK(sc_fix_side(m, 2, &b[1], SC_BOTTOM, MC_Y, 0));
  double *pr = malloc(sizeof(double) * (size_t)b[0].n_side_edges[SC_TOP]);
  for (mc_int k = 0; k < b[0].n_side_edges[SC_TOP]; ++k) pr[k] = p;
  OK(mc_add_pressure(m, 1, b[0].n_side_edges[SC_TOP], b[0].side_edges[SC_TOP], pr));
  OK(mc_set_contact(m, 1, b[0].n_side_edges[SC_BOTTOM], b[0].side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, b[1].n_side_edges[SC_TOP], b[1].side_edges[SC_TOP]));
  SUCCEEDS(mc_solve(m));
  const double estimate = info_real(m, MC_INFO_ERROR_ESTIMATE);
  free(pr);
  mc_destroy(m);
  sc_mesh_free(&b[0]), sc_mesh_free(&b[1]);
  return estimate;
}

START_TEST(patch_tests_estimate_round_off) {
  const int pairs[6][2] = {{3, 3}, {4, 6}, {6, 4}, {8, 9}, {9, 3}, {6, 8}};
  for (int k = 0; k < 6; ++k) {
    const double e = patch_estimate(pairs[k][0], pairs[k][1]);
    printf("contact patch test, %s on %s: estimate %.2e\n", cell_kind_name(pairs[k][0]), cell_kind_name(pairs[k][1]), e);
    ck_assert_msg(e <= 1e-10, "%s on %s: estimate %g", cell_kind_name(pairs[k][0]), cell_kind_name(pairs[k][1]), e);
  }
}
END_TEST

/* ---- the option, host bodies ------------------------------------------------------------------ */

START_TEST(option_off_and_host_bodies) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  sc_mesh q;
  ck_assert_int_eq(sc_mesh_cells(&q, 4, 4, 4, 0, 0, 1, 1, 0), 0);
  OK(sc_set_mesh(m, 1, &q, 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  OK(sc_fix_side(m, 1, &q, SC_BOTTOM, MC_XY, 0));
  OK(sc_traction_side(m, 1, &q, SC_TOP, 0.1, -0.1, 0));
  double eta[16];
  FAILS(mc_get_error_indicator(m, 1, eta), MC_ERROR_STATE, "mc_solve");
  SUCCEEDS(mc_solve(m));
  const double on = info_real(m, MC_INFO_ERROR_ESTIMATE);
  ck_assert_msg(on > 0 && on < 1, "estimate %g", on);
  OK(mc_get_error_indicator(m, 1, eta));
  FAILS(mc_get_error_indicator(m, 1, NULL), MC_ERROR_ARGUMENT, "eta");
  FAILS(mc_get_error_indicator(m, 2, eta), MC_ERROR_STATE, "no mesh");
  FAILS(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 2), MC_ERROR_ARGUMENT, "MC_OPTION_ERROR_ESTIMATE");
  FAILS(mc_set_option_real(m, MC_OPTION_ERROR_ESTIMATE, 1.0), MC_ERROR_ARGUMENT, "integer-valued");
  OK(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0));
  SUCCEEDS(mc_solve(m));
  ck_assert(info_real(m, MC_INFO_ERROR_ESTIMATE) == 0);
  FAILS(mc_get_error_indicator(m, 1, eta), MC_ERROR_STATE, "MC_OPTION_ERROR_ESTIMATE");
  OK(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 1));
  SUCCEEDS(mc_solve(m));
  ck_assert(info_real(m, MC_INFO_ERROR_ESTIMATE) == on); /* the same answer again */
  /* a host body: no cells, no indicators */
  const double xy[4] = {0, 0, 1, 0};
  const mc_int eq[4] = {0, 1, -1, -1}, rows[3] = {0, 1, 0}, cols[3] = {0, 1, 1};
  const double k[3] = {2, 2, -1}, f[2] = {1, 0};
  OK(mc_set_host_body(m, 2, 2, xy, eq, 2));
  OK(mc_add_stiffness(m, 2, 3, rows, cols, k, MC_MATRIX_TRIANGLE));
  OK(mc_set_load_vector(m, 2, 2, f));
  SUCCEEDS(mc_solve(m));
  FAILS(mc_get_error_indicator(m, 2, eta), MC_ERROR_STATE, "host body");
  OK(mc_get_error_indicator(m, 1, eta));
  mc_destroy(m);
  sc_mesh_free(&q);
}
END_TEST

int main(void) {
  Suite *s = suite_create("error_estimate");
  TCase *tc = tcase_create("estimate");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, patch_tests_estimate_round_off);
  tcase_add_test(tc, effectivity_axisymmetric_shrink_fit);
  tcase_add_test(tc, effectivity_plane_strain_shrink_fit);
  tcase_add_test(tc, option_off_and_host_bodies);
  suite_add_tcase(s, tc);
  return sc_run_suite(s);
}
