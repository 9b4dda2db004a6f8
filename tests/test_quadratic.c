/*
 * test_quadratic.c - quadratic cells (T6, Q8, Q9) beside P1 and Q1 (issue 21).
 *
 * - a linear displacement field reproduced by every cell kind, straight and curved cells, plane
 *   and axisymmetric: displacements, cell and nodal stresses exact to 1e-10;
 * - consistent loads: a uniform pressure on a straight quadratic edge gives 1/6, 1/6, 2/3 of its
 *   resultant; on a curved edge the resultant is p times the chord turned (whatever the curve);
 * - contact patch test across a straight non-matching interface for every pair of kinds (P1,
 *   Q1, T6, Q8, Q9 against each other), both interface solvers: pressures, stresses (cell and
 *   nodal) and displacements exact to 1e-10;
 * - hydrostatic patch test across a zigzag interface with T6, Q8 and Q9 cells;
 * - shrink fit of two closed rings with curved Q8 edges, 32 cells around: every nodal pressure
 *   within 0.5 % of Lame;
 * - bad input: nodes per cell, a folded curved cell, a mid-edge node shared inconsistently, an
 *   edge named by a mid-edge node; the model stays usable (and every method solves).
 */
#include "cell_kind_name.h"
#include "check_helpers.h"
#include "contact_checks.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static const int kKinds[5] = {3, 4, 6, 8, 9};

/* The contact spaces of a quadratic body 1 (docs/theory.md section 2b): the paper's linear
   multipliers, quadratic ones (MC_OPTION_MULTIPLIER), and dual mortar (the dual basis of the
   quadratic trace). For a linear body 1 the first is the paper's mortar, the last its dual. */
enum { SPACE_LINEAR, SPACE_QUADRATIC, SPACE_DUAL, SPACE_COUNT };
static const char *const kSpaceName[SPACE_COUNT] = {"linear multipliers", "quadratic multipliers", "dual mortar"};
static void set_space(mc_model *m, int space) {
  OK(mc_set_option_int(m, MC_OPTION_METHOD, space == SPACE_DUAL ? MC_METHOD_DUAL_MORTAR : MC_METHOD_MORTAR));
  OK(mc_set_option_int(m, MC_OPTION_MULTIPLIER, space == SPACE_QUADRATIC ? MC_MULTIPLIER_QUADRATIC : MC_MULTIPLIER_LINEAR));
}
/* ---- a linear field ------------------------------------------------------------------------- */

/* u = A x + c with a general A (plane), or u_r = a r, u_z = b z + c (axisymmetric): uniform
   strain, so uniform stress and no body force: the exact solution of the body with its boundary
   held to it. */
static void linear_field(double x, double y, int axisymmetric, double u[2]) {
  if (axisymmetric) {
    u[0] = 2e-3 * x, u[1] = -3e-3 * y + 1e-3;
  } else {
    u[0] = 1e-3 + 2e-3 * x - 1e-3 * y, u[1] = -2e-3 + 0.5e-3 * x - 3e-3 * y;
  }
}

/* Bends the unit square's cells: every node (mid-edge nodes included) moves, so the edges of
   quadratic cells become parabolas off their chords. */
static void bend(double *x, double *y, void *ctx) {
  (void)ctx;
  const double X = *x, Y = *y;
  *x = X + 0.08 * sin(PI * Y) * (X + 0.5);
  *y = Y + 0.06 * sin(PI * X) * (1 + Y);
}

static void shift_right(double *x, double *y, void *ctx) {
  (void)y;
  *x += *(const double *)ctx;
}

static void check_linear_field(int npc, int curved, int axisymmetric) {
  sc_mesh mesh;
  ck_assert_int_eq(sc_mesh_cells(&mesh, npc, 4, 3, 0, 0, 1, 1, 1), 0);
  if (curved) sc_mesh_map(&mesh, bend, NULL);
  double one = 1;
  if (axisymmetric) sc_mesh_map(&mesh, shift_right, &one); /* r in [1, 2] */
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  const double young = 2, nu = 0.3;
  if (axisymmetric) OK(mc_set_plane(m, MC_AXISYMMETRIC, 1));
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, young, nu));
  double *values = malloc(sizeof(double) * 2 * (size_t)mesh.n_boundary_nodes);
  for (mc_int k = 0; k < mesh.n_boundary_nodes; ++k) {
    const mc_int i = mesh.boundary_nodes[k];
    linear_field(mesh.xy[2 * i], mesh.xy[2 * i + 1], axisymmetric, values + 2 * k);
  }
  OK(mc_fix(m, 1, mesh.n_boundary_nodes, mesh.boundary_nodes, MC_XY, values));
  SUCCEEDS(mc_solve(m));
  double *u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  double *sigma = malloc(sizeof(double) * 4 * (size_t)mesh.n_cells), *nodal = malloc(sizeof(double) * 4 * (size_t)mesh.n_nodes);
  OK(mc_get_displacement(m, 1, u));
  OK(mc_get_stress(m, 1, sigma));
  OK(mc_get_nodal_stress(m, 1, nodal));
  double du = 0, scale = 0;
  for (mc_int i = 0; i < mesh.n_nodes; ++i) {
    double exact[2];
    linear_field(mesh.xy[2 * i], mesh.xy[2 * i + 1], axisymmetric, exact);
    du = fmax(du, fmax(fabs(u[2 * i] - exact[0]), fabs(u[2 * i + 1] - exact[1])));
    scale = fmax(scale, fmax(fabs(exact[0]), fabs(exact[1])));
  }
  /* the exact stress: plane strain of A's symmetric part, or axisymmetric (rr, zz, rz, tt) */
  double s[4];
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  if (axisymmetric) {
    const double err = 2e-3, ezz = -3e-3, ett = 2e-3, tr = err + ezz + ett;
    s[0] = lambda * tr + 2 * mu * err, s[1] = lambda * tr + 2 * mu * ezz, s[2] = 0, s[3] = lambda * tr + 2 * mu * ett;
  } else {
    const double exx = 2e-3, eyy = -3e-3, gxy = -1e-3 + 0.5e-3, tr = exx + eyy;
    s[0] = lambda * tr + 2 * mu * exx, s[1] = lambda * tr + 2 * mu * eyy, s[2] = mu * gxy, s[3] = nu * (s[0] + s[1]);
  }
  const double s_scale = fmax(fabs(s[0]), fabs(s[1]));
  double ds_cell = 0, ds_node = 0;
  for (mc_int c = 0; c < mesh.n_cells; ++c)
    for (int k = 0; k < 4; ++k) ds_cell = fmax(ds_cell, fabs(sigma[4 * c + k] - s[k]));
  for (mc_int i = 0; i < mesh.n_nodes; ++i)
    for (int k = 0; k < 4; ++k) ds_node = fmax(ds_node, fabs(nodal[4 * i + k] - s[k]));
  printf("linear field, %s, %s, %s: displacement error %.1e, cell stress %.1e, nodal stress %.1e (relative)\n",
         cell_kind_name(npc), curved ? "curved" : "straight", axisymmetric ? "axisymmetric" : "plane strain", du / scale,
         ds_cell / s_scale, ds_node / s_scale);
  ck_assert_msg(du <= 1e-10 * scale, "%s: displacement off by %g", cell_kind_name(npc), du / scale);
  ck_assert_msg(ds_cell <= 1e-10 * s_scale, "%s: cell stress off by %g", cell_kind_name(npc), ds_cell / s_scale);
  ck_assert_msg(ds_node <= 1e-10 * s_scale, "%s: nodal stress off by %g", cell_kind_name(npc), ds_node / s_scale);
  free(values), free(u), free(sigma), free(nodal);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}

START_TEST(linear_field_reproduced_by_every_cell_kind) {
  for (int k = 0; k < 5; ++k)
    for (int curved = 0; curved < 2; ++curved)
      for (int axisymmetric = 0; axisymmetric < 2; ++axisymmetric) check_linear_field(kKinds[k], curved, axisymmetric);
}
END_TEST

/* ---- consistent loads ------------------------------------------------------------------------ */

/* One quadratic cell, every node held, pressure p on its edge 0-1 (from (0,0) to (1,0)), whose
   middle is moved by (0, sag): the reactions are minus the consistent nodal forces. */
static void edge_load_reactions(int npc, double sag, double p, double *r) {
  sc_mesh mesh;
  ck_assert_int_eq(sc_mesh_cells(&mesh, npc, 1, 1, 0, 0, 1, 1, 0), 0);
  const mc_int mid = mesh.side_nodes[SC_BOTTOM][1];
  mesh.xy[2 * mid + 1] += sag;
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 1, 0.3));
  mc_int *all = malloc(sizeof(mc_int) * (size_t)mesh.n_nodes);
  for (mc_int i = 0; i < mesh.n_nodes; ++i) all[i] = i;
  OK(mc_fix(m, 1, mesh.n_nodes, all, MC_XY, NULL));
  OK(mc_add_pressure(m, 1, 1, mesh.side_edges[SC_BOTTOM], &p));
  SUCCEEDS(mc_solve(m));
  double *reaction = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  OK(mc_get_reaction(m, 1, reaction));
  const mc_int nodes[3] = {mesh.side_edges[SC_BOTTOM][0], mesh.side_edges[SC_BOTTOM][1], mid};
  for (int a = 0; a < 3; ++a) r[2 * a] = reaction[2 * nodes[a]], r[2 * a + 1] = reaction[2 * nodes[a] + 1];
  r[6] = r[7] = 0;
  for (mc_int i = 0; i < mesh.n_nodes; ++i) r[6] += reaction[2 * i], r[7] += reaction[2 * i + 1];
  free(all), free(reaction);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}

START_TEST(uniform_pressure_on_quadratic_edges_is_consistent) {
  const double p = 0.7;
  for (int k = 2; k < 5; ++k) {
    double r[8];
    edge_load_reactions(kKinds[k], 0, p, r); /* straight: the pressure pushes up with p per length */
    const double share[3] = {1.0 / 6, 1.0 / 6, 2.0 / 3};
    for (int a = 0; a < 3; ++a) {
      ck_assert_msg(fabs(r[2 * a]) <= 1e-14, "%s: tangential reaction %g", cell_kind_name(kKinds[k]), r[2 * a]);
      ck_assert_msg(fabs(r[2 * a + 1] + share[a] * p) <= 1e-14, "%s: node %d reaction %g, expected %g",
                    cell_kind_name(kKinds[k]), a, r[2 * a + 1], -share[a] * p);
    }
    /* curved (the middle 0.15 below the chord): the resultant of a pressure on any curve from
       (0,0) to (1,0) is p (0, 1); the ends get less and the middle more, and x-forces appear */
    edge_load_reactions(kKinds[k], -0.15, p, r);
    printf("%s edge, middle 0.15 off the chord: reactions (%.6f, %.6f) (%.6f, %.6f) (%.6f, %.6f), sum (%.2e, %.15f)\n",
           cell_kind_name(kKinds[k]), r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7]);
    ck_assert_msg(fabs(r[6]) <= 1e-14 && fabs(r[7] + p) <= 1e-14, "%s curved: resultant (%g, %g)", cell_kind_name(kKinds[k]),
                  r[6], r[7]);
    /* the edge bulges out of the cell: the pressure pushes its ends towards each other */
    ck_assert_msg(r[0] < 0 && r[2] > 0, "%s curved: the ends are not pushed together", cell_kind_name(kKinds[k]));
  }
}
END_TEST

/* ---- flat patch test, every pair of kinds ------------------------------------------------------ */

/* Body 1 = [0, 1] x [0, 0.5] (5 squares across), body 2 = [0, 1] x [-0.5, 0] (7 across: not
   matching), E1 = 1, E2 = 3, nu = 0.3, plane strain. Pressure p on body 1's top; rollers on both
   left sides (u_x = 0) and under body 2 (u_y = 0): body 1 is held vertically by contact alone.
   Exact: sigma = (0, -p, 0, -nu p) in both, u_x = nu (1 + nu) p / E x, u_y linear in y. */
typedef struct patch_errors {
  double pressure, stress, nodal_stress, displacement;
  int nodes;
} patch_errors;

static patch_errors flat_patch(int npc1, int npc2, int solver, int space) {
  const double p = 0.2, nu = 0.3, e[2] = {1, 3};
  sc_mesh b[2];
  ck_assert_int_eq(sc_mesh_cells(&b[0], npc1, 5, 3, 0, 0, 1, 0.5, 1), 0);
  ck_assert_int_eq(sc_mesh_cells(&b[1], npc2, 7, 3, 0, -0.5, 1, 0.5, 0), 0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  for (int k = 0; k < 2; ++k) {
    OK(sc_set_mesh(m, k + 1, &b[k], 0));
    OK(mc_set_material(m, k + 1, e[k], nu));
    OK(sc_fix_side(m, k + 1, &b[k], SC_LEFT, MC_X, 0));
  }
  OK(sc_fix_side(m, 2, &b[1], SC_BOTTOM, MC_Y, 0));
  double *pr = malloc(sizeof(double) * (size_t)b[0].n_side_edges[SC_TOP]);
  for (mc_int k = 0; k < b[0].n_side_edges[SC_TOP]; ++k) pr[k] = p;
  OK(mc_add_pressure(m, 1, b[0].n_side_edges[SC_TOP], b[0].side_edges[SC_TOP], pr));
  free(pr);
  OK(mc_set_contact(m, 1, b[0].n_side_edges[SC_BOTTOM], b[0].side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, b[1].n_side_edges[SC_TOP], b[1].side_edges[SC_TOP]));
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver));
  set_space(m, space);
  SUCCEEDS(mc_solve(m));
  const mc_int n_nodes[2] = {b[0].n_nodes, b[1].n_nodes};
  const double load1[2] = {0, -p}, none[2] = {0, 0};
  assert_kkt_and_balance(m, n_nodes, load1, none);
  patch_errors err = {0, 0, 0, 0, 0};
  contact_data c = contact_get(m);
  err.nodes = (int)c.n;
  for (mc_int j = 0; j < c.n; ++j) err.pressure = fmax(err.pressure, fabs(c.pressure[j] - p) / p);
  const double exact_stress[4] = {0, -p, 0, -nu * p};
  double u_top_of_2 = 0;
  for (int k = 1; k >= 0; --k) {
    double *sigma = malloc(sizeof(double) * 4 * (size_t)b[k].n_cells), *nodal = malloc(sizeof(double) * 4 * (size_t)b[k].n_nodes);
    double *u = displacement(m, k + 1, b[k].n_nodes);
    OK(mc_get_stress(m, k + 1, sigma));
    OK(mc_get_nodal_stress(m, k + 1, nodal));
    for (mc_int i = 0; i < b[k].n_cells * 4; ++i) err.stress = fmax(err.stress, fabs(sigma[i] - exact_stress[i % 4]) / p);
    for (mc_int i = 0; i < b[k].n_nodes * 4; ++i)
      err.nodal_stress = fmax(err.nodal_stress, fabs(nodal[i] - exact_stress[i % 4]) / p);
    const double exx = nu * (1 + nu) * p / e[k], eyy = -(1 - nu * nu) * p / e[k];
    const double scale = fabs(eyy) * 1.0;
    for (mc_int i = 0; i < b[k].n_nodes; ++i) {
      const double x = b[k].xy[2 * i], y = b[k].xy[2 * i + 1];
      const double ux = exx * x, uy = k == 1 ? eyy * (y + 0.5) : u_top_of_2 + eyy * y;
      err.displacement = fmax(err.displacement, fmax(fabs(u[2 * i] - ux), fabs(u[2 * i + 1] - uy)) / scale);
    }
    if (k == 1) u_top_of_2 = eyy * 0.5;
    free(sigma), free(nodal), free(u);
  }
  contact_free(&c);
  mc_destroy(m);
  sc_mesh_free(&b[0]), sc_mesh_free(&b[1]);
  return err;
}

START_TEST(flat_patch_test_every_pair_of_kinds) {
  patch_errors worst = {0, 0, 0, 0, 0};
  for (int space = 0; space < SPACE_COUNT; ++space)
  for (int solver = MC_INTERFACE_CONDENSED; solver <= MC_INTERFACE_SPARSE; ++solver)
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        if (space == SPACE_QUADRATIC && kKinds[i] <= 4) continue; /* the option is a quadratic body 1's */
        const patch_errors e = flat_patch(kKinds[i], kKinds[j], solver, space);
        printf("flat patch, %s on %s, %s, %s: %d contact nodes; errors: pressure %.1e p, stress %.1e p, "
               "nodal stress %.1e p, displacement %.1e\n",
               cell_kind_name(kKinds[i]), cell_kind_name(kKinds[j]), solver == MC_INTERFACE_SPARSE ? "sparse" : "condensed",
               kSpaceName[space], e.nodes, e.pressure, e.stress, e.nodal_stress,
               e.displacement);
        ck_assert_int_eq(e.nodes, kKinds[i] > 4 ? 11 : 6);
        worst.pressure = fmax(worst.pressure, e.pressure), worst.stress = fmax(worst.stress, e.stress);
        worst.nodal_stress = fmax(worst.nodal_stress, e.nodal_stress);
        worst.displacement = fmax(worst.displacement, e.displacement);
      }
  ck_assert_msg(worst.pressure <= 1e-10, "pressure off by %g p", worst.pressure);
  ck_assert_msg(worst.stress <= 1e-10, "cell stress off by %g p", worst.stress);
  ck_assert_msg(worst.nodal_stress <= 1e-10, "nodal stress off by %g p", worst.nodal_stress);
  ck_assert_msg(worst.displacement <= 1e-10, "displacement off by %g", worst.displacement);
}
END_TEST

/* ---- hydrostatic zigzag -------------------------------------------------------------------------- */

/* The interface y = z(x) on [0, 2]: slope +-1, kinks at x = 0.5, 1, 1.5 (test_contact_geometry). */
static double zigzag(double x) {
  const double t = fmod(x, 1.0);
  return t <= 0.5 ? t : 1 - t;
}
static void zigzag_map_above(double *x, double *y, void *ctx) {
  (void)ctx;
  const double z = zigzag(*x);
  *y = z + *y * (1 - z);
}
static void zigzag_map_below(double *x, double *y, void *ctx) {
  (void)ctx;
  const double z = zigzag(*x);
  *y = z + *y * (1 + z);
}

static void press_side(mc_model *m, int body, const sc_mesh *mesh, int side, double p) {
  const mc_int n = mesh->n_side_edges[side];
  double *pr = malloc(sizeof(double) * (size_t)n);
  for (mc_int e = 0; e < n; ++e) pr[e] = p;
  OK(mc_add_pressure(m, body, n, mesh->side_edges[side], pr));
  free(pr);
}

/* Uniform pressure p on every outer edge of both bodies; body 2 pinned isostatically, body 1 held
   by contact alone. Exact: sigma = -p I, contact pressure p, zero reactions. Body 1 has 3 cells per
   face, body 2 4 (not matching). */
START_TEST(zigzag_hydrostatic_patch_test_quadratic) {
  const double p = 0.3, nu = 0.3;
  for (int space = 0; space < SPACE_COUNT; ++space)
  for (int k = 2; k < 5; ++k) {
    const int npc = kKinds[k], npc2 = kKinds[(k + 1) % 5]; /* T6 on Q8, Q8 on Q9, Q9 on P1 */
    sc_mesh b1, b2;
    ck_assert_int_eq(sc_mesh_cells(&b1, npc, 12, 4, 0, 0, 2, 1, 0), 0);
    ck_assert_int_eq(sc_mesh_cells(&b2, npc2, 16, 4, 0, -1, 2, 1, 0), 0);
    sc_mesh_map(&b1, zigzag_map_above, NULL);
    sc_mesh_map(&b2, zigzag_map_below, NULL);
    mc_model *m = NULL;
    ck_assert_int_eq(mc_create(&m), MC_OK);
    OK(sc_set_mesh(m, 1, &b1, 0));
    OK(sc_set_mesh(m, 2, &b2, 0));
    OK(mc_set_material(m, 1, 2, nu));
    OK(mc_set_material(m, 2, 2, nu));
    const int sides1[3] = {SC_TOP, SC_LEFT, SC_RIGHT}, sides2[3] = {SC_BOTTOM, SC_LEFT, SC_RIGHT};
    for (int s = 0; s < 3; ++s) press_side(m, 1, &b1, sides1[s], p), press_side(m, 2, &b2, sides2[s], p);
    const mc_int left = b2.side_nodes[SC_BOTTOM][0], right = b2.side_nodes[SC_BOTTOM][b2.n_side_nodes[SC_BOTTOM] - 1];
    OK(mc_fix(m, 2, 1, &left, MC_XY, NULL));
    OK(mc_fix(m, 2, 1, &right, MC_Y, NULL));
    OK(mc_set_contact(m, 1, b1.n_side_edges[SC_BOTTOM], b1.side_edges[SC_BOTTOM]));
    OK(mc_set_contact(m, 2, b2.n_side_edges[SC_TOP], b2.side_edges[SC_TOP]));
    set_space(m, space);
    SUCCEEDS(mc_solve(m));
    contact_data c = contact_get(m);
    double pressure = 0, stress = 0, reaction = 0;
    for (mc_int j = 0; j < c.n; ++j) pressure = fmax(pressure, fabs(c.pressure[j] - p) / p);
    const sc_mesh *mesh[2] = {&b1, &b2};
    const double exact[4] = {-p, -p, 0, -2 * nu * p};
    for (int b = 0; b < 2; ++b) {
      double *sigma = malloc(sizeof(double) * 4 * (size_t)mesh[b]->n_nodes), *r = malloc(sizeof(double) * 2 * (size_t)mesh[b]->n_nodes);
      OK(mc_get_nodal_stress(m, b + 1, sigma));
      for (mc_int i = 0; i < 4 * mesh[b]->n_nodes; ++i) stress = fmax(stress, fabs(sigma[i] - exact[i % 4]) / p);
      OK(mc_get_reaction(m, b + 1, r));
      reaction = fmax(reaction, max_abs(r, 2 * (size_t)mesh[b]->n_nodes) / (p * 2.0 / 12));
      free(sigma), free(r);
    }
    printf("zigzag hydrostatic patch, %s on %s, %s: %d contact positions; errors: pressures %.1e p, nodal "
           "stresses %.1e p, reactions %.1e p h\n",
           cell_kind_name(npc), cell_kind_name(npc2), kSpaceName[space], (int)c.n,
           pressure, stress, reaction);
    ck_assert_msg(pressure <= 1e-10 && stress <= 1e-10 && reaction <= 1e-10, "%s: not exact", cell_kind_name(npc));
    contact_free(&c);
    mc_destroy(m);
    sc_mesh_free(&b1), sc_mesh_free(&b2);
  }
}
END_TEST

/* ---- body 2's end crossing a body-1 node ------------------------------------------------------------ */

/* Body 1 (5 x 3 cells on [0,1] x [0,0.5], pressed by 0.01 on its top, u_x = 0 on both sides) on a
   narrower body 2 (7 x 3 cells on [x0, x0 + 0.7] x [-0.5, 0], clamped): body 2's ends lie inside
   body-1 edges, in contact. Returns body 1's displacements; the contact forces must balance the
   load and satisfy KKT. */
static double *partly_covered(int npc1, int npc2, double x0, int space, mc_int *n_nodes) {
  sc_mesh b[2];
  ck_assert_int_eq(sc_mesh_cells(&b[0], npc1, 5, 3, 0, 0, 1, 0.5, 1), 0);
  ck_assert_int_eq(sc_mesh_cells(&b[1], npc2, 7, 3, x0, -0.5, 0.7, 0.5, 0), 0);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  for (int k = 0; k < 2; ++k) OK(sc_set_mesh(m, k + 1, &b[k], 0)), OK(mc_set_material(m, k + 1, 1, 0.3));
  OK(sc_fix_side(m, 1, &b[0], SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 1, &b[0], SC_RIGHT, MC_X, 0));
  OK(sc_fix_side(m, 2, &b[1], SC_BOTTOM, MC_XY, 0));
  press_side(m, 1, &b[0], SC_TOP, 0.01);
  OK(mc_set_contact(m, 1, b[0].n_side_edges[SC_BOTTOM], b[0].side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, b[1].n_side_edges[SC_TOP], b[1].side_edges[SC_TOP]));
  set_space(m, space);
  SUCCEEDS(mc_solve(m));
  /* (Not assert_kkt: the nodal gaps of a quadratic body 1 are its rows', and the positions
     without a row of their own, here the run's ends next to body 2's corners, may penetrate;
     a quadratic edge's consistent nodal forces may be negative at a corner next to a partly
     loaded edge. docs/robustness.md.) */
  contact_data c = contact_get(m);
  double total = 0, equilibrium, complementarity;
  for (mc_int j = 0; j < c.n; ++j) total += c.force[j];
  ck_assert_msg(fabs(total - 0.01) <= 1e-12, "contact forces %.15g against the load 0.01", total);
  OK(mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium));
  OK(mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity));
  ck_assert_msg(equilibrium < 1e-10 && complementarity < 1e-10, "residuals %g, %g", equilibrium, complementarity);
  for (mc_int j = 0; j < c.n; ++j) ck_assert_msg(c.pressure[j] >= 0, "pressure %g < 0 at position %d", c.pressure[j], (int)j);
  contact_free(&c);
  double *u = displacement(m, 1, b[0].n_nodes);
  *n_nodes = b[0].n_nodes;
  mc_destroy(m);
  sc_mesh_free(&b[0]), sc_mesh_free(&b[1]);
  return u;
}

/* The solution must not jump as body 2's end crosses a body-1 corner (x0 = 0.2; the other end at
   0.9, a middle) or a middle (x0 = 0.1, the other end on the corner 0.8): displacements at
   x0 +- 1e-5 (5e-5 of an edge) within 1e-3 of those at x0, for quadratic bodies 1 with every
   space (a constraint left pinned at the corner by a vanishing end element made this 3.7e-2
   before the ends were blended), and for a linear body 1 with the paper's rows and their dual
   (5.6e-3 before the dual basis shared its end hats as the paper's does). */
START_TEST(solution_continuous_as_body2_end_crosses_a_node) {
  const int pairs[4][2] = {{8, 8}, {6, 3}, {9, 4}, {3, 3}};
  const double crossings[2] = {0.2, 0.1}, eps = 1e-5;
  for (int p = 0; p < 4; ++p)
    for (int space = 0; space < SPACE_COUNT; ++space)
      for (int c = 0; c < 2; ++c) {
        mc_int n = 0;
        double *u0 = partly_covered(pairs[p][0], pairs[p][1], crossings[c], space, &n), scale = max_abs(u0, 2 * (size_t)n);
        double jump = 0;
        for (int side = -1; side <= 1; side += 2) {
          double *u = partly_covered(pairs[p][0], pairs[p][1], crossings[c] + side * eps, space, &n);
          for (mc_int i = 0; i < 2 * n; ++i) jump = fmax(jump, fabs(u[i] - u0[i]) / scale);
          free(u);
        }
        printf("body 2's end crossing x = %.1f, %s on %s, %s: displacements move by %.2e of their size "
               "for a shift of %.0e\n",
               crossings[c], cell_kind_name(pairs[p][0]), cell_kind_name(pairs[p][1]),
               kSpaceName[space], jump, eps);
        ck_assert_msg(jump <= 1e-3, "%s on %s: the solution jumps by %g", cell_kind_name(pairs[p][0]),
                      cell_kind_name(pairs[p][1]), jump);
        free(u0);
      }
}
END_TEST

/* ---- shrink fit, curved Q8 rings ------------------------------------------------------------------ */

/* The annulus r0 <= r <= r1 in Q8 cells with curved edges: nt cells around, nr across, every node
   (mid-edge nodes included) on its circle or ray. Lattice point (I, J), I < 2 nt around, J <= 2 nr
   out, at angle pi I / nt and radius r0 + J (r1 - r0) / (2 nr); a cell's centre is skipped. */
typedef struct q8_ring {
  int nt, nr;
  mc_int n_nodes, n_cells;
  double *xy;
  mc_int *cells, *id; /* id: lattice point -> node, -1 if unused */
} q8_ring;

static mc_int ring_id(const q8_ring *g, int I, int J) { return g->id[J * 2 * g->nt + (I % (2 * g->nt))]; }

static void q8_ring_build(q8_ring *g, int nt, int nr, double r0, double r1) {
  const int nI = 2 * nt, nJ = 2 * nr + 1;
  g->nt = nt, g->nr = nr;
  g->id = malloc(sizeof(mc_int) * (size_t)(nI * nJ));
  g->n_nodes = 0;
  for (int J = 0; J < nJ; ++J)
    for (int I = 0; I < nI; ++I) g->id[J * nI + I] = (I % 2 == 1 && J % 2 == 1) ? -1 : g->n_nodes++;
  g->xy = malloc(sizeof(double) * 2 * (size_t)g->n_nodes);
  for (int J = 0; J < nJ; ++J)
    for (int I = 0; I < nI; ++I) {
      const mc_int k = g->id[J * nI + I];
      if (k < 0) continue;
      const double r = r0 + J * (r1 - r0) / (2 * nr), t = PI * I / nt;
      const int q = I % (nI / 4) == 0 ? I / (nI / 4) : -1; /* exactly on an axis */
      const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
      g->xy[2 * k] = r * (q >= 0 ? cs[q] : cos(t)), g->xy[2 * k + 1] = r * (q >= 0 ? sn[q] : sin(t));
    }
  g->n_cells = nt * nr;
  g->cells = malloc(sizeof(mc_int) * 8 * (size_t)g->n_cells);
  mc_int *c = g->cells;
  for (int j = 0; j < nr; ++j)
    for (int i = 0; i < nt; ++i, c += 8) {
      const int I = 2 * i, J = 2 * j; /* outwards, then around: counter-clockwise */
      c[0] = ring_id(g, I, J), c[1] = ring_id(g, I, J + 2), c[2] = ring_id(g, I + 2, J + 2), c[3] = ring_id(g, I + 2, J);
      c[4] = ring_id(g, I, J + 1), c[5] = ring_id(g, I + 1, J + 2), c[6] = ring_id(g, I + 2, J + 1), c[7] = ring_id(g, I + 1, J);
    }
}

static void q8_ring_free(q8_ring *g) { free(g->xy), free(g->cells), free(g->id); }

/* Circle J (= 0: inner, = 2 nr: outer) as nt edges named by their corners, oriented as the cells. */
static mc_int *q8_ring_circle(const q8_ring *g, int J) {
  mc_int *e = malloc(sizeof(mc_int) * 2 * (size_t)g->nt);
  for (int i = 0; i < g->nt; ++i) {
    const mc_int a = ring_id(g, 2 * i, J), b = ring_id(g, 2 * i + 2, J);
    e[2 * i] = J == 0 ? b : a, e[2 * i + 1] = J == 0 ? a : b;
  }
  return e;
}

/* u_y = 0 on the x axis, u_x = 0 on the y axis (every node there). */
static void q8_ring_fix_axes(mc_model *m, int body, const q8_ring *g) {
  const int nJ = 2 * g->nr + 1;
  mc_int *ids = calloc(2 * (size_t)nJ, sizeof(mc_int));
  for (int J = 0; J < nJ; ++J) ids[2 * J] = ring_id(g, 0, J), ids[2 * J + 1] = ring_id(g, g->nt, J);
  OK(mc_fix(m, body, 2 * nJ, ids, MC_Y, NULL));
  for (int J = 0; J < nJ; ++J) ids[2 * J] = ring_id(g, g->nt / 2, J), ids[2 * J + 1] = ring_id(g, 3 * g->nt / 2, J);
  OK(mc_fix(m, body, 2 * nJ, ids, MC_X, NULL));
  free(ids);
}

static double lame_radial_displacement(double r, double ri, double ro, double pi, double po, double young, double nu) {
  const double d = ro * ro - ri * ri, A = (pi * ri * ri - po * ro * ro) / d, B = (pi - po) * ri * ri * ro * ro / d;
  return r * (1 + nu) / young * ((1 - 2 * nu) * A + B / (r * r));
}

/* Shaft ring [0.5, 1 + delta] (body 1, 32 Q8 cells around), hub ring [1, 2] (body 2, 40 around),
   E1 = 1, E2 = 2, nu = 0.3, plane strain: the pressure on the shaft from Lame (test_contact_geometry's
   shrink_fit_pressure). Returns the worst |p_j / p - 1| over every contact position. */
static double q8_shrink_fit(double delta_cells, int surface, int space) {
  const int nt1 = 32, nt2 = 40, nr = 4;
  const double a = 0.5, R = 1, c = 2, delta = delta_cells * 2 * PI / nt1, b = R + delta, e1 = 1, e2 = 2, nu = 0.3;
  q8_ring shaft, hub;
  q8_ring_build(&shaft, nt1, nr, a, b);
  q8_ring_build(&hub, nt2, 2 * nr, R, c);
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_mesh(m, 1, shaft.n_nodes, shaft.xy, shaft.n_cells, 8, shaft.cells));
  OK(mc_set_mesh(m, 2, hub.n_nodes, hub.xy, hub.n_cells, 8, hub.cells));
  OK(mc_set_material(m, 1, e1, nu));
  OK(mc_set_material(m, 2, e2, nu));
  q8_ring_fix_axes(m, 1, &shaft);
  q8_ring_fix_axes(m, 2, &hub);
  mc_int *loop1 = q8_ring_circle(&shaft, 2 * shaft.nr), *loop2 = q8_ring_circle(&hub, 0);
  OK(mc_set_contact(m, 1, nt1, loop1));
  OK(mc_set_contact(m, 2, nt2, loop2));
  OK(mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, surface));
  set_space(m, space);
  free(loop1), free(loop2);
  SUCCEEDS(mc_solve(m));
  const double u_shaft = -lame_radial_displacement(b, a, b, 0, 1, e1, nu);
  const double u_hub = lame_radial_displacement(R, R, c, 1, 0, e2, nu);
  const double p_lame = (b - R) / (u_shaft + u_hub * b / R);
  contact_data cd = contact_get(m);
  double worst = 0, lo = INFINITY, hi = 0, total = 0;
  for (mc_int j = 0; j < cd.n; ++j) total += cd.force[j];
  for (mc_int j = 0; j < cd.n; ++j) {
    worst = fmax(worst, fabs(cd.pressure[j] / p_lame - 1));
    lo = fmin(lo, cd.pressure[j] / p_lame), hi = fmax(hi, cd.pressure[j] / p_lame);
  }
  printf("Q8 shrink fit, %s, %s, delta = %.1f h: %d contact positions, nodal p / Lame in [%.5f, %.5f], "
         "mean %.5f, %ld iterations\n",
         surface == MC_SURFACE_SMOOTH ? "smooth" : "faceted", kSpaceName[space],
         delta_cells, (int)cd.n, lo, hi, total / (2 * PI * b) / p_lame,
         info_int(m, MC_INFO_ITERATIONS));
  ck_assert_int_eq(cd.n, 2 * nt1); /* corners and middles of the closed loop */
  contact_free(&cd);
  mc_destroy(m);
  q8_ring_free(&shaft), q8_ring_free(&hub);
  return worst;
}

START_TEST(shrink_fit_curved_q8_rings_lame) {
  const double deltas[3] = {0.1, 0.3, 1.0};
  for (int space = 0; space < SPACE_COUNT; ++space) {
    double worst[3];
    for (int k = 0; k < 3; ++k) {
      worst[k] = q8_shrink_fit(deltas[k], MC_SURFACE_SMOOTH, space);
      q8_shrink_fit(deltas[k], MC_SURFACE_FACETED, space);
    }
    for (int k = 0; k < 3; ++k)
      ck_assert_msg(worst[k] <= 0.005, "delta = %g h, %s: a nodal pressure %.3f %% from Lame", deltas[k],
                    kSpaceName[space], 100 * worst[k]);
  }
}
END_TEST

/* ---- axisymmetric shrink fit ------------------------------------------------------------------------ */

/* test_axisymmetric's shrink fit with quadratic cells: a hub b <= r <= c shrunk on a solid shaft
   r <= b, both 0 <= z <= L, free ends, interference delta by gap offsets on every node of the
   shaft's surface (mid-edge nodes included); the plane-stress Lame field is the exact 3D solution,
   a uniform pressure p = E delta (c^2 - b^2) / (2 b c^2). Coarse, non-matching: 8 x 12 shaft and
   8 x 17 hub cells (test_axisymmetric uses 32 x 48 and 32 x 68 linear cells and 1 %). */
START_TEST(axisymmetric_shrink_fit_quadratic_lame) {
  const double b = 1, c = 2, length = 1, delta = 1e-3, young = 1, nu = 0.3;
  const double lame = young * delta * (c * c - b * b) / (2 * b * c * c);
  const int kinds[3] = {6, 8, 9};
  for (int k = 0; k < 3; ++k)
    for (int method = MC_METHOD_MORTAR; method <= MC_METHOD_NODE_TO_SEGMENT; method += 2) {
      sc_mesh shaft, hub;
      ck_assert_int_eq(sc_mesh_cells(&shaft, kinds[k], 8, 12, 0, 0, b, length, 0), 0);
      ck_assert_int_eq(sc_mesh_cells(&hub, kinds[k], 8, 17, b, 0, c - b, length, 1), 0);
      mc_model *m = sc_axisymmetric_shrink_fit(&shaft, &hub, young, nu, delta);
      ck_assert_ptr_nonnull(m);
      const mc_int n = shaft.n_side_nodes[SC_RIGHT];
      OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
      SUCCEEDS(mc_solve(m));
      contact_data cd = contact_get(m);
      ck_assert_int_eq(cd.n, n);
      double worst = 0;
      for (mc_int j = 0; j < cd.n; ++j) worst = fmax(worst, fabs(cd.pressure[j] / lame - 1));
      printf("axisymmetric shrink fit, %s, %s: %d contact positions, every pressure within %.4f %% of Lame\n",
             cell_kind_name(kinds[k]), method == MC_METHOD_MORTAR ? "mortar" : "node-to-segment", (int)cd.n, 100 * worst);
      if (method == MC_METHOD_MORTAR) {
        ck_assert_msg(worst < 1e-3, "%s: a pressure %.3f %% off Lame", cell_kind_name(kinds[k]), 100 * worst);
        /* The quadratic multipliers and dual mortar: a value at every node, so the T6 shaft's
           one-way diagonals show in the pressure (docs/robustness.md); within the shrink fit's
           0.5 %. */
        for (int space = SPACE_QUADRATIC; space <= SPACE_DUAL; ++space) {
          set_space(m, space);
          SUCCEEDS(mc_solve(m));
          contact_data cq = contact_get(m);
          double worst_q = 0;
          for (mc_int j = 0; j < cq.n; ++j) worst_q = fmax(worst_q, fabs(cq.pressure[j] / lame - 1));
          printf("axisymmetric shrink fit, %s, %s: every pressure within %.4f %% of Lame\n", cell_kind_name(kinds[k]),
                 kSpaceName[space], 100 * worst_q);
          ck_assert_msg(worst_q < 5e-3, "%s, %s: a pressure %.3f %% off Lame", cell_kind_name(kinds[k]), kSpaceName[space],
                        100 * worst_q);
          contact_free(&cq);
        }
      }
      contact_free(&cd);
      mc_destroy(m);
      sc_mesh_free(&shaft), sc_mesh_free(&hub);
    }
}
END_TEST

/* ---- bad input -------------------------------------------------------------------------------------- */

START_TEST(bad_quadratic_input_is_refused_clearly) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  sc_mesh q8, t6;
  ck_assert_int_eq(sc_mesh_cells(&q8, 8, 2, 1, 0, 0, 2, 1, 0), 0);
  ck_assert_int_eq(sc_mesh_cells(&t6, 6, 2, 1, 0, -1, 2, 1, 0), 0);
  /* nodes per cell */
  for (int npc = 0; npc <= 10; ++npc) {
    if (npc == 3 || npc == 4 || npc == 6 || npc == 8 || npc == 9) continue;
    FAILS(mc_set_mesh(m, 1, q8.n_nodes, q8.xy, 1, npc, q8.cells), MC_ERROR_ARGUMENT, "nodes_per_cell");
  }
  /* a folded cell: the middle of edge 0-1 of cell 0 moved past the quarter point towards corner 0 */
  {
    double *xy = malloc(sizeof(double) * 2 * (size_t)q8.n_nodes);
    memcpy(xy, q8.xy, sizeof(double) * 2 * (size_t)q8.n_nodes);
    const mc_int mid = q8.cells[4];
    xy[2 * mid] = 0.1; /* corners at x = 0 and 1: the Jacobian turns negative near corner 0 */
    FAILS(mc_set_mesh(m, 1, q8.n_nodes, xy, q8.n_cells, 8, q8.cells), MC_ERROR_MESH, "cell 0 (Q8 quadrilateral) is inverted or folded");
    /* a curved edge bulging across the cell: corners fine, inside folded */
    memcpy(xy, q8.xy, sizeof(double) * 2 * (size_t)q8.n_nodes);
    xy[2 * q8.cells[4] + 1] = 1.2; /* the bottom edge's middle above the top edge */
    FAILS(mc_set_mesh(m, 1, q8.n_nodes, xy, q8.n_cells, 8, q8.cells), MC_ERROR_MESH, "inverted or folded inside");
    free(xy);
  }
  /* a straight-sided cell (middles at their edges' midpoints) whose corner 0 is nearly flat: its
     corner cross product 2e-10 passes the corner check (above 1e-12 of the longest side squared)
     but its Jacobian there is below 1e-8 of the cell's mean. The corners-only check of
     straight-sided cells must leave it to the lattice, which refuses it naming the point and
     node, as it did before that shortcut. */
  {
    const double corners[4][2] = {{0, 0}, {2, 0}, {1, 1}, {-1, 1e-10}};
    double xy8[16];
    for (int a = 0; a < 4; ++a) {
      const int b = (a + 1) % 4;
      xy8[2 * a] = corners[a][0], xy8[2 * a + 1] = corners[a][1];
      xy8[8 + 2 * a] = 0.5 * (corners[a][0] + corners[b][0]), xy8[8 + 2 * a + 1] = 0.5 * (corners[a][1] + corners[b][1]);
    }
    const mc_int cell8[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    FAILS(mc_set_mesh(m, 1, 8, xy8, 1, 8, cell8), MC_ERROR_MESH,
          "cell 0 (Q8 quadrilateral) is inverted or folded inside: its Jacobian is zero at reference point (-1, -1), "
          "nearest its node 0 (node 0)");
    const double tri[3][2] = {{0, 0}, {2, 0}, {-1, 1e-10}};
    double xy6[12];
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      xy6[2 * a] = tri[a][0], xy6[2 * a + 1] = tri[a][1];
      xy6[6 + 2 * a] = 0.5 * (tri[a][0] + tri[b][0]), xy6[6 + 2 * a + 1] = 0.5 * (tri[a][1] + tri[b][1]);
    }
    const mc_int cell6[6] = {0, 1, 2, 3, 4, 5};
    /* a straight-sided T6's Jacobian is constant, twice its area, so the lattice's test relative
       to the area always passes once the corners have: the sliver goes in, with the lattice as
       without it */
    SUCCEEDS(mc_set_mesh(m, 1, 6, xy6, 1, 6, cell6));
    /* the same straight-sided Q8 with a sound corner goes in */
    xy8[7] = 0.5, xy8[13] = 0.75, xy8[15] = 0.25; /* corner 3 at (-1, 0.5) and its two middles */
    SUCCEEDS(mc_set_mesh(m, 1, 8, xy8, 1, 8, cell8));
  }
  /* a mid-edge node shared inconsistently: cell 1 names another node as the middle of the edge it
     shares with cell 0 (cell 0's edge 1-2 is cell 1's edge 3-0) */
  {
    mc_int *cells = malloc(sizeof(mc_int) * 8 * (size_t)q8.n_cells);
    memcpy(cells, q8.cells, sizeof(mc_int) * 8 * (size_t)q8.n_cells);
    cells[8 + 7] = q8.cells[8 + 5]; /* cell 1's left middle := its own right middle */
    FAILS(mc_set_mesh(m, 1, q8.n_nodes, q8.xy, q8.n_cells, 8, cells), MC_ERROR_MESH, NULL);
    printf("mid-edge node twice: %s\n", mc_errmsg(m));
    memcpy(cells, q8.cells, sizeof(mc_int) * 8 * (size_t)q8.n_cells);
    cells[8 + 7] = q8.cells[6]; /* cell 1's left middle := cell 0's top middle: two roles */
    FAILS(mc_set_mesh(m, 1, q8.n_nodes, q8.xy, q8.n_cells, 8, cells), MC_ERROR_MESH, "mid-edge node");
    free(cells);
  }
  /* the model is still usable: a good mesh goes in, and an edge named by a mid-edge node is refused */
  SUCCEEDS(sc_set_mesh(m, 1, &q8, 0));
  SUCCEEDS(sc_set_mesh(m, 2, &t6, 0));
  const mc_int bad_edge[2] = {q8.side_nodes[SC_BOTTOM][0], q8.side_nodes[SC_BOTTOM][1]}; /* corner, middle */
  FAILS(mc_set_contact(m, 1, 1, bad_edge), MC_ERROR_CONTACT, "is named by its two corner nodes");
  const double p = 1;
  FAILS(mc_add_pressure(m, 1, 1, bad_edge, &p), MC_ERROR_MESH, "mid-edge");
  /* mc_set_contact_curved: the middle must be that edge's, every id in range, the cells quadratic */
  {
    const mc_int *bottom = q8.side_nodes[SC_BOTTOM]; /* corner, middle, corner, middle, corner */
    const mc_int wrong_middle[3] = {bottom[0], bottom[2], bottom[3]};
    FAILS(mc_set_contact_curved(m, 1, 1, wrong_middle), MC_ERROR_CONTACT, "is not the middle of that edge");
    printf("curved edge with another edge's middle: %s\n", mc_errmsg(m));
    const mc_int out_of_range[3] = {bottom[0], bottom[2], q8.n_nodes};
    FAILS(mc_set_contact_curved(m, 1, 1, out_of_range), MC_ERROR_ARGUMENT, "edges[2]");
    const mc_int good[3] = {bottom[0], bottom[2], bottom[1]};
    SUCCEEDS(mc_set_contact_curved(m, 1, 1, good));
    mc_model *linear = NULL;
    ck_assert_int_eq(mc_create(&linear), MC_OK);
    sc_mesh q1;
    ck_assert_int_eq(sc_mesh_cells(&q1, 4, 2, 1, 0, 0, 2, 1, 0), 0);
    {
      mc_model *m = linear; /* for the macros' messages */
      SUCCEEDS(sc_set_mesh(m, 1, &q1, 0));
      const mc_int *b = q1.side_nodes[SC_BOTTOM];
      const mc_int three[3] = {b[0], b[1], b[2]};
      FAILS(mc_set_contact_curved(m, 1, 1, three), MC_ERROR_CONTACT, "body 1 has linear cells");
    }
    mc_destroy(linear);
    sc_mesh_free(&q1);
  }
  /* every method on a quadratic body 1 */
  OK(mc_set_material(m, 1, 1, 0.3));
  OK(mc_set_material(m, 2, 1, 0.3));
  OK(sc_fix_side(m, 1, &q8, SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &t6, SC_LEFT, MC_X, 0));
  OK(sc_fix_side(m, 2, &t6, SC_BOTTOM, MC_Y, 0));
  OK(mc_add_pressure(m, 1, 1, q8.side_edges[SC_TOP], &p));
  OK(mc_set_contact(m, 1, q8.n_side_edges[SC_BOTTOM], q8.side_edges[SC_BOTTOM]));
  OK(mc_set_contact(m, 2, t6.n_side_edges[SC_TOP], t6.side_edges[SC_TOP]));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, MC_METHOD_DUAL_MORTAR));
  SUCCEEDS(mc_solve(m));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, MC_METHOD_NODE_TO_SEGMENT));
  SUCCEEDS(mc_solve(m));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, MC_METHOD_MORTAR));
  SUCCEEDS(mc_solve(m));
  /* MC_OPTION_MULTIPLIER: two values, integer-valued; the model stays usable */
  FAILS(mc_set_option_int(m, MC_OPTION_MULTIPLIER, 2), MC_ERROR_ARGUMENT, "MC_OPTION_MULTIPLIER");
  FAILS(mc_set_option_int(m, MC_OPTION_MULTIPLIER, -1), MC_ERROR_ARGUMENT, "MC_MULTIPLIER_QUADRATIC");
  FAILS(mc_set_option_real(m, MC_OPTION_MULTIPLIER, 1.0), MC_ERROR_ARGUMENT, "integer-valued");
  OK(mc_set_option_int(m, MC_OPTION_MULTIPLIER, MC_MULTIPLIER_QUADRATIC));
  SUCCEEDS(mc_solve(m));
  mc_destroy(m);
  sc_mesh_free(&q8), sc_mesh_free(&t6);
}
END_TEST

int main(void) {
  Suite *s = suite_create("quadratic");
  TCase *tc = tcase_create("cells");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, linear_field_reproduced_by_every_cell_kind);
  tcase_add_test(tc, uniform_pressure_on_quadratic_edges_is_consistent);
  tcase_add_test(tc, bad_quadratic_input_is_refused_clearly);
  suite_add_tcase(s, tc);
  TCase *contact = tcase_create("contact");
  tcase_set_timeout(contact, 300);
  tcase_add_test(contact, flat_patch_test_every_pair_of_kinds);
  tcase_add_test(contact, zigzag_hydrostatic_patch_test_quadratic);
  tcase_add_test(contact, shrink_fit_curved_q8_rings_lame);
  tcase_add_test(contact, axisymmetric_shrink_fit_quadratic_lame);
  tcase_add_test(contact, solution_continuous_as_body2_end_crosses_a_node);
  suite_add_tcase(s, contact);
  return sc_run_suite(s);
}
