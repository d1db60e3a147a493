!> The water's edges on the slide surface (thesis 4.25-4.26).
!>
!> From the streamline point r with frame K_w, the points
!>     r_wL = r + h z_w + (b/2) y_w,   r_wR = r + h z_w - (b/2) y_w
!> are the ends of the water surface across the flow. Each edge is the surface
!> point (u_e, v_e) whose Darboux frame (sigma = 1, alpha_u = 0, alpha_v = 1)
!> sees r_wL (r_wR) straight along its normal:
!>     (r_D - r_wL).x_D = 0,  (r_D - r_wL).y_D = 0          (4.25), (4.26)
!> with the analytic Jacobian
!>     d/du [(r_D - q).x_D] = r_u.x_D + (r_D - q).x_D,u  (x_D,u = frame%a), ...
!>
!> Solver (geometry_foot_point, FOOT_FRAME): plain Newton steps with that
!> Jacobian from the caller's guess (at
!> output times the previous outputs' edges carried forward with their rates),
!> which converge in one or two surface evaluations; HYBRJ from the
!> tangent-plane guess (the streamline point moved by +-(b/2) y_w) only when
!> Newton does not converge. Both stop on the same test: a step (scaled by the
!> Jacobian's column norms, as HYBRJ's mode 1) below xtol times the scaled x,
!> and max|f| <= residual_tolerance; Newton also stops after a step below
!> edge_quadratic_step (1e-6 m), which quadratic convergence makes accurate to
!> ~1e-12 m, and takes it without evaluating the surface again.
!>
!> Near the ends of a slide an edge's foot can lie beyond the surface (the flow
!> runs at an angle beta to the centerline, so one edge leads the streamline
!> in u). Fitted slides end there (their evaluation holds the end value), so
!> no solver can find the foot; this is reported as STATUS_DOMAIN ("beyond the
!> end of the slide") when Newton's iterates leave [u_min, u_max] and HYBRJ
!> fails too. Any other failure keeps the solver's own status.
!> The left edge lies towards +y_w, i.e. towards larger v.
!>
!> Rates of the edges along the motion (for the water field's C1
!> interpolation): with F(x, q) = [(r_D - q).x_D; (r_D - q).y_D] = 0 and
!> dF/dq = -[x_D; y_D], the foot moves at dx/dt = J^-1 [x_D.q'; y_D.q'] (J the
!> Jacobian above at the solution), where the target moves at
!> q' = r' + h' z_w + h z_w' +- (b'/2) y_w +- (b/2) y_w'.
module water_boundaries
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use geometry_foot_point, only: foot_point_options_t, foot_point_t, find_foot_point, FOOT_FRAME, &
    FOOT_STOP_SCALED, FOOT_DOMAIN_NOTE, FOOT_FALLBACK_FAILED
  use water_channel, only: channel_t
  use water_streamline, only: water_point_t, water_rates_t
  implicit none (type, external)
  private
  public :: water_edges, edge_options

  !> Convergence test of both solvers: xtol relative (~7e-9 m on a 67 m slide,
  !> u being arc length there); the residual (m) still <= 1e-10.
  real(wp), parameter :: edge_xtol = 1e-10_wp, edge_residual_tolerance = 1e-10_wp
  !> A Newton step (scaled by the Jacobian's column norms: metres) this small
  !> is the last one: the error after it is O(K step^2) with K of the order
  !> of the surface's curvature (2/m in a 0.5 m tube), ~2e-12 m, below both
  !> tolerances above; the step is taken without a further evaluation.
  real(wp), parameter :: edge_quadratic_step = 1e-6_wp
  !> Newton steps before falling back to HYBRJ: from a warm start two or three
  !> suffice (quadratic convergence from ~1e-5 m); more means a poor start.
  integer, parameter :: max_newton = 8
  type(foot_point_options_t), parameter :: edge_options = foot_point_options_t(equations=FOOT_FRAME, &
    stop_rule=FOOT_STOP_SCALED, domain_rule=FOOT_DOMAIN_NOTE, max_steps=max_newton, tolerance=edge_xtol, &
    residual_tolerance=edge_residual_tolerance, last_step=edge_quadratic_step, fallback=.true.)

contains

  !> Left and right edges [u, v] and their points for the water point q.
  !> left_guess/right_guess: starts for Newton (e.g. the previous output's
  !> edges moved with the streamline); without them the tangent-plane guess.
  !> With `rates` (water_point_rates at q), left_rate and right_rate are the
  !> edges' d[u, v]/dt along the motion.
  subroutine water_edges(channel, q, left, right, left_point, right_point, status, left_guess, right_guess, &
                         rates, left_rate, right_rate)
    class(channel_t), intent(in), target :: channel
    type(water_point_t), intent(in) :: q
    real(wp), intent(out) :: left(2), right(2), left_point(3), right_point(3)
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: left_guess(2), right_guess(2)
    type(water_rates_t), intent(in), optional :: rates
    real(wp), intent(out), optional :: left_rate(2), right_rate(2)
    real(wp) :: d(2), base(3), e, f, g, det, bu, bv, base_rate(3), side_rate(3)

    base = q%position + q%height*q%z_m
    ! tangent-plane guess: the offset (b/2) y_w mapped to (du, dv)
    e = dot_product(q%p%ru, q%p%ru); f = dot_product(q%p%ru, q%p%rv); g = dot_product(q%p%rv, q%p%rv)
    bu = 0.5_wp*q%width*dot_product(q%p%ru, q%y_w); bv = 0.5_wp*q%width*dot_product(q%p%rv, q%y_w)
    det = e*g - f*f
    d = [(g*bu - f*bv)/det, (e*bv - f*bu)/det]
    base_rate = 0; side_rate = 0
    if (present(rates)) then
      base_rate = q%velocity + q%height_rate*q%z_m + q%height*rates%z_m
      side_rate = 0.5_wp*rates%width*q%y_w + 0.5_wp*q%width*rates%y_w
    end if
    if (present(left_guess)) then
      call one_edge(channel, base + 0.5_wp*q%width*q%y_w, left_guess, [q%u, q%v] + d, left, left_point, status, &
                    base_rate + side_rate, left_rate)
    else
      call one_edge(channel, base + 0.5_wp*q%width*q%y_w, [q%u, q%v] + d, [q%u, q%v] + d, left, left_point, &
                    status, base_rate + side_rate, left_rate)
    end if
    if (.not. status%ok()) then
      call prefix_status(status, 'left water edge (4.25)')
      return
    end if
    if (present(right_guess)) then
      call one_edge(channel, base - 0.5_wp*q%width*q%y_w, right_guess, [q%u, q%v] - d, right, right_point, &
                    status, base_rate - side_rate, right_rate)
    else
      call one_edge(channel, base - 0.5_wp*q%width*q%y_w, [q%u, q%v] - d, [q%u, q%v] - d, right, right_point, &
                    status, base_rate - side_rate, right_rate)
    end if
    if (.not. status%ok()) call prefix_status(status, 'right water edge (4.26)')
  end subroutine water_edges

  !> The foot x = (u, v) of the normal through `target` and its point
  !> (geometry_foot_point: Newton from `start`, HYBRJ from `fallback` if
  !> Newton does not converge); with x_rate present, the foot's rate for a
  !> target moving at target_rate.
  subroutine one_edge(channel, target, start, fallback, x, point, status, target_rate, x_rate)
    class(channel_t), intent(in), target :: channel
    real(wp), intent(in) :: target(3), start(2), fallback(2), target_rate(3)
    real(wp), intent(out) :: x(2), point(3)
    type(status_t), intent(out) :: status
    real(wp), intent(out), optional :: x_rate(2)
    type(foot_point_t) :: foot
    real(wp) :: u_min, u_max

    x = start
    call find_foot_point(channel%slide, target, x(1), x(2), edge_options, foot, status, fallback)
    x = [foot%u, foot%v]
    if (status%ok()) then
      point = foot%point
      if (present(x_rate)) call foot_rate(foot%jacobian)
    else if (foot%reason == FOOT_FALLBACK_FAILED) then
      call channel%u_range(u_min, u_max)
      if (foot%left_domain .or. x(1) < u_min .or. x(1) > u_max) then
        if (.not. foot%left_domain) foot%u_outside = x(1)
        call set_status(status, STATUS_DOMAIN, 'the foot lies beyond the end of the slide (u = ' // &
                        format_short(foot%u_outside)//' outside ['//format_short(u_min)//', '// &
                        format_short(u_max)//'])')
      end if
    end if

  contains

    !> dx/dt = J^-1 [x_D.q'; y_D.q'] with J and the frame at the solution x.
    subroutine foot_rate(jacobian)
      real(wp), intent(in) :: jacobian(2, 2)
      real(wp) :: b(2), dj
      b = [dot_product(foot%frame%r(:, 1), target_rate), dot_product(foot%frame%r(:, 2), target_rate)]
      dj = jacobian(1, 1)*jacobian(2, 2) - jacobian(1, 2)*jacobian(2, 1)
      x_rate = [jacobian(2, 2)*b(1) - jacobian(1, 2)*b(2), jacobian(1, 1)*b(2) - jacobian(2, 1)*b(1)]/dj
    end subroutine foot_rate
  end subroutine one_edge
end module water_boundaries
