#include "linalg/matrix_graph.hpp"
#include <algorithm>

namespace mc {

MatrixGraph graph_of(const SymmetricCsc &a) {
  MatrixGraph g;
  g.start.assign(size_t(a.n) + 1, 0);
  for (int j = 0; j < a.n; ++j)
    for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
      if (a.rows[p] != j) ++g.start[size_t(a.rows[p]) + 1], ++g.start[size_t(j) + 1];
  for (int v = 0; v < a.n; ++v) g.start[size_t(v) + 1] += g.start[size_t(v)];
  g.next.resize(size_t(g.start[size_t(a.n)]));
  std::vector<int> fill(g.start.begin(), g.start.end() - 1);
  for (int j = 0; j < a.n; ++j)
    for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
      if (a.rows[p] != j) g.next[size_t(fill[size_t(a.rows[p])]++)] = j, g.next[size_t(fill[size_t(j)]++)] = a.rows[p];
  return g;
}

int breadth_first(const MatrixGraph &g, int root, bool by_degree, const std::vector<char> &numbered, std::vector<int> &level,
                  std::vector<int> &visit) {
  visit.clear();
  visit.push_back(root);
  level[size_t(root)] = 0;
  int depth = 1;
  for (size_t head = 0; head < visit.size(); ++head) {
    const int v = visit[head];
    const size_t first = visit.size();
    for (int p = g.start[size_t(v)]; p < g.start[size_t(v) + 1]; ++p) {
      const int w = g.next[size_t(p)];
      if (!numbered[size_t(w)] && level[size_t(w)] < 0)
        level[size_t(w)] = level[size_t(v)] + 1, visit.push_back(w), depth = std::max(depth, level[size_t(w)] + 1);
    }
    if (by_degree)
      std::sort(visit.begin() + long(first), visit.end(), [&](int x, int y) { return g.degree(x) < g.degree(y); });
  }
  return depth;
}

int pseudo_peripheral_node(const MatrixGraph &g, int seed, const std::vector<char> &numbered, std::vector<int> &level,
                           std::vector<int> &visit) {
  auto reset = [&] {
    for (int v : visit) level[size_t(v)] = -1;
  };
  int root = seed, depth = breadth_first(g, root, false, numbered, level, visit);
  std::vector<int> root_visit, root_level;  // the root's search, kept while a candidate's is tried
  for (int tries = 0; tries < 4; ++tries) {
    int candidate = -1;
    for (int v : visit)
      if (level[size_t(v)] == depth - 1 && (candidate < 0 || g.degree(v) < g.degree(candidate))) candidate = v;
    root_visit = visit, root_level.resize(visit.size());
    for (size_t k = 0; k < visit.size(); ++k) root_level[k] = level[size_t(visit[k])];
    reset();
    const int candidate_depth = breadth_first(g, candidate, false, numbered, level, visit);
    if (candidate_depth <= depth) {  // the root's search stands: put it back
      reset();
      visit.swap(root_visit);
      for (size_t k = 0; k < visit.size(); ++k) level[size_t(visit[k])] = root_level[k];
      break;
    }
    root = candidate, depth = candidate_depth;
  }
  return root;
}

std::vector<int> split_in_two(const MatrixGraph &g) {
  const int n = g.nodes();
  if (n < 3) return {};
  // From the first node's component (the matrices split here are connected: both bodies and the
  // rows that join them; where it is not, its halves hold too few nodes and nothing is split).
  std::vector<char> numbered(static_cast<size_t>(n), 0);
  std::vector<int> level(static_cast<size_t>(n), -1), visit;
  pseudo_peripheral_node(g, 0, numbered, level, visit);
  // The level at which half of the component has been visited (the search visits by level).
  const int middle = level[size_t(visit[visit.size() / 2])];
  std::vector<int> part(static_cast<size_t>(n), 0);
  int count[3] = {0, 0, 0};
  for (int v : visit) {
    const int l = level[size_t(v)];
    const int side = l < middle ? 0 : l > middle ? 1 : 2;
    part[size_t(v)] = side, ++count[side];
  }
  count[0] = n - count[1] - count[2];  // (with the other components)
  if (count[0] < n / 4 || count[1] < n / 4) return {};
  return part;
}

SymbolicFactor::SymbolicFactor(const SymmetricCsc &a, const int *perm) {
  const int n = a.n;
  std::vector<int> position(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) position[size_t(perm[k])] = k;
  // Each off-diagonal entry as (later, earlier) in the order, grouped by the later: row k of the
  // ordered matrix's lower triangle.
  start_.assign(size_t(n) + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
      if (a.rows[p] != j) ++start_[size_t(std::max(position[size_t(j)], position[size_t(a.rows[p])])) + 1];
  for (int k = 0; k < n; ++k) start_[size_t(k) + 1] += start_[size_t(k)];
  earlier_.resize(static_cast<size_t>(start_[size_t(n)]));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
      if (a.rows[p] != j) {
        const int x = position[size_t(j)], y = position[size_t(a.rows[p])];
        earlier_[size_t(fill[size_t(std::max(x, y))]++)] = std::min(x, y);
      }
  parent.assign(static_cast<size_t>(n), -1);
  count.assign(static_cast<size_t>(n), 1);  // the diagonal
  ancestor_.assign(static_cast<size_t>(n), -1), mark_.assign(static_cast<size_t>(n), -1);
}

void SymbolicFactor::rows(int first, int last) {
  for (int k = first; k < last; ++k) {
    const int *begin = earlier_.data() + start_[size_t(k)], *end = earlier_.data() + start_[size_t(k) + 1];
    // 1. Liu's algorithm: row k's entries make k the parent of the roots of their subtrees.
    for (const int *q = begin; q < end; ++q)
      for (int r = *q; r != -1 && r != k;) {
        const int next = ancestor_[size_t(r)];
        ancestor_[size_t(r)] = k;
        if (next == -1) parent[size_t(r)] = k;
        r = next;
      }
    // 2. Row k of L: the row subtree, the columns on the tree paths from row k's entries up to k
    //    (each column below k has its parent by now). Each visited once per row: L(k, j) != 0.
    mark_[size_t(k)] = k;
    for (const int *q = begin; q < end; ++q)
      for (int j = *q; mark_[size_t(j)] != k; j = parent[size_t(j)]) mark_[size_t(j)] = k, ++count[size_t(j)];
  }
}

}  // namespace mc
