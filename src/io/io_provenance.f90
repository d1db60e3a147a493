!> Where and when a result was made: the UTC time and the host name, from the
!> C library (time, gmtime, strftime, gethostname), and the git commit the
!> program was built from.
module io_provenance
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_size_t, c_long, c_ptr, c_null_char, &
                                         c_associated
  implicit none (type, external)
  private
  public :: utc_timestamp, host_name, set_build_commit, build_commit

  ! Set once by the program at its start (app/: its build stamps the commit,
  ! so a new commit relinks the program alone, not every test and
  ! benchmark); a program of its own on the library writes 'unknown'
  ! unless it sets it.
  character(len=:), allocatable, save :: commit_of_build

  interface
    function c_time(t) bind(C, name='time') result(now)
      import :: c_long
      integer(c_long), intent(inout) :: t
      integer(c_long) :: now
    end function c_time
    function c_gmtime(t) bind(C, name='gmtime') result(tm)
      import :: c_long, c_ptr
      integer(c_long), intent(in) :: t
      type(c_ptr) :: tm
    end function c_gmtime
    function c_strftime(buffer, size, format, tm) bind(C, name='strftime') result(n)
      import :: c_char, c_size_t, c_ptr
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_size_t), value :: size
      character(kind=c_char), intent(in) :: format(*)
      type(c_ptr), value :: tm
      integer(c_size_t) :: n
    end function c_strftime
    function c_gethostname(name, size) bind(C, name='gethostname') result(rc)
      import :: c_char, c_size_t, c_int
      character(kind=c_char), intent(out) :: name(*)
      integer(c_size_t), value :: size
      integer(c_int) :: rc
    end function c_gethostname
  end interface

contains

  !> Records the git commit of the program's build for the result files'
  !> provenance (call once, before any run).
  subroutine set_build_commit(commit)
    character(len=*), intent(in) :: commit
    commit_of_build = commit
  end subroutine set_build_commit

  !> The git commit set by set_build_commit, or 'unknown'.
  function build_commit() result(commit)
    character(len=:), allocatable :: commit
    commit = 'unknown'
    if (allocated(commit_of_build)) commit = commit_of_build
  end function build_commit

  !> The current UTC time as ISO 8601, e.g. 2026-11-24T02:03:04Z.
  function utc_timestamp() result(text)
    character(len=:), allocatable :: text
    character(kind=c_char) :: buffer(32)
    integer(c_long) :: now
    type(c_ptr) :: tm
    integer(c_size_t) :: n
    now = 0
    now = c_time(now)
    tm = c_gmtime(now)
    n = 0
    if (c_associated(tm)) n = c_strftime(buffer, size(buffer, kind=c_size_t), '%Y-%m-%dT%H:%M:%SZ'//c_null_char, tm)
    text = from_c(buffer, int(n))
    if (n == 0) text = 'unknown'
  end function utc_timestamp

  !> The name of this machine, or 'unknown'.
  function host_name() result(text)
    character(len=:), allocatable :: text
    character(kind=c_char) :: buffer(256)
    integer :: n
    buffer = c_null_char
    if (c_gethostname(buffer, size(buffer, kind=c_size_t) - 1) /= 0) then
      text = 'unknown'
      return
    end if
    n = findloc(buffer, c_null_char, dim=1) - 1
    text = from_c(buffer, n)
    if (n <= 0) text = 'unknown'
  end function host_name

  pure function from_c(buffer, n) result(text)
    character(kind=c_char), intent(in) :: buffer(:)
    integer, intent(in) :: n
    character(len=max(n, 0)) :: text
    integer :: i
    do i = 1, n
      text(i:i) = buffer(i)
    end do
  end function from_c
end module io_provenance
