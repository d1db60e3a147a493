!> The one foot-point solver (geometry_foot_point) against closed forms, and
!> the one curvature (geometry_curve_frame's curve_curvature):
!> - a point above (and below) a sphere, beside a cylinder, off a plane: the
!>   foot is the closed-form one, with each equation set and stop rule the
!>   callers use (contact search, rider start, water edges);
!> - points near the end of a tube: just inside, the foot; just beyond,
!>   FOOT_LEFT_DOMAIN (domain stop) or a clipped iterate at the edge that
!>   never converges (FOOT_STEP_LIMIT, clip);
!> - a start where Newton cannot run (the ellipsoid's pole: no Darboux frame)
!>   and a start too far for few Newton steps: HYBRJ's fallback finds it;
!> - the support point of an ellipsoid in a direction;
!> - curvature of a circle, a helix and a parabola (chi and chi_u closed
!>   forms), and the zero test on a line and at an inflection.
program test_foot_point
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: plane_t, ellipsoid_t, elliptic_cylinder_t
  use geometry_tube, only: tube_surface_t, new_straight_tube
  use geometry_curve_frame, only: curve_curvature
  use geometry_foot_point, only: foot_point_options_t, foot_point_t, find_foot_point, foot_reason_text, &
    FOOT_TANGENT, FOOT_FRAME, FOOT_SUPPORT, FOOT_STOP_PARAMETER, FOOT_STOP_LENGTH, FOOT_STOP_SCALED, &
    FOOT_DOMAIN_CLIP, FOOT_DOMAIN_STOP, FOOT_DOMAIN_NOTE, FOOT_CONVERGED, FOOT_LEFT_DOMAIN, FOOT_STEP_LIMIT
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! 1e-10: Newton converges quadratically to rounding (steps stop at 1e-14
  ! relative) and HYBRJ to xtol 1e-10 relative; a wrong foot is off by O(1)
  real(wp), parameter :: tol = 1e-10_wp
  real(wp), parameter :: radius = 1.3_wp
  type(status_t) :: st
  type(ellipsoid_t), target :: sphere, ellipsoid
  type(elliptic_cylinder_t), target :: cylinder
  type(plane_t), target :: plane
  type(tube_surface_t), target :: tube
  type(foot_point_options_t) :: rider_like, contact_like, water_like, support
  type(foot_point_t) :: foot
  type(surface_point_t) :: p
  real(wp) :: u, v, x(3), n(3), gram(2, 2), rhs(2), uv(2), h
  integer :: k

  sphere = ellipsoid_t(radius, radius, radius, st)
  ellipsoid = ellipsoid_t(2.0_wp, 1.0_wp, 0.5_wp, st)
  cylinder = elliptic_cylinder_t(radius, radius, st)
  plane = plane_t([0.0_wp, 0.0_wp, 1.0_wp], [1.0_wp, 1.0_wp, 1.0_wp], [-1.0_wp, 2.0_wp, 1.0_wp], st)
  if (st%ok()) tube = new_straight_tube(0.5_wp, 0.0_wp, 10.0_wp, st)
  call check(st%ok(), 'surfaces built')
  if (.not. st%ok()) call finish_tests('test_foot_point')

  ! the three callers' settings (rider_start, contact_surface_search, water_boundaries)
  rider_like = foot_point_options_t(stop_rule=FOOT_STOP_LENGTH, domain_rule=FOOT_DOMAIN_STOP, max_steps=30, &
                                    tolerance=1e-14_wp, require_minimum=.true.)
  contact_like = foot_point_options_t(stop_rule=FOOT_STOP_PARAMETER, domain_rule=FOOT_DOMAIN_CLIP, max_steps=50, &
                                      tolerance=1e-15_wp)
  water_like = foot_point_options_t(equations=FOOT_FRAME, stop_rule=FOOT_STOP_SCALED, domain_rule=FOOT_DOMAIN_NOTE, &
                                    max_steps=8, tolerance=1e-10_wp, residual_tolerance=1e-10_wp, last_step=1e-6_wp, &
                                    fallback=.true.)

  ! sphere: p = (R + h) e(u0, v0) has its foot at (u0, v0), above (h > 0) and below (h < 0)
  do k = 1, 6
    h = merge(0.4_wp, -0.5_wp, mod(k, 2) == 0)
    call sphere_case(0.3_wp + 0.9_wp*k, -1.0_wp + 0.3_wp*k, h, rider_like, 'rider-like')
    call sphere_case(0.3_wp + 0.9_wp*k, -1.0_wp + 0.3_wp*k, h, contact_like, 'contact-like')
    call sphere_case(0.3_wp + 0.9_wp*k, -1.0_wp + 0.3_wp*k, h, water_like, 'water-like')
  end do

  ! cylinder r = [R cos v, R sin v, u]: p = [(R + h) cos v0, (R + h) sin v0, z] -> (z, v0)
  x = [(radius + 0.7_wp)*cos(2.0_wp), (radius + 0.7_wp)*sin(2.0_wp), -0.8_wp]
  u = -0.5_wp; v = 2.3_wp
  call find_foot_point(cylinder, x, u, v, rider_like, foot, st)
  call check(st%ok() .and. foot%reason == FOOT_CONVERGED, 'cylinder: converged ('//foot_reason_text(foot%reason)//')')
  call check_close_array([foot%u, foot%v], [-0.8_wp, 2.0_wp], tol, tol, 'cylinder: foot (z, v0)')

  ! plane: the foot solves the Gram system [e_a.e_b] (u, v) = [e_a.(p - origin)]; Newton is exact in one step
  x = [0.4_wp, -2.0_wp, 3.1_wp]
  call plane%evaluate(0.0_wp, 0.0_wp, 1, p, st)
  gram = reshape([dot_product(p%ru, p%ru), dot_product(p%ru, p%rv), dot_product(p%ru, p%rv), &
                  dot_product(p%rv, p%rv)], [2, 2])
  rhs = [dot_product(p%ru, x - p%r), dot_product(p%rv, x - p%r)]
  uv = [gram(2, 2)*rhs(1) - gram(1, 2)*rhs(2), gram(1, 1)*rhs(2) - gram(2, 1)*rhs(1)]/ &
       (gram(1, 1)*gram(2, 2) - gram(1, 2)*gram(2, 1))
  u = 5; v = -7
  call find_foot_point(plane, x, u, v, contact_like, foot, st)
  call check(st%ok() .and. foot%reason == FOOT_CONVERGED, 'plane: converged')
  call check_close_array([foot%u, foot%v], uv, tol, tol, 'plane: foot = the Gram solution')
  call check(foot%steps <= 2, 'plane: Newton exact in one step (a second one is ~0)')

  ! near the end of a straight tube (u = arc length in [0, 10] m): just inside, the foot
  call tube%evaluate(9.99_wp, 2.0_wp, 1, p, st)
  n = cross(p%ru, p%rv)/norm2(cross(p%ru, p%rv))
  u = 9.5_wp; v = 2.1_wp
  call find_foot_point(tube, p%r + 0.1_wp*n, u, v, rider_like, foot, st)
  call check(st%ok() .and. foot%reason == FOOT_CONVERGED, 'tube end: a point 1 cm before the end converges')
  call check_close_array([foot%u, foot%v], [9.99_wp, 2.0_wp], tol, tol, 'tube end: its foot')
  ! ... 5 cm beyond the end: the domain stop says it left; the clip holds u at the edge without converging
  x = p%r + 0.06_wp*p%ru/norm2(p%ru) + 0.1_wp*n
  u = 9.5_wp; v = 2.1_wp
  call find_foot_point(tube, x, u, v, rider_like, foot, st)
  call check(st%ok() .and. foot%reason == FOOT_LEFT_DOMAIN, 'tube end: beyond it, FOOT_LEFT_DOMAIN ('// &
             foot_reason_text(foot%reason)//')')
  call check(foot%u > 10, 'tube end: the iterate that left lies beyond u_max')
  u = 9.5_wp; v = 2.1_wp
  call find_foot_point(tube, x, u, v, contact_like, foot, st)
  call check(st%ok() .and. foot%reason == FOOT_STEP_LIMIT .and. foot%u == 10, &
             'tube end: clipped to the edge, no convergence (FOOT_STEP_LIMIT)')

  ! the fallback: a start at the ellipsoid's pole (r_u = 0: no Darboux frame, Newton cannot start)
  call ellipsoid%evaluate(0.7_wp, 0.4_wp, 1, p, st)
  n = cross(p%ru, p%rv)/norm2(cross(p%ru, p%rv))
  u = 0.0_wp; v = pi/2
  call find_foot_point(ellipsoid, p%r + 0.05_wp*n, u, v, water_like, foot, st, fallback_start=[0.5_wp, 0.3_wp])
  call check(st%ok() .and. foot%reason == FOOT_CONVERGED .and. foot%by_fallback, &
             'ellipsoid: from the pole Newton cannot run; HYBRJ finds the foot')
  call check_close_array([foot%u, foot%v], [0.7_wp, 0.4_wp], tol, tol, 'ellipsoid: the fallback''s foot')
  call check_close_array(foot%point, p%r, tol, tol, 'ellipsoid: the fallback''s point')
  ! ... and Newton allowed one step from a start 0.6 rad away does not converge: HYBRJ does
  water_like%max_steps = 1
  u = 0.1_wp; v = 0.1_wp
  call find_foot_point(ellipsoid, p%r + 0.05_wp*n, u, v, water_like, foot, st)
  call check(st%ok() .and. foot%by_fallback, 'ellipsoid: one Newton step is not enough; the fallback converges')
  call check_close_array([foot%u, foot%v], [0.7_wp, 0.4_wp], tol, tol, 'ellipsoid: that foot')

  ! support point of the ellipsoid [2 cos v cos u, cos v sin u, 0.5 sin v] in direction d:
  ! min d.r at r = -A^2 d/|A d| (A = diag(a, b, c)), i.e. u = 3 pi/2 for d = +y
  support = contact_like
  support%equations = FOOT_SUPPORT
  u = 4.5_wp; v = 0.2_wp
  call find_foot_point(ellipsoid, [0.0_wp, 1.0_wp, 0.0_wp], u, v, support, foot, st)
  call ellipsoid%evaluate(foot%u, foot%v, 0, p, st)
  call check(foot%reason == FOOT_CONVERGED, 'ellipsoid support point: converged')
  call check_close_array(p%r, [0.0_wp, -1.0_wp, 0.0_wp], tol, tol, 'ellipsoid support point in +y: [0, -b, 0]')

  call curvature_cases()
  call finish_tests('test_foot_point')

contains

  subroutine sphere_case(u0, v0, h, options, name)
    real(wp), intent(in) :: u0, v0, h
    type(foot_point_options_t), intent(in) :: options
    character(len=*), intent(in) :: name
    real(wp) :: e(3), uu, vv
    e = [cos(v0)*cos(u0), cos(v0)*sin(u0), sin(v0)]
    uu = u0 + 0.25_wp; vv = v0 - 0.2_wp
    call find_foot_point(sphere, (radius + h)*e, uu, vv, options, foot, st)
    call check(st%ok() .and. foot%reason == FOOT_CONVERGED, 'sphere, '//name//': converged ('// &
               foot_reason_text(foot%reason)//')')
    call check_close_array([foot%u, foot%v], [u0, v0], tol, tol, 'sphere, '//name//': foot (u0, v0)')
    call sphere%evaluate(foot%u, foot%v, 0, p, st)
    call check_close(norm2((radius + h)*e - p%r), abs(h), tol, tol, 'sphere, '//name//': distance |h|')
  end subroutine sphere_case

  !> chi, chi_u of closed-form curves; d(:, k) = d^k c/du^k.
  subroutine curvature_cases()
    real(wp) :: d(3, 0:3), chi, chi_u, rr, cc, t
    integer :: i
    ! circle of radius 2 by angle: chi = 1/2, chi_u = 0
    t = 0.7_wp; rr = 2
    d(:, 0) = rr*[cos(t), sin(t), 0.0_wp]; d(:, 1) = rr*[-sin(t), cos(t), 0.0_wp]
    d(:, 2) = -d(:, 0); d(:, 3) = -d(:, 1)
    call curve_curvature(d, 3, chi, chi_u)
    ! 1e-14: a few roundings of O(1) numbers
    call check_close(chi, 1/rr, 1e-14_wp, 0.0_wp, 'circle: chi = 1/R')
    call check_close(chi_u, 0.0_wp, 0.0_wp, 1e-14_wp, 'circle: chi_u = 0')
    ! helix [R cos u, R sin u, c u]: chi = R/(R^2 + c^2), chi_u = 0
    rr = 1.5_wp; cc = 0.4_wp
    d(:, 0) = [rr*cos(t), rr*sin(t), cc*t]; d(:, 1) = [-rr*sin(t), rr*cos(t), cc]
    d(:, 2) = [-rr*cos(t), -rr*sin(t), 0.0_wp]; d(:, 3) = [rr*sin(t), -rr*cos(t), 0.0_wp]
    call curve_curvature(d, 3, chi, chi_u)
    call check_close(chi, rr/(rr**2 + cc**2), 1e-14_wp, 0.0_wp, 'helix: chi = R/(R^2 + c^2)')
    call check_close(chi_u, 0.0_wp, 0.0_wp, 1e-14_wp, 'helix: chi_u = 0')
    ! parabola [u, u^2, 0]: chi = 2/(1 + 4u^2)^(3/2), chi_u = -24 u/(1 + 4u^2)^(5/2) (varying: tests (4.9))
    do i = -2, 2
      t = 0.35_wp*i + 0.1_wp
      d(:, 0) = [t, t**2, 0.0_wp]; d(:, 1) = [1.0_wp, 2*t, 0.0_wp]
      d(:, 2) = [0.0_wp, 2.0_wp, 0.0_wp]; d(:, 3) = 0
      call curve_curvature(d, 3, chi, chi_u)
      call check_close(chi, 2/(1 + 4*t**2)**1.5_wp, 1e-14_wp, 0.0_wp, 'parabola: chi')
      call check_close(chi_u, -24*t/(1 + 4*t**2)**2.5_wp, 1e-13_wp, 1e-15_wp, 'parabola: chi_u (4.9)')
      call curve_curvature(d, 2, chi, chi_u)
      call check(chi_u == 0, 'order 2: no chi_u')
    end do
    ! the zero test: a line, an inflection (cubic [u, u^3, 0] at 0) and a radius of 1e15 m
    d = 0; d(:, 1) = [0.6_wp, 0.0_wp, -0.8_wp]
    call curve_curvature(d, 3, chi, chi_u)
    call check(chi == 0 .and. chi_u == 0, 'line: chi = chi_u = 0')
    d = 0; d(:, 1) = [1.0_wp, 0.0_wp, 0.0_wp]; d(:, 3) = [0.0_wp, 6.0_wp, 0.0_wp]
    call curve_curvature(d, 3, chi, chi_u)
    call check(chi == 0 .and. chi_u == 0, 'inflection: chi = 0, chi_u = 0 (|c'' x c''''| has a kink)')
    d(:, 2) = [0.0_wp, 1e-15_wp, 0.0_wp]
    call curve_curvature(d, 3, chi, chi_u)
    call check(chi == 1e-15_wp .and. chi_u == 0, 'radius 1e15 m: below the zero test, chi_u = 0')
    d(:, 2) = [0.0_wp, 1e-13_wp, 0.0_wp]
    call curve_curvature(d, 3, chi, chi_u)
    call check(chi_u /= 0, 'radius 1e13 m: above the zero test, chi_u from (4.9)')
  end subroutine curvature_cases
end program test_foot_point
