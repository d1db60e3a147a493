!> A real as the text of Fortran's ES16.8E3 edit descriptor (nine significant
!> digits, correctly rounded), without formatted I/O: the XDMF views carry
!> tens of thousands of such numbers, and gfortran's formatted write costs
!> some 5000 instructions each.
!>
!> Exact by construction: x times an exact power of ten (at most two
!> roundings, relative error < 2.3e-16) gives y in [1e8, 1e9) within 2.3e-7
!> of the true x 10^-k; rounding y to the nearest integer is therefore the
!> correct rounding unless y's fraction lies within 1e-6 of one half. Those
!> numbers (about two in a million), zero, the non-finite and magnitudes
!> outside 1e-30 .. 1e45 are handed to the formatted write itself, so the
!> text is always the write's.
module base_scientific_text
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: scientific_text

  !> the powers of ten a double holds exactly
  real(wp), parameter :: exact_powers(0:22) = [1e0_wp, 1e1_wp, 1e2_wp, 1e3_wp, 1e4_wp, 1e5_wp, 1e6_wp, &
    1e7_wp, 1e8_wp, 1e9_wp, 1e10_wp, 1e11_wp, 1e12_wp, 1e13_wp, 1e14_wp, 1e15_wp, 1e16_wp, 1e17_wp, &
    1e18_wp, 1e19_wp, 1e20_wp, 1e21_wp, 1e22_wp]
  real(wp), parameter :: near_half = 1e-6_wp   ! > 2.3e-7, the scaled value's largest error
  real(wp), parameter :: log10_of_2 = 0.30102999566398120_wp
  integer, parameter :: zero = iachar('0')

contains

  !> What `write (text, '(es16.8e3)') x` writes.
  pure function scientific_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=16) :: text
    real(wp) :: a, y, whole, fraction_part
    integer :: digits   ! nine of them: below 2^31
    integer :: e, tries, direction, high
    if (.not. ieee_is_finite(x)) then   ! tested alone: a NaN compared signals 'invalid'
      write (text, '(es16.8e3)') x
      return
    end if
    a = abs(x)
    if (.not. (a >= 1e-30_wp .and. a < 1e45_wp)) then
      write (text, '(es16.8e3)') x
      return
    end if
    ! floor(log10(a)) or one less, from the binary exponent b of a normal a (in
    ! [2^b, 2^(b+1)), its stored bits 52..62 hold b + 1023): corrected below;
    ! log10 cost a third of this function
    e = floor(real(ibits(transfer(a, 0_int64), 52, 11) - 1023, wp)*log10_of_2)
    direction = 0
    do tries = 1, 3
      y = scaled(a, 8 - e)
      if (y < 1e8_wp) then
        if (direction > 0) exit   ! y and 10 y on both sides of the range: left to the write
        direction = -1
        e = e - 1
      else if (y >= 1e9_wp) then
        if (direction < 0) exit
        direction = 1
        e = e + 1
      else
        whole = aint(y)
        fraction_part = y - whole   ! exact: y < 2^30
        if (abs(fraction_part - 0.5_wp) < near_half) exit
        digits = int(whole)
        if (fraction_part > 0.5_wp) digits = digits + 1
        if (digits == 1000000000) then   ! 9.999999995.. rounds up to 1.00000000E(e+1)
          digits = 100000000
          e = e + 1
        end if
        high = digits/1000000   ! the first three digits
        text(1:1) = merge('-', ' ', x < 0)
        text(2:2) = achar(zero + high/100)
        text(3:3) = '.'
        text(4:4) = achar(zero + mod(high/10, 10))
        text(5:5) = achar(zero + mod(high, 10))
        call put_three(mod(digits/1000, 1000), text(6:8))
        call put_three(mod(digits, 1000), text(9:11))
        text(12:13) = merge('E-', 'E+', e < 0)
        call put_three(abs(e), text(14:16))
        return
      end if
    end do
    write (text, '(es16.8e3)') x
  end function scientific_text

  !> The three numerals of n (0 <= n < 1000), with leading zeros.
  pure subroutine put_three(n, text)
    integer, intent(in) :: n
    character(len=3), intent(out) :: text
    text(1:1) = achar(zero + n/100)
    text(2:2) = achar(zero + mod(n/10, 10))
    text(3:3) = achar(zero + mod(n, 10))
  end subroutine put_three

  !> a 10^p by at most two exact powers of ten (|p| <= 44; one rounding each;
  !> scientific_text's range gives |p| <= 39)
  pure real(wp) function scaled(a, p) result(y)
    real(wp), intent(in) :: a
    integer, intent(in) :: p
    integer :: rest
    y = a
    rest = p
    if (abs(rest) > 22) then
      y = merge(y*exact_powers(22), y/exact_powers(22), rest > 0)
      rest = rest - sign(22, rest)
    end if
    if (rest >= 0) then
      y = y*exact_powers(rest)
    else
      y = y/exact_powers(-rest)
    end if
  end function scaled
end module base_scientific_text
