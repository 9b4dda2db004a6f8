// scene.hpp - the scene file of mortarcontact-run (docs/scene_format.md): JSON parsed and
// validated into plain structs. Every mistake (bad JSON, unknown or duplicated key, missing key,
// wrong type, value out of range) is a SceneError whose message names the file and the key,
// e.g. "hertz.json: bodies[0].material.nu: must be in (-1, 0.5), got 0.6".
#ifndef MC_RUNNER_SCENE_HPP
#define MC_RUNNER_SCENE_HPP

#include "mortarcontact.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace mcrun {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Support {
  std::string key;    // "bodies[0].supports[1]", for messages
  std::string group;  // physical group (points, lines or a surface)
  int components;     // MC_X, MC_Y or MC_XY
  double value[2];    // prescribed displacement (x, y); only the components fixed matter
};

enum class LoadType { Pressure, Traction, BodyForce, NodalForce };

struct Load {
  std::string key;
  LoadType type;
  std::string group;  // empty for a body force
  double value[2];    // pressure: value[0]; the others: (x, y)
};

struct Body {
  std::string key;           // "bodies[0]"
  std::string mesh;          // path as written in the scene file
  std::string mesh_path;     // resolved against the scene file's directory
  std::string domain;        // physical surface group, "" = every 2D cell of the file
  double young, poisson;
  std::vector<Support> supports;
  std::vector<Load> loads;
  std::string contact;       // line group of the candidate contact surface ("" in a scene with "pairs")
  bool has_gap_offset = false;
  double gap_offset = 0;     // body 1 only: clearance (> 0) or interference (< 0) on every contact node
};

// A contact pair (docs/scene_format.md, "pairs"): the non-mortar body's surface against the
// mortar body's. A scene without "pairs" has one, made of bodies[0].contact and
// bodies[1].contact (implied = true): the two-body calls set it up as before.
struct Pair {
  std::string key;             // "pairs[0]", or "bodies" for the implied pair
  int number = 1;              // 1, 2, ...: the library's pair number
  int nonmortar = 1, mortar = 2;  // bodies, 1-based
  std::string nonmortar_surface, mortar_surface;            // line groups
  std::string nonmortar_key, mortar_key;                    // for messages
  bool has_gap_offset = false;
  double gap_offset = 0;       // on every node of the non-mortar surface
  std::string gap_offset_key;
  bool implied = false;
  // Friction (docs/scene_format.md, "friction"): pairs[k].friction, or the top-level "friction"
  // of a scene without "pairs" (the implied pair 1). mc_set_friction(law, friction_value).
  int friction_law = MC_FRICTION_NONE;  // MC_FRICTION_*
  double friction_value = 0;            // Coulomb: mu; Tresca: the slip bound
  std::string friction_key;             // "pairs[0].friction" or "friction", for messages
};

struct Solver {
  int method;          // MC_METHOD_*
  double tolerance;
  int max_iterations;  // 0: not given (the library's default)
  int contact_normal;  // MC_NORMAL_*
  int q1_integration;  // MC_Q1_*
  int ordering;        // MC_ORDERING_*
  int contact_surface;   // MC_SURFACE_*
  double feature_angle;  // degrees
  int threads;         // MC_OPTION_THREADS: 0 automatic, 1 serial, n at most n
  int interface_solver;  // MC_INTERFACE_*: MC_OPTION_INTERFACE_SOLVER
  bool error_estimate;   // MC_OPTION_ERROR_ESTIMATE: estimate the error (and write the indicators)
  int multiplier;        // MC_MULTIPLIER_*: MC_OPTION_MULTIPLIER (a body 1 of second-order cells)
  double friction_ct;    // MC_OPTION_FRICTION_CT: 0 = scaled automatically
};

struct Output {
  std::string vtu;           // resolved path, "" = none (.vtu: one file; .pvd: collection + one per body)
  std::string pressure_csv;  // resolved path, "" = none
};

struct HertzCheck {
  bool enabled = false;
  double radius = 0;  // of the curved body
  double load = 0;    // total force per unit thickness pressing the bodies together
};

// Adaptive refinement (docs/scene_format.md, "adaptive"): the runner meshes `geo` with Gmsh,
// solves, and remeshes with a size field made of the error indicators until the estimate is at
// or below `target_error`.
struct Adaptive {
  bool enabled = false;
  std::string geo;             // as written in the scene
  std::string geo_path;        // resolved against the scene file's directory
  double target_error = 0;     // relative energy-norm error to reach (MC_INFO_ERROR_ESTIMATE), in (0, 1)
  int max_steps = 8;           // remeshes after the first mesh (step 0)
  int order = 1;               // element order: gmsh -order (1 or 2)
  std::vector<std::string> gmsh_arguments;  // added to every gmsh command line
  double aim = 0.8;            // each new mesh is sized for aim * target_error
  double max_refinement = 4;   // per step, a cell's size shrinks at most by this factor
  double max_coarsening = 2;   // ... and grows at most by this factor
  double min_size = 0;         // bounds of the requested sizes; 0 = none
  double max_size = 0;
  long long max_dofs = 0;      // stop before a mesh predicted larger than this; 0 = no limit
};

// Whether any pair of the scene has friction (law Tresca or Coulomb).
struct Scene;
bool has_friction(const Scene &scene);

struct Scene {
  std::string path;  // the scene file, for messages
  std::string description;
  int plane;         // MC_PLANE_STRAIN, MC_PLANE_STRESS or MC_AXISYMMETRIC
  double thickness;
  std::vector<Body> bodies;  // bodies[0] = body 1 (the non-mortar side of a two-body scene)
  std::vector<Pair> pairs;   // at least one; without "pairs" in the file, the implied pair 1
  bool has_pairs = false;    // the file lists "pairs"
  int load_steps = 1;        // MC_OPTION_LOAD_STEPS: the loads ramped in this many increments (friction)
  Solver solver;
  Output output;
  HertzCheck hertz;
  Adaptive adaptive;
};

// Reads and validates a scene file; relative paths inside are taken from the file's directory.
Scene load_scene(const std::string &path);
// The same from JSON text; `path` names the file in messages and gives the base directory.
Scene parse_scene(const std::string &text, const std::string &path);

}  // namespace mcrun

#endif
