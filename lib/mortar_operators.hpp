// The discrete non-penetration constraint: one row per body-1 node of a contact run (the
// paper's cone K_h, section 3):
//     (u1(x_j) - pi_h(u2)(x_j)) . n_j <= g0_j,   j = 0..m
// where pi_h(u2)(x_j) = sum_l w_jl u2(y_l) over body-2 surface nodes y_l. The weights w
// depend on the method:
//   mortar       : pi_h of (3.2) with the paper's multiplier space M_h^1 (constant on the two
//                  end segments): end values by interpolation, interior values D^-1 (M - D_E P_E)
//   dual mortar  : the same with Wohlmuth's biorthogonal test functions (D diagonal)
//   node-to-segment: interpolation of u2 at the point x_j projects to (no pi_h)
#pragma once
#include "contact_geometry.hpp"
#include <vector>

namespace mc {

struct ConstraintRows {
  std::vector<int> position;   // row -> index into ContactGeometry::nodes
  std::vector<int> start;      // CSR over rows of the body-2 part
  std::vector<int> body2_node;
  std::vector<double> weight;
  int size() const { return int(position.size()); }
};

// measure: the weight of the mortar integrals D and M (thickness, or 2 pi r in an axisymmetric
// model; line_measure.hpp), which also shapes the dual method's biorthogonal basis.
ConstraintRows build_constraint_rows(const ContactGeometry &geometry, const Mesh &body1, const Mesh &body2, int method,
                                     const LineMeasure &measure);

}  // namespace mc
