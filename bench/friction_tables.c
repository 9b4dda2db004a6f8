/*
 * friction_tables.c - Coulomb friction against closed forms and published tables (issue 33;
 * docs/benchmarks.md, "Friction: closed forms and published tables").
 *
 * 1. block: the NAFEMS CGS-4-type inclined block. A block (1 x 0.5) on a foundation (2 x 0.5,
 *    its bottom clamped), the contact plane inclined at tan(alpha) = 0.1 (both meshes rotated by
 *    alpha about the origin), mu = 0.3, E = 1, nu = 0.3 for both. The block is held by contact
 *    alone and loaded by a uniform body force (F, -G) (F horizontal, pushing it up the slope; G
 *    vertical). It can be held as long as F/G < (tan(alpha) + mu) / (1 - mu tan(alpha)) =
 *    0.4 / 0.97 = 0.41237113...; above that nothing holds it along the slope. The limit is
 *    found by bisection on F/G: each trial is mc_reset_history and one solve (a proportional
 *    load from the unloaded state); a trial holds when the solve succeeds with at least one
 *    sticking row, and fails when the solve fails (MC_ERROR_SINGULAR: the block in full slip;
 *    any other failure is reported). Bisection to a bracket of 1e-14.
 * 2. ssnv128: Code_Aster SSNV128 (V6.04.128, modelling A): a square plate of side 0.04 (body 1,
 *    Q1, n x n cells, E = 1.3e11, nu = 0.2, plane strain) on a base 0.04 x 0.005 (body 2, Q1,
 *    E = 1.3e14 (1000x), nu = 0.2, bottom clamped) standing in for the rigid plane, mu = 1.0;
 *    pressure 5e7 on the plate's top, 15e7 on its left face, ramped together; the plate's right
 *    face held in x and its bottom-right corner in x and y (Code_Aster's PPS). Reported: the
 *    plate's DX at the contact points A..E (x = 0, 0.00125, 0.005, 0.0075, 0.01125) against the
 *    published reference (an average of other codes, Feijoo, Barbosa and Zouain; tolerance 5 %)
 *    and Code_Aster's own values (ssnv128a.comm, VALE_CALC). Path dependence: the loads ramped
 *    together in 1, 5 and 20 load steps against the same loads in two orders (the left face
 *    first, then the top: two solves; and the top first, then the left face).
 * 3. ssnv503: Code_Aster SSNV503 (V6.04.503), adapted: a pad 40 x 20 mm (body 1, E = 2.1e5,
 *    nu = 0) on a base 60 x 5 mm (body 2, E = 1e5, nu = 0, every node fixed: rigid), plane strain,
 *    mu = 0.3, Pn = 300 on the pad's top (Fn = 12000 N per mm of thickness), a tangential
 *    pressure Pt on its left face (20 mm) ramped together with Pn in 2 load steps. Code_Aster
 *    holds the pad with weak springs (k = 2 N/mm); here a soft elastic strip (10 mm long, E = 100,
 *    part of the pad's mesh, its far end clamped; about 200 N/mm) on the pad's right face does.
 *    Pt = 0.99 mu Pn: the pad sticks, tangential reaction (the base's support reactions)
 *    0.99 mu Fn = 3564; Pt = 1.01 mu Pn: it slips, friction force mu Fn = 3600, every row
 *    slipping; and 1.01 mu Pn without the strip: MC_ERROR_SINGULAR naming body 1. The same with
 *    Tresca friction, bound g = mu Pn = 90 (slip limit g x 40 = 3600 whatever the pressure),
 *    checked likewise (1.01: the friction force 3600 to 1e-10).
 * 4. tresca (checked; docs/benchmarks.md, "4. Tresca friction"): (a) the pad at 0.5 to 1.01 of its
 *    Tresca limit, every method, 8 x 4 to 32 x 16: converges; below the limit it sticks at the
 *    trailing end and the base and the strip carry the load; at 1.01 every row slips and the
 *    friction force is g x 40 to 1e-10; the Tresca conditions at every position (sticking:
 *    abs(shear) <= g and no slip; slipping: abs(shear) = g against the slip; open: abs(shear) <= g).
 *    (b) SSNV128's plate with a bound g = 1e6 to 1e16 instead of Coulomb, 1 and 5 load steps:
 *    converges, the conditions hold; once nothing slips (g >= 1e10) u no longer depends on g; a
 *    bound a tenth of the all-stick answer's smallest shear makes every row slip. (c) the pad at
 *    4 x 2: the same answer to 1e-10 whatever the way to it (1, 2, 3, 7 load steps; c_t; after
 *    another solve and mc_reset_history; a zero step from the answer; the sparse interface path).
 *    (d) brute force: on the pad at 4 x 2 (and 8 x 4 without --quick) every combination of row
 *    states is solved as a plain elasticity problem through the C API (node-to-segment's rows on
 *    the fixed flat base are the pad's bottom nodes: contact and stick fix u_y and u_x, slip adds
 *    the force -+g x tributary); exactly the combinations that satisfy their own assumptions are
 *    answers, and every method's contact solve, on both interface paths, must equal them to 1e-10.
 *
 * Methods: mortar and dual mortar on non-matching meshes, node-to-segment on matching ones.
 * Times: wall clock of mc_solve (median of --repeat runs); the machine may be loaded.
 *
 * usage: friction_tables [--quick] [--repeat N] [--base-factor F] [--cells P1|Q1|T6|Q8|Q9] [block|ssnv128|ssnv503|tresca ...]
 *   --base-factor  SSNV128's base: Young's modulus F times the plate's (default 1000)
 *   --cells        SSNV128's cells (default Q1; n cells per side, quadratic ones with mid-edge nodes)
 *   --quick  coarse meshes, one repeat, and exit status 1 unless every check passes (ctest
 *            bench_friction_tables_quick; it includes 4 at coarse meshes). Without scene names:
 *            all four (block, ssnv128, ssnv503, tresca).
 */
#include "bench_timing.h"
#include "mortarcontact.h"
#include "scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int quick = 0, repeat = 3, failures = 0;

#define CALL(call)                                                                    \
  do {                                                                                \
    if ((call) != MC_OK) {                                                            \
      fprintf(stderr, "friction_tables: %s failed: %s\n", #call, mc_errmsg(m));       \
      exit(1);                                                                        \
    }                                                                                 \
  } while (0)

static void check(int ok, const char *what) {
  if (!ok) {
    ++failures;
    printf("CHECK FAILED: %s\n", what);
  }
}

static const int methods[3] = {MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR, MC_METHOD_NODE_TO_SEGMENT};
static const char *const method_names[3] = {"mortar", "dual mortar", "node-to-segment"};

static int64_t info_int(mc_model *m, int info) {
  int64_t v = -1;
  mc_get_info_int(m, info, &v);
  return v;
}

static double info_real(mc_model *m, int info) {
  double v = NAN;
  mc_get_info_real(m, info, &v);
  return v;
}

static const char *status_name(mc_status s) {
  switch (s) {
    case MC_OK: return "ok";
    case MC_ERROR_SINGULAR: return "MC_ERROR_SINGULAR";
    case MC_ERROR_NOT_CONVERGED: return "MC_ERROR_NOT_CONVERGED";
    default: return mc_status_string(s);
  }
}

/* ---------------------------------------------------------------- 1. the inclined block */

static const double TAN_ALPHA = 0.1;

static void rotate(double *x, double *y, void *ctx) {
  const double c = ((double *)ctx)[0], s = ((double *)ctx)[1], x0 = *x, y0 = *y;
  *x = c * x0 - s * y0;
  *y = s * x0 + c * y0;
}

typedef struct block_scene {
  sc_mesh block, foundation;
  mc_model *m;
} block_scene;

/* nx cells along the block (ny = nx / 2); the foundation 2 wide from x = -0.5: matching (2 nx
   cells) or not (2 nx * 3 / 4 + 1 cells). */
static void block_build(block_scene *s, int method, int nx, int matching, double mu) {
  const int nxf = matching ? 2 * nx : (3 * nx) / 2 + 1, nyb = nx / 2 > 1 ? nx / 2 : 1;
  if (sc_mesh_rect(&s->block, 4, nx, nyb, 0, 0, 1, 0.5, 0, 1) ||
      sc_mesh_rect(&s->foundation, 4, nxf, nyb, -0.5, -0.5, 2, 0.5, 0, 1)) {
    fprintf(stderr, "friction_tables: block meshes\n");
    exit(1);
  }
  const double alpha = atan(TAN_ALPHA), cs[2] = {cos(alpha), sin(alpha)};
  sc_mesh_map(&s->block, rotate, (void *)cs);
  sc_mesh_map(&s->foundation, rotate, (void *)cs);
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(1);
  s->m = m;
  CALL(mc_set_plane(m, MC_PLANE_STRAIN, 1));
  CALL(sc_set_mesh(m, 1, &s->block, 0));
  CALL(sc_set_mesh(m, 2, &s->foundation, 0));
  CALL(mc_set_material(m, 1, 1, 0.3));
  CALL(mc_set_material(m, 2, 1, 0.3));
  CALL(sc_fix_side(m, 2, &s->foundation, SC_BOTTOM, MC_XY, 0));
  CALL(mc_set_contact(m, 1, s->block.n_side_edges[SC_BOTTOM], s->block.side_edges[SC_BOTTOM]));
  CALL(mc_set_contact(m, 2, s->foundation.n_side_edges[SC_TOP], s->foundation.side_edges[SC_TOP]));
  CALL(mc_set_option_int(m, MC_OPTION_METHOD, method));
  CALL(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0));
  CALL(mc_set_friction(m, 1, MC_FRICTION_COULOMB, mu));
}

static void block_free(block_scene *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->block), sc_mesh_free(&s->foundation);
}

typedef struct trial {
  mc_status status;
  int64_t stick, slip, iterations;
  double seconds;
  char msg[400];
} trial;

/* One trial at F/G = ratio (G = 1 per unit area): from the unloaded state, one solve. */
static trial block_trial(block_scene *s, double ratio) {
  mc_model *m = s->m;
  trial t;
  CALL(mc_reset_history(m));
  CALL(mc_set_body_force(m, 1, ratio, -1.0));
  const double t0 = bench_wall();
  t.status = mc_solve(m);
  t.seconds = bench_wall() - t0;
  snprintf(t.msg, sizeof t.msg, "%s", t.status == MC_OK ? "" : mc_errmsg(m));
  t.stick = t.status == MC_OK ? info_int(m, MC_INFO_STICK_NODES) : -1;
  t.slip = t.status == MC_OK ? info_int(m, MC_INFO_SLIP_NODES) : -1;
  t.iterations = info_int(m, MC_INFO_ITERATIONS);
  return t;
}

static char block_message[512] = "";

/* One row: the limit for one method, mesh and mu, by bisection. */
static void block_row(int k, int nx, double mu, int print_message) {
  const double exact = (TAN_ALPHA + mu) / (1 - mu * TAN_ALPHA);
  const int matching = methods[k] == MC_METHOD_NODE_TO_SEGMENT;
  block_scene s;
  block_build(&s, methods[k], nx, matching, mu);
  const double t0 = bench_wall();
  double lo = 0.75 * exact, hi = 1.25 * exact;
  trial at_lo = block_trial(&s, lo), at_hi = block_trial(&s, hi), first_fail = at_hi;
  const int64_t cold_iterations = at_lo.iterations; /* the first solve: no earlier states to start from */
  double times[160];
  int n_trials = 0;
  times[n_trials++] = at_lo.seconds, times[n_trials++] = at_hi.seconds;
  char what[200];
  if (at_lo.status != MC_OK || at_lo.stick <= 0 || at_hi.status == MC_OK) {
    printf("| %s | %g | %d | [0.75, 1.25] x the closed form is not a bracket: %s at the low end (%s), %s at the high end |\n",
           method_names[k], mu, nx, status_name(at_lo.status), at_lo.msg, status_name(at_hi.status));
    snprintf(what, sizeof what, "block %s nx=%d mu=%g: [0.75, 1.25] x the closed form brackets the limit", method_names[k], nx, mu);
    check(0, what);
    block_free(&s);
    return;
  }
  char fail_msg[512] = "";
  snprintf(fail_msg, sizeof fail_msg, "%s", at_hi.msg);
  while (hi - lo > 1e-14 * exact && n_trials < 120) {
    const double mid = 0.5 * (lo + hi);
    trial t = block_trial(&s, mid);
    times[n_trials++] = t.seconds;
    if (t.status == MC_OK && t.stick > 0) {
      lo = mid, at_lo = t;
    } else {
      if (t.status == MC_OK) printf("(a trial at %.15f solved with no sticking row)\n", mid);
      hi = mid, first_fail = t;
      snprintf(fail_msg, sizeof fail_msg, "%s", t.msg);
    }
  }
  const double total = bench_wall() - t0, limit = 0.5 * (lo + hi), err = (limit - exact) / exact;
  const mc_int dofs = (mc_int)info_int(s.m, MC_INFO_DOFS);
  printf("| %s | %s | %g | %d x %d | %ld | %.10f | %.14f | %+.1e | %d | %ld, %ld | %ld / %ld | %s | %.4f | %.2f |\n",
         method_names[k], matching ? "matching" : "non-matching", mu, nx, nx / 2 > 1 ? nx / 2 : 1, (long)dofs, exact, limit, err,
         n_trials, (long)cold_iterations, (long)at_lo.iterations, (long)at_lo.stick, (long)at_lo.slip,
         status_name(first_fail.status), bench_median(times, n_trials), total);
  if (print_message) snprintf(block_message, sizeof block_message, "%s", fail_msg);
  snprintf(what, sizeof what, "block %s nx=%d mu=%g: limit within 1e-10 (relative) of %.12f", method_names[k], nx, mu, exact);
  check(fabs(err) <= 1e-10, what);
  snprintf(what, sizeof what, "block %s nx=%d mu=%g: the failing side is MC_ERROR_SINGULAR", method_names[k], nx, mu);
  check(first_fail.status == MC_ERROR_SINGULAR, what);
  block_free(&s);
}

static void block_table(void) {
  const int sizes_full[3] = {4, 16, 64}, sizes_quick[2] = {4, 8};
  const int *sizes = quick ? sizes_quick : sizes_full, n_sizes = quick ? 2 : 3;
  const double mus[4] = {0.1, 0.6, 1.0, 2.0};
  printf("\n## 1. Inclined block (NAFEMS CGS-4 type): tan(alpha) = %g; closed form F/G = (tan(alpha) + mu) / (1 - mu "
         "tan(alpha))\n\n", TAN_ALPHA);
  printf("| method | meshes | mu | block cells | DOFs | closed form | limit F/G found | relative error | trials | iterations: first "
         "trial, last holding one | last holding trial: stick / slip rows | failing trials | solve (s, median) | bisection (s) |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < 3; ++k)
    for (int si = 0; si < n_sizes; ++si) block_row(k, sizes[si], 0.3, k == 0 && si == 0);
  /* other friction coefficients (mu tan(alpha) < 1), at one mesh */
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      if (!quick || j == 2) block_row(k, quick ? 4 : 16, mus[j], 0);
  printf("\nThe failing trials' message (mortar, the first mesh): %s\n", block_message);
}

/* ---------------------------------------------------------------- 2. SSNV128 */

static const double A128 = 0.04, E128 = 1.3e11, NU128 = 0.2, P_TOP = 5e7, P_LEFT = 15e7;
static const double X128[5] = {0, 0.00125, 0.005, 0.0075, 0.01125};
static const double REF128[5] = {2.86e-5, 2.72e-5, 2.28e-5, 1.98e-5, 1.50e-5};
static const double ASTER128[5] = {2.8648839013e-05, 2.72686641895e-05, 2.29235577257e-05, 1.99288812011e-05,
                                   1.56084651799e-05};
static double base_stiffness_factor = 1000;
static int plate_friction = 1; /* 0: the same scene without friction (a time reference) */
static int plate_law = MC_FRICTION_COULOMB;
static double plate_value = 1.0; /* mu, or the Tresca bound */
static int plate_npc = 4; /* --cells: P1 3, Q1 4, T6 6, Q8 8, Q9 9 (plate and base) */

typedef struct plate_scene {
  sc_mesh plate, base;
  mc_model *m;
} plate_scene;

static void plate_build(plate_scene *s, int method, int n, int matching) {
  const int nb = matching ? n : (4 * n) / 5 + 1;
  if (sc_mesh_cells(&s->plate, plate_npc, n, n, 0, 0, A128, A128, 0) ||
      sc_mesh_cells(&s->base, plate_npc, nb, 2, 0, -0.005, A128, 0.005, 0)) {
    fprintf(stderr, "friction_tables: plate meshes\n");
    exit(1);
  }
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(1);
  s->m = m;
  CALL(mc_set_plane(m, MC_PLANE_STRAIN, 1));
  CALL(sc_set_mesh(m, 1, &s->plate, 0));
  CALL(sc_set_mesh(m, 2, &s->base, 0));
  CALL(mc_set_material(m, 1, E128, NU128));
  CALL(mc_set_material(m, 2, base_stiffness_factor * E128, NU128));
  CALL(sc_fix_side(m, 2, &s->base, SC_BOTTOM, MC_XY, 0));
  CALL(sc_fix_side(m, 1, &s->plate, SC_RIGHT, MC_X, 0));
  const mc_int corner = s->plate.lattice[(plate_npc > 4 ? 2 : 1) * n]; /* (0.04, 0) */
  CALL(mc_fix(m, 1, 1, &corner, MC_XY, NULL));
  CALL(mc_set_contact(m, 1, s->plate.n_side_edges[SC_BOTTOM], s->plate.side_edges[SC_BOTTOM]));
  CALL(mc_set_contact(m, 2, s->base.n_side_edges[SC_TOP], s->base.side_edges[SC_TOP]));
  CALL(mc_set_option_int(m, MC_OPTION_METHOD, method));
  CALL(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0));
  if (plate_friction) CALL(mc_set_friction(m, 1, plate_law, plate_value));
}

static void plate_free(plate_scene *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->plate), sc_mesh_free(&s->base);
}

/* The plate's loads scaled: top pressure times st, left pressure times sl. */
static void plate_loads(plate_scene *s, double st, double sl) {
  mc_model *m = s->m;
  CALL(mc_clear_loads(m, 1));
  const sc_mesh *p = &s->plate;
  double *v = malloc(sizeof(double) * (size_t)(p->n_side_edges[SC_TOP] + p->n_side_edges[SC_LEFT]));
  for (mc_int e = 0; e < p->n_side_edges[SC_TOP]; ++e) v[e] = st * P_TOP;
  if (st != 0) CALL(mc_add_pressure(m, 1, p->n_side_edges[SC_TOP], p->side_edges[SC_TOP], v));
  for (mc_int e = 0; e < p->n_side_edges[SC_LEFT]; ++e) v[e] = sl * P_LEFT;
  if (sl != 0) CALL(mc_add_pressure(m, 1, p->n_side_edges[SC_LEFT], p->side_edges[SC_LEFT], v));
  free(v);
}

typedef struct plate_result {
  mc_status status;
  double dx[5];
  int64_t stick, slip, iterations, first_stick, first_slip;
  double seconds, first_seconds, fc;
  char msg[400];
} plate_result;

static void plate_read(plate_scene *s, int n, plate_result *r) {
  mc_model *m = s->m;
  r->stick = info_int(m, MC_INFO_STICK_NODES), r->slip = info_int(m, MC_INFO_SLIP_NODES);
  r->fc = info_real(m, MC_INFO_FRICTION_COMPLEMENTARITY);
  double *u = malloc(sizeof(double) * 2 * (size_t)s->plate.n_nodes);
  CALL(mc_get_displacement(m, 1, u));
  for (int k = 0; k < 5; ++k) {
    const int order = plate_npc > 4 ? 2 : 1, i = (int)lround(X128[k] / (A128 / (order * n)));
    r->dx[k] = u[2 * s->plate.lattice[i]]; /* lattice point (i, 0) */
  }
  free(u);
}

/* order 0: together in `steps` load steps; 1: the left face first, then the top (two solves,
   `steps` steps each); 2: the top first, then the left face. */
static plate_result plate_run(int method, int n, int matching, int steps, int order) {
  plate_scene s;
  plate_build(&s, method, n, matching);
  mc_model *m = s.m;
  plate_result r;
  memset(&r, 0, sizeof r);
  CALL(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, steps));
  double times[16];
  int reps = order == 0 ? repeat : 1;
  for (int rep = 0; rep < reps; ++rep) {
    CALL(mc_reset_history(m));
    double t0 = bench_wall();
    if (order == 0) {
      plate_loads(&s, 1, 1);
      r.status = mc_solve(m);
    } else {
      plate_loads(&s, order == 2, order == 1);
      r.status = mc_solve(m);
      if (r.status == MC_OK) {
        r.first_stick = info_int(m, MC_INFO_STICK_NODES), r.first_slip = info_int(m, MC_INFO_SLIP_NODES);
        plate_loads(&s, 1, 1);
        r.status = mc_solve(m);
      }
    }
    times[rep] = bench_wall() - t0;
    if (r.status != MC_OK) break;
    if (rep == 0) r.iterations = info_int(m, MC_INFO_ITERATIONS); /* cold: no earlier states to start from */
  }
  r.first_seconds = times[0];
  r.seconds = bench_median(times, reps);
  if (r.status == MC_OK)
    plate_read(&s, n, &r);
  else
    snprintf(r.msg, sizeof r.msg, "%s", mc_errmsg(m));
  plate_free(&s);
  return r;
}

static void plate_row(const char *method, const char *meshes, int n, const char *loading, const plate_result *r) {
  if (r->status != MC_OK) {
    printf("| %s | %s | %d | %s | %s: %.200s |\n", method, meshes, n, loading, status_name(r->status), r->msg);
    return;
  }
  printf("| %s | %s | %d | %s |", method, meshes, n, loading);
  for (int k = 0; k < 5; ++k) printf(" %.4e (%+.1f %%) |", r->dx[k], 100 * (r->dx[k] / REF128[k] - 1));
  printf(" %ld / %ld | %ld | %.1e | %.3f | %.3f |\n", (long)r->stick, (long)r->slip, (long)r->iterations, r->fc, r->first_seconds,
         r->seconds);
}

static void ssnv128_table(void) {
  static const char *const cell_names[10] = {"", "", "", "P1", "Q1", "", "T6", "", "Q8", "Q9"};
  printf("\n## 2. Code_Aster SSNV128: DX of the contact points (m), against the published reference (%s cells, base %g x E)\n\n",
         cell_names[plate_npc], base_stiffness_factor);
  printf("| method | meshes | n | loading | DX(A) x=0 | DX(B) x=0.00125 | DX(C) x=0.005 | DX(D) x=0.0075 | DX(E) x=0.01125 | "
         "stick / slip rows | iterations | friction compl. | first solve (s) | re-solve (s, median) |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  printf("| published reference | | | | ");
  for (int k = 0; k < 5; ++k) printf("%.3g | ", REF128[k]);
  printf("| | | | |\n| Code_Aster ssnv128a (QUAD4, penalty) | | | 5 increments | ");
  for (int k = 0; k < 5; ++k) printf("%.4e (%+.1f %%) | ", ASTER128[k], 100 * (ASTER128[k] / REF128[k] - 1));
  printf("| | | | |\n");
  const int sizes_full[3] = {32, 64, 128}, sizes_quick[1] = {32};
  const int *sizes = quick ? sizes_quick : sizes_full, n_sizes = quick ? 1 : 3;
  plate_result five[3][3];
  for (int k = 0; k < 3; ++k)
    for (int si = 0; si < n_sizes; ++si) {
      const int matching = methods[k] == MC_METHOD_NODE_TO_SEGMENT;
      plate_result r = plate_run(methods[k], sizes[si], matching, 5, 0);
      five[k][si] = r;
      plate_row(method_names[k], matching ? "matching" : "non-matching", sizes[si], "together, 5 steps", &r);
      plate_friction = 0;
      plate_result plain = plate_run(methods[k], sizes[si], matching, 1, 0);
      plate_friction = 1;
      plate_row(method_names[k], matching ? "matching" : "non-matching", sizes[si], "no friction (a time reference)", &plain);
      char what[160];
      snprintf(what, sizeof what, "ssnv128 %s n=%d: solves", method_names[k], sizes[si]);
      check(r.status == MC_OK, what);
      if (r.status != MC_OK) continue;
      for (int p = 0; p < 5; ++p) {
        snprintf(what, sizeof what, "ssnv128 %s n=%d: DX at x=%g within 5 %% of %g", method_names[k], sizes[si], X128[p], REF128[p]);
        check(fabs(r.dx[p] / REF128[p] - 1) <= 0.05, what);
      }
    }
  for (int si = 0; si < n_sizes; ++si) {
    double d_dual = 0, d_nts = 0;
    for (int p = 0; p < 5; ++p)
      if (five[0][si].status == MC_OK && five[1][si].status == MC_OK && five[2][si].status == MC_OK) {
        d_dual = fmax(d_dual, fabs(five[1][si].dx[p] / five[0][si].dx[p] - 1));
        d_nts = fmax(d_nts, fabs(five[2][si].dx[p] / five[0][si].dx[p] - 1));
      }
    printf("| n = %d: largest relative difference from mortar | | | | dual mortar %.1e, node-to-segment %.1e | | | | | | | | | |\n",
           sizes[si], d_dual, d_nts);
  }
  /* Path dependence, at the middle size (the coarse one in quick mode), every method. */
  const int n = quick ? 32 : 64, si_path = quick ? 0 : 1;
  printf("\n### Path dependence (n = %d)\n\n", n);
  printf("| method | meshes | n | loading | DX(A) x=0 | DX(B) x=0.00125 | DX(C) x=0.005 | DX(D) x=0.0075 | DX(E) x=0.01125 | "
         "stick / slip rows | iterations | friction compl. | first solve (s) | re-solve (s, median) |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < 3; ++k) {
    const int matching = methods[k] == MC_METHOD_NODE_TO_SEGMENT;
    const char *meshes = matching ? "matching" : "non-matching";
    const int steps[3] = {1, 5, 20};
    plate_result rs[3];
    for (int j = 0; j < 3; ++j) {
      rs[j] = j == 1 ? five[k][si_path] : plate_run(methods[k], n, matching, steps[j], 0);
      char loading[64];
      snprintf(loading, sizeof loading, "together, %d step%s", steps[j], steps[j] > 1 ? "s" : "");
      plate_row(method_names[k], meshes, n, loading, &rs[j]);
    }
    plate_result lf = plate_run(methods[k], n, matching, 1, 1), tf = plate_run(methods[k], n, matching, 1, 2);
    char loading[128];
    snprintf(loading, sizeof loading, "left face, then top (2 solves; the first: %ld stick / %ld slip)", (long)lf.first_stick,
             (long)lf.first_slip);
    plate_row(method_names[k], meshes, n, loading, &lf);
    snprintf(loading, sizeof loading, "top, then left face (2 solves; the first: %ld stick / %ld slip)", (long)tf.first_stick,
             (long)tf.first_slip);
    plate_row(method_names[k], meshes, n, loading, &tf);
    double d1 = 0, d20 = 0, dlf = 0, dtf = 0;
    int ok = rs[0].status == MC_OK && rs[1].status == MC_OK && rs[2].status == MC_OK;
    for (int p = 0; p < 5 && ok; ++p) {
      d1 = fmax(d1, fabs(rs[0].dx[p] / rs[1].dx[p] - 1)), d20 = fmax(d20, fabs(rs[2].dx[p] / rs[1].dx[p] - 1));
      if (lf.status == MC_OK) dlf = fmax(dlf, fabs(lf.dx[p] / rs[1].dx[p] - 1));
      if (tf.status == MC_OK) dtf = fmax(dtf, fabs(tf.dx[p] / rs[1].dx[p] - 1));
    }
    printf("| %s: largest relative difference from 5 steps | | | 1 step: %.1e, 20 steps: %.1e, left first: %.2e, top first: "
           "%.2e | | | | | | | | | | |\n",
           method_names[k], d1, d20, dlf, dtf);
    char what[160];
    snprintf(what, sizeof what, "ssnv128 %s: 1, 5 and 20 steps agree to 1e-8", method_names[k]);
    check(ok && d1 <= 1e-8 && d20 <= 1e-8, what);
    snprintf(what, sizeof what, "ssnv128 %s: both orders solve", method_names[k]);
    check(lf.status == MC_OK && tf.status == MC_OK, what);
  }
  /* A load cycle with slip reversals: one model, one solve per line (5 load steps each), each from
     the last converged state. */
  static const double cycle[8][2] = {{1, 1}, {1, 0}, {1, 1}, {1, -0.5}, {1, 1}, {0.2, 1}, {1, 1}, {0, 0}};
  printf("\n### A load cycle (n = %d, 5 load steps per solve, one model)\n\n", n);
  printf("| method | solve | top x 5e7, left x 15e7 | status | DX(A) x=0 | DX(E) x=0.01125 | stick / slip rows | iterations | "
         "friction compl. |\n|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < 3; ++k) {
    plate_scene ps;
    plate_build(&ps, methods[k], n, methods[k] == MC_METHOD_NODE_TO_SEGMENT);
    mc_model *m = ps.m;
    CALL(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, 5));
    int all_ok = 1;
    double last_dx = 1;
    for (int c = 0; c < 8; ++c) {
      plate_loads(&ps, cycle[c][0], cycle[c][1]);
      const mc_status st = mc_solve(ps.m);
      char msg[200];
      snprintf(msg, sizeof msg, "%s", st == MC_OK ? "ok" : mc_errmsg(ps.m));
      plate_result r;
      memset(&r, 0, sizeof r);
      if (st == MC_OK) {
        r.iterations = info_int(ps.m, MC_INFO_ITERATIONS);
        plate_read(&ps, n, &r);
        last_dx = fmax(fabs(r.dx[0]), fabs(r.dx[4]));
      }
      all_ok = all_ok && st == MC_OK;
      printf("| %s | %d | %g, %g | %.150s | %.5e | %.5e | %ld / %ld | %ld | %.1e |\n", method_names[k], c + 1, cycle[c][0],
             cycle[c][1], msg, r.dx[0], r.dx[4], (long)r.stick, (long)r.slip, (long)r.iterations, r.fc);
    }
    plate_free(&ps);
    char what[160];
    snprintf(what, sizeof what, "ssnv128 %s: every solve of the load cycle converges, and zero load gives u = 0", method_names[k]);
    check(all_ok && last_dx <= 1e-20, what);
  }
}

/* ---------------------------------------------------------------- 3. SSNV503 */

static const double PN = 300, MU503 = 0.3, PAD_W = 40, PAD_H = 20, STRIP_L = 10, STRIP_E = 100;
static int pad_contact = 1; /* 0: pad_build makes no contact surfaces and no friction (4d's frozen states) */

typedef struct pad_scene {
  sc_mesh pad, base;
  mc_model *m;
  mc_int n_contact_edges;
  mc_int *contact_edges;
} pad_scene;

/* Pn on the pad's top over 0 <= x <= 40 (the lateral pressure: pad_side_load). */
static void pad_top_load(pad_scene *s) {
  mc_model *m = s->m;
  mc_int n_top = 0;
  mc_int *top = malloc(sizeof(mc_int) * 2 * (size_t)s->pad.n_side_edges[SC_TOP]);
  for (mc_int e = 0; e < s->pad.n_side_edges[SC_TOP]; ++e) {
    const mc_int a = s->pad.side_edges[SC_TOP][2 * e], b = s->pad.side_edges[SC_TOP][2 * e + 1];
    if (s->pad.xy[2 * a] <= PAD_W + 1e-9 && s->pad.xy[2 * b] <= PAD_W + 1e-9) top[2 * n_top] = a, top[2 * n_top + 1] = b, ++n_top;
  }
  double *pn = malloc(sizeof(double) * (size_t)n_top);
  for (mc_int e = 0; e < n_top; ++e) pn[e] = PN;
  CALL(mc_add_pressure(m, 1, n_top, top, pn));
  free(pn), free(top);
}

/* nx cells along the pad (nx divisible by 4; ny = nx / 2); with_strip: the pad's mesh runs on to
   x = 50, cells beyond x = 40 soft, their right side clamped. */
static void pad_build(pad_scene *s, int method, int nx, int matching, int with_strip, int law) {
  const double h = PAD_W / nx;
  const int nxp = with_strip ? nx + (int)lround(STRIP_L / h) : nx, ny = nx / 2;
  const int nb = matching ? (int)lround(60 / h) : (int)lround(60 / h * 0.7) + 1;
  if (sc_mesh_rect(&s->pad, 4, nxp, ny, 0, 0, nxp * h, PAD_H, 0, 1) || sc_mesh_rect(&s->base, 4, nb, 2, -10, -5, 60, 5, 0, 1)) {
    fprintf(stderr, "friction_tables: pad meshes\n");
    exit(1);
  }
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(1);
  s->m = m;
  CALL(mc_set_plane(m, MC_PLANE_STRAIN, 1));
  CALL(sc_set_mesh(m, 1, &s->pad, 0));
  CALL(sc_set_mesh(m, 2, &s->base, 0));
  CALL(mc_set_material(m, 2, 1e5, 0));
  if (with_strip) {
    double pad_d[9], strip_d[9];
    sc_isotropic_law(2.1e5, 0, MC_PLANE_STRAIN, pad_d, NULL);
    sc_isotropic_law(STRIP_E, 0, MC_PLANE_STRAIN, strip_d, NULL);
    double *d = malloc(sizeof(double) * 9 * (size_t)s->pad.n_cells);
    for (mc_int c = 0; c < s->pad.n_cells; ++c) {
      const int i = (int)(c % nxp);
      memcpy(d + 9 * c, i < nx ? pad_d : strip_d, sizeof pad_d);
    }
    CALL(mc_set_cell_elasticity(m, 1, d));
    free(d);
    CALL(sc_fix_side(m, 1, &s->pad, SC_RIGHT, MC_XY, 0));
  } else {
    CALL(mc_set_material(m, 1, 2.1e5, 0));
  }
  /* every node of the base fixed (Code_Aster's BATI) */
  mc_int *all = malloc(sizeof(mc_int) * (size_t)s->base.n_nodes);
  for (mc_int v = 0; v < s->base.n_nodes; ++v) all[v] = v;
  CALL(mc_fix(m, 2, s->base.n_nodes, all, MC_XY, NULL));
  free(all);
  /* contact: the pad's bottom edges with x <= 40 (the first nx of its bottom side) */
  s->n_contact_edges = nx;
  s->contact_edges = s->pad.side_edges[SC_BOTTOM];
  CALL(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0));
  if (pad_contact) {
    CALL(mc_set_contact(m, 1, s->n_contact_edges, s->contact_edges));
    CALL(mc_set_contact(m, 2, s->base.n_side_edges[SC_TOP], s->base.side_edges[SC_TOP]));
    CALL(mc_set_option_int(m, MC_OPTION_METHOD, method));
    CALL(mc_set_friction(m, 1, law, law == MC_FRICTION_COULOMB ? MU503 : MU503 * PN));
    CALL(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, 2));
  }
  pad_top_load(s);
}

static void pad_free(pad_scene *s) {
  mc_destroy(s->m);
  sc_mesh_free(&s->pad), sc_mesh_free(&s->base);
}

typedef struct pad_result {
  mc_status status;
  double fn, ft, shear_dev, ux;
  int64_t stick, slip, iterations;
  double seconds;
  char msg[400];
} pad_result;

/* The lateral pressure on the pad's left face: Pt = factor mu Pn 40 / 20 (the tangential force
   factor mu Fn over the left face's 20 mm; Code_Aster's PRES = 178.2 and 181.8). */
static void pad_side_load(pad_scene *s, double factor) {
  mc_model *m = s->m;
  const sc_mesh *p = &s->pad;
  double *pt = malloc(sizeof(double) * (size_t)p->n_side_edges[SC_LEFT]);
  for (mc_int e = 0; e < p->n_side_edges[SC_LEFT]; ++e) pt[e] = factor * MU503 * PN * PAD_W / PAD_H;
  CALL(mc_add_pressure(m, 1, p->n_side_edges[SC_LEFT], p->side_edges[SC_LEFT], pt));
  free(pt);
}

/* After a successful solve: reactions, row counts, the slipping rows' deviation from the bound. */
static void pad_measure(pad_scene *s, int law, pad_result *r) {
  mc_model *m = s->m;
  const sc_mesh *p = &s->pad;
  r->stick = info_int(m, MC_INFO_STICK_NODES), r->slip = info_int(m, MC_INFO_SLIP_NODES);
  r->fn = r->ft = r->shear_dev = 0;
  double *reac = malloc(sizeof(double) * 2 * (size_t)s->base.n_nodes);
  CALL(mc_get_reaction(m, 2, reac));
  for (mc_int v = 0; v < s->base.n_nodes; ++v) r->ft -= reac[2 * v], r->fn += reac[2 * v + 1];
  free(reac);
  /* where a row slips with pressure, |shear| - mu p (largest deviation relative to mu Pn) */
  mc_int nc;
  CALL(mc_get_pair_contact_count(m, 1, &nc));
  double *pr = malloc(sizeof(double) * (size_t)nc), *sh = malloc(sizeof(double) * (size_t)nc),
         *st = malloc(sizeof(double) * (size_t)nc);
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, pr));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, sh));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_STATE, st));
  for (mc_int j = 0; j < nc; ++j)
    if (st[j] == MC_STATE_SLIP)
      r->shear_dev = fmax(r->shear_dev, fabs(fabs(sh[j]) - MU503 * (law == MC_FRICTION_COULOMB ? pr[j] : PN)) / (MU503 * PN));
  free(pr), free(sh), free(st);
  double *u = malloc(sizeof(double) * 2 * (size_t)p->n_nodes);
  CALL(mc_get_displacement(m, 1, u));
  r->ux = u[2 * sc_node(p, 0, 0)];
  free(u);
}

/* factor: Pt = factor mu Pn; from the unloaded state, Pn and Pt ramped together in 2 steps. */
static pad_result pad_run(int method, int nx, int matching, int with_strip, double factor, int law) {
  pad_scene s;
  pad_build(&s, method, nx, matching, with_strip, law);
  mc_model *m = s.m;
  pad_side_load(&s, factor);
  pad_result r;
  memset(&r, 0, sizeof r);
  double times[16];
  const int reps = repeat;
  for (int rep = 0; rep < reps; ++rep) {
    CALL(mc_reset_history(m));
    const double t0 = bench_wall();
    r.status = mc_solve(m);
    times[rep] = bench_wall() - t0;
    if (r.status != MC_OK) break;
    if (rep == 0) r.iterations = info_int(m, MC_INFO_ITERATIONS); /* cold */
  }
  r.seconds = r.status == MC_OK ? bench_median(times, reps) : times[0];
  if (r.status != MC_OK)
    snprintf(r.msg, sizeof r.msg, "%s", mc_errmsg(m));
  else
    pad_measure(&s, law, &r);
  pad_free(&s);
  return r;
}

static void ssnv503_table(void) {
  const double fn = PN * PAD_W;
  printf("\n## 3. SSNV503-like pad (plane strain): Fn = %g, mu Fn = %g\n\n", fn, MU503 * fn);
  printf("| method | law | meshes | pad cells | tangential load / (mu Fn) | holder | status | Fn (base reactions) | tangential reaction | expected | "
         "error | stick / slip rows | slip rows: max abs(abs(shear) - mu p) / (mu Pn) | DX of the pad's corner (mm) | "
         "iterations | solve (s) |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  printf("| Code_Aster ssnv503b (QUAD4, penalty) | Coulomb | | | 0.99 | springs | | 11999.98 | 3563.94 | 3564 | | | | | | |\n");
  printf("| Code_Aster ssnv503b (QUAD4, penalty) | Coulomb | | | 1.01 | springs | | 11999.98 | 3599.99 | 3600 | | | | | | |\n");
  const int sizes_full[3] = {8, 16, 32}, sizes_quick[1] = {8};
  const int *sizes = quick ? sizes_quick : sizes_full, n_sizes = quick ? 1 : 3;
  for (int k = 0; k < 3; ++k)
    for (int si = 0; si < n_sizes; ++si) {
      const int matching = methods[k] == MC_METHOD_NODE_TO_SEGMENT, nx = sizes[si];
      for (int c = 0; c < 5; ++c) {
        /* 0, 1: Coulomb, 0.99 and 1.01, the strip; 2: Coulomb 1.01 without it (the first mesh);
           3, 4: Tresca with the bound mu Pn = 90, 0.99 and 1.01 (its slip limit mu Pn 40 = 3600
           whatever the pressure's distribution) */
        const double factor = c == 0 || c == 3 ? 0.99 : 1.01;
        const int strip = c != 2, law = c < 3 ? MC_FRICTION_COULOMB : MC_FRICTION_TRESCA, sticks = c == 0 || c == 3;
        if (c == 2 && si > 0) continue;
        pad_result r = pad_run(methods[k], nx, matching, strip, factor, law);
        /* sticking: the tangential load (less the little the strip carries); slipping: mu times the
           normal force the base carries (Coulomb; the strip carries a little of Pn too), mu Pn 40
           (Tresca) */
        const double expected =
            sticks ? factor * MU503 * fn : law == MC_FRICTION_TRESCA ? MU503 * fn : MU503 * (r.status == MC_OK ? r.fn : fn);
        const char *law_name = law == MC_FRICTION_COULOMB ? "Coulomb" : "Tresca";
        if (r.status != MC_OK) {
          printf("| %s | %s | %s | %d x %d | %.2f | %s | %s: %.200s | | | | | | | | | %.3f |\n", method_names[k], law_name,
                 matching ? "matching" : "non-matching", nx, nx / 2, factor, strip ? "soft strip" : "none", status_name(r.status),
                 r.msg, r.seconds);
        } else {
          printf("| %s | %s | %s | %d x %d | %.2f | %s | ok | %.4f | %.4f | %.2f | %+.1e | %ld / %ld | %.1e | %.4g | %ld | %.4f |\n",
                 method_names[k], law_name, matching ? "matching" : "non-matching", nx, nx / 2, factor, strip ? "soft strip" : "none",
                 r.fn, r.ft, expected, r.ft / expected - 1, (long)r.stick, (long)r.slip, r.shear_dev, r.ux, (long)r.iterations,
                 r.seconds);
        }
        char what[200];
        if (sticks) {
          snprintf(what, sizeof what, "ssnv503 %s %s nx=%d: 0.99 sticks, tangential reaction within 0.1 %% of 3564", method_names[k],
                   law_name, nx);
          check(r.status == MC_OK && r.stick > 0 && fabs(r.ft / expected - 1) <= 1e-3, what);
        } else if (strip) {
          const double tol = law == MC_FRICTION_TRESCA ? 1e-10 : 1e-8;
          snprintf(what, sizeof what, "ssnv503 %s %s nx=%d: 1.01 slips everywhere, friction force to %g", method_names[k], law_name,
                   nx, tol);
          check(r.status == MC_OK && r.stick == 0 && fabs(r.ft / expected - 1) <= tol && r.shear_dev <= tol, what);
        } else {
          snprintf(what, sizeof what, "ssnv503 %s nx=%d: 1.01 without a holder is MC_ERROR_SINGULAR naming body 1", method_names[k], nx);
          check(r.status == MC_ERROR_SINGULAR && strstr(r.msg, "body 1") != NULL, what);
        }
        if (r.status == MC_OK) {
          snprintf(what, sizeof what, "ssnv503 %s %s nx=%d: Fn = 12000 to 1e-3 (the strip carries a little)", method_names[k], law_name,
                   nx);
          check(fabs(r.fn / fn - 1) <= 1e-3, what);
        }
      }
    }
}

/* ---------------------------------------------------------------- 4. Tresca friction */

/* The discrete Tresca conditions at the positions of pair 1 after a solve, bound g (a shear
   traction): sticking |shear| <= g and no slip; slipping |shear| = g, opposite to the slip; open
   (no pressure) |shear| <= g (a Tresca row carries its bound on the whole contact surface, in
   contact or not, and MC_CONTACT_STATE says only "open" there). */
typedef struct tresca_state {
  int n, stick, slip, open, wrong_sign;
  double stick_excess; /* max (|shear| - g) / g over sticking and open positions (<= 0: held) */
  double slip_dev;     /* max abs(|shear| - g) / g over slipping positions */
  double stick_slip;   /* max |slip| over sticking positions / max |u| of body 1 */
  double stick_lo, stick_hi; /* the sticking positions' x range */
} tresca_state;

static tresca_state tresca_read(mc_model *m, double g, const double *xy1, mc_int n1) {
  tresca_state t;
  memset(&t, 0, sizeof t);
  t.stick_excess = -INFINITY, t.stick_lo = INFINITY, t.stick_hi = -INFINITY;
  mc_int nc;
  CALL(mc_get_pair_contact_count(m, 1, &nc));
  double *sh = malloc(sizeof(double) * 4 * (size_t)nc), *sl = sh + nc, *st = sl + nc, *pr = st + nc;
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)nc);
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, sh));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_SLIP, sl));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_STATE, st));
  CALL(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, pr));
  CALL(mc_get_pair_contact_nodes(m, 1, nodes));
  /* the displacement scale: round-off in a slip is relative to it */
  double slip_ref = 0, *u = malloc(sizeof(double) * 2 * (size_t)n1);
  CALL(mc_get_displacement(m, 1, u));
  for (mc_int j = 0; j < 2 * n1; ++j) slip_ref = fmax(slip_ref, fabs(u[j]));
  free(u);
  t.n = (int)nc;
  for (mc_int j = 0; j < nc; ++j) {
    if (st[j] == MC_STATE_SLIP) {
      ++t.slip;
      t.slip_dev = fmax(t.slip_dev, fabs(fabs(sh[j]) - g) / g);
      if (sh[j] * sl[j] > 0 && fabs(sl[j]) > 1e-10 * slip_ref) ++t.wrong_sign;
    } else {
      if (st[j] == MC_STATE_STICK) {
        ++t.stick;
        if (slip_ref > 0) t.stick_slip = fmax(t.stick_slip, fabs(sl[j]) / slip_ref);
        const double x = xy1[2 * nodes[j]];
        t.stick_lo = fmin(t.stick_lo, x), t.stick_hi = fmax(t.stick_hi, x);
      } else {
        ++t.open;
      }
      t.stick_excess = fmax(t.stick_excess, (fabs(sh[j]) - g) / g);
    }
  }
  free(sh), free(nodes);
  return t;
}

static int tresca_ok(const tresca_state *t) {
  return t->stick_excess <= 1e-10 && t->slip_dev <= 1e-10 && t->stick_slip <= 1e-10 && t->wrong_sign == 0;
}

/* The same for a solve of several load steps: MC_CONTACT_SLIP is the slip of the whole solve,
   and a position that slipped in an early step and sticks in the last one (a Tresca row out of
   contact, which reports its stick or slip state) has slipped in this solve: only the bounds
   and the slipping rows' signs are checked then. */
static int tresca_ok_steps(const tresca_state *t, int steps) {
  if (steps == 1) return tresca_ok(t);
  return t->stick_excess <= 1e-10 && t->slip_dev <= 1e-10 && t->wrong_sign == 0;
}

static void tresca_state_cells(const tresca_state *t) {
  printf(" %d / %d / %d | %.1e | %.1e | %.1e | %d |", t->stick, t->slip, t->open, t->stick_excess > -INFINITY ? t->stick_excess : 0,
         t->slip_dev, t->stick_slip, t->wrong_sign);
}

/* Largest difference of two displacement fields, relative to the first's largest entry. */
static double field_diff(const double *a, const double *b, size_t n) {
  double d = 0, ref = 0;
  for (size_t i = 0; i < n; ++i) d = fmax(d, fabs(a[i] - b[i])), ref = fmax(ref, fabs(a[i]));
  return ref > 0 ? d / ref : d;
}

/* 4a. The pad with Tresca friction, bound g = mu Pn = 90: its slip limit g x 40 = 3600. */
static void tresca_pad_table(void) {
  const double g = MU503 * PN, limit = g * PAD_W;
  printf("\n## 4. Tresca friction (checked)\n\n### 4a. The SSNV503-like pad, bound g = %g (slip limit g x 40 = %g), 2 load steps\n\n", g,
         limit);
  printf("| method | pad cells | load / (g x 40) | status | tangential reaction (base) | load - strip's share | expected | error | "
         "stick / slip / open positions | stick, open: max (abs(shear) - g)/g | slip: max abs(abs(shear) - g)/g | "
         "stick: max abs(slip) / max abs(u) | slip with the shear's sign | sticking x range | iterations |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const int sizes_full[3] = {8, 16, 32}, sizes_quick[1] = {8};
  const int *sizes = quick ? sizes_quick : sizes_full, n_sizes = quick ? 1 : 3;
  static const double fs[6] = {0.5, 0.8, 0.9, 0.95, 0.99, 1.01};
  for (int k = 0; k < 3; ++k)
    for (int si = 0; si < n_sizes; ++si)
      for (int i = 0; i < 6; ++i) {
        const int matching = methods[k] == MC_METHOD_NODE_TO_SEGMENT, nx = sizes[si];
        pad_scene s;
        pad_build(&s, methods[k], nx, matching, 1, MC_FRICTION_TRESCA);
        pad_side_load(&s, fs[i]);
        mc_model *m = s.m;
        pad_result r;
        memset(&r, 0, sizeof r);
        r.status = mc_solve(m);
        char what[240];
        snprintf(what, sizeof what, "tresca pad %s nx=%d %.2f: solves", method_names[k], nx, fs[i]);
        check(r.status == MC_OK, what);
        if (r.status != MC_OK) {
          printf("| %s | %d x %d | %.2f | %s: %.200s | | | | | | | | | | | |\n", method_names[k], nx, nx / 2, fs[i],
                 status_name(r.status), mc_errmsg(s.m));
          pad_free(&s);
          continue;
        }
        r.iterations = info_int(s.m, MC_INFO_ITERATIONS);
        pad_measure(&s, MC_FRICTION_TRESCA, &r);
        double *reac = malloc(sizeof(double) * 2 * (size_t)s.pad.n_nodes), strip = 0;
        CALL(mc_get_reaction(s.m, 1, reac));
        for (mc_int v = 0; v < s.pad.n_nodes; ++v) strip += reac[2 * v];
        free(reac);
        const tresca_state t = tresca_read(s.m, g, s.pad.xy, s.pad.n_nodes);
        const double load = fs[i] * limit, expected = fs[i] < 1 ? load : limit;
        printf("| %s | %d x %d | %.2f | ok | %.6f | %.6f | %.2f | %+.1e |", method_names[k], nx, nx / 2, fs[i], r.ft, load + strip, expected,
               r.ft / expected - 1);
        tresca_state_cells(&t);
        if (t.stick)
          printf(" %g to %g |", t.stick_lo, t.stick_hi);
        else
          printf(" none |");
        printf(" %ld |\n", (long)r.iterations);
        snprintf(what, sizeof what, "tresca pad %s nx=%d %.2f: the Tresca conditions at every position (1e-10)", method_names[k], nx,
                 fs[i]);
        check(tresca_ok(&t), what);
        snprintf(what, sizeof what, "tresca pad %s nx=%d %.2f: the base and the strip carry the load (1e-9)", method_names[k], nx, fs[i]);
        check(fabs(r.ft - (load + strip)) <= 1e-9 * load, what);
        if (fs[i] < 1) {
          snprintf(what, sizeof what, "tresca pad %s nx=%d %.2f: sticks (at the trailing end), the base carries the load to 1e-3",
                   method_names[k], nx, fs[i]);
          check(r.stick > 0 && t.stick > 0 && t.stick_hi >= PAD_W - 1e-9 && fabs(r.ft / load - 1) <= 1e-3, what);
        } else {
          snprintf(what, sizeof what, "tresca pad %s nx=%d %.2f: every row slips, friction force g x 40 to 1e-10", method_names[k], nx,
                   fs[i]);
          check(r.stick == 0 && t.stick == 0 && fabs(r.ft / limit - 1) <= 1e-10, what);
        }
        pad_free(&s);
      }
}

/* 4b. SSNV128 with a Tresca bound g instead of Coulomb. */
typedef struct plate_tresca {
  mc_status status;
  double dx[5], *u;
  tresca_state t;
  int64_t stick, slip, iterations;
  double min_shear; /* smallest |shear| over the positions */
  size_t nu;        /* entries of u */
  char msg[300];
} plate_tresca;

static plate_tresca plate_tresca_run(int method, int n, int law, double value, int steps) {
  plate_law = law, plate_value = value;
  plate_scene s;
  plate_build(&s, method, n, method == MC_METHOD_NODE_TO_SEGMENT);
  plate_law = MC_FRICTION_COULOMB, plate_value = 1.0;
  mc_model *m = s.m;
  plate_tresca r;
  memset(&r, 0, sizeof r);
  CALL(mc_set_option_int(s.m, MC_OPTION_LOAD_STEPS, steps));
  plate_loads(&s, 1, 1);
  r.status = mc_solve(s.m);
  snprintf(r.msg, sizeof r.msg, "%s", r.status == MC_OK ? "" : mc_errmsg(s.m));
  r.iterations = info_int(s.m, MC_INFO_ITERATIONS);
  if (r.status != MC_OK) {
    plate_free(&s);
    return r;
  }
  plate_result pr;
  plate_read(&s, n, &pr);
  memcpy(r.dx, pr.dx, sizeof r.dx);
  r.stick = pr.stick, r.slip = pr.slip;
  r.nu = 2 * (size_t)s.plate.n_nodes;
  r.u = malloc(sizeof(double) * r.nu);
  CALL(mc_get_displacement(s.m, 1, r.u));
  if (law == MC_FRICTION_TRESCA) r.t = tresca_read(s.m, value, s.plate.xy, s.plate.n_nodes);
  mc_int nc;
  CALL(mc_get_pair_contact_count(s.m, 1, &nc));
  double *sh = malloc(sizeof(double) * (size_t)nc);
  CALL(mc_get_pair_contact(s.m, 1, MC_CONTACT_SHEAR, sh));
  r.min_shear = INFINITY;
  for (mc_int j = 0; j < nc; ++j) r.min_shear = fmin(r.min_shear, fabs(sh[j]));
  free(sh);
  plate_free(&s);
  return r;
}

static void tresca_plate_table(void) {
  const int n = quick ? 16 : 32;
  printf("\n### 4b. Code_Aster SSNV128's plate with a Tresca bound g instead of Coulomb (n = %d, the loads together)\n\n", n);
  printf("| method | g | load steps | status | DX(A) x=0 | DX(E) x=0.01125 | stick / slip rows (MC_INFO) | stick / slip / open positions | "
         "stick, open: max (abs(shear) - g)/g | slip: max abs(abs(shear) - g)/g | stick: max abs(slip) / max abs(u) | slip with "
         "the shear's sign | u: max difference from 1 step | iterations |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  /* g_first_stuck on: nothing slips, and the answer must no longer depend on g */
  static const double gs[9] = {1e6, 1e7, 2e7, 3e7, 5e7, 1e8, 1e10, 1e13, 1e16};
  const int ng = 9, g_first_stuck = 6, g_ref = 7;
  size_t nn = 0; /* entries of u (every run of one method has the same meshes) */
  for (int k = 0; k < 3; ++k) {
    double *u_big = NULL, min_shear_big = 0, d_stuck = 0;
    double *u_stuck[9] = {NULL};
    for (int i = 0; i < ng; ++i) {
      double *u1 = NULL;
      for (int steps = 1; steps <= 5; steps += 4) {
        plate_tresca r = plate_tresca_run(methods[k], n, MC_FRICTION_TRESCA, gs[i], steps);
        char what[200];
        snprintf(what, sizeof what, "tresca ssnv128 %s g=%g %d steps: solves, the Tresca conditions (1e-10)", method_names[k], gs[i],
                 steps);
        check(r.status == MC_OK && tresca_ok_steps(&r.t, steps), what);
        if (r.status != MC_OK) {
          printf("| %s | %g | %d | %s: %.200s | | | | | | | | | | %ld |\n", method_names[k], gs[i], steps, status_name(r.status), r.msg,
                 (long)r.iterations);
          continue;
        }
        nn = r.nu;
        const double d = u1 ? field_diff(u1, r.u, nn) : 0;
        printf("| %s | %g | %d | ok | %.6e | %.6e | %ld / %ld |", method_names[k], gs[i], steps, r.dx[0], r.dx[4], (long)r.stick,
               (long)r.slip);
        tresca_state_cells(&r.t);
        printf(" %.1e | %ld |\n", d, (long)r.iterations);
        if (i >= g_first_stuck) {
          snprintf(what, sizeof what, "tresca ssnv128 %s g=%g %d steps: nothing slips", method_names[k], gs[i], steps);
          check(r.slip == 0 && r.t.slip == 0, what);
        }
        if (i == g_ref && steps == 1) min_shear_big = r.min_shear;
        if (u1) {
          /* Not 1e-10: the step-by-step problem is an evolution, and a row that slips in an early
             increment may stop (stick below g) in a later one, which the one-step answer does
             not see (n = 16, g = 1e7 and 2e7: an open row, 1e-7). The one answer of one step is
             checked in 4c. */
          snprintf(what, sizeof what, "tresca ssnv128 %s g=%g: 1 and 5 load steps agree to 1e-6", method_names[k], gs[i]);
          check(d <= 1e-6, what);
          free(r.u);
        } else {
          u1 = r.u;
        }
      }
      if (i >= g_first_stuck)
        u_stuck[i] = u1;
      else
        free(u1);
    }
    u_big = u_stuck[g_ref];
    for (int i = g_first_stuck; i < ng; ++i)
      d_stuck = u_big && u_stuck[i] ? fmax(d_stuck, field_diff(u_big, u_stuck[i], nn)) : INFINITY;
    printf("| %s: g = %g to %g (nothing slips): largest difference of u from g = %g | | | | | | | | | | | | %.1e | |\n", method_names[k],
           gs[g_first_stuck], gs[ng - 1], gs[g_ref], d_stuck);
    char what[200];
    snprintf(what, sizeof what, "tresca ssnv128 %s: once nothing slips (g = %g to %g) u does not depend on g (1e-10)", method_names[k],
             gs[g_first_stuck], gs[ng - 1]);
    check(d_stuck <= 1e-10, what);
    for (int i = g_first_stuck; i < ng; ++i)
      if (i != g_ref) free(u_stuck[i]);
    if (!u_big) continue;
    /* Coulomb with a large mu, for comparison (not checked: an open row is free under Coulomb,
       tied under Tresca; docs/robustness.md, "Friction") */
    static const double mus[2] = {10, 100};
    for (int j = 0; j < 2; ++j) {
      plate_tresca c = plate_tresca_run(methods[k], n, MC_FRICTION_COULOMB, mus[j], 1);
      if (c.status == MC_OK)
        printf("| %s | Coulomb mu = %g (not checked) | 1 | ok | %.6e | %.6e | %ld / %ld | | | | | | from g = %g: %.1e | %ld |\n",
               method_names[k], mus[j], c.dx[0], c.dx[4], (long)c.stick, (long)c.slip, gs[g_ref], field_diff(u_big, c.u, nn),
               (long)c.iterations);
      else
        printf("| %s | Coulomb mu = %g (not checked) | 1 | %s: %.200s | | | | | | | | | | %ld |\n", method_names[k], mus[j],
               status_name(c.status), c.msg, (long)c.iterations);
      free(c.u);
    }
    /* a bound well below every |shear| of the all-stick answer (a tenth of the smallest): every
       row slips at |shear| = g */
    /* (half of it is not always enough: at n = 16 an open row then sticks; the answer
       redistributes, so "below every all-stick shear" does not by itself make every row slip) */
    const double g_small = 0.1 * min_shear_big;
    plate_tresca r = plate_tresca_run(methods[k], n, MC_FRICTION_TRESCA, g_small, 1);
    if (r.status == MC_OK) {
      printf("| %s | %.4g (a tenth of the all-stick answer's smallest abs(shear)) | 1 | ok | %.6e | %.6e | %ld / %ld |", method_names[k], g_small,
             r.dx[0], r.dx[4], (long)r.stick, (long)r.slip);
      tresca_state_cells(&r.t);
      printf(" | %ld |\n", (long)r.iterations);
    } else {
      printf("| %s | %.4g | 1 | %s: %.200s | | | | | | | | | | |\n", method_names[k], g_small, status_name(r.status), r.msg);
    }
    snprintf(what, sizeof what, "tresca ssnv128 %s g=%.3g (below every all-stick shear): every row slips at abs(shear) = g (1e-10)",
             method_names[k], g_small);
    check(r.status == MC_OK && r.stick == 0 && r.t.stick == 0 && tresca_ok(&r.t), what);
    free(r.u);
    free(u_big);
  }
}

/* 4c. Uniqueness on a tiny mesh: the pad at 4 x 2 cells (5 contact positions). The convex Tresca
   problem has one answer; whatever path the stick/slip iteration takes to it (load steps, c_t,
   what was solved before mc_reset_history) it must end there, and satisfy the conditions. */
static void tresca_unique_table(void) {
  const double g = MU503 * PN;
  const int nx = 4;
  printf("\n### 4c. One answer: the pad at %d x %d cells, every way to reach it (bound g = %g)\n\n", nx, nx / 2, g);
  printf("| method | load / (g x 40) | way | status | stick / slip / open positions | stick, open: max (abs(shear) - g)/g | slip: max "
         "abs(abs(shear) - g)/g | stick: max abs(slip) / max abs(u) | slip with the shear's sign | u: max difference from 1 step | "
         "shear: max difference / g | iterations |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  static const double fs[3] = {0.5, 0.99, 1.01};
  enum { N_WAYS = 9 };
  static const char *const ways[N_WAYS] = {"1 step",
                                           "2 steps",
                                           "3 steps",
                                           "7 steps",
                                           "c_t = 1e-3",
                                           "c_t = 1e3",
                                           "c_t = 1e9",
                                           "after solving -0.8 (reversed) and mc_reset_history",
                                           "a second solve, no load change (a zero step from the answer)"};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      pad_scene s;
      pad_build(&s, methods[k], nx, methods[k] == MC_METHOD_NODE_TO_SEGMENT, 1, MC_FRICTION_TRESCA);
      mc_model *m = s.m;
      const size_t nu = 2 * (size_t)s.pad.n_nodes;
      mc_int nc;
      double *u_ref = malloc(sizeof(double) * nu), *u = malloc(sizeof(double) * nu), *sh_ref = NULL, *sh = NULL;
      int all_ok = 1;
      double worst_u = 0, worst_sh = 0;
      for (int w = 0; w < N_WAYS; ++w) {
        CALL(mc_set_option_real(m, MC_OPTION_FRICTION_CT, w == 4 ? 1e-3 : w == 5 ? 1e3 : w == 6 ? 1e9 : 0));
        CALL(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, w == 1 ? 2 : w == 2 ? 3 : w == 3 ? 7 : 1));
        if (w == 7) {
          CALL(mc_reset_history(m));
          CALL(mc_clear_loads(m, 1));
          pad_top_load(&s);
          pad_side_load(&s, -0.8);
          if (mc_solve(m) != MC_OK) all_ok = 0;
          CALL(mc_clear_loads(m, 1));
          pad_top_load(&s);
          pad_side_load(&s, fs[i]);
        } else if (w == 0) {
          pad_side_load(&s, fs[i]);
        }
        if (w != 8) CALL(mc_reset_history(m));
        const mc_status st = mc_solve(m);
        const int64_t iterations = info_int(m, MC_INFO_ITERATIONS);
        if (st != MC_OK) {
          all_ok = 0;
          printf("| %s | %.2f | %s | %s: %.200s | | | | | | | | %ld |\n", method_names[k], fs[i], ways[w], status_name(st), mc_errmsg(m),
                 (long)iterations);
          continue;
        }
        const tresca_state t = tresca_read(m, g, s.pad.xy, s.pad.n_nodes);
        CALL(mc_get_pair_contact_count(m, 1, &nc));
        if (!sh_ref) sh_ref = malloc(sizeof(double) * (size_t)nc), sh = malloc(sizeof(double) * (size_t)nc);
        CALL(mc_get_displacement(m, 1, w == 0 ? u_ref : u));
        CALL(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, w == 0 ? sh_ref : sh));
        double du = 0, dsh = 0;
        if (w > 0) {
          du = field_diff(u_ref, u, nu);
          for (mc_int j = 0; j < nc; ++j) dsh = fmax(dsh, fabs(sh[j] - sh_ref[j]) / g);
        }
        worst_u = fmax(worst_u, du), worst_sh = fmax(worst_sh, dsh);
        all_ok = all_ok && tresca_ok(&t);
        printf("| %s | %.2f | %s | ok |", method_names[k], fs[i], ways[w]);
        tresca_state_cells(&t);
        printf(" %.1e | %.1e | %ld |\n", du, dsh, (long)iterations);
      }
      char what[200];
      snprintf(what, sizeof what, "tresca 4x2 %s %.2f: every way solves, the conditions hold, one answer (u and shear to 1e-10)",
               method_names[k], fs[i]);
      check(all_ok && worst_u <= 1e-10 && worst_sh <= 1e-10, what);
      /* the sparse interface path: the same answer */
      if (i == 0) {
        CALL(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, MC_INTERFACE_SPARSE));
        CALL(mc_reset_history(m));
        const mc_status st = mc_solve(m);
        double du = INFINITY;
        if (st == MC_OK) {
          CALL(mc_get_displacement(m, 1, u));
          du = field_diff(u_ref, u, nu);
        }
        printf("| %s | %.2f | MC_OPTION_INTERFACE_SOLVER = MC_INTERFACE_SPARSE | %s %.200s | | | | | | %.1e | | |\n",
               method_names[k], fs[i], st == MC_OK ? "ok" : status_name(st), st == MC_OK ? "" : mc_errmsg(m), du);
        snprintf(what, sizeof what, "tresca 4x2 %s: the sparse interface path gives the same answer (1e-10)", method_names[k]);
        check(st == MC_OK && du <= 1e-10, what);
      }
      free(u_ref), free(u), free(sh_ref), free(sh);
      pad_free(&s);
    }
}

/* 4d. Brute force: the pad at 4 x 2 cells, node-to-segment on matching meshes. The base is fixed
   and flat, so node-to-segment's rows are the pad's 5 bottom nodes themselves: row r's gap is
   u_y, its slip u_x, its Tresca force g times its tributary length (5, 10, 10, 10, 5). Each
   combination of states (per row: contact or open, and stick, slip + or slip -) is then a plain
   elasticity problem of the pad alone, which the C API solves: contact fixes u_y = 0, stick fixes
   u_x = 0, slip + (-) adds the nodal force -(+) g x tributary in x. A combination is an answer
   when its solution satisfies what it assumed: contact rows pushed (reaction y >= 0), open rows
   not penetrating (u_y >= 0), sticking rows within the bound (abs(reaction x) <= g x tributary),
   slipping rows moving with their sign. Every combination is solved (6^5 = 7776); those that
   are answers must agree, and the contact solve's answer (every method, one load step) must be
   theirs. Without --quick also the pad at 8 x 4 cells (9 rows), its rows all in contact (the
   pressed pad's answer has none open): the 3^9 = 19683 tangential combinations. */
static void tresca_brute_force(int nx, int with_open) {
  const int np = nx + 1, nt = with_open ? 2 : 1;
  const double g = MU503 * PN, h = PAD_W / nx;
  int n_comb = 1;
  for (int r = 0; r < np; ++r) n_comb *= 3 * nt;
  printf("\n### 4d. Brute force: the pad at %d x %d cells, every combination of row states (%d%s), bound g = %g\n\n", nx, nx / 2, n_comb,
         with_open ? "" : ", every row in contact", g);
  printf("| load / (g x 40) | combinations solved | answers among them | the answer's states (x = 0 to 40) | answers: max difference of u | "
         "mortar, condensed | sparse | dual mortar, condensed | sparse | node-to-segment, condensed | sparse | brute force (s) |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  static const double fs[3] = {0.5, 0.99, 1.01};
  for (int i = 0; i < 3; ++i) {
    const double t0 = bench_wall();
    double *u_ans = NULL, d_ans = 0;
    int n_ans = 0, n_solved = 0;
    char states[256] = "";
    size_t nu = 0;
    for (int c = 0; c < n_comb; ++c) {
      pad_scene s;
      pad_contact = 0;
      pad_build(&s, MC_METHOD_NODE_TO_SEGMENT, nx, 1, 1, MC_FRICTION_TRESCA);
      pad_contact = 1;
      mc_model *m = s.m;
      pad_side_load(&s, fs[i]);
      int normal[16], tangent[16];
      mc_int nodes[16];
      for (int r = 0, code = c; r < np; ++r, code /= 3 * nt) {
        normal[r] = nt == 1 ? 0 : (code % (3 * nt)) / 3; /* 0 contact, 1 open */
        tangent[r] = code % 3;                          /* 0 stick, 1 slip +, 2 slip - */
        nodes[r] = sc_node(&s.pad, r, 0);
        const int comps = (normal[r] == 0 ? MC_Y : 0) | (tangent[r] == 0 ? MC_X : 0);
        if (comps) CALL(mc_fix(m, 1, 1, &nodes[r], comps, NULL));
        if (tangent[r]) {
          const double trib = r == 0 || r == nx ? h / 2 : h, f[2] = {(tangent[r] == 1 ? -1 : 1) * g * trib, 0};
          CALL(mc_add_nodal_force(m, 1, 1, &nodes[r], f));
        }
      }
      if (mc_solve(m) != MC_OK) { /* e.g. nothing holds the pad vertically: not an answer */
        pad_free(&s);
        continue;
      }
      ++n_solved;
      nu = 2 * (size_t)s.pad.n_nodes;
      double *u = malloc(sizeof(double) * nu), *reac = malloc(sizeof(double) * nu), u_max = 0;
      CALL(mc_get_displacement(m, 1, u));
      CALL(mc_get_reaction(m, 1, reac));
      for (size_t k = 0; k < nu; ++k) u_max = fmax(u_max, fabs(u[k]));
      const double tol_u = 1e-9 * u_max, tol_f = 1e-9 * g * h;
      int is_answer = 1;
      for (int r = 0; r < np && is_answer; ++r) {
        const double ux = u[2 * nodes[r]], uy = u[2 * nodes[r] + 1], rx = reac[2 * nodes[r]], ry = reac[2 * nodes[r] + 1];
        const double trib = r == 0 || r == nx ? h / 2 : h;
        if (normal[r] == 0 ? ry < -tol_f : uy < -tol_u) is_answer = 0;
        if (tangent[r] == 0 ? fabs(rx) > g * trib + tol_f : tangent[r] == 1 ? ux < -tol_u : ux > tol_u) is_answer = 0;
      }
      if (is_answer) {
        ++n_ans;
        if (!u_ans) {
          u_ans = u, u = NULL;
          char *p = states;
          for (int r = 0; r < np; ++r)
            p += sprintf(p, "%s%s%s", r ? ", " : "", normal[r] ? "open " : "", tangent[r] == 0 ? "stick" : tangent[r] == 1 ? "slip +" : "slip -");
        } else {
          d_ans = fmax(d_ans, field_diff(u_ans, u, nu));
        }
      }
      free(u), free(reac);
      pad_free(&s);
    }
    const double seconds = bench_wall() - t0;
    printf("| %.2f | %d | %d | %s | %.1e |", fs[i], n_solved, n_ans, states, d_ans);
    char what[200];
    snprintf(what, sizeof what, "tresca brute force nx=%d %.2f: at least one combination is an answer, and all such agree (1e-9)", nx,
             fs[i]);
    check(n_ans >= 1 && d_ans <= 1e-9, what);
    for (int k = 0; k < 6; ++k) {  /* each method on both interface paths */
      const int method = methods[k / 2], sparse = k % 2;
      pad_scene s;
      pad_build(&s, method, nx, method == MC_METHOD_NODE_TO_SEGMENT, 1, MC_FRICTION_TRESCA);
      mc_model *m = s.m;
      CALL(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, 1));
      CALL(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, sparse ? MC_INTERFACE_SPARSE : MC_INTERFACE_CONDENSED));
      pad_side_load(&s, fs[i]);
      const mc_status st = mc_solve(m);
      double d = INFINITY;
      if (st == MC_OK && u_ans) {
        double *u = malloc(sizeof(double) * nu);
        CALL(mc_get_displacement(m, 1, u));
        d = field_diff(u_ans, u, nu);
        free(u);
      }
      printf(" %s %.1e |", st == MC_OK ? "ok," : status_name(st), d);
      snprintf(what, sizeof what, "tresca brute force nx=%d %.2f: the %s contact solve (%s path) is the brute-force answer (1e-10)",
               nx, fs[i], method_names[k / 2], sparse ? "sparse" : "condensed");
      check(d <= 1e-10, what);
      pad_free(&s);
    }
    printf(" %.2f |\n", seconds);
    free(u_ans);
  }
}

static void tresca_table(void) {
  tresca_pad_table();
  tresca_plate_table();
  tresca_unique_table();
  tresca_brute_force(4, 1);
  if (!quick) tresca_brute_force(8, 0);
}

int main(int argc, char **argv) {
  int want[4] = {0, 0, 0, 0}, any = 0;
  for (int a = 1; a < argc; ++a) {
    if (!strcmp(argv[a], "--quick")) {
      quick = 1, repeat = 1;
    } else if (!strcmp(argv[a], "--repeat") && a + 1 < argc) {
      repeat = atoi(argv[++a]);
      if (repeat < 1 || repeat > 16) goto usage;
    } else if (!strcmp(argv[a], "--cells") && a + 1 < argc) {
      const char *c = argv[++a];
      plate_npc = !strcmp(c, "P1") ? 3 : !strcmp(c, "Q1") ? 4 : !strcmp(c, "T6") ? 6 : !strcmp(c, "Q8") ? 8 : !strcmp(c, "Q9") ? 9 : 0;
      if (!plate_npc) goto usage;
    } else if (!strcmp(argv[a], "--base-factor") && a + 1 < argc) {
      base_stiffness_factor = atof(argv[++a]);
    } else if (!strcmp(argv[a], "block")) {
      want[0] = any = 1;
    } else if (!strcmp(argv[a], "ssnv128")) {
      want[1] = any = 1;
    } else if (!strcmp(argv[a], "ssnv503")) {
      want[2] = any = 1;
    } else if (!strcmp(argv[a], "tresca")) {
      want[3] = any = 1;
    } else {
      goto usage;
    }
  }
  if (quick) repeat = 1;
  if (!any) want[0] = want[1] = want[2] = want[3] = 1;
  printf("friction_tables%s: mortarcontact %s, repeat %d\n", quick ? " --quick" : "", mc_version_string(), repeat);
  if (want[0]) block_table();
  if (want[1]) ssnv128_table();
  if (want[2]) ssnv503_table();
  if (want[3]) tresca_table();
  printf("\n%d check%s failed\n", failures, failures == 1 ? "" : "s");
  return failures ? 1 : 0;
usage:
  fprintf(stderr, "usage: friction_tables [--quick] [--repeat N (1..16)] [--base-factor F] [--cells P1|Q1|T6|Q8|Q9] "
                  "[block|ssnv128|ssnv503|tresca ...]\n");
  return 2;
}
