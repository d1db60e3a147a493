!> Rolling B-spline paraboloids from their shipped inputs (thesis 3.5.3.3,
!> table 3.2, and the tower of A.6): inputs/contact/paraboloids.nml (paraboloid
!> 2 on the table, paraboloid 3 in its bowl) for its 20 s and
!> inputs/contact/tower5.nml (five nested bowls) for its 5 s (the thesis's 20
!> s take about 6 s of CPU in Release: too long for a test), both rolling at
!> every contact, at P1. Rolling is lossless: the energy is conserved to 1e-8 of the largest
!> kinetic energy; the position-level closure stays below 1e-10 and the slip
!> below 1e-10 m/s at every output. The two paraboloids at velocity level (P2,
!> no stabilisation) drift (thesis fig. 3.23): their closure residual is
!> reported next to the position level's.
program test_rolling_paraboloids
  use base_kinds, only: wp
  use base_status, only: status_t
  use testing, only: check, finish_tests
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, &
    contact_convergence_coefficient, LEVEL_VELOCITY
  use io_input, only: input_text_t, load_input_file
  use io_contact_config, only: read_contact_config
  implicit none (type, external)

  real(wp) :: drift_position, drift_velocity

  call rolling('inputs/contact/paraboloids.nml', 20.0_wp, 1e-11_wp, 1e-10_wp, .false., drift_position)
  call rolling('inputs/contact/tower5.nml', 5.0_wp, 1e-11_wp, 1e-10_wp, .false.)
  call rolling('inputs/contact/paraboloids.nml', 20.0_wp, 1e-6_wp, 1e-5_wp, .true., drift_velocity)
  print '(a, es9.2, a, es9.2, a)', 'paraboloids, closure residual max over 20 s: position level (P1) ', &
    drift_position, ' m, velocity level (P2) ', drift_velocity, ' m'
  call check(drift_velocity > 1e3_wp*max(drift_position, 1e-16_wp), 'the velocity-level paraboloids drift')
  call finish_tests('test_rolling_paraboloids')

contains

  subroutine rolling(path, duration, rtol, atol, velocity_level, drift)
    character(len=*), intent(in) :: path
    real(wp), intent(in) :: duration, rtol, atol
    logical, intent(in) :: velocity_level
    real(wp), intent(out), optional :: drift
    type(input_text_t) :: input
    type(contact_system_t) :: system
    type(contact_model_t), target :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: energy_error, slip, closure, scale
    integer :: i, n
    character(len=:), allocatable :: label
    label = path(index(path, '/', back=.true.) + 1:)
    if (velocity_level) label = label//', velocity level'
    call load_input_file(path, input, st)
    call read_contact_config(input, system, st)
    if (velocity_level) system%contacts%level = LEVEL_VELOCITY
    call build_contact_model(system, model, st)
    call check(st%ok(), label//' built: '//st%text())
    if (.not. st%ok()) return
    options%t_end = duration
    options%output_step = 0.01_wp
    options%progress_seconds = 0
    options%ode%rtol = rtol
    options%ode%atol = atol
    call model%ode%start_series(nint(duration/options%output_step) + 100)
    options%ode%convergence_coefficient = contact_convergence_coefficient   ! as slidesim runs it
    call drive(model%ode, model%y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//' ran to the end: '//st%text())
    associate (s => model%ode%series)
      n = s%n
      if (n < 2) return
      scale = maxval(s%kinetic(:n))
      energy_error = maxval(abs(s%kinetic(:n) + s%potential(:n) - s%kinetic(1) - s%potential(1)))/scale
      slip = maxval([(maxval(norm2(s%slip(:, :, i), dim=1)), i = 1, n)])
      closure = maxval([(maxval(abs(s%monitor(:, i))), i = 1, n)])
      if (present(drift)) drift = closure
      if (.not. velocity_level) then
        ! rtol 1e-11 over ~5000 steps of a conservative motion: ~1e-9 of the energy
        call check(energy_error <= 1e-8_wp, label//': energy conserved to 1e-8 (rolling is lossless)')
        call check(closure < 1e-10_wp, label//': closure below 1e-10 at every output')
        call check(slip < 1e-10_wp, label//': slip below 1e-10 m/s at every output')
        call check(all(s%normal(:, :n) > 0), label//': the contacts press throughout')
      end if
      print '(a, 3(a, es9.2), a, i0, a, f7.3, a)', label, ': energy error ', energy_error, ', closure ', closure, &
        ' m, slip ', slip, ' m/s, ', model%ode%rhs_count, ' right-hand sides, ', result%cpu, ' s CPU'
    end associate
  end subroutine rolling
end program test_rolling_paraboloids
