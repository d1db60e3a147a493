!> The values of one variable of a group: gathered from the assignments that
!> give them (whole, by element or by section; --set replaces), each refused
!> or converted (a real in its bounds, a whole number, a logical, a text or
!> one of its words), with the message of io_group_reader.
submodule (io_group_reader) io_group_reader_values
  use base_kinds, only: wp, int64
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: lower, format_integer
  use io_namelist, only: nml_item_t, nml_value_t, read_real_token, read_integer_token, read_logical_token, &
    shown_value, VALUE_TEXT, NUMBER_OK
  implicit none (type, external)

contains

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
                              subscript_problem(item%name, item%rank, d, lo(d), hi(d), dims(d)))
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

  !> Why subscript d (lo:hi, one index when lo = hi) of `name` does not fit
  !> its extent 1:n, naming the index given: 'index 2 of scales lies outside
  !> [1, 1]'; of an array of rank 2 'the second index 4 of points ...'.
  pure function subscript_problem(name, rank, d, lo, hi, n) result(text)
    character(len=*), intent(in) :: name
    integer, intent(in) :: rank, d, lo, hi, n
    character(len=:), allocatable :: text
    character(len=*), parameter :: ordinals(2) = [character(len=6) :: 'first', 'second']
    integer :: given
    if (lo >= 1 .and. hi <= n) then
      text = 'the section '//format_integer(lo)//':'//format_integer(hi)//' of '//name//' is empty (its first '// &
             'index exceeds its last)'
      return
    end if
    given = hi
    if (lo < 1) given = lo
    text = 'index '
    if (rank > 1) text = 'the '//trim(ordinals(min(d, 2)))//' index '
    text = text//format_integer(given)//' of '//name//' lies outside [1, '//format_integer(n)//']'
  end function subscript_problem

  !> 'x', 'x(3)' or 'x(1, 3)' for flat element p of a variable of extents dims.
  pure function element_name(name, dims, p) result(text)
    character(len=*), intent(in) :: name
    integer, intent(in) :: dims(:), p
    character(len=:), allocatable :: text
    select case (size(dims))
    case (0)
      text = name
    case (1)
      text = indexed_name(name, p)
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

  module subroutine get_real(self, name, x, b, status)
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
  module subroutine get_real_vector(self, name, x, b, status)
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
  module subroutine get_real_list(self, name, x, most, b, status)
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
  module subroutine parts_real(self, name, x, b, limit, status, given)
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

  recursive module subroutine parts_text(self, name, x, limit, status, choices, given)
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

  module subroutine parts_logical(self, name, x, limit, status)
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
  module subroutine get_real_columns(self, name, x, b, limit, n_given, status, given)
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

  module subroutine get_integer(self, name, i, low, high, status)
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

  module subroutine get_logical(self, name, flag, status)
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
  recursive module subroutine get_text(self, name, x, status, choices)
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
end submodule io_group_reader_values
