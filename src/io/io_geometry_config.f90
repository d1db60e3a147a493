!> Geometry input: &geometry, &centerline, &cross_section, &slide_elements,
!> &blended and &bspline describe a tube, a slide from standard elements, a
!> blended or a B-spline surface. Every value is checked (ranges, units and
!> words from io_declarations_geometry) and read into a
!> geometry_description_t, a value the chosen kind does not use is refused;
!> the geometry layer then builds the surface from the description
!> (build_geometry) and checks it (frame defined everywhere, no folding, no
!> part of a tube passing through another). A geometry that cannot be built
!> from the input is bad input (STATUS_INVALID_INPUT), its message placed at
!> the group (and variable) the geometry names.
!> See docs/geometry.md for what every variable means.
module io_geometry_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT, STATUS_IO
  use geometry_description, only: geometry_description_t, patch_description_t, blended_description_t, &
    bspline_description_t
  use io_input, only: input_text_t, group_reader_t, open_group, in_range, bounds_t, format_real, group_present, &
    where_given
  use io_csv, only: read_csv_table
  use io_slide_geometry_config, only: read_centerline, read_slide_elements, read_cross_section, &
    check_list_length, check_exactly
  use io_declarations_geometry, only: max_patches
  implicit none (type, external)
  private
  public :: read_geometry_description, explain_geometry_failure
  public :: geometry_groups, geometry_file_groups

  character(len=*), parameter :: geometry_groups(6) = [character(len=14) :: 'geometry', 'centerline', &
    'cross_section', 'slide_elements', 'blended', 'bspline']
  !> What a file named by &surface geometry_file may hold: a geometry-scenario input.
  character(len=*), parameter :: geometry_file_groups(8) = [character(len=14) :: 'run', 'grid', geometry_groups]

contains

  !> The failure `built` of building the geometry of `input` (build_geometry's
  !> `part` and `variable`; `bspline_file` as given) put in `status`, naming
  !> the line of the group at fault. Nothing when `built` is ok.
  subroutine explain_geometry_failure(input, built, part, variable, bspline_file, status)
    type(input_text_t), intent(in) :: input
    type(status_t), intent(in) :: built
    character(len=*), intent(in) :: part, variable, bspline_file
    type(status_t), intent(inout) :: status
    integer :: cut
    if (built%ok()) return
    status = built
    if (status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
    select case (part)
    case ('centerline cross_section', 'slide_elements cross_section')
      ! a fold or a pass through itself: the section too large for the bends
      cut = index(part, ' ')
      call prefix_status(status, where_given(input, part(:cut - 1), '')//': &'//part(:cut - 1)// &
                         ' with &cross_section')
      if (part(:cut - 1) == 'centerline') then
        call suffix(status, '; make &cross_section radius (or half_width, half_height) smaller or the '// &
                    'bends wider (&centerline radius, pitch, points)')
      else
        call suffix(status, '; make &cross_section radius (or half_width, half_height) smaller or the '// &
                    'bends wider (&slide_elements radius, turns, drop)')
      end if
    case ('bspline')
      call prefix_status(status, where_given(input, part, 'file')//': &bspline: file = '''//bspline_file//'''')
    case default
      call prefix_status(status, where_given(input, part, variable)//': &'//part)
    end select
  end subroutine explain_geometry_failure

  !> The description of the surface the geometry groups of `input` give,
  !> every value checked; nothing built (build_geometry builds it). If `kind`
  !> is given (by &surface kind = 'slide', ...) &geometry kind may only repeat it;
  !> `bspline_file` is &bspline file as given (for messages).
  subroutine read_geometry_description(input, description, status, kind, bspline_file)
    type(input_text_t), intent(in) :: input
    type(geometry_description_t), intent(out) :: description
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: kind
    character(len=:), allocatable, intent(out), optional :: bspline_file
    character(len=8) :: gkind
    character(len=:), allocatable :: file
    integer :: i
    type(group_reader_t) :: r
    character(len=14) :: unused(6)

    file = ''
    if (present(bspline_file)) bspline_file = file
    gkind = description%kind
    call open_group(input, 'geometry', r, status)
    call r%get('kind', gkind, status)
    call r%get('check_samples', description%slide%check_samples, status)
    if (.not. status%ok()) return
    if (present(kind)) then
      if (r%has('kind') .and. gkind /= kind) then
        call r%invalid('kind', ''''//trim(gkind)//'''', '&surface kind = '''//kind//''' asks for a '//kind// &
                       '; give the same kind or leave &geometry kind out', status)
        return
      end if
      gkind = kind
    end if
    description%kind = gkind
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
      description%slide%kind = gkind
      if (gkind == 'tube') then
        call read_centerline(input, description%slide%centerline, status)
      else
        call read_slide_elements(input, description%slide%elements, status)
      end if
      if (status%ok()) call read_cross_section(input, description%slide%section, status)
    case ('blended')
      call read_blended(input, description%blended, status)
    case ('bspline')
      call read_bspline(input, description%bspline, file, status)
      if (present(bspline_file)) bspline_file = file
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
  end subroutine read_geometry_description

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


  !> &blended: n_patches elementary surfaces, each placed and cut to a range
  !> of its own parameters, blended along u (thesis 3.73-3.79).
  subroutine read_blended(input, described, status)
    type(input_text_t), intent(in) :: input
    type(blended_description_t), intent(out) :: described
    type(status_t), intent(inout) :: status
    integer :: n, i, n_columns
    character(len=24), allocatable :: kind(:)
    real(wp), allocatable :: a(:), b(:), c(:), origin(:, :), angles_deg(:, :), u_min(:), u_max(:), v_min(:), &
      v_max(:), transition(:), midpoint(:), u_99(:)
    logical, allocatable :: swap_uv(:), given_kind(:), given_c(:), given_midpoint(:), given_u_99(:)
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
              swap_uv(n), given_kind(n), given_c(n), transition(n - 1), midpoint(n - 1), u_99(n - 1), &
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
    end do
    if (.not. status%ok()) return
    allocate (described%patches(n))
    do i = 1, n
      described%patches(i) = patch_description_t(kind=kind(i), a=a(i), b=b(i), c=c(i), origin=origin(:, i), &
                                                  angles_deg=angles_deg(:, i), u_min=u_min(i), u_max=u_max(i), &
                                                  v_min=v_min(i), v_max=v_max(i), swap_uv=swap_uv(i))
    end do
    described%transition = transition
    if (any(given_midpoint)) then
      described%midpoint = midpoint
      described%u_99 = u_99
    end if
  end subroutine read_blended

  !> &bspline: a free-form B-spline surface fitted to points from a CSV file;
  !> `file` is the file's name as given.
  subroutine read_bspline(input, described, file, status)
    type(input_text_t), intent(in) :: input
    type(bspline_description_t), intent(out) :: described
    character(len=:), allocatable, intent(out) :: file
    type(status_t), intent(inout) :: status
    character(len=4096) :: given_file
    logical :: periodic_u, periodic_v
    integer :: columns
    type(group_reader_t) :: r
    type(bounds_t) :: coordinate
    character(len=*), parameter :: g = 'bspline'

    given_file = ''
    periodic_u = .false.; periodic_v = .false.
    call open_group(input, g, r, status)
    call r%get('file', given_file, status)
    call r%get('layout', described%layout, status)
    call r%get('smoothing', described%smoothing, status)
    call r%get('degree', described%degree, status)
    call r%get('periodic_u', periodic_u, status)
    call r%get('periodic_v', periodic_v, status)
    file = trim(given_file)
    described%periodic = [periodic_u, periodic_v]
    if (status%ok() .and. described%layout /= 'parametric' .and. (periodic_u .or. periodic_v)) &
      call r%invalid('periodic_u, periodic_v', 'true', 'only a parametric surface can be periodic', status)
    if (status%ok() .and. len(file) == 0) &
      call r%invalid('file', '''''', 'must name a CSV file with the points', status)
    if (.not. status%ok()) return
    coordinate = in_range(-1e6_wp, 1e6_wp, 'm')
    columns = merge(5, 3, described%layout == 'parametric')
    ! u and v of a parametric grid are plain parameters; x, y, z in m
    call read_csv_table(input%resolve_path(file), columns, columns, 10000000, &
                        [coordinate, coordinate, coordinate, coordinate, coordinate], described%table, status)
    if (.not. status%ok()) then
      if (status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
      call prefix_status(status, r%where('file')//': &'//g//': file = '''//file//'''')
    end if
  end subroutine read_bspline

  pure subroutine suffix(status, text)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in) :: text
    if (allocated(status%message)) status%message = status%message//text
  end subroutine suffix
end module io_geometry_config
