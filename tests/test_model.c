/*
 * test_model.c - the model object: lifecycle, version, status strings, options, infos,
 * index base, re-solves that reuse the factorization, re-setting a mesh, and the
 * independence of two models.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mortarcontact.h"
#include "check_helpers.h"
#include "scenes.h"

/* ---- lifecycle, version, status strings ------------------------------------ */

START_TEST(test_version) {
  char expected[32];
  ck_assert_int_eq(mc_version_number(), MC_VERSION_NUMBER);
  ck_assert_str_eq(mc_version_string(), MC_VERSION_STRING);
  snprintf(expected, sizeof expected, "%d.%d.%d", MC_VERSION_MAJOR, MC_VERSION_MINOR, MC_VERSION_PATCH);
  ck_assert_str_eq(mc_version_string(), expected);
  ck_assert_int_eq(MC_VERSION_NUMBER, MC_VERSION_MAJOR * 10000 + MC_VERSION_MINOR * 100 + MC_VERSION_PATCH);
}
END_TEST

START_TEST(test_create_destroy) {
  mc_model *m = NULL, *other = NULL;
  ck_assert_int_eq(mc_create(NULL), MC_ERROR_ARGUMENT);
  mc_destroy(NULL); /* fine */
  ck_assert_ptr_nonnull(mc_errmsg(NULL));
  ck_assert_int_eq(mc_create(&m), MC_OK);
  ck_assert_ptr_nonnull(m);
  ck_assert_str_eq(mc_errmsg(m), "");
  ck_assert_int_eq(mc_create(&other), MC_OK);
  ck_assert_ptr_ne(m, other);
  mc_destroy(m);
  mc_destroy(other);
}
END_TEST

/* MC_ERROR_MEMORY and MC_ERROR_INTERNAL cannot be triggered portably (no allocation hook,
   and an internal error is a bug by definition): their names are tested here instead, as
   are those of every other code. */
START_TEST(test_status_strings) {
  static const char *names[] = {"MC_OK",
                                "MC_ERROR_ARGUMENT",
                                "MC_ERROR_MESH",
                                "MC_ERROR_MATERIAL",
                                "MC_ERROR_STATE",
                                "MC_ERROR_CONTACT",
                                "MC_ERROR_SINGULAR",
                                "MC_ERROR_NOT_CONVERGED",
                                "MC_ERROR_MEMORY",
                                "MC_ERROR_INTERNAL"};
  int s;
  ck_assert_int_eq(MC_OK, 0);
  ck_assert_int_eq(MC_ERROR_ARGUMENT, 1);
  ck_assert_int_eq(MC_ERROR_MESH, 2);
  ck_assert_int_eq(MC_ERROR_MATERIAL, 3);
  ck_assert_int_eq(MC_ERROR_STATE, 4);
  ck_assert_int_eq(MC_ERROR_CONTACT, 5);
  ck_assert_int_eq(MC_ERROR_SINGULAR, 6);
  ck_assert_int_eq(MC_ERROR_NOT_CONVERGED, 7);
  ck_assert_int_eq(MC_ERROR_MEMORY, 8);
  ck_assert_int_eq(MC_ERROR_INTERNAL, 9);
  for (s = 0; s <= 9; ++s) ck_assert_str_eq(mc_status_string((mc_status)s), names[s]);
  ck_assert_str_eq(mc_status_string(MC_ERROR_MEMORY), "MC_ERROR_MEMORY");
  ck_assert_str_eq(mc_status_string(MC_ERROR_INTERNAL), "MC_ERROR_INTERNAL");
  ck_assert_str_eq(mc_status_string((mc_status)10), "unknown status");
  ck_assert_str_eq(mc_status_string((mc_status)-1), "unknown status");
  ck_assert_str_eq(mc_status_string((mc_status)1000), "unknown status");
}
END_TEST

/* Every entry point taking a model rejects NULL with MC_ERROR_ARGUMENT. */

/* ---- a small solved scene ----------------------------------------------------- */

/* Cantilever [0,2] x [0,1], P1 or Q1, nx x ny, clamped left, traction on the right. */
static mc_model *cantilever(sc_mesh *mesh, int npc, int nx, int ny) {
  mc_model *m = NULL;
  ck_assert_int_eq(sc_mesh_rect(mesh, npc, nx, ny, 0, 0, 2, 1, 0.15, 3u), 0);
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, mesh, 0));
  OK(mc_set_material(m, 1, 100.0, 0.3));
  OK(sc_fix_side(m, 1, mesh, SC_LEFT, MC_XY, 0));
  OK(sc_traction_side(m, 1, mesh, SC_RIGHT, 0.2, -1.0, 0));
  return m;
}

static double max_diff(const double *a, const double *b, size_t n, double factor) {
  double d = 0;
  size_t i;
  for (i = 0; i < n; ++i)
    if (fabs(a[i] - factor * b[i]) > d) d = fabs(a[i] - factor * b[i]);
  return d;
}

static double max_abs(const double *v, size_t n) {
  double s = 0;
  size_t i;
  for (i = 0; i < n; ++i)
    if (fabs(v[i]) > s) s = fabs(v[i]);
  return s;
}

/* ---- options ------------------------------------------------------------------ */

START_TEST(test_options) {
  sc_mesh mesh;
  mc_model *m = cantilever(&mesh, 4, 6, 3);
  double *u0 = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes), *u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes);
  size_t n = 2 * (size_t)mesh.n_nodes;
  int k;
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u0));
  /* every valid value is accepted, and the elasticity answer does not depend on the
     contact options nor on the ordering */
  {
    static const int methods[3] = {MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR, MC_METHOD_NODE_TO_SEGMENT};
    static const int orderings[3] = {MC_ORDERING_AUTO, MC_ORDERING_AMD, MC_ORDERING_METIS};
    static const int interface_solvers[3] = {MC_INTERFACE_SPARSE, MC_INTERFACE_CONDENSED, MC_INTERFACE_AUTO};
    for (k = 0; k < 3; ++k) {
      int64_t ran = -1;
      OK(mc_set_option_int(m, MC_OPTION_METHOD, methods[k]));
      OK(mc_set_option_int(m, MC_OPTION_ORDERING, orderings[k]));
      OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, interface_solvers[k]));
      OK(mc_set_option_int(m, MC_OPTION_MAX_ITERATIONS, k == 0 ? 1 : 1000000));
      OK(mc_set_option_real(m, MC_OPTION_TOLERANCE, k == 0 ? 1e-14 : 0.5));
      ck_assert_str_eq(mc_errmsg(m), "");
      OK(mc_solve(m));
      OK(mc_get_displacement(m, 1, u));
      ck_assert(max_diff(u, u0, n, 1) <= 1e-12 * max_abs(u0, n));
      OK(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &ran));
      ck_assert_int_eq(ran, 0); /* no contact: neither interface solver ran */
    }
  }
  OK(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, MC_Q1_BBAR));
  OK(mc_solve(m));
  OK(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, MC_Q1_FULL));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u));
  ck_assert(max_diff(u, u0, n, 1) <= 1e-12 * max_abs(u0, n));

  /* bad options and values: MC_ERROR_ARGUMENT, message names the option or value */
  FAILS(mc_set_option_int(m, 0, 1), MC_ERROR_ARGUMENT, "option");
  FAILS(mc_set_option_int(m, 5, 1), MC_ERROR_ARGUMENT, "option");
  FAILS(mc_set_option_int(m, 99, 1), MC_ERROR_ARGUMENT, "option");
  FAILS(mc_set_option_int(m, MC_OPTION_TOLERANCE, 1), MC_ERROR_ARGUMENT, "option");
  FAILS(mc_set_option_int(m, MC_OPTION_METHOD, 3), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_int(m, MC_OPTION_METHOD, -1), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_int(m, MC_OPTION_MAX_ITERATIONS, 0), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_int(m, MC_OPTION_ORDERING, 3), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, 2), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, 3), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, 0), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, 1), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, -1e-8), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_TOLERANCE, NAN), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_set_option_real(m, MC_OPTION_METHOD, 1), MC_ERROR_ARGUMENT, "option");
  FAILS(mc_set_option_real(m, 42, 1e-3), MC_ERROR_ARGUMENT, "option");
  /* still usable */
  OK(mc_set_option_real(m, MC_OPTION_TOLERANCE, 1e-10));
  ck_assert_str_eq(mc_errmsg(m), "");
  OK(mc_solve(m));
  ck_assert_str_eq(mc_errmsg(m), "");
  free(u0), free(u);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- infos ---------------------------------------------------------------------- */

START_TEST(test_infos) {
  sc_mesh mesh;
  mc_model *m = cantilever(&mesh, 3 + _i, 8, 4);
  int64_t v;
  double r, total, part, sum = 0;
  static const int times[5] = {MC_INFO_TIME_ASSEMBLY, MC_INFO_TIME_ANALYSIS, MC_INFO_TIME_FACTORIZATION,
                               MC_INFO_TIME_SOLVE, MC_INFO_TIME_CONTACT};
  int k;
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_DOFS, &v));
  ck_assert_int_eq(v, 2 * mesh.n_nodes - 2 * mesh.n_side_nodes[SC_LEFT]);
  OK(mc_get_info_int(m, MC_INFO_FACTOR_NNZ, &v));
  ck_assert_int_ge(v, 2 * mesh.n_nodes - 2 * mesh.n_side_nodes[SC_LEFT]);
  OK(mc_get_info_int(m, MC_INFO_ITERATIONS, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_info_int(m, MC_INFO_CONTACT_NODES, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 1);
  OK(mc_get_info_real(m, MC_INFO_TIME_TOTAL, &total));
  ck_assert(total >= 0 && isfinite(total));
  for (k = 0; k < 5; ++k) {
    OK(mc_get_info_real(m, times[k], &part));
    ck_assert(part >= 0 && isfinite(part));
    sum += part;
  }
  ck_assert_msg(sum <= total * (1 + 1e-9) + 1e-6, "timed parts %g exceed the total %g", sum, total);
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &r));
  ck_assert(r > 0);
  OK(mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &r));
  ck_assert(r == 0);
  OK(mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &r));
  ck_assert(r >= 0 && r <= 1e-10);
  OK(mc_get_info_real(m, MC_INFO_GAP_RESIDUAL, &r));
  ck_assert(r == 0); /* no contact */
  OK(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &v));
  ck_assert_int_eq(v, 0); /* no contact: no interface solver ran */
  OK(mc_get_info_int(m, MC_INFO_STICK_NODES, &v));
  ck_assert_int_eq(v, 0); /* no friction */
  OK(mc_get_info_int(m, MC_INFO_SLIP_NODES, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_info_real(m, MC_INFO_FRICTION_COMPLEMENTARITY, &r));
  ck_assert(r == 0);

  /* wrong kinds and unknown infos */
  FAILS(mc_get_info_int(m, MC_INFO_STRAIN_ENERGY, &v), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_int(m, 0, &v), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_int(m, 10, &v), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_real(m, MC_INFO_INTERFACE_SOLVER, &r), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_int(m, 19, &v), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_real(m, MC_INFO_DOFS, &r), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_real(m, 33, &r), MC_ERROR_ARGUMENT, "info"); /* past MC_INFO_TIME_RESULTS = 32 */
  FAILS(mc_get_info_int(m, MC_INFO_ERROR_ESTIMATE, &v), MC_ERROR_ARGUMENT, "real-valued");
  FAILS(mc_get_info_int(m, MC_INFO_TIME_RESULTS, &v), MC_ERROR_ARGUMENT, "real-valued");
  FAILS(mc_get_info_real(m, -1, &r), MC_ERROR_ARGUMENT, "info");
  FAILS(mc_get_info_int(m, MC_INFO_DOFS, NULL), MC_ERROR_ARGUMENT, "value");
  FAILS(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, NULL), MC_ERROR_ARGUMENT, "value");
  /* results are still there */
  OK(mc_get_info_int(m, MC_INFO_DOFS, &v));
  ck_assert_str_eq(mc_errmsg(m), "");
  ck_assert_int_eq(v, 2 * mesh.n_nodes - 2 * mesh.n_side_nodes[SC_LEFT]);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- re-solves ------------------------------------------------------------------- */

/* Changing only loads, prescribed values or nothing reuses the factorization
   (MC_INFO_FACTORIZATIONS == 0) and gives the linearly scaled answer. */
START_TEST(test_resolve_reuses_factorization) {
  sc_mesh mesh;
  mc_model *m = cantilever(&mesh, 3 + _i, 10, 4);
  size_t n = 2 * (size_t)mesh.n_nodes;
  double *u0 = malloc(sizeof(double) * n), *u1 = malloc(sizeof(double) * n), *u2 = malloc(sizeof(double) * n);
  double e0, e, scale;
  int64_t v;
  mc_int node = sc_node(&mesh, 5, 2), k;
  double force[2] = {0.7, 0.4};
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 1);
  OK(mc_get_displacement(m, 1, u0));
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &e0));
  scale = max_abs(u0, n);

  /* nothing changed */
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_displacement(m, 1, u1));
  ck_assert(max_diff(u1, u0, n, 1) <= 1e-13 * scale);

  /* loads scaled by -3 */
  OK(mc_clear_loads(m, 1));
  OK(sc_traction_side(m, 1, &mesh, SC_RIGHT, -0.6, 3.0, 0));
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_displacement(m, 1, u1));
  ck_assert(max_diff(u1, u0, n, -3) <= 1e-12 * scale);
  OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &e));
  ck_assert_double_eq_tol(e, 9 * e0, 1e-12 * 9 * e0);

  /* superposition: + a nodal force and a body force, each alone */
  OK(mc_clear_loads(m, 1));
  OK(mc_add_nodal_force(m, 1, 1, &node, force));
  OK(mc_set_body_force(m, 1, 0.3, -0.1));
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_displacement(m, 1, u2));
  /* a rejected load adds nothing */
  FAILS(mc_add_traction(m, 1, mesh.n_side_edges[SC_RIGHT], mesh.side_edges[SC_RIGHT], NULL), MC_ERROR_ARGUMENT,
        "traction");
  OK(sc_traction_side(m, 1, &mesh, SC_RIGHT, 0.2, -1.0, 0));
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 0);
  OK(mc_get_displacement(m, 1, u1));
  for (k = 0; k < (mc_int)n; ++k) ck_assert_double_eq_tol(u1[k], u0[k] + u2[k], 1e-12 * scale);

  /* prescribed values only: the left side moves by (0, d) rigidly, on top of the loads */
  {
    mc_int ns = mesh.n_side_nodes[SC_LEFT];
    double *values = malloc(sizeof(double) * 2 * (size_t)ns), d = -0.01;
    for (k = 0; k < ns; ++k) values[2 * k] = 0, values[2 * k + 1] = d;
    OK(mc_fix(m, 1, ns, mesh.side_nodes[SC_LEFT], MC_XY, values));
    OK(mc_solve(m));
    OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
    ck_assert_int_eq(v, 0);
    OK(mc_get_displacement(m, 1, u2));
    for (k = 0; k < mesh.n_nodes; ++k) {
      ck_assert_double_eq_tol(u2[2 * k], u1[2 * k], 1e-12 * scale);
      ck_assert_double_eq_tol(u2[2 * k + 1], u1[2 * k + 1] + d, 1e-12 * scale);
    }
    free(values);
  }

  /* a new material changes K: a factorization */
  OK(mc_set_material(m, 1, 200.0, 0.3));
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 1);
  /* a new support too */
  OK(mc_fix(m, 1, 1, &node, MC_X, NULL));
  OK(mc_solve(m));
  OK(mc_get_info_int(m, MC_INFO_FACTORIZATIONS, &v));
  ck_assert_int_eq(v, 1);
  free(u0), free(u1), free(u2);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* Setting a mesh again clears the body's material, supports and loads. */
START_TEST(test_reset_mesh_clears) {
  sc_mesh mesh;
  mc_model *m = cantilever(&mesh, 3, 6, 3);
  OK(mc_solve(m));
  OK(sc_set_mesh(m, 1, &mesh, 0));
  FAILS(mc_solve(m), MC_ERROR_STATE, "material");
  OK(mc_set_material(m, 1, 100.0, 0.3));
  ck_assert_str_eq(mc_errmsg(m), "");
  FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 1");
  OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  OK(mc_solve(m));
  ck_assert_str_eq(mc_errmsg(m), "");
  {
    /* and the loads are gone: zero displacement */
    double *u = malloc(sizeof(double) * 2 * (size_t)mesh.n_nodes), e;
    OK(mc_get_displacement(m, 1, u));
    ck_assert_double_eq(max_abs(u, 2 * (size_t)mesh.n_nodes), 0);
    OK(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, &e));
    ck_assert_double_eq(e, 0);
    free(u);
  }
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- index base ------------------------------------------------------------------ */

/* The same scene in base 0 and base 1 gives the same answer; ids out are in the base. */
START_TEST(test_index_base) {
  sc_mesh mesh;
  mc_model *m0 = NULL, *m = NULL;
  size_t n;
  double *u0, *u1, *r0, *r1;
  mc_int corner0 = 0, corner1 = 1, k, bad[1];
  double force[2] = {0.5, 0.5};
  ck_assert_int_eq(sc_mesh_rect(&mesh, 4, 5, 3, 0, 0, 2, 1, 0.2, 11u), 0);
  n = 2 * (size_t)mesh.n_nodes;
  u0 = malloc(sizeof(double) * n), u1 = malloc(sizeof(double) * n);
  r0 = malloc(sizeof(double) * n), r1 = malloc(sizeof(double) * n);
  {
    m = NULL;
    ck_assert_int_eq(mc_create(&m), MC_OK);
    m0 = m;
    OK(sc_set_mesh(m, 1, &mesh, 0));
    OK(mc_set_material(m, 1, 10.0, 0.2));
    OK(sc_fix_side(m, 1, &mesh, SC_BOTTOM, MC_XY, 0));
    OK(sc_traction_side(m, 1, &mesh, SC_TOP, 0.3, -0.2, 0));
    OK(mc_add_nodal_force(m, 1, 1, &corner0, force));
    OK(mc_solve(m));
    OK(mc_get_displacement(m, 1, u0));
    OK(mc_get_reaction(m, 1, r0));
  }
  m = NULL;
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(mc_set_index_base(m, 1));
  OK(sc_set_mesh(m, 1, &mesh, 1));
  OK(mc_set_material(m, 1, 10.0, 0.2));
  OK(sc_fix_side(m, 1, &mesh, SC_BOTTOM, MC_XY, 1));
  OK(sc_traction_side(m, 1, &mesh, SC_TOP, 0.3, -0.2, 1));
  /* id 0 is out of range in base 1, n_nodes is in range */
  bad[0] = 0;
  FAILS(mc_add_nodal_force(m, 1, 1, bad, force), MC_ERROR_ARGUMENT, "nodes(1) = 0"); /* the position in base 1 too */
  bad[0] = mesh.n_nodes + 1;
  FAILS(mc_add_nodal_force(m, 1, 1, bad, force), MC_ERROR_ARGUMENT, "nodes(1)");
  OK(mc_add_nodal_force(m, 1, 1, &corner1, force));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u1));
  OK(mc_get_reaction(m, 1, r1));
  for (k = 0; k < (mc_int)n; ++k) {
    ck_assert_double_eq_tol(u0[k], u1[k], 1e-13 * max_abs(u0, n));
    ck_assert_double_eq_tol(r0[k], r1[k], 1e-13 * max_abs(r0, n));
  }
  /* a mesh in base 1 with a 0 id is rejected; index base 2 is rejected */
  {
    mc_int cells[3] = {0, 1, 2};
    double xy[6] = {0, 0, 1, 0, 0, 1};
    FAILS(mc_set_mesh(m, 2, 3, xy, 1, 3, cells), MC_ERROR_ARGUMENT, "cells(1)");
  }
  FAILS(mc_set_index_base(m, 2), MC_ERROR_ARGUMENT, "base");
  FAILS(mc_set_index_base(m, -1), MC_ERROR_ARGUMENT, "base");
  OK(mc_solve(m));
  ck_assert_str_eq(mc_errmsg(m), "");
  free(u0), free(u1), free(r0), free(r1);
  mc_destroy(m0);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* ---- independent models ----------------------------------------------------------- */

START_TEST(test_models_independent) {
  sc_mesh ma, mb;
  mc_model *a = cantilever(&ma, 3, 6, 3), *b = cantilever(&mb, 4, 4, 2), *m = a;
  double *ua = malloc(sizeof(double) * 2 * (size_t)ma.n_nodes), *ua2 = malloc(sizeof(double) * 2 * (size_t)ma.n_nodes);
  size_t n = 2 * (size_t)ma.n_nodes;
  OK(mc_solve(a));
  OK(mc_get_displacement(a, 1, ua));
  /* errors and changes in b do not touch a */
  m = b;
  FAILS(mc_set_material(b, 1, -1, 0.3), MC_ERROR_MATERIAL, "young");
  ck_assert_str_eq(mc_errmsg(a), "");
  OK(mc_set_material(b, 1, 1.0, 0.1));
  OK(mc_set_index_base(b, 1));
  OK(mc_solve(b));
  mc_destroy(b);
  m = a;
  OK(mc_solve(a));
  OK(mc_get_displacement(a, 1, ua2));
  ck_assert(max_diff(ua, ua2, n, 1) == 0);
  free(ua), free(ua2);
  mc_destroy(a);
  sc_mesh_free(&ma), sc_mesh_free(&mb);
}
END_TEST

/* ---- call semantics ---------------------------------------------------------------- */

/* Outputs: the library writes exactly 2 per node / 4 per cell, nothing beyond. */
START_TEST(test_output_sizes) {
  sc_mesh mesh;
  mc_model *m = cantilever(&mesh, 3 + _i, 5, 2);
  const size_t nu = 2 * (size_t)mesh.n_nodes, ns = 4 * (size_t)mesh.n_cells, guard = 16;
  double *u = malloc(sizeof(double) * (nu + guard)), *r = malloc(sizeof(double) * (nu + guard));
  double *s = malloc(sizeof(double) * (ns + guard));
  size_t k;
  for (k = 0; k < nu + guard; ++k) u[k] = r[k] = -12345.0;
  for (k = 0; k < ns + guard; ++k) s[k] = -12345.0;
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u));
  OK(mc_get_reaction(m, 1, r));
  OK(mc_get_stress(m, 1, s));
  for (k = 0; k < nu; ++k) ck_assert(u[k] != -12345.0 && r[k] != -12345.0);
  for (k = 0; k < ns; ++k) ck_assert(s[k] != -12345.0);
  for (k = 0; k < guard; ++k) {
    ck_assert(u[nu + k] == -12345.0);
    ck_assert(r[nu + k] == -12345.0);
    ck_assert(s[ns + k] == -12345.0);
  }
  free(u), free(r), free(s);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* mc_fix: a later call overrides; a one-component call keeps the other component's value;
   NULL values mean zero. Tractions and nodal forces add up, the body force is replaced. */
START_TEST(test_call_semantics) {
  sc_mesh mesh;
  mc_model *m = NULL;
  size_t n;
  double *u, *u_ref;
  mc_int node, k;
  ck_assert_int_eq(sc_mesh_rect(&mesh, 4, 4, 2, 0, 0, 2, 1, 0.1, 9u), 0);
  n = 2 * (size_t)mesh.n_nodes;
  u = malloc(sizeof(double) * n), u_ref = malloc(sizeof(double) * n);
  node = sc_node(&mesh, 4, 1);
  /* reference: left clamped, node (4,1) at (0.01, -0.02), traction 2 t0, body force b1 */
  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 10.0, 0.3));
  OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0));
  {
    double v[2] = {0.01, -0.02};
    OK(mc_fix(m, 1, 1, &node, MC_XY, v));
  }
  OK(sc_traction_side(m, 1, &mesh, SC_TOP, 0.2, -0.4, 0));
  OK(mc_set_body_force(m, 1, 0.1, 0.3));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u_ref));
  mc_destroy(m);

  ck_assert_int_eq(mc_create(&m), MC_OK);
  OK(sc_set_mesh(m, 1, &mesh, 0));
  OK(mc_set_material(m, 1, 10.0, 0.3));
  {
    mc_int ns = mesh.n_side_nodes[SC_LEFT];
    double *junk = malloc(sizeof(double) * 2 * (size_t)ns);
    for (k = 0; k < 2 * ns; ++k) junk[k] = 1.0 + k;
    OK(mc_fix(m, 1, ns, mesh.side_nodes[SC_LEFT], MC_XY, junk));
    OK(sc_fix_side(m, 1, &mesh, SC_LEFT, MC_XY, 0)); /* overrides with zeros (NULL values) */
    free(junk);
  }
  {
    double v1[2] = {0.5, -0.02}, v2[2] = {0.01, 99.0};
    OK(mc_fix(m, 1, 1, &node, MC_XY, v1));
    OK(mc_fix(m, 1, 1, &node, MC_X, v2)); /* only x changes: 0.01; y stays -0.02 */
  }
  OK(sc_traction_side(m, 1, &mesh, SC_TOP, 0.1, -0.2, 0));
  OK(sc_traction_side(m, 1, &mesh, SC_TOP, 0.1, -0.2, 0)); /* adds */
  OK(mc_set_body_force(m, 1, 5.0, 5.0));
  OK(mc_set_body_force(m, 1, 0.1, 0.3)); /* replaces */
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u));
  for (k = 0; k < (mc_int)n; ++k) ck_assert_double_eq_tol(u[k], u_ref[k], 1e-12 * max_abs(u_ref, n));
  ck_assert_double_eq(u[2 * node], 0.01);
  ck_assert_double_eq(u[2 * node + 1], -0.02);
  free(u), free(u_ref);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* Changing the plane, thickness or material of a solved model gives what a fresh model
   gives; cell laws are replaced by mc_set_material and the other way round. */
START_TEST(test_scene_changes) {
  sc_mesh mesh, other;
  mc_model *m, *fresh;
  size_t n;
  double *u, *u_ref, *r, *r_ref;
  mc_int k;
  int step;
  m = cantilever(&mesh, 3 + _i, 6, 3);
  n = 2 * (size_t)mesh.n_nodes;
  u = malloc(sizeof(double) * n), u_ref = malloc(sizeof(double) * n);
  r = malloc(sizeof(double) * n), r_ref = malloc(sizeof(double) * n);
  OK(mc_solve(m));
  for (step = 0; step < 4; ++step) {
    mc_model *keep = m;
    double *d = NULL;
    if (step == 0) OK(mc_set_plane(m, MC_PLANE_STRESS, 1.0));
    if (step == 1) OK(mc_set_plane(m, MC_PLANE_STRESS, 3.0));
    if (step == 2) OK(mc_set_material(m, 1, 50.0, 0.1));
    if (step == 3) {
      double D[9];
      mc_int c;
      d = malloc(sizeof(double) * 9 * (size_t)mesh.n_cells);
      sc_isotropic_law(70.0, 0.2, MC_PLANE_STRESS, D, NULL);
      for (c = 0; c < mesh.n_cells; ++c) memcpy(d + 9 * c, D, sizeof D);
      OK(mc_set_cell_elasticity(m, 1, d));
    }
    OK(mc_solve(m));
    OK(mc_get_displacement(m, 1, u));
    OK(mc_get_reaction(m, 1, r));
    fresh = cantilever(&other, 3 + _i, 6, 3);
    m = fresh;
    OK(mc_set_plane(m, MC_PLANE_STRESS, step == 0 ? 1.0 : 3.0));
    if (step == 2) OK(mc_set_material(m, 1, 50.0, 0.1));
    if (step == 3) OK(mc_set_material(m, 1, 70.0, 0.2));
    OK(mc_solve(m));
    OK(mc_get_displacement(m, 1, u_ref));
    OK(mc_get_reaction(m, 1, r_ref));
    for (k = 0; k < (mc_int)n; ++k) {
      ck_assert_double_eq_tol(u[k], u_ref[k], 1e-12 * max_abs(u_ref, n));
      ck_assert_double_eq_tol(r[k], r_ref[k], 1e-12 * max_abs(r_ref, n));
    }
    mc_destroy(fresh);
    sc_mesh_free(&other);
    m = keep;
    free(d);
  }
  /* and back from cell laws to the material */
  OK(mc_set_material(m, 1, 50.0, 0.1));
  OK(mc_solve(m));
  OK(mc_get_displacement(m, 1, u));
  fresh = cantilever(&other, 3 + _i, 6, 3);
  OK(mc_set_plane(fresh, MC_PLANE_STRESS, 3.0));
  OK(mc_set_material(fresh, 1, 50.0, 0.1));
  OK(mc_solve(fresh));
  OK(mc_get_displacement(fresh, 1, u_ref));
  for (k = 0; k < (mc_int)n; ++k) ck_assert_double_eq_tol(u[k], u_ref[k], 1e-12 * max_abs(u_ref, n));
  mc_destroy(fresh);
  sc_mesh_free(&other);
  free(u), free(u_ref), free(r), free(r_ref);
  mc_destroy(m);
  sc_mesh_free(&mesh);
}
END_TEST

/* A body whose only unknown lies on its contact surface: every unknown of its analysis is an
   interface unknown. The condensed path's constrained ordering (CAMD) once read past its arrays
   here (a fuzz finding: a constraint set outside 0..n-1 for n = 1). Body 2, the unit square
   under body 1, is held at three corners; its top-left corner moves in y only. Both paths must
   solve it alike, and body 2's supports must carry the whole load on body 1. */
START_TEST(test_body_with_every_unknown_on_the_interface) {
  const double xy1[] = {0, 0, 1, 0, 1, 1, 0, 1}, xy2[] = {0, -1, 1, -1, 1, 0, 0, 0}, p = 0.1;
  const mc_int tri[] = {0, 1, 2, 0, 2, 3}, left[] = {0, 3}, bottom[] = {0, 1}, top[] = {2, 3};
  const mc_int held[] = {0, 1, 2}, corner[] = {3};
  double u[2][2][8], r[8];
  for (int path = 0; path < 2; ++path) {
    mc_model *m;
    int64_t solver = 0;
    OK(mc_create(&m));
    OK(mc_set_mesh(m, 1, 4, xy1, 2, 3, tri));
    OK(mc_set_mesh(m, 2, 4, xy2, 2, 3, tri));
    for (int b = 1; b <= 2; ++b) OK(mc_set_material(m, b, 1.0, 0.3));
    OK(mc_fix(m, 1, 2, left, MC_X, NULL));
    OK(mc_fix(m, 2, 3, held, MC_XY, NULL));
    OK(mc_fix(m, 2, 1, corner, MC_X, NULL));
    OK(mc_add_pressure(m, 1, 1, top, &p));
    OK(mc_set_contact(m, 1, 1, bottom));
    OK(mc_set_contact(m, 2, 1, top));
    OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
    OK(mc_solve(m));
    OK(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &solver));
    ck_assert_int_eq(solver, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED);
    OK(mc_get_displacement(m, 1, u[path][0]));
    OK(mc_get_displacement(m, 2, u[path][1]));
    OK(mc_get_reaction(m, 2, r));
    double ry = 0;
    for (int k = 0; k < 4; ++k) ry += r[2 * k + 1];
    ck_assert_msg(fabs(fabs(ry) - p) < 1e-12, "body 2's supports carry %.17g of the load %g", fabs(ry), p);
    ck_assert_msg(u[path][1][7] < 0, "the free corner of body 2 moves down (u_y = %g)", u[path][1][7]);
    mc_destroy(m);
  }
  for (int b = 0; b < 2; ++b)
    for (int k = 0; k < 8; ++k)
      ck_assert_msg(fabs(u[0][b][k] - u[1][b][k]) < 1e-12, "body %d, entry %d: condensed %.17g, sparse %.17g", b + 1,
                    k, u[0][b][k], u[1][b][k]);
}
END_TEST

static Suite *model_suite(void) {
  Suite *s = suite_create("model");
  TCase *tc = tcase_create("lifecycle");
  tcase_add_test(tc, test_version);
  tcase_add_test(tc, test_create_destroy);
  tcase_add_test(tc, test_status_strings);
  tcase_add_test(tc, test_models_independent);
  suite_add_tcase(s, tc);
  tc = tcase_create("options_infos");
  tcase_add_test(tc, test_options);
  tcase_add_loop_test(tc, test_infos, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("resolve");
  tcase_add_loop_test(tc, test_resolve_reuses_factorization, 0, 2);
  tcase_add_test(tc, test_reset_mesh_clears);
  tcase_add_test(tc, test_index_base);
  suite_add_tcase(s, tc);
  tc = tcase_create("semantics");
  tcase_add_loop_test(tc, test_output_sizes, 0, 2);
  tcase_add_test(tc, test_call_semantics);
  tcase_add_loop_test(tc, test_scene_changes, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("analysis");
  tcase_add_test(tc, test_body_with_every_unknown_on_the_interface);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(model_suite()); }
