!> The run driver shared by the multibody scenarios (pendulum, fourbar, sled):
!> check the start, open the result file, integrate and record, write, summarize.
module scenarios_mechanism
  use, intrinsic :: iso_fortran_env, only: output_unit
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use base_log, only: log_info
  use numerics_ode, only: ode_stats_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_recorder, only: mechanism_series_t, integrate_mechanism
  use io_input, only: input_text_t, format_real
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t
  use io_mechanism_config, only: write_mechanism_series
  use io_hdf5, only: result_file_t
  use io_surface_grid, only: write_surface_grid_around
  use geometry_surface, only: surface_t
  implicit none (type, external)
  private
  public :: run_mechanism

contains

  !> The common run of a multibody scenario from y0 = [q0, q0'].
  subroutine run_mechanism(scenario, input, run, solver, sys, y0, q_units, beta_units, status, surface)
    character(len=*), intent(in) :: scenario
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(solver_config_t), intent(in) :: solver
    type(mechanism_ode_t), intent(inout), target :: sys
    real(wp), intent(in) :: y0(:)
    character(len=*), intent(in) :: q_units(:), beta_units(:)   ! units of the q and of the dependent beta
    type(status_t), intent(inout) :: status
    class(surface_t), intent(in), optional :: surface   ! the surface of the contacts, written as a grid
    type(result_file_t) :: file
    type(mechanism_series_t) :: series
    type(ode_stats_t) :: stats
    type(status_t) :: run_status, write_status
    real(wp) :: cpu

    call sys%mechanism%check_start(y0(1:sys%mechanism%f), status)
    if (.not. status%ok()) then
      call prefix_status(status, input%name//': '//scenario)
      return
    end if
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call log_info(scenario//': '//format_real(solver%duration)//' s, output every '// &
                  format_real(solver%output_step)//' s')
    call integrate_mechanism(sys, y0, solver%options, solver%duration, solver%output_step, series, stats, &
                             cpu, run_status)
    if (.not. run_status%ok()) call prefix_status(run_status, scenario)
    call write_mechanism_series(file, scenario, input, run%title, series, stats, cpu, q_units, beta_units, &
                                write_status)
    ! the grid around the first contact's path (u, v are its first two coordinates)
    if (present(surface)) call write_surface_grid_around(file, surface, series%q(1, :series%n), &
                                                         series%q(2, :series%n), write_status)
    if (run_status%ok()) then
      call file%finish(write_status%ok(), write_status%text(), write_status)
    else
      call file%finish(.false., run_status%text(), write_status)
    end if
    call print_summary(scenario, series, stats, cpu, file%final_path(), run_status)
    if (.not. run_status%ok()) then
      status = run_status
    else if (.not. write_status%ok()) then
      status = write_status
    end if
  end subroutine run_mechanism

  subroutine print_summary(scenario, s, stats, cpu, path, run_status)
    character(len=*), intent(in) :: scenario
    type(mechanism_series_t), intent(in) :: s
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: path
    type(status_t), intent(in) :: run_status
    real(wp) :: e0, scale
    integer :: n, k
    n = s%n
    if (n < 1) return
    e0 = s%kinetic(1) + s%potential(1)
    scale = max(maxval(s%kinetic(:n)), maxval(abs(s%potential(:n) - s%potential(1))), tiny(1.0_wp))
    write (output_unit, '(a)') 'slidesim '//scenario
    write (output_unit, '(a, f0.4, a)') '  simulated time       ', s%time(n), ' s'
    do k = 1, s%f
      write (output_unit, '(a, a12, es14.6, a, es14.6)') '  final ', s%q_names(k), s%q(k, n), '  rate ', s%qd(k, n)
    end do
    write (output_unit, '(a, es10.3, a)') '  energy change        ', &
      (s%kinetic(n) + s%potential(n) - e0)/scale, ' (relative to the largest kinetic/potential change)'
    if (s%r > 0) write (output_unit, '(a, es10.3, a)') '  closure residual max ', maxval(s%closure(:n)), ' m'
    do k = 1, s%nc
      write (output_unit, '(a, a8, a, 2f12.4, a)') '  contact ', s%contact_names(k), ' normal force min/max', &
        minval(s%normal(k, :n)), maxval(s%normal(k, :n)), ' N'
    end do
    write (output_unit, '(a, i0, a, i0, a)') '  integrator           ', stats%steps, ' steps, ', &
      stats%rhs_evaluations, ' right-hand sides'
    write (output_unit, '(a, es10.3, a, es10.3, a)') '  CPU time             ', cpu, ' s (', &
      cpu/max(s%time(n), tiny(1.0_wp)), ' s per simulated second)'
    if (run_status%ok()) then
      write (output_unit, '(a)') '  results              '//path
    else
      write (output_unit, '(a)') '  results (INCOMPLETE) '//path
    end if
  end subroutine print_summary
end module scenarios_mechanism
