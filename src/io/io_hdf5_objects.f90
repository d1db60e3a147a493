!> HDF5 objects by their ids, for io_hdf5 and its submodules: the groups
!> along a path, our string type (variable-length UTF-8) and attributes
!> (replaced if present). HDF5 error codes are returned as they are
!> (hdferr); the callers turn them into statuses.
module io_hdf5_objects
  use, intrinsic :: iso_c_binding, only: c_char, c_null_char, c_ptr, c_loc
  use hdf5, only: hid_t, hsize_t, h5gcreate_f, h5gclose_f, h5lexists_f, h5oopen_f, h5oclose_f, &
                  h5screate_f, h5screate_simple_f, h5sclose_f, H5S_SCALAR_F, h5tcopy_f, h5tset_cset_f, &
                  h5tclose_f, H5T_STRING, H5T_CSET_UTF8_F, h5acreate_f, h5awrite_f, h5aclose_f, &
                  h5aexists_f, h5adelete_f
  implicit none (type, external)
  private
  public :: ensure_groups, utf8_string_type, c_string, write_string_attribute, write_string_attribute_on, &
    write_attribute, link_name_refusal, create_dataspace

contains

  !> Why `name` cannot be one link of a result's group path, or '' if it can:
  !> HDF5 reads a '/' as a path separator ('on/floor' becomes a group 'on'
  !> holding 'floor', and a reader listing the contacts finds 'on') and '.'
  !> as the group itself.
  pure function link_name_refusal(name) result(why)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: why
    why = ''
    if (index(name, '/') > 0) then
      why = 'must not contain ''/'': the name becomes a group in the result file, and HDF5 reads a ''/'' '// &
        'as a path separator'
    else if (trim(name) == '.') then
      why = 'must not be ''.'': HDF5 reads it as the group itself'
    end if
  end function link_name_refusal

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

  !> The memory and file type of our strings: variable length, UTF-8.
  subroutine utf8_string_type(type_id, hdferr)
    integer(hid_t), intent(out) :: type_id
    integer, intent(out) :: hdferr
    call h5tcopy_f(H5T_STRING, type_id, hdferr)
    if (hdferr == 0) call h5tset_cset_f(type_id, H5T_CSET_UTF8_F, hdferr)
  end subroutine utf8_string_type

  !> `text` with a terminating NUL, as the C library reads variable-length strings.
  pure subroutine c_string(text, buffer)
    character(len=*), intent(in) :: text
    character(kind=c_char), allocatable, intent(out) :: buffer(:)
    integer :: i
    allocate (buffer(len(text) + 1))
    do i = 1, len(text)
      buffer(i) = text(i:i)
    end do
    buffer(len(text) + 1) = c_null_char
  end subroutine c_string

  !> A scalar variable-length UTF-8 string attribute (replaced if present).
  subroutine write_string_attribute(file_id, object, name, value, hdferr)
    integer(hid_t), intent(in) :: file_id
    character(len=*), intent(in) :: object, name, value
    integer, intent(out) :: hdferr
    character(kind=c_char), allocatable, target :: buffer(:)
    type(c_ptr), target :: pointers(1)
    integer(hid_t) :: type_id
    integer(hsize_t) :: no_shape(0)
    integer :: err
    call c_string(value, buffer)
    pointers(1) = c_loc(buffer)
    call utf8_string_type(type_id, hdferr)
    if (hdferr /= 0) return
    call write_attribute(file_id, object, name, type_id, no_shape, c_loc(pointers), hdferr)
    call h5tclose_f(type_id, err)
  end subroutine write_string_attribute

  !> A string attribute of an object open as object_id that has none of that name yet.
  subroutine write_string_attribute_on(object_id, name, value, hdferr)
    integer(hid_t), intent(in) :: object_id
    character(len=*), intent(in) :: name, value
    integer, intent(out) :: hdferr
    character(kind=c_char), allocatable, target :: buffer(:)
    type(c_ptr), target :: pointers(1)
    integer(hid_t) :: type_id, space_id, attribute_id
    integer :: err
    call c_string(value, buffer)
    pointers(1) = c_loc(buffer)
    call utf8_string_type(type_id, hdferr)
    if (hdferr /= 0) return
    call h5screate_f(H5S_SCALAR_F, space_id, hdferr)
    if (hdferr == 0) then
      call h5acreate_f(object_id, name, type_id, space_id, attribute_id, hdferr)
      if (hdferr == 0) then
        call h5awrite_f(attribute_id, type_id, c_loc(pointers), hdferr)
        call h5aclose_f(attribute_id, err)
      end if
      call h5sclose_f(space_id, err)
    end if
    call h5tclose_f(type_id, err)
  end subroutine write_string_attribute_on

  !> The one attribute writer: `shape` in Fortran order (size 0: a scalar).
  subroutine write_attribute(file_id, object, name, type_id, shape, buffer, hdferr)
    integer(hid_t), intent(in) :: file_id, type_id
    character(len=*), intent(in) :: object, name
    integer(hsize_t), intent(in) :: shape(:)
    type(c_ptr), intent(in) :: buffer
    integer, intent(out) :: hdferr
    integer(hid_t) :: object_id, space_id, attribute_id
    logical :: exists
    integer :: err
    call h5oopen_f(file_id, object, object_id, hdferr)
    if (hdferr /= 0) return
    call h5aexists_f(object_id, name, exists, hdferr)
    if (hdferr == 0 .and. exists) call h5adelete_f(object_id, name, hdferr)
    if (hdferr == 0) then
      call create_dataspace(shape, space_id, hdferr)
      if (hdferr == 0) then
        call h5acreate_f(object_id, name, type_id, space_id, attribute_id, hdferr)
        if (hdferr == 0) then
          call h5awrite_f(attribute_id, type_id, buffer, hdferr)
          call h5aclose_f(attribute_id, err)
        end if
        call h5sclose_f(space_id, err)
      end if
    end if
    call h5oclose_f(object_id, err)
  end subroutine write_attribute

  !> The dataspace of a dataset or attribute of `shape`: a scalar for no extents.
  subroutine create_dataspace(shape, space_id, hdferr)
    integer(hsize_t), intent(in) :: shape(:)
    integer(hid_t), intent(out) :: space_id
    integer, intent(out) :: hdferr
    if (size(shape) == 0) then
      call h5screate_f(H5S_SCALAR_F, space_id, hdferr)
    else
      call h5screate_simple_f(size(shape), shape, space_id, hdferr)
    end if
  end subroutine create_dataspace
end module io_hdf5_objects
