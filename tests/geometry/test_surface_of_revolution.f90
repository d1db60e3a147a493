!> Surfaces of revolution (geometry_revolution) and the sphere kind
!> (geometry_sphere):
!>   - every partial to third order against central differences of the order
!>     below at scattered points, for the cone, the sphere zone and profiles
!>     through points (quintic: to third order; cubic: to second, its third
!>     derivative jumps at the knots);
!>   - the sphere zone is the sphere (3.57) point for point; a quintic profile
!>     through 13 points of a circle is that sphere zone to 1e-6 of its radius
!>     (interpolation error ~ h^6 |r^(6)|: (0.13)^6 ~ 5e-6 R at most, 1e-6
!>     between the points of a uniform spacing);
!>   - a profile that reaches the axis (a pole) is refused, saying so;
!>   - the sphere kind is the ellipsoid a = b = c: the same numbers and the
!>     same pole charts;
!>   - the kinds are built from specs by the registry (surface_from_spec).
program test_surface_of_revolution
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use base_spec, only: spec_t
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: ellipsoid_t
  use geometry_sphere, only: sphere_t, new_sphere
  use geometry_revolution, only: revolution_t, new_cone, new_sphere_zone, new_profile_revolution
  use geometry_surface_factory, only: surface_from_spec
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences: truncation h^2/6 |f'''| ~ 2e-11 S, rounding eps |f|/h
  ! ~ 2e-11 S (S the size of the partials, a few m here); 1e-7 S keeps a
  ! factor > 100 of margin while a wrong term (error ~ S) fails.
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  integer, parameter :: n_points = 12
  type(status_t) :: st
  type(revolution_t) :: cone, zone, quintic, cubic, circle
  real(wp), allocatable :: rho(:), z(:), phi(:)
  integer :: i

  cone = new_cone(0.5_wp, 0.2_wp, 2.0_wp, st)
  call check(st%ok(), 'cone built: '//st%text())
  call check_partials(cone, 0.0_wp, two_pi, 0.2_wp, 2.0_wp, 3, 'cone')
  zone = new_sphere_zone(1.5_wp, -1.2_wp, 0.9_wp, st)
  call check(st%ok(), 'sphere zone built: '//st%text())
  call check_partials(zone, 0.0_wp, two_pi, -1.2_wp, 0.9_wp, 3, 'sphere zone')
  ! a bowl with a lip: rho and z both turn (not a graph z(rho))
  rho = [0.3_wp, 0.5_wp, 0.8_wp, 1.0_wp, 1.1_wp, 1.05_wp, 0.95_wp]
  z = [0.0_wp, 0.05_wp, 0.25_wp, 0.55_wp, 0.9_wp, 1.1_wp, 1.2_wp]
  quintic = new_profile_revolution(rho, z, st)
  call check(st%ok(), 'quintic profile built: '//st%text())
  call check_partials(quintic, 0.0_wp, two_pi, 0.0_wp, 1.5_wp, 3, 'quintic profile')
  cubic = new_profile_revolution(rho(1:5), z(1:5), st)
  call check(st%ok(), 'cubic profile built: '//st%text())
  call check_partials(cubic, 0.0_wp, two_pi, 0.0_wp, 1.0_wp, 2, 'cubic profile')

  call zone_is_sphere()
  phi = [(-1.2_wp + 2.1_wp*i/12, i = 0, 12)]
  circle = new_profile_revolution(1.5_wp*cos(phi), 1.5_wp*sin(phi), st)
  call check(st%ok(), 'profile on a circle built: '//st%text())
  call profile_on_circle()
  call refusals()
  call sphere_is_ellipsoid()
  call from_specs()
  call finish_tests('test_surface_of_revolution')

contains

  subroutine check_partials(s, u0, u1, v0, v1, top, name)
    class(surface_t), intent(in) :: s
    real(wp), intent(in) :: u0, u1, v0, v1
    integer, intent(in) :: top   ! highest order checked
    character(len=*), intent(in) :: name
    type(surface_point_t) :: p, up, um, vp, vm
    type(status_t) :: st
    real(wp) :: u, v, scale
    integer :: k
    character(len=80) :: at
    do k = 1, n_points
      u = u0 + (u1 - u0)*modulo(0.1_wp + k*0.6180339887498949_wp, 1.0_wp)
      v = v0 + (v1 - v0)*(0.02_wp + 0.96_wp*modulo(0.3_wp + k*0.7548776662466927_wp, 1.0_wp))
      write (at, '(a, 2es12.4, a)') ' at (u, v) = (', u, v, ')'
      call s%evaluate(u, v, 3, p, st)
      call check(st%ok() .and. p%order == 3, name//' evaluate'//trim(at))
      call s%evaluate(u + h, v, 3, up, st)
      call s%evaluate(u - h, v, 3, um, st)
      call s%evaluate(u, v + h, 3, vp, st)
      call s%evaluate(u, v - h, 3, vm, st)
      scale = 1 + max(norm2(p%r), norm2(p%ru), norm2(p%rv), norm2(p%ruu), norm2(p%ruv), norm2(p%rvv))
      if (top >= 3) scale = max(scale, 1 + max(norm2(p%ruuu), norm2(p%ruuv), norm2(p%ruvv), norm2(p%rvvv)))
      call close3(p%ru, (up%r - um%r)/(2*h), scale, name//' r_u'//trim(at))
      call close3(p%rv, (vp%r - vm%r)/(2*h), scale, name//' r_v'//trim(at))
      call close3(p%ruu, (up%ru - um%ru)/(2*h), scale, name//' r_uu'//trim(at))
      call close3(p%ruv, (vp%ru - vm%ru)/(2*h), scale, name//' r_uv from r_u'//trim(at))
      call close3(p%ruv, (up%rv - um%rv)/(2*h), scale, name//' r_uv from r_v'//trim(at))
      call close3(p%rvv, (vp%rv - vm%rv)/(2*h), scale, name//' r_vv'//trim(at))
      if (top < 3) cycle
      call close3(p%ruuu, (up%ruu - um%ruu)/(2*h), scale, name//' r_uuu'//trim(at))
      call close3(p%ruuv, (vp%ruu - vm%ruu)/(2*h), scale, name//' r_uuv from r_uu'//trim(at))
      call close3(p%ruuv, (up%ruv - um%ruv)/(2*h), scale, name//' r_uuv from r_uv'//trim(at))
      call close3(p%ruvv, (vp%ruv - vm%ruv)/(2*h), scale, name//' r_uvv from r_uv'//trim(at))
      call close3(p%ruvv, (up%rvv - um%rvv)/(2*h), scale, name//' r_uvv from r_vv'//trim(at))
      call close3(p%rvvv, (vp%rvv - vm%rvv)/(2*h), scale, name//' r_vvv'//trim(at))
    end do
  end subroutine check_partials

  subroutine close3(x, ref, scale, what)
    real(wp), intent(in) :: x(3), ref(3), scale
    character(len=*), intent(in) :: what
    call check_close_array(x, ref, 0.0_wp, fd_tol*scale, what)
  end subroutine close3

  !> The zone's (u, v) is the sphere's (3.57) (u, v): the same point, to rounding.
  subroutine zone_is_sphere()
    type(surface_point_t) :: p
    real(wp) :: u, v, worst
    integer :: k
    worst = 0
    do k = 1, n_points
      u = two_pi*modulo(0.1_wp + k*0.618_wp, 1.0_wp)
      v = -1.2_wp + 2.1_wp*modulo(0.3_wp + k*0.755_wp, 1.0_wp)
      call zone%evaluate(u, v, 0, p, st)
      worst = max(worst, norm2(p%r - 1.5_wp*[cos(v)*cos(u), cos(v)*sin(u), sin(v)]))
    end do
    call check(worst <= 1e-15_wp, 'sphere zone: the sphere of radius 1.5 m point for point')
  end subroutine zone_is_sphere

  !> The quintic through 13 points of the circle is the zone: points, and the
  !> unit normal, between the points (the chord parameter is the arc to
  !> (h/R)^2/24 ~ 1e-4 relative, so compare positions by nearest latitude).
  subroutine profile_on_circle()
    type(surface_point_t) :: p
    real(wp) :: v, worst_r, worst_n, n(3), lat
    integer :: k
    worst_r = 0
    worst_n = 0
    do k = 0, 100
      v = 0.01_wp*k*circle_length()
      call circle%evaluate(0.7_wp, v, 1, p, st)
      worst_r = max(worst_r, abs(norm2(p%r) - 1.5_wp))
      n = cross(p%ru, p%rv)
      n = n/norm2(n)
      lat = asin(p%r(3)/norm2(p%r))
      worst_n = max(worst_n, norm2(n - [cos(lat)*cos(0.7_wp), cos(lat)*sin(0.7_wp), sin(lat)]))
    end do
    call check_close(worst_r, 0.0_wp, 0.0_wp, 1.5e-6_wp, 'profile on a circle: |r| = R between the points (m)')
    call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-4_wp, 'profile on a circle: the normal is the sphere''s')
  end subroutine profile_on_circle

  real(wp) function circle_length() result(length)
    real(wp) :: u_min, u_max, v_min, v_max
    call circle%domain(u_min, u_max, v_min, v_max)
    length = v_max
  end function circle_length

  pure function cross(a, b) result(c)
    real(wp), intent(in) :: a(3), b(3)
    real(wp) :: c(3)
    c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
  end function cross

  !> A profile on the axis is a pole: refused, saying so.
  subroutine refusals()
    type(revolution_t) :: s
    s = new_cone(0.5_wp, 0.0_wp, 1.0_wp, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'pole') > 0, 'cone to its apex: '//st%text())
    s = new_sphere_zone(1.0_wp, -pi/2, 0.5_wp, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'pole') > 0, &
               'sphere zone to its pole: '//st%text())
    s = new_profile_revolution([0.0_wp, 0.5_wp, 1.0_wp, 1.2_wp], [0.0_wp, 0.1_wp, 0.4_wp, 0.8_wp], st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'rho = 0') > 0, &
               'profile from the axis: '//st%text())
    ! the points stay off the axis, the interpolant between them does not
    s = new_profile_revolution([0.3_wp, 0.02_wp, 0.02_wp, 0.3_wp, 0.6_wp], [0.0_wp, 0.3_wp, 0.6_wp, 0.9_wp, 1.0_wp], st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'reaches the axis') > 0, &
               'a spline through the axis: '//st%text())
    s = new_profile_revolution([0.3_wp, 0.5_wp, 1.0_wp], [0.0_wp, 0.1_wp, 0.4_wp], st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'at least 4') > 0, &
               'three points: '//st%text())
  end subroutine refusals

  !> The sphere is the ellipsoid a = b = c: the same partials, the same charts.
  subroutine sphere_is_ellipsoid()
    type(sphere_t) :: sphere
    type(ellipsoid_t) :: ellipsoid
    type(surface_point_t) :: p, q
    class(surface_t), allocatable :: chart_s, chart_e
    real(wp) :: ps(3, 3), pe(3, 3), u, v
    integer :: k
    logical :: same
    sphere = new_sphere(0.25_wp, st)
    ellipsoid = ellipsoid_t(0.25_wp, 0.25_wp, 0.25_wp, st)
    same = .true.
    do k = 1, n_points
      u = two_pi*modulo(0.1_wp + k*0.618_wp, 1.0_wp)
      v = -1.5_wp + 3.0_wp*modulo(0.3_wp + k*0.755_wp, 1.0_wp)
      call sphere%evaluate(u, v, 3, p, st)
      call ellipsoid%evaluate(u, v, 3, q, st)
      same = same .and. all(p%r == q%r) .and. all(p%ru == q%ru) .and. all(p%rvv == q%rvv) .and. &
             all(p%rvvv == q%rvvv) .and. sphere%chart_margin(v) == ellipsoid%chart_margin(v)
    end do
    call check(same, 'sphere: the partials and chart margins of the ellipsoid a = b = c, bit for bit')
    call check(sphere%has_charts(), 'sphere: has the ellipsoid''s pole charts')
    call check(sphere%chart_toward([0.0_wp, 0.01_wp, 0.25_wp]) == ellipsoid%chart_toward([0.0_wp, 0.01_wp, 0.25_wp]), &
               'sphere: near its pole it names the chart the ellipsoid names')
    call sphere%chart(1, chart_s, ps)
    call ellipsoid%chart(1, chart_e, pe)
    call chart_s%evaluate(0.3_wp, 0.2_wp, 2, p, st)
    call chart_e%evaluate(0.3_wp, 0.2_wp, 2, q, st)
    call check(all(ps == pe) .and. all(p%r == q%r) .and. all(p%ruv == q%ruv), 'sphere: its chart 1 is the ellipsoid''s')
    call check(sphere%describe() == 'sphere radius = 0.25 m', 'sphere: describe "'//sphere%describe()//'"')
  end subroutine sphere_is_ellipsoid

  !> The registry builds the kinds from specs (and checks them).
  subroutine from_specs()
    type(spec_t) :: spec
    class(surface_t), allocatable :: s
    type(surface_point_t) :: p, q
    st = status_t()
    spec%kind = 'cone'
    call spec%set('half_angle_deg', [0.5_wp*180/pi])
    call spec%set('z_min', [0.2_wp])
    call spec%set('z_max', [2.0_wp])
    call surface_from_spec(spec, s, st)
    call check(st%ok(), 'cone from its spec: '//st%text())
    if (st%ok()) then
      call s%evaluate(1.0_wp, 1.3_wp, 3, p, st)
      call cone%evaluate(1.0_wp, 1.3_wp, 3, q, st)
      call check_close_array(p%rvv, q%rvv, 1e-15_wp, 1e-15_wp, 'cone from its spec: the cone')
      call check_close_array(p%r, q%r, 1e-15_wp, 1e-15_wp, 'cone from its spec: r')
    end if
    spec = spec_t('revolution')
    call spec%set('profile_rho', [0.3_wp, 0.5_wp, 0.8_wp, 1.0_wp])
    call spec%set('profile_z', [0.0_wp, 0.05_wp, 0.25_wp])
    st = status_t()
    call surface_from_spec(spec, s, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'one z per rho') > 0, &
               'a profile with fewer z than rho: '//st%text())
    spec = spec_t('sphere_zone')
    call spec%set('latitude_min_deg', [-30.0_wp])
    call spec%set('latitude_max_deg', [30.0_wp])
    st = status_t()
    call surface_from_spec(spec, s, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'needs radius') > 0, &
               'a sphere zone without its radius: '//st%text())
  end subroutine from_specs
end program test_surface_of_revolution
