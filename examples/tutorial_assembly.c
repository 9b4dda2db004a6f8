/*
 * tutorial_assembly.c - the program of docs/tutorial_assembly.md: an assembly of three bodies,
 * three concentric cylinders shrunk together, step by step.
 *
 * Three steel cylinders, 10 <= r <= 15, 15 <= r <= 20 and 20 <= r <= 25 (mm), each made with a
 * radial interference of 0.01 mm on the next, are shrunk together. Plane strain (long
 * cylinders, eps_z = 0), a quarter of the cross-section by symmetry. The program makes a model
 * of three bodies and two contact pairs, solves it, and compares the two interface pressures
 * and the radial displacements of the bore and of the outside with Lame's closed form.
 *
 * usage: tutorial_assembly [output.pvd]
 *   output.pvd: where to write the ParaView files (default: none written)
 *
 * Exit status 0 only if every check of step 9 passes (ctest runs it: tutorial_assembly).
 */
#include <math.h>
#include <mortarcontact.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* Every mc_ call returns a status; on failure mc_errmsg names the argument and index. */
#define CHECK(call)                                                                      \
  do {                                                                                   \
    mc_status status_ = (call);                                                          \
    if (status_ != MC_OK) {                                                              \
      fprintf(stderr, "%s: %s: %s\n", #call, mc_status_string(status_), mc_errmsg(model)); \
      return 1;                                                                          \
    }                                                                                    \
  } while (0)

/* A quarter ring r0 <= r <= r1, 0 <= theta <= pi/2, of nr x nt Q1 cells. Node (i, j) (i along
   the radius, j around) is j (nr + 1) + i. The lists: the nodes on y = 0 (theta = 0) and on
   x = 0 (theta = pi/2), and the edges and nodes of the inner and of the outer arc, each edge
   counter-clockwise around the ring's cells. */
typedef struct ring {
  int nr, nt, n_nodes, n_cells;
  double *xy;
  mc_int *cells;
  mc_int *on_x_axis, *on_y_axis;      /* nr + 1 nodes each */
  mc_int *inner_edges, *outer_edges;  /* nt edges each, 2 ids per edge */
  mc_int *inner_nodes, *outer_nodes;  /* nt + 1 nodes each */
} ring;

static ring quarter_ring(double r0, double r1, int nr, int nt) {
  ring g = {nr, nt, (nr + 1) * (nt + 1), nr * nt, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
  g.xy = malloc(sizeof(double) * 2 * g.n_nodes);
  g.cells = malloc(sizeof(mc_int) * 4 * g.n_cells);
  g.on_x_axis = malloc(sizeof(mc_int) * (nr + 1)), g.on_y_axis = malloc(sizeof(mc_int) * (nr + 1));
  g.inner_edges = malloc(sizeof(mc_int) * 2 * nt), g.outer_edges = malloc(sizeof(mc_int) * 2 * nt);
  g.inner_nodes = malloc(sizeof(mc_int) * (nt + 1)), g.outer_nodes = malloc(sizeof(mc_int) * (nt + 1));
  for (int j = 0; j <= nt; ++j)
    for (int i = 0; i <= nr; ++i) {
      const double r = r0 + (r1 - r0) * i / nr, t = 0.5 * PI * j / nt;
      g.xy[2 * (j * (nr + 1) + i)] = j == nt ? 0 : r * cos(t); /* exactly on the axes */
      g.xy[2 * (j * (nr + 1) + i) + 1] = j == 0 ? 0 : r * sin(t);
    }
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nr; ++i) { /* counter-clockwise: out along the radius, then around */
      mc_int *c = &g.cells[4 * (j * nr + i)], a = j * (nr + 1) + i;
      c[0] = a, c[1] = a + 1, c[2] = a + nr + 2, c[3] = a + nr + 1;
    }
  for (int i = 0; i <= nr; ++i) g.on_x_axis[i] = i, g.on_y_axis[i] = nt * (nr + 1) + i;
  for (int j = 0; j <= nt; ++j) g.inner_nodes[j] = j * (nr + 1), g.outer_nodes[j] = j * (nr + 1) + nr;
  for (int j = 0; j < nt; ++j) {
    g.outer_edges[2 * j] = g.outer_nodes[j], g.outer_edges[2 * j + 1] = g.outer_nodes[j + 1];
    g.inner_edges[2 * j] = g.inner_nodes[j + 1], g.inner_edges[2 * j + 1] = g.inner_nodes[j];
  }
  return g;
}

static void ring_free(ring *g) {
  free(g->xy), free(g->cells), free(g->on_x_axis), free(g->on_y_axis);
  free(g->inner_edges), free(g->outer_edges), free(g->inner_nodes), free(g->outer_nodes);
}

/* Lame: the radial displacement at r of a long cylinder a <= r <= b (plane strain) under the
   pressures p_in inside and p_out outside. sigma_r = A - B / r^2, sigma_theta = A + B / r^2. */
static double lame_u(double a, double b, double p_in, double p_out, double r, double young, double nu) {
  const double A = (p_in * a * a - p_out * b * b) / (b * b - a * a);
  const double B = (p_in - p_out) * a * a * b * b / (b * b - a * a);
  return (1 + nu) / young * ((1 - 2 * nu) * A * r + B / r);
}

int main(int argc, char **argv) {
  mc_model *model = NULL;

  /* ---- step 1: the problem and its closed form ---- */
  const double radius[4] = {10, 15, 20, 25}; /* mm: bore, the two interfaces, outside */
  const double delta = 0.01;                  /* mm: radial interference at r = 15 and r = 20 */
  const double young = 210000, nu = 0.3;      /* MPa, steel */
  /* Lame: the misfits u_outer(r_k) - u_inner(r_k) at the two interfaces are linear in the
     pressures (p1, p2); equal to delta they give a 2 x 2 system. */
  double misfit[2][2];
  for (int j = 0; j < 2; ++j) {
    const double p1 = j == 0, p2 = j == 1;
    misfit[0][j] = lame_u(radius[1], radius[2], p1, p2, radius[1], young, nu) -
                   lame_u(radius[0], radius[1], 0, p1, radius[1], young, nu);
    misfit[1][j] = lame_u(radius[2], radius[3], p2, 0, radius[2], young, nu) -
                   lame_u(radius[1], radius[2], p1, p2, radius[2], young, nu);
  }
  const double det = misfit[0][0] * misfit[1][1] - misfit[0][1] * misfit[1][0];
  const double lame[2] = {delta * (misfit[1][1] - misfit[0][1]) / det, delta * (misfit[0][0] - misfit[1][0]) / det};
  printf("Lame: p1 = %.4f MPa at r = 15, p2 = %.4f MPa at r = 20\n", lame[0], lame[1]);

  /* ---- step 2: three meshes that do not match ---- */
  const int nr = 8, nt[3] = {32, 44, 56}; /* cells along the radius and around each quarter ring */
  ring mesh[3];
  for (int k = 0; k < 3; ++k) mesh[k] = quarter_ring(radius[k], radius[k + 1], nr, nt[k]);

  /* ---- step 3: a model of three bodies ---- */
  CHECK(mc_create(&model));
  CHECK(mc_set_body_count(model, 3));
  CHECK(mc_set_plane(model, MC_PLANE_STRAIN, 1.0));
  for (int k = 0; k < 3; ++k) {
    CHECK(mc_set_mesh(model, k + 1, mesh[k].n_nodes, mesh[k].xy, mesh[k].n_cells, 4, mesh[k].cells));
    CHECK(mc_set_material(model, k + 1, young, nu));
  }

  /* ---- step 4: supports on the symmetry lines only ---- */
  for (int k = 0; k < 3; ++k) {
    CHECK(mc_fix(model, k + 1, nr + 1, mesh[k].on_x_axis, MC_Y, NULL)); /* y = 0: u_y = 0 */
    CHECK(mc_fix(model, k + 1, nr + 1, mesh[k].on_y_axis, MC_X, NULL)); /* x = 0: u_x = 0 */
  }

  /* ---- step 5: two contact pairs ---- */
  int pair[2];
  for (int k = 0; k < 2; ++k) {
    /* cylinder k + 1's outside (non-mortar) against cylinder k + 2's bore (mortar) */
    CHECK(mc_add_contact_pair(model, k + 1, k + 2, &pair[k]));
    CHECK(mc_set_pair_surface(model, pair[k], k + 1, nt[k], mesh[k].outer_edges));
    CHECK(mc_set_pair_surface(model, pair[k], k + 2, nt[k + 1], mesh[k + 1].inner_edges));
  }

  /* ---- step 6: the interference as gap offsets ---- */
  for (int k = 0; k < 2; ++k) {
    double *offset = malloc(sizeof(double) * (nt[k] + 1));
    for (int j = 0; j <= nt[k]; ++j) offset[j] = -delta; /* negative: the bodies overlap */
    CHECK(mc_set_pair_gap_offset(model, pair[k], nt[k] + 1, mesh[k].outer_nodes, offset));
    free(offset);
  }

  /* ---- step 7: solve ---- */
  CHECK(mc_solve(model));
  int64_t dofs, active;
  CHECK(mc_get_info_int(model, MC_INFO_DOFS, &dofs));
  CHECK(mc_get_info_int(model, MC_INFO_ACTIVE_NODES, &active));
  printf("solved: %lld unknowns, %lld contact nodes active on both pairs\n", (long long)dofs, (long long)active);

  /* ---- step 8: the pressures of each pair ---- */
  double mean[2], worst[2];
  for (int k = 0; k < 2; ++k) {
    mc_int n;
    CHECK(mc_get_pair_contact_count(model, pair[k], &n));
    double *p = malloc(sizeof(double) * n);
    CHECK(mc_get_pair_contact(model, pair[k], MC_CONTACT_PRESSURE, p));
    mean[k] = 0, worst[k] = 0;
    for (mc_int j = 0; j < n; ++j) mean[k] += p[j] / n, worst[k] = fmax(worst[k], fabs(p[j] / lame[k] - 1));
    printf("pair %d (r = %g): %d nodes, mean pressure %.4f MPa (Lame %.4f, %+.3f %%), largest nodal deviation %.3f %%\n",
           pair[k], radius[k + 1], (int)n, mean[k], lame[k], 100 * (mean[k] / lame[k] - 1), 100 * worst[k]);
    free(p);
  }

  /* ---- step 9: check against Lame ---- */
  /* The radial displacement of the bore (r = 10) and of the outside (r = 25), at the node on
     y = 0, where it is u_x. */
  double *u = malloc(sizeof(double) * 2 * mesh[0].n_nodes);
  CHECK(mc_get_displacement(model, 1, u));
  const double u_bore = u[2 * mesh[0].inner_nodes[0]];
  free(u);
  u = malloc(sizeof(double) * 2 * mesh[2].n_nodes);
  CHECK(mc_get_displacement(model, 3, u));
  const double u_out = u[2 * mesh[2].outer_nodes[0]];
  free(u);
  const double lame_bore = lame_u(radius[0], radius[1], 0, lame[0], radius[0], young, nu);
  const double lame_out = lame_u(radius[2], radius[3], lame[1], 0, radius[3], young, nu);
  printf("bore: u_r = %.6f mm (Lame %.6f), outside: u_r = %.6f mm (Lame %.6f)\n", u_bore, lame_bore, u_out, lame_out);
  int ok = 1;
  for (int k = 0; k < 2; ++k) ok = ok && fabs(mean[k] / lame[k] - 1) < 1e-3 && worst[k] < 5e-3;
  ok = ok && fabs(u_bore / lame_bore - 1) < 1e-3 && fabs(u_out / lame_out - 1) < 1e-3;
  printf("%s\n", ok ? "agrees with Lame: mean pressures and displacements within 0.1 %, every node within 0.5 %"
                    : "FAILED: not within 0.1 % (mean, displacements) or 0.5 % (every node) of Lame");

  /* ---- step 10: write the solution for ParaView ---- */
  if (argc > 1) {
    CHECK(mc_write_vtu(model, argv[1]));
    printf("wrote %s\n", argv[1]);
  }

  /* ---- step 11: clean up ---- */
  mc_destroy(model);
  for (int k = 0; k < 3; ++k) ring_free(&mesh[k]);
  return ok ? 0 : 1;
}
