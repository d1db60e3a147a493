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
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use base_constants, only: pi
  use geometry_slide_query, only: slide_surface_t
  use design_ride_evaluation, only: ride_limit_t, limit_report_unit, limit_bounds_text, spaced_unit
  use io_input, only: group_reader_t, open_group
  use io_friction_config, only: friction_law_variables
  use io_rider_config, only: read_limits
  use scenarios_ride, only: read_limit_gate, limits_exceeded_status
  use base_text, only: format_integer
  use kinetostatics_models, only: sled_description_t
  use rider_vehicle, only: vehicle_t, build_vehicle_model, vehicle_kinds, VEHICLE_BAR
  use rider_vehicle_flight, only: vehicle_contact_names, vehicle_units
  use design_vehicle_ride, only: vehicle_ride_description_t, vehicle_ride_t, build_vehicle_ride, run_vehicle_ride, &
    vehicle_quantities, flight_quantities, FAILED_REFUSED, FAILED_WATER, FAILED_START
  use scenarios_ride_flights, only: add_flights, write_flights
  use design_ride_evaluation, only: felt_acceleration_units
  use io_hdf5, only: result_file_t, run_outcome
  use io_summary, only: summary_t
  use base_text, only: format_short
  use io_input, only: input_text_t, check_known_groups, invalid, format_real, mark_input_failure
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config, check_output_count
  use io_surface_config, only: read_surface_config, surface_source_t, explain_surface_failure, start_domain_words
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use io_geometry_config, only: geometry_groups
  use scenarios_mechanism, only: run_mechanism, run_figures_t, mechanism_driver_options, refuse_start, &
    values_per_record, open_run_file, write_mechanism_run
  use scenarios_ride_results, only: write_limit_verdicts
  use scenarios_water, only: build_water
  use scenarios_report, only: inlets_text
  use water_run, only: water_description_t, water_result_t
  use water_flow, only: outcome_name
  use io_water_results, only: write_water_results
  use io_input, only: group_present, where_given
  use geometry_tube, only: tube_surface_t
  use base_log, only: log_warning
  use water_curve_entry, only: curve_entry_note, splash_note
  use base_status, only: set_status, prefix_status, STATUS_INVALID_INPUT
  implicit none (type, external)
  private
  public :: run_sled, sled_groups

  character(len=*), parameter :: sled_groups(14) = [character(len=14) :: 'run', 'solver', 'surface', 'sled', &
    'evaluation', 'water', 'water_solver', 'inlet', geometry_groups]
  !> the groups of the water a vehicle rides in (scenarios_water's build_water)
  character(len=*), parameter :: water_only_groups(3) = [character(len=12) :: 'water', 'water_solver', 'inlet']
  character(len=*), parameter :: contact_names(2) = [character(len=5) :: 'rear', 'front']
  !> &sled's start, named when the model refuses it
  character(len=*), parameter :: start_words = 'u0, v0, phi0, du0, dv0, dphi0'

  !> A vehicle's ride (design_vehicle_ride: the library's, which builds,
  !> runs and judges it) as the command writes it into /sled/vehicle and
  !> the summary (docs/vehicles.md, "What the run reports"). A target that
  !> stays put: the ride's drag laws point at its water.
  type, extends(run_figures_t) :: vehicle_report_t
    type(vehicle_ride_description_t) :: description
    type(vehicle_ride_t) :: ride
  contains
    procedure :: write => vehicle_write
    procedure :: summarise => vehicle_summarise
  end type vehicle_report_t

contains

  subroutine run_sled(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(sled_description_t) :: config
    type(vehicle_t) :: vehicle
    type(vehicle_report_t), target :: report   ! its ride's water: the drag laws of its model point at it
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    character(len=:), allocatable :: u_units, v_units
    character(len=8) :: q_units(3), beta_units(3)
    real(wp), allocatable :: q0(:), qd0(:)
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: surface_source
    type(status_t) :: built
    character(len=:), allocatable :: part, variable
    logical :: fail_on_limit

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
    call read_vehicle_limits(input, run, vehicle, config, surface, report%description%limits, fail_on_limit, status)
    if (status%ok()) call read_vehicle_water(input, vehicle, config, surface, report%description%water, status)
    if (.not. status%ok()) return
    call surface%parameter_units(u_units, v_units)
    q_units(1) = u_units; q_units(2) = v_units; q_units(3) = 'rad'   ! u, v, phi
    beta_units(1) = 'rad'; beta_units(2) = u_units; beta_units(3) = v_units   ! pitch, u2, v2
    if (vehicle%kind /= VEHICLE_BAR) then
      report%description%vehicle = vehicle
      report%description%sled = config
      report%description%driver = mechanism_driver_options('sled', solver)
      call move_alloc(surface, report%description%surface)
      call ride_vehicle(input, run, solver, report, q_units, beta_units, fail_on_limit, status)
      return
    end if
    ! the plain bar: the sled of kinetostatics_models, no ride figures
    call build_vehicle_model(vehicle, config, surface, sys%mechanism, q0, qd0, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    call run_mechanism('sled', input, run, solver, sys, q0, qd0, q_units, beta_units, status, surface=surface, &
                       start_variables=start_words)
  end subroutine run_sled

  !> A vehicle's ride through the library (design_vehicle_ride): built (a
  !> check, --check, builds it dry: the water is work), its start and its
  !> records' size checked before the file is opened, run, then written and
  !> summarised; a refusal of the library's named at the input's variable.
  subroutine ride_vehicle(input, run, solver, report, q_units, beta_units, fail_on_limit, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(solver_config_t), intent(in) :: solver
    type(vehicle_report_t), intent(inout), target :: report
    character(len=*), intent(in) :: q_units(:), beta_units(:)
    logical, intent(in) :: fail_on_limit
    type(status_t), intent(inout) :: status
    type(result_file_t) :: file
    character(len=8), allocatable :: units(:), dependent_units(:)
    integer, allocatable :: open(:, :)   ! none: not a contact's flight
    integer :: k
    associate (d => report%description, ride => report%ride)
      call build_vehicle_ride(d, ride, dry=run%check_only)
      ! the water's notes (water_curve_entry), as the ride warns of them
      if (d%vehicle%in_water .and. .not. run%check_only .and. (ride%status%ok() .or. ride%failed > FAILED_WATER)) then
        call warn(curve_entry_note(ride%water%series, d%water%f3))
        call warn(splash_note(ride%water%series, d%water%f3))
      end if
      if (.not. ride%status%ok()) then
        status = ride%status
        select case (ride%failed)
        case (FAILED_REFUSED)
          if (ride%refused == 'vehicle' .or. ride%refused == 'water') then
            status = status_t()
            if (ride%refused == 'vehicle') then
              call invalid(input, 'sled', 'vehicle', "'"//trim(vehicle_kinds(d%vehicle%kind))//"'", &
                           ride%status%message, status)
            else
              call invalid(input, 'sled', 'water', "'computed'", ride%status%message, status)
            end if
          end if
          call mark_input_failure(status)
        case (FAILED_WATER)
          call prefix_status(status, input%name)
          call keep_failed_water(input, run, d%water, ride%water, status)
        case (FAILED_START)
          call refuse_start('sled', input, status, start_words)
        case default
          call mark_input_failure(status)
        end select
        return
      end if
      call check_output_count(input, solver, solver%duration, values_per_record(ride%model()), 'sled', status)
      if (.not. status%ok() .or. run%check_only) return
      call open_run_file('sled', run, solver, file, status)
      if (.not. status%ok()) return
      call run_vehicle_ride(d, ride)
      units = q_units
      dependent_units = beta_units
      ! a flight's: the units of the joined records by their names (u, v the first two's)
      if (ride%flies) call vehicle_units(ride%flying%series, q_units(1), q_units(2), units, dependent_units)
      call write_mechanism_run('sled', input, run, ride%model(), file, ride%driven, ride%status, ride%outcome, units, &
                               dependent_units, open, status, surface=d%surface, figures=report)
      if (status%ok() .and. fail_on_limit .and. allocated(ride%verdicts)) &
        call limits_exceeded_status(input%name, d%limits, [(merge(1, 0, ride%judged(k) .and. &
                                    ride%verdicts(k)%exceeded), k = 1, size(d%limits))], .false., status)
    end associate

  contains

    !> A note on the water, as the ride warns of it.
    subroutine warn(note)
      character(len=*), intent(in) :: note
      if (len(note) > 0) call log_warning(input%name//': water: '//note)
    end subroutine warn
  end subroutine ride_vehicle

  !> &sled's limits (limit_quantity, limit_unit, limit_min, limit_max, read
  !> as &rider's) and whether one exceeded fails the run (&evaluation
  !> fail_on_limit, --fail-on-limit: exit status 4). Only a vehicle's ride is
  !> judged, on a slide (where: the rear contact's arc length), on the
  !> quantities it has (vehicle_quantities); the others are refused, naming
  !> why (docs/vehicles.md, "Limits").
  subroutine read_vehicle_limits(input, run, vehicle, config, surface, limits, fail_on_limit, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(vehicle_t), intent(in) :: vehicle
    type(sled_description_t), intent(in) :: config
    class(surface_t), intent(in) :: surface
    type(ride_limit_t), allocatable, intent(inout) :: limits(:)
    logical, intent(out) :: fail_on_limit
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    integer :: k
    fail_on_limit = .false.
    call open_group(input, 'sled', r, status, also=friction_law_variables())
    call read_limits(r, norm2(config%params%gravity), .true., limits, status)
    if (.not. status%ok()) return
    if (size(limits) > 0 .and. vehicle%kind == VEHICLE_BAR) then
      call r%invalid('limit_quantity', r%written('limit_quantity'), 'limits judge a vehicle''s ride (docs/'// &
                     'vehicles.md, "Limits"): the bar has no ride figures; give vehicle', status)
      return
    end if
    do k = 1, size(limits)
      if (any(vehicle_quantities == limits(k)%quantity)) cycle
      if (vehicle%may_fly .and. any(flight_quantities == limits(k)%quantity)) cycle
      if (any(flight_quantities == limits(k)%quantity)) then
        call r%invalid('limit_quantity('//format_integer(k)//')', ''''//limits(k)%quantity//'''', &
                       limits(k)%quantity//' limits a flight: it needs may_fly = .true. (without it a '// &
                       'lift-off ends the run; docs/vehicles.md, "Limits")', status)
        return
      end if
      call r%invalid('limit_quantity('//format_integer(k)//')', ''''//limits(k)%quantity//'''', &
                     'a vehicle''s ride is judged on speed, exit_speed, acceleration_longitudinal, '// &
                     'acceleration_lateral, acceleration_normal, normal_force, wall_angle, wall_distance and '// &
                     'ejection, and with may_fly on airtime and drop_height; '// &
                     limits(k)%quantity//' belongs to the body-slide rider (its tipping: '// &
                     'docs/vehicles.md, "Limits")', status)
      return
    end do
    if (size(limits) > 0) then
      select type (surface)
      class is (slide_surface_t)
      class default
        call r%invalid('limit_quantity', r%written('limit_quantity'), 'limits are judged along a slide (at '// &
                       'arc lengths); the '//surface%describe()//' is not one', status)
        return
      end select
    end if
    call read_limit_gate(input, run, limits, fail_on_limit, status, limits_group='sled')
  end subroutine read_vehicle_limits

  !> A water that failed before the vehicle rode: the result file with
  !> its provenance and /water as far as it ran, marked incomplete (exit
  !> status 2 keeps a file, as the ride's).
  subroutine keep_failed_water(input, run, water, water_result, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(water_description_t), intent(in) :: water
    type(water_result_t), intent(in) :: water_result
    type(status_t), intent(inout) :: status
    type(result_file_t) :: file
    type(status_t) :: write_status
    call file%create(trim(run%output), write_status)
    if (write_status%ok()) then
      call file%write_provenance('sled', trim(run%title), input%name, input%text(), write_status)
      call write_water_results(file, water, water_result, write_status)
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
  subroutine read_vehicle_water(input, vehicle, config, surface, water, status)
    type(input_text_t), intent(in) :: input
    type(vehicle_t), intent(in) :: vehicle
    type(sled_description_t), intent(in) :: config
    class(surface_t), intent(in) :: surface
    type(water_description_t), intent(inout) :: water
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=:), allocatable :: given, why
    integer :: k
    if (.not. status%ok()) return
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
    call build_water(input, water, status, stage=.true.)
    if (.not. status%ok()) return
    ! (the drag's spheres must fit in the slide: design_vehicle_ride refuses them)
    if (any(water%gravity /= config%params%gravity)) then
      call open_group(input, 'water', r, status)
      call r%invalid('gravity', r%written('gravity'), 'a ride has one gravity, and &sled''s is '// &
                     format_real(config%params%gravity(1))//', '//format_real(config%params%gravity(2))//', '// &
                     format_real(config%params%gravity(3))//' m/s^2: give it in &sled only, or the same in both', &
                     status)
    end if
  end subroutine read_vehicle_water

  subroutine vehicle_write(self, file, status)
    class(vehicle_report_t), intent(in) :: self
    type(result_file_t), intent(inout) :: file
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/sled/vehicle'
    integer :: k
    associate (d => self%description, ride => self%ride)
      if (d%vehicle%in_water) call write_water_results(file, d%water, ride%water, status)
      ! the width check's verdict (docs/vehicles.md, "Does it fit?")
      call file%write_scalar(g//'/width', ride%width, 'm', 'the vehicle''s width (across, the widest of vehicle '// &
                             'and riders)', status)
      if (ride%fits_checked) then
        call file%write_scalar(g//'/narrowest_section', ride%narrowest, 'm', 'the width of the slide''s narrowest '// &
                               'section across its bottom (the vehicle fits: not wider by more than 1 mm)', status)
        call file%write_scalar(g//'/narrowest_section_arc_length', ride%narrowest_at, 'm', 'where', status)
      else
        call file%write_text(g//'/narrowest_section', 'not checked', 'the surface is not a slide (no sections)', &
                             status)
      end if
      if (allocated(ride%verdicts)) call write_limit_verdicts(file, g//'/limits/', d%limits, ride%verdicts, &
        ride%judged, felt_acceleration_units(d%sled%params%gravity), 'the vehicle did not reach the end of the slide', &
        status)
      if (.not. allocated(ride%speed)) return
      call file%write_vector(g//'/speed', ride%speed, 'm/s', 'speed of the vehicle''s centre of mass', status)
      call file%write_matrix(g//'/felt_acceleration', ride%felt, felt_acceleration_units(d%sled%params%gravity), &
                             'felt acceleration (a - g)/|g| at the vehicle''s centre of mass along its x (forward), '// &
                             'y (left) and z (the normal) axes (3 x n; docs/vehicles.md)', status)
      if (allocated(ride%wall_angle)) then
        do k = 1, 2
          call file%write_vector(g//'/'//trim(contact_names(k))//'/wall_angle', ride%wall_angle(k, :), 'rad', &
                                 'the '//trim(contact_names(k))//' contact''s angle up the wall: the slide''s normal '// &
                                 'there from the bottom''s (signed, + to the left, +v)', status)
          call file%write_vector(g//'/'//trim(contact_names(k))//'/wall_distance', ride%wall_distance(k, :), 'm', &
                                 'its distance along the section from the bottom (signed)', status)
        end do
      end if
      if (d%vehicle%may_fly) then
        call write_flights(file, ride%flights, g//'/flight/', status, vehicle_contact_names)
        if (allocated(ride%open)) call file%write_integers(g//'/open', ride%open, '1', 'the contacts open at each '// &
          'record: 0 none, 1 the rear, 2 the front, 3 both (the vehicle in the air; docs/vehicles.md, "Flight")', &
          status)
      end if
      call file%set_attribute(g, 'vehicle', trim(vehicle_kinds(d%vehicle%kind)), status)
      call file%attach_scale('/sled/time', g, status)
      ! the components' scale of the sled's vectors (written with its series)
      call file%attach_scale('/sled/xyz', g, status, axis=1)
    end associate
  end subroutine vehicle_write

  subroutine vehicle_summarise(self, summary)
    class(vehicle_report_t), intent(in) :: self
    type(summary_t), intent(inout) :: summary
    character(len=:), allocatable :: units
    character(len=*), parameter :: axes(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    character(len=:), allocatable :: unit, line, unset, quantity
    integer :: k, n, i, exceeded
    associate (d => self%description, ride => self%ride)
      call summary%add('vehicle_width', 'vehicle width', ride%width, 'm')
      if (d%vehicle%in_water) then
        call summary%add_text('water', 'water', 'computed, '//format_short(d%water%flow_rate)//' m^3/s'// &
                              inlets_text(ride%water%series)//', '//outcome_name(ride%water%series%outcome)// &
                              ' (its drag at both contacts)')
      else
        call summary%add_text('water', 'water', 'none: the vehicle rides dry (&sled water = ''dry'')')
      end if
      if (ride%fits_checked) then
        call summary%add('narrowest_section', 'narrowest section', ride%narrowest, 'm', &
                         'm across its bottom, at arc length '//format_short(ride%narrowest_at)//' m')
      else
        call summary%add_text('narrowest_section', 'narrowest section', 'not checked: the surface is not a slide')
      end if
      if (.not. allocated(ride%speed)) return
      n = size(ride%speed)
      if (n < 1) return
      units = felt_acceleration_units(d%sled%params%gravity)
      call summary%add('vehicle_speed_max', 'vehicle top speed', maxval(ride%speed), 'm/s', &
                       'm/s at '//format_short(ride%time(maxloc(ride%speed, dim=1)))//' s')
      call summary%add('vehicle_speed_final', 'vehicle final speed', ride%speed(n), 'm/s')
      do k = 1, 3
        call summary%add_range('vehicle_felt_'//trim(axes(k)), 'felt '//trim(axes(k))//' min / max', &
                               minval(ride%felt(k, :)), maxval(ride%felt(k, :)), units, 'g')
      end do
      if (allocated(ride%wall_angle)) then
        do k = 1, 2
          ! the steepest and the highest: apart on a vertical wall or a widening section
          i = maxloc(abs(ride%wall_angle(k, :)), dim=1)
          call summary%add('vehicle_'//trim(contact_names(k))//'_wall_angle', trim(contact_names(k))// &
                           ' wall angle max', ride%wall_angle(k, i)*180/pi, 'deg', 'deg at arc length '// &
                           format_short(ride%where(i))//' m')
          i = maxloc(abs(ride%wall_distance(k, :)), dim=1)
          call summary%add('vehicle_'//trim(contact_names(k))//'_wall_distance', trim(contact_names(k))// &
                           ' highest on the wall', ride%wall_distance(k, i), 'm', 'm along the wall from the '// &
                           'bottom at arc length '//format_short(ride%where(i))//' m')
        end do
      end if
      if (d%vehicle%may_fly) call add_flights(summary, ride%flights, vehicle_contact_names)
      if (ride%solve_switches > 0) call summary%add_count('front_closure_switches', 'front closure switches', &
        ride%solve_switches, '(pitch <-> heading, by the normals; docs/vehicles.md, "Flight")')
      if (.not. allocated(ride%verdicts)) return
      exceeded = 0
      do k = 1, size(d%limits)
        associate (l => d%limits(k), v => ride%verdicts(k))
          unit = spaced_unit(limit_report_unit(l%quantity))
          if (.not. ride%judged(k)) then
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
      do k = 1, size(vehicle_quantities) + merge(size(flight_quantities), 0, d%vehicle%may_fly)
        if (k <= size(vehicle_quantities)) then
          quantity = trim(vehicle_quantities(k))
        else
          quantity = trim(flight_quantities(k - size(vehicle_quantities)))
        end if
        if (any([(d%limits(i)%quantity == quantity, i = 1, size(d%limits))])) cycle
        if (len(unset) > 0) unset = unset//', '
        unset = unset//quantity
      end do
      if (len(unset) > 0) call summary%add_text('limits_not_set', 'no limit set for', unset)
      call summary%add_count('limits_exceeded', 'limits exceeded', exceeded, 'of the '// &
                             format_integer(size(d%limits))//' set')
    end associate
  end subroutine vehicle_summarise
end module scenarios_sled
