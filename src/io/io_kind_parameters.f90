!> Reading the parameters of a kind (a surface kind, a force law) from an
!> input group by the kind's declarations (base_spec parameter_t): the
!> ranges, units and required-ness the reader checks come from the one
!> declaration the factory checks too. A scenario may read a parameter from
!> a variable of another name (`rename`, 'parameter=variable': the point
!> mass's friction_coefficient is the law's mu).
module io_kind_parameters
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_spec, only: parameter_t, spec_t, list_limit
  use io_input, only: group_reader_t, bounds_t, in_range, above
  implicit none (type, external)
  private
  public :: read_kind_parameters, refuse_other_parameters, variable_name, parameter_variables, variable_length

  integer, parameter :: variable_length = 32   !< of the names parameter_variables lists

contains

  !> The variable that holds `parameter` (renamed, or its own name).
  pure function variable_name(parameter, rename) result(variable)
    character(len=*), intent(in) :: parameter
    character(len=*), intent(in), optional :: rename(:)
    character(len=:), allocatable :: variable
    integer :: k, eq
    variable = parameter
    if (.not. present(rename)) return
    do k = 1, size(rename)
      eq = index(rename(k), '=')
      if (rename(k)(:eq - 1) == parameter) variable = trim(rename(k)(eq + 1:))
    end do
  end function variable_name

  !> The variables of every parameter of `parameters` not yet in `names`,
  !> appended to it (the names a group may hold for all kinds together).
  pure subroutine parameter_variables(parameters, names, rename)
    type(parameter_t), intent(in) :: parameters(:)
    character(len=variable_length), allocatable, intent(inout) :: names(:)
    character(len=*), intent(in), optional :: rename(:)
    character(len=variable_length) :: one(1)
    integer :: j
    do j = 1, size(parameters)
      one(1) = variable_name(parameters(j)%name, rename)
      if (.not. any(names == one(1))) names = [character(len=variable_length) :: names, one]
    end do
  end subroutine parameter_variables

  !> Reads into `spec` every parameter of the kind `kind` (chosen by the
  !> variable `selector`) the group gives, checked against its declaration;
  !> a required one not given is refused (`hint` is added to that message),
  !> unless the group has a default of its own for it (`defaults`, a spec
  !> of the same kind: the rider's Coulomb mu_D).
  subroutine read_kind_parameters(r, selector, kind, parameters, spec, status, rename, hint, defaults)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: selector, kind
    type(parameter_t), intent(in) :: parameters(:)
    type(spec_t), intent(inout) :: spec
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: rename(:), hint
    type(spec_t), intent(in), optional :: defaults
    type(bounds_t) :: b
    real(wp), allocatable :: x(:)
    character(len=:), allocatable :: variable, extra
    integer :: j
    spec%kind = kind
    extra = ''
    if (present(hint)) extra = '; '//hint
    do j = 1, size(parameters)
      if (.not. status%ok()) return
      associate (p => parameters(j))
        variable = variable_name(p%name, rename)
        if (p%open_low) then
          b = above(p%low, p%high, p%unit)
        else
          b = in_range(p%low, p%high, p%unit)
        end if
        if (r%has(variable)) then
          if (p%count == 0) then   ! a list
            call r%get_list(variable, x, list_limit, b, status)
          else
            allocate (x(p%count))
            x = 0
            if (.not. p%required) x = p%default
            if (p%count == 1) then
              call r%get(variable, x(1), b, status)
            else
              call r%get(variable, x, b, status)
            end if
          end if
          if (status%ok()) call spec%set(p%name, x)
          deallocate (x)
        else if (present(defaults)) then
          if (defaults%kind == kind .and. defaults%has(p%name)) call spec%set(p%name, defaults%vector(p%name))
        end if
        if (p%required .and. .not. spec%has(p%name) .and. status%ok()) then
          call r%invalid(variable, 'none (not given)', selector//' = '''//kind//''' needs '//variable//': it '// &
                         b%text()//extra, status)
        end if
      end associate
    end do
  end subroutine read_kind_parameters

  !> Refuses every variable of `all_variables` the group gives that is not a
  !> parameter of the chosen kind: it would be silently ignored.
  subroutine refuse_other_parameters(r, selector, kind, parameters, all_variables, status, rename)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: selector, kind
    type(parameter_t), intent(in) :: parameters(:)
    character(len=*), intent(in) :: all_variables(:)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: rename(:)
    integer :: k, j
    logical :: used
    do k = 1, size(all_variables)
      used = .false.
      do j = 1, size(parameters)
        if (variable_name(parameters(j)%name, rename) == trim(all_variables(k))) used = .true.
      end do
      if (.not. used) call r%refuse_given(all_variables(k:k), selector//' = '''//kind//''' does not use it', &
                                          status)
    end do
  end subroutine refuse_other_parameters
end module io_kind_parameters
