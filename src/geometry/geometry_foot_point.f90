!> The one foot-point solver: the surface parameters (u, v) whose normal
!> passes through a target point p (the foot of the perpendicular from p, a
!> stationary point of the distance |r(u, v) - p|), or, for a direction d,
!> where d.r(u, v) is stationary (the support point of a convex surface).
!> The contact search, the rider's start and the water's edges all find
!> their points here (docs/DESIGN.md, "Geometry queries").
!>
!> Equations (foot_point_options_t%equations):
!>   FOOT_TANGENT  (r - p).r_u = (r - p).r_v = 0, the distance's gradient;
!>                 Jacobian J = [r_a.r_b + (r - p).r_ab] (symmetric);
!>   FOOT_FRAME    (r - p).x_D = (r - p).y_D = 0 in the Darboux frame
!>                 (sigma = 1, alpha_u = 0, alpha_v = 1): residuals in
!>                 metres, J_ab = r_b.x_a + (r - p).(x_a)_b (thesis 4.25-4.26);
!>   FOOT_SUPPORT  d.r_u = d.r_v = 0 for the direction d; J = [d.r_ab].
!>
!> Newton: from the start, x <- x - J^-1 f (2 x 2 by Cramer's rule), one
!> surface evaluation (order 2) per step, at most max_steps. It stops on the
!> test `stop_rule` names:
!>   FOOT_STOP_PARAMETER  max|f| <= tolerance * (its scale) before a step,
!>                        or a step |du| + |dv| <= tolerance (1 + |u| + |v|);
!>   FOOT_STOP_LENGTH     a step of length |du||r_u| + |dv||r_v| below
!>                        tolerance (1 + |p|) metres (taken, then stop);
!>   FOOT_STOP_SCALED     HYBRJ's test: max|f| <= residual_tolerance and the
!>                        step scaled by J's column norms D, |D dx|, <=
!>                        tolerance |D x| (x kept), or |D dx| <= last_step
!>                        (taken without evaluating again: Newton's error
!>                        after it is O(curvature |D dx|^2)).
!> The domain (`domain_rule`): FOOT_DOMAIN_CLIP clips bounded, non-periodic
!> directions to the box; FOOT_DOMAIN_STOP ends the search when an iterate
!> leaves it (FOOT_LEFT_DOMAIN); FOOT_DOMAIN_NOTE goes on and notes where u
!> left [u_min, u_max] (foot%left_domain, foot%u_outside: the last such u).
!> require_minimum: stop (FOOT_NOT_MINIMUM) where det J <= 0, i.e. where
!> the distance is not at a minimum (the iterate is kept).
!>
!> Fallback (fallback = .true.): when Newton does not converge, MINPACK's
!> HYBRJ (numerics_nonlinear: a trust region, so it converges from farther
!> away) on the same equations from `fallback_start`, with xtol = tolerance
!> and residual_tolerance.
!>
!> The outcome is foot%reason (FOOT_CONVERGED or why not; foot_reason_text
!> words it); status fails only where the surface could not be evaluated or
!> HYBRJ failed (its status). What a caller accepts is the caller's choice.
module geometry_foot_point
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, solve_nonlinear
  implicit none (type, external)
  private
  public :: foot_point_options_t, foot_point_t, find_foot_point, foot_reason_text, foot_system_t

  integer, parameter, public :: FOOT_TANGENT = 1, FOOT_FRAME = 2, FOOT_SUPPORT = 3
  integer, parameter, public :: FOOT_STOP_PARAMETER = 1, FOOT_STOP_LENGTH = 2, FOOT_STOP_SCALED = 3
  integer, parameter, public :: FOOT_DOMAIN_CLIP = 1, FOOT_DOMAIN_STOP = 2, FOOT_DOMAIN_NOTE = 3
  integer, parameter, public :: FOOT_CONVERGED = 0, FOOT_STEP_LIMIT = 1, FOOT_LEFT_DOMAIN = 2, &
    FOOT_NOT_MINIMUM = 3, FOOT_SINGULAR = 4, FOOT_NOT_FINITE = 5, FOOT_EVALUATION_FAILED = 6, &
    FOOT_FALLBACK_FAILED = 7

  !> A box edge beyond this counts as unbounded (FOOT_DOMAIN_CLIP).
  real(wp), parameter :: bounded_limit = 1e6_wp

  type :: foot_point_options_t
    integer :: equations = FOOT_TANGENT
    integer :: stop_rule = FOOT_STOP_LENGTH
    integer :: domain_rule = FOOT_DOMAIN_STOP
    integer :: max_steps = 30
    real(wp) :: tolerance = 1e-14_wp            ! relative, see the stop rules
    real(wp) :: residual_tolerance = 1e-10_wp   ! m, FOOT_STOP_SCALED and the fallback
    real(wp) :: last_step = 0                   ! m, FOOT_STOP_SCALED: a scaled step this small is the last
    logical :: require_minimum = .false.
    logical :: fallback = .false.               ! HYBRJ when Newton does not converge
  end type foot_point_options_t

  type :: foot_point_t
    real(wp) :: u = 0, v = 0
    integer :: reason = FOOT_STEP_LIMIT
    integer :: steps = 0                 ! Newton steps taken
    logical :: by_fallback = .false.     ! HYBRJ found it
    !> r at the foot: evaluated there, or (after a last step taken without
    !> evaluating) the tangent-plane image of that step
    real(wp) :: point(3) = 0
    !> the last evaluation, its Jacobian and (FOOT_FRAME) its Darboux frame:
    !> at the foot, or at the point the last step started from
    type(surface_point_t) :: p
    real(wp) :: jacobian(2, 2) = 0
    type(darboux_frame_t) :: frame
    logical :: left_domain = .false.     ! FOOT_DOMAIN_NOTE: an iterate left [u_min, u_max] ...
    real(wp) :: u_outside = 0            ! ... here (the last Newton iterate outside)
  end type foot_point_t

  !> The equations as a nonlinear system for HYBRJ (residual and Jacobian at
  !> one point share one evaluation, kept as the last).
  type, extends(nonlinear_system_t) :: foot_system_t
    class(surface_t), pointer :: surface => null()
    real(wp) :: target(3) = 0
    integer :: equations = FOOT_FRAME
    real(wp) :: x_last(2) = huge(1.0_wp)
    type(surface_point_t) :: p_last
    type(darboux_frame_t) :: frame_last
  contains
    procedure :: residual => system_residual
    procedure :: jacobian => system_jacobian
  end type foot_system_t

contains

  !> The foot of `target` (a point, or a direction for FOOT_SUPPORT) on
  !> `surface` by Newton from (u, v), as the options say; (u, v) end at the
  !> last iterate. fallback_start: where HYBRJ starts (default: (u, v) as
  !> given).
  subroutine find_foot_point(surface, target, u, v, options, foot, status, fallback_start)
    class(surface_t), intent(in), target :: surface
    real(wp), intent(in) :: target(3)
    real(wp), intent(inout) :: u, v
    type(foot_point_options_t), intent(in) :: options
    type(foot_point_t), intent(out) :: foot
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: fallback_start(2)
    type(status_t) :: local
    real(wp) :: box(4), f(2), dx(2), det, scale(2), x(2), start(2)
    logical :: bounded(2)
    integer :: it

    if (.not. status%ok()) return
    start = [u, v]
    if (present(fallback_start)) start = fallback_start
    call surface%domain(box(1), box(2), box(3), box(4))
    bounded = [max(abs(box(1)), abs(box(2))) < bounded_limit, max(abs(box(3)), abs(box(4))) < bounded_limit]
    do it = 1, options%max_steps
      call equations_at(surface, options%equations, target, u, v, foot%p, foot%frame, f, foot%jacobian, local)
      if (.not. local%ok()) then
        foot%reason = FOOT_EVALUATION_FAILED
        exit
      end if
      associate (jac => foot%jacobian)
        if (options%stop_rule == FOOT_STOP_PARAMETER) then
          if (maxval(abs(f)) <= options%tolerance*residual_scale(foot%p)) then
            foot%reason = FOOT_CONVERGED
            exit
          end if
        end if
        det = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
        if (options%require_minimum) then
          if (.not. det > 0) then
            foot%reason = FOOT_NOT_MINIMUM
            exit
          end if
        else if (.not. abs(det) > 0) then
          foot%reason = FOOT_SINGULAR
          exit
        end if
        dx = -[jac(2, 2)*f(1) - jac(1, 2)*f(2), jac(1, 1)*f(2) - jac(2, 1)*f(1)]/det
        if (options%stop_rule == FOOT_STOP_SCALED) then
          x = [u, v]
          scale = [norm2(jac(:, 1)), norm2(jac(:, 2))]
          if (maxval(abs(f)) <= options%residual_tolerance .and. &
              norm2(scale*dx) <= options%tolerance*norm2(scale*x)) then
            foot%point = foot%p%r   ! at x; x + dx differs by far less than the tolerance
            foot%reason = FOOT_CONVERGED
            exit
          end if
          if (norm2(scale*dx) <= options%last_step .and. u + dx(1) >= box(1) .and. u + dx(1) <= box(2)) then
            foot%point = foot%p%r + foot%p%ru*dx(1) + foot%p%rv*dx(2)
            u = u + dx(1)
            v = v + dx(2)
            foot%steps = it
            foot%reason = FOOT_CONVERGED
            exit
          end if
        end if
      end associate
      u = u + dx(1)
      v = v + dx(2)
      foot%steps = it
      select case (options%domain_rule)
      case (FOOT_DOMAIN_CLIP)
        if (bounded(1) .and. .not. surface%periodic_u()) u = min(max(u, box(1)), box(2))
        if (bounded(2) .and. .not. surface%periodic_v()) v = min(max(v, box(3)), box(4))
      case (FOOT_DOMAIN_STOP)
        if (.not. surface%in_domain(u, v)) then
          foot%reason = FOOT_LEFT_DOMAIN
          exit
        end if
      case (FOOT_DOMAIN_NOTE)
        if (.not. (abs(u) <= huge(u) .and. abs(v) <= huge(v))) then
          foot%reason = FOOT_NOT_FINITE
          exit
        end if
        if (u < box(1) .or. u > box(2)) then
          foot%left_domain = .true.
          foot%u_outside = u
        end if
      end select
      select case (options%stop_rule)
      case (FOOT_STOP_PARAMETER)
        if (abs(dx(1)) + abs(dx(2)) <= options%tolerance*(1 + abs(u) + abs(v))) then
          foot%reason = FOOT_CONVERGED
          exit
        end if
      case (FOOT_STOP_LENGTH)
        if (abs(dx(1))*norm2(foot%p%ru) + abs(dx(2))*norm2(foot%p%rv) < options%tolerance*(1 + norm2(target))) then
          foot%reason = FOOT_CONVERGED
          exit
        end if
      end select
    end do
    foot%u = u
    foot%v = v
    if (foot%reason == FOOT_CONVERGED .or. .not. options%fallback) then
      if (foot%reason == FOOT_EVALUATION_FAILED) status = local
      return
    end if
    call hybrj_fallback()

  contains

    !> max|f|'s scale for FOOT_STOP_PARAMETER: |r_u|^2 (f = (r - p).r_u is
    !> a distance times |r_u|), |d| |r_u| for a direction.
    pure real(wp) function residual_scale(p) result(s)
      type(surface_point_t), intent(in) :: p
      if (options%equations == FOOT_SUPPORT) then
        s = norm2(target)*max(norm2(p%ru), norm2(p%rv))
      else
        s = max(dot_product(p%ru, p%ru), dot_product(p%rv, p%rv))
      end if
    end function residual_scale

    subroutine hybrj_fallback()
      type(foot_system_t) :: sys
      type(nonlinear_options_t) :: nl_options
      type(nonlinear_result_t) :: result
      real(wp) :: y(2)
      sys%surface => surface
      sys%target = target
      sys%equations = options%equations
      nl_options%xtol = options%tolerance
      nl_options%residual_tolerance = options%residual_tolerance
      y = start
      call solve_nonlinear(sys, y, nl_options, result, local)
      if (local%ok()) call sys%jacobian(y, foot%jacobian, local)   ! evaluates the surface and frame at y
      if (.not. local%ok()) then
        foot%reason = FOOT_FALLBACK_FAILED
        foot%u = y(1)
        foot%v = y(2)
        status = local
        return
      end if
      foot%reason = FOOT_CONVERGED
      foot%by_fallback = .true.
      foot%u = y(1)
      foot%v = y(2)
      u = y(1)
      v = y(2)
      foot%p = sys%p_last
      foot%frame = sys%frame_last
      foot%point = sys%p_last%r
    end subroutine hybrj_fallback
  end subroutine find_foot_point

  !> The equations f and their Jacobian at (u, v), from one evaluation.
  subroutine equations_at(surface, equations, target, u, v, p, frame, f, jac, status)
    class(surface_t), intent(in) :: surface
    integer, intent(in) :: equations
    real(wp), intent(in) :: target(3), u, v
    type(surface_point_t), intent(out) :: p
    type(darboux_frame_t), intent(inout) :: frame
    real(wp), intent(out) :: f(2), jac(2, 2)
    type(status_t), intent(out) :: status
    call surface%evaluate(u, v, 2, p, status)
    if (.not. status%ok()) return
    if (equations == FOOT_FRAME) then
      call darboux_frame(p, 1.0_wp, 0.0_wp, 1.0_wp, frame, status)
      if (.not. status%ok()) return
    end if
    call equations_from(p, frame, equations, target, f, jac)
  end subroutine equations_at

  pure subroutine equations_from(p, frame, equations, target, f, jac)
    type(surface_point_t), intent(in) :: p
    type(darboux_frame_t), intent(in) :: frame
    integer, intent(in) :: equations
    real(wp), intent(in) :: target(3)
    real(wp), intent(out) :: f(2), jac(2, 2)
    real(wp) :: d(3)
    select case (equations)
    case (FOOT_FRAME)
      d = p%r - target
      f(1) = dot_product(d, frame%r(:, 1))
      f(2) = dot_product(d, frame%r(:, 2))
      jac(1, 1) = dot_product(p%ru, frame%r(:, 1)) + dot_product(d, frame%a)
      jac(1, 2) = dot_product(p%rv, frame%r(:, 1)) + dot_product(d, frame%b)
      jac(2, 1) = dot_product(p%ru, frame%r(:, 2)) + dot_product(d, frame%e)
      jac(2, 2) = dot_product(p%rv, frame%r(:, 2)) + dot_product(d, frame%f)
    case (FOOT_SUPPORT)
      f = [dot_product(target, p%ru), dot_product(target, p%rv)]
      jac(1, 1) = dot_product(target, p%ruu)
      jac(1, 2) = dot_product(target, p%ruv)
      jac(2, 2) = dot_product(target, p%rvv)
      jac(2, 1) = jac(1, 2)
    case default
      f = [dot_product(p%r - target, p%ru), dot_product(p%r - target, p%rv)]
      jac(1, 1) = dot_product(p%ru, p%ru) + dot_product(p%r - target, p%ruu)
      jac(1, 2) = dot_product(p%ru, p%rv) + dot_product(p%r - target, p%ruv)
      jac(2, 2) = dot_product(p%rv, p%rv) + dot_product(p%r - target, p%rvv)
      jac(2, 1) = jac(1, 2)
    end select
  end subroutine equations_from

  !> Why a search ended, in words.
  pure function foot_reason_text(reason) result(text)
    integer, intent(in) :: reason
    character(len=:), allocatable :: text
    select case (reason)
    case (FOOT_CONVERGED)
      text = 'converged'
    case (FOOT_STEP_LIMIT)
      text = 'Newton did not converge within its steps'
    case (FOOT_LEFT_DOMAIN)
      text = 'an iterate left the parameter domain'
    case (FOOT_NOT_MINIMUM)
      text = 'the distance is not at a minimum there (det J <= 0)'
    case (FOOT_SINGULAR)
      text = 'the Jacobian is singular'
    case (FOOT_NOT_FINITE)
      text = 'an iterate is not finite'
    case (FOOT_EVALUATION_FAILED)
      text = 'the surface could not be evaluated'
    case (FOOT_FALLBACK_FAILED)
      text = 'Newton and its fallback (HYBRJ) did not converge'
    case default
      text = 'unknown'
    end select
  end function foot_reason_text

  !> The surface point and frame at x, reused when x is the last point asked for.
  subroutine system_point(self, x, status)
    class(foot_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    type(status_t), intent(inout) :: status
    if (all(x == self%x_last)) return
    call self%surface%evaluate(x(1), x(2), 2, self%p_last, status)
    if (.not. status%ok()) return
    if (self%equations == FOOT_FRAME) then
      call darboux_frame(self%p_last, 1.0_wp, 0.0_wp, 1.0_wp, self%frame_last, status)
      if (.not. status%ok()) return
    end if
    self%x_last = x
  end subroutine system_point

  subroutine system_residual(self, x, f, status)
    class(foot_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    real(wp) :: jac(2, 2)
    call system_point(self, x, status)
    if (.not. status%ok()) return
    call equations_from(self%p_last, self%frame_last, self%equations, self%target, f, jac)
  end subroutine system_residual

  subroutine system_jacobian(self, x, jac, status)
    class(foot_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: f(2)
    call system_point(self, x, status)
    if (.not. status%ok()) return
    call equations_from(self%p_last, self%frame_last, self%equations, self%target, f, jac)
  end subroutine system_jacobian
end module geometry_foot_point
