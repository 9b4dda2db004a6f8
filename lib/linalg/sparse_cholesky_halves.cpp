// SparseCholesky for a slender matrix in two halves (sparse_cholesky.hpp; docs/theory.md §6b
// item 3): its order, and its factorizations and solves with each half on its own thread.
#include "linalg/sparse_cholesky_impl.hpp"
#include "linalg/matrix_graph.hpp"
#include <algorithm>
#include <exception>
#include <pthread.h>
#include <system_error>
#include <thread>

namespace mc {

// main() on the calling thread and second() on a second one where threads_ allows (and one can
// be had), else one after the other; what second() throws is thrown here after the join.
void SparseCholesky::in_two_threads(const std::function<void()> &main, const std::function<void()> &second) const {
  std::exception_ptr failed;
  std::thread other;
  if (threads_ > 1) try {
      other = std::thread([&] {
        try {
          second();
        } catch (...) {
          failed = std::current_exception();
        }
      });
    } catch (const std::system_error &) {
    }
  if (!other.joinable()) {
    main(), second();
    return;
  }
  pthread_setname_np(other.native_handle(), "mc-body2");
  try {
    main();
  } catch (...) {
    other.join();
    throw;
  }
  other.join();
  if (failed) std::rethrow_exception(failed);
}

// A slender matrix's analysis in two halves (SparseCholesky::analyze): split by a level separator
// of at most kLargestSeparator unknowns, each half ordered by AMD, the separator last, simplicial;
// the split of its solves and factorizations planned from the analysis. False: not split (the
// caller analyses it as usual).
bool SparseCholesky::analyze_in_halves(const SymmetricCsc &a) {
  Impl &d = *impl_;
  const std::vector<int> part = split_in_two(graph_of(a));
  const long separator = std::count_if(part.begin(), part.end(), [](int side) { return side == 2; });
  if (part.empty() || separator > kLargestSeparator) return false;
  const std::vector<int> order = order_in_halves(a, part);
  // The symbolic factor made here, as cholmod_analyze_p would make it from this order (the
  // elimination tree, the column counts, then the tree's postorder weighted by them, composed
  // with the order): the same factor, in about 0.08 s at 16001 contact nodes on the strips
  // against 0.14 s for cholmod_analyze_p (which permutes the matrix twice to find what the
  // order's rows give at once) and 0.035 s more for a second elimination tree for the solve plan.
  // Each half's rows on a thread of its own (they name no column of the other), then the
  // separator's. Simplicial: the halves are for a simplicial factor (split solves and
  // factorizations, and modified in place); a slender matrix's fronts are small, about CHOLMOD's
  // own switch (39 to 45 flops per entry on the strips from 1001 to 4001 contact nodes).
  SymbolicFactor symbolic(a, order.data());
  const int first_half = int(std::count(part.begin(), part.end(), 0)), halves = a.n - int(separator);
  in_two_threads([&] { symbolic.rows(0, first_half); }, [&] { symbolic.rows(first_half, halves); });
  symbolic.rows(halves, a.n);
  const size_t n = size_t(a.n);
  std::vector<int> post(n);
  if (cholmod_postorder(symbolic.parent.data(), n, symbolic.count.data(), post.data(), &d.common) != a.n)
    fail(MC_ERROR_INTERNAL, "the elimination tree of the halves' order is not a forest");
  d.factor = cholmod_allocate_factor(n, &d.common);
  d.check("analyze");
  int *perm = static_cast<int *>(d.factor->Perm), *count = static_cast<int *>(d.factor->ColCount);
  std::vector<int> position_in_post(n);
  double lnz = 0, flops = 0;
  for (size_t k = 0; k < n; ++k) {
    perm[k] = order[size_t(post[k])], count[k] = symbolic.count[size_t(post[k])];
    position_in_post[size_t(post[k])] = int(k);
    lnz += count[k], flops += double(count[k]) * count[k];
  }
  d.factor->ordering = CHOLMOD_GIVEN;
  d.counts_made_here = true;
  d.common.lnz = lnz, d.common.fl = flops;  // (as cholmod_rowcolcounts counts them)
  // The tree in the factor's order: every factor of this analysis has it (Impl::elimination_tree).
  d.parent.assign(n, -1);
  for (size_t k = 0; k < n; ++k) {
    const int old_parent = symbolic.parent[size_t(post[k])];
    if (old_parent >= 0) d.parent[k] = position_in_post[size_t(old_parent)];
  }
  // The split of the solves (and factorizations) made now, from the analysis.
  d.plan_made = true;
  if (lnz >= kSubtreeSolveFromEntries) {
    const std::vector<double> entries(count, count + n);
    auto plan = std::make_unique<SubtreeSolvePlan>(d.parent, entries);
    if (plan->worthwhile()) d.plan = std::move(plan);
  }
  return true;
}

// The order of a matrix split in two halves (part[v]: 0, 1, or 2 for the separator): each half's
// unknowns by AMD on the half alone (no entry joins the halves: their orders are independent, the
// second on a second thread where set_threads allows), then the separator's. CAMD on the whole
// matrix with the three parts as constraint sets gave a factor 1.6 % larger at 16001 contact
// nodes and took 3 to 4 times AMD's time on the strips.
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
    in_two_threads([&] { order_half(0, &d.common); },
                   [&] {
                     CholmodWithoutOpenMpTeam its_own;
                     order_half(1, &d.second);
                   });
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

// A simplicial factorization by rows of S = triu(A(p, p)) (cholmod_rowfac, as cholmod_factorize
// runs it), where the solves are split and two threads may run the two halves' rows at once: a
// row of L is computed from the rows of its descendants in the elimination tree alone, so each
// half's subtrees need nothing of the other's, and the top's rows follow. Every row is computed
// as cholmod_factorize computes it: the same factor to the bit, on one thread or two.
void SparseCholesky::factorize_rows(cholmod_sparse &upper) {
  Impl &d = *impl_;
  cholmod_factor *f = d.factor;
  const int n = n_;
  CholmodWithoutOpenMpTeam serial_openmp;
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
  double beta[2] = {0, 0};
  const bool in_halves = threads_ > 1 && d.plan;
  if (!in_halves) {
    cholmod_rowfac(&upper, nullptr, beta, 0, size_t(n), f, &d.common);
  } else {
    // Half 1's workspace, allocated here: from the calling thread's memory (a first allocation
    // on a new thread would open a malloc arena of its own, resident memory the solve does not
    // need).
    cholmod_allocate_work(size_t(n), size_t(n), size_t(n), &d.second);
    if (d.second.status == CHOLMOD_OUT_OF_MEMORY) d.common.status = CHOLMOD_OUT_OF_MEMORY;
    struct FreedWork {
      cholmod_common &second;
      ~FreedWork() { cholmod_free_work(&second); }
    } freed{d.second};
    d.check("allocating a workspace");
    // Half 1 writes through a copy of the factor's header: the same arrays, its own `minor` (the
    // row where a pivot failed), merged below.
    cholmod_factor half_one = *f;
    auto rows_of = [&](int part, cholmod_factor *factor, cholmod_common *common) {
      for (const SubtreeSolvePlan::Range &r : d.plan->ranges(part))
        cholmod_rowfac(&upper, nullptr, beta, size_t(r.first), size_t(r.second), factor, common);
    };
    in_two_threads([&] { rows_of(0, f, &d.common); },
                   [&] {
                     CholmodWithoutOpenMpTeam its_own;
                     rows_of(1, &half_one, &d.second);
                   });
    f->minor = std::min(f->minor, half_one.minor);
    if (d.second.status == CHOLMOD_OUT_OF_MEMORY) d.common.status = CHOLMOD_OUT_OF_MEMORY;
    if (f->minor == size_t(n)) rows_of(2, f, &d.common);
  }
  if (d.common.status == CHOLMOD_NOT_POSDEF || f->minor < size_t(n)) {
    d.common.status = CHOLMOD_NOT_POSDEF;
    return;
  }
  d.check("factorize");
  // Column counts of our own (analyze_in_halves) checked against the factor: cholmod_rowfac
  // stores each row's structural entries, numerical zeros too, so each column holds its count.
  if (d.counts_made_here) {
    const int *lnz = static_cast<const int *>(f->nz), *count = static_cast<const int *>(f->ColCount);
    for (int k = 0; k < n; ++k)
      if (lnz[k] != count[k])
        fail(MC_ERROR_INTERNAL, "column %d of the factor holds %d entries, its analysis counted %d", k, lnz[k], count[k]);
  }
  // Left as cholmod_factorize leaves it (Common's final_pack and final_monotonic).
  cholmod_change_factor(CHOLMOD_REAL, 1, 0, d.common.final_pack, d.common.final_monotonic, f, &d.common);
  d.check("factorize");
  if (in_halves) ++split_factorizations_;
}

bool SparseCholesky::solve_by_subtrees(double *x) const {
  Impl &d = *impl_;
  const cholmod_factor *f = d.factor;
  if (!f || f->xtype == CHOLMOD_PATTERN) return false;
  if (f->is_super) return solve_supernodal_by_subtrees(x);
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

// A supernodal factor's solve split where split_supernodal_solves() asked for it (the sparse
// path's H_P where CHOLMOD chose a supernodal factor), whatever the threads: its halves in turn on
// one, so that the answer does not depend on MC_OPTION_THREADS.
bool SparseCholesky::solve_supernodal_by_subtrees(double *x) const {
  Impl &d = *impl_;
  const cholmod_factor *f = d.factor;
  if (!split_supernodal_) return false;
  SupernodalFactor view;
  view.n = n_, view.nsuper = int(f->nsuper);
  view.super = static_cast<const int *>(f->super), view.pi = static_cast<const int *>(f->pi);
  view.px = static_cast<const int *>(f->px), view.s_rows = static_cast<const int *>(f->s);
  view.x = static_cast<const double *>(f->x);
  if (!d.super_plan_made) {
    d.super_plan_made = true;
    if (double(d.common.lnz) >= kSubtreeSolveFromEntries) {
      auto plan = std::make_unique<SupernodalSolvePlan>(view);
      if (plan->worthwhile()) d.super_plan = std::move(plan);
    }
  }
  if (!d.super_plan) return false;
  const int *perm = static_cast<const int *>(f->Perm);
  std::vector<double> y(static_cast<size_t>(n_));
  for (int k = 0; k < n_; ++k) y[size_t(k)] = x[perm[k]];
  d.super_plan->solve(view, y.data(), threads_ > 1);
  for (int k = 0; k < n_; ++k) x[perm[k]] = y[size_t(k)];
  return true;
}

double SparseCholesky::split_top_share() const {
  if (impl_->factor && impl_->factor->is_super) {
    if (!impl_->super_plan) return -1;
    const SubtreeSolvePlan &p = impl_->super_plan->plan();
    return p.top_entries() / std::max(1.0, p.top_entries() + p.half_entries(0) + p.half_entries(1));
  }
  const SubtreeSolvePlan *plan = impl_->plan.get();
  if (!plan) return -1;
  return plan->top_entries() / std::max(1.0, plan->top_entries() + plan->half_entries(0) + plan->half_entries(1));
}

}  // namespace mc
