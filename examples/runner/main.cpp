// mortarcontact-run - solves a contact scene described by a JSON file (docs/scene_format.md)
// on Gmsh meshes, through the public C API of mortarcontact only.
//
//   mortarcontact-run [--quiet | --verbose] [--gmsh PATH] scene.json
//
// Exit codes: 0 solved; 1 the solve (or writing an output) failed, the library's message is
// printed; 2 bad command line, scene file or mesh, the message names the file, key and line;
// 3 adaptive refinement stopped above its target error (step or DOF limit); 4 Gmsh, which
// adaptive refinement runs, is missing or failed.
#include "adaptive.hpp"
#include "body_mesh.hpp"
#include "gmsh_reader.hpp"
#include "scene.hpp"

#include "mortarcontact.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
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
constexpr int EXIT_TARGET_NOT_MET = 3;
constexpr int EXIT_GMSH = 4;
constexpr double PI = 3.14159265358979323846;

struct Options {
  std::string scene;
  int verbosity = 1;  // 0 --quiet, 1 phases, 2 --verbose: also active-set iterations
  std::string gmsh;   // --gmsh: the Gmsh executable for adaptive refinement
};

// A failed library call after the set-up: the solve or an output (exit code 1).
struct SolveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void usage(FILE *to) {
  std::fprintf(to,
               "usage: mortarcontact-run [--quiet | --verbose] [--gmsh PATH] scene.json\n"
               "  Solves the contact of elastic bodies, frictionless or with friction, described by scene.json\n"
               "  (format: docs/scene_format.md) with mortarcontact %s.\n"
               "  --quiet      no progress messages on stderr\n"
               "  --verbose    also each active-set iteration\n"
               "  --gmsh PATH  the Gmsh executable adaptive refinement runs (default:\n"
               "               $MORTARCONTACT_GMSH, else gmsh on PATH)\n"
               "exit codes: 0 solved, 1 solve or output failed, 2 bad command line, scene or mesh,\n"
               "  3 adaptive refinement stopped above its target, 4 Gmsh missing or failed\n",
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
    } else if (arg == "--gmsh") {
      if (i + 1 >= argc || argv[i + 1][0] == '\0') {
        std::fprintf(stderr, "mortarcontact-run: --gmsh needs the path of the Gmsh executable\n");
        return EXIT_BAD_INPUT;
      }
      options->gmsh = argv[++i];
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

// The contact surfaces of a scene without "pairs": bodies[0].contact and bodies[1].contact, set
// with the two-body calls (pair 1, body 1 on body 2), as before pairs existed.
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

// Every node of edges (and their middles), once.
std::vector<int> surface_nodes(const std::vector<int> &edges, const std::vector<int> &mids) {
  std::vector<int> nodes(edges);
  nodes.insert(nodes.end(), mids.begin(), mids.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// The scene's "pairs": each made in order (the library numbers them 1, 2, ... as the scene
// does), its two surfaces, its gap offset on every node of the non-mortar surface.
void set_pairs(mc_model *m, const std::vector<BodyMesh> &bodies, const Scene &scene) {
  for (const Pair &p : scene.pairs) {
    int number = 0;
    setup(m, mc_add_contact_pair(m, p.nonmortar, p.mortar, &number), scene, p.key, "mc_add_contact_pair");
    if (number != p.number)
      throw SceneError(scene.path + ": " + p.key + ": the library numbered this pair " + std::to_string(number) +
                       ", expected " + std::to_string(p.number));
    std::vector<int> nonmortar_mids;
    for (int side = 0; side < 2; ++side) {
      const int body = side == 0 ? p.nonmortar : p.mortar;
      const std::string &key = side == 0 ? p.nonmortar_key : p.mortar_key;
      const std::string &group = side == 0 ? p.nonmortar_surface : p.mortar_surface;
      std::vector<int> mids;
      const std::vector<int> edges = at_key(scene, key + " (pair " + std::to_string(p.number) + ", body " +
                                                       std::to_string(body) + ")",
                                            [&] { return group_edges(bodies[size_t(body - 1)], group, &mids); });
      setup(m, mc_set_pair_surface(m, number, body, int(edges.size() / 2), edges.data()), scene, key,
            "mc_set_pair_surface");
      if (side == 0 && p.has_gap_offset) {
        const std::vector<int> nodes = surface_nodes(edges, mids);
        const std::vector<double> offsets(nodes.size(), p.gap_offset);
        setup(m, mc_set_pair_gap_offset(m, number, int(nodes.size()), nodes.data(), offsets.data()), scene,
              p.gap_offset_key, "mc_set_pair_gap_offset");
      }
    }
  }
}

void set_options(mc_model *m, const Scene &scene) {
  const Solver &s = scene.solver;
  setup(m, mc_set_plane(m, scene.plane, scene.thickness), scene, "plane/thickness", "mc_set_plane");
  setup(m, mc_set_option_int(m, MC_OPTION_METHOD, s.method), scene, "solver.method", "mc_set_option_int");
  setup(m, mc_set_option_real(m, MC_OPTION_TOLERANCE, s.tolerance), scene, "solver.tolerance", "mc_set_option_real");
  if (s.max_iterations > 0)  // (0: not in the scene, the library's default)
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
  setup(m, mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, s.error_estimate ? 1 : 0), scene, "solver.error_estimate",
        "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_MULTIPLIER, s.multiplier), scene, "solver.multiplier", "mc_set_option_int");
  setup(m, mc_set_option_int(m, MC_OPTION_LOAD_STEPS, scene.load_steps), scene, "load_steps", "mc_set_option_int");
  setup(m, mc_set_option_real(m, MC_OPTION_FRICTION_CT, s.friction_ct), scene, "solver.friction_ct", "mc_set_option_real");
}

// Each pair's friction law (after the pairs exist: mc_set_friction needs its pair).
void set_friction(mc_model *m, const Scene &scene) {
  for (const Pair &p : scene.pairs)
    if (!p.friction_key.empty())
      setup(m, mc_set_friction(m, p.number, p.friction_law, p.friction_value), scene, p.friction_key, "mc_set_friction");
}

// ---- results ------------------------------------------------------------------------------

void check(const mc_model *m, mc_status status, const char *call) {
  if (status != MC_OK) throw SolveError(std::string(call) + " failed: " + mc_status_string(status) + ": " + mc_errmsg(m));
}

// A pair's contact positions (nodes of its non-mortar body) and what the solve found there.
struct ContactResults {
  int pair = 1, nonmortar = 1, mortar = 2;
  std::vector<int> nodes;
  std::vector<double> pressure, force, gap, normal;  // normal: 2 per node
  // With friction in the scene (any pair), per position: MC_CONTACT_SHEAR, _SLIP, _SLIP_TOTAL, _STATE.
  std::vector<double> shear, slip, slip_total, state;
};

// The friction fields of pair `number` (the pair getters: the same positions, in the same order,
// as the two-body getters give pair 1's).
void friction_results(const mc_model *m, int number, ContactResults &r) {
  const size_t n = r.nodes.size();
  std::vector<double> *fields[4] = {&r.shear, &r.slip, &r.slip_total, &r.state};
  const int ids[4] = {MC_CONTACT_SHEAR, MC_CONTACT_SLIP, MC_CONTACT_SLIP_TOTAL, MC_CONTACT_STATE};
  for (int k = 0; k < 4; ++k) {
    fields[k]->resize(n);
    if (n > 0) check(m, mc_get_pair_contact(m, number, ids[k], fields[k]->data()), "mc_get_pair_contact");
  }
}

const char *state_name(double state) {
  if (state == MC_STATE_STICK) return "stick";
  if (state == MC_STATE_SLIP) return "slip";
  return "open";
}

// A pair of the scene's "pairs" list, through the pair getters.
ContactResults pair_results(const mc_model *m, const Pair &p) {
  ContactResults r;
  r.pair = p.number, r.nonmortar = p.nonmortar, r.mortar = p.mortar;
  mc_int n = 0;
  check(m, mc_get_pair_contact_count(m, p.number, &n), "mc_get_pair_contact_count");
  r.nodes.resize(size_t(n));
  r.pressure.resize(size_t(n));
  r.force.resize(size_t(n));
  r.gap.resize(size_t(n));
  r.normal.resize(2 * size_t(n));
  if (n == 0) return r;
  check(m, mc_get_pair_contact_nodes(m, p.number, r.nodes.data()), "mc_get_pair_contact_nodes");
  check(m, mc_get_pair_contact(m, p.number, MC_CONTACT_PRESSURE, r.pressure.data()), "mc_get_pair_contact");
  check(m, mc_get_pair_contact(m, p.number, MC_CONTACT_FORCE, r.force.data()), "mc_get_pair_contact");
  check(m, mc_get_pair_contact(m, p.number, MC_CONTACT_GAP, r.gap.data()), "mc_get_pair_contact");
  check(m, mc_get_pair_contact(m, p.number, MC_CONTACT_NORMAL, r.normal.data()), "mc_get_pair_contact");
  return r;
}

// Pair 1 of a scene without "pairs": body 1's contact nodes, through the two-body getters.
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

// Every pair's results, in the pairs' order.
std::vector<ContactResults> all_contact_results(const mc_model *m, const Scene &scene) {
  std::vector<ContactResults> all;
  if (!scene.has_pairs)
    all.push_back(contact_results(m));
  else
    for (const Pair &p : scene.pairs) all.push_back(pair_results(m, p));
  if (has_friction(scene))
    for (ContactResults &r : all) friction_results(m, r.pair, r);
  return all;
}

// The contact force on the pair's non-mortar body: lambda_j along -n_j.
void contact_resultant(const ContactResults &r, double resultant[2]) {
  resultant[0] = resultant[1] = 0;
  for (size_t j = 0; j < r.nodes.size(); ++j)
    for (int c = 0; c < 2; ++c) resultant[c] -= r.force[j] * r.normal[2 * j + size_t(c)];
}

// The path of the contact solve that ran (MC_INFO_INTERFACE_SOLVER; 0 without contact).
const char *interface_solver_name(int64_t value) {
  switch (value) {
    case MC_INTERFACE_CONDENSED: return "condensed";
    case MC_INTERFACE_SPARSE: return "sparse";
    default: return "unknown";
  }
}

void print_solve_summary(const mc_model *m, const Scene &scene, const std::vector<ContactResults> &all) {
  int64_t dofs = 0, iterations = 0, active = 0, interface_solver = 0;
  double total = 0, equilibrium = 0, complementarity = 0;
  check(m, mc_get_info_int(m, MC_INFO_DOFS, &dofs), "mc_get_info_int");
  check(m, mc_get_info_int(m, MC_INFO_ITERATIONS, &iterations), "mc_get_info_int");
  check(m, mc_get_info_int(m, MC_INFO_ACTIVE_NODES, &active), "mc_get_info_int");
  check(m, mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, &interface_solver), "mc_get_info_int");
  check(m, mc_get_info_real(m, MC_INFO_TIME_TOTAL, &total), "mc_get_info_real");
  check(m, mc_get_info_real(m, MC_INFO_EQUILIBRIUM, &equilibrium), "mc_get_info_real");
  check(m, mc_get_info_real(m, MC_INFO_COMPLEMENTARITY, &complementarity), "mc_get_info_real");
  size_t positions = 0;
  for (const ContactResults &r : all) positions += r.nodes.size();
  std::printf("solved: %lld DOFs, %lld active-set iterations, %lld of %zu contact nodes active, %.3f s\n",
              (long long)dofs, (long long)iterations, (long long)active, positions, total);
  if (interface_solver != 0)  // which path ran, and whether the scene forced it
    std::printf("  interface solver: %s (%s)\n", interface_solver_name(interface_solver),
                scene.solver.interface_solver == MC_INTERFACE_AUTO ? "chosen automatically" : "set by the scene");
  std::printf("  relative residuals: equilibrium %.2e, complementarity %.2e\n", equilibrium, complementarity);
  if (scene.solver.error_estimate) {
    double estimate = 0;
    check(m, mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &estimate), "mc_get_info_real");
    std::printf("  error estimate: %.3g %% (relative, energy norm of %s)\n", 100 * estimate,
                scene.bodies.size() == 2 ? "both bodies" : "all bodies");
  }
  if (has_friction(scene)) {
    int64_t stick = 0, slip = 0;
    double friction = 0;
    check(m, mc_get_info_int(m, MC_INFO_STICK_NODES, &stick), "mc_get_info_int");
    check(m, mc_get_info_int(m, MC_INFO_SLIP_NODES, &slip), "mc_get_info_int");
    check(m, mc_get_info_real(m, MC_INFO_FRICTION_COMPLEMENTARITY, &friction), "mc_get_info_real");
    std::printf("  friction: %lld stick, %lld slip (constraint rows), complementarity %.2e, %d load step%s\n",
                (long long)stick, (long long)slip, friction, scene.load_steps, scene.load_steps == 1 ? "" : "s");
    for (const ContactResults &r : all) {
      size_t count[3] = {0, 0, 0};  // open, stick, slip positions
      for (double st : r.state) ++count[st == MC_STATE_STICK ? 1 : st == MC_STATE_SLIP ? 2 : 0];
      std::printf("  pair %d friction: %zu open, %zu stick, %zu slip positions\n", r.pair, count[0], count[1], count[2]);
    }
  }
  double resultant[2];
  if (!scene.has_pairs) {
    contact_resultant(all[0], resultant);
    std::printf("  contact force on body 1: (%.10g, %.10g)\n", resultant[0], resultant[1]);
    return;
  }
  for (const ContactResults &r : all) {
    size_t loaded = 0;
    for (double p : r.pressure) loaded += p > 0;
    contact_resultant(r, resultant);
    std::printf("  pair %d (body %d on body %d): %zu contact positions, %zu with pressure > 0, contact force on "
                "body %d: (%.10g, %.10g)\n",
                r.pair, r.nonmortar, r.mortar, r.nodes.size(), loaded, r.nonmortar, resultant[0], resultant[1]);
  }
}

// x,y,pressure,gap per contact node of body 1; with "pairs", a first column pair and the rows
// of every pair, pair by pair (x, y on the pair's non-mortar body); with friction in the scene,
// the columns shear,slip,slip_total,state after them (state: open, stick or slip).
void write_pressure_csv(const std::string &path, const std::vector<BodyMesh> &bodies,
                        const std::vector<ContactResults> &all, bool pair_column, bool friction) {
  FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw SolveError("cannot write the pressure CSV " + path + ": " + std::strerror(errno));
  std::fprintf(f, "%s%s\n", pair_column ? "pair,x,y,pressure,gap" : "x,y,pressure,gap",
               friction ? ",shear,slip,slip_total,state" : "");
  for (const ContactResults &r : all) {
    const BodyMesh &body = bodies[size_t(r.nonmortar - 1)];
    for (size_t j = 0; j < r.nodes.size(); ++j) {
      const size_t i = size_t(r.nodes[j]);
      if (pair_column) std::fprintf(f, "%d,", r.pair);
      std::fprintf(f, "%.17g,%.17g,%.17g,%.17g", body.xy[2 * i], body.xy[2 * i + 1], r.pressure[j], r.gap[j]);
      if (friction)
        std::fprintf(f, ",%.17g,%.17g,%.17g,%s", r.shear[j], r.slip[j], r.slip_total[j], state_name(r.state[j]));
      std::fputc('\n', f);
    }
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

// Hertz's E*, a and p0 for the scene.
struct HertzReference {
  double e_star, a, p0;
};

HertzReference hertz_reference(const Scene &scene) {
  // Effective modulus of the two bodies in the plane state of the scene.
  double compliance = 0;
  for (const Body &b : scene.bodies)
    compliance += (scene.plane == MC_PLANE_STRESS ? 1.0 : 1 - b.poisson * b.poisson) / b.young;
  const double e_star = 1 / compliance;
  if (scene.plane == MC_AXISYMMETRIC) {  // a sphere on a flat: 3D Hertz, P the total force
    const double a = std::cbrt(3 * scene.hertz.load * scene.hertz.radius / (4 * e_star));
    return {e_star, a, 3 * scene.hertz.load / (2 * PI * a * a)};
  }
  const double a = std::sqrt(4 * scene.hertz.load * scene.hertz.radius / (PI * e_star));
  return {e_star, a, 2 * scene.hertz.load / (PI * a)};
}

void print_hertz(const Scene &scene, const HertzMeasured &h) {
  const HertzReference ref = hertz_reference(scene);
  const double e_star = ref.e_star, a = ref.a, p0 = ref.p0;
  if (scene.plane == MC_AXISYMMETRIC) {  // a sphere on a flat: 3D Hertz, P the total force
    std::printf("Hertz (sphere, axisymmetric): R = %g, P = %g (total force), E* = %.6g\n", scene.hertz.radius,
                scene.hertz.load, e_star);
    std::printf("  p0 = %.6g   Hertz %.6g   relative error %+.3f %% (the largest nodal pressure)\n", h.p0, p0,
                100 * (h.p0 / p0 - 1));
    std::printf("  a  = %.6g   Hertz %.6g   relative error %+.3f %% (a known to +-%.3g, half the node spacing there)\n",
                h.a, a, 100 * (h.a / a - 1), h.spacing / 2);
    std::printf("  axial contact force %.10g (P = %g)\n", h.force, scene.hertz.load);
    return;
  }
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

bool ends_with(const std::string &text, const std::string &suffix) {
  return text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// `path` without the extension `ext` if it has it.
std::string stem_of(const std::string &path, const std::string &ext) {
  return ends_with(path, ext) ? path.substr(0, path.size() - ext.size()) : path;
}

std::string file_name(const std::string &path) { return std::filesystem::path(path).filename().string(); }

using ModelPtr = std::unique_ptr<mc_model, void (*)(mc_model *)>;

ModelPtr create_model() {
  mc_model *m = nullptr;
  if (mc_create(&m) != MC_OK) throw SolveError("mc_create failed: out of memory");
  return ModelPtr(m, mc_destroy);
}

// Reads the meshes (each file once) and takes each body out of its file.
void load_meshes(const Scene &scene, const Options &options, std::map<std::string, GmshMesh> &files,
                 std::vector<BodyMesh> &bodies) {
  bodies.resize(scene.bodies.size());
  for (int b = 0; b < int(scene.bodies.size()); ++b) {
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

void set_up(mc_model *m, const Scene &scene, const std::vector<BodyMesh> &bodies) {
  set_options(m, scene);
  const int n = int(scene.bodies.size());
  if (n != 2) setup(m, mc_set_body_count(m, n), scene, "bodies", "mc_set_body_count");
  for (int b = 1; b <= n; ++b) {
    set_mesh(m, b, bodies[size_t(b - 1)], scene);
    apply_supports(m, b, bodies[size_t(b - 1)], scene);
    apply_loads(m, b, bodies[size_t(b - 1)], scene);
    if (!scene.has_pairs) set_contact(m, b, bodies[size_t(b - 1)], scene);
  }
  if (scene.has_pairs) set_pairs(m, bodies, scene);
  set_friction(m, scene);
}

// One solve of the scene on its meshes: the whole of a plain run, one step of an adaptive one.
struct Solution {
  std::map<std::string, GmshMesh> files;  // the bodies point into these
  std::vector<BodyMesh> bodies;
  ModelPtr model = create_model();
  std::vector<ContactResults> results;  // per pair
  std::vector<std::vector<double>> eta;  // per body, the cells' error indicators (empty without the estimate)
  double estimate = 0;         // MC_INFO_ERROR_ESTIMATE
};

// Throws SceneError for a bad scene or mesh, SolveError if the library fails.
std::unique_ptr<Solution> solve(const Scene &scene, const Options &options) {
  auto s = std::make_unique<Solution>();
  mc_model *m = s->model.get();
  load_meshes(scene, options, s->files, s->bodies);
  set_up(m, scene, s->bodies);
  check(m, mc_set_log_callback(m, options.verbosity > 0 ? log_message : nullptr, const_cast<Options *>(&options)),
        "mc_set_log_callback");
  progress(options, "solving");
  check(m, mc_solve(m), "mc_solve");
  s->results = all_contact_results(m, scene);
  s->eta.resize(s->bodies.size());
  if (scene.solver.error_estimate) {
    check(m, mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, &s->estimate), "mc_get_info_real");
    for (int b = 0; b < int(s->bodies.size()); ++b) {
      s->eta[b].resize(size_t(s->bodies[b].n_cells()));
      check(m, mc_get_error_indicator(m, b + 1, s->eta[b].data()), "mc_get_error_indicator");
    }
  }
  return s;
}

// The VTU files mc_write_vtu writes for `path`, and the bodies (0-based) each holds.
std::vector<std::pair<std::string, std::vector<int>>> vtu_files(const std::string &path, int n_bodies) {
  std::vector<int> all;
  for (int b = 0; b < n_bodies; ++b) all.push_back(b);
  if (!ends_with(path, ".pvd")) return {{path, all}};
  const std::string stem = stem_of(path, ".pvd");
  std::vector<std::pair<std::string, std::vector<int>>> files;
  for (int b = 0; b < n_bodies; ++b) files.push_back({stem + "_body" + std::to_string(b + 1) + ".vtu", {b}});
  return files;
}

// ParaView output with the error indicators as cell data "error_indicator".
void write_vtu(const Solution &s, const std::string &path) {
  make_parent_directory(path);
  check(s.model.get(), mc_write_vtu(s.model.get(), path.c_str()), "mc_write_vtu");
  if (s.eta.empty() || s.eta[0].empty()) return;
  for (const auto &file : vtu_files(path, int(s.bodies.size()))) {
    std::vector<double> values;
    for (int b : file.second) values.insert(values.end(), s.eta[b].begin(), s.eta[b].end());
    try {
      add_vtu_cell_data(file.first, "error_indicator", values);
    } catch (const std::runtime_error &e) {
      throw SolveError(e.what());
    }
  }
}

// A ParaView collection of the VTU files of mc_write_vtu's outputs `step_vtus`, the index in the
// list as time: for every step of an adaptive run, ParaView's time controls step through the meshes.
void write_collection(const std::string &path, const std::vector<std::string> &step_vtus, int n_bodies) {
  FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw SolveError("cannot write " + path + ": " + std::strerror(errno));
  std::fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                  "  <Collection>\n");
  for (size_t k = 0; k < step_vtus.size(); ++k)
    for (const auto &file : vtu_files(step_vtus[k], n_bodies))
      std::fprintf(f, "    <DataSet timestep=\"%zu\" group=\"\" part=\"%d\" file=\"%s\"/>\n", k,
                   file.second.size() == 1 ? file.second[0] : 0, file_name(file.first).c_str());
  std::fprintf(f, "  </Collection>\n</VTKFile>\n");
  if (std::fclose(f) != 0) throw SolveError("cannot write " + path);
}

// The scene's outputs; with `last_step_vtu` (adaptive refinement) output.vtu names the last
// step's files instead of writing them again: a .pvd collection of them, or a copy of the .vtu.
void write_outputs(const Solution &s, const Scene &scene, const std::string &last_step_vtu = "") {
  if (!scene.output.vtu.empty() && !last_step_vtu.empty()) {
    make_parent_directory(scene.output.vtu);
    if (ends_with(scene.output.vtu, ".pvd")) {
      write_collection(scene.output.vtu, {last_step_vtu}, int(scene.bodies.size()));
    } else {
      std::error_code error;
      std::filesystem::copy_file(last_step_vtu, scene.output.vtu, std::filesystem::copy_options::overwrite_existing,
                                 error);
      if (error) throw SolveError("cannot copy " + last_step_vtu + " to " + scene.output.vtu + ": " + error.message());
    }
    std::printf("wrote %s (the last step's)\n", scene.output.vtu.c_str());
  } else if (!scene.output.vtu.empty()) {
    write_vtu(s, scene.output.vtu);
    std::printf("wrote %s\n", scene.output.vtu.c_str());
  }
  if (!scene.output.pressure_csv.empty()) {
    make_parent_directory(scene.output.pressure_csv);
    write_pressure_csv(scene.output.pressure_csv, s.bodies, s.results, scene.has_pairs, has_friction(scene));
    std::printf("wrote %s\n", scene.output.pressure_csv.c_str());
  }
}

void print_results(const Solution &s, const Scene &scene) {
  print_solve_summary(s.model.get(), scene, s.results);
  if (scene.hertz.enabled)
    print_hertz(scene, measure_hertz(s.bodies[0], s.results[0], scene.thickness, scene.plane == MC_AXISYMMETRIC));
}

// ---- adaptive refinement ------------------------------------------------------------------

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct StepRow {
  int step;
  long long cells, dofs;
  double estimate, p0_error, gmsh_seconds, solve_seconds, total_seconds;
  double predicted_dofs;  // what the size field asked for (0 at step 0)
};

void print_table(const Scene &scene, const std::vector<StepRow> &rows) {
  const bool hertz = scene.hertz.enabled;
  std::printf("adaptive refinement of %s, target %.3g %% (estimated relative error, energy norm):\n",
              scene.adaptive.geo.c_str(), 100 * scene.adaptive.target_error);
  std::printf("  step    cells     DOFs  asked DOFs  estimate%s  gmsh s  solve s  total s\n",
              hertz ? "  p0 - Hertz" : "");
  for (const StepRow &r : rows) {
    char asked[32] = "          -";
    if (r.predicted_dofs > 0) std::snprintf(asked, sizeof asked, "%11.0f", r.predicted_dofs);
    char p0[32] = "";
    if (hertz) std::snprintf(p0, sizeof p0, "  %+9.3f %%", 100 * r.p0_error);
    std::printf("  %4d %8lld %8lld %s  %6.3f %%%s  %6.2f  %7.3f  %7.2f\n", r.step, r.cells, r.dofs, asked,
                100 * r.estimate, p0, r.gmsh_seconds, r.solve_seconds, r.total_seconds);
  }
}

// How Gmsh takes the sizes asked for, before the first refinement: the step-0 mesh is meshed
// again with its own cells' sizes, and the sizes asked for from then on are multiplied by
// sqrt(cells Gmsh made / cells of step 0): about 1.15 for triangles (a node takes the smallest
// size of its cells), 2.3 for quadrilaterals by subdivision (Gmsh halves every side after
// meshing with the sizes).
double calibrate(const BodyMesh bodies[2], const Scene &scene, const Adaptive &adaptive, const std::string &gmsh,
                 const std::string &mesh_stem, const Options &options, double *seconds) {
  const auto start = std::chrono::steady_clock::now();
  const std::string name = mesh_stem + "_step0_calibration";
  const SizeField field = current_size_field(bodies);
  try {
    write_size_view(name + "_size.pos", bodies, field);
    write_step_geo(name + ".geo", adaptive.geo_path, name + "_size.pos",
                   "step 0's mesh again, each cell asking for its own size: how many cells Gmsh makes of the "
                   "sizes asked for.");
  } catch (const std::runtime_error &e) {
    throw SolveError(e.what());
  }
  run_gmsh(gmsh, name + ".geo", name + ".msh", adaptive.order, adaptive.gmsh_arguments, name + "_gmsh.log");
  const GmshMesh file = at_key(scene, "adaptive.geo", [&] { return read_gmsh(name + ".msh"); });
  int cells = 0;
  for (int b = 0; b < 2; ++b)
    cells += at_key(scene, scene.bodies[b].key + ".domain",
                    [&] { return extract_body(file, scene.bodies[b].domain, b + 1); }).n_cells();
  *seconds = seconds_since(start);
  const double calibration = std::clamp(std::sqrt(double(cells) / field.predicted_cells), 0.2, 5.0);
  progress(options, "calibration: step 0's own sizes gave %d cells for its %d: sizes asked for times %.3g", cells,
           field.cells, calibration);
  return calibration;
}

int run_adaptive(const Scene &scene, const Options &options) {
  const Adaptive &adaptive = scene.adaptive;
  const auto start = std::chrono::steady_clock::now();
  std::error_code error;
  if (!std::filesystem::is_regular_file(adaptive.geo_path, error))
    throw SceneError(scene.path + ": adaptive.geo: no such file: " + adaptive.geo_path);
  const std::string gmsh = find_gmsh(options.gmsh);
  progress(options, "adaptive refinement to %.3g %% with %s", 100 * adaptive.target_error, gmsh.c_str());
  const std::string mesh_stem = stem_of(scene.bodies[0].mesh_path, ".msh");
  // Step k's ParaView files: <stem>_step<k>.pvd (or .vtu), and <stem>_steps.pvd for all steps.
  const std::string &vtu = scene.output.vtu;
  const std::string vtu_ext = ends_with(vtu, ".pvd") ? ".pvd" : ends_with(vtu, ".vtu") ? ".vtu" : "";
  const std::string vtu_stem = stem_of(vtu, vtu_ext);
  make_parent_directory(mesh_stem);
  std::vector<StepRow> rows;
  std::vector<std::string> step_vtus;
  std::unique_ptr<Solution> s;
  double calibration = 1;  // the sizes asked of Gmsh over those wanted, from the last step
  double probe_seconds = 0;  // the calibration's Gmsh run after step 0 (counted in step 1)
  double predicted_cells = 0, predicted_dofs = 0;
  for (int step = 0;; ++step) {
    const std::string step_name = mesh_stem + "_step" + std::to_string(step);
    const std::string msh = step_name + ".msh";
    s.reset();  // the last step's model: its size field is written
    const auto gmsh_start = std::chrono::steady_clock::now();
    if (step == 0) {
      progress(options, "step 0: gmsh on %s", adaptive.geo_path.c_str());
      run_gmsh(gmsh, adaptive.geo_path, msh, adaptive.order, adaptive.gmsh_arguments, step_name + "_gmsh.log");
    } else {
      progress(options, "step %d: gmsh on %s.geo", step, step_name.c_str());
      run_gmsh(gmsh, step_name + ".geo", msh, adaptive.order, adaptive.gmsh_arguments, step_name + "_gmsh.log");
    }
    const double gmsh_seconds = seconds_since(gmsh_start) + (step == 1 ? probe_seconds : 0);
    Scene step_scene = scene;
    for (Body &b : step_scene.bodies) b.mesh = file_name(msh), b.mesh_path = msh;
    s = solve(step_scene, options);
    mc_model *m = s->model.get();
    StepRow row{step, 0, 0, s->estimate, 0, gmsh_seconds, 0, 0, predicted_dofs};
    row.cells = s->bodies[0].n_cells() + s->bodies[1].n_cells();
    int64_t dofs = 0;
    check(m, mc_get_info_int(m, MC_INFO_DOFS, &dofs), "mc_get_info_int");
    row.dofs = dofs;
    check(m, mc_get_info_real(m, MC_INFO_TIME_TOTAL, &row.solve_seconds), "mc_get_info_real");
    if (scene.hertz.enabled)
      row.p0_error = measure_hertz(s->bodies[0], s->results[0], scene.thickness, scene.plane == MC_AXISYMMETRIC).p0 /
                         hertz_reference(scene).p0 - 1;
    if (step > 0 && predicted_cells > 0) {  // how Gmsh took the sizes: correct the next request
      const double ratio = std::sqrt(double(row.cells) / predicted_cells);
      calibration = std::clamp(calibration * std::clamp(ratio, 0.5, 2.0), 0.2, 5.0);
    }
    if (!vtu.empty()) {
      step_vtus.push_back(vtu_stem + "_step" + std::to_string(step) + vtu_ext);
      write_vtu(*s, step_vtus.back());
      write_collection(vtu_stem + "_steps.pvd", step_vtus, int(scene.bodies.size()));
    }
    row.total_seconds = seconds_since(start);
    rows.push_back(row);
    std::printf("step %d: %lld DOFs, error estimate %.3f %% (target %.3g %%)%s\n", step, row.dofs, 100 * row.estimate,
                100 * adaptive.target_error, row.estimate <= adaptive.target_error ? ": reached" : "");
    std::fflush(stdout);
    std::string stop;  // why the loop ends above the target
    if (row.estimate <= adaptive.target_error) break;
    if (step == adaptive.max_steps) {
      stop = "the target was not reached in adaptive.max_steps = " + std::to_string(adaptive.max_steps) +
             (adaptive.max_steps == 1 ? " refinement step" : " refinement steps");
    } else {
      if (step == 0) calibration = calibrate(s->bodies.data(), step_scene, adaptive, gmsh, mesh_stem, options, &probe_seconds);
      // The next mesh's sizes, from this step's indicators.
      const SizeField field = make_size_field(s->bodies.data(), s->eta.data(), adaptive, calibration);
      predicted_cells = field.predicted_cells;
      predicted_dofs = double(row.dofs) * field.predicted_cells / double(field.cells);
      progress(options, "step %d: size field: %d of %d cells refined (%d by the limit %g), %d coarsened; "
               "%.0f cells asked for (%.0f DOFs), calibration %.3g",
               step, field.refined, field.cells, field.limited, adaptive.max_refinement, field.coarsened,
               field.predicted_cells, predicted_dofs, calibration);
      if (adaptive.max_dofs > 0 && predicted_dofs > double(adaptive.max_dofs)) {
        char text[200];
        std::snprintf(text, sizeof text, "the next mesh would have about %.0f DOFs, above adaptive.max_dofs = %lld",
                      predicted_dofs, adaptive.max_dofs);
        stop = text;
      } else {
        const std::string next = mesh_stem + "_step" + std::to_string(step + 1);
        try {
          write_size_view(next + "_size.pos", s->bodies.data(), field);
          write_step_geo(next + ".geo", adaptive.geo_path, next + "_size.pos",
                         "step " + std::to_string(step + 1) + ", sized by step " + std::to_string(step) +
                             "'s error indicators.");
        } catch (const std::runtime_error &e) {
          throw SolveError(e.what());
        }
        continue;
      }
    }
    // Stopped above the target: the table, the last step's results, and why.
    print_table(scene, rows);
    print_results(*s, scene);
    write_outputs(*s, scene, step_vtus.empty() ? "" : step_vtus.back());
    std::fprintf(stderr,
                 "mortarcontact-run: error: adaptive refinement stopped above its target: %s; the estimate is "
                 "%.3g %% at step %d (%lld DOFs), the target %.3g %% (the outputs hold step %d)\n",
                 stop.c_str(), 100 * row.estimate, step, row.dofs, 100 * adaptive.target_error, step);
    return EXIT_TARGET_NOT_MET;
  }
  print_table(scene, rows);
  std::printf("target reached at step %zu: error estimate %.3f %% <= %.3g %%, %lld DOFs\n", rows.size() - 1,
              100 * rows.back().estimate, 100 * adaptive.target_error, rows.back().dofs);
  print_results(*s, scene);
  write_outputs(*s, scene, step_vtus.empty() ? "" : step_vtus.back());
  return 0;
}

int run(const Options &options) {
  Scene scene = load_scene(options.scene);
  progress(options, "scene %s%s%s", scene.path.c_str(), scene.description.empty() ? "" : ": ",
           scene.description.c_str());
  if (scene.adaptive.enabled) return run_adaptive(scene, options);
  const std::unique_ptr<Solution> s = solve(scene, options);
  print_results(*s, scene);
  write_outputs(*s, scene);
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  Options options;
  const int code = parse_arguments(argc, argv, &options);
  if (code >= 0) return code;
  try {
    return run(options);
  } catch (const SceneError &e) {
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_BAD_INPUT;
  } catch (const GmshError &e) {
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_GMSH;
  } catch (const SolveError &e) {
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_SOLVE_FAILED;
  } catch (const std::exception &e) {  // out of memory, a filesystem error
    std::fprintf(stderr, "mortarcontact-run: error: %s\n", e.what());
    return EXIT_SOLVE_FAILED;
  }
}
