!> The B-spline paraboloids of thesis table 3.2 (3.5.3.3): z = (u^2 + v^2)/a^2
!> sampled at 13 x 13 points, fitted by SURFIT with degree 5 and s = 0.05. A
!> quintic tensor spline without interior knots holds z exactly, so the fit
!> must reproduce the analytic paraboloid (3.58) and all its partials to third
!> order up to rounding of the least-squares solve, at scattered points of the
!> whole domain, edges included.
program test_paraboloid_fit
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_elementary, only: paraboloid_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_scattered
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  ! Rounding of a 36-unknown least-squares solve on O(1) data: ~1e-15 in z;
  ! each derivative order loses a factor ~ degree/knot span ~ 10 (observed:
  ! 2e-15, 2e-14, 1e-13, 6e-13). Tolerances 1e-13 .. 1e-10 relative keep a
  ! margin above 50 while any smoothing bias (fp > 0) would show at ~1e-3.
  real(wp), parameter :: tol(0:3) = [1e-13_wp, 1e-12_wp, 1e-11_wp, 1e-10_wp]
  type(status_t) :: st

  call check_paraboloid('paraboloid 2 (a^2 = 3 on [-2, 2]^2)', 3.0_wp, 2.0_wp)
  call check_paraboloid('paraboloid 3 (a^2 = 0.5 on [-0.5, 0.5]^2)', 0.5_wp, 0.5_wp)
  call finish_tests('test_paraboloid_fit')

contains

  subroutine check_paraboloid(label, a2, half_width)
    character(len=*), intent(in) :: label
    real(wp), intent(in) :: a2, half_width
    integer, parameter :: n = 13, kdeg = 5
    real(wp), parameter :: smoothing = 0.05_wp
    real(wp) :: x(n*n), y(n*n), z(n*n), u, v, worst(0:3), scale(0:3)
    type(bspline_surface_t) :: fit
    type(paraboloid_t) :: exact
    type(surface_point_t) :: p, q
    integer :: i, j, k
    do j = 1, n
      do i = 1, n
        k = i + n*(j - 1)
        x(k) = -half_width + 2*half_width*(i - 1)/real(n - 1, wp)
        y(k) = -half_width + 2*half_width*(j - 1)/real(n - 1, wp)
        z(k) = (x(k)**2 + y(k)**2)/a2        ! (3.58), c = 1, a = b
      end do
    end do
    fit = bspline_scattered(x, y, z, smoothing, kdeg, kdeg, st)
    call check(st%ok(), label//': SURFIT fit: '//st%text())
    if (.not. st%ok()) return
    call check(size(fit%spline%knots_u()) == 2*(kdeg + 1) .and. size(fit%spline%knots_v()) == 2*(kdeg + 1), &
               label//': no interior knots')
    call check_close(fit%spline%residual(), 0.0_wp, 0.0_wp, 1e-20_wp, label//': fp = 0 (exact representation)')
    exact = paraboloid_t(sqrt(a2), sqrt(a2), 1.0_wp, st)
    worst = 0
    scale = 0
    do k = 0, 400   ! scattered points, the domain's corners and edges among them
      u = half_width*merge(sin(7.3_wp*k), sign(1.0_wp, sin(1.1_wp*k)), mod(k, 10) /= 0)
      v = half_width*merge(cos(3.9_wp*k + 0.4_wp), sign(1.0_wp, cos(2.3_wp*k)), mod(k, 7) /= 0)
      call fit%evaluate(u, v, 3, p, st)
      call exact%evaluate(u, v, 3, q, st)
      worst(0) = max(worst(0), maxval(abs(p%r - q%r)))
      worst(1) = max(worst(1), maxval(abs([p%ru - q%ru, p%rv - q%rv])))
      worst(2) = max(worst(2), maxval(abs([p%ruu - q%ruu, p%ruv - q%ruv, p%rvv - q%rvv])))
      worst(3) = max(worst(3), maxval(abs([p%ruuu - q%ruuu, p%ruuv - q%ruuv, p%ruvv - q%ruvv, p%rvvv - q%rvvv])))
      scale(0) = max(scale(0), maxval(abs(q%r)))
      scale(1) = max(scale(1), maxval(abs([q%ru, q%rv])))
      scale(2) = max(scale(2), maxval(abs([q%ruu, q%ruv, q%rvv])))
    end do
    scale(3) = scale(2)/half_width   ! the exact third partials are zero
    call check(st%ok(), label//': evaluation')
    do k = 0, 3
      call check(worst(k) <= tol(k)*scale(k), label//': partials of order '//achar(48 + k)//' = analytic')
    end do
    print '(a, 4es10.2)', label//': max errors of orders 0..3 relative: ', worst/scale
  end subroutine check_paraboloid
end program test_paraboloid_fit
