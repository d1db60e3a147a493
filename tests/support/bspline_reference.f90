!> An independent B-spline reference for the spline tests: the B-splines and
!> their derivatives by the textbook recursions (de Boor, A Practical Guide
!> to Splines, IX.(15) and X.(12)), the knot span by a linear search. Slow
!> (2^k calls per B-spline) and simple, so the fast evaluations can be
!> checked against it.
module bspline_reference
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: bspline, span_of

contains

  !> m-th derivative of the B-spline B(i, p) (knots t(i..i+p+1)) at x in the
  !> non-empty knot span l (degree 0: the indicator of span l).
  recursive pure real(wp) function bspline(t, i, p, m, l, x) result(b)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: i, p, m, l
    b = 0
    if (p == 0) then
      if (i == l .and. m == 0) b = 1
      return
    end if
    if (m == 0) then
      if (t(i + p) > t(i)) b = b + (x - t(i))/(t(i + p) - t(i))*bspline(t, i, p - 1, 0, l, x)
      if (t(i + p + 1) > t(i + 1)) b = b + (t(i + p + 1) - x)/(t(i + p + 1) - t(i + 1))*bspline(t, i + 1, p - 1, 0, l, x)
    else
      if (t(i + p) > t(i)) b = b + p*bspline(t, i, p - 1, m - 1, l, x)/(t(i + p) - t(i))
      if (t(i + p + 1) > t(i + 1)) b = b - p*bspline(t, i + 1, p - 1, m - 1, l, x)/(t(i + p + 1) - t(i + 1))
    end if
  end function bspline

  !> The last non-empty knot span l (k+1 <= l <= n-k-1) with t(l) <= x, by a linear search.
  pure integer function span_of(t, k, x) result(l)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: k
    integer :: j
    l = k + 1
    do j = k + 1, size(t) - k - 1
      if (t(j) <= x .and. t(j + 1) > t(j)) l = j
    end do
  end function span_of
end module bspline_reference
