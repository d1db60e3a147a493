!> Curves and the horizon-vector frame: curve derivatives to 4th order and
!> frame derivatives to 3rd order against central differences at scattered
!> points (constant and varying horizon), orthonormality, the helix curvature
!> R/(R^2 + c^2) with chi_u = 0, chi_u against differences of chi, arc length
!> and its inverse, and the error for a horizon parallel to the tangent.
program test_curve_frame
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_DOMAIN
  use base_vector, only: cross
  use geometry_curve, only: curve_t, curve_point_t, helix_curve_t, line_curve_t, &
                            constant_curve_t, polynomial_curve_t, s_bend_curve_t
  use geometry_curve_frame, only: curve_frame_t, curve_frame_at
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences of the next-lower derivative with step h = 1e-5:
  ! truncation h^2/6 |f'''| ~ 2e-11 S, rounding eps |f|/h ~ 2e-11 S, with S the
  ! size of the derivatives here (< 100); 1e-7 (1 + S) leaves a margin > 100
  ! while any wrong term (an error of order S) fails.
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  real(wp), parameter :: u_points(7) = [0.13_wp, 0.71_wp, 1.37_wp, 2.05_wp, 2.9_wp, 3.6_wp, 4.4_wp]

  type(helix_curve_t) :: helix, horizon_helix, clockwise
  type(s_bend_curve_t) :: s_bend
  type(constant_curve_t) :: up, tilted
  type(polynomial_curve_t) :: poly
  type(line_curve_t) :: vertical
  type(curve_frame_t) :: f
  type(status_t) :: st
  integer :: i
  real(wp) :: rr, cc, u

  helix = helix_curve_t(center=[1.0_wp, -2.0_wp, 0.5_wp], radius=2.5_wp, pitch=0.4_wp, phase=0.3_wp, &
                        u_min=-1.0_wp, u_max=6.0_wp)
  ! a varying horizon (leaning up-and-around) exercises the h_u, h_uu, h_uuu terms
  horizon_helix = helix_curve_t(center=[0.0_wp, 0.0_wp, 0.0_wp], radius=0.3_wp, pitch=0.05_wp, phase=1.1_wp, &
                                u_min=-10.0_wp, u_max=10.0_wp)
  horizon_helix%center = [0.2_wp, -0.1_wp, 1.0_wp]
  up = constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp])
  tilted = constant_curve_t(value=[0.3_wp, -0.2_wp, 2.0_wp])
  poly%coef(:, 0) = [0.1_wp, 0.2_wp, 0.3_wp]
  poly%coef(:, 1) = [1.0_wp, 0.3_wp, -0.1_wp]
  poly%coef(:, 2) = [-0.2_wp, 0.5_wp, 0.05_wp]
  poly%coef(:, 3) = [0.03_wp, -0.08_wp, 0.01_wp]
  poly%coef(:, 4) = [0.004_wp, 0.002_wp, -0.003_wp]
  poly%coef(:, 5) = [-0.0005_wp, 0.0004_wp, 0.0002_wp]
  poly%u_min = 0; poly%u_max = 5

  clockwise = helix_curve_t(center=[0.5_wp, 0.0_wp, 2.0_wp], radius=2.0_wp, pitch=-0.5_wp, phase=0.7_wp, &
                            turn=-1.0_wp, u_min=0.0_wp, u_max=6.0_wp)
  s_bend = s_bend_curve_t(amplitude=1.5_wp, wavenumber=0.4_wp, slope=0.1_wp, u_min=0.0_wp, u_max=20.0_wp)
  call check_curve(helix, 'helix')
  call check_curve(clockwise, 'clockwise helix')
  call check_curve(s_bend, 'S-bend')
  call check_curve(poly, 'polynomial')
  ! a clockwise helix turns the other way: c_u x c_uu points down (seen from above, clockwise)
  call check_clockwise()
  do i = 1, size(u_points)
    call check_frame(clockwise, up, u_points(i), 'clockwise helix/up')
    call check_frame(s_bend, up, u_points(i), 'S-bend/up')
    call check_chi_u(s_bend, u_points(i))
    call check_frame(helix, up, u_points(i), 'helix/up')
    call check_frame(helix, horizon_helix, u_points(i), 'helix/varying horizon')
    call check_frame(poly, tilted, u_points(i), 'polynomial/tilted')
    call check_frame(poly, horizon_helix, u_points(i), 'polynomial/varying horizon')
    call check_chi_u(poly, u_points(i))
  end do

  ! Helix curvature R/(R^2 + c^2) (c = pitch per radian), constant: chi_u = 0.
  rr = 2.5_wp; cc = 0.4_wp
  do i = 1, size(u_points)
    call curve_frame_at(helix, up, u_points(i), 3, f, st)
    ! rtol 1e-13: closed form, a few roundings of O(1) numbers
    call check_close(f%chi, rr/(rr**2 + cc**2), 1e-13_wp, 0.0_wp, 'helix curvature')
    call check_close(f%chi_u, 0.0_wp, 0.0_wp, 1e-12_wp, 'helix chi_u')
    ! with h = up the y-axis is horizontal and z points upwards
    call check_close(f%y(3, 0), 0.0_wp, 0.0_wp, 1e-14_wp, 'y horizontal for h = up')
    call check(f%z(3, 0) > 0, 'z points up for h = up')
  end do

  ! Arc length of a helix: sqrt(R^2 + c^2) per radian; the inverse returns u.
  ! rtol 1e-12: composite 8-point Gauss on 256 panels of a trigonometric integrand
  call check_close(helix%arc_length(0.5_wp, 4.0_wp), 3.5_wp*sqrt(rr**2 + cc**2), 1e-12_wp, 0.0_wp, &
                   'helix arc length')
  call check_close(helix%total_length(), 7.0_wp*sqrt(rr**2 + cc**2), 1e-12_wp, 0.0_wp, 'helix length')
  call helix%parameter_at_length(2.0_wp*sqrt(rr**2 + cc**2), u, st)
  call check(st%ok(), 'parameter_at_length status')
  call check_close(u, 1.0_wp, 0.0_wp, 1e-10_wp, 'parameter at length')
  u = poly%arc_length(0.0_wp, 3.3_wp)
  call poly%parameter_at_length(u, rr, st)
  call check_close(rr, 3.3_wp, 0.0_wp, 1e-10_wp, 'polynomial: parameter at length inverts arc length')
  ! the line's and the helix's closed-form arc length equal the quadrature of
  ! |c_u| (rtol 1e-12: the rounding of 20000 sums)
  call check_close(clockwise%arc_length(0.3_wp, 5.2_wp), quadrature(clockwise, 0.3_wp, 5.2_wp), 1e-12_wp, 0.0_wp, &
                   'clockwise helix arc length = quadrature')
  vertical = line_curve_t(origin=[1.0_wp, 2.0_wp, 3.0_wp], direction=[0.3_wp, -1.2_wp, 0.4_wp], &
                          u_min=0.0_wp, u_max=2.0_wp)
  call check_close(vertical%arc_length(0.2_wp, 1.7_wp), quadrature(vertical, 0.2_wp, 1.7_wp), 1e-12_wp, 0.0_wp, &
                   'line arc length = quadrature')

  ! A vertical centerline with the horizon along it: clear error, no NaN.
  vertical = line_curve_t(origin=[0.0_wp, 0.0_wp, 0.0_wp], direction=[0.0_wp, 0.0_wp, -1.0_wp], &
                          u_min=0.0_wp, u_max=1.0_wp)
  call curve_frame_at(vertical, up, 0.5_wp, 2, f, st)
  call check(st%code == STATUS_DOMAIN, 'horizon parallel to tangent gives STATUS_DOMAIN')
  call check(index(st%text(), 'parallel') > 0, 'message names the parallel horizon: ' // st%text())

  call finish_tests('test_curve_frame')

contains

  subroutine check_curve(c, name)
    class(curve_t), intent(in) :: c
    character(len=*), intent(in) :: name
    type(curve_point_t) :: p, pp, pm
    integer :: i, k
    do i = 1, size(u_points)
      call c%evaluate(u_points(i), 4, p, st)
      call c%evaluate(u_points(i) + h, 4, pp, st)
      call c%evaluate(u_points(i) - h, 4, pm, st)
      do k = 1, 4
        call check_close_array(p%d(:, k), (pp%d(:, k - 1) - pm%d(:, k - 1))/(2*h), 0.0_wp, &
                               fd_tol*(1 + maxval(abs(p%d))), name // ' derivative')
      end do
    end do
  end subroutine check_curve

  subroutine check_frame(c, hz, u, name)
    class(curve_t), intent(in) :: c, hz
    real(wp), intent(in) :: u
    character(len=*), intent(in) :: name
    type(curve_frame_t) :: f0, fp, fm
    real(wp) :: s
    integer :: k
    call curve_frame_at(c, hz, u, 3, f0, st)
    call check(st%ok(), name // ': frame status')
    call curve_frame_at(c, hz, u + h, 3, fp, st)
    call curve_frame_at(c, hz, u - h, 3, fm, st)
    s = 1 + max(maxval(abs(f0%x)), maxval(abs(f0%y)), maxval(abs(f0%z)))
    do k = 1, 3
      call check_close_array(f0%x(:, k), (fp%x(:, k - 1) - fm%x(:, k - 1))/(2*h), 0.0_wp, fd_tol*s, &
                             name // ': x derivative')
      call check_close_array(f0%y(:, k), (fp%y(:, k - 1) - fm%y(:, k - 1))/(2*h), 0.0_wp, fd_tol*s, &
                             name // ': y derivative')
      call check_close_array(f0%z(:, k), (fp%z(:, k - 1) - fm%z(:, k - 1))/(2*h), 0.0_wp, fd_tol*s, &
                             name // ': z derivative')
    end do
    ! orthonormal, right-handed; y perpendicular to the horizon (3.62)
    call check_close(dot_product(f0%x(:, 0), f0%y(:, 0)), 0.0_wp, 0.0_wp, 1e-14_wp, name // ': x.y')
    call check_close(norm2(f0%y(:, 0)), 1.0_wp, 1e-14_wp, 0.0_wp, name // ': |y|')
    call check_close_array(cross(f0%x(:, 0), f0%y(:, 0)), f0%z(:, 0), 0.0_wp, 1e-14_wp, name // ': z = x cross y')
  end subroutine check_frame

  subroutine check_chi_u(c, u)
    class(curve_t), intent(in) :: c
    real(wp), intent(in) :: u
    type(curve_frame_t) :: f0, fp, fm
    call curve_frame_at(c, up, u, 3, f0, st)
    call curve_frame_at(c, up, u + h, 3, fp, st)
    call curve_frame_at(c, up, u - h, 3, fm, st)
    call check_close(f0%chi_u, (fp%chi - fm%chi)/(2*h), 0.0_wp, fd_tol*(1 + abs(f0%chi)), 'chi_u (4.9)')
    ! chi = |x_u|/|c_u| (curvature is the turning rate of the tangent per metre)
    call check_close(f0%chi, norm2(f0%x(:, 1))/speed(c, u), 1e-12_wp, 0.0_wp, 'chi (4.8) = |x_u|/|c_u|')
  end subroutine check_chi_u

  subroutine check_clockwise()
    type(curve_point_t) :: p
    real(wp) :: k3(3)
    integer :: k
    do k = 1, size(u_points)
      call clockwise%evaluate(u_points(k), 2, p, st)
      k3 = cross(p%d(:, 1), p%d(:, 2))
      call check(k3(3) < 0, 'clockwise helix turns clockwise seen from above')
      call helix%evaluate(u_points(k), 2, p, st)
      k3 = cross(p%d(:, 1), p%d(:, 2))
      call check(k3(3) > 0, 'helix (turn = +1) turns counter-clockwise')
    end do
  end subroutine check_clockwise

  !> int |c_u| du by the composite Simpson rule on 20000 panels
  real(wp) function quadrature(c, a, b)
    class(curve_t), intent(in) :: c
    real(wp), intent(in) :: a, b
    integer, parameter :: n = 20000
    integer :: k
    quadrature = speed(c, a) + speed(c, b)
    do k = 1, n - 1
      quadrature = quadrature + merge(4, 2, mod(k, 2) == 1)*speed(c, a + (b - a)*k/n)
    end do
    quadrature = quadrature*(b - a)/(3*n)
  end function quadrature

  real(wp) function speed(c, u)
    class(curve_t), intent(in) :: c
    real(wp), intent(in) :: u
    type(curve_point_t) :: p
    call c%evaluate(u, 1, p, st)
    speed = norm2(p%d(:, 1))
  end function speed
end program test_curve_frame
