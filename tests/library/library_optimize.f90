!> The shipped optimisation inputs run through the library alone (issue 24
!> point 2): every setup (optimization_setup_t: the design, its bounds, the
!> bodies and starts, the constraint and LMDER's settings), the robust
!> population (design_sweep's sweep_rows over its lists, design_population's
!> members) and the catalogue of standard parts (design_catalogue's allowed
!> values) filled here in code from the values the input files give (the
!> defaults they do not give: the types' own, which are the reader's), then
!> run by design_optimization_job's run_optimization (optimize_slide, the
!> end's rides and, with a catalogue, choose_from_catalogue), the call the
!> `optimize` scenario makes. No io module is linked (tests/CMakeLists.txt
!> links slidesim_design only).
!>
!> Prints `<input> <key> <value>` lines under the keys of the command's
!> --summary-json (a table row's values as `<table>.<row>.<column>`, a
!> vector's as `<key>.<index>`) and `TEXT <input> <key> <text>` for its
!> words (the outcome, the catalogue's verdict; key `line`: a line the
!> command's summary prints, the parts list). tests/library/library_without_io.sh
!> compares them with the command's runs of the same inputs (the fixture
!> cli_every_input, with its settings: the template at ftol = xtol = 0.1
!> without the constraint, the robust one from heading 0 only, one start,
!> ftol = xtol = 0.1, without the constraint); the inputs are those
!> tests/library/built_through_library.txt gives library_optimize. Exit
!> status 1 when a run fails.
program library_optimize
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_text, only: format_integer, format_short
  use geometry_slide_builder, only: slide_elements_description_t
  use design_sweep, only: N_SWEPT, V_MASS, V_HEIGHT, V_V0, V_HEADING, V_SPEED, swept_values_t, sweep_rows
  use design_population, only: population_base, set_population
  use design_robust_cost, only: COST_WORST
  use design_slide_design, only: table_4_12_design, start_x, PARAMETER_RADIUS, PARAMETER_SLOPE, PARAMETER_DROP
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, thesis_start_angles, &
    outcome_names, CONSTRAINT_NONE, CONSTRAINT_PENALTY
  use design_catalogue, only: catalogue_t, allowed_in_list, allowed_by_step, part_text
  use design_optimization_job, only: optimization_job_t, run_optimization
  use library_lines, only: put, put_text, stop_unless_ok
  use shipped_slides, only: element
  implicit none (type, external)
  real(wp), parameter :: degrees = 45/atan(1.0_wp)   ! io_summary's degrees per radian

  call table_4_12('inputs/design/optimize_table_4_12.nml', 1e-4_wp, 1e-3_wp, CONSTRAINT_PENALTY, 2)
  ! the template (its values are table 4.12's), at the fixture's settings
  call table_4_12('inputs/templates/optimize.nml', 0.1_wp, 0.1_wp, CONSTRAINT_NONE, 1)
  call robust()
  call standard_parts()
  call bowl_parts()

contains

  !> Table 4.12 (thesis 4.7): its design and rides (the types' defaults),
  !> &solver as the defaults (adams, rtol = atol = 1e-7, output every
  !> 0.005 s), the penalty 5e3 on a lever arm over 0.25 m, one start, LMDER
  !> at ftol and xtol, at most 10 restarts and 10000 designs.
  subroutine table_4_12(input, ftol, xtol, constraint, threads)
    character(len=*), intent(in) :: input
    real(wp), intent(in) :: ftol, xtol
    integer, intent(in) :: constraint, threads
    type(optimization_setup_t) :: setup
    type(optimization_job_t) :: job
    call thesis_setup(setup, ftol, xtol, constraint, threads)
    call optimize_and_print(input, setup, job)
    call print_points(input, setup, job%result)
  end subroutine table_4_12

  !> The setup of table 4.12 as the &optimize reader fills it.
  subroutine thesis_setup(setup, ftol, xtol, constraint, threads)
    type(optimization_setup_t), intent(out) :: setup
    real(wp), intent(in) :: ftol, xtol
    integer, intent(in) :: constraint, threads
    setup%design = table_4_12_design()
    setup%start_angles = thesis_start_angles()
    setup%start_speed = 0.5_wp
    setup%start_v = pi/2
    setup%constraint = constraint
    setup%lever_limit = 0.25_wp
    setup%penalty_factor = 5000
    setup%rho = 20*setup%penalty_factor
    setup%solver%ftol = ftol
    setup%solver%xtol = xtol
    setup%solver%max_evaluations = 10000
    setup%max_restarts = 10
    setup%starts = 1
    setup%threads = threads
  end subroutine thesis_setup

  !> inputs/design/optimize_robust.nml at the fixture's settings: table 4.12
  !> ridden by a population, the worst ride's cost. &sweep: mass and height
  !> paired (five persons), speed0 0.3 and 0.7 m/s, heading0_deg 0 (the
  !> fixture's; the input's five headings), v0 the bottom: 10 members.
  subroutine robust()
    character(len=*), parameter :: input = 'inputs/design/optimize_robust.nml'
    type(optimization_setup_t) :: setup
    type(optimization_job_t) :: job
    type(swept_values_t) :: lists(N_SWEPT)
    real(wp) :: base(N_SWEPT)
    logical :: together(N_SWEPT)
    integer :: k
    call thesis_setup(setup, 0.1_wp, 0.1_wp, CONSTRAINT_NONE, 2)
    setup%cost = COST_WORST
    base = population_base(setup)
    do k = 1, N_SWEPT
      lists(k)%x = [base(k)]
    end do
    lists(V_MASS)%x = [50.0_wp, 60.0_wp, 72.0_wp, 85.0_wp, 100.0_wp]
    lists(V_HEIGHT)%x = [1.55_wp, 1.65_wp, 1.75_wp, 1.82_wp, 1.92_wp]
    lists(V_SPEED)%x = [0.3_wp, 0.7_wp]
    lists(V_HEADING)%x = [0.0_wp]
    lists(V_V0)%x = [1.5707963267948966_wp]
    together = .false.
    together([V_MASS, V_HEIGHT]) = .true.
    call set_population(setup, sweep_rows(lists, together), heading_swept=.true.)
    call optimize_and_print(input, setup, job)
    call print_points(input, setup, job%result)
    call put(input, 'population_size', real(size(setup%members), wp))
    call put(input, 'robust_acceleration_start', job%result%before%robust_acceleration)
    call put(input, 'robust_acceleration', job%result%after%robust_acceleration)
    do k = 1, size(setup%members)
      associate (m => setup%members(k), row => 'members.'//format_integer(k)//'.')
        call put(input, row//'member', real(k, wp))
        call put(input, row//'height', m%height)
        call put(input, row//'mass', m%body%mass)
        call put(input, row//'speed0', m%speed)
        call put(input, row//'wall_angle', (m%v - pi/2)*degrees)
        call put(input, row//'heading', setup%start_angles(k)*degrees)
        call put(input, row//'max_a_end', job%result%after%rides(k)%max_acceleration)
        call put(input, row//'lever_arm_end', min(job%result%after%rides(k)%max_lever_arm, 1e30_wp))
      end associate
    end do
  end subroutine robust

  !> inputs/design/optimize_standard_parts.nml: a tube of radius 0.7 m
  !> around six elements from (0, 0, 7) heading 0, transitions 2 m; the radii
  !> of both curves and the slope of the straight between as the design, three
  !> rides from 1 m/s at -20, 0, 20 deg, the penalty (limit 0.25 m), LMDER at
  !> 1e-4 and 1e-3, one thread; the catalogue: radii 3, 4, 5, 6, 8 m, slopes
  !> in steps of 2 deg, at most 64 designs of the neighbourhood.
  subroutine standard_parts()
    character(len=*), parameter :: input = 'inputs/design/optimize_standard_parts.nml'
    type(optimization_setup_t) :: setup
    type(optimization_job_t) :: job
    type(catalogue_t) :: catalogue
    type(slide_elements_description_t) :: chain
    real(wp), parameter :: radii(5) = [3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp, 8.0_wp]
    integer :: k
    chain%start = [0.0_wp, 0.0_wp, 7.0_wp]
    chain%heading_deg = 0
    chain%transition_length = 2
    chain%elements = [element('straight', 3.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('curve', 0.0_wp, 6.0_wp, 4.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('straight', 3.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('curve', 0.0_wp, 6.0_wp, 4.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('straight', 3.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('runout', 4.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    setup%design%from_elements = .true.
    setup%design%chain = chain
    setup%design%radius = 0.7_wp
    setup%design%element = [2, 4, 3]
    setup%design%parameter = [PARAMETER_RADIUS, PARAMETER_RADIUS, PARAMETER_SLOPE]
    setup%design%lower = [3.0_wp, 3.0_wp, 4.0_wp]
    setup%design%upper = [8.0_wp, 8.0_wp, 12.0_wp]
    setup%start_angles = [-20.0_wp, 0.0_wp, 20.0_wp]*pi/180
    setup%start_speed = 1
    setup%constraint = CONSTRAINT_PENALTY
    setup%lever_limit = 0.25_wp
    setup%solver%ftol = 1e-4_wp
    setup%solver%xtol = 1e-3_wp
    setup%threads = 1
    allocate (catalogue%allowed(3))
    catalogue%max_designs = 64
    do k = 1, 2
      catalogue%allowed(k)%values = allowed_in_list(radii, setup%design%lower(k), setup%design%upper(k))
    end do
    catalogue%allowed(3)%values = allowed_by_step(2.0_wp, setup%design%lower(3), setup%design%upper(3))
    call optimize_and_print(input, setup, job, catalogue)
    call print_catalogue(input, setup, job)
  end subroutine standard_parts

  !> inputs/design/optimize_bowl_parts.nml: a tube of radius 1 m around an
  !> entry straight, a spherical bowl, an outlet straight and a run-out from
  !> (0, 0, 10) heading 0, transitions 2 m; the bowl's entry radius, wall
  !> slope and drop as the design, three rides from 1 m/s at -20, 0, 20 deg,
  !> the penalty (limit 0.25 m), LMDER at 1e-4 and 1e-3, one thread; the
  !> catalogue: entry radii 5, 6, 7, 8 m, wall slopes in steps of 5 deg,
  !> drops 1.5, 2, 2.5 m, at most 64 designs of the neighbourhood.
  subroutine bowl_parts()
    character(len=*), parameter :: input = 'inputs/design/optimize_bowl_parts.nml'
    type(optimization_setup_t) :: setup
    type(optimization_job_t) :: job
    type(catalogue_t) :: catalogue
    type(slide_elements_description_t) :: chain
    chain%start = [0.0_wp, 0.0_wp, 10.0_wp]
    chain%heading_deg = 0
    chain%transition_length = 2
    chain%elements = [element('straight', 12.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('bowl', 0.0_wp, 50.0_wp, 6.0_wp, 0.0_wp, 'left', 1.0_wp, 2.0_wp), &
                      element('straight', 10.0_wp, 14.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
                      element('runout', 8.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    setup%design%from_elements = .true.
    setup%design%chain = chain
    setup%design%radius = 1.0_wp
    setup%design%element = [2, 2, 2]
    setup%design%parameter = [PARAMETER_RADIUS, PARAMETER_SLOPE, PARAMETER_DROP]
    setup%design%lower = [5.0_wp, 40.0_wp, 1.5_wp]
    setup%design%upper = [8.0_wp, 55.0_wp, 2.5_wp]
    setup%start_angles = [-20.0_wp, 0.0_wp, 20.0_wp]*pi/180
    setup%start_speed = 1
    setup%constraint = CONSTRAINT_PENALTY
    setup%lever_limit = 0.25_wp
    setup%solver%ftol = 1e-4_wp
    setup%solver%xtol = 1e-3_wp
    setup%threads = 1
    allocate (catalogue%allowed(3))
    catalogue%max_designs = 64
    associate (lower => setup%design%lower, upper => setup%design%upper)
      catalogue%allowed(1)%values = allowed_in_list([5.0_wp, 6.0_wp, 7.0_wp, 8.0_wp], lower(1), upper(1))
      catalogue%allowed(2)%values = allowed_by_step(5.0_wp, lower(2), upper(2))
      catalogue%allowed(3)%values = allowed_in_list([1.5_wp, 2.0_wp, 2.5_wp], lower(3), upper(3))
    end associate
    call optimize_and_print(input, setup, job, catalogue)
    call print_catalogue(input, setup, job)
  end subroutine bowl_parts

  !> The summary's numbers and words of a design snapped to a catalogue: the
  !> cost, each variable (start, optimum, nearest, catalogue), the verdict,
  !> the catalogue design's costs and the parts list.
  subroutine print_catalogue(input, setup, job)
    character(len=*), intent(in) :: input
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_job_t), intent(in) :: job
    real(wp), allocatable :: x0(:), values(:)
    real(wp) :: scale
    integer :: k, j
    character(len=:), allocatable :: line
    call put(input, 'acceleration_cost', job%result%after%acceleration_cost)
    ! each variable (start, optimum, nearest, catalogue) in SI: the slope in rad
    x0 = start_x(setup%design)
    do k = 1, size(x0)
      values = [x0(k), job%result%x(k), job%chosen%x_nearest(k), job%chosen%x(k)]
      scale = merge(degrees, 1.0_wp, setup%design%parameter(k) == PARAMETER_SLOPE)
      do j = 1, 4
        call put(input, 'variable_'//format_integer(k)//'.'//format_integer(j), values(j)/scale)
      end do
    end do
    call put_text(input, 'catalogue', job%chosen%verdict)
    ! the nearest design's cost: a number when feasible, else in words (the summary's)
    if (job%chosen%candidate_feasible(1)) then
      call put(input, 'nearest_acceleration_cost', job%chosen%acceleration_cost(1))
    else if (job%chosen%acceleration_cost(1) < huge(1.0_wp)) then
      call put_text(input, 'nearest_acceleration_cost', format_short(job%chosen%acceleration_cost(1))// &
                    ' m^2/s^4, infeasible')
    else
      call put_text(input, 'nearest_acceleration_cost', 'cannot be built or ridden')
    end if
    call put(input, 'catalogue_acceleration_cost', job%chosen%chosen%acceleration_cost)
    call put(input, 'catalogue_max_lever_arm', job%chosen%chosen%max_lever_arm)
    call put(input, 'parts', real(size(job%chosen%parts), wp))
    call put(input, 'elements', real(sum(job%chosen%parts%count), wp))
    ! the parts list: '2 x straight, length 3 m, slope 8 deg (elements 1, 5)'
    do k = 1, size(job%chosen%parts)
      associate (part => job%chosen%parts(k))
        line = format_integer(part%count)//' x '//part_text(part%element)//' (element'// &
               trim(merge('s', ' ', part%count > 1))//' '
        do j = 1, size(part%elements)
          if (j > 1) line = line//', '
          line = line//format_integer(part%elements(j))
        end do
        call put_text(input, 'line', line//')')
      end associate
    end do
  end subroutine print_catalogue

  !> The job of `setup` (with `catalogue`: snapped to it) and the summary's
  !> numbers of every optimisation: the outcome, the costs, the lever arms,
  !> the designs evaluated, each ride's largest acceleration and lever arm.
  subroutine optimize_and_print(input, setup, job, catalogue)
    character(len=*), intent(in) :: input
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_job_t), intent(out) :: job
    type(catalogue_t), intent(in), optional :: catalogue
    type(status_t) :: status
    integer :: k
    call run_optimization(setup, job, status, catalogue)
    call stop_unless_ok(input, 'the optimisation', status)
    associate (result => job%result)
      call put_text(input, 'outcome', trim(outcome_names(result%outcome)))
      call put(input, 'restarts', real(result%restarts, wp))
      call put(input, 'cost_start', result%cost_before)
      call put(input, 'cost', result%cost_after)
      call lever(input, 'max_lever_arm_start', result%before%max_lever_arm)
      call lever(input, 'max_lever_arm', result%after%max_lever_arm)
      call put(input, 'lever_limit', setup%lever_limit)
      call put(input, 'evaluations', real(result%evaluations, wp))
      do k = 1, size(setup%start_angles)
        associate (row => 'rides.'//format_integer(k)//'.')
          call put(input, row//'start_angle', setup%start_angles(k)*degrees)
          call put(input, row//'max_a_start', result%before%rides(k)%max_acceleration)
          call put(input, row//'max_a_optimum', result%after%rides(k)%max_acceleration)
          call put(input, row//'lever_arm_start', min(result%before%rides(k)%max_lever_arm, 1e30_wp))
          call put(input, row//'lever_arm_optimum', min(result%after%rides(k)%max_lever_arm, 1e30_wp))
        end associate
      end do
    end associate
  end subroutine optimize_and_print

  !> A design of points: each variable's point, coordinate, start, optimum.
  subroutine print_points(input, setup, result)
    character(len=*), intent(in) :: input
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_result_t), intent(in) :: result
    real(wp), allocatable :: x0(:)
    integer :: k
    x0 = start_x(setup%design)
    do k = 1, size(result%x)
      associate (row => 'design.'//format_integer(k)//'.')
        call put(input, row//'point', real(setup%design%point(k) - 1, wp))
        call put(input, row//'coordinate', real(setup%design%coordinate(k), wp))
        call put(input, row//'start', x0(k))
        call put(input, row//'optimum', result%x(k))
        call put(input, row//'move', result%x(k) - x0(k))
      end associate
    end do
  end subroutine print_points

  !> A largest lever arm: its value, or the summary's words for a lift-off.
  subroutine lever(input, key, x)
    character(len=*), intent(in) :: input, key
    real(wp), intent(in) :: x
    if (x >= 1e30_wp) then
      call put_text(input, key, 'lift-off (a body does not stay pressed on the slide)')
    else
      call put(input, key, x)
    end if
  end subroutine lever
end program library_optimize
