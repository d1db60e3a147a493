!> Benchmark of the point-mass scenario: for each input file given on the command
!> line, integrates the run 7 times (no output file) and prints the median CPU
!> seconds per simulated second and the right-hand-side evaluations.
program point_mass_bench
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_integrator_t, ode_stats_t
  use kinetostatics_point_mass, only: point_mass_t
  use io_input, only: input_text_t, load_input_file
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 7
  type(input_text_t) :: input
  type(solver_config_t) :: solver
  type(point_mass_t), target :: model
  type(ode_integrator_t) :: ode
  type(ode_stats_t) :: stats
  type(status_t) :: status
  character(len=512) :: path
  real(wp), allocatable :: y0(:), y(:)
  real(wp) :: t, start, finish, cpu(repeats)
  integer :: i, r, k, n_out

  print '(a40, 3a16)', 'input', 'CPU s / sim s', 'rhs evals', 'steps'
  do i = 1, command_argument_count()
    call get_command_argument(i, path)
    call load_input_file(trim(path), input, status)
    if (status%ok()) call build_point_mass(input, solver, model, y0, status)
    if (.not. status%ok()) then
      print '(a)', trim(path)//': '//status%text()
      cycle
    end if
    n_out = nint(solver%duration/solver%output_step)
    y = y0   ! its size: the state's (with the air's drag one more)
    do r = 1, repeats
      call cpu_time(start)
      call ode%start(model, 0.0_wp, y0, solver%options, status)
      do k = 1, n_out
        call ode%advance(min(k*solver%output_step, solver%duration), t, y, status)
        if (.not. status%ok()) exit
      end do
      call cpu_time(finish)
      cpu(r) = finish - start
    end do
    stats = ode%statistics()
    print '(a40, es16.3, 2i16)', trim(path(max(1, len_trim(path) - 39):)), median(cpu)/solver%duration, &
      stats%rhs_evaluations, stats%steps
  end do

end program point_mass_bench
