#include "support/blas_threads.hpp"

// OpenBLAS's own controls (cblas.h declares them too; only these are needed).
extern "C" {
int openblas_get_parallel(void);  // 0 sequential, 1 pthread build, 2 OpenMP build
int openblas_get_num_threads(void);
void openblas_set_num_threads(int num_threads);
#ifdef MC_SERIAL_CHOLMOD_OPENMP
// libgomp's per-thread controls (linked for CHOLMOD's sake, see sparse_cholesky.cpp).
int omp_get_max_threads(void);
void omp_set_num_threads(int num_threads);
#endif
}

namespace mc {

namespace {
enum { kPthreadBuild = 1, kOpenMpBuild = 2 };
}

BlasPoolShare::BlasPoolShare(int per_body) {
  if (per_body <= 0 || openblas_get_parallel() != kPthreadBuild) return;
  const int pool = openblas_get_num_threads();
  if (pool <= per_body) return;  // the host already asked for no more than the share
  openblas_set_num_threads(per_body);
  set_ = per_body, restore_ = pool;
}

BlasPoolShare::~BlasPoolShare() {
  if (restore_ > 0 && openblas_get_num_threads() == set_) openblas_set_num_threads(restore_);
}

#ifdef MC_SERIAL_CHOLMOD_OPENMP
BlasThreadsOfThisThread::BlasThreadsOfThisThread(int threads) {
  if (threads <= 0 || openblas_get_parallel() != kOpenMpBuild) return;
  restore_ = omp_get_max_threads();
  omp_set_num_threads(threads);
}

BlasThreadsOfThisThread::~BlasThreadsOfThisThread() {
  if (restore_ > 0) omp_set_num_threads(restore_);
}
#else
// Without libgomp's controls the OpenMP build's teams cannot be sized per thread; the pthread
// build is handled by BlasPoolShare.
BlasThreadsOfThisThread::BlasThreadsOfThisThread(int) {}
BlasThreadsOfThisThread::~BlasThreadsOfThisThread() {}
#endif

}  // namespace mc
