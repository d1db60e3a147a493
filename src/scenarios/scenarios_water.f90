!> Scenario `water`: the stationary water flow down a tube slide (thesis 4.2):
!> the streamline, water height, width and edges, a table over arc length and
!> a report at stations. The slide is a tube from &surface (kind = 'tube' or
!> 'slide' with geometry_file) or a closed-form tube from &channel.
module scenarios_water
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_log, only: log_info, log_warning
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_tube, only: tube_surface_t
  use geometry_slide_query, only: slide_surface_t
  use numerics_ode, only: ode_stats_t
  use water_channel, only: channel_t, new_channel
  use water_streamline, only: streamline_t
  use water_flow, only: water_series_t, outcome_name, START_EDGES
  use water_run, only: water_description_t, water_result_t, new_streamline, compute_water
  use water_inlet, only: start_tolerance
  use water_curve_entry, only: curve_entry_note, splash_note
  use io_input, only: input_text_t, check_known_groups, group_present, invalid, format_real, mark_input_failure, &
    where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config, check_output_count
  use io_geometry_config, only: geometry_groups
  use io_surface_config, only: read_surface_config, surface_source_t, explain_surface_failure
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_water_config, only: read_water_config, read_channel_config, explain_channel_failure
  use geometry_channel, only: channel_description_t, build_channel
  use io_hdf5, only: result_file_t, run_outcome, run_message
  use io_water_results, only: write_water_results
  use io_system, only: write_standard_output
  use io_summary, only: summary_t, degrees
  use io_input_declarations, only: declared_unit
  use base_text, only: format_short, format_integer
  use io_surface_grid, only: write_surface_grid
  use base_grid, only: evenly_spaced
  use io_xdmf, only: xdmf_t
  use scenarios_report, only: end_report, add_run_cost
  implicit none (type, external)
  private
  public :: run_water, build_water, water_groups, write_slide_grid

  character(len=*), parameter :: water_groups(12) = [character(len=14) :: 'run', 'solver', 'surface', &
    'channel', 'water', 'inlet', geometry_groups]
  !> numbers stored per output time (water_series_t)
  integer, parameter :: values_per_output = 72
  !> most rows of the table over arc length
  real(wp), parameter :: max_table_rows = 1e6_wp
  integer, parameter :: grid_n_u = 400, grid_n_v = 48   ! the written surface grid

contains

  !> Reads and checks every input group and gives the water's description
  !> (what water_run computes); nothing is run or written. As a stage of
  !> another scenario (`stage` given, e.g. the ride) the caller checks the
  !> groups, and the water's integrator settings come from &water_solver
  !> (its own tolerances; the water and the rider do not share one &solver).
  subroutine build_water(input, description, status, stage)
    type(input_text_t), intent(in) :: input
    type(water_description_t), intent(out) :: description
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: stage
    type(solver_config_t) :: solver
    class(surface_t), allocatable :: surface
    type(tube_surface_t) :: tube
    type(channel_description_t) :: channel_description
    type(channel_t) :: channel
    type(streamline_t) :: model
    real(wp) :: u_min, u_max, v_min, v_max, total, start_speed, y0(7), start_arc
    type(surface_point_t) :: start_point
    real(wp), parameter :: plausible_speed = 30   ! m/s
    integer :: i
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: surface_source
    type(status_t) :: built
    character(len=:), allocatable :: part, variable

    if (present(stage)) then
      call read_solver_config(input, solver, status, group='water_solver')
    else
      call check_known_groups(input, water_groups, status, repeatable=[character(len=5) :: 'inlet'])
      if (status%ok()) call read_solver_config(input, solver, status)
    end if
    if (.not. status%ok()) return
    if (group_present(input, 'surface') .and. group_present(input, 'channel')) then
      call set_status(status, STATUS_INVALID_INPUT, where_given(input, 'channel', '')//': &channel is not '// &
                      'read: the slide is &surface ('//where_given(input, 'surface', '')//'); give the slide '// &
                      'either by &surface (a tube or slide) or by &channel, not both')
      return
    end if
    if (group_present(input, 'surface')) then
      call read_surface_config(input, surface_description, status, surface_source, &
                               described_as=description%slide_name)
      if (status%ok()) call build_surface(surface_description, surface, built, part, variable)
      if (status%ok()) call explain_surface_failure(surface_source, built, part, variable, status)
      call mark_input_failure(status)
      if (.not. status%ok()) return
      select type (surface)
      type is (tube_surface_t)
        description%slide = surface
      class default
        call set_status(status, STATUS_INVALID_INPUT, where_given(input, 'surface', 'kind')//': &surface: '// &
                        'the water needs a tube ' // &
                        '(kind = ''tube'' or ''slide''), not a '//surface%describe())
        return
      end select
    else
      call refuse_unselected_geometry(input, status)
      call read_channel_config(input, channel_description, status)
      if (status%ok()) call build_channel(channel_description, tube, built, variable)
      if (status%ok()) call explain_channel_failure(input, built, variable, status)
      if (.not. status%ok()) return
      description%slide = tube
      if (group_present(input, 'channel')) then
        description%slide_name = 'closed-form tube of &channel in '//input%name
      else
        description%slide_name = 'the default closed-form tube (&channel''s defaults: '//input%name// &
                                 ' has no &surface)'
      end if
    end if
    call read_water_config(input, description, status)
    if (.not. status%ok()) return

    description%solver%ode = solver%options
    description%solver%output_step = solver%output_step
    ! without &solver duration the water runs to the end of the slide
    if (solver%duration_given) then
      description%solver%time_bound = solver%duration
      call check_output_count(input, solver, solver%duration, values_per_output, 'water', status)
      if (.not. status%ok()) return
    end if

    ! the start and the stations against the slide, named as in the input
    channel = new_channel(description%slide)
    call channel%u_range(u_min, u_max)
    call channel%v_range(v_min, v_max)
    total = channel%arc_length(u_max)
    if (.not. (description%start%u0 >= 0 .and. description%start%u0 < total)) then
      call invalid(input, 'water', 'u0', format_real(description%start%u0), 'the start must lie on the slide: '// &
                   'its arc length along the centerline in [0, '//format_real(total)//') m', status)
      return
    end if
    ! the start edges (start = 'edges') or the water middle v0 (other starts)
    ! must lie on an open section's surface; the message names what was given
    if (description%start%mode == START_EDGES) then
      if (description%start%v_left > v_max .or. description%start%v_right < v_min) then
        call invalid(input, 'water', 'v_left0, v_right0', format_real(description%start%v_left)//', '// &
                     format_real(description%start%v_right), 'the start edges must lie inside the cross-section, '// &
                     'v in ['//format_real(v_min)//', '//format_real(v_max)//'] rad', status)
        return
      end if
    else if (description%start%v0 < v_min .or. description%start%v0 > v_max) then
      call invalid(input, 'water', 'v0', format_real(description%start%v0), &
                   'the start must lie inside the cross-section, v in ['//format_real(v_min)//', '// &
                   format_real(v_max)//'] rad', status)
      return
    end if
    if (total/description%table_step > max_table_rows) then
      call invalid(input, 'water', 'table_step', format_real(description%table_step), 'the table over the '// &
                   format_real(total)//' m of slide would have more than '//format_real(max_table_rows)// &
                   ' rows; raise table_step', status)
      return
    end if
    do i = 1, size(description%stations)
      if (description%stations(i) > total) then
        call invalid(input, 'water', 'stations', format_real(description%stations(i)), &
                     'stations must lie on the slide (arc length <= '//format_real(total)//' m)', status)
        return
      end if
    end do
    ! the inlets on the slide, from the start to before the end
    start_arc = description%start%u0
    do i = 1, size(description%inlets)
      associate (at => description%inlets(i)%arc_length)
        if (at < start_arc - start_tolerance .or. .not. at < total) then
          call set_status(status, STATUS_INVALID_INPUT, where_given(input, 'inlet', 'arc_length', i)// &
                          ': &inlet: arc_length = '//format_real(at)//' is not allowed: an inlet must lie on '// &
                          'the slide from the &water start ('//format_short(start_arc)//' m) to before its end ('// &
                          format_short(total)//' m of arc length)')
          return
        end if
      end associate
    end do
    ! the model and its start: what the run will check again
    call new_streamline(description, model, y0, status)
    if (.not. status%ok()) then
      call prefix_status(status, input%name//': &water')
      status%code = STATUS_INVALID_INPUT
      return
    end if
    ! Water in a slide runs at a few m/s; a start far beyond that is almost
    ! always a unit mistake (flow_rate in l/s instead of m^3/s, a height in mm).
    call channel%evaluate(y0(1), y0(2), 1, start_point, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    start_speed = norm2(y0(3)*start_point%ru + y0(4)*start_point%rv)
    if (start_speed > plausible_speed) call log_warning(input%name//': &water: the start speed is '// &
      format_real(start_speed)//' m/s, far above the few m/s of water in a slide; check flow_rate (m^3/s) '// &
      'and the start height (m)')
  end subroutine build_water

  !> Geometry groups are read only through &surface (kind = 'tube' or
  !> 'slide'): in an input without &surface they would be ignored and the
  !> water would run on the &channel tube instead of the slide they describe.
  subroutine refuse_unselected_geometry(input, status)
    type(input_text_t), intent(in) :: input
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: kind, instead
    integer :: i
    ! the groups that choose the slide first, then those that go with them
    character(len=*), parameter :: order(6) = [character(len=14) :: 'slide_elements', 'centerline', 'blended', &
      'bspline', 'cross_section', 'geometry']
    if (.not. status%ok()) return
    do i = 1, size(order)
      if (.not. group_present(input, order(i))) cycle
      select case (trim(order(i)))
      case ('centerline'); kind = '''tube'''
      case ('slide_elements'); kind = '''slide'''
      case default; kind = '''slide'' or ''tube'''
      end select
      if (group_present(input, 'channel')) then
        instead = 'the water would run on the &channel tube instead'
      else
        instead = 'the water would run on the default tube of &channel instead'
      end if
      call set_status(status, STATUS_INVALID_INPUT, where_given(input, order(i), '')//': &'// &
                      trim(order(i))//' is read only through &surface kind = '//kind// &
                      ', and this input has no &surface: '//instead//'; add &surface kind = '//kind// &
                      ' to run on the slide these groups describe')
      return
    end do
  end subroutine refuse_unselected_geometry

  subroutine run_water(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(water_description_t) :: description
    type(water_result_t) :: result
    type(result_file_t) :: file
    type(status_t) :: run_status, write_status
    logical :: complete
    character(len=:), allocatable :: message

    call build_water(input, description, status)
    if (.not. status%ok() .or. run%check_only) return
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call log_info('water: '//description%slide%describe()//', Q = '//format_real(description%flow_rate)//' m^3/s')
    call compute_water(description, result, run_status, log_info)
    call write_results(file, input, run, description, result, write_status)
    complete = run_status%ok() .and. write_status%ok()
    if (result%bounded) then
      message = run_message('ok: '//bounded_message(description, result), run_status, write_status)
    else
      message = run_message('ok: '//outcome_name(result%series%outcome), run_status, write_status)
    end if
    if (write_status%ok()) call write_xdmf(file, description%edges, write_status)
    call file%finish(complete, message, write_status)
    complete = complete .and. write_status%ok()   ! finish refuses a file with NaN or Inf
    call report(description, result, file%final_path(), run, complete, message, write_status)
    if (.not. (run_status%ok() .and. write_status%ok())) status = run_outcome(run_status, write_status)
  end subroutine run_water

  !> A run the user bounded by &solver duration that ended before the slide's end.
  function bounded_message(description, result) result(text)
    type(water_description_t), intent(in) :: description
    type(water_result_t), intent(in) :: result
    character(len=:), allocatable :: text
    associate (s => result%series)
      text = 'stopped at the time bound &solver duration = '//format_short(description%solver%time_bound)// &
             ' s, '//format_short(s%arc_length(s%n))//' m down the '//format_short(result%slide_length)// &
             ' m slide (its end not reached)'
    end associate
  end function bounded_message

  subroutine write_results(file, input, run, description, result, status)
    type(result_file_t), intent(inout) :: file
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(water_description_t), intent(in) :: description
    type(water_result_t), intent(in) :: result
    type(status_t), intent(inout) :: status
    call file%write_provenance('water', trim(run%title), input%name, input%text(), status)
    call write_water_results(file, description, result, status)
    call write_slide_grid(file, description%slide, status)
  end subroutine write_results

  !> The XDMF file next to the result: the slide, the streamline with its
  !> fields, and the water band with speed and height (when the edges were
  !> solved at the samples).
  subroutine write_xdmf(file, edges, status)
    type(result_file_t), intent(inout) :: file
    logical, intent(in) :: edges
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    call xdmf%start()
    call xdmf%surface(file, 'slide surface', '/geometry/surface')
    call xdmf%polyline(file, 'streamline', '/water/position', '/water')
    if (edges) call xdmf%band(file, 'water band', '/water/right_point', '/water/left_point', &
                              [character(len=13) :: '/water/speed', '/water/height'])
    call xdmf%attach(file, status)
  end subroutine write_xdmf

  !> The slide surface the water ran on: the whole u range, across the
  !> section (a closed tube's full turn).
  subroutine write_slide_grid(file, slide, status)
    type(result_file_t), intent(inout) :: file
    class(slide_surface_t), intent(in) :: slide
    type(status_t), intent(inout) :: status
    real(wp) :: u_min, u_max, v_min, v_max
    real(wp), parameter :: full_turn = 2*acos(-1.0_wp)
    call slide%domain(u_min, u_max, v_min, v_max)
    if (slide%periodic_v()) then   ! a closed tube: one turn
      v_min = 0; v_max = full_turn
    end if
    call write_surface_grid(file, slide, evenly_spaced(u_min, u_max, grid_n_u), &
                            evenly_spaced(v_min, v_max, grid_n_v), status, log_info)
  end subroutine write_slide_grid

  !> The printed summary and, with --summary-json, the same numbers as JSON.
  subroutine report(description, result, path, run, complete, message, status)
    type(water_description_t), intent(in) :: description
    type(water_result_t), intent(in), target :: result
    character(len=*), intent(in) :: path, message
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    real(wp), allocatable :: table(:, :)
    character(len=:), allocatable :: uu, vu, note
    character(len=100) :: line
    integer :: n, i
    type(water_series_t), pointer :: s
    s => result%series
    n = s%n
    if (n < 1) return
    call description%slide%parameter_units(uu, vu)
    call summary%start('water', 'slidesim water in '//description%slide%describe())
    if (allocated(description%slide_name)) call summary%add_text('slide', 'slide', description%slide_name)
    call summary%add('slide_length', 'slide centreline length', description%slide%length(), 'm')
    call summary%add('flow_rate', 'flow rate', s%flow_rate, declared_unit('water', 'flow_rate'), 'l/s', 1000.0_wp)
    if (allocated(s%inlets)) then
      if (size(s%inlets) > 0) then
        call summary%add_count('inlets_joined', 'inlets joined', count(s%inlets%joined), &
                               'of '//format_integer(size(s%inlets)))
        call summary%add('final_flow_rate', 'flow rate at the end', s%flow(n), declared_unit('water', 'flow_rate'), &
                         'l/s', 1000.0_wp)
      end if
    end if
    call summary%add('flow_time', 'flow time', s%time(n), 's')
    call summary%add('slide_length_covered', 'slide length covered', s%arc_length(n) - s%arc_length(1), 'm')
    call summary%add_text('outcome', 'stopped at', outcome_name(s%outcome))
    if (result%bounded) call summary%add_line('  time bound                '//bounded_message(description, result))
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
    call add_run_cost(summary, s%stats, result%cpu)
    if (s%edge_beyond > 0) call summary%add_line('  water edges               '//format_integer(s%edge_beyond)// &
      ' samples from arc length '//format_short(s%edge_beyond_from)// &
      ' m: an edge beyond the slide''s end (circle estimate)')
    if (s%edge_failures > 0) call summary%add_line('  water edges               '//format_integer(s%edge_failures)// &
      ' samples where the edge solve failed (circle estimate); first '//s%edge_message)
    note = curve_entry_note(s, description%f3)
    if (len(note) > 0) then
      call summary%add_line('  friction law stretched    '//note)
      call log_warning('water: '//note)
    end if
    note = splash_note(s, description%f3)
    if (len(note) > 0) then
      call summary%add_line('  friction law not valid    '//note)
      call log_warning('water: '//note)
    end if
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
      call write_standard_output('  station  arc length    time   v middle   v edges (right, left)   speed   height' &
        //'   width')
      call write_standard_output('                  m        s'//column(vu)//column(vu)//column(vu)// &
        '      m/s        m        m')
      do i = 1, size(s%stations)
        if (s%stations(i)%reached) then
          write (line, '(2x, i5, f12.3, f9.4, 3f11.4, f9.4, 2f9.5)') i, table(1:8, i)
        else
          write (line, '(2x, i5, a)') i, '   (not reached)'
        end if
        call write_standard_output(trim(line))
      end do
    end if
    call end_report(summary, run, path, complete, message, status)
  contains
    pure function column(units) result(text)   ! a unit right-aligned in the 11 characters of f11.4
      character(len=*), intent(in) :: units
      character(len=11) :: text
      text = repeat(' ', max(0, 11 - len(units)))//units
    end function column
  end subroutine report
end module scenarios_water
