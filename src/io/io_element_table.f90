!> A slide's standard elements from a manufacturer's element table (CSV,
!> &slide_elements elements_file): a header line naming the columns, then
!> one element per line, in order. Columns (any order; only `kind` is
!> required; an empty or missing cell is the namelist's default):
!>   kind (straight, curve, helix, runout, drop, funnel), length (m), radius (m),
!>   angle (deg, a curve's turning angle), slope (deg, downhill > 0),
!>   direction (left, right), turns (helix, bowl), drop (m, helix, drop,
!>   bowl), profile (a bowl's: sphere, cone, table; a table bowl's points
!>   are the namelist's bowl_rho, bowl_z).
!> Each row maps to one element of &slide_elements with the same meaning
!> (length, radius, angle_deg, slope_deg, direction, turns, drop) and the
!> same checks (check_element, shared with the namelist): every refusal
!> names the file, the line, the column, the value and what is allowed.
!> Lines starting with # and blank lines are skipped.
module io_element_table
  use base_kinds, only: wp
  use base_text, only: format_integer, next_data_line
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_constants, only: two_pi
  use io_namelist, only: nml_value_t, read_real_token, NUMBER_OK
  use io_input, only: read_text_file, format_real
  use geometry_drop_profile, only: drop_min_slope_deg, drop_max_slope_deg
  use geometry_slide_elements, only: max_element_slope_deg, max_element_slope_tan
  implicit none (type, external)
  private
  public :: element_table_t, read_element_table, check_element, table_columns

  !> The columns of a table and the namelist variables they stand for.
  character(len=*), parameter :: table_columns(9) = [character(len=12) :: 'kind', 'length', 'radius', &
    'angle', 'slope', 'direction', 'turns', 'drop', 'profile']
  character(len=*), parameter :: variables(9) = [character(len=12) :: 'kind', 'length', 'radius', &
    'angle_deg', 'slope_deg', 'direction', 'turns', 'drop', 'bowl_profile']

  type :: element_table_t
    character(len=8), allocatable :: kind(:)
    character(len=5), allocatable :: direction(:)
    character(len=6), allocatable :: bowl_profile(:)
    real(wp), allocatable :: length(:), radius(:), angle_deg(:), slope_deg(:), turns(:), drop(:)
    integer, allocatable :: line(:)       !< the file's line of each element
  end type element_table_t

contains

  !> The elements of the table at `path`, at most max_elements, checked.
  subroutine read_element_table(path, max_elements, table, status)
    character(len=*), intent(in) :: path
    integer, intent(in) :: max_elements
    type(element_table_t), intent(out) :: table
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: text, line, cells(:), variable, value, allowed
    integer :: column_of(9), start, line_no, n, k, c
    logical :: header_read

    allocate (table%kind(max_elements), table%direction(max_elements), table%length(max_elements), &
              table%radius(max_elements), table%angle_deg(max_elements), table%slope_deg(max_elements), &
              table%turns(max_elements), table%drop(max_elements), table%line(max_elements), &
              table%bowl_profile(max_elements))
    table%kind = ''; table%direction = 'left'; table%bowl_profile = 'sphere'
    table%length = 0; table%radius = 0; table%angle_deg = 0; table%slope_deg = 0; table%turns = 0; table%drop = 0
    call read_text_file(path, 'element table', text, status)
    if (.not. status%ok()) return
    header_read = .false.
    column_of = 0
    n = 0
    line_no = 0
    start = 1
    do while (status%ok())
      if (.not. next_data_line(text, start, line_no, line)) exit
      cells = split(line)
      if (.not. header_read) then
        header_read = .true.
        call read_header(cells)
        cycle
      end if
      n = n + 1
      if (n > max_elements) then
        call refuse('', '', 'a table holds at most '//format_integer(max_elements)//' elements (rows)')
        return
      end if
      table%line(n) = line_no
      if (size(cells) > count(column_of > 0)) then
        call refuse('', line, 'has '//format_integer(size(cells))//' cells, the header '// &
                    format_integer(count(column_of > 0)))
        return
      end if
      do c = 1, 9
        k = column_of(c)
        if (k == 0 .or. k > size(cells)) cycle
        if (len_trim(cells(k)) == 0) cycle
        call read_cell(c, trim(cells(k)))
        if (.not. status%ok()) return
      end do
      if (len_trim(table%kind(n)) == 0) then
        call refuse('kind', '', 'no kind given (straight, curve, helix, runout, drop, bowl or funnel)')
        return
      end if
      call check_element(table%kind(n), table%length(n), table%slope_deg(n), table%radius(n), table%angle_deg(n), &
                         table%direction(n), table%turns(n), table%drop(n), variable, value, allowed, &
                         table%bowl_profile(n))
      if (len(variable) > 0) then
        call refuse(table_columns(position(variables, variable)), value, allowed)
        return
      end if
    end do
    if (.not. status%ok()) return
    if (n == 0) then
      call set_status(status, STATUS_INVALID_INPUT, path//': the element table has no element (a header line '// &
                      'naming the columns, then one element per line)')
      return
    end if
    table%kind = table%kind(:n); table%direction = table%direction(:n); table%length = table%length(:n)
    table%radius = table%radius(:n); table%angle_deg = table%angle_deg(:n); table%slope_deg = table%slope_deg(:n)
    table%turns = table%turns(:n); table%drop = table%drop(:n); table%line = table%line(:n)
    table%bowl_profile = table%bowl_profile(:n)

  contains

    subroutine read_header(names)
      character(len=*), intent(in) :: names(:)
      integer :: j, c
      do j = 1, size(names)
        c = position(table_columns, lower_trim(names(j)))
        if (c == 0) then
          call refuse_at(j, trim(names(j)), 'a column name: '//list(table_columns)// &
                         ' (the first line that is not a comment names the columns)')
          return
        end if
        if (column_of(c) > 0) then
          call refuse_at(j, trim(names(j)), 'each column once (also column '//format_integer(column_of(c))//')')
          return
        end if
        column_of(c) = j
      end do
      if (column_of(1) == 0) call refuse_at(1, trim(names(1)), 'a column kind (straight, curve, helix, runout, '// &
                                            'drop, bowl, funnel)')
    end subroutine read_header

    subroutine read_cell(c, cell)
      integer, intent(in) :: c
      character(len=*), intent(in) :: cell
      type(nml_value_t) :: number
      real(wp) :: x, low, high
      integer :: outcome
      select case (c)
      case (1)
        if (all(lower_trim(cell) /= [character(len=8) :: 'straight', 'curve', 'helix', 'runout', 'drop', &
                                     'bowl', 'funnel'])) then
          call refuse(table_columns(c), cell, 'the kind must be straight, curve, helix, runout, drop, bowl or funnel')
          return
        end if
        table%kind(n) = lower_trim(cell)
      case (6)
        if (all(lower_trim(cell) /= [character(len=5) :: 'left', 'right'])) then
          call refuse(table_columns(c), cell, 'the direction must be left or right')
          return
        end if
        table%direction(n) = lower_trim(cell)
      case (9)
        if (all(lower_trim(cell) /= [character(len=6) :: 'sphere', 'cone', 'table'])) then
          call refuse(table_columns(c), cell, 'a bowl''s profile must be sphere, cone or table')
          return
        end if
        table%bowl_profile(n) = lower_trim(cell)
      case default
        number%text = cell
        call read_real_token(number, x, outcome)
        if (outcome /= NUMBER_OK) then
          call refuse(table_columns(c), cell, 'not a number')
          return
        end if
        select case (c)
        case (2, 3); low = 0; high = 1e4_wp
        case (4); low = 0; high = 720
        case (5); low = -45; high = 85   ! [-45, 45] but for a drop (check_element)
        case (7); low = 0; high = 100
        case default; low = -1e4_wp; high = 1e4_wp
        end select
        if (.not. (x >= low .and. x <= high)) then
          call refuse(table_columns(c), cell, 'must be in ['//format_real(low)//', '//format_real(high)//'] '// &
                      trim(merge('m  ', 'deg', c == 2 .or. c == 3 .or. c == 8)))
          return
        end if
        select case (c)
        case (2); table%length(n) = x
        case (3); table%radius(n) = x
        case (4); table%angle_deg(n) = x
        case (5); table%slope_deg(n) = x
        case (7); table%turns(n) = x
        case (8); table%drop(n) = x
        end select
      end select
    end subroutine read_cell

    !> A refusal at the current row: column `name` ('' the row itself).
    subroutine refuse(name, cell, what)
      character(len=*), intent(in) :: name, cell, what
      integer :: c
      character(len=:), allocatable :: where
      where = path//':'//format_integer(line_no)
      if (len(name) > 0) then
        c = position(table_columns, name)
        where = where//': column '//format_integer(column_of(c))//' ('//trim(name)//')'
      end if
      if (len(cell) > 0) where = where//': '''//cell//''''
      call set_status(status, STATUS_INVALID_INPUT, where//': element '//format_integer(n)//': '//what)
    end subroutine refuse

    subroutine refuse_at(column, cell, what)
      integer, intent(in) :: column
      character(len=*), intent(in) :: cell, what
      call set_status(status, STATUS_INVALID_INPUT, path//':'//format_integer(line_no)//': column '// &
                      format_integer(column)//': '''//cell//''': the header needs '//what)
    end subroutine refuse_at
  end subroutine read_element_table

  !> What is wrong with one element (variable '' when nothing): a value the
  !> kind does not use must be its default; the values a kind needs must be
  !> given. `variable` is the namelist's name (length, angle_deg, ...).
  subroutine check_element(kind, length, slope_deg, radius, angle_deg, direction, turns, drop, variable, &
                                value, allowed, bowl_profile)
    character(len=*), intent(in) :: kind, direction
    real(wp), intent(in) :: length, slope_deg, radius, angle_deg, turns, drop
    character(len=:), allocatable, intent(out) :: variable, value, allowed
    character(len=*), intent(in), optional :: bowl_profile   ! 'sphere' (the default) when absent
    character(len=:), allocatable :: profile
    variable = ''; value = ''; allowed = ''
    profile = 'sphere'
    if (present(bowl_profile)) profile = trim(bowl_profile)
    if (trim(kind) /= 'bowl' .and. profile /= 'sphere') call set('bowl_profile', ''''//profile//'''', &
      'a '//trim(kind)//' is no bowl; give ''sphere'' (the default) or leave it out')
    select case (trim(kind))
    case ('straight', 'runout', 'patch')
      call unused(radius, 'radius'); call unused(angle_deg, 'angle_deg')
      call unused(turns, 'turns'); call unused(drop, 'drop')
      if (len(variable) == 0 .and. direction /= 'left') call set('direction', ''''//trim(direction)//'''', &
        'a '//trim(kind)//' does not turn; give ''left'' (the default) or leave it out')
      if (len(variable) == 0 .and. .not. length > 0) call set('length', format_real(length), &
        'a '//trim(kind)//' needs a length > 0 (m)')
      call gentle(slope_deg)
    case ('curve')
      call unused(length, 'length'); call unused(turns, 'turns'); call unused(drop, 'drop')
      call gentle(slope_deg)
      if (len(variable) == 0 .and. .not. radius > 0) call set('radius', format_real(radius), &
        'a curve needs a radius > 0 (m)')
      if (len(variable) == 0 .and. .not. angle_deg >= 1e-6_wp) call set('angle_deg', format_real(angle_deg), &
        'a curve needs a turning angle in [1e-6, 720] (deg)')
    case ('helix')
      call unused(length, 'length'); call unused(slope_deg, 'slope_deg'); call unused(angle_deg, 'angle_deg')
      if (len(variable) == 0 .and. .not. radius > 0) call set('radius', format_real(radius), &
        'a helix needs a radius > 0 (m)')
      if (len(variable) == 0 .and. .not. turns > 0) call set('turns', format_real(turns), 'a helix needs turns > 0')
      if (len(variable) == 0 .and. .not. abs(drop) <= max_element_slope_tan*(two_pi*radius*turns)) &
        call set('drop', format_real(drop), 'the helix would be steeper than '//format_integer(nint(max_element_slope_deg))// &
                 ' deg (|drop| <= 2 pi radius turns)')
    case ('drop')
      call unused(length, 'length'); call unused(angle_deg, 'angle_deg'); call unused(turns, 'turns')
      if (len(variable) == 0 .and. direction /= 'left') call set('direction', ''''//trim(direction)//'''', &
        'a drop does not turn; give ''left'' (the default) or leave it out')
      if (len(variable) == 0 .and. .not. (slope_deg >= drop_min_slope_deg .and. slope_deg <= drop_max_slope_deg)) &
        call set('slope_deg', format_real(slope_deg), 'a drop falls at a top slope in ['// &
                 format_real(drop_min_slope_deg)//', '//format_real(drop_max_slope_deg)//'] (deg)')
      if (len(variable) == 0 .and. .not. radius > 0) call set('radius', format_real(radius), &
        'a drop needs the radius of its curve-out > 0 (m)')
      if (len(variable) == 0 .and. .not. drop > 0) call set('drop', format_real(drop), &
        'a drop needs the height it loses > 0 (m)')
    case ('funnel')
      call unused(angle_deg, 'angle_deg'); call unused(turns, 'turns'); call unused(drop, 'drop')
      if (len(variable) == 0 .and. direction /= 'left') call set('direction', ''''//trim(direction)//'''', &
        'a funnel does not turn; give ''left'' (the default) or leave it out')
      if (len(variable) == 0 .and. .not. length > 0) call set('length', format_real(length), &
        'a funnel needs a length > 0 (m)')
      call gentle(slope_deg)
      if (len(variable) == 0 .and. .not. radius > 0) call set('radius', format_real(radius), &
        'a funnel needs the radius of its widest section > 0 (m), wider than the slide''s section')
    case ('bowl')
      call unused(length, 'length'); call unused(angle_deg, 'angle_deg')
      if (len(variable) == 0 .and. all(profile /= [character(len=6) :: 'sphere', 'cone', 'table'])) &
        call set('bowl_profile', ''''//profile//'''', 'a bowl''s profile is ''sphere'', ''cone'' or ''table''')
      if (len(variable) == 0 .and. .not. radius > 0) call set('radius', format_real(radius), &
        'a bowl needs its entry''s distance from its axis > 0 (m)')
      if (profile == 'table') then
        if (len(variable) == 0 .and. slope_deg /= 0) call set('slope_deg', format_real(slope_deg), &
          'a table bowl''s wall rises as its table says at the entry; give 0 or leave it out')
      else if (len(variable) == 0 .and. .not. (slope_deg > 0 .and. slope_deg <= 85)) then
        call set('slope_deg', format_real(slope_deg), 'a bowl''s wall rises at its entry at a slope in (0, 85] (deg)')
      end if
      if (len(variable) == 0 .and. .not. drop > 0) call set('drop', format_real(drop), &
        'a bowl needs the height it loses from its entry to its outlet > 0 (m)')
      if (len(variable) == 0 .and. .not. turns > 0) call set('turns', format_real(turns), &
        'a bowl needs the turns of its spiral > 0')
    end select
  contains
    !> Only a drop is steeper than max_element_slope_deg (the geometry's limit).
    subroutine gentle(slope)
      real(wp), intent(in) :: slope
      if (len(variable) == 0 .and. .not. abs(slope) <= max_element_slope_deg) call set('slope_deg', &
        format_real(slope), 'a '//trim(kind)//'''s slope must lie in [-'//format_integer(nint(max_element_slope_deg))// &
        ', '//format_integer(nint(max_element_slope_deg))//'] (deg; only a drop is steeper)')
    end subroutine gentle

    subroutine unused(x, name)
      real(wp), intent(in) :: x
      character(len=*), intent(in) :: name
      if (len(variable) == 0 .and. x /= 0) call set(name, format_real(x), 'a '//trim(kind)//' does not use '// &
        name//'; give 0 or leave it out')
    end subroutine unused

    subroutine set(name, text, what)
      character(len=*), intent(in) :: name, text, what
      variable = name; value = text; allowed = what
    end subroutine set
  end subroutine check_element

  !> The comma-separated cells of a line, each trimmed.
  pure function split(line) result(cells)
    character(len=*), intent(in) :: line
    character(len=:), allocatable :: cells(:)
    integer :: n, k, start, width
    n = count([(line(k:k) == ',', k = 1, len(line))]) + 1
    width = max(1, len(line))
    allocate (character(len=width) :: cells(n))
    start = 1
    do k = 1, n
      if (k < n) then
        cells(k) = adjustl(line(start:start + index(line(start:), ',') - 2))
        start = start + index(line(start:), ',')
      else
        cells(k) = adjustl(line(start:))
      end if
    end do
  end function split

  !> Where `name` is in `list` (0: not there); texts compared without
  !> trailing blanks (gfortran's findloc misses a shorter text).
  pure integer function position(list, name)
    character(len=*), intent(in) :: list(:), name
    do position = 1, size(list)
      if (trim(list(position)) == trim(name)) return
    end do
    position = 0
  end function position

  pure function lower_trim(text) result(low)
    character(len=*), intent(in) :: text
    character(len=len_trim(text)) :: low
    integer :: k
    low = trim(text)
    do k = 1, len(low)
      if (low(k:k) >= 'A' .and. low(k:k) <= 'Z') low(k:k) = achar(iachar(low(k:k)) + 32)
    end do
  end function lower_trim

  pure function list(names) result(text)
    character(len=*), intent(in) :: names(:)
    character(len=:), allocatable :: text
    integer :: k
    text = trim(names(1))
    do k = 2, size(names)
      text = text//', '//trim(names(k))
    end do
  end function list
end module io_element_table
