!> The templates of `slidesim --default-input SCENARIO`, generated: every
!> comment comes from the declaration of the variable (io_declarations_*,
!> or a surface kind's or force law's own parameters, base_spec): its unit,
!> meaning, what is allowed and, where the value shown is not the default,
!> the default. What a scenario's template shows is a short spec
!> (inputs/templates/specs/<scenario>.spec, compiled in):
!>
!>     an introduction (the lines before the first group)
!>     &group ! a note on the group          (a group, in the template's order)
!>     name                                  (shown with its declared default)
!>     name = value ! a note                 (an example value, a note on it)
!>     - name = value ! why                  (written commented out, and why)
!>     | name = v1, v2, v3                   (consecutive | lines: aligned columns)
!>     + more values                         (continues the value above on a new line)
!>     # a comment of the spec               (not written)
!>
!> A name that is not declared, or a declared default that is not a value
!> (none, pi/2) without one given, is an error of the spec
!> (tests/cli/template_declarations.sh runs every scenario's).
module io_templates
  use base_kinds, only: wp
  use base_text, only: lower, format_integer
  use base_spec, only: parameter_t, spec_t
  use io_declaration, only: declaration_t, bound_text, words_joined, VALUE_REAL, VALUE_INTEGER, VALUE_WORDS
  use io_input_declarations, only: find_declaration, declaration
  use io_point_mass_config, only: point_mass_renamed
  use io_rider_config, only: rider_friction_defaults
  use io_kind_parameters, only: variable_name
  use io_surface_config, only: surface_kind_names
  use io_friction_config, only: friction_law_names
  use geometry_surface_kind, only: surface_kind_t
  use geometry_surface_factory, only: surface_kinds
  use kinetostatics_force_law, only: force_law_kind_t
  use kinetostatics_force_law_factory, only: force_law_kinds
  implicit none (type, external)
  private
  public :: template_from_spec

  character(len=*), parameter :: nl = new_line('a')
  integer, parameter :: comment_column = 36   !< where a variable's comment starts
  integer, parameter :: line_width = 110      !< comments wrap before it
  integer, parameter :: intro_width = 78
  character(len=*), parameter :: kept_blank = achar(1)   !< a blank where no line may break

  !> One variable of the spec, as written.
  type :: item_t
    character(len=:), allocatable :: name, value, note
    logical :: commented = .false.
  end type item_t

  !> Where the generation is: the scenario, the group open and its kind.
  type :: state_t
    character(len=:), allocatable :: scenario, group, selected_kind, error
  end type state_t

contains

  !> The template of `scenario` from its spec; `error` is '' or says what in
  !> the spec is wrong (then `text` is incomplete).
  subroutine template_from_spec(scenario, spec, text, error)
    character(len=*), intent(in) :: scenario, spec
    character(len=:), allocatable, intent(out) :: text, error
    type(state_t) :: s
    type(item_t), allocatable :: block(:)
    type(item_t) :: pending
    logical :: has_pending
    character(len=:), allocatable :: line, intro, code, note
    integer :: start, i, line_number

    s%scenario = scenario
    s%group = ''
    s%selected_kind = ''
    s%error = ''
    intro = ''
    text = ''
    allocate (block(0))
    has_pending = .false.
    start = 1
    line_number = 0
    do i = 1, len(spec) + 1
      if (i <= len(spec)) then
        if (spec(i:i) /= nl) cycle
      end if
      line = trim(spec(start:i - 1))
      start = i + 1
      line_number = line_number + 1
      if (len(line) == 0) cycle
      if (line(1:1) == '#') cycle
      ! a variable is written when no value line can follow; a block when it ends
      if (line(1:1) /= '+') call write_pending()
      if (line(1:1) /= '|' .and. size(block) > 0) call write_block()
      if (len(s%group) == 0 .and. .not. opens_group(line)) then
        intro = intro//' '//line
        cycle
      end if
      call split_note(line, code, note)
      select case (line(1:1))
      case ('&')
        if (len(s%group) == 0) text = header(scenario, intro)
        if (len(s%group) > 0) text = text//'/'//nl
        s%group = lower(trim(code(2:)))
        s%selected_kind = ''
        text = text//with_comment('&'//s%group, note)
      case ('|')
        block = [block, parsed(trim(adjustl(code(2:))), note, .false.)]
      case ('+')
        if (.not. has_pending) then
          call spec_error('a "+" line continues only a variable of its own (not a "|" line)')
        else
          pending%value = pending%value//nl//trim(adjustl(code(2:)))
        end if
      case ('-')
        pending = parsed(trim(adjustl(code(2:))), note, .true.)
        has_pending = .true.
      case default
        pending = parsed(code, note, .false.)
        has_pending = .true.
      end select
      if (len(s%error) > 0) exit
    end do
    call write_pending()
    if (size(block) > 0) call write_block()
    if (len(s%group) > 0) text = text//'/'//nl
    if (len(s%group) == 0) call spec_error('no group')
    error = ''
    if (len(s%error) > 0) error = scenario//'.spec:'//format_integer(line_number)//': '//s%error

  contains

    subroutine write_pending()
      if (has_pending) text = text//variable_lines(pending)
      has_pending = .false.
    end subroutine write_pending


    !> The aligned lines of the block of "|" variables: names, then each
    !> value under the same value of the lines above.
    subroutine write_block()
      character(len=:), allocatable :: values(:), row
      integer, allocatable :: widths(:)
      integer :: k, j, name_width
      name_width = maxval([(len(block(k)%name), k = 1, size(block))])
      allocate (widths(0))
      do k = 1, size(block)
        values = items(block(k)%value)
        if (size(values) > size(widths)) widths = [widths, [(0, j = size(widths) + 1, size(values))]]
        do j = 1, size(values)
          widths(j) = max(widths(j), len_trim(values(j)))
        end do
      end do
      do k = 1, size(block)
        values = items(block(k)%value)
        row = block(k)%name//repeat(' ', name_width - len(block(k)%name))//' ='
        do j = 1, size(values)
          ! every row as long, so that their comments line up
          if (j < size(values)) then
            row = row//' '//trim(values(j))//','//repeat(' ', widths(j) - len_trim(values(j)))
          else
            row = row//' '//trim(values(j))//repeat(' ', sum(widths(j:)) + 2 * (size(widths) - j) - &
                                                             len_trim(values(j)))
          end if
        end do
        block(k)%value = row(index(row, '=') + 2:)
        block(k)%name = row(:index(row, '=') - 2)
      end do
      do k = 1, size(block)
        text = text//variable_lines(block(k))
      end do
      deallocate (block)
      allocate (block(0))
    end subroutine write_block

    !> `name = value` (or `name`: its declared default) and its note.
    function parsed(assignment, note, commented) result(item)
      character(len=*), intent(in) :: assignment, note
      logical, intent(in) :: commented
      type(item_t) :: item
      integer :: equals
      equals = index(assignment, '=')
      if (equals > 0) then
        item%name = lower(trim(assignment(:equals - 1)))
        item%value = trim(adjustl(assignment(equals + 1:)))
      else
        item%name = lower(trim(assignment))
        item%value = ''
      end if
      item%note = note
      item%commented = commented
    end function parsed

    !> The lines of one variable: `name = value`, its comment (wrapped).
    function variable_lines(item) result(lines)
      type(item_t), intent(in) :: item
      character(len=:), allocatable :: lines, value, first, rest
      type(declaration_t) :: d
      logical :: found
      integer :: cut
      lines = ''
      if (len(s%error) > 0) return
      call find(s, item%name, d, found)
      if (.not. found) then
        call spec_error('&'//s%group//': '//item%name//' is not declared')
        return
      end if
      value = item%value
      if (len(value) == 0) then
        value = trim(d%default)
        if (.not. is_value(value)) then
          call spec_error('&'//s%group//': '//item%name//': its default "'//value//'" is not a value: give one')
          return
        end if
      end if
      if (.not. item%commented .and. (item%name == 'kind' .or. item%name == 'friction')) &
        s%selected_kind = lower(unquoted(value))
      ! a value over several lines: the rest under the first
      cut = index(value, nl)
      if (cut == 0) cut = len(value) + 1
      first = '  '//item%name//' = '//value(:cut - 1)
      if (item%commented) first = '  ! '//first(3:)
      lines = with_comment(first, comment(d, value, item%note))
      if (cut <= len(value)) then
        rest = value(cut + 1:)
        cut = len(first) - len(value(:index(value, nl) - 1))
        do while (len(rest) > 0)
          if (index(rest, nl) == 0) rest = rest//nl
          lines = lines//merge('  !', '   ', item%commented)//repeat(' ', cut - 3)//rest(:index(rest, nl))
          rest = rest(index(rest, nl) + 1:)
        end do
      end if
    end function variable_lines

    subroutine spec_error(message)
      character(len=*), intent(in) :: message
      if (len(s%error) == 0) s%error = message
    end subroutine spec_error
  end subroutine template_from_spec

  !> Whether `line` is `&group` (or `&group ! note`): the introduction may
  !> have a line that starts with a group's name in its text.
  pure logical function opens_group(line)
    character(len=*), intent(in) :: line
    integer :: after
    opens_group = .false.
    if (line(1:1) /= '&') return
    after = verify(line(2:), 'abcdefghijklmnopqrstuvwxyz_0123456789') + 1
    if (after == 1) then
      opens_group = .true.
    else
      opens_group = after > 2 .and. (len_trim(line(after:)) == 0 .or. index(adjustl(line(after:)), '!') == 1)
    end if
  end function opens_group

  !> The template's first lines: what it is, the spec's introduction, how to read it.
  function header(scenario, intro) result(text)
    character(len=*), intent(in) :: scenario, intro
    character(len=:), allocatable :: text
    text = wrapped('Template of the '//scenario//' scenario (slidesim --default-input '//scenario//'): '// &
                   trim(adjustl(intro))//' Each comment gives the unit and the values allowed, the meaning '// &
                   'and, where the value shown is not the default, the default (docs/inputs.md). Generated from '// &
                   'the declarations of the input variables and inputs/templates/specs/'//scenario//'.spec.', &
                   '! ', intro_width)
  end function header

  !> `code` and its comment from column comment_column (or two blanks after
  !> a longer code), the comment wrapped at line_width under itself.
  function with_comment(code, text) result(lines)
    character(len=*), intent(in) :: code, text
    character(len=:), allocatable :: lines, continued
    integer :: column
    if (len(text) == 0) then
      lines = code//nl
      return
    end if
    column = max(comment_column, len(code) + 3)
    lines = wrapped(text, '! ', max(line_width - column + 1, 30))
    continued = repeat(' ', column - 1)
    lines = code//repeat(' ', column - 1 - len(code))//replace_newlines(lines(:len(lines) - 1), nl//continued)//nl
    lines = replaced(lines, kept_blank, ' ')
  end function with_comment

  !> The comment of a variable: its unit and what is allowed first (on the
  !> variable's line, where tests/cli/check_template_declarations.py reads
  !> them), its meaning, the default if `value` is not it, the spec's note.
  function comment(d, value, note) result(text)
    type(declaration_t), intent(in) :: d
    character(len=*), intent(in) :: value, note
    character(len=:), allocatable :: text, meaning
    text = ''
    if (len_trim(d%unit) > 0 .and. trim(d%unit) /= '1') text = trim(d%unit)
    if (len(text) > 0 .and. len(allowed_values(d)) > 0) text = text//', '
    text = text//allowed_values(d)
    meaning = plain(trim(d%meaning))
    if (len_trim(d%shape) > 0) meaning = meaning//' ('//shape_text(trim(d%shape))//')'
    if (len(text) > 0) text = text//'; '
    text = text//meaning
    if (.not. same_values(value, trim(d%default))) text = text//'; default '//plain(trim(d%default))
    if (len(note) > 0) text = text//'; '//note
  end function comment

  pure function shape_text(shape) result(text)
    character(len=*), intent(in) :: shape
    character(len=:), allocatable :: text
    if (verify(shape, '0123456789') == 0) then
      text = shape//' values'
    else
      text = shape
    end if
  end function shape_text

  !> What the declaration allows, in plain text: '> 0 .. 50', 'whole number
  !> 1 .. 40', 'one of: adams, bdf'; '' for logicals and free texts.
  function allowed_values(d) result(text)
    type(declaration_t), intent(in) :: d
    character(len=:), allocatable :: text
    text = ''
    select case (d%kind)
    case (VALUE_REAL, VALUE_INTEGER)
      if (d%low < -huge(1.0_wp) / 2 .or. d%high > huge(1.0_wp) / 2) return
      ! a range is never wrapped: its blanks are kept_blank until the lines are made
      text = number_text(d%low)//kept_blank//'..'//kept_blank//number_text(d%high)
      if (d%open_low) text = '>'//kept_blank//text
      if (d%kind == VALUE_INTEGER) text = 'whole number '//text
    case (VALUE_WORDS)
      if (len_trim(d%choices) > 0) text = 'one of '//words_joined(trim(adjustl(d%choices)), ', ')
    end select
  end function allowed_values

  !> A bound or default as one would type it: 40, 0.01, 1e-14, 1e6.
  pure function number_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    real(wp) :: mantissa
    integer :: e
    if (x == 0) then
      text = '0'
      return
    end if
    e = floor(log10(abs(x)))
    mantissa = x / 10.0_wp**e
    if ((abs(x) < 1e-3_wp .or. abs(x) >= 1e5_wp) .and. abs(mantissa - nint(mantissa)) < 1e-9_wp) then
      text = format_integer(nint(mantissa))//'e'//format_integer(e)
    else if (x == aint(x) .and. abs(x) < huge(1)) then
      text = format_integer(int(x))
    else
      text = bound_text(x)
    end if
  end function number_text

  !> The declaration of `name` in the open group: a declared variable, else
  !> a parameter of the group's chosen kind (surface kind, friction law),
  !> else of any kind (a variable written commented out for another kind).
  subroutine find(s, name, d, found)
    type(state_t), intent(in) :: s
    character(len=*), intent(in) :: name
    type(declaration_t), intent(out) :: d
    logical, intent(out) :: found
    type(surface_kind_t), allocatable :: surfaces(:)
    type(force_law_kind_t), allocatable :: laws(:)
    type(spec_t) :: defaults
    character(len=:), allocatable :: table
    integer :: k, pass
    table = s%group
    if (table == 'identify') table = s%scenario   ! &identify of identify_rider, of identify_water
    k = find_declaration(table, name)
    found = k > 0
    if (found) then
      d = declaration(k)
      ! the words the reader takes, from the registries
      if (name == 'kind' .and. (s%group == 'surface' .or. s%group == 'shape')) &
        d%choices = joined(surface_kind_names())
      if (name == 'friction') d%choices = joined(friction_law_names())
      return
    end if
    do pass = 1, 2   ! the chosen kind, then any
      select case (s%group)
      case ('surface', 'shape')
        surfaces = surface_kinds()
        do k = 1, size(surfaces)
          if (pass == 1 .and. surfaces(k)%name /= s%selected_kind) cycle
          call find_parameter(surfaces(k)%parameters, name, d, found)
          if (found) return
        end do
      case ('point_mass', 'sled', 'contact', 'rider')
        laws = force_law_kinds()
        do k = 1, size(laws)
          if (pass == 1 .and. laws(k)%name /= s%selected_kind) cycle
          if (s%group == 'point_mass') then
            call find_parameter(laws(k)%parameters, name, d, found, point_mass_renamed)
          else
            call find_parameter(laws(k)%parameters, name, d, found)
          end if
          if (found .and. s%group == 'rider') then   ! the rider's own defaults (io_rider_config)
            defaults = rider_friction_defaults()
            if (defaults%kind == laws(k)%name .and. defaults%has(name)) d%default = number_text(defaults%value(name))
          end if
          if (found) return
        end do
      end select
    end do
  end subroutine find

  pure function joined(names) result(text)
    character(len=*), intent(in) :: names(:)
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, size(names)
      text = text//' '//trim(names(i))
    end do
  end function joined

  !> The parameter held by the variable `name` (renamed: `rename`) as a declaration.
  subroutine find_parameter(parameters, name, d, found, rename)
    type(parameter_t), intent(in) :: parameters(:)
    character(len=*), intent(in) :: name
    type(declaration_t), intent(out) :: d
    logical, intent(out) :: found
    character(len=*), intent(in), optional :: rename(:)
    character(len=:), allocatable :: default
    integer :: j, i
    found = .false.
    do j = 1, size(parameters)
      if (variable_name(parameters(j)%name, rename) /= name) cycle
      found = .true.
      d%name = name
      d%unit = parameters(j)%unit
      d%meaning = parameters(j)%meaning
      d%low = parameters(j)%low
      d%high = parameters(j)%high
      d%open_low = parameters(j)%open_low
      if (parameters(j)%count > 1) d%shape = format_integer(parameters(j)%count)
      if (parameters(j)%count == 0) d%shape = 'a list'
      if (parameters(j)%required) then
        d%default = 'none (required)'
      else
        default = ''
        do i = 1, size(parameters(j)%default)
          if (i > 1) default = default//', '
          default = default//number_text(parameters(j)%default(i))
        end do
        d%default = default
      end if
      return
    end do
  end subroutine find_parameter

  !> `line` without its note: the text after the first '!' outside quotes.
  subroutine split_note(line, code, note)
    character(len=*), intent(in) :: line
    character(len=:), allocatable, intent(out) :: code, note
    integer :: i
    logical :: quoted
    quoted = .false.
    do i = 1, len(line)
      if (line(i:i) == '''') quoted = .not. quoted
      if (line(i:i) == '!' .and. .not. quoted) then
        code = trim(line(:i - 1))
        note = trim(adjustl(line(i + 1:)))
        return
      end if
    end do
    code = line
    note = ''
  end subroutine split_note

  !> The values of a list, split at the commas outside quotes (a new line is a blank).
  function items(list) result(values)
    character(len=*), intent(in) :: list
    character(len=:), allocatable :: values(:)
    character(len=:), allocatable :: text
    integer :: i, start, width
    logical :: quoted
    text = replace_newlines(list, ' ')
    width = max(1, len(text))
    allocate (character(len=width) :: values(0))
    quoted = .false.
    start = 1
    do i = 1, len(text) + 1
      if (i <= len(text)) then
        if (text(i:i) == '''') quoted = .not. quoted
        if (text(i:i) /= ',' .or. quoted) cycle
      end if
      values = [character(len=width) :: values, adjustl(text(start:i - 1))]
      start = i + 1
    end do
  end function items

  !> Whether `text` is a value the namelist reader takes: numbers, quoted
  !> texts or logicals, separated by commas (not 'none', 'pi/2', '<scenario>.h5').
  function is_value(text) result(ok)
    character(len=*), intent(in) :: text
    logical :: ok
    character(len=:), allocatable :: values(:)
    character(len=:), allocatable :: v
    integer :: i
    values = items(text)
    ok = size(values) > 0
    do i = 1, size(values)
      v = lower(trim(values(i)))
      if (len(v) == 0) then
        ok = .false.
      else if (v(1:1) == '''') then
        ok = ok .and. len(v) >= 2 .and. v(len(v):) == '''' .and. index(v, '<') == 0
      else if (v /= '.true.' .and. v /= '.false.') then
        ok = ok .and. is_number(v)
      end if
    end do
  end function is_value

  pure logical function is_number(text)
    character(len=*), intent(in) :: text
    is_number = verify(lower(trim(text)), '0123456789.+-ed') == 0 .and. scan(text, '0123456789') > 0
  end function is_number

  !> Whether two lists hold the same values (numbers compared as numbers).
  function same_values(a, b) result(same)
    character(len=*), intent(in) :: a, b
    logical :: same
    character(len=:), allocatable :: x(:), y(:)
    real(wp) :: p, q
    integer :: i, ios_p, ios_q
    same = .false.
    if (.not. is_value(b)) return
    x = items(a)
    y = items(b)
    if (size(x) /= size(y)) return
    do i = 1, size(x)
      if (lower(trim(x(i))) == lower(trim(y(i)))) cycle
      if (.not. (is_number(x(i)) .and. is_number(y(i)))) return
      read (x(i), *, iostat=ios_p) p
      read (y(i), *, iostat=ios_q) q
      if (ios_p /= 0 .or. ios_q /= 0 .or. p /= q) return
    end do
    same = .true.
  end function same_values

  !> A text without its quotes.
  pure function unquoted(text) result(bare)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: bare
    bare = trim(adjustl(text))
    if (len(bare) >= 2) then
      if (bare(1:1) == '''' .and. bare(len(bare):) == '''') bare = bare(2:len(bare) - 1)
    end if
  end function unquoted

  !> Markdown's code marks taken out of a declaration's text.
  pure function plain(text) result(bare)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: bare
    integer :: i
    bare = ''
    do i = 1, len(text)
      if (text(i:i) /= '`') bare = bare//text(i:i)
    end do
  end function plain

  !> `text` in lines of at most `width` characters (a longer word stands
  !> alone), each after `prefix` and ending in a new line.
  pure function wrapped(text, prefix, width) result(lines)
    character(len=*), intent(in) :: text, prefix
    integer, intent(in) :: width
    character(len=:), allocatable :: lines, line, word
    integer :: i, start
    lines = ''
    line = ''
    start = 1
    do i = 1, len(text) + 1
      if (i <= len(text)) then
        if (text(i:i) /= ' ') cycle
      end if
      word = text(start:i - 1)
      start = i + 1
      if (len(word) == 0) cycle
      if (len(line) > 0 .and. len(prefix) + len(line) + 1 + len(word) > width) then
        lines = lines//prefix//line//nl
        line = ''
      end if
      if (len(line) > 0) line = line//' '
      line = line//word
    end do
    if (len(line) > 0 .or. len(lines) == 0) lines = lines//prefix//line//nl
  end function wrapped

  !> `text` with each new line replaced by `by`.
  pure function replace_newlines(text, by) result(changed)
    character(len=*), intent(in) :: text, by
    character(len=:), allocatable :: changed
    changed = replaced(text, nl, by)
  end function replace_newlines

  !> `text` with each character `what` replaced by `by`.
  pure function replaced(text, what, by) result(changed)
    character(len=*), intent(in) :: text, by
    character(len=1), intent(in) :: what
    character(len=:), allocatable :: changed
    integer :: i
    changed = ''
    do i = 1, len(text)
      if (text(i:i) == what) then
        changed = changed//by
      else
        changed = changed//text(i:i)
      end if
    end do
  end function replaced
end module io_templates
