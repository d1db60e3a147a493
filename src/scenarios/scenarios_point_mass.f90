!> Scenario `point_mass`: a point mass sliding under gravity on an elementary
!> surface placed anywhere in space, optionally with friction (any friction law
!> of the core's registry: viscous, Coulomb, ...).
module scenarios_point_mass
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use base_log, only: log_info, log_warning
  use base_text, only: format_short, format_integer
  use numerics_ode, only: ode_stats_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, DRIVE_EVENT_STOP
  use geometry_surface, only: surface_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_series_t, point_mass_description_t, &
    build_point_mass_model
  use io_input, only: input_text_t, check_known_groups, invalid, format_real, mark_input_failure, where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config, check_output_count
  use io_surface_config, only: read_surface_config, surface_source_t, explain_surface_failure, start_domain_words
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_geometry_config, only: geometry_groups
  use io_point_mass_config, only: read_point_mass_config
  use io_hdf5, only: result_file_t, run_outcome, run_message, units_per_second
  use io_summary, only: summary_t, standard_g, engineering
  use io_surface_grid, only: write_surface_grid_around
  use io_xdmf, only: xdmf_t
  use scenarios_report, only: end_report, add_run_cost
  implicit none (type, external)
  private
  public :: run_point_mass, build_point_mass, point_mass_groups

  character(len=*), parameter :: point_mass_groups(10) = [character(len=14) :: &
    'run', 'solver', 'surface', 'point_mass', geometry_groups]
  !> numbers stored per output time (point_mass_series_t)
  integer, parameter :: values_per_output = 35
  !> Runaway guard: a mean step below 1e-4 s after the driver's guard_steps
  !> steps. The shipped inputs take mean steps of 1e-3 s or more; a mass at
  !> rest under regularized Coulomb friction with Adams takes microseconds.
  real(wp), parameter :: min_mean_step = 1e-4_wp

contains

  !> Reads and checks every input group into the description, which the
  !> kinetostatics layer builds (build_point_mass_model); nothing is written.
  subroutine build_point_mass(input, solver, model, y0, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(out) :: solver
    type(point_mass_t), intent(out) :: model
    real(wp), allocatable, intent(out) :: y0(:)   ! [u, v, u', v', W] (+ the drag's work W_d, kinetostatics_point_mass)
    type(status_t), intent(inout) :: status
    type(point_mass_description_t) :: description
    class(surface_t), allocatable :: surface
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: surface_source
    type(status_t) :: built
    character(len=:), allocatable :: part, variable

    call check_known_groups(input, point_mass_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_surface_config(input, surface_description, status, surface_source)
    if (status%ok()) call build_surface(surface_description, surface, built, part, variable)
    if (status%ok()) call explain_surface_failure(surface_source, built, part, variable, status)
    if (status%ok()) call read_point_mass_config(input, description, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    ! said here too, with the line of the start
    if (.not. surface%in_domain(description%u0, description%v0)) then
      call invalid(input, 'point_mass', 'u0, v0', format_real(description%u0)//', '//format_real(description%v0), &
                   start_domain_words(surface), status)
      return
    end if
    call build_point_mass_model(description, surface, model, y0, status)
    if (.not. status%ok()) then
      call prefix_status(status, where_given(input, 'point_mass', 'friction')//': &point_mass')
      call mark_input_failure(status)
    end if
  end subroutine build_point_mass

  subroutine run_point_mass(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(result_file_t) :: file
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: run_status, write_status
    real(wp), allocatable :: y0(:)
    character(len=:), allocatable :: outcome, message
    logical :: complete

    call build_point_mass(input, solver, model, y0, status)
    call check_output_count(input, solver, solver%duration, values_per_output, 'point_mass', status)
    if (.not. status%ok() .or. run%check_only) return

    ! Open the result file before any work, so an unwritable path stops the run now.
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return

    call log_info('point_mass: '//model%surface%describe()//', '//format_real(solver%duration)// &
                  ' s, output every '//format_real(solver%output_step)//' s')
    call model%start_series(nint(solver%duration/solver%output_step) + 2)
    options%ode = solver%options
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%min_mean_step = min_mean_step
    options%label = 'point_mass'
    options%log => log_info
    call drive(model, y0, options, result, run_status)
    select case (result%outcome)
    case (DRIVE_END_TIME)
      outcome = 'the end of the simulated time'
    case (DRIVE_EVENT_STOP)
      outcome = model%outcome
    case default
      outcome = 'failed'
    end select

    call write_series(file, input, run, model, model%series, result%stats, result%cpu, write_status)
    complete = run_status%ok() .and. write_status%ok()
    message = run_message('ok: '//outcome, run_status, write_status)
    if (write_status%ok() .and. model%series%n > 0) call write_xdmf(file, model%series%time(:model%series%n), &
                                                                    write_status)
    call file%finish(complete, message, write_status)
    complete = complete .and. write_status%ok()   ! finish refuses a file with NaN or Inf
    call report(model, model%series, result%stats, result%cpu, file%final_path(), run, complete, message, &
                outcome, write_status)
    if (.not. (run_status%ok() .and. write_status%ok())) status = run_outcome(run_status, write_status)
  end subroutine run_point_mass

  subroutine write_series(file, input, run, model, s, stats, cpu, status)
    type(result_file_t), intent(inout) :: file
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(point_mass_t), intent(in) :: model
    type(point_mass_series_t), intent(in) :: s
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    type(status_t), intent(inout) :: status
    integer :: n
    character(len=*), parameter :: g = '/point_mass/'
    character(len=:), allocatable :: uu, vu   ! units of u and v of this surface

    n = s%n
    call model%surface%parameter_units(uu, vu)
    call file%write_provenance('point_mass', trim(run%title), input%name, input%text(), status)
    call file%write_vector(g//'time', s%time(:n), 's', 'time', status)
    call file%write_vector(g//'u', s%u(:n), uu, 'surface coordinate u', status)
    call file%write_vector(g//'v', s%v(:n), vu, 'surface coordinate v', status)
    call file%write_vector(g//'du', s%du(:n), units_per_second(uu), 'rate of u', status)
    call file%write_vector(g//'dv', s%dv(:n), units_per_second(vu), 'rate of v', status)
    call file%write_matrix(g//'position', s%position(:, :n), 'm', 'position (3 x n)', status)
    call file%write_matrix(g//'velocity', s%velocity(:, :n), 'm/s', 'velocity (3 x n)', status)
    call file%write_matrix(g//'acceleration', s%acceleration(:, :n), 'm/s^2', 'acceleration (3 x n)', status)
    call file%write_vector(g//'speed', s%speed(:n), 'm/s', 'speed |velocity|', status)
    call file%write_vector(g//'normal_force', pressing_force(s), 'N', 'normal force, positive while the mass '// &
                           'presses on the surface from its side (the side of frame z at the start; negative: the '// &
                           'surface pulls)', status)
    call file%write_matrix(g//'friction_force', s%friction_force(:, :n), 'N', 'friction force (3 x n)', status)
    call file%write_vector(g//'kinetic_energy', s%kinetic(:n), 'J', 'kinetic energy', status)
    call file%write_vector(g//'potential_energy', s%potential(:n), 'J', 'potential energy -m g.r', status)
    call file%write_vector(g//'energy', s%kinetic(:n) + s%potential(:n), 'J', 'kinetic + potential energy', status)
    call file%write_vector(g//'friction_work', s%friction_work(:n), 'J', &
                           'work done on the mass by friction since t = 0 (<= 0)', status)
    if (model%drag_area > 0) then
      call file%write_matrix(g//'drag_force', s%drag_force(:, :n), 'N', 'the air''s drag on the mass (3 x n)', &
                             status)
      call file%write_vector(g//'drag_work', s%drag_work(:n), 'J', &
                             'work done on the mass by the air''s drag since t = 0 (<= 0 in still air)', status)
    end if
    call file%write_array3(g//'frame', s%frame(:, :, :n), '1', &
                           'Darboux frame in world coordinates: frame[i, k, :] is axis k (0 x, 1 y, 2 z: the normal) '// &
                           'at sample i as h5py reads it (a row; the columns of the 3 x 3 x n Fortran array)', status)
    if (n > 0) then
      call file%make_scale(g//'time', status)
      call file%attach_scale(g//'time', g, status)
      call file%attach_components(g, status)
      call write_surface_grid_around(file, model%surface, s%u(:n), s%v(:n), status, log_info)
    end if
    call file%write_count('/statistics/steps', int(stats%steps), '1', 'integrator steps', status)
    call file%write_count('/statistics/rhs_evaluations', int(stats%rhs_evaluations), '1', &
                          'right-hand-side evaluations', status)
    call file%write_count('/statistics/error_test_failures', int(stats%error_test_failures), '1', &
                          'error test failures', status)
    call file%write_scalar('/statistics/cpu_time', cpu, 's', &
                           'CPU time of the run through the integration driver (integration, events, records)', status)
  end subroutine write_series

  !> The XDMF file next to the result: the surface, the path with its
  !> fields, and the mass moving over time.
  subroutine write_xdmf(file, time, status)
    type(result_file_t), intent(inout) :: file
    real(wp), intent(in) :: time(:)
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    call xdmf%start()
    call xdmf%surface(file, 'surface', '/geometry/surface')
    call xdmf%polyline(file, 'path', '/point_mass/position', '/point_mass')
    call xdmf%moving_points(file, 'mass', time, ['/point_mass/position'], .false.)
    call xdmf%attach(file, status)
  end subroutine write_xdmf

  !> The printed summary and, with --summary-json, the same numbers as JSON.
  subroutine report(model, s, stats, cpu, path, run, complete, message, outcome, status)
    type(point_mass_t), intent(in) :: model
    type(point_mass_series_t), intent(in) :: s
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: path, message, outcome
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    real(wp) :: e0, drift, accel
    real(wp), allocatable :: pressing(:)
    character(len=:), allocatable :: note
    integer :: n, i

    n = s%n
    if (n < 1) return
    e0 = s%kinetic(1) + s%potential(1)
    drift = maxval(abs(s%kinetic(:n) + s%potential(:n) - s%friction_work(:n) - s%drag_work(:n) - e0))
    accel = maxval([(norm2(s%acceleration(:, i)), i=1, n)])
    call summary%start('point_mass', 'slidesim point_mass on '//model%surface%describe())
    call summary%add('simulated_time', 'simulated time', s%time(n), 's')
    if (complete) call summary%add_text('outcome', 'stopped at', outcome)
    call summary%add_vector('final_position', 'final position', s%position(:, n), 'm')
    call summary%add('final_speed', 'final speed', s%speed(n), 'm/s')
    call summary%add('max_speed', 'max speed', maxval(s%speed(:n)), 'm/s', 'm/s ('// &
                     engineering(3.6_wp*maxval(s%speed(:n)))//' km/h)')
    call summary%add('max_acceleration', 'max acceleration', accel, 'm/s^2', 'g', 1/standard_g)
    pressing = pressing_force(s)
    call summary%add_range('normal_force', 'normal force min / max', minval(pressing), maxval(pressing), 'N', &
                           'N (> 0 pressing)')
    note = pulled_note(s, pressing)
    if (len(note) > 0) then
      call summary%add_line('  surface pulls the mass    '//note)
      call log_warning('point_mass: the surface pulls the mass '//note)
    end if
    call summary%add('drop', 'height drop', s%position(3, 1) - s%position(3, n), 'm')
    call summary%add('friction_work', 'friction work', s%friction_work(n), 'J')
    if (model%drag_area > 0) then
      call summary%add('drag_work', 'air drag work', s%drag_work(n), 'J')
      call summary%add('drag_force_max', 'air drag force max', maxval([(norm2(s%drag_force(:, i)), i=1, n)]), 'N')
    end if
    call summary%add('energy_balance_error', 'energy balance error', drift/max(abs(e0), s%kinetic(1), &
                     maxval(s%kinetic(:n)), tiny(1.0_wp)), '1', '(relative)')
    call add_run_cost(summary, stats, cpu)
    call summary%print()
    call end_report(summary, run, path, complete, message, status)
  end subroutine report

  !> The normal force as the mass feels it: positive while the mass presses
  !> on the surface. The mass rides on the side the frame's z points to at
  !> the start (sigma turns z, docs/inputs.md); where the parametrisation
  !> turns z over between two records (through a singular apex, where
  !> r_u x r_v changes sign: z(i).z(i-1) < 0) the mass stays on its side of
  !> the surface, so the sign turns with z. Negative: the surface pulls the
  !> mass, which the point mass model allows (it is held to the surface) and a
  !> real mass would not (pulled_note).
  pure function pressing_force(s) result(pressing)
    type(point_mass_series_t), intent(in) :: s
    real(wp) :: pressing(s%n)
    real(wp) :: side
    integer :: i
    side = 1
    do i = 1, s%n
      if (i > 1) then
        if (dot_product(s%frame(:, 3, i), s%frame(:, 3, i - 1)) < 0) side = -side
      end if
      pressing(i) = side*s%normal_force(i)
    end do
  end function pressing_force

  !> Where the surface pulls the mass (the pressing force below zero by more
  !> than rounding, 1e-9 of its largest size), in words: the first such
  !> stretch of records, where it starts and how many records pull; '' when
  !> none does.
  function pulled_note(s, pressing) result(text)
    type(point_mass_series_t), intent(in) :: s
    real(wp), intent(in) :: pressing(:)
    character(len=:), allocatable :: text
    logical :: pulled(size(pressing))
    integer :: first, last
    text = ''
    pulled = pressing < -1e-9_wp*maxval(abs(pressing))
    if (.not. any(pulled)) return
    first = findloc(pulled, .true., dim=1)
    last = first
    do while (last < size(pulled))
      if (.not. pulled(last + 1)) exit
      last = last + 1
    end do
    text = 'from t = '//format_short(s%time(first))//' to '//format_short(s%time(last))//' s (u, v = '// &
           format_short(s%u(first))//', '//format_short(s%v(first))//' at its start; '// &
           format_integer(count(pulled))//' records in all, normal force down to '//format_short(minval(pressing))// &
           ' N): a real mass would leave the surface there; the point mass model holds it on'
  end function pulled_note
end module scenarios_point_mass
