!> The water's geometry: the closed-form tubes (geometry_tube, seen through the
!> water's channel adapter) with their partials against central differences,
!> centerline curvature (4.8) and its rate (4.9) against closed forms and
!> differences, the circular segment (F.1) with dA/dh = b (F.2) and
!> dA/dR = R alpha - b (F.3), the profile area (4.45-4.47) against (F.1), and
!> the inverse A -> h.
program test_water_channel
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use testing, only: check, check_close, check_close_array, finish_tests
  use geometry_tube, only: new_straight_tube, new_helix_tube, new_s_bend_tube
  use water_channel, only: channel_t, new_channel
  use water_section, only: circle_segment, circle_height_for_area, profile_water
  implicit none (type, external)

  type(channel_t) :: tubes(4)
  type(status_t) :: st
  character(len=*), parameter :: names(4) = [character(len=24) :: 'straight tube', 'helix tube', &
    'clockwise helix tube', 'S-bend tube']
  integer :: k

  tubes(1) = new_channel(new_straight_tube(0.5_wp, 0.3_wp, 10.0_wp, st))
  tubes(2) = new_channel(new_helix_tube(0.5_wp, 3.0_wp, 0.3_wp, 1.0_wp, 10.0_wp, st))
  tubes(3) = new_channel(new_helix_tube(0.4_wp, 2.0_wp, 0.5_wp, -1.0_wp, 10.0_wp, st))
  tubes(4) = new_channel(new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 20.0_wp, st))
  call check(st%ok(), 'closed-form tubes built')
  do k = 1, size(tubes)
    call partials(tubes(k), trim(names(k)))
  end do
  call closed_forms()
  call curvature()
  call segment()
  call profile()
  call finish_tests('test_water_channel')

contains

  !> r_u, r_v, ..., r_vvv against central differences of the next lower order at
  !> scattered points (h = 1e-5: truncation ~h^2 |r'''| ~ 1e-9, rounding ~1e-11).
  subroutine partials(t, name)
    type(channel_t), intent(in) :: t
    character(len=*), intent(in) :: name
    type(surface_point_t) :: p, pu1, pu2, pv1, pv2
    type(status_t) :: st
    real(wp), parameter :: h = 1e-5_wp, tol = 1e-7_wp
    real(wp) :: us(3) = [0.7_wp, 2.3_wp, 5.1_wp], vs(3) = [0.4_wp, 1.6_wp, 2.9_wp]
    real(wp) :: chi, chi_s, chi1, chi_s1, speed, speed_u, speed_p, speed_m, speed_u1
    integer :: i
    do i = 1, 3
      call t%evaluate(us(i), vs(i), 3, p, st)
      call t%evaluate(us(i) + h, vs(i), 3, pu1, st)
      call t%evaluate(us(i) - h, vs(i), 3, pu2, st)
      call t%evaluate(us(i), vs(i) + h, 3, pv1, st)
      call t%evaluate(us(i), vs(i) - h, 3, pv2, st)
      call check(st%ok(), 'tube evaluation')
      call check_close_array(p%ru, (pu1%r - pu2%r)/(2*h), 0.0_wp, tol, name//' r_u')
      call check_close_array(p%rv, (pv1%r - pv2%r)/(2*h), 0.0_wp, tol, name//' r_v')
      call check_close_array(p%ruu, (pu1%ru - pu2%ru)/(2*h), 0.0_wp, tol, name//' r_uu')
      call check_close_array(p%ruv, (pv1%ru - pv2%ru)/(2*h), 0.0_wp, tol, name//' r_uv')
      call check_close_array(p%rvv, (pv1%rv - pv2%rv)/(2*h), 0.0_wp, tol, name//' r_vv')
      call check_close_array(p%ruuu, (pu1%ruu - pu2%ruu)/(2*h), 0.0_wp, tol, name//' r_uuu')
      call check_close_array(p%ruuv, (pv1%ruu - pv2%ruu)/(2*h), 0.0_wp, tol, name//' r_uuv')
      call check_close_array(p%ruvv, (pv1%ruv - pv2%ruv)/(2*h), 0.0_wp, tol, name//' r_uvv')
      call check_close_array(p%rvvv, (pv1%rvv - pv2%rvv)/(2*h), 0.0_wp, tol, name//' r_vvv')
      ! the section is the circle of radius r about the centerline, v = pi/2 at the bottom
      call check_close(norm2(p%rv), t%radius, 1e-14_wp, 0.0_wp, 'circle radius |r_v| = r')
      ! the integrator's path: the surface point and chi, chi_s from one
      ! centerline evaluation equal the separate evaluations
      call t%evaluate_with_curvature(us(i), vs(i), pu1, chi, chi_s, speed, speed_u, st)
      call t%curvature(us(i), chi1, chi_s1, st)
      call check(all([pu1%r, pu1%ru, pu1%rv, pu1%ruu, pu1%ruv, pu1%rvv] == [p%r, p%ru, p%rv, p%ruu, p%ruv, p%rvv]) &
                 .and. chi == chi1 .and. chi_s == chi_s1, name//': evaluate_with_curvature = evaluate + curvature')
      call check_close(speed, (t%arc_length(us(i) + h) - t%arc_length(us(i) - h))/(2*h), 1e-9_wp, 0.0_wp, &
                       name//': |c_u| = ds/du')
      call t%evaluate_with_curvature(us(i) + h, vs(i), pu2, chi, chi_s, speed_p, speed_u1, st)
      call t%evaluate_with_curvature(us(i) - h, vs(i), pu2, chi, chi_s, speed_m, speed_u1, st)
      call check_close(speed_u, (speed_p - speed_m)/(2*h), 0.0_wp, 1e-8_wp, name//': d|c_u|/du against differences')
    end do
    call t%evaluate(1.0_wp, pi/2, 2, p, st)
    call check(dot_product(cross(p%ru, p%rv), [0.0_wp, 0.0_wp, 1.0_wp]) > 0, &
               name//': normal r_u x r_v points up (into the tube) at the bottom')
  end subroutine partials

  !> The closed forms the tubes are defined by (docs/water.md, &channel):
  !> straight c = u [cos t, 0, -sin t]; helix c = [rho cos(s u), rho sin(s u), -p u];
  !> S-bend c = [u, a sin(k u), -q u]; the bottom (v = pi/2) lies r below c.
  subroutine closed_forms()
    type(surface_point_t) :: p
    real(wp) :: u, x(3), y(3), c(3, 0:3)
    u = 2.0_wp
    call tubes(1)%evaluate(u, pi/2, 0, p, st)
    call check_close_array(p%r, u*[cos(0.3_wp), 0.0_wp, -sin(0.3_wp)] - 0.5_wp*[sin(0.3_wp), 0.0_wp, cos(0.3_wp)], &
                           0.0_wp, 1e-14_wp, 'straight tube: bottom point')
    call tubes(2)%centerline(u, c, st)
    call check_close_array(c(:, 0), [3.0_wp*cos(u), 3.0_wp*sin(u), -0.3_wp*u], 0.0_wp, 1e-14_wp, &
                           'helix tube: counter-clockwise centerline')
    call tubes(3)%centerline(u, c, st)
    call check_close_array(c(:, 0), [2.0_wp*cos(u), -2.0_wp*sin(u), -0.5_wp*u], 0.0_wp, 1e-14_wp, &
                           'helix tube: clockwise centerline')
    call check_close_array(c(:, 1), [-2.0_wp*sin(u), -2.0_wp*cos(u), -0.5_wp], 0.0_wp, 1e-14_wp, &
                           'helix tube: clockwise tangent')
    ! S-bend: the bottom is c - r z with the horizon frame x = c'/|c'|,
    ! y = h x x/|h x x|, z = x x y (h = e_z)
    x = [1.0_wp, 1.5_wp*0.4_wp*cos(0.4_wp*u), -0.1_wp]
    x = x/norm2(x)
    y = [-x(2), x(1), 0.0_wp]/norm2(x(1:2))
    call tubes(4)%evaluate(u, pi/2, 0, p, st)
    call check_close_array(p%r, [u, 1.5_wp*sin(0.4_wp*u), -0.1_wp*u] - 0.5_wp*cross(x, y), 0.0_wp, 1e-14_wp, &
                           'S-bend: bottom point')
    ! arc length in closed form: straight u, helix sqrt(rho^2 + p^2) u
    call check_close(tubes(1)%arc_length(u), u, 1e-15_wp, 0.0_wp, 'straight tube arc length')
    call check_close(tubes(3)%arc_length(u), sqrt(2.0_wp**2 + 0.5_wp**2)*u, 1e-15_wp, 0.0_wp, 'helix arc length')
  end subroutine closed_forms

  subroutine curvature()
    real(wp) :: chi, chi_s, chi1, chi2, d1, d2, s1, s2, h
    type(status_t) :: st
    integer :: i
    real(wp) :: us(4) = [0.3_wp, 1.9_wp, 4.4_wp, 7.0_wp]
    call tubes(2)%curvature(1.0_wp, chi, chi_s, st)
    call check_close(chi, 3.0_wp/(3.0_wp**2 + 0.3_wp**2), 1e-14_wp, 0.0_wp, 'helix curvature rho/(rho^2+p^2)')
    call check_close(chi_s, 0.0_wp, 0.0_wp, 1e-14_wp, 'helix curvature constant')
    call tubes(1)%curvature(1.0_wp, chi, chi_s, st)
    call check(chi == 0 .and. chi_s == 0, 'straight tube: chi = 0')
    ! S-bend: chi_s = (d chi/du)/|c_u| against central differences of chi
    h = 1e-5_wp
    do i = 1, size(us)
      call tubes(4)%curvature(us(i), chi, chi_s, st)
      call tubes(4)%curvature(us(i) + h, chi1, d1, st)
      call tubes(4)%curvature(us(i) - h, chi2, d2, st)
      s1 = tubes(4)%arc_length(us(i) + h)
      s2 = tubes(4)%arc_length(us(i) - h)
      call check_close(chi_s, (chi1 - chi2)/(s1 - s2), 1e-6_wp, 1e-9_wp, 'S-bend d chi/ds (4.9)')
      ! closed form for c = [u, a sin ku, -q u]: chi = a k^2 |sin ku| sqrt(1+q^2)/|c'|^3
      call check_close(chi, 1.5_wp*0.16_wp*abs(sin(0.4_wp*us(i)))*sqrt(1 + 0.01_wp)/ &
                       sqrt(1 + 0.01_wp + (1.5_wp*0.4_wp*cos(0.4_wp*us(i)))**2)**3, 1e-13_wp, 0.0_wp, &
                       'S-bend curvature closed form')
    end do
    ! arc length: quadrature against the closed form of the helix
    call check_close(tubes(4)%arc_length(0.0_wp), 0.0_wp, 0.0_wp, 1e-14_wp, 'arc length starts at 0')
  end subroutine curvature

  subroutine segment()
    real(wp) :: a, b, alpha, ap, am, bp, bm, h, rr, d, hh
    type(status_t) :: st
    integer :: i
    real(wp) :: hs(4) = [0.001_wp, 0.02_wp, 0.3_wp, 0.9_wp]
    rr = 0.5_wp
    ! relative step 1e-4: truncation ~1e-9 relative; (F.1) cancels ~400 eps at h = 1e-3 m,
    ! i.e. 1e-13 of A, which a smaller step would amplify
    d = 1e-4_wp
    do i = 1, size(hs)
      h = hs(i)
      call circle_segment(h, rr, a, b, alpha)
      call check_close(a, rr**2*(alpha - sin(alpha))/2, 1e-12_wp, 0.0_wp, 'segment area R^2 (alpha - sin alpha)/2')
      call check_close(b, 2*rr*sin(alpha/2), 1e-12_wp, 0.0_wp, 'chord b = 2 R sin(alpha/2)')
      call circle_segment(h + d*h, rr, ap, bp, alpha)
      call circle_segment(h - d*h, rr, am, bm, alpha)
      call check_close((ap - am)/(2*d*h), b, 1e-7_wp, 0.0_wp, 'dA/dh = b (F.2)')   ! truncation up to 3e-8 at h = 0.9 m
      call circle_segment(h, rr*(1 + d), ap, bp, alpha)
      call circle_segment(h, rr*(1 - d), am, bm, alpha)
      call circle_segment(h, rr, a, b, alpha)
      call check_close((ap - am)/(2*d*rr), rr*alpha - b, 1e-7_wp, 1e-12_wp, 'dA/dR = R alpha - b (F.3)')
      call circle_height_for_area(a, rr, hh, st)
      call check(st%ok(), 'height from area')
      call check_close(hh, h, 1e-12_wp, 0.0_wp, 'height from area inverts A(h)')
    end do
  end subroutine segment

  !> The profile route (4.45-4.47) applied to a circular tube at the bottom
  !> reproduces the circular segment of radius r; off the bottom too.
  subroutine profile()
    real(wp) :: a, b, vl, vr, aref, bref, alpha
    type(status_t) :: st
    integer :: i
    real(wp) :: hs(3) = [0.005_wp, 0.05_wp, 0.2_wp], vs(3) = [pi/2, 1.2_wp, 2.0_wp]
    do i = 1, 3
      call profile_water(tubes(1), 2.0_wp, vs(i), hs(i), a, b, vl, vr, st)
      call check(st%ok(), 'profile water')
      call circle_segment(hs(i), 0.5_wp, aref, bref, alpha)
      call check_close(a, aref, 1e-12_wp, 0.0_wp, 'profile area = circular segment (F.1)')
      call check_close(b, bref, 1e-12_wp, 0.0_wp, 'profile width = chord')
      call check_close(vl - vr, alpha, 1e-12_wp, 0.0_wp, 'profile edges span the central angle')
      call check_close((vl + vr)/2, vs(i), 1e-12_wp, 0.0_wp, 'edges symmetric about the water point')
    end do
  end subroutine profile
end program test_water_channel
