!> The files of one run, and the one way slidesim writes a file.
!>
!> Every file the run reads is noted (read_text_file in io_input calls
!> note_input_file), and every file it will write is claimed before any work
!> (claim_output: the result file, its XDMF view, --summary-json, a sweep's
!> CSV). An output may not be
!> - a file the run reads: the same file by device and inode, so also through
!>   symbolic and hard links (bad input, nothing written); a file read after
!>   the outputs were claimed (a geometry file, a measurement CSV) is refused
!>   where it is read;
!> - another output of the run (the same path once resolved, or the same file);
!> - a folder, a device, a FIFO or a socket, or a link to one (STATUS_IO): the
!>   finished file is renamed onto its path, which would replace it (as root,
!>   a rename onto /dev/full replaces the device);
!> - in a folder that does not exist or cannot be written (STATUS_IO).
!>
!> text_output_t writes a text file (a CSV, JSON, XDMF) as the result file is
!> written: to a new temporary file `<path>.<pid>.XXXXXX.tmp` in the same
!> folder, closed (flushed to the disk) and renamed onto the path when
!> complete. A failed write or close (a full disk) is STATUS_IO naming the
!> file, and nothing of it is kept.
!>
!> The notes and claims are process state (one run at a time, main thread),
!> not simulation state: start_run_files forgets them when a run starts.
module io_output_files
  use, intrinsic :: iso_c_binding, only: c_int
  use base_status, only: status_t, set_status, STATUS_IO, STATUS_INVALID_INPUT
  use base_text, only: format_integer
  use io_system, only: open_unique_file, write_descriptor, close_descriptor, create_unique_file, remove_file, &
                       rename_file, nonregular_kind, file_identity_t, file_identity, resolved_path, process_id
  implicit none (type, external)
  private
  public :: start_run_files, note_input_file, claim_output, temporary_beside, text_output_t

  !> A file the run read: its path as named, what it is ('input file') and its identity.
  type :: input_note_t
    character(len=:), allocatable :: path, what
    type(file_identity_t) :: identity
  end type input_note_t

  !> A file the run will write: its path, how the user named it (origin:
  !> '-o x.h5', "main.nml:5: &run: output = 'x.h5'") and what it is.
  type :: output_claim_t
    character(len=:), allocatable :: path, resolved, origin, what
  end type output_claim_t

  type(input_note_t), allocatable :: inputs(:)
  type(output_claim_t), allocatable :: outputs(:)

  integer, parameter :: buffer_bytes = 65536   !< text gathered before one write

  !> A text file being written (create, write / write_line, finish; or
  !> close, then place, to put it in place later; discard drops it).
  type :: text_output_t
    private
    character(len=:), allocatable :: path, what, temporary, error
    character(len=:), allocatable :: buffer
    integer :: used = 0
    integer(c_int) :: fd = -1
  contains
    procedure :: create => text_create
    procedure :: write => text_write
    procedure :: write_line => text_write_line
    procedure :: close => text_close
    procedure :: place => text_place
    procedure :: finish => text_finish
    procedure :: discard => text_discard
    procedure :: temporary_name => text_temporary_name
  end type text_output_t

contains

  !> Forgets the files of an earlier run (in this process).
  subroutine start_run_files()
    if (allocated(inputs)) deallocate (inputs)
    if (allocated(outputs)) deallocate (outputs)
    allocate (inputs(0), outputs(0))
  end subroutine start_run_files

  !> Notes that the run reads `path` (`what`: 'input file', 'CSV file'); bad
  !> input if it is a file an output of the run was claimed for.
  subroutine note_input_file(path, what, status)
    character(len=*), intent(in) :: path, what
    type(status_t), intent(inout) :: status
    type(input_note_t) :: note
    integer :: k, claimed
    note = input_note_t(path=path, what=what, identity=file_identity(path))
    claimed = 0
    ! (files are read in the main thread today; the lists stay whole if not)
    !$omp critical (run_files)
    if (.not. allocated(inputs)) allocate (inputs(0), outputs(0))
    do k = 1, size(outputs)
      if (note%identity%same(file_identity(outputs(k)%path))) then
        claimed = k
        exit
      end if
    end do
    if (claimed == 0) inputs = [inputs, note]
    !$omp end critical (run_files)
    if (claimed == 0) return
    associate (output => outputs(claimed))
      call set_status(status, STATUS_INVALID_INPUT, what//' "'//path//'" is the file '//output%what// &
                      ' ('//output%origin//') would overwrite'//through_link(path, output%path)// &
                      ': the run would destroy a file it reads; name another output file')
    end associate
  end subroutine note_input_file

  !> Claims `path` for an output of the run before any work (see the module
  !> comment for what is refused). `origin` says where the user named it
  !> ('-o x.h5'), `what` what it is ('the result file'); `part` names a file
  !> that goes with it ('XDMF view': the path is the result file's view).
  subroutine claim_output(path, origin, what, status, part)
    character(len=*), intent(in) :: path, origin, what
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: part
    character(len=:), allocatable :: noun, subject, kind, probe, error, target
    type(file_identity_t) :: identity
    logical :: is_folder
    integer :: k

    if (.not. allocated(inputs)) call start_run_files()
    noun = what
    subject = 'it'
    if (present(part)) then
      noun = what//'''s '//part//' "'//path//'"'
      subject = '"'//path//'", where its '//part//' goes,'
    end if
    inquire (file=path//'/.', exist=is_folder)
    if (is_folder) then
      call set_status(status, STATUS_IO, origin//': cannot write '//what//': '//subject//' is a folder; name a file')
      return
    end if
    kind = nonregular_kind(path)
    if (len(kind) > 0) then
      call set_status(status, STATUS_IO, origin//': cannot write '//what//': '//subject//' is '//kind// &
                      ', which slidesim never replaces; name a regular file or a new one (--check reads and '// &
                      'checks the input without writing results)')
      return
    end if
    identity = file_identity(path)
    do k = 1, size(inputs)
      if (.not. identity%same(inputs(k)%identity)) cycle
      call set_status(status, STATUS_INVALID_INPUT, origin//': '//noun//' would overwrite the '//inputs(k)%what// &
                      ' "'//inputs(k)%path//'", which this run reads'//through_link(path, inputs(k)%path)// &
                      '; name another file')
      return
    end do
    target = resolved_path(path)
    do k = 1, size(outputs)
      if (.not. (identity%same(file_identity(outputs(k)%path)) .or. &
                 (len(target) > 0 .and. target == outputs(k)%resolved))) cycle
      call set_status(status, STATUS_INVALID_INPUT, origin//': '//noun//' would be written to the same file as '// &
                      outputs(k)%what//' ('//outputs(k)%origin//'); name another file')
      return
    end do
    ! the folder exists and can be written: a file made there and removed
    call create_unique_file(path//'.'//format_integer(process_id()), '.tmp', probe, error)
    if (len(probe) == 0) then
      call set_status(status, STATUS_IO, origin//': cannot write '//what//': '//error// &
                      ' (does its folder exist, and is it writable?)')
      return
    end if
    call remove_file(probe)
    outputs = [outputs, output_claim_t(path=path, resolved=target, origin=origin, what=noun)]
  end subroutine claim_output

  !> ' (the same file, through a link)' when two paths that name one file differ.
  function through_link(a, b) result(text)
    character(len=*), intent(in) :: a, b
    character(len=:), allocatable :: text
    text = ''
    if (resolved_path(a) /= resolved_path(b)) text = ' (the same file, through a link)'
  end function through_link

  !> A new empty file `<path>.<pid>.XXXXXX.tmp` beside `path` (its name in
  !> `temporary`; '' and `error` if it could not be made).
  subroutine temporary_beside(path, temporary, error)
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: temporary, error
    call create_unique_file(path//'.'//format_integer(process_id()), '.tmp', temporary, error)
  end subroutine temporary_beside

  ! ---------------------------------------------------------- text_output_t

  !> Opens a new temporary file beside `path` for `what` ('the CSV summary').
  subroutine text_create(self, path, what, status)
    class(text_output_t), intent(inout) :: self
    character(len=*), intent(in) :: path, what
    type(status_t), intent(inout) :: status
    self%path = path
    self%what = what
    self%error = ''
    self%used = 0
    if (.not. allocated(self%buffer)) allocate (character(len=buffer_bytes) :: self%buffer)
    call open_unique_file(path//'.'//format_integer(process_id()), '.tmp', self%temporary, self%fd, self%error)
    if (self%fd < 0) call set_status(status, STATUS_IO, 'cannot write '//what//' "'//path//'": '//self%error// &
                                     ' (does its folder exist, and is it writable?)')
  end subroutine text_create

  !> Appends `text`; a failure is remembered and reported by close.
  subroutine text_write(self, text)
    class(text_output_t), intent(inout) :: self
    character(len=*), intent(in) :: text
    if (self%fd < 0 .or. len(self%error) > 0) return
    if (self%used + len(text) > len(self%buffer)) call flush_buffer(self)
    if (len(text) > len(self%buffer)) then
      if (len(self%error) == 0) call write_descriptor(self%fd, text, self%error)
    else
      self%buffer(self%used + 1:self%used + len(text)) = text
      self%used = self%used + len(text)
    end if
  end subroutine text_write

  subroutine text_write_line(self, text)
    class(text_output_t), intent(inout) :: self
    character(len=*), intent(in) :: text
    call self%write(text//new_line('a'))
  end subroutine text_write_line

  subroutine flush_buffer(self)
    class(text_output_t), intent(inout) :: self
    if (self%used > 0 .and. len(self%error) == 0) call write_descriptor(self%fd, self%buffer(:self%used), self%error)
    self%used = 0
  end subroutine flush_buffer

  !> Writes what is left and closes the temporary file; on a failure (a
  !> write, the flush to the disk, the close) removes it: STATUS_IO.
  subroutine text_close(self, status)
    class(text_output_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: error
    if (self%fd < 0) return
    call flush_buffer(self)
    call close_descriptor(self%fd, error)
    self%fd = -1
    if (len(self%error) == 0) self%error = error
    if (len(self%error) == 0) return
    call remove_file(self%temporary)
    call set_status(status, STATUS_IO, 'cannot write '//self%what//' "'//self%path//'": '//self%error// &
                    '; nothing of it is kept')
  end subroutine text_close

  !> Renames the closed temporary file onto the path. A device, FIFO or
  !> socket that appeared there during the run is not replaced: the text
  !> stays in the temporary file, named in the message (STATUS_IO).
  subroutine text_place(self, status)
    class(text_output_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: kind, error
    logical :: renamed
    if (len(self%error) > 0 .or. self%fd >= 0 .or. .not. allocated(self%temporary)) return
    kind = nonregular_kind(self%path)
    if (len(kind) > 0) then
      call set_status(status, STATUS_IO, 'cannot put '//self%what//' in place: "'//self%path//'" is '//kind// &
                      ' (it appeared during the run), which slidesim never replaces; it is kept in "'// &
                      self%temporary//'" (rename it yourself)')
      return
    end if
    call rename_file(self%temporary, self%path, renamed, error)
    if (renamed) return
    call remove_file(self%temporary)
    call set_status(status, STATUS_IO, 'cannot write '//self%what//' "'//self%path//'": cannot rename "'// &
                    self%temporary//'" to it: '//error//'; nothing of it is kept')
  end subroutine text_place

  !> close, then place.
  subroutine text_finish(self, status)
    class(text_output_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    type(status_t) :: closed
    call self%close(closed)
    if (closed%ok()) then
      call self%place(status)
    else
      status = closed
    end if
  end subroutine text_finish

  !> Drops the file: closed if open, the temporary removed.
  subroutine text_discard(self)
    class(text_output_t), intent(inout) :: self
    character(len=:), allocatable :: error
    if (self%fd >= 0) call close_descriptor(self%fd, error)
    self%fd = -1
    if (allocated(self%temporary)) call remove_file(self%temporary)
  end subroutine text_discard

  function text_temporary_name(self) result(path)
    class(text_output_t), intent(in) :: self
    character(len=:), allocatable :: path
    path = ''
    if (allocated(self%temporary)) path = self%temporary
  end function text_temporary_name
end module io_output_files
