!> The few operating-system services the file boundary needs, through the C
!> library (POSIX): a new file with a unique name (mkstemps), removing and
!> renaming files, writing a file through its descriptor with every failure
!> reported (a full disk), the text of the last system error, the path a
!> path resolves to (realpath), which file a path names (device and inode),
!> what kind of file a path names when it is not a
!> regular one (statx: a device, a FIFO, a socket), an exclusive lock on a
!> folder (flock on the folder itself: no lock file), ignoring SIGXFSZ so that a write beyond the
!> file-size limit fails with an error we report instead of killing us, and
!> standard output written so that a lost line is known (a closed pipe, a
!> full disk, a closed stream: `guard_standard_streams`, `write_standard_output`).
module io_system
  use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_funptr, c_intptr_t, &
                                         c_associated, c_f_pointer, c_null_ptr, c_null_funptr, c_size_t, &
                                         c_loc, c_int16_t, c_int32_t, c_int64_t
  implicit none (type, external)
  private
  public :: create_unique_file, open_unique_file, write_descriptor, close_descriptor, remove_file, rename_file, &
            system_error_text, resolved_path, file_identity_t, file_identity, &
            ignore_file_size_signal, process_id, nonregular_kind, folder_lock_t
  public :: guard_standard_streams, write_standard_output, standard_output_lost, standard_input_closed

  integer(c_int), parameter :: sigxfsz = 25, sigpipe = 13   !< Linux (x86-64, arm64)
  integer(c_int), parameter :: eintr = 4
  integer(c_int), parameter :: at_fdcwd = -100   !< Linux: the working folder
  integer(c_int), parameter :: statx_type = 1, statx_ino = 256   !< ask for the type; the inode

  !> Linux's struct statx up to stx_dev_minor, padded to its 256 bytes.
  !> Unlike struct stat its layout is the same on every architecture.
  type, bind(C) :: statx_t
    integer(c_int32_t) :: mask = 0, block_size = 0
    integer(c_int64_t) :: attributes = 0
    integer(c_int32_t) :: links = 0, uid = 0, gid = 0
    integer(c_int16_t) :: mode = 0, spare = 0
    integer(c_int64_t) :: inode = 0, size = 0, blocks = 0, attributes_mask = 0
    integer(c_int64_t) :: times(8) = 0                     ! atime, btime, ctime, mtime: 16 bytes each
    integer(c_int32_t) :: rdev_major = 0, rdev_minor = 0, dev_major = 0, dev_minor = 0
    integer(c_int64_t) :: rest(14) = 0
  end type statx_t

  !> Which file a path names (links followed): its device and inode. Two
  !> paths, hard links or symbolic links to one file have the same identity.
  type :: file_identity_t
    logical :: exists = .false.
    integer(c_int64_t) :: inode = 0
    integer(c_int32_t) :: dev_major = 0, dev_minor = 0
  contains
    procedure :: same => identity_same
  end type file_identity_t

  !> An exclusive lock on a folder, held from `lock` until `unlock` (or the
  !> process ends): flock(2) on the open folder, so two processes that lock
  !> one folder take turns; nothing is written.
  type :: folder_lock_t
    private
    type(c_ptr) :: folder = c_null_ptr
  contains
    procedure :: lock => folder_lock
    procedure :: unlock => folder_unlock
  end type folder_lock_t

  !> What became of standard output: a line that could not be written (or the
  !> stream closed at the start) and why. Process state, not simulation state:
  !> set by guard_standard_streams and write_standard_output, which only the
  !> main thread calls (summaries are printed after the parallel parts).
  logical :: output_lost = .false.
  character(len=:), allocatable :: output_error
  !> standard input was closed at the start (slidesim - <&-): read, it would look empty
  logical :: input_closed = .false.

  interface
    function c_mkstemps(template, suffix_length) bind(C, name='mkstemps') result(fd)
      import :: c_char, c_int
      character(kind=c_char), intent(inout) :: template(*)
      integer(c_int), value :: suffix_length
      integer(c_int) :: fd
    end function c_mkstemps
    function c_umask(mask) bind(C, name='umask') result(old)
      import :: c_int
      integer(c_int), value :: mask
      integer(c_int) :: old
    end function c_umask
    function c_fchmod(fd, mode) bind(C, name='fchmod') result(rc)
      import :: c_int
      integer(c_int), value :: fd, mode
      integer(c_int) :: rc
    end function c_fchmod
    function c_fsync(fd) bind(C, name='fsync') result(rc)
      import :: c_int
      integer(c_int), value :: fd
      integer(c_int) :: rc
    end function c_fsync
    function c_close(fd) bind(C, name='close') result(rc)
      import :: c_int
      integer(c_int), value :: fd
      integer(c_int) :: rc
    end function c_close
    function c_unlink(path) bind(C, name='unlink') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: rc
    end function c_unlink
    function c_rename(old, new) bind(C, name='rename') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: old(*), new(*)
      integer(c_int) :: rc
    end function c_rename
    function c_write(fd, buffer, count) bind(C, name='write') result(written)
      import :: c_int, c_ptr, c_size_t
      integer(c_int), value :: fd
      type(c_ptr), value :: buffer
      integer(c_size_t), value :: count
      integer(c_size_t) :: written   ! ssize_t: -1 on an error
    end function c_write
    function c_dup(fd) bind(C, name='dup') result(new_fd)
      import :: c_int
      integer(c_int), value :: fd
      integer(c_int) :: new_fd
    end function c_dup
    function c_opendir(path) bind(C, name='opendir') result(folder)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr) :: folder
    end function c_opendir
    function c_dirfd(folder) bind(C, name='dirfd') result(fd)
      import :: c_ptr, c_int
      type(c_ptr), value :: folder
      integer(c_int) :: fd
    end function c_dirfd
    function c_closedir(folder) bind(C, name='closedir') result(rc)
      import :: c_ptr, c_int
      type(c_ptr), value :: folder
      integer(c_int) :: rc
    end function c_closedir
    function c_flock(fd, operation) bind(C, name='flock') result(rc)
      import :: c_int
      integer(c_int), value :: fd, operation
      integer(c_int) :: rc
    end function c_flock
    function c_getpid() bind(C, name='getpid') result(pid)
      import :: c_int
      integer(c_int) :: pid
    end function c_getpid
    function c_errno_location() bind(C, name='__errno_location') result(p)
      import :: c_ptr
      type(c_ptr) :: p
    end function c_errno_location
    function c_strerror(errnum) bind(C, name='strerror') result(p)
      import :: c_int, c_ptr
      integer(c_int), value :: errnum
      type(c_ptr) :: p
    end function c_strerror
    function c_realpath(path, resolved) bind(C, name='realpath') result(p)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr), value :: resolved
      type(c_ptr) :: p
    end function c_realpath
    function c_statx(dirfd, path, flags, mask, buffer) bind(C, name='statx') result(rc)
      import :: c_int, c_char, statx_t
      integer(c_int), value :: dirfd, flags, mask
      character(kind=c_char), intent(in) :: path(*)
      type(statx_t), intent(out) :: buffer
      integer(c_int) :: rc
    end function c_statx
    subroutine c_free(p) bind(C, name='free')
      import :: c_ptr
      type(c_ptr), value :: p
    end subroutine c_free
    function c_signal(signum, handler) bind(C, name='signal') result(old)
      import :: c_int, c_funptr
      integer(c_int), value :: signum
      type(c_funptr), value :: handler
      type(c_funptr) :: old
    end function c_signal
  end interface

contains

  !> Creates a new empty file `prefix`.XXXXXX`suffix` (XXXXXX replaced by
  !> random characters, the name unique at creation) and returns its name;
  !> '' if it could not be created (then `error` says why). Its permissions
  !> are those of any new file (0666 less the umask), not mkstemps' 0600.
  subroutine create_unique_file(prefix, suffix, path, error)
    character(len=*), intent(in) :: prefix, suffix
    character(len=:), allocatable, intent(out) :: path, error
    integer(c_int) :: fd, rc
    call open_unique_file(prefix, suffix, path, fd, error)
    if (fd >= 0) rc = c_close(fd)
  end subroutine create_unique_file

  !> As create_unique_file, and the file stays open for writing: `fd` is its
  !> descriptor (-1 if it could not be created), for write_descriptor and
  !> close_descriptor.
  subroutine open_unique_file(prefix, suffix, path, fd, error)
    character(len=*), intent(in) :: prefix, suffix
    character(len=:), allocatable, intent(out) :: path, error
    integer(c_int), intent(out) :: fd
    character(kind=c_char) :: template(len(prefix) + len(suffix) + 8)   ! with .XXXXXX and the NUL
    character(len=:), allocatable :: name
    integer(c_int) :: rc, mask
    integer :: i
    name = prefix//'.XXXXXX'//suffix
    do i = 1, len(name)
      template(i) = name(i:i)
    end do
    template(len(name) + 1) = c_null_char
    path = ''
    error = ''
    fd = c_mkstemps(template, int(len(suffix), c_int))
    if (fd < 0) then
      error = system_error_text()
      return
    end if
    mask = c_umask(0_c_int)
    rc = c_umask(mask)
    rc = c_fchmod(fd, iand(int(o'666', c_int), not(mask)))
    path = name
    do i = 1, len(name)
      path(i:i) = template(i)
    end do
  end subroutine open_unique_file

  !> Writes all of `text` to the open descriptor `fd`; `error` is '' or why
  !> not (a full disk: "No space left on device").
  subroutine write_descriptor(fd, text, error)
    integer(c_int), intent(in) :: fd
    character(len=*), intent(in) :: text
    character(len=:), allocatable, intent(out) :: error
    character(kind=c_char), allocatable, target :: buffer(:)
    integer(c_size_t) :: done, written
    integer(c_int), pointer :: errno
    error = ''
    if (len(text) == 0) return
    allocate (buffer(len(text)))
    buffer = transfer(text, buffer)
    call c_f_pointer(c_errno_location(), errno)
    done = 0
    do while (done < size(buffer, kind=c_size_t))
      written = c_write(fd, c_loc(buffer(done + 1)), size(buffer, kind=c_size_t) - done)
      if (written < 0) then
        if (errno == eintr) cycle
        error = system_error_text()
        if (len(error) == 0) error = 'write error'
        return
      end if
      done = done + written
    end do
  end subroutine write_descriptor

  !> Puts what was written on the disk (fsync: a file system that reserves
  !> space late reports a full disk here) and closes `fd`; `error` is '' or
  !> why either failed. The descriptor is closed in any case.
  subroutine close_descriptor(fd, error)
    integer(c_int), intent(in) :: fd
    character(len=:), allocatable, intent(out) :: error
    error = ''
    if (c_fsync(fd) /= 0) error = system_error_text()
    if (c_close(fd) /= 0 .and. len(error) == 0) error = system_error_text()
  end subroutine close_descriptor

  !> Waits for the exclusive lock on the folder `path` ('' or '.': the
  !> working folder); `locked` false if the folder cannot be opened or locked.
  subroutine folder_lock(self, path, locked)
    class(folder_lock_t), intent(inout) :: self
    character(len=*), intent(in) :: path
    logical, intent(out) :: locked
    integer(c_int), parameter :: lock_exclusive = 2   ! LOCK_EX
    integer(c_int) :: rc
    call self%unlock()
    locked = .false.
    if (len(path) == 0) then
      self%folder = c_opendir('.'//c_null_char)
    else
      self%folder = c_opendir(path//c_null_char)
    end if
    if (.not. c_associated(self%folder)) return
    do
      rc = c_flock(c_dirfd(self%folder), lock_exclusive)
      if (rc == 0) exit
      if (last_errno() /= eintr) then
        call self%unlock()
        return
      end if
    end do
    locked = .true.
  end subroutine folder_lock

  !> Releases the lock (closing the folder releases it); nothing if none is held.
  subroutine folder_unlock(self)
    class(folder_lock_t), intent(inout) :: self
    integer(c_int) :: rc
    if (.not. c_associated(self%folder)) return
    rc = c_closedir(self%folder)
    self%folder = c_null_ptr
  end subroutine folder_unlock

  integer(c_int) function last_errno()
    integer(c_int), pointer :: errno
    call c_f_pointer(c_errno_location(), errno)
    last_errno = errno
  end function last_errno

  !> Removes a file; no error if it is not there.
  subroutine remove_file(path)
    character(len=*), intent(in) :: path
    integer(c_int) :: rc
    rc = c_unlink(path//c_null_char)
  end subroutine remove_file

  !> Renames atomically (within one file system); `error` says why not.
  subroutine rename_file(old, new, ok, error)
    character(len=*), intent(in) :: old, new
    logical, intent(out) :: ok
    character(len=:), allocatable, intent(out) :: error
    ok = c_rename(old//c_null_char, new//c_null_char) == 0
    error = ''
    if (.not. ok) error = system_error_text()
  end subroutine rename_file

  !> The C library's text for the last error (errno), '' if none.
  function system_error_text() result(text)
    character(len=:), allocatable :: text
    integer(c_int), pointer :: errno
    call c_f_pointer(c_errno_location(), errno)
    text = ''
    if (errno /= 0) text = c_text(c_strerror(errno))
  end function system_error_text

  !> What `path` names if it exists and is not a regular file (links
  !> followed): 'a folder', 'a character device', 'a block device', 'a FIFO
  !> (named pipe)', 'a socket'; '' for a regular file, nothing (or a dangling
  !> link), or a path that cannot be examined (opening it reports why). A
  !> result file is renamed onto its path: that would replace such a file.
  function nonregular_kind(path) result(what)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: what
    type(statx_t) :: info
    integer :: file_type
    what = ''
    if (c_statx(at_fdcwd, path//c_null_char, 0_c_int, statx_type, info) /= 0) return
    ! stx_mode is unsigned 16 bits; S_IFMT and the types from <sys/stat.h>
    file_type = iand(iand(int(info%mode), 65535), int(o'170000'))
    select case (file_type)
    case (int(o'100000'))
      what = ''
    case (int(o'040000'))
      what = 'a folder'
    case (int(o'020000'))
      what = 'a character device'
    case (int(o'060000'))
      what = 'a block device'
    case (int(o'010000'))
      what = 'a FIFO (named pipe)'
    case (int(o'140000'))
      what = 'a socket'
    case default
      what = 'not a regular file'
    end select
  end function nonregular_kind

  !> The identity (device and inode) of the file `path` names, links
  !> followed; `exists` false if there is none (or it cannot be examined).
  function file_identity(path) result(identity)
    character(len=*), intent(in) :: path
    type(file_identity_t) :: identity
    type(statx_t) :: info
    if (c_statx(at_fdcwd, path//c_null_char, 0_c_int, ior(statx_type, statx_ino), info) /= 0) return
    if (iand(info%mask, statx_ino) == 0) return
    identity = file_identity_t(exists=.true., inode=info%inode, dev_major=info%dev_major, &
                               dev_minor=info%dev_minor)
  end function file_identity

  !> Are both existing files one file?
  elemental logical function identity_same(self, other)
    class(file_identity_t), intent(in) :: self
    type(file_identity_t), intent(in) :: other
    identity_same = self%exists .and. other%exists .and. self%inode == other%inode .and. &
                    self%dev_major == other%dev_major .and. self%dev_minor == other%dev_minor
  end function identity_same

  !> The absolute path `path` names after links and '..' (realpath); for a
  !> name not (yet) there, its folder's resolved path and the name. '' if
  !> the folder cannot be resolved either.
  function resolved_path(path) result(text)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: text, folder
    integer :: slash
    text = resolved(path)
    if (len(text) > 0) return
    slash = index(path, '/', back=.true.)
    if (slash == 0) then
      folder = resolved('.')
    else if (slash == 1) then
      folder = '/'
    else
      folder = resolved(path(:slash - 1))
    end if
    if (len(folder) == 0) return
    if (folder(len(folder):) /= '/') folder = folder//'/'
    text = folder//path(slash + 1:)
  end function resolved_path

  function resolved(path) result(text)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: text
    type(c_ptr) :: p
    text = ''
    p = c_realpath(path//c_null_char, c_null_ptr)
    if (.not. c_associated(p)) return
    text = c_text(p)
    call c_free(p)
  end function resolved

  !> A write beyond the file-size limit (ulimit -f) then fails with EFBIG,
  !> reported like a full disk, instead of killing the program.
  subroutine ignore_file_size_signal()
    type(c_funptr) :: old
    old = c_signal(sigxfsz, transfer(1_c_intptr_t, c_null_funptr))   ! SIG_IGN
  end subroutine ignore_file_size_signal

  !> Called once at the start. A write to a closed pipe (slidesim ... | head)
  !> then fails with EPIPE, which write_standard_output reports, instead of
  !> SIGPIPE killing the program part way (leaving its temporary result file).
  !> Standard streams closed at the start (slidesim >&-) are opened on
  !> /dev/null, so that no file opened later takes their number (a result file
  !> would receive what C libraries write to the stream); a closed standard
  !> output counts as lost.
  subroutine guard_standard_streams()
    type(c_funptr) :: old
    integer(c_int) :: fd, copy, rc
    integer :: unit, ios
    old = c_signal(sigpipe, transfer(1_c_intptr_t, c_null_funptr))   ! SIG_IGN
    do fd = 0, 2
      copy = c_dup(fd)
      if (copy >= 0) then
        rc = c_close(copy)
        cycle
      end if
      ! the lowest free number is fd (the lower ones are open): kept open to the end
      open (newunit=unit, file='/dev/null', action='readwrite', iostat=ios)
      if (fd == 0) input_closed = .true.
      if (fd == 1) call lose_output('standard output is closed')
    end do
  end subroutine guard_standard_streams

  !> Was standard input closed at the start (guard_standard_streams)?
  logical function standard_input_closed()
    standard_input_closed = input_closed
  end function standard_input_closed

  !> Writes `text` and a line end to standard output at once (unbuffered, so
  !> that it stays in order with the messages on standard error). gfortran
  !> ignores failed writes to its preconnected units, so summaries go through
  !> here: a failure is remembered (standard_output_lost) and nothing more is
  !> written after it.
  subroutine write_standard_output(text)
    character(len=*), intent(in) :: text
    character(kind=c_char), allocatable, target :: buffer(:)
    integer(c_size_t) :: done, written
    integer(c_int), pointer :: errno
    if (output_lost) return
    allocate (buffer(len(text) + 1))
    buffer = transfer(text//new_line('a'), buffer)
    call c_f_pointer(c_errno_location(), errno)
    done = 0
    do while (done < size(buffer, kind=c_size_t))
      written = c_write(1_c_int, c_loc(buffer(done + 1)), size(buffer, kind=c_size_t) - done)
      if (written < 0) then
        if (errno == eintr) cycle
        call lose_output(system_error_text())
        return
      end if
      done = done + written
    end do
  end subroutine write_standard_output

  !> Was a line of standard output lost, and why (set by the first loss)?
  logical function standard_output_lost(reason)
    character(len=:), allocatable, intent(out), optional :: reason
    standard_output_lost = output_lost
    if (present(reason)) then
      reason = ''
      if (allocated(output_error)) reason = output_error
    end if
  end function standard_output_lost

  subroutine lose_output(reason)
    character(len=*), intent(in) :: reason
    output_lost = .true.
    output_error = reason
    if (len(reason) == 0) output_error = 'write error'
  end subroutine lose_output

  integer function process_id()
    process_id = int(c_getpid())
  end function process_id

  !> A C string as Fortran text.
  function c_text(p) result(text)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    call c_f_pointer(p, chars, [65536])
    n = 0
    do while (chars(n + 1) /= c_null_char)
      n = n + 1
    end do
    allocate (character(len=n) :: text)
    text = transfer(chars(:n), text)
  end function c_text
end module io_system
