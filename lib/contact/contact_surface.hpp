// The geometry a contact surface presents to the contact constraint: its chains of boundary
// edges split into faces at corners, nodal normals, and a curve through the nodes on which
// points, normals and gaps are measured. The mesh itself never moves.
//
//   smooth  : on each face a C1 cubic Hermite curve through the nodes, with tangents from
//             nodal normals that are exact for nodes on a circle at any spacing (Yang, Laursen
//             & Meng, IJNME 62 (2005): each edge normal weighted by the other edge's length);
//             a straight face reconstructs as itself, parametrized like its edges.
//   faceted : the straight edges; nodal normals the mean of the adjacent edges' unit normals
//             (version 0.1's geometry), never split at corners.
//
//   quadratic: a body of quadratic cells (T6, Q8, Q9): each edge is the body's own isoparametric
//             3-node edge (a parabola through its ends and its mid-edge node), in both modes: it is
//             the surface the body has, and is smooth between nodes. Nodal normals are the mean
//             of the two edges' normals at the node (the curve turns there by O(h^2/R)); smooth
//             mode splits chains at corners, faceted mode does not.
//
// A segment's parameter s in [0,1] is also the coordinate of the finite element trace on that
// edge: the displacement at curve point (seg, s) is (1-s) u_a + s u_b, or on a quadratic edge
// N_a(s) u_a + N_b(s) u_b + N_m(s) u_m (cell_shapes.hpp, line_shapes).
#pragma once
#include "bodies/mesh.hpp"
#include <vector>

namespace mc {

// A boundary edge, oriented like its cell (body on the left).
struct SurfaceSegment {
  int a, b;
  int mid = -1;  // the mid-edge node of a quadratic edge
};

struct SurfaceOptions {
  bool smooth = true;
  double feature_angle_degrees = 40;  // smooth only: split a chain where edges turn by more
};

// A maximal piece of a chain on which the curve is smooth: consecutive nodes, closed if it is
// a whole loop without corners. Face ends at a corner hold the corner node; a corner node
// therefore belongs to two faces, with one normal in each.
struct SurfaceFace {
  std::vector<int> nodes;          // mesh node ids (corners of the cells)
  std::vector<int> mids;           // mid-edge node of edge k (nodes k, k+1), -1 on a linear surface
  std::vector<Point> normals;      // unit outward normal at each node, in this face
  bool closed = false;
  bool corner_at_start = false, corner_at_end = false;  // ends where the chain was split
  int segment_begin = 0;           // segments of this face: [segment_begin, segment_begin + edges)
  int edges() const { return closed ? int(nodes.size()) : int(nodes.size()) - 1; }
};

// One edge of a face with what the curve on it needs.
struct CurveSegment {
  int face, k;         // edge k of face: nodes k and k+1 (mod size for a closed face)
  int a, b;            // mesh node ids
  Point pa, pb;        // end points
  Point na, nb;        // unit nodal normals (in this face)
  Point ta, tb;        // Hermite end tangents (smooth), scaled to the chord length; a quadratic edge's own
  int mid = -1;        // quadratic edge: its mid-edge node, at pm, where its curve's normal is nm
  Point pm{0, 0}, nm{0, 0};
  Point edge_normal;   // unit normal of the straight edge
  double length;       // chord length
  Point box_lo, box_hi;  // a box around the curve (its Bezier points' or the chord's)
  bool quadratic() const { return mid >= 0; }
  // The curve's Bezier control points (4 for a Hermite cubic, 3 for a parabola, 2 for a chord).
  int bezier(Point control[4], bool smooth) const;
};

class SurfaceCurve {
public:
  SurfaceCurve() = default;
  SurfaceCurve(const Mesh &mesh, const std::vector<SurfaceSegment> &segments, const SurfaceOptions &options);

  bool smooth() const { return smooth_; }
  const std::vector<SurfaceFace> &faces() const { return faces_; }
  const std::vector<CurveSegment> &segments() const { return segments_; }
  int segment_of(int face, int k) const;

  Point point(int seg, double s) const;
  Point derivative(int seg, double s) const;  // d point / d s
  // The outward normal of the surface at (seg, s): the curve's own (smooth) or the edge's.
  Point surface_normal(int seg, double s) const;
  // The direction along which a non-mortar surface looks for the other body: the curve normal
  // (smooth) or the normalized linear interpolation of the nodal normals (faceted); on a
  // quadratic edge the quadratic interpolation of the nodal normals and the curve's normal at
  // its middle (continuous from edge to edge, where the curve's own normal jumps slightly).
  Point look_direction(int seg, double s) const;
  // Line element |d point / d s|.
  double speed(int seg, double s) const;

  // The intersection of the line p + t n with segment `seg`'s curve, where the curve faces
  // against n: s in [-slack, 1+slack] and t; false if there is none.
  bool intersect_line(int seg, Point p, Point n, double slack, double &s, double &t) const;
  // The nearest hit of the line p + t n (|t| least) on a segment facing against n, over all
  // segments. Returns false if the line misses the surface. `hint`: a segment likely hit (tried
  // first with its neighbours, so that segments farther than its hit are skipped), or -1.
  bool cast(Point p, Point n, int &seg, double &s, double &t, int hint = -1) const;
  // The point of the surface closest to p among segments facing against `facing`.
  bool closest_point(Point p, Point facing, int &seg, double &s) const;
  // The segments whose boxes come within `radius` of p (each once, in no particular order), into
  // `found` (cleared first).
  void segments_near(Point p, double radius, std::vector<int> &found) const;

private:
  // Distance from p to segment seg's box: a lower bound of the distance to its curve.
  double box_distance(int seg, Point p) const;
  // A uniform grid of cells over the segments' boxes (each segment listed in every cell its box
  // meets), so that cast and closest_point look at the segments near p first and stop when the
  // rest are farther than what they found: O(1) segments a query on a mesh-like surface, where a
  // scan of all segments made the geometry of a long interface cost O(q^2)
  // (docs/benchmarks.md, "Long contact interfaces").
  void build_grid();
  // Calls visit(k) once for each segment, ring after ring of cells around p, while
  // go_on(d) holds for d, a lower bound of the distance from p to the cells not yet visited.
  template <class Visit, class GoOn> void visit_near(Point p, Visit &&visit, GoOn &&go_on) const;

  bool smooth_ = true;
  std::vector<SurfaceFace> faces_;
  std::vector<CurveSegment> segments_;
  Point grid_lo_{0, 0};
  double cell_ = 1;
  int grid_nx_ = 0, grid_ny_ = 0;
  std::vector<int> cell_start_, cell_segment_;
};

}  // namespace mc
