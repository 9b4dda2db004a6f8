#include "linalg/envelope_bound.hpp"
#include "linalg/matrix_graph.hpp"
#include <algorithm>
#include <vector>

namespace mc {

EnvelopeBound envelope_cholesky_bound(const SymmetricCsc &a) {
  EnvelopeBound bound;
  const int n = a.n;
  if (n == 0) return bound;
  const MatrixGraph g = graph_of(a);
  std::vector<char> numbered(n, 0);
  std::vector<int> level(n, -1), visit, order;
  order.reserve(n);
  auto reset = [&] {
    for (int v : visit) level[v] = -1;
  };
  for (int seed = 0; seed < n; ++seed) {
    if (numbered[seed]) continue;
    const int root = pseudo_peripheral_node(g, seed, numbered, level, visit);
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
