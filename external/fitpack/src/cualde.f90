!> All derivatives of a spline at one point: fpader (kernel), spalde (one
!> coordinate), cualde (parametric curve). A point on an interior knot gets the
!> right-hand derivatives, the right end the left-hand ones.

!> d(j+1) = j-th derivative (j = 0..k) at x, t(l) <= x < t(l+1); the
!> coefficients of each derivative come from de Boor's difference formula
!> on the k+1 coefficients that matter in knot interval l (as splder).
pure subroutine fpader(t, n, c, k1, x, l, d)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: n, k1, l
  real(real64), intent(in) :: t(n), c(n), x
  real(real64), intent(out) :: d(k1)
  real(real64) :: v(6), h(6), ak, fac, sp
  integer :: i, j, k, kk, lk
  k = k1 - 1
  lk = l - k1
  v(1:k1) = c(lk + 1:lk + k1)
  kk = k
  do j = 0, k
    if (j > 0) then
      ! v(i) is the coefficient of global index lk+i of the j-th derivative
      ak = kk + 1
      do i = 1, k1 - j
        fac = t(lk + i + j + kk + 1) - t(lk + i + j)
        if (fac <= 0) cycle
        v(i) = ak*(v(i + 1) - v(i))/fac
      end do
    end if
    call fpbspl(t, n, kk, x, l, h)
    sp = 0
    do i = 1, k1 - j
      sp = sp + v(i)*h(i)
    end do
    d(j + 1) = sp
    kk = kk - 1
  end do
end subroutine fpader

pure subroutine spalde(t, n, c, k1, x, d, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpader
  implicit none (type, external)
  integer, intent(in) :: n, k1
  real(real64), intent(in) :: t(n), c(n), x
  real(real64), intent(out) :: d(k1)
  integer, intent(out) :: ier
  integer :: l, nk1
  ier = 10
  nk1 = n - k1
  if (x < t(k1) .or. x > t(nk1 + 1)) return
  l = k1
  do while (x >= t(l + 1) .and. l /= nk1)
    l = l + 1
  end do
  if (t(l) >= t(l + 1)) return
  ier = 0
  call fpader(t, n, c, k1, x, l, d)
end subroutine spalde

!> d(idim*j + i) = j-th derivative of coordinate i at u (j = 0..k1-1).
pure subroutine cualde(idim, t, n, c, nc, k1, u, d, nd, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpader
  implicit none (type, external)
  integer, intent(in) :: idim, n, nc, k1, nd
  real(real64), intent(in) :: t(n), c(nc), u
  real(real64), intent(out) :: d(nd)
  integer, intent(out) :: ier
  real(real64) :: h(6)
  integer :: i, j, kk, l, mm, nk1
  ier = 10
  if (nd < k1*idim) return
  nk1 = n - k1
  if (u < t(k1) .or. u > t(nk1 + 1)) return
  l = k1
  do while (u >= t(l + 1) .and. l /= nk1)
    l = l + 1
  end do
  if (t(l) >= t(l + 1)) return
  ier = 0
  j = 1
  do i = 1, idim
    call fpader(t, n, c(j), k1, u, l, h)
    mm = i
    do kk = 1, k1
      d(mm) = h(kk)
      mm = mm + idim
    end do
    j = j + n
  end do
end subroutine cualde
