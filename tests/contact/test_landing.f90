!> Landing on another surface (issue 25 point 2): a body with several
!> contacts with the ground (contact_open_gaps) is carried by one at a time
!> and may land on any other; each gap is an event function through the
!> contact search. Against closed forms:
!>   - dome_to_floor (inputs/contact/dome_floor.nml): a ball rolls without
!>     slip off a fixed dome (lift-off at cos theta = 10/17 cos theta_0) and
!>     flies the projectile c_L + v_L s + g s^2/2 from its lift-off state
!>     until its centre is r above the floor: s_1 = (v_z + sqrt(v_z^2 + 2 g
!>     (z_L - r)))/g, landing at the centre's (x, y) then, approaching at v_1
!>     = sqrt(v_z^2 + 2 g (z_L - r)). The floor is frictionless with e = 0.5:
!>     impact k meets the floor at e^(k-1) v_1, sends the ball up at e^k v_1
!>     after 2 e^(k-1) v_1/g in the air, takes m/2 (1 - e^2) of the approach's
!>     kinetic energy; the horizontal velocity and the spin never change. At
!>     the sixth impact e^6 v_1 = 0.06 m/s is below close_speed 0.1 m/s: the
!>     floor closes (that impact plastic) and the ball slides on at its
!>     height r. The floor's gap is z - r at every record before, 0 after;
!>     each contact's open flags switch once.
!>   - wall_then_floor: a ball thrown at a wall (a plane x = 1, e = 0.8) from
!>     1 m above the floor bounces off it at t_w = (0.9 - x_0)/u (x and z
!>     apart: v_x -> -e_w u, v_z kept), then lands on the floor (e = 0.5) at
!>     t_f = sqrt(2 h/g) and closes there after its bounces, sliding away from
!>     the wall (watched all the while: its gap 1 - r - x).
!>   - carried_into_a_wall: a ball sliding on the frictionless floor
!>     (closed) at u into the wall (open, e = 0.8): one impact through both
!>     at t_w = (0.9 - x_0)/u (contact_flight impact_on_carried: the wall's
!>     impulse m (1 + e) u, the floor's 0), and the ball slides back on the
!>     floor, x = 0.9 - e u (t - t_w).
!> Tolerances: rtol = atol = 1e-10 (the dome, as test_flight's dome) or
!> 1e-12 (the planes): the projectile to 1e-9 m from the recorded lift-off
!> state (test_flight), so the landing time to 1e-9 m / 3.9 m/s; each
!> later impact adds its root's ~1e-14 s and a flight of a parabola that
!> Adams reproduces nearly exactly: times 1e-8 s, speeds 1e-8 m/s (g times
!> the time) plus g dz/v for a height error dz = 1e-9 m at a landing met at
!> v (2e-8 m/s found at the sixth, 0.12 m/s), points 1e-8 m, energies 1e-8
!> J over 6 impacts.
program test_landing
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t, STATUS_DOMAIN
  use numerics_event_driver, only: driver_options_t, driver_result_t, DRIVE_END_TIME, DRIVE_FAILED
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t, build_flight, carrying_contact, closed_part
  use contact_closing, only: drive_flight, flight_after_closed
  use io_input, only: input_text_t, input_from_text, load_input_file
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity, r = 0.1_wp

  call dome_to_floor()
  call wall_then_floor()
  call carried_into_a_wall()
  call finish_tests('test_landing')

contains

  !> Runs `input` as the contact scenario does (closed on its carrying
  !> contact first, if it has one); open: drive_flight's flags.
  subroutine run(input, flight, system, open, result, st)
    type(input_text_t), intent(in) :: input
    type(flight_ode_t), intent(out), target :: flight
    type(contact_system_t), intent(out) :: system
    integer, allocatable, intent(out) :: open(:, :)
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: st
    type(solver_config_t) :: solver
    type(contact_model_t) :: model
    type(driver_options_t) :: options
    real(wp), allocatable :: q0(:), qd0(:)
    character(len=8), allocatable :: units(:)
    call read_solver_config(input, solver, st)
    if (st%ok()) call read_contact_config(input, system, st)
    if (.not. st%ok()) return
    if (carrying_contact(system) == 0) then
      call build_flight(system, flight, q0, qd0, units, st)
    else
      call build_contact_model(closed_part(system, carrying_contact(system)), model, st)
      call flight_after_closed(system, model, flight, q0, qd0, units, st)
    end if
    if (.not. st%ok()) return
    options%ode = solver%options
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call flight%start_series(400)
    call drive_flight(flight, flight%initial_state(q0, qd0), options, result, st, open)
  end subroutine run

  !> The place of monitor `name` in the series (0: none).
  integer function monitor(flight, name) result(k)
    type(flight_ode_t), intent(in) :: flight
    character(len=*), intent(in) :: name
    do k = 1, flight%series%nm
      if (trim(flight%series%monitor_names(k)) == name) return
    end do
    k = 0
  end function monitor

  subroutine dome_to_floor()
    real(wp), parameter :: e = 0.5_wp, mass = 1.0_wp
    type(input_text_t) :: input
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    type(driver_result_t) :: result
    type(status_t) :: st
    integer, allocatable :: open(:, :)
    real(wp) :: c_l(3), v_l(3), t_l, s1, v1, t_k, v_k, c0, point(3), worst_gap, worst_rest
    integer :: n, lift, closing, k, i, gm
    call load_input_file('inputs/contact/dome_floor.nml', input, st)
    if (st%ok()) call run(input, flight, system, open, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'dome to floor: runs to the end: '//st%text())
    if (.not. st%ok()) return
    call check(index(flight%outcome, 'lift-off: the normal force of contact ''ball_on_dome''') == 1 .and. &
               index(flight%outcome, 'contact ''ball_on_floor'' closed at the impact') > 0, &
               'dome to floor: the outcome says lift-off and closing on the floor: '//flight%outcome)
    associate (s => flight%series)
      n = s%n
      call check(size(open, 1) == 2 .and. size(open, 2) == n, 'dome to floor: open flags of both contacts')
      if (size(open, 2) /= n) return
      lift = count(open(1, :) == 0)
      closing = count(open(2, :) == 1)
      call check(all(open(1, :lift) == 0) .and. all(open(1, lift + 1:) == 1), &
                 'dome to floor: the dome closed, then open for good')
      call check(all(open(2, :closing) == 1) .and. all(open(2, closing + 1:) == 0) .and. closing > lift, &
                 'dome to floor: the floor open, then closed after the lift-off')
      c0 = s%body_r(3, 1, 1)/norm2(s%body_r(:, 1, 1))
      call check_close(s%body_r(3, 1, lift)/norm2(s%body_r(:, 1, lift)), 10.0_wp/17*c0, 1e-7_wp, 0.0_wp, &
                       'dome to floor: lift-off at cos theta = 10/17 cos theta_0')
      t_l = s%time(lift)
      c_l = s%body_r(:, 1, lift)
      v_l = s%body_v(:, 1, lift)
      v1 = sqrt(v_l(3)**2 + 2*g*(c_l(3) - r))
      s1 = (v_l(3) + v1)/g
      call check(size(flight%impacts) == 6, 'dome to floor: six impacts')
      if (size(flight%impacts) /= 6) return
      call check(all(flight%impacts%contact == 2), 'dome to floor: every impact on the floor (contact 2)')
      call check(all(flight%impacts%body_1 == 0) .and. all(flight%impacts%body_2 == 1), &
                 'dome to floor: every impact between the ground (0) and the ball (&body 1)')
      t_k = t_l + s1
      v_k = v1
      do k = 1, 6
        associate (impact => flight%impacts(k))
          call check_close(impact%time, t_k, 0.0_wp, 1e-8_wp, 'dome to floor: impact time (s)')
          ! a height error dz at the landing shifts the approach speed by g dz/v
          call check_close(impact%normal_speed_before, -v_k, 0.0_wp, 1e-8_wp + g*1e-9_wp/v_k, &
                           'dome to floor: approach speed e^(k-1) v_1 (m/s)')
          call check_close(impact%tangential_impulse, 0.0_wp, 0.0_wp, 1e-12_wp, &
                           'dome to floor: frictionless (N s)')
          i = findloc(s%time(:n), impact%time, dim=1)
          point = flight%gap_point(:, 2, i)
          call check_close(norm2(point - [c_l(1:2) + v_l(1:2)*(t_k - t_l), 0.0_wp]), 0.0_wp, 0.0_wp, 1e-8_wp, &
                           'dome to floor: the landing point below the projectile''s centre (m)')
          if (k < 6) then
            call check_close(impact%normal_speed_after, e*v_k, 0.0_wp, 1e-8_wp, 'dome to floor: rebound e v (m/s)')
            call check_close(impact%energy_lost, mass/2*(1 - e**2)*v_k**2, 0.0_wp, 1e-8_wp, &
                             'dome to floor: energy lost m/2 (1 - e^2) v^2 (J)')
          else
            call check_close(impact%normal_speed_after, 0.0_wp, 0.0_wp, 1e-12_wp, &
                             'dome to floor: the closing impact leaves no normal speed (m/s)')
            call check_close(impact%energy_lost, mass/2*v_k**2, 0.0_wp, 1e-8_wp, &
                             'dome to floor: the closing impact takes all of m v^2/2 (J)')
          end if
        end associate
        t_k = t_k + 2*e*v_k/g
        v_k = e*v_k
      end do
      call check(s%time(closing) == flight%impacts(6)%time, 'dome to floor: the flight ends at the closing impact')
      gm = monitor(flight, 'ball_on_floor.gap')
      call check(gm > 0, 'dome to floor: the floor''s gap recorded')
      if (gm == 0) return
      worst_gap = 0
      do i = 1, closing
        worst_gap = max(worst_gap, abs(s%monitor(gm, i) - (s%body_r(3, 1, i) - r)))
      end do
      call check_close(worst_gap, 0.0_wp, 0.0_wp, 1e-12_wp, &
                       'dome to floor: the floor''s gap z - r at every record, on the dome and in flight (m)')
      worst_rest = 0
      do i = closing + 1, n
        worst_rest = max(worst_rest, abs(s%body_r(3, 1, i) - r), norm2(s%body_v(1:2, 1, i) - v_l(1:2)), &
                         abs(s%body_v(3, 1, i)), abs(s%monitor(gm, i)))
      end do
      call check_close(worst_rest, 0.0_wp, 0.0_wp, 1e-8_wp, 'dome to floor: closed, it slides on at height r '// &
                       'with its horizontal velocity from the lift-off (m, m/s)')
    end associate
  end subroutine dome_to_floor

  !> A ball (its lowest point 1 m above the floor) thrown at u = 3 m/s
  !> towards a wall 0.9 m ahead of its centre.
  function wall_input(extra, floor_start) result(text)
    character(len=*), intent(in) :: extra, floor_start
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12, duration = 2, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''wall'', kind = ''plane'', origin = 1, 0, 0, angles_deg = 0, -90, 0 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''ball'', mass = 0.2, solid_of = ''ball'', '//extra//' /'//nl// &
           '&contact name = ''on_wall'', shape_1 = ''wall'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'start = ''open'', restitution = 0.8 /'//nl// &
           '&contact name = ''on_floor'', shape_1 = ''floor'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           floor_start//' /'//nl
  end function wall_input

  subroutine wall_then_floor()
    real(wp), parameter :: u = 3, e_wall = 0.8_wp, e = 0.5_wp, h = 1, x0 = 0
    type(input_text_t) :: input
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    type(driver_result_t) :: result
    type(status_t) :: st
    integer, allocatable :: open(:, :)
    real(wp) :: t_w, t_f, v_f, x_f, worst
    integer :: n, i, closing, gm
    call input_from_text('wall', wall_input('position = 0, 0, 1.1, velocity = 3, 0, 0', &
                                            'start = ''open'', restitution = 0.5, close_speed = 0.1'), input, st)
    if (st%ok()) call run(input, flight, system, open, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'wall then floor: runs to the end: '//st%text())
    if (.not. st%ok()) return
    call check(size(flight%impacts) >= 2, 'wall then floor: impacts on the wall and the floor')
    if (size(flight%impacts) < 2) return
    t_w = (0.9_wp - x0)/u
    t_f = sqrt(2*h/g)
    v_f = g*t_f
    x_f = 0.9_wp - e_wall*u*(t_f - t_w)
    associate (wall => flight%impacts(1), floor => flight%impacts(2), s => flight%series)
      call check(wall%contact == 1 .and. all(flight%impacts(2:)%contact == 2), &
                 'wall then floor: the first impact on the wall, the others on the floor')
      call check_close(wall%time, t_w, 0.0_wp, 1e-10_wp, 'wall then floor: the wall at (0.9 - x_0)/u (s)')
      call check_close(wall%normal_speed_before, -u, 0.0_wp, 1e-10_wp, 'wall then floor: the wall met at u (m/s)')
      call check_close(wall%normal_speed_after, e_wall*u, 0.0_wp, 1e-10_wp, 'wall then floor: rebound e_w u (m/s)')
      call check_close(floor%time, t_f, 0.0_wp, 1e-10_wp, 'wall then floor: the floor at sqrt(2 h/g) (s)')
      call check_close(floor%normal_speed_before, -v_f, 0.0_wp, 1e-9_wp, 'wall then floor: the floor met at g t (m/s)')
      call check_close(floor%normal_speed_after, e*v_f, 0.0_wp, 1e-9_wp, 'wall then floor: rebound e g t (m/s)')
      n = s%n
      i = findloc(s%time(:n), floor%time, dim=1)
      call check_close(norm2(flight%gap_point(:, 2, i) - [x_f, 0.0_wp, 0.0_wp]), 0.0_wp, 0.0_wp, 1e-9_wp, &
                       'wall then floor: the landing point 0.9 - e_w u (t_f - t_w) (m)')
      i = findloc(s%time(:n), wall%time, dim=1)
      call check_close(norm2(flight%gap_point(:, 1, i) - [1.0_wp, 0.0_wp, 1.1_wp - g*t_w**2/2]), 0.0_wp, 0.0_wp, &
                       1e-9_wp, 'wall then floor: the wall hit level with the centre (m)')
      call check(size(open, 2) == n .and. all(open(1, :) == 1), 'wall then floor: the wall open all along')
      closing = count(open(2, :) == 1)
      call check(all(open(2, closing + 1:) == 0) .and. closing < n, 'wall then floor: the floor closed at the end')
      gm = monitor(flight, 'on_wall.gap')
      call check(gm > 0, 'wall then floor: the wall''s gap recorded')
      if (gm == 0) return
      worst = 0
      do i = 1, n
        worst = max(worst, abs(s%monitor(gm, i) - (0.9_wp - s%body_r(1, 1, i))))
      end do
      call check_close(worst, 0.0_wp, 0.0_wp, 1e-12_wp, &
                       'wall then floor: the wall''s gap 0.9 - x at every record, in flight and on the floor (m)')
      call check_close(s%body_v(1, 1, n), -e_wall*u, 0.0_wp, 1e-9_wp, 'wall then floor: it slides away at e_w u (m/s)')
    end associate
  end subroutine wall_then_floor

  subroutine carried_into_a_wall()
    real(wp), parameter :: u = 1, x0 = 0.2_wp, e_wall = 0.8_wp, mass = 0.2_wp
    type(input_text_t) :: input
    type(flight_ode_t), target :: flight
    type(contact_system_t) :: system
    type(driver_result_t) :: result
    type(status_t) :: st
    integer, allocatable :: open(:, :)
    real(wp) :: t_w, worst
    integer :: i
    call input_from_text('carried', wall_input('position = 0.2, 0, 0.1, velocity = 1, 0, 0', &
                                               'start = ''closed'''), input, st)
    if (st%ok()) call run(input, flight, system, open, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'carried into a wall: runs to its end: '// &
               st%text()//' '//flight%outcome)
    if (.not. st%ok()) return
    call check(index(flight%outcome, 'contact ''on_wall'': body ''ball'' touches shape ''wall'' at t = ') == 1 .and. &
               index(flight%outcome, 'while contact ''on_floor'' carries it') > 0 .and. &
               index(flight%outcome, 'one impact at them all, after it ''on_floor'' closed, ''on_wall'' open') > 0, &
               'carried into a wall: the outcome says where and what: '//flight%outcome)
    t_w = (0.9_wp - x0)/u
    call check(size(flight%impacts) == 2, 'carried into a wall: one impact, a row for the wall and the floor')
    if (size(flight%impacts) /= 2) return
    associate (wall => flight%impacts(1), floor => flight%impacts(2))
      call check(wall%contact == 1 .and. floor%contact == 2, 'carried into a wall: the wall''s row, the floor''s')
      call check_close(wall%time, t_w, 0.0_wp, 1e-10_wp, 'carried into a wall: at (0.9 - x_0)/u (s)')
      call check_close(wall%normal_speed_before, -u, 0.0_wp, 1e-10_wp, 'carried into a wall: approach u (m/s)')
      call check_close(wall%normal_speed_after, e_wall*u, 0.0_wp, 1e-10_wp, 'carried into a wall: rebound e u (m/s)')
      call check_close(wall%normal_impulse, mass*(1 + e_wall)*u, 0.0_wp, 1e-10_wp, &
                       'carried into a wall: impulse m (1 + e) u (N s)')
      call check_close(floor%normal_impulse, 0.0_wp, 0.0_wp, 1e-12_wp, &
                       'carried into a wall: the floor takes nothing (its normal across the wall''s)')
      call check_close(wall%energy_lost + floor%energy_lost, (1 - e_wall**2)*mass*u**2/2, 0.0_wp, 1e-12_wp, &
                       'carried into a wall: the impact takes (1 - e^2) m u^2/2 (J)')
    end associate
    worst = 0
    associate (s => flight%series)
      do i = 1, s%n
        if (s%time(i) < t_w) then
          worst = max(worst, abs(s%body_r(1, 1, i) - (x0 + u*s%time(i))))
        else if (s%time(i) > t_w + 1e-9_wp) then   ! (the two records at t_w: before and after)
          worst = max(worst, abs(s%body_r(1, 1, i) - (0.9_wp - e_wall*u*(s%time(i) - t_w))), &
                      abs(s%body_v(1, 1, i) + e_wall*u))
        end if
        worst = max(worst, abs(s%body_r(3, 1, i) - 0.1_wp), abs(s%body_v(3, 1, i)))
      end do
      call check(size(open, 2) == s%n .and. all(open(1, :) == 1) .and. all(open(2, :) == 0), &
                 'carried into a wall: the wall open, the floor closed throughout')
      call check_close(s%time(s%n), 2.0_wp, 0.0_wp, 1e-12_wp, 'carried into a wall: on the floor to the end (s)')
    end associate
    call check_close(worst, 0.0_wp, 0.0_wp, 1e-9_wp, 'carried into a wall: x = 0.9 - e u (t - t_w) after, on the floor')
    print '(a, es10.2)', '  carried into a wall: worst x, v ', worst
  end subroutine carried_into_a_wall

end program test_landing
