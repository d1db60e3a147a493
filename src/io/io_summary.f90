!> The summary of a run: one list of named numbers that is both printed (in
!> engineering units: degrees, g) and written as JSON (`--summary-json FILE`,
!> SI values with a units map), so the two always show the same numbers.
!>
!> JSON layout (docs/outputs.md, "Summary JSON"):
!>   {"scenario": ..., "status": "complete"|"incomplete", "status_message": ...,
!>    "result_file": ..., "values": {key: number|string|[numbers]|[{...}]},
!>    "units": {key: UDUNITS/pint unit}}
module io_summary
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_text, only: format_real, format_integer
  use base_status, only: status_t
  use io_system, only: write_standard_output
  use io_output_files, only: text_output_t
  implicit none (type, external)
  private
  public :: summary_t, degrees, standard_g, engineering

  real(wp), parameter :: degrees = 45/atan(1.0_wp)   ! degrees per radian
  real(wp), parameter :: standard_g = standard_gravity   ! m/s^2 per g

  integer, parameter :: label_width = 26   ! printed labels are padded to this
  integer, parameter :: KIND_NUMBERS = 1, KIND_TEXT = 2, KIND_TABLE = 3, KIND_LINE = 4

  type :: entry_t
    integer :: kind = KIND_NUMBERS
    character(len=:), allocatable :: key, label, units, print_units, text
    real(wp), allocatable :: values(:)          ! SI
    real(wp) :: print_scale = 1                 ! printed value = scale * SI value
    logical :: integer_valued = .false.
    logical :: as_range = .false.               ! two values written as key_min, key_max
    character(len=:), allocatable :: columns(:), column_units(:)   ! a table
    real(wp), allocatable :: table(:, :)        ! (column, row)
  end type entry_t

  type :: summary_t
    character(len=:), allocatable :: scenario, heading
    type(entry_t), allocatable :: entries(:)
    integer :: n = 0
  contains
    procedure :: start => summary_start
    procedure :: add => summary_add
    procedure :: add_range => summary_add_range
    procedure :: add_vector => summary_add_vector
    procedure :: add_count => summary_add_count
    procedure :: add_text => summary_add_text
    procedure :: add_results => summary_add_results
    procedure :: add_table => summary_add_table
    procedure :: add_line => summary_add_line
    procedure :: print => summary_print
    procedure :: write_json => summary_write_json
  end type summary_t

contains

  subroutine summary_start(self, scenario, heading)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: scenario, heading
    self%scenario = scenario
    self%heading = heading
    self%n = 0
    if (.not. allocated(self%entries)) allocate (self%entries(32))
  end subroutine summary_start

  subroutine push(self, e)
    class(summary_t), intent(inout) :: self
    type(entry_t), intent(in) :: e
    type(entry_t), allocatable :: grown(:)
    if (.not. allocated(self%entries)) allocate (self%entries(32))
    if (self%n == size(self%entries)) then
      allocate (grown(2*self%n))
      grown(:self%n) = self%entries(:self%n)
      call move_alloc(grown, self%entries)
    end if
    self%n = self%n + 1
    self%entries(self%n) = e
  end subroutine push

  !> A number: key and units for JSON (SI), label for print; printed in
  !> print_units as print_scale*value when given (e.g. degrees).
  subroutine summary_add(self, key, label, value, units, print_units, print_scale)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: key, label, units
    real(wp), intent(in) :: value
    character(len=*), intent(in), optional :: print_units
    real(wp), intent(in), optional :: print_scale
    call self%add_vector(key, label, [value], units, print_units, print_scale)
  end subroutine summary_add

  !> A min/max pair: JSON keys key_min and key_max, one printed line.
  subroutine summary_add_range(self, key, label, low, high, units, print_units, print_scale)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: key, label, units
    real(wp), intent(in) :: low, high
    character(len=*), intent(in), optional :: print_units
    real(wp), intent(in), optional :: print_scale
    call self%add_vector(key, label, [low, high], units, print_units, print_scale)
    self%entries(self%n)%as_range = .true.
  end subroutine summary_add_range

  subroutine summary_add_vector(self, key, label, values, units, print_units, print_scale)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: key, label, units
    real(wp), intent(in) :: values(:)
    character(len=*), intent(in), optional :: print_units
    real(wp), intent(in), optional :: print_scale
    type(entry_t) :: e
    e%kind = KIND_NUMBERS
    e%key = key; e%label = label; e%units = units; e%values = values
    e%print_units = units
    if (present(print_units)) e%print_units = print_units
    if (present(print_scale)) e%print_scale = print_scale
    call push(self, e)
  end subroutine summary_add_vector

  subroutine summary_add_count(self, key, label, value, what)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: key, label, what   ! what: printed after the number ('steps')
    integer, intent(in) :: value
    type(entry_t) :: e
    e%kind = KIND_NUMBERS
    e%key = key; e%label = label; e%units = '1'; e%print_units = what
    e%values = [real(value, wp)]
    e%integer_valued = .true.
    call push(self, e)
  end subroutine summary_add_count

  subroutine summary_add_text(self, key, label, text)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: key, label, text
    type(entry_t) :: e
    e%kind = KIND_TEXT
    e%key = key; e%label = label; e%text = text; e%units = ''
    call push(self, e)
  end subroutine summary_add_text

  !> The result file's path, the summary's last line (marked when incomplete).
  subroutine summary_add_results(self, path, complete)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: path
    logical, intent(in) :: complete
    if (complete) then
      call self%add_text('results', 'results', path)
    else
      call self%add_text('results', 'results (INCOMPLETE)', path)
    end if
  end subroutine summary_add_results

  !> A table (rows of records in JSON); printed by the caller in its own layout.
  subroutine summary_add_table(self, key, columns, column_units, table)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: key
    character(len=*), intent(in) :: columns(:), column_units(:)
    real(wp), intent(in) :: table(:, :)   ! (column, row)
    type(entry_t) :: e
    e%kind = KIND_TABLE
    e%key = key; e%label = ''; e%units = ''
    allocate (character(len=len(columns)) :: e%columns(size(columns)))
    allocate (character(len=len(column_units)) :: e%column_units(size(column_units)))
    e%columns = columns
    e%column_units = column_units
    e%table = table
    call push(self, e)
  end subroutine summary_add_table

  !> A printed line only (a note), not in JSON.
  subroutine summary_add_line(self, text)
    class(summary_t), intent(inout) :: self
    character(len=*), intent(in) :: text
    type(entry_t) :: e
    e%kind = KIND_LINE
    e%key = ''; e%label = ''; e%units = ''; e%text = text
    call push(self, e)
  end subroutine summary_add_line

  !> The printed summary on standard output: the heading, then one line per
  !> entry ("  label               value(s) unit"); tables are left to the
  !> caller. A line that cannot be written is remembered (io_system's
  !> standard_output_lost), and the command ends with exit status 3.
  subroutine summary_print(self)
    class(summary_t), intent(in) :: self
    integer :: k, i
    character(len=:), allocatable :: line
    call write_standard_output(self%heading)
    do k = 1, self%n
      associate (e => self%entries(k))
        select case (e%kind)
        case (KIND_NUMBERS)
          line = '  '//e%label//repeat(' ', max(1, label_width - len(e%label)))
          do i = 1, size(e%values)
            if (i > 1 .and. e%as_range) line = line//' / '
            if (i > 1 .and. .not. e%as_range) line = line//', '
            if (e%integer_valued) then
              line = line//format_integer(nint(e%values(i)))
            else
              line = line//engineering(e%print_scale*e%values(i))
            end if
          end do
          if (len(e%print_units) > 0 .and. e%print_units /= '1') line = line//' '//e%print_units
          call write_standard_output(line)
        case (KIND_TEXT)
          call write_standard_output('  '//e%label//repeat(' ', max(1, label_width - len(e%label)))//e%text)
        case (KIND_LINE)
          call write_standard_output(e%text)
        end select
      end associate
    end do
  end subroutine summary_print

  !> Writes the summary as JSON to `path` as every output file is written
  !> (io_output_files: a temporary file renamed when complete; STATUS_IO,
  !> naming the file, if it cannot be written).
  subroutine summary_write_json(self, path, complete, message, result_file, status)
    class(summary_t), intent(in) :: self
    character(len=*), intent(in) :: path, message, result_file
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    type(text_output_t) :: out
    type(status_t) :: written
    integer :: k, i, row
    character(len=:), allocatable :: units_map, sep

    call out%create(path, 'the summary JSON', written)
    if (.not. written%ok()) then
      status = written
      return
    end if
    call out%write_line('{')
    call out%write_line('  "scenario": '//quoted(self%scenario)//',')
    call out%write_line('  "status": '//quoted(trim(merge('complete  ', 'incomplete', complete)))//',')
    call out%write_line('  "status_message": '//quoted(message)//',')
    call out%write_line('  "result_file": '//quoted(result_file)//',')
    call out%write_line('  "values": {')
    units_map = ''
    sep = ''
    do k = 1, self%n
      associate (e => self%entries(k))
        select case (e%kind)
        case (KIND_NUMBERS)
          if (e%as_range) then
            call out%write_line(sep//'    '//quoted(e%key//'_min')//': '//number(e%values(1))//',')
            call out%write('    '//quoted(e%key//'_max')//': '//number(e%values(2)))
            call append_unit(units_map, e%key//'_min', e%units)
            call append_unit(units_map, e%key//'_max', e%units)
          else
            if (e%integer_valued) then
              call out%write(sep//'    '//quoted(e%key)//': '//format_integer(nint(e%values(1))))
            else
              call out%write(sep//'    '//quoted(e%key)//': '//numbers(e%values, size(e%values) > 1))
            end if
            call append_unit(units_map, e%key, e%units)
          end if
          sep = ','//new_line('a')
        case (KIND_TEXT)
          call out%write(sep//'    '//quoted(e%key)//': '//quoted(e%text))
          sep = ','//new_line('a')
        case (KIND_TABLE)
          call out%write_line(sep//'    '//quoted(e%key)//': [')
          do row = 1, size(e%table, 2)
            call out%write('      {')
            do i = 1, size(e%columns)
              call out%write(quoted(trim(e%columns(i)))//': '//number(e%table(i, row))// &
                merge(', ', '  ', i < size(e%columns)))
            end do
            call out%write_line('}'//merge(',', ' ', row < size(e%table, 2)))
          end do
          call out%write('    ]')
          do i = 1, size(e%columns)
            call append_unit(units_map, e%key//'.'//trim(e%columns(i)), trim(e%column_units(i)))
          end do
          sep = ','//new_line('a')
        end select
      end associate
    end do
    call out%write_line(new_line('a')//'  },')
    call out%write_line('  "units": {')
    if (units_map /= '') call out%write_line(units_map)
    call out%write_line('  }')
    call out%write_line('}')
    call out%finish(written)
    if (.not. written%ok()) status = written
  end subroutine summary_write_json

  !> x with 5 significant digits for reading (18.312, 0.57366, 7.5185),
  !> exponent form outside [1e-3, 1e6).
  pure function engineering(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buffer
    integer :: decimals
    if (.not. ieee_is_finite(x)) then
      text = format_real(x)
      return
    end if
    if (x == 0) then
      text = '0'
    else if (abs(x) >= 1e-3_wp .and. abs(x) < 1e6_wp) then
      decimals = max(0, 4 - floor(log10(abs(x))))
      write (buffer, '(f0.'//format_integer(decimals)//')') x
      text = trim(buffer)
      if (text(1:1) == '.') text = '0'//text
      if (text(1:2) == '-.') text = '-0'//text(2:)
      if (text(len(text):) == '.') text = text(:len(text) - 1)
    else if (abs(x) >= 1e-99_wp .and. abs(x) < 1e100_wp) then
      write (buffer, '(es11.4)') x
      text = trim(adjustl(buffer))
    else
      write (buffer, '(es12.4e3)') x   ! three exponent digits: es11.4 drops the E
      text = trim(adjustl(buffer))
    end if
  end function engineering

  !> Adds '"key": "unit"' to the units map (one per line).
  pure subroutine append_unit(units_map, key, unit)
    character(len=:), allocatable, intent(inout) :: units_map
    character(len=*), intent(in) :: key, unit
    if (len(units_map) > 0) units_map = units_map//','//new_line('a')
    units_map = units_map//'    '//quoted(key)//': '//quoted(unit)
  end subroutine append_unit

  !> A JSON number that reads back exactly; null for NaN and infinities.
  pure function number(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    if (.not. ieee_is_finite(x)) then
      text = 'null'
    else
      text = format_real(x)
    end if
  end function number

  pure function numbers(x, as_list) result(text)
    real(wp), intent(in) :: x(:)
    logical, intent(in) :: as_list
    character(len=:), allocatable :: text
    integer :: i
    if (.not. as_list) then
      text = number(x(1))
      return
    end if
    text = '['
    do i = 1, size(x)
      text = text//number(x(i))//merge(', ', '] ', i < size(x))
    end do
    text = trim(text)
  end function numbers

  !> A JSON string with quotes, backslashes and control characters escaped.
  pure function quoted(text) result(json)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: json
    integer :: i, c
    character(len=*), parameter :: hex = '0123456789abcdef'
    json = '"'
    do i = 1, len(text)
      c = iachar(text(i:i))
      select case (c)
      case (34); json = json//'\"'
      case (92); json = json//'\\'
      case (10); json = json//'\n'
      case (9); json = json//'\t'
      case (0:8, 11:31); json = json//'\u00'//hex(c/16 + 1:c/16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
      case default; json = json//text(i:i)
      end select
    end do
    json = json//'"'
  end function quoted
end module io_summary
