"""
    MortarContact

Julia bindings of mortarcontact (include/mortarcontact.h): 2D contact between linear-elastic
bodies, frictionless or with Tresca or Coulomb friction, by the mortar finite element method.

UNTESTED AT RUN TIME: Julia is not available where this project is built and tested. The test
`julia_wrappers` (bindings/julia/check_julia_wrappers.py) only checks, by parsing, that every
`mc_` function of the header has a `ccall` here with matching argument and return types.

Two layers, both thin:
- `mc_create`, `mc_set_mesh`, ... : one `ccall` per C function, same name and arguments
  (raw pointers, `Ref`s and arrays);
- `Model` and `set_mesh!`, `solve!`, `get_displacement`, ...: a model with 1-based ids (Julia's
  own convention; `Model(index_base=0)` for 0-based), column-major arrays with one column per
  node/cell/edge (`xy` is 2×n_nodes, `cells` k×n_cells with k = 3, 4, 6, 8 or 9 nodes per cell,
  `edges` 2×n_edges), which is exactly the C layout, and errors thrown as
  `MortarContactError(status, message)`.
- Host bodies (a legacy program's own matrices): `set_host_body!`, `add_stiffness!` (a
  `SparseMatrixCSC`, any matrix, or coordinate vectors), `add_element_matrices!` (MUMPS's
  `eltptr`/`eltvar`/`a_elt`, or Smith and Griffiths' `g_g` and `storkm`), `set_load_vector!`,
  `get_equation_solution`, `get_contact_load`; `set_contact_curved!` for 3-node edges.
- Assemblies: `set_body_count!` (bodies 1..N), `add_contact_pair!` (returns the pair's number,
  1, 2, ... whatever the index base), `set_pair_surface!`, `set_pair_surface_curved!`,
  `set_pair_gap_offset!`, `get_pair_contact_count`, `get_pair_contact_nodes` and
  `get_pair_contact(m, pair, field)` with `MC_CONTACT_PRESSURE`, `_FORCE`, `_GAP`, `_INITIAL_GAP`
  (a vector) or `MC_CONTACT_NORMAL` (2×n_contact).
- Friction: `set_friction!(m, pair, law, value)` with `MC_FRICTION_NONE`, `MC_FRICTION_TRESCA`
  (value: the slip bound) or `MC_FRICTION_COULOMB` (value: μ), `reset_history!`, the options
  `MC_OPTION_LOAD_STEPS` and `MC_OPTION_FRICTION_CT`, the infos `MC_INFO_STICK_NODES`,
  `MC_INFO_SLIP_NODES`, `MC_INFO_FRICTION_COMPLEMENTARITY`, and the pair fields
  `MC_CONTACT_SHEAR`, `_SLIP`, `_SLIP_TOTAL` and `_STATE` (`MC_STATE_OPEN`, `_STICK`, `_SLIP` as
  Float64) through `get_pair_contact`.

The library is `libmortarcontact.so.0`, loaded from `ENV["MORTARCONTACT_LIBRARY"]` (full path)
if set, else from the install prefix this package was installed into
(`<prefix>/share/mortarcontact/julia/MortarContact/`), else from `build*/lib/` of the source
checkout it sits in (`bindings/julia/`), else from the system's library path.

```julia
using Pkg; Pkg.develop(path="<prefix>/share/mortarcontact/julia/MortarContact")  # once
using MortarContact
Model() do m
    set_mesh!(m, 1, xy1, cells1); set_material!(m, 1, 1.0, 0.3)
    # ...
    solve!(m)
    u1 = get_displacement(m, 1)
end
```
"""
module MortarContact

using Libdl
using SparseArrays: SparseMatrixCSC, findnz, sparse

export Model, MortarContactError, version_string, version_number, status_string
export set_index_base!, set_plane!, set_mesh!, set_material!, set_cell_elasticity!, fix!,
       add_traction!, add_pressure!, add_nodal_force!, set_body_force!, clear_loads!, set_contact!,
       set_option_int!, set_option_real!, solve!, get_info_int, get_info_real, get_displacement,
       get_stress, get_nodal_stress, get_error_indicator, get_reaction, get_contact_count,
       get_contact_nodes, get_contact_pressure, get_contact_force, get_contact_gap,
       get_contact_initial_gap, get_contact_normal, errmsg, set_gap_offset!, set_log_callback!,
       write_vtu
export set_host_body!, add_stiffness!, add_element_matrices!, set_load_vector!, get_equation_solution,
       get_contact_load, set_contact_curved!
export set_body_count!, add_contact_pair!, set_pair_surface!, set_pair_surface_curved!, set_pair_gap_offset!,
       get_pair_contact_count, get_pair_contact_nodes, get_pair_contact
export set_friction!, reset_history!

# Resolved by soname: __init__ dlopens the chosen file first, and the dynamic loader then
# matches this name against the already-loaded library's soname.
const libmortarcontact = "libmortarcontact.so.0"

function __init__()
    path = get(ENV, "MORTARCONTACT_LIBRARY", "")
    if isempty(path)
        path = find_installed()
    end
    isempty(path) || Libdl.dlopen(path, Libdl.RTLD_LAZY | Libdl.RTLD_GLOBAL)
    return nothing
end

# The package's src/ is <prefix>/share/mortarcontact/julia/MortarContact/src when installed
# (library in <prefix>/lib*/ or <prefix>/lib/<multiarch>/), <repo>/bindings/julia/src in a source
# checkout (library in <repo>/build*/lib/).
function find_installed()
    subdirs(d) = isdir(d) ? [joinpath(d, x) for x in readdir(d) if isdir(joinpath(d, x))] : String[]
    prefix = normpath(joinpath(@__DIR__, "..", "..", "..", "..", ".."))
    dirs = [d for d in subdirs(prefix) if startswith(basename(d), "lib")]
    append!(dirs, subdirs(joinpath(prefix, "lib")))
    repo = normpath(joinpath(@__DIR__, "..", "..", ".."))
    append!(dirs, [joinpath(d, "lib") for d in subdirs(repo) if startswith(basename(d), "build")])
    for d in dirs
        candidate = joinpath(d, libmortarcontact)
        isfile(candidate) && return candidate
    end
    return ""
end

# ---- constants of mortarcontact.h (frozen values; see docs/abi.md) ----------------------------
const MC_VERSION_MAJOR = 0
const MC_VERSION_MINOR = 1
const MC_VERSION_PATCH = 0
const MC_VERSION_NUMBER = MC_VERSION_MAJOR * 10000 + MC_VERSION_MINOR * 100 + MC_VERSION_PATCH
const MC_VERSION_STRING = "0.1.0"

const MC_OK = Cint(0)
const MC_ERROR_ARGUMENT = Cint(1)
const MC_ERROR_MESH = Cint(2)
const MC_ERROR_MATERIAL = Cint(3)
const MC_ERROR_STATE = Cint(4)
const MC_ERROR_CONTACT = Cint(5)
const MC_ERROR_SINGULAR = Cint(6)
const MC_ERROR_NOT_CONVERGED = Cint(7)
const MC_ERROR_MEMORY = Cint(8)
const MC_ERROR_INTERNAL = Cint(9)
const MC_PLANE_STRAIN = Cint(0)
const MC_PLANE_STRESS = Cint(1)
const MC_AXISYMMETRIC = Cint(2)
const MC_X = Cint(1)
const MC_Y = Cint(2)
const MC_XY = Cint(3)
const MC_OPTION_METHOD = Cint(1)
const MC_OPTION_TOLERANCE = Cint(2)
const MC_OPTION_MAX_ITERATIONS = Cint(3)
const MC_OPTION_ORDERING = Cint(4)
const MC_OPTION_Q1_INTEGRATION = Cint(6)
const MC_OPTION_CONTACT_NORMAL = Cint(7)
const MC_OPTION_CONTACT_SURFACE = Cint(8)
const MC_OPTION_FEATURE_ANGLE = Cint(9)
const MC_OPTION_THREADS = Cint(10)
const MC_OPTION_INTERFACE_SOLVER = Cint(11)
const MC_OPTION_ERROR_ESTIMATE = Cint(12)
const MC_OPTION_MULTIPLIER = Cint(13)
const MC_OPTION_LOAD_STEPS = Cint(14)
const MC_OPTION_FRICTION_CT = Cint(15)
const MC_OPTION_EAGER_RESULTS = Cint(16)
const MC_METHOD_MORTAR = Cint(0)
const MC_METHOD_DUAL_MORTAR = Cint(1)
const MC_METHOD_NODE_TO_SEGMENT = Cint(2)
const MC_NORMAL_NONMORTAR = Cint(0)
const MC_NORMAL_MORTAR = Cint(1)
const MC_SURFACE_SMOOTH = Cint(0)
const MC_SURFACE_FACETED = Cint(1)
const MC_ORDERING_AUTO = Cint(0)
const MC_ORDERING_AMD = Cint(1)
const MC_ORDERING_METIS = Cint(2)
const MC_Q1_FULL = Cint(0)
const MC_Q1_BBAR = Cint(1)
const MC_INTERFACE_AUTO = Cint(0)
const MC_INTERFACE_CONDENSED = Cint(1)
const MC_INTERFACE_SPARSE = Cint(2)
const MC_MULTIPLIER_LINEAR = Cint(0)
const MC_MULTIPLIER_QUADRATIC = Cint(1)
const MC_CONTACT_PRESSURE = Cint(1)
const MC_CONTACT_FORCE = Cint(2)
const MC_CONTACT_GAP = Cint(3)
const MC_CONTACT_INITIAL_GAP = Cint(4)
const MC_CONTACT_NORMAL = Cint(5)
const MC_CONTACT_SHEAR = Cint(6)
const MC_CONTACT_SLIP = Cint(7)
const MC_CONTACT_SLIP_TOTAL = Cint(8)
const MC_CONTACT_STATE = Cint(9)
const MC_STATE_OPEN = Cint(0)
const MC_STATE_STICK = Cint(1)
const MC_STATE_SLIP = Cint(2)
const MC_FRICTION_NONE = Cint(0)
const MC_FRICTION_TRESCA = Cint(1)
const MC_FRICTION_COULOMB = Cint(2)
const MC_MATRIX_FULL = Cint(1)
const MC_MATRIX_TRIANGLE = Cint(2)
const MC_LOG_PHASE = Cint(1)
const MC_LOG_ITERATION = Cint(2)
const MC_INFO_DOFS = Cint(1)
const MC_INFO_FACTOR_NNZ = Cint(2)
const MC_INFO_ITERATIONS = Cint(3)
const MC_INFO_ACTIVE_NODES = Cint(4)
const MC_INFO_CONTACT_NODES = Cint(5)
const MC_INFO_FACTORIZATIONS = Cint(6)
const MC_INFO_INTERFACE_SOLVER = Cint(7)
const MC_INFO_STICK_NODES = Cint(8)
const MC_INFO_SLIP_NODES = Cint(9)
const MC_INFO_TIME_ASSEMBLY = Cint(20)
const MC_INFO_TIME_ANALYSIS = Cint(21)
const MC_INFO_TIME_FACTORIZATION = Cint(22)
const MC_INFO_TIME_SOLVE = Cint(23)
const MC_INFO_TIME_CONTACT = Cint(24)
const MC_INFO_TIME_TOTAL = Cint(25)
const MC_INFO_STRAIN_ENERGY = Cint(26)
const MC_INFO_COMPLEMENTARITY = Cint(27)
const MC_INFO_EQUILIBRIUM = Cint(28)
const MC_INFO_GAP_RESIDUAL = Cint(29)
const MC_INFO_ERROR_ESTIMATE = Cint(30)
const MC_INFO_FRICTION_COMPLEMENTARITY = Cint(31)
const MC_INFO_TIME_RESULTS = Cint(32)

for name in names(@__MODULE__; all=true)
    startswith(String(name), "MC_") && @eval export $name
end

# ---- the C API: one ccall per function of mortarcontact.h, in header order -------------------
# Model handles are Ptr{Cvoid}; a Model converts to one (see unsafe_convert below).

mc_create(model) = ccall((:mc_create, libmortarcontact), Cint, (Ref{Ptr{Cvoid}},), model)
mc_destroy(model) = ccall((:mc_destroy, libmortarcontact), Cvoid, (Ptr{Cvoid},), model)
mc_errmsg(model) = ccall((:mc_errmsg, libmortarcontact), Cstring, (Ptr{Cvoid},), model)
mc_status_string(status) = ccall((:mc_status_string, libmortarcontact), Cstring, (Cint,), status)
mc_version_string() = ccall((:mc_version_string, libmortarcontact), Cstring, ())
mc_version_number() = ccall((:mc_version_number, libmortarcontact), Cint, ())
mc_set_index_base(m, base) =
    ccall((:mc_set_index_base, libmortarcontact), Cint, (Ptr{Cvoid}, Cint), m, base)
mc_set_plane(m, plane, thickness) =
    ccall((:mc_set_plane, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cdouble), m, plane, thickness)
mc_set_mesh(m, body, n_nodes, xy, n_cells, nodes_per_cell, cells) =
    ccall((:mc_set_mesh, libmortarcontact), Cint,
          (Ptr{Cvoid}, Cint, Int32, Ptr{Cdouble}, Int32, Cint, Ptr{Int32}),
          m, body, n_nodes, xy, n_cells, nodes_per_cell, cells)
mc_set_material(m, body, young, poisson) =
    ccall((:mc_set_material, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cdouble, Cdouble),
          m, body, young, poisson)
mc_set_cell_elasticity(m, body, d) =
    ccall((:mc_set_cell_elasticity, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, d)
mc_fix(m, body, n, nodes, components, values) =
    ccall((:mc_fix, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Cint, Ptr{Cdouble}),
          m, body, n, nodes, components, values)
mc_add_traction(m, body, n_edges, edges, traction) =
    ccall((:mc_add_traction, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Ptr{Cdouble}),
          m, body, n_edges, edges, traction)
mc_add_pressure(m, body, n_edges, edges, pressure) =
    ccall((:mc_add_pressure, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Ptr{Cdouble}),
          m, body, n_edges, edges, pressure)
mc_add_nodal_force(m, body, n, nodes, force) =
    ccall((:mc_add_nodal_force, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Ptr{Cdouble}),
          m, body, n, nodes, force)
mc_set_body_force(m, body, fx, fy) =
    ccall((:mc_set_body_force, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cdouble, Cdouble), m, body, fx, fy)
mc_clear_loads(m, body) = ccall((:mc_clear_loads, libmortarcontact), Cint, (Ptr{Cvoid}, Cint), m, body)
mc_set_contact(m, body, n_edges, edges) =
    ccall((:mc_set_contact, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}), m, body, n_edges, edges)
mc_set_gap_offset(m, n, nodes, offset) =
    ccall((:mc_set_gap_offset, libmortarcontact), Cint, (Ptr{Cvoid}, Int32, Ptr{Int32}, Ptr{Cdouble}),
          m, n, nodes, offset)
mc_set_body_count(m, n) = ccall((:mc_set_body_count, libmortarcontact), Cint, (Ptr{Cvoid}, Cint), m, n)
mc_add_contact_pair(m, nonmortar_body, mortar_body, pair) =
    ccall((:mc_add_contact_pair, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cint, Ref{Cint}),
          m, nonmortar_body, mortar_body, pair)
mc_set_pair_surface(m, pair, body, n_edges, edges) =
    ccall((:mc_set_pair_surface, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cint, Int32, Ptr{Int32}),
          m, pair, body, n_edges, edges)
mc_set_pair_surface_curved(m, pair, body, n_edges, edges) =
    ccall((:mc_set_pair_surface_curved, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cint, Int32, Ptr{Int32}),
          m, pair, body, n_edges, edges)
mc_set_pair_gap_offset(m, pair, n, nodes, offset) =
    ccall((:mc_set_pair_gap_offset, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Ptr{Cdouble}),
          m, pair, n, nodes, offset)
mc_get_pair_contact_count(m, pair, n) =
    ccall((:mc_get_pair_contact_count, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ref{Int32}), m, pair, n)
mc_get_pair_contact_nodes(m, pair, nodes) =
    ccall((:mc_get_pair_contact_nodes, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Int32}), m, pair, nodes)
mc_get_pair_contact(m, pair, field, out) =
    ccall((:mc_get_pair_contact, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cint, Ptr{Cdouble}), m, pair, field, out)
mc_set_friction(m, pair, law, value) =
    ccall((:mc_set_friction, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cint, Cdouble), m, pair, law, value)
mc_reset_history(m) = ccall((:mc_reset_history, libmortarcontact), Cint, (Ptr{Cvoid},), m)
mc_set_host_body(m, body, n_nodes, xy, equations, n_equations) =
    ccall((:mc_set_host_body, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Cdouble}, Ptr{Int32}, Int32),
          m, body, n_nodes, xy, equations, n_equations)
mc_add_stiffness(m, body, n_entries, rows, cols, values, storage) =
    ccall((:mc_add_stiffness, libmortarcontact), Cint,
          (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Ptr{Int32}, Ptr{Cdouble}, Cint),
          m, body, n_entries, rows, cols, values, storage)
mc_add_element_matrices(m, body, n_elements, eltptr, eltvar, a_elt) =
    ccall((:mc_add_element_matrices, libmortarcontact), Cint,
          (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}, Ptr{Int32}, Ptr{Cdouble}),
          m, body, n_elements, eltptr, eltvar, a_elt)
mc_set_load_vector(m, body, n_equations, f) =
    ccall((:mc_set_load_vector, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Cdouble}),
          m, body, n_equations, f)
mc_get_equation_solution(m, body, u) =
    ccall((:mc_get_equation_solution, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, u)
mc_get_contact_load(m, body, r) =
    ccall((:mc_get_contact_load, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, r)
mc_set_contact_curved(m, body, n_edges, edges) =
    ccall((:mc_set_contact_curved, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int32, Ptr{Int32}),
          m, body, n_edges, edges)
mc_set_option_int(m, option, value) =
    ccall((:mc_set_option_int, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Int64), m, option, value)
mc_set_option_real(m, option, value) =
    ccall((:mc_set_option_real, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Cdouble), m, option, value)
mc_solve(m) = ccall((:mc_solve, libmortarcontact), Cint, (Ptr{Cvoid},), m)
mc_set_log_callback(m, fn, user_data) =
    ccall((:mc_set_log_callback, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Cvoid}, Ptr{Cvoid}), m, fn, user_data)
mc_get_info_int(m, info, value) =
    ccall((:mc_get_info_int, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ref{Int64}), m, info, value)
mc_get_info_real(m, info, value) =
    ccall((:mc_get_info_real, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ref{Cdouble}), m, info, value)
mc_get_displacement(m, body, u) =
    ccall((:mc_get_displacement, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, u)
mc_get_stress(m, body, sigma) =
    ccall((:mc_get_stress, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, sigma)
mc_get_nodal_stress(m, body, sigma) =
    ccall((:mc_get_nodal_stress, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, sigma)
mc_get_error_indicator(m, body, eta) =
    ccall((:mc_get_error_indicator, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, eta)
mc_get_reaction(m, body, r) =
    ccall((:mc_get_reaction, libmortarcontact), Cint, (Ptr{Cvoid}, Cint, Ptr{Cdouble}), m, body, r)
mc_get_contact_count(m, n) =
    ccall((:mc_get_contact_count, libmortarcontact), Cint, (Ptr{Cvoid}, Ref{Int32}), m, n)
mc_get_contact_nodes(m, nodes) =
    ccall((:mc_get_contact_nodes, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Int32}), m, nodes)
mc_get_contact_pressure(m, p) =
    ccall((:mc_get_contact_pressure, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Cdouble}), m, p)
mc_get_contact_force(m, f) =
    ccall((:mc_get_contact_force, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Cdouble}), m, f)
mc_get_contact_gap(m, g) =
    ccall((:mc_get_contact_gap, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Cdouble}), m, g)
mc_get_contact_initial_gap(m, g0) =
    ccall((:mc_get_contact_initial_gap, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Cdouble}), m, g0)
mc_get_contact_normal(m, n) =
    ccall((:mc_get_contact_normal, libmortarcontact), Cint, (Ptr{Cvoid}, Ptr{Cdouble}), m, n)
mc_write_vtu(m, path) = ccall((:mc_write_vtu, libmortarcontact), Cint, (Ptr{Cvoid}, Cstring), m, path)

# ---- the Julia API ---------------------------------------------------------------------------

"""A failed call: `status` is the `mc_status` code (`MC_ERROR_*`), `message` the library's
(or the binding's) message."""
struct MortarContactError <: Exception
    status::Int
    message::String
end
Base.showerror(io::IO, e::MortarContactError) = print(io, status_string(e.status), ": ", e.message)

"""The library's English name of a status code."""
status_string(status::Integer) = unsafe_string(mc_status_string(Cint(status)))
"""The loaded library's version, "MAJOR.MINOR.PATCH"."""
version_string() = unsafe_string(mc_version_string())
"""The loaded library's version as MAJOR*10000+MINOR*100+PATCH."""
version_number() = Int(mc_version_number())

"""
    Model(; index_base=1)
    Model(f; index_base=1)   # do-block: closes the model afterwards

One scene (`mc_model`). Freed by `close(m)` or, failing that, by its finalizer.
"""
mutable struct Model
    ptr::Ptr{Cvoid}
    n_nodes::Vector{Int}   # per body 1..N (N = 2 until set_body_count!); -1 = no mesh or host body yet
    n_cells::Vector{Int}   # 0 for a host body
    n_equations::Vector{Int}  # a host body's system size; 0 for a mesh body
    base::Int              # the index base set through this Model
    log::Union{Nothing,Base.RefValue{Any}}  # the log callable; the C library holds a pointer to it
    function Model(; index_base::Integer=1)
        r = Ref{Ptr{Cvoid}}(C_NULL)
        st = mc_create(r)
        st == MC_OK || throw(MortarContactError(st, "mc_create failed"))
        m = new(r[], [-1, -1], [-1, -1], [0, 0], 0, nothing)
        finalizer(close, m)
        set_index_base!(m, index_base)
        return m
    end
end

function Model(f::Function; index_base::Integer=1)
    m = Model(; index_base=index_base)
    try
        return f(m)
    finally
        close(m)
    end
end

function Base.close(m::Model)
    if m.ptr != C_NULL
        mc_destroy(m.ptr)
        m.ptr = C_NULL
    end
    return nothing
end

# ccall keeps `m` alive for the duration of the call when it is passed itself.
function Base.unsafe_convert(::Type{Ptr{Cvoid}}, m::Model)
    m.ptr == C_NULL && throw(MortarContactError(MC_ERROR_STATE, "the model is closed"))
    return m.ptr
end

"""The message of the last call on the model ("" after a success)."""
errmsg(m::Model) = unsafe_string(mc_errmsg(m))

function check(m::Model, status)
    status == MC_OK || throw(MortarContactError(status, errmsg(m)))
    return nothing
end

argerror(msg) = throw(MortarContactError(MC_ERROR_ARGUMENT, msg))

function checkbody(m::Model, body, what)
    1 <= body <= length(m.n_nodes) || argerror("$what: body must be 1 to $(length(m.n_nodes)), got $body")
    m.n_nodes[body] >= 0 ||
        throw(MortarContactError(MC_ERROR_STATE, "$what: no mesh or host body set for body $body"))
    return nothing
end

function checkshape(a, want, what)
    size(a) == want || argerror("$what must have size $want, got $(size(a))")
    return nothing
end

reals(a) = convert(Array{Cdouble}, a)      # contiguous Float64 copy (no copy if already one)
ids(a) = convert(Array{Int32}, a)          # throws InexactError for ids beyond Int32

function set_index_base!(m::Model, base::Integer)
    check(m, mc_set_index_base(m, base))
    m.base = base
    return nothing
end
set_plane!(m::Model, plane::Integer, thickness::Real=1.0) = check(m, mc_set_plane(m, plane, thickness))

"""`xy`: 2×n_nodes; `cells`: 3×n_cells (P1), 4×n_cells (Q1), 6×n_cells (T6), 8×n_cells (Q8) or
9×n_cells (Q9): corners counter-clockwise, then the mid-edge nodes (and the Q9 centre), in
Gmsh's and VTK's order (see `mc_set_mesh` in the header)."""
function set_mesh!(m::Model, body::Integer, xy::AbstractMatrix{<:Real}, cells::AbstractMatrix{<:Integer})
    size(xy, 1) == 2 || argerror("xy must be 2×n_nodes, got $(size(xy))")
    x, c = reals(xy), ids(cells)
    check(m, mc_set_mesh(m, body, size(x, 2), x, size(c, 2), size(c, 1), c))
    if 1 <= body <= length(m.n_nodes)
        m.n_nodes[body] = size(x, 2)
        m.n_cells[body] = size(c, 2)
        m.n_equations[body] = 0
    end
    return nothing
end

set_material!(m::Model, body::Integer, young::Real, poisson::Real) =
    check(m, mc_set_material(m, body, young, poisson))

"""`d`: 3×3×n_cells symmetric positive definite matrices (Voigt xx, yy, xy)."""
function set_cell_elasticity!(m::Model, body::Integer, d::AbstractArray{<:Real,3})
    checkbody(m, body, "set_cell_elasticity!")
    checkshape(d, (3, 3, m.n_cells[body]), "d")
    check(m, mc_set_cell_elasticity(m, body, reals(d)))
end

"""Prescribes the `components` (MC_X, MC_Y, MC_XY) of `nodes`; `values` 2×n or `nothing` (zero)."""
function fix!(m::Model, body::Integer, nodes::AbstractVector{<:Integer}, components::Integer=MC_XY,
              values::Union{Nothing,AbstractMatrix{<:Real}}=nothing)
    n = ids(nodes)
    if values === nothing
        check(m, mc_fix(m, body, length(n), n, components, C_NULL))
    else
        checkshape(values, (2, length(n)), "values")
        check(m, mc_fix(m, body, length(n), n, components, reals(values)))
    end
end

"""`edges`: 2×n_edges; `traction`: 2×n_edges, force per unit length."""
function add_traction!(m::Model, body::Integer, edges::AbstractMatrix{<:Integer}, traction::AbstractMatrix{<:Real})
    checkshape(edges, (2, size(edges, 2)), "edges")
    checkshape(traction, (2, size(edges, 2)), "traction")
    check(m, mc_add_traction(m, body, size(edges, 2), ids(edges), reals(traction)))
end

"""`edges`: 2×n_edges; `pressure`: n_edges values, > 0 pushes into the body."""
function add_pressure!(m::Model, body::Integer, edges::AbstractMatrix{<:Integer}, pressure::AbstractVector{<:Real})
    checkshape(edges, (2, size(edges, 2)), "edges")
    checkshape(pressure, (size(edges, 2),), "pressure")
    check(m, mc_add_pressure(m, body, size(edges, 2), ids(edges), reals(pressure)))
end

"""`force`: 2×length(nodes)."""
function add_nodal_force!(m::Model, body::Integer, nodes::AbstractVector{<:Integer}, force::AbstractMatrix{<:Real})
    checkshape(force, (2, length(nodes)), "force")
    check(m, mc_add_nodal_force(m, body, length(nodes), ids(nodes), reals(force)))
end

set_body_force!(m::Model, body::Integer, fx::Real, fy::Real) = check(m, mc_set_body_force(m, body, fx, fy))
clear_loads!(m::Model, body::Integer) = check(m, mc_clear_loads(m, body))

"""Candidate contact surface, `edges` 2×n_edges; body 1 non-mortar, body 2 mortar (contact pair
1, made as (1, 2) if the model has no pair yet)."""
function set_contact!(m::Model, body::Integer, edges::AbstractMatrix{<:Integer})
    checkshape(edges, (2, size(edges, 2)), "edges")
    check(m, mc_set_contact(m, body, size(edges, 2), ids(edges)))
end

# ---- assemblies: bodies 1..N and contact pairs --------------------------------------------------

"""The number of bodies, `n` ≥ 2 (default 2). Growing keeps the bodies there are; shrinking drops the
last ones (`MC_ERROR_STATE` while a contact pair uses one of them)."""
function set_body_count!(m::Model, n::Integer)
    check(m, mc_set_body_count(m, n))
    for (sizes, none) in ((m.n_nodes, -1), (m.n_cells, -1), (m.n_equations, 0))
        old = length(sizes)
        resize!(sizes, n)
        n > old && fill!(view(sizes, old+1:n), none)
    end
    return nothing
end

"""Makes a contact pair between two different bodies and returns its number (1, 2, ... in the order
made, whatever the index base). The non-mortar body carries the constraint, the mortar body is the
surface it is measured against."""
function add_contact_pair!(m::Model, nonmortar_body::Integer, mortar_body::Integer)
    pair = Ref{Cint}(0)
    check(m, mc_add_contact_pair(m, nonmortar_body, mortar_body, pair))
    return Int(pair[])
end

"""One side of a pair: `body` its non-mortar or mortar body, `edges` 2×n_edges (as `set_contact!`).
Replaces that side's earlier edges."""
function set_pair_surface!(m::Model, pair::Integer, body::Integer, edges::AbstractMatrix{<:Integer})
    checkshape(edges, (2, size(edges, 2)), "edges")
    check(m, mc_set_pair_surface(m, pair, body, size(edges, 2), ids(edges)))
end

"""One side of a pair of quadratic edges, `edges` 3×n_edges: end, end, middle (as `set_contact_curved!`)."""
function set_pair_surface_curved!(m::Model, pair::Integer, body::Integer, edges::AbstractMatrix{<:Integer})
    checkshape(edges, (3, size(edges, 2)), "edges")
    check(m, mc_set_pair_surface_curved(m, pair, body, size(edges, 2), ids(edges)))
end

"""Adds `offset` to the initial gap of the pair's non-mortar `nodes` (as `set_gap_offset!` for pair 1)."""
function set_pair_gap_offset!(m::Model, pair::Integer, nodes::AbstractVector{<:Integer}, offset::AbstractVector{<:Real})
    checkshape(offset, (length(nodes),), "offset")
    check(m, mc_set_pair_gap_offset(m, pair, length(nodes), ids(nodes), reals(offset)))
end

# ---- friction ------------------------------------------------------------------------------------

"""
    set_friction!(m, pair, law, value=0.0)

The friction law of contact pair `pair` (1 for the two-body model's pair): `MC_FRICTION_COULOMB`
(`value`: μ ≥ 0), `MC_FRICTION_TRESCA` (`value`: the slip bound, a shear traction ≥ 0) or
`MC_FRICTION_NONE` (the default). Each `solve!` of a model with friction is a step from the last
converged state, in `MC_OPTION_LOAD_STEPS` increments; `reset_history!` returns to the unloaded state.
"""
set_friction!(m::Model, pair::Integer, law::Integer, value::Real=0.0) =
    check(m, mc_set_friction(m, pair, law, Cdouble(value)))

"""Forgets the converged state: the next solve starts from the unloaded state (u = 0, loads 0,
accumulated slip 0)."""
reset_history!(m::Model) = check(m, mc_reset_history(m))

# ---- host bodies: a legacy program's own matrices ----------------------------------------------

"""
    set_host_body!(m, body, xy, equations, n_equations)

Makes `body` a host body (no cells): `xy` 2×n_nodes, the nodes the contact surface and the rigid
modes need; `equations` 2×n_nodes, the host's equation number of each node's x and y freedom
counted from the index base (1 by default: Smith and Griffiths' `nf` after numbering, 0 meaning
restrained, can be passed as it is; a number below the base: no equation); `n_equations` the size
of the host's system.
"""
function set_host_body!(m::Model, body::Integer, xy::AbstractMatrix{<:Real}, equations::AbstractMatrix{<:Integer},
                        n_equations::Integer)
    size(xy, 1) == 2 || argerror("xy must be 2×n_nodes, got $(size(xy))")
    checkshape(equations, (2, size(xy, 2)), "equations")
    x, eq = reals(xy), ids(equations)
    check(m, mc_set_host_body(m, body, size(x, 2), x, eq, n_equations))
    if 1 <= body <= length(m.n_nodes)
        m.n_nodes[body] = size(x, 2)
        m.n_cells[body] = 0
        m.n_equations[body] = n_equations
    end
    return nothing
end

"""
    add_stiffness!(m, body, K; storage=MC_MATRIX_FULL)
    add_stiffness!(m, body, rows, cols, values; storage=MC_MATRIX_FULL)

Adds entries to a host body's stiffness (repeated calls add, duplicates are summed). `K`: a
`SparseMatrixCSC` (its stored entries) or any other matrix (converted with `sparse`), n_equations
square, row i being equation i - 1 + the index base; or coordinate vectors `rows`, `cols`
(equation numbers from the index base; below the base: skipped) and `values`. `storage`:
`MC_MATRIX_FULL` (both triangles, symmetric to round-off) or `MC_MATRIX_TRIANGLE` (one triangle,
either, each off-diagonal pair once: e.g. `triu(K)`).
"""
function add_stiffness!(m::Model, body::Integer, rows::AbstractVector{<:Integer}, cols::AbstractVector{<:Integer},
                        values::AbstractVector{<:Real}; storage::Integer=MC_MATRIX_FULL)
    checkshape(cols, (length(rows),), "cols")
    checkshape(values, (length(rows),), "values")
    check(m, mc_add_stiffness(m, body, length(rows), ids(rows), ids(cols), reals(values), storage))
end

function add_stiffness!(m::Model, body::Integer, K::AbstractMatrix{<:Real}; storage::Integer=MC_MATRIX_FULL)
    size(K, 1) == size(K, 2) || argerror("the stiffness matrix must be square, got $(size(K))")
    if 1 <= body <= length(m.n_nodes) && m.n_equations[body] > 0 && size(K, 1) != m.n_equations[body]
        argerror("the stiffness matrix must be $(m.n_equations[body])×$(m.n_equations[body]) " *
                 "(n_equations of body $body), got $(size(K))")
    end
    S = K isa SparseMatrixCSC ? K : sparse(K)
    I, J, V = findnz(S)
    shift = m.base - 1  # Julia's row 1 is the equation numbered by the index base
    add_stiffness!(m, body, I .+ shift, J .+ shift, V; storage=storage)
end

"""
    add_element_matrices!(m, body, eltptr, eltvar, a_elt)
    add_element_matrices!(m, body, g_g, storkm)

Adds element matrices to a host body's stiffness. MUMPS's elemental form: `eltptr` (n_elements
+ 1 entries, counted from the index base), element e's equations
`eltvar[eltptr[e] - base + 1 : eltptr[e + 1] - base]` (below the base: restrained, skipped),
`a_elt` each element's square matrix column by column, one after the other. Or elements of one
size k as Smith and Griffiths store them: `g_g` k×n_elements (a column of equations per element,
0 = restrained with the default base 1) and `storkm` k×k×n_elements, passed without reshaping.
"""
function add_element_matrices!(m::Model, body::Integer, eltptr::AbstractVector{<:Integer},
                               eltvar::AbstractVector{<:Integer}, a_elt::AbstractVector{<:Real})
    isempty(eltptr) && argerror("eltptr needs n_elements + 1 entries, got none")
    first(eltptr) == m.base || argerror("eltptr[1] = $(first(eltptr)), expected the index base $(m.base)")
    sizes = diff(Int64.(collect(eltptr)))
    k = findfirst(<(0), sizes)
    k === nothing || argerror("eltptr[$(k + 1)] = $(eltptr[k + 1]) is below eltptr[$k] = $(eltptr[k])")
    checkshape(eltvar, (Int(last(eltptr) - m.base),), "eltvar")
    checkshape(a_elt, (Int(sum(sizes .^ 2)),), "a_elt")
    check(m, mc_add_element_matrices(m, body, length(eltptr) - 1, ids(eltptr), ids(eltvar), reals(a_elt)))
end

function add_element_matrices!(m::Model, body::Integer, g_g::AbstractMatrix{<:Integer}, storkm::AbstractArray{<:Real,3})
    k, n_elements = size(g_g)
    checkshape(storkm, (k, k, n_elements), "storkm")
    eltptr = [m.base + k * e for e in 0:n_elements]
    check(m, mc_add_element_matrices(m, body, n_elements, ids(eltptr), ids(g_g), reals(storkm)))
end

"""The load of a host body, `f` (n_equations values) in the host's equation order (replaces the previous one)."""
set_load_vector!(m::Model, body::Integer, f::AbstractVector{<:Real}) =
    check(m, mc_set_load_vector(m, body, length(f), reals(f)))

"""Candidate contact surface of quadratic edges, `edges` 3×n_edges: end, end, middle. A host
body's edges run with the body on their left; a mesh body's are boundary edges of cells with
that middle node."""
function set_contact_curved!(m::Model, body::Integer, edges::AbstractMatrix{<:Integer})
    checkshape(edges, (3, size(edges, 2)), "edges")
    check(m, mc_set_contact_curved(m, body, size(edges, 2), ids(edges)))
end

set_option_int!(m::Model, option::Integer, value::Integer) = check(m, mc_set_option_int(m, option, value))
set_option_real!(m::Model, option::Integer, value::Real) = check(m, mc_set_option_real(m, option, value))
solve!(m::Model) = check(m, mc_solve(m))

"""Adds `offset` (lengths: > 0 clearance, < 0 interference) to the initial gap of the body-1
contact `nodes`; replaces earlier offsets of those nodes."""
function set_gap_offset!(m::Model, nodes::AbstractVector{<:Integer}, offset::AbstractVector{<:Real})
    checkshape(offset, (length(nodes),), "offset")
    check(m, mc_set_gap_offset(m, length(nodes), ids(nodes), reals(offset)))
end

# The C callback: user_data points to the Model's RefValue holding the Julia callable. An
# exception must not unwind into C: it is logged and dropped.
function log_trampoline(user_data::Ptr{Cvoid}, level::Cint, message::Cstring)::Cvoid
    holder = unsafe_pointer_to_objref(user_data)::Base.RefValue{Any}
    try
        holder[](Int(level), unsafe_string(message))
    catch err
        @error "mortarcontact: the log callback failed" exception = err
    end
    return nothing
end

"""
    set_log_callback!(m, f)

Calls `f(level, message)` (level `MC_LOG_PHASE` or `MC_LOG_ITERATION`, message a one-line
String) with the progress of `solve!`; `nothing` removes the callback.
"""
function set_log_callback!(m::Model, f)
    if f === nothing
        check(m, mc_set_log_callback(m, C_NULL, C_NULL))
        m.log = nothing
        return nothing
    end
    holder = Ref{Any}(f)
    fn = @cfunction(log_trampoline, Cvoid, (Ptr{Cvoid}, Cint, Cstring))
    check(m, mc_set_log_callback(m, fn, pointer_from_objref(holder)))
    m.log = holder  # keeps the callable alive as long as the model uses it
    return nothing
end

function get_info_int(m::Model, info::Integer)
    v = Ref{Int64}(0)
    check(m, mc_get_info_int(m, info, v))
    return v[]
end

function get_info_real(m::Model, info::Integer)
    v = Ref{Cdouble}(0.0)
    check(m, mc_get_info_real(m, info, v))
    return v[]
end

function per_body(f, m::Model, body, rows, count, what)
    checkbody(m, body, what)
    out = Matrix{Cdouble}(undef, rows, count(body))
    check(m, f(m, body, out))
    return out
end

"""Displacements, 2×n_nodes."""
get_displacement(m::Model, body::Integer) = per_body(mc_get_displacement, m, body, 2, b -> m.n_nodes[b], "get_displacement")
"""Cell-averaged stresses, 4×n_cells (xx, yy, xy, zz)."""
get_stress(m::Model, body::Integer) = per_body(mc_get_stress, m, body, 4, b -> m.n_cells[b], "get_stress")
"""Stresses at the nodes, 4×n_nodes (xx, yy, xy, zz): each cell's stress at its nodes, averaged over the cells."""
get_nodal_stress(m::Model, body::Integer) = per_body(mc_get_nodal_stress, m, body, 4, b -> m.n_nodes[b], "get_nodal_stress")
"""The cells' error indicators, a vector of n_cells: relative like `MC_INFO_ERROR_ESTIMATE`, their squares
over both bodies adding up to its square. `MC_ERROR_STATE` before a solve, for a host body, or when
`MC_OPTION_ERROR_ESTIMATE` is 0."""
get_error_indicator(m::Model, body::Integer) =
    vec(per_body(mc_get_error_indicator, m, body, 1, b -> m.n_cells[b], "get_error_indicator"))
"""Support reactions, 2×n_nodes."""
get_reaction(m::Model, body::Integer) = per_body(mc_get_reaction, m, body, 2, b -> m.n_nodes[b], "get_reaction")

# The length of a body's equation vectors: n_equations (host body) or 2 n_nodes (mesh body).
equation_count(m::Model, body) = m.n_equations[body] > 0 ? m.n_equations[body] : 2 * m.n_nodes[body]

"""The displacements in equation order: n_equations values for a host body (the host's
numbering), 2 per node (x, y) for a mesh body."""
get_equation_solution(m::Model, body::Integer) =
    vec(per_body(mc_get_equation_solution, m, body, 1, b -> equation_count(m, b), "get_equation_solution"))
"""The contact forces on the body as a load vector in its equation order (sized as
`get_equation_solution`): K u = f + r on the free equations."""
get_contact_load(m::Model, body::Integer) =
    vec(per_body(mc_get_contact_load, m, body, 1, b -> equation_count(m, b), "get_contact_load"))

"""Number of body-1 contact nodes."""
function get_contact_count(m::Model)
    n = Ref{Int32}(0)
    check(m, mc_get_contact_count(m, n))
    return Int(n[])
end

function contact_array(f, m::Model, T, rows)
    n = get_contact_count(m)
    out = rows == 1 ? Vector{T}(undef, n) : Matrix{T}(undef, rows, n)
    check(m, f(m, out))
    return out
end

get_contact_nodes(m::Model) = contact_array(mc_get_contact_nodes, m, Int32, 1)
get_contact_pressure(m::Model) = contact_array(mc_get_contact_pressure, m, Cdouble, 1)
get_contact_force(m::Model) = contact_array(mc_get_contact_force, m, Cdouble, 1)
get_contact_gap(m::Model) = contact_array(mc_get_contact_gap, m, Cdouble, 1)
get_contact_initial_gap(m::Model) = contact_array(mc_get_contact_initial_gap, m, Cdouble, 1)
"""Unit outward normals of body 1 at the contact nodes, 2×n_contact."""
get_contact_normal(m::Model) = contact_array(mc_get_contact_normal, m, Cdouble, 2)

"""After a solve: the number of the pair's contact positions (the length of its contact arrays)."""
function get_pair_contact_count(m::Model, pair::Integer)
    n = Ref{Int32}(0)
    check(m, mc_get_pair_contact_count(m, pair, n))
    return Int(n[])
end

"""The node ids of the pair's contact positions on its non-mortar body (index base applies)."""
function get_pair_contact_nodes(m::Model, pair::Integer)
    out = Vector{Int32}(undef, get_pair_contact_count(m, pair))
    check(m, mc_get_pair_contact_nodes(m, pair, out))
    return out
end

"""A field of the pair's contact positions: `MC_CONTACT_PRESSURE`, `MC_CONTACT_FORCE`, `MC_CONTACT_GAP`,
`MC_CONTACT_INITIAL_GAP` as a vector (as the `get_contact_*` getter of the same name), or
`MC_CONTACT_NORMAL` as 2×n_contact; friction: `MC_CONTACT_SHEAR`, `MC_CONTACT_SLIP`,
`MC_CONTACT_SLIP_TOTAL`, `MC_CONTACT_STATE` (`MC_STATE_OPEN`, `_STICK`, `_SLIP` as Float64) as vectors."""
function get_pair_contact(m::Model, pair::Integer, field::Integer)
    n = get_pair_contact_count(m, pair)
    out = field == MC_CONTACT_NORMAL ? Matrix{Cdouble}(undef, 2, n) : Vector{Cdouble}(undef, n)
    check(m, mc_get_pair_contact(m, pair, field, out))
    return out
end

"""Writes the solved scene for ParaView: a path ending in ".pvd" gives a collection plus
"<stem>_body1.vtu" and "<stem>_body2.vtu"; any other path one .vtu with both bodies."""
write_vtu(m::Model, path::AbstractString) = check(m, mc_write_vtu(m, path))

end # module
