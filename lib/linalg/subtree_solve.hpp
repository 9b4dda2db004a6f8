// Solves with a simplicial sparse Cholesky factor (LL^T, or the LDL^T that CHOLMOD's update and
// downdate leave) split by subtrees of its elimination tree, so that two threads can do them at
// once (docs/theory.md §6b, item 3).
//
// Why: a solve with the factor is a pass over its entries, bound by memory bandwidth; on the
// sparse interface path's strips a solve pair is most of a load step (16001 contact nodes: 23 of
// them, 43 ms each). One core reads about half of what the memory delivers here; two read twice
// as fast (measured, docs/notes/interface-solver.md).
//
// How: column j of L updates only rows that are ancestors of j in the elimination tree (parent of
// j: the smallest off-diagonal row of column j). Two sets of whole subtrees, "halves", of about
// equal entries, and the "top" (every column not in them: the ancestors that join the halves)
// partition the columns. Forward, L y = b: each half updates its own rows and the top's; half 1
// adds its updates of top rows into a buffer of its own, summed in after both halves; then the
// top columns. Backward, L^T x = y: the top first, then each half reading only its own rows and
// the top's. The arithmetic and its order are the plan's alone, whether the halves run on two
// threads or one after the other: the answer is the same to the bit either way.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

namespace mc {

// A simplicial factor in CHOLMOD's storage: column j's entries at x[p[j] .. p[j] + nz[j]), the
// diagonal first (D's entry for LDL^T, whose L has a unit diagonal), row indices in i.
struct SimplicialFactor {
  int n = 0;
  const int *p = nullptr, *i = nullptr, *nz = nullptr;
  const double *x = nullptr;
  bool ll = true;  // LL^T (else LDL^T)
};

class SubtreeSolvePlan {
public:
  using Range = std::pair<int, int>;  // columns first .. second - 1
  // The plan for a factor's pattern: its elimination tree (parent, -1 at a root; the order
  // postordered, so that a subtree's columns are consecutive) and the entries of each column.
  // Empty (worthwhile() false) when no split of the entries between two halves leaves the larger
  // half and the top under kWorthwhileShare of them, or the order is not postordered.
  SubtreeSolvePlan(const std::vector<int> &parent, const std::vector<double> &column_entries);
  SubtreeSolvePlan() = default;
  bool worthwhile() const { return !ranges_[0].empty() && !ranges_[1].empty(); }
  // Whether a factor has the pattern the plan was made for (as many columns and entries: the
  // factors of one analysis share its pattern, and CHOLMOD keeps each column's rows sorted).
  bool fits(const SimplicialFactor &factor) const;
  // y <- (L L^T)^-1 y (or (L D L^T)^-1 y), y in the factor's order; with two_threads the halves
  // run at once (one std::thread started per pass; if none can be started they run in turn).
  void solve(const SimplicialFactor &factor, double *y, bool two_threads) const;
  // The parts as ranges of consecutive columns, ascending: each half's subtrees (part 0, 1) and
  // the top's runs (part 2); for a factorization by rows (cholmod_rowfac) too.
  const std::vector<Range> &ranges(int part) const { return ranges_[part]; }
  // The shares of the entries: each half's and the top's (for the log and the tests).
  double half_entries(int h) const { return half_entries_[h]; }
  double top_entries() const { return top_entries_; }

private:
  std::vector<Range> ranges_[3];
  std::vector<size_t> top_offset_;  // per run of the top: the top's columns before it (and all, last)
  int n_ = 0;
  double total_entries_ = 0, half_entries_[2] = {0, 0}, top_entries_ = 0;
  void forward_part(const SimplicialFactor &f, int h, double *y, double *spill) const;
  void backward_part(const SimplicialFactor &f, int h, double *y) const;
  size_t top_position(int column) const;
};

}  // namespace mc
