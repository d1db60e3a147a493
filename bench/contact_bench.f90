!> Benchmark of contact between moving surfaces (issue 10, docs/contact.md):
!> the shipped inputs timed against the thesis's tables 3.1 and 3.2 (CPU
!> seconds for the whole span, median of repeated runs, nothing recorded),
!> then a tower of n rolling B-spline paraboloids for every tower input given
!> on the command line (bench/contact_bench.sh writes them with
!> scripts/make_contact_inputs.py): CPU seconds per simulated second, right-
!> hand sides and the cost of one right-hand side against n, and the largest n
!> that runs in real time at P1.
!>
!> Usage (from the repository root): contact_bench [tower_seconds tower1.nml ...]
program contact_bench
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_NOT_CONVERGED
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, drive_outcome_name
  use base_text, only: format_short
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use io_input, only: input_text_t, load_input_file
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 9
  real(wp), parameter :: p1(2) = [1e-11_wp, 1e-10_wp], p2(2) = [1e-6_wp, 1e-5_wp]   ! rtol, atol (thesis)
  integer :: i, n, bodies, bodies_1, largest_real_time
  real(wp) :: tower_seconds, cpu_per_second, cost, cost_1
  character(len=512) :: argument
  integer :: rhs

  ! one untimed run first: the first run of a process is the slowest (page
  ! faults, cold caches), whichever case it is
  call run_case('', 'inputs/contact/egg.nml', 0.3_wp, p2, 0.34_wp, 0.02_wp)
  print '(a, i0, a)', 'Thesis tables 3.1/3.2 (CPU s for the span; goal of issue 10 in brackets), median and least of ', &
    repeats, ' runs:'
  print '(a40, a11, a10, a10, a10, a10, a8)', 'case', 'CPU s', 'least s', 'thesis s', 'ratio', 'goal s', 'rhs'
  call run_case('egg, mu 0.3, P1, 10 s', 'inputs/contact/egg.nml', 0.3_wp, p1, 0.92_wp, 0.05_wp)
  call run_case('egg, mu 0.3, P2, 10 s', 'inputs/contact/egg.nml', 0.3_wp, p2, 0.34_wp, 0.02_wp)
  call run_neighbours('egg, mu 0.3 +-2 roundings, P1', 'inputs/contact/egg.nml', 0.3_wp, p1, 0.92_wp, 0.05_wp)
  call run_case('egg, mu 0.8, P1, 10 s', 'inputs/contact/egg.nml', 0.8_wp, p1, 0.92_wp, 0.05_wp)
  call run_case('egg, mu 0.8, P2, 10 s', 'inputs/contact/egg.nml', 0.8_wp, p2, 0.34_wp, 0.02_wp)
  call run_case('paraboloids, P1, 20 s', 'inputs/contact/paraboloids.nml', 0.0_wp, p1, 5.0_wp, 0.25_wp)
  call run_case('paraboloids, P2, 20 s', 'inputs/contact/paraboloids.nml', 0.0_wp, p2, 1.95_wp, 0.1_wp)

  n = command_argument_count()
  if (n < 2) stop
  call get_command_argument(1, argument)
  read (argument, *) tower_seconds
  print '(/, a, f0.1, a)', 'Tower of n rolling B-spline paraboloids at P1, ', tower_seconds, &
    ' s simulated (thesis: 5 in real time; goal: at least 10):'
  print '(a4, a16, a10, a14, a30)', 'n', 'CPU s / sim s', 'rhs', 'us per rhs', 'us per rhs and body / first'
  largest_real_time = 0
  cost_1 = 0
  bodies_1 = 1
  do i = 2, n
    call get_command_argument(i, argument)
    call run_tower(trim(argument), tower_seconds, 3, cpu_per_second, rhs, cost, bodies)
    if (rhs == 0) exit
    if (i == 2) then
      cost_1 = cost
      bodies_1 = bodies
    end if
    if (cpu_per_second < huge(1.0_wp)) then
      print '(i4, f16.3, i10, f14.1, f30.2)', bodies, cpu_per_second, rhs, 1e6_wp*cost, &
        (cost/bodies)/(cost_1/bodies_1)
    else
      print '(i4, a16, i10, f14.1, f30.2)', bodies, 'stopped', rhs, 1e6_wp*cost, (cost/bodies)/(cost_1/bodies_1)
    end if
    if (cpu_per_second <= 1) largest_real_time = max(largest_real_time, bodies)
  end do
  print '(a, i0)', 'largest n of the tower that runs in real time at P1 (CPU s per simulated s <= 1): ', &
    largest_real_time

contains

  !> Reads and builds the input at `path` (mu > 0 replaces the first
  !> contact's friction coefficient).
  subroutine build(path, mu, model, duration, status, bodies)
    character(len=*), intent(in) :: path
    real(wp), intent(in) :: mu
    type(contact_model_t), intent(out), target :: model
    real(wp), intent(out) :: duration
    type(status_t), intent(inout) :: status
    integer, intent(out), optional :: bodies
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(contact_system_t) :: system
    call load_input_file(path, input, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_contact_config(input, system, status)
    if (.not. status%ok()) return
    if (mu > 0) call system%contacts(1)%friction%set('mu', [mu])
    duration = solver%duration
    if (present(bodies)) bodies = size(system%bodies)
    call build_contact_model(system, model, status)
  end subroutine build

  !> CPU seconds of one run of `duration` at tolerances tol (rtol, atol),
  !> right-hand sides and the time reached (a failure keeps them).
  subroutine time_run(model, duration, tol, cpu, rhs, status, reached)
    type(contact_model_t), intent(inout), target :: model
    real(wp), intent(in) :: duration, tol(2)
    real(wp), intent(out) :: cpu
    integer, intent(out) :: rhs
    type(status_t), intent(inout) :: status
    real(wp), intent(out), optional :: reached
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    options%t_end = duration
    options%output_step = duration
    options%progress_seconds = 0
    options%ode%rtol = tol(1)
    options%ode%atol = tol(2)
    options%ode%convergence_coefficient = contact_convergence_coefficient   ! as slidesim runs it
    call drive(model%ode, model%y0, options, result, status)
    cpu = result%cpu
    rhs = int(result%stats%rhs_evaluations)
    if (present(reached)) reached = result%t
    if (status%ok() .and. result%outcome /= DRIVE_END_TIME) &
      call set_status(status, STATUS_NOT_CONVERGED, drive_outcome_name(result%outcome)//' at t = '// &
                      format_short(result%t)//' s')
  end subroutine time_run

  subroutine run_case(label, path, mu, tol, thesis, goal)
    character(len=*), intent(in) :: label, path
    real(wp), intent(in) :: mu, tol(2), thesis, goal
    type(contact_model_t), target :: model
    type(status_t) :: status
    real(wp) :: cpu(repeats), duration
    integer :: r, rhs
    do r = 1, repeats
      call build(path, mu, model, duration, status)
      if (status%ok()) call time_run(model, duration, tol, cpu(r), rhs, status)
      if (.not. status%ok()) then
        print '(a40, 2x, a)', label, 'FAILED: '//status%text()
        return
      end if
    end do
    if (len(label) > 0) print '(a40, f11.3, f10.3, f10.2, f10.3, f10.2, i8)', label, median(cpu), minval(cpu), thesis, &
      median(cpu)/thesis, goal, rhs
  end subroutine run_case

  !> The case at mu and at its 2 + 2 floating-point neighbours (mu moved by
  !> one or two roundings): the step count of Adams at P1 is a lottery in
  !> them (docs/contact.md, "Corrector"), so one mu alone can land far from
  !> the typical cost. Prints the median over the 5 of each one's median
  !> (and least) CPU s and the range of their right-hand sides.
  subroutine run_neighbours(label, path, mu, tol, thesis, goal)
    character(len=*), intent(in) :: label, path
    real(wp), intent(in) :: mu, tol(2), thesis, goal
    type(contact_model_t), target :: model
    type(status_t) :: status
    real(wp) :: cpu(repeats), duration, each(-2:2), least(-2:2), moved
    integer :: k, r, rhs(-2:2)
    do k = -2, 2
      moved = mu
      do r = 1, abs(k)
        moved = nearest(moved, real(k, wp))
      end do
      do r = 1, repeats
        call build(path, moved, model, duration, status)
        if (status%ok()) call time_run(model, duration, tol, cpu(r), rhs(k), status)
        if (.not. status%ok()) then
          print '(a40, 2x, a)', label, 'FAILED: '//status%text()
          return
        end if
      end do
      each(k) = median(cpu)
      least(k) = minval(cpu)
    end do
    print '(a40, f11.3, f10.3, f10.2, f10.3, f10.2, i8, a, i0, a)', label, median(each), median(least), thesis, &
      median(each)/thesis, goal, minval(rhs), ' - ', maxval(rhs), ' (median of the 5 mu)'
  end subroutine run_neighbours

  !> A tower input run for `seconds` at P1: median CPU s per simulated s,
  !> right-hand sides, CPU s per right-hand side (rhs = 0: not built) and
  !> the number of bodies. A run that stops early is timed up to there and
  !> reported (the cost per right-hand side still counts).
  subroutine run_tower(path, seconds, count, cpu_per_second, rhs, cost, bodies)
    character(len=*), intent(in) :: path
    real(wp), intent(in) :: seconds
    integer, intent(in) :: count
    real(wp), intent(out) :: cpu_per_second, cost
    integer, intent(out) :: rhs, bodies
    type(contact_model_t), target :: model
    type(status_t) :: status
    real(wp) :: cpu(count), per_rhs(count), per_second(count), duration, reached
    integer :: r
    rhs = 0
    cpu_per_second = huge(1.0_wp)
    cost = 0
    bodies = 0
    do r = 1, count
      status = status_t()
      call build(path, 0.0_wp, model, duration, status, bodies)
      if (.not. status%ok()) then
        print '(a, 2x, a)', path, 'FAILED: '//status%text()
        rhs = 0
        return
      end if
      call time_run(model, seconds, p1, cpu(r), rhs, status, reached)
      if (.not. status%ok() .and. r == 1) print '(4x, a, i0, a)', 'tower of ', bodies, ': '//status%text()
      per_rhs(r) = cpu(r)/max(rhs, 1)
      per_second(r) = huge(1.0_wp)
      if (status%ok()) per_second(r) = cpu(r)/seconds
    end do
    cpu_per_second = median(per_second)
    cost = median(per_rhs)
  end subroutine run_tower
end program contact_bench
