!> A ride, in memory: the rider (rider_model) on the integration driver, its
!> records in engineering quantities, and how it ends (docs/rider.md, "The
!> ride"). Built from a description and run without module state, so the
!> design layer can run thousands of rides (one per thread) with the same
!> code the `ride` scenario uses.
!>
!> Stops (besides the mechanism's own, kinetostatics_mechanism_ode):
!>   end of the slide   a contact's surface joint reaches u_max (the heels,
!>                      first): the normal end, the ride is complete;
!>   lift-off           a contact's normal force falls to zero: the ride
!>                      stops, saying which contact and where; with
!>                      may_fly it opens that contact instead
!>                      (rider_flight): its body flies, the ride goes on
!>                      until it lands, and on; with all three open the
!>                      whole rider flies;
!>   stall / turn back  the pelvis's rate along the slide u' falls below
!>                      min_speed/|c_u| (one root function): the ride stops
!>                      with a message;
!>   back at the start  a contact reaches u_min (after turning back).
!> The water's drag switches itself on and off at the edges
!> (rider_water_drag) and restarts the integrator there.
!>
!> The report's extremes (rider_extremes) are located between the records on
!> the integrator's dense output (numerics_dense_extremes): the driver shows
!> the ride every internal step, and a copy of the mechanism (the probe, so
!> that the integration's own closure warm starts are not touched) evaluates
!> the rider at the interpolated states.
module rider_ride
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_log, only: log_sink_i
  use numerics_ode, only: ode_options_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, add_driver_result, DRIVE_END_TIME, &
    DRIVE_EVENT_STOP, EVENT_STOP, EVENT_RECORD, EVENT_RESTART, RECORD_EVENT, RECORD_START
  use geometry_surface, only: surface_t
  use geometry_slide_query, only: slide_surface_t, as_slide
  use geometry_curve, only: curve_point_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_END_OF_SURFACE, STOP_START_OF_SURFACE, STOP_SIDE_EDGE, &
    STOP_LIFT_OFF
  use kinetostatics_mechanism, only: mechanism_t
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t
  use numerics_dense_extremes, only: dense_extremes_t
  use rider_extremes, only: extreme_quantities, N_EXTREMES, N_ATTACHED, EXTREME_GAP
  use rider_probe, only: ride_probe_t, pelvis_state
  use rider_series, only: contact_series_t, ride_series_t, size_series, move_series, values_per_record
  use water_field, only: water_field_t
  use rider_model, only: rider_params_t, rider_layout_t, build_rider, rider_start_velocity, contact_names, &
    CONTACT_PELVIS, CONTACT_HEELS, N_CONTACTS, rider_coulomb_mu, rider_default_mu, flexion_range, tilt_range
  use rider_water_drag, only: water_drag_t
  use rider_flight, only: ride_flights_t, rider_landing_t, contact_gap, full_state, contact_impact, add_landing, &
    centre_of_mass
  use rider_flight_builds, only: flight_builds_t, make_flight_builds
  implicit none (type, external)
  private
  public :: ride_options_t, ride_series_t, contact_series_t, ride_result_t, rider_ode_t, simulate_ride, &
    check_ride_start, prepare_ride

  !> How a ride ended (ride_result_t%ending; its outcome says it in words).
  integer, parameter, public :: RIDE_FAILED = 0, RIDE_END_OF_SLIDE = 1, RIDE_LAST_STATION = 2, RIDE_LIFT_OFF = 3, &
    RIDE_EJECTED = 4, RIDE_STALLED = 5, RIDE_BACK_AT_START = 6, RIDE_TIME_OUT = 7, RIDE_HIP_RANGE = 8

  !> What a stop of the driver asks simulate_ride to do: nothing (the ride
  !> ends), a contact's take-off, its landing.
  integer, parameter :: SWITCH_NONE = 0, SWITCH_TAKE_OFF = 1, SWITCH_LANDING = 2
  ! opening_gap, sink_gap: kinetostatics_point_impact (the gap's root
  ! after a take-off)

  type :: ride_options_t
    !> thesis B.7 tolerances; the step is capped at 0.05 s: each closure starts
    !> from the previous solution, and a capped step keeps that start near
    !> (on a straight the integrator would otherwise step over metres)
    type(ode_options_t) :: ode = ode_options_t(rtol=1e-10_wp, atol=1e-9_wp, max_step=0.05_wp)
    real(wp) :: output_step = 0.01_wp     ! s
    real(wp) :: max_duration = 600        ! s, a bound on the ride (it normally ends at the slide's end)
    real(wp) :: min_speed = 0.05_wp       ! m/s, below it the rider has stalled
    real(wp) :: progress_seconds = -1     ! wall-clock s between progress lines (0: none; < 0: slidesim's)
    procedure(log_sink_i), pointer, nopass :: log => null()   ! where they go (none given: none made)
    !> m of centerline arc length, increasing: the ride records the state
    !> where the pelvis first crosses each (a root function each; what an
    !> identification compares with measurements at stations)
    real(wp), allocatable :: stations(:)
    logical :: stop_at_last_station = .false.   ! end the ride there (nothing is measured after it)
    !> a contact's lift-off starts its flight (rider_flight; docs/rider.md
    !> "Flight") instead of ending the ride
    logical :: may_fly = .false.
    !> a landing: restitution e = 0 (plastic: the rider lands on a water
    !> film) and Coulomb mu, the rider's mu_D
    type(impact_law_t) :: landing = impact_law_t(restitution=0, mu=rider_default_mu)
  end type ride_options_t


  type :: ride_result_t
    type(ride_series_t) :: series
    logical :: complete = .false.         ! reached the end of the slide
    character(len=:), allocatable :: outcome   ! how it ended, in words
    integer :: ending = RIDE_FAILED            ! ... as a code (RIDE_*)
    !> the contact (CONTACT_PELVIS ...) whose normal force fell to zero (RIDE_LIFT_OFF; else 0)
    integer :: lifted_contact = 0
    type(driver_result_t) :: driver
    integer :: drag_switches = 0
    integer, allocatable :: station_record(:)   ! the record at each station (0: not reached)
    !> the contact (CONTACT_PELVIS ...) whose point went over the top edge of
    !> an open section's wall, ending the ride (0: none; docs/rider.md)
    integer :: ejected_contact = 0
    type(ride_flights_t) :: flights   ! the flights and landings (may_fly)
  end type ride_result_t


  !> The rider as a model of the integration driver.
  type, extends(mechanism_ode_t) :: rider_ode_t
    type(rider_layout_t) :: layout
    type(ride_series_t) :: ride
    class(slide_surface_t), allocatable :: slide   ! the slide query (geometry_slide_query)
    real(wp) :: min_rate = 0              ! u per s: stall below
    real(wp) :: min_speed = 0             ! m/s, the stall speed it stands for
    real(wp) :: slide_length = 0          ! m, for progress lines
    integer :: drag_switches = 0
    integer, allocatable :: station_record(:)   ! as ride_result_t's
    integer :: pending_station = 0        ! a station crossed, its record comes next
    logical :: stop_at_last_station = .false.
    integer :: ejected_contact = 0        ! the contact that went over a wall's top (0: none)
    integer :: ending = RIDE_FAILED       ! how the ride stopped (RIDE_*), set with outcome at the stop
    integer :: lifted_contact = 0         ! the contact whose normal force fell to zero (0: none)
    type(dense_extremes_t) :: extremes    ! the report's extremes so far
    type(ride_probe_t) :: probe           ! evaluates them between the records
    ! the flights (may_fly): the builds by their open contacts and the one
    ! in use (rider_flight_builds), the switch the last stop asks for and
    ! its state
    logical :: may_fly = .false.
    type(impact_law_t) :: landing
    real(wp) :: gravity = 0               ! m/s^2, |g|
    type(flight_builds_t) :: fly
    logical :: opened(N_CONTACTS) = .false.   ! the gap has opened beyond opening_gap
    real(wp) :: take_off_time(N_CONTACTS) = 0 ! s, of each contact's last switch
    integer :: switch = SWITCH_NONE
    integer :: switch_contact = 0
    real(wp) :: switch_t = 0
    real(wp), allocatable :: switch_y(:)
    integer :: quick_landings = 0         ! landings right after their take-off, in a row
    logical :: gap_rising(N_CONTACTS) = .false.   ! an open contact's gap rose at the last record
    type(ride_flights_t) :: flights
  contains
    procedure :: record => rider_record
    procedure :: observe_step => rider_observe_step
    procedure :: handle_event => rider_handle_event
    procedure :: progress => rider_progress
    procedure :: root_count => rider_root_count
    procedure :: roots => rider_roots
  end type rider_ode_t

  interface
    ! rider_ride_flight
    integer module function rider_root_count(self) result(n)
      class(rider_ode_t), intent(in) :: self
    end function rider_root_count

    module subroutine rider_roots(self, t, y, g)
      class(rider_ode_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: g(:)
    end subroutine rider_roots

    module subroutine gap_event(self, t, y, fired, action, status)
      class(rider_ode_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      integer, intent(in) :: fired(:)
      integer, intent(inout) :: action
      type(status_t), intent(inout) :: status
    end subroutine gap_event

    module subroutine switch_build(self, y, status)
      class(rider_ode_t), intent(inout) :: self
      real(wp), allocatable, intent(inout) :: y(:)
      type(status_t), intent(inout) :: status
    end subroutine switch_build

    module subroutine keep_highest(sys)
      type(rider_ode_t), intent(inout) :: sys
    end subroutine keep_highest

    module subroutine watch_gap_apexes(self, kind)
      class(rider_ode_t), intent(inout) :: self
      integer, intent(in) :: kind
    end subroutine watch_gap_apexes

    module subroutine end_flights(self, t)
      class(rider_ode_t), intent(inout) :: self
      real(wp), intent(in) :: t
    end subroutine end_flights

  end interface


contains

  !> Runs the ride of `params` on `surface` (with drag in `water` if given and
  !> params%drag). Returns with status ok when the ride ended (result%complete
  !> says whether it reached the end); otherwise with the failure, the
  !> samples so far in result%series.
  subroutine simulate_ride(params, surface, options, result, status, water, label)
    type(rider_params_t), intent(in) :: params
    class(surface_t), intent(in) :: surface
    type(ride_options_t), intent(in) :: options
    type(ride_result_t), intent(out) :: result
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional, target :: water
    character(len=*), intent(in), optional :: label
    type(rider_ode_t), target :: sys
    type(driver_options_t) :: driver
    type(driver_result_t) :: stretch
    real(wp), allocatable :: y0(:), y(:)
    type(status_t) :: run_status
    integer :: n_state, n_context

    if (.not. status%ok()) return
    call prepare_ride(params, surface, options, sys, y0, status, water)
    if (.not. status%ok()) return
    sys%observes_steps = .true.
    if (.not. sys%may_fly) sys%probe%mechanism = sys%mechanism
    sys%probe%layout = sys%layout
    sys%probe%slide = sys%slide
    sys%probe%gravity = params%gravity
    n_state = size(y0)
    n_context = 1 + sys%mechanism%r
    if (sys%may_fly) then
      ! the probe and the records see every state in the full layout, the
      ! context ends with the posture held in flight and the open contacts
      sys%probe%may_fly = .true.
      sys%probe%builds => sys%fly%builds
      sys%probe%picks = sys%fly%picks
      allocate (sys%probe%works(0:ubound(sys%fly%builds, 1)))
      n_state = sys%fly%flight_size
      n_context = 1 + sys%fly%max_r + 3
    end if
    sys%probe%applied = spread(huge(1.0_wp), 1, n_context)
    call sys%extremes%start(n_state, N_EXTREMES, N_ATTACHED, n_context)
    ! room for two minutes of outputs at first; the series grows as the ride goes
    call size_series(sys%ride, nint(min(options%max_duration, 120.0_wp)/options%output_step) + 16, n_state)
    driver%ode = options%ode
    ! Adams' corrector stops at half the local error tolerance (CVODE's
    ! default: a tenth): most steps take one iteration instead of two, 10148
    ! -> 7701 right-hand sides for 5147 -> 5406 steps on the demo slide, and
    ! the ride against a reference at rtol 1e-13 is as close as before or
    ! closer (docs/rider.md, "Speed")
    driver%ode%convergence_coefficient = 0.5_wp
    driver%t_end = options%max_duration
    driver%output_step = options%output_step
    driver%min_mean_step = 1e-5_wp
    driver%progress_seconds = options%progress_seconds
    driver%log => options%log
    driver%label = 'ride'
    if (present(label)) driver%label = label
    ! a stretch of the ride per build: a stop that asks for a switch (the
    ! heels' take-off or landing) goes on from there with the other build
    y = y0
    do
      call drive(sys, y, driver, stretch, run_status)
      call add_driver_result(result%driver, stretch)
      if (.not. run_status%ok() .or. stretch%outcome /= DRIVE_EVENT_STOP .or. sys%switch == SWITCH_NONE) exit
      call switch_build(sys, y, run_status)
      if (.not. run_status%ok()) exit
      driver%t_start = sys%switch_t
      driver%output_origin = 0
    end do
    if (run_status%ok()) call sys%extremes%finish(sys%probe, run_status)
    ! a flight under way at the end counts up to there
    if (sys%may_fly) call end_flights(sys, result%driver%t)
    call keep_extremes(sys)
    if (sys%may_fly) call keep_highest(sys)
    result%flights = sys%flights
    result%drag_switches = sys%drag_switches
    result%ejected_contact = sys%ejected_contact
    result%lifted_contact = sys%lifted_contact
    call move_alloc(sys%station_record, result%station_record)
    call move_series(sys%ride, result%series)
    select case (result%driver%outcome)
    case (DRIVE_EVENT_STOP)
      result%outcome = sys%outcome
      result%ending = sys%ending
      result%complete = sys%ending == RIDE_END_OF_SLIDE .or. sys%ending == RIDE_LAST_STATION
    case (DRIVE_END_TIME)
      result%outcome = 'the ride had not ended after '//format_short(options%max_duration)//' s'
      result%ending = RIDE_TIME_OUT
    case default
      result%outcome = 'failed: '//run_status%text()
    end select
    if (.not. run_status%ok()) status = run_status
  end subroutine simulate_ride

  !> Builds the rider and checks its start without running (the loops close,
  !> the contacts press, the start speed carries it down the slide): what a
  !> scenario checks before any work.
  subroutine check_ride_start(params, surface, options, status)
    type(rider_params_t), intent(in) :: params
    class(surface_t), intent(in) :: surface
    type(ride_options_t), intent(in) :: options
    type(status_t), intent(inout) :: status
    type(rider_ode_t), target :: sys
    real(wp), allocatable :: y0(:)
    call prepare_ride(params, surface, options, sys, y0, status)
  end subroutine check_ride_start

  !> The rider's model of the driver at its start state y0 (its drag laws
  !> point at `water`, which outlives sys).
  subroutine prepare_ride(params, surface, options, sys, y0, status, water)
    type(rider_params_t), intent(in) :: params
    class(surface_t), intent(in) :: surface
    type(ride_options_t), intent(in) :: options
    type(rider_ode_t), intent(inout) :: sys
    real(wp), allocatable, intent(out) :: y0(:)
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional, target :: water
    real(wp) :: q0(3), qd0(3), speed
    real(wp), allocatable :: station_u(:)
    integer :: i
    call as_slide(surface, sys%slide, status)
    if (.not. status%ok()) return
    call build_rider(params, surface, sys%mechanism, sys%layout, q0, status, water, free_pelvis=options%may_fly)
    if (status%ok()) call rider_start_velocity(params, surface, qd0, status)
    if (status%ok()) call sys%slide%centerline_speed(q0(1), speed, status)
    if (.not. status%ok()) return
    if (.not. speed > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'the slide''s centerline has no direction at the start (|c_u| = '// &
                      format_short(speed)//')')
      return
    end if
    sys%slide_length = sys%slide%length()
    if (options%may_fly) then
      ! a build per set of open contacts, from the same start (rider_flight_builds)
      sys%may_fly = .true.
      sys%flights%watched = .true.
      sys%landing = options%landing
      sys%gravity = norm2(params%gravity)
      call make_flight_builds(params, surface, sys%mechanism, sys%layout, sys%fly, status, water)
      if (.not. status%ok()) return
    end if
    sys%min_speed = options%min_speed
    sys%min_rate = options%min_speed/speed
    if (params%speed0 == 0) then
      ! the trap-door start (a drop): from rest, the stall is a falling crossing
      ! of min_rate only after the rider has risen above it
      call start_from_rest(status)
      if (.not. status%ok()) return
    else if (.not. qd0(1) > sys%min_rate) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start speed '//format_short(params%speed0)// &
                      ' m/s does not carry the rider down the slide (its rate along the slide must exceed '// &
                      format_short(options%min_speed)//' m/s)')
      return
    end if
    call stations_as_parameters(sys%slide, options, q0(1), station_u, status)
    if (.not. status%ok()) return
    ! stall or turning back: u' of the pelvis falls below min_rate; then the
    ! pelvis's u crossing each station
    sys%event_index = [4, (1, i=1, size(station_u))]
    sys%event_value = [sys%min_rate, station_u]
    sys%station_record = spread(0, 1, size(station_u))
    sys%stop_at_last_station = options%stop_at_last_station .and. size(station_u) > 0
    y0 = sys%initial_state(q0, qd0)
    call sys%check_start(y0, status)
    if (.not. status%ok()) call prefix_status(status, 'ride start')

  contains

    !> A rider at rest slides off only where the centerline is steeper than
    !> its friction holds (tan(slope) > mu at the pelvis's start; a law
    !> other than Coulomb holds nothing at rest: mu 0).
    subroutine start_from_rest(status)
      type(status_t), intent(inout) :: status
      type(curve_point_t) :: c
      real(wp) :: gradient, mu
      logical :: coulomb
      call sys%slide%centerline_point(q0(1), 1, c, status)
      if (.not. status%ok()) return
      gradient = -c%d(3, 1)/max(norm2(c%d(1:2, 1)), tiny(1.0_wp))
      call rider_coulomb_mu(params, mu, coulomb)
      if (.not. gradient > mu) call set_status(status, STATUS_INVALID_INPUT, 'a rider starting at rest '// &
        '(speed0 = 0) needs a start steeper than its friction holds: tan(slope) = '//format_short(gradient)// &
        ' at the start is not above mu = '//format_short(mu))
    end subroutine start_from_rest
  end subroutine prepare_ride

  !> The stations' surface parameters u, each after the start u0 and on the
  !> slide, increasing.
  subroutine stations_as_parameters(slide, options, u0, u, status)
    class(slide_surface_t), intent(in) :: slide
    type(ride_options_t), intent(in) :: options
    real(wp), intent(in) :: u0
    real(wp), allocatable, intent(out) :: u(:)
    type(status_t), intent(inout) :: status
    integer :: i
    allocate (u(0))
    if (.not. allocated(options%stations)) return
    u = options%stations
    do i = 1, size(u)
      call slide%parameter_at_length(options%stations(i), u(i), status)
      if (.not. status%ok()) then
        call prefix_status(status, 'ride station '//format_short(options%stations(i))//' m')
        return
      end if
      if (.not. u(i) > u0 .or. (i > 1 .and. .not. options%stations(i) > options%stations(max(i - 1, 1)))) then
        call set_status(status, STATUS_INVALID_INPUT, 'ride station '//format_short(options%stations(i))// &
                        ' m: the stations must lie after the start and increase along the slide')
        return
      end if
    end do
  end subroutine stations_as_parameters

  !> Progress lines: how far down the slide the pelvis is.
  subroutine rider_progress(self, t, y, t_start, t_end, fraction, text)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:), t_start, t_end
    real(wp), intent(out) :: fraction
    character(len=:), allocatable, intent(out) :: text
    real(wp) :: s
    associate (unused => t_start, unused_end => t_end)
    end associate
    s = self%slide%arc_length(y(1))
    fraction = -1
    if (self%slide_length > 0) fraction = s/self%slide_length
    text = 't = '//format_short(t)//' s, '//format_short(s)//' m down the slide'
  end subroutine rider_progress


  !> The complete state of the ride at (t, y).
  subroutine rider_record(self, t, y, kind, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    real(wp) :: residual, kinetic, potential
    real(wp) :: values(N_EXTREMES), attached(N_ATTACHED, N_EXTREMES)
    integer :: f, n, k, i, grown
    f = self%mechanism%f
    call self%mechanism%evaluate(self%work, t, y(1:f), y(f + 1:2*f), residual, status)
    if (.not. status%ok()) return
    call self%ride%make_room(16, 8.0_wp*(values_per_record + size(self%ride%state, 1)), 'ride', t, grown, status)
    if (.not. status%ok()) return
    if (grown > 0) call size_series(self%ride, grown, size(self%ride%state, 1))
    self%ride%n = self%ride%n + 1
    n = self%ride%n
    if (kind == RECORD_EVENT .and. self%pending_station > 0) then
      self%station_record(self%pending_station) = n
      self%pending_station = 0
    end if
    associate (m => self%mechanism, w => self%work, lay => self%layout, r => self%ride)
      r%time(n) = t
      r%kind(n) = kind
      if (self%may_fly) then
        call full_state(m, w, lay, y, r%state(:, n))
      else
        r%state(:, n) = y
      end if
      call pelvis_state(w, lay, r%speed(n), r%pelvis_acceleration(:, n), r%pelvis_axes(:, :, n), &
                        r%reaction_force(:, n), r%reaction_moment(:, n))
      r%heading(n) = w%scalars(lay%heading)%q
      r%phi_legs(n) = w%scalars(lay%flexion)%q
      r%phi_trunk(n) = w%scalars(lay%tilt)%q
      call m%energy(w, kinetic, potential)
      r%kinetic(n) = kinetic
      r%potential(n) = potential
      r%energy(n) = kinetic + potential
      r%friction_work(n) = 0
      r%drag_work(n) = 0
      do k = 1, N_CONTACTS
        if (lay%friction(k) > 0) r%friction_work(n) = r%friction_work(n) + y(2*f + lay%friction(k))
        if (lay%drag(k) > 0) r%drag_work(n) = r%drag_work(n) + y(2*f + lay%drag(k))
      end do
      r%closure_residual(n) = m%closure_residual(w)
      r%airborne(n) = self%fly%open_mask
      do k = 1, N_CONTACTS
        associate (c => r%contact(k), d => w%frames(lay%contact_frame(k)))
          c%u(n) = w%scalars(lay%u(k))%q
          c%v(n) = w%scalars(lay%v(k))%q
          c%arc_length(n) = self%slide%arc_length(c%u(n))
          call self%slide%wall_position(c%u(n), c%v(n), c%wall_angle(n), c%wall_distance(n), status)
          if (.not. status%ok()) return
          c%position(:, n) = d%r
          c%velocity(:, n) = d%v
          c%normal_force(n) = w%normal_force(lay%contact(k))
          c%friction_force(:, n) = 0
          if (lay%friction(k) > 0) c%friction_force(:, n) = m%law_force(w, lay%friction(k))
          c%drag_force(:, n) = 0
          c%in_water(n) = 0
          c%reynolds(n) = 0
          c%drag_coefficient(n) = 0
          c%projected_area(n) = 0
          c%relative_velocity(:, n) = 0
          i = lay%drag(k)
          if (i > 0) then
            select type (law => w%laws(i)%law)
            type is (water_drag_t)
              if (law%active) then
                c%in_water(n) = 1
                c%drag_force(:, n) = m%law_force(w, i)
                c%reynolds(n) = law%state%reynolds
                c%drag_coefficient(n) = law%state%drag_coefficient
                c%projected_area(n) = law%state%projected_area
                c%relative_velocity(:, n) = law%state%relative_velocity
              end if
            end select
          end if
        end associate
      end do
      r%arc_length(n) = r%contact(CONTACT_PELVIS)%arc_length(n)
      if (self%observes_steps) then
        call extreme_quantities(r%speed(n), r%pelvis_acceleration(:, n), r%pelvis_axes(:, :, n), &
          r%reaction_force(:, n), r%reaction_moment(:, n), r%arc_length(n), &
          [(r%contact(k)%wall_angle(n), k = 1, N_CONTACTS)], [(r%contact(k)%wall_distance(n), k = 1, N_CONTACTS)], &
          [(r%contact(k)%normal_force(n), k = 1, N_CONTACTS)], self%probe%gravity, self%fly%open_mask, &
          [(merge(contact_gap(w, lay, k), 0.0_wp, btest(self%fly%open_mask, k - 1)), k = 1, N_CONTACTS)], &
          [(r%contact(k)%arc_length(n), k = 1, N_CONTACTS)], values, attached)
        if (self%may_fly) then
          ! the context in the full layout: the betas of the build, the
          ! posture held, the open contacts last; a stretch's start
          ! after a switch splits the brackets as an event does
          call self%extremes%add_record(t, kind == RECORD_EVENT .or. (kind == RECORD_START .and. n > 1), &
            [real(sum([(merge(2**(k - 1), 0, r%contact(k)%in_water(n) == 1), k = 1, N_CONTACTS)]), wp), &
             (w%scalars(m%beta(k))%q, k = 1, m%r), spread(0.0_wp, 1, self%fly%max_r - m%r), self%fly%hold, &
             real(self%fly%open_mask, wp)], &
            values, attached)
          call watch_gap_apexes(self, kind)
        else
          call self%extremes%add_record(t, kind == RECORD_EVENT, &
            [real(sum([(merge(2**(k - 1), 0, r%contact(k)%in_water(n) == 1), k = 1, N_CONTACTS)]), wp), &
             (w%scalars(m%beta(k))%q, k = 1, m%r)], values, attached)
        end if
      end if
    end associate
  end subroutine rider_record


  !> An internal step's dense output, for the extremes.
  subroutine rider_observe_step(self, t_n, h, taylor, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t_n, h, taylor(:, 0:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    if (.not. self%may_fly) then
      call self%extremes%add_piece(t_n, h, taylor)
    else
      ! the build's piece in the full layout
      call self%fly%full_piece(self%mechanism%f, taylor)
      call self%extremes%add_piece(t_n, h, self%fly%padded(:, 0:ubound(taylor, 2)))
    end if
  end subroutine rider_observe_step

  !> The located extremes into the ride's series.
  subroutine keep_extremes(sys)
    type(rider_ode_t), intent(inout) :: sys
    associate (e => sys%extremes, x => sys%ride%extremes)
      x%located = e%records > 0
      x%records = e%records
      x%value = e%best_attached(1, :)
      x%at = e%best_attached(2, :)
      x%wall_distance = e%best_attached(3, :)
      x%time = e%best_t
      x%searches = e%searches
      x%evaluations = e%evaluations
    end associate
  end subroutine keep_extremes

  !> The mechanism's events (ends, lift-off, drag on/off), then the rider's:
  !> the stall crossing (the one user crossing) stops the ride.
  subroutine rider_handle_event(self, t, y, fired, action, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    logical :: was_active(self%mechanism%n_laws)
    integer :: k
    character(len=:), allocatable :: where
    do k = 1, self%mechanism%n_laws
      was_active(k) = self%work%laws(k)%law%active
    end do
    call self%mechanism_ode_t%handle_event(t, y, fired, action, status)
    if (.not. status%ok()) return
    do k = 1, self%mechanism%n_laws
      if (was_active(k) .neqv. self%work%laws(k)%law%active) self%drag_switches = self%drag_switches + 1
    end do
    where = ' at arc length '//format_short(self%slide%arc_length(y(1)))//' m (t = '//format_short(t)//' s)'
    self%switch = SWITCH_NONE
    if (self%may_fly .and. self%fly%open_mask /= 0) then
      if (any(fired(self%n_roots + 1:self%n_roots + N_CONTACTS) /= 0)) &
        call gap_event(self, t, y, fired(self%n_roots + 1:self%n_roots + N_CONTACTS), action, status)
      if (.not. status%ok()) return
      if (any(fired(self%n_roots + N_CONTACTS + 1:self%n_roots + N_CONTACTS + 2) /= 0)) then
        ! a limb swung out of the hip's range in flight (the free hip has no
        ! stiffness): the model's end, not the rider's
        action = EVENT_STOP
        self%switch = SWITCH_NONE
        self%ending = RIDE_HIP_RANGE
        self%outcome = 'hip range: in flight the '//trim(merge('legs ', 'trunk', &
          fired(self%n_roots + N_CONTACTS + 1) /= 0))//' swung out of the hip''s range (flexion '// &
          format_short(flexion_range(1)*180/pi)//' to '//format_short(flexion_range(2)*180/pi)//' deg, tilt '// &
          format_short(tilt_range(1)*180/pi)//' to '//format_short(tilt_range(2)*180/pi)//' deg: the free hip '// &
          'has no stiffness, the model ends here)'//where
        return
      end if
    end if
    if (fired(1) < 0) then
      action = EVENT_STOP
      self%switch = SWITCH_NONE   ! the stall ends the ride, whatever else happened here
      self%ending = RIDE_STALLED
      self%outcome = 'the rider stalled or turned back: the speed along the slide fell below min_speed = '// &
                     format_short(self%min_speed)//' m/s'//where
      return
    end if
    do k = 1, size(self%station_record)
      if (fired(1 + k) <= 0 .or. self%station_record(k) /= 0) cycle
      self%pending_station = k
      action = max(action, EVENT_RECORD)
      if (self%stop_at_last_station .and. k == size(self%station_record) .and. action /= EVENT_STOP) then
        action = EVENT_STOP
        self%switch = SWITCH_NONE
        self%ending = RIDE_LAST_STATION
        self%outcome = 'last station: the pelvis reached it'//where
      end if
    end do
    if (action == EVENT_STOP .and. self%ending /= RIDE_LAST_STATION .and. self%switch /= SWITCH_LANDING) then
      ! the mechanism's stop, by its code (the first event; outcome has them all)
      select case (self%stop_kind)
      case (STOP_END_OF_SURFACE)
        self%ending = RIDE_END_OF_SLIDE
        self%outcome = 'end of the slide: the '//contact_name(findloc(self%layout%joint, self%stop_element, dim=1))// &
                       ' reached it'//where
      case (STOP_SIDE_EDGE)
        self%ending = RIDE_EJECTED
        self%ejected_contact = findloc(self%layout%joint, self%stop_element, dim=1)
        self%outcome = 'ejected: the '//contact_name(self%ejected_contact)//' went over the top of the '// &
                       wall_side(self)//' wall of the open section'//where
      case (STOP_LIFT_OFF)
        self%ending = RIDE_LIFT_OFF
        self%lifted_contact = findloc(self%layout%contact, self%stop_contact, dim=1)
        self%outcome = 'lift-off: the normal force of the '//contact_name(self%lifted_contact)//' fell to zero'//where
        if (self%may_fly .and. self%lifted_contact > 0) then
          self%switch = SWITCH_TAKE_OFF
          self%switch_contact = self%lifted_contact
          self%switch_t = t
          self%switch_y = y
        end if
      case (STOP_START_OF_SURFACE)
        self%ending = RIDE_BACK_AT_START
      end select
    end if
  end subroutine rider_handle_event

  !> The name of contact k ('rider' for 0: none of the three).
  pure function contact_name(k) result(name)
    integer, intent(in) :: k
    character(len=:), allocatable :: name
    name = 'rider'
    if (k > 0) name = trim(contact_names(k))
  end function contact_name

  !> Which wall the ejected contact went over: left (its v at the section's
  !> upper edge, +v) or right, from its surface parameters at the event.
  function wall_side(self) result(side)
    class(rider_ode_t), intent(in) :: self
    character(len=:), allocatable :: side
    real(wp) :: u, v, v_min, v_max
    side = 'side'
    if (self%ejected_contact == 0) return
    associate (w => self%work, lay => self%layout)
      u = w%scalars(lay%u(self%ejected_contact))%q
      v = w%scalars(lay%v(self%ejected_contact))%q
    end associate
    call self%slide%section_edges(u, v_min, v_max)
    if (abs(v - v_max) < abs(v - v_min)) then
      side = 'left'
    else
      side = 'right'
    end if
  end function wall_side
end module rider_ride
