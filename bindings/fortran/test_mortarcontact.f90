! Tests of the Fortran binding: version, strings, the wrapper's size checks and messages, errors
! from the library, 1-based ids, a single-body solve, the README's two-square contact scene
! with MC_OPTION_INTERFACE_SOLVER forced to each path (MC_INFO_INTERFACE_SOLVER says which ran),
! the error estimate (MC_INFO_ERROR_ESTIMATE, mc_get_error_indicator, MC_OPTION_ERROR_ESTIMATE),
! MC_OPTION_MULTIPLIER's values, and that scene with body 1 a host body held as a Smith and
! Griffiths program holds it (nf, g_g, storkm, loads(0:neq)), given through each of the host-body
! calls, index bases 1 and 0; assemblies: three stacked blocks as three bodies in two contact pairs
! (a patch test: every contact pressure of both pairs is p), bad bodies and pairs; friction: the
! stick patch test (Tresca and Coulomb: every position sticks with shear -tau, no slip; load steps,
! mc_reset_history, the infos) and bad input for mc_set_friction and the friction options.
! The contact patch test is examples/fortran/patch_test.f90 (also run by ctest).

!> The log callback of the test: counts messages by level and keeps the phase messages.
module test_log
  use, intrinsic :: iso_c_binding, only: c_ptr, c_int, c_char, c_f_pointer
  use mortarcontact, only: mc_log_message, MC_LOG_PHASE
  implicit none
  type :: log_record
     integer :: phases = 0, others = 0
     character(len=4096) :: text = ''
  end type log_record
contains
  subroutine record_log(user_data, level, message) bind(C)
    type(c_ptr), value :: user_data
    integer(c_int), value :: level
    character(kind=c_char), intent(in) :: message(*)
    type(log_record), pointer :: rec
    call c_f_pointer(user_data, rec)
    if (level == MC_LOG_PHASE) then
       rec%phases = rec%phases + 1
       rec%text = trim(rec%text) // mc_log_message(message) // ';'
    else
       rec%others = rec%others + 1
    end if
  end subroutine record_log
end module test_log

program test_mortarcontact
  use, intrinsic :: iso_c_binding, only: c_loc
  use mortarcontact
  use test_log
  implicit none
  type(mc_model) :: m
  integer :: st, failures = 0
  integer :: dofs32
  integer(mc_int64) :: dofs64
  real(mc_real) :: energy
  real(mc_real) :: xy(2, 4) = reshape([0d0, 0d0, 1d0, 0d0, 1d0, 1d0, 0d0, 1d0], [2, 4])
  integer(mc_int) :: tri(3, 2) = reshape([1, 2, 3, 1, 3, 4], [3, 2])
  real(mc_real) :: u(2, 4), r(2, 4), sigma(4, 2), wrong(2, 3), d(3, 3, 2), big(3, 4)
  real(mc_real) :: strided(4, 4), sigma_n(4, 4), eta(2), eta_wrong(4), estimate
  ! one Q8 cell, the unit square: corners counter-clockwise, then the mid-edge nodes
  real(mc_real) :: xy8(2, 8) = reshape([0d0, 0d0, 1d0, 0d0, 1d0, 1d0, 0d0, 1d0, &
       0.5d0, 0d0, 1d0, 0.5d0, 0.5d0, 1d0, 0d0, 0.5d0], [2, 8])
  integer(mc_int) :: q8(8, 1) = reshape([1, 2, 3, 4, 5, 6, 7, 8], [8, 1])
  real(mc_real) :: sigma8(4, 1), sigma8_n(4, 8)
  ! the README's scene: body 2, the unit square below body 1 (the square xy above)
  real(mc_real) :: xy2(2, 4) = reshape([0d0, -1d0, 1d0, -1d0, 1d0, 0d0, 0d0, 0d0], [2, 4])
  real(mc_real) :: pressure(2)
  integer, parameter :: paths(2) = [MC_INTERFACE_SPARSE, MC_INTERFACE_CONDENSED]
  integer :: k, ran
  type(log_record), target :: rec
  character(len=256) :: line
  integer :: unit, ios
  logical :: found
  ! host bodies: body 1 of the README's scene as a Smith and Griffiths program holds it
  integer(mc_int) :: nf(2, 4) = reshape([0, 1, 2, 3, 4, 5, 0, 6], [2, 4])  ! x of nodes 1, 4 restrained
  integer(mc_int) :: g_g(6, 2), rows(72), cols(72), eltptr(3)
  real(mc_real) :: storkm(6, 6, 2), loads(0:6), kv(6, 6), values(72), sol(6), rload(6), rmesh(8)
  real(mc_real) :: u_mesh(2, 4), p_mesh(2), u_host(2, 4), p_host(2), sol8(8)
  integer :: e, i, j, n_entries, input, base
  ! assemblies: three stacked blocks, 3, 5 and 4 P1 cells across (non-matching)
  integer, parameter :: stack_nx(3) = [3, 5, 4]
  real(mc_real), parameter :: stack_p = 0.25d0
  integer :: pair
  integer(mc_int) :: npos
  real(mc_real), allocatable :: bxy(:, :), pvals(:), pnormal(:, :), sig(:, :), ustack(:, :)
  integer(mc_int), allocatable :: bcells(:, :), bbottom(:, :), btop(:, :), bleft(:), pnodes(:)
  ! friction: the stick patch test, an upper block of 3 P1 cells across on a lower one of 4
  real(mc_real), parameter :: fric_p = 0.01d0, fric_mu = 0.5d0, fric_tau = 0.4d0 * fric_mu * fric_p
  integer, parameter :: fric_nx(2) = [3, 4]
  integer :: law, stick, slip
  real(mc_real) :: fric_value, fcompl
  real(mc_real), allocatable :: shear(:), fslip(:), fstate(:), utop(:, :)

  call check(mc_version_number() == MC_HEADER_VERSION_NUMBER, 'mc_version_number')
  call check(mc_version_string() == MC_HEADER_VERSION_STRING, 'mc_version_string = ' // mc_version_string())
  call check(mc_status_string(MC_ERROR_MESH) == 'MC_ERROR_MESH', 'mc_status_string')
  call check(mc_status_string(777) == 'unknown status', 'mc_status_string(unknown)')

  ! A call on a model never created fails cleanly.
  st = mc_set_material(m, 1, 1d0, 0.3d0)
  call check(st == MC_ERROR_ARGUMENT, 'call before mc_create')

  call expect(mc_create(m), MC_OK, 'mc_create')
  call expect(mc_get_displacement(m, 1, u), MC_ERROR_STATE, 'results before a mesh')
  call check(index(mc_errmsg(m), 'no mesh') > 0, 'message: ' // mc_errmsg(m))

  ! Wrapper-side shape checks.
  call expect(mc_set_mesh(m, 1, big, tri), MC_ERROR_ARGUMENT, 'xy of shape (3, 4)')
  call check(index(mc_errmsg(m), '(2, n_nodes)') > 0 .and. index(mc_errmsg(m), '(3, 4)') > 0, &
       'message: ' // mc_errmsg(m))
  call expect(mc_set_mesh(m, 3, xy, tri), MC_ERROR_ARGUMENT, 'body 3 (library check)')
  call check(len(mc_errmsg(m)) > 0, 'library message for body 3: ' // mc_errmsg(m))
  call expect(mc_set_mesh(m, 1, xy, tri + 1), MC_ERROR_ARGUMENT, 'node id 5 of 4 (1-based)')
  call expect(mc_set_mesh(m, 1, xy, tri - 1), MC_ERROR_ARGUMENT, 'node id 0 (1-based)')
  call expect(mc_set_mesh(m, 1, xy, tri), MC_OK, 'mc_set_mesh')
  call check(mc_errmsg(m) == '', 'message cleared after a success')
  call expect(mc_set_material(m, 1, -1d0, 0.3d0), MC_ERROR_MATERIAL, 'E < 0')
  call expect(mc_set_material(m, 1, 1d0, 0.3d0), MC_OK, 'mc_set_material')
  call expect(mc_get_displacement(m, 1, wrong), MC_ERROR_ARGUMENT, 'u of shape (2, 3)')
  call check(index(mc_errmsg(m), '(2, 4)') > 0, 'message: ' // mc_errmsg(m))
  call expect(mc_add_traction(m, 1, reshape([3, 4], [2, 1]), reshape([0d0, 1d-3, 0d0, 0d0], [2, 2])), &
       MC_ERROR_ARGUMENT, 'traction of shape (2, 2) for 1 edge')
  call expect(mc_fix(m, 1, [1, 2], MC_XY, wrong), MC_ERROR_ARGUMENT, 'fix values of shape (2, 3)')
  d = 0
  d(1, 1, :) = 2; d(2, 2, :) = 2; d(3, 3, :) = 1
  call expect(mc_set_cell_elasticity(m, 1, d(:, :, 1:1)), MC_ERROR_ARGUMENT, 'd for 1 cell of 2')
  call expect(mc_set_option_int(m, MC_OPTION_MAX_ITERATIONS, 50), MC_OK, 'option, default integer')
  call expect(mc_set_option_int(m, MC_OPTION_METHOD, int(MC_METHOD_MORTAR, mc_int64)), MC_OK, 'option, int64')
  call expect(mc_set_option_real(m, MC_OPTION_TOLERANCE, 1d-12), MC_OK, 'real option')
  call expect(mc_set_option_int(m, 4242, 1), MC_ERROR_ARGUMENT, 'unknown option')
  ! the multipliers of a quadratic body 1: MC_MULTIPLIER_LINEAR (default) or _QUADRATIC; 2 is not a value
  call expect(mc_set_option_int(m, MC_OPTION_MULTIPLIER, MC_MULTIPLIER_QUADRATIC), MC_OK, 'quadratic multipliers')
  call expect(mc_set_option_int(m, MC_OPTION_MULTIPLIER, MC_MULTIPLIER_LINEAR), MC_OK, 'linear multipliers')
  call expect(mc_set_option_int(m, MC_OPTION_MULTIPLIER, 2), MC_ERROR_ARGUMENT, 'multiplier 2')
  call check(index(mc_errmsg(m), 'MC_OPTION_MULTIPLIER') > 0, 'message: ' // mc_errmsg(m))

  ! A unit square, bottom clamped, pulled up on top (1-based ids).
  call expect(mc_set_plane(m, MC_PLANE_STRAIN, 1d0), MC_OK, 'mc_set_plane')
  call expect(mc_fix(m, 1, [1, 2], MC_XY), MC_OK, 'mc_fix')
  call expect(mc_add_traction(m, 1, reshape([3, 4], [2, 1]), reshape([0d0, 1d-3], [2, 1])), MC_OK, &
       'mc_add_traction')
  call expect(mc_write_vtu(m, 'test_mortarcontact_fortran.vtu'), MC_ERROR_STATE, 'mc_write_vtu before a solve')
  call expect(mc_set_log_callback(m, record_log, c_loc(rec)), MC_OK, 'mc_set_log_callback')
  call expect(mc_solve(m), MC_OK, 'mc_solve (single body)')
  ! a single-body solve: phase messages only (iterations need contact), with the user data
  call check(rec%phases >= 5 .and. rec%others == 0, 'log: phase messages only')
  call check(index(rec%text, 'factorization: body 1') > 0 .and. index(rec%text, 'solve: done') > 0, &
       'log: ' // trim(rec%text))
  call expect(mc_set_log_callback(m), MC_OK, 'mc_set_log_callback (remove)')
  rec%phases = 0
  call expect(mc_solve(m), MC_OK, 'mc_solve (no callback)')
  call check(rec%phases == 0, 'log: no calls after removal')
  ! the file holds the 4 nodes and 2 cells; an unwritable path names itself in the message
  call expect(mc_write_vtu(m, 'test_mortarcontact_fortran.vtu'), MC_OK, 'mc_write_vtu')
  found = .false.
  open(newunit=unit, file='test_mortarcontact_fortran.vtu', status='old', action='read', iostat=ios)
  call check(ios == 0, 'the .vtu exists')
  if (ios == 0) then
     do
        read (unit, '(a)', iostat=ios) line
        if (ios /= 0) exit
        found = found .or. index(line, 'NumberOfPoints="4" NumberOfCells="2"') > 0
     end do
     close(unit, status='delete')
  end if
  call check(found, 'the .vtu declares 4 points and 2 cells')
  call expect(mc_write_vtu(m, '/nonexistent-mc-dir/x.vtu'), MC_ERROR_ARGUMENT, 'mc_write_vtu, no such directory')
  call check(index(mc_errmsg(m), '/nonexistent-mc-dir/x.vtu') > 0, 'message: ' // mc_errmsg(m))
  call expect(mc_set_gap_offset(m, [1], [1d0, 2d0]), MC_ERROR_ARGUMENT, 'gap offsets: 2 values for 1 node')
  if (failures == 0) then
     call expect(mc_get_displacement(m, 1, u), MC_OK, 'mc_get_displacement')
     call check(all(u(:, 1:2) == 0) .and. all(u(2, 3:4) > 0), 'the top moves up')
     ! a non-contiguous output: the compiler passes a temporary and copies back
     strided = -1
     call expect(mc_get_displacement(m, 1, strided(1:4:2, :)), MC_OK, 'strided output')
     call check(all(strided(1:4:2, :) == u) .and. all(strided(2:4:2, :) == -1), 'strided output values')
     call expect(mc_get_reaction(m, 1, r), MC_OK, 'mc_get_reaction')
     call check(abs(sum(r(2, :)) + 1d-3) < 1d-12, 'reactions balance the load')
     call expect(mc_get_stress(m, 1, sigma), MC_OK, 'mc_get_stress')
     call expect(mc_get_nodal_stress(m, 1, sigma), MC_ERROR_ARGUMENT, 'nodal stresses of shape (4, 2)')
     call check(index(mc_errmsg(m), '(4, n_nodes)') > 0 .and. index(mc_errmsg(m), '(4, 4)') > 0, &
          'message: ' // mc_errmsg(m))
     call expect(mc_get_nodal_stress(m, 2, sigma_n), MC_ERROR_STATE, 'nodal stresses of body 2 (no mesh)')
     call expect(mc_get_nodal_stress(m, 1, sigma_n), MC_OK, 'mc_get_nodal_stress')
     ! P1: a node gets the mean of its cells' constant stresses (nodes 2 and 4 are in one cell)
     call check(all(abs(sigma_n(:, 2) - sigma(:, 1)) < 1d-14) .and. all(abs(sigma_n(:, 4) - sigma(:, 2)) < 1d-14), &
          'nodal stresses of the nodes in one cell')
     call check(all(abs(sigma_n(:, 1) - 0.5d0 * (sigma(:, 1) + sigma(:, 2))) < 1d-14) .and. &
          all(abs(sigma_n(:, 3) - sigma_n(:, 1)) < 1d-14), 'nodal stresses of the nodes in both cells')
     call expect(mc_get_info_int(m, MC_INFO_DOFS, dofs32), MC_OK, 'info, default integer')
     call expect(mc_get_info_int(m, MC_INFO_DOFS, dofs64), MC_OK, 'info, int64')
     call check(dofs32 > 0 .and. dofs64 == dofs32, 'MC_INFO_DOFS')
     call expect(mc_get_info_real(m, MC_INFO_STRAIN_ENERGY, energy), MC_OK, 'real info')
     call check(energy > 0, 'strain energy > 0')
     ! the error estimate (on by default): the clamped square's stress is not uniform
     call expect(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, estimate), MC_OK, 'MC_INFO_ERROR_ESTIMATE')
     call check(estimate > 0 .and. estimate < 1, 'error estimate in (0, 1)')
     call expect(mc_get_error_indicator(m, 1, eta_wrong), MC_ERROR_ARGUMENT, 'indicators of shape (4)')
     call check(index(mc_errmsg(m), '(n_cells)') > 0 .and. index(mc_errmsg(m), '(2)') > 0, &
          'message: ' // mc_errmsg(m))
     call expect(mc_get_error_indicator(m, 2, eta), MC_ERROR_STATE, 'indicators of body 2 (no mesh)')
     call expect(mc_get_error_indicator(m, 1, eta), MC_OK, 'mc_get_error_indicator')
     call check(all(eta >= 0) .and. abs(sum(eta**2) - estimate**2) <= 1d-12 * estimate**2, &
          'the indicators'' squares add up to the estimate''s square')
     call expect(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 2), MC_ERROR_ARGUMENT, 'error estimate 2')
     call check(index(mc_errmsg(m), 'MC_OPTION_ERROR_ESTIMATE') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 0), MC_OK, 'error estimate off')
     call expect(mc_solve(m), MC_OK, 'mc_solve (no error estimate)')
     call expect(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, estimate), MC_OK, 'MC_INFO_ERROR_ESTIMATE (off)')
     call check(estimate == 0, 'no error estimate: 0')
     call expect(mc_get_error_indicator(m, 1, eta), MC_ERROR_STATE, 'indicators with the estimate off')
     call check(index(mc_errmsg(m), 'MC_OPTION_ERROR_ESTIMATE') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_option_int(m, MC_OPTION_ERROR_ESTIMATE, 1), MC_OK, 'error estimate on')
  end if
  call expect(mc_set_body_force(m, 1, 0d0, -1d-3), MC_OK, 'mc_set_body_force')
  call expect(mc_add_nodal_force(m, 1, [3], reshape([1d-4, 0d0], [2, 1])), MC_OK, 'mc_add_nodal_force')
  call expect(mc_add_pressure(m, 1, reshape([3, 4], [2, 1]), [1d-3]), MC_OK, 'mc_add_pressure')
  call expect(mc_clear_loads(m, 1), MC_OK, 'mc_clear_loads')
  call expect(mc_set_cell_elasticity(m, 1, d), MC_OK, 'mc_set_cell_elasticity')
  call expect(mc_set_contact(m, 1, reshape([1, 2], [2, 1])), MC_OK, 'mc_set_contact')
  call expect(mc_set_index_base(m, 0), MC_OK, 'mc_set_index_base(0)')
  call mc_destroy(m)
  call mc_destroy(m)   ! twice is fine: the wrapper nulls the pointer

  ! The README's scene (pressure 0.1 on body 1's top, transmitted exactly) with each interface
  ! solver forced: MC_INFO_INTERFACE_SOLVER is the path that ran; 3 is not a value.
  do k = 1, size(paths)
     call expect(mc_create(m), MC_OK, 'mc_create (contact)')
     call expect(mc_set_mesh(m, 1, xy, tri), MC_OK, 'mesh 1')
     call expect(mc_set_mesh(m, 2, xy2, tri), MC_OK, 'mesh 2')
     call expect(mc_set_material(m, 1, 1d0, 0.3d0), MC_OK, 'material 1')
     call expect(mc_set_material(m, 2, 1d0, 0.3d0), MC_OK, 'material 2')
     call expect(mc_fix(m, 1, [1, 4], MC_X), MC_OK, 'rollers 1')
     call expect(mc_fix(m, 2, [1, 4], MC_X), MC_OK, 'rollers 2')
     call expect(mc_fix(m, 2, [1, 2], MC_Y), MC_OK, 'base 2')
     call expect(mc_add_pressure(m, 1, reshape([3, 4], [2, 1]), [0.1d0]), MC_OK, 'pressure on top')
     call expect(mc_set_contact(m, 1, reshape([1, 2], [2, 1])), MC_OK, 'contact 1')
     call expect(mc_set_contact(m, 2, reshape([3, 4], [2, 1])), MC_OK, 'contact 2')
     call expect(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, 3), MC_ERROR_ARGUMENT, 'interface solver 3')
     call check(index(mc_errmsg(m), 'MC_OPTION_INTERFACE_SOLVER') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_option_int(m, MC_OPTION_INTERFACE_SOLVER, paths(k)), MC_OK, 'interface solver')
     call expect(mc_solve(m), MC_OK, 'mc_solve (contact)')
     ran = -1
     call expect(mc_get_info_int(m, MC_INFO_INTERFACE_SOLVER, ran), MC_OK, 'MC_INFO_INTERFACE_SOLVER')
     write (line, '(a, i0, a, i0)') 'MC_INFO_INTERFACE_SOLVER = ', ran, ', forced ', paths(k)
     call check(ran == paths(k), trim(line))
     pressure = 0
     call expect(mc_get_contact_pressure(m, pressure), MC_OK, 'mc_get_contact_pressure')
     call check(all(abs(pressure - 0.1d0) < 1d-12), 'uniform contact pressure 0.1')
     call expect(mc_get_nodal_stress(m, 2, sigma_n), MC_OK, 'mc_get_nodal_stress (contact)')
     call check(all(abs(sigma_n(2, :) + 0.1d0) < 1d-12), 'sigma_yy = -0.1 at the nodes of body 2')
     ! a contact patch test: the error estimate and every indicator are round-off
     call expect(mc_get_info_real(m, MC_INFO_ERROR_ESTIMATE, estimate), MC_OK, 'MC_INFO_ERROR_ESTIMATE (contact)')
     call expect(mc_get_error_indicator(m, 2, eta), MC_OK, 'mc_get_error_indicator (contact)')
     call check(estimate <= 1d-10 .and. all(eta <= 1d-10), 'error estimate of the patch test: round-off')
     call mc_destroy(m)
  end do

  ! A quadratic cell through the wrapper (cells(8, 1): Q8): the unit square on rollers at x = 0
  ! and y = 0, pressed with 0.1 on its top edge (named by its corners): a uniform stress,
  ! exact in the cell and at its nodes.
  call expect(mc_create(m), MC_OK, 'mc_create (Q8)')
  call expect(mc_set_mesh(m, 1, xy8, q8), MC_OK, 'mc_set_mesh (Q8)')
  call expect(mc_set_material(m, 1, 1d0, 0.3d0), MC_OK, 'material (Q8)')
  call expect(mc_fix(m, 1, [1, 8, 4], MC_X), MC_OK, 'rollers at x = 0 (Q8)')
  call expect(mc_fix(m, 1, [1, 5, 2], MC_Y), MC_OK, 'rollers at y = 0 (Q8)')
  call expect(mc_add_pressure(m, 1, reshape([3, 4], [2, 1]), [0.1d0]), MC_OK, 'pressure on top (Q8)')
  call expect(mc_solve(m), MC_OK, 'mc_solve (Q8)')
  call expect(mc_get_stress(m, 1, sigma8), MC_OK, 'mc_get_stress (Q8)')
  call expect(mc_get_nodal_stress(m, 1, sigma8_n), MC_OK, 'mc_get_nodal_stress (Q8)')
  call check(abs(sigma8(1, 1)) < 1d-12 .and. abs(sigma8(2, 1) + 0.1d0) < 1d-12 .and. abs(sigma8(3, 1)) < 1d-12, &
       'uniform stress sigma_yy = -0.1 (Q8)')
  call check(all(abs(sigma8_n - spread(sigma8(:, 1), 2, 8)) < 1d-12), 'nodal stresses = the uniform stress (Q8)')
  call mc_destroy(m)

  ! Host bodies. The mesh scene first: its answer is what the host bodies must give.
  call expect(mc_create(m), MC_OK, 'mc_create (mesh reference)')
  call readme_body_2(m, 1)
  call expect(mc_set_mesh(m, 1, xy, tri), MC_OK, 'mesh 1 (reference)')
  call expect(mc_set_material(m, 1, 1d0, 0.3d0), MC_OK, 'material 1 (reference)')
  call expect(mc_fix(m, 1, [1, 4], MC_X), MC_OK, 'rollers 1 (reference)')
  call expect(mc_add_pressure(m, 1, reshape([3, 4], [2, 1]), [0.1d0]), MC_OK, 'pressure (reference)')
  call expect(mc_set_contact(m, 1, reshape([1, 2], [2, 1])), MC_OK, 'contact 1 (reference)')
  call expect(mc_solve(m), MC_OK, 'mc_solve (reference)')
  call expect(mc_get_displacement(m, 1, u_mesh), MC_OK, 'displacements (reference)')
  call expect(mc_get_contact_pressure(m, p_mesh), MC_OK, 'pressures (reference)')
  call expect(mc_get_equation_solution(m, 2, sol8), MC_OK, 'equation solution of a mesh body')
  call expect(mc_get_displacement(m, 2, u), MC_OK, 'displacements of body 2')
  call check(all(sol8 == reshape(u, [8])), 'a mesh body''s equation solution: 2 per node')
  call expect(mc_get_contact_load(m, 2, rmesh), MC_OK, 'contact load of a mesh body')
  call check(abs(rmesh(6) + rmesh(8) + 0.1d0) < 1d-12, 'body 2''s contact load: 0.1 down')
  call expect(mc_get_contact_load(m, 2, rmesh(1:6)), MC_ERROR_ARGUMENT, 'contact load of size 6 for 4 nodes')
  call mc_destroy(m)

  ! The host's arrays: element stiffness, steering vectors, loads (S&G: loads(0) is a dump)
  do e = 1, 2
     storkm(:, :, e) = p1_km(xy, tri(:, e), 1d0, 0.3d0)
     g_g(:, e) = reshape(nf(:, tri(:, e)), [6])
  end do
  loads = 0
  loads(nf(2, 3)) = -0.05d0
  loads(nf(2, 4)) = -0.05d0
  kv = 0
  do e = 1, 2
     do j = 1, 6
        do i = 1, 6
           if (g_g(i, e) > 0 .and. g_g(j, e) > 0) kv(g_g(i, e), g_g(j, e)) = kv(g_g(i, e), g_g(j, e)) + storkm(i, j, e)
        end do
     end do
  end do

  ! 1: mc_add_element_matrices_sg; 2: MUMPS's elemental input; 3: coordinates, both triangles,
  ! restrained entries given; 4: coordinates, one triangle; 5: mc_add_element_matrices_sg with the
  ! index base 0 (g_g still as S&G number it)
  do input = 1, 5
     base = 1
     if (input == 5) base = 0
     write (line, '(a, i0)') 'host body input ', input
     call expect(mc_create(m), MC_OK, 'mc_create (host)')
     if (base == 0) call expect(mc_set_index_base(m, 0), MC_OK, 'index base 0')
     call expect(mc_set_host_body(m, 1, xy, nf(:, 1:3), 6), MC_ERROR_ARGUMENT, 'equations of shape (2, 3)')
     call check(index(mc_errmsg(m), '(2, n_nodes)') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_host_body(m, 1, xy, nf - (1 - base), 6), MC_OK, trim(line) // ': mc_set_host_body')
     select case (input)
     case (1, 5)
        call expect(mc_add_element_matrices_sg(m, 1, g_g, storkm(:, :, 1:1)), MC_ERROR_ARGUMENT, 'storkm for 1 of 2')
        call check(index(mc_errmsg(m), 'storkm') > 0, 'message: ' // mc_errmsg(m))
        call expect(mc_add_element_matrices_sg(m, 1, g_g, storkm), MC_OK, trim(line) // ': S&G element matrices')
     case (2)
        eltptr = [1, 7, 13]
        call expect(mc_add_element_matrices(m, 1, eltptr, reshape(g_g, [12]), reshape(storkm, [71])), &
             MC_ERROR_ARGUMENT, 'a_elt of 71 values')
        call expect(mc_add_element_matrices(m, 1, [0, 6, 12], reshape(g_g, [12]), reshape(storkm, [72])), &
             MC_ERROR_ARGUMENT, 'eltptr(1) = 0 with base 1')
        call expect(mc_add_element_matrices(m, 1, eltptr, reshape(g_g, [12]), reshape(storkm, [72])), MC_OK, &
             trim(line) // ': MUMPS element matrices')
     case (3, 4)
        n_entries = 0
        do e = 1, 2
           do j = 1, 6
              do i = 1, 6
                 if (input == 4 .and. (g_g(i, e) == 0 .or. g_g(j, e) == 0 .or. g_g(i, e) > g_g(j, e))) cycle
                 n_entries = n_entries + 1
                 rows(n_entries) = g_g(i, e)
                 cols(n_entries) = g_g(j, e)
                 values(n_entries) = storkm(i, j, e)
              end do
           end do
        end do
        call expect(mc_add_stiffness(m, 1, rows(1:n_entries), cols(1:n_entries - 1), values(1:n_entries)), &
             MC_ERROR_ARGUMENT, 'cols one short')
        if (input == 3) then
           call expect(mc_add_stiffness(m, 1, rows(1:n_entries), cols(1:n_entries), values(1:n_entries)), MC_OK, &
                trim(line) // ': coordinates, full')
        else
           call expect(mc_add_stiffness(m, 1, rows(1:n_entries), cols(1:n_entries), values(1:n_entries), &
                MC_MATRIX_TRIANGLE), MC_OK, trim(line) // ': coordinates, one triangle')
        end if
     end select
     call expect(mc_set_load_vector(m, 1, loads(0:)), MC_ERROR_ARGUMENT, 'loads(0:6): 7 values for 6 equations')
     call check(index(mc_errmsg(m), '(n_equations)') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_load_vector(m, 1, loads(1:)), MC_OK, trim(line) // ': mc_set_load_vector')
     call readme_body_2(m, base)
     call expect(mc_set_contact(m, 1, reshape([1, 2] - (1 - base), [2, 1])), MC_OK, trim(line) // ': contact 1')
     call expect(mc_solve(m), MC_OK, trim(line) // ': mc_solve')
     call expect(mc_get_displacement(m, 1, u_host), MC_OK, trim(line) // ': displacements')
     call expect(mc_get_contact_pressure(m, p_host), MC_OK, trim(line) // ': pressures')
     call check(all(abs(u_host - u_mesh) < 1d-10) .and. all(abs(p_host - p_mesh) < 1d-10), &
          trim(line) // ': displacements and pressures as with a mesh')
     call expect(mc_get_equation_solution(m, 1, sol(1:5)), MC_ERROR_ARGUMENT, 'solution of size 5')
     call expect(mc_get_equation_solution(m, 1, sol), MC_OK, trim(line) // ': mc_get_equation_solution')
     call check(all(abs(sol - [u_mesh(2, 1), u_mesh(:, 2), u_mesh(:, 3), u_mesh(2, 4)]) < 1d-10), &
          trim(line) // ': the solution in the host''s numbering')
     call expect(mc_get_contact_load(m, 1, rload), MC_OK, trim(line) // ': mc_get_contact_load')
     call check(all(abs(matmul(kv, sol) - loads(1:) - rload) < 1d-10), trim(line) // ': K u = f + r')
     call check(abs(rload(1) + rload(3) + rload(5) + rload(6) - 0.1d0) < 1d-12, trim(line) // ': contact lifts 0.1')
     call check(mc_get_stress(m, 1, sigma(:, 1:0)) /= MC_OK, 'stresses of a host body refused')
     call expect(mc_get_error_indicator(m, 1, eta(1:0)), MC_ERROR_STATE, 'indicators of a host body refused')
     if (input == 3) then  ! full storage must be symmetric, summed over the calls: mc_solve checks
        call expect(mc_add_stiffness(m, 1, [1, 2], [2, 1], [1d-3, 2d-3]), MC_OK, 'an asymmetric pair added')
        call expect(mc_solve(m), MC_ERROR_ARGUMENT, 'mc_solve of an asymmetric full matrix')
        call check(len(mc_errmsg(m)) > 0, 'library message for an asymmetric matrix')
     end if
     call mc_destroy(m)
  end do

  ! A curved contact edge of a mesh body: end, end, middle (Q8: the bottom edge 1-2, middle 5)
  call expect(mc_create(m), MC_OK, 'mc_create (curved)')
  call expect(mc_set_mesh(m, 1, xy8, q8), MC_OK, 'mc_set_mesh (curved)')
  call expect(mc_set_contact_curved(m, 1, reshape([1, 2], [2, 1])), MC_ERROR_ARGUMENT, 'curved edges of shape (2, 1)')
  call check(index(mc_errmsg(m), '(3, n_edges)') > 0, 'message: ' // mc_errmsg(m))
  call expect(mc_set_contact_curved(m, 1, reshape([1, 2, 5], [3, 1])), MC_OK, 'mc_set_contact_curved')
  call check(mc_set_contact_curved(m, 1, reshape([1, 2, 6], [3, 1])) /= MC_OK, 'a middle of another edge refused')
  call mc_destroy(m)

  ! Assemblies: blocks [0, 1] x [3 - k, 4 - k] as bodies k = 1 (top), 2, 3 (bottom); rollers on
  ! every left side, body 3 on rollers at y = 0, p on body 1's top; pairs (1 on 2) and (2 on 3).
  ! Bodies 1 and 2 are held in y by contact alone. The uniform stress is exact: every contact
  ! pressure of both pairs is p.
  call expect(mc_create(m), MC_OK, 'mc_create (stack)')
  call expect(mc_set_body_count(m, 3), MC_OK, 'mc_set_body_count')
  do k = 1, 3
     call make_block(stack_nx(k), 3d0 - k)
     call expect(mc_set_mesh(m, k, bxy, bcells), MC_OK, 'mc_set_mesh (stack)')
     call expect(mc_set_material(m, k, 2d0, 0.3d0), MC_OK, 'mc_set_material (stack)')
     call expect(mc_fix(m, k, bleft, MC_X), MC_OK, 'rollers (stack)')
     if (k == 1) call expect(mc_add_pressure(m, 1, btop, spread(stack_p, 1, size(btop, 2))), MC_OK, &
          'pressure (stack)')
     if (k == 3) call expect(mc_fix(m, 3, [(int(i, mc_int), i = 1, stack_nx(3) + 1)], MC_Y), MC_OK, &
          'base (stack)')
  end do
  do k = 1, 2
     call expect(mc_add_contact_pair(m, k, k + 1, pair), MC_OK, 'mc_add_contact_pair')
     call check(pair == k, 'pairs numbered 1, 2')
     call make_block(stack_nx(k), 3d0 - k)
     call expect(mc_set_pair_surface(m, pair, k, bbottom), MC_OK, 'mc_set_pair_surface (non-mortar)')
     call make_block(stack_nx(k + 1), 2d0 - k)
     call expect(mc_set_pair_surface(m, pair, k + 1, btop), MC_OK, 'mc_set_pair_surface (mortar)')
  end do
  call expect(mc_solve(m), MC_OK, 'mc_solve (stack)')
  do k = 1, 2
     call expect(mc_get_pair_contact_count(m, k, npos), MC_OK, 'mc_get_pair_contact_count')
     call check(npos == stack_nx(k) + 1, 'a position per node of the non-mortar bottom')
     allocate(pvals(npos), pnodes(npos), pnormal(2, npos))
     call expect(mc_get_pair_contact_nodes(m, k, pnodes), MC_OK, 'mc_get_pair_contact_nodes')
     call check(all([(any(pnodes == i), i = 1, npos)]), 'the pair''s nodes: the bottom row 1..nx+1')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_PRESSURE, pvals), MC_OK, 'MC_CONTACT_PRESSURE')
     call check(all(abs(pvals - stack_p) <= 1d-10 * stack_p), 'every contact pressure is p')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_FORCE, pvals), MC_OK, 'MC_CONTACT_FORCE')
     call check(abs(sum(pvals) - stack_p) <= 1d-10 * stack_p, 'the pair''s forces add up to p times the width')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_INITIAL_GAP, pvals), MC_OK, 'MC_CONTACT_INITIAL_GAP')
     call check(all(abs(pvals) < 1d-14), 'the blocks touch')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_NORMAL, pnormal), MC_OK, 'MC_CONTACT_NORMAL')
     call check(all(abs(pnormal(1, :)) < 1d-12) .and. all(abs(pnormal(2, :) + 1) < 1d-12), 'normals (0, -1)')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_NORMAL, pvals), MC_ERROR_ARGUMENT, 'normals need (2, n)')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_GAP, pnormal), MC_ERROR_ARGUMENT, 'gaps need (n)')
     call expect(mc_get_pair_contact(m, k, MC_CONTACT_GAP, pvals(2:)), MC_ERROR_ARGUMENT, 'gaps of size n - 1')
     call check(index(mc_errmsg(m), '(n_contact)') > 0, 'message: ' // mc_errmsg(m))
     if (k == 1) then  ! the two-body getters read pair 1
        call expect(mc_get_contact_pressure(m, pvals), MC_OK, 'mc_get_contact_pressure (pair 1)')
        call check(all(abs(pvals - stack_p) <= 1d-10 * stack_p), 'pair 1 through the two-body getter')
     end if
     deallocate(pvals, pnodes, pnormal)
  end do
  allocate(sig(4, 2 * stack_nx(3)), ustack(2, 2 * (stack_nx(3) + 1)))
  call expect(mc_get_stress(m, 3, sig), MC_OK, 'mc_get_stress of body 3')
  call check(all(abs(sig(2, :) + stack_p) <= 1d-10 * stack_p) .and. all(abs(sig(1, :)) <= 1d-10 * stack_p), &
       'body 3: sigma_yy = -p, sigma_xx = 0')
  call expect(mc_get_displacement(m, 3, ustack), MC_OK, 'mc_get_displacement of body 3')
  ! bad input: the library's status and message; the wrapper's for a body beyond the count
  call expect(mc_add_contact_pair(m, 2, 2, pair), MC_ERROR_ARGUMENT, 'a pair of a body with itself')
  call check(index(mc_errmsg(m), 'two different bodies') > 0, 'message: ' // mc_errmsg(m))
  call expect(mc_get_displacement(m, 4, ustack), MC_ERROR_ARGUMENT, 'body 4 of 3')
  call check(index(mc_errmsg(m), 'body must be 1 to 3') > 0, 'message: ' // mc_errmsg(m))
  call expect(mc_set_pair_surface(m, 3, 1, bbottom), MC_ERROR_ARGUMENT, 'pair 3 of 2')
  call check(index(mc_errmsg(m), 'pair = 3') > 0, 'message: ' // mc_errmsg(m))
  call expect(mc_set_pair_surface(m, 1, 1, reshape([1, 2, 3], [3, 1])), MC_ERROR_ARGUMENT, 'edges(3, 1)')
  call expect(mc_set_body_count(m, 2), MC_ERROR_STATE, 'dropping body 3, which pair 2 uses')
  call expect(mc_get_displacement(m, 3, ustack), MC_OK, 'body 3 kept')
  call mc_destroy(m)

  ! Friction: the stick patch test. Body 1 the block [0, 1] x [1, 2] (3 P1 cells across) on body 2,
  ! [0, 1] x [0, 1] (4 cells: non-matching), nu = 0, in the uniform stress sigma_yy = -p,
  ! sigma_xy = tau = 0.4 mu p, sigma_xx = 0: tractions on every free side, body 2's base held (the
  ! exact field is 0 there with nu = 0). Body 1 is held along x by friction alone: every position
  ! sticks with shear -tau, and its top moves by gamma y = 2 tau / E * 2 along x.
  do law = MC_FRICTION_TRESCA, MC_FRICTION_COULOMB
     call expect(mc_create(m), MC_OK, 'mc_create (friction)')
     call expect(mc_set_friction(m, 1, law, 0.3d0), MC_ERROR_STATE, 'friction before any contact pair')
     call check(index(mc_errmsg(m), 'contact pair') > 0, 'message: ' // mc_errmsg(m))
     do k = 1, 2
        call make_block(fric_nx(k), 2d0 - k)
        call expect(mc_set_mesh(m, k, bxy, bcells), MC_OK, 'mc_set_mesh (friction)')
        call expect(mc_set_material(m, k, 1d0, 0d0), MC_OK, 'mc_set_material (friction)')
        call expect(mc_add_traction(m, k, reshape(bleft, [2, 1]), reshape([0d0, -fric_tau], [2, 1])), MC_OK, &
             'traction on the left side')
        call expect(mc_add_traction(m, k, reshape(bleft + int(fric_nx(k), mc_int), [2, 1]), &
             reshape([0d0, fric_tau], [2, 1])), MC_OK, 'traction on the right side')
        if (k == 1) then
           call expect(mc_add_traction(m, 1, btop, spread([fric_tau, -fric_p], 2, size(btop, 2))), MC_OK, &
                'traction on the top')
           call expect(mc_set_contact(m, 1, bbottom), MC_OK, 'contact 1 (friction)')
        else
           call expect(mc_fix(m, 2, [(int(i, mc_int), i = 1, fric_nx(2) + 1)], MC_XY), MC_OK, 'base (friction)')
           call expect(mc_set_contact(m, 2, btop), MC_OK, 'contact 2 (friction)')
        end if
     end do
     ! bad input: the library's status and message; the model stays usable
     call expect(mc_set_friction(m, 1, MC_FRICTION_COULOMB, -0.1d0), MC_ERROR_ARGUMENT, 'a negative mu')
     call check(index(mc_errmsg(m), 'mu') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_friction(m, 1, MC_FRICTION_TRESCA, -1d0), MC_ERROR_ARGUMENT, 'a negative bound')
     call check(index(mc_errmsg(m), 'bound') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_friction(m, 1, 3, 0.3d0), MC_ERROR_ARGUMENT, 'law 3')
     call check(index(mc_errmsg(m), 'law = 3') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_friction(m, 2, law, 0.3d0), MC_ERROR_ARGUMENT, 'pair 2 of 1')
     call check(index(mc_errmsg(m), 'pair = 2') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, 0), MC_ERROR_ARGUMENT, 'load steps 0')
     call check(index(mc_errmsg(m), 'MC_OPTION_LOAD_STEPS') > 0, 'message: ' // mc_errmsg(m))
     call expect(mc_set_option_real(m, MC_OPTION_FRICTION_CT, -1d0), MC_ERROR_ARGUMENT, 'a negative c_t')
     ! Tresca: a bound above tau (mu p, as Coulomb's), so both stick
     fric_value = fric_mu
     if (law == MC_FRICTION_TRESCA) fric_value = fric_mu * fric_p
     call expect(mc_set_friction(m, 1, law, fric_value), MC_OK, 'mc_set_friction')
     call expect(mc_set_option_int(m, MC_OPTION_LOAD_STEPS, 2), MC_OK, 'MC_OPTION_LOAD_STEPS')
     call expect(mc_set_option_real(m, MC_OPTION_FRICTION_CT, 0d0), MC_OK, 'MC_OPTION_FRICTION_CT')
     call expect(mc_solve(m), MC_OK, 'mc_solve (friction)')
     call expect(mc_get_pair_contact_count(m, 1, npos), MC_OK, 'mc_get_pair_contact_count (friction)')
     call check(npos == fric_nx(1) + 1, 'a position per node of body 1''s bottom')
     allocate(pvals(npos), shear(npos), fslip(npos), fstate(npos), utop(2, 2 * (fric_nx(1) + 1)))
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_STATE, fstate), MC_OK, 'MC_CONTACT_STATE')
     call check(all(fstate == MC_STATE_STICK), 'every position sticks')
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, shear), MC_OK, 'MC_CONTACT_SHEAR')
     call check(all(abs(shear + fric_tau) <= 1d-10 * fric_p), 'shear -tau everywhere')
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_PRESSURE, pvals), MC_OK, 'MC_CONTACT_PRESSURE (friction)')
     call check(all(abs(pvals - fric_p) <= 1d-10 * fric_p), 'pressure p everywhere')
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_SLIP, fslip), MC_OK, 'MC_CONTACT_SLIP')
     call check(all(abs(fslip) <= 1d-10 * fric_p), 'no slip')
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_SLIP_TOTAL, fslip), MC_OK, 'MC_CONTACT_SLIP_TOTAL')
     call check(all(abs(fslip) <= 1d-10 * fric_p), 'no accumulated slip')
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, shear(2:)), MC_ERROR_ARGUMENT, 'shear of size n - 1')
     call expect(mc_get_info_int(m, MC_INFO_STICK_NODES, stick), MC_OK, 'MC_INFO_STICK_NODES')
     call expect(mc_get_info_int(m, MC_INFO_SLIP_NODES, slip), MC_OK, 'MC_INFO_SLIP_NODES')
     call check(stick > 0 .and. slip == 0, 'stick rows only')
     call expect(mc_get_info_real(m, MC_INFO_FRICTION_COMPLEMENTARITY, fcompl), MC_OK, &
          'MC_INFO_FRICTION_COMPLEMENTARITY')
     call check(fcompl <= 1d-10, 'friction complementarity: round-off')
     call expect(mc_get_displacement(m, 1, utop), MC_OK, 'mc_get_displacement (friction)')
     call check(abs(utop(1, 2 * (fric_nx(1) + 1)) - 4 * fric_tau) <= 1d-10 * fric_tau, &
          'the top-right corner moves by gamma y = 4 tau along x')
     ! forgotten, then solved again from the unloaded state: the same answer
     call expect(mc_reset_history(m), MC_OK, 'mc_reset_history')
     call expect(mc_solve(m), MC_OK, 'mc_solve after mc_reset_history')
     call expect(mc_get_pair_contact(m, 1, MC_CONTACT_SHEAR, shear), MC_OK, 'MC_CONTACT_SHEAR after the reset')
     call check(all(abs(shear + fric_tau) <= 1d-10 * fric_p), 'shear -tau after the reset')
     deallocate(pvals, shear, fslip, fstate, utop)
     call mc_destroy(m)
  end do

  if (failures > 0) then
     print '(i0, a)', failures, ' check(s) failed'
     error stop 1
  end if
  print '(a)', 'all Fortran binding checks passed'

contains

  !> Body 2 of the README's scene (the square below body 1) with ids from `base`.
  subroutine readme_body_2(model, base)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: base
    integer(mc_int) :: shift
    shift = int(1 - base, mc_int)
    call expect(mc_set_mesh(model, 2, xy2, tri - shift), MC_OK, 'mesh 2')
    call expect(mc_set_material(model, 2, 1d0, 0.3d0), MC_OK, 'material 2')
    call expect(mc_fix(model, 2, [1, 4] - shift, MC_X), MC_OK, 'rollers 2')
    call expect(mc_fix(model, 2, [1, 2] - shift, MC_Y), MC_OK, 'base 2')
    call expect(mc_set_contact(model, 2, reshape([3, 4] - shift, [2, 1])), MC_OK, 'contact 2')
  end subroutine readme_body_2

  !> A block [0, 1] x [y0, y0 + 1] of nx x 1 P1 cells, node (i, j) numbered j (nx + 1) + i + 1,
  !> into bxy, bcells, bbottom and btop (edge chains, left to right) and bleft (the left side).
  subroutine make_block(nx, y0)
    integer, intent(in) :: nx
    real(mc_real), intent(in) :: y0
    integer :: a, b
    if (allocated(bxy)) deallocate(bxy, bcells, bbottom, btop, bleft)
    allocate(bxy(2, 2 * (nx + 1)), bcells(3, 2 * nx), bbottom(2, nx), btop(2, nx))
    do b = 0, 1
       do a = 0, nx
          bxy(:, b * (nx + 1) + a + 1) = [real(a, mc_real) / nx, y0 + b]
       end do
    end do
    do a = 1, nx
       bcells(:, 2 * a - 1) = int([a, a + 1, nx + 2 + a], mc_int)
       bcells(:, 2 * a) = int([a, nx + 2 + a, nx + 1 + a], mc_int)
       bbottom(:, a) = int([a, a + 1], mc_int)
       btop(:, a) = int([nx + 1 + a, nx + 2 + a], mc_int)
    end do
    bleft = int([1, nx + 2], mc_int)
  end subroutine make_block

  !> The plane-strain stiffness of a P1 triangle, freedoms x1 y1 x2 y2 x3 y3.
  function p1_km(coord, nodes, young, poisson) result(km)
    real(mc_real), intent(in) :: coord(:, :), young, poisson
    integer(mc_int), intent(in) :: nodes(3)
    real(mc_real) :: km(6, 6), bee(3, 6), dee(3, 3), x(3), y(3), area, f
    integer :: a, b, c
    x = coord(1, nodes)
    y = coord(2, nodes)
    area = 0.5d0 * ((x(2) - x(1)) * (y(3) - y(1)) - (x(3) - x(1)) * (y(2) - y(1)))
    bee = 0
    do a = 1, 3
       b = mod(a, 3) + 1
       c = mod(a + 1, 3) + 1
       bee(1, 2 * a - 1) = (y(b) - y(c)) / (2 * area)
       bee(2, 2 * a) = (x(c) - x(b)) / (2 * area)
       bee(3, 2 * a - 1) = bee(2, 2 * a)
       bee(3, 2 * a) = bee(1, 2 * a - 1)
    end do
    f = young / ((1 + poisson) * (1 - 2 * poisson))
    dee = reshape([f * (1 - poisson), f * poisson, 0d0, f * poisson, f * (1 - poisson), 0d0, &
         0d0, 0d0, f * (1 - 2 * poisson) / 2], [3, 3])
    km = area * matmul(matmul(transpose(bee), dee), bee)
  end function p1_km

  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    if (.not. ok) then
       failures = failures + 1
       print '(2a)', 'FAIL: ', what
    end if
  end subroutine check

  subroutine expect(status, want, what)
    integer, intent(in) :: status, want
    character(len=*), intent(in) :: what
    if (status /= want) then
       failures = failures + 1
       print '(a, a, a, a, a, a, a, a)', 'FAIL: ', what, ': got ', mc_status_string(status), ', expected ', &
            mc_status_string(want), ': ', mc_errmsg(m)
    end if
  end subroutine expect

end program test_mortarcontact
