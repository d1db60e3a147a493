!> Scenario `contact`: bodies in point contact between smooth surfaces
!> (thesis 3.5.3; docs/contact.md): the spinning egg, rolling paraboloids, a
!> tower, a ball on an incline. The description (&contact_model, &shape,
!> &body, &contact) is built into one mechanism by contact_model and run by
!> the multibody scenarios' common run (scenarios_mechanism).
module scenarios_contact
  use base_status, only: status_t, prefix_status
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model
  use io_input, only: input_text_t, check_known_groups, mark_input_failure
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config, contact_groups, contact_repeatable_groups
  use scenarios_mechanism, only: run_mechanism
  implicit none (type, external)
  private
  public :: run_contact, contact_groups

contains

  subroutine run_contact(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(contact_system_t) :: system
    type(contact_model_t), target :: model
    integer :: f, ns

    call check_known_groups(input, contact_groups, status, repeatable=contact_repeatable_groups)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_contact_config(input, system, status)
    if (.not. status%ok()) return
    call build_contact_model(system, model, status)
    if (.not. status%ok()) then
      call prefix_status(status, input%name//': contact')
      call mark_input_failure(status)
      return
    end if
    f = model%ode%mechanism%f
    ns = model%ode%mechanism%ns
    call run_mechanism('contact', input, run, solver, model%ode, model%y0(1:f), model%y0(f + 1:f + ns), &
                       model%q_units, model%beta_units, status, &
                       surface=system%shapes(first_shape(system))%surface)
  end subroutine run_contact

  !> The shape of the first contact's surface 1 (its grid goes into the result).
  pure integer function first_shape(system) result(k)
    type(contact_system_t), intent(in) :: system
    do k = 1, size(system%shapes)
      if (system%shapes(k)%name == system%contacts(1)%shape_1) return
    end do
    k = 1
  end function first_shape
end module scenarios_contact
