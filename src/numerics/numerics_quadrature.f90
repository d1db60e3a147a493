!> Fixed quadrature rules shared by the layers below.
!>
!> gl8_x, gl8_w: the 8-point Gauss-Legendre rule on [-1, 1] (exact for
!> polynomials of degree <= 15): int_a^b f ~ (b - a)/2 sum_i gl8_w(i)
!> f((a + b)/2 + (b - a)/2 gl8_x(i)). The values are the usual tabulated
!> ones to 16 digits.
!>
!> piecewise_nodes: the nodes of an integral table over consecutive pieces,
!> each in equal steps (geometry_drop_profile, geometry_slide_bowl);
!> node_below: where a value lies in such a table.
module numerics_quadrature
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: piecewise_nodes, node_below

  real(wp), parameter, public :: gl8_x(8) = [-0.9602898564975363_wp, -0.7966664774136267_wp, &
    -0.5255324099163290_wp, -0.1834346424956498_wp, 0.1834346424956498_wp, &
    0.5255324099163290_wp, 0.7966664774136267_wp, 0.9602898564975363_wp]
  real(wp), parameter, public :: gl8_w(8) = [0.1012285362903763_wp, 0.2223810344533745_wp, &
    0.3137066458778873_wp, 0.3626837833783620_wp, 0.3626837833783620_wp, &
    0.3137066458778873_wp, 0.2223810344533745_wp, 0.1012285362903763_wp]

contains

  !> The nodes(0:n) of a table over the pieces [ends(p - 1), ends(p)], each
  !> in equal steps of at most `spacing` (at least one step a piece, its last
  !> node its end exactly), from nodes(0) = the first end; piece(k): the
  !> piece of the step from nodes(k - 1) to nodes(k).
  pure subroutine piecewise_nodes(ends, spacing, nodes, piece)
    real(wp), intent(in) :: ends(0:), spacing
    real(wp), allocatable, intent(out) :: nodes(:)
    integer, allocatable, intent(out) :: piece(:)
    integer :: p, m, j, k, n
    n = 0
    do p = 1, ubound(ends, 1)
      n = n + steps(p)
    end do
    allocate (nodes(0:n), piece(n))
    nodes(0) = ends(0)
    k = 0
    do p = 1, ubound(ends, 1)
      m = steps(p)
      do j = 1, m
        k = k + 1
        piece(k) = p
        nodes(k) = ends(p - 1) + (ends(p) - ends(p - 1))*j/real(m, wp)
        if (j == m) nodes(k) = ends(p)
      end do
    end do

  contains

    pure integer function steps(p)
      integer, intent(in) :: p
      steps = max(1, ceiling((ends(p) - ends(p - 1))/spacing))
    end function steps
  end subroutine piecewise_nodes

  !> The index lo of the last node <= x of the increasing nodes(0:n), by
  !> bisection (0 below nodes(1), n - 1 at or beyond nodes(n - 1)).
  pure integer function node_below(nodes, x) result(lo)
    real(wp), intent(in) :: nodes(0:), x
    integer :: hi, mid
    lo = 0
    hi = ubound(nodes, 1)
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (nodes(mid) <= x) then
        lo = mid
      else
        hi = mid
      end if
    end do
  end function node_below
end module numerics_quadrature
