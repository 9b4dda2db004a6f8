// gmsh_reader.cpp - Gmsh ASCII .msh reader, formats 2.2 and 4.1 (see gmsh_reader.hpp).
//
// Both formats are read through one token stream that remembers the line of every token, so
// each message can point at the offending line. Format references: the Gmsh manual, section
// "MSH file format" (4.1) and "Legacy formats" (2.2).
#include "gmsh_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace mcrun {

namespace {

struct Token {
  std::string text;
  long line;
};

// Whitespace-separated tokens; a token starting with '"' runs to the closing '"' (physical
// group names may contain spaces) and is returned without the quotes.
class Tokens {
 public:
  Tokens(const std::string &text, const std::string &name) : text_(text), name_(name) {}

  bool at_end() {
    skip_space();
    return pos_ >= text_.size();
  }

  Token next(const std::string &what) {
    if (at_end()) fail(line_, "unexpected end of file while reading " + what);
    Token t{std::string(), line_};
    if (text_[pos_] == '"') {
      size_t close = text_.find('"', pos_ + 1);
      size_t eol = text_.find('\n', pos_ + 1);
      if (close == std::string::npos || close > eol) fail(line_, "unterminated quoted name while reading " + what);
      t.text = text_.substr(pos_ + 1, close - pos_ - 1);
      pos_ = close + 1;
      return t;
    }
    size_t end = pos_;
    while (end < text_.size() && !is_space(text_[end])) ++end;
    t.text = text_.substr(pos_, end - pos_);
    pos_ = end;
    return t;
  }

  long next_int(const std::string &what, long *line = nullptr) {
    Token t = next(what);
    if (line) *line = t.line;
    errno = 0;
    char *end = nullptr;
    long v = std::strtol(t.text.c_str(), &end, 10);
    if (t.text.empty() || *end != '\0' || errno == ERANGE)
      fail(t.line, "expected an integer (" + what + "), found '" + t.text + "'");
    return v;
  }

  // A count or a tag: an integer >= `lowest`.
  long next_count(const std::string &what, long lowest = 0) {
    long line = 0;
    long v = next_int(what, &line);
    if (v < lowest) fail(line, what + " must be at least " + std::to_string(lowest) + ", found " + std::to_string(v));
    return v;
  }

  double next_real(const std::string &what) {
    Token t = next(what);
    errno = 0;
    char *end = nullptr;
    double v = std::strtod(t.text.c_str(), &end);
    if (t.text.empty() || *end != '\0' || !std::isfinite(v))
      fail(t.line, "expected a finite number (" + what + "), found '" + t.text + "'");
    return v;
  }

  void expect(const std::string &word) {
    Token t = next(word);
    if (t.text != word) fail(t.line, "expected " + word + ", found '" + t.text + "'");
  }

  long line() const { return line_; }

  [[noreturn]] void fail(long line, const std::string &message) const {
    throw MeshError(name_ + ":" + std::to_string(line) + ": " + message);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  const std::string &text_;
  std::string name_;
  size_t pos_ = 0;
  long line_ = 1;
};

// The element types kept: their dimension and node count.
struct ElementShape {
  int dim;
  int nodes;
};

// Gmsh's node order is the library's (and VTK's): corners first (counter-clockwise when the
// surface is), then the mid-edge nodes of the sides 0-1, 1-2, ..., then a 9-node quad's centre;
// a 3-node line is its two ends, then its middle.
bool supported_shape(long type, ElementShape *shape) {
  switch (type) {
    case 15: *shape = {0, 1}; return true;  // point
    case 1: *shape = {1, 2}; return true;   // 2-node line
    case 2: *shape = {2, 3}; return true;   // 3-node triangle
    case 3: *shape = {2, 4}; return true;   // 4-node quadrilateral
    case 8: *shape = {1, 3}; return true;   // 3-node line (second order)
    case 9: *shape = {2, 6}; return true;   // 6-node triangle (T6)
    case 16: *shape = {2, 8}; return true;  // 8-node quadrilateral (Q8, serendipity)
    case 10: *shape = {2, 9}; return true;  // 9-node quadrilateral (Q9, Lagrange)
    default: return false;
  }
}

// Why an element type is refused, in words a user can act on.
std::string unsupported_type_message(long type) {
  static const std::map<long, const char *> higher_order = {
      {20, "9-node triangle"},  {21, "10-node triangle"},  {22, "12-node triangle"},     {23, "15-node triangle"},
      {24, "15-node triangle"}, {25, "21-node triangle"},  {26, "4-node line"},          {27, "5-node line"},
      {28, "6-node line"},      {36, "16-node quadrilateral"}, {37, "25-node quadrilateral"}};
  static const std::map<long, const char *> solid = {
      {4, "tetrahedron"},  {5, "hexahedron"},  {6, "prism"},        {7, "pyramid"},      {11, "10-node tetrahedron"},
      {12, "27-node hexahedron"}, {13, "18-node prism"}, {14, "14-node pyramid"}, {17, "20-node hexahedron"},
      {18, "15-node prism"}, {19, "13-node pyramid"}};
  std::string kind = "element type " + std::to_string(type);
  if (auto it = higher_order.find(type); it != higher_order.end())
    return kind + " (" + it->second + ", order 3 or more, or incomplete) is not supported: only first- and "
                  "second-order triangles and quadrilaterals (3, 4, 6, 8, 9 nodes) and 2- and 3-node lines are "
                  "(mesh with -order 1 or -order 2)";
  if (auto it = solid.find(type); it != solid.end())
    return kind + " (" + it->second + ", 3D) is not supported: the scene is 2D (mesh with -2)";
  return kind + " is not supported: only 3- and 6-node triangles (2, 9), 4-, 8- and 9-node quadrilaterals "
                "(3, 16, 10), 2- and 3-node lines (1, 8) and points (15) are";
}

class Reader {
 public:
  Reader(const std::string &text, const std::string &name) : t_(text, name) { mesh_.path = name; }

  GmshMesh read() {
    bool has_format = false, has_nodes = false, has_elements = false;
    while (!t_.at_end()) {
      Token head = t_.next("a section header");
      if (!has_format && head.text != "$MeshFormat")
        t_.fail(head.line, "the file does not start with $MeshFormat: not a Gmsh mesh file");
      if (head.text.size() < 2 || head.text[0] != '$')
        t_.fail(head.line, "expected a section header such as $Nodes, found '" + head.text + "'");
      const std::string section = head.text.substr(1);
      if (section == "MeshFormat") {
        read_format(head.line);
        has_format = true;
      } else if (section == "PhysicalNames") {
        read_physical_names();
      } else if (section == "Entities") {
        read_entities();
        has_entities_ = true;
      } else if (section == "Nodes") {
        if (has_nodes) t_.fail(head.line, "a second $Nodes section");
        if (v4_) read_nodes_v4(); else read_nodes_v2();
        check_planar();
        has_nodes = true;
      } else if (section == "Elements") {
        if (!has_nodes) t_.fail(head.line, "$Elements before $Nodes");
        if (has_elements) t_.fail(head.line, "a second $Elements section");
        if (v4_) read_elements_v4(); else read_elements_v2();
        has_elements = true;
      } else if (section == "PartitionedEntities") {
        t_.fail(head.line, "partitioned meshes are not supported (mesh without partitioning)");
      } else {
        skip_section(section);  // $NodeData, $Periodic, $Comments, ...: not needed here
        continue;
      }
      t_.expect("$End" + section);
    }
    if (!has_format) t_.fail(t_.line(), "empty file: not a Gmsh mesh file");
    if (!has_nodes) t_.fail(t_.line(), "no $Nodes section");
    if (!has_elements) t_.fail(t_.line(), "no $Elements section");
    return std::move(mesh_);
  }

 private:
  void read_format(long line) {
    Token version = t_.next("the format version");
    long file_type = t_.next_int("the file type");
    t_.next_int("the data size");
    if (version.text == "2.2") {
      v4_ = false;
    } else if (version.text == "4.1") {
      v4_ = true;
    } else {
      t_.fail(version.line, "format version " + version.text +
                                " is not supported: save as 4.1 or 2.2 (gmsh -format msh41 or -format msh22)");
    }
    if (file_type != 0)
      t_.fail(line, "binary .msh files are not supported: save as ASCII (Mesh.Binary = 0, the default)");
    mesh_.version = version.text;
  }

  void read_physical_names() {
    long n = t_.next_count("the number of physical names");
    for (long k = 0; k < n; ++k) {
      long line = 0;
      long dim = t_.next_int("a physical group's dimension", &line);
      if (dim < 0 || dim > 3) t_.fail(line, "physical group dimension " + std::to_string(dim) + " is not 0..3");
      long tag = t_.next_count("a physical group's tag", 1);
      Token name = t_.next("a physical group's name");
      mesh_.groups.push_back({int(dim), int(tag), name.text});
    }
  }

  // Each entity's physical tags: 4.1 gives elements their groups through the entity they
  // belong to.
  void read_entities() {
    long count[4];
    for (int d = 0; d < 4; ++d) count[d] = t_.next_count("the number of entities of dimension " + std::to_string(d));
    for (int d = 0; d < 4; ++d)
      for (long k = 0; k < count[d]; ++k) {
        long tag = t_.next_int("an entity tag");
        const int box = d == 0 ? 3 : 6;  // a point has X Y Z, the others a bounding box
        for (int c = 0; c < box; ++c) t_.next_real("an entity's coordinates");
        long n_physical = t_.next_count("an entity's number of physical tags");
        std::vector<int> &physical = entity_physicals_[{d, tag}];
        for (long p = 0; p < n_physical; ++p) physical.push_back(int(t_.next_int("a physical tag")));
        if (d > 0) {
          long n_bounding = t_.next_count("an entity's number of bounding entities");
          for (long b = 0; b < n_bounding; ++b) t_.next_int("a bounding entity tag");
        }
      }
  }

  void add_node(long tag, long line, double x, double y, double z) {
    auto [it, fresh] = node_index_.emplace(tag, int(mesh_.node_tags.size()));
    if (!fresh) t_.fail(line, "node " + std::to_string(tag) + " is defined twice");
    mesh_.node_tags.push_back(tag);
    mesh_.node_lines.push_back(line);
    mesh_.xy.push_back(x);
    mesh_.xy.push_back(y);
    z_.push_back(z);
  }

  void read_nodes_v2() {
    long n = t_.next_count("the number of nodes");
    for (long k = 0; k < n; ++k) {
      long line = 0;
      long tag = t_.next_int("a node tag", &line);
      double x = t_.next_real("a node's x"), y = t_.next_real("a node's y"), z = t_.next_real("a node's z");
      add_node(tag, line, x, y, z);
    }
  }

  void read_nodes_v4() {
    long blocks = t_.next_count("the number of node blocks");
    long total = t_.next_count("the number of nodes");
    t_.next_int("the smallest node tag");
    t_.next_int("the largest node tag");
    for (long b = 0; b < blocks; ++b) {
      long dim = t_.next_int("a node block's entity dimension");
      t_.next_int("a node block's entity tag");
      long parametric = t_.next_int("a node block's parametric flag");
      long n = t_.next_count("a node block's number of nodes");
      std::vector<std::pair<long, long>> tags(static_cast<size_t>(n));  // tag, line
      for (auto &tl : tags) tl.first = t_.next_int("a node tag", &tl.second);
      const long extra = parametric ? dim : 0;  // parametric coordinates u (curves), u v (surfaces)
      for (auto &tl : tags) {
        double x = t_.next_real("a node's x"), y = t_.next_real("a node's y"), z = t_.next_real("a node's z");
        for (long e = 0; e < extra; ++e) t_.next_real("a node's parametric coordinate");
        add_node(tl.first, tl.second, x, y, z);
      }
    }
    if (long(mesh_.node_tags.size()) != total)
      t_.fail(t_.line(), "$Nodes announces " + std::to_string(total) + " nodes but its blocks hold " +
                             std::to_string(mesh_.node_tags.size()));
  }

  // The node tags of one element of `shape`, as indices into the node arrays.
  std::vector<int> element_nodes(const ElementShape &shape, long element_tag) {
    std::vector<int> nodes;
    for (int k = 0; k < shape.nodes; ++k) {
      long line = 0;
      long tag = t_.next_int("an element's node tag", &line);
      auto it = node_index_.find(tag);
      if (it == node_index_.end())
        t_.fail(line, "element " + std::to_string(element_tag) + " refers to node " + std::to_string(tag) +
                          ", which $Nodes does not define");
      nodes.push_back(it->second);
    }
    return nodes;
  }

  // Format 2.2 writes an element once per physical group holding it (with a new tag each
  // time); the copies are merged into one element carrying all the groups.
  void add_element(int dim, std::vector<int> nodes, std::vector<int> physical, long tag, long line) {
    std::vector<int> key = nodes;
    std::sort(key.begin(), key.end());
    key.push_back(dim);
    auto [it, fresh] = element_index_.emplace(key, int(mesh_.elements.size()));
    if (fresh) {
      mesh_.elements.push_back({dim, std::move(nodes), std::move(physical), tag, line});
      return;
    }
    std::vector<int> &groups = mesh_.elements[size_t(it->second)].physical_tags;
    for (int p : physical)
      if (std::find(groups.begin(), groups.end(), p) == groups.end()) groups.push_back(p);
  }

  void read_elements_v2() {
    long n = t_.next_count("the number of elements");
    for (long k = 0; k < n; ++k) {
      long line = 0;
      long tag = t_.next_int("an element tag", &line);
      long type = t_.next_int("an element type");
      ElementShape shape;
      if (!supported_shape(type, &shape)) t_.fail(line, unsupported_type_message(type));
      long n_tags = t_.next_count("an element's number of tags");
      std::vector<int> physical;
      for (long j = 0; j < n_tags; ++j) {
        long value = t_.next_int("an element tag value");
        if (j == 0 && value != 0) physical.push_back(int(value));  // the first tag is the physical group
      }
      add_element(shape.dim, element_nodes(shape, tag), physical, tag, line);
    }
  }

  void read_elements_v4() {
    long blocks = t_.next_count("the number of element blocks");
    long total = t_.next_count("the number of elements");
    t_.next_int("the smallest element tag");
    t_.next_int("the largest element tag");
    long read = 0;
    for (long b = 0; b < blocks; ++b) {
      long line = 0;
      long dim = t_.next_int("an element block's entity dimension", &line);
      long entity = t_.next_int("an element block's entity tag");
      long type = t_.next_int("an element block's element type");
      long n = t_.next_count("an element block's number of elements");
      ElementShape shape;
      if (!supported_shape(type, &shape)) t_.fail(line, unsupported_type_message(type));
      if (shape.dim != dim)
        t_.fail(line, "element type " + std::to_string(type) + " has dimension " + std::to_string(shape.dim) +
                          " but its block's entity has dimension " + std::to_string(dim));
      const std::vector<int> physical = entity_physical_tags(int(dim), entity, line);
      for (long k = 0; k < n; ++k) {
        long tag_line = 0;
        long tag = t_.next_int("an element tag", &tag_line);
        add_element(shape.dim, element_nodes(shape, tag), physical, tag, tag_line);
      }
      read += n;
    }
    if (read != total)
      t_.fail(t_.line(), "$Elements announces " + std::to_string(total) + " elements but its blocks hold " +
                             std::to_string(read));
  }

  std::vector<int> entity_physical_tags(int dim, long entity, long line) {
    if (!has_entities_) return {};  // no $Entities: no physical groups
    auto it = entity_physicals_.find({dim, entity});
    if (it == entity_physicals_.end())
      t_.fail(line, "element block of entity (dimension " + std::to_string(dim) + ", tag " + std::to_string(entity) +
                        ") that $Entities does not list");
    return it->second;
  }

  void skip_section(const std::string &section) {
    const std::string end = "$End" + section;
    while (t_.next("the end of section $" + section + " (" + end + ")").text != end) {
    }
  }

  // The scene is 2D: every node must lie in the plane z = 0 (to round-off of the mesh size).
  void check_planar() {
    double extent = 0;
    for (double c : mesh_.xy) extent = std::max(extent, std::fabs(c));
    for (size_t i = 0; i < z_.size(); ++i)
      if (std::fabs(z_[i]) > 1e-10 * std::max(extent, 1e-300))
        t_.fail(mesh_.node_lines[i], "node " + std::to_string(mesh_.node_tags[i]) + " has z = " + std::to_string(z_[i]) +
                                         ": a 2D mesh must lie in the plane z = 0");
  }

  Tokens t_;
  GmshMesh mesh_;
  bool v4_ = false;
  bool has_entities_ = false;
  std::vector<double> z_;
  std::unordered_map<long, int> node_index_;
  std::map<std::pair<int, long>, std::vector<int>> entity_physicals_;
  std::map<std::vector<int>, int> element_index_;
};

}  // namespace

std::vector<const PhysicalGroup *> GmshMesh::groups_named(const std::string &name) const {
  std::vector<const PhysicalGroup *> found;
  for (const PhysicalGroup &g : groups)
    if (g.name == name) found.push_back(&g);
  return found;
}

std::string GmshMesh::group_list() const {
  std::string list;
  for (const PhysicalGroup &g : groups) {
    if (g.name.empty()) continue;
    if (!list.empty()) list += ", ";
    list += "'" + g.name + "' (dim " + std::to_string(g.dim) + ")";
  }
  return list.empty() ? "none" : list;
}

GmshMesh parse_gmsh(const std::string &text, const std::string &name) { return Reader(text, name).read(); }

GmshMesh read_gmsh(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot open the mesh file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw MeshError(path + ": cannot read the mesh file");
  return parse_gmsh(text.str(), path);
}

}  // namespace mcrun
