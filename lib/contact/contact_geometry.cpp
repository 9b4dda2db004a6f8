#include "contact/contact_geometry.hpp"
#include "contact/points_between_lines.hpp"
#include "bodies/cell_shapes.hpp"
#include "support/error.hpp"
#include "mortarcontact.h"
#include "bodies/plane_vectors.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <string>

namespace mc {

namespace {

// The direction along which body 1 looks for body 2 at (segment, parameter) of its curve.
using LookDirection = std::function<Point(int, double)>;

// The distance from p to body-2 segment `segment` (a straight edge) and the edge's outward
// normal n2; false if the edge does not face `facing` (n2 . facing >= 0).
bool facing_edge(Point p, Point facing, const Mesh &body2, const SurfaceSegment &segment, double &distance, Point &n2) {
  Point a = body2.node(segment.a), b = body2.node(segment.b), e = minus(b, a);
  n2 = edge_normal(a, b);
  if (facing.x * n2.x + facing.y * n2.y >= 0) return false;
  double eta = std::clamp(((p.x - a.x) * e.x + (p.y - a.y) * e.y) / (e.x * e.x + e.y * e.y), 0.0, 1.0);
  Point foot = lerp(a, b, eta);
  distance = std::hypot(p.x - foot.x, p.y - foot.y);
  return true;
}

// Minus body 2's outward normal at the point of its surface closest to p, among the segments
// facing p's own normal; at a vertex of body 2, the mean of its two edges' normals. Keeps
// `fallback` if no segment faces p. Scans segments[k] for k in `scan` (ascending): every
// segment, or those that decide the answer (deciding_segments).
Point mortar_side_normal(Point p, Point fallback, const Mesh &body2, const std::vector<SurfaceSegment> &segments,
                         const std::vector<int> &scan) {
  double best = kNoGap;
  Point result = fallback;
  for (int s : scan) {
    double distance;
    Point n2;
    if (!facing_edge(p, fallback, body2, segments[s], distance, n2)) continue;
    if (distance < best * (1 - 1e-12)) {
      best = distance;
      result = {-n2.x, -n2.y};
    } else if (distance <= best * (1 + 1e-12)) {  // equally close: a vertex shared by two edges
      result = unit({result.x - n2.x, result.y - n2.y});
    }
  }
  return result;
}

// The segments (ascending) whose scan gives mortar_side_normal's answer at p, from the curve's
// grid (curve2: the same straight edges, its segment k being segments[input_of[k]]): a scan of
// every segment for every position cost O(n1 n2). With b the distance of the nearest facing
// one, those nearer than R are kept, R in [b (1 + 1e-9), b (1 + 2e-9)] chosen so that no
// segment's distance is within 1e-11 R of it. The others are farther than R (1 + 1e-11): wherever
// the full scan meets them, they can neither beat nor tie (tolerance 1e-12) a kept one, and what
// they leave before the first kept one is reset by it. So the scan of the kept ones, in the same
// order, ends in the same state, bit for bit. (b = 0: R = 0, the segments through p.) Every
// segment if no such R is found (dozens of edges equally far from p: a circle about it).
void deciding_segments(Point p, Point facing, const Mesh &body2, const std::vector<SurfaceSegment> &segments,
                       const SurfaceCurve &curve2, const std::vector<int> &input_of, std::vector<int> &near,
                       std::vector<int> &kept) {
  kept.clear();
  int seg;
  double s;
  if (!curve2.closest_point(p, facing, seg, s)) return;  // none faces p: the fallback
  const double b = norm(minus(curve2.point(seg, s), p));
  if (!std::isfinite(b)) {  // (coordinates near overflow: the scan of every segment)
    for (size_t k = 0; k < segments.size(); ++k) kept.push_back(int(k));
    return;
  }
  // (a foot's round-off can put it a little outside its edge's box: a margin of the coordinates' size)
  curve2.segments_near(p, b * (1 + 3e-9) + 1e-12 * (std::fabs(p.x) + std::fabs(p.y)), near);
  std::vector<std::pair<int, double>> facing_near;  // (segment, distance)
  for (int k : near) {
    double distance;
    Point n2;
    if (facing_edge(p, facing, body2, segments[input_of[k]], distance, n2)) facing_near.emplace_back(input_of[k], distance);
  }
  double r = b * (1 + 1e-9);
  for (bool clear = b == 0; !clear;) {
    clear = true;
    for (const auto &f : facing_near)
      if (std::fabs(f.second - r) <= 1e-11 * r) clear = false;
    if (!clear) r *= 1 + 3e-11;
    if (!(r <= b * (1 + 2e-9))) {  // (no room: the scan of every segment)
      for (size_t k = 0; k < segments.size(); ++k) kept.push_back(int(k));
      return;
    }
  }
  for (const auto &f : facing_near)
    if (f.second <= r) kept.push_back(f.first);
  std::sort(kept.begin(), kept.end());
}

// The xi in (0,1) at which the look direction of body-1 segment `seg` passes through y:
// a root of f(xi) = cross(y - x(xi), n(xi)), bracketed by the segment's ends (Illinois method).
bool inverse_projection(const SurfaceCurve &curve, int seg, const LookDirection &look, Point y, double &xi) {
  auto f = [&](double s) { return cross(minus(y, curve.point(seg, s)), look(seg, s)); };
  double a = 0, b = 1, fa = f(a), fb = f(b);
  if (fa == 0 || fb == 0 || (fa > 0) == (fb > 0)) return false;
  int side = 0;
  for (int it = 0; it < 100 && b - a > 1e-15; ++it) {
    const double c = (a * fb - b * fa) / (fb - fa), fc = f(c);
    if (fc == 0) {
      a = b = c;
      break;
    }
    if ((fc > 0) == (fb > 0)) {
      b = c, fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = c, fa = fc;
      if (side == +1) fb *= 0.5;
      side = +1;
    }
  }
  xi = 0.5 * (a + b);
  return xi > 1e-12 && xi < 1 - 1e-12;
}

// A covered piece of edge k of a body-1 face: [xi0, xi1] sees body-2 segment `mortar` along the
// look direction. `shift` places it on the face's parameter line t = shift + k + xi (a closed
// face's run that wraps past its first node shifts the pieces before it by -edges).
struct CoveredPiece {
  int k;
  double xi0, xi1;
  int mortar;
  double shift = 0;
  double t0() const { return shift + k + xi0; }
  double t1() const { return shift + k + xi1; }
};

// Gauss-Legendre points on [0,1]: exact for polynomials of degree 5.
constexpr double kGaussPoint[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr double kGaussWeight[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
// Trace points closer than this (in the segment's parameter) to a node are that node: a shorter
// end element would make its multiplier's row ill-conditioned (its integrals scale with its length),
// and snapping moves the answer by O(kSnap) only.
constexpr double kSnap = 1e-6;

// What building the runs of one body-1 face needs.
struct FaceContext {
  const ContactGeometry &g;
  int face, edges;
  bool closed;
  int first_position;  // position of face node 0; node k is first_position + stride k (mod size if closed)
  LookDirection look;
  LineMeasure measure;
  int stride = 1;      // 2 on a quadratic face: each node is followed by its edge's middle
  int points = 3;      // Gauss points per covered piece

  int position(int k) const {
    const int m = closed ? edges : edges + 1;
    return first_position + stride * (((k % m) + m) % m);
  }
  int segment(int k) const { return g.nonmortar.segment_of(face, k); }
};

// Projects the body-1 point x along n onto body-2 segment `mortar` (the one the adjacent
// covered piece sees): used at the ends of Gamma_c, where a ray may just miss. Returns the
// body-2 point and sets the distance t along n.
SurfacePoint project_onto(const SurfaceCurve &mortar_curve, int mortar, Point x, Point n, double &t) {
  double s;
  if (mortar_curve.intersect_line(mortar, x, n, 1e-6, s, t)) return {mortar, std::clamp(s, 0.0, 1.0)};
  const CurveSegment &c = mortar_curve.segments()[mortar];
  Point e = minus(c.pb, c.pa);
  s = std::clamp(dot(minus(x, c.pa), e) / dot(e, e), 0.0, 1.0);
  t = dot(minus(mortar_curve.point(mortar, s), x), n);
  return {mortar, s};
}

// The trace point at face parameter t: a position (t at a node) or a point inside a segment.
// `adjacent` is a covered piece next to it, whose body-2 segment it projects onto if its own
// ray misses body 2.
TracePoint trace_point(const FaceContext &f, double t, const CoveredPiece &adjacent) {
  TracePoint p;
  const double nearest = std::round(t);
  Point x, n;
  if (std::fabs(t - nearest) <= kSnap) {
    p.a = f.position(int(nearest));
    p.x = f.g.nonmortar.segments()[f.segment(int(nearest))].pa;
    if (!f.closed && int(nearest) == f.edges) p.x = f.g.nonmortar.segments()[f.segment(f.edges - 1)].pb;
    // (p.b stays -1: a trace point at a node is that node, on a quadratic edge too)
    if (f.g.projection[p.a].segment >= 0) {
      p.normal = f.g.normals[p.a], p.gap0 = f.g.gap0[p.a], p.projection = f.g.projection[p.a];
      return p;
    }
    x = f.g.nonmortar.point(f.segment(int(nearest)), 0);
    if (!f.closed && int(nearest) == f.edges) x = f.g.nonmortar.point(f.segment(f.edges - 1), 1);
    n = f.g.normals[p.a];
  } else {
    const int k = int(std::floor(t));
    p.a = f.position(k), p.b = f.position(k + 1), p.xi = t - k;
    const CurveSegment &c = f.g.nonmortar.segments()[f.segment(k)];
    p.x = c.quadratic() ? f.g.nonmortar.point(f.segment(k), p.xi) : lerp(c.pa, c.pb, p.xi);
    x = f.g.nonmortar.point(f.segment(k), p.xi);
    n = f.look(f.segment(k), p.xi);
  }
  p.normal = n;
  p.projection = project_onto(f.g.mortar, adjacent.mortar, x, n, p.gap0);
  return p;
}

// Quadrature points of piece p inside the element [t0, t1] of a run, and its share of the
// positions' tributary measures (the integral of each body-1 hat function times w over Gamma_c).
// The length measure is the chord's: the mortar integrals only need one measure used
// throughout, and with it Wohlmuth's biorthogonal basis keeps D diagonal on curved surfaces too.
// A quadratic body-1 edge is measured on its own curve (its arc length, the measure at the curve's
// point): the integrals then are those of the body's own trace, which its loads also use.
void add_quadrature(const FaceContext &f, const CoveredPiece &p, double t0, double t1, std::vector<QuadraturePoint> &element,
                    std::vector<double> &tributary) {
  const int seg = f.segment(p.k);
  const CurveSegment &c = f.g.nonmortar.segments()[seg];
  double gauss_point[5], gauss_weight[5];
  if (f.points == 3) {
    for (int q = 0; q < 3; ++q) gauss_point[q] = kGaussPoint[q], gauss_weight[q] = kGaussWeight[q];
  } else {
    gauss_on_unit_interval(f.points, gauss_point, gauss_weight);
  }
  const std::array<int, 3> &positions = f.g.segment_positions[seg];
  for (int q = 0; q < f.points; ++q) {
    const double xi = p.xi0 + (p.xi1 - p.xi0) * gauss_point[q];
    Point x = f.g.nonmortar.point(seg, xi), n = f.look(seg, xi);
    // The measure's weight (t, or 2 pi r: linear on the chord, so the rule stays exact for D)
    const double weight = c.quadratic() ? gauss_weight[q] * (p.xi1 - p.xi0) * f.g.nonmortar.speed(seg, xi) * f.measure.weight(x)
                                        : gauss_weight[q] * (p.xi1 - p.xi0) * c.length * f.measure.weight(lerp(c.pa, c.pb, xi));
    const double t = p.shift + p.k + xi;
    double distance;
    QuadraturePoint point{(t - t0) / (t1 - t0), weight, project_onto(f.g.mortar, p.mortar, x, n, distance)};
    point.segment1 = seg, point.xi1 = xi, point.gap = distance, point.normal = n;
    element.push_back(point);
    double shape[3], ds[3];
    line_shapes(c.quadratic() ? 3 : 2, xi, shape, ds);
    for (int a = 0; a < (c.quadratic() ? 3 : 2); ++a) tributary[positions[a]] += weight * shape[a];
  }
}

// Each piece's quadrature points (f.points each) into its element's place in the run's array
// (element_of[i]: piece i's element), in the order of the pieces, and the tributary measures.
void fill_points(const FaceContext &f, const std::vector<CoveredPiece> &pieces, const std::vector<int> &element_of,
                 const std::vector<double> &element_t, int elements, ContactRun &run, std::vector<double> &tributary) {
  RunElements &points = run.elements;
  points.start.assign(elements + 1, 0);
  for (int e : element_of) points.start[e + 1] += f.points;
  for (int e = 0; e < elements; ++e) points.start[e + 1] += points.start[e];
  points.points.reserve(points.start[elements]);
  if (std::is_sorted(element_of.begin(), element_of.end())) {  // (always, the pieces come along the face)
    for (size_t i = 0; i < pieces.size(); ++i)
      add_quadrature(f, pieces[i], element_t[element_of[i]], element_t[element_of[i] + 1], points.points, tributary);
    return;
  }
  points.points.resize(points.start[elements]);
  std::vector<int> next(points.start.begin(), points.start.end() - 1);
  std::vector<QuadraturePoint> piece_points;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const int e = element_of[i];
    piece_points.clear();
    add_quadrature(f, pieces[i], element_t[e], element_t[e + 1], piece_points, tributary);
    std::copy(piece_points.begin(), piece_points.end(), points.points.begin() + next[e]);
    next[e] += f.points;
  }
}

// Turns one maximal covered interval of a face into a run.
ContactRun open_run(const FaceContext &f, const std::vector<CoveredPiece> &pieces, std::vector<double> &tributary) {
  ContactRun run;
  auto snapped = [](double t) { return std::fabs(t - std::round(t)) <= kSnap ? std::round(t) : t; };
  const double t_begin = snapped(pieces.front().t0()), t_end = snapped(pieces.back().t1());
  std::vector<double> trace_t{t_begin};
  trace_t.reserve(pieces.size() + 2), run.trace.reserve(pieces.size() + 2);  // (at most a node per piece, and the ends)
  run.trace.push_back(trace_point(f, t_begin, pieces.front()));
  for (const CoveredPiece &p : pieces) {  // the nodes strictly inside the interval
    const double t = snapped(p.t1());
    if (t > std::max(t_begin, trace_t.back()) + kSnap && t < t_end - kSnap && t == std::round(t)) {
      trace_t.push_back(t);
      run.trace.push_back(trace_point(f, t, p));
    }
  }
  trace_t.push_back(t_end);
  run.trace.push_back(trace_point(f, t_end, pieces.back()));
  const size_t elements = run.trace.size() - 1;
  std::vector<int> element_of(pieces.size());  // each piece's element
  size_t element = 0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    while (element + 1 < elements && pieces[i].t0() >= trace_t[element + 1] - kSnap) ++element;
    element_of[i] = int(element);
  }
  fill_points(f, pieces, element_of, trace_t, int(elements), run, tributary);
  return run;
}

// A closed face covered all round: every node a trace point, element k the face's edge k.
ContactRun closed_run(const FaceContext &f, const std::vector<CoveredPiece> &pieces, std::vector<double> &tributary) {
  ContactRun run;
  run.closed = true;
  size_t first_on_edge = 0;  // the pieces come along the face: edge k's first piece (a scan of all cost O(edges^2))
  for (int k = 0; k < f.edges; ++k) {
    while (first_on_edge < pieces.size() && pieces[first_on_edge].k < k) ++first_on_edge;
    const bool on_edge = first_on_edge < pieces.size() && pieces[first_on_edge].k == k;
    run.trace.push_back(trace_point(f, k, on_edge ? pieces[first_on_edge] : pieces.front()));
  }
  std::vector<int> element_of(pieces.size());  // element k: edge k, from t = k to k + 1
  for (size_t i = 0; i < pieces.size(); ++i) element_of[i] = pieces[i].k;
  std::vector<double> element_t(f.edges + 1);
  for (int k = 0; k <= f.edges; ++k) element_t[k] = k;
  fill_points(f, pieces, element_of, element_t, f.edges, run, tributary);
  return run;
}

// Merges a face's covered pieces (sorted along the face) into maximal intervals and builds a
// run of each.
void runs_of_face(const FaceContext &f, std::vector<CoveredPiece> pieces, std::vector<ContactRun> &runs,
                  std::vector<double> &tributary) {
  if (pieces.empty()) return;
  std::vector<std::vector<CoveredPiece>> intervals;
  {
    // (each interval copied once at its size: grown piece by piece, a long one was copied into
    // fresh memory again and again)
    size_t begin = 0;
    for (size_t i = 1; i <= pieces.size(); ++i)
      if (i == pieces.size() || std::fabs(pieces[i].t0() - pieces[i - 1].t1()) > 1e-12) {
        intervals.emplace_back(pieces.begin() + begin, pieces.begin() + i);
        begin = i;
      }
  }
  if (f.closed && intervals.front().front().t0() <= 1e-12 && intervals.back().back().t1() >= f.edges - 1e-12) {
    if (intervals.size() == 1) {
      runs.push_back(closed_run(f, intervals.front(), tributary));
      return;
    }
    // The last interval continues through node 0 into the first: join them.
    std::vector<CoveredPiece> joined = intervals.back();
    for (CoveredPiece &p : joined) p.shift = -f.edges;
    joined.insert(joined.end(), intervals.front().begin(), intervals.front().end());
    intervals.front() = joined;
    intervals.pop_back();
  }
  for (const auto &interval : intervals)  // (an interval shorter than the snapping tolerance is no run)
    if (interval.back().t1() - interval.front().t0() > 2 * kSnap) runs.push_back(open_run(f, interval, tributary));
}

// A contact surface seen from afar, for the message of surfaces that do not face each other:
// its outward normal summed over its edges (each the right of its direction, length-weighted:
// the body on the edges' left) and its centre.
struct SurfaceFromAfar {
  Point normal, centre;
};

SurfaceFromAfar from_afar(const Mesh &mesh, const std::vector<SurfaceSegment> &surface) {
  Point normal{0, 0}, centre{0, 0};
  double length = 0;
  for (const SurfaceSegment &s : surface) {
    const Point a = mesh.node(s.a), b = mesh.node(s.b);
    const double l = norm(minus(b, a));
    normal = plus(normal, {b.y - a.y, a.x - b.x});
    centre = plus(centre, scaled(plus(a, b), 0.5 * l)), length += l;
  }
  return {norm(normal) > 0 ? unit(normal) : normal, length > 0 ? scaled(centre, 1 / length) : centre};
}

// Which surface is at fault when no body-1 node sees body 2: a surface whose normal points away
// from the other body. A body with cells has its surface oriented by them (body on
// the left), so it is the wrong side of its body; a host body's edges come oriented by the host,
// so its surface is more likely reversed (edges with the body on their right, the normal
// pointing into the body).
std::string facing_report(const Mesh &body1, const std::vector<SurfaceSegment> &surface1, const Mesh &body2,
                          const std::vector<SurfaceSegment> &surface2) {
  const Mesh *mesh[2] = {&body1, &body2};
  const SurfaceFromAfar seen[2] = {from_afar(body1, surface1), from_afar(body2, surface2)};
  std::string report;
  char text[320];
  // Where the other body lies: its nodes' centroid (two surfaces in contact share their place,
  // so the other surface's centre alone says little), or its surface's centre if a host gave
  // that body's surface nodes only.
  Point where[2];
  for (int k = 0; k < 2; ++k) {
    Point sum{0, 0};
    for (int i = 0; i < mesh[k]->n_nodes(); ++i) sum = plus(sum, mesh[k]->node(i));
    where[k] = scaled(sum, 1.0 / std::max(1, mesh[k]->n_nodes()));
    const double depth = std::fabs(dot(seen[k].normal, minus(where[k], seen[k].centre)));
    if (!(depth > 1e-6 * mesh[k]->characteristic_length())) where[k] = seen[k].centre;
  }
  bool toward[2];
  for (int k = 0; k < 2; ++k) toward[k] = dot(seen[k].normal, minus(where[1 - k], seen[k].centre)) > 0;
  for (int k = 0; k < 2; ++k) {
    if (toward[k]) continue;
    const bool host = mesh[k]->n_cells() == 0;
    if (host)
      std::snprintf(text, sizeof text,
                    " Body %d's surface looks reversed: its normal points away from body %d, so its edges seem to run "
                    "with the body on their right (a host body's edges must have it on their left): give each edge's "
                    "ends the other way round.",
                    k + 1, 2 - k);
    else
      std::snprintf(text, sizeof text,
                    " Body %d's surface (oriented by its cells, the body on its left) faces away from body %d: it is "
                    "not the side of body %d that touches body %d.",
                    k + 1, 2 - k, k + 1, 2 - k);
    report += text;
  }
  std::snprintf(text, sizeof text,
                " Outward normals (mean over the edges): body 1's (%.3g, %.3g) points %s body 2; body 2's (%.3g, %.3g) "
                "points %s body 1.",
                seen[0].normal.x, seen[0].normal.y, toward[0] ? "toward" : "away from", seen[1].normal.x,
                seen[1].normal.y, toward[1] ? "toward" : "away from");
  return report + text;
}

}  // namespace

std::vector<SurfaceSegment> oriented_surface(const Mesh &mesh, const int *edges, int per_edge, int n_edges, int base) {
  std::vector<SurfaceSegment> surface;
  std::vector<std::pair<int, int>> seen;
  for (int e = 0; e < n_edges; ++e) {
    const int *v = edges + per_edge * size_t(e);
    const int a = v[0], b = v[1];
    const std::string where = array_range("edges", per_edge * size_t(e), per_edge * size_t(e) + 1, base);
    if (a < 0 || a >= mesh.n_nodes() || b < 0 || b >= mesh.n_nodes())
      fail(MC_ERROR_ARGUMENT, "%s = (%d, %d): node id out of range [%d, %d)", where.c_str(), a + base, b + base, base,
           mesh.n_nodes() + base);
    const BoundaryEdge *edge = mesh.boundary_edge(a, b);
    char hint[160];
    if (!edge)
      fail(MC_ERROR_CONTACT, "%s = (%d, %d) is not an edge on the boundary of the mesh%s%s", where.c_str(), a + base,
           b + base, mesh.edge_hint(a, b, base, hint, 160),
           per_edge == 3 ? " (a curved edge is given as (end, end, middle))" : "");
    surface.push_back({edge->from, edge->to, edge->mid});
    seen.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(seen.begin(), seen.end());
  auto dup = std::adjacent_find(seen.begin(), seen.end());
  if (dup != seen.end()) fail(MC_ERROR_CONTACT, "edge (%d, %d) is given twice", dup->first + base, dup->second + base);
  return surface;
}

ContactGeometry build_contact_geometry(const Mesh &body1, const std::vector<SurfaceSegment> &surface1,
                                       const Mesh &body2, const std::vector<SurfaceSegment> &surface2,
                                       int normal_choice, const SurfaceOptions &surface_options,
                                       const LineMeasure &measure) {
  ContactGeometry g;
  g.nonmortar = SurfaceCurve(body1, surface1, surface_options);
  g.mortar = SurfaceCurve(body2, surface2, surface_options);
  const SurfaceCurve &curve1 = g.nonmortar, &curve2 = g.mortar;

  // Positions: the nodes of each face of body 1, with the face's nodal normals (on a quadratic
  // face each node followed by its edge's middle, with the curve's normal there).
  std::vector<int> first_position;
  // (A surface is quadratic when its edges have middles: a quadratic mesh's, or a host's 3-node edges.)
  g.quadratic_nonmortar = !surface1.empty() && surface1.front().mid >= 0;
  const bool quadratic_mortar = !surface2.empty() && surface2.front().mid >= 0;
  const int stride = g.quadratic_nonmortar ? 2 : 1;
  for (const SurfaceFace &face : curve1.faces()) {
    first_position.push_back(int(g.nodes.size()));
    for (size_t k = 0; k < face.nodes.size(); ++k) {
      g.nodes.push_back(face.nodes[k]), g.normals.push_back(face.normals[k]);
      if (stride == 2 && int(k) < face.edges()) {
        const CurveSegment &c = curve1.segments()[face.segment_begin + int(k)];
        g.nodes.push_back(c.mid), g.normals.push_back(c.nm);
      }
    }
  }
  g.segment_positions.resize(curve1.segments().size());
  for (size_t seg = 0; seg < curve1.segments().size(); ++seg) {
    const CurveSegment &c = curve1.segments()[seg];
    const int m = int(curve1.faces()[c.face].nodes.size());
    const int pa = first_position[c.face] + stride * c.k, pb = first_position[c.face] + stride * ((c.k + 1) % m);
    g.segment_positions[seg] = {pa, pb, c.quadratic() ? pa + 1 : -1};
  }
  const size_t n = g.nodes.size();
  std::vector<int> input_of, near, kept;  // (mortar_side_normal's: curve2's segment k is surface2[input_of[k]])
  if (normal_choice == MC_NORMAL_MORTAR && !curve2.smooth() && !quadratic_mortar) {
    std::vector<std::pair<std::pair<int, int>, int>> by_ends;
    for (size_t i = 0; i < surface2.size(); ++i) by_ends.push_back({{surface2[i].a, surface2[i].b}, int(i)});
    std::sort(by_ends.begin(), by_ends.end());
    for (const CurveSegment &c : curve2.segments())
      input_of.push_back(std::lower_bound(by_ends.begin(), by_ends.end(), std::make_pair(std::make_pair(c.a, c.b), -1))->second);
  }
  if (normal_choice == MC_NORMAL_MORTAR)
    for (size_t j = 0; j < n; ++j) {
      Point p = body1.node(g.nodes[j]);
      if (!curve2.smooth() && !quadratic_mortar) {
        deciding_segments(p, g.normals[j], body2, surface2, curve2, input_of, near, kept);
        g.normals[j] = mortar_side_normal(p, g.normals[j], body2, surface2, kept);
        continue;
      }
      int seg;
      double s;
      if (curve2.closest_point(p, g.normals[j], seg, s)) {
        Point m = curve2.surface_normal(seg, s);
        g.normals[j] = {-m.x, -m.y};
      }
    }
  g.gap0.assign(n, kNoGap);
  g.projection.assign(n, SurfacePoint{});
  bool any = false;
  int hint = -1;  // neighbouring positions hit neighbouring segments
  for (size_t j = 0; j < n; ++j) {
    int seg;
    double s, t;
    if (curve2.cast(body1.node(g.nodes[j]), g.normals[j], seg, s, t, hint))
      g.gap0[j] = t, g.projection[j] = {seg, s}, any = true, hint = seg;
  }
  if (!any)
    fail(MC_ERROR_CONTACT,
         "no node of body 1's contact surface sees body 2's contact surface along its outward normal: "
         "the surfaces do not face each other.%s",
         facing_report(body1, surface1, body2, surface2).c_str());

  // The direction along which body 1 looks for body 2 between its nodes: its smooth curve's
  // normal, or else the interpolated nodal normals (faceted, or body 2's normals chosen: the
  // projection then follows the constraint's own directions).
  // On a quadratic surface the positions' normals (its nodes' and its middles') interpolated by
  // the edge's shape functions: continuous from edge to edge.
  LookDirection look = [&](int seg, double s) -> Point {
    const std::array<int, 3> &pos = g.segment_positions[seg];
    if (pos[2] >= 0) {
      double shape[3], ds[3];
      line_shapes(3, s, shape, ds);
      return unit(plus(plus(scaled(g.normals[pos[0]], shape[0]), scaled(g.normals[pos[1]], shape[1])),
                       scaled(g.normals[pos[2]], shape[2])));
    }
    if (curve1.smooth() && normal_choice == MC_NORMAL_NONMORTAR) return curve1.look_direction(seg, s);
    return unit(lerp(g.normals[pos[0]], g.normals[pos[1]], s));
  };

  // Segmentation of each body-1 segment: breakpoints where body-2 nodes project, then each
  // piece facing one body-2 segment (tested at its midpoint).
  // Body 2's nodes (each once) in surface order, so that the tree's boxes are short pieces of it.
  const PointsBetweenLines body2_points = [&] {
    std::vector<char> taken(body2.n_nodes(), 0);
    std::vector<Point> points;
    for (const CurveSegment &c : curve2.segments())
      for (int id : {c.a, c.b})
        if (!taken[id]) taken[id] = 1, points.push_back(body2.node(id));
    return PointsBetweenLines(std::move(points));
  }();
  std::vector<Point> between;
  g.tributary.assign(n, 0.0);
  for (int face = 0; face < int(curve1.faces().size()); ++face) {
    const SurfaceFace &sf = curve1.faces()[face];
    FaceContext context{g, face, sf.edges(), sf.closed, first_position[face], look, measure};
    context.stride = stride;
    // Quadratic traces (either side): 5 points, exact to degree 9 on straight pieces (the
    // products of a linear multiplier, a quadratic trace and the weight 2 pi r are of degree 4);
    // linear ones keep the 3 points (degree 5) that are exact for theirs.
    context.points = g.quadratic_nonmortar || quadratic_mortar ? 5 : 3;
    std::vector<CoveredPiece> pieces;
    pieces.reserve(size_t(sf.edges()) * 2);  // (most edges hold one to three; grown, copied into fresh memory)
    std::vector<double> breaks;  // (kept from edge to edge: an allocation per edge was a tenth of the runs' time)
    for (int k = 0; k < sf.edges(); ++k) {
      const int seg = curve1.segment_of(face, k);
      breaks.assign({0.0, 1.0});
      // A body-2 node can project inside the segment only if it lies between the look lines
      // of the segment's ends (a sign change of the bracketing function).
      const Point xa = curve1.segments()[seg].pa, xb = curve1.segments()[seg].pb;
      body2_points.find(xa, look(seg, 0), xb, look(seg, 1), between);
      for (Point y : between) {
        double xi;
        if (inverse_projection(curve1, seg, look, y, xi)) breaks.push_back(xi);
      }
      std::sort(breaks.begin(), breaks.end());
      for (size_t b = 0; b + 1 < breaks.size(); ++b) {
        const double xi0 = breaks[b], xi1 = breaks[b + 1];
        if (xi1 - xi0 < 1e-12) continue;
        const double xim = 0.5 * (xi0 + xi1);
        int mortar;
        double s, t;
        if (!curve2.cast(curve1.point(seg, xim), look(seg, xim), mortar, s, t, hint)) continue;
        pieces.push_back({k, xi0, xi1, mortar});
        hint = mortar;
      }
    }
    runs_of_face(context, std::move(pieces), g.runs, g.tributary);
  }

  return g;
}

}  // namespace mc
