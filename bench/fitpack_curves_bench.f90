!> Curve benchmarks of our FITPACK against the genuine one (bench/fitpack_curves_bench.py
!> runs this program and times scipy on the same data):
!>   1. a cubic spline y(x) (interpolating 200 points of sin x + x/10 on [0,10]) at
!>      10^6 sorted points with splev;
!>   2. a cubic 3-D curve (interpolating 200 points of a helix) at 10^6 parameters
!>      with spline_curve_t%evaluate (point only) and FITPACK's curev;
!>   3. fitting 10^4 noisy points y_i = sin x_i + x_i/10 + 0.05 sin(12345.678 i) with
!>      curfit, s = m 0.05^2/2 (the noise's variance times m);
!>   4. fitting 10^4 noisy 3-D points with parcur (spline_curve_t%fit), same s rule.
!> Output: "<key> <value>" lines (best of several runs, seconds), with checksums
!> and the fits' n and fp, so the script can check both sides computed the same.
program fitpack_curves_bench
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_spline_curve, only: spline_curve_t
  use fitpack_interfaces, only: curfit, splev, curev
  implicit none (type, external)
  integer, parameter :: m0 = 200, ne = 1000000, mf = 10000, repeats = 5
  real(wp), allocatable :: x(:), y(:), w(:), t(:), c(:), wrk(:), xs(:), ys(:), pts(:, :), u(:), xyz(:)
  integer, allocatable :: iwrk(:)
  real(wp) :: fp, best, s, d(3, 0:0), checksum
  integer :: i, n, ier, nest, lwrk, r
  integer(int64) :: c0, c1, rate
  type(spline_curve_t) :: curve
  type(status_t) :: status

  call system_clock(count_rate=rate)

  ! 1. splev of an interpolating cubic at 10^6 points
  allocate (x(m0), y(m0), w(m0))
  do i = 1, m0
    x(i) = 10*real(i - 1, wp)/(m0 - 1)
  end do
  y = sin(x) + 0.1_wp*x
  w = 1
  nest = m0 + 4
  lwrk = m0*4 + nest*16
  allocate (t(nest), c(nest), wrk(lwrk), iwrk(nest))
  call curfit(0, m0, x, y, w, x(1), x(m0), 3, 0.0_wp, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
  allocate (xs(ne), ys(ne))
  do i = 1, ne
    xs(i) = 10*real(i - 1, wp)/(ne - 1)
  end do
  best = huge(1.0_wp)
  do r = 1, repeats
    call system_clock(c0)
    call splev(t, n, c, 3, xs, ys, ne, ier)
    call system_clock(c1)
    best = min(best, real(c1 - c0, wp)/rate)
  end do
  print '(a, es12.4)', 'splev_1e6 ', best
  print '(a, es24.16)', 'splev_1e6_checksum ', sum(ys)

  ! 2. a cubic 3-D curve at 10^6 parameters
  allocate (pts(3, m0), u(m0))
  do i = 1, m0
    u(i) = real(i - 1, wp)/(m0 - 1)
    pts(:, i) = [cos(12*u(i)), sin(12*u(i)), 2*u(i)]
  end do
  call curve%fit(pts, 0.0_wp, 3, status, parameters=u)
  if (.not. status%ok()) error stop 'bench: curve fit failed'
  best = huge(1.0_wp)
  do r = 1, repeats
    checksum = 0
    call system_clock(c0)
    do i = 1, ne
      call curve%evaluate(real(i - 1, wp)/(ne - 1), d, 0)
      checksum = checksum + d(1, 0) + d(2, 0) + d(3, 0)
    end do
    call system_clock(c1)
    best = min(best, real(c1 - c0, wp)/rate)
  end do
  print '(a, es12.4)', 'curve_eval_1e6 ', best
  print '(a, es24.16)', 'curve_eval_1e6_checksum ', checksum
  block
    real(wp), allocatable :: tk(:), ck(:, :), cf(:), us(:)
    integer :: nk, j
    tk = curve%get_knots()
    ck = curve%get_coefficients()
    nk = size(tk)
    allocate (cf(3*nk), us(ne), xyz(3*ne))
    cf = 0
    do j = 1, 3
      cf(nk*(j - 1) + 1:nk*(j - 1) + size(ck, 2)) = ck(j, :)
    end do
    do i = 1, ne
      us(i) = real(i - 1, wp)/(ne - 1)
    end do
    best = huge(1.0_wp)
    do r = 1, repeats
      call system_clock(c0)
      call curev(3, tk, nk, cf, 3*nk, 3, us, ne, xyz, 3*ne, ier)
      call system_clock(c1)
      best = min(best, real(c1 - c0, wp)/rate)
    end do
    print '(a, es12.4)', 'curev_1e6 ', best
    print '(a, es24.16)', 'curev_1e6_checksum ', sum(xyz)
  end block

  ! 3. curfit on 10^4 noisy points
  deallocate (x, y, w, t, c, wrk, iwrk)
  allocate (x(mf), y(mf), w(mf))
  do i = 1, mf
    x(i) = 10*real(i - 1, wp)/(mf - 1)
    y(i) = sin(x(i)) + 0.1_wp*x(i) + 0.05_wp*sin(12345.678_wp*(i - 1))
  end do
  w = 1
  s = mf*0.05_wp**2/2
  nest = mf + 4
  lwrk = mf*4 + nest*16
  allocate (t(nest), c(nest), wrk(lwrk), iwrk(nest))
  best = huge(1.0_wp)
  do r = 1, repeats
    call system_clock(c0)
    call curfit(0, mf, x, y, w, x(1), x(mf), 3, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call system_clock(c1)
    best = min(best, real(c1 - c0, wp)/rate)
  end do
  print '(a, es12.4)', 'curfit_1e4 ', best
  print '(a, i0)', 'curfit_1e4_n ', n
  print '(a, es24.16)', 'curfit_1e4_fp ', fp
  print '(a, i0)', 'curfit_1e4_ier ', ier

  ! 4. parcur (through spline_curve_t) on 10^4 noisy 3-D points, u given
  deallocate (pts, u)
  allocate (pts(3, mf), u(mf))
  do i = 1, mf
    u(i) = real(i - 1, wp)/(mf - 1)
    pts(:, i) = [cos(12*u(i)), sin(12*u(i)), 2*u(i)] + 0.05_wp*sin(12345.678_wp*(i - 1))
  end do
  s = 3*mf*0.05_wp**2/2
  best = huge(1.0_wp)
  do r = 1, repeats
    call system_clock(c0)
    call curve%fit(pts, s, 3, status, parameters=u)
    call system_clock(c1)
    best = min(best, real(c1 - c0, wp)/rate)
  end do
  print '(a, es12.4)', 'parcur_1e4 ', best
  print '(a, i0)', 'parcur_1e4_n ', size(curve%get_knots())
  print '(a, es24.16)', 'parcur_1e4_fp ', curve%residual()
end program fitpack_curves_bench
