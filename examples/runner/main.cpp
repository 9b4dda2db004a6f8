// mortarcontact-run - solves a contact scene described by a JSON file (docs/scene_format.md)
// on Gmsh meshes, through the public C API of mortarcontact only.
//
//   mortarcontact-run [--quiet | --verbose] scene.json
//
// Exit codes: 0 solved; 1 the solve (or writing an output) failed, the library's message is
// printed; 2 bad command line, scene file or mesh, the message names the file, key and line.
#include "body_mesh.hpp"
#include "gmsh_reader.hpp"
#include "scene.hpp"

#include "mortarcontact.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace mcrun;

constexpr int EXIT_SOLVE_FAILED = 1;
constexpr int EXIT_BAD_INPUT = 2;
constexpr double PI = 3.14159265358979323846;

struct Options {
  std::string scene;
  int verbosity = 1;  // 0 --quiet, 1 phases, 2 --verbose: also active-set iterations
};

// A failed library call after the set-up: the solve or an output (exit code 1).
struct SolveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void usage(FILE *to) {
  std::fprintf(to,
               "usage: mortarcontact-run [--quiet | --verbose] scene.json\n"
               "  Solves the frictionless contact of two elastic bodies described by scene.json\n"
               "  (format: docs/scene_format.md) with mortarcontact %s.\n"
               "  --quiet    no progress messages on stderr\n"
               "  --verbose  also each active-set iteration\n"
               "exit codes: 0 solved, 1 solve or output failed, 2 bad command line, scene or mesh\n",
               mc_version_string());
}

// Returns -1 to go on, else the exit code.
int parse_arguments(int argc, char **argv, Options *options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(stdout);
      return 0;
    } else if (arg == "--version") {
      std::printf("mortarcontact-run %s\n", mc_version_string());
      return 0;
    } else if (arg == "--quiet" || arg == "-q") {
      options->verbosity = 0;
    } else if (arg == "--verbose" || arg == "-v") {
      options->verbosity = 2;
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "mortarcontact-run: unknown option %s\n", arg.c_str());
      usage(stderr);
      return EXIT_BAD_INPUT;
    } else if (options->scene.empty()) {
      options->scene = arg;
    } else {
      std::fprintf(stderr, "mortarcontact-run: one scene file only (got %s and %s)\n", options->scene.c_str(),
                   arg.c_str());
      return EXIT_BAD_INPUT;
    }
  }
  if (options->scene.empty()) {
    usage(stderr);
    return EXIT_BAD_INPUT;
  }
  return -1;
}

// Progress of the runner's own phases, on stderr like the library's.
void progress(const Options &options, const char *format, ...) {
  if (options.verbosity < 1) return;
  std::va_list args;
  va_start(args, format);
  std::fputs("mortarcontact-run: ", stderr);
  std::vfprintf(stderr, format, args);
  std::fputc('\n', stderr);
  va_end(args);
}

void log_message(void *user_data, mc_log_level level, const char *message) {
  const Options &options = *static_cast<const Options *>(user_data);
  if (level == MC_LOG_ITERATION && options.verbosity < 2) return;
  std::fprintf(stderr, "mortarcontact-run:   %s\n", message);
}

// ---- set-up -------------------------------------------------------------------------------

// A library call during set-up failed: the scene or the mesh is what is wrong (exit code 2).
void setup(mc_model *m, mc_status status, const Scene &scene, const std::string &key, const char *call) {
  if (status != MC_OK)
    throw SceneError(scene.path + ": " + key + ": " + call + " failed: " + mc_status_string(status) + ": " +
                     mc_errmsg(m));
}

// Runs `f` and turns a mesh problem into a scene error naming the key it came from.
template <class F>
auto at_key(const Scene &scene, const std::string &key, F f) {
  try {
    return f();
  } catch (const MeshError &e) {
    throw SceneError(scene.path + ": " + key + ": " + e.what());
  }
}

const char *cell_name(int nodes_per_cell) {
  switch (nodes_per_cell) {
    case 3: return "triangles";
    case 4: return "quadrilaterals";
    case 6: return "6-node triangles";
    case 8: return "8-node quadrilaterals";
    default: return "9-node quadrilaterals";
  }
}

void set_mesh(mc_model *m, int body, const BodyMesh &mesh, const Scene &scene) {
  const Body &spec = scene.bodies[body - 1];
  const mc_status status = mc_set_mesh(m, body, mesh.n_nodes(), mesh.xy.data(), mesh.n_cells(), mesh.nodes_per_cell,
                                       mesh.cells.data());
  // The library's message names ids of the compact numbering: say how they map to the file.
  setup(m, status, scene, spec.key + ".mesh (" + spec.mesh + "; the library counts this body's nodes and cells "
                          "from 0 in file order)", "mc_set_mesh");
  setup(m, mc_set_material(m, body, spec.young, spec.poisson), scene, spec.key + ".material", "mc_set_material");
}

void apply_supports(mc_model *m, int body, const BodyMesh &mesh, const Scene &scene) {
  for (const Support &s : scene.bodies[body - 1].supports) {
    const std::vector<int> nodes = at_key(scene, s.key + ".group", [&] { return group_nodes(mesh, s.group); });
    std::vector<double> values;
    for (size_t k = 0; k < nodes.size(); ++k) values.insert(values.end(), {s.value[0], s.value[1]});
    setup(m, mc_fix(m, body, int(nodes.size()), nodes.data(), s.components, values.data()), scene, s.key, "mc_fix");
  }
}

void apply_loads(mc_model *m, int body, const BodyMesh &mesh, const Scene &scene) {
  double body_force[2] = {0, 0};  // the library sets one body force: the scene's add up
  for (const Load &load : scene.bodies[body - 1].loads) {
    const std::string group_key = load.key + ".group";
    if (load.type == LoadType::BodyForce) {
      body_force[0] += load.value[0];
      body_force[1] += load.value[1];
    } else if (load.type == LoadType::NodalForce) {
      const std::vector<int> nodes = at_key(scene, group_key, [&] { return group_nodes(mesh, load.group); });
      std::vector<double> force;
      for (size_t k = 0; k < nodes.size(); ++k) force.insert(force.end(), {load.value[0], load.value[1]});
      setup(m, mc_add_nodal_force(m, body, int(nodes.size()), nodes.data(), force.data()), scene, load.key,
            "mc_add_nodal_force");
    } else {
      const std::vector<int> edges = at_key(scene, group_key, [&] { return group_edges(mesh, load.group); });
      const int n = int(edges.size() / 2);
      std::vector<double> values;
      if (load.type == LoadType::Pressure) {
        values.assign(size_t(n), load.value[0]);
        setup(m, mc_add_pressure(m, body, n, edges.data(), values.data()), scene, load.key, "mc_add_pressure");
      } else {
        for (int e = 0; e < n; ++e) values.insert(values.end(), {load.value[0], load.value[1]});
        setup(m, mc_add_traction(m, body, n, edges.data(), values.data()), scene, load.key, "mc_add_traction");
      }
    }
  }
  if (body_force[0] != 0 || body_force[1] != 0)
    setup(m, mc_set_body_force(m, body, body_force[0], body_force[1]), scene, scene.bodies[body - 1].key + ".loads",
          "mc_set_body_force");
}

void set_contact(mc_model *m, int body, const BodyMesh &mesh, const Scene &scene) {
  const Body &spec = scene.bodies[body - 1];
  const std::string key = spec.key + ".contact";
  std::vector<int> mids;  // the mid-edge nodes of a second-order surface
  const std::vector<int> edges = at_key(scene, key, [&] { return group_edges(mesh, spec.contact, &mids); });
  setup(m, mc_set_contact(m, body, int(edges.size() / 2), edges.data()), scene, key, "mc_set_contact");
  if (!spec.has_gap_offset) return;
  std::vector<int> nodes(edges);  // every node of the contact surface, once
  nodes.insert(nodes.end(), mids.begin(), mids.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const std::vector<double> offsets(nodes.size(), spec.gap_offset);
  setup(m, mc_set_gap_offset(m, int(nodes.size()), nodes.data(), offsets.data()), scene, spec.key + ".gap_offset",
        "mc_set_gap_offset");
}

void set_options(mc_model *m, const Scene &scene) {
  const Solver &s = scene.solver;
  setup(m, mc_set_plane(m, scene.plane, scene.thickness), scene, "plane/thickness", "mc_set_plane");
  setup(m, mc_set_option_int(m, MC_OPTION_METHOD, s.method), scene, "solver.method", "mc_set_option_int");
  setup(m, mc_set_option_real(m, MC_OPTION_TOLERANCE, s.tolerance), scene, "solver.tolerance", "mc_set_option_real");
  setup(m, mc_set_option_int(m, MC_OPTION_MAX_ITERATIONS, s.max_iterations), scene, "solver.max_iterations",
        "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_CONTACT_NORMAL, s.contact_normal), scene, "solver.contact_normal",
        "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_Q1_INTEGRATION, s.q1_integration), scene, "solver.q1_integration",
        "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_ORDERING, s.ordering), scene, "solver.ordering", "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_CONTACT_SURFACE, s.contact_surface), scene, "solver.contact_surface",
        "mc_set_option_int");
  setup(m, mc_set_option_real(m, MC_OPTION_FEATURE_ANGLE, s.feature_angle), scene, "solver.feature_angle",
        "mc_set_option_real");
  setup(m, mc_set_option_int(m, MC_OPTION_THREADS, s.threads), scene, "solver.threads", "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, s.interface_solver), scene, "solver.interface_solver",
        "mc_set_option_int");
}

// ---- results ------------------------------------------------------------------------------

void check(const mc_model *m, mc_status status, const char *call) {
  if (status != MC_OK) throw SolveError(std::string(call) + " failed: " + mc_status_string(status) + ": " + mc_errmsg(m));
}

// Body 1's contact nodes and what the solve found there.
struct ContactResults {
  std::vector<int> nodes;
  std::vector<double> pressure, force, gap, normal;  // normal: 2 per node
};

ContactResults contact_results(const mc_model *m) {
  ContactResults r;
  mc_int n = 0;
  check(m, mc_get_contact_count(m, &n), "mc_get_contact_count");
  r.nodes.resize(size_t(n));
  r.pressure.resize(size_t(n));
  r.force.resize(size_t(n));
  r.gap.resize(size_t(n));
  r.normal.resize(2 * size_t(n));
  if (n == 0) return r;
  check(m, mc_get_contact_nodes(m, r.nodes.data()), "mc_get_contact_nodes");
  check(m, mc_get_contact_pressure(m, r.pressure.data()), "mc_get_contact_pressure");
  check(m, mc_get_contact_force(m, r.force.data()), "mc_get_contact_force");
  check(m, mc_get_contact_gap(m, r.gap.data()), "mc_get_contact_gap");
  check(m, mc_get_contact_normal(m, r.normal.data()), "mc_get_contact_normal");
  return r;
}

// The path of the contact solve that ran (MC_INFO_INTERFACE_SOLVER; 0 without contact).
const char *interface_solver_name(int64_t value) {
  switch (value) {
    case MC_INTERFACE_CONDENSED: return "condensed";
    case MC_INTERFACE_SPARSE: return "sparse";
    default: return "unknown";
  }
}

void print_solve_summary(const mc_model *m, const Scene &scene, const ContactResults &r) {
  int64_t dofs = 0, iterations = 0, active = 0, interface_solver = 0;
  double total = 0, equilibrium = 0, complementarity = 0;
  check(m, mc_get_info_int(m, MC_INFO_DOFS, &dofs), "mc_get_info_int");
  check(m, mc_get_info_int(m, MC_INFO_ITERATIONS, &iterations), "mc_get_info_int");
  check(m, mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active), "mc_get_info_int");
  check(m, mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &interface_solver), "mc_get_info_int");
  check(m, mc_get_info_real(m, MC_INFO_TIME_TOTAL, &total), "mc_get_info_real");
  check(m, mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium), "mc_get_info_real");
  check(m, mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity), "mc_get_info_real");
  double resultant[2] = {0, 0};  // the contact force on body 1: lambda_j along -n_j
  for (size_t j = 0; j < r.nodes.size(); ++j)
    for (int c = 0; c < 2; ++c) resultant[c] -= r.force[j] * r.normal[2 * j + size_t(c)];
  std::printf("solved: %lld DOFs, %lld active-set iterations, %lld of %zu contact nodes active, %.3f s\n",
              (long long)dofs, (long long)iterations, (long long)active, r.nodes.size(), total);
  if (interface_solver != 0)  // which path ran, and whether the scene forced it
    std::printf("  interface solver: %s (%s)\n", interface_solver_name(interface_solver),
                scene.solver.interface_solver == MC_INTERFACE_AUTO ? "chosen automatically" : "set by the scene");
  std::printf("  relative residuals: equilibrium %.2e, complementarity %.2e\n", equilibrium, complementarity);
  std::printf("  contact force on body 1: (%.10g, %.10g)\n", resultant[0], resultant[1]);
}

void write_pressure_csv(const std::string &path, const BodyMesh &body1, const ContactResults &r) {
  FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw SolveError("cannot write the pressure CSV " + path + ": " + std::strerror(errno));
  std::fprintf(f, "x,y,pressure,gap\n");
  for (size_t j = 0; j < r.nodes.size(); ++j) {
    const size_t i = size_t(r.nodes[j]);
    std::fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", body1.xy[2 * i], body1.xy[2 * i + 1], r.pressure[j], r.gap[j]);
  }
  if (std::fclose(f) != 0) throw SolveError("cannot write the pressure CSV " + path);
}

// ---- the Hertz comparison -----------------------------------------------------------------

// p0 and a of the computed pressure. a is measured along the tangent at the pressure peak:
// on each side, midway between the outermost loaded node (pressure above 1e-9 p0: round-off on
// an inactive node does not count) and the next node, so it is known to within half that
// spacing (reported).
struct HertzMeasured {
  double p0 = 0, a = 0, spacing = 0, force = 0;
};

// Axisymmetric (a sphere on a flat): the contact is the disc around the axis, so a is measured
// along the radius x, from the axis, and the force is the total over the turn.
HertzMeasured measure_hertz(const BodyMesh &body1, const ContactResults &r, double thickness, bool axisymmetric) {
  HertzMeasured h;
  size_t peak = 0;
  for (size_t j = 0; j < r.nodes.size(); ++j)
    if (r.pressure[j] > r.pressure[peak]) peak = j;
  if (r.nodes.empty() || !(r.pressure[peak] > 0)) return h;
  h.p0 = r.pressure[peak];
  // Loaded: a pressure above round-off of the peak's (an inactive node may carry 1e-12 p0).
  const double loaded = 1e-9 * h.p0;
  if (axisymmetric) {
    double last = 0, next = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < r.nodes.size(); ++j) {
      h.force -= r.force[j] * r.normal[2 * j + 1];  // along the axis, pressing body 1 down
      if (r.pressure[j] > loaded) last = std::max(last, body1.xy[2 * size_t(r.nodes[j])]);
    }
    for (size_t j = 0; j < r.nodes.size(); ++j) {
      const double x = body1.xy[2 * size_t(r.nodes[j])];
      if (x > last && x < next) next = x;
    }
    if (std::isinf(next)) next = last;
    h.a = 0.5 * (last + next);
    h.spacing = next - last;
    return h;
  }
  const double nx = r.normal[2 * peak], ny = r.normal[2 * peak + 1];
  const double x0 = body1.xy[2 * size_t(r.nodes[peak])], y0 = body1.xy[2 * size_t(r.nodes[peak]) + 1];
  std::vector<double> s(r.nodes.size());  // position along the tangent (-ny, nx) from the peak
  for (size_t j = 0; j < r.nodes.size(); ++j) {
    const size_t i = size_t(r.nodes[j]);
    s[j] = -(body1.xy[2 * i] - x0) * ny + (body1.xy[2 * i + 1] - y0) * nx;
    h.force += r.force[j] * (r.normal[2 * j] * nx + r.normal[2 * j + 1] * ny) / thickness;
  }
  for (double side : {-1.0, 1.0}) {
    double last = 0, next = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < s.size(); ++j)
      if (r.pressure[j] > loaded && side * s[j] > last) last = side * s[j];
    for (size_t j = 0; j < s.size(); ++j)
      if (side * s[j] > last && side * s[j] < next) next = side * s[j];
    if (std::isinf(next)) next = last;  // loaded to the end of the surface
    h.a += 0.25 * (last + next);
    h.spacing = std::max(h.spacing, next - last);
  }
  return h;
}

void print_hertz(const Scene &scene, const HertzMeasured &h) {
  // Effective modulus of the two bodies in the plane state of the scene.
  double compliance = 0;
  for (const Body &b : scene.bodies)
    compliance += (scene.plane == MC_PLANE_STRESS ? 1.0 : 1 - b.poisson * b.poisson) / b.young;
  const double e_star = 1 / compliance;
  if (scene.plane == MC_AXISYMMETRIC) {  // a sphere on a flat: 3D Hertz, P the total force
    const double a = std::cbrt(3 * scene.hertz.load * scene.hertz.radius / (4 * e_star));
    const double p0 = 3 * scene.hertz.load / (2 * PI * a * a);
    std::printf("Hertz (sphere, axisymmetric): R = %g, P = %g (total force), E* = %.6g\n", scene.hertz.radius,
                scene.hertz.load, e_star);
    std::printf("  p0 = %.6g   Hertz %.6g   relative error %+.3f %% (the largest nodal pressure)\n", h.p0, p0,
                100 * (h.p0 / p0 - 1));
    std::printf("  a  = %.6g   Hertz %.6g   relative error %+.3f %% (a known to +-%.3g, half the node spacing there)\n",
                h.a, a, 100 * (h.a / a - 1), h.spacing / 2);
    std::printf("  axial contact force %.10g (P = %g)\n", h.force, scene.hertz.load);
    return;
  }
  const double a = std::sqrt(4 * scene.hertz.load * scene.hertz.radius / (PI * e_star));
  const double p0 = 2 * scene.hertz.load / (PI * a);
  std::printf("Hertz: R = %g, P = %g per unit thickness, E* = %.6g\n", scene.hertz.radius, scene.hertz.load, e_star);
  std::printf("  p0 = %.6g   Hertz %.6g   relative error %+.3f %%\n", h.p0, p0, 100 * (h.p0 / p0 - 1));
  std::printf("  a  = %.6g   Hertz %.6g   relative error %+.3f %% (a known to +-%.3g, half the node spacing there)\n",
              h.a, a, 100 * (h.a / a - 1), h.spacing / 2);
  std::printf("  normal contact force per unit thickness %.10g (P = %g)\n", h.force, scene.hertz.load);
}

// ---- the run ------------------------------------------------------------------------------

void make_parent_directory(const std::string &path) {
  std::error_code ignored;  // if this fails, opening the file reports it
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ignored);
}

using ModelPtr = std::unique_ptr<mc_model, void (*)(mc_model *)>;

ModelPtr create_model() {
  mc_model *m = nullptr;
  if (mc_create(&m) != MC_OK) throw SolveError("mc_create failed: out of memory");
  return ModelPtr(m, mc_destroy);
}

// Reads the meshes (each file once) and takes each body out of its file.
void load_meshes(const Scene &scene, const Options &options, std::map<std::string, GmshMesh> &files,
                 BodyMesh bodies[2]) {
  for (int b = 0; b < 2; ++b) {
    const Body &spec = scene.bodies[b];
    auto it = files.find(spec.mesh_path);
    if (it == files.end()) {
      progress(options, "reading %s", spec.mesh_path.c_str());
      GmshMesh file = at_key(scene, spec.key + ".mesh", [&] { return read_gmsh(spec.mesh_path); });
      it = files.emplace(spec.mesh_path, std::move(file)).first;
    }
    bodies[b] = at_key(scene, spec.key + (spec.domain.empty() ? ".mesh" : ".domain"),
                       [&] { return extract_body(it->second, spec.domain, b + 1); });
    progress(options, "body %d: %d nodes, %d %s (%s%s%s)", b + 1, bodies[b].n_nodes(), bodies[b].n_cells(),
             cell_name(bodies[b].nodes_per_cell), spec.mesh.c_str(), spec.domain.empty() ? "" : ", group ",
             spec.domain.c_str());
  }
}

void set_up(mc_model *m, const Scene &scene, const BodyMesh bodies[2]) {
  set_options(m, scene);
  for (int b = 1; b <= 2; ++b) {
    set_mesh(m, b, bodies[b - 1], scene);
    apply_supports(m, b, bodies[b - 1], scene);
    apply_loads(m, b, bodies[b - 1], scene);
    set_contact(m, b, bodies[b - 1], scene);
  }
}

void write_outputs(const mc_model *m, const Scene &scene, const BodyMesh &body1, const ContactResults &r) {
  if (!scene.output.vtu.empty()) {
    make_parent_directory(scene.output.vtu);
    check(m, mc_write_vtu(m, scene.output.vtu.c_str()), "mc_write_vtu");
    std::printf("wrote %s\n", scene.output.vtu.c_str());
  }
  if (!scene.output.pressure_csv.empty()) {
    make_parent_directory(scene.output.pressure_csv);
    write_pressure_csv(scene.output.pressure_csv, body1, r);
    std::printf("wrote %s\n", scene.output.pressure_csv.c_str());
  }
}

int run(const Options &options) {
  Scene scene;
  std::map<std::string, GmshMesh> files;
  BodyMesh bodies[2];
  ModelPtr model = create_model();
  mc_model *m = model.get();
  try {
    scene = load_scene(options.scene);
    progress(options, "scene %s%s%s", scene.path.c_str(), scene.description.empty() ? "" : ": ",
             scene.description.c_str());
    load_meshes(scene, options, files, bodies);
    set_up(m, scene, bodies);
  } catch (const SceneError &e) {
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_BAD_INPUT;
  }
  check(m, mc_set_log_callback(m, options.verbosity > 0 ? log_message : nullptr, const_cast<Options *>(&options)),
        "mc_set_log_callback");
  progress(options, "solving");
  check(m, mc_solve(m), "mc_solve");
  const ContactResults results = contact_results(m);
  print_solve_summary(m, scene, results);
  if (scene.hertz.enabled) print_hertz(scene, measure_hertz(bodies[0], results, scene.thickness, scene.plane == MC_AXISYMMETRIC));
  write_outputs(m, scene, bodies[0], results);
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  Options options;
  const int code = parse_arguments(argc, argv, &options);
  if (code >= 0) return code;
  try {
    return run(options);
  } catch (const SolveError &e) {
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_SOLVE_FAILED;
  } catch (const std::exception &e) {  // out of memory, a filesystem error
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_SOLVE_FAILED;
  }
}
