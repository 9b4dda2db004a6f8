// A small dense square system factorized by LAPACK (dgetrf, partial pivoting) and accepted only
// when well conditioned: the reciprocal 1-norm condition number that dgecon estimates above a
// threshold the caller chooses (a fit of rigid motions, the Schur block of a low-rank factor
// update, the frictional active-set system). Each of those has a fallback for a rejected
// system, so a nearly singular one is never solved to round-off.
#pragma once
#include <vector>

namespace mc {

struct DenseLu {
  int n = 0;
  std::vector<double> lu;  // the factors, column-major (dgetrf's)
  std::vector<int> pivots;
  double rcond = 0;        // dgecon's estimate

  // Factorizes the n x n column-major matrix a (taken). False if a pivot is zero or the
  // estimated reciprocal condition is not above min_rcond.
  bool factorize(int n, std::vector<double> a, double min_rcond);
  // b = A^-1 b for `columns` right-hand sides of length n (column-major). False if LAPACK fails.
  bool solve(double *b, int columns = 1) const;
};

}  // namespace mc
