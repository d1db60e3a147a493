!> Slides from description types: a tube surface around a centerline (a
!> line, a helix, a spline through points, or a chain of standard slide
!> elements) with a cross-section (circle, ellipse, flume, profile, or several
!> blended along the centerline). The namelist reader
!> (io_slide_geometry_config) fills these descriptions from &centerline,
!> &slide_elements and &cross_section after checking every value; a library
!> caller (the design loop, a sweep) fills them directly; geometry_description
!> holds them with the other surfaces of the geometry groups. The defaults are
!> the input defaults (docs/inputs.md).
!>
!> What is checked here is only what the geometry itself refuses (a spline
!> that cannot be fitted, an element chain that does not connect, a
!> transition beyond the centerline's end, a tube that folds or passes
!> through itself); the messages name the part. Values out of their declared
!> ranges are the reader's business.
module geometry_slide_builder
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_text, only: format_real, format_short, format_integer
  use geometry_curve, only: curve_t, curve_point_t, line_curve_t, helix_curve_t, constant_curve_t, &
    spline_centerline_t, new_spline_centerline
  use geometry_cross_section, only: cross_section_t, section_holder_t, circle_section_t, ellipse_section_t, &
    flume_section_t, blended_section_t, new_blended_section, profile_section_t, new_profile_section
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use geometry_funnel_section, only: funnel_section_t, new_funnel_section
  use geometry_patch_section, only: patch_grid_t, patch_offset_t, patch_section_t, new_patch_offset, &
    new_patch_section
  implicit none (type, external)
  private
  public :: centerline_description_t, slide_elements_description_t, section_part_description_t, &
    cross_section_description_t, slide_description_t
  public :: build_centerline_curve, build_horizon, build_element_centerline, build_section_part, &
    build_cross_section, build_slide, fit_chain

  !> The most a spline through points may be longer than the polyline on any
  !> segment between two of them (check_overshoot): the shipped inputs reach
  !> 1.16 (docs/geometry.md, "&centerline"), a half circle between two
  !> points 1.57
  real(wp), parameter :: max_overshoot = 3
  !> The most a funnel's bottom radius may grow (or shrink) per m of
  !> horizontal length (a wall flaring at 45 deg to the axis): steeper, the
  !> rider meets the widening walls head-on (widen_for_funnels)
  real(wp), parameter :: max_funnel_flare = 1

  !> &centerline: kind 'line' (start, end), 'helix' (center, radius, rise per
  !> turn, turns, phase) or 'points' (a spline through points); the horizon
  !> field: a constant vector, or one vector per point (fitted).
  type :: centerline_description_t
    character(len=8) :: kind = 'line'
    real(wp) :: start(3) = [0.0_wp, 0.0_wp, 0.0_wp], end(3) = [10.0_wp, 0.0_wp, 0.0_wp]   !< m
    real(wp) :: center(3) = 0                  !< m
    real(wp) :: radius = 5                     !< m
    real(wp) :: rise_per_turn = 0              !< m
    real(wp) :: turns = 0.25_wp                !< 1
    real(wp) :: phase = -pi/2                  !< rad
    real(wp), allocatable :: points(:, :)      !< m, 3 x n (n >= degree + 1)
    real(wp) :: smoothing = 0                  !< m^2 (FITPACK's s; 0 interpolates)
    integer :: degree = 5                      !< 3, 4 or 5
    real(wp) :: start_tangent(3) = 0, end_tangent(3) = 0   !< 0: free; odd degree when given
    real(wp) :: horizon(3) = [0.0_wp, 0.0_wp, 1.0_wp]
    real(wp), allocatable :: horizon_points(:, :)          !< 3 x n: one horizon vector per point
  end type centerline_description_t

  !> &slide_elements: a chain of standard elements, its start, heading and
  !> transition length; the centerline is the chain itself ('exact') or a
  !> spline through its points every fit_spacing m (the thesis's way).
  type :: slide_elements_description_t
    type(slide_element_t), allocatable :: elements(:)
    real(wp) :: start(3) = 0                   !< m
    real(wp) :: heading_deg = 0                !< deg
    real(wp) :: transition_length = 2          !< m
    logical :: exact = .false.                 !< centerline_kind = 'exact'
    real(wp) :: fit_spacing = 0.125_wp         !< m
    real(wp) :: smoothing = 0                  !< m^2
    integer :: degree = 5                      !< 3 or 5
    type(patch_grid_t), allocatable :: patches(:)   !< one per element of kind 'patch'
  end type slide_elements_description_t

  !> One cross-section: 'circle' (radius), 'ellipse' (half width and
  !> height), 'flume' (radius, wall, joint width) or 'profile' (points).
  type :: section_part_description_t
    character(len=8) :: kind = 'circle'
    real(wp) :: radius = 0.5_wp                !< m
    real(wp) :: half_width = 0.5_wp, half_height = 0.5_wp   !< m
    real(wp) :: wall = 0.164_wp                !< m
    real(wp) :: joint_width = 0.05_wp          !< rad
    real(wp), allocatable :: profile_y(:), profile_z(:)     !< m
    real(wp) :: profile_smoothing = 0          !< m^2
    integer :: profile_degree = 5
  end type section_part_description_t

  !> &cross_section: one part, or several blended along the centerline with
  !> transitions at arc lengths (m) from the start.
  type :: cross_section_description_t
    type(section_part_description_t), allocatable :: parts(:)      !< default: one circle
    real(wp), allocatable :: transition_midpoint(:), transition_end(:)   !< m, one per transition
  end type cross_section_description_t

  !> A whole slide: kind 'tube' (from `centerline`) or 'slide' (from
  !> `elements`, horizon [0, 0, 1]), its cross-section, and the number of
  !> samples of the check that it neither folds nor passes through itself.
  type :: slide_description_t
    character(len=8) :: kind = 'slide'
    type(centerline_description_t) :: centerline
    type(slide_elements_description_t) :: elements
    type(cross_section_description_t) :: section
    integer :: check_samples = 2000
  end type slide_description_t

contains

  !> The centerline curve of a &centerline description.
  !> `variable`: the value at fault when the points are ('points'), else ''.
  subroutine build_centerline_curve(d, curve, status, variable)
    type(centerline_description_t), intent(in) :: d
    class(curve_t), allocatable, intent(out) :: curve
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out), optional :: variable
    type(spline_centerline_t) :: fitted
    type(status_t) :: built
    if (present(variable)) variable = ''
    select case (trim(d%kind))
    case ('line')
      curve = line_curve_t(origin=d%start, direction=(d%end - d%start)/norm2(d%end - d%start), u_min=0.0_wp, &
                           u_max=norm2(d%end - d%start))
    case ('helix')
      curve = helix_curve_t(center=d%center, radius=d%radius, pitch=d%rise_per_turn/two_pi, phase=d%phase, &
                            u_min=0.0_wp, u_max=two_pi*d%turns)
    case ('points')
      if (.not. allocated(d%points)) then
        call set_status(status, STATUS_INVALID_INPUT, 'centerline: no points')
        return
      end if
      if (any(d%start_tangent /= 0) .and. any(d%end_tangent /= 0)) then
        fitted = new_spline_centerline(d%points, d%smoothing, d%degree, built, &
                                       start_tangent=d%start_tangent, end_tangent=d%end_tangent)
      else if (any(d%start_tangent /= 0)) then
        fitted = new_spline_centerline(d%points, d%smoothing, d%degree, built, start_tangent=d%start_tangent)
      else if (any(d%end_tangent /= 0)) then
        fitted = new_spline_centerline(d%points, d%smoothing, d%degree, built, end_tangent=d%end_tangent)
      else
        fitted = new_spline_centerline(d%points, d%smoothing, d%degree, built)
      end if
      if (built%ok()) then
        call check_overshoot(fitted, d%points, built)
        if (.not. built%ok() .and. present(variable)) variable = 'points'
      end if
      if (.not. built%ok()) then
        status = built
        return
      end if
      allocate (curve, source=fitted)
    case default
      call set_status(status, STATUS_INVALID_INPUT, 'centerline: kind '''//trim(d%kind)// &
                      ''' is not one of line, helix, points')
    end select
  end subroutine build_centerline_curve

  !> A spline through points that swings far away from them is refused: on
  !> no segment between consecutive points may its arc length exceed
  !> max_overshoot times their distance (docs/geometry.md, "&centerline").
  !> Its parameter is the points' cumulative chord length, so the spline's
  !> length over a segment is the chord's times its mean speed |c_u| there;
  !> a point far off the others (a typing slip: 2.5e3 for 2.5) makes the
  !> quintic overshoot by orders of magnitude (3.3e8 m of it from points 5 km
  !> apart), which no ride on such a tube could mean.
  subroutine check_overshoot(fitted, points, status)
    type(spline_centerline_t), intent(in) :: fitted
    real(wp), intent(in) :: points(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: u0, u1, chord, length
    integer :: i
    u1 = 0
    do i = 2, size(points, 2)
      chord = norm2(points(:, i) - points(:, i - 1))
      u0 = u1
      u1 = u1 + chord   ! the parameter at points(:, i), as new_spline_centerline sets it
      length = fitted%arc_length(u0, u1)
      if (.not. length <= max_overshoot*chord) then
        call set_status(status, STATUS_INVALID_INPUT, 'points: the spline through them swings away '// &
                        'between points(:, '//format_integer(i - 1)//') and points(:, '// &
                        format_integer(i)//'), '//format_short(chord)//' m apart: it is '//format_short(length)// &
                        ' m long there, '//format_short(length/chord)//' times their distance; at most '// &
                        format_short(max_overshoot)//' times is allowed (a point far off the others? '// &
                        'move it, or add points between)')
        return
      end if
    end do
  end subroutine check_overshoot

  !> The horizon field of a &centerline description: the constant horizon,
  !> or for points with horizon_points a spline through them over the
  !> centerline's parameter (the chord length of the points).
  subroutine build_horizon(d, horizon, status)
    type(centerline_description_t), intent(in) :: d
    class(curve_t), allocatable, intent(out) :: horizon
    type(status_t), intent(inout) :: status
    type(spline_centerline_t) :: horizon_fit
    real(wp), allocatable :: chord(:)
    integer :: i, n
    if (trim(d%kind) /= 'points' .or. .not. allocated(d%horizon_points)) then
      allocate (horizon, source=constant_curve_t(value=d%horizon))
      return
    end if
    n = size(d%points, 2)
    allocate (chord(n))
    chord(1) = 0
    do i = 2, n
      chord(i) = chord(i - 1) + norm2(d%points(:, i) - d%points(:, i - 1))
    end do
    horizon_fit = new_spline_centerline(d%horizon_points, 0.0_wp, min(d%degree, 5), status, parameters=chord)
    if (status%ok()) allocate (horizon, source=horizon_fit)
  end subroutine build_horizon

  !> The centerline of a chain of slide elements: the chain, or the spline
  !> through its points (fit_chain).
  subroutine build_element_centerline(d, centerline, status)
    type(slide_elements_description_t), intent(in) :: d
    class(curve_t), allocatable, intent(out) :: centerline
    type(status_t), intent(inout) :: status
    type(element_chain_curve_t) :: chain
    type(status_t) :: built
    chain = new_element_chain(d%elements, d%start, d%heading_deg, d%transition_length, built)
    if (.not. built%ok()) then
      status = built
      return
    end if
    if (d%exact) then
      allocate (centerline, source=chain)
    else
      call fit_chain(chain, d%fit_spacing, d%smoothing, d%degree, centerline, built)
      if (.not. built%ok()) status = built
    end if
  end subroutine build_element_centerline

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
      pts(:, i) = chain%quadrature_point(chain%total*(i - 1)/real(n - 1, wp))
    end do
    call chain%evaluate(0.0_wp, 1, p, status)
    call chain%evaluate(chain%total, 1, q, status)
    fitted = new_spline_centerline(pts, smoothing, degree, status, start_tangent=p%d(:, 1), end_tangent=q%d(:, 1))
    if (status%ok()) allocate (centerline, source=fitted)
  end subroutine fit_chain

  !> One cross-section.
  subroutine build_section_part(p, section, status)
    type(section_part_description_t), intent(in) :: p
    class(cross_section_t), allocatable, intent(out) :: section
    type(status_t), intent(inout) :: status
    type(profile_section_t) :: profile
    type(status_t) :: built
    select case (trim(p%kind))
    case ('circle')
      allocate (section, source=circle_section_t(radius=p%radius))
    case ('ellipse')
      allocate (section, source=ellipse_section_t(a=p%half_width, b=p%half_height))
    case ('flume')
      allocate (section, source=flume_section_t(radius=p%radius, wall=p%wall, transition=p%joint_width))
    case ('profile')
      if (.not. (allocated(p%profile_y) .and. allocated(p%profile_z))) then
        call set_status(status, STATUS_INVALID_INPUT, 'cross-section: a profile needs profile_y and profile_z')
        return
      end if
      profile = new_profile_section(p%profile_y, p%profile_z, p%profile_smoothing, p%profile_degree, built)
      if (.not. built%ok()) then
        status = built
        return
      end if
      allocate (section, source=profile)
    case default
      call set_status(status, STATUS_INVALID_INPUT, 'cross-section: kind '''//trim(p%kind)// &
                      ''' is not one of circle, ellipse, flume, profile')
    end select
  end subroutine build_section_part

  !> The cross-section along `centerline`: one part, or the parts blended
  !> across the transitions (arc lengths along the centerline, within it and
  !> not overlapping). `variable` names a transition at fault ('' if none).
  subroutine build_cross_section(d, centerline, section, status, variable)
    type(cross_section_description_t), intent(in) :: d
    class(curve_t), intent(in) :: centerline
    class(cross_section_t), allocatable, intent(out) :: section
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out), optional :: variable
    type(section_holder_t), allocatable :: parts(:)
    type(blended_section_t) :: blend
    real(wp), allocatable :: u_mid(:), u_end(:)
    real(wp) :: total
    integer :: i, n
    if (present(variable)) variable = ''
    if (.not. allocated(d%parts)) then
      allocate (section, source=circle_section_t())
      return
    end if
    n = size(d%parts)
    allocate (parts(n))
    do i = 1, n
      call build_section_part(d%parts(i), parts(i)%section, status)
      if (.not. status%ok()) return
    end do
    if (n == 1) then
      call move_alloc(parts(1)%section, section)
      return
    end if
    if (.not. (allocated(d%transition_midpoint) .and. allocated(d%transition_end))) then
      call set_status(status, STATUS_INVALID_INPUT, 'cross-section: several parts need their transitions')
      return
    end if
    if (size(d%transition_midpoint) /= n - 1 .or. size(d%transition_end) /= n - 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'cross-section: one transition between each two parts')
      return
    end if
    allocate (u_mid(n - 1), u_end(n - 1))
    total = centerline%total_length()
    do i = 1, n - 1
      associate (mid => d%transition_midpoint, end => d%transition_end)
        if (.not. (mid(i) >= 0 .and. mid(i) <= total)) then
          call refuse('transition_midpoint', mid(i), 'must lie in [0, '//format_real(total)// &
                      '] (m of arc length along the centerline)')
        else if (.not. (end(i) > mid(i) .and. end(i) <= total)) then
          call refuse('transition_end', end(i), 'must lie after transition_midpoint('//format_integer(i)// &
                      ') and within the centerline ('//format_real(total)//' m)')
        else if (i > 1) then
          if (.not. mid(i) - mid(i - 1) >= (end(i) - mid(i)) + (end(i - 1) - mid(i - 1))) &
            call refuse('transition_midpoint', mid(i), 'transitions must not overlap (midpoints at least the '// &
                        'sum of the two half-widths apart)')
        end if
      end associate
      if (.not. status%ok()) return
      call centerline%parameter_at_length(d%transition_midpoint(i), u_mid(i), status)
      if (status%ok()) call centerline%parameter_at_length(d%transition_end(i), u_end(i), status)
      if (.not. status%ok()) return
    end do
    blend = new_blended_section(parts, u_mid, u_end, status)
    if (status%ok()) allocate (section, source=blend)

  contains

    !> Transition i's `name` = x is refused: `allowed` says why.
    subroutine refuse(name, x, allowed)
      character(len=*), intent(in) :: name, allowed
      real(wp), intent(in) :: x
      character(len=:), allocatable :: element
      element = name//'('//format_integer(i)//')'
      call set_status(status, STATUS_INVALID_INPUT, element//' = '//format_real(x)//' is not allowed: '//allowed)
      if (present(variable)) variable = element
    end subroutine refuse
  end subroutine build_cross_section

  !> The whole slide, checked (no folding, no part through another). Without
  !> `part` a failure names the part in words; with it, `part` names the part
  !> of the description at fault as its input group ('centerline',
  !> 'slide_elements', 'cross_section'; the whole tube: 'centerline
  !> cross_section' or 'slide_elements cross_section'), `variable` the value
  !> at fault ('' if none; 'horizon_points' for the horizon field), and the
  !> message is left for the caller to place.
  subroutine build_slide(d, slide, status, part, variable)
    type(slide_description_t), intent(in) :: d
    type(tube_surface_t), intent(out) :: slide
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out), optional :: part, variable
    class(curve_t), allocatable :: centerline, horizon
    class(cross_section_t), allocatable :: section
    character(len=:), allocatable :: group, words, failed, funnel_part
    failed = ''
    if (present(part)) part = ''
    if (present(variable)) variable = ''
    if (.not. status%ok()) return
    select case (trim(d%kind))
    case ('tube')
      group = 'centerline'
      words = 'centerline'
      call build_centerline_curve(d%centerline, centerline, status, failed)
      if (status%ok()) then
        call build_horizon(d%centerline, horizon, status)
        if (.not. status%ok()) then
          call prefix_status(status, 'horizon_points')
          failed = 'horizon_points'
        end if
      end if
    case ('slide')
      group = 'slide_elements'
      words = 'slide elements'
      call build_element_centerline(d%elements, centerline, status)
      if (status%ok()) allocate (horizon, source=constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp]))
    case default
      call set_status(status, STATUS_INVALID_INPUT, 'slide: kind '''//trim(d%kind)//''' is not tube or slide')
      return
    end select
    if (.not. status%ok()) then
      call failure(group, words)
      return
    end if
    call build_cross_section(d%section, centerline, section, status, failed)
    if (.not. status%ok()) then
      call failure('cross_section', 'cross-section')
      return
    end if
    if (trim(d%kind) == 'slide') then
      call widen_for_funnels(d, centerline, section, status, funnel_part, failed)
      if (status%ok()) call place_patches(d, centerline, section, status, funnel_part, failed)
      if (.not. status%ok()) then
        call failure(funnel_part, words)
        return
      end if
    end if
    slide = new_tube_surface(centerline, horizon, section, status)
    if (trim(d%kind) == 'slide') slide%name = element_slide_name(d%elements%elements, d%section)
    if (status%ok()) call slide%check(d%check_samples, status)
    if (.not. status%ok()) call failure(group//' cross_section', words//' with the cross-section')

  contains

    subroutine failure(failed_part, failed_words)
      character(len=*), intent(in) :: failed_part, failed_words
      if (present(part)) then
        part = failed_part
        if (present(variable)) variable = failed
      else
        call prefix_status(status, failed_words)
      end if
    end subroutine failure
  end subroutine build_slide

  !> What a slide from elements is, in words (its surface's describe): 'slide
  !> of 4 elements (straight, bowl, straight, runout) with a flume section';
  !> more than six elements counted by kind in the order of their first
  !> appearance, '(5 straight, 4 curve, 1 runout)'; several sections blended
  !> along it, 'with 2 sections blended (circle, flume)'.
  pure function element_slide_name(elements, section) result(text)
    type(slide_element_t), intent(in) :: elements(:)
    type(cross_section_description_t), intent(in) :: section
    character(len=:), allocatable :: text
    character(len=:), allocatable :: list
    integer :: i
    list = ''
    do i = 1, size(elements)
      if (size(elements) <= 6) then
        list = list//', '//trim(elements(i)%kind)
      else if (findloc(elements(:i - 1)%kind, elements(i)%kind, dim=1) == 0) then
        list = list//', '//format_integer(count(elements%kind == elements(i)%kind))//' '//trim(elements(i)%kind)
      end if
    end do
    text = 'slide of '//format_integer(size(elements))//' element'//trim(merge('s', ' ', size(elements) /= 1))// &
           ' ('//list(3:)//') with '
    if (.not. allocated(section%parts)) then
      text = text//'a circle section'
    else if (size(section%parts) == 1) then
      text = text//'a '//trim(section%parts(1)%kind)//' section'
    else
      list = ''
      do i = 1, size(section%parts)
        list = list//', '//trim(section%parts(i)%kind)
      end do
      text = text//format_integer(size(section%parts))//' sections blended ('//list(3:)//')'
    end if
  end function element_slide_name

  !> The section of a chain with funnels (kind = 'funnel'): the slide's one
  !> circle or flume section widened about its bottom along each funnel
  !> (geometry_funnel_section): over the funnel's first third to its
  !> `radius`, kept over the second, narrowed back over the last; the thirds
  !> of its horizontal length, mapped to the tube's u (the fitted spline's by
  !> the chain's arc length). Refused: another section, a funnel not wider
  !> than the section, walls that flare faster than max_funnel_flare. On a
  !> refusal `group` and `variable` name the value at fault.
  subroutine widen_for_funnels(d, centerline, section, status, group, variable)
    type(slide_description_t), intent(in) :: d
    class(curve_t), intent(in) :: centerline
    class(cross_section_t), allocatable, intent(inout) :: section
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out) :: group, variable
    type(element_chain_curve_t) :: chain
    type(funnel_section_t) :: funnel
    real(wp), allocatable :: u_ends(:, :), scale(:)
    real(wp) :: r, sigma, third, flare, s
    integer :: i, j, k, n
    character(len=:), allocatable :: what
    group = 'slide_elements'
    variable = ''
    n = count(d%elements%elements%kind == 'funnel')
    if (n == 0) return
    r = 0.5_wp   ! the default section, a circle
    what = 'circle'
    if (allocated(d%section%parts)) then
      what = trim(d%section%parts(1)%kind)
      r = d%section%parts(1)%radius
      if (size(d%section%parts) > 1 .or. (what /= 'circle' .and. what /= 'flume')) then
        group = 'cross_section'
        variable = 'kind'
        if (size(d%section%parts) > 1) what = what//' blended with others'
        call set_status(status, STATUS_INVALID_INPUT, 'a funnel widens the slide''s section about its bottom, '// &
                        'one circle or flume section (its radius the bottom''s): not '//what)
        return
      end if
    end if
    chain = new_element_chain(d%elements%elements, d%elements%start, d%elements%heading_deg, &
                              d%elements%transition_length, status)
    if (.not. status%ok()) return
    allocate (u_ends(4, n), scale(n))
    k = 0
    do i = 1, size(d%elements%elements)
      associate (e => d%elements%elements(i))
        if (e%kind /= 'funnel') cycle
        k = k + 1
        variable = 'radius('//format_integer(i)//')'
        if (.not. e%radius > r) then
          call set_status(status, STATUS_INVALID_INPUT, 'radius('//format_integer(i)//') = '// &
                          format_real(e%radius)//' m: a funnel widens the slide''s '//what//' section of radius '// &
                          format_real(r)//' m; give its widest radius > '//format_real(r)//' m')
          return
        end if
        third = e%length/3
        flare = (e%radius - r)*(35.0_wp/16)/third   ! the smoothstep's steepest slope is 35/16
        if (.not. flare <= max_funnel_flare) then
          call set_status(status, STATUS_INVALID_INPUT, 'radius('//format_integer(i)//') = '// &
                          format_real(e%radius)//' m: the funnel (element '//format_integer(i)//') would widen '// &
                          'from '//format_real(r)//' m within a third of its length ('//format_short(third)// &
                          ' m), its walls flaring at '//format_short(atan(flare)*180/pi)//' deg to '// &
                          'its axis, more than 45: give a longer funnel (length >= '// &
                          format_short(3*(e%radius - r)*35/16/max_funnel_flare)//' m) or a smaller radius')
          return
        end if
        do j = 1, 4
          sigma = chain%ends(i) - e%length + (j - 1)*third
          if (d%elements%exact) then
            u_ends(j, k) = sigma
          else
            s = chain%arc_length(0.0_wp, sigma)
            call centerline%parameter_at_length(s, u_ends(j, k), status)
            if (.not. status%ok()) return
          end if
        end do
        scale(k) = e%radius/r
      end associate
    end do
    variable = ''
    funnel = new_funnel_section(section, u_ends, scale)
    deallocate (section)
    allocate (section, source=funnel)
  end subroutine widen_for_funnels

  !> The section of a chain with patches (kind = 'patch'): the free-form
  !> patches laid on the slide's one circle or flume section (a funnel's
  !> too), each over its element (geometry_patch_section): its stations (m
  !> of horizontal length from the element's start) mapped to the tube's u
  !> (the fitted spline's by the chain's arc length), its angles within the
  !> circle's 360 deg or the flume's round part, 0 to 180 deg. Refused: a
  !> patch element without its grid or a grid on another element, another
  !> section, the grid's own faults (new_patch_offset). On a refusal `group`
  !> and `variable` name the value at fault.
  subroutine place_patches(d, centerline, section, status, group, variable)
    type(slide_description_t), intent(in) :: d
    class(curve_t), intent(in) :: centerline
    class(cross_section_t), allocatable, intent(inout) :: section
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out) :: group, variable
    type(element_chain_curve_t) :: chain
    type(patch_offset_t), allocatable :: placed(:)
    type(patch_grid_t), allocatable :: grids(:)
    type(patch_section_t) :: patched
    real(wp), allocatable :: u(:)
    real(wp) :: r, max_angle, sigma0
    integer :: i, k, n, e
    character(len=:), allocatable :: what
    group = 'slide_elements'
    variable = ''
    n = count(d%elements%elements%kind == 'patch')
    allocate (grids(0))
    if (allocated(d%elements%patches)) grids = d%elements%patches
    do i = 1, size(grids)
      e = grids(i)%element
      variable = 'patch_file('//format_integer(max(e, 1))//')'
      if (e < 1 .or. e > size(d%elements%elements)) then
        call set_status(status, STATUS_INVALID_INPUT, 'a patch grid is given for element '//format_integer(e)// &
                        ', which the chain of '//format_integer(size(d%elements%elements))//' elements does not have')
        return
      end if
      if (d%elements%elements(e)%kind /= 'patch' .or. count(grids%element == e) > 1) then
        call set_status(status, STATUS_INVALID_INPUT, 'element '//format_integer(e)//' ('// &
                        trim(d%elements%elements(e)%kind)//') has '//format_integer(count(grids%element == e))// &
                        ' patch grids: only an element of kind ''patch'' has one, and exactly one')
        return
      end if
    end do
    do i = 1, size(d%elements%elements)
      if (d%elements%elements(i)%kind == 'patch' .and. .not. any(grids%element == i)) then
        variable = 'patch_file('//format_integer(i)//')'
        call set_status(status, STATUS_INVALID_INPUT, 'element '//format_integer(i)//' is a patch without its '// &
                        'grid of offsets: give patch_file('//format_integer(i)//')')
        return
      end if
    end do
    if (n == 0) then
      variable = ''
      return
    end if
    r = 0.5_wp   ! the default section, a circle
    what = 'circle'
    max_angle = 360
    if (allocated(d%section%parts)) then
      what = trim(d%section%parts(1)%kind)
      r = d%section%parts(1)%radius
      if (what == 'flume') max_angle = 180
      if (size(d%section%parts) > 1 .or. (what /= 'circle' .and. what /= 'flume')) then
        group = 'cross_section'
        variable = 'kind'
        if (size(d%section%parts) > 1) what = what//' blended with others'
        call set_status(status, STATUS_INVALID_INPUT, 'a patch lies on the slide''s section as offsets along its '// &
                        'radius: one circle or flume section, not '//what)
        return
      end if
    end if
    chain = new_element_chain(d%elements%elements, d%elements%start, d%elements%heading_deg, &
                              d%elements%transition_length, status)
    if (.not. status%ok()) return
    allocate (placed(n))
    do k = 1, n
      associate (grid => grids(k))
        e = grid%element
        variable = 'patch_file('//format_integer(e)//')'
        sigma0 = chain%ends(e) - d%elements%elements(e)%length
        allocate (u(size(grid%station)))
        do i = 1, size(u)
          if (d%elements%exact) then
            u(i) = sigma0 + grid%station(i)
          else
            call centerline%parameter_at_length(chain%arc_length(0.0_wp, sigma0 + grid%station(i)), u(i), status)
            if (.not. status%ok()) return
          end if
        end do
        placed(k) = new_patch_offset(grid, u, d%elements%elements(e)%length, r, max_angle, status)
        if (.not. status%ok()) return
        deallocate (u)
      end associate
    end do
    variable = ''
    patched = new_patch_section(section, placed)
    deallocate (section)
    allocate (section, source=patched)
  end subroutine place_patches
end module geometry_slide_builder
