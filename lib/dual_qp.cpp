#include "dual_qp.hpp"
#include "error.hpp"
#include "lapack.hpp"
#include <algorithm>
#include <cmath>
#include <set>

namespace mc {

namespace {

// Least squares with nonnegative unknowns (Lawson and Hanson): min ||A x - b||, x >= 0, for A
// with few rows (k x q, column-major by columns of length k). Returns the residual norm.
double nonnegative_least_squares(int k, int q, const std::vector<double> &a, const std::vector<double> &b,
                                 std::vector<double> &x) {
  x.assign(q, 0.0);
  std::vector<char> passive(q, 0);
  auto residual = [&]() {
    std::vector<double> r(b);
    for (int j = 0; j < q; ++j)
      if (x[j] != 0)
        for (int i = 0; i < k; ++i) r[i] -= a[size_t(j) * k + i] * x[j];
    return r;
  };
  // Least squares on the passive columns by normal equations (at most k independent ones).
  auto solve_passive = [&](std::vector<double> &z) {
    std::vector<int> cols;
    for (int j = 0; j < q; ++j) if (passive[j]) cols.push_back(j);
    int p = int(cols.size());
    std::vector<double> ata(size_t(p) * p), atb(p);
    for (int u = 0; u < p; ++u) {
      for (int v = 0; v < p; ++v) {
        double s = 0;
        for (int i = 0; i < k; ++i) s += a[size_t(cols[u]) * k + i] * a[size_t(cols[v]) * k + i];
        ata[size_t(v) * p + u] = s;
      }
      double s = 0;
      for (int i = 0; i < k; ++i) s += a[size_t(cols[u]) * k + i] * b[i];
      atb[u] = s;
    }
    std::vector<int> ipiv(p);
    int one = 1, info = 0, lwork = std::max(1, 8 * p);
    std::vector<double> work(lwork);
    if (p > 0) dsysv_("U", &p, &one, ata.data(), &p, ipiv.data(), atb.data(), &p, work.data(), &lwork, &info);
    z.assign(q, 0.0);
    for (int u = 0; u < p; ++u) z[cols[u]] = info == 0 ? atb[u] : 0;
  };
  double bnorm = 0;
  for (double v : b) bnorm = std::max(bnorm, std::fabs(v));
  for (int outer = 0; outer < 3 * q + 10; ++outer) {
    std::vector<double> r = residual();
    int best = -1;
    double best_w = 1e-13 * std::max(bnorm, 1e-300);
    for (int j = 0; j < q; ++j) {
      if (passive[j]) continue;
      double w = 0, col_norm = 0;
      for (int i = 0; i < k; ++i) w += a[size_t(j) * k + i] * r[i], col_norm += a[size_t(j) * k + i] * a[size_t(j) * k + i];
      w /= std::sqrt(std::max(col_norm, 1e-300));
      if (w > best_w) best_w = w, best = j;
    }
    if (best < 0) break;
    passive[best] = 1;
    for (int inner = 0; inner < q + 10; ++inner) {
      std::vector<double> z;
      solve_passive(z);
      bool positive = true;
      for (int j = 0; j < q; ++j) if (passive[j] && z[j] <= 0) positive = false;
      if (positive) { x = z; break; }
      double step = 1;
      for (int j = 0; j < q; ++j)
        if (passive[j] && z[j] <= 0) step = std::min(step, x[j] / (x[j] - z[j]));
      for (int j = 0; j < q; ++j) {
        if (!passive[j]) continue;
        x[j] += step * (z[j] - x[j]);
        if (x[j] <= 1e-300) x[j] = 0, passive[j] = 0;
      }
    }
  }
  double norm = 0;
  for (double v : residual()) norm += v * v;
  return std::sqrt(norm);
}

// Solves the equality-constrained problem on the active set A:
//   S_AA l_A - G_A a = d_A,  G_A^T l_A = e.
// Returns false if the system is singular (G_A does not hold the floating modes).
bool solve_on_active_set(const DualQp &p, const std::vector<int> &act, double g_scale,
                         std::vector<double> &lambda, std::vector<double> &alpha) {
  const int na = int(act.size()), k = p.k, n = na + k;
  lambda.assign(p.q, 0.0);
  alpha.assign(k, 0.0);
  if (n == 0) return true;
  if (k > 0) {  // rank of G_A: its Gram matrix must be well conditioned
    if (na < k) return false;
    std::vector<double> gram(size_t(k) * k, 0.0), eig(k);
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b)
        for (int j : act) gram[size_t(b) * k + a] += p.g[size_t(a) * p.q + j] * p.g[size_t(b) * p.q + j];
    int lwork = 64, info = 0;
    std::vector<double> work(lwork);
    dsyev_("N", "U", &k, gram.data(), &k, eig.data(), work.data(), &lwork, &info);
    if (info != 0 || !(eig[0] > 1e-12 * eig[k - 1])) return false;
  }
  // Symmetric indefinite system, the G block scaled by g_scale so both blocks are of one size.
  std::vector<double> m(size_t(n) * n, 0.0), rhs(n);
  for (int b = 0; b < na; ++b)
    for (int a = 0; a < na; ++a) m[size_t(b) * n + a] = p.s[size_t(act[b]) * p.q + act[a]];
  for (int c = 0; c < k; ++c)
    for (int a = 0; a < na; ++a) {
      double v = -g_scale * p.g[size_t(c) * p.q + act[a]];
      m[size_t(na + c) * n + a] = v;
      m[size_t(a) * n + na + c] = v;
    }
  for (int a = 0; a < na; ++a) rhs[a] = p.d[act[a]];
  for (int c = 0; c < k; ++c) rhs[na + c] = -g_scale * p.e[c];
  std::vector<int> ipiv(n);
  int one = 1, info = 0, lwork = -1;
  double query;
  dsysv_("U", &n, &one, m.data(), &n, ipiv.data(), rhs.data(), &n, &query, &lwork, &info);
  lwork = std::max(1, int(query));
  std::vector<double> work(lwork);
  dsysv_("U", &n, &one, m.data(), &n, ipiv.data(), rhs.data(), &n, work.data(), &lwork, &info);
  if (info != 0) return false;
  for (int a = 0; a < na; ++a) lambda[act[a]] = rhs[a];
  for (int c = 0; c < k; ++c) alpha[c] = g_scale * rhs[na + c];
  return true;
}

// gap = S l - d - G a
std::vector<double> gap_of(const DualQp &p, const std::vector<double> &lambda, const std::vector<double> &alpha) {
  std::vector<double> gap(p.q);
  for (int i = 0; i < p.q; ++i) gap[i] = -p.d[i];
  int one = 1;
  double plus = 1.0, minus = -1.0;
  dgemv_("N", &p.q, &p.q, &plus, p.s.data(), &p.q, lambda.data(), &one, &plus, gap.data(), &one);
  if (p.k > 0) dgemv_("N", &p.q, &p.k, &minus, p.g.data(), &p.q, alpha.data(), &one, &plus, gap.data(), &one);
  return gap;
}

}  // namespace

DualQpResult solve_dual_qp(const DualQp &p, double tolerance, int max_iterations, const std::vector<char> &start) {
  DualQpResult result;
  const int q = p.q;
  double s_scale = 0, d_scale = 0, e_norm = 0;
  for (int i = 0; i < q; ++i) s_scale = std::max(s_scale, p.s[size_t(i) * q + i]), d_scale = std::max(d_scale, std::fabs(p.d[i]));
  for (double v : p.e) e_norm += v * v;
  e_norm = std::sqrt(e_norm);
  if (!(s_scale > 0)) s_scale = 1;

  // Floating bodies: contact forces l >= 0 must balance the loads, G^T l = e. If no l >= 0
  // can, the loads would move the body away: there is no solution.
  if (p.k > 0) {
    std::vector<double> gt(size_t(p.k) * q), x;  // G^T, column j = row j of G
    for (int j = 0; j < q; ++j)
      for (int c = 0; c < p.k; ++c) gt[size_t(j) * p.k + c] = p.g[size_t(c) * q + j];
    double residual = nonnegative_least_squares(p.k, q, gt, p.e, x);
    result.imbalance = e_norm > 0 ? residual / e_norm : residual;
    if (residual > 1e-8 * e_norm) {
      result.outcome = DualQpOutcome::loads_not_balanced;
      return result;
    }
  }

  std::vector<char> active(q, 0);
  if (int(start.size()) == q) active = start;
  else if (p.k > 0) std::fill(active.begin(), active.end(), 1);
  else for (int i = 0; i < q; ++i) active[i] = p.d[i] > 0;

  std::set<std::vector<char>> seen;
  std::vector<char> previous;
  bool single_pivoting = false;
  std::vector<double> lambda, alpha, gap;
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    std::vector<int> act;
    for (int i = 0; i < q; ++i) if (active[i]) act.push_back(i);
    if (!solve_on_active_set(p, act, s_scale, lambda, alpha)) {
      // The active set no longer holds a floating body: undo the last change and go on one
      // pivot at a time.
      if (previous.empty()) {
        result.outcome = DualQpOutcome::modes_not_held;
        return result;
      }
      active = previous;
      previous.clear();
      single_pivoting = true;
      continue;
    }
    gap = gap_of(p, lambda, alpha);
    double lambda_ref = 0;
    for (double v : lambda) lambda_ref = std::max(lambda_ref, std::fabs(v));
    lambda_ref = std::max(lambda_ref, 1e-300);
    double gap_ref = std::max({s_scale * lambda_ref, d_scale, 1e-300});
    const double eps = 1e-13;
    std::vector<int> violating;
    for (int i = 0; i < q; ++i)
      if ((active[i] && lambda[i] < -eps * lambda_ref) || (!active[i] && gap[i] < -eps * gap_ref)) violating.push_back(i);
    if (violating.empty()) {
      double worst = 0;
      for (int i = 0; i < q; ++i) {
        worst = std::max(worst, std::max(0.0, -lambda[i]) / lambda_ref);
        worst = std::max(worst, std::max(0.0, -gap[i]) / gap_ref);
        worst = std::max(worst, std::fabs(lambda[i] * gap[i]) / (lambda_ref * gap_ref));
      }
      result.violation = worst;
      result.lambda = lambda, result.alpha = alpha, result.gap = gap;
      result.outcome = worst <= tolerance ? DualQpOutcome::solved : DualQpOutcome::not_converged;
      return result;
    }
    previous = active;
    if (!single_pivoting) {
      for (int i : violating) active[i] = !active[i];
      if (!seen.insert(active).second) {  // a cycle: back to the last set, single pivots
        active = previous;
        single_pivoting = true;
        active[violating.front()] = !active[violating.front()];
      }
    } else {
      active[violating.front()] = !active[violating.front()];  // Murty's least index rule
    }
  }
  double worst = 0;
  for (int i = 0; i < q && !lambda.empty(); ++i) worst = std::max(worst, std::max(0.0, -lambda[i]));
  result.violation = worst;
  result.outcome = DualQpOutcome::not_converged;
  result.lambda = lambda, result.alpha = alpha, result.gap = gap;
  return result;
}

}  // namespace mc
