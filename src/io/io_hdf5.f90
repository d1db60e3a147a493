!> HDF5 result files: written under a temporary name and renamed when closed, so
!> a file with the final name is always a finished one (complete, or marked
!> incomplete with what was computed). Every dataset carries a `units` and a
!> `description` attribute; the root carries `status` and `status_message`.
module io_hdf5
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
  use hdf5, only: hid_t, hsize_t, h5open_f, h5fcreate_f, h5fclose_f, H5F_ACC_TRUNC_F, &
                  h5gcreate_f, h5gclose_f, h5lexists_f, h5eset_auto_f
  use h5lt, only: h5ltmake_dataset_double_f, h5ltset_attribute_string_f, &
                  h5ltmake_dataset_string_f, h5ltmake_dataset_int_f
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_IO
  implicit none (type, external)
  private
  public :: result_file_t

  type :: result_file_t
    private
    integer(hid_t) :: file_id = -1
    character(len=:), allocatable :: path, temporary_path
  contains
    procedure :: create => result_file_create
    procedure :: write_vector => result_file_write_vector
    procedure :: write_matrix => result_file_write_matrix
    procedure :: write_array3 => result_file_write_array3
    procedure :: write_integers => result_file_write_integers
    procedure :: write_text => result_file_write_text
    procedure :: set_attribute => result_file_set_attribute
    procedure :: finish => result_file_finish
    procedure :: is_open => result_file_is_open
    procedure :: final_path => result_file_final_path
  end type result_file_t

  interface
    function c_rename(old, new) bind(C, name='rename') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: old(*), new(*)
      integer(c_int) :: rc
    end function c_rename
  end interface

contains

  !> Opens `path`.tmp for writing; fails at once if the folder is not writable.
  subroutine result_file_create(self, path, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: path
    type(status_t), intent(inout) :: status
    integer :: hdferr

    self%path = trim(path)
    self%temporary_path = self%path//'.tmp'
    call h5open_f(hdferr)
    if (hdferr /= 0) then
      call set_status(status, STATUS_IO, 'cannot initialise the HDF5 library')
      return
    end if
    call h5eset_auto_f(0, hdferr)   ! failures come back as statuses, not as HDF5's stack dumps
    call h5fcreate_f(self%temporary_path, H5F_ACC_TRUNC_F, self%file_id, hdferr)
    if (hdferr /= 0) then
      self%file_id = -1
      call set_status(status, STATUS_IO, 'cannot create the result file "'//self%temporary_path// &
                      '" (does its folder exist, and is it writable?)')
      return
    end if
    call h5ltset_attribute_string_f(self%file_id, '/', 'status', 'running', hdferr)
  end subroutine result_file_create

  logical function result_file_is_open(self)
    class(result_file_t), intent(in) :: self
    result_file_is_open = self%file_id >= 0
  end function result_file_is_open

  function result_file_final_path(self) result(path)
    class(result_file_t), intent(in) :: self
    character(len=:), allocatable :: path
    path = self%path
  end function result_file_final_path

  !> Creates the groups along `name` ("/a/b/dataset") that do not exist yet.
  subroutine ensure_groups(file_id, name, hdferr)
    integer(hid_t), intent(in) :: file_id
    character(len=*), intent(in) :: name
    integer, intent(out) :: hdferr
    integer :: i
    logical :: exists
    integer(hid_t) :: group_id

    hdferr = 0
    do i = 2, len(name)
      if (name(i:i) /= '/') cycle
      call h5lexists_f(file_id, name(:i - 1), exists, hdferr)
      if (hdferr /= 0) return
      if (.not. exists) then
        call h5gcreate_f(file_id, name(:i - 1), group_id, hdferr)
        if (hdferr /= 0) return
        call h5gclose_f(group_id, hdferr)
      end if
    end do
  end subroutine ensure_groups

  subroutine describe(self, name, units, description, hdferr, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    integer, intent(inout) :: hdferr
    type(status_t), intent(inout) :: status
    integer :: err
    if (hdferr == 0) call h5ltset_attribute_string_f(self%file_id, name, 'units', units, err)
    if (hdferr == 0) hdferr = err
    if (hdferr == 0) call h5ltset_attribute_string_f(self%file_id, name, 'description', description, err)
    if (hdferr == 0) hdferr = err
    if (hdferr /= 0) call set_status(status, STATUS_IO, 'cannot write dataset "'//name// &
                                     '" to "'//self%temporary_path//'"')
  end subroutine describe

  subroutine result_file_write_vector(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in) :: values(:)
    type(status_t), intent(inout) :: status
    integer :: hdferr
    call ensure_groups(self%file_id, name, hdferr)
    if (hdferr == 0) call h5ltmake_dataset_double_f(self%file_id, name, 1, &
                                                    [int(size(values), hsize_t)], values, hdferr)
    call describe(self, name, units, description, hdferr, status)
  end subroutine result_file_write_vector

  !> A matrix as stored in Fortran: values(3, n) is read by h5py as shape (n, 3).
  subroutine result_file_write_matrix(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in) :: values(:, :)
    type(status_t), intent(inout) :: status
    integer :: hdferr
    call ensure_groups(self%file_id, name, hdferr)
    if (hdferr == 0) call h5ltmake_dataset_double_f(self%file_id, name, 2, &
                                                    int(shape(values), hsize_t), values, hdferr)
    call describe(self, name, units, description, hdferr, status)
  end subroutine result_file_write_matrix

  subroutine result_file_write_array3(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in) :: values(:, :, :)
    type(status_t), intent(inout) :: status
    integer :: hdferr
    call ensure_groups(self%file_id, name, hdferr)
    if (hdferr == 0) call h5ltmake_dataset_double_f(self%file_id, name, 3, &
                                                    int(shape(values), hsize_t), values, hdferr)
    call describe(self, name, units, description, hdferr, status)
  end subroutine result_file_write_array3

  subroutine result_file_write_integers(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    integer, intent(in) :: values(:)
    type(status_t), intent(inout) :: status
    integer :: hdferr
    call ensure_groups(self%file_id, name, hdferr)
    if (hdferr == 0) call h5ltmake_dataset_int_f(self%file_id, name, 1, &
                                                 [int(size(values), hsize_t)], values, hdferr)
    call describe(self, name, units, description, hdferr, status)
  end subroutine result_file_write_integers

  subroutine result_file_write_text(self, name, text, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, text, description
    type(status_t), intent(inout) :: status
    integer :: hdferr
    call ensure_groups(self%file_id, name, hdferr)
    if (hdferr == 0) call h5ltmake_dataset_string_f(self%file_id, name, text, hdferr)
    call describe(self, name, '', description, hdferr, status)
  end subroutine result_file_write_text

  !> A string attribute on an existing object ('/' for the file).
  subroutine result_file_set_attribute(self, object, name, value, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name, value
    type(status_t), intent(inout) :: status
    integer :: hdferr
    call h5ltset_attribute_string_f(self%file_id, object, name, value, hdferr)
    if (hdferr /= 0) call set_status(status, STATUS_IO, 'cannot write attribute "'//name// &
                                     '" of "'//object//'" in "'//self%temporary_path//'"')
  end subroutine result_file_set_attribute

  !> Marks the file complete (or incomplete, with the reason), closes it and
  !> renames it to its final name.
  subroutine result_file_finish(self, complete, message, status)
    class(result_file_t), intent(inout) :: self
    logical, intent(in) :: complete
    character(len=*), intent(in) :: message
    type(status_t), intent(inout) :: status
    integer :: hdferr

    if (self%file_id < 0) return
    if (complete) then
      call h5ltset_attribute_string_f(self%file_id, '/', 'status', 'complete', hdferr)
    else
      call h5ltset_attribute_string_f(self%file_id, '/', 'status', 'incomplete', hdferr)
    end if
    call h5ltset_attribute_string_f(self%file_id, '/', 'status_message', message, hdferr)
    call h5fclose_f(self%file_id, hdferr)
    self%file_id = -1
    if (hdferr /= 0) then
      call set_status(status, STATUS_IO, 'cannot close the result file "'//self%temporary_path//'"')
      return
    end if
    if (c_rename(self%temporary_path//c_null_char, self%path//c_null_char) /= 0) &
      call set_status(status, STATUS_IO, 'cannot rename "'//self%temporary_path//'" to "'// &
                      self%path//'"')
  end subroutine result_file_finish
end module io_hdf5
