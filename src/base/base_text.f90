!> Numbers and words as text for messages: the shortest form that reads back
!> exactly, so a message shows the value as the user typed it.
module base_text
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: format_real, format_short, format_vector, format_integer, format_with, lower
  public :: next_data_line, append_item

contains

  !> Appends `item` to the list `text`, after `separator` unless the list is
  !> still empty: 'a', 'a; b', 'a; b; c'.
  pure subroutine append_item(text, item, separator)
    character(len=:), allocatable, intent(inout) :: text
    character(len=*), intent(in) :: item, separator
    if (len(text) > 0) text = text//separator
    text = text//item
  end subroutine append_item

  !> The shortest text that reads back as x (so messages show what was typed).
  pure function format_real(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=40) :: buffer
    integer :: digits, e, low, high
    logical :: away   ! the digits are rounded away from zero, not to nearest
    if (ieee_is_nan(x)) then
      text = 'NaN'
      return
    else if (.not. ieee_is_finite(x)) then
      text = merge(' Inf', '-Inf', x > 0)
      text = trim(adjustl(text))
      return
    end if
    ! The fewest significant digits (1 to 17; 17 always read back) by
    ! bisection: correctly rounded to d + 1 digits is at least as close to x
    ! as to d digits, and the interval that reads back as x is symmetric
    ! about x unless x is a power of two, so "reads back" holds from the
    ! fewest digits on. A power of two (its interval below is half the one
    ! above) is searched digit by digit, and where the nearest d digits lie
    ! below it and do not read back, the d digits next above it still may
    ! (2**-1017: 7.120236347223045E-307, not the nearest ...044, and not 17
    ! digits).
    away = .false.
    if (fraction(abs(x)) == 0.5_wp) then
      do digits = 1, 17
        call write_digits(x, digits, buffer)
        if (reads_back(buffer, x)) exit
        call write_digits(x, digits, buffer, away=.true.)
        away = reads_back(buffer, x)
        if (away) exit
      end do
    else
      low = 0    ! fewer digits than the fewest that read back
      high = 17  ! reads back
      do while (high - low > 1)
        digits = (low + high)/2
        call write_digits(x, digits, buffer)
        if (reads_back(buffer, x)) then
          high = digits
        else
          low = digits
        end if
      end do
      if (digits /= high) call write_digits(x, high, buffer)
      digits = high
    end if
    text = trim(adjustl(buffer))
    e = index(text, '.E')
    if (e > 0) text = text(:e)//'0'//text(e + 1:)   ! 1.E-14 -> 1.0E-14
    ! Plain notation for moderate magnitudes: 2.5E+00 -> 2.5, 1.0E-04 stays.
    ! The exponent is the text's (floor(log10|x|) in floating point is 6 for
    ! 999999.9999999999, and 16 digits after the point then round to
    ! 1000000.0, another number); the same digits at the same places.
    read (text(index(text, 'E') + 1:), *) e
    if (e >= -3 .and. e <= 6) then
      write (buffer, '(' // rounding(x, away) // 'f40.' // format_integer(max(digits - 1 - e, 1)) // ')') x
      text = trim(adjustl(buffer))
      do while (len(text) > 2 .and. text(len(text):len(text)) == '0' .and. &
                text(len(text) - 1:len(text) - 1) /= '.')
        text = text(:len(text) - 1)
      end do
    end if
  end function format_real

  !> x in exponent form with `digits` significant digits (left-justified),
  !> rounded to nearest, or with `away` away from zero.
  pure subroutine write_digits(x, digits, buffer, away)
    real(wp), intent(in) :: x
    integer, intent(in) :: digits
    character(len=*), intent(out) :: buffer
    logical, intent(in), optional :: away
    write (buffer, '(' // rounding(x, away) // 'es40.' // format_integer(digits - 1) // ')') x
    buffer = with_exponent_letter(trim(adjustl(buffer)))
  end subroutine write_digits

  !> The rounding edit descriptor: none (the default, to nearest), or away
  !> from zero (up for positive x, down for negative).
  pure function rounding(x, away) result(mode)
    real(wp), intent(in) :: x
    logical, intent(in), optional :: away
    character(len=3) :: mode
    mode = ''
    if (present(away)) then
      if (away) mode = merge('RU,', 'RD,', x > 0)
    end if
  end function rounding

  !> An exponent form always with its E: Fortran writes an exponent of three
  !> digits without it (1.8+308, 4.9-324), which is no number in JSON and an
  !> odd one in a message.
  pure function with_exponent_letter(text) result(fixed)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: fixed
    integer :: sign_at
    sign_at = scan(text, '+-', back=.true.)   ! the exponent's sign (not a leading minus)
    if (index(text, 'E') > 0 .or. sign_at <= 1) then
      fixed = text
    else
      fixed = text(:sign_at - 1)//'E'//text(sign_at:)
    end if
  end function with_exponent_letter

  !> Does the exponent form in `buffer` read back as x? A text beyond the
  !> largest double (few digits of x near huge round up: 2.E+308) does not,
  !> and is not read: reading it overflows, which Debug builds trap (inside
  !> strtod).
  pure logical function reads_back(buffer, x)
    character(len=*), intent(in) :: buffer
    real(wp), intent(in) :: x
    real(wp) :: back
    integer :: ios
    reads_back = .false.
    if (beyond_huge(buffer)) return
    read (buffer, *, iostat=ios) back
    reads_back = ios == 0 .and. back == x
  end function reads_back

  !> Is the exponent form (write_digits, at most 17 digits) at least huge + half its
  !> last place, 1.79769313486231580793...E+308 (what reads as Inf)? With
  !> at most 17 digits: exponent 308 and digits above 17976931348623158.
  pure logical function beyond_huge(buffer)
    character(len=*), intent(in) :: buffer
    character(len=*), parameter :: huge_digits = '17976931348623158'
    character(len=len(huge_digits)) :: digits
    integer :: e, i, n
    beyond_huge = .false.
    e = index(buffer, 'E')
    if (e == 0) return
    if (buffer(e + 1:) /= '+308') return
    digits = repeat('0', len(digits))
    n = 0
    do i = 1, e - 1
      if (buffer(i:i) >= '0' .and. buffer(i:i) <= '9' .and. n < len(digits)) then
        n = n + 1
        digits(n:n) = buffer(i:i)
      end if
    end do
    beyond_huge = digits > huge_digits   ! (equal length: lexical order is numeric order)
  end function beyond_huge

  !> '[x1, x2, ...]'; without the brackets (`brackets` = .false.) as a
  !> namelist gives a vector in a message: 'x1, x2, ...'.
  pure function format_vector(x, brackets) result(text)
    real(wp), intent(in) :: x(:)
    logical, intent(in), optional :: brackets
    character(len=:), allocatable :: text
    integer :: i
    logical :: bracketed
    bracketed = .true.
    if (present(brackets)) bracketed = brackets
    text = ''
    do i = 1, size(x)
      text = text//format_real(x(i))
      if (i < size(x)) text = text//', '
    end do
    if (bracketed) text = '['//text//']'
  end function format_vector

  pure function lower(text) result(low)
    character(len=*), intent(in) :: text
    character(len=len(text)) :: low
    integer :: i, c
    low = text
    do i = 1, len(text)
      c = iachar(text(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) low(i:i) = achar(c + 32)
    end do
  end function lower

  !> A computed number for messages: 6 significant digits, plain where that
  !> reads well (0.001 <= |x| < 1e6), else exponent form.
  pure function format_short(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buffer
    integer :: k
    if (ieee_is_nan(x) .or. .not. ieee_is_finite(x)) then
      text = format_real(x)
    else if (x == 0) then
      text = '0'
    else if (abs(x) >= 1e-3_wp .and. abs(x) < 1e6_wp) then
      write (buffer, '(f0.6)') x
      k = len_trim(buffer)
      do while (k > 1 .and. buffer(k:k) == '0')
        k = k - 1
      end do
      if (buffer(k:k) == '.') k = k - 1
      text = buffer(:k)
      if (text(1:1) == '.') text = '0'//text
      if (text(1:2) == '-.') text = '-0'//text(2:)
    else
      write (buffer, '(es12.5)') x
      text = with_exponent_letter(trim(adjustl(buffer)))
    end if
  end function format_short

  !> x written with one Fortran edit descriptor (`edit`: f11.3, es12.4), its
  !> field kept (the columns of printed tables), trailing blanks dropped.
  pure function format_with(x, edit) result(text)
    real(wp), intent(in) :: x
    character(len=*), intent(in) :: edit
    character(len=:), allocatable :: text
    character(len=40) :: buffer
    write (buffer, '('//edit//')') x
    text = trim(buffer)
  end function format_with

  pure function format_integer(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    character(len=20) :: buffer
    integer(int64) :: rest
    integer :: first
    ! digits by division (an internal write costs ~20 times as much)
    rest = abs(int(i, int64))
    first = len(buffer) + 1
    do
      first = first - 1
      buffer(first:first) = achar(iachar('0') + int(mod(rest, 10_int64)))
      rest = rest/10
      if (rest == 0) exit
    end do
    if (i < 0) then
      first = first - 1
      buffer(first:first) = '-'
    end if
    text = buffer(first:)
  end function format_integer

  !> The next line of `text` from position `start` that holds data: a carriage
  !> return before the line end is dropped, the line is trimmed on both sides,
  !> blank lines and lines starting with # are passed over. `line_no` counts
  !> every line passed (the file's line number of the line returned); false at
  !> the end of the text.
  logical function next_data_line(text, start, line_no, line) result(found)
    character(len=*), intent(in) :: text
    integer, intent(inout) :: start, line_no
    character(len=:), allocatable, intent(out) :: line
    integer :: next
    found = .false.
    do while (start <= len(text))
      next = index(text(start:), new_line('a'))
      if (next == 0) then
        line = text(start:)
        start = len(text) + 1
      else
        line = text(start:start + next - 2)
        start = start + next
      end if
      line_no = line_no + 1
      if (len(line) > 0) then
        if (line(len(line):) == achar(13)) line = line(:len(line) - 1)
      end if
      line = trim(adjustl(line))
      if (len(line) == 0) cycle
      if (line(1:1) == '#') cycle
      found = .true.
      return
    end do
  end function next_data_line
end module base_text
