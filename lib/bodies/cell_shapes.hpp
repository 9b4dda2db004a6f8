// The reference cells of the mesh and their isoparametric shape functions, quadrature rules and
// edges: P1 and T6 triangles, Q1, Q8 and Q9 quadrilaterals. Node order is Gmsh's and VTK's
// (corners counter-clockwise, then the mid-edge nodes of edges 0-1, 1-2, ..., then Q9's centre).
//
//   triangle      reference (xi, eta) with xi, eta >= 0, xi + eta <= 1: corners (0,0) (1,0) (0,1)
//   quadrilateral reference [-1, 1]^2: corners (-1,-1) (1,-1) (1,1) (-1,1)
//
// An edge of a cell runs from corner k to corner k+1 (mod corners); on a quadratic cell its
// mid-edge node is node corners + k. Along an edge the trace is the 2-node (linear) or 3-node
// (end, end, middle) line with parameter s in [0, 1] from the first corner to the second.
#pragma once

namespace mc {

constexpr int kMaxCellNodes = 9;
constexpr int kMaxCellPoints = 9;  // quadrature points of a cell (3x3 Gauss)

struct CellType {
  int nodes;      // 3, 4, 6, 8, 9
  int corners;    // 3 or 4
  bool quadratic; // mid-edge nodes (T6, Q8, Q9)
  bool triangle() const { return corners == 3; }
};

// Whether nodes_per_cell is one the library has; cell_type of it.
bool is_cell_kind(int nodes_per_cell);
CellType cell_type(int nodes_per_cell);
// "P1 triangle", "Q8 quadrilateral", ... for messages.
const char *cell_name(int nodes_per_cell);

// Shape functions and their derivatives in the reference coordinates at (xi, eta).
void reference_shapes(int nodes_per_cell, double xi, double eta, double n[kMaxCellNodes], double dxi[kMaxCellNodes],
                      double deta[kMaxCellNodes]);
// Reference coordinates of node a.
void reference_node(int nodes_per_cell, int a, double &xi, double &eta);

// The cell's quadrature rule (reference points and weights; a triangle's weights sum to 1/2, a
// quadrilateral's to 4):
//   P1: the centroid (plane; B is constant), or 3 interior points (axisymmetric: degree 2,
//       never on the axis, where the hoop row N_a / r is undefined);
//   Q1: 2x2 Gauss;
//   T6: plane, the 3 interior points (2/3, 1/6, 1/6) of degree 2: exact for the stiffness of a
//       straight-sided T6 (B is linear) and for its body forces; the patch test holds on curved
//       T6 too (the integral of B over a cell is of degree 2 in the reference coordinates);
//       3 points x 3 strains leave no spurious zero-energy mode. Axisymmetric, 6 points of
//       degree 4 (Dunavant): the weight r and the hoop row N_a / r raise the degree;
//   Q8, Q9: 3x3 Gauss, exact to degree 5 in each direction: the stiffness of a parallelogram.
int quadrature_rule(int nodes_per_cell, bool axisymmetric, double xi[kMaxCellPoints], double eta[kMaxCellPoints],
                    double weight[kMaxCellPoints]);
// The rule of the error estimate's integral of |sigma* - sigma_h|^2 (degree 4 on a T6): the
// cell's rule, but always the 6 points of degree 4 on a T6. Its plane stiffness rule's 3 points
// are where the recovery samples sigma_h (cell_sampled_stresses), so the difference would be
// integrated where it is smallest.
int error_quadrature_rule(int nodes_per_cell, bool axisymmetric, double xi[kMaxCellPoints], double eta[kMaxCellPoints],
                          double weight[kMaxCellPoints]);

// Shapes of the 2-node (nodes = 2: 1 - s, s) or 3-node (nodes = 3: end, end, middle) line at
// s in [0, 1], and their derivatives in s.
void line_shapes(int nodes, double s, double n[3], double ds[3]);

// Gauss-Legendre points and weights on [0, 1] with `count` points (1 to 5).
void gauss_on_unit_interval(int count, double point[5], double weight[5]);

}  // namespace mc
