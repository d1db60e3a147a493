!> The slide query (geometry_slide_query) the rider rides on:
!> - a surface that does not answer it (a plane, an ellipsoid) is refused by
!>   the rider's start check with a message naming the surface and the query;
!> - the tube's answers against closed forms: on a helical tube
!>   c = [rho cos u, rho sin u, -p u] the centerline speed |c_u| =
!>   sqrt(rho^2 + p^2), the arc length |c_u| u, its inverse and the length;
!>   on a straight tube |c_u| = 1; a circular section is closed (edges
!>   +-huge); the wall position's closed form equals the general one.
program test_slide_query
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_elementary, only: plane_t, ellipsoid_t
  use geometry_tube, only: tube_surface_t, new_straight_tube, new_helix_tube
  use geometry_slide_query, only: general_wall_position
  use rider_model, only: rider_params_t
  use rider_ride, only: ride_options_t, check_ride_start
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  type(status_t) :: st
  type(plane_t) :: plane
  type(ellipsoid_t) :: ellipsoid
  type(tube_surface_t) :: helix, straight
  type(rider_params_t) :: params
  type(ride_options_t) :: options
  real(wp), parameter :: rho = 6, pitch = 0.8_wp, u_max = 5
  real(wp) :: speed, u, s, v_min, v_max, a1, d1, a2, d2
  integer :: i

  plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, -0.2_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
  call check_ride_start(params, plane, options, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'is not a slide') > 0 .and. &
             index(st%text(), 'slide query') > 0 .and. index(st%text(), 'plane') > 0, &
             'a plane is refused with the slide query message: '//st%text())
  st = status_t()
  ellipsoid = ellipsoid_t(2.0_wp, 1.0_wp, 1.0_wp, st)
  call check_ride_start(params, ellipsoid, options, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'is not a slide') > 0, &
             'an ellipsoid is refused: '//st%text())

  st = status_t()
  helix = new_helix_tube(0.5_wp, rho, pitch, 1.0_wp, u_max, st)
  if (st%ok()) straight = new_straight_tube(0.5_wp, 0.1_wp, 20.0_wp, st)
  call check(st%ok(), 'tubes built')
  ! rtol 1e-12: |c_u| is one norm; the arc length a quadrature exact for a constant speed
  do i = 0, 4
    u = 0.3_wp + 1.1_wp*i
    call helix%centerline_speed(u, speed, st)
    call check(st%ok(), 'helix: centerline speed evaluated')
    call check_close(speed, sqrt(rho**2 + pitch**2), 1e-14_wp, 0.0_wp, 'helix: |c_u| = sqrt(rho^2 + p^2)')
    call check_close(helix%arc_length(u), sqrt(rho**2 + pitch**2)*u, 1e-12_wp, 0.0_wp, 'helix: s(u) = |c_u| u')
    call helix%parameter_at_length(sqrt(rho**2 + pitch**2)*u, s, st)
    call check(st%ok(), 'helix: u at s')
    call check_close(s, u, 1e-12_wp, 0.0_wp, 'helix: u(s(u)) = u')
    call straight%centerline_speed(2*u, speed, st)
    call check(speed == 1, 'straight tube: |c_u| = 1 (u is arc length)')
    call helix%section_edges(u, v_min, v_max)
    call check(v_min == -huge(1.0_wp) .and. v_max == huge(1.0_wp), 'circular section: closed')
    call helix%wall_position(u, 1.2_wp + 0.2_wp*i, a1, d1, st)
    call general_wall_position(helix, u, 1.2_wp + 0.2_wp*i, a2, d2, st)
    ! 1e-12: the closed form against two unit normals' angle and a 5-point Gauss rule exact here
    call check_close(a1, a2, 1e-12_wp, 1e-14_wp, 'helix: wall angle closed form = general')
    call check_close(d1, d2, 1e-12_wp, 1e-14_wp, 'helix: wall distance closed form = general')
  end do
  call check_close(helix%length(), sqrt(rho**2 + pitch**2)*u_max, 1e-12_wp, 0.0_wp, 'helix: length')
  call finish_tests('test_slide_query')
end program test_slide_query
