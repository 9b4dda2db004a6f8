// The condensed contact problem with friction: the stick/slip iteration (friction_iteration.hpp)
// on the dense interface operator. The rows of S, d and G (dual_qp.hpp) are the q normal rows,
// then one tangential row per normal row of a pair with friction; with l = (l_n, l_t),
// gap = S l - d - G a (for a tangential row: minus the weighted slip of the step, -s_j), and
// G^T l = e for the floating bodies. The linear system of frozen states is nonsymmetric for
// Coulomb (l_t = +-mu l_n couples the columns): LU with pivoting.
#pragma once
#include "linalg/dual_qp.hpp"
#include "linalg/friction_iteration.hpp"
#include <vector>

namespace mc {

// start_active / start_state: the last converged states (warm start), or empty.
FrictionResult solve_friction_qp(const DualQp &problem, const FrictionProblem &friction, double tolerance,
                                 int max_iterations, const std::vector<char> &start_active,
                                 const std::vector<FrictionState> &start_state, const FrictionObserver &observe = {});

}  // namespace mc
