!> The one growable series: a run's records (one per output time or event)
!> stored in arrays whose last dimension is the record, grown as the run
!> goes instead of sized by a bound on its duration. A series type extends
!> growable_series_t (the count of records and the room for them) and grows
!> each of its arrays with `resize`; `make_room` says when and to what size
!> (doubling) and fails the run, with a message, before the records would
!> take more than max_series_bytes.
module base_series
  use base_kinds, only: wp
  use base_text, only: format_integer, format_short
  use base_status, only: status_t, set_status, STATUS_SOLVER
  implicit none (type, external)
  private
  public :: growable_series_t, resize, max_series_bytes

  !> Most memory the stored records of one run may take.
  real(wp), parameter :: max_series_bytes = 2.0_wp*1024**3

  type :: growable_series_t
    integer :: n = 0              !< records stored
    integer :: capacity = 0       !< records the arrays have room for
  contains
    procedure :: make_room => series_make_room
  end type growable_series_t

  !> x with room for n records (its last dimension), the first records kept;
  !> the leading extents are given (they are needed on the first call).
  interface resize
    module procedure resize_reals, resize_columns, resize_matrices, resize_blocks, resize_integers
  end interface resize

contains

  !> Before the next record is stored: when the arrays are full, `grown` is
  !> the capacity to resize them to (twice the records, at least `first`),
  !> else 0. `record_bytes` is the memory of one record; a series that would
  !> pass max_series_bytes fails with a message naming `what` and the time
  !> `t` reached (s), and how to record less.
  subroutine series_make_room(self, first, record_bytes, what, t, grown, status)
    class(growable_series_t), intent(in) :: self
    integer, intent(in) :: first
    real(wp), intent(in) :: record_bytes, t
    character(len=*), intent(in) :: what
    integer, intent(out) :: grown
    type(status_t), intent(inout) :: status
    real(wp) :: wanted
    grown = 0
    if (self%n < self%capacity) return
    wanted = max(real(first, wp), 2.0_wp*self%capacity)
    if (self%n + 1 > max_series_bytes/record_bytes .or. self%n >= huge(1)/2) then
      call set_status(status, STATUS_SOLVER, what//': '//format_integer(self%n)//' records stored by t = '// &
                      format_short(t)//' s fill the '//format_short(max_series_bytes/1024**3)//' GB the '// &
                      'records of a run may take; raise &solver output_step or set a shorter duration')
      return
    end if
    grown = int(min(wanted, max_series_bytes/record_bytes, real(huge(1), wp)))
  end subroutine series_make_room

  pure subroutine resize_reals(x, n)
    real(wp), allocatable, intent(inout) :: x(:)
    integer, intent(in) :: n
    real(wp), allocatable :: y(:)
    allocate (y(n))
    if (allocated(x)) y(:min(n, size(x))) = x(:min(n, size(x)))
    call move_alloc(y, x)
  end subroutine resize_reals

  pure subroutine resize_columns(x, rows, n)
    real(wp), allocatable, intent(inout) :: x(:, :)
    integer, intent(in) :: rows, n
    real(wp), allocatable :: y(:, :)
    allocate (y(rows, n))
    if (allocated(x)) y(:, :min(n, size(x, 2))) = x(:, :min(n, size(x, 2)))
    call move_alloc(y, x)
  end subroutine resize_columns

  pure subroutine resize_matrices(x, rows, columns, n)
    real(wp), allocatable, intent(inout) :: x(:, :, :)
    integer, intent(in) :: rows, columns, n
    real(wp), allocatable :: y(:, :, :)
    allocate (y(rows, columns, n))
    if (allocated(x)) y(:, :, :min(n, size(x, 3))) = x(:, :, :min(n, size(x, 3)))
    call move_alloc(y, x)
  end subroutine resize_matrices

  pure subroutine resize_blocks(x, rows, columns, layers, n)
    real(wp), allocatable, intent(inout) :: x(:, :, :, :)
    integer, intent(in) :: rows, columns, layers, n
    real(wp), allocatable :: y(:, :, :, :)
    allocate (y(rows, columns, layers, n))
    if (allocated(x)) y(:, :, :, :min(n, size(x, 4))) = x(:, :, :, :min(n, size(x, 4)))
    call move_alloc(y, x)
  end subroutine resize_blocks

  pure subroutine resize_integers(x, n)
    integer, allocatable, intent(inout) :: x(:)
    integer, intent(in) :: n
    integer, allocatable :: y(:)
    allocate (y(n))
    if (allocated(x)) y(:min(n, size(x))) = x(:min(n, size(x)))
    call move_alloc(y, x)
  end subroutine resize_integers
end module base_series
