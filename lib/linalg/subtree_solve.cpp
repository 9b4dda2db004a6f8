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
  // The halves' columns, and the top: every column outside them.
  std::vector<char> owner(static_cast<size_t>(n), 2);
  std::vector<int> stack, root_of(static_cast<size_t>(n), -1);
  for (size_t k = 0; k < best_frontier.size(); ++k) {
    stack.assign(1, best_frontier[k]);
    while (!stack.empty()) {
      const int j = stack.back();
      stack.pop_back();
      owner[size_t(j)] = char(best_side[k]), root_of[size_t(j)] = best_frontier[k];
      for (int c = child_start[size_t(j)]; c < child_start[size_t(j) + 1]; ++c) stack.push_back(children[size_t(c)]);
    }
  }
  for (int j = 0; j < n; ++j) {
    const int h = owner[size_t(j)];
    if (h == 2) top_entries_ += column_entries[size_t(j)];
    else half_entries_[h] += column_entries[size_t(j)];
    if (h == 1) root_.push_back(root_of[size_t(j)]);
    columns_[h].push_back(j);
  }
  entries_.resize(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) entries_[size_t(j)] = int(column_entries[size_t(j)]);
  // Ranges: in a postordered tree the subtree of r is r - size(r) + 1 .. r.
  bool consecutive = true;
  for (size_t k = 0; k < best_frontier.size() && consecutive; ++k) {
    const int r = best_frontier[k], first = r - size[size_t(r)] + 1;
    for (int j = first; j <= r && consecutive; ++j) consecutive = j >= 0 && root_of[size_t(j)] == r;
    ranges_[best_side[k]].emplace_back(first, r + 1);
  }
  for (int j = 0; j < n && consecutive;) {
    if (owner[size_t(j)] != 2) {
      ++j;
      continue;
    }
    int end = j;
    while (end < n && owner[size_t(end)] == 2) ++end;
    ranges_[2].emplace_back(j, end);
    j = end;
  }
  for (auto &r : ranges_) {
    if (!consecutive) r.clear();
    std::sort(r.begin(), r.end());
  }
}

bool SubtreeSolvePlan::fits(const SimplicialFactor &f) const {
  if (f.n != int(entries_.size())) return false;
  for (int j = 0; j < f.n; ++j)
    if (f.nz[j] != entries_[size_t(j)]) return false;
  return true;
}

// L y = b on a part's columns, ascending (and D's division, for LDL^T). Half 0 and the top update
// their rows in y itself, half 1 the top's rows in spill (indexed by top position): the halves
// never write the same entry. A row of a column is one of its ancestors: in its own subtree up to
// the subtree's root, the top's above. (Columns of one supernode done together, each index read
// once for all of them, was tried: slower, its index reads no longer one sequential stream.)
void SubtreeSolvePlan::forward_part(const SimplicialFactor &f, int h, double *y, double *spill) const {
  const std::vector<int> &columns = columns_[h];
  for (size_t c = 0; c < columns.size(); ++c) {
    const int j = columns[c], first = f.p[j], end = first + f.nz[j];
    double yj = y[j];
    if (f.ll) yj /= f.x[first], y[j] = yj;
    if (h != 1) {
      for (int q = first + 1; q < end; ++q) y[f.i[q]] -= f.x[q] * yj;
    } else {
      const int root = root_[c];
      for (int q = first + 1; q < end; ++q) {
        const int i = f.i[q];
        if (i <= root) y[i] -= f.x[q] * yj;
        else spill[top_position(i)] -= f.x[q] * yj;
      }
    }
    if (!f.ll) y[j] = yj / f.x[first];
  }
}

// L^T x = y on a part's columns, descending: reads its own rows and the top's, written before.
// A top column's position among the top's (a search: few entries of half 1 reach the top).
size_t SubtreeSolvePlan::top_position(int column) const {
  return size_t(std::lower_bound(columns_[2].begin(), columns_[2].end(), column) - columns_[2].begin());
}

void SubtreeSolvePlan::backward_part(const SimplicialFactor &f, int h, double *y) const {
  const std::vector<int> &columns = columns_[h];
  for (auto it = columns.rbegin(); it != columns.rend(); ++it) {
    const int j = *it, first = f.p[j], end = first + f.nz[j];
    double s = y[j];
    for (int q = first + 1; q < end; ++q) s -= f.x[q] * y[f.i[q]];
    y[j] = f.ll ? s / f.x[first] : s;
  }
}

void SubtreeSolvePlan::solve(const SimplicialFactor &f, double *y, bool two_threads) const {
  std::vector<double> spill(columns_[2].size(), 0.0);
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
  for (size_t t = 0; t < columns_[2].size(); ++t) y[columns_[2][t]] += spill[t];
  forward_part(f, 2, y, nullptr);
  backward_part(f, 2, y);
  both_halves([&](int h) { backward_part(f, h, y); });
}

}  // namespace mc
