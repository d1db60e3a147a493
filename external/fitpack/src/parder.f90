!> parder: the partial derivative d^(nux+nuy) s / dx^nux dy^nuy of a bivariate
!> spline on the grid x(1..mx) x y(1..my), z(my*(i-1)+j). 0 <= nux < kx,
!> 0 <= nuy < ky. The derivative is itself a spline of degrees kx-nux, ky-nuy on
!> the knots tx(nux+1..nx-nux), ty(nuy+1..ny-nuy); its coefficients come from
!> repeated differencing of c and it is then evaluated like bispev.
!> lwrk >= mx*(kx+1-nux)+my*(ky+1-nuy)+(nx-kx-1)*(ny-ky-1), kwrk >= mx+my.
!> ier = 0, or 10 for invalid input.
subroutine parder(tx, nx, ty, ny, c, kx, ky, nux, nuy, x, mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_surface_interfaces, only: fpbisp
  implicit none (type, external)
  integer, intent(in) :: nx, ny, kx, ky, nux, nuy, mx, my, lwrk, kwrk
  real(real64), intent(in) :: tx(nx), ty(ny), c((nx - kx - 1)*(ny - ky - 1)), x(mx), y(my)
  real(real64), intent(out) :: z(mx*my)
  real(real64), intent(inout) :: wrk(lwrk)
  integer, intent(inout) :: iwrk(kwrk)
  integer, intent(out) :: ier
  integer :: nxx, nyy, nc, iwx, iwy, kkx, kky, i, j, m
  real(real64) :: fac
  ier = 10
  if (nux < 0 .or. nux >= kx) return
  if (nuy < 0 .or. nuy >= ky) return
  nxx = nx - kx - 1
  nyy = ny - ky - 1
  nc = nxx*nyy
  if (lwrk < nc + (kx + 1 - nux)*mx + (ky + 1 - nuy)*my) return
  if (kwrk < mx + my) return
  if (mx < 1 .or. my < 1) return
  if (mx > 1) then
    if (any(x(2:mx) < x(1:mx - 1))) return
  end if
  if (my > 1) then
    if (any(y(2:my) < y(1:my - 1))) return
  end if
  ier = 0
  wrk(1:nc) = c(1:nc)
  ! coefficients (row i, column j) at wrk(nyy0*(i-1)+j), nyy0 the original
  ! row length; differencing shrinks the used block in place.
  kkx = kx
  do m = 1, nux
    nxx = nxx - 1
    do i = 1, nxx
      fac = tx(i + m + kkx) - tx(i + m)
      do j = 1, nyy
        if (fac > 0) then
          wrk((i - 1)*nyy + j) = kkx*(wrk(i*nyy + j) - wrk((i - 1)*nyy + j))/fac
        else
          wrk((i - 1)*nyy + j) = 0
        end if
      end do
    end do
    kkx = kkx - 1
  end do
  kky = ky
  do m = 1, nuy
    do i = 1, nxx
      do j = 1, nyy - 1
        fac = ty(j + m + kky) - ty(j + m)
        if (fac > 0) then
          wrk((i - 1)*nyy + j) = kky*(wrk((i - 1)*nyy + j + 1) - wrk((i - 1)*nyy + j))/fac
        else
          wrk((i - 1)*nyy + j) = 0
        end if
      end do
    end do
    kky = kky - 1
  end do
  ! repack rows to the new length nyy - nuy
  if (nuy > 0) then
    do i = 1, nxx
      do j = 1, nyy - nuy
        wrk((i - 1)*(nyy - nuy) + j) = wrk((i - 1)*nyy + j)
      end do
    end do
  end if
  iwx = nc + 1
  iwy = iwx + mx*(kx + 1 - nux)
  call fpbisp(tx(nux + 1), nx - 2*nux, ty(nuy + 1), ny - 2*nuy, wrk(1), kx - nux, ky - nuy, &
    x, mx, y, my, z, wrk(iwx), wrk(iwy), iwrk(1), iwrk(mx + 1))
end subroutine parder
