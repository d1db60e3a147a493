!> Geometry input: &geometry, &centerline, &cross_section, &slide_elements,
!> &blended and &bspline build a tube, a slide from standard elements, a
!> blended or a B-spline surface. Every value is checked before anything is
!> built, a value the chosen kind does not use is refused, and the whole
!> surface is then checked (frame defined everywhere, no folding, no part of
!> a tube passing through another) before it is returned. A geometry that
!> cannot be built from the input is bad input (STATUS_INVALID_INPUT).
!> Every variable is declared in io_declarations_geometry (docs/inputs.md).
module io_geometry_config
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_text, only: format_integer
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT, STATUS_IO
  use geometry_surface, only: surface_t
  use geometry_curve, only: curve_t, constant_curve_t
  use geometry_curve_frame, only: horizon_parallel_tol
  use geometry_cross_section, only: cross_section_t, section_holder_t, blended_section_t, new_blended_section, &
    polyline_self_intersection
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: centerline_description_t, slide_elements_description_t, &
    section_part_description_t, build_centerline_curve, build_horizon, build_element_centerline, build_section_part
  use geometry_blended_surface, only: blended_surface_t, blend_patch_t, new_blended_surface
  use geometry_elementary, only: ellipsoid_t, paraboloid_t, elliptic_cylinder_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_from_table
  use io_input, only: input_text_t, group_reader_t, open_group, in_range, above, bounds_t, format_real, &
    format_vector, group_present, where_given
  use io_csv, only: read_csv_table
  use io_element_table, only: element_table_t, read_element_table, check_element
  use io_declarations_geometry, only: max_centerline_points, max_sections, max_elements, max_patches, &
    max_profile_points
  implicit none (type, external)
  private
  public :: read_geometry_config, geometry_groups, geometry_file_groups

  character(len=*), parameter :: geometry_groups(6) = [character(len=14) :: 'geometry', 'centerline', &
    'cross_section', 'slide_elements', 'blended', 'bspline']
  !> What a file named by &surface geometry_file may hold: a geometry-scenario input.
  character(len=*), parameter :: geometry_file_groups(8) = [character(len=14) :: 'run', 'grid', geometry_groups]

contains

  !> Builds the surface described by the geometry groups of `input`. If `kind`
  !> is given (by &surface kind = 'slide', ...) &geometry kind may only repeat it.
  subroutine read_geometry_config(input, surface, status, kind)
    type(input_text_t), intent(in) :: input
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: kind
    character(len=8) :: gkind
    integer :: check_samples, i
    class(curve_t), allocatable :: centerline
    class(cross_section_t), allocatable :: section
    class(curve_t), allocatable :: horizon
    type(tube_surface_t) :: tube
    type(status_t) :: built
    type(group_reader_t) :: r
    character(len=14) :: unused(6)

    gkind = 'slide'
    check_samples = 2000
    call open_group(input, 'geometry', r, status)
    call r%get('kind', gkind, status)
    call r%get('check_samples', check_samples, status)
    if (.not. status%ok()) return
    if (present(kind)) then
      if (r%has('kind') .and. gkind /= kind) then
        call r%invalid('kind', ''''//trim(gkind)//'''', '&surface kind = '''//kind//''' asks for a '//kind// &
                       '; give the same kind or leave &geometry kind out', status)
        return
      end if
      gkind = kind
    end if
    ! groups the kind does not read would be silently ignored
    select case (trim(gkind))
    case ('tube'); unused = [character(len=14) :: 'slide_elements', 'blended', 'bspline', '', '', '']
    case ('slide'); unused = [character(len=14) :: 'centerline', 'blended', 'bspline', '', '', '']
    case ('blended'); unused = [character(len=14) :: 'centerline', 'slide_elements', 'cross_section', 'bspline', '', '']
    case default; unused = [character(len=14) :: 'centerline', 'slide_elements', 'cross_section', 'blended', '', '']
    end select
    do i = 1, size(unused)
      if (len_trim(unused(i)) == 0) cycle
      if (group_present(input, unused(i))) then
        call set_status(status, STATUS_INVALID_INPUT, where_given(input, unused(i), '')//': &'// &
                        trim(unused(i))//' is not read: the surface is a '//trim(gkind)//' ('//kind_source()// &
                        '), which reads '//groups_read(gkind)//'; remove the group or change the kind')
        return
      end if
    end do

    select case (trim(gkind))
    case ('tube', 'slide')
      if (gkind == 'tube') then
        call read_centerline(input, centerline, horizon, status)
      else
        call read_slide_elements(input, centerline, status)
        if (status%ok()) allocate (horizon, source=constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp]))
      end if
      if (.not. status%ok()) return
      call read_cross_section(input, centerline, section, status)
      if (.not. status%ok()) return
      tube = new_tube_surface(centerline, horizon, section, built)
      if (built%ok()) call tube%check(check_samples, built)
      ! a fold or a pass through itself: the section too large for the bends
      if (.not. built%ok()) then
        if (gkind == 'tube') then
          call prefix_status(built, where_given(input, 'centerline', '')//': &centerline with &cross_section')
          call suffix(built, '; make &cross_section radius (or half_width, half_height) smaller or the '// &
                      'bends wider (&centerline radius, pitch, points)')
        else
          call prefix_status(built, where_given(input, 'slide_elements', '')//': &slide_elements with '// &
                             '&cross_section')
          call suffix(built, '; make &cross_section radius (or half_width, half_height) smaller or the '// &
                      'bends wider (&slide_elements radius, turns, drop)')
        end if
        status = built
        if (status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
        return
      end if
      if (.not. status%ok()) return
      allocate (surface, source=tube)
    case ('blended')
      call read_blended(input, surface, status)
    case ('bspline')
      call read_bspline(input, surface, status)
    end select

  contains

    !> Where the kind was chosen, for the message above.
    function kind_source() result(text)
      character(len=:), allocatable :: text
      if (present(kind)) then
        text = '&surface kind = '''//kind//''''
      else if (r%has('kind')) then
        text = '&geometry kind, '//r%where('kind')
      else
        text = 'the default of &geometry kind'
      end if
    end function kind_source
  end subroutine read_geometry_config

  !> The geometry groups a kind of surface reads, for messages.
  pure function groups_read(kind) result(text)
    character(len=*), intent(in) :: kind
    character(len=:), allocatable :: text
    select case (trim(kind))
    case ('tube'); text = '&geometry, &centerline and &cross_section'
    case ('slide'); text = '&geometry, &slide_elements and &cross_section'
    case ('blended'); text = '&geometry and &blended'
    case default; text = '&geometry and &bspline'
    end select
  end function groups_read

  !> &centerline: kind = 'line' | 'helix' | 'points', and the horizon field
  !> (a constant vector, or for points one horizon vector per point, fitted).
  !> Points come from `points` or from the CSV file `points_file`.
  subroutine read_centerline(input, curve, horizon_out, status)
    type(input_text_t), intent(in) :: input
    class(curve_t), allocatable, intent(out) :: curve
    class(curve_t), allocatable, intent(out) :: horizon_out
    type(status_t), intent(inout) :: status
    character(len=8) :: kind
    character(len=4096) :: points_file
    real(wp) :: start(3), end(3), center(3), radius, rise_per_turn, turns, phase_deg, horizon(3)
    real(wp) :: smoothing, start_tangent(3), end_tangent(3)
    real(wp), allocatable :: points(:, :), horizon_points(:, :), table(:, :)
    type(centerline_description_t) :: described
    integer :: n_points, n_given, n_horizon, degree, i
    logical :: have_horizon_points
    character(len=*), parameter :: g = 'centerline'
    real(wp) :: t(3), d
    type(status_t) :: built
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
    allocate (horizon_out, source=constant_curve_t(value=horizon))
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
      described%kind = 'line'
      described%start = start
      described%end = end
      call build_centerline_curve(described, curve, status)
    case ('helix')
      call r%get('center', center, status)
      call r%get('radius', radius, status)
      call r%get('rise_per_turn', rise_per_turn, status)
      call r%get('turns', turns, status)
      call r%get('phase_deg', phase_deg, status)
      if (.not. status%ok()) return
      described%kind = 'helix'
      described%center = center
      described%radius = radius
      described%rise_per_turn = rise_per_turn
      described%turns = turns
      described%phase = phase_deg*pi/180
      call build_centerline_curve(described, curve, status)
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
      described%kind = 'points'
      described%points = points(:, 1:n_points)
      described%smoothing = smoothing
      described%degree = degree
      described%start_tangent = start_tangent
      described%end_tangent = end_tangent
      described%horizon = horizon
      call build_centerline_curve(described, curve, built)
      call take_build_failure(input, g, built, status)
      if (.not. status%ok()) return
      if (have_horizon_points) then
        described%horizon_points = horizon_points(:, 1:n_points)
        deallocate (horizon_out)
        call build_horizon(described, horizon_out, built)
        call take_build_failure(input, g//': horizon_points', built, status)
        if (.not. status%ok()) return
      end if
    end select
  end subroutine read_centerline

  !> &slide_elements: the slide as a chain of standard elements. A value an
  !> element does not use must be left out or equal its default (0; 'left'
  !> for direction), so that tables with a column per element stay possible.
  subroutine read_slide_elements(input, centerline, status)
    type(input_text_t), intent(in) :: input
    class(curve_t), allocatable, intent(out) :: centerline
    type(status_t), intent(inout) :: status
    integer :: n, i, degree
    character(len=8), allocatable :: kind(:)
    character(len=5), allocatable :: direction(:)
    real(wp), allocatable :: length(:), slope_deg(:), radius(:), angle_deg(:), turns(:), drop(:)
    logical, allocatable :: given_kind(:)
    real(wp) :: start(3), heading_deg, transition_length, fit_spacing, smoothing
    character(len=8) :: centerline_kind
    type(slide_element_t), allocatable :: e(:)
    type(slide_elements_description_t) :: described
    type(status_t) :: built
    type(group_reader_t) :: r
    character(len=:), allocatable :: lim
    character(len=*), parameter :: g = 'slide_elements'
    character(len=4096) :: elements_file
    type(element_table_t) :: table
    character(len=:), allocatable :: variable, value, allowed

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
      call r%refuse_given([character(len=9) :: 'kind', 'length', 'slope_deg', 'radius', 'angle_deg', 'direction', &
                           'turns', 'drop'], 'the elements come from elements_file', status)
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
      allocate (given_kind(n), e(n))
      given_kind = .true.
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
                given_kind(n), e(n))
      kind = ''; direction = 'left'
      length = 0; slope_deg = 0; radius = 0; angle_deg = 0; turns = 0; drop = 0
      call r%get_parts('kind', kind, lim, status, given=given_kind)
      call r%get_parts('direction', direction, lim, status)
      call r%get_parts('length', length, lim, status)
      call r%get_parts('slope_deg', slope_deg, lim, status)
      call r%get_parts('radius', radius, lim, status)
      call r%get_parts('angle_deg', angle_deg, lim, status)
      call r%get_parts('turns', turns, lim, status)
      call r%get_parts('drop', drop, lim, status)
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
                         drop(i), variable, value, allowed)
      if (len(variable) > 0) call r%invalid(part(variable), value, allowed, status)
      if (.not. status%ok()) return
      e(i) = slide_element_t(kind=kind(i), length=length(i), slope_deg=slope_deg(i), radius=radius(i), &
                             angle_deg=angle_deg(i), direction=direction(i), turns=turns(i), drop=drop(i))
    end do
    described%elements = e
    described%start = start
    described%heading_deg = heading_deg
    described%transition_length = transition_length
    described%exact = centerline_kind == 'exact'
    described%fit_spacing = fit_spacing
    described%smoothing = smoothing
    described%degree = degree
    call build_element_centerline(described, centerline, built)
    call take_build_failure(input, g, built, status)

  contains

    pure function part(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      text = name//'('//format_integer(i)//')'
    end function part
  end subroutine read_slide_elements

  !> &cross_section: n_sections sections (circle, ellipse, flume, profile)
  !> blended along the centerline; transitions given in arc length (m).
  subroutine read_cross_section(input, centerline, section, status)
    type(input_text_t), intent(in) :: input
    class(curve_t), intent(in) :: centerline
    class(cross_section_t), allocatable, intent(out) :: section
    type(status_t), intent(inout) :: status
    integer :: n, i, k, n_profile, profile_degree
    character(len=8), allocatable :: kind(:)
    real(wp), allocatable :: radius(:), half_width(:), half_height(:), wall(:), joint_width_deg(:), &
      transition_midpoint(:), transition_end(:), u_mid(:), u_end(:), profile_y(:), profile_z(:)
    logical, allocatable :: given_kind(:), given_radius(:), given_half_width(:), given_half_height(:), &
      given_wall(:), given_joint(:), given_midpoint(:), given_end(:)
    real(wp) :: profile_smoothing, total
    type(section_holder_t), allocatable :: parts(:)
    type(blended_section_t) :: blend
    type(section_part_description_t) :: described
    type(status_t) :: built
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
              given_radius(n), given_half_width(n), given_half_height(n), given_wall(n), given_joint(n), parts(n), &
              transition_midpoint(n - 1), transition_end(n - 1), u_mid(n - 1), u_end(n - 1), given_midpoint(n - 1), &
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
      call build_section_part(described, parts(i)%section, built)
      call take_build_failure(input, g, built, status)
      if (.not. status%ok()) return
    end do
    if (.not. status%ok()) return
    if (n == 1) then
      call move_alloc(parts(1)%section, section)
      return
    end if
    total = centerline%total_length()
    do i = 1, n - 1
      if (.not. transition_midpoint(i) <= total) &
        call r%invalid('transition_midpoint('//format_integer(i)//')', format_real(transition_midpoint(i)), &
                       'must lie in [0, '//format_real(total)//'] (m of arc length along the centerline)', status)
      if (status%ok() .and. .not. (transition_end(i) > transition_midpoint(i) .and. transition_end(i) <= total)) &
        call r%invalid('transition_end('//format_integer(i)//')', format_real(transition_end(i)), &
                       'must lie after transition_midpoint('//format_integer(i)//') and within the centerline ('// &
                       format_real(total)//' m)', status)
      if (status%ok() .and. i > 1) then
        if (.not. transition_midpoint(i) - transition_midpoint(i - 1) >= &
            (transition_end(i) - transition_midpoint(i)) + (transition_end(i - 1) - transition_midpoint(i - 1))) &
          call r%invalid('transition_midpoint('//format_integer(i)//')', format_real(transition_midpoint(i)), &
                         'transitions must not overlap (midpoints at least the sum of the two half-widths apart)', &
                         status)
      end if
      if (.not. status%ok()) return
      call centerline%parameter_at_length(transition_midpoint(i), u_mid(i), built)
      if (built%ok()) call centerline%parameter_at_length(transition_end(i), u_end(i), built)
      call take_build_failure(input, g, built, status)
      if (.not. status%ok()) return
    end do
    blend = new_blended_section(parts, u_mid, u_end, built)
    call take_build_failure(input, g, built, status)
    if (.not. status%ok()) return
    allocate (section, source=blend)

  contains

    !> A value section i does not use, given for it, is refused.
    subroutine unused(given, name)
      logical, intent(in) :: given(:)
      character(len=*), intent(in) :: name
      if (status%ok() .and. given(i)) call r%invalid(name//'('//format_integer(i)//')', r%written(name), &
        'a '//trim(kind(i))//' section does not use '//name, status)
    end subroutine unused
  end subroutine read_cross_section

  !> &blended: n_patches elementary surfaces, each placed and cut to a range
  !> of its own parameters, blended along u (thesis 3.73-3.79).
  subroutine read_blended(input, surface, status)
    type(input_text_t), intent(in) :: input
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    integer :: n, i, n_columns
    character(len=24), allocatable :: kind(:)
    real(wp), allocatable :: a(:), b(:), c(:), origin(:, :), angles_deg(:, :), u_min(:), u_max(:), v_min(:), &
      v_max(:), transition(:), midpoint(:), u_99(:)
    logical, allocatable :: swap_uv(:), given_kind(:), given_c(:), given_midpoint(:), given_u_99(:)
    type(blend_patch_t), allocatable :: patches(:)
    type(blended_surface_t) :: blend
    class(surface_t), allocatable :: base
    type(status_t) :: built
    type(group_reader_t) :: r
    character(len=:), allocatable :: lim, tlim
    character(len=*), parameter :: g = 'blended'

    n = 0
    call open_group(input, g, r, status)
    call r%get('n_patches', n, status)
    if (status%ok() .and. .not. r%has('n_patches')) &
      call r%invalid('n_patches', '0', 'give the number of patches (2 to '//format_integer(max_patches)//')', status)
    if (.not. status%ok()) return
    lim = 'n_patches = '//format_integer(n)
    tlim = 'n_patches - 1 = '//format_integer(n - 1)//' transitions'
    allocate (kind(n), a(n), b(n), c(n), origin(3, n), angles_deg(3, n), u_min(n), u_max(n), v_min(n), v_max(n), &
              swap_uv(n), given_kind(n), given_c(n), patches(n), transition(n - 1), midpoint(n - 1), u_99(n - 1), &
              given_midpoint(n - 1), given_u_99(n - 1))
    kind = ''; a = 1; b = 1; c = 1; origin = 0; angles_deg = 0
    u_min = 0; u_max = 1; v_min = 0; v_max = 1; swap_uv = .false.
    transition = 0; midpoint = 0; u_99 = 0
    call r%get_parts('kind', kind, lim, status, given=given_kind)
    call r%get_parts('a', a, lim, status)
    call r%get_parts('b', b, lim, status)
    call r%get_parts('c', c, lim, status, given=given_c)
    call r%get_columns('origin', origin, lim, n_columns, status)
    call r%get_columns('angles_deg', angles_deg, lim, n_columns, status)
    call r%get_parts('u_min', u_min, lim, status)
    call r%get_parts('u_max', u_max, lim, status)
    call r%get_parts('v_min', v_min, lim, status)
    call r%get_parts('v_max', v_max, lim, status)
    call r%get_parts('swap_uv', swap_uv, lim, status)
    call r%get_parts('transition', transition, tlim, status)
    call r%get_parts('midpoint', midpoint, tlim, status, given=given_midpoint)
    call r%get_parts('u_99', u_99, tlim, status, given=given_u_99)
    if (.not. status%ok()) return
    call check_list_length(r, 'n_patches', n, 'kind', count(given_kind), 'patches', status)
    if (any(given_midpoint) .or. any(given_u_99)) then
      call check_exactly(r, 'midpoint', count(given_midpoint), n - 1, n, status)
      call check_exactly(r, 'u_99', count(given_u_99), n - 1, n, status)
    end if
    ! where the blend of a transition reaches 99 % (new_blended_surface)
    do i = 1, n - 1
      if (.not. status%ok()) return
      if (any(given_midpoint)) then
        if (.not. u_99(i) > midpoint(i)) call r%invalid('u_99('//format_integer(i)//')', format_real(u_99(i)), &
          'must lie after midpoint('//format_integer(i)//') = '//format_real(midpoint(i)), status)
      else if (.not. transition(i) > 0) then
        call r%invalid('transition('//format_integer(i)//')', format_real(transition(i)), 'a transition of '// &
                       'length 0 needs an explicit midpoint and u_99', status)
      end if
    end do
    do i = 1, n
      if (.not. status%ok()) return
      if (given_c(i) .and. kind(i) /= 'ellipsoid') &
        call r%invalid('c('//format_integer(i)//')', format_real(c(i)), 'a '//trim(kind(i))// &
                       ' has no third semi-axis c', status)
      if (status%ok() .and. .not. u_max(i) > u_min(i)) &
        call r%invalid('u_max('//format_integer(i)//')', format_real(u_max(i)), 'must exceed u_min('// &
                       format_integer(i)//') = '//format_real(u_min(i)), status)
      if (status%ok() .and. v_max(i) == v_min(i)) &
        call r%invalid('v_max('//format_integer(i)//')', format_real(v_max(i)), 'must differ from v_min', status)
      if (.not. status%ok()) return
      select case (trim(kind(i)))
      case ('ellipsoid'); base = ellipsoid_t(a(i), b(i), c(i), built)
      case ('elliptic_paraboloid'); base = paraboloid_t(a(i), b(i), 1.0_wp, built)
      case ('hyperbolic_paraboloid'); base = paraboloid_t(a(i), b(i), -1.0_wp, built)
      case default; base = elliptic_cylinder_t(a(i), b(i), built)
      end select
      if (built%ok()) allocate (patches(i)%surface, source=placed_surface_t(base, origin(:, i), built, &
                                                                            angles=angles_deg(:, i)*pi/180))
      call take_build_failure(input, g, built, status)
      if (.not. status%ok()) return
      patches(i)%u_min = u_min(i); patches(i)%u_max = u_max(i)
      patches(i)%v_min = v_min(i); patches(i)%v_max = v_max(i)
      patches(i)%swap_uv = swap_uv(i)
    end do
    if (any(given_midpoint)) then
      blend = new_blended_surface(patches, transition, built, midpoint=midpoint, u_99=u_99)
    else
      blend = new_blended_surface(patches, transition, built)
    end if
    call take_build_failure(input, g, built, status)
    if (.not. status%ok()) return
    allocate (surface, source=blend)
  end subroutine read_blended

  !> &bspline: a free-form B-spline surface fitted to points from a CSV file.
  subroutine read_bspline(input, surface, status)
    type(input_text_t), intent(in) :: input
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    character(len=4096) :: file
    character(len=12) :: layout
    real(wp) :: smoothing
    real(wp), allocatable :: table(:, :)
    integer :: degree, columns
    logical :: periodic_u, periodic_v
    type(bspline_surface_t) :: b
    type(group_reader_t) :: r
    type(bounds_t) :: coordinate
    character(len=*), parameter :: g = 'bspline'

    file = ''; layout = 'scattered'; smoothing = 0; degree = 3
    periodic_u = .false.; periodic_v = .false.
    call open_group(input, g, r, status)
    call r%get('file', file, status)
    call r%get('layout', layout, status)
    call r%get('smoothing', smoothing, status)
    call r%get('degree', degree, status)
    call r%get('periodic_u', periodic_u, status)
    call r%get('periodic_v', periodic_v, status)
    if (status%ok() .and. layout /= 'parametric' .and. (periodic_u .or. periodic_v)) &
      call r%invalid('periodic_u, periodic_v', 'true', 'only a parametric surface can be periodic', status)
    if (status%ok() .and. len_trim(file) == 0) &
      call r%invalid('file', '''''', 'must name a CSV file with the points', status)
    if (.not. status%ok()) return
    coordinate = in_range(-1e6_wp, 1e6_wp, 'm')
    columns = merge(5, 3, layout == 'parametric')
    ! u and v of a parametric grid are plain parameters; x, y, z in m
    call read_csv_table(input%resolve_path(file), columns, columns, 10000000, &
                        [coordinate, coordinate, coordinate, coordinate, coordinate], table, status)
    if (status%ok()) call bspline_from_table(trim(layout), table, smoothing, degree, [periodic_u, periodic_v], b, status)
    if (.not. status%ok()) then
      if (status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
      call prefix_status(status, r%where('file')//': &'//g//': file = '''//trim(file)//'''')
      return
    end if
    allocate (surface, source=b)
  end subroutine read_bspline

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

  !> A build step of group `place` failed (`built` not ok): its status,
  !> prefixed with the file and '&' // place, becomes `status`. A geometry
  !> that cannot be built from the input is bad input.
  subroutine take_build_failure(input, place, built, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: place
    type(status_t), intent(in) :: built
    type(status_t), intent(inout) :: status
    if (built%ok()) return
    status = built
    if (status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
    call prefix_status(status, where_given(input, place, '')//': &'//place)
  end subroutine take_build_failure

  pure subroutine suffix(status, text)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in) :: text
    if (allocated(status%message)) status%message = status%message//text
  end subroutine suffix

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
end module io_geometry_config
