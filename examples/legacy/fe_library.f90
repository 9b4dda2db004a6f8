!-------------------------------------------------------------------------------------------------
! fe_library.f90 - the element library of the legacy program contact_blocks.f90, written in the
! manner of I. M. Smith, D. V. Griffiths and L. Margetts, "Programming the Finite Element Method"
! (5th ed., Wiley 2014): 8-node quadrilaterals in plane strain, 3 x 3 Gauss points, element
! steering vectors from an nf array. Nothing here knows about contact: this is what a legacy
! program already has before it calls mortarcontact.
!
! Local node order of the 8-node quadrilateral (Smith and Griffiths): from the corner
! (xi, eta) = (-1, -1), clockwise, corners and mid-sides interleaved:
!
!        3 ---- 4 ---- 5         eta
!        |             |          ^
!        2             6          |
!        |             |          +--> xi
!        1 ---- 8 ---- 7
!
! Freedoms of a node: x then y; equation numbers in nf(2, nn): 0 = restrained, 1..neq otherwise.
!-------------------------------------------------------------------------------------------------
module fe_library
  implicit none
  private
  integer, parameter, public :: iwp = selected_real_kind(15)
  public :: mesh_q8, formnf, num_to_g, sample_3x3, shape_der_q8, deemat, beemat, determinant, invert2

  ! local coordinates of the 8 nodes, in Smith and Griffiths' order
  integer, parameter :: xi_node(8) = [-1, -1, -1, 0, 1, 1, 1, 0]
  integer, parameter :: eta_node(8) = [-1, 0, 1, 1, 1, 0, -1, -1]

contains

  !> A block of nxe x nye 8-node quadrilaterals: x0 <= x <= x0 + width, bottom(x) <= y <= top,
  !> where bottom(x) = top - height on a flat block and, when radius > 0, the circular arc
  !> top - height + radius - sqrt(radius**2 - (x - xc)**2) (xc the middle of the block) of a
  !> crowned one. Nodes are numbered column by column from the left, each column from the bottom;
  !> elements likewise. g_coord(2, nn), g_num(8, nels) in the local order above.
  subroutine mesh_q8(nxe, nye, x0, width, top, height, radius, g_coord, g_num)
    integer, intent(in) :: nxe, nye
    real(iwp), intent(in) :: x0, width, top, height, radius
    real(iwp), allocatable, intent(out) :: g_coord(:, :)
    integer, allocatable, intent(out) :: g_num(:, :)
    integer, allocatable :: node_at(:, :)
    integer :: i, j, ip, iq, nn, iel
    real(iwp) :: x, xc, bottom
    allocate(node_at(0:2 * nxe, 0:2 * nye))
    node_at = 0
    nn = 0
    do i = 0, 2 * nxe
       do j = 0, 2 * nye
          if (mod(i, 2) == 1 .and. mod(j, 2) == 1) cycle      ! no node at an element's centre
          nn = nn + 1
          node_at(i, j) = nn
       end do
    end do
    allocate(g_coord(2, nn), g_num(8, nxe * nye))
    xc = x0 + 0.5_iwp * width
    do i = 0, 2 * nxe
       x = x0 + width * real(i, iwp) / real(2 * nxe, iwp)
       bottom = top - height
       if (radius > 0._iwp) bottom = bottom + radius - sqrt(radius**2 - (x - xc)**2)
       do j = 0, 2 * nye
          if (node_at(i, j) == 0) cycle
          g_coord(:, node_at(i, j)) = [x, bottom + (top - bottom) * real(j, iwp) / real(2 * nye, iwp)]
       end do
    end do
    iel = 0
    do ip = 1, nxe
       do iq = 1, nye
          iel = iel + 1
          i = 2 * ip - 2
          j = 2 * iq - 2
          g_num(:, iel) = [node_at(i, j), node_at(i, j + 1), node_at(i, j + 2), node_at(i + 1, j + 2), &
               node_at(i + 2, j + 2), node_at(i + 2, j + 1), node_at(i + 2, j), node_at(i + 1, j)]
       end do
    end do
  end subroutine mesh_q8

  !> Numbers the freedoms: on entry nf holds 1 (free) or 0 (restrained); on exit the free ones
  !> are 1..neq, node by node.
  subroutine formnf(nf, neq)
    integer, intent(inout) :: nf(:, :)
    integer, intent(out) :: neq
    integer :: i, j
    neq = 0
    do j = 1, size(nf, 2)
       do i = 1, size(nf, 1)
          if (nf(i, j) /= 0) then
             neq = neq + 1
             nf(i, j) = neq
          end if
       end do
    end do
  end subroutine formnf

  !> The steering vector g of an element from its nodes num and nf.
  subroutine num_to_g(num, nf, g)
    integer, intent(in) :: num(:), nf(:, :)
    integer, intent(out) :: g(:)
    integer :: i, nodof
    nodof = size(nf, 1)
    do i = 1, size(num)
       g((i - 1) * nodof + 1:i * nodof) = nf(:, num(i))
    end do
  end subroutine num_to_g

  !> The 3 x 3 Gauss points and weights of the square [-1, 1]^2.
  subroutine sample_3x3(points, weights)
    real(iwp), intent(out) :: points(9, 2), weights(9)
    real(iwp), parameter :: r = 0.77459666924148337704_iwp
    real(iwp) :: x(3), w(3)
    integer :: i, j, k
    x = [-r, 0._iwp, r]
    w = [5._iwp / 9._iwp, 8._iwp / 9._iwp, 5._iwp / 9._iwp]
    k = 0
    do j = 1, 3
       do i = 1, 3
          k = k + 1
          points(k, :) = [x(i), x(j)]
          weights(k) = w(i) * w(j)
       end do
    end do
  end subroutine sample_3x3

  !> Derivatives der(2, 8) of the 8-node shape functions in (xi, eta) at point i of points.
  subroutine shape_der_q8(der, points, i)
    real(iwp), intent(out) :: der(2, 8)
    real(iwp), intent(in) :: points(:, :)
    integer, intent(in) :: i
    real(iwp) :: xi, eta, a, b
    integer :: k
    xi = points(i, 1)
    eta = points(i, 2)
    do k = 1, 8
       a = real(xi_node(k), iwp)
       b = real(eta_node(k), iwp)
       if (xi_node(k) /= 0 .and. eta_node(k) /= 0) then  ! corner
          der(1, k) = 0.25_iwp * a * (1._iwp + b * eta) * (2._iwp * a * xi + b * eta)
          der(2, k) = 0.25_iwp * b * (1._iwp + a * xi) * (a * xi + 2._iwp * b * eta)
       else if (xi_node(k) == 0) then                    ! mid-side of a horizontal side
          der(1, k) = -xi * (1._iwp + b * eta)
          der(2, k) = 0.5_iwp * b * (1._iwp - xi * xi)
       else                                              ! mid-side of a vertical side
          der(1, k) = 0.5_iwp * a * (1._iwp - eta * eta)
          der(2, k) = -eta * (1._iwp + a * xi)
       end if
    end do
  end subroutine shape_der_q8

  !> The plane-strain stress-strain matrix dee(3, 3) of Young's modulus e and Poisson's ratio v.
  subroutine deemat(dee, e, v)
    real(iwp), intent(out) :: dee(3, 3)
    real(iwp), intent(in) :: e, v
    real(iwp) :: c
    c = e / ((1._iwp + v) * (1._iwp - 2._iwp * v))
    dee = 0._iwp
    dee(1, 1) = c * (1._iwp - v)
    dee(2, 2) = c * (1._iwp - v)
    dee(1, 2) = c * v
    dee(2, 1) = c * v
    dee(3, 3) = 0.5_iwp * c * (1._iwp - 2._iwp * v)
  end subroutine deemat

  !> The strain-displacement matrix bee(3, 2 * nod) from the shape derivatives deriv(2, nod) in x, y.
  subroutine beemat(bee, deriv)
    real(iwp), intent(out) :: bee(:, :)
    real(iwp), intent(in) :: deriv(:, :)
    integer :: k
    bee = 0._iwp
    do k = 1, size(deriv, 2)
       bee(1, 2 * k - 1) = deriv(1, k)
       bee(2, 2 * k) = deriv(2, k)
       bee(3, 2 * k - 1) = deriv(2, k)
       bee(3, 2 * k) = deriv(1, k)
    end do
  end subroutine beemat

  !> The determinant of a 2 x 2 matrix.
  real(iwp) function determinant(jac)
    real(iwp), intent(in) :: jac(2, 2)
    determinant = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
  end function determinant

  !> Inverts a 2 x 2 matrix in place.
  subroutine invert2(jac)
    real(iwp), intent(inout) :: jac(2, 2)
    real(iwp) :: det, t
    det = determinant(jac)
    t = jac(1, 1)
    jac(1, 1) = jac(2, 2) / det
    jac(2, 2) = t / det
    jac(1, 2) = -jac(1, 2) / det
    jac(2, 1) = -jac(2, 1) / det
  end subroutine invert2

end module fe_library
