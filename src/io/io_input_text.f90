!> The text of one namelist input (a file, standard input, or a built-in input),
!> read once, parsed into groups (io_namelist) and kept so that the text can be
!> stored in the result file, with the command-line overrides applied to it
!> (--set, --unset: the submodule io_input_overrides); the groups it holds.
module io_input_text
  use, intrinsic :: iso_fortran_env, only: input_unit, iostat_end, iostat_eor
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_IO
  use base_text, only: lower, format_integer
  use io_namelist, only: nml_group_t, parse_namelist
  use io_builtin_inputs, only: builtin_input, builtin_input_names
  use io_output_files, only: note_input_file
  implicit none (type, external)
  private
  public :: input_text_t, load_input_file, input_from_text, stdin_name, read_text_file
  public :: check_known_groups, group_present, group_count, group_index, in_list

  character(len=*), parameter :: builtin_prefix = 'builtin:'
  character(len=*), parameter :: stdin_name = '<stdin>'   !< the name of an input read from standard input
  integer, parameter :: max_input_bytes = 64*1024*1024     !< larger is not a hand-written input

  type :: input_text_t
    character(len=:), allocatable :: name        !< file path, '<stdin>', or 'builtin:<name>'
    character(len=:), allocatable :: folder      !< the file's folder ('' for text), ends in '/'
    character(len=:), allocatable :: raw         !< the text as read
    character(len=:), allocatable :: overrides   !< the --set arguments applied, one per line
    type(nml_group_t), allocatable :: groups(:)
  contains
    procedure :: text => input_text
    procedure :: resolve_path => input_resolve_path
    procedure :: override => input_override
    procedure :: unset => input_unset
  end type input_text_t

  interface
    module subroutine input_override(self, spec, status)
      class(input_text_t), intent(inout) :: self
      character(len=*), intent(in) :: spec
      type(status_t), intent(inout) :: status
    end subroutine input_override

    module subroutine input_unset(self, spec, status)
      class(input_text_t), intent(inout) :: self
      character(len=*), intent(in) :: spec
      type(status_t), intent(inout) :: status
    end subroutine input_unset
  end interface

contains

  ! ---------------------------------------------------------------- loading

  !> Reads an input file, standard input ('-'), or a built-in input named
  !> 'builtin:<name>' (the files of inputs/ compiled into the program; see
  !> io_builtin_inputs), and parses it. A file that cannot be read is
  !> STATUS_IO; a text that is not a valid namelist input is STATUS_INVALID_INPUT.
  subroutine load_input_file(path, input, status)
    character(len=*), intent(in) :: path
    type(input_text_t), intent(out) :: input
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: text
    logical :: exists

    if (index(path, builtin_prefix) == 1) then
      call builtin_input(path(len(builtin_prefix) + 1:), text, exists)
      if (.not. exists) then
        call set_status(status, STATUS_IO, 'there is no built-in input "'//path//'"; built in are: '// &
                        builtin_input_names())
        return
      end if
      call input_from_text(path, text, input, status)
      return
    end if
    if (path == '-') then
      call read_unit(input_unit, stdin_name, text, status)
      if (.not. status%ok()) return
      call input_from_text(stdin_name, text, input, status)
      return
    end if
    call read_text_file(path, 'input file', text, status)
    if (.not. status%ok()) return
    call input_from_text(path, text, input, status)
    input%folder = path(:index(path, '/', back=.true.))
  end subroutine load_input_file

  !> The whole text of a file, read sequentially (pipes and /dev/stdin work:
  !> nothing is rewound or sized); `what` names it in messages ('input file').
  !> Noted as a file the run reads: no output may overwrite it, and one
  !> that an output was claimed for is refused (io_output_files).
  subroutine read_text_file(path, what, text, status)
    character(len=*), intent(in) :: path, what
    character(len=:), allocatable, intent(out) :: text
    type(status_t), intent(inout) :: status
    integer :: unit, ios
    character(len=256) :: msg
    logical :: exists

    text = ''
    inquire (file=path, exist=exists)
    if (.not. exists) then
      call set_status(status, STATUS_IO, what//' "'//path//'" does not exist')
      return
    end if
    inquire (file=path//'/.', exist=exists)
    if (exists) then
      call set_status(status, STATUS_IO, what//' "'//path//'" is a folder, not a file')
      return
    end if
    call note_input_file(path, what, status)
    if (.not. status%ok()) return
    open (newunit=unit, file=path, status='old', action='read', form='formatted', access='sequential', &
          iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call set_status(status, STATUS_IO, 'cannot open '//what//' "'//path//'": '//trim(msg))
      return
    end if
    call read_unit(unit, path, text, status)
    close (unit)
  end subroutine read_text_file

  !> Reads lines of any length from an open unit until its end.
  subroutine read_unit(unit, name, text, status)
    integer, intent(in) :: unit
    character(len=*), intent(in) :: name
    character(len=:), allocatable, intent(out) :: text
    type(status_t), intent(inout) :: status
    character(len=4096) :: chunk
    character(len=:), allocatable :: buffer
    integer :: ios, got, n
    character(len=256) :: msg

    allocate (character(len=65536) :: buffer)
    n = 0
    do
      read (unit, '(a)', advance='no', size=got, iostat=ios, iomsg=msg) chunk
      if (ios /= 0 .and. ios /= iostat_eor .and. ios /= iostat_end) then
        call set_status(status, STATUS_IO, 'cannot read input "'//name//'": '//trim(msg))
        return
      end if
      if (ios == iostat_end) exit
      call put(chunk(:got))
      if (ios == iostat_eor) call put(new_line('a'))
      if (n > max_input_bytes) then
        call set_status(status, STATUS_INVALID_INPUT, 'input "'//name//'" is longer than '// &
                        format_integer(max_input_bytes/1024/1024)//' MB: that is not a namelist input')
        return
      end if
    end do
    text = buffer(:n)

  contains

    subroutine put(piece)
      character(len=*), intent(in) :: piece
      character(len=:), allocatable :: longer
      if (n + len(piece) > len(buffer)) then
        allocate (character(len=2*len(buffer) + len(piece)) :: longer)
        longer(:n) = buffer(:n)
        call move_alloc(longer, buffer)
      end if
      buffer(n + 1:n + len(piece)) = piece
      n = n + len(piece)
    end subroutine put
  end subroutine read_unit

  !> An input from its text; `name` stands for it in messages.
  subroutine input_from_text(name, text, input, status)
    character(len=*), intent(in) :: name, text
    type(input_text_t), intent(out) :: input
    type(status_t), intent(inout) :: status
    input%name = name
    input%folder = ''
    input%raw = text
    input%overrides = ''
    call parse_namelist(name, text, input%groups, status)
  end subroutine input_from_text

  !> A path named inside this input: relative paths are taken from the input
  !> file's folder (from the working folder for inputs given as text); absolute
  !> and 'builtin:' paths stay as they are.
  pure function input_resolve_path(self, path) result(resolved)
    class(input_text_t), intent(in) :: self
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: resolved
    resolved = trim(adjustl(path))
    if (len(resolved) == 0) return
    if (resolved(1:1) == '/' .or. index(resolved, builtin_prefix) == 1) return
    if (allocated(self%folder)) resolved = self%folder//resolved
  end function input_resolve_path

  !> The text as read, followed by the command-line overrides (as comments).
  pure function input_text(self) result(text)
    class(input_text_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = self%raw
    if (len(text) > 0) then
      if (text(len(text):) /= new_line('a')) text = text//new_line('a')
    end if
    if (len(self%overrides) > 0) text = text//'! command-line overrides, applied to the groups above:'// &
      new_line('a')//prefixed_lines('! ', self%overrides)
  end function input_text

  pure function prefixed_lines(prefix, lines) result(text)
    character(len=*), intent(in) :: prefix, lines
    character(len=:), allocatable :: text
    integer :: start, i
    text = ''
    start = 1
    do i = 1, len(lines)
      if (lines(i:i) == new_line('a')) then
        text = text//prefix//lines(start:i)
        start = i + 1
      end if
    end do
  end function prefixed_lines

  ! ----------------------------------------------------------------- groups

  !> The index of the first group named `group` (or of its occurrence-th), 0 if none.
  pure integer function group_index(input, group, occurrence) result(g)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    integer, intent(in), optional :: occurrence
    integer :: seen
    seen = 0
    do g = 1, size(input%groups)
      if (input%groups(g)%name == lower(group)) then
        seen = seen + 1
        if (.not. present(occurrence)) return
        if (seen == occurrence) return
      end if
    end do
    g = 0
  end function group_index

  !> How many groups named `group` the input has (repeatable groups, see
  !> check_known_groups).
  pure integer function group_count(input, group) result(n)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    integer :: g
    n = 0
    do g = 1, size(input%groups)
      if (input%groups(g)%name == lower(group)) n = n + 1
    end do
  end function group_count

  !> Is `word` (lower case) one of `list` (compared in lower case)?
  pure logical function in_list(word, list)
    character(len=*), intent(in) :: word, list(:)
    integer :: j
    in_list = .false.
    do j = 1, size(list)
      if (lower(trim(adjustl(list(j)))) == word) in_list = .true.
    end do
  end function in_list

  pure logical function group_present(input, group)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    group_present = group_index(input, group) > 0
  end function group_present

  !> Every group in the input must be one the scenario reads, and appear once.
  subroutine check_known_groups(input, allowed, status, repeatable)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: allowed(:)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: repeatable(:)   !< groups that may appear more than once
    integer :: i, j
    character(len=:), allocatable :: list

    if (.not. status%ok()) return
    do i = 1, size(input%groups)
      associate (g => input%groups(i))
        if (present(repeatable)) then
          if (in_list(g%name, repeatable)) then
            if (in_list(g%name, allowed)) cycle
          end if
        end if
        do j = 1, i - 1
          if (input%groups(j)%name == g%name) then
            call set_status(status, STATUS_INVALID_INPUT, group_where(input, g)//': &'//g%name// &
                            ' appears more than once (also at line '//format_integer(input%groups(j)%line)// &
                            '); give each group once')
            return
          end if
        end do
        if (in_list(g%name, allowed)) cycle
        list = ''
        do j = 1, size(allowed)
          list = list//' &'//trim(allowed(j))
        end do
        call set_status(status, STATUS_INVALID_INPUT, group_where(input, g)//': unknown namelist group &'// &
                        g%name//'; this scenario reads'//list)
        return
      end associate
    end do
  end subroutine check_known_groups

  !> 'file:line' of a group, or the --set argument that created it.
  pure function group_where(input, g) result(where)
    type(input_text_t), intent(in) :: input
    type(nml_group_t), intent(in) :: g
    character(len=:), allocatable :: where
    if (g%line > 0) then
      where = input%name//':'//format_integer(g%line)
    else if (size(g%items) > 0) then
      where = g%items(1)%origin
    else
      where = input%name
    end if
  end function group_where
end module io_input_text
