!> The reader every input group is read through.
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
!> used. The values themselves are gathered and converted in the submodule
!> io_group_reader_values.
module io_group_reader
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_INTERNAL
  use base_text, only: lower, format_integer
  use io_namelist, only: nml_item_t, shown_value
  use io_declaration, only: declaration_t, VALUE_REAL, VALUE_INTEGER, VALUE_LOGICAL, VALUE_WORDS
  use io_input_declarations, only: find_declaration, declaration, declared_names
  use io_input_text, only: input_text_t, group_index, in_list
  use io_input_bounds, only: bounds_t, in_range, above
  implicit none (type, external)
  private
  public :: group_reader_t, open_group, invalid, where_given, indexed_name
  ! for the submodule io_group_reader_values (gfortran drops a private
  ! procedure that only a submodule calls)
  public :: item_where, shown_values, find_declared, declared_words

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

  interface
    module subroutine get_real(self, name, x, b, status)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: x
      type(bounds_t), intent(in) :: b
      type(status_t), intent(inout) :: status
    end subroutine get_real

    module subroutine get_real_vector(self, name, x, b, status)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: x(:)
      type(bounds_t), intent(in) :: b
      type(status_t), intent(inout) :: status
    end subroutine get_real_vector

    module subroutine get_real_list(self, name, x, most, b, status)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(out) :: x(:)
      integer, intent(in) :: most
      type(bounds_t), intent(in) :: b
      type(status_t), intent(inout) :: status
    end subroutine get_real_list

    module subroutine parts_real(self, name, x, b, limit, status, given)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name, limit
      real(wp), intent(inout) :: x(:)
      type(bounds_t), intent(in) :: b
      type(status_t), intent(inout) :: status
      logical, intent(out), optional :: given(:)
    end subroutine parts_real

    recursive module subroutine parts_text(self, name, x, limit, status, choices, given)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name, limit
      character(len=*), intent(inout) :: x(:)
      type(status_t), intent(inout) :: status
      character(len=*), intent(in), optional :: choices(:)
      logical, intent(out), optional :: given(:)
    end subroutine parts_text

    module subroutine parts_logical(self, name, x, limit, status)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name, limit
      logical, intent(inout) :: x(:)
      type(status_t), intent(inout) :: status
    end subroutine parts_logical

    module subroutine get_real_columns(self, name, x, b, limit, n_given, status, given)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name, limit
      real(wp), intent(inout) :: x(:, :)
      type(bounds_t), intent(in) :: b
      integer, intent(out) :: n_given
      type(status_t), intent(inout) :: status
      logical, intent(out), optional :: given(:)
    end subroutine get_real_columns

    module subroutine get_integer(self, name, i, low, high, status)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name
      integer, intent(inout) :: i
      integer, intent(in) :: low, high
      type(status_t), intent(inout) :: status
    end subroutine get_integer

    module subroutine get_logical(self, name, flag, status)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name
      logical, intent(inout) :: flag
      type(status_t), intent(inout) :: status
    end subroutine get_logical

    recursive module subroutine get_text(self, name, x, status, choices)
      class(group_reader_t), intent(in) :: self
      character(len=*), intent(in) :: name
      character(len=*), intent(inout) :: x
      type(status_t), intent(inout) :: status
      character(len=*), intent(in), optional :: choices(:)
    end subroutine get_text
  end interface

contains

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

  !> 'name(i)': element i of a list variable, as messages name it.
  pure function indexed_name(name, i) result(text)
    character(len=*), intent(in) :: name
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    text = name//'('//format_integer(i)//')'
  end function indexed_name
end module io_group_reader
