!> parcur: smoothing spline curve s(u) in idim dimensions (Dierckx's calling
!> sequence, reals real64). ipar = 0: parameters from the cumulative chord
!> length scaled to [0,1] (ub = 0, ue = 1 on return); 1: u, ub, ue given.
!> x(idim*(i-1)+j); coefficients c(n*(j-1)+i); nc >= nest*idim;
!> lwrk >= m*(k+1) + nest*(6+idim+3*k); iwrk(nest). ier as curfit.
subroutine parcur(iopt, ipar, idim, m, u, mx, x, w, ub, ue, k, s, nest, n, t, nc, c, fp, &
                  wrk, lwrk, iwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpchec
  implicit none (type, external)
  integer, intent(in) :: iopt, ipar, idim, m, mx, k, nest, nc, lwrk
  real(real64), intent(inout) :: u(m), ub, ue
  real(real64), intent(in) :: x(mx), w(m), s
  integer, intent(inout) :: n, iwrk(nest)
  real(real64), intent(inout) :: t(nest), c(nc), fp, wrk(lwrk)
  integer, intent(out) :: ier
  external :: fppara
  real(real64), parameter :: tol = 0.001_real64
  integer, parameter :: maxit = 20
  real(real64) :: dist
  integer :: i, i1, i2, ia, ib, ifp, ig, iq, iz, j, k1, k2, lwest, ncc, nmin

  ier = 10
  if (iopt < -1 .or. iopt > 1) return
  if (ipar < 0 .or. ipar > 1) return
  if (idim <= 0 .or. idim > 10) return
  if (k <= 0 .or. k > 5) return
  k1 = k + 1
  k2 = k1 + 1
  nmin = 2*k1
  if (m < k1 .or. nest < nmin) return
  ncc = nest*idim
  if (mx < m*idim .or. nc < ncc) return
  lwest = m*k1 + nest*(6 + idim + 3*k)
  if (lwrk < lwest) return
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
    ub = 0
    ue = 1
    u(m) = ue
  end if
  if (ub > u(1) .or. ue < u(m) .or. w(1) <= 0) return
  do i = 2, m
    if (u(i - 1) >= u(i) .or. w(i) <= 0) return
  end do
  if (iopt < 0) then
    if (n < nmin .or. n > nest) return
    j = n
    do i = 1, k1
      t(i) = ub
      t(j) = ue
      j = j - 1
    end do
    call fpchec(u, m, t, n, k, ier)
    if (ier /= 0) return
  else
    if (s < 0) return
    if (s == 0 .and. nest < m + k1) return
    ier = 0
  end if
  ifp = 1
  iz = ifp + nest
  ia = iz + ncc
  ib = ia + nest*k1
  ig = ib + nest*k2
  iq = ig + nest*k2
  call fppara(iopt, idim, m, u, mx, x, w, ub, ue, k, s, nest, tol, maxit, k1, k2, n, t, ncc, c, fp, &
              wrk(ifp), wrk(iz), wrk(ia), wrk(ib), wrk(ig), wrk(iq), iwrk, ier)
end subroutine parcur

!> Dierckx's fppara: the parcur engine (fpcurve_core without end constraints).
subroutine fppara(iopt, idim, m, u, mx, x, w, ub, ue, k, s, nest, tol, maxit, k1, k2, n, t, nc, c, &
                  fp, fpint, z, a, b, g, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, idim, m, mx, k, nest, maxit, k1, k2, nc
  real(real64), intent(in) :: u(m), x(mx), w(m), ub, ue, s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nc), fp, fpint(nest), z(nc)
  real(real64), intent(inout) :: a(nest, k1), b(nest, k2), g(nest, k2), q(m, k1)
  external :: fpcurve_core
  call fpcurve_core(iopt, idim, m, u, mx, x, w, ub, ue, 0, 0, k, s, nest, tol, maxit, .true., k1, k2, n, t, &
                    nc, c, fp, fpint, z, a, b, g, q, nrdata, ier)
end subroutine fppara
