// What every part of the C API layer shares: the handle, guard() (which turns an mc::Error, or
// any other exception, into a status and the model's message: no C++ exception crosses the C
// ABI), and the checks of arguments with messages naming the argument and index.
#pragma once
#include "support/error.hpp"
#include "solve/model.hpp"
#include "mortarcontact.h"
#include <cmath>
#include <new>
#include <string>

struct mc_model {
  mc::Model model;
  std::string message;
};

namespace mc::capi {

using mc::fail;

template <class F>
mc_status guard(mc_model *m, F &&body) {
  if (!m) return MC_ERROR_ARGUMENT;
  try {
    body(m->model);
    m->message.clear();
    return MC_OK;
  } catch (const mc::Error &e) {
    m->message = e.what();
    return e.status();
  } catch (const std::bad_alloc &) {
    m->message = "out of memory";
    return MC_ERROR_MEMORY;
  } catch (const std::exception &e) {
    m->message = std::string("internal error: ") + e.what();
    return MC_ERROR_INTERNAL;
  } catch (...) {
    m->message = "internal error: unknown exception";
    return MC_ERROR_INTERNAL;
  }
}

// Getters take a const model but still record their error message.
template <class F>
mc_status guard_const(const mc_model *m, F &&body) {
  return guard(const_cast<mc_model *>(m), [&](mc::Model &model) { body(static_cast<const mc::Model &>(model)); });
}

// A body number given by the caller (1..N whatever the index base, like pairs), 0-based.
inline int body_index(const mc::Model &model, int body) {
  if (body < 1 || body > model.n_bodies()) {
    if (model.n_bodies() == 2) fail(MC_ERROR_ARGUMENT, "body = %d: must be 1 or 2", body);
    fail(MC_ERROR_ARGUMENT, "body = %d: must be 1 to %d (mc_set_body_count)", body, model.n_bodies());
  }
  return body - 1;
}

// A pair number given by the caller (1..pairs made), 0-based.
inline int pair_index(const mc::Model &model, int pair) {
  if (model.pairs.empty())
    fail(MC_ERROR_ARGUMENT, "pair = %d: the model has no contact pairs (mc_add_contact_pair, mc_set_contact)", pair);
  if (pair < 1 || pair > int(model.pairs.size()))
    fail(MC_ERROR_ARGUMENT, "pair = %d: must be 1 to %zu (the pairs made)", pair, model.pairs.size());
  return pair - 1;
}

// A body's contact surfaces refer to its node ids: a new mesh or host body drops them (and the
// non-mortar offsets), as it drops loads and supports.
inline void forget_contact_surfaces(mc::Model &model, int b) {
  for (mc::ContactPair &pair : model.pairs) {
    for (int side = 0; side < 2; ++side)
      if (pair.body_of_side(side) == b) pair.side[side].clear(), pair.has_side[side] = false;
    if (pair.nonmortar == b) pair.gap_offset.clear();
  }
}

inline mc::Body &meshed_body(mc::Model &model, int body) {
  mc::Body &b = model.body[body_index(model, body)];
  if (!b.has_mesh) fail(MC_ERROR_STATE, "body %d has no mesh: call mc_set_mesh first", body);
  return b;
}

// A body that must have cells: a host body refuses the call, saying why.
inline mc::Body &cell_body(mc::Model &model, int body, const char *call, const char *instead) {
  mc::Body &b = meshed_body(model, body);
  if (b.host)
    fail(MC_ERROR_STATE, "body %d is a host body (mc_set_host_body): %s does not apply to it, %s", body, call, instead);
  return b;
}

inline mc::Body &host_body(mc::Model &model, int body, const char *call) {
  mc::Body &b = model.body[body_index(model, body)];
  if (!b.host) fail(MC_ERROR_STATE, "body %d is not a host body: %s needs mc_set_host_body first", body, call);
  return b;
}

inline const mc::Body &solved_body(const mc::Model &model, int body) {
  const mc::Body &b = model.body[body_index(model, body)];
  if (!b.has_mesh) fail(MC_ERROR_STATE, "body %d has no mesh: call mc_set_mesh first", body);
  if (!model.solved) fail(MC_ERROR_STATE, "no solution: call mc_solve first (or again, after changing the scene)");
  return b;
}

// Results a host body does not have (stresses, reactions), refused saying why.
inline void refuse_host(const mc::Body &b, int body, const char *call, const char *why) {
  if (b.host) fail(MC_ERROR_STATE, "body %d is a host body: %s does not apply to it: %s", body, call, why);
}

inline void require_pointer(const void *p, const char *name) {
  if (!p) fail(MC_ERROR_ARGUMENT, "%s is NULL", name);
}

inline void require_count(mc_int n, const char *name) {
  if (n < 0) fail(MC_ERROR_ARGUMENT, "%s = %d: must not be negative", name, int(n));
}

// (base: the model's index base, for the position in the message)
inline void require_finite(const double *values, size_t count, const char *name, int base) {
  for (size_t i = 0; i < count; ++i)
    if (!std::isfinite(values[i]))
      fail(MC_ERROR_ARGUMENT, "%s is not finite", mc::array_position(name, i, base).c_str());
}

// A node id given by the caller, checked and made 0-based.
inline int node_id(const mc::Model &model, const mc::Mesh &mesh, mc_int id, const char *name, size_t index) {
  const long long local = (long long)id - model.index_base;  // no int overflow for id = INT_MIN
  if (local < 0 || local >= mesh.n_nodes())
    fail(MC_ERROR_ARGUMENT, "%s = %d: node id out of range [%d, %d] (index base %d)",
         mc::array_position(name, index, model.index_base).c_str(), int(id), model.index_base, mesh.n_nodes() - 1 + model.index_base, model.index_base);
  return int(local);
}

}  // namespace mc::capi
