#include "contact_geometry.hpp"
#include "error.hpp"
#include "mortarcontact.h"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

double cross(Point u, Point v) { return u.x * v.y - u.y * v.x; }
Point minus(Point u, Point v) { return {u.x - v.x, u.y - v.y}; }
Point lerp(Point u, Point v, double s) { return {u.x + s * (v.x - u.x), u.y + s * (v.y - u.y)}; }
Point unit(Point u) {
  double l = std::hypot(u.x, u.y);
  return {u.x / l, u.y / l};
}
// Outward normal of an edge a->b with the body on its left.
Point edge_normal(Point a, Point b) { return unit({b.y - a.y, a.x - b.x}); }

// Chains of a surface: sequences of nodes following the edges' orientation.
struct Chain {
  std::vector<int> nodes;
  bool closed = false;
};

std::vector<Chain> chains_of(const std::vector<SurfaceSegment> &surface) {
  std::vector<std::pair<int, int>> next;  // (from, to), sorted by from
  for (auto &s : surface) next.push_back({s.a, s.b});
  std::sort(next.begin(), next.end());
  auto successor = [&](int node) {
    auto it = std::lower_bound(next.begin(), next.end(), std::make_pair(node, -1));
    return it != next.end() && it->first == node ? it->second : -1;
  };
  std::vector<int> heads;
  {
    std::vector<int> targets;
    for (auto &s : surface) targets.push_back(s.b);
    std::sort(targets.begin(), targets.end());
    for (auto &s : surface)
      if (!std::binary_search(targets.begin(), targets.end(), s.a)) heads.push_back(s.a);
    std::sort(heads.begin(), heads.end());
  }
  std::vector<char> used_edge(next.size(), 0);
  auto take = [&](int from) {
    auto it = std::lower_bound(next.begin(), next.end(), std::make_pair(from, -1));
    used_edge[it - next.begin()] = 1;
  };
  std::vector<Chain> chains;
  for (int head : heads) {
    Chain c;
    for (int node = head; node >= 0; node = successor(node)) {
      c.nodes.push_back(node);
      if (successor(node) >= 0) take(node);
    }
    chains.push_back(c);
  }
  for (size_t e = 0; e < next.size(); ++e) {  // what is left are closed loops
    if (used_edge[e]) continue;
    Chain c;
    c.closed = true;
    int start = next[e].first;
    int node = start;
    do {
      c.nodes.push_back(node);
      take(node);
      node = successor(node);
    } while (node != start);
    chains.push_back(c);
  }
  return chains;
}

// Ray p + t n against body 2's segments: the facing segment hit nearest to p (|t| least).
// Returns t (kNoGap if no hit) and the point.
double cast_ray(Point p, Point n, const Mesh &body2, const std::vector<SurfaceSegment> &segments,
                SurfacePoint &hit) {
  double best = kNoGap;
  hit = SurfacePoint{};
  for (size_t s = 0; s < segments.size(); ++s) {
    Point a = body2.node(segments[s].a), b = body2.node(segments[s].b);
    Point e = minus(b, a);
    double det = cross(n, e);
    Point n2 = edge_normal(a, b);
    if (n.x * n2.x + n.y * n2.y >= 0 || std::fabs(det) < 1e-14 * std::hypot(e.x, e.y)) continue;
    Point w = minus(a, p);
    double t = cross(w, e) / det, eta = cross(w, n) / det;
    if (eta < -1e-12 || eta > 1 + 1e-12) continue;
    if (std::fabs(t) < std::fabs(best)) best = t, hit = SurfacePoint{int(s), std::clamp(eta, 0.0, 1.0)};
  }
  return best;
}

// eta on the (infinite) line of segment s of the ray p + t n.
double eta_on_line(Point p, Point n, Point a, Point b) {
  Point e = minus(b, a);
  return cross(minus(a, p), n) / cross(n, e);
}

// The xi in [0,1] at which the normal line of body-1 segment (xa,na)-(xb,nb), normals
// interpolated linearly, passes through y: cross(x(xi) - y, n(xi)) = 0, a quadratic.
bool inverse_projection(Point xa, Point xb, Point na, Point nb, Point y, double &xi) {
  Point dx = minus(xb, xa), dn = minus(nb, na), w = minus(xa, y);
  double c0 = cross(w, na), c1 = cross(w, dn) + cross(dx, na), c2 = cross(dx, dn);
  double scale = std::fabs(c1) + std::fabs(c0) + std::fabs(c2);
  std::vector<double> roots;
  if (std::fabs(c2) <= 1e-12 * scale) {
    if (c1 != 0) roots.push_back(-c0 / c1);
  } else {
    double disc = c1 * c1 - 4 * c2 * c0;
    if (disc < 0) return false;
    double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    if (q != 0) roots.push_back(c0 / q);
    roots.push_back(q / c2);
  }
  for (double r : roots)
    if (r > 1e-12 && r < 1 - 1e-12) {
      xi = r;
      return true;
    }
  return false;
}

// Minus body 2's outward normal at the point of its surface closest to p, among the segments
// facing p's own normal; at a vertex of body 2, the mean of its two edges' normals. Keeps
// `fallback` if no segment faces p.
Point mortar_side_normal(Point p, Point fallback, const Mesh &body2, const std::vector<SurfaceSegment> &segments) {
  double best = kNoGap;
  Point result = fallback;
  for (size_t s = 0; s < segments.size(); ++s) {
    Point a = body2.node(segments[s].a), b = body2.node(segments[s].b), e = minus(b, a);
    Point n2 = edge_normal(a, b);
    if (fallback.x * n2.x + fallback.y * n2.y >= 0) continue;
    double eta = std::clamp(((p.x - a.x) * e.x + (p.y - a.y) * e.y) / (e.x * e.x + e.y * e.y), 0.0, 1.0);
    Point foot = lerp(a, b, eta);
    double distance = std::hypot(p.x - foot.x, p.y - foot.y);
    if (distance < best * (1 - 1e-12)) {
      best = distance;
      result = {-n2.x, -n2.y};
    } else if (distance <= best * (1 + 1e-12)) {  // equally close: a vertex shared by two edges
      result = unit({result.x - n2.x, result.y - n2.y});
    }
  }
  return result;
}

}  // namespace

std::vector<SurfaceSegment> oriented_surface(const Mesh &mesh, const int *edges, int n_edges, int base) {
  std::vector<SurfaceSegment> surface;
  std::vector<std::pair<int, int>> seen;
  for (int e = 0; e < n_edges; ++e) {
    int a = edges[2 * e], b = edges[2 * e + 1];
    if (a < 0 || a >= mesh.n_nodes() || b < 0 || b >= mesh.n_nodes())
      fail(MC_ERROR_ARGUMENT, "edges[%d..%d] = (%d, %d): node id out of range [%d, %d)", 2 * e, 2 * e + 1, a + base,
           b + base, base, mesh.n_nodes() + base);
    const BoundaryEdge *edge = mesh.boundary_edge(a, b);
    if (!edge)
      fail(MC_ERROR_CONTACT, "edges[%d..%d] = (%d, %d) is not an edge on the boundary of the mesh", 2 * e, 2 * e + 1,
           a + base, b + base);
    surface.push_back({edge->from, edge->to});
    seen.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(seen.begin(), seen.end());
  auto dup = std::adjacent_find(seen.begin(), seen.end());
  if (dup != seen.end()) fail(MC_ERROR_CONTACT, "edge (%d, %d) is given twice", dup->first + base, dup->second + base);
  return surface;
}

ContactGeometry build_contact_geometry(const Mesh &body1, const std::vector<SurfaceSegment> &surface1,
                                       const Mesh &body2, const std::vector<SurfaceSegment> &surface2,
                                       int normal_choice, const LineMeasure &measure) {
  ContactGeometry g;
  g.mortar_segments = surface2;
  std::vector<Chain> chains = chains_of(surface1);
  // Nodal normals: the mean of the unit normals of the adjacent edges, exact on straight pieces.
  std::vector<std::pair<int, int>> chain_range;
  for (Chain &c : chains) {
    const size_t first = g.nodes.size(), m = c.nodes.size();
    for (size_t k = 0; k < m; ++k) {
      Point p = body1.node(c.nodes[k]), sum{0, 0};
      bool has_prev = c.closed || k > 0, has_next = c.closed || k + 1 < m;
      double tributary = 0, at_o, at_p;  // the lumped weight: integral of phi_j w (line_measure.hpp)
      if (has_prev) {
        Point o = body1.node(c.nodes[(k + m - 1) % m]), q = edge_normal(o, p);
        sum.x += q.x, sum.y += q.y;
        measure.hat_integrals(o, p, at_o, at_p);
        tributary += at_p;
      }
      if (has_next) {
        Point o = body1.node(c.nodes[(k + 1) % m]), q = edge_normal(p, o);
        sum.x += q.x, sum.y += q.y;
        measure.hat_integrals(p, o, at_p, at_o);
        tributary += at_p;
      }
      g.nodes.push_back(c.nodes[k]);
      g.normals.push_back(unit(sum));
      g.tributary.push_back(tributary);
    }
    chain_range.push_back({int(first), int(m)});
  }
  const size_t n = g.nodes.size();
  if (normal_choice == MC_NORMAL_MORTAR)
    for (size_t j = 0; j < n; ++j) g.normals[j] = mortar_side_normal(body1.node(g.nodes[j]), g.normals[j], body2, surface2);
  g.gap0.assign(n, kNoGap);
  g.projection.assign(n, SurfacePoint{});
  bool any = false;
  for (size_t j = 0; j < n; ++j) {
    g.gap0[j] = cast_ray(body1.node(g.nodes[j]), g.normals[j], body2, surface2, g.projection[j]);
    any = any || g.projection[j].segment >= 0;
  }
  if (!any)
    fail(MC_ERROR_CONTACT,
         "no node of body 1's contact surface sees body 2's contact surface along its outward normal: "
         "the surfaces do not face each other");

  // Runs of consecutive seeing nodes. A closed loop is opened at a node that does not see
  // body 2, or at its first node if all do (then its last segment carries no constraint).
  for (size_t c = 0; c < chains.size(); ++c) {
    int first = chain_range[c].first, m = chain_range[c].second;
    int start = 0;
    if (chains[c].closed)
      for (int k = 0; k < m; ++k)
        if (g.projection[first + k].segment < 0) { start = k; break; }
    ContactRun run;
    auto flush = [&]() {
      if (!run.positions.empty()) g.runs.push_back(run);
      run = ContactRun{};
    };
    for (int step = 0; step < m; ++step) {
      int pos = first + (start + step) % m;
      if (g.projection[pos].segment < 0) flush();
      else run.positions.push_back(pos);
    }
    flush();
  }

  // Segmentation of each body-1 segment of a run: breakpoints where body-2 nodes project,
  // then each piece facing one body-2 segment.
  std::vector<int> surface2_nodes;
  for (auto &s : surface2) surface2_nodes.push_back(s.a), surface2_nodes.push_back(s.b);
  std::sort(surface2_nodes.begin(), surface2_nodes.end());
  surface2_nodes.erase(std::unique(surface2_nodes.begin(), surface2_nodes.end()), surface2_nodes.end());
  for (ContactRun &run : g.runs) {
    for (size_t k = 0; k + 1 < run.positions.size(); ++k) {
      int pa = run.positions[k], pb = run.positions[k + 1];
      Point xa = body1.node(g.nodes[pa]), xb = body1.node(g.nodes[pb]);
      Point na = g.normals[pa], nb = g.normals[pb];
      double seg_length = std::hypot(xb.x - xa.x, xb.y - xa.y);
      run.segment_length.push_back(seg_length);
      std::vector<double> breaks{0.0, 1.0};
      for (int node : surface2_nodes) {
        double xi;
        if (inverse_projection(xa, xb, na, nb, body2.node(node), xi)) breaks.push_back(xi);
      }
      std::sort(breaks.begin(), breaks.end());
      for (size_t b = 0; b + 1 < breaks.size(); ++b) {
        double xi0 = breaks[b], xi1 = breaks[b + 1];
        if (xi1 - xi0 < 1e-12) continue;
        double xim = 0.5 * (xi0 + xi1);
        SurfacePoint mid;
        if (cast_ray(lerp(xa, xb, xim), unit(lerp(na, nb, xim)), body2, surface2, mid) == kNoGap) continue;
        const SurfaceSegment &s = surface2[mid.segment];
        Point a2 = body2.node(s.a), b2 = body2.node(s.b);
        MortarPiece piece;
        piece.k = int(k);
        piece.xi0 = xi0, piece.xi1 = xi1;
        piece.segment = mid.segment;
        piece.eta0 = eta_on_line(lerp(xa, xb, xi0), lerp(na, nb, xi0), a2, b2);
        piece.eta1 = eta_on_line(lerp(xa, xb, xi1), lerp(na, nb, xi1), a2, b2);
        piece.length = (xi1 - xi0) * seg_length;
        run.pieces.push_back(piece);
      }
    }
  }
  return g;
}

}  // namespace mc
