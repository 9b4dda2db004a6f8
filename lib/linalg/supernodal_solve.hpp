// Solves with a supernodal Cholesky factor (CHOLMOD's, LL^T) split by subtrees of its supernodal
// elimination tree, so that two threads can do them at once, as subtree_solve.hpp does for a
// simplicial factor (docs/theory.md §6b, item 3).
//
// Why: the sparse path's H_P on Hertz and Westergaard factors supernodal, and its solves (20 to
// 40 a solve, 25 to 80 ms each on one thread) are most of what is not a factorization. A solve is
// a pass over the factor's entries, bound by memory bandwidth: two threads read about twice as
// fast. CHOLMOD's own supernodal solve runs on one.
//
// How: the plan of subtree_solve.hpp made over supernodes (each supernode's parent: the one
// holding its first row below its columns; its entries: its block's). Forward, each supernode
// solves its diagonal block, then sums its block's rows below into one update per row (a dense
// pass down its columns), scattered once; half 1's updates of the top's rows go into a buffer of
// its own, added after both halves. Backward, each supernode gathers its rows below once, then
// its columns' dot products and the diagonal block. The arithmetic and its order are the plan's:
// the same answer to the bit on one thread or two.
#pragma once
#include "linalg/subtree_solve.hpp"
#include <vector>

namespace mc {

// A supernodal factor in CHOLMOD's storage: supernode s holds columns super[s] .. super[s + 1] - 1,
// its rows at s_rows[pi[s] .. pi[s + 1]) (its own columns first), its values column-major from
// x[px[s]] (leading dimension pi[s + 1] - pi[s]).
struct SupernodalFactor {
  int n = 0, nsuper = 0;
  const int *super = nullptr, *pi = nullptr, *px = nullptr, *s_rows = nullptr;
  const double *x = nullptr;
};

class SupernodalSolvePlan {
public:
  explicit SupernodalSolvePlan(const SupernodalFactor &f);
  bool worthwhile() const { return plan_.worthwhile(); }
  // y <- (L L^T)^-1 y, y in the factor's order; with two_threads the halves run at once.
  void solve(const SupernodalFactor &f, double *y, bool two_threads) const;
  const SubtreeSolvePlan &plan() const { return plan_; }

private:
  SubtreeSolvePlan plan_;      // over supernodes
  std::vector<int> top_slot_;  // a column of the top: its place among the top's columns (-1 elsewhere)
  int top_columns_ = 0;
  void forward_part(const SupernodalFactor &f, int h, double *y, double *spill) const;
  void backward_part(const SupernodalFactor &f, int h, double *y) const;
};

}  // namespace mc
