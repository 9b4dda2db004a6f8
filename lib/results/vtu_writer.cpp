#include "results/vtu_writer.hpp"
#include "support/error.hpp"
#include "solve/model.hpp"
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace mc {

namespace {

// VTK cell types by nodes per cell; the node order of quadratic cells is the library's (corners
// counter-clockwise, then the mid-edge nodes of edges 0-1, 1-2, ..., then Q9's centre).
constexpr int kVtkTriangle = 5, kVtkQuad = 9, kVtkQuadraticTriangle = 22, kVtkQuadraticQuad = 23,
              kVtkBiquadraticQuad = 28;

int vtk_cell_type(int nodes_per_cell) {
  switch (nodes_per_cell) {
    case 3: return kVtkTriangle;
    case 4: return kVtkQuad;
    case 6: return kVtkQuadraticTriangle;
    case 8: return kVtkQuadraticQuad;
    default: return kVtkBiquadraticQuad;  // 9
  }
}
// Written for gap and initial gap where the API reports +infinity (no mortar surface seen).
constexpr double kUnseenGap = -1.0;

// strerror_r comes in a GNU flavour (returns the text) and an XSI one (returns 0 on success).
[[maybe_unused]] const char *error_text(const char *gnu, const char *) { return gnu; }
[[maybe_unused]] const char *error_text(int xsi, const char *buffer) { return xsi == 0 ? buffer : "unknown error"; }

std::string system_error(int code) {
  char buffer[256] = "";
  return error_text(strerror_r(code, buffer, sizeof buffer), buffer);
}

// A text file written through a buffer, with numbers formatted by std::to_chars: printf's
// %g would follow the host program's LC_NUMERIC and could write "0,5".
class TextFile {
public:
  explicit TextFile(std::string path) : path_(std::move(path)) {
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) {
      int code = errno;
      fail(MC_ERROR_ARGUMENT, "path = \"%s\": cannot open the file for writing: %s", path_.c_str(),
           system_error(code).c_str());
    }
  }
  TextFile(const TextFile &) = delete;
  TextFile &operator=(const TextFile &) = delete;
  // Reached with the file still open only when writing failed part-way: drop the fragment.
  ~TextFile() {
    if (file_) std::fclose(file_), std::remove(path_.c_str());
  }

  TextFile &operator<<(const char *text) { return append(text, std::strlen(text)); }
  TextFile &operator<<(const std::string &text) { return append(text.data(), text.size()); }
  TextFile &operator<<(double value) {
    char digits[32];  // %.17g: enough digits for every double to read back exactly
    auto end = std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, 17).ptr;
    return append(digits, size_t(end - digits));
  }
  TextFile &operator<<(long value) {
    char digits[24];
    auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
    return append(digits, size_t(end - digits));
  }
  TextFile &operator<<(int value) { return *this << long(value); }

  void close() {
    flush();
    FILE *file = file_;
    file_ = nullptr;
    if (std::fclose(file) != 0) {
      int code = errno;
      std::remove(path_.c_str());
      fail(MC_ERROR_ARGUMENT, "path = \"%s\": writing the file failed: %s", path_.c_str(), system_error(code).c_str());
    }
  }

private:
  TextFile &append(const char *text, size_t n) {
    buffer_.append(text, n);
    if (buffer_.size() >= (1u << 16)) flush();
    return *this;
  }
  void flush() {
    if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
      int code = errno;
      fail(MC_ERROR_ARGUMENT, "path = \"%s\": writing the file failed: %s", path_.c_str(), system_error(code).c_str());
    }
    buffer_.clear();
  }

  std::string path_;
  FILE *file_ = nullptr;
  std::string buffer_;
};

std::string xml_escaped(const std::string &text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// The contact results of a body spread onto all its nodes: those of every group in which it is
// the non-mortar side (zero off its contact surfaces, and on a body that is only ever mortar).
struct NodalContact {
  std::vector<double> pressure, gap, initial_gap;
  std::vector<int> active, constrained;
  // MC_CONTACT_SHEAR, _SLIP (a node at one position: that position's values, bit for bit; a
  // corner in two faces or pairs: their means weighted by the tributary measures, as the
  // pressure's), _SLIP_TOTAL (the larger) and _STATE (that of the position weighing most, as the
  // library's own rule for a position in several rows).
  std::vector<double> shear, slip, slip_total;
  std::vector<int> state;
};

NodalContact nodal_contact(const Model &model, int b) {
  const int n = model.body[b].has_mesh ? model.body[b].mesh.n_nodes() : 0;
  NodalContact c;
  c.pressure.assign(n, 0.0), c.gap.assign(n, 0.0), c.initial_gap.assign(n, 0.0);
  c.active.assign(n, 0), c.constrained.assign(n, 0);
  c.shear.assign(n, 0.0), c.slip.assign(n, 0.0), c.slip_total.assign(n, 0.0);
  c.state.assign(n, MC_STATE_OPEN);
  if (!model.contact()) return c;
  // A corner node is a contact position in each of its two faces (or of two pairs): its pressure
  // is its total normal force over its total tributary measure, its gaps the smaller one.
  // (With the weak rows of a quadratic non-mortar side the pressure is the multiplier field, not
  // the lumped force: there a corner in two faces gets the mean of its two pressures, weighted by
  // their tributary measures.)
  std::vector<double> force(n, 0.0), tributary(n, 0.0), state_weight(n, -1.0), shear_sum(n, 0.0), slip_sum(n, 0.0);
  std::vector<int> positions_at(n, 0);
  std::vector<char> on_surface(n, 0);
  const auto at = [](const std::vector<double> &field, size_t pos) { return pos < field.size() ? field[pos] : 0.0; };
  for (const ContactGroup &group : model.contact()->groups) {
    if (group.nonmortar != b) continue;
    const ContactGeometry &g = group.geometry;
    const bool field = !group.rows.pressure_of_position.empty();
    for (size_t local = 0; local < g.nodes.size(); ++local) {
      const size_t pos = group.first_position + local;
      const int node = g.nodes[local];
      on_surface[node] = 1;
      const bool sees_mortar = std::isfinite(model.contact_gap[pos]);
      force[node] += field ? model.contact_pressure[pos] * g.tributary[local] : model.contact_force[pos];
      tributary[node] += g.tributary[local];
      if (sees_mortar) {
        const double gap = model.contact_gap[pos], initial = model.initial_gap(pos);
        c.gap[node] = c.constrained[node] ? std::min(c.gap[node], gap) : gap;
        c.initial_gap[node] = c.constrained[node] ? std::min(c.initial_gap[node], initial) : initial;
        c.constrained[node] = 1;
      }
      c.active[node] = c.active[node] || model.contact_force[pos] > 0;
      c.shear[node] = at(model.contact_shear, pos), c.slip[node] = at(model.contact_slip, pos);
      shear_sum[node] += c.shear[node] * g.tributary[local], slip_sum[node] += c.slip[node] * g.tributary[local];
      ++positions_at[node];
      c.slip_total[node] = std::max(c.slip_total[node], at(model.contact_slip_total, pos));
      if (g.tributary[local] > state_weight[node] && pos < model.contact_state.size())
        state_weight[node] = g.tributary[local], c.state[node] = model.contact_state[pos];
    }
  }
  for (int node = 0; node < n; ++node) {
    if (!on_surface[node]) continue;
    if (!c.constrained[node]) c.gap[node] = c.initial_gap[node] = kUnseenGap;
    c.pressure[node] = tributary[node] > 0 ? force[node] / tributary[node] : 0.0;
    if (positions_at[node] > 1) {
      c.shear[node] = tributary[node] > 0 ? shear_sum[node] / tributary[node] : 0.0;
      c.slip[node] = tributary[node] > 0 ? slip_sum[node] / tributary[node] : 0.0;
    }
  }
  return c;
}

// sigma_vM from the in-plane stresses and the out-of-plane normal stress (sigma_zz of plane
// strain, the hoop stress of an axisymmetric model): the same formula in (r, z, theta).
double von_mises(const double *s) {
  const double xx = s[0], yy = s[1], xy = s[2], zz = s[3];
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) + 3 * xy * xy);
}

// Scalars leave NumberOfComponents at VTK's default of 1 (readers then give flat arrays).
void open_array(TextFile &out, const char *type, const char *name, int components) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
  if (components > 1) out << " NumberOfComponents=\"" << components << "\"";
  out << " format=\"ascii\">\n";
}

void close_array(TextFile &out) { out << "        </DataArray>\n"; }

// The ComponentName attributes of a 4-component stress array: an axisymmetric model's
// components are (rr, zz, rz, hoop) in the slots of (xx, yy, xy, zz).
const char *stress_component_names(const Model &model) {
  return model.axisymmetric ? "ComponentName0=\"rr\" ComponentName1=\"zz\" ComponentName2=\"rz\" "
                              "ComponentName3=\"theta_theta\""
                            : "ComponentName0=\"xx\" ComponentName1=\"yy\" ComponentName2=\"xy\" ComponentName3=\"zz\"";
}

// One <Piece> holding the given bodies (0-based), nodes and cells numbered body after body.
void write_piece(TextFile &out, const Model &model, const std::vector<int> &bodies) {
  long n_points = 0, n_cells = 0;
  for (int b : bodies) n_points += model.body[b].mesh.n_nodes(), n_cells += model.body[b].mesh.n_cells();
  std::vector<NodalContact> contact;
  for (int b : bodies) contact.push_back(nodal_contact(model, b));
  out << "    <Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << n_cells << "\">\n";

  out << "      <PointData Vectors=\"displacement\" Scalars=\"pressure\">\n";
  open_array(out, "Float64", "displacement", 3);
  for (int b : bodies) {
    const std::vector<double> &u = model.body[b].u;
    for (int i = 0; i < model.body[b].mesh.n_nodes(); ++i) out << u[2 * i] << " " << u[2 * i + 1] << " 0\n";
  }
  close_array(out);
  // Each body's values as a non-mortar side (zero where it is none).
  auto contact_field = [&](const char *type, const char *name, auto value) {
    open_array(out, type, name, 1);
    for (size_t k = 0; k < bodies.size(); ++k)
      for (int i = 0; i < model.body[bodies[k]].mesh.n_nodes(); ++i) out << value(contact[k], i) << "\n";
    close_array(out);
  };
  contact_field("Float64", "pressure", [&](const NodalContact &c, int i) { return c.pressure[i]; });
  contact_field("Float64", "gap", [&](const NodalContact &c, int i) { return c.gap[i]; });
  contact_field("Float64", "initial_gap", [&](const NodalContact &c, int i) { return c.initial_gap[i]; });
  contact_field("Int32", "active", [&](const NodalContact &c, int i) { return c.active[i]; });
  contact_field("Int32", "contact", [&](const NodalContact &c, int i) { return c.constrained[i]; });
  // Friction (MC_CONTACT_SHEAR, _SLIP, _SLIP_TOTAL, _STATE; frictionless contact slips with no shear).
  contact_field("Float64", "shear", [&](const NodalContact &c, int i) { return c.shear[i]; });
  contact_field("Float64", "slip", [&](const NodalContact &c, int i) { return c.slip[i]; });
  contact_field("Float64", "slip_total", [&](const NodalContact &c, int i) { return c.slip_total[i]; });
  contact_field("Int32", "state", [&](const NodalContact &c, int i) { return c.state[i]; });
  // Each cell's stress at its nodes, averaged over the cells sharing a node (mc_get_nodal_stress).
  out << "        <DataArray type=\"Float64\" Name=\"nodal_stress\" NumberOfComponents=\"4\" "
      << stress_component_names(model) << " format=\"ascii\">\n";
  for (int b : bodies) {
    const std::vector<double> &s = model.nodal_stresses(b);
    for (int i = 0; i < model.body[b].mesh.n_nodes(); ++i)
      out << s[4 * size_t(i)] << " " << s[4 * size_t(i) + 1] << " " << s[4 * size_t(i) + 2] << " " << s[4 * size_t(i) + 3]
          << "\n";
  }
  close_array(out);
  out << "      </PointData>\n";

  out << "      <CellData Scalars=\"von_mises\">\n";
  out << "        <DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"4\" " << stress_component_names(model)
      << " format=\"ascii\">\n";
  for (int b : bodies) {
    const std::vector<double> &s = model.cell_stresses(b);
    for (int c = 0; c < model.body[b].mesh.n_cells(); ++c)
      out << s[4 * size_t(c)] << " " << s[4 * size_t(c) + 1] << " " << s[4 * size_t(c) + 2] << " " << s[4 * size_t(c) + 3]
          << "\n";
  }
  close_array(out);
  open_array(out, "Float64", "von_mises", 1);
  for (int b : bodies)
    for (int c = 0; c < model.body[b].mesh.n_cells(); ++c) out << von_mises(&model.cell_stresses(b)[4 * size_t(c)]) << "\n";
  close_array(out);
  open_array(out, "Int32", "body", 1);
  for (int b : bodies)
    for (int c = 0; c < model.body[b].mesh.n_cells(); ++c) out << b + 1 << "\n";
  close_array(out);
  out << "      </CellData>\n";

  out << "      <Points>\n";
  open_array(out, "Float64", "coordinates", 3);
  for (int b : bodies) {
    const Mesh &mesh = model.body[b].mesh;
    for (int i = 0; i < mesh.n_nodes(); ++i) out << mesh.node(i).x << " " << mesh.node(i).y << " 0\n";
  }
  close_array(out);
  out << "      </Points>\n";

  out << "      <Cells>\n";
  out << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  long first_node = 0;
  for (int b : bodies) {
    const Mesh &mesh = model.body[b].mesh;
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int *v = mesh.cell(c);
      for (int a = 0; a < mesh.nodes_per_cell(); ++a) out << (a ? " " : "") << first_node + v[a];
      out << "\n";
    }
    first_node += mesh.n_nodes();
  }
  close_array(out);
  out << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  long offset = 0;
  for (int b : bodies)
    for (int c = 0; c < model.body[b].mesh.n_cells(); ++c) offset += model.body[b].mesh.nodes_per_cell(), out << offset << "\n";
  close_array(out);
  out << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int b : bodies) {
    const int type = vtk_cell_type(model.body[b].mesh.nodes_per_cell());
    for (int c = 0; c < model.body[b].mesh.n_cells(); ++c) out << type << "\n";
  }
  close_array(out);
  out << "      </Cells>\n";
  out << "    </Piece>\n";
}

void write_unstructured_grid(const std::string &path, const Model &model, const std::vector<int> &bodies) {
  TextFile out(path);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <UnstructuredGrid>\n";
  write_piece(out, model, bodies);
  out << "  </UnstructuredGrid>\n"
         "</VTKFile>\n";
  out.close();
}

bool ends_with(const std::string &text, const std::string &suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

void write_vtu(const Model &model, const std::string &path) {
  if (!model.solved) fail(MC_ERROR_STATE, "no solution: call mc_solve first (or again, after changing the scene)");
  std::vector<int> bodies;
  for (int b = 0; b < model.n_bodies(); ++b)
    if (model.body[b].has_mesh && !model.body[b].host) bodies.push_back(b);  // a host body has no cells to draw
  if (bodies.empty()) fail(MC_ERROR_STATE, "no mesh body to write: host bodies (mc_set_host_body) have no cells");
  // The stresses first (computed now if no getter asked for them yet): an error there (an
  // overflow) is reported before any file is written.
  for (int b : bodies) model.cell_stresses(b);
  if (!ends_with(path, ".pvd")) {
    write_unstructured_grid(path, model, bodies);
    return;
  }
  // The collection names its pieces relative to its own directory, as ParaView resolves them.
  const std::string stem = path.substr(0, path.size() - 4);
  const size_t slash = stem.find_last_of('/');
  const std::string stem_name = slash == std::string::npos ? stem : stem.substr(slash + 1);
  for (int b : bodies) write_unstructured_grid(stem + "_body" + std::to_string(b + 1) + ".vtu", model, {b});
  TextFile out(path);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  for (int b : bodies)
    out << "    <DataSet timestep=\"0\" group=\"\" part=\"" << b << "\" name=\"body" << b + 1 << "\" file=\""
        << xml_escaped(stem_name + "_body" + std::to_string(b + 1) + ".vtu") << "\"/>\n";
  out << "  </Collection>\n"
         "</VTKFile>\n";
  out.close();
}

}  // namespace mc
