!> The air's drag on a body (kinetostatics_force_laws air_drag_t; &body
!> drag_area, &contact_model air_density and wind), against closed forms,
!> from namelist text through the contact scenario's reader:
!>   - the law alone: F = -1/2 rho C_d A |w| w at the centre of mass S, w =
!>     v_S - wind, its moment arm x F about the frame's origin; a negative
!>     C_d A refused;
!>   - a ball dropped from rest (drop): with k = rho C_d A/(2 m) and the
!>     terminal speed v_t = sqrt(g/k) = sqrt(2 m g/(rho C_d A)), its centre
!>     falls at v(t) = v_t tanh(g t/v_t), by d(t) = v_t^2/g ln cosh(g t/v_t),
!>     and lands at t_L = v_t/g acosh(exp(g h/v_t^2)); the drag's work
!>     (the law's integrated power) equals the energy change at every record;
!>   - a body whose centre is off its origin, spinning about the vertical,
!>     dropped moving with a horizontal wind (wind): its centre drifts with
!>     the wind and falls as above relative to it, its spin stays (the drag
!>     acts at the centre: no moment about it);
!>   - a ball bouncing (restitution) with drag, closing and sliding on the
!>     frictionless floor (bouncing): E(t) - E(0) - W_drag + impacts' losses
!>     = 0 at every record, the drag's work going on across the switch; after
!>     the closing the horizontal speed decays as v_s/(1 + k v_s s);
!>   - a ball sliding off a dome with viscous friction and drag, lifting off
!>     and flying (dome): the balance holds after the lift-off too, where the
!>     friction law is gone (its work so far kept) and the drag goes on;
!>   - refusals of the input: a negative drag_area or air_density, the air
!>     given with no body that has a drag_area.
!> Tolerances: rtol = atol = 1e-12 over a few hundred steps of a smooth
!> (not polynomial) motion: the global error is at most about the steps
!> times the local tolerance, 1e-10 of the metres and m/s here; checked to
!> 1e-9 m, m/s (the runs show 1e-11 .. 1e-10). The landing time: a root
!> located to ~1e-14 s of a trajectory right to 1e-10 m, falling at ~v_t:
!> 1e-9 s. The energy balance: the work's quadrature state is integrated
!> with the same tolerance, 1e-9 of the largest energy change.
program test_air_drag
  use base_kinds, only: wp
  use base_constants, only: standard_gravity, dry_air_density
  use base_status, only: status_t
  use base_vector, only: cross
  use numerics_event_driver, only: driver_result_t, DRIVE_EVENT_STOP, DRIVE_END_TIME
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_contact, only: contact_state_t
  use kinetostatics_force_laws, only: air_drag_t, new_air_drag
  use kinetostatics_recorder, only: mechanism_series_t
  use contact_model, only: contact_system_t
  use contact_flight, only: flight_ode_t
  use io_input, only: input_text_t, input_from_text
  use io_contact_config, only: read_contact_config
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, ball_over_floor, read_flight, read_closed_flight, fly
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity, mass = 0.2_wp, radius = 0.1_wp

  call law_alone()
  call drop()
  call wind()
  call bouncing()
  call dome()
  call refusals()
  call finish_tests('test_air_drag')

contains

  !> C_d A (m^2) of a body of `mass` whose terminal speed in air of `density` is v_t.
  pure real(wp) function drag_area_for(v_t, density) result(area)
    real(wp), intent(in) :: v_t, density
    area = 2*mass*g/(density*v_t**2)
  end function drag_area_for

  !> Reads `text` and runs its open start (drive_flight) to `duration`.
  subroutine run(text, label, flight, duration, outcome, in_flight, system)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out), target :: flight
    real(wp), intent(in) :: duration
    integer, intent(out) :: outcome
    integer, allocatable, intent(out) :: in_flight(:)
    type(contact_system_t), intent(out) :: system
    integer, allocatable :: open(:, :)
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    type(driver_result_t) :: result
    outcome = 0
    call read_flight(text, label, flight, q0, qd0, st, system)
    call check(st%ok(), label//': built from the input: '//st%text())
    if (.not. st%ok()) return
    call fly(flight, q0, qd0, 1e-12_wp, duration, 400, result, st, open)
    in_flight = open(1, :)   ! the one contact
    call check(st%ok(), label//': ran: '//st%text())
    outcome = result%outcome
  end subroutine run

  !> The largest |E(t) - E(0) - (work of the laws) + (impacts' losses)| over the records (J).
  function balance_error(s, flight) result(worst)
    type(mechanism_series_t), intent(in) :: s
    type(flight_ode_t), intent(in) :: flight
    real(wp) :: worst, lost
    integer :: i
    worst = 0
    do i = 1, s%n
      lost = 0
      if (size(flight%impacts) > 0) lost = sum(flight%impacts%energy_lost, mask=flight%impacts%time <= s%time(i))
      worst = max(worst, abs(s%kinetic(i) + s%potential(i) - s%kinetic(1) - s%potential(1) - &
                             sum(s%law_work(:, i)) + lost))
    end do
  end function balance_error

  !> The law at one frame, rotated, moving and spinning: the force from the
  !> centre's velocity relative to the wind, its moment about the origin.
  subroutine law_alone()
    type(air_drag_t) :: law
    type(frame_state_t) :: frames(1)
    type(scalar_state_t) :: scalars(0)
    type(contact_state_t) :: contacts(0)
    type(status_t) :: st, refused
    real(wp), parameter :: centre(3) = [0.1_wp, -0.2_wp, 0.3_wp], wind_speed(3) = [1.0_wp, 2.0_wp, -0.5_wp]
    real(wp) :: c, s, arm(3), w(3), f(3)
    c = cos(0.7_wp)
    s = sin(0.7_wp)
    frames(1)%rot = reshape([c, s, 0.0_wp, -s, c, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], [3, 3])
    frames(1)%r = [1.0_wp, 2.0_wp, 3.0_wp]
    frames(1)%v = [3.0_wp, -4.0_wp, 5.0_wp]
    frames(1)%omega = [0.5_wp, -1.5_wp, 2.5_wp]
    law = new_air_drag('ball.air_drag', 1, centre, 0.3_wp, 1.1_wp, wind_speed, st)
    call check(st%ok(), 'law: built: '//st%text())
    call law%evaluate(0.0_wp, frames, scalars, contacts, st)
    call check(st%ok(), 'law: evaluated: '//st%text())
    ! the centre's arm in world axes, by the rotation about z written out
    arm = [c*centre(1) - s*centre(2), s*centre(1) + c*centre(2), centre(3)]
    w = frames(1)%v + [frames(1)%omega(2)*arm(3) - frames(1)%omega(3)*arm(2), &
                       frames(1)%omega(3)*arm(1) - frames(1)%omega(1)*arm(3), &
                       frames(1)%omega(1)*arm(2) - frames(1)%omega(2)*arm(1)] - wind_speed
    f = -0.5_wp*1.1_wp*0.3_wp*norm2(w)*w
    call check(size(law%loads) == 1 .and. law%loads(1)%frame == 1, 'law: one load, at its frame')
    call check_close(maxval(abs(law%loads(1)%force - f)), 0.0_wp, 0.0_wp, 1e-14_wp*norm2(f), &
                     'law: F = -1/2 rho C_d A |w| w, w the centre''s velocity relative to the wind (N)')
    call check_close(maxval(abs(law%loads(1)%torque - cross(arm, f))), 0.0_wp, 0.0_wp, 1e-14_wp*norm2(f), &
                     'law: its moment about the origin arm x F (N m)')
    ! its power F.v + tau.omega is F.v_S: the work the air does on the body
    call check_close(dot_product(law%loads(1)%force, frames(1)%v) + dot_product(law%loads(1)%torque, &
                     frames(1)%omega), dot_product(f, w + wind_speed), 1e-13_wp, 0.0_wp, 'law: its power F.v_S (W)')
    law = new_air_drag('ball.air_drag', 1, centre, -0.3_wp, 1.1_wp, wind_speed, refused)
    call check(.not. refused%ok() .and. index(refused%text(), 'drag area C_d A = -0.3') > 0, &
               'law: a negative C_d A refused: '//refused%text())
  end subroutine law_alone

  !> A ball dropped from rest, its lowest point h = 3 m above the floor, v_t
  !> = 3 m/s (still air of the default density): the closed form at every
  !> record to the landing, which ends the run (no restitution).
  subroutine drop()
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    integer :: outcome, n, i
    integer, allocatable :: in_flight(:)
    real(wp), parameter :: h = 3, v_t = 3
    real(wp) :: t, worst_z, worst_v, worst_side, scale
    call run(ball_over_floor('3', 'solid_of = ''ball'', position = 0, 0, '//number(radius + h)//', drag_area = '// &
                         number(drag_area_for(v_t, dry_air_density)), '', ''), 'drop', flight, 3.0_wp, &
             outcome, in_flight, system)
    call check(outcome == DRIVE_EVENT_STOP, 'drop: ends at the landing')
    call check(system%air_density == dry_air_density, 'drop: the default air density, dry air at 20 C')
    associate (s => flight%series)
      n = s%n
      call check(n > 100 .and. s%nl == 1, 'drop: records to the landing, one force law')
      if (n <= 100 .or. s%nl /= 1) return
      call check(s%law_names(1) == 'ball.air_drag', 'drop: the law is ball.air_drag: '//s%law_names(1))
      call check_close(s%time(n), v_t/g*acosh(exp(g*h/v_t**2)), 0.0_wp, 1e-9_wp, &
                       'drop: lands at t = v_t/g acosh(exp(g h/v_t^2)) (s)')
      worst_z = 0
      worst_v = 0
      worst_side = 0
      do i = 1, n
        t = s%time(i)
        worst_z = max(worst_z, abs(s%body_r(3, 1, i) - (radius + h - v_t**2/g*log(cosh(g*t/v_t)))))
        worst_v = max(worst_v, abs(s%body_v(3, 1, i) + v_t*tanh(g*t/v_t)))
        worst_side = max(worst_side, norm2(s%body_r(1:2, 1, i)), norm2(s%body_v(1:2, 1, i)))
      end do
      call check_close(worst_z, 0.0_wp, 0.0_wp, 1e-9_wp, 'drop: fallen by v_t^2/g ln cosh(g t/v_t) (m)')
      call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-9_wp, 'drop: falling at v_t tanh(g t/v_t) (m/s)')
      call check_close(worst_side, 0.0_wp, 0.0_wp, 1e-12_wp, 'drop: straight down (m, m/s)')
      call check(s%body_v(3, 1, n) < -0.99_wp*v_t, 'drop: near the terminal speed at the landing')
      scale = maxval(abs(s%potential(:n) - s%potential(1)))
      call check_close(balance_error(s, flight), 0.0_wp, 0.0_wp, 1e-9_wp*scale, &
                       'drop: E(t) - E(0) = the drag''s work at every record (J)')
      ! most of the potential energy went into the air: m g h - m v^2/2
      call check_close(-s%law_work(1, n), mass*g*h - mass/2*v_t**2*tanh(g*s%time(n)/v_t)**2, 0.0_wp, 1e-8_wp, &
                       'drop: dissipated m g h - m v(t_L)^2/2 (J)')
    end associate
  end subroutine drop

  !> A body of a ball's shape whose centre is 5 cm off its origin along its x
  !> axis (given centre and an isotropic inertia), spinning at 10 rad/s about
  !> the vertical, dropped in a wind of 2 m/s along x with its centre moving
  !> with the wind (the origin's velocity (2, -0.5, 0): omega x arm = (0, 0.5,
  !> 0)), in air of density 1: the centre drifts at 2 m/s and falls as the
  !> drop's closed form; the spin stays; the arm turns in the horizontal plane
  !> (the origin's height is the centre's).
  subroutine wind()
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    integer :: outcome, n, i
    integer, allocatable :: in_flight(:)
    real(wp), parameter :: h = 2, v_t = 4, arm0(3) = [0.05_wp, 0.0_wp, 0.0_wp], spin(3) = [0.0_wp, 0.0_wp, 10.0_wp]
    real(wp) :: t, centre(3), worst_centre, worst_spin, worst_v
    call run(ball_over_floor('3', 'centre = 0.05, 0, 0, inertia = 1e-3, 1e-3, 1e-3, position = 0, 0, '// &
                         number(radius + h)//', velocity = 2, -0.5, 0, angular_velocity = 0, 0, 10, drag_area = '// &
                         number(drag_area_for(v_t, 1.0_wp)), '', '&contact_model air_density = 1, wind = 2, 0, 0 /'), &
             'wind', flight, 3.0_wp, outcome, in_flight, system)
    call check(outcome == DRIVE_EVENT_STOP, 'wind: ends at the landing')
    associate (s => flight%series)
      n = s%n
      call check(n > 50, 'wind: records to the landing')
      if (n <= 50) return
      worst_centre = 0
      worst_spin = 0
      worst_v = 0
      do i = 1, n
        t = s%time(i)
        centre = s%body_r(:, 1, i) + matmul(s%body_rot(:, :, 1, i), arm0)
        worst_centre = max(worst_centre, norm2(centre - [0.05_wp + 2*t, 0.0_wp, radius + h - &
                                                         v_t**2/g*log(cosh(g*t/v_t))]))
        worst_v = max(worst_v, norm2(s%body_v(:, 1, i) + cross(s%body_omega(:, 1, i), centre - s%body_r(:, 1, i)) - &
                                     [2.0_wp, 0.0_wp, -v_t*tanh(g*t/v_t)]))
        worst_spin = max(worst_spin, norm2(s%body_omega(:, 1, i) - spin))
      end do
      call check_close(worst_centre, 0.0_wp, 0.0_wp, 1e-9_wp, &
                       'wind: the centre drifts with the wind and falls by v_t^2/g ln cosh(g t/v_t) (m)')
      call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-9_wp, 'wind: the centre''s velocity (2, 0, -v_t tanh) (m/s)')
      call check_close(worst_spin, 0.0_wp, 0.0_wp, 1e-9_wp, 'wind: the spin stays (no moment about the centre) (rad/s)')
      call check_close(s%time(n), v_t/g*acosh(exp(g*h/v_t**2)), 0.0_wp, 1e-9_wp, 'wind: lands at t_L (s)')
      call check_close(balance_error(s, flight), 0.0_wp, 0.0_wp, 1e-9_wp*maxval(s%kinetic(:n)), &
                       'wind: E(t) - E(0) = the air''s work (J)')
    end associate
  end subroutine wind

  !> The bouncing ball of test_flight (h = 1 m, sideways at 0.3 m/s,
  !> restitution 0.5, close_speed 0.1 m/s) with v_t = 6 m/s: it bounces,
  !> closes and slides on the frictionless floor, slowed by the air alone:
  !> dv/ds = -k v^2, v = v_s/(1 + k v_s s) from the closing (the spin stays
  !> and does not couple: the drag has no moment about the centre).
  subroutine bouncing()
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    integer :: outcome, n, i, switch
    integer, allocatable :: in_flight(:)
    real(wp), parameter :: h = 1, v_t = 6
    real(wp) :: k, v_s, worst_slide, scale
    call run(ball_over_floor('3', 'solid_of = ''ball'', position = 0, 0, '//number(radius + h)//', velocity = 0.3, 0, 0, '// &
                         'angular_velocity = 1, -2, 3, drag_area = '//number(drag_area_for(v_t, dry_air_density)), &
                         ', restitution = 0.5, close_speed = 0.1', ''), 'bouncing', flight, 3.0_wp, outcome, &
             in_flight, system)
    call check(outcome == DRIVE_END_TIME, 'bouncing: runs to the end')
    call check(index(flight%outcome, 'contact ''on_floor'' closed at the impact') == 1, &
               'bouncing: the contact closed: '//flight%outcome)
    call check(size(flight%impacts) >= 3, 'bouncing: bounces before it closes')
    associate (s => flight%series)
      n = s%n
      call check(size(in_flight) == n .and. any(in_flight == 0) .and. in_flight(1) == 1, 'bouncing: flight, closed')
      if (size(in_flight) /= n .or. all(in_flight == 1) .or. s%nl /= 1) return
      switch = count(in_flight == 1)
      call check(s%law_work(1, switch + 1) == s%law_work(1, switch) .and. s%law_work(1, switch) < 0, &
                 'bouncing: the drag''s work goes on across the closing')
      scale = maxval(abs(s%potential(:n) - s%potential(1)))
      call check_close(balance_error(s, flight), 0.0_wp, 0.0_wp, 1e-9_wp*scale, &
                       'bouncing: E(t) - E(0) - drag''s work + impacts'' losses = 0 at every record (J)')
      k = dry_air_density*drag_area_for(v_t, dry_air_density)/(2*mass)
      v_s = s%body_v(1, 1, switch + 1)
      worst_slide = 0
      do i = switch + 1, n
        worst_slide = max(worst_slide, abs(s%body_v(1, 1, i) - v_s/(1 + k*v_s*(s%time(i) - s%time(switch + 1)))), &
                          abs(s%body_v(2, 1, i)), abs(s%body_v(3, 1, i)))
      end do
      call check_close(worst_slide, 0.0_wp, 0.0_wp, 1e-9_wp, &
                       'bouncing: sliding at v_s/(1 + k v_s s) once closed (m/s)')
      call check(s%body_v(1, 1, n) < 0.99_wp*v_s, 'bouncing: the air slowed the slide')
    end associate
  end subroutine bouncing

  !> A ball sliding (viscous friction) from near the top of a dome, with
  !> drag, its contact may open: it lifts off and flies. The balance at every
  !> record, before and after the lift-off: the friction's work stays in it
  !> once the friction is gone, the drag's goes on.
  subroutine dome()
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:)
    integer, allocatable :: in_flight(:), open(:, :)
    integer :: n, lift, friction, drag
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-11, atol = 1e-11, duration = 1.5, output_step = 0.01 /'//nl// &
           '&shape name = ''dome'', kind = ''sphere'', radius = 1 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''ball'', mass = 0.2, solid_of = ''ball'', position = 0.1, 0, 1.1, '// &
           'angles_deg = 90, 0, 0, drag_area = 0.02 /'//nl// &
           '&contact name = ''ball_on_dome'', shape_1 = ''dome'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'friction = ''viscous'', viscous_coefficient = 0.1, may_open = .true. /'//nl
    call read_closed_flight(text, 'dome', flight, q0, qd0, st)
    call check(st%ok(), 'dome: built from the input: '//st%text())
    if (.not. st%ok()) return
    call fly(flight, q0, qd0, 1e-11_wp, 1.5_wp, 400, result, st, open)
    in_flight = open(1, :)   ! the one contact
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'dome: runs to the end: '//st%text())
    associate (s => flight%series)
      n = s%n
      call check(size(in_flight) == n .and. in_flight(1) == 0 .and. in_flight(n) == 1 .and. s%nl == 2, &
                 'dome: closed, then in flight; two laws')
      if (size(in_flight) /= n .or. in_flight(n) /= 1 .or. s%nl /= 2) return
      lift = count(in_flight == 0)
      friction = findloc(s%law_names == 'ball_on_dome.friction', .true., dim=1)
      drag = findloc(s%law_names == 'ball.air_drag', .true., dim=1)
      call check(friction > 0 .and. drag > 0, 'dome: the laws ball_on_dome.friction and ball.air_drag')
      if (friction == 0 .or. drag == 0) return
      call check(s%law_work(friction, lift) < 0 .and. all(s%law_work(friction, lift + 1:n) == &
                                                          s%law_work(friction, lift)), &
                 'dome: the friction''s work held once the contact opened')
      call check(s%law_work(drag, lift + 1) == s%law_work(drag, lift) .and. s%law_work(drag, n) < s%law_work(drag, lift), &
                 'dome: the drag''s work goes on across the lift-off and in flight')
      call check_close(balance_error(s, flight), 0.0_wp, 0.0_wp, 1e-8_wp*maxval(s%kinetic(:n)), &
                       'dome: E(t) - E(0) = the laws'' work at every record, closed and in flight (J)')
    end associate
  end subroutine dome

  !> The reader's refusals, each naming the group, the variable and the value.
  subroutine refusals()
    call refused(ball_over_floor('3', 'solid_of = ''ball'', position = 0, 0, 1, drag_area = -0.01', '', ''), &
                 '&body: drag_area = -0.01', 'a negative drag_area')
    call refused(ball_over_floor('3', 'solid_of = ''ball'', position = 0, 0, 1, drag_area = 0.01', '', &
                             '&contact_model air_density = -1 /'), '&contact_model: air_density = -1', &
                 'a negative air_density')
    call refused(ball_over_floor('3', 'solid_of = ''ball'', position = 0, 0, 1', '', '&contact_model air_density = 1.1 /'), &
                 'no &body has one', 'the air with no drag_area')
    call refused(ball_over_floor('3', 'solid_of = ''ball'', position = 0, 0, 1', '', '&contact_model wind = 1, 0, 0 /'), &
                 '&contact_model: wind', 'a wind with no drag_area')
  end subroutine refusals

  subroutine refused(text, expected, what)
    character(len=*), intent(in) :: text, expected, what
    type(input_text_t) :: input
    type(contact_system_t) :: system
    type(status_t) :: st
    call input_from_text('refused.nml', text, input, st)
    call read_contact_config(input, system, st)
    call check(.not. st%ok() .and. index(st%text(), expected) > 0, 'refused: '//what//': '//st%text())
  end subroutine refused
end program test_air_drag
