/*
 * scenes.h - shared helpers for the Check test suite (C99).
 *
 * - sc_mesh: structured rectangle meshes, P1 (2 triangles per square, diagonal from
 *   node (i,j) to (i+1,j+1)) or Q1, nx x ny cells, with optional random interior
 *   distortion (fixed seed, Q1 cells stay convex), and per-side node and edge lists.
 * - Field helpers: set a mesh on a model, fix nodes to a function, consistent nodal
 *   load of a non-uniform body force, L2 and H1-seminorm errors of a P1/Q1 field.
 * - Small laws: the in-plane isotropic Voigt matrix for plane strain / plane stress.
 *
 * CMake: tests/CMakeLists.txt builds this as the static library target `mc_test_scenes`
 * (links mortarcontact, PkgConfig::CHECK and libm; include dir tests/). A test program needs
 * only `target_link_libraries(t PRIVATE mc_test_scenes)`; or use the function
 * mc_add_check_test(name source...) defined there, which also registers it with ctest.
 *
 * Assertion macros for Check tests (OK, SUCCEEDS, FAILS with status and message piece) are in
 * check_helpers.h.
 *
 * All ids stored in an sc_mesh are 0-based. Functions that pass ids to the library take
 * a `base` (0 or 1) that is added on the way in; it must match mc_set_index_base.
 *
 * Node numbering: node (i, j), 0 <= i <= nx, 0 <= j <= ny, has id j*(nx+1) + i and sits
 * at (x0 + i*lx/nx, y0 + j*ly/ny) before distortion. Boundary nodes are never moved.
 * Q1 cell (i, j) has id j*nx + i and nodes (i,j) (i+1,j) (i+1,j+1) (i,j+1).
 * P1 cells 2*(j*nx+i) and 2*(j*nx+i)+1 are (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1).
 */
#ifndef MC_TESTS_SCENES_H
#define MC_TESTS_SCENES_H

#include "mortarcontact.h"

/* Sides of the rectangle. Edges of each side are listed counter-clockwise around the body
   (bottom: left to right, right: bottom to top, top: right to left, left: top to bottom),
   i.e. each edge (a, b) is oriented as its cell; nodes in the same order. */
enum { SC_BOTTOM = 0, SC_RIGHT = 1, SC_TOP = 2, SC_LEFT = 3 };

typedef struct sc_mesh {
  int nx, ny;
  int npc;              /* nodes per cell: 3 (P1) or 4 (Q1) */
  mc_int n_nodes;
  double *xy;           /* 2 per node */
  mc_int n_cells;
  mc_int *cells;        /* npc per cell, counter-clockwise, 0-based */
  mc_int n_side_nodes[4];
  mc_int *side_nodes[4];  /* ordered along the side, see above; corners belong to two sides */
  mc_int n_side_edges[4];
  mc_int *side_edges[4];  /* 2 node ids per edge */
  mc_int n_boundary_nodes;
  mc_int *boundary_nodes; /* every boundary node once, increasing ids */
  char *on_boundary;      /* per node: 1 if on the boundary */
  mc_int *lattice;        /* sc_mesh_cells only: node id of lattice point (I, J), or -1 (see there) */
} sc_mesh;

/* Builds a structured mesh of the rectangle [x0, x0+lx] x [y0, y0+ly]. npc = 3 or 4.
   distortion in [0, 0.25]: every interior node moves by a random vector of length at most
   distortion * min(hx, hy) (uniform in a disk, deterministic from seed). Returns 0 on
   success, nonzero on bad arguments or if a cell came out non-convex / inverted. */
int sc_mesh_rect(sc_mesh *mesh, int npc, int nx, int ny, double x0, double y0, double lx, double ly,
                 double distortion, unsigned seed);
void sc_mesh_free(sc_mesh *mesh);
/* Any cell kind: npc = 3 (P1), 4 (Q1), 6 (T6), 8 (Q8), 9 (Q9), nx x ny squares of the rectangle,
   no distortion. Triangles: two per square, the diagonal from (i,j) to (i+1,j+1) as in
   sc_mesh_rect, or with criss_cross alternating from square to square ((i + j) odd: from
   (i+1,j) to (i,j+1)). Nodes: the lattice of corners (order 1) or of corners and mid-edge points
   (order 2: (2nx+1) x (2ny+1) points, point (I, J) at (x0 + I lx/(2nx), y0 + J ly/(2ny))),
   numbered row by row, skipping points no cell uses (a Q8 square's centre). mesh->lattice maps
   lattice point (I, J) (index J * (order nx + 1) + I) to its node id or -1. Side node lists hold
   every node of the side (mid-edge nodes included), side edges the corner pairs. sc_node is not
   for these meshes. Returns 0 on success. */
int sc_mesh_cells(sc_mesh *mesh, int npc, int nx, int ny, double x0, double y0, double lx, double ly, int criss_cross);
/* Id of node (i, j). */
mc_int sc_node(const sc_mesh *mesh, int i, int j);
/* Applies map(x, y) to every node (e.g. to bend a side); side lists are unchanged. */
void sc_mesh_map(sc_mesh *mesh, void (*map)(double *x, double *y, void *ctx), void *ctx);
/* Signed area of cell c (positive for counter-clockwise). */
double sc_cell_area(const sc_mesh *mesh, mc_int c);

/* A copy of ids with base added (caller frees). */
mc_int *sc_ids(const mc_int *ids, mc_int n, int base);

/* A vector field and, optionally, its gradient.
   val[2] = (u_x, u_y); grad (may be NULL) = (du_x/dx, du_x/dy, du_y/dx, du_y/dy). */
typedef void (*sc_field)(double x, double y, void *ctx, double val[2], double grad[4]);

/* mc_set_mesh of body with the mesh's ids shifted by base. */
mc_status sc_set_mesh(mc_model *m, int body, const sc_mesh *mesh, int base);
/* mc_fix of the n nodes (0-based, shifted by base) in both components to field(x, y). */
mc_status sc_fix_field(mc_model *m, int body, const sc_mesh *mesh, mc_int n, const mc_int *nodes, int base,
                       sc_field field, void *ctx);
/* mc_fix of one side, with components mask and zero values. */
mc_status sc_fix_side(mc_model *m, int body, const sc_mesh *mesh, int side, int components, int base);
/* mc_add_traction of a uniform traction on every edge of a side. */
mc_status sc_traction_side(mc_model *m, int body, const sc_mesh *mesh, int side, double tx, double ty, int base);

/* The consistent nodal load vector F (2 per node, overwritten) of a body force per unit
   area f(x, y) (field's val; its grad is not used), times thickness:
   F_a = thickness * sum_cells int f N_a, Gauss quadrature (P1: 7-point degree 5; Q1: 3x3). */
void sc_consistent_load(const sc_mesh *mesh, sc_field f, void *ctx, double thickness, double *F);
/* Adds F as nodal forces on every node (mc_add_nodal_force). */
mc_status sc_add_nodal_forces(mc_model *m, int body, const sc_mesh *mesh, const double *F, int base);

/* Errors of the P1/Q1 field u (2 per node) against exact (val and grad used):
   *l2 = ||u - u_h||_L2, *h1 = |u - u_h|_H1 (seminorm), by quadrature per cell
   (P1: 7-point degree 5; Q1: 4x4 Gauss). Either output may be NULL. */
void sc_errors(const sc_mesh *mesh, const double *u, sc_field exact, void *ctx, double *l2, double *h1);

/* The in-plane isotropic law D (row-major 3x3 Voigt, engineering shear) for plane strain
   (plane = MC_PLANE_STRAIN) or plane stress, and the out-of-plane stress factor:
   sigma_zz = zz[0]*eps_xx + zz[1]*eps_yy (0 for plane stress). zz may be NULL. */
void sc_isotropic_law(double young, double poisson, int plane, double D[9], double zz[2]);

/* The axisymmetric shrink fit (test_axisymmetric, test_quadratic, test_error_estimate): a new
   axisymmetric model with the solid shaft (body 1, its right side r = b the contact surface) and
   the hub (body 2, its left side r = b), one material (young, nu), rollers on both bottoms
   (z = 0), and the radial interference delta as gap offsets on every node of the shaft's
   surface. Returns the model (NULL and a message on stderr if a call failed). */
mc_model *sc_axisymmetric_shrink_fit(const sc_mesh *shaft, const sc_mesh *hub, double young, double nu, double delta);

/* Deterministic uniform random numbers in [0, 1) (xorshift), independent of rand(). */
double sc_random(unsigned *state);

/* Relative difference |a - b| / max(|a|, |b|, floor). */
double sc_reldiff(double a, double b, double floor);

/* Runs a Check suite with CK_NORMAL output (the summary line reaches the log), frees it, and
   returns the process exit code: 0 if every check passed. */
#include <check.h>
int sc_run_suite(Suite *suite); /* in check_runner.c (linked into every test program) */

/* ---- full rings (structured polar meshes) ---- */
/* The annulus r0 <= r <= r1: nt cells around (a multiple of 4, so that nodes lie on both axes),
   nr across, Q1 (npc 4) or P1 (each quad split along one diagonal). Node (i, j) at angle
   2 pi i / nt and radius r0 + j (r1 - r0) / nr has id j nt + i (i taken modulo nt). */
typedef struct sc_polar_ring {
  int nt, nr, npc;
  double r0, r1;
  mc_int n_nodes, n_cells;
  double *xy;
  mc_int *cells;
} sc_polar_ring;
mc_int sc_ring_node(const sc_polar_ring *g, int i, int j);
/* Returns 0, or nonzero for bad arguments (nt not a positive multiple of 4, npc not 3 or 4). */
int sc_polar_ring_build(sc_polar_ring *g, int nt, int nr, int npc, double r0, double r1);
void sc_polar_ring_free(sc_polar_ring *g);
/* The circle j as a closed loop of nt edges, oriented as its cells (the body on the left):
   counter-clockwise for the outer circle, clockwise for the inner one (caller frees). */
mc_int *sc_ring_circle_edges(const sc_polar_ring *g, int j);

#endif /* MC_TESTS_SCENES_H */
