!> The geometry groups of a tube or a slide: &centerline, &slide_elements
!> and &cross_section, each read into its description
!> (geometry_slide_builder) after every value is checked: its range and
!> words from the declarations (io_declarations_geometry), and what follows
!> from several values (a horizon parallel to the centerline, points
!> repeated, a profile crossing itself, a value the chosen kind does not
!> use). Nothing is built here: what only the built slide can tell (a
!> spline that cannot be fitted, a transition beyond the centerline's end, a
!> tube that folds) the geometry layer refuses when it builds the slide
!> (io_geometry_config places its message in the input).
module io_slide_geometry_config
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_text, only: format_integer
  use base_constants, only: pi
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use geometry_curve_frame, only: horizon_parallel_tol
  use geometry_cross_section, only: polyline_self_intersection
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: centerline_description_t, slide_elements_description_t, &
    section_part_description_t, cross_section_description_t
  use io_input, only: input_text_t, group_reader_t, open_group, bounds_t, format_real, format_vector, group_present, &
    indexed_name
  use io_csv, only: read_csv_table
  use io_element_table, only: element_table_t, read_element_table, check_element
  use io_patch_grid, only: read_patch_grid
  use geometry_patch_section, only: patch_grid_t
  use io_declarations_geometry, only: max_centerline_points, max_elements, max_profile_points
  implicit none (type, external)
  private
  public :: read_centerline, read_slide_elements, read_cross_section, check_list_length, check_exactly

contains

  !> &centerline: kind = 'line' | 'helix' | 'points', and the horizon field
  !> (a constant vector, or for points one horizon vector per point, fitted).
  !> Points come from `points` or from the CSV file `points_file`.
  subroutine read_centerline(input, described, status)
    type(input_text_t), intent(in) :: input
    type(centerline_description_t), intent(out) :: described
    type(status_t), intent(inout) :: status
    character(len=8) :: kind
    character(len=4096) :: points_file
    real(wp) :: start(3), end(3), center(3), radius, rise_per_turn, turns, phase_deg, horizon(3)
    real(wp) :: smoothing, start_tangent(3), end_tangent(3)
    real(wp), allocatable :: points(:, :), horizon_points(:, :), table(:, :)
    integer :: n_points, n_given, n_horizon, degree, i
    logical :: have_horizon_points
    character(len=*), parameter :: g = 'centerline'
    real(wp) :: t(3), d
    type(group_reader_t) :: r
    type(bounds_t) :: position, direction
    character(len=:), allocatable :: unused

    kind = 'line'
    start = [0, 0, 0]; end = [10, 0, 0]
    center = 0; radius = 5; rise_per_turn = 0; turns = 0.25_wp; phase_deg = -90
    horizon = [0, 0, 1]
    n_points = 0; smoothing = 0; degree = 5; points_file = ''
    start_tangent = 0; end_tangent = 0
    call open_group(input, g, r, status)
    call r%get('kind', kind, status)
    call r%get('horizon', horizon, status)
    call r%bounds('points', position, status)
    call r%bounds('horizon_points', direction, status)
    if (.not. status%ok()) return
    unused = 'a '//trim(kind)//' centerline does not use it (see docs/geometry.md)'
    if (kind /= 'line') call r%refuse_given([character(len=5) :: 'start', 'end'], unused, status)
    if (kind /= 'helix') call r%refuse_given([character(len=13) :: 'center', 'radius', 'rise_per_turn', 'turns', &
                                              'phase_deg'], unused, status)
    if (kind /= 'points') call r%refuse_given([character(len=14) :: 'n_points', 'points', 'points_file', &
      'smoothing', 'degree', 'start_tangent', 'end_tangent', 'horizon_points'], unused, status)
    if (status%ok() .and. .not. norm2(horizon) > 0) &
      call r%invalid('horizon', format_vector(horizon), 'must be a non-zero vector', status)
    if (.not. status%ok()) return
    described%kind = kind
    described%horizon = horizon
    select case (trim(kind))
    case ('line')
      call r%get('start', start, status)
      call r%get('end', end, status)
      if (status%ok() .and. .not. norm2(end - start) > 1e-3_wp) &
        call r%invalid('end', format_vector(end), 'must lie at least 1 mm from start', status)
      if (.not. status%ok()) return
      t = (end - start)/norm2(end - start)
      if (norm2(cross(horizon/norm2(horizon), t)) < horizon_parallel_tol) then
        call r%invalid('horizon', format_vector(horizon), &
                       'must not be parallel to the centerline tangent '//format_vector(t), status)
        return
      end if
      described%start = start
      described%end = end
    case ('helix')
      call r%get('center', center, status)
      call r%get('radius', radius, status)
      call r%get('rise_per_turn', rise_per_turn, status)
      call r%get('turns', turns, status)
      call r%get('phase_deg', phase_deg, status)
      if (.not. status%ok()) return
      described%center = center
      described%radius = radius
      described%rise_per_turn = rise_per_turn
      described%turns = turns
      described%phase = phase_deg*pi/180
    case ('points')
      call r%get('n_points', n_points, status)
      call r%get('points_file', points_file, status)
      if (.not. status%ok()) return
      allocate (points(3, max_centerline_points), horizon_points(3, max_centerline_points))
      points = 0
      horizon_points = 0
      if (len_trim(points_file) > 0) then
        call r%refuse_given([character(len=14) :: 'points', 'horizon_points'], 'the points come from points_file',  &
                            status)
        if (.not. status%ok()) return
        ! x, y, z per line, or x, y, z, hx, hy, hz with the horizon vector of each point
        call read_csv_table(input%resolve_path(points_file), 3, 6, max_centerline_points, &
                            [position, position, position, direction, direction, direction], table, status)
        if (.not. status%ok()) then
          call prefix_status(status, r%where('points_file')//': &'//g//': points_file = '''//trim(points_file)//'''')
          return
        end if
        if (size(table, 1) /= 3 .and. size(table, 1) /= 6) then
          call r%invalid('points_file', ''''//trim(points_file)//'''', 'needs 3 columns (x, y, z) or 6 '// &
                         '(x, y, z, hx, hy, hz with the horizon vector), not '//format_integer(size(table, 1)), status)
          return
        end if
        n_given = size(table, 2)
        points(:, :n_given) = table(1:3, :)
        have_horizon_points = size(table, 1) == 6
        if (have_horizon_points) horizon_points(:, :n_given) = table(4:6, :)
        if (.not. r%has('n_points')) n_points = n_given
        if (n_given < 4) then
          call r%invalid('points_file', ''''//trim(points_file)//'''', 'has '//format_integer(n_given)// &
                         ' points; a centerline needs at least 4', status)
          return
        end if
      else
        call r%get_columns('points', points, 'the limit of '//format_integer(max_centerline_points)//' points', n_given, status)
        call r%get_columns('horizon_points', horizon_points, 'the limit of '//format_integer(max_centerline_points)// &
                           ' points', n_horizon, status)
        if (.not. status%ok()) return
        have_horizon_points = n_horizon > 0
        if (.not. r%has('n_points')) then
          call r%invalid('n_points', format_integer(n_points), 'give the number of centerline points '// &
                         '(4 to '//format_integer(max_centerline_points)//')', status)
          return
        end if
        if (have_horizon_points .and. n_horizon /= n_points) then
          call r%invalid('horizon_points', format_integer(3*n_horizon)//' numbers', 'give one horizon vector '// &
                         '(3 numbers) per centerline point: '//format_integer(3*n_points)// &
                         ' numbers for n_points = '//format_integer(n_points), status)
          return
        end if
      end if
      call check_list_length(r, 'n_points', n_points, merge('points_file', 'points     ', len_trim(points_file) > 0), &
                             n_given, 'points', status)
      call r%get('smoothing', smoothing, status)
      call r%get('degree', degree, status)
      call r%get('start_tangent', start_tangent, status)
      call r%get('end_tangent', end_tangent, status)
      if (status%ok() .and. mod(degree, 2) == 0 .and. (any(start_tangent /= 0) .or. any(end_tangent /= 0))) &
        call r%invalid('degree', format_integer(degree), 'must be odd (3 or 5) when end tangents are given', status)
      if (.not. status%ok()) return
      d = maxval(norm2(points(:, 2:n_points) - points(:, 1:n_points - 1), dim=1))
      do i = 2, n_points
        if (norm2(points(:, i) - points(:, i - 1)) <= 1e-9_wp*max(d, 1.0_wp)) then
          call r%invalid('points(:, '//format_integer(i)//')', format_vector(points(:, i)), &
                         'duplicate consecutive centerline point (equal to points(:, '//format_integer(i - 1)//'))', &
                         status)
          return
        end if
        t = (points(:, i) - points(:, i - 1))/norm2(points(:, i) - points(:, i - 1))
        if (have_horizon_points) then
          if (.not. (norm2(horizon_points(:, i)) > 0 .and. norm2(horizon_points(:, i - 1)) > 0)) then
            call r%invalid('horizon_points(:, '//format_integer(merge(i, i - 1, norm2(horizon_points(:, i)) == 0)) &
                           //')', '0', 'every horizon point must be a non-zero vector', status)
            return
          end if
          if (norm2(cross(horizon_points(:, i)/norm2(horizon_points(:, i)), t)) < horizon_parallel_tol .or. &
              norm2(cross(horizon_points(:, i - 1)/norm2(horizon_points(:, i - 1)), t)) < horizon_parallel_tol) then
            call r%invalid('horizon_points(:, '//format_integer(i)//')', format_vector(horizon_points(:, i)), &
                           'is parallel to the centerline between points '//format_integer(i - 1)// &
                           ' and '//format_integer(i), status)
            return
          end if
        else if (norm2(cross(horizon/norm2(horizon), t)) < horizon_parallel_tol) then
          call r%invalid('horizon', format_vector(horizon), 'is parallel to the centerline '// &
                         'between points '//format_integer(i - 1)//' and '//format_integer(i), status)
          return
        end if
      end do
      described%points = points(:, 1:n_points)
      described%smoothing = smoothing
      described%degree = degree
      described%start_tangent = start_tangent
      described%end_tangent = end_tangent
      if (have_horizon_points) described%horizon_points = horizon_points(:, 1:n_points)
    end select
  end subroutine read_centerline

  !> &slide_elements: the slide as a chain of standard elements. A value an
  !> element does not use must be left out or equal its default (0; 'left'
  !> for direction), so that tables with a column per element stay possible.
  subroutine read_slide_elements(input, described, status)
    type(input_text_t), intent(in) :: input
    type(slide_elements_description_t), intent(out) :: described
    type(status_t), intent(inout) :: status
    integer :: n, i, degree, n_bowl
    real(wp), allocatable :: bowl_rho(:), bowl_z(:)
    character(len=8), allocatable :: kind(:)
    character(len=5), allocatable :: direction(:)
    character(len=6), allocatable :: bowl_profile(:)
    real(wp), allocatable :: length(:), slope_deg(:), radius(:), angle_deg(:), turns(:), drop(:)
    logical, allocatable :: given_kind(:)
    real(wp) :: start(3), heading_deg, transition_length, fit_spacing, smoothing
    character(len=8) :: centerline_kind
    type(slide_element_t), allocatable :: e(:)
    type(group_reader_t) :: r
    character(len=:), allocatable :: lim
    character(len=*), parameter :: g = 'slide_elements'
    character(len=4096) :: elements_file
    type(element_table_t) :: table
    character(len=:), allocatable :: variable, value, allowed
    character(len=1024), allocatable :: patch_file(:)
    logical, allocatable :: given_patch(:)

    n = 0
    start = [0, 0, 0]; heading_deg = 0; transition_length = 2
    centerline_kind = 'fitted'; fit_spacing = 0.125_wp; smoothing = 0; degree = 5
    if (status%ok() .and. .not. group_present(input, g)) then
      call set_status(status, STATUS_INVALID_INPUT, input%name//': &'//g//' is missing: a slide (&geometry '// &
                      'kind = ''slide'', the default) is built from its elements; give &'//g// &
                      ' or choose another &geometry kind')
      return
    end if
    elements_file = ''
    call open_group(input, g, r, status)
    call r%get('elements_file', elements_file, status)
    if (.not. status%ok()) return
    if (len_trim(elements_file) > 0) then
      ! the elements from a manufacturer's table (io_element_table), checked there
      call r%refuse_given([character(len=12) :: 'kind', 'length', 'slope_deg', 'radius', 'angle_deg', 'direction', &
                           'turns', 'drop', 'bowl_profile', 'patch_file'], 'the elements come from elements_file', &
                          status)
      if (status%ok()) call read_element_table(input%resolve_path(elements_file), max_elements, table, status)
      if (.not. status%ok()) then
        call prefix_status(status, r%where('elements_file')//': &'//g//': elements_file = '''// &
                           trim(elements_file)//'''')
        return
      end if
      n = size(table%kind)
      call r%get('n_elements', n, n, n, status)   ! if given, the table's number of rows
      if (.not. status%ok()) return
      kind = table%kind; direction = table%direction; length = table%length; slope_deg = table%slope_deg
      radius = table%radius; angle_deg = table%angle_deg; turns = table%turns; drop = table%drop
      bowl_profile = table%bowl_profile
      allocate (given_kind(n), e(n), patch_file(n), given_patch(n))
      given_kind = .true.
      given_patch = .false.
    else
      call r%get('n_elements', n, status)
      if (.not. status%ok()) return
      if (.not. r%has('n_elements')) then
        call r%invalid('n_elements', '0', 'give the number of elements (1 to '//format_integer(max_elements)// &
                       ') or an elements_file', status)
        return
      end if
      lim = 'n_elements = '//format_integer(n)
      allocate (kind(n), direction(n), length(n), slope_deg(n), radius(n), angle_deg(n), turns(n), drop(n), &
                given_kind(n), e(n), bowl_profile(n), patch_file(n), given_patch(n))
      kind = ''; direction = 'left'; bowl_profile = 'sphere'
      length = 0; slope_deg = 0; radius = 0; angle_deg = 0; turns = 0; drop = 0
      call r%get_parts('kind', kind, lim, status, given=given_kind)
      call r%get_parts('direction', direction, lim, status)
      call r%get_parts('length', length, lim, status)
      call r%get_parts('slope_deg', slope_deg, lim, status)
      call r%get_parts('radius', radius, lim, status)
      call r%get_parts('angle_deg', angle_deg, lim, status)
      call r%get_parts('turns', turns, lim, status)
      call r%get_parts('drop', drop, lim, status)
      call r%get_parts('bowl_profile', bowl_profile, lim, status)
      patch_file = ''
      call r%get_parts('patch_file', patch_file, lim, status, given=given_patch)
    end if
    ! the profile table of the bowls with bowl_profile = 'table' (one for all)
    if (.not. status%ok()) return
    if (.not. any(bowl_profile == 'table')) then
      call r%refuse_given([character(len=13) :: 'n_bowl_points', 'bowl_rho', 'bowl_z'], &
                          'only a bowl with bowl_profile = ''table'' uses it', status)
    else
      call r%get('n_bowl_points', n_bowl, status)
      call r%get_list('bowl_rho', bowl_rho, max_profile_points, status)
      call r%get_list('bowl_z', bowl_z, max_profile_points, status)
      if (status%ok() .and. .not. r%has('n_bowl_points')) &
        call r%invalid('n_bowl_points', '0', 'a bowl with bowl_profile = ''table'' needs its profile''s points: '// &
                       'give n_bowl_points, bowl_rho and bowl_z', status)
      if (.not. status%ok()) return
      call check_list_length(r, 'n_bowl_points', n_bowl, 'bowl_rho', size(bowl_rho), 'points', status)
      call check_list_length(r, 'n_bowl_points', n_bowl, 'bowl_z', size(bowl_z), 'points', status)
    end if
    call r%get('start', start, status)
    call r%get('heading_deg', heading_deg, status)
    call r%get('transition_length', transition_length, status)
    call r%get('centerline_kind', centerline_kind, status)
    if (.not. status%ok()) return
    if (centerline_kind == 'exact') then
      call r%refuse_given([character(len=11) :: 'fit_spacing', 'smoothing', 'degree'], &
                          'centerline_kind = ''exact'' is not fitted', status)
    else
      call r%get('fit_spacing', fit_spacing, status)
      call r%get('smoothing', smoothing, status)
      call r%get('degree', degree, status)
      if (status%ok() .and. degree == 4) call r%invalid('degree', '4', 'must be 3 or 5', status)
    end if
    if (.not. status%ok()) return
    call check_list_length(r, 'n_elements', n, 'kind', count(given_kind), 'elements', status)
    do i = 1, n
      if (.not. status%ok()) return
      call check_element(kind(i), length(i), slope_deg(i), radius(i), angle_deg(i), direction(i), turns(i), &
                         drop(i), variable, value, allowed, bowl_profile(i))
      if (len(variable) > 0) call r%invalid(indexed_name(variable, i), value, allowed, status)
      if (.not. status%ok()) return
      e(i) = slide_element_t(kind=kind(i), length=length(i), slope_deg=slope_deg(i), radius=radius(i), &
                             angle_deg=angle_deg(i), direction=direction(i), turns=turns(i), drop=drop(i), &
                             bowl_profile=bowl_profile(i))
      if (bowl_profile(i) == 'table') then
        e(i)%bowl_rho = bowl_rho
        e(i)%bowl_z = bowl_z
      end if
    end do
    described%elements = e
    call read_patches(status)
    if (.not. status%ok()) return
    described%start = start
    described%heading_deg = heading_deg
    described%transition_length = transition_length
    described%exact = centerline_kind == 'exact'
    described%fit_spacing = fit_spacing
    described%smoothing = smoothing
    described%degree = degree

  contains

    !> The grid of every patch from its patch_file (io_patch_grid); a
    !> patch_file for another kind is refused.
    subroutine read_patches(status)
      type(status_t), intent(inout) :: status
      type(patch_grid_t) :: grid
      allocate (described%patches(0))
      do i = 1, n
        if (kind(i) /= 'patch') then
          if (given_patch(i)) call r%invalid(indexed_name('patch_file', i), ''''//trim(patch_file(i))//'''', &
                                             'a '//trim(kind(i))//' has no patch; leave it out', status)
          if (.not. status%ok()) return
          cycle
        end if
        if (len_trim(patch_file(i)) == 0) then
          call r%invalid(indexed_name('patch_file', i), '''''', 'a patch needs the CSV file of its offsets '// &
                         '(station, angle, offset per line; docs/geometry.md)', status)
          return
        end if
        call read_patch_grid(input%resolve_path(trim(patch_file(i))), i, grid, status)
        if (.not. status%ok()) then
          call prefix_status(status, r%where('patch_file')//': &'//g//': '//indexed_name('patch_file', i)//' = '''// &
                             trim(patch_file(i))//'''')
          return
        end if
        grid%source = indexed_name('patch_file', i)//' = '''//trim(patch_file(i))//''''
        described%patches = [described%patches, grid]
      end do
    end subroutine read_patches
  end subroutine read_slide_elements

  !> &cross_section: n_sections sections (circle, ellipse, flume, profile)
  !> blended along the centerline; transitions given in arc length (m),
  !> checked against the centerline's length when the slide is built.
  subroutine read_cross_section(input, sections, status)
    type(input_text_t), intent(in) :: input
    type(cross_section_description_t), intent(out) :: sections
    type(status_t), intent(inout) :: status
    integer :: n, i, k, n_profile, profile_degree
    character(len=8), allocatable :: kind(:)
    real(wp), allocatable :: radius(:), half_width(:), half_height(:), wall(:), joint_width_deg(:), &
      transition_midpoint(:), transition_end(:), profile_y(:), profile_z(:)
    logical, allocatable :: given_kind(:), given_radius(:), given_half_width(:), given_half_height(:), &
      given_wall(:), given_joint(:), given_midpoint(:), given_end(:)
    real(wp) :: profile_smoothing
    type(section_part_description_t) :: described
    type(group_reader_t) :: r
    character(len=:), allocatable :: lim, tlim
    character(len=*), parameter :: g = 'cross_section'

    n = 1
    n_profile = 0; profile_smoothing = 0; profile_degree = 5
    call open_group(input, g, r, status)
    call r%get('n_sections', n, status)
    if (.not. status%ok()) return
    lim = 'n_sections = '//format_integer(n)
    tlim = 'n_sections - 1 = '//format_integer(n - 1)//' transitions'
    allocate (kind(n), radius(n), half_width(n), half_height(n), wall(n), joint_width_deg(n), given_kind(n), &
              given_radius(n), given_half_width(n), given_half_height(n), given_wall(n), given_joint(n), &
              sections%parts(n), transition_midpoint(n - 1), transition_end(n - 1), given_midpoint(n - 1), &
              given_end(n - 1))
    kind = ''
    radius = 0.5_wp; half_width = 0.5_wp; half_height = 0.5_wp; wall = 0.164_wp
    joint_width_deg = 0.05_wp*180/pi
    transition_midpoint = 0; transition_end = 0
    call r%get_parts('kind', kind, lim, status, given=given_kind)
    if (n == 1 .and. .not. r%has('kind')) then
      kind(1) = 'circle'
      given_kind = .true.
    end if
    call r%get_parts('radius', radius, lim, status, given=given_radius)
    call r%get_parts('half_width', half_width, lim, status, given=given_half_width)
    call r%get_parts('half_height', half_height, lim, status, given=given_half_height)
    call r%get_parts('wall', wall, lim, status, given=given_wall)
    call r%get_parts('joint_width_deg', joint_width_deg, lim, status, given=given_joint)
    call r%get_parts('transition_midpoint', transition_midpoint, tlim, status, given=given_midpoint)
    call r%get_parts('transition_end', transition_end, tlim, status, given=given_end)
    if (.not. status%ok()) return
    call check_list_length(r, 'n_sections', n, 'kind', count(given_kind), 'sections', status)
    call check_exactly(r, 'transition_midpoint', count(given_midpoint), n - 1, n, status)
    call check_exactly(r, 'transition_end', count(given_end), n - 1, n, status)
    if (.not. status%ok()) return
    if (.not. any(kind == 'profile')) call r%refuse_given([character(len=17) :: 'n_profile', 'profile_y', &
      'profile_z', 'profile_smoothing', 'profile_degree'], 'only a profile section uses it', status)
    do i = 1, n
      if (.not. status%ok()) return
      if (kind(i) /= 'circle' .and. kind(i) /= 'flume') call unused(given_radius, 'radius')
      if (kind(i) /= 'ellipse') call unused(given_half_width, 'half_width')
      if (kind(i) /= 'ellipse') call unused(given_half_height, 'half_height')
      if (kind(i) /= 'flume') call unused(given_wall, 'wall')
      if (kind(i) /= 'flume') call unused(given_joint, 'joint_width_deg')
      if (.not. status%ok()) return
      described = section_part_description_t(kind=kind(i), radius=radius(i), half_width=half_width(i), &
                                             half_height=half_height(i), wall=wall(i), &
                                             joint_width=joint_width_deg(i)*pi/180)
      select case (trim(kind(i)))
      case ('profile')
        call r%get('n_profile', n_profile, status)
        call r%get_list('profile_y', profile_y, max_profile_points, status)
        call r%get_list('profile_z', profile_z, max_profile_points, status)
        call r%get('profile_smoothing', profile_smoothing, status)
        call r%get('profile_degree', profile_degree, status)
        if (status%ok() .and. .not. r%has('n_profile')) &
          call r%invalid('n_profile', '0', 'too few profile points: need at least 4 (profile_y, profile_z)', status)
        call check_list_length(r, 'n_profile', n_profile, 'profile_y', size(profile_y), 'points', status)
        call check_list_length(r, 'n_profile', n_profile, 'profile_z', size(profile_z), 'points', status)
        if (.not. status%ok()) return
        do k = 2, n_profile
          if (profile_y(k) == profile_y(k - 1) .and. profile_z(k) == profile_z(k - 1)) then
            call r%invalid('profile_y('//format_integer(k)//'), profile_z('//format_integer(k)//')', &
                           format_vector([profile_y(k), profile_z(k)]), 'repeats the point before it', status)
            return
          end if
        end do
        k = polyline_self_intersection(profile_y, profile_z)
        if (k > 0) then
          call r%invalid('profile_y, profile_z', 'points '//format_integer(k)//' to '//format_integer(k + 1), &
                         'the profile intersects itself (this segment crosses a later one)', status)
          return
        end if
        described%profile_y = profile_y
        described%profile_z = profile_z
        described%profile_smoothing = profile_smoothing
        described%profile_degree = profile_degree
      end select
      sections%parts(i) = described
    end do
    sections%transition_midpoint = transition_midpoint
    sections%transition_end = transition_end

  contains

    !> A value section i does not use, given for it, is refused.
    subroutine unused(given, name)
      logical, intent(in) :: given(:)
      character(len=*), intent(in) :: name
      if (status%ok() .and. given(i)) call r%invalid(indexed_name(name, i), r%written(name), &
        'a '//trim(kind(i))//' section does not use '//name, status)
    end subroutine unused
  end subroutine read_cross_section


  !> `count_name` = n must equal the number `given` of `what` in `list_name`.
  subroutine check_list_length(r, count_name, n, list_name, given, what, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: count_name, list_name, what
    integer, intent(in) :: n, given
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. given == n) return
    if (given < n) then
      call r%invalid(count_name, format_integer(n), 'only '//format_integer(given)//' '//noun(what, given)// &
                     ' given in '//trim(list_name), status)
    else
      call r%invalid(count_name, format_integer(n), format_integer(given)//' '//noun(what, given)// &
                     ' given in '//trim(list_name)//'; '//count_name//' must equal their number', status)
    end if
  end subroutine check_list_length

  !> List `list_name` of transitions (`given` entries) needs exactly `want`:
  !> one per transition between the n parts.
  subroutine check_exactly(r, list_name, given, want, n, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: list_name
    integer, intent(in) :: given, want, n
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. given == want) return
    call r%invalid(list_name, format_integer(given)//' values', 'needs exactly '//format_integer(want)// &
                   ', one per transition between the '//format_integer(n)//' parts', status)
  end subroutine check_exactly


  !> 'points were' or, for one, 'point was' ('patches' -> 'patch').
  pure function noun(plural, k) result(text)
    character(len=*), intent(in) :: plural
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: n
    n = len(plural)
    if (k /= 1) then
      text = plural//' were'
    else if (n > 4 .and. plural(max(1, n - 3):) == 'ches') then
      text = plural(:n - 2)//' was'
    else
      text = plural(:n - 1)//' was'
    end if
  end function noun
end module io_slide_geometry_config
