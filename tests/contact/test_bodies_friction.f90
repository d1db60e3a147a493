!> Friction between bodies resting on each other (issue 25): a contact
!> between two moving bodies where contacts open and close takes the
!> friction laws of the ground's contacts (kinetostatics_force_law_factory)
!> on the tangential slip of the two bodies' material points.
!>
!> The case: a box (M) on two frictionless feet slides along a horizontal
!> floor at V_0; a ball (m, R, I = 2/5 m R^2) at rest on its lid, Coulomb's
!> law with mu and regularization eps between them. The slip w (the ball's
!> contact point relative to the box, along x) obeys, with F the friction
!> on the ball, dw/dt = K F (K = 1/m + R^2/I + 1/M = 7/(2 m) + 1/M: the
!> ball's centre, its spin and the box each move under F), F = -mu m g
!> w/sqrt(w^2 + eps^2) (N = m g: nothing moves vertically). So dw/dt = -k
!> w/s, k = mu g (7/2 + m/M), s = sqrt(w^2 + eps^2), whose solution is
!> G(w(t)) = G(w_0) - k t with G(w) = s + eps ln(|w|/(s + eps)): for eps
!> -> 0 the slip falls linearly, |w| = |w_0| - k t, and ends at t* =
!> |w_0|/k. The ball's speed u = (w - w_0)/(m K), its spin R omega_y =
!> -(w - w_0)/(m K) 5/2, the box's V = V_0 - (w - w_0)/(M K): the pair's
!> momentum m u + M V = M V_0 is kept, and the kinetic energy falls by
!> (w_0^2 - w^2)/(2 K), which is minus the friction law's work (its
!> integral of F w).
!>   - starts_closed: the ball starts closed on the box (may_open: a run
!>     whose contacts open and close), w_0 = -V_0.
!>   - lands: the ball is dropped onto the lid (restitution 0, a
!>     frictionless impact): it lands at sqrt(2 h/g), its rebound below
!>     close_speed closes the contact, and it slips from there as above.
!>   - viscous: the same ball with the viscous law -c w_t: w = w_0
!>     exp(-c K t).
!>   - rolls_on_plank: the box's feet with Coulomb's mu_f on the floor
!>     (the box slows at mu_f g), the ball dropped on the lid at rest with
!>     rolling = .true. and restitution 0: at its landing (sqrt(2 h/g)) the
!>     closing takes away its whole relative velocity, the slip -V_1 by the
!>     tangential impulse V_1/K (the ball leaves at V_1/(m K), the box at
!>     V_1 - V_1/(M K)); from there it rolls on the slowing box, the ball
!>     pushed by f = 2 m A/7, the box at A = -mu_f (M + m) g/(M + 2 m/7)
!>     (a ball rolling on a plank that slides on a rough floor), both on
!>     their parabolas, no slip; the energy's fall is the impacts' and the
!>     feet's friction's.
!>   - ball_on_cart: inputs/contact/ball_on_cart.nml, a ball (0.2 kg) with
!>     forward spin (R omega_0 = 1 m/s) dropped 0.3 m on a cart (4 kg) on
!>     three frictionless feet, both at 1 m/s: frictionless impacts (e =
!>     0.6) at the floor's times t_1 + (2 v/g) (e + .. + e^(k-1)), the
!>     seventh closes the contact, and from there the slip -R omega_0 on
!>     the Coulomb closed form (mu 0.2, eps 1e-6 m/s: BDF); the momentum along
!>     x kept throughout.
program test_bodies_friction
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use numerics_event_driver, only: driver_result_t, DRIVE_END_TIME
  use kinetostatics_recorder, only: mechanism_series_t
  use contact_flight, only: flight_ode_t
  use testing, only: check, check_close, finish_tests
  use io_input, only: input_text_t, load_input_file
  use scenario_fixtures, only: number, run_contact_text, run_contact_input
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity
  real(wp), parameter :: mb = 2, m = 0.3_wp, r = 0.05_wp, v0 = 0.5_wp, mu = 0.3_wp
  real(wp), parameter :: box_inertia(3) = [0.0216666666666667_wp, 0.0333333333333333_wp, 0.0416666666666667_wp]
  real(wp), parameter :: kk = 7/(2*m) + 1/mb   ! K = 1/m + R^2/I + 1/M

  !> A ball slipping on a box (program comment): the masses, the ball's
  !> radius, the law (1: Coulomb with mu and eps, 2: viscous with c = eps),
  !> at the slip's start the ball's speed u0 and spin omega0 (about y) and
  !> the box's speed v0 (along x), the names of the box and of the contact,
  !> the tolerance of the closed forms (relative to the slip w0).
  type :: slipping_t
    real(wp) :: m = m, mb = mb, r = r, mu = mu, eps = 0
    integer :: law = 1
    real(wp) :: u0 = 0, omega0 = 0, v0 = v0
    character(len=16) :: box = 'box', contact = 'ball_on_box'
    real(wp) :: tolerance = 1e-9_wp
  end type slipping_t

  call starts_closed()
  call lands()
  call viscous()
  call rolls_on_plank()
  call ball_on_cart()
  call finish_tests('test_bodies_friction')

contains

  !> The box on its feet moving at v0 and the ball on or over its lid
  !> (its centre `above` the lid's contact height), the ball's contact
  !> `ball_on_box` with the rest of its group `contact`, the feet's with
  !> `feet` if present; `duration` s, records every 0.002 s.
  function box_and_ball(above, contact, duration, feet) result(text)
    real(wp), intent(in) :: above, duration
    character(len=*), intent(in) :: contact
    character(len=*), intent(in), optional :: feet
    character(len=:), allocatable :: text, foot
    foot = ''
    if (present(feet)) foot = ', '//feet
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = '//number(duration)//', output_step = 0.002 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''rear'', kind = ''sphere'', radius = 0.02, origin = -0.2, 0, -0.1 /'//nl// &
           '&shape name = ''front'', kind = ''sphere'', radius = 0.02, origin = 0.2, 0, -0.1 /'//nl// &
           '&shape name = ''lid'', kind = ''plane'', origin = 0, 0, 0.05 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = '//number(r)//' /'//nl// &
           '&body name = ''box'', mass = '//number(mb)//', inertia = '//number(box_inertia(1))//', '// &
           number(box_inertia(2))//', '//number(box_inertia(3))//', position = 0, 0, 0.12, velocity = '// &
           number(v0)//', 0, 0 /'//nl// &
           '&body name = ''ball'', mass = '//number(m)//', solid_of = ''ball'', position = 0, 0, '// &
           number(0.17_wp + r + above)//' /'//nl// &
           '&contact name = ''rear_on_floor'', shape_1 = ''floor'', body_2 = ''box'', shape_2 = ''rear'''// &
           foot//' /'//nl// &
           '&contact name = ''front_on_floor'', shape_1 = ''floor'', body_2 = ''box'', shape_2 = ''front'''// &
           foot//' /'//nl// &
           '&contact name = ''ball_on_box'', body_1 = ''box'', shape_1 = ''lid'', body_2 = ''ball'', '// &
           'shape_2 = ''ball'', '//contact//' /'//nl
  end function box_and_ball

  !> The slip of Coulomb's regularized law after time t from w0 (< 0):
  !> G(|w|) = G(|w0|) - k t, G(a) = s + eps ln(a/(s + eps)), s = sqrt(a^2 +
  !> eps^2), increasing in a; solved by bisection on ln |w| (|w| may be far
  !> below the smallest normal number in the tail).
  real(wp) function coulomb_slip(w0, k, eps, t) result(w)
    real(wp), intent(in) :: w0, k, eps, t
    real(wp) :: target, lo, hi, x
    integer :: it
    target = big_g(log(abs(w0)), eps) - k*t
    lo = -745
    hi = log(abs(w0))
    if (big_g(lo, eps) >= target) then
      w = 0
      return
    end if
    do it = 1, 200
      x = (lo + hi)/2
      if (x <= lo .or. x >= hi) exit
      if (big_g(x, eps) < target) then
        lo = x
      else
        hi = x
      end if
    end do
    w = sign(exp((lo + hi)/2), w0)
  end function coulomb_slip

  !> G at |w| = exp(x) (coulomb_slip).
  pure real(wp) function big_g(x, eps)
    real(wp), intent(in) :: x, eps
    real(wp) :: s
    s = sqrt(exp(x)**2 + eps**2)
    big_g = s + eps*(x - log(s + eps))
  end function big_g

  !> The bodies' kinetic energy at record i (J): the box translating (it
  !> stays level: its feet closed), the ball with its spin.
  real(wp) function kinetic(s, i, box, ball, p)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: i, box, ball
    type(slipping_t), intent(in) :: p
    kinetic = p%mb*sum(s%body_v(:, box, i)**2)/2 + p%m*sum(s%body_v(:, ball, i)**2)/2 + &
              (2*p%m*p%r**2/5)*sum(s%body_omega(:, ball, i)**2)/2
  end function kinetic

  !> The bodies' energy at record i (J): kinetic and the potential of
  !> gravity along -z.
  real(wp) function total(s, i, box, ball, p)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: i, box, ball
    type(slipping_t), intent(in) :: p
    total = kinetic(s, i, box, ball, p) + p%m*g*s%body_r(3, ball, i) + p%mb*g*s%body_r(3, box, i)
  end function total

  !> The slip at the ball's lowest point relative to the box (x) at record i.
  real(wp) function slip(s, i, box, ball, p)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: i, box, ball
    type(slipping_t), intent(in) :: p
    slip = s%body_v(1, ball, i) - p%r*s%body_omega(2, ball, i) - s%body_v(1, box, i)
  end function slip

  !> The checks of the ball slipping on the box from t0 (the case p: the
  !> slip w0 = u0 - R omega0 - v0 there) against its closed form at every
  !> record from t0 (program comment); `label` names the case.
  subroutine check_slip(flight, t0, p, label)
    type(flight_ode_t), intent(in) :: flight
    real(wp), intent(in) :: t0
    type(slipping_t), intent(in) :: p
    character(len=*), intent(in) :: label
    real(wp) :: w, w0, w_cf, k, big_k, worst_w, worst_v, worst_p, worst_e, worst_n, worst_rise, e0, work0, lost, &
                scale, t_end, p0
    integer :: i, box, ball, lid, friction, records
    big_k = 7/(2*p%m) + 1/p%mb
    k = p%mu*g*p%m*big_k
    w0 = p%u0 - p%r*p%omega0 - p%v0
    p0 = p%m*p%u0 + p%mb*p%v0
    worst_w = 0
    worst_v = 0
    worst_p = 0
    worst_e = 0
    worst_n = 0
    worst_rise = 0
    records = 0
    scale = w0**2/(2*big_k)   ! the energy friction takes
    associate (s => flight%series)
      box = findloc(s%body_names, p%box, dim=1)
      ball = findloc(s%body_names, 'ball', dim=1)
      lid = findloc(s%contact_names, p%contact, dim=1)
      friction = findloc(s%law_names, trim(p%contact)//'.friction', dim=1)
      call check(box > 0 .and. ball > 0 .and. lid > 0 .and. friction > 0, label//': the bodies, the contact and '// &
                 'its friction law recorded')
      if (box == 0 .or. ball == 0 .or. lid == 0 .or. friction == 0) return
      e0 = -1
      work0 = 0
      do i = 1, s%n
        if (i > 1) worst_rise = max(worst_rise, total(s, i, box, ball, p) - total(s, i - 1, box, ball, p))
        worst_p = max(worst_p, abs(p%m*s%body_v(1, ball, i) + p%mb*s%body_v(1, box, i) - p0))
        if (s%time(i) < t0) cycle
        if (i < s%n) then   ! of the two records at a switch the second (after the closing)
          if (s%time(i + 1) == s%time(i)) cycle
        end if
        if (e0 < 0) then   ! the first record from t0: the slip starts there
          e0 = kinetic(s, i, box, ball, p)
          work0 = s%law_work(friction, i)
        end if
        records = records + 1
        w = slip(s, i, box, ball, p)
        if (p%law == 1) then
          w_cf = coulomb_slip(w0, k, p%eps, s%time(i) - t0)
        else
          w_cf = w0*exp(-p%eps*big_k*(s%time(i) - t0))
        end if
        worst_w = max(worst_w, abs(w - w_cf))
        worst_v = max(worst_v, abs(s%body_v(1, ball, i) - p%u0 - (w - w0)/(p%m*big_k)), &
                      abs(p%r*s%body_omega(2, ball, i) - p%r*p%omega0 + 5*(w - w0)/(2*p%m*big_k)), &
                      abs(s%body_v(1, box, i) - p%v0 + (w - w0)/(p%mb*big_k)), &
                      norm2(s%body_v(2:3, ball, i)), norm2(s%body_v(2:3, box, i)), norm2(s%body_omega(:, box, i)))
        lost = e0 - kinetic(s, i, box, ball, p)
        worst_e = max(worst_e, abs(lost - (w0**2 - w**2)/(2*big_k))/scale, &
                      abs(lost + (s%law_work(friction, i) - work0))/scale)
        worst_n = max(worst_n, abs(s%normal(lid, i) - p%m*g)/(p%m*g))
        t_end = s%time(i)
      end do
    end associate
    call check(records > 10, label//': slipping at more than 10 records')
    call check_close(worst_w, 0.0_wp, 0.0_wp, p%tolerance*abs(w0), label//': the slip on its closed form (m/s)')
    call check_close(worst_v, 0.0_wp, 0.0_wp, p%tolerance*abs(w0), label//': the ball''s speed u_0 + (w - w_0)/'// &
                     '(m K), its spin R omega_0 - 5/2 (w - w_0)/(m K), the box''s v_0 - (w - w_0)/(M K), nothing '// &
                     'else moving (m/s)')
    call check_close(worst_p, 0.0_wp, 0.0_wp, 1e-10_wp*p0, label//': the pair''s momentum along x kept (N s)')
    call check_close(worst_e, 0.0_wp, 0.0_wp, p%tolerance, label//': the kinetic energy falls by (w_0^2 - w^2)/'// &
                     '(2 K), the friction law''s work (relative to w_0^2/(2 K))')
    call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-9_wp, label//': N = m g on the lid (relative)')
    call check(worst_rise <= 1e-9_wp*scale, label//': the energy never rises: '//number(worst_rise))
    print '(2a, 6es10.2, a, f7.4, a)', '  ', label//': slip, speeds, momentum, energy, N, rise ', worst_w, worst_v, &
      worst_p, worst_e, worst_n, worst_rise, '; to ', t_end, ' s'
  end subroutine check_slip

  !> starts_closed (program comment): the slip ends at t* = v0/k, where the
  !> regularized law's slip has fallen to eps^2/(e v0) (its closed form).
  subroutine starts_closed()
    real(wp), parameter :: eps = 1e-4_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: t_star, w_before, w_after, k
    integer :: i, box, ball
    call run_contact_text(box_and_ball(0.0_wp, 'may_open = .true., friction = ''coulomb'', mu = '//number(mu)// &
                          ', regularization_speed = '//number(eps), 0.08_wp), 'starts closed', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'starts closed: runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check(size(flight%impacts) == 0, 'starts closed: no impact')
    call check_slip(flight, 0.0_wp, slipping_t(eps=eps), 'starts closed')
    k = mu*g*(7.0_wp/2 + m/mb)
    t_star = v0/k
    w_before = 0
    w_after = 0
    associate (s => flight%series)
      box = findloc(s%body_names, 'box', dim=1)
      ball = findloc(s%body_names, 'ball', dim=1)
      do i = 1, s%n
        if (s%time(i) <= t_star - 0.005_wp) w_before = slip(s, i, box, ball, slipping_t()) + v0 - k*s%time(i)
        if (s%time(i) >= t_star + 0.005_wp) w_after = max(w_after, abs(slip(s, i, box, ball, slipping_t())))
      end do
    end associate
    call check(abs(w_before) < 2e-7_wp .and. w_after < 1e-12_wp, 'starts closed: the slip falls as v_0 - k t '// &
               'until 5 ms before t* = v_0/k (the regularization adds eps^2/(2 |w|) < 1e-7 m/s there) and is '// &
               'gone 5 ms after: '//number(w_before)//', '//number(w_after))
  end subroutine starts_closed

  !> lands (program comment).
  subroutine lands()
    real(wp), parameter :: eps = 1e-4_wp, h = 0.05_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: t1
    call run_contact_text(box_and_ball(h, 'start = ''open'', restitution = 0, friction = ''coulomb'', mu = '// &
                          number(mu)//', regularization_speed = '//number(eps), 0.2_wp), 'lands', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'lands: runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    t1 = sqrt(2*h/g)
    call check(size(flight%impacts) == 3 .and. index(flight%outcome, '''ball_on_box'' closed') > 0, 'lands: one '// &
               'impact (the lid and both feet), the contact closed: '//flight%outcome)
    if (size(flight%impacts) /= 3) return
    call check_close(flight%impacts(3)%time, t1, 0.0_wp, 1e-10_wp, 'lands: at sqrt(2 h/g) (s)')
    call check_close(flight%impacts(3)%normal_impulse, m*g*t1, 0.0_wp, 1e-10_wp, 'lands: plastic, m g t_1 (N s)')
    call check_slip(flight, flight%impacts(3)%time, slipping_t(eps=eps), 'lands')
  end subroutine lands

  !> viscous (program comment): c = 0.6 N s/m.
  subroutine viscous()
    real(wp), parameter :: c = 0.6_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    call run_contact_text(box_and_ball(0.0_wp, 'may_open = .true., friction = ''viscous'', viscous_coefficient = '// &
                          number(c), 0.2_wp), 'viscous', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'viscous: runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check_slip(flight, 0.0_wp, slipping_t(eps=c, law=2), 'viscous')
  end subroutine viscous

  !> rolls_on_plank (program comment): mu_f = 0.1, h = 0.05 m, 0.4 s.
  subroutine rolls_on_plank()
    real(wp), parameter :: mu_f = 0.1_wp, h = 0.05_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: t1, v1, p_t, u1, w1, a, t, worst_m, worst_e, worst_rise, e0, lost, e_now, x1, xb1
    integer :: i, box, ball, lid, rear, front, i1
    call run_contact_text(box_and_ball(h, 'start = ''open'', restitution = 0, rolling = .true.', 0.4_wp, &
                          'friction = ''coulomb'', mu = '//number(mu_f)), 'rolls on plank', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'rolls on plank: runs to its end: '//st%text()// &
               ' '//flight%outcome)
    if (.not. st%ok()) return
    t1 = sqrt(2*h/g)
    v1 = v0 - mu_f*g*t1
    p_t = v1/kk
    call check(size(flight%impacts) == 3 .and. index(flight%outcome, '''ball_on_box'' closed') > 0, 'rolls on '// &
               'plank: one impact (the lid and both feet), the contact closed: '//flight%outcome)
    if (size(flight%impacts) /= 3) return
    call check_close(flight%impacts(3)%time, t1, 0.0_wp, 1e-10_wp, 'rolls on plank: the landing at sqrt(2 h/g) (s)')
    call check_close(flight%impacts(3)%normal_impulse, m*g*t1, 0.0_wp, 1e-10_wp, 'rolls on plank: plastic, m g '// &
                     't_1 (N s)')
    call check_close(flight%impacts(3)%tangential_impulse, p_t, 0.0_wp, 1e-10_wp, 'rolls on plank: the closing''s '// &
                     'tangential impulse V_1/K (N s)')
    a = -mu_f*(mb + m)*g/(mb + 2*m/7)
    u1 = p_t/m
    w1 = v1 - p_t/mb
    worst_m = 0
    worst_e = 0
    worst_rise = 0
    associate (s => flight%series)
      box = findloc(s%body_names, 'box', dim=1)
      ball = findloc(s%body_names, 'ball', dim=1)
      lid = findloc(s%contact_names, 'ball_on_box', dim=1)
      rear = findloc(s%law_names, 'rear_on_floor.friction', dim=1)
      front = findloc(s%law_names, 'front_on_floor.friction', dim=1)
      call check(box > 0 .and. ball > 0 .and. lid > 0 .and. rear > 0 .and. front > 0, 'rolls on plank: bodies, '// &
                 'contact and the feet''s laws recorded')
      if (box == 0 .or. ball == 0 .or. lid == 0 .or. rear == 0 .or. front == 0) return
      e0 = total(s, 1, box, ball, slipping_t())
      ! the record after the closing: the second of the two at the impact's time
      i1 = findloc([(s%time(i) == flight%impacts(3)%time .and. s%time(max(i - 1, 1)) == s%time(i) .and. i > 1, &
                     i = 1, s%n)], .true., dim=1)
      call check(i1 > 0, 'rolls on plank: two records at the impact, the second after the closing')
      if (i1 == 0) return
      x1 = s%body_r(1, ball, i1)
      xb1 = s%body_r(1, box, i1)
      do i = 1, s%n
        t = s%time(i)
        e_now = total(s, i, box, ball, slipping_t())
        if (i > 1) worst_rise = max(worst_rise, e_now - total(s, i - 1, box, ball, slipping_t()))
        ! the energy's fall: the feet's friction's work and, after it, the impact's losses
        lost = -(s%law_work(rear, i) + s%law_work(front, i))
        if (i >= i1) lost = lost + sum(flight%impacts%energy_lost)
        worst_e = max(worst_e, abs(e0 - e_now - lost))
        if (i < i1) then   ! the box alone slows at mu_f g, the ball falls
          worst_m = max(worst_m, abs(s%body_v(1, box, i) - v0 + mu_f*g*t), &
                        abs(s%body_r(1, box, i) - v0*t + mu_f*g*t**2/2), norm2(s%body_v(:, ball, i) - [0.0_wp, &
                        0.0_wp, -g*t]))
          cycle
        end if
        t = t - s%time(i1)
        worst_m = max(worst_m, abs(s%body_v(1, ball, i) - u1 - 2*a*t/7), abs(s%body_v(1, box, i) - w1 - a*t), &
                      abs(s%body_r(1, ball, i) - x1 - u1*t - a*t**2/7), abs(s%body_r(1, box, i) - xb1 - w1*t - &
                      a*t**2/2), abs(r*s%body_omega(2, ball, i) - s%body_v(1, ball, i) + s%body_v(1, box, i)), &
                      norm2(s%body_v(2:3, ball, i)), norm2(s%body_omega(:, box, i)), &
                      abs(s%body_r(3, ball, i) - 0.17_wp - r))
      end do
    end associate
    call check_close(worst_m, 0.0_wp, 0.0_wp, 1e-9_wp, 'rolls on plank: the box slowing at mu_f g, then at A, the '// &
                     'ball from V_1/(m K) at 2 A/7, rolling on the lid without slip (m, m/s)')
    call check_close(worst_e, 0.0_wp, 0.0_wp, 1e-9_wp*e0, 'rolls on plank: the energy''s fall the feet''s '// &
                     'friction''s work and the impacts'' losses (J)')
    call check(worst_rise <= 1e-12_wp*e0, 'rolls on plank: the energy never rises: '//number(worst_rise))
    print '(a, 3es10.2)', '  rolls on plank: motion, energy, rise ', worst_m, worst_e, worst_rise
  end subroutine rolls_on_plank

  !> ball_on_cart (program comment).
  subroutine ball_on_cart()
    real(wp), parameter :: e = 0.6_wp, h = 0.3_wp
    type(input_text_t) :: input
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: v, t_k, worst_t, worst_v
    integer :: k
    call load_input_file('inputs/contact/ball_on_cart.nml', input, st)
    if (st%ok()) call run_contact_input(input, flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'ball on cart: runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check(size(flight%impacts) == 28, 'ball on cart: seven impacts, each at the lid and the three feet: '// &
               number(real(size(flight%impacts), wp)))
    if (size(flight%impacts) /= 28) return
    v = sqrt(2*g*h)
    t_k = v/g
    worst_t = 0
    worst_v = 0
    do k = 1, 7
      associate (row => flight%impacts(4*k))
        worst_t = max(worst_t, abs(row%time - t_k))
        worst_v = max(worst_v, abs(row%normal_speed_before + e**(k - 1)*v), &
                      abs(row%normal_speed_after - merge(e**k*v, 0.0_wp, k < 7)), abs(row%tangential_impulse))
        call check(row%contact == 4, 'ball on cart: the lid''s row last')
      end associate
      t_k = t_k + 2*e**k*v/g
    end do
    call check_close(worst_t, 0.0_wp, 0.0_wp, 1e-9_wp, 'ball on cart: the impacts at t_1 + (2 v/g) (e + .. + '// &
                     'e^(k-1)) (s)')
    call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-9_wp*v, 'ball on cart: approach e^(k-1) v, rebound e^k v (0 at '// &
                     'the seventh, closing), no tangential impulse (m/s, N s)')
    call check(index(flight%outcome, '''ball_on_cart'' closed') > 0, 'ball on cart: the contact closes: '// &
               flight%outcome)
    call check_slip(flight, flight%impacts(28)%time, slipping_t(m=0.2_wp, mb=4.0_wp, mu=0.2_wp, eps=1e-6_wp, &
                    u0=1.0_wp, omega0=20.0_wp, v0=1.0_wp, box='cart', contact='ball_on_cart'), &
                    'ball on cart')
    print '(a, 2es10.2)', '  ball on cart: impact times, speeds ', worst_t, worst_v
  end subroutine ball_on_cart
end program test_bodies_friction
