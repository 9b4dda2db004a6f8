/*
 * mortarcontact.hpp - header-only C++17 wrapper of the C API in mortarcontact.h.
 *
 * Everything here is inline over the C functions: it adds no symbol to the library and no
 * dependency beyond the standard library, and the C ABI stays the only ABI (docs/abi.md).
 *
 *   #include <mortarcontact.hpp>
 *   mortarcontact::Model m;                                  // mc_create; mc_destroy when it goes
 *   m.set_mesh(1, xy, cells, 3);                             // std::vector overloads ...
 *   m.set_mesh(1, n_nodes, xy_ptr, n_cells, 3, cells_ptr);   // ... and the C pointer-and-count ones
 *   m.solve();                                               // throws mortarcontact::Error
 *   std::vector<double> p = m.get_contact_pressure();
 *
 * Naming: C function mc_NAME(model, ...) is Model::NAME(...); mc_NAME without a model is the
 * free function mortarcontact::NAME(); mc_create/mc_destroy are Model's constructor and
 * destructor. Constants are scoped enums whose values are the C constants (Option::method is
 * MC_OPTION_METHOD). The test cxx_wrapper_coverage checks, from the header, that every C
 * function is called here and every C constant has its enumerator.
 *
 * Errors: a status other than MC_OK throws mortarcontact::Error, carrying the Status and the
 * library's message (mc_errmsg). Arrays whose size does not fit the call (an odd number of
 * coordinates, ...) throw Error with Status::error_argument before the C call.
 *
 * Getters returning vectors size them from the counts this Model passed to set_mesh or
 * set_host_body (the C API has no node-count getter): a body set through the raw handle get() is
 * unknown to them. Bodies are 1..N (set_body_count; 2 by default), contact pairs 1, 2, ... in the
 * order add_contact_pair made them, whatever the index base. The Model also remembers the index base it set (set_index_base), which the
 * vector overload of add_element_matrices needs to check its arrays.
 */
#ifndef MORTARCONTACT_HPP
#define MORTARCONTACT_HPP

#include <mortarcontact.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mortarcontact {

// ---- constants: scoped enums over the C values ------------------------------------------

enum class Status : int {
  ok = MC_OK,
  error_argument = MC_ERROR_ARGUMENT,
  error_mesh = MC_ERROR_MESH,
  error_material = MC_ERROR_MATERIAL,
  error_state = MC_ERROR_STATE,
  error_contact = MC_ERROR_CONTACT,
  error_singular = MC_ERROR_SINGULAR,
  error_not_converged = MC_ERROR_NOT_CONVERGED,
  error_memory = MC_ERROR_MEMORY,
  error_internal = MC_ERROR_INTERNAL
};

enum class Plane : int { strain = MC_PLANE_STRAIN, stress = MC_PLANE_STRESS, axisymmetric = MC_AXISYMMETRIC };

/// Component masks of Model::fix.
enum class Components : int { x = MC_X, y = MC_Y, xy = MC_XY };

enum class Option : int {
  method = MC_OPTION_METHOD,
  tolerance = MC_OPTION_TOLERANCE,
  max_iterations = MC_OPTION_MAX_ITERATIONS,
  ordering = MC_OPTION_ORDERING,
  q1_integration = MC_OPTION_Q1_INTEGRATION,
  contact_normal = MC_OPTION_CONTACT_NORMAL,
  contact_surface = MC_OPTION_CONTACT_SURFACE,
  feature_angle = MC_OPTION_FEATURE_ANGLE,
  threads = MC_OPTION_THREADS,
  interface_solver = MC_OPTION_INTERFACE_SOLVER,
  error_estimate = MC_OPTION_ERROR_ESTIMATE,
  multiplier = MC_OPTION_MULTIPLIER,
  load_steps = MC_OPTION_LOAD_STEPS,
  friction_ct = MC_OPTION_FRICTION_CT,
  eager_results = MC_OPTION_EAGER_RESULTS
};

/// Values of Option::method.
enum class Method : int {
  mortar = MC_METHOD_MORTAR,
  dual_mortar = MC_METHOD_DUAL_MORTAR,
  node_to_segment = MC_METHOD_NODE_TO_SEGMENT
};

/// Values of Option::contact_normal.
enum class ContactNormal : int { nonmortar = MC_NORMAL_NONMORTAR, mortar = MC_NORMAL_MORTAR };

/// Values of Option::contact_surface.
enum class ContactSurface : int { smooth = MC_SURFACE_SMOOTH, faceted = MC_SURFACE_FACETED };

/// Values of Option::ordering ("auto" is a C++ keyword).
enum class Ordering : int { automatic = MC_ORDERING_AUTO, amd = MC_ORDERING_AMD, metis = MC_ORDERING_METIS };

/// Values of Option::q1_integration.
enum class Q1Integration : int { full = MC_Q1_FULL, bbar = MC_Q1_BBAR };

/// Values of Option::interface_solver ("auto" is a C++ keyword), and of Info::interface_solver
/// (which one ran: condensed or sparse; 0 without contact).
enum class InterfaceSolver : int {
  automatic = MC_INTERFACE_AUTO,
  condensed = MC_INTERFACE_CONDENSED,
  sparse = MC_INTERFACE_SPARSE
};

/// Values of Option::multiplier: the contact multipliers of a body 1 with quadratic cells.
enum class Multiplier : int { linear = MC_MULTIPLIER_LINEAR, quadratic = MC_MULTIPLIER_QUADRATIC };

enum class Info : int {
  dofs = MC_INFO_DOFS,
  factor_nnz = MC_INFO_FACTOR_NNZ,
  iterations = MC_INFO_ITERATIONS,
  active_nodes = MC_INFO_ACTIVE_NODES,
  contact_nodes = MC_INFO_CONTACT_NODES,
  factorizations = MC_INFO_FACTORIZATIONS,
  interface_solver = MC_INFO_INTERFACE_SOLVER,
  stick_nodes = MC_INFO_STICK_NODES,
  slip_nodes = MC_INFO_SLIP_NODES,
  time_assembly = MC_INFO_TIME_ASSEMBLY,
  time_analysis = MC_INFO_TIME_ANALYSIS,
  time_factorization = MC_INFO_TIME_FACTORIZATION,
  time_solve = MC_INFO_TIME_SOLVE,
  time_contact = MC_INFO_TIME_CONTACT,
  time_total = MC_INFO_TIME_TOTAL,
  strain_energy = MC_INFO_STRAIN_ENERGY,
  complementarity = MC_INFO_COMPLEMENTARITY,
  equilibrium = MC_INFO_EQUILIBRIUM,
  gap_residual = MC_INFO_GAP_RESIDUAL,
  error_estimate = MC_INFO_ERROR_ESTIMATE,
  friction_complementarity = MC_INFO_FRICTION_COMPLEMENTARITY,
  time_results = MC_INFO_TIME_RESULTS
};

enum class LogLevel : int { phase = MC_LOG_PHASE, iteration = MC_LOG_ITERATION };

/// The field argument of Model::get_pair_contact: one value per contact position (normal: two,
/// x and y), as the get_contact_* getter of the same name.
enum class ContactField : int {
  pressure = MC_CONTACT_PRESSURE,
  force = MC_CONTACT_FORCE,
  gap = MC_CONTACT_GAP,
  initial_gap = MC_CONTACT_INITIAL_GAP,
  normal = MC_CONTACT_NORMAL,
  shear = MC_CONTACT_SHEAR,              ///< tangential traction along t = (-n_y, n_x)
  slip = MC_CONTACT_SLIP,                ///< slip of the last solve
  slip_total = MC_CONTACT_SLIP_TOTAL,    ///< accumulated |slip| since the unloaded state
  state = MC_CONTACT_STATE               ///< a ContactState as a double
};

/// Values of ContactField::state (read as doubles: ContactState(int(value))).
enum class ContactState : int { open = MC_STATE_OPEN, stick = MC_STATE_STICK, slip = MC_STATE_SLIP };

/// The law argument of Model::set_friction.
enum class Friction : int {
  none = MC_FRICTION_NONE,        ///< frictionless (default); value 0
  tresca = MC_FRICTION_TRESCA,    ///< value: the slip bound, a shear traction >= 0
  coulomb = MC_FRICTION_COULOMB   ///< value: the friction coefficient mu >= 0
};

/// The storage argument of Model::add_stiffness.
enum class MatrixStorage : int {
  full = MC_MATRIX_FULL,         ///< both triangles given (summed duplicates symmetric to round-off)
  triangle = MC_MATRIX_TRIANGLE  ///< one triangle, either, each off-diagonal pair once
};

/// The header's version (the library's own: version_string(), version_number()).
constexpr int header_version_major = MC_VERSION_MAJOR;
constexpr int header_version_minor = MC_VERSION_MINOR;
constexpr int header_version_patch = MC_VERSION_PATCH;
constexpr int header_version_number = MC_VERSION_NUMBER;
constexpr const char *header_version_string = MC_VERSION_STRING;

// ---- functions without a model -------------------------------------------------------------

/// "MC_OK", "MC_ERROR_MESH", ...; "unknown status" for other values.
inline std::string status_string(Status status) { return ::mc_status_string(static_cast<mc_status>(status)); }
inline std::string version_string() { return ::mc_version_string(); }
inline int version_number() { return ::mc_version_number(); }

// ---- errors --------------------------------------------------------------------------------

/// A failed call: what() is "MC_ERROR_...: message".
class Error : public std::runtime_error {
 public:
  Error(Status status, const std::string &message)
      : std::runtime_error(status_string(status) + ": " + message), status_(status), message_(message) {}
  Status status() const noexcept { return status_; }
  /// The library's mc_errmsg (or the wrapper's own message for a size it rejected).
  const std::string &message() const noexcept { return message_; }

 private:
  Status status_;
  std::string message_;
};

namespace detail {

/// Number of items of `per_item` values in an array of `size` values, as the C API's mc_int.
inline mc_int item_count(std::size_t size, std::size_t per_item, const char *what) {
  if (size % per_item != 0)
    throw Error(Status::error_argument, std::string(what) + ": " + std::to_string(size) + " values, not " +
                                            std::to_string(per_item) + " per item");
  const std::size_t count = size / per_item;
  if (count > static_cast<std::size_t>(std::numeric_limits<mc_int>::max()))
    throw Error(Status::error_argument, std::string(what) + ": more items than mc_int counts");
  return static_cast<mc_int>(count);
}

/// The number of items in `ids` (`ids_per_item` ids each), checked to be the number of items in
/// `values` (`values_per_item` each). An empty `values` is allowed where the C API takes NULL
/// (`values_optional`).
inline mc_int paired_count(const std::vector<mc_int> &ids, std::size_t ids_per_item, const std::vector<double> &values,
                           std::size_t values_per_item, const char *what, bool values_optional = false) {
  const mc_int count = item_count(ids.size(), ids_per_item, what);
  if (values_optional && values.empty()) return count;
  const std::size_t want = static_cast<std::size_t>(count) * values_per_item;
  if (values.size() != want)
    throw Error(Status::error_argument, std::string(what) + ": " + std::to_string(values.size()) +
                                            " values for " + std::to_string(count) + " items, expected " +
                                            std::to_string(want));
  return count;
}

template <class T>
const T *data_or_null(const std::vector<T> &v) {
  return v.empty() ? nullptr : v.data();
}

/// A vector's data, or a valid pointer to nothing when it is empty (an empty std::vector may give
/// nullptr, which the C API refuses even for zero entries).
template <class T>
const T *data_or_empty(const std::vector<T> &v) {
  static const T none{};
  return v.empty() ? &none : v.data();
}

/// The log callback's state. Heap-allocated so that its address, the C callback's user data,
/// survives moving the Model.
struct LogRelay {
  std::function<void(LogLevel, const char *)> callback;
  std::exception_ptr pending;  // thrown by the callback; rethrown when mc_solve has returned

  // Exceptions must not unwind through the C library: they are kept and rethrown by solve().
  static void relay(void *user_data, mc_log_level level, const char *message) noexcept {
    auto *self = static_cast<LogRelay *>(user_data);
    if (self->pending) return;  // the first exception wins; later messages are dropped
    try {
      self->callback(static_cast<LogLevel>(level), message);
    } catch (...) {
      self->pending = std::current_exception();
    }
  }
};

}  // namespace detail

// ---- the model -----------------------------------------------------------------------------

/// One contact scene (an mc_model). Move-only; destroys the mc_model when it goes.
class Model {
 public:
  /// mc_create; index_base 0 (C and C++ convention) or 1.
  explicit Model(int index_base = 0) {
    mc_model *handle = nullptr;
    const mc_status status = ::mc_create(&handle);
    if (status != MC_OK) throw Error(static_cast<Status>(status), ::mc_errmsg(nullptr));
    handle_.reset(handle);
    if (index_base != 0) set_index_base(index_base);
  }

  Model(Model &&) noexcept = default;
  Model &operator=(Model &&) noexcept = default;
  Model(const Model &) = delete;
  Model &operator=(const Model &) = delete;
  ~Model() = default;

  /// The C handle, for C calls this wrapper lacks; the Model still owns it.
  mc_model *get() const noexcept { return handle_.get(); }

  /// The message of the last failed call, "" after a success.
  std::string errmsg() const { return ::mc_errmsg(get()); }

  // ---- the scene ----

  void set_index_base(int base) {
    check(::mc_set_index_base(get(), base));
    base_ = base;
  }
  /// The number of bodies, n >= 2 (default 2). Growing keeps the bodies there are; shrinking
  /// drops the last ones (Status::error_state while a contact pair uses one of them).
  void set_body_count(int n) {
    check(::mc_set_body_count(get(), n));
    meshes_.resize(static_cast<std::size_t>(n));
  }
  void set_plane(Plane plane, double thickness = 1.0) {
    check(::mc_set_plane(get(), static_cast<int>(plane), thickness));
  }

  /// xy: 2 per node; cells: nodes_per_cell (3, 4, 6, 8 or 9) ids each.
  void set_mesh(int body, mc_int n_nodes, const double *xy, mc_int n_cells, int nodes_per_cell,
                const mc_int *cells) {
    check(::mc_set_mesh(get(), body, n_nodes, xy, n_cells, nodes_per_cell, cells));
    mesh_of(body) = MeshSize{n_nodes, n_cells, 0};
  }
  void set_mesh(int body, const std::vector<double> &xy, const std::vector<mc_int> &cells, int nodes_per_cell) {
    if (nodes_per_cell <= 0) throw Error(Status::error_argument, "set_mesh: nodes_per_cell must be 3, 4, 6, 8 or 9");
    set_mesh(body, detail::item_count(xy.size(), 2, "set_mesh: xy"), xy.data(),
             detail::item_count(cells.size(), static_cast<std::size_t>(nodes_per_cell), "set_mesh: cells"),
             nodes_per_cell, cells.data());
  }

  void set_material(int body, double young, double poisson) {
    check(::mc_set_material(get(), body, young, poisson));
  }

  /// d: 9 per cell (row-major symmetric 3x3, Voigt notation).
  void set_cell_elasticity(int body, const double *d) { check(::mc_set_cell_elasticity(get(), body, d)); }
  void set_cell_elasticity(int body, const std::vector<double> &d) {
    const mc_int n_cells = known_mesh(body).n_cells;
    if (d.size() != 9 * static_cast<std::size_t>(n_cells))
      throw Error(Status::error_argument, "set_cell_elasticity: " + std::to_string(d.size()) + " values, expected 9 for each of " +
                                              std::to_string(n_cells) + " cells");
    set_cell_elasticity(body, d.data());
  }

  /// values: 2 per node, or nullptr / empty for zero.
  void fix(int body, mc_int n, const mc_int *nodes, Components components, const double *values = nullptr) {
    check(::mc_fix(get(), body, n, nodes, static_cast<int>(components), values));
  }
  void fix(int body, const std::vector<mc_int> &nodes, Components components,
           const std::vector<double> &values = {}) {
    fix(body, detail::paired_count(nodes, 1, values, 2, "fix", true), nodes.data(), components,
        detail::data_or_null(values));
  }

  /// edges: 2 ids each; traction: 2 per edge.
  void add_traction(int body, mc_int n_edges, const mc_int *edges, const double *traction) {
    check(::mc_add_traction(get(), body, n_edges, edges, traction));
  }
  void add_traction(int body, const std::vector<mc_int> &edges, const std::vector<double> &traction) {
    add_traction(body, detail::paired_count(edges, 2, traction, 2, "add_traction"), edges.data(), traction.data());
  }

  /// edges: 2 ids each; pressure: 1 per edge.
  void add_pressure(int body, mc_int n_edges, const mc_int *edges, const double *pressure) {
    check(::mc_add_pressure(get(), body, n_edges, edges, pressure));
  }
  void add_pressure(int body, const std::vector<mc_int> &edges, const std::vector<double> &pressure) {
    add_pressure(body, detail::paired_count(edges, 2, pressure, 1, "add_pressure"), edges.data(), pressure.data());
  }

  /// force: 2 per node.
  void add_nodal_force(int body, mc_int n, const mc_int *nodes, const double *force) {
    check(::mc_add_nodal_force(get(), body, n, nodes, force));
  }
  void add_nodal_force(int body, const std::vector<mc_int> &nodes, const std::vector<double> &force) {
    add_nodal_force(body, detail::paired_count(nodes, 1, force, 2, "add_nodal_force"), nodes.data(), force.data());
  }

  void set_body_force(int body, double fx, double fy) { check(::mc_set_body_force(get(), body, fx, fy)); }
  void clear_loads(int body) { check(::mc_clear_loads(get(), body)); }

  /// edges: 2 ids each.
  void set_contact(int body, mc_int n_edges, const mc_int *edges) {
    check(::mc_set_contact(get(), body, n_edges, edges));
  }
  void set_contact(int body, const std::vector<mc_int> &edges) {
    set_contact(body, detail::item_count(edges.size(), 2, "set_contact: edges"), edges.data());
  }

  /// offset: 1 per node.
  void set_gap_offset(mc_int n, const mc_int *nodes, const double *offset) {
    check(::mc_set_gap_offset(get(), n, nodes, offset));
  }
  void set_gap_offset(const std::vector<mc_int> &nodes, const std::vector<double> &offset) {
    set_gap_offset(detail::paired_count(nodes, 1, offset, 1, "set_gap_offset"), nodes.data(), offset.data());
  }

  // ---- assemblies: contact pairs ----

  /// Makes a contact pair between two different bodies; returns its number (1, 2, ...).
  int add_contact_pair(int nonmortar_body, int mortar_body) {
    int pair = 0;
    check(::mc_add_contact_pair(get(), nonmortar_body, mortar_body, &pair));
    return pair;
  }
  /// One side of a pair: body is the pair's non-mortar or mortar body; edges 2 ids each.
  /// Replaces that side's earlier edges.
  void set_pair_surface(int pair, int body, mc_int n_edges, const mc_int *edges) {
    check(::mc_set_pair_surface(get(), pair, body, n_edges, edges));
  }
  void set_pair_surface(int pair, int body, const std::vector<mc_int> &edges) {
    set_pair_surface(pair, body, detail::item_count(edges.size(), 2, "set_pair_surface: edges"),
                     detail::data_or_empty(edges));
  }
  /// One side of a pair of quadratic edges: 3 ids each (end, end, middle).
  void set_pair_surface_curved(int pair, int body, mc_int n_edges, const mc_int *edges) {
    check(::mc_set_pair_surface_curved(get(), pair, body, n_edges, edges));
  }
  void set_pair_surface_curved(int pair, int body, const std::vector<mc_int> &edges) {
    set_pair_surface_curved(pair, body, detail::item_count(edges.size(), 3, "set_pair_surface_curved: edges"),
                            detail::data_or_empty(edges));
  }
  /// Initial-gap offsets of the pair's non-mortar nodes, 1 per node (as set_gap_offset for pair 1).
  void set_pair_gap_offset(int pair, mc_int n, const mc_int *nodes, const double *offset) {
    check(::mc_set_pair_gap_offset(get(), pair, n, nodes, offset));
  }
  void set_pair_gap_offset(int pair, const std::vector<mc_int> &nodes, const std::vector<double> &offset) {
    set_pair_gap_offset(pair, detail::paired_count(nodes, 1, offset, 1, "set_pair_gap_offset"),
                        detail::data_or_empty(nodes), detail::data_or_empty(offset));
  }

  // ---- friction ----

  /// The friction law of a contact pair (1 for the two-body model's pair): Friction::tresca
  /// (value: the slip bound) or Friction::coulomb (value: mu); Friction::none (value 0) removes it.
  void set_friction(int pair, Friction law, double value = 0) {
    check(::mc_set_friction(get(), pair, static_cast<int>(law), value));
  }
  /// The raw law number (checked by the library: an unknown law is Status::error_argument).
  void set_friction(int pair, int law, double value) { check(::mc_set_friction(get(), pair, law, value)); }
  /// Forgets the converged state: the next solve starts from the unloaded state.
  void reset_history() { check(::mc_reset_history(get())); }

  // ---- host bodies: a legacy program's own matrices ----

  /// A body with no cells: xy 2 per node, equations 2 per node (x then y; a number below the
  /// index base: no equation), n_equations the size of the host's system.
  void set_host_body(int body, mc_int n_nodes, const double *xy, const mc_int *equations, mc_int n_equations) {
    check(::mc_set_host_body(get(), body, n_nodes, xy, equations, n_equations));
    mesh_of(body) = MeshSize{n_nodes, 0, n_equations};
  }
  void set_host_body(int body, const std::vector<double> &xy, const std::vector<mc_int> &equations,
                     mc_int n_equations) {
    const mc_int n_nodes = detail::item_count(xy.size(), 2, "set_host_body: xy");
    if (equations.size() != xy.size())
      throw Error(Status::error_argument, "set_host_body: " + std::to_string(equations.size()) +
                                              " equation numbers for " + std::to_string(n_nodes) +
                                              " nodes, expected 2 per node");
    set_host_body(body, n_nodes, xy.data(), equations.data(), n_equations);
  }

  /// Coordinate entries (values[k] at rows[k], cols[k], host equation numbers), duplicates summed.
  void add_stiffness(int body, mc_int n_entries, const mc_int *rows, const mc_int *cols, const double *values,
                     MatrixStorage storage = MatrixStorage::full) {
    check(::mc_add_stiffness(get(), body, n_entries, rows, cols, values, static_cast<int>(storage)));
  }
  void add_stiffness(int body, const std::vector<mc_int> &rows, const std::vector<mc_int> &cols,
                     const std::vector<double> &values, MatrixStorage storage = MatrixStorage::full) {
    const mc_int n = detail::paired_count(rows, 1, values, 1, "add_stiffness: rows and values");
    if (cols.size() != rows.size())
      throw Error(Status::error_argument, "add_stiffness: " + std::to_string(cols.size()) + " cols for " +
                                              std::to_string(rows.size()) + " rows");
    add_stiffness(body, n, detail::data_or_empty(rows), detail::data_or_empty(cols), detail::data_or_empty(values),
                  storage);
  }

  /// Element matrices (MUMPS's elemental input): element e's equations are
  /// eltvar[eltptr[e] - base .. eltptr[e + 1] - base), its square matrix column by column in a_elt.
  void add_element_matrices(int body, mc_int n_elements, const mc_int *eltptr, const mc_int *eltvar,
                            const double *a_elt) {
    check(::mc_add_element_matrices(get(), body, n_elements, eltptr, eltvar, a_elt));
  }
  /// eltptr: n_elements + 1 entries counted from the index base; eltvar and a_elt exactly as long
  /// as eltptr says (checked before the C call, which has no length for them).
  void add_element_matrices(int body, const std::vector<mc_int> &eltptr, const std::vector<mc_int> &eltvar,
                            const std::vector<double> &a_elt) {
    const mc_int n_elements = detail::item_count(eltptr.size(), 1, "add_element_matrices: eltptr") - 1;
    if (n_elements < 0) throw Error(Status::error_argument, "add_element_matrices: eltptr needs n_elements + 1 entries");
    if (eltptr.front() != base_)
      throw Error(Status::error_argument, "add_element_matrices: eltptr[0] = " + std::to_string(eltptr.front()) +
                                              ", expected the index base " + std::to_string(base_));
    std::size_t n_values = 0;
    for (mc_int e = 0; e < n_elements; ++e) {
      const std::size_t i = static_cast<std::size_t>(e);
      if (eltptr[i + 1] < eltptr[i])
        throw Error(Status::error_argument, "add_element_matrices: eltptr[" + std::to_string(e + 1) + "] = " +
                                                std::to_string(eltptr[i + 1]) + " is below eltptr[" +
                                                std::to_string(e) + "] = " + std::to_string(eltptr[i]));
      const auto size = static_cast<std::size_t>(static_cast<std::int64_t>(eltptr[i + 1]) - eltptr[i]);
      n_values += size * size;
    }
    const auto n_vars = static_cast<std::size_t>(static_cast<std::int64_t>(eltptr.back()) - base_);
    if (eltvar.size() != n_vars || a_elt.size() != n_values)
      throw Error(Status::error_argument, "add_element_matrices: eltptr gives " + std::to_string(n_vars) +
                                              " equations and " + std::to_string(n_values) + " matrix values, got " +
                                              std::to_string(eltvar.size()) + " and " + std::to_string(a_elt.size()));
    add_element_matrices(body, n_elements, eltptr.data(), detail::data_or_empty(eltvar), detail::data_or_empty(a_elt));
  }

  /// The load of a host body in equation order (replaces the previous one).
  void set_load_vector(int body, mc_int n_equations, const double *f) {
    check(::mc_set_load_vector(get(), body, n_equations, f));
  }
  void set_load_vector(int body, const std::vector<double> &f) {
    set_load_vector(body, detail::item_count(f.size(), 1, "set_load_vector: f"), f.data());
  }

  /// Candidate contact surface of quadratic edges: 3 ids each (end, end, middle).
  void set_contact_curved(int body, mc_int n_edges, const mc_int *edges) {
    check(::mc_set_contact_curved(get(), body, n_edges, edges));
  }
  void set_contact_curved(int body, const std::vector<mc_int> &edges) {
    set_contact_curved(body, detail::item_count(edges.size(), 3, "set_contact_curved: edges"), edges.data());
  }

  // ---- options and solving ----

  void set_option_int(Option option, std::int64_t value) {
    check(::mc_set_option_int(get(), static_cast<int>(option), value));
  }
  /// An option whose value is one of the enums above: set_option_int(Option::method, Method::dual_mortar).
  template <class Value, std::enable_if_t<std::is_enum_v<Value>, int> = 0>
  void set_option_int(Option option, Value value) {
    set_option_int(option, static_cast<std::int64_t>(value));
  }
  void set_option_real(Option option, double value) {
    check(::mc_set_option_real(get(), static_cast<int>(option), value));
  }

  /// Rethrows, after mc_solve has returned, an exception the log callback threw.
  void solve() {
    const mc_status status = ::mc_solve(get());
    if (log_ && log_->pending) std::rethrow_exception(std::exchange(log_->pending, nullptr));
    check(status);
  }

  /// The raw C callback (nullptr removes it).
  void set_log_callback(mc_log_fn fn, void *user_data) {
    check(::mc_set_log_callback(get(), fn, user_data));
    log_.reset();
  }
  /// Any callable; it may throw (solve() rethrows). An empty function removes it.
  void set_log_callback(std::function<void(LogLevel, const char *)> callback) {
    if (!callback) return set_log_callback(nullptr, nullptr);
    auto relay = std::make_unique<detail::LogRelay>();
    relay->callback = std::move(callback);
    check(::mc_set_log_callback(get(), &detail::LogRelay::relay, relay.get()));
    log_ = std::move(relay);
  }

  // ---- results ----

  std::int64_t get_info_int(Info info) const {
    std::int64_t value = 0;
    check(::mc_get_info_int(get(), static_cast<int>(info), &value));
    return value;
  }
  double get_info_real(Info info) const {
    double value = 0;
    check(::mc_get_info_real(get(), static_cast<int>(info), &value));
    return value;
  }

  /// 2 per node of the body.
  void get_displacement(int body, double *u) const { check(::mc_get_displacement(get(), body, u)); }
  std::vector<double> get_displacement(int body) const { return per_node(body, 2, ::mc_get_displacement); }
  /// 4 per cell: xx yy xy zz.
  void get_stress(int body, double *sigma) const { check(::mc_get_stress(get(), body, sigma)); }
  std::vector<double> get_stress(int body) const { return per_cell(body, 4, ::mc_get_stress); }
  /// 4 per node of the body: xx yy xy zz, each cell's stress at its nodes averaged over the cells.
  void get_nodal_stress(int body, double *sigma) const { check(::mc_get_nodal_stress(get(), body, sigma)); }
  std::vector<double> get_nodal_stress(int body) const { return per_node(body, 4, ::mc_get_nodal_stress); }
  /// 1 per cell: the cells' error indicators, relative like Info::error_estimate (their squares
  /// over both bodies add up to its square). Refused (Status::error_state) before a solve, for a
  /// host body, or when Option::error_estimate is 0.
  void get_error_indicator(int body, double *eta) const { check(::mc_get_error_indicator(get(), body, eta)); }
  std::vector<double> get_error_indicator(int body) const { return per_cell(body, 1, ::mc_get_error_indicator); }
  /// 2 per node of the body.
  void get_reaction(int body, double *r) const { check(::mc_get_reaction(get(), body, r)); }
  std::vector<double> get_reaction(int body) const { return per_node(body, 2, ::mc_get_reaction); }

  /// The displacements in equation order: n_equations of a host body, 2 per node of a mesh body.
  void get_equation_solution(int body, double *u) const { check(::mc_get_equation_solution(get(), body, u)); }
  std::vector<double> get_equation_solution(int body) const {
    return body_values(body, equation_count(body), 1, ::mc_get_equation_solution);
  }
  /// The contact forces on the body as a load vector in its equation order (sized as above).
  void get_contact_load(int body, double *r) const { check(::mc_get_contact_load(get(), body, r)); }
  std::vector<double> get_contact_load(int body) const {
    return body_values(body, equation_count(body), 1, ::mc_get_contact_load);
  }

  /// Number of body-1 contact nodes: the length of the contact arrays.
  mc_int get_contact_count() const {
    mc_int n = 0;
    check(::mc_get_contact_count(get(), &n));
    return n;
  }
  void get_contact_nodes(mc_int *nodes) const { check(::mc_get_contact_nodes(get(), nodes)); }
  std::vector<mc_int> get_contact_nodes() const { return per_contact_node<mc_int>(1, ::mc_get_contact_nodes); }
  void get_contact_pressure(double *p) const { check(::mc_get_contact_pressure(get(), p)); }
  std::vector<double> get_contact_pressure() const { return per_contact_node<double>(1, ::mc_get_contact_pressure); }
  void get_contact_force(double *f) const { check(::mc_get_contact_force(get(), f)); }
  std::vector<double> get_contact_force() const { return per_contact_node<double>(1, ::mc_get_contact_force); }
  void get_contact_gap(double *g) const { check(::mc_get_contact_gap(get(), g)); }
  std::vector<double> get_contact_gap() const { return per_contact_node<double>(1, ::mc_get_contact_gap); }
  void get_contact_initial_gap(double *g0) const { check(::mc_get_contact_initial_gap(get(), g0)); }
  std::vector<double> get_contact_initial_gap() const {
    return per_contact_node<double>(1, ::mc_get_contact_initial_gap);
  }
  /// 2 per contact node.
  void get_contact_normal(double *n) const { check(::mc_get_contact_normal(get(), n)); }
  std::vector<double> get_contact_normal() const { return per_contact_node<double>(2, ::mc_get_contact_normal); }

  /// After a solve: the number of the pair's contact positions (the length of its contact arrays).
  mc_int get_pair_contact_count(int pair) const {
    mc_int n = 0;
    check(::mc_get_pair_contact_count(get(), pair, &n));
    return n;
  }
  /// Their node ids on the non-mortar body (index base applies).
  void get_pair_contact_nodes(int pair, mc_int *nodes) const { check(::mc_get_pair_contact_nodes(get(), pair, nodes)); }
  std::vector<mc_int> get_pair_contact_nodes(int pair) const {
    std::vector<mc_int> nodes(static_cast<std::size_t>(get_pair_contact_count(pair)));
    mc_int none = 0;
    check(::mc_get_pair_contact_nodes(get(), pair, nodes.empty() ? &none : nodes.data()));
    return nodes;
  }
  /// A field of the pair's contact positions: 1 value per position, 2 (x, y) for ContactField::normal.
  void get_pair_contact(int pair, ContactField field, double *out) const {
    check(::mc_get_pair_contact(get(), pair, static_cast<int>(field), out));
  }
  std::vector<double> get_pair_contact(int pair, ContactField field) const {
    const std::size_t per_position = field == ContactField::normal ? 2 : 1;
    std::vector<double> values(per_position * static_cast<std::size_t>(get_pair_contact_count(pair)));
    double none = 0;
    get_pair_contact(pair, field, values.empty() ? &none : values.data());
    return values;
  }

  // ---- output ----

  void write_vtu(const std::string &path) const { check(::mc_write_vtu(get(), path.c_str())); }

 private:
  struct Destroy {
    void operator()(mc_model *m) const noexcept { ::mc_destroy(m); }
  };
  struct MeshSize {
    mc_int n_nodes = 0;
    mc_int n_cells = 0;      // 0 for a host body
    mc_int n_equations = 0;  // a host body's system size; 0 for a mesh body
    bool known() const { return n_nodes > 0; }
  };

  void check(mc_status status) const {
    if (status != MC_OK) throw Error(static_cast<Status>(status), ::mc_errmsg(get()));
  }

  // Called after a successful C call, so body is 1..N (meshes_ grows if the count was set
  // through the raw handle); any other number is left to the C call to reject with its message.
  MeshSize &mesh_of(int body) {
    const auto index = static_cast<std::size_t>(body - 1);
    if (index >= meshes_.size()) meshes_.resize(index + 1);
    return meshes_[index];
  }
  MeshSize known_mesh(int body) const {
    const MeshSize mesh =
        (body >= 1 && static_cast<std::size_t>(body) <= meshes_.size()) ? meshes_[static_cast<std::size_t>(body - 1)] : MeshSize{};
    if (!mesh.known())
      throw Error(Status::error_state, "body " + std::to_string(body) +
                                           " has no mesh or host body set through this Model: the array size is unknown");
    return mesh;
  }
  /// The length of a body's equation vectors: n_equations (host body) or 2 n_nodes (mesh body).
  mc_int equation_count(int body) const {
    const MeshSize mesh = known_mesh(body);
    return mesh.n_equations > 0 ? mesh.n_equations : 2 * mesh.n_nodes;
  }

  using BodyGetter = mc_status (*)(const mc_model *, int, double *);
  template <class T>
  using ContactGetter = mc_status (*)(const mc_model *, T *);

  /// A C getter's values, `per_item` for each of `count` items, in a new vector.
  std::vector<double> body_values(int body, mc_int count, std::size_t per_item, BodyGetter c_getter) const {
    std::vector<double> values(per_item * static_cast<std::size_t>(count));
    double none = 0;  // no values (a host body has no cells): still a pointer, the C call says why
    check(c_getter(get(), body, values.empty() ? &none : values.data()));
    return values;
  }
  std::vector<double> per_node(int body, std::size_t per_item, BodyGetter c_getter) const {
    return body_values(body, known_mesh(body).n_nodes, per_item, c_getter);
  }
  std::vector<double> per_cell(int body, std::size_t per_item, BodyGetter c_getter) const {
    return body_values(body, known_mesh(body).n_cells, per_item, c_getter);
  }
  template <class T>
  std::vector<T> per_contact_node(std::size_t per_item, ContactGetter<T> c_getter) const {
    std::vector<T> values(per_item * static_cast<std::size_t>(get_contact_count()));
    check(c_getter(get(), values.data()));
    return values;
  }

  std::unique_ptr<mc_model, Destroy> handle_;
  std::vector<MeshSize> meshes_ = std::vector<MeshSize>(2);  // bodies 1..N
  int base_ = 0;  // the index base set through this Model
  std::unique_ptr<detail::LogRelay> log_;
};

}  // namespace mortarcontact

#endif /* MORTARCONTACT_HPP */
