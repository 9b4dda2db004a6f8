// Mesh intake of one body: validated nodes and cells (P1 and T6 triangles, Q1, Q8 and Q9
// quadrilaterals: cell_shapes.hpp) and the boundary edges derived from them.
#pragma once
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mc {

struct Point {
  double x, y;
};

// A boundary edge oriented as in its cell (counter-clockwise), so the body lies on its left
// and its outward normal is (dy, -dx)/length.
// On a quadratic mesh the edge is a 3-node line: its mid-edge node is `mid` (-1 on a linear mesh).
struct BoundaryEdge {
  int from, to;
  int cell;
  int mid = -1;
};

class Mesh {
public:
  // Validates and copies. ids are 0-based here (the C API layer removes the index base);
  // messages show ids plus `base`, as the caller numbers them.
  // Throws mc::Error naming the argument and index on bad input.
  Mesh(int n_nodes, const double *xy, int n_cells, int nodes_per_cell, const int *cells, int base = 0);
  Mesh() = default;
  // Nodes without cells: a host body's (mc_set_host_body). No boundary is derived; its contact
  // edges come oriented from the host.
  static Mesh points(int n_nodes, const double *xy, int base);  // base: for the messages

  int n_nodes() const { return n_nodes_; }
  int n_cells() const { return n_cells_; }
  int nodes_per_cell() const { return nodes_per_cell_; }
  int corners_per_cell() const { return corners_; }
  bool quadratic() const { return nodes_per_cell_ > 4; }
  Point node(int i) const { return {xy_[2 * i], xy_[2 * i + 1]}; }
  const int *cell(int c) const { return &cells_[size_t(c) * nodes_per_cell_]; }
  const std::vector<double> &xy() const { return xy_; }
  double characteristic_length() const { return length_scale_; }

  // The boundary edge joining nodes a and b (either order), or nullptr if a-b is not a
  // boundary edge.
  const BoundaryEdge *boundary_edge(int a, int b) const;
  // Whether node i is a corner of some cell (every node of a linear mesh is).
  bool is_corner(int i) const { return !quadratic() || corner_[i]; }
  // " (node 7 is a mid-edge node: an edge is named by its two corner nodes)", or "" if a and b
  // are corners: what a message about a bad edge adds on a quadratic mesh.
  const char *edge_hint(int a, int b, int base, char *buffer, int size) const;

private:
  static uint64_t edge_key(int a, int b);
  void check_cell_shapes(int base);
  void check_jacobians(int base) const;
  bool straight_sided_jacobian_positive(int c, double threshold) const;
  void check_node_roles(int base) const;
  void derive_boundary(int base);
  void fail_on_duplicate_cell(int base) const;

  int n_nodes_ = 0, n_cells_ = 0, nodes_per_cell_ = 0, corners_ = 0;
  std::vector<double> xy_;
  std::vector<int> cells_;
  std::vector<char> corner_;  // quadratic meshes: per node, a corner of some cell
  double length_scale_ = 1.0;
  std::unordered_map<uint64_t, BoundaryEdge> boundary_;
};

}  // namespace mc
