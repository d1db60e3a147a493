!> The error convention of slidesim: anything that can fail returns a status_t.
!>
!> Library code never stops the program; it fills a status with a code and a
!> readable message, and only `app/` turns a status into an exit code.
module base_status
  implicit none (type, external)
  private
  public :: status_t, set_status, prefix_status
  public :: STATUS_OK, STATUS_INVALID_INPUT, STATUS_DOMAIN, STATUS_SOLVER, &
            STATUS_NOT_CONVERGED, STATUS_IO, STATUS_INTERNAL, STATUS_LIMITS_EXCEEDED, status_code_name

  integer, parameter :: STATUS_OK = 0
  integer, parameter :: STATUS_INVALID_INPUT = 1   !< a value outside what is allowed
  integer, parameter :: STATUS_DOMAIN = 2          !< left a parameter domain during a run
  integer, parameter :: STATUS_SOLVER = 3          !< a numerical solver gave up
  integer, parameter :: STATUS_NOT_CONVERGED = 4   !< an iteration did not converge
  integer, parameter :: STATUS_IO = 5              !< a file could not be read or written
  integer, parameter :: STATUS_INTERNAL = 6        !< a broken invariant: a bug
  !> done and the results complete, but a limit was exceeded and the run was
  !> asked to fail on that (--fail-on-limit, &evaluation fail_on_limit)
  integer, parameter :: STATUS_LIMITS_EXCEEDED = 7

  type :: status_t
    integer :: code = STATUS_OK
    character(len=:), allocatable :: message
  contains
    procedure :: ok => status_is_ok
    procedure :: text => status_text
  end type status_t

contains

  elemental logical function status_is_ok(self)
    class(status_t), intent(in) :: self
    status_is_ok = self%code == STATUS_OK
  end function status_is_ok

  !> The message, or "ok".
  pure function status_text(self) result(text)
    class(status_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (allocated(self%message)) then
      text = self%message
    else if (self%code == STATUS_OK) then
      text = 'ok'
    else
      text = status_code_name(self%code)
    end if
  end function status_text

  pure subroutine set_status(status, code, message)
    type(status_t), intent(inout) :: status
    integer, intent(in) :: code
    character(len=*), intent(in) :: message
    status%code = code
    status%message = message
  end subroutine set_status

  !> Adds context in front of an existing message ("where: what").
  pure subroutine prefix_status(status, where)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in) :: where
    if (allocated(status%message)) then
      status%message = where // ': ' // status%message
    else
      status%message = where // ': ' // status_code_name(status%code)
    end if
  end subroutine prefix_status

  pure function status_code_name(code) result(name)
    integer, intent(in) :: code
    character(len=:), allocatable :: name
    select case (code)
    case (STATUS_OK);            name = 'ok'
    case (STATUS_INVALID_INPUT); name = 'invalid input'
    case (STATUS_DOMAIN);        name = 'outside the parameter domain'
    case (STATUS_SOLVER);        name = 'solver failure'
    case (STATUS_NOT_CONVERGED); name = 'not converged'
    case (STATUS_IO);            name = 'input/output error'
    case (STATUS_LIMITS_EXCEEDED); name = 'limits exceeded'
    case default;                name = 'internal error'
    end select
  end function status_code_name
end module base_status
