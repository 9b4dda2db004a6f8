#include "linalg/sparse_contact_solve.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>
#include <exception>
#include <pthread.h>
#include <set>
#include <system_error>
#include <thread>

namespace mc {

namespace {


// Refinement steps on the KKT system's own residuals (solve_on_active_set); the Krylov solves
// are in sparse_krylov.cpp, the low-rank updates of the factor in sparse_factor_update.cpp.
constexpr int kMaxRefinements = 6;
// A final answer whose KKT residual (relative, as solve_on_active_set measures it) stays above
// this after refinement through a low-rank update is solved again on a factorization of its
// own: on the long strips pressed over a tenth of their length (bench/moving_load) the update's
// answers stopped at 4e-12 and differed from a first solve's by 5.6e-5 of the pressure, a
// factorization's by 3e-8 (docs/robustness.md, "A load on a part of a long strip").
constexpr double kUpdateResidual = 1e-14;
// Where the surfaces are apart at the start (a cylinder on a block, a wavy surface), a solve
// without a start begins from the rows whose initial gap is at most this share of the way from
// the smallest (or 0, if some rows overlap) to the largest, instead of from every row (measured
// from the smallest: a disc 10 to 1000 cells above its block took 9 to 10 iterations from the
// largest's share, which then held every row; test_contact_hard's gaps with the sparse path).
// From every row the primal-dual iteration releases a band of rows
// at each end of a zone per iteration (Hertz forced sparse: 12 iterations, 46, 29, 59, ... 1
// rows). A guess the iteration corrects, chosen among 0.02, 0.05, 0.1 and 0.2 on Hertz (h1 =
// 0.004: 12 iterations -> 7, 7, 4, 8; h1 = 0.0025: 12 -> 8, 6, 5, 8) and Westergaard at 100
// wavelengths (5 -> 5, 4, 3 from 0.05 on); docs/notes/interface-solver.md, "A start from the
// gaps".
constexpr double kStartGap = 0.1;
// The sets on the way to the final one are judged by a Krylov solve to this relative residual
// of the active rows (the final set's is refined to round-off, and judged again). On the load
// history at 4001 contact nodes (bench/moving_load) a step took 27 CG steps to 1e-14, 22 to
// 1e-12, 20 to 1e-10, 17 to 1e-8, and 42 to 1e-6 (the final set's refinement then starts far
// off), with the same sets and iterations at each (docs/notes/interface-solver.md, "Session 20").
constexpr double kJudgingTolerance = 1e-8;
// The refinement stops at a relative KKT residual this small: each of x's entries is then
// rounded to double as it is stored, and a residual of x rounded is up to half an epsilon of
// the row's terms; a further step cannot halve it but by chance (on the strips, the load history
// and Westergaard, every step past 7e-17 to 8e-17 was thrown away, at 4 Krylov solves and two
// residuals each: 6 % to 14 % of a solve; docs/notes/interface-solver.md, "Session 23").
constexpr double kRoundOffResidual = 0.5 * 2.220446049250313e-16;

}  // namespace

bool SparseContactSolver::aside_holds_every_row() const {
  if (aside_set_.empty() || aside_modifications_ != 0) return false;
  const SparseContactStructure &s = *structure_;
  for (int r = 0; r < s.rows(); ++r)
    if (bool(aside_set_[r]) != bool(s.row_is_inequality[r])) return false;
  return true;
}

double SparseContactSolver::row_compliance(int r) const { return kAugmentation / weight_[size_t(r)]; }

double SparseContactSolver::row_times(int r, const std::vector<double> &x) const {
  const SparseContactStructure &s = *structure_;
  double v = 0;
  for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) v += s.value[p] * x[s.column[p]];
  return v;
}

void SparseContactSolver::apply_ct(const std::vector<double> &y, std::vector<double> &out) const {
  const SparseContactStructure &s = *structure_;
  out.assign(s.n_unknowns, 0.0);
  for (int r = 0; r < s.rows(); ++r)
    if (y[r] != 0)
      for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) out[s.column[p]] += s.value[p] * y[r];
}

void SparseContactSolver::apply_dt(const std::vector<double> &y, std::vector<double> &out) const {
  apply_ct(y, out);
  const SparseContactStructure &s = *structure_;
  for (const Coupling &c : coupling_)
    if (y[c.row] != 0)
      for (int p = s.row_start[c.other]; p < s.row_start[c.other + 1]; ++p)
        out[s.column[p]] += c.coefficient * s.value[p] * y[c.row];
}

void SparseContactSolver::run_in_pairs(const std::function<void(size_t)> &task, bool worth_a_thread) const {
  if (threads_ > 1 && worth_a_thread) {
    // What the second thread throws (an allocation that failed) is thrown here after the join.
    std::exception_ptr failed;
    std::thread second;
    try {
      second = std::thread([&] {
        try {
          task(1);
        } catch (...) {
          failed = std::current_exception();
        }
      });
    } catch (const std::system_error &) {  // no thread to be had: in turn
    }
    if (second.joinable()) {
      // The library's second thread has one name wherever it runs (model.cpp's body threads).
      pthread_setname_np(second.native_handle(), "mc-body2");
      try {
        task(0);
      } catch (...) {
        second.join();
        throw;
      }
      second.join();
      if (failed) std::rethrow_exception(failed);
      return;
    }
  }
  task(0), task(1);
}

double SparseContactSolver::solve_on_active_set(const std::vector<double> &load, const std::vector<double> &target,
                                              std::vector<double> &x, std::vector<double> &lambda,
                                              SparseContactResult &result, KktGoal goal) const {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  auto krylov = [&](const std::vector<double> &f, const std::vector<double> &t, std::vector<double> &xx,
                    std::vector<double> &ll, double tolerance) {
    if (coupling_.empty()) conjugate_gradients(f, t, xx, ll, result, tolerance);
    else gmres(f, t, xx, ll, result);
  };
  // A set on the way is judged by the signs of its forces and gaps: to kJudgingTolerance.
  if (goal != KktGoal::refine) krylov(load, target, x, lambda, goal == KktGoal::judge ? kJudgingTolerance : 0.0);
  if (goal == KktGoal::judge) return -1;  // not measured
  // Iterative refinement on the KKT system's own residuals (F - H x - C_A^T lambda, t_A - C_A x):
  // CG's recursive residual drifts from the true one by round-off of H_P's conditioning.
  // The residuals are summed in long double (x87 extended precision, 64-bit mantissa, where the
  // platform has it): a residual summed in double carries round-off of eps |H| |x|, which bounds
  // how far refinement can take the answer; summed more precisely, refinement reaches the exact
  // solution of the stored system to about eps times its condition less (classical mixed-
  // precision refinement; docs/notes/interface-solver.md).
  auto residuals = [&](std::vector<double> &rf, std::vector<double> &rt) {
    // (Each term's size is summed in double: it only scales the residual.)
    std::vector<long double> sum(s.n_unknowns, 0.0L);
    std::vector<double> size(s.n_unknowns, 0.0);
    for (int i = 0; i < s.n_unknowns; ++i) sum[i] = load[i], size[i] = std::fabs(load[i]);
    for (int r = 0; r < nrows; ++r)
      if (!s.row_is_inequality[r] || factorized_[r])
        for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) {
          sum[s.column[p]] -= (long double)s.value[p] * lambda[r], size[s.column[p]] += std::fabs(s.value[p] * lambda[r]);
        }
    for (const Coupling &c : coupling_)  // D_r = C_r + coefficient C_other
      for (int p = s.row_start[c.other]; p < s.row_start[c.other + 1]; ++p) {
        const long double term = (long double)c.coefficient * s.value[p] * lambda[c.row];
        sum[s.column[p]] -= term, size[s.column[p]] += double(std::fabs(term));
      }
    // H x, block by block: each block's unknowns are its own, so the odd blocks (body 2's) may
    // run on a second thread, each sum in the same order either way.
    auto block_terms = [&](size_t first) {
      for (size_t b = first; b < s.blocks.size(); b += 2) {
        const int o = s.block_offset[b];
        for (int j = 0; j < s.blocks[b].n; ++j)
          s.blocks[b].for_each_in_column(j, [&](int i, double value) {
            sum[o + i] -= (long double)value * x[o + j], size[o + i] += std::fabs(value * x[o + j]);
            if (i != j) sum[o + j] -= (long double)value * x[o + i], size[o + j] += std::fabs(value * x[o + i]);
          });
      }
    };
    run_in_pairs(block_terms, s.blocks.size() > 1 && s.n_unknowns >= kResidualThreadsFromUnknowns);
    rf.assign(s.n_unknowns, 0.0);
    long double worst = 0, largest = 0;
    for (int i = 0; i < s.n_unknowns; ++i) {
      rf[i] = double(sum[i]);
      worst = std::max(worst, std::fabs(sum[i])), largest = std::max(largest, (long double)size[i]);
    }
    rt.assign(nrows, 0.0);
    long double gap_worst = 0, gap_size = 0;
    for (int r = 0; r < nrows; ++r)
      if (!s.row_is_inequality[r] || factorized_[r]) {
        long double g = target[r], terms = std::fabs(target[r]);
        double norm = 0;
        for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) {
          const long double term = (long double)s.value[p] * x[s.column[p]];
          g -= term, terms += std::fabs(term), norm = std::max(norm, std::fabs(s.value[p]));
        }
        rt[r] = double(g);
        if (norm > 0) gap_worst = std::max(gap_worst, std::fabs(g) / norm), gap_size = std::max(gap_size, terms / norm);
      }
    return double(std::max(worst / std::max(largest, 1e-300L), gap_worst / std::max(gap_size, 1e-300L)));
  };
  std::vector<double> rf, rt;
  double current = residuals(rf, rt);
  for (int step = 0; step < kMaxRefinements && current > kRoundOffResidual; ++step) {
    std::vector<double> dx(s.n_unknowns, 0.0), dl(nrows, 0.0);
    krylov(rf, rt, dx, dl, 0.0);
    std::vector<double> x_new(x), l_new(lambda);
    for (int i = 0; i < s.n_unknowns; ++i) x_new[i] += dx[i];
    for (int r = 0; r < nrows; ++r) l_new[r] += dl[r];
    std::swap(x, x_new), std::swap(lambda, l_new);
    std::vector<double> rf_new, rt_new;
    const double refined = residuals(rf_new, rt_new);
    if (!(refined < 0.5 * current)) {  // no gain: keep what we had
      std::swap(x, x_new), std::swap(lambda, l_new);
      break;
    }
    current = refined, rf = std::move(rf_new), rt = std::move(rt_new);
  }
  return current;
}

// Complementarity of the contact rows, measured as the condensed path measures it: their gaps,
// the rows that violate it (an active row pulling, an inactive one penetrating: to be flipped),
// the largest relative violation; lambda_ref the largest |force|.
double SparseContactSolver::complementarity(const std::vector<double> &target, const std::vector<char> &active,
                                            const std::vector<double> &x, const std::vector<double> &lambda,
                                            std::vector<double> &gap,
                                            std::vector<int> &violating, double &lambda_ref) const {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  const double eps = 1e-13;
  double gap_ref = 0;
  lambda_ref = 0;
  for (int r = 0; r < nrows; ++r) {
    if (!s.row_is_inequality[r]) continue;
    gap[r] = target[r] - row_times(r, x);
    double terms = std::fabs(target[r]);
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) terms += std::fabs(s.value[p] * x[s.column[p]]);
    lambda_ref = std::max(lambda_ref, std::fabs(lambda[r]));
    gap_ref = std::max(gap_ref, terms);
  }
  lambda_ref = std::max(lambda_ref, 1e-300), gap_ref = std::max(gap_ref, 1e-300);
  violating.clear();
  double violation = 0;
  for (int r = 0; r < nrows; ++r) {
    if (!s.row_is_inequality[r]) continue;
    if ((active[r] && lambda[r] < -eps * lambda_ref) || (!active[r] && gap[r] < -eps * gap_ref)) violating.push_back(r);
    violation = std::max(violation, std::max(0.0, -lambda[r]) / lambda_ref);
    violation = std::max(violation, std::max(0.0, -gap[r]) / gap_ref);
    violation = std::max(violation, std::fabs(lambda[r] * gap[r]) / (lambda_ref * gap_ref));
  }
  return violation;
}

SparseContactResult SparseContactSolver::solve(const std::vector<double> &load, const std::vector<double> &target,
                                               const std::vector<char> &start, double tolerance, int max_iterations,
                                               const std::function<bool(const std::vector<char> &)> &hold_modes,
                                               const DualQpObserver &observe, const std::vector<double> &initial_gap) {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  SparseContactResult result;
  coupling_.clear();
  // The factor aside lives for this solve only (it doubles the factors' memory), unless it is
  // that of every contact row, unmodified: the start a re-solve may go back to.
  struct AsideForThisSolve {
    SparseContactSolver &solver;
    explicit AsideForThisSolve(SparseContactSolver &s) : solver(s) { solver.keep_aside_ = true; }
    ~AsideForThisSolve() {
      solver.keep_aside_ = false;
      if (solver.aside_holds_every_row()) return;
      solver.cholesky_.release_aside();
      solver.aside_set_.clear();
    }
  } aside_for_this_solve(*this);
  std::vector<char> active(nrows, 0);
  const bool warm_start = int(start.size()) == nrows;
  for (int r = 0; r < nrows; ++r) active[r] = s.row_is_inequality[r] && (warm_start ? start[r] : 1);
  // A solve without a start begins from the rows whose initial gap is within kStartGap of the
  // way from the smallest to the largest (all of them where the surfaces touch along their
  // length), if those hold the floating bodies, else from every row; if the iteration from there cycles, wanders or reaches
  // a set that does not hold the floating bodies, it starts again from every row.
  bool started = warm_start, from_gaps = false;
  if (!warm_start) {
    const std::vector<double> &gap0 = initial_gap.empty() ? target : initial_gap;
    std::vector<char> near(nrows, 0);
    double largest = -HUGE_VAL, smallest = HUGE_VAL;
    for (int r = 0; r < nrows; ++r)
      if (s.row_is_inequality[r]) largest = std::max(largest, gap0[r]), smallest = std::min(smallest, gap0[r]);
    const double bound = std::max(smallest, 0.0) + kStartGap * (largest - std::max(smallest, 0.0));
    for (int r = 0; r < nrows; ++r) near[r] = s.row_is_inequality[r] && gap0[r] <= bound;
    if (largest > 0 && near != active && (!hold_modes || hold_modes(near)))
      active = std::move(near), started = from_gaps = true;
  }
  int release_at = started ? 2 : 1;  // the iteration after which release_slack_rows applies
  bool restarted = false;  // from every row, once (a re-solve's first step proposed a set far from both factors)
  // A re-solve after one whose start was poor begins from every row (begin_from_every_row_).
  const std::vector<char> start_set = active;
  const bool begun_from_every_row = warm_start && begin_from_every_row_ && aside_holds_every_row();
  if (begun_from_every_row) active = aside_set_, restarted = true, release_at = 1;
  bool sent_to_every_row = false;  // by the first step's proposal (below)
  // What the next re-solve learns from this one's start (begin_from_every_row_).
  auto judge_the_start = [&]() {
    begin_from_every_row_ =
        warm_start && (sent_to_every_row || (begun_from_every_row && far_apart(start_set, active)));
  };
  begin_from_every_row_ = false;
  std::vector<double> x(s.n_unknowns, 0.0), lambda(nrows, 0.0), gap(nrows, 0.0);
  std::set<std::vector<char>> seen;
  size_t fewest_violating = size_t(nrows) + 1;
  int fewest_at = 0;
  const int patience = 20;  // as the condensed path's (dual_qp.cpp)
  std::vector<int> sizes;  // the active rows of each iteration
  auto start_again_from_every_row = [&](int it) {
    for (int r = 0; r < nrows; ++r) active[r] = s.row_is_inequality[r];
    from_gaps = false, release_at = it + 1, seen.clear(), fewest_violating = size_t(nrows) + 1, fewest_at = it;
  };
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    int n_active = 0;
    for (int r = 0; r < nrows; ++r) n_active += s.row_is_inequality[r] && active[r];
    if (hold_modes && !hold_modes(active)) {
      if (observe) observe({it, n_active, 0, 0.0, false});
      if (from_gaps) {
        start_again_from_every_row(it);
        continue;
      }
      result.outcome = it == 1 ? SparseContactOutcome::modes_not_held : SparseContactOutcome::not_converged;
      result.cycled = it > 1;
      return result;
    }
    if (factorized_ != active) factorize(active, result);
    // The sets on the way are judged by the Krylov solve alone (the signs of forces and gaps,
    // far above its error); refined only a set that looks final, then judged again. On Hertz
    // forced onto this path refining every set took 86 of 125 CG steps.
    solve_on_active_set(load, target, x, lambda, result, KktGoal::judge);
    std::vector<int> violating;
    double lambda_ref = 0, violation = complementarity(target, active, x, lambda, gap, violating, lambda_ref);
    if (violating.empty()) {
      const double refined = solve_on_active_set(load, target, x, lambda, result, KktGoal::refine);
      if ((!update_.rows.empty() || modifications_ > 0) && refined > kUpdateResidual) {
        // The answer came through a low-rank update and its refinement stopped short of
        // round-off (an ill-conditioned H_P: a long strip whose free part only the contact zone
        // holds): its own factorization, so that the answer is that of a first solve.
        factorize_afresh(active, result);
        solve_on_active_set(load, target, x, lambda, result, KktGoal::refine);
      }
      violation = complementarity(target, active, x, lambda, gap, violating, lambda_ref);
    }
    result.violation = violation;
    if (observe) observe({it, n_active, int(violating.size()), violation, true});
    if (violating.empty()) {
      judge_the_start();
      result.x = std::move(x), result.lambda = std::move(lambda), result.active = active;
      result.outcome = violation <= tolerance ? SparseContactOutcome::solved : SparseContactOutcome::not_converged;
      return result;
    }
    if (violating.size() < fewest_violating) fewest_violating = violating.size(), fewest_at = it;
    // A crawl is progress too (crawling, dual_qp.hpp).
    sizes.push_back(n_active);
    if (crawling(sizes, violating.size(), patience)) fewest_at = it;
    if (it - fewest_at >= patience) {
      if (!from_gaps) break;
      start_again_from_every_row(it);
      continue;
    }
    std::vector<char> next(active);
    for (int r : violating) next[r] = !next[r];
    // Negligible forces released with the pulling ones (release_slack_rows, dual_qp.hpp).
    if (it == release_at) release_slack_rows(lambda, lambda_ref, next);
    if (!seen.insert(next).second) {  // a cycle
      // Among sets whose violations are round-off (every force of a body resting at zero gap
      // is 1e-16 of either sign: test_interface_solvers' weakly active nodes) the flips follow
      // the signs of round-off and may come back: a set within the tolerance asked for ends the
      // iteration, refined as a final one; else the condensed path takes over.
      solve_on_active_set(load, target, x, lambda, result, KktGoal::refine);
      result.violation = complementarity(target, active, x, lambda, gap, violating, lambda_ref);
      if (result.violation <= tolerance) {
        judge_the_start();
        result.x = std::move(x), result.lambda = std::move(lambda), result.active = active;
        result.outcome = SparseContactOutcome::solved;
        return result;
      }
      if (!from_gaps) break;
      start_again_from_every_row(it);
      continue;
    }
    // A re-solve after a load change whose first step proposes a set that only a factorization
    // reaches (the strips under a moved load: the last zone tips body 1 and thousands of rows
    // enter, to leave again at the next step, docs/notes/interface-solver.md) goes on from every
    // row instead, as a first solve starts, whose factor is kept: from there the next set lies
    // near the last step's, whose factor is then modified. A factorization less per load step.
    if (warm_start && it == 1 && !restarted && aside_holds_every_row() && next != aside_set_ &&
        needs_factorization(next)) {
      next = aside_set_, restarted = sent_to_every_row = true, release_at = it + 1;
      seen.insert(next);
    }
    active = std::move(next);
  }
  result.outcome = SparseContactOutcome::not_converged;
  result.cycled = result.iterations < max_iterations;
  result.x = std::move(x), result.lambda = std::move(lambda);
  return result;
}

void SparseContactSolver::solve_rows(const std::vector<double> &load, const std::vector<double> &target,
                                     const std::vector<char> &set, const std::vector<Coupling> &coupling,
                                     std::vector<double> &x, std::vector<double> &lambda, SparseContactResult &result) {
  const SparseContactStructure &s = *structure_;
  std::vector<char> rows(set);
  for (int r = 0; r < s.rows(); ++r) rows[r] = s.row_is_inequality[r] && set[r];
  if (factorized_ != rows) factorize(rows, result);
  coupling_ = coupling;
  x.assign(s.n_unknowns, 0.0);
  lambda.resize(s.rows(), 0.0);
  solve_on_active_set(load, target, x, lambda, result, KktGoal::exact);
  coupling_.clear();
}

}  // namespace mc
