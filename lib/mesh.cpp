#include "mesh.hpp"
#include "error.hpp"
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <map>

namespace mc {

Mesh::Mesh(int n_nodes, const double *xy, int n_cells, int nodes_per_cell, const int *cells, int base)
    : n_nodes_(n_nodes), n_cells_(n_cells), nodes_per_cell_(nodes_per_cell) {
  if (n_nodes < 3) fail(MC_ERROR_ARGUMENT, "n_nodes = %d: a mesh needs at least 3 nodes", n_nodes);
  if (n_cells < 1) fail(MC_ERROR_ARGUMENT, "n_cells = %d: a mesh needs at least 1 cell", n_cells);
  if (nodes_per_cell != 3 && nodes_per_cell != 4)
    fail(MC_ERROR_ARGUMENT, "nodes_per_cell = %d: must be 3 (P1 triangle) or 4 (Q1 quadrilateral)",
         nodes_per_cell);
  if (!xy) fail(MC_ERROR_ARGUMENT, "xy is NULL");
  if (!cells) fail(MC_ERROR_ARGUMENT, "cells is NULL");
  xy_.assign(xy, xy + 2 * size_t(n_nodes));
  double xmin = xy_[0], xmax = xy_[0], ymin = xy_[1], ymax = xy_[1];
  for (size_t i = 0; i < xy_.size(); ++i) {
    if (!std::isfinite(xy_[i])) fail(MC_ERROR_ARGUMENT, "xy[%zu] (node %zu) is not finite", i, i / 2);
    if (i % 2 == 0) xmin = std::min(xmin, xy_[i]), xmax = std::max(xmax, xy_[i]);
    else ymin = std::min(ymin, xy_[i]), ymax = std::max(ymax, xy_[i]);
  }
  length_scale_ = std::max(xmax - xmin, ymax - ymin);
  if (!(length_scale_ > 0)) fail(MC_ERROR_MESH, "xy: all %d nodes coincide (the mesh has no extent)", n_nodes);
  cells_.assign(cells, cells + size_t(n_cells) * nodes_per_cell);
  std::vector<char> used(n_nodes, 0);
  for (size_t k = 0; k < cells_.size(); ++k) {
    int id = cells_[k];
    if (id < 0 || id >= n_nodes)
      fail(MC_ERROR_ARGUMENT, "cells[%zu] = %d (cell %zu): node id out of range [%d, %d)", k, id + base,
           k / nodes_per_cell + base, base, n_nodes + base);
    used[id] = 1;
  }
  for (int c = 0; c < n_cells; ++c) {
    const int *v = cell(c);
    for (int a = 0; a < nodes_per_cell; ++a)
      for (int b = a + 1; b < nodes_per_cell; ++b)
        if (v[a] == v[b]) fail(MC_ERROR_MESH, "cell %d uses node %d twice", c + base, v[a] + base);
  }
  for (int i = 0; i < n_nodes; ++i)
    if (!used[i]) fail(MC_ERROR_MESH, "node %d is used by no cell (it would have no stiffness)", i + base);
  check_cell_shapes(base);
  derive_boundary(base);
}

// Cells must be counter-clockwise and non-degenerate; a quadrilateral must also be convex
// (its bilinear map then has a positive Jacobian everywhere). The tolerance is relative to
// the cell's own size, so the check does not depend on units.
void Mesh::check_cell_shapes(int base) {
  const int n = nodes_per_cell_;
  for (int c = 0; c < n_cells_; ++c) {
    const int *v = cell(c);
    double longest2 = 0;  // the longest side, squared
    for (int a = 0; a < n; ++a) {
      Point p = node(v[a]), q = node(v[(a + 1) % n]);
      longest2 = std::max(longest2, (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y));
    }
    for (int a = 0; a < n; ++a) {
      Point p = node(v[(a + n - 1) % n]), q = node(v[a]), r = node(v[(a + 1) % n]);
      double corner = (q.x - p.x) * (r.y - q.y) - (q.y - p.y) * (r.x - q.x);
      if (!(corner > 1e-12 * longest2))
        fail(MC_ERROR_MESH,
             "cell %d is %s at its corner %d (node %d): cells must be counter-clockwise, "
             "non-degenerate%s",
             c + base, corner < 0 ? "clockwise or non-convex" : "degenerate", a, v[a] + base,
             n == 4 ? " and convex" : "");
    }
  }
}

// Duplicated cells: the same node set twice. Only called when derive_boundary has found an
// edge used wrongly: a duplicate that passed check_cell_shapes has the same orientation as its
// original (a reversed or reordered copy is clockwise or not convex), so it repeats the
// original's directed edges, and this finds the cause to name.
void Mesh::fail_on_duplicate_cell(int base) const {
  const int n = nodes_per_cell_;
  std::map<std::array<int, 4>, int> seen;
  for (int c = 0; c < n_cells_; ++c) {
    std::array<int, 4> key{INT_MAX, INT_MAX, INT_MAX, INT_MAX};  // a triangle's fourth slot stays last
    std::copy(cell(c), cell(c) + n, key.begin());
    std::sort(key.begin(), key.end());
    auto [it, fresh] = seen.emplace(key, c);
    if (!fresh) fail(MC_ERROR_MESH, "cell %d duplicates cell %d", c + base, it->second + base);
  }
}

uint64_t Mesh::edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}

// An edge used by one cell is on the boundary; by two, interior; by more, the mesh is not a
// surface. Two cells using the same edge in the same direction overlap (one is inverted).
// The uses of an edge are found by bucketing the directed edges by their smaller node (a
// counting sort) and sorting each small bucket by the other node: linear in the cells, with
// no hash table over all edges. A wrong edge is reported as the first one met in cell order.
void Mesh::derive_boundary(int base) {
  const int npc = nodes_per_cell_;
  const size_t n_uses = size_t(n_cells_) * npc;  // use k: edge k % npc of cell k / npc
  auto from = [&](size_t k) { return cells_[k]; };
  auto to = [&](size_t k) { return cells_[k % npc == size_t(npc - 1) ? k + 1 - npc : k + 1]; };
  auto low = [&](size_t k) { return std::min(from(k), to(k)); };
  auto high = [&](size_t k) { return std::max(from(k), to(k)); };
  std::vector<size_t> start(size_t(n_nodes_) + 1, 0);
  for (size_t k = 0; k < n_uses; ++k) start[low(k) + 1]++;
  for (int i = 0; i < n_nodes_; ++i) start[i + 1] += start[i];
  std::vector<size_t> use(n_uses), next(start.begin(), start.end() - 1);
  for (size_t k = 0; k < n_uses; ++k) use[next[low(k)]++] = k;
  size_t wrong = n_uses, first_use = 0;  // the first wrong use in cell order, and its edge's first use
  bool overlap = false;                    // wrong is a second use in the first one's direction
  std::vector<size_t> single;
  for (int i = 0; i < n_nodes_; ++i) {
    auto begin = use.begin() + start[i], end = use.begin() + start[i + 1];
    std::sort(begin, end, [&](size_t a, size_t b) { return high(a) != high(b) ? high(a) < high(b) : a < b; });
    for (auto g = begin; g != end;) {
      auto g_end = g + 1;
      while (g_end != end && high(*g_end) == high(*g)) ++g_end;
      const size_t count = size_t(g_end - g);
      if (count == 1) single.push_back(*g);
      else if (from(g[1]) == from(g[0]) || count > 2) {  // overlap at the second use, or a third use
        const bool same_direction = from(g[1]) == from(g[0]);
        const size_t k = same_direction ? g[1] : g[2];
        if (k < wrong) wrong = k, first_use = g[0], overlap = same_direction;
      }
      g = g_end;
    }
  }
  if (wrong < n_uses) {
    fail_on_duplicate_cell(base);
    const int c = int(wrong / npc), a = from(wrong), b = to(wrong);
    if (overlap)
      fail(MC_ERROR_MESH, "cells %d and %d overlap along edge %d-%d", int(first_use / npc) + base, c + base, a + base,
           b + base);
    fail(MC_ERROR_MESH, "edge %d-%d of cell %d is shared by more than two cells", a + base, b + base, c + base);
  }
  boundary_.reserve(single.size());
  for (size_t k : single) boundary_.emplace(edge_key(from(k), to(k)), BoundaryEdge{from(k), to(k), int(k / npc)});
}

const BoundaryEdge *Mesh::boundary_edge(int a, int b) const {
  auto it = boundary_.find(edge_key(a, b));
  return it == boundary_.end() ? nullptr : &it->second;
}

}  // namespace mc
