#include "linalg/friction_qp.hpp"
#include "linalg/dense_lu.hpp"
#include "linalg/sparse_lu.hpp"
#include "mortarcontact.h"
#include "support/lapack.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

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
    if (f.sticks(j, active, state)) index[q + j] = int(rows.size()), rows.push_back(q + j);
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
  DenseLu lu;
  if (!lu.factorize(n, std::move(a), 1e-14) || !lu.solve(rhs.data())) return false;
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
    if (f.sticks(int(j), active, state)) rows.push_back(q + int(j));
  std::vector<int> modes;
  if (k == 0) return modes;
  const RowsGram gram = rows_gram(p.g.data(), nb, k, rows, true);
  if (!gram.ok) return modes;
  const std::vector<double> &eig = gram.eigenvalues;
  std::vector<char> free(k, 0);
  for (int c = 0; c < k && eig[c] <= 1e-10 * std::max(eig[k - 1], 1e-300); ++c)
    for (int a = 0; a < k; ++a)
      if (std::fabs(gram.gram[size_t(c) * k + a]) >= 0.1) free[a] = 1;
  for (int a = 0; a < k; ++a)
    if (free[a]) modes.push_back(a);
  return modes;
}

}  // namespace

FrictionResult solve_friction_qp(const DualQp &p, const FrictionProblem &f, double tolerance, int max_iterations,
                                 const std::vector<char> &start_active, const std::vector<FrictionState> &start_state,
                                 const FrictionObserver &observe) {
  const int nb = p.q, q = f.normal_rows;
  FrictionScales scales;
  scales.compliance = 0;
  for (int i = 0; i < nb; ++i) scales.compliance = std::max(scales.compliance, p.s.diagonal(i));
  for (int i = 0; i < nb; ++i) scales.gap = std::max(scales.gap, std::fabs(p.d[i]));
  if (!(scales.compliance > 0)) scales.compliance = 1;
  std::vector<char> active(q, 0);
  if (int(start_active.size()) == q) active = start_active;
  else if (p.k > 0) std::fill(active.begin(), active.end(), 1);
  else for (int r = 0; r < q; ++r) active[r] = p.d[r] > 0;
  // One set of states: its linear system, then gap = S l - d - G a.
  auto solve = [&](const std::vector<char> &act, const std::vector<FrictionState> &state, FrictionStatesSolution &out) {
    if (!solve_states(p, f, act, state, scales.compliance, out.lambda, out.alpha)) return false;
    out.gap.assign(nb, 0.0);
    for (int i = 0; i < nb; ++i) out.gap[i] = -p.d[i];
    if (nb > 0) {
      int one = 1;
      double plus = 1.0, minus = -1.0;
      p.s.multiply_add(plus, out.lambda.data(), out.gap.data());
      if (p.k > 0) dgemv_("N", &nb, &p.k, &minus, p.g.data(), &nb, out.alpha.data(), &one, &plus, out.gap.data(), &one);
    }
    return true;
  };
  FrictionResult result = iterate_friction_states(f, solve, scales, tolerance, max_iterations, active, start_state, observe);
  if (result.outcome == FrictionOutcome::modes_not_held) result.unheld_modes = free_modes(p, f, result.active, result.state);
  return result;
}

}  // namespace mc
