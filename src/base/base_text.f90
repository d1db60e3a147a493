!> Numbers and words as text for messages: the shortest form that reads back
!> exactly, so a message shows the value as the user typed it.
module base_text
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: format_real, format_short, format_vector, format_integer, lower

contains

  !> The shortest text that reads back as x (so messages show what was typed).
  pure function format_real(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=40) :: buffer
    real(wp) :: back
    integer :: digits, ios, e
    if (ieee_is_nan(x)) then
      text = 'NaN'
      return
    else if (.not. ieee_is_finite(x)) then
      text = merge(' Inf', '-Inf', x > 0)
      text = trim(adjustl(text))
      return
    end if
    do digits = 1, 17
      write (buffer, '(es40.' // digit_text(digits - 1) // ')') x
      read (buffer, *, iostat=ios) back
      if (ios == 0 .and. back == x) exit
    end do
    text = trim(adjustl(buffer))
    e = index(text, '.E')
    if (e > 0) text = text(:e)//'0'//text(e + 1:)   ! 1.E-14 -> 1.0E-14
    ! Plain notation for moderate magnitudes: 2.5E+00 -> 2.5, 1.0E-03 stays.
    e = exponent10(x)
    if (e >= -3 .and. e <= 6) then
      write (buffer, '(f40.' // digit_text(max(digits - 1 - e, 1)) // ')') x
      text = trim(adjustl(buffer))
      do while (len(text) > 2 .and. text(len(text):len(text)) == '0' .and. &
                text(len(text) - 1:len(text) - 1) /= '.')
        text = text(:len(text) - 1)
      end do
    end if
  end function format_real

  pure integer function exponent10(x)
    real(wp), intent(in) :: x
    if (x == 0) then
      exponent10 = 0
    else
      exponent10 = floor(log10(abs(x)))
    end if
  end function exponent10

  pure function digit_text(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    character(len=8) :: buffer
    write (buffer, '(i0)') i
    text = trim(buffer)
  end function digit_text

  pure function format_vector(x) result(text)
    real(wp), intent(in) :: x(:)
    character(len=:), allocatable :: text
    integer :: i
    text = '['
    do i = 1, size(x)
      text = text//format_real(x(i))
      if (i < size(x)) text = text//', '
    end do
    text = text//']'
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
      text = trim(adjustl(buffer))
    end if
  end function format_short

  pure function format_integer(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    character(len=16) :: buffer
    write (buffer, '(i0)') i
    text = trim(buffer)
  end function format_integer
end module base_text
