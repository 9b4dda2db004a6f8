// Solves with a supernodal factor split by subtrees of its supernodal tree (supernodal_solve.hpp).
#include "linalg/supernodal_solve.hpp"
#include <exception>
#include <functional>
#include <pthread.h>
#include <system_error>
#include <thread>

namespace mc {

namespace {
// The plan over supernodes: each one's parent (the supernode of its first row below its
// columns, -1 at a root) and its block's entries.
SubtreeSolvePlan plan_over_supernodes(const SupernodalFactor &f) {
  std::vector<int> supernode_of(static_cast<size_t>(f.n), -1), parent(static_cast<size_t>(f.nsuper), -1);
  std::vector<double> entries(static_cast<size_t>(f.nsuper), 0.0);
  for (int s = 0; s < f.nsuper; ++s)
    for (int j = f.super[s]; j < f.super[s + 1]; ++j) supernode_of[size_t(j)] = s;
  for (int s = 0; s < f.nsuper; ++s) {
    const int nscol = f.super[s + 1] - f.super[s], nsrow = f.pi[s + 1] - f.pi[s];
    if (nsrow > nscol) parent[size_t(s)] = supernode_of[size_t(f.s_rows[f.pi[s] + nscol])];
    entries[size_t(s)] = double(nscol) * nsrow - double(nscol) * (nscol - 1) / 2;
  }
  return SubtreeSolvePlan(parent, entries);
}
}  // namespace

SupernodalSolvePlan::SupernodalSolvePlan(const SupernodalFactor &f) : plan_(plan_over_supernodes(f)) {
  if (!plan_.worthwhile()) return;
  top_slot_.assign(static_cast<size_t>(f.n), -1);
  for (const SubtreeSolvePlan::Range &r : plan_.ranges(2))
    for (int j = f.super[r.first]; j < f.super[r.second]; ++j) top_slot_[size_t(j)] = top_columns_++;
}

// L y = b on a part's supernodes, ascending. Half 0 and the top update their rows in y itself,
// half 1 the top's rows in spill (by top slot): the halves never write the same entry.
void SupernodalSolvePlan::forward_part(const SupernodalFactor &f, int h, double *y, double *spill) const {
  std::vector<double> t;
  for (const SubtreeSolvePlan::Range &r : plan_.ranges(h)) {
    const int last = f.super[r.second] - 1;  // (half 1: rows above it are the top's)
    for (int s = r.first; s < r.second; ++s) {
      const int k1 = f.super[s], nscol = f.super[s + 1] - k1, nsrow = f.pi[s + 1] - f.pi[s];
      const double *l = f.x + f.px[s];
      const int *rows = f.s_rows + f.pi[s];
      // The diagonal block: y[k1 ..] <- L_ss^-1 y[k1 ..], by columns.
      double *ys = y + k1;
      for (int k = 0; k < nscol; ++k) {
        const double *column = l + size_t(k) * size_t(nsrow);
        const double yk = ys[k] / column[k];
        ys[k] = yk;
        for (int i = k + 1; i < nscol; ++i) ys[i] -= column[i] * yk;
      }
      // The rows below: t = L_rs y_s, then one update per row.
      const int below = nsrow - nscol;
      if (below == 0) continue;
      t.assign(size_t(below), 0.0);
      for (int k = 0; k < nscol; ++k) {
        const double *column = l + size_t(k) * size_t(nsrow) + nscol;
        const double yk = ys[k];
        for (int i = 0; i < below; ++i) t[size_t(i)] += column[i] * yk;
      }
      for (int i = 0; i < below; ++i) {
        const int row = rows[nscol + i];
        if (h != 1 || row <= last) y[row] -= t[size_t(i)];
        else spill[top_slot_[size_t(row)]] -= t[size_t(i)];
      }
    }
  }
}

// L^T x = y on a part's supernodes, descending: reads its own rows and the top's, written before.
void SupernodalSolvePlan::backward_part(const SupernodalFactor &f, int h, double *y) const {
  std::vector<double> t;
  const std::vector<SubtreeSolvePlan::Range> &ranges = plan_.ranges(h);
  for (auto r = ranges.rbegin(); r != ranges.rend(); ++r)
    for (int s = r->second - 1; s >= r->first; --s) {
      const int k1 = f.super[s], nscol = f.super[s + 1] - k1, nsrow = f.pi[s + 1] - f.pi[s];
      const double *l = f.x + f.px[s];
      const int *rows = f.s_rows + f.pi[s];
      const int below = nsrow - nscol;
      t.resize(size_t(below));
      for (int i = 0; i < below; ++i) t[size_t(i)] = y[rows[nscol + i]];
      double *ys = y + k1;
      for (int k = nscol - 1; k >= 0; --k) {
        const double *column = l + size_t(k) * size_t(nsrow);
        double sum = ys[k];
        for (int i = 0; i < below; ++i) sum -= column[nscol + i] * t[size_t(i)];
        for (int i = k + 1; i < nscol; ++i) sum -= column[i] * ys[i];
        ys[k] = sum / column[k];
      }
    }
}

void SupernodalSolvePlan::solve(const SupernodalFactor &f, double *y, bool two_threads) const {
  std::vector<double> spill(static_cast<size_t>(top_columns_), 0.0);
  // Both halves at once, or in turn if no thread can be started: the same arithmetic. What the
  // second thread throws (an allocation) is thrown here after the join.
  auto both_halves = [&](const std::function<void(int)> &half) {
    std::exception_ptr failed;
    std::thread second;
    if (two_threads) try {
        second = std::thread([&] {
          try {
            half(1);
          } catch (...) {
            failed = std::current_exception();
          }
        });
      } catch (const std::system_error &) {
      }
    if (!second.joinable()) {
      half(0), half(1);
      return;
    }
    // The library's second thread has one name wherever it runs (model.cpp's body threads).
    pthread_setname_np(second.native_handle(), "mc-body2");
    try {
      half(0);
    } catch (...) {
      second.join();
      throw;
    }
    second.join();
    if (failed) std::rethrow_exception(failed);
  };
  both_halves([&](int h) { forward_part(f, h, y, spill.data()); });
  size_t t = 0;
  for (const SubtreeSolvePlan::Range &r : plan_.ranges(2))
    for (int j = f.super[r.first]; j < f.super[r.second]; ++j) y[j] += spill[t++];
  forward_part(f, 2, y, nullptr);
  backward_part(f, 2, y);
  both_halves([&](int h) { backward_part(f, h, y); });
}

}  // namespace mc
