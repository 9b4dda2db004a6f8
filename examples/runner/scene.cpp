// scene.cpp - parse and validate a scene file (docs/scene_format.md) with nlohmann::json.
//
// Strictness is the point: a typo in a key must not silently fall back to a default, so every
// object is checked against the keys it may hold, duplicated keys are refused (JSON parsers
// otherwise keep the last one), and every value is checked for type and range.
#include "scene.hpp"

#include "mortarcontact.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

namespace mcrun {

namespace {

using json = nlohmann::json;

// Edit distance, to suggest the key a typo meant.
size_t edit_distance(const std::string &a, const std::string &b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// A JSON value together with its key path ("bodies[0].material.nu") for messages.
class Value {
 public:
  Value(const json &j, std::string key, const std::string &file) : j_(j), key_(std::move(key)), file_(file) {}

  [[noreturn]] void fail(const std::string &message) const {
    throw SceneError(file_ + ": " + (key_.empty() ? "top level" : key_) + ": " + message);
  }

  const std::string &key() const { return key_; }

  // An object whose keys are all among `allowed`.
  void expect_object(std::initializer_list<const char *> allowed) const {
    if (!j_.is_object()) fail("must be an object {...}, got " + describe());
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      bool known = false;
      std::string best;
      size_t best_distance = 3;  // suggest only close matches
      for (const char *a : allowed) {
        if (it.key() == a) known = true;
        size_t d = edit_distance(it.key(), a);
        if (d < best_distance) best_distance = d, best = a;
      }
      if (known) continue;
      std::string list;
      for (const char *a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      child(it.key()).fail("unknown key" + (best.empty() ? std::string() : " (did you mean '" + best + "'?)") +
                           "; allowed here: " + list);
    }
  }

  bool has(const char *name) const { return j_.contains(name); }
  bool is_integer() const { return j_.is_number_integer(); }

  Value at(const char *name) const {
    if (!has(name)) child(name).fail("missing (required)");
    return child(name);
  }

  Value child(const std::string &name) const {
    static const json null_value;
    auto it = j_.find(name);
    return Value(it == j_.end() ? null_value : *it, key_.empty() ? name : key_ + "." + name, file_);
  }

  std::vector<Value> items() const {
    if (!j_.is_array()) fail("must be an array [...], got " + describe());
    std::vector<Value> values;
    for (size_t i = 0; i < j_.size(); ++i) values.emplace_back(j_[i], key_ + "[" + std::to_string(i) + "]", file_);
    return values;
  }

  double number() const {
    if (!j_.is_number()) fail("must be a number, got " + describe());
    double v = j_.get<double>();
    if (!std::isfinite(v)) fail("must be finite");
    return v;
  }

  double positive() const {
    double v = number();
    if (!(v > 0)) fail("must be > 0, got " + j_.dump());
    return v;
  }

  int positive_integer() const {
    if (!j_.is_number_integer() || j_.get<long long>() < 1 || j_.get<long long>() > 1000000000)
      fail("must be an integer >= 1, got " + describe());
    return int(j_.get<long long>());
  }

  // An integer in [lo, hi].
  int integer_in(long long lo, long long hi) const {
    if (!j_.is_number_integer() || j_.get<long long>() < lo || j_.get<long long>() > hi)
      fail("must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + describe());
    return int(j_.get<long long>());
  }

  bool boolean() const {
    if (!j_.is_boolean()) fail("must be true or false, got " + describe());
    return j_.get<bool>();
  }

  std::string string() const {
    if (!j_.is_string()) fail("must be a string, got " + describe());
    std::string s = j_.get<std::string>();
    if (s.empty()) fail("must not be empty");
    return s;
  }

  // One of the named choices; returns its value.
  int choice(std::initializer_list<std::pair<const char *, int>> choices) const {
    std::string s = string(), list;
    for (const auto &c : choices) {
      if (s == c.first) return c.second;
      list += std::string(list.empty() ? "\"" : ", \"") + c.first + "\"";
    }
    fail("\"" + s + "\" is not one of " + list);
  }

  void pair(double out[2]) const {
    if (!j_.is_array() || j_.size() != 2) fail("must be an array of two numbers [x, y], got " + describe());
    std::vector<Value> v = items();
    out[0] = v[0].number();
    out[1] = v[1].number();
  }

  std::string describe() const {
    std::string text = j_.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(j_.type_name()) + " " + text;
  }

 private:
  const json &j_;
  std::string key_;
  const std::string &file_;
};

// Refuses duplicated keys during parsing (nlohmann keeps the last one silently), naming the
// key path. A frame per open object or array tracks the keys seen and the element index.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const std::string &file) : file_(file) {}

  bool operator()(int, json::parse_event_t event, json &parsed) {
    switch (event) {
      case json::parse_event_t::object_start: frames_.push_back({false, 0, "", {}}); break;
      case json::parse_event_t::array_start: frames_.push_back({true, 0, "", {}}); break;
      case json::parse_event_t::key: {
        Frame &f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.seen.insert(f.key).second) throw SceneError(file_ + ": " + path() + ": duplicated key");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        element_done();
        break;
      case json::parse_event_t::value: element_done(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    size_t index;
    std::string key;
    std::set<std::string> seen;
  };

  void element_done() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  std::string path() const {
    std::string p;
    for (const Frame &f : frames_)
      p += f.array ? "[" + std::to_string(f.index) + "]" : (p.empty() ? "" : ".") + f.key;
    return p;
  }

  const std::string &file_;
  std::vector<Frame> frames_;
};

json parse_json(const std::string &text, const std::string &path) {
  try {
    return json::parse(text, DuplicateKeyCheck(path));
  } catch (const json::parse_error &e) {
    std::string what = e.what();
    size_t bracket = what.find("] ");  // drop nlohmann's "[json.exception.parse_error.101] "
    throw SceneError(path + ": invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
}

std::string resolve(const std::string &base_dir, const std::string &relative) {
  std::filesystem::path p(relative);
  return p.is_absolute() ? relative : (std::filesystem::path(base_dir) / p).string();
}

Support parse_support(const Value &v) {
  v.expect_object({"group", "components", "value"});
  Support s{v.key(), v.at("group").string(), 0, {0, 0}};
  s.components = v.at("components").choice({{"x", MC_X}, {"y", MC_Y}, {"both", MC_XY}});
  if (v.has("value")) {
    if (s.components == MC_XY) {
      v.child("value").pair(s.value);
    } else {
      const double u = v.child("value").number();  // one component: one number
      s.value[s.components == MC_X ? 0 : 1] = u;
    }
  }
  return s;
}

Load parse_load(const Value &v) {
  v.expect_object({"type", "group", "value"});
  const LoadType type = LoadType(v.at("type").choice({{"pressure", int(LoadType::Pressure)},
                                                     {"traction", int(LoadType::Traction)},
                                                     {"body_force", int(LoadType::BodyForce)},
                                                     {"nodal_force", int(LoadType::NodalForce)}}));
  Load load{v.key(), type, "", {0, 0}};
  if (type == LoadType::BodyForce) {
    if (v.has("group")) v.child("group").fail("a body force acts on the whole body: no group");
  } else {
    load.group = v.at("group").string();
  }
  if (type == LoadType::Pressure)
    load.value[0] = v.at("value").number();
  else
    v.at("value").pair(load.value);
  return load;
}

Body parse_body(const Value &v, int index, const std::string &base_dir, bool with_pairs) {
  v.expect_object({"mesh", "domain", "material", "supports", "loads", "contact", "gap_offset"});
  Body b;
  b.key = v.key();
  b.mesh = v.at("mesh").string();
  b.mesh_path = resolve(base_dir, b.mesh);
  if (v.has("domain")) b.domain = v.child("domain").string();
  Value material = v.at("material");
  material.expect_object({"E", "nu"});
  b.young = material.at("E").positive();
  b.poisson = material.at("nu").number();
  if (!(b.poisson > -1 && b.poisson < 0.5))
    material.child("nu").fail("must be in (-1, 0.5), got " + std::to_string(b.poisson));
  if (v.has("supports"))
    for (const Value &s : v.child("supports").items()) b.supports.push_back(parse_support(s));
  if (v.has("loads"))
    for (const Value &l : v.child("loads").items()) b.loads.push_back(parse_load(l));
  if (with_pairs) {  // the surfaces are the pairs'
    for (const char *key : {"contact", "gap_offset"})
      if (v.has(key))
        v.child(key).fail(std::string("the scene lists \"pairs\": name the contact surfaces and gap offsets there (") +
                          "pairs[].nonmortar_surface, mortar_surface, gap_offset), not in the bodies");
    return b;
  }
  b.contact = v.at("contact").string();
  if (v.has("gap_offset")) {
    if (index != 0) v.child("gap_offset").fail("only body 1 (the non-mortar side, bodies[0]) takes a gap offset");
    b.has_gap_offset = true;
    b.gap_offset = v.child("gap_offset").number();
  }
  return b;
}

// A pair's "friction": {"law": "coulomb", "mu": 0.3}, {"law": "tresca", "bound": 0.01} or
// {"law": "none"}; the value must be finite and >= 0 (the library checks it again).
void parse_friction(const Value &f, Pair &p) {
  p.friction_key = f.key();
  if (!f.has("law")) f.expect_object({"law", "mu", "bound"});  // a typo of "law" first
  p.friction_law = f.at("law").choice({{"none", MC_FRICTION_NONE}, {"tresca", MC_FRICTION_TRESCA},
                                       {"coulomb", MC_FRICTION_COULOMB}});
  const char *value_key = p.friction_law == MC_FRICTION_COULOMB ? "mu" : "bound";
  if (p.friction_law == MC_FRICTION_NONE) {
    f.expect_object({"law"});
    return;
  }
  if (p.friction_law == MC_FRICTION_COULOMB)
    f.expect_object({"law", "mu"});
  else
    f.expect_object({"law", "bound"});
  const Value value = f.at(value_key);
  p.friction_value = value.number();
  if (!(p.friction_value >= 0))
    value.fail(std::string(p.friction_law == MC_FRICTION_COULOMB ? "the friction coefficient" : "the Tresca slip bound") +
               " must be >= 0, got " + value.describe());
}

// pairs[k]: its bodies must exist and differ; both surfaces are required.
Pair parse_pair(const Value &v, int number, int n_bodies) {
  v.expect_object({"nonmortar", "mortar", "nonmortar_surface", "mortar_surface", "gap_offset", "friction"});
  Pair p;
  p.key = v.key();
  p.number = number;
  const std::string pair_name = "pair " + std::to_string(number);
  for (const char *side : {"nonmortar", "mortar"}) {
    const Value b = v.at(side);
    int body = 0;
    if (b.is_integer()) body = b.integer_in(-1000000000, 1000000000);
    if (!b.is_integer() || body < 1 || body > n_bodies)
      b.fail(pair_name + " names body " + (b.is_integer() ? std::to_string(body) : b.describe()) +
             ", which does not exist: the scene has bodies 1 to " + std::to_string(n_bodies) +
             " (body k is bodies[k-1])");
    (side[0] == 'n' ? p.nonmortar : p.mortar) = body;
  }
  if (p.nonmortar == p.mortar)
    v.fail(pair_name + " joins body " + std::to_string(p.nonmortar) +
           " with itself: nonmortar and mortar must be two different bodies");
  p.nonmortar_surface = v.at("nonmortar_surface").string();
  p.mortar_surface = v.at("mortar_surface").string();
  p.nonmortar_key = v.key() + ".nonmortar_surface";
  p.mortar_key = v.key() + ".mortar_surface";
  if (v.has("gap_offset")) {
    p.has_gap_offset = true;
    p.gap_offset = v.child("gap_offset").number();
    p.gap_offset_key = v.key() + ".gap_offset";
  }
  if (v.has("friction")) parse_friction(v.child("friction"), p);
  return p;
}

Solver parse_solver(const Value &v) {
  // Defaults: the library's (mortarcontact.h).
  Solver s{MC_METHOD_MORTAR, 1e-10, 0, MC_NORMAL_NONMORTAR, MC_Q1_FULL, MC_ORDERING_AUTO, MC_SURFACE_SMOOTH, 40, 0,
           MC_INTERFACE_AUTO, true, MC_MULTIPLIER_LINEAR, 0.0};
  if (!v.has("solver")) return s;
  Value o = v.child("solver");
  o.expect_object({"method", "tolerance", "max_iterations", "contact_normal", "q1_integration", "ordering",
                   "contact_surface", "feature_angle", "threads", "interface_solver", "error_estimate",
                   "multiplier", "friction_ct"});
  if (o.has("method"))
    s.method = o.child("method").choice({{"mortar", MC_METHOD_MORTAR},
                                         {"dual_mortar", MC_METHOD_DUAL_MORTAR},
                                         {"node_to_segment", MC_METHOD_NODE_TO_SEGMENT}});
  if (o.has("tolerance")) s.tolerance = o.child("tolerance").positive();
  if (o.has("max_iterations")) s.max_iterations = o.child("max_iterations").positive_integer();
  if (o.has("contact_normal"))
    s.contact_normal = o.child("contact_normal").choice({{"nonmortar", MC_NORMAL_NONMORTAR}, {"mortar", MC_NORMAL_MORTAR}});
  if (o.has("q1_integration"))
    s.q1_integration = o.child("q1_integration").choice({{"full", MC_Q1_FULL}, {"bbar", MC_Q1_BBAR}});
  if (o.has("ordering"))
    s.ordering = o.child("ordering").choice({{"auto", MC_ORDERING_AUTO}, {"amd", MC_ORDERING_AMD}, {"metis", MC_ORDERING_METIS}});
  if (o.has("contact_surface"))
    s.contact_surface = o.child("contact_surface").choice({{"smooth", MC_SURFACE_SMOOTH}, {"faceted", MC_SURFACE_FACETED}});
  if (o.has("feature_angle")) s.feature_angle = o.child("feature_angle").number();  // the library checks the range
  if (o.has("threads")) s.threads = o.child("threads").integer_in(0, 1024);
  if (o.has("interface_solver"))
    s.interface_solver = o.child("interface_solver").choice({{"auto", MC_INTERFACE_AUTO},
                                                             {"condensed", MC_INTERFACE_CONDENSED},
                                                             {"sparse", MC_INTERFACE_SPARSE}});
  if (o.has("error_estimate")) s.error_estimate = o.child("error_estimate").boolean();
  if (o.has("multiplier"))
    s.multiplier = o.child("multiplier").choice({{"linear", MC_MULTIPLIER_LINEAR}, {"quadratic", MC_MULTIPLIER_QUADRATIC}});
  if (o.has("friction_ct")) {
    s.friction_ct = o.child("friction_ct").number();
    if (!(s.friction_ct >= 0))
      o.child("friction_ct").fail("must be >= 0 (0: scaled automatically), got " + o.child("friction_ct").describe());
  }
  return s;
}

Output parse_output(const Value &v, const std::string &base_dir) {
  Output out;
  if (!v.has("output")) return out;
  Value o = v.child("output");
  o.expect_object({"vtu", "pressure_csv"});
  if (o.has("vtu")) out.vtu = resolve(base_dir, o.child("vtu").string());
  if (o.has("pressure_csv")) out.pressure_csv = resolve(base_dir, o.child("pressure_csv").string());
  return out;
}

HertzCheck parse_analytic(const Value &v) {
  HertzCheck h;
  if (!v.has("analytic")) return h;
  Value a = v.child("analytic");
  a.expect_object({"type", "radius", "load"});
  a.at("type").choice({{"hertz", 1}});
  h.enabled = true;
  h.radius = a.at("radius").positive();
  h.load = a.at("load").positive();
  return h;
}

// What the runner makes Gmsh do itself: these arguments would fight it.
const char *const reserved_gmsh_arguments[] = {"-o", "-order", "-bgm", "-0", "-1", "-2", "-3", "-format", "-save"};

Adaptive parse_adaptive(const Value &v, const std::string &base_dir) {
  Adaptive a;
  if (!v.has("adaptive")) return a;
  Value o = v.child("adaptive");
  o.expect_object({"geo", "target_error", "max_steps", "order", "gmsh_arguments", "aim", "max_refinement",
                   "max_coarsening", "min_size", "max_size", "max_dofs"});
  a.enabled = true;
  a.geo = o.at("geo").string();
  a.geo_path = resolve(base_dir, a.geo);
  if (a.geo_path.find('"') != std::string::npos) o.child("geo").fail("a path with a double quote cannot be handed to Gmsh");
  a.target_error = o.at("target_error").positive();
  if (!(a.target_error < 1))
    o.child("target_error").fail("is a relative error: must be in (0, 1) (0.01 = 1 %), got " +
                                 o.child("target_error").describe());
  if (o.has("max_steps")) a.max_steps = o.child("max_steps").integer_in(0, 100);
  if (o.has("order")) a.order = o.child("order").integer_in(1, 2);
  if (o.has("gmsh_arguments"))
    for (const Value &arg : o.child("gmsh_arguments").items()) {
      a.gmsh_arguments.push_back(arg.string());
      for (const char *r : reserved_gmsh_arguments)
        if (a.gmsh_arguments.back() == r)
          arg.fail(std::string("the runner sets ") + r + " itself (the mesh file, its dimension, format and order: "
                   "use adaptive.order for -order)");
    }
  if (o.has("aim")) {
    a.aim = o.child("aim").positive();
    if (!(a.aim <= 1)) o.child("aim").fail("must be in (0, 1], got " + o.child("aim").describe());
  }
  if (o.has("max_refinement")) {
    a.max_refinement = o.child("max_refinement").positive();
    if (!(a.max_refinement > 1)) o.child("max_refinement").fail("must be > 1, got " + o.child("max_refinement").describe());
  }
  if (o.has("max_coarsening")) {
    a.max_coarsening = o.child("max_coarsening").positive();
    if (!(a.max_coarsening >= 1)) o.child("max_coarsening").fail("must be >= 1, got " + o.child("max_coarsening").describe());
  }
  if (o.has("min_size")) a.min_size = o.child("min_size").positive();
  if (o.has("max_size")) a.max_size = o.child("max_size").positive();
  if (a.min_size > 0 && a.max_size > 0 && !(a.min_size < a.max_size))
    o.child("max_size").fail("must be larger than adaptive.min_size");
  if (o.has("max_dofs")) a.max_dofs = o.child("max_dofs").positive_integer();
  return a;
}

}  // namespace

Scene parse_scene(const std::string &text, const std::string &path) {
  const json root = parse_json(text, path);
  const Value v(root, "", path);
  v.expect_object({"description", "plane", "thickness", "bodies", "pairs", "friction", "load_steps", "solver", "output",
                   "analytic", "adaptive"});
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  Scene s;
  s.path = path;
  if (v.has("description")) s.description = v.child("description").string();
  s.plane = v.has("plane") ? v.child("plane").choice({{"strain", MC_PLANE_STRAIN},
                                                      {"stress", MC_PLANE_STRESS},
                                                      {"axisymmetric", MC_AXISYMMETRIC}})
                           : MC_PLANE_STRAIN;
  if (s.plane == MC_AXISYMMETRIC && v.has("thickness"))
    v.child("thickness").fail("an axisymmetric scene has no thickness (x is the radius, forces are totals over the turn)");
  s.thickness = v.has("thickness") ? v.child("thickness").positive() : 1.0;
  std::vector<Value> bodies = v.at("bodies").items();
  s.has_pairs = v.has("pairs");
  if (!s.has_pairs && bodies.size() != 2)
    v.child("bodies").fail("must list exactly two bodies (body 1, the non-mortar side, first), got " +
                           std::to_string(bodies.size()) + "; a scene of other than two bodies names its contact "
                           "surfaces in a \"pairs\" list");
  if (bodies.size() < 2 || bodies.size() > 10000)
    v.child("bodies").fail("must list 2 to 10000 bodies, got " + std::to_string(bodies.size()));
  for (size_t b = 0; b < bodies.size(); ++b) s.bodies.push_back(parse_body(bodies[b], int(b), base_dir, s.has_pairs));
  // Bodies from one file need their surface groups, or each would take every cell.
  for (size_t b = 1; b < s.bodies.size(); ++b)
    for (size_t a = 0; a < b; ++a)
      if (std::filesystem::path(s.bodies[a].mesh_path).lexically_normal() ==
              std::filesystem::path(s.bodies[b].mesh_path).lexically_normal() &&
          (s.bodies[a].domain.empty() || s.bodies[b].domain.empty()))
        v.child(s.bodies[a].domain.empty() ? s.bodies[a].key + ".domain" : s.bodies[b].key + ".domain")
            .fail("missing: both bodies use the mesh " + s.bodies[a].mesh + " (" + s.bodies[a].key + " and " +
                  s.bodies[b].key + "), so each must name its physical surface group");
  if (s.has_pairs) {
    std::vector<Value> pairs = v.child("pairs").items();
    if (pairs.empty()) v.child("pairs").fail("must list at least one contact pair");
    for (size_t k = 0; k < pairs.size(); ++k) s.pairs.push_back(parse_pair(pairs[k], int(k + 1), int(s.bodies.size())));
  } else {  // today's two-body scene: pair 1, body 1 on body 2, from the bodies' "contact"
    Pair p;
    p.key = "bodies";
    p.nonmortar_surface = s.bodies[0].contact;
    p.mortar_surface = s.bodies[1].contact;
    p.nonmortar_key = "bodies[0].contact";
    p.mortar_key = "bodies[1].contact";
    p.has_gap_offset = s.bodies[0].has_gap_offset;
    p.gap_offset = s.bodies[0].gap_offset;
    p.gap_offset_key = "bodies[0].gap_offset";
    p.implied = true;
    if (v.has("friction")) parse_friction(v.child("friction"), p);
    s.pairs.push_back(p);
  }
  if (s.has_pairs && v.has("friction"))
    v.child("friction").fail("the scene lists \"pairs\": give each pair its friction (pairs[].friction)");
  if (v.has("load_steps")) s.load_steps = v.child("load_steps").integer_in(1, 1000000);
  s.solver = parse_solver(v);
  s.output = parse_output(v, base_dir);
  s.hertz = parse_analytic(v);
  if (s.hertz.enabled && s.bodies.size() != 2)
    v.child("analytic").fail("the Hertz check compares two bodies in contact, the scene has " +
                             std::to_string(s.bodies.size()));
  s.adaptive = parse_adaptive(v, base_dir);
  if (s.adaptive.enabled && s.bodies.size() != 2)
    v.child("adaptive").fail("adaptive refinement handles scenes of two bodies for now, the scene has " +
                             std::to_string(s.bodies.size()));
  if (s.adaptive.enabled) {
    // One .geo gives one mesh: both bodies are taken out of it, each by its surface group.
    if (std::filesystem::path(s.bodies[0].mesh_path).lexically_normal() !=
        std::filesystem::path(s.bodies[1].mesh_path).lexically_normal())
      v.child("bodies[1].mesh").fail("adaptive refinement meshes adaptive.geo into one file for both bodies: name the "
                                     "same mesh as bodies[0].mesh (" + s.bodies[0].mesh + "), each body with its domain");
    if (!s.solver.error_estimate)
      v.child("solver.error_estimate").fail("adaptive refinement needs the error estimate: leave it true");
  }
  return s;
}

bool has_friction(const Scene &scene) {
  for (const Pair &p : scene.pairs)
    if (p.friction_law != MC_FRICTION_NONE) return true;
  return false;
}

Scene load_scene(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path);
}

}  // namespace mcrun
