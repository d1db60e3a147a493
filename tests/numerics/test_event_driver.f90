!> Models with closed-form event times for test_event_driver.
module test_event_driver_systems
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_event_driver, only: event_system_t, EVENT_RECORD, EVENT_RESTART, EVENT_STOP, &
    RECORD_OUTPUT, RECORD_EVENT
  implicit none (type, external)
  private
  public :: bouncing_ball_t, stiff_t, sticky_root_t

  !> A ball under gravity bouncing on the floor with restitution e: at h = 0
  !> (falling) v -> -e v and the integrator restarts; a station at height
  !> h_mark (rising crossings recorded, falling ignored by the root direction);
  !> the run stops at the n_stop-th bounce.
  type, extends(event_system_t) :: bouncing_ball_t
    real(wp) :: gravity = 9.81_wp, restitution = 0.8_wp, h_mark = 0.5_wp
    integer :: n_stop = 4, bounces = 0
    integer :: n = 0, outputs = 0
    real(wp) :: event_time(100) = 0, event_kind(100) = 0, last_output = -1
    real(wp) :: fail_after = huge(1.0_wp)   ! s: the right-hand side fails (domain) beyond this time
  contains
    procedure :: rhs => ball_rhs
    procedure :: root_count => ball_root_count
    procedure :: roots => ball_roots
    procedure :: record => ball_record
    procedure :: handle_event => ball_event
  end type bouncing_ball_t

  !> y' = -k (y - cos t): stiff for large k.
  type, extends(event_system_t) :: stiff_t
    real(wp) :: k = 1e6_wp
    character(len=:), allocatable :: diagnosis   ! what diagnose says ('' if unset)
    logical :: not_stiffness = .false.           ! the diagnosis rules stiffness out
  contains
    procedure :: rhs => stiff_rhs
    procedure :: record => stiff_record
    procedure :: diagnose => stiff_diagnose
    procedure :: stiffness_may_cause => stiff_may_cause
  end type stiff_t

  !> y' = 1 with the root function g = min(t - t_stick, 0): zero from
  !> t_stick on. Its root is recorded and the run goes on (EVENT_RECORD),
  !> where CVODE finds g zero at the root and just after it: "root found at
  !> and very near t", CV_ILL_INPUT, part way through the run.
  type, extends(event_system_t) :: sticky_root_t
    real(wp) :: t_stick = 0.45_wp   ! s, between two outputs
    integer :: outputs = 0, events = 0
  contains
    procedure :: rhs => sticky_rhs
    procedure :: root_count => sticky_root_count
    procedure :: roots => sticky_roots
    procedure :: record => sticky_record
    procedure :: handle_event => sticky_event
  end type sticky_root_t

contains

  subroutine sticky_rhs(self, t, y, ydot, status)
    class(sticky_root_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t, unused_y => y, unused_s => status)
    end associate
    ydot = 1
  end subroutine sticky_rhs

  integer function sticky_root_count(self) result(n)
    class(sticky_root_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 1
  end function sticky_root_count

  subroutine sticky_roots(self, t, y, g)
    class(sticky_root_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    associate (unused_y => y)
    end associate
    g(1) = min(t - self%t_stick, 0.0_wp)
  end subroutine sticky_roots

  subroutine sticky_record(self, t, y, kind, status)
    class(sticky_root_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_y => y, unused_s => status)
    end associate
    if (kind == RECORD_OUTPUT) self%outputs = self%outputs + 1
    if (kind == RECORD_EVENT) self%events = self%events + 1
  end subroutine sticky_record

  subroutine sticky_event(self, t, y, fired, action, status)
    class(sticky_root_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t, unused_y => y, unused_f => fired, unused_s => status)
    end associate
    action = EVENT_RECORD
  end subroutine sticky_event

  subroutine ball_rhs(self, t, y, ydot, status)
    class(bouncing_ball_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    ydot(1) = y(2)
    ydot(2) = -self%gravity
    if (t > self%fail_after) call set_status(status, 99, 'the test model fails here on purpose')
  end subroutine ball_rhs

  integer function ball_root_count(self) result(n)
    class(bouncing_ball_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 2
  end function ball_root_count

  subroutine ball_roots(self, t, y, g)
    class(bouncing_ball_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    associate (unused_t => t)
    end associate
    g(1) = y(1)
    g(2) = y(1) - self%h_mark
  end subroutine ball_roots

  subroutine ball_record(self, t, y, kind, status)
    class(bouncing_ball_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    associate (unused_y => y, unused_s => status)
    end associate
    if (kind == RECORD_OUTPUT) then
      self%outputs = self%outputs + 1
      self%last_output = t
    else if (kind == RECORD_EVENT) then
      self%n = self%n + 1
      self%event_time(self%n) = t
    end if
  end subroutine ball_record

  subroutine ball_event(self, t, y, fired, action, status)
    class(bouncing_ball_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_s => status)
    end associate
    action = EVENT_RECORD
    if (fired(1) < 0) then
      self%bounces = self%bounces + 1
      self%event_kind(self%n + 1) = 1
      if (self%bounces >= self%n_stop) then
        action = EVENT_STOP
      else
        y(1) = 0
        y(2) = -self%restitution*y(2)
        action = EVENT_RESTART
      end if
    else if (fired(2) > 0) then
      self%event_kind(self%n + 1) = 2
    else if (fired(2) < 0) then
      self%event_kind(self%n + 1) = -2
    end if
  end subroutine ball_event

  subroutine stiff_rhs(self, t, y, ydot, status)
    class(stiff_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused_s => status)
    end associate
    ydot(1) = -self%k*(y(1) - cos(t))
  end subroutine stiff_rhs

  function stiff_diagnose(self, t, y) result(text)
    class(stiff_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    character(len=:), allocatable :: text
    associate (unused_y => y)
    end associate
    text = ''
    if (allocated(self%diagnosis)) text = self%diagnosis//' (t > 0: '//merge('yes', 'no ', t > 0)//')'
  end function stiff_diagnose

  logical function stiff_may_cause(self, t, y) result(may)
    class(stiff_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    associate (unused_t => t, unused_y => y)
    end associate
    may = .not. self%not_stiffness
  end function stiff_may_cause

  subroutine stiff_record(self, t, y, kind, status)
    class(stiff_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t, unused_y => y, unused_k => kind, unused_s => status)
    end associate
  end subroutine stiff_record
end module test_event_driver_systems

!> The event-driven integration driver: event times against closed forms
!> (restarts after a velocity jump, recorded stations, a stop), bounded runs
!> ending exactly at t_end, the runaway guards, failures passed on.
program test_event_driver
  use base_kinds, only: wp, int64
  use base_status, only: status_t, STATUS_SOLVER
  use numerics_ode, only: ODE_ADAMS, ODE_BDF
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, &
    DRIVE_EVENT_STOP, DRIVE_FAILED, runaway_step_limit
  use test_event_driver_systems, only: bouncing_ball_t, stiff_t, sticky_root_t
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  call bouncing_ball()
  call bounded_run()
  call runaway_guards()
  call failure_passed_on()
  call ill_input_part_way()
  call finish_tests('test_event_driver')

contains

  !> Drop from h0 at rest: bounce k at t_k = t_1 + sum_{j<k} 2 e^j v_1/g with
  !> v_1 = sqrt(2 g h0); the rising crossing of h_mark after bounce j at
  !> t_j + (v_j - sqrt(v_j^2 - 2 g h_mark))/g while v_j^2 > 2 g h_mark.
  subroutine bouncing_ball()
    type(bouncing_ball_t), target :: ball
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: status
    real(wp) :: h0, g, e, v1, tb, vj, expected(100)
    integer :: m, j, i
    h0 = 2
    g = ball%gravity
    e = ball%restitution
    options%ode%rtol = 1e-12_wp
    options%ode%atol = 1e-12_wp
    allocate (options%ode%root_direction(2))
    options%ode%root_direction = [-1, 1]   ! the floor falling only, the mark rising only
    options%output_step = 0.01_wp
    options%progress_seconds = 0
    call drive(ball, [h0, 0.0_wp], options, result, status)
    call check(status%ok(), 'ball: drive ok: '//status%text())
    call check(result%outcome == DRIVE_EVENT_STOP, 'ball: stopped by the 4th bounce')
    call check(result%restarts == 3, 'ball: three restarts')
    ! the events in order: bounce, mark (while the rebound rises above it), bounce, ...
    v1 = sqrt(2*g*h0)
    m = 0
    tb = sqrt(2*h0/g)
    vj = v1
    do j = 1, ball%n_stop
      m = m + 1
      expected(m) = tb
      vj = e*vj
      if (j < ball%n_stop .and. vj**2 > 2*g*ball%h_mark) then
        m = m + 1
        expected(m) = tb + (vj - sqrt(vj**2 - 2*g*ball%h_mark))/g
      end if
      tb = tb + 2*vj/g
    end do
    call check(ball%n == m, 'ball: number of recorded events')
    do i = 1, min(m, ball%n)
      ! rtol 1e-12 over a few hundred steps: event times to 1e-9 s
      call check_close(ball%event_time(i), expected(i), 0.0_wp, 1e-9_wp, 'ball: event time')
    end do
    call check_close(result%t, expected(m), 0.0_wp, 1e-9_wp, 'ball: stop time')
    call check(ball%last_output < result%t, 'ball: no output after the stop')
  end subroutine bouncing_ball

  !> A run bounded by t_end ends exactly there with every output recorded.
  subroutine bounded_run()
    type(bouncing_ball_t), target :: ball
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: status
    ball%h_mark = -1   ! never crossed
    options%t_end = 0.3_wp   ! before the first bounce (0.639 s)
    options%output_step = 0.07_wp
    options%progress_seconds = 0
    call drive(ball, [2.0_wp, 0.0_wp], options, result, status)
    call check(status%ok(), 'bounded: ok')
    call check(result%outcome == DRIVE_END_TIME, 'bounded: ends at t_end')
    call check(ball%outputs == 5, 'bounded: outputs at 0.07, 0.14, 0.21, 0.28, 0.3')
    call check(ball%last_output == 0.3_wp, 'bounded: last output exactly at t_end')
    call check(result%t == 0.3_wp, 'bounded: time reached')
  end subroutine bounded_run

  !> Adams on a stiff problem trips the mean-step guard with a hint to use
  !> BDF; BDF runs it; the total step budget trips too.
  subroutine runaway_guards()
    type(stiff_t), target :: stiff
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: status
    options%t_end = 10
    options%output_step = 0.1_wp
    options%progress_seconds = 0
    options%ode%rtol = 1e-8_wp
    options%ode%atol = 1e-8_wp
    options%min_mean_step = 1e-4_wp
    options%guard_steps = 2000
    options%ode%method = ODE_ADAMS
    call drive(stiff, [1.0_wp], options, result, status)
    call check(.not. status%ok(), 'stiff/adams: stopped by the guard')
    call check(result%outcome == DRIVE_FAILED, 'stiff/adams: outcome failed')
    call check(index(status%text(), 'bdf') > 0, 'stiff/adams: message suggests bdf: '//status%text())
    call check(result%t < 1, 'stiff/adams: stopped early')
    ! the model's own diagnosis at the failure state leads the message
    stiff%diagnosis = 'k is large'
    call drive(stiff, [1.0_wp], options, result, status)
    call check(index(status%text(), '; k is large (t > 0: yes); if not that, the model looks stiff') > 0 .and. &
               index(status%text(), 'bdf') > 0, 'stiff/adams: the model''s diagnosis, then the bdf hint: '// &
               status%text())
    ! a diagnosis that rules stiffness out is given alone: BDF would not help
    stiff%not_stiffness = .true.
    call drive(stiff, [1.0_wp], options, result, status)
    call check(index(status%text(), '; k is large (t > 0: yes); a sound run') > 0 .and. &
               index(status%text(), 'bdf') == 0, 'stiff/adams, stiffness ruled out: the diagnosis without the '// &
               'bdf hint: '//status%text())
    stiff%not_stiffness = .false.
    deallocate (stiff%diagnosis)
    options%ode%method = ODE_BDF
    call drive(stiff, [1.0_wp], options, result, status)
    call check(status%ok(), 'stiff/bdf: runs: '//status%text())
    call check(result%outcome == DRIVE_END_TIME, 'stiff/bdf: to the end')
    options%ode%method = ODE_ADAMS
    options%min_mean_step = 0
    options%max_steps_total = 500_int64
    call drive(stiff, [1.0_wp], options, result, status)
    call check(.not. status%ok() .and. index(status%text(), 'runaway') > 0, 'total step budget: '//status%text())
    ! the guard follows the tolerances and a bounded step (issue 27): 1e-4 s
    ! at rtol 1e-6, (1e-5)^(1/6) of it at rtol 1e-11, never raised by a
    ! looser rtol, a tenth of max_step
    options%max_steps_total = 0
    options%min_mean_step = 1e-4_wp
    options%ode%rtol = 1e-6_wp
    call check_close(runaway_step_limit(options), 1e-4_wp, 0.0_wp, 1e-15_wp, 'guard at rtol 1e-6')
    options%ode%rtol = 1e-11_wp
    call check_close(runaway_step_limit(options), 1e-4_wp*1e-5_wp**(1.0_wp/6), 0.0_wp, 1e-15_wp, &
                     'guard at rtol 1e-11')
    options%ode%rtol = 1e-3_wp
    call check_close(runaway_step_limit(options), 1e-4_wp, 0.0_wp, 1e-15_wp, 'guard at rtol 1e-3')
    options%ode%max_step = 1e-5_wp
    call check_close(runaway_step_limit(options), 1e-6_wp, 0.0_wp, 1e-15_wp, 'guard with max_step 1e-5 s')
    ! a sound run with a bounded step (10000 steps of 1e-5 s, mean below
    ! min_mean_step) is no runaway; the guard's message names max_step
    options%ode%rtol = 1e-8_wp
    options%ode%method = ODE_BDF
    options%t_end = 0.1_wp
    options%output_step = 0.01_wp
    call drive(stiff, [1.0_wp], options, result, status)
    call check(status%ok() .and. result%outcome == DRIVE_END_TIME, 'max_step 1e-5 s: runs to the end: '// &
               status%text())
    options%ode%method = ODE_ADAMS
    options%ode%max_step = 0
    options%t_end = 10
    options%output_step = 0.1_wp
    call drive(stiff, [1.0_wp], options, result, status)
    call check(index(status%text(), 'below the guard') > 0 .and. index(status%text(), 'set max_step in &solver') > 0, &
               'guard message: the limit and how to change it: '//status%text())
  end subroutine runaway_guards

  !> A right-hand side that fails ends the run as failed with its message.
  subroutine failure_passed_on()
    type(bouncing_ball_t), target :: ball
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: status
    ball%fail_after = 0.2_wp
    ball%h_mark = -1
    options%progress_seconds = 0
    options%output_step = 0.05_wp
    options%ode%max_step = 0.01_wp   ! steps short enough to reach the outputs before 0.2 s
    call drive(ball, [2.0_wp, 0.0_wp], options, result, status)
    call check(.not. status%ok(), 'failure: status set')
    call check(result%outcome == DRIVE_FAILED, 'failure: outcome')
    call check(index(status%text(), 'on purpose') > 0, 'failure: the model''s message: '//status%text())
    call check(ball%outputs >= 3 .and. ball%last_output <= 0.2_wp, 'failure: outputs before it kept')
    options%output_step = -1
    call drive(ball, [2.0_wp, 0.0_wp], options, result, status)
    call check(.not. status%ok() .and. index(status%text(), 'output_step') > 0, 'bad options refused')
  end subroutine failure_passed_on

  !> CVODE's CV_ILL_INPUT after the run has started (records made) is a
  !> failure part way (STATUS_SOLVER: exit 2, the file kept and marked
  !> incomplete), not bad input with nothing written (STATUS_INVALID_INPUT:
  !> exit 1), which it was taken for before.
  subroutine ill_input_part_way()
    type(sticky_root_t), target :: sticky
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: status
    options%progress_seconds = 0
    options%output_step = 0.1_wp
    options%t_end = 2
    call drive(sticky, [0.0_wp], options, result, status)
    call check(.not. status%ok() .and. result%outcome == DRIVE_FAILED, 'ill input part way: the run failed')
    call check(index(status%text(), 'CV_ILL_INPUT') > 0, 'ill input part way: CVODE''s flag named: '//status%text())
    call check(status%code == STATUS_SOLVER, 'ill input part way: a failure part way (STATUS_SOLVER), not '// &
               'bad input')
    ! CVODE reports the root where its search first sees g = 0 (at t_stick or
    ! up to the output time after it) and fails on the call after that
    call check(sticky%outputs >= 4 .and. sticky%events == 1 .and. result%t >= sticky%t_stick .and. &
               result%t <= sticky%t_stick + options%output_step, &
               'ill input part way: the outputs before t_stick and the root were recorded')
  end subroutine ill_input_part_way
end program test_event_driver
