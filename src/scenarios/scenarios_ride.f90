!> Scenario `ride`: slidesim's main job. The water first (its own &water_solver
!> tolerances), then the rider in it (&rider, &solver), then the evaluation of
!> the ride against the user's limits; one result file with /water, /rider
!> and /evaluation, and a ride report in engineering terms (docs/rider.md).
!> Every input is checked before any work, including whether the rider's
!> heels and back reach the slide at the start (read_ride_description: the
!> input as a ride description); the ride itself is the library's
!> (design_ride_job's run_ride), this module prints its report and writes
!> the XDMF view; the records in the file and the CSV are
!> scenarios_ride_results'.
module scenarios_ride
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_short, format_integer
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_LIMITS_EXCEEDED
  use base_log, only: log_info, log_warning
  use geometry_slide_query, only: slide_surface_t
  use water_run, only: water_description_t
  use water_curve_entry, only: curve_entry_note, splash_note
  use rider_model, only: rider_params_t, N_CONTACTS, contact_names, CONTACT_PELVIS, CONTACT_HEELS
  use rider_ride, only: ride_result_t, ride_series_t, ride_options_t, check_ride_start
  use design_ride_evaluation, only: limit_report_unit, limit_bounds_text, spaced_unit, ride_limit_t, &
    quantities_without_limit, noise_free, rider_size
  use design_ride_report, only: ride_report_t
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  use io_input, only: input_text_t, check_known_groups, format_real, invalid, where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config, apply_accuracy, check_output_count
  use io_geometry_config, only: geometry_groups
  use io_rider_config, only: read_rider_config, read_ride_gravity
  use io_evaluation_config, only: evaluation_config_t, read_evaluation_config
  use io_hdf5, only: result_file_t, run_message
  use io_water_results, only: write_water_results
  use io_summary, only: summary_t, degrees
  use io_xdmf, only: xdmf_t
  use scenarios_water, only: build_water, write_slide_grid
  use scenarios_ride_flights, only: add_flights
  use scenarios_ride_results, only: friction_name, write_ride, write_evaluation, write_ride_csv
  use scenarios_report, only: close_report, inlets_text
  use water_series, only: water_series_t
  implicit none (type, external)
  private
  public :: run_ride_scenario, read_ride_description, ride_groups, check_sphere_radii, read_limit_gate, &
    limits_exceeded_status, refuse_start, read_water_and_rider, set_ride_duration

  character(len=*), parameter :: ride_groups(14) = [character(len=14) :: 'run', 'solver', 'water_solver', &
    'surface', 'water', 'inlet', 'rider', 'evaluation', geometry_groups]
  !> numbers stored per output time of the ride (ride_series_t), for the memory bound
  integer, parameter :: values_per_output = 120
  !> Without &solver duration the ride runs until it ends (the slide's end,
  !> lift-off, a stall); as a safety bound it stops after this many times
  !> the time the slide takes at the stall speed.
  real(wp), parameter :: safety_factor = 10

contains

  subroutine run_ride_scenario(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(ride_description_t) :: description
    type(ride_job_result_t) :: result
    type(result_file_t) :: file
    type(status_t) :: write_status
    character(len=:), allocatable :: message, water_note
    logical :: complete, fail_on_limit
    integer :: k

    call read_ride_description(input, run, description, fail_on_limit, status)
    if (.not. status%ok() .or. run%check_only) return

    ! ---- the water, then the rider in it, then the report (design_ride_job)
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call file%write_provenance('ride', trim(run%title), input%name, input%text(), write_status)
    description%log => log_info
    result = run_ride(description)
    water_note = curve_entry_note(result%water%series, description%water%f3)
    if (len(water_note) > 0) call log_warning(input%name//': water: '//water_note)
    water_note = splash_note(result%water%series, description%water%f3)
    if (len(water_note) > 0) call log_warning(input%name//': water: '//water_note)
    associate (slide => description%water%slide, ride => result%ride, report => result%report)
      call write_water_results(file, description%water, result%water, write_status)
      call write_slide_grid(file, slide, write_status)
      if (result%ridden) then
        call write_ride(file, slide, ride, report, result%ride_cpu, friction_name(description%rider), write_status)
        call write_evaluation(file, ride, report, write_status)
      end if

      complete = result%status%ok() .and. write_status%ok()
      if (allocated(ride%outcome)) then
        message = run_message('ok: '//ride%outcome, result%status, write_status)
      else
        message = run_message('the water did not reach the rider', result%status, write_status)
      end if
      if (write_status%ok() .and. ride%series%n > 0) call write_xdmf(file, ride%series, report, write_status)
      call file%finish(complete, message, write_status)
      if (allocated(ride%outcome)) call print_report(ride, report, result%water_outcome, result%water_cpu, &
                                                     result%ride_cpu, file%final_path(), run, complete, message, &
                                                     write_status, description%water, result%water%series)
      ! the time series as CSV only for a complete run: a CSV cannot say it is cut short
      if (complete .and. write_status%ok() .and. allocated(run%ride_csv)) then
        if (len(run%ride_csv) > 0) call write_ride_csv(run%ride_csv, ride%series, report, ride%flights%watched, &
                                                        write_status)
      end if
      if (.not. result%status%ok()) then
        status = result%status
      else if (.not. write_status%ok()) then
        status = write_status
      else if (fail_on_limit .and. allocated(report%verdicts)) then
        call limits_exceeded_status(input%name, report%limits, &
                                    [(merge(1, 0, report%judged(k) .and. report%verdicts(k)%exceeded), &
                                      k = 1, size(report%limits))], .false., status)
      end if
    end associate
  end subroutine run_ride_scenario

  !> The ride an input describes (&surface or the slide's groups, &water,
  !> &water_solver, &rider, &solver, &evaluation), everything checked before
  !> any work: also that the spheres fit in the tube and that the rider's
  !> heels and back reach the slide at the start. `fail_on_limit`: whether a
  !> limit exceeded fails the run (&evaluation, --fail-on-limit in `run`).
  subroutine read_ride_description(input, run, description, fail_on_limit, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(ride_description_t), intent(out) :: description
    logical, intent(out) :: fail_on_limit
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver, defaults

    fail_on_limit = .false.
    call check_known_groups(input, ride_groups, status, repeatable=[character(len=5) :: 'inlet'])
    defaults%options = description%options%ode
    defaults%output_step = description%options%output_step
    call read_water_and_rider(input, defaults, .true., solver, description%water, description%rider, &
                              description%options, description%limits, status)
    if (status%ok()) call read_limit_gate(input, run, description%limits, fail_on_limit, status)
    if (.not. status%ok()) return
    associate (slide => description%water%slide, options => description%options)
      call check_sphere_radii(input, description%rider, slide, status)
      if (.not. status%ok()) return
      call set_ride_duration(input, solver, slide%length(), options, status)
      if (.not. status%ok()) return
      call check_ride_start(description%rider, slide, options, status)
      if (.not. status%ok()) then
        call refuse_start(input, description%rider, status)
        return
      end if
    end associate
  end subroutine read_ride_description

  !> The water and the rider of a ride, a sweep or a rider identification,
  !> read in one order: &solver (from `defaults`; with `presets` a preset of
  !> its accuracy sets both integrators' tolerances), the water (staged), one
  !> gravity for the water and the rider, the rider with its limits. Nothing
  !> is read after a failure.
  subroutine read_water_and_rider(input, defaults, presets, solver, water, rider, options, limits, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(in) :: defaults
    logical, intent(in) :: presets
    type(solver_config_t), intent(inout) :: solver
    type(water_description_t), intent(inout) :: water
    type(rider_params_t), intent(inout) :: rider
    type(ride_options_t), intent(inout) :: options
    type(ride_limit_t), allocatable, intent(inout) :: limits(:)
    type(status_t), intent(inout) :: status
    real(wp) :: gravity(3)   ! m/s^2
    if (status%ok()) call read_solver_config(input, solver, status, defaults=defaults, presets=presets)
    if (status%ok()) call build_water(input, water, status, stage=.true.)
    if (status%ok() .and. presets) call apply_accuracy(input, solver, water%solver%ode, status)
    if (status%ok()) call read_ride_gravity(input, gravity, status)
    if (status%ok()) water%gravity = gravity
    if (status%ok()) call read_rider_config(input, rider, options, limits, status, gravity)
  end subroutine read_water_and_rider

  !> A ride's integration from &solver: the integrator, the output step and
  !> the longest duration. The outputs of a duration the user gave are
  !> bounded before the run; without it the series grows with what the ride
  !> records (a safety bound on the time must not size, or refuse, a sound
  !> ride): `safety_factor` times the time the slide of `slide_length` (m)
  !> takes at the stall speed.
  subroutine set_ride_duration(input, solver, slide_length, options, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(in) :: solver
    real(wp), intent(in) :: slide_length
    type(ride_options_t), intent(inout) :: options
    type(status_t), intent(inout) :: status
    options%ode = solver%options
    options%output_step = solver%output_step
    options%max_duration = safety_factor*slide_length/options%min_speed
    if (solver%duration_given) then
      options%max_duration = solver%duration
      call check_output_count(input, solver, options%max_duration, values_per_output, 'ride', status)
    end if
  end subroutine set_ride_duration

  !> Whether a limit exceeded fails the run (exit status 4): --fail-on-limit
  !> or &evaluation fail_on_limit. Asked with no limit to judge, the run
  !> would pass whatever the ride did: refused.
  subroutine read_limit_gate(input, run, limits, fail_on_limit, status, limits_group)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(ride_limit_t), intent(in) :: limits(:)
    logical, intent(out) :: fail_on_limit
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: limits_group   ! the group of the limits ('rider')
    type(evaluation_config_t) :: evaluation
    character(len=:), allocatable :: group
    fail_on_limit = .false.
    group = 'rider'
    if (present(limits_group)) group = limits_group
    call read_evaluation_config(input, evaluation, status)
    if (.not. status%ok()) return
    fail_on_limit = evaluation%fail_on_limit .or. run%fail_on_limit
    if (fail_on_limit .and. size(limits) == 0) then
      if (evaluation%fail_on_limit) then
        call invalid(input, 'evaluation', 'fail_on_limit', '.true.', 'there is no limit to fail on: set '// &
                     'limits in &'//group//' (limit_quantity, limit_unit, limit_min or limit_max)', status)
      else
        call set_status(status, STATUS_INVALID_INPUT, input%name//': --fail-on-limit: there is no limit to '// &
                        'fail on: set limits in &'//group//' (limit_quantity, limit_unit, limit_min or limit_max)')
      end if
    end if
  end subroutine read_limit_gate

  !> STATUS_LIMITS_EXCEEDED naming the limits exceeded (exceeded(k) > 0:
  !> limit k, by that many rides of a sweep), or nothing when none is.
  subroutine limits_exceeded_status(name, limits, exceeded, sweep, status)
    character(len=*), intent(in) :: name
    type(ride_limit_t), intent(in) :: limits(:)
    integer, intent(in) :: exceeded(:)
    logical, intent(in) :: sweep
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: list
    integer :: k
    if (all(exceeded == 0)) return
    list = ''
    do k = 1, size(limits)
      if (exceeded(k) == 0) cycle
      if (len(list) > 0) list = list//', '
      list = list//format_integer(k)//' '//limits(k)%quantity
      if (sweep) list = list//' (in '//format_integer(exceeded(k))//' rides)'
    end do
    call set_status(status, STATUS_LIMITS_EXCEEDED, name//': limits exceeded: '//list// &
                    '; the results are complete (exit status 4: asked to fail on a limit)')
  end subroutine limits_exceeded_status

  !> A start the rider cannot take (a contact cannot reach the slide, a
  !> speed that does not carry it down) is bad input: refused where the
  !> start is given (&rider u0), with the values that make it.
  subroutine refuse_start(input, rider, status)
    type(input_text_t), intent(in) :: input
    type(rider_params_t), intent(in) :: rider
    type(status_t), intent(inout) :: status
    associate (p => rider)
      call set_status(status, STATUS_INVALID_INPUT, where_given(input, 'rider', 'u0')//': &rider: the start u0 = '// &
                      format_short(p%u0)//', v0 = '//format_short(p%v0)//', heading0_deg = '// &
                      format_short(p%heading0*180/pi)//', speed0 = '//format_short(p%speed0)//' (height = '// &
                      format_short(p%body%height)//' m): '//status%text())
    end associate
  end subroutine refuse_start

  !> The spheres must fit in the slide: none larger than the smallest radius
  !> of curvature across its bottom along the slide (the slide query's
  !> bottom_radius: a circle's radius; any other slide or section sampled
  !> from its surface). A bottom that cannot be read is refused with why.
  subroutine check_sphere_radii(input, rider, slide, status)
    type(input_text_t), intent(in) :: input
    type(rider_params_t), intent(in) :: rider
    class(slide_surface_t), intent(in) :: slide
    type(status_t), intent(inout) :: status
    type(status_t) :: st
    real(wp) :: room, u_at
    integer :: k
    if (.not. status%ok()) return
    call slide%bottom_radius(room, u_at, st)
    if (.not. st%ok()) then
      call invalid(input, 'rider', 'drag_radius', format_real(maxval(rider%drag_radius)), &
                   'the spheres'' room in the slide could not be checked: '//st%text(), status)
      return
    end if
    do k = 1, N_CONTACTS
      ! a sampled room carries rounding (~1e-15 relative): a sphere of the
      ! section's own radius fits
      if (rider%drag_radius(k) > room*(1 + 1e-9_wp)) then
        call invalid(input, 'rider', 'drag_radius('//format_integer(k)//')', &
                     format_real(rider%drag_radius(k)), 'the '//trim(contact_names(k))// &
                     ' sphere must fit in the slide: at most the radius of curvature across its bottom, '// &
                     format_short(room)//' m (the smallest, at '//format_short(slide%arc_length(u_at))// &
                     ' m of arc length)', status)
        return
      end if
    end do
  end subroutine check_sphere_radii

  !> XDMF next to the result: the slide, the water band, the contacts' paths
  !> (each with its own data and the rider's), the rider's posture line and
  !> its three bodies as boxes moving with it.
  subroutine write_xdmf(file, s, r, status)
    type(result_file_t), intent(inout) :: file
    type(ride_series_t), intent(in) :: s
    type(ride_report_t), intent(in) :: r
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    character(len=*), parameter :: contacts(3) = [character(len=22) :: &
      '/rider/pelvis/position', '/rider/heels/position', '/rider/back/position']
    integer :: k
    call xdmf%start()
    call xdmf%surface(file, 'slide surface', '/geometry/surface')
    call xdmf%band(file, 'water band', '/water/right_point', '/water/left_point', &
                   [character(len=13) :: '/water/speed', '/water/height'])
    do k = 1, N_CONTACTS
      call xdmf%polyline(file, trim(contact_names(k))//' path', '/rider/'//trim(contact_names(k))//'/position', &
                         '/rider/'//trim(contact_names(k)), more='/rider')
    end do
    ! heels - pelvis - back as one polyline per time step: the rider's posture
    call xdmf%moving_points(file, 'rider', s%time(:s%n), [contacts(2), contacts(1), contacts(3)], .true.)
    if (allocated(r%felt)) then
      if (size(r%felt, 2) >= s%n) call add_rider_bodies(xdmf, s, r)
    end if
    call xdmf%attach(file, status)
  end subroutine write_xdmf

  !> The rider's pelvis, legs (pelvis to heels) and trunk (pelvis to back)
  !> as boxes lying on the slide (their sizes are for the picture only):
  !> each with its contact's normal force and wall angle, and the rider's
  !> speed and felt acceleration.
  subroutine add_rider_bodies(xdmf, s, r)
    type(xdmf_t), intent(inout) :: xdmf
    type(ride_series_t), intent(in) :: s
    type(ride_report_t), intent(in) :: r
    real(wp), parameter :: pelvis_half(3) = [0.12_wp, 0.18_wp, 0.10_wp]   ! m
    real(wp), parameter :: legs_half(2) = [0.15_wp, 0.07_wp]   ! m, half width and thickness
    real(wp), parameter :: trunk_half(2) = [0.18_wp, 0.10_wp]
    character(len=*), parameter :: names(3) = [character(len=12) :: 'normal_force', 'wall_angle', 'speed']
    real(wp), allocatable :: centre(:, :), axes(:, :, :), scalars(:, :), vectors(:, :, :)
    real(wp) :: length(s%n)
    integer :: n, i, k, tip
    n = s%n
    allocate (centre(3, n), axes(3, 3, n), scalars(3, n), vectors(3, 1, n))
    vectors(:, 1, :) = r%felt(:, :n)
    do k = 1, N_CONTACTS
      scalars(1, :) = s%contact(k)%normal_force(:n)
      scalars(2, :) = s%contact(k)%wall_angle(:n)
      scalars(3, :) = s%speed(:n)
      if (k == CONTACT_PELVIS) then
        axes = s%pelvis_axes(:, :, :n)
        do i = 1, n
          centre(:, i) = s%contact(k)%position(:, i) + pelvis_half(3)*axes(:, 3, i)
        end do
        call xdmf%moving_box('rider pelvis', s%time(:n), centre, axes, pelvis_half, names, scalars, &
                             ['felt_acceleration_g'], vectors)
        cycle
      end if
      tip = k
      do i = 1, n
        call segment_axes(s%contact(CONTACT_PELVIS)%position(:, i), s%contact(tip)%position(:, i), &
                          s%pelvis_axes(:, 3, i), axes(:, :, i), length(i))
        centre(:, i) = 0.5_wp*(s%contact(CONTACT_PELVIS)%position(:, i) + s%contact(tip)%position(:, i))
      end do
      if (k == CONTACT_HEELS) then
        do i = 1, n
          centre(:, i) = centre(:, i) + legs_half(2)*axes(:, 3, i)
        end do
        call xdmf%moving_box('rider legs', s%time(:n), centre, axes, [0.5_wp*maxval(length), legs_half], &
                             names, scalars, ['felt_acceleration_g'], vectors)
      else
        do i = 1, n
          centre(:, i) = centre(:, i) + trunk_half(2)*axes(:, 3, i)
        end do
        call xdmf%moving_box('rider trunk', s%time(:n), centre, axes, [0.5_wp*maxval(length), trunk_half], &
                             names, scalars, ['felt_acceleration_g'], vectors)
      end if
    end do
  end subroutine add_rider_bodies

  !> Axes of a body from `a` to `b` lying on a surface of normal `normal`:
  !> x along a -> b, z the normal's part across x, y = z x x; `length` |b - a|.
  pure subroutine segment_axes(a, b, normal, axes, length)
    real(wp), intent(in) :: a(3), b(3), normal(3)
    real(wp), intent(out) :: axes(3, 3), length
    length = norm2(b - a)
    axes(:, 1) = (b - a)/max(length, tiny(1.0_wp))
    axes(:, 3) = normal - dot_product(normal, axes(:, 1))*axes(:, 1)
    axes(:, 3) = axes(:, 3)/max(norm2(axes(:, 3)), tiny(1.0_wp))
    axes(:, 2) = [axes(2, 3)*axes(3, 1) - axes(3, 3)*axes(2, 1), axes(3, 3)*axes(1, 1) - axes(1, 3)*axes(3, 1), &
                  axes(1, 3)*axes(2, 1) - axes(2, 3)*axes(1, 1)]
  end subroutine segment_axes

  !> The ride report (stdout) and, with --summary-json, its numbers as JSON.
  subroutine print_report(ride, r, water_done, water_cpu, ride_cpu, path, run, complete, message, status, water, &
                          water_series)
    type(ride_result_t), intent(in) :: ride
    type(water_description_t), intent(in) :: water   !< the slide ridden: named in the report
    type(water_series_t), intent(in) :: water_series   !< its water: the inlets named in the report
    type(ride_report_t), intent(in) :: r
    character(len=*), intent(in) :: water_done, path, message
    real(wp), intent(in) :: water_cpu, ride_cpu
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    character(len=*), parameter :: axis(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    character(len=:), allocatable :: c, line, unit, unset
    integer :: k, exceeded
    real(wp) :: felt_min(3), felt_max(3), force_scale
    call summary%start('ride', 'slidesim ride')
    if (allocated(water%slide_name)) call summary%add_text('slide', 'slide', water%slide_name)
    call summary%add('slide_length', 'slide centreline length', water%slide%length(), 'm')
    if (len(inlets_text(water_series)) > 0) then
      ! the start's flow and the end's, the inlets joined (the ride's water)
      call summary%add_text('water', 'water', water_done//'; '//format_short(water_series%flow(1))//' m^3/s'// &
                            inlets_text(water_series))
    else
      call summary%add_text('water', 'water', water_done)
    end if
    call summary%add_text('outcome', 'ride ended', ride%outcome)
    if (r%ejected_contact > 0) then
      call summary%add_text('ejected', 'EJECTED', 'the '//trim(contact_names(r%ejected_contact))// &
                            ' went over the top of a wall')
      call summary%add('ejected_arc_length', '  at arc length', r%ejected_at, 'm')
    end if
    if (r%n > 0) then
      call summary%add('ride_time', 'ride time', r%ride_time, 's')
      call summary%add('distance', 'slide length ridden', r%distance, 'm')
      call summary%add('top_speed', 'top speed', r%top_speed, 'm/s')
      call summary%add('top_speed_arc_length', '  at arc length', r%top_speed_at, 'm')
      ! longitudinal: in words, braking (the slide and water push towards the
      ! head, f < 0) and pushing (towards the feet, f > 0), printed >= 0; the
      ! JSON keeps the signed values (felt_longitudinal_max, _min)
      ! rounding noise (design_ride_evaluation's noise_free) prints as 0,
      ! without a direction: felt g on the scale of 1 g, normal forces on
      ! the ride's largest, the lever arm on the rider's size
      felt_min = noise_free(r%felt_min, 1.0_wp)
      felt_max = noise_free(r%felt_max, 1.0_wp)
      force_scale = max(maxval([(abs(ride%series%contact(k)%normal_force(:r%n)), k = 1, N_CONTACTS)]), tiny(1.0_wp))
      if (felt_min(1) < 0) then
        call summary%add('felt_longitudinal_min', 'felt braking max', felt_min(1), r%felt_units, 'g', -1.0_wp)
      else
        call summary%add('felt_longitudinal_min', 'felt pushing min', felt_min(1), '1', 'g (never braked)')
      end if
      call summary%add('felt_longitudinal_min_arc_length', '  at arc length', r%felt_min_at(1), 'm')
      if (felt_max(1) > 0) then
        call summary%add('felt_longitudinal_max', 'felt pushing max', felt_max(1), r%felt_units, 'g')
      else
        call summary%add('felt_longitudinal_max', 'felt braking min', felt_max(1), r%felt_units, &
                         trim(merge('g (braked all the way)', 'g                     ', felt_max(1) < 0)), -1.0_wp)
      end if
      call summary%add('felt_longitudinal_max_arc_length', '  at arc length', r%felt_max_at(1), 'm')
      do k = 2, 3
        c = trim(axis(k))
        call summary%add('felt_'//c//'_max', 'felt '//c//' max', felt_max(k), r%felt_units, &
                         'g'//sense(k, felt_max(k)))
        call summary%add('felt_'//c//'_max_arc_length', '  at arc length', r%felt_max_at(k), 'm')
        call summary%add('felt_'//c//'_min', 'felt '//c//' min', felt_min(k), r%felt_units, &
                         'g'//sense(k, felt_min(k)))
        call summary%add('felt_'//c//'_min_arc_length', '  at arc length', r%felt_min_at(k), 'm')
      end do
      do k = 1, N_CONTACTS
        c = trim(contact_names(k))
        call summary%add(c//'_wall_angle', c//' steepest on the wall', resolved(k, r%climb_angle(k)), 'rad', &
                         'deg from the bottom'//side(resolved(k, r%climb_angle(k))), degrees)
        call summary%add(c//'_wall_arc_length', '  at arc length', r%climb_at(k), 'm')
        call summary%add(c//'_wall_distance', c//' highest on the wall', &
                         resolved_distance(r%wall_distance_max(k)), 'm', &
                         'm along the wall from the bottom'//side(resolved_distance(r%wall_distance_max(k))))
        call summary%add(c//'_wall_distance_arc_length', '  at arc length', r%wall_distance_at(k), 'm')
        call summary%add(c//'_normal_force_min', c//' normal force min', noise_free(r%normal_min(k), force_scale), 'N')
        call summary%add(c//'_normal_force_min_arc_length', '  at arc length', r%normal_min_at(k), 'm')
      end do
      call summary%add('lever_arm_max', 'largest tipping lever arm', noise_free(r%lever_max, rider_size), 'm')
      call summary%add('lever_arm_max_arc_length', '  at arc length', r%lever_max_at, 'm')
      ! with may_fly: what the felt figures and the lever arm leave out (rider_extremes' felt_basis)
      if (ride%flights%watched) call summary%add('felt_not_judged_time', 'felt g not judged', r%not_judged_time, &
        's', 's with the pelvis in the air or alone on the slide (the model holds its attitude there: not what '// &
        'a rider feels); the whole rider in the air counts as 0 g (docs/rider.md)')
      if (ride%complete) then
        call summary%add('exit_speed', 'exit speed (end of the slide)', r%final_speed, 'm/s')
      else
        call summary%add('final_speed', 'speed at the stop', r%final_speed, 'm/s')
      end if
      if (ride%flights%watched) call add_flights(summary, ride%flights)
      exceeded = 0
      do k = 1, size(r%limits)
        unit = spaced_unit(limit_report_unit(r%limits(k)%quantity))
        if (.not. r%judged(k)) then
          line = 'limit '//r%limits(k)%quantity//': not judged (the ride did not reach the exit)'
        else if (r%verdicts(k)%exceeded) then
          exceeded = exceeded + 1
          line = 'LIMIT EXCEEDED: '//r%limits(k)%quantity//' '//limit_bounds_text(r%limits(k))//'; worst '// &
                 format_short(r%verdicts(k)%worst)//unit//' at arc length '// &
                 format_short(r%verdicts(k)%worst_where)//' m (first at '// &
                 format_short(r%verdicts(k)%first_where)//' m)'
        else
          line = 'limit '//r%limits(k)%quantity//' '//limit_bounds_text(r%limits(k))//': ok (closest '// &
                 format_short(r%verdicts(k)%worst)//unit//' at arc length '// &
                 format_short(r%verdicts(k)%worst_where)//' m)'
        end if
        call summary%add_line('  '//line)
      end do
      unset = quantities_without_limit(r%limits, ride%flights%watched)
      if (len(unset) > 0) call summary%add_text('limits_not_set', 'no limit set for', unset)
      call summary%add_count('limits_exceeded', 'limits exceeded', exceeded, 'of the '// &
                             format_integer(size(r%limits))//' set')
    end if
    call summary%add('water_cpu_time', 'CPU time water', water_cpu, 's')
    call summary%add('ride_cpu_time', 'CPU time rider', ride_cpu, 's')
    call summary%add_count('ride_steps', 'integrator', int(ride%driver%stats%steps), 'steps')
    call close_report(summary, run, path, complete, message, status)

  contains

    !> A climb of contact k as printed: 0 where the contact stayed within the
    !> closure's tolerance of the bottom (unresolved); the file keeps the
    !> computed value.
    pure real(wp) function resolved(k, climb)
      integer, intent(in) :: k
      real(wp), intent(in) :: climb
      resolved = merge(0.0_wp, climb, unresolved(r%climb_distance(k)))
    end function resolved

    !> A distance up the wall as printed: 0 where unresolved.
    pure real(wp) function resolved_distance(distance)
      real(wp), intent(in) :: distance
      resolved_distance = merge(0.0_wp, distance, unresolved(distance))
    end function resolved_distance

    !> Within the closure's tolerance (1e-10 m, mechanism_t's
    !> closure_tolerance) of the bottom, which a position solved to that
    !> tolerance does not resolve (rounding noise such as 5e-14 deg on a
    !> straight slide).
    pure logical function unresolved(distance)
      real(wp), intent(in) :: distance
      real(wp), parameter :: closure_tolerance = 1e-10_wp   ! m
      unresolved = abs(distance) < closure_tolerance
    end function unresolved

    !> What the sign of a felt acceleration along axis k (2 lateral, 3 normal) means.
    pure function sense(k, value) result(text)
      integer, intent(in) :: k
      real(wp), intent(in) :: value
      character(len=:), allocatable :: text
      text = ''
      if (k == 3 .and. value == 0) text = ', weightless'
      if (value == 0) return
      if (k == 2) text = trim(merge(', pushed to the left ', ', pushed to the right', value > 0))
      if (k == 3) text = trim(merge(', pressed onto the slide', ', pulled off the slide  ', value > 0))
    end function sense

    !> The side of the slide a signed wall angle (+ towards +v) lies on.
    pure function side(angle) result(text)
      real(wp), intent(in) :: angle
      character(len=:), allocatable :: text
      text = ''
      if (angle > 0) text = ', on the left'
      if (angle < 0) text = ', on the right'
    end function side

  end subroutine print_report
end module scenarios_ride
