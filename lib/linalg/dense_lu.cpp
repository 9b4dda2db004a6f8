#include "linalg/dense_lu.hpp"
#include "support/lapack.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

bool DenseLu::factorize(int size, std::vector<double> a, double min_rcond) {
  n = size, lu = std::move(a), rcond = 0;
  double norm = 0;  // the 1-norm, for the condition estimate
  for (int c = 0; c < n; ++c) {
    double sum = 0;
    for (int r = 0; r < n; ++r) sum += std::fabs(lu[size_t(c) * n + r]);
    norm = std::max(norm, sum);
  }
  pivots.assign(n, 0);
  int info = 0;
  dgetrf_(&n, &n, lu.data(), &n, pivots.data(), &info);
  if (info != 0) return false;
  std::vector<double> work(4 * size_t(n));
  std::vector<int> iwork(n);
  dgecon_("1", &n, lu.data(), &n, &norm, &rcond, work.data(), iwork.data(), &info);
  return info == 0 && rcond > min_rcond;
}

bool DenseLu::solve(double *b, int columns) const {
  int info = 0;
  dgetrs_("N", &n, &columns, lu.data(), &n, pivots.data(), b, &n, &info);
  return info == 0;
}

}  // namespace mc
