!> Tables of numbers from CSV files (centerline points, B-spline surface
!> points), checked cell by cell: every refusal names the file, the line, the
!> column, the value and what is allowed. Lines starting with # and blank
!> lines are skipped; the first other line may be a header (its first field
!> is not a number); every data line then has the same number of fields.
module io_csv
  use base_kinds, only: wp
  use base_text, only: format_integer, next_data_line
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use io_namelist, only: nml_value_t, read_real_token, NUMBER_OK, NUMBER_NOT
  use io_input, only: bounds_t, read_text_file
  implicit none (type, external)
  private
  public :: read_csv_table

contains

  !> table(k, i) is column k of data line i; between min_columns and
  !> max_columns columns, at most max_rows lines; column k within bounds(k).
  !> `lines(i)`: the file's line number of data line i (for the messages of
  !> checks made on the table later).
  subroutine read_csv_table(path, min_columns, max_columns, max_rows, bounds, table, status, lines)
    character(len=*), intent(in) :: path
    integer, intent(in) :: min_columns, max_columns, max_rows
    type(bounds_t), intent(in) :: bounds(:)
    real(wp), allocatable, intent(out) :: table(:, :)
    type(status_t), intent(inout) :: status
    integer, allocatable, intent(out), optional :: lines(:)
    character(len=:), allocatable :: text, line
    integer, allocatable :: line_of(:)
    real(wp), allocatable :: rows(:, :)
    integer :: start, line_no, columns, n, k
    logical :: header_allowed

    allocate (table(0, 0))
    if (present(lines)) allocate (lines(0))
    call read_text_file(path, 'CSV file', text, status)
    if (.not. status%ok()) return
    columns = 0
    n = 0
    line_no = 0
    header_allowed = .true.
    start = 1
    do while (next_data_line(text, start, line_no, line))
      if (header_allowed) then
        header_allowed = .false.
        if (.not. first_is_number(line)) cycle
      end if
      if (columns == 0) then
        columns = count_fields(line)
        if (columns < min_columns .or. columns > max_columns) then
          call fail('has '//format_integer(columns)//' columns; '//columns_wanted())
          return
        end if
        allocate (rows(columns, 64), line_of(64))
      end if
      if (count_fields(line) /= columns) then
        call fail('has '//format_integer(count_fields(line))//' columns, the lines before it '// &
                  format_integer(columns))
        return
      end if
      if (n == max_rows) then
        call fail('more than '//format_integer(max_rows)//' lines of numbers')
        return
      end if
      if (n == size(rows, 2)) then
        rows = reshape(rows, [columns, 2*n], pad=[0.0_wp])
        line_of = [line_of, spread(0, 1, n)]
      end if
      n = n + 1
      line_of(n) = line_no
      do k = 1, columns
        call take_cell(field(line, k), k, rows(k, n))
        if (.not. status%ok()) return
      end do
    end do
    if (n == 0) then
      call set_status(status, STATUS_INVALID_INPUT, path//': no lines of numbers ('//columns_wanted()//')')
      return
    end if
    table = rows(:, :n)
    if (present(lines)) lines = line_of(:n)

  contains

    subroutine take_cell(cell, k, x)
      character(len=*), intent(in) :: cell
      integer, intent(in) :: k
      real(wp), intent(out) :: x
      type(nml_value_t) :: value
      integer :: outcome
      value%text = trim(adjustl(cell))
      call read_real_token(value, x, outcome)
      if (outcome == NUMBER_OK) then
        if (bounds(k)%allows(x)) return
      end if
      if (len(value%text) == 0) then
        call fail('column '//format_integer(k)//' is empty')
      else
        call fail('column '//format_integer(k)//': '''//value%text//''' is not allowed: '//bounds(k)%text())
      end if
    end subroutine take_cell

    subroutine fail(what)
      character(len=*), intent(in) :: what
      call set_status(status, STATUS_INVALID_INPUT, path//':'//format_integer(line_no)//': '//what)
    end subroutine fail

    function columns_wanted() result(text)
      character(len=:), allocatable :: text
      if (min_columns == max_columns) then
        text = 'expected '//format_integer(min_columns)//' numbers per line, separated by commas'
      else
        text = 'expected '//format_integer(min_columns)//' to '//format_integer(max_columns)// &
               ' numbers per line, separated by commas'
      end if
    end function columns_wanted
  end subroutine read_csv_table

  pure integer function count_fields(line)
    character(len=*), intent(in) :: line
    integer :: k
    count_fields = count([(line(k:k) == ',', k=1, len(line))]) + 1
  end function count_fields

  !> Field k (1-based) of a comma-separated line.
  pure function field(line, k) result(text)
    character(len=*), intent(in) :: line
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: i, start, found
    start = 1
    found = 1
    do i = 1, len(line)
      if (line(i:i) /= ',') cycle
      if (found == k) then
        text = line(start:i - 1)
        return
      end if
      found = found + 1
      start = i + 1
    end do
    text = line(start:)
  end function field

  logical function first_is_number(line)
    character(len=*), intent(in) :: line
    type(nml_value_t) :: value
    real(wp) :: x
    integer :: outcome
    value%text = trim(adjustl(field(line, 1)))
    call read_real_token(value, x, outcome)
    first_is_number = outcome /= NUMBER_NOT   ! anything that reads as a number, even a refused one (NaN, 1e400)
  end function first_is_number
end module io_csv
