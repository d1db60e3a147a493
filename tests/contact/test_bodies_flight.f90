!> Several bodies flying at once (issue 25): two balls dropped on a floor,
!> each with its own contact, restitution and close_speed, bounce in one
!> run (contact_flight: one mechanism, each body's gaps at its own pose,
!> each impact changing its own body's twist only). Against closed forms and
!> against each ball's run alone:
!>   - two_balls: ball a (R 0.1 m, 0.2 kg, spinning, moving sideways) from
!>     h_a = 1 m with e = 0.5, ball b (R 0.05 m, 0.5 kg, moving the other
!>     way) from h_b = 0.6 m with e = 0.8, close_speed 0.1 m/s. Impact k of a
!>     ball meets the floor at v_(k-1) = e^(k-1) v_0 (v_0 = sqrt(2 g h)) and
!>     sends it up at v_k = e v_(k-1): apexes e^(2k) h, flights 2 v_k/g
!>     between impacts, impulse m (v_(k-1) + v_k), energy lost (1 - e^2) of
!>     the normal kinetic energy m v_(k-1)^2/2. a's sixth rebound, e^6 v_0 =
!>     0.069 m/s, is below close_speed: a's contact closes (at t0_a (1 + 2e
!>     (1 - e^5)/(1 - e)) = 1.327 s) while b flies on (contact_bodies; b has
!>     had two impacts by then, four by the end at 2 s), saying so. Each gap
!>     at every record on its ball's closed form (a's until it closes).
!>   - each ball alone (the same input without the other): the same impacts
!>     (a's sixth closes its contact alone: its time and approach speed
!>     compared) and the same motion at the common output times. Rounding
!>     is not reached: the run of two integrates both balls with one step
!>     sequence (CVODE's error test over both), so each ball's free flight,
!>     integrated to rtol = atol = 1e-12, differs from its run alone by the
!>     integration error, not its rounding; each flight is a parabola that
!>     Adams reproduces nearly exactly, and each impact is a root located to
!>     ~1e-14 s: 1e-10 in times (s), speeds and impulses (m/s, N s) and
!>     positions (m), found 5e-13..1e-11; the spin (a free rotation's angles
!>     through chart changes, 37 rad/s) to 1e-10 of |omega|, found 6e-11.
!>   - same_instant: two equal balls dropped from the same height apart
!>     land at the same instant (the same root): two impacts in one event,
!>     each on its own ball, both as one ball's (alike to 1e-12 m/s: the
!>     contact search rounds otherwise at another place).
program test_bodies_flight
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use numerics_event_driver, only: DRIVE_END_TIME, RECORD_OUTPUT
  use contact_flight, only: flight_ode_t, impact_record_t
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, vector_text, run_flight
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity
  ! the balls: radius, mass, height of the lowest point, restitution, start velocity
  real(wp), parameter :: radius(2) = [0.1_wp, 0.05_wp], mass(2) = [0.2_wp, 0.5_wp], height(2) = [1.0_wp, 0.6_wp]
  real(wp), parameter :: restitution(2) = [0.5_wp, 0.8_wp], close_speed = 0.1_wp
  real(wp), parameter :: velocity(3, 2) = reshape([0.3_wp, 0.0_wp, 0.0_wp, 0.0_wp, -0.2_wp, 0.0_wp], [3, 2])
  real(wp), parameter :: spin(3, 2) = reshape([10.0_wp, -20.0_wp, 30.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], [3, 2])
  character(len=*), parameter :: names(2) = ['a', 'b']

  call two_balls()
  call same_instant()
  call finish_tests('test_bodies_flight')

contains

  !> The groups of ball k: its shape, body (at x = k - 1) and contact with the floor.
  function ball_groups(k, lowest) result(text)
    integer, intent(in) :: k
    real(wp), intent(in) :: lowest   ! m, the height of its lowest point
    character(len=:), allocatable :: text
    text = '&shape name = '''//names(k)//''', kind = ''sphere'', radius = '//number(radius(k))//' /'//nl// &
           '&body name = '''//names(k)//''', mass = '//number(mass(k))//', solid_of = '''//names(k)// &
           ''', position = '//number(real(k - 1, wp))//', 0, '//number(radius(k) + lowest)// &
           ', velocity = '//vector_text(velocity(:, k))//', angular_velocity = '//vector_text(spin(:, k))//' /'//nl// &
           '&contact name = '''//names(k)//'_floor'', shape_1 = ''floor'', body_2 = '''//names(k)// &
           ''', shape_2 = '''//names(k)//''', start = ''open'', restitution = '//number(restitution(k))// &
           ', close_speed = '//number(close_speed)//' /'//nl
  end function ball_groups

  function floor_input(balls) result(text)
    character(len=*), intent(in) :: balls
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 2, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl//balls
  end function floor_input

  !> Ball k's closed form: its impact times t(1:n) and speeds v(0:n) (v(j) after impact j).
  subroutine bounces(k, n, t, v)
    integer, intent(in) :: k, n
    real(wp), intent(out) :: t(n), v(0:n)
    integer :: j
    v = [(restitution(k)**j*sqrt(2*g*height(k)), j = 0, n)]
    t(1) = v(0)/g
    do j = 2, n
      t(j) = t(j - 1) + 2*v(j - 1)/g
    end do
  end subroutine bounces

  !> Ball k's gap at time s on its closed form (before its impact n + 1).
  pure real(wp) function gap_at(k, s, t, v) result(gap)
    integer, intent(in) :: k
    real(wp), intent(in) :: s, t(:), v(0:)
    integer :: j
    real(wp) :: since
    j = count(t <= s)
    if (j == 0) then
      gap = height(k) - g*s**2/2
    else
      since = s - t(j)
      gap = v(j)*since - g*since**2/2
    end if
  end function gap_at

  subroutine two_balls()
    type(flight_ode_t), target :: both, alone(2)
    integer :: outcome, k, j, i, m, n_impacts(2), worst_index
    real(wp) :: t_a(6), v_a(0:6), t_b(4), v_b(0:4), worst_gap(2), worst_alone(2), worst_spin(2), worst_impact(2), &
                t_stop
    type(impact_record_t), allocatable :: rows(:)
    call run_flight(floor_input(ball_groups(1, height(1))//ball_groups(2, height(2))), 'two balls', both, 2.0_wp, &
                    outcome)
    call check(outcome == DRIVE_END_TIME, 'two balls: the run goes on to its end (a at rest beside b flying)')
    call check(index(both%outcome, 'contact ''a_floor'' closed at the impact') > 0, &
               'two balls: the outcome says a''s contact closed: '//both%outcome)
    call bounces(1, 6, t_a, v_a)
    call bounces(2, 4, t_b, v_b)
    t_stop = t_a(6)
    call check_close(t_stop, sqrt(2*height(1)/g)*(1 + 2*restitution(1)*(1 - restitution(1)**5)/(1 - restitution(1))), &
                     0.0_wp, 1e-12_wp, 'two balls: (the closed form: a''s sixth impact at the partial Zeno sum)')
    n_impacts = [count(both%impacts%body_2 == 1), count(both%impacts%body_2 == 2)]
    call check(all(n_impacts == [6, 4]) .and. size(both%impacts) == 10, 'two balls: six impacts of a, four of b')
    if (.not. all(n_impacts == [6, 4])) return
    call check(all(both%impacts%body_1 == 0), 'two balls: every impact with the ground (body_1 0)')
    call check(all(both%impacts(2:)%time >= both%impacts(:9)%time), 'two balls: the impacts in time order')
    ! each ball against its closed form
    do k = 1, 2
      rows = pack(both%impacts, both%impacts%body_2 == k)
      call check(all(rows%contact == k), 'two balls: ball '//names(k)//'''s impacts on its own contact')
      do j = 1, size(rows)
        associate (row => rows(j))
          if (k == 1 .and. j == 6) then
            ! the closing: a plastic impact, all of the normal kinetic energy
            call check_close(row%time, t_a(j), 0.0_wp, 1e-9_wp, 'two balls: a''s closing impact time (s)')
            call check_close(row%normal_speed_after, 0.0_wp, 0.0_wp, 1e-12_wp, 'two balls: a''s closing: no '// &
                             'rebound (m/s)')
            call check_close(row%normal_impulse, mass(k)*v_a(j - 1), 0.0_wp, 1e-9_wp, 'two balls: a''s closing '// &
                             'impulse m v_5 (N s)')
            call check_close(row%energy_lost, mass(k)*v_a(j - 1)**2/2, 0.0_wp, 1e-9_wp, 'two balls: a''s closing '// &
                             'takes all its normal kinetic energy (J)')
          else if (k == 1) then
            call check_impact(row, k, t_a(j), v_a(j - 1), v_a(j))
          else
            call check_impact(row, k, t_b(j), v_b(j - 1), v_b(j))
          end if
        end associate
      end do
    end do
    associate (s => both%series)
      call check(s%nb == 2 .and. s%body_names(1) == 'a' .and. s%body_names(2) == 'b', 'two balls: both bodies recorded')
      call check_close(s%time(s%n), 2.0_wp, 0.0_wp, 1e-12_wp, 'two balls: the run ends at its end time (s)')
      worst_gap = 0
      do i = 1, s%n
        ! a's gap 0 from its closing on (its closed form: at rest)
        if (s%time(i) <= t_stop) then
          worst_gap(1) = max(worst_gap(1), abs(s%monitor(1, i) - gap_at(1, s%time(i), t_a(:5), v_a)))
        else
          worst_gap(1) = max(worst_gap(1), abs(s%monitor(1, i)))
        end if
        worst_gap(2) = max(worst_gap(2), abs(s%monitor(2, i) - gap_at(2, s%time(i), t_b, v_b)))
      end do
      call check(s%monitor_names(1) == 'a_floor.gap' .and. s%monitor_names(2) == 'b_floor.gap', &
                 'two balls: each contact''s gap recorded')
      do k = 1, 2
        call check_close(worst_gap(k), 0.0_wp, 0.0_wp, 1e-9_wp, 'two balls: ball '//names(k)//'''s gap at every '// &
                         'record on its closed-form bounces, apexes e^(2k) h (m)')
      end do
    end associate
    ! each ball alone
    call run_flight(floor_input(ball_groups(1, height(1))), 'a alone', alone(1), 2.0_wp, outcome)
    call run_flight(floor_input(ball_groups(2, height(2))), 'b alone', alone(2), 2.0_wp, outcome)
    worst_impact = 0
    do k = 1, 2
      rows = pack(both%impacts, both%impacts%body_2 == k)
      associate (one => alone(k)%impacts)
        call check(size(one) >= size(rows), 'ball '//names(k)//' alone: at least its impacts in the run of two')
        if (size(one) < size(rows)) cycle
        do j = 1, size(rows)
          worst_impact(k) = max(worst_impact(k), abs(rows(j)%time - one(j)%time), &
                                abs(rows(j)%normal_speed_before - one(j)%normal_speed_before))
          if (k == 1 .and. j == 6) cycle   ! alone, a's sixth closes its contact (plastic)
          worst_impact(k) = max(worst_impact(k), abs(rows(j)%normal_speed_after - one(j)%normal_speed_after), &
                                abs(rows(j)%normal_impulse - one(j)%normal_impulse), &
                                abs(rows(j)%tangential_impulse - one(j)%tangential_impulse), &
                                abs(rows(j)%energy_lost - one(j)%energy_lost))
        end do
      end associate
      call check_close(worst_impact(k), 0.0_wp, 0.0_wp, 1e-10_wp, 'ball '//names(k)//': its impacts in the run of '// &
                       'two as in its run alone (s, m/s, N s, J)')
      ! the motion at the output times both runs share
      worst_alone(k) = 0
      worst_spin(k) = 0
      m = 0
      associate (s => both%series, s1 => alone(k)%series)
        do i = 1, s%n
          if (s%kind(i) /= RECORD_OUTPUT) cycle
          worst_index = findloc(s1%time(:s1%n), s%time(i), dim=1)
          if (worst_index == 0) cycle
          m = m + 1
          worst_alone(k) = max(worst_alone(k), maxval(abs(s%body_r(:, k, i) - s1%body_r(:, 1, worst_index))), &
                               maxval(abs(s%body_v(:, k, i) - s1%body_v(:, 1, worst_index))))
          worst_spin(k) = max(worst_spin(k), maxval(abs(s%body_omega(:, k, i) - s1%body_omega(:, 1, worst_index))))
        end do
      end associate
      call check(m >= 130, 'ball '//names(k)//': the runs share the output times up to the stop')
      call check_close(worst_alone(k), 0.0_wp, 0.0_wp, 1e-10_wp, 'ball '//names(k)//': its motion in the run of '// &
                       'two as alone at every shared output time (m, m/s)')
      call check_close(worst_spin(k), 0.0_wp, 0.0_wp, 1e-10_wp*max(norm2(spin(:, k)), 1.0_wp), 'ball '//names(k)// &
                       ': its angular velocity in the run of two as alone (rad/s, 1e-10 of |omega|)')
      print '(a, 3es10.3)', '  ball '//names(k)//' against alone: impacts, motion, spin ', worst_impact(k), &
        worst_alone(k), worst_spin(k)
    end do
  end subroutine two_balls

  !> Impact `row` of ball k: at t, approaching at v_before, leaving at v_after
  !> (frictionless: no tangential impulse), m (v_before + v_after), energy
  !> lost (1 - e^2) m v_before^2/2.
  subroutine check_impact(row, k, t, v_before, v_after)
    type(impact_record_t), intent(in) :: row
    integer, intent(in) :: k
    real(wp), intent(in) :: t, v_before, v_after
    character(len=:), allocatable :: label
    label = 'two balls: ball '//names(k)//', '
    call check_close(row%time, t, 0.0_wp, 1e-9_wp, label//'impact time after flights 2 v_k/g (s)')
    call check_close(row%normal_speed_before, -v_before, 0.0_wp, 1e-9_wp, label//'approach speed e^(k-1) v0 (m/s)')
    call check_close(row%normal_speed_after, v_after, 0.0_wp, 1e-9_wp, label//'rebound e^k v0 (m/s)')
    call check_close(row%normal_impulse, mass(k)*(v_before + v_after), 0.0_wp, 1e-9_wp, &
                     label//'normal impulse m (v_(k-1) + v_k) (N s)')
    call check_close(row%tangential_impulse, 0.0_wp, 0.0_wp, 1e-12_wp, label//'no tangential impulse (N s)')
    call check_close(row%energy_lost, (1 - restitution(k)**2)*mass(k)*v_before**2/2, 0.0_wp, 1e-9_wp, &
                     label//'energy lost (1 - e^2) of the normal kinetic energy (J)')
  end subroutine check_impact

  !> Two balls a, alike but for their place (a's input twice, x = 0 and 1),
  !> from the same height: both land at t0 in one event, two impacts.
  subroutine same_instant()
    type(flight_ode_t), target :: flight
    integer :: outcome
    character(len=:), allocatable :: second
    real(wp) :: t(2), v(0:2)
    second = ball_groups(1, height(1))
    second = replace_all(second, '''a''', '''twin''')
    second = replace_all(second, '''a_floor''', '''twin_floor''')
    second = replace_all(second, 'position = '//number(0.0_wp), 'position = '//number(1.0_wp))
    call run_flight(floor_input(ball_groups(1, height(1))//second), 'same instant', flight, 1.0_wp, outcome)
    call check(outcome == DRIVE_END_TIME, 'same instant: runs to the end (1 s, before any rebound is slow): '// &
               flight%outcome)
    call bounces(1, 2, t, v)
    call check(size(flight%impacts) == 4, 'same instant: two impacts of each ball by 1 s')
    if (size(flight%impacts) /= 4) return
    call check(all(flight%impacts%body_2 == [1, 2, 1, 2]), 'same instant: a and twin at each landing')
    call check(flight%impacts(1)%time == flight%impacts(2)%time .and. flight%impacts(3)%time == &
               flight%impacts(4)%time, 'same instant: both impacts in one event')
    call check_close(flight%impacts(2)%time, t(1), 0.0_wp, 1e-9_wp, 'same instant: at t0 = sqrt(2 h/g) (s)')
    call check_close(flight%impacts(4)%time, t(2), 0.0_wp, 1e-9_wp, 'same instant: again 2 e v0/g later (s)')
    call check_close(maxval(abs(flight%impacts(2:4:2)%normal_speed_after - v(1:2))), 0.0_wp, 0.0_wp, 1e-9_wp, &
                     'same instant: twin leaves at e^k v0 (m/s)')
    ! the contact search at x = 1 rounds otherwise than at x = 0
    call check_close(maxval(abs(flight%impacts(1:3:2)%normal_speed_after - flight%impacts(2:4:2)%normal_speed_after)), &
                     0.0_wp, 0.0_wp, 1e-12_wp, 'same instant: each impact on its own ball, both alike (m/s)')
  end subroutine same_instant

  function replace_all(text, old, new) result(changed)
    character(len=*), intent(in) :: text, old, new
    character(len=:), allocatable :: changed
    integer :: at
    changed = text
    do
      at = index(changed, old)
      if (at == 0) return
      changed = changed(:at - 1)//new//changed(at + len(old):)
    end do
  end function replace_all
end program test_bodies_flight
