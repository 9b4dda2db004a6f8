// body_mesh.cpp - a body's mesh and its groups out of a Gmsh file (see body_mesh.hpp).
#include "body_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace mcrun {

namespace {

std::string where(const GmshMesh &file, const Element &e) {
  return file.path + ":" + std::to_string(e.line) + ": element " + std::to_string(e.tag);
}

uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(uint32_t(a)) << 32) | uint32_t(b);
}

// The physical tags called `name` among the dimensions allowed (dims[d] true); throws when the
// name is unknown or only exists with another dimension. `purpose` says what the group is for.
std::vector<int> tags_named(const GmshMesh &file, const std::string &name, const bool dims[3], const std::string &purpose,
                            int *dim_found = nullptr) {
  std::vector<const PhysicalGroup *> found = file.groups_named(name);
  if (found.empty())
    throw MeshError("no physical group named '" + name + "' in " + file.path + " (its groups: " + file.group_list() +
                    ")");
  std::vector<int> tags;
  for (const PhysicalGroup *g : found)
    if (g->dim <= 2 && dims[g->dim]) {
      tags.push_back(g->tag);
      if (dim_found) *dim_found = g->dim;
    }
  if (tags.empty())
    throw MeshError("physical group '" + name + "' in " + file.path + " has dimension " + std::to_string(found[0]->dim) +
                    ", but " + purpose);
  return tags;
}

bool in_groups(const Element &e, const std::vector<int> &tags) {
  for (int t : e.physical_tags)
    if (std::find(tags.begin(), tags.end(), t) != tags.end()) return true;
  return false;
}

// Twice the signed area of a polygon (positive when counter-clockwise).
double twice_signed_area(const std::vector<double> &xy, const std::vector<int> &nodes) {
  double sum = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    size_t next = (k + 1) % nodes.size();
    sum += xy[2 * nodes[k]] * xy[2 * nodes[next] + 1] - xy[2 * nodes[next]] * xy[2 * nodes[k] + 1];
  }
  return sum;
}

double longest_side(const std::vector<double> &xy, const std::vector<int> &nodes) {
  double longest = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    size_t next = (k + 1) % nodes.size();
    longest = std::max(longest, std::hypot(xy[2 * nodes[next]] - xy[2 * nodes[k]],
                                           xy[2 * nodes[next] + 1] - xy[2 * nodes[k] + 1]));
  }
  return longest;
}

int corners_of(size_t nodes_per_cell) { return nodes_per_cell == 3 || nodes_per_cell == 6 ? 3 : 4; }

// "a 6-node triangle (second order)", for messages.
std::string cell_kind(size_t nodes_per_cell) {
  const bool triangle = corners_of(nodes_per_cell) == 3;
  return (nodes_per_cell == 8 ? "an " : "a ") + std::to_string(nodes_per_cell) + "-node " +
         (triangle ? "triangle" : "quadrilateral") + (nodes_per_cell > 4 ? " (second order)" : " (first order)");
}

// "6-node triangles (second order)": a body's cells, for messages.
std::string cells_kind(int nodes_per_cell) {
  const bool triangle = corners_of(size_t(nodes_per_cell)) == 3;
  return std::to_string(nodes_per_cell) + "-node " + (triangle ? "triangles" : "quadrilaterals") +
         (nodes_per_cell > 4 ? " (second order)" : " (first order)");
}

// Why two cells of one body cannot be mixed, and what to mesh instead.
std::string mixed_cells_hint(size_t a, size_t b) {
  if ((a > 4) != (b > 4))
    return "a body takes one cell type, all first order or all second order (mesh the whole body with "
           "-order 2, or Mesh.ElementOrder = 2)";
  if (corners_of(a) == corners_of(b))  // 8- and 9-node quadrilaterals
    return "a body takes one cell type (Mesh.SecondOrderIncomplete = 1 gives 8-node quadrilaterals everywhere, "
           "0 gives 9-node ones)";
  return "a body takes one cell type (for all quadrilaterals mesh with Mesh.RecombineAll = 1 and "
         "Mesh.SubdivisionAlgorithm = 1)";
}

// The cell's nodes counter-clockwise: Gmsh orients cells as their surface, and a surface built
// from a clockwise curve loop gives clockwise cells, which the library rejects. The orientation
// is the corners'; reversing a second-order cell reverses its corners after the first and its
// mid-edge nodes (side 0-1 becomes the last side 1-0), and keeps a 9-node quad's centre.
std::vector<int> counter_clockwise(const GmshMesh &file, const Element &e) {
  std::vector<int> nodes = e.nodes;
  const int corners = corners_of(nodes.size());
  const std::vector<int> corner_nodes(nodes.begin(), nodes.begin() + corners);
  const double area = twice_signed_area(file.xy, corner_nodes), size = longest_side(file.xy, corner_nodes);
  if (!(std::fabs(area) > 1e-12 * size * size))
    throw MeshError(where(file, e) + " is a degenerate cell (zero area)");
  if (area < 0) {
    std::reverse(nodes.begin() + 1, nodes.begin() + corners);
    if (nodes.size() > size_t(corners)) std::reverse(nodes.begin() + corners, nodes.begin() + 2 * corners);
  }
  return nodes;
}

void collect_boundary(BodyMesh &mesh) {
  const int n = mesh.nodes_per_cell, corners = mesh.corners_per_cell();
  for (int c = 0; c < mesh.n_cells(); ++c)
    for (int k = 0; k < corners; ++k) {
      const int *cell = &mesh.cells[size_t(c) * size_t(n)];
      const int a = cell[k], b = cell[(k + 1) % corners], mid = mesh.quadratic() ? cell[corners + k] : -1;
      auto [it, fresh] = mesh.edges.emplace(edge_key(a, b), BodyMesh::DirectedEdge{a, b, 1, mid});
      if (!fresh) ++it->second.cells;
    }
}

// A line of a group whose order (2 or 3 nodes) is not the body's: its mid-edge node would be
// missing from a support, or a 3-node line would name a side the body's cells do not have.
void check_line_order(const BodyMesh &mesh, const Element &e, const std::string &name) {
  if (e.dim != 1 || (e.nodes.size() == 3) == mesh.quadratic()) return;
  throw MeshError(where(*mesh.file, e) + " (group '" + name + "') is a " + std::to_string(e.nodes.size()) +
                  "-node line but body " + std::to_string(mesh.body) + "'s cells are " + cells_kind(mesh.nodes_per_cell) +
                  ": lines and cells must have the same order (mesh the whole file with -order " +
                  (mesh.quadratic() ? "2" : "1") + ")");
}

}  // namespace

BodyMesh extract_body(const GmshMesh &file, const std::string &domain, int body) {
  BodyMesh mesh;
  mesh.file = &file;
  mesh.body = body;
  std::vector<int> tags;
  if (!domain.empty()) {
    const bool surfaces[3] = {false, false, true};
    tags = tags_named(file, domain, surfaces, "a body's domain must be a surface group (dimension 2)");
  }
  std::vector<std::vector<int>> cells;
  const Element *first = nullptr;
  for (const Element &e : file.elements) {
    if (e.dim != 2 || (!domain.empty() && !in_groups(e, tags))) continue;
    if (!first) first = &e;
    if (e.nodes.size() != first->nodes.size())
      throw MeshError(where(file, e) + " is " + cell_kind(e.nodes.size()) + " but element " + std::to_string(first->tag) +
                      " (line " + std::to_string(first->line) + ") is " + cell_kind(first->nodes.size()) + ": " +
                      mixed_cells_hint(e.nodes.size(), first->nodes.size()));
    cells.push_back(counter_clockwise(file, e));
    mesh.cell_tags.push_back(e.tag);
  }
  if (cells.empty())
    throw MeshError(file.path + ": no 2D cells" + (domain.empty() ? std::string() : " in group '" + domain + "'"));
  mesh.nodes_per_cell = int(first->nodes.size());

  // Compact node ids in file order: only the nodes of this body's cells.
  mesh.compact.assign(file.node_tags.size(), -1);
  for (const auto &c : cells)
    for (int v : c) mesh.compact[size_t(v)] = 0;
  for (size_t i = 0; i < mesh.compact.size(); ++i) {
    if (mesh.compact[i] < 0) continue;
    mesh.compact[i] = mesh.n_nodes();
    mesh.node_tags.push_back(file.node_tags[i]);
    mesh.xy.push_back(file.xy[2 * i]);
    mesh.xy.push_back(file.xy[2 * i + 1]);
  }
  for (const auto &c : cells)
    for (int v : c) mesh.cells.push_back(mesh.compact[size_t(v)]);
  collect_boundary(mesh);
  return mesh;
}

std::vector<int> group_nodes(const BodyMesh &mesh, const std::string &name) {
  const GmshMesh &file = *mesh.file;
  const bool any[3] = {true, true, true};
  const std::vector<int> tags = tags_named(file, name, any, "node groups need dimension 0, 1 or 2");
  std::vector<int> nodes;
  for (const Element &e : file.elements) {
    if (!in_groups(e, tags)) continue;
    const size_t before = nodes.size();
    for (int v : e.nodes)
      if (mesh.compact[size_t(v)] >= 0) nodes.push_back(mesh.compact[size_t(v)]);
    if (nodes.size() > before) check_line_order(mesh, e, name);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes.empty())
    throw MeshError("physical group '" + name + "' in " + file.path + " has no node on body " +
                    std::to_string(mesh.body) + " (it may belong to the other body)");
  return nodes;
}

std::vector<int> group_edges(const BodyMesh &mesh, const std::string &name, std::vector<int> *mids) {
  const GmshMesh &file = *mesh.file;
  const bool lines[3] = {false, true, false};
  const std::vector<int> tags = tags_named(file, name, lines, "edges need a line group (dimension 1)");
  std::vector<int> edges;
  if (mids) mids->clear();
  for (const Element &e : file.elements) {
    if (e.dim != 1 || !in_groups(e, tags)) continue;
    const int a = mesh.compact[size_t(e.nodes[0])], b = mesh.compact[size_t(e.nodes[1])];
    if (a < 0 && b < 0) continue;  // a line of the other body
    if (a < 0 || b < 0)
      throw MeshError(where(file, e) + " (group '" + name + "') has only one node on body " +
                      std::to_string(mesh.body));
    check_line_order(mesh, e, name);
    auto it = mesh.edges.find(edge_key(a, b));
    if (it == mesh.edges.end())
      throw MeshError(where(file, e) + " (group '" + name + "') is not a side of a cell of body " +
                      std::to_string(mesh.body));
    if (it->second.cells != 1)
      throw MeshError(where(file, e) + " (group '" + name + "') lies inside body " + std::to_string(mesh.body) +
                      " (shared by two cells): loads and contact surfaces need boundary edges");
    if (mesh.quadratic()) {
      const int middle = mesh.compact[size_t(e.nodes[2])];
      if (middle != it->second.mid)
        throw MeshError(where(file, e) + " (group '" + name + "'): its middle node " +
                        std::to_string(file.node_tags[size_t(e.nodes[2])]) + " is not the mid-edge node " +
                        std::to_string(mesh.node_tags[size_t(it->second.mid)]) + " of the side " +
                        std::to_string(mesh.node_tags[size_t(a)]) + "-" + std::to_string(mesh.node_tags[size_t(b)]) +
                        " of its cell on body " + std::to_string(mesh.body));
      if (mids) mids->push_back(middle);
    }
    edges.push_back(it->second.from);
    edges.push_back(it->second.to);
  }
  if (edges.empty())
    throw MeshError("physical group '" + name + "' in " + file.path + " has no line on body " +
                    std::to_string(mesh.body) + " (it may belong to the other body)");
  return edges;
}

}  // namespace mcrun
