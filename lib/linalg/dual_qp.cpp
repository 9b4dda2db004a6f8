#include "linalg/dual_qp.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "linalg/sparse_lu.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
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

// solve_on_active_set's system when S is stored by blocks, eliminating l_A first with a
// sparse Cholesky factorization (CHOLMOD, supernodal: S's blocks are its supernodes) of
//   M = S_AA + shift I + rho G_A G_A^T   (rho > 0 only for shift = 0),
// which is SPD: S is positive semidefinite and definite on ker G_A^T (the augmentation, exact
// because G_A^T l_A = e, covers the rest; G G^T couples rows that share a floating body, so M
// keeps S's block pattern). With r = d_A + rho G_A e the system reads M l_A - G_A a = r,
// (G_A^T l_A + shift / g^2 a = e), so
//   (G_A^T M^-1 G_A + shift / g^2 I) a = e - G_A^T M^-1 r,   l_A = M^-1 (r + G_A a),
// a k x k dense system (k the floating modes). Returns false, having solved nothing, if M is
// not numerically positive definite (S_AA singular where G_A does not cover it: a fully
// prescribed body, see primal_active_set); the caller then factorizes the whole system by LU.
bool solve_on_active_set_by_cholesky(const DualQp &p, const std::vector<char> &in_a, double g_scale,
                                     std::vector<double> &lambda, std::vector<double> &alpha, double shift) {
  const int k = p.k;
  std::vector<int> order;  // unknown i: row order[i]
  SymmetricCsc m = p.s.principal_upper(in_a, order);
  const int na = m.n;
  double s_scale = 0, g_norm2 = 0;
  for (int c = 0; c < na; ++c) {
    s_scale = std::max(s_scale, m.values[m.colptr[c + 1] - 1]);  // (the diagonal ends each column)
    double norm2 = 0;
    for (int a = 0; a < k; ++a) norm2 += p.g[size_t(a) * p.q + order[c]] * p.g[size_t(a) * p.q + order[c]];
    g_norm2 = std::max(g_norm2, norm2);
  }
  // rho G G^T of S's size: the augmentation neither dominates nor drowns in round-off.
  const double rho = shift == 0 && k > 0 && g_norm2 > 0 ? std::max(s_scale, 1e-300) / g_norm2 : 0;
  // G_A's rows sparse: a row's nonzero modes are those of the (at most two) bodies it touches.
  std::vector<std::vector<std::pair<int, double>>> g_row(na);
  for (int i = 0; i < na; ++i)
    for (int a = 0; a < k; ++a)
      if (p.g[size_t(a) * p.q + order[i]] != 0) g_row[i].emplace_back(a, p.g[size_t(a) * p.q + order[i]]);
  for (int c = 0; c < na; ++c)
    for (int e = m.colptr[c]; e < m.colptr[c + 1]; ++e) {
      const int r = m.rows[e];
      if (r == c) m.values[e] += shift;
      if (rho == 0 || g_row[r].empty() || g_row[c].empty()) continue;
      double dot = 0;
      for (const auto &x : g_row[r])
        for (const auto &y : g_row[c])
          if (x.first == y.first) dot += x.second * y.second;
      m.values[e] += rho * dot;
    }
  SparseCholesky cholesky;
  try {
    cholesky.analyze(m, {}, MC_ORDERING_AMD);
    cholesky.factorize(m);
  } catch (const Error &error) {
    if (error.status() != MC_ERROR_SINGULAR) throw;
    return false;
  }
  // X = M^-1 [r, G_A]: k + 1 right-hand sides.
  std::vector<double> x(size_t(na) * (k + 1));
  for (int i = 0; i < na; ++i) {
    double r = p.d[order[i]];
    for (const auto &y : g_row[i]) r += rho * y.second * p.e[y.first];
    x[i] = r;
    for (const auto &y : g_row[i]) x[size_t(1 + y.first) * na + i] = y.second;
  }
  cholesky.solve(x.data(), k + 1);
  std::vector<double> a(k);
  if (k > 0) {
    // The Schur complement H = G_A^T M^-1 G_A + shift / g^2 I and its right-hand side.
    std::vector<double> h(size_t(k) * k, 0.0);
    for (int b = 0; b < k; ++b) a[b] = p.e[b];
    for (int i = 0; i < na; ++i)
      for (const auto &y : g_row[i]) {
        a[y.first] -= y.second * x[i];
        for (int b = 0; b < k; ++b) h[size_t(b) * k + y.first] += y.second * x[size_t(1 + b) * na + i];
      }
    for (int b = 0; b < k; ++b) h[size_t(b) * k + b] += shift / (g_scale * g_scale);
    std::vector<int> ipiv(k);
    int one = 1, info = 0, lwork = std::max(1, 64 * k);
    std::vector<double> work(lwork);
    dsysv_("U", &k, &one, h.data(), &k, ipiv.data(), a.data(), &k, work.data(), &lwork, &info);
    if (info != 0) return false;
  }
  for (int i = 0; i < na; ++i) {
    double l = x[i];
    for (int b = 0; b < k; ++b) l += x[size_t(1 + b) * na + i] * a[b];
    lambda[order[i]] = l;
  }
  for (int b = 0; b < k; ++b) alpha[b] = a[b];
  return true;
}

// solve_on_active_set's system when S is stored by blocks and M above is not positive
// definite: the same matrix as the dense path's,
//   [S_AA + shift I, -g G_A; -g G_A^T, -shift I] [l_A; a / g] = [d_A; -g e],
// assembled sparse (S_AA from the stored blocks only, G_A's nonzeros: a row's rigid modes are
// those of the bodies it touches) and factorized by sparse LU with pivoting, which like dsysv
// needs no definite S_AA. Returns false if a pivot is zero.
bool solve_on_active_set_by_blocks(const DualQp &p, const std::vector<int> &act, double g_scale,
                                   std::vector<double> &lambda, std::vector<double> &alpha, double shift) {
  const int na = int(act.size()), k = p.k, n = na + k;
  std::vector<int> position(p.q, -1);
  std::vector<char> in_a(p.q, 0);
  for (int a = 0; a < na; ++a) position[act[a]] = a, in_a[act[a]] = 1;
  if (solve_on_active_set_by_cholesky(p, in_a, g_scale, lambda, alpha, shift)) return true;
  std::vector<long> row, column;
  std::vector<double> value, rhs(n);
  auto add = [&](int r, int c, double v) { row.push_back(r), column.push_back(c), value.push_back(v); };
  p.s.for_each_entry(in_a, in_a, [&](int r, int c, double v) { add(position[r], position[c], v); });
  for (int a = 0; a < na; ++a)
    if (shift != 0) add(a, a, shift);
  for (int c = 0; c < k; ++c) {
    if (shift != 0) add(na + c, na + c, -shift);
    for (int a = 0; a < na; ++a) {
      const double v = -g_scale * p.g[size_t(c) * p.q + act[a]];
      if (v != 0) add(a, na + c, v), add(na + c, a, v);
    }
  }
  for (int a = 0; a < na; ++a) rhs[a] = p.d[act[a]];
  for (int c = 0; c < k; ++c) rhs[na + c] = -g_scale * p.e[c];
  SparseLu lu;
  if (!lu.factorize(n, row, column, value)) return false;
  std::vector<double> x(n);
  lu.solve(rhs.data(), x.data());
  for (int a = 0; a < na; ++a) lambda[act[a]] = x[a];
  for (int c = 0; c < k; ++c) alpha[c] = g_scale * x[na + c];
  return true;
}

// Solves the equality-constrained problem on the active set A:
//   S_AA l_A - G_A a = d_A,  G_A^T l_A = e.
// Returns false if the system is singular (G_A does not hold the floating modes).
// shift (>= 0) is added to the diagonal of S_AA (see primal_active_set). With shift > 0 a G_A
// of deficient rank is accepted: the primal method only asks this of sets on which G_A^T l = e
// is consistent (its current feasible iterate lives there); the alpha block then gets -shift
// on its diagonal, which picks the alpha of least norm (the rows outside A decide the rest of
// alpha once they enter).
bool solve_on_active_set(const DualQp &p, const std::vector<int> &act, double g_scale,
                         std::vector<double> &lambda, std::vector<double> &alpha, double shift = 0) {
  const int na = int(act.size()), k = p.k, n = na + k;
  lambda.assign(p.q, 0.0);
  alpha.assign(k, 0.0);
  if (n == 0) return true;
  if (k > 0 && shift == 0 && !rows_hold_modes(p.g.data(), p.q, k, act)) return false;
  if (!p.s.dense()) return solve_on_active_set_by_blocks(p, act, g_scale, lambda, alpha, shift);
  // Symmetric indefinite system, the G block scaled by g_scale so both blocks are of one size.
  const double *s = p.s.dense_values();
  std::vector<double> m(size_t(n) * n, 0.0), rhs(n);
  for (int b = 0; b < na; ++b)
    for (int a = 0; a < na; ++a) m[size_t(b) * n + a] = s[size_t(act[b]) * p.q + act[a]];
  for (int a = 0; a < na; ++a) m[size_t(a) * n + a] += shift;
  for (int c = 0; c < k; ++c) m[size_t(na + c) * n + na + c] -= shift;
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
  if (p.q == 0) return gap;  // (BLAS refuses a leading dimension of 0: "DGEMV parameter 6", seen by the fuzzer)
  p.s.multiply_add(plus, lambda.data(), gap.data());
  if (p.k > 0) dgemv_("N", &p.q, &p.k, &minus, p.g.data(), &p.q, alpha.data(), &one, &plus, gap.data(), &one);
  return gap;
}

// Largest relative violation of l >= 0, gap >= 0 and l . gap = 0 (MC_INFO_COMPLEMENTARITY).
double complementarity_residual(const std::vector<double> &lambda, const std::vector<double> &gap,
                                double lambda_ref, double gap_ref) {
  double worst = 0;
  for (size_t i = 0; i < lambda.size(); ++i) {
    worst = std::max(worst, std::max(0.0, -lambda[i]) / lambda_ref);
    worst = std::max(worst, std::max(0.0, -gap[i]) / gap_ref);
    worst = std::max(worst, std::fabs(lambda[i] * gap[i]) / (lambda_ref * gap_ref));
  }
  return worst;
}

// Primal active-set method on the same problem (Lawson and Hanson's NNLS scheme carried over to
// the QP): the fallback when the primal-dual iteration cycles, which it does when S is far from
// an M-matrix. The typical case is an ill-conditioned S: a stiff non-mortar body whose trace is
// finer than a soft mortar side has multiplier modes that only its own small compliance
// controls (a rigid one, fully prescribed, none: S is then singular). Every iterate is feasible
// (l >= 0, G^T l = e, from the feasible start `lambda`) and the objective decreases, so it does
// not cycle. The free set W (warm-started with `free_set`) grows by the row of most negative
// gap; a step towards the minimiser on W stops where a multiplier reaches 0, which leaves W.
// S_WW gets a diagonal shift of 1e-14 of S's largest entry, so that the equality problems
// stay solvable when S is singular; the gaps it leaves (1e-14 relative) are far below any
// tolerance. Counts one iteration per equality problem solved. Returns false at the iteration
// limit or if an equality problem fails.
bool primal_active_set(const DualQp &p, double s_scale, double d_scale, std::vector<char> free_set, int max_iterations,
                       const DualQpObserver &observe, int &iterations, std::vector<double> &lambda,
                       std::vector<double> &alpha, std::vector<double> &gap) {
  const int q = p.q;
  const double shift = 1e-14 * s_scale, eps = 1e-13;
  std::vector<char> &w = free_set;
  for (int i = 0; i < q; ++i) {
    if (lambda[i] > 0) w[i] = 1;
    else lambda[i] = 0;
  }
  // Rows that round-off sends straight back out after entering: not tried again (the final
  // complementarity check judges what they leave).
  std::vector<char> refused(q, 0);
  int entered = -1;
  std::vector<double> z, za;
  for (;;) {
    for (;;) {  // minimise on W, stepping back to stay feasible
      if (iterations >= max_iterations) return false;
      ++iterations;
      std::vector<int> act;
      for (int i = 0; i < q; ++i) if (w[i]) act.push_back(i);
      if (!solve_on_active_set(p, act, s_scale, z, za, shift)) return false;
      double step = 1, lambda_max = 0;
      int blocking = -1;
      for (int i : act) {
        lambda_max = std::max(lambda_max, lambda[i]);
        if (z[i] <= 0 && lambda[i] / (lambda[i] - z[i]) < step) step = lambda[i] / (lambda[i] - z[i]), blocking = i;
      }
      if (observe) observe({iterations, int(act.size()), blocking >= 0 ? 1 : 0, 0.0, true});
      if (blocking < 0) {
        lambda = z, alpha = za;
        break;
      }
      if (blocking == entered && step == 0) refused[blocking] = 1;
      entered = -1;
      for (int i : act) {
        lambda[i] += step * (z[i] - lambda[i]);
        // leaving: the blocking row and any other that the step took to 0 on its way down (a
        // zero multiplier headed up, z > 0, stays: a warm start begins with all of W at 0)
        if (i == blocking || (lambda[i] <= 1e-15 * lambda_max && z[i] <= 0)) lambda[i] = 0, w[i] = 0;
      }
    }
    gap = gap_of(p, lambda, alpha);
    double lambda_ref = 0;
    for (double v : lambda) lambda_ref = std::max(lambda_ref, std::fabs(v));
    const double gap_ref = std::max({s_scale * lambda_ref, d_scale, 1e-300});
    int best = -1;
    double most = -eps * gap_ref;
    for (int i = 0; i < q; ++i)
      if (!w[i] && !refused[i] && gap[i] < most) most = gap[i], best = i;
    if (best < 0) return true;
    w[best] = 1, entered = best;
  }
}

}  // namespace

RowsGram rows_gram(const double *g, int ld, int k, const std::vector<int> &rows, bool vectors) {
  RowsGram r;
  r.gram.assign(size_t(k) * k, 0.0), r.eigenvalues.assign(k, 0.0);
  if (k == 0) return r.ok = true, r;
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b)
      for (int j : rows) r.gram[size_t(b) * k + a] += g[size_t(a) * ld + j] * g[size_t(b) * ld + j];
  // k counts the rigid modes of every floating body (up to 3 each): dsyev needs 3k - 1
  int n = k, lwork = std::max(64, 3 * k), info = 0;
  std::vector<double> work(lwork);
  dsyev_(vectors ? "V" : "N", "U", &n, r.gram.data(), &n, r.eigenvalues.data(), work.data(), &lwork, &info);
  r.ok = info == 0;
  return r;
}

bool rows_hold_modes(const double *g, int ld, int k, const std::vector<int> &rows) {
  if (k == 0) return true;
  if (int(rows.size()) < k) return false;
  const RowsGram r = rows_gram(g, ld, k, rows, false);
  return r.ok && r.eigenvalues[0] > 1e-12 * r.eigenvalues[k - 1];
}

void release_slack_rows(const std::vector<double> &lambda, double lambda_ref, std::vector<char> &active) {
  for (size_t r = 0; r < active.size(); ++r)
    if (active[r] && lambda[r] < kSlackForce * lambda_ref) active[r] = 0;
}

bool crawling(const std::vector<int> &sizes, size_t flips, int window) {
  if (flips > kCrawlFlips || window <= 0 || int(sizes.size()) <= window) return false;
  const int change = sizes.back() - sizes[sizes.size() - 1 - size_t(window)];
  return std::abs(change) >= window;
}

double load_imbalance(const DualQp &p) {
  if (p.k == 0) return 0;
  double e_norm = 0;
  for (double v : p.e) e_norm += v * v;
  e_norm = std::sqrt(e_norm);
  std::vector<double> gt(size_t(p.k) * p.q), x;  // G^T, column j = row j of G
  for (int j = 0; j < p.q; ++j)
    for (int c = 0; c < p.k; ++c) gt[size_t(j) * p.k + c] = p.g[size_t(c) * p.q + j];
  const double residual = nonnegative_least_squares(p.k, p.q, gt, p.e, x);
  return e_norm > 0 ? residual / e_norm : residual;
}

bool solve_correction(const DualQp &p, const std::vector<char> &active, std::vector<double> &dl,
                      std::vector<double> &da) {
  double s_scale = 0;
  for (int i = 0; i < p.q; ++i) s_scale = std::max(s_scale, p.s.diagonal(i));
  if (!(s_scale > 0)) s_scale = 1;
  std::vector<int> act;
  for (int i = 0; i < p.q; ++i)
    if (active[i]) act.push_back(i);
  return solve_on_active_set(p, act, s_scale, dl, da);
}

DualQpResult solve_dual_qp(const DualQp &p, double tolerance, int max_iterations, const std::vector<char> &start,
                           const DualQpObserver &observe) {
  DualQpResult result;
  const int q = p.q;
  double s_scale = 0, d_scale = 0, e_norm = 0;
  for (int i = 0; i < q; ++i) s_scale = std::max(s_scale, p.s.diagonal(i)), d_scale = std::max(d_scale, std::fabs(p.d[i]));
  for (double v : p.e) e_norm += v * v;
  e_norm = std::sqrt(e_norm);
  if (!(s_scale > 0)) s_scale = 1;

  // Floating bodies: contact forces l >= 0 must balance the loads, G^T l = e. If no l >= 0
  // can, the loads would move the body away: there is no solution. Otherwise those forces are a
  // feasible start for the primal active-set fallback.
  std::vector<double> balanced(q, 0.0);
  if (p.k > 0) {
    std::vector<double> gt(size_t(p.k) * q), x;  // G^T, column j = row j of G
    for (int j = 0; j < q; ++j)
      for (int c = 0; c < p.k; ++c) gt[size_t(j) * p.k + c] = p.g[size_t(c) * q + j];
    double residual = nonnegative_least_squares(p.k, q, gt, p.e, x);
    balanced = x;
    result.imbalance = e_norm > 0 ? residual / e_norm : residual;
    if (residual > 1e-8 * e_norm) {
      result.outcome = DualQpOutcome::loads_not_balanced;
      return result;
    }
  }

  std::vector<char> active(q, 0);
  const bool warm_start = int(start.size()) == q;
  if (warm_start) active = start;
  else if (p.k > 0) std::fill(active.begin(), active.end(), 1);
  else for (int i = 0; i < q; ++i) active[i] = p.d[i] > 0;

  std::set<std::vector<char>> seen;
  std::vector<char> previous;
  // Progress of the primal-dual iteration: the fewest violating rows so far, and when.
  size_t fewest_violating = size_t(q) + 1;
  int fewest_at = 0;
  const int patience = 20;
  std::vector<int> sizes;  // the active rows of each iteration
  std::vector<double> lambda, alpha, gap;
  auto finish = [&](double lambda_ref, double gap_ref) {
    result.violation = complementarity_residual(lambda, gap, lambda_ref, gap_ref);
    result.lambda = lambda, result.alpha = alpha, result.gap = gap;
    result.outcome = result.violation <= tolerance ? DualQpOutcome::solved : DualQpOutcome::not_converged;
    return result;
  };
  // When the primal-dual iteration cycles, or its last change leaves a floating body unheld:
  // the primal active-set method, warm-started with the last set that worked.
  auto fall_back = [&](const std::vector<char> &warm) {
    lambda = balanced;
    int iterations = result.iterations;
    bool converged = primal_active_set(p, s_scale, d_scale, warm, max_iterations, observe, iterations, lambda, alpha, gap);
    result.iterations = iterations;
    if (alpha.size() != size_t(p.k) || gap.size() != size_t(q)) {  // stopped before a first minimiser
      alpha.assign(p.k, 0.0);
      gap = gap_of(p, lambda, alpha);
    }
    double lambda_ref = 0;
    for (double v : lambda) lambda_ref = std::max(lambda_ref, std::fabs(v));
    lambda_ref = std::max(lambda_ref, 1e-300);
    DualQpResult r = finish(lambda_ref, std::max({s_scale * lambda_ref, d_scale, 1e-300}));
    if (!converged) r.outcome = DualQpOutcome::not_converged;
    return r;
  };
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    std::vector<int> act;
    for (int i = 0; i < q; ++i) if (active[i]) act.push_back(i);
    if (!solve_on_active_set(p, act, s_scale, lambda, alpha)) {
      if (observe) observe({it, int(act.size()), 0, 0.0, false});
      if (previous.empty()) {
        result.outcome = DualQpOutcome::modes_not_held;
        return result;
      }
      return fall_back(previous);
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
    if (observe)
      observe({it, int(act.size()), int(violating.size()), complementarity_residual(lambda, gap, lambda_ref, gap_ref),
               true});
    if (violating.empty()) return finish(lambda_ref, gap_ref);
    // Without a new fewest count of violating rows for `patience` iterations the iteration is
    // wandering (it is only guaranteed to converge for M-matrices): fall back. Well-behaved
    // scenes converge within about 15 iterations (Hertz, 778k DOFs: 13); the wandering ones
    // measured (a stiff non-mortar disc finer than a soft block, E1/E2 = 1e6) went on for 200
    // iterations without repeating a set.
    if (violating.size() < fewest_violating) fewest_violating = violating.size(), fewest_at = it;
    sizes.push_back(int(act.size()));
    if (crawling(sizes, violating.size(), patience)) fewest_at = it;  // progress (dual_qp.hpp)
    if (it - fewest_at >= patience) return fall_back(active);
    previous = active;
    for (int i : violating) active[i] = !active[i];
    // Negligible forces released with the pulling ones (release_slack_rows, dual_qp.hpp).
    if (it == (warm_start ? 2 : 1)) release_slack_rows(lambda, lambda_ref, active);
    if (!seen.insert(active).second) return fall_back(previous);  // a cycle
  }
  double lambda_ref = 0;
  for (double v : lambda) lambda_ref = std::max(lambda_ref, std::fabs(v));
  lambda_ref = std::max(lambda_ref, 1e-300);
  DualQpResult r = finish(lambda_ref, std::max({s_scale * lambda_ref, d_scale, 1e-300}));
  r.outcome = DualQpOutcome::not_converged;
  return r;
}

}  // namespace mc
