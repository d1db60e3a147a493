!> The datasets and attributes of a result file (io_hdf5): the one dataset
!> writer (units, description, long_name; NaN and Inf noted for finish), the
!> typed writers, the attribute setters, and what was written (shape,
!> values, names) for the scales and the XDMF view.
submodule (io_hdf5) io_hdf5_datasets
  use, intrinsic :: iso_c_binding, only: c_char, c_ptr, c_loc
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use hdf5, only: h5sclose_f, h5tclose_f, &
                  H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, h5dcreate_f, h5dwrite_f, h5dread_f, h5dclose_f, &
                  h5dopen_f, h5pcreate_f, h5pset_buffer_f, h5pclose_f, H5P_DATASET_XFER_F
  use io_hdf5_objects, only: ensure_groups, utf8_string_type, c_string, write_string_attribute, &
                             write_string_attribute_on, write_attribute, create_dataspace
  implicit none (type, external)

  !> Conversion buffer of a text dataset's write: one variable-length string
  !> (a pointer and a length) needs 16 bytes
  integer(hsize_t), parameter :: text_transfer_bytes = 4096

contains

  module procedure result_file_write_vector
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status, finite=all(ieee_is_finite(values)))
  end procedure result_file_write_vector

  !> A matrix as stored in Fortran: values(3, n) is read by h5py as shape (n, 3).
  module procedure result_file_write_matrix
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status, finite=all(ieee_is_finite(values)))
  end procedure result_file_write_matrix

  module procedure result_file_write_array3
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status, finite=all(ieee_is_finite(values)))
  end procedure result_file_write_array3

  module procedure result_file_write_integers
    call write_dataset(self, name, H5T_NATIVE_INTEGER, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status)
  end procedure result_file_write_integers

  !> A real scalar dataset (h5py shape ()).
  module procedure result_file_write_scalar
    real(wp), target :: copy
    integer(hsize_t) :: no_shape(0)
    copy = value
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, no_shape, c_loc(copy), units, description, status, &
                       finite=ieee_is_finite(value))
  end procedure result_file_write_scalar

  !> An integer scalar dataset (h5py shape ()), e.g. a count of steps.
  module procedure result_file_write_count
    integer, target :: copy
    integer(hsize_t) :: no_shape(0)
    copy = value
    call write_dataset(self, name, H5T_NATIVE_INTEGER, no_shape, c_loc(copy), units, description, status)
  end procedure result_file_write_count

  !> A text as a scalar variable-length UTF-8 string dataset (units '').
  module procedure result_file_write_text
    character(kind=c_char), allocatable, target :: buffer(:)
    type(c_ptr), target :: pointers(1)
    integer(hid_t) :: type_id, transfer
    integer(hsize_t) :: no_shape(0)
    integer :: hdferr, err
    if (.not. status%ok() .or. self%file_id < 0) return
    call c_string(text, buffer)
    pointers(1) = c_loc(buffer)
    call utf8_string_type(type_id, hdferr)
    ! a transfer buffer for one string: HDF5's default conversion buffers
    ! (1 MiB, zeroed for every write of a variable-length string) cost more
    ! than the rest of the write; the file's bytes are the same
    if (hdferr == 0) call h5pcreate_f(H5P_DATASET_XFER_F, transfer, hdferr)
    if (hdferr == 0) call h5pset_buffer_f(transfer, text_transfer_bytes, hdferr)
    if (hdferr /= 0) then
      call write_failure(self, 'dataset "'//name//'"', status)
      return
    end if
    call write_dataset(self, name, type_id, no_shape, c_loc(pointers), '', description, status, transfer=transfer)
    call h5pclose_f(transfer, err)
    call h5tclose_f(type_id, err)
  end procedure result_file_write_text

  !> A text attribute on an existing object ('/' for the file).
  module procedure set_attribute_text
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    call write_string_attribute(self%file_id, object, name, value, hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end procedure set_attribute_text

  !> A real scalar attribute (the unit belongs in its name, e.g. flow_rate_m3_per_s).
  module procedure set_attribute_real
    real(wp), target :: copy
    integer(hsize_t) :: no_shape(0)
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    call note_finite(self, object//' attribute '//name, ieee_is_finite(value))
    copy = value
    call write_attribute(self%file_id, object, name, H5T_NATIVE_DOUBLE, no_shape, c_loc(copy), hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end procedure set_attribute_real

  !> A real array attribute (h5py shape (n,)).
  module procedure set_attribute_reals
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    call note_finite(self, object//' attribute '//name, all(ieee_is_finite(values)))
    call write_attribute(self%file_id, object, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), &
                         c_loc(values), hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end procedure set_attribute_reals

  !> An integer scalar attribute.
  module procedure set_attribute_integer
    integer, target :: copy
    integer(hsize_t) :: no_shape(0)
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    copy = value
    call write_attribute(self%file_id, object, name, H5T_NATIVE_INTEGER, no_shape, c_loc(copy), hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end procedure set_attribute_integer

  !> The shape (h5py/C order) of a dataset written to this file; size 0 if
  !> it was not written (or is a scalar).
  module procedure result_file_shape_of
    integer :: k
    k = find_written(self, name)
    if (k == 0) then
      allocate (dims(0))
    else
      dims = int(self%written(k)%shape(size(self%written(k)%shape):1:-1))
    end if
  end procedure result_file_shape_of

  !> The values of a double-precision or integer dataset written to this
  !> file (integers as reals), read back in the file's (C) order, the last
  !> index fastest: the rows of an (n, 3) dataset as x1 y1 z1 x2 ...; size 0
  !> if it was not written, is text or cannot be read.
  module procedure result_file_values_of
    integer(hid_t) :: dataset_id
    type(c_ptr) :: buffer
    integer :: k, hdferr, err
    k = find_written(self, name)
    allocate (values(0))
    if (k == 0) return
    if (.not. (self%written(k)%is_real .or. self%written(k)%is_integer)) return
    deallocate (values)
    allocate (values(product(self%written(k)%shape)))
    call h5dopen_f(self%file_id, name, dataset_id, hdferr)
    if (hdferr /= 0) then
      deallocate (values); allocate (values(0))
      return
    end if
    buffer = c_loc(values)
    call h5dread_f(dataset_id, H5T_NATIVE_DOUBLE, buffer, hdferr)
    call h5dclose_f(dataset_id, err)
    if (hdferr /= 0) then
      deallocate (values); allocate (values(0))
    end if
  end procedure result_file_values_of

  !> Whether `name` was written as a double-precision dataset.
  module procedure result_file_is_real
    integer :: k
    k = find_written(self, name)
    is_real = .false.
    if (k > 0) is_real = self%written(k)%is_real
  end procedure result_file_is_real

  !> The units of a dataset written to this file ('' if it was not written).
  module procedure result_file_units_of
    integer :: k
    k = find_written(self, name)
    units = ''
    if (k > 0) then
      if (allocated(self%written(k)%units)) units = self%written(k)%units
    end if
  end procedure result_file_units_of

  !> The datasets written directly in `group` (not in its subgroups), in the
  !> order they were written.
  module procedure result_file_names_in
    character(len=:), allocatable :: prefix, found(:)
    logical, allocatable :: member(:)
    integer :: k, n, width
    prefix = group
    if (prefix(len(prefix):) /= '/') prefix = prefix//'/'
    allocate (member(self%n_written))
    width = 1
    do k = 1, self%n_written
      associate (name => self%written(k)%name)
        member(k) = index(name, prefix) == 1
        if (member(k)) member(k) = index(name(len(prefix) + 1:), '/') == 0
        if (member(k)) width = max(width, len(name))
      end associate
    end do
    ! allocated as a local first: gfortran 12 fails on an allocate of the
    ! deferred-length result of a separate module procedure
    allocate (character(len=width) :: found(count(member)))
    n = 0
    do k = 1, self%n_written
      if (member(k)) then
        n = n + 1; found(n) = self%written(k)%name
      end if
    end do
    call move_alloc(found, names)
  end procedure result_file_names_in

  module procedure find_written
    do k = self%n_written, 1, -1
      if (self%written(k)%name == name) return
    end do
    k = 0
  end procedure find_written

  !> The one dataset writer: `shape` in Fortran order (size 0: a scalar),
  !> `buffer` the values in memory type `type_id`; then units, description and long_name.
  !> `finite` = .false.: the values hold NaN or Inf (see finish).
  !> `transfer`: a dataset transfer property list (default: HDF5's).
  subroutine write_dataset(self, name, type_id, shape, buffer, units, description, status, finite, transfer)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    integer(hid_t), intent(in) :: type_id
    integer(hsize_t), intent(in) :: shape(:)
    type(c_ptr), intent(in) :: buffer
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: finite
    integer(hid_t), intent(in), optional :: transfer
    integer(hid_t) :: space_id, dataset_id
    integer :: hdferr, err

    if (.not. status%ok() .or. self%file_id < 0) return
    if (present(finite)) call note_finite(self, name, finite)
    call ensure_groups(self%file_id, name, hdferr)
    if (hdferr == 0) call create_dataspace(shape, space_id, hdferr)
    if (hdferr == 0) then
      call h5dcreate_f(self%file_id, name, type_id, space_id, dataset_id, hdferr)
      if (hdferr == 0) then
        if (present(transfer)) then
          call h5dwrite_f(dataset_id, type_id, buffer, hdferr, xfer_prp=transfer)
        else
          call h5dwrite_f(dataset_id, type_id, buffer, hdferr)
        end if
        ! the attributes of the new dataset through its open id (no lookup by name)
        if (hdferr == 0) call write_string_attribute_on(dataset_id, 'units', units, hdferr)
        if (hdferr == 0) call write_string_attribute_on(dataset_id, 'description', description, hdferr)
        ! CF readers (xarray, ncview, Panoply) label a variable by long_name
        if (hdferr == 0) call write_string_attribute_on(dataset_id, 'long_name', description, hdferr)
        call h5dclose_f(dataset_id, err)
      end if
      call h5sclose_f(space_id, err)
    end if
    if (hdferr /= 0) then
      call write_failure(self, 'dataset "'//name//'"', status)
      return
    end if
    call remember(self, name, shape)
    self%written(self%n_written)%is_real = type_id == H5T_NATIVE_DOUBLE
    self%written(self%n_written)%is_integer = type_id == H5T_NATIVE_INTEGER
    self%written(self%n_written)%units = units
  end subroutine write_dataset

  !> Remembers the first dataset or attribute that is not finite.
  subroutine note_finite(self, name, finite)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    logical, intent(in) :: finite
    if (.not. finite .and. len(self%nonfinite) == 0) self%nonfinite = name
  end subroutine note_finite

  subroutine remember(self, name, shape)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer(hsize_t), intent(in) :: shape(:)
    type(written_t), allocatable :: grown(:)
    if (.not. allocated(self%written)) allocate (self%written(64))
    if (self%n_written == size(self%written)) then
      allocate (grown(2*size(self%written)))
      grown(:self%n_written) = self%written
      call move_alloc(grown, self%written)
    end if
    self%n_written = self%n_written + 1
    self%written(self%n_written) = written_t(name, shape, spread(.false., 1, size(shape)), .false., .false.)
  end subroutine remember

  subroutine attribute_status(self, object, name, hdferr, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name
    integer, intent(in) :: hdferr
    type(status_t), intent(inout) :: status
    if (hdferr /= 0) call write_failure(self, 'attribute "'//name//'" of "'//object//'"', status)
  end subroutine attribute_status
end submodule io_hdf5_datasets
