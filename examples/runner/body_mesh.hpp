// body_mesh.hpp - one body's mesh taken out of a Gmsh file, in the form mc_set_mesh wants:
// nodes renumbered compactly (in file order), cells counter-clockwise, and the physical groups
// turned into node lists (supports, nodal forces) or boundary edges oriented as their cell, the
// body on the left (loads, contact surfaces).
//
// Second-order meshes (gmsh -order 2): 6-node triangles, 8- or 9-node quadrilaterals, with
// 3-node lines on the boundary. An edge handed to the library is named by its two corner nodes
// (the first two nodes of a 3-node line); the library finds the mid-edge node from the cell. A
// node group (supports, nodal forces) holds every node of its elements, mid-edge nodes included.
// A body is all first order or all second order: a 2-node line on a second-order body (or a
// 3-node line on a first-order one) is an error, as its mid-edge node would be left out.
#ifndef MC_RUNNER_BODY_MESH_HPP
#define MC_RUNNER_BODY_MESH_HPP

#include "gmsh_reader.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace mcrun {

struct BodyMesh {
  const GmshMesh *file = nullptr;
  int body = 0;                 // 1 or 2, for messages
  int nodes_per_cell = 0;       // 3, 6 triangles; 4, 8, 9 quadrilaterals (mc_set_mesh's)
  std::vector<double> xy;       // 2 per node
  std::vector<int> cells;       // nodes_per_cell per cell, counter-clockwise, 0-based ids
  std::vector<long> cell_tags;  // file element tag of each cell
  std::vector<long> node_tags;  // file node tag of each node
  std::vector<int> compact;     // file node index -> node id, -1 when not a node of this body

  int n_nodes() const { return int(node_tags.size()); }
  int n_cells() const { return int(cell_tags.size()); }
  int corners_per_cell() const { return nodes_per_cell == 3 || nodes_per_cell == 6 ? 3 : 4; }
  bool quadratic() const { return nodes_per_cell > 4; }

  // Cell sides: key of the unordered corner pair -> the pair in its cell's order, its
  // mid-edge node (-1 on a first-order body) and the number of cells sharing it (1: boundary).
  struct DirectedEdge {
    int from, to, cells, mid;
  };
  std::unordered_map<uint64_t, DirectedEdge> edges;
};

// The body made of the 2D elements of physical surface group `domain` ("" = every 2D element
// of the file). Throws MeshError naming the file, element and line of what is wrong: no cells,
// triangles mixed with quadrilaterals, first-order cells mixed with second-order ones (or 8-
// with 9-node quadrilaterals), a degenerate cell.
BodyMesh extract_body(const GmshMesh &file, const std::string &domain, int body);

// The body's nodes on elements of the physical group(s) called `name`, of any dimension,
// increasing ids: every node of the elements (a 3-node line's middle too). Nodes of the group
// on other bodies are left out; throws MeshError if the group does not exist, has no node on
// this body, or has a line of the other order than the body's cells.
std::vector<int> group_nodes(const BodyMesh &mesh, const std::string &name);

// The body's boundary edges in the line group `name` (2 corner node ids each), each oriented
// as the cell it bounds (the body on its left). Lines with no node on this body are left out
// (they belong to the other body); throws MeshError if the group does not exist, is not a line
// group, has no line on this body, or has a line that is not a boundary edge of its cells
// (for a 3-node line: whose middle is not that side's mid-edge node), or of the other order.
// mids, if given, receives the mid-edge node of each edge (nothing on a first-order body).
std::vector<int> group_edges(const BodyMesh &mesh, const std::string &name, std::vector<int> *mids = nullptr);

}  // namespace mcrun

#endif
