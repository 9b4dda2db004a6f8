// Sparse SPD factorization with CHOLMOD (supernodal LL^T). Each instance owns its own
// cholmod_common: no state is shared between models.
//
// Unknowns named "interface" are ordered last. Then the trailing block L_GG of the factor
// gives (K^-1)_GG = L_GG^-T L_GG^-1, which is all the contact solve needs to form the
// interface operator S = B K^-1 B^T without one sparse solve per contact node
// (design note "Solving the QP fast").
#pragma once
#include "bodies/assembly.hpp"
#include <memory>
#include <vector>

namespace mc {

class SparseCholesky {
public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky &) = delete;
  SparseCholesky &operator=(const SparseCholesky &) = delete;

  // Ordering and symbolic factorization. ordering: MC_ORDERING_*.
  void analyze(const SymmetricCsc &a, const std::vector<int> &interface, int ordering);
  // Frees the analysis and the factor (analyze starts afresh).
  void release();
  bool analyzed() const;
  // Numeric factorization; throws MC_ERROR_SINGULAR if a is not positive definite.
  void factorize(const SymmetricCsc &a);
  // x <- A^-1 x, for nrhs right-hand sides stored one after the other (n each).
  void solve(double *x, int nrhs = 1) const;
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
  bool analyzed_ = false;
  int failed_unknown_ = -1;
};

}  // namespace mc
