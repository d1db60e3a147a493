!> Knot insertion (Boehm): insert and its kernel fpinst. Dierckx's calling
!> sequences, reals real64. iopt = 1 keeps the spline periodic (the inserted
!> knot must then lie at least 2k knots from either end).

pure subroutine insert(iopt, t, n, c, k, x, tt, nn, cc, nest, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpinst
  implicit none (type, external)
  integer, intent(in) :: iopt, n, k, nest
  real(real64), intent(in) :: t(nest), c(nest), x
  integer, intent(out) :: nn, ier
  real(real64), intent(out) :: tt(nest), cc(nest)
  integer :: k1, kk, l, nk, nk1
  ier = 10
  nn = n
  tt = t
  cc = c
  if (iopt /= 0 .and. iopt /= 1) return
  if (nest <= n) return
  k1 = k + 1
  nk = n - k
  if (x < t(k1) .or. x > t(nk)) return
  nk1 = nk - 1
  l = k1
  do while (x >= t(l + 1) .and. l /= nk1)
    l = l + 1
  end do
  if (t(l) >= t(l + 1)) return
  if (iopt /= 0) then
    kk = 2*k
    if (l <= kk .or. l >= n - kk) return
  end if
  ier = 0
  call fpinst(iopt, t, n, c, k, x, l, tt, nn, cc, nest)
end subroutine insert

!> Inserts x, t(l) <= x < t(l+1), into the knots t(1..n) of a degree-k
!> spline: tt(1..n+1), and the coefficients cc of the same spline.
pure subroutine fpinst(iopt, t, n, c, k, x, l, tt, nn, cc, nest)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, n, k, l, nest
  real(real64), intent(in) :: t(nest), c(nest), x
  integer, intent(out) :: nn
  real(real64), intent(out) :: tt(nest), cc(nest)
  real(real64) :: fac, per
  integer :: i, j, k1, mk, nk, nk1, nl
  k1 = k + 1
  nk1 = n - k1
  tt(1:l) = t(1:l)
  tt(l + 1) = x
  tt(l + 2:n + 1) = t(l + 1:n)
  ! coefficients: unchanged left of l-k and right of l; a convex combination between
  cc(1:l - k) = c(1:l - k)
  do i = l - k + 1, l
    fac = (x - t(i))/(t(i + k) - t(i))
    cc(i) = fac*c(i) + (1 - fac)*c(i - 1)
  end do
  cc(l + 1:nk1 + 1) = c(l:nk1)
  nn = n + 1
  if (iopt == 0) return
  ! periodic: the first and last k coefficients and outer knots must repeat
  nk = nn - k
  nl = nk - k1
  per = tt(nk) - tt(k1)
  i = k1
  j = nk
  if (l + 1 > nl) then
    do mk = 1, k
      cc(mk) = cc(mk + nl)
      i = i - 1
      j = j - 1
      tt(i) = tt(j) - per
    end do
  else if (l + 1 <= k1 + k) then
    do mk = 1, k
      cc(mk + nl) = cc(mk)
      i = i + 1
      j = j + 1
      tt(j) = tt(i) + per
    end do
  end if
end subroutine fpinst
