#include "linalg/sparse_cholesky_impl.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>
#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace mc {

namespace {
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

SparseCholesky::SparseCholesky() : impl_(new Impl) {}
SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze(const SymmetricCsc &a, const std::vector<int> &interface, int ordering, bool in_halves) {
  Impl &d = *impl_;
  CholmodWithoutOpenMpTeam serial_openmp;
  if (d.factor) cholmod_free_factor(&d.factor, &d.common);
  if (d.symbolic) cholmod_free_factor(&d.symbolic, &d.common);
  if (d.aside) cholmod_free_factor(&d.aside, &d.common);
  d.forget_tree();
  d.counts_made_here = false;
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
  if (interface.empty() && in_halves && ordering == MC_ORDERING_AUTO && a.n >= kHalvesFromUnknowns &&
      analyze_in_halves(a))
    return;
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
  d.modified.clear();
  {
    CholmodWithoutOpenMpTeam serial_openmp;
    if (d.factor->is_super && d.factor->xtype == CHOLMOD_PATTERN) {
      // The numeric part allocated here, as cholmod_super_numeric would (same arguments), so
      // that its pages can be populated before the factorization writes them.
      cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, d.factor, &d.common);
      d.check("allocating the factor");
      populate_pages(d.factor->x, d.factor->xsize * sizeof(double));
    }
    cholmod_factorize(&s, d.factor, &d.common);
  }
  report_failed_pivot(a.n);
}

std::vector<int> SparseCholesky::simplicial_order() const {
  const cholmod_factor *f = impl_->factor;
  if (n_ == 0 || !f || f->is_super) return {};
  const int *perm = static_cast<const int *>(f->Perm);
  if (!perm) {
    std::vector<int> natural(static_cast<size_t>(n_));
    for (int k = 0; k < n_; ++k) natural[size_t(k)] = k;
    return natural;
  }
  return std::vector<int>(perm, perm + n_);
}

void SparseCholesky::factorize_ordered(const SymmetricCsc &a_pp) {
  Impl &d = *impl_;
  failed_unknown_ = -1;
  if (n_ == 0) return;
  if (!d.factor || d.factor->is_super) fail(MC_ERROR_INTERNAL, "factorize_ordered without a simplicial analysis");
  if (a_pp.n != n_) fail(MC_ERROR_INTERNAL, "factorize_ordered: %d unknowns, the analysis has %d", a_pp.n, n_);
  cholmod_sparse s = d.view(a_pp);
  d.modified.clear();
  factorize_rows(s);
  report_failed_pivot(a_pp.n);
}

// After a factorization: a pivot that failed thrown as MC_ERROR_SINGULAR, naming its unknown.
void SparseCholesky::report_failed_pivot(int n) {
  Impl &d = *impl_;
  if (d.common.status == CHOLMOD_NOT_POSDEF) {
    const int *perm = static_cast<const int *>(d.factor->Perm);
    const int minor = int(d.factor->minor);
    failed_unknown_ = perm && minor < n ? perm[minor] : minor;
  }
  if (d.common.status == CHOLMOD_NOT_POSDEF)
    fail(MC_ERROR_SINGULAR,
         "the stiffness matrix is not positive definite (pivot %d of %d): a part of the body can move "
         "rigidly, or a material is not positive definite",
         int(d.factor->minor), n);
  d.check("factorize");
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
  d.modified_aside = std::move(d.modified), d.modified.clear();
  d.factor = cholmod_copy_factor(d.symbolic, &d.common);
  if (!d.factor) std::swap(d.factor, d.aside);  // (nothing moved: the check below reports it)
  d.check("copying the analysis");
}

void SparseCholesky::swap_aside() {
  Impl &d = *impl_;
  if (!d.aside) fail(MC_ERROR_INTERNAL, "swap_aside without a factor aside");
  std::swap(d.factor, d.aside);
  std::swap(d.modified, d.modified_aside);
}

void SparseCholesky::release_aside() {
  Impl &d = *impl_;
  if (d.aside) cholmod_free_factor(&d.aside, &d.common);
  d.modified_aside.clear();
}

bool SparseCholesky::modified_in_place() const { return impl_->modified.count > 0; }

bool SparseCholesky::supernodal() const { return impl_->factor && impl_->factor->is_super; }

bool SparseCholesky::modify(bool add, int k, const int *colptr, const int *rows, const double *values) {
  Impl &d = *impl_;
  if (n_ == 0 || k == 0) return true;
  if (!d.factor || d.factor->xtype == CHOLMOD_PATTERN) fail(MC_ERROR_INTERNAL, "modify before factorize");
  // CHOLMOD takes C in the factor's order (rows permuted by L->Perm), each column sorted.
  const std::vector<int> &inverse = d.inverse_permutation(n_);
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
  // tree paths from C's rows changed (an update or downdate walks them): their pivots are
  // checked, not all n, and they are marked modified in place (refactorize_paths).
  const int *lp = static_cast<const int *>(d.factor->p);
  const double *lx = static_cast<const double *>(d.factor->x);
  d.elimination_tree();
  if (d.on_path.empty()) d.on_path.assign(static_cast<size_t>(n_), 0);
  std::vector<int> visited;
  for (int q = 0; q < nnz; ++q)
    for (int j = i[size_t(q)]; j >= 0 && !d.on_path[size_t(j)]; j = d.parent[size_t(j)])
      d.on_path[size_t(j)] = 1, visited.push_back(j);
  bool positive = true;
  for (int j : visited) {
    d.on_path[size_t(j)] = 0, d.modified.mark(j, n_);
    positive = positive && lx[lp[j]] > 0 && std::isfinite(lx[lp[j]]);
  }
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
