!> The namelist language of slidesim's inputs, read by our own lexer instead of
!> the compiler's namelist READ, so that every flaw of an input is found and
!> named with its line: groups `&name ... /` (or `&end`), assignments
!> `var = v1, v2, ...` and `var(i) = ...`, `var(:, j) = ...`, `var(i:k) = ...`,
!> repeat counts `r*v`, quoted texts ('...' or "..." with doubled quotes),
!> comments from `!`, any line length. Refused: a group not closed before the
!> end of the text (a file cut short), text outside groups that is not a
!> comment, a group opened inside another, null values (`a = 1,,2`, `r*`),
!> an assignment without a value, a text not closed on its line, control
!> characters (a binary file). Values are kept as written (with their line);
!> what they mean is decided by the reader of each group (io_input), which
!> knows the variables' types, sizes and ranges.
module io_namelist
  use base_kinds, only: wp, int64
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_integer, lower
  implicit none (type, external)
  private
  public :: nml_value_t, nml_item_t, nml_group_t, parse_namelist, parse_assignment
  public :: VALUE_BARE, VALUE_TEXT, NUMBER_OK, NUMBER_NONFINITE, NUMBER_TOO_LARGE, NUMBER_NOT
  public :: read_real_token, read_integer_token, read_logical_token, shown_value

  integer, parameter :: VALUE_BARE = 1   !< a number, a logical or a word, as written
  integer, parameter :: VALUE_TEXT = 2   !< a quoted text (quotes removed, doubled quotes undone)

  !> Outcomes of reading a number.
  integer, parameter :: NUMBER_OK = 0, NUMBER_NONFINITE = 1, NUMBER_TOO_LARGE = 2, NUMBER_NOT = 3

  !> Decimal exponents beyond this are refused before conversion: no input
  !> quantity comes near them, and converting 1e400 would overflow.
  integer, parameter :: max_decimal_exponent = 300

  type :: nml_value_t
    character(len=:), allocatable :: text
    integer :: kind = VALUE_BARE
    integer(int64) :: repeat = 1        !< r of r*v
    integer :: line = 0
  end type nml_value_t

  !> One assignment `name(subscript) = values`.
  type :: nml_item_t
    character(len=:), allocatable :: name        !< lower case
    character(len=:), allocatable :: subscript   !< as written with its parentheses, '' if none
    integer :: rank = 0                          !< 0: the whole variable
    integer :: low(2) = 0, high(2) = 0           !< bounds per subscript dimension
    logical :: whole(2) = .false.                !< ':' in that dimension
    type(nml_value_t), allocatable :: values(:)
    integer :: line = 0
    character(len=:), allocatable :: origin      !< '' from the text; else where it came from (--set ...)
  end type nml_item_t

  type :: nml_group_t
    character(len=:), allocatable :: name        !< lower case
    integer :: line = 0                          !< where it opens (0: added from the command line)
    type(nml_item_t), allocatable :: items(:)
    type(nml_item_t), allocatable :: removed(:)  !< variables --unset removed (no values), for the name check
  end type nml_group_t

  !> Position in the text being read.
  type :: cursor_t
    integer :: pos = 1, line = 1
  end type cursor_t

  character(len=*), parameter :: name_start = 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ'
  character(len=*), parameter :: name_chars = name_start//'0123456789_'
  character(len=1), parameter :: tab = achar(9), lf = achar(10), cr = achar(13)

contains

  !> Reads `text` (from `source`, for messages) into its groups.
  subroutine parse_namelist(source, text, groups, status)
    character(len=*), intent(in) :: source, text
    type(nml_group_t), allocatable, intent(out) :: groups(:)
    type(status_t), intent(inout) :: status
    type(cursor_t) :: c
    type(nml_group_t) :: group
    character(len=:), allocatable :: word

    allocate (groups(0))
    call check_characters(source, text, status)
    if (.not. status%ok()) return
    do
      call skip_blanks(text, c)
      if (c%pos > len(text)) exit
      if (text(c%pos:c%pos) /= '&') then
        call fail(source, c%line, 'text outside a group: "'//clipped(rest_of_line(text, c%pos))// &
                  '"; an input holds only namelist groups (&name ... /) and comments (after !)', status)
        return
      end if
      c%pos = c%pos + 1
      word = read_name(text, c)
      if (len(word) == 0) then
        call fail(source, c%line, '"&" without a group name after it', status)
        return
      end if
      if (word == 'end') then
        call fail(source, c%line, '&end without an open group', status)
        return
      end if
      group%name = word
      group%line = c%line
      call read_group_body(source, text, c, group, status)
      if (.not. status%ok()) return
      groups = [groups, group]
    end do
  end subroutine parse_namelist

  !> Reads one assignment `name(subscript) = values` given alone (from the
  !> command line: --set group%name=values); `origin` names it in messages.
  subroutine parse_assignment(origin, text, item, status)
    character(len=*), intent(in) :: origin, text
    type(nml_item_t), intent(out) :: item
    type(status_t), intent(inout) :: status
    type(cursor_t) :: c
    call check_characters(origin, text, status)
    if (.not. status%ok()) return
    call skip_blanks(text, c)
    if (.not. starts_name(text, c%pos)) then
      call set_status(status, STATUS_INVALID_INPUT, origin//': expected a variable name')
      return
    end if
    call read_item(origin, '', text, c, item, status)
    if (.not. status%ok()) return
    item%origin = origin
    call skip_blanks(text, c)
    if (c%pos <= len(text)) call set_status(status, STATUS_INVALID_INPUT, origin// &
      ': unexpected "'//clipped(text(c%pos:))//'" after the values (one variable per --set)')
  end subroutine parse_assignment

  subroutine read_group_body(source, text, c, group, status)
    character(len=*), intent(in) :: source, text
    type(cursor_t), intent(inout) :: c
    type(nml_group_t), intent(inout) :: group
    type(status_t), intent(inout) :: status
    type(nml_item_t) :: item
    type(cursor_t) :: mark
    character(len=:), allocatable :: word
    character(len=:), allocatable :: where

    where = '&'//group%name//' (opened at line '//format_integer(group%line)//')'
    if (allocated(group%items)) deallocate (group%items)
    allocate (group%items(0))
    do
      call skip_blanks(text, c)
      if (c%pos > len(text)) then
        call fail(source, c%line - merge(1, 0, c%line > 1 .and. text(len(text):len(text)) == lf), &
                  where//' is not closed by "/" before the end of the input: is the file cut short?', status)
        return
      end if
      select case (text(c%pos:c%pos))
      case ('/')
        c%pos = c%pos + 1
        return
      case ('&')
        mark = c
        c%pos = c%pos + 1
        word = read_name(text, c)
        if (word == 'end') return
        call fail(source, mark%line, where//' is not closed by "/" before &'//word//' opens', status)
        return
      case (',')
        c%pos = c%pos + 1   ! a separator after the last value of an assignment
      case default
        if (.not. starts_name(text, c%pos)) then
          call fail(source, c%line, '&'//group%name//': expected a variable name or the closing "/", found "'// &
                    clipped(rest_of_line(text, c%pos))//'"', status)
          return
        end if
        call read_item(source, group%name, text, c, item, status)
        if (.not. status%ok()) return
        item%origin = ''
        group%items = [group%items, item]
      end select
    end do
  end subroutine read_group_body

  !> name [subscript] = value, value, ... up to the next name, "/" or "&".
  subroutine read_item(source, group, text, c, item, status)
    character(len=*), intent(in) :: source, group, text
    type(cursor_t), intent(inout) :: c
    type(nml_item_t), intent(inout) :: item
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: prefix
    type(nml_value_t) :: value
    type(nml_value_t), allocatable :: values(:)
    integer :: n
    logical :: after_comma

    prefix = ''
    if (len(group) > 0) prefix = '&'//group//': '
    item%line = c%line
    item%name = read_name(text, c)
    item%subscript = ''
    item%rank = 0
    call skip_blanks(text, c)
    if (c%pos <= len(text)) then
      if (text(c%pos:c%pos) == '(') then
        call read_subscript(source, prefix, text, c, item, status)
        if (.not. status%ok()) return
        call skip_blanks(text, c)
      end if
    end if
    if (c%pos > len(text)) then
      call fail(source, item%line, prefix//'"'//item%name//'" without "=" and a value: is the file cut short?', status)
      return
    end if
    if (text(c%pos:c%pos) /= '=') then
      call fail(source, c%line, prefix//'expected "=" after the variable name "'//item%name//item%subscript// &
                '", found "'//clipped(rest_of_line(text, c%pos))//'"', status)
      return
    end if
    c%pos = c%pos + 1

    allocate (values(8))
    n = 0
    after_comma = .false.
    do
      call skip_blanks(text, c)
      if (c%pos > len(text)) exit
      select case (text(c%pos:c%pos))
      case (',')
        if (n == 0 .or. after_comma) then
          call fail(source, c%line, prefix//item%name//item%subscript//': a value is missing before a comma '// &
                    '(null values are not accepted: give every value)', status)
          return
        end if
        after_comma = .true.
        c%pos = c%pos + 1
        cycle
      case ('/', '&')
        exit
      end select
      if (next_is_assignment(text, c)) exit
      call read_value(source, prefix//item%name//item%subscript, text, c, value, status)
      if (.not. status%ok()) return
      call push_value(values, n, value)
      after_comma = .false.
    end do
    item%values = values(:n)
    if (n == 0) call fail(source, item%line, prefix//item%name//item%subscript//' = without a value', status)
  end subroutine read_item

  !> (i), (i, j), (:, j), (i:k), (i:k, j): one or two dimensions.
  subroutine read_subscript(source, prefix, text, c, item, status)
    character(len=*), intent(in) :: source, prefix, text
    type(cursor_t), intent(inout) :: c
    type(nml_item_t), intent(inout) :: item
    type(status_t), intent(inout) :: status
    integer :: close, comma
    logical :: ok
    character(len=:), allocatable :: inside
    character(len=*), parameter :: how = ' (write (i), (i, j), (:, j) or (i:k) with whole numbers)'

    close = index(text(c%pos:), ')')
    if (close > 0) then
      if (index(text(c%pos:c%pos + close - 1), lf) > 0) close = 0
    end if
    if (close == 0) then
      call fail(source, c%line, prefix//item%name//': "(" without ")" on its line'//how, status)
      return
    end if
    item%subscript = text(c%pos:c%pos + close - 1)
    inside = text(c%pos + 1:c%pos + close - 2)
    c%pos = c%pos + close
    comma = index(inside, ',')
    ok = index(inside(comma + 1:), ',') == 0
    if (comma > 0) then
      item%rank = 2
      if (ok) call read_bounds(inside(:comma - 1), 1, ok)
      if (ok) call read_bounds(inside(comma + 1:), 2, ok)
    else
      item%rank = 1
      call read_bounds(inside, 1, ok)
    end if
    if (.not. ok) call fail(source, c%line, prefix//'subscript '//item%name//item%subscript// &
                            ' is not understood'//how, status)

  contains

    subroutine read_bounds(part_in, d, ok)
      character(len=*), intent(in) :: part_in
      integer, intent(in) :: d
      logical, intent(out) :: ok
      character(len=:), allocatable :: part
      integer :: colon, ios
      part = trim(adjustl(part_in))
      item%whole(d) = part == ':'
      ok = .true.
      if (item%whole(d)) return
      ok = len(part) > 0 .and. len(part) <= 9 + index(part, ':') .and. verify(part, '0123456789: ') == 0
      if (.not. ok) return
      colon = index(part, ':')
      if (colon > 0) then
        ok = colon > 1 .and. colon < len(part) .and. index(part(colon + 1:), ':') == 0
        if (.not. ok) return
        read (part(:colon - 1), *, iostat=ios) item%low(d)
        if (ios == 0) read (part(colon + 1:), *, iostat=ios) item%high(d)
      else
        read (part, *, iostat=ios) item%low(d)
        item%high(d) = item%low(d)
      end if
      ok = ios == 0
    end subroutine read_bounds
  end subroutine read_subscript

  !> A quoted text or a bare token (with an optional repeat count r*).
  subroutine read_value(source, what, text, c, value, status)
    character(len=*), intent(in) :: source, what, text
    type(cursor_t), intent(inout) :: c
    type(nml_value_t), intent(out) :: value
    type(status_t), intent(inout) :: status
    integer :: start, star, ios

    value%line = c%line
    value%repeat = 1
    start = c%pos
    if (.not. is_quote(text(c%pos:c%pos))) then
      do while (c%pos <= len(text))
        if (index(' ,/!&='//tab//lf//cr//'''"', text(c%pos:c%pos)) > 0) exit
        c%pos = c%pos + 1
      end do
      value%text = text(start:c%pos - 1)
      star = index(value%text, '*')
      if (star > 1 .and. verify(value%text(:max(star - 1, 1)), '0123456789') == 0) then
        if (star - 1 > 9) then
          ios = 1
        else
          read (value%text(:star - 1), *, iostat=ios) value%repeat
        end if
        if (ios /= 0 .or. value%repeat < 1) then
          call fail(source, c%line, what//': repeat count "'//value%text(:star)//'" must be a whole number '// &
                    'from 1 to 999999999', status)
          return
        end if
        value%text = value%text(star + 1:)
        if (len(value%text) == 0) then
          if (c%pos <= len(text)) then
            if (is_quote(text(c%pos:c%pos))) then
              call read_quoted(source, what, text, c, value, status)
              return
            end if
          end if
          call fail(source, c%line, what//': "'//text(start:c%pos - 1)//'" repeats a null value; '// &
                    'null values are not accepted: give every value', status)
        end if
      else if (len(value%text) == 0) then
        call fail(source, c%line, what//': unexpected "'//text(c%pos:c%pos)//'"', status)
      end if
      return
    end if
    call read_quoted(source, what, text, c, value, status)
  end subroutine read_value

  subroutine read_quoted(source, what, text, c, value, status)
    character(len=*), intent(in) :: source, what, text
    type(cursor_t), intent(inout) :: c
    type(nml_value_t), intent(inout) :: value
    type(status_t), intent(inout) :: status
    character(len=1) :: quote
    character(len=:), allocatable :: buffer
    integer :: start, n

    quote = text(c%pos:c%pos)
    c%pos = c%pos + 1
    allocate (character(len=len(text)) :: buffer)
    n = 0
    start = c%pos
    do
      if (c%pos > len(text)) exit
      if (text(c%pos:c%pos) == lf) exit
      if (text(c%pos:c%pos) == quote) then
        if (c%pos < len(text)) then
          if (text(c%pos + 1:c%pos + 1) == quote) then   ! a doubled quote stands for one
            n = n + 1
            buffer(n:n) = quote
            c%pos = c%pos + 2
            cycle
          end if
        end if
        c%pos = c%pos + 1
        value%kind = VALUE_TEXT
        value%text = buffer(:n)
        return
      end if
      n = n + 1
      buffer(n:n) = text(c%pos:c%pos)
      c%pos = c%pos + 1
    end do
    call fail(source, c%line, what//': the text '//quote//clipped(text(start:c%pos - 1))// &
              ' is not closed by '//quote//' on its line', status)
  end subroutine read_quoted

  !> Is the text at the cursor `name [subscript] =` (the next assignment)?
  logical function next_is_assignment(text, c) result(yes)
    character(len=*), intent(in) :: text
    type(cursor_t), intent(in) :: c
    type(cursor_t) :: look
    character(len=:), allocatable :: word
    integer :: close
    yes = .false.
    if (.not. starts_name(text, c%pos)) return
    look = c
    word = read_name(text, look)
    call skip_blanks(text, look)
    if (look%pos > len(text)) return
    if (text(look%pos:look%pos) == '(') then
      close = index(text(look%pos:), ')')
      if (close == 0) return
      look%pos = look%pos + close
      call skip_blanks(text, look)
      if (look%pos > len(text)) return
    end if
    yes = text(look%pos:look%pos) == '='
  end function next_is_assignment

  !> Blanks, tabs, line ends and comments (from ! to the end of the line).
  subroutine skip_blanks(text, c)
    character(len=*), intent(in) :: text
    type(cursor_t), intent(inout) :: c
    do while (c%pos <= len(text))
      select case (text(c%pos:c%pos))
      case (' ', tab, cr)
        c%pos = c%pos + 1
      case (lf)
        c%pos = c%pos + 1
        c%line = c%line + 1
      case ('!')
        do while (c%pos <= len(text))
          if (text(c%pos:c%pos) == lf) exit
          c%pos = c%pos + 1
        end do
      case default
        return
      end select
    end do
  end subroutine skip_blanks

  function read_name(text, c) result(name)
    character(len=*), intent(in) :: text
    type(cursor_t), intent(inout) :: c
    character(len=:), allocatable :: name
    integer :: start
    start = c%pos
    if (starts_name(text, c%pos)) then
      do while (c%pos <= len(text))
        if (index(name_chars, text(c%pos:c%pos)) == 0) exit
        c%pos = c%pos + 1
      end do
    end if
    name = trim(lower(text(start:c%pos - 1)))
  end function read_name

  pure logical function starts_name(text, pos)
    character(len=*), intent(in) :: text
    integer, intent(in) :: pos
    starts_name = .false.
    if (pos <= len(text)) starts_name = index(name_start, text(pos:pos)) > 0
  end function starts_name

  pure logical function is_quote(ch)
    character(len=1), intent(in) :: ch
    is_quote = ch == '''' .or. ch == '"'
  end function is_quote

  !> Control characters other than tab and line ends mean a binary file.
  subroutine check_characters(source, text, status)
    character(len=*), intent(in) :: source, text
    type(status_t), intent(inout) :: status
    integer :: i, code, line
    character(len=2) :: hex
    line = 1
    do i = 1, len(text)
      code = iachar(text(i:i))
      if (code == 10) line = line + 1
      if ((code < 32 .and. code /= 9 .and. code /= 10 .and. code /= 13) .or. code == 127) then
        write (hex, '(z2.2)') code
        call fail(source, line, 'byte 0x'//hex//' is not text: is this a namelist input file?', status)
        return
      end if
    end do
  end subroutine check_characters

  function rest_of_line(text, pos) result(rest)
    character(len=*), intent(in) :: text
    integer, intent(in) :: pos
    character(len=:), allocatable :: rest
    integer :: e
    e = index(text(pos:), lf)
    if (e == 0) then
      rest = trim(text(pos:))
    else
      rest = trim(text(pos:pos + e - 2))
    end if
    if (len(rest) > 0) then
      if (rest(len(rest):) == cr) rest = rest(:len(rest) - 1)
    end if
  end function rest_of_line

  !> A value or a piece of text for a message: long ones cut, with their length.
  pure function clipped(text) result(short)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: short
    integer, parameter :: most = 60
    if (len(text) <= most) then
      short = text
    else
      short = text(:most - 20)//'... ('//format_integer(len(text))//' characters)'
    end if
  end function clipped

  !> A value as the user wrote it, for messages: texts in quotes, long ones cut.
  pure function shown_value(value) result(text)
    type(nml_value_t), intent(in) :: value
    character(len=:), allocatable :: text
    if (value%kind == VALUE_TEXT) then
      text = ''''//clipped(value%text)//''''
    else
      text = clipped(value%text)
    end if
  end function shown_value

  subroutine fail(source, line, message, status)
    character(len=*), intent(in) :: source, message
    integer, intent(in) :: line
    type(status_t), intent(inout) :: status
    if (line > 0) then
      call set_status(status, STATUS_INVALID_INPUT, source//':'//format_integer(line)//': '//message)
    else
      call set_status(status, STATUS_INVALID_INPUT, source//': '//message)
    end if
  end subroutine fail

  !> A real number as written: [sign] digits [. digits] [e|d [sign] digits].
  !> Names of non-finite values (NaN, Inf, Infinity) and decimal exponents
  !> beyond +-300 are recognised and refused without converting them.
  subroutine read_real_token(value, x, outcome)
    type(nml_value_t), intent(in) :: value
    real(wp), intent(out) :: x
    integer, intent(out) :: outcome
    character(len=:), allocatable :: t
    integer :: i, mantissa_digits, point_digits, first_nonzero, exponent, decimal_exponent, ios, e
    logical :: seen_point

    x = 0
    outcome = NUMBER_NOT
    if (value%kind /= VALUE_BARE) return
    t = lower(value%text)
    i = 1
    if (len(t) > 0) then
      if (t(1:1) == '+' .or. t(1:1) == '-') i = 2
    end if
    select case (t(i:))
    case ('nan', 'inf', 'infinity')
      outcome = NUMBER_NONFINITE
      return
    end select
    mantissa_digits = 0
    point_digits = 0
    first_nonzero = 0
    seen_point = .false.
    do while (i <= len(t))
      if (t(i:i) == '.') then
        if (seen_point) return
        seen_point = .true.
      else if (index('0123456789', t(i:i)) > 0) then
        mantissa_digits = mantissa_digits + 1
        if (seen_point) point_digits = point_digits + 1
        if (first_nonzero == 0 .and. t(i:i) /= '0') first_nonzero = mantissa_digits
      else
        exit
      end if
      i = i + 1
    end do
    if (mantissa_digits == 0) return
    exponent = 0
    if (i <= len(t)) then
      if (t(i:i) /= 'e' .and. t(i:i) /= 'd') return
      e = i + 1
      if (e <= len(t)) then
        if (t(e:e) == '+' .or. t(e:e) == '-') e = e + 1
      end if
      if (e > len(t)) return
      if (verify(t(e:), '0123456789') /= 0) return
      if (len(t) - e + 1 > 6) then
        exponent = sign(999999, merge(-1, 1, t(i + 1:i + 1) == '-'))
      else
        read (t(i + 1:), *, iostat=ios) exponent
        if (ios /= 0) return
      end if
      t(i:i) = 'e'
    end if
    if (first_nonzero == 0) then   ! all digits zero
      outcome = NUMBER_OK
      return
    end if
    ! the value is d.ddd * 10**decimal_exponent
    decimal_exponent = exponent + (mantissa_digits - point_digits) - first_nonzero
    if (abs(decimal_exponent) > max_decimal_exponent) then
      outcome = NUMBER_TOO_LARGE
      return
    end if
    read (t, *, iostat=ios) x
    if (ios /= 0) return
    outcome = NUMBER_OK
  end subroutine read_real_token

  !> A whole number as written ([sign] digits), within the 64-bit range.
  subroutine read_integer_token(value, i, outcome)
    type(nml_value_t), intent(in) :: value
    integer(int64), intent(out) :: i
    integer, intent(out) :: outcome
    integer :: s, ios
    i = 0
    outcome = NUMBER_NOT
    if (value%kind /= VALUE_BARE .or. len(value%text) == 0) return
    s = 1
    if (value%text(1:1) == '+' .or. value%text(1:1) == '-') s = 2
    if (s > len(value%text)) return
    if (verify(value%text(s:), '0123456789') /= 0) return
    if (len(value%text) - s + 1 > 18) then
      outcome = NUMBER_TOO_LARGE
      return
    end if
    read (value%text, *, iostat=ios) i
    if (ios == 0) outcome = NUMBER_OK
  end subroutine read_integer_token

  !> .true. / .false. / T / F / true / false / .t. / .f. (any case).
  subroutine read_logical_token(value, flag, ok)
    type(nml_value_t), intent(in) :: value
    logical, intent(out) :: flag, ok
    flag = .false.
    ok = .false.
    if (value%kind /= VALUE_BARE) return
    select case (lower(value%text))
    case ('.true.', 't', '.t.', 'true')
      flag = .true.
      ok = .true.
    case ('.false.', 'f', '.f.', 'false')
      ok = .true.
    end select
  end subroutine read_logical_token

  !> Appends to list(:n), doubling its capacity when full (long point lists).
  subroutine push_value(list, n, value)
    type(nml_value_t), allocatable, intent(inout) :: list(:)
    integer, intent(inout) :: n
    type(nml_value_t), intent(in) :: value
    type(nml_value_t), allocatable :: longer(:)
    if (n == size(list)) then
      allocate (longer(2*n))
      longer(:n) = list(:n)
      call move_alloc(longer, list)
    end if
    n = n + 1
    list(n) = value
  end subroutine push_value

end module io_namelist
