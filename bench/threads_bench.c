/*
 * threads_bench.c - the contact solve with MC_OPTION_THREADS = 1 (serial) and 0 (automatic)
 * side by side, in one run (docs/benchmarks.md, "Threads").
 *
 * Scenes:
 *   equal  two equal unit squares, P1 on N x N squares each, body 1 on top of body 2: body 2
 *          clamped at its bottom, body 1 on rollers on its left side and held vertically by
 *          contact alone, a uniform traction on its top;
 *   hertz  the Hertz scene (examples/scenes/hertz_scene.h, h2 = 1.37 h1), mortar method.
 * Each measurement runs in a child process of its own (so that neither mode inherits the other's
 * heap, or OpenBLAS worker threads still spinning after the other's calls): one untimed solve
 * (the first solve of a process maps fresh memory: 10-15 % of the time at 10^5 DOFs), then the
 * timed solve, from mc_create to the results read back, and a re-solve after a load change.
 * Serial and automatic alternate, in turn first, so that neither order nor a change of load on
 * the machine favours one. Prints medians, the ratio auto/serial, the thread count the
 * automatic solve chose, and whether both gave the same displacements bit for bit.
 * --same-process 1 measures as runs 1 to 4 of docs/benchmarks.md did: one process per size, one
 * untimed serial solve, then the two modes alternating in that process.
 *
 * The last column is the interface solver that ran (MC_INFO_INTERFACE_SOLVER of the automatic
 * solve: condensed or sparse; "-" from a library that does not set it).
 *
 * usage: threads_bench [--repeat n] [--threads n] [--solver auto|condensed|sparse] [--phases 1]
 *                      [--same-process 1] equal:N | hertz:h1 ...
 *        (default: the sizes of docs/benchmarks.md, 10^4 to 2*10^6 DOFs, 5 repeats;
 *         --threads: the value compared with serial, default 0 = automatic;
 *         --solver: MC_OPTION_INTERFACE_SOLVER of every solve, default auto = the option not
 *         set (the library's choice); condensed or sparse forces that path in both modes;
 *         --phases 1: every solve's phase messages on stderr, timed from mc_create;
 *         --only t: no comparison, `repeat` solves with MC_OPTION_THREADS = t in one process,
 *         each time on stderr: for profiling with perf)
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include "bench_timing.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define MAX_REPEAT 15

static int show_phases; /* --phases: print each solve's log with the wall time since mc_create */
static int solver_option = MC_INTERFACE_AUTO; /* --solver: MC_OPTION_INTERFACE_SOLVER, AUTO = not set */
static double phase_origin;

static void print_phase(void *user, mc_log_level level, const char *message) {
  (void)user;
  if (level == MC_LOG_PHASE) fprintf(stderr, "  %7.3f  %s\n", bench_wall() - phase_origin, message);
}

/* A scene: the two meshes, supports, load edges and contact edges. */
typedef struct scene {
  hertz_scene s; /* the equal scene is stored in the same struct */
  double load;   /* downwards traction on body 1's top edges */
} scene;

static int equal_scene(scene *sc, int n) {
  memset(sc, 0, sizeof *sc);
  hertz_scene *s = &sc->s;
  const int nodes = (n + 1) * (n + 1), cells = 2 * n * n;
  for (int b = 0; b < 2; ++b) {
    hertz_mesh *m = &s->body[b];
    m->n_nodes = nodes, m->n_cells = cells, m->nodes_per_cell = 3;
    m->xy = malloc(sizeof(double) * 2 * nodes), m->cells = malloc(sizeof(int) * 3 * cells);
    if (!m->xy || !m->cells) return 1;
    const double y0 = b == 0 ? 0.0 : -1.0; /* body 1 = [0,1]^2 on top of body 2 = [0,1]x[-1,0] */
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m->xy[2 * (j * (n + 1) + i)] = (double)i / n, m->xy[2 * (j * (n + 1) + i) + 1] = y0 + (double)j / n;
    for (int j = 0, c = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, c += 2) {
        int a = j * (n + 1) + i, bb = a + 1, d = a + n + 1, e = d + 1;
        int t[6] = {a, bb, e, a, e, d};
        memcpy(m->cells + 3 * c, t, sizeof t);
      }
  }
  /* body 1: contact on its bottom edge (boundary walk: left to right), load on its top edge
     (right to left), rollers on its left side; body 2: contact on its top edge, clamped bottom */
  s->n_contact_edges[0] = s->n_contact_edges[1] = n, s->n_top_edges = n;
  s->contact_edges[0] = malloc(sizeof(int) * 2 * n), s->contact_edges[1] = malloc(sizeof(int) * 2 * n);
  s->top_edges = malloc(sizeof(int) * 2 * n);
  s->n_axis_nodes = n + 1, s->axis_nodes = malloc(sizeof(int) * (n + 1));
  s->n_bottom_nodes = n + 1, s->bottom_nodes = malloc(sizeof(int) * (n + 1));
  if (!s->contact_edges[0] || !s->contact_edges[1] || !s->top_edges || !s->axis_nodes || !s->bottom_nodes) return 1;
  for (int i = 0; i < n; ++i) {
    s->contact_edges[0][2 * i] = i, s->contact_edges[0][2 * i + 1] = i + 1;
    s->contact_edges[1][2 * i] = n * (n + 1) + n - i, s->contact_edges[1][2 * i + 1] = n * (n + 1) + n - i - 1;
    s->top_edges[2 * i] = n * (n + 1) + n - i, s->top_edges[2 * i + 1] = n * (n + 1) + n - i - 1;
  }
  for (int j = 0; j <= n; ++j) s->axis_nodes[j] = j * (n + 1), s->bottom_nodes[j] = j;
  sc->load = 0.05;
  return 0;
}

static int hertz(scene *sc, double h1) {
  memset(sc, 0, sizeof *sc);
  sc->load = 0.005; /* P = 0.01 over the top of length 2 */
  return hertz_scene_build(&sc->s, h1, 1.37 * h1, 0);
}

typedef struct timing {
  double first, resolve;
  long dofs;
  int ok, threads_seen, solver_ran;
  double *u; /* both bodies' displacements, for the bit-for-bit comparison */
} timing;

static mc_status load(mc_model *m, const scene *sc, double scale) {
  const hertz_scene *s = &sc->s;
  double *t = malloc(sizeof(double) * 2 * s->n_top_edges);
  for (int e = 0; e < s->n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -scale * sc->load;
  mc_status st = mc_clear_loads(m, 1);
  if (!st) st = mc_add_traction(m, 1, s->n_top_edges, s->top_edges, t);
  free(t);
  return st;
}

static void solve(const scene *sc, int threads, timing *out) {
  const hertz_scene *s = &sc->s;
  mc_model *m = NULL;
  double start = bench_wall();
  mc_status st = mc_create(&m);
  if (show_phases) {
    phase_origin = start;
    fprintf(stderr, "%s solve:\n", threads == 1 ? "serial" : "threaded");
    if (!st) st = mc_set_log_callback(m, print_phase, NULL);
  }
  for (int b = 0; b < 2 && !st; ++b) {
    st = mc_set_mesh(m, b + 1, s->body[b].n_nodes, s->body[b].xy, s->body[b].n_cells, 3, s->body[b].cells);
    if (!st) st = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  if (!st) st = mc_fix(m, 1, s->n_axis_nodes, s->axis_nodes, MC_X, NULL);
  if (!st) st = mc_fix(m, 2, s->n_bottom_nodes, s->bottom_nodes, MC_XY, NULL);
  if (!st) st = load(m, sc, 1.0);
  if (!st) st = mc_set_contact(m, 1, s->n_contact_edges[0], s->contact_edges[0]);
  if (!st) st = mc_set_contact(m, 2, s->n_contact_edges[1], s->contact_edges[1]);
  if (!st) st = mc_set_option_int(m, MC_OPTION_THREADS, threads);
  if (!st && solver_option != MC_INTERFACE_AUTO) st = mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, solver_option);
  if (!st) st = mc_solve(m);
  int64_t ran = 0;
  if (!st) mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &ran);
  out->solver_ran = (int)ran;
  size_t n0 = 2 * (size_t)s->body[0].n_nodes, n1 = 2 * (size_t)s->body[1].n_nodes;
  free(out->u);
  out->u = malloc(sizeof(double) * (n0 + n1));
  if (!st) st = mc_get_displacement(m, 1, out->u);
  if (!st) st = mc_get_displacement(m, 2, out->u + n0);
  out->first = bench_wall() - start;
  int64_t dofs = 0;
  if (!st) st = mc_get_info_int(m, MC_INFO_DOFS, &dofs);
  out->dofs = (long)dofs;
  /* a load step: the factorizations and S are reused */
  start = bench_wall();
  if (show_phases) phase_origin = start, fprintf(stderr, "re-solve:\n");
  if (!st) st = load(m, sc, 1.5);
  if (!st) st = mc_solve(m);
  if (!st) st = mc_get_displacement(m, 1, out->u);
  if (!st) st = mc_get_displacement(m, 2, out->u + n0);
  out->resolve = bench_wall() - start;
  out->ok = st == MC_OK;
  if (st) fprintf(stderr, "solve failed: %s\n", mc_errmsg(m));
  mc_destroy(m);
}

/* Did the automatic solve run on two threads? Its start message says so. */
static void note_threads(void *seen, mc_log_level level, const char *message) {
  (void)level;
  if (strstr(message, "solve: start") && strstr(message, "2 threads")) *(int *)seen = 2;
}

static int chosen_threads(const scene *sc, int threads) {
  const hertz_scene *s = &sc->s;
  mc_model *m = NULL;
  int seen = 1;
  mc_status st = mc_create(&m);
  for (int b = 0; b < 2 && !st; ++b) {
    st = mc_set_mesh(m, b + 1, s->body[b].n_nodes, s->body[b].xy, s->body[b].n_cells, 3, s->body[b].cells);
    if (!st) st = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  if (!st) st = mc_set_option_int(m, MC_OPTION_THREADS, threads);
  if (!st) st = mc_set_log_callback(m, note_threads, &seen);
  /* a solve that fails at once (no supports: body 2 not held) still logs its start */
  if (!st) mc_solve(m);
  mc_destroy(m);
  return seen;
}

/* One measurement in a child process: what it sends back through shared memory. */
typedef struct shared_result {
  double first, resolve;
  long dofs;
  int ok, solver_ran;
} shared_result;

static int solve_in_child(const scene *sc, int threads, shared_result *out, double *u, size_t n_u) {
  out->ok = 0;
  pid_t child = fork();
  if (child < 0) return 0;
  if (child == 0) {
    timing t = {0};
    solve(sc, threads, &t); /* not timed */
    if (t.ok) solve(sc, threads, &t);
    out->first = t.first, out->resolve = t.resolve, out->dofs = t.dofs, out->ok = t.ok, out->solver_ran = t.solver_ran;
    if (t.ok) memcpy(u, t.u, sizeof(double) * n_u);
    _exit(t.ok ? 0 : 1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 && out->ok;
}

static int same_process; /* --same-process 1: both modes in one process, as in runs 1 to 4 */
static int only = -1;     /* --only t: `repeat` solves with MC_OPTION_THREADS = t in this process (for perf) */

static int run(const char *spec, int repeat, int threads) {
  scene sc;
  int bad;
  if (strncmp(spec, "equal:", 6) == 0) bad = equal_scene(&sc, atoi(spec + 6));
  else if (strncmp(spec, "hertz:", 6) == 0) bad = hertz(&sc, atof(spec + 6));
  else bad = 1;
  if (bad) {
    fprintf(stderr, "bad size %s\n", spec);
    return 1;
  }
  double first[2][MAX_REPEAT], resolve[2][MAX_REPEAT];
  timing t[2] = {{0}, {0}};
  if (only >= 0) {
    for (int k = 0; k < repeat; ++k) {
      solve(&sc, only, &t[0]);
      if (!t[0].ok) return 1;
      fprintf(stderr, "%s threads %d: first solve %.3f s, re-solve %.4f s\n", spec, only, t[0].first, t[0].resolve);
    }
    free(t[0].u);
    hertz_scene_free(&sc.s);
    return 0;
  }
  int identical = 1;
  const size_t n_u = 2 * (size_t)(sc.s.body[0].n_nodes + sc.s.body[1].n_nodes);
  if (same_process) {
    /* A first solve, not timed: the process's first solve of a size pays for mapping fresh
       memory, which later ones reuse. Then the two alternate, in turn first. */
    solve(&sc, 1, &t[0]);
    for (int k = 0; k < repeat; ++k)
      for (int turn = 0; turn < 2; ++turn) {
        const int mode = (turn + k) % 2;
        solve(&sc, mode == 0 ? 1 : threads, &t[mode]);
        if (!t[mode].ok) return 1;
        first[mode][k] = t[mode].first, resolve[mode][k] = t[mode].resolve;
        if (turn == 1) identical = identical && memcmp(t[0].u, t[1].u, sizeof(double) * n_u) == 0;
      }
  } else {
    /* Each measurement in a process of its own, serial and automatic alternating (in turn
       first): an untimed solve (the first solve of a process maps fresh memory), then the timed
       solve and re-solve. So neither mode inherits the other's heap or OpenBLAS's worker threads
       still spinning after a call (docs/benchmarks.md, "Threads"). */
    shared_result *shared = mmap(NULL, 2 * sizeof(shared_result) + 2 * n_u * sizeof(double), PROT_READ | PROT_WRITE,
                                 MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared == MAP_FAILED) return 1;
    double *u_shared = (double *)(shared + 2);
    for (int k = 0; k < repeat; ++k) {
      for (int turn = 0; turn < 2; ++turn) {
        const int mode = (turn + k) % 2;
        if (!solve_in_child(&sc, mode == 0 ? 1 : threads, &shared[mode], u_shared + mode * n_u, n_u)) return 1;
        first[mode][k] = shared[mode].first, resolve[mode][k] = shared[mode].resolve;
        t[mode].dofs = shared[mode].dofs, t[mode].solver_ran = shared[mode].solver_ran;
      }
      identical = identical && memcmp(u_shared, u_shared + n_u, sizeof(double) * n_u) == 0;
    }
    munmap(shared, 2 * sizeof(shared_result) + 2 * n_u * sizeof(double));
  }
  /* every measurement on stderr, in the order taken, for the spread */
  fprintf(stderr, "%s samples (serial / auto, first solve; re-solve):", spec);
  for (int k = 0; k < repeat; ++k) fprintf(stderr, " %.3f/%.3f", first[0][k], first[1][k]);
  fprintf(stderr, ";");
  for (int k = 0; k < repeat; ++k) fprintf(stderr, " %.4f/%.4f", resolve[0][k], resolve[1][k]);
  fprintf(stderr, "\n");
  double f1 = bench_median(first[0], repeat), fa = bench_median(first[1], repeat);
  double r1 = bench_median(resolve[0], repeat), ra = bench_median(resolve[1], repeat);
  const int ran = t[1].solver_ran;
  printf("| %s | %ld | %d + %d | %d | %.3f | %.3f | %.2f | %.4f | %.4f | %.2f | %s | %s |\n", strncmp(spec, "equal", 5) ? "hertz" : "equal",
         t[0].dofs, 2 * sc.s.body[0].n_nodes, 2 * sc.s.body[1].n_nodes, chosen_threads(&sc, threads), f1, fa, fa / f1, r1, ra,
         ra / r1, identical ? "yes" : "NO",
         ran == MC_INTERFACE_CONDENSED ? "condensed" : ran == MC_INTERFACE_SPARSE ? "sparse" : "-");
  fflush(stdout);
  free(t[0].u), free(t[1].u);
  hertz_scene_free(&sc.s); /* frees the equal scene's arrays too (same layout) */
  return identical ? 0 : 1;
}

int main(int argc, char **argv) {
  static const char *defaults[] = {"equal:50",    "equal:87",     "equal:158",   "equal:224",  "equal:354",
                                   "equal:500",   "equal:707",    "hertz:0.012", "hertz:0.006", "hertz:0.004",
                                   "hertz:0.0025", "hertz:0.0017", "hertz:0.00107", "hertz:0.0008"};
  int repeat = 5, threads = 0, first = 1;
  while (first + 1 < argc && argv[first][0] == '-') {
    if (strcmp(argv[first], "--repeat") == 0) repeat = atoi(argv[first + 1]);
    else if (strcmp(argv[first], "--threads") == 0) threads = atoi(argv[first + 1]);
    else if (strcmp(argv[first], "--phases") == 0) show_phases = atoi(argv[first + 1]);
    else if (strcmp(argv[first], "--same-process") == 0) same_process = atoi(argv[first + 1]);
    else if (strcmp(argv[first], "--only") == 0) only = atoi(argv[first + 1]);
    else if (strcmp(argv[first], "--solver") == 0) {
      const char *v = argv[first + 1];
      solver_option = !strcmp(v, "condensed") ? MC_INTERFACE_CONDENSED : !strcmp(v, "sparse") ? MC_INTERFACE_SPARSE : MC_INTERFACE_AUTO;
      if (strcmp(v, "auto") && solver_option == MC_INTERFACE_AUTO) {
        fprintf(stderr, "--solver: auto, condensed or sparse\n");
        return 2;
      }
    }
    else break;
    first += 2;
  }
  if (repeat < 1 || repeat > MAX_REPEAT) repeat = 5;
  int count = argc > first ? argc - first : (int)(sizeof defaults / sizeof *defaults);
  printf("| scene | DOFs | unknowns per body | threads (auto) | serial s | auto s | auto/serial | re-solve serial s | re-solve auto s | auto/serial | same u bit for bit | interface solver |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  fflush(stdout);
  int failed = 0;
  for (int k = 0; k < count; ++k) {
    const char *spec = argc > first ? argv[first + k] : defaults[k];
    pid_t child = fork();
    if (child == 0) _exit(run(spec, repeat, threads));
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) failed = 1;
  }
  return failed;
}
