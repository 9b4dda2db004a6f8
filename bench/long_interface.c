/*
 * long_interface.c - the cost of a long contact interface (docs/benchmarks.md, "Long contact
 * interfaces"; docs/robustness.md, "Known limitations").
 *
 * Two strips 0.4 high, one on the other: body 1 of nx x 4 squares (P1, 2 triangles each) on
 * body 2 of round(1.37 nx) x 4 (non-matching meshes), their whole length nx/10 in contact; a
 * uniform pressure p = 0.01 on body 1's top, body 2 held vertically on its bottom and both held
 * horizontally at one left corner node: a uniform stress sigma_yy = -p in both, so every contact
 * pressure is exactly p (a patch test: the "pressure error" column checks the answer).
 * The interface has nx + 1 body-1 nodes, a fraction of the unknowns that does not shrink with
 * the mesh: the case where condensing onto the interface (a dense operator S of order q, from
 * a dense trailing block of each factor) costs most.
 *
 * For each nx prints the contact solve's time and the parts the log reports (contact geometry,
 * interface operator, active-set solve, refinement), the factors' nonzeros, the plain solve of the same
 * meshes and load with body 1 held vertically on its bottom instead of by contact, and the two
 * accuracy infos: MC_INFO_COMPLEMENTARITY (of the condensed problem) and MC_INFO_GAP_RESIDUAL
 * (of the returned displacements).
 *
 * usage: long_interface [nx ...]   (default: 250 500 1000 2000 4000)
 */
#include "mortarcontact.h"
#include "scenes.h"
#include "bench_timing.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

/* The seconds at the end of the log messages of the contact parts ("..., 0.123 s"). */
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
}

static const double kPressure = 0.01;

/* 1. The model: both strips, the supports, the pressure; contact or body 1 held on its bottom. */
static mc_model *strips(const sc_mesh mesh[2], int contact, parts *log) {
  mc_model *m = NULL;
  mc_status st = mc_create(&m);
  for (int b = 0; b < 2 && !st; ++b) {
    st = sc_set_mesh(m, b + 1, &mesh[b], 0);
    if (!st) st = mc_set_material(m, b + 1, 1.0, 0.3);
  }
  const mc_int corner1 = mesh[0].side_nodes[SC_LEFT][0], corner2 = mesh[1].side_nodes[SC_LEFT][0];
  if (!st) st = sc_fix_side(m, 2, &mesh[1], SC_BOTTOM, MC_Y, 0);
  if (!st) st = mc_fix(m, 2, 1, &corner2, MC_X, NULL);
  if (!st) st = mc_fix(m, 1, 1, &corner1, MC_X, NULL);
  double *p = malloc(sizeof(double) * mesh[0].n_side_edges[SC_TOP]);
  for (mc_int e = 0; e < mesh[0].n_side_edges[SC_TOP]; ++e) p[e] = kPressure;
  if (!st) st = mc_add_pressure(m, 1, mesh[0].n_side_edges[SC_TOP], mesh[0].side_edges[SC_TOP], p);
  free(p);
  if (contact) {
    if (!st) st = mc_set_contact(m, 1, mesh[0].n_side_edges[SC_BOTTOM], mesh[0].side_edges[SC_BOTTOM]);
    if (!st) st = mc_set_contact(m, 2, mesh[1].n_side_edges[SC_TOP], mesh[1].side_edges[SC_TOP]);
  } else if (!st) {
    st = sc_fix_side(m, 1, &mesh[0], SC_BOTTOM, MC_Y, 0);
  }
  if (!st && log) st = mc_set_log_callback(m, note_parts, log);
  if (st) {
    fprintf(stderr, "model: %s\n", mc_errmsg(m));
    mc_destroy(m);
    return NULL;
  }
  return m;
}

int main(int argc, char **argv) {
  static const int defaults[] = {250, 500, 1000, 2000, 4000};
  const int count = argc > 1 ? argc - 1 : (int)(sizeof defaults / sizeof *defaults);
  printf("| nx | contact nodes | DOFs | nnz(L) contact | nnz(L) plain | contact solve s | geometry s | interface operator s | active-set s | refinement s | plain solve s | contact/plain | pressure error / p | MC_INFO_COMPLEMENTARITY | MC_INFO_GAP_RESIDUAL |\n");
  printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < count; ++k) {
    const int nx = argc > 1 ? atoi(argv[k + 1]) : defaults[k];
    const int nx2 = (int)lround(1.37 * nx);
    const double length = 0.1 * nx;
    sc_mesh mesh[2];
    if (nx < 1 || sc_mesh_rect(&mesh[0], 3, nx, 4, 0, 0, length, 0.4, 0, 1) ||
        sc_mesh_rect(&mesh[1], 3, nx2, 4, 0, -0.4, length, 0.4, 0, 2)) {
      fprintf(stderr, "bad size %s\n", argc > 1 ? argv[k + 1] : "");
      return 1;
    }
    /* 2. The contact solve, timed from mc_solve to its return. */
    parts log = {0, 0, 0, 0};
    mc_model *m = strips(mesh, 1, &log);
    if (!m) return 1;
    double start = bench_wall();
    if (mc_solve(m)) {
      fprintf(stderr, "nx %d: %s\n", nx, mc_errmsg(m));
      return 1;
    }
    const double t_contact = bench_wall() - start;
    int64_t dofs = 0, nnz_contact = 0, nnz_plain = 0;
    mc_get_info_int(m, MC_INFO_DOFS, &dofs);
    mc_get_info_int(m, MC_INFO_FACTOR_NNZ, &nnz_contact);
    double complementarity = 0, gap_residual = 0;
    mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity);
    mc_get_info_real(m, MC_INFO_GAP_RESIDUAL, &gap_residual);
    /* 3. Its answer against the exact one: every contact pressure p. */
    mc_int n = 0;
    mc_get_contact_count(m, &n);
    double *pressure = malloc(sizeof(double) * (n > 0 ? n : 1)), worst = n > 0 ? 0 : INFINITY;
    mc_get_contact_pressure(m, pressure);
    for (mc_int j = 0; j < n; ++j) worst = fmax(worst, fabs(pressure[j] - kPressure) / kPressure);
    free(pressure);
    mc_destroy(m);
    /* 4. The plain solve of the same meshes and load. */
    mc_model *plain = strips(mesh, 0, NULL);
    if (!plain) return 1;
    start = bench_wall();
    if (mc_solve(plain)) {
      fprintf(stderr, "nx %d, plain: %s\n", nx, mc_errmsg(plain));
      return 1;
    }
    const double t_plain = bench_wall() - start;
    mc_get_info_int(plain, MC_INFO_FACTOR_NNZ, &nnz_plain);
    mc_destroy(plain);
    printf("| %d | %d | %ld | %ld | %ld | %.3f | %.3f | %.3f | %.3f | %.3f | %.4f | %.0f | %.1e | %.1e | %.1e |\n", nx,
           (int)n, (long)dofs, (long)nnz_contact, (long)nnz_plain, t_contact, log.geometry, log.interface, log.active_set,
           log.refinement, t_plain, t_contact / t_plain, worst, complementarity, gap_residual);
    fflush(stdout);
    sc_mesh_free(&mesh[0]);
    sc_mesh_free(&mesh[1]);
  }
  return 0;
}
