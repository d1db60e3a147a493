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
!> Solver: plain Newton steps with that Jacobian from the caller's guess (at
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
  use geometry_surface, only: surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, &
                                solve_nonlinear
  use water_channel, only: channel_t
  use water_streamline, only: water_point_t, water_rates_t
  implicit none (type, external)
  private
  public :: water_edges, edge_system_t, edge_xtol, edge_residual_tolerance

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

  !> The foot x = (u, v) of the normal through `target` and its point: Newton
  !> from `start`, HYBRJ from `fallback` if Newton does not converge; with
  !> x_rate present, the foot's rate for a target moving at target_rate.
  subroutine one_edge(channel, target, start, fallback, x, point, status, target_rate, x_rate)
    class(channel_t), intent(in), target :: channel
    real(wp), intent(in) :: target(3), start(2), fallback(2), target_rate(3)
    real(wp), intent(out) :: x(2), point(3)
    type(status_t), intent(out) :: status
    real(wp), intent(out), optional :: x_rate(2)
    type(edge_system_t) :: sys
    type(nonlinear_options_t) :: options
    type(nonlinear_result_t) :: result
    type(status_t) :: st
    real(wp) :: f(2), jac(2, 2), dx(2), scale(2), det, u_min, u_max, u_out
    integer :: it
    logical :: outside

    sys%channel => channel
    sys%target = target
    call channel%u_range(u_min, u_max)
    outside = .false.; u_out = 0
    x = start
    do it = 1, max_newton
      call sys%residual(x, f, st)
      if (st%ok()) call sys%jacobian(x, jac, st)
      if (.not. st%ok()) exit
      det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
      if (.not. abs(det) > 0) exit
      dx = -[jac(2, 2)*f(1) - jac(1, 2)*f(2), jac(1, 1)*f(2) - jac(2, 1)*f(1)]/det
      scale = [norm2(jac(:, 1)), norm2(jac(:, 2))]
      if (maxval(abs(f)) <= edge_residual_tolerance .and. &
          norm2(scale*dx) <= edge_xtol*norm2(scale*x)) then
        point = sys%p_last%r   ! at x; x + dx differs by far less than xtol
        if (present(x_rate)) call foot_rate(jac)
        return
      end if
      if (norm2(scale*dx) <= edge_quadratic_step .and. x(1) + dx(1) >= u_min .and. x(1) + dx(1) <= u_max) then
        ! the last step: Newton's error after it is <= K |dx|^2 (quadratic
        ! convergence), K ~ the surface's curvature ~ 2/m: ~2e-12 m
        point = sys%p_last%r + sys%p_last%ru*dx(1) + sys%p_last%rv*dx(2)
        if (present(x_rate)) call foot_rate(jac)
        x = x + dx
        return
      end if
      x = x + dx
      if (.not. all(abs(x) <= huge(x))) exit
      if (x(1) < u_min .or. x(1) > u_max) then
        outside = .true.; u_out = x(1)
      end if
    end do

    x = fallback
    options%xtol = edge_xtol
    options%residual_tolerance = edge_residual_tolerance
    sys%x_last = huge(1.0_wp)
    call solve_nonlinear(sys, x, options, result, status)
    if (status%ok()) then
      call sys%jacobian(x, jac, status)   ! evaluates the surface and frame at x
      point = sys%p_last%r
      if (status%ok() .and. present(x_rate)) call foot_rate(jac)
    else if (outside .or. x(1) < u_min .or. x(1) > u_max) then
      if (.not. outside) u_out = x(1)
      call set_status(status, STATUS_DOMAIN, 'the foot lies beyond the end of the slide (u = ' // &
                      format_short(u_out)//' outside ['//format_short(u_min)//', '//format_short(u_max)//'])')
    end if

  contains

    !> dx/dt = J^-1 [x_D.q'; y_D.q'] with J and the frame at the solution x.
    subroutine foot_rate(jacobian)
      real(wp), intent(in) :: jacobian(2, 2)
      real(wp) :: b(2), dj
      b = [dot_product(sys%frame_last%r(:, 1), target_rate), dot_product(sys%frame_last%r(:, 2), target_rate)]
      dj = jacobian(1, 1)*jacobian(2, 2) - jacobian(1, 2)*jacobian(2, 1)
      x_rate = [jacobian(2, 2)*b(1) - jacobian(1, 2)*b(2), jacobian(1, 1)*b(2) - jacobian(2, 1)*b(1)]/dj
    end subroutine foot_rate
  end subroutine one_edge

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
