// SparseCholesky's insides, shared by its two files: sparse_cholesky.cpp (the analysis, the
// factorization, the modifications, the solves) and sparse_cholesky_halves.cpp (a slender
// matrix in two halves: its order, and its factorizations and solves on two threads).
#pragma once
#include "linalg/sparse_cholesky.hpp"
#include "linalg/subtree_solve.hpp"
#include "linalg/supernodal_solve.hpp"
#include "support/error.hpp"
#include <cholmod.h>
#include <cstring>
#include <memory>
#include <vector>

#ifdef MC_SERIAL_CHOLMOD_OPENMP
// libgomp's per-thread controls (CHOLMOD links libgomp; declared here so that no OpenMP
// compiler flag is needed).
extern "C" {
int omp_get_dynamic(void);
void omp_set_dynamic(int dynamic_threads);
int omp_get_max_threads(void);
void omp_set_num_threads(int num_threads);
}
#endif

namespace mc {

// Debian's CHOLMOD runs the zeroing and scatter loops of its supernodal factorization with a
// fixed OpenMP team (CHOLMOD_OMP_NUM_THREADS = 4, a num_threads clause), between the BLAS
// calls that OpenBLAS already spreads over every core. The two thread pools then compete for
// the same cores, and OpenMP's spinning workers starve OpenBLAS's (docs/benchmarks.md,
// "Threads": 1.6x slower on 2 cores, 30x with OMP_THREAD_LIMIT=2). While CHOLMOD runs, the
// calling thread's OpenMP controls ask for one thread: with dyn-var true, a num_threads clause
// is bounded by nthreads-var = 1. Both are the calling thread's own settings (OpenMP data-
// environment ICVs), restored on return: no global state, and the host's own OpenMP is untouched.
class CholmodWithoutOpenMpTeam {
public:
#ifdef MC_SERIAL_CHOLMOD_OPENMP
  CholmodWithoutOpenMpTeam() : dynamic_(omp_get_dynamic()), threads_(omp_get_max_threads()) {
    omp_set_dynamic(1);
    omp_set_num_threads(1);
  }
  ~CholmodWithoutOpenMpTeam() {
    omp_set_num_threads(threads_);
    omp_set_dynamic(dynamic_);
  }

private:
  int dynamic_, threads_;
#else
  CholmodWithoutOpenMpTeam() {}  // (user-provided: a guard object, not an unused variable)
  ~CholmodWithoutOpenMpTeam() {}
#endif
};

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor *factor = nullptr;
  cholmod_factor *symbolic = nullptr;  // a simplicial analysis (keep_aside)
  cholmod_factor *aside = nullptr;     // keep_aside's second factor
  std::vector<int> interface;  // original indices, in the caller's order
  // For modify, made at its first call after an analysis (every factor of the analysis shares
  // them): the inverse of the factor's permutation, the elimination tree (each column's parent,
  // -1 at a root), and a marker per column.
  std::vector<int> inverse_perm, parent;
  std::vector<char> on_path;
  // The columns of each factor (the one at hand, the one aside) modified in place since its
  // numeric factorization and not computed afresh since (refactorize_paths), and their count:
  // where none is, the factor is as a factorization leaves it.
  struct Modified {
    std::vector<char> column;
    long count = 0;
    void clear() { column.clear(), count = 0; }
    void mark(int j, int n) {
      if (column.empty()) column.assign(size_t(n), 0);
      if (!column[size_t(j)]) column[size_t(j)] = 1, ++count;
    }
    void unmark(int j) {
      if (!column.empty() && column[size_t(j)]) column[size_t(j)] = 0, --count;
    }
  } modified, modified_aside;
  // The split of a simplicial factor's solves over two threads, made at the first solve after an
  // analysis (subtree_solve.hpp); none (plan_made, no plan) where it would not pay.
  std::unique_ptr<SubtreeSolvePlan> plan;
  bool plan_made = false;
  // The same for a supernodal factor (supernodal_solve.hpp), made at its first solve with two
  // threads to split it over.
  std::unique_ptr<SupernodalSolvePlan> super_plan;
  bool super_plan_made = false;
  // The symbolic factor was made by analyze_in_halves, not by cholmod_analyze: its column counts
  // are checked at each factorization.
  bool counts_made_here = false;
  // The workspace of the second thread's rows in a factorization by halves (its own: CHOLMOD's
  // workspace is per common), freed after each.
  cholmod_common second;
  void forget_tree() {
    super_plan.reset(), super_plan_made = false;
    inverse_perm.clear(), parent.clear(), on_path.clear(), plan.reset(), plan_made = false;
    modified.clear(), modified_aside.clear();
  }
  // The elimination tree of a simplicial numeric factor: each column's parent is its smallest
  // off-diagonal row. Every factor of one analysis shares it (their patterns are the analysis's:
  // an update or downdate of a row whose terms the analysed pattern holds adds no fill).
  // The inverse of the factor's permutation (every factor of one analysis shares it).
  const std::vector<int> &inverse_permutation(int n) {
    if (inverse_perm.empty()) {
      const int *perm = static_cast<const int *>(factor->Perm);
      inverse_perm.resize(static_cast<size_t>(n));
      for (int i = 0; i < n; ++i) inverse_perm[size_t(perm[i])] = i;
    }
    return inverse_perm;
  }
  const std::vector<int> &elimination_tree() {
    if (!parent.empty()) return parent;
    const int n = int(factor->n);
    const int *lp = static_cast<const int *>(factor->p), *li = static_cast<const int *>(factor->i);
    const int *lnz = static_cast<const int *>(factor->nz);
    parent.assign(static_cast<size_t>(n), -1);
    for (int j = 0; j < n; ++j)
      for (int q = lp[j] + 1; q < lp[j] + lnz[j]; ++q)
        if (parent[size_t(j)] < 0 || li[q] < parent[size_t(j)]) parent[size_t(j)] = li[q];
    return parent;
  }
  Impl() {
    cholmod_start(&common);
    common.print = 0;  // the library never prints; errors are reported through statuses
    common.error_handler = nullptr;
    common.supernodal = CHOLMOD_SUPERNODAL;
    cholmod_start(&second);
    second.print = 0;
    second.error_handler = nullptr;
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    if (symbolic) cholmod_free_factor(&symbolic, &common);
    if (aside) cholmod_free_factor(&aside, &common);
    cholmod_finish(&common);
    cholmod_finish(&second);
  }
  // A cholmod_sparse view (no copy) of the upper triangle.
  cholmod_sparse view(const SymmetricCsc &a) {
    cholmod_sparse s;
    std::memset(&s, 0, sizeof s);
    s.nrow = s.ncol = size_t(a.n);
    s.nzmax = a.values.size();
    s.p = const_cast<int *>(a.colptr.data());
    s.i = const_cast<int *>(a.rows.data());
    s.x = const_cast<double *>(a.values.data());
    s.stype = 1;
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }
  void check(const char *what) {
    if (common.status == CHOLMOD_OUT_OF_MEMORY) fail(MC_ERROR_MEMORY, "CHOLMOD ran out of memory in %s", what);
    if (common.status == CHOLMOD_TOO_LARGE)
      fail(MC_ERROR_MEMORY, "CHOLMOD in %s: the factor is too large for its 32-bit indices", what);
    if (common.status < CHOLMOD_OK) fail(MC_ERROR_INTERNAL, "CHOLMOD failed in %s (status %d)", what, common.status);
  }
};

}  // namespace mc
