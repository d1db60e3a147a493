!> Scenario `identify_rider`: the rider's friction mu_D from measured rider
!> positions and speeds (thesis 4.4.3, cost 4.43; docs/design.md). The slide,
!> the water and the rider as in the `ride` scenario (&surface, &water,
!> &water_solver, &rider, &solver; &rider mu is the start value), the
!> measurements and the fit in &identify. The water first (mu_D does not
!> change it), then the fit; /identify_rider holds the estimate with its
!> standard error, the cost and its parts, and the measured and simulated
!> values at every station and segment; the body-parameter study of table
!> 4.10 on request.
module scenarios_identify_rider
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_integer, format_short, format_with
  use base_log, only: log_info
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_model, only: rider_params_t, N_CONTACTS, contact_names, rider_coulomb_mu, set_rider_mu
  use design_rider_identification, only: rider_identification_t, rider_fit_t, rider_stations_t, &
    new_rider_identification, simulate_rider, fit_rider_friction, rider_body_sensitivity, body_variants, &
    n_variants => N_BODY_VARIANTS, variant_names => body_variant_names
  use io_input, only: input_text_t, check_known_groups
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t
  use io_geometry_config, only: geometry_groups
  use io_rider_config, only: require_coulomb_rider
  use io_rider_identification_config, only: rider_identification_config_t, read_rider_identification_config
  use io_hdf5, only: result_file_t, run_outcome, run_message
  use io_identification_results, only: identification_words_t, write_identification_segments, &
    write_identification_cost, write_identification_runs, summarise_identification_cost, &
    summarise_identification_runs
  use io_summary, only: summary_t
  use io_input_declarations, only: declared_unit
  use io_xdmf, only: attach_surface_view
  use scenarios_water, only: write_slide_grid
  use scenarios_ride, only: refuse_start, read_water_and_rider
  use rider_ride, only: check_ride_start
  use design_ride_evaluation, only: ride_limit_t
  use scenarios_report, only: close_report
  implicit none (type, external)
  private
  public :: run_identify_rider, identify_rider_groups

  character(len=*), parameter :: identify_rider_groups(13) = [character(len=14) :: 'run', 'solver', &
    'water_solver', 'surface', 'water', 'rider', 'identify', geometry_groups]


contains

  !> How the results name the fit's pieces (io_identification_results).
  pure function words() result(w)
    type(identification_words_t) :: w
    w = identification_words_t(weight='w_RP', k='k2', cost='F2', &
      equation='(4.43)', runs_note='rides run by the fit', rejected_note='rides that ended early (rejected steps)', &
      runs_label='rides', runs_unit='rides')
  end function words

  subroutine run_identify_rider(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(water_description_t) :: water_description
    type(water_result_t) :: water
    type(ride_limit_t), allocatable :: limits(:)
    type(rider_identification_config_t) :: config
    type(rider_identification_t) :: setup
    type(rider_fit_t) :: fit
    type(rider_params_t) :: variants(n_variants)
    type(status_t) :: variant_status(n_variants)
    real(wp) :: deviation(n_variants), cpu0, cpu1, mu_start
    logical :: coulomb
    type(result_file_t) :: file
    type(status_t) :: run_status, write_status
    character(len=:), allocatable :: message

    call check_known_groups(input, identify_rider_groups, status)
    call read_water_and_rider(input, default_solver(setup), .false., solver, water_description, setup%params, &
                              setup%options, limits, status)
    if (status%ok()) call require_coulomb_rider(input, setup%params, .false., 'identify_rider fits the '// &
                                                'Coulomb mu_D of the three contacts (&rider mu is its start)', status)
    if (status%ok()) call read_rider_identification_config(input, config, status)
    if (.not. status%ok()) return
    if (allocated(limits)) then
      if (size(limits) > 0) then
        call set_status(status, STATUS_INVALID_INPUT, input%name//': &rider: limit_quantity is not used by '// &
                        'identify_rider (a fit judges no limits; run the ride scenario with the identified mu)')
        return
      end if
    end if
    setup%slide = water_description%slide
    setup%options%ode = solver%options
    setup%options%output_step = solver%output_step
    setup%options%max_duration = 10*setup%slide%length()/setup%options%min_speed
    if (solver%duration_given) setup%options%max_duration = solver%duration
    setup%data = config%data
    setup%threads = config%threads
    setup%with_water = setup%params%drag
    call new_rider_identification(setup, status)
    if (.not. status%ok()) call prefix_status(status, '&identify')
    ! the same start the ride scenario refuses is refused here (not a failed fit)
    if (status%ok()) then
      call check_ride_start(setup%params, setup%slide, setup%options, status)
      if (.not. status%ok()) then
        call refuse_start(input, setup%params, status)
        return
      end if
    end if
    call rider_coulomb_mu(setup%params, mu_start, coulomb)
    if (.not. (mu_start >= config%options%lower .and. mu_start <= config%options%upper)) &
      call set_status(status, STATUS_INVALID_INPUT, 'the start value &rider mu = '// &
                      format_short(mu_start)//' must lie within &identify lower, upper = '// &
                      format_short(config%options%lower)//', '//format_short(config%options%upper))
    if (.not. status%ok()) then
      call prefix_status(status, input%name)
      status%code = STATUS_INVALID_INPUT
      return
    end if
    if (run%check_only) return
    deviation = -1
    cpu0 = 0
    cpu1 = 0

    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call file%write_provenance('identify_rider', trim(run%title), input%name, input%text(), write_status)
    if (setup%with_water) then
      call log_info('identify_rider: the water first')
      call compute_water(water_description, water, run_status, log_info)
      if (.not. run_status%ok()) call prefix_status(run_status, 'the water')
      setup%water = water%field
    end if
    if (run_status%ok() .and. config%twin) call synthesise(setup, config%twin_mu, run_status)
    if (run_status%ok()) then
      call log_info('identify_rider: fitting mu_D to '//format_integer(size(setup%data%station_arc_length))// &
                    ' stations and '//format_integer(size(setup%data%segment_start))//' segments')
      call cpu_time(cpu0)
      call fit_rider_friction(setup, config%options, mu_start, fit, run_status)
      call cpu_time(cpu1)
      if (run_status%ok()) call write_fit(file, setup, config, fit, cpu1 - cpu0, write_status)
    end if
    if (run_status%ok() .and. config%sensitivity) then
      call log_info('identify_rider: the body-parameter study (table 4.10)')
      call set_rider_mu(setup%params, fit%mu)
      variants = body_variants(setup%params)
      call rider_body_sensitivity(setup, variants, deviation, variant_status, run_status)
      if (run_status%ok()) call write_sensitivity(file, deviation, write_status)
    end if
    call write_slide_grid(file, setup%slide, write_status)
    message = run_message('ok', run_status, write_status)
    if (write_status%ok()) call attach_surface_view(file, 'slide surface', '/geometry/surface', write_status)
    call file%finish(run_status%ok() .and. write_status%ok(), message, write_status)
    if (run_status%ok()) call report(setup, config, fit, deviation, variant_status, cpu1 - cpu0, &
                                     file%final_path(), run, write_status%ok(), message, write_status)
    if (.not. (run_status%ok() .and. write_status%ok())) status = run_outcome(run_status, write_status)
  end subroutine run_identify_rider

  !> A twin experiment: the measurements are the ride of twin_mu at the places.
  subroutine synthesise(setup, twin_mu, status)
    type(rider_identification_t), intent(inout) :: setup
    real(wp), intent(in) :: twin_mu
    type(status_t), intent(inout) :: status
    type(rider_params_t) :: params
    type(rider_stations_t) :: simulated
    call log_info('identify_rider: twin measurements with mu_D = '//format_short(twin_mu))
    params = setup%params
    call set_rider_mu(params, twin_mu)
    call simulate_rider(setup, params, simulated, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'the twin measurements')
      return
    end if
    setup%data%angle = simulated%angle
    setup%data%segment_speed = simulated%segment_speed
  end subroutine synthesise

  !> The ride's integration (thesis B.7) as the &solver defaults.
  function default_solver(setup) result(defaults)
    type(rider_identification_t), intent(in) :: setup
    type(solver_config_t) :: defaults
    defaults%options = setup%options%ode
    defaults%output_step = setup%options%output_step
  end function default_solver

  subroutine write_fit(file, setup, config, fit, cpu, status)
    type(result_file_t), intent(inout) :: file
    type(rider_identification_t), intent(in) :: setup
    type(rider_identification_config_t), intent(in) :: config
    type(rider_fit_t), intent(in) :: fit
    real(wp), intent(in) :: cpu
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/identify_rider/'
    integer :: k
    call file%write_scalar(g//'mu', fit%mu, '1', 'identified Coulomb friction mu_D of the three contacts', status)
    call file%write_scalar(g//'standard_error', fit%standard_error, '1', &
                           'standard error of mu_D, s^2 (J^T J)^-1 at the optimum (0: at a bound)', status)
    if (config%twin) call file%write_scalar(g//'twin_mu', config%twin_mu, '1', &
      'the mu_D the twin measurements were simulated with', status)
    call write_identification_cost(file, g, fit, fit%k2, words(), status)
    call file%write_vector(g//'contact_part', fit%contact_part, 'rad^2', &
                           'the position part of each contact: pelvis, heels, back', status)
    call file%write_vector(g//'rmse_angle', fit%rmse_angle, 'rad', 'RMSE of each contact''s angle', status)
    call file%write_vector(g//'max_angle_error', fit%max_angle, 'rad', 'largest |error| of each contact''s angle', &
                           status)
    call write_identification_runs(file, g, fit, cpu, words(), status)
    call file%write_vector(g//'contact_number', [(real(k, wp), k=1, N_CONTACTS)], '1', &
                           '1 pelvis, 2 heels, 3 back; dimension scale', status)
    call file%make_scale(g//'contact_number', status)
    call file%attach_scale(g//'contact_number', g, status)
    if (size(setup%data%station_arc_length) > 0) then
      call file%write_vector(g//'stations/arc_length', setup%data%station_arc_length, 'm', &
                             'centerline arc length of each station (the pelvis crosses it); dimension scale', status)
      call file%write_matrix(g//'stations/measured_angle', setup%data%angle, 'rad', &
                             'measured wall angle of pelvis, heels, back (+ towards +v)', status)
      call file%write_matrix(g//'stations/simulated_angle', fit%simulated%angle, 'rad', &
                             'simulated wall angle at the optimum', status)
      call file%write_matrix(g//'stations/error', fit%error_angle, 'rad', 'simulated - measured', status)
      call file%write_vector(g//'stations/rmse', fit%station_rmse, 'rad', &
                             'RMSE over the three contacts at the station', status)
      call file%make_scale(g//'stations/arc_length', status)
      call file%attach_scale(g//'stations/arc_length', g//'stations/', status)
      call file%attach_scale(g//'contact_number', g//'stations/', status, axis=1)
    end if
    if (size(setup%data%segment_start) > 0) then
      call write_identification_segments(file, g, setup%data%segment_start, setup%data%segment_end, &
                                         setup%data%segment_speed, fit%simulated%segment_speed, fit%error_speed, &
                                         'measured speed: length over the passage time', &
                                         'simulated speed at the optimum (the pelvis''s passage)', status)
    end if
  end subroutine write_fit

  subroutine write_sensitivity(file, deviation, status)
    type(result_file_t), intent(inout) :: file
    real(wp), intent(in) :: deviation(:)
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/identify_rider/sensitivity/'
    integer :: k
    call file%write_vector(g//'variant', [(real(k, wp), k=1, size(deviation))], '1', &
                           'body variant (docs/design.md: mass +-1 %, height +-1 %, ...); dimension scale', status)
    call file%write_vector(g//'pelvis_deviation', deviation, 'm', &
                           'mean |pelvis wall distance - the identified ride''s| at the stations (-1: failed)', status)
    call file%make_scale(g//'variant', status)
    call file%attach_scale(g//'variant', g, status)
  end subroutine write_sensitivity

  subroutine report(setup, config, fit, deviation, variant_status, cpu, path, run, complete, message, status)
    type(rider_identification_t), intent(in) :: setup
    type(rider_identification_config_t), intent(in) :: config
    type(rider_fit_t), intent(in) :: fit
    real(wp), intent(in) :: deviation(:), cpu
    type(status_t), intent(in) :: variant_status(:)
    character(len=*), intent(in) :: path, message
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    real(wp), allocatable :: table(:, :)
    integer :: k, n
    n = size(setup%data%station_arc_length)
    call summary%start('identify_rider', 'slidesim identify_rider: mu_D from '//format_integer(n)// &
                       ' stations and '//format_integer(size(setup%data%segment_start))//' segments')
    call summary%add('mu', 'mu_D', fit%mu, declared_unit('sweep', 'mu'))
    call summary%add('standard_error', 'standard error', fit%standard_error, '1')
    if (fit%at_bound) call summary%add_text('at_bound', 'at a bound', 'yes: mu_D lies on lower or upper')
    call summarise_identification_cost(summary, fit, words())
    do k = 1, N_CONTACTS
      call summary%add('rmse_'//trim(contact_names(k)), 'RMSE '//trim(contact_names(k)), fit%rmse_angle(k), 'rad')
    end do
    call summarise_identification_runs(summary, fit, cpu, words())
    if (n > 0) then
      allocate (table(5, n))
      do k = 1, n
        table(:, k) = [setup%data%station_arc_length(k), fit%error_angle(:, k), fit%station_rmse(k)]
      end do
      call summary%add_table('stations', [character(len=12) :: 'arc_length', 'error_pelvis', 'error_heels', &
                             'error_back', 'rmse'], [character(len=3) :: 'm', 'rad', 'rad', 'rad', 'rad'], table)
      call summary%add_line('  station (m)   simulated - measured (rad): pelvis, heels, back      RMSE (rad)')
      do k = 1, n
        call summary%add_line('  '//format_with(table(1, k), 'f11.3')//'   '//format_with(table(2, k), 'es12.4')// &
                              format_with(table(3, k), 'es12.4')//format_with(table(4, k), 'es12.4')//'   '// &
                              format_with(table(5, k), 'es12.4'))
      end do
    end if
    if (size(setup%data%segment_start) > 0) then
      call summary%add_line('  segment (m)          speed measured, simulated (m/s)')
      do k = 1, size(setup%data%segment_start)
        call summary%add_line('  '//format_with(setup%data%segment_start(k), 'f8.3')//' .. '// &
                              format_with(setup%data%segment_end(k), 'f8.3')//'   '// &
                              format_with(setup%data%segment_speed(k), 'f10.4')// &
                              format_with(fit%simulated%segment_speed(k), 'f10.4'))
      end do
    end if
    if (config%sensitivity) then
      do k = 1, size(deviation)
        if (variant_status(k)%ok()) then
          call summary%add('deviation_'//format_integer(k), 'pelvis deviation, '//trim(variant_names(k)), &
                           deviation(k), 'm')
        else
          call summary%add_text('deviation_'//format_integer(k), 'pelvis deviation, '//trim(variant_names(k)), &
                                'the ride failed: '//variant_status(k)%text())
        end if
      end do
    end if
    call close_report(summary, run, path, complete, message, status)
  end subroutine report
end module scenarios_identify_rider
