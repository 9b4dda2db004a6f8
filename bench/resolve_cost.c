/*
 * resolve_cost.c - what a re-solve after a load change costs against the first solve, with the
 * results computed on demand (the default) and eagerly (MC_OPTION_EAGER_RESULTS = 1, what every
 * solve did before), in one run (docs/benchmarks.md, "Re-solves and results on demand").
 *
 * Scenes:
 *   hertz:h1  the Hertz scene (examples/scenes/hertz_scene.h, h2 = 1.37 h1, mortar method);
 *   punch:N   a punch on a block: body 2 the unit square [0,1] x [-1,0], P1 on N x N squares,
 *             clamped at its bottom; body 1 the punch [0.375,0.625] x [0,0.25] on (N/4) x (N/4)
 *             squares, its top pressed down by a uniform traction and held at u_x = 0; contact
 *             between the punch's bottom and the block's top (the punch's corners press into it).
 * Each measurement runs in a child process of its own (so that no mode inherits the other's heap);
 * the modes alternate, in turn first. In a child: the first solve (mc_create, the scene, mc_solve,
 * the displacements and contact pressures read back), then three re-solves at other loads (the
 * factorizations reused), each reading the displacements and pressures back and:
 *   re-solve       nothing more;
 *   + estimate     MC_INFO_ERROR_ESTIMATE (on demand: the estimate computed by that call);
 *   + all          the estimate, and both bodies' stresses and nodal stresses.
 * Eager children time the first solve and the plain re-solve (everything is computed anyway).
 * The lazy child also times MC_INFO_ERROR_ESTIMATE read after its first solve (the estimate's own
 * cost; MC_INFO_TIME_RESULTS says the same from inside). Printed: medians of --repeat children per
 * mode, and the ratios first / re-solve of each kind from those medians.
 *
 * usage: resolve_cost [--repeat n] [--threads n] hertz:h1 | punch:N ...
 *        (--threads: MC_OPTION_THREADS of every solve, default the library's automatic)
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "hertz_model.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAX_REPEAT 15

static int threads_option = -1;

typedef struct scene {
  hertz_scene s;    /* the punch is stored in the same struct */
  int is_punch;
  double traction;  /* the punch's downwards traction (hertz: hertz_model_load's) */
} scene;

/* P1 mesh of [x0, x0 + lx] x [y0, y0 + ly], nx x ny squares, two triangles each. */
static int grid(hertz_mesh *m, int nx, int ny, double x0, double y0, double lx, double ly) {
  m->n_nodes = (nx + 1) * (ny + 1), m->n_cells = 2 * nx * ny, m->nodes_per_cell = 3;
  m->xy = malloc(sizeof(double) * 2 * (size_t)m->n_nodes), m->cells = malloc(sizeof(int) * 3 * (size_t)m->n_cells);
  if (!m->xy || !m->cells) return 1;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m->xy[2 * (j * (nx + 1) + i)] = x0 + lx * i / nx;
      m->xy[2 * (j * (nx + 1) + i) + 1] = y0 + ly * j / ny;
    }
  for (int j = 0, c = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i, c += 2) {
      const int a = j * (nx + 1) + i, b = a + 1, d = a + nx + 1, e = d + 1;
      const int t[6] = {a, b, e, a, e, d};
      memcpy(m->cells + 3 * c, t, sizeof t);
    }
  return 0;
}

static int punch_scene(scene *sc, int n) {
  memset(sc, 0, sizeof *sc);
  sc->is_punch = 1, sc->traction = 0.02;
  hertz_scene *s = &sc->s;
  const int np = n / 4 > 1 ? n / 4 : 2;
  if (grid(&s->body[0], np, np, 0.375, 0, 0.25, 0.25) || grid(&s->body[1], n, n, 0, -1, 1, 1)) return 1;
  /* body 1: contact on its bottom (left to right), load on its top (right to left), u_x = 0 on
     its top nodes; body 2: contact on its top (right to left), bottom nodes clamped */
  s->n_contact_edges[0] = np, s->n_contact_edges[1] = n, s->n_top_edges = np;
  s->contact_edges[0] = malloc(sizeof(int) * 2 * np), s->contact_edges[1] = malloc(sizeof(int) * 2 * n);
  s->top_edges = malloc(sizeof(int) * 2 * np);
  s->n_axis_nodes = np + 1, s->axis_nodes = malloc(sizeof(int) * (np + 1));
  s->n_bottom_nodes = n + 1, s->bottom_nodes = malloc(sizeof(int) * (n + 1));
  if (!s->contact_edges[0] || !s->contact_edges[1] || !s->top_edges || !s->axis_nodes || !s->bottom_nodes) return 1;
  for (int i = 0; i < np; ++i) {
    s->contact_edges[0][2 * i] = i, s->contact_edges[0][2 * i + 1] = i + 1;
    s->top_edges[2 * i] = np * (np + 1) + np - i, s->top_edges[2 * i + 1] = np * (np + 1) + np - i - 1;
  }
  for (int i = 0; i < n; ++i)
    s->contact_edges[1][2 * i] = n * (n + 1) + n - i, s->contact_edges[1][2 * i + 1] = n * (n + 1) + n - i - 1;
  for (int i = 0; i <= np; ++i) s->axis_nodes[i] = np * (np + 1) + i;
  for (int i = 0; i <= n; ++i) s->bottom_nodes[i] = i;
  return 0;
}

static mc_status set_load(mc_model *m, const scene *sc, double scale) {
  if (!sc->is_punch) return hertz_model_load(m, &sc->s, scale);
  const hertz_scene *s = &sc->s;
  double *t = malloc(sizeof(double) * 2 * (size_t)s->n_top_edges);
  if (!t) return MC_ERROR_MEMORY;
  for (int e = 0; e < s->n_top_edges; ++e) t[2 * e] = 0, t[2 * e + 1] = -scale * sc->traction;
  mc_status st = mc_clear_loads(m, 1);
  if (!st) st = mc_add_traction(m, 1, s->n_top_edges, s->top_edges, t);
  free(t);
  return st;
}

typedef struct times {
  double first, estimate_first, results_info, resolve, resolve_estimate, resolve_all;
  long dofs;
  int ok;
} times;

/* The displacements and contact pressures, as a host reads them back after every solve. */
static mc_status read_back(mc_model *m, const scene *sc, double *u[2], double *p) {
  mc_status st = MC_OK;
  for (int b = 0; b < 2 && !st; ++b) st = mc_get_displacement(m, b + 1, u[b]);
  (void)sc;
  if (!st) st = mc_get_contact_pressure(m, p);
  return st;
}

static void measure(const scene *sc, int eager, times *out) {
  const hertz_scene *s = &sc->s;
  memset(out, 0, sizeof *out);
  double *u[2], *sigma = NULL, *p = NULL, estimate;
  for (int b = 0; b < 2; ++b) u[b] = malloc(sizeof(double) * 2 * (size_t)s->body[b].n_nodes);
  size_t most = 0;
  for (int b = 0; b < 2; ++b) {
    const size_t n = 4 * (size_t)(s->body[b].n_nodes > s->body[b].n_cells ? s->body[b].n_nodes : s->body[b].n_cells);
    if (n > most) most = n;
  }
  sigma = malloc(sizeof(double) * most);
  mc_model *m = NULL;
  double start = bench_wall();
  mc_status st = mc_create(&m);
  for (int b = 0; b < 2 && !st; ++b) {
    const hertz_mesh *mesh = &s->body[b];
    st = mc_set_mesh(m, b + 1, mesh->n_nodes, mesh->xy, mesh->n_cells, mesh->nodes_per_cell, mesh->cells);
    if (!st) st = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  if (!st) st = mc_fix(m, 1, s->n_axis_nodes, s->axis_nodes, MC_X, NULL);
  if (!st) st = mc_fix(m, 2, s->n_bottom_nodes, s->bottom_nodes, MC_XY, NULL);
  if (!st) st = set_load(m, sc, 1.0);
  if (!st) st = mc_set_contact(m, 1, s->n_contact_edges[0], s->contact_edges[0]);
  if (!st) st = mc_set_contact(m, 2, s->n_contact_edges[1], s->contact_edges[1]);
  if (!st && threads_option >= 0) st = mc_set_option_int(m, MC_OPTION_THREADS, threads_option);
  if (!st && eager) st = mc_set_option_int(m, MC_OPTION_EAGER_RESULTS, 1);
  if (!st) st = mc_solve(m);
  mc_int q = 0;
  if (!st) st = mc_get_contact_count(m, &q);
  p = malloc(sizeof(double) * (size_t)(q + 1));
  if (!st) st = read_back(m, sc, u, p);
  out->first = bench_wall() - start;
  int64_t dofs = 0;
  if (!st) st = mc_get_info_int(m, MC_INFO_DOFS, &dofs);
  out->dofs = (long)dofs;
  if (!st && !eager) {
    start = bench_wall();
    st = mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &estimate);
    out->estimate_first = bench_wall() - start;
    if (!st) st = mc_get_info_real(m, MC_INFO_TIME_RESULTS, &out->results_info);
  }
  /* re-solves: the factorizations and the interface operator reused */
  start = bench_wall();
  if (!st) st = set_load(m, sc, 1.5);
  if (!st) st = mc_solve(m);
  if (!st) st = read_back(m, sc, u, p);
  out->resolve = bench_wall() - start;
  if (!eager) {
    start = bench_wall();
    if (!st) st = set_load(m, sc, 2.0);
    if (!st) st = mc_solve(m);
    if (!st) st = read_back(m, sc, u, p);
    if (!st) st = mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &estimate);
    out->resolve_estimate = bench_wall() - start;
    start = bench_wall();
    if (!st) st = set_load(m, sc, 2.5);
    if (!st) st = mc_solve(m);
    if (!st) st = read_back(m, sc, u, p);
    if (!st) st = mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &estimate);
    for (int b = 0; b < 2 && !st; ++b) {
      st = mc_get_stress(m, b + 1, sigma);
      if (!st) st = mc_get_nodal_stress(m, b + 1, sigma);
    }
    out->resolve_all = bench_wall() - start;
  }
  out->ok = st == MC_OK;
  if (st) fprintf(stderr, "failed: %s\n", mc_errmsg(m));
  mc_destroy(m);
  free(u[0]), free(u[1]), free(sigma), free(p);
}

static int measure_in_child(const scene *sc, int eager, times *out) {
  int fd[2];
  if (pipe(fd) != 0) return 1;
  pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    times t;
    measure(sc, eager, &t);
    ssize_t written = write(fd[1], &t, sizeof t);
    _exit(written == (ssize_t)sizeof t ? 0 : 1);
  }
  close(fd[1]);
  ssize_t got = read(fd[0], out, sizeof *out);
  close(fd[0]);
  waitpid(pid, NULL, 0);
  return got != (ssize_t)sizeof *out || !out->ok;
}

static void run(const char *spec, int repeat) {
  scene sc;
  const char *colon = strchr(spec, ':');
  if (!colon) return;
  int failed = 0;
  if (!strncmp(spec, "punch", 5)) failed = punch_scene(&sc, atoi(colon + 1));
  else memset(&sc, 0, sizeof sc), sc.traction = 0, failed = hertz_scene_build(&sc.s, atof(colon + 1), 1.37 * atof(colon + 1), 0);
  if (failed) {
    fprintf(stderr, "%s: the scene could not be built\n", spec);
    return;
  }
  double first[2][MAX_REPEAT], resolve[2][MAX_REPEAT], resolve_estimate[MAX_REPEAT], resolve_all[MAX_REPEAT];
  double estimate_first[MAX_REPEAT];
  long dofs = 0;
  for (int k = 0; k < repeat; ++k)
    for (int j = 0; j < 2; ++j) {
      const int eager = (k + j) % 2; /* in turn first */
      times t;
      if (measure_in_child(&sc, eager, &t)) {
        fprintf(stderr, "%s: a solve failed\n", spec);
        return;
      }
      dofs = t.dofs;
      first[eager][k] = t.first, resolve[eager][k] = t.resolve;
      if (!eager)
        resolve_estimate[k] = t.resolve_estimate, resolve_all[k] = t.resolve_all, estimate_first[k] = t.estimate_first;
      fprintf(stderr, "%s %s: first %.4f s, re-solve %.5f s", spec, eager ? "eager" : "on demand", t.first, t.resolve);
      if (!eager)
        fprintf(stderr, ", + estimate %.5f s, + all %.5f s; the estimate after the first solve %.4f s (info %.4f s)",
                t.resolve_estimate, t.resolve_all, t.estimate_first, t.results_info);
      fprintf(stderr, "\n");
    }
  const double f = bench_median(first[0], repeat), fe = bench_median(first[1], repeat);
  const double r = bench_median(resolve[0], repeat), re = bench_median(resolve[1], repeat);
  const double rest = bench_median(resolve_estimate, repeat), rall = bench_median(resolve_all, repeat);
  const double est = bench_median(estimate_first, repeat);
  printf("| %s | %ld | %.3f | %.3f | %.2f | %.4f | %.0f | %.4f | %.1f | %.4f | %.1f | %.4f | %.1f | %.3f (%.1f %%) |\n", spec, dofs,
         f, fe, f / fe, r, f / r, rest, f / rest, rall, f / rall, re, fe / re, est, 100 * est / f);
  fflush(stdout);
  hertz_scene_free(&sc.s);
}

int main(int argc, char **argv) {
  int repeat = 5;
  printf("| scene | DOFs | first solve s | first, eager s | on demand / eager | re-solve s | first / re-solve | "
         "re-solve + estimate s | first / that | re-solve + estimate + stresses s | first / that | eager re-solve s | "
         "eager first / re-solve | the estimate after the first solve, s (share of it) |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  fflush(stdout); /* before the children are forked */
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = atoi(argv[++i]);
      if (repeat < 1 || repeat > MAX_REPEAT) repeat = 5;
    } else if (!strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads_option = atoi(argv[++i]);
    } else if (strchr(argv[i], ':')) {
      run(argv[i], repeat);
    } else {
      fprintf(stderr, "usage: %s [--repeat n] [--threads n] hertz:h1 | punch:N ...\n", argv[0]);
      return 2;
    }
  }
  return 0;
}
