!> HDF5 result files, written the way h5py, xarray and ParaView users expect
!> (the layout and its version: docs/outputs.md).
!>
!> Life cycle: `create` opens a new temporary file `<path>.<pid>.XXXXXX.tmp`
!> (a unique name in the result's folder: two runs on one path never share
!> it); `finish` marks the root attribute `status` complete or incomplete,
!> closes and renames it to `<path>` in one step, so a file with the final
!> name is always a finished one. A run killed on the way leaves only its
!> temporary file. When a write fails (a full disk, the file-size limit) the
!> temporary file is deleted and nothing is kept (STATUS_IO). A device, FIFO
!> or socket found at the final name (or its companion's) is never replaced:
!> the results stay in the temporary file(s), named in the message (STATUS_IO).
!> Numbers that are not finite (NaN, Inf) are written but make `finish` mark
!> the file incomplete, naming the first such dataset (STATUS_DOMAIN): no file marked
!> complete holds one.
!>
!> Conventions every writer here keeps, so no caller has to:
!> - strings (attributes and text datasets) are scalar variable-length UTF-8,
!>   so h5py returns `str` (`f.attrs['status'] == 'complete'`);
!> - numbers are numbers: `set_attribute` takes text, a real, a real array or
!>   an integer; `write_scalar`/`write_count` make scalar datasets (shape ());
!> - every dataset has `units` (UDUNITS-2 and pint syntax: 'm', 'm/s', 'm/s^2',
!>   'm^-1', 'rad', '1', 'J', 'kg m^2'; no '1/m', which UDUNITS-2 refuses),
!>   `description` and `long_name` (the same text: the CF attribute);
!> - arrays are stored as in Fortran: values(3, n) is read by h5py as (n, 3),
!>   so the sample index (time, arc length) is numpy axis 0;
!> - `make_scale` turns a 1-d dataset into a dimension scale and `attach_scale`
!>   attaches it to every dataset written under a group whose numpy axis (0 by
!>   default) has the scale's length, so xarray and HDFView show coordinates;
!> - `write_provenance` writes what made the file (version, git commit,
!>   compiler and flags, UTC time, host, the input text and its SHA-256).
module io_hdf5
  use, intrinsic :: iso_c_binding, only: c_char, c_null_char, c_ptr, c_loc
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use hdf5, only: hid_t, hsize_t, h5open_f, h5dont_atexit_f, h5fcreate_f, h5fclose_f, H5F_ACC_TRUNC_F, &
                  h5gcreate_f, h5gclose_f, h5lexists_f, h5eset_auto_f, h5oopen_f, h5oclose_f, &
                  h5screate_f, h5screate_simple_f, h5sclose_f, H5S_SCALAR_F, &
                  h5tcopy_f, h5tset_size_f, h5tset_cset_f, h5tclose_f, H5T_STRING, H5T_CSET_UTF8_F, &
                  H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, &
                  h5acreate_f, h5awrite_f, h5aclose_f, h5aexists_f, h5adelete_f, &
                  h5dcreate_f, h5dwrite_f, h5dread_f, h5dclose_f, h5dopen_f, &
                  h5pcreate_f, h5pset_buffer_f, h5pclose_f, H5P_DATASET_XFER_F
  use h5ds, only: h5dsset_scale_f, h5dsattach_scale_f
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_IO, STATUS_DOMAIN, STATUS_INVALID_INPUT
  use base_sha256, only: sha256_hex
  use base_version, only: slidesim_version, slidesim_compiler, slidesim_compiler_options
  use base_build_commit, only: slidesim_git_commit
  use io_provenance, only: utc_timestamp, host_name
  use io_system, only: remove_file, rename_file, system_error_text, nonregular_kind
  use io_output_files, only: temporary_beside, text_output_t
  implicit none (type, external)
  private
  public :: result_file_t, result_layout_version, units_per_second, run_outcome

  !> Version of the layout in docs/outputs.md: raised when an existing name,
  !> shape or unit changes; new groups and datasets do not raise it.
  integer, parameter :: result_layout_version = 1

  !> Conversion buffer of a text dataset's write: one variable-length string
  !> (a pointer and a length) needs 16 bytes
  integer(hsize_t), parameter :: text_transfer_bytes = 4096

  !> A dataset written so far: its shape (Fortran order) for attach_scale.
  type :: written_t
    character(len=:), allocatable :: name
    integer(hsize_t), allocatable :: shape(:)
    logical, allocatable :: scaled(:)    ! per Fortran dimension: a scale is attached
    logical :: is_scale = .false.
    logical :: is_real = .false.         ! a double-precision dataset (else integer or text)
  end type written_t

  type :: result_file_t
    private
    integer(hid_t) :: file_id = -1
    character(len=:), allocatable :: path, temporary_path
    type(written_t), allocatable :: written(:)
    integer :: n_written = 0
    logical :: write_failed = .false.              !< a write failed: the file is not kept
    character(len=:), allocatable :: nonfinite     !< the first dataset with NaN or Inf ('' none)
    !> a text file kept with the result (its XDMF view): written by finish
    !> before the result is renamed, so that both or neither are kept
    character(len=:), allocatable :: companion_path, companion_text
  contains
    procedure :: create => result_file_create
    procedure :: write_provenance => result_file_write_provenance
    procedure :: write_vector => result_file_write_vector
    procedure :: write_matrix => result_file_write_matrix
    procedure :: write_array3 => result_file_write_array3
    procedure :: write_integers => result_file_write_integers
    procedure :: write_scalar => result_file_write_scalar
    procedure :: write_count => result_file_write_count
    procedure :: write_text => result_file_write_text
    procedure, private :: set_attribute_text, set_attribute_real, set_attribute_reals, set_attribute_integer
    generic :: set_attribute => set_attribute_text, set_attribute_real, set_attribute_reals, set_attribute_integer
    procedure :: shape_of => result_file_shape_of
    procedure :: values_of => result_file_values_of
    procedure :: names_in => result_file_names_in
    procedure :: is_real => result_file_is_real
    procedure :: make_scale => result_file_make_scale
    procedure :: attach_scale => result_file_attach_scale
    procedure :: attach_components => result_file_attach_components
    procedure :: add_companion => result_file_add_companion
    procedure :: finish => result_file_finish
    procedure :: is_open => result_file_is_open
    procedure :: final_path => result_file_final_path
    procedure :: temporary_name => result_file_temporary_name
  end type result_file_t


contains

  !> Opens a new temporary file next to `path` for writing; fails at once if
  !> the folder is not writable.
  subroutine result_file_create(self, path, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: path
    type(status_t), intent(inout) :: status
    integer :: hdferr
    character(len=:), allocatable :: error

    self%path = trim(path)
    self%n_written = 0
    self%write_failed = .false.
    self%nonfinite = ''
    call temporary_beside(self%path, self%temporary_path, error)
    if (len(self%temporary_path) == 0) then
      call set_status(status, STATUS_IO, 'cannot create a file next to the result file "'//self%path// &
                      '": '//error//' (does its folder exist, and is it writable?)')
      return
    end if
    call h5dont_atexit_f(hdferr)   ! fails harmlessly once the library is running
    call h5open_f(hdferr)
    if (hdferr /= 0) then
      call remove_file(self%temporary_path)
      call set_status(status, STATUS_IO, 'cannot initialise the HDF5 library')
      return
    end if
    call h5eset_auto_f(0, hdferr)   ! failures come back as statuses, not as HDF5's stack dumps
    call h5fcreate_f(self%temporary_path, H5F_ACC_TRUNC_F, self%file_id, hdferr)
    if (hdferr /= 0) then
      self%file_id = -1
      error = system_error_text()   ! (before remove_file can change errno)
      if (len(error) > 0) error = ': '//error
      call remove_file(self%temporary_path)
      call set_status(status, STATUS_IO, 'cannot create the result file "'//self%temporary_path//'"'//error// &
                      ' (is the disk full, is the folder writable?)')
      return
    end if
    call write_string_attribute(self%file_id, '/', 'status', 'running', hdferr)
  end subroutine result_file_create

  logical function result_file_is_open(self)
    class(result_file_t), intent(in) :: self
    result_file_is_open = self%file_id >= 0
  end function result_file_is_open

  !> The result file's name, or what happened to it if it was not kept.
  function result_file_final_path(self) result(path)
    class(result_file_t), intent(in) :: self
    character(len=:), allocatable :: path
    path = self%path
    if (self%write_failed) path = 'none: '//self%path//' could not be written'
  end function result_file_final_path

  !> The temporary file written while the file is open ('' before create).
  function result_file_temporary_name(self) result(path)
    class(result_file_t), intent(in) :: self
    character(len=:), allocatable :: path
    path = ''
    if (allocated(self%temporary_path)) path = self%temporary_path
  end function result_file_temporary_name

  !> The root attributes saying what made the file, and the input: scenario,
  !> title, layout_version, slidesim_version, git_commit, compiler,
  !> compiler_options, created_utc, host, input_sha256 (of the bytes of
  !> /input/namelist); the datasets /input/namelist and /input/source.
  subroutine result_file_write_provenance(self, scenario, title, input_source, input_text, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: scenario, title, input_source, input_text
    type(status_t), intent(inout) :: status
    call self%set_attribute('/', 'scenario', scenario, status)
    call self%set_attribute('/', 'title', title, status)
    call self%set_attribute('/', 'layout_version', result_layout_version, status)
    call self%set_attribute('/', 'slidesim_version', slidesim_version, status)
    call self%set_attribute('/', 'git_commit', slidesim_git_commit(), status)
    call self%set_attribute('/', 'compiler', slidesim_compiler, status)
    call self%set_attribute('/', 'compiler_options', slidesim_compiler_options, status)
    call self%set_attribute('/', 'created_utc', utc_timestamp(), status)
    call self%set_attribute('/', 'host', host_name(), status)
    call self%set_attribute('/', 'input_sha256', sha256_hex(input_text), status)
    call self%write_text('/input/namelist', input_text, 'the input namelist text of this run', status)
    call self%write_text('/input/source', input_source, 'where the input came from (a path, '// &
                         '<built-in default> or builtin:<name>)', status)
  end subroutine result_file_write_provenance

  !> The unit of a rate or, with power = 2, of an acceleration:
  !> 'm' -> 'm/s' (or 'm/s^2'), '1' -> 's^-1' (UDUNITS-2 does not read '1/s').
  pure function units_per_second(units, power) result(rate)
    character(len=*), intent(in) :: units
    integer, intent(in), optional :: power
    character(len=:), allocatable :: rate
    integer :: p
    p = 1
    if (present(power)) p = power
    if (units == '1') then
      rate = merge('s^-1', 's^-2', p == 1)
    else
      rate = units//trim(merge('/s  ', '/s^2', p == 1))
    end if
  end function units_per_second

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
    if (hdferr == 0) then
      if (size(shape) == 0) then
        call h5screate_f(H5S_SCALAR_F, space_id, hdferr)
      else
        call h5screate_simple_f(size(shape), shape, space_id, hdferr)
      end if
    end if
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
  end subroutine write_dataset

  !> Remembers the first dataset or attribute that is not finite.
  subroutine note_finite(self, name, finite)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    logical, intent(in) :: finite
    if (.not. finite .and. len(self%nonfinite) == 0) self%nonfinite = name
  end subroutine note_finite

  !> A write failed (a full disk, the file-size limit, an I/O error): the
  !> file will not be kept; the message says what and why.
  subroutine write_failure(self, what, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: what
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: why
    self%write_failed = .true.
    why = system_error_text()
    if (len(why) > 0) why = ': '//why
    call set_status(status, STATUS_IO, 'cannot write '//what//' to the result file "'//self%temporary_path// &
                    '"'//why//' (is the disk full?); nothing is kept')
  end subroutine write_failure

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

  subroutine result_file_write_vector(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in), target, contiguous :: values(:)
    type(status_t), intent(inout) :: status
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status, finite=all(ieee_is_finite(values)))
  end subroutine result_file_write_vector

  !> A matrix as stored in Fortran: values(3, n) is read by h5py as shape (n, 3).
  subroutine result_file_write_matrix(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in), target, contiguous :: values(:, :)
    type(status_t), intent(inout) :: status
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status, finite=all(ieee_is_finite(values)))
  end subroutine result_file_write_matrix

  subroutine result_file_write_array3(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in), target, contiguous :: values(:, :, :)
    type(status_t), intent(inout) :: status
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status, finite=all(ieee_is_finite(values)))
  end subroutine result_file_write_array3

  subroutine result_file_write_integers(self, name, values, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    integer, intent(in), target, contiguous :: values(:)
    type(status_t), intent(inout) :: status
    call write_dataset(self, name, H5T_NATIVE_INTEGER, shape(values, kind=hsize_t), c_loc(values), units, &
                       description, status)
  end subroutine result_file_write_integers

  !> A real scalar dataset (h5py shape ()).
  subroutine result_file_write_scalar(self, name, value, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    real(wp), target :: copy
    integer(hsize_t) :: no_shape(0)
    copy = value
    call write_dataset(self, name, H5T_NATIVE_DOUBLE, no_shape, c_loc(copy), units, description, status, &
                       finite=ieee_is_finite(value))
  end subroutine result_file_write_scalar

  !> An integer scalar dataset (h5py shape ()), e.g. a count of steps.
  subroutine result_file_write_count(self, name, value, units, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, units, description
    integer, intent(in) :: value
    type(status_t), intent(inout) :: status
    integer, target :: copy
    integer(hsize_t) :: no_shape(0)
    copy = value
    call write_dataset(self, name, H5T_NATIVE_INTEGER, no_shape, c_loc(copy), units, description, status)
  end subroutine result_file_write_count

  !> A text as a scalar variable-length UTF-8 string dataset (units '').
  subroutine result_file_write_text(self, name, text, description, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name, text, description
    type(status_t), intent(inout) :: status
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
  end subroutine result_file_write_text

  !> A text attribute on an existing object ('/' for the file).
  subroutine set_attribute_text(self, object, name, value, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name, value
    type(status_t), intent(inout) :: status
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    call write_string_attribute(self%file_id, object, name, value, hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end subroutine set_attribute_text

  !> A real scalar attribute (the unit belongs in its name, e.g. flow_rate_m3_per_s).
  subroutine set_attribute_real(self, object, name, value, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    real(wp), target :: copy
    integer(hsize_t) :: no_shape(0)
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    call note_finite(self, object//' attribute '//name, ieee_is_finite(value))
    copy = value
    call write_attribute(self%file_id, object, name, H5T_NATIVE_DOUBLE, no_shape, c_loc(copy), hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end subroutine set_attribute_real

  !> A real array attribute (h5py shape (n,)).
  subroutine set_attribute_reals(self, object, name, values, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name
    real(wp), intent(in), target, contiguous :: values(:)
    type(status_t), intent(inout) :: status
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    call note_finite(self, object//' attribute '//name, all(ieee_is_finite(values)))
    call write_attribute(self%file_id, object, name, H5T_NATIVE_DOUBLE, shape(values, kind=hsize_t), &
                         c_loc(values), hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end subroutine set_attribute_reals

  !> An integer scalar attribute.
  subroutine set_attribute_integer(self, object, name, value, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name
    integer, intent(in) :: value
    type(status_t), intent(inout) :: status
    integer, target :: copy
    integer(hsize_t) :: no_shape(0)
    integer :: hdferr
    if (.not. status%ok() .or. self%file_id < 0) return
    copy = value
    call write_attribute(self%file_id, object, name, H5T_NATIVE_INTEGER, no_shape, c_loc(copy), hdferr)
    call attribute_status(self, object, name, hdferr, status)
  end subroutine set_attribute_integer

  subroutine attribute_status(self, object, name, hdferr, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: object, name
    integer, intent(in) :: hdferr
    type(status_t), intent(inout) :: status
    if (hdferr /= 0) call write_failure(self, 'attribute "'//name//'" of "'//object//'"', status)
  end subroutine attribute_status

  !> Makes the 1-d dataset `name` a dimension scale (named after its last
  !> path component), to be attached with attach_scale.
  subroutine result_file_make_scale(self, name, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    type(status_t), intent(inout) :: status
    integer(hid_t) :: dataset_id
    integer :: hdferr, err, k
    if (.not. status%ok() .or. self%file_id < 0) return
    k = find_written(self, name)
    if (k == 0) then
      call set_status(status, STATUS_IO, 'dimension scale "'//name//'" was not written')
      return
    end if
    call h5dopen_f(self%file_id, name, dataset_id, hdferr)
    if (hdferr == 0) then
      call h5dsset_scale_f(dataset_id, hdferr, name(index(name, '/', back=.true.) + 1:))
      call h5dclose_f(dataset_id, err)
    end if
    if (hdferr /= 0) then
      call set_status(status, STATUS_IO, 'cannot make "'//name//'" a dimension scale in "'// &
                      self%temporary_path//'"')
      return
    end if
    self%written(k)%is_scale = .true.
  end subroutine result_file_make_scale

  !> Attaches the dimension scale `scale` to every dataset written so far
  !> under the group `under` (and its subgroups) whose numpy axis `axis`
  !> (default 0, the first index in h5py; the last in Fortran) has the
  !> scale's length and no scale yet: attach a subgroup's own scale first
  !> (/water/table/arc_length before /water/time). Scales are left alone
  !> (HDF5 does not attach scales to scales).
  subroutine result_file_attach_scale(self, scale, under, status, axis)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: scale, under
    type(status_t), intent(inout) :: status
    integer, intent(in), optional :: axis
    integer(hid_t) :: scale_id, dataset_id
    integer :: hdferr, err, k, s, numpy_axis, fortran_dim
    character(len=:), allocatable :: prefix
    if (.not. status%ok() .or. self%file_id < 0) return
    numpy_axis = 0
    if (present(axis)) numpy_axis = axis
    s = find_written(self, scale)
    if (s == 0) then
      call set_status(status, STATUS_IO, 'dimension scale "'//scale//'" was not written')
      return
    end if
    if (.not. self%written(s)%is_scale) then
      call set_status(status, STATUS_IO, '"'//scale//'" is not a dimension scale (make_scale first)')
      return
    end if
    prefix = under
    if (prefix(len(prefix):) /= '/') prefix = prefix//'/'
    call h5dopen_f(self%file_id, scale, scale_id, hdferr)
    do k = 1, self%n_written
      if (hdferr /= 0) exit
      associate (w => self%written(k))
        if (w%is_scale .or. index(w%name, prefix) /= 1) cycle
        if (size(w%shape) <= numpy_axis) cycle
        fortran_dim = size(w%shape) - numpy_axis
        if (w%scaled(fortran_dim) .or. w%shape(fortran_dim) /= self%written(s)%shape(1)) cycle
        call h5dopen_f(self%file_id, w%name, dataset_id, hdferr)
        if (hdferr /= 0) exit
        ! the Fortran binding numbers dimensions as C (numpy) does, from 1
        call h5dsattach_scale_f(dataset_id, scale_id, numpy_axis + 1, hdferr)
        call h5dclose_f(dataset_id, err)
        w%scaled(fortran_dim) = .true.
      end associate
    end do
    call h5dclose_f(scale_id, err)
    if (hdferr /= 0) call set_status(status, STATUS_IO, 'cannot attach the dimension scale "'//scale// &
                                     '" under "'//under//'" in "'//self%temporary_path//'"')
  end subroutine result_file_attach_scale

  !> The shape (h5py/C order) of a dataset written to this file; size 0 if
  !> it was not written (or is a scalar).
  function result_file_shape_of(self, name) result(dims)
    class(result_file_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer, allocatable :: dims(:)
    integer :: k
    k = find_written(self, name)
    if (k == 0) then
      allocate (dims(0))
    else
      dims = int(self%written(k)%shape(size(self%written(k)%shape):1:-1))
    end if
  end function result_file_shape_of

  !> The values of a double-precision dataset written to this file, read
  !> back in the file's (C) order, the last index fastest: the rows of an
  !> (n, 3) dataset as x1 y1 z1 x2 ...; size 0 if it was not written or
  !> cannot be read.
  function result_file_values_of(self, name) result(values)
    class(result_file_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), allocatable, target :: values(:)
    integer(hid_t) :: dataset_id
    type(c_ptr) :: buffer
    integer :: k, hdferr, err
    k = find_written(self, name)
    allocate (values(0))
    if (k == 0) return
    if (.not. self%written(k)%is_real) return
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
  end function result_file_values_of

  !> Whether `name` was written as a double-precision dataset.
  logical function result_file_is_real(self, name) result(is_real)
    class(result_file_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer :: k
    k = find_written(self, name)
    is_real = .false.
    if (k > 0) is_real = self%written(k)%is_real
  end function result_file_is_real

  !> The datasets written directly in `group` (not in its subgroups), in the
  !> order they were written.
  function result_file_names_in(self, group) result(names)
    class(result_file_t), intent(in) :: self
    character(len=*), intent(in) :: group
    character(len=:), allocatable :: names(:)
    character(len=:), allocatable :: prefix
    integer :: k, n, width
    prefix = group
    if (prefix(len(prefix):) /= '/') prefix = prefix//'/'
    n = 0; width = 1
    do k = 1, self%n_written
      if (in_group(self%written(k)%name)) then
        n = n + 1; width = max(width, len(self%written(k)%name))
      end if
    end do
    allocate (character(len=width) :: names(n))
    n = 0
    do k = 1, self%n_written
      if (in_group(self%written(k)%name)) then
        n = n + 1; names(n) = self%written(k)%name
      end if
    end do
  contains
    logical function in_group(name)
      character(len=*), intent(in) :: name
      in_group = index(name, prefix) == 1
      if (in_group) in_group = index(name(len(prefix) + 1:), '/') == 0
    end function in_group
  end function result_file_names_in

  !> Labels the vector and matrix axes (length 3 after the sample axis) of the
  !> datasets under `group` with a dimension scale `<group>/xyz` = [0, 1, 2]
  !> (x, y, z), so that every axis has a scale: netCDF readers (xarray with
  !> h5netcdf) refuse a dataset with labelled and unlabelled axes. Call after
  !> the group's own scales are attached.
  subroutine result_file_attach_components(self, group, status)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: group
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: prefix, scale
    integer :: k, axis
    logical :: needed
    if (.not. status%ok() .or. self%file_id < 0) return
    prefix = group
    if (prefix(len(prefix):) /= '/') prefix = prefix//'/'
    needed = .false.
    do k = 1, self%n_written
      associate (w => self%written(k))
        if (index(w%name, prefix) == 1 .and. size(w%shape) >= 2) needed = needed .or. any(w%shape(:size(w%shape) - 1) == 3)
      end associate
    end do
    if (.not. needed) return
    scale = prefix//'xyz'
    call self%write_integers(scale, [0, 1, 2], '1', 'vector component: 0 x, 1 y, 2 z (world axes); '// &
                             'for 3 x 3 frames the second index is the axis', status)
    call self%make_scale(scale, status)
    do axis = 1, 2
      call self%attach_scale(scale, group, status, axis=axis)
    end do
  end subroutine result_file_attach_components

  integer function find_written(self, name) result(k)
    class(result_file_t), intent(in) :: self
    character(len=*), intent(in) :: name
    do k = self%n_written, 1, -1
      if (self%written(k)%name == name) return
    end do
    k = 0
  end function find_written

  !> Marks the file complete (or incomplete, with the reason), closes it and
  !> renames it to its final name. A file with a failed write is deleted
  !> instead (STATUS_IO); a file asked to be complete that holds a number
  !> that is not finite is marked incomplete (STATUS_DOMAIN naming the
  !> dataset): `status` is then not ok.
  subroutine result_file_finish(self, complete_asked, message, status)
    class(result_file_t), intent(inout) :: self
    logical, intent(in) :: complete_asked
    character(len=*), intent(in) :: message
    type(status_t), intent(inout) :: status
    integer :: hdferr, err
    logical :: renamed, complete
    character(len=:), allocatable :: text, error, what
    type(text_output_t) :: companion
    type(status_t) :: companion_status

    if (self%file_id < 0) return
    complete = complete_asked
    text = message
    if (self%write_failed) then
      call discard(self)
      complete = .false.
      if (status%code /= STATUS_IO) call set_status(status, STATUS_IO, 'cannot write the result file "'// &
                                                    self%temporary_path//'"; nothing is kept')
      return
    end if
    if (complete .and. len(self%nonfinite) > 0) then
      complete = .false.
      text = 'the results hold numbers that are not finite (NaN or Inf), first in '//self%nonfinite// &
             '; they cannot be trusted'
      call set_status(status, STATUS_DOMAIN, text)
    end if
    if (complete) then
      call write_string_attribute(self%file_id, '/', 'status', 'complete', hdferr)
    else
      call write_string_attribute(self%file_id, '/', 'status', 'incomplete', hdferr)
    end if
    call write_string_attribute(self%file_id, '/', 'status_message', text, err)
    if (hdferr == 0) hdferr = err
    call h5fclose_f(self%file_id, err)
    ! closed or not, never closed again: a second close of a file whose
    ! flush failed (a full disk) crashes HDF5 (see discard)
    self%file_id = -1
    if (hdferr == 0) hdferr = err
    if (hdferr /= 0) then
      call write_failure(self, 'the status', status)
      call discard(self)
      complete = .false.
      return
    end if
    if (allocated(self%companion_path)) then
      call companion%create(self%companion_path, 'the XDMF view of the result file', companion_status)
      call companion%write(self%companion_text)
      if (companion_status%ok()) call companion%close(companion_status)
      if (.not. companion_status%ok()) then
        call remove_file(self%temporary_path)
        call set_status(status, STATUS_IO, companion_status%text()//'; the result file is not kept either')
        return
      end if
    end if
    ! checked when the run started (scenarios_registry); this catches one that
    ! appeared since, short of the instant between this check and the rename
    what = nonregular_kind(self%path)
    if (len(what) > 0) then
      what = '"'//self%path//'" is '//what
    else if (allocated(self%companion_path)) then
      what = nonregular_kind(self%companion_path)
      if (len(what) > 0) what = '"'//self%companion_path//'", where the XDMF view goes, is '//what
    end if
    if (len(what) > 0) then
      text = 'the results are kept in "'//self%temporary_path//'"'
      if (allocated(self%companion_path)) text = text//' and their XDMF view in "'// &
                                                 companion%temporary_name()//'"'
      call set_status(status, STATUS_IO, 'cannot put the result file in place: '//what//' (it appeared '// &
                      'during the run), which slidesim never replaces; '//text//' (rename them yourself)')
      return
    end if
    call rename_file(self%temporary_path, self%path, renamed, error)
    if (.not. renamed) then
      call remove_file(self%temporary_path)
      call companion%discard()
      complete = .false.
      call set_status(status, STATUS_IO, 'cannot rename "'//self%temporary_path//'" to "'//self%path//'": '// &
                      error//'; nothing is kept')
      return
    end if
    if (allocated(self%companion_path)) then
      call companion%place(companion_status)
      if (.not. companion_status%ok()) then
        ! an old view would describe another file (a device is never removed)
        if (len(nonregular_kind(self%companion_path)) == 0) call remove_file(self%companion_path)
        call set_status(status, STATUS_IO, 'the results are in "'//self%path//'", but '//companion_status%text())
      end if
    end if
  end subroutine result_file_finish

  !> The text file `path` kept with the result (at most one: its XDMF view).
  subroutine result_file_add_companion(self, path, text)
    class(result_file_t), intent(inout) :: self
    character(len=*), intent(in) :: path, text
    self%companion_path = path
    self%companion_text = text
  end subroutine result_file_add_companion

  !> Closes what can be closed of a file that will not be kept and deletes
  !> it. A file whose flush failed cannot be closed a second time (HDF5 1.10
  !> crashes in H5F__close_cb), which is why create asks HDF5 not to close
  !> files at exit (h5dont_atexit): every kept file is closed by finish.
  subroutine discard(self)
    class(result_file_t), intent(inout) :: self
    integer :: err
    if (self%file_id >= 0) call h5fclose_f(self%file_id, err)
    self%file_id = -1
    call remove_file(self%temporary_path)
  end subroutine discard

  !> The status a run ends with once its result file was created: a file that
  !> could not be written first (nothing was kept: exit 3), then the run's own
  !> failure (file kept incomplete: exit 2), then a failure found while
  !> finishing the file. A failure reported as bad input this late is a failed
  !> run (exit 2: a file was kept; exit 1 promises none).
  pure function run_outcome(run_status, file_status) result(status)
    type(status_t), intent(in) :: run_status, file_status
    type(status_t) :: status
    if (file_status%code == STATUS_IO) then
      status = file_status
    else if (.not. run_status%ok()) then
      status = run_status
    else
      status = file_status
    end if
    if (status%code == STATUS_INVALID_INPUT) status%code = STATUS_DOMAIN
  end function run_outcome


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
      if (size(shape) == 0) then
        call h5screate_f(H5S_SCALAR_F, space_id, hdferr)
      else
        call h5screate_simple_f(size(shape), shape, space_id, hdferr)
      end if
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
end module io_hdf5
