// The sparse path's Krylov solves of one active set's KKT system through H_P (docs/theory.md
// §6b, item 3; §7c for friction's nonsymmetric systems): conjugate gradients on S_P, GMRES when
// slipping Coulomb rows make it nonsymmetric.
#include "linalg/sparse_contact_solve.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

// Conjugate gradients stop when every active row's residual is below this, relative to the
// size of the quantities it is computed from, or when it has stopped decreasing.
constexpr double kRowTolerance = 1e-14;
constexpr int kMaxCgSteps = 300;

}  // namespace

int SparseContactSolver::conjugate_gradients(const std::vector<double> &load, const std::vector<double> &target,
                                             std::vector<double> &x, std::vector<double> &lambda,
                                             SparseContactResult &result, double tolerance) const {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  std::vector<char> in(nrows);
  for (int r = 0; r < nrows; ++r) in[r] = !s.row_is_inequality[r] || factorized_[r];
  auto timed_solve = [&](std::vector<double> &v) { apply_inverse(v, result); };
  // x(lambda) = H_P^-1 (F + C_A^T (P t - lambda)).
  std::vector<double> y(nrows, 0.0);
  for (int r = 0; r < nrows; ++r)
    if (in[r]) y[r] = weight_[r] * target[r] - lambda[r];
    else lambda[r] = 0;
  apply_ct(y, x);
  for (int i = 0; i < s.n_unknowns; ++i) x[i] += load[i];
  timed_solve(x);
  // The residual b - S_P lambda is C_A x - t_A (minus the gaps of the active rows).
  std::vector<double> res(nrows, 0.0), row_scale(nrows, 0.0);
  double size = 0;
  for (int r = 0; r < nrows; ++r) {
    if (!in[r]) continue;
    double norm = 0, terms = std::fabs(target[r]);
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
      norm = std::max(norm, std::fabs(s.value[p])), terms += std::fabs(s.value[p] * x[s.column[p]]);
    row_scale[r] = norm > 0 ? 1 / norm : 0;
    size = std::max(size, terms * row_scale[r]);
    res[r] = row_times(r, x) - target[r];
  }
  auto worst = [&]() {
    double w = 0;
    for (int r = 0; r < nrows; ++r) w = std::max(w, std::fabs(res[r]) * row_scale[r]);
    return w;
  };
  const double goal = (tolerance > 0 ? tolerance : kRowTolerance) * std::max(size, 1e-300);
  double best = worst();
  int steps = 0, since_best = 0;
  if (best <= goal) return 0;
  std::vector<double> z(nrows), p(nrows), v, sp(nrows);
  double rz = 0;
  for (int r = 0; r < nrows; ++r) z[r] = weight_[r] * res[r], p[r] = z[r], rz += res[r] * z[r];
  while (steps < kMaxCgSteps) {
    ++steps;
    apply_ct(p, v);
    timed_solve(v);  // v = H_P^-1 C_A^T p
    double pq = 0;
    for (int r = 0; r < nrows; ++r) sp[r] = in[r] ? row_times(r, v) : 0, pq += p[r] * sp[r];
    if (!(pq > 0)) break;
    const double a = rz / pq;
    // res = b - S_P lambda: lambda += a p moves it by -a S_P p; x = x(lambda) by -a v.
    for (int r = 0; r < nrows; ++r) lambda[r] += a * p[r], res[r] -= a * sp[r];
    for (int i = 0; i < s.n_unknowns; ++i) x[i] -= a * v[i];
    const double w = worst();
    if (w <= goal) break;
    if (w < 0.5 * best) best = w, since_best = 0;
    else if (++since_best >= 10) break;  // stagnating at round-off: the refinement takes over
    double rz_new = 0;
    for (int r = 0; r < nrows; ++r) z[r] = weight_[r] * res[r], rz_new += res[r] * z[r];
    const double beta = rz_new / rz;
    rz = rz_new;
    for (int r = 0; r < nrows; ++r) p[r] = z[r] + beta * p[r];
  }
  result.cg_steps += steps;
  return steps;
}

// GMRES (Saad and Schultz 1986), restarted, left-preconditioned by P, on the rows of E:
// A lambda = b with A = C_E H_P^-1 D_E^T, whose residual b - A lambda is C_E x(lambda) - t_E for
// x(lambda) = H_P^-1 (F + C_E^T P t_E - D_E^T lambda). A coupled row's extra term
// coefficient C_other H_P^-1 C_r^T is of the size of the row's own 1/P (its normal direction is
// held by P), so P A is I plus a perturbation of the size of mu: a few steps, each one forward
// and one backward solve, as a CG step. Krylov vectors live in the rows' space only; x is formed
// once per cycle from lambda.
int SparseContactSolver::gmres(const std::vector<double> &load, const std::vector<double> &target, std::vector<double> &x,
                               std::vector<double> &lambda, SparseContactResult &result) const {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  std::vector<int> rows;
  for (int r = 0; r < nrows; ++r)
    if (!s.row_is_inequality[r] || factorized_[r]) rows.push_back(r);
    else lambda[r] = 0;
  const int n = int(rows.size());
  auto timed_solve = [&](std::vector<double> &v) { apply_inverse(v, result); };
  // x(lambda), and the rows' residuals C_E x - t_E.
  std::vector<double> y(nrows, 0.0), res(nrows, 0.0), row_scale(nrows, 0.0);
  auto form_x = [&]() {
    std::vector<double> pt(nrows, 0.0), dl;
    for (int r : rows) pt[r] = weight_[r] * target[r];
    apply_ct(pt, x);
    apply_dt(lambda, dl);
    for (int i = 0; i < s.n_unknowns; ++i) x[i] += load[i] - dl[i];
    timed_solve(x);
    for (int r : rows) res[r] = row_times(r, x) - target[r];
  };
  form_x();
  double size = 0;
  for (int r : rows) {
    double norm = 0, terms = std::fabs(target[r]);
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
      norm = std::max(norm, std::fabs(s.value[p])), terms += std::fabs(s.value[p] * x[s.column[p]]);
    row_scale[r] = norm > 0 ? 1 / norm : 0;
    size = std::max(size, terms * row_scale[r]);
  }
  auto worst = [&]() {
    double w = 0;
    for (int r : rows) w = std::max(w, std::fabs(res[r]) * row_scale[r]);
    return w;
  };
  const double goal = kRowTolerance * std::max(size, 1e-300);
  double best = worst();
  if (best <= goal || n == 0) return 0;
  constexpr int kRestart = 60, kMaxCycles = 8;
  int steps = 0, stalled = 0;
  std::vector<std::vector<double>> v;  // the Krylov basis (over the n rows of E)
  std::vector<double> h(size_t(kRestart + 1) * kRestart), cs(kRestart), sn(kRestart), g(kRestart + 1), w(n), full(nrows);
  auto hes = [&](int i, int j) -> double & { return h[size_t(j) * (kRestart + 1) + i]; };
  auto norm2 = [](const std::vector<double> &a) {
    double t = 0;
    for (double e : a) t += e * e;
    return std::sqrt(t);
  };
  for (int cycle = 0; cycle < kMaxCycles; ++cycle) {
    // r = b - A lambda is res; z = P r.
    v.assign(1, std::vector<double>(n));
    for (int i = 0; i < n; ++i) v[0][i] = weight_[rows[i]] * res[rows[i]];
    const double beta = norm2(v[0]);
    if (!(beta > 0)) break;
    for (double &e : v[0]) e /= beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    int k = 0;
    for (; k < kRestart; ++k) {
      ++steps;
      // w = P A v_k: v_k on the rows, D^T, H_P^-1, C_E, P.
      std::fill(full.begin(), full.end(), 0.0);
      for (int i = 0; i < n; ++i) full[rows[i]] = v[k][i];
      std::vector<double> u;
      apply_dt(full, u);
      timed_solve(u);
      for (int i = 0; i < n; ++i) w[i] = weight_[rows[i]] * row_times(rows[i], u);
      for (int j = 0; j <= k; ++j) {  // modified Gram-Schmidt
        double d = 0;
        for (int i = 0; i < n; ++i) d += w[i] * v[j][i];
        hes(j, k) = d;
        for (int i = 0; i < n; ++i) w[i] -= d * v[j][i];
      }
      const double w_norm = norm2(w);  // the next basis vector's length (rotated out of H below)
      hes(k + 1, k) = w_norm;
      for (int j = 0; j < k; ++j) {  // the earlier rotations, then this column's
        const double a = hes(j, k), b = hes(j + 1, k);
        hes(j, k) = cs[j] * a + sn[j] * b, hes(j + 1, k) = -sn[j] * a + cs[j] * b;
      }
      const double a = hes(k, k), b = hes(k + 1, k), rho = std::hypot(a, b);
      cs[k] = rho > 0 ? a / rho : 1, sn[k] = rho > 0 ? b / rho : 0;
      hes(k, k) = rho, hes(k + 1, k) = 0;
      g[k + 1] = -sn[k] * g[k], g[k] = cs[k] * g[k];
      const bool last = std::fabs(g[k + 1]) <= 1e-13 * beta || !(rho > 0) || !(w_norm > 0) || k + 1 == kRestart;
      if (!last) {
        v.emplace_back(n);
        for (int i = 0; i < n; ++i) v[k + 1][i] = w[i] / w_norm;
      } else {
        ++k;
        break;
      }
    }
    // lambda += V y, H y = g (upper triangular k x k).
    std::vector<double> coef(k, 0.0);
    for (int i = k - 1; i >= 0; --i) {
      double t = g[i];
      for (int j = i + 1; j < k; ++j) t -= hes(i, j) * coef[j];
      coef[i] = hes(i, i) != 0 ? t / hes(i, i) : 0;
    }
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < n; ++i) lambda[rows[i]] += coef[j] * v[j][i];
    form_x();
    const double now_worst = worst();
    if (now_worst <= goal) break;
    if (now_worst < 0.5 * best) best = now_worst, stalled = 0;
    else if (++stalled >= 2) break;  // at round-off: the refinement takes over
  }
  result.cg_steps += steps;
  return steps;
}


}  // namespace mc
