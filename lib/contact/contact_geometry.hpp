// Contact geometry between body 1 (non-mortar, the paper's Omega^1) and body 2 (mortar):
// the contact positions of body 1 with their normals, the projection of each along its normal
// onto body 2's surface (initial gap g0), and Gamma_c: the parts of body 1's surface that see
// body 2, as runs of trace points with quadrature points on which both traces are known
// (section 3: the mortar integrals need this segmentation).
//
// Gamma_c follows the covered part of body 1's surface, not its nodes: a body-1 segment that
// body 2 covers only partly belongs to Gamma_c over its covered part, and the run then ends at
// a trace point inside that segment (where body 2's last node projects). As body 2's end
// moves across a body-1 node, the run's end moves continuously along the segment, so the
// constraint, and the answer, change continuously. A closed loop covered all round is a closed
// run without ends.
#pragma once
#include "contact/contact_surface.hpp"
#include "bodies/line_measure.hpp"
#include "bodies/mesh.hpp"
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace mc {

// A point of body 2's contact surface: curve segment and its parameter eta in [0,1] (also the
// coordinate of the linear displacement trace on that edge).
struct SurfacePoint {
  int segment = -1;
  double eta = 0;
};

// A trace point of Gamma_c on body 1: a contact position (b = -1, xi = 0) or a point inside the
// segment from position a to position b, at (1 - xi) a + xi b.
struct TracePoint {
  int a = -1, b = -1;
  double xi = 0;
  Point x{0, 0};         // where it is on body 1's chords (the element ends of the mortar integrals)
  Point normal{0, 0};    // unit normal of the constraint there
  double gap0 = 0;       // initial gap along it (without the host's offsets)
  SurfacePoint projection;
  bool is_position() const { return b < 0; }
};

// A quadrature point of an element of a run: the element's own coordinate s in [0,1], the
// weight (the line measure included: chord length times the thickness, or times 2 pi r) and the
// body-2 point it faces.
struct QuadraturePoint {
  double s, weight;
  SurfacePoint mortar;
  int segment1 = -1;  // body 1's curve segment and parameter there (its trace's shape functions)
  double xi1 = 0;
  double gap = 0;     // initial gap along the look direction (without the host's offsets)
  Point normal{0, 0}; // that look direction
};

// A connected piece of Gamma_c: the paper's Gamma_c with trace nodes c1 = trace.front(),
// c2 = trace.back(), or a closed loop (element k joins trace k and k+1 mod size).
// The quadrature points of one element of a run, as a range over the run's array.
struct ElementPoints {
  const QuadraturePoint *first, *last;
  const QuadraturePoint *begin() const { return first; }
  const QuadraturePoint *end() const { return last; }
  size_t size() const { return size_t(last - first); }
  bool empty() const { return first == last; }
  const QuadraturePoint &front() const { return *first; }
  const QuadraturePoint &back() const { return *(last - 1); }
};

// The points of a run's elements, element after element in one array (CSR): a long interface
// has tens of thousands of elements, and an array each cost an allocation each, most of the
// runs' time (docs/notes/contact-geometry-cost.md).
struct RunElements {
  std::vector<QuadraturePoint> points;
  std::vector<int> start{0};  // element e: points start[e] .. start[e + 1] - 1
  size_t size() const { return start.size() - 1; }
  ElementPoints operator[](size_t e) const { return {points.data() + start[e], points.data() + start[e + 1]}; }
};

struct ContactRun {
  bool closed = false;
  std::vector<TracePoint> trace;
  RunElements elements;
};

struct ContactGeometry {
  // Contact positions: body 1's contact-surface nodes face after face; a node where the
  // surface is split at a corner is a position in each of its two faces, with that face's normal.
  // On a quadratic surface the mid-edge nodes are positions too, each after its edge's first
  // node (corner, middle, corner, middle, ... along the face); a middle's normal is its
  // curve's.
  std::vector<int> nodes;
  std::vector<Point> normals;      // unit outward normals of body 1 at the positions
  std::vector<double> gap0;        // along the normal; +inf where body 2 is not seen
  std::vector<SurfacePoint> projection;  // of each position onto body 2 (segment -1: none)
  std::vector<double> tributary;   // integral of phi_j w over Gamma_c (the covered part; w: t or 2 pi r)
  std::vector<ContactRun> runs;
  SurfaceCurve nonmortar, mortar;  // the two surfaces as the contact constraint sees them
  // The positions of each body-1 curve segment's first node, last node and middle (-1: linear).
  std::vector<std::array<int, 3>> segment_positions;
  bool quadratic_nonmortar = false;  // body 1's surface has quadratic edges
};

// Checks the edges (per_edge ids each, 0-based: the two corners, then a middle that is not
// looked at here) are boundary edges of the mesh and returns them oriented as their cells.
// Throws MC_ERROR_CONTACT naming the edge (its position in the caller's array, in base) otherwise.
std::vector<SurfaceSegment> oriented_surface(const Mesh &mesh, const int *edges, int per_edge, int n_edges, int base);

// The whole geometry. Throws MC_ERROR_CONTACT if no body-1 node sees body 2.
// normal_choice: MC_NORMAL_NONMORTAR or MC_NORMAL_MORTAR.
ContactGeometry build_contact_geometry(const Mesh &body1, const std::vector<SurfaceSegment> &surface1,
                                       const Mesh &body2, const std::vector<SurfaceSegment> &surface2,
                                       int normal_choice, const SurfaceOptions &surface_options,
                                       const LineMeasure &measure);

constexpr double kNoGap = std::numeric_limits<double>::infinity();

}  // namespace mc
