// The C API: argument checks with messages naming the argument and index, the index base,
// and the boundary no C++ exception crosses. Every entry point follows one pattern: run the
// body inside guard(), which turns an mc::Error (or any other exception) into a status and
// the model's message.
#include "capi/capi_support.hpp"
#include "bodies/cell_shapes.hpp"
#include "bodies/plane_vectors.hpp"
#include "results/vtu_writer.hpp"
#include <algorithm>
#include <cfloat>
#include <cstring>

using namespace mc::capi;

namespace {

using mc::fail;

// In an axisymmetric model x is the radius: no node may lie left of the axis.
void require_radii(const mc::Mesh &mesh, int body, int base, const char *what) {
  const int i = mc::first_node_left_of_axis(mesh);
  if (i >= 0)
    fail(MC_ERROR_MESH,
         "%s = %g (node %d of body %d): a radius must be >= 0, and %s is axisymmetric (x = r, the axis x = 0)",
         mc::array_position("xy", 2 * size_t(i), base).c_str(), mesh.node(i).x, i + base, body, what);
}

// Edges for loads: boundary edges, returned oriented as their cells.
std::vector<mc::SurfaceSegment> load_edges(const mc::Model &model, const mc::Mesh &mesh, mc_int n, const mc_int *edges) {
  std::vector<mc::SurfaceSegment> out;
  for (mc_int e = 0; e < n; ++e) {
    int a = node_id(model, mesh, edges[2 * e], "edges", 2 * size_t(e));
    int b = node_id(model, mesh, edges[2 * e + 1], "edges", 2 * size_t(e) + 1);
    const mc::BoundaryEdge *edge = mesh.boundary_edge(a, b);
    char hint[160];
    if (!edge)
      fail(MC_ERROR_MESH, "%s = (%d, %d) is not an edge on the boundary of the mesh%s",
           mc::array_range("edges", 2 * size_t(e), 2 * size_t(e) + 1, model.index_base).c_str(), int(edges[2 * e]), int(edges[2 * e + 1]), mesh.edge_hint(a, b, model.index_base, hint, 160));
    out.push_back({edge->from, edge->to});
  }
  return out;
}

// A symmetric positive definite 3x3 matrix (Cholesky succeeds with positive pivots).
bool symmetric_positive_definite(const double *d) {
  double scale = 0;
  for (int i = 0; i < 9; ++i) scale = std::max(scale, std::fabs(d[i]));
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::fabs(d[3 * i + j] - d[3 * j + i]) > 1e-12 * scale) return false;
  double l00 = d[0];
  if (!(l00 > 1e-14 * scale)) return false;
  double l10 = d[3] / std::sqrt(l00), l20 = d[6] / std::sqrt(l00);
  double l11sq = d[4] - l10 * l10;
  if (!(l11sq > 1e-14 * scale)) return false;
  double l21 = (d[7] - l20 * l10) / std::sqrt(l11sq);
  return d[8] - l20 * l20 - l21 * l21 > 1e-14 * scale;
}

// Results beyond double range (E, thickness, loads or prescribed values near DBL_MAX, or E so
// small that the displacements overflow) are reported, never returned as inf/NaN with MC_OK.
void require_finite_results(mc::Model &model) {
  auto overflow = [&](const char *what, size_t i, int body, double v) {
    model.solved = false;
    fail(MC_ERROR_ARGUMENT,
         "the solution overflows: %s of body %d is %g; the scene's numbers (Young's moduli, thickness, "
         "loads, prescribed values) are beyond what double precision can solve: rescale the units",
         mc::array_position(what, i, model.index_base).c_str(), body, v);
  };
  for (int b = 0; b < model.n_bodies(); ++b) {
    const mc::Body &body = model.body[b];
    if (!body.has_mesh) continue;
    for (size_t i = 0; i < body.u.size(); ++i) if (!std::isfinite(body.u[i])) overflow("u", i, b + 1, body.u[i]);
    if (model.options.eager_results && !body.host) {  // (else checked when first asked for)
      const std::vector<double> &stress = model.cell_stresses(b);
      for (size_t i = 0; i < stress.size(); ++i)
        if (!std::isfinite(stress[i])) overflow("sigma", i, b + 1, stress[i]);
    }
    for (size_t i = 0; i < body.reaction.size(); ++i)
      if (!std::isfinite(body.reaction[i])) overflow("r", i, b + 1, body.reaction[i]);
  }
  for (size_t j = 0; j < model.contact_force.size(); ++j) {
    const int b = model.contact()->group_of_position(int(j)).nonmortar + 1;
    if (!std::isfinite(model.contact_force[j])) overflow("contact force", j, b, model.contact_force[j]);
    if (!std::isfinite(model.contact_pressure[j])) overflow("contact pressure", j, b, model.contact_pressure[j]);
    // +infinity is the gap of a node that sees no mortar surface
    if (std::isnan(model.contact_gap[j]) || model.contact_gap[j] < -DBL_MAX) overflow("gap", j, b, model.contact_gap[j]);
  }
}

}  // namespace

extern "C" {

mc_status mc_create(mc_model **model) {
  if (!model) return MC_ERROR_ARGUMENT;
  *model = nullptr;
  try {
    *model = new mc_model();
  } catch (...) {
    return MC_ERROR_MEMORY;
  }
  return MC_OK;
}

void mc_destroy(mc_model *model) { delete model; }

const char *mc_errmsg(const mc_model *model) {
  if (!model) return "model is NULL";
  return model->message.c_str();
}

const char *mc_status_string(mc_status status) {
  // A C caller may pass any int: read it as one (loading an mc_status outside the enum's
  // range is undefined behaviour in C++).
  int code;
  static_assert(sizeof code == sizeof status, "mc_status is int-sized");
  std::memcpy(&code, &status, sizeof code);
  switch (code) {
    case MC_OK: return "MC_OK";
    case MC_ERROR_ARGUMENT: return "MC_ERROR_ARGUMENT";
    case MC_ERROR_MESH: return "MC_ERROR_MESH";
    case MC_ERROR_MATERIAL: return "MC_ERROR_MATERIAL";
    case MC_ERROR_STATE: return "MC_ERROR_STATE";
    case MC_ERROR_CONTACT: return "MC_ERROR_CONTACT";
    case MC_ERROR_SINGULAR: return "MC_ERROR_SINGULAR";
    case MC_ERROR_NOT_CONVERGED: return "MC_ERROR_NOT_CONVERGED";
    case MC_ERROR_MEMORY: return "MC_ERROR_MEMORY";
    case MC_ERROR_INTERNAL: return "MC_ERROR_INTERNAL";
  }
  return "unknown status";
}

const char *mc_version_string(void) { return MC_VERSION_STRING; }
int mc_version_number(void) { return MC_VERSION_NUMBER; }

mc_status mc_set_index_base(mc_model *m, int base) {
  return guard(m, [&](mc::Model &model) {
    if (base != 0 && base != 1) fail(MC_ERROR_ARGUMENT, "base = %d: must be 0 or 1", base);
    model.index_base = base;
  });
}

mc_status mc_set_plane(mc_model *m, int plane, double thickness) {
  return guard(m, [&](mc::Model &model) {
    if (plane != MC_PLANE_STRAIN && plane != MC_PLANE_STRESS && plane != MC_AXISYMMETRIC)
      fail(MC_ERROR_ARGUMENT, "plane = %d: must be MC_PLANE_STRAIN (0), MC_PLANE_STRESS (1) or MC_AXISYMMETRIC (2)",
           plane);
    const bool axisymmetric = plane == MC_AXISYMMETRIC;
    if (!axisymmetric && (!(thickness > 0) || !std::isfinite(thickness)))  // ignored when axisymmetric
      fail(MC_ERROR_ARGUMENT, "thickness = %g: must be positive and finite", thickness);
    if (axisymmetric)
      for (int b = 0; b < model.n_bodies(); ++b)
        if (model.body[b].has_mesh) require_radii(model.body[b].mesh, b + 1, model.index_base, "MC_AXISYMMETRIC");
    model.plane_stress = plane == MC_PLANE_STRESS;
    model.axisymmetric = axisymmetric;
    if (!axisymmetric) model.thickness = thickness;
    model.structure_changed();
  });
}

mc_status mc_set_mesh(mc_model *m, int body, mc_int n_nodes, const double *xy, mc_int n_cells, int nodes_per_cell,
                      const mc_int *cells) {
  return guard(m, [&](mc::Model &model) {
    int b = body_index(model, body);
    require_pointer(xy, "xy");
    require_pointer(cells, "cells");
    require_count(n_nodes, "n_nodes");
    require_count(n_cells, "n_cells");
    if (!mc::is_cell_kind(nodes_per_cell))
      fail(MC_ERROR_ARGUMENT,
           "nodes_per_cell = %d: must be 3 (P1 triangle), 4 (Q1 quadrilateral), 6 (T6 triangle), 8 (Q8 "
           "quadrilateral) or 9 (Q9 quadrilateral)",
           nodes_per_cell);
    // (as mc::Mesh checks them, before the ids, so that counts are reported first)
    if (n_nodes < 3) fail(MC_ERROR_ARGUMENT, "n_nodes = %d: a mesh needs at least 3 nodes", int(n_nodes));
    if (n_cells < 1) fail(MC_ERROR_ARGUMENT, "n_cells = %d: a mesh needs at least 1 cell", int(n_cells));
    std::vector<int> local(size_t(n_cells) * nodes_per_cell);
    for (size_t k = 0; k < local.size(); ++k) {
      const long long id = (long long)cells[k] - model.index_base;  // no int overflow for INT_MIN
      if (id < 0 || id >= n_nodes)
        fail(MC_ERROR_ARGUMENT, "%s = %d (cell %zu): node id out of range [%d, %d)",
             mc::array_position("cells", k, model.index_base).c_str(), int(cells[k]), k / nodes_per_cell + model.index_base, model.index_base, int(n_nodes) + model.index_base);
      local[k] = int(id);
    }
    mc::Body fresh;
    fresh.mesh = mc::Mesh(n_nodes, xy, n_cells, nodes_per_cell, local.data(), model.index_base);
    if (model.axisymmetric) require_radii(fresh.mesh, body, model.index_base, "the model");
    fresh.has_mesh = true;
    fresh.prescribed.assign(2 * size_t(n_nodes), 0);
    fresh.prescribed_value.assign(2 * size_t(n_nodes), 0.0);
    fresh.nodal_force.assign(2 * size_t(n_nodes), 0.0);
    model.body[b] = std::move(fresh);
    forget_contact_surfaces(model, b);
    model.structure_changed();
  });
}

mc_status mc_set_material(mc_model *m, int body, double young, double poisson) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = cell_body(model, body, "mc_set_material", "its stiffness is the host's own (mc_add_stiffness)");
    if (!(young > 0) || !std::isfinite(young))
      fail(MC_ERROR_MATERIAL, "young = %g (body %d): Young's modulus must be positive and finite", young, body);
    if (!(poisson > -1 && poisson < 0.5))
      fail(MC_ERROR_MATERIAL, "poisson = %g (body %d): Poisson's ratio must lie in (-1, 1/2)", poisson, body);
    b.young = young, b.poisson = poisson, b.has_material = true;
    b.cell_elasticity.clear();
    model.structure_changed();
  });
}

mc_status mc_set_cell_elasticity(mc_model *m, int body, const double *d) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = cell_body(model, body, "mc_set_cell_elasticity", "its stiffness is the host's own (mc_add_stiffness)");
    require_pointer(d, "d");
    const size_t n = 9 * size_t(b.mesh.n_cells());
    require_finite(d, n, "d", model.index_base);
    for (int c = 0; c < b.mesh.n_cells(); ++c)
      if (!symmetric_positive_definite(d + 9 * size_t(c)))
        fail(MC_ERROR_MATERIAL, "%s (cell %d of body %d): the elasticity matrix must be symmetric positive definite",
             mc::array_range("d", 9 * size_t(c), 9 * size_t(c) + 8, model.index_base).c_str(), c + model.index_base, body);
    b.cell_elasticity.assign(d, d + n);
    b.has_material = true;
    model.structure_changed();
  });
}

mc_status mc_fix(mc_model *m, int body, mc_int n, const mc_int *nodes, int components, const double *values) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = cell_body(model, body, "mc_fix",
                            "its supports are its restrained freedoms: give them no equation in mc_set_host_body");
    require_count(n, "n");
    if (n > 0) require_pointer(nodes, "nodes");
    if (components < MC_X || components > MC_XY)
      fail(MC_ERROR_ARGUMENT, "components = %d: must be MC_X (1), MC_Y (2) or MC_XY (3)", components);
    if (values)  // only the components in the mask: the others are ignored (header)
      for (size_t k = 0; k < 2 * size_t(n); ++k)
        if ((components & (1 << (k % 2))) && !std::isfinite(values[k]))
          fail(MC_ERROR_ARGUMENT, "%s is not finite", mc::array_position("values", k, model.index_base).c_str());
    std::vector<int> local(n);
    for (mc_int i = 0; i < n; ++i) local[i] = node_id(model, b.mesh, nodes[i], "nodes", size_t(i));
    bool new_support = false;
    for (mc_int i = 0; i < n; ++i)
      for (int c = 0; c < 2; ++c) {
        if (!(components & (1 << c))) continue;
        int dof = 2 * local[i] + c;
        new_support = new_support || !b.prescribed[dof];
        b.prescribed[dof] = 1;
        b.prescribed_value[dof] = values ? values[2 * size_t(i) + c] : 0.0;
      }
    if (new_support) model.structure_changed();
    else model.values_changed();
  });
}

mc_status mc_add_traction(mc_model *m, int body, mc_int n_edges, const mc_int *edges, const double *traction) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = cell_body(model, body, "mc_add_traction", "its loads are the host's load vector (mc_set_load_vector)");
    require_count(n_edges, "n_edges");
    if (n_edges > 0) require_pointer(edges, "edges"), require_pointer(traction, "traction");
    if (n_edges > 0) require_finite(traction, 2 * size_t(n_edges), "traction", model.index_base);
    std::vector<mc::SurfaceSegment> oriented = load_edges(model, b.mesh, n_edges, edges);
    for (mc_int e = 0; e < n_edges; ++e)
      b.edge_loads.push_back({oriented[e].a, oriented[e].b, traction[2 * e], traction[2 * e + 1], false});
    model.values_changed();
  });
}

mc_status mc_add_pressure(mc_model *m, int body, mc_int n_edges, const mc_int *edges, const double *pressure) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = cell_body(model, body, "mc_add_pressure", "its loads are the host's load vector (mc_set_load_vector)");
    require_count(n_edges, "n_edges");
    if (n_edges > 0) require_pointer(edges, "edges"), require_pointer(pressure, "pressure");
    if (n_edges > 0) require_finite(pressure, size_t(n_edges), "pressure", model.index_base);
    std::vector<mc::SurfaceSegment> oriented = load_edges(model, b.mesh, n_edges, edges);
    for (mc_int e = 0; e < n_edges; ++e) b.edge_loads.push_back({oriented[e].a, oriented[e].b, pressure[e], 0, true});
    model.values_changed();
  });
}

mc_status mc_add_nodal_force(mc_model *m, int body, mc_int n, const mc_int *nodes, const double *force) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = meshed_body(model, body);
    require_count(n, "n");
    if (n > 0) require_pointer(nodes, "nodes"), require_pointer(force, "force");
    if (n > 0) require_finite(force, 2 * size_t(n), "force", model.index_base);
    std::vector<int> local(n);
    for (mc_int i = 0; i < n; ++i) local[i] = node_id(model, b.mesh, nodes[i], "nodes", size_t(i));
    for (mc_int i = 0; i < n; ++i)
      for (int c = 0; c < 2; ++c) {
        const int dof = model.dof_of(body - 1, local[i], c);  // a host body's restrained freedom: none
        if (dof >= 0) b.nodal_force[dof] += force[2 * i + c];
      }
    model.values_changed();
  });
}

mc_status mc_set_body_force(mc_model *m, int body, double fx, double fy) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = cell_body(model, body, "mc_set_body_force", "its loads are the host's load vector (mc_set_load_vector)");
    if (!std::isfinite(fx)) fail(MC_ERROR_ARGUMENT, "fx = %g: must be finite", fx);
    if (!std::isfinite(fy)) fail(MC_ERROR_ARGUMENT, "fy = %g: must be finite", fy);
    b.body_force[0] = fx, b.body_force[1] = fy;
    model.values_changed();
  });
}

mc_status mc_clear_loads(mc_model *m, int body) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = meshed_body(model, body);
    std::fill(b.nodal_force.begin(), b.nodal_force.end(), 0.0);
    std::fill(b.host_data.load.begin(), b.host_data.load.end(), 0.0);
    b.edge_loads.clear();
    b.body_force[0] = b.body_force[1] = 0;
    model.values_changed();
  });
}

mc_status mc_set_option_int(mc_model *m, int option, int64_t value) {
  return guard(m, [&](mc::Model &model) {
    switch (option) {
      case MC_OPTION_METHOD:
        if (value < MC_METHOD_MORTAR || value > MC_METHOD_NODE_TO_SEGMENT)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_METHOD takes MC_METHOD_MORTAR (0), MC_METHOD_DUAL_MORTAR (1) "
               "or MC_METHOD_NODE_TO_SEGMENT (2)", (long long)value);
        model.options.method = int(value);
        model.structure_changed();
        break;
      case MC_OPTION_MULTIPLIER:
        if (value != MC_MULTIPLIER_LINEAR && value != MC_MULTIPLIER_QUADRATIC)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_MULTIPLIER takes MC_MULTIPLIER_LINEAR (0) or "
               "MC_MULTIPLIER_QUADRATIC (1)", (long long)value);
        model.options.multiplier = int(value);
        model.structure_changed();
        break;
      case MC_OPTION_MAX_ITERATIONS:
        if (value < 1 || value > 1000000)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_MAX_ITERATIONS takes 1 to 1000000", (long long)value);
        model.options.max_iterations = int(value);
        model.values_changed();
        break;
      case MC_OPTION_ORDERING:
        if (value < MC_ORDERING_AUTO || value > MC_ORDERING_METIS)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_ORDERING takes MC_ORDERING_AUTO (0), MC_ORDERING_AMD (1) "
               "or MC_ORDERING_METIS (2)", (long long)value);
        model.options.ordering = int(value);
        model.structure_changed();
        break;
      case MC_OPTION_Q1_INTEGRATION:
        if (value != MC_Q1_FULL && value != MC_Q1_BBAR)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_Q1_INTEGRATION takes MC_Q1_FULL (0) or MC_Q1_BBAR (1)",
               (long long)value);
        model.options.q1_integration = int(value);
        model.structure_changed();
        break;
      case MC_OPTION_CONTACT_NORMAL:
        if (value != MC_NORMAL_NONMORTAR && value != MC_NORMAL_MORTAR)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_CONTACT_NORMAL takes MC_NORMAL_NONMORTAR (0) or "
               "MC_NORMAL_MORTAR (1)", (long long)value);
        model.options.contact_normal = int(value);
        model.structure_changed();
        break;
      case MC_OPTION_CONTACT_SURFACE:
        if (value != MC_SURFACE_SMOOTH && value != MC_SURFACE_FACETED)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_CONTACT_SURFACE takes MC_SURFACE_SMOOTH (0) or "
               "MC_SURFACE_FACETED (1)", (long long)value);
        model.options.contact_surface = int(value);
        model.structure_changed();
        break;
      case MC_OPTION_THREADS:
        if (value < 0 || value > 1024)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_THREADS takes 0 (automatic), 1 (serial) or at most n "
               "threads, n up to 1024", (long long)value);
        model.options.threads = int(value);  // how, not what: the results and factorizations stay valid
        break;
      case MC_OPTION_ERROR_ESTIMATE:
        if (value != 0 && value != 1)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_ERROR_ESTIMATE is 0 (off) or 1 (on)", (long long)value);
        model.options.error_estimate = value == 1;
        model.values_changed();
        break;
      case MC_OPTION_EAGER_RESULTS:
        if (value != 0 && value != 1)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_EAGER_RESULTS is 0 (results when asked for) or 1 (every solve "
               "computes them)", (long long)value);
        model.options.eager_results = value == 1;  // when, not what: the results stay valid
        break;
      case MC_OPTION_INTERFACE_SOLVER:
        if (value < MC_INTERFACE_AUTO || value > MC_INTERFACE_SPARSE)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_INTERFACE_SOLVER takes MC_INTERFACE_AUTO (0), "
               "MC_INTERFACE_CONDENSED (1) or MC_INTERFACE_SPARSE (2)", (long long)value);
        model.options.interface_solver = int(value);
        model.structure_changed();  // the two paths factorize different matrices
        break;
      case MC_OPTION_LOAD_STEPS:
        if (value < 1 || value > 1000000)
          fail(MC_ERROR_ARGUMENT, "value = %lld: MC_OPTION_LOAD_STEPS takes 1 to 1000000", (long long)value);
        model.options.load_steps = int(value);
        model.values_changed();
        break;
      case MC_OPTION_TOLERANCE:
      case MC_OPTION_FEATURE_ANGLE:
      case MC_OPTION_FRICTION_CT:
        fail(MC_ERROR_ARGUMENT, "option = %d is real-valued: use mc_set_option_real", option);
      default:
        fail(MC_ERROR_ARGUMENT, "option = %d: not an integer option", option);
    }
  });
}

mc_status mc_set_option_real(mc_model *m, int option, double value) {
  return guard(m, [&](mc::Model &model) {
    if (option == MC_OPTION_FEATURE_ANGLE) {
      if (!(value > 0 && value < 180))
        fail(MC_ERROR_ARGUMENT, "value = %g: MC_OPTION_FEATURE_ANGLE must lie in (0, 180) degrees", value);
      model.options.feature_angle = value;
      model.structure_changed();
      return;
    }
    if (option == MC_OPTION_FRICTION_CT) {
      if (!(value >= 0 && std::isfinite(value)))
        fail(MC_ERROR_ARGUMENT, "value = %g: MC_OPTION_FRICTION_CT must be finite and >= 0 (0: scaled automatically)",
             value);
      model.options.friction_ct = value;
      model.values_changed();
      return;
    }
    if (option != MC_OPTION_TOLERANCE) {
      if (option == MC_OPTION_METHOD || option == MC_OPTION_MAX_ITERATIONS || option == MC_OPTION_ORDERING ||
          option == MC_OPTION_Q1_INTEGRATION || option == MC_OPTION_CONTACT_NORMAL ||
          option == MC_OPTION_CONTACT_SURFACE || option == MC_OPTION_THREADS || option == MC_OPTION_INTERFACE_SOLVER ||
          option == MC_OPTION_ERROR_ESTIMATE || option == MC_OPTION_MULTIPLIER || option == MC_OPTION_LOAD_STEPS ||
          option == MC_OPTION_EAGER_RESULTS)
        fail(MC_ERROR_ARGUMENT, "option = %d is integer-valued: use mc_set_option_int", option);
      fail(MC_ERROR_ARGUMENT, "option = %d: not a real option", option);
    }
    if (!(value > 0 && value < 1))
      fail(MC_ERROR_ARGUMENT, "value = %g: MC_OPTION_TOLERANCE must lie in (0, 1)", value);
    model.options.tolerance = value;
    model.values_changed();
  });
}

mc_status mc_solve(mc_model *m) {
  return guard(m, [&](mc::Model &model) {
    model.solve();
    require_finite_results(model);
  });
}

mc_status mc_set_log_callback(mc_model *m, mc_log_fn fn, void *user_data) {
  return guard(m, [&](mc::Model &model) {
    model.progress.fn = fn;
    model.progress.user_data = fn ? user_data : nullptr;
  });
}

mc_status mc_get_info_int(const mc_model *m, int info, int64_t *value) {
  return guard_const(m, [&](const mc::Model &model) {
    require_pointer(value, "value");
    const mc::Infos &i = model.infos;
    switch (info) {
      case MC_INFO_DOFS: *value = i.dofs; break;
      case MC_INFO_FACTOR_NNZ: *value = i.factor_nnz; break;
      case MC_INFO_ITERATIONS: *value = i.iterations; break;
      case MC_INFO_ACTIVE_NODES: *value = i.active; break;
      case MC_INFO_CONTACT_NODES: *value = i.contact_rows; break;
      case MC_INFO_FACTORIZATIONS: *value = i.factorizations; break;
      case MC_INFO_INTERFACE_SOLVER: *value = i.interface_solver; break;
      case MC_INFO_STICK_NODES: *value = i.stick; break;
      case MC_INFO_SLIP_NODES: *value = i.slip; break;
      default:
        if (info >= MC_INFO_TIME_ASSEMBLY && info <= MC_INFO_TIME_RESULTS)
          fail(MC_ERROR_ARGUMENT, "info = %d is real-valued: use mc_get_info_real", info);
        fail(MC_ERROR_ARGUMENT, "info = %d: not an info", info);
    }
  });
}

mc_status mc_get_info_real(const mc_model *m, int info, double *value) {
  return guard_const(m, [&](const mc::Model &model) {
    require_pointer(value, "value");
    const mc::Infos &i = model.infos;
    switch (info) {
      case MC_INFO_TIME_ASSEMBLY: *value = i.t_assembly; break;
      case MC_INFO_TIME_ANALYSIS: *value = i.t_analysis; break;
      case MC_INFO_TIME_FACTORIZATION: *value = i.t_factor; break;
      case MC_INFO_TIME_SOLVE: *value = i.t_solve; break;
      case MC_INFO_TIME_CONTACT: *value = i.t_contact; break;
      case MC_INFO_TIME_TOTAL: *value = i.t_total; break;
      case MC_INFO_STRAIN_ENERGY: *value = i.energy; break;
      case MC_INFO_COMPLEMENTARITY: *value = i.complementarity; break;
      case MC_INFO_EQUILIBRIUM: *value = i.equilibrium; break;
      case MC_INFO_GAP_RESIDUAL: *value = i.gap_residual; break;
      case MC_INFO_ERROR_ESTIMATE: *value = model.error_estimate(); break;  // (computed if not yet)
      case MC_INFO_TIME_RESULTS: *value = model.results_seconds(); break;
      case MC_INFO_FRICTION_COMPLEMENTARITY: *value = i.friction_complementarity; break;
      default:
        if (info >= MC_INFO_DOFS && info <= MC_INFO_SLIP_NODES)
          fail(MC_ERROR_ARGUMENT, "info = %d is integer-valued: use mc_get_info_int", info);
        fail(MC_ERROR_ARGUMENT, "info = %d: not an info", info);
    }
  });
}

mc_status mc_get_displacement(const mc_model *m, int body, double *u) {
  return guard_const(m, [&](const mc::Model &model) {
    solved_body(model, body);
    require_pointer(u, "u");
    const std::vector<double> nodal = model.nodal_displacement(body - 1);  // (a host body's: from its equations)
    std::memcpy(u, nodal.data(), nodal.size() * sizeof(double));
  });
}

mc_status mc_get_stress(const mc_model *m, int body, double *sigma) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::Body &b = solved_body(model, body);
    refuse_host(b, body, "mc_get_stress", "a host body has no cells: the host computes its stresses from mc_get_equation_solution");
    require_pointer(sigma, "sigma");
    const std::vector<double> &stress = model.cell_stresses(body - 1);  // (computed if not yet)
    std::memcpy(sigma, stress.data(), stress.size() * sizeof(double));
  });
}

mc_status mc_get_nodal_stress(const mc_model *m, int body, double *sigma) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::Body &b = solved_body(model, body);
    refuse_host(b, body, "mc_get_nodal_stress", "a host body has no cells: the host computes its stresses from mc_get_equation_solution");
    require_pointer(sigma, "sigma");
    const std::vector<double> &stress = model.nodal_stresses(body - 1);  // (computed if not yet)
    std::memcpy(sigma, stress.data(), stress.size() * sizeof(double));
  });
}

mc_status mc_get_error_indicator(const mc_model *m, int body, double *eta) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::Body &b = solved_body(model, body);
    refuse_host(b, body, "mc_get_error_indicator", "a host body has no cells to estimate on");
    if (!model.options.error_estimate)
      fail(MC_ERROR_STATE, "no error estimate: MC_OPTION_ERROR_ESTIMATE is 0 (set it to 1 and solve again)");
    require_pointer(eta, "eta");
    const std::vector<double> &indicators = model.error_indicators(body - 1);  // (computed if not yet)
    std::fill(eta, eta + b.mesh.n_cells(), 0.0);  // (a body the estimate did not reach: 0)
    if (!indicators.empty()) std::memcpy(eta, indicators.data(), indicators.size() * sizeof(double));
  });
}

mc_status mc_get_reaction(const mc_model *m, int body, double *r) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::Body &b = solved_body(model, body);
    refuse_host(b, body, "mc_get_reaction", "its supports are the host's restrained freedoms: the host computes their reactions (mc_get_contact_load gives the contact forces)");
    require_pointer(r, "r");
    std::memcpy(r, b.reaction.data(), b.reaction.size() * sizeof(double));
  });
}

}  // extern "C"

extern "C" {

mc_status mc_write_vtu(const mc_model *m, const char *path) {
  return guard_const(m, [&](const mc::Model &model) {
    require_pointer(path, "path");
    mc::write_vtu(model, path);
  });
}

}  // extern "C"
