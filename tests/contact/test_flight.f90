!> Flight (issue 25): a contact that starts open leaves its body where &body
!> puts it, flying free under gravity; without restitution the run ends
!> where the gap falls to zero (contact_flight), with it the body bounces
!> until a rebound is below close_speed and the contact closes
!> (contact_closing). From namelist text through the contact scenario's
!> reader:
!>   - a ball (radius r) dropped with its lowest point h above a plane, moving
!>     sideways at u and spinning: it lands at t = sqrt(2 h/g) with the
!>     approach speed g t, at x = u t; the recorded gap is h - g t^2/2 at
!>     every record; the energy stays; a sphere's angular velocity stays
!>     (torque-free, isotropic) through the free rotation's chart changes;
!>   - bounces of e = 0.5 (see bouncing_ball), closing at the partial Zeno
!>     sum, then at rest; a ball landing with spin and sideways speed, rolling
!>     after closing (rolling_on);
!>   - lift-off (may_open): a ball rolling off a dome (dome_lift_off), and
!>     one rolling round the inside of a sphere too slowly for the loop,
!>     lifting off, flying and landing on the sphere again
!>     (loop_lift_off_and_landing);
!>   - refused: an open start that touches or overlaps, a body flying
!>     beside one that starts closed, friction on an open start without restitution
!>     (unused: the run ends at the landing).
!> Tolerances: rtol = atol = 1e-12 over ~100 steps of a polynomial motion
!> (the parabola is a degree-2 polynomial: Adams reproduces it nearly
!> exactly), so positions to 1e-10 m; the landing root is located to
!> CVODE's 1e-14 s-ish, its time checked to 1e-10 s.
program test_flight
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use base_vector, only: cross
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_EVENT_STOP, DRIVE_END_TIME, &
    RECORD_EVENT, RECORD_OUTPUT
  use contact_model, only: contact_system_t, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, ball_over_floor, read_flight, read_closed_flight, fly, run_flight
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity, radius = 0.1_wp, h = 1.0_wp, u = 0.3_wp
  real(wp), parameter :: spin(3) = [10.0_wp, -20.0_wp, 30.0_wp]   ! rad/s: several chart changes of the free rotation

  call dropped_ball()
  call bouncing_ball()
  call rolling_after_impact()
  call rolling_on()
  call dome_lift_off()
  call loop_lift_off_and_landing()
  call refusals()
  call finish_tests('test_flight')

contains

  function ball_input(height, extra) result(text)
    real(wp), intent(in) :: height   ! of the ball's lowest point above the plane (m)
    character(len=*), intent(in) :: extra   ! appended to the text
    character(len=:), allocatable :: text
    text = ball_over_floor('2', 'solid_of = ''ball'', position = 0, 0, '//number(radius + height)// &
                           ', velocity = '//number(u)//', 0, 0, angular_velocity = '//number(spin(1))//', '// &
                           number(spin(2))//', '//number(spin(3)), '', extra)
  end function ball_input

  !> text with its first `old` replaced by `new`.
  function replace(text, old, new) result(changed)
    character(len=*), intent(in) :: text, old, new
    character(len=:), allocatable :: changed
    integer :: at
    at = index(text, old)
    changed = text(:at - 1)//new//text(at + len(old):)
  end function replace

  subroutine dropped_ball()
    type(flight_ode_t), target :: flight
    real(wp), allocatable :: q0(:), qd0(:), e(:)
    type(status_t) :: st
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    real(wp) :: t_land, worst_gap, worst_spin, t
    integer :: n, i
    call read_flight(ball_input(h, ''), 'dropped ball', flight, q0, qd0, st)
    call check(st%ok(), 'dropped ball: built from the input: '//st%text())
    if (.not. st%ok()) return
    call check_close(flight%gaps%gap(1)%gap, h, 0.0_wp, 1e-12_wp, 'dropped ball: the gap at the start (m)')
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

  !> e = 0.5 (energetic; frictionless and spinless it is Newton's too): the
  !> k-th impact meets the ball at v_(k-1) = e^(k-1) v_0 (v_0 = sqrt(2 g h))
  !> and sends it up at v_k = e v_(k-1); between impacts the gap is
  !> v_k s - g s^2/2 (s since the impact): apex e^(2k) h after a flight of
  !> 2 v_k/g. Without closing this never ends (Zeno): the impacts come at
  !> t_0 (1 + 2 sum_(j<k) e^j), t_0 = v_0/g, and pile up at
  !> t_inf = t_0 (1 + 2e/(1 - e)). The sixth rebound, e^6 v_0 = 0.069 m/s, is
  !> below close_speed = 0.1 m/s: the contact closes at the sixth impact, at
  !> t_0 (1 + 2e (1 - e^5)/(1 - e)), 2 t_0 e^6/(1 - e) before t_inf (the
  !> flights it cut off); that impact is plastic (m v_5, all of m v_5^2/2
  !> lost), and the ball stays on the floor to the end (gap 0, N = m g),
  !> sliding on at u with its spin (frictionless: neither ever changes).
  !> Each impact time is a root located to ~1e-14 s after flights integrated
  !> at rtol 1e-12: 1e-9 s over six; speeds and gaps to 1e-9.
  !> At the switch the flight's last record and the closed contact's first
  !> hold the same state: the pose is the one the contact search starts from
  !> (moved by the gap left at the root, v_5 times the root's time error,
  !> ~1e-14 m) and the twist the least-squares fit of the flight's (J^T J
  !> solved by Cholesky: 1e-16 times its condition, ~1e2): 1e-12 m and
  !> 1e-12 of v_0 (m/s, rad/s x R).
  subroutine bouncing_ball()
    type(flight_ode_t), target :: flight
    integer :: outcome, k, i, n, j, switch
    integer, allocatable :: in_flight(:)
    real(wp) :: v0, t0, t_k(6), v_k(0:6), worst_gap, worst_energy, e_lost, since, expected, t_inf, worst_rest, &
                worst_spin
    real(wp), allocatable :: e(:)
    real(wp), parameter :: restitution = 0.5_wp, mass = 0.2_wp
    call run_flight(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', restitution = 0.5, '// &
                     'close_speed = 0.1'), 'bouncing ball', flight, 3.0_wp, outcome, in_flight)
    call check(outcome == DRIVE_END_TIME, 'bouncing ball: runs to the end, closed after the bounces')
    call check(index(flight%outcome, 'contact ''on_floor'' closed at the impact') == 1, &
               'bouncing ball: the outcome says the contact closed: '//flight%outcome)
    call check(size(flight%impacts) == 6, 'bouncing ball: six impacts (e^6 v0 < close_speed < e^5 v0)')
    if (size(flight%impacts) /= 6) return
    v0 = sqrt(2*g*h)
    t0 = v0/g
    v_k = [(restitution**k*v0, k = 0, 6)]
    t_k(1) = t0
    do k = 2, 6
      t_k(k) = t_k(k - 1) + 2*v_k(k - 1)/g
    end do
    do k = 1, 6
      associate (impact => flight%impacts(k))
        call check_close(impact%time, t_k(k), 0.0_wp, 1e-9_wp, 'bouncing ball: impact time after flights 2 v_k/g (s)')
        call check_close(impact%normal_speed_before, -v_k(k - 1), 0.0_wp, 1e-9_wp, &
                         'bouncing ball: approach speed e^(k-1) v0 (m/s)')
        if (k < 6) then
          call check_close(impact%normal_speed_after, v_k(k), 0.0_wp, 1e-9_wp, 'bouncing ball: rebound e^k v0 (m/s)')
          call check_close(impact%normal_impulse, mass*(v_k(k - 1) + v_k(k)), 0.0_wp, 1e-9_wp, &
                           'bouncing ball: normal impulse m (v_(k-1) + v_k) (N s)')
          call check_close(impact%energy_lost, mass/2*(v_k(k - 1)**2 - v_k(k)**2), 0.0_wp, 1e-9_wp, &
                           'bouncing ball: energy lost m/2 (v_(k-1)^2 - v_k^2) (J)')
        else
          call check_close(impact%normal_speed_after, 0.0_wp, 0.0_wp, 1e-12_wp, &
                           'bouncing ball: the closing impact leaves no normal speed (m/s)')
          call check_close(impact%normal_impulse, mass*v_k(5), 0.0_wp, 1e-9_wp, &
                           'bouncing ball: the closing impact is plastic, m v_5 (N s)')
          call check_close(impact%energy_lost, mass/2*v_k(5)**2, 0.0_wp, 1e-9_wp, &
                           'bouncing ball: the closing impact takes all of m v_5^2/2 (J)')
        end if
      end associate
    end do
    t_inf = t0*(1 + 2*restitution/(1 - restitution))
    call check_close(flight%impacts(6)%time, t0*(1 + 2*restitution*(1 - restitution**5)/(1 - restitution)), &
                     0.0_wp, 1e-9_wp, 'bouncing ball: closes at the partial Zeno sum t0 (1 + 2e (1 - e^5)/(1 - e)) (s)')
    call check_close(t_inf - flight%impacts(6)%time, 2*t0*restitution**6/(1 - restitution), 0.0_wp, 1e-9_wp, &
                     'bouncing ball: closes 2 t0 e^6/(1 - e) before the Zeno time t0 (1 + 2e/(1 - e)) (s)')
    associate (s => flight%series)
      n = s%n
      call check(size(in_flight) == n, 'bouncing ball: a phase for every record')
      if (size(in_flight) /= n) return
      call check_close(s%time(n), 3.0_wp, 0.0_wp, 1e-12_wp, 'bouncing ball: runs to the end (s)')
      switch = count(in_flight == 1)
      call check(all(in_flight(:switch) == 1) .and. all(in_flight(switch + 1:) == 0), &
                 'bouncing ball: in flight, then closed')
      call check(s%time(switch) == flight%impacts(6)%time .and. s%time(switch + 1) == flight%impacts(6)%time, &
                 'bouncing ball: the flight''s last record and the closed contact''s first at the closing')
      call check(s%kind(switch + 1) == RECORD_EVENT, 'bouncing ball: the switch is an event record')
      call check_close(maxval(abs(s%body_r(:, 1, switch + 1) - s%body_r(:, 1, switch))), 0.0_wp, 0.0_wp, 1e-12_wp, &
                       'bouncing ball: the position continuous across the switch (m)')
      call check_close(maxval(abs(s%body_rot(:, :, 1, switch + 1) - s%body_rot(:, :, 1, switch))), 0.0_wp, 0.0_wp, &
                       1e-12_wp, 'bouncing ball: the orientation continuous across the switch')
      call check_close(maxval(abs(s%body_v(:, 1, switch + 1) - s%body_v(:, 1, switch))), 0.0_wp, 0.0_wp, &
                       1e-12_wp*v0, 'bouncing ball: the velocity continuous across the switch (m/s)')
      call check_close(radius*maxval(abs(s%body_omega(:, 1, switch + 1) - s%body_omega(:, 1, switch))), 0.0_wp, &
                       0.0_wp, 1e-12_wp*v0, 'bouncing ball: the angular velocity continuous across the switch (R rad/s)')
      worst_gap = 0
      worst_energy = 0
      worst_rest = 0
      worst_spin = 0
      e = s%kinetic(:n) + s%potential(:n)
      do i = 1, n
        ! the closed form: falling from h before the first impact, then rising from impact j at v_j, at rest
        ! (gap 0) once closed
        j = count(t_k <= s%time(i))
        if (j == 0) then
          expected = h - g*s%time(i)**2/2
        else if (j < 6) then
          since = s%time(i) - t_k(j)
          expected = v_k(j)*since - g*since**2/2
        else
          expected = 0
          worst_rest = max(worst_rest, norm2(s%body_v(:, 1, i) - [u, 0.0_wp, 0.0_wp]), abs(s%body_r(3, 1, i) - radius))
          worst_spin = max(worst_spin, norm2(s%body_omega(:, 1, i) - spin))
        end if
        worst_gap = max(worst_gap, abs(s%monitor(1, i) - expected))
        ! the record at an impact holds the state after it (its time is the table's)
        e_lost = sum(flight%impacts%energy_lost, mask=flight%impacts%time <= s%time(i))
        worst_energy = max(worst_energy, abs(e(i) + e_lost - e(1)))
      end do
      call check(s%monitor_names(1) == 'on_floor.gap', 'bouncing ball: the gap is the first measurement')
      call check_close(worst_gap, 0.0_wp, 0.0_wp, 1e-9_wp, &
                       'bouncing ball: gap at every record on the closed-form bounces, apexes e^(2k) h, 0 closed (m)')
      call check_close(worst_energy, 0.0_wp, 0.0_wp, 1e-9_wp*e(1), &
                       'bouncing ball: energy kept in flight and at rest, lost only at the impacts (the table''s sum) (J)')
      call check_close(worst_rest, 0.0_wp, 0.0_wp, 1e-10_wp, &
                       'bouncing ball: on the floor once closed, sliding at u (m/s, m)')
      ! the closed contact integrates the spin through its chain's angles (phi, u2, v2): ten turns in 1.7 s
      ! at rtol 1e-12, ~1e-11 of |Omega| per turn
      call check_close(worst_spin, 0.0_wp, 0.0_wp, 1e-10_wp*norm2(spin), &
                       'bouncing ball: the spin kept once closed (frictionless) (rad/s)')
      call check_close(s%normal(1, n), mass*g, 0.0_wp, 1e-9_wp, 'bouncing ball: carried by the floor, N = m g (N)')
      call check(all(s%normal(1, :switch) == 0), 'bouncing ball: no normal force in flight')
      call check(count(s%kind(:n) == RECORD_EVENT) >= 7, 'bouncing ball: a record at every impact and the switch')
      call check(all(pack(abs(s%time(:n)/0.01_wp - nint(s%time(:n)/0.01_wp)), s%kind(:n) == RECORD_OUTPUT) < 1e-9_wp), &
                 'bouncing ball: the closed contact''s outputs on the run''s grid (multiples of 0.01 s)')
      call check(count(s%kind(:n) == RECORD_OUTPUT) == 300, 'bouncing ball: one output every 0.01 s to 3 s')
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
    call run_flight(replace(replace(ball_input(0.2_wp, ''), 'start = ''open''', 'start = ''open'', restitution = 0.5, '// &
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

  !> The ball of rolling_after_impact (u = 0.3 m/s sideways, spin -5 rad/s
  !> about y, dropped 0.2 m, impact mu 10: it leaves the first impact rolling,
  !> v_x = (5 u + 2 R Omega)/7) with a rolling contact: its later impacts meet
  !> no slip and leave v_x; the eighth rebound, e^8 v0 = 0.0077 m/s, is below
  !> the default close_speed 0.01 m/s and the contact closes; the ball rolls
  !> on at v_x (a sphere rolling on a level plane keeps its speed): x = u t_1
  !> + v_x (t - t_1) at every record after the first impact t_1, omega_y =
  !> v_x/R, N = m g. Tolerances as bouncing_ball's (1e-9).
  subroutine rolling_on()
    type(flight_ode_t), target :: flight
    integer :: outcome, i, n
    integer, allocatable :: in_flight(:)
    real(wp), parameter :: omega_y = -5.0_wp, v_x = (5*u + 2*radius*omega_y)/7, drop = 0.2_wp
    real(wp) :: t_1, worst_x, worst_spin
    call run_flight(replace(replace(ball_input(drop, ''), 'start = ''open''', 'start = ''open'', restitution = 0.5, '// &
                     'impact_mu = 10, rolling = .true.'), 'angular_velocity = '//number(spin(1))//', '// &
                     number(spin(2))//', '//number(spin(3)), 'angular_velocity = 0, '//number(omega_y)//', 0'), &
             'rolling on', flight, 1.0_wp, outcome, in_flight)
    call check(outcome == DRIVE_END_TIME, 'rolling on: runs to the end')
    call check(size(flight%impacts) == 8, 'rolling on: eight impacts (e^8 v0 < close_speed < e^7 v0)')
    call check(flight%landed == 1 .and. allocated(flight%closed), 'rolling on: the contact closed')
    if (size(flight%impacts) < 1 .or. .not. allocated(flight%closed)) return
    t_1 = flight%impacts(1)%time
    call check_close(t_1, sqrt(2*drop/g), 0.0_wp, 1e-10_wp, 'rolling on: the first landing at sqrt(2 h/g) (s)')
    associate (s => flight%series)
      n = s%n
      worst_x = 0
      worst_spin = 0
      do i = 1, n
        if (s%time(i) < t_1) cycle
        worst_x = max(worst_x, abs(s%body_r(1, 1, i) - (u*t_1 + v_x*(s%time(i) - t_1))))
        worst_spin = max(worst_spin, radius*abs(s%body_omega(2, 1, i) - v_x/radius))
      end do
      call check_close(worst_x, 0.0_wp, 0.0_wp, 1e-9_wp, 'rolling on: x = u t_1 + v_x (t - t_1) after the first '// &
                       'landing, in flight and rolling (m)')
      call check_close(worst_spin, 0.0_wp, 0.0_wp, 1e-9_wp, 'rolling on: omega_y = v_x/R throughout (R rad/s)')
      call check(in_flight(n) == 0, 'rolling on: closed at the end')
      call check_close(s%normal(1, n), 0.2_wp*g, 0.0_wp, 1e-9_wp, 'rolling on: N = m g once rolling (N)')
      call check_close(s%body_r(3, 1, n), radius, 0.0_wp, 1e-10_wp, 'rolling on: on the floor (m)')
      call check_close(s%body_v(3, 1, n), 0.0_wp, 0.0_wp, 1e-10_wp, 'rolling on: no vertical speed (m/s)')
    end associate
  end subroutine rolling_on

  !> A ball (radius r = 0.1 m) rolling without slip off a fixed sphere (the
  !> dome, radius 1 m), from rest near its top at theta_0 from the vertical
  !> (its centre on the sphere of radius R = 1.1 m): energy m g R (cos
  !> theta_0 - cos theta) = 7/10 m v^2 (rolling: v = omega r, I = 2/5 m r^2)
  !> and the normal force m g cos theta - m v^2/R falling to zero give the
  !> lift-off at cos theta = 10/17 cos theta_0. With may_open the contact opens
  !> there and the ball flies: its centre on the projectile c_L + v_L s +
  !> g s^2/2 from the lift-off state (c_L, v_L; s since the lift-off), its
  !> angular velocity kept (a sphere, torque-free), its pose and twist
  !> continuous across the switch (1e-12 m, 1e-12 of v_L); it moves away from
  !> the dome (the gap grows: no landing) to the end. Without may_open the
  !> same input ends at the lift-off, as before. Tolerances: rtol 1e-10: the
  !> lift-off's cos theta to 1e-7 as cli_contact_lift_off's dome, the flight
  !> (a polynomial motion from the recorded lift-off state) to 1e-9 m.
  subroutine dome_lift_off()
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:)
    integer, allocatable :: in_flight(:), open(:, :)
    character(len=:), allocatable :: text
    real(wp) :: c0, c_l, s, worst_path, worst_spin, gap_min
    integer :: n, lift, i
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-10, atol = 1e-10, duration = 3, output_step = 0.01 /'//nl// &
           '&shape name = ''dome'', kind = ''ellipsoid'', a = 1, b = 1, c = 1 /'//nl// &
           '&shape name = ''ball'', kind = ''ellipsoid'', a = 0.1, b = 0.1, c = 0.1 /'//nl// &
           '&body name = ''ball'', mass = 1, solid_of = ''ball'', position = 0.05, 0, 1.1, angles_deg = 90, 0, 0 /'// &
           nl//'&contact name = ''ball_on_dome'', shape_1 = ''dome'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'rolling = .true., may_open = .true. /'//nl
    call read_closed_flight(text, 'dome', flight, q0, qd0, st, system)
    call check(st%ok(), 'dome: built from the input: '//st%text())
    if (.not. st%ok()) return
    call fly(flight, q0, qd0, 1e-10_wp, 3.0_wp, 400, result, st, open)
    in_flight = open(1, :)   ! the one contact
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'dome: runs to the end: '//st%text())
    call check(index(flight%outcome, 'lift-off: the normal force of contact ''ball_on_dome'' fell to zero') == 1 &
               .and. index(flight%outcome, 'the contact opens (may_open), the body flies') > 0, &
               'dome: the outcome says lift-off and flight: '//flight%outcome)
    associate (sr => flight%series)
      n = sr%n
      call check(size(in_flight) == n .and. in_flight(1) == 0 .and. in_flight(n) == 1, &
                 'dome: closed, then in flight')
      if (size(in_flight) /= n .or. n < 3) return
      lift = count(in_flight == 0)
      call check(all(in_flight(:lift) == 0) .and. all(in_flight(lift + 1:) == 1), 'dome: one switch')
      call check(sr%time(lift) == sr%time(lift + 1), 'dome: the closed contact''s last record and the flight''s '// &
                 'first at the lift-off')
      c0 = sr%body_r(3, 1, 1)/norm2(sr%body_r(:, 1, 1))
      c_l = sr%body_r(3, 1, lift)/norm2(sr%body_r(:, 1, lift))
      call check_close(c_l, 10.0_wp/17*c0, 1e-7_wp, 0.0_wp, 'dome: lift-off at cos theta = 10/17 cos theta_0')
      call check_close(maxval(abs(sr%body_r(:, 1, lift + 1) - sr%body_r(:, 1, lift))), 0.0_wp, 0.0_wp, 1e-12_wp, &
                       'dome: the position continuous across the switch (m)')
      call check_close(maxval(abs(sr%body_rot(:, :, 1, lift + 1) - sr%body_rot(:, :, 1, lift))), 0.0_wp, 0.0_wp, &
                       1e-12_wp, 'dome: the orientation continuous across the switch')
      call check_close(maxval(abs(sr%body_v(:, 1, lift + 1) - sr%body_v(:, 1, lift))), 0.0_wp, 0.0_wp, &
                       1e-12_wp*norm2(sr%body_v(:, 1, lift)), 'dome: the velocity continuous across the switch (m/s)')
      call check_close(0.1_wp*maxval(abs(sr%body_omega(:, 1, lift + 1) - sr%body_omega(:, 1, lift))), 0.0_wp, &
                       0.0_wp, 1e-12_wp*norm2(sr%body_v(:, 1, lift)), &
                       'dome: the angular velocity continuous across the switch (r rad/s)')
      worst_path = 0
      worst_spin = 0
      gap_min = huge(1.0_wp)
      do i = lift + 1, n
        s = sr%time(i) - sr%time(lift)
        worst_path = max(worst_path, norm2(sr%body_r(:, 1, i) - (sr%body_r(:, 1, lift) + sr%body_v(:, 1, lift)*s + &
                                                                  system%gravity*s**2/2)))
        worst_spin = max(worst_spin, norm2(sr%body_omega(:, 1, i) - sr%body_omega(:, 1, lift)))
        gap_min = min(gap_min, norm2(sr%body_r(:, 1, i)) - 1.1_wp)
      end do
      call check_close(worst_path, 0.0_wp, 0.0_wp, 1e-9_wp, 'dome: the projectile from the lift-off state (m)')
      call check_close(worst_spin, 0.0_wp, 0.0_wp, 1e-9_wp, 'dome: the spin kept in flight (rad/s)')
      call check(gap_min >= -1e-12_wp .and. norm2(sr%body_r(:, 1, n)) > 1.5_wp, &
                 'dome: it flies away from the dome (no landing)')
    end associate
  end subroutine dome_lift_off

  !> A ball (radius r = 0.1 m, rolling without slip) round the inside of a
  !> fixed sphere (radius 1 m, its poles turned horizontal, out of the ball's
  !> way) in the vertical x-z plane: from the bottom at v_0 with v_0^2 =
  !> 3 g rho (rho = 0.9 m, the sphere its centre keeps to), too slow for the
  !> loop. With theta from the top, rolling energy 7/10 m v^2 + m g rho cos
  !> theta = 7/10 m v_0^2 - m g rho and the normal force m (v^2/rho - g cos
  !> theta) falling to zero give the lift-off at cos theta_L = (7 v_0^2/(g
  !> rho) - 10)/17 = 11/17, v_L^2 = g rho cos theta_L. There the contact
  !> opens (may_open) and the ball flies the parabola c_L + v_L s + g s^2/2
  !> inside the sphere until its centre is rho from the centre again: the
  !> landing (no restitution: the run ends there, the outcome says so). The
  !> landing's s solves |c(s)| = rho (bisection here, on the closed-form
  !> parabola). Checked: the lift-off angle; the flight on the parabola from
  !> the recorded lift-off state; the landing time, place and normal speed
  !> from it, and from the closed-form lift-off state. Tolerances: rtol 1e-10:
  !> cos theta_L to 1e-7 as the dome (1.6e-9 seen); the flight (a polynomial
  !> motion from the recorded state) to 1e-9 m as the dome (7e-15 m seen);
  !> the landing from the recorded lift-off state: CVODE locates the root to
  !> 100 u (|t| + |h|) ~ 5e-14 s, so its time to 1e-12 s, its place to 1e-11 m
  !> and its normal speed to 1e-11 m/s (at 5.5 m/s and g: 3e-13 m, 5e-13 m/s;
  !> 2e-14 s, 9e-14 m, 1e-13 m/s seen); from the closed-form lift-off state
  !> the lift-off's 1e-7 in cos theta moves the landing by ~0.25 s per unit
  !> cos theta, so 1e-7 s and 1e-6 m (4e-10 s, 5e-9 m seen).
  subroutine loop_lift_off_and_landing()
    real(wp), parameter :: rho = 0.9_wp, cos_lift = 11.0_wp/17
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:)
    integer, allocatable :: in_flight(:), open(:, :)
    character(len=:), allocatable :: text
    character(len=46) :: numbers
    real(wp) :: v0, s, worst_path, s_land, s_ideal, sin_lift, c_ideal(3), v_ideal(3), c_end(3), v_end(3), e(3)
    integer :: n, lift, i
    v0 = sqrt(3*g*rho)
    write (numbers, '(2(es22.15,1x))') v0, v0/radius
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-10, atol = 1e-10, duration = 3, output_step = 0.01 /'//nl// &
           '&shape name = ''loop'', kind = ''sphere'', radius = 1, angles_deg = 90, 0, 0 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''ball'', mass = 1, solid_of = ''ball'', position = 0, 0, -0.9, velocity = '// &
           numbers(1:22)//', 0, 0, angular_velocity = 0, '//numbers(24:45)//', 0 /'//nl// &
           '&contact name = ''in_loop'', shape_1 = ''loop'', side_1 = -1, body_2 = ''ball'', shape_2 = ''ball'', '// &
           'rolling = .true., may_open = .true. /'//nl
    call read_closed_flight(text, 'loop', flight, q0, qd0, st, system)
    call check(st%ok(), 'loop: built from the input: '//st%text())
    if (.not. st%ok()) return
    call fly(flight, q0, qd0, 1e-10_wp, 3.0_wp, 400, result, st, open)
    in_flight = open(1, :)   ! the one contact
    call check(st%ok() .and. result%outcome == DRIVE_EVENT_STOP, 'loop: ends at the landing: '//st%text())
    call check(index(flight%outcome, 'lift-off: the normal force of contact ''in_loop'' fell to zero') == 1 &
               .and. index(flight%outcome, 'the contact opens (may_open), the body flies') > 0 .and. &
               index(flight%outcome, 'landing: the gap of contact ''in_loop'' fell to zero') > 0, &
               'loop: the outcome says lift-off, flight and landing: '//flight%outcome)
    associate (sr => flight%series)
      n = sr%n
      call check(size(in_flight) == n .and. in_flight(1) == 0 .and. in_flight(n) == 1, &
                 'loop: closed, then in flight')
      if (size(in_flight) /= n .or. n < 3) return
      lift = count(in_flight == 0)
      call check(all(in_flight(:lift) == 0) .and. all(in_flight(lift + 1:) == 1), 'loop: one switch')
      call check_close(sr%body_r(3, 1, lift)/norm2(sr%body_r(:, 1, lift)), cos_lift, 1e-7_wp, 0.0_wp, &
                       'loop: lift-off at cos theta = 11/17')
      call check_close(norm2(sr%body_v(:, 1, lift))**2, g*rho*cos_lift, 1e-7_wp, 0.0_wp, &
                       'loop: lift-off at v^2 = g rho cos theta')
      worst_path = 0
      do i = lift + 1, n
        s = sr%time(i) - sr%time(lift)
        worst_path = max(worst_path, norm2(sr%body_r(:, 1, i) - parabola(sr%body_r(:, 1, lift), sr%body_v(:, 1, lift), s)))
      end do
      call check_close(worst_path, 0.0_wp, 0.0_wp, 1e-9_wp, 'loop: the projectile from the lift-off state (m)')
      s_land = landing(sr%body_r(:, 1, lift), sr%body_v(:, 1, lift), rho)
      call check_close(sr%time(n) - sr%time(lift), s_land, 0.0_wp, 1e-12_wp, &
                       'loop: lands where the parabola from the lift-off state meets the sphere (s)')
      c_end = parabola(sr%body_r(:, 1, lift), sr%body_v(:, 1, lift), s_land)
      v_end = sr%body_v(:, 1, lift) + system%gravity*s_land
      e = c_end/norm2(c_end)
      call check_close(maxval(abs(sr%body_r(:, 1, n) - c_end)), 0.0_wp, 0.0_wp, 1e-11_wp, 'loop: the landing place (m)')
      call check(dot_product(v_end, e) > 1, 'loop: lands approaching the wall (normal speed > 1 m/s)')
      call check_close(dot_product(sr%body_v(:, 1, n), e), dot_product(v_end, e), 0.0_wp, 1e-11_wp, &
                       'loop: the landing''s normal speed (m/s)')
      ! from the closed-form lift-off state: going up the +x side, over towards -x
      sin_lift = sqrt(1 - cos_lift**2)
      c_ideal = rho*[sin_lift, 0.0_wp, cos_lift]
      v_ideal = sqrt(g*rho*cos_lift)*[-cos_lift, 0.0_wp, sin_lift]
      s_ideal = landing(c_ideal, v_ideal, rho)
      call check_close(sr%time(n) - sr%time(lift), s_ideal, 0.0_wp, 1e-7_wp, &
                       'loop: the flight time from the closed-form lift-off (s)')
      call check_close(maxval(abs(sr%body_r(:, 1, n) - parabola(c_ideal, v_ideal, s_ideal))), 0.0_wp, 0.0_wp, &
                       1e-6_wp, 'loop: the landing place from the closed-form lift-off (m)')
    end associate
  end subroutine loop_lift_off_and_landing

  !> The centre at s on the parabola from (c, v) under standard gravity.
  pure function parabola(c, v, s) result(p)
    real(wp), intent(in) :: c(3), v(3), s
    real(wp) :: p(3)
    p = c + v*s + [0.0_wp, 0.0_wp, -g]*s**2/2
  end function parabola

  !> The first s > 0 where the parabola from (c, v) is rho from the origin
  !> again (it starts there tangent, goes inside: steps of 1 ms to the
  !> first point outside, then bisection to rounding).
  pure real(wp) function landing(c, v, rho) result(s)
    real(wp), intent(in) :: c(3), v(3), rho
    real(wp) :: lo, hi
    integer :: k
    hi = 1e-3_wp
    do while (norm2(parabola(c, v, hi)) < rho)
      hi = hi + 1e-3_wp
    end do
    lo = hi - 1e-3_wp
    do k = 1, 200
      s = (lo + hi)/2
      if (s <= lo .or. s >= hi) exit
      if (norm2(parabola(c, v, s)) < rho) then
        lo = s
      else
        hi = s
      end if
    end do
  end function landing

  subroutine refusals()
    type(flight_ode_t) :: flight
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    call read_flight(ball_input(-0.01_wp, ''), 'overlap', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'touches or overlaps') > 0, &
               'an open start in the floor is refused: '//st%text())
    call read_flight(ball_input(h, '&shape name = ''ball2'', kind = ''sphere'', radius = 0.1 /'//nl// &
                          '&body name = ''ball2'', mass = 0.2, solid_of = ''ball2'', position = 1, 0, 0.1 /'//nl// &
                          '&contact name = ''second'', body_1 = ''ball'', shape_1 = ''ball'', body_2 = ''ball2'', '// &
                          'shape_2 = ''ball2'', start = ''open'', restitution = 0.5, level = ''velocity'' /'//nl), &
                     'body on body', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'a contact between two bodies closes at position level, '// &
               'sliding by the open chain or rolling by the loop (level and chain there are not built)') > 0, &
               'a contact between two bodies at velocity level is refused: '//st%text())
    call read_flight(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', friction = ''coulomb'', mu = 0.5'), &
               'friction', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'needs restitution') > 0, &
               'friction with an open start without restitution is refused (unused: the run ends at the '// &
               'landing): '//st%text())
    call read_flight(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', friction = ''coulomb'', '// &
                       'mu = 0.5, restitution = 0.5'), 'friction with restitution', flight, q0, qd0, st)
    call check(st%ok(), 'friction with an open start and restitution: the closed contact''s: '//st%text())
    call read_flight(replace(ball_input(h, ''), 'start = ''open''', 'restitution = 0.5'), 'closed with restitution', &
               flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'restitution') > 0 .and. index(st%text(), 'never lands') > 0, &
               'restitution on a closed start is refused (unused): '//st%text())
    call read_flight(replace(ball_input(h, ''), 'start = ''open''', 'start = ''open'', close_speed = 0.1'), &
               'close_speed alone', flight, q0, qd0, st)
    call check(.not. st%ok() .and. index(st%text(), 'close_speed') > 0, &
               'close_speed without restitution is refused (unused): '//st%text())
  end subroutine refusals
end program test_flight
