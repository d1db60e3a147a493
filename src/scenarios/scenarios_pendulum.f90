!> Scenario `pendulum`: a simple or double pendulum (revolutes about y, gravity
!> along -z by default), run by the multibody driver of scenarios_mechanism.
module scenarios_pendulum
  use base_status, only: status_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use base_kinds, only: wp
  use kinetostatics_models, only: pendulum_description_t, build_pendulum_model
  use io_input, only: input_text_t, check_known_groups, mark_input_failure
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_mechanism_config, only: read_pendulum_config
  use scenarios_mechanism, only: run_mechanism
  implicit none (type, external)
  private
  public :: run_pendulum, pendulum_groups

  character(len=*), parameter :: pendulum_groups(3) = [character(len=8) :: 'run', 'solver', 'pendulum']

contains

  subroutine run_pendulum(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(pendulum_description_t) :: description
    type(mechanism_ode_t), target :: sys
    real(wp), allocatable :: q0(:), qd0(:)

    call check_known_groups(input, pendulum_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_pendulum_config(input, description, status)
    if (status%ok()) call build_pendulum_model(description, sys%mechanism, q0, qd0, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    call run_mechanism('pendulum', input, run, solver, sys, q0, qd0, &
                       [character(len=4) :: 'rad', 'rad'], [character(len=4) ::], status, &
                       start_variables='theta0, dtheta0')
  end subroutine run_pendulum
end module scenarios_pendulum
