!> The friction law of a group, read the same way by &contact, &point_mass,
!> &sled and &rider: `friction` names 'none' or a kind of the force-law registry
!> (kinetostatics_force_law_factory), and the kind's parameters are the
!> group's variables by their declarations (io_kind_parameters). A group
!> opens with `friction_law_variables()` added (also=), reads `friction`
!> with the choices `friction_law_names()`, then calls `read_friction_law`.
module io_friction_config
  use base_status, only: status_t
  use base_spec, only: spec_t
  use kinetostatics_force_law, only: force_law_kind_t
  use kinetostatics_force_law_factory, only: force_law_kinds, force_law_kind_index
  use io_input, only: group_reader_t
  use io_kind_parameters, only: read_kind_parameters, refuse_other_parameters, parameter_variables, &
                                variable_length
  implicit none (type, external)
  private
  public :: friction_law_variables, friction_law_names, read_friction_law

contains

  !> The variables of every registered law kind (under the group's names: `rename`).
  function friction_law_variables(rename) result(variables)
    character(len=*), intent(in), optional :: rename(:)
    character(len=variable_length), allocatable :: variables(:)
    type(force_law_kind_t), allocatable :: laws(:)
    integer :: j
    laws = force_law_kinds()
    allocate (variables(0))
    do j = 1, size(laws)
      call parameter_variables(laws(j)%parameters, variables, rename)
    end do
  end function friction_law_variables

  !> 'none' and every registered law kind: the values `friction` may take.
  function friction_law_names() result(names)
    character(len=variable_length), allocatable :: names(:)
    type(force_law_kind_t), allocatable :: laws(:)
    integer :: j
    laws = force_law_kinds()
    names = [character(len=variable_length) :: 'none', (laws(j)%name, j = 1, size(laws))]
  end function friction_law_names

  !> The spec of the law `friction` from the group `r`: its parameters by
  !> their declarations; a required one not given (mu: the law would run
  !> frictionless) and another law's are refused, and with 'none' any.
  !> `defaults`: the group's own defaults of the laws' parameters (a
  !> required one given there is not required).
  subroutine read_friction_law(r, friction, spec, status, rename, defaults)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: friction
    type(spec_t), intent(inout) :: spec
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: rename(:)
    type(spec_t), intent(in), optional :: defaults
    type(force_law_kind_t), allocatable :: laws(:)
    character(len=variable_length), allocatable :: law_variables(:)
    if (.not. status%ok()) return
    law_variables = friction_law_variables(rename)
    if (friction == 'none') then
      call r%refuse_given(law_variables, 'friction = ''none'' has no parameters; name the law they are '// &
                          'for (friction = ''coulomb'', ...)', status)
      return
    end if
    laws = force_law_kinds()
    associate (law => laws(force_law_kind_index(friction)))
      call read_kind_parameters(r, 'friction', friction, law%parameters, spec, status, rename=rename, &
                                hint='friction = ''none'' for no friction', defaults=defaults)
      call refuse_other_parameters(r, 'friction', friction, law%parameters, law_variables, status, rename=rename)
    end associate
  end subroutine read_friction_law
end module io_friction_config
