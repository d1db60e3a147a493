!> Assertions for test programs: count failures, print each with its context,
!> and end with a non-zero exit status if any failed.
module testing
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: check, check_close, check_close_array, finish_tests, failures

  integer :: failures = 0
  integer :: checks = 0

contains

  subroutine check(condition, what)
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. condition) then
      failures = failures + 1
      print '(a)', 'FAIL: '//what
    end if
  end subroutine check

  !> |x - ref| <= atol + rtol |ref|
  subroutine check_close(x, ref, rtol, atol, what)
    real(wp), intent(in) :: x, ref, rtol, atol
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. (abs(x - ref) <= atol + rtol*abs(ref))) then
      failures = failures + 1
      print '(a, 3(a, es24.16))', 'FAIL: '//what, '  got ', x, '  expected ', ref, &
        '  diff ', x - ref
    end if
  end subroutine check_close

  subroutine check_close_array(x, ref, rtol, atol, what)
    real(wp), intent(in) :: x(:), ref(:), rtol, atol
    character(len=*), intent(in) :: what
    integer :: i
    checks = checks + 1
    if (size(x) /= size(ref)) then
      failures = failures + 1
      print '(a, 2i8)', 'FAIL: '//what//' sizes differ', size(x), size(ref)
      return
    end if
    do i = 1, size(x)
      if (.not. (abs(x(i) - ref(i)) <= atol + rtol*abs(ref(i)))) then
        failures = failures + 1
        print '(a, i0, 3(a, es24.16))', 'FAIL: '//what//' at index ', i, '  got ', x(i), &
          '  expected ', ref(i), '  diff ', x(i) - ref(i)
        return
      end if
    end do
  end subroutine check_close_array

  !> Prints the tally and stops with status 1 if anything failed.
  subroutine finish_tests(name)
    character(len=*), intent(in) :: name
    print '(a, ": ", i0, " checks, ", i0, " failed")', name, checks, failures
    if (failures > 0) error stop 1
  end subroutine finish_tests
end module testing
