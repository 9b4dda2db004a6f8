/*
 * test_input.c - bad input on every entry point of the header, beyond test_errors.c: each
 * call gets its status and a message naming the argument (and index, as the caller numbers it,
 * in index base 0 and 1), and the model stays usable: after the failed calls, a solve gives
 * exactly the answer from before (the failed calls changed nothing).
 *
 *   null_model        every entry point with a NULL model; status names of unknown codes
 *   null_outputs      NULL output pointers on every getter (infos, contact arrays)
 *   mesh_arguments    mc_set_mesh: NULL arrays, counts, nodes per cell, cell ids out of range
 *                     (base - 1, n_nodes + base, INT_MIN, INT_MAX)
 *   mesh_cells        degenerate, inverted, duplicated, non-convex cells, a node twice in a
 *                     cell, an edge in three cells, overlapping cells, coincident nodes
 *   extreme_ids       INT_MIN / INT_MAX / -1 ids on every call that takes ids (no overflow)
 *   edges             load and contact edges: not on the boundary, not an edge, degenerate,
 *                     out of range, given twice, pinched contact surfaces (cells meeting at a
 *                     node), bad counts
 *   non_finite        NaN / +-inf in every real array and scalar
 *   material          the bounds of E and nu, exactly and just inside; finite numbers whose
 *                     solution overflows (MC_ERROR_ARGUMENT from mc_solve, not inf/NaN results;
 *                     stresses alone: from the getter that computes them, or from mc_solve with
 *                     MC_OPTION_EAGER_RESULTS)
 *   options_infos     every option with values out of range, wrong type; infos of wrong type
 *   interface_solver  MC_OPTION_INTERFACE_SOLVER out of range (the message names the value and
 *                     the option) and through mc_set_option_real; MC_INFO_INTERFACE_SOLVER
 *                     through mc_get_info_real (both "integer-valued")
 *   out_of_order      each call before its prerequisites, results after a change or a failed
 *                     solve; contact surfaces that do not face each other or do not overlap
 *   gap_offset        mc_set_gap_offset: state, ids, nodes not on the contact surface
 *   fully_supported   valid input at an edge: a body with every node fixed (rigid obstacle)
 */
#include <check.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mortarcontact.h"
#include "check_helpers.h"
#include "scenes.h"

/* ---- a contact scene whose answer must survive every failed call ----------------------- */

/* Two stacked blocks: body 1 = [0,1] x [0,0.5] (P1 6x3, base-shifted ids) on body 2 =
   [0,1] x [-0.5,0] (Q1 8x4) clamped at its bottom; body 1 held by contact and u_x = 0 at its
   top middle node, pushed down by t = (0.1, -1) on its top. */
typedef struct {
  mc_model *m;
  int base;
  sc_mesh top, bottom;
  double *u1, *u2, *p; /* reference answer */
  mc_int nc;
} scene;

static mc_int *shifted(const sc_mesh *mesh, int side, int base) {
  return sc_ids(mesh->side_edges[side], 2 * mesh->n_side_edges[side], base);
}

static void scene_solution(scene *s, double *u1, double *u2, double *p) {
  mc_model *m = s->m;
  mc_int nc = -1;
  OK(mc_get_displacement(m, 1, u1));
  OK(mc_get_displacement(m, 2, u2));
  OK(mc_get_contact_count(m, &nc));
  ck_assert_int_eq(nc, s->nc);
  OK(mc_get_contact_pressure(m, p));
}

static void scene_make(scene *s, int base) {
  mc_model *m = NULL;
  mc_int mid, *e1, *e2;
  double total = 0;
  mc_int k;
  memset(s, 0, sizeof *s);
  s->base = base;
  ck_assert_int_eq(sc_mesh_rect(&s->top, 3, 6, 3, 0, 0, 1, 0.5, 0, 1u), 0);
  ck_assert_int_eq(sc_mesh_rect(&s->bottom, 4, 8, 4, 0, -0.5, 1, 0.5, 0, 1u), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  s->m = m;
  if (base) OK(mc_set_index_base(m, 1));
  OK(sc_set_mesh(m, 1, &s->top, base));
  OK(sc_set_mesh(m, 2, &s->bottom, base));
  OK(mc_set_material(m, 1, 100.0, 0.3));
  OK(mc_set_material(m, 2, 200.0, 0.3));
  OK(sc_fix_side(m, 2, &s->bottom, SC_BOTTOM, MC_XY, base));
  mid = sc_node(&s->top, 3, 3) + base;
  OK(mc_fix(m, 1, 1, &mid, MC_X, NULL));
  OK(sc_traction_side(m, 1, &s->top, SC_TOP, 0.1, -1.0, base));
  e1 = shifted(&s->top, SC_BOTTOM, base);
  e2 = shifted(&s->bottom, SC_TOP, base);
  OK(mc_set_contact(m, 1, s->top.n_side_edges[SC_BOTTOM], e1));
  OK(mc_set_contact(m, 2, s->bottom.n_side_edges[SC_TOP], e2));
  free(e1), free(e2);
  OK(mc_solve(m));
  OK(mc_get_contact_count(m, &s->nc));
  ck_assert_int_eq(s->nc, s->top.n_side_nodes[SC_BOTTOM]);
  s->u1 = malloc(sizeof(double) * 2 * (size_t)s->top.n_nodes);
  s->u2 = malloc(sizeof(double) * 2 * (size_t)s->bottom.n_nodes);
  s->p = malloc(sizeof(double) * (size_t)s->nc);
  scene_solution(s, s->u1, s->u2, s->p);
  /* a meaningful reference: uniform push of 1 per unit length, so the pressure is about 1 */
  for (k = 0; k < s->nc; ++k) total += s->p[k];
  ck_assert_msg(fabs(total / s->nc - 1) < 0.05, "mean pressure %g", total / s->nc);
}

/* The failed calls changed nothing: results are still there (first_pass 0), and a new solve
   gives OK, "" and exactly the same answer. */
static void scene_check(scene *s, int first_pass) {
  mc_model *m = s->m;
  double *u1 = malloc(sizeof(double) * 2 * (size_t)s->top.n_nodes);
  double *u2 = malloc(sizeof(double) * 2 * (size_t)s->bottom.n_nodes);
  double *p = malloc(sizeof(double) * (size_t)s->nc);
  int pass;
  mc_int k;
  for (pass = first_pass; pass < 2; ++pass) {
    if (pass == 1) SUCCEEDS(mc_solve(m));
    scene_solution(s, u1, u2, p);
    for (k = 0; k < 2 * s->top.n_nodes; ++k) ck_assert_msg(u1[k] == s->u1[k], "u1[%d] changed", (int)k);
    for (k = 0; k < 2 * s->bottom.n_nodes; ++k) ck_assert_msg(u2[k] == s->u2[k], "u2[%d] changed", (int)k);
    for (k = 0; k < s->nc; ++k) ck_assert_msg(p[k] == s->p[k], "p[%d] = %.17g, was %.17g", (int)k, p[k], s->p[k]);
  }
  ck_assert_str_eq(mc_errmsg(m), "");
  free(u1), free(u2), free(p);
}

static void scene_usable(scene *s) { scene_check(s, 0); }
/* After successful calls that changed nothing of substance (but require a new solve). */
static void scene_resolves(scene *s) { scene_check(s, 1); }

static void scene_free(scene *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->top);
  sc_mesh_free(&s->bottom);
  free(s->u1), free(s->u2), free(s->p);
}

/* "name[index] = id" as the library writes it in base 0, "name(index + 1) = id" in base 1 */
static const char *needle(char *buf, size_t size, const char *name, long index, long id, int base) {
  snprintf(buf, size, "%s = %ld", AT(name, index, base), id);
  return buf;
}

/* ---- NULL model, status names ------------------------------------------------------------ */

START_TEST(test_null_model) {
  mc_int id = 0, edge[2] = {0, 1}, n;
  double v[9] = {0}, xy[6] = {0, 0, 1, 0, 0, 1};
  int64_t iv;
  int k;
  ck_assert_int_eq(mc_set_index_base(NULL, 0), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_plane(NULL, MC_PLANE_STRAIN, 1), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_mesh(NULL, 1, 3, xy, 1, 3, edge), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_material(NULL, 1, 1, 0.3), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_cell_elasticity(NULL, 1, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_fix(NULL, 1, 1, &id, MC_XY, NULL), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_add_traction(NULL, 1, 1, edge, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_add_pressure(NULL, 1, 1, edge, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_add_nodal_force(NULL, 1, 1, &id, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_body_force(NULL, 1, 0, 0), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_clear_loads(NULL, 1), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_contact(NULL, 1, 1, edge), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_gap_offset(NULL, 1, &id, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_option_int(NULL, MC_OPTION_METHOD, MC_METHOD_MORTAR), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_option_real(NULL, MC_OPTION_TOLERANCE, 1e-8), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_solve(NULL), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_set_log_callback(NULL, NULL, NULL), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_info_int(NULL, MC_INFO_DOFS, &iv), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_info_real(NULL, MC_INFO_STRAIN_ENERGY, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_displacement(NULL, 1, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_stress(NULL, 1, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_reaction(NULL, 1, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_count(NULL, &n), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_nodes(NULL, &n), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_pressure(NULL, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_force(NULL, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_gap(NULL, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_initial_gap(NULL, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_get_contact_normal(NULL, v), MC_ERROR_ARGUMENT);
  ck_assert_int_eq(mc_write_vtu(NULL, "/dev/null"), MC_ERROR_ARGUMENT);
  ck_assert(strstr(mc_errmsg(NULL), "NULL") != NULL);
  /* status names: every code has its own; anything else, including values a C caller may
     pass outside the enum, is "unknown status" */
  for (k = MC_OK; k <= MC_ERROR_INTERNAL; ++k) {
    int j;
    ck_assert_str_ne(mc_status_string((mc_status)k), "unknown status");
    for (j = MC_OK; j < k; ++j) ck_assert_str_ne(mc_status_string((mc_status)k), mc_status_string((mc_status)j));
  }
  ck_assert_str_eq(mc_status_string((mc_status)-1), "unknown status");
  ck_assert_str_eq(mc_status_string((mc_status)10), "unknown status");
  ck_assert_str_eq(mc_status_string((mc_status)1234), "unknown status");
  ck_assert_str_eq(mc_status_string((mc_status)INT_MIN), "unknown status");
  ck_assert_int_eq(mc_version_number(), MC_VERSION_NUMBER);
  ck_assert_str_eq(mc_version_string(), MC_VERSION_STRING);
}
END_TEST

/* ---- NULL outputs ---------------------------------------------------------------------------- */

START_TEST(test_null_outputs) {
  scene s;
  mc_model *m;
  scene_make(&s, _i);
  m = s.m;
  FAILS(mc_get_info_int(m, MC_INFO_DOFS, NULL), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, NULL), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_get_stress(m, 2, NULL), MC_ERROR_ARGUMENT, "sigma");
  FAILS(mc_get_reaction(m, 2, NULL), MC_ERROR_ARGUMENT, "r");
  FAILS(mc_get_contact_count(m, NULL), MC_ERROR_ARGUMENT, "n is NULL");
  FAILS(mc_get_contact_nodes(m, NULL), MC_ERROR_ARGUMENT, "nodes is NULL");
  FAILS(mc_get_contact_pressure(m, NULL), MC_ERROR_ARGUMENT, "p is NULL");
  FAILS(mc_get_contact_force(m, NULL), MC_ERROR_ARGUMENT, "f is NULL");
  FAILS(mc_get_contact_gap(m, NULL), MC_ERROR_ARGUMENT, "g is NULL");
  FAILS(mc_get_contact_initial_gap(m, NULL), MC_ERROR_ARGUMENT, "g0 is NULL");
  FAILS(mc_get_contact_normal(m, NULL), MC_ERROR_ARGUMENT, "n is NULL");
  FAILS(mc_write_vtu(m, NULL), MC_ERROR_ARGUMENT, "path");
  scene_usable(&s);
  scene_free(&s);
}
END_TEST

/* ---- mc_set_mesh: arguments --------------------------------------------------------------------- */

START_TEST(test_mesh_arguments) {
  scene s;
  mc_model *m;
  const int base = _i;
  mc_int n, nc, *cells;
  char buf[96];
  static const mc_int extreme[2] = {INT_MIN, INT_MAX};
  int k;
  scene_make(&s, base);
  m = s.m;
  n = s.top.n_nodes, nc = s.top.n_cells;
  cells = sc_ids(s.top.cells, 3 * nc, base);
  FAILS(mc_set_mesh(m, 1, n, NULL, nc, 3, cells), MC_ERROR_ARGUMENT, "xy is NULL");
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 3, NULL), MC_ERROR_ARGUMENT, "cells is NULL");
  FAILS(mc_set_mesh(m, 1, -1, s.top.xy, nc, 3, cells), MC_ERROR_ARGUMENT, "n_nodes = -1");
  FAILS(mc_set_mesh(m, 1, 2, s.top.xy, 1, 3, cells), MC_ERROR_ARGUMENT, "n_nodes = 2");
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, -3, 3, cells), MC_ERROR_ARGUMENT, "n_cells = -3");
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, 0, 3, cells), MC_ERROR_ARGUMENT, "n_cells = 0");
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 2, cells), MC_ERROR_ARGUMENT, "nodes_per_cell = 2");
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 5, cells), MC_ERROR_ARGUMENT, "nodes_per_cell = 5");
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 0, cells), MC_ERROR_ARGUMENT, "nodes_per_cell = 0");
  scene_usable(&s);
  /* ids: base - 1 and n_nodes + base are the first ids out of range on either side */
  cells[7] = base - 1;
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 3, cells), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "cells", 7, base - 1, base));
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 3, cells), MC_ERROR_ARGUMENT, base ? "(cell 3)" : "(cell 2)");
  cells[7] = s.top.cells[7] + base;
  cells[3 * nc - 1] = n + base;
  FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 3, cells), MC_ERROR_ARGUMENT,
        needle(buf, sizeof buf, "cells", 3 * nc - 1, n + base, base));
  for (k = 0; k < 2; ++k) {
    cells[3 * nc - 1] = extreme[k];
    FAILS(mc_set_mesh(m, 1, n, s.top.xy, nc, 3, cells), MC_ERROR_ARGUMENT,
          needle(buf, sizeof buf, "cells", 3 * nc - 1, extreme[k], base));
  }
  cells[3 * nc - 1] = s.top.cells[3 * nc - 1] + base;
  scene_usable(&s);
  /* the repaired arrays are accepted */
  SUCCEEDS(mc_set_mesh(m, 1, n, s.top.xy, nc, 3, cells));
  free(cells);
  scene_free(&s);
}
END_TEST

/* ---- mc_set_mesh: cells ----------------------------------------------------------------------- */

/* Each case: a small mesh with one defect; the message names the cell (or node) as the caller
   numbers it. Square: 0 (0,0) 1 (1,0) 2 (1,1) 3 (0,1). */
typedef struct {
  int n_nodes, n_cells, npc;
  double xy[10];
  mc_int cells[9];
  const char *what; /* message piece; %d = the cell or node id before the index base */
  int id;
} mesh_case;

#define SQUARE {0, 0, 1, 0, 1, 1, 0, 1}

START_TEST(test_mesh_cells) {
  scene s;
  mc_model *m;
  const int base = _i;
  char buf[96];
  int k;
  static const mesh_case bad[] = {
      {4, 2, 3, SQUARE, {0, 1, 2, 0, 3, 2}, "cell %d is clockwise", 1}, /* inverted */
      {5, 3, 3, {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5}, {0, 1, 2, 0, 2, 3, 0, 4, 2}, "cell %d is degenerate", 2},
      {4, 3, 3, SQUARE, {0, 1, 2, 0, 2, 3, 2, 0, 1}, "cell %d duplicates cell", 2},
      {4, 2, 3, SQUARE, {0, 1, 2, 0, 2, 2}, "cell %d uses node", 1},
      {4, 1, 4, {0, 0, 2, 0, 2, 2, 1.5, 0.5}, {0, 1, 2, 3}, "cell %d is clockwise or non-convex at its corner 3", 0},
      {4, 1, 4, SQUARE, {0, 1, 2, 2}, "cell %d uses node", 0},
      {5, 2, 3, {0, 0, 1, 0, 1, 1, 0, 1, 2, 0}, {0, 1, 2, 0, 2, 3}, "node %d is used by no cell", 4},
      {4, 3, 3, SQUARE, {0, 1, 2, 0, 2, 3, 0, 1, 3}, "overlap along edge", 0}, /* cells 0 and 2 */
      {5, 3, 3, {0, 0, 1, 0, 1, 1, 2, 0.5, 3, 0.5}, {0, 1, 2, 1, 3, 2, 1, 4, 2}, "of cell %d is shared by more than two", 2},
  };
  scene_make(&s, base);
  m = s.m;
  for (k = 0; k < (int)(sizeof bad / sizeof bad[0]); ++k) {
    mc_int *cells = sc_ids(bad[k].cells, bad[k].n_cells * bad[k].npc, base);
    snprintf(buf, sizeof buf, bad[k].what, bad[k].id + base);
    FAILS(mc_set_mesh(m, 1 + k % 2, bad[k].n_nodes, bad[k].xy, bad[k].n_cells, bad[k].npc, cells), MC_ERROR_MESH, buf);
    free(cells);
  }
  /* cells 0 and 2 of the overlap case, in the caller's numbering */
  {
    mc_int *cells = sc_ids(bad[7].cells, 9, base);
    snprintf(buf, sizeof buf, "cells %d and %d overlap", base, 2 + base);
    FAILS(mc_set_mesh(m, 1, 4, bad[7].xy, 3, 3, cells), MC_ERROR_MESH, buf);
    free(cells);
  }
  /* every node at one point */
  {
    static const double same[8] = {3, 3, 3, 3, 3, 3, 3, 3};
    static const mc_int cells0[6] = {0, 1, 2, 0, 2, 3};
    mc_int *cells = sc_ids(cells0, 6, base);
    FAILS(mc_set_mesh(m, 1, 4, same, 2, 3, cells), MC_ERROR_MESH, "xy: all 4 nodes coincide");
    free(cells);
  }
  scene_usable(&s);
  /* a tiny valid mesh far from the origin is fine (tolerances are relative to the cell) */
  {
    mc_model *m2 = NULL;
    static const double far[8] = {1e6, 1e6, 1e6 + 1e-3, 1e6, 1e6 + 1e-3, 1e6 + 1e-3, 1e6, 1e6 + 1e-3};
    static const mc_int cells[6] = {0, 1, 2, 0, 2, 3};
    ck_assert_int_eq(mc_create(&m2), MC_OK);
    m = m2;
    SUCCEEDS(mc_set_mesh(m2, 1, 4, far, 2, 3, cells));
    mc_destroy(m2);
  }
  scene_free(&s);
}
END_TEST

/* ---- extreme ids: no int overflow, the caller's id in the message ------------------------------- */

START_TEST(test_extreme_ids) {
  scene s;
  mc_model *m;
  const int base = _i;
  static const mc_int extreme[4] = {INT_MIN, INT_MAX, INT_MIN + 1, -1};
  char buf[96];
  int k;
  scene_make(&s, base);
  m = s.m;
  for (k = 0; k < 4; ++k) {
    mc_int id = extreme[k];
    mc_int nodes[2] = {base, id};
    mc_int edges[4] = {s.top.side_edges[SC_TOP][0] + base, s.top.side_edges[SC_TOP][1] + base, id, base};
    double v[4] = {0, 0, 0, 0};
    FAILS(mc_fix(m, 1, 2, nodes, MC_XY, NULL), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "nodes", 1, id, base));
    FAILS(mc_add_nodal_force(m, 2, 2, nodes, v), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "nodes", 1, id, base));
    FAILS(mc_add_traction(m, 1, 2, edges, v), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "edges", 2, id, base));
    FAILS(mc_add_pressure(m, 1, 2, edges, v), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "edges", 2, id, base));
    FAILS(mc_set_contact(m, 1, 2, edges), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "edges", 2, id, base));
    FAILS(mc_set_gap_offset(m, 2, nodes, v), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "nodes", 1, id, base));
    {
      mc_int cells[6] = {base, 1 + base, 2 + base, base, id, 2 + base};
      double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
      FAILS(mc_set_mesh(m, 2, 4, xy, 2, 3, cells), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "cells", 4, id, base));
    }
  }
  scene_usable(&s);
  scene_free(&s);
}
END_TEST

/* ---- load and contact edges --------------------------------------------------------------------- */

START_TEST(test_edges) {
  scene s;
  mc_model *m;
  const int base = _i;
  const sc_mesh *top;
  mc_int interior[2], corners[2], same[2], reversed[4], *side;
  double t[4] = {1, 0, 1, 0};
  char buf[96];
  scene_make(&s, base);
  m = s.m;
  top = &s.top;
  interior[0] = sc_node(top, 2, 1) + base, interior[1] = sc_node(top, 3, 1) + base;
  corners[0] = sc_node(top, 0, 0) + base, corners[1] = sc_node(top, 6, 3) + base; /* not an edge */
  same[0] = same[1] = sc_node(top, 0, 0) + base;
  side = shifted(top, SC_BOTTOM, base);
  /* loads: not an edge on the boundary (MC_ERROR_MESH), naming the pair of entries */
  FAILS(mc_add_traction(m, 1, 1, interior, t), MC_ERROR_MESH, AT_RANGE("edges", 0, 1, base));
  FAILS(mc_add_traction(m, 1, 1, corners, t), MC_ERROR_MESH, AT_RANGE("edges", 0, 1, base));
  FAILS(mc_add_pressure(m, 1, 1, same, t), MC_ERROR_MESH, AT_RANGE("edges", 0, 1, base));
  {
    mc_int two[4] = {side[0], side[1], interior[0], interior[1]};
    FAILS(mc_add_pressure(m, 1, 2, two, t), MC_ERROR_MESH, AT_RANGE("edges", 2, 3, base));
    snprintf(buf, sizeof buf, "(%d, %d)", (int)interior[0], (int)interior[1]);
    FAILS(mc_add_traction(m, 1, 2, two, t), MC_ERROR_MESH, buf);
  }
  /* with base 1, 0-based ids of the last node are one off */
  if (base == 1) {
    mc_int zero_based[2] = {0, 1};
    FAILS(mc_add_traction(m, 1, 1, zero_based, t), MC_ERROR_ARGUMENT, "edges(1) = 0");
    FAILS(mc_add_traction(m, 1, 1, zero_based, t), MC_ERROR_ARGUMENT, "index base 1");
  }
  scene_usable(&s);

  /* contact surfaces */
  FAILS(mc_set_contact(m, 1, 0, side), MC_ERROR_ARGUMENT, "n_edges = 0");
  FAILS(mc_set_contact(m, 1, -1, side), MC_ERROR_ARGUMENT, "n_edges = -1");
  FAILS(mc_set_contact(m, 1, 1, interior), MC_ERROR_CONTACT, AT_RANGE("edges", 0, 1, base));
  FAILS(mc_set_contact(m, 1, 1, corners), MC_ERROR_CONTACT, AT_RANGE("edges", 0, 1, base));
  FAILS(mc_set_contact(m, 2, 1, same), MC_ERROR_CONTACT, AT_RANGE("edges", 0, 1, base));
  reversed[0] = side[2], reversed[1] = side[3], reversed[2] = side[3], reversed[3] = side[2];
  snprintf(buf, sizeof buf, "edge (%d, %d) is given twice", (int)(side[2] < side[3] ? side[2] : side[3]),
           (int)(side[2] < side[3] ? side[3] : side[2]));
  FAILS(mc_set_contact(m, 1, 2, reversed), MC_ERROR_CONTACT, buf);
  reversed[2] = side[2], reversed[3] = side[3];
  FAILS(mc_set_contact(m, 1, 2, reversed), MC_ERROR_CONTACT, buf);
  free(side);
  scene_usable(&s);
  /* zero load edges: a no-op, NULL arrays are fine then */
  SUCCEEDS(mc_add_traction(m, 1, 0, NULL, NULL));
  SUCCEEDS(mc_add_pressure(m, 2, 0, NULL, NULL));
  scene_resolves(&s);
  scene_free(&s);
}
END_TEST

/* Two triangles meeting at node 0 only (a bow tie): its boundary passes twice through node 0.
   Such a contact surface has no order and no normal at node 0: MC_ERROR_CONTACT (it used to
   hang mc_solve in an endless chain walk). A simple chain of the same mesh is fine. */
START_TEST(test_pinched_contact) {
  mc_model *m = NULL;
  const int base = _i;
  static const double xy[10] = {0, 0, 1, -1, 1, 1, -1, 1, -1, -1};
  static const mc_int cells0[6] = {0, 1, 2, 0, 3, 4};
  static const mc_int loop0[8] = {4, 0, 0, 1, 1, 2, 2, 0}; /* 4 -> 0, then 0 -> 1 -> 2 -> 0 */
  static const mc_int both0[4] = {4, 0, 2, 0};             /* both arrive at 0 */
  static const mc_int out0[4] = {0, 1, 0, 3};              /* both leave 0 */
  static const double xy2[8] = {-2, -3, 2, -3, 2, -2, -2, -2};
  static const mc_int quad0[4] = {0, 1, 2, 3}, top0[2] = {2, 3};
  mc_int *cells = sc_ids(cells0, 6, base), *loop = sc_ids(loop0, 8, base), *both = sc_ids(both0, 4, base);
  mc_int *out = sc_ids(out0, 4, base), *quad = sc_ids(quad0, 4, base), *top = sc_ids(top0, 2, base);
  mc_int chain[4] = {cells[4], cells[5], cells[5], cells[3]}; /* 3 -> 4 -> 0: a simple chain */
  char buf[64];
  SUCCEEDS(mc_create(&m));
  if (base) SUCCEEDS(mc_set_index_base(m, 1));
  SUCCEEDS(mc_set_mesh(m, 1, 5, xy, 2, 3, cells));
  SUCCEEDS(mc_set_material(m, 1, 1, 0.3));
  SUCCEEDS(mc_set_mesh(m, 2, 4, xy2, 1, 4, quad));
  SUCCEEDS(mc_set_material(m, 2, 1, 0.3));
  SUCCEEDS(mc_fix(m, 2, 4, quad, MC_XY, NULL));
  SUCCEEDS(mc_set_contact(m, 2, 1, top));
  snprintf(buf, sizeof buf, "arrive at node %d", base);
  FAILS(mc_set_contact(m, 1, 4, loop), MC_ERROR_CONTACT, buf);
  FAILS(mc_set_contact(m, 1, 4, loop), MC_ERROR_CONTACT, AT_RANGE("edges", 6, 7, base));
  FAILS(mc_set_contact(m, 1, 2, both), MC_ERROR_CONTACT, buf);
  snprintf(buf, sizeof buf, "leave node %d", base);
  FAILS(mc_set_contact(m, 1, 2, out), MC_ERROR_CONTACT, buf);
  FAILS(mc_set_contact(m, 1, 2, out), MC_ERROR_CONTACT, AT_RANGE("edges", 2, 3, base));
  /* the model is usable: a simple chain of the same mesh solves. Each triangle is held by
     supports (they would hinge about node 0), body 1's weight pulls it towards body 2. */
  SUCCEEDS(mc_set_contact(m, 1, 2, chain));
  {
    mc_int held[3] = {cells[0], cells[1], cells[4]}, nc = 0; /* nodes 0, 1, 3 */
    int64_t rows = 0;
    SUCCEEDS(mc_fix(m, 1, 3, held, MC_XY, NULL));
    SUCCEEDS(mc_set_body_force(m, 1, 0, -1));
    SUCCEEDS(mc_solve(m));
    SUCCEEDS(mc_get_contact_count(m, &nc));
    ck_assert_int_eq(nc, 4); /* node 4 is a corner (135 degrees): a position in each face */
    SUCCEEDS(mc_get_info_int(m, MC_INFO_CONTACT_NODES, &rows));
    ck_assert_int_ge(rows, 1); /* node 4 sees body 2 */
  }
  mc_destroy(m);
  free(cells), free(loop), free(both), free(out), free(quad), free(top);
}
END_TEST

/* ---- a body whose every unknown is prescribed --------------------------------------------------- */

/* Valid input that used to give MC_ERROR_INTERNAL (CHOLMOD analyze of a 0 x 0 matrix): a body
   with all nodes fixed, alone and as a rigid obstacle under body 1, which is pressed onto it
   by a prescribed displacement of its top. */
START_TEST(test_fully_supported_body) {
  mc_model *m = NULL;
  sc_mesh top, bottom;
  mc_int k, nc = 0, *e1, *e2;
  double *u, *r, *f, *g, dy = -0.01, total = 0, reaction = 0;
  ck_assert_int_eq(sc_mesh_rect(&top, 4, 3, 2, 0, 0, 1, 1, 0, 1u), 0);
  ck_assert_int_eq(sc_mesh_rect(&bottom, 3, 5, 2, -0.5, -1, 2, 1, 0, 1u), 0);
  SUCCEEDS(mc_create(&m));
  SUCCEEDS(sc_set_mesh(m, 2, &bottom, 0));
  SUCCEEDS(mc_set_material(m, 2, 10, 0.3));
  SUCCEEDS(mc_fix(m, 2, bottom.n_boundary_nodes, bottom.boundary_nodes, MC_XY, NULL));
  SUCCEEDS(mc_solve(m)); /* interior nodes free */
  {
    mc_int *all = malloc(sizeof(mc_int) * (size_t)bottom.n_nodes);
    for (k = 0; k < bottom.n_nodes; ++k) all[k] = k;
    SUCCEEDS(mc_fix(m, 2, bottom.n_nodes, all, MC_XY, NULL));
    free(all);
  }
  SUCCEEDS(mc_solve(m)); /* nothing free */
  u = malloc(sizeof(double) * 2 * (size_t)bottom.n_nodes);
  SUCCEEDS(mc_get_displacement(m, 2, u));
  for (k = 0; k < 2 * bottom.n_nodes; ++k) ck_assert(u[k] == 0);
  free(u);
  /* body 1 pressed onto it */
  SUCCEEDS(sc_set_mesh(m, 1, &top, 0));
  SUCCEEDS(mc_set_material(m, 1, 10, 0.3));
  {
    double *v = calloc(2 * (size_t)top.n_side_nodes[SC_TOP], sizeof(double));
    for (k = 0; k < top.n_side_nodes[SC_TOP]; ++k) v[2 * k + 1] = dy;
    SUCCEEDS(mc_fix(m, 1, top.n_side_nodes[SC_TOP], top.side_nodes[SC_TOP], MC_XY, v));
    free(v);
  }
  e1 = top.side_edges[SC_BOTTOM], e2 = bottom.side_edges[SC_TOP];
  SUCCEEDS(mc_set_contact(m, 1, top.n_side_edges[SC_BOTTOM], e1));
  SUCCEEDS(mc_set_contact(m, 2, bottom.n_side_edges[SC_TOP], e2));
  SUCCEEDS(mc_solve(m));
  SUCCEEDS(mc_get_contact_count(m, &nc));
  ck_assert_int_eq(nc, top.n_side_nodes[SC_BOTTOM]);
  f = malloc(sizeof(double) * (size_t)nc), g = malloc(sizeof(double) * (size_t)nc);
  r = malloc(sizeof(double) * 2 * (size_t)top.n_nodes);
  SUCCEEDS(mc_get_contact_force(m, f));
  SUCCEEDS(mc_get_contact_gap(m, g));
  SUCCEEDS(mc_get_reaction(m, 1, r));
  for (k = 0; k < nc; ++k) {
    total += f[k];
    ck_assert_msg(g[k] > -1e-12 && (f[k] == 0 || fabs(g[k]) < 1e-12), "node %d: gap %g, force %g", (int)k, g[k], f[k]);
  }
  for (k = 0; k < top.n_side_nodes[SC_TOP]; ++k) reaction += r[2 * top.side_nodes[SC_TOP][k] + 1];
  ck_assert_msg(total > 0, "contact force %g", total);
  /* the supports push down exactly what contact pushes up */
  ck_assert_msg(fabs(reaction + total) < 1e-10 * total, "reaction %.17g, contact %.17g", reaction, total);
  free(f), free(g), free(r);
  mc_destroy(m);
  sc_mesh_free(&top);
  sc_mesh_free(&bottom);
}
END_TEST

/* ---- non-finite reals ----------------------------------------------------------------------------- */

START_TEST(test_non_finite) {
  scene s;
  mc_model *m;
  const int base = _i;
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  int k;
  scene_make(&s, base);
  m = s.m;
  for (k = 0; k < 3; ++k) {
    const double x = bad[k];
    mc_int nodes[2] = {base, 1 + base};
    mc_int *edges = shifted(&s.top, SC_TOP, base);
    double v[4] = {0, 0, 0, x}, d[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double *dd = malloc(sizeof(double) * 9 * (size_t)s.top.n_cells), *xy;
    mc_int c, *cells;
    FAILS(mc_fix(m, 1, 2, nodes, MC_Y, v), MC_ERROR_ARGUMENT, AT("values", 3, base));
    FAILS(mc_fix(m, 1, 2, nodes, MC_XY, v), MC_ERROR_ARGUMENT, AT("values", 3, base));
    {
      /* components outside the mask are ignored, even when not finite (a fresh model) */
      mc_model *m2 = NULL;
      ck_assert_int_eq(mc_create(&m2), MC_OK);
      if (base) ck_assert_int_eq(mc_set_index_base(m2, 1), MC_OK);
      ck_assert_int_eq(sc_set_mesh(m2, 1, &s.top, base), MC_OK);
      ck_assert_int_eq(mc_fix(m2, 1, 2, nodes, MC_X, v), MC_OK);
      ck_assert_str_eq(mc_errmsg(m2), "");
      mc_destroy(m2);
    }
    FAILS(mc_add_nodal_force(m, 1, 2, nodes, v), MC_ERROR_ARGUMENT, AT("force", 3, base));
    FAILS(mc_add_traction(m, 1, 2, edges, v), MC_ERROR_ARGUMENT, AT("traction", 3, base));
    v[1] = x;
    FAILS(mc_add_pressure(m, 1, 2, edges, v), MC_ERROR_ARGUMENT, AT("pressure", 1, base));
    FAILS(mc_set_body_force(m, 2, x, 0), MC_ERROR_ARGUMENT, "fx");
    FAILS(mc_set_body_force(m, 2, 0, x), MC_ERROR_ARGUMENT, "fy");
    FAILS(mc_set_plane(m, MC_PLANE_STRAIN, x), MC_ERROR_ARGUMENT, "thickness");
    FAILS(mc_set_material(m, 1, x, 0.3), MC_ERROR_MATERIAL, "young");
    FAILS(mc_set_material(m, 1, 1, x), MC_ERROR_MATERIAL, "poisson");
    FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, x), MC_ERROR_ARGUMENT, "value");
    /* offsets of body-1 contact nodes (the bottom side) */
    nodes[0] = s.top.side_nodes[SC_BOTTOM][0] + base, nodes[1] = s.top.side_nodes[SC_BOTTOM][1] + base;
    FAILS(mc_set_gap_offset(m, 2, nodes, v), MC_ERROR_ARGUMENT, AT("offset", 1, base));
    for (c = 0; c < s.top.n_cells; ++c) memcpy(dd + 9 * c, d, sizeof d);
    dd[9 * (s.top.n_cells - 1) + 4] = x;
    {
      char buf[32];
      snprintf(buf, sizeof buf, "%s", AT("d", 9 * (s.top.n_cells - 1) + 4, base));
      FAILS(mc_set_cell_elasticity(m, 1, dd), MC_ERROR_ARGUMENT, buf);
    }
    xy = malloc(sizeof(double) * 2 * (size_t)s.bottom.n_nodes);
    memcpy(xy, s.bottom.xy, sizeof(double) * 2 * (size_t)s.bottom.n_nodes);
    xy[0] = x;
    cells = sc_ids(s.bottom.cells, 4 * s.bottom.n_cells, base);
    FAILS(mc_set_mesh(m, 2, s.bottom.n_nodes, xy, s.bottom.n_cells, 4, cells), MC_ERROR_ARGUMENT, AT("xy", 0, base));
    free(edges), free(dd), free(xy), free(cells);
  }
  /* finite but huge coordinates: span overflows to infinity; rejected, not a crash */
  {
    double xy[8] = {-DBL_MAX, 0, DBL_MAX, 0, DBL_MAX, 1, -DBL_MAX, 1};
    mc_int q[4] = {base, 1 + base, 2 + base, 3 + base};
    FAILS(mc_set_mesh(m, 2, 4, xy, 1, 4, q), MC_ERROR_MESH, "cell");
  }
  scene_usable(&s);
  scene_free(&s);
}
END_TEST

/* ---- E and nu: the bounds ----------------------------------------------------------------------- */

START_TEST(test_material) {
  scene s;
  mc_model *m;
  scene_make(&s, 0);
  m = s.m;
  FAILS(mc_set_material(m, 1, -0.0, 0.3), MC_ERROR_MATERIAL, "young");
  FAILS(mc_set_material(m, 2, -DBL_MIN, 0.3), MC_ERROR_MATERIAL, "young");
  FAILS(mc_set_material(m, 1, 1, -1.0), MC_ERROR_MATERIAL, "poisson = -1");
  FAILS(mc_set_material(m, 1, 1, 0.5), MC_ERROR_MATERIAL, "poisson = 0.5");
  FAILS(mc_set_material(m, 1, 1, nextafter(-1.0, -2.0)), MC_ERROR_MATERIAL, "poisson");
  FAILS(mc_set_material(m, 1, 1, nextafter(0.5, 1.0)), MC_ERROR_MATERIAL, "poisson");
  FAILS(mc_set_material(m, 2, 1, 2), MC_ERROR_MATERIAL, "body 2");
  scene_usable(&s);
  /* accepted, but beyond what double precision can solve: the solve says so instead of
     returning infinities or NaN with MC_OK; no results; the scene repairs */
  {
    double u[2 * 64];
    int64_t iv;
    ck_assert_int_le(s.top.n_nodes, 64);
    mc_status st;
    SUCCEEDS(mc_set_material(m, 1, DBL_MAX, 0.3));
    st = mc_solve(m); /* MC_ERROR_SINGULAR today: the infinities reach the contact problem */
    ck_assert_msg(st != MC_OK, "E = DBL_MAX solved");
    FAILS(mc_get_displacement(m, 1, u), MC_ERROR_STATE, "mc_solve");
    SUCCEEDS(mc_set_material(m, 1, 100.0, 0.3));
    FAILS(mc_get_contact_pressure(m, u), MC_ERROR_STATE, "mc_solve");
    scene_resolves(&s);
    SUCCEEDS(mc_get_info_int(m, MC_INFO_ITERATIONS, &iv));
  }
  /* the same without contact (with contact, overflow inside the contact problem may surface
     as MC_ERROR_SINGULAR instead): thickness, body force, traction */
  {
    mc_model *m2 = NULL;
    double u[2 * 64];
    ck_assert_int_eq(mc_create(&m2), MC_OK);
    m = m2;
    SUCCEEDS(sc_set_mesh(m, 1, &s.top, 0));
    SUCCEEDS(mc_set_material(m, 1, 100.0, 0.3));
    SUCCEEDS(sc_fix_side(m, 1, &s.top, SC_LEFT, MC_XY, 0));
    SUCCEEDS(mc_set_plane(m, MC_PLANE_STRESS, DBL_MAX));
    FAILS(mc_solve(m), MC_ERROR_ARGUMENT, "overflows");
    SUCCEEDS(mc_set_plane(m, MC_PLANE_STRESS, 1));
    SUCCEEDS(mc_set_body_force(m, 1, -DBL_MAX, 0));
    /* only the stresses overflow here (the displacements stay finite): with results
       on demand (the default) the solve succeeds and mc_get_stress (or mc_get_nodal_stress,
       mc_write_vtu) says so, again and again, the displacements staying readable; with eager
       results mc_solve says so */
    {
      double sigma[4 * 64];
      ck_assert_int_le(4 * s.top.n_cells, 4 * 64);
      SUCCEEDS(mc_solve(m));
      FAILS(mc_get_stress(m, 1, sigma), MC_ERROR_ARGUMENT, "overflow");
      FAILS(mc_get_nodal_stress(m, 1, sigma), MC_ERROR_ARGUMENT, "sigma[");
      FAILS(mc_write_vtu(m, "/dev/null"), MC_ERROR_ARGUMENT, "overflow");
      SUCCEEDS(mc_get_displacement(m, 1, u));
      SUCCEEDS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 1));
      FAILS(mc_solve(m), MC_ERROR_ARGUMENT, "overflows");
      FAILS(mc_get_displacement(m, 1, u), MC_ERROR_STATE, "mc_solve");
      SUCCEEDS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 0));
    }
    SUCCEEDS(mc_set_body_force(m, 1, 0, 0));
    SUCCEEDS(sc_traction_side(m, 1, &s.top, SC_RIGHT, 0, 1e308, 0));
    {
      double sigma[4 * 64];
      SUCCEEDS(mc_solve(m)); /* the stresses overflow, as above */
      FAILS(mc_get_stress(m, 1, sigma), MC_ERROR_ARGUMENT, "overflow");
      SUCCEEDS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 1));
      FAILS(mc_solve(m), MC_ERROR_ARGUMENT, "overflows");
      FAILS(mc_get_displacement(m, 1, u), MC_ERROR_STATE, "mc_solve");
      SUCCEEDS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 0));
    }
    SUCCEEDS(mc_clear_loads(m, 1));
    SUCCEEDS(sc_traction_side(m, 1, &s.top, SC_RIGHT, 0, 1, 0));
    SUCCEEDS(mc_solve(m));
    SUCCEEDS(mc_get_displacement(m, 1, u));
    ck_assert(u[2 * sc_node(&s.top, 6, 0) + 1] > 0); /* pulled up at the free end */
    mc_destroy(m2);
    m = s.m;
  }
  /* just inside: accepted */
  SUCCEEDS(mc_set_material(m, 1, 100.0, nextafter(0.5, 0.0)));
  SUCCEEDS(mc_set_material(m, 1, 100.0, nextafter(-1.0, 0.0)));
  SUCCEEDS(mc_set_material(m, 1, DBL_MIN, 0.3));
  scene_free(&s);
}
END_TEST

/* ---- options and infos ------------------------------------------------------------------------- */

START_TEST(test_options_infos) {
  scene s;
  mc_model *m;
  static const int int_options[6] = {MC_OPTION_METHOD, MC_OPTION_MAX_ITERATIONS, MC_OPTION_ORDERING,
                                     MC_OPTION_Q1_INTEGRATION, MC_OPTION_CONTACT_NORMAL, MC_OPTION_LOAD_STEPS};
  static const int64_t too_big[6] = {MC_METHOD_NODE_TO_SEGMENT + 1, 1000001, MC_ORDERING_METIS + 1, MC_Q1_BBAR + 1,
                                     MC_NORMAL_MORTAR + 1, 1000001};
  static const int64_t too_small[6] = {-1, 0, -1, -1, -1, 0};
  int k;
  int64_t iv = -7;
  double rv = -7;
  scene_make(&s, 0);
  m = s.m;
  for (k = 0; k < 6; ++k) {
    int o = int_options[k];
    FAILS(mc_set_option_int(m, o, too_big[k]), MC_ERROR_ARGUMENT, "value");
    FAILS(mc_set_option_int(m, o, too_small[k]), MC_ERROR_ARGUMENT, "value");
    FAILS(mc_set_option_int(m, o, INT64_MAX), MC_ERROR_ARGUMENT, "value");
    FAILS(mc_set_option_int(m, o, INT64_MIN), MC_ERROR_ARGUMENT, "value");
    FAILS(mc_set_option_int(m, o, (int64_t)1 << 32), MC_ERROR_ARGUMENT, "value"); /* not truncated to 0 */
    FAILS(mc_set_option_real(m, o, 1.0), MC_ERROR_ARGUMENT, "integer-valued");
  }
  /* MC_OPTION_EAGER_RESULTS: 0 or 1, named in the message */
  FAILS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 2), MC_ERROR_ARGUMENT, "MC_OPTION_EAGER_RESULTS");
  FAILS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, -1), MC_ERROR_ARGUMENT, "value = -1");
  FAILS(mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, (int64_t)1 << 32), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_EAGER_RESULTS, 1.0), MC_ERROR_ARGUMENT, "integer-valued");
  FAILS(mc_set_option_int(m, MC_OPTION_TOLERANCE, 1), MC_ERROR_ARGUMENT, "real-valued");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, 0), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, 1), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, -1e-8), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_int(m, MC_OPTION_FRICTION_CT, 1), MC_ERROR_ARGUMENT, "real-valued");
  FAILS(mc_set_option_real(m, MC_OPTION_FRICTION_CT, -1e-8), MC_ERROR_ARGUMENT, "MC_OPTION_FRICTION_CT");
  FAILS(mc_set_option_real(m, MC_OPTION_FRICTION_CT, NAN), MC_ERROR_ARGUMENT, "MC_OPTION_FRICTION_CT");
  FAILS(mc_set_option_real(m, MC_OPTION_FRICTION_CT, INFINITY), MC_ERROR_ARGUMENT, "MC_OPTION_FRICTION_CT");
  FAILS(mc_set_option_int(m, 0, 0), MC_ERROR_ARGUMENT, "option = 0");
  FAILS(mc_set_option_int(m, 5, 0), MC_ERROR_ARGUMENT, "option = 5"); /* a gap in the values */
  FAILS(mc_set_option_real(m, -1, 0.5), MC_ERROR_ARGUMENT, "option = -1");
  /* infos: wrong type, unknown, NULL; the output is untouched on failure */
  FAILS(mc_get_info_int(m, MC_INFO_STRAIN_ENERGY, &iv), MC_ERROR_ARGUMENT, "real-valued");
  FAILS(mc_get_info_real(m, MC_INFO_DOFS, &rv), MC_ERROR_ARGUMENT, "integer-valued");
  FAILS(mc_get_info_int(m, MC_INFO_TIME_RESULTS, &iv), MC_ERROR_ARGUMENT, "real-valued"); /* the last real one */
  FAILS(mc_get_info_real(m, MC_INFO_SLIP_NODES, &rv), MC_ERROR_ARGUMENT, "integer-valued"); /* the last integer one */
  for (k = -1; k <= 34; ++k) {
    if ((k >= MC_INFO_DOFS && k <= MC_INFO_SLIP_NODES) || (k >= MC_INFO_TIME_ASSEMBLY && k <= MC_INFO_TIME_RESULTS))
      continue;
    FAILS(mc_get_info_int(m, k, &iv), MC_ERROR_ARGUMENT, "info");
    FAILS(mc_get_info_real(m, k, &rv), MC_ERROR_ARGUMENT, "info");
  }
  ck_assert_int_eq(iv, -7);
  ck_assert(rv == -7);
  /* options unchanged: the same answer */
  scene_usable(&s);
  scene_free(&s);
}
END_TEST

/* MC_OPTION_INTERFACE_SOLVER takes MC_INTERFACE_AUTO (0), _CONDENSED (1) or _SPARSE (2): any
   other value fails with a message naming the value and the option (a 64-bit value is not
   truncated to a valid one), the real call says the option is integer-valued, and
   MC_INFO_INTERFACE_SOLVER is an integer info. The failed calls change nothing. */
START_TEST(test_interface_solver_option) {
  scene s;
  mc_model *m;
  static const int64_t bad[6] = {-1, MC_INTERFACE_SPARSE + 1, INT64_MIN, INT64_MAX,
                                 ((int64_t)1 << 32) + MC_INTERFACE_SPARSE, -((int64_t)1 << 32)};
  char value[64];
  int k;
  int64_t iv = -7;
  double rv = -7;
  scene_make(&s, 0);
  m = s.m;
  for (k = 0; k < 6; ++k) {
    snprintf(value, sizeof value, "value = %lld", (long long)bad[k]);
    FAILS(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, bad[k]), MC_ERROR_ARGUMENT, value);
    ck_assert_msg(strstr(mc_errmsg(m), "MC_OPTION_INTERFACE_SOLVER") != NULL, "message \"%s\" names no option",
                  mc_errmsg(m));
  }
  FAILS(mc_set_option_real(m, MC_OPTION_INTERFACE_SOLVER, MC_INTERFACE_SPARSE), MC_ERROR_ARGUMENT, "integer-valued");
  FAILS(mc_set_option_real(m, MC_OPTION_INTERFACE_SOLVER, 3.0), MC_ERROR_ARGUMENT, "integer-valued");
  FAILS(mc_get_info_real(m, MC_INFO_INTERFACE_SOLVER, &rv), MC_ERROR_ARGUMENT, "integer-valued");
  ck_assert(rv == -7); /* untouched */
  SUCCEEDS(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &iv)); /* the contact solve of scene_make: one of the two */
  ck_assert_msg(iv == MC_INTERFACE_CONDENSED || iv == MC_INTERFACE_SPARSE, "MC_INFO_INTERFACE_SOLVER = %lld",
                (long long)iv);
  /* the option unchanged, the results kept: the same answer */
  scene_usable(&s);
  /* the default, set explicitly: a rebuild, the same answer */
  SUCCEEDS(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, MC_INTERFACE_AUTO));
  scene_resolves(&s);
  scene_free(&s);
}
END_TEST

/* ---- calls out of order --------------------------------------------------------------------- */

START_TEST(test_out_of_order) {
  scene s;
  mc_model *m;
  const int base = _i;
  double *buf = malloc(sizeof(double) * 1024);
  mc_int node = base, edge[2] = {base, base + 1}, n, *e;
  double p = 1;
  scene_make(&s, base);
  m = s.m;
  /* results of a scene that changed since the solve (loads, supports, options, contact) */
  SUCCEEDS(mc_set_body_force(m, 1, 0, -0.1));
  FAILS(mc_get_displacement(m, 1, buf), MC_ERROR_STATE, "mc_solve");
  FAILS(mc_get_contact_count(m, &n), MC_ERROR_STATE, "mc_solve");
  FAILS(mc_get_contact_pressure(m, buf), MC_ERROR_STATE, "mc_solve");
  FAILS(mc_write_vtu(m, "/dev/null"), MC_ERROR_STATE, NULL);
  SUCCEEDS(mc_set_body_force(m, 1, 0, 0));
  scene_resolves(&s);

  /* calls before their prerequisites, on a fresh model */
  {
    mc_model *m2 = NULL;
    double d[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    mc_int *cells;
    SUCCEEDS(mc_create(&m2));
    m = m2;
    if (base) SUCCEEDS(mc_set_index_base(m, 1));
    FAILS(mc_set_cell_elasticity(m, 1, d), MC_ERROR_STATE, "body 1 has no mesh");
    FAILS(mc_clear_loads(m, 2), MC_ERROR_STATE, "body 2 has no mesh");
    FAILS(mc_add_pressure(m, 1, 1, edge, &p), MC_ERROR_STATE, "mesh");
    FAILS(mc_set_gap_offset(m, 1, &node, &p), MC_ERROR_STATE, "mesh");
    FAILS(mc_get_contact_nodes(m, &n), MC_ERROR_STATE, NULL);
    FAILS(mc_write_vtu(m, "/dev/null"), MC_ERROR_STATE, NULL);
    SUCCEEDS(sc_set_mesh(m, 1, &s.top, base));
    /* a contact surface on body 1 only: no gap offsets before mc_set_contact */
    FAILS(mc_set_gap_offset(m, 1, &node, &p), MC_ERROR_STATE, "mc_set_contact");
    /* the index base changes how ids are read, not the stored mesh */
    SUCCEEDS(mc_set_index_base(m, 1 - base));
    cells = sc_ids(s.top.cells, 3 * s.top.n_cells, base);
    FAILS(mc_set_mesh(m, 1, s.top.n_nodes, s.top.xy, s.top.n_cells, 3, cells), MC_ERROR_ARGUMENT, 1 - base ? "cells(" : "cells[");
    free(cells);
    SUCCEEDS(mc_set_index_base(m, base));
    mc_destroy(m2);
    m = s.m;
  }

  /* contact surfaces that do not face each other, then the right ones */
  e = shifted(&s.bottom, SC_BOTTOM, base);
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_BOTTOM], e));
  FAILS(mc_solve(m), MC_ERROR_CONTACT, "face");
  /* a failed solve leaves no results */
  FAILS(mc_get_contact_count(m, &n), MC_ERROR_STATE, "mc_solve");
  FAILS(mc_get_displacement(m, 2, buf), MC_ERROR_STATE, "mc_solve");
  free(e);
  /* facing, but side by side: body 2's right side looks away from body 1's bottom */
  e = shifted(&s.bottom, SC_RIGHT, base);
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_RIGHT], e));
  FAILS(mc_solve(m), MC_ERROR_CONTACT, "face");
  free(e);
  e = shifted(&s.bottom, SC_TOP, base);
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_TOP], e));
  free(e);
  scene_resolves(&s);
  free(buf);
  scene_free(&s);
}
END_TEST

/* ---- mc_set_gap_offset --------------------------------------------------------------------------- */

START_TEST(test_gap_offset) {
  scene s;
  mc_model *m;
  const int base = _i;
  mc_int nodes[2], inner;
  double off[2] = {0, 0};
  char buf[64];
  scene_make(&s, base);
  m = s.m;
  nodes[0] = s.top.side_nodes[SC_BOTTOM][1] + base;
  nodes[1] = s.top.side_nodes[SC_TOP][1] + base; /* on body 1, not on its contact surface */
  inner = sc_node(&s.top, 2, 1) + base;
  snprintf(buf, sizeof buf, "%s = %d", AT("nodes", 1, base), (int)nodes[1]);
  FAILS(mc_set_gap_offset(m, 2, nodes, off), MC_ERROR_ARGUMENT, buf);
  FAILS(mc_set_gap_offset(m, 1, &inner, off), MC_ERROR_ARGUMENT, AT("nodes", 0, base));
  FAILS(mc_set_gap_offset(m, -1, nodes, off), MC_ERROR_ARGUMENT, "n = -1");
  FAILS(mc_set_gap_offset(m, 1, NULL, off), MC_ERROR_ARGUMENT, "nodes is NULL");
  FAILS(mc_set_gap_offset(m, 1, nodes, NULL), MC_ERROR_ARGUMENT, "offset is NULL");
  nodes[1] = s.top.n_nodes + base;
  FAILS(mc_set_gap_offset(m, 2, nodes, off), MC_ERROR_ARGUMENT, needle(buf, sizeof buf, "nodes", 1, s.top.n_nodes + base, base));
  scene_usable(&s);
  /* zero offsets on the right nodes: accepted, the same answer */
  nodes[1] = s.top.side_nodes[SC_BOTTOM][2] + base;
  SUCCEEDS(mc_set_gap_offset(m, 2, nodes, off));
  SUCCEEDS(mc_set_gap_offset(m, 0, NULL, NULL));
  scene_resolves(&s);
  scene_free(&s);
}
END_TEST

static Suite *input_suite(void) {
  Suite *s = suite_create("input");
  TCase *tc = tcase_create("null");
  tcase_add_test(tc, test_null_model);
  tcase_add_loop_test(tc, test_null_outputs, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("mesh");
  tcase_add_loop_test(tc, test_mesh_arguments, 0, 2);
  tcase_add_loop_test(tc, test_mesh_cells, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("ids");
  tcase_add_loop_test(tc, test_extreme_ids, 0, 2);
  tcase_add_loop_test(tc, test_edges, 0, 2);
  tcase_add_loop_test(tc, test_pinched_contact, 0, 2);
  tcase_add_test(tc, test_fully_supported_body);
  suite_add_tcase(s, tc);
  tc = tcase_create("values");
  tcase_add_loop_test(tc, test_non_finite, 0, 2);
  tcase_add_test(tc, test_material);
  tcase_add_test(tc, test_options_infos);
  tcase_add_test(tc, test_interface_solver_option);
  suite_add_tcase(s, tc);
  tc = tcase_create("state");
  tcase_add_loop_test(tc, test_out_of_order, 0, 2);
  tcase_add_loop_test(tc, test_gap_offset, 0, 2);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(input_suite()); }
