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
 * - results on demand (MC_OPTION_EAGER_RESULTS 0, the default) against eager ones (1): the cells'
 *   stresses, the nodal stresses, the indicators and the estimate the same bit for bit (memcmp),
 *   whatever the getters' order, on mesh bodies of linear and quadratic cells, with a host body,
 *   axisymmetric, three bodies, one body's work on a second thread, before and after a load change;
 *   computed once per solve, through a const handle, forgotten when the model changes.
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


/* ---- results on demand against eager results ---------------------------------------------------- */

#define OK_M(call, model) ck_assert_msg((call) == MC_OK, "%s failed: %s", #call, mc_errmsg(model))

/* The scenes: 0 P1 on Q1 (plane strain); 1 Q1 on a host body (element matrices of a P1 mesh,
   its bottom without equations); 2 axisymmetric shrink fit, P1 shaft in a Q1 hub; 3 T6 on Q8, and
   4 Q9 on T6 (plane stress); 5 three bodies (Q1 on P1 on Q8), the pairs' bodies on two threads. */
enum { LAZY_SCENES = 6 };

typedef struct lazy_scene {
  int n_bodies, host[3];
  sc_mesh mesh[3];
} lazy_scene;

static void lazy_scene_free(lazy_scene *s) {
  for (int b = 0; b < s->n_bodies; ++b) sc_mesh_free(&s->mesh[b]);
}

/* Body `body` a host body of P1 element matrices on `mesh`, its bottom side's nodes without
   equations (restrained). */
static void host_block(mc_model *m, int body, const sc_mesh *mesh) {
  const int npc = mesh->npc;
  char *bottom = calloc((size_t)mesh->n_nodes, 1);
  for (mc_int k = 0; k < mesh->n_side_nodes[SC_BOTTOM]; ++k) bottom[mesh->side_nodes[SC_BOTTOM][k]] = 1;
  mc_int *equations = malloc(sizeof(mc_int) * 2 * (size_t)mesh->n_nodes), n_eq = 0;
  for (mc_int i = 0; i < mesh->n_nodes; ++i)
    for (int c = 0; c < 2; ++c) equations[2 * i + c] = bottom[i] ? -1 : n_eq++;
  OK(mc_set_host_body(m, body, mesh->n_nodes, mesh->xy, equations, n_eq));
  mc_int *eltptr, *eltvar;
  double *a, D[9];
  ha_law_plane_strain(2, 0.3, D);
  ck_assert_int_eq(ha_mesh_element_matrices(npc, mesh->n_cells, mesh->cells, mesh->xy, equations, D, &eltptr, &eltvar, &a), 0);
  OK(mc_add_element_matrices(m, body, mesh->n_cells, eltptr, eltvar, a));
  free(bottom), free(equations), free(eltptr), free(eltvar), free(a);
}

static mc_model *lazy_model(lazy_scene *s, int scene, int eager) {
  mc_model *m = NULL;
  memset(s, 0, sizeof *s);
  if (scene == 2) {
    s->n_bodies = 2;
    ck_assert_int_eq(sc_mesh_cells(&s->mesh[0], 3, 6, 9, 0, 0, 1, 1, 1), 0);
    ck_assert_int_eq(sc_mesh_cells(&s->mesh[1], 4, 7, 9, 1, 0, 1, 1, 0), 0);
    m = sc_axisymmetric_shrink_fit(&s->mesh[0], &s->mesh[1], 1, 0.3, 1e-3);
    ck_assert_ptr_nonnull(m);
  } else {
    static const int kinds[LAZY_SCENES][3] = {{3, 4, 0}, {4, 3, 0}, {0}, {6, 8, 0}, {9, 6, 0}, {4, 3, 8}};
    s->n_bodies = scene == 5 ? 3 : 2;
    ck_assert_int_eq(mc_create(&m), MC_OK);
    if (s->n_bodies == 3) OK(mc_set_body_count(m, 3));
    for (int b = 0; b < s->n_bodies; ++b) {
      const int nx = kinds[scene][b] > 4 ? 4 : 7 + b, ny = kinds[scene][b] > 4 ? 3 : 4;
      ck_assert_int_eq(sc_mesh_cells(&s->mesh[b], kinds[scene][b], nx, ny, 0, -0.5 * b, 1, 0.5, b % 2), 0);
      s->host[b] = scene == 1 && b == 1;
      if (s->host[b]) {
        host_block(m, b + 1, &s->mesh[b]);
        continue;
      }
      OK(sc_set_mesh(m, b + 1, &s->mesh[b], 0));
      OK(mc_set_material(m, b + 1, 1 + b, 0.3));
      OK(sc_fix_side(m, b + 1, &s->mesh[b], SC_LEFT, MC_X, 0));
    }
    if (!s->host[s->n_bodies - 1]) OK(sc_fix_side(m, s->n_bodies, &s->mesh[s->n_bodies - 1], SC_BOTTOM, MC_Y, 0));
    if (scene == 3 || scene == 4) OK(mc_set_plane(m, MC_PLANE_STRESS, 0.5));
    OK(sc_traction_side(m, 1, &s->mesh[0], SC_TOP, 0.05, -0.2, 0));
    for (int b = 0; b + 1 < s->n_bodies; ++b) {
      int pair = 1;
      if (s->n_bodies == 2) {
        OK(mc_set_contact(m, 1, s->mesh[0].n_side_edges[SC_BOTTOM], s->mesh[0].side_edges[SC_BOTTOM]));
        OK(mc_set_contact(m, 2, s->mesh[1].n_side_edges[SC_TOP], s->mesh[1].side_edges[SC_TOP]));
        continue;
      }
      OK(mc_add_contact_pair(m, b + 1, b + 2, &pair));
      OK(mc_set_pair_surface(m, pair, b + 1, s->mesh[b].n_side_edges[SC_BOTTOM], s->mesh[b].side_edges[SC_BOTTOM]));
      OK(mc_set_pair_surface(m, pair, b + 2, s->mesh[b + 1].n_side_edges[SC_TOP], s->mesh[b + 1].side_edges[SC_TOP]));
    }
    if (scene == 5) OK(mc_set_option_int(m, MC_OPTION_THREADS, 2)); /* the estimate's bodies on two threads too */
  }
  if (eager) OK(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 1));
  return m;
}

typedef struct derived {
  double *stress[3], *nodal[3], *eta[3], estimate;
} derived;

static void derived_free(derived *d) {
  for (int b = 0; b < 3; ++b) free(d->stress[b]), free(d->nodal[b]), free(d->eta[b]);
  memset(d, 0, sizeof *d);
}

/* Every derived result of a solved model, through a const handle; `reverse`: the estimate first,
   the nodal stresses before the cells', the bodies last to first (a different computing order). */
static void read_derived(const mc_model *m, const lazy_scene *s, int reverse, derived *d) {
  memset(d, 0, sizeof *d);
  double v = -1;
  if (reverse) ck_assert_int_eq(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &d->estimate), MC_OK);
  for (int k = 0; k < s->n_bodies; ++k) {
    const int b = reverse ? s->n_bodies - 1 - k : k;
    const sc_mesh *mesh = &s->mesh[b];
    d->stress[b] = malloc(sizeof(double) * 4 * (size_t)mesh->n_cells);
    d->nodal[b] = malloc(sizeof(double) * 4 * (size_t)mesh->n_nodes);
    d->eta[b] = malloc(sizeof(double) * (size_t)mesh->n_cells);
    if (s->host[b]) {
      ck_assert_int_eq(mc_get_stress(m, b + 1, d->stress[b]), MC_ERROR_STATE);
      ck_assert_int_eq(mc_get_nodal_stress(m, b + 1, d->nodal[b]), MC_ERROR_STATE);
      ck_assert_int_eq(mc_get_error_indicator(m, b + 1, d->eta[b]), MC_ERROR_STATE);
      memset(d->stress[b], 0, sizeof(double) * 4 * (size_t)mesh->n_cells);
      memset(d->nodal[b], 0, sizeof(double) * 4 * (size_t)mesh->n_nodes);
      memset(d->eta[b], 0, sizeof(double) * (size_t)mesh->n_cells);
      continue;
    }
    if (reverse) {
      ck_assert_int_eq(mc_get_error_indicator(m, b + 1, d->eta[b]), MC_OK);
      ck_assert_int_eq(mc_get_nodal_stress(m, b + 1, d->nodal[b]), MC_OK);
      ck_assert_int_eq(mc_get_stress(m, b + 1, d->stress[b]), MC_OK);
    } else {
      ck_assert_int_eq(mc_get_stress(m, b + 1, d->stress[b]), MC_OK);
      ck_assert_int_eq(mc_get_nodal_stress(m, b + 1, d->nodal[b]), MC_OK);
      ck_assert_int_eq(mc_get_error_indicator(m, b + 1, d->eta[b]), MC_OK);
    }
  }
  if (!reverse) ck_assert_int_eq(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &d->estimate), MC_OK);
  ck_assert_int_eq(mc_get_info_real(m, MC_INFO_TIME_RESULTS, &v), MC_OK);
  ck_assert_msg(v > 0, "MC_INFO_TIME_RESULTS %g after the results were read", v);
}

static void assert_same_derived(const derived *a, const derived *b, const lazy_scene *s, const char *what) {
  for (int k = 0; k < s->n_bodies; ++k) {
    const sc_mesh *mesh = &s->mesh[k];
    ck_assert_msg(memcmp(a->stress[k], b->stress[k], sizeof(double) * 4 * (size_t)mesh->n_cells) == 0, "%s: body %d stress", what, k + 1);
    ck_assert_msg(memcmp(a->nodal[k], b->nodal[k], sizeof(double) * 4 * (size_t)mesh->n_nodes) == 0, "%s: body %d nodal stress", what, k + 1);
    ck_assert_msg(memcmp(a->eta[k], b->eta[k], sizeof(double) * (size_t)mesh->n_cells) == 0, "%s: body %d indicators", what, k + 1);
  }
  ck_assert_msg(memcmp(&a->estimate, &b->estimate, sizeof(double)) == 0, "%s: estimate %.17g and %.17g", what, a->estimate,
                b->estimate);
}

START_TEST(results_on_demand_same_as_eager) {
  const int scene = _i;
  static const char *const names[LAZY_SCENES] = {"P1 on Q1", "Q1 on a host body", "axisymmetric P1 in Q1",
                                                 "T6 on Q8", "Q9 on T6", "three bodies, two threads"};
  lazy_scene se, sl;
  mc_model *eager = lazy_model(&se, scene, 1), *lazy = lazy_model(&sl, scene, 0);
  derived de, dl, dl_again, first;
  double t = -1, t_again = -1, sigma[4];
  for (int step = 0; step < 2; ++step) {
    if (step == 1) { /* a load change: a re-solve, the factorizations reused */
      OK_M(mc_set_body_force(eager, 1, 0.01, -0.02), eager);
      OK_M(mc_set_body_force(lazy, 1, 0.01, -0.02), lazy);
      ck_assert_int_eq(mc_get_stress(lazy, 1, sigma), MC_ERROR_STATE); /* changed: no results to give */
    }
    OK_M(mc_solve(eager), eager);
    OK_M(mc_solve(lazy), lazy);
    ck_assert_int_eq(mc_get_info_real(lazy, MC_INFO_TIME_RESULTS, &t), MC_OK);
    ck_assert_msg(t == 0, "%s: results computed by the solve (%g s)", names[scene], t);
    if (step == 1) {
      int64_t factorizations = -1;
      ck_assert_int_eq(mc_get_info_int(lazy, MC_INFO_FACTORIZATIONS, &factorizations), MC_OK);
      ck_assert_int_eq(factorizations, 0);
    }
    read_derived(eager, &se, 0, &de);
    read_derived(lazy, &sl, 1, &dl);
    ck_assert_msg(de.estimate > 0 && de.estimate < 1, "%s: estimate %g", names[scene], de.estimate);
    assert_same_derived(&de, &dl, &se, names[scene]);
    /* read again: the same numbers, nothing computed twice */
    ck_assert_int_eq(mc_get_info_real(lazy, MC_INFO_TIME_RESULTS, &t), MC_OK);
    read_derived(lazy, &sl, 0, &dl_again);
    assert_same_derived(&dl, &dl_again, &sl, names[scene]);
    ck_assert_int_eq(mc_get_info_real(lazy, MC_INFO_TIME_RESULTS, &t_again), MC_OK);
    ck_assert_msg(t_again == t, "%s: computed again (%g s, then %g s)", names[scene], t, t_again);
    printf("results on demand, %s, %s: estimate %.6g, bit for bit the eager results\n", names[scene],
           step ? "re-solve" : "first solve", de.estimate);
    derived_free(&de), derived_free(&dl_again);
    if (step == 0) first = dl;
  }
  /* the re-solve's results are its own, not the first solve's kept */
  ck_assert_msg(memcmp(first.stress[0], dl.stress[0], sizeof(double) * 4 * (size_t)sl.mesh[0].n_cells) != 0 &&
                    first.estimate != dl.estimate,
                "%s: the re-solve gave the first solve's results", names[scene]);
  derived_free(&first), derived_free(&dl);
  mc_destroy(eager), mc_destroy(lazy);
  lazy_scene_free(&se), lazy_scene_free(&sl);
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
  tcase_add_loop_test(tc, results_on_demand_same_as_eager, 0, LAZY_SCENES);
  suite_add_tcase(s, tc);
  return sc_run_suite(s);
}
