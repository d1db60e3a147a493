!> &solver: the ODE integrator's settings and the simulated time span.
module io_solver_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t
  use numerics_ode, only: ode_options_t, ODE_ADAMS, ODE_BDF
  use io_input, only: input_text_t, namelist_read_error, check_positive, check_range, &
                      check_choice, check_nonnegative, invalid, format_real, lower
  implicit none (type, external)
  private
  public :: solver_config_t, read_solver_config

  type :: solver_config_t
    type(ode_options_t) :: options
    real(wp) :: duration = 10       ! s
    real(wp) :: output_step = 0.01_wp   ! s
  end type solver_config_t

contains

  subroutine read_solver_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    character(len=16) :: method
    real(wp) :: rtol, atol, duration, output_step, initial_step, max_step
    integer :: max_steps, ios
    character(len=256) :: msg
    namelist /solver/ method, rtol, atol, max_steps, initial_step, max_step, duration, output_step
    character(len=*), parameter :: g = 'solver'

    method = 'adams'
    rtol = config%options%rtol
    atol = config%options%atol
    max_steps = config%options%max_steps
    initial_step = config%options%initial_step
    max_step = config%options%max_step
    duration = config%duration
    output_step = config%output_step
    read (input%lines, nml=solver, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=12) :: 'method', 'rtol', 'atol', &
                               'max_steps', 'initial_step', 'max_step', 'duration', 'output_step'], status)
      return
    end if
    call check_choice(input, g, 'method', method, [character(len=5) :: 'adams', 'bdf'], status)
    call check_range(input, g, 'rtol', rtol, 1e-14_wp, 1e-2_wp, '1', status)
    call check_range(input, g, 'atol', atol, 1e-16_wp, 1.0_wp, 'units of the state', status)
    call check_positive(input, g, 'duration', duration, 's', status)
    call check_positive(input, g, 'output_step', output_step, 's', status)
    call check_nonnegative(input, g, 'initial_step', initial_step, 's', status)
    call check_nonnegative(input, g, 'max_step', max_step, 's', status)
    if (status%ok() .and. max_steps < 1) &
      call invalid(input, g, 'max_steps', format_integer(max_steps), 'must be an integer >= 1', status)
    if (status%ok() .and. output_step > duration) &
      call invalid(input, g, 'output_step', format_real(output_step), &
                   'must not exceed duration = '//format_real(duration)//' s', status)
    if (.not. status%ok()) return

    config%options%method = merge(ODE_BDF, ODE_ADAMS, lower(adjustl(method)) == 'bdf')
    config%options%rtol = rtol
    config%options%atol = atol
    config%options%max_steps = max_steps
    config%options%initial_step = initial_step
    config%options%max_step = max_step
    config%duration = duration
    config%output_step = output_step
  end subroutine read_solver_config
end module io_solver_config
