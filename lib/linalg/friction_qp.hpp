// The condensed contact problem with friction (design note friction.md; Hüeber, Stadler and
// Wohlmuth 2008; Kunisch and Stadler 2005 for Tresca in 2D). The rows of S, d and G (dual_qp.hpp)
// are the q normal rows, then one tangential row per normal row of a pair with friction
// (tangent_of[j] is the normal row of tangential row q + j). With l = (l_n, l_t) and
// gap = S l - d - G a (for a tangential row: minus the weighted slip of the step, -s_j):
//   normal rows:      l_n >= 0, gap_n >= 0, l_n gap_n = 0
//   tangential rows:  open (Coulomb, l_n = 0): l_t = 0
//                     stick:            s = 0,               |l_t| <= bound
//                     slip:             l_t = bound sign(s)  (s != 0)
//   (a Tresca row is never open: FrictionProblem::live)
//   G^T l = e (floating bodies), bound = mu l_n (Coulomb) or the row's Tresca force.
// Once the states are frozen every condition is linear: each iteration solves one linear system
// (nonsymmetric for Coulomb: l_t = +-mu l_n couples the columns; LU with pivoting), then updates
// the states by the primal-dual active-set rule: a normal row is active iff (l_n > 0 or
// gap_n < 0, as in dual_qp.cpp); a sticking row slips (with the sign of l_t) once |l_t| exceeds
// its bound, a slipping row whose slip turns against its sign sticks, and a row coming into
// contact sticks iff |l_t + c_t s| <= bound, else slips with the sign of l_t + c_t s. c_t
// changes the iterates, never the converged answer. If the states cycle, one change per
// iteration (the row of least index) from there.
// Converged states satisfy the conditions to round-off: nothing is regularized.
#pragma once
#include "linalg/dual_qp.hpp"
#include <string>
#include <vector>

namespace mc {

enum class FrictionState : char { open = 0, stick = 1, slip_plus = 2, slip_minus = 3 };

struct FrictionProblem {
  int normal_rows = 0;               // q; the tangential rows follow
  std::vector<int> tangent_of;       // per tangential row j: its normal row
  std::vector<int> law;              // MC_FRICTION_TRESCA or MC_FRICTION_COULOMB
  std::vector<double> bound;         // mu (Coulomb) or the Tresca bound as a force
  double ct = 0;                     // c_t; 0: 1 / (largest diagonal entry of S)
  // Whether tangential row j carries friction in the states `active` of the normal rows: a
  // Coulomb row only in contact (its bound mu l_n is 0 when open); a Tresca row always: the
  // given-bound problem of Kikuchi and Oden holds |l_t| <= g on the whole contact surface,
  // which keeps it convex with a unique answer (bounds that vanish where a row opens would
  // couple the tangential states to the normal ones, and the iteration cycled on them).
  bool live(int j, const std::vector<char> &active) const;
};

enum class FrictionOutcome { solved, modes_not_held, not_converged, cycled };

struct FrictionResult {
  FrictionOutcome outcome = FrictionOutcome::solved;
  std::vector<double> lambda, alpha, gap;  // size q + m, k, q + m
  std::vector<char> active;                // normal rows in contact
  std::vector<FrictionState> state;        // tangential rows
  int iterations = 0;
  long stick = 0, slip = 0;
  double violation = 0;           // the normal rows' complementarity (as DualQpResult::violation)
  double friction_violation = 0;  // largest relative violation of the tangential conditions
  std::vector<int> unheld_modes;  // modes_not_held: the columns of G (rigid modes) left free
  std::vector<int> changing_rows; // cycled / not_converged: the rows (of q + m) the last iteration changed
};

// What one iteration did (MC_LOG_ITERATION).
struct FrictionIteration {
  int iteration = 0, active = 0, stick = 0, slip = 0, changed = 0;
};
using FrictionObserver = std::function<void(const FrictionIteration &)>;

// start_active / start_state: the last converged states (warm start), or empty.
FrictionResult solve_friction_qp(const DualQp &problem, const FrictionProblem &friction, double tolerance,
                                 int max_iterations, const std::vector<char> &start_active,
                                 const std::vector<FrictionState> &start_state, const FrictionObserver &observe = {});

}  // namespace mc
