#include "linalg/friction_qp.hpp"
#include "linalg/sparse_lu.hpp"
#include "mortarcontact.h"
#include "support/lapack.hpp"
#include <algorithm>
#include <cmath>
#include <set>

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

double slip_sign(FrictionState s) { return s == FrictionState::slip_plus ? 1.0 : -1.0; }
bool slipping(FrictionState s) { return s == FrictionState::slip_plus || s == FrictionState::slip_minus; }

// A slipping row's multiplier in terms of the unknowns: l_t = sign * mu * l_n (Coulomb) or
// sign * its Tresca force.
void set_slip_multipliers(const FrictionProblem &f, const std::vector<char> &active,
                          const std::vector<FrictionState> &state, std::vector<double> &lambda) {
  const int q = f.normal_rows, m = int(f.tangent_of.size());
  for (int j = 0; j < m; ++j)
    if (f.live(j, active) && slipping(state[j]))
      lambda[q + j] = slip_sign(state[j]) * f.bound[j] * (f.law[j] == MC_FRICTION_COULOMB ? lambda[f.tangent_of[j]] : 1.0);
}

// solve_states' system when S is stored by blocks: the same equations assembled sparse (S's
// stored blocks only, G's nonzeros) and factorized by sparse LU with pivoting (UMFPACK), with
// the same test of the reciprocal condition number (dgecon's estimator on the sparse factor).
// rows / index: the unknowns' rows and each row's unknown (-1: none), as solve_states numbers them.
bool solve_states_by_blocks(const DualQp &p, const FrictionProblem &f, const std::vector<char> &active,
                            const std::vector<FrictionState> &state, double g_scale, const std::vector<int> &rows,
                            const std::vector<int> &index, std::vector<double> &lambda, std::vector<double> &alpha) {
  const int nb = p.q, q = f.normal_rows, m = int(f.tangent_of.size()), k = p.k, nf = int(rows.size()), n = nf + k;
  std::vector<long> row, column;
  std::vector<double> value, rhs(n, 0.0);
  auto add = [&](int r, int c, double v) { row.push_back(r), column.push_back(c), value.push_back(v); };
  // The slipping rows: a Coulomb row's column goes to its normal row's unknown (times mu and its
  // sign), a Tresca row's known force to the right-hand side.
  std::vector<char> unknown(nb, 0), slip(nb, 0);
  for (int r : rows) unknown[r] = 1;
  std::vector<double> slip_factor(nb, 0.0);
  for (int j = 0; j < m; ++j)
    if (f.live(j, active) && slipping(state[j])) slip[q + j] = 1, slip_factor[q + j] = slip_sign(state[j]) * f.bound[j];
  auto slip_term = [&](int eq, int col, double v) {
    const int j = col - q;
    if (f.law[j] == MC_FRICTION_COULOMB) add(eq, index[f.tangent_of[j]], v * slip_factor[col]);
    else rhs[eq] -= v * slip_factor[col];
  };
  // Equations of the unknowns' rows: (S l - G a)_i = d_i.
  p.s.for_each_entry(unknown, unknown, [&](int r, int c, double v) { add(index[r], index[c], v); });
  p.s.for_each_entry(unknown, slip, [&](int r, int c, double v) { slip_term(index[r], c, v); });
  for (int e = 0; e < nf; ++e) rhs[e] += p.d[rows[e]];
  // G^T l = e (scaled by -g_scale), and G's columns.
  for (int c = 0; c < k; ++c) {
    const int e = nf + c;
    for (int col = 0; col < nf; ++col) {
      const double v = -g_scale * p.g[size_t(c) * nb + rows[col]];
      if (v != 0) add(e, col, v), add(col, e, v);
    }
    for (int r = q; r < nb; ++r) {
      const double v = -g_scale * p.g[size_t(c) * nb + r];
      if (slip[r] && v != 0) slip_term(e, r, v);
    }
    rhs[e] += -g_scale * p.e[c];
  }
  SparseLu lu;
  if (!lu.factorize(n, row, column, value)) return false;
  if (!(lu.reciprocal_condition() > 1e-14)) return false;
  std::vector<double> x(n);
  lu.solve(rhs.data(), x.data());
  for (int e = 0; e < nf; ++e) lambda[rows[e]] = x[e];
  for (int c = 0; c < k; ++c) alpha[c] = g_scale * x[nf + c];
  set_slip_multipliers(f, active, state, lambda);
  return true;
}

// The linear system of one set of states: unknowns l on the normal rows in contact and on the
// sticking tangential rows, and alpha; a slipping row's l_t = sign * (mu l_n or its Tresca
// force) is substituted. Equations: (S l - G a)_i = d_i on the unknowns' rows, G^T l = e (the G
// block scaled by g_scale so that both blocks are of one size). Returns false if the system is
// singular (reciprocal condition number below 1e-14): a floating body's motion that no row in
// contact, no sticking row and no support holds.
bool solve_states(const DualQp &p, const FrictionProblem &f, const std::vector<char> &active,
                  const std::vector<FrictionState> &state, double g_scale, std::vector<double> &lambda,
                  std::vector<double> &alpha) {
  const int nb = p.q, q = f.normal_rows, m = int(f.tangent_of.size()), k = p.k;
  std::vector<int> rows, index(nb, -1);
  for (int r = 0; r < q; ++r)
    if (active[r]) index[r] = int(rows.size()), rows.push_back(r);
  for (int j = 0; j < m; ++j)
    if (f.live(j, active) && state[j] == FrictionState::stick) index[q + j] = int(rows.size()), rows.push_back(q + j);
  const int nf = int(rows.size()), n = nf + k;
  lambda.assign(nb, 0.0);
  alpha.assign(k, 0.0);
  if (n == 0) return true;
  if (!p.s.dense()) return solve_states_by_blocks(p, f, active, state, g_scale, rows, index, lambda, alpha);
  std::vector<double> a(size_t(n) * n, 0.0), rhs(n, 0.0);
  auto at = [&](int row, int col) -> double & { return a[size_t(col) * n + row]; };
  const double *s_values = p.s.dense_values();
  const auto s = [&](int i, int c) { return s_values[size_t(c) * nb + i]; };
  const auto g = [&](int i, int c) { return p.g[size_t(c) * nb + i]; };
  // A slipping row's multiplier: coefficient times l_n (Coulomb) or a known force (Tresca).
  auto slip_terms = [&](int eq, auto &&value_of_row) {
    for (int j = 0; j < m; ++j) {
      if (!f.live(j, active) || !slipping(state[j])) continue;
      const double v = value_of_row(q + j) * slip_sign(state[j]);
      if (f.law[j] == MC_FRICTION_COULOMB) at(eq, index[f.tangent_of[j]]) += v * f.bound[j];
      else rhs[eq] -= v * f.bound[j];
    }
  };
  for (int e = 0; e < nf; ++e) {
    const int i = rows[e];
    for (int c = 0; c < nf; ++c) at(e, c) = s(i, rows[c]);
    slip_terms(e, [&](int col) { return s(i, col); });
    for (int c = 0; c < k; ++c) at(e, nf + c) = -g_scale * g(i, c);
    rhs[e] += p.d[i];
  }
  for (int c = 0; c < k; ++c) {
    const int e = nf + c;
    for (int col = 0; col < nf; ++col) at(e, col) = -g_scale * g(rows[col], c);
    slip_terms(e, [&](int row) { return -g_scale * g(row, c); });
    rhs[e] += -g_scale * p.e[c];
  }
  double norm = 0;  // 1-norm, for the condition estimate
  for (int c = 0; c < n; ++c) {
    double sum = 0;
    for (int r = 0; r < n; ++r) sum += std::fabs(at(r, c));
    norm = std::max(norm, sum);
  }
  std::vector<int> ipiv(n), iwork(n);
  int info = 0, one = 1;
  dgetrf_(&n, &n, a.data(), &n, ipiv.data(), &info);
  if (info != 0) return false;
  double rcond = 0;
  std::vector<double> work(4 * size_t(n));
  dgecon_("1", &n, a.data(), &n, &norm, &rcond, work.data(), iwork.data(), &info);
  if (info != 0 || !(rcond > 1e-14)) return false;
  dgetrs_("N", &n, &one, a.data(), &n, ipiv.data(), rhs.data(), &n, &info);
  if (info != 0) return false;
  for (int e = 0; e < nf; ++e) lambda[rows[e]] = rhs[e];
  for (int c = 0; c < k; ++c) alpha[c] = g_scale * rhs[nf + c];
  set_slip_multipliers(f, active, state, lambda);
  return true;
}

// The rigid modes that the rows in contact and the sticking rows leave free: the null space of
// their rows of G (eigenvectors of G_F^T G_F with eigenvalues below 1e-10 of the largest), as
// the modes with a share of 10 % or more in one of them.
std::vector<int> free_modes(const DualQp &p, const FrictionProblem &f, const std::vector<char> &active,
                            const std::vector<FrictionState> &state) {
  const int nb = p.q, q = f.normal_rows, k = p.k;
  std::vector<int> rows;
  for (int r = 0; r < q; ++r)
    if (active[r]) rows.push_back(r);
  for (size_t j = 0; j < f.tangent_of.size(); ++j)
    if (f.live(j, active) && state[j] == FrictionState::stick) rows.push_back(q + int(j));
  std::vector<double> gram(size_t(k) * k, 0.0), eig(k);
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b)
      for (int r : rows) gram[size_t(b) * k + a] += p.g[size_t(a) * nb + r] * p.g[size_t(b) * nb + r];
  int n = k, lwork = 64 + 3 * k, info = 0;
  std::vector<double> work(lwork);
  std::vector<int> modes;
  if (k == 0) return modes;
  dsyev_("V", "U", &n, gram.data(), &n, eig.data(), work.data(), &lwork, &info);
  if (info != 0) return modes;
  std::vector<char> free(k, 0);
  for (int c = 0; c < k && eig[c] <= 1e-10 * std::max(eig[k - 1], 1e-300); ++c)
    for (int a = 0; a < k; ++a)
      if (std::fabs(gram[size_t(c) * k + a]) >= 0.1) free[a] = 1;
  for (int a = 0; a < k; ++a)
    if (free[a]) modes.push_back(a);
  return modes;
}

}  // namespace

FrictionResult solve_friction_qp(const DualQp &p, const FrictionProblem &f, double tolerance, int max_iterations,
                                 const std::vector<char> &start_active, const std::vector<FrictionState> &start_state,
                                 const FrictionObserver &observe) {
  FrictionResult result;
  const int nb = p.q, q = f.normal_rows, m = int(f.tangent_of.size());
  double s_scale = 0, d_scale = 0;
  for (int i = 0; i < nb; ++i) s_scale = std::max(s_scale, p.s.diagonal(i));
  for (int i = 0; i < nb; ++i) d_scale = std::max(d_scale, std::fabs(p.d[i]));
  if (!(s_scale > 0)) s_scale = 1;
  const double cn = 1 / s_scale, ct = f.ct > 0 ? f.ct : 1 / s_scale, eps = 1e-13;

  std::vector<char> active(q, 0);
  if (int(start_active.size()) == q) active = start_active;
  else if (p.k > 0) std::fill(active.begin(), active.end(), 1);
  else for (int r = 0; r < q; ++r) active[r] = p.d[r] > 0;
  std::vector<FrictionState> state(m, FrictionState::stick);
  if (int(start_state.size()) == m) state = start_state;
  for (int j = 0; j < m; ++j)
    if (state[j] == FrictionState::open) state[j] = f.bound[j] == 0 ? FrictionState::slip_plus : FrictionState::stick;

  std::set<std::string> seen;
  auto key = [&](const std::vector<char> &a, const std::vector<FrictionState> &st) {
    std::string text(a.begin(), a.end());
    for (FrictionState x : st) text.push_back(char(x));
    return text;
  };
  std::vector<double> lambda, alpha, gap;
  std::vector<int> last_changing;
  bool single_changes = false;
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    if (!solve_states(p, f, active, state, s_scale, lambda, alpha)) {
      result.outcome = FrictionOutcome::modes_not_held;
      result.unheld_modes = free_modes(p, f, active, state);
      result.active = active, result.state = state;
      return result;
    }
    gap.assign(nb, 0.0);
    for (int i = 0; i < nb; ++i) gap[i] = -p.d[i];
    if (nb > 0) {
      int one = 1;
      double plus = 1.0, minus = -1.0;
      p.s.multiply_add(plus, lambda.data(), gap.data());
      if (p.k > 0) dgemv_("N", &nb, &p.k, &minus, p.g.data(), &nb, alpha.data(), &one, &plus, gap.data(), &one);
    }
    double lambda_ref = 0;
    for (double v : lambda) lambda_ref = std::max(lambda_ref, std::fabs(v));
    lambda_ref = std::max(lambda_ref, 1e-300);
    const double gap_ref = std::max({s_scale * lambda_ref, d_scale, 1e-300});
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
      result.lambda = lambda, result.alpha = alpha, result.gap = gap;
      result.active = active, result.state = next_state;
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
        result.active = active, result.state = state, result.lambda = lambda, result.alpha = alpha, result.gap = gap;
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
    if (single_changes) {
      const int row = changing.front();
      if (row < q) {
        active[row] = next_active[row];
        // a row leaving contact leaves its tangential row open; one entering sticks first
      } else {
        state[row - q] = next_state[row - q];
      }
      for (int j = 0; j < m; ++j)  // (a row coming into contact: its trial state)
        if (!f.live(j, active)) state[j] = FrictionState::open;
        else if (state[j] == FrictionState::open)
          state[j] = next_state[j] != FrictionState::open ? next_state[j] : FrictionState::stick;
      continue;
    }
    active = next_active, state = next_state;
    for (int j = 0; j < m; ++j)
      if (state[j] == FrictionState::open && f.live(j, active))
        state[j] = f.bound[j] == 0 ? FrictionState::slip_plus : FrictionState::stick;
  }
  result.outcome = FrictionOutcome::not_converged;
  result.active = active, result.state = state, result.lambda = lambda, result.alpha = alpha, result.gap = gap;
  result.changing_rows = last_changing;
  return result;
}

}  // namespace mc
