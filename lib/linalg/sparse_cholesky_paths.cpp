// SparseCholesky: the rows of a simplicial factor on the elimination-tree paths of the columns
// that changed, computed afresh (sparse_cholesky.hpp, refactorize_paths; docs/theory.md §6b
// item 4). Row k of L depends only on A's column k and on the rows of k's descendants (an
// up-looking factorization, as cholmod_rowfac computes it: L(k, 0:k-1) solves
// L(0:k-1, 0:k-1) y = A(0:k-1, k)). When A changes in a few columns, only those columns' rows
// and their ancestors' change; the others are the factor's already.
#include "linalg/sparse_cholesky_impl.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

// The columns on the elimination-tree paths from `start` (factor order) to the roots, ascending.
std::vector<int> columns_on_paths(const std::vector<int> &parent, const std::vector<int> &start) {
  std::vector<char> on(parent.size(), 0);
  std::vector<int> columns;
  for (int c : start)
    for (int j = c; j >= 0 && !on[size_t(j)]; j = parent[size_t(j)]) on[size_t(j)] = 1, columns.push_back(j);
  std::sort(columns.begin(), columns.end());
  return columns;
}

}  // namespace

std::vector<int> SparseCholesky::changed_in_factor_order(const std::vector<int> &changed) {
  Impl &d = *impl_;
  const std::vector<int> &inverse = d.inverse_permutation(n_);
  std::vector<int> start;
  start.reserve(changed.size());
  for (int c : changed) start.push_back(inverse[size_t(c)]);
  // And the columns modified in place since the factorization: computed afresh with the others
  // (their paths share most of the changed columns' on a load history), so that the factor is
  // then as a factorization leaves it.
  for (size_t j = 0; d.modified.count > 0 && j < d.modified.column.size(); ++j)
    if (d.modified.column[j]) start.push_back(int(j));
  return start;
}

double SparseCholesky::paths_entries(const std::vector<int> &changed) {
  Impl &d = *impl_;
  if (n_ == 0 || !d.factor || d.factor->is_super || d.factor->xtype == CHOLMOD_PATTERN) return HUGE_VAL;
  const int *lnz = static_cast<const int *>(d.factor->nz);
  double entries = 0;
  for (int j : columns_on_paths(d.elimination_tree(), changed_in_factor_order(changed))) entries += lnz[j];
  return entries;
}

bool SparseCholesky::refactorize_paths(const SymmetricCsc &a_pp, const std::vector<int> &changed) {
  Impl &d = *impl_;
  cholmod_factor *f = d.factor;
  if (n_ == 0 || changed.empty()) return true;
  if (!f || f->is_super || f->xtype != CHOLMOD_REAL || a_pp.n != n_) return false;
  const std::vector<int> rows = columns_on_paths(d.elimination_tree(), changed_in_factor_order(changed));
  const std::vector<int> &parent = d.parent;
  const int *lp = static_cast<const int *>(f->p), *li = static_cast<const int *>(f->i);
  const int *lnz = static_cast<const int *>(f->nz);
  double *lx = static_cast<double *>(f->x);
  const bool ll = f->is_ll;
  // Each column as a row factorization leaves it: its diagonal first, then its rows ascending
  // (the loop below finds row k in column j by walking its rows below j up to k). Checked on
  // the columns a recomputed row reads, as they are read.
  std::vector<double> y(static_cast<size_t>(n_), 0.0);
  std::vector<int> flag(static_cast<size_t>(n_), -1), stack(static_cast<size_t>(n_));
  for (int k : rows) {
    // The pattern of row k: the columns reached from A(0:k-1, k)'s rows up the elimination tree
    // (cs_ereach), in an order where each column comes after its descendants; y = A(0:k, k).
    int top = n_;
    flag[size_t(k)] = k;
    for (int p = a_pp.colptr[k]; p < a_pp.colptr[k + 1]; ++p) {
      int i = a_pp.rows[p];
      if (i > k) return false;  // (an upper triangle, each column's rows <= its own)
      y[size_t(i)] += a_pp.values[p];
      int length = 0;
      while (flag[size_t(i)] != k) {
        stack[size_t(length++)] = i, flag[size_t(i)] = k;
        i = parent[size_t(i)];
        if (i < 0 || i > k) return false;  // not this analysis's tree
      }
      while (length > 0) stack[size_t(--top)] = stack[size_t(--length)];
    }
    double pivot = y[size_t(k)];
    y[size_t(k)] = 0;
    for (int t = top; t < n_; ++t) {
      const int j = stack[size_t(t)];
      const double yj = y[size_t(j)];
      y[size_t(j)] = 0;
      const int end = lp[j] + lnz[j];
      if (li[lp[j]] != j) return false;  // the diagonal first
      int p = lp[j] + 1, last = j;
      // L(k, j) = y_j / L(j, j), the rows below j updated by it (LL^T); or L(k, j) = y_j / D_j,
      // the rows updated by y_j itself (LDL^T, as CHOLMOD's update/downdate leaves the factor).
      const double lkj = yj / lx[lp[j]], carried = ll ? lkj : yj;
      for (; p < end && li[p] < k; ++p) {
        if (li[p] <= last) return false;  // rows not ascending
        last = li[p];
        y[size_t(li[p])] -= lx[p] * carried;
      }
      if (p == end || li[p] != k) return false;  // row k not in column j's pattern
      lx[p] = lkj;
      pivot -= lkj * (ll ? lkj : yj);
    }
    if (!(pivot > 0) || !std::isfinite(pivot)) {
      for (int t = top; t < n_; ++t) y[size_t(stack[size_t(t)])] = 0;
      return false;
    }
    lx[lp[k]] = ll ? std::sqrt(pivot) : pivot;
    d.modified.unmark(k);  // (its column is now all computed afresh: its rows are k's ancestors, in rows)
  }
  return true;
}

}  // namespace mc
