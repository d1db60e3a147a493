!> The water as a library run: a water description (the slide, the inflow,
!> the friction, the start, the model switches, the solver settings) in, the
!> computed water out (samples, the water field, the table over arc length),
!> all in memory. No input text, no files: the namelist reader produces a
!> description (io_water_config via scenarios_water), the command writes the
!> result (io_water_results); an identification or a sweep calls
!> compute_water as often as it likes, from several threads at once (the
!> description is intent(in), the run keeps its state in locals, nothing is
!> kept in module variables).
module water_run
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_text, only: format_short, format_integer
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_log, only: log_sink_i
  use numerics_ode, only: ode_options_t
  use geometry_slide_query, only: slide_surface_t
  use water_channel, only: channel_t, new_channel
  use water_streamline, only: streamline_t, default_f1, default_f2, default_f3, CORRECTION_FULL, &
    CORRECTION_NO_RADIUS, CORRECTION_OFF
  use water_flow, only: water_start_t, water_series_t, water_initial_state, simulate_water, &
    OUTCOME_DURATION, START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED
  use water_inlet, only: water_inlet_t, join_start_inlets, start_tolerance
  use water_field, only: water_field_t, new_water_field
  use water_table, only: water_table_t, new_water_table, solve_row_edges
  implicit none (type, external)
  private
  public :: water_description_t, water_solver_t, water_result_t, new_streamline, compute_water
  public :: water_inlet_t

  !> How the water is integrated and recorded.
  type :: water_solver_t
    type(ode_options_t) :: ode                  !< tolerances, method, steps (numerics_ode defaults)
    real(wp) :: output_step = 0.005_wp          !< s between samples (the thesis's step)
    real(wp) :: time_bound = huge(1.0_wp)       !< s; huge: none, the run goes to the slide's end
  end type water_solver_t

  !> Everything a water run needs (docs/water.md, "The water from a description").
  type :: water_description_t
    class(slide_surface_t), allocatable :: slide              !< the slide query (a tube, or any slide)
    character(len=:), allocatable :: slide_name               !< which slide, from where (for reports)
    real(wp) :: flow_rate = 0.004_wp                          !< m^3/s (Q); not used by START_HEIGHT_SPEED
    real(wp) :: f1 = default_f1, f2 = default_f2, f3 = default_f3   !< kg/m, kg, kg m (4.7)
    type(water_start_t) :: start                              !< where and how the water enters
    !> more water joining along the slide, in order of arc_length (water_inlet)
    type(water_inlet_t), allocatable :: inlets(:)
    integer :: correction = CORRECTION_FULL                   !< Saint-Venant correction mode
    real(wp) :: mass = 1                                      !< kg, the streamline mass m_w
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   !< m/s^2
    real(wp) :: min_speed = 0.05_wp                           !< m/s: the water stalls below it
    real(wp) :: min_criticality = 0.02_wp                     !< 1 - 1/Fr^2 below it: near critical
    real(wp), allocatable :: stations(:)                      !< m of centerline arc length, increasing
    logical :: edges = .true.                                 !< solve the edges at every sample
    real(wp) :: table_step = 0.1_wp                           !< m between the rows of the table
    type(water_solver_t) :: solver
  end type water_description_t

  !> The computed water.
  type :: water_result_t
    type(water_series_t) :: series         !< the samples, the stations, how the run ended
    type(water_field_t) :: field           !< the water for other models (water_field)
    type(water_table_t) :: table           !< the water every table_step of arc length
    real(wp) :: slide_length = 0           !< m, the whole centerline
    logical :: bounded = .false.           !< ended by solver%time_bound before the slide's end
    real(wp) :: cpu = 0                    !< s of process CPU time (run, field and table)
  end type water_result_t

contains

  !> The model and its start state from a description, every value checked
  !> (the messages name the description's components). The inlets at the
  !> start have joined in y0 and model%flow_rate; `inlets` gives every inlet
  !> with its u, those at the start marked joined.
  subroutine new_streamline(description, model, y0, status, inlets)
    type(water_description_t), intent(in) :: description
    type(streamline_t), intent(out) :: model
    real(wp), intent(out) :: y0(7)
    type(status_t), intent(inout) :: status
    type(water_inlet_t), allocatable, intent(out), optional :: inlets(:)
    type(water_inlet_t), allocatable :: joining(:)
    type(water_start_t) :: start
    character(len=:), allocatable :: k
    real(wp) :: start_arc
    real(wp) :: total, u_min, u_max, v_min, v_max
    integer :: i

    y0 = 0
    if (.not. status%ok()) return
    associate (d => description)
      if (.not. slide_built(d%slide)) then
        call fail('slide: no slide built')
      else if (d%start%mode /= START_HEIGHT_SPEED .and. .not. (d%flow_rate > 0 .and. d%flow_rate < 1e3_wp)) then
        call fail('flow_rate = '//format_short(d%flow_rate)//' m^3/s: must be > 0 (and below 1e3)')
      else if (.not. (all([d%f1, d%f2, d%f3] >= 0) .and. all([d%f1, d%f2, d%f3] < 1e6_wp))) then
        call fail('f1, f2, f3 = '//format_short(d%f1)//', '//format_short(d%f2)//', '//format_short(d%f3)// &
                  ': must be >= 0 and finite')
      else if (.not. (d%mass > 0 .and. d%mass < 1e6_wp)) then
        call fail('mass = '//format_short(d%mass)//' kg: must be > 0 and finite')
      else if (.not. all(abs(d%gravity) < 1e6_wp)) then
        call fail('gravity: must be finite')
      else if (.not. (d%min_speed > 0 .and. d%min_speed < 1e3_wp)) then
        call fail('min_speed = '//format_short(d%min_speed)//' m/s: must be > 0')
      else if (.not. (d%min_criticality >= 1e-6_wp .and. d%min_criticality <= 0.9_wp)) then
        call fail('min_criticality = '//format_short(d%min_criticality)//': must lie in [1e-6, 0.9]')
      else if (d%correction /= CORRECTION_FULL .and. d%correction /= CORRECTION_NO_RADIUS .and. &
               d%correction /= CORRECTION_OFF) then
        call fail('correction: not one of CORRECTION_FULL, CORRECTION_NO_RADIUS, CORRECTION_OFF')
      else if (all(d%start%mode /= [START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED])) then
        call fail('start%mode: not one of START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED')
      else if (.not. (d%solver%output_step > 0 .and. d%solver%output_step < 1e6_wp)) then
        call fail('solver%output_step = '//format_short(d%solver%output_step)//' s: must be > 0')
      else if (.not. (d%solver%time_bound > 0)) then
        call fail('solver%time_bound = '//format_short(d%solver%time_bound)//' s: must be > 0')
      else if (.not. (d%table_step > 0 .and. d%table_step < 1e6_wp)) then
        call fail('table_step = '//format_short(d%table_step)//' m: must be > 0')
      end if
      if (.not. status%ok()) return

      allocate (model%channel, source=new_channel(d%slide))
      model%mass = d%mass
      model%gravity = d%gravity
      model%f1 = d%f1; model%f2 = d%f2; model%f3 = d%f3
      model%correction = d%correction
      model%flow_rate = d%flow_rate
      model%min_speed = d%min_speed
      model%min_criticality = d%min_criticality
      call model%channel%u_range(u_min, u_max)
      total = model%channel%arc_length(u_max)
      call model%channel%v_range(v_min, v_max)
      if (d%start%mode == START_EDGES) then
        if (.not. (d%start%v_left <= v_max .and. d%start%v_right >= v_min)) then
          call fail('start%v_left, start%v_right = '//format_short(d%start%v_left)//', '// &
                    format_short(d%start%v_right)//' rad: the start edges must lie inside the cross-section')
          return
        end if
      else if (.not. (d%start%v0 >= v_min .and. d%start%v0 <= v_max)) then
        call fail('start%v0 = '//format_short(d%start%v0)//' rad: must lie inside the cross-section')
        return
      end if
      if (.not. allocated(d%stations)) then
        allocate (model%stations(0))
      else
        allocate (model%stations(size(d%stations)))
        do i = 1, size(d%stations)
          if (.not. (d%stations(i) >= 0 .and. d%stations(i) <= total)) then
            call fail('stations('//format_short(real(i, wp))//') = '//format_short(d%stations(i))// &
                      ' m: must lie on the slide, 0 ... '//format_short(total)//' m of arc length')
            return
          end if
          if (i > 1) then
            if (.not. d%stations(i) > d%stations(i - 1)) then
              call fail('stations must increase along the slide')
              return
            end if
          end if
          call model%channel%parameter_at_length(d%stations(i), model%stations(i), status)
          if (.not. status%ok()) return
        end do
      end if
      ! the start as the model takes it: at the centerline parameter of u0
      start = d%start
      call start_parameter(model%channel, d%start%u0, total, start%u0, status)
      if (.not. status%ok()) return
      call water_initial_state(model, start, y0, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'water start')
        return
      end if
      if (allocated(d%inlets)) then
        joining = d%inlets
      else
        allocate (joining(0))
      end if
      start_arc = model%channel%arc_length(start%u0)
      do i = 1, size(joining)
        k = format_integer(i)
        associate (inlet => joining(i))
          if (.not. (inlet%flow_rate > 0 .and. inlet%flow_rate < 1e3_wp)) then
            call fail('inlets('//k//')%flow_rate = '//format_short(inlet%flow_rate)//' m^3/s: must be > 0')
          else if (.not. (inlet%speed > 0 .and. inlet%speed < 1e3_wp)) then
            call fail('inlets('//k//')%speed = '//format_short(inlet%speed)//' m/s: must be > 0')
          else if (.not. (abs(inlet%beta) < 1.5_wp + 1e-12_wp)) then
            call fail('inlets('//k//')%beta = '//format_short(inlet%beta)//' rad: must lie in [-1.5, 1.5]')
          else if (.not. (inlet%arc_length >= start_arc - start_tolerance .and. inlet%arc_length < total)) then
            call fail('inlets('//k//')%arc_length = '//format_short(inlet%arc_length)//' m: must lie from the '// &
                      'start ('//format_short(start_arc)//' m) to before the end ('//format_short(total)//' m)')
          else if (i > 1) then
            if (.not. inlet%arc_length >= joining(i - 1)%arc_length) &
              call fail('inlets('//k//')%arc_length: the inlets must be in order along the slide')
          end if
          if (.not. status%ok()) return
          inlet%joined = .false.
          call model%channel%parameter_at_length(inlet%arc_length, inlet%u, status)
          if (.not. status%ok()) return
        end associate
      end do
      call join_start_inlets(model, start, start_arc, joining, y0, status)
      if (present(inlets)) call move_alloc(joining, inlets)
    end associate

  contains

    subroutine fail(message)
      character(len=*), intent(in) :: message
      call set_status(status, STATUS_INVALID_INPUT, 'water description: '//message)
    end subroutine fail
  end subroutine new_streamline

  !> The centerline parameter u of the start from `arc`, its arc length
  !> along the centerline from the slide's start (m; water%start%u0, &water
  !> u0, as declared): the parameter is not arc length on an exact element
  !> chain (its horizontal length) nor on a fitted one (the chord length of
  !> its points). A start off the slide, or at its end (`total` m), is
  !> refused. Where the parameter already is arc length to rounding (a
  !> straight tube; the start of a fitted one, u0 = 0) arc is kept as given:
  !> the point the search would find, and the same bits.
  subroutine start_parameter(channel, arc, total, u, status)
    class(channel_t), intent(in) :: channel
    real(wp), intent(in) :: arc, total
    real(wp), intent(out) :: u
    type(status_t), intent(inout) :: status
    u = arc
    if (.not. (arc >= 0 .and. arc < total)) then
      call set_status(status, STATUS_INVALID_INPUT, 'water description: start%u0 = '//format_short(arc)// &
                      ' m: the start must lie on the slide, from 0 to before its end ('//format_short(total)// &
                      ' m of arc length along the centerline)')
      return
    end if
    if (abs(channel%arc_length(arc) - arc) <= 8*epsilon(1.0_wp)*max(total, 1.0_wp)) return
    call channel%parameter_at_length(arc, u, status)
    if (.not. status%ok()) call prefix_status(status, 'water description: start%u0 = '//format_short(arc)//' m')
  end subroutine start_parameter

  !> A slide is given and built (the slide query's built: a tube with its
  !> centerline).
  pure logical function slide_built(slide)
    class(slide_surface_t), allocatable, intent(in) :: slide
    slide_built = allocated(slide)
    if (slide_built) slide_built = slide%built()
  end function slide_built

  !> Runs the water of `description` to the end of the slide (or its time
  !> bound, or a stop of the model) and builds its field and table. `status`:
  !> invalid input (nothing run), ok (the end, or the bound: result%bounded),
  !> or why the run stopped early (the result holds what was computed up to
  !> there, with its field and table). Progress lines go to `log` when given
  !> (the program's interval); without it none are made.
  subroutine compute_water(description, result, status, log)
    type(water_description_t), intent(in) :: description
    type(water_result_t), intent(out) :: result
    type(status_t), intent(inout) :: status
    procedure(log_sink_i), optional :: log
    type(streamline_t), target :: model
    type(status_t) :: run_status, st
    real(wp) :: y0(7), cpu0, cpu1, u_min, u_max
    real(wp), allocatable :: left(:, :), right(:, :)
    type(water_inlet_t), allocatable :: inlets(:)

    call cpu_time(cpu0)
    call new_streamline(description, model, y0, status, inlets)
    if (.not. status%ok()) return
    call model%channel%u_range(u_min, u_max)
    result%slide_length = model%channel%arc_length(u_max)
    if (present(log)) then
      call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, &
                          description%solver%output_step, result%series, run_status, edges=description%edges, &
                          log=log, inlets=inlets)
    else
      call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, &
                          description%solver%output_step, result%series, run_status, edges=description%edges, &
                          progress_seconds=0.0_wp, inlets=inlets)
    end if
    result%bounded = result%series%outcome == OUTCOME_DURATION
    if (result%series%n >= 2) then
      st%code = 0
      result%field = new_water_field(result%series, st)
      ! without edges at the samples, the field takes those solved at the rows of the table
      if (st%ok() .and. .not. description%edges) then
        call solve_row_edges(result%field, model, description%table_step, left, right, st)
        if (st%ok()) result%field = new_water_field(result%series, st, left, right)
      end if
      if (st%ok()) call new_water_table(result%field, model, description%table_step, result%table, st)
      if (.not. st%ok() .and. run_status%ok()) run_status = st
    end if
    if (.not. run_status%ok()) status = run_status
    call cpu_time(cpu1)
    result%cpu = cpu1 - cpu0
  end subroutine compute_water
end module water_run
