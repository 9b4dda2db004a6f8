// adaptive.cpp - size field, Gmsh files, Gmsh runs and VTU cell data of the adaptive refinement
// (adaptive.hpp).
#include "adaptive.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace mcrun {

namespace {

double twice_signed_area(const BodyMesh &mesh, int cell) {
  const int n = mesh.corners_per_cell();
  const int *v = &mesh.cells[size_t(cell) * size_t(mesh.nodes_per_cell)];
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const size_t a = size_t(v[k]), b = size_t(v[(k + 1) % n]);
    sum += mesh.xy[2 * a] * mesh.xy[2 * b + 1] - mesh.xy[2 * b] * mesh.xy[2 * a + 1];
  }
  return sum;
}

std::string absolute(const std::string &path) {
  std::error_code ignored;
  const std::filesystem::path p = std::filesystem::absolute(path, ignored);
  return (p.empty() ? std::filesystem::path(path) : p).lexically_normal().string();
}

bool is_executable_file(const std::string &path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// `name` looked up as the shell would: a name with a slash as it is, else along PATH.
std::string look_up(const std::string &name) {
  if (name.find('/') != std::string::npos) return is_executable_file(name) ? name : "";
  const char *path = std::getenv("PATH");
  if (!path) return "";
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
    if (is_executable_file(candidate)) return candidate;
  }
  return "";
}

// The lines of Gmsh's log that say what went wrong (at most 8), or its last lines.
std::string gmsh_errors(const std::string &log) {
  std::ifstream in(log);
  std::vector<std::string> errors, last;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("Error", 0) == 0 && errors.size() < 8) errors.push_back(line);
    last.push_back(line);
    if (last.size() > 5) last.erase(last.begin());
  }
  const std::vector<std::string> &shown = errors.empty() ? last : errors;
  std::string text;
  for (const std::string &l : shown) text += "\n  " + l;
  return text;
}

}  // namespace

double cell_size(const BodyMesh &mesh, int cell) {
  const double area = 0.5 * std::fabs(twice_signed_area(mesh, cell));
  return mesh.corners_per_cell() == 3 ? std::sqrt(4 * area / std::sqrt(3.0)) : std::sqrt(area);
}

namespace {

// Node sizes: each node the smallest of calibration * ratio(b, c) * cell_size over its cells,
// kept within the adaptive bounds; counts the cells asked for.
template <class Ratio>
SizeField node_sizes(const BodyMesh bodies[2], const Adaptive *adaptive, double calibration, Ratio ratio) {
  SizeField field;
  for (int b = 0; b < 2; ++b) {
    const BodyMesh &mesh = bodies[b];
    std::vector<double> &size = field.node_size[b];
    size.assign(size_t(mesh.n_nodes()), std::numeric_limits<double>::infinity());
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const double r = ratio(b, c);
      field.refined += r < 1;
      field.coarsened += r > 1;
      field.predicted_cells += 1 / (r * r);
      ++field.cells;
      const double h = calibration * r * cell_size(mesh, c);
      // Every node of the cell, mid-edge nodes too (only corners are written, but all stay defined).
      for (int k = 0; k < mesh.nodes_per_cell; ++k) {
        const size_t i = size_t(mesh.cells[size_t(c) * size_t(mesh.nodes_per_cell) + size_t(k)]);
        size[i] = std::min(size[i], h);
      }
    }
    if (adaptive)
      for (double &h : size) {
        if (adaptive->min_size > 0) h = std::max(h, adaptive->min_size);
        if (adaptive->max_size > 0) h = std::min(h, adaptive->max_size);
      }
  }
  return field;
}

}  // namespace

SizeField current_size_field(const BodyMesh bodies[2]) {
  return node_sizes(bodies, nullptr, 1.0, [](int, int) { return 1.0; });
}

SizeField make_size_field(const BodyMesh bodies[2], const std::vector<double> eta[2], const Adaptive &adaptive,
                          double calibration) {
  const int p = bodies[0].quadratic() || bodies[1].quadratic() ? 2 : 1;  // the order the error falls with
  const double aim = adaptive.aim * adaptive.target_error;
  // N: the cells of the smallest mesh whose cells all have the error aim / sqrt(N).
  double sum = 0;
  for (int b = 0; b < 2; ++b)
    for (double e : eta[b]) sum += std::pow(e / aim, 2.0 / (p + 1));
  const double optimal_cells = std::pow(sum, (p + 1.0) / p);
  const double per_cell = aim / std::sqrt(std::max(optimal_cells, 1.0));
  int limited = 0;
  SizeField field = node_sizes(bodies, &adaptive, calibration, [&](int b, int c) {
    const double e = eta[b][size_t(c)];
    const double r = e > 0 ? std::pow(per_cell / e, 1.0 / (p + 1)) : adaptive.max_coarsening;
    if (r > 1 / adaptive.max_refinement) return std::min(r, adaptive.max_coarsening);
    ++limited;
    return 1 / adaptive.max_refinement;
  });
  field.optimal_cells = optimal_cells;
  field.limited = limited;
  return field;
}

void write_size_view(const std::string &path, const BodyMesh bodies[2], const SizeField &field) {
  FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write the size field " + path + ": " + std::strerror(errno));
  std::fprintf(f, "// Mesh size for Gmsh, written by mortarcontact-run from the error indicators: one element per\n"
                  "// cell of the last step's mesh (both bodies), its corners with their new sizes, then a skirt\n"
                  "// of elements outside the boundary sides (a curved boundary bulges out of the straight sides).\n"
                  "View \"mesh size\" {\n");
  for (int b = 0; b < 2; ++b) {
    const BodyMesh &mesh = bodies[b];
    const int n = mesh.corners_per_cell();
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int *v = &mesh.cells[size_t(c) * size_t(mesh.nodes_per_cell)];
      std::fputs(n == 3 ? "ST(" : "SQ(", f);
      for (int k = 0; k < n; ++k)
        std::fprintf(f, "%s%.12g,%.12g,0", k ? "," : "", mesh.xy[2 * size_t(v[k])], mesh.xy[2 * size_t(v[k]) + 1]);
      std::fputs("){", f);
      for (int k = 0; k < n; ++k) std::fprintf(f, "%s%.6g", k ? "," : "", field.node_size[b][size_t(v[k])]);
      std::fputs("};\n", f);
    }
  }
  // A skirt outside every boundary side: Gmsh puts the new boundary nodes on the geometry, which
  // bulges out of the straight sides of the view's cells where it is curved, and a point in no
  // cell of the view would get no size at all. Its width: a quarter of the side (a circle of
  // radius down to half the side stays inside), plus twice the bulge a mid-edge node shows.
  for (int b = 0; b < 2; ++b) {
    const BodyMesh &mesh = bodies[b];
    const int n = mesh.corners_per_cell();
    for (int c = 0; c < mesh.n_cells(); ++c) {
      const int *v = &mesh.cells[size_t(c) * size_t(mesh.nodes_per_cell)];
      for (int k = 0; k < n; ++k) {
        const int i = v[k], j = v[(k + 1) % n];  // counter-clockwise: the body on the left
        const auto edge = mesh.edges.find(uint64_t(std::min(i, j)) << 32 | uint64_t(std::max(i, j)));  // edge_key
        if (edge == mesh.edges.end() || edge->second.cells != 1) continue;
        const double xi = mesh.xy[2 * size_t(i)], yi = mesh.xy[2 * size_t(i) + 1];
        const double xj = mesh.xy[2 * size_t(j)], yj = mesh.xy[2 * size_t(j) + 1];
        const double length = std::hypot(xj - xi, yj - yi);
        if (!(length > 0)) continue;
        const double nx = (yj - yi) / length, ny = -(xj - xi) / length;  // outward
        double bulge = 0;
        if (mesh.quadratic()) {
          const size_t m = size_t(v[n + k]);
          bulge = std::fabs((mesh.xy[2 * m] - xi) * nx + (mesh.xy[2 * m + 1] - yi) * ny);
        }
        const double w = 0.25 * length + 2 * bulge;
        const double si = field.node_size[b][size_t(i)], sj = field.node_size[b][size_t(j)];
        std::fprintf(f, "SQ(%.12g,%.12g,0,%.12g,%.12g,0,%.12g,%.12g,0,%.12g,%.12g,0){%.6g,%.6g,%.6g,%.6g};\n", xi, yi, xj,
                     yj, xj + w * nx, yj + w * ny, xi + w * nx, yi + w * ny, si, sj, sj, si);
      }
    }
  }
  std::fputs("};\n", f);
  if (std::fclose(f) != 0) throw std::runtime_error("cannot write the size field " + path);
}

void write_step_geo(const std::string &path, const std::string &scene_geo, const std::string &size_view,
                    const std::string &what) {
  const std::string geo = absolute(scene_geo), view = absolute(size_view);
  if (geo.find('"') != std::string::npos || view.find('"') != std::string::npos)
    throw std::runtime_error("cannot hand a path with a double quote to Gmsh: " + geo + ", " + view);
  std::ofstream out(path);
  out << "// Written by mortarcontact-run (adaptive refinement): " << what
      << "\n"
         "// The scene's geometry meshed with the sizes of a post-processing view used as the background\n"
         "// mesh (only its sizes count: those from points, curvature and the boundary are off).\n"
         "Include \""
      << geo
      << "\";\n"
         "Mesh.MeshSizeFromPoints = 0;\n"
         "Mesh.MeshSizeFromCurvature = 0;\n"
         "Mesh.MeshSizeExtendFromBoundary = 0;\n"
         "Merge \""
      << view
      << "\";\n"
         "Background Mesh View[PostProcessing.NbViews - 1];\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string find_gmsh(const std::string &requested) {
  std::string name = requested, from = "--gmsh";
  if (name.empty()) {
    const char *env = std::getenv("MORTARCONTACT_GMSH");
    if (env && *env) name = env, from = "MORTARCONTACT_GMSH";
  }
  if (name.empty()) {
    const std::string found = look_up("gmsh");
    if (found.empty())
      throw GmshError("adaptive refinement runs Gmsh, and there is no gmsh on PATH: install it (Debian: apt-get "
                      "install gmsh) or name the executable with --gmsh PATH or MORTARCONTACT_GMSH=PATH");
    return found;
  }
  const std::string found = look_up(name);
  if (found.empty())
    throw GmshError("adaptive refinement runs Gmsh, and " + from + " names '" + name + "', which is " +
                    (name.find('/') != std::string::npos ? "not an executable file" : "not on PATH"));
  return found;
}

void run_gmsh(const std::string &gmsh, const std::string &geo, const std::string &msh, int order,
              const std::vector<std::string> &arguments, const std::string &log) {
  std::vector<std::string> args = {gmsh, "-2", "-format", "msh41"};
  if (order == 2) args.insert(args.end(), {"-order", "2"});
  args.insert(args.end(), arguments.begin(), arguments.end());
  args.insert(args.end(), {geo, "-o", msh});
  std::vector<char *> argv;
  for (std::string &a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::remove(msh.c_str());  // an old mesh must not pass for a new one

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, gmsh.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw GmshError("cannot run " + gmsh + ": " + std::strerror(spawned));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw GmshError("waiting for " + gmsh + ": " + std::strerror(errno));
  std::string command;
  for (const std::string &a : args) command += (command.empty() ? "" : " ") + a;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status) ? "exited with " + std::to_string(WEXITSTATUS(status))
                                              : "was killed by signal " + std::to_string(WTERMSIG(status));
    throw GmshError("Gmsh " + how + " on " + geo + " (" + command + "; its output is in " + log + "):" +
                    gmsh_errors(log));
  }
  struct stat st;
  if (::stat(msh.c_str(), &st) != 0 || st.st_size == 0)
    throw GmshError("Gmsh wrote no mesh from " + geo + " (" + command + "; its output is in " + log + "):" +
                    gmsh_errors(log));
}

void add_vtu_cell_data(const std::string &vtu, const std::string &name, const std::vector<double> &values) {
  std::string text;
  {
    std::ifstream in(vtu, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + vtu + " to add " + name);
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  if (text.find("Name=\"" + name + "\"") != std::string::npos) return;
  const std::string end = "      </CellData>\n";
  const size_t at = text.find(end);
  if (at == std::string::npos || text.find(end, at + 1) != std::string::npos)
    throw std::runtime_error(vtu + ": not one <CellData> section: cannot add " + name);
  std::string array = "        <DataArray type=\"Float64\" Name=\"" + name + "\" format=\"ascii\">\n";
  char number[32];
  for (double v : values) {
    std::snprintf(number, sizeof number, "%.17g\n", v);
    array += number;
  }
  array += "        </DataArray>\n";
  text.insert(at, array);
  std::ofstream out(vtu, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + vtu);
}

}  // namespace mcrun
