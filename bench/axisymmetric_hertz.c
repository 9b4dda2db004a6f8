/*
 * axisymmetric_hertz.c - the sphere on a flat (3D Hertz, MC_AXISYMMETRIC) and its cost.
 *
 *   build/bench/axisymmetric_hertz [speed] [h ...]   (default h: 0.04 0.02 0.01 0.007 0.005;
 *                                                      "speed": the speed table only)
 *
 * For each spacing h (both bodies' fine spacing near the contact, examples/scenes) and each
 * of P1/Q1 x mortar/dual: DOFs, p0 and a fitted to the pressure profile against Hertz, a from
 * the last loaded node, the axis node's pressure. Then the speed comparison (one run each):
 * the axisymmetric contact solve against the plane-strain solve of the same meshes
 * (MC_INFO_TIME_TOTAL). docs/benchmarks.md, "Axisymmetric: sphere on a flat", holds a run.
 */
#include "mortarcontact.h"
#include "sphere_on_flat.h"
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
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
