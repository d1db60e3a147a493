!> The run shared by the multibody scenarios (pendulum, fourbar, sled): check
!> the start, open the result file, run through the integration driver
!> (outputs, events, progress lines, runaway guards), write, summarize.
module scenarios_mechanism
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INTERNAL
  use base_log, only: log_info
  use numerics_ode, only: ode_stats_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, DRIVE_EVENT_STOP
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_recorder, only: mechanism_series_t
  use kinetostatics_mechanism, only: mechanism_t
  use base_vector, only: cross
  use base_text, only: format_integer
  use io_input, only: input_text_t, format_real, mark_input_failure, where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, check_output_count
  use io_mechanism_config, only: write_mechanism_series
  use io_hdf5, only: result_file_t, run_outcome, run_message
  use io_summary, only: summary_t, degrees, engineering
  use io_surface_grid, only: write_surface_grid_around
  use io_xdmf, only: xdmf_t, body_shape_t
  use geometry_surface, only: surface_t
  use scenarios_report, only: end_report, add_run_cost
  use design_ride_evaluation, only: noise_free
  use contact_flight, only: flight_ode_t, impact_record_t
  use contact_closing, only: drive_flight
  use rider_vehicle_flight, only: vehicle_flight_ode_t, drive_vehicle, vehicle_units
  implicit none (type, external)
  private
  public :: run_mechanism, mechanism_driver_options, run_figures_t
  public :: refuse_start, values_per_record, open_run_file, write_mechanism_run

  !> Figures a scenario adds to its mechanism's run (the sled's vehicle,
  !> scenarios_sled, computed by the library's ride): written into the
  !> result file before it is finished, and added to the summary.
  type, abstract :: run_figures_t
  contains
    procedure(figures_write_i), deferred :: write
    procedure(figures_summarise_i), deferred :: summarise
  end type run_figures_t

  abstract interface
    subroutine figures_write_i(self, file, status)
      import :: run_figures_t, result_file_t, status_t
      class(run_figures_t), intent(in) :: self
      type(result_file_t), intent(inout) :: file
      type(status_t), intent(inout) :: status
    end subroutine figures_write_i
    subroutine figures_summarise_i(self, summary)
      import :: run_figures_t, summary_t
      class(run_figures_t), intent(in) :: self
      type(summary_t), intent(inout) :: summary
    end subroutine figures_summarise_i
  end interface

  !> Runaway guard of the multibody scenarios: a mean step below 1e-4 s after
  !> the driver's guard_steps steps. Their regular runs take mean steps of
  !> 1e-3 s or more (bench/multibody_bench: the four-bar at rtol 1e-12 the
  !> smallest, 1.1e-3 s); a body at rest under regularized Coulomb friction
  !> with Adams takes steps of a few microseconds (millions of them).
  real(wp), parameter :: min_mean_step = 1e-4_wp

contains

  !> Driver options of a multibody scenario from its &solver.
  function mechanism_driver_options(scenario, solver) result(options)
    character(len=*), intent(in) :: scenario
    type(solver_config_t), intent(in) :: solver
    type(driver_options_t) :: options
    options%ode = solver%options
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%min_mean_step = min_mean_step
    options%label = scenario
    options%log => log_info
  end function mechanism_driver_options

  !> The common run of a multibody scenario from q0, q0'.
  subroutine run_mechanism(scenario, input, run, solver, sys, q0, qd0, q_units, beta_units, status, surface, &
                           start_variables, shapes)
    character(len=*), intent(in) :: scenario
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(solver_config_t), intent(in) :: solver
    class(mechanism_ode_t), intent(inout), target :: sys   ! or an extension (contact_flight)
    real(wp), intent(in) :: q0(:), qd0(:)
    character(len=*), intent(in) :: q_units(:), beta_units(:)   ! units of the q and of the dependent beta
    type(status_t), intent(inout) :: status
    class(surface_t), intent(in), optional :: surface   ! the surface of the contacts, written as a grid
    character(len=*), intent(in), optional :: start_variables   ! of &<scenario>, named when the start fails
    type(body_shape_t), intent(in), optional :: shapes(:)   ! drawn moving with their bodies in the XDMF view
    type(result_file_t) :: file
    type(driver_result_t) :: result
    type(status_t) :: run_status
    real(wp), allocatable :: y0(:)
    character(len=:), allocatable :: outcome
    character(len=8), allocatable :: units(:), dependent_units(:)
    integer, allocatable :: open(:, :)

    y0 = sys%initial_state(q0, qd0)
    call sys%check_start(y0, status)
    if (.not. status%ok()) then
      call refuse_start(scenario, input, status, start_variables)
      return
    end if
    call check_output_count(input, solver, solver%duration, values_per_record(sys), scenario, status)
    if (.not. status%ok() .or. run%check_only) return
    call open_run_file(scenario, run, solver, file, status)
    if (.not. status%ok()) return
    call sys%start_series(nint(solver%duration/solver%output_step) + 2)
    units = q_units
    dependent_units = beta_units
    select type (sys)
    class is (flight_ode_t)
      ! a flight may close its contact and go on closed (contact_closing)
      call drive_flight(sys, y0, mechanism_driver_options(scenario, solver), result, run_status, open)
      units = sys%q_units
      dependent_units = sys%beta_units
    class is (vehicle_flight_ode_t)
      ! a vehicle that may fly: stretch by stretch through its builds, the
      ! units of the joined records by their names (u, v the first two's)
      call drive_vehicle(sys, y0, mechanism_driver_options(scenario, solver), result, run_status)
      call vehicle_units(sys%series, q_units(1), q_units(2), units, dependent_units)
    class default
      call drive(sys, y0, mechanism_driver_options(scenario, solver), result, run_status)
    end select
    select case (result%outcome)
    case (DRIVE_END_TIME)
      outcome = 'the end of the simulated time'
      ! what happened on the way (a flight's closing, a vehicle's flights)
      if (allocated(open) .and. len(sys%outcome) > 0) outcome = sys%outcome//'; '//outcome
      select type (sys)
      class is (vehicle_flight_ode_t)
        if (len(sys%outcome) > 0) outcome = sys%outcome//'; '//outcome
      end select
    case (DRIVE_EVENT_STOP)
      outcome = sys%outcome
    case default
      outcome = 'failed: '//run_status%text()
    end select
    call write_mechanism_run(scenario, input, run, sys, file, result, run_status, outcome, units, dependent_units, &
                             open, status, surface, shapes)
  end subroutine run_mechanism

  !> A start the model refuses (check_start): the input's failure, named at
  !> the scenario's group, which holds the start (`start_variables`).
  subroutine refuse_start(scenario, input, status, start_variables)
    character(len=*), intent(in) :: scenario
    type(input_text_t), intent(in) :: input
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: start_variables
    call prefix_status(status, where_given(input, scenario, '')//': &'//scenario//': '//scenario)
    if (present(start_variables)) status%message = status%message//'; change the start ('//start_variables//')'
    call mark_input_failure(status)
  end subroutine refuse_start

  !> The numbers stored per output time (mechanism_series_t; every element
  !> counted as a body), for check_output_count.
  integer function values_per_record(sys) result(n)
    class(mechanism_ode_t), intent(in) :: sys
    n = 6 + 3*sys%mechanism%f + 2*sys%mechanism%r + 18*sys%mechanism%n_elements + 10*size(sys%mechanism%contacts) + &
        6*sys%mechanism%n_laws
  end function values_per_record

  !> The result file of a run, opened before it runs (a file that cannot
  !> be written fails before any work), and the run's first progress line.
  subroutine open_run_file(scenario, run, solver, file, status)
    character(len=*), intent(in) :: scenario
    type(run_config_t), intent(in) :: run
    type(solver_config_t), intent(in) :: solver
    type(result_file_t), intent(inout) :: file
    type(status_t), intent(inout) :: status
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call log_info(scenario//': '//format_real(solver%duration)//' s, output every '// &
                  format_real(solver%output_step)//' s')
  end subroutine open_run_file

  !> A run's records (sys%series, the driver's `result`, ended as `outcome`;
  !> run_status its failure) into the open `file`, with the scenario's own
  !> figures (the sled's vehicle), the flight's impacts and phases (`open`),
  !> the surface's grid and the XDMF view; the file finished, the summary
  !> printed; status the run's or the writing's failure.
  subroutine write_mechanism_run(scenario, input, run, sys, file, result, run_status, outcome, units, dependent_units, &
                                 open, status, surface, shapes, figures)
    character(len=*), intent(in) :: scenario, outcome
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    class(mechanism_ode_t), intent(in) :: sys
    type(result_file_t), intent(inout) :: file
    type(driver_result_t), intent(in) :: result
    type(status_t), intent(in) :: run_status
    character(len=*), intent(in) :: units(:), dependent_units(:)
    integer, allocatable, intent(in) :: open(:, :)   ! a flight's (drive_flight)
    type(status_t), intent(inout) :: status
    class(surface_t), intent(in), optional :: surface
    type(body_shape_t), intent(in), optional :: shapes(:)
    class(run_figures_t), intent(in), optional :: figures   ! the scenario's own figures of the run
    type(status_t) :: write_status
    real(wp), allocatable :: losses(:)
    logical :: complete
    character(len=:), allocatable :: message

    losses = impact_losses(sys)
    call write_mechanism_series(file, scenario, input, run%title, sys%series, outcome, result%stats, result%cpu, &
                                units, dependent_units, write_status, losses)
    ! a failed run's too: what of them its records gave (the sled's vehicle)
    if (present(figures)) call figures%write(file, write_status)
    select type (sys)
    class is (flight_ode_t)
      call write_impacts(file, sys, write_status)
      call write_phases(file, sys, open, write_status)
    end select
    ! the grid around the first contact's path (u, v are its first two coordinates)
    if (present(surface)) call write_surface_grid_around(file, surface, sys%series%q(1, :sys%series%n), &
                                                         sys%series%q(2, :sys%series%n), write_status, log_info)
    complete = run_status%ok() .and. write_status%ok()
    message = run_message('ok: '//outcome, run_status, write_status)
    if (write_status%ok() .and. sys%series%n > 0) call write_xdmf(file, scenario, sys%series, write_status, shapes)
    call file%finish(complete, message, write_status)
    complete = complete .and. write_status%ok()   ! finish refuses a file with NaN or Inf
    select type (sys)
    class is (flight_ode_t)
      if (allocated(sys%closed)) then
        ! the joined series' contacts and bodies are the closed contact's
        call report(scenario, sys%series, result%stats, result%cpu, units, file%final_path(), run, complete, &
                    message, outcome, sys%chart_changes, sys%closed%ode%mechanism, write_status, sys%impacts, losses, &
                    closed=closed_records(sys, open), body_names=description_bodies(sys))
      else
        call report(scenario, sys%series, result%stats, result%cpu, units, file%final_path(), run, complete, &
                    message, outcome, sys%chart_changes, sys%mechanism, write_status, sys%impacts, losses, &
                    carried_bodies=carried_bodies(sys, open), closed=closed_records(sys, open), &
                    body_names=description_bodies(sys))
      end if
    class default
      call report(scenario, sys%series, result%stats, result%cpu, units, file%final_path(), run, complete, &
                  message, outcome, sys%chart_changes, sys%mechanism, write_status, impacts_of(sys), losses, &
                  figures)
    end select
    if (.not. (run_status%ok() .and. write_status%ok())) status = run_outcome(run_status, write_status)
  end subroutine write_mechanism_run

  !> The impacts of a flight (contact_flight), none for any other run.
  function impacts_of(sys) result(impacts)
    class(mechanism_ode_t), intent(in) :: sys
    type(impact_record_t), allocatable :: impacts(:)
    allocate (impacts(0))
    select type (sys)
    class is (flight_ode_t)
      impacts = sys%impacts
    end select
  end function impacts_of

  !> The energy the impacts removed up to each record (J): a record at an
  !> impact holds the state after it, but where the phase stopped before
  !> the impact's velocities were taken (after_switch: an impact through a
  !> carried body) the first record at its time holds the state before it
  !> (the next phase's first, at the same time, after it; a switch that
  !> failed has none). Zero without impacts.
  function impact_losses(sys) result(losses)
    class(mechanism_ode_t), intent(in) :: sys
    real(wp), allocatable :: losses(:)
    type(impact_record_t), allocatable :: impacts(:)
    logical :: first_at_time
    integer :: i
    select type (sys)
    class is (vehicle_flight_ode_t)
      losses = sys%losses   ! a vehicle's landings (drive_vehicle)
      return
    end select
    impacts = impacts_of(sys)
    allocate (losses(sys%series%n))
    do i = 1, sys%series%n
      associate (t => sys%series%time)
        first_at_time = .true.
        if (i > 1) first_at_time = t(i - 1) /= t(i)
        losses(i) = sum(impacts%energy_lost, mask=impacts%time < t(i) .or. (impacts%time == t(i) .and. &
                        .not. (impacts%after_switch .and. first_at_time)))
      end associate
    end do
  end function impact_losses

  !> Per record and contact of a flight whether it was open (1, the body in
  !> flight or carried by another) or closed (0),
  !> /contact/contacts/<name>/open (docs/outputs.md).
  subroutine write_phases(file, flight, open, status)
    type(result_file_t), intent(inout) :: file
    type(flight_ode_t), intent(in) :: flight
    integer, intent(in) :: open(:, :)
    type(status_t), intent(inout) :: status
    integer :: c
    if (.not. status%ok() .or. flight%series%n == 0) return
    do c = 1, size(open, 1)
      call file%write_integers('/contact/contacts/'//flight%system%contacts(c)%name//'/open', &
                               open(c, :flight%series%n), '1', '1 while the contact is open (its body in '// &
                               'flight or on another contact, its gap in /contact/measurements), 0 while closed', &
                               status)
    end do
    call file%attach_scale('/contact/time', '/contact/contacts', status)   ! written after the series's
  end subroutine write_phases

  !> The impacts table of a flight (docs/outputs.md, /contact/impacts), if
  !> it had any: one row per impact. Its place is the point of its contact
  !> (drive_flight: the gap's point on shape_1 while open) at the first
  !> record at the impact's time (the driver records every impact: the state
  !> after it, the flight's at a closing): the landing point.
  subroutine write_impacts(file, flight, status)
    type(result_file_t), intent(inout) :: file
    type(flight_ode_t), intent(in) :: flight
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: position(:, :)
    integer :: j, i
    if (.not. status%ok()) return
    associate (impacts => flight%impacts, s => flight%series)
      if (size(impacts) == 0) return
      allocate (position(3, size(impacts)))
      do j = 1, size(impacts)
        i = findloc(s%time(:s%n), impacts(j)%time, dim=1)
        if (i == 0) then
          call set_status(status, STATUS_INTERNAL, 'the impact at t = '//format_real(impacts(j)%time)// &
                          ' s has no record at its time')
          return
        end if
        position(:, j) = flight%gap_point(:, impacts(j)%contact, i)
      end do
      call write_impacts_table(file, impacts, position, status)
      call file%write_text('/contact/impacts/body_names', body_names(flight), 'the bodies of body_1 and body_2 '// &
                           'by their numbers: 0 the ground, then each &body''s name after its place', status)
    end associate
  end subroutine write_impacts

  !> "0 ground, 1 <name of the first &body>, 2 ...": the numbers of the
  !> impacts table's bodies.
  function body_names(flight) result(text)
    type(flight_ode_t), intent(in) :: flight
    character(len=:), allocatable :: text
    integer :: b
    text = '0 ground'
    do b = 1, size(flight%system%bodies)
      text = text//', '//format_integer(b)//' '//flight%system%bodies(b)%name
    end do
  end function body_names

  !> The impacts table's datasets and their scales.
  subroutine write_impacts_table(file, impacts, position, status)
    type(result_file_t), intent(inout) :: file
    type(impact_record_t), intent(in) :: impacts(:)
    real(wp), intent(in) :: position(:, :)   ! 3 x k, m
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/contact/impacts/'
    call file%write_vector(g//'time', impacts%time, 's', 'time of each impact', status)
    call file%write_integers(g//'contact', impacts%contact, '1', &
                             'the impact''s contact: its place among the &contact groups (1: the first)', status)
    call file%write_integers(g//'body_1', impacts%body_1, '1', 'the impact''s first body, its contact''s '// &
                             'body_1: its place among the &body groups (1: the first; 0: the ground)', status)
    call file%write_integers(g//'body_2', impacts%body_2, '1', 'the impact''s second body, its contact''s '// &
                             'body_2: its place among the &body groups (1: the first; 0: the ground)', status)
    call file%write_vector(g//'normal_speed_before', impacts%normal_speed_before, 'm/s', &
                           'separation speed of the contact points before (< 0: approaching)', status)
    call file%write_vector(g//'normal_speed_after', impacts%normal_speed_after, 'm/s', &
                           'separation speed of the contact points after', status)
    call file%write_vector(g//'normal_impulse', impacts%normal_impulse, 'N s', &
                           'normal impulse on the body', status)
    call file%write_vector(g//'tangential_impulse', impacts%tangential_impulse, 'N s', &
                           'size of the tangential (friction) impulse on the body', status)
    call file%write_vector(g//'energy_lost', impacts%energy_lost, 'J', 'kinetic energy the impact removed', status)
    call file%write_matrix(g//'position', position, 'm', &
                           'where the impact happened: the contact point on shape_1 (k x 3)', status)
    ! the table's rows by their time; position's columns by /contact/xyz
    call file%make_scale(g//'time', status)
    call file%attach_scale(g//'time', g, status)
    call file%attach_scale('/contact/xyz', g, status, axis=1)
  end subroutine write_impacts_table

  !> The XDMF file next to the result: the surface (sled), each body's and
  !> contact's path, the bodies and the contacts (joined: the sled's bar)
  !> moving over time. A contact that can open (a flight) shows on its path
  !> and its moving point whether it is open (1) and its gap (m), and the
  !> impacts are a set of points at the landings (docs/outputs.md).
  subroutine write_xdmf(file, scenario, s, status, shapes)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: scenario
    type(mechanism_series_t), intent(in) :: s
    type(status_t), intent(inout) :: status
    type(body_shape_t), intent(in), optional :: shapes(:)
    integer :: b, j
    type(xdmf_t) :: xdmf
    character(len=:), allocatable :: g
    character(len=128) :: bodies(s%nb), contacts(s%nc), phase(2, s%nc)
    real(wp), allocatable :: phases(:, :, :), values(:)   ! open, gap x contact x record
    integer :: k
    g = '/'//scenario
    call xdmf%start()
    call xdmf%surface(file, 'surface', '/geometry/surface')
    do k = 1, s%nb
      bodies(k) = g//'/bodies/'//trim(s%body_names(k))//'/position'
      call xdmf%polyline(file, 'path of '//trim(s%body_names(k)), trim(bodies(k)), &
                         g//'/bodies/'//trim(s%body_names(k)))
    end do
    allocate (phases(2, s%nc, s%n), source=0.0_wp)
    do k = 1, s%nc
      contacts(k) = g//'/contacts/'//trim(s%contact_names(k))//'/position'
      phase(:, k) = [character(len=128) :: g//'/contacts/'//trim(s%contact_names(k))//'/open', &
                     g//'/measurements/'//trim(s%contact_names(k))//'.gap']
      call xdmf%polyline(file, 'path of contact '//trim(s%contact_names(k)), trim(contacts(k)), &
                         g//'/contacts/'//trim(s%contact_names(k)), field_names=['open', 'gap '], fields=phase(:, k))
      do j = 1, 2
        values = file%values_of(trim(phase(j, k)))
        if (size(values) == s%n) phases(j, k, :) = values
      end do
    end do
    if (s%nb > 0) call xdmf%moving_points(file, 'bodies', s%time(:s%n), bodies, .false.)
    if (s%nc > 0) then
      ! a contact that can open: every contact's state (0 and no gap: closed)
      if (any([(size(file%shape_of(trim(phase(1, k)))) > 0, k = 1, s%nc)])) then
        call xdmf%moving_points(file, 'contacts', s%time(:s%n), contacts, .true., ['open', 'gap '], phases)
      else
        call xdmf%moving_points(file, 'contacts', s%time(:s%n), contacts, .true.)
      end if
    end if
    call xdmf%point_set(file, 'impacts', g//'/impacts/position', g//'/impacts')
    if (present(shapes)) then
      do j = 1, size(shapes)
        ! (gfortran's findloc misses a shorter text in a character array)
        b = findloc([(trim(s%body_names(b)) == shapes(j)%body, b = 1, s%nb)], .true., dim=1)
        if (b > 0) call xdmf%moving_grid(shapes(j)%body//' as '//shapes(j)%shape, s%time(:s%n), shapes(j)%points, &
                                         s%body_rot(:, :, b, :s%n), s%body_r(:, b, :s%n))
      end do
    end if
    call xdmf%attach(file, status)
  end subroutine write_xdmf

  !> The printed summary (angles in degrees) and, with --summary-json, the
  !> same numbers as JSON (SI).
  subroutine report(scenario, s, stats, cpu, q_units, path, run, complete, message, outcome, chart_changes, m, &
                    status, impacts, losses, figures, carried_bodies, closed, body_names)
    character(len=*), intent(in) :: scenario, path, message, outcome
    integer, intent(in) :: chart_changes   ! coordinates re-based on a new chart (docs/multibody.md, events)
    type(mechanism_series_t), intent(in) :: s
    type(mechanism_t), intent(in) :: m
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: q_units(:)
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(impact_record_t), intent(in) :: impacts(:)
    real(wp), intent(in) :: losses(:)   ! J, the impacts' energy lost up to each record
    class(run_figures_t), intent(in), optional :: figures
    character(len=*), intent(in), optional :: carried_bodies(:)   ! each contact's body_2 where it closed (else '')
    logical, intent(in), optional :: closed(:, :)   ! (contact, record): closed there (a flight's); absent: always
    character(len=*), intent(in), optional :: body_names(:)   ! the &body groups' names (the impacts' body places)
    type(summary_t) :: summary
    real(wp) :: e0, scale
    integer :: n, k, i, events
    character(len=:), allocatable :: q, u, note
    n = s%n
    if (n < 1) return
    e0 = s%kinetic(1) + s%potential(1)
    scale = max(maxval(s%kinetic(:n)), maxval(abs(s%potential(:n) - s%potential(1))), tiny(1.0_wp))
    call summary%start(scenario, 'slidesim '//scenario)
    call summary%add('simulated_time', 'simulated time', s%time(n), 's')
    if (complete) call summary%add_text('outcome', 'stopped at', outcome)
    if (scenario == 'contact') then
      ! bodies and contacts in engineering terms (docs/contact.md, Outputs)
      if (.not. complete) call summary%add_text('failure', 'stopped because', message)
      call add_body_terms(summary, s, m, impacts, body_names)
      call add_contact_terms(summary, s, m, carried_bodies, closed)
      if (size(impacts) > 0) then
        ! one impact at several contacts (a landing on a carried body): a row each, at one time
        events = 1 + count(impacts(2:)%time /= impacts(:size(impacts) - 1)%time)
        note = '(landings, /contact/impacts)'
        if (events < size(impacts)) note = '(landings; '//format_integer(size(impacts))//' rows of /contact/impacts)'
        call summary%add_count('impacts', 'impacts', events, note)
        call summary%add('impact_speed_max', 'impact speed max', maxval(-impacts%normal_speed_before), 'm/s', &
                         'm/s (the fastest approach)')
        call summary%add('impact_energy_lost', 'impacts energy lost', sum(impacts%energy_lost), 'J')
      end if
      call summary%add('energy_change_joules', 'energy change', s%kinetic(n) + s%potential(n) - e0, 'J')
      call summary%add('energy_change', 'energy change relative', (s%kinetic(n) + s%potential(n) - e0)/scale, '1', &
                       '(of the largest kinetic/potential change)')
    end if
    do k = 1, merge(0, s%f, scenario == 'contact')
      q = trim(s%q_names(k))
      u = trim(q_units(k))
      if (u == 'rad') then
        call summary%add(q//'_final', q//' final', s%q(k, n), u, 'deg', degrees)
        call summary%add_range(q, q//' min / max', minval(s%q(k, :n)), maxval(s%q(k, :n)), u, 'deg', degrees)
        call summary%add(q//'_rate_final', q//' rate final', s%qd(k, n), u//'/s', 'deg/s', degrees)
        call summary%add(q//'_rate_max', q//' rate max', maxval(abs(s%qd(k, :n))), u//'/s', 'deg/s', degrees)
      else
        call summary%add(q//'_final', q//' final', s%q(k, n), u)
        call summary%add_range(q, q//' min / max', minval(s%q(k, :n)), maxval(s%q(k, :n)), u)
        call summary%add(q//'_rate_final', q//' rate final', s%qd(k, n), u//'/s')
      end if
    end do
    do k = 1, merge(0, s%nc, scenario == 'contact')
      q = trim(s%contact_names(k))
      call summary%add(q//'_speed_max', q//' slip speed max', maxval([(norm2(s%slip(:, k, i)), i=1, n)]), 'm/s', &
                       'm/s ('//engineering(3.6_wp*maxval([(norm2(s%slip(:, k, i)), i=1, n)]))//' km/h)')
      call summary%add_range(q//'_normal_force', q//' normal force min / max', minval(s%normal(k, :n)), &
                             maxval(s%normal(k, :n)), 'N')
    end do
    if (scenario /= 'contact') call summary%add('energy_change', 'energy change', &
                                                (s%kinetic(n) + s%potential(n) - e0)/scale, '1', &
                                                '(relative to the largest kinetic/potential change)')
    if (s%nl > 0) call summary%add('law_work', 'work of the force laws', sum(s%law_work(:, n)), 'J')
    ! whatever takes energy out (force laws, impacts), the balance adds it back
    if (s%nl > 0 .or. losses(n) > 0) then
      if (s%nl == 0) then
        note = '(E(t) - E(0) + impacts'' losses, same scale)'
      else if (losses(n) > 0) then
        note = '(E(t) - E(0) - work + impacts'' losses, same scale)'
      else
        note = '(E(t) - E(0) - work, same scale)'
      end if
      call summary%add('energy_balance_error', 'energy balance error', &
                       (s%kinetic(n) + s%potential(n) - e0 - sum(s%law_work(:, n)) + losses(n))/scale, '1', note)
    end if
    if (s%r > 0) call summary%add('closure_residual_max', 'closure residual max', maxval(s%closure(:n)), 'm')
    if (present(figures)) call figures%summarise(summary)
    if (chart_changes > 0) call summary%add_count('chart_changes', 'chart changes', chart_changes, &
                                                  '(coordinates re-based, the motion continuous)')
    call add_run_cost(summary, stats, cpu)
    call summary%print()
    call end_report(summary, run, path, complete, message, status)
  end subroutine report

  !> Per body of the contact scenario: the height of its centre of mass, the
  !> tilt of its symmetry axis from the vertical and its spin about that axis
  !> (a body with two equal principal moments and a third apart; a sphere:
  !> its angular speed; none: its angular speed), the speed of its centre
  !> (at the records and, with `body_names`, just before each impact it
  !> takes part in: its peak, which the record after the impact misses).
  !> An angular speed below report_noise_floor of the body's turning scale
  !> (its largest centre speed over its radius of gyration, plus its largest
  !> angular speed) is rounding noise and prints as 0 (design_ride_evaluation
  !> noise_free: a ball that never spins shows no 5e-15 rad/s).
  subroutine add_body_terms(summary, s, m, impacts, body_names)
    type(summary_t), intent(inout) :: summary
    type(mechanism_series_t), intent(in) :: s
    type(mechanism_t), intent(in) :: m
    type(impact_record_t), intent(in) :: impacts(:)
    character(len=*), intent(in), optional :: body_names(:)
    real(wp) :: up(3), centre(3, s%n), speed(s%n), tilt(s%n), spin(s%n), mass, com(3), inertia(3, 3), gravity(3)
    real(wp) :: gyration, turning, peak
    integer :: k, i, e, j, axis, place
    character(len=:), allocatable :: b, axis_name
    do k = 1, s%nb
      b = trim(s%body_names(k))
      ! by name: a flight's joined series keeps the last phase's frames, m is the first phase's
      e = findloc([(m%elements(m%masses(j))%e%name == s%body_names(k), j = 1, size(m%masses))], .true., dim=1)
      if (e == 0) cycle   ! no such mass in m: no terms rather than another body's
      axis = 0
      e = m%masses(e)
      call m%elements(e)%e%mass_properties(mass, com, inertia, gravity)
      up = -gravity
      if (norm2(up) > 0) up = up/norm2(up)
      if (.not. norm2(up) > 0) up = [0.0_wp, 0.0_wp, 1.0_wp]
      axis = symmetry_axis(inertia)
      do i = 1, s%n
        associate (rot => s%body_rot(:, :, k, i), omega => s%body_omega(:, k, i))
          centre(:, i) = s%body_r(:, k, i) + matmul(rot, com)
          speed(i) = norm2(s%body_v(:, k, i) + cross(omega, matmul(rot, com)))
          if (axis > 0) then
            ! atan2, not acos of the dot product: exact near upright (acos loses ~1e-8 rad there)
            tilt(i) = atan2(norm2(cross(rot(:, axis), up)), dot_product(rot(:, axis), up))
            spin(i) = dot_product(omega, rot(:, axis))
          else
            spin(i) = norm2(omega)
          end if
        end associate
      end do
      call summary%add(b//'_height_final', b//' height final', dot_product(centre(:, s%n), up), 'm', &
                       'm (centre of mass, along the vertical)')
      call summary%add_range(b//'_height', b//' height min / max', minval(matmul(up, centre)), &
                             maxval(matmul(up, centre)), 'm')
      peak = maxval(speed)
      place = 0
      if (present(body_names)) place = findloc([(trim(body_names(j)) == b, j = 1, size(body_names))], .true., dim=1)
      if (place > 0) then
        do i = 1, size(impacts)
          if (impacts(i)%body_1 == place) peak = max(peak, impacts(i)%speed_before(1))
          if (impacts(i)%body_2 == place) peak = max(peak, impacts(i)%speed_before(2))
        end do
      end if
      call summary%add(b//'_speed_max', b//' speed max', peak, 'm/s', 'm/s (centre of mass)')
      if (axis > 0) then
        axis_name = 'body '//'xyz'(axis:axis)
        call summary%add(b//'_tilt_start', b//' tilt start', tilt(1), 'rad', &
                         'deg (symmetry axis '//axis_name//' from the vertical)', degrees)
        call summary%add(b//'_tilt_final', b//' tilt final', tilt(s%n), 'rad', 'deg', degrees)
        call summary%add_range(b//'_tilt', b//' tilt min / max', minval(tilt), maxval(tilt), 'rad', 'deg', &
                               degrees)
        call summary%add(b//'_spin_final', b//' spin final', spin(s%n), 'rad/s', &
                         'rad/s (about '//axis_name//', '//engineering(spin(s%n)*30/acos(-1.0_wp))//' rpm)')
        call summary%add(b//'_spin_max', b//' spin max', maxval(abs(spin)), 'rad/s')
      else
        gyration = sqrt((inertia(1, 1) + inertia(2, 2) + inertia(3, 3))/(3*mass))
        turning = maxval(speed)/gyration + maxval(spin)
        call summary%add(b//'_angular_speed_final', b//' angular speed final', noise_free(spin(s%n), turning), &
                         'rad/s')
        call summary%add(b//'_angular_speed_max', b//' angular speed max', noise_free(maxval(spin), turning), 'rad/s')
      end if
    end do
  end subroutine add_body_terms

  !> Per contact: its slip speed, its normal force in N and in weights of
  !> the body it carries (body 2), its friction force. The series' contacts
  !> may be more than the mechanism's (a flight's phases: m is the first's);
  !> carried_bodies names each contact's body 2 where the contact closed in
  !> a later phase. Bodies are found by name: the series' frames may be a
  !> later phase's, m's are the first phase's.
  subroutine add_contact_terms(summary, s, m, carried_bodies, closed)
    type(summary_t), intent(inout) :: summary
    type(mechanism_series_t), intent(in) :: s
    type(mechanism_t), intent(in) :: m
    character(len=*), intent(in), optional :: carried_bodies(:)
    logical, intent(in), optional :: closed(:, :)   ! (contact, record) closed; absent: closed throughout
    real(wp) :: weight, slip(s%n), friction(s%n), normal(s%n), mass, com(3), inertia(3, 3), gravity(3)
    logical :: is_closed(s%n)
    integer :: k, i, e, j
    character(len=:), allocatable :: c, body, while
    do k = 1, s%nc
      c = trim(s%contact_names(k))
      ! the series' contacts may be more than the mechanism's (a flight's
      ! phases: the last closed contact's); in a series of one body that body
      body = ''
      j = findloc([(trim(m%contacts(j)%name) == c, j = 1, size(m%contacts))], .true., dim=1)
      if (j > 0) then
        e = findloc([(m%elements(m%masses(e))%e%mass_frame() == m%contacts(j)%frame_b, e = 1, size(m%masses))], &
                    .true., dim=1)
        if (e > 0) body = trim(m%elements(m%masses(e))%e%name)
      else if (s%nb == 1) then
        body = trim(s%body_names(1))
      else if (present(carried_bodies)) then
        body = trim(carried_bodies(k))
      end if
      weight = 0
      e = 0
      if (len(body) > 0) e = findloc([(m%elements(m%masses(e))%e%name == body, e = 1, size(m%masses))], .true., dim=1)
      if (e > 0) then
        call m%elements(m%masses(e))%e%mass_properties(mass, com, inertia, gravity)
        weight = mass*norm2(gravity)
      end if
      ! a contact's slip and forces while it is closed: while open its
      ! velocity is the flight's relative speed, its forces zero
      is_closed = .true.
      if (present(closed)) is_closed = closed(k, :s%n)
      if (.not. any(is_closed)) cycle
      while = ''
      if (.not. all(is_closed)) while = ' (while closed)'
      slip = [(norm2(s%slip(:, k, i)), i=1, s%n)]
      friction = [(norm2(s%friction(:, k, i)), i=1, s%n)]
      normal = s%normal(k, :s%n)
      if (is_closed(s%n)) call summary%add(c//'_slip_speed_final', c//' slip speed final', slip(s%n), 'm/s')
      call summary%add(c//'_slip_speed_max', c//' slip speed max', maxval(slip, mask=is_closed), 'm/s', 'm/s'//while)
      call summary%add_range(c//'_normal_force', c//' normal force min / max', minval(normal, mask=is_closed), &
                             maxval(normal, mask=is_closed), 'N', 'N'//while)
      if (weight > 0) call summary%add_range(c//'_normal_force_weights', c//' normal force in weights', &
                                             minval(normal, mask=is_closed)/weight, &
                                             maxval(normal, mask=is_closed)/weight, '1', 'of '//body//'''s weight'//while)
      call summary%add(c//'_friction_force_max', c//' friction force max', maxval(friction, mask=is_closed), 'N', &
                       'N'//while)
    end do
  end subroutine add_contact_terms

  !> The names of a flight's &body groups, in their order (the places its
  !> impacts name).
  function description_bodies(flight) result(names)
    type(flight_ode_t), intent(in) :: flight
    character(len=32), allocatable :: names(:)
    integer :: k
    allocate (names(size(flight%system%bodies)))
    do k = 1, size(names)
      names(k) = flight%system%bodies(k)%name
    end do
  end function description_bodies

  !> Each series contact's body_2 (its name) where the contact was closed at
  !> some record (open(c, :) of the description's contact c has a 0), else
  !> '': the report's weights of the contacts a later phase closed.
  function carried_bodies(flight, open) result(bodies)
    type(flight_ode_t), intent(in) :: flight
    integer, intent(in) :: open(:, :)
    character(len=32), allocatable :: bodies(:)
    integer :: k, c
    associate (s => flight%series, contacts => flight%system%contacts)
      allocate (bodies(s%nc))
      bodies = ''
      do k = 1, s%nc
        c = findloc([(contacts(c)%name == trim(s%contact_names(k)), c = 1, size(contacts))], .true., dim=1)
        if (c == 0 .or. c > size(open, 1)) cycle
        if (all(open(c, :) /= 0)) cycle
        bodies(k) = contacts(c)%body_2
      end do
    end associate
  end function carried_bodies

  !> Per series contact and record of a flight whether the contact was
  !> closed there (open(c, :) of the description's contact c is 0); a
  !> contact the description does not name, closed throughout.
  function closed_records(flight, open) result(closed)
    type(flight_ode_t), intent(in) :: flight
    integer, intent(in) :: open(:, :)
    logical, allocatable :: closed(:, :)
    integer :: k, c
    associate (s => flight%series, contacts => flight%system%contacts)
      allocate (closed(s%nc, s%n))
      closed = .true.
      do k = 1, s%nc
        c = findloc([(contacts(c)%name == trim(s%contact_names(k)), c = 1, size(contacts))], .true., dim=1)
        if (c == 0 .or. c > size(open, 1)) cycle
        closed(k, :) = open(c, :s%n) == 0
      end do
    end associate
  end function closed_records

  !> The symmetry axis of an inertia tensor (body axes): the axis whose
  !> moment differs from two equal others (1e-6 relative), the products zero;
  !> 0 for a sphere's or a tensor without one.
  pure integer function symmetry_axis(inertia) result(axis)
    real(wp), intent(in) :: inertia(3, 3)
    real(wp), parameter :: rtol = 1e-6_wp
    real(wp) :: d(3), scale
    integer :: k
    axis = 0
    d = [inertia(1, 1), inertia(2, 2), inertia(3, 3)]
    scale = maxval(abs(d))
    if (.not. scale > 0) return
    if (abs(inertia(1, 2)) + abs(inertia(1, 3)) + abs(inertia(2, 3)) > rtol*scale) return
    do k = 1, 3
      associate (a => d(modulo(k, 3) + 1), b => d(modulo(k + 1, 3) + 1))
        if (abs(a - b) <= rtol*scale .and. abs(d(k) - a) > rtol*scale) axis = k
      end associate
    end do
  end function symmetry_axis
end module scenarios_mechanism
