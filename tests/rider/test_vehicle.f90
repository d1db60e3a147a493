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
!> inertia ~ s^5.
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
  call scaling()
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
    character(len=40) :: label

    write (label, '(a, 1x, i0, a, f4.2)') trim(vehicle_kinds(v%kind)), v%riders, ' rider(s), scale ', v%scale
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
      call check_close(work%qdd(1), acc, 1e-8_wp, 0.0_wp, 'incline: u'''' = g (sin a - mu cos a), '//trim(label))
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

  subroutine refusals()
    type(vehicle_body_t) :: vb
    type(status_t) :: st
    call vehicle_body(vehicle_t(VEHICLE_RING, 2, 1.0_wp), vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'riders = 2: a ring carries 1 to 1') > 0, &
               'a single ring with 2 riders refused: '//st%text())
    st = status_t()
    call vehicle_body(vehicle_t(VEHICLE_RAFT, 5, 1.0_wp), vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'riders = 5') > 0, 'a raft with 5 riders refused: '//st%text())
    st = status_t()
    call vehicle_body(vehicle_t(VEHICLE_MAT, 1, 0.5_wp), vb, st)
    call check(.not. st%ok() .and. index(st%text(), 'scale = 0.5') > 0, 'scale 0.5 refused: '//st%text())
  end subroutine refusals
end program test_vehicle
