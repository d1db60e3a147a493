!> The dimension scales of a result file (io_hdf5): a 1-d dataset made a
!> scale, attached to the datasets under a group whose axis has its length,
!> and the xyz scale of vector and matrix axes.
submodule (io_hdf5) io_hdf5_scales
  use hdf5, only: h5dopen_f, h5dclose_f
  use h5ds, only: h5dsset_scale_f, h5dsattach_scale_f
  use base_status, only: set_status
  implicit none (type, external)

contains

  !> Makes the 1-d dataset `name` a dimension scale (named after its last
  !> path component), to be attached with attach_scale.
  module procedure result_file_make_scale
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
  end procedure result_file_make_scale

  !> Attaches the dimension scale `scale` to every dataset written so far
  !> under the group `under` (and its subgroups) whose numpy axis `axis`
  !> (default 0, the first index in h5py; the last in Fortran) has the
  !> scale's length and no scale yet: attach a subgroup's own scale first
  !> (/water/table/arc_length before /water/time). Scales are left alone
  !> (HDF5 does not attach scales to scales).
  module procedure result_file_attach_scale
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
  end procedure result_file_attach_scale

  !> Labels the vector and matrix axes (length 3 after the sample axis) of the
  !> datasets under `group` with a dimension scale `<group>/xyz` = [0, 1, 2]
  !> (x, y, z), so that every axis has a scale: netCDF readers (xarray with
  !> h5netcdf) refuse a dataset with labelled and unlabelled axes. Call after
  !> the group's own scales are attached.
  module procedure result_file_attach_components
    character(len=:), allocatable :: prefix, scale
    integer :: k, axis
    logical :: needed
    if (.not. status%ok() .or. self%file_id < 0) return
    prefix = group
    if (prefix(len(prefix):) /= '/') prefix = prefix//'/'
    needed = .false.
    do k = 1, self%n_written
      associate (w => self%written(k))
        if (index(w%name, prefix) == 1 .and. size(w%shape) >= 2) &
          needed = needed .or. any(w%shape(:size(w%shape) - 1) == 3)
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
  end procedure result_file_attach_components
end submodule io_hdf5_scales
