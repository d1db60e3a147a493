!> Scenario `fourbar`: a planar four-bar linkage whose loop is closed by two
!> plane-point measurements (thesis 3.2.2, 3.3), driven only by gravity and its
!> initial crank speed.
module scenarios_fourbar
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: build_fourbar, fourbar_assembly
  use io_input, only: input_text_t, check_known_groups, mark_input_failure, where_given
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_mechanism_config, only: fourbar_config_t, read_fourbar_config
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
    type(fourbar_config_t) :: config
    type(mechanism_ode_t), target :: sys
    real(wp) :: beta0(2)

    call check_known_groups(input, fourbar_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_fourbar_config(input, config, status)
    if (.not. status%ok()) return
    ! the assembly gives the start of the closure; the closure itself decides
    call fourbar_assembly(config%params, config%crank0, config%branch, beta0, status)
    if (.not. status%ok()) then
      call prefix_status(status, where_given(input, 'fourbar', '')//': &fourbar: loop ''coupler-rocker''')
      status%message = status%message//'; change a, b, c, d or crank0'
      call mark_input_failure(status)
      return
    end if
    call build_fourbar(config%params, beta0, sys%mechanism, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    call run_mechanism('fourbar', input, run, solver, sys, [config%crank0], [config%dcrank0], &
                       [character(len=4) :: 'rad'], [character(len=4) :: 'rad', 'rad'], status, &
                       start_variables='crank0, dcrank0, branch')
  end subroutine run_fourbar
end module scenarios_fourbar
