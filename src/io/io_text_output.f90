!> Text files written safely: under a temporary name next to the file,
!> renamed into place when complete (a failed write leaves nothing, the old
!> file stays); a device, FIFO or socket is never written. Messages start
!> with the option that named the file (e.g. '--export-stl FILE').
module io_text_output
  use base_status, only: status_t, set_status, STATUS_IO
  use base_kinds, only: wp
  use base_text, only: format_integer
  use io_system, only: create_unique_file, remove_file, rename_file, nonregular_kind, process_id
  implicit none (type, external)
  private
  public :: open_text_output, close_text_output, write_csv_columns

contains

  !> Opens a temporary file next to `path` for formatted writing on `unit`.
  subroutine open_text_output(option, path, unit, temporary, status)
    character(len=*), intent(in) :: option, path
    integer, intent(out) :: unit
    character(len=:), allocatable, intent(out) :: temporary
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: error, what
    character(len=512) :: message
    integer :: ios
    unit = -1
    what = nonregular_kind(path)
    if (len(what) > 0) then
      call set_status(status, STATUS_IO, option//' '//path//': cannot write there: it is '//what)
      return
    end if
    call create_unique_file(path//'.'//format_integer(process_id()), '.tmp', temporary, error)
    if (len(temporary) == 0) then
      call set_status(status, STATUS_IO, option//' '//path//': cannot create a file next to it: '//error)
      return
    end if
    open (newunit=unit, file=temporary, status='replace', action='write', form='formatted', iostat=ios, &
          iomsg=message)
    if (ios /= 0) then
      call remove_file(temporary)
      call set_status(status, STATUS_IO, option//' '//path//': cannot write: '//trim(message))
    end if
  end subroutine open_text_output

  !> Closes `unit` and renames the temporary file onto `path`, unless a write
  !> failed (ios /= 0: the temporary file is removed).
  subroutine close_text_output(option, path, unit, temporary, ios, status)
    character(len=*), intent(in) :: option, path, temporary
    integer, intent(in) :: unit, ios
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: error
    integer :: closed
    logical :: ok
    close (unit, iostat=closed)
    if (ios /= 0 .or. closed /= 0) then
      call remove_file(temporary)
      call set_status(status, STATUS_IO, option//' '//path//': writing failed (disk full?); nothing written')
      return
    end if
    call rename_file(temporary, path, ok, error)
    if (.not. ok) then
      call remove_file(temporary)
      call set_status(status, STATUS_IO, option//' '//path//': cannot rename the finished file into place: '//error)
    end if
  end subroutine close_text_output
  !> A CSV file: a header of `names`, then row i of values(i, :) per line
  !> (nine significant digits).
  subroutine write_csv_columns(option, path, names, values, status)
    character(len=*), intent(in) :: option, path
    character(len=*), intent(in) :: names(:)
    real(wp), intent(in) :: values(:, :)
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: temporary, header
    integer :: unit, ios, i, k
    call open_text_output(option, path, unit, temporary, status)
    if (.not. status%ok()) return
    header = trim(names(1))
    do k = 2, size(names)
      header = header//','//trim(names(k))
    end do
    write (unit, '(a)', iostat=ios) header
    do i = 1, size(values, 1)
      if (ios /= 0) exit
      write (unit, '(*(g0.9, :, ","))', iostat=ios) values(i, :)
    end do
    call close_text_output(option, path, unit, temporary, ios, status)
  end subroutine write_csv_columns
end module io_text_output
