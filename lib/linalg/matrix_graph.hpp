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

// The symbolic Cholesky factor of P A P^T (a: the upper triangle by columns; perm: the order,
// perm[k] = the unknown eliminated k-th), in the factor's order: the elimination tree (each
// column's parent, -1 at a root; Liu's algorithm with path compression) and the column counts of
// L, the diagonal included (each row's subtree walked once: O(nnz(L)) time, O(nnz(A)) memory).
// Made row by row: rows(first, last) once the rows its rows name are done, so that two ranges
// whose rows name no column of the other (two halves of a split order) may run at once.
class SymbolicFactor {
 public:
  SymbolicFactor(const SymmetricCsc &a, const int *perm);  // the ordered matrix's rows, nothing counted
  void rows(int first, int last);
  std::vector<int> parent, count;

 private:
  std::vector<int> start_, earlier_;  // row k's columns before k: earlier_[start_[k] .. start_[k + 1])
  std::vector<int> ancestor_, mark_;
};

}  // namespace mc
