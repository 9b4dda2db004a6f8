/*
 * test_errors.c - every error status, produced by at least one call, with a non-empty
 * message naming the argument (and index), and the model still usable afterwards: each
 * failure is followed by a successful call whose mc_errmsg is "" and, where the scene was
 * complete, by a solve that gives exactly the answer from before the failed call.
 *
 * MC_ERROR_MESH is exercised in detail in test_mesh.c (clockwise, degenerate, duplicated
 * cells, unused node, edges not on the boundary); here once more for completeness.
 * MC_ERROR_MEMORY and MC_ERROR_INTERNAL cannot be triggered portably (no allocation hook; an
 * internal error is a library bug by definition): test_model.c checks mc_status_string for
 * every code instead.
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

/* ---- a complete scene whose answer must survive every failed call ---------------- */

typedef struct {
  mc_model *m;
  sc_mesh mesh;
  double *u0;
  size_t n;
} scene;

static void scene_make(scene *s, int base) {
  mc_model *m = NULL;
  mc_int node;
  double force[2] = {0.1, 0.2};
  ck_assert_int_eq(sc_mesh_rect(&s->mesh, 3, 6, 3, 0, 0, 2, 1, 0.2, 33u), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  s->m = m;
  if (base) OK(mc_set_index_base(m, 1));
  OK(sc_set_mesh(m, 1, &s->mesh, base));
  OK(mc_set_material(m, 1, 100.0, 0.3));
  OK(sc_fix_side(m, 1, &s->mesh, SC_LEFT, MC_XY, base));
  OK(sc_traction_side(m, 1, &s->mesh, SC_RIGHT, 0.2, -1.0, base));
  node = sc_node(&s->mesh, 3, 1) + base;
  OK(mc_add_nodal_force(m, 1, 1, &node, force));
  OK(mc_set_body_force(m, 1, 0.0, -0.5));
  OK(mc_solve(m));
  s->n = 2 * (size_t)s->mesh.n_nodes;
  s->u0 = malloc(sizeof(double) * s->n);
  OK(mc_get_displacement(m, 1, s->u0));
}

/* The failed calls changed nothing: the results are still there, and solving again gives
   OK, "" and the same answer as before. */
static void scene_usable(scene *s) {
  mc_model *m = s->m;
  double *u = malloc(sizeof(double) * s->n);
  size_t k;
  SUCCEEDS(mc_get_displacement(m, 1, u));
  for (k = 0; k < s->n; ++k) ck_assert_msg(u[k] == s->u0[k], "u[%zu] = %.17g, was %.17g", k, u[k], s->u0[k]);
  SUCCEEDS(mc_solve(m));
  SUCCEEDS(mc_get_displacement(m, 1, u));
  for (k = 0; k < s->n; ++k) ck_assert_msg(u[k] == s->u0[k], "u[%zu] = %.17g, was %.17g", k, u[k], s->u0[k]);
  free(u);
}

static void scene_free(scene *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->mesh);
  free(s->u0);
}

/* ---- MC_ERROR_ARGUMENT --------------------------------------------------------------- */

START_TEST(test_argument_create) {
  mc_model *m = NULL;
  ck_assert_int_eq(mc_create(NULL), MC_ERROR_ARGUMENT);
  ck_assert_ptr_nonnull(mc_errmsg(NULL));
  ck_assert(strlen(mc_errmsg(NULL)) > 0);
  mc_destroy(NULL);
  SUCCEEDS(mc_create(&m));
  ck_assert_str_eq(mc_errmsg(m), "");
  mc_destroy(m);
}
END_TEST

/* Body numbers other than 1 and 2, on every call that takes one. */
START_TEST(test_argument_body) {
  static const int bad[3] = {0, 3, -1};
  scene s;
  mc_model *m;
  int k;
  mc_int edge[2] = {0, 1}, node = 0;
  double v[64] = {0}, d[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double *big = malloc(sizeof(double) * 4096);
  scene_make(&s, 0);
  m = s.m;
  for (k = 0; k < 3; ++k) {
    int b = bad[k];
    FAILS(mc_set_mesh(m, b, s.mesh.n_nodes, s.mesh.xy, s.mesh.n_cells, 3, s.mesh.cells), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_set_material(m, b, 1, 0.3), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_set_cell_elasticity(m, b, d), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_fix(m, b, 1, &node, MC_XY, NULL), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_add_traction(m, b, 1, edge, v), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_add_pressure(m, b, 1, edge, v), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_add_nodal_force(m, b, 1, &node, v), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_set_body_force(m, b, 1, 1), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_clear_loads(m, b), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_set_contact(m, b, 1, edge), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_get_displacement(m, b, big), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_get_stress(m, b, big), MC_ERROR_ARGUMENT, "body");
    FAILS(mc_get_reaction(m, b, big), MC_ERROR_ARGUMENT, "body");
    scene_usable(&s);
  }
  free(big);
  scene_free(&s);
}
END_TEST

/* NULL pointers, node ids out of range, bad masks and counts, non-finite values. */
START_TEST(test_argument_values) {
  scene s;
  mc_model *m;
  mc_int n_nodes, nodes[3], edge[2];
  double values[6] = {0, 0, 0, 0, 0, 0}, t[2] = {1, 1};
  const int base = _i;
  scene_make(&s, base);
  m = s.m;
  n_nodes = s.mesh.n_nodes;
  nodes[0] = base, nodes[1] = 1 + base, nodes[2] = 2 + base;
  edge[0] = s.mesh.side_edges[SC_TOP][0] + base, edge[1] = s.mesh.side_edges[SC_TOP][1] + base;

  /* NULL pointers */
  FAILS(mc_fix(m, 1, 3, NULL, MC_XY, values), MC_ERROR_ARGUMENT, "nodes");
  FAILS(mc_add_nodal_force(m, 1, 3, nodes, NULL), MC_ERROR_ARGUMENT, "force");
  FAILS(mc_add_nodal_force(m, 1, 3, NULL, values), MC_ERROR_ARGUMENT, "nodes");
  FAILS(mc_add_traction(m, 1, 1, edge, NULL), MC_ERROR_ARGUMENT, "traction");
  FAILS(mc_add_traction(m, 1, 1, NULL, t), MC_ERROR_ARGUMENT, "edges");
  FAILS(mc_add_pressure(m, 1, 1, edge, NULL), MC_ERROR_ARGUMENT, "pressure");
  FAILS(mc_set_cell_elasticity(m, 1, NULL), MC_ERROR_ARGUMENT, "d");
  FAILS(mc_set_contact(m, 1, 1, NULL), MC_ERROR_ARGUMENT, "edges");
  FAILS(mc_get_displacement(m, 1, NULL), MC_ERROR_ARGUMENT, "u");
  FAILS(mc_get_stress(m, 1, NULL), MC_ERROR_ARGUMENT, "sigma");
  FAILS(mc_get_reaction(m, 1, NULL), MC_ERROR_ARGUMENT, "r");
  scene_usable(&s);

  /* node ids out of range: the message names the array index and the id */
  {
    char needle[64];
    mc_int bad[3];
    bad[0] = base, bad[1] = 1 + base, bad[2] = n_nodes + base;
    snprintf(needle, sizeof needle, "%s = %d", AT("nodes", 2, base), (int)(n_nodes + base));
    FAILS(mc_fix(m, 1, 3, bad, MC_XY, values), MC_ERROR_ARGUMENT, needle);
    FAILS(mc_add_nodal_force(m, 1, 3, bad, values), MC_ERROR_ARGUMENT, needle);
    bad[2] = base - 1;
    snprintf(needle, sizeof needle, "%s = %d", AT("nodes", 2, base), base - 1);
    FAILS(mc_fix(m, 1, 3, bad, MC_XY, values), MC_ERROR_ARGUMENT, needle);
    FAILS(mc_add_nodal_force(m, 1, 3, bad, values), MC_ERROR_ARGUMENT, needle);
    scene_usable(&s);
  }

  /* masks and counts */
  FAILS(mc_fix(m, 1, 3, nodes, 0, values), MC_ERROR_ARGUMENT, "components");
  FAILS(mc_fix(m, 1, 3, nodes, 4, values), MC_ERROR_ARGUMENT, "components");
  FAILS(mc_fix(m, 1, -1, nodes, MC_XY, values), MC_ERROR_ARGUMENT, "n");
  FAILS(mc_add_nodal_force(m, 1, -2, nodes, values), MC_ERROR_ARGUMENT, "n");
  FAILS(mc_add_traction(m, 1, -1, edge, t), MC_ERROR_ARGUMENT, "n_edges");
  FAILS(mc_add_pressure(m, 1, -1, edge, t), MC_ERROR_ARGUMENT, "n_edges");
  scene_usable(&s);

  /* non-finite values: the position in the index base, "values[3]" in base 0, "values(4)" in base 1 */
  values[3] = NAN;
  FAILS(mc_fix(m, 1, 3, nodes, MC_XY, values), MC_ERROR_ARGUMENT, AT("values", 3, base));
  FAILS(mc_add_nodal_force(m, 1, 3, nodes, values), MC_ERROR_ARGUMENT, AT("force", 3, base));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), base ? "force(4) is not finite" : "force[3] is not finite"));
  values[3] = 0;
  t[1] = INFINITY;
  FAILS(mc_add_traction(m, 1, 1, edge, t), MC_ERROR_ARGUMENT, AT("traction", 1, base));
  t[0] = NAN;
  FAILS(mc_add_pressure(m, 1, 1, edge, t), MC_ERROR_ARGUMENT, AT("pressure", 0, base));
  FAILS(mc_set_body_force(m, 1, NAN, 0), MC_ERROR_ARGUMENT, "fx");
  FAILS(mc_set_body_force(m, 1, 0, -INFINITY), MC_ERROR_ARGUMENT, "fy");
  scene_usable(&s);

  /* plane and thickness */
  FAILS(mc_set_plane(m, 3, 1), MC_ERROR_ARGUMENT, "plane");
  FAILS(mc_set_plane(m, -1, 1), MC_ERROR_ARGUMENT, "plane");
  FAILS(mc_set_plane(m, MC_PLANE_STRESS, 0), MC_ERROR_ARGUMENT, "thickness");
  FAILS(mc_set_plane(m, MC_PLANE_STRESS, -1), MC_ERROR_ARGUMENT, "thickness");
  FAILS(mc_set_plane(m, MC_PLANE_STRESS, NAN), MC_ERROR_ARGUMENT, "thickness");
  FAILS(mc_set_plane(m, MC_PLANE_STRESS, INFINITY), MC_ERROR_ARGUMENT, "thickness");
  scene_usable(&s);

  /* index base */
  FAILS(mc_set_index_base(m, 2), MC_ERROR_ARGUMENT, "base");
  FAILS(mc_set_index_base(m, -1), MC_ERROR_ARGUMENT, "base");
  scene_usable(&s);

  /* non-finite coordinates */
  {
    double *xy = malloc(sizeof(double) * s.n);
    mc_int *cells = sc_ids(s.mesh.cells, 3 * s.mesh.n_cells, base);
    char needle[32];
    memcpy(xy, s.mesh.xy, sizeof(double) * s.n);
    xy[9] = NAN;
    FAILS(mc_set_mesh(m, 1, n_nodes, xy, s.mesh.n_cells, 3, cells), MC_ERROR_ARGUMENT, AT("xy", 9, base));
    snprintf(needle, sizeof needle, "(node %d)", 4 + base); /* xy's 10th value: node 4's y, in base */
    ck_assert_ptr_nonnull(strstr(mc_errmsg(m), needle));
    xy[9] = s.mesh.xy[9];
    xy[s.n - 1] = INFINITY;
    snprintf(needle, sizeof needle, "%s", AT("xy", s.n - 1, base));
    FAILS(mc_set_mesh(m, 1, n_nodes, xy, s.mesh.n_cells, 3, cells), MC_ERROR_ARGUMENT, needle);
    scene_usable(&s);
    free(xy), free(cells);
  }

  /* options and infos */
  {
    int64_t iv;
    double rv;
    FAILS(mc_set_option_int(m, 12345, 1), MC_ERROR_ARGUMENT, "option");
    FAILS(mc_set_option_real(m, 12345, 0.1), MC_ERROR_ARGUMENT, "option");
    FAILS(mc_set_option_int(m, MC_OPTION_METHOD, 7), MC_ERROR_ARGUMENT, "value");
    FAILS(mc_get_info_int(m, 12345, &iv), MC_ERROR_ARGUMENT, "info");
    FAILS(mc_get_info_real(m, 12345, &rv), MC_ERROR_ARGUMENT, "info");
    scene_usable(&s);
  }
  scene_free(&s);
}
END_TEST

/* ---- MC_ERROR_MESH ------------------------------------------------------------------- */

START_TEST(test_mesh) {
  scene s;
  mc_model *m;
  static const double xy[10] = {0, 0, 1, 0, 1, 1, 0, 1, 3, 3};
  mc_int cw[6] = {0, 2, 1, 0, 2, 3}, degenerate[9] = {0, 1, 2, 0, 2, 3, 0, 2, 4}, dup[9] = {0, 1, 2, 0, 2, 3, 1, 2, 0};
  mc_int good[6] = {0, 1, 2, 0, 2, 3};
  double xy_deg[10] = {0, 0, 1, 0, 1, 1, 0, 1, 2, 2}; /* node 4 on the line 0-2 */
  scene_make(&s, 0);
  m = s.m;
  FAILS(mc_set_mesh(m, 1, 4, xy, 2, 3, cw), MC_ERROR_MESH, "cell 0");
  scene_usable(&s);
  FAILS(mc_set_mesh(m, 1, 5, xy_deg, 3, 3, degenerate), MC_ERROR_MESH, "cell 2");
  scene_usable(&s);
  FAILS(mc_set_mesh(m, 1, 4, xy, 3, 3, dup), MC_ERROR_MESH, "cell 2");
  scene_usable(&s);
  FAILS(mc_set_mesh(m, 1, 5, xy, 2, 3, good), MC_ERROR_MESH, "node 4");
  scene_usable(&s);
  {
    /* traction edge not on the boundary */
    mc_int interior[2] = {sc_node(&s.mesh, 2, 1), sc_node(&s.mesh, 3, 1)};
    double t[2] = {1, 0};
    FAILS(mc_add_traction(m, 1, 1, interior, t), MC_ERROR_MESH, "edges[0..1]");
    FAILS(mc_add_pressure(m, 1, 1, interior, t), MC_ERROR_MESH, "edges[0..1]");
    scene_usable(&s);
  }
  scene_free(&s);
}
END_TEST

/* ---- MC_ERROR_MATERIAL ----------------------------------------------------------------- */

START_TEST(test_material) {
  scene s;
  mc_model *m;
  double *d;
  mc_int c;
  const int base = _i;
  char needle[32];
  scene_make(&s, base);
  m = s.m;
  FAILS(mc_set_material(m, 1, 0, 0.3), MC_ERROR_MATERIAL, "young");
  FAILS(mc_set_material(m, 1, -5, 0.3), MC_ERROR_MATERIAL, "young");
  FAILS(mc_set_material(m, 1, NAN, 0.3), MC_ERROR_MATERIAL, "young");
  FAILS(mc_set_material(m, 1, INFINITY, 0.3), MC_ERROR_MATERIAL, "young");
  FAILS(mc_set_material(m, 1, 1, 0.5), MC_ERROR_MATERIAL, "poisson");
  FAILS(mc_set_material(m, 1, 1, 0.7), MC_ERROR_MATERIAL, "poisson");
  FAILS(mc_set_material(m, 1, 1, -1), MC_ERROR_MATERIAL, "poisson");
  FAILS(mc_set_material(m, 1, 1, NAN), MC_ERROR_MATERIAL, "poisson");
  scene_usable(&s);
  /* cell matrices: cell 4 not positive definite, then not symmetric */
  d = malloc(sizeof(double) * 9 * (size_t)s.mesh.n_cells);
  for (c = 0; c < s.mesh.n_cells; ++c) {
    double e[9] = {2, 0.5, 0, 0.5, 2, 0, 0, 0, 0.7};
    memcpy(d + 9 * c, e, sizeof e);
  }
  d[9 * 4 + 8] = -0.1;
  snprintf(needle, sizeof needle, "cell %d", 4 + base);
  FAILS(mc_set_cell_elasticity(m, 1, d), MC_ERROR_MATERIAL, needle);
  d[9 * 4 + 8] = 0.7;
  d[9 * 4 + 1] = 0.5, d[9 * 4 + 3] = 0.5, d[9 * 4 + 0] = 0.2, d[9 * 4 + 4] = 0.2; /* indefinite 2x2 block */
  FAILS(mc_set_cell_elasticity(m, 1, d), MC_ERROR_MATERIAL, needle);
  d[9 * 4 + 0] = 2, d[9 * 4 + 4] = 2, d[9 * 4 + 2] = 0.3; /* not symmetric */
  FAILS(mc_set_cell_elasticity(m, 1, d), MC_ERROR_MATERIAL, needle);
  d[9 * 4 + 2] = 0;
  d[9 * 7 + 5] = NAN;
  FAILS(mc_set_cell_elasticity(m, 1, d), MC_ERROR_ARGUMENT, AT("d", 68, base));
  scene_usable(&s);
  d[9 * 7 + 5] = 0;
  SUCCEEDS(mc_set_cell_elasticity(m, 1, d));
  free(d);
  scene_free(&s);
}
END_TEST

/* ---- MC_ERROR_STATE -------------------------------------------------------------------- */

START_TEST(test_state) {
  mc_model *m = NULL;
  sc_mesh mesh, mesh2;
  double *buf;
  mc_int node = 0, edge[2], n;
  double v[2] = {1, 1};
  int64_t iv;
  double rv;
  ck_assert_int_eq(sc_mesh_rect(&mesh, 4, 4, 2, 0, 0, 2, 1, 0, 1u), 0);
  ck_assert_int_eq(sc_mesh_rect(&mesh2, 4, 4, 2, 0, -1, 2, 1, 0, 1u), 0);
  buf = malloc(sizeof(double) * 4 * 64);
  edge[0] = mesh.side_edges[SC_BOTTOM][0], edge[1] = mesh.side_edges[SC_BOTTOM][1];
  SUCCEEDS(mc_create(&m));

  /* nothing yet */
  FAILS(mc_solve(m), MC_ERROR_STATE, "mesh");
  FAILS(mc_set_material(m, 1, 1, 0.3), MC_ERROR_STATE, "mesh");
  FAILS(mc_fix(m, 1, 1, &node, MC_XY, NULL), MC_ERROR_STATE, "mesh");
  FAILS(mc_add_nodal_force(m, 2, 1, &node, v), MC_ERROR_STATE, "mesh");
  FAILS(mc_add_traction(m, 1, 1, edge, v), MC_ERROR_STATE, "mesh");
  FAILS(mc_set_body_force(m, 1, 0, 1), MC_ERROR_STATE, "mesh");
  FAILS(mc_set_contact(m, 1, 1, edge), MC_ERROR_STATE, "mesh");
  FAILS(mc_get_displacement(m, 1, buf), MC_ERROR_STATE, NULL);
  SUCCEEDS(mc_set_plane(m, MC_PLANE_STRESS, 1));

  /* a mesh, no material */
  SUCCEEDS(sc_set_mesh(m, 1, &mesh, 0));
  SUCCEEDS(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  FAILS(mc_solve(m), MC_ERROR_STATE, "material");
  FAILS(mc_solve(m), MC_ERROR_STATE, "body 1");
  SUCCEEDS(mc_set_material(m, 1, 1, 0.3));

  /* results before a solve */
  FAILS(mc_get_displacement(m, 1, buf), MC_ERROR_STATE, "solve");
  FAILS(mc_get_stress(m, 1, buf), MC_ERROR_STATE, "solve");
  FAILS(mc_get_reaction(m, 1, buf), MC_ERROR_STATE, "solve");
  FAILS(mc_get_displacement(m, 2, buf), MC_ERROR_STATE, "body 2");
  SUCCEEDS(sc_traction_side(m, 1, &mesh, SC_RIGHT, 0, -1, 0));
  SUCCEEDS(mc_solve(m));
  SUCCEEDS(mc_get_displacement(m, 1, buf));
  SUCCEEDS(mc_get_info_int(m, MC_INFO_DOFS, &iv));
  SUCCEEDS(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &rv));
  /* body 2 has no mesh: no results for it */
  FAILS(mc_get_displacement(m, 2, buf), MC_ERROR_STATE, "body 2");
  /* contact results without contact surfaces */
  FAILS(mc_get_contact_count(m, &n), MC_ERROR_STATE, "contact");
  FAILS(mc_get_contact_nodes(m, &n), MC_ERROR_STATE, "contact");
  FAILS(mc_get_contact_pressure(m, buf), MC_ERROR_STATE, "contact");
  FAILS(mc_get_contact_force(m, buf), MC_ERROR_STATE, "contact");
  FAILS(mc_get_contact_gap(m, buf), MC_ERROR_STATE, "contact");
  FAILS(mc_get_contact_initial_gap(m, buf), MC_ERROR_STATE, "contact");
  FAILS(mc_get_contact_normal(m, buf), MC_ERROR_STATE, "contact");
  SUCCEEDS(mc_get_reaction(m, 1, buf));

  /* body 2 meshed but no material */
  SUCCEEDS(sc_set_mesh(m, 2, &mesh2, 0));
  SUCCEEDS(sc_fix_side(m, 2, &mesh2, SC_BOTTOM, MC_XY, 0));
  FAILS(mc_solve(m), MC_ERROR_STATE, "body 2");
  SUCCEEDS(mc_set_material(m, 2, 2, 0.2));
  SUCCEEDS(mc_solve(m));

  /* contact on one body only */
  SUCCEEDS(mc_set_contact(m, 1, mesh.n_side_edges[SC_BOTTOM], mesh.side_edges[SC_BOTTOM]));
  FAILS(mc_solve(m), MC_ERROR_STATE, "contact");
  FAILS(mc_solve(m), MC_ERROR_STATE, "body 2");
  SUCCEEDS(mc_set_body_force(m, 1, 0, -0.1));
  /* re-setting body 1's mesh clears its contact surface: a plain solve again */
  SUCCEEDS(sc_set_mesh(m, 1, &mesh, 0));
  SUCCEEDS(mc_set_material(m, 1, 1, 0.3));
  SUCCEEDS(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  SUCCEEDS(mc_solve(m));
  /* the same with body 2 */
  SUCCEEDS(mc_set_contact(m, 2, mesh2.n_side_edges[SC_TOP], mesh2.side_edges[SC_TOP]));
  FAILS(mc_solve(m), MC_ERROR_STATE, "body 1");
  SUCCEEDS(mc_get_info_int(m, MC_INFO_DOFS, &iv));

  free(buf);
  mc_destroy(m);
  sc_mesh_free(&mesh);
  sc_mesh_free(&mesh2);
}
END_TEST

/* ---- contact scenes ----------------------------------------------------------------------- */

/* Two stacked blocks: body 2 = [0,1] x [-0.5,0] (Q1 8x4) clamped at its bottom, body 1 =
   [0,1] x [0,0.5] (P1 6x3, non-matching) touching it, held only by contact and by u_x = 0 at
   its top middle node. Contact surfaces: body 1's bottom side, body 2's top side. */
typedef struct {
  mc_model *m;
  sc_mesh top, bottom;
} stack;

static void stack_make(stack *s) {
  mc_model *m = NULL;
  mc_int mid;
  ck_assert_int_eq(sc_mesh_rect(&s->top, 3, 6, 3, 0, 0, 1, 0.5, 0, 1u), 0);
  ck_assert_int_eq(sc_mesh_rect(&s->bottom, 4, 8, 4, 0, -0.5, 1, 0.5, 0, 1u), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  s->m = m;
  OK(sc_set_mesh(m, 1, &s->top, 0));
  OK(sc_set_mesh(m, 2, &s->bottom, 0));
  OK(mc_set_material(m, 1, 100.0, 0.3));
  OK(mc_set_material(m, 2, 200.0, 0.3));
  OK(sc_fix_side(m, 2, &s->bottom, SC_BOTTOM, MC_XY, 0));
  mid = sc_node(&s->top, 3, 3);
  OK(mc_fix(m, 1, 1, &mid, MC_X, NULL));
}

static void stack_free(stack *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->top);
  sc_mesh_free(&s->bottom);
}

/* A wavy load on body 1's top: t_y = -1 + 6 cos(2 pi x) per edge (net push -1 per unit
   length, pulling up near both ends). */
static void stack_wavy_load(stack *s) {
  mc_model *m = s->m;
  mc_int k, ne = s->top.n_side_edges[SC_TOP];
  double *t = malloc(sizeof(double) * 2 * (size_t)ne);
  for (k = 0; k < ne; ++k) {
    const mc_int *e = s->top.side_edges[SC_TOP] + 2 * k;
    double x = 0.5 * (s->top.xy[2 * e[0]] + s->top.xy[2 * e[1]]);
    t[2 * k] = 0, t[2 * k + 1] = -1 + 6 * cos(2 * M_PI * x);
  }
  OK(mc_add_traction(m, 1, ne, s->top.side_edges[SC_TOP], t));
  free(t);
}

/* ---- MC_ERROR_CONTACT ---------------------------------------------------------------------- */

START_TEST(test_contact) {
  stack s;
  mc_model *m;
  stack_make(&s);
  m = s.m;
  stack_wavy_load(&s);
  {
    /* an edge not on the boundary */
    mc_int interior[4] = {sc_node(&s.top, 0, 0), sc_node(&s.top, 1, 0), sc_node(&s.top, 1, 1), sc_node(&s.top, 2, 1)};
    FAILS(mc_set_contact(m, 1, 2, interior), MC_ERROR_CONTACT, "edges[2..3]");
    SUCCEEDS(mc_set_body_force(m, 1, 0, 0));
  }
  /* surfaces that do not face each other: body 1's top (looking up) against body 2's top */
  SUCCEEDS(mc_set_contact(m, 1, s.top.n_side_edges[SC_TOP], s.top.side_edges[SC_TOP]));
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_TOP], s.bottom.side_edges[SC_TOP]));
  FAILS(mc_solve(m), MC_ERROR_CONTACT, "do not face each other");
  /* the message says which surface is at fault (body 1's, whose normal points up, away from
     body 2) and what each normal does */
  printf("surfaces not facing (body 1's top): %s\n", mc_errmsg(m));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "Body 1's surface (oriented by its cells"));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "faces away from body 2"));
  ck_assert_ptr_null(strstr(mc_errmsg(m), "Body 2's surface"));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "body 2's (0, 1) points toward body 1"));
  /* and body 2's bottom, facing away from body 1 */
  SUCCEEDS(mc_set_contact(m, 1, s.top.n_side_edges[SC_BOTTOM], s.top.side_edges[SC_BOTTOM]));
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_BOTTOM], s.bottom.side_edges[SC_BOTTOM]));
  FAILS(mc_solve(m), MC_ERROR_CONTACT, "do not face each other");
  printf("surfaces not facing (body 2's bottom): %s\n", mc_errmsg(m));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "Body 2's surface (oriented by its cells"));
  ck_assert_ptr_nonnull(strstr(mc_errmsg(m), "faces away from body 1"));
  ck_assert_ptr_null(strstr(mc_errmsg(m), "Body 1's surface"));
  /* the right surfaces: solves */
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_TOP], s.bottom.side_edges[SC_TOP]));
  SUCCEEDS(mc_solve(m));
  stack_free(&s);
}
END_TEST

/* ---- MC_ERROR_NOT_CONVERGED ------------------------------------------------------------------ */

START_TEST(test_not_converged) {
  stack s;
  mc_model *m;
  int64_t iterations, active, rows;
  stack_make(&s);
  m = s.m;
  stack_wavy_load(&s);
  SUCCEEDS(mc_set_contact(m, 1, s.top.n_side_edges[SC_BOTTOM], s.top.side_edges[SC_BOTTOM]));
  SUCCEEDS(mc_set_contact(m, 2, s.bottom.n_side_edges[SC_TOP], s.bottom.side_edges[SC_TOP]));
  SUCCEEDS(mc_set_option_int(m, MC_OPTION_MAX_ITERATIONS, 1));
  FAILS(mc_solve(m), MC_ERROR_NOT_CONVERGED, "iterations");
  /* usable: with the default limit it converges, and needed more than one iteration */
  SUCCEEDS(mc_set_option_int(m, MC_OPTION_MAX_ITERATIONS, 200));
  SUCCEEDS(mc_solve(m));
  SUCCEEDS(mc_get_info_int(m, MC_INFO_ITERATIONS, &iterations));
  SUCCEEDS(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active));
  SUCCEEDS(mc_get_info_int(m, MC_INFO_CONTACT_NODES, &rows));
  ck_assert_int_ge(iterations, 2);
  ck_assert_int_gt(active, 0);
  ck_assert_int_lt(active, rows); /* the ends lift off */
  stack_free(&s);
}
END_TEST

/* ---- MC_ERROR_SINGULAR ------------------------------------------------------------------------- */

START_TEST(test_singular) {
  mc_model *m = NULL;
  sc_mesh mesh, mesh2;
  mc_int corner;
  ck_assert_int_eq(sc_mesh_rect(&mesh, 3 + _i, 6, 3, 0, 0, 2, 1, 0.1, 5u), 0);
  ck_assert_int_eq(sc_mesh_rect(&mesh2, 4, 3, 3, 5, 0, 1, 1, 0.1, 6u), 0);
  SUCCEEDS(mc_create(&m));
  SUCCEEDS(sc_set_mesh(m, 1, &mesh, 0));
  SUCCEEDS(mc_set_material(m, 1, 10, 0.3));
  SUCCEEDS(sc_traction_side(m, 1, &mesh, SC_RIGHT, 0.1, -0.1, 0));
  /* no supports and no contact */
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 1");
  SUCCEEDS(mc_set_body_force(m, 1, 0, 0));
  /* only u_x supports on the left side: free translation in y */
  SUCCEEDS(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_X, 0));
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "translation in y");
  /* one more support in y: held */
  corner = sc_node(&mesh, 0, 0);
  SUCCEEDS(mc_fix(m, 1, 1, &corner, MC_Y, NULL));
  SUCCEEDS(mc_solve(m));
  /* a single fully fixed node: rotation free */
  SUCCEEDS(sc_set_mesh(m, 1, &mesh, 0));
  SUCCEEDS(mc_set_material(m, 1, 10, 0.3));
  SUCCEEDS(mc_fix(m, 1, 1, &corner, MC_XY, NULL));
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "rotation");
  SUCCEEDS(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  SUCCEEDS(mc_solve(m));
  /* body 2 without supports while body 1 is held: the message names body 2 */
  SUCCEEDS(sc_set_mesh(m, 2, &mesh2, 0));
  SUCCEEDS(mc_set_material(m, 2, 10, 0.3));
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 2");
  SUCCEEDS(sc_fix_side(m, 2, &mesh2, SC_BOTTOM, MC_XY, 0));
  SUCCEEDS(mc_solve(m));
  /* re-setting a mesh clears its supports */
  SUCCEEDS(sc_set_mesh(m, 1, &mesh, 0));
  SUCCEEDS(mc_set_material(m, 1, 10, 0.3));
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 1");
  SUCCEEDS(sc_fix_side(m, 1, &mesh, SC_RIGHT, MC_XY, 0));
  SUCCEEDS(mc_solve(m));
  mc_destroy(m);
  sc_mesh_free(&mesh);
  sc_mesh_free(&mesh2);
}
END_TEST

static Suite *errors_suite(void) {
  Suite *s = suite_create("errors");
  TCase *tc = tcase_create("argument");
  tcase_add_test(tc, test_argument_create);
  tcase_add_test(tc, test_argument_body);
  tcase_add_loop_test(tc, test_argument_values, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("mesh");
  tcase_add_test(tc, test_mesh);
  suite_add_tcase(s, tc);
  tc = tcase_create("material");
  tcase_add_loop_test(tc, test_material, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("state");
  tcase_add_test(tc, test_state);
  suite_add_tcase(s, tc);
  tc = tcase_create("contact");
  tcase_add_test(tc, test_contact);
  tcase_add_test(tc, test_not_converged);
  suite_add_tcase(s, tc);
  tc = tcase_create("singular");
  tcase_add_loop_test(tc, test_singular, 0, 2);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(errors_suite()); }
