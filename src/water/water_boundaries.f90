!> The water's edges on the slide surface (thesis 4.25-4.26).
!>
!> From the streamline point r with frame K_w, the points
!>     r_wL = r + h z_w + (b/2) y_w,   r_wR = r + h z_w - (b/2) y_w
!> are the ends of the water surface across the flow. Each edge is the surface
!> point (u_e, v_e) whose Darboux frame (sigma = 1, alpha_u = 0, alpha_v = 1)
!> sees r_wL (r_wR) straight along its normal:
!>     (r_D - r_wL).x_D = 0,  (r_D - r_wL).y_D = 0          (4.25), (4.26)
!> solved by HYBRJ with the analytic Jacobian
!>     d/du [(r_D - q).x_D] = r_u.x_D + (r_D - q).x_D,u  (x_D,u = frame%a), ...
!> started from the streamline point moved by +-(b/2) y_w in the tangent plane.
!> The left edge lies towards +y_w, i.e. towards larger v.
module water_boundaries
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use geometry_surface, only: surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, &
                                solve_nonlinear
  use water_channel, only: channel_t
  use water_streamline, only: water_point_t
  implicit none (type, external)
  private
  public :: water_edges, edge_system_t

  !> Foot of the normal from `target` onto the channel surface, in (u, v).
  type, extends(nonlinear_system_t) :: edge_system_t
    class(channel_t), pointer :: channel => null()
    real(wp) :: target(3) = 0
    ! HYBRJ asks for the residual and the Jacobian at the same point: keep the
    ! last evaluation (surface point and frame) to serve both
    real(wp) :: x_last(2) = huge(1.0_wp)
    type(surface_point_t) :: p_last
    type(darboux_frame_t) :: frame_last
  contains
    procedure :: residual => edge_residual
    procedure :: jacobian => edge_jacobian
    procedure :: point => edge_point
  end type edge_system_t

contains

  !> Left and right edges [u, v] and their points for the water point q.
  subroutine water_edges(channel, q, left, right, left_point, right_point, status)
    class(channel_t), intent(in), target :: channel
    type(water_point_t), intent(in) :: q
    real(wp), intent(out) :: left(2), right(2), left_point(3), right_point(3)
    type(status_t), intent(out) :: status
    type(edge_system_t) :: sys
    type(nonlinear_options_t) :: options
    type(nonlinear_result_t) :: result
    real(wp) :: d(2), uv(2), base(3), e, f, g, det, bu, bv
    type(surface_point_t) :: p

    options%xtol = 1e-10_wp   ! relative: ~1e-8 m on a 70 m slide; residual still <= 1e-10 m
    options%residual_tolerance = 1e-10_wp
    sys%channel => channel
    base = q%position + q%height*q%z_m
    ! first guess: the offset (b/2) y_w in the tangent plane, mapped to (du, dv)
    e = dot_product(q%p%ru, q%p%ru); f = dot_product(q%p%ru, q%p%rv); g = dot_product(q%p%rv, q%p%rv)
    bu = 0.5_wp*q%width*dot_product(q%p%ru, q%y_w); bv = 0.5_wp*q%width*dot_product(q%p%rv, q%y_w)
    det = e*g - f*f
    d = [(g*bu - f*bv)/det, (e*bv - f*bu)/det]
    uv = [q%u, q%v] + d
    sys%target = base + 0.5_wp*q%width*q%y_w
    call solve_nonlinear(sys, uv, options, result, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'left water edge (4.25)')
      return
    end if
    left = uv
    call channel%evaluate(uv(1), uv(2), 0, p, status)
    left_point = p%r
    uv = [q%u, q%v] - d
    sys%target = base - 0.5_wp*q%width*q%y_w
    call solve_nonlinear(sys, uv, options, result, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'right water edge (4.26)')
      return
    end if
    right = uv
    call channel%evaluate(uv(1), uv(2), 0, p, status)
    right_point = p%r
  end subroutine water_edges

  !> Surface point and Darboux frame (sigma = 1, alpha_u = 0, alpha_v = 1) at x,
  !> reused when x is the last point asked for.
  subroutine edge_point(self, x, status)
    class(edge_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    type(status_t), intent(inout) :: status
    if (all(x == self%x_last)) return
    call self%channel%evaluate(x(1), x(2), 2, self%p_last, status)
    if (.not. status%ok()) return
    call darboux_frame(self%p_last, 1.0_wp, 0.0_wp, 1.0_wp, self%frame_last, status)
    if (.not. status%ok()) return
    self%x_last = x
  end subroutine edge_point

  subroutine edge_residual(self, x, f, status)
    class(edge_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    call self%point(x, status)
    if (.not. status%ok()) return
    associate (p => self%p_last, frame => self%frame_last)
      f(1) = dot_product(p%r - self%target, frame%r(:, 1))
      f(2) = dot_product(p%r - self%target, frame%r(:, 2))
    end associate
  end subroutine edge_residual

  subroutine edge_jacobian(self, x, jac, status)
    class(edge_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: d(3)
    call self%point(x, status)
    if (.not. status%ok()) return
    associate (p => self%p_last, frame => self%frame_last)
      d = p%r - self%target
      jac(1, 1) = dot_product(p%ru, frame%r(:, 1)) + dot_product(d, frame%a)
      jac(1, 2) = dot_product(p%rv, frame%r(:, 1)) + dot_product(d, frame%b)
      jac(2, 1) = dot_product(p%ru, frame%r(:, 2)) + dot_product(d, frame%e)
      jac(2, 2) = dot_product(p%rv, frame%r(:, 2)) + dot_product(d, frame%f)
    end associate
  end subroutine edge_jacobian
end module water_boundaries
