!> The Darboux frame of the surface joint, thesis 3.5.1 (3.37)-(3.51), with the
!> rule at singular points where r_u = 0 (3.39)-(3.40) and appendix A.
!>
!>     x_D = (alpha_u r_u + alpha_v r_v)/|...|             (3.41)
!>     z_D = sigma r_u x r_v/|...|                          (3.38)
!>     y_D = z_D x x_D                                      (3.42)
!>
!> and the rate vectors of (3.45): dx_D/dt = a u' + b v', dz_D/dt = c u' + d v',
!> dy_D/dt = e u' + f v', i.e. a = dx_D/du, b = dx_D/dv, c = dz_D/du,
!> d = dz_D/dv, e = dy_D/du, f = dy_D/dv (3.46)-(3.51).
!>
!> Every unit vector here is n = w/|w| of some field w(u, v); its derivative is
!> n_u = (w_u - n (n.w_u))/|w|, which is (3.46)-(3.49) written without the
!> double cross product: -w x (w x w_u)/|w|^3 = (w_u |w|^2 - w (w.w_u))/|w|^3.
!>
!> Singular points. r_u counts as zero when |r_u| <= singular_tol |r_v| with
!> singular_tol = sqrt(epsilon) ~ 1.5e-8: above it the regular normal is
!> accurate to ~ (rounding of r_u)/|r_u| <= sqrt(epsilon) even when r_u carries
!> absolute rounding noise of epsilon |r_v| (as fitted surfaces do), and
!> below it the rule (3.40) differs from the true normal by O(distance to the
!> singular point) = O(sqrt(epsilon)). There z_D is taken from (3.40),
!>     z_D = sigma r_v x (r_v x r_vv)/|...|,
!> the right-hand side of (3.40)/(A.1). (The middle form sigma t_v/|t_v| of
!> (3.40) has the opposite sign, since t_v = -r_v x (r_v x r_vv)/|r_v|^3; the
!> right-hand side is the one that equals the limit of (3.38) at the poles of
!> the ellipsoid and at the apex of the apex paraboloid approached from v > 0.)
!> Its rates c, d are (A.5)-(A.7), the u and v derivatives of that field; they
!> need r_uvv and r_vvv, so a singular point must be evaluated to order 3.
!> The rule (3.40) gives the surface normal only where the v-curve's curvature
!> vector is normal to the surface, and its rates c, d are the derivatives of
!> the field (3.40), which equal the limits of the regular rates only where
!> the v-curves are lines of curvature (e.g. a circular apex paraboloid, a
!> sphere's poles); on the apex paraboloid with a /= b they differ.
!> The optional rule SINGULAR_RULE_LIMIT instead takes the limit of (3.38) at
!> a pole-type singularity, where r_u = 0 along the whole line v = v0
!> (so r_uu = r_uuu = 0 there): with delta = v - v0,
!>     r_u x r_v = delta [r_uv x r_v + delta (r_uvv x r_v/2 + r_uv x r_vv) + ...],
!> so z_D = +-sigma (r_uv x r_v)/|...| with rates from the bracket's
!> derivatives r_uuv x r_v (in u) and r_uvv x r_v/2 + r_uv x r_vv (in v). The
!> sign is the one of the side (3.40) points to. Frame and rates are then the
!> limits of the regular ones (to O(delta) at points below the threshold).
!> x_D is (3.41) projected onto the plane normal to z_D (it differs from it
!> only by O(singular_tol)), so the frame stays orthonormal.
!>
!> Second derivatives (for the acceleration map, appendix B) are filled when
!> the point has order 3 and is regular: a_u = x_uu, a_v = b_u = x_uv,
!> b_v = x_vv, and likewise c/d for z and e/f for y. At singular points they
!> would need fourth partials of r and are left zero (second_order = .false.).
module geometry_darboux
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_vector, only: cross
  use geometry_surface, only: surface_point_t
  implicit none (type, external)
  private
  public :: darboux_frame_t, darboux_frame, darboux_axes, singular_tol
  public :: SINGULAR_RULE_THESIS, SINGULAR_RULE_LIMIT

  !> Singular-point rules: (3.40) with appendix A (default), or the limit of (3.38).
  integer, parameter :: SINGULAR_RULE_THESIS = 1, SINGULAR_RULE_LIMIT = 2

  !> |r_u| <= singular_tol |r_v| selects the singular-point rule (see above).
  real(wp), parameter :: singular_tol = sqrt(epsilon(1.0_wp))

  type :: darboux_frame_t
    !> Columns x_D, y_D, z_D in the surface's coordinates (3.37).
    real(wp) :: r(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    !> Rates (3.45): x_u, x_v, z_u, z_v, y_u, y_v (1/unit of u or v).
    real(wp) :: a(3) = 0, b(3) = 0, c(3) = 0, d(3) = 0, e(3) = 0, f(3) = 0
    !> A singular-point rule was used (|r_u| <= singular_tol |r_v|).
    logical :: singular = .false.
    !> The second derivatives below are filled (order-3 point, regular).
    logical :: second_order = .false.
    real(wp) :: a_u(3) = 0, a_v(3) = 0, b_u(3) = 0, b_v(3) = 0   ! x_uu, x_uv, x_uv, x_vv
    real(wp) :: c_u(3) = 0, c_v(3) = 0, d_u(3) = 0, d_v(3) = 0   ! z_uu, z_uv, z_uv, z_vv
    real(wp) :: e_u(3) = 0, e_v(3) = 0, f_u(3) = 0, f_v(3) = 0   ! y_uu, y_uv, y_uv, y_vv
  end type darboux_frame_t

contains

  !> The Darboux frame at the surface point p (order >= 2; order 3 at singular
  !> points and for the second derivatives). sigma /= 0 orients z_D (3.38);
  !> alpha_u, alpha_v choose x_D (3.41). Fails (STATUS_DOMAIN) where r_u and r_v
  !> are parallel or both zero, where x_D is undefined (alpha_u r_u + alpha_v r_v
  !> = 0) or where the singular rule is undefined (r_vv parallel to r_v for
  !> (3.40), r_uv parallel to r_v for the limit rule). singular_rule selects
  !> SINGULAR_RULE_THESIS (default) or SINGULAR_RULE_LIMIT (see above).
  !> frame is filled entirely (intent(inout) only to spare the hot path the
  !> default initialisation of a record it overwrites); on failure it is the
  !> default frame.
  pure subroutine darboux_frame(p, sigma, alpha_u, alpha_v, frame, status, singular_rule)
    type(surface_point_t), intent(in) :: p
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    type(darboux_frame_t), intent(inout) :: frame
    type(status_t), intent(out) :: status
    integer, intent(in), optional :: singular_rule
    real(wp) :: w(3), wu(3), wv(3), wuu(3), wuv(3), wvv(3), w340(3)
    real(wp) :: x(3), y(3), z(3), norm_ru, norm_rv, norm_w
    logical :: second, limit_rule

    wuu = 0; wuv = 0; wvv = 0
    if (p%order < 2) then
      call set_status(status, STATUS_INVALID_INPUT, &
                      'Darboux frame: the surface point must be evaluated to order >= 2')
      frame = darboux_frame_t()
      return
    end if
    call check_sigma(sigma, status)
    if (.not. status%ok()) then
      frame = darboux_frame_t()
      return
    end if
    limit_rule = .false.
    if (present(singular_rule)) then
      if (singular_rule /= SINGULAR_RULE_THESIS .and. singular_rule /= SINGULAR_RULE_LIMIT) then
        call set_status(status, STATUS_INVALID_INPUT, 'Darboux frame: unknown singular_rule')
        frame = darboux_frame_t()
        return
      end if
      limit_rule = singular_rule == SINGULAR_RULE_LIMIT
    end if
    norm_ru = norm2(p%ru)
    norm_rv = norm2(p%rv)
    frame%singular = norm_ru <= singular_tol*norm_rv .or. norm_rv == 0
    second = p%order >= 3 .and. .not. frame%singular

    ! z_D and its derivatives.
    if (.not. frame%singular) then
      ! thesis (3.38), (3.48), (3.49)
      w = sigma*local_cross(p%ru, p%rv)
      norm_w = norm2(w)
      if (norm_w <= singular_tol*abs(sigma)*norm_ru*norm_rv) then
        call fail_parallel(status)
        frame = darboux_frame_t()
        return
      end if
      wu = sigma*(local_cross(p%ruu, p%rv) + local_cross(p%ru, p%ruv))
      wv = sigma*(local_cross(p%ruv, p%rv) + local_cross(p%ru, p%rvv))
      if (second) then
        wuu = sigma*(local_cross(p%ruuu, p%rv) + 2*local_cross(p%ruu, p%ruv) + local_cross(p%ru, p%ruuv))
        wuv = sigma*(local_cross(p%ruuv, p%rv) + local_cross(p%ruu, p%rvv) + local_cross(p%ru, p%ruvv))
        wvv = sigma*(local_cross(p%ruvv, p%rv) + 2*local_cross(p%ruv, p%rvv) + local_cross(p%ru, p%rvvv))
      end if
    else
      ! thesis (3.40), (A.1); rates (A.3), (A.5)-(A.7); or the limit rule
      if (norm_rv == 0) then
        call set_status(status, STATUS_DOMAIN, &
                        'Darboux frame: r_u = 0 and r_v = 0; the frame is undefined')
        frame = darboux_frame_t()
        return
      end if
      if (p%order < 3) then
        call set_status(status, STATUS_INVALID_INPUT, 'Darboux frame: singular point (r_u = 0) ' // &
                        'needs the surface point evaluated to order 3')
        frame = darboux_frame_t()
        return
      end if
      w340 = sigma*local_cross(p%rv, local_cross(p%rv, p%rvv))
      if (limit_rule) then
        w = sigma*local_cross(p%ruv, p%rv)
        norm_w = norm2(w)
        if (norm_w <= singular_tol*abs(sigma)*norm2(p%ruv)*norm_rv) then
          call set_status(status, STATUS_DOMAIN, 'Darboux frame: singular point (r_u = 0) where ' // &
                          'r_uv is parallel to r_v; the limit of the normal is undefined')
          frame = darboux_frame_t()
          return
        end if
        wu = sigma*local_cross(p%ruuv, p%rv)
        wv = sigma*(local_cross(p%ruvv, p%rv)/2 + local_cross(p%ruv, p%rvv))
        if (dot_product(w, w340) < 0) then
          w = -w; wu = -wu; wv = -wv
        end if
      else
        w = w340
        norm_w = norm2(w)
        if (norm_w <= singular_tol*abs(sigma)*norm_rv**2*norm2(p%rvv)) then
          call set_status(status, STATUS_DOMAIN, 'Darboux frame: singular point (r_u = 0) where ' // &
                          'r_vv is parallel to r_v; the rule (3.40) is undefined')
          frame = darboux_frame_t()
          return
        end if
        wu = sigma*(local_cross(p%ruv, local_cross(p%rv, p%rvv)) + &
                    local_cross(p%rv, local_cross(p%ruv, p%rvv) + local_cross(p%rv, p%ruvv)))   ! c_1 of (A.3)
        wv = sigma*(local_cross(p%rvv, local_cross(p%rv, p%rvv)) + &
                    local_cross(p%rv, local_cross(p%rv, p%rvvv)))                          ! d_1 of (A.3)
      end if
    end if
    call unit_and_derivatives(w, norm_w, wu, wv, wuu, wuv, wvv, second, z, frame%c, frame%d, &
                              frame%c_u, frame%c_v, frame%d_v)

    ! x_D and its derivatives, thesis (3.41), (3.46), (3.47).
    w = alpha_u*p%ru + alpha_v*p%rv
    norm_w = norm2(w)
    if (norm_w <= singular_tol*(abs(alpha_u)*norm_ru + abs(alpha_v)*norm_rv)) then
      call fail_x_undefined(status)
      frame = darboux_frame_t()
      return
    end if
    wu = alpha_u*p%ruu + alpha_v*p%ruv
    wv = alpha_u*p%ruv + alpha_v*p%rvv
    if (second) then
      wuu = alpha_u*p%ruuu + alpha_v*p%ruuv
      wuv = alpha_u*p%ruuv + alpha_v*p%ruvv
      wvv = alpha_u*p%ruvv + alpha_v*p%rvvv
    end if
    call unit_and_derivatives(w, norm_w, wu, wv, wuu, wuv, wvv, second, x, frame%a, frame%b, &
                              frame%a_u, frame%a_v, frame%b_v)
    if (frame%singular) x = (x - dot_product(x, z)*z)/norm2(x - dot_product(x, z)*z)

    ! y_D = z_D x x_D (3.42) and its derivatives (3.50), (3.51).
    y = local_cross(z, x)
    frame%e = local_cross(frame%c, x) + local_cross(z, frame%a)
    frame%f = local_cross(frame%d, x) + local_cross(z, frame%b)
    if (second) then
      frame%e_u = local_cross(frame%c_u, x) + 2*local_cross(frame%c, frame%a) + local_cross(z, frame%a_u)
      frame%e_v = local_cross(frame%c_v, x) + local_cross(frame%c, frame%b) + local_cross(frame%d, frame%a) &
                  + local_cross(z, frame%a_v)
      frame%f_v = local_cross(frame%d_v, x) + 2*local_cross(frame%d, frame%b) + local_cross(z, frame%b_v)
      frame%b_u = frame%a_v
      frame%d_u = frame%c_v
      frame%f_u = frame%e_v
    else
      frame%a_u = 0; frame%a_v = 0; frame%b_u = 0; frame%b_v = 0
      frame%c_u = 0; frame%c_v = 0; frame%d_u = 0; frame%d_v = 0
      frame%e_u = 0; frame%e_v = 0; frame%f_u = 0; frame%f_v = 0
    end if
    frame%second_order = second
    frame%r(:, 1) = x
    frame%r(:, 2) = y
    frame%r(:, 3) = z
  contains
    !> base_vector's cross, local: LTO does not inline that one into this long
    !> routine (--param max-inline-insns-auto), this one it does (-1.3 % of
    !> the egg's instructions, the same operations).
    pure function local_cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c(1) = a(2)*b(3) - a(3)*b(2)
      c(2) = a(3)*b(1) - a(1)*b(3)
      c(3) = a(1)*b(2) - a(2)*b(1)
    end function local_cross
  end subroutine darboux_frame

  !> The axes alone (columns x_D, y_D, z_D) at a point p evaluated to order
  !> >= 1, for a position map that needs no rates: at a regular point the same
  !> axes and failures as darboux_frame. singular = .true. where the
  !> singular-point rule applies (|r_u| <= singular_tol |r_v|); the axes are
  !> then not set (they need p to order 3: call darboux_frame).
  pure subroutine darboux_axes(p, sigma, alpha_u, alpha_v, axes, singular, status)
    type(surface_point_t), intent(in) :: p
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    real(wp), intent(out) :: axes(3, 3)
    logical, intent(out) :: singular
    type(status_t), intent(out) :: status
    real(wp) :: w(3), x(3), z(3), norm_ru, norm_rv, s
    axes = 0
    singular = .false.
    if (p%order < 1) then
      call set_status(status, STATUS_INVALID_INPUT, &
                      'Darboux axes: the surface point must be evaluated to order >= 1')
      return
    end if
    call check_sigma(sigma, status)
    if (.not. status%ok()) return
    norm_ru = norm2(p%ru)
    norm_rv = norm2(p%rv)
    singular = norm_ru <= singular_tol*norm_rv .or. norm_rv == 0
    if (singular) return
    ! z_D (3.38) and x_D (3.41) as unit_and_derivatives forms them
    w = sigma*cross(p%ru, p%rv)
    s = norm2(w)
    if (s <= singular_tol*abs(sigma)*norm_ru*norm_rv) then
      call fail_parallel(status)
      return
    end if
    z = w/s
    w = alpha_u*p%ru + alpha_v*p%rv
    s = norm2(w)
    if (s <= singular_tol*(abs(alpha_u)*norm_ru + abs(alpha_v)*norm_rv)) then
      call fail_x_undefined(status)
      return
    end if
    x = w/s
    axes(:, 1) = x
    axes(:, 2) = cross(z, x)
    axes(:, 3) = z
  end subroutine darboux_axes

  !> sigma orients z_D (3.38): any value but 0.
  pure subroutine check_sigma(sigma, status)
    real(wp), intent(in) :: sigma
    type(status_t), intent(inout) :: status
    if (sigma == 0) call set_status(status, STATUS_INVALID_INPUT, 'Darboux frame: sigma = 0 is not allowed')
  end subroutine check_sigma

  pure subroutine fail_parallel(status)
    type(status_t), intent(inout) :: status
    call set_status(status, STATUS_DOMAIN, 'Darboux frame: r_u and r_v are parallel; the surface normal is undefined')
  end subroutine fail_parallel

  pure subroutine fail_x_undefined(status)
    type(status_t), intent(inout) :: status
    call set_status(status, STATUS_DOMAIN, 'Darboux frame: alpha_u r_u + alpha_v r_v = 0; ' // &
                    'x_D is undefined (at r_u = 0 alpha_v must not be 0)')
  end subroutine fail_x_undefined

  !> n = w/|w| and its partials from those of w (w /= 0, s = |w|):
  !> n_u = (w_u - n (n.w_u))/|w|, and, if `second`,
  !> n_uv = (w_uv - n_v (n.w_u) - n (n_v.w_u + n.w_uv))/|w| - n_u (n.w_v)/|w|.
  pure subroutine unit_and_derivatives(w, s, wu, wv, wuu, wuv, wvv, second, n, nu, nv, nuu, nuv, nvv)
    real(wp), intent(in) :: w(3), s, wu(3), wv(3), wuu(3), wuv(3), wvv(3)
    logical, intent(in) :: second
    real(wp), intent(out) :: n(3), nu(3), nv(3)
    real(wp), intent(inout) :: nuu(3), nuv(3), nvv(3)
    n = w/s
    nu = (wu - n*dot_product(n, wu))/s
    nv = (wv - n*dot_product(n, wv))/s
    if (.not. second) return
    nuu = (wuu - nu*dot_product(n, wu) - n*(dot_product(nu, wu) + dot_product(n, wuu)))/s &
          - nu*dot_product(n, wu)/s
    nuv = (wuv - nv*dot_product(n, wu) - n*(dot_product(nv, wu) + dot_product(n, wuv)))/s &
          - nu*dot_product(n, wv)/s
    nvv = (wvv - nv*dot_product(n, wv) - n*(dot_product(nv, wv) + dot_product(n, wvv)))/s &
          - nv*dot_product(n, wv)/s
  end subroutine unit_and_derivatives
end module geometry_darboux
