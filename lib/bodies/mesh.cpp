#include "bodies/mesh.hpp"
#include "bodies/cell_shapes.hpp"
#include "support/error.hpp"
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>

namespace mc {

Mesh::Mesh(int n_nodes, const double *xy, int n_cells, int nodes_per_cell, const int *cells, int base)
    : n_nodes_(n_nodes), n_cells_(n_cells), nodes_per_cell_(nodes_per_cell) {
  if (n_nodes < 3) fail(MC_ERROR_ARGUMENT, "n_nodes = %d: a mesh needs at least 3 nodes", n_nodes);
  if (n_cells < 1) fail(MC_ERROR_ARGUMENT, "n_cells = %d: a mesh needs at least 1 cell", n_cells);
  if (!is_cell_kind(nodes_per_cell))
    fail(MC_ERROR_ARGUMENT,
         "nodes_per_cell = %d: must be 3 (P1 triangle), 4 (Q1 quadrilateral), 6 (T6 triangle), 8 (Q8 "
         "quadrilateral) or 9 (Q9 quadrilateral)",
         nodes_per_cell);
  corners_ = cell_type(nodes_per_cell).corners;
  if (!xy) fail(MC_ERROR_ARGUMENT, "xy is NULL");
  if (!cells) fail(MC_ERROR_ARGUMENT, "cells is NULL");
  xy_.assign(xy, xy + 2 * size_t(n_nodes));
  double xmin = xy_[0], xmax = xy_[0], ymin = xy_[1], ymax = xy_[1];
  for (size_t i = 0; i < xy_.size(); ++i) {
    if (!std::isfinite(xy_[i]))
      fail(MC_ERROR_ARGUMENT, "%s (node %zu) is not finite", array_position("xy", i, base).c_str(), i / 2 + base);
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
      fail(MC_ERROR_ARGUMENT, "%s = %d (cell %zu): node id out of range [%d, %d)", array_position("cells", k, base).c_str(), id + base,
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
  if (quadratic()) {
    corner_.assign(n_nodes_, 0);
    for (int c = 0; c < n_cells_; ++c)
      for (int a = 0; a < corners_; ++a) corner_[cell(c)[a]] = 1;
    check_node_roles(base);
    check_jacobians(base);
  }
  derive_boundary(base);
}

Mesh Mesh::points(int n_nodes, const double *xy, int base) {
  Mesh mesh;
  if (n_nodes < 1) fail(MC_ERROR_ARGUMENT, "n_nodes = %d: a host body needs at least 1 node", n_nodes);
  if (!xy) fail(MC_ERROR_ARGUMENT, "xy is NULL");
  mesh.n_nodes_ = n_nodes;
  mesh.xy_.assign(xy, xy + 2 * size_t(n_nodes));
  double xmin = xy[0], xmax = xy[0], ymin = xy[1], ymax = xy[1];
  for (size_t i = 0; i < mesh.xy_.size(); ++i) {
    if (!std::isfinite(mesh.xy_[i]))
      fail(MC_ERROR_ARGUMENT, "%s (node %zu) is not finite", array_position("xy", i, base).c_str(), i / 2 + base);
    if (i % 2 == 0) xmin = std::min(xmin, mesh.xy_[i]), xmax = std::max(xmax, mesh.xy_[i]);
    else ymin = std::min(ymin, mesh.xy_[i]), ymax = std::max(ymax, mesh.xy_[i]);
  }
  mesh.length_scale_ = std::max(xmax - xmin, ymax - ymin);
  if (!(mesh.length_scale_ > 0)) mesh.length_scale_ = 1;  // one node, or all at one point
  return mesh;
}

// Cells must be counter-clockwise and non-degenerate; a quadrilateral must also be convex
// (its bilinear map then has a positive Jacobian everywhere). The tolerance is relative to
// the cell's own size, so the check does not depend on units.
void Mesh::check_cell_shapes(int base) {
  const int n = corners_;
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
  const int n = corners_;  // a duplicate has the same corners
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
  const int npc = corners_, stride = nodes_per_cell_;
  const size_t n_uses = size_t(n_cells_) * npc;  // use k: edge k % npc of cell k / npc (corner to corner)
  auto from = [&](size_t k) { return cells_[(k / npc) * stride + k % npc]; };
  auto to = [&](size_t k) { return cells_[(k / npc) * stride + (k % npc + 1) % npc]; };
  auto mid = [&](size_t k) { return quadratic() ? cells_[(k / npc) * stride + npc + k % npc] : -1; };
  auto low = [&](size_t k) { return std::min(from(k), to(k)); };
  auto high = [&](size_t k) { return std::max(from(k), to(k)); };
  std::vector<size_t> start(size_t(n_nodes_) + 1, 0);
  for (size_t k = 0; k < n_uses; ++k) start[low(k) + 1]++;
  for (int i = 0; i < n_nodes_; ++i) start[i + 1] += start[i];
  std::vector<size_t> use(n_uses), next(start.begin(), start.end() - 1);
  for (size_t k = 0; k < n_uses; ++k) use[next[low(k)]++] = k;
  size_t wrong = n_uses, first_use = 0;  // the first wrong use in cell order, and its edge's first use
  bool overlap = false;                    // wrong is a second use in the first one's direction
  size_t mid_mismatch = n_uses, mid_first = 0;  // an interior edge whose two cells name different middles
  std::vector<size_t> single;
  for (int i = 0; i < n_nodes_; ++i) {
    auto begin = use.begin() + start[i], end = use.begin() + start[i + 1];
    std::sort(begin, end, [&](size_t a, size_t b) { return high(a) != high(b) ? high(a) < high(b) : a < b; });
    for (auto g = begin; g != end;) {
      auto g_end = g + 1;
      while (g_end != end && high(*g_end) == high(*g)) ++g_end;
      const size_t count = size_t(g_end - g);
      if (count == 1) single.push_back(*g);
      else if (count == 2 && from(g[1]) != from(g[0]) && mid(g[0]) != mid(g[1])) {
        if (g[1] < mid_mismatch) mid_mismatch = g[1], mid_first = g[0];
      } else if (from(g[1]) == from(g[0]) || count > 2) {  // overlap at the second use, or a third use
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
  if (mid_mismatch < n_uses) {
    const size_t k = mid_mismatch, k0 = mid_first;
    fail(MC_ERROR_MESH,
         "cells %d and %d share edge %d-%d but give it different mid-edge nodes (%d and %d): a quadratic edge "
         "has one middle node, shared by both cells",
         int(k0 / npc) + base, int(k / npc) + base, from(k0) + base, to(k0) + base, mid(k0) + base, mid(k) + base);
  }
  boundary_.reserve(single.size());
  for (size_t k : single)
    boundary_.emplace(edge_key(from(k), to(k)), BoundaryEdge{from(k), to(k), int(k / npc), mid(k)});
}

// Each node of a quadratic mesh has one role: a corner (of any number of cells), the middle of
// one edge (of the one or two cells sharing it), or the centre of one Q9 cell. A node in two
// roles makes cells that do not fit together.
void Mesh::check_node_roles(int base) const {
  const int nc = corners_, npc = nodes_per_cell_;
  enum Role { kNone, kCorner, kMid, kCentre };
  std::vector<char> role(n_nodes_, kNone);
  std::vector<int> first_cell(n_nodes_, -1);
  std::vector<uint64_t> edge_of(n_nodes_, 0);
  for (int c = 0; c < n_cells_; ++c)
    for (int a = 0; a < nc; ++a) {
      const int v = cell(c)[a];
      if (role[v] == kNone) role[v] = kCorner, first_cell[v] = c;
    }
  for (int c = 0; c < n_cells_; ++c)
    for (int a = nc; a < npc; ++a) {
      const int v = cell(c)[a];
      const bool centre = a == 8;
      const int e0 = cell(c)[a - nc], e1 = cell(c)[(a - nc + 1) % nc];
      const uint64_t key = centre ? ~uint64_t(c) : edge_key(e0, e1);
      if (role[v] == kCorner)
        fail(MC_ERROR_MESH, "node %d is a corner of cell %d and also the %s of cell %d%s", v + base, first_cell[v] + base,
             centre ? "centre node" : "mid-edge node", c + base, centre ? "" : " (of its edge between two corners)");
      if (role[v] == kNone) {
        role[v] = centre ? kCentre : kMid, first_cell[v] = c, edge_of[v] = key;
        continue;
      }
      if (edge_of[v] != key || centre)
        fail(MC_ERROR_MESH, "node %d is the %s of cell %d and also the %s of cell %d: a mid-edge node belongs to one "
             "edge, a centre node to one cell",
             v + base, role[v] == kCentre ? "centre node" : "mid-edge node", first_cell[v] + base,
             centre ? "centre node" : "mid-edge node of another edge", c + base);
    }
}

// An isoparametric cell is valid if its map is one-to-one: the Jacobian determinant keeps its
// sign (positive: counter-clockwise) everywhere in the cell, not only at the corners, where a
// misplaced mid-edge node can fold an edge while the corners look fine. It is checked on a
// lattice of the reference cell, corners and edges included (45 points on a triangle, 81 on a
// quadrilateral), against 1e-8 of its mean over the cell.
void Mesh::check_jacobians(int base) const {
  const int npc = nodes_per_cell_;
  const bool triangle = corners_ == 3;
  constexpr int kSteps = 8;
  // The lattice and its shape derivatives, once for every cell.
  struct LatticePoint {
    double xi, eta, dxi[kMaxCellNodes], deta[kMaxCellNodes];
  };
  std::vector<LatticePoint> lattice;
  for (int j = 0; j <= kSteps; ++j)
    for (int i = 0; i <= kSteps; ++i) {
      if (triangle && i + j > kSteps) continue;
      LatticePoint point;
      point.xi = triangle ? double(i) / kSteps : -1 + 2.0 * i / kSteps;
      point.eta = triangle ? double(j) / kSteps : -1 + 2.0 * j / kSteps;
      double n[kMaxCellNodes];
      reference_shapes(npc, point.xi, point.eta, n, point.dxi, point.deta);
      lattice.push_back(point);
    }
  const double reference_area = triangle ? 0.5 : 4;
  for (int c = 0; c < n_cells_; ++c) {
    const int *v = cell(c);
    double area = 0;  // of the corner polygon: the mean Jacobian of a straight-sided cell
    for (int a = 0; a < corners_; ++a) {
      const Point p = node(v[a]), q = node(v[(a + 1) % corners_]);
      area += 0.5 * (p.x * q.y - q.x * p.y);
    }
    const double threshold = 1e-8 * area / reference_area;
    if (straight_sided_jacobian_positive(c, threshold)) continue;
    for (const LatticePoint &point : lattice) {
      double j11 = 0, j12 = 0, j21 = 0, j22 = 0;
      for (int a = 0; a < npc; ++a) {
        const Point p = node(v[a]);
        j11 += point.dxi[a] * p.x, j12 += point.dxi[a] * p.y, j21 += point.deta[a] * p.x, j22 += point.deta[a] * p.y;
      }
      const double det = j11 * j22 - j12 * j21;
      if (det > threshold) continue;
      int nearest = 0;  // the node nearest to the failing point, in reference coordinates
      double best = 1e300;
      for (int a = 0; a < npc; ++a) {
        double xa, ya;
        reference_node(npc, a, xa, ya);
        const double d = std::hypot(xa - point.xi, ya - point.eta);
        if (d < best) best = d, nearest = a;
      }
      fail(MC_ERROR_MESH,
           "cell %d (%s) is inverted or folded inside: its Jacobian is %s at reference point (%g, %g), nearest its "
           "node %d (node %d): check the mid-edge nodes' positions (a middle node must lie well inside its edge's "
           "middle half) and that the corners are counter-clockwise",
           c + base, cell_name(npc), det < 0 ? "negative" : "zero", point.xi, point.eta, nearest, v[nearest] + base);
    }
  }
}

// A cell whose middles sit at their edges' midpoints (and a Q9 centre at the corners' mean), to
// round-off, has the map of its corners: affine (T6), whose Jacobian is constant, twice the
// corner triangle's area; or bilinear (Q8, Q9), whose Jacobian is linear in xi and in eta, so
// smallest at a corner. Then the corners decide what the lattice would. False: not
// straight-sided, or a corner at or below the threshold (the lattice then names the point).
bool Mesh::straight_sided_jacobian_positive(int c, double threshold) const {
  const int *v = cell(c);
  double longest = 0;
  for (int a = 0; a < corners_; ++a) {
    const Point p = node(v[a]), q = node(v[(a + 1) % corners_]);
    longest = std::max(longest, std::hypot(q.x - p.x, q.y - p.y));
  }
  const double tolerance = 1e-12 * longest;
  auto near = [&](Point p, double x, double y) { return std::fabs(p.x - x) <= tolerance && std::fabs(p.y - y) <= tolerance; };
  for (int a = 0; a < corners_; ++a) {
    const Point p = node(v[a]), q = node(v[(a + 1) % corners_]);
    if (!near(node(v[corners_ + a]), 0.5 * (p.x + q.x), 0.5 * (p.y + q.y))) return false;
  }
  if (nodes_per_cell_ == 9) {
    double x = 0, y = 0;
    for (int a = 0; a < 4; ++a) x += 0.25 * node(v[a]).x, y += 0.25 * node(v[a]).y;
    if (!near(node(v[8]), x, y)) return false;
  }
  for (int a = 0; a < corners_; ++a) {
    // The Jacobian at corner a: (x_{a+1} - x_a) x (x_{a-1} - x_a), over 1 (triangle) or 4.
    const Point p = node(v[a]), next = node(v[(a + 1) % corners_]), previous = node(v[(a + corners_ - 1) % corners_]);
    const double cross = (next.x - p.x) * (previous.y - p.y) - (next.y - p.y) * (previous.x - p.x);
    if (!(cross / (corners_ == 3 ? 1 : 4) > threshold)) return false;
  }
  return true;
}

const char *Mesh::edge_hint(int a, int b, int base, char *buffer, int size) const {
  buffer[0] = 0;
  for (int v : {a, b})
    if (v >= 0 && v < n_nodes_ && !is_corner(v)) {
      std::snprintf(buffer, size_t(size), " (node %d is a mid-edge or centre node: an edge of a quadratic cell is named by its two corner nodes)", v + base);
      break;
    }
  return buffer;
}

const BoundaryEdge *Mesh::boundary_edge(int a, int b) const {
  auto it = boundary_.find(edge_key(a, b));
  return it == boundary_.end() ? nullptr : &it->second;
}

}  // namespace mc
