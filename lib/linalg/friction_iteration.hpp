// The stick/slip iteration of the frictional contact problem, whatever solves its linear systems
// (design note friction.md; Hüeber, Stadler and Wohlmuth 2008; Kunisch and Stadler 2005 for
// Tresca in 2D). Rows: q normal rows, then one tangential row per normal row of a pair with
// friction (tangent_of[j] is the normal row of tangential row q + j). With multipliers
// l = (l_n, l_t) and gaps (gap_n >= 0 open; gap_t = -s, minus the weighted slip of the step):
//   normal rows:      l_n >= 0, gap_n >= 0, l_n gap_n = 0
//   tangential rows:  open (Coulomb, l_n = 0): l_t = 0
//                     stick:            s = 0,               |l_t| <= bound
//                     slip:             l_t = bound sign(s)  (s != 0)
//   (a Tresca row is never open: FrictionProblem::live)
//   bound = mu l_n (Coulomb) or the row's Tresca force.
// Once the states are frozen every condition is linear: each iteration solves one linear system
// (FrictionStatesSolver: the condensed path's dense one, friction_qp.hpp, or the sparse path's,
// sparse_contact_solve.hpp), then updates the states by the primal-dual active-set rule: a
// normal row is active iff (l_n > 0 or gap_n < 0, as in dual_qp.cpp); a sticking row slips (with
// the sign of l_t) once |l_t| exceeds its bound, a slipping row whose slip turns against its sign
// sticks, and a row coming into contact sticks iff |l_t + c_t s| <= bound, else slips with the
// sign of l_t + c_t s. c_t changes the iterates, never the converged answer. If the states
// cycle, one change per iteration (the row of least index) from there.
// Converged states satisfy the conditions to round-off: nothing is regularized.
#pragma once
#include <functional>
#include <vector>

namespace mc {

enum class FrictionState : char { open = 0, stick = 1, slip_plus = 2, slip_minus = 3 };

inline double slip_sign(FrictionState s) { return s == FrictionState::slip_plus ? 1.0 : -1.0; }
inline bool slipping(FrictionState s) { return s == FrictionState::slip_plus || s == FrictionState::slip_minus; }

struct FrictionProblem {
  int normal_rows = 0;               // q; the tangential rows follow
  std::vector<int> tangent_of;       // per tangential row j: its normal row
  std::vector<int> law;              // MC_FRICTION_TRESCA or MC_FRICTION_COULOMB
  std::vector<double> bound;         // mu (Coulomb) or the Tresca bound as a force
  double ct = 0;                     // c_t; 0: 1 / (the largest compliance of a row)
  // Per tangential row (or empty: none): its slip is prescribed, no unknown moves it (both
  // sides' tangential motion held by supports there, e.g. a corner node on a support facing a
  // supported node). Such a row is never an unknown of the linear system (its S row is zero):
  // it sticks if its prescribed slip is zero, else slips with that slip's sign, and its force
  // goes to the supports' reactions.
  std::vector<char> prescribed;
  bool is_prescribed(int j) const { return !prescribed.empty() && prescribed[j]; }
  // Whether tangential row j carries friction in the states `active` of the normal rows: a
  // Coulomb row only in contact (its bound mu l_n is 0 when open); a Tresca row always: the
  // given-bound problem of Kikuchi and Oden holds |l_t| <= g on the whole contact surface,
  // which keeps it convex with a unique answer (bounds that vanish where a row opens would
  // couple the tangential states to the normal ones, and the iteration cycled on them).
  bool live(int j, const std::vector<char> &active) const;
  // Whether tangential row j is in the linear system of states (active, state) as an equation
  // (s = 0): live and sticking, and not prescribed. A live slipping row's multiplier is known instead (l_t = sign *
  // mu l_n, or sign * its Tresca force), an open one's is 0.
  bool sticks(int j, const std::vector<char> &active, const std::vector<FrictionState> &state) const {
    return live(j, active) && state[j] == FrictionState::stick && !is_prescribed(j);
  }
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
  std::vector<int> unheld_modes;  // modes_not_held: the rigid modes left free (if the solver says)
  std::vector<int> changing_rows; // cycled / not_converged: the rows (of q + m) the last iteration changed
};

// What one iteration did (MC_LOG_ITERATION).
struct FrictionIteration {
  int iteration = 0, active = 0, stick = 0, slip = 0, changed = 0;
};
using FrictionObserver = std::function<void(const FrictionIteration &)>;

// The linear system of frozen states (active normal rows, tangential states): fills lambda
// (q + m, the slipping rows' l_t included), alpha (the floating bodies' rigid-mode amplitudes)
// and gap (q + m). Returns false if the states hold no floating body's motion (the system is
// singular). gap_scale: the size of the terms the gaps were computed from, if the solver knows
// it (the sparse path), else 0.
struct FrictionStatesSolution {
  std::vector<double> lambda, alpha, gap;
  double gap_scale = 0;
};
using FrictionStatesSolver = std::function<bool(const std::vector<char> &active, const std::vector<FrictionState> &state,
                                                FrictionStatesSolution &solution)>;

// The sizes the iteration measures against: the largest compliance of a row (S's largest
// diagonal entry, or an estimate of it; c_n = 1 / compliance) and the size of the gaps the loads
// alone would open or close (|d|).
struct FrictionScales {
  double compliance = 1, gap = 0;
};

// start_active: the normal rows to start in contact (size q); start_state: the last converged
// states (a warm start), or empty (every row sticks).
FrictionResult iterate_friction_states(const FrictionProblem &friction, const FrictionStatesSolver &solve_states,
                                       const FrictionScales &scales, double tolerance, int max_iterations,
                                       const std::vector<char> &start_active, const std::vector<FrictionState> &start_state,
                                       const FrictionObserver &observe = {});

}  // namespace mc
