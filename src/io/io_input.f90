!> The text of one namelist input (a file, standard input, or a built-in input),
!> read once, parsed into groups (io_namelist) and kept so that the text can be
!> stored in the result file; command-line overrides (--set group%var=value);
!> and the reader every input group is read through.
!>
!> A group is read by opening it and asking for each variable by name. A
!> declared group (io_input_declarations) takes its names, and every
!> variable its type, range or words and unit, from the declarations: a real
!> in [low, high] (or > low), a whole number in [low, high], a logical, a
!> quoted text of at most len characters (or one of the declared words); any
!> other name is refused. A group not yet declared is opened with its names
!> and each variable asked for with its range. A variable not given keeps
!> the caller's default. Every refusal
!> names the place (file:line, or the --set argument), the group, the
!> variable, the value as written and what is allowed, before any value is
!> used.
module io_input
  use, intrinsic :: iso_fortran_env, only: input_unit, iostat_end, iostat_eor
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use base_kinds, only: wp, int64
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_IO, STATUS_INTERNAL
  use base_text, only: format_real, format_vector, lower, format_integer
  use io_namelist, only: nml_group_t, nml_item_t, nml_value_t, parse_namelist, parse_assignment, &
    read_real_token, read_integer_token, read_logical_token, shown_value, VALUE_TEXT, NUMBER_OK
  use io_builtin_inputs, only: builtin_input, builtin_input_names
  use io_output_files, only: note_input_file
  use io_declaration, only: declaration_t, bound_text, VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS
  use io_input_declarations, only: find_declaration, declaration, declared_names
  implicit none (type, external)
  private
  public :: input_text_t, load_input_file, input_from_text, stdin_name, read_text_file
  public :: check_known_groups, group_present, group_count, lower, format_real, format_vector, invalid, where_given
  public :: check_finite, check_positive, check_nonnegative, check_range, check_choice
  public :: group_reader_t, open_group, bounds_t, in_range, above, mark_input_failure

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

  !> What a real variable may be: low <= x <= high, or low < x <= high.
  type :: bounds_t
    real(wp) :: low = -huge(1.0_wp), high = huge(1.0_wp)
    logical :: open_low = .false.
    character(len=:), allocatable :: unit
  contains
    procedure :: allows => bounds_allow
    procedure :: text => bounds_text
  end type bounds_t

  !> One group of an input, opened for reading with the names it may hold.
  type :: group_reader_t
    character(len=:), allocatable :: source      !< the input's name
    character(len=:), allocatable :: group
    integer :: line = 0                          !< where the group opens (0: not in the text)
    logical :: present = .false.
    logical :: declared = .false.                !< its variables are those of io_input_declarations
    !> the declarations' name of a declared group read differently by two
    !> scenarios (&identify: identify_rider, identify_water); else the group
    character(len=:), allocatable :: table
    type(nml_item_t), allocatable :: items(:)
  contains
    procedure :: has => reader_has
    procedure :: where => reader_where
    procedure :: written => reader_written
    procedure :: invalid => reader_invalid
    procedure :: refuse_given => reader_refuse_given
    procedure :: bounds => reader_bounds
    procedure, private :: get_real, get_real_vector, get_integer, get_logical, get_text
    procedure, private :: get_declared_real, get_declared_vector, get_declared_integer
    generic :: get => get_real, get_real_vector, get_integer, get_logical, get_text, &
                      get_declared_real, get_declared_vector, get_declared_integer
    procedure, private :: get_real_list, get_declared_list
    generic :: get_list => get_real_list, get_declared_list
    procedure, private :: parts_real, parts_text, parts_logical, parts_declared_real
    generic :: get_parts => parts_real, parts_text, parts_logical, parts_declared_real
    procedure, private :: get_real_columns, get_declared_columns
    generic :: get_columns => get_real_columns, get_declared_columns
  end type group_reader_t

  interface open_group
    module procedure open_named_group, open_declared_group
  end interface open_group

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

  !> Applies one command-line override `group%variable=values` (or
  !> `group%variable(i)=values`): it replaces what the text assigns to that
  !> variable (or element), or adds it; the group is added if absent. A group
  !> the input gives more than once must be addressed: `group(k)%...` (its
  !> k-th occurrence) or `group(name)%...` (the one with name = 'name');
  !> without that the override is refused, never applied to one of them
  !> silently. Whether the group and variable exist is checked where the
  !> group is read.
  subroutine input_override(self, spec, status)
    class(input_text_t), intent(inout) :: self
    character(len=*), intent(in) :: spec
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: origin, group, selector
    type(nml_item_t) :: item
    type(nml_group_t), allocatable :: longer(:)
    type(nml_item_t), allocatable :: kept(:)
    integer :: percent, g, i, n

    if (.not. status%ok()) return
    origin = '--set '//spec
    percent = index(spec, '%')
    if (percent < 2) then
      call set_status(status, STATUS_INVALID_INPUT, origin//': write --set group%variable=value, '// &
                      'e.g. --set solver%rtol=1e-8')
      return
    end if
    call target_group(origin, spec(:percent - 1), 'group%variable=value', group, selector, status)
    if (.not. status%ok()) return
    call parse_assignment(origin, spec(percent + 1:), item, status)
    if (.not. status%ok()) then
      ! the usual cause on a command line: a text with / , or blanks, not quoted
      if (scan(spec(percent + 1:), '''"') == 0) status%message = status%message//'; a text with / , = or '// &
        'blanks goes in quotes, which the shell must pass on: --set "'//spec(:percent)// &
        quoted_example(spec(percent + 1:))//'"'
      return
    end if
    call choose_group(self, origin, '--set', group, selector, spec(percent:), g, status)
    if (.not. status%ok()) return
    if (g == 0) then
      allocate (longer(size(self%groups) + 1))
      longer(:size(self%groups)) = self%groups
      longer(size(longer))%name = group
      longer(size(longer))%line = 0
      allocate (longer(size(longer))%items(0))
      call move_alloc(longer, self%groups)
      g = size(self%groups)
    end if
    associate (items => self%groups(g)%items)
      ! a whole assignment replaces every earlier one of the variable; an element one the same element
      allocate (kept(size(items) + 1))
      n = 0
      do i = 1, size(items)
        if (items(i)%name == item%name .and. (item%rank == 0 .or. items(i)%subscript == item%subscript)) cycle
        n = n + 1
        kept(n) = items(i)
      end do
    end associate
    n = n + 1
    kept(n) = item
    self%groups(g)%items = kept(:n)
    self%overrides = self%overrides//'--set '//spec//new_line('a')
  end subroutine input_override

  !> Applies one command-line removal `group%variable` (--unset): every
  !> assignment of the variable in that group is removed, so it takes its
  !> default (a friction input made frictionless, a default restored). The
  !> group is chosen as by --set (group(k)%, group(name)% for a repeated
  !> group); a group the input does not have is refused (nothing to remove).
  !> Whether the variable exists is checked where the group is read, whether
  !> or not the input gave it (open_group): a misspelt name is refused, never
  !> a silent no-op.
  subroutine input_unset(self, spec, status)
    class(input_text_t), intent(inout) :: self
    character(len=*), intent(in) :: spec
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: origin, group, selector, variable
    type(nml_item_t) :: removal
    logical, allocatable :: keep(:)
    integer :: percent, g, i

    if (.not. status%ok()) return
    origin = '--unset '//spec
    percent = index(spec, '%')
    if (percent < 2) then
      call set_status(status, STATUS_INVALID_INPUT, origin//': write --unset group%variable, '// &
                      'e.g. --unset solver%duration')
      return
    end if
    call target_group(origin, spec(:percent - 1), 'group%variable', group, selector, status)
    if (.not. status%ok()) return
    variable = lower(trim(adjustl(spec(percent + 1:))))
    if (len(variable) == 0 .or. verify(variable, 'abcdefghijklmnopqrstuvwxyz0123456789_') /= 0) then
      call set_status(status, STATUS_INVALID_INPUT, origin//': "'//variable//'" is not a variable name; '// &
                      '--unset removes a whole variable (no value, no subscript): --unset '//spec(:percent)//'name')
      return
    end if
    call choose_group(self, origin, '--unset', group, selector, spec(percent:), g, status)
    if (.not. status%ok()) return
    if (g == 0) then
      call set_status(status, STATUS_INVALID_INPUT, origin//': the input has no &'//group//' group: '// &
                      'nothing to remove')
      return
    end if
    associate (grp => self%groups(g))
      keep = [(grp%items(i)%name /= variable, i = 1, size(grp%items))]
      grp%items = pack(grp%items, keep)
      removal%name = variable
      removal%subscript = ''
      removal%origin = origin
      allocate (removal%values(0))
      if (.not. allocated(grp%removed)) allocate (grp%removed(0))
      grp%removed = [grp%removed, removal]
    end associate
    self%overrides = self%overrides//origin//new_line('a')
  end subroutine input_unset

  !> The group an override addresses, from `head` (what precedes the %):
  !> `group`, `group(k)` or `group(name)`; `selector` is the k or the name
  !> ('' if none). `form` shows the argument's form in messages.
  subroutine target_group(origin, head_text, form, group, selector, status)
    character(len=*), intent(in) :: origin, head_text, form
    character(len=:), allocatable, intent(out) :: group, selector
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: head
    integer :: open_at
    head = trim(adjustl(head_text))
    selector = ''
    group = ''
    open_at = index(head, '(')
    if (open_at > 0) then
      if (head(len(head):) /= ')' .or. open_at == len(head) - 1) then
        call set_status(status, STATUS_INVALID_INPUT, origin//': "'//head//'" is not a group: write '// &
                        form//', or group(k)%... for the k-th of a repeated group')
        return
      end if
      selector = trim(adjustl(head(open_at + 1:len(head) - 1)))
      head = trim(head(:open_at - 1))
    end if
    group = lower(head)
    if (len(group) == 0 .or. verify(group, 'abcdefghijklmnopqrstuvwxyz0123456789_') /= 0) &
      call set_status(status, STATUS_INVALID_INPUT, origin//': "'//group//'" is not a group name')
  end subroutine target_group

  !> `variable=value` with the value in single quotes, for the hint above.
  pure function quoted_example(assignment) result(text)
    character(len=*), intent(in) :: assignment
    character(len=:), allocatable :: text
    integer :: equals
    equals = index(assignment, '=')
    text = assignment
    if (equals > 0) text = assignment(:equals)//''''//trim(adjustl(assignment(equals + 1:)))//''''
  end function quoted_example

  !> The group an override of `group` changes: its index, 0 to add it (not in
  !> the input). `selector` is '' (the group must then occur at most once), a
  !> number k (its k-th occurrence) or a name (the occurrence whose `name` is
  !> that, quotes optional); `rest` is '%variable=value', for the messages.
  subroutine choose_group(self, origin, option, group, selector, rest, g, status)
    type(input_text_t), intent(in) :: self
    character(len=*), intent(in) :: origin, option, group, selector, rest
    integer, intent(out) :: g
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: wanted, list, example
    integer :: n, k, ios

    g = 0
    n = group_count(self, group)
    if (len(selector) == 0) then
      if (n <= 1) then
        g = group_index(self, group)
        return
      end if
      ! in double quotes: the shell would take the parentheses itself
      example = occurrence_name(self, group, n)
      if (len(example) > 0) example = ' or '//option//' "'//group//'('//example//')'//rest//'"'
      call set_status(status, STATUS_INVALID_INPUT, origin//': the input has '//format_integer(n)//' &'//group// &
                      ' groups ('//occurrence_list(self, group)//'); say which one to change, e.g. '//option// &
                      ' "'//group//'('//format_integer(n)//')'//rest//'"'//example)
      return
    end if
    if (verify(selector, '0123456789') == 0) then
      k = 0
      ios = 1
      if (len(selector) <= 6) read (selector, *, iostat=ios) k
      if (ios == 0 .and. k >= 1 .and. k <= max(n, 1)) then
        g = group_index(self, group, k)   ! 0 (added) for group(1) of a group not in the input
        return
      end if
      if (n == 0) then
        call set_status(status, STATUS_INVALID_INPUT, origin//': the input has no &'//group//' group; '// &
                        group//'(1) or '//group//' adds one')
      else
        call set_status(status, STATUS_INVALID_INPUT, origin//': k in '//group//'(k) must be 1 to '// &
                        format_integer(n)//': the input has '//occurrence_list(self, group))
      end if
      return
    end if
    wanted = selector
    if (len(wanted) >= 2) then
      if (scan(wanted(1:1), '''"') > 0 .and. wanted(len(wanted):) == wanted(1:1)) &
        wanted = wanted(2:len(wanted) - 1)
    end if
    do k = 1, n
      if (occurrence_name(self, group, k) == wanted) then
        g = group_index(self, group, k)
        return
      end if
    end do
    list = occurrence_list(self, group)
    if (len(list) == 0) list = 'none'
    call set_status(status, STATUS_INVALID_INPUT, origin//': no &'//group//' group has name = '''//wanted// &
                    '''; the input has: '//list)
  end subroutine choose_group

  !> The name = '...' given in the k-th `group`, '' if none.
  pure function occurrence_name(self, group, k) result(text)
    type(input_text_t), intent(in) :: self
    character(len=*), intent(in) :: group
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: g, i
    text = ''
    g = group_index(self, group, k)
    if (g == 0) return
    do i = 1, size(self%groups(g)%items)
      associate (item => self%groups(g)%items(i))
        if (item%name == 'name' .and. item%rank == 0 .and. size(item%values) > 0) text = item%values(1)%text
      end associate
    end do
  end function occurrence_name

  !> "body(1) name = 'a' at line 20, body(2) ...": every occurrence of `group`.
  pure function occurrence_list(self, group) result(text)
    type(input_text_t), intent(in) :: self
    character(len=*), intent(in) :: group
    character(len=:), allocatable :: text, name
    integer :: k, g
    text = ''
    do k = 1, group_count(self, group)
      g = group_index(self, group, k)
      if (k > 1) text = text//', '
      text = text//group//'('//format_integer(k)//')'
      name = occurrence_name(self, group, k)
      if (len(name) > 0) text = text//' name = '''//name//''''
      if (self%groups(g)%line > 0) then
        text = text//' at line '//format_integer(self%groups(g)%line)
      else
        text = text//' from --set'
      end if
    end do
  end function occurrence_list

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

  ! ------------------------------------------------------------- the reader

  !> Opens declared `group` of `input` for reading (its occurrence-th, for a
  !> repeated group): every variable it assigns must be declared in it (or be
  !> one of `also`, names that follow from the declared ones, such as
  !> &sweep's NAME_range). `table` names the declarations of a group that
  !> differs by scenario (default: the group). An absent group reads as
  !> empty (every default kept).
  subroutine open_declared_group(input, group, reader, status, occurrence, also, table)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    type(group_reader_t), intent(out) :: reader
    type(status_t), intent(inout) :: status
    integer, intent(in), optional :: occurrence
    character(len=*), intent(in), optional :: also(:), table
    character(len=32), allocatable :: names(:)
    character(len=32), allocatable :: declared(:)
    character(len=:), allocatable :: declarations_name
    integer :: n
    declarations_name = lower(group)
    if (present(table)) declarations_name = lower(table)
    declared = declared_names(declarations_name)
    n = size(declared)
    if (present(also)) n = n + size(also)
    allocate (names(n))
    names(:size(declared)) = declared
    if (present(also)) names(size(declared) + 1:) = also
    if (size(declared) == 0) then
      reader%source = input%name
      reader%group = lower(group)
      allocate (reader%items(0))
      call set_status(status, STATUS_INTERNAL, '&'//declarations_name//' has no declared variables (a bug: '// &
                      'src/io/io_declarations_*.f90)')
      return
    end if
    call open_named_group(input, group, names, reader, status, occurrence)
    reader%declared = .true.
    reader%table = declarations_name
  end subroutine open_declared_group

  !> Opens `group` of `input` for reading (its occurrence-th, for a repeated
  !> group); every variable it assigns must be one of `names`. An absent group
  !> reads as empty (every default kept).
  subroutine open_named_group(input, group, names, reader, status, occurrence)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    character(len=*), intent(in) :: names(:)
    type(group_reader_t), intent(out) :: reader
    type(status_t), intent(inout) :: status
    integer, intent(in), optional :: occurrence
    integer :: g, i, j
    character(len=:), allocatable :: list

    reader%source = input%name
    reader%group = lower(group)
    g = group_index(input, group, occurrence)
    if (g == 0) then
      allocate (reader%items(0))
      return
    end if
    reader%present = .true.
    reader%line = input%groups(g)%line
    reader%items = input%groups(g)%items
    if (.not. status%ok()) return
    call check_names(reader%items)
    ! the variables --unset removed must be the group's too (a misspelt one
    ! would otherwise be a silent no-op)
    if (allocated(input%groups(g)%removed)) call check_names(input%groups(g)%removed)

  contains

    subroutine check_names(items)
      type(nml_item_t), intent(in) :: items(:)
      if (.not. status%ok()) return
      do i = 1, size(items)
        if (in_list(items(i)%name, names)) cycle
        list = ''
        do j = 1, size(names)
          list = list//' '//trim(names(j))
        end do
        call set_status(status, STATUS_INVALID_INPUT, item_where(reader, items(i), items(i)%line)// &
                        ': &'//reader%group//': unknown variable "'//items(i)%name//'"; allowed:'//list)
        return
      end do
    end subroutine check_names
  end subroutine open_named_group

  pure logical function reader_has(self, name)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer :: i
    reader_has = .false.
    do i = 1, size(self%items)
      if (self%items(i)%name == lower(name)) reader_has = .true.
    end do
  end function reader_has

  !> 'file:line' of the first assignment of `name` (the first name in a list
  !> such as 'u0, v0' or 'kind(2)'), or of the group, or the file.
  pure function reader_where(self, name) result(where)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: where
    character(len=:), allocatable :: first
    integer :: i, cut
    first = lower(trim(adjustl(name)))
    cut = scan(first, '(, ')
    if (cut > 0) first = first(:cut - 1)
    do i = 1, size(self%items)
      if (self%items(i)%name == first) then
        where = item_where(self, self%items(i), self%items(i)%line)
        return
      end if
    end do
    if (self%line > 0) then
      where = self%source//':'//format_integer(self%line)
    else
      where = self%source
    end if
  end function reader_where

  !> The values of `name` as written (for messages), '' if not given.
  pure function reader_written(self, name) result(text)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, size(self%items)
      if (self%items(i)%name == lower(name)) then
        text = shown_values(self%items(i))
        return
      end if
    end do
  end function reader_written

  pure function item_where(self, item, line) result(where)
    type(group_reader_t), intent(in) :: self
    type(nml_item_t), intent(in) :: item
    integer, intent(in) :: line
    character(len=:), allocatable :: where
    if (len(item%origin) > 0) then
      where = item%origin
    else
      where = self%source//':'//format_integer(line)
    end if
  end function item_where

  !> The common message of every refused value of this group.
  subroutine reader_invalid(self, variable, value, allowed, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: variable, value, allowed
    type(status_t), intent(inout) :: status
    call set_status(status, STATUS_INVALID_INPUT, self%where(variable)//': &'//self%group//': '//variable// &
                    ' = '//value//' is not allowed: '//allowed)
  end subroutine reader_invalid

  !> Refuses the first of `names` that the group gives: it is not used here,
  !> for the reason `why` (e.g. "a helix does not use it").
  subroutine reader_refuse_given(self, names, why, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: names(:), why
    type(status_t), intent(inout) :: status
    integer :: k
    if (.not. status%ok()) return
    do k = 1, size(names)
      if (self%has(trim(names(k)))) then
        call self%invalid(trim(names(k)), self%written(trim(names(k))), why, status)
        return
      end if
    end do
  end subroutine reader_refuse_given

  !> The same message for a check made outside a reader (names the line of
  !> the variable if the input assigns it).
  subroutine invalid(input, group, variable, value, allowed, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, value, allowed
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: reader
    call unchecked_reader(input, group, reader)
    call reader%invalid(variable, value, allowed, status)
  end subroutine invalid

  !> 'file:line' where the input assigns `variable` of `group` (or the
  !> group's line, or the file's name), for messages made outside a reader.
  function where_given(input, group, variable, occurrence) result(where)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable
    integer, intent(in), optional :: occurrence   !< of a repeated group
    character(len=:), allocatable :: where
    type(group_reader_t) :: reader
    call unchecked_reader(input, group, reader, occurrence)
    where = reader%where(variable)
  end function where_given

  !> A reader of `group` without the check of its names (for messages).
  subroutine unchecked_reader(input, group, reader, occurrence)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group
    type(group_reader_t), intent(out) :: reader
    integer, intent(in), optional :: occurrence
    integer :: g
    reader%source = input%name
    reader%group = lower(group)
    g = group_index(input, group, occurrence)
    if (g > 0) then
      reader%line = input%groups(g)%line
      reader%items = input%groups(g)%items
    else
      allocate (reader%items(0))
    end if
  end subroutine unchecked_reader

  !> The values assigned to `name`, a variable of extents `dims` (none: a
  !> scalar): the flat (column-major) index of every element given, its value
  !> and the item it came from. A whole assignment fills from the first
  !> element (every element if `exact`); a subscripted one exactly its
  !> section. An element assigned twice in the text is refused; an override
  !> (--set) replaces it. `limit` names the extent in messages.
  subroutine gather(self, name, dims, exact, limit, positions, values, from, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    integer, intent(in) :: dims(:)
    logical, intent(in) :: exact
    integer, allocatable, intent(out) :: positions(:), from(:)
    type(nml_value_t), allocatable, intent(out) :: values(:)
    type(status_t), intent(inout) :: status
    integer :: total, i, k, d, p, lo(2), hi(2), section, r
    integer(int64) :: count
    integer, allocatable :: owner(:), flat(:)
    type(nml_value_t), allocatable :: slot(:)
    character(len=:), allocatable :: here

    allocate (positions(0), from(0), values(0))
    if (.not. status%ok()) return
    total = product(dims)
    allocate (owner(total), slot(total))
    owner = 0
    do i = 1, size(self%items)
      associate (item => self%items(i))
        if (item%name /= lower(name)) cycle
        here = item_where(self, item, item%line)//': &'//self%group//': '//item%name//item%subscript
        count = sum(item%values%repeat)
        if (item%rank == 0) then
          if (count > total) then
            if (size(dims) == 0) then
              call set_status(status, STATUS_INVALID_INPUT, here//' = '//shown_values(item)// &
                              ' is not allowed: a single value is expected, '//format_integer(int(min(count, 999999999_int64)))// &
                              ' are given')
            else
              call set_status(status, STATUS_INVALID_INPUT, here//' = '//shown_values(item)// &
                              ' is not allowed: '//format_integer(int(min(count, 999999999_int64)))// &
                              ' values are more than '//limit)
            end if
            return
          end if
          if (exact .and. count /= total) then
            call set_status(status, STATUS_INVALID_INPUT, here//' = '//shown_values(item)// &
                            ' is not allowed: needs exactly '//format_integer(total)//' values, '// &
                            format_integer(int(count))//' given')
            return
          end if
          flat = [(k, k=1, int(count))]
        else
          if (size(dims) == 0) then
            call set_status(status, STATUS_INVALID_INPUT, here//': '//item%name// &
                            ' is a single value, not a list: write '//item%name//' = value')
            return
          end if
          if (item%rank /= size(dims)) then
            call set_status(status, STATUS_INVALID_INPUT, here//': '//item%name//' has '// &
                            format_integer(size(dims))//' subscript(s), not '//format_integer(item%rank))
            return
          end if
          lo = 1; hi = 1
          do d = 1, item%rank
            if (item%whole(d)) then
              lo(d) = 1; hi(d) = dims(d)
            else
              lo(d) = item%low(d); hi(d) = item%high(d)
            end if
            if (lo(d) < 1 .or. hi(d) > dims(d) .or. lo(d) > hi(d)) then
              call set_status(status, STATUS_INVALID_INPUT, here//': the subscript is not allowed: '// &
                              'index '//format_integer(d)//' must lie in [1, '//format_integer(dims(d))//']')
              if (len(limit) > 0) status%message = status%message//' ('//limit//')'
              return
            end if
          end do
          section = (hi(1) - lo(1) + 1)*(hi(2) - lo(2) + 1)
          if (count /= section) then
            call set_status(status, STATUS_INVALID_INPUT, here//' = '//shown_values(item)// &
                            ' is not allowed: the section holds '//format_integer(section)//' values, '// &
                            format_integer(int(min(count, 999999999_int64)))//' given')
            return
          end if
          if (item%rank == 1) then
            flat = [(k, k=lo(1), hi(1))]
          else
            flat = [((lo(1) + k - 1 + (d - 1)*dims(1), k=1, hi(1) - lo(1) + 1), d=lo(2), hi(2))]
          end if
        end if
        p = 0
        do k = 1, size(item%values)
          do r = 1, int(item%values(k)%repeat)
            p = p + 1
            if (owner(flat(p)) /= 0 .and. len(item%origin) == 0) then
              call set_status(status, STATUS_INVALID_INPUT, item_where(self, item, item%values(k)%line)// &
                              ': &'//self%group//': '//element_name(name, dims, flat(p))// &
                              ' is given twice (also at line '// &
                              format_integer(self%items(owner(flat(p)))%line)//'); give it once')
              return
            end if
            owner(flat(p)) = i
            slot(flat(p)) = item%values(k)
          end do
        end do
      end associate
    end do
    positions = pack([(k, k=1, total)], owner > 0)
    from = owner(positions)
    values = slot(positions)
  end subroutine gather

  pure function shown_values(item) result(text)
    type(nml_item_t), intent(in) :: item
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, min(size(item%values), 6)
      if (k > 1) text = text//', '
      if (item%values(k)%repeat > 1) text = text//format_integer(int(item%values(k)%repeat))//'*'
      text = text//shown_value(item%values(k))
    end do
    if (size(item%values) > 6) text = text//', ... ('//format_integer(size(item%values))//' values)'
  end function shown_values

  !> 'x', 'x(3)' or 'x(1, 3)' for flat element p of a variable of extents dims.
  pure function element_name(name, dims, p) result(text)
    character(len=*), intent(in) :: name
    integer, intent(in) :: dims(:), p
    character(len=:), allocatable :: text
    select case (size(dims))
    case (0)
      text = name
    case (1)
      text = name//'('//format_integer(p)//')'
    case default
      text = name//'('//format_integer(mod(p - 1, dims(1)) + 1)//', '//format_integer((p - 1)/dims(1) + 1)//')'
    end select
  end function element_name

  !> Refuses value `v` of element `p`, which came from item `from`.
  subroutine refuse(self, name, dims, p, from, v, allowed, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, allowed
    integer, intent(in) :: dims(:), p, from
    type(nml_value_t), intent(in) :: v
    type(status_t), intent(inout) :: status
    call set_status(status, STATUS_INVALID_INPUT, item_where(self, self%items(from), v%line)//': &'// &
                    self%group//': '//element_name(name, dims, p)//' = '//shown_value(v)// &
                    ' is not allowed: '//allowed)
  end subroutine refuse

  !> Converts the values of elements `positions` to reals within `b`.
  subroutine take_reals(self, name, dims, positions, values, from, b, x, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: dims(:), positions(:), from(:)
    type(nml_value_t), intent(in) :: values(:)
    type(bounds_t), intent(in) :: b
    real(wp), intent(inout) :: x(:)
    type(status_t), intent(inout) :: status
    integer :: k, outcome
    real(wp) :: value
    do k = 1, size(positions)
      call read_real_token(values(k), value, outcome)
      if (outcome == NUMBER_OK) then
        if (b%allows(value)) then
          x(positions(k)) = value
          cycle
        end if
      end if
      call refuse(self, name, dims, positions(k), from(k), values(k), b%text(), status)
      return
    end do
  end subroutine take_reals

  subroutine get_real(self, name, x, b, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(inout) :: x
    type(bounds_t), intent(in) :: b
    type(status_t), intent(inout) :: status
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    real(wp) :: one(1)
    integer :: no_dims(0)
    call gather(self, name, no_dims, .true., '', positions, values, from, status)
    if (size(positions) == 0 .or. .not. status%ok()) return
    one = x
    call take_reals(self, name, no_dims, positions, values, from, b, one, status)
    x = one(1)
  end subroutine get_real

  !> A vector of fixed length (gravity, origin): given whole with every
  !> component, or element by element.
  subroutine get_real_vector(self, name, x, b, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(inout) :: x(:)
    type(bounds_t), intent(in) :: b
    type(status_t), intent(inout) :: status
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    call gather(self, name, [size(x)], .true., '', positions, values, from, status)
    if (size(positions) == 0 .or. .not. status%ok()) return
    call take_reals(self, name, [size(x)], positions, values, from, b, x, status)
  end subroutine get_real_vector

  !> A list of up to `most` values given without gaps (stations); `x` is
  !> allocated to the number given (0 if the variable is not given).
  subroutine get_real_list(self, name, x, most, b, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), allocatable, intent(out) :: x(:)
    integer, intent(in) :: most
    type(bounds_t), intent(in) :: b
    type(status_t), intent(inout) :: status
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    real(wp), allocatable :: all(:)
    integer :: k
    allocate (x(0))
    call gather(self, name, [most], .false., 'the limit of '//format_integer(most), positions, values, from, status)
    if (size(positions) == 0 .or. .not. status%ok()) return
    do k = 1, size(positions)
      if (positions(k) /= k) then
        call set_status(status, STATUS_INVALID_INPUT, self%where(name)//': &'//self%group//': '// &
                        element_name(name, [most], k)//' is not given: list the values without gaps')
        return
      end if
    end do
    allocate (all(most))
    all = 0
    call take_reals(self, name, [most], positions, values, from, b, all, status)
    if (status%ok()) x = all(:size(positions))
  end subroutine get_real_list

  !> Values per part (element, section, patch): x(i) for parts 1..size(x),
  !> defaults kept where not given; `limit` names the count ('n_elements =
  !> 3'); `given` tells which were given.
  subroutine parts_real(self, name, x, b, limit, status, given)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    real(wp), intent(inout) :: x(:)
    type(bounds_t), intent(in) :: b
    type(status_t), intent(inout) :: status
    logical, intent(out), optional :: given(:)
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    if (present(given)) given = .false.
    call gather(self, name, [size(x)], .false., limit, positions, values, from, status)
    if (.not. status%ok()) return
    call take_reals(self, name, [size(x)], positions, values, from, b, x, status)
    if (present(given)) given(positions) = .true.
  end subroutine parts_real

  recursive subroutine parts_text(self, name, x, limit, status, choices, given)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    character(len=*), intent(inout) :: x(:)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: choices(:)
    logical, intent(out), optional :: given(:)
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    integer :: k
    character(len=32), allocatable :: words(:)
    if (present(given)) given = .false.
    if (self%declared .and. .not. present(choices)) then
      words = declared_words(self, name, status)
      if (size(words) > 0) then
        call parts_text(self, name, x, limit, status, words, given)
        return
      end if
    end if
    call gather(self, name, [size(x)], .false., limit, positions, values, from, status)
    if (.not. status%ok()) return
    do k = 1, size(positions)
      call take_text(self, name, [size(x)], positions(k), from(k), values(k), x(positions(k)), status, choices)
      if (.not. status%ok()) return
    end do
    if (present(given)) given(positions) = .true.
  end subroutine parts_text

  subroutine parts_logical(self, name, x, limit, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    logical, intent(inout) :: x(:)
    type(status_t), intent(inout) :: status
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    integer :: k
    logical :: ok
    type(declaration_t) :: d
    if (self%declared) call find_declared(self, name, VALUE_LOGICAL, d, status)
    call gather(self, name, [size(x)], .false., limit, positions, values, from, status)
    if (.not. status%ok()) return
    do k = 1, size(positions)
      call read_logical_token(values(k), x(positions(k)), ok)
      if (.not. ok) then
        call refuse(self, name, [size(x)], positions(k), from(k), values(k), 'must be .true. or .false.', status)
        return
      end if
    end do
  end subroutine parts_logical

  !> Columns of a matrix x(rows, columns) (points(3, n), origin(3, patches)):
  !> a whole assignment gives complete columns in order; `n_given` is the
  !> last column given, `given` (optional) tells which.
  subroutine get_real_columns(self, name, x, b, limit, n_given, status, given)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    real(wp), intent(inout) :: x(:, :)
    type(bounds_t), intent(in) :: b
    integer, intent(out) :: n_given
    type(status_t), intent(inout) :: status
    logical, intent(out), optional :: given(:)
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    real(wp) :: flat(size(x))
    integer :: i, rows
    n_given = 0
    if (present(given)) given = .false.
    rows = size(x, 1)
    call gather(self, name, shape(x), .false., limit, positions, values, from, status)
    if (.not. status%ok()) return
    do i = 1, size(self%items)
      if (self%items(i)%name /= lower(name) .or. self%items(i)%rank /= 0) cycle
      if (mod(sum(self%items(i)%values%repeat), int(rows, int64)) /= 0) then
        call set_status(status, STATUS_INVALID_INPUT, item_where(self, self%items(i), self%items(i)%line)// &
                        ': &'//self%group//': '//name//' gives '// &
                        format_integer(int(sum(self%items(i)%values%repeat)))//' numbers, not a multiple of '// &
                        format_integer(rows)//' (one column of '//name//'('//format_integer(rows)//', :) each)')
        return
      end if
    end do
    flat = reshape(x, [size(x)])
    call take_reals(self, name, shape(x), positions, values, from, b, flat, status)
    if (.not. status%ok()) return
    x = reshape(flat, shape(x))
    if (size(positions) > 0) n_given = (maxval(positions) - 1)/rows + 1
    if (present(given)) then
      do i = 1, size(positions)
        given((positions(i) - 1)/rows + 1) = .true.
      end do
    end if
  end subroutine get_real_columns

  subroutine get_integer(self, name, i, low, high, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer, intent(inout) :: i
    integer, intent(in) :: low, high
    type(status_t), intent(inout) :: status
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    integer(int64) :: value
    integer :: outcome, no_dims(0)
    call gather(self, name, no_dims, .true., '', positions, values, from, status)
    if (size(positions) == 0 .or. .not. status%ok()) return
    call read_integer_token(values(1), value, outcome)
    if (outcome == NUMBER_OK) then
      if (value >= low .and. value <= high) then
        i = int(value)
        return
      end if
    end if
    call refuse(self, name, no_dims, 1, from(1), values(1), 'must be a whole number in ['// &
                format_integer(low)//', '//format_integer(high)//']', status)
  end subroutine get_integer

  subroutine get_logical(self, name, flag, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    logical, intent(inout) :: flag
    type(status_t), intent(inout) :: status
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    integer :: no_dims(0)
    logical :: ok, value
    type(declaration_t) :: d
    if (self%declared) call find_declared(self, name, VALUE_LOGICAL, d, status)
    call gather(self, name, no_dims, .true., '', positions, values, from, status)
    if (size(positions) == 0 .or. .not. status%ok()) return
    call read_logical_token(values(1), value, ok)
    if (ok) then
      flag = value
    else
      call refuse(self, name, no_dims, 1, from(1), values(1), 'must be .true. or .false.', status)
    end if
  end subroutine get_logical

  !> A quoted text of at most len(x) characters; with `choices`, one of those
  !> words (any case), returned in lower case.
  recursive subroutine get_text(self, name, x, status, choices)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    character(len=*), intent(inout) :: x
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: choices(:)
    integer, allocatable :: positions(:), from(:)
    type(nml_value_t), allocatable :: values(:)
    integer :: no_dims(0)
    character(len=32), allocatable :: words(:)
    if (self%declared .and. .not. present(choices)) then
      words = declared_words(self, name, status)
      if (size(words) > 0) then
        call get_text(self, name, x, status, words)
        return
      end if
    end if
    call gather(self, name, no_dims, .true., '', positions, values, from, status)
    if (size(positions) == 0 .or. .not. status%ok()) return
    call take_text(self, name, no_dims, 1, from(1), values(1), x, status, choices)
  end subroutine get_text

  subroutine take_text(self, name, dims, p, from, v, x, status, choices)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: dims(:), p, from
    type(nml_value_t), intent(in) :: v
    character(len=*), intent(inout) :: x
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: choices(:)
    character(len=:), allocatable :: list, word, quotes
    integer :: j
    logical :: text_given
    ! a file's text goes in quotes; on the command line a word needs none
    ! (--set solver%method=bdf), since the shell removes quotes unless escaped
    quotes = ' (in quotes)'
    text_given = v%kind == VALUE_TEXT
    if (len(self%items(from)%origin) > 0) then
      quotes = ''
      text_given = .true.
    end if
    if (present(choices)) then
      list = ''
      do j = 1, size(choices)
        list = list//' '//trim(choices(j))
      end do
      word = lower(trim(adjustl(v%text)))
      if (.not. text_given .or. .not. any(choices == word)) then
        call refuse(self, name, dims, p, from, v, 'must be one of'//list//quotes, status)
        return
      end if
      x = word
      return
    end if
    if (.not. text_given) then
      call refuse(self, name, dims, p, from, v, 'must be a text in quotes', status)
    else if (len(v%text) > len(x)) then
      call refuse(self, name, dims, p, from, v, 'is longer than the '//format_integer(len(x))// &
                  ' characters allowed', status)
    else
      x = v%text
    end if
  end subroutine take_text


  ! ------------------------------------------------- variables as declared

  !> The declaration of `name` in this reader's group, which must be a
  !> variable of `kind`: a reader asking for anything else is a bug.
  subroutine find_declared(self, name, kind, d, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind
    type(declaration_t), intent(out) :: d
    type(status_t), intent(inout) :: status
    integer :: k
    if (.not. status%ok()) return
    if (allocated(self%table)) then
      k = find_declaration(self%table, name)
    else
      k = find_declaration(self%group, name)
    end if
    if (k == 0) then
      call set_status(status, STATUS_INTERNAL, '&'//self%group//': '//name//' is read but not declared (a bug: '// &
                      'src/io/io_declarations_*.f90)')
      return
    end if
    d = declaration(k)
    if (d%kind /= kind) call set_status(status, STATUS_INTERNAL, '&'//self%group//': '//name// &
                                        ' is read as another type than declared (a bug)')
  end subroutine find_declared

  !> The declared range of real variable `name` (for checks of values that
  !> follow from it, such as &sweep's NAME_range).
  subroutine reader_bounds(self, name, b, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    type(bounds_t), intent(out) :: b
    type(status_t), intent(inout) :: status
    type(declaration_t) :: d
    call find_declared(self, name, VALUE_REAL, d, status)
    if (.not. status%ok()) return
    if (d%open_low) then
      b = above(d%low, d%high, trim(d%unit))
    else
      b = in_range(d%low, d%high, trim(d%unit))
    end if
  end subroutine reader_bounds

  !> The declared words of text variable `name` (none: any text).
  function declared_words(self, name, status) result(words)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    type(status_t), intent(inout) :: status
    character(len=32), allocatable :: words(:)
    type(declaration_t) :: d
    integer :: i, n
    call find_declared(self, name, VALUE_WORDS, d, status)
    ! a word starts where a blank is followed by a letter
    n = 0
    do i = 1, len_trim(d%choices)
      if (starts(i)) n = n + 1
    end do
    allocate (words(n))
    n = 0
    do i = 1, len_trim(d%choices)
      if (starts(i)) then
        n = n + 1
        words(n) = d%choices(i:i - 1 + index(d%choices(i:)//' ', ' ') - 1)
      end if
    end do
  contains
    logical function starts(i)
      integer, intent(in) :: i
      starts = d%choices(i:i) /= ' '
      if (i > 1) starts = starts .and. d%choices(i - 1:i - 1) == ' '
    end function starts
  end function declared_words

  subroutine get_declared_real(self, name, x, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(inout) :: x
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    call self%bounds(name, b, status)
    call get_real(self, name, x, b, status)
  end subroutine get_declared_real

  subroutine get_declared_vector(self, name, x, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(inout) :: x(:)
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    call self%bounds(name, b, status)
    call get_real_vector(self, name, x, b, status)
  end subroutine get_declared_vector

  subroutine get_declared_list(self, name, x, most, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), allocatable, intent(out) :: x(:)
    integer, intent(in) :: most
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    call self%bounds(name, b, status)
    call get_real_list(self, name, x, most, b, status)
  end subroutine get_declared_list

  subroutine parts_declared_real(self, name, x, limit, status, given)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    real(wp), intent(inout) :: x(:)
    type(status_t), intent(inout) :: status
    logical, intent(out), optional :: given(:)
    type(bounds_t) :: b
    if (present(given)) given = .false.
    call self%bounds(name, b, status)
    call parts_real(self, name, x, b, limit, status, given)
  end subroutine parts_declared_real

  subroutine get_declared_columns(self, name, x, limit, n_given, status, given)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name, limit
    real(wp), intent(inout) :: x(:, :)
    integer, intent(out) :: n_given
    type(status_t), intent(inout) :: status
    logical, intent(out), optional :: given(:)
    type(bounds_t) :: b
    n_given = 0
    if (present(given)) given = .false.
    call self%bounds(name, b, status)
    call get_real_columns(self, name, x, b, limit, n_given, status, given)
  end subroutine get_declared_columns

  subroutine get_declared_integer(self, name, i, status)
    class(group_reader_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer, intent(inout) :: i
    type(status_t), intent(inout) :: status
    type(declaration_t) :: d
    call find_declared(self, name, VALUE_INTEGER, d, status)
    if (.not. status%ok()) return
    call get_integer(self, name, i, nint(d%low), nint(d%high), status)
  end subroutine get_declared_integer

  ! ----------------------------------------------------------------- bounds

  !> low <= x <= high, in `unit` (shown in messages).
  pure function in_range(low, high, unit) result(b)
    real(wp), intent(in) :: low, high
    character(len=*), intent(in) :: unit
    type(bounds_t) :: b
    b%low = low
    b%high = high
    b%unit = unit
  end function in_range

  !> low < x <= high, in `unit`.
  pure function above(low, high, unit) result(b)
    real(wp), intent(in) :: low, high
    character(len=*), intent(in) :: unit
    type(bounds_t) :: b
    b = in_range(low, high, unit)
    b%open_low = .true.
  end function above

  elemental logical function bounds_allow(self, x)
    class(bounds_t), intent(in) :: self
    real(wp), intent(in) :: x
    bounds_allow = .false.
    if (.not. ieee_is_finite(x)) return
    if (x > self%high) return
    if (self%open_low) then
      bounds_allow = x > self%low
    else
      bounds_allow = x >= self%low
    end if
  end function bounds_allow

  pure function bounds_text(self) result(text)
    class(bounds_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (self%open_low) then
      text = 'must be a finite number > '//bound_text(self%low)//' and <= '//bound_text(self%high)
    else
      text = 'must be a finite number in ['//bound_text(self%low)//', '//bound_text(self%high)//']'
    end if
    if (allocated(self%unit)) then
      if (len(self%unit) > 0) text = text//' ('//self%unit//')'
    end if
  end function bounds_text

  ! ------------------------------------------ checks of values already read

  !> A model that cannot be built from the input is bad input (exit status 1,
  !> nothing written), whatever the builder's code, unless a file could not be read.
  pure subroutine mark_input_failure(status)
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .and. status%code /= STATUS_IO) status%code = STATUS_INVALID_INPUT
  end subroutine mark_input_failure

  subroutine check_finite(input, group, variable, value, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. ieee_is_finite(value)) &
      call invalid(input, group, variable, format_real(value), 'must be a finite number', status)
  end subroutine check_finite

  !> value > 0 and finite; `unit` is shown in the message.
  subroutine check_positive(input, group, variable, value, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    if (.not. status%ok()) return
    b = above(0.0_wp, huge(1.0_wp), unit)
    if (.not. b%allows(value)) &
      call invalid(input, group, variable, format_real(value), 'must be a finite number > 0 ('//unit//')', status)
  end subroutine check_positive

  subroutine check_nonnegative(input, group, variable, value, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    if (.not. status%ok()) return
    b = in_range(0.0_wp, huge(1.0_wp), unit)
    if (.not. b%allows(value)) &
      call invalid(input, group, variable, format_real(value), 'must be a finite number >= 0 ('//unit//')', status)
  end subroutine check_nonnegative

  subroutine check_range(input, group, variable, value, low, high, unit, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, unit
    real(wp), intent(in) :: value, low, high
    type(status_t), intent(inout) :: status
    type(bounds_t) :: b
    if (.not. status%ok()) return
    b = in_range(low, high, unit)
    if (.not. b%allows(value)) call invalid(input, group, variable, format_real(value), b%text(), status)
  end subroutine check_range

  !> A keyword among `choices` (compared in lower case, trailing blanks ignored).
  subroutine check_choice(input, group, variable, value, choices, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: group, variable, value
    character(len=*), intent(in) :: choices(:)
    type(status_t), intent(inout) :: status
    integer :: j
    character(len=:), allocatable :: list
    if (.not. status%ok()) return
    if (any(choices == lower(trim(adjustl(value))))) return
    list = ''
    do j = 1, size(choices)
      list = list//' '//trim(choices(j))
    end do
    call invalid(input, group, variable, "'"//trim(value)//"'", 'must be one of'//list, status)
  end subroutine check_choice
end module io_input
