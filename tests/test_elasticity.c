/*
 * test_elasticity.c - the physics of the elasticity solve (no contact):
 *  - exactness (patch test): a linear displacement prescribed on the whole boundary is
 *    reproduced inside to round-off, with the exact constant stress; P1/Q1, plane strain and
 *    stress, thickness != 1, distorted meshes, index base 1, per-cell anisotropic laws,
 *    Q1 B-bar;
 *  - convergence on a smooth manufactured solution: observed H1 and L2 rates, P1 and Q1;
 *  - equilibrium of a loaded cantilever (forces and moment), the equilibrium info and
 *    Clapeyron's theorem (strain energy = 1/2 f.u, and u.(f + r) with nonzero supports);
 *  - a uniaxial bar under end traction against the closed-form answer;
 *  - two bodies without contact are independent.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mortarcontact.h"
#include "check_helpers.h"
#include "scenes.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static double max_abs(const double *v, size_t n) {
  double s = 0;
  size_t i;
  for (i = 0; i < n; ++i)
    if (fabs(v[i]) > s) s = fabs(v[i]);
  return s;
}

/* ---- exactness ------------------------------------------------------------ */

/* u_x = a0 + a1 x + a2 y, u_y = a3 + a4 x + a5 y */
static void linear_field(double x, double y, void *ctx, double v[2], double g[4]) {
  const double *a = ctx;
  v[0] = a[0] + a[1] * x + a[2] * y;
  v[1] = a[3] + a[4] * x + a[5] * y;
  if (g) g[0] = a[1], g[1] = a[2], g[2] = a[4], g[3] = a[5];
}

/* A random symmetric positive definite 3x3 matrix of size ~scale. */
static void random_spd(unsigned *state, double scale, double d[9]) {
  double b[9];
  int i, j, k;
  for (i = 0; i < 9; ++i) b[i] = 2 * sc_random(state) - 1;
  for (i = 0; i < 3; ++i)
    for (j = 0; j <= i; ++j) {
      double s = 0;
      for (k = 0; k < 3; ++k) s += b[3 * i + k] * b[3 * j + k];
      d[3 * i + j] = d[3 * j + i] = scale * (s + (i == j ? 0.3 : 0));
    }
}

/* Exactness case, from the loop index:
   bit 0: Q1 (else P1); bit 1: plane stress (else strain); bit 2: thickness 2.5 (else 1);
   bit 3: distorted mesh; bit 4: index base 1; bit 5: per-cell anisotropic laws;
   bit 6: Q1 B-bar integration (only with Q1; with nu = 0.49). */
static void run_patch_scaled(int index, double length, double modulus, double offset) {
  const int npc = (index & 1) ? 4 : 3;
  const int plane = (index & 2) ? MC_PLANE_STRESS : MC_PLANE_STRAIN;
  const double thickness = (index & 4) ? 2.5 : 1.0;
  const double distortion = (index & 8) ? 0.25 : 0.0;
  const int base = (index & 16) ? 1 : 0;
  const int cell_laws = (index & 32) != 0;
  const int bbar = (index & 64) != 0;
  const double young = 210.0 * modulus, poisson = bbar ? 0.49 : 0.3;
  double a[6] = {0.01 * length, 2e-3, -1.5e-3, -0.02 * length, 0.7e-3, 1.1e-3};
  sc_mesh mesh;
  mc_model *m = NULL;
  double *u, *sigma, *r, *claws = NULL, D[9], zz[2], eps[3], energy_exact = 0, energy;
  double umax = 0, err = 0, smax = 0, serr = 0, rsum[3] = {0, 0, 0}, rmax;
  mc_int i, c;
  unsigned state = 777u + (unsigned)index;

  ck_assert_int_eq(sc_mesh_rect(&mesh, npc, 6, 5, (0.3 + offset) * length, (-0.7 + offset) * length, 2.0 * length,
                                1.5 * length, distortion, 4242u + (unsigned)index), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  if (base) OK(mc_set_index_base(m, 1));
  OK(mc_set_plane(m, plane, thickness));
  OK(sc_set_mesh(m, 1, &mesh, base));
  if (cell_laws) {
    claws = malloc(sizeof(double) * 9 * (size_t)mesh.n_cells);
    /* the same general anisotropic law in every cell, given per cell (a linear field is only
       an exact solution of a homogeneous body; heterogeneous laws: test_cell_laws_heterogeneous) */
    random_spd(&state, young, claws);
    for (c = 1; c < mesh.n_cells; ++c) memcpy(claws + 9 * c, claws, 9 * sizeof(double));
    OK(mc_set_cell_elasticity(m, 1, claws));
  } else {
    OK(mc_set_material(m, 1, young, poisson));
  }
  if (bbar) OK(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, MC_Q1_BBAR));
  OK(sc_fix_field(m, 1, &mesh, mesh.n_boundary_nodes, mesh.boundary_nodes, base, linear_field, a));
  OK(mc_solve(m));
  ck_assert_str_eq(mc_errmsg(m), "");

  u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  r = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  sigma = malloc(sizeof(double) * 4 * (size_t)mesh.n_cells);
  OK(mc_get_displacement(m, 1, u));
  OK(mc_get_stress(m, 1, sigma));
  OK(mc_get_reaction(m, 1, r));

  /* nodal displacements, the interior ones are the unknowns */
  for (i = 0; i < mesh.n_nodes; ++i) {
    double v[2];
    linear_field(mesh.xy[2 * i], mesh.xy[2 * i + 1], a, v, NULL);
    if (fabs(v[0]) > umax) umax = fabs(v[0]);
    if (fabs(v[1]) > umax) umax = fabs(v[1]);
    if (fabs(u[2 * i] - v[0]) > err) err = fabs(u[2 * i] - v[0]);
    if (fabs(u[2 * i + 1] - v[1]) > err) err = fabs(u[2 * i + 1] - v[1]);
  }
  ck_assert_msg(err <= 1e-12 * umax, "case %d: displacement error %g (max %g)", index, err, umax);

  /* stresses against the law applied by hand to the constant strain */
  eps[0] = a[1], eps[1] = a[5], eps[2] = a[2] + a[4];
  sc_isotropic_law(young, poisson, plane, D, zz);
  for (c = 0; c < mesh.n_cells; ++c) {
    const double *Dc = cell_laws ? claws + 9 * c : D;
    double s[4];
    int k;
    s[0] = Dc[0] * eps[0] + Dc[1] * eps[1] + Dc[2] * eps[2];
    s[1] = Dc[3] * eps[0] + Dc[4] * eps[1] + Dc[5] * eps[2];
    s[2] = Dc[6] * eps[0] + Dc[7] * eps[1] + Dc[8] * eps[2];
    s[3] = cell_laws ? 0.0 : zz[0] * eps[0] + zz[1] * eps[1];
    for (k = 0; k < 4; ++k) {
      if (fabs(s[k]) > smax) smax = fabs(s[k]);
      if (fabs(sigma[4 * c + k] - s[k]) > serr) serr = fabs(sigma[4 * c + k] - s[k]);
    }
    energy_exact += 0.5 * thickness * sc_cell_area(&mesh, c) * (s[0] * eps[0] + s[1] * eps[1] + s[2] * eps[2]);
  }
  ck_assert_msg(serr <= 1e-10 * smax, "case %d: stress error %g (max %g)", index, serr, smax);

  /* no loads: the reactions are self-equilibrated */
  rmax = max_abs(r, 2 * (size_t)mesh.n_nodes);
  ck_assert(rmax > 0);
  for (i = 0; i < mesh.n_nodes; ++i) {
    rsum[0] += r[2 * i], rsum[1] += r[2 * i + 1];
    rsum[2] += mesh.xy[2 * i] * r[2 * i + 1] - mesh.xy[2 * i + 1] * r[2 * i];
  }
  ck_assert_msg(fabs(rsum[0]) <= 1e-10 * rmax && fabs(rsum[1]) <= 1e-10 * rmax &&
                    fabs(rsum[2]) <= 1e-10 * max_abs(mesh.xy, 2 * (size_t)mesh.n_nodes) * rmax,
                "case %d: reactions not balanced: %g %g %g (max %g)", index, rsum[0], rsum[1], rsum[2], rmax);

  /* energy = 1/2 t sum_c |c| sigma : eps */
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &energy));
  ck_assert_msg(sc_reldiff(energy, energy_exact, 1e-300) <= 1e-10, "case %d: energy %.15g, expected %.15g", index,
                energy, energy_exact);

  free(u), free(r), free(sigma), free(claws);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}

static void run_patch(int index) { run_patch_scaled(index, 1.0, 1.0, 0.0); }

START_TEST(test_patch_isotropic) { run_patch(_i); }
END_TEST

START_TEST(test_patch_cell_elasticity) {
  /* bit 5 set; vary element, thickness, distortion, base */
  run_patch(32 | (_i & 1) | ((_i & 2) ? 4 : 0) | ((_i & 4) ? 8 : 0) | ((_i & 8) ? 16 : 0));
}
END_TEST

START_TEST(test_patch_bbar) {
  /* Q1 with B-bar: bits 0 and 6 set; vary plane, thickness, distortion, base */
  run_patch(1 | 64 | ((_i & 1) ? 2 : 0) | ((_i & 2) ? 4 : 0) | ((_i & 4) ? 8 : 0) | ((_i & 8) ? 16 : 0));
}
END_TEST

/* Heterogeneous per-cell laws: mc_set_cell_elasticity with the isotropic in-plane law in
   every cell gives the mc_set_material answer (stresses except sigma_zz); with random SPD laws
   per cell (P1), each cell's stress is its own D_c times the strain of the nodal field. */
START_TEST(test_cell_laws_heterogeneous) {
  const int plane = _i ? MC_PLANE_STRESS : MC_PLANE_STRAIN;
  sc_mesh mesh;
  mc_model *m = NULL;
  double *d, *u1, *u2, *s1, *s2, D[9], umax, smax, equilibrium;
  mc_int c, k, node;
  double force[2] = {0.3, -1.0};
  unsigned state = 99u;
  size_t nu, ns;
  ck_assert_int_eq(sc_mesh_rect(&mesh, 3, 6, 4, 0, 0, 3, 1, 0.2, 8u), 0);
  nu = 2 * (size_t)mesh.n_nodes, ns = 4 * (size_t)mesh.n_cells;
  d = malloc(sizeof(double) * 9 * (size_t)mesh.n_cells);
  u1 = malloc(sizeof(double) * nu), u2 = malloc(sizeof(double) * nu);
  s1 = malloc(sizeof(double) * ns), s2 = malloc(sizeof(double) * ns);
  node = sc_node(&mesh, 6, 4);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_plane(m, plane, 1.5));
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  OK(mc_add_nodal_force(m, 1, 1, &node, force));
  OK(mc_set_body_force(m, 1, 0.1, -0.2));
  OK(mc_set_material(m, 1, 50.0, 0.35));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u1));
  OK(mc_get_stress(m, 1, s1));
  sc_isotropic_law(50.0, 0.35, plane, D, NULL);
  for (c = 0; c < mesh.n_cells; ++c) memcpy(d + 9 * c, D, sizeof D);
  OK(mc_set_cell_elasticity(m, 1, d));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u2));
  OK(mc_get_stress(m, 1, s2));
  umax = max_abs(u1, nu), smax = max_abs(s1, ns);
  for (k = 0; k < (mc_int)nu; ++k) ck_assert_double_eq_tol(u1[k], u2[k], 1e-12 * umax);
  for (c = 0; c < mesh.n_cells; ++c) {
    for (k = 0; k < 3; ++k) ck_assert_double_eq_tol(s1[4 * c + k], s2[4 * c + k], 1e-11 * smax);
    ck_assert_double_eq(s2[4 * c + 3], 0); /* the matrix is the in-plane law: sigma_zz = 0 */
  }
  /* random laws per cell */
  for (c = 0; c < mesh.n_cells; ++c) random_spd(&state, 10.0 + 90.0 * sc_random(&state), d + 9 * c);
  OK(mc_set_cell_elasticity(m, 1, d));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u2));
  OK(mc_get_stress(m, 1, s2));
  OK(mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium));
  ck_assert_msg(equilibrium <= 1e-10, "MC_INFO_EQUILIBRIUM = %g", equilibrium);
  smax = max_abs(s2, ns);
  for (c = 0; c < mesh.n_cells; ++c) {
    const mc_int *v = mesh.cells + 3 * c;
    const double *p0 = mesh.xy + 2 * v[0], *p1 = mesh.xy + 2 * v[1], *p2 = mesh.xy + 2 * v[2];
    double det = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
    double gx[3], gy[3], eps[3] = {0, 0, 0};
    const double *Dc = d + 9 * c;
    int a;
    gx[0] = (p1[1] - p2[1]) / det, gy[0] = (p2[0] - p1[0]) / det;
    gx[1] = (p2[1] - p0[1]) / det, gy[1] = (p0[0] - p2[0]) / det;
    gx[2] = (p0[1] - p1[1]) / det, gy[2] = (p1[0] - p0[0]) / det;
    for (a = 0; a < 3; ++a) {
      eps[0] += gx[a] * u2[2 * v[a]];
      eps[1] += gy[a] * u2[2 * v[a] + 1];
      eps[2] += gy[a] * u2[2 * v[a]] + gx[a] * u2[2 * v[a] + 1];
    }
    for (k = 0; k < 3; ++k)
      ck_assert_double_eq_tol(s2[4 * c + k], Dc[3 * k] * eps[0] + Dc[3 * k + 1] * eps[1] + Dc[3 * k + 2] * eps[2],
                              1e-11 * smax);
    ck_assert_double_eq(s2[4 * c + 3], 0);
  }
  free(d), free(u1), free(u2), free(s1), free(s2);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* Units: the same patch in SI-like units, lengths 1e-4 (offset from the origin by 10 body
   sizes), moduli 2e11 / 210; and in large units, lengths 1e3, moduli 1e-3. */
START_TEST(test_patch_units) {
  const int index = (_i & 1) | ((_i & 2) ? 8 : 0) | ((_i & 4) ? 2 : 0);
  run_patch_scaled(index, 1e-4, 2e11 / 210.0, 10.0);
  run_patch_scaled(index, 1e3, 1e-3, 0.0);
}
END_TEST

/* ---- convergence ---------------------------------------------------------- */

typedef struct {
  double lambda, mu;
} lame;

/* u = (sin(pi x) cos(pi y), exp(x) sin(pi y)) */
static void smooth_u(double x, double y, void *ctx, double v[2], double g[4]) {
  const double p = M_PI;
  (void)ctx;
  v[0] = sin(p * x) * cos(p * y);
  v[1] = exp(x) * sin(p * y);
  if (g) {
    g[0] = p * cos(p * x) * cos(p * y);
    g[1] = -p * sin(p * x) * sin(p * y);
    g[2] = exp(x) * sin(p * y);
    g[3] = p * exp(x) * cos(p * y);
  }
}

/* f = -div sigma(u) = -(mu lap u + (lambda + mu) grad div u) (checked with sympy) */
static void smooth_f(double x, double y, void *ctx, double v[2], double g[4]) {
  const lame *l = ctx;
  const double p = M_PI, p2 = M_PI * M_PI;
  double lap_x = -2 * p2 * sin(p * x) * cos(p * y);
  double lap_y = (1 - p2) * exp(x) * sin(p * y);
  double ddx = -p2 * sin(p * x) * cos(p * y) + p * exp(x) * cos(p * y);
  double ddy = -p2 * cos(p * x) * sin(p * y) - p2 * exp(x) * sin(p * y);
  (void)g;
  v[0] = -(l->mu * lap_x + (l->lambda + l->mu) * ddx);
  v[1] = -(l->mu * lap_y + (l->lambda + l->mu) * ddy);
}

/* Solves the manufactured problem on an n x n mesh of the unit square; returns the errors. */
static void manufactured(int npc, int bbar, int n, double *l2, double *h1) {
  const double young = 1.0, poisson = 0.3;
  lame l;
  sc_mesh mesh;
  mc_model *m = NULL;
  double *F, *u;
  l.lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  l.mu = young / (2 * (1 + poisson));
  ck_assert_int_eq(sc_mesh_rect(&mesh, npc, n, n, 0, 0, 1, 1, 0, 1u), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_plane(m, MC_PLANE_STRAIN, 1.0));
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, young, poisson));
  if (bbar) OK(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, MC_Q1_BBAR));
  OK(sc_fix_field(m, 1, &mesh, mesh.n_boundary_nodes, mesh.boundary_nodes, 0, smooth_u, NULL));
  F = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  sc_consistent_load(&mesh, smooth_f, &l, 1.0, F);
  OK(sc_add_nodal_forces(m, 1, &mesh, F, 0));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u));
  sc_errors(&mesh, u, smooth_u, NULL, l2, h1);
  free(F), free(u);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}

START_TEST(test_convergence) {
  /* _i: 0 = P1, 1 = Q1, 2 = Q1 B-bar */
  static const char *names[3] = {"P1", "Q1", "Q1 B-bar"};
  const int npc = _i == 0 ? 3 : 4, bbar = _i == 2;
  const int sizes[4] = {8, 16, 32, 64};
  double l2[4], h1[4], rate_l2[3], rate_h1[3];
  int k;
  for (k = 0; k < 4; ++k) manufactured(npc, bbar, sizes[k], &l2[k], &h1[k]);
  for (k = 0; k < 3; ++k) {
    rate_l2[k] = log(l2[k] / l2[k + 1]) / log(2.0);
    rate_h1[k] = log(h1[k] / h1[k + 1]) / log(2.0);
  }
  printf("convergence %s: n = 8 16 32 64\n  L2 errors %.4e %.4e %.4e %.4e, rates %.3f %.3f %.3f\n"
         "  H1 errors %.4e %.4e %.4e %.4e, rates %.3f %.3f %.3f\n",
         names[_i], l2[0], l2[1], l2[2], l2[3], rate_l2[0], rate_l2[1], rate_l2[2], h1[0], h1[1], h1[2], h1[3],
         rate_h1[0], rate_h1[1], rate_h1[2]);
  fflush(stdout);
  for (k = 1; k < 3; ++k) {
    ck_assert_msg(rate_h1[k] >= 0.9, "%s: H1 rate %g < 0.9 between n = %d and %d", names[_i], rate_h1[k], sizes[k],
                  sizes[k + 1]);
    ck_assert_msg(rate_l2[k] >= 1.8, "%s: L2 rate %g < 1.8 between n = %d and %d", names[_i], rate_l2[k], sizes[k],
                  sizes[k + 1]);
  }
}
END_TEST

/* ---- equilibrium and Clapeyron -------------------------------------------- */

/* Cantilever [0,4] x [0,1], clamped on the left, with tractions (top, right), pressures
   (bottom), nodal forces (interior, free boundary and clamped nodes) and a body force.
   _i bit 0: Q1; bit 1: nonzero prescribed displacements on the left (generalized Clapeyron). */
START_TEST(test_cantilever_equilibrium) {
  const int npc = (_i & 1) ? 4 : 3, moved = (_i & 2) != 0;
  const double t = 1.7, bx = 0.2, by = -0.9;
  sc_mesh mesh;
  mc_model *m = NULL;
  double *f, *u, *r, *te, *pe, *Fb, applied[3] = {0, 0, 0}, reaction[3] = {0, 0, 0}, scale = 0;
  double work = 0, rwork = 0, energy, equilibrium;
  mc_int k, n_nodal = 4, nodal[4];
  double nodal_force[8] = {0.3, -0.4, -1.1, 0.25, 0.6, 0.9, -0.2, -0.7};
  int s;

  ck_assert_int_eq(sc_mesh_rect(&mesh, npc, 16, 4, 0, 0, 4, 1, 0.2, 99u), 0);
  nodal[0] = sc_node(&mesh, 5, 2);    /* interior */
  nodal[1] = sc_node(&mesh, 16, 1);   /* right side */
  nodal[2] = sc_node(&mesh, 0, 2);    /* on the clamped side */
  nodal[3] = sc_node(&mesh, 11, 3);   /* interior */
  f = calloc(2 * (size_t)mesh.n_nodes, sizeof(double));
  u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  r = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  Fb = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  te = malloc(sizeof(double) * 2 * 16);
  pe = malloc(sizeof(double) * 16);

  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_plane(m, MC_PLANE_STRESS, t));
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 1000.0, 0.25));
  if (moved) {
    mc_int n = mesh.n_side_nodes[SC_LEFT];
    double *values = malloc(sizeof(double) * 2 * (size_t)n);
    for (k = 0; k < n; ++k) {
      double y = mesh.xy[2 * mesh.side_nodes[SC_LEFT][k] + 1];
      values[2 * k] = 1e-3 * (y - 0.5);
      values[2 * k + 1] = -2e-3 + 1e-3 * y * y;
    }
    OK(mc_fix(m, 1, n, mesh.side_nodes[SC_LEFT], MC_XY, values));
    free(values);
  } else {
    OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  }

  /* loads, and by hand: the nodal load vector f, resultant and moment about the origin */
  for (s = 0; s < 3; ++s) {
    int side = s == 0 ? SC_TOP : s == 1 ? SC_RIGHT : SC_BOTTOM;
    mc_int ne = mesh.n_side_edges[side];
    for (k = 0; k < ne; ++k) {
      mc_int a = mesh.side_edges[side][2 * k], b = mesh.side_edges[side][2 * k + 1];
      double xa = mesh.xy[2 * a], ya = mesh.xy[2 * a + 1], xb = mesh.xy[2 * b], yb = mesh.xy[2 * b + 1];
      double len = hypot(xb - xa, yb - ya), fx, fy;
      if (side == SC_BOTTOM) {
        pe[k] = 0.7 + 0.1 * k;
        fx = pe[k] * t * -(yb - ya); /* force = -p n_out len t, n_out = (dy, -dx)/len */
        fy = pe[k] * t * (xb - xa);
      } else {
        te[2 * k] = side == SC_TOP ? 0.1 * k : 0.5;
        te[2 * k + 1] = side == SC_TOP ? -1.0 - 0.05 * k : -2.0 + 0.3 * k;
        fx = te[2 * k] * len * t;
        fy = te[2 * k + 1] * len * t;
      }
      f[2 * a] += 0.5 * fx, f[2 * a + 1] += 0.5 * fy;
      f[2 * b] += 0.5 * fx, f[2 * b + 1] += 0.5 * fy;
      applied[0] += fx, applied[1] += fy;
      applied[2] += 0.5 * (xa + xb) * fy - 0.5 * (ya + yb) * fx;
      scale += fabs(fx) + fabs(fy);
    }
    if (side == SC_BOTTOM) OK(mc_add_pressure(m, 1, ne, mesh.side_edges[side], pe));
    else OK(mc_add_traction(m, 1, ne, mesh.side_edges[side], te));
  }
  OK(mc_add_nodal_force(m, 1, n_nodal, nodal, nodal_force));
  for (k = 0; k < n_nodal; ++k) {
    double x = mesh.xy[2 * nodal[k]], y = mesh.xy[2 * nodal[k] + 1];
    f[2 * nodal[k]] += nodal_force[2 * k], f[2 * nodal[k] + 1] += nodal_force[2 * k + 1];
    applied[0] += nodal_force[2 * k], applied[1] += nodal_force[2 * k + 1];
    applied[2] += x * nodal_force[2 * k + 1] - y * nodal_force[2 * k];
    scale += fabs(nodal_force[2 * k]) + fabs(nodal_force[2 * k + 1]);
  }
  OK(mc_set_body_force(m, 1, bx, by));
  {
    double area = 4.0 * 1.0, cx = 2.0, cy = 0.5;
    double b[2] = {bx, by};
    applied[0] += bx * area * t, applied[1] += by * area * t;
    applied[2] += area * t * (cx * by - cy * bx);
    scale += (fabs(bx) + fabs(by)) * area * t;
    /* consistent nodal load of the uniform body force: exact by quadrature */
    for (k = 0; k < mesh.n_nodes; ++k) Fb[2 * k] = 0;
    {
      /* reuse sc_consistent_load with a constant field through linear_field */
      double cst[6] = {b[0], 0, 0, b[1], 0, 0};
      sc_consistent_load(&mesh, linear_field, cst, t, Fb);
    }
    for (k = 0; k < 2 * mesh.n_nodes; ++k) f[k] += Fb[k];
  }

  OK(mc_solve(m));
  ck_assert_str_eq(mc_errmsg(m), "");
  OK(mc_get_displacement(m, 1, u));
  OK(mc_get_reaction(m, 1, r));
  for (k = 0; k < mesh.n_nodes; ++k) {
    double x = mesh.xy[2 * k], y = mesh.xy[2 * k + 1];
    reaction[0] += r[2 * k], reaction[1] += r[2 * k + 1];
    reaction[2] += x * r[2 * k + 1] - y * r[2 * k];
    /* reactions only at prescribed components: here the left side */
    if (!(mesh.xy[2 * k] == 0.0)) {
      ck_assert_msg(r[2 * k] == 0 && r[2 * k + 1] == 0, "reaction at free node %d: %g %g", (int)k, r[2 * k],
                    r[2 * k + 1]);
    }
    work += f[2 * k] * u[2 * k] + f[2 * k + 1] * u[2 * k + 1];
    rwork += r[2 * k] * u[2 * k] + r[2 * k + 1] * u[2 * k + 1];
  }
  ck_assert_msg(fabs(reaction[0] + applied[0]) <= 1e-10 * scale, "x: reactions %.15g + loads %.15g != 0", reaction[0],
                applied[0]);
  ck_assert_msg(fabs(reaction[1] + applied[1]) <= 1e-10 * scale, "y: reactions %.15g + loads %.15g != 0", reaction[1],
                applied[1]);
  ck_assert_msg(fabs(reaction[2] + applied[2]) <= 1e-10 * scale * 4.0, "moment: reactions %.15g + loads %.15g != 0",
                reaction[2], applied[2]);
  OK(mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium));
  ck_assert_msg(equilibrium >= 0 && equilibrium <= 1e-10, "MC_INFO_EQUILIBRIUM = %g", equilibrium);
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &energy));
  ck_assert(energy > 0);
  if (!moved) {
    /* Clapeyron: homogeneous supports, the reactions do no work */
    ck_assert_msg(sc_reldiff(energy, 0.5 * work, 1e-300) <= 1e-10, "energy %.15g != 1/2 f.u = %.15g", energy,
                  0.5 * work);
  } else {
    /* u.K.u = u.(f + r) */
    ck_assert_msg(sc_reldiff(energy, 0.5 * (work + rwork), 1e-300) <= 1e-10, "energy %.15g != 1/2 (f + r).u = %.15g",
                  energy, 0.5 * (work + rwork));
  }
  free(f), free(u), free(r), free(Fb), free(te), free(pe);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* A pressure p on an edge is the traction -p n_out: the same answer both ways. */
START_TEST(test_pressure_is_normal_traction) {
  sc_mesh mesh;
  mc_model *m = NULL;
  double *u1, *u2, p[8], *t;
  mc_int k, ne;
  size_t n;
  ck_assert_int_eq(sc_mesh_rect(&mesh, 3 + _i, 8, 4, 0, 0, 2, 1, 0.2, 5u), 0);
  ne = mesh.n_side_edges[SC_RIGHT];
  n = 2 * (size_t)mesh.n_nodes;
  u1 = malloc(sizeof(double) * n);
  u2 = malloc(sizeof(double) * n);
  t = malloc(sizeof(double) * 2 * (size_t)ne);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 5.0, 0.2));
  OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  for (k = 0; k < ne; ++k) p[k] = 1.0 + 0.25 * k, t[2 * k] = -p[k], t[2 * k + 1] = 0;
  OK(mc_add_pressure(m, 1, ne, mesh.side_edges[SC_RIGHT], p));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u1));
  ck_assert(u1[2 * sc_node(&mesh, 8, 2)] < 0); /* pushed into the body */
  OK(mc_clear_loads(m, 1));
  OK(mc_add_traction(m, 1, ne, mesh.side_edges[SC_RIGHT], t));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u2));
  for (k = 0; k < (mc_int)n; ++k) ck_assert_double_eq_tol(u1[k], u2[k], 1e-12 * max_abs(u1, n));
  free(u1), free(u2), free(t);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- uniaxial bar ---------------------------------------------------------- */

/* Bar [0,L] x [0,H]: u_x = 0 on the left, u_y = 0 at the bottom-left corner, traction
   (sigma, 0) on the right. Plane stress: u_x = sigma x / E, u_y = -nu sigma y / E; plane
   strain: E' = E / (1 - nu^2), nu' = nu / (1 - nu). Linear, so exact on any mesh.
   _i bit 0: Q1; bit 1: plane strain; bit 2: distorted. */
START_TEST(test_uniaxial_bar) {
  const int npc = (_i & 1) ? 4 : 3, plane = (_i & 2) ? MC_PLANE_STRAIN : MC_PLANE_STRESS;
  const double L = 3.0, H = 1.0, E = 70.0, nu = 0.3, sig = 0.35, t = 2.0;
  const double Ep = plane == MC_PLANE_STRESS ? E : E / (1 - nu * nu);
  const double nup = plane == MC_PLANE_STRESS ? nu : nu / (1 - nu);
  sc_mesh mesh;
  mc_model *m = NULL;
  double *u, *s, *r, rx = 0, ry = 0, energy, umax = sig * L / Ep;
  mc_int k, corner;
  ck_assert_int_eq(sc_mesh_rect(&mesh, npc, 6, 3, 0, 0, L, H, (_i & 4) ? 0.25 : 0, 31u), 0);
  u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  r = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  s = malloc(sizeof(double) * 4 * (size_t)mesh.n_cells);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_plane(m, plane, t));
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, E, nu));
  OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_X, 0));
  corner = sc_node(&mesh, 0, 0);
  OK(mc_fix(m, 1, 1, &corner, MC_Y, NULL));
  OK(sc_traction_side(m, 1, &mesh, SC_RIGHT, sig, 0, 0));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u));
  OK(mc_get_stress(m, 1, s));
  OK(mc_get_reaction(m, 1, r));
  /* the end: sigma L / E' */
  for (k = 0; k < mesh.n_side_nodes[SC_RIGHT]; ++k)
    ck_assert_double_eq_tol(u[2 * mesh.side_nodes[SC_RIGHT][k]], sig * L / Ep, 1e-12 * umax);
  for (k = 0; k < mesh.n_nodes; ++k) {
    double x = mesh.xy[2 * k], y = mesh.xy[2 * k + 1];
    ck_assert_double_eq_tol(u[2 * k], sig * x / Ep, 1e-12 * umax);
    ck_assert_double_eq_tol(u[2 * k + 1], -nup * sig * y / Ep, 1e-12 * umax);
    rx += r[2 * k], ry += r[2 * k + 1];
  }
  for (k = 0; k < mesh.n_cells; ++k) {
    ck_assert_double_eq_tol(s[4 * k], sig, 1e-10 * sig);
    ck_assert_double_eq_tol(s[4 * k + 1], 0, 1e-10 * sig);
    ck_assert_double_eq_tol(s[4 * k + 2], 0, 1e-10 * sig);
    ck_assert_double_eq_tol(s[4 * k + 3], plane == MC_PLANE_STRESS ? 0 : nu * sig, 1e-10 * sig);
  }
  /* the supports carry the end force sigma H t */
  ck_assert_double_eq_tol(rx, -sig * H * t, 1e-10 * sig * H * t);
  ck_assert_double_eq_tol(ry, 0, 1e-10 * sig * H * t);
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &energy));
  ck_assert_double_eq_tol(energy, 0.5 * sig * sig / Ep * L * H * t, 1e-10 * energy);
  free(u), free(s), free(r);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- two independent bodies ------------------------------------------------- */

/* Body with mesh a: cantilever, loads; body with mesh b: fixed bottom, traction on top. */
static void load_body(mc_model *m, int body, const sc_mesh *mesh, int which) {
  if (which == 0) {
    mc_int node = sc_node(mesh, 4, 2);
    double force[2] = {0.5, -0.25};
    OK(mc_set_material(m, body, 100.0, 0.3));
    OK(sc_fix_side(m, body, mesh, SC_LEFT, MC_XY, 0));
    OK(sc_traction_side(m, body, mesh, SC_TOP, 0.1, -0.8, 0));
    OK(mc_add_nodal_force(m, body, 1, &node, force));
    OK(mc_set_body_force(m, body, 0, -0.3));
  } else {
    OK(mc_set_material(m, body, 30.0, 0.15));
    OK(sc_fix_side(m, body, mesh, SC_BOTTOM, MC_XY, 0));
    OK(sc_traction_side(m, body, mesh, SC_TOP, 0.4, -0.1, 0));
    OK(mc_set_body_force(m, body, 0.05, 0.2));
  }
}

typedef struct {
  double *u, *s, *r;
  double energy;
  int64_t dofs;
} result;

static void get_result(mc_model *m, int body, const sc_mesh *mesh, result *res) {
  res->u = malloc(sizeof(double) * 2 * (size_t)mesh->n_nodes);
  res->r = malloc(sizeof(double) * 2 * (size_t)mesh->n_nodes);
  res->s = malloc(sizeof(double) * 4 * (size_t)mesh->n_cells);
  OK(mc_get_displacement(m, body, res->u));
  OK(mc_get_reaction(m, body, res->r));
  OK(mc_get_stress(m, body, res->s));
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &res->energy));
  OK(mc_get_info_int(m, MC_INFO_DOFS, &res->dofs));
}

static void free_result(result *res) { free(res->u), free(res->r), free(res->s); }

static void same_result(const result *x, const result *y, const sc_mesh *mesh) {
  size_t k, nu = 2 * (size_t)mesh->n_nodes, ns = 4 * (size_t)mesh->n_cells;
  double su = max_abs(x->u, nu), sr = max_abs(x->r, nu), ss = max_abs(x->s, ns);
  ck_assert(su > 0 && sr > 0 && ss > 0);
  for (k = 0; k < nu; ++k) ck_assert_double_eq_tol(x->u[k], y->u[k], 1e-12 * su);
  for (k = 0; k < nu; ++k) ck_assert_double_eq_tol(x->r[k], y->r[k], 1e-12 * sr);
  for (k = 0; k < ns; ++k) ck_assert_double_eq_tol(x->s[k], y->s[k], 1e-12 * ss);
}

/* A model with one body (mesh, loads `which`) as body number `body`, solved. */
static mc_model *solve_alone(int body, const sc_mesh *mesh, int which, result *res) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_plane(m, MC_PLANE_STRESS, 0.5));
  OK(sc_set_mesh(m, body, mesh, 0));
  load_body(m, body, mesh, which);
  OK(mc_solve(m));
  get_result(m, body, mesh, res);
  return m;
}

START_TEST(test_two_bodies_independent) {
  sc_mesh a, b;
  mc_model *m = NULL, *m1, *m2, *m3;
  result both1, both2, alone1, alone2, swapped;
  ck_assert_int_eq(sc_mesh_rect(&a, 3, 8, 3, 0, 0, 2, 1, 0.2, 1u), 0);
  ck_assert_int_eq(sc_mesh_rect(&b, 4, 5, 6, 0.5, -0.5, 1, 1.5, 0.2, 2u), 0); /* overlaps a: no contact */
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_plane(m, MC_PLANE_STRESS, 0.5));
  OK(sc_set_mesh(m, 1, &a, 0));
  OK(sc_set_mesh(m, 2, &b, 0));
  load_body(m, 1, &a, 0);
  load_body(m, 2, &b, 1);
  OK(mc_solve(m));
  get_result(m, 1, &a, &both1);
  get_result(m, 2, &b, &both2);

  m1 = solve_alone(1, &a, 0, &alone1);
  m2 = solve_alone(2, &b, 1, &alone2);
  m3 = solve_alone(1, &b, 1, &swapped); /* the body number does not matter without contact */

  same_result(&both1, &alone1, &a);
  same_result(&both2, &alone2, &b);
  same_result(&both2, &swapped, &b);
  ck_assert_double_eq_tol(both1.energy, alone1.energy + alone2.energy, 1e-12 * both1.energy);
  ck_assert_int_eq(both1.dofs, alone1.dofs + alone2.dofs);
  ck_assert_int_eq(alone1.dofs, 2 * a.n_nodes - 2 * a.n_side_nodes[SC_LEFT]);
  ck_assert_int_eq(alone2.dofs, 2 * b.n_nodes - 2 * b.n_side_nodes[SC_BOTTOM]);

  free_result(&both1), free_result(&both2), free_result(&alone1), free_result(&alone2), free_result(&swapped);
  mc_destroy(m), mc_destroy(m1), mc_destroy(m2), mc_destroy(m3);
  sc_mesh_free(&a), sc_mesh_free(&b);
}
END_TEST

static Suite *elasticity_suite(void) {
  Suite *s = suite_create("elasticity");
  TCase *tc = tcase_create("exactness");
  tcase_add_loop_test(tc, test_patch_isotropic, 0, 32);
  tcase_add_loop_test(tc, test_patch_cell_elasticity, 0, 16);
  tcase_add_loop_test(tc, test_patch_bbar, 0, 16);
  tcase_add_loop_test(tc, test_cell_laws_heterogeneous, 0, 2);
  tcase_add_loop_test(tc, test_patch_units, 0, 8);
  suite_add_tcase(s, tc);
  tc = tcase_create("convergence");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_convergence, 0, 3);
  suite_add_tcase(s, tc);
  tc = tcase_create("equilibrium");
  tcase_add_loop_test(tc, test_cantilever_equilibrium, 0, 4);
  tcase_add_loop_test(tc, test_pressure_is_normal_traction, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("analytic");
  tcase_add_loop_test(tc, test_uniaxial_bar, 0, 8);
  suite_add_tcase(s, tc);
  tc = tcase_create("independence");
  tcase_add_test(tc, test_two_bodies_independent);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(elasticity_suite()); }
