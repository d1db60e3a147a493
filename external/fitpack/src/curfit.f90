!> curfit: smoothing spline y = s(x) of degree k (Dierckx's calling sequence,
!> reals are real64). See fpcurve_core for the algorithm. Workspace:
!> lwrk >= m*(k+1) + nest*(7+3*k); iwrk(nest). Returns ier as the original:
!> 0, -1 (interpolating), -2 (polynomial), 1 (nest too small), 2, 3, 10.
subroutine curfit(iopt, m, x, y, w, xb, xe, k, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, m, k, nest, lwrk
  real(real64), intent(in) :: x(m), y(m), w(m), xb, xe, s
  integer, intent(inout) :: n, iwrk(nest)
  real(real64), intent(inout) :: t(nest), c(nest), fp, wrk(lwrk)
  integer, intent(out) :: ier
  external :: fpcurf
  real(real64), parameter :: tol = 0.001_real64
  integer, parameter :: maxit = 20
  integer :: i, ia, ib, ifp, ig, iq, iz, j, k1, k2, lwest, nmin

  ier = 10
  if (k <= 0 .or. k > 5) return
  k1 = k + 1
  k2 = k1 + 1
  if (iopt < -1 .or. iopt > 1) return
  nmin = 2*k1
  if (m < k1 .or. nest < nmin) return
  lwest = m*k1 + nest*(7 + 3*k)
  if (lwrk < lwest) return
  if (xb > x(1) .or. xe < x(m)) return
  if (w(1) <= 0) return
  do i = 2, m
    if (x(i - 1) >= x(i) .or. w(i) <= 0) return
  end do
  if (iopt < 0) then
    if (n < nmin .or. n > nest) return
    j = n
    do i = 1, k1
      t(i) = xb
      t(j) = xe
      j = j - 1
    end do
    call fpchec_checked(ier)
    if (ier /= 0) return
  else
    if (s < 0) return
    if (s == 0 .and. nest < m + k1) return
    ier = 0
  end if
  ifp = 1
  iz = ifp + nest
  ia = iz + nest
  ib = ia + nest*k1
  ig = ib + nest*k2
  iq = ig + nest*k2
  call fpcurf(iopt, x, y, w, m, xb, xe, k, s, nest, tol, maxit, k1, k2, n, t, c, fp, wrk(ifp), &
              wrk(iz), wrk(ia), wrk(ib), wrk(ig), wrk(iq), iwrk, ier)
contains
  subroutine fpchec_checked(code)
    use fitpack_interfaces, only: fpchec
    integer, intent(out) :: code
    call fpchec(x, m, t, n, k, code)
  end subroutine fpchec_checked
end subroutine curfit

!> Dierckx's fpcurf: the curfit engine (one coordinate of fpcurve_core).
subroutine fpcurf(iopt, x, y, w, m, xb, xe, k, s, nest, tol, maxit, k1, k2, n, t, c, fp, fpint, &
                  z, a, b, g, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, m, k, nest, maxit, k1, k2
  real(real64), intent(in) :: x(m), y(m), w(m), xb, xe, s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nest), fp, fpint(nest), z(nest)
  real(real64), intent(inout) :: a(nest, k1), b(nest, k2), g(nest, k2), q(m, k1)
  external :: fpcurve_core
  call fpcurve_core(iopt, 1, m, x, m, y, w, xb, xe, 0, 0, k, s, nest, tol, maxit, .false., k1, k2, n, t, &
                    nest, c, fp, fpint, z, a, b, g, q, nrdata, ier)
end subroutine fpcurf
