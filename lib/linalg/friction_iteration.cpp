#include "linalg/friction_iteration.hpp"
#include "mortarcontact.h"
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace mc {

bool FrictionProblem::live(int j, const std::vector<char> &active) const {
  return law[j] == MC_FRICTION_TRESCA || active[tangent_of[j]];
}

namespace {

// The rows' Coulomb or Tresca bound: mu times the normal multiplier's prediction
// max(l_n - c_n gap_n, 0) (l_n itself on a row in contact, where gap_n = 0), or the Tresca force.
double friction_bound(const FrictionProblem &f, int j, double lambda_n, double gap_n, double cn) {
  if (f.law[j] == MC_FRICTION_COULOMB) return f.bound[j] * std::max(lambda_n - cn * gap_n, 0.0);
  return f.bound[j];
}

}  // namespace

FrictionResult iterate_friction_states(const FrictionProblem &f, const FrictionStatesSolver &solve_states,
                                       const FrictionScales &scales, double tolerance, int max_iterations,
                                       const std::vector<char> &start_active, const std::vector<FrictionState> &start_state,
                                       const FrictionObserver &observe) {
  FrictionResult result;
  const int q = f.normal_rows, m = int(f.tangent_of.size());
  const double s_scale = scales.compliance > 0 ? scales.compliance : 1, d_scale = scales.gap;
  const double cn = 1 / s_scale, ct = f.ct > 0 ? f.ct : 1 / s_scale, eps = 1e-13;

  std::vector<char> active(start_active);
  std::vector<FrictionState> state(m, FrictionState::stick);
  if (int(start_state.size()) == m) state = start_state;
  for (int j = 0; j < m; ++j)  // (a row without a bound slips whatever happens: it starts so)
    if (state[j] == FrictionState::open || f.bound[j] == 0)
      state[j] = f.bound[j] == 0 ? FrictionState::slip_plus : FrictionState::stick;

  std::set<std::string> seen;
  auto key = [&](const std::vector<char> &a, const std::vector<FrictionState> &st) {
    std::string text(a.begin(), a.end());
    for (FrictionState x : st) text.push_back(char(x));
    return text;
  };
  FrictionStatesSolution solution;
  std::vector<int> last_changing;
  bool single_changes = false;
  auto keep = [&](std::vector<FrictionState> states) {
    result.lambda = solution.lambda, result.alpha = solution.alpha, result.gap = solution.gap;
    result.active = active, result.state = std::move(states);
  };
  // One change (normal row or tangential row `row`, of q + m) of the update (next_active,
  // next_state) applied to (active, state) alone.
  auto apply_one = [&](int row, const std::vector<char> &next_active, const std::vector<FrictionState> &next_state) {
    if (row < q) active[row] = next_active[row];  // a row leaving contact leaves its tangential row open
    else state[row - q] = next_state[row - q];
    for (int j = 0; j < m; ++j)  // (a row coming into contact: its trial state, or it sticks first)
      if (!f.live(j, active)) state[j] = FrictionState::open;
      else if (state[j] == FrictionState::open)
        state[j] = next_state[j] != FrictionState::open ? next_state[j] : FrictionState::stick;
  };
  // The last states whose system was solvable and the update they asked for: if the full update
  // lands on states that hold no floating body's motion (a transient set, as the frictionless
  // iteration meets too, dual_qp.cpp), the iteration steps back and takes the first of those
  // changes that keeps the system solvable, then goes on one change at a time.
  struct Update {
    std::vector<char> active, next_active;
    std::vector<FrictionState> state, next_state;
    std::vector<int> changing;
  } last;
  bool stepped_back = false;
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    bool solved = solve_states(active, state, solution);
    if (!solved && !stepped_back && last.changing.size() > 1) {
      // (a single change that failed is not retried: a second step back is not taken)
      stepped_back = true;
      for (int row : last.changing) {
        active = last.active, state = last.state;
        apply_one(row, last.next_active, last.next_state);
        if (++it > max_iterations) break;
        result.iterations = it;
        if ((solved = solve_states(active, state, solution))) break;
      }
      if (solved) single_changes = true, seen.clear();
    }
    if (!solved) {
      result.outcome = FrictionOutcome::modes_not_held;
      result.active = active, result.state = state;
      return result;
    }
    const std::vector<double> &lambda = solution.lambda, &gap = solution.gap;
    double lambda_ref = 0;
    for (double v : lambda) lambda_ref = std::max(lambda_ref, std::fabs(v));
    lambda_ref = std::max(lambda_ref, 1e-300);
    const double gap_ref = std::max({s_scale * lambda_ref, d_scale, solution.gap_scale, 1e-300});
    // The states' update (the primal-dual active-set rule).
    std::vector<char> next_active(active);
    for (int r = 0; r < q; ++r)
      next_active[r] = active[r] ? !(lambda[r] < -eps * lambda_ref) : gap[r] < -eps * gap_ref;
    std::vector<FrictionState> next_state(state);
    double friction_violation = 0;
    long stick = 0, slip = 0;
    for (int j = 0; j < m; ++j) {
      const int r = f.tangent_of[j];
      if (!f.live(j, next_active)) {
        next_state[j] = FrictionState::open;
        continue;
      }
      const double bound = friction_bound(f, j, lambda[r], gap[r], cn), lt = lambda[q + j], s = -gap[q + j];
      if (f.is_prescribed(j)) {  // its slip is given: its state follows it
        next_state[j] = std::fabs(s) <= eps * gap_ref ? FrictionState::stick
                        : s > 0                      ? FrictionState::slip_plus
                                                     : FrictionState::slip_minus;
        if (next_state[j] == FrictionState::stick) ++stick;
        else ++slip;
        continue;
      }
      if (f.bound[j] == 0) {  // mu = 0 or a zero Tresca bound: l_t = 0 whatever the slip's sign
        next_state[j] = FrictionState::slip_plus;
        ++slip;
        continue;
      }
      auto by_trial = [&]() {  // |l_t + c_t s| against the bound
        const double xi = lt + ct * s;
        return std::fabs(xi) <= bound ? FrictionState::stick : xi > 0 ? FrictionState::slip_plus : FrictionState::slip_minus;
      };
      const bool was_live = f.live(j, active);
      if (was_live && state[j] == FrictionState::stick) {
        if (std::fabs(lt) > bound + eps * lambda_ref) next_state[j] = lt > 0 ? FrictionState::slip_plus : FrictionState::slip_minus;
        friction_violation = std::max({friction_violation, std::fabs(s) / gap_ref,
                                       std::max(0.0, std::fabs(lt) - bound) / lambda_ref});
      } else if (was_live && slipping(state[j])) {
        // A slip against its sign: stick first (the trial value would send a row whose c_t s
        // outweighs its bound straight to the other sign, and the iteration zig-zags between
        // the two; both rules have the same fixed points).
        if (slip_sign(state[j]) * s < -eps * gap_ref) next_state[j] = FrictionState::stick;
        friction_violation = std::max({friction_violation, std::max(0.0, -slip_sign(state[j]) * s) / gap_ref,
                                       std::fabs(lt - slip_sign(state[j]) * bound) / lambda_ref});
      } else {
        next_state[j] = by_trial();
      }
      if (next_state[j] == FrictionState::stick) ++stick;
      else ++slip;
    }
    int changed = 0;
    std::vector<int> changing;
    for (int r = 0; r < q; ++r)
      if (next_active[r] != active[r]) ++changed, changing.push_back(r);
    for (int j = 0; j < m; ++j)
      if (next_state[j] != state[j] && !(state[j] == FrictionState::open && next_state[j] == FrictionState::open))
        if (f.live(j, active) || f.live(j, next_active)) ++changed, changing.push_back(q + j);
    int n_active = 0;
    for (char x : active) n_active += x;
    if (observe) observe({it, n_active, int(stick), int(slip), changed});
    if (changed == 0) {
      keep(next_state);
      result.stick = stick, result.slip = slip;
      // The normal rows' complementarity, as the frictionless solver reports it.
      double worst = 0;
      for (int r = 0; r < q; ++r) {
        worst = std::max(worst, std::max(0.0, -lambda[r]) / lambda_ref);
        worst = std::max(worst, std::max(0.0, -gap[r]) / gap_ref);
        worst = std::max(worst, std::fabs(lambda[r] * gap[r]) / (lambda_ref * gap_ref));
      }
      result.violation = worst, result.friction_violation = friction_violation;
      result.outcome = worst <= tolerance && friction_violation <= tolerance ? FrictionOutcome::solved
                                                                             : FrictionOutcome::not_converged;
      return result;
    }
    if (!seen.insert(key(active, state)).second) {
      if (single_changes) {
        result.outcome = FrictionOutcome::cycled;
        keep(state);
        result.changing_rows = changing;
        return result;
      }
      // The full update cycled (it converges only for M-matrix-like operators, as the
      // frictionless one, dual_qp.cpp): from here one change per iteration, the row of least
      // index (Murty's rule, finite for the frictionless problem; for friction no rule is
      // known to be, so a second cycle is reported).
      single_changes = true;
      seen.clear();
      seen.insert(key(active, state));
    }
    last_changing = changing;
    last = {active, next_active, state, next_state, changing};
    if (single_changes) {
      apply_one(changing.front(), next_active, next_state);
      continue;
    }
    active = next_active, state = next_state;
    for (int j = 0; j < m; ++j)
      if (state[j] == FrictionState::open && f.live(j, active))
        state[j] = f.bound[j] == 0 ? FrictionState::slip_plus : FrictionState::stick;
  }
  result.outcome = FrictionOutcome::not_converged;
  keep(state);
  result.changing_rows = last_changing;
  return result;
}

}  // namespace mc
