#include "linalg/sparse_lu.hpp"
#include "support/error.hpp"
#include "support/lapack.hpp"
#include <algorithm>
#include <cmath>
#include <umfpack.h>

namespace mc {

namespace {
void check_status(long status, const char *what) {
  if (status == UMFPACK_ERROR_out_of_memory) fail(MC_ERROR_MEMORY, "UMFPACK ran out of memory in %s", what);
  if (status < 0) fail(MC_ERROR_INTERNAL, "UMFPACK failed in %s (status %ld)", what, status);
}
}  // namespace

SparseLu::~SparseLu() { free(); }

void SparseLu::free() {
  if (numeric_) umfpack_dl_free_numeric(&numeric_);
  numeric_ = nullptr;
}

bool SparseLu::factorize(int n, const std::vector<long> &row, const std::vector<long> &column,
                         const std::vector<double> &value) {
  free();
  n_ = n;
  if (n == 0) return true;
  const long nz = long(value.size());
  start_.assign(size_t(n) + 1, 0), index_.assign(std::max(nz, 1L), 0), value_.assign(std::max(nz, 1L), 0.0);
  check_status(umfpack_dl_triplet_to_col(n, n, nz, row.data(), column.data(), value.data(), start_.data(),
                                         index_.data(), value_.data(), nullptr),
               "assembly");
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_dl_defaults(control);
  void *symbolic = nullptr;
  long status = umfpack_dl_symbolic(n, n, start_.data(), index_.data(), value_.data(), &symbolic, control, info);
  check_status(status, "the symbolic analysis");
  status = umfpack_dl_numeric(start_.data(), index_.data(), value_.data(), symbolic, &numeric_, control, info);
  umfpack_dl_free_symbolic(&symbolic);
  check_status(status, "the factorization");
  return status != UMFPACK_WARNING_singular_matrix;
}

void SparseLu::solve(int system, const double *b, double *x) const {
  if (n_ == 0) return;
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_dl_defaults(control);
  check_status(umfpack_dl_solve(system, start_.data(), index_.data(), value_.data(), x, b, numeric_, control, info),
               "a solve");
}

void SparseLu::solve(const double *b, double *x) const { solve(UMFPACK_A, b, x); }

double SparseLu::reciprocal_condition() const {
  if (n_ == 0) return 1;
  double norm = 0;  // ||A||_1
  for (int c = 0; c < n_; ++c) {
    double sum = 0;
    for (long p = start_[c]; p < start_[c + 1]; ++p) sum += std::fabs(value_[p]);
    norm = std::max(norm, sum);
  }
  std::vector<double> v(n_), x(n_), y(n_);
  std::vector<int> sign(n_);
  int kase = 0, isave[3] = {0, 0, 0};
  double estimate = 0;  // of ||A^-1||_1
  for (;;) {
    dlacn2_(&n_, v.data(), x.data(), sign.data(), &estimate, &kase, isave);
    if (kase == 0) break;
    solve(kase == 1 ? UMFPACK_A : UMFPACK_At, x.data(), y.data());
    x.swap(y);
  }
  return norm > 0 && estimate > 0 ? 1 / (norm * estimate) : 0;
}

}  // namespace mc
