/*
 * test_interface_blocks.c - the condensed interface operator stored by blocks (issue 32: "do not
 * form or factor a dense block between two bodies that share no pair";
 * lib/linalg/block_sparse_operator.hpp).
 *
 * - a chain of N blocks (N = 4, 6: block tridiagonal, the first N with blocks left out), crowned
 *   interfaces (mc_set_pair_gap_offset) under a pressure that varies along the top, so that each
 *   interface is partly open and its pressure not uniform: the condensed path (S by blocks, its
 *   active-set systems by CHOLMOD) gives the sparse path's answer, pressures and displacements
 *   to 1e-10 of their largest;
 * - the storage grows linearly with the chain: the log of the interface operator phase names
 *   N - 1 blocks of rows and exactly sum m_k^2 + sum m_k m_(k+1) stored entries (m_k the rows of
 *   pair k), for N = 4, 8, 16; two bodies keep one dense block of q^2 entries;
 * - friction on separate blocks: a partial-slip scene (stick, slip and open positions; Coulomb and
 *   Tresca) set twice in one model, bodies 1-2 and 3-4 side by side, gives the answer of the
 *   scene alone (one dense block, LAPACK) to 1e-10: the block path of the frictional solve (UMFPACK).
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_helpers.h"
#include "mortarcontact.h"
#include "scenes.h"

static const double E = 1.0, NU = 0.3, P0 = 0.01;

/* ---- the log line of the interface operator --------------------------------------------- */

typedef struct operator_log {
  int seen, order, blocks;
  long entries;
} operator_log;

static void note_operator(void *user, mc_log_level level, const char *message) {
  (void)level;
  operator_log *log = user;
  if (strncmp(message, "interface operator:", 19) != 0) return;
  const char *order = strstr(message, "of order ");
  ck_assert_ptr_nonnull(order);
  ck_assert_int_eq(sscanf(order, "of order %d, %d block", &log->order, &log->blocks), 2);
  const char *comma = strstr(order, "of rows, ");
  ck_assert_ptr_nonnull(comma);
  ck_assert_int_eq(sscanf(comma, "of rows, %ld entries stored", &log->entries), 1);
  ++log->seen;
}

/* ---- a chain of N blocks --------------------------------------------------------------------- */

/* Block k (k = 0 top .. n - 1 bottom): [0, 1] x [n - 1 - k, n - k], P1, nx alternating 3 and 4
   (every interface non-matching), 2 cells high. Pair k: block k's bottom (non-mortar) on block
   k + 1's top. The bottom block's base held; every block's bottom-left corner held in x; the
   others held vertically and in rotation by contact alone. crown > 0: pair k's non-mortar nodes
   get the gap offset crown (x - 1/2)^2; the top pressure is then P0 (0.4 + 1.2 x) (edge
   midpoints), else P0. */
typedef struct chain {
  int n;
  sc_mesh *mesh;
} chain;

static int chain_nx(int k) { return k % 2 ? 4 : 3; }

static mc_model *chain_model(chain *c, int n, double crown, int path) {
  mc_model *m;
  c->n = n;
  c->mesh = calloc((size_t)n, sizeof(sc_mesh));
  OK(mc_create(&m));
  OK(mc_set_body_count(m, n));
  for (int k = 0; k < n; ++k) {
    ck_assert_int_eq(sc_mesh_rect(&c->mesh[k], 3, chain_nx(k), 2, 0, n - 1 - k, 1, 1, 0, 1), 0);
    OK(sc_set_mesh(m, k + 1, &c->mesh[k], 0));
    OK(mc_set_material(m, k + 1, E, NU));
    mc_int corner = sc_node(&c->mesh[k], 0, 0);
    OK(mc_fix(m, k + 1, 1, &corner, MC_X, NULL));
  }
  OK(sc_fix_side(m, n, &c->mesh[n - 1], SC_BOTTOM, MC_XY, 0));
  const sc_mesh *top = &c->mesh[0];
  const mc_int n_top = top->n_side_edges[SC_TOP];
  double *p = malloc(sizeof(double) * (size_t)n_top);
  for (mc_int e = 0; e < n_top; ++e) {
    const mc_int a = top->side_edges[SC_TOP][2 * e], b = top->side_edges[SC_TOP][2 * e + 1];
    const double x = 0.5 * (top->xy[2 * a] + top->xy[2 * b]);
    p[e] = crown > 0 ? P0 * (0.4 + 1.2 * x) : P0;
  }
  OK(mc_add_pressure(m, 1, n_top, top->side_edges[SC_TOP], p));
  free(p);
  for (int k = 0; k + 1 < n; ++k) {
    int pair = 0;
    const sc_mesh *upper = &c->mesh[k], *lower = &c->mesh[k + 1];
    OK(mc_add_contact_pair(m, k + 1, k + 2, &pair));
    ck_assert_int_eq(pair, k + 1);
    OK(mc_set_pair_surface(m, pair, k + 1, upper->n_side_edges[SC_BOTTOM], upper->side_edges[SC_BOTTOM]));
    OK(mc_set_pair_surface(m, pair, k + 2, lower->n_side_edges[SC_TOP], lower->side_edges[SC_TOP]));
    if (crown > 0) {
      const mc_int nn = upper->n_side_nodes[SC_BOTTOM];
      double *offset = malloc(sizeof(double) * (size_t)nn);
      for (mc_int j = 0; j < nn; ++j) {
        const double x = upper->xy[2 * upper->side_nodes[SC_BOTTOM][j]];
        offset[j] = crown * (x - 0.5) * (x - 0.5);
      }
      OK(mc_set_pair_gap_offset(m, pair, nn, upper->side_nodes[SC_BOTTOM], offset));
      free(offset);
    }
  }
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
  return m;
}

static void chain_free(chain *c) {
  for (int k = 0; k < c->n; ++k) sc_mesh_free(&c->mesh[k]);
  free(c->mesh);
}

typedef struct chain_answer {
  double *pressure, *u; /* every pair's positions, then every body's displacements */
  mc_int n_pressure, n_u;
} chain_answer;

static chain_answer chain_read(mc_model *m, const chain *c) {
  chain_answer a = {0};
  for (int pair = 1; pair < c->n; ++pair) {
    mc_int n = 0;
    OK(mc_get_pair_contact_count(m, pair, &n));
    a.pressure = realloc(a.pressure, sizeof(double) * (size_t)(a.n_pressure + n));
    OK(mc_get_pair_contact(m, pair, MC_CONTACT_PRESSURE, a.pressure + a.n_pressure));
    a.n_pressure += n;
  }
  for (int k = 0; k < c->n; ++k) {
    const mc_int n = 2 * c->mesh[k].n_nodes;
    a.u = realloc(a.u, sizeof(double) * (size_t)(a.n_u + n));
    OK(mc_get_displacement(m, k + 1, a.u + a.n_u));
    a.n_u += n;
  }
  return a;
}

/* max |a - b| / max |b| */
static double relative_difference(const double *a, const double *b, mc_int n) {
  double worst = 0, scale = 0;
  for (mc_int i = 0; i < n; ++i) worst = fmax(worst, fabs(a[i] - b[i])), scale = fmax(scale, fabs(b[i]));
  return worst / scale;
}

/* _i: N = 4, 6 */
START_TEST(chain_paths_agree) {
  const int n = _i ? 6 : 4;
  chain answers_of[2];
  chain_answer answer[2];
  operator_log log = {0};
  for (int path = 0; path < 2; ++path) {
    mc_model *m = chain_model(&answers_of[path], n, 0.02, path);
    if (path == 0) OK(mc_set_log_callback(m, note_operator, &log));
    OK(mc_solve(m));
    int64_t solver = 0;
    OK(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &solver));
    ck_assert_int_eq(solver, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED);
    answer[path] = chain_read(m, &answers_of[path]);
    mc_destroy(m);
  }
  ck_assert_int_eq(log.seen, 1);
  ck_assert_int_eq(log.blocks, n - 1); /* one block per pair: S block tridiagonal */
  ck_assert_int_eq(answer[0].n_pressure, answer[1].n_pressure);
  /* the scene is not trivial: some positions open, the pressure far from uniform */
  int open = 0;
  double pmax = 0;
  for (mc_int j = 0; j < answer[1].n_pressure; ++j) open += answer[1].pressure[j] == 0, pmax = fmax(pmax, answer[1].pressure[j]);
  ck_assert_int_gt(open, 0);
  ck_assert_double_gt(pmax, 1.2 * P0);
  const double dp = relative_difference(answer[0].pressure, answer[1].pressure, answer[1].n_pressure);
  const double du = relative_difference(answer[0].u, answer[1].u, answer[1].n_u);
  ck_assert_msg(dp <= 1e-10, "N = %d: pressures differ by %g of the largest", n, dp);
  ck_assert_msg(du <= 1e-10, "N = %d: displacements differ by %g of the largest", n, du);
  for (int path = 0; path < 2; ++path) {
    free(answer[path].pressure), free(answer[path].u);
    chain_free(&answers_of[path]);
  }
}
END_TEST

/* The stored entries of the chains of 4, 8 and 16 blocks, and of two. */
START_TEST(chain_storage_grows_linearly) {
  static const int sizes[4] = {2, 4, 8, 16};
  for (int s = 0; s < 4; ++s) {
    const int n = sizes[s];
    chain c;
    operator_log log = {0};
    mc_model *m = chain_model(&c, n, 0, 0);
    OK(mc_set_log_callback(m, note_operator, &log));
    OK(mc_solve(m));
    /* the rows: one per non-mortar position of each pair (P1, every position sees the mortar side) */
    long q = 0, expected = 0, previous = 0;
    for (int k = 0; k + 1 < n; ++k) {
      const long rows = chain_nx(k) + 1;
      q += rows, expected += rows * rows + rows * previous, previous = rows;
    }
    ck_assert_int_eq(log.seen, 1);
    ck_assert_int_eq(log.order, q);
    ck_assert_int_eq(log.blocks, n - 1);
    ck_assert_int_eq(log.entries, expected);
    if (n > 4) ck_assert_int_lt(log.entries, q * q / 2);
    mc_destroy(m);
    chain_free(&c);
  }
}
END_TEST

/* ---- friction on separate blocks ------------------------------------------------------------ */

/* The partial-slip scene of test_friction.c (the upper block, E = 1, pressed into the stiffer
   lower one, E = 3, by its top moved down and sideways, and a corner force: stick, slip and open
   positions), once (bodies 1-2) or twice (also bodies 3-4, moved right by 2). */
typedef struct slip_scene {
  sc_mesh upper[2], lower[2];
} slip_scene;

static void add_slip_scene(mc_model *m, slip_scene *s, int copy, int law, double value) {
  const int up = 2 * copy + 1, low = 2 * copy + 2;
  const double x0 = 2.0 * copy;
  ck_assert_int_eq(sc_mesh_rect(&s->upper[copy], 3, 3, 2, x0, 1, 1, 1, 0.1, 3), 0);
  ck_assert_int_eq(sc_mesh_rect(&s->lower[copy], 3, 4, 3, x0, 0, 1, 1, 0.1, 5), 0);
  const sc_mesh *u = &s->upper[copy], *l = &s->lower[copy];
  OK(sc_set_mesh(m, up, u, 0));
  OK(sc_set_mesh(m, low, l, 0));
  OK(mc_set_material(m, up, E, NU));
  OK(mc_set_material(m, low, 3 * E, NU));
  OK(sc_fix_side(m, low, l, SC_BOTTOM, MC_XY, 0));
  const mc_int n = u->n_side_nodes[SC_TOP];
  double *values = malloc(sizeof(double) * 2 * (size_t)n);
  for (mc_int k = 0; k < n; ++k) values[2 * k] = 0.004, values[2 * k + 1] = -0.01;
  OK(mc_fix(m, up, n, u->side_nodes[SC_TOP], MC_XY, values));
  free(values);
  const mc_int corner = u->side_nodes[SC_RIGHT][0];
  const double force[2] = {-1e-4, 0};
  OK(mc_add_nodal_force(m, up, 1, &corner, force));
  int pair = 0;
  OK(mc_add_contact_pair(m, up, low, &pair));
  ck_assert_int_eq(pair, copy + 1);
  OK(mc_set_pair_surface(m, pair, up, u->n_side_edges[SC_BOTTOM], u->side_edges[SC_BOTTOM]));
  OK(mc_set_pair_surface(m, pair, low, l->n_side_edges[SC_TOP], l->side_edges[SC_TOP]));
  OK(mc_set_friction(m, pair, law, value));
}

typedef struct slip_answer {
  mc_int n;
  double *pressure, *shear, *state, *u;
  mc_int n_u;
} slip_answer;

static slip_answer slip_read(mc_model *m, const slip_scene *s, int copy) {
  slip_answer a = {0};
  OK(mc_get_pair_contact_count(m, copy + 1, &a.n));
  a.pressure = malloc(sizeof(double) * (size_t)a.n), a.shear = malloc(sizeof(double) * (size_t)a.n);
  a.state = malloc(sizeof(double) * (size_t)a.n);
  OK(mc_get_pair_contact(m, copy + 1, MC_CONTACT_PRESSURE, a.pressure));
  OK(mc_get_pair_contact(m, copy + 1, MC_CONTACT_SHEAR, a.shear));
  OK(mc_get_pair_contact(m, copy + 1, MC_CONTACT_STATE, a.state));
  a.n_u = 2 * (s->upper[copy].n_nodes + s->lower[copy].n_nodes);
  a.u = malloc(sizeof(double) * (size_t)a.n_u);
  OK(mc_get_displacement(m, 2 * copy + 1, a.u));
  OK(mc_get_displacement(m, 2 * copy + 2, a.u + 2 * s->upper[copy].n_nodes));
  return a;
}

static void slip_free(slip_answer *a) { free(a->pressure), free(a->shear), free(a->state), free(a->u); }

/* _i: 0 Coulomb (mu 0.3), 1 Tresca (bound 2e-3) */
START_TEST(friction_on_separate_blocks_gives_the_answer_of_each) {
  const int law = _i ? MC_FRICTION_TRESCA : MC_FRICTION_COULOMB;
  const double value = _i ? 2e-3 : 0.3;
  slip_scene alone, twice;
  mc_model *m;
  OK(mc_create(&m));
  add_slip_scene(m, &alone, 0, law, value);
  OK(mc_solve(m));
  slip_answer reference = slip_read(m, &alone, 0);
  mc_destroy(m);
  OK(mc_create(&m));
  OK(mc_set_body_count(m, 4));
  add_slip_scene(m, &twice, 0, law, value);
  add_slip_scene(m, &twice, 1, law, value);
  operator_log log = {0};
  OK(mc_set_log_callback(m, note_operator, &log));
  OK(mc_solve(m));
  ck_assert_int_eq(log.seen, 1);
  ck_assert_int_eq(log.blocks, 2); /* the two scenes share no body */
  ck_assert_int_eq(log.entries, (long)log.order * log.order / 2);
  /* the scene has stick, slip and open positions */
  int states[3] = {0, 0, 0};
  for (mc_int j = 0; j < reference.n; ++j) {
    const int st = (int)reference.state[j];
    states[st == MC_STATE_OPEN ? 0 : st == MC_STATE_STICK ? 1 : 2]++;
  }
  ck_assert_msg(states[1] > 0 && states[2] > 0, "stick %d, slip %d", states[1], states[2]);
  double pmax = 0, tmax = 0;
  for (mc_int j = 0; j < reference.n; ++j) pmax = fmax(pmax, reference.pressure[j]), tmax = fmax(tmax, fabs(reference.shear[j]));
  for (int copy = 0; copy < 2; ++copy) {
    slip_answer a = slip_read(m, &twice, copy);
    ck_assert_int_eq(a.n, reference.n);
    for (mc_int j = 0; j < a.n; ++j) {
      ck_assert_msg(fabs(a.pressure[j] - reference.pressure[j]) <= 1e-10 * pmax, "copy %d, position %d: pressure %.17g, alone %.17g",
                    copy, (int)j, a.pressure[j], reference.pressure[j]);
      ck_assert_msg(fabs(a.shear[j] - reference.shear[j]) <= 1e-10 * tmax, "copy %d, position %d: shear %.17g, alone %.17g",
                    copy, (int)j, a.shear[j], reference.shear[j]);
      ck_assert_double_eq(a.state[j], reference.state[j]);
    }
    const double du = relative_difference(a.u, reference.u, a.n_u);
    ck_assert_msg(du <= 1e-10, "copy %d: displacements differ by %g of the largest", copy, du);
    slip_free(&a);
  }
  slip_free(&reference);
  mc_destroy(m);
  for (int k = 0; k < 2; ++k) {
    sc_mesh_free(&twice.upper[k]), sc_mesh_free(&twice.lower[k]);
  }
  sc_mesh_free(&alone.upper[0]), sc_mesh_free(&alone.lower[0]);
}
END_TEST

static Suite *interface_blocks_suite(void) {
  Suite *s = suite_create("interface_blocks");
  TCase *tc = tcase_create("block-sparse interface operator");
  tcase_set_timeout(tc, 120);
  tcase_add_loop_test(tc, chain_paths_agree, 0, 2);
  tcase_add_test(tc, chain_storage_grows_linearly);
  tcase_add_loop_test(tc, friction_on_separate_blocks_gives_the_answer_of_each, 0, 2);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(interface_blocks_suite()); }
