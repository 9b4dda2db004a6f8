#include "linalg/envelope_bound.hpp"
#include <algorithm>
#include <vector>

namespace mc {

namespace {

// The matrix's graph: both triangles' off-diagonal entries, CSR.
struct Graph {
  std::vector<int> start, next;
  int degree(int v) const { return start[v + 1] - start[v]; }
};

Graph graph_of(const SymmetricCsc &a) {
  Graph g;
  g.start.assign(a.n + 1, 0);
  for (int j = 0; j < a.n; ++j)
    for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
      if (a.rows[p] != j) ++g.start[a.rows[p] + 1], ++g.start[j + 1];
  for (int v = 0; v < a.n; ++v) g.start[v + 1] += g.start[v];
  g.next.resize(g.start[a.n]);
  std::vector<int> fill(g.start.begin(), g.start.end() - 1);
  for (int j = 0; j < a.n; ++j)
    for (int p = a.colptr[j]; p < a.colptr[j + 1]; ++p)
      if (a.rows[p] != j) g.next[fill[a.rows[p]]++] = j, g.next[fill[j]++] = a.rows[p];
  return g;
}

// Breadth-first search from `root` over the nodes not yet numbered (level[v] < 0 marks them
// for this search; reset afterwards); the nodes in visiting order, each level's neighbours by
// increasing degree when `by_degree` (Cuthill-McKee). Returns the number of levels.
int breadth_first(const Graph &g, int root, bool by_degree, const std::vector<char> &numbered, std::vector<int> &level,
                  std::vector<int> &visit) {
  visit.clear();
  visit.push_back(root);
  level[root] = 0;
  int depth = 1;
  for (size_t head = 0; head < visit.size(); ++head) {
    const int v = visit[head];
    const size_t first = visit.size();
    for (int p = g.start[v]; p < g.start[v + 1]; ++p) {
      const int w = g.next[p];
      if (!numbered[w] && level[w] < 0) level[w] = level[v] + 1, visit.push_back(w), depth = std::max(depth, level[w] + 1);
    }
    if (by_degree)
      std::sort(visit.begin() + long(first), visit.end(), [&](int x, int y) { return g.degree(x) < g.degree(y); });
  }
  return depth;
}

}  // namespace

EnvelopeBound envelope_cholesky_bound(const SymmetricCsc &a) {
  EnvelopeBound bound;
  const int n = a.n;
  if (n == 0) return bound;
  const Graph g = graph_of(a);
  std::vector<char> numbered(n, 0);
  std::vector<int> level(n, -1), visit, order;
  order.reserve(n);
  auto reset = [&] {
    for (int v : visit) level[v] = -1;
  };
  for (int seed = 0; seed < n; ++seed) {
    if (numbered[seed]) continue;
    // A pseudo-peripheral root (Gibbs, Poole and Stockmeyer): from the far end of a search,
    // a node of least degree in its last level, while the depth grows (a few searches).
    int root = seed, depth = breadth_first(g, root, false, numbered, level, visit);
    for (int tries = 0; tries < 4; ++tries) {
      int candidate = -1;
      for (int v : visit)
        if (level[v] == depth - 1 && (candidate < 0 || g.degree(v) < g.degree(candidate))) candidate = v;
      reset();
      const int candidate_depth = breadth_first(g, candidate, false, numbered, level, visit);
      if (candidate_depth <= depth) break;
      root = candidate, depth = candidate_depth;  // (the search from it is the one in `visit`)
    }
    reset();
    breadth_first(g, root, true, numbered, level, visit);
    reset();
    for (int v : visit) numbered[v] = 1, order.push_back(v);
  }
  std::reverse(order.begin(), order.end());  // reverse Cuthill-McKee: a smaller envelope
  std::vector<int> position(n);
  for (int i = 0; i < n; ++i) position[order[i]] = i;
  // Row i of L lies in columns first(i) .. i (first(i): its leftmost neighbour before it): it
  // adds one to the counts of those columns (a difference array).
  std::vector<int> count(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    const int v = order[i];
    int first = i;
    for (int p = g.start[v]; p < g.start[v + 1]; ++p) first = std::min(first, position[g.next[p]]);
    ++count[first], --count[i + 1];
  }
  double c = 0;
  for (int j = 0; j < n; ++j) {
    c += count[j];
    bound.nnz += c, bound.flops += c * c;
  }
  return bound;
}

}  // namespace mc
