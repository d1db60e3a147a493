!> Integral of a spline: splint and its kernel fpintb (Dierckx's calling
!> sequences, reals real64). Limits outside [t(k+1), t(n-k)] are clamped to it;
!> a > b gives the negative integral.

!> bint(i) = integral of the i-th normalized B-spline from x to y. Computed per
!> knot span by 3-point Gauss-Legendre quadrature (exact for degree <= 5).
pure subroutine fpintb(t, n, bint, nk1, x, y)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: n, nk1
  real(real64), intent(in) :: t(n), x, y
  real(real64), intent(out) :: bint(nk1)
  real(real64), parameter :: node = 0.77459666924148337704_real64   ! sqrt(3/5)
  real(real64), parameter :: gw(3) = [5.0_real64/9, 8.0_real64/9, 5.0_real64/9]
  real(real64) :: a, b, lo, hi, mid, half, h(6), xq
  integer :: k, k1, l, q, j
  logical :: swapped
  bint = 0
  k1 = n - nk1
  k = k1 - 1
  swapped = x > y
  a = min(x, y)
  b = max(x, y)
  a = max(a, t(k1))
  b = min(b, t(nk1 + 1))
  if (a >= b) return
  do l = k1, nk1
    lo = max(a, t(l))
    hi = min(b, t(l + 1))
    if (hi <= lo) cycle
    mid = 0.5_real64*(lo + hi)
    half = 0.5_real64*(hi - lo)
    do q = 1, 3
      xq = mid + real(q - 2, real64)*node*half
      call fpbspl(t, n, k, xq, l, h)
      do j = 1, k1
        bint(l - k1 + j) = bint(l - k1 + j) + gw(q)*half*h(j)
      end do
    end do
  end do
  if (swapped) bint = -bint
end subroutine fpintb

function splint(t, n, c, k, a, b, wrk) result(integral)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpintb
  implicit none (type, external)
  integer, intent(in) :: n, k
  real(real64), intent(in) :: t(n), c(n), a, b
  real(real64), intent(out) :: wrk(n)
  real(real64) :: integral
  integer :: nk1
  nk1 = n - k - 1
  call fpintb(t, n, wrk, nk1, a, b)
  integral = sum(c(1:nk1)*wrk(1:nk1))
end function splint
