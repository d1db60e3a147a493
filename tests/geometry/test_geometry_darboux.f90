!> The Darboux frame (thesis 3.37-3.51, appendix A): orthonormal and
!> right-handed, z_D along sigma N, x_D along alpha_u r_u + alpha_v r_v, the
!> rates a-f and their u, v derivatives against central differences at
!> scattered points, and the singular-point rule at the apex of the apex
!> paraboloid and the poles of a sphere.
!> A test surface with r_u = 0 along v = 0 and r_uvv /= 0 there, to exercise
!> every term of the singular rates (r_uvv with a normal part, r_vvv /= 0):
!> r = [v cos u + k v^2 cos 2u, v sin u, v^2 (1 + q cos 2u) + m v^3].
module test_geometry_darboux_surfaces
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t, surface_point_t
  implicit none (type, external)
  private
  public :: twisted_apex_t

  type, extends(surface_t) :: twisted_apex_t
    real(wp) :: k = 0.3_wp, m = 0.5_wp, q = 0.4_wp
  contains
    procedure :: evaluate => twisted_evaluate
  end type twisted_apex_t

contains

  pure subroutine twisted_evaluate(self, u, v, order, p, status)
    class(twisted_apex_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: cu, su, c2, s2, k, g, gu, guu, guuu
    status%code = 0
    k = self%k
    cu = cos(u); su = sin(u); c2 = cos(2*u); s2 = sin(2*u)
    g = 1 + self%q*c2; gu = -2*self%q*s2; guu = -4*self%q*c2; guuu = 8*self%q*s2
    p%order = order
    p%r = [v*cu + k*v**2*c2, v*su, v**2*g + self%m*v**3]
    p%ru = [-v*su - 2*k*v**2*s2, v*cu, v**2*gu]
    p%rv = [cu + 2*k*v*c2, su, 2*v*g + 3*self%m*v**2]
    p%ruu = [-v*cu - 4*k*v**2*c2, -v*su, v**2*guu]
    p%ruv = [-su - 4*k*v*s2, cu, 2*v*gu]
    p%rvv = [2*k*c2, 0.0_wp, 2*g + 6*self%m*v]
    p%ruuu = [v*su + 8*k*v**2*s2, -v*cu, v**2*guuu]
    p%ruuv = [-cu - 8*k*v*c2, -su, 2*v*guu]
    p%ruvv = [-4*k*s2, 0.0_wp, 2*gu]
    p%rvvv = [0.0_wp, 0.0_wp, 6*self%m]
  end subroutine twisted_evaluate
end module test_geometry_darboux_surfaces

program test_geometry_darboux
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_constants, only: half_pi, two_pi
  use base_vector, only: cross
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t, &
                                 apex_paraboloid_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_differential, only: unit_normal
  use geometry_darboux, only: darboux_frame_t, darboux_frame, darboux_axes, singular_tol, &
                              SINGULAR_RULE_LIMIT, SINGULAR_RULE_THESIS
  use test_geometry_darboux_surfaces, only: twisted_apex_t
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Frame identities: a few roundings of unit vectors -> 1e-13.
  real(wp), parameter :: exact_tol = 1e-13_wp
  ! Central differences with h = 1e-5 of unit vectors whose derivatives are of
  ! size S (<= ~10 here): truncation h^2/6 |x'''| ~ 2e-10 S, rounding
  ! eps/h ~ 2e-11; 1e-7 S leaves a wide margin while a wrong term fails at O(S).
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  integer, parameter :: n_points = 10

  type(status_t) :: st
  type(plane_t) :: plane
  type(ellipsoid_t) :: ellipsoid, sphere
  type(paraboloid_t) :: elliptic, hyperbolic
  type(elliptic_cylinder_t) :: cylinder
  type(apex_paraboloid_t) :: apex, round_apex
  type(placed_surface_t) :: placed
  type(twisted_apex_t) :: twisted

  plane = plane_t([0.0_wp, 0.0_wp, 1.0_wp], [1.0_wp, 1.0_wp, 1.5_wp], [-1.0_wp, 2.0_wp, 1.0_wp], st)
  ellipsoid = ellipsoid_t(2.0_wp, 1.2_wp, 0.8_wp, st)
  sphere = ellipsoid_t(1.5_wp, 1.5_wp, 1.5_wp, st)
  elliptic = paraboloid_t(1.5_wp, 0.9_wp, 1.0_wp, st)
  hyperbolic = paraboloid_t(1.1_wp, 1.6_wp, -1.0_wp, st)
  cylinder = elliptic_cylinder_t(1.4_wp, 0.7_wp, st)
  apex = apex_paraboloid_t(1.3_wp, 0.6_wp, st)
  round_apex = apex_paraboloid_t(0.8_wp, 0.8_wp, st)
  placed = placed_surface_t(ellipsoid, [1.0_wp, 2.0_wp, 3.0_wp], st, angles=[0.5_wp, -0.3_wp, 2.0_wp])
  call check(st%ok(), 'constructors')

  call check_regular(plane, -2.0_wp, 2.0_wp, -2.0_wp, 2.0_wp, 'plane')
  call check_regular(ellipsoid, 0.0_wp, two_pi, -1.3_wp, 1.3_wp, 'ellipsoid')
  call check_regular(elliptic, -2.0_wp, 2.0_wp, -2.0_wp, 2.0_wp, 'elliptic paraboloid')
  call check_regular(hyperbolic, -2.0_wp, 2.0_wp, -2.0_wp, 2.0_wp, 'hyperbolic paraboloid')
  call check_regular(cylinder, -2.0_wp, 2.0_wp, 0.0_wp, two_pi, 'elliptic cylinder')
  call check_regular(apex, 0.0_wp, two_pi, 0.2_wp, 1.5_wp, 'apex paraboloid')
  call check_regular(placed, 0.0_wp, two_pi, -1.3_wp, 1.3_wp, 'placed ellipsoid')

  call check_regular(twisted, 0.0_wp, two_pi, 0.2_wp, 1.2_wp, 'twisted apex (test surface)')

  call check_apex_singular()
  call check_twisted_singular()
  call check_sphere_poles()
  call check_limit_rule(apex, 0.0_wp, 1.0_wp, 'limit rule, apex paraboloid a /= b')
  call check_limit_rule(twisted, 0.0_wp, 1.0_wp, 'limit rule, twisted apex')
  call check_limit_rule(ellipsoid, half_pi, -1.0_wp, 'limit rule, ellipsoid north pole')
  call check_limit_rule(ellipsoid, -half_pi, 1.0_wp, 'limit rule, ellipsoid south pole')
  call check_errors()
  call check_reused_frame()

  call finish_tests('test_geometry_darboux')

contains

  !> Frame identities and rates at scattered regular points, for several
  !> choices of sigma and alpha.
  subroutine check_regular(s, u0, u1, v0, v1, name)
    class(surface_t), intent(in) :: s
    real(wp), intent(in) :: u0, u1, v0, v1
    character(len=*), intent(in) :: name
    real(wp), parameter :: params(3, 4) = reshape([1.0_wp, 1.0_wp, 0.0_wp, &
                                                   -1.0_wp, 0.0_wp, 1.0_wp, &
                                                   2.5_wp, 0.3_wp, 0.8_wp, &
                                                   -0.4_wp, -1.0_wp, 0.6_wp], [3, 4])
    type(surface_point_t) :: p
    type(darboux_frame_t) :: fr, up, um, vp, vm
    real(wp) :: u, v, sigma, au, av, w(3), axes(3, 3)
    logical :: singular
    integer :: k, j
    character(len=100) :: at
    do k = 1, n_points
      u = u0 + (u1 - u0)*modulo(0.2_wp + k*0.6180339887498949_wp, 1.0_wp)
      v = v0 + (v1 - v0)*modulo(0.4_wp + k*0.7548776662466927_wp, 1.0_wp)
      j = 1 + modulo(k, 4)
      sigma = params(1, j); au = params(2, j); av = params(3, j)
      write (at, '(a, 2es11.3, a, 3f6.2)') ' at (u, v) = (', u, v, ') sigma, alpha:', sigma, au, av
      call frame_at(s, u, v, sigma, au, av, fr)
      call check(.not. fr%singular .and. fr%second_order, name // ' regular with second order' // trim(at))
      call check_close_array(reshape(matmul(transpose(fr%r), fr%r), [9]), &
                             [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                             0.0_wp, exact_tol, name // ' R^T R = I' // trim(at))
      call check_close_array(cross(fr%r(:, 1), fr%r(:, 2)), fr%r(:, 3), 0.0_wp, exact_tol, &
                             name // ' right-handed x x y = z' // trim(at))
      call s%evaluate(u, v, 3, p, st)
      call check_close_array(fr%r(:, 3), sign(1.0_wp, sigma)*unit_normal(p), 0.0_wp, exact_tol, &
                             name // ' z_D = sign(sigma) N' // trim(at))
      w = au*p%ru + av*p%rv
      call check_close(dot_product(fr%r(:, 1), w), norm2(w), exact_tol, exact_tol, &
                       name // ' x_D along alpha_u r_u + alpha_v r_v' // trim(at))
      ! the axes alone from the point to order 1 (the lazy position maps):
      ! the frame's axes to the last bit
      call s%evaluate(u, v, 1, p, st)
      call darboux_axes(p, sigma, au, av, axes, singular, st)
      call check(st%ok() .and. .not. singular .and. all(axes == fr%r), &
                 name // ' darboux_axes at order 1 = darboux_frame%r' // trim(at))
      ! rates: central differences of the frame itself and of its rates
      call frame_at(s, u + h, v, sigma, au, av, up)
      call frame_at(s, u - h, v, sigma, au, av, um)
      call frame_at(s, u, v + h, sigma, au, av, vp)
      call frame_at(s, u, v - h, sigma, au, av, vm)
      call fd3(fr%a, (up%r(:, 1) - um%r(:, 1))/(2*h), name // ' a = x_u' // trim(at))
      call fd3(fr%b, (vp%r(:, 1) - vm%r(:, 1))/(2*h), name // ' b = x_v' // trim(at))
      call fd3(fr%c, (up%r(:, 3) - um%r(:, 3))/(2*h), name // ' c = z_u' // trim(at))
      call fd3(fr%d, (vp%r(:, 3) - vm%r(:, 3))/(2*h), name // ' d = z_v' // trim(at))
      call fd3(fr%e, (up%r(:, 2) - um%r(:, 2))/(2*h), name // ' e = y_u' // trim(at))
      call fd3(fr%f, (vp%r(:, 2) - vm%r(:, 2))/(2*h), name // ' f = y_v' // trim(at))
      call fd3(fr%a_u, (up%a - um%a)/(2*h), name // ' a_u' // trim(at))
      call fd3(fr%a_v, (vp%a - vm%a)/(2*h), name // ' a_v' // trim(at))
      call fd3(fr%b_u, (up%b - um%b)/(2*h), name // ' b_u' // trim(at))
      call fd3(fr%b_v, (vp%b - vm%b)/(2*h), name // ' b_v' // trim(at))
      call fd3(fr%c_u, (up%c - um%c)/(2*h), name // ' c_u' // trim(at))
      call fd3(fr%c_v, (vp%c - vm%c)/(2*h), name // ' c_v' // trim(at))
      call fd3(fr%d_u, (up%d - um%d)/(2*h), name // ' d_u' // trim(at))
      call fd3(fr%d_v, (vp%d - vm%d)/(2*h), name // ' d_v' // trim(at))
      call fd3(fr%e_u, (up%e - um%e)/(2*h), name // ' e_u' // trim(at))
      call fd3(fr%e_v, (vp%e - vm%e)/(2*h), name // ' e_v' // trim(at))
      call fd3(fr%f_u, (up%f - um%f)/(2*h), name // ' f_u' // trim(at))
      call fd3(fr%f_v, (vp%f - vm%f)/(2*h), name // ' f_v' // trim(at))
    end do
  end subroutine check_regular

  subroutine frame_at(s, u, v, sigma, au, av, fr)
    class(surface_t), intent(in) :: s
    real(wp), intent(in) :: u, v, sigma, au, av
    type(darboux_frame_t), intent(out) :: fr
    type(surface_point_t) :: p
    type(status_t) :: st1, st2
    call s%evaluate(u, v, 3, p, st1)
    call darboux_frame(p, sigma, au, av, fr, st2)
    call check(st1%ok() .and. st2%ok(), 'frame evaluates: ' // st1%text() // ' / ' // st2%text())
  end subroutine frame_at

  subroutine fd3(x, ref, what)
    real(wp), intent(in) :: x(3), ref(3)
    character(len=*), intent(in) :: what
    call check_close_array(x, ref, 0.0_wp, fd_tol*(1 + norm2(ref)), what)
  end subroutine fd3

  !> (3.40) at the apex v = 0 of r = [a cos(u) v, b sin(u) v, v^2].
  subroutine check_apex_singular()
    type(surface_point_t) :: p
    type(darboux_frame_t) :: fr, near, tiny
    real(wp) :: u, sigma, zhat(3), zp(3), zm(3), x_expected(3)
    integer :: k
    character(len=60) :: at
    do k = 1, n_points
      u = two_pi*modulo(0.1_wp + k*0.6180339887498949_wp, 1.0_wp)
      sigma = merge(1.0_wp, -2.0_wp, modulo(k, 2) == 0)
      write (at, '(a, f8.4, a, f5.1)') ' at u = ', u, ', sigma = ', sigma
      call apex%evaluate(u, 0.0_wp, 3, p, st)
      call darboux_frame(p, sigma, 0.5_wp, 1.0_wp, fr, st)
      call check(st%ok() .and. fr%singular .and. .not. fr%second_order, &
                 'apex: singular rule used' // at // ' ' // st%text())
      ! z = sigma r_v x (r_v x r_vv)/|..| = -sign(sigma) e_z at the apex
      call check_close_array(fr%r(:, 3), [0.0_wp, 0.0_wp, -sign(1.0_wp, sigma)], 0.0_wp, exact_tol, &
                             'apex: z_D = (0, 0, -sign sigma)' // at)
      x_expected = [1.3_wp*cos(u), 0.6_wp*sin(u), 0.0_wp]
      call check_close_array(fr%r(:, 1), x_expected/norm2(x_expected), 0.0_wp, exact_tol, &
                             'apex: x_D along r_v' // at)
      call check_close_array(reshape(matmul(transpose(fr%r), fr%r), [9]), &
                             [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                             0.0_wp, exact_tol, 'apex: R^T R = I' // at)
      call check(all(abs([fr%a, fr%b, fr%c, fr%d, fr%e, fr%f]) < 1e3_wp), 'apex: finite rates' // at)
      ! c, d are the u, v derivatives of the field (3.40) (appendix A)
      zp = rule_340(apex, u + h, 0.0_wp, sigma); zm = rule_340(apex, u - h, 0.0_wp, sigma)
      call fd3(fr%c, (zp - zm)/(2*h), 'apex: c = d/du of (3.40)' // at)
      zp = rule_340(apex, u, h, sigma); zm = rule_340(apex, u, -h, sigma)
      call fd3(fr%d, (zp - zm)/(2*h), 'apex: d = d/dv of (3.40)' // at)
      zhat = rule_340(apex, u, 0.0_wp, sigma)
      call check_close_array(fr%r(:, 3), zhat, 0.0_wp, exact_tol, 'apex: z_D = (3.40)' // at)
      ! Below the threshold the rule is used and agrees with the regular
      ! frame just above it to O(distance) (here 1e-6, so 1e-5 allows S ~ 10).
      call apex%evaluate(u, 0.5_wp*singular_tol/2, 3, p, st)
      call darboux_frame(p, sigma, 0.5_wp, 1.0_wp, tiny, st)
      call check(st%ok() .and. tiny%singular, 'apex: rule used below the threshold' // at)
      call apex%evaluate(u, 1e-6_wp, 3, p, st)
      call darboux_frame(p, sigma, 0.5_wp, 1.0_wp, near, st)
      call check(st%ok() .and. .not. near%singular, 'apex: regular at v = 1e-6' // at)
      call check_close_array(reshape(tiny%r, [9]), reshape(near%r, [9]), 0.0_wp, 1e-5_wp, &
                             'apex: frame continuous across the threshold' // at)
      call check_close_array(reshape(fr%r, [9]), reshape(near%r, [9]), 0.0_wp, 1e-5_wp, &
                             'apex: frame at v = 0 is the limit v -> 0+' // at)
      call check_close_array([fr%a, fr%b], [near%a, near%b], 0.0_wp, 1e-5_wp, &
                             'apex: a, b are the limit v -> 0+' // at)
      ! On the circular apex paraboloid the v-curves are normal sections, so
      ! the rates of (3.40) are the limit of the regular rates as well.
      call round_apex%evaluate(u, 0.0_wp, 3, p, st)
      call darboux_frame(p, sigma, 0.5_wp, 1.0_wp, fr, st)
      call round_apex%evaluate(u, 1e-6_wp, 3, p, st)
      call darboux_frame(p, sigma, 0.5_wp, 1.0_wp, near, st)
      call check(fr%singular .and. .not. near%singular, 'round apex: singular and regular')
      call check_close_array([fr%a, fr%b, fr%c, fr%d, fr%e, fr%f], &
                             [near%a, near%b, near%c, near%d, near%e, near%f], 0.0_wp, 1e-5_wp, &
                             'round apex: rates a-f at v = 0 are the limit v -> 0+' // at)
    end do
  end subroutine check_apex_singular

  !> Every term of (A.3): c, d against central differences of the field (3.40)
  !> where r_uvv /= 0 at the singular line.
  subroutine check_twisted_singular()
    type(surface_point_t) :: p
    type(darboux_frame_t) :: fr
    real(wp) :: u, zp(3), zm(3)
    integer :: k
    character(len=40) :: at
    do k = 1, n_points
      u = two_pi*modulo(0.3_wp + k*0.6180339887498949_wp, 1.0_wp)
      write (at, '(a, f8.4)') ' at u = ', u
      call twisted%evaluate(u, 0.0_wp, 3, p, st)
      call darboux_frame(p, -1.0_wp, 0.7_wp, 1.0_wp, fr, st)
      call check(st%ok() .and. fr%singular, 'twisted apex: singular rule' // at)
      zp = rule_340(twisted, u + h, 0.0_wp, -1.0_wp); zm = rule_340(twisted, u - h, 0.0_wp, -1.0_wp)
      call fd3(fr%c, (zp - zm)/(2*h), 'twisted apex: c = d/du of (3.40)' // at)
      zp = rule_340(twisted, u, h, -1.0_wp); zm = rule_340(twisted, u, -h, -1.0_wp)
      call fd3(fr%d, (zp - zm)/(2*h), 'twisted apex: d = d/dv of (3.40)' // at)
      call check_close_array(reshape(matmul(transpose(fr%r), fr%r), [9]), &
                             [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                             0.0_wp, exact_tol, 'twisted apex: R^T R = I' // at)
    end do
  end subroutine check_twisted_singular

  !> The field of (3.40), sigma r_v x (r_v x r_vv)/|..|, evaluated directly.
  function rule_340(s, u, v, sigma) result(z)
    class(surface_t), intent(in) :: s
    real(wp), intent(in) :: u, v, sigma
    real(wp) :: z(3), w(3)
    type(surface_point_t) :: p
    type(status_t) :: st1
    call s%evaluate(u, v, 2, p, st1)
    w = sigma*cross(p%rv, cross(p%rv, p%rvv))
    z = w/norm2(w)
  end function rule_340

  !> Sphere poles v = +-pi/2: z_D from (3.40) is the outward normal (sigma = 1),
  !> the limit of (3.38) from inside the domain, and the rates are the limit too.
  subroutine check_sphere_poles()
    type(surface_point_t) :: p
    type(darboux_frame_t) :: fr, near
    real(wp) :: u, pole
    integer :: k, side
    character(len=60) :: at
    do side = -1, 1, 2
      pole = side*half_pi
      do k = 1, 4
        u = 1.7_wp*k
        write (at, '(a, f7.3, a, f7.3)') ' at u = ', u, ', v = ', pole
        call sphere%evaluate(u, pole, 3, p, st)
        call darboux_frame(p, 1.0_wp, 1.0_wp, 1.0_wp, fr, st)
        call check(st%ok() .and. fr%singular, 'sphere pole: singular rule' // at)
        call check_close_array(fr%r(:, 3), [0.0_wp, 0.0_wp, real(side, wp)], 0.0_wp, exact_tol, &
                               'sphere pole: z_D outward' // at)
        call sphere%evaluate(u, pole - side*1e-6_wp, 3, p, st)
        call darboux_frame(p, 1.0_wp, 1.0_wp, 1.0_wp, near, st)
        call check_close_array(reshape(fr%r, [9]), reshape(near%r, [9]), 0.0_wp, 1e-5_wp, &
                               'sphere pole: frame is the limit from inside' // at)
        call check_close_array([fr%a, fr%b, fr%c, fr%d, fr%e, fr%f], &
                               [near%a, near%b, near%c, near%d, near%e, near%f], 0.0_wp, 1e-5_wp, &
                               'sphere pole: rates are the limit from inside' // at)
      end do
    end do
  end subroutine check_sphere_poles

  !> SINGULAR_RULE_LIMIT: frame and all rates at the singular line v = v0 are
  !> the limits of the regular ones approached from the side `inward`; the
  !> regular frame at distance 1e-7 differs by O(1e-7 S) <= 1e-6, hence 1e-5.
  subroutine check_limit_rule(s, v0, inward, name)
    class(surface_t), intent(in) :: s
    real(wp), intent(in) :: v0, inward
    character(len=*), intent(in) :: name
    type(surface_point_t) :: p
    type(darboux_frame_t) :: fr, near, thesis
    real(wp) :: u, sigma
    integer :: k
    character(len=60) :: at
    do k = 1, n_points
      u = two_pi*modulo(0.15_wp + k*0.6180339887498949_wp, 1.0_wp)
      sigma = merge(1.0_wp, -0.5_wp, modulo(k, 3) /= 0)
      write (at, '(a, f8.4, a, f5.1)') ' at u = ', u, ', sigma = ', sigma
      call s%evaluate(u, v0, 3, p, st)
      call darboux_frame(p, sigma, 0.3_wp, 1.0_wp, fr, st, singular_rule=SINGULAR_RULE_LIMIT)
      call check(st%ok() .and. fr%singular, name // ': singular' // at // ' ' // st%text())
      call darboux_frame(p, sigma, 0.3_wp, 1.0_wp, thesis, st, singular_rule=SINGULAR_RULE_THESIS)
      call check(dot_product(fr%r(:, 3), thesis%r(:, 3)) > 0, name // ': same side as (3.40)' // at)
      call check_close_array(reshape(matmul(transpose(fr%r), fr%r), [9]), &
                             [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                             0.0_wp, exact_tol, name // ': R^T R = I' // at)
      call s%evaluate(u, v0 + inward*1e-7_wp, 3, p, st)
      call darboux_frame(p, sigma, 0.3_wp, 1.0_wp, near, st)
      call check(st%ok() .and. .not. near%singular, name // ': regular nearby' // at)
      call check_close_array(reshape(fr%r, [9]), reshape(near%r, [9]), 0.0_wp, 1e-5_wp, &
                             name // ': frame is the limit' // at)
      call check_close_array([fr%a, fr%b, fr%c, fr%d, fr%e, fr%f], &
                             [near%a, near%b, near%c, near%d, near%e, near%f], 0.0_wp, 1e-5_wp, &
                             name // ': rates a-f are the limit' // at)
    end do
  end subroutine check_limit_rule

  subroutine check_errors()
    type(surface_point_t) :: p
    type(darboux_frame_t) :: fr
    real(wp) :: axes(3, 3)
    logical :: singular
    call ellipsoid%evaluate(0.3_wp, 0.2_wp, 1, p, st)
    call darboux_frame(p, 1.0_wp, 1.0_wp, 0.0_wp, fr, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'order') > 0, &
               'order 1 refused: ' // st%text())
    call ellipsoid%evaluate(0.3_wp, 0.2_wp, 2, p, st)
    call darboux_frame(p, 0.0_wp, 1.0_wp, 0.0_wp, fr, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'sigma = 0') > 0, &
               'sigma = 0 refused: ' // st%text())
    call darboux_frame(p, 1.0_wp, 0.0_wp, 0.0_wp, fr, st)
    call check(st%code == STATUS_DOMAIN, 'alpha = 0 refused: ' // st%text())
    call ellipsoid%evaluate(0.3_wp, 0.2_wp, 2, p, st)
    call darboux_frame(p, 1.0_wp, 1.0_wp, 0.0_wp, fr, st)
    call check(st%ok() .and. .not. fr%second_order .and. all(fr%a_u == 0), &
               'order 2: first rates only')
    call apex%evaluate(0.3_wp, 0.0_wp, 2, p, st)
    call darboux_frame(p, 1.0_wp, 1.0_wp, 1.0_wp, fr, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'order 3') > 0, &
               'singular point at order 2 refused: ' // st%text())
    call apex%evaluate(0.3_wp, 0.0_wp, 3, p, st)
    call darboux_frame(p, 1.0_wp, 1.0_wp, 0.0_wp, fr, st)
    call check(st%code == STATUS_DOMAIN .and. index(st%text(), 'x_D') > 0, &
               'singular point with alpha_v = 0 refused: ' // st%text())
    call darboux_frame(p, 1.0_wp, 1.0_wp, 1.0_wp, fr, st, singular_rule=7)
    call check(st%code == STATUS_INVALID_INPUT, 'unknown singular_rule refused: ' // st%text())
    ! darboux_axes: order 0 and sigma = 0 refused, a singular point flagged
    ! (its axes need order 3), the regular failures as darboux_frame's
    call ellipsoid%evaluate(0.3_wp, 0.2_wp, 0, p, st)
    call darboux_axes(p, 1.0_wp, 1.0_wp, 0.0_wp, axes, singular, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'order') > 0, &
               'axes: order 0 refused: ' // st%text())
    call ellipsoid%evaluate(0.3_wp, 0.2_wp, 1, p, st)
    call darboux_axes(p, 0.0_wp, 1.0_wp, 0.0_wp, axes, singular, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'sigma = 0') > 0, &
               'axes: sigma = 0 refused: ' // st%text())
    call darboux_axes(p, 1.0_wp, 0.0_wp, 0.0_wp, axes, singular, st)
    call check(st%code == STATUS_DOMAIN .and. index(st%text(), 'x_D') > 0, 'axes: alpha = 0 refused: ' // st%text())
    p%rv = 2*p%ru
    call darboux_axes(p, 1.0_wp, 1.0_wp, 0.0_wp, axes, singular, st)
    call check(st%code == STATUS_DOMAIN .and. index(st%text(), 'parallel') > 0, &
               'axes: parallel r_u, r_v refused: ' // st%text())
    call apex%evaluate(0.3_wp, 0.0_wp, 1, p, st)
    call darboux_axes(p, 1.0_wp, 1.0_wp, 1.0_wp, axes, singular, st)
    call check(st%ok() .and. singular, 'axes: singular point flagged')
  end subroutine check_errors

  !> darboux_frame overwrites the whole record it is given (intent(inout), no
  !> default initialisation): a record left over from another point gives the
  !> same bits as a fresh one, at a regular order-3 point, at order 2 (no
  !> second derivatives), at singular points (both rules) and after failures.
  subroutine check_reused_frame()
    type(surface_point_t) :: p
    type(darboux_frame_t) :: stale, fresh
    type(status_t) :: st_stale, st_fresh
    integer :: k, rule
    logical :: same
    real(wp) :: u, v
    integer :: order
    class(surface_t), allocatable :: s
    same = .true.
    do k = 1, 12
      ! a full record (order 3, regular) from elsewhere first
      call ellipsoid%evaluate(0.9_wp + k, 0.4_wp - 0.05_wp*k, 3, p, st)
      call darboux_frame(p, 1.0_wp, 1.0_wp, 0.3_wp, stale, st)
      select case (mod(k, 4))
      case (0)   ! regular, order 3
        s = hyperbolic; u = 0.3_wp*k - 1; v = 0.7_wp - 0.1_wp*k; order = 3
      case (1)   ! regular, order 2
        s = ellipsoid; u = 0.5_wp*k; v = 0.1_wp*k - 0.6_wp; order = 2
      case (2)   ! singular: the apex
        s = apex; u = 0.4_wp*k; v = 0; order = 3
      case default   ! failure: a singular point at order 2
        s = apex; u = 0.4_wp*k; v = 0; order = 2
      end select
      rule = SINGULAR_RULE_THESIS
      if (k > 6) rule = SINGULAR_RULE_LIMIT
      call s%evaluate(u, v, order, p, st)
      call darboux_frame(p, -1.0_wp, 0.6_wp, 0.8_wp, stale, st_stale, singular_rule=rule)
      call darboux_frame(p, -1.0_wp, 0.6_wp, 0.8_wp, fresh, st_fresh, singular_rule=rule)
      same = same .and. st_stale%code == st_fresh%code .and. frame_bits_equal(stale, fresh)
      fresh = darboux_frame_t()
    end do
    call check(same, 'a reused frame record gives the bits of a fresh one (regular, order 2, singular, failed)')
  end subroutine check_reused_frame

  logical function frame_bits_equal(a, b) result(same)
    type(darboux_frame_t), intent(in) :: a, b
    same = same_bits(reshape(a%r, [9]), reshape(b%r, [9])) .and. &
           same_bits([a%a, a%b, a%c, a%d, a%e, a%f], [b%a, b%b, b%c, b%d, b%e, b%f]) .and. &
           same_bits([a%a_u, a%a_v, a%b_u, a%b_v, a%c_u, a%c_v, a%d_u, a%d_v, a%e_u, a%e_v, a%f_u, a%f_v], &
                     [b%a_u, b%a_v, b%b_u, b%b_v, b%c_u, b%c_v, b%d_u, b%d_v, b%e_u, b%e_v, b%f_u, b%f_v]) .and. &
           (a%singular .eqv. b%singular) .and. (a%second_order .eqv. b%second_order)
  end function frame_bits_equal

  !> The same bit patterns (so -0 differs from +0, and NaN equals its copy).
  logical function same_bits(x, y) result(same)
    real(wp), intent(in) :: x(:), y(:)
    same = size(x) == size(y)
    if (same) same = all(transfer(x, 0_int64, size(x)) == transfer(y, 0_int64, size(y)))
  end function same_bits
end program test_geometry_darboux
