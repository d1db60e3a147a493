!> &optimize: the geometry optimisation of a tube slide around a centerline
!> through points (thesis 4.7; docs/design.md lists every variable with unit,
!> default and range). The defaults are thesis table 4.12 and (4.49).
module io_optimization_config
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_integer
  use base_status, only: status_t
  use numerics_ode, only: ode_options_t
  use design_cuboid_ride, only: ACCELERATION_KINEMATIC, ACCELERATION_FELT
  use design_geometry_optimization, only: optimization_setup_t, table_4_12_design, thesis_start_angles, &
    CONSTRAINT_PENALTY, CONSTRAINT_EXACT, CONSTRAINT_NONE
  use io_input, only: input_text_t, group_reader_t, open_group, bounds_t, format_real, group_present
  implicit none (type, external)
  private
  public :: read_optimization_config, max_points, max_design, max_rides

  !> the largest n_points, n_design and start_angles_deg of the declarations
  !> (io_declarations_design; test_input_declarations checks they agree)
  integer, parameter :: max_points = 200, max_design = 50, max_rides = 50
  !> The letters of the design coordinates 1, 2, 3 (slide_design_t%coordinate).
  character(len=*), parameter :: axes = 'xyz'

contains

  subroutine read_optimization_config(input, setup, status)
    type(input_text_t), intent(in) :: input
    type(optimization_setup_t), intent(out) :: setup
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    real(wp), allocatable :: points(:, :), lower(:), upper(:), angles(:), point_real(:)
    character(len=1), allocatable :: coordinate(:)
    character(len=10) :: acceleration, constraint
    integer :: n_points, n_design, n_given, i
    real(wp) :: start_wall_angle_deg
    type(bounds_t) :: point_bounds

    setup%design = table_4_12_design()
    setup%start_angles = thesis_start_angles()
    n_points = size(setup%design%points, 2)
    n_design = size(setup%design%point)
    acceleration = 'kinematic'
    constraint = 'penalty'
    start_wall_angle_deg = 0
    call open_group(input, 'optimize', r, status)
    if (.not. status%ok()) return

    ! the centerline points and the design variables (default: table 4.12)
    call r%get('n_points', n_points, status)
    allocate (points(3, max_points))
    points = 0
    points(:, :size(setup%design%points, 2)) = setup%design%points
    call r%get_columns('points', points, 'the limit of '//format_integer(max_points)//' points', n_given, status)
    if (.not. status%ok()) return
    if (r%has('points') .and. n_given /= n_points) then
      call r%invalid('points', format_integer(n_given)//' points', 'give n_points = '// &
                     format_integer(n_points)//' points (x, y, z each)', status)
      return
    end if
    if (r%has('n_points') .and. .not. r%has('points')) then
      call r%invalid('n_points', format_integer(n_points), 'give the points too', status)
      return
    end if
    setup%design%points = points(:, :n_points)

    call r%get('n_design', n_design, status)
    if (.not. status%ok()) return
    allocate (point_real(n_design), coordinate(n_design), lower(n_design), upper(n_design))
    point_real = 0
    coordinate = 'x'
    lower = 0
    upper = 0
    if (.not. r%has('n_design') .and. n_design == size(setup%design%point)) then
      ! table 4.12's design variables, as the design layer gives them
      point_real = real(setup%design%point - 1, wp)
      coordinate = [(axes(setup%design%coordinate(i):setup%design%coordinate(i)), i=1, n_design)]
      lower = setup%design%lower
      upper = setup%design%upper
    end if
    call r%get_parts('design_point', point_real, 'n_design = '//format_integer(n_design), status)
    call r%get_parts('design_coordinate', coordinate, 'n_design = '//format_integer(n_design), status)
    call r%get_parts('lower', lower, 'n_design = '//format_integer(n_design), status)
    call r%get_parts('upper', upper, 'n_design = '//format_integer(n_design), status)
    if (.not. status%ok()) return
    ! a point of this centerline: the declared range up to n_points - 1
    call r%bounds('design_point', point_bounds, status)
    point_bounds%high = n_points - 1
    do i = 1, n_design
      if (status%ok() .and. .not. point_bounds%allows(point_real(i))) &
        call r%invalid('design_point('//format_integer(i)//')', format_real(point_real(i)), &
                       point_bounds%text()//': a point of the n_points = '//format_integer(n_points), status)
    end do
    if (.not. status%ok()) return
    if (r%has('n_design') .and. .not. (r%has('design_point') .and. r%has('design_coordinate') .and. &
                                       r%has('lower') .and. r%has('upper'))) then
      call r%invalid('n_design', format_integer(n_design), 'give design_point, design_coordinate, lower and '// &
                     'upper for every design variable', status)
      return
    end if
    setup%design%point = nint(point_real) + 1
    setup%design%coordinate = [(index(axes, coordinate(i)), i=1, n_design)]
    setup%design%lower = lower
    setup%design%upper = upper
    do i = 1, n_design
      if (abs(point_real(i) - nint(point_real(i))) > 0) then
        call r%invalid('design_point('//format_integer(i)//')', format_real(point_real(i)), &
                       'must be a whole point number, 0 for the first point', status)
        return
      end if
      if (.not. lower(i) < upper(i)) then
        call r%invalid('upper('//format_integer(i)//')', format_real(upper(i)), 'must exceed lower('// &
                       format_integer(i)//') = '//format_real(lower(i)), status)
        return
      end if
      associate (x => setup%design%points(setup%design%coordinate(i), setup%design%point(i)))
        if (x < lower(i) .or. x > upper(i)) then
          call r%invalid('lower('//format_integer(i)//'), upper('//format_integer(i)//')', &
                         format_real(lower(i))//', '//format_real(upper(i)), 'must hold the start value '// &
                         format_real(x)//' m of point '//format_integer(setup%design%point(i) - 1)//' '// &
                         coordinate(i), status)
          return
        end if
      end associate
      if (any(setup%design%point(:i - 1) == setup%design%point(i) .and. &
              setup%design%coordinate(:i - 1) == setup%design%coordinate(i))) then
        call r%invalid('design_point('//format_integer(i)//')', format_real(point_real(i)), &
                       'this coordinate is already a design variable', status)
        return
      end if
    end do

    call r%get('radius', setup%design%radius, status)
    call r%get('degree', setup%design%degree, status)
    call r%get('smoothing', setup%design%smoothing, status)
    call r%get('horizon', setup%design%horizon, status)
    if (status%ok() .and. .not. norm2(setup%design%horizon) > 0) &
      call r%invalid('horizon', '0', 'must be a non-zero vector', status)
    if (status%ok() .and. setup%design%degree + 1 > n_points) &
      call r%invalid('degree', format_integer(setup%design%degree), 'needs more than degree points', status)

    ! the rides
    call r%get_list('start_angles_deg', angles, max_rides, status)
    if (status%ok() .and. r%has('start_angles_deg')) setup%start_angles = angles*pi/180
    ! (an element design's variables are counted by io_element_design_config,
    ! a population's members by io_optimization_population)
    if (status%ok() .and. 2*size(setup%start_angles) < n_design .and. &
        .not. (group_present(input, 'design_elements') .or. group_present(input, 'sweep'))) &
      call r%invalid('start_angles_deg', format_integer(size(setup%start_angles))//' rides', 'give at least '// &
                     format_integer((n_design + 1)/2)//' rides for '//format_integer(n_design)// &
                     ' design variables (each ride gives two residuals: its acceleration and its lever arm)', status)
    call r%get('start_speed', setup%start_speed, status)
    call r%get('start_wall_angle_deg', start_wall_angle_deg, status)
    setup%start_v = pi/2 + start_wall_angle_deg*pi/180
    call r%get('body_mass', setup%body%mass, status)
    call r%get('body_length', setup%body%length, status)
    call r%get('body_width', setup%body%width, status)
    call r%get('body_height', setup%body%height, status)
    call r%get('com_height', setup%body%com_height, status)
    call r%get('acceleration', acceleration, status)
    setup%ride%acceleration = merge(ACCELERATION_FELT, ACCELERATION_KINEMATIC, acceleration == 'felt')

    ! the constraint and the optimiser
    call r%get('constraint', constraint, status)
    select case (trim(constraint))
    case ('exact'); setup%constraint = CONSTRAINT_EXACT
    case ('none'); setup%constraint = CONSTRAINT_NONE
    case default; setup%constraint = CONSTRAINT_PENALTY
    end select
    call r%get('lever_limit', setup%lever_limit, status)
    call r%get('penalty_factor', setup%penalty_factor, status)
    call r%get('lever_tolerance', setup%lever_tolerance, status)
    call r%get('threads', setup%threads, status)
    call r%get('ftol', setup%solver%ftol, status)
    call r%get('xtol', setup%solver%xtol, status)
    call r%get('max_designs', setup%solver%max_evaluations, status)
    call r%get('max_restarts', setup%max_restarts, status)
    call r%get('starts', setup%starts, status)
    call r%get('seed', setup%seed, status)
    if (setup%starts == 1) call r%refuse_given(['seed'], 'seed draws the starts after the first: it is used '// &
      'only with starts > 1', status)
    setup%rho = 20*setup%penalty_factor
  end subroutine read_optimization_config
end module io_optimization_config
