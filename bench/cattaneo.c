/*
 * cattaneo.c - Cattaneo-Mindlin partial slip in 2D against its closed form (docs/benchmarks.md,
 * "Friction: Cattaneo-Mindlin partial slip").
 *
 * The scene: the shared Hertz scene (examples/scenes/hertz_scene.h: a half-disc of radius R = 1
 * on a block, both E = 1, nu = 0.3, plane strain, the block's base clamped), identical materials
 * (Dundurs beta = 0: the normal and tangential problems uncouple), Coulomb friction mu = 0.3.
 * The disc's flat top is moved rigidly: step 1 presses it down by d (chosen so that the normal
 * force P is about 0.0025, a = 0.076 R: p_target), step 2 moves it sideways by delta at the same depth. The rigid top
 * carries the moment of the tangential force, so the contact sees Q without a moment, as in
 * Johnson's solution (Contact Mechanics, ch. 7): a stick zone |x| < c,
 *     c / a = sqrt(1 - Q / (mu P)),
 *     q(x) = mu p0 sqrt(1 - x^2/a^2) - mu p0 (c/a) sqrt(1 - x^2/c^2)   (|x| < c)
 *     q(x) = mu p0 sqrt(1 - x^2/a^2)                                   (c <= |x| <= a),
 * a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), E* = E / (2 (1 - nu^2)), with P and Q measured
 * (the top's reactions). delta is found by a secant iteration on Q / (mu P) = 0.25, 0.5, 0.75
 * (each trial: mc_reset_history, the pressing step, the sliding step: two re-solves).
 *
 * Measured per mesh and method: c / a against sqrt(1 - Q/(mu P)) (c from the positions' margin
 * mu p - |q|, extrapolated to zero like the contact half-width, bench/contact_half_width.h), a
 * against Hertz, and the largest error of the shear profile relative to mu p0 away from the
 * stick zone's edges and the contact's ends (0.1 a from each, EDGE_BAND).
 *
 * Usage: cattaneo [--quick] [--levels n] [--h-over-a n1,n2,...] [--ratio r] [--method mortar|dual] [--fresh n]
 *                 [--one-step] [--normal mortar|nonmortar] [--load P] [--press-steps n] [--slide-steps n] [--press-friction]
 *        cattaneo --cost [--levels n | --h-over-a ...] [--repeat n] [--solver auto|condensed|sparse] [--history n]
 *                                                                   (what friction costs: cost_table)
 *   --quick: h = a/10 and a/20, asserts bounds (about twice what they measure), exit 1 if one fails.
 *   --h-over-a: these meshes (h = a/n1, a/n2, ...) instead of a/10, a/20, ... (--levels of them);
 *   --ratio: this Q/(mu P) only; --method: this method only.
 *   --fresh n: then, per row, the whole two-step run again from a fresh model at the d and delta the
 *     secant found (mc_create to the results read back), timed: the median of n runs, in a second
 *     table with the pressure's quality (largest and central nodal value against Hertz, node-to-node
 *     swing, error against Hertz's profile) beside c/a and the shear (bench/getfem_cattaneo.py
 *     measures GetFEM alike).
 *   --one-step: no pressing step: the top moved by (delta, -d) in one step with friction from the
 *     unloaded state (the static problem GetFEM's nodal friction brick solves); d as before.
 *   --normal mortar: MC_NORMAL_MORTAR, body 2's normal (GetFEM's brick projects on it); the default,
 *     body 1's nodal normal, tilts with the disc (x/R at x: 0.07 rad at 0.9 a), so "pressure" and
 *     "shear" there mix the vertical and horizontal tractions by that much.
 *   CATTANEO_PROFILE=1 prints every position's pressure and shear; CATTANEO_LOG=1 the library's log.
 */
#include "bench_timing.h"
#include "contact_half_width.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MU 0.3
/* "Away from the edges": at least this fraction of a from the stick zone's edges and the
   contact's ends, where q(x) and p(x) have square-root edges and the nodal values (force over
   tributary length) average over a cell across them. */
#define EDGE_BAND 0.1
#define NU 0.3
#define CHECK(call)                                                                  \
  do {                                                                               \
    if ((call) != MC_OK) {                                                           \
      fprintf(stderr, "%s:%d: %s failed: %s\n", __FILE__, __LINE__, #call, mc_errmsg(m)); \
      exit(2);                                                                       \
    }                                                                                \
  } while (0)

typedef struct scene {
  hertz_scene s;
  int n_top;
  int *top;  /* body-1 nodes on the flat top */
} scene;

/* The normal force: 0.0025 gives a = 0.076 R. At P = 0.01 (a = 0.15 R, the frictionless Hertz
   benchmark's load) the finite disc is no half-space: the contact is 2 % narrower than Hertz's
   and the slip zone's shear, mu p exactly, follows that pressure (measured: the shear off by
   5 to 7 % of mu p0 at 0.87 a on the finest mesh; --load 0.01). */
static double p_target = 0.0025;

/* Fine cells of h within 3 a of the contact point, growing by 1.15 beyond. */
static void scene_build(scene *sc, double h, double a) {
  memset(sc, 0, sizeof *sc);
  if (hertz_scene_build_graded(&sc->s, h, h, 3, 1.15, fmin(fmax(3 * a, h), 0.5)) != 0) {
    fprintf(stderr, "hertz_scene_build(%g) failed\n", h);
    exit(2);
  }
  char *on = calloc((size_t)sc->s.body[0].n_nodes, 1);
  for (int e = 0; e < sc->s.n_top_edges; ++e) on[sc->s.top_edges[2 * e]] = on[sc->s.top_edges[2 * e + 1]] = 1;
  sc->top = malloc(sizeof(int) * (size_t)sc->s.body[0].n_nodes);
  for (int v = 0; v < sc->s.body[0].n_nodes; ++v)
    if (on[v]) sc->top[sc->n_top++] = v;
  free(on);
}

static void scene_free(scene *sc) {
  hertz_scene_free(&sc->s);
  free(sc->top);
}

static void print_log(void *user, mc_log_level level, const char *message) {
  (void)level, (void)user;
  fprintf(stderr, "log: %s\n", message);
}

/* --normal mortar: MC_NORMAL_MORTAR (body 2's normal, along which GetFEM's node-to-segment brick
   measures the gap and splits the traction); default the library's, body 1's nodal normal */
static int contact_normal = MC_NORMAL_NONMORTAR;

/* The scene's model; mu < 0: without friction. */
static mc_model *scene_model_mu(const scene *sc, int method, double mu) {
  mc_model *m;
  if (mc_create(&m) != MC_OK) exit(2);
  if (getenv("CATTANEO_LOG")) CHECK(mc_set_log_callback(m, print_log, NULL));
  for (int b = 0; b < 2; ++b) {
    const hertz_mesh *mesh = &sc->s.body[b];
    CHECK(mc_set_mesh(m, b + 1, mesh->n_nodes, mesh->xy, mesh->n_cells, mesh->nodes_per_cell, mesh->cells));
    CHECK(mc_set_material(m, b + 1, 1.0, NU));
  }
  CHECK(mc_fix(m, 2, sc->s.n_bottom_nodes, sc->s.bottom_nodes, MC_XY, NULL));
  CHECK(mc_set_contact(m, 1, sc->s.n_contact_edges[0], sc->s.contact_edges[0]));
  CHECK(mc_set_contact(m, 2, sc->s.n_contact_edges[1], sc->s.contact_edges[1]));
  CHECK(mc_set_option_int(m, MC_OPTION_METHOD, method));
  CHECK(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0));
  if (contact_normal != MC_NORMAL_NONMORTAR) CHECK(mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, contact_normal));
  if (mu >= 0) CHECK(mc_set_friction(m, 1, MC_FRICTION_COULOMB, mu));
  return m;
}

static mc_model *scene_model(const scene *sc, int method) { return scene_model_mu(sc, method, MU); }

/* Moves the disc's top rigidly by (dx, -d) and solves (one step from the last state). Returns
   P and Q, the top's reactions (the forces the contact carries). */
static int press_steps = 1, slide_steps = 1, press_with_friction = 0;
/* --one-step: no pressing step before the sliding one; the top moved by (delta, -d) in one step
   with friction from the unloaded state: the static problem GetFEM's nodal friction brick solves
   (it measures slip from the reference configuration; bench/getfem_cattaneo.py) */
static int one_step = 0;

/* The pressing step (dx = 0) without friction unless press_with_friction: with identical
   materials the normal problem carries no shear (Dundurs beta = 0), which Johnson's solution
   assumes; the finite disc and block are not half-spaces, and pressing them with friction locks
   in a shear of some 10 % of mu p0 (measured: the --press-friction column). */
static void step(mc_model *m, const scene *sc, double dx, double d, double *P, double *Q) {
  CHECK(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, dx == 0 ? press_steps : slide_steps));
  CHECK(mc_set_friction(m, 1, MC_FRICTION_COULOMB, dx == 0 && !press_with_friction ? 0.0 : MU));
  double *values = malloc(sizeof(double) * 2 * (size_t)sc->n_top);
  for (int k = 0; k < sc->n_top; ++k) values[2 * k] = dx, values[2 * k + 1] = -d;
  CHECK(mc_fix(m, 1, sc->n_top, sc->top, MC_XY, values));
  free(values);
  CHECK(mc_solve(m));
  double *r = malloc(sizeof(double) * 2 * (size_t)sc->s.body[0].n_nodes);
  CHECK(mc_get_reaction(m, 1, r));
  double fx = 0, fy = 0;
  for (int k = 0; k < sc->n_top; ++k) fx += r[2 * sc->top[k]], fy += r[2 * sc->top[k] + 1];
  free(r);
  *P = fabs(fy), *Q = fabs(fx);
}

typedef struct result {
  double P, Q, ratio;     /* Q / (mu P) reached */
  double c_over_a, c_exact, a_h, a, p0;
  double shear_error;     /* max |q_h - q| / (mu p0) away from the edges */
  double shear_error_at;  /* where (x / a) */
  int positions, stick, slip, iterations;
  long dofs;
  double seconds;         /* the sliding step's mc_solve */
  double dx, d;           /* the sliding and pressing displacements of the top */
  double p0_h, p_center;  /* the largest nodal pressure, the one nearest x = 0 */
  double swing;           /* node-to-node swing / p0: max |e_j - (e's linear interpolant between j's neighbours)|, e = p_h - Hertz's p,
                             the three nodes within (1 - EDGE_BAND) a of the centre */
  double pressure_error;  /* max |p_j - Hertz p(x_j)| / p0, |x_j| <= (1 - EDGE_BAND) a */
} result;

/* The pressing depth that gives P close to 0.01: two secant steps from a guess. */
static double pressing_depth(mc_model *m, const scene *sc) {
  double d0 = 0.4 * p_target, P0, Q, d1, P1;
  CHECK(mc_reset_history(m));
  step(m, sc, 0, d0, &P0, &Q);
  d1 = d0 * p_target / P0;
  CHECK(mc_reset_history(m));
  step(m, sc, 0, d1, &P1, &Q);
  const double d2 = d1 + (p_target - P1) * (d1 - d0) / (P1 - P0);
  return d2;
}

static void measure(mc_model *m, const scene *sc, result *res);

static result slide_to(mc_model *m, const scene *sc, double d, double target) {
  result res;
  memset(&res, 0, sizeof res);
  double P, Q, x0 = 0.01 * p_target, x1, f0, f1, dx = x0;
  CHECK(mc_reset_history(m));
  if (!one_step) step(m, sc, 0, d, &P, &Q);
  step(m, sc, x0, d, &P, &Q);
  f0 = Q / (MU * P) - target;
  x1 = x0 * target / (Q / (MU * P));
  for (int it = 0; it < 30; ++it) {
    CHECK(mc_reset_history(m));
    if (!one_step) step(m, sc, 0, d, &P, &Q);
    const double start = bench_wall();
    step(m, sc, x1, d, &P, &Q);
    res.seconds = bench_wall() - start;
    f1 = Q / (MU * P) - target;
    dx = x1;
    if (fabs(f1) <= 1e-5 * target) break;
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1, f0 = f1, x1 = x2;
  }
  res.P = P, res.Q = Q;
  measure(m, sc, &res);
  res.dx = dx, res.d = d;
  return res;
}

/* Reads the last solve's results back and measures them against Johnson's closed form. */
static void measure(mc_model *m, const scene *sc, result *out) {
  result res = *out;
  double P = res.P, Q = res.Q;
  int64_t iterations, dofs;
  CHECK(mc_get_info_int(m, MC_INFO_ITERATIONS, &iterations));
  CHECK(mc_get_info_int(m, MC_INFO_DOFS, &dofs));
  res.iterations = (int)iterations, res.dofs = (long)dofs;
  res.P = P, res.Q = Q, res.ratio = Q / (MU * P);
  const double estar = 1.0 / (2 * (1 - NU * NU));
  res.a = sqrt(4 * P / (M_PI * estar)), res.p0 = 2 * P / (M_PI * res.a);
  res.c_exact = sqrt(1 - res.ratio);

  mc_int n;
  CHECK(mc_get_pair_contact_count(m, 1, &n));
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)n);
  double *pressure = malloc(sizeof(double) * (size_t)n), *shear = malloc(sizeof(double) * (size_t)n);
  double *state = malloc(sizeof(double) * (size_t)n), *x = malloc(sizeof(double) * (size_t)n);
  double *margin = malloc(sizeof(double) * (size_t)n);
  CHECK(mc_get_pair_contact_nodes(m, 1, nodes));
  CHECK(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, pressure));
  CHECK(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, shear));
  CHECK(mc_get_pair_contact(m, 1, MC_CONTACT_STATE, state));
  res.positions = (int)n;
  for (mc_int j = 0; j < n; ++j) {
    x[j] = sc->s.body[0].xy[2 * nodes[j]];
    margin[j] = fmax(MU * pressure[j] - fabs(shear[j]), 0.0);
    if (state[j] == MC_STATE_STICK) ++res.stick;
    if (state[j] == MC_STATE_SLIP) ++res.slip;
  }
  res.a_h = contact_half_width((int)n, x, pressure);
  const double c = contact_half_width((int)n, x, margin);
  res.c_over_a = c / res.a;
  /* the shear profile away from the stick zone's edges and the contact's ends */
  const double cc = res.c_exact * res.a;
  if (getenv("CATTANEO_PROFILE"))
    for (mc_int j = 0; j < n; ++j) {
      const double ax = fabs(x[j]);
      double q = MU * res.p0 * sqrt(fmax(1 - ax * ax / (res.a * res.a), 0));
      if (ax < cc) q -= MU * res.p0 * res.c_exact * sqrt(1 - ax * ax / (cc * cc));
      if (ax < 1.2 * res.a)
        fprintf(stderr, "x %+.5f p %.5f shear %+.5f state %g mu p %.5f q %.5f\n", x[j], pressure[j], shear[j], state[j],
                MU * pressure[j], q);
    }
  for (mc_int j = 0; j < n; ++j) {
    const double ax = fabs(x[j]);
    if (fabs(ax - cc) < EDGE_BAND * res.a || ax > (1 - EDGE_BAND) * res.a) continue;
    double q = MU * res.p0 * sqrt(fmax(1 - ax * ax / (res.a * res.a), 0));
    if (ax < cc) q -= MU * res.p0 * res.c_exact * sqrt(1 - ax * ax / (cc * cc));
    const double e = fabs(fabs(shear[j]) - q) / (MU * res.p0);
    if (e > res.shear_error) res.shear_error = e, res.shear_error_at = x[j] / res.a;
  }
  /* the pressures: largest, at the centre, node-to-node swing and error against Hertz (the
     positions sorted by x; the swing is the distance from the line through both neighbours) */
  int *order = malloc(sizeof(int) * (size_t)n);
  for (mc_int j = 0; j < n; ++j) order[j] = (int)j;
  for (mc_int i = 1; i < n; ++i)
    for (mc_int k = i; k > 0 && x[order[k - 1]] > x[order[k]]; --k) {
      int t = order[k];
      order[k] = order[k - 1], order[k - 1] = t;
    }
  res.p0_h = 0, res.swing = 0, res.pressure_error = 0;
  double best = INFINITY;
  for (mc_int j = 0; j < n; ++j) {
    res.p0_h = fmax(res.p0_h, pressure[j]);
    if (fabs(x[j]) < best) best = fabs(x[j]), res.p_center = pressure[j];
    const double ax = fabs(x[j]);
    if (ax > (1 - EDGE_BAND) * res.a) continue;
    res.pressure_error = fmax(res.pressure_error, fabs(pressure[j] - res.p0 * sqrt(1 - ax * ax / (res.a * res.a))) / res.p0);
  }
  for (mc_int k = 1; k + 1 < n; ++k) {
    const int l = order[k - 1], j = order[k], r = order[k + 1];
    const double band = (1 - EDGE_BAND) * res.a;
    if (fabs(x[l]) > band || fabs(x[j]) > band || fabs(x[r]) > band) continue;
    /* on the difference from Hertz's profile, whose own curvature is not a swing */
    double e[3];
    const int at[3] = {l, j, r};
    for (int i = 0; i < 3; ++i)
      e[i] = pressure[at[i]] - res.p0 * sqrt(fmax(1 - x[at[i]] * x[at[i]] / (res.a * res.a), 0));
    const double t = (x[j] - x[l]) / (x[r] - x[l]);
    res.swing = fmax(res.swing, fabs(e[1] - ((1 - t) * e[0] + t * e[2])) / res.p0);
  }
  free(order);
  free(nodes), free(pressure), free(shear), free(state), free(x), free(margin);
  *out = res;
}

/* The whole two-step run from a fresh model at the pressing depth d and the sliding displacement
   dx found by the secant: mc_create, meshes, materials, supports, contact, the pressing step, the
   sliding step, the results read back (--fresh). Returns its wall time. */
static double fresh_run(const scene *sc, int method, double d, double dx, result *res) {
  const double start = bench_wall();
  mc_model *m = scene_model(sc, method);
  double P, Q;
  if (!one_step) step(m, sc, 0, d, &P, &Q);
  step(m, sc, dx, d, &P, &Q);
  memset(res, 0, sizeof *res);
  res->P = P, res->Q = Q;
  measure(m, sc, res);
  const double seconds = bench_wall() - start;
  mc_destroy(m);
  res->dx = dx, res->d = d;
  return seconds;
}

/* ---- --cost: what friction costs (issue 33's cost goals) ------------------------------------
   Per mesh, each a fresh model's solves, medians of `repeats`, serial (MC_OPTION_THREADS 1):
   - frictionless: the disc pressed and moved sideways in one solve (first solve: assembly,
     factorization, the interface operator, the active set, recovery);
   - Coulomb: the same solve with mu = 0.3 (its interface operator has a tangential row per
     contact row);
   - a 10-step history: the same final loads reached in 10 solves (each a step from the last).
   The displacements are those of Q/(mu P) = 0.5 at this mesh (the secant runs first, untimed).
   Wall and process CPU time: on a loaded machine the wall clock measures the neighbours too. */
static double cpu_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* --solver: MC_OPTION_INTERFACE_SOLVER of the timed solves (default: not set, automatic); --history:
   the history's steps (default 10; 0: no history column, e.g. when only one solve's cost is
   wanted: bench/interface_choice.py). With CATTANEO_LOG set, a line "timed solves: ..." on stderr
   before each timed model's log. */
static int cost_solver = MC_INTERFACE_AUTO, history_steps = 10;

static double timed_solves(const scene *sc, int method, double mu, int steps, double d, double dx, double *cpu) {
  if (getenv("CATTANEO_LOG")) fprintf(stderr, "timed solves: mu %g, %d steps\n", mu, steps);
  mc_model *m = scene_model_mu(sc, method, mu > 0 ? mu : -1);
  CHECK(mc_set_option_int(m, MC_OPTION_THREADS, 1));
  if (cost_solver != MC_INTERFACE_AUTO) CHECK(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, cost_solver));
  double *values = malloc(sizeof(double) * 2 * (size_t)sc->n_top);
  const double start = bench_wall(), cpu_start = cpu_seconds();
  for (int k = 1; k <= steps; ++k) {
    for (int i = 0; i < sc->n_top; ++i) values[2 * i] = dx * k / steps, values[2 * i + 1] = -d * k / steps;
    CHECK(mc_fix(m, 1, sc->n_top, sc->top, MC_XY, values));
    CHECK(mc_solve(m));
  }
  const double seconds = bench_wall() - start;
  *cpu = cpu_seconds() - cpu_start;
  free(values);
  mc_destroy(m);
  return seconds;
}

static void cost_table(int n_sizes, const int *sizes, int repeats) {
  const double a_nominal = sqrt(4 * p_target / (M_PI / (2 * (1 - NU * NU))));
  printf("| h / a | DOFs | frictionless s | Coulomb s | Coulomb / frictionless | %d-step history s | history / one Coulomb solve | the same ratios from CPU time |\n",
         history_steps);
  printf("|---|---|---|---|---|---|---|---|\n");
  for (int level = 0; level < n_sizes; ++level) {
    const double h = a_nominal / sizes[level];
    scene sc;
    scene_build(&sc, h, a_nominal);
    mc_model *m = scene_model(&sc, MC_METHOD_MORTAR);
    const double d = pressing_depth(m, &sc);
    result r = slide_to(m, &sc, d, 0.5);
    mc_destroy(m);
    double t0[16], t1[16], t10[16], c0[16], c1[16], c10[16];
    const int n = repeats < 16 ? repeats : 16;
    for (int k = 0; k < n; ++k) {
      t0[k] = timed_solves(&sc, MC_METHOD_MORTAR, 0, 1, d, r.dx, &c0[k]);
      t1[k] = timed_solves(&sc, MC_METHOD_MORTAR, MU, 1, d, r.dx, &c1[k]);
      t10[k] = history_steps > 0 ? timed_solves(&sc, MC_METHOD_MORTAR, MU, history_steps, d, r.dx, &c10[k]) : NAN;
      if (history_steps == 0) c10[k] = NAN;
    }
    const double m0 = bench_median(t0, n), m1 = bench_median(t1, n), m10 = bench_median(t10, n);
    const double p0 = bench_median(c0, n), p1 = bench_median(c1, n), p10 = bench_median(c10, n);
    printf("| 1/%d | %ld | %.3f | %.3f | %.2f | %.3f | %.2f | %.2f, %.2f |\n", sizes[level], r.dofs, m0, m1, m1 / m0, m10,
           m10 / m1, p1 / p0, p10 / p1);
    fflush(stdout);
    scene_free(&sc);
  }
}

int main(int argc, char **argv) {
  int quick = 0, levels = 4, fresh = 0, n_sizes = 0, sizes[16], method_only = -1, cost = 0, repeats = 3;
  double ratio_only = 0;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--quick")) quick = 1, levels = 2;
    else if (!strcmp(argv[i], "--levels") && i + 1 < argc) levels = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--press-steps") && i + 1 < argc) press_steps = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--slide-steps") && i + 1 < argc) slide_steps = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--press-friction")) press_with_friction = 1;
    else if (!strcmp(argv[i], "--load") && i + 1 < argc) p_target = atof(argv[++i]);
    else if (!strcmp(argv[i], "--fresh") && i + 1 < argc) fresh = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--cost")) cost = 1;
    else if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeats = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--history") && i + 1 < argc) history_steps = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--solver") && i + 1 < argc) {
      ++i;
      cost_solver = !strcmp(argv[i], "auto") ? MC_INTERFACE_AUTO : !strcmp(argv[i], "condensed") ? MC_INTERFACE_CONDENSED
                  : !strcmp(argv[i], "sparse") ? MC_INTERFACE_SPARSE : -1;
      if (cost_solver < 0) {
        fprintf(stderr, "--solver: auto, condensed or sparse\n");
        return 2;
      }
    }
    else if (!strcmp(argv[i], "--one-step")) one_step = 1;
    else if (!strcmp(argv[i], "--normal") && i + 1 < argc) {
      ++i;
      if (!strcmp(argv[i], "mortar")) contact_normal = MC_NORMAL_MORTAR;
      else if (!strcmp(argv[i], "nonmortar")) contact_normal = MC_NORMAL_NONMORTAR;
      else {
        fprintf(stderr, "--normal: mortar or nonmortar\n");
        return 2;
      }
    }
    else if (!strcmp(argv[i], "--ratio") && i + 1 < argc) ratio_only = atof(argv[++i]);
    else if (!strcmp(argv[i], "--method") && i + 1 < argc) {
      ++i;
      method_only = !strcmp(argv[i], "mortar") ? 0 : !strcmp(argv[i], "dual") ? 1 : -2;
      if (method_only < -1) {
        fprintf(stderr, "--method: mortar or dual\n");
        return 2;
      }
    } else if (!strcmp(argv[i], "--h-over-a") && i + 1 < argc) {
      for (char *t = strtok(argv[++i], ","); t && n_sizes < 16; t = strtok(NULL, ",")) sizes[n_sizes++] = atoi(t);
    } else {
      fprintf(stderr, "usage: %s [--quick] [--levels n] [--h-over-a n1,n2,...] [--ratio r] [--method mortar|dual] [--fresh n]"
                      " [--one-step] [--normal mortar|nonmortar] [--load P] [--press-steps n] [--slide-steps n] [--press-friction]\n", argv[0]);
      return 2;
    }
  }
  if (n_sizes == 0)
    for (int level = cost ? 1 : 0; level < levels && level < 16; ++level) sizes[n_sizes++] = 10 << level;
  if (cost) {
    cost_table(n_sizes, sizes, repeats);
    return 0;
  }
  for (int k = 0; k < n_sizes; ++k)
    if (sizes[k] < 1) {
      fprintf(stderr, "--h-over-a: positive integers n (h = a / n)\n");
      return 2;
    }
  const double a_nominal = sqrt(4 * p_target / (M_PI / (2 * (1 - NU * NU))));  /* Hertz */
  const double all_ratios[3] = {0.25, 0.5, 0.75};
  const double *ratios = ratio_only > 0 ? &ratio_only : all_ratios;
  const int n_ratios = ratio_only > 0 ? 1 : 3;
  const int methods[2] = {MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR};
  const char *const method_name[2] = {"mortar", "dual mortar"};
  int failed = 0, n_rows = 0;
  typedef struct fresh_row { int method, n; result res; double seconds; } fresh_row;
  fresh_row *rows = malloc(sizeof(fresh_row) * (size_t)(2 * 3 * n_sizes));
  printf("| method | h / a | DOFs | Q/(mu P) | P | positions: stick, slip | c/a | sqrt(1 - Q/(mu P)) | error | a_h / a - 1 | shear error / (mu p0) (at x/a) | iterations | sliding step s |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int level = 0; level < n_sizes; ++level) {
    const double h_over_a = 1.0 / sizes[level], h = a_nominal * h_over_a;
    scene sc;
    scene_build(&sc, h, a_nominal);
    for (int k = 0; k < 2; ++k) {
      if (method_only >= 0 && k != method_only) continue;
      mc_model *m = scene_model(&sc, methods[k]);
      const double d = pressing_depth(m, &sc);
      for (int r = 0; r < n_ratios; ++r) {
        result res = slide_to(m, &sc, d, ratios[r]);
        const double error = res.c_over_a / res.c_exact - 1;
        printf("| %s | 1/%d | %ld | %.4f | %.5f | %d, %d | %.4f | %.4f | %+.2f %% | %+.2f %% | %.2f %% (%+.2f) | %d | %.3f |\n",
               method_name[k], sizes[level], res.dofs, res.ratio, res.P, res.stick, res.slip, res.c_over_a, res.c_exact,
               100 * error, 100 * (res.a_h / res.a - 1), 100 * res.shear_error, res.shear_error_at, res.iterations, res.seconds);
        fflush(stdout);
        /* quick: h = a/10 and a/20; bounds about twice what those meshes measured */
        if (quick && (fabs(error) > (level == 0 ? 0.10 : 0.055) || res.shear_error > (level == 0 ? 0.07 : 0.05) ||
                      fabs(res.ratio - ratios[r]) > 1e-3)) {
          fprintf(stderr, "FAILED: %s h = a/%d, Q/(mu P) = %.2f: c/a error %.3g, shear error %.3g\n", method_name[k],
                  sizes[level], ratios[r], error, res.shear_error);
          failed = 1;
        }
        if (fresh > 0) {
          /* the secant's model is freed first: only one model is alive while timing */
          double *t = malloc(sizeof(double) * (size_t)fresh);
          fresh_row *row = &rows[n_rows++];
          row->method = k, row->n = sizes[level];
          for (int rep = 0; rep < fresh; ++rep) t[rep] = fresh_run(&sc, methods[k], res.d, res.dx, &row->res);
          row->seconds = bench_median(t, fresh);
          free(t);
        }
      }
      mc_destroy(m);
    }
    scene_free(&sc);
  }
  if (fresh > 0) {
    /* --fresh: the same answers from a fresh model, timed whole (median of n runs), and the
       pressure's quality: the largest and the central nodal pressure against Hertz's p0 (from the
       measured P), the node-to-node swing (e = the nodal pressure minus Hertz's: the largest
       distance of e_j from the line through its two neighbours' values, the three within
       (1 - EDGE_BAND) a of the centre) and the largest error against Hertz's profile (within
       (1 - EDGE_BAND) a), both relative to p0 */
    printf("\nThe whole two-step run from a fresh model (mc_create to the results read back), median of %d:\n\n", fresh);
    printf("| method | h / a | DOFs | Q/(mu P) | c/a error | shear error / (mu p0) | a_h / a - 1 | p0_h / p0 - 1 | p(0) / p0 - 1 | pressure swing / p0 | pressure error / p0 | two steps s |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < n_rows; ++k) {
      const result *res = &rows[k].res;
      printf("| %s | 1/%d | %ld | %.4f | %+.2f %% | %.2f %% | %+.2f %% | %+.2f %% | %+.2f %% | %.2f %% | %.2f %% | %.4f |\n",
             method_name[rows[k].method], rows[k].n, res->dofs, res->ratio, 100 * (res->c_over_a / res->c_exact - 1),
             100 * res->shear_error, 100 * (res->a_h / res->a - 1), 100 * (res->p0_h / res->p0 - 1),
             100 * (res->p_center / res->p0 - 1), 100 * res->swing, 100 * res->pressure_error, rows[k].seconds);
    }
  }
  free(rows);
  return failed;
}
