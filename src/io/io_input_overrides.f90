!> Command-line overrides of an input: --set group%variable=value replaces or
!> adds an assignment, --unset group%variable removes every one; a repeated
!> group is addressed as group(k) or group(name). What they change is checked
!> where the group is read (io_group_reader), like the text's own values.
submodule (io_input_text) io_input_overrides
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: lower, format_integer
  use io_namelist, only: nml_group_t, nml_item_t, parse_assignment
  implicit none (type, external)

contains

  !> Applies one command-line override `group%variable=values` (or
  !> `group%variable(i)=values`): it replaces what the text assigns to that
  !> variable (or element), or adds it; the group is added if absent. A group
  !> the input gives more than once must be addressed: `group(k)%...` (its
  !> k-th occurrence) or `group(name)%...` (the one with name = 'name');
  !> without that the override is refused, never applied to one of them
  !> silently. Whether the group and variable exist is checked where the
  !> group is read.
  module subroutine input_override(self, spec, status)
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
  module subroutine input_unset(self, spec, status)
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
end submodule io_input_overrides
