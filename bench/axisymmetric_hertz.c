/*
 * axisymmetric_hertz.c - the sphere on a flat (3D Hertz, MC_AXISYMMETRIC) and its cost.
 *
 *   build/bench/axisymmetric_hertz [speed] [h ...]   (default h: 0.04 0.02 0.01 0.007 0.005;
 *                                                      "speed": the speed table only)
 *   build/bench/axisymmetric_hertz cells [--multiplier linear|quadratic] [--method mortar|dual] KIND:h,h,...
 *                                        (--method dual: T6, Q8, Q9 by dual mortar, P1 by mortar)
 *                                        (KIND: P1 Q1 T6 Q8 Q9; MC_OPTION_MULTIPLIER, default linear)
 *
 * "cells": the cell kinds side by side (mortar, sphere_on_flat_solve_cells; h a cell's size):
 * DOFs, p0 and a fitted against Hertz, the larger of the two errors, and for each kind other
 * than P1 the DOFs P1 needs for that larger error (log-log interpolated between the two P1
 * sizes where P1's error, from that size on, gets there); then the same with a_moment (from the
 * contact forces, no fit) in place of the fitted a. docs/benchmarks.md "Axisymmetric:
 * quadratic cells".
 *
 * For each spacing h (both bodies' fine spacing near the contact, examples/scenes) and each
 * of P1/Q1 x mortar/dual: DOFs, p0 and a fitted to the pressure profile against Hertz, a from
 * the last loaded node, the axis node's pressure. Then the speed comparison (one run each):
 * the axisymmetric contact solve against the plane-strain solve of the same meshes
 * (MC_INFO_TIME_TOTAL). docs/benchmarks.md, "Axisymmetric: sphere on a flat", holds a run.
 */
#include "cell_kind_name.h"
#include "mortarcontact.h"
#include "sphere_on_flat.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct kind_row {
  int npc;
  double h;
  sphere_result r;
  double err[2]; /* max(|p0 error|, |a error|) with a fitted, and with a_moment */
} kind_row;

/* The DOFs P1 needs for a larger error `e` (measure `which`): log-log interpolated between the
   two P1 sizes where P1's error, from that size on (envelope env over the P1 rows p1, by DOFs),
   gets there; NAN beyond P1's finest; *at_coarsest when already P1's coarsest does. */
static double p1_dofs_at(const kind_row *rows, const int *p1, int m, const double *env, double e, int *at_coarsest) {
  *at_coarsest = 0;
  if (m == 0 || !isfinite(e)) return NAN;
  if (env[0] <= e) return *at_coarsest = 1, (double)rows[p1[0]].r.dofs;
  for (int k = 1; k < m; ++k)
    if (env[k] <= e) {
      double t = env[k] > 0 ? log(e / env[k - 1]) / log(env[k] / env[k - 1]) : 1;
      double lo = log((double)rows[p1[k - 1]].r.dofs), hi = log((double)rows[p1[k]].r.dofs);
      return exp(lo + t * (hi - lo));
    }
  return NAN;
}

/* The cell kinds side by side: see the file header. */
static int compare_kinds(int argc, char **argv) {
  static kind_row rows[128];
  int n = 0, multiplier = MC_MULTIPLIER_LINEAR, dual = 0;
  for (int i = 0; i < argc; ++i) {
    if (!strcmp(argv[i], "--method") && i + 1 < argc) {
      ++i;
      if (!strcmp(argv[i], "dual")) dual = 1;
      else if (strcmp(argv[i], "mortar")) {
        fprintf(stderr, "cells: --method takes mortar or dual, got %s\n", argv[i]);
        return 2;
      }
      continue;
    }
    if (!strcmp(argv[i], "--multiplier") && i + 1 < argc) {
      ++i;
      if (!strcmp(argv[i], "linear")) multiplier = MC_MULTIPLIER_LINEAR;
      else if (!strcmp(argv[i], "quadratic")) multiplier = MC_MULTIPLIER_QUADRATIC;
      else {
        fprintf(stderr, "cells: --multiplier takes linear or quadratic, got %s\n", argv[i]);
        return 2;
      }
      continue;
    }
    const char *colon = strchr(argv[i], ':');
    int npc = 0;
    for (int k = 3; k <= 9; ++k)
      if (colon && colon - argv[i] == 2 && !strncmp(argv[i], cell_kind_name(k), 2)) npc = k;
    if (!npc) {
      fprintf(stderr, "cells: expected KIND:h,h,... (KIND: P1 Q1 T6 Q8 Q9), got %s\n", argv[i]);
      return 2;
    }
    for (const char *q = colon + 1; *q && n < 128;) {
      char *end;
      double h = strtod(q, &end);
      if (end == q || !(h > 0)) {
        fprintf(stderr, "cells: bad size in %s\n", argv[i]);
        return 2;
      }
      rows[n].npc = npc, rows[n++].h = h;
      q = *end == ',' ? end + 1 : end;
    }
  }
  printf("| cells | h | DOFs | p0 fitted | error | a fitted | error | larger error | solve s (library) | P1 DOFs at that "
         "error | DOFs / P1's | a_moment error | larger of p0's and a_moment's | P1 DOFs at that error | DOFs / P1's |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 0; i < n; ++i) {
    kind_row *w = &rows[i];
    const int method = dual && w->npc > 4 ? MC_METHOD_DUAL_MORTAR : MC_METHOD_MORTAR; /* P1 stays the paper's */
    int st = sphere_on_flat_solve_cells(w->h, w->npc, method, MC_NORMAL_MORTAR, MC_AXISYMMETRIC, multiplier, &w->r);
    if (st) {
      printf("| %s | %g | failed (%d) |\n", cell_kind_name(w->npc), w->h, st);
      return 1;
    }
    w->err[0] = fmax(fabs(w->r.p0 / w->r.p0_hertz - 1), fabs(w->r.a / w->r.a_hertz - 1));
    w->err[1] = fmax(fabs(w->r.p0 / w->r.p0_hertz - 1), fabs(w->r.a_moment / w->r.a_hertz - 1));
  }
  /* P1's envelope: from each P1 size on (by DOFs), the largest error */
  int p1[128], m = 0;
  for (int i = 0; i < n; ++i)
    if (rows[i].npc == 3) p1[m++] = i;
  for (int i = 1; i < m; ++i)
    for (int k = i; k > 0 && rows[p1[k - 1]].r.dofs > rows[p1[k]].r.dofs; --k) {
      int t = p1[k];
      p1[k] = p1[k - 1], p1[k - 1] = t;
    }
  double env[2][128];
  for (int e = 0; e < 2; ++e)
    for (int k = m - 1; k >= 0; --k) env[e][k] = fmax(rows[p1[k]].err[e], k + 1 < m ? env[e][k + 1] : 0);
  for (int i = 0; i < n; ++i) {
    const kind_row *w = &rows[i];
    printf("| %s | %g | %ld | %.5g | %+.2f %% | %.5g | %+.2f %% | %.2f %% | %.3f |", cell_kind_name(w->npc), w->h, w->r.dofs,
           w->r.p0, 100 * (w->r.p0 / w->r.p0_hertz - 1), w->r.a, 100 * (w->r.a / w->r.a_hertz - 1), 100 * w->err[0],
           w->r.seconds);
    for (int e = 0; e < 2; ++e) {
      if (e == 1) printf(" %+.2f %% | %.2f %% |", 100 * (w->r.a_moment / w->r.a_hertz - 1), 100 * w->err[1]);
      int coarsest;
      const double dofs = w->npc == 3 ? NAN : p1_dofs_at(rows, p1, m, env[e], w->err[e], &coarsest);
      if (w->npc == 3 || !isfinite(w->err[e])) printf(" - | - |");
      else if (!isfinite(dofs)) printf(" beyond P1's finest | - |");
      else printf(" %s%.0f | %.2f |", coarsest ? "<= " : "", dofs, w->r.dofs / dofs);
    }
    printf("\n");
    fflush(stdout);
  }
  return 0;
}

int main(int argc, char **argv) {
  if (argc > 1 && !strcmp(argv[1], "cells")) return compare_kinds(argc - 2, argv + 2);
  double default_h[] = {0.04, 0.02, 0.01, 0.007, 0.005}, h[16];
  int n = 0, k, quads, method, speed_only = argc > 1 && argv[1][0] == 's';
  for (k = 1 + speed_only; k < argc && n < 16; ++k) h[n++] = atof(argv[k]);
  if (n == 0)
    for (k = 0; k < 5; ++k) h[n++] = default_h[k];
  if (!speed_only)
    printf("| cells | method | h | DOFs | p0 fitted | error | a fitted | error | a (last loaded node) | error | "
         "axis node p / p0 Hertz |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (quads = 0; quads <= 1 && !speed_only; ++quads)
    for (method = MC_METHOD_MORTAR; method <= MC_METHOD_DUAL_MORTAR; ++method)
      for (k = 0; k < n; ++k) {
        sphere_result r;
        int st = sphere_on_flat(h[k], quads, method, &r);
        if (st) {
          printf("h = %g: failed (%d)\n", h[k], st);
          return 1;
        }
        printf("| %s | %s | %g | %ld | %.5g | %+.2f %% | %.5g | %+.2f %% | %.5g | %+.2f %% | %.3f |\n", quads ? "Q1" : "P1",
               method == MC_METHOD_MORTAR ? "mortar" : "dual", h[k], r.dofs, r.p0, 100 * (r.p0 / r.p0_hertz - 1), r.a,
               100 * (r.a / r.a_hertz - 1), r.a_nodes, 100 * (r.a_nodes / r.a_hertz - 1), r.axis_pressure / r.p0_hertz);
        fflush(stdout);
      }
  printf("\nSpeed (P1, mortar, one run each): axisymmetric against plane strain on the same meshes\n\n"
         "| h | DOFs | axisymmetric s (assembly, factorization, contact; iterations) | plane strain s (same) | ratio |\n"
         "|---|---|---|---|---|\n");
  for (k = 0; k < n; ++k) {
    sphere_result axi, plane;
    if (sphere_on_flat_solve(h[k], 0, MC_METHOD_MORTAR, MC_NORMAL_MORTAR, MC_AXISYMMETRIC, &axi) ||
        sphere_on_flat_solve(h[k], 0, MC_METHOD_MORTAR, MC_NORMAL_MORTAR, MC_PLANE_STRAIN, &plane)) {
      printf("h = %g: failed\n", h[k]);
      return 1;
    }
    printf("| %g | %ld | %.3f (%.3f, %.3f, %.3f; %d) | %.3f (%.3f, %.3f, %.3f; %d) | %.2f |\n", h[k], axi.dofs, axi.seconds,
           axi.seconds_assembly, axi.seconds_factorization, axi.seconds_contact, axi.iterations, plane.seconds,
           plane.seconds_assembly, plane.seconds_factorization, plane.seconds_contact, plane.iterations,
           axi.seconds / plane.seconds);
    fflush(stdout);
  }
  return 0;
}
