!> Systems with closed-form solutions for test_ode.
module test_ode_systems
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_ode, only: ode_system_t
  implicit none (type, external)
  private
  public :: oscillator_t, ball_t, domain_t, plateau_t

  !> x'' = -omega^2 x as y = [x, x']; roots: g1 = x, g2 = t - t_mark.
  type, extends(ode_system_t) :: oscillator_t
    real(wp) :: omega = 2     ! 1/s
    real(wp) :: t_mark = 1.234_wp   ! s
    logical :: with_roots = .false.
  contains
    procedure :: rhs => oscillator_rhs
    procedure :: root_count => oscillator_root_count
    procedure :: roots => oscillator_roots
  end type oscillator_t

  !> A ball falling under gravity, y = [height, vertical speed]; root: height.
  type, extends(ode_system_t) :: ball_t
    real(wp) :: gravity = 9.81_wp   ! m/s^2
  contains
    procedure :: rhs => ball_rhs
    procedure :: root_count => ball_root_count
    procedure :: roots => ball_roots
  end type ball_t

  !> y' = 1 with the root g = min(y - 1, 0): exactly zero from y = 1 on, so
  !> CVODE finds a root there and then refuses to go on (a root at and very
  !> near the last one: CV_ILL_INPUT).
  type, extends(ode_system_t) :: plateau_t
  contains
    procedure :: rhs => plateau_rhs
    procedure :: root_count => plateau_root_count
    procedure :: roots => plateau_roots
  end type plateau_t

  !> y' = -1 with a domain y > 0.5: the right-hand side refuses outside it.
  type, extends(ode_system_t) :: domain_t
  contains
    procedure :: rhs => domain_rhs
  end type domain_t

contains

  subroutine oscillator_rhs(self, t, y, ydot, status)
    class(oscillator_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_status => status)
    end associate
    ydot(1) = y(2)
    ydot(2) = -self%omega**2*y(1)
  end subroutine oscillator_rhs

  integer function oscillator_root_count(self) result(n)
    class(oscillator_t), intent(in) :: self
    n = merge(2, 0, self%with_roots)
  end function oscillator_root_count

  subroutine oscillator_roots(self, t, y, g)
    class(oscillator_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    g(1) = y(1)
    g(2) = t - self%t_mark
  end subroutine oscillator_roots

  subroutine ball_rhs(self, t, y, ydot, status)
    class(ball_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_status => status)
    end associate
    ydot(1) = y(2)
    ydot(2) = -self%gravity
  end subroutine ball_rhs

  integer function ball_root_count(self) result(n)
    class(ball_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 1
  end function ball_root_count

  subroutine ball_roots(self, t, y, g)
    class(ball_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    associate (unused_self => self, unused_t => t)
    end associate
    g(1) = y(1)
  end subroutine ball_roots

  subroutine plateau_rhs(self, t, y, ydot, status)
    class(plateau_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused_self => self, unused_t => t, unused_y => y, unused_status => status)
    end associate
    ydot = 1
  end subroutine plateau_rhs

  integer function plateau_root_count(self) result(n)
    class(plateau_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 1
  end function plateau_root_count

  subroutine plateau_roots(self, t, y, g)
    class(plateau_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    associate (unused_self => self, unused_t => t)
    end associate
    g(1) = min(y(1) - 1, 0.0_wp)
  end subroutine plateau_roots

  subroutine domain_rhs(self, t, y, ydot, status)
    class(domain_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused_self => self, unused_t => t)
    end associate
    ydot = -1
    if (y(1) < 0.5_wp) call set_status(status, STATUS_DOMAIN, 'test system: y left the domain y > 0.5')
  end subroutine domain_rhs
end module test_ode_systems

program test_ode
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_SOLVER, STATUS_DOMAIN, STATUS_INVALID_INPUT, &
    STATUS_INTERNAL
  use numerics_ode, only: ode_integrator_t, ode_options_t, ode_stats_t, ODE_ADAMS, ODE_BDF
  use testing, only: check, check_close, finish_tests
  use test_ode_systems, only: oscillator_t, ball_t, domain_t, plateau_t
  implicit none (type, external)

  call oscillator_against_closed_form(ODE_ADAMS, 'Adams')
  call oscillator_against_closed_form(ODE_BDF, 'BDF')
  call roots_with_index_and_direction()
  call bouncing_ball()
  call too_much_work()
  call system_status_comes_back()
  call stop_time_and_misuse()
  call failure_time_is_the_last_reached()
  call finish_tests('test_ode')

contains

  !> x = cos(2t), x' = -2 sin(2t) at 100 outputs over 10 s (about 3 periods),
  !> at tolerances 1e-10 and 1e-12.
  subroutine oscillator_against_closed_form(method, name)
    integer, intent(in) :: method
    character(len=*), intent(in) :: name
    real(wp) :: err_10, err_12

    call oscillator_run(method, name, 1e-10_wp, err_10)
    call oscillator_run(method, name, 1e-12_wp, err_12)
    ! The error must follow the tolerance: 100x tighter tolerances, >= 10x smaller error.
    call check(err_12 < err_10/10, name//' oscillator error decreases with the tolerance')
  end subroutine oscillator_against_closed_form

  subroutine oscillator_run(method, name, tol, err)
    integer, intent(in) :: method
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: tol
    real(wp), intent(out) :: err
    type(oscillator_t), target :: system
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(status_t) :: status
    type(ode_stats_t) :: stats
    real(wp) :: t, y(2), bound
    integer :: k

    options%method = method
    options%rtol = tol
    options%atol = tol
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call check(status%ok(), name//' start: '//status%text())
    err = 0
    do k = 1, 100
      call ode%advance(0.1_wp*k, t, y, status)
      if (.not. status%ok()) exit
      err = max(err, abs(y(1) - cos(2*t)), abs(y(2) + 2*sin(2*t)))
      call check(t == 0.1_wp*k, name//' output time is t_out')
    end do
    call check(status%ok(), name//' oscillator integration: '//status%text())
    stats = ode%statistics()
    ! The oscillator neither damps nor amplifies errors, so the global error is at
    ! most the sum of the local errors CVODE allows, (atol + rtol |y|) per step, |y| <= 2.
    bound = real(stats%steps, wp)*(options%atol + 2*options%rtol)
    call check_close(err, 0.0_wp, 0.0_wp, bound, name//' oscillator max error vs closed form')
    call check(stats%steps > 100, name//' statistics: steps counted')
    call check(stats%rhs_evaluations >= stats%steps, name//' statistics: rhs evaluations >= steps')
    call check(stats%root_evaluations == 0, name//' statistics: no root evaluations without roots')
    call check(stats%last_step > 0 .and. stats%last_order >= 1, name//' statistics: last step and order')
    if (method == ODE_BDF) call check(stats%last_order <= 5, 'BDF order at most 5')
  end subroutine oscillator_run

  !> g1 = cos(2t) falls through 0 at pi/4, rises at 3 pi/4; g2 = t - 1.234 rises.
  subroutine roots_with_index_and_direction()
    ! Root time error = solution error / slope |g1'| = 2. At rtol = atol = 1e-12
    ! the solution error by t = 2.4 is a few 1e-12 (1e-10 tolerances give a few
    ! 1e-10 there), so 1e-10 s holds with a margin and a 1e-10 run would fail.
    real(wp), parameter :: t_tol = 1e-10_wp
    type(oscillator_t), target :: system
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(status_t) :: status
    type(ode_stats_t) :: stats
    real(wp) :: t, y(2)
    logical :: found
    integer :: index(2)

    system%with_roots = .true.
    options%rtol = 1e-12_wp
    options%atol = 1e-12_wp
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call check(status%ok(), 'roots start: '//status%text())
    call ode%advance(3.0_wp, t, y, status, found, index)
    call check(status%ok() .and. found, 'first root found')
    call check_close(t, pi/4, 0.0_wp, t_tol, 'first root time pi/4')
    call check(all(index == [-1, 0]), 'first root: g1 falling, g2 not')
    call check_close(y(1), 0.0_wp, 0.0_wp, 2*t_tol, 'x = 0 at the root')
    call ode%advance(3.0_wp, t, y, status, found, index)
    call check(found, 'second root found')
    call check_close(t, system%t_mark, 0.0_wp, t_tol, 'second root time t_mark')
    call check(all(index == [0, 1]), 'second root: g2 rising')
    call ode%advance(3.0_wp, t, y, status, found, index)
    call check_close(t, 3*pi/4, 0.0_wp, t_tol, 'third root time 3 pi/4')
    call check(all(index == [1, 0]), 'third root: g1 rising')
    call ode%advance(3.0_wp, t, y, status, found, index)
    call check(status%ok() .and. .not. found .and. t == 3.0_wp .and. all(index == 0), &
      'no root before t_out = 3')
    stats = ode%statistics()
    call check(stats%root_evaluations > 0, 'statistics: root evaluations counted')

    ! Only rising zeros of g1, no zeros of g2 at all: the first event is 3 pi/4.
    options%root_direction = [1, 1]
    system%t_mark = -1   ! g2 > 0 throughout
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call ode%advance(3.0_wp, t, y, status, found, index)
    call check(status%ok() .and. found, 'rising-only root found')
    call check_close(t, 3*pi/4, 0.0_wp, t_tol, 'rising-only root skips the falling one at pi/4')
    call check(all(index == [1, 0]), 'rising-only root index')

    options%root_direction = [1]
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call check(status%code == STATUS_INVALID_INPUT, 'root_direction of the wrong size refused')
  end subroutine roots_with_index_and_direction

  !> Ball dropped from h0 = 10 m, restitution e = 0.8: the first impact is at
  !> t1 = sqrt(2 h0 / g) with speed v1 = g t1; after impact k the ball flies
  !> 2 e^k v1 / g, so t_(k+1) = t_k + 2 e^k v1 / g.
  subroutine bouncing_ball()
    ! The flight is a parabola, which Adams (order >= 2) and its interpolant
    ! reproduce exactly; what is left is CVODE's root tolerance, 100 u (|t| + |h|)
    ! ~ 1e-13 s per impact, amplified by 2e = 1.6 per later flight (a timing error
    ! d changes the rebound speed by g d): ~20 x 1e-13 after 6 impacts; 1e-10 s.
    real(wp), parameter :: t_tol = 1e-10_wp
    real(wp), parameter :: h0 = 10, e = 0.8_wp
    type(ball_t), target :: ball
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(status_t) :: status
    type(ode_stats_t) :: first, last
    real(wp) :: t, y(2), t_ref, v1
    logical :: found
    integer :: index(1), k

    options%root_direction = [-1]
    call ode%start(ball, 0.0_wp, [h0, 0.0_wp], options, status)
    call check(status%ok(), 'ball start: '//status%text())
    t_ref = sqrt(2*h0/ball%gravity)
    v1 = ball%gravity*t_ref
    do k = 1, 6
      call ode%advance(100.0_wp, t, y, status, found, index)
      call check(status%ok() .and. found .and. index(1) == -1, 'ball impact found')
      call check_close(t, t_ref, 0.0_wp, t_tol, 'bounce time vs closed form')
      call check_close(y(2), -e**(k - 1)*v1, 1e-9_wp, 0.0_wp, 'impact speed vs closed form')
      if (k == 1) first = ode%statistics()
      call ode%restart(t, [0.0_wp, -e*y(2)], status)
      call check(status%ok(), 'ball restart: '//status%text())
      t_ref = t_ref + 2*e**k*v1/ball%gravity
    end do
    ! CVodeReInit zeroes CVODE's counters; the integrator's statistics must sum the
    ! six flights (each needs a similar number of steps), not show the last one only.
    last = ode%statistics()
    call check(last%steps > 2*first%steps .and. last%rhs_evaluations > 2*first%rhs_evaluations .and. &
      last%root_evaluations > 2*first%root_evaluations, 'statistics summed over restarts')
  end subroutine bouncing_ball

  !> max_steps = 5 cannot reach t = 10: CVODE's CV_TOO_MUCH_WORK with its message.
  subroutine too_much_work()
    type(oscillator_t), target :: system
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(status_t) :: status
    real(wp) :: t, y(2)

    options%max_steps = 5
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call ode%advance(10.0_wp, t, y, status)
    call check(status%code == STATUS_SOLVER, 'too much work gives a solver status')
    call check(index(status%text(), 'CV_TOO_MUCH_WORK') > 0, 'message names the flag: '//status%text())
    call check(index(status%text(), 'mxstep') > 0, 'message carries CVODE''s own text: '//status%text())
    call check(t > 0 .and. t < 10, 'time reached is returned on failure')
    ! The state returned is the solution at the time reached (rtol 1e-10 solve).
    call check_close(y(1), cos(2*t), 0.0_wp, 1e-8_wp, 'state at failure is the solution at t')

    ! Tolerances below what double precision can deliver: CV_TOO_MUCH_ACC.
    options = ode_options_t(rtol=0, atol=1e-30_wp)
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call ode%advance(10.0_wp, t, y, status)
    call check(status%code == STATUS_SOLVER .and. index(status%text(), 'CV_TOO_MUCH_ACC') > 0, &
      'too much accuracy named: '//status%text())
  end subroutine too_much_work

  !> y' = -1 from y = 1 leaves y > 0.5 at t = 0.5: the system's own status returns.
  subroutine system_status_comes_back()
    type(domain_t), target :: system
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(status_t) :: status
    real(wp) :: t, y(1)

    options%method = ODE_BDF
    call ode%start(system, 0.0_wp, [1.0_wp], options, status)
    call ode%advance(2.0_wp, t, y, status)
    call check(status%code == STATUS_DOMAIN, 'status code of the system comes back')
    call check(status%text() == 'test system: y left the domain y > 0.5', &
      'message of the system comes back unchanged: '//status%text())
    call check(t <= 0.5_wp + 1e-9_wp .and. t > 0, 'stopped before leaving the domain')

    ! Outside the domain from the start: CVODE's first call fails, same status.
    call ode%start(system, 0.0_wp, [0.4_wp], options, status)
    call ode%advance(2.0_wp, t, y, status)
    call check(status%code == STATUS_DOMAIN .and. t == 0, 'status of a failing first call comes back')
  end subroutine system_status_comes_back

  subroutine stop_time_and_misuse()
    type(oscillator_t), target :: system
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(status_t) :: status
    real(wp) :: t, y(2)

    call ode%advance(1.0_wp, t, y, status)
    call check(status%code == STATUS_INTERNAL, 'advance before start is refused')
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call ode%set_stop_time(0.7_wp, status)
    call check(status%ok(), 'set_stop_time: '//status%text())
    call ode%advance(2.0_wp, t, y, status)
    call check(status%ok() .and. t == 0.7_wp, 'advance stops exactly at the stop time')
    call check_close(y(1), cos(1.4_wp), 0.0_wp, 1e-9_wp, 'state at the stop time')
    options%rtol = -1
    call ode%start(system, 0.0_wp, [1.0_wp, 0.0_wp], options, status)
    call check(status%code == STATUS_INVALID_INPUT, 'negative rtol refused')
    call ode%destroy()
    call ode%destroy()   ! twice is harmless
  end subroutine stop_time_and_misuse

  !> A failure that CVODE reports without the time it reached (its root
  !> check before the first step: a root at and very near the last one) gives
  !> the last time reached, here the root's (it was uninitialised memory, e.g.
  !> 4.68e-310 s in a message).
  subroutine failure_time_is_the_last_reached()
    type(plateau_t), target :: system, other_system
    type(ode_integrator_t) :: ode, other
    type(ode_options_t) :: options
    type(status_t) :: status
    real(wp) :: t, t_root, y(1)
    logical :: found
    call ode%start(system, 0.0_wp, [0.0_wp], options, status)
    call ode%advance(5.0_wp, t, y, status, found)
    call check(status%ok() .and. found .and. t >= 1 .and. t < 5, 'plateau: the root where g becomes 0')
    t_root = t
    ! another integrator's advance in between (to 0.5 s) leaves its time where
    ! an unset one would be read
    call other%start(other_system, 0.0_wp, [0.0_wp], options, status)
    call other%advance(0.5_wp, t, y, status, found)
    call check(status%ok() .and. .not. found .and. t == 0.5_wp, 'plateau: another run to 0.5 s')
    call ode%advance(5.0_wp, t, y, status, found)
    ! part way through the run (steps taken): a failure part way, not bad input
    call check(status%code == STATUS_SOLVER .and. index(status%text(), 'CV_ILL_INPUT') > 0, &
               'plateau: CVODE refuses the root at and very near the last one: '//status%text())
    call check(t == t_root, 'plateau: the failure''s time is the last time reached (the message''s too)')
  end subroutine failure_time_is_the_last_reached
end program test_ode
