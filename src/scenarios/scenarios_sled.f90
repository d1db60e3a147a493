!> Scenario `sled`: a rigid bar sliding on a surface, rear end on a surface
!> joint (q = u, v, phi), front end held on the surface by a second surface
!> joint and three plane-point closure conditions (beta = pitch, u2, v2), as
!> the rider's legs in thesis (4.27); gravity and Coulomb/viscous friction at
!> both contacts. `vehicle` puts a mat, a ring or a raft with its riders in
!> place of the bar (rider_vehicle).
module scenarios_sled
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_END_OF_SURFACE
  use base_constants, only: pi
  use geometry_slide_query, only: slide_surface_t
  use design_ride_evaluation, only: ride_limit_t, limit_verdict_t, evaluate_limit, limit_report_unit, limit_bounds_text, spaced_unit
  use io_input, only: group_reader_t, open_group
  use io_friction_config, only: friction_law_variables
  use io_rider_config, only: read_limits
  use scenarios_ride, only: read_limit_gate, limits_exceeded_status
  use base_text, only: format_integer
  use kinetostatics_models, only: sled_description_t
  use rider_vehicle, only: vehicle_t, vehicle_body_t, vehicle_body, build_vehicle_model, vehicle_ride_figures, &
    vehicle_kinds, VEHICLE_BAR, narrowest_section, width_tolerance
  use rider_vehicle_flight, only: vehicle_flight_ode_t, build_vehicle_flight, vehicle_contact_names
  use rider_flight, only: ride_flights_t
  use scenarios_ride_flights, only: add_flights, write_flights
  use design_ride_evaluation, only: felt_acceleration_units
  use design_ride_report, only: judge_flights
  use io_hdf5, only: result_file_t, run_outcome
  use io_summary, only: summary_t
  use base_text, only: format_short
  use io_input, only: input_text_t, check_known_groups, invalid, format_real, mark_input_failure
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_surface_config, only: read_surface_config, surface_source_t, explain_surface_failure, start_domain_words
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use io_geometry_config, only: geometry_groups
  use scenarios_mechanism, only: run_mechanism, run_figures_t
  use scenarios_ride_results, only: write_limit_verdicts
  use scenarios_water, only: build_water
  use water_run, only: water_description_t, water_result_t, compute_water
  use water_flow, only: outcome_name
  use io_water_results, only: write_water_results
  use io_input, only: group_present, where_given
  use geometry_tube, only: tube_surface_t
  use base_log, only: log_info, log_warning
  use water_curve_entry, only: curve_entry_note, splash_note
  use base_status, only: set_status, prefix_status, STATUS_INVALID_INPUT
  implicit none (type, external)
  private
  public :: run_sled, sled_groups

  character(len=*), parameter :: sled_groups(14) = [character(len=14) :: 'run', 'solver', 'surface', 'sled', &
    'evaluation', 'water', 'water_solver', 'inlet', geometry_groups]
  !> the groups of the water a vehicle rides in (scenarios_water's build_water)
  character(len=*), parameter :: water_only_groups(3) = [character(len=12) :: 'water', 'water_solver', 'inlet']
  !> The limits a vehicle's ride is judged on (docs/vehicles.md, "Limits"):
  !> the quantities of the body-slide rider that a rigid vehicle has.
  character(len=*), parameter :: vehicle_quantities(8) = [character(len=25) :: 'speed', 'exit_speed', &
    'acceleration_longitudinal', 'acceleration_lateral', 'acceleration_normal', 'normal_force', 'wall_angle', &
    'wall_distance']
  character(len=*), parameter :: contact_names(2) = [character(len=5) :: 'rear', 'front']
  !> ... and those of a vehicle that may fly (&sled may_fly)
  character(len=*), parameter :: flight_quantities(2) = [character(len=12) :: 'airtime', 'drop_height']

  !> A vehicle's ride figures (docs/vehicles.md, "What the run reports"):
  !> per record the speed of its centre of mass and the felt acceleration
  !> there, in /sled/vehicle and the summary (largest speed, exit speed,
  !> felt extremes).
  type, extends(run_figures_t) :: vehicle_figures_t
    type(vehicle_t) :: vehicle
    real(wp) :: gravity(3) = 0
    real(wp), allocatable :: speed(:), felt(:, :)   ! m/s; 3 x n, g
    real(wp), allocatable :: time(:)                ! s
    real(wp) :: width = 0                           ! m, the vehicle's
    logical :: fits_checked = .false.               ! the surface is a slide: its sections were measured
    real(wp) :: narrowest = 0, narrowest_at = 0     ! m: the narrowest section's width and arc length
    type(ride_limit_t), allocatable :: limits(:)    ! &sled limit_*
    !> on a slide: where the limits are judged (the rear contact's arc
    !> length) and the contacts' wall positions
    class(slide_surface_t), allocatable :: slide
    real(wp), allocatable :: wall_angle(:, :)       ! 2 x n, rad: each contact's, from the bottom (+ towards +v)
    real(wp), allocatable :: wall_distance(:, :)    ! 2 x n, m: along the section from the bottom (signed)
    real(wp), allocatable :: where(:)               ! n, m: the rear contact's arc length
    type(limit_verdict_t), allocatable :: verdicts(:)
    logical, allocatable :: judged(:)               ! exit_speed: only when the vehicle reached the end
    logical :: in_water = .false.                   ! the water computed on the slide, its drag at the contacts
    type(water_description_t) :: water             ! (in_water) the water as given
    type(water_result_t) :: water_result            ! (in_water) the computed water, written under /water
    !> a vehicle that may fly (&sled may_fly): its flights and landings,
    !> each record's open contacts (bit 0 the rear, bit 1 the front)
    type(ride_flights_t) :: flights
    integer, allocatable :: open(:)
    integer :: solve_switches = 0    ! how often the front's closure changed the coordinate it solves
  contains
    procedure :: compute => vehicle_compute
    procedure :: write => vehicle_write
    procedure :: summarise => vehicle_summarise
  end type vehicle_figures_t

contains

  subroutine run_sled(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(sled_description_t) :: config
    type(vehicle_t) :: vehicle
    type(vehicle_figures_t), target :: figures   ! its water_result%field: the drag laws of sys point at it
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    type(vehicle_flight_ode_t), target :: flying   ! a vehicle that may fly (its builds)
    character(len=:), allocatable :: u_units, v_units
    character(len=8) :: q_units(3), beta_units(3)
    real(wp), allocatable :: q0(:), qd0(:)
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: surface_source
    type(status_t) :: built
    character(len=:), allocatable :: part, variable
    logical :: fail_on_limit
    integer :: k

    call check_known_groups(input, sled_groups, status, repeatable=[character(len=5) :: 'inlet'])
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_surface_config(input, surface_description, status, surface_source)
    if (status%ok()) call build_surface(surface_description, surface, built, part, variable)
    if (status%ok()) call explain_surface_failure(surface_source, built, part, variable, status)
    if (status%ok()) call read_sled_config(input, config, status, vehicle)
    if (.not. status%ok()) return
    if (.not. surface%in_domain(config%q0(1), config%q0(2))) then
      call invalid(input, 'sled', 'u0, v0', format_real(config%q0(1))//', '//format_real(config%q0(2)), &
                   start_domain_words(surface), status)
      return
    end if
    if (vehicle%kind /= VEHICLE_BAR) call check_vehicle_fits(input, vehicle, surface, figures, status)
    if (status%ok()) call read_vehicle_limits(input, run, vehicle, config, surface, figures, fail_on_limit, status)
    if (status%ok()) call read_vehicle_water(input, vehicle, config, surface, figures, status)
    if (.not. status%ok()) return
    ! a check (--check) builds the vehicle dry: the water is work
    if (figures%in_water .and. .not. run%check_only) then
      call log_info('sled: the water first ('//format_real(figures%water%flow_rate)//' m^3/s)')
      call compute_water(figures%water, figures%water_result, status, log_info)
      if (.not. status%ok()) then
        call prefix_status(status, input%name//': the water the vehicle rides in')
        call keep_failed_water(input, run, figures, status)
        return
      end if
      call warn(curve_entry_note(figures%water_result%series, figures%water%f3))
      call warn(splash_note(figures%water_result%series, figures%water%f3))
      if (vehicle%may_fly) then
        call build_vehicle_flight(vehicle, config, surface, flying, q0, qd0, status, water=figures%water_result%field)
      else
        call build_vehicle_model(vehicle, config, surface, sys%mechanism, q0, qd0, status, &
                                 water=figures%water_result%field)
      end if
    else if (vehicle%may_fly) then
      call build_vehicle_flight(vehicle, config, surface, flying, q0, qd0, status)
    else
      call build_vehicle_model(vehicle, config, surface, sys%mechanism, q0, qd0, status)
    end if
    call mark_input_failure(status)
    if (.not. status%ok()) return
    call surface%parameter_units(u_units, v_units)
    q_units(1) = u_units; q_units(2) = v_units; q_units(3) = 'rad'   ! u, v, phi
    beta_units(1) = 'rad'; beta_units(2) = u_units; beta_units(3) = v_units   ! pitch, u2, v2
    if (vehicle%kind == VEHICLE_BAR) then
      call run_mechanism('sled', input, run, solver, sys, q0, qd0, q_units, beta_units, status, &
                         surface=surface, start_variables='u0, v0, phi0, du0, dv0, dphi0')
    else
      figures%vehicle = vehicle
      figures%gravity = config%params%gravity
      if (vehicle%may_fly) then
        call run_mechanism('sled', input, run, solver, flying, q0, qd0, q_units, beta_units, status, &
                           surface=surface, start_variables='u0, v0, phi0, du0, dv0, dphi0', figures=figures)
      else
        call run_mechanism('sled', input, run, solver, sys, q0, qd0, q_units, beta_units, status, &
                           surface=surface, start_variables='u0, v0, phi0, du0, dv0, dphi0', figures=figures)
      end if
      if (status%ok() .and. fail_on_limit .and. allocated(figures%verdicts)) &
        call limits_exceeded_status(input%name, figures%limits, [(merge(1, 0, figures%judged(k) .and. &
                                    figures%verdicts(k)%exceeded), k = 1, size(figures%limits))], .false., status)
    end if

  contains

    !> A note on the water (water_curve_entry), as the ride warns of it.
    subroutine warn(note)
      character(len=*), intent(in) :: note
      if (len(note) > 0) call log_warning(input%name//': water: '//note)
    end subroutine warn
  end subroutine run_sled

  !> &sled's limits (limit_quantity, limit_unit, limit_min, limit_max, read
  !> as &rider's) and whether one exceeded fails the run (&evaluation
  !> fail_on_limit, --fail-on-limit: exit status 4). Only a vehicle's ride is
  !> judged, on a slide (where: the rear contact's arc length), on the
  !> quantities it has (vehicle_quantities); the others are refused, naming
  !> why (docs/vehicles.md, "Limits").
  subroutine read_vehicle_limits(input, run, vehicle, config, surface, figures, fail_on_limit, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(vehicle_t), intent(in) :: vehicle
    type(sled_description_t), intent(in) :: config
    class(surface_t), intent(in) :: surface
    type(vehicle_figures_t), intent(inout) :: figures
    logical, intent(out) :: fail_on_limit
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    integer :: k
    fail_on_limit = .false.
    call open_group(input, 'sled', r, status, also=friction_law_variables())
    call read_limits(r, norm2(config%params%gravity), .true., figures%limits, status)
    if (.not. status%ok()) return
    if (size(figures%limits) > 0 .and. vehicle%kind == VEHICLE_BAR) then
      call r%invalid('limit_quantity', r%written('limit_quantity'), 'limits judge a vehicle''s ride (docs/'// &
                     'vehicles.md, "Limits"): the bar has no ride figures; give vehicle', status)
      return
    end if
    do k = 1, size(figures%limits)
      if (any(vehicle_quantities == figures%limits(k)%quantity)) cycle
      if (vehicle%may_fly .and. any(flight_quantities == figures%limits(k)%quantity)) cycle
      if (any(flight_quantities == figures%limits(k)%quantity)) then
        call r%invalid('limit_quantity('//format_integer(k)//')', ''''//figures%limits(k)%quantity//'''', &
                       figures%limits(k)%quantity//' limits a flight: it needs may_fly = .true. (without it a '// &
                       'lift-off ends the run; docs/vehicles.md, "Limits")', status)
        return
      end if
      call r%invalid('limit_quantity('//format_integer(k)//')', ''''//figures%limits(k)%quantity//'''', &
                     'a vehicle''s ride is judged on speed, exit_speed, acceleration_longitudinal, '// &
                     'acceleration_lateral, acceleration_normal, normal_force, wall_angle and wall_distance, '// &
                     'and with may_fly on airtime and drop_height; '// &
                     figures%limits(k)%quantity//' belongs to the body-slide rider (its tipping: '// &
                     'docs/vehicles.md, "Limits")', status)
      return
    end do
    select type (surface)
    class is (slide_surface_t)
      allocate (figures%slide, source=surface)
    end select
    if (size(figures%limits) > 0) then
      select type (surface)
      class is (slide_surface_t)
      class default
        call r%invalid('limit_quantity', r%written('limit_quantity'), 'limits are judged along a slide (at '// &
                       'arc lengths); the '//surface%describe()//' is not one', status)
        return
      end select
    end if
    call read_limit_gate(input, run, figures%limits, fail_on_limit, status, limits_group='sled')
  end subroutine read_vehicle_limits

  !> A water that failed before the vehicle rode: the result file with
  !> its provenance and /water as far as it ran, marked incomplete (exit
  !> status 2 keeps a file, as the ride's).
  subroutine keep_failed_water(input, run, figures, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(vehicle_figures_t), intent(in) :: figures
    type(status_t), intent(inout) :: status
    type(result_file_t) :: file
    type(status_t) :: write_status
    call file%create(trim(run%output), write_status)
    if (write_status%ok()) then
      call file%write_provenance('sled', trim(run%title), input%name, input%text(), write_status)
      call write_water_results(file, figures%water, figures%water_result, write_status)
      call file%finish(.false., status%text(), write_status)
    end if
    status = run_outcome(status, write_status)
  end subroutine keep_failed_water

  !> The water a vehicle rides in (docs/vehicles.md, "In the water"): with
  !> &sled water = 'computed' (a vehicle's default) the water of &water,
  !> &water_solver and &inlet on the slide, read and checked as the ride's
  !> (build_water), its gravity the sled's; a surface without water (not a
  !> tube or slide) is refused unless water = 'dry' says so. Riding dry,
  !> the water's groups are refused (they would not be used).
  subroutine read_vehicle_water(input, vehicle, config, surface, figures, status)
    type(input_text_t), intent(in) :: input
    type(vehicle_t), intent(in) :: vehicle
    type(sled_description_t), intent(in) :: config
    class(surface_t), intent(in) :: surface
    type(vehicle_figures_t), intent(inout) :: figures
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    type(vehicle_body_t) :: vb
    real(wp) :: room, u_at
    character(len=:), allocatable :: given, why
    integer :: k
    if (.not. status%ok()) return
    figures%in_water = vehicle%in_water
    if (.not. vehicle%in_water) then
      do k = 1, size(water_only_groups)
        if (.not. group_present(input, trim(water_only_groups(k)))) cycle
        why = '&sled water = ''dry'''
        if (vehicle%kind == VEHICLE_BAR) why = 'it is the plain bar: &sled gives no vehicle'
        call set_status(status, STATUS_INVALID_INPUT, where_given(input, trim(water_only_groups(k)), '')// &
                        ': &'//trim(water_only_groups(k))//' is not read: the sled rides dry ('//why// &
                        '); a vehicle (&sled vehicle = ''mat'', ''ring'', ...) rides in the water with water = '// &
                        '''computed''')
        return
      end do
      return
    end if
    select type (surface)
    type is (tube_surface_t)
    class default
      call open_group(input, 'sled', r, status, also=friction_law_variables())
      given = '''computed'''
      if (r%has('water')) given = r%written('water')
      call r%invalid('water', given, 'the water is computed '// &
                     'on a slide (&surface kind = ''slide'' or ''tube''), not on the '//surface%describe()// &
                     '; give water = ''dry'' to ride dry (docs/vehicles.md, "In the water")', status)
      return
    end select
    call build_water(input, figures%water, status, stage=.true.)
    if (.not. status%ok()) return
    ! the drag's spheres must fit in the slide, as the rider's (check_sphere_radii)
    call vehicle_body(vehicle, vb, status)
    if (status%ok()) call figures%water%slide%bottom_radius(room, u_at, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    if (maxval(vb%drag_radius) > room*(1 + 1e-9_wp)) then
      call invalid(input, 'sled', 'water', '''computed''', 'the water''s drag acts on a sphere of '// &
                   format_short(maxval(vb%drag_radius))//' m under the '//trim(vehicle_kinds(vehicle%kind))// &
                   ', which must fit in the slide: at most the radius of curvature across its bottom, '// &
                   format_short(room)//' m (the smallest, at '// &
                   format_short(figures%water%slide%arc_length(u_at))//' m of arc length)', status)
      return
    end if
    if (any(figures%water%gravity /= config%params%gravity)) then
      call open_group(input, 'water', r, status)
      call r%invalid('gravity', r%written('gravity'), 'a ride has one gravity, and &sled''s is '// &
                     format_real(config%params%gravity(1))//', '//format_real(config%params%gravity(2))//', '// &
                     format_real(config%params%gravity(3))//' m/s^2: give it in &sled only, or the same in both', &
                     status)
    end if
  end subroutine read_vehicle_water

  !> A vehicle wider than the narrowest section of the slide (by more than
  !> width_tolerance) is refused before any work: the sled's two contacts
  !> under its long axis would carry it down a slide it cannot be in
  !> (docs/vehicles.md, "Does it fit?"). On a surface that is not a slide
  !> there is no section to check (the summary says so).
  subroutine check_vehicle_fits(input, vehicle, surface, figures, status)
    type(input_text_t), intent(in) :: input
    type(vehicle_t), intent(in) :: vehicle
    class(surface_t), intent(in) :: surface
    type(vehicle_figures_t), intent(inout) :: figures
    type(status_t), intent(inout) :: status
    type(vehicle_body_t) :: vb
    call vehicle_body(vehicle, vb, status)
    call narrowest_section(surface, figures%narrowest, figures%narrowest_at, figures%fits_checked, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    figures%width = vb%width
    if (figures%fits_checked .and. vb%width > figures%narrowest + width_tolerance) &
      call invalid(input, 'sled', 'vehicle', ''''//trim(vehicle_kinds(vehicle%kind))//'''', 'it is '// &
                   format_short(vb%width)//' m wide, but the slide''s section at arc length '// &
                   format_short(figures%narrowest_at)//' m is only '//format_short(figures%narrowest)// &
                   ' m wide across its bottom: a vehicle must fit every section of the slide (docs/vehicles.md, '// &
                   '"Does it fit?")', status)
  end subroutine check_vehicle_fits

  subroutine vehicle_compute(self, sys, status)
    class(vehicle_figures_t), intent(inout) :: self
    class(mechanism_ode_t), intent(inout) :: sys
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: values(:), where(:)
    integer :: k, i, n
    select type (sys)
    class is (vehicle_flight_ode_t)
      ! computed stretch by stretch, each with its build (drive_vehicle)
      self%speed = sys%speed
      self%felt = sys%felt
      self%flights = sys%flights
      self%open = sys%open_record
      self%solve_switches = sys%solve_switches
    class default
      call vehicle_ride_figures(sys%mechanism, sys%work, sys%series, self%speed, self%felt, status)
    end select
    n = sys%series%n
    self%time = sys%series%time(:n)
    if (.not. (status%ok() .and. allocated(self%slide))) return
    call contacts_on_the_wall(self, sys, status)
    if (.not. (status%ok() .and. allocated(self%limits))) return
    if (size(self%limits) == 0) return
    ! the limits, judged as the body-slide rider's (design_ride_report)
    where = self%where
    allocate (self%verdicts(size(self%limits)), self%judged(size(self%limits)))
    self%judged = .true.
    do k = 1, size(self%limits)
      select case (self%limits(k)%quantity)
      case ('speed')
        values = self%speed
      case ('exit_speed')
        self%judged(k) = sys%stop_kind == STOP_END_OF_SURFACE
        if (self%judged(k)) call evaluate_limit(self%limits(k), self%speed(n:n), where(n:n), self%verdicts(k))
        cycle
      case ('acceleration_longitudinal')
        values = self%felt(1, :)
      case ('acceleration_lateral')
        values = self%felt(2, :)
      case ('acceleration_normal')
        values = self%felt(3, :)
      case ('normal_force')
        values = [(minval(sys%series%normal(:, i)), i = 1, n)]   ! the smaller of the two contacts'
      case ('wall_angle')
        values = maxval(abs(self%wall_angle), dim=1)*180/pi       ! the higher of the two contacts'
      case ('wall_distance')
        values = maxval(abs(self%wall_distance), dim=1)
      case ('airtime', 'drop_height')
        call judge_flights(self%limits(k), where(1), self%verdicts(k), self%flights)
        cycle
      end select
      call evaluate_limit(self%limits(k), values, where, self%verdicts(k))
    end do
  end subroutine vehicle_compute

  !> Each contact's wall position at each record (the slide's
  !> wall_position: the angle of the slide's normal there from the
  !> bottom's, + towards +v, and the distance along the section), as the
  !> body-slide rider's; the rear contact's arc length.
  subroutine contacts_on_the_wall(self, sys, status)
    class(vehicle_figures_t), intent(inout) :: self
    class(mechanism_ode_t), intent(in) :: sys
    type(status_t), intent(inout) :: status
    integer :: coordinate(2, 2), k, i, n
    logical :: dependent(2)
    real(wp) :: u, v
    ! where each contact's (u, v) is recorded: a coordinate (q) or a
    ! dependent one of the closure (beta), by the records' names (a flying
    ! vehicle's records join its builds')
    associate (s => sys%series)
      coordinate(:, 1) = [findloc(s%q_names, 'u', 1), findloc(s%q_names, 'v', 1)]
      coordinate(:, 2) = [findloc(s%beta_names, 'u2', 1), findloc(s%beta_names, 'v2', 1)]
      dependent = [.false., .true.]
      n = s%n
      allocate (self%wall_angle(2, n), self%wall_distance(2, n))
      do i = 1, n
        do k = 1, 2
          if (dependent(k)) then
            u = s%beta(coordinate(1, k), i); v = s%beta(coordinate(2, k), i)
          else
            u = s%q(coordinate(1, k), i); v = s%q(coordinate(2, k), i)
          end if
          call self%slide%wall_position(u, v, self%wall_angle(k, i), self%wall_distance(k, i), status)
        end do
        if (.not. status%ok()) then
          call prefix_status(status, 'the contacts'' wall positions at t = '//format_real(s%time(i))//' s')
          return
        end if
      end do
      self%where = [(self%slide%arc_length(s%q(coordinate(1, 1), i)), i = 1, n)]
    end associate
  end subroutine contacts_on_the_wall

  subroutine vehicle_write(self, file, status)
    class(vehicle_figures_t), intent(in) :: self
    type(result_file_t), intent(inout) :: file
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/sled/vehicle'
    integer :: k
    if (self%in_water) call write_water_results(file, self%water, self%water_result, status)
    ! the width check's verdict (docs/vehicles.md, "Does it fit?")
    call file%write_scalar(g//'/width', self%width, 'm', 'the vehicle''s width (across, the widest of vehicle '// &
                           'and riders)', status)
    if (self%fits_checked) then
      call file%write_scalar(g//'/narrowest_section', self%narrowest, 'm', 'the width of the slide''s narrowest '// &
                             'section across its bottom (the vehicle fits: not wider by more than 1 mm)', status)
      call file%write_scalar(g//'/narrowest_section_arc_length', self%narrowest_at, 'm', 'where', status)
    else
      call file%write_text(g//'/narrowest_section', 'not checked', 'the surface is not a slide (no sections)', &
                           status)
    end if
    if (allocated(self%verdicts)) call write_limit_verdicts(file, g//'/limits/', self%limits, self%verdicts, &
      self%judged, felt_acceleration_units(self%gravity), 'the vehicle did not reach the end of the slide', status)
    if (.not. allocated(self%speed)) return
    call file%write_vector(g//'/speed', self%speed, 'm/s', 'speed of the vehicle''s centre of mass', status)
    call file%write_matrix(g//'/felt_acceleration', self%felt, felt_acceleration_units(self%gravity), &
                           'felt acceleration (a - g)/|g| at the vehicle''s centre of mass along its x (forward), '// &
                           'y (left) and z (the normal) axes (3 x n; docs/vehicles.md)', status)
    if (allocated(self%wall_angle)) then
      do k = 1, 2
        call file%write_vector(g//'/'//trim(contact_names(k))//'/wall_angle', self%wall_angle(k, :), 'rad', &
                               'the '//trim(contact_names(k))//' contact''s angle up the wall: the slide''s normal '// &
                               'there from the bottom''s (signed, + to the left, +v)', status)
        call file%write_vector(g//'/'//trim(contact_names(k))//'/wall_distance', self%wall_distance(k, :), 'm', &
                               'its distance along the section from the bottom (signed)', status)
      end do
    end if
    if (self%vehicle%may_fly) then
      call write_flights(file, self%flights, g//'/flight/', status, vehicle_contact_names)
      if (allocated(self%open)) call file%write_integers(g//'/open', self%open, '1', 'the contacts open at each '// &
        'record: 0 none, 1 the rear, 2 the front, 3 both (the vehicle in the air; docs/vehicles.md, "Flight")', &
        status)
    end if
    call file%set_attribute(g, 'vehicle', trim(vehicle_kinds(self%vehicle%kind)), status)
    call file%attach_scale('/sled/time', g, status)
    ! the components' scale of the sled's vectors (written with its series)
    call file%attach_scale('/sled/xyz', g, status, axis=1)
  end subroutine vehicle_write

  subroutine vehicle_summarise(self, summary)
    class(vehicle_figures_t), intent(in) :: self
    type(summary_t), intent(inout) :: summary
    character(len=:), allocatable :: units
    character(len=*), parameter :: axes(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    character(len=:), allocatable :: unit, line, unset, quantity
    integer :: k, n, i, exceeded
    call summary%add('vehicle_width', 'vehicle width', self%width, 'm')
    if (self%in_water) then
      call summary%add_text('water', 'water', 'computed, '//format_short(self%water%flow_rate)//' m^3/s, '// &
                            outcome_name(self%water_result%series%outcome)//' (its drag at both contacts)')
    else
      call summary%add_text('water', 'water', 'none: the vehicle rides dry (&sled water = ''dry'')')
    end if
    if (self%fits_checked) then
      call summary%add('narrowest_section', 'narrowest section', self%narrowest, 'm', &
                       'm across its bottom, at arc length '//format_short(self%narrowest_at)//' m')
    else
      call summary%add_text('narrowest_section', 'narrowest section', 'not checked: the surface is not a slide')
    end if
    if (.not. allocated(self%speed)) return
    n = size(self%speed)
    if (n < 1) return
    units = felt_acceleration_units(self%gravity)
    call summary%add('vehicle_speed_max', 'vehicle top speed', maxval(self%speed), 'm/s', &
                     'm/s at '//format_short(self%time(maxloc(self%speed, dim=1)))//' s')
    call summary%add('vehicle_speed_final', 'vehicle final speed', self%speed(n), 'm/s')
    do k = 1, 3
      call summary%add_range('vehicle_felt_'//trim(axes(k)), 'felt '//trim(axes(k))//' min / max', &
                             minval(self%felt(k, :)), maxval(self%felt(k, :)), units, 'g')
    end do
    if (allocated(self%wall_angle)) then
      do k = 1, 2
        ! the steepest and the highest: apart on a vertical wall or a widening section
        i = maxloc(abs(self%wall_angle(k, :)), dim=1)
        call summary%add('vehicle_'//trim(contact_names(k))//'_wall_angle', trim(contact_names(k))// &
                         ' wall angle max', self%wall_angle(k, i)*180/pi, 'deg', 'deg at arc length '// &
                         format_short(self%where(i))//' m')
        i = maxloc(abs(self%wall_distance(k, :)), dim=1)
        call summary%add('vehicle_'//trim(contact_names(k))//'_wall_distance', trim(contact_names(k))// &
                         ' highest on the wall', self%wall_distance(k, i), 'm', 'm along the wall from the '// &
                         'bottom at arc length '//format_short(self%where(i))//' m')
      end do
    end if
    if (self%vehicle%may_fly) call add_flights(summary, self%flights, vehicle_contact_names)
    if (self%solve_switches > 0) call summary%add_count('front_closure_switches', 'front closure switches', &
      self%solve_switches, '(pitch <-> heading, by the normals; docs/vehicles.md, "Flight")')
    if (.not. allocated(self%verdicts)) return
    exceeded = 0
    do k = 1, size(self%limits)
      associate (l => self%limits(k), v => self%verdicts(k))
        unit = spaced_unit(limit_report_unit(l%quantity))
        if (.not. self%judged(k)) then
          line = 'limit '//l%quantity//': not judged (the vehicle did not reach the end of the slide)'
        else if (v%exceeded) then
          exceeded = exceeded + 1
          line = 'LIMIT EXCEEDED: '//l%quantity//' '//limit_bounds_text(l)//'; worst '//format_short(v%worst)//unit// &
                 ' at arc length '//format_short(v%worst_where)//' m (first at '//format_short(v%first_where)//' m)'
        else
          line = 'limit '//l%quantity//' '//limit_bounds_text(l)//': ok (closest '//format_short(v%worst)//unit// &
                 ' at arc length '//format_short(v%worst_where)//' m)'
        end if
      end associate
      call summary%add_line('  '//line)
    end do
    unset = ''
    do k = 1, size(vehicle_quantities) + merge(size(flight_quantities), 0, self%vehicle%may_fly)
      if (k <= size(vehicle_quantities)) then
        quantity = trim(vehicle_quantities(k))
      else
        quantity = trim(flight_quantities(k - size(vehicle_quantities)))
      end if
      if (any([(self%limits(i)%quantity == quantity, i = 1, size(self%limits))])) cycle
      if (len(unset) > 0) unset = unset//', '
      unset = unset//quantity
    end do
    if (len(unset) > 0) call summary%add_text('limits_not_set', 'no limit set for', unset)
    call summary%add_count('limits_exceeded', 'limits exceeded', exceeded, 'of the '// &
                           format_integer(size(self%limits))//' set')
  end subroutine vehicle_summarise
end module scenarios_sled
