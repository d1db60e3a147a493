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

contains

  !> What `write (text, '(es16.8e3)') x` writes.
  pure function scientific_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=16) :: text
    real(wp) :: a, y, whole, fraction_part
    integer(int64) :: digits
    integer :: e, k, tries, direction
    character(len=1), parameter :: numeral(0:9) = ['0', '1', '2', '3', '4', '5', '6', '7', '8', '9']
    if (.not. ieee_is_finite(x)) then   ! tested alone: a NaN compared signals 'invalid'
      write (text, '(es16.8e3)') x
      return
    end if
    a = abs(x)
    if (.not. (a >= 1e-30_wp .and. a < 1e45_wp)) then
      write (text, '(es16.8e3)') x
      return
    end if
    e = floor(log10(a))   ! may be one off next to a power of ten: corrected below
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
        digits = int(whole, int64)
        if (fraction_part > 0.5_wp) digits = digits + 1
        if (digits == 1000000000_int64) then   ! 9.999999995.. rounds up to 1.00000000E(e+1)
          digits = 100000000_int64
          e = e + 1
        end if
        text(1:1) = merge('-', ' ', x < 0)
        do k = 11, 3, -1
          text(k:k) = numeral(mod(digits, 10_int64))
          digits = digits/10
        end do
        text(2:2) = text(3:3)
        text(3:3) = '.'
        text(12:13) = merge('E-', 'E+', e < 0)
        text(14:14) = numeral(abs(e)/100)
        text(15:15) = numeral(mod(abs(e)/10, 10))
        text(16:16) = numeral(mod(abs(e), 10))
        return
      end if
    end do
    write (text, '(es16.8e3)') x
  end function scientific_text

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
