! The contact patch test in Fortran: two stacked blocks with non-matching meshes,
! a uniform pressure on top, the lower block resting on y = 0, rollers on the left.
!   body 1 (upper, non-mortar): [0, 1] x [1, 2], 5 x 3 cells, P1 triangles, E = 1, nu = 0.3
!   body 2 (lower, mortar):     [0, 1] x [0, 1], 9 x 4 cells, Q1 quadrilaterals, E = 3, nu = 0.25
! The exact solution is linear in each body (sigma_yy = -p, sigma_xx = 0, plane strain), so the
! mortar method must reproduce it to round-off with a uniform contact pressure p.
! Exits with status 1 if it does not. Build and run:
!   gfortran patch_test.f90 $(pkg-config --cflags --libs mortarcontact-fortran) && ./a.out   (installed)
!   gfortran mortarcontact.f90 patch_test.f90 -lmortarcontact && ./a.out        (module source)
program patch_test
  use mortarcontact
  implicit none
  integer, parameter :: nx1 = 5, ny1 = 3, nx2 = 9, ny2 = 4
  real(mc_real), parameter :: p = 0.01d0, e1 = 1, nu1 = 0.3d0, e2 = 3, nu2 = 0.25d0
  type(mc_model) :: m
  real(mc_real), allocatable :: xy1(:, :), xy2(:, :), u1(:, :), u2(:, :), ex1(:, :), ex2(:, :)
  real(mc_real), allocatable :: pres(:), gap(:)
  integer(mc_int), allocatable :: tri(:, :), quad(:, :), cnodes(:)
  integer(mc_int) :: ncontact
  integer(mc_int64) :: iterations
  real(mc_real) :: exx1, eyy1, exx2, eyy2, err_u, err_p, scale
  integer :: i, method
  character(len=*), parameter :: names(0:1) = [character(len=11) :: 'mortar', 'dual mortar']
  logical :: ok = .true.

  call grid(0d0, 1d0, 1d0, 2d0, nx1, ny1, xy1)
  call grid(0d0, 1d0, 0d0, 1d0, nx2, ny2, xy2)
  call quads(nx1, ny1, quad)
  allocate(tri(3, 2 * size(quad, 2)))
  tri(:, 1::2) = quad([1, 2, 3], :)
  tri(:, 2::2) = quad([1, 3, 4], :)
  call quads(nx2, ny2, quad)

  exx1 = nu1 * (1 + nu1) * p / e1;  eyy1 = -(1 - nu1**2) * p / e1
  exx2 = nu2 * (1 + nu2) * p / e2;  eyy2 = -(1 - nu2**2) * p / e2
  ex1 = reshape([(exx1 * xy1(1, i), eyy2 + eyy1 * (xy1(2, i) - 1), i = 1, size(xy1, 2))], shape(xy1))
  ex2 = reshape([(exx2 * xy2(1, i), eyy2 * xy2(2, i), i = 1, size(xy2, 2))], shape(xy2))
  scale = max(maxval(abs(ex1)), maxval(abs(ex2)))
  allocate(u1, mold=xy1)
  allocate(u2, mold=xy2)

  print '(a, a)', 'mortarcontact ', mc_version_string()
  do method = MC_METHOD_MORTAR, MC_METHOD_DUAL_MORTAR
     call ok_or_stop(mc_create(m), 'mc_create')
     call ok_or_stop(mc_set_mesh(m, 1, xy1, tri), 'mesh 1')
     call ok_or_stop(mc_set_mesh(m, 2, xy2, quad), 'mesh 2')
     call ok_or_stop(mc_set_material(m, 1, e1, nu1), 'material 1')
     call ok_or_stop(mc_set_material(m, 2, e2, nu2), 'material 2')
     ! pressure on the top row of body 1: nodes (i, ny1) for i = 0..nx1
     call ok_or_stop(mc_add_pressure(m, 1, chain([(id(i, ny1, ny1), i = 0, nx1)]), [(p, i = 1, nx1)]), 'pressure')
     call ok_or_stop(mc_fix(m, 1, [(id(0, i, ny1), i = 0, ny1)], MC_X), 'rollers 1')
     call ok_or_stop(mc_fix(m, 2, [(id(0, i, ny2), i = 0, ny2)], MC_X), 'rollers 2')
     call ok_or_stop(mc_fix(m, 2, [(id(i, 0, ny2), i = 0, nx2)], MC_Y), 'base 2')
     call ok_or_stop(mc_set_contact(m, 1, chain([(id(i, 0, ny1), i = 0, nx1)])), 'contact 1')
     call ok_or_stop(mc_set_contact(m, 2, chain([(id(i, ny2, ny2), i = 0, nx2)])), 'contact 2')
     call ok_or_stop(mc_set_option_int(m, MC_OPTION_METHOD, method), 'method')
     call ok_or_stop(mc_solve(m), 'mc_solve')

     call ok_or_stop(mc_get_displacement(m, 1, u1), 'u1')
     call ok_or_stop(mc_get_displacement(m, 2, u2), 'u2')
     call ok_or_stop(mc_get_contact_count(m, ncontact), 'count')
     allocate(pres(ncontact), gap(ncontact), cnodes(ncontact))
     call ok_or_stop(mc_get_contact_nodes(m, cnodes), 'nodes')
     call ok_or_stop(mc_get_contact_pressure(m, pres), 'pressure')
     call ok_or_stop(mc_get_contact_gap(m, gap), 'gap')
     call ok_or_stop(mc_get_info_int(m, MC_INFO_ITERATIONS, iterations), 'iterations')
     err_u = max(maxval(abs(u1 - ex1)), maxval(abs(u2 - ex2))) / scale
     err_p = maxval(abs(pres - p)) / p
     print '(a, a11, a, i0, a, i0, a, es9.2, a, es9.2, a, es9.2)', 'method ', names(method), ': ', ncontact, &
          ' contact nodes, ', iterations, ' iterations, displacement error ', err_u, &
          ', pressure error ', err_p, ', max |gap| ', maxval(abs(gap))
     if (ncontact /= nx1 + 1 .or. minval(cnodes) < 1 .or. err_u > 1d-9 .or. err_p > 1d-8) ok = .false.
     deallocate(pres, gap, cnodes)
     call mc_destroy(m)
  end do
  deallocate(xy1, xy2, u1, u2, ex1, ex2, tri, quad)  ! main-program arrays are not freed at exit
  if (.not. ok) then
     print '(a)', 'patch test FAILED'
     error stop 1
  end if
  print '(a)', 'patch test passed'

contains

  !> 1-based id of grid node (i, j), i = 0..nx, j = 0..ny, numbered column by column.
  integer(mc_int) function id(i, j, ny)
    integer, intent(in) :: i, j, ny
    id = int(i * (ny + 1) + j + 1, mc_int)
  end function id

  !> Nodes of an nx-by-ny grid on [x0,x1]x[y0,y1], interior nodes moved off the lines.
  subroutine grid(x0, x1, y0, y1, nx, ny, xy)
    real(mc_real), intent(in) :: x0, x1, y0, y1
    integer, intent(in) :: nx, ny
    real(mc_real), allocatable, intent(out) :: xy(:, :)
    integer :: i, j, k
    allocate(xy(2, (nx + 1) * (ny + 1)))
    do i = 0, nx
       do j = 0, ny
          k = id(i, j, ny)
          xy(:, k) = [x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny]
          if (i > 0 .and. i < nx .and. j > 0 .and. j < ny) &
               xy(:, k) = xy(:, k) + 0.15d0 * [(x1 - x0) / nx * sin(7d0 * k), (y1 - y0) / ny * cos(5d0 * k)]
       end do
    end do
  end subroutine grid

  !> Counter-clockwise quadrilaterals of the grid.
  subroutine quads(nx, ny, q)
    integer, intent(in) :: nx, ny
    integer(mc_int), allocatable, intent(out) :: q(:, :)
    integer :: i, j
    allocate(q(4, nx * ny))
    do i = 0, nx - 1
       do j = 0, ny - 1
          q(:, i * ny + j + 1) = [id(i, j, ny), id(i + 1, j, ny), id(i + 1, j + 1, ny), id(i, j + 1, ny)]
       end do
    end do
  end subroutine quads

  !> Edges (2, n-1) joining consecutive nodes of a chain.
  function chain(nodes) result(edges)
    integer(mc_int), intent(in) :: nodes(:)
    integer(mc_int) :: edges(2, size(nodes) - 1)
    edges(1, :) = nodes(1:size(nodes) - 1)
    edges(2, :) = nodes(2:)
  end function chain

  subroutine ok_or_stop(status, what)
    integer, intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= MC_OK) then
       print '(a, a, a, a, a, a)', 'error in ', what, ': ', mc_status_string(status), ': ', mc_errmsg(m)
       error stop 1
    end if
  end subroutine ok_or_stop

end program patch_test
