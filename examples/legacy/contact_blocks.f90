!-------------------------------------------------------------------------------------------------
! contact_blocks.f90 - a legacy finite-element program adds contact between two of its bodies
! through mortarcontact's host bodies. docs/tutorial_legacy.md walks through it.
!
! The program is written against Smith, Griffiths and Margetts' "Programming the Finite Element
! Method" (5th ed.) library, modules geom and main (fe_library.f90 here, a stand-in with the
! same routine names, argument lists and numbering: link the real library instead and the
! program is unchanged). As their chapter-5 programs do, it builds its meshes with geom_rect
! (8-node quadrilaterals, nodes and elements counted down each column from the TOP), numbers the
! restraints with formnf, integrates with sample/shape_der/beemat/deemat at 3 x 3 Gauss points,
! and stores the stiffness both ways their programs do: element by element (g_g and storkm, as
! the preconditioned conjugate gradient programs) and in skyline storage (kv and kdiag from
! fkdiag and fsparv, as p51 before sparin and spabac). Its load vector is loads(0:neq).
!
! The scene, plane strain with unit thickness:
!   body 1  a crowned block (a short cylinder): -1 <= x <= 1, its top y = 1, its bottom a
!           circular arc of radius 10 touching the origin; 8 x 4 elements; E = 200, v = 0.3; a
!           uniform pressure p = 1.5 on its top; restrained in x at its top centre, and held
!           vertically and in rotation by contact alone;
!   body 2  a foundation -3 <= x <= 3, -2 <= y <= 0; 16 x 4 elements; E = 100, v = 0.25; its
!           base restrained.
! Steps 1-4 are what the program did before it knew about contact. Steps 5-7 hand both bodies
! to mortarcontact as host bodies (nf, g_g, storkm, loads and the contact sides), solve, and read
! the displacements and contact forces back into the program's own arrays. Step 8 solves again
! with both bodies handed over as their skyline matrices kv, kdiag, and checks body 2 against the
! program's own sparin and spabac. Step 9 solves with body 2 as a library mesh body of Q8 cells
! (mc_set_mesh). Step 10 solves the same scene with both bodies as mesh bodies (mc_set_mesh,
! mc_set_material, mc_fix, mc_add_pressure) and checks that the displacements and the contact
! pressures of steps 5, 8 and 9 agree with it to 1e-10 of their largest values.
!
! Exit status: 0 if they agree, 1 if they do not, 2 if a call fails. Build and run: ctest runs it
! as tutorial_legacy (examples/legacy/CMakeLists.txt); by hand, with the library installed in
! PREFIX (docs/tutorial_legacy.md, "Building against an installed library"),
!   gfortran fe_library.f90 contact_blocks.f90 $(pkg-config --cflags --libs mortarcontact-fortran) \
!     -Wl,-rpath,$(pkg-config --variable=libdir mortarcontact-fortran)
!-------------------------------------------------------------------------------------------------
program contact_blocks
  use geom
  use main
  use mortarcontact
  implicit none
  integer, parameter :: iwp = selected_real_kind(15)
  integer, parameter :: nod = 8, nodof = 2, ndof = nod * nodof, nip = 9
  character(len=15), parameter :: element = 'quadrilateral'
  ! The local order of the 8-node quadrilateral (fe_library.f90) in the library's (Gmsh's) order:
  ! corners counter-clockwise from (-1, -1), then the mid-sides of sides 1-2, 2-3, 3-4, 4-1
  integer, parameter :: to_library(nod) = [1, 7, 5, 3, 8, 6, 4, 2]
  ! An element's bottom and top sides in the book's order, corner-middle-corner, each walked with
  ! the element on its left; mc_set_contact_curved wants (end, end, middle): side(to_curved)
  integer, parameter :: bottom_side(3) = [1, 8, 7], top_side(3) = [5, 4, 3], to_curved(3) = [1, 3, 2]
  integer, parameter :: host_host = 1, skyline = 2, host_mesh = 3, mesh_mesh = 4   ! the solves
  real(iwp), parameter :: p = 1.5_iwp, tolerance = 1.e-10_iwp

  type body_arrays                                   ! what the program holds for each body
     integer :: nxe, nye, nn, nels, neq
     real(iwp) :: e, v                               ! Young's modulus, Poisson's ratio
     real(iwp), allocatable :: x_coords(:), y_coords(:)  ! mesh lines for geom_rect, y top down
     real(iwp), allocatable :: g_coord(:, :)         ! (2, nn) node coordinates
     integer, allocatable :: g_num(:, :)             ! (nod, nels) element nodes
     integer, allocatable :: nf(:, :)                ! (nodof, nn) equation numbers, 0 = restrained
     integer, allocatable :: g_g(:, :)               ! (ndof, nels) steering vectors
     real(iwp), allocatable :: storkm(:, :, :)       ! (ndof, ndof, nels) element stiffnesses
     integer, allocatable :: kdiag(:)                ! (neq) skyline: positions of the diagonals
     real(iwp), allocatable :: kv(:)                 ! (kdiag(neq)) skyline: lower triangle
     real(iwp), allocatable :: loads(:)              ! (0:neq) load vector
     real(iwp), allocatable :: displ(:)              ! (0:neq) solution vector
     real(iwp), allocatable :: fcont(:)              ! (0:neq) contact forces as a load vector
     integer, allocatable :: surface(:, :)           ! (3, n) contact sides: end, end, middle
     real(iwp), allocatable :: disps(:, :, :)        ! (2, nn, solve) node displacements
  end type body_arrays
  type(body_arrays) :: b(2)
  integer, allocatable :: top(:, :)                  ! (3, nxe) body 1's loaded sides
  integer(mc_int), allocatable :: cnodes(:, :)       ! (ncontact, solve) contact positions' nodes
  real(iwp), allocatable :: pres(:, :)               ! (ncontact, solve) contact pressures
  type(mc_model) :: m
  integer :: ib, iel, i, k, ip, ncontact, status
  integer :: num(nod), g(ndof)
  integer(mc_int64) :: iterations, rows, active
  real(iwp) :: points(nip, 2), weights(nip), dee(3, 3), coord(nod, 2), der(2, nod), deriv(2, nod)
  real(iwp) :: jac(2, 2), det, bee(3, ndof), km(ndof, ndof), kd(ndof), side, bottom
  real(iwp) :: du(3), dp(3), dx
  real(iwp), allocatable :: residual(:), sigma(:, :), kv_factor(:), x(:)
  character(len=:), allocatable :: refusal
  logical :: passed

  ! ---- step 1: the meshes of the two bodies ----
  ! geom_rect's mesh lines: x_coords left to right, y_coords from the TOP down (row 1 is the top)
  b(1)%nxe = 8
  b(1)%nye = 4
  b(1)%e = 200._iwp
  b(1)%v = 0.3_iwp
  b(1)%x_coords = [(-1._iwp + 2._iwp * i / b(1)%nxe, i = 0, b(1)%nxe)]
  b(1)%y_coords = [(1._iwp - 1._iwp * i / b(1)%nye, i = 0, b(1)%nye)]
  b(2)%nxe = 16
  b(2)%nye = 4
  b(2)%e = 100._iwp
  b(2)%v = 0.25_iwp
  b(2)%x_coords = [(-3._iwp + 6._iwp * i / b(2)%nxe, i = 0, b(2)%nxe)]
  b(2)%y_coords = [(0._iwp - 2._iwp * i / b(2)%nye, i = 0, b(2)%nye)]
  do ib = 1, 2
     call mesh_size(element, nod, b(ib)%nels, b(ib)%nn, b(ib)%nxe, b(ib)%nye)
     allocate(b(ib)%g_coord(2, b(ib)%nn), b(ib)%g_num(nod, b(ib)%nels))
     do iel = 1, b(ib)%nels
        call geom_rect(element, iel, b(ib)%x_coords, b(ib)%y_coords, coord, num, 'y')
        b(ib)%g_num(:, iel) = num
        b(ib)%g_coord(:, num) = transpose(coord)
     end do
  end do
  ! body 1's bottom becomes the arc y = 10 - sqrt(100 - x**2): each node keeps its fraction of
  ! the height between the arc and the top y = 1 (geom_rect makes rectangles only)
  do i = 1, b(1)%nn
     bottom = 10._iwp - sqrt(100._iwp - b(1)%g_coord(1, i)**2)
     b(1)%g_coord(2, i) = bottom + (1._iwp - bottom) * b(1)%g_coord(2, i)
  end do
  ! geom_rect counts down each column: element (ip, iq), iq = 1 the TOP row, is (ip - 1) * nye + iq.
  ! Body 1 touches with its bottom row (iq = nye), body 2 with its top row (iq = 1).
  allocate(b(1)%surface(3, b(1)%nxe), b(2)%surface(3, b(2)%nxe), top(3, b(1)%nxe))
  do ip = 1, b(1)%nxe
     b(1)%surface(:, ip) = b(1)%g_num(bottom_side(to_curved), ip * b(1)%nye)
     top(:, ip) = b(1)%g_num(top_side(to_curved), (ip - 1) * b(1)%nye + 1)
  end do
  do ip = 1, b(2)%nxe
     b(2)%surface(:, ip) = b(2)%g_num(top_side(to_curved), (ip - 1) * b(2)%nye + 1)
  end do
  ! a contact side must lie on the boundary: an interior line (the wrong row) belongs to two elements
  do ib = 1, 2
     do k = 1, size(b(ib)%surface, 2)
        if (count(any(b(ib)%g_num == b(ib)%surface(1, k), 1) .and. &
             any(b(ib)%g_num == b(ib)%surface(2, k), 1)) /= 1) then
           write (*, '(a, i0, a, i0, a)') 'contact_blocks: body ', ib, ' contact side ', k, ' is not on the boundary'
           stop 1
        end if
     end do
  end do

  ! ---- step 2: restraints and equation numbering ----
  ! nf = 1 (free) or 0 (restrained), then numbered 1..neq node by node. Body 1 is restrained in
  ! x at its top centre only; body 2's base is restrained in x and y.
  do ib = 1, 2
     allocate(b(ib)%nf(nodof, b(ib)%nn))
     b(ib)%nf = 1
  end do
  do i = 1, b(1)%nn
     if (abs(b(1)%g_coord(1, i)) < 1.e-9_iwp .and. abs(b(1)%g_coord(2, i) - 1._iwp) < 1.e-9_iwp) &
          b(1)%nf(1, i) = 0
  end do
  do i = 1, b(2)%nn
     if (abs(b(2)%g_coord(2, i) + 2._iwp) < 1.e-9_iwp) b(2)%nf(:, i) = 0
  end do
  do ib = 1, 2
     call formnf(b(ib)%nf)
     b(ib)%neq = maxval(b(ib)%nf)
  end do

  ! ---- step 3: element stiffness integration and storage ----
  ! the skyline profile first, as p51 does: row lengths from every steering vector, then positions
  do ib = 1, 2
     allocate(b(ib)%g_g(ndof, b(ib)%nels), b(ib)%kdiag(b(ib)%neq))
     b(ib)%kdiag = 0
     do iel = 1, b(ib)%nels
        call num_to_g(b(ib)%g_num(:, iel), b(ib)%nf, g)
        b(ib)%g_g(:, iel) = g
        call fkdiag(b(ib)%kdiag, g)
     end do
     do i = 2, b(ib)%neq
        b(ib)%kdiag(i) = b(ib)%kdiag(i) + b(ib)%kdiag(i - 1)
     end do
     allocate(b(ib)%kv(b(ib)%kdiag(b(ib)%neq)), b(ib)%storkm(ndof, ndof, b(ib)%nels))
     b(ib)%kv = 0._iwp
  end do
  call sample(element, points, weights)
  do ib = 1, 2
     call deemat(dee, b(ib)%e, b(ib)%v)
     do iel = 1, b(ib)%nels
        num = b(ib)%g_num(:, iel)
        coord = transpose(b(ib)%g_coord(:, num))
        g = b(ib)%g_g(:, iel)
        km = 0._iwp
        do i = 1, nip
           call shape_der(der, points, i)
           jac = matmul(der, coord)
           det = determinant(jac)
           call invert(jac)
           deriv = matmul(jac, der)
           call beemat(bee, deriv)
           km = km + matmul(matmul(transpose(bee), dee), bee) * det * weights(i)
        end do
        b(ib)%storkm(:, :, iel) = km               ! element by element ...
        call fsparv(b(ib)%kv, km, g, b(ib)%kdiag)  ! ... or assembled in skyline storage
     end do
  end do

  ! ---- step 4: the load vector ----
  ! the pressure p on body 1's top as consistent nodal forces: 1/6, 1/6 and 2/3 of p times the
  ! side's length at its ends and middle; body 2 carries no load
  do ib = 1, 2
     allocate(b(ib)%loads(0:b(ib)%neq), b(ib)%displ(0:b(ib)%neq), b(ib)%fcont(0:b(ib)%neq))
     allocate(b(ib)%disps(nodof, b(ib)%nn, 4))
     b(ib)%loads = 0._iwp
  end do
  do ip = 1, b(1)%nxe
     side = abs(b(1)%g_coord(1, top(2, ip)) - b(1)%g_coord(1, top(1, ip)))
     do k = 1, 3
        i = b(1)%nf(2, top(k, ip))
        b(1)%loads(i) = b(1)%loads(i) - p * side * merge(4._iwp, 1._iwp, k == 3) / 6._iwp
     end do
  end do
  b(1)%loads(0) = 0._iwp

  ! ---- step 5: both bodies as host bodies ----
  call check(mc_create(m), 'mc_create')   ! the Fortran module counts ids and equations from 1
  call add_host_body(1)
  call add_host_body(2)
  call check(mc_solve(m), 'mc_solve')

  ! ---- step 6: read the results back in the program's numbering ----
  call read_results(host_host, [.true., .true.])

  ! ---- step 7: the report ----
  call check(mc_get_info_int(m, MC_INFO_ITERATIONS, iterations), 'mc_get_info_int')
  call check(mc_get_info_int(m, MC_INFO_CONTACT_NODES, rows), 'mc_get_info_int')
  call check(mc_get_info_int(m, MC_INFO_ACTIVE_NODES, active), 'mc_get_info_int')
  ! stresses need the library's cells: the program computes them from displ with its elements
  allocate(sigma(4, 0))
  status = mc_get_stress(m, 1, sigma)
  refusal = mc_status_string(status) // ': ' // mc_errmsg(m)
  call mc_destroy(m)
  write (*, '(a)') 'contact_blocks: a crowned block on a foundation, 8-node quadrilaterals, plane strain'
  do ib = 1, 2
     write (*, '(a, i0, a, i0, a, i0, a, i0, a)') '  body ', ib, ': ', b(ib)%nn, ' nodes, ', b(ib)%nels, &
          ' elements, ', b(ib)%neq, ' equations'
  end do
  write (*, '(a, i0, a, i0, a, i0, a, i0, a)') 'both bodies as host bodies: ', ncontact, ' contact positions, ', &
       active, ' of ', rows, ' constraint rows active, ', iterations, ' active-set iterations'
  write (*, '(a)') '   node         x          u_y   pressure'
  do k = 1, ncontact
     i = cnodes(k, host_host)
     write (*, '(i7, 3f11.5)') i, b(1)%g_coord(1, i), b(1)%disps(2, i, host_host), pres(k, host_host)
  end do
  write (*, '(a, f11.7, a, f11.7, a)') 'body 1: contact force ', sum(b(1)%fcont(b(1)%nf(2, :))), &
       ' upwards, load ', -sum(b(1)%loads(b(1)%nf(2, :))), ' downwards'
  do ib = 1, 2                            ! K u = f + r, with the program's own storkm
     allocate(residual(0:b(ib)%neq))
     residual = 0._iwp
     do iel = 1, b(ib)%nels
        g = b(ib)%g_g(:, iel)
        kd = matmul(b(ib)%storkm(:, :, iel), b(ib)%displ(g))
        do k = 1, ndof
           residual(g(k)) = residual(g(k)) + kd(k)
        end do
     end do
     residual = residual - b(ib)%loads - b(ib)%fcont
     residual(0) = 0._iwp
     write (*, '(a, i0, a, es8.1, a)') 'body ', ib, ': |K u - f - r| = ', maxval(abs(residual)) / &
          max(maxval(abs(b(ib)%loads)), maxval(abs(b(ib)%fcont))), ' of the largest force'
     deallocate(residual)
  end do
  write (*, '(a)') 'mc_get_stress of a host body: ' // refusal
  if (status /= MC_ERROR_STATE) then
     write (*, '(a)') 'contact_blocks: FAILED, mc_get_stress should refuse a host body'
     stop 1
  end if

  ! ---- step 8: both bodies as skyline matrices ----
  ! kv is handed over before sparin factors it in place; the library keeps its own copy
  call check(mc_create(m), 'mc_create')
  do ib = 1, 2
     call check(mc_set_host_body(m, ib, b(ib)%g_coord, b(ib)%nf, b(ib)%neq), 'mc_set_host_body')
     call check(add_skyline_stiffness(m, ib, b(ib)%kv, b(ib)%kdiag), 'mc_add_stiffness')
     call check(mc_set_load_vector(m, ib, b(ib)%loads(1:)), 'mc_set_load_vector')
     call check(mc_set_contact_curved(m, ib, b(ib)%surface), 'mc_set_contact_curved')
  end do
  call check(mc_solve(m), 'mc_solve')
  call read_results(skyline, [.true., .true.])
  call mc_destroy(m)
  ! body 2 is held by its base, so its kv alone is positive definite: the program's own solver
  ! with the contact forces added to the loads gives the same displacements
  kv_factor = b(2)%kv
  call sparin(kv_factor, b(2)%kdiag)
  allocate(x(0:b(2)%neq))
  x = b(2)%loads + b(2)%fcont
  call spabac(kv_factor, x, b(2)%kdiag)
  dx = maxval(abs(x(1:) - b(2)%displ(1:))) / maxval(abs(b(2)%displ))
  write (*, '(a, es8.1, a)') 'body 2: sparin/spabac of loads + contact forces: ', dx, ' from the contact solve'

  ! ---- step 9: body 2 as a library mesh body ----
  call check(mc_create(m), 'mc_create')
  call add_host_body(1)
  call add_mesh_body(2)
  call check(mc_solve(m), 'mc_solve')
  call read_results(host_mesh, [.true., .false.])
  call mc_destroy(m)

  ! ---- step 10: the same scene with mesh bodies, and the check ----
  call check(mc_create(m), 'mc_create')
  call add_mesh_body(1)
  call add_mesh_body(2)
  call check(mc_solve(m), 'mc_solve')
  call read_results(mesh_mesh, [.false., .false.])
  call mc_destroy(m)
  call compare(host_host, du(1), dp(1))
  call compare(skyline, du(2), dp(2))
  call compare(host_mesh, du(3), dp(3))
  write (*, '(a)') 'against mesh bodies (Q8 cells), largest difference / largest value:'
  write (*, '(a, es8.1, a, es8.1)') '  both bodies host bodies: displacements ', du(1), ', pressures ', dp(1)
  write (*, '(a, es8.1, a, es8.1)') '  both bodies skylines:    displacements ', du(2), ', pressures ', dp(2)
  write (*, '(a, es8.1, a, es8.1)') '  body 2 a mesh body:      displacements ', du(3), ', pressures ', dp(3)
  passed = max(maxval(du), maxval(dp), dx) <= tolerance
  if (.not. passed) then
     write (*, '(a, es8.1)') 'contact_blocks: FAILED, differences above ', tolerance
     stop 1
  end if
  write (*, '(a, es8.1, a)') 'contact_blocks: passed (differences below ', tolerance, ')'

contains

  !> Hands body ib to the model as a host body: its nodes with their equation numbers (nf), its
  !> element matrices (g_g, storkm), its load vector and its contact sides.
  subroutine add_host_body(ib)
    integer, intent(in) :: ib
    call check(mc_set_host_body(m, ib, b(ib)%g_coord, b(ib)%nf, b(ib)%neq), 'mc_set_host_body')
    call check(mc_add_element_matrices_sg(m, ib, b(ib)%g_g, b(ib)%storkm), 'mc_add_element_matrices_sg')
    call check(mc_set_load_vector(m, ib, b(ib)%loads(1:)), 'mc_set_load_vector')
    call check(mc_set_contact_curved(m, ib, b(ib)%surface), 'mc_set_contact_curved')
  end subroutine add_host_body

  !> Hands a skyline matrix to host body `body`: Smith and Griffiths' kv and kdiag (kdiag(i) the
  !> position of equation i's diagonal in kv, row i of the lower triangle ending there), taken
  !> before sparin overwrites kv with its factor. Every position of kv becomes one coordinate
  !> entry (row, column) of the lower triangle, MC_MATRIX_TRIANGLE; the zeros inside the profile
  !> go along (they cost memory only). Returns the status of mc_add_stiffness.
  integer function add_skyline_stiffness(model, body, kv, kdiag) result(status)
    type(mc_model), intent(inout) :: model
    integer, intent(in) :: body
    real(iwp), intent(in) :: kv(:)
    integer, intent(in) :: kdiag(:)
    integer(mc_int), allocatable :: rows(:), cols(:)
    integer :: row, first, k
    allocate(rows(size(kv)), cols(size(kv)))
    first = 1                                         ! kv(first:kdiag(row)) is row `row`
    do row = 1, size(kdiag)
       do k = first, kdiag(row)
          rows(k) = row
          cols(k) = row - (kdiag(row) - k)            ! the diagonal at k = kdiag(row)
       end do
       first = kdiag(row) + 1
    end do
    status = mc_add_stiffness(model, body, rows, cols, kv, MC_MATRIX_TRIANGLE)
  end function add_skyline_stiffness

  !> Hands body ib to the model as a mesh body of the library's Q8 cells, with the same
  !> material, restraints, load and contact sides.
  subroutine add_mesh_body(ib)
    integer, intent(in) :: ib
    integer(mc_int), allocatable :: cells(:, :), fixed(:)
    integer :: i, iel, n, components
    allocate(cells(nod, b(ib)%nels), fixed(b(ib)%nn))
    do iel = 1, b(ib)%nels
       cells(:, iel) = b(ib)%g_num(to_library, iel)
    end do
    call check(mc_set_mesh(m, ib, b(ib)%g_coord, cells), 'mc_set_mesh')
    call check(mc_set_material(m, ib, b(ib)%e, b(ib)%v), 'mc_set_material')
    do components = MC_X, MC_XY           ! nf's zeros as supports: x (1), y (2) or both (3)
       n = 0
       do i = 1, b(ib)%nn
          if (merge(MC_X, 0, b(ib)%nf(1, i) == 0) + merge(MC_Y, 0, b(ib)%nf(2, i) == 0) == components) then
             n = n + 1
             fixed(n) = i
          end if
       end do
       if (n > 0) call check(mc_fix(m, ib, fixed(1:n), components), 'mc_fix')
    end do
    if (ib == 1) call check(mc_add_pressure(m, 1, top(1:2, :), [(p, i = 1, size(top, 2))]), 'mc_add_pressure')
    call check(mc_set_contact(m, ib, b(ib)%surface(1:2, :)), 'mc_set_contact')
  end subroutine add_mesh_body

  !> After a solve: the node displacements of both bodies (host bodies: through their solution
  !> vectors and nf) and the contact positions and pressures, kept as those of solve `run`.
  subroutine read_results(run, host)
    integer, intent(in) :: run
    logical, intent(in) :: host(2)
    integer :: ib, i
    integer(mc_int) :: n
    do ib = 1, 2
       if (host(ib)) then
          call check(mc_get_equation_solution(m, ib, b(ib)%displ(1:)), 'mc_get_equation_solution')
          call check(mc_get_contact_load(m, ib, b(ib)%fcont(1:)), 'mc_get_contact_load')
          b(ib)%displ(0) = 0._iwp
          b(ib)%fcont(0) = 0._iwp
          do i = 1, b(ib)%nn
             b(ib)%disps(:, i, run) = b(ib)%displ(b(ib)%nf(:, i))
          end do
       else
          call check(mc_get_displacement(m, ib, b(ib)%disps(:, :, run)), 'mc_get_displacement')
       end if
    end do
    call check(mc_get_contact_count(m, n), 'mc_get_contact_count')
    if (.not. allocated(cnodes)) then
       ncontact = n
       allocate(cnodes(ncontact, 4), pres(ncontact, 4))
    end if
    if (n /= ncontact) then
       write (*, '(a, i0, a, i0)') 'contact_blocks: FAILED, contact positions ', n, ' instead of ', ncontact
       stop 1
    end if
    call check(mc_get_contact_nodes(m, cnodes(:, run)), 'mc_get_contact_nodes')
    call check(mc_get_contact_pressure(m, pres(:, run)), 'mc_get_contact_pressure')
  end subroutine read_results

  !> The largest differences of solve `run` from the mesh bodies' solve: du of the displacements,
  !> dp of the contact pressures, each relative to the largest value of the mesh bodies' solve.
  subroutine compare(run, du, dp)
    integer, intent(in) :: run
    real(iwp), intent(out) :: du, dp
    real(iwp) :: umax
    umax = max(maxval(abs(b(1)%disps(:, :, mesh_mesh))), maxval(abs(b(2)%disps(:, :, mesh_mesh))))
    du = max(maxval(abs(b(1)%disps(:, :, run) - b(1)%disps(:, :, mesh_mesh))), &
         maxval(abs(b(2)%disps(:, :, run) - b(2)%disps(:, :, mesh_mesh)))) / umax
    dp = maxval(abs(pres(:, run) - pres(:, mesh_mesh))) / maxval(pres(:, mesh_mesh))
    if (any(cnodes(:, run) /= cnodes(:, mesh_mesh))) then
       write (*, '(a, i0)') 'contact_blocks: the contact positions differ in solve ', run
       dp = huge(dp)
    end if
  end subroutine compare

  !> Stops with status 2 and the library's message if a call failed.
  subroutine check(status, what)
    integer, intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= MC_OK) then
       write (*, '(a)') 'contact_blocks: ' // what // ' failed: ' // mc_errmsg(m)
       stop 2
    end if
  end subroutine check

end program contact_blocks
