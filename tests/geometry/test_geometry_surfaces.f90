!> Elementary and placed surfaces: partial derivatives to third order against
!> central differences of the next-lower order at scattered points, the
!> order/zero-fill contract, domains, constructor validation, and the chart
!> hooks (a surface without charts keeps its one; an ellipsoid's pole charts
!> are the same surface turned, and chart_parameters inverts evaluate).
program test_geometry_surfaces
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use base_constants, only: pi, half_pi, two_pi
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t, &
                                 apex_paraboloid_t
  use geometry_placed_surface, only: placed_surface_t
  use base_vector, only: rotation_xyz
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central difference step and tolerance. The truncation error of a central
  ! difference is h^2/6 |f'''| ~ 2e-11 S and the rounding error eps |f|/h ~ 2e-11 S,
  ! S the size of the partials near the point (at most ~10 m here); 1e-7 S
  ! keeps a factor > 100 of margin while any wrong term (error ~ S) fails.
  real(wp), parameter :: h = 1e-5_wp
  real(wp), parameter :: fd_tol = 1e-7_wp
  integer, parameter :: n_points = 12

  type(status_t) :: status
  type(plane_t) :: plane
  type(ellipsoid_t) :: ellipsoid
  type(paraboloid_t) :: elliptic, hyperbolic
  type(elliptic_cylinder_t) :: cylinder
  type(apex_paraboloid_t) :: apex
  type(placed_surface_t) :: placed_ellipsoid, placed_apex

  plane = plane_t([1.0_wp, -2.0_wp, 0.5_wp], [3.0_wp, -1.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 2.0_wp], status)
  call check(status%ok(), 'plane constructor: ' // status%text())
  ellipsoid = ellipsoid_t(3.0_wp, 2.0_wp, 1.5_wp, status)
  call check(status%ok(), 'ellipsoid constructor: ' // status%text())
  elliptic = paraboloid_t(2.0_wp, 1.5_wp, 1.0_wp, status)
  call check(status%ok(), 'elliptic paraboloid constructor: ' // status%text())
  hyperbolic = paraboloid_t(1.2_wp, 2.5_wp, -1.0_wp, status)
  call check(status%ok(), 'hyperbolic paraboloid constructor: ' // status%text())
  cylinder = elliptic_cylinder_t(1.5_wp, 0.8_wp, status)
  call check(status%ok(), 'cylinder constructor: ' // status%text())
  apex = apex_paraboloid_t(1.3_wp, 0.7_wp, status)
  call check(status%ok(), 'apex paraboloid constructor: ' // status%text())

  call check_partials(plane, -3.0_wp, 3.0_wp, -3.0_wp, 3.0_wp, 'plane')
  call check_partials(ellipsoid, 0.0_wp, two_pi, -1.5_wp, 1.5_wp, 'ellipsoid')
  call check_partials(elliptic, -2.0_wp, 2.0_wp, -2.0_wp, 2.0_wp, 'elliptic paraboloid')
  call check_partials(hyperbolic, -2.0_wp, 2.0_wp, -2.0_wp, 2.0_wp, 'hyperbolic paraboloid')
  call check_partials(cylinder, -3.0_wp, 3.0_wp, 0.0_wp, two_pi, 'elliptic cylinder')
  call check_partials(apex, 0.0_wp, two_pi, -1.5_wp, 1.5_wp, 'apex paraboloid')

  placed_ellipsoid = placed_surface_t(ellipsoid, [1.0_wp, -2.0_wp, 3.0_wp], status, &
                                      angles=[0.3_wp, -0.7_wp, 1.1_wp])
  call check(status%ok(), 'placed ellipsoid constructor: ' // status%text())
  placed_apex = placed_surface_t(apex, [0.5_wp, 0.0_wp, -1.0_wp], status, &
                                 rotation=rotation_xyz([-0.2_wp, 0.4_wp, 2.5_wp]))
  call check(status%ok(), 'placed apex paraboloid constructor: ' // status%text())
  call check_partials(placed_ellipsoid, 0.0_wp, two_pi, -1.5_wp, 1.5_wp, 'placed ellipsoid')
  call check_partials(placed_apex, 0.0_wp, two_pi, -1.5_wp, 1.5_wp, 'placed apex paraboloid')
  call check_placed()

  call check_order_contract()
  call check_shapes()
  call check_domains()
  call check_charts()
  call check_invalid_input()

  call finish_tests('test_geometry_surfaces')

contains

  !> Compares every partial of order k = 1..3 with the central difference of an
  !> order k-1 partial, in u and in v (mixed partials both ways), at n_points
  !> points scattered over [u0, u1] x [v0, v1] (golden-ratio sequences).
  subroutine check_partials(s, u0, u1, v0, v1, name)
    class(surface_t), intent(in) :: s
    real(wp), intent(in) :: u0, u1, v0, v1
    character(len=*), intent(in) :: name
    type(surface_point_t) :: p, up, um, vp, vm
    type(status_t) :: st
    real(wp) :: u, v, scale
    integer :: k
    character(len=80) :: at
    do k = 1, n_points
      u = u0 + (u1 - u0)*modulo(0.1_wp + k*0.6180339887498949_wp, 1.0_wp)
      v = v0 + (v1 - v0)*modulo(0.3_wp + k*0.7548776662466927_wp, 1.0_wp)
      write (at, '(a, 2es12.4, a)') ' at (u, v) = (', u, v, ')'
      call s%evaluate(u, v, 3, p, st)
      call check(st%ok() .and. p%order == 3, name // ' evaluate' // trim(at))
      call s%evaluate(u + h, v, 3, up, st)
      call s%evaluate(u - h, v, 3, um, st)
      call s%evaluate(u, v + h, 3, vp, st)
      call s%evaluate(u, v - h, 3, vm, st)
      scale = 1 + max(norm2(p%r), norm2(p%ru), norm2(p%rv), norm2(p%ruu), norm2(p%ruv), &
                      norm2(p%rvv), norm2(p%ruuu), norm2(p%ruuv), norm2(p%ruvv), norm2(p%rvvv))
      call close3(p%ru, (up%r - um%r)/(2*h), scale, name // ' r_u' // trim(at))
      call close3(p%rv, (vp%r - vm%r)/(2*h), scale, name // ' r_v' // trim(at))
      call close3(p%ruu, (up%ru - um%ru)/(2*h), scale, name // ' r_uu' // trim(at))
      call close3(p%ruv, (vp%ru - vm%ru)/(2*h), scale, name // ' r_uv from r_u' // trim(at))
      call close3(p%ruv, (up%rv - um%rv)/(2*h), scale, name // ' r_uv from r_v' // trim(at))
      call close3(p%rvv, (vp%rv - vm%rv)/(2*h), scale, name // ' r_vv' // trim(at))
      call close3(p%ruuu, (up%ruu - um%ruu)/(2*h), scale, name // ' r_uuu' // trim(at))
      call close3(p%ruuv, (vp%ruu - vm%ruu)/(2*h), scale, name // ' r_uuv from r_uu' // trim(at))
      call close3(p%ruuv, (up%ruv - um%ruv)/(2*h), scale, name // ' r_uuv from r_uv' // trim(at))
      call close3(p%ruvv, (vp%ruv - vm%ruv)/(2*h), scale, name // ' r_uvv from r_uv' // trim(at))
      call close3(p%ruvv, (up%rvv - um%rvv)/(2*h), scale, name // ' r_uvv from r_vv' // trim(at))
      call close3(p%rvvv, (vp%rvv - vm%rvv)/(2*h), scale, name // ' r_vvv' // trim(at))
    end do
  end subroutine check_partials

  subroutine close3(x, ref, scale, what)
    real(wp), intent(in) :: x(3), ref(3), scale
    character(len=*), intent(in) :: what
    call check_close_array(x, ref, 0.0_wp, fd_tol*scale, what)
  end subroutine close3

  !> Order k fills r and the partials up to k and leaves the rest zero;
  !> an order outside 0..3 is an error.
  !> The chart hooks (geometry_surface): the default has one chart and keeps
  !> it; each of an ellipsoid's three charts is the ellipsoid turned by P
  !> (its point r' at (u, v) is the ellipsoid's point P r', to rounding),
  !> chart_parameters gives back (u, v) of a point (v to rounding 1e-9 rad
  !> from a pole, u there to 1e-6: r_u ~ 1e-9), chart_toward picks the
  !> axis along which the point lies least far out, and the margin is
  !> cos v - cos 1.4 (zero at |v| = 1.4 rad).
  subroutine check_charts()
    class(surface_t), allocatable :: turned
    type(surface_point_t) :: p, q
    type(status_t) :: st
    real(wp) :: rot(3, 3), u, v
    integer :: k
    call check(.not. plane%has_charts() .and. plane%chart_margin(1.5_wp) > 0 .and. &
               plane%chart_toward([1.0_wp, 0.0_wp, 0.0_wp]) == 0, 'a plane has one chart, never left')
    call plane%chart(2, turned, rot)
    call check(same_type_as(turned, plane) .and. all(rot == reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])), &
               'the default chart is the surface itself')
    call plane%chart_parameters([1.0_wp, 2.0_wp, 3.0_wp], u, v, st)
    call check(.not. st%ok(), 'a surface without charts refuses chart_parameters')
    call check(ellipsoid%has_charts(), 'an ellipsoid has charts')
    call check_close(ellipsoid%chart_margin(1.4_wp), 0.0_wp, 0.0_wp, 1e-15_wp, 'the chart edge at |v| = 1.4')
    call check(ellipsoid%chart_margin(-1.3_wp) > 0 .and. ellipsoid%chart_margin(1.5_wp) < 0, &
               'the margin is positive inside the chart, negative beyond')
    call check(ellipsoid%chart_toward([0.1_wp, 1.9_wp, 0.3_wp]) == 1 .and. &
               ellipsoid%chart_toward([2.9_wp, 0.1_wp, 0.2_wp]) == 2 .and. &
               ellipsoid%chart_toward([0.3_wp, 0.5_wp, 1.4_wp]) == 1, 'chart_toward: the axis of least |r_i|/a_i')
    do k = 1, 3
      call ellipsoid%chart(k, turned, rot)
      call turned%evaluate(0.7_wp, -0.4_wp, 0, p, st)
      call turned%chart_parameters(p%r, u, v, st)
      call check(st%ok(), 'chart_parameters of an ellipsoid')
      call check_close(u, 0.7_wp, 0.0_wp, 1e-14_wp, 'chart_parameters gives back u')
      call check_close(v, -0.4_wp, 0.0_wp, 1e-14_wp, 'chart_parameters gives back v')
      call ellipsoid%chart_parameters(matmul(rot, p%r), u, v, st)
      call ellipsoid%evaluate(u, v, 0, q, st)
      call check_close_array(q%r, matmul(rot, p%r), 0.0_wp, 1e-14_wp, 'a chart''s point is the ellipsoid''s, turned')
      call check_close(rot(k, 3), 1.0_wp, 0.0_wp, 0.0_wp, 'chart k has its poles on axis k')
      ! 1e-9 rad from a pole: v to rounding (asin(z/c) there is off by ~1e-8)
      call turned%evaluate(0.7_wp, pi/2 - 1e-9_wp, 0, p, st)
      call turned%chart_parameters(p%r, u, v, st)
      call check(abs(v - (pi/2 - 1e-9_wp)) <= 1e-15_wp .and. abs(u - 0.7_wp) <= 1e-6_wp, &
                 'chart_parameters near a pole gives back v to rounding')
    end do
  end subroutine check_charts

  subroutine check_order_contract()
    type(surface_point_t) :: p
    type(status_t) :: st
    call ellipsoid%evaluate(0.4_wp, 0.3_wp, 1, p, st)
    call check(st%ok() .and. p%order == 1, 'order 1 evaluates')
    call check(norm2(p%ru) > 0 .and. norm2(p%rv) > 0, 'order 1 fills r_u, r_v')
    call check(all([p%ruu, p%ruv, p%rvv, p%ruuu, p%ruuv, p%ruvv, p%rvvv] == 0), &
               'order 1 leaves second and third partials zero')
    call ellipsoid%evaluate(0.4_wp, 0.3_wp, 2, p, st)
    call check(norm2(p%ruu) > 0 .and. all([p%ruuu, p%ruuv, p%ruvv, p%rvvv] == 0), &
               'order 2 fills second, not third partials')
    call ellipsoid%evaluate(0.4_wp, 0.3_wp, 0, p, st)
    call check(st%ok() .and. norm2(p%r) > 0 .and. all(p%ru == 0), 'order 0 fills r only')
    call ellipsoid%evaluate(0.4_wp, 0.3_wp, 4, p, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'order = 4') > 0, &
               'order 4 is refused naming the value: ' // st%text())
    call apex%evaluate(0.4_wp, 0.3_wp, -1, p, st)
    call check(st%code == STATUS_INVALID_INPUT, 'order -1 is refused')
  end subroutine check_order_contract

  !> Closed-form shapes: the points lie on the implicit surfaces, the plane
  !> passes through A, B, C, and the apex paraboloid is the shape of (3.58).
  subroutine check_shapes()
    type(surface_point_t) :: p
    type(status_t) :: st
    real(wp) :: x(3)
    integer :: k
    ! rtol 1e-14: a few roundings of O(1) numbers
    call plane%evaluate(0.0_wp, 0.0_wp, 0, p, st)
    call check_close_array(p%r, [1.0_wp, -2.0_wp, 0.5_wp], 1e-14_wp, 1e-14_wp, 'plane passes through A')
    call plane%evaluate(norm2([2.0_wp, 1.0_wp, -0.5_wp]), 0.0_wp, 0, p, st)
    call check_close_array(p%r, [3.0_wp, -1.0_wp, 0.0_wp], 1e-14_wp, 1e-14_wp, 'plane passes through B')
    call plane%evaluate(0.0_wp, norm2([-1.0_wp, 3.0_wp, 1.5_wp]), 0, p, st)
    call check_close_array(p%r, [0.0_wp, 1.0_wp, 2.0_wp], 1e-14_wp, 1e-14_wp, 'plane passes through C')
    do k = 1, n_points
      call ellipsoid%evaluate(0.7_wp*k, -1.4_wp + 0.25_wp*k, 0, p, st)
      x = p%r
      call check_close((x(1)/3)**2 + (x(2)/2)**2 + (x(3)/1.5_wp)**2, 1.0_wp, 1e-14_wp, 0.0_wp, &
                       'ellipsoid point on x^2/a^2 + y^2/b^2 + z^2/c^2 = 1')
      call apex%evaluate(0.7_wp*k, -1.4_wp + 0.25_wp*k, 0, p, st)
      x = p%r
      call check_close(x(3), (x(1)/1.3_wp)**2 + (x(2)/0.7_wp)**2, 1e-14_wp, 1e-15_wp, &
                       'apex paraboloid point on z = x^2/a^2 + y^2/b^2')
      call cylinder%evaluate(0.7_wp*k, 0.5_wp*k, 0, p, st)
      x = p%r
      call check_close((x(1)/1.5_wp)**2 + (x(2)/0.8_wp)**2, 1.0_wp, 1e-14_wp, 0.0_wp, &
                       'cylinder point on x^2/a^2 + y^2/b^2 = 1')
    end do
    call hyperbolic%evaluate(0.5_wp, 0.0_wp, 0, p, st)
    call check(p%r(3) < 0, 'hyperbolic paraboloid: c = -1 bends down along u')
    call hyperbolic%evaluate(0.0_wp, 0.5_wp, 0, p, st)
    call check(p%r(3) > 0, 'hyperbolic paraboloid: bends up along v')
  end subroutine check_shapes

  subroutine check_domains()
    real(wp) :: u_min, u_max, v_min, v_max
    call ellipsoid%domain(u_min, u_max, v_min, v_max)
    call check(u_min == 0 .and. u_max == two_pi .and. v_min == -half_pi .and. v_max == half_pi, &
               'ellipsoid domain [0, 2 pi] x [-pi/2, pi/2]')
    call check(ellipsoid%periodic_u() .and. .not. ellipsoid%periodic_v(), 'ellipsoid periodic in u only')
    call check(ellipsoid%in_domain(10.0_wp, 1.0_wp), 'ellipsoid: any u is inside (periodic)')
    call check(.not. ellipsoid%in_domain(1.0_wp, 1.6_wp), 'ellipsoid: v > pi/2 is outside')
    call check(ellipsoid_in_domain_is_the_box(), 'ellipsoid: in_domain (its own) = the box of domain and ' // &
               'periodic_u, at scattered points and the edges')
    call check(cylinder%periodic_v() .and. .not. cylinder%periodic_u(), 'cylinder periodic in v only')
    call check(cylinder%in_domain(-1e6_wp, 20.0_wp), 'cylinder: any u, v inside')
    call check(apex%periodic_u() .and. apex%in_domain(0.3_wp, -5.0_wp), 'apex paraboloid: v in R')
    call check(.not. plane%periodic_u() .and. plane%in_domain(1e9_wp, -1e9_wp), 'plane unbounded')
    call check(index(elliptic%describe(), 'elliptic paraboloid') == 1, 'describe: ' // elliptic%describe())
    call check(index(hyperbolic%describe(), 'hyperbolic paraboloid') == 1, 'describe: ' // hyperbolic%describe())
    call check(index(ellipsoid%describe(), 'ellipsoid') == 1, 'describe: ' // ellipsoid%describe())
    call check(abs(pi - 3.141592653589793_wp) < 1e-15_wp, 'pi')
  end subroutine check_domains

  !> The ellipsoid's own in_domain against surface_t's default rule, built
  !> here from its domain and periodicity (no NaN: the Debug build traps the
  !> comparison).
  logical function ellipsoid_in_domain_is_the_box() result(same)
    real(wp) :: u_min, u_max, v_min, v_max, u, v, vs(10)
    integer :: i, j
    call ellipsoid%domain(u_min, u_max, v_min, v_max)
    vs = [v_min, v_max, nearest(v_min, -1.0_wp), nearest(v_max, 1.0_wp), nearest(v_min, 1.0_wp), &
          nearest(v_max, -1.0_wp), 0.37_wp, -huge(1.0_wp), 0.0_wp, 2.0_wp]
    same = .true.
    do i = -3, 3
      do j = 1, size(vs)
        u = 2.9_wp*i
        v = vs(j)
        if (i == 3) u = huge(1.0_wp)
        same = same .and. (ellipsoid%in_domain(u, v) .eqv. ((ellipsoid%periodic_u() .or. &
               (u >= u_min .and. u <= u_max)) .and. (ellipsoid%periodic_v() .or. (v >= v_min .and. v <= v_max))))
      end do
    end do
  end function ellipsoid_in_domain_is_the_box

  !> r = origin + R r_base, partials rotated, domain and periodicity forwarded,
  !> bad placements refused.
  subroutine check_placed()
    type(surface_point_t) :: p, q
    type(status_t) :: st
    type(placed_surface_t) :: bad
    real(wp) :: r(3, 3), u_min, u_max, v_min, v_max
    r = rotation_xyz([0.3_wp, -0.7_wp, 1.1_wp])
    call ellipsoid%evaluate(0.9_wp, -0.4_wp, 3, q, st)
    call placed_ellipsoid%evaluate(0.9_wp, -0.4_wp, 3, p, st)
    ! rtol/atol 1e-14: one 3x3 product of O(1) numbers
    call check_close_array(p%r, [1.0_wp, -2.0_wp, 3.0_wp] + matmul(r, q%r), 1e-14_wp, 1e-14_wp, &
                           'placed r = origin + R r')
    call check_close_array(p%ruvv, matmul(r, q%ruvv), 1e-14_wp, 1e-14_wp, 'placed r_uvv = R r_uvv')
    call check(p%order == 3, 'placed order')
    call placed_ellipsoid%domain(u_min, u_max, v_min, v_max)
    call check(u_max == two_pi .and. v_min == -half_pi, 'placed domain forwarded')
    call check(placed_ellipsoid%periodic_u() .and. .not. placed_ellipsoid%periodic_v(), &
               'placed periodicity forwarded')
    call check(.not. placed_ellipsoid%in_domain(0.0_wp, 2.0_wp), 'placed in_domain forwarded')
    call check(index(placed_apex%describe(), 'placed paraboloid with singular apex') == 1, &
               'placed describe: ' // placed_apex%describe())
    r = reshape([1, 0, 0, 0, 1, 0, 0, 0, -1], [3, 3])
    bad = placed_surface_t(ellipsoid, [0.0_wp, 0.0_wp, 0.0_wp], st, rotation=r)
    call expect_error(st, 'det R = -1', 'placed reflection refused')
    r(3, 3) = 1.1_wp
    bad = placed_surface_t(ellipsoid, [0.0_wp, 0.0_wp, 0.0_wp], st, rotation=r)
    call expect_error(st, 'not a proper rotation', 'placed non-orthogonal matrix refused')
  end subroutine check_placed

  !> Every constructor refuses bad values with a message naming the value.
  subroutine check_invalid_input()
    type(status_t) :: st
    type(ellipsoid_t) :: e
    type(paraboloid_t) :: q
    type(elliptic_cylinder_t) :: c
    type(apex_paraboloid_t) :: a
    type(plane_t) :: p
    real(wp) :: zero
    zero = 0
    e = ellipsoid_t(1.0_wp, -2.0_wp, 1.0_wp, st)
    call expect_error(st, 'b = -2', 'ellipsoid negative b')
    e = ellipsoid_t(0.0_wp, 2.0_wp, 1.0_wp, st)
    call expect_error(st, 'a = 0', 'ellipsoid zero a')
    e = ellipsoid_t(1.0_wp, 2.0_wp, ieee_value(zero, ieee_positive_inf), st)
    call expect_error(st, 'c = Inf', 'ellipsoid infinite c')
    c = elliptic_cylinder_t(1.0_wp, ieee_value(zero, ieee_quiet_nan), st)
    call expect_error(st, 'b = NaN', 'cylinder NaN b')
    p = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, ieee_value(zero, ieee_quiet_nan)], &
                [2.0_wp, 2.0_wp, 2.0_wp], st)
    call expect_error(st, 'point B', 'plane NaN in B')
    q = paraboloid_t(1.0_wp, 1.0_wp, 0.5_wp, st)
    call expect_error(st, 'c = 0.5', 'paraboloid c not +-1')
    q = paraboloid_t(1.0_wp, 1.0_wp, ieee_value(zero, ieee_quiet_nan), st)
    call expect_error(st, 'c = NaN', 'paraboloid NaN c')
    q = paraboloid_t(1.0_wp, -1.0_wp, 1.0_wp, st)
    call expect_error(st, 'b = -1', 'paraboloid negative b')
    c = elliptic_cylinder_t(-0.25_wp, 1.0_wp, st)
    call expect_error(st, 'a = -0.25', 'cylinder negative a')
    a = apex_paraboloid_t(1.0_wp, -3.0_wp, st)
    call expect_error(st, 'b = -3', 'apex paraboloid negative b')
    p = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 1.0_wp, 1.0_wp], [2.0_wp, 2.0_wp, 2.0_wp], st)
    call expect_error(st, 'collinear', 'plane collinear points')
    p = plane_t([1.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [2.0_wp, 2.0_wp, 2.0_wp], st)
    call expect_error(st, 'coincide', 'plane coincident A, B')
    p = plane_t([1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], st)
    call expect_error(st, 'coincide', 'plane coincident A, C')
  end subroutine check_invalid_input

  subroutine expect_error(st, fragment, what)
    type(status_t), intent(in) :: st
    character(len=*), intent(in) :: fragment, what
    call check(st%code == STATUS_INVALID_INPUT, what // ': status is invalid input')
    call check(index(st%text(), fragment) > 0, what // ': message names the value: ' // st%text())
  end subroutine expect_error
end program test_geometry_surfaces
