!> The element design of `optimize` (docs/design.md, "Designs from standard
!> parts"): &slide_elements (the start design, read as for the geometry),
!> &design_elements (which element parameters are the design variables, and
!> their bounds) and &catalogue (the values each may take in the end).
!> A variable is a parameter of an element; which kinds have which, and the
!> &catalogue list and step of each (a catalogue kind: a curve's radius and a
!> bowl's entry radius are different parts), are the table below; the range
!> of a variable is what its element kind allows (&slide_elements' own check,
!> io_element_table check_element) inside its catalogue list's declaration
!> (io_declarations_design).
!> Without &design_elements the design is &optimize's points, and
!> &slide_elements and &catalogue are refused.
module io_element_design_config
  use base_kinds, only: wp
  use base_text, only: format_integer, format_short, append_item
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use design_slide_design, only: parameter_value, set_parameter, parameter_names, parameter_units, &
    PARAMETER_LENGTH, PARAMETER_SLOPE, PARAMETER_RADIUS, PARAMETER_ANGLE, PARAMETER_DROP
  use design_geometry_optimization, only: optimization_setup_t
  use design_catalogue, only: catalogue_t, allowed_in_list, allowed_by_step, step_indices
  use io_input, only: input_text_t, group_reader_t, open_group, group_present, format_real, indexed_name
  use io_slide_geometry_config, only: read_slide_elements
  use io_element_table, only: check_element
  use geometry_slide_elements, only: slide_element_t
  use io_declaration, only: declaration_t, in_groups, bound_text, words_joined
  use io_input_declarations, only: find_declaration, declaration
  implicit none (type, external)
  private
  public :: read_element_design, refuse_point_design

  !> The catalogue's kinds of parts: a parameter (PARAMETER_*) of the element
  !> kinds named, its &catalogue list and step. A design variable is the
  !> parameter of an element whose kind one of them names; its values lie in
  !> its list's declared range. Not design variables: a helix's turns and
  !> drop, a bowl's turns (the spiral's path in the same bowl, not its size),
  !> a drop's drop (the height of the tower: an optimisation of the
  !> accelerations would only ride it down to its lower bound), a patch's
  !> values (its wall is a file of its own).
  integer, parameter :: n_kinds = 11
  integer, parameter :: kind_parameter(n_kinds) = [PARAMETER_LENGTH, PARAMETER_SLOPE, PARAMETER_RADIUS, &
    PARAMETER_ANGLE, PARAMETER_RADIUS, PARAMETER_SLOPE, PARAMETER_DROP, PARAMETER_LENGTH, PARAMETER_RADIUS, &
    PARAMETER_SLOPE, PARAMETER_RADIUS]
  character(len=*), parameter :: kind_elements(n_kinds) = [character(len=28) :: 'straight runout', &
    'straight curve runout funnel', 'curve helix', 'curve', 'bowl', 'bowl', 'bowl', 'funnel', 'funnel', 'drop', 'drop']
  character(len=*), parameter :: list_names(n_kinds) = [character(len=15) :: 'lengths', 'slopes_deg', 'radii', &
    'angles_deg', 'bowl_radii', 'bowl_slopes_deg', 'bowl_drops', 'funnel_lengths', 'funnel_radii', &
    'drop_slopes_deg', 'drop_radii']
  character(len=*), parameter :: step_names(n_kinds) = [character(len=19) :: 'length_step', 'slope_step_deg', &
    'radius_step', 'angle_step_deg', 'bowl_radius_step', 'bowl_slope_step_deg', 'bowl_drop_step', &
    'funnel_length_step', 'funnel_radius_step', 'drop_slope_step_deg', 'drop_radius_step']
  !> Each in words: 'radius' (of a curve or helix), 'bowl radius', ...
  character(len=*), parameter :: kind_nouns(n_kinds) = [character(len=13) :: 'length', 'slope', 'radius', 'angle', &
    'bowl radius', 'bowl slope', 'bowl drop', 'funnel length', 'funnel radius', 'drop slope', 'drop radius']
  integer, parameter :: max_allowed = 10000   !< allowed values of one variable from a step
  integer, parameter :: max_list = 200        !< the declared length of a &catalogue list

contains

  !> Reads the element design into setup%design (unless there is none) and
  !> the catalogue (`with_catalogue`: &catalogue given).
  subroutine read_element_design(input, setup, catalogue, with_catalogue, status)
    type(input_text_t), intent(in) :: input
    type(optimization_setup_t), intent(inout) :: setup
    type(catalogue_t), intent(out) :: catalogue
    logical, intent(out) :: with_catalogue
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=*), parameter :: g = 'design_elements'
    character(len=8), allocatable :: parameter(:)
    real(wp), allocatable :: element_real(:), lower(:), upper(:)
    integer :: n, i, p, k, c, b
    real(wp) :: x, bound
    character(len=:), allocatable :: why
    character(len=*), parameter :: bound_names(2) = [character(len=5) :: 'lower', 'upper']

    with_catalogue = .false.
    if (.not. status%ok()) return
    if (.not. group_present(input, g)) then
      call refuse_group('slide_elements')
      call refuse_group('catalogue')
      return
    end if
    call open_group(input, g, r, status)
    if (status%ok() .and. .not. group_present(input, 'slide_elements')) then
      call set_status(status, STATUS_INVALID_INPUT, r%where('')//': &'//g//' varies the elements of '// &
                      '&slide_elements, which is missing: give the chain (docs/geometry.md)')
      return
    end if
    call read_slide_elements(input, setup%design%chain, status)
    n = 0
    call r%get('n_design', n, status)
    if (.not. status%ok()) return
    if (.not. (r%has('n_design') .and. r%has('element') .and. r%has('parameter') .and. r%has('lower') .and. &
               r%has('upper'))) then
      call r%invalid('n_design', format_integer(n), 'give n_design and, for every design variable, element, '// &
                     'parameter, lower and upper', status)
      return
    end if
    allocate (element_real(n), parameter(n), lower(n), upper(n))
    element_real = 0; parameter = ''; lower = 0; upper = 0
    call r%get_parts('element', element_real, 'n_design = '//format_integer(n), status)
    call r%get_parts('parameter', parameter, 'n_design = '//format_integer(n), status)
    call r%get_parts('lower', lower, 'n_design = '//format_integer(n), status)
    call r%get_parts('upper', upper, 'n_design = '//format_integer(n), status)
    if (.not. status%ok()) return
    associate (d => setup%design, elements => setup%design%chain%elements)
      d%from_elements = .true.
      d%element = nint(element_real)
      d%parameter = [(findloc(parameter_names, trim(parameter(i)), 1), i=1, n)]
      d%lower = lower
      d%upper = upper
      do i = 1, n
        if (.not. status%ok()) return
        p = d%parameter(i)
        if (abs(element_real(i) - d%element(i)) > 0 .or. d%element(i) > size(elements)) then
          call r%invalid(indexed_name('element', i), format_real(element_real(i)), 'must be the number of an element of '// &
                         '&slide_elements, 1 to n_elements = '//format_integer(size(elements)), status)
          cycle
        end if
        c = catalogue_kind(elements(d%element(i))%kind, p)
        if (c == 0) then
          call r%invalid(indexed_name('parameter', i), ''''//trim(parameter(i))//'''', 'element '// &
                         format_integer(d%element(i))//' is a '//trim(elements(d%element(i))%kind)//', whose '// &
                         trim(parameter_names(p))//' is not a design variable ('//kinds_using(p)//')', status)
          cycle
        end if
        if (.not. lower(i) < upper(i)) then
          call r%invalid(indexed_name('upper', i), format_real(upper(i)), 'must exceed '//indexed_name('lower', i)//' = '// &
                         format_real(lower(i)), status)
          cycle
        end if
        why = ''
        do b = 1, 2
          bound = merge(lower(i), upper(i), b == 1)
          why = element_refusal(elements(d%element(i)), d%element(i), p, bound)
          if (len(why) > 0) exit
        end do
        if (len(why) > 0) then
          call r%invalid(indexed_name(trim(bound_names(b)), i), format_real(bound), why, status)
          cycle
        end if
        if (.not. in_range(c, lower(i), upper(i))) then
          call r%invalid(indexed_name('lower', i)//', '//indexed_name('upper', i), &
                         format_real(lower(i))//', '//format_real(upper(i)), &
                         'the '//trim(kind_nouns(c))//' must lie in '//range_text(c)//' (the range of &catalogue '// &
                         trim(list_names(c))//')', status)
          cycle
        end if
        ! the start value passed &slide_elements' own check when it was read
        x = parameter_value(elements(d%element(i)), p)
        if (x < lower(i) .or. x > upper(i)) then
          call r%invalid(indexed_name('lower', i)//', '//indexed_name('upper', i), &
                         format_real(lower(i))//', '//format_real(upper(i)), &
                         'must hold the start value '//format_short(x)//' '//trim(parameter_units(p))// &
                         ' of element '//format_integer(d%element(i))//' (&slide_elements)', status)
          cycle
        end if
        do k = 1, i - 1
          if (d%element(k) == d%element(i) .and. d%parameter(k) == p) then
            call r%invalid(indexed_name('parameter', i), ''''//trim(parameter(i))//'''', 'the '//trim(parameter_names(p))// &
                           ' of element '//format_integer(d%element(i))//' is already design variable '// &
                           format_integer(k), status)
            exit
          end if
        end do
      end do
    end associate
    if (.not. status%ok()) return
    if (2*size(setup%start_angles) < n) then
      call open_group(input, 'optimize', r, status)
      call r%invalid('start_angles_deg', format_integer(size(setup%start_angles))//' rides', 'give at least '// &
                     format_integer((n + 1)/2)//' rides for '//format_integer(n)//' design variables (each '// &
                     'ride gives two residuals: its acceleration and its lever arm)', status)
      return
    end if
    with_catalogue = group_present(input, 'catalogue')
    if (with_catalogue) call read_catalogue(input, setup, catalogue, status)

  contains

    subroutine refuse_group(name)
      character(len=*), intent(in) :: name
      type(group_reader_t) :: other
      if (.not. status%ok() .or. .not. group_present(input, name)) return
      call open_group(input, name, other, status)
      if (.not. status%ok()) return
      call set_status(status, STATUS_INVALID_INPUT, other%where('')//': &'//name//' is not used: an '// &
                      'optimisation of element parameters needs &'//g//' (which parameters vary, their bounds); '// &
                      'without it the design is &optimize''s points')
    end subroutine refuse_group
  end subroutine read_element_design

  !> With &design_elements, refuses the variables of &optimize that describe
  !> a design of points (before &optimize is read: its own checks of them
  !> would speak of points).
  subroutine refuse_point_design(input, status)
    type(input_text_t), intent(in) :: input
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    if (.not. status%ok() .or. .not. group_present(input, 'design_elements')) return
    call open_group(input, 'optimize', r, status)
    call r%refuse_given([character(len=17) :: 'n_points', 'points', 'n_design', 'design_point', &
                         'design_coordinate', 'lower', 'upper', 'degree', 'smoothing', 'horizon'], &
                        'the design is the element chain of &slide_elements with the variables of &design_elements', &
                        status)
  end subroutine refuse_point_design

  !> &catalogue: for each catalogue kind of the design variables a list of
  !> allowed values or a step; each variable may take those inside its bounds.
  subroutine read_catalogue(input, setup, catalogue, status)
    type(input_text_t), intent(in) :: input
    type(optimization_setup_t), intent(in) :: setup
    type(catalogue_t), intent(out) :: catalogue
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    real(wp), allocatable :: list(:), values(:)
    real(wp) :: step
    integer :: c, i, k, first, last
    integer, allocatable :: kind_of(:)                 ! the catalogue kind of each variable
    logical :: any_given
    character(len=:), allocatable :: name, step_name   ! of the list and the step of catalogue kind c
    character(len=:), allocatable :: given             ! the one given

    call open_group(input, 'catalogue', r, status)
    call r%get('max_designs', catalogue%max_designs, status)
    if (.not. status%ok()) return
    allocate (catalogue%allowed(size(setup%design%lower)))
    allocate (kind_of(size(setup%design%parameter)))
    do i = 1, size(kind_of)
      kind_of(i) = catalogue_kind(setup%design%chain%elements(setup%design%element(i))%kind, &
                                  setup%design%parameter(i))
    end do
    any_given = .false.
    do c = 1, n_kinds
      any_given = any_given .or. r%has(trim(list_names(c))) .or. r%has(trim(step_names(c)))
    end do
    if (.not. any_given) then
      call set_status(status, STATUS_INVALID_INPUT, r%where('')//': &catalogue is empty: give the values made '// &
                      'of each parameter of the design variables ('//all_kinds()//')')
      return
    end if
    do c = 1, n_kinds
      name = trim(list_names(c))
      step_name = trim(step_names(c))
      associate (d => setup%design)
        if (.not. (r%has(name) .or. r%has(step_name))) then
          do i = 1, size(kind_of)
            if (kind_of(i) == c) then
              call r%invalid(name, 'none', 'design variable '//format_integer(i)//' ('//variable_name(i)// &
                             ') needs its allowed values: give '//name//' or '//step_name, status)
              return
            end if
          end do
          cycle
        end if
        if (r%has(name) .and. r%has(step_name)) then
          call r%invalid(step_name, r%written(step_name), 'give '//name//' or '//step_name//', not both', status)
          return
        end if
        given = step_name
        if (r%has(name)) given = name
        if (.not. any(kind_of == c)) then
          call r%invalid(given, r%written(given), &
                         'no design variable of &design_elements has parameter = '''// &
                         trim(parameter_names(kind_parameter(c)))//''' on a '// &
                         words_joined(trim(kind_elements(c)), ' or ')//' (the catalogue is for the variables '// &
                         'only)', status)
          return
        end if
        if (r%has(name)) then
          call r%get_list(name, list, max_list, status)
          if (.not. status%ok()) return
          do k = 2, size(list)
            if (.not. list(k) > list(k - 1)) then
              call r%invalid(indexed_name(name, k), format_real(list(k)), 'must exceed '//name// &
                             '('//format_integer(k - 1)//') = '//format_real(list(k - 1))//' (increasing, '// &
                             'each once)', status)
              return
            end if
          end do
          do k = 1, size(list)
            if (.not. any(kind_of == c .and. d%lower <= list(k) .and. list(k) <= d%upper)) then
              call r%invalid(indexed_name(name, k), format_real(list(k)), 'lies outside the bounds '// &
                             'of every '//trim(kind_nouns(c))//' variable ('//bounds_of(c)//'): an unused '// &
                             'part; leave it out or widen the bounds (&design_elements lower, upper)', status)
              return
            end if
          end do
        else
          call r%get(step_name, step, status)
          if (.not. status%ok()) return
        end if
        do i = 1, size(kind_of)
          if (kind_of(i) /= c) cycle
          if (r%has(name)) then
            values = allowed_in_list(list, d%lower(i), d%upper(i))
          else
            call step_indices(step, d%lower(i), d%upper(i), first, last)
            if (real(last - first, wp) >= max_allowed) then
              call r%invalid(step_name, r%written(step_name), 'gives more than '//format_integer(max_allowed)// &
                             ' values inside the bounds of design variable '//format_integer(i)//' ('// &
                             variable_name(i)//'): a larger step', status)
              return
            end if
            values = allowed_by_step(step, d%lower(i), d%upper(i))
          end if
          if (size(values) == 0) then
            call r%invalid(given, r%written(given), &
                           'holds no value inside the bounds '//format_short(d%lower(i))//' … '// &
                           format_short(d%upper(i))//' '//trim(parameter_units(d%parameter(i)))// &
                           ' of design variable '//format_integer(i)//' ('//variable_name(i)//')', status)
            return
          end if
          catalogue%allowed(i)%values = values
        end do
      end associate
    end do

  contains

    !> 'element 2 radius'
    function variable_name(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      text = 'element '//format_integer(setup%design%element(i))//' '// &
             trim(parameter_names(setup%design%parameter(i)))
    end function variable_name

    !> The bounds of every variable of catalogue kind c, in words.
    function bounds_of(c) result(text)
      integer, intent(in) :: c
      character(len=:), allocatable :: text
      integer :: j
      text = ''
      do j = 1, size(kind_of)
        if (kind_of(j) /= c) cycle
        if (len(text) > 0) text = text//'; '
        text = text//variable_name(j)//' '//format_short(setup%design%lower(j))//' … '// &
               format_short(setup%design%upper(j))//' '//trim(parameter_units(setup%design%parameter(j)))
      end do
    end function bounds_of
  end subroutine read_catalogue

  !> Why element e (number `number` of the chain) cannot be built with its
  !> parameter p at x ('' when it can): &slide_elements' own check of an
  !> element (check_element, the one statement of each kind's limits), so
  !> that a variable's bounds hold only elements that can be built. Each
  !> kind's limits on one parameter are an interval (given the others), so
  !> bounds that pass hold only values that pass.
  function element_refusal(e, number, p, x) result(why)
    type(slide_element_t), intent(in) :: e
    integer, intent(in) :: number, p
    real(wp), intent(in) :: x
    character(len=:), allocatable :: why
    type(slide_element_t) :: moved
    character(len=:), allocatable :: variable, value, allowed
    moved = e
    call set_parameter(moved, p, x)
    call check_element(moved%kind, moved%length, moved%slope_deg, moved%radius, moved%angle_deg, moved%direction, &
                       moved%turns, moved%drop, variable, value, allowed, moved%bowl_profile)
    why = ''
    if (len(variable) == 0) return
    why = 'element '//format_integer(number)//' is a '//trim(e%kind)//', and '
    ! a limit on another of its values that this one moves (a helix's drop by its radius)
    if (variable /= trim(parameter_names(p)) .and. variable /= trim(parameter_names(p))//'_deg') &
      why = why//'with '//trim(parameter_names(p))//' '//format_short(x)//' '//trim(parameter_units(p))// &
            ' its '//variable//' = '//value//' is refused: '
    why = why//allowed//' (&slide_elements): the bounds may hold only elements that can be built'
  end function element_refusal

  !> The catalogue kind of parameter p of an element of `kind` (0: p is not a
  !> design variable of that kind).
  pure integer function catalogue_kind(kind, p) result(c)
    character(len=*), intent(in) :: kind
    integer, intent(in) :: p
    do c = 1, n_kinds
      if (kind_parameter(c) == p .and. in_groups(trim(kind), kind_elements(c))) return
    end do
    c = 0
  end function catalogue_kind

  !> The element kinds that have parameter p as a design variable: 'a radius:
  !> curve, helix, bowl, funnel, drop'.
  pure function kinds_using(p) result(text)
    integer, intent(in) :: p
    character(len=:), allocatable :: text
    character(len=:), allocatable :: kinds
    integer :: c
    kinds = ''
    do c = 1, n_kinds
      if (kind_parameter(c) == p) kinds = kinds//' '//trim(kind_elements(c))
    end do
    text = 'a '
    if (p == PARAMETER_ANGLE) text = 'an '
    text = text//trim(parameter_names(p))//': '//words_joined(trim(kinds), ', ')
  end function kinds_using

  !> Every list and step in words: 'lengths or length_step, ...'.
  pure function all_kinds() result(text)
    character(len=:), allocatable :: text
    integer :: c
    text = ''
    do c = 1, n_kinds
      call append_item(text, trim(list_names(c))//' or '//trim(step_names(c)), ', ')
    end do
  end function all_kinds

  !> The declaration of catalogue kind c's list: its unit and range.
  pure type(declaration_t) function kind_declaration(c) result(d)
    integer, intent(in) :: c
    d = declaration(find_declaration('catalogue', trim(list_names(c))))
  end function kind_declaration

  !> Whether bounds lower < upper lie in the range of catalogue kind c.
  pure logical function in_range(c, lower, upper)
    integer, intent(in) :: c
    real(wp), intent(in) :: lower, upper
    type(declaration_t) :: d
    d = kind_declaration(c)
    in_range = (lower > d%low .or. (.not. d%open_low .and. lower == d%low)) .and. upper <= d%high
  end function in_range

  !> '(0, 10000] m', '[-60, 60] deg'
  pure function range_text(c) result(text)
    integer, intent(in) :: c
    character(len=:), allocatable :: text
    type(declaration_t) :: d
    d = kind_declaration(c)
    text = '['
    if (d%open_low) text = '('
    text = text//bound_text(d%low)//', '//bound_text(d%high)//'] '//trim(d%unit)
  end function range_text
end module io_element_design_config
