!> Kernels of the B-spline curves and surfaces (numerics_spline_curve,
!> numerics_spline_surface), which both evaluate from tables of Taylor
!> coefficients per knot span: the knot span of a parameter, the Taylor shift
!> of a span's polynomial (Horner), and the B-splines' derivatives at a point.
module numerics_spline_kernels
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: max_degree, factorial, find_interval, taylor_shift, basis_derivatives

  integer, parameter :: max_degree = 5
  real(wp), parameter :: factorial(0:max_degree) = [1, 1, 2, 6, 24, 120]

contains

  !> Knot interval l, t(l) <= u < t(l+1), k+1 <= l <= n-k-1 (for u in the
  !> domain); at the end of the domain (u >= t(n-k-1)) the last non-empty
  !> span. First guess: the span of u if the knots were evenly spaced, and
  !> its neighbours (fitted knots mostly are nearly even); then bisection.
  pure integer function find_interval(t, k, u) result(l)
    real(wp), intent(in) :: t(:), u
    integer, intent(in) :: k
    integer :: lo, hi, mid
    lo = k + 1
    hi = size(t) - k - 1
    if (u >= t(hi)) then
      l = hi
      ! a multiple knot at the end of the domain: back to the span that ends there
      do while (t(l + 1) <= t(l) .and. l > lo)
        l = l - 1
      end do
      return
    end if
    if (u > t(lo)) then
      mid = lo + int((u - t(lo))/(t(hi + 1) - t(lo))*(hi + 1 - lo))
      mid = min(max(mid, lo), hi - 1)
      if (u >= t(mid)) then
        if (u < t(mid + 1)) then
          l = mid
          return
        end if
        lo = mid + 1
        if (u < t(lo + 1)) then
          l = lo
          return
        end if
      else
        hi = mid
        if (u >= t(mid - 1)) then
          l = mid - 1
          return
        end if
      end if
    end if
    ! invariant t(lo) <= u < t(hi)
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (u >= t(mid)) then
        lo = mid
      else
        hi = mid
      end if
    end do
    l = lo
  end function find_interval

  !> The Taylor coefficients b(0:k) of a degree-k polynomial about 0 shifted
  !> to h (repeated synthetic division): b(m) = p^(m)(h)/m!, m = 0..mt; the
  !> entries above mt are left partly shifted. Degree 5 in scalars.
  pure subroutine taylor_shift(b, k, h, mt)
    real(wp), intent(inout) :: b(0:max_degree)
    integer, intent(in) :: k, mt
    real(wp), intent(in) :: h
    integer :: m, i
    if (k == 5) then
      call quintic_shift(b, h, mt)
      return
    end if
    do m = 0, mt
      do i = k - 1, m, -1
        b(i) = b(i) + h*b(i + 1)
      end do
    end do
  end subroutine taylor_shift

  !> The Taylor shift for degree 5 (the same
  !> operations in the same order, in scalars): b(m) = p^(m)(h)/m!, m = 0..mt.
  pure subroutine quintic_shift(b, h, mt)
    real(wp), intent(inout) :: b(0:max_degree)
    real(wp), intent(in) :: h
    integer, intent(in) :: mt
    real(wp) :: b0, b1, b2, b3, b4, b5
    b0 = b(0)
    b1 = b(1)
    b2 = b(2)
    b3 = b(3)
    b4 = b(4)
    b5 = b(5)
    b4 = b4 + h*b5
    b3 = b3 + h*b4
    b2 = b2 + h*b3
    b1 = b1 + h*b2
    b(0) = b0 + h*b1
    if (mt < 1) return
    b4 = b4 + h*b5
    b3 = b3 + h*b4
    b2 = b2 + h*b3
    b(1) = b1 + h*b2
    if (mt < 2) return
    b4 = b4 + h*b5
    b3 = b3 + h*b4
    b(2) = b2 + h*b3
    if (mt < 3) return
    b4 = b4 + h*b5
    b(3) = b3 + h*b4
    if (mt < 4) return
    b(4) = b4 + h*b5
  end subroutine quintic_shift

  !> d(r, i): r-th derivative (r = 0..k) of the k+1 B-splines of degree k that
  !> do not vanish on [t(l), t(l+1)), at x. The Cox-de Boor recurrence gives
  !> the values of degrees 0..k; the m-th derivative of degree k then follows
  !> from the values of degree k-m by m steps of
  !>   B'_{i,p} = p (B_{i,p-1}/(t_{i+p} - t_i) - B_{i+1,p-1}/(t_{i+p+1} - t_{i+1}))
  !> applied to the (m-1)-th derivatives of degree p-1 (de Boor, A Practical
  !> Guide to Splines, X.(12)). Every denominator is one of the k(k+1)/2 knot
  !> spans of the recurrence, each inverted once.
  pure subroutine basis_derivatives(t, k, x, l, d)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: k, l
    real(wp), intent(out) :: d(0:max_degree, max_degree + 1)
    ! nd(r, p): the B-spline of degree p starting at knot l-p+r, r = 0..p;
    ! inv(p, r) = 1/(t(l+r+1) - t(l+r+1-p)), positive since the span holds
    ! [t(l), t(l+1)]
    real(wp) :: nd(0:max_degree, 0:max_degree), inv(max_degree, 0:max_degree - 1)
    real(wp) :: left(max_degree), right(max_degree), b(0:max_degree), q(0:max_degree - 1), saved, temp
    integer :: j, r, m, p
    nd(0, 0) = 1
    do j = 1, k
      left(j) = x - t(l + 1 - j)
      right(j) = t(l + j) - x
      saved = 0
      do r = 0, j - 1
        inv(j, r) = 1/(t(l + r + 1) - t(l + r + 1 - j))
        temp = nd(r, j - 1)*inv(j, r)
        nd(r, j) = saved + right(r + 1)*temp
        saved = left(j - r)*temp
      end do
      nd(j, j) = saved
    end do
    d = 0
    d(0, 1:k + 1) = nd(0:k, k)
    do m = 1, k
      ! b: the (p-k+m)-th derivatives of the B-splines of degree p
      b(0:k - m) = nd(0:k - m, k - m)
      do p = k - m + 1, k
        do r = 0, p - 1
          q(r) = p*b(r)*inv(p, r)
        end do
        b(0) = -q(0)
        do r = 1, p - 1
          b(r) = q(r - 1) - q(r)
        end do
        b(p) = q(p - 1)
      end do
      d(m, 1:k + 1) = b(0:k)
    end do
  end subroutine basis_derivatives
end module numerics_spline_kernels
