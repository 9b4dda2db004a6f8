// The C API of contact: the candidate surfaces (edges given by their corners, or with their
// middles), the host's gap offsets, and the results at body 1's contact positions.
#include "capi/capi_support.hpp"
#include "contact/contact_geometry.hpp"
#include "contact/host_contact_edges.hpp"
#include "bodies/plane_vectors.hpp"
#include <algorithm>
#include <cstdio>
#include <cstring>

using namespace mc::capi;

namespace {

// Consecutive contact edges turning by more than this fold back on themselves (mc_set_contact).
constexpr double kFoldAngleDegrees = 175;

// "edges[6..7] = (4, 5)" in base 0, "edges(7:8) = (4, 5)" in base 1 (or with three ids for a
// curved edge): edge e as the caller gave it, its position in the model's index base.
std::string edge_text(const mc_int *edges, int per_edge, size_t e, int base) {
  char text[160];
  const mc_int *v = edges + per_edge * e;
  const std::string where = mc::array_range("edges", per_edge * e, per_edge * e + per_edge - 1, base);
  if (per_edge == 2)
    std::snprintf(text, sizeof text, "%s = (%d, %d)", where.c_str(), int(v[0]), int(v[1]));
  else
    std::snprintf(text, sizeof text, "%s = (%d, %d, %d)", where.c_str(), int(v[0]), int(v[1]), int(v[2]));
  return text;
}

// A host body's contact edges as given (ids 0-based; per_edge 2, or 3 for curved edges):
// oriented by the host with the body on their left. Every node needs an equation in x or y.
// Curved edges have no cells to be checked against: their nodes' positions and roles are
// checked instead, and a surface given (corner, middle, corner) throughout is reordered
// (host_contact_edges.hpp), which the log says.
std::vector<mc::SurfaceSegment> host_surface(const mc::Model &model, int body, std::vector<int> &ids, int per_edge,
                                             const mc_int *edges, int n_edges) {
  const mc::Body &b = model.body[body - 1];
  const int base = model.index_base;
  for (int e = 0; e < n_edges; ++e) {
    const int *v = ids.data() + per_edge * size_t(e);
    for (int k = 0; k < per_edge; ++k)
      if (b.host_data.equation(v[k], 0) < 0 && b.host_data.equation(v[k], 1) < 0)
        fail(MC_ERROR_CONTACT, "%s: node %d has no equation (mc_set_host_body): a contact node needs a freedom in x or y",
             edge_text(edges, per_edge, e, base).c_str(), v[k] + base);
    if (v[0] == v[1] || (per_edge == 3 && (v[2] == v[0] || v[2] == v[1])))
      fail(MC_ERROR_CONTACT, "%s uses a node twice", edge_text(edges, per_edge, e, base).c_str());
  }
  if (per_edge == 3) {
    auto describe = [&](int e) { return edge_text(edges, 3, size_t(e), base); };
    if (mc::order_host_curved_edges(b.mesh, ids, base, describe))
      model.progress(MC_LOG_PHASE,
                     "body %d: its %d curved contact edges were given as (corner, middle, corner), as Smith and "
                     "Griffiths' 8-node quadrilateral numbers a side, and none as (end, end, middle): taken as "
                     "(end, end, middle), the first as (%d, %d, %d)",
                     body, n_edges, ids[0] + base, ids[1] + base, ids[2] + base);
  }
  std::vector<mc::SurfaceSegment> surface;
  std::vector<std::pair<int, int>> seen;
  for (int e = 0; e < n_edges; ++e) {
    const int *v = ids.data() + per_edge * size_t(e);
    surface.push_back({v[0], v[1], per_edge == 3 ? v[2] : -1});
    seen.push_back({std::min(v[0], v[1]), std::max(v[0], v[1])});
  }
  std::sort(seen.begin(), seen.end());
  auto dup = std::adjacent_find(seen.begin(), seen.end());
  if (dup != seen.end())
    fail(MC_ERROR_CONTACT, "edge (%d, %d) is given twice", dup->first + model.index_base, dup->second + model.index_base);
  return surface;
}

// A body's contact edges as given (2 ids per edge, or 3: end, end, middle), checked and
// oriented: mc_set_contact, mc_set_contact_curved and the pairs' mc_set_pair_surface*.
std::vector<mc::SurfaceSegment> checked_surface(mc::Model &model, int body, mc_int n_edges, const mc_int *edges,
                                                int per_edge) {
  mc::Body &b = meshed_body(model, body);
  if (n_edges < 1) fail(MC_ERROR_ARGUMENT, "n_edges = %d: a contact surface needs at least one edge", int(n_edges));
  require_pointer(edges, "edges");
  std::vector<int> local(per_edge * size_t(n_edges));
  for (size_t k = 0; k < local.size(); ++k) {
    const long long id = (long long)edges[k] - model.index_base;  // no int overflow for INT_MIN
    const size_t e = k / per_edge;
    if (id < 0 || id >= b.mesh.n_nodes())
      fail(MC_ERROR_ARGUMENT, "%s: %s = %d: node id out of range [%d, %d] (index base %d)",
           edge_text(edges, per_edge, e, model.index_base).c_str(), mc::array_position("edges", k, model.index_base).c_str(),
           int(edges[k]), model.index_base,
           b.mesh.n_nodes() - 1 + model.index_base, model.index_base);
    local[k] = int(id);
  }
  std::vector<mc::SurfaceSegment> surface;
  if (b.host) {
    surface = host_surface(model, body, local, per_edge, edges, n_edges);
  } else {
    surface = mc::oriented_surface(b.mesh, local.data(), per_edge, n_edges, model.index_base);
    if (per_edge == 3) {
      if (!b.mesh.quadratic())
        fail(MC_ERROR_CONTACT, "body %d has linear cells, whose edges have no middle node: give its contact edges by "
             "their two nodes (mc_set_contact)", body);
      for (mc_int e = 0; e < n_edges; ++e)
        if (surface[e].mid != local[3 * e + 2])
          fail(MC_ERROR_CONTACT, "%s: node %d is not the middle of that edge, whose cell has node %d there",
               edge_text(edges, 3, e, model.index_base).c_str(), int(edges[3 * e + 2]), surface[e].mid + model.index_base);
    }
  }
  // Simple chains and loops only: at most one surface edge leaves and one arrives at a node.
  // Two would mean cells meeting at that node alone (a pinch), where the surface has no
  // normal and its chains no order.
  std::vector<int> leaving(b.mesh.n_nodes(), -1), arriving(b.mesh.n_nodes(), -1);
  for (mc_int e = 0; e < n_edges; ++e) {
    const mc::SurfaceSegment &seg = surface[e];
    const int other = leaving[seg.a] >= 0 ? leaving[seg.a] : arriving[seg.b];
    if (other >= 0)
      fail(MC_ERROR_CONTACT, "%s and %s both %s node %d: cells meet only at that node, a contact surface must be "
           "simple chains or loops", edge_text(edges, per_edge, e, model.index_base).c_str(),
           edge_text(edges, per_edge, other, model.index_base).c_str(),
           leaving[seg.a] >= 0 ? "leave" : "arrive at", (leaving[seg.a] >= 0 ? seg.a : seg.b) + model.index_base);
    leaving[seg.a] = arriving[seg.b] = int(e);
  }
  // A chain that folds back on itself (consecutive edges turning by nearly 180 degrees) has no
  // normal where it turns and its two faces overlap: no contact surface.
  for (int node = 0; node < b.mesh.n_nodes(); ++node) {
    const int in = arriving[node], out = leaving[node];
    if (in < 0 || out < 0) continue;
    const double turn = mc::turn_angle(b.mesh.node(surface[in].a), b.mesh.node(node), b.mesh.node(surface[out].b)) *
                        180 / 3.14159265358979323846;
    if (std::fabs(turn) > kFoldAngleDegrees)
      fail(MC_ERROR_CONTACT, "%s and %s fold back at node %d: the surface turns by %.1f degrees there (more than %.0f): "
           "a contact surface must not fold back on itself", edge_text(edges, per_edge, in, model.index_base).c_str(),
           edge_text(edges, per_edge, out, model.index_base).c_str(), node + model.index_base, turn, kFoldAngleDegrees);
  }
  return surface;
}

// Sets one side of pair p (0-based) to the body's checked edges.
void set_pair_side(mc::Model &model, int p, int body, mc_int n_edges, const mc_int *edges, int per_edge) {
  mc::ContactPair &pair = model.pairs[p];
  const long long b = (long long)body - 1;  // (body may be any int: INT_MIN - 1 overflowed, a fuzz finding)
  if (b != pair.nonmortar && b != pair.mortar)
    fail(MC_ERROR_ARGUMENT, "body = %d: pair %d joins bodies %d (non-mortar) and %d (mortar)", body, p + 1,
         pair.nonmortar + 1, pair.mortar + 1);
  const int side = b == pair.nonmortar ? 0 : 1;
  pair.side[side] = checked_surface(model, body, n_edges, edges, per_edge);
  pair.has_side[side] = true;
  model.structure_changed();
}

// The two-body calls act on pair 1, made as (non-mortar 1, mortar 2) by the first of them.
int legacy_pair(mc::Model &model, const char *call, bool make) {
  if (model.pairs.empty()) {
    if (!make) fail(MC_ERROR_STATE, "body 1 has no contact surface: call mc_set_contact first");
    model.pairs.push_back(mc::ContactPair{});
  }
  const mc::ContactPair &pair = model.pairs[0];
  if (pair.nonmortar != 0 || pair.mortar != 1)
    fail(MC_ERROR_STATE, "%s acts on pair 1 as (non-mortar body 1, mortar body 2), and this model's pair 1 joins "
         "bodies %d and %d: use the pair calls (mc_set_pair_surface, mc_set_pair_gap_offset, mc_get_pair_contact)",
         call, pair.nonmortar + 1, pair.mortar + 1);
  return 0;
}

void set_contact_surface(mc::Model &model, int body, mc_int n_edges, const mc_int *edges, int per_edge) {
  const int b = body_index(model, body);
  if (b > 1)
    fail(MC_ERROR_ARGUMENT, "body = %d: mc_set_contact acts on pair 1, between bodies 1 and 2; make a pair with "
         "mc_add_contact_pair and give its sides with mc_set_pair_surface", body);
  meshed_body(model, body);  // (the mesh is checked before a pair is made)
  set_pair_side(model, legacy_pair(model, per_edge == 2 ? "mc_set_contact" : "mc_set_contact_curved", true), body,
                n_edges, edges, per_edge);
}

// The initial-gap offsets of pair p's non-mortar nodes.
// legacy: called as mc_set_gap_offset, whose messages speak of body 1's contact surface.
void set_pair_gap_offset(mc::Model &model, int p, mc_int n, const mc_int *nodes, const double *offset, bool legacy) {
  mc::ContactPair &pair = model.pairs[p];
  const int body = pair.nonmortar + 1;
  mc::Body &b = meshed_body(model, body);
  if (!pair.has_side[0]) {
    if (legacy)
      fail(MC_ERROR_STATE, "body 1 has no contact surface: call mc_set_contact first");
    fail(MC_ERROR_STATE, "pair %d has no non-mortar surface (body %d): call mc_set_pair_surface first", p + 1, body);
  }
  require_count(n, "n");
  if (n > 0) require_pointer(nodes, "nodes"), require_pointer(offset, "offset");
  if (n > 0) require_finite(offset, size_t(n), "offset", model.index_base);
  std::vector<char> on_surface(b.mesh.n_nodes(), 0);
  for (const mc::SurfaceSegment &s : pair.side[0]) {
    on_surface[s.a] = on_surface[s.b] = 1;
    if (s.mid >= 0) on_surface[s.mid] = 1;
  }
  std::vector<int> local(n);
  for (mc_int i = 0; i < n; ++i) {
    local[i] = node_id(model, b.mesh, nodes[i], "nodes", size_t(i));
    if (!on_surface[local[i]]) {
      if (legacy)
        fail(MC_ERROR_ARGUMENT, "%s = %d is not on body 1's contact surface",
             mc::array_position("nodes", size_t(i), model.index_base).c_str(), int(nodes[i]));
      fail(MC_ERROR_ARGUMENT, "%s = %d is not on pair %d's non-mortar surface (body %d)",
           mc::array_position("nodes", size_t(i), model.index_base).c_str(), int(nodes[i]), p + 1, body);
    }
  }
  if (pair.gap_offset.empty()) pair.gap_offset.assign(b.mesh.n_nodes(), 0.0);
  for (mc_int i = 0; i < n; ++i) pair.gap_offset[local[i]] = offset[i];
  model.values_changed();
}

}  // namespace

extern "C" {

mc_status mc_set_contact(mc_model *m, int body, mc_int n_edges, const mc_int *edges) {
  return guard(m, [&](mc::Model &model) { set_contact_surface(model, body, n_edges, edges, 2); });
}

mc_status mc_set_contact_curved(mc_model *m, int body, mc_int n_edges, const mc_int *edges) {
  return guard(m, [&](mc::Model &model) { set_contact_surface(model, body, n_edges, edges, 3); });
}

mc_status mc_set_gap_offset(mc_model *m, mc_int n, const mc_int *nodes, const double *offset) {
  return guard(m, [&](mc::Model &model) {
    meshed_body(model, 1);
    set_pair_gap_offset(model, legacy_pair(model, "mc_set_gap_offset", false), n, nodes, offset, true);
  });
}

mc_status mc_set_body_count(mc_model *m, int n) {
  return guard(m, [&](mc::Model &model) {
    if (n < 2) fail(MC_ERROR_ARGUMENT, "n = %d: a model has at least 2 bodies", n);
    for (size_t p = 0; p < model.pairs.size(); ++p)
      for (int side = 0; side < 2; ++side)
        if (model.pairs[p].body_of_side(side) >= n)
          fail(MC_ERROR_STATE, "n = %d: pair %zu uses body %d", n, p + 1, model.pairs[p].body_of_side(side) + 1);
    if (n != model.n_bodies()) {
      model.body.resize(size_t(n));
      model.structure_changed();
    }
  });
}

mc_status mc_add_contact_pair(mc_model *m, int nonmortar_body, int mortar_body, int *pair) {
  return guard(m, [&](mc::Model &model) {
    require_pointer(pair, "pair");
    auto check = [&](int body, const char *name) {
      if (body < 1 || body > model.n_bodies())
        fail(MC_ERROR_ARGUMENT, "%s = %d: must be 1 to %d (mc_set_body_count)", name, body, model.n_bodies());
    };
    check(nonmortar_body, "nonmortar_body");
    check(mortar_body, "mortar_body");
    if (nonmortar_body == mortar_body)
      fail(MC_ERROR_ARGUMENT, "nonmortar_body = mortar_body = %d: a pair joins two different bodies (no self-contact)",
           nonmortar_body);
    mc::ContactPair made;
    made.nonmortar = nonmortar_body - 1, made.mortar = mortar_body - 1;
    model.pairs.push_back(made);
    *pair = int(model.pairs.size());
    model.structure_changed();
  });
}

mc_status mc_set_pair_surface(mc_model *m, int pair, int body, mc_int n_edges, const mc_int *edges) {
  return guard(m, [&](mc::Model &model) { set_pair_side(model, pair_index(model, pair), body, n_edges, edges, 2); });
}

mc_status mc_set_pair_surface_curved(mc_model *m, int pair, int body, mc_int n_edges, const mc_int *edges) {
  return guard(m, [&](mc::Model &model) { set_pair_side(model, pair_index(model, pair), body, n_edges, edges, 3); });
}

mc_status mc_set_pair_gap_offset(mc_model *m, int pair, mc_int n, const mc_int *nodes, const double *offset) {
  return guard(m, [&](mc::Model &model) { set_pair_gap_offset(model, pair_index(model, pair), n, nodes, offset, false); });
}

}  // extern "C"

namespace {

// The positions of pair p (0-based) after a solve, checked.
const std::vector<int> &solved_pair_positions(const mc::Model &model, int p) {
  if (!model.solved || !model.contact())
    fail(MC_ERROR_STATE, "no solution: call mc_solve first (or again, after changing the scene)");
  if (!model.pairs[p].complete())
    fail(MC_ERROR_STATE, "pair %d has no surface on %s: give both its sides (mc_set_pair_surface), then mc_solve", p + 1,
         model.pairs[p].has_side[0] ? "its mortar side" : "its non-mortar side");
  return model.contact()->pair_positions[p];
}

// Pair 1 for the two-body getters, with their messages.
const std::vector<int> &legacy_positions(const mc::Model &model) {
  if (!model.contact_active() || model.pairs.empty())
    fail(MC_ERROR_STATE, "no contact surfaces: call mc_set_contact on both bodies");
  if (model.pairs[0].nonmortar != 0 || model.pairs[0].mortar != 1)
    fail(MC_ERROR_STATE, "the mc_get_contact_* getters read pair 1 as (non-mortar body 1, mortar body 2), and this "
         "model's pair 1 joins bodies %d and %d: use mc_get_pair_contact", model.pairs[0].nonmortar + 1,
         model.pairs[0].mortar + 1);
  return solved_pair_positions(model, 0);
}

void check_field(int field) {
  if (field < MC_CONTACT_PRESSURE || field > MC_CONTACT_STATE)
    fail(MC_ERROR_ARGUMENT, "field = %d: must be MC_CONTACT_PRESSURE (1), _FORCE (2), _GAP (3), _INITIAL_GAP (4), "
         "_NORMAL (5), _SHEAR (6), _SLIP (7), _SLIP_TOTAL (8) or _STATE (9)", field);
}

// One field at the given positions (MC_CONTACT_NORMAL: 2 per position).
void copy_field(const mc::Model &model, const std::vector<int> &positions, int field, double *out) {
  for (size_t j = 0; j < positions.size(); ++j) {
    const int pos = positions[j];
    switch (field) {
      case MC_CONTACT_PRESSURE: out[j] = model.contact_pressure[pos]; break;
      case MC_CONTACT_FORCE: out[j] = model.contact_force[pos]; break;
      case MC_CONTACT_GAP: out[j] = model.contact_gap[pos]; break;
      case MC_CONTACT_INITIAL_GAP: out[j] = model.initial_gap(size_t(pos)); break;
      case MC_CONTACT_NORMAL: {
        const mc::ContactGroup &group = model.contact()->group_of_position(pos);
        const mc::Point n = group.geometry.normals[pos - group.first_position];
        out[2 * j] = n.x, out[2 * j + 1] = n.y;
        break;
      }
      case MC_CONTACT_SHEAR: out[j] = model.contact_shear[pos]; break;
      case MC_CONTACT_SLIP: out[j] = model.contact_slip[pos]; break;
      case MC_CONTACT_SLIP_TOTAL: out[j] = model.contact_slip_total[pos]; break;
      case MC_CONTACT_STATE: out[j] = double(model.contact_state[pos]); break;
      default:
        check_field(field);
    }
  }
}


template <class F>
mc_status legacy_array(const mc_model *m, void *out, const char *name, F &&copy) {
  return guard_const(m, [&](const mc::Model &model) {
    const std::vector<int> &positions = legacy_positions(model);
    require_pointer(out, name);
    copy(model, positions);
  });
}

}  // namespace

extern "C" {

mc_status mc_get_contact_count(const mc_model *m, mc_int *n) {
  return legacy_array(m, n, "n", [&](const mc::Model &, const std::vector<int> &pos) { *n = mc_int(pos.size()); });
}

mc_status mc_get_contact_nodes(const mc_model *m, mc_int *nodes) {
  return legacy_array(m, nodes, "nodes", [&](const mc::Model &model, const std::vector<int> &pos) {
    for (size_t j = 0; j < pos.size(); ++j) nodes[j] = mc_int(model.position_node(size_t(pos[j])) + model.index_base);
  });
}

mc_status mc_get_contact_pressure(const mc_model *m, double *p) {
  return legacy_array(m, p, "p", [&](const mc::Model &model, const std::vector<int> &pos) {
    copy_field(model, pos, MC_CONTACT_PRESSURE, p);
  });
}

mc_status mc_get_contact_force(const mc_model *m, double *f) {
  return legacy_array(m, f, "f", [&](const mc::Model &model, const std::vector<int> &pos) {
    copy_field(model, pos, MC_CONTACT_FORCE, f);
  });
}

mc_status mc_get_contact_gap(const mc_model *m, double *g) {
  return legacy_array(m, g, "g", [&](const mc::Model &model, const std::vector<int> &pos) {
    copy_field(model, pos, MC_CONTACT_GAP, g);
  });
}

mc_status mc_get_contact_initial_gap(const mc_model *m, double *g0) {
  return legacy_array(m, g0, "g0", [&](const mc::Model &model, const std::vector<int> &pos) {
    copy_field(model, pos, MC_CONTACT_INITIAL_GAP, g0);
  });
}

mc_status mc_get_contact_normal(const mc_model *m, double *n) {
  return legacy_array(m, n, "n", [&](const mc::Model &model, const std::vector<int> &pos) {
    copy_field(model, pos, MC_CONTACT_NORMAL, n);
  });
}

mc_status mc_set_friction(mc_model *m, int pair, int law, double value) {
  return guard(m, [&](mc::Model &model) {
    if (model.pairs.empty())
      fail(MC_ERROR_STATE, "the model has no contact pair: make one (mc_set_contact or mc_add_contact_pair) before "
           "setting its friction");
    const int p = pair_index(model, pair);
    if (law != MC_FRICTION_NONE && law != MC_FRICTION_TRESCA && law != MC_FRICTION_COULOMB)
      fail(MC_ERROR_ARGUMENT, "law = %d: must be MC_FRICTION_NONE (0), MC_FRICTION_TRESCA (1) or MC_FRICTION_COULOMB (2)",
           law);
    if (!(value >= 0 && std::isfinite(value)))
      fail(MC_ERROR_ARGUMENT, "value = %g: %s must be finite and >= 0", value,
           law == MC_FRICTION_TRESCA ? "the Tresca slip bound" : law == MC_FRICTION_COULOMB ? "mu" : "the value");
    mc::ContactPair &c = model.pairs[p];
    const bool had = c.friction_law != MC_FRICTION_NONE, has = law != MC_FRICTION_NONE;
    c.friction_law = law, c.friction_value = has ? value : 0;
    if (had != has) model.structure_changed();  // tangential rows come or go
    else model.values_changed();
  });
}

mc_status mc_reset_history(mc_model *m) {
  return guard(m, [&](mc::Model &model) {
    model.reset_history();
    model.values_changed();
  });
}

mc_status mc_get_pair_contact_count(const mc_model *m, int pair, mc_int *n) {
  return guard_const(m, [&](const mc::Model &model) {
    const std::vector<int> &positions = solved_pair_positions(model, pair_index(model, pair));
    require_pointer(n, "n");
    *n = mc_int(positions.size());
  });
}

mc_status mc_get_pair_contact_nodes(const mc_model *m, int pair, mc_int *nodes) {
  return guard_const(m, [&](const mc::Model &model) {
    const std::vector<int> &positions = solved_pair_positions(model, pair_index(model, pair));
    require_pointer(nodes, "nodes");
    for (size_t j = 0; j < positions.size(); ++j)
      nodes[j] = mc_int(model.position_node(size_t(positions[j])) + model.index_base);
  });
}

mc_status mc_get_pair_contact(const mc_model *m, int pair, int field, double *out) {
  return guard_const(m, [&](const mc::Model &model) {
    const int p = pair_index(model, pair);
    check_field(field);
    const std::vector<int> &positions = solved_pair_positions(model, p);
    require_pointer(out, "out");
    copy_field(model, positions, field, out);
  });
}

}  // extern "C"
