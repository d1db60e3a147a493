!> The stops of the water run that end it early, on frictionless straight tubes
!> (f1 = f2 = f3 = 0, correction off) where the motion has closed forms:
!> - lift-off: in a horizontal tube the along speed a stays constant and the
!>   across motion is a point on a circle of radius r under gravity: with the
!>   across speed c0 at the bottom, c^2 = c0^2 - 2 g r (1 - cos phi) at the angle
!>   phi from the bottom, and N/m = c^2/r + g cos phi (into the tube). N = 0 at
!>       cos phi* = (2 g r - c0^2)/(3 g r),
!>   so the run must stop (root on N) at v = pi/2 + phi*; water that starts
!>   without contact (at the top of the tube, slow) stops at once;
!> - turning back: up an ascending tube (incline -theta) the along speed falls
!>   linearly, a(t) = a0 - g sin(theta) t, whatever the across motion does; the
!>   run must stop where cos(beta) = a/w = 0.01 (root) with a message.
program test_water_stops
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t, STATUS_DOMAIN
  use numerics_ode, only: ode_options_t
  use testing, only: check, check_close, finish_tests
  use geometry_tube, only: new_straight_tube
  use water_channel, only: new_channel
  use water_streamline, only: streamline_t, CORRECTION_OFF
  use water_flow, only: water_start_t, water_series_t, water_initial_state, simulate_water, &
    START_HEIGHT_SPEED, OUTCOME_LIFT, OUTCOME_TURN, OUTCOME_STALL
  implicit none (type, external)

  real(wp), parameter :: r = 0.5_wp, g = standard_gravity

  call lift_off()
  call lift_off_at_start()
  call stall_at_start()
  call turn_back()
  call finish_tests('test_water_stops')

contains

  subroutine make(model, incline)
    type(streamline_t), intent(out) :: model
    real(wp), intent(in) :: incline
    type(status_t) :: st
    allocate (model%channel, source=new_channel(new_straight_tube(r, incline, 100.0_wp, st)))
    model%correction = CORRECTION_OFF
    model%f1 = 0; model%f2 = 0; model%f3 = 0
  end subroutine make

  subroutine lift_off()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7), c0, phi, along_err
    integer :: i

    call make(model, 0.0_wp)
    start%mode = START_HEIGHT_SPEED; start%height = 0.01_wp; start%speed = 5; start%beta = 1.2_wp
    start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'lift-off: start')
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 5.0_wp, 0.01_wp, s, st, edges=.false.)
    call check(s%outcome == OUTCOME_LIFT, 'lift-off: the run stops with outcome "lifted off"')
    call check(st%code == STATUS_DOMAIN, 'lift-off: a domain status (the file is then marked incomplete)')
    call check(index(st%text(), 'lifts off') > 0, 'lift-off: the message says the water lifts off')
    call check(index(s%message, 'lifts off') > 0, 'lift-off: the series keeps the message')
    c0 = 5*sin(1.2_wp)
    phi = acos((2*g*r - c0**2)/(3*g*r))
    ! 1e-7 rad: rtol 1e-12 over ~100 steps and CVODE's root time (~1e-13 s at dv/dt ~ 5 rad/s) keep
    ! the error near 1e-10; a check at output times (every 0.01 s) would be off by up to 0.05 rad
    call check_close(s%v(s%n), pi/2 + phi, 0.0_wp, 1e-7_wp, 'lift-off at cos(phi) = (2 g r - c0^2)/(3 g r)')
    ! 1e-7 N: N moves ~100 N/s there, the root time is exact to ~1e-12 s; N ~ 10 N at the start
    call check_close(s%normal_force(s%n), 0.0_wp, 0.0_wp, 1e-7_wp, 'lift-off: N = 0 at the stop')
    call check(all(s%normal_force(:s%n - 1) > 0), 'lift-off: N > 0 before the stop')
    along_err = 0
    do i = 1, s%n
      along_err = max(along_err, abs(s%speed(i)*cos(s%beta(i)) - 5*cos(1.2_wp)))
    end do
    ! 1e-9 m/s: no along force on a frictionless horizontal cylinder; integration error only
    call check(along_err <= 1e-9_wp, 'lift-off: the along speed stays constant')
    print '(a, f10.6, a, f10.6, a, es9.2)', '  lift-off at v = ', s%v(s%n), ' (closed form ', pi/2 + phi, &
      '), N = ', s%normal_force(s%n)
  end subroutine lift_off

  subroutine lift_off_at_start()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7)

    call make(model, 0.0_wp)
    ! at the top of the tube, 1 m/s along: N/m = -g (nothing holds the water up)
    start%mode = START_HEIGHT_SPEED; start%height = 0.01_wp; start%speed = 1; start%v0 = 3*pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'lift-off at the start: start values')
    call simulate_water(model, y0, opt, 5.0_wp, 0.01_wp, s, st, edges=.false.)
    call check(s%outcome == OUTCOME_LIFT .and. st%code == STATUS_DOMAIN, &
               'water started on the ceiling stops at once as lifted off')
    call check(s%n == 1, 'lift-off at the start: only the start sample')
    ! 1e-12 relative: N = m z.(a_hat - g) with a_hat = 0 on a straight line at v' = 0
    call check_close(s%normal_force(1), -g, 1e-12_wp, 0.0_wp, 'lift-off at the start: N = -m g on the ceiling')
  end subroutine lift_off_at_start

  !> A start slower than min_speed: the stall is a root falling through zero,
  !> which would never fire from below; the run must stop at once instead of
  !> going on outside the model (it went on to the end before).
  subroutine stall_at_start()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7)

    call make(model, 0.2_wp)
    model%min_speed = 3
    start%mode = START_HEIGHT_SPEED; start%height = 0.01_wp; start%speed = 2; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'stall at the start: start values')
    call simulate_water(model, y0, opt, 5.0_wp, 0.01_wp, s, st, edges=.false.)
    call check(s%outcome == OUTCOME_STALL .and. st%code == STATUS_DOMAIN, &
               'water started below min_speed stops at once as stalled: '//st%text())
    call check(s%n == 1, 'stall at the start: only the start sample')
    call check(index(st%text(), 'stalled') > 0 .and. index(s%message, 'stalled') > 0, &
               'stall at the start: the message says so')
  end subroutine stall_at_start

  subroutine turn_back()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7), theta, a0, err
    integer :: i

    theta = 20*pi/180
    call make(model, -theta)   ! ascending
    start%mode = START_HEIGHT_SPEED; start%height = 0.01_wp; start%speed = 4; start%beta = 0.3_wp
    start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'turn back: start')
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 5.0_wp, 0.01_wp, s, st, edges=.false.)
    call check(s%outcome == OUTCOME_TURN, 'turn back: the run stops with outcome "turned back"')
    call check(st%code == STATUS_DOMAIN, 'turn back: a domain status (the file is then marked incomplete)')
    call check(index(st%text(), 'turns across the slide or back') > 0, 'turn back: the message says why')
    ! 1e-9: cos(beta) - 0.01 is the root function; its rate ~3 1/s, root time exact to ~1e-12 s
    call check_close(cos(s%beta(s%n)), 0.01_wp, 0.0_wp, 1e-9_wp, 'turn back: stops at cos(beta) = 0.01')
    a0 = 4*cos(0.3_wp)
    err = 0
    do i = 1, s%n
      err = max(err, abs(s%speed(i)*cos(s%beta(i)) - (a0 - g*sin(theta)*s%time(i))))
    end do
    ! 1e-9 m/s: constant deceleration g sin(theta) along a frictionless cylinder; integration error only
    call check(err <= 1e-9_wp, 'turn back: the along speed falls as a0 - g sin(theta) t')
    call check(s%speed(s%n) > model%min_speed, 'turn back: caught before the water stalls')
    print '(a, f8.4, a, es9.2, a, f7.4, a)', '  turned back at t = ', s%time(s%n), ' s (along-speed error ', err, &
      ', speed ', s%speed(s%n), ' m/s)'
  end subroutine turn_back
end program test_water_stops
