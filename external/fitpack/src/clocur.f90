!> clocur: closed (periodic) smoothing spline curve in idim dimensions
!> (Dierckx's calling sequence, reals real64). The first and last data points
!> must coincide. ipar = 0: chord-length parameters scaled to [0,1].
!> x(idim*(i-1)+j); c(n*(j-1)+i); nc >= nest*idim;
!> lwrk >= m*(k+1) + nest*(7+idim+5*k); iwrk(nest). ier as percur.
subroutine clocur(iopt, ipar, idim, m, u, mx, x, w, k, s, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fp_periodic_knot_checks
  implicit none (type, external)
  integer, intent(in) :: iopt, ipar, idim, m, mx, k, nest, nc, lwrk
  real(real64), intent(inout) :: u(m)
  real(real64), intent(in) :: x(mx), w(m), s
  integer, intent(inout) :: n, iwrk(nest)
  real(real64), intent(inout) :: t(nest), c(nc), fp, wrk(lwrk)
  integer, intent(out) :: ier
  external :: fpclos
  real(real64), parameter :: tol = 0.001_real64
  integer, parameter :: maxit = 20
  real(real64) :: dist
  integer :: i, i1, i2, j, k1, k2, lwest, ncc, nmin, ifp, iz, ia1, ia2, ib, ig1, ig2, iq

  ier = 10
  if (iopt < -1 .or. iopt > 1) return
  if (ipar < 0 .or. ipar > 1) return
  if (idim <= 0 .or. idim > 10) return
  if (k <= 0 .or. k > 5) return
  k1 = k + 1
  k2 = k1 + 1
  nmin = 2*k1
  if (m < 2 .or. nest < nmin) return
  ncc = nest*idim
  if (mx < m*idim .or. nc < ncc) return
  lwest = m*k1 + nest*(7 + idim + 5*k)
  if (lwrk < lwest) return
  i1 = idim
  i2 = m*idim
  do j = 1, idim
    if (x(i1) /= x(i2)) return
    i1 = i1 - 1
    i2 = i2 - 1
  end do
  if (ipar == 0 .and. iopt <= 0) then
    i1 = 0
    i2 = idim
    u(1) = 0
    do i = 2, m
      dist = 0
      do j = 1, idim
        i1 = i1 + 1
        i2 = i2 + 1
        dist = dist + (x(i2) - x(i1))**2
      end do
      u(i) = u(i - 1) + sqrt(dist)
    end do
    if (u(m) <= 0) return
    do i = 2, m
      u(i) = u(i)/u(m)
    end do
    u(m) = 1
  end if
  if (w(1) <= 0) return
  do i = 1, m - 1
    if (u(i) >= u(i + 1) .or. w(i) <= 0) return
  end do
  call fp_periodic_knot_checks(iopt, u, m, k, s, nest, n, t, ier)
  if (ier /= 0) return
  ifp = 1
  iz = ifp + nest
  ia1 = iz + ncc
  ia2 = ia1 + nest*k1
  ib = ia2 + nest*k
  ig1 = ib + nest*k2
  ig2 = ig1 + nest*k2
  iq = ig2 + nest*k1
  call fpclos(iopt, idim, m, u, mx, x, w, k, s, nest, tol, maxit, k1, k2, n, t, ncc, c, fp, wrk(ifp), &
              wrk(iz), wrk(ia1), wrk(ia2), wrk(ib), wrk(ig1), wrk(ig2), wrk(iq), iwrk, ier)
end subroutine clocur

!> Dierckx's fpclos: the clocur engine (fpperiodic_core).
subroutine fpclos(iopt, idim, m, u, mx, x, w, k, s, nest, tol, maxit, k1, k2, n, t, nc, c, fp, fpint, &
                  z, a1, a2, b, g1, g2, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, idim, m, mx, k, nest, maxit, k1, k2, nc
  real(real64), intent(in) :: u(m), x(mx), w(m), s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nc), fp, fpint(nest), z(nc)
  real(real64), intent(inout) :: a1(nest, k1), a2(nest, k), b(nest, k2), g1(nest, k2), &
                                 g2(nest, k1), q(m, k1)
  external :: fpperiodic_core
  call fpperiodic_core(iopt, idim, m, u, mx, x, w, k, s, nest, tol, maxit, k1, k2, n, t, nc, c, fp, &
                       fpint, z, a1, a2, b, g1, g2, q, nrdata, ier)
end subroutine fpclos
