!> Flight (issue 25, first slice): a contact that starts open leaves its body
!> where &body puts it, flying free under gravity, and the run ends where
!> the gap falls to zero (contact_flight). From namelist text through the
!> contact scenario's reader:
!>   - a ball (radius r) dropped with its lowest point h above a plane, moving
!>     sideways at u and spinning: it lands at t = sqrt(2 h/g) with the
!>     approach speed g t, at x = u t; the recorded gap is h - g t^2/2 at
!>     every record; the energy stays; a sphere's angular velocity stays
!>     (torque-free, isotropic) through the free rotation's chart changes;
!>   - refused: an open start that touches or overlaps, more than one
!>     contact or body, friction on an open start (unused: the run ends at
!>     the landing).
!> Tolerances: rtol = atol = 1e-12 over ~100 steps of a polynomial motion
!> (the parabola is a degree-2 polynomial: Adams reproduces it nearly
!> exactly), so positions to 1e-10 m; the landing root is located to
!> CVODE's 1e-14 s-ish, its time checked to 1e-10 s.
program test_flight
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_EVENT_STOP
  use contact_model, only: contact_system_t, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t, build_flight
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity, radius = 0.1_wp, h = 1.0_wp, u = 0.3_wp
  real(wp), parameter :: spin(3) = [10.0_wp, -20.0_wp, 30.0_wp]   ! rad/s: several chart changes of the free rotation

  call dropped_ball()
  call refusals()
  call finish_tests('test_flight')

contains

  function ball_input(height, extra) result(text)
    real(wp), intent(in) :: height   ! of the ball's lowest point above the plane (m)
    character(len=*), intent(in) :: extra   ! appended to the text
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 2, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''ball'', mass = 0.2, solid_of = ''ball'', position = 0, 0, '//number(radius + height)// &
           ', velocity = '//number(u)//', 0, 0, angular_velocity = '//number(spin(1))//', '//number(spin(2))// &
           ', '//number(spin(3))//' /'//nl// &
           '&contact name = ''on_floor'', shape_1 = ''floor'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'start = ''open'' /'//nl//extra
  end function ball_input

  !> text with its first `old` replaced by `new`.
  function replace(text, old, new) result(changed)
    character(len=*), intent(in) :: text, old, new
    character(len=:), allocatable :: changed
    integer :: at
    at = index(text, old)
    changed = text(:at - 1)//new//text(at + len(old):)
  end function replace

  function number(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=30) :: buffer
    write (buffer, '(es24.17)') x
    text = trim(adjustl(buffer))
  end function number

  subroutine build(text, label, flight, q0, qd0, st)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(out) :: st
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(contact_system_t) :: system
    character(len=8), allocatable :: units(:)
    call input_from_text(label, text, input, st)
    call read_solver_config(input, solver, st)
    call read_contact_config(input, system, st)
    call build_flight(system, flight, q0, qd0, units, st)
  end subroutine build

  subroutine dropped_ball()
    type(flight_ode_t), target :: flight
    real(wp), allocatable :: q0(:), qd0(:), e(:)
    type(status_t) :: st
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    real(wp) :: t_land, worst_gap, worst_spin, t
    integer :: n, i
    call build(ball_input(h, ''), 'dropped ball', flight, q0, qd0, st)
    call check(st%ok(), 'dropped ball: built from the input: '//st%text())
    if (.not. st%ok()) return
    call check_close(flight%gap%gap, h, 0.0_wp, 1e-12_wp, 'dropped ball: the gap at the start (m)')
    options%ode%rtol = 1e-12_wp
    options%ode%atol = 1e-12_wp
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = 2
    options%output_step = 0.01_wp
    options%progress_seconds = 0
    call flight%start_series(300)
    call drive(flight, flight%initial_state(q0, qd0), options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_EVENT_STOP, 'dropped ball: ran to an event: '//st%text())
    call check(index(flight%outcome, 'landing: the gap of contact ''on_floor'' fell to zero') == 1, &
               'dropped ball: the outcome says landing: '//flight%outcome)
    t_land = sqrt(2*h/g)
    associate (s => flight%series)
      n = s%n
      call check(n >= 40, 'dropped ball: records up to the landing')
      if (n < 40) return
      call check_close(s%time(n), t_land, 0.0_wp, 1e-10_wp, 'dropped ball: lands at t = sqrt(2 h/g) (s)')
      call check_close(s%body_r(1, 1, n), u*t_land, 0.0_wp, 1e-10_wp, 'dropped ball: lands at x = u t (m)')
      call check_close(s%body_v(3, 1, n), -g*t_land, 0.0_wp, 1e-9_wp, 'dropped ball: approach speed g t (m/s)')
      call check(index(flight%outcome, 'approaching at 4.4') > 0, &
                 'dropped ball: the outcome gives the approach speed sqrt(2 g h) = 4.43 m/s: '//flight%outcome)
      worst_gap = 0
      worst_spin = 0
      do i = 1, n
        t = s%time(i)
        worst_gap = max(worst_gap, abs(s%monitor(1, i) - (h - g*t**2/2)))
        worst_spin = max(worst_spin, norm2(s%body_omega(:, 1, i) - spin))
      end do
      call check(s%monitor_names(1) == 'on_floor.gap', 'dropped ball: the gap is recorded as on_floor.gap')
      call check_close(worst_gap, 0.0_wp, 0.0_wp, 1e-10_wp, 'dropped ball: gap = h - g t^2/2 at every record (m)')
      call check_close(worst_spin, 0.0_wp, 0.0_wp, 1e-9_wp, 'dropped ball: the angular velocity stays (rad/s)')
      call check(flight%chart_changes > 0, 'dropped ball: the free rotation changed chart on the way')
      e = s%kinetic(:n) + s%potential(:n)
      call check_close(maxval(abs(e - e(1))), 0.0_wp, 0.0_wp, 1e-9_wp*maxval(s%kinetic(:n)), &
                       'dropped ball: energy conserved in flight (J, 1e-9 of the kinetic energy)')
    end associate
  end subroutine dropped_ball

  subroutine refusals()
    type(flight_ode_t) :: flight
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    call build(ball_input(-0.01_wp, ''), 'overlap', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'touches or overlaps') > 0, &
               'an open start in the floor is refused: '//st%text())
    call build(ball_input(h, '&shape name = ''ball2'', kind = ''sphere'', radius = 0.1 /'//nl// &
                          '&body name = ''ball2'', mass = 0.2, solid_of = ''ball2'', position = 1, 0, 0.1 /'//nl// &
                          '&contact name = ''second'', shape_1 = ''floor'', body_2 = ''ball2'', '// &
                          'shape_2 = ''ball2'' /'//nl), 'two contacts', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'single contact') > 0, &
               'an open start among two contacts is refused: '//st%text())
    call build(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', friction = ''coulomb'', mu = 0.5'), &
               'friction', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'takes no friction') > 0, &
               'friction with an open start is refused (unused: the run ends at the landing): '//st%text())
  end subroutine refusals
end program test_flight
