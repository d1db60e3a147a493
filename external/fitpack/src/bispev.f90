!> bispev: values of a bivariate spline s(x,y) of degrees kx, ky (knots tx, ty,
!> coefficients c((ny-ky-1)*(i-1)+j)) on the grid x(1..mx) x y(1..my);
!> z(my*(i-1)+j) = s(x(i), y(j)). Points outside the knot range are clamped to
!> it. ier = 0, or 10 for invalid input (workspace too small, points not
!> non-decreasing). Workspace: lwrk >= mx*(kx+1)+my*(ky+1), kwrk >= mx+my.
subroutine bispev(tx, nx, ty, ny, c, kx, ky, x, mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_surface_interfaces, only: fpbisp
  implicit none (type, external)
  integer, intent(in) :: nx, ny, kx, ky, mx, my, lwrk, kwrk
  real(real64), intent(in) :: tx(nx), ty(ny), c((nx - kx - 1)*(ny - ky - 1)), x(mx), y(my)
  real(real64), intent(out) :: z(mx*my)
  real(real64), intent(inout) :: wrk(lwrk)
  integer, intent(inout) :: iwrk(kwrk)
  integer, intent(out) :: ier
  integer :: iw
  ier = 10
  if (lwrk < (kx + 1)*mx + (ky + 1)*my) return
  if (kwrk < mx + my) return
  if (mx < 1 .or. my < 1) return
  if (mx > 1) then
    if (any(x(2:mx) < x(1:mx - 1))) return
  end if
  if (my > 1) then
    if (any(y(2:my) < y(1:my - 1))) return
  end if
  ier = 0
  iw = mx*(kx + 1) + 1
  call fpbisp(tx, nx, ty, ny, c, kx, ky, x, mx, y, my, z, wrk(1), wrk(iw), iwrk(1), iwrk(mx + 1))
end subroutine bispev

!> fpbisp: the work of bispev. wx(i,:) holds the kx+1 B-splines that do not
!> vanish at x(i) and lx(i) the index of the first of them minus one (likewise
!> for y); then each grid value is the (kx+1) x (ky+1) tensor sum.
pure subroutine fpbisp(tx, nx, ty, ny, c, kx, ky, x, mx, y, my, z, wx, wy, lx, ly)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl
  implicit none (type, external)
  integer, intent(in) :: nx, ny, kx, ky, mx, my
  real(real64), intent(in) :: tx(nx), ty(ny), c((nx - kx - 1)*(ny - ky - 1)), x(mx), y(my)
  real(real64), intent(out) :: z(mx*my), wx(mx, kx + 1), wy(my, ky + 1)
  integer, intent(out) :: lx(mx), ly(my)
  call locate(tx, nx, kx, x, mx, wx, lx)
  call locate(ty, ny, ky, y, my, wy, ly)
  block
    integer :: i, j, i1, j1, l1, m, nky1
    real(real64) :: sp, row
    nky1 = ny - ky - 1
    m = 0
    do i = 1, mx
      do j = 1, my
        sp = 0
        l1 = lx(i)*nky1 + ly(j)
        do i1 = 1, kx + 1
          row = 0
          do j1 = 1, ky + 1
            row = row + c(l1 + j1)*wy(j, j1)
          end do
          sp = sp + row*wx(i, i1)
          l1 = l1 + nky1
        end do
        m = m + 1
        z(m) = sp
      end do
    end do
  end block
contains
  !> Knot interval t(l) <= arg < t(l+1) (k+1 <= l <= n-k-1) of each clamped
  !> point, found by moving right only (points are sorted).
  pure subroutine locate(t, n, k, p, mp, w, lp)
    integer, intent(in) :: n, k, mp
    real(real64), intent(in) :: t(n), p(mp)
    real(real64), intent(out) :: w(mp, k + 1)
    integer, intent(out) :: lp(mp)
    real(real64) :: arg, h(6)
    integer :: i, l
    l = k + 1
    do i = 1, mp
      arg = min(max(p(i), t(k + 1)), t(n - k))
      do while (arg >= t(l + 1) .and. l /= n - k - 1)
        l = l + 1
      end do
      call fpbspl(t, n, k, arg, l, h)
      w(i, :) = h(1:k + 1)
      lp(i) = l - k - 1
    end do
  end subroutine locate
end subroutine fpbisp
