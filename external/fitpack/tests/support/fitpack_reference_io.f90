!> Reader for the FITPACK reference tables in tests/reference/fitpack/*.txt.
!>
!> Format (plain text, also described in each table's header):
!>   - lines starting with '#' are comments (the header says how the table was made);
!>   - `case <name>` starts a case, `end` closes it;
!>   - inside a case, `<key> <count>` is followed by <count> numbers, whitespace
!>     separated, over as many lines as needed (integers are written as numbers too).
!> The whole file is held in memory; look-ups are by case name and key.
module fitpack_reference_io
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  private
  public :: reference_table_t, load_table, get_reals, get_int, get_real, has_key
  public :: reference_path, expect, expect_close, expect_close_array, expect_close_scaled, &
            expect_coefficients, finish_checks

  type :: entry_t
    integer :: case_index = 0
    character(len=:), allocatable :: key
    real(real64), allocatable :: values(:)
  end type entry_t

  type :: reference_table_t
    integer :: n_cases = 0
    character(len=64), allocatable :: case_names(:)
    type(entry_t), allocatable :: entries(:)
    integer :: n_entries = 0
  end type reference_table_t

  integer :: n_checks = 0, n_failures = 0

contains

  !> Reads a table; ok is false (with a message on stdout) if the file cannot be read.
  subroutine load_table(path, table, ok)
    character(len=*), intent(in) :: path
    type(reference_table_t), intent(out) :: table
    logical, intent(out) :: ok
    integer :: unit, ios, count, current
    character(len=4096) :: line
    character(len=256) :: word, key
    type(entry_t), allocatable :: grown(:)
    character(len=64), allocatable :: grown_names(:)

    ok = .false.
    allocate (table%case_names(16), table%entries(64))
    open (newunit=unit, file=path, status='old', action='read', iostat=ios)
    if (ios /= 0) then
      print '(a)', 'cannot open reference table '//trim(path)
      return
    end if
    current = 0
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      line = adjustl(line)
      if (len_trim(line) == 0 .or. line(1:1) == '#') cycle
      read (line, *) word
      if (word == 'case') then
        read (line, *) word, key
        if (table%n_cases == size(table%case_names)) then
          allocate (grown_names(2*table%n_cases))
          grown_names(1:table%n_cases) = table%case_names
          call move_alloc(grown_names, table%case_names)
        end if
        table%n_cases = table%n_cases + 1
        table%case_names(table%n_cases) = key(1:64)
        current = table%n_cases
      else if (word == 'end') then
        current = 0
      else
        read (line, *, iostat=ios) key, count
        if (ios /= 0 .or. current == 0) then
          print '(a)', 'malformed line in '//trim(path)//': '//trim(line)
          close (unit)
          return
        end if
        if (table%n_entries == size(table%entries)) then
          allocate (grown(2*table%n_entries))
          grown(1:table%n_entries) = table%entries
          call move_alloc(grown, table%entries)
        end if
        table%n_entries = table%n_entries + 1
        associate (e => table%entries(table%n_entries))
          e%case_index = current
          e%key = trim(key)
          allocate (e%values(count))
          if (count > 0) read (unit, *, iostat=ios) e%values
        end associate
        if (ios /= 0) then
          print '(a)', 'cannot read values of '//trim(key)//' in '//trim(path)
          close (unit)
          return
        end if
      end if
    end do
    close (unit)
    ok = .true.
  end subroutine load_table

  integer function find_entry(table, case_name, key) result(idx)
    type(reference_table_t), intent(in) :: table
    character(len=*), intent(in) :: case_name, key
    integer :: i
    idx = 0
    do i = 1, table%n_entries
      associate (e => table%entries(i))
        if (table%case_names(e%case_index) == case_name .and. e%key == key) then
          idx = i
          return
        end if
      end associate
    end do
  end function find_entry

  logical function has_key(table, case_name, key)
    type(reference_table_t), intent(in) :: table
    character(len=*), intent(in) :: case_name, key
    has_key = find_entry(table, case_name, key) > 0
  end function has_key

  !> values of key in case; found false (and values empty) if absent.
  subroutine get_reals(table, case_name, key, values, found)
    type(reference_table_t), intent(in) :: table
    character(len=*), intent(in) :: case_name, key
    real(real64), allocatable, intent(out) :: values(:)
    logical, intent(out) :: found
    integer :: idx
    idx = find_entry(table, case_name, key)
    found = idx > 0
    if (found) then
      values = table%entries(idx)%values
    else
      allocate (values(0))
    end if
  end subroutine get_reals

  subroutine get_real(table, case_name, key, value, found)
    type(reference_table_t), intent(in) :: table
    character(len=*), intent(in) :: case_name, key
    real(real64), intent(out) :: value
    logical, intent(out) :: found
    integer :: idx
    idx = find_entry(table, case_name, key)
    found = idx > 0
    value = 0
    if (found) found = size(table%entries(idx)%values) >= 1
    if (found) value = table%entries(idx)%values(1)
  end subroutine get_real

  subroutine get_int(table, case_name, key, value, found)
    type(reference_table_t), intent(in) :: table
    character(len=*), intent(in) :: case_name, key
    integer, intent(out) :: value
    logical, intent(out) :: found
    real(real64) :: r
    call get_real(table, case_name, key, r, found)
    value = nint(r)
  end subroutine get_int

  !> Path of table file `name` in the folder given as the first command-line argument.
  function reference_path(name) result(path)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: path
    character(len=1024) :: folder
    integer :: length
    call get_command_argument(1, folder, length)
    if (length == 0) folder = 'tests/reference/fitpack'
    path = trim(folder)//'/'//name
  end function reference_path

  !> Counts a check; prints what failed.
  subroutine expect(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    n_checks = n_checks + 1
    if (.not. condition) then
      n_failures = n_failures + 1
      print '(a)', 'FAIL: '//what
    end if
  end subroutine expect

  !> |x - ref| <= atol + rtol |ref|
  subroutine expect_close(x, ref, rtol, atol, what)
    real(real64), intent(in) :: x, ref, rtol, atol
    character(len=*), intent(in) :: what
    n_checks = n_checks + 1
    if (.not. (abs(x - ref) <= atol + rtol*abs(ref))) then
      n_failures = n_failures + 1
      print '(a, 3(a, es24.16))', 'FAIL: '//what, '  got ', x, '  expected ', ref, '  diff ', x - ref
    end if
  end subroutine expect_close

  !> Element-wise |x - ref| <= atol + rtol |ref|; sizes must agree.
  subroutine expect_close_array(x, ref, rtol, atol, what)
    real(real64), intent(in) :: x(:), ref(:), rtol, atol
    character(len=*), intent(in) :: what
    integer :: i, worst
    real(real64) :: excess, worst_excess
    n_checks = n_checks + 1
    if (size(x) /= size(ref)) then
      n_failures = n_failures + 1
      print '(a, 2i8)', 'FAIL: '//what//' size differs', size(x), size(ref)
      return
    end if
    worst = 0
    worst_excess = 0
    do i = 1, size(x)
      excess = abs(x(i) - ref(i)) - (atol + rtol*abs(ref(i)))
      if (.not. (excess <= worst_excess)) then
        worst = i
        worst_excess = excess
      end if
    end do
    if (worst > 0) then
      n_failures = n_failures + 1
      print '(a, i6, 3(a, es24.16))', 'FAIL: '//what//' at ', worst, '  got ', x(worst), &
        '  expected ', ref(worst), '  diff ', x(worst) - ref(worst)
    end if
  end subroutine expect_close_array

  !> max |x - ref| <= rtol max |ref| + atol: for quantities whose small entries
  !> carry no digits of their own (knots near zero, values of one evaluation).
  subroutine expect_close_scaled(x, ref, rtol, atol, what)
    real(real64), intent(in) :: x(:), ref(:), rtol, atol
    character(len=*), intent(in) :: what
    real(real64) :: scale
    scale = 0
    if (size(ref) > 0) scale = maxval(abs(ref))
    call expect_close_array(x, ref, 0.0_real64, rtol*scale + atol, what)
  end subroutine expect_close_scaled

  !> Coefficients against the genuine ones, each relative to itself:
  !> |x(i) - ref(i)| <= rtol |ref(i)| + 64 epsilon max |ref|. The floor covers only
  !> coefficients that are themselves at rounding level of the largest one (a
  !> coefficient of size ~eps*max|c| has no correct digits in either program);
  !> 64 ulps of the largest coefficient is what a few dozen rotations can leave.
  subroutine expect_coefficients(x, ref, rtol, what)
    real(real64), intent(in) :: x(:), ref(:), rtol
    character(len=*), intent(in) :: what
    real(real64) :: floor
    floor = 0
    if (size(ref) > 0) floor = 64*epsilon(1.0_real64)*maxval(abs(ref))
    call expect_close_array(x, ref, rtol, floor, what)
  end subroutine expect_coefficients

  !> Prints the summary and stops with status 1 if any check failed.
  subroutine finish_checks(name)
    character(len=*), intent(in) :: name
    print '(a, i0, a, i0, a)', trim(name)//': ', n_checks - n_failures, ' of ', n_checks, ' checks passed'
    if (n_failures > 0) error stop 1
  end subroutine finish_checks
end module fitpack_reference_io
