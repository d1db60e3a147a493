!> The lines the library programs of tests/library print (library_without_io,
!> library_optimize, library_vehicle, shipped_descriptions), one number a
!> line, `<input> <key> <value>`, for their wrappers to compare with the
!> command's summary of the same input (library_without_io.sh,
!> compare_shipped.py); a value exactly (format_real: the fewest digits that
!> read back as it), a text `TEXT <input> <key> <words>` (the summary's
!> words, or with key `line` a line of its printed summary). A step that
!> fails prints `FAIL <what>: <why>` and counts in `failures`, which the
!> program ends on, or stops the program at once (stop_unless_ok).
module library_lines
  use base_kinds, only: wp
  use base_text, only: format_real, format_integer
  use base_status, only: status_t
  implicit none (type, external)
  private
  public :: put, put_count, put_text, expect_ok, stop_unless_ok, failures

  integer :: failures = 0   !< the steps that failed (expect_ok)

contains

  !> The number x under `key` of input `input`.
  subroutine put(input, key, x)
    character(len=*), intent(in) :: input, key
    real(wp), intent(in) :: x
    print '(a)', input//' '//key//' '//format_real(x)
  end subroutine put

  !> The count n under `key` of input `input`.
  subroutine put_count(input, key, n)
    character(len=*), intent(in) :: input, key
    integer, intent(in) :: n
    print '(a)', input//' '//key//' '//format_integer(n)
  end subroutine put_count

  !> The words under `key` of input `input`.
  subroutine put_text(input, key, words)
    character(len=*), intent(in) :: input, key, words
    print '(a)', 'TEXT '//input//' '//key//' '//words
  end subroutine put_text

  !> A step's status: a failure is printed, naming `what`, and counted.
  subroutine expect_ok(status, what)
    type(status_t), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status%ok()) return
    print '(a)', 'FAIL '//what//': '//status%text()
    failures = failures + 1
  end subroutine expect_ok

  !> A step's status: a failure is printed, naming the input and `what`,
  !> and ends the program (status 1).
  subroutine stop_unless_ok(input, what, status)
    character(len=*), intent(in) :: input, what
    type(status_t), intent(in) :: status
    if (status%ok()) return
    print '(a)', 'FAIL '//input//': '//what//': '//status%text()
    error stop 1
  end subroutine stop_unless_ok
end module library_lines
