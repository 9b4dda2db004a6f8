/*
 * cylinders_layout.c - two cylinders in contact (R = 1 on R = 3, plane strain) meshed with each
 * cell kind and triangle layout, and the node-to-node ripple of the nodal contact pressures
 * (docs/robustness.md, "Quadratic cells").
 *
 * Body 1: the part |x| <= 0.6, y <= 0.6 of the disc of radius 1 centred at (0, 1) (its arc touches
 * the origin); body 2: the part |x| <= 1.5, y >= -1.5 of the disc of radius 3 centred at (0, -3).
 * Both are mapped structured grids, spacing about h at the contact point, growing away from it;
 * every node (a quadratic cell's mid-edge nodes included) is placed by the same map, so the arcs'
 * nodes lie on the circles and quadratic edges are curved. E = 1, nu = 0.3 both; body 1 loaded by
 * P = 0.01 on its top, u_x = 0 on its axis, held vertically by contact alone; body 2 clamped at
 * its bottom. Triangles: one-way diagonals, or criss-cross (alternating square by square).
 *
 * Ripple: the largest deviation |p_j - (p_{j-1} + p_{j+1}) / 2| of a nodal pressure from the
 * mean of its two neighbours along body 1's surface (corner and mid-edge positions alike, in
 * order) inside 0.6 a, over p0: node-to-node oscillation. A smooth profile gives about
 * p0 d^2 / a^2 (d the spacing of the positions): 0.3 % at d = a / 13. p0: the largest nodal pressure; Hertz:
 * 1/R* = 1/1 + 1/3, 1/E* = 2 (1 - nu^2) / E.
 *
 * A quadratic body 1 is solved with both MC_OPTION_MULTIPLIER values.
 *
 * usage: cylinders_layout [h ...]       (default h = 0.01; PROFILE=1 in the environment also prints
 *        each solve's nonzero nodal pressures against x)
 */
#include "mortarcontact.h"
#include "scenes.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* Node of lattice point (I, J) of a mesh from sc_mesh_cells (tests/scenes.h). */
static mc_int node_at(const sc_mesh *m, int I, int J) {
  const int order = m->npc > 4 ? 2 : 1;
  return m->lattice[J * (order * m->nx + 1) + I];
}

typedef struct shape {
  double radius, half_width, height, beta, gamma;
  int upper; /* body 1: the arc at the bottom, eta = 0 */
} shape;

/* x = W (beta xi + (1 - beta) xi^3): spacing W beta / n at the contact point, growing outwards;
   body 1: y from its arc (eta = 0) up to the height, body 2: from -height (eta = 0) up to its arc;
   psi grades the spacing towards the arc (gamma: the first step's fraction of a uniform one). */
static void shape_map(double *x, double *y, void *ctx) {
  const shape *s = ctx;
  const double xi = *x, eta = *y;
  const double X = xi == 0 ? 0 : s->half_width * (s->beta * xi + (1 - s->beta) * xi * xi * xi);
  const double r = s->radius;
  *x = X;
  if (s->upper) {
    const double arc = r - sqrt(r * r - X * X), t = eta;
    const double psi = t * (s->gamma + (1 - s->gamma) * t);
    *y = eta == 0 ? arc : arc + (s->height - arc) * psi;
  } else {
    const double arc = -r + sqrt(r * r - X * X), t = 1 - eta;
    const double psi = t * (s->gamma + (1 - s->gamma) * t);
    *y = eta == 1 ? arc : arc - (arc + s->height) * psi;
  }
}

typedef struct outcome {
  long dofs;
  int positions;
  double p0, ripple, seconds;
} outcome;

/* coarse: a quadratic mesh with half the cells each way, of twice the size (the same nodes as the
   linear mesh of h). */
static outcome solve(int npc, int criss, double h, int coarse, int multiplier) {
  const int n_half = coarse ? 20 : 40, ny = coarse ? 12 : 24;
  if (coarse) h *= 2;
  shape s1 = {1, 0.6, 0.6, 0, 0, 1}, s2 = {3, 1.5, 1.5, 0, 0, 0};
  s1.beta = h * n_half / s1.half_width, s2.beta = h * n_half / s2.half_width;
  s1.gamma = h * ny / s1.height, s2.gamma = h * ny / s2.height;
  sc_mesh b[2]; /* the rectangle [-1, 1] x [0, 1] mapped by shape_map */
  if (sc_mesh_cells(&b[0], npc, 2 * n_half, ny, -1, 0, 2, 1, criss) || sc_mesh_cells(&b[1], npc, 2 * n_half, ny, -1, 0, 2, 1, criss)) {
    fprintf(stderr, "mesh generation failed\n");
    exit(1);
  }
  sc_mesh_map(&b[0], shape_map, &s1);
  sc_mesh_map(&b[1], shape_map, &s2);
  const int nI = (npc > 4 ? 2 : 1) * 2 * n_half + 1, nJ = (npc > 4 ? 2 : 1) * ny + 1;
  mc_model *m = NULL;
  mc_create(&m);
  const int o = npc > 4 ? 2 : 1;
  for (int k = 0; k < 2; ++k) {
    if (mc_set_mesh(m, k + 1, b[k].n_nodes, b[k].xy, b[k].n_cells, npc, b[k].cells) != MC_OK) {
      fprintf(stderr, "mesh %d: %s\n", k + 1, mc_errmsg(m));
      exit(1);
    }
    mc_set_material(m, k + 1, 1, 0.3);
  }
  /* body 1: u_x = 0 on its axis (lattice column nI / 2); load on its top; contact on its arc */
  mc_int *ids = malloc(sizeof(mc_int) * (size_t)(nJ + nI + 2 * nI));
  int n = 0;
  for (int J = 0; J < nJ; ++J) ids[n++] = node_at(&b[0], nI / 2, J);
  mc_fix(m, 1, n, ids, MC_X, NULL);
  n = 0;
  for (int I = 0; I < nI; ++I) ids[n++] = node_at(&b[1], I, 0);
  mc_fix(m, 2, n, ids, MC_XY, NULL);
  const int cells_across = 2 * n_half;
  mc_int *top = malloc(sizeof(mc_int) * 2 * (size_t)cells_across), *arc1 = malloc(sizeof(mc_int) * 2 * (size_t)cells_across),
         *arc2 = malloc(sizeof(mc_int) * 2 * (size_t)cells_across);
  double *traction = malloc(sizeof(double) * 2 * (size_t)cells_across);
  const double P = 0.01, width = 2 * s1.half_width;
  for (int i = 0; i < cells_across; ++i) {
    /* top of body 1, right to left; arc of body 1 left to right; arc of body 2 right to left */
    top[2 * i] = node_at(&b[0], o * (cells_across - i), nJ - 1), top[2 * i + 1] = node_at(&b[0], o * (cells_across - i - 1), nJ - 1);
    arc1[2 * i] = node_at(&b[0], o * i, 0), arc1[2 * i + 1] = node_at(&b[0], o * (i + 1), 0);
    arc2[2 * i] = node_at(&b[1], o * (cells_across - i), nJ - 1), arc2[2 * i + 1] = node_at(&b[1], o * (cells_across - i - 1), nJ - 1);
    traction[2 * i] = 0, traction[2 * i + 1] = -P / width;
  }
  mc_add_traction(m, 1, cells_across, top, traction);
  mc_set_contact(m, 1, cells_across, arc1);
  mc_set_contact(m, 2, cells_across, arc2);
  mc_set_option_int(m, MC_OPTION_MULTIPLIER, multiplier);
  if (mc_solve(m) != MC_OK) {
    fprintf(stderr, "solve: %s\n", mc_errmsg(m));
    exit(1);
  }
  outcome out = {0, 0, 0, 0, 0};
  int64_t dofs;
  mc_get_info_int(m, MC_INFO_DOFS, &dofs);
  mc_get_info_real(m, MC_INFO_TIME_TOTAL, &out.seconds);
  out.dofs = (long)dofs;
  mc_int count;
  mc_get_contact_count(m, &count);
  out.positions = (int)count;
  mc_int *nodes = malloc(sizeof(mc_int) * (size_t)count);
  double *p = malloc(sizeof(double) * (size_t)count);
  mc_get_contact_nodes(m, nodes);
  mc_get_contact_pressure(m, p);
  for (int j = 0; j < count; ++j) out.p0 = fmax(out.p0, p[j]);
  if (getenv("PROFILE"))
    for (int j = 0; j < count; ++j)
      if (p[j] > 0) printf("  x %+.5f p %.6f\n", b[0].xy[2 * nodes[j]], p[j]);
  const double nu = 0.3, r_star = 1.0 / (1.0 + 1.0 / 3.0), e_star = 1 / (2 * (1 - nu * nu));
  const double a = sqrt(4 * P * r_star / (PI * e_star));
  for (int j = 1; j + 1 < count; ++j) {
    const double x0 = b[0].xy[2 * nodes[j - 1]], x2 = b[0].xy[2 * nodes[j + 1]];
    if (fmax(fabs(x0), fabs(x2)) > 0.6 * a) continue;
    out.ripple = fmax(out.ripple, fabs(p[j] - 0.5 * (p[j - 1] + p[j + 1])) / out.p0);
  }
  free(nodes), free(p), free(ids), free(top), free(arc1), free(arc2), free(traction);
  sc_mesh_free(&b[0]), sc_mesh_free(&b[1]);
  mc_destroy(m);
  return out;
}

int main(int argc, char **argv) {
  for (int arg = 1; arg < (argc > 1 ? argc : 2); ++arg) {
  const double h = argc > 1 ? atof(argv[arg]) : 0.01;
  const double P = 0.01, nu = 0.3, r_star = 1.0 / (1.0 + 1.0 / 3.0), e_star = 1 / (2 * (1 - nu * nu));
  const double a = sqrt(4 * P * r_star / (PI * e_star)), p0 = 2 * P / (PI * a);
  printf("two cylinders R = 1 on R = 3, h = %g at the contact point (a = %.4f, %.1f cells across a)\n\n", h, a, a / h);
  printf("| cells | triangles | multipliers | cell size at contact | DOFs | contact positions | p0 vs Hertz | ripple: largest |p_j - (p_j-1 + p_j+1)/2| inside 0.6 a | time (s) |\n");
  printf("|---|---|---|---:|---:|---:|---:|---:|---:|\n");
  const int kinds[5] = {3, 6, 4, 8, 9};
  for (int k = 0; k < 5; ++k)
    for (int coarse = kinds[k] > 4; coarse >= 0; --coarse)
    for (int criss = 0; criss < (kinds[k] == 3 || kinds[k] == 6 ? 2 : 1); ++criss)
    for (int multiplier = MC_MULTIPLIER_LINEAR; multiplier <= (kinds[k] > 4 ? MC_MULTIPLIER_QUADRATIC : MC_MULTIPLIER_LINEAR); ++multiplier) {
      const outcome o = solve(kinds[k], criss, h, coarse, multiplier);
      const char *name = kinds[k] == 3 ? "P1" : kinds[k] == 6 ? "T6" : kinds[k] == 4 ? "Q1" : kinds[k] == 8 ? "Q8" : "Q9";
      printf("| %s | %s | %s | %g | %ld | %d | %+.2f %% | %.2f %% of p0 | %.3f |\n", name,
             kinds[k] == 3 || kinds[k] == 6 ? (criss ? "criss-cross" : "one-way") : "-",
             kinds[k] <= 4 ? "paper's" : multiplier == MC_MULTIPLIER_LINEAR ? "linear" : "quadratic", coarse ? 2 * h : h, o.dofs, o.positions,
             100 * (o.p0 / p0 - 1), 100 * o.ripple, o.seconds);
    }
  printf("\n");
  }
  return 0;
}
