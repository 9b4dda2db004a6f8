/*
 * hertz_phases.c - where the time of a small Hertz solve goes, phase by phase, for each cell kind
 * (docs/notes/quadratic-cells.md, "Where a small solve's time goes"; issue 21).
 *
 * The plane-strain Hertz scene of examples/scenes/hertz_scene.h (as bench/hertz_quadratic.c:
 * h2 = 1.37 h1, the force 0.01 as a traction on body 1's top, MC_NORMAL_MORTAR), built once per
 * mesh; then `repeat` times the whole host sequence, mc_create to mc_destroy, and the median of
 * each phase:
 *   wall        mc_create .. mc_solve returned (what hertz_quadratic's time holds, less reading
 *               the results back);
 *   mesh        mc_create and both bodies' mc_set_mesh, materials, supports and loads (mesh
 *               validation: node roles, the Jacobian check of quadratic cells, the boundary);
 *   assembly, analysis, factorization, solve, contact
 *               MC_INFO_TIME_ASSEMBLY, _ANALYSIS, _FACTORIZATION, _SOLVE, _CONTACT (each the sum
 *               over both bodies);
 *   rest        MC_INFO_TIME_TOTAL less those five: the loads, the recovery of displacements,
 *               reactions and stresses, the error estimate, the interface solver's choice.
 * Threads: the library's default (automatic: one thread below its size threshold).
 *
 * usage: hertz_phases [--repeat n] [--method mortar|dual] RUN ...
 *   RUN = KIND:h1[:growth:fine], KIND one of P1 Q1 T6 Q8 Q9; growth and fine as
 *   hertz_scene_build_graded (defaults 1.15 and 0.4). --method dual: T6, Q8 and Q9 by
 *   MC_METHOD_DUAL_MORTAR (P1 and Q1 keep MC_METHOD_MORTAR). Default --repeat 41.
 * Example (the meshes of docs/benchmarks.md's best gradings at p0 within 0.3 and 0.1 %):
 *   build/bench/hertz_phases --method dual P1:0.019249:2:0.15 Q8:0.0385:3:0.15 P1:0.0147:1.5:0.15 T6:0.035229:3:0.2
 * Exit status 1 if a solve failed, 2 on a bad command line.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench_timing.h"
#include "cell_kind_name.h"
#include "hertz_model.h"
#include "hertz_scene.h"
#include "mortarcontact.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { PHASES = 8, MAX_REPEAT = 1001 };
static const char *phase_name[PHASES] = {"wall", "mesh", "assembly", "analysis", "factorization", "solve", "contact",
                                         "rest"};

/* One run of the host sequence; t[PHASES] in seconds. Returns 0, or 1 on a failed call. */
static int run_once(const hertz_scene *s, int dual, double t[PHASES], int64_t *dofs, int64_t *iterations) {
  mc_model *m = NULL;
  int failed = 1;
  const double start = bench_wall();
  if (mc_create(&m) != MC_OK || hertz_model_bodies(m, s) != MC_OK) goto done;
  const double meshed = bench_wall();
  if (mc_set_contact(m, 1, s->n_contact_edges[0], s->contact_edges[0]) != MC_OK ||
      mc_set_contact(m, 2, s->n_contact_edges[1], s->contact_edges[1]) != MC_OK ||
      mc_set_option_int(m, MC_OPTION_METHOD,
                        dual && s->body[0].nodes_per_cell > 4 ? MC_METHOD_DUAL_MORTAR : MC_METHOD_MORTAR) != MC_OK ||
      mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, MC_NORMAL_MORTAR) != MC_OK || mc_solve(m) != MC_OK) {
    fprintf(stderr, "solve failed: %s\n", mc_errmsg(m));
    goto done;
  }
  t[0] = bench_wall() - start, t[1] = meshed - start;
  const int info[5] = {MC_INFO_TIME_ASSEMBLY, MC_INFO_TIME_ANALYSIS, MC_INFO_TIME_FACTORIZATION, MC_INFO_TIME_SOLVE,
                       MC_INFO_TIME_CONTACT};
  double total = 0;
  mc_get_info_real(m, MC_INFO_TIME_TOTAL, &total);
  t[7] = total;
  for (int k = 0; k < 5; ++k) mc_get_info_real(m, info[k], &t[2 + k]), t[7] -= t[2 + k];
  mc_get_info_int(m, MC_INFO_DOFS, dofs);
  mc_get_info_int(m, MC_INFO_ITERATIONS, iterations);
  failed = 0;
done:
  mc_destroy(m);
  return failed;
}

/* KIND:h1[:growth:fine] into its parts; 0, or -1 if it is not one. */
static int parse_run(const char *spec, int *npc, double *h1, double *growth, double *fine) {
  const char *colon = strchr(spec, ':');
  char kind[8] = {0};
  if (!colon || (size_t)(colon - spec) >= sizeof kind) return -1;
  memcpy(kind, spec, (size_t)(colon - spec));
  *growth = 1.15, *fine = 0.4, *npc = 0;
  const int fields = sscanf(colon + 1, "%lf:%lf:%lf", h1, growth, fine);
  for (int k = 3; k <= 9; ++k)
    if (!strcmp(kind, cell_kind_name(k))) *npc = k;
  return *npc && (fields == 1 || fields == 3) && *h1 > 0 ? 0 : -1;
}

int main(int argc, char **argv) {
  int repeat = 41, dual = 0, n_runs = 0, status = 0;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--method") && i + 1 < argc) {
      const char *v = argv[++i];
      if (strcmp(v, "dual") && strcmp(v, "mortar")) goto usage;
      dual = !strcmp(v, "dual");
    } else {
      int npc;
      double h1, growth, fine;
      if (parse_run(argv[i], &npc, &h1, &growth, &fine) != 0) goto usage;
      ++n_runs;
    }
  }
  if (n_runs == 0 || repeat < 1 || repeat > MAX_REPEAT) goto usage;
  double *t[PHASES];
  for (int k = 0; k < PHASES; ++k) t[k] = malloc(sizeof(double) * (size_t)repeat);
  printf("| kind | h1 | growth | fine | DOFs | iterations |");
  for (int k = 0; k < PHASES; ++k) printf(" %s ms |", phase_name[k]);
  printf("\n|---|---|---|---|---|---|");
  for (int k = 0; k < PHASES; ++k) printf("---|");
  printf("\n");
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--repeat") || !strcmp(argv[i], "--method")) {
      ++i;
      continue;
    }
    int npc;
    double h1, growth, fine;
    parse_run(argv[i], &npc, &h1, &growth, &fine);  /* (checked above) */
    hertz_scene s;
    if (hertz_scene_build_graded(&s, h1, 1.37 * h1, npc, growth, fine) != 0) {
      fprintf(stderr, "%s: the scene could not be built (growth 1.01..3, fine 0..0.5)\n", argv[i]);
      status = 1;
      continue;
    }
    int64_t dofs = 0, iterations = 0;
    double one[PHASES];
    int ok = 1;
    for (int r = 0; r < repeat && ok; ++r) {
      ok = !run_once(&s, dual, one, &dofs, &iterations);
      for (int k = 0; k < PHASES && ok; ++k) t[k][r] = one[k];
    }
    hertz_scene_free(&s);
    if (!ok) {
      status = 1;
      continue;
    }
    printf("| %s | %g | %g | %g | %ld | %ld |", cell_kind_name(npc), h1, growth, fine, (long)dofs, (long)iterations);
    for (int k = 0; k < PHASES; ++k) printf(" %.3f |", 1e3 * bench_median(t[k], repeat));
    printf("\n");
  }
  for (int k = 0; k < PHASES; ++k) free(t[k]);
  return status;
usage:
  fprintf(stderr,
          "usage: %s [--repeat n (1..%d)] [--method mortar|dual] KIND:h1[:growth:fine] ...\n"
          "       (KIND: P1 Q1 T6 Q8 Q9)\n",
          argv[0], MAX_REPEAT);
  return 2;
}
