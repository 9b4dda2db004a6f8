// A square sparse system factorized by UMFPACK (LU with partial pivoting): the active-set
// systems of the condensed interface problem when its operator S is stored by blocks
// (block_sparse_operator.hpp): the frictional one (nonsymmetric for Coulomb, friction_qp.cpp),
// and the frictionless KKT system (symmetric indefinite, dual_qp.cpp) where its faster route
// through CHOLMOD finds S_AA + rho G_A G_A^T not positive definite. Their dense counterparts
// are LAPACK's dsysv and dgetrf; pivoting keeps the saddle-point systems and a singular S_AA
// (a fully prescribed body, dual_qp.cpp) solvable as they are there. Each instance owns its
// factor: no state is shared.
#pragma once
#include <vector>

namespace mc {

class SparseLu {
public:
  SparseLu() = default;
  ~SparseLu();
  SparseLu(const SparseLu &) = delete;
  SparseLu &operator=(const SparseLu &) = delete;

  // The n x n matrix as triplets (row, column, value; duplicates summed). Returns false if a
  // pivot is exactly zero (as dsysv's and dgetrf's info > 0); throws MC_ERROR_MEMORY when
  // UMFPACK runs out of memory.
  bool factorize(int n, const std::vector<long> &row, const std::vector<long> &column, const std::vector<double> &value);
  // x = A^-1 b.
  void solve(const double *b, double *x) const;
  // An estimate of the 1-norm reciprocal condition number, as LAPACK's dgecon computes it for
  // a dense factor (Higham's estimator, here with solves by the factor and its transpose).
  double reciprocal_condition() const;
  int n() const { return n_; }

private:
  void free();
  void solve(int system, const double *b, double *x) const;
  int n_ = 0;
  std::vector<long> start_, index_;  // the matrix, compressed columns
  std::vector<double> value_;
  void *numeric_ = nullptr;
};

}  // namespace mc
