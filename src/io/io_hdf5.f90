!> HDF5 result files, written the way h5py, xarray and ParaView users expect
!> (the layout and its version: docs/outputs.md).
!>
!> Life cycle: `create` opens a new temporary file `<path>.<pid>.XXXXXX.tmp`
!> (a unique name in the result's folder: two runs on one path never share
!> it); `finish` marks the root attribute `status` complete or incomplete,
!> closes and renames it to `<path>` in one step, so a file with the final
!> name is always a finished one; with its XDMF companion (which reads the
!> result's datasets) both are renamed under an exclusive lock on their
!> folder, so that of two runs on one path the last leaves both of its
!> files. A run killed on the way leaves only its temporary file. When a write fails (a full disk, the file-size limit) the
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
  use hdf5, only: hid_t, hsize_t
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_IO, STATUS_DOMAIN, STATUS_INVALID_INPUT
  implicit none (type, external)
  private
  public :: result_file_t, result_layout_version, units_per_second, run_outcome, run_message

  !> Version of the layout in docs/outputs.md: raised when an existing name,
  !> shape or unit changes; new groups and datasets do not raise it.
  integer, parameter :: result_layout_version = 1

  !> A dataset written so far: its shape (Fortran order) for attach_scale.
  type :: written_t
    character(len=:), allocatable :: name
    integer(hsize_t), allocatable :: shape(:)
    logical, allocatable :: scaled(:)    ! per Fortran dimension: a scale is attached
    logical :: is_scale = .false.
    logical :: is_real = .false.         ! a double-precision dataset (else integer or text)
    logical :: is_integer = .false.      ! an integer dataset
    character(len=:), allocatable :: units
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
    procedure :: units_of => result_file_units_of
    procedure :: make_scale => result_file_make_scale
    procedure :: attach_scale => result_file_attach_scale
    procedure :: attach_components => result_file_attach_components
    procedure :: add_companion => result_file_add_companion
    procedure :: finish => result_file_finish
    procedure :: is_open => result_file_is_open
    procedure :: final_path => result_file_final_path
    procedure :: temporary_name => result_file_temporary_name
  end type result_file_t

  ! The procedures of the file, in the submodules io_hdf5_life_cycle (create,
  ! provenance, finish: the temporary file and its rename), io_hdf5_datasets
  ! (datasets and attributes written, and what was written) and io_hdf5_scales
  ! (dimension scales); the HDF5 calls on groups and attributes by id in
  ! io_hdf5_objects.
  interface
    module subroutine result_file_create(self, path, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: path
      type(status_t), intent(inout) :: status
    end subroutine result_file_create

    logical module function result_file_is_open(self)
      class(result_file_t), intent(in) :: self
    end function result_file_is_open

    module function result_file_final_path(self) result(path)
      class(result_file_t), intent(in) :: self
      character(len=:), allocatable :: path
    end function result_file_final_path

    module function result_file_temporary_name(self) result(path)
      class(result_file_t), intent(in) :: self
      character(len=:), allocatable :: path
    end function result_file_temporary_name

    module subroutine result_file_write_provenance(self, scenario, title, input_source, input_text, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: scenario, title, input_source, input_text
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_provenance

    module subroutine result_file_add_companion(self, path, text)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: path, text
    end subroutine result_file_add_companion

    module subroutine result_file_finish(self, complete_asked, message, status)
      class(result_file_t), intent(inout) :: self
      logical, intent(in) :: complete_asked
      character(len=*), intent(in) :: message
      type(status_t), intent(inout) :: status
    end subroutine result_file_finish

    module subroutine write_failure(self, what, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: what
      type(status_t), intent(inout) :: status
    end subroutine write_failure

    module subroutine result_file_write_vector(self, name, values, units, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, units, description
      real(wp), intent(in), target, contiguous :: values(:)
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_vector

    module subroutine result_file_write_matrix(self, name, values, units, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, units, description
      real(wp), intent(in), target, contiguous :: values(:, :)
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_matrix

    module subroutine result_file_write_array3(self, name, values, units, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, units, description
      real(wp), intent(in), target, contiguous :: values(:, :, :)
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_array3

    module subroutine result_file_write_integers(self, name, values, units, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, units, description
      integer, intent(in), target, contiguous :: values(:)
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_integers

    module subroutine result_file_write_scalar(self, name, value, units, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, units, description
      real(wp), intent(in) :: value
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_scalar

    module subroutine result_file_write_count(self, name, value, units, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, units, description
      integer, intent(in) :: value
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_count

    module subroutine result_file_write_text(self, name, text, description, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name, text, description
      type(status_t), intent(inout) :: status
    end subroutine result_file_write_text

    module subroutine set_attribute_text(self, object, name, value, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: object, name, value
      type(status_t), intent(inout) :: status
    end subroutine set_attribute_text

    module subroutine set_attribute_real(self, object, name, value, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: object, name
      real(wp), intent(in) :: value
      type(status_t), intent(inout) :: status
    end subroutine set_attribute_real

    module subroutine set_attribute_reals(self, object, name, values, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: object, name
      real(wp), intent(in), target, contiguous :: values(:)
      type(status_t), intent(inout) :: status
    end subroutine set_attribute_reals

    module subroutine set_attribute_integer(self, object, name, value, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: object, name
      integer, intent(in) :: value
      type(status_t), intent(inout) :: status
    end subroutine set_attribute_integer

    module function result_file_shape_of(self, name) result(dims)
      class(result_file_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer, allocatable :: dims(:)
    end function result_file_shape_of

    module function result_file_values_of(self, name) result(values)
      class(result_file_t), intent(in) :: self
      character(len=*), intent(in) :: name
      real(wp), allocatable, target :: values(:)
    end function result_file_values_of

    logical module function result_file_is_real(self, name) result(is_real)
      class(result_file_t), intent(in) :: self
      character(len=*), intent(in) :: name
    end function result_file_is_real

    module function result_file_units_of(self, name) result(units)
      class(result_file_t), intent(in) :: self
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: units
    end function result_file_units_of

    module function result_file_names_in(self, group) result(names)
      class(result_file_t), intent(in) :: self
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: names(:)
    end function result_file_names_in

    integer module function find_written(self, name) result(k)
      class(result_file_t), intent(in) :: self
      character(len=*), intent(in) :: name
    end function find_written

    module subroutine result_file_make_scale(self, name, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      type(status_t), intent(inout) :: status
    end subroutine result_file_make_scale

    module subroutine result_file_attach_scale(self, scale, under, status, axis)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: scale, under
      type(status_t), intent(inout) :: status
      integer, intent(in), optional :: axis
    end subroutine result_file_attach_scale

    module subroutine result_file_attach_components(self, group, status)
      class(result_file_t), intent(inout) :: self
      character(len=*), intent(in) :: group
      type(status_t), intent(inout) :: status
    end subroutine result_file_attach_components
  end interface

contains

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

  !> The message a result file closes with (and the summary repeats): the
  !> run's failure, else the writing's, else `done` (how a complete run
  !> ended: 'ok', 'ok: ' and its outcome).
  pure function run_message(done, run_status, file_status) result(message)
    character(len=*), intent(in) :: done
    type(status_t), intent(in) :: run_status, file_status
    character(len=:), allocatable :: message
    if (.not. run_status%ok()) then
      message = run_status%text()
    else if (.not. file_status%ok()) then
      message = file_status%text()
    else
      message = done
    end if
  end function run_message
end module io_hdf5
