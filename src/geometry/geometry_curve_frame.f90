!> The moving frame of a centerline from a horizon vector field (thesis 2.12,
!> 3.60-3.63, appendix C.1), its u-derivatives to third order, and the
!> centerline curvature chi and its derivative chi_u (thesis 4.8-4.9).
!>
!>   x = c_u/|c_u|,  y = (h x x)/|h x x|,  z = x x y
!>
!> The derivatives are not the expanded expressions C.4-C.15 but the same
!> quantities computed by two rules that are easy to check: for e = a/|a|
!> with L = |a| (L L' = a.a', L'^2 + L L'' = a'.a' + a.a'',
!> 3 L' L'' + L L''' = 3 a'.a'' + a.a'''),
!>   e' = (a' - L' e)/L,  e'' = (a'' - 2 L' e' - L'' e)/L,
!>   e''' = (a''' - 3 L' e'' - 3 L'' e' - L''' e)/L,
!> and Leibniz' rule for the cross products h x x and x x y (C.7-C.9, C.13-C.15;
!> note C.14 as printed lacks "x y" in its first term: z_uu = x_uu x y + ...).
!> The third derivative of x needs c_uuuu (C.6).
module geometry_curve_frame
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN, STATUS_INVALID_INPUT
  use base_vector, only: cross
  use geometry_curve, only: curve_t, curve_point_t
  implicit none (type, external)
  private
  public :: curve_frame_t, curve_frame_from_points, curve_frame_at
  public :: centerline_curvature, curve_curvature, horizon_parallel_tol

  !> Smallest allowed sine of the angle between the horizon and the tangent;
  !> below it the y-axis (3.62) is numerically undefined.
  real(wp), parameter :: horizon_parallel_tol = 1e-6_wp

  !> Axes of the frame and their u-derivatives: x(:, k) = d^k x/du^k, k <= order.
  type :: curve_frame_t
    integer :: order = 0
    real(wp) :: x(3, 0:3) = 0, y(3, 0:3) = 0, z(3, 0:3) = 0
    real(wp) :: chi = 0      ! centerline curvature, 1/m (4.8); needs order >= 1
    real(wp) :: chi_u = 0    ! d chi/du, 1/(m unit of u) (4.9); needs order >= 2
  end type curve_frame_t

contains

  !> Unit vector e = a/|a| and its derivatives to order n (<= 3) from those
  !> of a, with l = |a| (the caller has it); e(:, n+1:) is left as it is.
  pure subroutine normalized_derivatives(a, l, n, e)
    real(wp), intent(in) :: a(3, 0:3), l
    integer, intent(in) :: n
    real(wp), intent(inout) :: e(3, 0:3)
    real(wp) :: l1, l2, l3   ! derivatives of l
    e(:, 0) = a(:, 0)/l
    if (n < 1) return
    l1 = dot_product(e(:, 0), a(:, 1))
    e(:, 1) = (a(:, 1) - l1*e(:, 0))/l
    if (n < 2) return
    l2 = (dot_product(a(:, 0), a(:, 2)) + dot_product(a(:, 1), a(:, 1)) - l1**2)/l
    e(:, 2) = (a(:, 2) - 2*l1*e(:, 1) - l2*e(:, 0))/l
    if (n < 3) return
    l3 = (3*dot_product(a(:, 1), a(:, 2)) + dot_product(a(:, 0), a(:, 3)) - 3*l1*l2)/l
    e(:, 3) = (a(:, 3) - 3*l1*e(:, 2) - 3*l2*e(:, 1) - l3*e(:, 0))/l
  end subroutine normalized_derivatives

  !> Leibniz' rule for a x b to order n (c(:, n+1:) is left as it is).
  !> Derivatives of a that are zero (a constant horizon) add nothing and are
  !> skipped; the terms are written out per order (the frame is on the hot
  !> path of every tube evaluation), each sum from 0 in the order of j.
  pure subroutine cross_derivatives(a, b, n, c)
    real(wp), intent(in) :: a(3, 0:3), b(3, 0:3)
    integer, intent(in) :: n
    real(wp), intent(inout) :: c(3, 0:3)
    logical :: a_zero(3)
    integer :: j
    do j = 1, n
      a_zero(j) = all(a(:, j) == 0)
    end do
    c(:, 0) = 0 + cross(a(:, 0), b(:, 0))
    if (n < 1) return
    c(:, 1) = 0 + cross(a(:, 0), b(:, 1))
    if (.not. a_zero(1)) c(:, 1) = c(:, 1) + cross(a(:, 1), b(:, 0))
    if (n < 2) return
    c(:, 2) = 0 + cross(a(:, 0), b(:, 2))
    if (.not. a_zero(1)) c(:, 2) = c(:, 2) + 2*cross(a(:, 1), b(:, 1))
    if (.not. a_zero(2)) c(:, 2) = c(:, 2) + cross(a(:, 2), b(:, 0))
    if (n < 3) return
    c(:, 3) = 0 + cross(a(:, 0), b(:, 3))
    if (.not. a_zero(1)) c(:, 3) = c(:, 3) + 3*cross(a(:, 1), b(:, 2))
    if (.not. a_zero(2)) c(:, 3) = c(:, 3) + 3*cross(a(:, 2), b(:, 1))
    if (.not. a_zero(3)) c(:, 3) = c(:, 3) + cross(a(:, 3), b(:, 0))
  end subroutine cross_derivatives

  !> Curvature chi = |c_u x c_uu|/|c_u|^3 (4.8) of the curve point c and, if
  !> c holds c_uuu, its derivative chi_u (4.9); see curve_curvature.
  pure subroutine centerline_curvature(c, chi, chi_u)
    type(curve_point_t), intent(in) :: c
    real(wp), intent(out) :: chi, chi_u
    call curve_curvature(c%d(:, 0:3), c%order, chi, chi_u)
  end subroutine centerline_curvature

  !> The one curvature of a curve (the tube's frame, the water's friction):
  !> chi = |c' x c''|/|c'|^3 (4.8) from d(:, k) = d^k c/du^k (k = 1..order)
  !> and, for order >= 3, chi_u = (|q|_u |c'|^3 - |q| (|c'|^3)_u)/|c'|^6
  !> (4.9), q = c' x c'', |q|_u = q.(c' x c''')/|q|, (|c'|^3)_u =
  !> 3 (c'.c'') |c'|. order < 2: chi = chi_u = 0.
  !> The zero test: where |c' x c''| <= 1e-14 |c'|^3, i.e. chi <= 1e-14 /m (a
  !> radius of curvature beyond 1e14 m: a straight piece, or the inflection
  !> of an S-bend, where |q| has a kink and no derivative), chi_u = 0.
  pure subroutine curve_curvature(d, order, chi, chi_u)
    real(wp), intent(in) :: d(3, 0:3)
    integer, intent(in) :: order
    real(wp), intent(out) :: chi, chi_u
    real(wp) :: k(3), speed, k_norm, k_norm_u, speed3_u
    chi = 0; chi_u = 0
    if (order < 2) return
    k = cross(d(:, 1), d(:, 2))
    speed = norm2(d(:, 1))
    k_norm = norm2(k)
    chi = k_norm/speed**3
    if (order < 3 .or. k_norm <= 1e-14_wp*speed**3) return
    k_norm_u = dot_product(cross(d(:, 1), d(:, 3)), k)/k_norm
    speed3_u = 3*dot_product(d(:, 1), d(:, 2))*speed
    chi_u = (k_norm_u*speed**3 - k_norm*speed3_u)/speed**6
  end subroutine curve_curvature

  !> The frame (3.60-3.63) and its derivatives to `order` (0..3) from the
  !> centerline point c (needs derivatives to order+1) and the horizon h
  !> (needs derivatives to `order`). chi needs order >= 1, chi_u order >= 2;
  !> with_curvature = .false. leaves them 0 (a tube's evaluation needs none).
  pure subroutine curve_frame_from_points(c, h, order, f, status, with_curvature)
    type(curve_point_t), intent(in) :: c, h
    integer, intent(in) :: order
    type(curve_frame_t), intent(out) :: f
    type(status_t), intent(out) :: status
    logical, intent(in), optional :: with_curvature
    real(wp) :: w(3, 0:3), speed, hn, wn
    character(len=40) :: buf
    if (order < 0 .or. order > 3) then
      call set_status(status, STATUS_INVALID_INPUT, 'curve frame: order must be 0..3')
      return
    end if
    f%order = order
    speed = norm2(c%d(:, 1))
    if (.not. speed > 0) then
      call set_status(status, STATUS_DOMAIN, 'curve frame: centerline tangent c_u is zero')
      return
    end if
    call normalized_derivatives(c%d(:, 1:4), speed, order, f%x)
    call cross_derivatives(h%d(:, 0:3), f%x, order, w)
    hn = sqrt(dot_product(h%d(:, 0), h%d(:, 0)))   ! only for the check: no scaled norm2 needed
    wn = norm2(w(:, 0))
    if (.not. wn > horizon_parallel_tol*hn) then
      write (buf, '(es12.4)') wn/max(hn, tiny(1.0_wp))
      call set_status(status, STATUS_DOMAIN, 'curve frame: horizon vector is parallel to the ' // &
                      'centerline tangent (sine of angle ' // trim(adjustl(buf)) // ')')
      return
    end if
    call normalized_derivatives(w, wn, order, f%y)
    call cross_derivatives(f%x, f%y, order, f%z)
    if (present(with_curvature)) then
      if (.not. with_curvature) return
    end if
    if (order >= 1) call centerline_curvature(c, f%chi, f%chi_u)
    if (order < 2) f%chi_u = 0
  end subroutine curve_frame_from_points

  !> The frame at u of a centerline and a horizon field.
  pure subroutine curve_frame_at(centerline, horizon, u, order, f, status, c)
    class(curve_t), intent(in) :: centerline, horizon
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_frame_t), intent(out) :: f
    type(status_t), intent(out) :: status
    type(curve_point_t), intent(out), optional :: c   ! the centerline point used
    type(curve_point_t) :: cp, hp
    call centerline%evaluate(u, order + 1, cp, status)
    if (.not. status%ok()) return
    call horizon%evaluate(u, order, hp, status)
    if (.not. status%ok()) return
    call curve_frame_from_points(cp, hp, order, f, status)
    if (present(c)) c = cp
  end subroutine curve_frame_at
end module geometry_curve_frame
