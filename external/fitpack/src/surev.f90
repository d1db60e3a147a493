!> surev: values of a bicubic parametric surface (knots tu, tv, coefficients
!> c((nu-4)*(nv-4)*(l-1)+(nv-4)*(i-1)+j), l = 1..idim) on the grid
!> u(1..mu) x v(1..mv): f(mu*mv*(l-1)+mv*(i-1)+j) = r_l(u(i), v(j)). Points
!> outside [tu(4), tu(nu-3)] x [tv(4), tv(nv-3)] are clamped. ier = 0, or 10
!> for invalid input. mf >= mu*mv*idim, lwrk >= 4*(mu+mv), kwrk >= mu+mv.
subroutine surev(idim, tu, nu, tv, nv, c, u, mu, v, mv, f, mf, wrk, lwrk, iwrk, kwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_surface_interfaces, only: fpsuev
  implicit none (type, external)
  integer, intent(in) :: idim, nu, nv, mu, mv, mf, lwrk, kwrk
  real(real64), intent(in) :: tu(nu), tv(nv), c((nu - 4)*(nv - 4)*idim), u(mu), v(mv)
  real(real64), intent(out) :: f(mf)
  real(real64), intent(inout) :: wrk(lwrk)
  integer, intent(inout) :: iwrk(kwrk)
  integer, intent(out) :: ier
  ier = 10
  if (idim < 1) return
  if (mf < mu*mv*idim) return
  if (lwrk < 4*(mu + mv)) return
  if (kwrk < mu + mv) return
  if (mu < 1 .or. mv < 1) return
  if (mu > 1) then
    if (any(u(2:mu) < u(1:mu - 1))) return
  end if
  if (mv > 1) then
    if (any(v(2:mv) < v(1:mv - 1))) return
  end if
  ier = 0
  call fpsuev(idim, tu, nu, tv, nv, c, u, mu, v, mv, f, wrk(1), wrk(4*mu + 1), iwrk(1), iwrk(mu + 1))
end subroutine surev

!> fpsuev: the work of surev (the four nonzero cubic B-splines per point, then
!> a 4 x 4 tensor sum per coordinate).
pure subroutine fpsuev(idim, tu, nu, tv, nv, c, u, mu, v, mv, f, wu, wv, lu, lv)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: idim, nu, nv, mu, mv
  real(real64), intent(in) :: tu(nu), tv(nv), c((nu - 4)*(nv - 4)*idim), u(mu), v(mv)
  real(real64), intent(out) :: f(mu*mv*idim), wu(mu, 4), wv(mv, 4)
  integer, intent(out) :: lu(mu), lv(mv)
  integer :: i, j, l, i1, j1, ncv, nc, base
  real(real64) :: sp
  call locate(tu, nu, u, mu, wu, lu)
  call locate(tv, nv, v, mv, wv, lv)
  ncv = nv - 4
  nc = (nu - 4)*ncv
  do l = 1, idim
    do i = 1, mu
      do j = 1, mv
        sp = 0
        base = nc*(l - 1) + lu(i)*ncv + lv(j)
        do i1 = 1, 4
          do j1 = 1, 4
            sp = sp + c(base + (i1 - 1)*ncv + j1)*wu(i, i1)*wv(j, j1)
          end do
        end do
        f(mu*mv*(l - 1) + mv*(i - 1) + j) = sp
      end do
    end do
  end do
contains
  pure subroutine locate(t, n, p, mp, w, lp)
    integer, intent(in) :: n, mp
    real(real64), intent(in) :: t(n), p(mp)
    real(real64), intent(out) :: w(mp, 4)
    integer, intent(out) :: lp(mp)
    real(real64) :: arg, h(6)
    integer :: ii, ll
    ll = 4
    do ii = 1, mp
      arg = min(max(p(ii), t(4)), t(n - 3))
      do while (arg >= t(ll + 1) .and. ll /= n - 4)
        ll = ll + 1
      end do
      call fpbspl(t, n, 3, arg, ll, h)
      w(ii, :) = h(1:4)
      lp(ii) = ll - 4
    end do
  end subroutine locate
end subroutine fpsuev
