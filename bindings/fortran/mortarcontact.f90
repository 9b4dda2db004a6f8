!> Fortran 2008 bindings of mortarcontact (include/mortarcontact.h) on iso_c_binding.
!>
!> Every C function has a wrapper of the same name taking a type(mc_model) instead of the
!> C pointer. Differences from the C API, all in the caller's favour:
!>  - ids are 1-based: mc_create sets the model's index base to 1 (mc_set_index_base can
!>    change it back; the wrappers pass ids through unchanged);
!>  - arrays are assumed-shape, one column per node/cell/edge: xy(2, n_nodes),
!>    cells(nodes_per_cell, n_cells), edges(2, n_edges), d(3, 3, n_cells), u(2, n_nodes),
!>    sigma(4, n_cells) (mc_get_nodal_stress: sigma(4, n_nodes)), eta(n_cells), a contact pair's
!>    values(n_contact) (MC_CONTACT_NORMAL: values(2, n_contact)); the counts
!>    come from the shapes, and each shape is checked before the C call: a wrong one returns
!>    MC_ERROR_ARGUMENT (MC_ERROR_STATE when the body has no mesh yet) with a message, and
!>    the C library is not called;
!>  - functions return the status as a default integer (MC_OK = 0); mc_errmsg(model)
!>    returns the message of the last failed call as a Fortran string ('' after a success);
!>  - strings (mc_errmsg, mc_status_string, mc_version_string) are Fortran strings;
!>  - mc_set_option_int and mc_get_info_int accept default (32-bit) or 64-bit integers;
!>  - host bodies take the host's 1-based arrays: equations(2, n_nodes) is Smith and Griffiths'
!>    nf after numbering (0 = restrained, below the base 1), equation vectors are f(n_equations)
!>    (a host's loads(0:neq) passes as loads(1:)), and mc_add_element_matrices_sg takes S&G's
!>    g_g(ndof, nels) and storkm(ndof, ndof, nels) as they are (no copy with base 1).
!> The header's MC_VERSION_NUMBER / MC_VERSION_STRING are MC_HEADER_VERSION_NUMBER /
!> MC_HEADER_VERSION_STRING here (Fortran names are case-insensitive, and mc_version_number
!> / mc_version_string are the functions).
!>
!> Free a model with mc_destroy (there is no finalizer: a type(mc_model) may be copied).
!>
!> Standard: Fortran 2008 with no extensions (the build compiles it with gfortran -std=f2008).
!> Build: gfortran -c mortarcontact.f90, then link the program with -lmortarcontact.
module mortarcontact
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_f_pointer, c_char, &
       c_int, c_int32_t, c_int64_t, c_double, c_size_t, c_funptr, c_funloc, c_null_funptr, c_null_char
  implicit none
  private

  integer, parameter, public :: mc_int = c_int32_t   !< kind of node, cell and edge ids
  integer, parameter, public :: mc_int64 = c_int64_t !< kind of 64-bit option values and infos
  integer, parameter, public :: mc_real = c_double   !< kind of every real

  ! ---- constants of mortarcontact.h (values frozen by the ABI, see docs/abi.md) ----------
  integer, parameter, public :: MC_VERSION_MAJOR = 0, MC_VERSION_MINOR = 1, MC_VERSION_PATCH = 0
  integer, parameter, public :: MC_HEADER_VERSION_NUMBER = &
       MC_VERSION_MAJOR * 10000 + MC_VERSION_MINOR * 100 + MC_VERSION_PATCH
  character(len=*), parameter, public :: MC_HEADER_VERSION_STRING = "0.1.0"

  integer, parameter, public :: MC_OK = 0, MC_ERROR_ARGUMENT = 1, MC_ERROR_MESH = 2, &
       MC_ERROR_MATERIAL = 3, MC_ERROR_STATE = 4, MC_ERROR_CONTACT = 5, MC_ERROR_SINGULAR = 6, &
       MC_ERROR_NOT_CONVERGED = 7, MC_ERROR_MEMORY = 8, MC_ERROR_INTERNAL = 9
  integer, parameter, public :: MC_PLANE_STRAIN = 0, MC_PLANE_STRESS = 1, MC_AXISYMMETRIC = 2
  integer, parameter, public :: MC_X = 1, MC_Y = 2, MC_XY = 3
  integer, parameter, public :: MC_OPTION_METHOD = 1, MC_OPTION_TOLERANCE = 2, &
       MC_OPTION_MAX_ITERATIONS = 3, MC_OPTION_ORDERING = 4, MC_OPTION_Q1_INTEGRATION = 6, &
       MC_OPTION_CONTACT_NORMAL = 7, MC_OPTION_CONTACT_SURFACE = 8, MC_OPTION_FEATURE_ANGLE = 9, &
       MC_OPTION_THREADS = 10, MC_OPTION_INTERFACE_SOLVER = 11, MC_OPTION_ERROR_ESTIMATE = 12, &
       MC_OPTION_MULTIPLIER = 13, MC_OPTION_LOAD_STEPS = 14, MC_OPTION_FRICTION_CT = 15, &
       MC_OPTION_EAGER_RESULTS = 16
  integer, parameter, public :: MC_METHOD_MORTAR = 0, MC_METHOD_DUAL_MORTAR = 1, &
       MC_METHOD_NODE_TO_SEGMENT = 2
  integer, parameter, public :: MC_NORMAL_NONMORTAR = 0, MC_NORMAL_MORTAR = 1
  integer, parameter, public :: MC_SURFACE_SMOOTH = 0, MC_SURFACE_FACETED = 1
  integer, parameter, public :: MC_ORDERING_AUTO = 0, MC_ORDERING_AMD = 1, MC_ORDERING_METIS = 2
  integer, parameter, public :: MC_Q1_FULL = 0, MC_Q1_BBAR = 1
  integer, parameter, public :: MC_INTERFACE_AUTO = 0, MC_INTERFACE_CONDENSED = 1, &
       MC_INTERFACE_SPARSE = 2
  integer, parameter, public :: MC_MULTIPLIER_LINEAR = 0, MC_MULTIPLIER_QUADRATIC = 1
  integer, parameter, public :: MC_CONTACT_PRESSURE = 1, MC_CONTACT_FORCE = 2, MC_CONTACT_GAP = 3, &
       MC_CONTACT_INITIAL_GAP = 4, MC_CONTACT_NORMAL = 5, MC_CONTACT_SHEAR = 6, MC_CONTACT_SLIP = 7, &
       MC_CONTACT_SLIP_TOTAL = 8, MC_CONTACT_STATE = 9
  integer, parameter, public :: MC_STATE_OPEN = 0, MC_STATE_STICK = 1, MC_STATE_SLIP = 2
  integer, parameter, public :: MC_FRICTION_NONE = 0, MC_FRICTION_TRESCA = 1, MC_FRICTION_COULOMB = 2
  integer, parameter, public :: MC_MATRIX_FULL = 1, MC_MATRIX_TRIANGLE = 2
  integer, parameter, public :: MC_LOG_PHASE = 1, MC_LOG_ITERATION = 2
  integer, parameter, public :: MC_INFO_DOFS = 1, MC_INFO_FACTOR_NNZ = 2, MC_INFO_ITERATIONS = 3, &
       MC_INFO_ACTIVE_NODES = 4, MC_INFO_CONTACT_NODES = 5, MC_INFO_FACTORIZATIONS = 6, &
       MC_INFO_INTERFACE_SOLVER = 7, MC_INFO_STICK_NODES = 8, MC_INFO_SLIP_NODES = 9, &
       MC_INFO_TIME_ASSEMBLY = 20, MC_INFO_TIME_ANALYSIS = 21, MC_INFO_TIME_FACTORIZATION = 22, &
       MC_INFO_TIME_SOLVE = 23, MC_INFO_TIME_CONTACT = 24, MC_INFO_TIME_TOTAL = 25, &
       MC_INFO_STRAIN_ENERGY = 26, MC_INFO_COMPLEMENTARITY = 27, MC_INFO_EQUILIBRIUM = 28, &
       MC_INFO_GAP_RESIDUAL = 29, MC_INFO_ERROR_ESTIMATE = 30, MC_INFO_FRICTION_COMPLEMENTARITY = 31, &
       MC_INFO_TIME_RESULTS = 32

  !> One scene (mc_model). Create with mc_create, free with mc_destroy.
  type, public :: mc_model
     private
     type(c_ptr) :: ptr = c_null_ptr
     ! per body 1..N (N = 2 until mc_set_body_count; unallocated before mc_create):
     integer(mc_int), allocatable :: n_nodes(:)   ! mesh sizes, known from successful mc_set_mesh
     integer(mc_int), allocatable :: n_cells(:)   ! calls (and mc_set_host_body calls: no cells); -1: none
     integer(mc_int), allocatable :: n_equations(:)  ! a host body's system size; 0 for a mesh body
     integer :: base = 1                  ! the index base set through the wrapper
     character(len=:), allocatable :: msg ! message of the last failed call
  end type mc_model

  public :: mc_create, mc_destroy, mc_errmsg, mc_status_string, mc_version_string, mc_version_number
  public :: mc_set_index_base, mc_set_plane, mc_set_mesh, mc_set_material, mc_set_cell_elasticity
  public :: mc_fix, mc_add_traction, mc_add_pressure, mc_add_nodal_force, mc_set_body_force
  public :: mc_clear_loads, mc_set_contact, mc_set_option_int, mc_set_option_real, mc_solve
  public :: mc_get_info_int, mc_get_info_real, mc_get_displacement, mc_get_stress, mc_get_reaction
  public :: mc_get_nodal_stress, mc_get_error_indicator
  public :: mc_get_contact_count, mc_get_contact_nodes, mc_get_contact_pressure
  public :: mc_get_contact_force, mc_get_contact_gap, mc_get_contact_initial_gap
  public :: mc_get_contact_normal
  public :: mc_set_gap_offset, mc_set_log_callback, mc_write_vtu, mc_log_fn, mc_log_message
  public :: mc_set_host_body, mc_add_stiffness, mc_add_element_matrices, mc_add_element_matrices_sg
  public :: mc_set_load_vector, mc_get_equation_solution, mc_get_contact_load, mc_set_contact_curved
  public :: mc_set_body_count, mc_add_contact_pair, mc_set_pair_surface, mc_set_pair_surface_curved
  public :: mc_set_pair_gap_offset, mc_get_pair_contact_count, mc_get_pair_contact_nodes, mc_get_pair_contact
  public :: mc_set_friction, mc_reset_history

  !> The log callback (mc_set_log_callback): a bind(C) subroutine of this interface, e.g.
  !>   subroutine my_log(user_data, level, message) bind(C)
  !>     type(c_ptr), value :: user_data; integer(c_int), value :: level
  !>     character(kind=c_char), intent(in) :: message(*)
  !>     print '(a)', mc_log_message(message)
  !> level is MC_LOG_PHASE or MC_LOG_ITERATION; message is NUL-terminated, valid during the call.
  abstract interface
     subroutine mc_log_fn(user_data, level, message) bind(C)
       import :: c_ptr, c_int, c_char
       type(c_ptr), value :: user_data
       integer(c_int), value :: level
       character(kind=c_char), intent(in) :: message(*)
     end subroutine
  end interface

  !> Sets an integer option; value may be a default or a 64-bit integer.
  interface mc_set_option_int
     module procedure set_option_int32, set_option_int64
  end interface mc_set_option_int
  !> Gets an integer info; value may be a default or a 64-bit integer.
  interface mc_get_info_int
     module procedure get_info_int32, get_info_int64
  end interface mc_get_info_int
  !> A field of a pair's contact positions: values(n_contact), or values(2, n_contact) for
  !> MC_CONTACT_NORMAL.
  interface mc_get_pair_contact
     module procedure get_pair_contact_1, get_pair_contact_2
  end interface mc_get_pair_contact

  ! ---- the C API, one interface per function of mortarcontact.h ----------------------------
  interface
     integer(c_int) function c_mc_create(model) bind(C, name="mc_create")
       import :: c_ptr, c_int
       type(c_ptr), intent(out) :: model
     end function
     subroutine c_mc_destroy(model) bind(C, name="mc_destroy")
       import :: c_ptr
       type(c_ptr), value :: model
     end subroutine
     type(c_ptr) function c_mc_errmsg(model) bind(C, name="mc_errmsg")
       import :: c_ptr
       type(c_ptr), value :: model
     end function
     type(c_ptr) function c_mc_status_string(status) bind(C, name="mc_status_string")
       import :: c_ptr, c_int
       integer(c_int), value :: status
     end function
     type(c_ptr) function c_mc_version_string() bind(C, name="mc_version_string")
       import :: c_ptr
     end function
     integer(c_int) function c_mc_version_number() bind(C, name="mc_version_number")
       import :: c_int
     end function
     integer(c_int) function c_mc_set_index_base(m, base) bind(C, name="mc_set_index_base")
       import :: c_ptr, c_int
       type(c_ptr), value :: m
       integer(c_int), value :: base
     end function
     integer(c_int) function c_mc_set_plane(m, plane, thickness) bind(C, name="mc_set_plane")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: plane
       real(c_double), value :: thickness
     end function
     integer(c_int) function c_mc_set_mesh(m, body, n_nodes, xy, n_cells, nodes_per_cell, cells) &
          bind(C, name="mc_set_mesh")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body, nodes_per_cell
       integer(c_int32_t), value :: n_nodes, n_cells
       real(c_double), intent(in) :: xy(*)
       integer(c_int32_t), intent(in) :: cells(*)
     end function
     integer(c_int) function c_mc_set_material(m, body, young, poisson) bind(C, name="mc_set_material")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), value :: young, poisson
     end function
     integer(c_int) function c_mc_set_cell_elasticity(m, body, d) bind(C, name="mc_set_cell_elasticity")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(in) :: d(*)
     end function
     integer(c_int) function c_mc_fix(m, body, n, nodes, components, values) bind(C, name="mc_fix")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body, components
       integer(c_int32_t), value :: n
       integer(c_int32_t), intent(in) :: nodes(*)
       real(c_double), intent(in) :: values(*)  ! not OPTIONAL: that needs Fortran 2018 in BIND(C)
     end function
     integer(c_int) function c_mc_add_traction(m, body, n_edges, edges, traction) &
          bind(C, name="mc_add_traction")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_edges
       integer(c_int32_t), intent(in) :: edges(*)
       real(c_double), intent(in) :: traction(*)
     end function
     integer(c_int) function c_mc_add_pressure(m, body, n_edges, edges, pressure) &
          bind(C, name="mc_add_pressure")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_edges
       integer(c_int32_t), intent(in) :: edges(*)
       real(c_double), intent(in) :: pressure(*)
     end function
     integer(c_int) function c_mc_add_nodal_force(m, body, n, nodes, force) &
          bind(C, name="mc_add_nodal_force")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n
       integer(c_int32_t), intent(in) :: nodes(*)
       real(c_double), intent(in) :: force(*)
     end function
     integer(c_int) function c_mc_set_body_force(m, body, fx, fy) bind(C, name="mc_set_body_force")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), value :: fx, fy
     end function
     integer(c_int) function c_mc_clear_loads(m, body) bind(C, name="mc_clear_loads")
       import :: c_ptr, c_int
       type(c_ptr), value :: m
       integer(c_int), value :: body
     end function
     integer(c_int) function c_mc_set_contact(m, body, n_edges, edges) bind(C, name="mc_set_contact")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_edges
       integer(c_int32_t), intent(in) :: edges(*)
     end function
     integer(c_int) function c_mc_set_gap_offset(m, n, nodes, offset) bind(C, name="mc_set_gap_offset")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int32_t), value :: n
       integer(c_int32_t), intent(in) :: nodes(*)
       real(c_double), intent(in) :: offset(*)
     end function
     integer(c_int) function c_mc_set_body_count(m, n) bind(C, name="mc_set_body_count")
       import :: c_ptr, c_int
       type(c_ptr), value :: m
       integer(c_int), value :: n
     end function
     integer(c_int) function c_mc_add_contact_pair(m, nonmortar_body, mortar_body, pair) &
          bind(C, name="mc_add_contact_pair")
       import :: c_ptr, c_int
       type(c_ptr), value :: m
       integer(c_int), value :: nonmortar_body, mortar_body
       integer(c_int), intent(out) :: pair
     end function
     integer(c_int) function c_mc_set_pair_surface(m, pair, body, n_edges, edges) bind(C, name="mc_set_pair_surface")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int), value :: pair, body
       integer(c_int32_t), value :: n_edges
       integer(c_int32_t), intent(in) :: edges(*)
     end function
     integer(c_int) function c_mc_set_pair_surface_curved(m, pair, body, n_edges, edges) &
          bind(C, name="mc_set_pair_surface_curved")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int), value :: pair, body
       integer(c_int32_t), value :: n_edges
       integer(c_int32_t), intent(in) :: edges(*)
     end function
     integer(c_int) function c_mc_set_pair_gap_offset(m, pair, n, nodes, offset) bind(C, name="mc_set_pair_gap_offset")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: pair
       integer(c_int32_t), value :: n
       integer(c_int32_t), intent(in) :: nodes(*)
       real(c_double), intent(in) :: offset(*)
     end function
     integer(c_int) function c_mc_get_pair_contact_count(m, pair, n) bind(C, name="mc_get_pair_contact_count")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int), value :: pair
       integer(c_int32_t), intent(out) :: n
     end function
     integer(c_int) function c_mc_get_pair_contact_nodes(m, pair, nodes) bind(C, name="mc_get_pair_contact_nodes")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int), value :: pair
       integer(c_int32_t), intent(out) :: nodes(*)
     end function
     integer(c_int) function c_mc_get_pair_contact(m, pair, field, out) bind(C, name="mc_get_pair_contact")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: pair, field
       real(c_double), intent(out) :: out(*)
     end function
     integer(c_int) function c_mc_set_friction(m, pair, law, value) bind(C, name="mc_set_friction")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: pair, law
       real(c_double), value :: value
     end function
     integer(c_int) function c_mc_reset_history(m) bind(C, name="mc_reset_history")
       import :: c_ptr, c_int
       type(c_ptr), value :: m
     end function
     integer(c_int) function c_mc_set_host_body(m, body, n_nodes, xy, equations, n_equations) &
          bind(C, name="mc_set_host_body")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_nodes
       real(c_double), intent(in) :: xy(*)
       integer(c_int32_t), intent(in) :: equations(*)
       integer(c_int32_t), value :: n_equations
     end function
     integer(c_int) function c_mc_add_stiffness(m, body, n_entries, rows, cols, values, storage) &
          bind(C, name="mc_add_stiffness")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_entries
       integer(c_int32_t), intent(in) :: rows(*), cols(*)
       real(c_double), intent(in) :: values(*)
       integer(c_int), value :: storage
     end function
     integer(c_int) function c_mc_add_element_matrices(m, body, n_elements, eltptr, eltvar, a_elt) &
          bind(C, name="mc_add_element_matrices")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_elements
       integer(c_int32_t), intent(in) :: eltptr(*), eltvar(*)
       real(c_double), intent(in) :: a_elt(*)
     end function
     integer(c_int) function c_mc_set_load_vector(m, body, n_equations, f) bind(C, name="mc_set_load_vector")
       import :: c_ptr, c_int, c_int32_t, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_equations
       real(c_double), intent(in) :: f(*)
     end function
     integer(c_int) function c_mc_get_equation_solution(m, body, u) bind(C, name="mc_get_equation_solution")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: u(*)
     end function
     integer(c_int) function c_mc_get_contact_load(m, body, r) bind(C, name="mc_get_contact_load")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: r(*)
     end function
     integer(c_int) function c_mc_set_contact_curved(m, body, n_edges, edges) bind(C, name="mc_set_contact_curved")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int), value :: body
       integer(c_int32_t), value :: n_edges
       integer(c_int32_t), intent(in) :: edges(*)
     end function
     integer(c_int) function c_mc_set_option_int(m, option, value) bind(C, name="mc_set_option_int")
       import :: c_ptr, c_int, c_int64_t
       type(c_ptr), value :: m
       integer(c_int), value :: option
       integer(c_int64_t), value :: value
     end function
     integer(c_int) function c_mc_set_option_real(m, option, value) bind(C, name="mc_set_option_real")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: option
       real(c_double), value :: value
     end function
     integer(c_int) function c_mc_solve(m) bind(C, name="mc_solve")
       import :: c_ptr, c_int
       type(c_ptr), value :: m
     end function
     integer(c_int) function c_mc_set_log_callback(m, fn, user_data) bind(C, name="mc_set_log_callback")
       import :: c_ptr, c_int, c_funptr
       type(c_ptr), value :: m
       type(c_funptr), value :: fn
       type(c_ptr), value :: user_data
     end function
     integer(c_int) function c_mc_get_info_int(m, info, value) bind(C, name="mc_get_info_int")
       import :: c_ptr, c_int, c_int64_t
       type(c_ptr), value :: m
       integer(c_int), value :: info
       integer(c_int64_t), intent(out) :: value
     end function
     integer(c_int) function c_mc_get_info_real(m, info, value) bind(C, name="mc_get_info_real")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: info
       real(c_double), intent(out) :: value
     end function
     integer(c_int) function c_mc_get_displacement(m, body, u) bind(C, name="mc_get_displacement")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: u(*)
     end function
     integer(c_int) function c_mc_get_stress(m, body, sigma) bind(C, name="mc_get_stress")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: sigma(*)
     end function
     integer(c_int) function c_mc_get_nodal_stress(m, body, sigma) bind(C, name="mc_get_nodal_stress")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: sigma(*)
     end function
     integer(c_int) function c_mc_get_error_indicator(m, body, eta) bind(C, name="mc_get_error_indicator")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: eta(*)
     end function
     integer(c_int) function c_mc_get_reaction(m, body, r) bind(C, name="mc_get_reaction")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       integer(c_int), value :: body
       real(c_double), intent(out) :: r(*)
     end function
     integer(c_int) function c_mc_get_contact_count(m, n) bind(C, name="mc_get_contact_count")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int32_t), intent(out) :: n
     end function
     integer(c_int) function c_mc_get_contact_nodes(m, nodes) bind(C, name="mc_get_contact_nodes")
       import :: c_ptr, c_int, c_int32_t
       type(c_ptr), value :: m
       integer(c_int32_t), intent(out) :: nodes(*)
     end function
     integer(c_int) function c_mc_get_contact_pressure(m, p) bind(C, name="mc_get_contact_pressure")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       real(c_double), intent(out) :: p(*)
     end function
     integer(c_int) function c_mc_get_contact_force(m, f) bind(C, name="mc_get_contact_force")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       real(c_double), intent(out) :: f(*)
     end function
     integer(c_int) function c_mc_get_contact_gap(m, g) bind(C, name="mc_get_contact_gap")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       real(c_double), intent(out) :: g(*)
     end function
     integer(c_int) function c_mc_get_contact_initial_gap(m, g0) bind(C, name="mc_get_contact_initial_gap")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       real(c_double), intent(out) :: g0(*)
     end function
     integer(c_int) function c_mc_get_contact_normal(m, n) bind(C, name="mc_get_contact_normal")
       import :: c_ptr, c_int, c_double
       type(c_ptr), value :: m
       real(c_double), intent(out) :: n(*)
     end function
     integer(c_int) function c_mc_write_vtu(m, path) bind(C, name="mc_write_vtu")
       import :: c_ptr, c_int, c_char
       type(c_ptr), value :: m
       character(kind=c_char), intent(in) :: path(*)
     end function
     integer(c_size_t) function c_strlen(s) bind(C, name="strlen")
       import :: c_ptr, c_size_t
       type(c_ptr), value :: s
     end function
  end interface

contains

  ! ---- helpers ---------------------------------------------------------------------------

  !> A NUL-terminated C string as a Fortran string ('' for NULL).
  function c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    if (.not. c_associated(p)) then
       s = ''
       return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate(character(len=n) :: s)
    do i = 1, n
       s(i:i) = chars(i)
    end do
  end function c_string

  !> Records the outcome of a C call on the model and returns its status.
  integer function finish(model, status)
    type(mc_model), intent(inout) :: model
    integer(c_int), intent(in) :: status
    if (status == MC_OK) then
       model%msg = ''
    else
       model%msg = c_string(c_mc_errmsg(model%ptr))
    end if
    finish = int(status)
  end function finish

  !> A failure detected by the wrapper: the C library is not called.
  integer function fail(model, status, message)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: status
    character(len=*), intent(in) :: message
    model%msg = message
    fail = status
  end function fail

  !> '(a, b)' or '(a)' for messages.
  function shape_str(s) result(r)
    integer, intent(in) :: s(:)
    character(len=:), allocatable :: r
    character(len=24) :: buf
    integer :: i
    r = '('
    do i = 1, size(s)
       write (buf, '(i0)') s(i)
       r = r // trim(buf)
       if (i < size(s)) r = r // ', '
    end do
    r = r // ')'
  end function shape_str

  !> Checks that an array's shape is `want`; else sets the message and returns .false.
  logical function shape_ok(model, what, got, want, names, status)
    type(mc_model), intent(inout) :: model
    character(len=*), intent(in) :: what, names
    integer, intent(in) :: got(:), want(:)
    integer, intent(out) :: status
    shape_ok = all(got == want)
    status = MC_OK
    if (.not. shape_ok) status = fail(model, MC_ERROR_ARGUMENT, what // ' must have shape ' // names // &
         ' = ' // shape_str(want) // ', got ' // shape_str(got))
  end function shape_ok

  !> The number of bodies the wrapper knows (2 before mc_create and until mc_set_body_count).
  integer function body_count(model)
    type(mc_model), intent(in) :: model
    body_count = 2
    if (allocated(model%n_nodes)) body_count = size(model%n_nodes)
  end function body_count

  !> Whether the wrapper holds the sizes of `body` (1..N of a created model).
  logical function known_body(model, body)
    type(mc_model), intent(in) :: model
    integer, intent(in) :: body
    known_body = .false.
    if (allocated(model%n_nodes)) known_body = body >= 1 .and. body <= size(model%n_nodes)
  end function known_body

  !> Sets the number of bodies whose sizes the wrapper holds: keeps the first ones, the new ones
  !> have none yet.
  subroutine resize_bodies(model, n)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: n
    integer(mc_int), allocatable :: nodes(:), cells(:), equations(:)
    integer :: keep
    allocate(nodes(n), cells(n), equations(n))
    nodes = -1
    cells = -1
    equations = 0
    if (allocated(model%n_nodes)) then
       keep = min(n, size(model%n_nodes))
       nodes(1:keep) = model%n_nodes(1:keep)
       cells(1:keep) = model%n_cells(1:keep)
       equations(1:keep) = model%n_equations(1:keep)
    end if
    call move_alloc(nodes, model%n_nodes)
    call move_alloc(cells, model%n_cells)
    call move_alloc(equations, model%n_equations)
  end subroutine resize_bodies

  !> Checks that `body` is 1..N and has a mesh known to the wrapper.
  logical function body_ok(model, what, body, status)
    type(mc_model), intent(inout) :: model
    character(len=*), intent(in) :: what
    integer, intent(in) :: body
    integer, intent(out) :: status
    character(len=16) :: buf, count
    body_ok = .false.
    if (body < 1 .or. body > body_count(model)) then
       write (buf, '(i0)') body
       write (count, '(i0)') body_count(model)
       status = fail(model, MC_ERROR_ARGUMENT, what // ': body must be 1 to ' // trim(count) // ', got ' // trim(buf))
    else if (.not. known_body(model, body)) then
       write (buf, '(i0)') body
       status = fail(model, MC_ERROR_STATE, what // ': no mesh or host body set for body ' // trim(buf))
    else if (model%n_nodes(body) < 0) then
       write (buf, '(i0)') body
       status = fail(model, MC_ERROR_STATE, what // ': no mesh or host body set for body ' // trim(buf))
    else
       body_ok = .true.
       status = MC_OK
    end if
  end function body_ok

  ! ---- lifecycle, errors, version ----------------------------------------------------------

  !> Creates an empty model with 1-based ids.
  integer function mc_create(model) result(status)
    type(mc_model), intent(inout) :: model
    if (allocated(model%n_nodes)) deallocate(model%n_nodes, model%n_cells, model%n_equations)
    call resize_bodies(model, 2)
    status = c_mc_create(model%ptr)
    if (status /= MC_OK) then
       model%msg = 'mc_create failed: ' // c_string(c_mc_status_string(int(status, c_int)))
       return
    end if
    status = finish(model, c_mc_set_index_base(model%ptr, 1_c_int))
    model%base = 1
  end function mc_create

  !> Frees the model (a model never created is fine).
  subroutine mc_destroy(model)
    type(mc_model), intent(inout) :: model
    call c_mc_destroy(model%ptr)
    model%ptr = c_null_ptr
    if (allocated(model%n_nodes)) deallocate(model%n_nodes, model%n_cells, model%n_equations)
    model%base = 1
  end subroutine mc_destroy

  !> The message of the last failed call on this model ('' if it succeeded).
  function mc_errmsg(model) result(msg)
    type(mc_model), intent(in) :: model
    character(len=:), allocatable :: msg
    if (allocated(model%msg)) then
       msg = model%msg
    else
       msg = ''
    end if
  end function mc_errmsg

  !> The English name of a status code ("MC_OK", ...).
  function mc_status_string(status) result(s)
    integer, intent(in) :: status
    character(len=:), allocatable :: s
    s = c_string(c_mc_status_string(int(status, c_int)))
  end function mc_status_string

  !> The library's version, "MAJOR.MINOR.PATCH".
  function mc_version_string() result(s)
    character(len=:), allocatable :: s
    s = c_string(c_mc_version_string())
  end function mc_version_string

  !> The library's version as MAJOR*10000+MINOR*100+PATCH.
  integer function mc_version_number()
    mc_version_number = int(c_mc_version_number())
  end function mc_version_number

  ! ---- the scene -------------------------------------------------------------------------

  !> 0 or 1: the base of all ids (the wrapper's mc_create sets 1).
  integer function mc_set_index_base(model, base) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: base
    status = finish(model, c_mc_set_index_base(model%ptr, int(base, c_int)))
    if (status == MC_OK) model%base = base
  end function mc_set_index_base

  !> MC_PLANE_STRAIN, MC_PLANE_STRESS or MC_AXISYMMETRIC (x = r >= 0, y the axis; the thickness
  !> is then ignored), and the thickness.
  integer function mc_set_plane(model, plane, thickness) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: plane
    real(mc_real), intent(in) :: thickness
    status = finish(model, c_mc_set_plane(model%ptr, int(plane, c_int), thickness))
  end function mc_set_plane

  !> The mesh of a body: xy(2, n_nodes), cells(nodes_per_cell, n_cells) with nodes_per_cell
  !> 3 (P1), 4 (Q1), 6 (T6), 8 (Q8) or 9 (Q9): corners counter-clockwise, then the mid-edge
  !> nodes (and the Q9 centre), in Gmsh's and VTK's order (mc_set_mesh in the header).
  integer function mc_set_mesh(model, body, xy, cells) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(in) :: xy(:, :)
    integer(mc_int), intent(in) :: cells(:, :)
    if (.not. shape_ok(model, 'mc_set_mesh: xy', shape(xy), [2, size(xy, 2)], '(2, n_nodes)', status)) return
    status = finish(model, c_mc_set_mesh(model%ptr, int(body, c_int), int(size(xy, 2), mc_int), xy, &
         int(size(cells, 2), mc_int), int(size(cells, 1), c_int), cells))
    if (status == MC_OK .and. known_body(model, body)) then
       model%n_nodes(body) = size(xy, 2)
       model%n_cells(body) = size(cells, 2)
       model%n_equations(body) = 0
    end if
  end function mc_set_mesh

  !> Isotropic material of the whole body.
  integer function mc_set_material(model, body, young, poisson) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(in) :: young, poisson
    status = finish(model, c_mc_set_material(model%ptr, int(body, c_int), young, poisson))
  end function mc_set_material

  !> Per-cell elasticity: d(3, 3, n_cells), symmetric positive definite (Voigt xx, yy, xy).
  integer function mc_set_cell_elasticity(model, body, d) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(in) :: d(:, :, :)
    if (.not. body_ok(model, 'mc_set_cell_elasticity', body, status)) return
    if (.not. shape_ok(model, 'mc_set_cell_elasticity: d', shape(d), [3, 3, model%n_cells(body)], &
         '(3, 3, n_cells)', status)) return
    ! d is symmetric, so its column-major layout is the row-major one the C API reads.
    status = finish(model, c_mc_set_cell_elasticity(model%ptr, int(body, c_int), d))
  end function mc_set_cell_elasticity

  !> Prescribes the components (MC_X, MC_Y, MC_XY) of nodes(n); values(2, n), absent = zero.
  integer function mc_fix(model, body, nodes, components, values) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body, components
    integer(mc_int), intent(in) :: nodes(:)
    real(mc_real), intent(in), optional :: values(:, :)
    real(mc_real), allocatable :: zeros(:, :)
    if (present(values)) then
       if (.not. shape_ok(model, 'mc_fix: values', shape(values), [2, size(nodes)], '(2, size(nodes))', &
            status)) return
       status = finish(model, c_mc_fix(model%ptr, int(body, c_int), int(size(nodes), mc_int), nodes, &
            int(components, c_int), values))
    else
       ! zeros, as the C API's NULL means: passing NULL would need an OPTIONAL argument of a
       ! BIND(C) interface, Fortran 2018, and the module keeps to Fortran 2008
       allocate(zeros(2, size(nodes)))
       zeros = 0._mc_real
       status = finish(model, c_mc_fix(model%ptr, int(body, c_int), int(size(nodes), mc_int), nodes, &
            int(components, c_int), zeros))
    end if
  end function mc_fix

  !> Adds a uniform traction(2, n_edges) on boundary edges(2, n_edges).
  integer function mc_add_traction(model, body, edges, traction) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: edges(:, :)
    real(mc_real), intent(in) :: traction(:, :)
    if (.not. shape_ok(model, 'mc_add_traction: edges', shape(edges), [2, size(edges, 2)], '(2, n_edges)', &
         status)) return
    if (.not. shape_ok(model, 'mc_add_traction: traction', shape(traction), [2, size(edges, 2)], &
         '(2, n_edges)', status)) return
    status = finish(model, c_mc_add_traction(model%ptr, int(body, c_int), int(size(edges, 2), mc_int), &
         edges, traction))
  end function mc_add_traction

  !> Adds a normal pressure(n_edges) (> 0 pushes in) on boundary edges(2, n_edges).
  integer function mc_add_pressure(model, body, edges, pressure) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: edges(:, :)
    real(mc_real), intent(in) :: pressure(:)
    if (.not. shape_ok(model, 'mc_add_pressure: edges', shape(edges), [2, size(edges, 2)], '(2, n_edges)', &
         status)) return
    if (.not. shape_ok(model, 'mc_add_pressure: pressure', shape(pressure), [size(edges, 2)], '(n_edges)', &
         status)) return
    status = finish(model, c_mc_add_pressure(model%ptr, int(body, c_int), int(size(edges, 2), mc_int), &
         edges, pressure))
  end function mc_add_pressure

  !> Adds point forces force(2, n) at nodes(n).
  integer function mc_add_nodal_force(model, body, nodes, force) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: nodes(:)
    real(mc_real), intent(in) :: force(:, :)
    if (.not. shape_ok(model, 'mc_add_nodal_force: force', shape(force), [2, size(nodes)], &
         '(2, size(nodes))', status)) return
    status = finish(model, c_mc_add_nodal_force(model%ptr, int(body, c_int), int(size(nodes), mc_int), &
         nodes, force))
  end function mc_add_nodal_force

  !> Sets (replaces) a uniform body force per unit area.
  integer function mc_set_body_force(model, body, fx, fy) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(in) :: fx, fy
    status = finish(model, c_mc_set_body_force(model%ptr, int(body, c_int), fx, fy))
  end function mc_set_body_force

  !> Removes every load of a body (supports stay).
  integer function mc_clear_loads(model, body) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    status = finish(model, c_mc_clear_loads(model%ptr, int(body, c_int)))
  end function mc_clear_loads

  !> The number of bodies, n >= 2 (default 2). Growing keeps the bodies there are; shrinking
  !> drops the last ones (MC_ERROR_STATE while a contact pair uses one of them).
  integer function mc_set_body_count(model, n) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: n
    status = finish(model, c_mc_set_body_count(model%ptr, int(n, c_int)))
    if (status == MC_OK) call resize_bodies(model, n)
  end function mc_set_body_count

  !> Candidate contact surface: boundary edges(2, n_edges). Body 1 non-mortar, body 2 mortar
  !> (contact pair 1, made as (1, 2) if the model has no pair yet).
  integer function mc_set_contact(model, body, edges) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: edges(:, :)
    if (.not. shape_ok(model, 'mc_set_contact: edges', shape(edges), [2, size(edges, 2)], '(2, n_edges)', &
         status)) return
    status = finish(model, c_mc_set_contact(model%ptr, int(body, c_int), int(size(edges, 2), mc_int), edges))
  end function mc_set_contact

  !> Adds offset(n) (a length: > 0 clearance, < 0 interference) to the initial gap of the body-1
  !> contact nodes(n); replaces earlier offsets of those nodes.
  integer function mc_set_gap_offset(model, nodes, offset) result(status)
    type(mc_model), intent(inout) :: model
    integer(mc_int), intent(in) :: nodes(:)
    real(mc_real), intent(in) :: offset(:)
    if (.not. shape_ok(model, 'mc_set_gap_offset: offset', shape(offset), [size(nodes)], '(size(nodes))', &
         status)) return
    status = finish(model, c_mc_set_gap_offset(model%ptr, int(size(nodes), mc_int), nodes, offset))
  end function mc_set_gap_offset

  ! ---- assemblies: contact pairs --------------------------------------------------------------

  !> Makes a contact pair between two different bodies; pair receives its number (1, 2, ... in
  !> the order made, whatever the index base).
  integer function mc_add_contact_pair(model, nonmortar_body, mortar_body, pair) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: nonmortar_body, mortar_body
    integer, intent(out) :: pair
    integer(c_int) :: p
    p = 0
    status = finish(model, c_mc_add_contact_pair(model%ptr, int(nonmortar_body, c_int), int(mortar_body, c_int), p))
    pair = int(p)
  end function mc_add_contact_pair

  !> One side of a pair: body is the pair's non-mortar or mortar body, edges(2, n_edges) as in
  !> mc_set_contact. Replaces that side's earlier edges.
  integer function mc_set_pair_surface(model, pair, body, edges) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair, body
    integer(mc_int), intent(in) :: edges(:, :)
    if (.not. shape_ok(model, 'mc_set_pair_surface: edges', shape(edges), [2, size(edges, 2)], '(2, n_edges)', &
         status)) return
    status = finish(model, c_mc_set_pair_surface(model%ptr, int(pair, c_int), int(body, c_int), &
         int(size(edges, 2), mc_int), edges))
  end function mc_set_pair_surface

  !> One side of a pair of quadratic edges(3, n_edges): end, end, middle (as mc_set_contact_curved).
  integer function mc_set_pair_surface_curved(model, pair, body, edges) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair, body
    integer(mc_int), intent(in) :: edges(:, :)
    if (.not. shape_ok(model, 'mc_set_pair_surface_curved: edges', shape(edges), [3, size(edges, 2)], &
         '(3, n_edges)', status)) return
    status = finish(model, c_mc_set_pair_surface_curved(model%ptr, int(pair, c_int), int(body, c_int), &
         int(size(edges, 2), mc_int), edges))
  end function mc_set_pair_surface_curved

  !> Adds offset(n) to the initial gap of the pair's non-mortar nodes(n), as mc_set_gap_offset
  !> does for pair 1; replaces earlier offsets of those nodes.
  integer function mc_set_pair_gap_offset(model, pair, nodes, offset) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair
    integer(mc_int), intent(in) :: nodes(:)
    real(mc_real), intent(in) :: offset(:)
    if (.not. shape_ok(model, 'mc_set_pair_gap_offset: offset', shape(offset), [size(nodes)], '(size(nodes))', &
         status)) return
    status = finish(model, c_mc_set_pair_gap_offset(model%ptr, int(pair, c_int), int(size(nodes), mc_int), &
         nodes, offset))
  end function mc_set_pair_gap_offset

  ! ---- friction ---------------------------------------------------------------------------------

  !> The friction law of a contact pair (1 for the two-body model's pair): MC_FRICTION_COULOMB
  !> (value: mu >= 0), MC_FRICTION_TRESCA (value: the slip bound, a shear traction >= 0) or
  !> MC_FRICTION_NONE (the default). Each mc_solve of a model with friction is a step from the last
  !> converged state, in MC_OPTION_LOAD_STEPS increments; mc_reset_history returns to the unloaded state.
  integer function mc_set_friction(model, pair, law, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair, law
    real(mc_real), intent(in) :: value
    status = finish(model, c_mc_set_friction(model%ptr, int(pair, c_int), int(law, c_int), value))
  end function mc_set_friction

  !> Forgets the converged state: the next solve starts from the unloaded state (u = 0, loads 0,
  !> accumulated slip 0).
  integer function mc_reset_history(model) result(status)
    type(mc_model), intent(inout) :: model
    status = finish(model, c_mc_reset_history(model%ptr))
  end function mc_reset_history

  ! ---- host bodies: a legacy program's own matrices -------------------------------------------

  !> Makes a body a host body (no cells): xy(2, n_nodes) the nodes the contact surface and the
  !> rigid modes need, equations(2, n_nodes) the host's equation number of each node's x and y
  !> freedom (Smith and Griffiths' nf after numbering: 1..n_equations, 0 = restrained, with the
  !> index base 1), n_equations the size of the host's system.
  integer function mc_set_host_body(model, body, xy, equations, n_equations) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body, n_equations
    real(mc_real), intent(in) :: xy(:, :)
    integer(mc_int), intent(in) :: equations(:, :)
    if (.not. shape_ok(model, 'mc_set_host_body: xy', shape(xy), [2, size(xy, 2)], '(2, n_nodes)', status)) return
    if (.not. shape_ok(model, 'mc_set_host_body: equations', shape(equations), [2, size(xy, 2)], &
         '(2, n_nodes)', status)) return
    status = finish(model, c_mc_set_host_body(model%ptr, int(body, c_int), int(size(xy, 2), mc_int), xy, &
         equations, int(n_equations, mc_int)))
    if (status == MC_OK .and. known_body(model, body)) then
       model%n_nodes(body) = size(xy, 2)
       model%n_cells(body) = 0
       model%n_equations(body) = n_equations
    end if
  end function mc_set_host_body

  !> Adds coordinate entries values(k) at (rows(k), cols(k)) (host equation numbers; 0 with base
  !> 1: restrained, skipped; duplicates summed) to a host body's stiffness. storage:
  !> MC_MATRIX_FULL (default: both triangles) or MC_MATRIX_TRIANGLE (one triangle, either).
  integer function mc_add_stiffness(model, body, rows, cols, values, storage) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: rows(:), cols(:)
    real(mc_real), intent(in) :: values(:)
    integer, intent(in), optional :: storage
    integer :: kind
    kind = MC_MATRIX_FULL
    if (present(storage)) kind = storage
    if (.not. shape_ok(model, 'mc_add_stiffness: cols', shape(cols), [size(rows)], '(size(rows))', status)) return
    if (.not. shape_ok(model, 'mc_add_stiffness: values', shape(values), [size(rows)], '(size(rows))', &
         status)) return
    status = finish(model, c_mc_add_stiffness(model%ptr, int(body, c_int), int(size(rows), mc_int), rows, cols, &
         values, int(kind, c_int)))
  end function mc_add_stiffness

  !> Adds element matrices to a host body's stiffness, MUMPS's elemental input: eltptr(n_elements
  !> + 1) counted from the index base (ELTPTR(1) = 1), element e's equations
  !> eltvar(eltptr(e) - base + 1 : eltptr(e + 1) - base) (0 with base 1: restrained), its square
  !> matrix column by column in a_elt after the previous element's. The sizes of eltvar and a_elt
  !> are checked against eltptr.
  integer function mc_add_element_matrices(model, body, eltptr, eltvar, a_elt) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: eltptr(:), eltvar(:)
    real(mc_real), intent(in) :: a_elt(:)
    integer(mc_int64) :: values, length
    integer :: e
    character(len=64) :: buf
    if (size(eltptr) < 1) then
       status = fail(model, MC_ERROR_ARGUMENT, 'mc_add_element_matrices: eltptr needs n_elements + 1 entries')
       return
    end if
    if (eltptr(1) /= model%base) then
       write (buf, '(a, i0, a, i0)') 'eltptr(1) = ', eltptr(1), ', expected the index base ', model%base
       status = fail(model, MC_ERROR_ARGUMENT, 'mc_add_element_matrices: ' // trim(buf))
       return
    end if
    values = 0
    do e = 1, size(eltptr) - 1
       length = int(eltptr(e + 1), mc_int64) - eltptr(e)
       if (length < 0) then
          write (buf, '(a, i0, a, i0)') 'eltptr(', e + 1, ') is below eltptr(', e
          status = fail(model, MC_ERROR_ARGUMENT, 'mc_add_element_matrices: ' // trim(buf) // ')')
          return
       end if
       values = values + length * length
    end do
    if (.not. shape_ok(model, 'mc_add_element_matrices: eltvar', shape(eltvar), &
         [int(eltptr(size(eltptr))) - model%base], '(eltptr(n_elements + 1) - base)', status)) return
    if (values > huge(1)) then
       status = fail(model, MC_ERROR_ARGUMENT, 'mc_add_element_matrices: more matrix values than a default integer counts')
       return
    end if
    if (.not. shape_ok(model, 'mc_add_element_matrices: a_elt', shape(a_elt), [int(values)], &
         '(sum of the elements'' sizes squared)', status)) return
    status = finish(model, c_mc_add_element_matrices(model%ptr, int(body, c_int), int(size(eltptr) - 1, mc_int), &
         eltptr, eltvar, a_elt))
  end function mc_add_element_matrices

  !> Adds element matrices as a Smith and Griffiths program stores them: g_g(ndof, nels) the
  !> steering vectors (equations 1..neq, 0 = restrained, whatever the index base) and
  !> storkm(ndof, ndof, nels) the element stiffness matrices. Both are passed as they are (only
  !> eltptr is built; with an index base of 0, g_g - 1 is passed instead).
  integer function mc_add_element_matrices_sg(model, body, g_g, storkm) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: g_g(:, :)
    real(mc_real), intent(in) :: storkm(:, :, :)
    integer(mc_int), allocatable :: eltptr(:)
    integer :: e, ndof, nels
    ndof = size(g_g, 1)
    nels = size(g_g, 2)
    if (.not. shape_ok(model, 'mc_add_element_matrices_sg: storkm', shape(storkm), [ndof, ndof, nels], &
         '(ndof, ndof, nels) of g_g(ndof, nels)', status)) return
    allocate(eltptr(nels + 1))
    eltptr = [(int(model%base + ndof * e, mc_int), e = 0, nels)]
    if (model%base == 1) then
       status = finish(model, c_mc_add_element_matrices(model%ptr, int(body, c_int), int(nels, mc_int), eltptr, &
            g_g, storkm))
    else
       status = finish(model, c_mc_add_element_matrices(model%ptr, int(body, c_int), int(nels, mc_int), eltptr, &
            g_g - (1 - model%base), storkm))
    end if
  end function mc_add_element_matrices_sg

  !> The load of a host body, f(n_equations) in the host's equation order (replaces the previous
  !> one; mc_clear_loads zeroes it). A Smith and Griffiths loads(0:neq) passes as loads(1:).
  integer function mc_set_load_vector(model, body, f) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(in) :: f(:)
    if (known_body(model, body)) then
       if (model%n_equations(body) > 0) then
          if (.not. shape_ok(model, 'mc_set_load_vector: f', shape(f), [int(model%n_equations(body))], &
               '(n_equations)', status)) return
       end if
    end if
    status = finish(model, c_mc_set_load_vector(model%ptr, int(body, c_int), int(size(f), mc_int), f))
  end function mc_set_load_vector

  !> The length of a body's equation vectors, checked against an array's.
  logical function equations_ok(model, what, body, got, status)
    type(mc_model), intent(inout) :: model
    character(len=*), intent(in) :: what
    integer, intent(in) :: body, got(:)
    integer, intent(out) :: status
    equations_ok = .false.
    if (.not. body_ok(model, what, body, status)) return
    if (model%n_equations(body) > 0) then
       equations_ok = shape_ok(model, what // ': array', got, [int(model%n_equations(body))], '(n_equations)', status)
    else
       equations_ok = shape_ok(model, what // ': array', got, [2 * int(model%n_nodes(body))], &
            '(2 * n_nodes) of a mesh body', status)
    end if
  end function equations_ok

  !> After a solve: the displacements u(n_equations) of a host body in its equation order (a
  !> Smith and Griffiths loads(0:neq) receives them as loads(1:)), or u(2 * n_nodes) of a mesh body.
  integer function mc_get_equation_solution(model, body, u) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: u(:)
    if (.not. equations_ok(model, 'mc_get_equation_solution', body, shape(u), status)) return
    status = finish(model, c_mc_get_equation_solution(model%ptr, int(body, c_int), u))
  end function mc_get_equation_solution

  !> After a solve: the contact forces on a body as a load vector r, sized as in
  !> mc_get_equation_solution; K u = f + r on the free equations.
  integer function mc_get_contact_load(model, body, r) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: r(:)
    if (.not. equations_ok(model, 'mc_get_contact_load', body, shape(r), status)) return
    status = finish(model, c_mc_get_contact_load(model%ptr, int(body, c_int), r))
  end function mc_get_contact_load

  !> Candidate contact surface of quadratic edges(3, n_edges): end, end, middle. A host body's
  !> edges run with the body on their left; a mesh body's are boundary edges of cells with that
  !> middle node.
  integer function mc_set_contact_curved(model, body, edges) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    integer(mc_int), intent(in) :: edges(:, :)
    if (.not. shape_ok(model, 'mc_set_contact_curved: edges', shape(edges), [3, size(edges, 2)], &
         '(3, n_edges)', status)) return
    status = finish(model, c_mc_set_contact_curved(model%ptr, int(body, c_int), int(size(edges, 2), mc_int), edges))
  end function mc_set_contact_curved

  ! ---- options and solving -----------------------------------------------------------------

  integer function set_option_int32(model, option, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: option
    integer(c_int32_t), intent(in) :: value
    status = finish(model, c_mc_set_option_int(model%ptr, int(option, c_int), int(value, c_int64_t)))
  end function set_option_int32

  integer function set_option_int64(model, option, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: option
    integer(c_int64_t), intent(in) :: value
    status = finish(model, c_mc_set_option_int(model%ptr, int(option, c_int), value))
  end function set_option_int64

  !> Sets a real option (MC_OPTION_TOLERANCE).
  integer function mc_set_option_real(model, option, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: option
    real(mc_real), intent(in) :: value
    status = finish(model, c_mc_set_option_real(model%ptr, int(option, c_int), value))
  end function mc_set_option_real

  !> Solves the scene.
  integer function mc_solve(model) result(status)
    type(mc_model), intent(inout) :: model
    status = finish(model, c_mc_solve(model%ptr))
  end function mc_solve

  !> Installs fn (a bind(C) procedure of interface mc_log_fn) with user_data (c_null_ptr when
  !> absent) as the progress log of mc_solve; without fn, removes the callback.
  integer function mc_set_log_callback(model, fn, user_data) result(status)
    type(mc_model), intent(inout) :: model
    procedure(mc_log_fn), optional :: fn
    type(c_ptr), intent(in), optional :: user_data
    type(c_ptr) :: data
    data = c_null_ptr
    if (present(user_data)) data = user_data
    if (present(fn)) then
       status = finish(model, c_mc_set_log_callback(model%ptr, c_funloc(fn), data))
    else
       status = finish(model, c_mc_set_log_callback(model%ptr, c_null_funptr, c_null_ptr))
    end if
  end function mc_set_log_callback

  !> The NUL-terminated message a log callback receives, as a Fortran string.
  function mc_log_message(message) result(s)
    character(kind=c_char), intent(in) :: message(*)
    character(len=:), allocatable :: s
    integer :: i, n
    n = 0
    do while (message(n + 1) /= c_null_char)
       n = n + 1
    end do
    allocate(character(len=n) :: s)
    do i = 1, n
       s(i:i) = message(i)
    end do
  end function mc_log_message

  ! ---- results -------------------------------------------------------------------------------

  integer function get_info_int64(model, info, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: info
    integer(c_int64_t), intent(out) :: value
    status = finish(model, c_mc_get_info_int(model%ptr, int(info, c_int), value))
  end function get_info_int64

  integer function get_info_int32(model, info, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: info
    integer(c_int32_t), intent(out) :: value
    integer(c_int64_t) :: v
    v = 0
    status = finish(model, c_mc_get_info_int(model%ptr, int(info, c_int), v))
    if (status == MC_OK .and. (v > huge(value) .or. v < -huge(value))) then
       status = fail(model, MC_ERROR_ARGUMENT, 'mc_get_info_int: the value does not fit in 32 bits; ' // &
            'pass an integer(mc_int64)')
    end if
    value = int(v, c_int32_t)
  end function get_info_int32

  !> A real info (MC_INFO_TIME_*, MC_INFO_STRAIN_ENERGY, ...).
  integer function mc_get_info_real(model, info, value) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: info
    real(mc_real), intent(out) :: value
    status = finish(model, c_mc_get_info_real(model%ptr, int(info, c_int), value))
  end function mc_get_info_real

  !> Displacements u(2, n_nodes) of a body.
  integer function mc_get_displacement(model, body, u) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: u(:, :)
    if (.not. body_ok(model, 'mc_get_displacement', body, status)) return
    if (.not. shape_ok(model, 'mc_get_displacement: u', shape(u), [2, model%n_nodes(body)], &
         '(2, n_nodes)', status)) return
    status = finish(model, c_mc_get_displacement(model%ptr, int(body, c_int), u))
  end function mc_get_displacement

  !> Cell-averaged stresses sigma(4, n_cells): xx, yy, xy, zz.
  integer function mc_get_stress(model, body, sigma) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: sigma(:, :)
    if (.not. body_ok(model, 'mc_get_stress', body, status)) return
    if (.not. shape_ok(model, 'mc_get_stress: sigma', shape(sigma), [4, model%n_cells(body)], &
         '(4, n_cells)', status)) return
    status = finish(model, c_mc_get_stress(model%ptr, int(body, c_int), sigma))
  end function mc_get_stress

  !> Stresses at the nodes sigma(4, n_nodes): xx, yy, xy, zz; each cell's stress at its nodes,
  !> averaged over the cells sharing a node.
  integer function mc_get_nodal_stress(model, body, sigma) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: sigma(:, :)
    if (.not. body_ok(model, 'mc_get_nodal_stress', body, status)) return
    if (.not. shape_ok(model, 'mc_get_nodal_stress: sigma', shape(sigma), [4, model%n_nodes(body)], &
         '(4, n_nodes)', status)) return
    status = finish(model, c_mc_get_nodal_stress(model%ptr, int(body, c_int), sigma))
  end function mc_get_nodal_stress

  !> The cells' error indicators eta(n_cells), relative like MC_INFO_ERROR_ESTIMATE: their
  !> squares over both bodies add up to its square. MC_ERROR_STATE before a solve, for a host
  !> body, or when MC_OPTION_ERROR_ESTIMATE is 0.
  integer function mc_get_error_indicator(model, body, eta) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: eta(:)
    if (.not. body_ok(model, 'mc_get_error_indicator', body, status)) return
    if (.not. shape_ok(model, 'mc_get_error_indicator: eta', shape(eta), [model%n_cells(body)], &
         '(n_cells)', status)) return
    status = finish(model, c_mc_get_error_indicator(model%ptr, int(body, c_int), eta))
  end function mc_get_error_indicator

  !> Support reactions r(2, n_nodes).
  integer function mc_get_reaction(model, body, r) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(mc_real), intent(out) :: r(:, :)
    if (.not. body_ok(model, 'mc_get_reaction', body, status)) return
    if (.not. shape_ok(model, 'mc_get_reaction: r', shape(r), [2, model%n_nodes(body)], &
         '(2, n_nodes)', status)) return
    status = finish(model, c_mc_get_reaction(model%ptr, int(body, c_int), r))
  end function mc_get_reaction

  !> Number of body-1 contact nodes (the size of the contact arrays).
  integer function mc_get_contact_count(model, n) result(status)
    type(mc_model), intent(inout) :: model
    integer(mc_int), intent(out) :: n
    n = 0
    status = finish(model, c_mc_get_contact_count(model%ptr, n))
  end function mc_get_contact_count

  !> The contact count, checked against the size of a caller's array (rows values per node).
  logical function contact_ok(model, what, got, rows, status)
    type(mc_model), intent(inout) :: model
    character(len=*), intent(in) :: what
    integer, intent(in) :: got(:), rows
    integer, intent(out) :: status
    integer(mc_int) :: n
    contact_ok = .false.
    status = mc_get_contact_count(model, n)
    if (status /= MC_OK) return
    if (rows == 1) then
       contact_ok = shape_ok(model, what, got, [int(n)], '(n_contact)', status)
    else
       contact_ok = shape_ok(model, what, got, [rows, int(n)], '(2, n_contact)', status)
    end if
  end function contact_ok

  !> Ids of the body-1 contact nodes, nodes(n_contact), in order along each chain.
  integer function mc_get_contact_nodes(model, nodes) result(status)
    type(mc_model), intent(inout) :: model
    integer(mc_int), intent(out) :: nodes(:)
    if (.not. contact_ok(model, 'mc_get_contact_nodes: nodes', shape(nodes), 1, status)) return
    status = finish(model, c_mc_get_contact_nodes(model%ptr, nodes))
  end function mc_get_contact_nodes

  !> Contact pressure p(n_contact) >= 0 (lumped recovery).
  integer function mc_get_contact_pressure(model, p) result(status)
    type(mc_model), intent(inout) :: model
    real(mc_real), intent(out) :: p(:)
    if (.not. contact_ok(model, 'mc_get_contact_pressure: p', shape(p), 1, status)) return
    status = finish(model, c_mc_get_contact_pressure(model%ptr, p))
  end function mc_get_contact_pressure

  !> Nodal contact forces f(n_contact) >= 0 (the multipliers lambda_j).
  integer function mc_get_contact_force(model, f) result(status)
    type(mc_model), intent(inout) :: model
    real(mc_real), intent(out) :: f(:)
    if (.not. contact_ok(model, 'mc_get_contact_force: f', shape(f), 1, status)) return
    status = finish(model, c_mc_get_contact_force(model%ptr, f))
  end function mc_get_contact_force

  !> Discrete gap g(n_contact) after the solve (+infinity where no mortar surface is seen).
  integer function mc_get_contact_gap(model, g) result(status)
    type(mc_model), intent(inout) :: model
    real(mc_real), intent(out) :: g(:)
    if (.not. contact_ok(model, 'mc_get_contact_gap: g', shape(g), 1, status)) return
    status = finish(model, c_mc_get_contact_gap(model%ptr, g))
  end function mc_get_contact_gap

  !> Initial normal gap g0(n_contact) (negative: interference).
  integer function mc_get_contact_initial_gap(model, g0) result(status)
    type(mc_model), intent(inout) :: model
    real(mc_real), intent(out) :: g0(:)
    if (.not. contact_ok(model, 'mc_get_contact_initial_gap: g0', shape(g0), 1, status)) return
    status = finish(model, c_mc_get_contact_initial_gap(model%ptr, g0))
  end function mc_get_contact_initial_gap

  !> Unit outward normals n(2, n_contact) of body 1 at the contact nodes.
  integer function mc_get_contact_normal(model, n) result(status)
    type(mc_model), intent(inout) :: model
    real(mc_real), intent(out) :: n(:, :)
    if (.not. contact_ok(model, 'mc_get_contact_normal: n', shape(n), 2, status)) return
    status = finish(model, c_mc_get_contact_normal(model%ptr, n))
  end function mc_get_contact_normal

  !> After a solve: the number of the pair's contact positions (the size of its contact arrays).
  integer function mc_get_pair_contact_count(model, pair, n) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair
    integer(mc_int), intent(out) :: n
    n = 0
    status = finish(model, c_mc_get_pair_contact_count(model%ptr, int(pair, c_int), n))
  end function mc_get_pair_contact_count

  !> The pair's contact count, checked against the shape of a caller's array (rows values per
  !> position: 1 for a rank-1 array, 2 for MC_CONTACT_NORMAL's values(2, n_contact)).
  logical function pair_contact_ok(model, what, pair, got, rows, status)
    type(mc_model), intent(inout) :: model
    character(len=*), intent(in) :: what
    integer, intent(in) :: pair, got(:), rows
    integer, intent(out) :: status
    integer(mc_int) :: n
    pair_contact_ok = .false.
    status = mc_get_pair_contact_count(model, pair, n)
    if (status /= MC_OK) return
    if (rows == 1) then
       pair_contact_ok = shape_ok(model, what, got, [int(n)], '(n_contact)', status)
    else
       pair_contact_ok = shape_ok(model, what, got, [rows, int(n)], '(2, n_contact)', status)
    end if
  end function pair_contact_ok

  !> The node ids of the pair's contact positions on its non-mortar body, nodes(n_contact).
  integer function mc_get_pair_contact_nodes(model, pair, nodes) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair
    integer(mc_int), intent(out) :: nodes(:)
    if (.not. pair_contact_ok(model, 'mc_get_pair_contact_nodes: nodes', pair, shape(nodes), 1, status)) return
    status = finish(model, c_mc_get_pair_contact_nodes(model%ptr, int(pair, c_int), nodes))
  end function mc_get_pair_contact_nodes

  !> mc_get_pair_contact with values(n_contact): MC_CONTACT_PRESSURE, _FORCE, _GAP, _INITIAL_GAP.
  integer function get_pair_contact_1(model, pair, field, values) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair, field
    real(mc_real), intent(out) :: values(:)
    if (field == MC_CONTACT_NORMAL) then
       status = fail(model, MC_ERROR_ARGUMENT, 'mc_get_pair_contact: MC_CONTACT_NORMAL gives values(2, n_contact)')
       return
    end if
    if (.not. pair_contact_ok(model, 'mc_get_pair_contact: values', pair, shape(values), 1, status)) return
    status = finish(model, c_mc_get_pair_contact(model%ptr, int(pair, c_int), int(field, c_int), values))
  end function get_pair_contact_1

  !> mc_get_pair_contact with values(2, n_contact): MC_CONTACT_NORMAL, the unit outward normals
  !> of the non-mortar body.
  integer function get_pair_contact_2(model, pair, field, values) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: pair, field
    real(mc_real), intent(out) :: values(:, :)
    if (field /= MC_CONTACT_NORMAL) then
       status = fail(model, MC_ERROR_ARGUMENT, 'mc_get_pair_contact: values(2, n_contact) is for ' // &
            'MC_CONTACT_NORMAL; the other fields give values(n_contact)')
       return
    end if
    if (.not. pair_contact_ok(model, 'mc_get_pair_contact: values', pair, shape(values), 2, status)) return
    status = finish(model, c_mc_get_pair_contact(model%ptr, int(pair, c_int), int(field, c_int), values))
  end function get_pair_contact_2

  ! ---- output ------------------------------------------------------------------------------

  !> Writes the solved scene for ParaView: path ending in '.pvd' gives a collection plus
  !> '<stem>_body1.vtu' and '<stem>_body2.vtu'; any other path one .vtu with both bodies.
  !> Trailing blanks of path are ignored.
  integer function mc_write_vtu(model, path) result(status)
    type(mc_model), intent(inout) :: model
    character(len=*), intent(in) :: path
    status = finish(model, c_mc_write_vtu(model%ptr, trim(path) // c_null_char))
  end function mc_write_vtu

end module mortarcontact
