!> Scenario `water`: the stationary water flow down a tube slide (thesis 4.2):
!> the streamline, water height, width and edges, a table over arc length and
!> a report at stations. The slide is a tube from &surface (kind = 'tube' or
!> 'slide' with geometry_file) or a closed-form tube from &channel.
module scenarios_water
  use, intrinsic :: iso_fortran_env, only: output_unit
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_log, only: log_info, log_warning
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_tube, only: tube_surface_t
  use numerics_ode, only: ode_stats_t
  use water_channel, only: channel_t, new_channel
  use water_streamline, only: streamline_t, CORRECTION_FULL, CORRECTION_NO_RADIUS
  use water_flow, only: water_series_t, water_table_t, water_initial_state, simulate_water, &
    water_table, outcome_name, OUTCOME_DURATION, START_EDGES
  use io_input, only: input_text_t, check_known_groups, group_present, invalid, format_real, mark_input_failure
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config, check_output_count
  use io_geometry_config, only: geometry_groups
  use io_surface_config, only: read_surface_config
  use io_water_config, only: water_config_t, read_water_config, read_channel_config
  use io_hdf5, only: result_file_t, units_per_second
  use io_summary, only: summary_t, degrees
  use base_text, only: format_short, format_integer
  use io_surface_grid, only: write_surface_grid, evenly_spaced
  use io_xdmf, only: xdmf_t, xdmf_path
  implicit none (type, external)
  private
  public :: run_water, build_water, water_groups

  character(len=*), parameter :: water_groups(11) = [character(len=14) :: 'run', 'solver', 'surface', &
    'channel', 'water', geometry_groups]
  !> Without &solver duration the water runs to the end of the slide; as a
  !> safety bound it stops (failed) after this many times the time the slide
  !> takes at min_speed.
  real(wp), parameter :: safety_factor = 10
  !> numbers stored per output time (water_series_t)
  integer, parameter :: values_per_output = 64
  !> most rows of the table over arc length
  real(wp), parameter :: max_table_rows = 1e6_wp
  integer, parameter :: grid_n_u = 400, grid_n_v = 48   ! the written surface grid

contains

  !> Reads and checks every input group, builds the model and its start state;
  !> nothing is written.
  subroutine build_water(input, solver, config, model, y0, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(out) :: solver
    type(water_config_t), intent(out) :: config
    type(streamline_t), intent(out) :: model
    real(wp), intent(out) :: y0(7)
    type(status_t), intent(inout) :: status
    class(surface_t), allocatable :: surface
    type(tube_surface_t) :: tube
    real(wp) :: u_min, u_max, v_min, v_max, total, start_speed
    type(surface_point_t) :: start_point
    real(wp), parameter :: plausible_speed = 30   ! m/s
    integer :: i

    y0 = 0
    call check_known_groups(input, water_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (.not. status%ok()) return
    if (group_present(input, 'surface') .and. group_present(input, 'channel')) then
      call set_status(status, STATUS_INVALID_INPUT, input%name//': give the slide either by &surface ' // &
                      '(a tube or slide) or by &channel, not both')
      return
    end if
    if (group_present(input, 'surface')) then
      call read_surface_config(input, surface, status)
      call mark_input_failure(status)
      if (.not. status%ok()) return
      select type (surface)
      type is (tube_surface_t)
        allocate (model%channel, source=new_channel(surface))
      class default
        call set_status(status, STATUS_INVALID_INPUT, input%name//': &surface: the water needs a tube ' // &
                        '(kind = ''tube'' or ''slide''), not a '//surface%describe())
        return
      end select
    else
      call read_channel_config(input, tube, status)
      if (.not. status%ok()) return
      allocate (model%channel, source=new_channel(tube))
    end if
    call read_water_config(input, config, status)
    if (.not. status%ok()) return

    model%mass = config%mass
    model%gravity = config%gravity
    model%f1 = config%f1; model%f2 = config%f2; model%f3 = config%f3
    model%correction = config%correction
    model%flow_rate = config%flow_rate
    model%min_speed = config%min_speed
    model%min_criticality = config%min_criticality

    call model%channel%u_range(u_min, u_max)
    call model%channel%v_range(v_min, v_max)
    if (config%start%u0 < u_min .or. config%start%u0 >= u_max) then
      call invalid(input, 'water', 'u0', format_real(config%start%u0), 'the start must lie on the slide, ' // &
                   'u in ['//format_real(u_min)//', '//format_real(u_max)//')', status)
      return
    end if
    ! the start edges (start = 'edges') or the water middle v0 (other starts)
    ! must lie on an open section's surface; the message names what was given
    if (config%start%mode == START_EDGES) then
      if (config%start%v_left > v_max .or. config%start%v_right < v_min) then
        call invalid(input, 'water', 'v_left0, v_right0', format_real(config%start%v_left)//', '// &
                     format_real(config%start%v_right), 'the start edges must lie inside the cross-section, '// &
                     'v in ['//format_real(v_min)//', '//format_real(v_max)//'] rad', status)
        return
      end if
    else if (config%start%v0 < v_min .or. config%start%v0 > v_max) then
      call invalid(input, 'water', 'v0', format_real(config%start%v0), &
                   'the start must lie inside the cross-section, v in ['//format_real(v_min)//', '// &
                   format_real(v_max)//'] rad', status)
      return
    end if
    total = model%channel%arc_length(u_max)
    if (total/config%table_step > max_table_rows) then
      call invalid(input, 'water', 'table_step', format_real(config%table_step), 'the table over the '// &
                   format_real(total)//' m of slide would have more than '//format_real(max_table_rows)// &
                   ' rows; raise table_step', status)
      return
    end if
    allocate (model%stations(size(config%stations)))
    do i = 1, size(config%stations)
      if (config%stations(i) > total) then
        call invalid(input, 'water', 'stations', format_real(config%stations(i)), &
                     'stations must lie on the slide (arc length <= '//format_real(total)//' m)', status)
        return
      end if
      call model%channel%parameter_at_length(config%stations(i), model%stations(i), status)
      call mark_input_failure(status)
      if (.not. status%ok()) return
    end do
    call water_initial_state(model, config%start, y0, status)
    if (.not. status%ok()) then
      call prefix_status(status, input%name//': &water: start')
      status%code = STATUS_INVALID_INPUT
      return
    end if
    ! Water in a slide runs at a few m/s; a start far beyond that is almost
    ! always a unit mistake (flow_rate in l/s instead of m^3/s, a height in mm).
    call model%channel%evaluate(y0(1), y0(2), 1, start_point, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    start_speed = norm2(y0(3)*start_point%ru + y0(4)*start_point%rv)
    if (start_speed > plausible_speed) call log_warning(input%name//': &water: the start speed is '// &
      format_real(start_speed)//' m/s, far above the few m/s of water in a slide; check flow_rate (m^3/s) '// &
      'and the start height (m)')
  end subroutine build_water

  subroutine run_water(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(water_config_t) :: config
    type(streamline_t), target :: model
    type(water_series_t) :: series
    type(water_table_t) :: table
    type(result_file_t) :: file
    type(status_t) :: run_status, write_status
    real(wp) :: y0(7), cpu_start, cpu_end, t_end, total, u_min, u_max
    logical :: complete
    character(len=:), allocatable :: message, done

    call build_water(input, solver, config, model, y0, status)
    if (.not. status%ok()) return
    call model%channel%u_range(u_min, u_max)
    total = model%channel%arc_length(u_max)
    if (solver%duration_given) then
      t_end = solver%duration
      call check_output_count(input, solver, t_end, values_per_output, 'water', status)
    else
      t_end = safety_factor*total/config%min_speed
    end if
    if (.not. status%ok() .or. run%check_only) return
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call log_info('water: '//model%channel%describe()//', Q = '//format_real(model%flow_rate)//' m^3/s')
    call cpu_time(cpu_start)
    call simulate_water(model, y0, solver%options, t_end, solver%output_step, series, &
                        run_status, edges=config%edges)
    done = 'ok: '//outcome_name(series%outcome)
    if (run_status%ok() .and. series%outcome == OUTCOME_DURATION) then
      if (solver%duration_given) then
        ! the user's bound: what was asked for, but say that the slide's end was not reached
        done = 'ok: stopped at &solver duration = '//format_real(t_end)//' s, '// &
               format_real(series%arc_length(series%n))//' m down the '//format_real(total)// &
               ' m slide (its end not reached)'
      else
        call set_status(run_status, STATUS_DOMAIN, 'the water did not reach the end of the slide within t = '// &
                        format_real(t_end)//' s ('//format_real(safety_factor)//' x slide length / min_speed), '// &
                        'at '//format_real(series%arc_length(series%n))//' m of '//format_real(total)// &
                        ' m; give &solver duration to bound the run')
      end if
    end if
    call water_table(series, model, config%table_step, table)
    call cpu_time(cpu_end)
    call write_results(file, input, run, model, config, series, table, cpu_end - cpu_start, write_status)
    complete = run_status%ok() .and. write_status%ok()
    message = done
    if (.not. write_status%ok()) message = write_status%text()
    if (.not. run_status%ok()) message = run_status%text()
    call file%finish(complete, message, write_status)
    if (write_status%ok()) call write_xdmf(file, write_status)
    call report(model, series, cpu_end - cpu_start, file%final_path(), run, complete, message, write_status)
    if (.not. run_status%ok()) then
      status = run_status
    else if (.not. write_status%ok()) then
      status = write_status
    end if
  end subroutine run_water

  subroutine write_results(file, input, run, model, config, s, table, cpu, status)
    type(result_file_t), intent(inout) :: file
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(streamline_t), intent(in) :: model
    type(water_config_t), intent(in) :: config
    type(water_series_t), intent(in) :: s
    type(water_table_t), intent(in) :: table
    real(wp), intent(in) :: cpu
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/water/', t = '/water/table/', st = '/water/stations/'
    integer :: n, i
    character(len=16) :: mode
    character(len=:), allocatable :: uu, vu   ! units of u and v of this channel
    real(wp), allocatable :: col(:)   ! a contiguous station column

    n = s%n
    call model%channel%parameter_units(uu, vu)
    call file%write_provenance('water', trim(run%title), input%name, input%text(), status)
    call file%write_vector(g//'time', s%time(:n), 's', 'time', status)
    call file%write_vector(g//'arc_length', s%arc_length(:n), 'm', &
                           'arc length of the centerline at the water point (from the slide start)', status)
    call file%write_vector(g//'u', s%u(:n), uu, 'surface coordinate u (along the slide)', status)
    call file%write_vector(g//'v', s%v(:n), vu, 'surface coordinate v (across; pi/2 = bottom)', status)
    call file%write_vector(g//'du', s%du(:n), units_per_second(uu), 'rate of u', status)
    call file%write_vector(g//'dv', s%dv(:n), units_per_second(vu), 'rate of v', status)
    call file%write_matrix(g//'position', s%position(:, :n), 'm', 'streamline point (3 x n)', status)
    call file%write_matrix(g//'velocity', s%velocity(:, :n), 'm/s', 'water velocity (3 x n)', status)
    call file%write_vector(g//'speed', s%speed(:n), 'm/s', 'water speed w', status)
    call file%write_vector(g//'height', s%height(:n), 'm', 'water height h (4.24)', status)
    call file%write_vector(g//'width', s%width(:n), 'm', 'water width b (4.19, 4.47)', status)
    call file%write_vector(g//'area', s%area(:n), 'm^2', 'water cross-section area A (F.1, 4.45)', status)
    call file%write_vector(g//'radius', s%radius(:n), 'm', &
                           'equivalent circle radius R (4.15); 0 for non-circular sections', status)
    call file%write_vector(g//'beta', s%beta(:n), 'rad', 'angle between flow and centerline (+ towards +v)', &
                           status)
    call file%write_vector(g//'alpha', s%alpha(:n), 'rad', 'central angle of the water (4.19)', status)
    call file%write_vector(g//'normal_force', s%normal_force(:n), 'N', &
                           'normal force on the 1 kg streamline mass (4.12)', status)
    call file%write_vector(g//'friction_force', s%friction_force(:n), 'N', 'friction F_R (4.7)', status)
    call file%write_vector(g//'curvature', s%curvature(:n), '1/m', 'centerline curvature chi (4.8)', status)
    call file%write_vector(g//'froude', s%froude(:n), '1', 'Froude number sqrt(m b w^2/(N A))', status)
    call file%write_vector(g//'kinetic_energy', s%kinetic(:n), 'J', 'kinetic energy of the 1 kg mass', status)
    call file%write_vector(g//'potential_energy', s%potential(:n), 'J', 'potential energy -m g.r', status)
    call file%write_vector(g//'energy', s%kinetic(:n) + s%potential(:n), 'J', 'kinetic + potential energy', &
                           status)
    call file%write_vector(g//'friction_work', s%friction_work(:n), 'J', &
                           'work done by friction since the start (<= 0)', status)
    call file%write_vector(g//'correction_work', s%correction_work(:n), 'J', &
                           'work done by the Saint-Venant term since the start', status)
    call file%write_vector(g//'left_edge_u', s%left_edge(1, :n), uu, 'u of the left water edge, towards +v (4.25)', &
                           status)
    call file%write_vector(g//'left_edge_v', s%left_edge(2, :n), vu, 'v of the left water edge (4.25)', status)
    call file%write_vector(g//'right_edge_u', s%right_edge(1, :n), uu, 'u of the right water edge (4.26)', status)
    call file%write_vector(g//'right_edge_v', s%right_edge(2, :n), vu, 'v of the right water edge (4.26)', status)
    call file%write_matrix(g//'left_point', s%left_point(:, :n), 'm', 'left water edge point (3 x n)', status)
    call file%write_matrix(g//'right_point', s%right_point(:, :n), 'm', 'right water edge point (3 x n)', status)
    call file%write_integers(g//'edge_solved', s%edge_solved(:n), '1', &
                             '1: edges solved (4.25-4.26); 0: circle estimate (edge beyond the slide''s end, ' // &
                             'failed, or edges off)', &
                             status)
    call file%set_attribute('/water', 'outcome', outcome_name(s%outcome), status)
    call file%set_attribute('/water', 'flow_rate_m3_per_s', s%flow_rate, status)
    mode = 'off'
    if (model%correction == CORRECTION_FULL) mode = 'full'
    if (model%correction == CORRECTION_NO_RADIUS) mode = 'no_radius'
    call file%set_attribute('/water', 'correction', trim(mode), status)
    call file%set_attribute('/water', 'friction_f1_f2_f3', [model%f1, model%f2, model%f3], status)

    call file%write_vector(t//'arc_length', table%arc_length, 'm', 'centerline arc length', status)
    call file%write_vector(t//'u', table%u, uu, 'u at that arc length', status)
    call file%write_vector(t//'time', table%time, 's', 'time the water point passes', status)
    call file%write_vector(t//'v', table%v, vu, 'v of the water middle', status)
    call file%write_vector(t//'speed', table%speed, 'm/s', 'water speed', status)
    call file%write_vector(t//'height', table%height, 'm', 'water height', status)
    call file%write_vector(t//'width', table%width, 'm', 'water width', status)
    call file%write_vector(t//'beta', table%beta, 'rad', 'flow angle to the centerline', status)
    call file%write_vector(t//'v_left', table%v_left, vu, 'v of the left edge', status)
    call file%write_vector(t//'v_right', table%v_right, vu, 'v of the right edge', status)
    if (size(table%arc_length) > 0) then
      call file%make_scale(t//'arc_length', status)
      call file%attach_scale(t//'arc_length', t, status)
    end if

    if (size(s%stations) > 0) then
      call file%write_vector(st//'arc_length', config%stations, 'm', 'station arc length (input)', status)
      col = s%stations%u
      call file%write_vector(st//'u', col, uu, 'u of the station', status)
      col = s%stations%time
      call file%write_vector(st//'time', col, 's', 'time the water passes', status)
      col = s%stations%v
      call file%write_vector(st//'v', col, vu, 'v of the streamline', status)
      col = s%stations%v_middle
      call file%write_vector(st//'v_middle', col, vu, &
                             'v of the middle between the edges (as measured, 4.32)', status)
      col = s%stations%v_left
      call file%write_vector(st//'v_left', col, vu, 'v of the left edge', status)
      col = s%stations%v_right
      call file%write_vector(st//'v_right', col, vu, 'v of the right edge', status)
      col = s%stations%speed
      call file%write_vector(st//'speed', col, 'm/s', 'water speed', status)
      col = s%stations%height
      call file%write_vector(st//'height', col, 'm', 'water height', status)
      col = s%stations%width
      call file%write_vector(st//'width', col, 'm', 'water width', status)
      call file%write_integers(st//'reached', [(merge(1, 0, s%stations(i)%reached), i = 1, size(s%stations))], &
                               '1', '1 if the water reached the station', status)
      call file%make_scale(st//'arc_length', status)
      call file%attach_scale(st//'arc_length', st, status)
    end if
    if (n > 0) then
      call file%make_scale(g//'time', status)
      call file%attach_scale(g//'time', '/water', status)
    end if
    call write_channel_grid(file, model%channel, status)
    call write_stats(file, s%stats, cpu, status)
  end subroutine write_results

  !> The XDMF file next to the result: the slide, the streamline with its
  !> fields, and the water band with speed and height.
  subroutine write_xdmf(file, status)
    type(result_file_t), intent(in) :: file
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    call xdmf%start(file%final_path())
    call xdmf%surface(file, 'slide surface', '/geometry/surface')
    call xdmf%polyline(file, 'streamline', '/water/position', '/water')
    call xdmf%band(file, 'water band', '/water/right_point', '/water/left_point', &
                   [character(len=13) :: '/water/speed', '/water/height'])
    call xdmf%write(xdmf_path(file%final_path()), status)
  end subroutine write_xdmf

  !> The slide surface the water ran on: the whole u range, across the
  !> section (a closed tube's full turn).
  subroutine write_channel_grid(file, channel, status)
    type(result_file_t), intent(inout) :: file
    class(channel_t), intent(in) :: channel
    type(status_t), intent(inout) :: status
    real(wp) :: u_min, u_max, v_min, v_max
    real(wp), parameter :: full_turn = 2*acos(-1.0_wp)
    call channel%u_range(u_min, u_max)
    call channel%v_range(v_min, v_max)
    if (v_min < -full_turn .or. v_max > 2*full_turn) then   ! a closed tube (+-huge): one turn
      v_min = 0; v_max = full_turn
    end if
    call write_surface_grid(file, channel%tube, evenly_spaced(u_min, u_max, grid_n_u), &
                            evenly_spaced(v_min, v_max, grid_n_v), status)
  end subroutine write_channel_grid

  subroutine write_stats(file, stats, cpu, status)
    type(result_file_t), intent(inout) :: file
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    type(status_t), intent(inout) :: status
    call file%write_count('/statistics/steps', int(stats%steps), '1', 'integrator steps', status)
    call file%write_count('/statistics/rhs_evaluations', int(stats%rhs_evaluations), '1', &
                          'right-hand-side evaluations', status)
    call file%write_count('/statistics/error_test_failures', int(stats%error_test_failures), '1', &
                          'error test failures', status)
    call file%write_scalar('/statistics/cpu_time', cpu, 's', 'CPU time of the water computation', status)
  end subroutine write_stats

  !> The printed summary and, with --summary-json, the same numbers as JSON.
  subroutine report(model, s, cpu, path, run, complete, message, status)
    type(streamline_t), intent(in) :: model
    type(water_series_t), intent(in) :: s
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: path, message
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    real(wp), allocatable :: table(:, :)
    character(len=:), allocatable :: uu, vu
    integer :: n, i
    n = s%n
    if (n < 1) return
    call model%channel%parameter_units(uu, vu)
    call summary%start('water', 'slidesim water in '//model%channel%describe())
    call summary%add('flow_rate', 'flow rate', s%flow_rate, 'm^3/s', 'l/s', 1000.0_wp)
    call summary%add('flow_time', 'flow time', s%time(n), 's')
    call summary%add('slide_length_covered', 'slide length covered', s%arc_length(n) - s%arc_length(1), 'm')
    call summary%add_text('outcome', 'stopped at', outcome_name(s%outcome))
    call summary%add_range('speed', 'speed min / max', minval(s%speed(:n)), maxval(s%speed(:n)), 'm/s')
    call summary%add('final_speed', 'final speed', s%speed(n), 'm/s')
    call summary%add_range('height', 'height min / max', minval(s%height(:n)), maxval(s%height(:n)), 'm', &
                           'mm', 1000.0_wp)
    call summary%add_range('width', 'width min / max', minval(s%width(:n)), maxval(s%width(:n)), 'm', 'mm', &
                           1000.0_wp)
    call summary%add_range('flow_angle', 'flow angle min / max', minval(s%beta(:n)), maxval(s%beta(:n)), &
                           'rad', 'deg', degrees)
    if (vu == 'rad') then
      call summary%add_range('v', 'v min / max', minval(s%v(:n)), maxval(s%v(:n)), 'rad', &
                             'deg (90 = bottom)', degrees)
    else
      call summary%add_range('v', 'v min / max', minval(s%v(:n)), maxval(s%v(:n)), vu)
    end if
    call summary%add_count('steps', 'integrator', int(s%stats%steps), 'steps')
    call summary%add_count('rhs_evaluations', 'right-hand sides', int(s%stats%rhs_evaluations), 'evaluations')
    call summary%add('cpu_time', 'CPU time', cpu, 's')
    if (s%edge_beyond > 0) call summary%add_line('  water edges               '//format_integer(s%edge_beyond)// &
      ' samples from arc length '//format_short(s%edge_beyond_from)// &
      ' m: an edge beyond the slide''s end (circle estimate)')
    if (s%edge_failures > 0) call summary%add_line('  water edges               '//format_integer(s%edge_failures)// &
      ' samples where the edge solve failed (circle estimate); first '//s%edge_message)
    if (size(s%stations) > 0) then
      allocate (table(10, size(s%stations)))
      do i = 1, size(s%stations)
        associate (st => s%stations(i))
          table(:, i) = [st%arc_length, st%time, st%v_middle, st%v_right, st%v_left, st%speed, st%height, &
                         st%width, st%u, merge(1.0_wp, 0.0_wp, st%reached)]
        end associate
      end do
      call summary%add_table('stations', [character(len=10) :: 'arc_length', 'time', 'v_middle', 'v_right', &
                             'v_left', 'speed', 'height', 'width', 'u', 'reached'], &
                             [character(len=4) :: 'm', 's', vu, vu, vu, 'm/s', 'm', 'm', uu, '1'], table)
    end if
    call summary%print()
    if (size(s%stations) > 0) then
      write (output_unit, '(a)') '  station  arc length    time   v middle   v edges (right, left)   speed   height' &
        //'   width'
      write (output_unit, '(a)') '                  m        s'//column(vu)//column(vu)//column(vu)// &
        '      m/s        m        m'
      do i = 1, size(s%stations)
        if (s%stations(i)%reached) then
          write (output_unit, '(2x, i5, f12.3, f9.4, 3f11.4, f9.4, 2f9.5)') i, table(1:8, i)
        else
          write (output_unit, '(2x, i5, a)') i, '   (not reached)'
        end if
      end do
    end if
    if (complete) then
      write (output_unit, '(a)') '  results                   '//path
    else
      write (output_unit, '(a)') '  results (INCOMPLETE)      '//path
    end if
    if (allocated(run%summary_json)) then
      if (len(run%summary_json) > 0) call summary%write_json(run%summary_json, complete, message, path, status)
    end if
  contains
    pure function column(units) result(text)   ! a unit right-aligned in the 11 characters of f11.4
      character(len=*), intent(in) :: units
      character(len=11) :: text
      text = repeat(' ', max(0, 11 - len(units)))//units
    end function column
  end subroutine report
end module scenarios_water
