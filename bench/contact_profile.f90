!> One run of a contact input (no repeats, nothing recorded), for profiling
!> with callgrind and for the integrator's counts: steps, right-hand sides,
!> error-test and nonlinear failures, root evaluations, events, restarts, and
!> the root calls the stored values served or that evaluated the dynamics.
!>
!> Usage (from the repository root):
!>   contact_profile input.nml [p1|p2|ref] [mu] [seconds] [coefficient] [file]
!> p1: rtol 1e-11, atol 1e-10; p2: 1e-6, 1e-5 (thesis); ref: 1e-13, 1e-12 (a
!> reference); mu > 0 replaces the first contact's friction coefficient;
!> seconds > 0 replaces the input's duration; coefficient > 0 replaces Adams'
!> corrector coefficient (CVODE's nlscoef; default slidesim's for contact,
!> contact_convergence_coefficient); with `file`, the first body's
!> state every 5 ms is written there (t, tilt of body y from the vertical in
!> degrees, origin x y z in m, energy in J), for comparisons with a reference.
program contact_profile
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use io_input, only: input_text_t, load_input_file
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  implicit none (type, external)

  character(len=512) :: path, argument, file
  real(wp) :: mu, tol(2), coefficient, duration
  integer :: unit, i
  type(input_text_t) :: input
  type(solver_config_t) :: solver
  type(contact_system_t) :: system
  type(contact_model_t), target :: model
  type(status_t) :: status
  type(driver_options_t) :: options
  type(driver_result_t) :: result

  if (command_argument_count() < 1) then
    print '(a)', 'usage: contact_profile input.nml [p1|p2|ref] [mu] [seconds] [coefficient] [file]'
    stop
  end if
  call get_command_argument(1, path)
  tol = [1e-11_wp, 1e-10_wp]
  mu = 0
  call load_input_file(trim(path), input, status)
  if (status%ok()) call read_solver_config(input, solver, status)
  if (status%ok()) call read_contact_config(input, system, status)
  options%t_end = solver%duration
  if (command_argument_count() >= 2) then
    call get_command_argument(2, argument)
    if (argument == 'p2') tol = [1e-6_wp, 1e-5_wp]
    if (argument == 'ref') tol = [1e-13_wp, 1e-12_wp]
  end if
  if (command_argument_count() >= 3) then
    call get_command_argument(3, argument)
    read (argument, *) mu
  end if
  if (command_argument_count() >= 4) then
    call get_command_argument(4, argument)
    read (argument, *) duration
    if (duration > 0) options%t_end = duration
  end if
  coefficient = 0
  if (command_argument_count() >= 5) then
    call get_command_argument(5, argument)
    read (argument, *) coefficient
  end if
  file = ''
  if (command_argument_count() >= 6) call get_command_argument(6, file)
  if (status%ok() .and. mu > 0) call system%contacts(1)%friction%set('mu', [mu])
  if (status%ok()) call build_contact_model(system, model, status)
  if (.not. status%ok()) then
    print '(a)', status%text()
    stop
  end if
  options%output_step = options%t_end
  options%progress_seconds = 0
  options%ode%rtol = tol(1)
  options%ode%atol = tol(2)
  options%ode%convergence_coefficient = contact_convergence_coefficient
  if (coefficient > 0) options%ode%convergence_coefficient = coefficient
  if (len_trim(file) > 0) then
    options%output_step = 5e-3_wp
    call model%ode%start_series(nint(options%t_end/options%output_step) + 20)
  end if
  call drive(model%ode, model%y0, options, result, status)
  if (len_trim(file) > 0) then
    open (newunit=unit, file=trim(file), status='replace', action='write')
    associate (s => model%ode%series)
      do i = 1, s%n
        write (unit, '(6es25.16e3)') s%time(i), acos(min(abs(s%body_rot(3, 2, 1, i)), 1.0_wp))*180/acos(-1.0_wp), &
          s%body_r(:, 1, i), s%kinetic(i) + s%potential(i)
      end do
    end associate
    close (unit)
  end if
  if (.not. status%ok()) print '(a)', status%text()
  print '(a, f0.4, a, f0.3)', 't reached ', result%t, '  CPU s ', result%cpu
  print '(a, i0, a, i0, a, i0, a, i0, a, i0)', 'steps ', result%stats%steps, '  rhs ', &
    result%stats%rhs_evaluations, '  error-test failures ', result%stats%error_test_failures, &
    '  nonlinear failures ', result%stats%nonlinear_failures, '  root evaluations ', result%stats%root_evaluations
  print '(a, i0, a, i0, a, i0)', 'events ', result%events, '  restarts ', result%restarts, &
    '  last order ', result%stats%last_order
  associate (ode => model%ode)
    print '(a, i0, a, i0, a, i0, a, i0, a, i0)', 'root calls ', ode%root_calls, '  served by stored values ', &
      ode%root_cache_hits, '  dynamics ', ode%root_dynamics, ' (at outputs ', ode%root_dynamics_at_outputs, &
      ')  partial ', ode%root_partial
  end associate
end program contact_profile
