!> Scenario `optimize`: the geometry optimisation of a tube slide (thesis
!> 4.7): the design points, five (or any number of) rides of a rigid body on
!> a Darboux frame, the cost (4.49) and the tipping lever-arm limit
!> (docs/design.md). Writes /optimize with the start and optimised
!> designs, every ride's figures and samples before and after. The design
!> is &optimize's points, or element parameters of &slide_elements
!> (&design_elements), snapped to the standard parts of &catalogue
!> (design_catalogue; scenarios_optimize_parts writes and reports them).
!> The optimisation itself, its end's rides and the catalogue's design are
!> the library's job (design_optimization_job's run_optimization); here the
!> input is read, the start design checked, the ranks started, and the job
!> written and reported.
module scenarios_optimize
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, prefix_status, STATUS_INVALID_INPUT
  use base_text, only: format_integer, format_short, format_with
  use base_log, only: log_info
  use design_cuboid_ride, only: cuboid_ride_t
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, design_evaluation_t, &
    evaluate_design, design_points, build_design_slide, OUTCOME_OPTIMUM, OUTCOME_FAILED, outcome_names
  use geometry_tube, only: tube_surface_t
  use design_slide_design, only: start_x
  use design_catalogue, only: catalogue_t, catalogue_result_t
  use design_optimization_job, only: optimization_job_t, run_optimization
  use io_element_design_config, only: read_element_design, refuse_point_design
  use scenarios_optimize_parts, only: write_element_variables, write_catalogue, report_element_design
  use geometry_curve, only: curve_point_t
  use io_input, only: input_text_t, check_known_groups, group_present, where_given
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_surface_grid, only: write_surface_grid
  use base_grid, only: evenly_spaced
  use io_xdmf, only: xdmf_t
  use io_run_config, only: run_config_t
  use io_optimization_config, only: read_optimization_config
  use io_optimization_population, only: read_optimization_population
  use design_sweep_ranks, only: start_ranks, finish_ranks
  use design_optimize_ranks, only: share_flag
  use scenarios_optimize_population, only: write_population, report_population, lever_text
  use io_hdf5, only: result_file_t, run_outcome, run_message
  use io_summary, only: summary_t, degrees
  use io_input_declarations, only: declared_unit
  use scenarios_report, only: end_report
  implicit none (type, external)
  private
  public :: run_optimize, optimize_groups

  character(len=*), parameter :: optimize_groups(7) = [character(len=15) :: 'run', 'solver', 'optimize', &
    'slide_elements', 'design_elements', 'catalogue', 'sweep']
  integer, parameter :: grid_n_u = 300, grid_n_v = 48   ! the written surface grid

contains

  subroutine run_optimize(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(optimization_setup_t) :: setup
    type(optimization_job_t) :: job
    type(design_evaluation_t) :: before
    type(solver_config_t) :: solver
    type(result_file_t) :: file
    type(status_t) :: run_status, write_status
    type(catalogue_t) :: catalogue
    logical :: complete, ended, with_catalogue, started, go
    character(len=:), allocatable :: message

    call check_known_groups(input, optimize_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call refuse_point_design(input, status)
    if (status%ok()) call read_optimization_config(input, setup, status)
    if (status%ok()) call read_optimization_population(input, setup, status)
    if (status%ok()) call read_element_design(input, setup, catalogue, with_catalogue, status)
    if (.not. status%ok()) return
    ! &solver: the rides' integration, sampling of the maxima and time bound
    if (group_present(input, 'solver')) then
      setup%ride%ode = solver%options
      setup%ride%output_step = solver%output_step
      if (solver%duration_given) setup%ride%t_end = solver%duration
    end if
    ! the start design must be buildable and rideable: bad input otherwise
    call evaluate_design(setup, start_x(setup%design), before, status, keep_series=.true.)
    if (.not. status%ok()) then
      call prefix_status(status, where_given(input, 'optimize', '')//': &optimize: the start design')
      status%message = status%message//'; change '// &
                       trim(merge('points  ', 'elements', .not. setup%design%from_elements))// &
                       ', radius or start_angles_deg (or &solver duration)'
      status%code = STATUS_INVALID_INPUT
      return
    end if
    if (run%check_only) return
    ! under MPI every rank optimises, sharing the rides; rank 0 writes and reports
    call start_ranks(setup%rank, setup%ranks, started)
    if (setup%rank == 0) call file%create(trim(run%output), status)
    go = status%ok()
    call share_flag(go, setup%ranks)
    if (.not. go) then
      call finish_ranks(started)
      return
    end if
    if (setup%rank == 0) then
      message = ''
      if (setup%ranks > 1) message = ', '//format_integer(setup%ranks)//' MPI ranks'
      call log_info('optimize: '//format_integer(size(setup%design%lower))//' design variables, '// &
                    format_integer(size(setup%start_angles))//' rides per design'//message)
      setup%log => log_info
    end if
    if (with_catalogue) then
      call run_optimization(setup, job, run_status, catalogue)
    else
      call run_optimization(setup, job, run_status)
    end if
    call finish_ranks(started)
    if (setup%rank /= 0) return   ! the same numbers as rank 0's, written by it
    ! an end that is not a minimum or violates a constraint is no optimum (or
    ! a catalogue without a feasible design): exit 2, file incomplete
    ended = job%ended
    call write_results(file, input, run, setup, job%result, before, job%after, ended, job%cpu_seconds, &
                       write_status)
    call write_population(file, setup, before, job%after, ended, write_status)
    if (setup%design%from_elements .and. ended .and. with_catalogue) then
      call write_element_variables(file, setup%design, write_status, job%result%x, catalogue, job%chosen)
      if (job%chosen%ridden) then
        call write_evaluation(file, '/optimize/chosen/', job%chosen%chosen, write_status)
        call scale_evaluation(file, '/optimize/chosen/', size(job%chosen%chosen%rides), write_status)
      end if
      call write_centerline(file, '/optimize/centerline_catalogue', setup, job%chosen%x, write_status)
      call write_catalogue(file, job%chosen, write_status)
    else if (setup%design%from_elements .and. ended) then
      call write_element_variables(file, setup%design, write_status, job%result%x)
    else if (setup%design%from_elements) then
      call write_element_variables(file, setup%design, write_status)
    end if
    if (setup%design%from_elements) then   ! the scales of what was written here
      call file%attach_scale('/optimize/centerline_fraction', '/optimize', write_status)
      call file%attach_components('/optimize', write_status)
    end if
    complete = run_status%ok() .and. write_status%ok()
    message = run_message('ok', run_status, write_status)
    if (write_status%ok()) call write_xdmf(file, size(setup%start_angles), ended, &
                                           ended .and. with_catalogue .and. job%chosen%ridden, write_status)
    call file%finish(complete, message, write_status)
    complete = complete .and. write_status%ok()
    if (ended .and. with_catalogue) then
      call report(setup, job%result, job%cpu_seconds, file%final_path(), run, complete, message, write_status, &
                  job%chosen)
    else if (ended) then
      call report(setup, job%result, job%cpu_seconds, file%final_path(), run, complete, message, write_status)
    end if
    if (.not. (run_status%ok() .and. write_status%ok())) status = run_outcome(run_status, write_status)
  end subroutine run_optimize

  subroutine write_results(file, input, run, setup, result, before, after, optimized, cpu, status)
    type(result_file_t), intent(inout) :: file
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_result_t), intent(in) :: result
    type(design_evaluation_t), intent(in) :: before, after
    logical, intent(in) :: optimized
    real(wp), intent(in) :: cpu
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/optimize/'
    integer, parameter :: n_centerline = 400
    integer :: k
    logical :: points
    points = .not. setup%design%from_elements   ! else the variables are written by scenarios_optimize_parts
    call file%write_provenance('optimize', trim(run%title), input%name, input%text(), status)
    if (points) then
      call file%write_matrix(g//'points_start', setup%design%points, 'm', &
                             'centerline points of the start design (x, y, z per column)', status)
      call file%write_vector(g//'x_start', start_x(setup%design), 'm', 'design variables at the start', status)
      call file%write_vector(g//'lower', setup%design%lower, 'm', 'lower bounds of the design variables', status)
      call file%write_vector(g//'upper', setup%design%upper, 'm', 'upper bounds of the design variables', status)
      call file%write_integers(g//'design_point', setup%design%point - 1, '1', &
                               'the point of each design variable (0 = the first point)', status)
      call file%write_integers(g//'design_coordinate', setup%design%coordinate, '1', &
                               'the coordinate of each design variable (1 x, 2 y, 3 z)', status)
    end if
    call file%write_scalar(g//'lever_limit', setup%lever_limit, 'm', 'largest allowed tipping lever arm', status)
    call write_centerline(file, g//'centerline_start', setup, start_x(setup%design), status)
    call write_evaluation(file, g//'before/', before, status)
    if (optimized) then
      call write_centerline(file, g//'centerline', setup, result%x, status)
      if (points) then
        call file%write_matrix(g//'points', design_points(setup%design, result%x), 'm', &
                               'centerline points of the optimised design', status)
        call file%write_vector(g//'x', result%x, 'm', 'design variables at the optimum', status)
      end if
      call file%write_scalar(g//'cost_start', result%cost_before, 'm^2/s^4', &
                             'the fit''s cost (4.49 with the constraint terms) at the start', status)
      call file%write_scalar(g//'cost', result%cost_after, 'm^2/s^4', 'the fit''s cost at the optimum', status)
      call file%write_count(g//'evaluations', result%evaluations, '1', 'designs evaluated (each all rides)', status)
      call file%write_count(g//'rejected', result%rejected, '1', &
                            'designs that could not be built or ridden (rejected steps)', status)
      call file%write_count(g//'outer_iterations', result%outer, '1', &
                            'augmented Lagrangian updates (constraint = exact), else 1', status)
      call file%write_scalar(g//'cpu_time', cpu, 's', 'process CPU time of the optimisation', status)
      call write_evaluation(file, g//'after/', after, status)
      call write_outcome(file, result, points, status)
    end if
    ! the slide's surface (the optimum's, else the start's) for ParaView
    if (optimized) then
      call write_grid(file, setup, result%x, status)
    else
      call write_grid(file, setup, start_x(setup%design), status)
    end if
    ! dimension scales: each ride's time, the rides' start angles, the design
    ! variables, the points and the centerline samples
    call scale_evaluation(file, g//'before/', size(before%rides), status)
    if (optimized) call scale_evaluation(file, g//'after/', size(after%rides), status)
    if (points) call file%write_vector(g//'point_number', [(real(k, wp), k=0, size(setup%design%points, 2) - 1)], &
                                       '1', 'number of each centerline point (0 = the first)', status)
    call file%write_vector(g//'centerline_fraction', [(real(k, wp)/(n_centerline - 1), k=0, n_centerline - 1)], &
                           '1', 'fraction of the centerline''s parameter range of each centerline sample', status)
    if (points) call file%make_scale(g//'x_start', status)
    if (optimized) call file%make_scale(g//'starts/start', status)
    if (points) call file%make_scale(g//'point_number', status)
    call file%make_scale(g//'centerline_fraction', status)
    if (optimized) call file%attach_scale(g//'starts/start', g//'starts/', status)   ! before x_start's
    if (points) call file%attach_scale(g//'x_start', g, status)
    if (optimized .and. points) call file%attach_scale(g//'x_start', g//'starts/', status, axis=1)
    if (points) call file%attach_scale(g//'point_number', g, status)
    call file%attach_scale(g//'centerline_fraction', g, status)
    ! the (x, y, z) axes (/optimize/xyz): an element design's after its catalogue's centerline
    if (points) call file%attach_components('/optimize', status)
  end subroutine write_results

  !> The scales of one evaluation's group: each ride's time, the start angles.
  subroutine scale_evaluation(file, group, n, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: group
    integer, intent(in) :: n
    type(status_t), intent(inout) :: status
    integer :: i
    do i = 1, n
      call file%make_scale(group//'ride_'//format_integer(i)//'/time', status)
      call file%attach_scale(group//'ride_'//format_integer(i)//'/time', group//'ride_'//format_integer(i), status)
    end do
    call file%make_scale(group//'start_angle', status)
    call file%attach_scale(group//'start_angle', group, status)
  end subroutine scale_evaluation

  !> How the optimisation ended (attributes of /optimize) and every start
  !> (/optimize/starts).
  subroutine write_outcome(file, result, points, status)
    type(result_file_t), intent(inout) :: file
    type(optimization_result_t), intent(in) :: result
    logical, intent(in) :: points   !< the design variables are coordinates (m), one unit for the matrices
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/optimize', s = '/optimize/starts/'
    integer :: k, n
    call file%set_attribute(g, 'outcome', trim(outcome_names(result%outcome)), status)
    call file%set_attribute(g, 'verdict', result%verdict, status)
    call file%set_attribute(g, 'stop_test', result%stop_test, status)
    call file%set_attribute(g, 'stop_reason', result%stop_reason, status)
    call file%set_attribute(g, 'final_stop_reason', result%final_stop_reason, status)
    call file%set_attribute(g, 'minimum_check', result%minimum_check, status)
    call file%set_attribute(g, 'restarts', result%restarts, status)
    call file%set_attribute(g, 'constraints', constraints_text(result), status)
    call file%set_attribute(g, 'best_start', result%best_start, status)
    n = size(result%starts)
    call file%write_vector(s//'start', [(real(k, wp), k=1, n)], '1', &
                           'number of each start (1 = the given design); dimension scale', status)
    if (points) then
      call file%write_matrix(s//'start_design', reshape([(result%starts(k)%x_start, k=1, n)], [size(result%x), n]), &
                             'm', 'design variables at each start (one column per start)', status)
      call file%write_matrix(s//'end_design', reshape([(result%starts(k)%x, k=1, n)], [size(result%x), n]), 'm', &
                             'design variables at each start''s end', status)
    end if
    call file%write_vector(s//'cost_start', result%starts%cost_start, 'm^2/s^4', 'the fit''s cost at each start', &
                           status)
    call file%write_vector(s//'cost', min(result%starts%cost, 1e30_wp), 'm^2/s^4', &
                           'the fit''s cost at each start''s end (1e30: the start failed)', status)
    call file%write_vector(s//'acceleration_cost', min(result%starts%acceleration_cost, 1e30_wp), 'm^2/s^4', &
                           'the acceleration cost at each start''s end (1e30: the start failed)', status)
    call file%write_integers(s//'outcome', result%starts%outcome, '1', &
                             'how each start ended: 0 optimum, 1 constraint violated, 2 not a minimum, 3 failed', status)
    call file%write_integers(s//'evaluations', result%starts%evaluations, '1', 'designs ridden by each start', status)
  end subroutine write_outcome

  !> 'hold' or the violated constraints.
  function constraints_text(result) result(text)
    type(optimization_result_t), intent(in) :: result
    character(len=:), allocatable :: text
    text = 'hold'
    if (len(result%violations) > 0) text = 'violated: '//result%violations
  end function constraints_text

  subroutine write_grid(file, setup, x, status)
    type(result_file_t), intent(inout) :: file
    type(optimization_setup_t), intent(in) :: setup
    real(wp), intent(in) :: x(:)
    type(status_t), intent(inout) :: status
    type(tube_surface_t) :: slide
    type(status_t) :: built
    real(wp) :: u_min, u_max
    call build_design_slide(setup%design, x, slide, built)
    if (.not. built%ok()) return
    call slide%centerline%domain(u_min, u_max)
    call write_surface_grid(file, slide, evenly_spaced(u_min, u_max, grid_n_u), &
                            evenly_spaced(0.0_wp, 2*pi, grid_n_v), status, log_info)
  end subroutine write_grid

  !> The XDMF file: the slide and every ride's path, before and after.
  subroutine write_xdmf(file, n, optimized, with_catalogue, status)
    type(result_file_t), intent(inout) :: file
    integer, intent(in) :: n
    logical, intent(in) :: optimized, with_catalogue
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    integer :: k
    character(len=:), allocatable :: r
    call xdmf%start()
    call xdmf%surface(file, 'slide surface', '/geometry/surface')
    do k = 1, n
      r = '/optimize/before/ride_'//format_integer(k)
      call xdmf%polyline(file, 'start design, ride '//format_integer(k), r//'/position', r)
      if (optimized) then
        r = '/optimize/after/ride_'//format_integer(k)
        call xdmf%polyline(file, 'optimum, ride '//format_integer(k), r//'/position', r)
      end if
      if (with_catalogue) then
        r = '/optimize/chosen/ride_'//format_integer(k)
        call xdmf%polyline(file, 'catalogue design, ride '//format_integer(k), r//'/position', r)
      end if
    end do
    call xdmf%attach(file, status)
  end subroutine write_xdmf

  !> The start angles of the rides of an evaluation.
  pure function setup_angles(e) result(a)
    type(design_evaluation_t), intent(in) :: e
    real(wp) :: a(size(e%rides))
    a = e%rides%start_angle
  end function setup_angles

  !> The centerline of design x at 400 points, for plots.
  subroutine write_centerline(file, name, setup, x, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: name
    type(optimization_setup_t), intent(in) :: setup
    real(wp), intent(in) :: x(:)
    type(status_t), intent(inout) :: status
    type(tube_surface_t) :: slide
    type(curve_point_t) :: p
    type(status_t) :: built
    real(wp) :: c(3, 400), u_min, u_max
    integer :: i
    call build_design_slide(setup%design, x, slide, built)
    if (.not. built%ok()) return
    call slide%centerline%domain(u_min, u_max)
    do i = 1, size(c, 2)
      call slide%centerline%evaluate(u_min + (u_max - u_min)*(i - 1)/real(size(c, 2) - 1, wp), 0, p, built)
      c(:, i) = p%d(:, 0)
    end do
    call file%write_matrix(name, c, 'm', 'the centerline (x, y, z per column)', status)
  end subroutine write_centerline

  !> Every ride's figures and samples of one design.
  subroutine write_evaluation(file, g, e, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: g
    type(design_evaluation_t), intent(in) :: e
    type(status_t), intent(inout) :: status
    integer :: k, n
    character(len=:), allocatable :: r
    call file%write_vector(g//'max_acceleration', e%rides%max_acceleration, 'm/s^2', &
                           'largest acceleration of each ride (the kind of &optimize acceleration)', status)
    call file%write_vector(g//'max_lever_arm', min(e%rides%max_lever_arm, 1e30_wp), 'm', &
                           'largest tipping lever arm of each ride (1e30: the body lifts off)', status)
    call file%write_vector(g//'max_tipping_excess', e%rides%max_tipping_excess, 'm', &
                           'largest tipping excess of each ride (<= 0: the limit holds)', status)
    call file%write_vector(g//'min_normal_force', e%rides%min_normal_force, 'N', &
                           'smallest normal force of each ride (<= 0: lift-off)', status)
    call file%write_vector(g//'duration', e%rides%duration, 's', 'time to the end of the slide', status)
    call file%write_vector(g//'start_angle', setup_angles(e), 'rad', &
                           'start direction of each ride to the centerline, + towards +v', status)
    call file%write_scalar(g//'acceleration_cost', e%acceleration_cost, 'm^2/s^4', &
                           '1/2 sum of the squared maxima (4.49 without the constraint)', status)
    do k = 1, size(e%rides)
      r = g//'ride_'//format_integer(k)//'/'
      associate (s => e%rides(k)%series)
        n = s%n
        call file%write_vector(r//'time', s%time(:n), 's', 'time', status)
        call file%write_vector(r//'u', s%u(:n), '1', 'centerline parameter of the Darboux frame', status)
        call file%write_vector(r//'v', s%v(:n), 'rad', 'section angle of the Darboux frame (pi/2 bottom)', status)
        call file%write_matrix(r//'position', s%position(:, :n), 'm', 'Darboux frame origin', status)
        call file%write_vector(r//'acceleration', s%acceleration(:n), 'm/s^2', 'acceleration (&optimize kind)', &
                               status)
        call file%write_vector(r//'lever_arm', min(max(s%lever_arm(:n), -1e30_wp), 1e30_wp), 'm', &
                               'tipping lever arm (1e30: not pressed)', status)
        call file%write_vector(r//'normal_force', s%normal_force(:n), 'N', 'normal force F_r . z_D', status)
        call file%write_vector(r//'speed', s%speed(:n), 'm/s', 'speed of the Darboux frame origin', status)
      end associate
    end do
  end subroutine write_evaluation

  subroutine report(setup, result, cpu, path, run, complete, message, status, chosen)
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_result_t), intent(in) :: result
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: path, message
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(catalogue_result_t), intent(in), optional :: chosen   !< the design chosen from the catalogue
    type(summary_t) :: summary
    real(wp), allocatable :: table(:, :)
    integer :: k, n
    character(len=:), allocatable :: end
    n = size(setup%start_angles)
    end = 'optimum'
    if (result%outcome /= OUTCOME_OPTIMUM) end = 'end (no optimum)'
    call summary%start('optimize', 'slidesim optimize: '//format_integer(size(result%x))//' design variables, '// &
                       format_integer(n)//' rides')
    call summary%add_text('outcome', 'outcome', trim(outcome_names(result%outcome)))
    call summary%add_text('verdict', 'verdict', result%verdict)
    call summary%add_text('stop_reason', 'MINPACK stopped first on', result%stop_reason)
    call summary%add_count('restarts', 'restarts from the end', result%restarts, 'restarts')
    call summary%add_text('minimum_check', 'minimum check', result%minimum_check)
    call summary%add_text('constraints', 'constraints at the end', constraints_text(result))
    call summary%add('cost_start', 'cost at the start', result%cost_before, 'm^2/s^4')
    call summary%add('cost', 'cost at the '//end, result%cost_after, 'm^2/s^4')
    call add_lever('max_lever_arm_start', 'largest lever arm, start', result%before%max_lever_arm)
    call add_lever('max_lever_arm', 'largest lever arm, '//end, result%after%max_lever_arm)
    call summary%add('lever_limit', 'lever-arm limit', setup%lever_limit, declared_unit('optimize', 'lever_limit'))
    call summary%add_count('evaluations', 'designs evaluated', result%evaluations, 'designs')
    call summary%add('cpu_time', 'CPU time', cpu, 's')
    if (size(result%starts) > 1) call add_starts()
    call report_population(summary, setup, result%before, result%after, end)
    if (setup%design%from_elements) then
      call summary%add('acceleration_cost', 'acceleration cost, '//end, result%after%acceleration_cost, 'm^2/s^4')
      call report_element_design(summary, setup%design, result%x, chosen)
    else
      call add_points()
    end if
    allocate (table(5, n))
    do k = 1, n
      table(:, k) = [setup%start_angles(k)*degrees, result%before%rides(k)%max_acceleration, &
                     result%after%rides(k)%max_acceleration, min(result%before%rides(k)%max_lever_arm, 1e30_wp), &
                     min(result%after%rides(k)%max_lever_arm, 1e30_wp)]
    end do
    call summary%add_table('rides', [character(len=17) :: 'start_angle', 'max_a_start', 'max_a_optimum', &
                           'lever_arm_start', 'lever_arm_optimum'], &
                           [character(len=6) :: 'deg', 'm/s^2', 'm/s^2', 'm', 'm'], table)
    if (.not. allocated(setup%members)) then   ! else the members' lines of report_population
      call summary%add_line('  ride at (deg)   max |a| start, optimum (m/s^2)   lever arm start, optimum (m)')
      do k = 1, n
        call summary%add_line('    '//format_with(table(1, k), 'f12.4')//'      '//format_with(table(2, k), 'f12.4')// &
          format_with(table(3, k), 'f12.4')//'        '//lever_text(table(4, k), 12)//lever_text(table(5, k), 12))
      end do
    end if
    call summary%print()
    call end_report(summary, run, path, complete, message, status)

  contains

    !> The coordinates moved: their point, start, optimum and move.
    subroutine add_points()
      allocate (table(5, size(result%x)))
      do k = 1, size(result%x)
        table(:, k) = [real(setup%design%point(k) - 1, wp), real(setup%design%coordinate(k), wp), &
                       setup%design%points(setup%design%coordinate(k), setup%design%point(k)), result%x(k), &
                       result%x(k) - setup%design%points(setup%design%coordinate(k), setup%design%point(k))]
      end do
      call summary%add_table('design', [character(len=10) :: 'point', 'coordinate', 'start', 'optimum', 'move'], &
                             [character(len=2) :: '1', '1', 'm', 'm', 'm'], table)
      call summary%add_line('  design variable      start (m)  optimum (m)   move (m)')
      do k = 1, size(result%x)
        call summary%add_line('    P'//format_integer(setup%design%point(k) - 1)//'.'// &
          'xyz'(setup%design%coordinate(k):setup%design%coordinate(k))//repeat(' ', 12)// &
          format_with(table(3, k), 'f12.4')//format_with(table(4, k), 'f12.4')//format_with(table(5, k), 'f12.4'))
      end do
      deallocate (table)
    end subroutine add_points

    !> Every start's costs and outcome, the best one and the spread.
    subroutine add_starts()
      real(wp), allocatable :: starts(:, :), ended(:)
      integer :: j
      associate (s => result%starts)
        call summary%add_count('best_start', 'best start', result%best_start, '(1 = the given design)')
        ended = pack(s%acceleration_cost, s%outcome /= OUTCOME_FAILED)
        call summary%add_range('acceleration_cost_spread', 'acceleration cost over the starts', minval(ended), &
                               maxval(ended), 'm^2/s^4')
        allocate (starts(6, size(s)))
        do j = 1, size(s)
          starts(:, j) = [real(j, wp), s(j)%cost_start, min(s(j)%cost, 1e30_wp), &
                          min(s(j)%acceleration_cost, 1e30_wp), real(s(j)%outcome, wp), real(s(j)%evaluations, wp)]
        end do
        call summary%add_table('starts', [character(len=17) :: 'start', 'cost_start', 'cost', 'acceleration_cost', &
                               'outcome', 'designs'], [character(len=7) :: '1', 'm^2/s^4', 'm^2/s^4', 'm^2/s^4', &
                               '1', '1'], starts)
        call summary%add_line('  start   cost start       cost end   acceleration cost  designs  outcome')
        do j = 1, size(s)
          call summary%add_line('  '//padded(j, 5)//format_with(starts(2, j), 'es13.4')// &
            format_with(starts(3, j), 'es15.4')//format_with(starts(4, j), 'es20.4')// &
            padded(s(j)%evaluations, 9)//'  '//trim(outcome_names(s(j)%outcome)))
        end do
      end associate
    end subroutine add_starts

    subroutine add_lever(key, label, value)
      character(len=*), intent(in) :: key, label
      real(wp), intent(in) :: value
      if (value >= 1e30_wp) then
        call summary%add_text(key, label, 'lift-off (a body does not stay pressed on the slide)')
      else
        call summary%add(key, label, value, 'm')
      end if
    end subroutine add_lever
  end subroutine report

  !> i right-aligned in `width` columns.
  pure function padded(i, width) result(text)
    integer, intent(in) :: i, width
    character(len=:), allocatable :: text
    text = format_integer(i)
    text = repeat(' ', max(0, width - len(text)))//text
  end function padded
end module scenarios_optimize
