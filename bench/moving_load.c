/*
 * moving_load.c - a load history on a long interface: what ten load steps cost against the first
 * solve (docs/benchmarks.md, "A load history on a long interface"; issue 34).
 *
 * The strips of bench/long_interface.c: body 1 of nx x 4 squares (P1) on body 2 of
 * round(1.37 nx) x 4 (non-matching), 0.4 high, nx/10 long, body 2 held vertically on its bottom,
 * both held horizontally at their left corner node. Body 1 is pressed by a pressure p = 0.01 on
 * the part of its top that lies in a window a tenth of its length wide, starting at 0.3 of the
 * length; each load step moves the window right by a tenth of its own width (`mc_clear_loads`,
 * `mc_add_pressure`, `mc_solve` on the same handle: factorizations and the last active set
 * reused), for --steps steps. The contact zone follows the window, so both its ends change at
 * every step (by about nx/100 nodes each).
 *
 * Printed per nx (medians over --repeat fresh handles; each repeat runs the whole history):
 *   the first solve's time, each step's time, the steps' sum against the first solve (the
 *   issue's goal: the 10 steps together <= 3 first solves), and against the plain solve (body 1
 *   held vertically on its bottom instead, the window at its first place);
 *   per step (the last repeat): active rows, the zone's ends, active-set iterations,
 *   factorizations and factor updates (from the log), MC_INFO_COMPLEMENTARITY;
 *   two checks that could fail: the contact forces balance the load at every step (sum of
 *   mc_get_contact_force against p times the window's loaded length), and the last step's
 *   pressures equal those of a fresh handle solved for the last window alone (a re-solve gives
 *   the same answer as a first solve, to round-off).
 *
 * usage: moving_load [--steps n] [--repeat n] [--solver auto|condensed|sparse] [--weight q] [--log] [nx ...]
 *   default: --steps 10 --repeat 3, the solver not set (auto), no weight, nx 16000
 *   --weight q: a pressure q on the whole top of body 1 as well (a rail's weight), so that body 1
 *   rests on body 2 everywhere but where the window lifts it (the balance check counts it).
 * Exit status 1 if a solve failed or a check is off by more than 1e-8, 2 on a bad command line.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "mortarcontact.h"
#include "scenes.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_STEPS 100
#define MAX_REPEAT 15

static const double kPressure = 0.01;
static int echo_log;
static double weight; /* --weight q: a pressure q on the whole top of body 1 besides the window's */

/* What the log says of one solve: factorizations and factor updates of the active-set solve. */
typedef struct solve_log {
  long factorizations, updates;
} solve_log;

static long number_before(const char *message, const char *what) {
  const char *at = strstr(message, what);
  if (!at) return -1;
  while (at > message && at[-1] >= '0' && at[-1] <= '9') --at;
  return atol(at);
}

static void note(void *user, mc_log_level level, const char *message) {
  (void)level;
  solve_log *l = user;
  if (echo_log) fprintf(stderr, "    %s\n", message);
  if (strncmp(message, "active-set solve", 16) == 0) {
    l->factorizations = number_before(message, " factorizations");
    l->updates = number_before(message, " factor updates");
  }
}

/* 1. The scene: both strips, the supports; contact, or (plain) body 1 held on its bottom. */
typedef struct scene {
  sc_mesh mesh[2];
  double length, width; /* the strips' length; the load window's width */
} scene;

static int scene_build(scene *s, int nx) {
  s->length = 0.1 * nx, s->width = 0.1 * s->length;
  const int nx2 = (int)lround(1.37 * nx);
  return sc_mesh_rect(&s->mesh[0], 3, nx, 4, 0, 0, s->length, 0.4, 0, 1) ||
         sc_mesh_rect(&s->mesh[1], 3, nx2, 4, 0, -0.4, s->length, 0.4, 0, 2);
}

static mc_model *strips(const scene *s, int plain, int solver, solve_log *log) {
  mc_model *m = NULL;
  mc_status st = mc_create(&m);
  for (int b = 0; b < 2 && !st; ++b) {
    st = sc_set_mesh(m, b + 1, &s->mesh[b], 0);
    if (!st) st = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  const mc_int corner1 = s->mesh[0].side_nodes[SC_LEFT][0], corner2 = s->mesh[1].side_nodes[SC_LEFT][0];
  if (!st) st = sc_fix_side(m, 2, &s->mesh[1], SC_BOTTOM, MC_Y, 0);
  if (!st) st = mc_fix(m, 2, 1, &corner2, MC_X, NULL);
  if (!st) st = mc_fix(m, 1, 1, &corner1, MC_X, NULL);
  if (plain) {
    if (!st) st = sc_fix_side(m, 1, &s->mesh[0], SC_BOTTOM, MC_Y, 0);
  } else {
    if (!st) st = mc_set_contact(m, 1, s->mesh[0].n_side_edges[SC_BOTTOM], s->mesh[0].side_edges[SC_BOTTOM]);
    if (!st) st = mc_set_contact(m, 2, s->mesh[1].n_side_edges[SC_TOP], s->mesh[1].side_edges[SC_TOP]);
    if (!st && solver != MC_INTERFACE_AUTO) st = mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver);
  }
  if (!st && log) st = mc_set_log_callback(m, note, log);
  if (st) {
    fprintf(stderr, "model: %s\n", m ? mc_errmsg(m) : "mc_create failed");
    mc_destroy(m);
    return NULL;
  }
  return m;
}

/* 2. The load of step k: p on body 1's top edges whose middle lies in the window
      [x0, x0 + width], x0 = 0.3 length + k width / 10. Returns the loaded length, or -1. */
static double load_step(mc_model *m, const scene *s, int k) {
  const sc_mesh *top = &s->mesh[0];
  const double x0 = 0.3 * s->length + k * 0.1 * s->width, x1 = x0 + s->width;
  const mc_int n = top->n_side_edges[SC_TOP];
  mc_int *edges = malloc(sizeof(mc_int) * 2 * (size_t)n), count = 0;
  double *p = malloc(sizeof(double) * (size_t)n), loaded = 0;
  for (mc_int e = 0; e < n; ++e) {
    const mc_int a = top->side_edges[SC_TOP][2 * e], b = top->side_edges[SC_TOP][2 * e + 1];
    const double xa = top->xy[2 * a], xb = top->xy[2 * b], middle = 0.5 * (xa + xb);
    if (middle < x0 || middle > x1) continue;
    edges[2 * count] = a, edges[2 * count + 1] = b, p[count++] = kPressure;
    loaded += fabs(xb - xa);
  }
  mc_status st = mc_clear_loads(m, 1) || mc_add_pressure(m, 1, count, edges, p);
  if (!st && weight > 0) {
    double *q = malloc(sizeof(double) * (size_t)n);
    for (mc_int e = 0; e < n; ++e) q[e] = weight;
    st = mc_add_pressure(m, 1, n, top->side_edges[SC_TOP], q);
    free(q);
  }
  free(edges), free(p);
  if (st) fprintf(stderr, "loads: %s\n", mc_errmsg(m));
  return st ? -1 : loaded;
}

/* The total of the loads of a step whose window covers `loaded` (the weight's share included). */
static double total_load(const scene *s, double loaded) { return kPressure * loaded + weight * s->length; }

/* 3. What one step's answer says: active rows and the zone's ends, and the balance of forces. */
typedef struct step_answer {
  long active, iterations, factorizations, updates;
  double left, right, balance, complementarity, seconds;
} step_answer;

static int read_answer(const mc_model *m, const scene *s, double loaded, step_answer *a, double **pressure, mc_int *q) {
  mc_get_contact_count(m, q);
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)(*q > 0 ? *q : 1));
  double *f = malloc(sizeof(double) * (size_t)(*q > 0 ? *q : 1));
  *pressure = malloc(sizeof(double) * (size_t)(*q > 0 ? *q : 1));
  int bad = mc_get_contact_nodes(m, nodes) || mc_get_contact_force(m, f) || mc_get_contact_pressure(m, *pressure);
  double total = 0;
  a->active = 0, a->left = INFINITY, a->right = -INFINITY;
  for (mc_int j = 0; j < *q && !bad; ++j) {
    total += f[j];
    if (f[j] <= 0) continue;
    const double x = s->mesh[0].xy[2 * nodes[j]];
    a->active++, a->left = fmin(a->left, x), a->right = fmax(a->right, x);
  }
  a->balance = fabs(total - total_load(s, loaded)) / total_load(s, loaded);
  int64_t v = 0;
  mc_get_info_int(m, MC_INFO_ITERATIONS, &v), a->iterations = (long)v;
  mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &a->complementarity);
  free(nodes), free(f);
  return bad;
}

static void usage(void) {
  fprintf(stderr, "usage: moving_load [--steps n] [--repeat n] [--solver auto|condensed|sparse] [--weight q] [--log] [nx ...]\n");
}

int main(int argc, char **argv) {
  int steps = 10, repeat = 3, solver = MC_INTERFACE_AUTO, sizes[32], n_sizes = 0, status = 0;
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i], *next = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--log")) echo_log = 1;
    else if (next && !strcmp(a, "--steps")) steps = atoi(next), ++i;
    else if (next && !strcmp(a, "--repeat")) repeat = atoi(next), ++i;
    else if (next && !strcmp(a, "--weight")) weight = atof(next), ++i;
    else if (next && !strcmp(a, "--solver")) {
      ++i;
      if (!strcmp(next, "auto")) solver = MC_INTERFACE_AUTO;
      else if (!strcmp(next, "condensed")) solver = MC_INTERFACE_CONDENSED;
      else if (!strcmp(next, "sparse")) solver = MC_INTERFACE_SPARSE;
      else return usage(), 2;
    } else if (atoi(a) >= 20 && n_sizes < 32) sizes[n_sizes++] = atoi(a);
    else return usage(), 2;
  }
  if (steps < 1 || steps > MAX_STEPS || repeat < 1 || repeat > MAX_REPEAT) return usage(), 2;
  if (n_sizes == 0) sizes[n_sizes++] = 16000;
  printf("A load history on the long strips: p = %g on a window a tenth of the length wide, moved by a tenth of "
         "its width per step, %d steps; %d repeat(s), medians; solver %s\n",
         kPressure, steps, repeat,
         solver == MC_INTERFACE_AUTO ? "auto" : solver == MC_INTERFACE_CONDENSED ? "condensed" : "sparse");
  printf("| nx | contact nodes | DOFs | ran | plain solve s | first solve s | first/plain | steps s (sum) | "
         "steps / first solve | median step s | worst balance | last step against a fresh solve |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int z = 0; z < n_sizes; ++z) {
    const int nx = sizes[z];
    scene s;
    if (scene_build(&s, nx)) {
      fprintf(stderr, "cannot mesh nx = %d\n", nx);
      return 1;
    }
    /* 4. The plain solve, the window at its first place. */
    double plain[MAX_REPEAT], first[MAX_REPEAT], sum[MAX_REPEAT], step_time[MAX_REPEAT * MAX_STEPS];
    for (int r = 0; r < repeat; ++r) {
      mc_model *m = strips(&s, 1, solver, NULL);
      if (!m || load_step(m, &s, 0) < 0) return 1;
      const double t0 = bench_wall();
      if (mc_solve(m)) return fprintf(stderr, "plain solve: %s\n", mc_errmsg(m)), 1;
      plain[r] = bench_wall() - t0;
      mc_destroy(m);
    }
    /* 5. The history, `repeat` times on fresh handles. */
    step_answer answer[MAX_STEPS + 1];
    double worst_balance = 0, fresh_difference = 0;
    int64_t dofs = 0, ran = 0;
    mc_int q = 0;
    for (int r = 0; r < repeat; ++r) {
      solve_log log = {-1, -1};
      mc_model *m = strips(&s, 0, solver, &log);
      if (!m) return 1;
      double *last_pressure = NULL;
      sum[r] = 0;
      for (int k = 0; k <= steps; ++k) {
        if (echo_log) fprintf(stderr, "  nx %d, repeat %d, step %d:\n", nx, r + 1, k);
        const double loaded = load_step(m, &s, k);
        if (loaded < 0) return 1;
        log.factorizations = log.updates = -1;
        const double t0 = bench_wall();
        if (mc_solve(m)) return fprintf(stderr, "step %d: %s\n", k, mc_errmsg(m)), 1;
        const double t = bench_wall() - t0;
        if (k == 0) first[r] = t;
        else sum[r] += t, step_time[r * steps + k - 1] = t;
        step_answer a;
        double *pressure = NULL;
        if (read_answer(m, &s, loaded, &a, &pressure, &q)) return fprintf(stderr, "results: %s\n", mc_errmsg(m)), 1;
        a.factorizations = log.factorizations, a.updates = log.updates, a.seconds = t;
        worst_balance = fmax(worst_balance, a.balance);
        if (r == repeat - 1) answer[k] = a;
        free(last_pressure);
        last_pressure = pressure;
      }
      mc_get_info_int(m, MC_INFO_DOFS, &dofs);
      mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &ran);
      mc_destroy(m);
      /* 6. The last window solved alone on a fresh handle: the same pressures to round-off. */
      if (r == repeat - 1) {
        solve_log fresh_log = {-1, -1};
        mc_model *f = strips(&s, 0, solver, &fresh_log);
        const double loaded = f ? load_step(f, &s, steps) : -1;
        if (loaded < 0 || mc_solve(f)) return fprintf(stderr, "fresh solve: %s\n", f ? mc_errmsg(f) : "?"), 1;
        step_answer a;
        double *pressure = NULL;
        mc_int qf = 0;
        read_answer(f, &s, loaded, &a, &pressure, &qf);
        for (mc_int j = 0; j < qf && qf == q; ++j)
          fresh_difference = fmax(fresh_difference, fabs(pressure[j] - last_pressure[j]) / kPressure);
        if (qf != q) fresh_difference = INFINITY;
        free(pressure);
        mc_destroy(f);
      }
      free(last_pressure);
    }
    const double t_plain = bench_median(plain, repeat), t_first = bench_median(first, repeat), t_steps = bench_median(sum, repeat);
    const double t_step = bench_median(step_time, repeat * steps);
    printf("| %d | %ld | %ld | %s | %.3f | %.3f | %.2f | %.3f | %.2f | %.3f | %.1e | %.1e |\n", nx, (long)q, (long)dofs,
           ran == MC_INTERFACE_SPARSE ? "sparse" : ran == MC_INTERFACE_CONDENSED ? "condensed" : "?", t_plain, t_first,
           t_first / t_plain, t_steps, t_steps / t_first, t_step, worst_balance, fresh_difference);
    printf("\n| step | active rows | zone from x | to x | iterations | factorizations | factor updates | seconds | "
           "MC_INFO_COMPLEMENTARITY | balance |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k <= steps; ++k) {
      char factorizations[24] = "-", updates[24] = "-"; /* "-": the path did not log them (condensed) */
      if (answer[k].factorizations >= 0) snprintf(factorizations, sizeof factorizations, "%ld", answer[k].factorizations);
      if (answer[k].updates >= 0) snprintf(updates, sizeof updates, "%ld", answer[k].updates);
      printf("| %d | %ld | %.2f | %.2f | %ld | %s | %s | %.3f | %.1e | %.1e |\n", k, answer[k].active, answer[k].left,
             answer[k].right, answer[k].iterations, factorizations, updates, answer[k].seconds, answer[k].complementarity,
             answer[k].balance);
    }
    printf("\n");
    if (worst_balance > 1e-8 || fresh_difference > 1e-8) status = 1;
    sc_mesh_free(&s.mesh[0]), sc_mesh_free(&s.mesh[1]);
  }
  return status;
}
