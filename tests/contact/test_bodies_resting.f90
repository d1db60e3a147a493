!> Bodies that come to rest on each other and leave each other again (issue
!> 25): a contact between two moving bodies closes during a run (its
!> rebound below close_speed: body_1 carries body_2 from there,
!> contact_bodies, contact_model), opens again where its normal force falls
!> to zero (may_open), and a body may hit a stack of closed contacts.
!>   - box_ride: a box on two feet slides down a frictionless floor whose
!>     gravity is tilted by alpha = 20 degrees (g sin alpha along x) and a
!>     ball (e = 0.5, close_speed 0.1 m/s) falls on its lid with the box's
!>     velocity: in the box's frame it bounces as on a floor under g cos
!>     alpha (impacts at t_1 + (2 u/g') (e + .. + e^(k-1)), rebound e^k u),
!>     the box takes each hit through its feet and slides on undisturbed;
!>     the fourth rebound is below close_speed and the ball rides on the
!>     box: both at x = v_0 t + g sin alpha t^2/2 at every record (the ball
!>     above the box's centre throughout), the lid's N = m g cos alpha,
!>     each foot's (M + m) g cos alpha/2; the energy never rises, the poses
!>     the same before and after each switch.
!>   - slides_off: a ball (m) starts at rest on top of a ball (M) that the
!>     frictionless floor carries, theta_0 = 0.3 rad from the top, its
!>     contact closed and may_open (listed before the floor's: the builder
!>     waits for its body_1's carrier). It slides off, the low ball
!>     recoiling along the floor; horizontal momentum 0 and energy kept at
!>     every record; the contact opens where its normal force falls to
!>     zero, at 3 cos theta - k cos^3 theta = 2 cos theta_0, k = m/(m + M)
!>     (the low ball unaccelerated there: the high one in free fall, its
!>     centripetal acceleration g cos theta); poses and twists the same
!>     before and after the switch; then the high ball flies a parabola
!>     and the low one slides on at constant speed.
!>   - three_stack: a ball dropped centrally on a ball resting on a ball the
!>     floor carries (both contacts closed from the start): one impact at
!>     the hit and at both closed contacts (the simultaneous law), each
!>     taking m (1 + e) v, the dropped ball back at e v, the stack at rest.
!>   - flying_together: two bodies closed on each other while both fly (their
!>     contact presses with nothing in uniform gravity): refused at the
!>     start, and where two flying balls would close the run ends there,
!>     not built, saying so.
program test_bodies_resting
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use numerics_event_driver, only: driver_result_t, DRIVE_END_TIME, RECORD_EVENT
  use kinetostatics_recorder, only: mechanism_series_t
  use contact_model, only: contact_system_t
  use contact_flight, only: flight_ode_t
  use contact_bodies, only: build_bodies, start_carriers
  use io_input, only: input_text_t, input_from_text
  use io_contact_config, only: read_contact_config
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, fly, run_contact_text
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity

  call box_ride()
  call slides_off()
  call three_stack()
  call flying_together()
  call finish_tests('test_bodies_resting')

contains

  !> The contact scenario in `text` (named `label`) run as the command
  !> runs it (scenario_fixtures run_contact_text: its closed contacts
  !> carrying their bodies from the start), checked to be built and to run
  !> to its end.
  subroutine run(text, label, flight, result, st)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out), target :: flight
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: st
    call run_contact_text(text, label, flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, label//': built and runs to its end: '// &
               st%text()//' '//flight%outcome)
  end subroutine run

  !> The bodies' energy at record i (J): kinetic (each body's mass, its
  !> inertia about its origin, the centre of mass there) and the potential
  !> of the uniform gravity `gravity`.
  real(wp) function energy(s, i, mass, inertia, gravity)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: i
    real(wp), intent(in) :: mass(:), inertia(:, :, :), gravity(3)
    real(wp) :: w(3)
    integer :: b
    energy = 0
    do b = 1, size(mass)
      w = matmul(transpose(s%body_rot(:, :, b, i)), s%body_omega(:, b, i))
      energy = energy + mass(b)*(sum(s%body_v(:, b, i)**2)/2 - dot_product(gravity, s%body_r(:, b, i))) + &
               dot_product(w, matmul(inertia(:, :, b), w))/2
    end do
  end function energy

  !> The largest change of the bodies' poses (and with `twists` their
  !> twists) between the records before and after each switch (two records
  !> at one time, the second an event); switches: how many.
  real(wp) function across_switches(s, twists, switches) result(worst)
    type(mechanism_series_t), intent(in) :: s
    logical, intent(in) :: twists
    integer, intent(out) :: switches
    integer :: i
    worst = 0
    switches = 0
    do i = 2, s%n
      if (.not. (s%time(i) == s%time(i - 1) .and. s%kind(i) == RECORD_EVENT)) cycle
      switches = switches + 1
      worst = max(worst, maxval(abs(s%body_r(:, :, i) - s%body_r(:, :, i - 1))), &
                  maxval(abs(s%body_rot(:, :, :, i) - s%body_rot(:, :, :, i - 1))))
      if (twists) worst = max(worst, maxval(abs(s%body_v(:, :, i) - s%body_v(:, :, i - 1))), &
                              maxval(abs(s%body_omega(:, :, i) - s%body_omega(:, :, i - 1))))
    end do
  end function across_switches

  !> The diagonal inertia `d` as a matrix.
  pure function diagonal(d) result(a)
    real(wp), intent(in) :: d(3)
    real(wp) :: a(3, 3)
    integer :: k
    a = 0
    do k = 1, 3
      a(k, k) = d(k)
    end do
  end function diagonal

  !> box_ride (program comment).
  subroutine box_ride()
    real(wp), parameter :: pi = acos(-1.0_wp), alpha = 20*pi/180, mb = 2, mball = 0.3_wp, rball = 0.05_wp
    real(wp), parameter :: e = 0.5_wp, h0 = 0.1_wp, v0 = 0.5_wp, duration = 0.6_wp
    real(wp), parameter :: box_inertia(3) = [0.0216666666666667_wp, 0.0333333333333333_wp, 0.0416666666666667_wp]
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    character(len=:), allocatable :: text
    real(wp) :: gp, u, t_k, worst_t, worst_v, worst_x, worst_n, worst_rise, worst_switch, x, gravity(3), &
                inertia(3, 3, 2), t_c
    integer :: i, k, box, ball, lid, rear, front, switches
    gravity = [g*sin(alpha), 0.0_wp, -g*cos(alpha)]
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = '//number(duration)//', output_step = 0.01 /'//nl// &
           '&contact_model gravity = '//number(gravity(1))//', 0, '//number(gravity(3))//' /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''rear'', kind = ''sphere'', radius = 0.02, origin = -0.2, 0, -0.1 /'//nl// &
           '&shape name = ''front'', kind = ''sphere'', radius = 0.02, origin = 0.2, 0, -0.1 /'//nl// &
           '&shape name = ''lid'', kind = ''plane'', origin = 0, 0, 0.05 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = '//number(rball)//' /'//nl// &
           '&body name = ''box'', mass = '//number(mb)//', inertia = '//number(box_inertia(1))//', '// &
           number(box_inertia(2))//', '//number(box_inertia(3))//', position = 0, 0, 0.12, velocity = '// &
           number(v0)//', 0, 0 /'//nl// &
           '&body name = ''ball'', mass = '//number(mball)//', solid_of = ''ball'', position = 0, 0, '// &
           number(0.17_wp + rball + h0)//', velocity = '//number(v0)//', 0, 0 /'//nl// &
           '&contact name = ''rear_on_floor'', shape_1 = ''floor'', body_2 = ''box'', shape_2 = ''rear'' /'//nl// &
           '&contact name = ''front_on_floor'', shape_1 = ''floor'', body_2 = ''box'', shape_2 = ''front'' /'//nl// &
           '&contact name = ''ball_on_box'', body_1 = ''box'', shape_1 = ''lid'', body_2 = ''ball'', '// &
           'shape_2 = ''ball'', start = ''open'', restitution = '//number(e)//', close_speed = 0.1 /'//nl
    call run(text, 'box ride', flight, result, st)
    if (.not. st%ok()) return
    gp = g*cos(alpha)
    u = sqrt(2*gp*h0)
    ! three impacts rebound (e^3 u = 0.17 m/s), the fourth closes (e^4 u = 0.085 m/s < 0.1 m/s)
    call check(size(flight%impacts) == 12, 'box ride: four impacts, each at the lid and both feet: '// &
               number(real(size(flight%impacts), wp)))
    call check(index(flight%outcome, '''ball_on_box'' closed') > 0, 'box ride: the ball''s contact closes: '// &
               flight%outcome)
    if (size(flight%impacts) /= 12) return
    worst_t = 0
    worst_v = 0
    t_k = sqrt(2*h0/gp)
    t_c = 0
    do k = 1, 4
      do i = 3*k - 2, 3*k
        associate (row => flight%impacts(i))
          worst_t = max(worst_t, abs(row%time - t_k))
          if (row%contact /= 3) then   ! the feet: they stay closed, each taking half
            worst_v = max(worst_v, abs(row%normal_speed_before), abs(row%normal_speed_after), &
                          abs(row%normal_impulse - flight%impacts(3*k)%normal_impulse/2))
            cycle
          end if
          worst_v = max(worst_v, abs(row%normal_speed_before + e**(k - 1)*u), &
                        abs(row%normal_speed_after - merge(e**k*u, 0.0_wp, k < 4)), &
                        abs(row%normal_impulse - mball*(merge(1 + e, 1.0_wp, k < 4))*e**(k - 1)*u))
        end associate
      end do
      t_c = t_k
      t_k = t_k + 2*e**k*u/gp
    end do
    call check(all(flight%impacts%contact == [([1, 2, 3], k = 1, 4)]), 'box ride: each impact''s rows: the '// &
               'feet and the lid')
    call check_close(worst_t, 0.0_wp, 0.0_wp, 1e-9_wp, 'box ride: the impacts at t_1 + (2 u/g'') (e + .. + '// &
                     'e^(k-1)) (s)')
    call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-9_wp*g, 'box ride: approach e^(k-1) u, rebound e^k u (0 at '// &
                     'the fourth, closing), impulse m (1 + e) e^(k-1) u (m e^3 u), each foot half of it, its '// &
                     'speed 0')
    worst_x = 0
    worst_n = 0
    worst_rise = 0
    inertia(:, :, 1) = diagonal(box_inertia)
    inertia(:, :, 2) = diagonal(spread(2*mball*rball**2/5, 1, 3))
    associate (s => flight%series)
      box = findloc(s%body_names, 'box', dim=1)
      ball = findloc(s%body_names, 'ball', dim=1)
      lid = findloc(s%contact_names, 'ball_on_box', dim=1)
      rear = findloc(s%contact_names, 'rear_on_floor', dim=1)
      front = findloc(s%contact_names, 'front_on_floor', dim=1)
      call check(box == 1 .and. ball == 2 .and. lid > 0 .and. rear > 0 .and. front > 0, 'box ride: the bodies '// &
                 'and contacts recorded')
      if (box /= 1 .or. ball /= 2 .or. lid == 0 .or. rear == 0 .or. front == 0) return
      do i = 1, s%n
        x = v0*s%time(i) + gravity(1)*s%time(i)**2/2
        worst_x = max(worst_x, abs(s%body_r(1, box, i) - x), abs(s%body_r(1, ball, i) - x), &
                      abs(s%body_r(3, box, i) - 0.12_wp), norm2(s%body_omega(:, box, i)))
        if (i > 1) worst_rise = max(worst_rise, energy(s, i, [mb, mball], inertia, gravity) - &
                                    energy(s, i - 1, [mb, mball], inertia, gravity))
        if (s%time(i) <= t_c) cycle
        worst_x = max(worst_x, abs(s%body_r(3, ball, i) - 0.17_wp - rball), &
                      norm2(s%body_v(:, ball, i) - s%body_v(:, box, i)))
        worst_n = max(worst_n, abs(s%normal(lid, i) - mball*gp)/(mball*gp), &
                      abs(s%normal(rear, i) - (mb + mball)*gp/2)/((mb + mball)*gp/2), &
                      abs(s%normal(front, i) - (mb + mball)*gp/2)/((mb + mball)*gp/2))
      end do
      call check(s%time(s%n) == duration, 'box ride: to its end')
      worst_switch = across_switches(s, .false., switches)
      call check(switches == 4, 'box ride: a switch at each impact')
    end associate
    call check_close(worst_x, 0.0_wp, 0.0_wp, 1e-9_wp, 'box ride: box and ball at x = v_0 t + g sin alpha t^2/2, '// &
                     'the box level at its height; after the closing the ball on the lid, moving with the box')
    call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-9_wp, 'box ride: after the closing the lid''s N = m g cos alpha, '// &
                     'each foot''s (M + m) g cos alpha/2 (relative)')
    call check(worst_rise <= 1e-9_wp*(mb + mball)*g, 'box ride: the energy never rises: '//number(worst_rise))
    call check_close(worst_switch, 0.0_wp, 0.0_wp, 1e-12_wp, 'box ride: the poses the same before and after '// &
                     'each switch (m)')
    print '(a, 6es10.2)', '  box ride: time, impacts, motion, N, rise, switch ', worst_t, worst_v, worst_x, worst_n, &
      worst_rise, worst_switch
  end subroutine box_ride

  !> slides_off (program comment).
  subroutine slides_off()
    real(wp), parameter :: ml = 1, rl = 0.1_wp, mh = 0.1_wp, rh = 0.05_wp, rho = rl + rh, theta0 = 0.3_wp
    real(wp), parameter :: duration = 0.8_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    character(len=:), allocatable :: text
    real(wp) :: k, c, cos_lift, worst_p, worst_e, e0, worst_switch, worst_fly, inertia(3, 3, 2), gravity(3), &
                v_low(3), v_high(3), t_lift, rel(3)
    integer :: i, j, it, low, high, switches
    gravity = [0.0_wp, 0.0_wp, -g]
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = '//number(duration)//', output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''low'', kind = ''sphere'', radius = '//number(rl)//' /'//nl// &
           '&shape name = ''high'', kind = ''sphere'', radius = '//number(rh)//' /'//nl// &
           '&body name = ''low'', mass = '//number(ml)//', solid_of = ''low'', position = 0, 0, '//number(rl)//' /'// &
           nl//'&body name = ''high'', mass = '//number(mh)//', solid_of = ''high'', position = '// &
           number(rho*sin(theta0))//', 0, '//number(rl + rho*cos(theta0))//' /'//nl// &
           '&contact name = ''high_on_low'', body_1 = ''low'', shape_1 = ''low'', body_2 = ''high'', '// &
           'shape_2 = ''high'', may_open = .true. /'//nl// &
           '&contact name = ''low_on_floor'', shape_1 = ''floor'', body_2 = ''low'', shape_2 = ''low'' /'//nl
    call run(text, 'slides off', flight, result, st)
    if (.not. st%ok()) return
    call check(index(flight%outcome, 'lift-off: the normal force of contact ''high_on_low'' fell to zero') > 0 .and. &
               index(flight%outcome, 'the contact opens (may_open), the body flies') > 0, 'slides off: the contact '// &
               'opens at its lift-off: '//flight%outcome)
    ! 3 c - k c^3 = 2 cos theta_0 (Newton's method from c = 2 cos theta_0/3)
    k = mh/(mh + ml)
    c = 2*cos(theta0)/3
    do it = 1, 50
      c = c - (3*c - k*c**3 - 2*cos(theta0))/(3 - 3*k*c**2)
    end do
    inertia(:, :, 1) = diagonal(spread(2*ml*rl**2/5, 1, 3))
    inertia(:, :, 2) = diagonal(spread(2*mh*rh**2/5, 1, 3))
    worst_p = 0
    worst_e = 0
    worst_fly = 0
    cos_lift = -2
    associate (s => flight%series)
      low = findloc(s%body_names, 'low', dim=1)
      high = findloc(s%body_names, 'high', dim=1)
      call check(low == 1 .and. high == 2, 'slides off: the bodies recorded')
      if (low /= 1 .or. high /= 2) return
      worst_switch = across_switches(s, .true., switches)
      call check(switches == 1, 'slides off: one switch, the lift-off: '//number(real(switches, wp)))
      j = 0
      do i = 2, s%n
        if (s%time(i) == s%time(i - 1) .and. s%kind(i) == RECORD_EVENT) j = i
      end do
      if (j == 0) return
      t_lift = s%time(j)
      rel = s%body_r(:, high, j) - s%body_r(:, low, j)
      cos_lift = rel(3)/norm2(rel)
      v_low = s%body_v(:, low, j)
      v_high = s%body_v(:, high, j)
      e0 = energy(s, 1, [ml, mh], inertia, gravity)
      do i = 1, s%n
        worst_p = max(worst_p, abs(ml*s%body_v(1, low, i) + mh*s%body_v(1, high, i)), &
                      abs(ml*s%body_v(2, low, i) + mh*s%body_v(2, high, i)))
        worst_e = max(worst_e, abs(energy(s, i, [ml, mh], inertia, gravity) - e0))
        if (i <= j) cycle
        worst_fly = max(worst_fly, norm2(s%body_v(:, low, i) - v_low), &
                        norm2(s%body_v(:, high, i) - v_high - gravity*(s%time(i) - t_lift)), &
                        norm2(s%body_r(:, high, i) - s%body_r(:, high, j) - v_high*(s%time(i) - t_lift) - &
                              gravity*(s%time(i) - t_lift)**2/2))
      end do
    end associate
    call check_close(cos_lift, c, 0.0_wp, 1e-8_wp, 'slides off: the lift-off at 3 cos theta - k cos^3 theta = 2 '// &
                     'cos theta_0')
    call check_close(worst_switch, 0.0_wp, 0.0_wp, 1e-12_wp, 'slides off: poses and twists the same before and '// &
                     'after the switch')
    call check_close(worst_p, 0.0_wp, 0.0_wp, 1e-10_wp, 'slides off: the horizontal momentum stays 0 (N s)')
    call check_close(worst_e, 0.0_wp, 0.0_wp, 1e-9_wp*mh*g*rho, 'slides off: the energy kept (J)')
    call check_close(worst_fly, 0.0_wp, 0.0_wp, 1e-9_wp, 'slides off: after the lift-off the low ball at its '// &
                     'speed, the high one on the parabola from its lift-off state')
    print '(a, 5es10.2)', '  slides off: cos theta, switch, momentum, energy, flight ', cos_lift - c, worst_switch, &
      worst_p, worst_e, worst_fly
  end subroutine slides_off

  !> three_stack (program comment).
  subroutine three_stack()
    real(wp), parameter :: e = 0.5_wp, h = 0.2_wp, mt = 0.05_wp, height(2) = [0.1_wp, 0.3_wp]
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    character(len=:), allocatable :: text
    real(wp) :: v, worst_p, worst_rest
    integer :: i, j
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 0.3, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&shape name = ''top'', kind = ''sphere'', radius = 0.05 /'//nl// &
           '&body name = ''low'', mass = 1, solid_of = ''ball'', position = 0, 0, 0.1 /'//nl// &
           '&body name = ''mid'', mass = 0.5, solid_of = ''ball'', position = 0, 0, 0.3 /'//nl// &
           '&body name = ''top'', mass = '//number(mt)//', solid_of = ''top'', position = 0, 0, '// &
           number(0.45_wp + h)//' /'//nl// &
           '&contact name = ''low_on_floor'', shape_1 = ''floor'', body_2 = ''low'', shape_2 = ''ball'' /'//nl// &
           '&contact name = ''mid_on_low'', body_1 = ''low'', shape_1 = ''ball'', body_2 = ''mid'', '// &
           'shape_2 = ''ball'' /'//nl// &
           '&contact name = ''top_on_mid'', body_1 = ''mid'', shape_1 = ''ball'', body_2 = ''top'', '// &
           'shape_2 = ''top'', start = ''open'', restitution = '//number(e)//' /'//nl
    call run(text, 'three stack', flight, result, st)
    if (.not. st%ok()) return
    v = sqrt(2*g*h)
    call check(size(flight%impacts) == 3, 'three stack: one impact, at the hit and both closed contacts')
    if (size(flight%impacts) /= 3) return
    call check(all(flight%impacts%contact == [1, 2, 3]) .and. all(flight%impacts%time == flight%impacts(1)%time), &
               'three stack: the rows of the floor, the contact between the low balls and the hit, at one time')
    worst_p = 0
    do i = 1, 3
      worst_p = max(worst_p, abs(flight%impacts(i)%normal_impulse - mt*(1 + e)*v))
    end do
    worst_p = max(worst_p, abs(flight%impacts(3)%normal_speed_after - e*v), &
                  abs(flight%impacts(1)%normal_speed_after), abs(flight%impacts(2)%normal_speed_after))
    worst_rest = 0
    associate (s => flight%series)
      do i = 1, s%n
        do j = 1, 2
          worst_rest = max(worst_rest, abs(s%body_r(3, j, i) - height(j)), norm2(s%body_r(1:2, j, i)), &
                           norm2(s%body_v(:, j, i)), norm2(s%body_omega(:, j, i)))
        end do
      end do
    end associate
    call check_close(worst_p, 0.0_wp, 0.0_wp, 1e-9_wp, 'three stack: each contact takes m (1 + e) v, the top ball '// &
                     'back at e v, the closed contacts'' speeds after 0')
    call check_close(worst_rest, 0.0_wp, 0.0_wp, 1e-12_wp, 'three stack: the low balls at rest throughout')
    print '(a, 2es10.2)', '  three stack: impulses, rest ', worst_p, worst_rest
  end subroutine three_stack
  !> Two bodies closed on each other while both fly: in uniform gravity
  !> their contact presses with nothing. A ball that starts closed on a
  !> free one is refused at the start ("does not press"), and two balls
  !> thrown at each other with e = 0 (their rebound below close_speed) end
  !> the run there, not built, saying so, the impact kept.
  subroutine flying_together()
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st, pair_st
    type(input_text_t) :: input
    type(contact_system_t) :: system
    real(wp), allocatable :: q0(:), qd0(:)
    integer, allocatable :: open(:, :)
    character(len=8), allocatable :: units(:)
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''low'', mass = 1, solid_of = ''ball'', position = 0, 0, 0.5 /'//nl// &
           '&body name = ''top'', mass = 0.5, solid_of = ''ball'', position = 0, 0, 0.7 /'//nl// &
           '&contact name = ''top_on_low'', body_1 = ''low'', shape_1 = ''ball'', body_2 = ''top'', '// &
           'shape_2 = ''ball'' /'//nl// &
           '&contact name = ''low_on_floor'', shape_1 = ''floor'', body_2 = ''low'', shape_2 = ''ball'', '// &
           'start = ''open'', restitution = 0 /'//nl
    call input_from_text('together', text, input, st)
    if (st%ok()) call read_contact_config(input, system, st)
    if (st%ok()) call build_bodies(system, start_carriers(system), flight, q0, qd0, units, st, 0, .false.)
    call check(index(st%text(), 'contact ''top_on_low'' does not press') > 0, 'flying together: a ball closed '// &
               'on a free one is refused at the start: '//st%text())
    text = '&run scenario = ''contact'' /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''a'', mass = 1, solid_of = ''ball'', position = 0, 0, 1, velocity = 1, 0, 0 /'//nl// &
           '&body name = ''b'', mass = 0.5, solid_of = ''ball'', position = 0.5, 0, 1, velocity = -1, 0, 0 /'//nl// &
           '&contact name = ''a_b'', body_1 = ''a'', shape_1 = ''ball'', body_2 = ''b'', shape_2 = ''ball'', '// &
           'start = ''open'', restitution = 0 /'//nl
    call input_from_text('pair', text, input, pair_st)
    if (pair_st%ok()) call read_contact_config(input, system, pair_st)
    if (pair_st%ok()) call build_bodies(system, start_carriers(system), flight, q0, qd0, units, pair_st, 0, .false.)
    call check(pair_st%ok(), 'flying together: the pair built: '//pair_st%text())
    if (.not. pair_st%ok()) return
    call fly(flight, q0, qd0, 1e-12_wp, 0.5_wp, 100, result, st, open)
    call check(.not. st%ok() .and. index(flight%outcome, 'bodies ''a'' and ''b'' would fly on closed on each '// &
               'other, their contact pressing with nothing in uniform gravity (two flying bodies closed on each '// &
               'other are not built): the run ends here') > 0, 'flying together: the pair''s plastic impact in '// &
               'flight ends the run, saying why: '//flight%outcome)
    call check(size(flight%impacts) == 1, 'flying together: the impact kept')
    if (size(flight%impacts) == 1) call check_close(flight%impacts(1)%time, 0.3_wp/2, 0.0_wp, 1e-9_wp, &
                                                    'flying together: the impact at (0.5 - 0.2)/2 s')
  end subroutine flying_together
end program test_bodies_resting
