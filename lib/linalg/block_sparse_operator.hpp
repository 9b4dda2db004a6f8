// The condensed interface operator S = B K^+ B^T = sum_b s_b stored by blocks (docs/theory.md,
// "Two interface solvers"). Body b's share s_b couples only the rows that touch b, so S(r, c)
// can be nonzero only if rows r and c touch a common body. The rows are grouped into blocks by
// the set of bodies that touch them (a pair's normal and tangential rows: one block), and block
// (I, J) is stored, dense, iff some body touches both I and J. For a chain of N bodies S is then
// block tridiagonal: storage and work grow like N, not N^2 (N^3 for a dense factorization).
//
// When every pair of blocks is stored (two bodies: every row touches both), S is kept as one
// dense block over all rows in their order: today's column-major q x q array, with the same
// arithmetic (dense(), dense_values()).
#pragma once
#include "bodies/assembly.hpp"
#include <cstddef>
#include <vector>

namespace mc {

class BlockSparseOperator {
public:
  BlockSparseOperator() = default;
  // The pattern of an operator of order n whose shares couple the rows touching each body:
  // body_rows[b] lists them, increasing. Only the pattern: the values (stored_entries() of
  // them, zero) are allocated by the first add_share, so that the pattern can be costed first.
  BlockSparseOperator(int n, const std::vector<std::vector<int>> &body_rows);

  // Adds one body's share: s (column-major, rows.size() squared; its upper triangle is read)
  // over `rows` (increasing). Shares added body by body in a fixed order sum every entry in that
  // order, whatever the storage. Then symmetrize() once all are in.
  void add_share(const std::vector<int> &rows, const std::vector<double> &s);
  void symmetrize();

  int order() const { return n_; }
  int blocks() const { return int(block_rows_.size()); }
  size_t stored_entries() const { return stored_; }
  // One dense block over rows 0 .. n-1 in order: dense_values() is S, n x n column-major.
  bool dense() const { return blocks() <= 1; }
  const double *dense_values() const { return values_.data(); }
  // The dense factorization's flops for the sparse LU of an active set, counted on the block
  // pattern: eliminating block I costs about |I| (sum of its neighbours' sizes)^2, fill beyond
  // the neighbours ignored (none for a chain or a tree in the right order). n^3 for one block.
  double elimination_flops() const;

  double operator()(int r, int c) const;
  double diagonal(int r) const { return (*this)(r, r); }
  // y += alpha S x (x, y of size n). For one dense block: a single DGEMV into y.
  void multiply_add(double alpha, const double *x, double *y) const;
  // Calls add(r, c, S(r, c)) for every stored entry with row_mask[r] and col_mask[c] set (each
  // entry of that submatrix once; entries outside the stored blocks are zero).
  template <class Add>
  void for_each_entry(const std::vector<char> &row_mask, const std::vector<char> &col_mask, Add &&add) const;
  // The principal submatrix on the rows with mask[r] set, as the upper triangle in compressed
  // columns (what CHOLMOD reads), its unknowns numbered block by block: order[i] is unknown i's
  // row. Each column is then a run of stored blocks' columns, already sorted: no sort, no search.
  SymmetricCsc principal_upper(const std::vector<char> &mask, std::vector<int> &order) const;

private:
  struct Neighbour {
    int block;      // J
    size_t offset;  // of the stored block (min(I, J), max(I, J)) in values_
  };
  int n_ = 0;
  std::vector<std::vector<int>> block_rows_;      // per block its rows, increasing
  std::vector<int> block_of_, local_of_;          // per row: its block and place there
  std::vector<std::vector<Neighbour>> neighbours_;  // per block I: the J sharing a body, increasing (I included)
  std::vector<double> values_;                    // block (I, J), I <= J: |I| x |J| column-major
  size_t stored_ = 0;                             // values_'s size once allocated
  size_t offset_of(int i, int j) const;           // of stored block (i, j); SIZE_MAX if not stored
  void allocate();
};

template <class Add>
void BlockSparseOperator::for_each_entry(const std::vector<char> &row_mask, const std::vector<char> &col_mask,
                                         Add &&add) const {
  const int nb = blocks();
  std::vector<std::vector<int>> rows_in(nb), cols_in(nb);  // per block: masked local indices
  for (int b = 0; b < nb; ++b)
    for (int l = 0; l < int(block_rows_[b].size()); ++l) {
      if (row_mask[block_rows_[b][l]]) rows_in[b].push_back(l);
      if (col_mask[block_rows_[b][l]]) cols_in[b].push_back(l);
    }
  for (int i = 0; i < nb; ++i)
    for (const Neighbour &nj : neighbours_[i]) {
      const int j = nj.block;
      const std::vector<int> &ri = block_rows_[i], &rj = block_rows_[j];
      if (i <= j) {  // stored as (i, j): entry (a, c) at c |i| + a
        const size_t ld = ri.size();
        for (int c : cols_in[j])
          for (int a : rows_in[i]) add(ri[a], rj[c], values_[nj.offset + size_t(c) * ld + a]);
      } else {  // stored as (j, i): S(ri[a], rj[c]) = S(rj[c], ri[a]) at a |j| + c
        const size_t ld = rj.size();
        for (int c : cols_in[j])
          for (int a : rows_in[i]) add(ri[a], rj[c], values_[nj.offset + size_t(a) * ld + c]);
      }
    }
}

}  // namespace mc
