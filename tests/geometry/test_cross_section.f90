!> Cross-sections: the logistic function and its derivatives (C.38-C.40)
!> against differences and its 0.99 definition (3.72); blend weights; every
!> section's partials against differences; the circle's orientation (thesis
!> 4.2); the flume's shape (semicircle 0.52 m, walls 0.164 m, exact away from
!> the joints, within r dv^2/2 near them) and smoothness of its curvature.
program test_cross_section
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_cross_section, only: cross_section_t, section_point_t, circle_section_t, &
    ellipse_section_t, flume_section_t, blended_section_t, section_holder_t, new_blended_section, &
    logistic, logistic_rate, blend_weights
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences, step 1e-5: error ~1e-11 S (S the derivative size,
  ! < 1e3 here); 1e-7 (1 + S) leaves a margin > 100, a wrong term fails.
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  type(status_t) :: st
  real(wp) :: lam(0:3), lp(0:3), lm(0:3), xi, v, w(0:3, 3), l2(0:3, 2)
  type(circle_section_t) :: circle
  type(ellipse_section_t) :: ellipse
  type(flume_section_t) :: flume
  type(blended_section_t) :: blend
  type(section_holder_t) :: parts(2)
  type(section_point_t) :: p
  integer :: i, k
  real(wp) :: kappa, worst, expected(2), vmin, vmax

  ! Logistic function (3.70) with the thesis's fig. 3.10 values: midpoint 5, u_99 = 7.
  xi = logistic_rate(5.0_wp, 7.0_wp)
  call logistic(7.0_wp, 5.0_wp, xi, lam)
  call check_close(lam(0), 0.99_wp, 1e-14_wp, 0.0_wp, 'Lambda(u_99) = 0.99 (3.72)')
  call logistic(5.0_wp, 5.0_wp, xi, lam)
  call check_close(lam(0), 0.5_wp, 1e-15_wp, 0.0_wp, 'Lambda(midpoint) = 0.5')
  call logistic(3.0_wp, 5.0_wp, xi, lam)
  call check_close(lam(0), 0.01_wp, 1e-13_wp, 0.0_wp, 'Lambda symmetric: 0.01 at 2 midpoint - u_99')
  do i = 0, 20
    v = 0.5_wp*i
    call logistic(v, 5.0_wp, xi, lam)
    call logistic(v + h, 5.0_wp, xi, lp)
    call logistic(v - h, 5.0_wp, xi, lm)
    do k = 1, 3
      call check_close(lam(k), (lp(k - 1) - lm(k - 1))/(2*h), 0.0_wp, fd_tol*(1 + maxval(abs(lam))), &
                       'logistic derivative (C.38-C.40)')
    end do
  end do
  ! far from the midpoint: no overflow, exactly 0 or 1 to rounding
  call logistic(1e4_wp, 0.0_wp, 50.0_wp, lam)
  call check(lam(0) == 1 .and. all(abs(lam(1:3)) < 1e-280_wp), 'logistic saturates at +large')
  call logistic(-1e4_wp, 0.0_wp, 50.0_wp, lam)
  call check(lam(0) < 1e-280_wp .and. all(abs(lam(1:3)) < 1e-280_wp), 'logistic saturates at -large')

  ! Blend weights (3.69) for 3 sections: value and derivatives against differences.
  do i = 0, 12
    v = 0.7_wp*i
    call weights_at(v, w)
    block
      real(wp) :: wp_(0:3, 3), wm_(0:3, 3)
      call weights_at(v + h, wp_)
      call weights_at(v - h, wm_)
      do k = 1, 3
        call check_close_array(w(k, :), (wp_(k - 1, :) - wm_(k - 1, :))/(2*h), 0.0_wp, &
                               fd_tol*(1 + maxval(abs(w))), 'blend weight derivative')
      end do
    end block
  end do
  call weights_at(0.0_wp, w)
  call check_close_array(w(0, :), [1.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-6_wp, 'weights at the start')
  call weights_at(8.0_wp, w)
  call check_close_array(w(0, :), [0.0_wp, 0.0_wp, 1.0_wp], 0.0_wp, 1e-6_wp, 'weights at the end')

  ! Circle (thesis 4.2): v = pi/2 is the bottom (z = -r), v = 0 is y = -r.
  circle = circle_section_t(radius=0.7_wp)
  call circle%evaluate(0.0_wp, pi/2, 0, p, st)
  call check_close_array(p%s(:, 0, 0), [0.0_wp, -0.7_wp], 0.0_wp, 1e-15_wp, 'circle bottom at v = pi/2')
  call circle%evaluate(0.0_wp, 0.0_wp, 0, p, st)
  call check_close_array(p%s(:, 0, 0), [-0.7_wp, 0.0_wp], 0.0_wp, 1e-15_wp, 'circle at v = 0')
  ellipse = ellipse_section_t(a=0.6_wp, b=0.3_wp)
  flume = flume_section_t()
  call fd_section(circle, 'circle')
  call fd_section(ellipse, 'ellipse')
  call fd_section(flume, 'flume')
  allocate (parts(1)%section, source=circle)
  allocate (parts(2)%section, source=ellipse)
  blend = new_blended_section(parts, [2.0_wp], [2.5_wp], st)
  call check(st%ok(), 'blend built')
  call fd_section(blend, 'blended circle/ellipse')

  ! Flume: range, exact semicircle and walls away from the joints.
  call flume%v_range(vmin, vmax)
  call check_close(vmin, -0.164_wp/0.52_wp, 1e-15_wp, 0.0_wp, 'flume v_min = -wall/r')
  call check_close(vmax, pi + 0.164_wp/0.52_wp, 1e-15_wp, 0.0_wp, 'flume v_max')
  worst = 0
  do i = 0, 400
    v = vmin + (vmax - vmin)*i/400.0_wp
    call flume%evaluate(0.0_wp, v, 3, p, st)
    if (v < 0) then
      expected = [-0.52_wp, -0.52_wp*v]
    else if (v <= pi) then
      expected = [-0.52_wp*cos(v), -0.52_wp*sin(v)]
    else
      expected = [0.52_wp, 0.52_wp*(v - pi)]
    end if
    if (min(abs(v), abs(v - pi)) > 0.35_wp) then
      ! more than 7 transition widths from a joint: weights are 1 to ~1e-14
      call check_close_array(p%s(:, 0, 0), expected, 0.0_wp, 1e-12_wp, 'flume exact away from joints')
    end if
    worst = max(worst, norm2(p%s(:, 0, 0) - expected))
    ! curvature of the profile stays bounded (no folds or spikes): |kappa| < 2.5/r
    kappa = (p%s(1, 0, 1)*p%s(2, 0, 2) - p%s(2, 0, 1)*p%s(1, 0, 2))/norm2(p%s(:, 0, 1))**3
    call check(abs(kappa) < 2.5_wp/0.52_wp, 'flume curvature bounded')
  end do
  ! the blended joint deviates by at most r dv^2/2 = 0.65 mm (dv = 0.05 rad)
  call check(worst <= 0.52_wp*0.05_wp**2/2, 'flume deviation near joints within r dv^2/2')
  call check(worst > 0, 'flume joints are actually smoothed')
  ! flume at the bottom
  call flume%evaluate(0.0_wp, pi/2, 0, p, st)
  call check_close_array(p%s(:, 0, 0), [0.0_wp, -0.52_wp], 0.0_wp, 1e-14_wp, 'flume bottom')

  ! The extent (the tube's fold and clearance checks): the largest |s| of the
  ! sampled points, the flume's at its walls' tops, the ellipse's its half
  ! width; a kind that says it does not vary along u gives the same number
  ! at every u (the tube takes it once), a blend says it varies.
  call check_close(flume%extent(0.0_wp), hypot(0.52_wp, 0.164_wp), 0.0_wp, 1e-12_wp, &
                   'flume extent: its walls'' tops')
  call check_close(ellipse%extent(0.0_wp), 0.6_wp, 0.0_wp, 1e-15_wp, 'ellipse extent: its half width')
  call check(circle%extent(0.0_wp) == 0.7_wp, 'circle extent: its radius')
  do i = 1, 20
    v = -5 + 1.7_wp*i   ! a u
    call check(flume%extent(v) == flume%extent(0.0_wp) .and. ellipse%extent(v) == ellipse%extent(0.0_wp) .and. &
               circle%extent(v) == circle%extent(0.0_wp), 'one extent at every u where the section does not vary')
  end do
  call check(.not. (flume%varies_along() .or. ellipse%varies_along() .or. circle%varies_along()) .and. &
             blend%varies_along(), 'circle, ellipse, flume one section along u; a blend varies')
  call check(abs(blend%extent(0.0_wp) - 0.7_wp) < 1e-12_wp .and. abs(blend%extent(5.0_wp) - 0.7_wp) < 1e-12_wp, &
             'the blend''s extent: the larger of its sections''')

  ! Invalid blends.
  blend = new_blended_section(parts, [2.0_wp], [1.5_wp], st)
  call check(st%code == STATUS_INVALID_INPUT, 'u_99 before midpoint rejected')

  call finish_tests('test_cross_section')

contains

  subroutine weights_at(x, wout)
    real(wp), intent(in) :: x
    real(wp), intent(out) :: wout(0:3, 3)
    call logistic(x, 2.5_wp, logistic_rate(2.5_wp, 3.0_wp), l2(:, 1))
    call logistic(x, 5.5_wp, logistic_rate(5.5_wp, 6.0_wp), l2(:, 2))
    call blend_weights(l2, wout)
  end subroutine weights_at

  subroutine fd_section(sec, name)
    class(cross_section_t), intent(in) :: sec
    character(len=*), intent(in) :: name
    type(section_point_t) :: p0, pu1, pu0, pv1, pv0
    real(wp) :: a, b, uu, vv, tol
    integer :: i, k, l
    call sec%v_range(a, b)
    do i = 1, 5
      uu = 0.9_wp*i - 0.4_wp
      vv = a + (b - a)*(0.17_wp*i - 0.05_wp)
      call sec%evaluate(uu, vv, 3, p0, st)
      call sec%evaluate(uu + h, vv, 3, pu1, st)
      call sec%evaluate(uu - h, vv, 3, pu0, st)
      call sec%evaluate(uu, vv + h, 3, pv1, st)
      call sec%evaluate(uu, vv - h, 3, pv0, st)
      tol = fd_tol*(1 + maxval(abs(p0%s)))
      do k = 0, 3
        do l = 0, 3 - k
          if (k > 0) call check_close_array(p0%s(:, k, l), (pu1%s(:, k - 1, l) - pu0%s(:, k - 1, l))/(2*h), &
                                            0.0_wp, tol, name // ': u-derivative')
          if (l > 0) call check_close_array(p0%s(:, k, l), (pv1%s(:, k, l - 1) - pv0%s(:, k, l - 1))/(2*h), &
                                            0.0_wp, tol, name // ': v-derivative')
        end do
      end do
    end do
  end subroutine fd_section
end program test_cross_section
