!> The element design of `optimize` (docs/design.md, "Designs from standard
!> parts"): &slide_elements (the start design, read as for the geometry),
!> &design_elements (which element parameters are the design variables, and
!> their bounds) and &catalogue (the values each may take in the end).
!> Without &design_elements the design is &optimize's points, and
!> &slide_elements and &catalogue are refused.
module io_element_design_config
  use base_kinds, only: wp
  use base_text, only: format_integer, format_short
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use design_slide_design, only: parameter_value, parameter_names, parameter_units, PARAMETER_LENGTH, &
    PARAMETER_SLOPE, PARAMETER_RADIUS, PARAMETER_ANGLE
  use design_geometry_optimization, only: optimization_setup_t
  use design_catalogue, only: catalogue_t, allowed_in_list, allowed_by_step, step_indices
  use io_input, only: input_text_t, group_reader_t, open_group, group_present, format_real, indexed_name
  use io_slide_geometry_config, only: read_slide_elements
  implicit none (type, external)
  private
  public :: read_element_design, refuse_point_design

  !> The &catalogue names of each parameter kind (PARAMETER_*): a list and a step.
  character(len=*), parameter :: list_names(4) = [character(len=10) :: 'lengths', 'slopes_deg', 'radii', &
                                                  'angles_deg']
  character(len=*), parameter :: step_names(4) = [character(len=14) :: 'length_step', 'slope_step_deg', &
                                                  'radius_step', 'angle_step_deg']
  !> The values a parameter can take at all (the element chain's own checks).
  real(wp), parameter :: lowest(4) = [0.0_wp, -60.0_wp, 0.0_wp, 0.0_wp]
  real(wp), parameter :: highest(4) = [1e4_wp, 60.0_wp, 1e4_wp, 720.0_wp]
  logical, parameter :: open_high(4) = [.false., .true., .false., .false.]
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
    integer :: n, i, p, k
    real(wp) :: x

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
        if (.not. uses(elements(d%element(i))%kind, p)) then
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
        if (.not. (lower(i) > lowest(p) .and. (upper(i) < highest(p) .or. &
                                                (.not. open_high(p) .and. upper(i) == highest(p))))) then
          call r%invalid(indexed_name('lower', i)//', '//indexed_name('upper', i), &
                         format_real(lower(i))//', '//format_real(upper(i)), &
                         'the '//trim(parameter_names(p))//' must lie in '//range_text(p), status)
          cycle
        end if
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

  !> &catalogue: for each parameter kind of the design variables a list of
  !> allowed values or a step; each variable may take those inside its bounds.
  subroutine read_catalogue(input, setup, catalogue, status)
    type(input_text_t), intent(in) :: input
    type(optimization_setup_t), intent(in) :: setup
    type(catalogue_t), intent(out) :: catalogue
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    real(wp), allocatable :: list(:), values(:)
    real(wp) :: step
    integer :: p, i, k, first, last
    logical :: any_given
    character(len=:), allocatable :: name, step_name   ! of the list and the step of parameter kind p
    character(len=:), allocatable :: given             ! the one given

    call open_group(input, 'catalogue', r, status)
    call r%get('max_designs', catalogue%max_designs, status)
    if (.not. status%ok()) return
    allocate (catalogue%allowed(size(setup%design%lower)))
    any_given = .false.
    do p = 1, size(list_names)
      any_given = any_given .or. r%has(trim(list_names(p))) .or. r%has(trim(step_names(p)))
    end do
    if (.not. any_given) then
      call set_status(status, STATUS_INVALID_INPUT, r%where('')//': &catalogue is empty: give the values made '// &
                      'of each parameter of the design variables (radii or radius_step, angles_deg or '// &
                      'angle_step_deg, slopes_deg or slope_step_deg, lengths or length_step)')
      return
    end if
    do p = 1, size(list_names)
      name = trim(list_names(p))
      step_name = trim(step_names(p))
      associate (d => setup%design)
        if (.not. (r%has(name) .or. r%has(step_name))) then
          do i = 1, size(d%parameter)
            if (d%parameter(i) == p) then
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
        if (.not. any(d%parameter == p)) then
          call r%invalid(given, r%written(given), &
                         'no design variable of &design_elements has parameter = '''// &
                         trim(parameter_names(p))//''' (the catalogue is for the variables only)', status)
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
            if (.not. any(d%parameter == p .and. d%lower <= list(k) .and. list(k) <= d%upper)) then
              call r%invalid(indexed_name(name, k), format_real(list(k)), 'lies outside the bounds '// &
                             'of every '//trim(parameter_names(p))//' variable ('//bounds_of(p)//'): an unused '// &
                             'part; leave it out or widen the bounds (&design_elements lower, upper)', status)
              return
            end if
          end do
        else
          call r%get(step_name, step, status)
          if (.not. status%ok()) return
        end if
        do i = 1, size(d%parameter)
          if (d%parameter(i) /= p) cycle
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
                           format_short(d%upper(i))//' '//trim(parameter_units(p))//' of design variable '// &
                           format_integer(i)//' ('//variable_name(i)//')', status)
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

    !> The bounds of every variable of kind p, in words.
    function bounds_of(p) result(text)
      integer, intent(in) :: p
      character(len=:), allocatable :: text
      integer :: j
      text = ''
      do j = 1, size(setup%design%parameter)
        if (setup%design%parameter(j) /= p) cycle
        if (len(text) > 0) text = text//'; '
        text = text//variable_name(j)//' '//format_short(setup%design%lower(j))//' … '// &
               format_short(setup%design%upper(j))//' '//trim(parameter_units(p))
      end do
    end function bounds_of
  end subroutine read_catalogue

  !> Whether an element of `kind` has parameter p.
  pure logical function uses(kind, p)
    character(len=*), intent(in) :: kind
    integer, intent(in) :: p
    select case (p)
    case (PARAMETER_LENGTH); uses = kind == 'straight' .or. kind == 'runout'
    case (PARAMETER_SLOPE); uses = kind == 'straight' .or. kind == 'curve' .or. kind == 'runout'
    case (PARAMETER_RADIUS); uses = kind == 'curve' .or. kind == 'helix'
    case default; uses = kind == 'curve'
    end select
  end function uses

  pure function kinds_using(p) result(text)
    integer, intent(in) :: p
    character(len=:), allocatable :: text
    select case (p)
    case (PARAMETER_LENGTH); text = 'a length: straight, runout'
    case (PARAMETER_SLOPE); text = 'a slope: straight, curve, runout'
    case (PARAMETER_RADIUS); text = 'a radius: curve, helix'
    case default; text = 'an angle: curve'
    end select
  end function kinds_using

  function range_text(p) result(text)
    integer, intent(in) :: p
    character(len=:), allocatable :: text
    text = '('//format_short(lowest(p))//', '//format_short(highest(p))//merge(')', ']', open_high(p))//' '// &
           trim(parameter_units(p))
  end function range_text
end module io_element_design_config
