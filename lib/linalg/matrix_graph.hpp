// The graph of a symmetric sparse matrix and the breadth-first searches the orderings make on
// it: the reverse Cuthill-McKee envelope (envelope_bound.cpp) and the split of a matrix in two
// halves by one level of a search (SparseCholesky's analysis on the sparse interface path).
#pragma once
#include "bodies/assembly.hpp"
#include <vector>

namespace mc {

// Both triangles' off-diagonal entries, CSR.
struct MatrixGraph {
  std::vector<int> start, next;
  int nodes() const { return int(start.size()) - 1; }
  int degree(int v) const { return start[size_t(v) + 1] - start[size_t(v)]; }
};

// a: the upper triangle by columns (SymmetricCsc).
MatrixGraph graph_of(const SymmetricCsc &a);

// Breadth-first search from `root` over the nodes not yet numbered (level[v] < 0 marks them
// for this search; the caller resets them); the nodes in visiting order, each level's
// neighbours by increasing degree when `by_degree` (Cuthill-McKee). Returns the number of levels.
int breadth_first(const MatrixGraph &g, int root, bool by_degree, const std::vector<char> &numbered, std::vector<int> &level,
                  std::vector<int> &visit);

// A pseudo-peripheral node of seed's component (Gibbs, Poole and Stockmeyer): from the far end
// of a search, a node of least degree in its last level, while the depth grows (a few searches).
// On return `visit` and `level` hold the search from it (levels of the visited nodes set).
int pseudo_peripheral_node(const MatrixGraph &g, int seed, const std::vector<char> &numbered, std::vector<int> &level,
                           std::vector<int> &visit);

// Two halves and a separator: part[v] = 0 or 1 for the halves, 2 for the separator, such that no
// entry of the matrix joins the two halves. The separator is the level of a breadth-first search
// from a pseudo-peripheral node of the first node's component at which half of its nodes have
// been visited: on a long strip, one cross-section. Nodes of other components go to half 0. Empty
// when the separator would not leave each half a quarter of the nodes.
std::vector<int> split_in_two(const MatrixGraph &g);

// The elimination tree of the Cholesky factor of P A P^T (a: the upper triangle by columns; perm:
// the order, perm[k] = the unknown eliminated k-th): each column's parent (-1 at a root), in
// the factor's order (Liu's algorithm with path compression; O(nnz) memory for the pattern
// sorted by the later of each entry's two positions).
std::vector<int> elimination_tree(const SymmetricCsc &a, const int *perm);

}  // namespace mc
