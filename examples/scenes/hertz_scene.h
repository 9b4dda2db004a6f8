/*
 * hertz_scene.h - meshes of the shared Hertz benchmark scene (docs: method.md,
 * "Shared benchmark scenes"): body 1 = lower half-disc of radius 1 centred at
 * (0,1), flat top at y = 1, touching the origin; body 2 = block [-4,4]x[-4,0]
 * clamped at y = -4. Both meshes are graded: fine and uniform near the contact
 * point, growing geometrically (factor 1.15) away from it.
 *
 * Plain C99, libc/libm only, no global state: usable from the examples, the
 * tests and the benchmarks alike. bench/getfem_hertz.py re-implements exactly
 * the same construction in numpy, so any change here must be mirrored there.
 */
#ifndef HERTZ_SCENE_H
#define HERTZ_SCENE_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hertz_mesh {
  int n_nodes;
  double *xy;         /* 2 per node */
  int n_cells;
  int nodes_per_cell; /* 3 = P1 triangles, 4 = Q1, 6 = T6, 8 = Q8, 9 = Q9; counter-clockwise */
  int *cells;         /* nodes_per_cell per cell, 0-based */
} hertz_mesh;

typedef struct hertz_scene {
  hertz_mesh body[2];                    /* body[0] = body 1 (half-disc), body[1] = body 2 (block) */
  int n_contact_edges[2]; int *contact_edges[2]; /* 2 node ids each, 0-based */
  int n_top_edges; int *top_edges;       /* body-1 flat top edges y == 1 (the load goes here) */
  int n_axis_nodes; int *axis_nodes;     /* body-1 nodes with x == 0 exactly (u_x = 0 there) */
  int n_bottom_nodes; int *bottom_nodes; /* body-2 nodes with y == -4 (clamped) */
} hertz_scene;

/* h1: body-1 fine spacing near the contact point (physical); h2: body-2 fine spacing.
   quads: 0 = P1 triangles (each quad split along the lower-left/upper-right diagonal), 1 = Q1.
   Returns 0 on success, nonzero on bad arguments (h1, h2 outside (0, 0.2], quads not 0/1)
   or allocation failure; on failure *s is left zeroed (hertz_scene_free is still fine).
   Both meshes are structured grids numbered row by row (bottom row first, left to right);
   edge lists follow the counter-clockwise boundary walk of their body.
   The P1 body-1 cell next to the arc corner (x,y) = (1/sqrt 2, 1 - 1/sqrt 2) is split
   along the other diagonal (three arc vertices would make a sliver). Near both arc corners
   the elliptical map is singular: cells there are thin but valid (see hertz_scene.c). */
int hertz_scene_build(hertz_scene *s, double h1, double h2, int quads);
/* The same scene with cells of any kind the library has: nodes_per_cell = 3 (P1), 4 (Q1) (as
   hertz_scene_build with quads 0, 1), 6 (T6), 8 (Q8) or 9 (Q9). Quadratic meshes are the same
   grids with a mid-edge node at the parameter middle of each cell edge, mapped like the
   corners (so the disc's arc nodes, mid-edge ones included, lie on the circle and its edges are
   curved), numbered row by row on the lattice of corners and middles (a Q8 mesh skips the
   cells' centres). Edge lists name each edge by its two corners; axis, bottom and top node
   lists hold every node there, mid-edge ones included. */
int hertz_scene_build_cells(hertz_scene *s, double h1, double h2, int nodes_per_cell);
/* The same with another grading: cells grow by `growth` (1.01 to 3; default 1.15) outside a
   uniformly fine zone of physical half-width fine_half_width (from max(h1, h2) to 0.5; default
   0.4). Quadratic cells, whose error in the smooth far field falls faster, are accurate with a
   faster growth (bench/hertz_quadratic --growth). */
int hertz_scene_build_graded(hertz_scene *s, double h1, double h2, int nodes_per_cell, double growth,
                             double fine_half_width);
void hertz_scene_free(hertz_scene *s); /* NULL-safe, frees everything */
/* The axisymmetric scene "sphere on a flat" (3D Hertz): the part x >= 0 of the same meshes,
   read as meridians with x = r and y the axis: body 1 = the lower hemisphere of radius 1
   centred at (0,1) with its flat top at y = 1, body 2 = the cylinder r <= 4, -4 <= y <= 0.
   Edge and node lists keep their members with x >= 0 (axis_nodes: the nodes on the axis).
   Returns as hertz_scene_build, or 3 if a cell straddles x = 0. */
int hertz_scene_axisymmetric(hertz_scene *s, double h1, double h2, int quads);
int hertz_scene_axisymmetric_cells(hertz_scene *s, double h1, double h2, int nodes_per_cell);
/* 3D Hertz of that scene for a total force `load`: a^3 = 3 P R / (4 E*), p0 = 3 P / (2 pi a^2),
   approach of distant points delta = a^2 / R (R = 1, E = 1, nu = 0.3 both). Any output may be NULL. */
void hertz_analytic_sphere(double load, double *a, double *p0, double *approach);
/* analytic Hertz values for this scene (R=1, E=1, nu=0.3 both, plane strain, P=0.01) */
void hertz_analytic(double *a, double *p0);

#ifdef __cplusplus
}
#endif
#endif /* HERTZ_SCENE_H */
