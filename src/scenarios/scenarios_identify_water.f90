!> Scenario `identify_water`: the water's friction f1, f2, f3 from measured
!> positions of the flow at sections and speeds on segments (thesis 4.4.1,
!> cost 4.34; docs/design.md). The slide and the water as in the `water`
!> scenario (&surface or &channel, &water: its f1, f2, f3 are the start
!> values, its start the measured start 4.33; &solver the integration), the
!> measurements and the fit in &identify. /identify_water holds the estimates
!> with standard errors and correlations, the cost and its parts, and the
!> measured and simulated values at every section and segment; the weight
!> sweep of table 4.2 on request.
module scenarios_identify_water
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_integer, format_short, format_with
  use base_log, only: log_info
  use water_run, only: water_description_t
  use design_water_identification, only: water_identification_t, water_fit_t, new_water_identification, &
    simulate_measurements, fit_water_friction, water_weight_sweep
  use io_input, only: input_text_t, check_known_groups, where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_geometry_config, only: geometry_groups
  use io_water_identification_config, only: water_identification_config_t, read_water_identification_config
  use io_hdf5, only: result_file_t, run_outcome, run_message
  use io_identification_results, only: identification_words_t, write_identification_segments, &
    write_identification_cost, write_identification_runs, summarise_identification_cost, &
    summarise_identification_runs
  use io_summary, only: summary_t
  use io_input_declarations, only: declared_unit
  use io_xdmf, only: attach_surface_view
  use scenarios_water, only: build_water, write_slide_grid
  use scenarios_report, only: close_report
  implicit none (type, external)
  private
  public :: run_identify_water, identify_water_groups

  character(len=*), parameter :: identify_water_groups(12) = [character(len=14) :: 'run', 'solver', 'surface', &
    'channel', 'water', 'identify', geometry_groups]


contains

  !> How the results name the fit's pieces (io_identification_results).
  pure function words() result(w)
    type(identification_words_t) :: w
    w = identification_words_t(weight='w', k='k1', cost='F1', &
      equation='(4.34)', runs_note='water runs of the fit', rejected_note='water runs that failed (rejected steps)', &
      runs_label='water runs', runs_unit='runs')
  end function words

  subroutine run_identify_water(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(water_description_t) :: water
    type(water_identification_config_t) :: config
    type(water_identification_t) :: setup
    type(water_fit_t) :: fit
    type(water_fit_t), allocatable :: sweep(:)
    real(wp) :: f_start(3), cpu0, cpu1
    type(result_file_t) :: file
    type(status_t) :: run_status, write_status
    character(len=:), allocatable :: message

    call check_known_groups(input, identify_water_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call build_water(input, water, status, stage=.true.)
    if (status%ok()) call read_water_identification_config(input, config, status)
    if (.not. status%ok()) return
    if (allocated(water%stations)) then
      if (size(water%stations) > 0) then
        call set_status(status, STATUS_INVALID_INPUT, input%name//': &water: stations are not used by '// &
                        'identify_water (the places of the measurements are in &identify)')
        return
      end if
    end if
    setup%water = water
    setup%ode = solver%options
    setup%data = config%data
    setup%speed_kind = config%speed_kind
    setup%middle_kind = config%middle_kind
    setup%threads = config%threads
    f_start = [water%f1, water%f2, water%f3]
    call new_water_identification(setup, status)
    if (status%ok() .and. .not. all(f_start >= config%options%lower .and. f_start <= config%options%upper)) &
      call set_status(status, STATUS_INVALID_INPUT, 'the start values &water f1, f2, f3 = '// &
                      format_short(f_start(1))//', '//format_short(f_start(2))//', '//format_short(f_start(3))// &
                      ' must lie within &identify lower .. upper')
    if (.not. status%ok()) then
      if (index(status%message, 'the measurement places') == 1) then
        call prefix_status(status, where_given(input, 'identify', 'section_arc_length')// &
                           ': &identify: section_arc_length, segment_start')
      else
        call prefix_status(status, input%name)
      end if
      status%code = STATUS_INVALID_INPUT
      return
    end if
    if (run%check_only) return
    cpu0 = 0
    cpu1 = 0

    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call file%write_provenance('identify_water', trim(run%title), input%name, input%text(), write_status)
    if (config%twin) then
      call log_info('identify_water: twin measurements with f = '//format_short(config%twin_f(1))//', '// &
                    format_short(config%twin_f(2))//', '//format_short(config%twin_f(3)))
      call simulate_measurements(setup, config%twin_f, setup%data%section_v, setup%data%segment_speed, run_status)
      if (.not. run_status%ok()) call prefix_status(run_status, 'the twin measurements')
    end if
    if (run_status%ok()) then
      call log_info('identify_water: fitting f to '//format_integer(size(setup%data%section_v))// &
                    ' sections and '//format_integer(size(setup%data%segment_speed))//' segments')
      call cpu_time(cpu0)
      call fit_water_friction(setup, config%options, f_start, fit, run_status)
      call cpu_time(cpu1)
      if (run_status%ok()) call write_fit(file, setup, config, fit, cpu1 - cpu0, write_status)
    end if
    if (run_status%ok() .and. size(config%sweep_weights) > 0) then
      call log_info('identify_water: the weight sweep (table 4.2)')
      call water_weight_sweep(setup, config%options, config%sweep_weights, f_start, sweep, run_status)
      if (run_status%ok()) call write_sweep(file, config%sweep_weights, sweep, write_status)
    end if
    call write_slide_grid(file, setup%water%slide, write_status)
    message = run_message('ok', run_status, write_status)
    if (write_status%ok()) call attach_surface_view(file, 'slide surface', '/geometry/surface', write_status)
    call file%finish(run_status%ok() .and. write_status%ok(), message, write_status)
    if (run_status%ok()) call report(setup, fit, cpu1 - cpu0, file%final_path(), run, write_status%ok(), &
                                     message, write_status)
    if (.not. (run_status%ok() .and. write_status%ok())) status = run_outcome(run_status, write_status)
  end subroutine run_identify_water

  subroutine write_fit(file, setup, config, fit, cpu, status)
    type(result_file_t), intent(inout) :: file
    type(water_identification_t), intent(in) :: setup
    type(water_identification_config_t), intent(in) :: config
    type(water_fit_t), intent(in) :: fit
    real(wp), intent(in) :: cpu
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/identify_water/'
    integer :: k
    call file%write_vector(g//'parameter_number', [(real(k, wp), k=1, 3)], '1', &
                           '1 f1 (kg/m), 2 f2 (kg), 3 f3 (kg m); dimension scale', status)
    call file%write_vector(g//'f', fit%f, '1', 'identified f1 (kg/m), f2 (kg), f3 (kg m)', status)
    call file%write_vector(g//'standard_error', fit%standard_error, '1', &
                           'their standard errors, s^2 (J^T J)^-1 at the optimum (0: held or at a bound)', status)
    call file%write_matrix(g//'correlation', fit%correlation, '1', 'their correlation matrix', status)
    call file%write_integers(g//'estimated', merge(1, 0, fit%estimated), '1', '1: estimated, 0: held', status)
    if (config%twin) call file%write_vector(g//'twin_f', config%twin_f, '1', &
      'the f1, f2, f3 the twin measurements were simulated with', status)
    call file%make_scale(g//'parameter_number', status)
    call file%attach_scale(g//'parameter_number', g, status)
    call file%attach_scale(g//'parameter_number', g, status, axis=1)   ! the correlation's columns
    call write_identification_cost(file, g, fit, fit%k1, words(), status)
    call file%write_scalar(g//'rmse_position', fit%rmse_position, 'rad', 'RMSE of the middle angles', status)
    call write_identification_runs(file, g, fit, cpu, words(), status)
    if (size(setup%data%section_v) > 0) then
      call file%write_vector(g//'sections/arc_length', setup%data%section_arc_length, 'm', &
                             'centerline arc length of each section; dimension scale', status)
      call file%write_vector(g//'sections/measured_v', setup%data%section_v, 'rad', &
                             'measured middle of the flow (pi/2: the bottom)', status)
      call file%write_vector(g//'sections/simulated_v', fit%simulated_v, 'rad', &
                             'simulated middle at the optimum', status)
      call file%write_vector(g//'sections/error', fit%error_v, 'rad', 'simulated - measured', status)
      call file%make_scale(g//'sections/arc_length', status)
      call file%attach_scale(g//'sections/arc_length', g//'sections/', status)
    end if
    if (size(setup%data%segment_speed) > 0) then
      call write_identification_segments(file, g, setup%data%segment_start, setup%data%segment_end, &
                                         setup%data%segment_speed, fit%simulated_speed, fit%error_speed, &
                                         'measured speed', 'simulated speed at the optimum', status)
    end if
  end subroutine write_fit

  !> Table 4.2: every weight's f, cost, parts and errors.
  subroutine write_sweep(file, weights, fits, status)
    type(result_file_t), intent(inout) :: file
    real(wp), intent(in) :: weights(:)
    type(water_fit_t), intent(in) :: fits(:)
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/identify_water/sweep/'
    real(wp) :: f(3, size(fits))
    integer :: k
    do k = 1, size(fits)
      f(:, k) = fits(k)%f
    end do
    call file%write_vector(g//'weight', weights, '1', 'the weight w of each fit; dimension scale', status)
    call file%write_matrix(g//'f', f, '1', 'f1 (kg/m), f2 (kg), f3 (kg m) of each fit', status)
    call file%write_vector(g//'cost', fits%cost, 'rad^2', 'F1 (4.34)', status)
    call file%write_vector(g//'position_part', fits%position_part, 'rad^2', 'its position part', status)
    call file%write_vector(g//'speed_part', fits%speed_part, 'rad^2', 'its speed part', status)
    call file%write_vector(g//'mae_position', fits%mae_position, 'rad', 'MAE of the middle angles', status)
    call file%write_vector(g//'mae_speed', fits%mae_speed, 'm/s', 'MAE of the speeds', status)
    call file%make_scale(g//'weight', status)
    call file%attach_scale(g//'weight', g, status)
  end subroutine write_sweep

  subroutine report(setup, fit, cpu, path, run, complete, message, status)
    type(water_identification_t), intent(in) :: setup
    type(water_fit_t), intent(in) :: fit
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: path, message
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    real(wp), allocatable :: table(:, :)
    character(len=:), allocatable :: unit
    integer :: k, n
    n = size(setup%data%section_v)
    call summary%start('identify_water', 'slidesim identify_water: f1, f2, f3 from '//format_integer(n)// &
                       ' sections and '//format_integer(size(setup%data%segment_speed))//' segments')
    do k = 1, 3
      unit = declared_unit('water', 'f'//format_integer(k))
      call summary%add('f'//format_integer(k), 'f'//format_integer(k), fit%f(k), unit)
      call summary%add('f'//format_integer(k)//'_standard_error', 'its standard error', fit%standard_error(k), unit)
    end do
    call summary%add('correlation_12', 'correlation f1, f2', fit%correlation(1, 2), '1')
    call summary%add('correlation_13', 'correlation f1, f3', fit%correlation(1, 3), '1')
    call summary%add('correlation_23', 'correlation f2, f3', fit%correlation(2, 3), '1')
    call summarise_identification_cost(summary, fit, words())
    call summary%add('rmse_position', 'RMSE middle angle', fit%rmse_position, 'rad')
    call summarise_identification_runs(summary, fit, cpu, words())
    if (n > 0) then
      allocate (table(2, n))
      table(1, :) = setup%data%section_arc_length
      table(2, :) = fit%error_v
      call summary%add_table('sections', [character(len=10) :: 'arc_length', 'error'], &
                             [character(len=3) :: 'm', 'rad'], table)
      call summary%add_line('  section (m)   simulated - measured middle (rad)')
      do k = 1, n
        call summary%add_line('  '//format_with(table(1, k), 'f11.3')//'   '//format_with(table(2, k), 'es12.4'))
      end do
    end if
    call close_report(summary, run, path, complete, message, status)
  end subroutine report
end module scenarios_identify_water
