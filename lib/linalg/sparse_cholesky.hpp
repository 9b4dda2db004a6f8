// Sparse SPD factorization with CHOLMOD (supernodal LL^T). Each instance owns its own
// cholmod_common: no state is shared between models.
//
// Unknowns named "interface" are ordered last. Then the trailing block L_GG of the factor
// gives (K^-1)_GG = L_GG^-T L_GG^-1, which is all the contact solve needs to form the
// interface operator S = B K^-1 B^T without one sparse solve per contact node
// (design note "Solving the QP fast").
#pragma once
#include "bodies/assembly.hpp"
#include <functional>
#include <memory>
#include <vector>

struct cholmod_sparse_struct;  // (cholmod.h's cholmod_sparse)

namespace mc {

class SparseCholesky {
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky &) = delete;
  SparseCholesky &operator=(const SparseCholesky &) = delete;

  // Ordering and symbolic factorization. ordering: MC_ORDERING_*. With in_halves (and no
  // interface, MC_ORDERING_AUTO, kHalvesFromUnknowns unknowns or more), the unknowns are first
  // split in two halves by a separator (split_in_two), each half ordered by AMD, the separator
  // last: the elimination tree then has two subtrees that solves and factorizations do at once.
  void analyze(const SymmetricCsc &a, const std::vector<int> &interface, int ordering, bool in_halves = false);
  // Frees the analysis and the factor (analyze starts afresh).
  void release();
  bool analyzed() const;
  // Numeric factorization; throws MC_ERROR_SINGULAR if a is not positive definite.
  void factorize(const SymmetricCsc &a);
  // After an analysis whose factor is simplicial: its permutation p, for a caller that keeps its
  // matrix in the factor's order and factorizes with factorize_ordered. Empty where the factor
  // is supernodal (or there is none): factorize then permutes the matrix itself.
  std::vector<int> simplicial_order() const;
  // factorize, for a matrix already in the factor's order: the upper triangle of A(p, p), p from
  // simplicial_order(), each column sorted. cholmod_factorize would first copy A into that order
  // (two transposes per factorization, and the copy beside the factor at the solve's peak
  // memory). The factor's rows are computed as cholmod_factorize computes them (cholmod_rowfac):
  // the same factor to the bit; where the solves are split (the plan's halves) and set_threads
  // allows two threads, each half's rows at once on its own thread, then the top's.
  void factorize_ordered(const SymmetricCsc &a_pp);
  // The factor of A + C C^T (add) or A - C C^T, modified in place (CHOLMOD's update/downdate,
  // which leaves a simplicial LDL^T; meant for a simplicial factor): C has k columns, given by columns in a's
  // numbering (colptr k + 1, rows, values). Returns false if the modified factor is not
  // positive definite to working precision (a pivot <= 0 or not finite): then it is no factor of
  // anything useful and the caller factorizes afresh.
  bool modify(bool add, int k, const int *colptr, const int *rows, const double *values);
  // The factor of a matrix that differs from the factorized one in the columns `changed` (a's
  // numbering) only, by computing afresh the rows of L on their elimination-tree paths (no
  // other row of L changes: a row depends on A's column and on its descendants' rows) and on
  // those of the columns modified in place since the factorization (modified_in_place is then
  // false: the factor is as a factorization of a_pp leaves it), from
  // a_pp as factorize_ordered takes it; LL^T or LDL^T as the factor is (simplicial only). What
  // it costs does not grow with the number of rows of C that changed, as a modification's
  // does: only with their paths' union (paths_entries). Returns false if the factor is not one
  // this can recompute or a pivot is not positive: then it is no factor, and the caller
  // factorizes afresh (sparse_cholesky_paths.cpp).
  bool refactorize_paths(const SymmetricCsc &a_pp, const std::vector<int> &changed);
  // Whether a column of the factor was modified in place (modify) since its factorization and
  // has not been computed afresh since (refactorize_paths computes a column afresh with its row:
  // the column's rows are the row's ancestors, all on the paths).
  bool modified_in_place() const;
  // The entries of L in the columns on those paths (HUGE_VAL where there is no simplicial factor).
  double paths_entries(const std::vector<int> &changed);
  bool supernodal() const;
  // A second numeric factor of the same analysis, kept aside (simplicial analyses only: their
  // symbolic part is a few arrays of n): keep_aside() moves the factor aside (freeing the one
  // there) and leaves a fresh copy of the analysis to factorize; swap_aside() exchanges the two;
  // release_aside() frees the one aside.
  bool can_keep_aside() const;
  void keep_aside();
  void swap_aside();
  void release_aside();
  // For each unknown (a's numbering): the entries of L in the columns of its elimination-tree
  // path, from its column to the root: what an update or downdate of a column of C with a
  // nonzero there touches. Empty before a numeric factorization.
  std::vector<double> path_entries() const;
  // x <- A^-1 x, for nrhs right-hand sides stored one after the other (n each). A single one
  // with a simplicial factor of kSubtreeSolveFromEntries entries or more is solved by subtrees of
  // the elimination tree (subtree_solve.hpp), on two threads when set_threads asks for them; with
  // a supernodal one too where split_supernodal_solves() asked for it (supernodal_solve.hpp; the
  // sparse path's H_P: a body's supernodal factor keeps CHOLMOD's solve).
  void solve(double *x, int nrhs = 1) const;
  // Threads a solve may use (1: the calling thread alone); the answer does not depend on it.
  void set_threads(int threads) { threads_ = threads; }
  void split_supernodal_solves() { split_supernodal_ = true; }
  static constexpr double kSubtreeSolveFromEntries = 2e5;
  // Halves from as many unknowns as two bodies of the size from which MC_OPTION_THREADS = 0 gives
  // two threads (30000 each): below, one thread gains nothing from them and pays their fill (the
  // strips at 1001 and 2001 contact nodes: 7 to 10 % more entries, analysis and factorization
  // 30 to 100 % slower on one thread). The order does not depend on the threads: the answer is the
  // same whatever MC_OPTION_THREADS.
  static constexpr int kHalvesFromUnknowns = 60000;
  // One split only: deeper dissection (3 to 10 levels of level separators, tried on the strips)
  // gave separators dense enough that CHOLMOD chose a supernodal factor, which is not modified in
  // place: a load step then cost 3 to 4 times as much (docs/notes/interface-solver.md). Halves only for a slender matrix, whose separator is at most this many unknowns (the
  // strips': 65 at any length): its factor stays simplicial (CHOLMOD's switch: 40 flops per entry).
  // A wider one keeps AMD's order (Westergaard's block: a separator of 232, Hertz: 797; in halves
  // the Westergaard factor, supernodal, grew 6 % and its factorizations took 28 % longer).
  static constexpr long kLargestSeparator = 100;
  // The share of the factor's entries outside the two halves its solves are split into (the
  // serial part), or -1 where its solves are not split (no plan yet, or none worth it).
  double split_top_share() const;
  // Factorizations since the analysis whose halves ran on two threads (factorize_ordered).
  int split_factorizations() const { return split_factorizations_; }
  // The two halves of a solve, A = P^T L L^T P: y = L^-1 P b (y in the factor's order) and
  // x = P^T L^-T z. The contact solve works between them: the interface unknowns are the
  // trailing ones (from interface_start()), where L^-1 P B^T is the only nonzero part.
  void forward(const double *b, double *y) const;
  void backward(const double *z, double *x) const;
  int interface_start() const;
  // The trailing block L_GG (dense, column-major, |interface|^2, lower triangular) in the
  // factor's order; order[k] is the position in the interface list (given to analyze) of
  // the factor's k-th interface unknown.
  std::vector<double> interface_factor(std::vector<int> &order) const;

  // After factorize threw MC_ERROR_SINGULAR: the unknown (in a's numbering) whose pivot failed.
  int failed_unknown() const { return failed_unknown_; }
  long factor_nnz() const;
  // CHOLMOD's count of the numeric factorization's floating-point operations, from the analysis.
  double analysis_flops() const;
  int n() const { return n_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int n_ = 0;
  int threads_ = 1;
  bool split_supernodal_ = false;
  int split_factorizations_ = 0;
  bool analyzed_ = false;
  bool solve_by_subtrees(double *x) const;
  std::vector<int> order_in_halves(const SymmetricCsc &a, const std::vector<int> &part);
  bool analyze_in_halves(const SymmetricCsc &a);
  bool solve_supernodal_by_subtrees(double *x) const;
  void in_two_threads(const std::function<void()> &main, const std::function<void()> &second) const;
  void factorize_rows(cholmod_sparse_struct &upper);
  void report_failed_pivot(int n);
  std::vector<int> changed_in_factor_order(const std::vector<int> &changed);
  int failed_unknown_ = -1;
};

}  // namespace mc
