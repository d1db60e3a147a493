!> Impacts between two bodies (issue 25): the impulse of the pair at the
!> contact point from its Delassus matrix K = K_1 + K_2 (contact_body_impact),
!> against closed forms, and in flight (contact_flight: a contact between
!> two bodies that starts open, its gap a root, its landing an impact).
!>   - head_on: two spheres (m1 = 0.2 kg, R1 = 0.1 m; m2 = 0.5 kg, R2 =
!>     0.05 m) meeting along the line of their centres at v1 = 2, v2 = -1
!>     m/s, e in {0, 0.6, 1}, frictionless: v1' = ((m1 - e m2) v1 + (1 + e)
!>     m2 v2)/(m1 + m2) (and v2' alike), the energy lost (1 - e^2) m1 m2/(2
!>     (m1 + m2)) dv^2, no spin; momentum to rounding.
!>   - oblique: the same spheres meeting along n = (1, 0.6, -0.3)/|..|,
!>     spinning, frictionless: each centre's speed across n and each spin
!>     unchanged, the normal speeds by the head-on law; momentum to rounding.
!>   - general: two bodies of unequal principal inertias, turned, the
!>     contact point off the line of centres, spinning, with friction (mu =
!>     0.4, e = 0.7): momentum and angular momentum (about the world origin,
!>     the impulse acting at one point on both) kept to rounding, the energy
!>     lost the kinetic energy's fall (to rounding) and >= 0; K against the
!>     bodies' response: an impulse L (+L on body 2, -L on body 1) changes
!>     the points' relative velocity by K L (to rounding); a body 1 of mass
!>     and inertia 1e12 times larger acts as the ground (to 1e-11).
!>   - head_on_flight: the spheres of head_on thrown at each other at one
!>     height 0.5 m apart (centres), e = 0.6: the impact at t* = (0.5 - R1 -
!>     R2)/3 s, the speeds after by the closed form, the gap at every record
!>     the distance of the centres less R1 + R2 (both fall alike), the
!>     pair's horizontal momentum kept and its vertical m g t.
!>   - oblique_flight: the same with ball 2 0.1 m aside: frictionless, each
!>     ball's velocity across the normal at the impact unchanged.
!>   - stacked (inputs/contact/stacked_balls.nml): a small ball dropped with
!>     a big one just below it; the big one bounces off the floor (e_f) and
!>     meets the small one coming down: approach speed (1 + e_f) v0, the
!>     meeting at t0 + gap/((1 + e_f) v0), and the speeds after by the
!>     head-on law with the pair's e; later the small ball falls twice on
!>     the big one resting on the floor: each hit one impact at the hit and
!>     the floor, the rebound e_p of the approach, the floor taking the
!>     whole impulse, the big ball at rest, back after 2 u/g.
!>   - on_carried: a ball dropped centrally onto a ball carried by the
!>     floor (start closed), e = 0.5: one impact at the hit and the floor
!>     (Newton's restitution at each, the floor's 0): the low ball stays at
!>     rest, the floor takes m (1 + e) v, the high ball bounces at e^k v,
!>     impact times t_1 + (2 v/g) (e + .. + e^(k-1)), N = m g between; the
!>     eighth rebound is below close_speed: the contact closes (plastic)
!>     and the stack rests, the floor's N = (m_l + m_h) g, the contact's
!>     m_h g, the poses continuous across the switch, the energy never
!>     rising.
!>   - on_carried_elastic: the same with e = 1, the balls' energy kept.
!>   - on_carried_oblique: dropped 0.05 m aside: the low ball's effective
!>     mass through the floor, P = (1 + e) v cos a/(1/m_h + sin^2 a/m_l),
!>     the low ball sliding off on its closed form, energy kept (e = 1).
!>   - hit_from_below: the law itself: hit from below the floor opens (P =
!>     0, its speed after > 0, the free pair's law at the hit); from above
!>     it takes the whole impulse; in a run both contacts are left open at
!>     gap 0 and the low ball flies to the floor on its parabola.
!>   - carried_law_random: 300 random frictionless hits on a box resting on
!>     three feet: complementarity at every contact, the energy never
!>     rising (kept at e = 1), its fall the rows' sum.
!>   - two_at_once: a ball dropped into a V of two planes at +-30 degrees
!>     lands on both at once: the frictionless impact at two points
!>     (Newton's restitution at each; W's off-diagonal cos60/m) on its
!>     closed form, four bounces as on a floor; the fifth closes both
!>     planes and the ball rests in the V (N = m g/(2 cos30) at each); with
!>     friction the same bounces, each contact slipping
!>     (test_impacts_at_once has the law's closed forms).
program test_body_impact
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t, STATUS_DOMAIN
  use base_vector, only: cross
  use numerics_event_driver, only: driver_result_t, DRIVE_END_TIME, DRIVE_FAILED, RECORD_EVENT
  use kinetostatics_impact, only: impact_law_t
  use contact_body_impact, only: impact_body_t, collision_t, collide, collide_at_once, pair_delassus, &
    relative_velocity, apply_impulse
  use kinetostatics_recorder, only: mechanism_series_t
  use contact_flight, only: flight_ode_t
  use io_input, only: input_text_t, load_input_file
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, run_contact_input, run_contact_text
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity
  real(wp), parameter :: m1 = 0.2_wp, r1 = 0.1_wp, m2 = 0.5_wp, r2 = 0.05_wp
  real(wp), parameter :: rounding = 16*epsilon(1.0_wp)

  call head_on()
  call oblique()
  call general()
  call head_on_flight()
  call oblique_flight()
  call stacked()
  call on_carried()
  call on_carried_elastic()
  call on_carried_oblique()
  call hit_from_below()
  call carried_law_random()
  call two_at_once()
  call finish_tests('test_body_impact')

contains

  !> A solid sphere of mass m and radius r at centre c (its origin there).
  function sphere(m, r, c, v, omega) result(body)
    real(wp), intent(in) :: m, r, c(3), v(3), omega(3)
    type(impact_body_t) :: body
    integer :: i
    body%mass = m
    body%inertia = 0
    do i = 1, 3
      body%inertia(i, i) = 2*m*r**2/5
    end do
    body%origin = c
    body%centre = c
    body%velocity = v
    body%omega = omega
  end function sphere

  !> The velocity of a body's centre of mass.
  pure function centre_velocity(body) result(v)
    type(impact_body_t), intent(in) :: body
    real(wp) :: v(3)
    v = body%velocity + cross(body%omega, body%centre - body%origin)
  end function centre_velocity

  pure function momentum(a, b) result(p)
    type(impact_body_t), intent(in) :: a, b
    real(wp) :: p(3)
    p = a%mass*centre_velocity(a) + b%mass*centre_velocity(b)
  end function momentum

  !> Angular momentum of both about the world origin.
  pure function angular_momentum(a, b) result(h)
    type(impact_body_t), intent(in) :: a, b
    real(wp) :: h(3)
    h = matmul(a%inertia, a%omega) + cross(a%centre, a%mass*centre_velocity(a)) + &
        matmul(b%inertia, b%omega) + cross(b%centre, b%mass*centre_velocity(b))
  end function angular_momentum

  pure real(wp) function kinetic_energy(a, b) result(e)
    type(impact_body_t), intent(in) :: a, b
    e = (a%mass*sum(centre_velocity(a)**2) + dot_product(a%omega, matmul(a%inertia, a%omega)) + &
         b%mass*sum(centre_velocity(b)**2) + dot_product(b%omega, matmul(b%inertia, b%omega)))/2
  end function kinetic_energy

  pure function unit(v) result(u)
    real(wp), intent(in) :: v(3)
    real(wp) :: u(3)
    u = v/norm2(v)
  end function unit

  !> The head-on law along one line: the speeds after (v1, v2 before).
  pure function head_on_law(e, v1, v2) result(after)
    real(wp), intent(in) :: e, v1, v2
    real(wp) :: after(2)
    after(1) = ((m1 - e*m2)*v1 + (1 + e)*m2*v2)/(m1 + m2)
    after(2) = ((m2 - e*m1)*v2 + (1 + e)*m1*v1)/(m1 + m2)
  end function head_on_law

  subroutine head_on()
    real(wp), parameter :: es(3) = [0.0_wp, 0.6_wp, 1.0_wp], v1 = 2, v2 = -1
    real(wp), parameter :: x(3) = [1.0_wp, 0.0_wp, 0.0_wp]
    type(impact_body_t) :: a, b
    type(collision_t) :: hit
    type(status_t) :: st
    real(wp) :: p0(3), after(2)
    integer :: i
    character(len=:), allocatable :: label
    do i = 1, size(es)
      label = 'head on, e = '//number(es(i))//': '
      a = sphere(m1, r1, [0.0_wp, 0.0_wp, 0.0_wp], v1*x, [0.0_wp, 0.0_wp, 0.0_wp])
      b = sphere(m2, r2, (r1 + r2)*x, v2*x, [0.0_wp, 0.0_wp, 0.0_wp])
      p0 = momentum(a, b)
      call collide(impact_law_t(restitution=es(i), mu=0.0_wp), x, r1*x, r1*x, a, b, 1e-3_wp, .false., hit, st)
      call check(st%ok(), label//'resolved: '//st%text())
      after = head_on_law(es(i), v1, v2)
      call check_close(a%velocity(1), after(1), 0.0_wp, rounding*abs(v1), label//'v1'' (m/s)')
      call check_close(b%velocity(1), after(2), 0.0_wp, rounding*abs(v1), label//'v2'' (m/s)')
      call check(all(a%velocity(2:) == 0) .and. all(b%velocity(2:) == 0), label//'along the line only')
      call check(all(a%omega == 0) .and. all(b%omega == 0), label//'no spin (the impulse through the centres)')
      call check_close(hit%energy_lost, (1 - es(i)**2)*m1*m2/(2*(m1 + m2))*(v1 - v2)**2, 0.0_wp, &
                       rounding*m1*v1**2, label//'energy lost (1 - e^2) m1 m2/(2 (m1 + m2)) dv^2 (J)')
      call check_close(hit%outcome%normal_speed_before, v2 - v1, 0.0_wp, 0.0_wp, label//'approach (m/s)')
      call check_close(hit%outcome%normal_speed_after, es(i)*(v1 - v2), 0.0_wp, rounding*abs(v1), &
                       label//'rebound e dv (m/s)')
      call check_close(norm2(momentum(a, b) - p0), 0.0_wp, 0.0_wp, rounding*norm2(p0), &
                       label//'momentum kept (kg m/s)')
      call check(hit%closed .eqv. es(i) == 0, label//'closed (below close_speed 1e-3 m/s) only at e = 0 (the '// &
                 'closing then takes nothing more: the speeds above)')
    end do
  end subroutine head_on

  subroutine oblique()
    real(wp), parameter :: e = 0.6_wp
    type(impact_body_t) :: a, b, a0, b0
    type(collision_t) :: hit
    type(status_t) :: st
    real(wp) :: n(3), p0(3), after(2)
    n = unit([1.0_wp, 0.6_wp, -0.3_wp])
    a = sphere(m1, r1, [0.1_wp, 0.2_wp, 0.3_wp], [2.0_wp, 0.5_wp, 0.3_wp], [3.0_wp, -1.0_wp, 2.0_wp])
    b = sphere(m2, r2, a%centre + (r1 + r2)*n, [-1.0_wp, 0.2_wp, -0.4_wp], [-5.0_wp, 4.0_wp, 1.0_wp])
    a0 = a
    b0 = b
    p0 = momentum(a, b)
    call collide(impact_law_t(restitution=e, mu=0.0_wp), n, a%centre + r1*n, a%centre + r1*n, a, b, 0.01_wp, &
                 .false., hit, st)
    call check(st%ok(), 'oblique: resolved: '//st%text())
    after = head_on_law(e, dot_product(a0%velocity, n), dot_product(b0%velocity, n))
    call check_close(dot_product(a%velocity, n), after(1), 0.0_wp, 4*rounding, 'oblique: a''s normal speed (m/s)')
    call check_close(dot_product(b%velocity, n), after(2), 0.0_wp, 4*rounding, 'oblique: b''s normal speed (m/s)')
    call check_close(norm2(a%velocity - dot_product(a%velocity, n)*n - (a0%velocity - dot_product(a0%velocity, n)*n)), &
                     0.0_wp, 0.0_wp, 4*rounding, 'oblique: a''s speed across n unchanged (m/s)')
    call check_close(norm2(b%velocity - dot_product(b%velocity, n)*n - (b0%velocity - dot_product(b0%velocity, n)*n)), &
                     0.0_wp, 0.0_wp, 4*rounding, 'oblique: b''s speed across n unchanged (m/s)')
    ! the arm along n to rounding: a torque of rounding |L| R, turned into spin by I = 2/5 m R^2
    call check_close(norm2(a%omega - a0%omega) + norm2(b%omega - b0%omega), 0.0_wp, 0.0_wp, &
                     rounding*norm2(hit%impulse)*(r1/(0.4_wp*m1*r1**2) + r2/(0.4_wp*m2*r2**2)), &
                     'oblique: spins unchanged (rad/s, to the rounding of the arm)')
    call check_close(norm2(hit%impulse - dot_product(hit%impulse, n)*n), 0.0_wp, 0.0_wp, rounding*norm2(hit%impulse), &
                     'oblique: no tangential impulse (N s)')
    call check_close(norm2(momentum(a, b) - p0), 0.0_wp, 0.0_wp, rounding*norm2(p0), 'oblique: momentum kept')
  end subroutine oblique

  !> A turned body of principal inertias diag(j) (kg m^2), its centre of
  !> mass `offset` (body axes) from its origin at `origin`.
  function turned_body(m, j, angle, origin, offset, v, omega) result(body)
    real(wp), intent(in) :: m, j(3), angle, origin(3), offset(3), v(3), omega(3)
    type(impact_body_t) :: body
    real(wp) :: rot(3, 3), c, s
    c = cos(angle)
    s = sin(angle)
    ! about the axis (1, 1, 1)/sqrt(3) (Rodrigues)
    rot = reshape([c + (1 - c)/3, (1 - c)/3 + s/sqrt(3.0_wp), (1 - c)/3 - s/sqrt(3.0_wp), &
                   (1 - c)/3 - s/sqrt(3.0_wp), c + (1 - c)/3, (1 - c)/3 + s/sqrt(3.0_wp), &
                   (1 - c)/3 + s/sqrt(3.0_wp), (1 - c)/3 - s/sqrt(3.0_wp), c + (1 - c)/3], [3, 3])
    body%mass = m
    body%inertia = matmul(rot, matmul(reshape([j(1), 0.0_wp, 0.0_wp, 0.0_wp, j(2), 0.0_wp, 0.0_wp, 0.0_wp, j(3)], &
                                              [3, 3]), transpose(rot)))
    body%origin = origin
    body%centre = origin + matmul(rot, offset)
    body%velocity = v
    body%omega = omega
  end function turned_body

  subroutine general()
    type(impact_body_t) :: a, b, a0, b0, ground, heavy, b_ground, b_heavy
    type(collision_t) :: hit, on_ground, on_heavy
    type(status_t) :: st
    real(wp) :: n(3), point(3), p0(3), h0(3), e0, k(3, 3), impulse(3), v0(3)
    n = unit([0.2_wp, -0.3_wp, 1.0_wp])
    point = [0.05_wp, -0.02_wp, 0.4_wp]
    a = turned_body(1.3_wp, [0.02_wp, 0.05_wp, 0.07_wp], 0.7_wp, [0.0_wp, 0.1_wp, 0.2_wp], &
                    [0.03_wp, -0.01_wp, 0.02_wp], [0.5_wp, -0.2_wp, 1.5_wp], [4.0_wp, -2.0_wp, 1.0_wp])
    b = turned_body(0.4_wp, [0.004_wp, 0.006_wp, 0.003_wp], -1.1_wp, [0.1_wp, -0.1_wp, 0.55_wp], &
                    [-0.02_wp, 0.01_wp, 0.0_wp], [-0.7_wp, 0.9_wp, -2.0_wp], [-3.0_wp, 6.0_wp, 2.0_wp])
    a0 = a
    b0 = b
    ! K against the bodies' response to an impulse: linear, K L exactly
    impulse = [0.3_wp, -0.7_wp, 0.2_wp]
    k = pair_delassus(a, b, point, point)
    v0 = relative_velocity(a, b, point, point)
    call apply_impulse(b, point, impulse, st)
    call apply_impulse(a, point, -impulse, st)
    call check(st%ok(), 'general: impulses applied')
    call check_close(norm2(relative_velocity(a, b, point, point) - v0 - matmul(k, impulse)), 0.0_wp, 0.0_wp, &
                     4*rounding*norm2(v0), 'general: the relative velocity changes by K L (m/s)')
    call check_close(maxval(abs(k - transpose(k))), 0.0_wp, 0.0_wp, rounding*maxval(abs(k)), 'general: K symmetric')
    a = a0
    b = b0
    p0 = momentum(a, b)
    h0 = angular_momentum(a, b)
    e0 = kinetic_energy(a, b)
    call check(dot_product(n, relative_velocity(a, b, point, point)) < 0, 'general: the points approach')
    call collide(impact_law_t(restitution=0.7_wp, mu=0.4_wp), n, point, point, a, b, 0.01_wp, .false., hit, st)
    call check(st%ok(), 'general: resolved: '//st%text())
    call check(norm2(hit%impulse - dot_product(hit%impulse, n)*n) > 1e-3_wp*norm2(hit%impulse), &
               'general: friction acts (a tangential impulse)')
    call check_close(norm2(momentum(a, b) - p0), 0.0_wp, 0.0_wp, rounding*norm2(p0), 'general: momentum kept')
    call check_close(norm2(angular_momentum(a, b) - h0), 0.0_wp, 0.0_wp, rounding*norm2(h0), &
                     'general: angular momentum about the origin kept')
    call check(hit%energy_lost >= 0, 'general: energy lost >= 0')
    call check_close(e0 - kinetic_energy(a, b), hit%energy_lost, 0.0_wp, rounding*e0, &
                     'general: the energy lost is the kinetic energy''s fall (J)')
    ! a body 1 1e12 times heavier is the ground (both at rest there)
    ground = impact_body_t()
    heavy = a0
    heavy%mass = 1e12_wp*a0%mass
    heavy%inertia = 1e12_wp*a0%inertia
    heavy%velocity = 0
    heavy%omega = 0
    b_ground = b0
    b_heavy = b0
    call collide(impact_law_t(restitution=0.7_wp, mu=0.4_wp), n, point, point, ground, b_ground, 0.01_wp, .false., &
                 on_ground, st)
    call collide(impact_law_t(restitution=0.7_wp, mu=0.4_wp), n, point, point, heavy, b_heavy, 0.01_wp, .false., &
                 on_heavy, st)
    call check(st%ok(), 'general: on the ground and on a heavy body: resolved')
    call check_close(norm2(b_ground%velocity - b_heavy%velocity) + norm2(b_ground%omega - b_heavy%omega)*0.1_wp, &
                     0.0_wp, 0.0_wp, 1e-11_wp*norm2(b0%velocity), 'general: a heavy body 1 acts as the ground')
    call check(ground%mass == 0 .and. all(ground%velocity == 0) .and. all(ground%omega == 0), &
               'general: the ground does not move')
  end subroutine general

  !> The contact scenario's groups of two balls 'a' (m1, r1) and 'b' (m2,
  !> r2) at height 1 m, b at (0.5, aside, 1), thrown at each other (2 and -1
  !> m/s along x), the contact 'a_b' between them (restitution e); no floor.
  function pair_input(aside, e) result(text)
    real(wp), intent(in) :: aside, e
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 0.3, output_step = 0.01 /'//nl// &
           '&shape name = ''a'', kind = ''sphere'', radius = '//number(r1)//' /'//nl// &
           '&shape name = ''b'', kind = ''sphere'', radius = '//number(r2)//' /'//nl// &
           '&body name = ''a'', mass = '//number(m1)//', solid_of = ''a'', position = 0, 0, 1, velocity = 2, 0, 0 /'// &
           nl//'&body name = ''b'', mass = '//number(m2)//', solid_of = ''b'', position = 0.5, '//number(aside)// &
           ', 1, velocity = -1, 0, 0 /'//nl// &
           '&contact name = ''a_b'', body_1 = ''a'', shape_1 = ''a'', body_2 = ''b'', shape_2 = ''b'', '// &
           'start = ''open'', restitution = '//number(e)//' /'//nl
  end function pair_input

  subroutine head_on_flight()
    real(wp), parameter :: e = 0.6_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: t_hit, after(2), gap, worst_gap, worst_p, worst_v, worst_spin, p0(3), p(3)
    integer :: i
    call run_contact_text(pair_input(0.0_wp, e), 'head on flight', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'head on flight: runs to its end: '//st%text()// &
               ' '//flight%outcome)
    if (.not. st%ok()) return
    t_hit = (0.5_wp - r1 - r2)/3
    after = head_on_law(e, 2.0_wp, -1.0_wp)
    call check(size(flight%impacts) == 1, 'head on flight: one impact')
    if (size(flight%impacts) /= 1) return
    associate (row => flight%impacts(1))
      call check(row%contact == 1 .and. row%body_1 == 1 .and. row%body_2 == 2, 'head on flight: between a and b')
      call check_close(row%time, t_hit, 0.0_wp, 1e-10_wp, 'head on flight: at t* = (0.5 - R1 - R2)/3 (s)')
      call check_close(row%normal_speed_before, -3.0_wp, 0.0_wp, 1e-10_wp, 'head on flight: approach 3 m/s')
      call check_close(row%normal_speed_after, 3*e, 0.0_wp, 1e-10_wp, 'head on flight: rebound 3 e (m/s)')
      call check_close(row%normal_impulse, m2*(after(2) + 1), 0.0_wp, 1e-10_wp, &
                       'head on flight: impulse m2 (v2'' - v2) (N s)')
      call check_close(row%tangential_impulse, 0.0_wp, 0.0_wp, 1e-12_wp, 'head on flight: no tangential impulse')
      call check_close(row%energy_lost, (1 - e**2)*m1*m2/(2*(m1 + m2))*9, 0.0_wp, 1e-10_wp, &
                       'head on flight: energy lost (1 - e^2) m1 m2 dv^2/(2 (m1 + m2)) (J)')
    end associate
    worst_gap = 0
    worst_p = 0
    worst_v = 0
    worst_spin = 0
    associate (s => flight%series)
      p0 = m1*s%body_v(:, 1, 1) + m2*s%body_v(:, 2, 1)
      do i = 1, s%n
        if (s%time(i) < t_hit) then
          gap = 0.5_wp - 3*s%time(i) - r1 - r2
        else
          gap = (after(2) - after(1))*(s%time(i) - t_hit)
          worst_v = max(worst_v, abs(s%body_v(1, 1, i) - after(1)), abs(s%body_v(1, 2, i) - after(2)))
        end if
        worst_gap = max(worst_gap, abs(s%monitor(1, i) - gap))
        p = m1*s%body_v(:, 1, i) + m2*s%body_v(:, 2, i)
        worst_p = max(worst_p, norm2(p - p0 - [0.0_wp, 0.0_wp, -(m1 + m2)*g*s%time(i)]))
        worst_spin = max(worst_spin, maxval(abs(s%body_omega(:, :, i))))
      end do
      call check(s%time(s%n) == 0.3_wp, 'head on flight: to 0.3 s')
    end associate
    call check_close(worst_gap, 0.0_wp, 0.0_wp, 1e-10_wp, 'head on flight: the gap at every record (m)')
    call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-10_wp, 'head on flight: the speeds after by the closed form')
    call check_close(worst_p, 0.0_wp, 0.0_wp, 1e-10_wp, 'head on flight: momentum p0 + (m1 + m2) g t')
    call check_close(worst_spin, 0.0_wp, 0.0_wp, 1e-10_wp, 'head on flight: no spin (rad/s)')
    print '(a, 4es10.2)', '  head on flight: gap, speeds, momentum, spin ', worst_gap, worst_v, worst_p, worst_spin
  end subroutine head_on_flight

  subroutine oblique_flight()
    real(wp), parameter :: e = 0.8_wp, aside = 0.1_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: t_hit, n(3), after(2), va(3), vb(3), worst
    integer :: i
    call run_contact_text(pair_input(aside, e), 'oblique flight', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'oblique flight: runs to its end: '//st%text())
    if (.not. st%ok()) return
    n = [sqrt((r1 + r2)**2 - aside**2), aside, 0.0_wp]/(r1 + r2)
    t_hit = (0.5_wp - n(1)*(r1 + r2))/3
    call check(size(flight%impacts) == 1, 'oblique flight: one impact')
    if (size(flight%impacts) /= 1) return
    call check_close(flight%impacts(1)%time, t_hit, 0.0_wp, 1e-10_wp, 'oblique flight: the impact''s time (s)')
    call check_close(flight%impacts(1)%tangential_impulse, 0.0_wp, 0.0_wp, 1e-12_wp, &
                     'oblique flight: no tangential impulse')
    after = head_on_law(e, 2*n(1), -n(1))
    worst = 0
    associate (s => flight%series)
      i = findloc(s%time(:s%n), flight%impacts(1)%time, dim=1)
      call check(i > 0, 'oblique flight: the impact recorded')
      if (i == 0) return
      ! the state after the impact; the vertical speed -g t* of both
      va = s%body_v(:, 1, i) + [0.0_wp, 0.0_wp, g*t_hit]
      vb = s%body_v(:, 2, i) + [0.0_wp, 0.0_wp, g*t_hit]
      worst = max(norm2(va - dot_product(va, n)*n - ([2.0_wp, 0.0_wp, 0.0_wp] - 2*n(1)*n)), &
                  norm2(vb - dot_product(vb, n)*n - ([-1.0_wp, 0.0_wp, 0.0_wp] + n(1)*n)), &
                  abs(dot_product(va, n) - after(1)), abs(dot_product(vb, n) - after(2)))
    end associate
    call check_close(worst, 0.0_wp, 0.0_wp, 1e-10_wp, 'oblique flight: speeds across n kept, along n by the '// &
                     'head-on law (m/s)')
    print '(a, es10.2)', '  oblique flight: speeds after ', worst
  end subroutine oblique_flight

  !> inputs/contact/stacked_balls.nml against the closed form of its
  !> first two impacts: the big ball on the floor at t0 = sqrt(2 h/g), the
  !> small ball, gap d above it and still falling at v0 = g t0, met at t0 +
  !> d/((1 + e_f) v0) (the approach speed (1 + e_f) v0: gravity moves both
  !> alike), each then at its speed by the head-on law.
  subroutine stacked()
    real(wp), parameter :: h = 1.0_wp, d = 0.01_wp, e_f = 0.8_wp, e_p = 0.9_wp, mb = 0.6_wp, ms = 0.057_wp
    type(input_text_t) :: input
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: t0, v0, s, ub, us, ub_after, us_after, worst_speed, worst_p
    integer :: i, k
    integer, allocatable :: hits(:)
    call load_input_file('inputs/contact/stacked_balls.nml', input, st)
    if (st%ok()) call run_contact_input(input, flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'stacked: runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    t0 = sqrt(2*h/g)
    v0 = g*t0
    s = d/((1 + e_f)*v0)
    ub = e_f*v0 - g*s
    us = -v0 - g*s
    ub_after = ((mb - e_p*ms)*ub + (1 + e_p)*ms*us)/(mb + ms)
    us_after = ((ms - e_p*mb)*us + (1 + e_p)*mb*ub)/(mb + ms)
    call check(size(flight%impacts) >= 2, 'stacked: the floor''s impact and the pair''s')
    if (size(flight%impacts) < 2) return
    associate (floor => flight%impacts(1), pair => flight%impacts(2))
      call check(floor%contact == 1 .and. floor%body_1 == 0 .and. floor%body_2 == 1, 'stacked: first the big '// &
                 'ball on the floor')
      call check_close(floor%time, t0, 0.0_wp, 1e-9_wp, 'stacked: the big ball lands at sqrt(2 h/g) (s)')
      call check(pair%contact == 2 .and. pair%body_1 == 1 .and. pair%body_2 == 2, 'stacked: then the small '// &
                 'ball on the big one (body_1 big, body_2 small)')
      call check_close(pair%time, t0 + s, 0.0_wp, 1e-9_wp, 'stacked: they meet at t0 + d/((1 + e_f) v0) (s)')
      call check_close(pair%normal_speed_before, us - ub, 0.0_wp, 1e-8_wp, 'stacked: approach (1 + e_f) v0 (m/s)')
      call check_close(pair%normal_speed_after, e_p*(ub - us), 0.0_wp, 1e-8_wp, 'stacked: rebound e_p dv (m/s)')
      call check_close(pair%normal_impulse, ms*(us_after - us), 0.0_wp, 1e-8_wp, 'stacked: impulse on the small '// &
                       'ball m_s (u_s'' - u_s) (N s)')
      call check_close(pair%energy_lost, (1 - e_p**2)*mb*ms/(2*(mb + ms))*(ub - us)**2, 0.0_wp, 1e-8_wp, &
                       'stacked: energy lost (J)')
      i = findloc(flight%series%time(:flight%series%n), pair%time, dim=1)
      call check(i > 0, 'stacked: the pair''s impact recorded')
      if (i == 0) return
      call check_close(flight%series%body_v(3, 2, i), us_after, 0.0_wp, 1e-8_wp, 'stacked: the small ball '// &
                       'leaves at the head-on law''s speed (m/s)')
      call check_close(flight%series%body_v(3, 1, i), ub_after, 0.0_wp, 1e-8_wp, 'stacked: the big ball '// &
                       'leaves at the head-on law''s speed (m/s)')
      print '(a, 2f9.4)', '  stacked: the speeds after (m/s) ', us_after, ub_after
    end associate
    call check(size(flight%impacts) == 27 .and. flight%series%time(flight%series%n) == 5.5_wp, 'stacked: to 5.5 '// &
               's, 27 impact rows')
    ! the hits on the big ball resting on the floor (closed at its Zeno sum)
    hits = pack([(i, i = 1, size(flight%impacts))], flight%impacts%contact == 2 .and. flight%impacts%time > 3)
    call check(size(hits) == 2, 'stacked: the small ball falls twice on the resting big one')
    if (size(hits) /= 2) return
    worst_speed = 0
    worst_p = 0
    do k = 1, 2
      associate (hit => flight%impacts(hits(k)), floor => flight%impacts(hits(k) - 1))
        call check(floor%contact == 1 .and. floor%time == hit%time .and. hit%body_1 == 1 .and. hit%body_2 == 2, &
                   'stacked: each hit one impact at the hit and the floor')
        worst_speed = max(worst_speed, abs(hit%normal_speed_after + e_p*hit%normal_speed_before), &
                          abs(floor%normal_speed_before), abs(floor%normal_speed_after))
        worst_p = max(worst_p, abs(hit%normal_impulse + ms*(1 + e_p)*hit%normal_speed_before), &
                      abs(floor%normal_impulse - hit%normal_impulse))
        i = findloc(flight%series%time(:flight%series%n), hit%time, dim=1, back=.true.)
        worst_speed = max(worst_speed, abs(flight%series%body_v(3, 1, i)), abs(flight%series%body_r(3, 1, i) - 0.12_wp))
      end associate
    end do
    call check_close(worst_speed, 0.0_wp, 0.0_wp, 1e-9_wp, 'stacked: rebound e_p of the approach, the floor''s '// &
                     'speed 0 before and after, the big ball at rest after (m/s)')
    call check_close(worst_p, 0.0_wp, 0.0_wp, 1e-9_wp, 'stacked: the floor takes the hit''s whole impulse m_s (1 '// &
                     '+ e_p) v (N s)')
    ! the small ball's flight from the first hit back onto the resting big one: 2 u/g
    call check_close(flight%impacts(hits(2))%time - flight%impacts(hits(1))%time, &
                     2*flight%impacts(hits(1))%normal_speed_after/g, 0.0_wp, 1e-9_wp, 'stacked: back after 2 u/g (s)')
    call check_close(flight%impacts(hits(2))%normal_speed_before, -flight%impacts(hits(1))%normal_speed_after, &
                     0.0_wp, 1e-9_wp, 'stacked: back at the speed it left (m/s)')
    print '(a, 2es10.2)', '  stacked: the hits on the resting ball, speeds and impulses ', worst_speed, worst_p
  end subroutine stacked

  !> The groups of a ball 'high' (0.05 m, 0.1 kg) dropped from rest at
  !> (dx, 0, 0.55) onto a ball 'low' (0.1 m, 1 kg) that the frictionless
  !> floor carries (start closed, its centre at (0, 0, 0.1)); the contact
  !> 'high_on_low' between them (restitution e). `extra`: more groups.
  function carried_input(dx, e, duration, extra) result(text)
    real(wp), intent(in) :: dx, e, duration
    character(len=*), intent(in) :: extra
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = '//number(duration)//', output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''low'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&shape name = ''high'', kind = ''sphere'', radius = 0.05 /'//nl// &
           '&body name = ''low'', mass = 1, solid_of = ''low'', position = 0, 0, 0.1 /'//nl// &
           '&body name = ''high'', mass = 0.1, solid_of = ''high'', position = '//number(dx)//', 0, 0.55 /'//nl// &
           '&contact name = ''low_on_floor'', shape_1 = ''floor'', body_2 = ''low'', shape_2 = ''low'' '//extra// &
           ' /'//nl//'&contact name = ''high_on_low'', body_1 = ''low'', shape_1 = ''low'', body_2 = ''high'', '// &
           'shape_2 = ''high'', start = ''open'', restitution = '//number(e)//' /'//nl
  end function carried_input

  !> The energy of the balls of carried_input at record i (J): kinetic,
  !> spin included, and potential.
  real(wp) function balls_energy(s, i) result(energy)
    type(mechanism_series_t), intent(in) :: s
    integer, intent(in) :: i
    real(wp), parameter :: mass(2) = [1.0_wp, 0.1_wp], radius(2) = [0.1_wp, 0.05_wp]
    integer :: b
    energy = 0
    do b = 1, 2
      energy = energy + mass(b)*(sum(s%body_v(:, b, i)**2)/2 + g*s%body_r(3, b, i)) + &
               mass(b)*radius(b)**2*sum(s%body_omega(:, b, i)**2)/5
    end do
  end function balls_energy

  !> Complementarity at the impact rows of the contact `floor` (1): each
  !> normal impulse >= 0, its separation speed after >= 0, one of them 0
  !> (to the speeds' rounding); returns the worst breach (m/s or N s).
  real(wp) function floor_complementarity(flight, floor, scale) result(worst)
    type(flight_ode_t), intent(in) :: flight
    integer, intent(in) :: floor
    real(wp), intent(in) :: scale   ! N s and m/s: the impact's size
    integer :: i
    worst = 0
    do i = 1, size(flight%impacts)
      associate (row => flight%impacts(i))
        if (row%contact /= floor) cycle
        worst = max(worst, -row%normal_impulse, -row%normal_speed_after, &
                    min(row%normal_impulse, abs(row%normal_speed_after)))
      end associate
    end do
    worst = worst/scale
  end function floor_complementarity

  !> A ball dropped centrally from 0.3 m above the top of a ball that the
  !> floor carries, e = 0.5 (the simultaneous impact: Newton's restitution
  !> at the hit and at the floor, the floor's restitution 0 as a carrying
  !> contact's): the low ball stays at rest, the floor takes the whole
  !> impulse m (1 + e) v, the high ball leaves at e v; so it bounces on the
  !> resting ball at t_k = t_1 + (2 v/g) (e + .. + e^(k-1)), t_1 = sqrt(2
  !> h/g), approach e^(k-1) v, and between the impacts the floor carries the
  !> low ball alone, N = m g. The eighth rebound, e^8 v, is below the
  !> contact's close_speed (0.01 m/s): the contact closes there (plastic:
  !> the hit's and the floor's impulse m e^7 v, all of m (e^7 v)^2/2 lost at
  !> the hit) and the stack rests to the end: the high ball on the low one,
  !> the floor's N = (m_l + m_h) g, the contact's N = m_h g (1e-9
  !> relative), the balls' poses the same in the records before and after
  !> the switch (1e-12), the balls' energy never rising.
  subroutine on_carried()
    real(wp), parameter :: e = 0.5_wp, h = 0.3_wp, m = 0.1_wp, ml = 1
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: v, t_k, v_k, worst_low, worst_n, worst_time, worst_speed, worst_p, worst_lost, worst_rest, &
                worst_switch, worst_rise
    integer :: i, k, floor_c, hit_c, j, high, low
    call run_contact_text(carried_input(0.0_wp, e, 1.0_wp, ''), 'on carried', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'on carried: runs to its end: '//st%text()// &
               ' '//flight%outcome)
    call check(index(flight%outcome, 'body ''high'' lands on ''high_on_low'' at t = ') > 0 .and. &
               index(flight%outcome, 'while ''low_on_floor'' carries ''low'': one impact at them all, after it '// &
               '''low_on_floor'', ''high_on_low'' closed') > 0, 'on carried: the outcome says the contact '// &
               'closed: '//flight%outcome)
    v = sqrt(2*g*h)
    call check(size(flight%impacts) == 16, 'on carried: eight impacts, a row at the floor and at the hit each')
    if (size(flight%impacts) /= 16) return
    worst_time = 0
    worst_speed = 0
    worst_p = 0
    worst_lost = 0
    t_k = sqrt(2*h/g)
    do k = 1, 8
      v_k = e**(k - 1)*v
      associate (floor => flight%impacts(2*k - 1), hit => flight%impacts(2*k))
        call check(floor%contact == 1 .and. floor%body_1 == 0 .and. floor%body_2 == 1 .and. hit%contact == 2 .and. &
                   hit%body_1 == 1 .and. hit%body_2 == 2 .and. floor%time == hit%time, 'on carried: impact '// &
                   number(real(k, wp))//' at the floor and the hit at once')
        worst_time = max(worst_time, abs(hit%time - t_k))
        worst_speed = max(worst_speed, abs(hit%normal_speed_before + v_k), abs(floor%normal_speed_before), &
                          abs(floor%normal_speed_after))
        if (k < 8) then
          worst_speed = max(worst_speed, abs(hit%normal_speed_after - e*v_k))
          worst_p = max(worst_p, abs(hit%normal_impulse - m*(1 + e)*v_k), abs(floor%normal_impulse - m*(1 + e)*v_k))
          worst_lost = max(worst_lost, abs(hit%energy_lost - (1 - e**2)*m*v_k**2/2), abs(floor%energy_lost))
        else   ! the closing: plastic
          worst_speed = max(worst_speed, abs(hit%normal_speed_after))
          worst_p = max(worst_p, abs(hit%normal_impulse - m*v_k), abs(floor%normal_impulse - m*v_k))
          worst_lost = max(worst_lost, abs(hit%energy_lost - m*v_k**2/2), abs(floor%energy_lost))
        end if
      end associate
      t_k = t_k + 2*e**k*v/g
    end do
    call check_close(worst_time, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried: the impacts at t_1 + (2 v/g) (e + .. + '// &
                     'e^(k-1)) (s)')
    ! the speeds to g times the times' tolerance (an impact found 1e-9 s off meets the ball g 1e-9 m/s off)
    call check_close(worst_speed, 0.0_wp, 0.0_wp, 1e-9_wp*g, 'on carried: approach e^(k-1) v, rebound e^k v at '// &
                     'the hit (0 at the eighth, closing), the floor''s normal speed 0 before and after (m/s)')
    call check_close(worst_p, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried: the impulse m (1 + e) e^(k-1) v at the hit '// &
                     'and at the floor, m e^7 v at the closing (N s)')
    call check_close(worst_lost, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried: the energy (1 - e^2) m (e^(k-1) v)^2/2 '// &
                     'lost at the hit (all of it at the closing), none at the floor (J)')
    call check_close(floor_complementarity(flight, 1, m*v), 0.0_wp, 0.0_wp, rounding, 'on carried: the floor''s '// &
                     'impulse >= 0, its speed after >= 0, one of them 0')
    worst_low = 0
    worst_n = 0
    worst_rest = 0
    worst_rise = 0
    worst_switch = huge(1.0_wp)
    associate (s => flight%series)
      floor_c = findloc(s%contact_names, 'low_on_floor', dim=1)
      hit_c = findloc(s%contact_names, 'high_on_low', dim=1)
      low = findloc(s%body_names, 'low', dim=1)
      high = findloc(s%body_names, 'high', dim=1)
      call check(floor_c > 0 .and. hit_c > 0 .and. low == 1 .and. high == 2, 'on carried: both contacts'' normal '// &
                 'forces recorded, the balls in their order')
      if (floor_c == 0 .or. hit_c == 0 .or. low /= 1 .or. high /= 2) return
      ! the switch at the eighth impact: the records before and after it
      j = findloc(s%time(:s%n), flight%impacts(16)%time, dim=1, back=.true.)
      call check(j > 1, 'on carried: the records at the closing')
      if (j < 2) return
      call check(s%time(j - 1) == s%time(j) .and. s%kind(j) == RECORD_EVENT, 'on carried: the records before and '// &
                 'after the closing, the second an event')
      ! the poses (the twists change by the impact: after it, on the closed forms below)
      worst_switch = max(maxval(abs(s%body_r(:, :, j) - s%body_r(:, :, j - 1))), &
                         maxval(abs(s%body_rot(:, :, :, j) - s%body_rot(:, :, :, j - 1))))
      do i = 1, s%n
        worst_low = max(worst_low, abs(s%body_r(3, 1, i) - 0.1_wp), norm2(s%body_r(1:2, 1, i)), &
                        norm2(s%body_v(:, 1, i)), norm2(s%body_omega(:, 1, i)))
        if (i > 1) worst_rise = max(worst_rise, balls_energy(s, i) - balls_energy(s, i - 1))
        if (i < j) then
          worst_n = max(worst_n, abs(s%normal(floor_c, i) - ml*g)/(ml*g))
          cycle
        end if
        worst_n = max(worst_n, abs(s%normal(floor_c, i) - (ml + m)*g)/((ml + m)*g), &
                      abs(s%normal(hit_c, i) - m*g)/(m*g))
        ! its spin as its surface's speed, 0.05 |omega| (the impacts' rounding left ~1e-11 rad/s)
        worst_rest = max(worst_rest, abs(s%body_r(3, 2, i) - 0.25_wp), norm2(s%body_r(1:2, 2, i)), &
                         norm2(s%body_v(:, 2, i)), 0.05_wp*norm2(s%body_omega(:, 2, i)))
      end do
      call check(s%time(s%n) == 1.0_wp, 'on carried: the stack rests to the end (1 s)')
    end associate
    call check_close(worst_switch, 0.0_wp, 0.0_wp, 1e-12_wp, 'on carried: the balls'' poses the same before and '// &
                     'after the closing (m)')
    call check_close(worst_low, 0.0_wp, 0.0_wp, 1e-12_wp, 'on carried: the low ball at rest on the floor at '// &
                     'every record (m, m/s, rad/s)')
    call check_close(worst_rest, 0.0_wp, 0.0_wp, 1e-12_wp, 'on carried: the high ball at rest on the low one '// &
                     'after the closing (m, m/s, its spin r |omega| m/s)')
    call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried: the floor carries the low ball, N = m_l g, '// &
                     'then both, (m_l + m_h) g, the contact N = m_h g (relative)')
    call check(worst_rise <= 1e-9_wp*balls_energy(flight%series, 1), 'on carried: the balls'' energy never rises '// &
               '(1e-9 of it)')
    print '(a, 9es10.2)', '  on carried: time, speed, impulse, energy, low, N, rest, switch, rise ', worst_time, &
      worst_speed, worst_p, worst_lost, worst_low, worst_n, worst_rest, worst_switch, worst_rise
  end subroutine on_carried

  !> on_carried with e = 1 for 2 s: the high ball bounces on the resting
  !> low one at t_1 + 2 (k - 1) v/g, back at v each time, the balls' energy
  !> kept at every record (frictionless, elastic: 1e-9 of it), the run to
  !> its end.
  subroutine on_carried_elastic()
    real(wp), parameter :: h = 0.3_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: v, e0, worst_e, worst_t, worst_v
    integer :: i, k
    call run_contact_text(carried_input(0.0_wp, 1.0_wp, 2.0_wp, ''), 'on carried elastic', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'on carried elastic: runs to its end: '// &
               st%text()//' '//flight%outcome)
    if (.not. st%ok()) return
    v = sqrt(2*g*h)
    call check(size(flight%impacts) == 8, 'on carried elastic: four impacts, each at the floor and the hit')
    if (size(flight%impacts) /= 8) return
    worst_t = 0
    worst_v = 0
    do k = 1, 4
      worst_t = max(worst_t, abs(flight%impacts(2*k)%time - sqrt(2*h/g) - 2*(k - 1)*v/g))
      worst_v = max(worst_v, abs(flight%impacts(2*k)%normal_speed_before + v), &
                    abs(flight%impacts(2*k)%normal_speed_after - v), abs(flight%impacts(2*k)%energy_lost), &
                    abs(flight%impacts(2*k - 1)%energy_lost))
    end do
    worst_e = 0
    associate (s => flight%series)
      e0 = balls_energy(s, 1)
      do i = 1, s%n
        worst_e = max(worst_e, abs(balls_energy(s, i) - e0))
      end do
      call check(s%time(s%n) == 2.0_wp, 'on carried elastic: to 2 s')
    end associate
    call check_close(worst_t, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried elastic: impacts at t_1 + 2 (k - 1) v/g (s)')
    call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried elastic: back at v, no energy lost')
    call check_close(worst_e, 0.0_wp, 0.0_wp, 1e-9_wp*e0, 'on carried elastic: the balls'' energy kept (J)')
    print '(a, 3es10.2)', '  on carried elastic: times, speeds, energy ', worst_t, worst_v, worst_e
  end subroutine on_carried_elastic

  !> The high ball dropped 0.05 m aside (the normal n = (sin a, 0, cos a)
  !> at the touch, sin a = 1/3) onto the low ball on the frictionless floor,
  !> e = 1: the low ball can move only along the floor, so the hit meets
  !> its effective mass through its closed contact: the normal impulse
  !> P = (1 + e) v cos a/(1/m_h + sin^2 a/m_l), the floor's P cos a (its
  !> speed after 0), the low ball sliding away at -P sin a/m_l without
  !> spin, the high one leaving at (0, 0, -v) + P n/m_h; then the low ball
  !> on x = -P sin a/m_l (t - t_h), z = 0.1 to the end, and the balls'
  !> energy kept at every record (1e-9 of it).
  subroutine on_carried_oblique()
    real(wp), parameter :: dx = 0.05_wp, ml = 1, mh = 0.1_wp, e = 1
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: sin_a, cos_a, n(3), z_hit, v, t_hit, p, u, e0, worst_e, worst_low, worst_high, high_after(3)
    integer :: i, j
    call run_contact_text(carried_input(dx, e, 0.5_wp, ''), 'on carried oblique', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'on carried oblique: runs to its end: '// &
               st%text()//' '//flight%outcome)
    if (.not. st%ok()) return
    sin_a = dx/0.15_wp
    cos_a = sqrt(1 - sin_a**2)
    n = [sin_a, 0.0_wp, cos_a]
    z_hit = 0.1_wp + 0.15_wp*cos_a
    v = sqrt(2*g*(0.55_wp - z_hit))
    t_hit = v/g
    p = (1 + e)*v*cos_a/(1/mh + sin_a**2/ml)
    u = -p*sin_a/ml
    high_after = [0.0_wp, 0.0_wp, -v] + p*n/mh
    call check(size(flight%impacts) == 2, 'on carried oblique: one impact, at the floor and the hit')
    if (size(flight%impacts) /= 2) return
    associate (floor => flight%impacts(1), hit => flight%impacts(2))
      call check_close(hit%time, t_hit, 0.0_wp, 1e-9_wp, 'on carried oblique: the touch at v/g (s)')
      call check_close(hit%normal_speed_before, -v*cos_a, 0.0_wp, 1e-9_wp, 'on carried oblique: approach v cos a')
      call check_close(hit%normal_impulse, p, 0.0_wp, 1e-9_wp, 'on carried oblique: P = (1 + e) v cos a/(1/m_h '// &
                       '+ sin^2 a/m_l) (N s)')
      call check_close(hit%normal_speed_after, v*cos_a, 0.0_wp, 1e-9_wp, 'on carried oblique: rebound e v cos a')
      call check_close(floor%normal_impulse, p*cos_a, 0.0_wp, 1e-9_wp, 'on carried oblique: the floor''s P cos a')
      call check_close(floor%normal_speed_after, 0.0_wp, 0.0_wp, 1e-12_wp, 'on carried oblique: the floor stays '// &
                       'closed (its speed after 0)')
    end associate
    worst_e = 0
    worst_low = 0
    worst_high = 0
    associate (s => flight%series)
      e0 = balls_energy(s, 1)
      j = findloc(s%time(:s%n), flight%impacts(1)%time, dim=1, back=.true.)
      call check(j > 1 .and. s%time(j - 1) == s%time(j), 'on carried oblique: the records before and after the '// &
                 'impact')
      if (j < 2) return
      worst_high = norm2(s%body_v(:, 2, j) - high_after)
      do i = 1, s%n
        worst_e = max(worst_e, abs(balls_energy(s, i) - e0))
        if (i < j) cycle
        worst_low = max(worst_low, abs(s%body_r(1, 1, i) - u*(s%time(i) - t_hit)), abs(s%body_r(3, 1, i) - 0.1_wp), &
                        norm2(s%body_v(:, 1, i) - [u, 0.0_wp, 0.0_wp]), norm2(s%body_omega(:, 1, i)))
      end do
      call check(s%time(s%n) == 0.5_wp, 'on carried oblique: to 0.5 s')
    end associate
    call check_close(worst_high, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried oblique: the high ball leaves at (0, 0, -v) '// &
                     '+ P n/m_h (m/s)')
    call check_close(worst_low, 0.0_wp, 0.0_wp, 1e-9_wp, 'on carried oblique: the low ball slides on x = -P sin '// &
                     'a/m_l (t - t_h), z = 0.1, without spin')
    call check_close(worst_e, 0.0_wp, 0.0_wp, 1e-9_wp*e0, 'on carried oblique: the balls'' energy kept (J)')
    print '(a, 3es10.2)', '  on carried oblique: high, low, energy ', worst_high, worst_low, worst_e
  end subroutine on_carried_oblique

  !> The law at a carried body hit from below: the low ball at rest on the
  !> floor (its carrying contact, restitution 0) hit by the high ball coming
  !> up along -n, n = (sin a, 0, -cos a) out of the low ball at a = 75 deg
  !> (contact_body_impact collide_at_once, the contacts the flight gives
  !> it): the hit lifts the low ball, so the floor takes nothing and opens
  !> (P = 0, its speed after P_h cos a/m_l > 0) and the hit is the free
  !> pair's head-on law, P_h = (1 + e) u/(1/m_l + 1/m_h); the centrally
  !> dropped ball of on_carried at the law's level: the floor takes
  !> P_h (its speed after 0). Then, in a run, the floor (may_open) and the
  !> hit both left open at gap 0, each watched from its opening: the low
  !> ball leaves at -P_h n/m_l, flies the parabola and lands on the floor
  !> again at 2 v_z/g after the hit (no restitution: the run ends there).
  subroutine hit_from_below()
    real(wp), parameter :: ml = 1, mh = 0.1_wp, e = 0.5_wp, u = 2
    type(impact_body_t) :: bodies(0:2)
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: a, n(3), normals(3, 2), points_1(3, 2), points_2(3, 2), ph, low(3), v_low(3), worst
    integer :: i, j
    real(wp), dimension(2) :: impulse, tangential, before, after, lost
    character(len=:), allocatable :: text
    a = 75*acos(-1.0_wp)/180
    n = [sin(a), 0.0_wp, -cos(a)]
    low = [0.0_wp, 0.0_wp, 0.1_wp]
    bodies(1) = sphere(ml, 0.1_wp, low, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp])
    bodies(2) = sphere(mh, 0.05_wp, low + 0.15_wp*n, -u*n, [0.0_wp, 0.0_wp, 0.0_wp])
    normals = reshape([0.0_wp, 0.0_wp, 1.0_wp, n], [3, 2])
    points_1 = reshape([0.0_wp, 0.0_wp, 0.0_wp, low + 0.1_wp*n], [3, 2])
    points_2 = points_1
    call collide_at_once([0.0_wp, e], [0.0_wp, 0.0_wp], normals, points_1, points_2, reshape([0, 1, 1, 2], [2, 2]), &
                         bodies, impulse, tangential, before, after, lost, st)
    call check(st%ok(), 'from below: resolved: '//st%text())
    ph = (1 + e)*u/(1/ml + 1/mh)
    call check(impulse(1) == 0 .and. after(1) > 0, 'from below: the floor takes nothing and opens')
    call check_close(after(1), ph*cos(a)/ml, 0.0_wp, rounding*u, 'from below: the floor''s speed after P_h cos '// &
                     'a/m_l (m/s)')
    call check_close(impulse(2), ph, 0.0_wp, rounding*mh*u, 'from below: the free pair''s head-on impulse (N s)')
    call check_close(after(2), e*u, 0.0_wp, rounding*u, 'from below: the rebound e u (m/s)')
    call check(all(lost >= -rounding*mh*u**2), 'from below: no contact gives energy')
    ! dropped centrally from above at u: the floor takes it all
    bodies(1) = sphere(ml, 0.1_wp, low, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp])
    bodies(2) = sphere(mh, 0.05_wp, low + [0.0_wp, 0.0_wp, 0.15_wp], [0.0_wp, 0.0_wp, -u], [0.0_wp, 0.0_wp, 0.0_wp])
    normals(:, 2) = [0.0_wp, 0.0_wp, 1.0_wp]
    points_1(:, 2) = low + [0.0_wp, 0.0_wp, 0.1_wp]
    points_2 = points_1
    call collide_at_once([0.0_wp, e], [0.0_wp, 0.0_wp], normals, points_1, points_2, reshape([0, 1, 1, 2], [2, 2]), &
                         bodies, impulse, tangential, before, after, lost, st)
    call check(st%ok(), 'from above: resolved: '//st%text())
    call check_close(impulse(1), mh*(1 + e)*u, 0.0_wp, rounding*mh*u, 'from above: the floor takes m_h (1 + e) u')
    call check_close(after(1), 0.0_wp, 0.0_wp, rounding*u, 'from above: the floor stays closed')
    call check(norm2(bodies(1)%velocity) <= rounding*u, 'from above: the low ball stays at rest')
    ! in a run: the floor may open; both contacts are left open at gap 0
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 0.5, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''low'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&shape name = ''high'', kind = ''sphere'', radius = 0.05 /'//nl// &
           '&body name = ''low'', mass = 1, solid_of = ''low'', position = 0, 0, 0.1 /'//nl// &
           '&body name = ''high'', mass = 0.1, solid_of = ''high'', position = '// &
           number(0.17_wp*sin(a))//', 0, '//number(0.1_wp - 0.17_wp*cos(a))//', velocity = '// &
           number(-u*sin(a))//', 0, '//number(u*cos(a))//' /'//nl// &
           '&contact name = ''low_on_floor'', shape_1 = ''floor'', body_2 = ''low'', shape_2 = ''low'', '// &
           'may_open = .true. /'//nl// &
           '&contact name = ''high_on_low'', body_1 = ''low'', shape_1 = ''low'', body_2 = ''high'', '// &
           'shape_2 = ''high'', start = ''open'', restitution = '//number(e)//' /'//nl
    call run_contact_text(text, 'from below', flight, result, st)
    call check(st%ok() .and. index(flight%outcome, 'one impact at them all, after it ''low_on_floor'', '// &
               '''high_on_low'' open') > 0 .and. index(flight%outcome, 'landing: the gap of contact '// &
               '''low_on_floor'' fell to zero') > 0, 'from below: both contacts open at the hit, each watched from '// &
               'its opening, and the low ball lands on the floor again (no restitution: the run ends there): '// &
               st%text()//' '//flight%outcome)
    call check(size(flight%impacts) == 2, 'from below: one impact, the floor''s row and the hit''s')
    if (size(flight%impacts) /= 2) return
    call check(flight%impacts(1)%normal_impulse == 0 .and. flight%impacts(1)%normal_speed_after > 0, &
               'from below: the floor takes nothing and opens')
    worst = 0
    associate (s => flight%series, t_h => flight%impacts(1)%time, ph_run => flight%impacts(2)%normal_impulse)
      j = findloc(s%time(:s%n), t_h, dim=1, back=.true.)
      call check(j > 1, 'from below: the records at the hit')
      if (j < 2) return
      call check(s%time(j - 1) == t_h .and. s%kind(j) == RECORD_EVENT, 'from below: the records before and '// &
                 'after the hit, the second an event')
      ! the low ball leaves at -P_h n/m_l (n along the centres at the hit) and flies a parabola back to the floor
      n = s%body_r(:, 2, j) - s%body_r(:, 1, j)
      n = n/norm2(n)
      low = s%body_r(:, 1, j)
      v_low = -ph_run*n/ml
      worst = max(worst, norm2(s%body_v(:, 1, j) - v_low), abs(s%time(s%n) - t_h - 2*v_low(3)/g))
      do i = j, s%n
        worst = max(worst, norm2(s%body_r(:, 1, i) - low - v_low*(s%time(i) - t_h) - &
                                 [0.0_wp, 0.0_wp, -g]*(s%time(i) - t_h)**2/2))
      end do
      call check(all(s%body_r(3, 1, j + 1:s%n - 1) > 0.1_wp), 'from below: the low ball above the floor until '// &
                 'it lands')
    end associate
    call check_close(worst, 0.0_wp, 0.0_wp, 1e-9_wp, 'from below: the low ball leaves at -P_h n/m_l, flies the '// &
                     'parabola and lands again at 2 v_z/g after the hit')
    print '(a, es10.2)', '  from below: the low ball''s flight ', worst
  end subroutine hit_from_below

  !> The law at a carried body, at random: a box (2 kg, half sides 0.2,
  !> 0.1, 0.05 m) resting on three feet on the floor (carrying contacts,
  !> restitution 0, normal speed 0 before) hit on its top by a ball (0.3
  !> kg) at a random point, along a random normal within 70 deg of the
  !> vertical, at a random approaching velocity and spin, with a random e
  !> in [0, 1], frictionless (collide_at_once): 300 hits, at every contact
  !> the impulse >= 0; at each foot its speed after >= 0 and one of the two
  !> 0; at the hit the speed after >= -e v- and either P = 0 or it is -e
  !> v-; the kinetic energy never rises and its fall is the rows' sum; with
  !> e = 1 everywhere the hit keeps it (to the speeds' rounding).
  subroutine carried_law_random()
    real(wp), parameter :: half(3) = [0.2_wp, 0.1_wp, 0.05_wp], mb = 2
    type(impact_body_t) :: bodies(0:2)
    type(status_t) :: st
    real(wp) :: normals(3, 4), points(3, 4), r(8), n(3), e, e_before, e_after, scale, worst_c, worst_e
    real(wp), dimension(4) :: impulse, tangential, before, after, lost, restitution
    integer :: k, i, fails, seed_size
    integer, allocatable :: seed(:)
    call random_seed(size=seed_size)
    seed = [(7919*i, i = 1, seed_size)]
    call random_seed(put=seed)
    worst_c = 0
    worst_e = 0
    fails = 0
    do k = 1, 300
      call random_number(r)
      bodies(1) = impact_body_t(mass=mb, inertia=0, origin=[0.0_wp, 0.0_wp, half(3)], &
                                centre=[0.0_wp, 0.0_wp, half(3)])
      do i = 1, 3
        bodies(1)%inertia(i, i) = mb*(4*sum(half**2) - 4*half(i)**2)/12
      end do
      n = [2*r(1) - 1, 2*r(2) - 1, 0.0_wp]
      n = n*sin(70*acos(-1.0_wp)/180*r(3))/max(norm2(n), tiny(1.0_wp))
      n(3) = sqrt(1 - sum(n(1:2)**2))
      points(:, 4) = [half(1)*(2*r(4) - 1), half(2)*(2*r(5) - 1), 2*half(3)]
      bodies(2) = sphere(0.3_wp, 0.05_wp, points(:, 4) + 0.05_wp*n, -(1 + 3*r(6))*n + [r(7), -r(8), 0.0_wp], &
                         [r(8), 2*r(7), -r(6)])
      normals(:, 1:3) = spread([0.0_wp, 0.0_wp, 1.0_wp], 2, 3)
      normals(:, 4) = n
      points(:, 1:3) = reshape([half(1), half(2), 0.0_wp, half(1), -half(2), 0.0_wp, -half(1), 0.0_wp, 0.0_wp], &
                               [3, 3])
      e = merge(1.0_wp, r(2), k > 250)
      restitution = [0.0_wp, 0.0_wp, 0.0_wp, e]
      e_before = kinetic_energy(bodies(1), bodies(2))
      call collide_at_once(restitution, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], normals, points, points, &
                           reshape([0, 1, 0, 1, 0, 1, 1, 2], [2, 4]), bodies, impulse, tangential, before, after, &
                           lost, st)
      if (.not. st%ok()) then
        fails = fails + 1
        cycle
      end if
      e_after = kinetic_energy(bodies(1), bodies(2))
      scale = rounding*(4 + maxval(abs(before)))   ! 16 eps of the speeds (m/s)
      worst_c = max(worst_c, max(maxval(-impulse)/0.3_wp, maxval(-after(1:3)), &
                                 maxval(min(impulse(1:3)/0.3_wp, abs(after(1:3)))), -(after(4) + e*before(4)), &
                                 min(impulse(4)/0.3_wp, abs(after(4) + e*before(4))))/scale)
      worst_e = max(worst_e, (e_after - e_before)/e_before, abs(e_before - e_after - sum(lost))/e_before)
      if (k > 250) worst_e = max(worst_e, abs(e_after - e_before)/e_before)
    end do
    call check(fails == 0, 'carried at random: every hit resolved')
    call check(worst_c <= 1, 'carried at random: complementarity at the feet and the hit (in the speeds'' '// &
               'rounding): '//number(worst_c))
    call check_close(worst_e, 0.0_wp, 0.0_wp, 1e-14_wp, 'carried at random: the energy never rises, its fall the '// &
                     'rows'' sum, kept at e = 1 (relative)')
    print '(a, 2es10.2)', '  carried at random: complementarity (of the rounding), energy ', worst_c, worst_e
  end subroutine carried_law_random

  !> The groups of a ball (radius, 1 kg) at height z0 over a V of two planes
  !> tilted +-angle about y (their normals (+-sin, 0, cos)), a contact with
  !> each (restitution e, impact_mu mu, close_speed 0.1 m/s).
  function v_input(angle, z0, radius, e, mu) result(text)
    real(wp), intent(in) :: angle, z0, radius, e, mu
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = 3, output_step = 0.01 /'//nl// &
           '&shape name = ''left'', kind = ''plane'', angles_deg = 0, '//number(angle)//', 0 /'//nl// &
           '&shape name = ''right'', kind = ''plane'', angles_deg = 0, '//number(-angle)//', 0 /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = '//number(radius)//' /'//nl// &
           '&body name = ''ball'', mass = 1, solid_of = ''ball'', position = 0, 0, '//number(z0)//' /'//nl// &
           '&contact name = ''on_left'', shape_1 = ''left'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'start = ''open'', restitution = '//number(e)//', impact_mu = '//number(mu)//', close_speed = 0.1 /'// &
           nl//'&contact name = ''on_right'', shape_1 = ''right'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'start = ''open'', restitution = '//number(e)//', impact_mu = '//number(mu)//', close_speed = 0.1 /'//nl
  end function v_input

  !> A ball dropped into a V of planes at +-30 degrees lands on both at
  !> once: the frictionless impact at two points (Newton's restitution e =
  !> 0.5 at each, W = [1 cos60; cos60 1]/m): each normal impulse (1 + e) m
  !> v cos30/(1 + cos60), the ball thrown straight up at e v (v = e^(k-1)
  !> v0), each contact's normal speed -v cos30 before and e v cos30 after,
  !> the pair's energy (1 - e^2) m v^2/2; bounces e^(2k) high at the times
  !> of a ball on a floor; at the fifth the rebound e^5 v0 cos30 is below
  !> close_speed and both contacts close (contact_body_impact close_at_once:
  !> the impulses v cos30/(1 + cos60) at each in all, the ball stopped, its
  !> m v^2/2 taken): the ball rests in the V to the end, N = m g/(2 cos30)
  !> at each plane. With friction (impact_mu 0.3;
  !> kinetostatics_point_impacts) the same bounces, each contact slipping:
  !> normal impulses (1 + e) m v/(2 (cos30 - mu sin30)), friction mu of
  !> them.
  subroutine two_at_once()
    real(wp), parameter :: z0 = 0.5_wp, radius = 0.1_wp, e = 0.5_wp, angle = 30, mu = 0.3_wp
    type(flight_ode_t), target :: flight
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: c30, v0, v, t, worst_x, worst_spin, worst_n, rest
    integer :: k, i, j
    c30 = cos(angle*acos(-1.0_wp)/180)
    call run_contact_text(v_input(angle, z0, radius, e, 0.0_wp), 'two at once', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'two at once: runs to its end: '//st%text()//' '// &
               flight%outcome)
    if (.not. st%ok()) return
    call check(index(flight%outcome, 'contacts ''on_left'', ''on_right'' closed at the impact at several contacts '// &
                     'at once') > 0, 'two at once: the outcome says the fifth closes both: '//flight%outcome)
    call check(size(flight%impacts) == 10, 'two at once: five impacts at two points each')
    if (size(flight%impacts) /= 10) return
    v0 = sqrt(2*g*(z0 - radius/c30))
    t = v0/g
    v = v0
    do k = 1, 5
      associate (left => flight%impacts(2*k - 1), right => flight%impacts(2*k))
        call check(left%contact == 1 .and. right%contact == 2 .and. left%time == right%time, &
                   'two at once: both contacts in one impact')
        call check_close(left%time, t, 0.0_wp, 1e-9_wp, 'two at once: impact times as on a floor (s)')
        rest = merge(0.0_wp, 1.0_wp, k == 5)   ! the fifth closes: no rebound
        do i = 2*k - 1, 2*k
          call check_close(flight%impacts(i)%normal_speed_before, -v*c30, 0.0_wp, 1e-9_wp, &
                           'two at once: approach v cos30 (m/s)')
          call check_close(flight%impacts(i)%normal_speed_after, rest*e*v*c30, 0.0_wp, 1e-9_wp, &
                           'two at once: rebound e v cos30 at each, 0 at the fifth (m/s)')
          call check_close(flight%impacts(i)%normal_impulse, (1 + rest*e)*v*c30/1.5_wp, 0.0_wp, 1e-9_wp, &
                           'two at once: impulse (1 + e) m v cos30/(1 + cos60) at each, e 0 at the fifth (N s)')
        end do
        call check_close(left%energy_lost + right%energy_lost, (1 - (rest*e)**2)*v**2/2, 0.0_wp, 1e-9_wp, &
                         'two at once: the pair takes (1 - e^2) m v^2/2, all at the fifth (J)')
      end associate
      t = t + 2*e*v/g
      v = e*v
    end do
    worst_x = 0
    worst_spin = 0
    associate (s => flight%series)
      do i = 1, s%n
        worst_x = max(worst_x, abs(s%body_r(1, 1, i)), abs(s%body_v(1, 1, i)))
        worst_spin = max(worst_spin, maxval(abs(s%body_omega(:, 1, i))))
      end do
    end associate
    call check_close(worst_x + worst_spin, 0.0_wp, 0.0_wp, 1e-12_wp, 'two at once: straight up and down, no spin')
    print '(a, 2es10.2)', '  two at once: sideways, spin ', worst_x, worst_spin
    ! at rest in the V after the fifth: each plane's N = m g/(2 cos30)
    worst_n = 0
    associate (s => flight%series)
      do i = 1, s%n
        if (s%time(i) <= t) cycle
        do j = 1, s%nc
          worst_n = max(worst_n, abs(s%normal(j, i)*2*c30/g - 1))
        end do
        worst_n = max(worst_n, norm2(s%body_v(:, 1, i)))
      end do
      call check(s%nc == 2 .and. s%time(s%n) > t + 1, 'two at once: the ball rests in the V to the end')
    end associate
    call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-9_wp, 'two at once: at rest, N = m g/(2 cos30) at each (relative)')
    print '(a, es10.2)', '  two at once: at rest, N relative and speed ', worst_n
    ! with friction (kinetostatics_point_impacts): by symmetry the ball goes
    ! straight up at e v as without it, its contact points slipping up the
    ! planes after the impact; friction mu P against that slip: the vertical
    ! impulse 2 P (cos30 - mu sin30) = (1 + e) m v
    call run_contact_text(v_input(angle, z0, radius, e, mu), 'two at once, friction', flight, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'two at once, friction: runs to its end: '//st%text())
    call check(index(flight%outcome, 'contacts ''on_left'', ''on_right'' closed at the impact at several contacts '// &
                     'at once') > 0, 'two at once, friction: the fifth closes both: '//flight%outcome)
    call check(size(flight%impacts) == 10, 'two at once, friction: five impacts at two points each')
    if (size(flight%impacts) /= 10) return
    t = v0/g
    v = v0
    do k = 1, 4   ! (the fifth closes both)
      do i = 2*k - 1, 2*k
        associate (row => flight%impacts(i))
          call check_close(row%time, t, 0.0_wp, 1e-9_wp, 'two at once, friction: impact times as on a floor (s)')
          call check_close(row%normal_speed_after, e*v*c30, 0.0_wp, 1e-9_wp, &
                           'two at once, friction: rebound e v cos30 at each (m/s)')
          call check_close(row%normal_impulse, (1 + e)*v/(2*(c30 - mu/2)), 0.0_wp, 1e-9_wp, &
                           'two at once, friction: impulse (1 + e) m v/(2 (cos30 - mu sin30)) at each (N s)')
          call check_close(row%tangential_impulse, mu*row%normal_impulse, 0.0_wp, 1e-9_wp, &
                           'two at once, friction: each slips: friction mu P (N s)')
        end associate
      end do
      call check_close(flight%impacts(2*k - 1)%energy_lost + flight%impacts(2*k)%energy_lost, (1 - e**2)*v**2/2, &
                       0.0_wp, 1e-9_wp, 'two at once, friction: the pair takes (1 - e^2) m v^2/2 (J)')
      t = t + 2*e*v/g
      v = e*v
    end do
  end subroutine two_at_once
end program test_body_impact
