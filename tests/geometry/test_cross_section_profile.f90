!> Profiles from points (spline-fitted cross-sections): an open U-profile and
!> a closed circle through points lie on their shapes within the fit's
!> accuracy, derivatives against differences, and a tube with a profile
!> section; self-intersecting, repeated and too few points are rejected.
program test_cross_section_profile
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_cross_section, only: profile_section_t, new_profile_section, section_point_t, &
                                    polyline_self_intersection
  use geometry_curve, only: line_curve_t, constant_curve_t
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use geometry_surface, only: surface_point_t
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  type(status_t) :: st
  type(profile_section_t) :: u_profile, ring
  type(section_point_t) :: p, pp, pm
  type(tube_surface_t) :: tube
  type(surface_point_t) :: q
  real(wp) :: y(41), z(41), a, b, v, worst, h
  integer :: i, k

  ! --- an open semicircle of radius 0.52 m through 41 points (thesis 4.2 orientation)
  do i = 1, 41
    v = pi*(i - 1)/40
    y(i) = -0.52_wp*cos(v); z(i) = -0.52_wp*sin(v)
  end do
  u_profile = new_profile_section(y, z, 0.0_wp, 5, st)
  call check(st%ok(), 'U profile fitted: ' // st%text())
  call u_profile%v_range(a, b)
  call check(a == 0 .and. abs(b - 0.52_wp*pi) < 1e-3_wp, 'profile v is chord length (~ arc length)')
  worst = 0
  do i = 0, 100
    call u_profile%evaluate(0.0_wp, a + (b - a)*i/100.0_wp, 0, p, st)
    worst = max(worst, abs(norm2(p%s(:, 0, 0)) - 0.52_wp))
  end do
  ! quintic interpolation, points 4.5 deg apart: error ~ r dphi^6 ~ 1e-8 m; require 1e-6 m
  call check(worst < 1e-6_wp, 'U profile on its semicircle within the fit accuracy')
  ! derivatives against central differences (step 1e-5; error ~1e-10 S; tol 1e-7 (1 + S))
  h = 1e-5_wp
  do i = 1, 7
    v = a + (b - a)*(i - 0.3_wp)/7.2_wp
    call u_profile%evaluate(0.0_wp, v, 3, p, st)
    call u_profile%evaluate(0.0_wp, v + h, 3, pp, st)
    call u_profile%evaluate(0.0_wp, v - h, 3, pm, st)
    do k = 1, 3
      call check_close_array(p%s(:, 0, k), (pp%s(:, 0, k - 1) - pm%s(:, 0, k - 1))/(2*h), 0.0_wp, &
                             1e-7_wp*(1 + maxval(abs(p%s))), 'profile v-derivative')
    end do
  end do

  ! --- a closed ring: periodic profile
  do i = 1, 41
    v = two_pi*(i - 1)/40
    y(i) = -0.4_wp*cos(v); z(i) = -0.4_wp*sin(v)
  end do
  y(41) = y(1); z(41) = z(1)
  ring = new_profile_section(y, z, 0.0_wp, 5, st)
  call check(st%ok(), 'closed profile fitted: ' // st%text())
  call check(ring%periodic(), 'closed profile is periodic')

  ! --- a tube with the U profile on a straight centerline
  tube = new_tube_surface(line_curve_t(origin=[0.0_wp, 0.0_wp, 0.0_wp], direction=[1.0_wp, 0.0_wp, 0.0_wp], &
                          u_min=0.0_wp, u_max=5.0_wp), constant_curve_t(), u_profile, st)
  call tube%evaluate(2.0_wp, 0.26_wp*pi, 0, q, st)
  call check_close(q%r(3), -0.52_wp, 0.0_wp, 1e-6_wp, 'profile tube: bottom at the middle of the profile')

  ! --- bad profiles
  call check(polyline_self_intersection([0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, 0.5_wp], &
             [0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, -1.0_wp]) == 1, 'self-intersection found at its first segment')
  call check(polyline_self_intersection(y, z) == 0, 'a closed circle does not intersect itself')
  u_profile = new_profile_section([0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp, 0.5_wp, 0.6_wp], &
                                  [0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, -1.0_wp, -1.2_wp], 0.0_wp, 3, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'intersects') > 0, &
             'self-intersecting profile rejected: ' // st%text())
  u_profile = new_profile_section([0.0_wp, 1.0_wp, 1.0_wp, 2.0_wp, 3.0_wp], &
                                  [0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 1.0_wp], 0.0_wp, 3, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'repeats') > 0, &
             'repeated point rejected: ' // st%text())
  u_profile = new_profile_section([0.0_wp, 1.0_wp, 2.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], 0.0_wp, 3, st)
  call check(st%code == STATUS_INVALID_INPUT, 'too few profile points rejected')

  call finish_tests('test_cross_section_profile')
end program test_cross_section_profile
