// The sparse path's low-rank updates of its factor (docs/theory.md §6b, item 4): an active set a
// few rows away from the factor's solved through the last factor and a k x k system, instead of
// a new factorization.
#include "linalg/sparse_contact_solve.hpp"
#include "support/lapack.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

// When the rows to hold differ from the factor's by a few (an active-set iteration or a load step
// that moves the ends of the contact zone), H_P = H_0 + sum_r sign_r P_r c_r^T c_r is a rank-k
// change of the factorized H_0: its inverse is H_0^-1 - Z M^-1 Z^T with Z = H_0^-1 C_k^T and
// M = diag(1 / (sign_r P_r)) + C_k Z (Sherman-Morrison-Woodbury), a k x k LU instead of a
// factorization. Z's columns are kept from one set to the next (a row that still differs keeps
// its column: its sign has not changed), so that an iteration pays one solve per row that
// newly differs. The answer stays exact: the refinement works on the KKT system's own residuals
// (solve_on_active_set), whatever H_P^-1 was applied. Removing a row cancels P_r against
// c_r H_0^-1 c_r^T (about 1/P_r, kAugmentation larger than their difference): the update loses
// some 3 digits, which the refinement wins back.
namespace {
// What a numeric factorization costs in solves with its factor (one right-hand side), measured
// on two cores (docs/notes/interface-solver.md, "Simplicial against supernodal"): 22 on the
// long strips' H_P at 4001 contact nodes (97335 unknowns, 0.225 s against 10 ms), 23 on Hertz
// at h1 = 0.004 (100090 unknowns, 0.52 s against 23 ms), 22 at h1 = 0.0025 (0.7 s against
// 32 ms a column of an update). CHOLMOD's flop counts put them 8.6, 47 and 61 solves apart: a
// solve runs at memory speed and a factorization of small supernodes far below BLAS-3 speed,
// so flops would have taken updates of 29 rows on Hertz that cost as much as a factorization,
// and refused updates of 5 rows on the strips.
constexpr double kFactorizationSolves = 20;
// An update is taken when its new solves cost under half a factorization, and Z (n x k) takes
// under half the factor's memory.
constexpr double kUpdateShare = 0.5;
// Modifying the factor in place (CHOLMOD's update/downdate, simplicial factors only) costs about
// one pass over the entries of L on each differing row's elimination-tree path: measured at 0.8
// to 1.0 ns an entry on the strips' and the wavy contact's H_P (2.5e5 to 1.3e9 entries touched,
// 2 to 3596 rows), against 0.64 Gflop/s for a simplicial numeric factorization (the strips at
// 4001 contact nodes: 8.2e7 flops in 0.13 s). Taken when it costs under half a factorization (a
// downdate loses some digits, which the refinement wins back). A supernodal factor is left to
// the low-rank update: CHOLMOD would first turn it into a simplicial LDL^T (0.28 s for 1.8e7
// entries on Hertz at h1 = 0.0025, with both held at once: peak memory 339 -> 401 MiB), whose
// solves are 20 to 40 % slower (docs/notes/interface-solver.md, "Session 19").
constexpr double kSecondsPerTouchedEntry = 0.9e-9;
constexpr double kSecondsPerFlopSimplicial = 1.0 / 0.64e9;
constexpr double kModifyShare = 0.5;
// Modifications build on each other: the factor kept aside over a load history carries those of
// every step before. Each answer is refined to round-off, but on the load history at
// 16001 contact nodes (H_P about as ill-conditioned as a free strip 1000 times longer than high)
// the last step's pressures drifted from a fresh solve's by 5e-11, 9e-9 and 3e-8 of p after 2, 5
// and 10 steps of 4 modifications each (fresh solves with AMD and METIS orderings differ by 2e-8
// to 7e-8 there: the problem's own round-off). Past this many modifications the factor is
// computed afresh: 8e-12 after 10 steps (docs/notes/interface-solver.md, "Session 19").
constexpr int kMaxModifications = 12;
// Computing afresh the rows of L on the elimination-tree paths of the columns that changed
// (SparseCholesky::refactorize_paths) costs about this much per entry of L on those paths:
// 70 to 80 ns on the strips at 4001 and 16001 contact nodes (1.2 to 6.2 million entries, one
// thread; a row's up-looking solve reads its columns' entries above it, so the work is more
// than the entries themselves). A modification's cost grows with the rows that changed, this
// one with their paths' union: a load step's 326 rows at 16001 nodes are 1.1 million entries
// (0.08 s) against a modification of 0.36 s; two rows, 0.67 million (0.05 s) against 0.007 s.
constexpr double kSecondsPerPathEntry = 75e-9;
}  // namespace

// The rows where `active` differs from the factor's set, and for each the column of the update
// in use that it keeps (-1: a fresh one, a solve).
void SparseContactSolver::update_rows(const std::vector<char> &active, std::vector<int> &rows, std::vector<int> &kept,
                                      int &fresh) const {
  const SparseContactStructure &s = *structure_;
  rows.clear();
  for (int r = 0; r < s.rows(); ++r)
    if (s.row_is_inequality[r] && active[r] != factor_set_[r]) rows.push_back(r);
  const int k = int(rows.size());
  // The columns of Z already computed (update_.rows is sorted, as rows is).
  kept.assign(k, -1);
  fresh = 0;
  for (int c = 0, o = 0; c < k; ++c) {
    const std::vector<int> &old = update_.rows;
    while (o < int(old.size()) && old[o] < rows[c]) ++o;
    if (o < int(old.size()) && old[o] == rows[c]) kept[c] = o;
    else ++fresh;
  }
}

// An update of k rows, `fresh` of them new, costs under half a factorization, and Z (n x k)
// takes under half the factor's memory.
bool SparseContactSolver::update_fits(int k, int fresh) const {
  const double solves_per_factorization =
      measured_costs() ? kFactorizationSolves : flops_ / (4.0 * double(cholesky_.factor_nnz()));
  return double(fresh) <= kUpdateShare * solves_per_factorization &&
         double(k) * structure_->n_unknowns <= kUpdateShare * double(cholesky_.factor_nnz());
}

bool SparseContactSolver::needs_factorization(const std::vector<char> &set) {
  if (factor_set_.size() != set.size()) return true;
  const double half_a_factorization = kModifyShare * flops_ * kSecondsPerFlopSimplicial;
  if (!aside_set_.empty() && modify_seconds(aside_set_, aside_modifications_, set) <= half_a_factorization) return false;
  if (modify_seconds(factor_set_, modifications_, set) <= half_a_factorization) return false;
  std::vector<int> rows, kept;
  int fresh = 0;
  update_rows(set, rows, kept, fresh);
  return !rows.empty() && !update_fits(int(rows.size()), fresh);
}

// More rows apart than a low-rank update of from's factor would take (a modification's estimate
// is no measure here: on the strips under a moving load, 320 rows estimated under half a
// factorization took a whole one).
double SparseContactSolver::paths_seconds(const std::vector<char> &to, std::vector<int> &changed) {
  changed.clear();
  if (inverse_order_.empty() || factor_set_.size() != to.size() || values_set_.size() != to.size() ||
      !measured_costs() || cholesky_.supernodal())
    return HUGE_VAL;
  // The paths' union holds each differing row's own path, so it costs at least 1/k of a
  // modification of those k rows (modify_seconds: the sum of their paths) times
  // kSecondsPerPathEntry / kSecondsPerTouchedEntry: up to that many rows a modification costs
  // less whatever the paths, and they are not walked (the few rows of most iterations).
  const SparseContactStructure &s = *structure_;
  int k = 0;
  for (int r = 0; r < s.rows(); ++r) k += s.row_is_inequality[r] && bool(factor_set_[r]) != bool(to[r]);
  if (k * kSecondsPerTouchedEntry <= kSecondsPerPathEntry) return HUGE_VAL;
  changed = columns_of_differing_rows(factor_set_, to);
  const double seconds = cholesky_.paths_entries(changed) * kSecondsPerPathEntry;
  return seconds <= kModifyShare * flops_ * kSecondsPerFlopSimplicial ? seconds : HUGE_VAL;
}

bool SparseContactSolver::far_apart(const std::vector<char> &from, const std::vector<char> &to) {
  const SparseContactStructure &s = *structure_;
  int k = 0;
  for (int r = 0; r < s.rows(); ++r) k += s.row_is_inequality[r] && bool(from[r]) != bool(to[r]);
  return !update_fits(k, k);
}

bool SparseContactSolver::update_from_factor(const std::vector<char> &active, SparseContactResult &result) {
  const SparseContactStructure &s = *structure_;
  if (factor_set_.size() != active.size()) return false;
  std::vector<int> rows, kept;
  int fresh = 0;
  update_rows(active, rows, kept, fresh);
  const int n = s.n_unknowns, k = int(rows.size());
  if (k == 0) {
    update_ = {}, factorized_ = active;
    return true;
  }
  if (!update_fits(k, fresh)) return false;
  const double start = now();
  LowRankUpdate u;
  u.rows = rows;
  u.z.assign(size_t(n) * k, 0.0);
  std::vector<double> block(size_t(n) * std::max(fresh, 1), 0.0);
  std::vector<int> fresh_columns;
  for (int c = 0; c < k; ++c) {
    if (kept[c] >= 0) {
      std::copy_n(update_.z.begin() + size_t(kept[c]) * n, n, u.z.begin() + size_t(c) * n);
      continue;
    }
    const size_t f = fresh_columns.size();
    fresh_columns.push_back(c);
    for (int p = s.row_start[rows[c]]; p < s.row_start[rows[c] + 1]; ++p) block[f * n + s.column[p]] = s.value[p];
  }
  if (fresh > 0) cholesky_.solve(block.data(), fresh);
  for (size_t f = 0; f < fresh_columns.size(); ++f)
    std::copy_n(block.begin() + f * n, n, u.z.begin() + size_t(fresh_columns[f]) * n);
  // The old Z is not needed past here (a refused update is followed by a factorization): freed
  // now rather than when the new one replaces it, after M's LU. (While its kept columns are
  // copied both are held: up to the factor's memory, Z being capped at half of it.)
  block = {}, update_ = {}, factorized_ = factor_set_;
  std::vector<double> m(size_t(k) * k, 0.0);
  for (int c = 0; c < k; ++c) {
    for (int i = 0; i < k; ++i) {
      double v = 0;
      for (int p = s.row_start[rows[i]]; p < s.row_start[rows[i] + 1]; ++p) v += s.value[p] * u.z[size_t(c) * n + s.column[p]];
      m[size_t(c) * k + i] = v;
    }
    const double sign = active[rows[c]] ? 1.0 : -1.0;
    m[size_t(c) * k + c] += 1 / (sign * weight_[rows[c]]);
  }
  const bool regular = u.m.factorize(k, std::move(m), 1e-12);
  result.t_factor += now() - start;
  if (!regular) return false;  // (a factorization then says what is singular)
  update_ = std::move(u);
  factorized_ = active;
  result.updates++;
  return true;
}

double SparseContactSolver::modify_seconds(const std::vector<char> &from, int modifications,
                                           const std::vector<char> &to) {
  const SparseContactStructure &s = *structure_;
  if (from.size() != to.size() || !measured_costs() || cholesky_.supernodal()) return HUGE_VAL;
  if (modifications >= kMaxModifications) return HUGE_VAL;
  if (path_.empty()) path_ = cholesky_.path_entries();
  // What the modification touches: each differing row's path (the longest of its columns').
  double touched = 0;
  for (int r = 0; r < s.rows(); ++r) {
    if (!s.row_is_inequality[r] || to[r] == from[r]) continue;
    double longest = 0;
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) longest = std::max(longest, path_[size_t(s.column[p])]);
    touched += longest;
  }
  return touched * kSecondsPerTouchedEntry;
}

bool SparseContactSolver::modify_factor(const std::vector<char> &active, SparseContactResult &result) {
  const SparseContactStructure &s = *structure_;
  if (modify_seconds(factor_set_, modifications_, active) > kModifyShare * flops_ * kSecondsPerFlopSimplicial) return false;
  const double start = now();
  // sqrt(P_r) c_r^T for the rows that enter (added: an update) and those that leave (removed: a
  // downdate); the update first, so that the matrix stays positive definite on the way.
  std::vector<int> colptr[2] = {{0}, {0}}, rows[2];
  std::vector<double> values[2];
  for (int r = 0; r < s.rows(); ++r) {
    if (!s.row_is_inequality[r] || active[r] == factor_set_[r]) continue;
    const int which = active[r] ? 0 : 1;
    const double scale = std::sqrt(weight_[size_t(r)]);
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
      rows[which].push_back(s.column[p]), values[which].push_back(scale * s.value[p]);
    colptr[which].push_back(int(rows[which].size()));
  }
  if (colptr[0].size() + colptr[1].size() == 2) {  // no row differs (a low-rank update was in use)
    update_ = {}, factorized_ = active;
    return true;
  }
  update_ = {}, factorized_.clear(), factor_set_.clear();
  bool positive = true;
  for (int which = 0; which < 2 && positive; ++which)
    positive = cholesky_.modify(which == 0, int(colptr[which].size()) - 1, colptr[which].data(), rows[which].data(),
                                values[which].data());
  result.t_factor += now() - start;
  if (!positive) return false;  // (the factor is then no factor: a factorization follows)
  factorized_ = factor_set_ = active;
  modifications_++;
  result.modifications++;
  return true;
}

std::vector<int> SparseContactSolver::columns_of_differing_rows(const std::vector<char> &from,
                                                                const std::vector<char> &to) const {
  const SparseContactStructure &s = *structure_;
  std::vector<int> columns;
  std::vector<char> seen(size_t(s.n_unknowns), 0);
  for (int r = 0; r < s.rows(); ++r)
    if (s.row_is_inequality[r] && bool(from[r]) != bool(to[r]))
      for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
        if (!seen[size_t(s.column[p])]) seen[size_t(s.column[p])] = 1, columns.push_back(s.column[p]);
  return columns;
}

// matrix_'s values of `active`, computed afresh where a row that differs from values_set_ has
// terms, as factorize_afresh computes them (H's value, then each held row's P_r c_ri c_rj in the
// rows' order: the same sums to the bit). Adding and taking away the differing rows' terms instead
// left each such entry with the round-off of P_r c_r^2, some 10^3 times H's: the strips' load
// history with the window jumping by its width (4001 contact nodes) then ended 3.5e-10 of p from
// a fresh solve instead of 3e-12.
void SparseContactSolver::set_values(const std::vector<char> &active) {
  const SparseContactStructure &s = *structure_;
  if (column_rows_start_.empty()) {  // C by columns (its rows' indices), once
    column_rows_start_.assign(size_t(s.n_unknowns) + 1, 0);
    for (int p = 0; p < s.row_start[s.rows()]; ++p) column_rows_start_[size_t(s.column[p]) + 1]++;
    for (int c = 0; c < s.n_unknowns; ++c) column_rows_start_[size_t(c) + 1] += column_rows_start_[size_t(c)];
    column_rows_.resize(size_t(s.row_start[s.rows()]));
    std::vector<int> at(column_rows_start_.begin(), column_rows_start_.end() - 1);
    for (int r = 0; r < s.rows(); ++r)
      for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) column_rows_[size_t(at[size_t(s.column[p])]++)] = r;
  }
  // The entries the differing rows have terms in, and the rows with terms there (those sharing
  // a column with a differing row), ascending.
  std::vector<char> marked(matrix_.values.size(), 0), row_marked(size_t(s.rows()), 0);
  std::vector<int> entries, rows;
  for (int r = 0; r < s.rows(); ++r) {
    if (!s.row_is_inequality[r] || bool(active[r]) == bool(values_set_[r])) continue;
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p) {
      for (int q = s.row_start[r]; q < s.row_start[r + 1]; ++q) {
        if (s.column[q] < s.column[p]) continue;
        const int at = position(s.column[p], s.column[q]);
        if (!marked[size_t(at)]) marked[size_t(at)] = 1, entries.push_back(at);
      }
      const int c = s.column[p];
      for (int k = column_rows_start_[size_t(c)]; k < column_rows_start_[size_t(c) + 1]; ++k)
        if (!row_marked[size_t(column_rows_[size_t(k)])]) row_marked[size_t(column_rows_[size_t(k)])] = 1, rows.push_back(column_rows_[size_t(k)]);
    }
  }
  std::sort(rows.begin(), rows.end());
  for (int at : entries) matrix_.values[size_t(at)] = 0;
  size_t k = 0;  // H's entries in add_blocks_of_h's order (block_position_: matrix_ is in the factor's order)
  for (size_t b = 0; b < s.blocks.size(); ++b)
    for (int c = 0; c < s.blocks[b].n; ++c)
      s.blocks[b].for_each_in_column(c, [&](int, double value) {
        const int at = block_position_[k++];
        if (marked[size_t(at)]) matrix_.values[size_t(at)] += value;
      });
  for (int r : rows) {
    if (s.row_is_inequality[r] && !active[r]) continue;
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
      for (int q = s.row_start[r]; q < s.row_start[r + 1]; ++q)
        if (s.column[q] >= s.column[p]) {
          const int at = position(s.column[p], s.column[q]);
          if (marked[size_t(at)]) matrix_.values[size_t(at)] += weight_[r] * s.value[p] * s.value[q];
        }
  }
  values_set_ = active;
}

bool SparseContactSolver::refactorize_paths(const std::vector<char> &active, const std::vector<int> &changed,
                                            SparseContactResult &result) {
  if (inverse_order_.empty() || factor_set_.size() != active.size() || values_set_.size() != active.size())
    return false;
  if (changed.empty()) {
    update_ = {}, factorized_ = active;
    return true;
  }
  const double start = now();
  set_values(active);
  update_ = {}, factorized_.clear(), factor_set_.clear();
  const bool done = cholesky_.refactorize_paths(matrix_, changed);
  result.t_factor += now() - start;
  if (!done) return false;
  // The columns modified in place before were computed afresh too: the factor is as a
  // factorization leaves it (no drift to cap: on the load history no step factorizes for it).
  factorized_ = factor_set_ = active;
  modifications_ = cholesky_.modified_in_place() ? modifications_ + 1 : 0;
  result.modifications++, result.path_refactorizations++;
  return true;
}

void SparseContactSolver::apply_inverse(std::vector<double> &v, SparseContactResult &result) const {
  const double start = now();
  cholesky_.solve(v.data());
  const int k = int(update_.rows.size()), n = structure_->n_unknowns;
  if (k > 0) {
    std::vector<double> t(k);
    for (int i = 0; i < k; ++i) t[i] = row_times(update_.rows[i], v);
    update_.m.solve(t.data());
    int one = 1, kk = k, nn = n;
    double minus = -1.0, plus = 1.0;
    dgemv_("N", &nn, &kk, &minus, update_.z.data(), &nn, t.data(), &one, &plus, v.data(), &one);
  }
  result.t_solve += now() - start;
}

}  // namespace mc
