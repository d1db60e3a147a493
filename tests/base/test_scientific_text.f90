!> scientific_text against the formatted write it replaces, '(es16.8e3)',
!> character for character: random doubles over the whole range, the
!> numbers whose ninth digit is a rounding tie or next to one, the powers of
!> ten and their neighbours (where the exponent changes), and the special
!> values.
program test_scientific_text
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_negative_inf, ieee_quiet_nan, &
                                          ieee_next_after
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_scientific_text, only: scientific_text
  use testing, only: check, finish_tests
  implicit none (type, external)

  integer :: mismatches, k, e, tried
  integer(int64) :: bits
  real(wp) :: u(4), x, p
  character(len=16) :: first_wrong

  mismatches = 0
  tried = 0
  first_wrong = ''
  call random_seed(put=[(7919*k, k = 1, 64)])

  ! random bit patterns: every finite double is as likely as any other
  do k = 1, 200000
    call random_number(u)
    bits = ior(shiftl(int(u(1)*2047, int64), 52), int(u(2)*2.0_wp**26, int64)*2_int64**26 + int(u(3)*2.0_wp**26, int64))
    if (u(4) < 0.5_wp) bits = ibset(bits, 63)
    x = transfer(bits, x)
    call compare(x)
  end do
  ! the sizes a view holds (1e-6 .. 1e4), uniformly in the logarithm
  do k = 1, 200000
    call random_number(u)
    call compare(sign(10.0_wp**(10*u(1) - 6), u(2) - 0.5_wp))
  end do
  ! a ninth digit exactly on a tie (the write's own rounding decides) and
  ! within a few roundings of one, at every scale
  do e = -30, 44
    do k = 1, 200
      call random_number(u)
      x = (aint(1e8_wp + u(1)*9e8_wp) + 0.5_wp)*10.0_wp**(e - 8)
      call compare(x)
      call compare(ieee_next_after(x, 0.0_wp))
      call compare(ieee_next_after(x, huge(x)))
      call compare(-x)
    end do
  end do
  ! 0.5 exactly on a tie in binary: 100000000.5, 123456789.5 and scaled by 2^-n
  do k = 0, 40
    call compare(100000000.5_wp*2.0_wp**(-k))
    call compare(123456789.5_wp*2.0_wp**(-k))
    call compare(999999999.5_wp*2.0_wp**(-k))
  end do
  ! the powers of ten, their neighbours, and numbers that round up to the
  ! next power (9.999999995..)
  do e = -300, 300
    p = 10.0_wp**e
    call compare(p)
    call compare(ieee_next_after(p, 0.0_wp))
    call compare(ieee_next_after(p, huge(p)))
    call compare(9.999999995_wp*10.0_wp**(e - 1))
    call compare(9.9999999949999_wp*10.0_wp**(e - 1))
  end do
  ! the special values
  call compare(0.0_wp)
  call compare(-0.0_wp)
  call compare(huge(x))
  call compare(-huge(x))
  call compare(tiny(x))
  call compare(tiny(x)/3)
  call compare(ieee_value(x, ieee_positive_inf))
  call compare(ieee_value(x, ieee_negative_inf))
  call compare(ieee_value(x, ieee_quiet_nan))
  call compare(1e-30_wp)
  call compare(ieee_next_after(1e-30_wp, 0.0_wp))
  call compare(1e45_wp)
  call compare(ieee_next_after(1e45_wp, 0.0_wp))

  call check(mismatches == 0, 'scientific_text is the write''s text for all of '//trim(count_text(tried))// &
             ' numbers (first mismatch: "'//first_wrong//'")')
  call finish_tests('test_scientific_text')

contains

  subroutine compare(value)
    real(wp), intent(in) :: value
    character(len=16) :: expected
    write (expected, '(es16.8e3)') value
    tried = tried + 1
    if (scientific_text(value) /= expected) then
      mismatches = mismatches + 1
      if (mismatches == 1) first_wrong = expected
    end if
  end subroutine compare

  function count_text(n) result(text)
    integer, intent(in) :: n
    character(len=12) :: text
    write (text, '(i0)') n
  end function count_text
end program test_scientific_text
