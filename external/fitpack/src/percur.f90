!> percur: periodic smoothing spline y = s(x) of degree k with period
!> x(m) - x(1) (Dierckx's calling sequence, reals real64). y(m) plays no role
!> (it is y(1) by periodicity). lwrk >= m*(k+1) + nest*(8+5*k); iwrk(nest);
!> s = 0 needs nest >= m+2k. ier as curfit (-2: the constant is good enough).
subroutine percur(iopt, m, x, y, w, k, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fp_periodic_knot_checks
  implicit none (type, external)
  integer, intent(in) :: iopt, m, k, nest, lwrk
  real(real64), intent(in) :: x(m), y(m), w(m), s
  integer, intent(inout) :: n, iwrk(nest)
  real(real64), intent(inout) :: t(nest), c(nest), fp, wrk(lwrk)
  integer, intent(out) :: ier
  external :: fpperi
  real(real64), parameter :: tol = 0.001_real64
  integer, parameter :: maxit = 20
  integer :: i, k1, k2, lwest, nmin, ifp, iz, ia1, ia2, ib, ig1, ig2, iq

  ier = 10
  if (k <= 0 .or. k > 5) return
  k1 = k + 1
  k2 = k1 + 1
  if (iopt < -1 .or. iopt > 1) return
  nmin = 2*k1
  if (m < 2 .or. nest < nmin) return
  lwest = m*k1 + nest*(8 + 5*k)
  if (lwrk < lwest) return
  do i = 1, m - 1
    if (x(i) >= x(i + 1) .or. w(i) <= 0) return
  end do
  call fp_periodic_knot_checks(iopt, x, m, k, s, nest, n, t, ier)
  if (ier /= 0) return
  ifp = 1
  iz = ifp + nest
  ia1 = iz + nest
  ia2 = ia1 + nest*k1
  ib = ia2 + nest*k
  ig1 = ib + nest*k2
  ig2 = ig1 + nest*k2
  iq = ig2 + nest*k1
  call fpperi(iopt, x, y, w, m, k, s, nest, tol, maxit, k1, k2, n, t, c, fp, wrk(ifp), wrk(iz), &
              wrk(ia1), wrk(ia2), wrk(ib), wrk(ig1), wrk(ig2), wrk(iq), iwrk, ier)
end subroutine percur

!> Dierckx's fpperi: the percur engine (fpperiodic_core for one coordinate).
subroutine fpperi(iopt, x, y, w, m, k, s, nest, tol, maxit, k1, k2, n, t, c, fp, fpint, z, a1, a2, &
                  b, g1, g2, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, m, k, nest, maxit, k1, k2
  real(real64), intent(in) :: x(m), y(m), w(m), s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nest), fp, fpint(nest), z(nest)
  real(real64), intent(inout) :: a1(nest, k1), a2(nest, k), b(nest, k2), g1(nest, k2), &
                                 g2(nest, k1), q(m, k1)
  external :: fpperiodic_core
  call fpperiodic_core(iopt, 1, m, x, m, y, w, k, s, nest, tol, maxit, k1, k2, n, t, nest, c, fp, &
                       fpint, z, a1, a2, b, g1, g2, q, nrdata, ier)
end subroutine fpperi
