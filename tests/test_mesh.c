/*
 * test_mesh.c - mesh intake: valid meshes are accepted; bad ones (clockwise, degenerate,
 * non-convex, duplicated or overlapping cells, unused nodes, repeated nodes in a cell, bad ids,
 * non-finite coordinates) are rejected with MC_ERROR_MESH or MC_ERROR_ARGUMENT, a message
 * naming the cell/node/argument, and the model as it was (the previous mesh, material,
 * supports and loads still solve to the same answer). Also the edges given to tractions,
 * pressures and contact surfaces, and the structured meshes of scenes.c themselves.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mortarcontact.h"
#include "check_helpers.h"
#include "scenes.h"

/* ---- the structured meshes themselves ------------------------------------------ */

START_TEST(test_scenes_rect) {
  static const double distortions[3] = {0, 0.1, 0.25};
  int npc, d;
  for (npc = 3; npc <= 4; ++npc)
    for (d = 0; d < 3; ++d) {
      sc_mesh mesh;
      double area = 0;
      mc_int c, k;
      int s;
      ck_assert_int_eq(sc_mesh_rect(&mesh, npc, 7, 5, -1, 2, 3.5, 1.25, distortions[d], 17u), 0);
      ck_assert_int_eq(mesh.n_nodes, 8 * 6);
      ck_assert_int_eq(mesh.n_cells, npc == 4 ? 35 : 70);
      for (c = 0; c < mesh.n_cells; ++c) {
        ck_assert(sc_cell_area(&mesh, c) > 0);
        area += sc_cell_area(&mesh, c);
      }
      ck_assert_double_eq_tol(area, 3.5 * 1.25, 1e-12);
      ck_assert_int_eq(mesh.n_boundary_nodes, 2 * (7 + 5));
      for (s = 0; s < 4; ++s) {
        ck_assert_int_eq(mesh.n_side_edges[s], mesh.n_side_nodes[s] - 1);
        for (k = 0; k < mesh.n_side_nodes[s]; ++k) ck_assert(mesh.on_boundary[mesh.side_nodes[s][k]]);
      }
      /* sides are counter-clockwise: each side ends where the next begins */
      for (s = 0; s < 4; ++s)
        ck_assert_int_eq(mesh.side_nodes[s][mesh.n_side_nodes[s] - 1], mesh.side_nodes[(s + 1) % 4][0]);
      ck_assert_int_eq(mesh.side_nodes[SC_BOTTOM][0], sc_node(&mesh, 0, 0));
      /* the library accepts it */
      {
        mc_model *m = NULL;
        ck_assert_int_eq(mc_create(&m), MC_OK);
        OK(sc_set_mesh(m, 1, &mesh, 0));
        OK(sc_set_mesh(m, 2, &mesh, 0));
        mc_destroy(m);
      }
      sc_mesh_free(&mesh);
    }
}
END_TEST

/* ---- a baseline scene: every failed call must leave it as it was ----------------- */

typedef struct {
  mc_model *m;
  sc_mesh mesh;
  double *u0;
  size_t n;
} baseline;

static void baseline_make(baseline *b, int npc) {
  mc_model *m = NULL;
  ck_assert_int_eq(sc_mesh_rect(&b->mesh, npc, 6, 3, 0, 0, 2, 1, 0.2, 21u), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  b->m = m;
  OK(sc_set_mesh(m, 1, &b->mesh, 0));
  OK(mc_set_material(m, 1, 100.0, 0.3));
  OK(sc_fix_side(m, 1, &b->mesh, SC_LEFT, MC_XY, 0));
  OK(sc_traction_side(m, 1, &b->mesh, SC_RIGHT, 0.2, -1.0, 0));
  OK(mc_set_body_force(m, 1, 0.0, -0.5));
  OK(mc_solve(m));
  b->n = 2 * (size_t)b->mesh.n_nodes;
  b->u0 = malloc(sizeof(double) * b->n);
  OK(mc_get_displacement(m, 1, b->u0));
}

/* The failed calls changed nothing: the results are still there, and the model still
   solves, with an empty message, to the baseline answer. */
static void baseline_usable(baseline *b) {
  mc_model *m = b->m;
  double *u = malloc(sizeof(double) * b->n);
  size_t k;
  SUCCEEDS(mc_get_displacement(m, 1, u));
  for (k = 0; k < b->n; ++k) ck_assert_msg(u[k] == b->u0[k], "u[%zu] = %.17g, was %.17g", k, u[k], b->u0[k]);
  OK(mc_solve(m));
  ck_assert_str_eq(mc_errmsg(m), "");
  OK(mc_get_displacement(m, 1, u));
  for (k = 0; k < b->n; ++k) ck_assert_msg(u[k] == b->u0[k], "u[%zu] = %.17g, was %.17g", k, u[k], b->u0[k]);
  free(u);
}

static void baseline_free(baseline *b) {
  mc_destroy(b->m);
  sc_mesh_free(&b->mesh);
  free(b->u0);
}

/* Unit square 0(0,0) 1(1,0) 2(1,1) 3(0,1), 4(2,0), 5(2,1) */
static const double square_xy[12] = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};

/* Tries a bad mesh on body 1 of the baseline: expected status and message piece, then the
   baseline must still hold. */
static void try_mesh(baseline *b, mc_int n_nodes, const double *xy, mc_int n_cells, int npc, const mc_int *cells,
                     mc_status want, const char *needle) {
  mc_model *m = b->m;
  FAILS(mc_set_mesh(m, 1, n_nodes, xy, n_cells, npc, cells), want, needle);
  baseline_usable(b);
}

START_TEST(test_valid_small_meshes) {
  mc_model *m = NULL;
  mc_int tri[6] = {0, 1, 2, 0, 2, 3}, quad[4] = {0, 1, 2, 3}, two_quads[8] = {0, 1, 2, 3, 1, 4, 5, 2};
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_mesh(m, 1, 4, square_xy, 2, 3, tri));
  OK(mc_set_mesh(m, 1, 4, square_xy, 1, 4, quad));
  OK(mc_set_mesh(m, 2, 6, square_xy, 2, 4, two_quads));
  /* any starting corner, as long as counter-clockwise */
  {
    mc_int rotated[4] = {2, 3, 0, 1};
    OK(mc_set_mesh(m, 1, 4, square_xy, 1, 4, rotated));
  }
  mc_destroy(m);
}
END_TEST

START_TEST(test_mesh_errors) {
  baseline b;
  baseline_make(&b, 3 + _i);
  {
    /* clockwise */
    mc_int cw_tri[6] = {0, 2, 1, 0, 2, 3}, cw_quad[4] = {0, 3, 2, 1};
    try_mesh(&b, 4, square_xy, 2, 3, cw_tri, MC_ERROR_MESH, "cell 0");
    try_mesh(&b, 4, square_xy, 2, 3, cw_tri, MC_ERROR_MESH, "clockwise");
    try_mesh(&b, 4, square_xy, 1, 4, cw_quad, MC_ERROR_MESH, "cell 0");
  }
  {
    /* degenerate: three collinear nodes */
    mc_int cells[9] = {0, 1, 2, 0, 2, 3, 0, 1, 4};
    double xy[10] = {0, 0, 1, 0, 1, 1, 0, 1, 3, 0};
    try_mesh(&b, 5, xy, 3, 3, cells, MC_ERROR_MESH, "cell 2");
    try_mesh(&b, 5, xy, 3, 3, cells, MC_ERROR_MESH, "degenerate");
  }
  {
    /* degenerate quadrilateral: one corner on the line of its neighbours */
    double xy[8] = {0, 0, 1, 0, 2, 0, 0, 1};
    mc_int quad[4] = {0, 1, 2, 3};
    try_mesh(&b, 4, xy, 1, 4, quad, MC_ERROR_MESH, "cell 0");
  }
  {
    /* non-convex quadrilateral */
    double xy[8] = {0, 0, 2, 0, 0.5, 0.5, 0, 2};
    mc_int quad[4] = {0, 1, 2, 3};
    try_mesh(&b, 4, xy, 1, 4, quad, MC_ERROR_MESH, "convex");
  }
  {
    /* duplicated cells, also with another starting node */
    mc_int dup[9] = {0, 1, 2, 0, 2, 3, 0, 1, 2}, dup2[9] = {0, 1, 2, 0, 2, 3, 2, 3, 0};
    mc_int dupq[8] = {0, 1, 2, 3, 1, 2, 3, 0};
    try_mesh(&b, 4, square_xy, 3, 3, dup, MC_ERROR_MESH, "cell 2");
    try_mesh(&b, 4, square_xy, 3, 3, dup2, MC_ERROR_MESH, "cell 2");
    try_mesh(&b, 4, square_xy, 2, 4, dupq, MC_ERROR_MESH, "cell 1");
  }
  {
    /* a node used by no cell: node 4 */
    mc_int tri[6] = {0, 1, 2, 0, 2, 3};
    try_mesh(&b, 5, square_xy, 2, 3, tri, MC_ERROR_MESH, "node 4");
  }
  {
    /* a cell using a node twice */
    mc_int quad[4] = {0, 1, 1, 3};
    try_mesh(&b, 4, square_xy, 1, 4, quad, MC_ERROR_MESH, "cell 0");
  }
  {
    /* overlapping cells (both counter-clockwise, one edge used twice the same way) */
    mc_int tri[6] = {0, 1, 2, 0, 1, 3};
    try_mesh(&b, 4, square_xy, 2, 3, tri, MC_ERROR_MESH, NULL);
  }
  {
    /* an edge shared by three cells: 0-2 with 1 and 3 on either side, and 4' beyond */
    double xy[10] = {0, 0, 1, 0, 1, 1, 0, 1, 2, -1};
    mc_int tri[9] = {0, 1, 2, 0, 2, 3, 0, 4, 2};
    try_mesh(&b, 5, xy, 3, 3, tri, MC_ERROR_MESH, NULL);
  }
  {
    /* two faults: the edge 2-3 in a third cell (cell 3) and cells 0 and 4 overlapping along
       0-1 (an edge of lower nodes, met later in cell order); then the overlap first. The first
       wrong edge in cell order is the one reported. */
    double xy[12] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 2, 0.5, -1};
    mc_int triple_first[15] = {0, 1, 2, 0, 2, 3, 3, 2, 4, 2, 3, 5, 0, 1, 4};
    try_mesh(&b, 6, xy, 5, 3, triple_first, MC_ERROR_MESH, "edge 2-3 of cell 3 is shared by more than two cells");
    mc_int overlap_first[15] = {0, 1, 2, 0, 2, 3, 0, 1, 4, 3, 2, 4, 2, 3, 5};
    try_mesh(&b, 6, xy, 5, 3, overlap_first, MC_ERROR_MESH, "cells 0 and 2 overlap along edge 0-1");
  }
  {
    /* all nodes at one point */
    double xy[6] = {1, 1, 1, 1, 1, 1};
    mc_int tri[3] = {0, 1, 2};
    try_mesh(&b, 3, xy, 1, 3, tri, MC_ERROR_MESH, NULL);
  }
  baseline_free(&b);
}
END_TEST

START_TEST(test_mesh_argument_errors) {
  baseline b;
  mc_int tri[6] = {0, 1, 2, 0, 2, 3};
  baseline_make(&b, 3 + _i);
  try_mesh(&b, 4, NULL, 2, 3, tri, MC_ERROR_ARGUMENT, "xy");
  try_mesh(&b, 4, square_xy, 2, 3, NULL, MC_ERROR_ARGUMENT, "cells");
  try_mesh(&b, 4, square_xy, 2, 5, tri, MC_ERROR_ARGUMENT, "nodes_per_cell");
  try_mesh(&b, 4, square_xy, 2, 2, tri, MC_ERROR_ARGUMENT, "nodes_per_cell");
  try_mesh(&b, 2, square_xy, 2, 3, tri, MC_ERROR_ARGUMENT, "n_nodes");
  try_mesh(&b, -4, square_xy, 2, 3, tri, MC_ERROR_ARGUMENT, "n_nodes");
  try_mesh(&b, 4, square_xy, 0, 3, tri, MC_ERROR_ARGUMENT, "n_cells");
  try_mesh(&b, 4, square_xy, -1, 3, tri, MC_ERROR_ARGUMENT, "n_cells");
  {
    mc_int bad[6] = {0, 1, 2, 0, 2, 4};
    try_mesh(&b, 4, square_xy, 2, 3, bad, MC_ERROR_ARGUMENT, "cells[5]");
    bad[5] = -1;
    try_mesh(&b, 4, square_xy, 2, 3, bad, MC_ERROR_ARGUMENT, "cells[5]");
  }
  {
    double xy[8];
    memcpy(xy, square_xy, sizeof xy);
    xy[3] = NAN;
    try_mesh(&b, 4, xy, 2, 3, tri, MC_ERROR_ARGUMENT, "xy[3]");
    xy[3] = 0, xy[6] = INFINITY;
    try_mesh(&b, 4, xy, 2, 3, tri, MC_ERROR_ARGUMENT, "xy[6]");
    xy[6] = -INFINITY;
    try_mesh(&b, 4, xy, 2, 3, tri, MC_ERROR_ARGUMENT, "xy[6]");
  }
  {
    mc_model *m = b.m;
    FAILS(mc_set_mesh(m, 0, 4, square_xy, 2, 3, tri), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_set_mesh(m, 3, 4, square_xy, 2, 3, tri), MC_ERROR_ARGUMENT, "body");
    baseline_usable(&b);
  }
  baseline_free(&b);
}
END_TEST

/* A mesh error on body 2 leaves body 1 alone; a good mesh on body 2 then solves. */
START_TEST(test_mesh_error_other_body) {
  baseline b;
  mc_model *m;
  mc_int cw[6] = {0, 2, 1, 0, 2, 3};
  baseline_make(&b, 4);
  m = b.m;
  FAILS(mc_set_mesh(m, 2, 4, square_xy, 2, 3, cw), MC_ERROR_MESH, "cell 0");
  baseline_usable(&b);
  baseline_free(&b);
}
END_TEST

/* ---- edges of loads and contact surfaces ------------------------------------------ */

START_TEST(test_load_edges) {
  baseline b;
  mc_model *m;
  const sc_mesh *mesh;
  double t[4] = {1, 0, 1, 0}, p[2] = {1, 1};
  baseline_make(&b, 3 + _i);
  m = b.m;
  mesh = &b.mesh;
  {
    /* an interior edge: (1,1)-(2,1) */
    mc_int interior[4] = {sc_node(mesh, 1, 1), sc_node(mesh, 2, 1), sc_node(mesh, 6, 0), sc_node(mesh, 5, 0)};
    FAILS(mc_add_traction(m, 1, 2, interior, t), MC_ERROR_MESH, "edges[0..1]");
    FAILS(mc_add_pressure(m, 1, 2, interior, p), MC_ERROR_MESH, "edges[0..1]");
    baseline_usable(&b);
  }
  {
    /* two boundary nodes that are not an edge: the bottom corners; a valid edge first, so
       the failure must not add that one either */
    mc_int not_edge[4] = {sc_node(mesh, 6, 0), sc_node(mesh, 5, 0), sc_node(mesh, 0, 0), sc_node(mesh, 6, 0)};
    FAILS(mc_add_traction(m, 1, 2, not_edge, t), MC_ERROR_MESH, "edges[2..3]");
    FAILS(mc_add_pressure(m, 1, 2, not_edge, p), MC_ERROR_MESH, "edges[2..3]");
    baseline_usable(&b);
  }
  {
    mc_int out[2] = {0, b.mesh.n_nodes};
    FAILS(mc_add_traction(m, 1, 1, out, t), MC_ERROR_ARGUMENT, "edges[1]");
    FAILS(mc_add_pressure(m, 1, 1, out, p), MC_ERROR_ARGUMENT, "edges[1]");
    baseline_usable(&b);
  }
  baseline_free(&b);
}
END_TEST

/* A load edge may be given in either direction. */
START_TEST(test_edge_direction) {
  sc_mesh mesh;
  mc_model *m = NULL;
  mc_int k, ne, *rev;
  double *u1, *u2, *t;
  size_t n;
  ck_assert_int_eq(sc_mesh_rect(&mesh, 3 + _i, 6, 3, 0, 0, 2, 1, 0.2, 4u), 0);
  ne = mesh.n_side_edges[SC_TOP];
  n = 2 * (size_t)mesh.n_nodes;
  rev = malloc(sizeof(mc_int) * 2 * (size_t)ne);
  t = malloc(sizeof(double) * 2 * (size_t)ne);
  u1 = malloc(sizeof(double) * n), u2 = malloc(sizeof(double) * n);
  for (k = 0; k < ne; ++k) {
    rev[2 * k] = mesh.side_edges[SC_TOP][2 * k + 1], rev[2 * k + 1] = mesh.side_edges[SC_TOP][2 * k];
    t[2 * k] = 0.1 * k, t[2 * k + 1] = -1;
  }
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 10.0, 0.25));
  OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  OK(mc_add_traction(m, 1, ne, mesh.side_edges[SC_TOP], t));
  OK(mc_add_pressure(m, 1, ne, mesh.side_edges[SC_TOP], t)); /* t[2k] as a pressure: 0, 0.1, ... */
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u1));
  OK(mc_clear_loads(m, 1));
  OK(mc_add_traction(m, 1, ne, rev, t));
  OK(mc_add_pressure(m, 1, ne, rev, t));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u2));
  for (k = 0; k < (mc_int)n; ++k) ck_assert_double_eq_tol(u1[k], u2[k], 1e-14);
  free(rev), free(t), free(u1), free(u2);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

START_TEST(test_contact_edges) {
  baseline b;
  mc_model *m;
  const sc_mesh *mesh;
  baseline_make(&b, 3 + _i);
  m = b.m;
  mesh = &b.mesh;
  {
    mc_int interior[4] = {sc_node(mesh, 6, 0), sc_node(mesh, 5, 0), sc_node(mesh, 1, 1), sc_node(mesh, 2, 1)};
    FAILS(mc_set_contact(m, 1, 2, interior), MC_ERROR_CONTACT, "edges[2..3]");
    baseline_usable(&b); /* no contact surface was kept: still a plain elasticity solve */
  }
  {
    mc_int twice[4] = {sc_node(mesh, 5, 0), sc_node(mesh, 6, 0), sc_node(mesh, 6, 0), sc_node(mesh, 5, 0)};
    FAILS(mc_set_contact(m, 1, 2, twice), MC_ERROR_CONTACT, "twice");
    baseline_usable(&b);
  }
  {
    mc_int out[2] = {0, -1};
    FAILS(mc_set_contact(m, 1, 1, out), MC_ERROR_ARGUMENT, "edges[0..1]");
    FAILS(mc_set_contact(m, 1, 0, out), MC_ERROR_ARGUMENT, "n_edges");
    FAILS(mc_set_contact(m, 1, 1, NULL), MC_ERROR_ARGUMENT, "edges");
    baseline_usable(&b);
  }
  baseline_free(&b);
}
END_TEST

static Suite *mesh_suite(void) {
  Suite *s = suite_create("mesh");
  TCase *tc = tcase_create("valid");
  tcase_add_test(tc, test_scenes_rect);
  tcase_add_test(tc, test_valid_small_meshes);
  suite_add_tcase(s, tc);
  tc = tcase_create("invalid");
  tcase_add_loop_test(tc, test_mesh_errors, 0, 2);
  tcase_add_loop_test(tc, test_mesh_argument_errors, 0, 2);
  tcase_add_test(tc, test_mesh_error_other_body);
  suite_add_tcase(s, tc);
  tc = tcase_create("edges");
  tcase_add_loop_test(tc, test_load_edges, 0, 2);
  tcase_add_loop_test(tc, test_edge_direction, 0, 2);
  tcase_add_loop_test(tc, test_contact_edges, 0, 2);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(mesh_suite()); }
