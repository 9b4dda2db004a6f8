!-------------------------------------------------------------------------------------------------
! fe_library.f90 - a stand-in for the library of I. M. Smith, D. V. Griffiths and L. Margetts,
! "Programming the Finite Element Method" (5th ed., Wiley 2014), for the legacy program
! contact_blocks.f90. Nothing here knows about contact: it is what a program written against
! their library already calls before it calls mortarcontact.
!
! The routines are written for this example, but their modules (geom, main), names, argument
! lists and conventions are the published library's, so that a program written against this
! file builds unchanged against the real library and vice versa. Only the cases the example
! needs are implemented (quadrilaterals of 4 or 8 nodes, plane strain); any other case stops
! with a message instead of returning garbage.
!
! The conventions a contact program depends on:
!   geom_rect  numbers a rectangular mesh from the TOP: x_coords(1:nxe+1) left to right and
!              y_coords(1:nye+1) from the top down (y_coords(1) the largest, as in the book's
!              data: 0, -0.5, -1, ...). Element (ip, iq), ip the column from the left and iq
!              the row from the top, is iel = (ip - 1) * nye + iq for dir = 'y' (numbering down
!              each column) and iel = (iq - 1) * nxe + ip for dir = 'x' (along each row). So row
!              iq = 1 is the top row and iq = nye the bottom row. Nodes are numbered the same
!              way: down each column ('y') or along each row ('x'), from the top left.
!   local node order of the 8-node quadrilateral: from the corner (xi, eta) = (-1, -1), i.e. the
!              bottom left, clockwise, corners and mid-sides interleaved, so that every side is
!              three consecutive nodes corner-middle-corner (the bottom side is 7-8-1):
!
!                   3 ---- 4 ---- 5         eta
!                   |             |          ^
!                   2             6          |
!                   |             |          +--> xi
!                   1 ---- 8 ---- 7
!
!              The 4-node quadrilateral: 1 bottom left, 2 top left, 3 top right, 4 bottom right.
!   nf(nodof, nn) 1 (free) or 0 (restrained) on entry to formnf, equation numbers on exit.
!   skyline storage: kdiag(i) is the position in kv of the diagonal of equation i; row i of the
!              lower triangle, from its first nonzero column to the diagonal, is
!              kv(kdiag(i - 1) + 1 : kdiag(i)) (kdiag(0) = 0). fkdiag gives the row lengths,
!              and the program sums them into positions before fsparv assembles.
!-------------------------------------------------------------------------------------------------
module geom
  implicit none
  private
  integer, parameter :: iwp = selected_real_kind(15)
  public :: formnf, mesh_size, geom_rect

contains

  !> Numbers the freedoms: on entry nf(nodof, nn) holds 1 (free) or 0 (restrained); on exit the
  !> free ones are 1..neq, node by node (neq = maxval(nf)).
  subroutine formnf(nf)
    integer, intent(inout) :: nf(:, :)
    integer :: node, freedom, neq
    neq = 0
    do node = 1, size(nf, 2)
       do freedom = 1, size(nf, 1)
          if (nf(freedom, node) == 0) cycle
          neq = neq + 1
          nf(freedom, node) = neq
       end do
    end do
  end subroutine formnf

  !> The number of elements nels and of nodes nn of an nxe x nye mesh of geom_rect.
  subroutine mesh_size(element, nod, nels, nn, nxe, nye, nze)
    character(len=*), intent(in) :: element
    integer, intent(in) :: nod, nxe, nye
    integer, intent(in), optional :: nze
    integer, intent(out) :: nels, nn
    if (present(nze)) call refuse('mesh_size', 'three-dimensional meshes')
    if (element /= 'quadrilateral') call refuse('mesh_size', element)
    nels = nxe * nye
    select case (nod)
    case (4)
       nn = (nxe + 1) * (nye + 1)
    case (8)                          ! corner lines have 2 nye + 1 nodes, middle lines nye + 1
       nn = (nxe + 1) * (2 * nye + 1) + nxe * (nye + 1)
    case default
       call refuse('mesh_size', 'this number of nodes')
    end select
  end subroutine mesh_size

  !> The coordinates coord(nod, 2) and node numbers num(nod) of element iel of a rectangular
  !> mesh of quadrilaterals on the lines x_coords (left to right) and y_coords (top down),
  !> counting in the x or y direction (dir = 'x' or 'r', 'y' or 'z'). See the header.
  subroutine geom_rect(element, iel, x_coords, y_coords, coord, num, dir)
    character(len=*), intent(in) :: element
    integer, intent(in) :: iel
    real(iwp), intent(in) :: x_coords(:), y_coords(:)
    real(iwp), intent(out) :: coord(:, :)
    integer, intent(out) :: num(:)
    character(len=1), intent(in) :: dir
    integer :: nxe, nye, ip, iq, first, line
    logical :: along_x
    if (element /= 'quadrilateral') call refuse('geom_rect', element)
    nxe = size(x_coords) - 1
    nye = size(y_coords) - 1
    along_x = dir == 'x' .or. dir == 'r'
    if (along_x) then
       iq = (iel - 1) / nxe + 1
       ip = iel - (iq - 1) * nxe
    else
       ip = (iel - 1) / nye + 1
       iq = iel - (ip - 1) * nye
    end if
    select case (size(num))
    case (4)
       if (along_x) then                ! rows of nxe + 1 nodes from the top
          num = [iq * (nxe + 1) + ip, (iq - 1) * (nxe + 1) + ip, (iq - 1) * (nxe + 1) + ip + 1, &
               iq * (nxe + 1) + ip + 1]
       else                             ! columns of nye + 1 nodes from the left
          num = [(ip - 1) * (nye + 1) + iq + 1, (ip - 1) * (nye + 1) + iq, ip * (nye + 1) + iq, &
               ip * (nye + 1) + iq + 1]
       end if
       coord(:, 1) = [x_coords(ip), x_coords(ip), x_coords(ip + 1), x_coords(ip + 1)]
       coord(:, 2) = [y_coords(iq + 1), y_coords(iq), y_coords(iq), y_coords(iq + 1)]
    case (8)
       ! Each band of the mesh is a line through corners and mid-sides (2 n + 1 nodes) followed
       ! by a line through mid-sides only (n + 1 nodes): 3 n + 2 nodes per band.
       if (along_x) then                ! bands are rows: iq-th from the top
          first = (iq - 1) * (3 * nxe + 2)
          line = 2 * nxe + 1
          num(3:5) = first + 2 * ip - 1 + [0, 1, 2]                   ! top line, left to right
          num(2) = first + line + ip                                   ! middle line
          num(6) = num(2) + 1
          num([1, 8, 7]) = first + 3 * nxe + 2 + 2 * ip - 1 + [0, 1, 2] ! bottom line
       else                             ! bands are columns: ip-th from the left
          first = (ip - 1) * (3 * nye + 2)
          line = 2 * nye + 1
          num([3, 2, 1]) = first + 2 * iq - 1 + [0, 1, 2]              ! left line, top down
          num(4) = first + line + iq                                   ! middle line
          num(8) = num(4) + 1
          num(5:7) = first + 3 * nye + 2 + 2 * iq - 1 + [0, 1, 2]      ! right line, top down
       end if
       coord(:, 1) = [x_coords(ip), x_coords(ip), x_coords(ip), 0._iwp, x_coords(ip + 1), &
            x_coords(ip + 1), x_coords(ip + 1), 0._iwp]
       coord(:, 2) = [y_coords(iq + 1), 0._iwp, y_coords(iq), y_coords(iq), y_coords(iq), 0._iwp, &
            y_coords(iq + 1), y_coords(iq + 1)]
       coord([4, 8], 1) = 0.5_iwp * (x_coords(ip) + x_coords(ip + 1))
       coord([2, 6], 2) = 0.5_iwp * (y_coords(iq) + y_coords(iq + 1))
    case default
       call refuse('geom_rect', 'this number of nodes')
    end select
  end subroutine geom_rect

  subroutine refuse(routine, what)
    character(len=*), intent(in) :: routine, what
    write (*, '(a)') 'fe_library: ' // routine // ': ' // trim(what) // ' not implemented in this stand-in'
    stop 3
  end subroutine refuse

end module geom

module main
  implicit none
  private
  integer, parameter :: iwp = selected_real_kind(15)
  public :: num_to_g, sample, shape_fun, shape_der, deemat, beemat, determinant, invert
  public :: fkdiag, fsparv, sparin, spabac

  ! local coordinates of the quadrilaterals' nodes, in the order of the header
  integer, parameter :: xi8(8) = [-1, -1, -1, 0, 1, 1, 1, 0], eta8(8) = [-1, 0, 1, 1, 1, 0, -1, -1]
  integer, parameter :: xi4(4) = [-1, -1, 1, 1], eta4(4) = [-1, 1, 1, -1]

contains

  !> The steering vector g of an element: the equation numbers nf(:, num(i)) of its nodes in turn.
  subroutine num_to_g(num, nf, g)
    integer, intent(in) :: num(:), nf(:, :)
    integer, intent(out) :: g(:)
    integer :: i, nodof
    nodof = size(nf, 1)
    do i = 1, size(num)
       g((i - 1) * nodof + 1:i * nodof) = nf(:, num(i))
    end do
  end subroutine num_to_g

  !> Gauss points s(nip, 2) and weights wt(nip) of the square [-1, 1]^2 (element =
  !> 'quadrilateral', nip = 1, 4 or 9), rows of points from eta = +1 down, xi from -1 up.
  subroutine sample(element, s, wt)
    character(len=*), intent(in) :: element
    real(iwp), intent(out) :: s(:, :)
    real(iwp), intent(out), optional :: wt(:)
    real(iwp) :: x(3), w(3)
    integer :: n, i, j, k
    if (element /= 'quadrilateral') call refuse('sample', element)
    select case (size(s, 1))
    case (1)
       n = 1
       x(1) = 0._iwp
       w(1) = 2._iwp
    case (4)
       n = 2
       x(1:2) = [-1._iwp, 1._iwp] / sqrt(3._iwp)
       w(1:2) = 1._iwp
    case (9)
       n = 3
       x = [-sqrt(0.6_iwp), 0._iwp, sqrt(0.6_iwp)]
       w = [5._iwp, 8._iwp, 5._iwp] / 9._iwp
    case default
       call refuse('sample', 'this number of points')
    end select
    k = 0
    do j = n, 1, -1
       do i = 1, n
          k = k + 1
          s(k, 1:2) = [x(i), x(j)]
          if (present(wt)) wt(k) = w(i) * w(j)
       end do
    end do
  end subroutine sample

  !> The shape functions fun(nod) of a 4- or 8-node quadrilateral at point i of points.
  subroutine shape_fun(fun, points, i)
    real(iwp), intent(out) :: fun(:)
    real(iwp), intent(in) :: points(:, :)
    integer, intent(in) :: i
    real(iwp) :: xi, eta, a, b
    integer :: k
    xi = points(i, 1)
    eta = points(i, 2)
    select case (size(fun))
    case (4)
       do k = 1, 4
          fun(k) = 0.25_iwp * (1._iwp + xi4(k) * xi) * (1._iwp + eta4(k) * eta)
       end do
    case (8)
       do k = 1, 8
          a = real(xi8(k), iwp)
          b = real(eta8(k), iwp)
          if (xi8(k) /= 0 .and. eta8(k) /= 0) then            ! corner
             fun(k) = 0.25_iwp * (1._iwp + a * xi) * (1._iwp + b * eta) * (a * xi + b * eta - 1._iwp)
          else if (xi8(k) == 0) then                          ! middle of a horizontal side
             fun(k) = 0.5_iwp * (1._iwp - xi * xi) * (1._iwp + b * eta)
          else                                                ! middle of a vertical side
             fun(k) = 0.5_iwp * (1._iwp + a * xi) * (1._iwp - eta * eta)
          end if
       end do
    case default
       call refuse('shape_fun', 'this number of nodes')
    end select
  end subroutine shape_fun

  !> The derivatives der(2, nod) of the shape functions in (xi, eta) at point i of points.
  subroutine shape_der(der, points, i)
    real(iwp), intent(out) :: der(:, :)
    real(iwp), intent(in) :: points(:, :)
    integer, intent(in) :: i
    real(iwp) :: xi, eta, a, b
    integer :: k
    if (size(der, 1) /= 2) call refuse('shape_der', 'other than two dimensions')
    xi = points(i, 1)
    eta = points(i, 2)
    select case (size(der, 2))
    case (4)
       do k = 1, 4
          der(1, k) = 0.25_iwp * xi4(k) * (1._iwp + eta4(k) * eta)
          der(2, k) = 0.25_iwp * eta4(k) * (1._iwp + xi4(k) * xi)
       end do
    case (8)
       do k = 1, 8
          a = real(xi8(k), iwp)
          b = real(eta8(k), iwp)
          if (xi8(k) /= 0 .and. eta8(k) /= 0) then
             der(1, k) = 0.25_iwp * a * (1._iwp + b * eta) * (2._iwp * a * xi + b * eta)
             der(2, k) = 0.25_iwp * b * (1._iwp + a * xi) * (a * xi + 2._iwp * b * eta)
          else if (xi8(k) == 0) then
             der(1, k) = -xi * (1._iwp + b * eta)
             der(2, k) = 0.5_iwp * b * (1._iwp - xi * xi)
          else
             der(1, k) = 0.5_iwp * a * (1._iwp - eta * eta)
             der(2, k) = -eta * (1._iwp + a * xi)
          end if
       end do
    case default
       call refuse('shape_der', 'this number of nodes')
    end select
  end subroutine shape_der

  !> The elastic stress-strain matrix dee of Young's modulus e and Poisson's ratio v: plane
  !> strain for dee(3, 3), plane strain with the hoop (or out-of-plane) stress for dee(4, 4).
  subroutine deemat(dee, e, v)
    real(iwp), intent(out) :: dee(:, :)
    real(iwp), intent(in) :: e, v
    real(iwp) :: c
    integer :: n
    n = size(dee, 1)
    if (n /= 3 .and. n /= 4) call refuse('deemat', 'this size')
    c = e / ((1._iwp + v) * (1._iwp - 2._iwp * v))
    dee = 0._iwp
    dee(1:2, 1:2) = c * v
    dee(1, 1) = c * (1._iwp - v)
    dee(2, 2) = c * (1._iwp - v)
    dee(3, 3) = 0.5_iwp * c * (1._iwp - 2._iwp * v)
    if (n == 4) then
       dee([1, 2], 4) = c * v
       dee(4, [1, 2]) = c * v
       dee(4, 4) = c * (1._iwp - v)
    end if
  end subroutine deemat

  !> The strain-displacement matrix bee(nst, 2 nod) (nst = 3 or 4; the caller fills row 4 of an
  !> axisymmetric element) from the shape derivatives deriv(2, nod) in x and y.
  subroutine beemat(bee, deriv)
    real(iwp), intent(out) :: bee(:, :)
    real(iwp), intent(in) :: deriv(:, :)
    integer :: k
    if (size(deriv, 1) /= 2) call refuse('beemat', 'other than two dimensions')
    bee = 0._iwp
    do k = 1, size(deriv, 2)
       bee(1, 2 * k - 1) = deriv(1, k)
       bee(2, 2 * k) = deriv(2, k)
       bee(3, 2 * k - 1) = deriv(2, k)
       bee(3, 2 * k) = deriv(1, k)
    end do
  end subroutine beemat

  !> The determinant of a 1 x 1, 2 x 2 or 3 x 3 Jacobian.
  function determinant(jac) result(det)
    real(iwp), intent(in) :: jac(:, :)
    real(iwp) :: det
    select case (size(jac, 1))
    case (1)
       det = jac(1, 1)
    case (2)
       det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
    case (3)
       det = jac(1, 1) * (jac(2, 2) * jac(3, 3) - jac(2, 3) * jac(3, 2)) &
            - jac(1, 2) * (jac(2, 1) * jac(3, 3) - jac(2, 3) * jac(3, 1)) &
            + jac(1, 3) * (jac(2, 1) * jac(3, 2) - jac(2, 2) * jac(3, 1))
    case default
       det = 0._iwp
       call refuse('determinant', 'this size')
    end select
  end function determinant

  !> Inverts a small square matrix in place (Gauss-Jordan without pivoting, as for a Jacobian).
  subroutine invert(matrix)
    real(iwp), intent(inout) :: matrix(:, :)
    real(iwp) :: pivot, factor
    integer :: k, i
    do k = 1, size(matrix, 1)
       pivot = matrix(k, k)
       matrix(k, k) = 1._iwp
       matrix(k, :) = matrix(k, :) / pivot
       do i = 1, size(matrix, 1)
          if (i == k) cycle
          factor = matrix(i, k)
          matrix(i, k) = 0._iwp
          matrix(i, :) = matrix(i, :) - factor * matrix(k, :)
       end do
    end do
  end subroutine invert

  !> Skyline profile: raises kdiag(k), for each equation k of the steering vector g, to the
  !> length of row k from the element's lowest equation to the diagonal. kdiag starts at 0;
  !> after all elements the program sums it into positions (kdiag(i) += kdiag(i - 1)).
  subroutine fkdiag(kdiag, g)
    integer, intent(inout) :: kdiag(:)
    integer, intent(in) :: g(:)
    integer :: i, lowest
    if (all(g == 0)) return
    lowest = minval(g, mask=g /= 0)
    do i = 1, size(g)
       if (g(i) /= 0) kdiag(g(i)) = max(kdiag(g(i)), g(i) - lowest + 1)
    end do
  end subroutine fkdiag

  !> Adds the element matrix km with steering vector g to the lower triangle of the skyline
  !> matrix kv: entry (row, col), col <= row, lives at kv(kdiag(row) - (row - col)).
  subroutine fsparv(kv, km, g, kdiag)
    real(iwp), intent(inout) :: kv(:)
    real(iwp), intent(in) :: km(:, :)
    integer, intent(in) :: g(:), kdiag(:)
    integer :: i, j
    do i = 1, size(g)
       if (g(i) == 0) cycle
       do j = 1, size(g)
          if (g(j) == 0 .or. g(j) > g(i)) cycle
          kv(kdiag(g(i)) - g(i) + g(j)) = kv(kdiag(g(i)) - g(i) + g(j)) + km(i, j)
       end do
    end do
  end subroutine fsparv

  !> Cholesky factorization K = L L^T of the skyline matrix kv in place (L in kv's profile).
  subroutine sparin(kv, kdiag)
    real(iwp), intent(inout) :: kv(:)
    integer, intent(in) :: kdiag(:)
    integer :: i, j, first_i, first_j, k0, off_i, off_j
    real(iwp) :: x
    do i = 1, size(kdiag)
       off_i = kdiag(i) - i                     ! kv(off_i + j) is L(i, j)
       first_i = i - (kdiag(i) - row_start(kdiag, i)) + 1
       do j = first_i, i
          off_j = kdiag(j) - j
          first_j = j - (kdiag(j) - row_start(kdiag, j)) + 1
          k0 = max(first_i, first_j)
          x = kv(off_i + j) - dot_product(kv(off_i + k0:off_i + j - 1), kv(off_j + k0:off_j + j - 1))
          if (j < i) then
             kv(off_i + j) = x / kv(kdiag(j))
          else
             kv(kdiag(i)) = sqrt(x)
          end if
       end do
    end do
  end subroutine sparin

  !> Solves L L^T x = loads(1:) with the factor of sparin; loads(0:neq) as the programs hold it.
  subroutine spabac(kv, loads, kdiag)
    real(iwp), intent(in) :: kv(:)
    real(iwp), intent(inout) :: loads(0:)
    integer, intent(in) :: kdiag(:)
    integer :: i, first, off
    do i = 1, size(kdiag)                       ! forward: L y = loads
       off = kdiag(i) - i
       first = i - (kdiag(i) - row_start(kdiag, i)) + 1
       loads(i) = (loads(i) - dot_product(kv(off + first:off + i - 1), loads(first:i - 1))) / kv(kdiag(i))
    end do
    do i = size(kdiag), 1, -1                   ! backward: L^T x = y, column i of L^T is row i of L
       off = kdiag(i) - i
       first = i - (kdiag(i) - row_start(kdiag, i)) + 1
       loads(i) = loads(i) / kv(kdiag(i))
       loads(first:i - 1) = loads(first:i - 1) - loads(i) * kv(off + first:off + i - 1)
    end do
  end subroutine spabac

  !> kdiag(i - 1), with kdiag(0) = 0: the position in kv before row i.
  pure integer function row_start(kdiag, i)
    integer, intent(in) :: kdiag(:), i
    row_start = 0
    if (i > 1) row_start = kdiag(i - 1)
  end function row_start

  subroutine refuse(routine, what)
    character(len=*), intent(in) :: routine, what
    write (*, '(a)') 'fe_library: ' // routine // ': ' // trim(what) // ' not implemented in this stand-in'
    stop 3
  end subroutine refuse

end module main
