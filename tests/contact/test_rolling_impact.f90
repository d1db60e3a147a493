!> An impact through a rolling contact that carries a body (issue 25,
!> docs/contact.md "A hit on a carried body"): the rolling contact takes
!> part in the impact with its normal row (restitution 0: it stays closed,
!> P_n >= 0) and its two tangential rows as no-slip equalities (its
!> relative velocity after the impact is 0; no cone). Each case runs the
!> contact scenario through the impact and checks it against its closed
!> form: the impacts table's rows (impulses, speeds, energies), the twists
!> after it and the energy.
!>
!>   - hit_box: a box (M, centre at height z_c, lid at z_l) on two
!>     frictionless feet at rest, a ball (m, R, I = 2/5 m R^2) at rest
!>     rolling on its lid, a hammer (m_h, a sphere) flying along -x hits
!>     the box's front face (frictionless, restitution e). The impulse P
!>     on the hammer along +x, -P on the box; Q the lid's tangential
!>     impulse on the ball along x (-Q on the box). The ball: m v = Q,
!>     I omega_y = -R Q (the impulse at its lowest point, -R z from its
!>     centre), so its lowest point moves at v - R omega_y = Q (1/m +
!>     R^2/I) = 7 Q/(2 m); no slip after the impact: that is the box's
!>     V, Q = (2 m/7) V: the ball meets the box with its effective mass
!>     2 m/7. The box: M V = -P - Q, V = -P/M_e with M_e = M + 2 m/7. The
!>     hammer (u its approach speed): m_h (u_h + u) = P, and Newton's
!>     restitution on the face u_h - V = e u give P = (1 + e) u mu_e,
!>     mu_e = m_h M_e/(m_h + M_e); the energy lost (1 - e^2) mu_e u^2/2
!>     (the ball's kinetic energy m v^2/2 + I omega^2/2 = (2 m/7) V^2/2),
!>     all in the hammer's row, the lid's and the feet's rows 0 (their
!>     velocities before and after 0); e = 1 keeps the energy. The box
!>     does not pitch (the feet's impulses 0) when the angular impulses
!>     about its centre cancel: P (z_h - z_c) = -Q (z_l - z_c), the
!>     hammer hitting at z_h = z_c + (z_l - z_c) (2 m/7)/M_e. After it the
!>     ball rolls on the box without slip, both at constant speeds (no
!>     horizontal force), the hammer flies back.
!>   - rolls_into_wall: a ball (m, R) rolling on the floor (a rolling
!>     contact with the ground) at v into a frictionless wall (restitution
!>     e) with its centre's height: the ball pivots about its floor point,
!>     its effective mass at the centre I_0/R^2 = 7 m/5; the wall's
!>     impulse P = (1 + e) (7 m/5) v, the ball rolls back at -e v (omega =
!>     -e v/R), the floor's tangential impulse Q = P - (1 + e) m v = (2/5)
!>     (1 + e) m v, its normal impulse 0; the energy lost (1 - e^2) (7
!>     m/5) v^2/2, all in the wall's row.
!>   - lifted: a ball (m, R) at rest rolling on the floor (may_open) hit
!>     below its centre by a hammer (m_h) flying along +x: the stick would
!>     pull the ball down, so the floor's contact takes no impulse at all
!>     (its rows 0, its tangential impulse 0) and opens; the hit is the
!>     free pair's along the line of the centres n (frictionless, through
!>     the ball's centre: no spin), P = (1 + e) u_n m m_h/(m + m_h), u_n
!>     the hammer's approach along n at the hit; the ball flies off at P
!>     n/m. Without may_open the run stops there saying the impact would
!>     lift the floor's contact off.
!>   - no_slip_law: resolve_impacts' no-slip contact itself. One contact
!>     with W = [1 0 b; 0 1 0; b 0 1] (b = 0.9, n = z) and c = (-1, 0,
!>     c_n): the stick P = -W^-1 c has n.P = -(b + c_n)/(1 - b^2), pushing
!>     for c_n = -1 (it holds: v+ = 0, P = (1 - b) (1, 0, 1)/(1 - b^2)),
!>     pulling for c_n = -0.1
!>     (its points would approach without it: refused, "would have to
!>     pull") and for c_n = 0.1 (they move apart: no impulse, v+ = c). And
!>     400 random impacts at two and three contacts (W = A A^T + I/10,
!>     random normals and velocities, e in {0, 0.5}), the first contact
!>     no-slip, the others frictionless: after each resolved one the
!>     no-slip contact holds (v+ = 0, n.P >= 0) or is left apart with no
!>     impulse (P = 0, n.v+ >= 0), the others' normal complementarity, v+ =
!>     v- + W P, the energy's fall >= 0 at e = 0.
!> Before the rolling carrying contact took part the runs ended at the
!> impact (exit 2, "an impact through a rolling contact is not built").
program test_rolling_impact
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use numerics_event_driver, only: driver_result_t, DRIVE_END_TIME
  use kinetostatics_recorder, only: mechanism_series_t
  use contact_flight, only: flight_ode_t
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, run_contact_text, random_impact
  use kinetostatics_point_impacts, only: resolve_impacts
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity
  ! rtol 1e-9: the impact's Gauss-Seidel settles to 1e-14 of the largest impulse, the run's rtol 1e-12
  real(wp), parameter :: rtol = 1e-9_wp
  ! hit_box's: the box, ball and hammer (kg, m), the hammer's speed and gap to the face (m/s, m), the box's centre
  ! and lid heights (m)
  real(wp), parameter :: mb = 2, m = 0.3_wp, r = 0.05_wp, mh = 0.5_wp, rh = 0.03_wp, u = 1, gap = 0.02_wp
  real(wp), parameter :: z_c = 0.12_wp, z_l = 0.17_wp
  real(wp), parameter :: box_inertia(3) = [0.0216666666666667_wp, 0.0333333333333333_wp, 0.0416666666666667_wp]

  call hit_box(0.5_wp, 'hit box (e = 0.5)')
  call hit_box(1.0_wp, 'hit box (e = 1)')
  call rolls_into_wall(0.8_wp)
  call lifted(.true.)
  call lifted(.false.)
  call no_slip_law()
  call finish_tests('test_rolling_impact')

contains

  !> hit_box (program comment): M = 2 kg, m = 0.3 kg, R = 0.05 m, m_h =
  !> 0.5 kg (R_h = 0.03 m) at u = 1 m/s, restitution e; 0.1 s.
  subroutine hit_box(e, label)
    real(wp), intent(in) :: e
    character(len=*), intent(in) :: label
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    character(len=:), allocatable :: text
    real(wp) :: me, mue, p, q, v_box, t_hit, z_h, e_before, e_after, worst, fall
    integer :: i, i1, box, ball, hammer, k
    integer, parameter :: rear = 1, front = 2, lid = 3, face = 4
    me = mb + 2*m/7
    mue = mh*me/(mh + me)
    p = (1 + e)*u*mue
    v_box = -p/me
    q = 2*m*v_box/7
    t_hit = gap/u
    z_h = z_c + (z_l - z_c)*(2*m/7)/me
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 0.1, output_step = 0.002 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''rear'', kind = ''sphere'', radius = 0.02, origin = -0.2, 0, -0.1 /'//nl// &
           '&shape name = ''front'', kind = ''sphere'', radius = 0.02, origin = 0.2, 0, -0.1 /'//nl// &
           '&shape name = ''lid'', kind = ''plane'', origin = 0, 0, 0.05 /'//nl// &
           '&shape name = ''face'', kind = ''plane'', origin = 0.25, 0, 0, angles_deg = 0, 90, 0 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = '//number(r)//' /'//nl// &
           '&shape name = ''hammer'', kind = ''sphere'', radius = '//number(rh)//' /'//nl// &
           '&body name = ''box'', mass = '//number(mb)//', inertia = '//number(box_inertia(1))//', '// &
           number(box_inertia(2))//', '//number(box_inertia(3))//', position = 0, 0, '//number(z_c)//' /'//nl// &
           '&body name = ''ball'', mass = '//number(m)//', solid_of = ''ball'', position = 0, 0, '// &
           number(z_l + r)//' /'//nl// &
           '&body name = ''hammer'', mass = '//number(mh)//', solid_of = ''hammer'', position = '// &
           number(0.25_wp + rh + gap)//', 0, '//number(z_h + g*t_hit**2/2)//', velocity = '//number(-u)// &
           ', 0, 0 /'//nl// &
           '&contact name = ''rear_on_floor'', shape_1 = ''floor'', body_2 = ''box'', shape_2 = ''rear'' /'//nl// &
           '&contact name = ''front_on_floor'', shape_1 = ''floor'', body_2 = ''box'', shape_2 = ''front'' /'//nl// &
           '&contact name = ''ball_on_box'', body_1 = ''box'', shape_1 = ''lid'', body_2 = ''ball'', '// &
           'shape_2 = ''ball'', rolling = .true. /'//nl// &
           '&contact name = ''hammer_on_box'', body_1 = ''box'', shape_1 = ''face'', body_2 = ''hammer'', '// &
           'shape_2 = ''hammer'', start = ''open'', restitution = '//number(e)//' /'//nl
    call run_contact_text(text, label, flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//': runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check(size(flight%impacts) == 4, label//': one impact, a row at each of the four contacts: '// &
               number(real(size(flight%impacts), wp)))
    if (size(flight%impacts) /= 4) return
    call check(all(flight%impacts%contact == [rear, front, lid, face]), label//': the rows in the contacts'' order')
    associate (hit => flight%impacts(face), rolled => flight%impacts(lid))
      call check_close(hit%time, t_hit, 0.0_wp, 1e-10_wp, label//': the hit at gap/u (s)')
      call check_close(hit%normal_speed_before, -u, rtol, 0.0_wp, label//': the hammer approaches at u (m/s)')
      call check_close(hit%normal_speed_after, e*u, rtol, 0.0_wp, label//': it leaves the face at e u (m/s)')
      call check_close(hit%normal_impulse, p, rtol, 0.0_wp, label//': P = (1 + e) u mu_e (N s)')
      call check_close(hit%tangential_impulse, 0.0_wp, 0.0_wp, rtol*p, label//': frictionless (N s)')
      call check_close(hit%energy_lost, (1 - e**2)*mue*u**2/2, rtol, rtol*mue*u**2, label//': the hammer''s '// &
                       'row (1 - e^2) mu_e u^2/2 (J)')
      call check_close(rolled%tangential_impulse, abs(q), rtol, 0.0_wp, label//': the lid''s tangential impulse '// &
                       '(2 m/7) |V| (N s)')
      worst = maxval(abs([rolled%normal_impulse, flight%impacts(rear)%normal_impulse, &
                          flight%impacts(front)%normal_impulse]))
      call check_close(worst, 0.0_wp, 0.0_wp, rtol*p, label//': the lid''s and the feet''s normal impulses 0 '// &
                       '(no pitch) (N s)')
      worst = maxval(abs([(flight%impacts(k)%energy_lost, flight%impacts(k)%normal_speed_before, &
                           flight%impacts(k)%normal_speed_after, k = 1, 3)]))
      call check_close(worst, 0.0_wp, 0.0_wp, rtol*u, label//': the carrying rows'' speeds and energies 0 '// &
                       '(m/s, J)')
    end associate
    associate (s => flight%series)
      box = findloc(s%body_names, 'box', dim=1)
      ball = findloc(s%body_names, 'ball', dim=1)
      hammer = findloc(s%body_names, 'hammer', dim=1)
      call check(box > 0 .and. ball > 0 .and. hammer > 0, label//': the bodies recorded')
      if (box == 0 .or. ball == 0 .or. hammer == 0) return
      ! the record after the impact: the second of the two at its time
      i1 = findloc([(i > 1 .and. s%time(i) == flight%impacts(face)%time .and. s%time(max(i - 1, 1)) == s%time(i), i = 1, s%n)], &
                   .true., dim=1)
      call check(i1 > 0, label//': two records at the impact, the second after it')
      if (i1 == 0) return
      e_before = energy(s, i1 - 1, box, ball, hammer)
      e_after = energy(s, i1, box, ball, hammer)
      fall = sum(flight%impacts%energy_lost)
      call check_close(e_before - e_after, fall, 0.0_wp, rtol*e_before, label//': the energy''s fall the rows'' '// &
                       'sum (J)')
      if (e >= 1) call check_close(fall, 0.0_wp, 0.0_wp, rtol*e_before, label//': e = 1 keeps the energy (J)')
      ! from the impact to the end: the box and the ball at their speeds after it, rolling, the hammer flying
      worst = 0
      do i = i1, s%n
        worst = max(worst, norm2(s%body_v(:, box, i) - [v_box, 0.0_wp, 0.0_wp]), norm2(s%body_omega(:, box, i)), &
                    norm2(s%body_v(:, ball, i) - [2*v_box/7, 0.0_wp, 0.0_wp]), &
                    r*norm2(s%body_omega(:, ball, i) - [0.0_wp, -5*v_box/(7*r), 0.0_wp]), &
                    abs(s%body_v(1, hammer, i) - (-u + p/mh)), abs(s%body_v(3, hammer, i) + g*s%time(i)), &
                    abs(s%body_r(3, ball, i) - z_l - r), abs(s%body_r(3, box, i) - z_c))
        worst = max(worst, abs(energy(s, i, box, ball, hammer) - e_after)/e_after)
      end do
      call check_close(worst, 0.0_wp, 0.0_wp, rtol, label//': after it the box at -P/M_e, the ball at 2 V/7 '// &
                       'rolling on the lid (omega_y -5 V/(7 R)), the hammer at -u + P/m_h, the energy kept (m/s, '// &
                       'relative)')
      print '(a, 2es10.2)', '  '//label//': after, energy fall ', worst, e_before - e_after - fall
    end associate
  end subroutine hit_box

  !> hit_box's bodies' kinetic and potential energy at record i of s (J).
  real(wp) function energy(s, i, box, ball, hammer)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: i, box, ball, hammer
    energy = mb*sum(s%body_v(:, box, i)**2)/2 + m*sum(s%body_v(:, ball, i)**2)/2 + &
             (2*m*r**2/5)*sum(s%body_omega(:, ball, i)**2)/2 + mh*sum(s%body_v(:, hammer, i)**2)/2 + &
             (2*mh*rh**2/5)*sum(s%body_omega(:, hammer, i)**2)/2 + &
             g*(mb*s%body_r(3, box, i) + m*s%body_r(3, ball, i) + mh*s%body_r(3, hammer, i))
  end function energy

  !> rolls_into_wall (program comment): m = 0.2 kg, R = 0.1 m, v = 1 m/s,
  !> the wall 0.7 m ahead; 1 s.
  subroutine rolls_into_wall(e)
    real(wp), intent(in) :: e
    real(wp), parameter :: m = 0.2_wp, r = 0.1_wp, v = 1   ! its own ball's (kg, m, m/s)
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    character(len=:), allocatable :: text, label
    real(wp) :: p, worst, t_hit
    integer :: i, ball
    integer, parameter :: wall = 1, floor = 2
    label = 'rolls into wall'
    p = (1 + e)*(7*m/5)*v
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 1, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''wall'', kind = ''plane'', origin = 1, 0, 0, angles_deg = 0, -90, 0 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = '//number(r)//' /'//nl// &
           '&body name = ''ball'', mass = '//number(m)//', solid_of = ''ball'', position = 0.2, 0, '// &
           number(r)//', velocity = '//number(v)//', 0, 0, angular_velocity = 0, '//number(v/r)//', 0 /'//nl// &
           '&contact name = ''on_wall'', shape_1 = ''wall'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'start = ''open'', restitution = '//number(e)//' /'//nl// &
           '&contact name = ''on_floor'', shape_1 = ''floor'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'rolling = .true. /'//nl
    call run_contact_text(text, label, flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//': runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check(size(flight%impacts) == 2, label//': one impact, the wall''s row and the floor''s')
    if (size(flight%impacts) /= 2) return
    associate (hit => flight%impacts(wall), rolled => flight%impacts(floor))
      call check(hit%contact == wall .and. rolled%contact == floor, label//': the rows in the contacts'' order')
      call check_close(hit%time, 0.7_wp/v, 0.0_wp, 1e-10_wp, label//': the hit after 0.7 m (s)')
      call check_close(hit%normal_speed_after, e*v, rtol, 0.0_wp, label//': the rebound e v (m/s)')
      call check_close(hit%normal_impulse, p, rtol, 0.0_wp, label//': the wall''s P = (1 + e) (7 m/5) v (N s)')
      call check_close(hit%energy_lost, (1 - e**2)*(7*m/5)*v**2/2, rtol, 0.0_wp, label//': its row (1 - e^2) '// &
                       '(7 m/5) v^2/2 (J)')
      call check_close(rolled%tangential_impulse, 2*(1 + e)*m*v/5, rtol, 0.0_wp, label//': the floor''s '// &
                       'tangential impulse (2/5) (1 + e) m v (N s)')
      call check_close(abs(rolled%normal_impulse) + abs(rolled%energy_lost), 0.0_wp, 0.0_wp, rtol*p, label// &
                       ': the floor''s normal impulse and energy 0 (N s, J)')
    end associate
    associate (s => flight%series)
      ball = findloc(s%body_names, 'ball', dim=1)
      t_hit = flight%impacts(wall)%time
      worst = 0
      do i = 1, s%n
        if (s%time(i) < t_hit) cycle
        if (s%time(i) == t_hit .and. s%time(min(i + 1, s%n)) == s%time(i)) cycle   ! the record before it
        worst = max(worst, norm2(s%body_v(:, ball, i) - [-e*v, 0.0_wp, 0.0_wp]), &
                    r*norm2(s%body_omega(:, ball, i) - [0.0_wp, -e*v/r, 0.0_wp]), abs(s%body_r(3, ball, i) - r), &
                    abs(s%body_r(1, ball, i) - (0.9_wp - e*v*(s%time(i) - t_hit))))
      end do
      call check_close(worst, 0.0_wp, 0.0_wp, rtol*v, label//': after it rolling back at -e v, omega_y -e v/R '// &
                       '(m/s, m)')
      print '(a, es10.2)', '  '//label//': after ', worst
    end associate
  end subroutine rolls_into_wall

  !> lifted (program comment): m = 0.2 kg, R = 0.1 m; m_h = 0.1 kg (R_h =
  !> 0.03 m) from 0.15 m behind at u = 2 m/s, its centre 0.05 m up; e =
  !> 0.8; 0.05 s (the ball in flight to the end). `may_open`: the floor's.
  subroutine lifted(may_open)
    logical, intent(in) :: may_open
    real(wp), parameter :: m = 0.2_wp, r = 0.1_wp, mh = 0.1_wp, rh = 0.03_wp, u = 2, e = 0.8_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    character(len=:), allocatable :: text, label, opens
    real(wp) :: t, n(3), un, p, worst, dt
    integer :: i, ball
    integer, parameter :: floor = 1, hit = 2
    label = 'lifted'
    opens = ', restitution = 0.5, may_open = .true.'   ! it may land again
    if (.not. may_open) label = 'lifted, no may_open'
    if (.not. may_open) opens = ''
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 0.05, output_step = 0.005 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = '//number(r)//' /'//nl// &
           '&shape name = ''hammer'', kind = ''sphere'', radius = '//number(rh)//' /'//nl// &
           '&body name = ''ball'', mass = '//number(m)//', solid_of = ''ball'', position = 0, 0, '//number(r)// &
           ' /'//nl// &
           '&body name = ''hammer'', mass = '//number(mh)//', solid_of = ''hammer'', position = -0.15, 0, 0.05, '// &
           'velocity = '//number(u)//', 0, 0 /'//nl// &
           '&contact name = ''on_floor'', shape_1 = ''floor'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'rolling = .true.'//opens//' /'//nl// &
           '&contact name = ''hit'', body_1 = ''hammer'', shape_1 = ''hammer'', body_2 = ''ball'', '// &
           'shape_2 = ''ball'', start = ''open'', restitution = '//number(e)//' /'//nl
    call run_contact_text(text, label, flight, result, st)
    if (.not. may_open) then
      call check(.not. st%ok(), label//': the run fails')
      if (.not. allocated(flight%outcome)) flight%outcome = st%text()
      call check(index(flight%outcome, 'would lift ''on_floor'' off, which may not open') > 0 .and. &
                 size(flight%impacts) == 0, label//': the run stops at the hit, saying the floor''s contact may '// &
                 'not open: '//flight%outcome)
      return
    end if
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//': runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check(size(flight%impacts) == 2 .and. index(flight%outcome, '''on_floor'', ''hit'' open') > 0, label// &
               ': one impact, the floor''s contact and the hit left open: '//flight%outcome)
    if (size(flight%impacts) /= 2) return
    ! the pair's law along the line of the centres at the hit
    t = flight%impacts(hit)%time
    n = [0.0_wp, 0.0_wp, r] - [-0.15_wp + u*t, 0.0_wp, 0.05_wp - g*t**2/2]
    call check_close(norm2(n), r + rh, 0.0_wp, 1e-10_wp, label//': the hit where the centres are R + R_h apart (m)')
    n = n/norm2(n)
    un = dot_product(n, [u, 0.0_wp, -g*t])
    p = (1 + e)*un*m*mh/(m + mh)
    associate (hitting => flight%impacts(hit), rolled => flight%impacts(floor))
      call check_close(hitting%normal_impulse, p, rtol, 0.0_wp, label//': P = (1 + e) u_n m m_h/(m + m_h) (N s)')
      call check_close(hitting%normal_speed_after, e*un, rtol, 0.0_wp, label//': the hit''s rebound e u_n (m/s)')
      call check_close(hitting%energy_lost, (1 - e**2)*m*mh/(m + mh)*un**2/2, rtol, 0.0_wp, label//': its row''s '// &
                       'energy (1 - e^2) of the pair''s (J)')
      call check(rolled%normal_impulse == 0 .and. rolled%tangential_impulse == 0 .and. rolled%energy_lost == 0, &
                 label//': the floor''s contact takes no impulse')
      call check_close(rolled%normal_speed_after, p*n(3)/m, rtol, 0.0_wp, label//': the ball leaves the floor at '// &
                       'P n_z/m (m/s)')
    end associate
    associate (s => flight%series)
      ball = findloc(s%body_names, 'ball', dim=1)
      worst = 0
      do i = 1, s%n
        if (s%time(i) <= t) cycle
        dt = s%time(i) - t
        worst = max(worst, norm2(s%body_v(:, ball, i) - (p*n/m - [0.0_wp, 0.0_wp, g*dt])), &
                    r*norm2(s%body_omega(:, ball, i)), &
                    norm2(s%body_r(:, ball, i) - ([0.0_wp, 0.0_wp, r] + p*n/m*dt - [0.0_wp, 0.0_wp, g*dt**2/2])))
      end do
      call check_close(worst, 0.0_wp, 0.0_wp, rtol*u, label//': the ball flies off at P n/m, no spin (m/s, m)')
      print '(a, es10.2)', '  '//label//': flight ', worst
    end associate
  end subroutine lifted

  !> no_slip_law (program comment).
  subroutine no_slip_law()
    real(wp), parameter :: b = 0.9_wp, tol = 1e-9_wp   ! relative to the speeds (the sweeps settle to 1e-14)
    integer, parameter :: cases = 400
    real(wp) :: w1(3, 3), p1(3, 1), after1(3, 1), lost1(1), stick(3), worst
    real(wp), allocatable :: w(:, :), normals(:, :), v(:, :), p(:, :), after(:, :), lost(:), e(:), mu(:)
    real(wp) :: vn, pn, scale
    logical, allocatable :: no_slip(:)
    integer :: k, m, i, held, apart, refused, seed_size
    integer, allocatable :: seed(:)
    type(status_t) :: st
    w1 = reshape([1.0_wp, 0.0_wp, b, 0.0_wp, 1.0_wp, 0.0_wp, b, 0.0_wp, 1.0_wp], [3, 3])
    ! pushing: it holds
    call resolve_impacts(w1, reshape([0.0_wp, 0.0_wp, 1.0_wp], [3, 1]), reshape([-1.0_wp, 0.0_wp, -1.0_wp], [3, 1]), &
                         [0.0_wp], [0.0_wp], p1, after1, lost1, st, [.true.])
    stick = [(1 - b), 0.0_wp, (1 - b)]/(1 - b**2)   ! -W^-1 c for c = (-1, 0, -1)
    call check(st%ok(), 'no-slip law: a pushing stick resolved: '//st%text())
    call check_close(norm2(p1(:, 1) - stick) + norm2(after1), 0.0_wp, 0.0_wp, 1e-14_wp, 'no-slip law: it holds, '// &
                     'P = -W^-1 c, v+ = 0 (N s, m/s)')
    ! pulling, its points approaching without it: refused
    st = status_t()
    call resolve_impacts(w1, reshape([0.0_wp, 0.0_wp, 1.0_wp], [3, 1]), reshape([-1.0_wp, 0.0_wp, -0.1_wp], [3, 1]), &
                         [0.0_wp], [0.0_wp], p1, after1, lost1, st, [.true.])
    call check(.not. st%ok() .and. index(st%text(), 'would have to pull') > 0, 'no-slip law: a contact that would '// &
               'pull with its points approaching refused: '//st%text())
    ! pulling, its points moving apart: no impulse
    st = status_t()
    call resolve_impacts(w1, reshape([0.0_wp, 0.0_wp, 1.0_wp], [3, 1]), reshape([-1.0_wp, 0.0_wp, 0.1_wp], [3, 1]), &
                         [0.0_wp], [0.0_wp], p1, after1, lost1, st, [.true.])
    call check(st%ok() .and. all(p1 == 0) .and. all(after1(:, 1) == [-1.0_wp, 0.0_wp, 0.1_wp]), 'no-slip law: '// &
               'a contact that would pull with its points moving apart gets no impulse: '//st%text())
    call random_seed(size=seed_size)
    seed = [(7907*i, i = 1, seed_size)]
    call random_seed(put=seed)
    held = 0
    apart = 0
    refused = 0
    worst = 0
    do k = 1, cases
      m = 2 + mod(k, 2)
      allocate (p(3, m), after(3, m), lost(m), e(m), mu(m), no_slip(m))
      call random_impact(m, w, normals, v)
      v(:, 1) = 0   ! the carrying contact at rest relative to its body before the impact
      mu = 0
      no_slip = [.true., (.false., i = 2, m)]
      e = merge(0.0_wp, 0.5_wp, k <= cases/2)
      e(1) = 0
      st = status_t()
      call resolve_impacts(w, normals, v, e, mu, p, after, lost, st, no_slip)
      if (.not. st%ok()) then
        refused = refused + 1
        call check(index(st%text(), 'would have to pull') > 0 .or. index(st%text(), 'raise the kinetic') > 0, &
                   'no-slip law: refused only where it would pull, or for the energy: '//st%text())
        deallocate (p, after, lost, e, mu, no_slip)
        cycle
      end if
      scale = maxval(abs(v))
      worst = max(worst, maxval(abs(after - v - reshape(matmul(w, reshape(p, [3*m])), [3, m])))/scale)
      if (all(p(:, 1) == 0)) then
        apart = apart + 1
        worst = max(worst, -dot_product(normals(:, 1), after(:, 1))/scale)
      else
        held = held + 1
        worst = max(worst, norm2(after(:, 1))/scale, -dot_product(normals(:, 1), p(:, 1))/norm2(p(:, 1)))
      end if
      do i = 2, m
        vn = dot_product(normals(:, i), after(:, i)) + e(i)*min(dot_product(normals(:, i), v(:, i)), 0.0_wp)
        pn = dot_product(normals(:, i), p(:, i))
        worst = max(worst, -vn/scale, -pn/scale, min(vn, pn)/scale, norm2(p(:, i) - pn*normals(:, i))/scale)
      end do
      if (e(2) == 0) worst = max(worst, -sum(lost)/scale**2)
      deallocate (p, after, lost, e, mu, no_slip)
    end do
    call check(worst <= tol, 'no-slip law: the conditions at every contact after the impact (relative to the '// &
               'speeds): '//number(worst))
    call check(held > cases/4 .and. apart > cases/20, 'no-slip law: both ways taken, held '// &
               number(real(held, wp))//', apart '//number(real(apart, wp)))
    print '(a, es10.2, 3(a, i0))', '  no-slip law: worst ', worst, ', held ', held, ', apart ', apart, &
      ', refused ', refused
  end subroutine no_slip_law
end program test_rolling_impact
