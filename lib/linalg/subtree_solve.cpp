// Solves with a simplicial factor split by subtrees of its elimination tree (subtree_solve.hpp).
#include "linalg/subtree_solve.hpp"
#include <algorithm>
#include <functional>
#include <pthread.h>
#include <system_error>
#include <thread>

namespace mc {

namespace {

// A plan pays when the serial part (the top) and the larger half together are at most this share
// of all the entries: below, two threads gain too little to be worth a thread start per pass.
constexpr double kWorthwhileShare = 0.75;
// The split's search: the heaviest subtree of the frontier is opened (its root moved to the top,
// its children into the frontier) at most this many times, and stops once the top passes a
// quarter of the entries or the frontier this many subtrees.
constexpr int kMaxOpenings = 4000;
constexpr double kMaxTopShare = 0.25;
constexpr size_t kMaxFrontier = 20000;

// Longest processing time first: the subtrees, heaviest first, each to the lighter half.
// Returns the heavier half's entries; side[k] the half of frontier[k].
double balance(const std::vector<int> &frontier, const std::vector<double> &weight, std::vector<int> &side) {
  std::vector<int> order(frontier.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = int(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double wa = weight[size_t(frontier[size_t(a)])], wb = weight[size_t(frontier[size_t(b)])];
    return wa != wb ? wa > wb : frontier[size_t(a)] < frontier[size_t(b)];
  });
  double load[2] = {0, 0};
  side.assign(frontier.size(), 0);
  for (int k : order) {
    const int h = load[1] < load[0] ? 1 : 0;
    side[size_t(k)] = h, load[h] += weight[size_t(frontier[size_t(k)])];
  }
  return std::max(load[0], load[1]);
}

}  // namespace

SubtreeSolvePlan::SubtreeSolvePlan(const std::vector<int> &parent, const std::vector<double> &column_entries) {
  const int n = int(parent.size());
  // Each subtree's entries (a parent's index is above its children's), and the children lists.
  std::vector<double> weight(column_entries);
  std::vector<int> size(static_cast<size_t>(n), 1);
  std::vector<int> child_start(size_t(n) + 1, 0), children(static_cast<size_t>(n));
  std::vector<int> roots;
  double total = 0;
  for (int j = 0; j < n; ++j) {
    total += column_entries[size_t(j)];
    if (parent[size_t(j)] > j) {
      weight[size_t(parent[size_t(j)])] += weight[size_t(j)], size[size_t(parent[size_t(j)])] += size[size_t(j)];
      ++child_start[size_t(parent[size_t(j)]) + 1];
    }
    else roots.push_back(j);
  }
  for (int j = 0; j < n; ++j) child_start[size_t(j) + 1] += child_start[size_t(j)];
  {
    std::vector<int> next(child_start.begin(), child_start.end() - 1);
    for (int j = 0; j < n; ++j)
      if (parent[size_t(j)] > j) children[size_t(next[size_t(parent[size_t(j)])]++)] = j;
  }
  if (!(total > 0)) return;
  // Open the heaviest subtree of the frontier while that lowers the time of a solve on two
  // threads, the larger half plus the top; keep the best frontier seen.
  std::vector<int> frontier(roots), side, best_frontier, best_side;
  double top = 0, best_time = total;
  for (int opening = 0; opening <= kMaxOpenings && frontier.size() <= kMaxFrontier; ++opening) {
    const double time = balance(frontier, weight, side) + top;
    if (time < best_time) best_time = time, best_frontier = frontier, best_side = side;
    if (top > kMaxTopShare * total || frontier.empty()) break;
    size_t heaviest = 0;
    for (size_t k = 1; k < frontier.size(); ++k)
      if (weight[size_t(frontier[k])] > weight[size_t(frontier[heaviest])]) heaviest = k;
    const int root = frontier[heaviest];
    frontier.erase(frontier.begin() + long(heaviest));
    top += column_entries[size_t(root)];
    for (int c = child_start[size_t(root)]; c < child_start[size_t(root) + 1]; ++c) frontier.push_back(children[size_t(c)]);
  }
  if (best_frontier.empty() || best_time > kWorthwhileShare * total) return;
  // The halves' subtrees and the top's runs as ranges of columns: in a postordered tree the subtree
  // of r is r - size(r) + 1 .. r (checked: no plan for an order that is not postordered).
  std::vector<char> owner(static_cast<size_t>(n), 2);
  std::vector<Range> ranges[3];
  for (size_t k = 0; k < best_frontier.size(); ++k) {
    const int r = best_frontier[k], first = r - size[size_t(r)] + 1;
    if (first < 0) return;
    for (int j = first; j <= r; ++j) {
      if (owner[size_t(j)] != 2) return;  // (subtrees overlapping: not postordered)
      owner[size_t(j)] = char(best_side[k]);
    }
    ranges[best_side[k]].emplace_back(first, r + 1);
  }
  for (int j = 0; j < n;) {
    int end = j + 1;
    while (end < n && owner[size_t(end)] == owner[size_t(j)]) ++end;
    if (owner[size_t(j)] == 2) ranges[2].emplace_back(j, end);
    j = end;
  }
  // Each range of a half one subtree: its columns' ancestors within it (checked by the parents).
  for (int h = 0; h < 2; ++h)
    for (const Range &r : ranges[h])
      for (int j = r.first; j < r.second - 1; ++j)
        if (parent[size_t(j)] < j || parent[size_t(j)] >= r.second) return;
  for (int h = 0; h < 3; ++h) {
    std::sort(ranges[h].begin(), ranges[h].end());
    for (const Range &r : ranges[h])
      for (int j = r.first; j < r.second; ++j) (h == 2 ? top_entries_ : half_entries_[h]) += column_entries[size_t(j)];
    ranges_[h] = std::move(ranges[h]);
  }
  top_offset_.assign(1, 0);
  for (const Range &r : ranges_[2]) top_offset_.push_back(top_offset_.back() + size_t(r.second - r.first));
  n_ = n, total_entries_ = total;
}

bool SubtreeSolvePlan::fits(const SimplicialFactor &f) const {
  if (f.n != n_) return false;
  double entries = 0;
  for (int j = 0; j < f.n; ++j) entries += f.nz[j];
  return entries == total_entries_;
}

// L y = b on a part's columns, ascending (and D's division, for LDL^T). Half 0 and the top update
// their rows in y itself, half 1 the top's rows in spill (indexed by top position): the halves
// never write the same entry. A row of a column is one of its ancestors: in its own subtree up to
// the subtree's root, the top's above. (Columns of one supernode done together, each index read
// once for all of them, was tried: slower, its index reads no longer one sequential stream.)
void SubtreeSolvePlan::forward_part(const SimplicialFactor &f, int h, double *y, double *spill) const {
  for (const Range &r : ranges_[h]) {
    const int root = r.second - 1;  // (half 1: rows above it are the top's)
    for (int j = r.first; j < r.second; ++j) {
      const int first = f.p[j], end = first + f.nz[j];
      double yj = y[j];
      if (f.ll) yj /= f.x[first], y[j] = yj;
      if (h != 1) {
        for (int q = first + 1; q < end; ++q) y[f.i[q]] -= f.x[q] * yj;
      } else {
        for (int q = first + 1; q < end; ++q) {
          const int i = f.i[q];
          if (i <= root) y[i] -= f.x[q] * yj;
          else spill[top_position(i)] -= f.x[q] * yj;
        }
      }
      if (!f.ll) y[j] = yj / f.x[first];
    }
  }
}

// The position of a top column among the top's (a search: few entries of half 1 reach the top).
size_t SubtreeSolvePlan::top_position(int column) const {
  const auto after = std::upper_bound(ranges_[2].begin(), ranges_[2].end(), Range{column, n_});
  const size_t k = size_t(after - ranges_[2].begin()) - 1;  // the run holding it
  return top_offset_[k] + size_t(column - ranges_[2][k].first);
}

// L^T x = y on a part's columns, descending: reads its own rows and the top's, written before.
void SubtreeSolvePlan::backward_part(const SimplicialFactor &f, int h, double *y) const {
  for (auto r = ranges_[h].rbegin(); r != ranges_[h].rend(); ++r)
    for (int j = r->second - 1; j >= r->first; --j) {
      const int first = f.p[j], end = first + f.nz[j];
      double s = y[j];
      for (int q = first + 1; q < end; ++q) s -= f.x[q] * y[f.i[q]];
      y[j] = f.ll ? s / f.x[first] : s;
    }
}

void SubtreeSolvePlan::solve(const SimplicialFactor &f, double *y, bool two_threads) const {
  std::vector<double> spill(top_offset_.back(), 0.0);
  // Both halves at once, or in turn if no thread can be started: the same arithmetic.
  auto both_halves = [&](const std::function<void(int)> &half) {
    if (two_threads) {
      try {
        std::thread second([&] { half(1); });
        // The library's second thread has one name wherever it runs (model.cpp's body threads).
        pthread_setname_np(second.native_handle(), "mc-body2");
        half(0);
        second.join();
        return;
      } catch (const std::system_error &) {
      }
    }
    half(0), half(1);
  };
  both_halves([&](int h) { forward_part(f, h, y, spill.data()); });
  size_t t = 0;
  for (const Range &r : ranges_[2])
    for (int j = r.first; j < r.second; ++j) y[j] += spill[t++];
  forward_part(f, 2, y, nullptr);
  backward_part(f, 2, y);
  both_halves([&](int h) { backward_part(f, h, y); });
}

}  // namespace mc
