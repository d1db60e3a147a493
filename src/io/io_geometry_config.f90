!> Geometry input: &geometry, &centerline, &cross_section, &slide_elements and
!> &blended build a tube, a slide from standard elements, or a blended surface.
!> Every value is checked before anything is built; the whole surface is then
!> checked (frame defined everywhere, no folding) before it is returned.
!> See docs/geometry.md for every variable with unit, default and range.
module io_geometry_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t
  use geometry_curve, only: curve_t, curve_point_t, line_curve_t, helix_curve_t, constant_curve_t, &
                            spline_centerline_t, new_spline_centerline
  use geometry_curve_frame, only: horizon_parallel_tol
  use geometry_cross_section, only: cross_section_t, section_holder_t, circle_section_t, &
    ellipse_section_t, flume_section_t, blended_section_t, new_blended_section, profile_section_t, &
    new_profile_section, polyline_self_intersection
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use geometry_blended_surface, only: blended_surface_t, blend_patch_t, new_blended_surface
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_from_csv
  use io_input, only: input_text_t, namelist_read_error, check_positive, check_nonnegative, &
    check_finite, check_finite_vector, check_choice, check_range, invalid, format_real, &
    format_vector, lower
  implicit none (type, external)
  private
  public :: read_geometry_config, geometry_groups, geometry_kinds

  character(len=*), parameter :: geometry_groups(6) = [character(len=14) :: 'geometry', 'centerline', &
    'cross_section', 'slide_elements', 'blended', 'bspline']
  character(len=*), parameter :: geometry_kinds(4) = [character(len=8) :: 'tube', 'slide', 'blended', 'bspline']

  integer, parameter :: max_points = 2000, max_sections = 8, max_elements = 40, max_patches = 8
  integer, parameter :: max_profile = 400
  !> Default of the list variables before reading: an entry still equal to it
  !> was not given, so counts (n_points, n_elements, ...) can be checked against
  !> the lists; replaced by the documented default afterwards.
  real(wp), parameter :: unset = -huge(1.0_wp)

contains

  !> Builds the surface described by the geometry groups of `input`. If `kind`
  !> is given it replaces &geometry kind (used by &surface kind = 'slide', ...).
  subroutine read_geometry_config(input, surface, status, kind)
    type(input_text_t), intent(in) :: input
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: kind
    character(len=16) :: gkind
    integer :: check_samples
    class(curve_t), allocatable :: centerline
    class(cross_section_t), allocatable :: section
    class(curve_t), allocatable :: horizon
    type(tube_surface_t) :: tube
    type(status_t) :: built

    call read_geometry_group(input, gkind, check_samples, status)
    if (present(kind)) gkind = kind
    if (.not. status%ok()) return
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
      call take_build_failure(input, trim(merge('centerline    ', 'slide_elements', gkind == 'tube')) // &
                              ' with &cross_section', built, status)
      if (.not. status%ok()) return
      allocate (surface, source=tube)
    case ('blended')
      call read_blended(input, surface, status)
    case ('bspline')
      call read_bspline(input, surface, status)
    end select
  end subroutine read_geometry_config

  subroutine read_geometry_group(input, kind, check_samples, status)
    type(input_text_t), intent(in) :: input
    character(len=16), intent(out) :: kind
    integer, intent(out) :: check_samples
    type(status_t), intent(inout) :: status
    character(len=256) :: msg
    integer :: ios
    namelist /geometry/ kind, check_samples
    kind = 'slide'
    check_samples = 2000
    read (input%lines, nml=geometry, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, 'geometry', msg, [character(len=13) :: 'kind', 'check_samples'], status)
      return
    end if
    kind = lower(adjustl(kind))
    call check_choice(input, 'geometry', 'kind', kind, geometry_kinds, status)
    call check_integer_in(input, 'geometry', 'check_samples', check_samples, 10, 1000000, status)
  end subroutine read_geometry_group

  !> &centerline: kind = 'line' | 'helix' | 'points', and the horizon field
  !> (a constant vector, or for points one horizon vector per point, fitted).
  subroutine read_centerline(input, curve, horizon_out, status)
    type(input_text_t), intent(in) :: input
    class(curve_t), allocatable, intent(out) :: curve
    class(curve_t), allocatable, intent(out) :: horizon_out
    type(status_t), intent(inout) :: status
    character(len=8) :: kind
    real(wp) :: start(3), end(3), center(3), radius, rise_per_turn, turns, phase_deg, horizon(3)
    real(wp) :: points(3, max_points), smoothing, start_tangent(3), end_tangent(3)
    real(wp) :: horizon_points(3, max_points), chord(max_points)
    type(spline_centerline_t) :: horizon_fit
    integer :: n_points, degree, ios, i, n_given
    logical :: have_horizon_points
    character(len=256) :: msg
    character(len=*), parameter :: g = 'centerline'
    real(wp) :: t(3), d
    type(spline_centerline_t) :: fitted
    type(status_t) :: built
    namelist /centerline/ kind, start, end, center, radius, rise_per_turn, turns, phase_deg, horizon, &
      n_points, points, smoothing, degree, start_tangent, end_tangent, horizon_points
    kind = 'line'
    start = [0, 0, 0]; end = [10, 0, 0]
    center = 0; radius = 5; rise_per_turn = 0; turns = 0.25_wp; phase_deg = -90
    horizon = [0, 0, 1]
    n_points = 0; points = unset; smoothing = 0; degree = 5
    start_tangent = 0; end_tangent = 0; horizon_points = unset
    read (input%lines, nml=centerline, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=14) :: 'kind', 'start', 'end', 'center', &
        'radius', 'rise_per_turn', 'turns', 'phase_deg', 'horizon', 'n_points', 'points', 'smoothing', &
        'degree', 'start_tangent', 'end_tangent', 'horizon_points'], status)
      return
    end if
    kind = lower(adjustl(kind))
    call check_choice(input, g, 'kind', kind, [character(len=6) :: 'line', 'helix', 'points'], status)
    call check_finite_vector(input, g, 'horizon', horizon, status)
    if (status%ok() .and. .not. norm2(horizon) > 0) &
      call invalid(input, g, 'horizon', format_vector(horizon), 'must be a non-zero vector', status)
    if (.not. status%ok()) return
    allocate (horizon_out, source=constant_curve_t(value=horizon))
    select case (trim(kind))
    case ('line')
      call check_finite_vector(input, g, 'start', start, status)
      call check_finite_vector(input, g, 'end', end, status)
      if (status%ok() .and. .not. norm2(end - start) > 0) &
        call invalid(input, g, 'end', format_vector(end), 'must differ from start', status)
      if (.not. status%ok()) return
      t = (end - start)/norm2(end - start)
      if (norm2(cross3(horizon/norm2(horizon), t)) < horizon_parallel_tol) then
        call invalid(input, g, 'horizon', format_vector(horizon), &
                     'must not be parallel to the centerline tangent ' // format_vector(t), status)
        return
      end if
      curve = line_curve_t(origin=start, direction=(end - start)/norm2(end - start), u_min=0.0_wp, &
                                u_max=norm2(end - start))
    case ('helix')
      call check_finite_vector(input, g, 'center', center, status)
      call check_positive(input, g, 'radius', radius, 'm', status)
      call check_finite(input, g, 'rise_per_turn', rise_per_turn, status)
      call check_positive(input, g, 'turns', turns, '1', status)
      call check_finite(input, g, 'phase_deg', phase_deg, status)
      if (.not. status%ok()) return
      curve = helix_curve_t(center=center, radius=radius, pitch=rise_per_turn/two_pi, &
                                 phase=phase_deg*pi/180, u_min=0.0_wp, u_max=two_pi*turns)
    case ('points')
      if (n_points < 4) then
        call invalid(input, g, 'n_points', format_integer(n_points), 'too few centerline points: ' // &
                     'need at least 4', status)
        return
      end if
      if (n_points > max_points) then
        call invalid(input, g, 'n_points', format_integer(n_points), 'more than the limit of ' // &
                     format_integer(max_points) // ' centerline points', status)
        return
      end if
      n_given = count_given(reshape(points, [size(points)]))
      if (mod(n_given, 3) /= 0) then
        call invalid(input, g, 'points', format_integer(n_given) // ' numbers', 'give 3 coordinates (x, y, z) per point', &
                     status)
        return
      end if
      call check_list_length(input, g, 'n_points', n_points, 'points', n_given/3, 'points', status)
      n_given = count_given(reshape(horizon_points, [size(horizon_points)]))
      have_horizon_points = n_given > 0
      if (status%ok() .and. have_horizon_points .and. n_given /= 3*n_points) &
        call invalid(input, g, 'horizon_points', format_integer(n_given) // ' numbers', 'give one horizon vector ' // &
                     '(3 numbers) per centerline point: ' // format_integer(3*n_points) // ' numbers for n_points = ' // &
                     format_integer(n_points), status)
      if (.not. status%ok()) return
      where (horizon_points == unset) horizon_points = 0
      call check_finite_vector(input, g, 'points', reshape(points(:, 1:n_points), [3*n_points]), status)
      if (.not. status%ok()) return
      d = maxval(norm2(points(:, 2:n_points) - points(:, 1:n_points - 1), dim=1))
      do i = 2, n_points
        if (norm2(points(:, i) - points(:, i - 1)) <= 1e-9_wp*max(d, 1.0_wp)) then
          call invalid(input, g, 'points(:, ' // format_integer(i) // ')', format_vector(points(:, i)), &
                       'duplicate consecutive centerline point (equal to points(:, ' // format_integer(i - 1) // '))', status)
          return
        end if
        t = (points(:, i) - points(:, i - 1))/norm2(points(:, i) - points(:, i - 1))
        if (have_horizon_points) then
          if (.not. (norm2(horizon_points(:, i)) > 0 .and. norm2(horizon_points(:, i - 1)) > 0)) then
            call invalid(input, g, 'horizon_points(:, ' // format_integer(merge(i, i - 1, norm2(horizon_points(:, i)) == 0)) &
                         // ')', '0', 'every horizon point must be a non-zero vector', status)
            return
          end if
          if (norm2(cross3(horizon_points(:, i)/norm2(horizon_points(:, i)), t)) < horizon_parallel_tol .or. &
              norm2(cross3(horizon_points(:, i - 1)/norm2(horizon_points(:, i - 1)), t)) < horizon_parallel_tol) then
            call invalid(input, g, 'horizon_points(:, ' // format_integer(i) // ')', format_vector(horizon_points(:, i)), &
                         'is parallel to the centerline between points ' // format_integer(i - 1) // &
                         ' and ' // format_integer(i), status)
            return
          end if
        else if (norm2(cross3(horizon/norm2(horizon), t)) < horizon_parallel_tol) then
          call invalid(input, g, 'horizon', format_vector(horizon), 'is parallel to the centerline ' // &
                       'between points ' // format_integer(i - 1) // ' and ' // format_integer(i), status)
          return
        end if
      end do
      call check_nonnegative(input, g, 'smoothing', smoothing, 'm^2', status)
      if (status%ok() .and. (degree < 3 .or. degree > 5)) &
        call invalid(input, g, 'degree', format_integer(degree), 'must be 3, 4 or 5', status)
      call check_finite_vector(input, g, 'start_tangent', start_tangent, status)
      call check_finite_vector(input, g, 'end_tangent', end_tangent, status)
      if (status%ok() .and. mod(degree, 2) == 0 .and. (any(start_tangent /= 0) .or. any(end_tangent /= 0))) &
        call invalid(input, g, 'degree', format_integer(degree), &
                     'must be odd (3 or 5) when end tangents are given', status)
      if (.not. status%ok()) return
      if (any(start_tangent /= 0) .and. any(end_tangent /= 0)) then
        fitted = new_spline_centerline(points(:, 1:n_points), smoothing, degree, built, &
                                       start_tangent=start_tangent, end_tangent=end_tangent)
      else if (any(start_tangent /= 0)) then
        fitted = new_spline_centerline(points(:, 1:n_points), smoothing, degree, built, start_tangent=start_tangent)
      else if (any(end_tangent /= 0)) then
        fitted = new_spline_centerline(points(:, 1:n_points), smoothing, degree, built, end_tangent=end_tangent)
      else
        fitted = new_spline_centerline(points(:, 1:n_points), smoothing, degree, built)
      end if
      call take_build_failure(input, g, built, status)
      if (.not. status%ok()) return
      allocate (curve, source=fitted)
      if (have_horizon_points) then
        ! the horizon field over the centerline's parameter (chord length of the points)
        chord(1) = 0
        do i = 2, n_points
          chord(i) = chord(i - 1) + norm2(points(:, i) - points(:, i - 1))
        end do
        horizon_fit = new_spline_centerline(horizon_points(:, 1:n_points), 0.0_wp, min(degree, 5), built, &
                                            parameters=chord(1:n_points))
        call take_build_failure(input, g // ': horizon_points', built, status)
        if (.not. status%ok()) return
        deallocate (horizon_out)
        allocate (horizon_out, source=horizon_fit)
      end if
    end select
  end subroutine read_centerline

  !> &slide_elements: the slide as a chain of standard elements.
  subroutine read_slide_elements(input, centerline, status)
    type(input_text_t), intent(in) :: input
    class(curve_t), allocatable, intent(out) :: centerline
    type(status_t), intent(inout) :: status
    integer :: n_elements, ios, i
    character(len=8) :: kind(max_elements)
    character(len=5) :: direction(max_elements)
    real(wp) :: length(max_elements), slope_deg(max_elements), radius(max_elements), &
      angle_deg(max_elements), turns(max_elements), drop(max_elements)
    real(wp) :: start(3), heading_deg, transition_length, fit_spacing, smoothing
    character(len=8) :: centerline_kind
    integer :: degree
    type(slide_element_t) :: e(max_elements)
    type(element_chain_curve_t) :: chain
    type(status_t) :: built
    character(len=256) :: msg
    character(len=*), parameter :: g = 'slide_elements'
    character(len=:), allocatable :: lim
    namelist /slide_elements/ n_elements, kind, length, slope_deg, radius, angle_deg, direction, turns, &
      drop, start, heading_deg, transition_length, centerline_kind, fit_spacing, smoothing, degree
    n_elements = 0
    kind = ''; direction = ''
    length = unset; slope_deg = unset; radius = unset; angle_deg = unset; turns = unset; drop = unset
    start = [0, 0, 0]; heading_deg = 0; transition_length = 2
    centerline_kind = 'fitted'; fit_spacing = 0.125_wp; smoothing = 0; degree = 5
    read (input%lines, nml=slide_elements, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=17) :: 'n_elements', 'kind', 'length', &
        'slope_deg', 'radius', 'angle_deg', 'direction', 'turns', 'drop', 'start', 'heading_deg', &
        'transition_length', 'centerline_kind', 'fit_spacing', 'smoothing', 'degree'], status)
      return
    end if
    call check_part_count(input, g, 'n_elements', n_elements, 1, max_elements, kind, 'elements', lim, status)
    if (.not. status%ok()) return
    call check_at_most(input, g, 'direction', count_given_text(direction), n_elements, lim, status)
    call check_at_most(input, g, 'length', count_given(length), n_elements, lim, status)
    call check_at_most(input, g, 'slope_deg', count_given(slope_deg), n_elements, lim, status)
    call check_at_most(input, g, 'radius', count_given(radius), n_elements, lim, status)
    call check_at_most(input, g, 'angle_deg', count_given(angle_deg), n_elements, lim, status)
    call check_at_most(input, g, 'turns', count_given(turns), n_elements, lim, status)
    call check_at_most(input, g, 'drop', count_given(drop), n_elements, lim, status)
    if (.not. status%ok()) return
    where (direction == '') direction = 'left'
    where (length == unset) length = 0
    where (slope_deg == unset) slope_deg = 0
    where (radius == unset) radius = 0
    where (angle_deg == unset) angle_deg = 0
    where (turns == unset) turns = 0
    where (drop == unset) drop = 0
    call check_finite_vector(input, g, 'start', start, status)
    call check_finite(input, g, 'heading_deg', heading_deg, status)
    call check_nonnegative(input, g, 'transition_length', transition_length, 'm', status)
    centerline_kind = lower(adjustl(centerline_kind))
    call check_choice(input, g, 'centerline_kind', centerline_kind, [character(len=6) :: 'fitted', 'exact'], status)
    call check_range(input, g, 'fit_spacing', fit_spacing, 0.05_wp, 5.0_wp, 'm', status)
    call check_nonnegative(input, g, 'smoothing', smoothing, 'm^2', status)
    if (status%ok() .and. degree /= 3 .and. degree /= 5) &
      call invalid(input, g, 'degree', format_integer(degree), 'must be 3 or 5', status)
    do i = 1, n_elements
      kind(i) = lower(adjustl(kind(i)))
      direction(i) = lower(adjustl(direction(i)))
      call check_choice(input, g, 'kind(' // format_integer(i) // ')', kind(i), [character(len=8) :: 'straight', &
                        'curve', 'helix', 'runout'], status)
      if (.not. status%ok()) return
      select case (trim(kind(i)))
      case ('straight', 'runout')
        call check_positive(input, g, 'length(' // format_integer(i) // ')', length(i), 'm', status)
        call check_range(input, g, 'slope_deg(' // format_integer(i) // ')', slope_deg(i), -45.0_wp, 45.0_wp, 'deg', status)
      case ('curve')
        call check_positive(input, g, 'radius(' // format_integer(i) // ')', radius(i), 'm', status)
        call check_range(input, g, 'angle_deg(' // format_integer(i) // ')', angle_deg(i), 1e-6_wp, 720.0_wp, 'deg', status)
        call check_range(input, g, 'slope_deg(' // format_integer(i) // ')', slope_deg(i), -45.0_wp, 45.0_wp, 'deg', status)
        call check_choice(input, g, 'direction(' // format_integer(i) // ')', direction(i), &
                          [character(len=5) :: 'left', 'right'], status)
      case ('helix')
        call check_positive(input, g, 'radius(' // format_integer(i) // ')', radius(i), 'm', status)
        call check_positive(input, g, 'turns(' // format_integer(i) // ')', turns(i), '1', status)
        call check_finite(input, g, 'drop(' // format_integer(i) // ')', drop(i), status)
        call check_choice(input, g, 'direction(' // format_integer(i) // ')', direction(i), &
                          [character(len=5) :: 'left', 'right'], status)
        if (status%ok() .and. abs(drop(i)) > two_pi*radius(i)*turns(i)) &
          call invalid(input, g, 'drop(' // format_integer(i) // ')', format_real(drop(i)), &
                       'the helix would be steeper than 45 deg (|drop| <= 2 pi radius turns)', status)
      end select
      if (.not. status%ok()) return
      e(i) = slide_element_t(kind=kind(i), length=length(i), slope_deg=slope_deg(i), radius=radius(i), &
                             angle_deg=angle_deg(i), direction=direction(i), turns=turns(i), drop=drop(i))
    end do
    if (.not. status%ok()) return
    chain = new_element_chain(e(1:n_elements), start, heading_deg, transition_length, built)
    call take_build_failure(input, g, built, status)
    if (.not. status%ok()) return
    if (centerline_kind == 'exact') then
      allocate (centerline, source=chain)
    else
      call fit_chain(chain, fit_spacing, smoothing, degree, centerline, built)
      call take_build_failure(input, g, built, status)
    end if
  end subroutine read_slide_elements

  !> The thesis's way: points of the element chain every ~spacing m of
  !> horizontal length, fitted by a spline (parcur/concur) with the chain's
  !> end tangents prescribed.
  subroutine fit_chain(chain, spacing, smoothing, degree, centerline, status)
    type(element_chain_curve_t), intent(in) :: chain
    real(wp), intent(in) :: spacing, smoothing
    integer, intent(in) :: degree
    class(curve_t), allocatable, intent(out) :: centerline
    type(status_t), intent(out) :: status
    real(wp), allocatable :: pts(:, :)
    type(curve_point_t) :: p, q
    type(spline_centerline_t) :: fitted
    integer :: n, i
    n = max(degree + 1, ceiling(chain%total/spacing) + 1)
    allocate (pts(3, n))
    do i = 1, n
      call chain%evaluate(chain%total*(i - 1)/real(n - 1, wp), 0, p, status)
      pts(:, i) = p%d(:, 0)
    end do
    call chain%evaluate(0.0_wp, 1, p, status)
    call chain%evaluate(chain%total, 1, q, status)
    fitted = new_spline_centerline(pts, smoothing, degree, status, start_tangent=p%d(:, 1), end_tangent=q%d(:, 1))
    if (status%ok()) allocate (centerline, source=fitted)
  end subroutine fit_chain

  !> &cross_section: n_sections sections (circle, ellipse, flume) blended along
  !> the centerline; transitions given in arc length along the centerline (m).
  subroutine read_cross_section(input, centerline, section, status)
    type(input_text_t), intent(in) :: input
    class(curve_t), intent(in) :: centerline
    class(cross_section_t), allocatable, intent(out) :: section
    type(status_t), intent(inout) :: status
    integer :: n_sections, ios, i
    character(len=8) :: kind(max_sections)
    real(wp) :: radius(max_sections), half_width(max_sections), half_height(max_sections), &
      wall(max_sections), joint_width_deg(max_sections)
    real(wp) :: transition_midpoint(max_sections - 1), transition_end(max_sections - 1)
    real(wp) :: u_mid(max_sections - 1), u_end(max_sections - 1), total
    real(wp) :: profile_y(max_profile), profile_z(max_profile), profile_smoothing
    integer :: n_profile, profile_degree, k
    type(section_holder_t) :: parts(max_sections)
    type(blended_section_t) :: blend
    type(profile_section_t) :: profile
    type(status_t) :: built
    character(len=256) :: msg
    character(len=*), parameter :: g = 'cross_section'
    character(len=:), allocatable :: lim
    namelist /cross_section/ n_sections, kind, radius, half_width, half_height, wall, joint_width_deg, &
      transition_midpoint, transition_end, n_profile, profile_y, profile_z, profile_smoothing, profile_degree
    n_sections = 1
    kind = ''; radius = unset; half_width = unset; half_height = unset
    wall = unset; joint_width_deg = unset
    transition_midpoint = unset; transition_end = unset
    n_profile = 0; profile_y = unset; profile_z = unset; profile_smoothing = 0; profile_degree = 5
    read (input%lines, nml=cross_section, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=19) :: 'n_sections', 'kind', 'radius', &
        'half_width', 'half_height', 'wall', 'joint_width_deg', 'transition_midpoint', 'transition_end', &
        'n_profile', 'profile_y', 'profile_z', 'profile_smoothing', 'profile_degree'], status)
      return
    end if
    if (n_sections == 1 .and. count_given_text(kind) == 0) kind(1) = 'circle'
    call check_part_count(input, g, 'n_sections', n_sections, 1, max_sections, kind, 'sections', lim, status)
    if (.not. status%ok()) return
    call check_at_most(input, g, 'radius', count_given(radius), n_sections, lim, status)
    call check_at_most(input, g, 'half_width', count_given(half_width), n_sections, lim, status)
    call check_at_most(input, g, 'half_height', count_given(half_height), n_sections, lim, status)
    call check_at_most(input, g, 'wall', count_given(wall), n_sections, lim, status)
    call check_at_most(input, g, 'joint_width_deg', count_given(joint_width_deg), n_sections, lim, status)
    call check_exactly(input, g, 'transition_midpoint', count_given(transition_midpoint), n_sections - 1, &
                       'n_sections', n_sections, status)
    call check_exactly(input, g, 'transition_end', count_given(transition_end), n_sections - 1, &
                       'n_sections', n_sections, status)
    if (.not. status%ok()) return
    where (radius == unset) radius = 0.5_wp
    where (half_width == unset) half_width = 0.5_wp
    where (half_height == unset) half_height = 0.5_wp
    where (wall == unset) wall = 0.164_wp
    where (joint_width_deg == unset) joint_width_deg = 0.05_wp*180/pi
    where (transition_midpoint == unset) transition_midpoint = 0
    where (transition_end == unset) transition_end = 0
    do i = 1, n_sections
      kind(i) = lower(adjustl(kind(i)))
      call check_choice(input, g, 'kind(' // format_integer(i) // ')', kind(i), &
                        [character(len=7) :: 'circle', 'ellipse', 'flume', 'profile'], status)
      if (.not. status%ok()) return
      select case (trim(kind(i)))
      case ('circle')
        call check_positive(input, g, 'radius(' // format_integer(i) // ')', radius(i), 'm', status)
        if (status%ok()) allocate (parts(i)%section, source=circle_section_t(radius=radius(i)))
      case ('ellipse')
        call check_positive(input, g, 'half_width(' // format_integer(i) // ')', half_width(i), 'm', status)
        call check_positive(input, g, 'half_height(' // format_integer(i) // ')', half_height(i), 'm', status)
        if (status%ok()) allocate (parts(i)%section, &
                                   source=ellipse_section_t(a=half_width(i), b=half_height(i)))
      case ('flume')
        call check_positive(input, g, 'radius(' // format_integer(i) // ')', radius(i), 'm', status)
        call check_positive(input, g, 'wall(' // format_integer(i) // ')', wall(i), 'm', status)
        call check_range(input, g, 'joint_width_deg(' // format_integer(i) // ')', joint_width_deg(i), 0.1_wp, 20.0_wp, &
                         'deg', status)
        if (status%ok()) allocate (parts(i)%section, source=flume_section_t(radius=radius(i), wall=wall(i), &
                                   transition=joint_width_deg(i)*pi/180))
      case ('profile')
        if (n_profile < 4) then
          call invalid(input, g, 'n_profile', format_integer(n_profile), &
                       'too few profile points: need at least 4 (profile_y, profile_z)', status)
          return
        end if
        if (n_profile > max_profile) then
          call invalid(input, g, 'n_profile', format_integer(n_profile), &
                       'more than the limit of ' // format_integer(max_profile) // ' profile points', status)
          return
        end if
        call check_list_length(input, g, 'n_profile', n_profile, 'profile_y', count_given(profile_y), &
                               'points', status)
        call check_list_length(input, g, 'n_profile', n_profile, 'profile_z', count_given(profile_z), &
                               'points', status)
        if (.not. status%ok()) return
        call check_finite_vector(input, g, 'profile_y', profile_y(1:n_profile), status)
        call check_finite_vector(input, g, 'profile_z', profile_z(1:n_profile), status)
        call check_nonnegative(input, g, 'profile_smoothing', profile_smoothing, 'm^2', status)
        if (status%ok() .and. (profile_degree < 3 .or. profile_degree > 5)) &
          call invalid(input, g, 'profile_degree', format_integer(profile_degree), 'must be 3, 4 or 5', status)
        if (.not. status%ok()) return
        do k = 2, n_profile
          if (profile_y(k) == profile_y(k - 1) .and. profile_z(k) == profile_z(k - 1)) then
            call invalid(input, g, 'profile_y(' // format_integer(k) // '), profile_z(' // format_integer(k) // ')', &
                         format_vector([profile_y(k), profile_z(k)]), 'repeats the point before it', status)
            return
          end if
        end do
        k = polyline_self_intersection(profile_y(1:n_profile), profile_z(1:n_profile))
        if (k > 0) then
          call invalid(input, g, 'profile_y, profile_z', 'points ' // format_integer(k) // ' to ' // format_integer(k + 1), &
                       'the profile intersects itself (this segment crosses a later one)', status)
          return
        end if
        profile = new_profile_section(profile_y(1:n_profile), profile_z(1:n_profile), profile_smoothing, &
                                      profile_degree, built)
        call take_build_failure(input, g, built, status)
        if (.not. status%ok()) return
        allocate (parts(i)%section, source=profile)
      end select
      if (.not. status%ok()) return
    end do
    if (n_sections == 1) then
      call move_alloc(parts(1)%section, section)
      return
    end if
    total = centerline%total_length()
    do i = 1, n_sections - 1
      call check_range(input, g, 'transition_midpoint(' // format_integer(i) // ')', transition_midpoint(i), 0.0_wp, &
                       total, 'm of arc length along the centerline', status)
      if (status%ok() .and. .not. (transition_end(i) > transition_midpoint(i) .and. transition_end(i) <= total)) &
        call invalid(input, g, 'transition_end(' // format_integer(i) // ')', format_real(transition_end(i)), &
                     'must lie after transition_midpoint(' // format_integer(i) // ') and within the centerline (' // &
                     format_real(total) // ' m)', status)
      if (status%ok() .and. i > 1) then
        if (.not. transition_midpoint(i) - transition_midpoint(i - 1) >= &
            (transition_end(i) - transition_midpoint(i)) + (transition_end(i - 1) - transition_midpoint(i - 1))) &
          call invalid(input, g, 'transition_midpoint(' // format_integer(i) // ')', format_real(transition_midpoint(i)), &
                       'transitions must not overlap (midpoints at least the sum of the two half-widths apart)', &
                       status)
      end if
      if (.not. status%ok()) return
      call centerline%parameter_at_length(transition_midpoint(i), u_mid(i), built)
      if (built%ok()) call centerline%parameter_at_length(transition_end(i), u_end(i), built)
      call take_build_failure(input, g, built, status)
      if (.not. status%ok()) return
    end do
    blend = new_blended_section(parts(1:n_sections), u_mid(1:n_sections - 1), u_end(1:n_sections - 1), built)
    call take_build_failure(input, g, built, status)
    if (.not. status%ok()) return
    allocate (section, source=blend)
  end subroutine read_cross_section

  !> &blended: n_patches elementary surfaces, each placed and cut to a range
  !> of its own parameters, blended along u (thesis 3.73-3.79).
  subroutine read_blended(input, surface, status)
    type(input_text_t), intent(in) :: input
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    integer :: n_patches, ios, i
    character(len=24) :: kind(max_patches)
    real(wp) :: a(max_patches), b(max_patches), c(max_patches), origin(3, max_patches), &
      angles_deg(3, max_patches), u_min(max_patches), u_max(max_patches), v_min(max_patches), &
      v_max(max_patches), transition(max_patches - 1), midpoint(max_patches - 1), u_99(max_patches - 1)
    logical :: swap_uv(max_patches)
    type(blend_patch_t) :: patches(max_patches)
    type(blended_surface_t) :: blend
    class(surface_t), allocatable :: base
    type(status_t) :: built
    character(len=256) :: msg
    character(len=*), parameter :: g = 'blended'
    character(len=:), allocatable :: lim
    namelist /blended/ n_patches, kind, a, b, c, origin, angles_deg, u_min, u_max, v_min, v_max, swap_uv, &
      transition, midpoint, u_99
    n_patches = 0
    kind = ''; a = unset; b = unset; c = unset; origin = unset; angles_deg = unset
    u_min = unset; u_max = unset; v_min = unset; v_max = unset; swap_uv = .false.
    transition = unset; midpoint = unset; u_99 = unset
    read (input%lines, nml=blended, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=10) :: 'n_patches', 'kind', 'a', 'b', 'c', &
        'origin', 'angles_deg', 'u_min', 'u_max', 'v_min', 'v_max', 'swap_uv', 'transition', 'midpoint', &
        'u_99'], status)
      return
    end if
    call check_part_count(input, g, 'n_patches', n_patches, 2, max_patches, kind, 'patches', lim, status)
    if (.not. status%ok()) return
    call check_at_most(input, g, 'a', count_given(a), n_patches, lim, status)
    call check_at_most(input, g, 'b', count_given(b), n_patches, lim, status)
    call check_at_most(input, g, 'c', count_given(c), n_patches, lim, status)
    call check_at_most(input, g, 'origin', count_given_columns(origin), n_patches, lim, status)
    call check_at_most(input, g, 'angles_deg', count_given_columns(angles_deg), n_patches, lim, status)
    call check_at_most(input, g, 'u_min', count_given(u_min), n_patches, lim, status)
    call check_at_most(input, g, 'u_max', count_given(u_max), n_patches, lim, status)
    call check_at_most(input, g, 'v_min', count_given(v_min), n_patches, lim, status)
    call check_at_most(input, g, 'v_max', count_given(v_max), n_patches, lim, status)
    call check_at_most(input, g, 'transition', count_given(transition), n_patches - 1, &
                       'n_patches - 1 = ' // format_integer(n_patches - 1) // ' transitions', status)
    if (count_given(midpoint) > 0 .or. count_given(u_99) > 0) then
      call check_exactly(input, g, 'midpoint', count_given(midpoint), n_patches - 1, 'n_patches', n_patches, status)
      call check_exactly(input, g, 'u_99', count_given(u_99), n_patches - 1, 'n_patches', n_patches, status)
    end if
    if (.not. status%ok()) return
    where (a == unset) a = 1
    where (b == unset) b = 1
    where (c == unset) c = 1
    where (origin == unset) origin = 0
    where (angles_deg == unset) angles_deg = 0
    where (u_min == unset) u_min = 0
    where (u_max == unset) u_max = 1
    where (v_min == unset) v_min = 0
    where (v_max == unset) v_max = 1
    where (transition == unset) transition = 0
    do i = 1, n_patches
      kind(i) = lower(adjustl(kind(i)))
      call check_choice(input, g, 'kind(' // format_integer(i) // ')', kind(i), [character(len=21) :: 'ellipsoid', &
                        'elliptic_paraboloid', 'hyperbolic_paraboloid', 'elliptic_cylinder'], status)
      call check_positive(input, g, 'a(' // format_integer(i) // ')', a(i), 'm', status)
      call check_positive(input, g, 'b(' // format_integer(i) // ')', b(i), 'm', status)
      if (kind(i) == 'ellipsoid') call check_positive(input, g, 'c(' // format_integer(i) // ')', c(i), 'm', status)
      call check_finite_vector(input, g, 'origin(:, ' // format_integer(i) // ')', origin(:, i), status)
      call check_finite_vector(input, g, 'angles_deg(:, ' // format_integer(i) // ')', angles_deg(:, i), status)
      if (status%ok() .and. .not. u_max(i) > u_min(i)) &
        call invalid(input, g, 'u_max(' // format_integer(i) // ')', format_real(u_max(i)), 'must exceed u_min', status)
      if (status%ok() .and. v_max(i) == v_min(i)) &
        call invalid(input, g, 'v_max(' // format_integer(i) // ')', format_real(v_max(i)), 'must differ from v_min', status)
      if (i < n_patches) call check_nonnegative(input, g, 'transition(' // format_integer(i) // ')', transition(i), &
                                                'patch parameter units', status)
      if (.not. status%ok()) return
      select case (trim(kind(i)))
      case ('ellipsoid'); base = ellipsoid_t(a(i), b(i), c(i), built)
      case ('elliptic_paraboloid'); base = paraboloid_t(a(i), b(i), 1.0_wp, built)
      case ('hyperbolic_paraboloid'); base = paraboloid_t(a(i), b(i), -1.0_wp, built)
      case default; base = elliptic_cylinder_t(a(i), b(i), built)
      end select
      allocate (patches(i)%surface, source=placed_surface_t(base, origin(:, i), built, &
                                                            angles=angles_deg(:, i)*pi/180))
      patches(i)%u_min = u_min(i); patches(i)%u_max = u_max(i)
      patches(i)%v_min = v_min(i); patches(i)%v_max = v_max(i)
      patches(i)%swap_uv = swap_uv(i)
    end do
    if (count_given(midpoint) > 0) then
      blend = new_blended_surface(patches(1:n_patches), transition(1:n_patches - 1), built, &
                                  midpoint=midpoint(1:n_patches - 1), u_99=u_99(1:n_patches - 1))
    else
      blend = new_blended_surface(patches(1:n_patches), transition(1:n_patches - 1), built)
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
    character(len=256) :: file, msg
    character(len=12) :: layout
    real(wp) :: smoothing
    integer :: degree, ios
    logical :: periodic_u, periodic_v, exists
    type(bspline_surface_t) :: b
    character(len=*), parameter :: g = 'bspline'
    namelist /bspline/ file, layout, smoothing, degree, periodic_u, periodic_v
    file = ''; layout = 'scattered'; smoothing = 0; degree = 3
    periodic_u = .false.; periodic_v = .false.
    read (input%lines, nml=bspline, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=10) :: 'file', 'layout', 'smoothing', 'degree', &
                               'periodic_u', 'periodic_v'], status)
      return
    end if
    layout = lower(adjustl(layout))
    call check_choice(input, g, 'layout', layout, [character(len=10) :: 'scattered', 'grid', 'parametric'], status)
    call check_nonnegative(input, g, 'smoothing', smoothing, 'm^2 (sum of squared residuals)', status)
    call check_integer_in(input, g, 'degree', degree, 1, 5, status)
    if (status%ok() .and. layout /= 'parametric' .and. (periodic_u .or. periodic_v)) &
      call invalid(input, g, 'periodic_u, periodic_v', 'true', 'only a parametric surface can be periodic', status)
    if (.not. status%ok()) return
    file = input%resolve_path(file)   ! relative to the geometry file's folder
    inquire (file=trim(file), exist=exists)
    if (len_trim(file) == 0 .or. .not. exists) then
      call invalid(input, g, 'file', '''' // trim(file) // '''', 'must name an existing CSV file', status)
      return
    end if
    call bspline_from_csv(trim(file), trim(layout), smoothing, degree, [periodic_u, periodic_v], b, status)
    if (.not. status%ok()) then
      call prefix_status(status, input%name // ': &' // g)
      return
    end if
    allocate (surface, source=b)
  end subroutine read_bspline

  !> Number of entries of a list given in the input: the index of the last
  !> entry that is not `unset` (entries after it were not given).
  pure integer function count_given(a) result(n)
    real(wp), intent(in) :: a(:)
    do n = size(a), 1, -1
      if (a(n) /= unset) return
    end do
    n = 0
  end function count_given

  !> The same for a list of vectors a(:, i): the last column with any entry given.
  pure integer function count_given_columns(a) result(n)
    real(wp), intent(in) :: a(:, :)
    do n = size(a, 2), 1, -1
      if (any(a(:, n) /= unset)) return
    end do
    n = 0
  end function count_given_columns

  !> The same for a list of words (default blank).
  pure integer function count_given_text(a) result(n)
    character(len=*), intent(in) :: a(:)
    do n = size(a), 1, -1
      if (len_trim(a(n)) > 0) return
    end do
    n = 0
  end function count_given_text

  !> `count_name` = n must equal the number `given` of `what` in list `list_name`.
  subroutine check_list_length(input, g, count_name, n, list_name, given, what, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: g, count_name, list_name, what
    integer, intent(in) :: n, given
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. given == n) return
    if (given < n) then
      call invalid(input, g, count_name, format_integer(n), 'only ' // format_integer(given) // ' ' // noun(what, given) // &
                   ' given in ' // list_name, status)
    else
      call invalid(input, g, count_name, format_integer(n), format_integer(given) // ' ' // noun(what, given) // &
                   ' given in ' // list_name // '; ' // count_name // ' must equal their number', status)
    end if
  end subroutine check_list_length

  !> List `list_name` of transitions (`given` entries) needs exactly `want`:
  !> one per transition between the `count_name` = n parts.
  subroutine check_exactly(input, g, list_name, given, want, count_name, n, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: g, list_name, count_name
    integer, intent(in) :: given, want, n
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. given == want) return
    call invalid(input, g, list_name, format_integer(given) // ' values', 'needs exactly ' // format_integer(want) // &
                 ', one per transition (' // count_name // ' - 1 with ' // count_name // ' = ' // format_integer(n) // ')', status)
  end subroutine check_exactly

  !> List `list_name` (`given` entries) must not go past `limit` entries
  !> (`what` names the limit, e.g. 'n_elements = 8').
  subroutine check_at_most(input, g, list_name, given, limit, what, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: g, list_name, what
    integer, intent(in) :: given, limit
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. given <= limit) return
    call invalid(input, g, list_name, format_integer(given) // ' values', 'more values than ' // what, status)
  end subroutine check_at_most

  !> The count `count_name` = n of the parts of group g (elements, sections,
  !> patches) must lie in [low, high] and equal the number of entries of its
  !> `kind` list; `lim` ('n_elements = 3') then names the limit for check_at_most.
  subroutine check_part_count(input, g, count_name, n, low, high, kind, what, lim, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: g, count_name, kind(:), what
    integer, intent(in) :: n, low, high
    character(len=:), allocatable, intent(out) :: lim
    type(status_t), intent(inout) :: status
    call check_integer_in(input, g, count_name, n, low, high, status)
    if (.not. status%ok()) return
    call check_list_length(input, g, count_name, n, 'kind', count_given_text(kind), what, status)
    lim = count_name // ' = ' // format_integer(n)
  end subroutine check_part_count

  !> Integer `variable` = value of group g must lie in [low, high].
  subroutine check_integer_in(input, g, variable, value, low, high, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: g, variable
    integer, intent(in) :: value, low, high
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. (value >= low .and. value <= high)) return
    call invalid(input, g, variable, format_integer(value), 'must lie in [' // format_integer(low) // ', ' // &
                 format_integer(high) // ']', status)
  end subroutine check_integer_in

  !> A build step of group `place` failed (`built` not ok): its status,
  !> prefixed with the file and '&' // place, becomes `status`.
  subroutine take_build_failure(input, place, built, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: place
    type(status_t), intent(in) :: built
    type(status_t), intent(inout) :: status
    if (built%ok()) return
    status = built
    call prefix_status(status, input%name // ': &' // place)
  end subroutine take_build_failure

  !> 'points were' or, for one, 'point was' ('patches' -> 'patch').
  pure function noun(plural, k) result(text)
    character(len=*), intent(in) :: plural
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: n
    n = len(plural)
    if (k /= 1) then
      text = plural // ' were'
    else if (n > 4 .and. plural(max(1, n - 3):) == 'ches') then
      text = plural(:n - 2) // ' was'
    else
      text = plural(:n - 1) // ' was'
    end if
  end function noun

  pure function cross3(a, b) result(c)
    real(wp), intent(in) :: a(3), b(3)
    real(wp) :: c(3)
    c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
  end function cross3
end module io_geometry_config
