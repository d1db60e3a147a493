!> Tube surfaces: a straight centerline with a circular section is the analytic
!> cylinder (points and all partials); all partials to third order against
!> central differences at scattered points for curved centerlines, varying
!> horizons and u-dependent (blended) sections; the thesis example of fig. 3.11
!> (0.5 m into 1.0 m over the middle third, 0.75 m at mid-length); arc length
!> both ways; and the folding check (radius of curvature below the tube radius).
program test_tube
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_curve, only: curve_t, line_curve_t, helix_curve_t, constant_curve_t, polynomial_curve_t
  use geometry_cross_section, only: circle_section_t, ellipse_section_t, flume_section_t, &
                                    blended_section_t, section_holder_t, new_blended_section
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences of the next-lower partial, step 1e-5: truncation
  ! h^2/6 |f'''| and rounding eps |f|/h are both ~1e-11 S (S: size of the
  ! partials, < 1e3 with the steepest logistic here); 1e-7 (1 + S) leaves a
  ! margin > 100 while a wrong or missing term (error ~ S) fails.
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  real(wp), parameter :: us(5) = [0.11_wp, 0.83_wp, 1.52_wp, 2.37_wp, 3.91_wp]
  real(wp), parameter :: vs(5) = [0.2_wp, 1.3_wp, 2.6_wp, 3.9_wp, 5.7_wp]

  type(status_t) :: st
  type(tube_surface_t) :: tube
  type(line_curve_t) :: line
  type(helix_curve_t) :: helix, hhelix
  type(constant_curve_t) :: up
  type(polynomial_curve_t) :: poly
  type(circle_section_t) :: small, large
  type(ellipse_section_t) :: ellipse
  type(flume_section_t) :: flume
  type(blended_section_t) :: blend
  type(section_holder_t) :: parts(3)
  type(surface_point_t) :: p
  integer :: i, j
  real(wp) :: r0, u, v, length, s, um, radius

  up = constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp])

  ! 1. Straight centerline along x, circle r0: r = [u, -r0 cos v, -r0 sin v].
  r0 = 0.5_wp
  line = line_curve_t(origin=[0.0_wp, 0.0_wp, 0.0_wp], direction=[1.0_wp, 0.0_wp, 0.0_wp], &
                      u_min=0.0_wp, u_max=10.0_wp)
  small = circle_section_t(radius=r0)
  tube = new_tube_surface(line, up, small, st)
  call check(st%ok(), 'straight tube built')
  do i = 1, size(us)
    do j = 1, size(vs)
      u = us(i)*2; v = vs(j)
      call tube%evaluate(u, v, 3, p, st)
      ! atol 1e-10 (acceptance): exact up to a few roundings of O(1) numbers
      call check_close_array(p%r, [u, -r0*cos(v), -r0*sin(v)], 0.0_wp, 1e-10_wp, 'cylinder r')
      call check_close_array(p%ru, [1.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'cylinder r_u')
      call check_close_array(p%rv, [0.0_wp, r0*sin(v), -r0*cos(v)], 0.0_wp, 1e-10_wp, 'cylinder r_v')
      call check_close_array(p%ruu, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'cylinder r_uu')
      call check_close_array(p%ruv, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'cylinder r_uv')
      call check_close_array(p%rvv, [0.0_wp, r0*cos(v), r0*sin(v)], 0.0_wp, 1e-10_wp, 'cylinder r_vv')
      call check_close_array(p%ruuu, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'cylinder r_uuu')
      call check_close_array(p%ruuv, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'cylinder r_uuv')
      call check_close_array(p%ruvv, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'cylinder r_uvv')
      call check_close_array(p%rvvv, [0.0_wp, -r0*sin(v), r0*cos(v)], 0.0_wp, 1e-10_wp, 'cylinder r_vvv')
      ! v = pi/2 is the bottom (thesis 4.2)
    end do
  end do
  call tube%evaluate(1.0_wp, pi/2, 0, p, st)
  call check_close(p%r(3), -r0, 0.0_wp, 1e-15_wp, 'v = pi/2 is the bottom')
  call check(tube%periodic_v(), 'full circle is periodic in v')

  ! 2. Partials against differences: helix with a varying horizon and a circle,
  ! polynomial centerline with an ellipse, a flume and a three-section blend.
  helix = helix_curve_t(center=[0.0_wp, 0.0_wp, 0.0_wp], radius=4.0_wp, pitch=-0.5_wp, phase=0.2_wp, &
                        u_min=0.0_wp, u_max=5.0_wp)
  hhelix = helix_curve_t(center=[0.1_wp, 0.0_wp, 1.0_wp], radius=0.25_wp, pitch=0.03_wp, phase=0.4_wp, &
                         u_min=-1.0_wp, u_max=9.0_wp)
  poly%coef(:, 0) = [0.1_wp, 0.2_wp, 0.3_wp]
  poly%coef(:, 1) = [2.0_wp, 0.3_wp, -0.4_wp]
  poly%coef(:, 2) = [-0.2_wp, 0.5_wp, 0.05_wp]
  poly%coef(:, 3) = [0.03_wp, -0.08_wp, 0.01_wp]
  poly%coef(:, 4) = [0.004_wp, 0.002_wp, -0.003_wp]
  poly%coef(:, 5) = [-0.0005_wp, 0.0004_wp, 0.0002_wp]
  poly%u_min = 0; poly%u_max = 5
  ellipse = ellipse_section_t(a=0.6_wp, b=0.4_wp)
  flume = flume_section_t()
  large = circle_section_t(radius=1.0_wp)
  allocate (parts(1)%section, source=small)
  allocate (parts(2)%section, source=ellipse)
  allocate (parts(3)%section, source=large)
  blend = new_blended_section(parts, [1.0_wp, 3.0_wp], [1.5_wp, 3.4_wp], st)
  call check(st%ok(), 'blended section built')

  tube = new_tube_surface(helix, hhelix, small, st)
  call fd_surface(tube, 'helix/varying horizon/circle', 0.0_wp, two_pi)
  tube = new_tube_surface(poly, up, ellipse, st)
  call fd_surface(tube, 'polynomial/ellipse', 0.0_wp, two_pi)
  tube = new_tube_surface(poly, hhelix, flume, st)
  call fd_surface(tube, 'polynomial/flume', -0.3_wp, pi + 0.3_wp)
  call grid_points(tube, 'polynomial/flume', -0.3_wp, pi + 0.3_wp)
  tube = new_tube_surface(helix, up, blend, st)
  call fd_surface(tube, 'helix/blended section', 0.0_wp, two_pi)

  ! 3. Thesis fig. 3.11: straight centerline of length 9 m, circles 0.5 m -> 1.0 m,
  ! transition over the middle third: midpoint 4.5 m, 0.99 point at 6 m.
  length = 9
  line%u_max = length
  deallocate (parts(2)%section, parts(3)%section)
  allocate (parts(2)%section, source=large)
  blend = new_blended_section(parts(1:2), [length/2], [length/2 + length/6], st)
  tube = new_tube_surface(line, up, blend, st)
  call tube%evaluate(length/2, 1.0_wp, 0, p, st)
  ! rtol 1e-14: at the midpoint both weights are exactly 1/2
  call check_close(norm2(p%r(2:3)), 0.75_wp, 1e-14_wp, 0.0_wp, 'fig. 3.11: radius 0.75 m at mid-length')
  call tube%evaluate(length*2/3, 1.0_wp, 0, p, st)
  call check_close(norm2(p%r(2:3)), 0.99_wp*1.0_wp + 0.01_wp*0.5_wp, 1e-13_wp, 0.0_wp, &
                   'fig. 3.11: weight 0.99 at the end of the middle third')
  call tube%evaluate(length/3, 1.0_wp, 0, p, st)
  call check_close(norm2(p%r(2:3)), 0.99_wp*0.5_wp + 0.01_wp*1.0_wp, 1e-13_wp, 0.0_wp, &
                   'fig. 3.11: weight 0.01 at the start of the middle third')
  ! outside the transition the section is the patch to the 0.99 definition
  do i = 0, 30
    u = length*i/30.0_wp
    call tube%evaluate(u, 2.0_wp, 0, p, st)
    radius = norm2(p%r(2:3))
    if (u <= length/3) call check(abs(radius - 0.5_wp) <= 0.01_wp*0.5_wp + 1e-14_wp, 'fig 3.11: first third is 0.5 m')
    if (u >= 2*length/3) call check(abs(radius - 1.0_wp) <= 0.01_wp*0.5_wp + 1e-14_wp, 'fig 3.11: last third is 1.0 m')
    if (i > 0) call check(radius >= um, 'fig 3.11: radius grows monotonically')
    um = radius
  end do
  call fd_surface(tube, 'fig. 3.11 tube', 0.0_wp, two_pi)

  ! 4. Arc length both ways on the helix tube.
  tube = new_tube_surface(helix, up, small, st)
  s = tube%arc_length(3.0_wp)
  ! rtol 1e-12: Gauss quadrature of a constant speed
  call check_close(s, 3.0_wp*sqrt(16.0_wp + 0.25_wp), 1e-12_wp, 0.0_wp, 'tube arc length')
  call tube%parameter_at_length(s, u, st)
  call check_close(u, 3.0_wp, 0.0_wp, 1e-10_wp, 'tube parameter at length')

  ! 5. Folding: a helix of radius 0.6 m has radius of curvature (R^2+c^2)/R
  ! = 0.6 m < ellipse extent 0.6 m + ... -> error naming where; radius 4 m passes.
  st = status_t()
  call tube%check(50, st)
  call check(st%ok(), 'helix R = 4 m with a 0.5 m tube passes the folding check')
  helix%radius = 0.45_wp
  helix%pitch = 0.0_wp
  tube = new_tube_surface(helix, up, small, st)
  call tube%check(50, st)
  call check(st%code == STATUS_INVALID_INPUT, 'radius of curvature 0.45 m < tube radius 0.5 m is rejected')
  call check(index(st%text(), 'arc length') > 0 .and. index(st%text(), 'fold') > 0, &
             'folding message says where: ' // st%text())

  ! 6. A circular section takes its own path (circle_in_slice); an ellipse
  ! with a = b = r takes the general one with the same products: every
  ! partial to every order the same to the bit (helix, varying horizon).
  call same_as_general(helix, hhelix, 0.5_wp)
  call same_as_general(poly, up, 0.8_wp)

  call finish_tests('test_tube')

contains

  subroutine same_as_general(centerline, horizon, r)
    class(curve_t), intent(in) :: centerline, horizon
    real(wp), intent(in) :: r
    type(tube_surface_t) :: circle_tube, ellipse_tube
    type(surface_point_t) :: pc, pe
    type(status_t) :: sc, se
    logical :: same
    integer :: i, j, order
    circle_tube = new_tube_surface(centerline, horizon, circle_section_t(radius=r), sc)
    ellipse_tube = new_tube_surface(centerline, horizon, ellipse_section_t(a=r, b=r), se)
    same = sc%ok() .and. se%ok()
    do order = 0, 3
      do i = 1, size(us)
        do j = 1, size(vs)
          call circle_tube%evaluate(us(i), vs(j), order, pc, sc)
          call ellipse_tube%evaluate(us(i), vs(j), order, pe, se)
          same = same .and. sc%ok() .and. se%ok() .and. pc%order == pe%order .and. all(pc%r == pe%r) &
                 .and. all(pc%ru == pe%ru) .and. all(pc%rv == pe%rv) .and. all(pc%ruu == pe%ruu) &
                 .and. all(pc%ruv == pe%ruv) .and. all(pc%rvv == pe%rvv) .and. all(pc%ruuu == pe%ruuu) &
                 .and. all(pc%ruuv == pe%ruuv) .and. all(pc%ruvv == pe%ruvv) .and. all(pc%rvvv == pe%rvvv)
        end do
      end do
    end do
    call check(same, 'circular section: the same bits as the general path (ellipse a = b)')
  end subroutine same_as_general

  !> points_on_grid (the centerline and frame once per u) = evaluate at every point
  subroutine grid_points(surf, name, v_lo, v_hi)
    type(tube_surface_t), intent(in) :: surf
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: v_lo, v_hi
    real(wp) :: u(7), v(5), x(5, 7), y(5, 7), z(5, 7), a, b, d1, d2
    type(surface_point_t) :: q
    integer :: i, j
    call surf%domain(a, b, d1, d2)
    u = [(a + (b - a)*i/6.0_wp, i = 0, 6)]
    v = [(v_lo + (v_hi - v_lo)*j/4.0_wp, j = 0, 4)]
    call surf%points_on_grid(u, v, x, y, z, st)
    call check(st%ok(), name//': grid status')
    do i = 1, 7
      do j = 1, 5
        call surf%evaluate(u(i), v(j), 0, q, st)
        call check_close_array([x(j, i), y(j, i), z(j, i)], q%r, 0.0_wp, 1e-14_wp, name//': grid point = evaluate')
      end do
    end do
  end subroutine grid_points

  subroutine fd_surface(surf, name, v_lo, v_hi)
    class(surface_t), intent(in) :: surf
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: v_lo, v_hi
    type(surface_point_t) :: p0, pu1, pu0, pv1, pv0
    real(wp) :: a, b, c, d, uu, vv, tol
    integer :: i, j
    call surf%domain(a, b, c, d)
    do i = 1, 4
      do j = 1, 4
        uu = a + (b - a)*(0.05_wp + 0.21_wp*i - 0.03_wp*j)
        vv = v_lo + (v_hi - v_lo)*(0.03_wp + 0.23_wp*j + 0.01_wp*i)
        call surf%evaluate(uu, vv, 3, p0, st)
        call check(st%ok(), name // ': evaluate status')
        call surf%evaluate(uu + h, vv, 3, pu1, st)
        call surf%evaluate(uu - h, vv, 3, pu0, st)
        call surf%evaluate(uu, vv + h, 3, pv1, st)
        call surf%evaluate(uu, vv - h, 3, pv0, st)
        tol = fd_tol*(1 + maxval(abs([p0%r, p0%ru, p0%rv, p0%ruu, p0%ruv, p0%rvv, p0%ruuu, p0%ruuv, &
                                      p0%ruvv, p0%rvvv])))
        call check_close_array(p0%ru, (pu1%r - pu0%r)/(2*h), 0.0_wp, tol, name // ': r_u')
        call check_close_array(p0%rv, (pv1%r - pv0%r)/(2*h), 0.0_wp, tol, name // ': r_v')
        call check_close_array(p0%ruu, (pu1%ru - pu0%ru)/(2*h), 0.0_wp, tol, name // ': r_uu')
        call check_close_array(p0%ruv, (pv1%ru - pv0%ru)/(2*h), 0.0_wp, tol, name // ': r_uv')
        call check_close_array(p0%ruv, (pu1%rv - pu0%rv)/(2*h), 0.0_wp, tol, name // ': r_vu')
        call check_close_array(p0%rvv, (pv1%rv - pv0%rv)/(2*h), 0.0_wp, tol, name // ': r_vv')
        call check_close_array(p0%ruuu, (pu1%ruu - pu0%ruu)/(2*h), 0.0_wp, tol, name // ': r_uuu')
        call check_close_array(p0%ruuv, (pv1%ruu - pv0%ruu)/(2*h), 0.0_wp, tol, name // ': r_uuv')
        call check_close_array(p0%ruvv, (pv1%ruv - pv0%ruv)/(2*h), 0.0_wp, tol, name // ': r_uvv')
        call check_close_array(p0%ruvv, (pu1%rvv - pu0%rvv)/(2*h), 0.0_wp, tol, name // ': r_vvu')
        call check_close_array(p0%rvvv, (pv1%rvv - pv0%rvv)/(2*h), 0.0_wp, tol, name // ': r_vvv')
      end do
    end do
  end subroutine fd_surface
end program test_tube
