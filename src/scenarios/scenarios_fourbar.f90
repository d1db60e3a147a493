!> Scenario `fourbar`: a planar four-bar linkage whose loop is closed by two
!> plane-point measurements (thesis 3.2.2, 3.3), driven only by gravity and its
!> initial crank speed.
module scenarios_fourbar
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: fourbar_description_t, build_fourbar_model
  use io_input, only: input_text_t, check_known_groups, mark_input_failure, where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_mechanism_config, only: read_fourbar_config
  use scenarios_mechanism, only: run_mechanism
  implicit none (type, external)
  private
  public :: run_fourbar, fourbar_groups

  character(len=*), parameter :: fourbar_groups(3) = [character(len=8) :: 'run', 'solver', 'fourbar']

contains

  subroutine run_fourbar(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(fourbar_description_t) :: description
    type(mechanism_ode_t), target :: sys
    real(wp), allocatable :: q0(:), qd0(:)

    call check_known_groups(input, fourbar_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_fourbar_config(input, description, status)
    if (.not. status%ok()) return
    call build_fourbar_model(description, sys%mechanism, q0, qd0, status)
    if (.not. status%ok()) then
      call prefix_status(status, where_given(input, 'fourbar', '')//': &fourbar')
      call mark_input_failure(status)
      return
    end if
    call run_mechanism('fourbar', input, run, solver, sys, q0, qd0, &
                       [character(len=4) :: 'rad'], [character(len=4) :: 'rad', 'rad'], status, &
                       start_variables='crank0, dcrank0, branch')
  end subroutine run_fourbar
end module scenarios_fourbar
