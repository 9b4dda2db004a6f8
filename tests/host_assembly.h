/*
 * host_assembly.h - what a host finite-element program has before it calls the library's host
 * bodies (issue 22): element stiffness matrices and consistent load vectors, written here from
 * the math alone (no code shared with lib/), so that the tests and the benchmark of host bodies
 * compare the library against an independent assembler (C99, libm only).
 *
 * Cells: 3 = P1, 4 = Q1, 6 = T6, 8 = Q8, 9 = Q9, isoparametric, in Gmsh's node order (corners
 * counter-clockwise, then the middles of edges 0-1, 1-2, ..., then Q9's centre). Reference cells:
 * the triangle (0,0) (1,0) (0,1) (xi, eta the barycentric coordinates of nodes 1 and 2) and the
 * square [-1,1]^2 with corner 0 at (-1,-1). Quadrature (the library's rules, so that the two
 * agree to round-off): P1 1 point (axisymmetric: 3 points at barycentric (2/3,1/6,1/6)), Q1 2x2
 * Gauss, T6 the same 3 points (axisymmetric: Dunavant's 6-point degree-4 rule), Q8 and Q9 3x3
 * Gauss.
 *
 * Freedoms of a cell: x then y per node, node by node (2 npc). Laws: plane, a 3x3 row-major
 * Voigt matrix (xx, yy, engineering xy) weighted by the thickness; axisymmetric, 4x4 on
 * (rr, zz, rz, theta-theta) weighted by 2 pi r.
 */
#ifndef MC_TESTS_HOST_ASSEMBLY_H
#define MC_TESTS_HOST_ASSEMBLY_H

#include <stddef.h>

#include "mortarcontact.h"

/* The isotropic plane-strain law (3x3) and the isotropic axisymmetric law (4x4, rr zz rz tt). */
void ha_law_plane_strain(double young, double nu, double D[9]);
void ha_law_axisymmetric(double young, double nu, double D[16]);
/* The in-plane law of an orthotropic material in the axes: the inverse of the compliance
   [[s11, s12, 0], [s12, s22, 0], [0, 0, s33]]. */
void ha_law_orthotropic(double s11, double s22, double s12, double s33, double D[9]);

/* Shape functions of a cell kind at reference point (xi, eta): N, dN/dxi, dN/deta (npc each). */
void ha_shape(int npc, double xi, double eta, double *N, double *dxi, double *deta);
/* The quadrature rule of a cell kind: up to 9 points (2 reference coordinates each) and their
   weights (summing to the reference measure: 1/2 for triangles, 4 for squares). Returns the
   number of points. */
int ha_rule(int npc, int axisymmetric, double *points, double *weights);

/* Element stiffness of one cell: xy its nodes' coordinates (2 per node), D the law (9 or 16
   values), thickness for plane models. ke: (2 npc)^2 values, row-major (symmetric). Returns 0,
   or 1 if the Jacobian is not positive at a quadrature point (or r <= 0 there, axisymmetric). */
int ha_element_stiffness(int npc, const double *xy, int axisymmetric, double thickness, const double *D, double *ke);
/* A layered section (plane models, quadrilaterals 4, 8, 9): the reference cell cut along eta
   into n_layers layers, layer l between eta_bounds[l] and eta_bounds[l + 1] (increasing from -1
   to 1) with the law D + 9 l, each layer integrated with the cell's Gauss rule mapped onto it.
   On a cell whose sides eta = const are straight lines (a rectangle) the layers are bands. */
int ha_layered_stiffness(int npc, const double *xy, double thickness, int n_layers, const double *eta_bounds,
                         const double *D, double *ke);

/* The element matrices of every cell of a mesh (n_cells cells of npc nodes, Gmsh order; xy 2 per
   node) with the plane law D at thickness 1, as mc_add_element_matrices takes them: eltptr
   (n_cells + 1 offsets), eltvar (2 npc per cell: equations[2 v], equations[2 v + 1] of its nodes
   v), a ((2 npc)^2 per cell, row-major); each malloc'ed, the caller frees them. Returns 0, or
   1 + the index of the first cell whose Jacobian is not positive. */
int ha_mesh_element_matrices(int npc, mc_int n_cells, const mc_int *cells, const double *xy, const mc_int *equations,
                             const double D[9], mc_int **eltptr, mc_int **eltvar, double **a);

/* Consistent nodal forces of a uniform traction t (force per unit area of the surface, global
   axes) on an edge of n = 2 nodes (a, b) or 3 nodes (a, b, middle): f (2 per node, overwritten)
   = the integral of N_a t over the isoparametric edge, times the thickness or 2 pi r. 3-point
   Gauss: exact on straight edges (also with the weight r). */
void ha_edge_load(int n, const double *xy, const double t[2], int axisymmetric, double thickness, double *f);

/* The middle node of the edge (a, b) of a quadratic mesh (npc 6, 8, 9; cells Gmsh-ordered), or
   -1 if no cell has that edge. */
mc_int ha_edge_middle(int npc, mc_int n_cells, const mc_int *cells, mc_int a, mc_int b);

/* A sparse matrix as coordinate entries, duplicates kept (summed by the products). */
typedef struct ha_coo {
  size_t n, cap;
  mc_int *row, *col;
  double *val;
} ha_coo;
void ha_coo_add(ha_coo *a, mc_int row, mc_int col, double value);
void ha_coo_free(ha_coo *a);
/* y = A x on n rows (y overwritten; entries with an index outside [0, n) are skipped). */
void ha_coo_multiply(const ha_coo *a, const double *x, double *y, mc_int n);

#endif /* MC_TESTS_HOST_ASSEMBLY_H */
