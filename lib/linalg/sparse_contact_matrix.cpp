// SparseContactSolver's matrix H_P = H + C^T P C (sparse_contact_solve.hpp): its pattern and P's
// weights (the analysis), the pattern in the simplicial factor's order, and its values for an
// active set (a numeric factorization). The iteration over active sets, the solves and the
// refinement are in sparse_contact_solve.cpp.
#include "linalg/sparse_contact_solve.hpp"
#include "support/error.hpp"
#include "support/stopwatch.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

void SparseContactSolver::analyze(const SparseContactStructure &s, int ordering) {
  const double start = now();
  structure_ = &s;
  factorized_.clear(), values_set_.clear(), column_rows_start_.clear(), column_rows_.clear();
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
    for (int c = 0; c < s.blocks[b].n; ++c) block_of[s.block_offset[b] + c] = int(b);
  matrix_ = SymmetricCsc{};
  matrix_.n = n;
  matrix_.colptr.assign(n + 1, 0);
  // Columns [first, last) of a pass (0: each column's count into colptr[j + 1]; 1: its rows,
  // sorted), with a marker of its own: the columns in two ranges of about as many unknowns, one
  // per thread.
  auto columns = [&](int pass, int first, int last) {
    std::vector<int> mark(n, -1);
    for (int j = first; j < last; ++j) {
      int top = pass == 0 ? 0 : matrix_.colptr[j];
      auto keep = [&](int i) {
        if (mark[i] == j) return;
        mark[i] = j;
        if (pass == 1) matrix_.rows[size_t(top)] = i;
        ++top;
      };
      if (block_of[j] >= 0) {
        const int o = s.block_offset[size_t(block_of[j])];
        s.blocks[size_t(block_of[j])].for_each_in_column(j - o, [&](int i, double) { keep(o + i); });
      }
      keep(j);  // the diagonal, also for w and alpha
      for (int q = ct_start[j]; q < ct_start[j + 1]; ++q) {
        const int r = ct_row[size_t(q)];
        for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
          if (s.column[p] <= j) keep(s.column[p]);
      }
      if (pass == 0) matrix_.colptr[j + 1] = top;
      else std::sort(matrix_.rows.begin() + matrix_.colptr[j], matrix_.rows.begin() + top);
    }
  };
  for (int pass = 0; pass < 2; ++pass) {
    run_in_pairs([&](size_t part) { part == 0 ? columns(pass, 0, n / 2) : columns(pass, n / 2, n); },
                 n >= kResidualThreadsFromUnknowns);
    if (pass == 0) {
      for (int j = 0; j < n; ++j) matrix_.colptr[j + 1] += matrix_.colptr[j];
      matrix_.rows.resize(size_t(matrix_.colptr[n]));
    }
  }
  std::vector<int>().swap(ct_row), std::vector<int>().swap(block_of);
  matrix_.values.assign(matrix_.rows.size(), 0.0);
  // 2. H's diagonal, for P's weights.
  std::vector<double> diagonal(n, 0.0);
  for (size_t b = 0; b < s.blocks.size(); ++b)
    for (int c = 0; c < s.blocks[b].n; ++c)
      s.blocks[b].for_each_in_column(c, [&](int i, double value) {
        if (i == c) diagonal[s.block_offset[b] + c] = value;
      });
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
  // 4. Ordering and symbolic factorization; a supernodal factor's solves split too.
  cholesky_.split_supernodal_solves();
  cholesky_.analyze(matrix_, {}, ordering, true);
  // 5. H_P kept in the factor's order where the factor is simplicial (factorize_ordered).
  order_as_factor();
  path_.clear();
  flops_ = cholesky_.analysis_flops();
  t_analysis_ = now() - start;
}

// H_P's pattern in the simplicial factor's order (the upper triangle of H_P(p, p), each column
// sorted), so that each factorization reads it as it is: cholmod_factorize would copy it into
// that order first (two transposes, 0.13 s of a 0.46 s factorization on the strips at 16001
// contact nodes, and 80 MB beside the factor at the solve's peak memory). With it, where each
// of H's entries goes (block_position_): H's values are added in one pass, as in the unknowns'
// order (a search per entry instead took 0.07 s there). A supernodal factor keeps the pattern
// in the unknowns' own order.
void SparseContactSolver::order_as_factor() {
  inverse_order_.clear(), block_position_.clear();
  const std::vector<int> order = cholesky_.simplicial_order();
  if (order.empty()) return;
  const SparseContactStructure &s = *structure_;
  const int n = matrix_.n;
  std::vector<int> inverse(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) inverse[size_t(order[size_t(k)])] = k;
  std::vector<double>().swap(matrix_.values);
  // 1. Each entry (i, j) of the pattern goes to column max(p^-1 i, p^-1 j) of the ordered one.
  SymmetricCsc ordered;
  ordered.n = n;
  ordered.colptr.assign(size_t(n) + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int q = matrix_.colptr[j]; q < matrix_.colptr[j + 1]; ++q)
      ordered.colptr[size_t(std::max(inverse[size_t(matrix_.rows[q])], inverse[size_t(j)])) + 1]++;
  for (int j = 0; j < n; ++j) ordered.colptr[size_t(j) + 1] += ordered.colptr[size_t(j)];
  const size_t nnz = matrix_.rows.size();
  ordered.rows.resize(nnz);
  std::vector<int> where(nnz);  // entry q of the pattern: its place in the ordered one
  {
    std::vector<int> next(ordered.colptr.begin(), ordered.colptr.end() - 1), origin(nnz);
    for (int j = 0; j < n; ++j)
      for (int q = matrix_.colptr[j]; q < matrix_.colptr[j + 1]; ++q) {
        const int a = inverse[size_t(matrix_.rows[q])], b = inverse[size_t(j)];
        const int slot = next[size_t(std::max(a, b))]++;
        ordered.rows[size_t(slot)] = std::min(a, b), origin[size_t(slot)] = q;
      }
    // 2. Each column sorted, and where each entry went: the columns in two ranges of about as
    //    many entries, one per thread.
    const int middle = int(std::upper_bound(ordered.colptr.begin(), ordered.colptr.end(), ordered.colptr[size_t(n)] / 2) -
                           ordered.colptr.begin()) - 1;
    run_in_pairs(
        [&](size_t part) {
          std::vector<std::pair<int, int>> column;
          for (int c = part == 0 ? 0 : middle; c < (part == 0 ? middle : n); ++c) {
            column.clear();
            for (int k = ordered.colptr[c]; k < ordered.colptr[c + 1]; ++k)
              column.emplace_back(ordered.rows[size_t(k)], origin[size_t(k)]);
            std::sort(column.begin(), column.end());
            for (size_t k = 0; k < column.size(); ++k) {
              ordered.rows[size_t(ordered.colptr[c]) + k] = column[k].first;
              where[size_t(column[k].second)] = ordered.colptr[c] + int(k);
            }
          }
        },
        n >= kResidualThreadsFromUnknowns);
  }
  // 3. H's entries, in the order add_blocks_of_h reads them: their places in the ordered pattern
  //    (found by walking the block's column and the pattern's, both sorted); each block's on a
  //    thread of its own where there are two.
  std::vector<std::vector<int>> positions(s.blocks.size());
  auto place_blocks = [&](size_t first) {
    for (size_t b = first; b < s.blocks.size(); b += 2) {
      const int o = s.block_offset[b];
      for (int c = 0; c < s.blocks[b].n; ++c) {
        int at = matrix_.colptr[o + c];
        s.blocks[b].for_each_in_column(c, [&](int i, double) {
          while (matrix_.rows[size_t(at)] != o + i) ++at;
          positions[b].push_back(where[size_t(at)]);
        });
      }
    }
  };
  run_in_pairs(place_blocks, s.blocks.size() > 1 && n >= kResidualThreadsFromUnknowns);
  size_t total = 0;
  for (const std::vector<int> &p : positions) total += p.size();
  block_position_.reserve(total);
  for (std::vector<int> &p : positions) block_position_.insert(block_position_.end(), p.begin(), p.end()), std::vector<int>().swap(p);
  block_position_.shrink_to_fit();
  ordered.values.assign(nnz, 0.0);
  matrix_ = std::move(ordered);
  inverse_order_ = std::move(inverse);
}

// Entry (i, j) of the pattern (i <= j), i and j in the unknowns' order.
int SparseContactSolver::position(int i, int j) const {
  if (!inverse_order_.empty()) i = inverse_order_[size_t(i)], j = inverse_order_[size_t(j)];
  if (i > j) std::swap(i, j);
  auto first = matrix_.rows.begin() + matrix_.colptr[j], last = matrix_.rows.begin() + matrix_.colptr[j + 1];
  return int(std::lower_bound(first, last, i) - matrix_.rows.begin());
}

// H_P's values for an active set: H's blocks (each block column merged into the pattern's
// column, both sorted), then each active row's c_r^T P_r c_r. Nothing of H is kept beside the
// pattern: its values are read from the bodies' matrices each time (memory: docs/benchmarks.md).
void SparseContactSolver::factorize(const std::vector<char> &active, SparseContactResult &result) {
  // The factor kept aside, if the set is nearer to its own: a load step's first set (the last
  // step's) goes to a wild one (thousands of rows that the next set releases again, docs/notes/
  // interface-solver.md), and the set after it is a few rows from the first.
  if (!aside_set_.empty() &&
      modify_seconds(aside_set_, aside_modifications_, active) < modify_seconds(factor_set_, modifications_, active)) {
    cholesky_.swap_aside();
    std::swap(factor_set_, aside_set_), std::swap(modifications_, aside_modifications_);
    update_ = {}, factorized_ = factor_set_;
  }
  // A simplicial factor in the matrix's order: its rows on the changed columns' paths computed
  // afresh where that costs less than a modification (many rows changed, near each other: their
  // paths share most of their columns); else modified in place (a few milliseconds for a few
  // rows, against a solve per row for the low-rank update); a supernodal one is updated
  // (sparse_factor_update.cpp); else a factorization.
  std::vector<int> changed;
  if (paths_seconds(active, changed) < modify_seconds(factor_set_, modifications_, active)) {
    if (refactorize_paths(active, changed, result)) return;
    if (factor_set_.empty()) {  // (the factor was touched, and is no factor now)
      factorize_afresh(active, result);
      return;
    }
  }
  if (modify_factor(active, result) || update_from_factor(active, result)) return;
  factorize_afresh(active, result);
}

// H's blocks into matrix_'s values (H_P's first terms; each entry has one block's value).
void SparseContactSolver::add_blocks_of_h() {
  const SparseContactStructure &s = *structure_;
  if (inverse_order_.empty()) {
    for (size_t b = 0; b < s.blocks.size(); ++b) {
      const int o = s.block_offset[b];
      for (int c = 0; c < s.blocks[b].n; ++c) {
        int at = matrix_.colptr[o + c];  // (the block's column and the pattern's: both sorted)
        s.blocks[b].for_each_in_column(c, [&](int i, double value) {
          while (matrix_.rows[size_t(at)] != o + i) ++at;
          matrix_.values[size_t(at)] += value;
        });
      }
    }
    return;
  }
  // In the factor's order: each entry's place found at the analysis (order_as_factor).
  size_t k = 0;
  for (size_t b = 0; b < s.blocks.size(); ++b)
    for (int c = 0; c < s.blocks[b].n; ++c)
      s.blocks[b].for_each_in_column(c, [&](int, double value) { matrix_.values[size_t(block_position_[k++])] += value; });
}

// Each held row's c_r^T P_r c_r into matrix_'s values (H_P's other terms), rows in order, each
// entry's term w_r c_ri c_rj with i before j in the unknowns' order (as set_values recomputes
// them). In the factor's order the row's entries are sorted by their places there, so that the
// places of a column's terms are found by one walk down that column (a search per term took
// 0.04 s of a factorization on the strips at 16001 contact nodes).
void SparseContactSolver::add_rows_terms(const std::vector<char> &active) {
  const SparseContactStructure &s = *structure_;
  if (inverse_order_.empty()) {
    for (int r = 0; r < s.rows(); ++r) {
      if (s.row_is_inequality[r] && !active[r]) continue;
      for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
        for (int q = s.row_start[r]; q < s.row_start[r + 1]; ++q)
          if (s.column[q] >= s.column[p])
            matrix_.values[size_t(position(s.column[p], s.column[q]))] += weight_[r] * s.value[p] * s.value[q];
    }
    return;
  }
  struct Term {
    int place, column;  // in the factor's order, in the unknowns'
    double value;
    bool operator<(const Term &o) const { return place < o.place; }
  };
  std::vector<Term> row;
  for (int r = 0; r < s.rows(); ++r) {
    if (s.row_is_inequality[r] && !active[r]) continue;
    row.clear();
    for (int p = s.row_start[r]; p < s.row_start[r + 1]; ++p)
      row.push_back({inverse_order_[size_t(s.column[p])], s.column[p], s.value[p]});
    std::sort(row.begin(), row.end());
    for (size_t b = 0; b < row.size(); ++b) {
      int at = matrix_.colptr[row[b].place];
      for (size_t a = 0; a <= b; ++a) {
        while (matrix_.rows[size_t(at)] != row[a].place) ++at;
        const Term &first = row[a].column <= row[b].column ? row[a] : row[b], &second = &first == &row[a] ? row[b] : row[a];
        matrix_.values[size_t(at)] += weight_[r] * first.value * second.value;
      }
    }
  }
}

void SparseContactSolver::factorize_afresh(const std::vector<char> &active, SparseContactResult &result) {
  const double start = now();
  std::fill(matrix_.values.begin(), matrix_.values.end(), 0.0);
  add_blocks_of_h();
  add_rows_terms(active);
  // (Not over the factor of every row kept aside: a re-solve's restart, solve().)
  if (keep_aside_ && !factor_set_.empty() && measured_costs() && cholesky_.can_keep_aside() &&
      !aside_holds_every_row()) {
    cholesky_.keep_aside();
    aside_set_ = factor_set_, aside_modifications_ = modifications_;
  }
  factorized_.clear(), factor_set_.clear(), update_ = {}, modifications_ = 0;
  if (inverse_order_.empty()) cholesky_.factorize(matrix_);
  else cholesky_.factorize_ordered(matrix_);
  factorized_ = factor_set_ = values_set_ = active;
  result.factorizations++;
  result.t_factor += now() - start;
}

}  // namespace mc
