!> Plain descriptions of the kinds a factory makes (surfaces, force laws):
!> the parameters of a kind are declared once (parameter_t: name, number of
!> values, unit, range, default or required, meaning), and a spec (spec_t)
!> names a kind and carries the values given. io fills a spec from an input
!> by the kind's declarations (the reader's checks and messages come from
!> them); the factory of the layer that owns the kind completes it (defaults,
!> ranges: `complete_spec`) and builds (geometry_surface_factory,
!> kinetostatics_force_law_factory).
module base_spec
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  implicit none (type, external)
  private
  public :: parameter_t, spec_t, spec_value_t, declare, complete_spec, range_text, list_limit

  integer, parameter :: list_limit = 10000   !< most values of a list parameter

  !> One parameter of a kind: `count` values (0: a list of any length up to
  !> list_limit) in [low, high] (low excluded if open_low), `unit`; `default`
  !> if not required.
  type :: parameter_t
    character(len=:), allocatable :: name, unit, meaning
    integer :: count = 1
    real(wp) :: low = -huge(1.0_wp), high = huge(1.0_wp)
    logical :: open_low = .false.
    logical :: required = .false.
    real(wp), allocatable :: default(:)
  end type parameter_t

  type :: spec_value_t
    character(len=:), allocatable :: name
    real(wp), allocatable :: values(:)
  end type spec_value_t

  !> A kind and the values of its parameters (by name).
  type :: spec_t
    character(len=:), allocatable :: kind
    type(spec_value_t), allocatable :: values(:)
  contains
    procedure :: set => spec_set
    procedure :: has => spec_has
    procedure :: value => spec_value
    procedure :: vector => spec_vector
  end type spec_t

contains

  !> A parameter declaration; without `default` it is required.
  pure function declare(name, unit, low, high, meaning, default, count, open_low) result(p)
    character(len=*), intent(in) :: name, unit, meaning
    real(wp), intent(in) :: low, high
    real(wp), intent(in), optional :: default(:)
    integer, intent(in), optional :: count
    logical, intent(in), optional :: open_low
    type(parameter_t) :: p
    p%name = name
    p%unit = unit
    p%meaning = meaning
    p%low = low
    p%high = high
    if (present(count)) p%count = count
    if (present(open_low)) p%open_low = open_low
    p%required = .not. present(default)
    if (present(default)) p%default = default
  end function declare

  !> The allowed range in words: '> 0 and <= 10 s/m'.
  pure function range_text(p) result(text)
    type(parameter_t), intent(in) :: p
    character(len=:), allocatable :: text
    text = merge('> ', '>=', p%open_low)//' '//format_short(p%low)//' and <= '//format_short(p%high)
    if (len(p%unit) > 0) text = text//' '//p%unit
  end function range_text

  !> Sets (or replaces) the values of `name`.
  pure subroutine spec_set(self, name, values)
    class(spec_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: values(:)
    type(spec_value_t), allocatable :: grown(:)
    integer :: k, n
    if (.not. allocated(self%values)) allocate (self%values(0))
    n = size(self%values)
    do k = 1, n
      if (self%values(k)%name == name) then
        self%values(k)%values = values
        return
      end if
    end do
    ! grown by hand: gfortran 12 leaks the allocatable components of a
    ! structure constructor inside an array constructor ([a, t(...)])
    allocate (grown(n + 1))
    do k = 1, n
      call move_alloc(self%values(k)%name, grown(k)%name)
      call move_alloc(self%values(k)%values, grown(k)%values)
    end do
    grown(n + 1)%name = name
    grown(n + 1)%values = values
    call move_alloc(grown, self%values)
  end subroutine spec_set

  pure logical function spec_has(self, name) result(has)
    class(spec_t), intent(in) :: self
    character(len=*), intent(in) :: name
    integer :: k
    has = .false.
    if (.not. allocated(self%values)) return
    do k = 1, size(self%values)
      if (self%values(k)%name == name) has = .true.
    end do
  end function spec_has

  !> The values of `name` (none if not set).
  pure function spec_vector(self, name) result(values)
    class(spec_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), allocatable :: values(:)
    integer :: k
    allocate (values(0))
    if (.not. allocated(self%values)) return
    do k = 1, size(self%values)
      if (self%values(k)%name == name) values = self%values(k)%values
    end do
  end function spec_vector

  !> The first value of `name` (a completed spec has every parameter).
  pure real(wp) function spec_value(self, name) result(x)
    class(spec_t), intent(in) :: self
    character(len=*), intent(in) :: name
    real(wp), allocatable :: values(:)
    values = self%vector(name)
    x = huge(1.0_wp)
    if (size(values) > 0) x = values(1)
  end function spec_value

  !> Checks `spec` against the declarations of its kind (`what`: 'force law
  !> ''coulomb''' for messages): every value a declared parameter with the
  !> right count, finite and in range; every required one given; the
  !> defaults of the others filled in.
  subroutine complete_spec(spec, parameters, what, status)
    type(spec_t), intent(inout) :: spec
    type(parameter_t), intent(in) :: parameters(:)
    character(len=*), intent(in) :: what
    type(status_t), intent(inout) :: status
    integer :: k, j
    logical :: known
    if (.not. status%ok()) return
    if (.not. allocated(spec%values)) allocate (spec%values(0))
    do k = 1, size(spec%values)
      known = .false.
      do j = 1, size(parameters)
        if (parameters(j)%name == spec%values(k)%name) known = .true.
      end do
      if (.not. known) then
        call set_status(status, STATUS_INVALID_INPUT, what//' has no parameter '''//spec%values(k)%name// &
                        ''''//parameter_list(parameters))
        return
      end if
    end do
    do j = 1, size(parameters)
      associate (p => parameters(j))
        if (.not. spec%has(p%name)) then
          if (p%required) then
            call set_status(status, STATUS_INVALID_INPUT, what//' needs '//p%name//' ('//range_text(p)//')')
            return
          end if
          call spec%set(p%name, p%default)
          cycle
        end if
        associate (x => spec%vector(p%name))
          if ((p%count > 0 .and. size(x) /= p%count) .or. size(x) < 1 .or. size(x) > list_limit) then
            if (p%count > 0) then
              call set_status(status, STATUS_INVALID_INPUT, what//': '//p%name//' takes '// &
                              format_short(real(p%count, wp))//' value(s)')
            else
              call set_status(status, STATUS_INVALID_INPUT, what//': '//p%name//' takes a list of 1 to '// &
                              format_short(real(list_limit, wp))//' values')
            end if
            return
          end if
          do k = 1, size(x)
            if (.not. (x(k) <= p%high .and. (x(k) > p%low .or. (.not. p%open_low .and. x(k) == p%low)))) then
              call set_status(status, STATUS_INVALID_INPUT, what//': '//p%name//' = '//format_short(x(k))// &
                              ' is not allowed: it must be '//range_text(p))
              return
            end if
          end do
        end associate
      end associate
    end do
  end subroutine complete_spec

  pure function parameter_list(parameters) result(text)
    type(parameter_t), intent(in) :: parameters(:)
    character(len=:), allocatable :: text
    integer :: j
    text = '; it has'
    if (size(parameters) == 0) text = '; it has no parameters'
    do j = 1, size(parameters)
      text = text//' '//parameters(j)%name
    end do
  end function parameter_list
end module base_spec
