#include "contact/contact_surface.hpp"
#include "bodies/cell_shapes.hpp"
#include "support/error.hpp"
#include "bodies/plane_vectors.hpp"
#include <algorithm>
#include <cmath>

namespace mc {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The direction of travel whose outward normal is n (the body on the left).
Point tangent_of(Point n) { return {-n.y, n.x}; }

// Chains of a surface: sequences of nodes following the edges' orientation; mids[k] is the
// mid-edge node of the edge from nodes[k] to the next (-1 on a linear surface).
struct Chain {
  std::vector<int> nodes, mids;
  bool closed = false;
};

std::vector<Chain> chains_of(const std::vector<SurfaceSegment> &surface) {
  std::vector<std::pair<int, int>> next;  // (from, to), sorted by from
  for (auto &s : surface) next.push_back({s.a, s.b});
  std::sort(next.begin(), next.end());
  std::vector<std::pair<int, int>> mid_after;  // (from, mid), sorted by from
  for (auto &s : surface) mid_after.push_back({s.a, s.mid});
  std::sort(mid_after.begin(), mid_after.end());
  auto mid_of = [&](int node) {
    auto it = std::lower_bound(mid_after.begin(), mid_after.end(), std::make_pair(node, -2));
    return it != mid_after.end() && it->first == node ? it->second : -1;
  };
  auto find = [&](int node) { return std::lower_bound(next.begin(), next.end(), std::make_pair(node, -1)); };
  auto successor = [&](int node) {
    auto it = find(node);
    return it != next.end() && it->first == node ? it->second : -1;
  };
  std::vector<int> targets, heads;
  for (auto &s : surface) targets.push_back(s.b);
  std::sort(targets.begin(), targets.end());
  for (auto &s : surface)
    if (!std::binary_search(targets.begin(), targets.end(), s.a)) heads.push_back(s.a);
  std::sort(heads.begin(), heads.end());
  std::vector<char> used_edge(next.size(), 0);
  auto take = [&](int from) { used_edge[find(from) - next.begin()] = 1; };
  std::vector<Chain> chains;
  for (int head : heads) {
    Chain c;
    for (int node = head; node >= 0; node = successor(node)) {
      c.nodes.push_back(node);
      if (successor(node) >= 0) take(node), c.mids.push_back(mid_of(node));
    }
    chains.push_back(c);
  }
  for (size_t e = 0; e < next.size(); ++e) {  // what is left are closed loops
    if (used_edge[e]) continue;
    Chain c;
    c.closed = true;
    const int start = next[e].first;
    int node = start;
    do {
      c.nodes.push_back(node);
      c.mids.push_back(mid_of(node));
      take(node);
      node = successor(node);
    } while (node != start);
    chains.push_back(c);
  }
  return chains;
}

// Splits a chain into faces at corners (turns above the feature angle). A closed loop without
// corners stays one closed face; one with corners is opened at a corner.
// The tangent (direction of travel) of a quadratic edge p -> q with middle m at its start (s = 0)
// or end (s = 1): x'(0) = 4m - 3p - q, x'(1) = 3q + p - 4m.
Point quadratic_tangent(Point p, Point q, Point m, bool at_end) {
  return at_end ? Point{3 * q.x + p.x - 4 * m.x, 3 * q.y + p.y - 4 * m.y}
                : Point{4 * m.x - 3 * p.x - q.x, 4 * m.y - 3 * p.y - q.y};
}

// The unit outward normal of a (possibly quadratic) chain edge k at its start or end.
Point chain_edge_normal(const Mesh &mesh, const std::vector<int> &nodes, const std::vector<int> &mids, int k,
                        bool at_end) {
  const int m = int(nodes.size());
  const Point p = mesh.node(nodes[k % m]), q = mesh.node(nodes[(k + 1) % m]);
  if (mids.empty() || mids[k] < 0) return edge_normal(p, q);
  const Point t = quadratic_tangent(p, q, mesh.node(mids[k]), at_end);
  return unit({t.y, -t.x});
}

std::vector<SurfaceFace> faces_of(const Mesh &mesh, const Chain &chain, bool split, double feature_angle) {
  const int m = int(chain.nodes.size());
  const bool quadratic = !chain.mids.empty() && chain.mids[0] >= 0;
  auto at = [&](int k) { return mesh.node(chain.nodes[((k % m) + m) % m]); };
  auto wrap = [&](int k) { return ((k % m) + m) % m; };
  std::vector<char> corner(m, 0);
  if (split)
    for (int k = 0; k < m; ++k) {
      if (!chain.closed && (k == 0 || k == m - 1)) continue;
      double turn;
      if (quadratic) {  // the turn of the curve itself: between the two edges' tangents at the node
        const Point n_in = chain_edge_normal(mesh, chain.nodes, chain.mids, wrap(k - 1), true);
        const Point n_out = chain_edge_normal(mesh, chain.nodes, chain.mids, k, false);
        turn = std::atan2(cross(n_in, n_out), dot(n_in, n_out));
      } else {
        turn = turn_angle(at(k - 1), at(k), at(k + 1));
      }
      corner[k] = std::fabs(turn) > feature_angle;
    }
  std::vector<SurfaceFace> faces;
  int first_corner = -1;
  for (int k = 0; k < m; ++k)
    if (corner[k]) { first_corner = k; break; }
  if (chain.closed && first_corner < 0) {
    SurfaceFace face;
    face.nodes = chain.nodes;
    face.mids = chain.mids;
    face.closed = true;
    faces.push_back(face);
    return faces;
  }
  // Walk from the start (open chain) or from the first corner (closed loop), cutting at corners.
  const int start = chain.closed ? first_corner : 0, steps = chain.closed ? m : m - 1;
  SurfaceFace face;
  face.nodes.push_back(chain.nodes[start]);
  face.corner_at_start = corner[start];
  for (int step = 1; step <= steps; ++step) {
    const int k = (start + step) % m;
    face.mids.push_back(chain.mids[wrap(k - 1)]);
    face.nodes.push_back(chain.nodes[k]);
    if (corner[k] || step == steps) {
      face.corner_at_end = corner[k];
      faces.push_back(face);
      face = SurfaceFace{};
      face.nodes.push_back(chain.nodes[k]);
      face.corner_at_start = corner[k];
    }
  }
  return faces;
}

// Unit normal at the end node p0 of an open face from the circle through p0, p1, p2 (exact on
// a circle, the edge normal on a straight face); the edge normal `fallback` when they are
// (nearly) collinear.
Point end_normal_from_circle(Point p0, Point p1, Point p2, Point fallback) {
  Point u = minus(p1, p0), v = minus(p2, p0);
  const double d = 2 * cross(u, v);
  const double scale = norm(u) * norm(v);
  if (std::fabs(d) <= 1e-10 * scale) return fallback;
  const double uu = dot(u, u), vv = dot(v, v);
  Point centre{p0.x + (v.y * uu - u.y * vv) / d, p0.y + (u.x * vv - v.x * uu) / d};
  Point n = unit(minus(p0, centre));
  return dot(n, fallback) >= 0 ? n : scaled(n, -1);
}

// Nodal normals of a face. Smooth: Yang-Laursen-Meng, n ~ l2 n1 + l1 n2 (exact on circles);
// faceted: the mean of the unit edge normals.
void face_normals(const Mesh &mesh, SurfaceFace &face, bool smooth) {
  const int m = int(face.nodes.size());
  auto p = [&](int k) { return mesh.node(face.nodes[((k % m) + m) % m]); };
  face.normals.assign(m, Point{0, 0});
  if (!face.mids.empty() && face.mids[0] >= 0) {
    // Quadratic edges: the mean of the two edges' own normals at the node; a face's end, the
    // end edge's own normal there (its curve goes on as it went).
    const int edges = face.edges();
    for (int k = 0; k < m; ++k) {
      const bool has_prev = face.closed || k > 0, has_next = face.closed || k + 1 < m;
      Point n{0, 0};
      if (has_prev) n = plus(n, chain_edge_normal(mesh, face.nodes, face.mids, (k + edges - 1) % edges, true));
      if (has_next) n = plus(n, chain_edge_normal(mesh, face.nodes, face.mids, k % edges, false));
      face.normals[k] = unit(n);
    }
    return;
  }
  for (int k = 0; k < m; ++k) {
    const bool has_prev = face.closed || k > 0, has_next = face.closed || k + 1 < m;
    if (has_prev && has_next) {
      Point n1 = edge_normal(p(k - 1), p(k)), n2 = edge_normal(p(k), p(k + 1));
      double l1 = norm(minus(p(k), p(k - 1))), l2 = norm(minus(p(k + 1), p(k)));
      face.normals[k] = smooth ? unit(plus(scaled(n1, l2), scaled(n2, l1))) : unit(plus(n1, n2));
    } else {
      // A face's end: where the chain ends, the circle through the last three nodes (the
      // surface goes on as it went); at a corner, the end edge's own normal, so that the two
      // faces' rows there keep directions as different as the corner (two circles fitted on
      // either side of a corner that is no real corner, a coarse circle's node turning by just
      // the feature angle, would give one normal twice and two identical constraint rows).
      Point n = has_next ? edge_normal(p(k), p(k + 1)) : edge_normal(p(k - 1), p(k));
      const bool at_corner = has_next ? face.corner_at_start : face.corner_at_end;
      if (smooth && m >= 3 && !at_corner) n = has_next ? end_normal_from_circle(p(k), p(k + 1), p(k + 2), n)
                                                       : end_normal_from_circle(p(k), p(k - 1), p(k - 2), n);
      face.normals[k] = n;
    }
  }
}

// Cubic Hermite basis and its derivative.
void hermite(double s, double h[4]) {
  const double s2 = s * s, s3 = s2 * s;
  h[0] = 2 * s3 - 3 * s2 + 1, h[1] = s3 - 2 * s2 + s, h[2] = -2 * s3 + 3 * s2, h[3] = s3 - s2;
}
void hermite_derivative(double s, double h[4]) {
  const double s2 = s * s;
  h[0] = 6 * s2 - 6 * s, h[1] = 3 * s2 - 4 * s + 1, h[2] = -6 * s2 + 6 * s, h[3] = 3 * s2 - 2 * s;
}

}  // namespace

SurfaceCurve::SurfaceCurve(const Mesh &mesh, const std::vector<SurfaceSegment> &segments, const SurfaceOptions &options)
    : smooth_(options.smooth) {
  const double feature = options.feature_angle_degrees * kPi / 180;
  segments_.reserve(segments.size());  // one per edge (a long surface's, grown, were copied and copied)
  for (const Chain &chain : chains_of(segments))
    for (SurfaceFace &face : faces_of(mesh, chain, smooth_, feature)) {
      face_normals(mesh, face, smooth_);
      face.segment_begin = int(segments_.size());
      const int m = int(face.nodes.size());
      for (int k = 0; k < face.edges(); ++k) {
        CurveSegment c;
        c.face = int(faces_.size()), c.k = k;
        c.a = face.nodes[k], c.b = face.nodes[(k + 1) % m];
        c.pa = mesh.node(c.a), c.pb = mesh.node(c.b);
        c.na = face.normals[k], c.nb = face.normals[(k + 1) % m];
        c.length = norm(minus(c.pb, c.pa));
        c.edge_normal = edge_normal(c.pa, c.pb);
        c.ta = scaled(tangent_of(c.na), c.length), c.tb = scaled(tangent_of(c.nb), c.length);
        if (!face.mids.empty() && face.mids[k] >= 0) {
          c.mid = face.mids[k], c.pm = mesh.node(c.mid);
          c.ta = quadratic_tangent(c.pa, c.pb, c.pm, false), c.tb = quadratic_tangent(c.pa, c.pb, c.pm, true);
          const Point t = plus(c.ta, c.tb);  // x'(1/2): x' is linear in s
          c.nm = unit({t.y, -t.x});
        }
        // The curve lies in the convex hull of its Bezier points (the chord if faceted).
        Point hull[4];
        const int count = c.bezier(hull, smooth_);
        c.box_lo = c.box_hi = c.pa;
        for (int h = 1; h < count; ++h) {
          c.box_lo = {std::min(c.box_lo.x, hull[h].x), std::min(c.box_lo.y, hull[h].y)};
          c.box_hi = {std::max(c.box_hi.x, hull[h].x), std::max(c.box_hi.y, hull[h].y)};
        }
        segments_.push_back(c);
      }
      faces_.push_back(std::move(face));
    }
  build_grid();
}

namespace {
// The grid cell (0..n-1) of coordinate t = offset / cell size, clamped in floating point before
// the conversion: a coordinate far outside the grid (1e300, found by the fuzzer) or NaN has no
// int value, and converting it is undefined behaviour.
int grid_cell(double t, int n) {
  const double f = std::floor(t);
  if (!(f >= 0)) return 0;  // below the grid, or NaN
  return f >= double(n - 1) ? n - 1 : int(f);
}
}  // namespace

void SurfaceCurve::build_grid() {
  const int count = int(segments_.size());
  cell_start_.assign(1, 0), cell_segment_.clear(), grid_nx_ = grid_ny_ = 0;
  if (count == 0) return;
  Point lo = segments_[0].box_lo, hi = segments_[0].box_hi;
  double total = 0;
  for (const CurveSegment &c : segments_) {
    lo = {std::min(lo.x, c.box_lo.x), std::min(lo.y, c.box_lo.y)};
    hi = {std::max(hi.x, c.box_hi.x), std::max(hi.y, c.box_hi.y)};
    total += std::max(c.box_hi.x - c.box_lo.x, c.box_hi.y - c.box_lo.y);
  }
  // Cells about the size of a segment, at most a few per segment in all.
  const double wx = hi.x - lo.x, wy = hi.y - lo.y, extent = std::max(wx, wy);
  double cell = std::max(total / count, 1e-12 * std::max(extent, 1e-300));
  while ((std::floor(wx / cell) + 1) * (std::floor(wy / cell) + 1) > 4.0 * count + 16) cell *= 2;
  grid_lo_ = lo, cell_ = cell > 0 ? cell : 1;
  // (the loop above bounds the cell counts by 4 count + 16; an extent that overflows to inf, or a
  // NaN, gives cell_ inf or NaN, and grid_cell keeps the counts in range all the same)
  const int most = 4 * count + 16;
  grid_nx_ = grid_cell(wx / cell_, most) + 1, grid_ny_ = grid_cell(wy / cell_, most) + 1;
  auto cell_range = [&](const CurveSegment &c, int &i0, int &i1, int &j0, int &j1) {
    i0 = grid_cell((c.box_lo.x - lo.x) / cell_, grid_nx_);
    i1 = grid_cell((c.box_hi.x - lo.x) / cell_, grid_nx_);
    j0 = grid_cell((c.box_lo.y - lo.y) / cell_, grid_ny_);
    j1 = grid_cell((c.box_hi.y - lo.y) / cell_, grid_ny_);
  };
  std::vector<int> count_in(size_t(grid_nx_) * grid_ny_ + 1, 0);
  int i0, i1, j0, j1;
  for (const CurveSegment &c : segments_) {
    cell_range(c, i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) count_in[size_t(j) * grid_nx_ + i + 1]++;
  }
  for (size_t k = 1; k < count_in.size(); ++k) count_in[k] += count_in[k - 1];
  cell_start_ = count_in;
  cell_segment_.assign(size_t(count_in.back()), 0);
  for (int k = 0; k < count; ++k) {
    cell_range(segments_[k], i0, i1, j0, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) cell_segment_[size_t(count_in[size_t(j) * grid_nx_ + i]++)] = k;
  }
}

template <class Visit, class GoOn> void SurfaceCurve::visit_near(Point p, Visit &&visit, GoOn &&go_on) const {
  if (grid_nx_ == 0) return;
  // p's cell, clamped to the grid: distances from the clamped point bound those from p below
  // (the projection onto the grid's box does not increase distances to points inside it).
  const int ci = grid_cell((p.x - grid_lo_.x) / cell_, grid_nx_);
  const int cj = grid_cell((p.y - grid_lo_.y) / cell_, grid_ny_);
  std::vector<int> seen;  // a segment spans a few cells: visited once
  const int rings = std::max({ci, grid_nx_ - 1 - ci, cj, grid_ny_ - 1 - cj});
  for (int r = 0; r <= rings; ++r) {
    if (r > 0 && !go_on((r - 1) * cell_)) return;
    for (int j = cj - r; j <= cj + r; ++j) {
      if (j < 0 || j >= grid_ny_) continue;
      const bool edge_row = j == cj - r || j == cj + r;
      for (int i = ci - r; i <= ci + r; i += edge_row ? 1 : 2 * std::max(r, 1)) {
        if (i < 0 || i >= grid_nx_) continue;
        const size_t cell = size_t(j) * grid_nx_ + i;
        for (int q = cell_start_[cell]; q < cell_start_[cell + 1]; ++q) {
          const int k = cell_segment_[size_t(q)];
          if (std::find(seen.begin(), seen.end(), k) != seen.end()) continue;
          seen.push_back(k);
          visit(k);
        }
        if (r == 0) break;
      }
    }
  }
}

int CurveSegment::bezier(Point control[4], bool smooth) const {
  control[0] = pa;
  if (quadratic()) {  // a parabola's middle control point: 2 x(1/2) - (pa + pb) / 2
    control[1] = {2 * pm.x - 0.5 * (pa.x + pb.x), 2 * pm.y - 0.5 * (pa.y + pb.y)};
    control[2] = pb;
    return 3;
  }
  if (!smooth) {
    control[1] = pb;
    return 2;
  }
  control[1] = plus(pa, scaled(ta, 1.0 / 3)), control[2] = minus(pb, scaled(tb, 1.0 / 3)), control[3] = pb;
  return 4;
}

int SurfaceCurve::segment_of(int face, int k) const {
  const SurfaceFace &f = faces_[face];
  const int e = f.edges();
  return f.segment_begin + ((k % e) + e) % e;
}

Point SurfaceCurve::point(int seg, double s) const {
  const CurveSegment &c = segments_[seg];
  if (c.quadratic()) {
    double n[3], ds[3];
    line_shapes(3, s, n, ds);
    return {n[0] * c.pa.x + n[1] * c.pb.x + n[2] * c.pm.x, n[0] * c.pa.y + n[1] * c.pb.y + n[2] * c.pm.y};
  }
  if (!smooth_) return plus(c.pa, scaled(minus(c.pb, c.pa), s));
  double h[4];
  hermite(s, h);
  return {h[0] * c.pa.x + h[1] * c.ta.x + h[2] * c.pb.x + h[3] * c.tb.x,
          h[0] * c.pa.y + h[1] * c.ta.y + h[2] * c.pb.y + h[3] * c.tb.y};
}

Point SurfaceCurve::derivative(int seg, double s) const {
  const CurveSegment &c = segments_[seg];
  if (c.quadratic()) {
    double n[3], ds[3];
    line_shapes(3, s, n, ds);
    return {ds[0] * c.pa.x + ds[1] * c.pb.x + ds[2] * c.pm.x, ds[0] * c.pa.y + ds[1] * c.pb.y + ds[2] * c.pm.y};
  }
  if (!smooth_) return minus(c.pb, c.pa);
  double h[4];
  hermite_derivative(s, h);
  return {h[0] * c.pa.x + h[1] * c.ta.x + h[2] * c.pb.x + h[3] * c.tb.x,
          h[0] * c.pa.y + h[1] * c.ta.y + h[2] * c.pb.y + h[3] * c.tb.y};
}

Point SurfaceCurve::surface_normal(int seg, double s) const {
  if (!smooth_ && !segments_[seg].quadratic()) return segments_[seg].edge_normal;
  Point d = derivative(seg, s);
  return unit({d.y, -d.x});
}

Point SurfaceCurve::look_direction(int seg, double s) const {
  const CurveSegment &c = segments_[seg];
  if (c.quadratic()) {
    double n[3], ds[3];
    line_shapes(3, s, n, ds);
    return unit(plus(plus(scaled(c.na, n[0]), scaled(c.nb, n[1])), scaled(c.nm, n[2])));
  }
  if (smooth_) return surface_normal(seg, s);
  return unit(plus(scaled(c.na, 1 - s), scaled(c.nb, s)));
}

double SurfaceCurve::speed(int seg, double s) const { return norm(derivative(seg, s)); }

bool SurfaceCurve::intersect_line(int seg, Point p, Point n, double slack, double &s, double &t) const {
  const CurveSegment &c = segments_[seg];
  // f(s) = cross(point(s) - p, n): zero where the curve crosses the line.
  auto f = [&](double x) { return cross(minus(point(seg, x), p), n); };
  const double tolerance = 1e-14 * (c.length + norm(minus(c.pa, p)));
  const bool curved = smooth_ || c.quadratic();
  if (curved) {
    // The curve lies in the convex hull of its Bezier points: skip it if they are all on one side.
    Point bezier[4];
    const int count = c.bezier(bezier, smooth_);
    double lo = 1e300, hi = -1e300;
    for (int h = 0; h < count; ++h) {
      double v = cross(minus(bezier[h], p), n);
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double reach = slack * 2 * (c.length + norm(c.ta) + norm(c.tb));
    if (lo > reach + tolerance || hi < -reach - tolerance) return false;
  }
  double a = -slack, b = 1 + slack, fa = f(a), fb = f(b);
  if (std::fabs(fa) <= tolerance) fa = 0;
  if (std::fabs(fb) <= tolerance) fb = 0;
  if ((fa > 0 && fb > 0) || (fa < 0 && fb < 0)) return false;
  if (!curved) {
    s = fa == fb ? 0.5 : a + (b - a) * fa / (fa - fb);  // f is linear in s
  } else {
    // Safeguarded Newton inside the bracket [a, b] (the curve turns little on one segment).
    s = fa == fb ? 0.5 : a + (b - a) * fa / (fa - fb);
    for (int it = 0; it < 60; ++it) {
      const double fs = f(s);
      if (fs == 0) break;
      if ((fs < 0) == (fa < 0)) a = s, fa = fs;
      else b = s;
      const double slope = cross(derivative(seg, s), n);
      double next = slope != 0 ? s - fs / slope : 0.5 * (a + b);
      if (!(next > a && next < b)) next = 0.5 * (a + b);
      const bool done = std::fabs(next - s) <= 1e-15;
      s = next;
      if (done || b - a <= 1e-15) break;
    }
  }
  if (s < -slack || s > 1 + slack) return false;
  if (dot(surface_normal(seg, std::clamp(s, 0.0, 1.0)), n) >= 0) return false;  // seen from behind
  t = dot(minus(point(seg, s), p), n);
  return true;
}

double SurfaceCurve::box_distance(int seg, Point p) const {
  const CurveSegment &c = segments_[seg];
  const double dx = std::max({c.box_lo.x - p.x, 0.0, p.x - c.box_hi.x});
  const double dy = std::max({c.box_lo.y - p.y, 0.0, p.y - c.box_hi.y});
  return std::hypot(dx, dy);
}

bool SurfaceCurve::cast(Point p, Point n, int &seg, double &s, double &t, int hint) const {
  const int count = int(segments_.size());
  // The nearest hit (|t| least); among equally near ones the first in the order of a scan that
  // tries the hint and its neighbours, then every segment by index (rank below).
  auto rank = [&](int k) {
    if (hint >= 0 && hint < count) {
      if (k == hint) return -3;
      if (k == hint - 1) return -2;
      if (k == hint + 1) return -1;
    }
    return k;
  };
  double best = 0;
  bool found = false;
  auto consider = [&](int k) {
    double sk, tk;
    if (!intersect_line(k, p, n, 1e-12, sk, tk)) return;
    if (!found || std::fabs(tk) < std::fabs(best) || (std::fabs(tk) == std::fabs(best) && rank(k) < rank(seg)))
      best = tk, seg = k, s = std::clamp(sk, 0.0, 1.0), t = tk, found = true;
  };
  if (hint >= 0 && hint < count)
    for (int k : {hint, hint - 1, hint + 1})
      if (k >= 0 && k < count) consider(k);
  // A hit on segment k is at least its box's distance away from p: no nearer than the best.
  visit_near(
      p,
      [&](int k) {
        if (hint >= 0 && k >= hint - 1 && k <= hint + 1) return;
        if (found && box_distance(k, p) > std::fabs(best) * (1 + 1e-12)) return;
        consider(k);
      },
      [&](double distance) { return !found || distance <= std::fabs(best) * (1 + 1e-12); });
  return found;
}

void SurfaceCurve::segments_near(Point p, double radius, std::vector<int> &found) const {
  found.clear();
  visit_near(
      p,
      [&](int k) {
        if (box_distance(k, p) <= radius) found.push_back(k);
      },
      [&](double distance) { return distance <= radius; });
}

bool SurfaceCurve::closest_point(Point p, Point facing, int &seg, double &s) const {
  double best = 1e300;
  bool found = false;
  int nearest = -1;
  // Among equally near points, the first of a scan that tries the segment whose box is nearest,
  // then every segment by index.
  auto rank = [&](int k) { return k == nearest ? -1 : k; };
  auto consider = [&](int k) {
    const CurveSegment &c = segments_[k];
    Point e = minus(c.pb, c.pa);
    double x = std::clamp(dot(minus(p, c.pa), e) / dot(e, e), 0.0, 1.0);
    if (smooth_ || c.quadratic())  // Newton on (point(x) - p) . point'(x) = 0, kept in [0, 1]
      for (int it = 0; it < 20; ++it) {
        Point r = minus(point(k, x), p), d = derivative(k, x);
        double g = dot(r, d), slope = dot(d, d);
        double next = std::clamp(x - g / slope, 0.0, 1.0);
        if (std::fabs(next - x) <= 1e-15) break;
        x = next;
      }
    if (dot(surface_normal(k, x), facing) >= 0) return;
    double distance = norm(minus(point(k, x), p));
    if (distance < best || (distance == best && found && rank(k) < rank(seg))) best = distance, seg = k, s = x, found = true;
  };
  // The segment whose box is nearest (the first by index among equals) first; then only the
  // segments whose box is nearer than the best point so far (the box's distance bounds the
  // curve's from below).
  double nearest_box = 1e300;
  visit_near(
      p,
      [&](int k) {
        const double d = box_distance(k, p);
        if (d < nearest_box || (d == nearest_box && k < nearest)) nearest_box = d, nearest = k;
      },
      [&](double distance) { return nearest < 0 || distance <= nearest_box; });
  if (nearest >= 0) consider(nearest);
  visit_near(
      p,
      [&](int k) {
        if (k != nearest && box_distance(k, p) <= best) consider(k);
      },
      [&](double distance) { return distance <= best; });
  return found;
}

}  // namespace mc
