!> The life cycle of a result file (io_hdf5): the temporary file next to the
!> result, its provenance, and finish: status, close, the XDMF companion and
!> the rename to the final name, or the file deleted when a write failed.
submodule (io_hdf5) io_hdf5_life_cycle
  use hdf5, only: h5open_f, h5dont_atexit_f, h5fcreate_f, h5fclose_f, H5F_ACC_TRUNC_F, h5eset_auto_f
  use base_status, only: set_status
  use base_sha256, only: sha256_hex
  use base_version, only: slidesim_version, slidesim_compiler, slidesim_compiler_options
  use io_provenance, only: utc_timestamp, host_name, build_commit
  use io_system, only: remove_file, rename_file, system_error_text, nonregular_kind, folder_lock_t
  use io_output_files, only: temporary_beside, text_output_t
  use io_hdf5_objects, only: write_string_attribute
  implicit none (type, external)

contains

  !> Opens a new temporary file next to `path` for writing; fails at once if
  !> the folder is not writable.
  module procedure result_file_create
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
  end procedure result_file_create

  module procedure result_file_is_open
    result_file_is_open = self%file_id >= 0
  end procedure result_file_is_open

  !> The result file's name, or what happened to it if it was not kept.
  module procedure result_file_final_path
    path = self%path
    if (self%write_failed) path = 'none: '//self%path//' could not be written'
  end procedure result_file_final_path

  !> The temporary file written while the file is open ('' before create).
  module procedure result_file_temporary_name
    path = ''
    if (allocated(self%temporary_path)) path = self%temporary_path
  end procedure result_file_temporary_name

  !> The root attributes saying what made the file, and the input: scenario,
  !> title, layout_version, slidesim_version, git_commit, compiler,
  !> compiler_options, created_utc, host, input_sha256 (of the bytes of
  !> /input/namelist); the datasets /input/namelist and /input/source.
  module procedure result_file_write_provenance
    call self%set_attribute('/', 'scenario', scenario, status)
    call self%set_attribute('/', 'title', title, status)
    call self%set_attribute('/', 'layout_version', result_layout_version, status)
    call self%set_attribute('/', 'slidesim_version', slidesim_version, status)
    call self%set_attribute('/', 'git_commit', build_commit(), status)
    call self%set_attribute('/', 'compiler', slidesim_compiler, status)
    call self%set_attribute('/', 'compiler_options', slidesim_compiler_options, status)
    call self%set_attribute('/', 'created_utc', utc_timestamp(), status)
    call self%set_attribute('/', 'host', host_name(), status)
    call self%set_attribute('/', 'input_sha256', sha256_hex(input_text), status)
    call self%write_text('/input/namelist', input_text, 'the input namelist text of this run', status)
    call self%write_text('/input/source', input_source, 'where the input came from (a path, '// &
                         '<built-in default> or builtin:<name>)', status)
  end procedure result_file_write_provenance

  !> The text file `path` kept with the result (at most one: its XDMF view).
  module procedure result_file_add_companion
    self%companion_path = path
    self%companion_text = text
  end procedure result_file_add_companion

  !> Marks the file complete (or incomplete, with the reason), closes it and
  !> renames it to its final name. A file with a failed write is deleted
  !> instead (STATUS_IO); a file asked to be complete that holds a number
  !> that is not finite is marked incomplete (STATUS_DOMAIN naming the
  !> dataset): `status` is then not ok.
  module procedure result_file_finish
    integer :: hdferr, err
    logical :: renamed, complete, locked
    character(len=:), allocatable :: text, error, what
    type(text_output_t) :: companion
    type(status_t) :: companion_status
    type(folder_lock_t) :: pair_lock

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
    ! the pair renamed under the folder's lock: of two runs on one path, the
    ! last to rename leaves both its files (its view reads its own result);
    ! a folder that cannot be locked (not readable) is renamed into unlocked
    if (allocated(self%companion_path)) call pair_lock%lock(folder_of(self%path), locked)
    call rename_file(self%temporary_path, self%path, renamed, error)
    if (.not. renamed) then
      call pair_lock%unlock()
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
    call pair_lock%unlock()
  end procedure result_file_finish

  !> The folder of a file's path ('' for the working folder).
  pure function folder_of(path) result(folder)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: folder
    integer :: slash
    slash = index(path, '/', back=.true.)
    folder = path(:max(slash - 1, 0))
    if (slash == 1) folder = '/'
  end function folder_of

  !> A write failed (a full disk, the file-size limit, an I/O error): the
  !> file will not be kept; the message says what and why.
  module procedure write_failure
    character(len=:), allocatable :: why
    self%write_failed = .true.
    why = system_error_text()
    if (len(why) > 0) why = ': '//why
    call set_status(status, STATUS_IO, 'cannot write '//what//' to the result file "'//self%temporary_path// &
                    '"'//why//' (is the disk full?); nothing is kept')
  end procedure write_failure

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
end submodule io_hdf5_life_cycle
