// gmsh_reader.hpp - reads Gmsh ASCII mesh files (.msh, format 2.2 and 4.1) into a flat list of
// nodes, elements and physical groups. Only what a 2D linear-elastic scene needs is kept:
// first- and second-order cells (3- and 6-node triangles, 4-, 8- and 9-node quadrilaterals:
// Gmsh types 2, 9, 3, 16, 10), 2- and 3-node lines (types 1, 8: boundary pieces) and 1-node
// points, with their nodes in Gmsh's order (corners, then mid-edge nodes, then a 9-node quad's
// centre; a 3-node line's ends, then its middle), which is also the library's and VTK's.
// Anything else (order 3 or more, 3D elements, binary or partitioned files) is rejected with a
// message "file:line: what is wrong". Node tags may be sparse and in any order (4.1 writes
// them per entity): elements refer to nodes by index into the node arrays.
#ifndef MC_RUNNER_GMSH_READER_HPP
#define MC_RUNNER_GMSH_READER_HPP

#include <stdexcept>
#include <string>
#include <vector>

namespace mcrun {

// A bad, unreadable or unsupported mesh file. The message names the file and, where there
// is one, the line.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PhysicalGroup {
  int dim;           // 0 points, 1 lines, 2 surfaces
  int tag;
  std::string name;  // "" when the file gives the group no name
};

struct Element {
  int dim;                         // 0 point, 1 line, 2 cell
  std::vector<int> nodes;          // indices into GmshMesh::node_tags / xy (not file tags), Gmsh's order
  std::vector<int> physical_tags;  // physical groups of dimension `dim` holding it
  long tag;                        // element tag in the file (first one if written twice)
  long line;                       // line of the file where it is (first) written
};

struct GmshMesh {
  std::string path;             // as given to read_gmsh, for messages
  std::string version;          // "2.2" or "4.1"
  std::vector<long> node_tags;  // file tag of each node, in file order
  std::vector<double> xy;       // 2 per node (z was checked to be 0)
  std::vector<long> node_lines; // line of each node's coordinates, for messages
  std::vector<Element> elements;
  std::vector<PhysicalGroup> groups;

  // Physical groups with this name, of any dimension (Gmsh allows one name per dimension).
  std::vector<const PhysicalGroup *> groups_named(const std::string &name) const;
  // "name (dim d), ..." of every named group, for "no such group" messages.
  std::string group_list() const;
};

// Reads the file at `path`; throws MeshError.
GmshMesh read_gmsh(const std::string &path);
// Parses mesh text; `name` is the file name used in messages.
GmshMesh parse_gmsh(const std::string &text, const std::string &name);

}  // namespace mcrun

#endif
