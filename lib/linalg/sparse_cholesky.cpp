#include "linalg/sparse_cholesky.hpp"
#include "linalg/matrix_graph.hpp"
#include "linalg/subtree_solve.hpp"
#include "support/error.hpp"
#include <cholmod.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <system_error>
#include <thread>
#include <vector>
#include <pthread.h>
#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

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

namespace {
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

// Asks the kernel to back [data, data + bytes) with memory now, in one call, instead of one page
// fault per 4 KiB page when the factorization first writes it: the supernodal factor of a body
// with 2.5*10^5 unknowns is about 200 MB of fresh pages (50 thousand faults), and on these
// machines a 4 KiB fault costs about 2.6 microseconds against 1.7 a page populated in one call
// (docs/benchmarks.md, "Plain elasticity"). MADV_POPULATE_WRITE (Linux 5.14) faults the pages in
// as a write would and leaves their contents alone; where it is not known (older kernels:
// EINVAL) nothing happens and the pages fault in as before.
void populate_pages(void *data, size_t bytes) {
#ifdef __linux__
  constexpr int populate_write = 23;  // MADV_POPULATE_WRITE; older headers do not name it
  const long page_size = sysconf(_SC_PAGESIZE);
  if (page_size <= 0) return;
  const uintptr_t page = uintptr_t(page_size);
  const uintptr_t first = (uintptr_t(data) + page - 1) & ~(page - 1);
  const uintptr_t end = (uintptr_t(data) + bytes) & ~(page - 1);
  if (end > first) (void)madvise(reinterpret_cast<void *>(first), end - first, populate_write);
#else
  (void)data, (void)bytes;
#endif
}
}  // namespace

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
  // The split of a simplicial factor's solves over two threads, made at the first solve after an
  // analysis (subtree_solve.hpp); none (plan_made, no plan) where it would not pay.
  std::unique_ptr<SubtreeSolvePlan> plan;
  bool plan_made = false;
  // The workspace of the second thread's rows in a factorization by halves (its own: CHOLMOD's
  // workspace is per common), freed after each.
  cholmod_common second;
  void forget_tree() { inverse_perm.clear(), parent.clear(), on_path.clear(), plan.reset(), plan_made = false; }
  // The elimination tree of a simplicial numeric factor: each column's parent is its smallest
  // off-diagonal row. Every factor of one analysis shares it (their patterns are the analysis's:
  // an update or downdate of a row whose terms the analysed pattern holds adds no fill).
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

SparseCholesky::SparseCholesky() : impl_(new Impl) {}
SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze(const SymmetricCsc &a, const std::vector<int> &interface, int ordering, bool in_halves) {
  Impl &d = *impl_;
  CholmodWithoutOpenMpTeam serial_openmp;
  if (d.factor) cholmod_free_factor(&d.factor, &d.common);
  if (d.symbolic) cholmod_free_factor(&d.symbolic, &d.common);
  if (d.aside) cholmod_free_factor(&d.aside, &d.common);
  d.forget_tree();
  n_ = a.n;
  analyzed_ = true;
  split_factorizations_ = 0;
  d.interface = interface;
  if (n_ == 0) return;  // every unknown prescribed (a fully supported body): nothing to factor
  cholmod_sparse s = d.view(a);
  // Without an interface block, CHOLMOD's own choice between a simplicial and a supernodal
  // factor (supernodal from 40 flops per entry of L: supernodes big enough for the BLAS): a
  // slender body's factor, or the sparse interface path's H_P of two strips, has supernodes of
  // some 9 columns, where the BLAS calls cost more than their arithmetic (H_P of the strips at
  // 4001 contact nodes: 0.225 s supernodal, 0.129 s simplicial LL^T; docs/notes/interface-
  // solver.md). LL^T either way: forward() and backward() are L's own solves. The condensed
  // path's factors (interface last) stay supernodal: interface_factor reads their trailing block.
  d.common.supernodal = interface.empty() ? CHOLMOD_AUTO : CHOLMOD_SUPERNODAL;
  d.common.final_ll = 1;
  // In halves where the solves will be split (kHalvesFromUnknowns): a small matrix keeps AMD's
  // ordering, and its round-off, as before.
  if (interface.empty() && in_halves && ordering == MC_ORDERING_AUTO && a.n >= kHalvesFromUnknowns) {
    const std::vector<int> part = split_in_two(graph_of(a));
    const long separator = std::count_if(part.begin(), part.end(), [](int side) { return side == 2; });
    if (!part.empty() && separator <= kLargestSeparator) {
      const std::vector<int> perm = order_in_halves(a, part);
      d.common.nmethods = 1;
      d.common.method[0].ordering = CHOLMOD_GIVEN;
      d.common.postorder = 1;
      // Simplicial: the halves are for a simplicial factor (split solves and factorizations, and
      // modified in place); a slender matrix's fronts are small, about CHOLMOD's own switch (39 to
      // 45 flops per entry on the strips from 1001 to 4001 contact nodes in this order).
      d.common.supernodal = CHOLMOD_SIMPLICIAL;
      d.factor = cholmod_analyze_p(&s, const_cast<int *>(perm.data()), nullptr, 0, &d.common);
      d.check("analyze");
      // The split of the solves (and factorizations) made now, from the analysis: the elimination
      // tree of the ordered matrix and the column counts.
      d.plan_made = true;
      if (!d.factor->is_super && double(d.common.lnz) >= kSubtreeSolveFromEntries) {
        const int *count = static_cast<const int *>(d.factor->ColCount);
        const std::vector<double> entries(count, count + n_);
        auto plan = std::make_unique<SubtreeSolvePlan>(elimination_tree(a, static_cast<const int *>(d.factor->Perm)), entries);
        if (plan->worthwhile()) d.plan = std::move(plan);
      }
      return;
    }
  }
  if (interface.empty()) {
    d.common.nmethods = 1;
    d.common.method[0].ordering = ordering == MC_ORDERING_METIS ? CHOLMOD_METIS : CHOLMOD_AMD;
    d.common.postorder = 1;
    d.factor = cholmod_analyze(&s, &d.common);
    d.check("analyze");
    return;
  }
  // Interface last: a constrained minimum-degree ordering (CAMD) when AMD is asked, or METIS
  // with the interface moved to the end; no postordering, which could move interior unknowns
  // behind interface ones.
  std::vector<int> perm(a.n);
  std::vector<char> is_interface(a.n, 0);
  // The list is the caller's (interface_factor reads the factor's trailing block in its order):
  // an unknown outside the matrix or listed twice is a defect upstream, refused before CAMD sees it.
  const int n_interface = int(interface.size());
  for (int g : interface) {
    if (g < 0 || g >= a.n) fail(MC_ERROR_INTERNAL, "interface unknown %d outside the %d unknowns of the analysis", g, a.n);
    if (is_interface[g]) fail(MC_ERROR_INTERNAL, "interface unknown %d listed twice", g);
    is_interface[g] = 1;
  }
  if (ordering == MC_ORDERING_METIS) {
    std::vector<int> metis(a.n);
    cholmod_metis(&s, nullptr, 0, 1, metis.data(), &d.common);
    d.check("METIS ordering");
    int k = 0;
    for (int i : metis) if (!is_interface[i]) perm[k++] = i;
    for (int i : metis) if (is_interface[i]) perm[k++] = i;
  } else {
    // CAMD's constraint sets must lie in 0..n-1 (it indexes arrays of n by them): a body whose
    // every unknown is on the interface (n = 1 with set 1 read past its arrays: a fuzz finding,
    // docs/robustness.md) needs no constraint, so all go in set 0.
    std::vector<int> member(a.n, 0);
    if (n_interface < a.n)
      for (int i = 0; i < a.n; ++i) member[i] = is_interface[i];
    cholmod_camd(&s, nullptr, 0, member.data(), perm.data(), &d.common);
    d.check("CAMD ordering");
  }
  d.common.nmethods = 1;
  d.common.method[0].ordering = CHOLMOD_GIVEN;
  d.common.postorder = 0;
  d.factor = cholmod_analyze_p(&s, perm.data(), nullptr, 0, &d.common);
  d.check("analyze");
  const int *final_perm = static_cast<const int *>(d.factor->Perm);
  for (int k = a.n - n_interface; k < a.n; ++k)
    if (!is_interface[final_perm[k]])
      fail(MC_ERROR_INTERNAL, "the ordering did not keep the %d interface unknowns last", n_interface);
}

// The order of a matrix split in two halves (part[v]: 0, 1, or 2 for the separator): each half's
// unknowns by AMD on the half alone (no entry joins the halves: their orders are independent, the
// second on a second thread where set_threads allows), then the separator's. CAMD on the whole
// matrix with the three parts as constraint sets gave the same factor size and took 3 to 4 times
// AMD's time on the strips.
std::vector<int> SparseCholesky::order_in_halves(const SymmetricCsc &a, const std::vector<int> &part) {
  Impl &d = *impl_;
  const int n = a.n;
  std::vector<int> local(static_cast<size_t>(n)), members[3];
  for (int v = 0; v < n; ++v) local[size_t(v)] = int(members[part[size_t(v)]].size()), members[part[size_t(v)]].push_back(v);
  std::vector<int> order[2];
  auto order_half = [&](int h, cholmod_common *common) {
    // The half's own matrix: the upper triangle's pattern on its unknowns, in their order.
    const std::vector<int> &m = members[h];
    std::vector<int> colptr(m.size() + 1, 0), rows;
    for (size_t c = 0; c < m.size(); ++c) {
      const int j = m[c];
      for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
        if (part[size_t(a.rows[p])] == h) rows.push_back(local[size_t(a.rows[p])]);
      colptr[c + 1] = int(rows.size());
    }
    cholmod_sparse half;
    std::memset(&half, 0, sizeof half);
    half.nrow = half.ncol = m.size();
    half.nzmax = std::max<size_t>(rows.size(), 1);
    half.p = colptr.data(), half.i = rows.data();
    half.stype = 1, half.itype = CHOLMOD_INT, half.xtype = CHOLMOD_PATTERN, half.dtype = CHOLMOD_DOUBLE;
    half.sorted = 1, half.packed = 1;
    order[h].resize(m.size());
    cholmod_amd(&half, nullptr, 0, order[h].data(), common);
  };
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    bool ran = false;
    if (threads_ > 1) try {
        std::thread second([&] {
          CholmodWithoutOpenMpTeam its_own;
          order_half(1, &d.second);
        });
        pthread_setname_np(second.native_handle(), "mc-body2");
        order_half(0, &d.common);
        second.join();
        ran = true;
      } catch (const std::system_error &) {
      }
    if (!ran) order_half(0, &d.common), order_half(1, &d.second);
  }
  cholmod_free_work(&d.second);
  if (d.second.status == CHOLMOD_OUT_OF_MEMORY) d.common.status = CHOLMOD_OUT_OF_MEMORY;
  d.check("AMD ordering");
  std::vector<int> perm;
  perm.reserve(static_cast<size_t>(n));
  for (int h = 0; h < 2; ++h)
    for (int k : order[h]) perm.push_back(members[h][size_t(k)]);
  perm.insert(perm.end(), members[2].begin(), members[2].end());
  return perm;
}

bool SparseCholesky::analyzed() const { return analyzed_; }

void SparseCholesky::release() {
  Impl &d = *impl_;
  if (d.factor) cholmod_free_factor(&d.factor, &d.common);
  if (d.symbolic) cholmod_free_factor(&d.symbolic, &d.common);
  if (d.aside) cholmod_free_factor(&d.aside, &d.common);
  cholmod_free_work(&d.common);  // the workspace CHOLMOD keeps between calls (a few n-sized arrays)
  d.interface.clear();
  d.forget_tree();
  n_ = 0;
  analyzed_ = false;
}

void SparseCholesky::factorize(const SymmetricCsc &a) {
  Impl &d = *impl_;
  failed_unknown_ = -1;
  if (n_ == 0) return;
  if (!d.factor) fail(MC_ERROR_INTERNAL, "factorize before analyze");
  cholmod_sparse s = d.view(a);
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    if (d.factor->is_super && d.factor->xtype == CHOLMOD_PATTERN) {
      // The numeric part allocated here, as cholmod_super_numeric would (same arguments), so
      // that its pages can be populated before the factorization writes them.
      cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, d.factor, &d.common);
      d.check("allocating the factor");
      populate_pages(d.factor->x, d.factor->xsize * sizeof(double));
    }
    if (!factorize_by_subtrees(s)) cholmod_factorize(&s, d.factor, &d.common);
  }
  if (d.common.status == CHOLMOD_NOT_POSDEF) {
    const int *perm = static_cast<const int *>(d.factor->Perm);
    const int minor = int(d.factor->minor);
    failed_unknown_ = perm && minor < a.n ? perm[minor] : minor;
  }
  if (d.common.status == CHOLMOD_NOT_POSDEF)
    fail(MC_ERROR_SINGULAR,
         "the stiffness matrix is not positive definite (pivot %d of %d): a part of the body can move "
         "rigidly, or a material is not positive definite",
         int(d.factor->minor), a.n);
  d.check("factorize");
}

// A simplicial factorization by rows (cholmod_rowfac, as cholmod_factorize runs it), the two halves'
// rows at once: a row of L is computed from the rows of its descendants in the elimination tree
// alone, so each half's subtrees need nothing of the other's, and the top's rows follow. Every row
// is computed as cholmod_factorize computes it: the same factor to the bit. Only where the solves
// are split (the plan's ranges) and two threads may run; false: nothing done.
bool SparseCholesky::factorize_by_subtrees(cholmod_sparse &a) {
  Impl &d = *impl_;
  cholmod_factor *f = d.factor;
  if (threads_ < 2 || !d.plan || f->is_super) return false;
  // S = triu(A(p, p)), as cholmod_factorize_p forms it for cholmod_rowfac.
  cholmod_sparse *lower = cholmod_ptranspose(&a, 2, static_cast<int *>(f->Perm), nullptr, 0, &d.common);
  d.check("permuting the matrix");
  cholmod_sparse *upper = cholmod_ptranspose(lower, 2, nullptr, nullptr, 0, &d.common);
  cholmod_free_sparse(&lower, &d.common);
  d.check("permuting the matrix");
  struct Freed {
    cholmod_sparse *&matrix;
    Impl &d;
    ~Freed() {
      cholmod_free_sparse(&matrix, &d.common);
      cholmod_free_work(&d.second);
    }
  } freed{upper, d};
  const int n = n_;
  if (f->xtype == CHOLMOD_PATTERN) {
    // Numeric, each column its exact size (as cholmod_factorize_p allocates a packed factor).
    const size_t grow2 = d.common.grow2;
    d.common.grow2 = 0;
    cholmod_change_factor(CHOLMOD_REAL, 1, 0, 0, 1, f, &d.common);
    d.common.grow2 = grow2;
    d.check("allocating the factor");
  } else {
    // A refactorization: every column emptied to its diagonal, as cholmod_rowfac does for all rows.
    f->minor = size_t(n);
    int *lnz = static_cast<int *>(f->nz);
    for (int k = 0; k < n; ++k) lnz[k] = 1;
  }
  f->is_ll = 1;
  // Half 1's workspace, allocated here: from the calling thread's memory (a first allocation on
  // a new thread would open a malloc arena of its own, resident memory the solve does not need).
  cholmod_allocate_work(size_t(n), size_t(n), size_t(n), &d.second);
  if (d.second.status == CHOLMOD_OUT_OF_MEMORY) d.common.status = CHOLMOD_OUT_OF_MEMORY;
  d.check("allocating a workspace");
  double beta[2] = {0, 0};
  // Half 1 writes through a copy of the factor's header: the same arrays, its own `minor` (the row
  // where a pivot failed), merged below.
  cholmod_factor half_one = *f;
  auto rows_of = [&](int part, cholmod_factor *factor, cholmod_common *common) {
    for (const SubtreeSolvePlan::Range &r : d.plan->ranges(part))
      cholmod_rowfac(upper, nullptr, beta, size_t(r.first), size_t(r.second), factor, common);
  };
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    bool ran = false;
    try {
      std::thread second([&] {
        CholmodWithoutOpenMpTeam its_own;
        rows_of(1, &half_one, &d.second);
      });
      pthread_setname_np(second.native_handle(), "mc-body2");
      rows_of(0, f, &d.common);
      second.join();
      ran = true;
    } catch (const std::system_error &) {
    }
    if (!ran) rows_of(0, f, &d.common), rows_of(1, &half_one, &d.second);
    f->minor = std::min(f->minor, half_one.minor);
    cholmod_free_work(&d.second);  // (before the top's rows: the solve's peak memory is near here)
    if (f->minor == size_t(n)) rows_of(2, f, &d.common);
  }
  if (d.second.status == CHOLMOD_OUT_OF_MEMORY) d.common.status = CHOLMOD_OUT_OF_MEMORY;
  d.check("factorize");
  if (f->minor < size_t(n)) {
    d.common.status = CHOLMOD_NOT_POSDEF;
    return true;
  }
  // Left as cholmod_factorize leaves it (Common's final_pack and final_monotonic), the permuted
  // matrix freed first (packing moves the factor).
  cholmod_free_sparse(&upper, &d.common);
  cholmod_change_factor(CHOLMOD_REAL, 1, 0, d.common.final_pack, d.common.final_monotonic, f, &d.common);
  d.check("factorize");
  ++split_factorizations_;
  return true;
}

bool SparseCholesky::can_keep_aside() const {
  const cholmod_factor *f = impl_->factor;
  return n_ > 0 && f && !f->is_super && f->xtype != CHOLMOD_PATTERN;
}

void SparseCholesky::keep_aside() {
  Impl &d = *impl_;
  if (!can_keep_aside()) fail(MC_ERROR_INTERNAL, "keep_aside without a simplicial numeric factor");
  if (!d.symbolic) {
    // The analysis, from the factor: a simplicial symbolic factor is its permutation and column
    // counts (made when first needed: two arrays of n that a solve without an aside never holds).
    d.symbolic = cholmod_allocate_factor(size_t(n_), &d.common);
    d.check("allocating a factor");
    std::memcpy(d.symbolic->Perm, d.factor->Perm, sizeof(int) * size_t(n_));
    std::memcpy(d.symbolic->ColCount, d.factor->ColCount, sizeof(int) * size_t(n_));
    d.symbolic->ordering = d.factor->ordering;
  }
  if (d.aside) cholmod_free_factor(&d.aside, &d.common);
  d.aside = d.factor;
  d.factor = cholmod_copy_factor(d.symbolic, &d.common);
  if (!d.factor) std::swap(d.factor, d.aside);  // (nothing moved: the check below reports it)
  d.check("copying the analysis");
}

void SparseCholesky::swap_aside() {
  Impl &d = *impl_;
  if (!d.aside) fail(MC_ERROR_INTERNAL, "swap_aside without a factor aside");
  std::swap(d.factor, d.aside);
}

void SparseCholesky::release_aside() {
  Impl &d = *impl_;
  if (d.aside) cholmod_free_factor(&d.aside, &d.common);
}

bool SparseCholesky::supernodal() const { return impl_->factor && impl_->factor->is_super; }

bool SparseCholesky::modify(bool add, int k, const int *colptr, const int *rows, const double *values) {
  Impl &d = *impl_;
  if (n_ == 0 || k == 0) return true;
  if (!d.factor || d.factor->xtype == CHOLMOD_PATTERN) fail(MC_ERROR_INTERNAL, "modify before factorize");
  // CHOLMOD takes C in the factor's order (rows permuted by L->Perm), each column sorted.
  if (d.inverse_perm.empty()) {
    const int *perm = static_cast<const int *>(d.factor->Perm);
    d.inverse_perm.resize(static_cast<size_t>(n_));
    for (int i = 0; i < n_; ++i) d.inverse_perm[size_t(perm[i])] = i;
  }
  const std::vector<int> &inverse = d.inverse_perm;
  const int nnz = colptr[k];
  std::vector<int> p(colptr, colptr + k + 1), i(static_cast<size_t>(nnz));
  std::vector<double> x(static_cast<size_t>(nnz));
  std::vector<std::pair<int, double>> column;
  for (int c = 0; c < k; ++c) {
    column.clear();
    for (int q = colptr[c]; q < colptr[c + 1]; ++q) column.emplace_back(inverse[size_t(rows[q])], values[q]);
    std::sort(column.begin(), column.end());
    for (int q = colptr[c]; q < colptr[c + 1]; ++q)
      i[size_t(q)] = column[size_t(q - colptr[c])].first, x[size_t(q)] = column[size_t(q - colptr[c])].second;
  }
  cholmod_sparse cs;
  std::memset(&cs, 0, sizeof cs);
  cs.nrow = size_t(n_), cs.ncol = size_t(k), cs.nzmax = size_t(nnz);
  cs.p = p.data(), cs.i = i.data(), cs.x = x.data();
  cs.stype = 0, cs.itype = CHOLMOD_INT, cs.xtype = CHOLMOD_REAL, cs.dtype = CHOLMOD_DOUBLE;
  cs.sorted = 1, cs.packed = 1;
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    cholmod_updown(add ? 1 : 0, &cs, d.factor, &d.common);
  }
  d.check("update/downdate");
  // A simplicial LDL^T now: D is each column's first entry. Only the columns on the elimination-
  // tree paths from each column of C's first row changed (an update or downdate walks them):
  // their pivots are checked, not all n.
  const int *lp = static_cast<const int *>(d.factor->p);
  const double *lx = static_cast<const double *>(d.factor->x);
  d.elimination_tree();
  if (d.on_path.empty()) d.on_path.assign(static_cast<size_t>(n_), 0);
  std::vector<int> visited;
  bool positive = true;
  for (int c = 0; c < k && positive; ++c) {
    if (p[size_t(c)] == p[size_t(c) + 1]) continue;
    for (int j = i[size_t(p[size_t(c)])]; j >= 0 && !d.on_path[size_t(j)]; j = d.parent[size_t(j)]) {
      d.on_path[size_t(j)] = 1, visited.push_back(j);
      if (!(lx[lp[j]] > 0) || !std::isfinite(lx[lp[j]])) {
        positive = false;
        break;
      }
    }
  }
  for (int j : visited) d.on_path[size_t(j)] = 0;
  return positive;
}

std::vector<double> SparseCholesky::path_entries() const {
  const cholmod_factor *f = impl_->factor;
  if (n_ == 0 || !f || f->xtype == CHOLMOD_PATTERN) return {};
  std::vector<int> parent(static_cast<size_t>(n_), -1);
  std::vector<double> count(static_cast<size_t>(n_), 0.0);
  if (f->is_super) {
    const int *super = static_cast<const int *>(f->super), *pi = static_cast<const int *>(f->pi);
    const int *ls = static_cast<const int *>(f->s);
    for (size_t s = 0; s < f->nsuper; ++s) {
      const int k1 = super[s], k2 = super[s + 1], nsrow = pi[s + 1] - pi[s];
      for (int k = k1; k < k2; ++k) {
        count[size_t(k)] = nsrow - (k - k1);
        parent[size_t(k)] = k + 1 < k2 ? k + 1 : (nsrow > k2 - k1 ? ls[pi[s] + (k2 - k1)] : -1);
      }
    }
  } else {
    const int *lp = static_cast<const int *>(f->p), *li = static_cast<const int *>(f->i), *lnz = static_cast<const int *>(f->nz);
    for (int j = 0; j < n_; ++j) {
      count[size_t(j)] = lnz[j];
      int first = -1;
      for (int q = lp[j] + 1; q < lp[j] + lnz[j]; ++q)
        if (first < 0 || li[q] < first) first = li[q];
      parent[size_t(j)] = first;
    }
  }
  std::vector<double> path(static_cast<size_t>(n_), 0.0);
  for (int j = n_ - 1; j >= 0; --j) path[size_t(j)] = count[size_t(j)] + (parent[size_t(j)] > j ? path[size_t(parent[size_t(j)])] : 0.0);
  const int *perm = static_cast<const int *>(f->Perm);
  std::vector<double> by_unknown(static_cast<size_t>(n_));
  for (int k = 0; k < n_; ++k) by_unknown[size_t(perm[k])] = path[size_t(k)];
  return by_unknown;
}

void SparseCholesky::solve(double *x, int nrhs) const {
  Impl &d = *impl_;
  if (n_ == 0) return;
  if (nrhs == 1 && solve_by_subtrees(x)) return;
  cholmod_dense b;
  std::memset(&b, 0, sizeof b);
  b.nrow = size_t(n_);
  b.ncol = size_t(nrhs);
  b.nzmax = size_t(n_) * nrhs;
  b.d = size_t(n_);
  b.x = x;
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense *solution;
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    solution = cholmod_solve(CHOLMOD_A, d.factor, &b, &d.common);
  }
  d.check("solve");
  std::memcpy(x, solution->x, sizeof(double) * size_t(n_) * nrhs);
  cholmod_free_dense(&solution, &d.common);
}

bool SparseCholesky::solve_by_subtrees(double *x) const {
  Impl &d = *impl_;
  const cholmod_factor *f = d.factor;
  if (!f || f->is_super || f->xtype == CHOLMOD_PATTERN) return false;
  SimplicialFactor view;
  view.n = n_;
  view.p = static_cast<const int *>(f->p), view.i = static_cast<const int *>(f->i);
  view.nz = static_cast<const int *>(f->nz), view.x = static_cast<const double *>(f->x);
  view.ll = f->is_ll != 0;
  // The plan, made at the first solve after an analysis (and again should a factor's pattern
  // ever differ from it); none where it would not pay.
  if (d.plan_made && d.plan && !d.plan->fits(view)) d.plan.reset(), d.plan_made = false;
  if (!d.plan_made) {
    d.plan_made = true;
    if (double(d.common.lnz) >= kSubtreeSolveFromEntries) {
      std::vector<double> entries(view.nz, view.nz + n_);
      auto plan = std::make_unique<SubtreeSolvePlan>(d.elimination_tree(), entries);
      if (plan->worthwhile()) d.plan = std::move(plan);
    }
  }
  if (!d.plan) return false;
  const int *perm = static_cast<const int *>(f->Perm);
  std::vector<double> y(static_cast<size_t>(n_));
  for (int k = 0; k < n_; ++k) y[size_t(k)] = x[perm[k]];
  d.plan->solve(view, y.data(), threads_ > 1);
  for (int k = 0; k < n_; ++k) x[perm[k]] = y[size_t(k)];
  return true;
}

double SparseCholesky::split_top_share() const {
  const SubtreeSolvePlan *plan = impl_->plan.get();
  if (!plan) return -1;
  return plan->top_entries() / std::max(1.0, plan->top_entries() + plan->half_entries(0) + plan->half_entries(1));
}

namespace {
// One triangular solve with the factor (system CHOLMOD_L or CHOLMOD_Lt) in place on x.
void triangular_solve(cholmod_factor *factor, cholmod_common &common, int system, double *x, int n) {
  cholmod_dense b;
  std::memset(&b, 0, sizeof b);
  b.nrow = b.d = b.nzmax = size_t(n);
  b.ncol = 1;
  b.x = x;
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense *solution;
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    solution = cholmod_solve(system, factor, &b, &common);
  }
  if (!solution) fail(MC_ERROR_INTERNAL, "CHOLMOD failed in a triangular solve (status %d)", common.status);
  std::memcpy(x, solution->x, sizeof(double) * size_t(n));
  cholmod_free_dense(&solution, &common);
}
}  // namespace

void SparseCholesky::forward(const double *b, double *y) const {
  Impl &d = *impl_;
  if (n_ == 0) return;
  const int *perm = static_cast<const int *>(d.factor->Perm);
  bool zero = true;
  for (int k = 0; k < n_; ++k) y[k] = b[perm[k]], zero = zero && y[k] == 0;
  // A body loaded only through contact (a foundation held by supports at rest): L^-1 0 = 0,
  // and a quarter of a re-solve's work is saved.
  if (!zero) triangular_solve(d.factor, d.common, CHOLMOD_L, y, n_);
}

void SparseCholesky::backward(const double *z, double *x) const {
  Impl &d = *impl_;
  if (n_ == 0) return;
  std::vector<double> t(z, z + n_);
  triangular_solve(d.factor, d.common, CHOLMOD_Lt, t.data(), n_);
  const int *perm = static_cast<const int *>(d.factor->Perm);
  for (int k = 0; k < n_; ++k) x[perm[k]] = t[k];
}

int SparseCholesky::interface_start() const { return n_ - int(impl_->interface.size()); }

std::vector<double> SparseCholesky::interface_factor(std::vector<int> &order) const {
  const Impl &d = *impl_;
  const cholmod_factor *f = d.factor;
  const int ng = int(d.interface.size()), first = n_ - ng;
  if (!f->is_super) fail(MC_ERROR_INTERNAL, "expected a supernodal factor");
  // position in the factor -> position in the caller's interface list
  std::vector<int> inverse(n_, -1);
  const int *perm = static_cast<const int *>(f->Perm);
  for (int k = 0; k < n_; ++k) inverse[perm[k]] = k;
  order.assign(ng, -1);
  for (int i = 0; i < ng; ++i) order[inverse[d.interface[i]] - first] = i;
  std::vector<double> l(size_t(ng) * ng, 0.0);
  const int *super = static_cast<const int *>(f->super), *pi = static_cast<const int *>(f->pi);
  const int *px = static_cast<const int *>(f->px), *ls = static_cast<const int *>(f->s);
  const double *lx = static_cast<const double *>(f->x);
  for (size_t s = 0; s < f->nsuper; ++s) {
    int k1 = super[s], k2 = super[s + 1];
    if (k2 <= first) continue;
    int nsrow = pi[s + 1] - pi[s];
    for (int k = std::max(k1, first); k < k2; ++k)
      for (int r = 0; r < nsrow; ++r) {
        int row = ls[pi[s] + r];
        if (row < k) continue;  // the upper part of a supernode's diagonal block is not L
        l[size_t(row - first) + size_t(k - first) * ng] = lx[px[s] + r + size_t(k - k1) * nsrow];
      }
  }
  return l;
}

double SparseCholesky::analysis_flops() const { return impl_->factor ? impl_->common.fl : 0; }

long SparseCholesky::factor_nnz() const {
  const cholmod_factor *f = impl_->factor;
  if (!f) return 0;
  if (f->is_super) {
    long nnz = 0;
    const int *super = static_cast<const int *>(f->super), *pi = static_cast<const int *>(f->pi);
    for (size_t s = 0; s < f->nsuper; ++s) {
      long ncol = super[s + 1] - super[s], nrow = pi[s + 1] - pi[s];
      nnz += ncol * nrow - ncol * (ncol - 1) / 2;
    }
    return nnz;
  }
  return long(impl_->common.lnz);
}

}  // namespace mc
