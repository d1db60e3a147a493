!> A body carried by a closed contact beside a flying one (issue 25,
!> contact_bodies): one mechanism of the bodies as they are, rebuilt where
!> one switches (a closing, a lift-off), the others going on as they were.
!> Against closed forms and against each ball's run alone:
!>   - slide_beside_bounce: ball a (R 0.1 m, 0.2 kg) starts closed on a
!>     frictionless 30 degree slope, at rest, and slides down it at
!>     g sin(theta): s = g sin(theta) t^2/2 along the slope (its spin stays
!>     0); ball b (R 0.05 m, 0.5 kg) drops from h = 0.6 m onto a floor with
!>     e = 0.8: impacts at t0 = v0/g and then after flights 2 v_k/g, v_k =
!>     e^k v0. a on its closed form at every record to 1e-12 m, m/s (its
!>     motion is a parabola Adams integrates exactly: rounding only); a
!>     against its closed run alone and b against its flight alone (1e-10:
!>     b's impacts are roots located to ~1e-14 s, the rest the integration
!>     error of another step sequence, as in test_bodies_flight).
!>   - rest_beside_flying: ball a bounces on the floor with e = 0.5 until
!>     its sixth rebound, e^6 v0 = 0.069 m/s, falls below close_speed 0.1
!>     m/s: its contact closes (Zeno) at t0 (1 + 2e (1 - e^5)/(1 - e)) =
!>     1.3266 s while ball b (e = 0.9, from 1 m) flies on; a then slides on
!>     the frictionless floor at its 0.3 m/s (x = 0.3 t, its centre at R,
!>     no vertical speed: 1e-12), b bounces on through its third impact
!>     after a closed (each on its closed form, 1e-9; b against b alone,
!>     1e-10); a against its run alone (bounces, closes, slides: the single
!>     body's phases), 1e-10. At a's closing b's pose and twist are the same
!>     in the records before and after the switch (rounding: 1e-14).
!>   - energy_pair: a slides on the slope (closed) while b bounces on the
!>     floor with e = 1, both frictionless: the total energy (kinetic and
!>     potential of both) stays at its start to 1e-8 over 2 s.
!>   - lift_off_beside_flying: a rolls off a dome (inputs/contact/
!>     dome_floor.nml's ball: may_open, the floor a second contact with e =
!>     0.5) while b bounces beside it: a's contact with the dome opens at its
!>     lift-off (a switch of a's part only), a flies, lands on the floor and
!>     bounces until that contact closes; a against its run alone (the one
!>     body's phases) and b against its flight alone, 1e-9.
program test_bodies_carried
  use base_kinds, only: wp
  use base_constants, only: standard_gravity, pi
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME, RECORD_OUTPUT, &
    RECORD_EVENT
  use io_input, only: input_text_t, input_from_text
  use io_contact_config, only: read_contact_config
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t, build_flight, impact_record_t
  use contact_bodies, only: build_bodies, start_carriers
  use contact_closing, only: drive_flight, flight_after_closed
  use contact_flight, only: closed_part, carrying_contact
  use kinetostatics_recorder, only: mechanism_series_t
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, vector_text
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity, theta = 30*pi/180
  real(wp), parameter :: ra = 0.1_wp, ma = 0.2_wp, rb = 0.05_wp, mb = 0.5_wp
  real(wp), parameter :: downhill(3) = [cos(theta), 0.0_wp, -sin(theta)], normal(3) = [sin(theta), 0.0_wp, cos(theta)]

  call slide_beside_bounce(.false.)
  call slide_beside_bounce(.true.)
  call rest_beside_flying()
  call energy_pair()
  call lift_off_beside_flying()
  call finish_tests('test_bodies_carried')

contains

  function head(duration) result(text)
    real(wp), intent(in) :: duration
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = '//number(duration)//', output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''slope'', kind = ''plane'', angles_deg = 0, 30, 0 /'//nl// &
           '&shape name = ''a'', kind = ''sphere'', radius = '//number(ra)//' /'//nl// &
           '&shape name = ''b'', kind = ''sphere'', radius = '//number(rb)//' /'//nl
  end function head

  !> Ball a at rest on the slope, its contact closed: frictionless, or
  !> rolling (its poles turned off the contact point: angles_deg).
  function a_on_slope(rolling) result(text)
    logical, intent(in) :: rolling
    character(len=:), allocatable :: text
    text = '&body name = ''a'', mass = '//number(ma)//', solid_of = ''a'', position = '//vector_text(ra*normal)// &
           trim(merge(', angles_deg = -90, 0, 0', '                        ', rolling))//' /'//nl// &
           '&contact name = ''a_slope'', shape_1 = ''slope'', body_2 = ''a'', shape_2 = ''a'''// &
           trim(merge(', rolling = .true.', '                  ', rolling))//' /'//nl
  end function a_on_slope

  !> A ball `name` (radius r, mass m) dropped from `lowest` (its lowest
  !> point) at x, moving at vx, onto the floor with restitution e.
  function dropped(name, r, m, x, lowest, vx, e) result(text)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: r, m, x, lowest, vx, e
    character(len=:), allocatable :: text
    text = '&body name = '''//name//''', mass = '//number(m)//', solid_of = '''//name//''', position = '// &
           vector_text([x, 2.0_wp, r + lowest])//', velocity = '//vector_text([vx, 0.0_wp, 0.0_wp])//' /'//nl// &
           '&contact name = '''//name//'_floor'', shape_1 = ''floor'', body_2 = '''//name//''', shape_2 = '''// &
           name//''', start = ''open'', restitution = '//number(e)//', close_speed = 0.1 /'//nl
  end function dropped

  function options_for(duration) result(options)
    real(wp), intent(in) :: duration
    type(driver_options_t) :: options
    options%ode%rtol = 1e-12_wp
    options%ode%atol = 1e-12_wp
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = duration
    options%output_step = 0.01_wp
    options%progress_seconds = 0
  end function options_for

  subroutine read_system(text, label, system, ok)
    character(len=*), intent(in) :: text, label
    type(contact_system_t), intent(out) :: system
    logical, intent(out) :: ok
    type(input_text_t) :: input
    type(status_t) :: st
    call input_from_text(label, text, input, st)
    call read_contact_config(input, system, st)
    ok = st%ok()
    call check(ok, label//': read: '//st%text())
  end subroutine read_system

  !> The flight of `text` (several bodies through contact_bodies where a
  !> contact starts closed), driven for `duration`; outcome the driver's.
  subroutine run(text, label, duration, flight, outcome, open)
    character(len=*), intent(in) :: text, label
    real(wp), intent(in) :: duration
    type(flight_ode_t), intent(out), target :: flight
    integer, intent(out) :: outcome
    integer, allocatable, intent(out) :: open(:, :)
    type(contact_system_t) :: system
    type(contact_model_t) :: model
    real(wp), allocatable :: q0(:), qd0(:)
    character(len=8), allocatable :: units(:)
    type(status_t) :: st
    type(driver_result_t) :: result
    logical :: ok
    outcome = 0
    call read_system(text, label, system, ok)
    if (.not. ok) return
    if (size(system%bodies) > 1 .and. .not. all(system%contacts%start_open)) then
      call build_bodies(system, start_carriers(system), flight, q0, qd0, units, st, 0, .false.)
    else if (carrying_contact(system) > 0) then
      ! one body that starts closed (as scenarios_contact runs it)
      call build_contact_model(closed_part(system, carrying_contact(system)), model, st)
      call flight_after_closed(system, model, flight, q0, qd0, units, st)
    else
      call build_flight(system, flight, q0, qd0, units, st)
    end if
    call check(st%ok(), label//': built: '//st%text())
    if (.not. st%ok()) return
    call flight%start_series(300)
    call drive_flight(flight, flight%initial_state(q0, qd0), options_for(duration), result, st, open)
    call check(st%ok(), label//': ran: '//st%text())
    outcome = result%outcome
  end subroutine run

  !> The closed run of `text` (one body, its contact closed) for `duration`.
  subroutine run_closed(text, label, duration, model)
    character(len=*), intent(in) :: text, label
    real(wp), intent(in) :: duration
    type(contact_model_t), intent(out), target :: model
    type(contact_system_t) :: system
    type(status_t) :: st
    type(driver_result_t) :: result
    logical :: ok
    call read_system(text, label, system, ok)
    if (.not. ok) return
    call build_contact_model(system, model, st)
    call check(st%ok(), label//': built: '//st%text())
    if (.not. st%ok()) return
    call model%ode%start_series(300)
    call drive(model%ode, model%y0, options_for(duration), result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//': ran to the end: '//st%text())
  end subroutine run_closed

  !> The place of body `name` among the series' bodies.
  integer function body_of(s, name) result(k)
    type(mechanism_series_t), intent(in) :: s
    character(len=*), intent(in) :: name
    do k = 1, s%nb
      if (trim(s%body_names(k)) == name) return
    end do
    k = 0
  end function body_of

  !> The largest difference of body `name`'s position and velocity (m, m/s)
  !> between the series s and its run alone s1 at their common output times
  !> (before t_end); count the times compared.
  subroutine against_alone(s, s1, name, t_end, worst, count)
    type(mechanism_series_t), intent(in) :: s, s1
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: t_end
    real(wp), intent(out) :: worst
    integer, intent(out) :: count
    integer :: i, j, k, k1
    real(wp) :: at, before
    worst = 0
    at = 0
    count = 0
    k = body_of(s, name)
    k1 = body_of(s1, name)
    do i = 1, s%n
      if (s%kind(i) /= RECORD_OUTPUT .or. s%time(i) > t_end) cycle
      j = findloc(s1%time(:s1%n), s%time(i), dim=1)
      if (j == 0) cycle
      if (s1%kind(j) /= RECORD_OUTPUT) cycle
      count = count + 1
      before = worst
      worst = max(worst, maxval(abs(s%body_r(:, k, i) - s1%body_r(:, k1, j))), &
                  maxval(abs(s%body_v(:, k, i) - s1%body_v(:, k1, j))))
      if (worst > before) at = s%time(i)
    end do
    print '(a, es10.3, a, f8.4, a)', '    '//name//' against alone: ', worst, ' at t = ', at, ' s'
  end subroutine against_alone

  !> A dropped ball's closed form: impact times t(1:n), speeds v(0:n) (v(j) after impact j).
  subroutine bounces(height, e, n, t, v)
    real(wp), intent(in) :: height, e
    integer, intent(in) :: n
    real(wp), intent(out) :: t(n), v(0:n)
    integer :: j
    v = [(e**j*sqrt(2*g*height), j = 0, n)]
    t(1) = v(0)/g
    do j = 2, n
      t(j) = t(j - 1) + 2*v(j - 1)/g
    end do
  end subroutine bounces

  !> The impacts of contact c in `flight` against the closed form (times and speeds, 1e-9).
  subroutine check_bounces(flight, c, height, e, n, label)
    type(flight_ode_t), intent(in) :: flight
    integer, intent(in) :: c, n
    real(wp), intent(in) :: height, e
    character(len=*), intent(in) :: label
    real(wp) :: t(n), v(0:n)
    integer :: j, i
    call bounces(height, e, n, t, v)
    call check(count(flight%impacts%contact == c) >= n, label//': at least its impacts on the closed form')
    j = 0
    do i = 1, size(flight%impacts)
      if (flight%impacts(i)%contact /= c) cycle
      j = j + 1
      if (j > n) exit
      call check_close(flight%impacts(i)%time, t(j), 0.0_wp, 1e-9_wp, label//': impact time (s)')
      call check_close(flight%impacts(i)%normal_speed_before, -v(j - 1), 0.0_wp, 1e-9_wp, &
                       label//': approach speed e^(k-1) v0 (m/s)')
      if (j < n .or. v(j) >= 0.1_wp) call check_close(flight%impacts(i)%normal_speed_after, v(j), 0.0_wp, 1e-9_wp, &
                                                      label//': rebound e^k v0 (m/s)')
    end do
  end subroutine check_bounces

  subroutine slide_beside_bounce(rolling)
    logical, intent(in) :: rolling
    type(flight_ode_t), target :: both, b_alone
    type(contact_model_t), target :: a_alone
    integer :: outcome, i, k, n
    integer, allocatable :: open(:, :), open_b(:, :)
    real(wp) :: worst_r, worst_v, worst_a, worst_b, expected_r(3), expected_v(3), accel, spin(3)
    character(len=:), allocatable :: label
    label = trim(merge('roll beside bounce ', 'slide beside bounce', rolling))
    ! along the slope: g sin(theta) sliding, 5/7 of it rolling (the spin v/R about the slope's horizontal)
    accel = merge(5.0_wp/7, 1.0_wp, rolling)*g*sin(theta)
    call run(head(1.0_wp)//a_on_slope(rolling)//dropped('b', rb, mb, -3.0_wp, 0.6_wp, 0.0_wp, 0.8_wp), label, 1.0_wp, &
             both, outcome, open)
    call check(outcome == DRIVE_END_TIME, label//': runs to the end: '//both%outcome)
    if (outcome /= DRIVE_END_TIME) return
    associate (s => both%series)
      k = body_of(s, 'a')
      worst_r = 0
      worst_v = 0
      do i = 1, s%n
        expected_r = ra*normal + downhill*accel*s%time(i)**2/2
        expected_v = downhill*accel*s%time(i)
        spin = 0
        if (rolling) spin = [0.0_wp, accel*s%time(i)/ra, 0.0_wp]
        worst_r = max(worst_r, maxval(abs(s%body_r(:, k, i) - expected_r)))
        worst_v = max(worst_v, maxval(abs(s%body_v(:, k, i) - expected_v)), &
                      ra*maxval(abs(s%body_omega(:, k, i) - spin)))
      end do
      call check_close(worst_r, 0.0_wp, 0.0_wp, 1e-11_wp, label//': a at every record on s = a t^2/2 down the '// &
                       'slope, a = g sin(theta) (sliding), 5/7 g sin(theta) (rolling) (m)')
      call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-12_wp, label//': a''s velocity a t, its spin 0 (sliding), '// &
                       'a t/R (rolling) (m/s)')
      call check(all(open(1, :s%n) == 0) .and. all(open(2, :s%n) == 1), label//': a''s contact closed, b''s open '// &
                 'at every record')
      print '(a, 2es10.3)', '  '//label//': a on its closed form (m, m/s) ', worst_r, worst_v
    end associate
    call check(all(both%impacts%contact == 2) .and. size(both%impacts) == 2, label//': two impacts, both b''s')
    call check_bounces(both, 2, 0.6_wp, 0.8_wp, 2, label//': b')
    ! each alone
    call run_closed(head(1.0_wp)//a_on_slope(rolling), 'a alone', 1.0_wp, a_alone)
    call against_alone(both%series, a_alone%ode%series, 'a', 1.0_wp, worst_a, n)
    call check(n >= 100, label//': a: the runs share the output times')
    call check_close(worst_a, 0.0_wp, 0.0_wp, 1e-11_wp, label//': a as in its closed run alone (m, m/s)')
    call run(head(1.0_wp)//dropped('b', rb, mb, -3.0_wp, 0.6_wp, 0.0_wp, 0.8_wp), 'b alone', 1.0_wp, b_alone, &
             outcome, open_b)
    call against_alone(both%series, b_alone%series, 'b', 1.0_wp, worst_b, n)
    call check(n >= 100, label//': b: the runs share the output times')
    call check_close(worst_b, 0.0_wp, 0.0_wp, 1e-10_wp, label//': b as in its flight alone (m, m/s)')
    print '(a, 2es10.3)', '  '//label//': a, b against alone (m, m/s) ', worst_a, worst_b
  end subroutine slide_beside_bounce

  subroutine rest_beside_flying()
    type(flight_ode_t), target :: both, a_alone, b_alone
    integer :: outcome, i, k, kb, n, switch
    integer, allocatable :: open(:, :), open_1(:, :)
    real(wp) :: t_close, worst_rest, worst_a, worst_b, jump_b
    character(len=*), parameter :: label = 'rest beside flying'
    character(len=:), allocatable :: a_text, b_text
    a_text = dropped('a', ra, ma, 0.0_wp, 1.0_wp, 0.3_wp, 0.5_wp)
    b_text = dropped('b', rb, mb, -3.0_wp, 1.0_wp, -0.2_wp, 0.9_wp)
    call run(head(2.5_wp)//a_text//b_text, label, 2.5_wp, both, outcome, open)
    call check(outcome == DRIVE_END_TIME, label//': runs to the end (a at rest does not end it): '//both%outcome)
    if (outcome /= DRIVE_END_TIME) return
    call check(index(both%outcome, 'contact ''a_floor'' closed at the impact') > 0, &
               label//': the outcome says a''s contact closed: '//both%outcome)
    t_close = sqrt(2/g)*(1 + 2*0.5_wp*(1 - 0.5_wp**5)/(1 - 0.5_wp))
    call check_bounces(both, 1, 1.0_wp, 0.5_wp, 6, label//': a')
    call check_bounces(both, 2, 1.0_wp, 0.9_wp, 3, label//': b')
    call check(count(both%impacts%contact == 1) == 6 .and. count(both%impacts%contact == 2) == 3, &
               label//': six impacts of a (the sixth closes), three of b')
    associate (s => both%series)
      k = body_of(s, 'a')
      kb = body_of(s, 'b')
      worst_rest = 0
      switch = 0
      do i = 1, s%n
        if (s%time(i) < t_close - 1e-9_wp) then
          if (open(1, i) /= 1) worst_rest = huge(1.0_wp)
          cycle
        end if
        if (s%time(i) > t_close + 1e-9_wp .and. open(1, i) /= 0) worst_rest = huge(1.0_wp)
        if (open(1, i) == 0 .and. switch == 0) switch = i
        if (open(1, i) /= 0) cycle
        worst_rest = max(worst_rest, abs(s%body_r(3, k, i) - ra), abs(s%body_v(3, k, i)), &
                         abs(s%body_v(1, k, i) - 0.3_wp), abs(s%body_r(1, k, i) - 0.3_wp*s%time(i)), &
                         abs(s%body_r(2, k, i) - 2), abs(s%body_v(2, k, i)))
      end do
      call check_close(worst_rest, 0.0_wp, 0.0_wp, 1e-12_wp, label//': a closed from its sixth impact on, at '// &
                       'rest on the floor sliding on at 0.3 m/s: x = 0.3 t, its centre at R (m, m/s)')
      call check(switch > 1 .and. s%kind(switch) == RECORD_EVENT, label//': a record at the switch')
      if (switch > 1) then
        call check_close(s%time(switch), t_close, 0.0_wp, 1e-10_wp, label//': a closes at its sixth impact (s)')
        jump_b = max(maxval(abs(s%body_r(:, kb, switch) - s%body_r(:, kb, switch - 1))), &
                     maxval(abs(s%body_v(:, kb, switch) - s%body_v(:, kb, switch - 1))))
        call check_close(jump_b, 0.0_wp, 0.0_wp, 1e-14_wp, label//': b''s pose and velocity kept at a''s switch')
        print '(a, 2es10.3)', '  '//label//': a at rest (m, m/s), b across the switch ', worst_rest, jump_b
      end if
    end associate
    call run(head(2.5_wp)//a_text, 'a alone', 2.5_wp, a_alone, outcome, open_1)
    call against_alone(both%series, a_alone%series, 'a', 2.5_wp, worst_a, n)
    call check(n >= 240, label//': a: the runs share the output times')
    call check_close(worst_a, 0.0_wp, 0.0_wp, 1e-9_wp, label//': a as in its run alone (m, m/s)')
    call run(head(2.5_wp)//b_text, 'b alone', 2.5_wp, b_alone, outcome, open_1)
    call against_alone(both%series, b_alone%series, 'b', 2.5_wp, worst_b, n)
    call check(n >= 240, label//': b: the runs share the output times')
    call check_close(worst_b, 0.0_wp, 0.0_wp, 1e-9_wp, label//': b as in its flight alone (m, m/s)')
    print '(a, 2es10.3)', '  '//label//': a, b against alone (m, m/s) ', worst_a, worst_b
  end subroutine rest_beside_flying

  subroutine energy_pair()
    type(flight_ode_t), target :: both
    integer :: outcome, i, k, kb
    integer, allocatable :: open(:, :)
    real(wp) :: e0, worst
    character(len=*), parameter :: label = 'energy pair'
    call run(head(2.0_wp)//a_on_slope(.false.)//dropped('b', rb, mb, -3.0_wp, 0.6_wp, 0.4_wp, 1.0_wp), label, 2.0_wp, &
             both, outcome, open)
    call check(outcome == DRIVE_END_TIME, label//': runs to the end: '//both%outcome)
    if (outcome /= DRIVE_END_TIME) return
    call check(count(both%impacts%contact == 2) == 3, label//': b bounces (three impacts in 2 s)')
    associate (s => both%series)
      k = body_of(s, 'a')
      kb = body_of(s, 'b')
      e0 = energy(s, k, kb, 1)
      worst = 0
      do i = 1, s%n
        worst = max(worst, abs(energy(s, k, kb, i) - e0))
      end do
      call check_close(worst/e0, 0.0_wp, 0.0_wp, 1e-8_wp, label//': the total energy at its start (relative)')
      print '(a, es10.3)', '  '//label//': energy relative to its start ', worst/e0
    end associate
  end subroutine energy_pair

  subroutine lift_off_beside_flying()
    type(flight_ode_t), target :: both, a_alone, b_alone
    integer :: outcome, n, i, opened, opened_1
    integer, allocatable :: open(:, :), open_1(:, :)
    real(wp) :: worst_a, worst_b
    character(len=*), parameter :: label = 'lift-off beside flying'
    type(impact_record_t), allocatable :: rows(:)
    character(len=:), allocatable :: a_text, b_text, dome
    dome = '&shape name = ''dome'', kind = ''sphere'', radius = 1.0 /'//nl
    a_text = '&body name = ''a'', mass = 1.0, solid_of = ''a'', position = 0.05, 0.0, 1.1, '// &
             'angles_deg = 90, 0, 0 /'//nl// &
             '&contact name = ''a_dome'', shape_1 = ''dome'', body_2 = ''a'', shape_2 = ''a'', rolling = .true., '// &
             'may_open = .true. /'//nl// &
             '&contact name = ''a_floor'', shape_1 = ''floor'', body_2 = ''a'', shape_2 = ''a'', start = ''open'', '// &
             'restitution = 0.5, close_speed = 0.1 /'//nl
    b_text = dropped('b', rb, mb, -3.0_wp, 1.0_wp, -0.2_wp, 0.9_wp)
    call run(head(2.8_wp)//dome//a_text//b_text, label, 2.8_wp, both, outcome, open)
    call check(outcome == DRIVE_END_TIME, label//': runs to the end: '//both%outcome)
    if (outcome /= DRIVE_END_TIME) return
    call check(index(both%outcome, 'the contact opens (may_open)') > 0 .and. &
               index(both%outcome, 'contact ''a_floor'' closed at the impact') > 0, &
               label//': a lifts off the dome, lands on the floor and its contact there closes: '//both%outcome)
    call check(count(both%impacts%contact == 3) == 4, label//': b''s four impacts')
    call check_bounces(both, 3, 1.0_wp, 0.9_wp, 4, label//': b')
    call run(head(2.8_wp)//dome//a_text, 'a alone', 2.8_wp, a_alone, outcome, open_1)
    call check(outcome == DRIVE_END_TIME, label//': a alone runs to the end: '//a_alone%outcome)
    ! the lift-off: the first record with a's dome contact open
    opened = findloc(open(1, :both%series%n), 1, dim=1)
    opened_1 = findloc(open_1(1, :a_alone%series%n), 1, dim=1)
    call check(opened > 1 .and. opened_1 > 1, label//': a''s dome contact opens during the run')
    if (opened > 1 .and. opened_1 > 1) then
      call check_close(both%series%time(opened), a_alone%series%time(opened_1), 0.0_wp, 1e-9_wp, &
                       label//': a lifts off as alone (s)')
      call check(all(open(1, :opened - 1) == 0) .and. all(open(1, opened:both%series%n) == 1), &
                 label//': the dome contact closed before the lift-off, open after')
    end if
    call check(count(both%impacts%contact == 2) == count(a_alone%impacts%contact == 2) .and. &
               count(a_alone%impacts%contact == 2) >= 2, label//': a''s impacts on the floor as alone')
    if (count(both%impacts%contact == 2) == count(a_alone%impacts%contact == 2)) then
      rows = pack(both%impacts, both%impacts%contact == 2)
      associate (one => a_alone%impacts)
        worst_a = 0
        do i = 1, size(rows)
          worst_a = max(worst_a, abs(rows(i)%time - one(i)%time), &
                        abs(rows(i)%normal_speed_before - one(i)%normal_speed_before))
        end do
        call check_close(worst_a, 0.0_wp, 0.0_wp, 1e-9_wp, label//': a''s impacts as alone (s, m/s)')
        print '(a, es10.3)', '  '//label//': a''s impacts against alone ', worst_a
      end associate
    end if
    call against_alone(both%series, a_alone%series, 'a', 2.8_wp, worst_a, n)
    call check(n >= 270, label//': a: the runs share the output times')
    call check_close(worst_a, 0.0_wp, 0.0_wp, 1e-9_wp, label//': a as in its run alone (m, m/s)')
    call run(head(2.8_wp)//b_text, 'b alone', 2.8_wp, b_alone, outcome, open_1)
    call against_alone(both%series, b_alone%series, 'b', 2.8_wp, worst_b, n)
    call check_close(worst_b, 0.0_wp, 0.0_wp, 1e-9_wp, label//': b as in its flight alone (m, m/s)')
    print '(a, 2es10.3)', '  '//label//': a, b against alone (m, m/s) ', worst_a, worst_b
  end subroutine lift_off_beside_flying

  !> The kinetic and potential energy of balls a (body k) and b (body kb) at record i (J).
  real(wp) function energy(s, k, kb, i)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: k, kb, i
    energy = ma*(dot_product(s%body_v(:, k, i), s%body_v(:, k, i))/2 + g*s%body_r(3, k, i)) + &
             ma*ra**2/5*dot_product(s%body_omega(:, k, i), s%body_omega(:, k, i)) + &
             mb*(dot_product(s%body_v(:, kb, i), s%body_v(:, kb, i))/2 + g*s%body_r(3, kb, i)) + &
             mb*rb**2/5*dot_product(s%body_omega(:, kb, i), s%body_omega(:, kb, i))
  end function energy
end program test_bodies_carried
