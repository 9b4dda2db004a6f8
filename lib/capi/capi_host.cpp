// The C API of host bodies (mc_set_host_body and what goes with it): a legacy program's own
// stiffness, load and numbering (lib/host_body.hpp), and the results in that numbering.
#include "capi/capi_support.hpp"
#include "bodies/host_body.hpp"
#include <cstring>

using namespace mc::capi;

namespace {

// The results of a body as a vector in its equation order: per DOF, which is a host body's
// equation order and a mesh body's 2 per node.
const mc::Body &solved_with_dofs(const mc::Model &model, int body, const void *out, const char *name) {
  const mc::Body &b = solved_body(model, body);
  require_pointer(out, name);
  return b;
}

}  // namespace

extern "C" {

mc_status mc_set_host_body(mc_model *m, int body, mc_int n_nodes, const double *xy, const mc_int *equations,
                           mc_int n_equations) {
  return guard(m, [&](mc::Model &model) {
    const int b = body_index(model, body);
    require_count(n_nodes, "n_nodes");
    mc::Body fresh;
    fresh.mesh = mc::Mesh::points(n_nodes, xy, model.index_base);
    if (model.axisymmetric) {
      const int i = mc::first_node_left_of_axis(fresh.mesh);
      if (i >= 0)
        fail(MC_ERROR_MESH, "%s = %g (node %d of body %d): a radius must be >= 0 in an axisymmetric model",
             mc::array_position("xy", 2 * size_t(i), model.index_base).c_str(), fresh.mesh.node(i).x, i + model.index_base, body);
    }
    fresh.host_data = mc::make_host_body(n_nodes, equations, n_equations, model.index_base);
    fresh.host = true;
    fresh.has_mesh = true;
    fresh.prescribed.assign(size_t(n_equations), 0);
    fresh.prescribed_value.assign(size_t(n_equations), 0.0);
    fresh.nodal_force.assign(size_t(n_equations), 0.0);
    model.body[b] = std::move(fresh);
    forget_contact_surfaces(model, b);
    model.structure_changed();
  });
}

mc_status mc_add_stiffness(mc_model *m, int body, mc_int n_entries, const mc_int *rows, const mc_int *cols,
                           const double *values, int storage) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = host_body(model, body, "mc_add_stiffness");
    mc::add_coordinate_entries(b.host_data, n_entries, rows, cols, values, storage, model.index_base);
    model.structure_changed();
  });
}

mc_status mc_add_element_matrices(mc_model *m, int body, mc_int n_elements, const mc_int *eltptr, const mc_int *eltvar,
                                  const double *a_elt) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = host_body(model, body, "mc_add_element_matrices");
    mc::add_element_matrices(b.host_data, n_elements, eltptr, eltvar, a_elt, model.index_base);
    model.structure_changed();
  });
}

mc_status mc_set_load_vector(mc_model *m, int body, mc_int n_equations, const double *f) {
  return guard(m, [&](mc::Model &model) {
    mc::Body &b = host_body(model, body, "mc_set_load_vector");
    if (n_equations != b.host_data.n_equations)
      fail(MC_ERROR_ARGUMENT, "n_equations = %d: body %d's system has %d equations (mc_set_host_body)", int(n_equations),
           body, b.host_data.n_equations);
    require_pointer(f, "f");
    require_finite(f, size_t(n_equations), "f", model.index_base);
    b.host_data.load.assign(f, f + n_equations);
    model.values_changed();
  });
}

mc_status mc_get_equation_solution(const mc_model *m, int body, double *u) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::Body &b = solved_with_dofs(model, body, u, "u");
    std::memcpy(u, b.u.data(), b.u.size() * sizeof(double));
  });
}

mc_status mc_get_contact_load(const mc_model *m, int body, double *r) {
  return guard_const(m, [&](const mc::Model &model) {
    const mc::Body &b = solved_with_dofs(model, body, r, "r");
    if (b.contact_load.empty()) std::memset(r, 0, b.u.size() * sizeof(double));  // a solve without contact
    else std::memcpy(r, b.contact_load.data(), b.contact_load.size() * sizeof(double));
  });
}

}  // extern "C"
