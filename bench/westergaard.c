/*
 * westergaard.c - a long interface with many separate contact patches: Westergaard's periodic
 * wavy contact (K. L. Johnson, Contact Mechanics, section 13.2), against its closed form.
 *
 * The scene (tests/westergaard_scene.h): two flat rectangular bodies N wavelengths long (L = 1),
 * body 1 on body 2, non-matching structured meshes (Q1 by default; body 1 n cells (nodes) per
 * wavelength along the interface, body 2 0.83 n), each one wavelength deep with rows graded from
 * the interface; the waviness Delta (1 - cos(2 pi x / L)), Delta = 1e-3 L, is body 1's initial gap
 * (mc_set_gap_offset), so that the crests x = 0, L, 2L, ... touch first. Side walls on rollers,
 * body 2's bottom on rollers, the mean pressure pm = 0.3 p* on body 1's top (p* = pi E* Delta / L,
 * full contact), body 1 held vertically by contact alone. Westergaard: a patch of half-width a,
 * sin^2(pi a / L) = pm / p*, around every crest, peak pressure p0 = 2 sqrt(pm p*).
 * At the default size (N = 100, n = 40): 4001 body-1 contact nodes, 101 patches (99 whole ones
 * and a half one at each wall), 284199 unknowns. Why this mesh (Q1, one wavelength deep, rows
 * graded by 1.25, the waviness as gap offsets): measured, see tests/westergaard_scene.h.
 *
 * For each interface solver asked for, prints: the solver that ran (MC_INFO_INTERFACE_SOLVER),
 * n (body-1 nodes, i.e. cells, per wavelength), N, DOFs, contact nodes, active nodes, patches,
 * MC_INFO_ITERATIONS; the crest-node pressure averaged over the interior crests against
 * 2 sqrt(pm p*) (relative error, and the spread over the crests), the nodal profile error within
 * 0.8 a; the half-width a (last active node + h/2, averaged over crests and sides) against the
 * closed form, also in units of the spacing h; the time of the contact solve (mc_solve, median of
 * -r runs, a fresh model each; the parts its log reports in the first run: contact geometry,
 * interface operator, active-set solve, refinement, as in bench/long_interface.c, 0 where a path
 * does not log one), of the plain solve (the same meshes and loads, body 1 held vertically on its
 * bottom by supports instead of contact, as in bench/long_interface.c), and their ratio;
 * MC_INFO_GAP_RESIDUAL. With --both, the condensed and sparse solvers side by side, and the
 * largest difference of their pressures.
 *
 * usage: westergaard [-N wavelengths] [-n nodes per wavelength] [-r repeats]
 *                    [-s auto|condensed|sparse] [--both] [-t 3|4] [-d depth] [-g grading] [-p pm/p*] [--wavy-mesh]
 *   defaults: -N 100 -n 40 -r 1 -s auto -t 4 -d 1 -g 1.25 -p 0.3
 *   WESTERGAARD_LOG=1: every contact solve's log messages on stderr (bench/interface_choice.py
 *   reads the automatic choice's estimates from them)
 *   e.g. the closed form at increasing resolution, cheap:
 *     for n in 20 40 80 160; do build/bench/westergaard -N 4 -n $n -s condensed -r 3; done
 */
#include "mortarcontact.h"
#include "scenes.h"
#include "westergaard_scene.h"
#include "bench_timing.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *solver_name(long s) {
  return s == MC_INTERFACE_AUTO        ? "auto"
         : s == MC_INTERFACE_CONDENSED ? "condensed"
         : s == MC_INTERFACE_SPARSE    ? "sparse"
                                       : "?";
}

/* The seconds at the end of the log messages of the contact parts ("..., 0.123 s"), as in
   bench/long_interface.c; parts a path does not log stay 0. */
typedef struct parts {
  double geometry, interface, active_set, refinement;
} parts;

static double trailing_seconds(const char *message) {
  const char *comma = strrchr(message, ',');
  return comma ? atof(comma + 1) : 0;
}

static void note_parts(void *user, mc_log_level level, const char *message) {
  (void)level;
  parts *p = user;
  if (strncmp(message, "contact geometry", 16) == 0) p->geometry = trailing_seconds(message);
  if (strncmp(message, "interface operator", 18) == 0) p->interface = trailing_seconds(message);
  if (strncmp(message, "active-set solve", 16) == 0) p->active_set = trailing_seconds(message);
  if (strncmp(message, "refinement", 10) == 0) p->refinement = trailing_seconds(message);
  if (getenv("WESTERGAARD_LOG")) fprintf(stderr, "  log: %s\n", message);
}

static void usage(void) {
  fprintf(stderr, "usage: westergaard [-N wavelengths] [-n nodes per wavelength] [-r repeats] "
                  "[-s auto|condensed|sparse] [--both] [-t 3|4] [-d depth] [-g grading] [-p pm/p*] [--wavy-mesh]\n");
}

/* 1. The contact solve with one interface solver: r fresh models, mc_solve timed; the first
      one's answer measured (and its pressures kept in *pressure, caller frees). */
static int contact_runs(const wg_scene *s, int solver, int repeats, wg_result *res, double *t_median,
                        parts *log, double **pressure, mc_int *q) {
  double *times = malloc(sizeof(double) * (size_t)repeats);
  for (int k = 0; k < repeats; ++k) {
    mc_model *m = wg_model(s, 1, solver);
    if (!m) return 1;
    parts mine = {0, 0, 0, 0};
    mc_set_log_callback(m, note_parts, &mine);
    const double start = bench_wall();
    if (mc_solve(m)) {
      fprintf(stderr, "contact solve (%s): %s\n", solver_name(solver), mc_errmsg(m));
      mc_destroy(m);
      return 1;
    }
    times[k] = bench_wall() - start;
    if (k == 0) *log = mine; /* the parts of the first run */
    if (k == 0) {
      mc_get_contact_count(m, q);
      *pressure = malloc(sizeof(double) * (size_t)(*q > 0 ? *q : 1));
      if (wg_measure(m, s, res, *pressure)) {
        fprintf(stderr, "measuring the contact answer failed: %s\n", mc_errmsg(m));
        mc_destroy(m);
        return 1;
      }
    }
    mc_destroy(m);
  }
  *t_median = bench_median(times, repeats);
  free(times);
  return 0;
}

/* 2. The plain solve: the same meshes and loads, body 1 on supports instead of contact. */
static int plain_runs(const wg_scene *s, int repeats, double *t_median) {
  double *times = malloc(sizeof(double) * (size_t)repeats);
  for (int k = 0; k < repeats; ++k) {
    mc_model *m = wg_model(s, 0, 0);
    if (!m) return 1;
    const double start = bench_wall();
    if (mc_solve(m)) {
      fprintf(stderr, "plain solve: %s\n", mc_errmsg(m));
      mc_destroy(m);
      return 1;
    }
    times[k] = bench_wall() - start;
    mc_destroy(m);
  }
  *t_median = bench_median(times, repeats);
  free(times);
  return 0;
}

int main(int argc, char **argv) {
  wg_params prm = wg_default_params();
  int repeats = 1, both = 0, solver = MC_INTERFACE_AUTO;
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i], *next = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--both")) both = 1;
    else if (!strcmp(a, "--wavy-mesh")) prm.wavy_mesh = 1;
    else if (!strcmp(a, "-h") || !strcmp(a, "--help")) return usage(), 0;
    else if (next && !strcmp(a, "-N")) prm.wavelengths = atoi(next), ++i;
    else if (next && !strcmp(a, "-n")) prm.cells = atoi(next), ++i;
    else if (next && !strcmp(a, "-r")) repeats = atoi(next), ++i;
    else if (next && !strcmp(a, "-t")) prm.npc = atoi(next), ++i;
    else if (next && !strcmp(a, "-d")) prm.depth = atof(next), ++i;
    else if (next && !strcmp(a, "-g")) prm.grading = atof(next), ++i;
    else if (next && !strcmp(a, "-p")) prm.load = atof(next), ++i;
    else if (next && !strcmp(a, "-s")) {
      ++i;
      if (!strcmp(next, "auto")) solver = MC_INTERFACE_AUTO;
      else if (!strcmp(next, "condensed")) solver = MC_INTERFACE_CONDENSED;
      else if (!strcmp(next, "sparse")) solver = MC_INTERFACE_SPARSE;
      else return usage(), 2;
    } else return usage(), 2;
  }
  if (repeats < 1) return usage(), 2;
  /* 3. The scene and its closed form. */
  wg_scene s;
  if (wg_scene_build(&s, &prm)) {
    fprintf(stderr, "bad scene parameters\n");
    return usage(), 2;
  }
  printf("Westergaard: N %d wavelengths, n %d body-1 cells per wavelength (body 2: %d in all), %s, depth %g L "
         "(rows %d and %d, grading %g), waviness as %s\n",
         prm.wavelengths, prm.cells, s.mesh[1].nx, prm.npc == 4 ? "Q1" : "P1", prm.depth, s.mesh[0].ny, s.mesh[1].ny,
         prm.grading, prm.wavy_mesh ? "a wavy body-2 mesh" : "gap offsets");
  printf("  E* %.6g, p* %.6g, pm/p* %g; closed form: p0 = 2 sqrt(pm p*) = %.6g, a = %.6g L (%.2f h)\n", s.e_star,
         s.p_star, prm.load, s.p0_exact, s.a_exact, s.a_exact / (s.length / prm.cells));
  /* 4. The plain solve once per invocation, then the contact solve(s). */
  double t_plain = 0;
  if (plain_runs(&s, repeats, &t_plain)) return 1;
  printf("| asked | ran | nodes per wavelength | N | DOFs | contact nodes | active | patches | iterations | "
         "p0 crest mean | p0 error | p0 spread | profile error | a | a error | a error / h | contact solve s | "
         "geometry s | interface operator s | active-set s | refinement s | plain solve s | contact/plain | "
         "MC_INFO_GAP_RESIDUAL |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const int solvers[2] = {both ? MC_INTERFACE_CONDENSED : solver, MC_INTERFACE_SPARSE};
  double *pressure[2] = {NULL, NULL};
  mc_int q[2] = {0, 0};
  for (int k = 0; k < (both ? 2 : 1); ++k) {
    wg_result r;
    double t_contact = 0;
    parts log;
    if (contact_runs(&s, solvers[k], repeats, &r, &t_contact, &log, &pressure[k], &q[k])) return 1;
    const char *ran = r.interface_solver == 0 ? "0 (not reported)" : solver_name(r.interface_solver);
    printf("| %s | %s | %d | %d | %ld | %ld | %ld | %d | %ld | %.6g | %+.3f %% | %.3f %% | %.2f %% | %.5f | %+.2f %% | "
           "%+.2f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f | %.1e |\n",
           solver_name(solvers[k]), ran, prm.cells, prm.wavelengths, r.dofs, r.contact_nodes, r.active_nodes, r.patches,
           r.iterations, r.p0_mean, 100 * (r.p0_mean / s.p0_exact - 1), 100 * (r.p0_max - r.p0_min) / s.p0_exact,
           100 * r.profile_error, r.a_mean, 100 * (r.a_mean / s.a_exact - 1), (r.a_mean - s.a_exact) / r.h,
           t_contact, log.geometry, log.interface, log.active_set, log.refinement, t_plain, t_contact / t_plain,
           r.gap_residual);
    fflush(stdout);
  }
  if (both && q[0] == q[1]) {
    double diff = 0;
    for (mc_int j = 0; j < q[0]; ++j) diff = fmax(diff, fabs(pressure[0][j] - pressure[1][j]));
    printf("condensed against sparse: largest pressure difference %.2e p0\n", diff / s.p0_exact);
  }
  free(pressure[0]), free(pressure[1]);
  wg_scene_free(&s);
  return 0;
}
