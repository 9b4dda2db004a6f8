// The discrete non-penetration constraint: one row per trace point of Gamma_c (the paper's
// cone K_h, section 3):
//     (u1(x_j) - pi_h(u2)(x_j)) . n_j <= g0_j
// where u1(x_j) is body 1's displacement at trace point j (a node, or a point inside a partly
// covered segment at an end of Gamma_c) and pi_h(u2)(x_j) = sum_l w_jl u2(y_l) over body-2
// surface nodes y_l. The weights w depend on the method:
//   mortar       : pi_h of (3.2) with the paper's multiplier space M_h^1 (constant on the two
//                  end elements): end values by interpolation, interior values D^-1 (M - D_E P_E);
//                  on a closed loop (no ends) all values D^-1 M with M_h^1 = W_h^1
//   dual mortar  : the same with Wohlmuth's biorthogonal test functions (D diagonal)
//   node-to-segment: interpolation of u2 at the point each body-1 node projects to (no pi_h)
#pragma once
#include "contact_geometry.hpp"
#include <vector>

namespace mc {

struct ConstraintRows {
  // Row r: body-1 part sum_k weight1 u1(position1) (CSR start1), body-2 part sum_l weight2 u2
  // (CSR start2), along normal[r], initial gap gap0[r] (the host's offsets not included).
  std::vector<int> start1{0}, position1;
  std::vector<double> weight1;
  std::vector<int> start2{0}, body2_node;
  std::vector<double> weight2;
  std::vector<Point> normal;
  std::vector<double> gap0;
  // The position whose nodal row this is (its gap is reported there); -1 for a row at an end
  // of Gamma_c inside a partly covered segment.
  std::vector<int> own_position;
  int size() const { return int(normal.size()); }
};

// measure: the weight of the mortar integrals (the dual basis is biorthogonal in it).
ConstraintRows build_constraint_rows(const ContactGeometry &geometry, int method, const LineMeasure &measure);

}  // namespace mc
