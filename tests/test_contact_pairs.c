/*
 * test_contact_pairs.c - assemblies: bodies 1..N and contact pairs (mc_set_body_count,
 * mc_add_contact_pair, mc_set_pair_surface, mc_get_pair_contact).
 *
 * - old programs: a two-body scene written with mc_set_contact and with an explicit pair 1 gives
 *   the same answers, bit for bit;
 * - patch tests at round-off on non-matching meshes, both interface paths, mortar and dual
 *   mortar: a stack of three blocks under a uniform pressure (every contact pressure p), and a
 *   block pushed into a corner by a floor body and a wall body (p_y on the floor, p_x on the wall,
 *   at the block's corner node too, which is non-mortar in both pairs);
 * - invariance: the three blocks with the bodies renumbered and the pairs made in another order;
 *   a non-mortar surface split into two pairs facing the same mortar body (the unsplit answer);
 * - conservation: per pair the forces on its two sides cancel; per body loads, reactions and
 *   contact forces balance;
 * - a rigid mode no pair holds (a block between two frictionless plates slides sideways):
 *   MC_ERROR_SINGULAR naming the body and the mode;
 * - bad input, each refused with its status and a message naming the body, pair, edge or node,
 *   the handle usable afterwards.
 */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_helpers.h"
#include "host_assembly.h"
#include "mortarcontact.h"
#include "scenes.h"

/* ---- the stack of three blocks ------------------------------------------------------------ */

/* Blocks [0,1] x [y0, y0 + 1], y0 = 2, 1, 0 for top, middle and bottom, non-matching P1 or Q1
   meshes (nx 3, 5, 4). The bottom block on rollers (u_y = 0 at its bottom); every block's
   bottom-left corner held in x; p on the top block's top. The top and middle blocks are held
   in y and in rotation by contact alone. */
typedef struct stack3 {
  sc_mesh mesh[3];   /* top, middle, bottom */
  int body_of[3];    /* the model's body number of each block */
} stack3;

static const double STACK_P = 0.25, STACK_E = 2.0, STACK_NU = 0.3;

static void stack3_meshes(stack3 *s, int npc) {
  static const int nx[3] = {3, 5, 4};
  for (int k = 0; k < 3; ++k) {
    if (npc <= 4) ck_assert_int_eq(sc_mesh_rect(&s->mesh[k], npc, nx[k], 2, 0, 2 - k, 1, 1, 0.1, 7 + k), 0);
    else ck_assert_int_eq(sc_mesh_cells(&s->mesh[k], npc, nx[k], 2, 0, 2 - k, 1, 1, 0), 0); /* T6, Q8, Q9 */
  }
}

static void stack3_free(stack3 *s) {
  for (int k = 0; k < 3; ++k) sc_mesh_free(&s->mesh[k]);
}

/* A block as a host body: its element matrices from the independent assembler
   (host_assembly.h), 2 equations per node in node order, the bottom-left corner's x restrained. */
static void set_host_block(mc_model *m, int body, const sc_mesh *mesh) {
  const int npc = mesh->npc;
  const mc_int corner = sc_node(mesh, 0, 0);
  mc_int *equations = malloc(sizeof(mc_int) * 2 * (size_t)mesh->n_nodes), n_eq = 0;
  for (mc_int i = 0; i < mesh->n_nodes; ++i)
    for (int c = 0; c < 2; ++c) equations[2 * i + c] = i == corner && c == 0 ? -1 : n_eq++;
  OK(mc_set_host_body(m, body, mesh->n_nodes, mesh->xy, equations, n_eq));
  mc_int *eltptr, *eltvar;
  double *a, D[9];
  ha_law_plane_strain(STACK_E, STACK_NU, D);
  /* symmetric element matrices: either storage order */
  ck_assert_int_eq(ha_mesh_element_matrices(npc, mesh->n_cells, mesh->cells, mesh->xy, equations, D, &eltptr, &eltvar, &a), 0);
  OK(mc_add_element_matrices(m, body, mesh->n_cells, eltptr, eltvar, a));
  free(equations), free(eltptr), free(eltvar), free(a);
}

/* Builds the model with block k as body body_of[k]; the pairs (top on middle, middle on bottom)
   made in the order given by `order` (0: top pair first). host_middle: the middle block is a
   host body (its own element matrices) between two mesh bodies. */
static mc_model *stack3_model_host(stack3 *s, const int body_of[3], int order, int method, int path, int host_middle) {
  mc_model *m;
  int pair[2];
  OK(mc_create(&m));
  OK(mc_set_body_count(m, 3));
  for (int k = 0; k < 3; ++k) {
    s->body_of[k] = body_of[k];
    if (k == 1 && host_middle) {
      set_host_block(m, body_of[k], &s->mesh[k]);
      continue;
    }
    OK(sc_set_mesh(m, body_of[k], &s->mesh[k], 0));
    OK(mc_set_material(m, body_of[k], STACK_E, STACK_NU));
    mc_int corner = sc_node(&s->mesh[k], 0, 0);
    OK(mc_fix(m, body_of[k], 1, &corner, MC_X, NULL));
  }
  OK(sc_fix_side(m, body_of[2], &s->mesh[2], SC_BOTTOM, MC_Y, 0));
  double *p = malloc(sizeof(double) * (size_t)s->mesh[0].n_side_edges[SC_TOP]);
  for (mc_int e = 0; e < s->mesh[0].n_side_edges[SC_TOP]; ++e) p[e] = STACK_P;
  OK(mc_add_pressure(m, body_of[0], s->mesh[0].n_side_edges[SC_TOP], s->mesh[0].side_edges[SC_TOP], p));
  free(p);
  for (int j = 0; j < 2; ++j) {
    const int k = order ? 1 - j : j; /* the pair of block k (non-mortar) on block k + 1 (mortar) */
    OK(mc_add_contact_pair(m, body_of[k], body_of[k + 1], &pair[k]));
    ck_assert_int_eq(pair[k], j + 1);
    OK(mc_set_pair_surface(m, pair[k], body_of[k], s->mesh[k].n_side_edges[SC_BOTTOM], s->mesh[k].side_edges[SC_BOTTOM]));
    OK(mc_set_pair_surface(m, pair[k], body_of[k + 1], s->mesh[k + 1].n_side_edges[SC_TOP],
                           s->mesh[k + 1].side_edges[SC_TOP]));
  }
  OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
  return m;
}

static mc_model *stack3_model(stack3 *s, const int body_of[3], int order, int method, int path) {
  return stack3_model_host(s, body_of, order, method, path, 0);
}

/* The pair numbers of the stack's two contacts (top on middle, middle on bottom) for `order`. */
static int stack3_pair(int contact, int order) { return order ? 2 - contact : contact + 1; }

/* Every contact pressure of pair `pair` is p within tol (relative), on the positions that see the
   mortar side (all of them here), and returns how many there were. */
static int assert_pair_pressure(mc_model *m, int pair, double p, double tol) {
  mc_int n = 0;
  OK(mc_get_pair_contact_count(m, pair, &n));
  ck_assert_int_gt(n, 0);
  double *values = malloc(sizeof(double) * (size_t)n);
  OK(mc_get_pair_contact(m, pair, MC_CONTACT_PRESSURE, values));
  for (mc_int j = 0; j < n; ++j)
    ck_assert_msg(fabs(values[j] - p) <= tol * p, "pair %d, position %d: pressure %.17g, expected %g", pair, (int)j,
                  values[j], p);
  free(values);
  return (int)n;
}

/* _i: method (0 mortar, 1 dual) x path (condensed, sparse) x cells (P1, Q1, T6, Q8) */
START_TEST(stack_of_three_blocks_is_a_patch_test) {
  static const int kinds[4] = {3, 4, 6, 8};
  const int method = _i % 2, path = _i / 2 % 2, npc = kinds[_i / 4];
  const int natural[3] = {1, 2, 3};
  stack3 s;
  stack3_meshes(&s, npc);
  mc_model *m = stack3_model(&s, natural, 0, method, path);
  OK(mc_solve(m));
  int64_t solver = 0, active = 0, rows = 0;
  OK(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &solver));
  ck_assert_int_eq(solver, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED);
  const int n1 = assert_pair_pressure(m, 1, STACK_P, 1e-10), n2 = assert_pair_pressure(m, 2, STACK_P, 1e-10);
  const int per_edge = npc > 4 ? 2 : 1; /* quadratic sides: the middles are positions too */
  ck_assert_int_eq(n1, per_edge * s.mesh[0].nx + 1);
  ck_assert_int_eq(n2, per_edge * s.mesh[1].nx + 1);
  /* the infos that count contact count both pairs */
  OK(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active));
  OK(mc_get_info_int(m, MC_INFO_CONTACT_NODES, &rows));
  ck_assert_int_eq(active, rows); /* every row of both pairs presses */
  if (npc <= 4) ck_assert_int_eq(rows, n1 + n2); /* one row per position (quadratic sides: per multiplier) */
  else ck_assert_int_gt(rows, 0);
  /* the uniform stress state in every block: sigma_yy = -p, sigma_xx = 0 */
  for (int k = 0; k < 3; ++k) {
    double *sigma = malloc(sizeof(double) * 4 * (size_t)s.mesh[k].n_cells);
    OK(mc_get_stress(m, k + 1, sigma));
    for (mc_int c = 0; c < s.mesh[k].n_cells; ++c) {
      ck_assert_msg(fabs(sigma[4 * c + 1] + STACK_P) < 1e-10 * STACK_P, "block %d cell %d: sigma_yy %.17g", k + 1, (int)c,
                    sigma[4 * c + 1]);
      ck_assert_msg(fabs(sigma[4 * c]) < 1e-10 * STACK_P, "block %d cell %d: sigma_xx %.17g", k + 1, (int)c, sigma[4 * c]);
    }
    free(sigma);
  }
  mc_destroy(m);
  stack3_free(&s);
}
END_TEST

/* The middle block as a host body (mortar in one pair, non-mortar in the other, held by contact
   alone in y and in rotation): the same patch test. _i: path x cells (P1, Q1). */
START_TEST(stack_with_a_host_body_in_the_middle_is_a_patch_test) {
  const int path = _i % 2, npc = 3 + _i / 2;
  const int natural[3] = {1, 2, 3};
  stack3 s;
  stack3_meshes(&s, npc);
  mc_model *m = stack3_model_host(&s, natural, 0, MC_METHOD_MORTAR, path, 1);
  OK(mc_solve(m));
  assert_pair_pressure(m, 1, STACK_P, 1e-10);
  assert_pair_pressure(m, 2, STACK_P, 1e-10);
  mc_destroy(m);
  stack3_free(&s);
}
END_TEST

/* The displacements of each block, read from a model whose blocks are bodies body_of[]. */
static void stack3_displacements(mc_model *m, const stack3 *s, double *u[3]) {
  for (int k = 0; k < 3; ++k) {
    u[k] = malloc(sizeof(double) * 2 * (size_t)s->mesh[k].n_nodes);
    OK(mc_get_displacement(m, s->body_of[k], u[k]));
  }
}

/* A load that bends the stack (a pressure over the top's left part only, so the contact zones
   open partly): the answers must not depend on body numbers or pair order. _i: path. */
START_TEST(renumbered_bodies_and_reordered_pairs_change_nothing) {
  const int path = _i;
  const int numbering[3][3] = {{1, 2, 3}, {3, 1, 2}, {2, 3, 1}};
  double *reference[3] = {NULL, NULL, NULL}, p_ref[64];
  mc_int n_ref = 0;
  for (int variant = 0; variant < 6; ++variant) {
    const int *body_of = numbering[variant % 3], order = variant / 3;
    stack3 s;
    stack3_meshes(&s, 3);
    mc_model *m = stack3_model(&s, body_of, order, MC_METHOD_MORTAR, path);
    /* an extra load on the top block's right half: the stack tilts onto its right side */
    mc_int node = sc_node(&s.mesh[0], s.mesh[0].nx, s.mesh[0].ny);
    double f[2] = {0, -0.2};
    OK(mc_add_nodal_force(m, body_of[0], 1, &node, f));
    OK(mc_solve(m));
    double *u[3];
    stack3_displacements(m, &s, u);
    mc_int n = 0;
    const int pair_top = stack3_pair(0, order);
    OK(mc_get_pair_contact_count(m, pair_top, &n));
    ck_assert_int_le(n, 64);
    double p[64];
    OK(mc_get_pair_contact(m, pair_top, MC_CONTACT_PRESSURE, p));
    if (variant == 0) {
      for (int k = 0; k < 3; ++k) reference[k] = u[k];
      memcpy(p_ref, p, sizeof(double) * (size_t)n);
      n_ref = n;
    } else {
      double scale = 0;
      for (int k = 0; k < 3; ++k)
        for (mc_int i = 0; i < 2 * s.mesh[k].n_nodes; ++i) scale = fmax(scale, fabs(reference[k][i]));
      for (int k = 0; k < 3; ++k) {
        for (mc_int i = 0; i < 2 * s.mesh[k].n_nodes; ++i)
          ck_assert_msg(fabs(u[k][i] - reference[k][i]) <= 1e-12 * scale, "variant %d, block %d, entry %d: %.17g vs %.17g",
                        variant, k + 1, (int)i, u[k][i], reference[k][i]);
        free(u[k]);
      }
      ck_assert_int_eq(n, n_ref);
      for (mc_int j = 0; j < n; ++j)
        ck_assert_msg(fabs(p[j] - p_ref[j]) <= 1e-12 * STACK_P, "variant %d, position %d: %.17g vs %.17g", variant, (int)j,
                      p[j], p_ref[j]);
    }
    mc_destroy(m);
    stack3_free(&s);
  }
  for (int k = 0; k < 3; ++k) free(reference[k]);
}
END_TEST

/* The bodies' work on two threads (the odd bodies on the second): the serial answer. */
START_TEST(two_threads_give_the_serial_answer) {
  const int natural[3] = {1, 2, 3};
  double *u[2][3];
  for (int threads = 1; threads <= 2; ++threads) {
    stack3 s;
    stack3_meshes(&s, 4);
    mc_model *m = stack3_model(&s, natural, 0, MC_METHOD_MORTAR, _i);
    mc_int node = sc_node(&s.mesh[0], s.mesh[0].nx, s.mesh[0].ny);
    double f[2] = {0, -0.2};
    OK(mc_add_nodal_force(m, 1, 1, &node, f));
    OK(mc_set_option_int(m, MC_OPTION_THREADS, threads));
    OK(mc_solve(m));
    stack3_displacements(m, &s, u[threads - 1]);
    if (threads == 2)
      for (int k = 0; k < 3; ++k) {
        for (mc_int i = 0; i < 2 * s.mesh[k].n_nodes; ++i)
          ck_assert_msg(fabs(u[0][k][i] - u[1][k][i]) <= 1e-13, "block %d entry %d: %.17g serial, %.17g on two threads",
                        k + 1, (int)i, u[0][k][i], u[1][k][i]);
        free(u[0][k]), free(u[1][k]);
      }
    mc_destroy(m);
    stack3_free(&s);
  }
}
END_TEST

/* Per pair the contact forces on its two sides cancel, per body f + r + contact = 0. */
START_TEST(forces_balance_per_pair_and_per_body) {
  const int natural[3] = {1, 2, 3};
  stack3 s;
  stack3_meshes(&s, 4);
  mc_model *m = stack3_model(&s, natural, 0, MC_METHOD_MORTAR, _i);
  mc_int node = sc_node(&s.mesh[0], s.mesh[0].nx, s.mesh[0].ny);
  double f[2] = {0, -0.2};
  OK(mc_add_nodal_force(m, 1, 1, &node, f));
  OK(mc_solve(m));
  double total[3][2];
  for (int k = 0; k < 3; ++k) {
    const size_t n = 2 * (size_t)s.mesh[k].n_nodes;
    double *c = malloc(sizeof(double) * n), *r = malloc(sizeof(double) * n);
    OK(mc_get_contact_load(m, k + 1, c));
    OK(mc_get_reaction(m, k + 1, r));
    double load_y = k == 0 ? -STACK_P * 1.0 - 0.2 : 0, sum[2] = {0, 0}, rsum[2] = {0, 0};
    for (size_t i = 0; i < n; ++i) sum[i % 2] += c[i], rsum[i % 2] += r[i];
    total[k][0] = sum[0], total[k][1] = sum[1];
    ck_assert_msg(fabs(load_y + rsum[1] + sum[1]) < 1e-10, "block %d: load %g + reactions %.17g + contact %.17g", k + 1,
                  load_y, rsum[1], sum[1]);
    ck_assert_msg(fabs(rsum[0] + sum[0]) < 1e-10, "block %d in x: reactions %.17g + contact %.17g", k + 1, rsum[0], sum[0]);
    free(c), free(r);
  }
  /* block 1 touches pair 1 only, block 3 pair 2 only: block 2 carries both, so pair 1's forces
     on block 2 are -(block 1's) and pair 2's -(block 3's) */
  ck_assert_msg(fabs(total[0][1] + total[1][1] + total[2][1]) < 1e-10, "the pairs' forces do not cancel: %.17g %.17g %.17g",
                total[0][1], total[1][1], total[2][1]);
  /* contact pushes the top block up and the bottom block down by the whole load */
  ck_assert_msg(fabs(total[0][1] - (STACK_P + 0.2)) < 1e-10 && fabs(total[2][1] + (STACK_P + 0.2)) < 1e-10,
                "pair forces %.17g and %.17g, expected %g and %g", total[0][1], total[2][1], STACK_P + 0.2, -STACK_P - 0.2);
  /* pair 1's forces from its pressures: the sum of its position forces is the load */
  mc_int n = 0;
  OK(mc_get_pair_contact_count(m, 1, &n));
  double *force = malloc(sizeof(double) * (size_t)n), sum = 0;
  OK(mc_get_pair_contact(m, 1, MC_CONTACT_FORCE, force));
  for (mc_int j = 0; j < n; ++j) sum += force[j];
  ck_assert_msg(fabs(sum - (STACK_P + 0.2)) < 1e-10, "pair 1's forces sum to %.17g", sum);
  free(force);
  mc_destroy(m);
  stack3_free(&s);
}
END_TEST

/* ---- the block in a corner -------------------------------------------------------------- */

/* Block [0,1]^2 (body 1, no supports), floor [0,1] x [-1,0] (body 2: u_y = 0 at its bottom, its
   bottom-left corner held in x), wall [-1,0] x [0,1] (body 3: u_x = 0 at its left, its
   bottom-left corner held in y); p_y on the block's top, p_x on its right. Pairs: the block's
   bottom on the floor's top, the block's left on the wall's right. _i: method x path x cells. */
START_TEST(block_pushed_into_a_corner_is_a_patch_test) {
  const int method = _i % 2, path = _i / 2 % 2, npc = 3 + _i / 4;
  const double px = 0.15, py = 0.35;
  sc_mesh block, floor_, wall;
  ck_assert_int_eq(sc_mesh_rect(&block, npc, 3, 4, 0, 0, 1, 1, 0.1, 3), 0);
  ck_assert_int_eq(sc_mesh_rect(&floor_, npc, 5, 2, 0, -1, 1, 1, 0.1, 4), 0);
  ck_assert_int_eq(sc_mesh_rect(&wall, npc, 2, 7, -1, 0, 1, 1, 0.1, 5), 0);
  mc_model *m;
  int floor_pair, wall_pair;
  OK(mc_create(&m));
  OK(mc_set_body_count(m, 3));
  OK(sc_set_mesh(m, 1, &block, 0));
  OK(sc_set_mesh(m, 2, &floor_, 0));
  OK(sc_set_mesh(m, 3, &wall, 0));
  for (int b = 1; b <= 3; ++b) OK(mc_set_material(m, b, 3.0, 0.25));
  OK(sc_fix_side(m, 2, &floor_, SC_BOTTOM, MC_Y, 0));
  mc_int corner = sc_node(&floor_, 0, 0);
  OK(mc_fix(m, 2, 1, &corner, MC_X, NULL));
  OK(sc_fix_side(m, 3, &wall, SC_LEFT, MC_X, 0));
  corner = sc_node(&wall, 0, 0);
  OK(mc_fix(m, 3, 1, &corner, MC_Y, NULL));
  double p[16];
  for (int e = 0; e < 16; ++e) p[e] = py;
  OK(mc_add_pressure(m, 1, block.n_side_edges[SC_TOP], block.side_edges[SC_TOP], p));
  for (int e = 0; e < 16; ++e) p[e] = px;
  OK(mc_add_pressure(m, 1, block.n_side_edges[SC_RIGHT], block.side_edges[SC_RIGHT], p));
  OK(mc_add_contact_pair(m, 1, 2, &floor_pair));
  OK(mc_set_pair_surface(m, floor_pair, 1, block.n_side_edges[SC_BOTTOM], block.side_edges[SC_BOTTOM]));
  OK(mc_set_pair_surface(m, floor_pair, 2, floor_.n_side_edges[SC_TOP], floor_.side_edges[SC_TOP]));
  OK(mc_add_contact_pair(m, 1, 3, &wall_pair));
  OK(mc_set_pair_surface(m, wall_pair, 1, block.n_side_edges[SC_LEFT], block.side_edges[SC_LEFT]));
  OK(mc_set_pair_surface(m, wall_pair, 3, wall.n_side_edges[SC_RIGHT], wall.side_edges[SC_RIGHT]));
  OK(mc_set_option_int(m, MC_OPTION_METHOD, method));
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
  OK(mc_solve(m));
  assert_pair_pressure(m, floor_pair, py, 1e-10);
  assert_pair_pressure(m, wall_pair, px, 1e-10);
  /* the block's corner node is a position of both pairs, with each pair's normal */
  mc_int n = 0, nodes[32];
  double normal[64];
  int seen = 0;
  const int pairs[2] = {floor_pair, wall_pair};
  for (int k = 0; k < 2; ++k) {
    OK(mc_get_pair_contact_count(m, pairs[k], &n));
    OK(mc_get_pair_contact_nodes(m, pairs[k], nodes));
    OK(mc_get_pair_contact(m, pairs[k], MC_CONTACT_NORMAL, normal));
    for (mc_int j = 0; j < n; ++j)
      if (nodes[j] == sc_node(&block, 0, 0)) {
        ++seen;
        ck_assert_msg(fabs(normal[2 * j] - (k ? -1 : 0)) < 1e-12 && fabs(normal[2 * j + 1] - (k ? 0 : -1)) < 1e-12,
                      "pair %d: the corner's normal is (%g, %g)", pairs[k], normal[2 * j], normal[2 * j + 1]);
      }
  }
  ck_assert_int_eq(seen, 2);
  /* uniform stress in the block */
  double *sigma = malloc(sizeof(double) * 4 * (size_t)block.n_cells);
  OK(mc_get_stress(m, 1, sigma));
  for (mc_int c = 0; c < block.n_cells; ++c)
    ck_assert_msg(fabs(sigma[4 * c] + px) < 1e-10 && fabs(sigma[4 * c + 1] + py) < 1e-10 && fabs(sigma[4 * c + 2]) < 1e-10,
                  "block cell %d: sigma %.17g %.17g %.17g", (int)c, sigma[4 * c], sigma[4 * c + 1], sigma[4 * c + 2]);
  free(sigma);
  mc_destroy(m);
  sc_mesh_free(&block), sc_mesh_free(&floor_), sc_mesh_free(&wall);
}
END_TEST

/* ---- two bodies: old calls, explicit pair 1, a split surface ------------------------------ */

/* Body 1 [0,1] x [0, 0.5] (P1 6 x 3) on body 2 [0,1] x [-0.5, 0] (Q1 8 x 4, clamped at its
   bottom), a load leaning on body 1's right (the contact zone partly open). how: 0 the two-body
   calls, 1 an explicit pair 1, 2 body 1's bottom split into two pairs at node split. */
static mc_model *two_blocks(sc_mesh *a, sc_mesh *b, int how, int split, int path) {
  mc_model *m;
  OK(mc_create(&m));
  OK(sc_set_mesh(m, 1, a, 0));
  OK(sc_set_mesh(m, 2, b, 0));
  OK(mc_set_material(m, 1, 1.0, 0.3));
  OK(mc_set_material(m, 2, 2.0, 0.3));
  OK(sc_fix_side(m, 2, b, SC_BOTTOM, MC_XY, 0));
  mc_int corner = sc_node(a, 0, a->ny);
  OK(mc_fix(m, 1, 1, &corner, MC_X, NULL));
  mc_int node = sc_node(a, a->nx, a->ny);
  double f[2] = {0, -1.0};
  OK(mc_add_nodal_force(m, 1, 1, &node, f));
  node = sc_node(a, a->nx / 2, a->ny);
  OK(mc_add_nodal_force(m, 1, 1, &node, f));
  const mc_int n1 = a->n_side_edges[SC_BOTTOM], *e1 = a->side_edges[SC_BOTTOM];
  const mc_int n2 = b->n_side_edges[SC_TOP], *e2 = b->side_edges[SC_TOP];
  if (how == 0) {
    OK(mc_set_contact(m, 1, n1, e1));
    OK(mc_set_contact(m, 2, n2, e2));
  } else if (how == 1) {
    int pair;
    OK(mc_add_contact_pair(m, 1, 2, &pair));
    ck_assert_int_eq(pair, 1);
    OK(mc_set_pair_surface(m, pair, 2, n2, e2)); /* the mortar side first: order does not matter */
    OK(mc_set_pair_surface(m, pair, 1, n1, e1));
  } else {
    int left, right;
    OK(mc_add_contact_pair(m, 1, 2, &left));
    OK(mc_add_contact_pair(m, 1, 2, &right));
    OK(mc_set_pair_surface(m, left, 1, split, e1));
    OK(mc_set_pair_surface(m, right, 1, n1 - split, e1 + 2 * split));
    OK(mc_set_pair_surface(m, left, 2, n2, e2)); /* both face the whole of body 2's top */
    OK(mc_set_pair_surface(m, right, 2, n2, e2));
  }
  OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
  return m;
}

/* _i: path */
START_TEST(old_calls_and_explicit_pair_one_agree_bit_for_bit) {
  sc_mesh a, b;
  ck_assert_int_eq(sc_mesh_rect(&a, 3, 6, 3, 0, 0, 1, 0.5, 0.15, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&b, 4, 8, 4, 0, -0.5, 1, 0.5, 0.15, 2), 0);
  double *u[2][2];
  mc_int n[2];
  double p[2][64], g[2][64];
  for (int how = 0; how < 2; ++how) {
    mc_model *m = two_blocks(&a, &b, how, 0, _i);
    OK(mc_solve(m));
    for (int body = 0; body < 2; ++body) {
      const sc_mesh *mesh = body ? &b : &a;
      u[how][body] = malloc(sizeof(double) * 2 * (size_t)mesh->n_nodes);
      OK(mc_get_displacement(m, body + 1, u[how][body]));
    }
    OK(mc_get_contact_count(m, &n[how]));
    ck_assert_int_le(n[how], 64);
    OK(mc_get_contact_pressure(m, p[how]));
    OK(mc_get_contact_gap(m, g[how]));
    /* the pair getter reads the same */
    mc_int np = 0;
    double pp[64];
    OK(mc_get_pair_contact_count(m, 1, &np));
    ck_assert_int_eq(np, n[how]);
    OK(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, pp));
    ck_assert_int_eq(memcmp(pp, p[how], sizeof(double) * (size_t)np), 0);
    mc_destroy(m);
  }
  ck_assert_int_eq(n[0], n[1]);
  ck_assert_int_eq(memcmp(p[0], p[1], sizeof(double) * (size_t)n[0]), 0);
  ck_assert_int_eq(memcmp(g[0], g[1], sizeof(double) * (size_t)n[0]), 0);
  for (int body = 0; body < 2; ++body) {
    const sc_mesh *mesh = body ? &b : &a;
    ck_assert_int_eq(memcmp(u[0][body], u[1][body], sizeof(double) * 2 * (size_t)mesh->n_nodes), 0);
    free(u[0][body]), free(u[1][body]);
  }
  sc_mesh_free(&a), sc_mesh_free(&b);
}
END_TEST

/* _i: path x split node (2, 3, 4) */
START_TEST(a_surface_split_into_two_pairs_gives_the_unsplit_answer) {
  const int path = _i % 2, split = 2 + _i / 2;
  sc_mesh a, b;
  ck_assert_int_eq(sc_mesh_rect(&a, 3, 6, 3, 0, 0, 1, 0.5, 0.15, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&b, 4, 8, 4, 0, -0.5, 1, 0.5, 0.15, 2), 0);
  mc_model *whole = two_blocks(&a, &b, 0, 0, path), *parts = two_blocks(&a, &b, 2, split, path);
  for (int k = 0; k < 2; ++k) {
    mc_model *m = k ? parts : whole;
    OK(mc_solve(m));
  }
  double *u[2];
  for (int k = 0; k < 2; ++k) {
    u[k] = malloc(sizeof(double) * 2 * (size_t)a.n_nodes);
    {
      mc_model *m = k ? parts : whole;
      OK(mc_get_displacement(m, 1, u[k]));
    }
  }
  double scale = 0;
  for (mc_int i = 0; i < 2 * a.n_nodes; ++i) scale = fmax(scale, fabs(u[0][i]));
  for (mc_int i = 0; i < 2 * a.n_nodes; ++i)
    ck_assert_msg(fabs(u[0][i] - u[1][i]) <= 1e-12 * scale, "split at %d, entry %d: %.17g vs %.17g", split, (int)i, u[0][i],
                  u[1][i]);
  /* the pressures: each pair's positions are the whole surface's on its edges, the split node in both */
  mc_int n = 0, nodes_whole[64], n1 = 0, n2 = 0, nodes1[64], nodes2[64];
  double p_whole[64], p1[64], p2[64];
  {
    mc_model *m = whole;
    OK(mc_get_contact_count(m, &n));
    OK(mc_get_contact_nodes(m, nodes_whole));
    OK(mc_get_contact_pressure(m, p_whole));
  }
  {
    mc_model *m = parts;
    OK(mc_get_pair_contact_count(m, 1, &n1));
    OK(mc_get_pair_contact_count(m, 2, &n2));
    OK(mc_get_pair_contact_nodes(m, 1, nodes1));
    OK(mc_get_pair_contact_nodes(m, 2, nodes2));
    OK(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, p1));
    OK(mc_get_pair_contact(m, 2, MC_CONTACT_PRESSURE, p2));
  }
  ck_assert_int_eq(n1 + n2, n + 1);
  for (mc_int j = 0; j < n; ++j) {
    int found = 0;
    for (mc_int k = 0; k < n1; ++k)
      if (nodes1[k] == nodes_whole[j]) found = 1, ck_assert_msg(fabs(p1[k] - p_whole[j]) < 1e-12, "node %d", (int)nodes1[k]);
    for (mc_int k = 0; k < n2; ++k)
      if (nodes2[k] == nodes_whole[j]) found = 1, ck_assert_msg(fabs(p2[k] - p_whole[j]) < 1e-12, "node %d", (int)nodes2[k]);
    ck_assert_msg(found, "node %d of the whole surface is in neither pair", (int)nodes_whole[j]);
  }
  free(u[0]), free(u[1]);
  mc_destroy(whole), mc_destroy(parts);
  sc_mesh_free(&a), sc_mesh_free(&b);
}
END_TEST

/* ---- what no pair holds, and bad input ------------------------------------------------- */

/* A block between two frictionless plates: nothing holds its sideways slide. */
START_TEST(a_slide_no_pair_holds_is_singular) {
  sc_mesh plate_top, block, plate_bottom;
  ck_assert_int_eq(sc_mesh_rect(&plate_top, 3, 4, 1, -0.5, 1, 2, 0.5, 0, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&block, 3, 3, 3, 0, 0, 1, 1, 0, 2), 0);
  ck_assert_int_eq(sc_mesh_rect(&plate_bottom, 3, 4, 1, -0.5, -0.5, 2, 0.5, 0, 3), 0);
  mc_model *m;
  int pair;
  OK(mc_create(&m));
  OK(mc_set_body_count(m, 3));
  OK(sc_set_mesh(m, 1, &plate_top, 0));
  OK(sc_set_mesh(m, 2, &block, 0));
  OK(sc_set_mesh(m, 3, &plate_bottom, 0));
  for (int b = 1; b <= 3; ++b) OK(mc_set_material(m, b, 1.0, 0.3));
  OK(sc_fix_side(m, 1, &plate_top, SC_TOP, MC_XY, 0));
  OK(sc_fix_side(m, 3, &plate_bottom, SC_BOTTOM, MC_XY, 0));
  OK(mc_add_contact_pair(m, 2, 1, &pair));
  OK(mc_set_pair_surface(m, pair, 2, block.n_side_edges[SC_TOP], block.side_edges[SC_TOP]));
  OK(mc_set_pair_surface(m, pair, 1, plate_top.n_side_edges[SC_BOTTOM], plate_top.side_edges[SC_BOTTOM]));
  OK(mc_add_contact_pair(m, 2, 3, &pair));
  OK(mc_set_pair_surface(m, pair, 2, block.n_side_edges[SC_BOTTOM], block.side_edges[SC_BOTTOM]));
  OK(mc_set_pair_surface(m, pair, 3, plate_bottom.n_side_edges[SC_TOP], plate_bottom.side_edges[SC_TOP]));
  for (int path = 0; path < 2; ++path) {
    OK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, path ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
    FAILS(mc_solve(m), MC_ERROR_SINGULAR, "body 2");
    ck_assert_msg(strstr(mc_errmsg(m), "translation in x") != NULL, "message: %s", mc_errmsg(m));
  }
  /* held sideways at one node, it solves (the handle is usable) */
  mc_int corner = sc_node(&block, 0, 0);
  OK(mc_fix(m, 2, 1, &corner, MC_X, NULL));
  OK(mc_solve(m));
  mc_destroy(m);
  sc_mesh_free(&plate_top), sc_mesh_free(&block), sc_mesh_free(&plate_bottom);
}
END_TEST

START_TEST(bad_bodies_and_pairs_are_refused) {
  sc_mesh a, b, c;
  ck_assert_int_eq(sc_mesh_rect(&a, 3, 2, 2, 0, 0, 1, 1, 0, 1), 0);
  ck_assert_int_eq(sc_mesh_rect(&b, 3, 3, 2, 0, -1, 1, 1, 0, 2), 0);
  ck_assert_int_eq(sc_mesh_rect(&c, 3, 2, 2, 0, -2, 1, 1, 0, 3), 0);
  mc_model *m;
  int pair = -7;
  OK(mc_create(&m));
  FAILS(mc_set_body_count(m, 1), MC_ERROR_ARGUMENT, "n = 1");
  FAILS(sc_set_mesh(m, 3, &c, 0), MC_ERROR_ARGUMENT, "body = 3: must be 1 or 2");
  OK(mc_set_body_count(m, 3));
  FAILS(sc_set_mesh(m, 4, &c, 0), MC_ERROR_ARGUMENT, "body = 4: must be 1 to 3");
  FAILS(sc_set_mesh(m, 0, &c, 0), MC_ERROR_ARGUMENT, "body = 0");
  OK(sc_set_mesh(m, 1, &a, 0));
  OK(sc_set_mesh(m, 2, &b, 0));
  for (int k = 1; k <= 2; ++k) OK(mc_set_material(m, k, 1.0, 0.3));
  FAILS(mc_add_contact_pair(m, 2, 2, &pair), MC_ERROR_ARGUMENT, "two different bodies");
  FAILS(mc_add_contact_pair(m, 1, 4, &pair), MC_ERROR_ARGUMENT, "mortar_body = 4");
  FAILS(mc_add_contact_pair(m, 1, 2, NULL), MC_ERROR_ARGUMENT, "pair is NULL");
  ck_assert_int_eq(pair, -7);
  FAILS(mc_set_pair_surface(m, 1, 1, a.n_side_edges[SC_BOTTOM], a.side_edges[SC_BOTTOM]), MC_ERROR_ARGUMENT,
        "no contact pairs");
  OK(mc_add_contact_pair(m, 1, 2, &pair));
  ck_assert_int_eq(pair, 1);
  FAILS(mc_set_pair_surface(m, 2, 1, a.n_side_edges[SC_BOTTOM], a.side_edges[SC_BOTTOM]), MC_ERROR_ARGUMENT, "pair = 2");
  {
    mc_int top_node = sc_node(&a, 0, a.ny);
    double offset = 0.01;
    FAILS(mc_set_pair_gap_offset(m, 1, 1, &top_node, &offset), MC_ERROR_STATE, "pair 1 has no non-mortar surface (body 1)");
    OK(mc_set_pair_surface(m, 1, 1, a.n_side_edges[SC_BOTTOM], a.side_edges[SC_BOTTOM]));
    FAILS(mc_set_pair_gap_offset(m, 1, 1, &top_node, &offset), MC_ERROR_ARGUMENT,
          "nodes[0] = "); /* the top node is not on the pair's non-mortar surface */
    ck_assert_msg(strstr(mc_errmsg(m), "is not on pair 1's non-mortar surface (body 1)") != NULL, "message: %s", mc_errmsg(m));
    FAILS(mc_set_pair_gap_offset(m, 3, 1, &top_node, &offset), MC_ERROR_ARGUMENT, "pair = 3");
  }
  FAILS(mc_set_pair_surface(m, 1, 3, c.n_side_edges[SC_TOP], c.side_edges[SC_TOP]), MC_ERROR_ARGUMENT,
        "pair 1 joins bodies 1 (non-mortar) and 2 (mortar)");
  OK(mc_set_pair_surface(m, 1, 1, a.n_side_edges[SC_BOTTOM], a.side_edges[SC_BOTTOM]));
  /* solve: body 3 has no mesh in a three-body model; then pair 1's mortar side is missing */
  FAILS(mc_solve(m), MC_ERROR_STATE, "body 3 has no mesh");
  OK(sc_set_mesh(m, 3, &c, 0));
  OK(mc_set_material(m, 3, 1.0, 0.3));
  OK(sc_fix_side(m, 3, &c, SC_BOTTOM, MC_XY, 0));
  OK(sc_fix_side(m, 2, &b, SC_BOTTOM, MC_XY, 0));
  OK(sc_fix_side(m, 1, &a, SC_TOP, MC_XY, 0));
  FAILS(mc_solve(m), MC_ERROR_STATE, "pair 1 has no surface on its mortar body 2");
  OK(mc_set_pair_surface(m, 1, 2, b.n_side_edges[SC_TOP], b.side_edges[SC_TOP]));
  /* the same non-mortar edge on a second pair */
  int second;
  OK(mc_add_contact_pair(m, 1, 3, &second));
  OK(mc_set_pair_surface(m, second, 1, 1, a.side_edges[SC_BOTTOM]));
  OK(mc_set_pair_surface(m, second, 3, c.n_side_edges[SC_TOP], c.side_edges[SC_TOP]));
  FAILS(mc_solve(m), MC_ERROR_CONTACT, "is on the non-mortar side of pair 1 and of pair 2");
  /* shrinking below a body a pair uses */
  FAILS(mc_set_body_count(m, 2), MC_ERROR_STATE, "pair 2 uses body 3");
  /* the two-body calls on a model whose pair 1 is (1, 2) still act on it; results before a solve */
  FAILS(mc_get_pair_contact_count(m, 1, &second), MC_ERROR_STATE, "no solution");
  FAILS(mc_get_pair_contact(m, 1, 99, NULL), MC_ERROR_ARGUMENT, "field = 99");
  mc_destroy(m);

  /* a model whose pair 1 joins bodies 2 and 3: the two-body calls are MC_ERROR_STATE */
  OK(mc_create(&m));
  OK(mc_set_body_count(m, 3));
  OK(sc_set_mesh(m, 2, &b, 0));
  OK(sc_set_mesh(m, 3, &c, 0));
  OK(mc_add_contact_pair(m, 2, 3, &pair));
  FAILS(mc_set_contact(m, 1, a.n_side_edges[SC_BOTTOM], a.side_edges[SC_BOTTOM]), MC_ERROR_STATE, "body 1 has no mesh");
  OK(sc_set_mesh(m, 1, &a, 0));
  FAILS(mc_set_contact(m, 1, a.n_side_edges[SC_BOTTOM], a.side_edges[SC_BOTTOM]), MC_ERROR_STATE, "joins bodies 2 and 3");
  FAILS(mc_set_contact(m, 3, c.n_side_edges[SC_TOP], c.side_edges[SC_TOP]), MC_ERROR_ARGUMENT, "acts on pair 1");
  mc_destroy(m);
  sc_mesh_free(&a), sc_mesh_free(&b), sc_mesh_free(&c);
}
END_TEST

static Suite *contact_pairs_suite(void) {
  Suite *s = suite_create("contact_pairs");
  TCase *tc = tcase_create("patch tests");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, stack_of_three_blocks_is_a_patch_test, 0, 16);
  tcase_add_loop_test(tc, block_pushed_into_a_corner_is_a_patch_test, 0, 8);
  tcase_add_loop_test(tc, stack_with_a_host_body_in_the_middle_is_a_patch_test, 0, 4);
  suite_add_tcase(s, tc);
  tc = tcase_create("invariance");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, old_calls_and_explicit_pair_one_agree_bit_for_bit, 0, 2);
  tcase_add_loop_test(tc, a_surface_split_into_two_pairs_gives_the_unsplit_answer, 0, 6);
  tcase_add_loop_test(tc, renumbered_bodies_and_reordered_pairs_change_nothing, 0, 2);
  tcase_add_loop_test(tc, forces_balance_per_pair_and_per_body, 0, 2);
  tcase_add_loop_test(tc, two_threads_give_the_serial_answer, 0, 2);
  suite_add_tcase(s, tc);
  tc = tcase_create("errors");
  tcase_add_test(tc, a_slide_no_pair_holds_is_singular);
  tcase_add_test(tc, bad_bodies_and_pairs_are_refused);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return sc_run_suite(contact_pairs_suite()); }
