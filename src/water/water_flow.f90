!> Running the streamline: start values, and the run on the shared integration
!> driver (numerics_event_driver) to the end of the slide: outputs every
!> output_step (with the water edges), the report at stations, the run's own
!> stops (stall, turning back, near-critical flow, lift-off) as events with
!> messages, and a time bound (the user's, or a safety bound).
!>
!> How a run ends:
!> - the end of the slide (root u = u_end): OUTCOME_END, status ok;
!> - the caller's time bound `duration` (finite: the user asked for it):
!>   OUTCOME_DURATION, status ok; the caller says so in its report;
!> - a stop of the model (stall, turn, critical flow, lift-off): status
!>   STATUS_DOMAIN with the message, the samples up to the stop kept;
!> - the safety bound t_safety = 200 L/min_speed (L the slide's length from
!>   the start to u_end), which no run can reach without a stop firing first:
!>   while the water runs at w >= min_speed at an angle |beta| <= 89.4 deg
!>   (cos beta >= 0.01) to the centerline, a section moves along at least
!>   w cos(beta) |c_u|/(-y_M.r_u) >= 0.01 min_speed/2 (the factor, the
!>   centerline's over the wall's speed at an offset, stays above 1/2 as long
!>   as the tube does not fold: chi times the extent < 1). Reaching it is a
!>   failure (OUTCOME_SAFETY_BOUND, STATUS_DOMAIN) that points to a bug or a
!>   model the reasoning does not cover;
!> - a failure of the integrator or the model (OUTCOME_ERROR).
!> Inlets downstream of the start (water_inlet) are roots u = u_inlet: the
!> sample before the merge is recorded, the inlet joins (flow rate and state
!> jump), the sample after it is recorded and the integrator restarts from
!> there; a merged state already beyond a stop of the model ends the run
!> with that stop.
!> The model is not changed by a run (intent(in)); the run's own state lives
!> in a local event system, so runs can go on in several threads at once.
!> The start values are water_start's, the samples water_series'.
module water_flow
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_log, only: log_sink_i
  use base_series, only: max_series_bytes
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use numerics_ode, only: ode_options_t
  use numerics_event_driver, only: event_system_t, driver_options_t, driver_result_t, drive, &
    EVENT_IGNORE, EVENT_RESTART, EVENT_STOP, RECORD_START, DRIVE_END_TIME, DRIVE_EVENT_STOP
  use water_streamline, only: streamline_t, water_point_t, water_point, CORRECTION_OFF
  use water_boundaries, only: water_edges
  use water_inlet, only: water_inlet_t, join_inlet
  use water_start, only: water_start_t, water_initial_state, START_EDGES, START_HEIGHT, START_SPEED, &
    START_HEIGHT_SPEED
  use water_series, only: water_series_t, water_station_t, allocate_series, record_sample, values_per_sample, &
    OUTCOME_END, OUTCOME_DURATION, OUTCOME_STALL, OUTCOME_TURN, OUTCOME_CRITICAL, OUTCOME_ERROR, &
    OUTCOME_LIFT, OUTCOME_SAFETY_BOUND, outcome_name
  implicit none (type, external)
  private
  ! the start (water_start) and the samples (water_series), as the run's callers name them
  public :: water_start_t, water_series_t, water_station_t
  public :: water_initial_state, simulate_water, safety_time_bound
  public :: START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED
  public :: OUTCOME_END, OUTCOME_DURATION, OUTCOME_STALL, OUTCOME_TURN, OUTCOME_CRITICAL, &
    OUTCOME_ERROR, OUTCOME_LIFT, OUTCOME_SAFETY_BOUND, outcome_name
  public :: ROOT_END, ROOT_STALL, ROOT_CRITICAL, ROOT_TURN, ROOT_LIFT, ROOT_FIRST_STATION

  !> Root functions of a run: the end, the model's stops, then one per
  !> station, then one per inlet.
  integer, parameter :: ROOT_END = 1, ROOT_STALL = 2, ROOT_CRITICAL = 3, ROOT_TURN = 4, ROOT_LIFT = 5, &
                        ROOT_FIRST_STATION = 6
  !> cos(beta) at which the flow counts as turning across or back (89.4 deg;
  !> R of (4.15) is singular at 90 deg)
  real(wp), parameter :: turn_cosine = 0.01_wp
  !> Adams' fixed-point corrector stops at half the local error tolerance
  !> (CVODE's default: a tenth): most steps take one iteration instead of
  !> two, 7995 -> 6202 right-hand sides for 4110 -> 4257 steps on the demo
  !> slide, and the water against a reference at rtol 1e-13 is as close as
  !> before (docs/water.md, "Speed"). As the ride's (rider_ride).
  real(wp), parameter :: water_convergence_coefficient = 0.5_wp
  !> the safety bound in units of L/min_speed (see the module header)
  real(wp), parameter :: safety_factor = 200

  !> The running water: the model (read only), what is recorded, and a cache
  !> of the last water point (the root functions at an output time and the
  !> record there see the same state, and a step's right-hand side may too).
  type, extends(event_system_t) :: water_system_t
    type(streamline_t), pointer :: model => null()
    type(water_series_t), pointer :: series => null()
    logical :: with_edges = .true.
    real(wp) :: u_start = 0, u_end = 0
    real(wp) :: flow = 0                         ! m^3/s, the flow rate now (inlets joined so far)
    type(water_inlet_t), allocatable :: inlets(:)
    integer :: outcome = 0                       ! set by a model stop (or OUTCOME_ERROR)
    character(len=:), allocatable :: message
    logical :: cached = .false.
    real(wp) :: cache_y(5) = 0           ! the state self%q belongs to
    type(water_point_t) :: q             ! the last water point (valid if cached)
    ! the root values that depend on the water point (stall, critical, turn,
    ! lift-off) at the last right-hand side, its (t, y), and the largest
    ! |value| of each met in the run (system_roots)
    logical :: rhs_roots_known = .false.
    real(wp) :: rhs_t = 0, rhs_y(5) = 0, rhs_g(ROOT_STALL:ROOT_LIFT) = 0
    real(wp) :: root_scale(ROOT_STALL:ROOT_LIFT) = 0
  contains
    procedure :: rhs => system_rhs
    procedure :: root_count => system_root_count
    procedure :: roots => system_roots
    procedure :: record => system_record
    procedure :: handle_event => system_handle_event
    procedure :: progress => system_progress
    procedure :: point => system_point
  end type water_system_t

contains



  !> The safety bound on time of a run from u0 to u_end: 200 L/min_speed
  !> (module header), L the centerline arc length between them.
  function safety_time_bound(model, u0) result(t)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: u0
    real(wp) :: t
    real(wp) :: u_min, u_max
    call model%channel%u_range(u_min, u_max)
    t = safety_factor*(model%channel%arc_length(min(model%u_end, u_max)) - model%channel%arc_length(u0)) &
        /model%min_speed
  end function safety_time_bound

  !> Room for the samples a run will likely take: at the start speed (or
  !> 0.5 m/s, if slower) the slide twice over, or the bound; grown if needed.
  !> Room never written costs no memory (the pages are not touched).
  function initial_samples(model, y0, duration, output_step) result(n)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: y0(:), duration, output_step
    integer :: n
    type(water_point_t) :: q
    type(status_t) :: st
    real(wp) :: t_likely
    call water_point(model, y0, q, st)
    t_likely = 2*(safety_time_bound(model, y0(1))*model%min_speed/safety_factor)/max(q%speed, 0.5_wp)
    n = int(min(min(duration, t_likely)/output_step, max_series_bytes/(8*values_per_sample))) + 16
  end function initial_samples

  !> Integrates from y0 to the end of the slide (u = u_end, at the latest the
  !> channel's end) on the shared driver. `duration`: the caller's bound on
  !> time (huge(1.0): none, the safety bound applies). Records every
  !> output_step; fills the stations at their roots; solves the edges at every
  !> record if `edges`. The series keeps what was computed and why the run
  !> ended (outcome, message); `status` is ok at the end of the slide and at
  !> the caller's bound, else it says why the run stopped early. The model is
  !> not changed. Progress lines (the driver's): to `log` if given (none
  !> without it, or when `progress_seconds` is 0; default: the program's interval).
  !> `inlets`: water joining downstream of the start (u set; those marked
  !> joined are taken as joined already, at the start); series%inlets says
  !> which joined when.
  subroutine simulate_water(model, y0, options, duration, output_step, series, status, edges, log, &
                            progress_seconds, inlets)
    type(streamline_t), intent(in), target :: model
    real(wp), intent(in) :: y0(:), duration, output_step
    type(ode_options_t), intent(in) :: options
    type(water_series_t), intent(out), target :: series
    type(status_t), intent(out) :: status
    logical, intent(in), optional :: edges
    procedure(log_sink_i), optional :: log
    real(wp), intent(in), optional :: progress_seconds
    type(water_inlet_t), intent(in), optional :: inlets(:)
    type(water_system_t), target :: system
    type(driver_options_t) :: opts
    type(driver_result_t) :: result
    real(wp) :: u_min, u_max, t_safety
    integer :: nroots, i

    system%model => model
    system%series => series
    system%with_edges = .true.
    if (present(edges)) system%with_edges = edges
    series%edges = system%with_edges
    call model%channel%u_range(u_min, u_max)
    system%u_end = min(model%u_end, u_max)   ! the slide ends at the channel's end at the latest
    system%u_start = y0(1)
    series%flow_rate = model%flow_rate
    system%flow = model%flow_rate
    if (present(inlets)) then
      system%inlets = inlets
    else
      allocate (system%inlets(0))
    end if
    call allocate_series(series, initial_samples(model, y0, duration, output_step))
    nroots = system%root_count()
    allocate (series%stations(station_count(system)))
    do i = 1, size(series%stations)
      series%stations(i)%u = model%stations(i)
    end do

    t_safety = safety_time_bound(model, y0(1))
    opts%ode = options
    opts%ode%convergence_coefficient = water_convergence_coefficient
    if (allocated(opts%ode%root_direction)) deallocate (opts%ode%root_direction)
    allocate (opts%ode%root_direction(nroots))
    opts%ode%root_direction = -1                  ! the stops: falling through zero
    opts%ode%root_direction(ROOT_FIRST_STATION:) = 1
    opts%t_end = min(duration, t_safety)
    opts%output_step = output_step
    opts%label = 'water'
    if (present(log)) opts%log => log
    if (present(progress_seconds)) opts%progress_seconds = progress_seconds
    series%time_bound = opts%t_end
    call drive(system, y0, opts, result, status)
    series%stats = result%stats
    series%cpu = result%cpu
    series%inlets = system%inlets

    if (system%outcome /= OUTCOME_ERROR .and. system%outcome /= 0) then
      ! a stop of the model, decided at its event (or at the start)
      series%outcome = system%outcome
      if (allocated(system%message)) then
        call set_status(status, STATUS_DOMAIN, system%message)
      else
        status%code = 0
      end if
    else if (status%ok() .and. result%outcome == DRIVE_END_TIME) then
      if (duration <= t_safety) then
        series%outcome = OUTCOME_DURATION
      else
        series%outcome = OUTCOME_SAFETY_BOUND
        call set_status(status, STATUS_DOMAIN, 'the water did not reach the end of the slide within the '// &
                        'safety bound t = '//format_short(t_safety)//' s (200 x slide length / min_speed; '// &
                        'see docs/water.md) at arc length '//format_short(series%arc_length(series%n))//' m')
      end if
    else if (status%ok() .and. result%outcome == DRIVE_EVENT_STOP) then
      series%outcome = OUTCOME_END   ! the only event that stops without a model stop
    else
      series%outcome = OUTCOME_ERROR
    end if
    if (.not. status%ok()) series%message = status%text()
  end subroutine simulate_water

  !> The water point at y (the cached one if y(1:5) is the cached state).
  !> Makes self%q the water point at y: kept from the last call if y(1:5) is
  !> the same state (no copy), else evaluated in place.
  subroutine system_point(self, y, status)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: y(:)
    type(status_t), intent(inout) :: status
    if (self%cached) then
      if (all(y(1:5) == self%cache_y)) return
    end if
    call water_point(self%model, y, self%q, status)
    self%cached = status%ok()
    if (self%cached) self%cache_y = y(1:5)
  end subroutine system_point

  subroutine system_rhs(self, t, y, ydot, status)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused => t)
    end associate
    self%rhs_roots_known = .false.
    call self%point(y, status)
    if (.not. status%ok()) then
      ydot = 0
      return
    end if
    call point_roots(self, self%rhs_g)
    self%root_scale = max(self%root_scale, abs(self%rhs_g))
    self%rhs_t = t
    self%rhs_y = y(1:5)
    self%rhs_roots_known = .true.
    ydot(1) = y(3)
    ydot(2) = y(4)
    ydot(3) = self%q%udd
    ydot(4) = self%q%vdd
    ydot(5) = self%q%height_rate
    ydot(6) = -self%q%friction*self%q%speed
    ydot(7) = -self%q%kappa*self%q%speed
  end subroutine system_rhs

  integer function system_root_count(self) result(n)
    class(water_system_t), intent(in) :: self
    n = ROOT_FIRST_STATION - 1 + station_count(self) + size(self%inlets)
  end function system_root_count

  pure integer function station_count(self) result(n)
    class(water_system_t), intent(in) :: self
    n = 0
    if (allocated(self%model%stations)) n = size(self%model%stations)
  end function station_count

  !> g1 = u_end - u (end of slide), g2 = w - min_speed (stall), g3 = criticality
  !> - min_criticality (approach to Fr = 1), g4 = cos(beta) - 0.01 (turning across
  !> or back; R of (4.15) is singular at beta = 90 deg), g5 = N/m (lift-off: the
  !> normal force (4.12) turns negative, the surface would have to pull the
  !> water), then u - u_i for the stations.
  !> Lift-off is a root, not a check at output times: N depends continuously on
  !> the state (u, v, u', v') through r_uu, r_uv, r_vv, so its sign change is an
  !> event in time that root finding locates to the integrator's accuracy, while
  !> a check every output_step would stop up to one step late (centimetres of
  !> flight computed as if on the surface) and miss a short dip between outputs.
  subroutine system_roots(self, t, y, g)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    type(status_t) :: st
    integer :: i
    associate (unused => t)
    end associate
    g(ROOT_END) = self%u_end - y(1)
    do i = 1, station_count(self)
      g(ROOT_FIRST_STATION - 1 + i) = y(1) - self%model%stations(i)
    end do
    ! an inlet that joined (here, or at the start) fires no more
    do i = 1, size(self%inlets)
      g(ROOT_FIRST_STATION - 1 + station_count(self) + i) = merge(1.0_wp, y(1) - self%inlets(i)%u, &
                                                                   self%inlets(i)%joined)
    end do
    if (rhs_values_serve()) then
      g(ROOT_STALL:ROOT_LIFT) = self%rhs_g
      return
    end if
    call self%point(y, st)
    if (st%ok()) then
      call point_roots(self, g(ROOT_STALL:ROOT_LIFT))
    else
      g(ROOT_STALL) = 1; g(ROOT_CRITICAL) = 1; g(ROOT_TURN) = y(3); g(ROOT_LIFT) = 1
    end if
  contains
    !> CVODE asks for the roots at the end of each step, at y_n, while its
    !> last right-hand side was at the corrector's previous iterate: the
    !> same t, a state within the corrector's tolerance. The values there
    !> serve (no water point of its own) when the states differ by at most
    !> 1e-7 relative and every value is far from zero, >= 1e-3 of the
    !> largest met in the run: the error of such a value is its sensitivity
    !> to the state (O(1-10) per unit of u, v, u', v', h) times the
    !> difference, orders of magnitude below 1e-3 of its scale, so no sign
    !> can be wrong (as the mechanism's, kinetostatics_mechanism_ode). Near
    !> a root, or at any other (t, y), the water point is evaluated.
    logical function rhs_values_serve() result(serve)
      serve = .false.
      if (.not. self%rhs_roots_known .or. t /= self%rhs_t) return
      if (self%cached) then
        if (all(y(1:5) == self%cache_y)) return   ! the exact point is at hand
      end if
      if (maxval(abs(y(1:5) - self%rhs_y)) > 1e-7_wp*max(maxval(abs(self%rhs_y)), 1.0_wp)) return
      serve = all(abs(self%rhs_g) >= 1e-3_wp*self%root_scale)
    end function rhs_values_serve
  end subroutine system_roots

  !> The root values of the water point self%q: stall, critical, turn, lift-off.
  subroutine point_roots(self, g)
    class(water_system_t), intent(in) :: self
    real(wp), intent(out) :: g(ROOT_STALL:ROOT_LIFT)
    g = stop_margins(self%model, self%q)
  end subroutine point_roots

  !> The model's stops at the water point q, each > 0 while the run may go on:
  !> stall, critical, turn, lift-off (see system_roots).
  pure function stop_margins(model, q) result(g)
    type(streamline_t), intent(in) :: model
    type(water_point_t), intent(in) :: q
    real(wp) :: g(ROOT_STALL:ROOT_LIFT)
    g(ROOT_TURN) = -dot_product(q%y_m, q%x_w) - turn_cosine   ! cos(beta) - 0.01: turning across
    g(ROOT_STALL) = q%speed - model%min_speed
    g(ROOT_LIFT) = q%normal_force/model%mass    ! m/s^2
    if (model%correction == CORRECTION_OFF) then
      g(ROOT_CRITICAL) = 1
    else
      g(ROOT_CRITICAL) = q%criticality - model%min_criticality
    end if
  end function stop_margins

  !> Stations are filled here (no sample); the end and the model's stops end
  !> the run (recorded by the driver) with their outcome and message; inlets
  !> join (join_inlets) and the integrator restarts.
  subroutine system_handle_event(self, t, y, fired, action, status)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    integer :: i
    logical :: stopped
    do i = 1, station_count(self)
      if (fired(ROOT_FIRST_STATION - 1 + i) /= 0) call station(self, i, t, y)
    end do
    call model_stop(self, t, y, fired(ROOT_END:ROOT_LIFT), stopped)
    if (stopped) then
      action = EVENT_STOP
    else
      action = EVENT_IGNORE   ! stations, inlets
      call join_inlets(self, t, y, fired(ROOT_FIRST_STATION + station_count(self):), action, status)
    end if
  end subroutine system_handle_event

  !> The end or a stop of the model among `fired` (ROOT_END ... ROOT_LIFT):
  !> its outcome and message set, `stopped`.
  subroutine model_stop(self, t, y, fired, stopped)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: fired(ROOT_END:ROOT_LIFT)
    logical, intent(out) :: stopped
    stopped = .true.
    if (fired(ROOT_END) /= 0) then
      self%outcome = 0   ! the end: status ok (simulate_water sets OUTCOME_END)
    else if (fired(ROOT_STALL) /= 0) then
      call stop_model(OUTCOME_STALL, 'the water stalled (speed below min_speed = '// &
                      format_short(self%model%min_speed)//' m/s) at t = '//format_short(t)//' s, u = '//format_short(y(1)))
    else if (fired(ROOT_TURN) /= 0) then
      call stop_model(OUTCOME_TURN, 'the water turns across the slide or back (angle to the centerline '// &
                      'beyond 89.4 deg) at t = '//format_short(t)//' s, u = '//format_short(y(1)))
    else if (fired(ROOT_LIFT) /= 0) then
      call stop_model(OUTCOME_LIFT, lift_message(t, y))
    else if (fired(ROOT_CRITICAL) /= 0) then
      call stop_model(OUTCOME_CRITICAL, 'the flow approaches critical (1 - 1/Fr^2 = '// &
                      format_short(self%model%min_criticality)//') at t = '//format_short(t)//' s, u = '// &
                      format_short(y(1))//': the Saint-Venant correction is singular at Fr = 1; '// &
                      'the water is too slow for shallow supercritical flow here; '// &
                      'switch the correction off (correction = ''off'') to go on')
    else
      stopped = .false.
    end if
  contains
    subroutine stop_model(outcome, message)
      integer, intent(in) :: outcome
      character(len=*), intent(in) :: message
      self%outcome = outcome
      self%message = message
    end subroutine stop_model
  end subroutine model_stop

  !> The inlets whose roots fired (`fired`, one per inlet) join the stream at
  !> (t, y): the sample before is recorded here, y and the flow rate become
  !> the merged ones (the driver records them and restarts: EVENT_RESTART).
  !> A merged state beyond a stop of the model (slower than min_speed, near
  !> critical, ...) ends the run there with that stop (EVENT_STOP).
  subroutine join_inlets(self, t, y, fired, action, status)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(inout) :: action
    type(status_t), intent(inout) :: status
    real(wp) :: y_joined(size(y)), flow_joined, g(ROOT_STALL:ROOT_LIFT)
    integer :: k, stops(ROOT_END:ROOT_LIFT)
    logical :: stopped
    if (.not. any(fired /= 0 .and. .not. self%inlets%joined)) return
    call self%point(y, status)
    if (status%ok()) call record_sample(self%model, t, y, self%flow, self%q, self%series, self%with_edges, status)
    do k = 1, size(self%inlets)
      if (.not. status%ok()) return
      if (fired(k) == 0 .or. self%inlets(k)%joined) cycle
      call join_inlet(self%model, y, self%flow, self%inlets(k), y_joined, flow_joined, status)
      if (.not. status%ok()) return
      y = y_joined
      self%flow = flow_joined
      self%inlets(k)%joined = .true.
      self%inlets(k)%time = t
    end do
    self%rhs_roots_known = .false.
    action = EVENT_RESTART
    call self%point(y, status)
    if (.not. status%ok()) then   ! e.g. subcritical: outside the model at once
      status%code = STATUS_DOMAIN
      call prefix_status(status, 'the inlet joined at arc length '// &
                         format_short(self%model%channel%arc_length(y(1)))//' m, the merged water')
      return
    end if
    g = stop_margins(self%model, self%q)
    if (all(g > 0)) return
    stops = 0
    where (.not. g > 0) stops(ROOT_STALL:ROOT_LIFT) = -1
    call model_stop(self, t, y, stops, stopped)
    action = EVENT_STOP
    self%message = 'after the inlet joined at arc length '// &
                   format_short(self%model%channel%arc_length(y(1)))//' m: '//self%message
  end subroutine join_inlets

  pure function lift_message(t, y) result(text)
    real(wp), intent(in) :: t, y(:)
    character(len=:), allocatable :: text
    text = 'the water lifts off the slide surface (normal force (4.12) down to 0: the surface would ' // &
           'have to pull it) at t = '//format_short(t)//' s, u = '//format_short(y(1))//', v = '// &
           format_short(y(2))//' rad; the streamline model holds only while the water is pressed on the slide'
  end function lift_message

  !> The station i reached at (t, y): the water there and its edges (4.25-4.26).
  subroutine station(self, i, t, y)
    class(water_system_t), intent(inout) :: self
    integer, intent(in) :: i
    real(wp), intent(in) :: t, y(:)
    type(status_t) :: st
    real(wp) :: l(2), r(2), pl(3), pr(3)
    call self%point(y, st)
    if (.not. st%ok()) return
    associate (s => self%series%stations(i))
      s%reached = .true.
      s%time = t
      s%v = y(2)
      s%speed = self%q%speed
      s%height = self%q%height
      s%width = self%q%width
      s%arc_length = self%model%channel%arc_length(y(1))
      call water_edges(self%model%channel, self%q, l, r, pl, pr, st)
      if (st%ok()) then
        s%v_left = l(2)
        s%v_right = r(2)
        s%v_middle = (l(2) + r(2))/2
      else
        s%v_middle = y(2)
      end if
    end associate
  end subroutine station

  !> A sample at (t, y). At the start, a state already beyond one of the
  !> model's stops (water not pressed on the surface, slower than min_speed,
  !> near critical, turning across) stops the run at once with that stop's
  !> outcome and message: the stops are roots falling through zero, which
  !> would never fire from there, and the run would go on outside the model.
  subroutine system_record(self, t, y, kind, status)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    integer, allocatable :: fired(:)
    integer :: action
    real(wp) :: g(ROOT_STALL:ROOT_LIFT), y_event(size(y))
    call self%point(y, status)
    if (.not. status%ok()) return
    call record_sample(self%model, t, y, self%flow, self%q, self%series, self%with_edges, status)
    if (.not. status%ok() .or. kind /= RECORD_START) return
    g = stop_margins(self%model, self%q)
    if (all(g > 0)) return
    allocate (fired(self%root_count()))
    fired = 0
    where (.not. g > 0) fired(ROOT_STALL:ROOT_LIFT) = -1
    y_event = y
    call self%handle_event(t, y_event, fired, action, status)
    if (status%ok()) call set_status(status, STATUS_DOMAIN, self%message)
  end subroutine system_record

  !> Progress lines of long runs: the fraction of the slide covered.
  subroutine system_progress(self, t, y, t_start, t_end, fraction, text)
    class(water_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:), t_start, t_end
    real(wp), intent(out) :: fraction
    character(len=:), allocatable, intent(out) :: text
    associate (unused => t_start, unused_end => t_end)
    end associate
    fraction = (y(1) - self%u_start)/max(self%u_end - self%u_start, tiny(1.0_wp))
    text = 't = '//format_short(t)//' s, u = '//format_short(y(1))
  end subroutine system_progress



end module water_flow
