!> A ball in a conical bowl (the `cone` surface of revolution and the
!> `sphere` kind, from namelist text through the contact scenario's reader):
!>   - frictionless, on the steady circular orbit: the normal force through the
!>     ball's centre balances gravity and the centripetal force, so the centre
!>     (on the offset cone, half-angle alpha) circles at v^2 = g rho_c/tan(alpha)
!>     with N = m g/sin(alpha): rho_c and z_c stay, and after one period
!>     T = 2 pi rho_c/v the ball is back where it started;
!>   - frictionless from a slower start: it rises and falls in the bowl; the
!>     energy and the angular momentum about the axis m (x v_y - y v_x) stay
!>     (the normal force meets the axis, gravity is parallel to it, the ball
!>     does not spin);
!>   - rolling (no slip) from the same start: the energy stays (no slip, no work).
!> The input gives no gravity: the default, standard gravity (9.80665 m/s^2).
program test_revolution_bowl
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use scenario_fixtures, only: number
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity, alpha = pi/6, z_touch = 0.5_wp, radius = 0.05_wp, mass = 0.2_wp
  real(wp) :: rho_c, z_c, speed, period

  ! the centre of the ball touching the cone at height z_touch, x > 0
  rho_c = z_touch*tan(alpha) - radius*cos(alpha)
  z_c = z_touch + radius*sin(alpha)
  speed = sqrt(g*rho_c/tan(alpha))
  period = 2*pi*rho_c/speed
  call steady_orbit()
  call rise_and_fall('', 'sliding')
  call rise_and_fall(', rolling = .true.', 'rolling')
  call finish_tests('test_revolution_bowl')

contains

  function bowl_input(duration, v0, contact, rolls) result(text)
    real(wp), intent(in) :: duration, v0
    character(len=*), intent(in) :: contact
    logical, intent(in) :: rolls   ! start rolling: omega x (P - C) = -v, omega in the meridian plane
    character(len=:), allocatable :: text
    character(len=400) :: numbers
    character(len=:), allocatable :: spin
    spin = ''
    if (rolls) spin = ', angular_velocity = '//number(-v0/radius*sin(alpha))//', 0, '//number(-v0/radius*cos(alpha))
    write (numbers, '(a, es24.17, a, es24.17, a, es24.17, a, es24.17)') 'duration = ', duration, &
      ', output_step = ', duration/40, ' /'//nl//'&body name = ''ball'', mass = 0.2, solid_of = ''ball'', '// &
      'position = ', rho_c, ', 0, ', z_c
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-11, atol = 1e-11, '//trim(numbers)//', velocity = 0, '//number(v0)//', 0'//spin//' /'//nl// &
           '&shape name = ''bowl'', kind = ''cone'', half_angle_deg = 30, z_min = 0.1, z_max = 1.0 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.05 /'//nl// &
           '&contact name = ''in_bowl'', shape_1 = ''bowl'', side_1 = -1, body_2 = ''ball'', '// &
           'shape_2 = ''ball'''//contact//' /'//nl
  end function bowl_input

  subroutine run(text, model, label)
    character(len=*), intent(in) :: text, label
    type(contact_model_t), intent(inout), target :: model
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(contact_system_t) :: system
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    call input_from_text(label, text, input, st)
    call read_solver_config(input, solver, st)
    call read_contact_config(input, system, st)
    call build_contact_model(system, model, st)
    call check(st%ok(), label//': built from the input: '//st%text())
    if (.not. st%ok()) return
    options%ode = solver%options
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call model%ode%start_series(60)
    call drive(model%ode, model%y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//': ran: '//st%text())
  end subroutine run

  !> rtol 1e-11 over two revolutions (a few hundred steps): positions to 1e-9 m.
  subroutine steady_orbit()
    type(contact_model_t), target :: model
    real(wp) :: worst_rho, worst_z, worst_n
    integer :: i, n
    call run(bowl_input(2*period, speed, '', .false.), model, 'steady orbit')
    associate (s => model%ode%series)
      n = s%n
      call check(n == 41, 'steady orbit: 41 records, one every T/20')
      if (n /= 41) return
      worst_rho = 0
      worst_z = 0
      worst_n = 0
      do i = 1, n
        worst_rho = max(worst_rho, abs(norm2(s%body_r(1:2, s%nb, i)) - rho_c))
        worst_z = max(worst_z, abs(s%body_r(3, s%nb, i) - z_c))
        worst_n = max(worst_n, abs(s%normal(1, i) - mass*g/sin(alpha)))
      end do
      call check_close(worst_rho, 0.0_wp, 0.0_wp, 1e-9_wp, 'steady orbit: the centre''s distance from the axis (m)')
      call check_close(worst_z, 0.0_wp, 0.0_wp, 1e-9_wp, 'steady orbit: the centre''s height (m)')
      call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-9_wp*mass*g, 'steady orbit: N = m g/sin(alpha) (N)')
      ! after two periods (the last record) back at the start
      call check_close(norm2(s%body_r(:, s%nb, n) - [rho_c, 0.0_wp, z_c]), 0.0_wp, 0.0_wp, 1e-8_wp, &
                       'steady orbit: back at the start after two periods T = 2 pi rho_c/v (m)')
      call check_close(norm2(s%body_r(:, s%nb, 21) - [rho_c, 0.0_wp, z_c]), 0.0_wp, 0.0_wp, 1e-8_wp, &
                       'steady orbit: back at the start after one period (m)')
      call check_close(norm2(s%body_r(:, s%nb, 11) - [-rho_c, 0.0_wp, z_c]), 0.0_wp, 0.0_wp, 1e-8_wp, &
                       'steady orbit: opposite after half a period (m)')
    end associate
  end subroutine steady_orbit

  !> 80 % of the orbit's speed: the ball sinks and rises. Energy to 1e-9 of
  !> the energies exchanged (rtol 1e-11 over ~1000 steps), L_z to 1e-9.
  subroutine rise_and_fall(contact, label)
    character(len=*), intent(in) :: contact, label
    type(contact_model_t), target :: model
    real(wp), allocatable :: e(:), lz(:), z(:)
    real(wp) :: scale
    integer :: n, i
    call run(bowl_input(2*period, 0.8_wp*speed, contact, contact /= ''), model, label)
    associate (s => model%ode%series)
      n = s%n
      if (n < 2) return
      e = s%kinetic(:n) + s%potential(:n)
      z = s%body_r(3, s%nb, :n)
      scale = maxval(s%kinetic(:n))
      call check(maxval(z) - minval(z) > 1e-3_wp, label//': the ball sinks and rises (more than 1 mm)')
      call check_close(maxval(abs(e - e(1))), 0.0_wp, 0.0_wp, 1e-9_wp*scale, label//': energy (J)')
      if (contact == '') then
        lz = [(mass*(s%body_r(1, s%nb, i)*s%body_v(2, s%nb, i) - s%body_r(2, s%nb, i)*s%body_v(1, s%nb, i)), &
               i = 1, n)]
        call check_close(maxval(abs(lz - lz(1))), 0.0_wp, 0.0_wp, 1e-9_wp*abs(lz(1)), &
                         label//': angular momentum about the axis (kg m^2/s)')
      end if
    end associate
  end subroutine rise_and_fall
end program test_revolution_bowl
