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
  use base_vector, only: cross
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_EVENT_STOP, RECORD_EVENT
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
  call bouncing_ball()
  call rolling_after_impact()
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

  !> Runs an open-start input to its end; the driver's outcome.
  subroutine run(text, label, flight, duration, outcome)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out), target :: flight
    real(wp), intent(in) :: duration
    integer, intent(out) :: outcome
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    outcome = 0
    call build(text, label, flight, q0, qd0, st)
    call check(st%ok(), label//': built from the input: '//st%text())
    if (.not. st%ok()) return
    options%ode%rtol = 1e-12_wp
    options%ode%atol = 1e-12_wp
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = duration
    options%output_step = 0.01_wp
    options%progress_seconds = 0
    call flight%start_series(300)
    call drive(flight, flight%initial_state(q0, qd0), options, result, st)
    call check(st%ok(), label//': ran: '//st%text())
    outcome = result%outcome
  end subroutine run

  !> e = 0.5 (energetic; frictionless and spinless it is Newton's too): the
  !> k-th impact meets the ball at v_(k-1) = e^(k-1) v_0 (v_0 = sqrt(2 g h))
  !> and sends it up at v_k = e v_(k-1); between impacts the gap is
  !> v_k s - g s^2/2 (s since the impact): apex e^(2k) h after a flight of
  !> 2 v_k/g. The sixth rebound, e^6 v_0 = 0.069 m/s, is below
  !> close_speed = 0.1 m/s: the contact would close there and the run ends.
  !> Each impact time is a root located to ~1e-14 s after flights integrated
  !> at rtol 1e-12: 1e-9 s over six; speeds and gaps to 1e-9.
  subroutine bouncing_ball()
    type(flight_ode_t), target :: flight
    integer :: outcome, k, i, n, j
    real(wp) :: v0, t_k(6), v_k(0:6), worst_gap, worst_energy, e_lost, since, expected
    real(wp), allocatable :: e(:)
    real(wp), parameter :: restitution = 0.5_wp
    call run(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', restitution = 0.5, '// &
                     'close_speed = 0.1'), 'bouncing ball', flight, 5.0_wp, outcome)
    call check(outcome == DRIVE_EVENT_STOP, 'bouncing ball: ends at an event')
    call check(index(flight%outcome, 'would close at the impact') > 0, &
               'bouncing ball: ends where the rebound is below close_speed: '//flight%outcome)
    call check(size(flight%impacts) == 6, 'bouncing ball: six impacts (e^6 v0 < close_speed < e^5 v0)')
    if (size(flight%impacts) /= 6) return
    v0 = sqrt(2*g*h)
    v_k = [(restitution**k*v0, k = 0, 6)]
    t_k(1) = v0/g
    do k = 2, 6
      t_k(k) = t_k(k - 1) + 2*v_k(k - 1)/g
    end do
    do k = 1, 6
      associate (impact => flight%impacts(k))
        call check_close(impact%time, t_k(k), 0.0_wp, 1e-9_wp, 'bouncing ball: impact time after flights 2 v_k/g (s)')
        call check_close(impact%normal_speed_before, -v_k(k - 1), 0.0_wp, 1e-9_wp, &
                         'bouncing ball: approach speed e^(k-1) v0 (m/s)')
        call check_close(impact%normal_speed_after, v_k(k), 0.0_wp, 1e-9_wp, 'bouncing ball: rebound e^k v0 (m/s)')
        call check_close(impact%normal_impulse, 0.2_wp*(v_k(k - 1) + v_k(k)), 0.0_wp, 1e-9_wp, &
                         'bouncing ball: normal impulse m (v_(k-1) + v_k) (N s)')
        call check_close(impact%energy_lost, 0.1_wp*(v_k(k - 1)**2 - v_k(k)**2), 0.0_wp, 1e-9_wp, &
                         'bouncing ball: energy lost m/2 (v_(k-1)^2 - v_k^2) (J)')
      end associate
    end do
    associate (s => flight%series)
      n = s%n
      worst_gap = 0
      worst_energy = 0
      e = s%kinetic(:n) + s%potential(:n)
      do i = 1, n
        ! the closed form: falling from h before the first impact, then rising from impact j at v_j
        j = count(t_k <= s%time(i))
        if (j == 0) then
          expected = h - g*s%time(i)**2/2
        else
          since = s%time(i) - t_k(j)
          expected = v_k(j)*since - g*since**2/2
        end if
        worst_gap = max(worst_gap, abs(s%monitor(1, i) - expected))
        ! the record at an impact holds the state after it (its time is the table's)
        e_lost = sum(flight%impacts%energy_lost, mask=flight%impacts%time <= s%time(i))
        worst_energy = max(worst_energy, abs(e(i) + e_lost - e(1)))
      end do
      call check_close(worst_gap, 0.0_wp, 0.0_wp, 1e-9_wp, &
                       'bouncing ball: gap at every record on the closed-form bounces, apexes e^(2k) h (m)')
      call check_close(worst_energy, 0.0_wp, 0.0_wp, 1e-9_wp*e(1), &
                       'bouncing ball: energy kept in flight, lost only at the impacts (the table''s sum) (J)')
      call check(count(s%kind(:n) == RECORD_EVENT) >= 6, 'bouncing ball: a record at every impact')
    end associate
  end subroutine bouncing_ball

  !> A ball landing with sideways speed u and spin Omega about y, the impact's
  !> mu large (10, so it sticks): the impulse about the contact point leaves
  !> the angular momentum about it, so the ball leaves rolling, v_t = 0 at the
  !> contact: v_x = (5 u + 2 R Omega)/7 (solid sphere, I = 2/5 m R^2),
  !> omega_y = v_x/R; the normal speed e v_n (no coupling in a sphere's K).
  subroutine rolling_after_impact()
    type(flight_ode_t), target :: flight
    integer :: outcome, i, n
    real(wp), parameter :: omega_y = -5.0_wp, v_x = (5*u + 2*radius*omega_y)/7
    real(wp) :: contact_velocity(3)
    call run(replace(replace(ball_input(0.2_wp, ''), 'start = ''open''', 'start = ''open'', restitution = 0.5, '// &
                     'impact_mu = 10'), 'angular_velocity = '//number(spin(1))//', '//number(spin(2))//', '// &
                     number(spin(3)), 'angular_velocity = 0, '//number(omega_y)//', 0'), 'rolling after impact', &
             flight, 0.5_wp, outcome)
    call check(size(flight%impacts) >= 1, 'rolling after impact: it landed')
    if (size(flight%impacts) < 1) return
    associate (s => flight%series)
      n = s%n
      i = findloc(s%time(:n), flight%impacts(1)%time, dim=1)
      call check(i > 0, 'rolling after impact: a record at the impact')
      if (i == 0) return
      call check_close(s%body_v(1, 1, i), v_x, 0.0_wp, 1e-9_wp, 'rolling after impact: v_x = (5 u + 2 R Omega)/7 (m/s)')
      call check_close(s%body_omega(2, 1, i), v_x/radius, 0.0_wp, 1e-8_wp, &
                       'rolling after impact: omega_y = v_x/R (rad/s)')
      contact_velocity = s%body_v(:, 1, i) + cross(s%body_omega(:, 1, i), [0.0_wp, 0.0_wp, -radius])
      call check_close(norm2(contact_velocity(1:2)), 0.0_wp, 0.0_wp, 1e-9_wp, &
                       'rolling after impact: no slip at the contact after the impact (m/s)')
      call check_close(s%body_v(3, 1, i), 0.5_wp*sqrt(2*g*0.2_wp), 0.0_wp, 1e-9_wp, &
                       'rolling after impact: rebound e v_n (m/s)')
      call check(flight%impacts(1)%tangential_impulse > 0, 'rolling after impact: a friction impulse')
    end associate
  end subroutine rolling_after_impact

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
    call build(replace(ball_input(h, ''), 'start = ''open''', 'restitution = 0.5'), 'closed with restitution', &
               flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'restitution') > 0 .and. index(st%text(), 'never lands') > 0, &
               'restitution on a closed start is refused (unused): '//st%text())
    call build(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', close_speed = 0.1'), &
               'close_speed alone', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'close_speed') > 0, &
               'close_speed without restitution is refused (unused): '//st%text())
  end subroutine refusals
end program test_flight
