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
!>                      stops, saying which contact and where;
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
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_series, only: growable_series_t, resize
  use base_log, only: log_sink_i
  use numerics_ode, only: ode_options_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, DRIVE_EVENT_STOP, &
    EVENT_STOP, EVENT_RECORD, RECORD_EVENT
  use geometry_surface, only: surface_t
  use geometry_slide_query, only: slide_surface_t, as_slide
  use geometry_curve, only: curve_point_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_END_OF_SURFACE, STOP_START_OF_SURFACE, STOP_SIDE_EDGE, &
    STOP_LIFT_OFF
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use numerics_dense_extremes, only: dense_extremes_t, dense_quantities_t
  use rider_extremes, only: ride_extremes_t, extreme_quantities, N_EXTREMES, N_ATTACHED
  use water_field, only: water_field_t
  use rider_model, only: rider_params_t, rider_layout_t, build_rider, rider_start_velocity, contact_names, &
    CONTACT_PELVIS, N_CONTACTS, rider_coulomb_mu
  use rider_water_drag, only: water_drag_t
  implicit none (type, external)
  private
  public :: ride_options_t, ride_series_t, contact_series_t, ride_result_t, rider_ode_t, simulate_ride, &
    check_ride_start, prepare_ride

  !> How a ride ended (ride_result_t%ending; its outcome says it in words).
  integer, parameter, public :: RIDE_FAILED = 0, RIDE_END_OF_SLIDE = 1, RIDE_LAST_STATION = 2, RIDE_LIFT_OFF = 3, &
    RIDE_EJECTED = 4, RIDE_STALLED = 5, RIDE_BACK_AT_START = 6, RIDE_TIME_OUT = 7

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
  end type ride_options_t

  !> One contact over the ride (n samples).
  type :: contact_series_t
    real(wp), allocatable :: u(:), v(:)                 ! surface parameters
    real(wp), allocatable :: arc_length(:)              ! m, centerline arc length at u
    real(wp), allocatable :: wall_angle(:)              ! rad, normal's angle from the bottom's (+ towards +v)
    real(wp), allocatable :: wall_distance(:)           ! m, along the section from v = pi/2 (+ towards +v)
    real(wp), allocatable :: position(:, :), velocity(:, :)   ! 3 x n: m, m/s
    real(wp), allocatable :: normal_force(:)            ! N
    real(wp), allocatable :: friction_force(:, :)       ! 3 x n, N
    real(wp), allocatable :: drag_force(:, :)           ! 3 x n, N
    integer, allocatable :: in_water(:)                 ! 1: between the water's edges
    real(wp), allocatable :: reynolds(:), drag_coefficient(:), projected_area(:)   ! 1, 1, m^2 (0 when dry)
    real(wp), allocatable :: relative_velocity(:, :)    ! 3 x n, m/s: contact minus water (0 when dry)
  end type contact_series_t

  !> Numbers of one record of ride_series_t besides the state (the arrays
  !> below: 31 of the pelvis and the rider, 25 per contact), for the memory bound.
  integer, parameter :: values_per_record = 31 + 25*N_CONTACTS

  !> The ride's records; grown as the ride goes (base_series).
  type, extends(growable_series_t) :: ride_series_t
    real(wp), allocatable :: time(:)                    ! s
    integer, allocatable :: kind(:)                     ! RECORD_START, _OUTPUT, _EVENT
    real(wp), allocatable :: state(:, :)                ! the integrator's state y = [q, q', W] (a ride can
                                                        ! be restarted from any record)
    real(wp), allocatable :: arc_length(:)              ! m, of the pelvis
    real(wp), allocatable :: speed(:)                   ! m/s, of the pelvis contact
    real(wp), allocatable :: heading(:), phi_legs(:), phi_trunk(:)   ! rad
    real(wp), allocatable :: pelvis_acceleration(:, :)  ! 3 x n, m/s^2: of the pelvis's centre of mass
    real(wp), allocatable :: pelvis_axes(:, :, :)       ! 3 x 3 x n: x (to the feet), y (left), z (normal)
    real(wp), allocatable :: reaction_force(:, :)       ! 3 x n, N: the slide's reaction on the rider at the pelvis
    real(wp), allocatable :: reaction_moment(:, :)      ! 3 x n, N m: ... its moment about the pelvis contact
    real(wp), allocatable :: kinetic(:), potential(:), energy(:)    ! J
    real(wp), allocatable :: friction_work(:), drag_work(:)          ! J (negative: taken out)
    real(wp), allocatable :: closure_residual(:)        ! m
    type(contact_series_t) :: contact(N_CONTACTS)
    type(ride_extremes_t) :: extremes                   ! the report's extremes, located between the records
  end type ride_series_t

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
  end type ride_result_t

  !> The rider's report quantities at any state between the records: a copy
  !> of the rider's mechanism (its closure warm starts are its own) with the
  !> water drag switched as at the record that starts the stretch and its
  !> closure started from that record's dependent coordinates (context: bit
  !> k-1 of context(1) set when contact k is in the water, then beta).
  type, extends(dense_quantities_t) :: ride_probe_t
    type(mechanism_t) :: mechanism
    type(mechanism_workspace_t) :: work
    type(rider_layout_t) :: layout
    class(slide_surface_t), allocatable :: slide
    real(wp) :: gravity(3) = 0            ! m/s^2
    real(wp), allocatable :: applied(:)   ! the context it was last switched to
  contains
    procedure :: evaluate => probe_evaluate
  end type ride_probe_t

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
  contains
    procedure :: record => rider_record
    procedure :: observe_step => rider_observe_step
    procedure :: handle_event => rider_handle_event
    procedure :: progress => rider_progress
  end type rider_ode_t

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
    type(water_field_t), intent(in), optional :: water
    character(len=*), intent(in), optional :: label
    type(rider_ode_t), target :: sys
    type(driver_options_t) :: driver
    real(wp), allocatable :: y0(:)
    type(status_t) :: run_status

    if (.not. status%ok()) return
    call prepare_ride(params, surface, options, sys, y0, status, water)
    if (.not. status%ok()) return
    sys%observes_steps = .true.
    sys%probe%mechanism = sys%mechanism
    sys%probe%layout = sys%layout
    sys%probe%slide = sys%slide
    sys%probe%gravity = params%gravity
    sys%probe%applied = spread(huge(1.0_wp), 1, 1 + sys%mechanism%r)
    call sys%extremes%start(size(y0), N_EXTREMES, N_ATTACHED, 1 + sys%mechanism%r)
    ! room for two minutes of outputs at first; the series grows as the ride goes
    call size_series(sys%ride, nint(min(options%max_duration, 120.0_wp)/options%output_step) + 16, size(y0))
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
    call drive(sys, y0, driver, result%driver, run_status)
    if (run_status%ok()) call sys%extremes%finish(sys%probe, run_status)
    call keep_extremes(sys)
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

  !> The rider's model of the driver at its start state y0.
  subroutine prepare_ride(params, surface, options, sys, y0, status, water)
    type(rider_params_t), intent(in) :: params
    class(surface_t), intent(in) :: surface
    type(ride_options_t), intent(in) :: options
    type(rider_ode_t), intent(inout) :: sys
    real(wp), allocatable, intent(out) :: y0(:)
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional :: water
    real(wp) :: q0(3), qd0(3), speed
    real(wp), allocatable :: station_u(:)
    integer :: i
    call as_slide(surface, sys%slide, status)
    if (.not. status%ok()) return
    call build_rider(params, surface, sys%mechanism, sys%layout, q0, status, water)
    if (status%ok()) call rider_start_velocity(params, surface, qd0, status)
    if (status%ok()) call sys%slide%centerline_speed(q0(1), speed, status)
    if (.not. status%ok()) return
    if (.not. speed > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'the slide''s centerline has no direction at the start (|c_u| = '// &
                      format_short(speed)//')')
      return
    end if
    sys%slide_length = sys%slide%length()
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

  !> Room for `capacity` records in every array of the series, the recorded
  !> ones kept (first call: allocates). Every array of ride_series_t is listed
  !> here once, so growing keeps them all.
  subroutine size_series(s, capacity, state_size)
    type(ride_series_t), intent(inout) :: s
    integer, intent(in) :: capacity, state_size
    integer :: k, n
    n = capacity
    call resize(s%time, n); call resize(s%kind, n); call resize(s%state, state_size, n)
    call resize(s%arc_length, n); call resize(s%speed, n); call resize(s%heading, n)
    call resize(s%phi_legs, n); call resize(s%phi_trunk, n); call resize(s%pelvis_acceleration, 3, n)
    call resize(s%pelvis_axes, 3, 3, n); call resize(s%reaction_force, 3, n); call resize(s%reaction_moment, 3, n)
    call resize(s%kinetic, n); call resize(s%potential, n); call resize(s%energy, n)
    call resize(s%friction_work, n); call resize(s%drag_work, n); call resize(s%closure_residual, n)
    do k = 1, N_CONTACTS
      associate (c => s%contact(k))
        call resize(c%u, n); call resize(c%v, n); call resize(c%arc_length, n); call resize(c%wall_angle, n)
        call resize(c%wall_distance, n); call resize(c%position, 3, n); call resize(c%velocity, 3, n)
        call resize(c%normal_force, n); call resize(c%friction_force, 3, n); call resize(c%drag_force, 3, n)
        call resize(c%in_water, n); call resize(c%reynolds, n); call resize(c%drag_coefficient, n)
        call resize(c%projected_area, n); call resize(c%relative_velocity, 3, n)
      end associate
    end do
    s%capacity = capacity
  end subroutine size_series

  !> Moves every array of a into b (a is left empty).
  subroutine move_series(a, b)
    type(ride_series_t), intent(inout) :: a, b
    integer :: k
    b%n = a%n
    b%capacity = a%capacity
    if (allocated(a%time)) call move_alloc(a%time, b%time)
    call move_alloc(a%kind, b%kind); call move_alloc(a%state, b%state); call move_alloc(a%arc_length, b%arc_length)
    call move_alloc(a%speed, b%speed); call move_alloc(a%heading, b%heading)
    call move_alloc(a%phi_legs, b%phi_legs); call move_alloc(a%phi_trunk, b%phi_trunk)
    call move_alloc(a%pelvis_acceleration, b%pelvis_acceleration); call move_alloc(a%pelvis_axes, b%pelvis_axes)
    call move_alloc(a%reaction_force, b%reaction_force); call move_alloc(a%reaction_moment, b%reaction_moment)
    call move_alloc(a%kinetic, b%kinetic); call move_alloc(a%potential, b%potential)
    call move_alloc(a%energy, b%energy); call move_alloc(a%friction_work, b%friction_work)
    call move_alloc(a%drag_work, b%drag_work); call move_alloc(a%closure_residual, b%closure_residual)
    do k = 1, N_CONTACTS
      b%contact(k) = a%contact(k)
    end do
    b%extremes = a%extremes
  end subroutine move_series

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
    call self%ride%make_room(16, 8.0_wp*(values_per_record + size(y)), 'ride', t, grown, status)
    if (.not. status%ok()) return
    if (grown > 0) call size_series(self%ride, grown, size(y))
    self%ride%n = self%ride%n + 1
    n = self%ride%n
    if (kind == RECORD_EVENT .and. self%pending_station > 0) then
      self%station_record(self%pending_station) = n
      self%pending_station = 0
    end if
    associate (m => self%mechanism, lay => self%layout, r => self%ride)
      r%time(n) = t
      r%kind(n) = kind
      r%state(:, n) = y
      call pelvis_state(m, lay, r%speed(n), r%pelvis_acceleration(:, n), r%pelvis_axes(:, :, n), &
                        r%reaction_force(:, n), r%reaction_moment(:, n))
      r%heading(n) = m%scalars(lay%heading)%q
      r%phi_legs(n) = m%scalars(lay%flexion)%q
      r%phi_trunk(n) = m%scalars(lay%tilt)%q
      call m%energy(kinetic, potential)
      r%kinetic(n) = kinetic
      r%potential(n) = potential
      r%energy(n) = kinetic + potential
      r%friction_work(n) = 0
      r%drag_work(n) = 0
      do k = 1, N_CONTACTS
        if (lay%friction(k) > 0) r%friction_work(n) = r%friction_work(n) + y(2*f + lay%friction(k))
        if (lay%drag(k) > 0) r%drag_work(n) = r%drag_work(n) + y(2*f + lay%drag(k))
      end do
      r%closure_residual(n) = m%closure_residual()
      do k = 1, N_CONTACTS
        associate (c => r%contact(k), d => m%frames(lay%contact_frame(k)))
          c%u(n) = m%scalars(lay%u(k))%q
          c%v(n) = m%scalars(lay%v(k))%q
          c%arc_length(n) = self%slide%arc_length(c%u(n))
          call self%slide%wall_position(c%u(n), c%v(n), c%wall_angle(n), c%wall_distance(n), status)
          if (.not. status%ok()) return
          c%position(:, n) = d%r
          c%velocity(:, n) = d%v
          c%normal_force(n) = m%contacts(lay%contact(k))%normal_force
          c%friction_force(:, n) = 0
          if (lay%friction(k) > 0) c%friction_force(:, n) = m%law_force(lay%friction(k))
          c%drag_force(:, n) = 0
          c%in_water(n) = 0
          c%reynolds(n) = 0
          c%drag_coefficient(n) = 0
          c%projected_area(n) = 0
          c%relative_velocity(:, n) = 0
          i = lay%drag(k)
          if (i > 0) then
            select type (law => m%laws(i)%law)
            type is (water_drag_t)
              if (law%active) then
                c%in_water(n) = 1
                c%drag_force(:, n) = m%law_force(i)
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
          [(r%contact(k)%normal_force(n), k = 1, N_CONTACTS)], self%probe%gravity, values, attached)
        call self%extremes%add_record(t, kind == RECORD_EVENT, &
          [real(sum([(merge(2**(k - 1), 0, r%contact(k)%in_water(n) == 1), k = 1, N_CONTACTS)]), wp), &
           (m%scalars(m%beta(k))%q, k = 1, m%r)], values, attached)
      end if
    end associate
  end subroutine rider_record

  !> Pelvis's speed, centre-of-mass acceleration, axes and the slide's
  !> reaction on the rider there, from an evaluated mechanism.
  subroutine pelvis_state(m, lay, speed, acceleration, axes, force, moment)
    type(mechanism_t), intent(in) :: m
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(out) :: speed, acceleration(3), axes(3, 3), force(3), moment(3)
    real(wp) :: s(3)
    associate (d => m%frames(lay%contact_frame(CONTACT_PELVIS)), p => m%frames(lay%body_frame(CONTACT_PELVIS)))
      speed = norm2(d%v)
      s = matmul(p%rot, lay%body%pelvis%com)
      acceleration = p%a + cross(p%alpha, s) + cross(p%omega, cross(p%omega, s))
      axes = p%rot
      ! the slide's reaction on the rider at the pelvis contact is minus the
      ! load the mechanism puts on the Darboux frame there (docs/rider.md)
      force = -d%force
      moment = -d%torque
    end associate
  end subroutine pelvis_state

  !> The report quantities at (t, y) with the water drag of `context`.
  subroutine probe_evaluate(self, t, y, context, values, attached, status)
    class(ride_probe_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(in) :: context(:)
    real(wp), intent(out) :: values(:), attached(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: residual, speed, acceleration(3), axes(3, 3), force(3), moment(3)
    real(wp) :: angle(N_CONTACTS), distance(N_CONTACTS), normal(N_CONTACTS)
    integer :: f, k
    associate (m => self%mechanism, lay => self%layout)
      if (any(context /= self%applied)) then
        ! another stretch: its drag, and the closure from its record (a cold
        ! start: no predictor from the last solution, which may lie far off)
        do k = 1, N_CONTACTS
          if (lay%drag(k) > 0) m%laws(lay%drag(k))%law%active = btest(nint(context(1)), k - 1)
        end do
        do k = 1, m%r
          m%scalars(m%beta(k))%q = context(1 + k)
        end do
        m%warm = .false.
        m%converged = .false.
        self%applied = context
      end if
      f = m%f
      call m%evaluate(self%work, t, y(1:f), y(f + 1:2*f), residual, status)
      if (.not. status%ok()) return
      call pelvis_state(m, lay, speed, acceleration, axes, force, moment)
      do k = 1, N_CONTACTS
        call self%slide%wall_position(m%scalars(lay%u(k))%q, m%scalars(lay%v(k))%q, angle(k), distance(k), status)
        if (.not. status%ok()) return
        normal(k) = m%contacts(lay%contact(k))%normal_force
      end do
      call extreme_quantities(speed, acceleration, axes, force, moment, &
        self%slide%arc_length(m%scalars(lay%u(CONTACT_PELVIS))%q), angle, distance, normal, self%gravity, &
        values, attached)
    end associate
  end subroutine probe_evaluate

  !> An internal step's dense output, for the extremes.
  subroutine rider_observe_step(self, t_n, h, taylor, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t_n, h, taylor(:, 0:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    call self%extremes%add_piece(t_n, h, taylor)
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
      was_active(k) = self%mechanism%laws(k)%law%active
    end do
    call self%mechanism_ode_t%handle_event(t, y, fired, action, status)
    if (.not. status%ok()) return
    do k = 1, self%mechanism%n_laws
      if (was_active(k) .neqv. self%mechanism%laws(k)%law%active) self%drag_switches = self%drag_switches + 1
    end do
    where = ' at arc length '//format_short(self%slide%arc_length(y(1)))//' m (t = '//format_short(t)//' s)'
    if (fired(1) < 0) then
      action = EVENT_STOP
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
        self%ending = RIDE_LAST_STATION
        self%outcome = 'last station: the pelvis reached it'//where
      end if
    end do
    if (action == EVENT_STOP .and. self%ending /= RIDE_LAST_STATION) then
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
    associate (m => self%mechanism, lay => self%layout)
      u = m%scalars(lay%u(self%ejected_contact))%q
      v = m%scalars(lay%v(self%ejected_contact))%q
    end associate
    call self%slide%section_edges(u, v_min, v_max)
    if (abs(v - v_max) < abs(v - v_min)) then
      side = 'left'
    else
      side = 'right'
    end if
  end function wall_side
end module rider_ride
