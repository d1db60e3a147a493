!> The text of one namelist input (a file, or the built-in default), read once and
!> kept so that every group is read from the same lines and the text can be stored
!> in the result file; plus the checks every group reader uses, each producing a
!> message that names the file, the group, the variable, the value and what is
!> allowed.
module io_input
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_IO
  use base_text, only: format_real, format_vector, lower, format_integer
  use io_builtin_inputs, only: builtin_input, builtin_input_names
  implicit none (type, external)
  private
  public :: input_text_t, load_input_file, input_from_text, line_length
  public :: check_known_groups, namelist_read_error, group_present, lower
  public :: check_finite, check_positive, check_nonnegative, check_range, check_choice, &
            check_finite_vector, format_real, format_vector, invalid

  integer, parameter :: line_length = 512
  character(len=*), parameter :: builtin_prefix = 'builtin:'

  type :: input_text_t
    character(len=:), allocatable :: name        !< file path, or 'builtin:<name>'
    character(len=:), allocatable :: folder      !< the file's folder ('' for text), ends in '/'
    character(len=line_length), allocatable :: lines(:)
  contains
    procedure :: text => input_text
    procedure :: resolve_path => input_resolve_path
  end type input_text_t

contains

  !> Reads an input file, or a built-in input named 'builtin:<name>' (the
  !> files of inputs/ compiled into the program; see io_builtin_inputs).
  subroutine load_input_file(path, input, status)
    character(len=*), intent(in) :: path
    type(input_text_t), intent(out) :: input
    type(status_t), intent(inout) :: status
    integer :: unit, ios, n
    character(len=line_length) :: line
    character(len=256) :: msg
    character(len=:), allocatable :: text
    logical :: exists

    if (index(path, builtin_prefix) == 1) then
      call builtin_input(path(len(builtin_prefix) + 1:), text, exists)
      if (.not. exists) then
        call set_status(status, STATUS_IO, 'there is no built-in input "'//path//'"; built in are: '// &
                        builtin_input_names())
        return
      end if
      call input_from_text(path, text, input)
      return
    end if
    input%name = path
    input%folder = path(:index(path, '/', back=.true.))
    inquire (file=path, exist=exists)
    if (.not. exists) then
      call set_status(status, STATUS_IO, 'input file "'//path//'" does not exist')
      return
    end if
    open (newunit=unit, file=path, status='old', action='read', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call set_status(status, STATUS_IO, 'cannot open input file "'//path//'": '//trim(msg))
      return
    end if
    n = 0
    do
      read (unit, '(a)', iostat=ios, iomsg=msg) line
      if (ios /= 0) exit
      n = n + 1
    end do
    if (ios > 0) then
      close (unit)
      call set_status(status, STATUS_IO, 'cannot read input file "'//path//'" (is it a folder?): '//trim(msg))
      return
    end if
    if (n == 0) then
      close (unit)
      call set_status(status, STATUS_IO, 'input file "'//path//'" is empty')
      return
    end if
    allocate (input%lines(n))
    rewind (unit)
    do n = 1, size(input%lines)
      read (unit, '(a)') input%lines(n)
    end do
    close (unit)
  end subroutine load_input_file

  !> Splits `text` at new-line characters.
  pure subroutine input_from_text(name, text, input)
    character(len=*), intent(in) :: name, text
    type(input_text_t), intent(out) :: input
    integer :: i, start, n

    input%name = name
    input%folder = ''
    n = count([(text(i:i) == new_line('a'), i=1, len(text))]) + 1
    allocate (input%lines(n))
    start = 1
    n = 0
    do i = 1, len(text) + 1
      if (i > len(text)) then
        n = n + 1
        input%lines(n) = text(start:)
      else if (text(i:i) == new_line('a')) then
        n = n + 1
        input%lines(n) = text(start:i - 1)
        start = i + 1
      end if
    end do
  end subroutine input_from_text

  !> A path named inside this input: relative paths are taken from the input
  !> file's folder (from the working folder for inputs given as text); absolute
  !> and 'builtin:' paths stay as they are.
  pure function input_resolve_path(self, path) result(resolved)
    class(input_text_t), intent(in) :: self
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: resolved
    resolved = trim(adjustl(path))
    if (len(resolved) == 0) return
    if (resolved(1:1) == '/' .or. index(resolved, builtin_prefix) == 1) return
    if (allocated(self%folder)) resolved = self%folder//resolved
  end function input_resolve_path

  pure function input_text(self) result(text)
    class(input_text_t), intent(in) :: self
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, size(self%lines)
      text = text//trim(self%lines(i))//new_line('a')
    end do
  end function input_text

  !> Group names ('&name') that open a namelist group in the input, lower case.
  pure logical function group_present(input, group)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    integer :: i
    character(len=line_length) :: line
    group_present = .false.
    do i = 1, size(input%lines)
      line = adjustl(lower(input%lines(i)))
      if (line(1:1) /= '&') cycle
      if (first_word(line(2:)) == lower(group)) group_present = .true.
    end do
  end function group_present

  !> How many groups named `group` the input opens.
  pure integer function group_count(input, group)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    integer :: i
    character(len=line_length) :: line
    group_count = 0
    do i = 1, size(input%lines)
      line = adjustl(lower(input%lines(i)))
      if (line(1:1) /= '&') cycle
      if (first_word(line(2:)) == lower(group)) group_count = group_count + 1
    end do
  end function group_count

  !> Every group in the input must be one the scenario reads, and appear once.
  subroutine check_known_groups(input, allowed, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: allowed(:)
    type(status_t), intent(inout) :: status
    integer :: i, j
    character(len=line_length) :: line
    character(len=:), allocatable :: group, list
    logical :: known

    do i = 1, size(input%lines)
      line = adjustl(lower(input%lines(i)))
      if (line(1:1) /= '&') cycle
      group = first_word(line(2:))
      if (group == '' .or. group == 'end') cycle
      if (group_count(input, group) > 1) then
        call set_status(status, STATUS_INVALID_INPUT, input%name//': line '//format_integer(i)//': &'//group// &
                        ' appears more than once; give each group once')
        return
      end if
      known = .false.
      do j = 1, size(allowed)
        if (group == trim(allowed(j))) known = .true.
      end do
      if (.not. known) then
        list = ''
        do j = 1, size(allowed)
          list = list//' &'//trim(allowed(j))
        end do
        call set_status(status, STATUS_INVALID_INPUT, input%name//': line '//format_integer(i)// &
                        ': unknown namelist group &'//group//'; this scenario reads'//list)
        return
      end if
    end do
  end subroutine check_known_groups

  !> Turns a failed namelist read into a message naming the file, the group and,
  !> for an unknown or malformed variable, the variable and the allowed ones.
  subroutine namelist_read_error(input, group, iomsg, allowed, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, iomsg
    character(len=*), intent(in) :: allowed(:)
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: list, detail
    integer :: j, k

    list = ''
    do j = 1, size(allowed)
      list = list//' '//trim(allowed(j))
    end do
    k = index(iomsg, 'Cannot match namelist object name')
    if (k > 0) then
      detail = trim(adjustl(iomsg(k + 33:)))
      if (verify(detail(1:1), 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_') /= 0) then
        ! Not a name: a value the variable's type cannot take (a text for a number,
        ! too many values, a missing comma), which the reader then took for a name.
        detail = 'cannot read a value near "'//detail//'" (check its type: a number, a quoted text, '// &
                 'the number of values); allowed variables:'//list
      else
        detail = 'unknown variable "'//detail//'"; allowed:'//list
      end if
    else
      detail = trim(iomsg)//' (check the spelling, the type and the number of values); allowed:'//list
    end if
    call set_status(status, STATUS_INVALID_INPUT, input%name//': &'//group//': '//detail)
  end subroutine namelist_read_error

  !> The common message of every failed check.
  subroutine invalid(input, group, variable, value, allowed, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, value, allowed
    type(status_t), intent(inout) :: status
    call set_status(status, STATUS_INVALID_INPUT, input%name//': &'//group//': '//variable// &
                    ' = '//value//' is not allowed: '//allowed)
  end subroutine invalid

  subroutine check_finite(input, group, variable, value, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. ieee_is_finite(value)) &
      call invalid(input, group, variable, format_real(value), 'must be a finite number', status)
  end subroutine check_finite

  subroutine check_finite_vector(input, group, variable, value, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable
    real(wp), intent(in) :: value(:)
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. all(ieee_is_finite(value))) &
      call invalid(input, group, variable, format_vector(value), 'all components must be finite', status)
  end subroutine check_finite_vector

  !> value > 0 and finite; `unit` is shown in the message.
  subroutine check_positive(input, group, variable, value, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    ! Fortran's .and. does not short-circuit: compare only finite values (NaN traps in Debug).
    if (.not. ieee_is_finite(value)) then
      call invalid(input, group, variable, format_real(value), 'must be a finite number > 0 ('//unit//')', status)
    else if (value <= 0) then
      call invalid(input, group, variable, format_real(value), 'must be a finite number > 0 ('//unit//')', status)
    end if
  end subroutine check_positive

  subroutine check_nonnegative(input, group, variable, value, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. ieee_is_finite(value)) then
      call invalid(input, group, variable, format_real(value), 'must be a finite number >= 0 ('//unit//')', status)
    else if (value < 0) then
      call invalid(input, group, variable, format_real(value), 'must be a finite number >= 0 ('//unit//')', status)
    end if
  end subroutine check_nonnegative

  subroutine check_range(input, group, variable, value, lower, upper, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value, lower, upper
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. ieee_is_finite(value)) then
      call invalid(input, group, variable, format_real(value), 'must lie in ['//format_real(lower)// &
                   ', '//format_real(upper)//'] ('//unit//')', status)
    else if (value < lower .or. value > upper) then
      call invalid(input, group, variable, format_real(value), 'must lie in ['//format_real(lower)// &
                   ', '//format_real(upper)//'] ('//unit//')', status)
    end if
  end subroutine check_range

  !> A keyword among `choices` (compared in lower case, trailing blanks ignored).
  subroutine check_choice(input, group, variable, value, choices, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, value
    character(len=*), intent(in) :: choices(:)
    type(status_t), intent(inout) :: status
    integer :: j
    character(len=:), allocatable :: list
    if (.not. status%ok()) return
    do j = 1, size(choices)
      if (lower(trim(value)) == trim(choices(j))) return
    end do
    list = ''
    do j = 1, size(choices)
      list = list//' '//trim(choices(j))
    end do
    call invalid(input, group, variable, "'"//trim(value)//"'", 'must be one of'//list, status)
  end subroutine check_choice


  pure function first_word(text) result(word)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: word
    integer :: i
    do i = 1, len(text)
      if (text(i:i) == ' ' .or. text(i:i) == '/' .or. text(i:i) == ',') exit
    end do
    word = text(:i - 1)
  end function first_word
end module io_input
