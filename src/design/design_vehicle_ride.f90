!> One vehicle's ride as a library call (docs/DESIGN.md, "The path of one
!> vehicle ride"; docs/vehicles.md): a description in memory (the vehicle,
!> its start, the surface it rides, the water it rides in, the limits, the
!> integration) in, the ride out (the water, the driven model with its
!> records, the ride figures and every limit's verdict, the status and how
!> the ride stopped). The `sled` command with a vehicle runs exactly this; it
!> prints nothing: progress lines go to the description's driver%log when it
!> gives one.
!>
!> Two calls, so that a command can check the built model before it opens a
!> file: build_vehicle_ride (the checks the description must pass, the
!> water, the model at its start) and run_vehicle_ride (the drive, the
!> figures, the verdicts; it builds first when that was not done). The ride
!> must be a TARGET that stays where it is from the build on: the water's
!> drag laws of its model point at its water.
!>
!> Here and not in the rider layer: the limits are judged as the body-slide
!> rider's (design_ride_evaluation, design_ride_report), a layer above.
module design_vehicle_ride
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_text, only: format_real, format_short, format_vector
  use geometry_surface, only: surface_t
  use geometry_slide_query, only: slide_surface_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, DRIVE_EVENT_STOP
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_END_OF_SURFACE, STOP_SIDE_EDGE
  use kinetostatics_models, only: sled_description_t
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_flight, only: ride_flights_t
  use rider_vehicle, only: vehicle_t, vehicle_body_t, vehicle_body, build_vehicle_model, vehicle_ride_figures, &
    vehicle_kinds, VEHICLE_BAR, narrowest_section, width_tolerance
  use rider_vehicle_flight, only: vehicle_flight_ode_t, build_vehicle_flight, drive_vehicle
  use design_ride_evaluation, only: ride_limit_t, limit_verdict_t, evaluate_limit
  use design_ride_report, only: judge_flights
  implicit none (type, external)
  private
  public :: vehicle_ride_description_t, vehicle_ride_t, build_vehicle_ride, run_vehicle_ride
  public :: vehicle_quantities, flight_quantities
  public :: FAILED_NONE, FAILED_REFUSED, FAILED_WATER, FAILED_BUILD, FAILED_START, FAILED_RUN

  !> The limits a vehicle's ride is judged on (docs/vehicles.md, "Limits"):
  !> the quantities of the body-slide rider that a rigid vehicle has (its
  !> ejection: a contact over the top of an open section's wall, where the
  !> run stops at the surface's side edge) ...
  character(len=*), parameter :: vehicle_quantities(9) = [character(len=25) :: 'speed', 'exit_speed', &
    'acceleration_longitudinal', 'acceleration_lateral', 'acceleration_normal', 'normal_force', 'wall_angle', &
    'wall_distance', 'ejection']
  !> ... and those of a vehicle that may fly (vehicle%may_fly)
  character(len=*), parameter :: flight_quantities(2) = [character(len=12) :: 'airtime', 'drop_height']

  !> Where a ride stopped short (vehicle_ride_t%failed).
  integer, parameter :: FAILED_NONE = 0
  integer, parameter :: FAILED_REFUSED = 1   !< the description, before any work (`refused` names what)
  integer, parameter :: FAILED_WATER = 2     !< the water the vehicle rides in
  integer, parameter :: FAILED_BUILD = 3     !< the vehicle's model
  integer, parameter :: FAILED_START = 4     !< the start (the model's check_start)
  integer, parameter :: FAILED_RUN = 5       !< the drive or the figures: the records up to there are kept

  !> Everything one vehicle's ride needs.
  type :: vehicle_ride_description_t
    type(vehicle_t) :: vehicle                !< its kind (not the bar), riders, their scales, its parts, ...
    type(sled_description_t) :: sled          !< its start and the sled's parameters (gravity, friction)
    class(surface_t), allocatable :: surface  !< what it rides on (a slide: its sections and limits)
    type(water_description_t) :: water        !< vehicle%in_water: the water on the slide, gravity the sled's
    type(ride_limit_t), allocatable :: limits(:)   !< judged along the slide (none: nothing judged)
    !> integration, t_end (the duration), output_step, the runaway guard,
    !> the label of messages, and the log of the stage and progress lines
    type(driver_options_t) :: driver
  end type vehicle_ride_description_t

  !> What one vehicle's ride gave.
  type :: vehicle_ride_t
    type(status_t) :: status                  !< ok, or why it failed
    integer :: failed = FAILED_NONE
    !> FAILED_REFUSED: what of the description ('vehicle': it does not fit
    !> the slide, 'water': the drag's sphere does not, 'gravity', 'limits';
    !> '': its vehicle or slide could not be measured)
    character(len=:), allocatable :: refused
    logical :: built = .false.                !< the model stands at its start
    ! the width check (docs/vehicles.md, "Does it fit?")
    real(wp) :: width = 0                     !< m, the vehicle's (the widest of vehicle and riders)
    logical :: fits_checked = .false.         !< the surface is a slide: its sections were measured
    real(wp) :: narrowest = 0, narrowest_at = 0   !< m: the narrowest section's width and arc length
    type(water_result_t) :: water             !< the water computed (vehicle%in_water)
    !> the vehicle's model, its records in series: `closed`, or with the
    !> flight's builds `flying` (flies: vehicle%may_fly); model() is the one
    !> in use. (Two components, not one polymorphic: gfortran 12 frees a
    !> polymorphic allocatable component of this dynamic type wrongly.)
    logical :: flies = .false.
    type(mechanism_ode_t) :: closed
    type(vehicle_flight_ode_t) :: flying
    real(wp), allocatable :: y0(:)            !< its start state
    type(driver_result_t) :: driven           !< the integrator's statistics and CPU time
    character(len=:), allocatable :: outcome  !< how the ride ended, in words
    ! the ride figures (docs/vehicles.md, "What the run reports"), per record
    real(wp), allocatable :: time(:)          !< s
    real(wp), allocatable :: speed(:), felt(:, :)   !< m/s, the centre of mass's; 3 x n, g (x, y, z of the vehicle)
    !> on a slide: each contact's wall position (rear, front; the slide's
    !> wall_position) and the rear contact's arc length
    real(wp), allocatable :: wall_angle(:, :)       !< 2 x n, rad from the bottom (+ towards +v)
    real(wp), allocatable :: wall_distance(:, :)    !< 2 x n, m along the section from the bottom (signed)
    real(wp), allocatable :: where(:)               !< n, m
    type(limit_verdict_t), allocatable :: verdicts(:)   !< one per description%limits
    logical, allocatable :: judged(:)               !< exit_speed: only when the vehicle reached the end
    !> a vehicle that may fly: its flights and landings, each record's open
    !> contacts (bit 0 the rear, bit 1 the front), how often the front's
    !> closure changed the coordinate it solves
    type(ride_flights_t) :: flights
    integer, allocatable :: open(:)
    integer :: solve_switches = 0
  contains
    procedure :: model => ride_model
  end type vehicle_ride_t

contains

  !> The vehicle's model in use: ride%flying or ride%closed.
  function ride_model(self) result(sys)
    class(vehicle_ride_t), intent(inout), target :: self
    class(mechanism_ode_t), pointer :: sys
    if (self%flies) then
      sys => self%flying
    else
      sys => self%closed
    end if
  end function ride_model

  !> The checks the description must pass (the vehicle fits every section
  !> of a slide, the water's drag fits in it, one gravity, the limits a
  !> vehicle's), then the water (vehicle%in_water, unless `dry`: a check
  !> without work), then the model at its start, checked.
  subroutine build_vehicle_ride(d, ride, dry)
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), intent(inout), target :: ride
    logical, intent(in), optional :: dry
    real(wp), allocatable :: q0(:), qd0(:)
    logical :: with_water
    class(mechanism_ode_t), pointer :: sys
    ride%status = status_t()
    ride%failed = FAILED_NONE
    ride%refused = ''
    ride%built = .false.
    call refuse_misfit(d, ride)
    if (ride%status%ok()) call refuse_limits(d, ride)
    with_water = d%vehicle%in_water
    if (present(dry)) with_water = with_water .and. .not. dry
    if (ride%status%ok() .and. d%vehicle%in_water) call refuse_water(d, ride)
    if (.not. ride%status%ok()) then
      ride%failed = FAILED_REFUSED
      return
    end if
    if (with_water) then
      call log_line(d, d%driver%label//': the water first ('//format_real(d%water%flow_rate)//' m^3/s)')
      if (associated(d%driver%log)) then
        call compute_water(d%water, ride%water, ride%status, d%driver%log)
      else
        call compute_water(d%water, ride%water, ride%status)
      end if
      if (.not. ride%status%ok()) then
        call prefix_status(ride%status, 'the water the vehicle rides in')
        ride%failed = FAILED_WATER
        return
      end if
    end if
    ride%flies = d%vehicle%may_fly
    if (ride%flies .and. with_water) then
      call build_vehicle_flight(d%vehicle, d%sled, d%surface, ride%flying, q0, qd0, ride%status, &
                                water=ride%water%field)
    else if (ride%flies) then
      call build_vehicle_flight(d%vehicle, d%sled, d%surface, ride%flying, q0, qd0, ride%status)
    else if (with_water) then
      call build_vehicle_model(d%vehicle, d%sled, d%surface, ride%closed%mechanism, q0, qd0, ride%status, &
                               water=ride%water%field)
    else
      call build_vehicle_model(d%vehicle, d%sled, d%surface, ride%closed%mechanism, q0, qd0, ride%status)
    end if
    if (.not. ride%status%ok()) then
      ride%failed = FAILED_BUILD
      return
    end if
    sys => ride%model()
    ride%y0 = sys%initial_state(q0, qd0)
    call sys%check_start(ride%y0, ride%status)
    if (.not. ride%status%ok()) then
      ride%failed = FAILED_START
      return
    end if
    ride%built = .true.
  end subroutine build_vehicle_ride

  !> The ride from its start over d%driver%t_end (built first unless
  !> build_vehicle_ride was called), then its figures and the limits'
  !> verdicts. A failure on the way keeps the records up to there and
  !> their figures (FAILED_RUN; status the run's failure, the figures of
  !> the records as far as they could be computed, exit_speed not judged).
  subroutine run_vehicle_ride(d, ride)
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), intent(inout), target :: ride
    class(mechanism_ode_t), pointer :: sys
    type(status_t) :: run_status
    if (.not. ride%built) call build_vehicle_ride(d, ride)
    if (.not. ride%built) return
    sys => ride%model()
    call sys%start_series(nint(d%driver%t_end/d%driver%output_step) + 2)
    if (ride%flies) then
      ! stretch by stretch through its builds (rider_vehicle_flight)
      call drive_vehicle(ride%flying, ride%y0, d%driver, ride%driven, ride%status)
    else
      call drive(ride%closed, ride%y0, d%driver, ride%driven, ride%status)
    end if
    select case (ride%driven%outcome)
    case (DRIVE_END_TIME)
      ride%outcome = 'the end of the simulated time'
      ! what happened on the way (its flights)
      if (ride%flies .and. len(sys%outcome) > 0) ride%outcome = sys%outcome//'; '//ride%outcome
    case (DRIVE_EVENT_STOP)
      ride%outcome = sys%outcome
    case default
      ride%outcome = 'failed: '//ride%status%text()
    end select
    if (sys%series%n > 0) then
      ! a failed run's figures too: its records are kept; its failure comes first
      run_status = ride%status
      ride%status = status_t()
      call ride_figures(d, ride)
      if (.not. run_status%ok()) ride%status = run_status
    end if
    if (.not. ride%status%ok()) ride%failed = FAILED_RUN
  end subroutine run_vehicle_ride

  !> A vehicle wider than the narrowest section of the slide (by more than
  !> width_tolerance) is refused before any work: the sled's two contacts
  !> under its long axis would carry it down a slide it cannot be in
  !> (docs/vehicles.md, "Does it fit?"). On a surface that is not a slide
  !> there is no section to check (fits_checked stays false).
  subroutine refuse_misfit(d, ride)
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), intent(inout) :: ride
    type(vehicle_body_t) :: vb
    if (d%vehicle%kind == VEHICLE_BAR) then
      call refuse(ride, 'vehicle', 'the plain bar has no ride figures: a vehicle rides (docs/vehicles.md)')
      return
    end if
    call vehicle_body(d%vehicle, vb, ride%status)
    call narrowest_section(d%surface, ride%narrowest, ride%narrowest_at, ride%fits_checked, ride%status)
    if (.not. ride%status%ok()) return
    ride%width = vb%width
    if (ride%fits_checked .and. vb%width > ride%narrowest + width_tolerance) &
      call refuse(ride, 'vehicle', 'it is '//format_short(vb%width)//' m wide, but the slide''s section at arc '// &
                  'length '//format_short(ride%narrowest_at)//' m is only '//format_short(ride%narrowest)// &
                  ' m wide across its bottom: a vehicle must fit every section of the slide (docs/vehicles.md, '// &
                  '"Does it fit?")')
  end subroutine refuse_misfit

  !> Limits only of the quantities a vehicle's ride has (flight_quantities
  !> only when it may fly), judged along a slide. The command's reader
  !> refuses them first, naming the input's variable (scenarios_sled).
  subroutine refuse_limits(d, ride)
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), intent(inout) :: ride
    integer :: k
    if (.not. allocated(d%limits)) return
    do k = 1, size(d%limits)
      associate (quantity => d%limits(k)%quantity)
        if (any(vehicle_quantities == quantity)) cycle
        if (d%vehicle%may_fly .and. any(flight_quantities == quantity)) cycle
        call refuse(ride, 'limits', 'a vehicle''s ride is not judged on '//quantity//' (docs/vehicles.md, "Limits")')
        return
      end associate
    end do
    if (size(d%limits) == 0) return
    select type (surface => d%surface)
    class is (slide_surface_t)
    class default
      call refuse(ride, 'limits', 'limits are judged along a slide (at arc lengths); the '//surface%describe()// &
                  ' is not one')
    end select
  end subroutine refuse_limits

  !> The water's drag acts on a sphere at each contact (rider_vehicle),
  !> which must fit in the slide, as the rider's (check_sphere_radii); a
  !> ride has one gravity.
  subroutine refuse_water(d, ride)
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), intent(inout) :: ride
    type(vehicle_body_t) :: vb
    real(wp) :: room, u_at
    if (.not. allocated(d%water%slide)) then
      call refuse(ride, 'water', 'the water is computed on a slide: give water%slide')
      return
    end if
    call vehicle_body(d%vehicle, vb, ride%status)
    if (ride%status%ok()) call d%water%slide%bottom_radius(room, u_at, ride%status)
    if (.not. ride%status%ok()) return
    if (maxval(vb%drag_radius) > room*(1 + 1e-9_wp)) then
      call refuse(ride, 'water', 'the water''s drag acts on a sphere of '//format_short(maxval(vb%drag_radius))// &
                  ' m under the '//trim(vehicle_kinds(d%vehicle%kind))//', which must fit in the slide: at most '// &
                  'the radius of curvature across its bottom, '//format_short(room)//' m (the smallest, at '// &
                  format_short(d%water%slide%arc_length(u_at))//' m of arc length)')
    else if (any(d%water%gravity /= d%sled%params%gravity)) then
      call refuse(ride, 'gravity', 'water%gravity = '//format_vector(d%water%gravity)//' m/s^2 but the sled''s '// &
                  'is '//format_vector(d%sled%params%gravity)//' m/s^2: a ride has one gravity')
    end if
  end subroutine refuse_water

  subroutine refuse(ride, what, words)
    type(vehicle_ride_t), intent(inout) :: ride
    character(len=*), intent(in) :: what, words
    ride%refused = what
    call set_status(ride%status, STATUS_INVALID_INPUT, words)
  end subroutine refuse

  subroutine log_line(d, line)
    type(vehicle_ride_description_t), intent(in) :: d
    character(len=*), intent(in) :: line
    if (associated(d%driver%log)) call d%driver%log(line)
  end subroutine log_line

  !> The ride figures of the records: the speed and felt acceleration of
  !> the centre of mass, on a slide the contacts' wall positions and the
  !> limits' verdicts, judged as the body-slide rider's (design_ride_report).
  subroutine ride_figures(d, ride)
    type(vehicle_ride_description_t), intent(in) :: d
    type(vehicle_ride_t), intent(inout), target :: ride
    real(wp), allocatable :: values(:)
    class(mechanism_ode_t), pointer :: sys
    integer :: k, i, n
    sys => ride%model()
    n = sys%series%n
    if (ride%flies) then
      ! computed stretch by stretch, each with its build (drive_vehicle);
      ! a failed stretch's only where they could be
      associate (flying => ride%flying)
        if (size(flying%speed) == n) then
          ride%speed = flying%speed
          ride%felt = flying%felt
        end if
        ride%flights = flying%flights
        ride%open = flying%open_record
        ride%solve_switches = flying%solve_switches
      end associate
    else
      call vehicle_ride_figures(ride%closed%mechanism, ride%closed%work, ride%closed%series, ride%speed, ride%felt, &
                                ride%status)
      ! not at every record: none (a failed run's file keeps its records without them)
      if (.not. ride%status%ok()) deallocate (ride%speed, ride%felt)
    end if
    ride%time = sys%series%time(:n)
    if (.not. (ride%status%ok() .and. allocated(ride%speed))) return
    select type (slide => d%surface)
    class is (slide_surface_t)
      call contacts_on_the_wall(slide, ride)
    class default
      return
    end select
    if (.not. (ride%status%ok() .and. allocated(d%limits))) return
    if (size(d%limits) == 0) return
    allocate (ride%verdicts(size(d%limits)), ride%judged(size(d%limits)))
    ride%judged = .true.
    associate (where => ride%where, series => sys%series)
      do k = 1, size(d%limits)
        select case (d%limits(k)%quantity)
        case ('speed')
          values = ride%speed
        case ('exit_speed')
          ride%judged(k) = sys%stop_kind == STOP_END_OF_SURFACE
          if (ride%judged(k)) call evaluate_limit(d%limits(k), ride%speed(n:n), where(n:n), ride%verdicts(k))
          cycle
        case ('acceleration_longitudinal')
          values = ride%felt(1, :)
        case ('acceleration_lateral')
          values = ride%felt(2, :)
        case ('acceleration_normal')
          values = ride%felt(3, :)
        case ('normal_force')
          values = [(minval(series%normal(:, i)), i = 1, n)]   ! the smaller of the two contacts'
        case ('wall_angle')
          values = maxval(abs(ride%wall_angle), dim=1)*180/pi       ! the higher of the two contacts'
        case ('wall_distance')
          values = maxval(abs(ride%wall_distance), dim=1)
        case ('ejection')   ! 1: a contact went over the top of a wall (the run stopped there), else 0
          call evaluate_limit(d%limits(k), [merge(1.0_wp, 0.0_wp, sys%stop_kind == STOP_SIDE_EDGE)], where(n:n), &
                              ride%verdicts(k))
          cycle
        case ('airtime', 'drop_height')
          call judge_flights(d%limits(k), where(1), ride%verdicts(k), ride%flights)
          cycle
        end select
        call evaluate_limit(d%limits(k), values, where, ride%verdicts(k))
      end do
    end associate
  end subroutine ride_figures

  !> Each contact's wall position at each record (the slide's
  !> wall_position: the angle of the slide's normal there from the
  !> bottom's, + towards +v, and the distance along the section), as the
  !> body-slide rider's; the rear contact's arc length.
  subroutine contacts_on_the_wall(slide, ride)
    class(slide_surface_t), intent(in) :: slide
    type(vehicle_ride_t), intent(inout), target :: ride
    class(mechanism_ode_t), pointer :: sys
    integer :: coordinate(2, 2), k, i, n
    logical :: dependent(2)
    real(wp) :: u, v
    sys => ride%model()
    ! where each contact's (u, v) is recorded: a coordinate (q) or a
    ! dependent one of the closure (beta), by the records' names (a flying
    ! vehicle's records join its builds')
    associate (s => sys%series)
      coordinate(:, 1) = [findloc(s%q_names, 'u', 1), findloc(s%q_names, 'v', 1)]
      coordinate(:, 2) = [findloc(s%beta_names, 'u2', 1), findloc(s%beta_names, 'v2', 1)]
      dependent = [.false., .true.]
      n = s%n
      allocate (ride%wall_angle(2, n), ride%wall_distance(2, n))
      do i = 1, n
        do k = 1, 2
          if (dependent(k)) then
            u = s%beta(coordinate(1, k), i); v = s%beta(coordinate(2, k), i)
          else
            u = s%q(coordinate(1, k), i); v = s%q(coordinate(2, k), i)
          end if
          call slide%wall_position(u, v, ride%wall_angle(k, i), ride%wall_distance(k, i), ride%status)
        end do
        if (.not. ride%status%ok()) then
          call prefix_status(ride%status, 'the contacts'' wall positions at t = '//format_real(s%time(i))//' s')
          deallocate (ride%wall_angle, ride%wall_distance)   ! not at every record: none
          return
        end if
      end do
      ride%where = [(slide%arc_length(s%q(coordinate(1, 1), i)), i = 1, n)]
    end associate
  end subroutine contacts_on_the_wall
end module design_vehicle_ride
