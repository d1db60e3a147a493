!> The one integration driver every model runs through: outputs at fixed
!> times, events from CVODE's root finding handled by the model, progress
!> lines on long runs (to the caller's log; none without one), and a guard
!> against runaway step counts.
!>
!> A model is an `event_system_t`: an ODE system (right-hand side and root
!> functions, numerics_ode) that also records its state and decides what each
!> event means. At a root the driver asks the model (`handle_event`) and does
!> what it answers:
!>   EVENT_IGNORE   go on (no record);
!>   EVENT_RECORD   record the state at the event and go on (e.g. a station);
!>   EVENT_RESTART  the model changed itself or the state (a force switched on
!>                  or off, a velocity jump): record, then restart the
!>                  integrator from (t, y) with no history (CVodeReInit);
!>   EVENT_STOP     record and end the run (end of the slide, lift-off, ...).
!> The model sees model state in its root functions (normal forces, water
!> edges) because they are its own procedures.
!>
!> Outputs: t_start + k output_step up to t_end (the last one exactly at t_end
!> when t_end is finite), or with an output_origin the times origin + k
!> output_step after t_start (a run going on from another's end, on its grid). With t_end = huge (no bound) the model must end the
!> run by an event; the runaway guards bound the work.
!>
!> Runaway guards: max_steps_total internal steps in all, and a mean step
!> below the guard's limit once guard_steps steps have been taken (e.g. Adams
!> on a stiff problem such as bodies at rest under regularized Coulomb
!> friction); both end the run as failed with a message that says what to
!> change. The limit follows the tolerances and the step bound
!> (runaway_step_limit): min_mean_step is meant for rtol 1e-6; a tighter rtol
!> lowers it by (rtol/1e-6)^(1/6), as the steps of a method of order 5 (BDF's
!> highest; Adams runs at such orders or higher at these tolerances) shrink,
!> and a max_step lowers it to a tenth of that step, so that a sound run with
!> tight tolerances or a bounded step is not called a runaway (the Coulomb
!> egg at rtol 1e-11 with BDF takes 3.4e-5 s steps; the guard is 1.5e-5 s
!> there). Under Adams the message says the model looks stiff and to use BDF,
!> which integrates such runs (a decision: no silent switch of the method the
!> input asked for).
module numerics_event_driver
  use base_kinds, only: wp, int64
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_SOLVER
  use base_log, only: progress_interval, log_sink_i
  use numerics_ode, only: ode_system_t, ode_options_t, ode_stats_t, ode_integrator_t, ODE_ADAMS
  implicit none (type, external)
  private
  public :: event_system_t, driver_options_t, driver_result_t, drive
  public :: EVENT_IGNORE, EVENT_RECORD, EVENT_RESTART, EVENT_STOP
  public :: RECORD_START, RECORD_OUTPUT, RECORD_EVENT
  public :: DRIVE_END_TIME, DRIVE_EVENT_STOP, DRIVE_FAILED, drive_outcome_name, runaway_step_limit
  public :: add_driver_result

  integer, parameter :: EVENT_IGNORE = 0, EVENT_RECORD = 1, EVENT_RESTART = 2, EVENT_STOP = 3
  integer, parameter :: RECORD_START = 1, RECORD_OUTPUT = 2, RECORD_EVENT = 3
  integer, parameter :: DRIVE_END_TIME = 1, DRIVE_EVENT_STOP = 2, DRIVE_FAILED = 3
  integer, parameter :: chunk_steps = 5000   !< internal steps between two looks at guards and progress
  integer, parameter :: max_dense_order = 12   !< CVODE's highest order (Adams)

  !> An ODE system with records and event handling.
  type, abstract, extends(ode_system_t) :: event_system_t
    !> the output time the driver integrates toward: a root function called
    !> at it is followed by a record there (CVODE checks the roots at t_out
    !> when t_out lies inside its step); other calls between step ends are
    !> CVODE's root location
    real(wp) :: t_output = huge(1.0_wp)
    !> true: the driver shows the system every internal step's dense output
    !> (observe_step), for quantities located between the records; CVODE
    !> then returns after each step (max_steps 1 per call: the same steps,
    !> roots and outputs as in one call per output)
    logical :: observes_steps = .false.
  contains
    procedure(record_i), deferred :: record
    procedure :: observe_step => default_observe_step
    procedure :: handle_event => default_handle_event
    procedure :: progress => default_progress
    procedure :: diagnose => default_diagnose
    procedure :: stiffness_may_cause => default_stiffness_may_cause
  end type event_system_t

  abstract interface
    !> Keeps the state (t, y); `kind` is RECORD_START, RECORD_OUTPUT or
    !> RECORD_EVENT. A failure (status set) ends the run as failed.
    subroutine record_i(self, t, y, kind, status)
      import :: event_system_t, wp, status_t
      class(event_system_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      integer, intent(in) :: kind
      type(status_t), intent(inout) :: status
    end subroutine record_i
  end interface

  type :: driver_options_t
    type(ode_options_t) :: ode
    real(wp) :: t_start = 0                   !< s
    real(wp) :: t_end = huge(1.0_wp)          !< s; huge: no bound (the model stops by an event)
    real(wp) :: output_step = 0.01_wp         !< s, > 0
    !> s: the output times are output_origin + k output_step after t_start
    !> (a run that goes on from another's end keeps its grid); huge: t_start
    real(wp) :: output_origin = huge(1.0_wp)
    integer(int64) :: max_steps_total = 0     !< internal steps in all; 0: no limit
    real(wp) :: min_mean_step = 0             !< s at rtol 1e-6; a smaller mean step after guard_steps fails
                                              !< the run (runaway_step_limit: tighter tolerances lower it)
    integer(int64) :: guard_steps = 20000     !< steps before min_mean_step is judged
    !> wall-clock s between progress lines; 0: none; < 0: the program's
    !> setting (base_log progress_interval: 2 s unless slidesim --progress)
    real(wp) :: progress_seconds = -1
    character(len=:), allocatable :: label    !< names the run in progress lines and messages
    !> where the progress lines go; not given: none (the library prints nothing)
    procedure(log_sink_i), pointer, nopass :: log => null()
  end type driver_options_t

  type :: driver_result_t
    integer :: outcome = DRIVE_FAILED
    real(wp) :: t = 0                         !< s, time reached
    integer, allocatable :: fired(:)          !< the roots of the stopping event (+1 rising, -1 falling)
    integer :: events = 0, restarts = 0, outputs = 0
    type(ode_stats_t) :: stats
    real(wp) :: cpu = 0                       !< s of process CPU time spent in drive
  end type driver_result_t

contains

  !> A later stretch of one run (a drive after a switch of model or phase)
  !> added to `total`: the stretch's outcome, time, fired roots and last
  !> step; counts and CPU time summed.
  pure subroutine add_driver_result(total, part)
    type(driver_result_t), intent(inout) :: total
    type(driver_result_t), intent(in) :: part
    total%outcome = part%outcome
    total%t = part%t
    if (allocated(total%fired)) deallocate (total%fired)
    if (allocated(part%fired)) total%fired = part%fired
    total%events = total%events + part%events
    total%restarts = total%restarts + part%restarts
    total%outputs = total%outputs + part%outputs
    total%cpu = total%cpu + part%cpu
    total%stats%steps = total%stats%steps + part%stats%steps
    total%stats%rhs_evaluations = total%stats%rhs_evaluations + part%stats%rhs_evaluations
    total%stats%error_test_failures = total%stats%error_test_failures + part%stats%error_test_failures
    total%stats%nonlinear_failures = total%stats%nonlinear_failures + part%stats%nonlinear_failures
    total%stats%root_evaluations = total%stats%root_evaluations + part%stats%root_evaluations
    total%stats%last_step = part%stats%last_step
    total%stats%last_order = part%stats%last_order
  end subroutine add_driver_result

  pure function drive_outcome_name(outcome) result(text)
    integer, intent(in) :: outcome
    character(len=:), allocatable :: text
    select case (outcome)
    case (DRIVE_END_TIME); text = 'end time'
    case (DRIVE_EVENT_STOP); text = 'stopped by an event'
    case default; text = 'failed'
    end select
  end function drive_outcome_name

  !> The runaway guard's mean-step limit (s) for these options (module
  !> comment): min_mean_step times min(1, (rtol/1e-6)^(1/6)), at most a tenth
  !> of max_step when that is set; 0: no guard.
  pure real(wp) function runaway_step_limit(options) result(limit)
    type(driver_options_t), intent(in) :: options
    real(wp), parameter :: reference_rtol = 1e-6_wp
    limit = options%min_mean_step*min(1.0_wp, (options%ode%rtol/reference_rtol)**(1.0_wp/6))
    if (options%ode%max_step > 0) limit = min(limit, options%ode%max_step/10)
  end function runaway_step_limit

  !> Default: every event stops the run.
  subroutine default_handle_event(self, t, y, fired, action, status)
    class(event_system_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t, unused_y => y, unused_f => fired, unused_s => status)
    end associate
    action = EVENT_STOP
  end subroutine default_handle_event

  !> Default: steps are not observed.
  subroutine default_observe_step(self, t_n, h, taylor, status)
    class(event_system_t), intent(inout) :: self
    real(wp), intent(in) :: t_n, h, taylor(:, 0:)
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t_n, unused_h => h, unused_p => taylor, unused_s => status)
    end associate
  end subroutine default_observe_step

  !> Default progress: the fraction of [t_start, t_end] done (negative when the
  !> run has no time bound) and the time reached.
  subroutine default_progress(self, t, y, t_start, t_end, fraction, text)
    class(event_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:), t_start, t_end
    real(wp), intent(out) :: fraction
    character(len=:), allocatable, intent(out) :: text
    associate (unused => self, unused_y => y)
    end associate
    fraction = -1
    if (t_end < huge(t_end)) fraction = (t - t_start)/(t_end - t_start)
    text = 't = '//format_short(t)//' s'
  end subroutine default_progress

  !> What makes the model hard to integrate at (t, y), in the user's terms,
  !> for the message of a run that fails by its step count ('' when nothing
  !> is known: the default).
  function default_diagnose(self, t, y) result(text)
    class(event_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    character(len=:), allocatable :: text
    associate (unused => self, unused_t => t, unused_y => y)
    end associate
    text = ''
  end function default_diagnose

  !> Whether stiffness may be what makes the model hard to integrate at
  !> (t, y), so that method = 'bdf' may help (the default: it may). A model
  !> whose diagnose names a cause BDF cannot mend (a singular coordinate)
  !> says no: the message then gives that cause alone.
  logical function default_stiffness_may_cause(self, t, y) result(may)
    class(event_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    associate (unused => self, unused_t => t, unused_y => y)
    end associate
    may = .true.
  end function default_stiffness_may_cause

  !> Runs `system` from (t_start, y0). Returns with status ok when the run
  !> reached t_end or an event stopped it (result%outcome says which); with
  !> the failure otherwise (result%outcome = DRIVE_FAILED, result%t the time
  !> reached). Everything recorded before a failure stays with the system.
  subroutine drive(system, y0, options, result, status)
    class(event_system_t), intent(inout), target :: system
    real(wp), intent(in) :: y0(:)
    type(driver_options_t), intent(in) :: options
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    type(ode_integrator_t) :: integrator
    type(ode_options_t) :: ode_options
    real(wp) :: y(size(y0)), t, t_out, cpu0, cpu1
    real(wp), allocatable :: taylor(:, :)
    real(wp) :: observed_t, observed_h
    integer, allocatable :: fired(:)
    integer :: action
    integer(int64) :: k, k_origin, clock_rate, clock_last, clock_now, steps_at_output
    logical :: root_found, chunk_ended
    character(len=:), allocatable :: label

    call cpu_time(cpu0)
    label = 'run'
    if (allocated(options%label)) label = options%label
    call check_driver_options(options, status)
    if (.not. status%ok()) return
    allocate (fired(max(system%root_count(), 1)))
    allocate (result%fired(size(fired)))
    result%fired = 0
    y = y0
    t = options%t_start
    result%t = t

    call system%record(t, y, RECORD_START, status)
    if (.not. status%ok()) then
      call prefix_status(status, label//' at the start')
      call finish()
      return
    end if
    ! CVODE works in chunks of at most chunk_steps internal steps, so that the
    ! guards and the progress lines act inside long output intervals too; the
    ! user's max_steps (per output interval) is counted here.
    ode_options = options%ode
    ode_options%max_steps = min(options%ode%max_steps, chunk_steps)
    if (system%observes_steps) then
      ode_options%max_steps = 1
      allocate (taylor(size(y0), 0:max_dense_order))
      observed_t = t
      observed_h = 0
    end if
    call integrator%start(system, t, y, ode_options, status)
    if (status%ok() .and. options%t_end < huge(options%t_end)) call integrator%set_stop_time(options%t_end, status)
    if (.not. status%ok()) then
      call prefix_status(status, label)
      call finish()
      return
    end if
    call system_clock(clock_last, clock_rate)

    k = 0
    steps_at_output = 0
    k_origin = first_output_index(options)
    do
      if (options%output_origin < huge(options%output_origin)) then
        t_out = options%output_origin + real(k_origin + k, wp)*options%output_step
      else
        t_out = options%t_start + real(k + 1, wp)*options%output_step
      end if
      if (t_out > options%t_end) t_out = options%t_end
      system%t_output = t_out
      call integrator%advance(t_out, t, y, status, root_found, fired, chunk_ended)
      result%t = t
      if (.not. status%ok()) then
        call prefix_status(status, label//' stopped at t = '//format_short(t)//' s')
        exit
      end if
      if (system%observes_steps) call observe_step(status)
      if (.not. status%ok()) then
        call prefix_status(status, label//' at t = '//format_short(t)//' s')
        exit
      end if
      call check_runaway(status)
      if (.not. status%ok()) exit
      call report_progress()
      if (chunk_ended) cycle

      if (root_found) then
        result%events = result%events + 1
        call system%handle_event(t, y, fired, action, status)
        if (.not. status%ok()) then
          call prefix_status(status, label//' at the event at t = '//format_short(t)//' s')
          exit
        end if
        if (action == EVENT_IGNORE) cycle
        call system%record(t, y, RECORD_EVENT, status)
        if (.not. status%ok()) then
          call prefix_status(status, label//' at t = '//format_short(t)//' s')
          exit
        end if
        select case (action)
        case (EVENT_STOP)
          result%outcome = DRIVE_EVENT_STOP
          result%fired = fired
          exit
        case (EVENT_RESTART)
          call integrator%restart(t, y, status)
          if (.not. status%ok()) then
            call prefix_status(status, label//' restart at t = '//format_short(t)//' s')
            exit
          end if
          result%restarts = result%restarts + 1
        end select
        cycle
      end if

      k = k + 1
      result%stats = integrator%statistics()
      steps_at_output = result%stats%steps
      result%outputs = result%outputs + 1
      call system%record(t, y, RECORD_OUTPUT, status)
      if (.not. status%ok()) then
        call prefix_status(status, label//' at t = '//format_short(t)//' s')
        exit
      end if
      if (t >= options%t_end) then
        result%outcome = DRIVE_END_TIME
        exit
      end if
    end do
    call finish()

  contains

    subroutine finish()
      result%stats = integrator%statistics()
      call cpu_time(cpu1)
      result%cpu = cpu1 - cpu0
    end subroutine finish

    !> The system sees each internal step once, before the records and
    !> events at its end (an event's handling may change the model).
    subroutine observe_step(st)
      type(status_t), intent(inout) :: st
      real(wp) :: t_n, h
      integer :: order
      call integrator%step_polynomial(t_n, h, order, taylor, st)
      if (.not. st%ok() .or. h == 0) return
      if (t_n == observed_t .and. h == observed_h) return
      observed_t = t_n
      observed_h = h
      call system%observe_step(t_n, h, taylor(:, 0:order), st)
    end subroutine observe_step

    subroutine check_runaway(st)
      type(status_t), intent(inout) :: st
      type(ode_stats_t) :: s
      real(wp) :: mean_step, limit
      s = integrator%statistics()
      if (s%steps - steps_at_output > options%ode%max_steps) then
        call set_status(st, STATUS_SOLVER, label//': more than max_steps = '// &
          format_short(real(options%ode%max_steps, wp))//' internal steps between two outputs, at t = '// &
          format_short(t)//' s (raise max_steps in &solver)'//hint())
        return
      end if
      if (options%max_steps_total > 0 .and. s%steps > options%max_steps_total) then
        call set_status(st, STATUS_SOLVER, label//': runaway integration, more than '// &
          format_short(real(options%max_steps_total, wp))//' internal steps by t = '//format_short(t)//' s'//hint())
        return
      end if
      limit = runaway_step_limit(options)
      if (limit > 0 .and. s%steps >= options%guard_steps) then
        mean_step = (t - options%t_start)/real(s%steps, wp)
        if (mean_step < limit) then
          call set_status(st, STATUS_SOLVER, label//': runaway integration, '// &
            format_short(real(s%steps, wp))//' internal steps for '//format_short(t - options%t_start)// &
            ' s simulated (mean step '//format_short(mean_step)//' s, below the guard '// &
            format_short(limit)//' s: '//format_short(options%min_mean_step)//' s at rtol 1e-6, times '// &
            '(rtol/1e-6)^(1/6) for a tighter rtol, at most a tenth of max_step)'//hint()// &
            '; a sound run with steps this short: set max_step in &solver, the guard becomes a tenth of it')
        end if
      end if
    end subroutine check_runaway

    !> What the model knows about the trouble at (t, y), and the stiffness
    !> hint where BDF may help: the run is Adams and the model does not rule
    !> stiffness out (stiffness_may_cause).
    function hint() result(text)
      character(len=:), allocatable :: text, stiff
      stiff = ''
      text = system%diagnose(t, y)
      if (options%ode%method == ODE_ADAMS) then
        if (system%stiffness_may_cause(t, y)) stiff = 'the model looks stiff (for example bodies at rest '// &
          'under Coulomb friction): use method = ''bdf'' in &solver'
      end if
      if (len(text) > 0 .and. len(stiff) > 0) then
        text = '; '//text//'; if not that, '//stiff
      else if (len(text) + len(stiff) > 0) then
        text = '; '//text//stiff
      end if
    end function hint

    subroutine report_progress()
      real(wp) :: fraction, interval
      character(len=:), allocatable :: text
      if (.not. associated(options%log)) return
      interval = options%progress_seconds
      if (interval < 0) interval = progress_interval()
      if (.not. interval > 0) return
      call system_clock(clock_now)
      if (real(clock_now - clock_last, wp) < interval*real(clock_rate, wp)) return
      clock_last = clock_now
      call system%progress(t, y, options%t_start, options%t_end, fraction, text)
      if (fraction >= 0) text = format_short(100*min(fraction, 1.0_wp))//' % ('//text//')'
      call options%log(label//': '//text)
    end subroutine report_progress
  end subroutine drive

  !> With an output origin: the index of the first output time after t_start
  !> (origin + index output_step > t_start); 1 without one.
  pure integer(int64) function first_output_index(options) result(k)
    type(driver_options_t), intent(in) :: options
    k = 1
    if (.not. options%output_origin < huge(options%output_origin)) return
    k = int(floor((options%t_start - options%output_origin)/options%output_step), int64) + 1
    do while (options%output_origin + real(k, wp)*options%output_step <= options%t_start)
      k = k + 1
    end do
  end function first_output_index

  subroutine check_driver_options(options, status)
    type(driver_options_t), intent(in) :: options
    type(status_t), intent(inout) :: status
    if (.not. (abs(options%t_start) < huge(1.0_wp))) then
      call set_status(status, STATUS_INVALID_INPUT, 'driver: t_start must be finite')
    else if (.not. (options%t_end > options%t_start)) then
      call set_status(status, STATUS_INVALID_INPUT, 'driver: t_end must be greater than t_start')
    else if (.not. (options%output_step > 0 .and. options%output_step < huge(1.0_wp))) then
      call set_status(status, STATUS_INVALID_INPUT, 'driver: output_step must be a finite number > 0')
    else if (options%output_origin < huge(1.0_wp) .and. .not. (options%output_origin <= options%t_start)) then
      call set_status(status, STATUS_INVALID_INPUT, 'driver: output_origin must be at or before t_start')
    else if (.not. (options%min_mean_step >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'driver: min_mean_step must be >= 0')
    else if (options%t_end < huge(1.0_wp)) then
      ! the output count must stay representable (and the time grid resolvable)
      if ((options%t_end - options%t_start)/options%output_step > 1e12_wp) &
        call set_status(status, STATUS_INVALID_INPUT, 'driver: more than 1e12 output times; '// &
                        'choose a larger output_step')
    end if
  end subroutine check_driver_options
end module numerics_event_driver
