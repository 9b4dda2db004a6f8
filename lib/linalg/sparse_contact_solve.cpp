#include "linalg/sparse_contact_solve.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>
#include <set>

namespace mc {

namespace {


// P's weights: row r gets kAugmentation / sigma_r, sigma_r = sum_i c_ri^2 / H_ii (a Jacobi
// estimate of the row's local compliance c_r H^-1 c_r^T). Then P S_P's local eigenvalues are
// about kAugmentation / (1 + kAugmentation), and CG converges in a few steps; larger values
// cost conditioning of H_P, which the refinement below must then win back (chosen by
// measurement, docs/notes/interface-solver.md).
constexpr double kAugmentation = 1e3;
// Conjugate gradients stop when every active row's residual is below this, relative to the
// size of the quantities it is computed from, or when it has stopped decreasing.
constexpr double kRowTolerance = 1e-14;
constexpr int kMaxCgSteps = 300;
constexpr int kMaxRefinements = 6;

}  // namespace

void SparseContactSolver::analyze(const SparseContactStructure &s, int ordering) {
  const double start = now();
  structure_ = &s;
  factorized_.clear();
  const int n = s.n_unknowns, nrows = s.rows();
  // 1. The pattern of H + C^T C (upper triangle by columns), column by column: H's column j and,
  //    for each row r that names j, r's columns up to j; a marker keeps each row index once.
  //    Two passes (count, then fill), so that no list with duplicates is ever held.
  std::vector<int> ct_start(n + 1, 0), ct_row;  // C^T: the rows naming each column
  for (int r = 0; r < nrows; ++r)
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) ct_start[s.column[p] + 1]++;
  for (int j = 0; j < n; ++j) ct_start[j + 1] += ct_start[j];
  ct_row.resize(size_t(ct_start[n]));
  {
    std::vector<int> next(ct_start.begin(), ct_start.end() - 1);
    for (int r = 0; r < nrows; ++r)
      for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) ct_row[size_t(next[s.column[p]]++)] = r;
  }
  std::vector<int> block_of(n, -1);
  for (size_t b = 0; b < s.blocks.size(); ++b)
    for (int c = 0; c < s.blocks[b]->n; ++c) block_of[s.block_offset[b] + c] = int(b);
  std::vector<int> mark(n, -1);
  matrix_ = SymmetricCsc{};
  matrix_.n = n;
  matrix_.colptr.assign(n + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::fill(mark.begin(), mark.end(), -1);
    for (int j = 0; j < n; ++j) {
      int top = matrix_.colptr[j];
      auto keep = [&](int i) {
        if (mark[i] == j) return;
        mark[i] = j;
        if (pass == 1) matrix_.rows[size_t(top)] = i;
        ++top;
      };
      if (block_of[j] >= 0) {
        const SymmetricCsc &k = *s.blocks[size_t(block_of[j])];
        const int o = s.block_offset[size_t(block_of[j])], c = j - o;
        for (int p = k.colptr[c]; p < k.colptr[c + 1]; ++p) keep(o + k.rows[p]);
      }
      keep(j);  // the diagonal, also for w and alpha
      for (int q = ct_start[j]; q < ct_start[j + 1]; ++q) {
        const int r = ct_row[size_t(q)];
        for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
          if (s.column[p] <= j) keep(s.column[p]);
      }
      if (pass == 0) matrix_.colptr[j + 1] = top - matrix_.colptr[j];
      else std::sort(matrix_.rows.begin() + matrix_.colptr[j], matrix_.rows.begin() + top);
    }
    if (pass == 0) {
      for (int j = 0; j < n; ++j) matrix_.colptr[j + 1] += matrix_.colptr[j];
      matrix_.rows.resize(size_t(matrix_.colptr[n]));
    }
  }
  std::vector<int>().swap(ct_row), std::vector<int>().swap(mark), std::vector<int>().swap(block_of);
  matrix_.values.assign(matrix_.rows.size(), 0.0);
  // 2. H's diagonal, for P's weights.
  std::vector<double> diagonal(n, 0.0);
  for (size_t b = 0; b < s.blocks.size(); ++b) {
    const SymmetricCsc &k = *s.blocks[b];
    for (int c = 0; c < k.n; ++c)
      for (int p = k.colptr[c]; p < k.colptr[c + 1]; ++p)
        if (k.rows[p] == c) diagonal[s.block_offset[b] + c] = k.values[p];
  }
  // 3. P's weights.
  double mean_diagonal = 0;
  int counted = 0;
  for (double d : diagonal)
    if (d > 0) mean_diagonal += d, ++counted;
  mean_diagonal = counted ? mean_diagonal / counted : 1;
  weight_.assign(nrows, 0.0);
  for (int r = 0; r < nrows; ++r) {
    double sigma = 0, norm2 = 0;
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) {
      const double c = s.value[p];
      norm2 += c * c;
      if (diagonal[s.column[p]] > 0) sigma += c * c / diagonal[s.column[p]];
    }
    // A row whose terms on the bodies' unknowns are round-off beside its others (a tangential
    // row at a node whose tangential freedom is a floating body's pin: only its mortar value
    // and rigid modes are left) is weighed by its size: sigma would give it a weight of 1e35.
    if (sigma > 1e-8 * norm2 / mean_diagonal) weight_[r] = kAugmentation / sigma;
    else if (norm2 > 0) weight_[r] = kAugmentation * mean_diagonal / norm2;
    else weight_[r] = 1;  // an empty row: never coupled, never active
  }
  // 4. Ordering and symbolic factorization.
  cholesky_.analyze(matrix_, {}, ordering);
  flops_ = cholesky_.analysis_flops();
  t_analysis_ = now() - start;
}

// Entry (i, j) of the pattern (i <= j).
int SparseContactSolver::position(int i, int j) const {
  if (i > j) std::swap(i, j);
  auto first = matrix_.rows.begin() + matrix_.colptr[j], last = matrix_.rows.begin() + matrix_.colptr[j + 1];
  return int(std::lower_bound(first, last, i) - matrix_.rows.begin());
}

// H_P's values for an active set: H's blocks (each block column merged into the pattern's
// column, both sorted), then each active row's c_r^T P_r c_r. Nothing of H is kept beside the
// pattern: its values are read from the bodies' matrices each time (memory: docs/benchmarks.md).
void SparseContactSolver::factorize(const std::vector<char> &active, SparseContactResult &result) {
  if (update_from_factor(active, result)) return;
  const double start = now();
  const SparseContactStructure &s = *structure_;
  std::fill(matrix_.values.begin(), matrix_.values.end(), 0.0);
  for (size_t b = 0; b < s.blocks.size(); ++b) {
    const SymmetricCsc &k = *s.blocks[b];
    const int o = s.block_offset[b];
    for (int c = 0; c < k.n; ++c) {
      int at = matrix_.colptr[o + c];
      for (int p = k.colptr[c]; p < k.colptr[c + 1]; ++p) {
        while (matrix_.rows[size_t(at)] != o + k.rows[p]) ++at;
        matrix_.values[size_t(at)] += k.values[p];
      }
    }
  }
  for (int r = 0; r < s.rows(); ++r) {
    if (s.row_is_inequality[r] && !active[r]) continue;
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
      for (int q = s.row_start[r]; q < s.row_start[r + 1]; ++q)
        if (s.column[q] >= s.column[p])
          matrix_.values[size_t(position(s.column[p], s.column[q]))] += weight_[r] * s.value[p] * s.value[q];
  }
  factorized_.clear(), factor_set_.clear(), update_ = {};
  cholesky_.factorize(matrix_);
  factorized_ = factor_set_ = active;
  result.factorizations++;
  result.t_factor += now() - start;
}

// When the rows to hold differ from the factor's by a few (an active-set iteration or a load step
// that moves the ends of the contact zone), H_P = H_0 + sum_r sign_r P_r c_r^T c_r is a rank-k
// change of the factorized H_0: its inverse is H_0^-1 - Z M^-1 Z^T with Z = H_0^-1 C_k^T and
// M = diag(1 / (sign_r P_r)) + C_k Z (Sherman-Morrison-Woodbury), k solves and a k x k LU
// instead of a factorization. Taken when the k solves cost under half a factorization and Z
// takes under half the factor's memory. The answer stays exact: the refinement works on the KKT
// system's own residuals (solve_on_active_set), whatever H_P^-1 was applied. Removing a row
// cancels P_r against c_r H_0^-1 c_r^T (about 1/P_r, kAugmentation larger than their
// difference): the update loses some 3 digits, which the refinement wins back.
bool SparseContactSolver::update_from_factor(const std::vector<char> &active, SparseContactResult &result) {
  const SparseContactStructure &s = *structure_;
  if (factor_set_.size() != active.size()) return false;
  std::vector<int> rows;
  for (int r = 0; r < s.rows(); ++r)
    if (s.row_is_inequality[r] && active[r] != factor_set_[r]) rows.push_back(r);
  const int n = s.n_unknowns, k = int(rows.size());
  const double solve_flops = 4.0 * double(cholesky_.factor_nnz());
  if (k == 0) {
    update_ = {}, factorized_ = active;
    return true;
  }
  if (double(k) * solve_flops > 0.5 * flops_ || double(k) * n > 0.5 * double(cholesky_.factor_nnz())) return false;
  const double start = now();
  LowRankUpdate u;
  u.rows = rows;
  u.z.assign(size_t(n) * k, 0.0);
  for (int c = 0; c < k; ++c)
    for (int p = s.row_start[rows[c]]; p < s.row_start[rows[c] + 1]; ++p) u.z[size_t(c) * n + s.column[p]] = s.value[p];
  cholesky_.solve(u.z.data(), k);
  u.m.assign(size_t(k) * k, 0.0);
  double norm = 0;
  for (int c = 0; c < k; ++c) {
    for (int i = 0; i < k; ++i) {
      double v = 0;
      for (int p = s.row_start[rows[i]]; p < s.row_start[rows[i] + 1]; ++p) v += s.value[p] * u.z[size_t(c) * n + s.column[p]];
      u.m[size_t(c) * k + i] = v;
    }
    const double sign = active[rows[c]] ? 1.0 : -1.0;
    u.m[size_t(c) * k + c] += 1 / (sign * weight_[rows[c]]);
  }
  for (int c = 0; c < k; ++c) {
    double sum = 0;
    for (int i = 0; i < k; ++i) sum += std::fabs(u.m[size_t(c) * k + i]);
    norm = std::max(norm, sum);
  }
  u.pivots.resize(k);
  int info = 0, kk = k;
  dgetrf_(&kk, &kk, u.m.data(), &kk, u.pivots.data(), &info);
  double rcond = 0;
  if (info == 0) {
    std::vector<double> work(4 * size_t(k));
    std::vector<int> iwork(k);
    dgecon_("1", &kk, u.m.data(), &kk, &norm, &rcond, work.data(), iwork.data(), &info);
  }
  result.t_factor += now() - start;
  if (info != 0 || !(rcond > 1e-12)) return false;  // (a factorization then says what is singular)
  update_ = std::move(u);
  factorized_ = active;
  result.updates++;
  return true;
}

void SparseContactSolver::apply_inverse(std::vector<double> &v, SparseContactResult &result) const {
  const double start = now();
  cholesky_.solve(v.data());
  const int k = int(update_.rows.size()), n = structure_->n_unknowns;
  if (k > 0) {
    std::vector<double> t(k);
    for (int i = 0; i < k; ++i) t[i] = row_times(update_.rows[i], v);
    int one = 1, info = 0, kk = k;
    dgetrs_("N", &kk, &one, update_.m.data(), &kk, update_.pivots.data(), t.data(), &kk, &info);
    int nn = n;
    double minus = -1.0, plus = 1.0;
    dgemv_("N", &nn, &kk, &minus, update_.z.data(), &nn, t.data(), &one, &plus, v.data(), &one);
  }
  result.t_solve += now() - start;
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

int SparseContactSolver::conjugate_gradients(const std::vector<double> &load, const std::vector<double> &target,
                                             std::vector<double> &x, std::vector<double> &lambda,
                                             SparseContactResult &result) const {
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
  const double goal = kRowTolerance * std::max(size, 1e-300);
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

void SparseContactSolver::solve_on_active_set(const std::vector<double> &load, const std::vector<double> &target,
                                              std::vector<double> &x, std::vector<double> &lambda,
                                              SparseContactResult &result) const {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  auto krylov = [&](const std::vector<double> &f, const std::vector<double> &t, std::vector<double> &xx,
                    std::vector<double> &ll) {
    if (coupling_.empty()) conjugate_gradients(f, t, xx, ll, result);
    else gmres(f, t, xx, ll, result);
  };
  krylov(load, target, x, lambda);
  // Iterative refinement on the KKT system's own residuals (F - H x - C_A^T lambda, t_A - C_A x):
  // CG's recursive residual drifts from the true one by round-off of H_P's conditioning.
  // The residuals are summed in long double (x87 extended precision, 64-bit mantissa, where the
  // platform has it): a residual summed in double carries round-off of eps |H| |x|, which bounds
  // how far refinement can take the answer; summed more precisely, refinement reaches the exact
  // solution of the stored system to about eps times its condition less (classical mixed-
  // precision refinement; docs/notes/interface-solver.md).
  auto residuals = [&](std::vector<double> &rf, std::vector<double> &rt) {
    std::vector<long double> sum(s.n_unknowns, 0.0L), size(s.n_unknowns, 0.0L);
    for (int i = 0; i < s.n_unknowns; ++i) sum[i] = load[i], size[i] = std::fabs(load[i]);
    for (int r = 0; r < nrows; ++r)
      if (!s.row_is_inequality[r] || factorized_[r])
        for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) {
          const long double term = (long double)s.value[p] * lambda[r];
          sum[s.column[p]] -= term, size[s.column[p]] += std::fabs(term);
        }
    for (const Coupling &c : coupling_)  // D_r = C_r + coefficient C_other
      for (int p = s.row_start[c.other]; p < s.row_start[c.other + 1]; ++p) {
        const long double term = (long double)c.coefficient * s.value[p] * lambda[c.row];
        sum[s.column[p]] -= term, size[s.column[p]] += std::fabs(term);
      }
    for (size_t b = 0; b < s.blocks.size(); ++b) {
      const SymmetricCsc &k = *s.blocks[b];
      const int o = s.block_offset[b];
      for (int j = 0; j < k.n; ++j)
        for (int p = k.colptr[j]; p < k.colptr[j + 1]; ++p) {
          const int i = k.rows[p];
          const long double a = (long double)k.values[p] * x[o + j];
          sum[o + i] -= a, size[o + i] += std::fabs(a);
          if (i != j) {
            const long double c = (long double)k.values[p] * x[o + i];
            sum[o + j] -= c, size[o + j] += std::fabs(c);
          }
        }
    }
    rf.assign(s.n_unknowns, 0.0);
    long double worst = 0, largest = 0;
    for (int i = 0; i < s.n_unknowns; ++i) {
      rf[i] = double(sum[i]);
      worst = std::max(worst, std::fabs(sum[i])), largest = std::max(largest, size[i]);
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
  for (int step = 0; step < kMaxRefinements && current > 1e-18; ++step) {
    std::vector<double> dx(s.n_unknowns, 0.0), dl(nrows, 0.0);
    krylov(rf, rt, dx, dl);
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
}

SparseContactResult SparseContactSolver::solve(const std::vector<double> &load, const std::vector<double> &target,
                                               const std::vector<char> &start, double tolerance, int max_iterations,
                                               const std::function<bool(const std::vector<char> &)> &hold_modes,
                                               const DualQpObserver &observe) {
  const SparseContactStructure &s = *structure_;
  const int nrows = s.rows();
  SparseContactResult result;
  coupling_.clear();
  std::vector<char> active(nrows, 0);
  for (int r = 0; r < nrows; ++r)
    active[r] = s.row_is_inequality[r] && (int(start.size()) == nrows ? start[r] : 1);
  std::vector<double> x(s.n_unknowns, 0.0), lambda(nrows, 0.0), gap(nrows, 0.0);
  std::set<std::vector<char>> seen;
  size_t fewest_violating = size_t(nrows) + 1;
  int fewest_at = 0;
  const int patience = 20;  // as the condensed path's (dual_qp.cpp)
  const double eps = 1e-13;
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    int n_active = 0;
    for (int r = 0; r < nrows; ++r) n_active += s.row_is_inequality[r] && active[r];
    if (hold_modes && !hold_modes(active)) {
      if (observe) observe({it, n_active, 0, 0.0, false});
      result.outcome = it == 1 ? SparseContactOutcome::modes_not_held : SparseContactOutcome::not_converged;
      result.cycled = it > 1;
      return result;
    }
    if (factorized_ != active) factorize(active, result);
    solve_on_active_set(load, target, x, lambda, result);
    // Complementarity of the contact rows, measured as the condensed path measures it.
    double lambda_ref = 0, gap_ref = 0;
    for (int r = 0; r < nrows; ++r) {
      if (!s.row_is_inequality[r]) continue;
      gap[r] = target[r] - row_times(r, x);
      double terms = std::fabs(target[r]);
      for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) terms += std::fabs(s.value[p] * x[s.column[p]]);
      lambda_ref = std::max(lambda_ref, std::fabs(lambda[r]));
      gap_ref = std::max(gap_ref, terms);
    }
    lambda_ref = std::max(lambda_ref, 1e-300), gap_ref = std::max(gap_ref, 1e-300);
    std::vector<int> violating;
    double violation = 0;
    for (int r = 0; r < nrows; ++r) {
      if (!s.row_is_inequality[r]) continue;
      if ((active[r] && lambda[r] < -eps * lambda_ref) || (!active[r] && gap[r] < -eps * gap_ref)) violating.push_back(r);
      violation = std::max(violation, std::max(0.0, -lambda[r]) / lambda_ref);
      violation = std::max(violation, std::max(0.0, -gap[r]) / gap_ref);
      violation = std::max(violation, std::fabs(lambda[r] * gap[r]) / (lambda_ref * gap_ref));
    }
    result.violation = violation;
    if (observe) observe({it, n_active, int(violating.size()), violation, true});
    if (violating.empty()) {
      result.x = std::move(x), result.lambda = std::move(lambda), result.active = active;
      result.outcome = violation <= tolerance ? SparseContactOutcome::solved : SparseContactOutcome::not_converged;
      return result;
    }
    if (violating.size() < fewest_violating) fewest_violating = violating.size(), fewest_at = it;
    if (it - fewest_at >= patience) break;
    for (int r : violating) active[r] = !active[r];
    if (!seen.insert(active).second) break;  // a cycle
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
  solve_on_active_set(load, target, x, lambda, result);
  coupling_.clear();
}

}  // namespace mc
