!> Evaluation of splines in B-spline form: splev (values), splder (nu-th
!> derivative), curev (parametric curve). Dierckx's calling sequences; points
!> outside [t(k+1), t(n-k)] are clamped to the ends, and the points must be
!> non-decreasing (else ier = 10).

!> Knot interval l with t(l) <= arg < t(l+1), k1 <= l <= nk1, starting the
!> search from the previous l (moves in either direction).
pure subroutine fp_find_interval(t, n, k1, arg, l)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: n, k1
  real(real64), intent(in) :: t(n), arg
  integer, intent(inout) :: l
  integer :: nk1
  nk1 = n - k1
  if (l < k1 .or. l > nk1) l = k1
  do while (arg < t(l) .and. l > k1)
    l = l - 1
  end do
  do while (arg >= t(l + 1) .and. l < nk1)
    l = l + 1
  end do
end subroutine fp_find_interval

pure subroutine splev(t, n, c, k, x, y, m, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: n, k, m
  real(real64), intent(in) :: t(n), c(n), x(m)
  real(real64), intent(out) :: y(m)
  integer, intent(out) :: ier
  interface
    pure subroutine fp_find_interval(t, n, k1, arg, l)
      import :: real64
      integer, intent(in) :: n, k1
      real(real64), intent(in) :: t(n), arg
      integer, intent(inout) :: l
    end subroutine fp_find_interval
  end interface
  real(real64) :: arg, sp, tb, te, h(6)
  integer :: i, j, k1, l, ll, nk1
  ier = 10
  if (m < 1) return
  do i = 2, m
    if (x(i) < x(i - 1)) return
  end do
  ier = 0
  k1 = k + 1
  nk1 = n - k1
  tb = t(k1)
  te = t(nk1 + 1)
  l = k1
  do i = 1, m
    arg = min(max(x(i), tb), te)
    call fp_find_interval(t, n, k1, arg, l)
    call fpbspl(t, n, k, arg, l, h)
    sp = 0
    ll = l - k1
    do j = 1, k1
      ll = ll + 1
      sp = sp + c(ll)*h(j)
    end do
    y(i) = sp
  end do
end subroutine splev

pure subroutine splder(t, n, c, k, nu, x, y, m, wrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: n, k, nu, m
  real(real64), intent(in) :: t(n), c(n), x(m)
  real(real64), intent(out) :: y(m), wrk(n)
  integer, intent(out) :: ier
  interface
    pure subroutine fp_find_interval(t, n, k1, arg, l)
      import :: real64
      integer, intent(in) :: n, k1
      real(real64), intent(in) :: t(n), arg
      integer, intent(inout) :: l
    end subroutine fp_find_interval
  end interface
  real(real64) :: ak, arg, fac, sp, tb, te, h(6)
  integer :: i, j, k1, k2, kk, l, l1, l2, ll, nk1
  ier = 10
  if (nu < 0 .or. nu > k) return
  if (m < 1) return
  do i = 2, m
    if (x(i) < x(i - 1)) return
  end do
  ier = 0
  k1 = k + 1
  nk1 = n - k1
  tb = t(k1)
  te = t(nk1 + 1)
  ! B-spline coefficients of the nu-th derivative (de Boor's difference formula)
  wrk(1:nk1) = c(1:nk1)
  kk = k
  do j = 1, nu
    ak = kk
    do i = 1, nk1 - j
      l1 = i + j
      l2 = l1 + kk
      fac = t(l2) - t(l1)
      if (fac <= 0) cycle
      wrk(i) = ak*(wrk(i + 1) - wrk(i))/fac
    end do
    kk = kk - 1
  end do
  k2 = k1 - nu
  l = k1
  do i = 1, m
    arg = min(max(x(i), tb), te)
    call fp_find_interval(t, n, k1, arg, l)
    call fpbspl(t, n, kk, arg, l, h)
    sp = 0
    ll = l - k1
    do j = 1, k2
      ll = ll + 1
      sp = sp + wrk(ll)*h(j)
    end do
    y(i) = sp
  end do
end subroutine splder

!> Points x(idim*(i-1)+j) of the parametric curve with coefficients
!> c(n*(j-1)+l) at parameters u(1..m).
pure subroutine curev(idim, t, n, c, nc, k, u, m, x, mx, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: idim, n, nc, k, m, mx
  real(real64), intent(in) :: t(n), c(nc), u(m)
  real(real64), intent(out) :: x(mx)
  integer, intent(out) :: ier
  interface
    pure subroutine fp_find_interval(t, n, k1, arg, l)
      import :: real64
      integer, intent(in) :: n, k1
      real(real64), intent(in) :: t(n), arg
      integer, intent(inout) :: l
    end subroutine fp_find_interval
  end interface
  real(real64) :: arg, sp, tb, te, h(6)
  integer :: i, j, j1, jj, k1, l, ll, md, nk1
  ier = 10
  if (m < 1) return
  do i = 2, m
    if (u(i) < u(i - 1)) return
  end do
  if (mx < m*idim) return
  if (nc < idim*n - k - 1) return
  ier = 0
  k1 = k + 1
  nk1 = n - k1
  tb = t(k1)
  te = t(nk1 + 1)
  l = k1
  md = 0
  do i = 1, m
    arg = min(max(u(i), tb), te)
    call fp_find_interval(t, n, k1, arg, l)
    call fpbspl(t, n, k, arg, l, h)
    ll = l - k1
    do j1 = 1, idim
      jj = ll
      sp = 0
      do j = 1, k1
        jj = jj + 1
        sp = sp + c(jj)*h(j)
      end do
      md = md + 1
      x(md) = sp
      ll = ll + n
    end do
  end do
end subroutine curev
