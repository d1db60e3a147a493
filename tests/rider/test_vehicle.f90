!> The vehicles of rider_vehicle (issue 26 point 2): every kind and rider
!> count on a plane inclined by 20 degrees with Coulomb friction mu = 0.2,
!> heading down the fall line, against the closed forms of a rigid body
!> sliding without turning: u'' = g (sin a - mu cos a) whatever the mass, its
!> distribution and the rider count; N_rear + N_front = M g cos a; the split
!> from the moments about the centre of mass (x_c, z_c in V, L the contacts'
!> distance): N_front = M g cos a (x_c + mu z_c)/L; the ride figures: the
!> felt acceleration at the centre of mass (-mu cos a, 0, cos a) g along the
!> vehicle's axes and its speed u0' + a t (it does not turn). The persons scale
!> isometrically: a rider sitting on the slide has mass ~ s^3, length ~ s and
!> inertia ~ s^5. In the water (uniform water on the incline, a constant
!> drag coefficient): the speed against the closed form of quadratic drag
!> balancing g (sin a - mu cos a), v = w + v_t tanh(t/T + atanh(1/2)), and
!> the felt acceleration with the drag of the record, whatever the run's
!> last state.
program test_vehicle
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use numerics_event_driver, only: RECORD_START, RECORD_OUTPUT
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: sled_description_t
  use kinetostatics_force_law_factory, only: law_spec
  use rider_vehicle, only: vehicle_t, vehicle_body_t, vehicle_body, build_vehicle_model, vehicle_kinds, &
    vehicle_ride_figures, &
    VEHICLE_MAT, VEHICLE_SITTING, VEHICLE_RING, VEHICLE_DOUBLE_RING, VEHICLE_RAFT, person_reference_mass, torus
  use rider_body, only: rigid_body_t
  use rider_drag, only: morrison_drag_coefficient, morrison_reynolds_max
  use water_series, only: water_series_t
  use water_field, only: water_field_t, new_water_field
  use io_declarations_multibody, only: multibody_declarations
  implicit none (type, external)

  real(wp), parameter :: g = 9.80665_wp
  integer :: riders

  call incline(vehicle_t(VEHICLE_RING, 1, 1.0_wp))
  do riders = 1, 2
    call incline(vehicle_t(VEHICLE_DOUBLE_RING, riders, 1.0_wp))
  end do
  do riders = 1, 4
    call incline(vehicle_t(VEHICLE_RAFT, riders, 1.0_wp))
  end do
  call incline(vehicle_t(VEHICLE_RAFT, 4, 0.6_wp))
  call incline(vehicle_t(VEHICLE_RAFT, 2, 1.1_wp))
  call incline(vehicle_t(VEHICLE_MAT, 1, 1.0_wp))
  call incline(vehicle_t(VEHICLE_MAT, 1, 0.6_wp))
  call incline(vehicle_t(VEHICLE_SITTING, 1, 1.0_wp))
  call terminal_speed(vehicle_t(VEHICLE_RING, 1, 1.0_wp))
  call terminal_speed(vehicle_t(VEHICLE_DOUBLE_RING, 2, 1.0_wp))
  call terminal_speed(vehicle_t(VEHICLE_RAFT, 4, 1.0_wp))
  call terminal_speed(vehicle_t(VEHICLE_MAT, 1, 1.0_wp))
  call terminal_speed(vehicle_t(VEHICLE_SITTING, 1, 0.8_wp))
  ! the parts and the riders' sizes from input (&sled mat_*, ring_*, raft_*,
  ! scales): a raft's riders of different sizes placed symmetrically about
  ! its long axis (the first at the rear, the third at the front, the second
  ! and fourth of one size on either side: a raft heavier on one side turns)
  call incline(resized(vehicle_t(VEHICLE_RING, 1, 1.0_wp), [0.8_wp]))
  call incline(resized(vehicle_t(VEHICLE_DOUBLE_RING, 2, 1.0_wp), [0.6_wp, 1.08_wp]))
  call incline(resized(vehicle_t(VEHICLE_RAFT, 4, 1.0_wp), [0.6_wp, 0.9_wp, 1.1_wp, 0.9_wp]))
  call incline(resized(vehicle_t(VEHICLE_RAFT, 2, 1.0_wp), [1.1_wp, 0.6_wp]))
  call incline(resized(vehicle_t(VEHICLE_MAT, 1, 1.0_wp), [0.7_wp]))
  call terminal_speed(resized(vehicle_t(VEHICLE_RAFT, 4, 1.0_wp), [0.6_wp, 0.9_wp, 1.1_wp, 0.9_wp]))
  call scaling()
  call ring_from_input()
  call declared_defaults()
  call torus_inertia(0.45_wp, 0.15_wp)
  call torus_inertia(0.75_wp, 0.22_wp)
  call refusals()
  call finish_tests('test_vehicle')

contains

  subroutine incline(v)
    type(vehicle_t), intent(in) :: v
    real(wp), parameter :: theta = 20*pi/180, mu = 0.2_wp
    type(sled_description_t) :: d
    type(vehicle_body_t) :: vb
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: acc, t, res, weight_normal, n_front
    real(wp), allocatable :: y(:), q0(:), qd0(:), speed(:), felt(:, :)
    character(len=64) :: label

    write (label, '(a, 1x, i0, a, 4(1x, f4.2))') trim(vehicle_kinds(v%kind)), v%riders, ' rider(s), scale', &
      v%scales(:v%riders)
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(theta), 0.0_wp, -sin(theta)], [0.0_wp, 1.0_wp, 0.0_wp], st)
    d%params%friction = [law_spec('coulomb', 'mu', mu)]
    d%q0 = [0.5_wp, 0.2_wp, 0.0_wp]
    d%qd0 = [1.0_wp, 0.0_wp, 0.0_wp]
    call vehicle_body(v, vb, st)
    call build_vehicle_model(v, d, plane, sys%mechanism, q0, qd0, st)
    if (st%ok()) call sys%mechanism%check_start(sys%work, q0, st)
    call check(st%ok(), 'incline: '//trim(label)//' starts: '//st%text())
    if (.not. st%ok()) return
    acc = g*(sin(theta) - mu*cos(theta))
    weight_normal = vb%body%mass*g*cos(theta)
    associate (m => sys%mechanism, work => sys%work)
      call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
      call check(st%ok(), 'incline: evaluate: '//st%text())
      ! exact algebra but for the Coulomb law's regularization, (eps/|w|)^2/2
      ! = 5e-13 relative at 1 m/s, and the closure's rounding
      call check_close(work%qdd(1), acc, 1e-9_wp, 0.0_wp, 'incline: u'''' = g (sin a - mu cos a), '//trim(label))
      call check(abs(work%qdd(2)) <= 1e-8_wp*g .and. abs(work%qdd(3)) <= 1e-8_wp*g, &
                 'incline: v'''' = phi'''' = 0, '//trim(label))
      call check_close(work%normal_force(1) + work%normal_force(2), weight_normal, 1e-10_wp, 0.0_wp, &
                       'incline: N_rear + N_front = M g cos a, '//trim(label))
      ! no pitch: the moments about the centre of mass balance
      n_front = weight_normal*(vb%body%com(1) + mu*vb%body%com(3))/vb%length
      call check_close(work%normal_force(2), n_front, 1e-10_wp, 0.0_wp, &
                       'incline: N_front = M g cos a (x_c + mu z_c)/L, '//trim(label))
      call check(min(work%normal_force(1), work%normal_force(2)) > 0, &
                 'incline: both contacts pressed, '//trim(label))
    end associate
    opt%rtol = 1e-10_wp
    opt%atol = 1e-12_wp
    y = sys%initial_state(q0, qd0)
    call integ%start(sys, 0.0_wp, y, opt, st)
    call integ%advance(1.0_wp, t, y, st)
    call check(st%ok(), 'incline: integrated 1 s: '//st%text())
    ! constant acceleration: the integrator follows a quadratic to its rtol
    call check_close(y(1), q0(1) + qd0(1) + acc/2, 1e-8_wp, 0.0_wp, 'incline: u(1 s) = u0 + u0'' + a/2, '// &
                     trim(label))
    call check_close(y(4), qd0(1) + acc, 1e-8_wp, 0.0_wp, 'incline: u''(1 s) = u0'' + a, '//trim(label))
    ! the ride figures at the start and after 1 s: the closed forms to the
    ! closure's rounding (felt) and to the integration's 1e-8 (speed)
    call sys%record(0.0_wp, sys%initial_state(q0, qd0), RECORD_START, st)
    call sys%record(t, y, RECORD_OUTPUT, st)
    call vehicle_ride_figures(sys%mechanism, sys%work, sys%series, speed, felt, st)
    call check(st%ok() .and. size(speed) == 2, 'incline: the ride figures at two records: '//st%text())
    if (.not. st%ok()) return
    call check(maxval(abs(felt(:, 1) - [-mu*cos(theta), 0.0_wp, cos(theta)])) <= 1e-10_wp .and. &
               maxval(abs(felt(:, 2) - [-mu*cos(theta), 0.0_wp, cos(theta)])) <= 1e-10_wp, &
               'incline: felt acceleration (-mu cos a, 0, cos a) g, '//trim(label))
    call check_close(speed(1), qd0(1), 1e-12_wp, 0.0_wp, 'incline: speed of the centre at the start, '//trim(label))
    call check_close(speed(2), qd0(1) + acc, 1e-8_wp, 0.0_wp, 'incline: speed of the centre after 1 s, '// &
                     trim(label))
  end subroutine incline

  !> The vehicle in water flowing down the incline of `incline` (a = 20
  !> degrees, mu = 0.2) at w = 2 m/s, 1.2 m deep everywhere (every drag
  !> sphere, r <= 0.5 m, under water: the projected area pi r^2), its
  !> kinematic viscosity 1e-8 m^2/s so that Re = |v - w| 2 r/nu > 1e6 at
  !> every speed the run reaches (C_D held at C_D(1e6), rider_drag): the
  !> drag is k (v - w)^2 against the motion relative to the water,
  !> k = rho C_D pi sum(r^2)/2 over both contacts, along the fall line (no
  !> normal part: N_rear + N_front = M g cos a, the friction mu M g cos a),
  !> so M v' = M g (sin a - mu cos a) - k (v - w)^2: the terminal speed
  !> w + v_t, v_t = sqrt(M g (sin a - mu cos a)/k), approached from
  !> w + v_t/2 as v = w + v_t tanh(t/T + atanh(1/2)), T = M/(k v_t) (from
  !> below: above it the drag's moment about the centre of mass, its force
  !> at the contacts under it, would lift a ring's rear off). The
  !> integration at rtol 1e-10 follows it to 1e-8 relative (the tolerance
  !> argued as incline's); a drag at one contact only, or with the wrong
  !> area, misses by > 10 %.
  subroutine terminal_speed(v)
    type(vehicle_t), intent(in) :: v
    real(wp), parameter :: theta = 20*pi/180, mu = 0.2_wp, w = 2.0_wp, depth = 1.2_wp
    type(vehicle_t) :: wet
    type(sled_description_t) :: d
    type(vehicle_body_t) :: vb
    class(surface_t), allocatable :: plane
    type(water_field_t), target :: water   ! the drag laws point at it
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: k, v_t, period, t, t_out, res, expected, down(3), normal(3)
    real(wp), allocatable :: y(:), q0(:), qd0(:), speed(:), felt(:, :)
    character(len=64) :: label
    integer :: i, drag(2)

    write (label, '(a, 1x, i0, a, 4(1x, f4.2))') trim(vehicle_kinds(v%kind)), v%riders, ' rider(s), scale', &
      v%scales(:v%riders)
    down = [cos(theta), 0.0_wp, -sin(theta)]
    normal = [sin(theta), 0.0_wp, cos(theta)]   ! down x (0, 1, 0): the side the vehicle is on
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], down, [0.0_wp, 1.0_wp, 0.0_wp], st)
    water = uniform_water(down, normal, w, depth, st)
    call check(st%ok(), 'terminal speed: the water field: '//st%text())
    wet = v
    wet%in_water = .true.
    wet%water%kinematic_viscosity = 1e-8_wp
    call vehicle_body(wet, vb, st)
    k = wet%water%density*morrison_drag_coefficient(morrison_reynolds_max)*pi*sum(vb%drag_radius**2)/2
    v_t = sqrt(vb%body%mass*g*(sin(theta) - mu*cos(theta))/k)
    period = vb%body%mass/(k*v_t)
    call check(2*minval(vb%drag_radius)*0.49_wp*v_t/wet%water%kinematic_viscosity > morrison_reynolds_max, &
               'terminal speed: Re > 1e6 from v_t/2 (C_D constant), '//trim(label))
    d%params%friction = [law_spec('coulomb', 'mu', mu)]
    d%q0 = [0.5_wp, 0.2_wp, 0.0_wp]
    d%qd0 = [w + v_t/2, 0.0_wp, 0.0_wp]
    call build_vehicle_model(wet, d, plane, sys%mechanism, q0, qd0, st, water=water)
    if (st%ok()) call sys%mechanism%check_start(sys%work, q0, st)
    call check(st%ok(), 'terminal speed: '//trim(label)//' starts: '//st%text())
    if (.not. st%ok()) return
    call check(sys%mechanism%law_index('rear_water_drag') > 0 .and. sys%mechanism%law_index('front_water_drag') > 0, &
               'terminal speed: the water''s drag at both contacts, '//trim(label))
    associate (m => sys%mechanism, work => sys%work)
      call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
      call check_close(work%normal_force(1) + work%normal_force(2), vb%body%mass*g*cos(theta), 1e-10_wp, 0.0_wp, &
                       'terminal speed: the drag has no normal part, N_rear + N_front = M g cos a, '//trim(label))
      ! at w + v_t/2: M u'' = M g (sin a - mu cos a) (1 - 1/4)
      call check_close(work%qdd(1), 0.75_wp*g*(sin(theta) - mu*cos(theta)), 1e-8_wp, 0.0_wp, &
                       'terminal speed: u'''' at the start = 3/4 g (sin a - mu cos a), '//trim(label))
      call check(min(work%normal_force(1), work%normal_force(2)) > 0, &
                 'terminal speed: both contacts pressed, '//trim(label))
    end associate
    opt%rtol = 1e-10_wp
    opt%atol = 1e-12_wp
    y = sys%initial_state(q0, qd0)
    call integ%start(sys, 0.0_wp, y, opt, st)
    do i = 1, 4
      t_out = period*2**(i - 2)   ! T/2 ... 4 T
      call integ%advance(t_out, t, y, st)
      call check(st%ok(), 'terminal speed: integrated: '//st%text())
      expected = w + v_t*tanh(t/period + log(3.0_wp)/2)
      call check_close(y(4), expected, 1e-8_wp, 0.0_wp, 'terminal speed: u''(t) = w + v_t tanh(t/T + atanh 1/2), '// &
                       trim(label))
    end do
    ! The ride figures take each record's drag as it was then, not as the
    ! run left it: recorded in the water, then the drag switched off (as
    ! at the end of a ride whose vehicle left the water), the felt
    ! acceleration along the fall line is still (a - g sin a)/g
    ! = -mu cos a - k (v - w)^2/(M g), not the dry -mu cos a.
    call sys%record(t, y, RECORD_OUTPUT, st)
    drag = [sys%mechanism%law_index('rear_water_drag'), sys%mechanism%law_index('front_water_drag')]
    do i = 1, 2
      sys%work%laws(drag(i))%law%active = .false.
    end do
    call vehicle_ride_figures(sys%mechanism, sys%work, sys%series, speed, felt, st)
    call check(st%ok() .and. size(speed) == 1, 'terminal speed: the ride figures at one record: '//st%text())
    if (.not. st%ok()) return
    call check_close(felt(1, 1), -mu*cos(theta) - k*(y(4) - w)**2/(vb%body%mass*g), 1e-8_wp, 0.0_wp, &
                     'terminal speed: felt along the fall line with the record''s drag, '//trim(label))
    call check(.not. (sys%work%laws(drag(1))%law%active .or. sys%work%laws(drag(2))%law%active), &
               'terminal speed: the run''s last drag flags restored after the figures, '//trim(label))
  end subroutine terminal_speed

  !> Water flowing at speed w along `down` over the plane through the origin,
  !> `depth` deep everywhere, its edges 5 m to either side: a water field
  !> (water_field) from three samples with their rates, u the arc length.
  function uniform_water(down, normal, w, depth, status) result(field)
    real(wp), intent(in) :: down(3), normal(3), w, depth
    type(status_t), intent(out) :: status
    type(water_field_t) :: field
    type(water_series_t) :: s
    integer, parameter :: n = 3
    real(wp), parameter :: u(n) = [-10.0_wp, 500.0_wp, 1010.0_wp]
    integer :: i
    s%n = n
    s%flow_rate = 1
    s%u = u
    s%arc_length = u
    s%time = u/w
    s%du = [(w, i = 1, n)]
    s%flow = [(1.0_wp, i = 1, n)]
    s%v = [(0.0_wp, i = 1, n)]
    s%dv = s%v
    s%speed = s%du
    s%height = [(depth, i = 1, n)]
    s%width = [(10.0_wp, i = 1, n)]
    s%centerline_speed = [(1.0_wp, i = 1, n)]
    s%speed_rate = s%v; s%height_rate = s%v; s%width_rate = s%v; s%udd = s%v; s%vdd = s%v
    allocate (s%position(3, n), s%velocity(3, n), s%acceleration(3, n), s%x_m(3, n), s%z_m(3, n), &
              s%x_m_rate(3, n), s%z_m_rate(3, n), s%left_edge(2, n), s%right_edge(2, n), s%left_edge_rate(2, n), &
              s%right_edge_rate(2, n))
    do i = 1, n
      s%position(:, i) = u(i)*down
      s%velocity(:, i) = w*down
      s%x_m(:, i) = [0.0_wp, 1.0_wp, 0.0_wp]
      s%z_m(:, i) = normal
      s%left_edge(:, i) = [u(i), 5.0_wp]
      s%right_edge(:, i) = [u(i), -5.0_wp]
      s%left_edge_rate(:, i) = [w, 0.0_wp]
      s%right_edge_rate(:, i) = [w, 0.0_wp]
    end do
    s%acceleration = 0; s%x_m_rate = 0; s%z_m_rate = 0
    s%edge_solved = [(1, i = 1, n)]
    field = new_water_field(s, status)
  end function uniform_water

  !> A rider sitting on the slide, no vehicle: every length ~ s, mass ~ s^3,
  !> so the inertia ~ s^5, the contacts' distance ~ s and the centre of mass ~ s.
  subroutine scaling()
    type(vehicle_body_t) :: small, large
    type(status_t) :: st
    real(wp), parameter :: s = 0.6_wp
    call vehicle_body(vehicle_t(VEHICLE_SITTING, 1, s), small, st)
    call vehicle_body(vehicle_t(VEHICLE_SITTING, 1, 1.0_wp), large, st)
    call check(st%ok(), 'scaling: built: '//st%text())
    call check_close(small%body%mass, s**3*person_reference_mass, 1e-13_wp, 0.0_wp, 'scaling: mass s^3 M_ref')
    call check_close(large%body%mass, person_reference_mass, 1e-13_wp, 0.0_wp, 'scaling: mass M_ref at s = 1')
    call check_close(small%length, s*large%length, 1e-13_wp, 0.0_wp, 'scaling: contacts'' distance ~ s')
    call check(maxval(abs(small%body%com - s*large%body%com)) <= 1e-13_wp, 'scaling: centre of mass ~ s')
    call check(maxval(abs(small%body%inertia - s**5*large%body%inertia)) <= 1e-12_wp*maxval(abs(small%body%inertia)), &
               'scaling: inertia ~ s^5')
    call check(abs(large%body%inertia(1, 3)) > 1e-3_wp, 'scaling: sitting up, the inertia has an x-z product')
  end subroutine scaling

  !> The thin-walled torus's inertia against a quadrature over its shell:
  !> r(theta, t) = ((R + r cos t) cos theta, (R + r cos t) sin theta, r sin t),
  !> dA = r (R + r cos t) dtheta dt, mass spread evenly. The integrands are
  !> trigonometric polynomials of degree <= 3 in each angle, so the
  !> trapezoidal rule on 16 x 16 points is exact but for rounding (1e-14
  !> relative); a coefficient of the closed form changed by a quarter moves
  !> the result by > 1 %.
  subroutine torus_inertia(big, small)
    real(wp), intent(in) :: big, small
    integer, parameter :: n = 16
    real(wp), parameter :: mass = 7.0_wp
    type(rigid_body_t) :: b
    real(wp) :: theta, t, p(3), dm, inertia(3, 3), area
    integer :: i, j, k
    inertia = 0
    area = 4*pi**2*big*small
    do i = 0, n - 1
      theta = 2*pi*i/n
      do j = 0, n - 1
        t = 2*pi*j/n
        p = [(big + small*cos(t))*cos(theta), (big + small*cos(t))*sin(theta), small*sin(t)]
        dm = mass*small*(big + small*cos(t))*(2*pi/n)**2/area
        do k = 1, 3
          inertia(k, k) = inertia(k, k) + dm*(dot_product(p, p) - p(k)**2)
        end do
        inertia(1, 2) = inertia(1, 2) - dm*p(1)*p(2)
        inertia(1, 3) = inertia(1, 3) - dm*p(1)*p(3)
        inertia(2, 3) = inertia(2, 3) - dm*p(2)*p(3)
      end do
    end do
    inertia(2, 1) = inertia(1, 2); inertia(3, 1) = inertia(1, 3); inertia(3, 2) = inertia(2, 3)
    b = torus(mass, [big, small])
    call check_close(b%mass, mass, 0.0_wp, 0.0_wp, 'torus: mass')
    call check(all(b%com == 0), 'torus: centre of mass at its centre')
    do k = 1, 3
      call check_close(b%inertia(k, k), inertia(k, k), 1e-13_wp, 0.0_wp, 'torus: inertia about axis '// &
                       achar(iachar('w') + k)//' against the shell quadrature')
    end do
    call check(abs(b%inertia(1, 2)) + abs(b%inertia(1, 3)) + abs(b%inertia(2, 3)) == 0 .and. &
               abs(inertia(1, 2)) + abs(inertia(1, 3)) + abs(inertia(2, 3)) <= 1e-14_wp*inertia(3, 3), &
               'torus: no products of inertia')
  end subroutine torus_inertia

  !> Vehicle `v` with its parts and riders' sizes changed from the defaults
  !> (the input's &sled mat_*, ring_*, raft_*, scales): every kind's parts
  !> set, its own used, the others' ignored.
  function resized(v, scales) result(w)
    type(vehicle_t), intent(in) :: v
    real(wp), intent(in) :: scales(:)
    type(vehicle_t) :: w
    w = v
    w%scales(:size(scales)) = scales
    w%mat_size = [1.3_wp, 0.7_wp, 0.06_wp]
    w%mat_mass = 3.2_wp
    w%ring_radii = [0.52_wp, 0.18_wp]
    w%ring_mass = 11.5_wp
    w%raft_radii = [0.9_wp, 0.26_wp]
    w%raft_mass = 42.0_wp
    w%raft_floor = 0.05_wp
  end function resized

  !> A ring's and a double ring's body from input radii and mass (not the
  !> defaults) against their closed form: each thin-walled torus (R, r,
  !> mass m) I_z = m (R^2 + 3 r^2/2), I_x = I_y = m (R^2/2 + 5 r^2/4) about
  !> its centre (R, 0, r) in V (the second ring's 2 (R + r) ahead), each
  !> rider the sitting person of its own scale (the 'sitting' vehicle's body:
  !> seat at the origin) at the ring's centre, all moved to their common
  !> centre of mass by Steiner's theorem here (not rider_vehicle's
  !> add_body); the contacts' distance 2 R (4 R + 2 r), the width 2 (R + r).
  !> Exact algebra: to 1e-12 relative. With the default radii or mass in
  !> place of the input's the inertia is off by > 5 %.
  subroutine ring_from_input()
    real(wp), parameter :: big = 0.52_wp, small = 0.18_wp, mass = 11.5_wp, s(2) = [0.6_wp, 1.08_wp]
    type(vehicle_t) :: v
    type(vehicle_body_t) :: vb, person(2)
    type(rigid_body_t) :: ring
    type(status_t) :: st
    real(wp) :: centre(3), centre2(3)
    integer :: k
    do k = 1, 2
      call vehicle_body(vehicle_t(VEHICLE_SITTING, 1, s(k)), person(k), st)
    end do
    ring%mass = mass
    ring%com = 0
    ring%inertia = 0
    ring%inertia(1, 1) = mass*(big**2/2 + 5*small**2/4)
    ring%inertia(2, 2) = ring%inertia(1, 1)
    ring%inertia(3, 3) = mass*(big**2 + 3*small**2/2)
    centre = [big, 0.0_wp, small]
    centre2 = centre + [2*(big + small), 0.0_wp, 0.0_wp]
    v = vehicle_t(VEHICLE_RING, 1, s(1))
    v%ring_radii = [big, small]
    v%ring_mass = mass
    call vehicle_body(v, vb, st)
    call check(st%ok(), 'ring from input: built: '//st%text())
    call compare(vb, [ring, person(1)%body], reshape([centre, centre], [3, 2]), 2*big, 2*(big + small), small, 'ring')
    v%kind = VEHICLE_DOUBLE_RING
    v%riders = 2
    v%scales(:2) = s
    call vehicle_body(v, vb, st)
    call check(st%ok(), 'double ring from input: built: '//st%text())
    ! the first rider (scale s(1)) in the front ring, the second in the rear
    call compare(vb, [ring, person(2)%body, ring, person(1)%body], reshape([centre, centre, centre2, centre2], &
                 [3, 4]), 4*big + 2*small, 2*(big + small), small, 'double ring, riders of scales 0.6 and 1.08')
  end subroutine ring_from_input

  !> vb against `parts` placed at `at` (V), joined by Steiner's theorem;
  !> its contacts' distance, width and drag spheres (the tube's radius).
  subroutine compare(vb, parts, at, length, width, small, what)
    type(vehicle_body_t), intent(in) :: vb
    type(rigid_body_t), intent(in) :: parts(:)
    real(wp), intent(in) :: at(:, :), length, width, small
    character(len=*), intent(in) :: what
    real(wp) :: total, com(3), inertia(3, 3), d(3), eye(3, 3)
    integer :: i, j
    eye = 0
    do i = 1, 3
      eye(i, i) = 1
    end do
    total = sum(parts%mass)
    com = 0
    do j = 1, size(parts)
      com = com + parts(j)%mass*(at(:, j) + parts(j)%com)/total
    end do
    inertia = 0
    do j = 1, size(parts)
      d = at(:, j) + parts(j)%com - com
      inertia = inertia + parts(j)%inertia + parts(j)%mass*(dot_product(d, d)*eye - spread(d, 2, 3)*spread(d, 1, 3))
    end do
    call check_close(vb%body%mass, total, 1e-14_wp, 0.0_wp, what//' from input: its mass')
    call check(maxval(abs(vb%body%com - com)) <= 1e-12_wp*norm2(com), what//' from input: its centre of mass')
    call check(maxval(abs(vb%body%inertia - inertia)) <= 1e-12_wp*maxval(abs(inertia)), &
               what//' from input: its inertia, the torus formulas and Steiner''s theorem')
    call check_close(vb%length, length, 1e-15_wp, 0.0_wp, what//' from input: the contacts'' distance')
    call check_close(vb%width, width, 1e-15_wp, 0.0_wp, what//' from input: its width 2 (R + r)')
    call check(all(vb%drag_radius == small), what//' from input: the drag''s spheres of the tube''s radius')
  end subroutine compare

  !> The declared defaults of the vehicle's inputs (io_declarations_multibody,
  !> docs/inputs.md) are the vehicle_t's: what the reader keeps when the
  !> input gives none is what the reference says.
  subroutine declared_defaults()
    type(vehicle_t) :: v
    call default_is('mat_length', v%mat_size(1:1))
    call default_is('mat_width', v%mat_size(2:2))
    call default_is('mat_thickness', v%mat_size(3:3))
    call default_is('mat_mass', [v%mat_mass])
    call default_is('ring_radii', v%ring_radii)
    call default_is('ring_mass', [v%ring_mass])
    call default_is('raft_radii', v%raft_radii)
    call default_is('raft_mass', [v%raft_mass])
    call default_is('raft_floor', [v%raft_floor])
    call default_is('scale', v%scales(1:1))
  end subroutine declared_defaults

  !> The &sled declaration of `name`: its default is x.
  subroutine default_is(name, x)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: x(:)
    real(wp) :: declared(size(x))
    integer :: k, stat
    declared = -1
    stat = 1
    do k = 1, size(multibody_declarations)
      associate (d => multibody_declarations(k))
        if (d%name == name .and. index(' '//trim(d%groups)//' ', ' sled ') > 0) &
          read (d%default, *, iostat=stat) declared
      end associate
    end do
    call check(stat == 0 .and. all(declared == x), '&sled '//name//': the declared default is vehicle_t''s')
  end subroutine default_is

  subroutine refusals()
    type(vehicle_body_t) :: vb
    type(vehicle_t) :: v
    type(status_t) :: st
    call vehicle_body(vehicle_t(VEHICLE_RING, 2, 1.0_wp), vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'riders = 2: a ring carries 1 rider only') > 0, &
               'a single ring with 2 riders refused: '//st%text())
    st = status_t()
    call vehicle_body(vehicle_t(VEHICLE_RAFT, 5, 1.0_wp), vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'riders = 5: a raft carries 1 to 4 riders') > 0, &
               'a raft with 5 riders refused: '//st%text())
    st = status_t()
    call vehicle_body(vehicle_t(VEHICLE_MAT, 1, 0.5_wp), vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'scales(1) = 0.5') > 0, 'scale 0.5 refused: '//st%text())
    st = status_t()
    v = vehicle_t(VEHICLE_DOUBLE_RING, 2, 1.0_wp)
    v%scales(2) = 1.2_wp
    call vehicle_body(v, vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'scales(2) = 1.2') > 0, 'the second rider''s scale 1.2 '// &
               'refused: '//st%text())
    st = status_t()
    v = vehicle_t(VEHICLE_RING, 1, 1.0_wp)
    v%ring_radii = [0.2_wp, 0.2_wp]
    call vehicle_body(v, vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'ring_radii = 0.2, 0.2: the tube''s radius r (the second) '// &
               'must be > 0 and less than R') > 0, 'a ring with r = R refused: '//st%text())
    st = status_t()
    v = vehicle_t(VEHICLE_RAFT, 4, 1.0_wp)
    v%raft_floor = 0.5_wp
    call vehicle_body(v, vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'raft_floor = 0.5: must lie in [0, 2 r] = [0, 0.44] m') > 0, &
               'a raft''s floor above its tube refused: '//st%text())
    st = status_t()
    v = vehicle_t(VEHICLE_MAT, 1, 1.0_wp)
    v%mat_mass = 0
    call vehicle_body(v, vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'mat_mass = 0') > 0, 'a mat of no mass refused: '//st%text())
    ! a part of another kind is not looked at: a ring's radii on a mat
    st = status_t()
    v = vehicle_t(VEHICLE_MAT, 1, 1.0_wp)
    v%ring_radii = [0.2_wp, 0.2_wp]
    call vehicle_body(v, vb, st)
    call check(st%ok(), 'a mat is built whatever a ring''s radii: '//st%text())
  end subroutine refusals
end program test_vehicle
