// Contact geometry between body 1 (non-mortar, the paper's Omega^1) and body 2 (mortar):
// the chains of body 1's contact surface with nodal normals, the projection of each body-1
// node along its normal onto body 2's surface (initial gap g0), and the segmentation of
// Gamma_c into pieces on which both traces are linear (section 3: needed for exact mortar
// integrals).
#pragma once
#include "line_measure.hpp"
#include "mesh.hpp"
#include <limits>
#include <utility>
#include <vector>

namespace mc {

// A surface given as boundary edges, oriented like their cells (body on the left).
struct SurfaceSegment {
  int a, b;
};

// Where a point lands on body 2's surface: segment index and local coordinate eta in [0,1]
// (the point is (1-eta) a + eta b).
struct SurfacePoint {
  int segment = -1;
  double eta = 0;
};

// A piece of Gamma_c: part [xi0, xi1] of body-1 segment (node positions k, k+1 of a run),
// facing part [eta0, eta1] of body-2 segment `segment`; the map xi -> eta is linear on it.
struct MortarPiece {
  int k;  // run-local index of the segment's first node
  double xi0, xi1;
  int segment;
  double eta0, eta1;
  double length;  // physical length on body 1's side
};

// A maximal run of consecutive body-1 nodes that see body 2: the paper's Gamma_c with ends
// c1 = first, c2 = last (one per connected piece of contact).
struct ContactRun {
  std::vector<int> positions;       // indices into ContactGeometry::nodes
  std::vector<double> segment_length;  // body-1 segment k joins positions k and k+1
  std::vector<MortarPiece> pieces;
};

struct ContactGeometry {
  std::vector<int> nodes;          // body-1 contact nodes, chain after chain
  std::vector<Point> normals;      // unit outward normals of body 1 at those nodes
  std::vector<double> gap0;        // along the normal; +inf where body 2 is not seen
  std::vector<SurfacePoint> projection;  // of each node onto body 2 (segment -1: none)
  std::vector<SurfaceSegment> mortar_segments;  // body 2's contact edges
  std::vector<ContactRun> runs;
  std::vector<double> tributary;   // integral of phi_j w over body 1's contact surface (w: the measure's t or 2 pi r)
};

// Checks the edges (2 per edge, 0-based) are boundary edges of the mesh and returns them
// oriented as their cells. Throws MC_ERROR_CONTACT naming the edge otherwise.
std::vector<SurfaceSegment> oriented_surface(const Mesh &mesh, const int *edges, int n_edges, int base = 0);

// The whole geometry. Throws MC_ERROR_CONTACT if no body-1 node sees body 2.
// normal_choice: MC_NORMAL_NONMORTAR or MC_NORMAL_MORTAR. measure: the weight of the
// tributary integrals (thickness, or 2 pi r in an axisymmetric model).
ContactGeometry build_contact_geometry(const Mesh &body1, const std::vector<SurfaceSegment> &surface1,
                                       const Mesh &body2, const std::vector<SurfaceSegment> &surface2,
                                       int normal_choice, const LineMeasure &measure);

constexpr double kNoGap = std::numeric_limits<double>::infinity();

}  // namespace mc
