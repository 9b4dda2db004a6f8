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

// mc_set_contact (2 ids per edge) and mc_set_contact_curved (3: end, end, middle).
void set_contact_surface(mc::Model &model, int body, mc_int n_edges, const mc_int *edges, int per_edge) {
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
  b.contact = std::move(surface);
  b.has_contact = true;
  model.structure_changed();
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
    mc::Body &b = meshed_body(model, 1);
    if (!b.has_contact) fail(MC_ERROR_STATE, "body 1 has no contact surface: call mc_set_contact first");
    require_count(n, "n");
    if (n > 0) require_pointer(nodes, "nodes"), require_pointer(offset, "offset");
    if (n > 0) require_finite(offset, size_t(n), "offset", model.index_base);
    std::vector<char> on_surface(b.mesh.n_nodes(), 0);
    for (const mc::SurfaceSegment &s : b.contact) {
      on_surface[s.a] = on_surface[s.b] = 1;
      if (s.mid >= 0) on_surface[s.mid] = 1;
    }
    std::vector<int> local(n);
    for (mc_int i = 0; i < n; ++i) {
      local[i] = node_id(model, b.mesh, nodes[i], "nodes", size_t(i));
      if (!on_surface[local[i]])
        fail(MC_ERROR_ARGUMENT, "%s = %d is not on body 1's contact surface",
             mc::array_position("nodes", size_t(i), model.index_base).c_str(), int(nodes[i]));
    }
    if (b.gap_offset.empty()) b.gap_offset.assign(b.mesh.n_nodes(), 0.0);
    for (mc_int i = 0; i < n; ++i) b.gap_offset[local[i]] = offset[i];
    model.values_changed();
  });
}

}  // extern "C"

namespace {

const mc::ContactGeometry &solved_contact(const mc::Model &model) {
  if (!model.contact_active()) fail(MC_ERROR_STATE, "no contact surfaces: call mc_set_contact on both bodies");
  if (!model.solved || !model.contact())
    fail(MC_ERROR_STATE, "no solution: call mc_solve first (or again, after changing the scene)");
  return model.contact()->geometry;
}

template <class F>
mc_status contact_array(const mc_model *m, void *out, const char *name, F &&copy) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::ContactGeometry &g = solved_contact(model);
    require_pointer(out, name);
    copy(model, g);
  });
}

}  // namespace

extern "C" {

mc_status mc_get_contact_count(const mc_model *m, mc_int *n) {
  return contact_array(m, n, "n", [&](const mc::Model &, const mc::ContactGeometry &g) { *n = mc_int(g.nodes.size()); });
}

mc_status mc_get_contact_nodes(const mc_model *m, mc_int *nodes) {
  return contact_array(m, nodes, "nodes", [&](const mc::Model &model, const mc::ContactGeometry &g) {
    for (size_t j = 0; j < g.nodes.size(); ++j) nodes[j] = mc_int(g.nodes[j] + model.index_base);
  });
}

mc_status mc_get_contact_pressure(const mc_model *m, double *p) {
  return contact_array(m, p, "p", [&](const mc::Model &model, const mc::ContactGeometry &) {
    std::memcpy(p, model.contact_pressure.data(), model.contact_pressure.size() * sizeof(double));
  });
}

mc_status mc_get_contact_force(const mc_model *m, double *f) {
  return contact_array(m, f, "f", [&](const mc::Model &model, const mc::ContactGeometry &) {
    std::memcpy(f, model.contact_force.data(), model.contact_force.size() * sizeof(double));
  });
}

mc_status mc_get_contact_gap(const mc_model *m, double *g) {
  return contact_array(m, g, "g", [&](const mc::Model &model, const mc::ContactGeometry &) {
    std::memcpy(g, model.contact_gap.data(), model.contact_gap.size() * sizeof(double));
  });
}

mc_status mc_get_contact_initial_gap(const mc_model *m, double *g0) {
  return contact_array(m, g0, "g0", [&](const mc::Model &model, const mc::ContactGeometry &g) {
    for (size_t j = 0; j < g.gap0.size(); ++j) g0[j] = model.initial_gap(j);
  });
}

mc_status mc_get_contact_normal(const mc_model *m, double *n) {
  return contact_array(m, n, "n", [&](const mc::Model &, const mc::ContactGeometry &g) {
    for (size_t j = 0; j < g.normals.size(); ++j) n[2 * j] = g.normals[j].x, n[2 * j + 1] = g.normals[j].y;
  });
}

}  // extern "C"
