!> The sled: a bar on a surface with a rear surface joint (q = u, v, phi) and a
!> front surface joint closed by three plane-point conditions (beta = pitch,
!> u2, v2), like the rider's legs (thesis 4.27). Friction laws at its two
!> contacts: exact Coulomb solve against the incline's closed form, the two
!> normal-force rules, loads on the bar equal to loads on the Darboux frames,
!> energy balance with the work integrals; the air's drag (drag_area)
!> against the closed form of a bar sliding down a frictionless incline.
program test_sled
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t, paraboloid_t
  use numerics_ode, only: ode_integrator_t, ode_options_t, ODE_BDF
  use kinetostatics_mechanism, only: mechanism_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: sled_params_t, build_sled
  use kinetostatics_force_law_factory, only: law_spec
  implicit none (type, external)

  real(wp), parameter :: g = 9.80665_wp

  call incline(0.0_wp, 1.0_wp)
  call incline(0.7_wp, 1.0_wp)
  call incline(0.3_wp, -1.0_wp)
  call viscous_plane()
  call viscous_weight_plane()
  call bowl(0.0_wp)
  call bowl(0.15_wp)
  call darboux_loads_equal_body_loads()
  call energy_balance()
  call incline_drag()
  call finish_tests('test_sled')

contains

  pure function unit(i) result(e)
    integer, intent(in) :: i
    real(wp) :: e(3)
    e = 0
    e(i) = 1
  end function unit

  !> On a plane inclined by theta with Coulomb mu the bar slides straight down
  !> with u'' = g (sin theta - mu cos theta) whatever its heading phi. With
  !> sigma = -1 the Darboux z axes point into the plane, N comes out negative
  !> and the friction, |N|-proportional, must be the same.
  subroutine incline(phi, sigma)
    real(wp), intent(in) :: phi, sigma
    real(wp), parameter :: theta = 20*pi/180, mu = 0.2_wp
    type(sled_params_t) :: p
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: qdd(3), acc, t, res, q0(3), qd0(3)
    real(wp), allocatable :: y(:)
    character(len=20) :: label

    write (label, '(f4.2, a, f4.1)') phi, ', sigma ', sigma
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(theta), 0.0_wp, -sin(theta)], [0.0_wp, 1.0_wp, 0.0_wp], st)
    p%friction = [law_spec('coulomb', 'mu', mu)]
    p%sigma = sigma
    p%front_normal_from_cut_force = sigma < 0   ! the other rule in one of the cases
    q0 = [0.5_wp, 0.2_wp, phi]
    qd0 = [1.0_wp, 0.0_wp, 0.0_wp]
    call build_sled(p, plane, q0, sys%mechanism, st)
    call sys%mechanism%check_start(sys%work, q0, st)
    call check(st%ok(), 'sled on the incline starts: '//st%text())
    associate (m => sys%mechanism, work => sys%work)
      call check(m%closure_residual(work) <= 1e-10_wp, 'incline: closed at the start')
      call check_close(work%scalars(m%scalar_index('pitch'))%q, 0.0_wp, 0.0_wp, 1e-12_wp, 'incline: pitch 0 on a plane')
      call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
      call check(st%ok(), 'incline: evaluate: '//st%text())
      qdd = work%qdd
      acc = g*(sin(theta) - mu*cos(theta))
      ! exact algebra; the only approximation is the regularization
      ! (eps/|w|)^2/2 = 5e-13 relative
      call check_close(qdd(1), acc, 1e-8_wp, 0.0_wp, 'incline: u'''' = g (sin theta - mu cos theta), phi = '//label)
      call check(abs(qdd(2)) <= 1e-8_wp*g .and. abs(qdd(3)) <= 1e-8_wp*g, &
                 'incline: v'''' = phi'''' = 0, phi = '//label)
      ! N > 0 presses along z_D: with sigma = -1 z_D points into the plane,
      ! away from the bar, so the plane must pull (N < 0)
      call check_close(sigma*(work%normal_force(1) + work%normal_force(2)), p%mass*g*cos(theta), &
                       1e-10_wp, 0.0_wp, 'incline: N_rear + N_front = m g cos theta, '//label)
      call check_close(work%normal_force(1), work%normal_force(2), 1e-10_wp, 0.0_wp, &
                       'incline: centre of mass halfway: equal normal forces')
      call check(res <= 1e-10_wp*p%mass*g, 'incline: inverse dynamics with the friction found has zero residual')
      ! the cut force of the plane-point condition along the front normal z_D2
      ! is the force on the bar's front end along that normal: N_front (with
      ! either rule for the front contact's normal force)
      call check_close(work%lambda(3), work%normal_force(2), 1e-10_wp, 0.0_wp, &
                       'incline: cut force of front_z = normal force at the front contact, '//label)
      call check_close(work%law_power(1), -abs(work%normal_force(1))*mu*qd0(1), 1e-10_wp, 0.0_wp, &
                       'incline: Coulomb power at the rear = -mu N |w|')
    end associate
    opt%rtol = 1e-10_wp
    opt%atol = 1e-12_wp
    y = sys%initial_state(q0, qd0)
    call integ%start(sys, 0.0_wp, y, opt, st)
    call integ%advance(1.0_wp, t, y, st)
    call check(st%ok(), 'incline: integrated 1 s: '//st%text())
    ! constant acceleration: Adams integrates a quadratic exactly up to rounding
    call check_close(y(1), q0(1) + qd0(1) + acc/2, 1e-8_wp, 0.0_wp, 'incline: u(1 s) = u0 + u0'' + a/2')
    call check_close(y(4), qd0(1) + acc, 1e-8_wp, 0.0_wp, 'incline: u''(1 s) = u0'' + a')
  end subroutine incline

  !> On a horizontal plane with viscous friction c at both contacts the bar
  !> translating along its axis slows as u' = u0' exp(-2 c t/m).
  subroutine viscous_plane()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t
    real(wp), parameter :: c = 3   ! N s/m
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
    p%friction = [law_spec('viscous', 'viscous_coefficient', c)]
    call build_sled(p, plane, [0.0_wp, 0.0_wp, 0.0_wp], sys%mechanism, st)
    y = sys%initial_state([0.0_wp, 0.0_wp, 0.0_wp], [2.0_wp, 0.0_wp, 0.0_wp])
    call sys%mechanism%check_start(sys%work, y(1:3), st)
    opt%rtol = 1e-11_wp
    opt%atol = 1e-13_wp
    call integ%start(sys, 0.0_wp, y, opt, st)
    call integ%advance(1.5_wp, t, y, st)
    call check(st%ok(), 'viscous plane: integrated: '//st%text())
    ! rtol 1e-11 over ~100 steps of a smooth exponential
    call check_close(y(4), 2*exp(-2*c*1.5_wp/p%mass), 1e-8_wp, 0.0_wp, &
                     'viscous friction: u'' = u0'' exp(-2 c t/m)')
    call check_close(y(1), 2*p%mass/(2*c)*(1 - exp(-2*c*1.5_wp/p%mass)), 1e-8_wp, 0.0_wp, &
                     'viscous friction: u = u0'' m/(2c) (1 - exp(-2 c t/m))')
    ! each contact's work: -c int w^2 dt = -c u0'^2 m/(4c) (1 - exp(-4 c t/m))
    call check_close(y(7), -c*4*p%mass/(4*c)*(1 - exp(-4*c*1.5_wp/p%mass)), 1e-8_wp, &
                     0.0_wp, 'viscous friction: work integral of the rear contact in closed form')
    call check_close(y(8), y(7), 1e-10_wp, 0.0_wp, 'viscous friction: both contacts do the same work')
  end subroutine viscous_plane

  !> viscous_weight (mu per weight) at both contacts: each carries half the
  !> sled's weight M g, so together -mu M g u' and the bar translating on a
  !> horizontal plane slows as u' = u0' exp(-mu g t), whatever its mass
  !> (before, the sled gave its laws no weight: no force at all).
  subroutine viscous_weight_plane()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t, g
    real(wp), parameter :: mu = 0.4_wp   ! s/m
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
    p%friction = [law_spec('viscous_weight', 'mu', mu)]
    g = norm2(p%gravity)
    call build_sled(p, plane, [0.0_wp, 0.0_wp, 0.0_wp], sys%mechanism, st)
    y = sys%initial_state([0.0_wp, 0.0_wp, 0.0_wp], [2.0_wp, 0.0_wp, 0.0_wp])
    call sys%mechanism%check_start(sys%work, y(1:3), st)
    call check(st%ok(), 'viscous_weight plane: starts: '//st%text())
    opt%rtol = 1e-11_wp
    opt%atol = 1e-13_wp
    call integ%start(sys, 0.0_wp, y, opt, st)
    call integ%advance(0.5_wp, t, y, st)
    call check(st%ok(), 'viscous_weight plane: integrated: '//st%text())
    ! rtol 1e-11 over a smooth exponential, as viscous_plane
    call check_close(y(4), 2*exp(-mu*g*0.5_wp), 1e-8_wp, 0.0_wp, &
                     'viscous_weight friction: u'' = u0'' exp(-mu g t)')
    call check_close(y(1), 2/(mu*g)*(1 - exp(-mu*g*0.5_wp)), 1e-8_wp, 0.0_wp, &
                     'viscous_weight friction: u = u0''/(mu g) (1 - exp(-mu g t))')
  end subroutine viscous_weight_plane

  !> In a paraboloid bowl: without friction energy is conserved (drift < 1e-8
  !> of the energy scale m g L + T0 over 10 s) and the loop stays closed; with
  !> friction energy only decreases. M is symmetric positive definite and
  !> q'.M q'/2 equals the bodies' kinetic energy.
  subroutine bowl(mu)
    real(wp), intent(in) :: mu
    type(sled_params_t) :: p
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t, e0, e, e_prev, drift, worst, scale, tk, vk, res, chol(3, 3), q0(3), qd0(3), &
                mpol(3, 3), tij
    integer :: k, i, j
    logical :: decreasing, spd
    character(len=8) :: label

    write (label, '(f4.2)') mu
    surface = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, st)
    if (mu > 0) p%friction = [law_spec('coulomb', 'mu', mu)]   ! Coulomb's mu > 0: none for 0
    q0 = [1.0_wp, 0.0_wp, 0.3_wp]
    qd0 = [0.0_wp, 1.2_wp, 0.5_wp]
    call build_sled(p, surface, q0, sys%mechanism, st)
    call sys%mechanism%check_start(sys%work, q0, st)
    call check(st%ok(), 'sled in the bowl starts: '//st%text())
    associate (m => sys%mechanism, work => sys%work)
      call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
      call check(res <= 1e-10_wp*p%mass*g, 'bowl: inverse-dynamics residual zero at the computed q'''', mu = '//label)
      call check(maxval(abs(work%mass - transpose(work%mass))) <= 1e-13_wp*maxval(abs(work%mass)), &
                 'bowl: M symmetric')
      chol = work%mass
      spd = .true.
      do j = 1, 3   ! Cholesky by hand: positive pivots <=> positive definite
        chol(j, j) = chol(j, j) - sum(chol(j, 1:j - 1)**2)
        spd = spd .and. chol(j, j) > 0
        if (.not. spd) exit
        chol(j, j) = sqrt(chol(j, j))
        do i = j + 1, 3
          chol(i, j) = (chol(i, j) - sum(chol(i, 1:j - 1)*chol(j, 1:j - 1)))/chol(j, j)
        end do
      end do
      call check(spd, 'bowl: M positive definite')
      ! M entry by entry from the kinetic energy of the bodies (polarization):
      ! M_ij = T(e_i + e_j) - T(e_i) - T(e_j), M_ii = 2 T(e_i); independent of
      ! the force passes, rounding only
      do i = 1, 3
        do j = 1, 3
          call m%set_velocities(work, unit(i) + unit(j))
          call m%energy(work, tk, vk)
          tij = tk
          call m%set_velocities(work, unit(i))
          call m%energy(work, tk, vk)
          tij = tij - tk
          call m%set_velocities(work, unit(j))
          call m%energy(work, tk, vk)
          tij = tij - tk
          mpol(i, j) = tij
        end do
      end do
      call check(maxval(abs(mpol - work%mass)) <= 1e-12_wp*maxval(abs(work%mass)), &
                 'bowl: M from the f+1 passes = M from the kinetic energy (through the closed loop)')
      call m%set_velocities(work, qd0)
      call m%energy(work, tk, vk)
      call check_close(0.5_wp*dot_product(qd0, matmul(work%mass, qd0)), tk, 1e-12_wp, 0.0_wp, &
                       'bowl: q''.M q''/2 = kinetic energy (M through the closed loop)')
      scale = p%mass*g*p%length + tk
      e0 = tk + vk
    end associate
    opt%rtol = 1e-11_wp
    opt%atol = 1e-11_wp
    if (mu > 0) then
      ! the rear contact comes to rest near t = 2.8 s and then sticks: the
      ! regularized friction is stiff there (see kinetostatics_mechanism), BDF
      opt%method = ODE_BDF
      opt%rtol = 1e-8_wp
      opt%atol = 1e-10_wp
    end if
    y = sys%initial_state(q0, qd0)
    call integ%start(sys, 0.0_wp, y, opt, st)
    drift = 0
    worst = 0
    e_prev = e0
    decreasing = .true.
    do k = 1, 100
      call integ%advance(0.1_wp*k, t, y, st)
      if (.not. st%ok()) exit
      call sys%mechanism%set_positions(sys%work, y(1:3), st)
      call sys%mechanism%set_velocities(sys%work, y(4:6))
      call sys%mechanism%energy(sys%work, tk, vk)
      e = tk + vk
      worst = max(worst, sys%mechanism%closure_residual(sys%work))
      drift = max(drift, abs(e - e0))
      decreasing = decreasing .and. e <= e_prev + 1e-9_wp*scale
      e_prev = e
    end do
    call check(st%ok(), 'bowl: integrated 10 s: '//st%text())
    if (mu > 0) print '(a, 6es11.3, a, i0)', '  sled with friction at 10 s: ', y(1:6), ', rhs ', sys%rhs_count
    call check(worst <= 1e-10_wp, 'bowl: closure residual below 1e-10 all along')
    if (mu == 0) then
      call check(drift <= 1e-8_wp*scale, 'bowl, frictionless: energy drift below 1e-8 over 10 s')
      print '(a, es10.2, a, es10.2, a, i0)', '  sled in the bowl: closure ', worst, ', energy drift ', drift/scale, &
        ', rhs ', sys%rhs_count
    else
      call check(decreasing .and. e_prev < e0 - 1e-3_wp*scale, 'bowl, mu = '//label//': energy decreases')
    end if
  end subroutine bowl
  !> Friction at the body frames (material slip at the contact points, the
  !> default) against friction at the Darboux frames (the thesis's form): the
  !> bar rides on the rear Darboux frame (same origin, so same velocity and a
  !> force there passes the revolutes unchanged), and at the front the closure
  !> holds the bar's end on the front Darboux origin, so their velocities are
  !> equal and the two loads differ only by a constraint force, which changes
  !> the cut forces of front_x and front_y but not q'', N or the powers.
  !> Equal to rounding at scattered states; trajectories equal to the
  !> integrator's tolerance.
  subroutine darboux_loads_equal_body_loads()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: body, darboux
    type(ode_integrator_t) :: integ_body, integ_darboux
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: yb(:), yd(:)
    real(wp) :: q0(3), qd0(3), q(3), qd(3), qdd_b(3), qdd_d(3), t, worst_qdd, worst_n, worst_p, r(6)
    integer :: k
    surface = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, st)
    p%friction = [law_spec('coulomb', 'mu', 0.15_wp), law_spec('viscous', 'viscous_coefficient', 0.8_wp)]
    q0 = [1.0_wp, 0.0_wp, 0.3_wp]
    qd0 = [0.0_wp, 1.2_wp, 0.5_wp]
    call build_sled(p, surface, q0, body%mechanism, st)
    p%loads_on_darboux_frames = .true.
    call build_sled(p, surface, q0, darboux%mechanism, st)
    call body%mechanism%check_start(body%work, q0, st)
    call darboux%mechanism%check_start(darboux%work, q0, st)
    call check(st%ok(), 'sled with loads on the body and on the Darboux frames builds: '//st%text())
    worst_qdd = 0
    worst_n = 0
    worst_p = 0
    do k = 1, 7
      call random_number(r)
      q = q0 + 0.2_wp*(r(1:3) - 0.5_wp)
      qd = 2*(r(4:6) - 0.5_wp)
      call body%mechanism%dynamics(body%work, 0.0_wp, q, qd, qdd_b, st)
      call darboux%mechanism%dynamics(darboux%work, 0.0_wp, q, qd, qdd_d, st)
      worst_qdd = max(worst_qdd, maxval(abs(qdd_b - qdd_d))/maxval(abs(qdd_b)))
      worst_n = max(worst_n, maxval(abs(body%work%normal - darboux%work%normal))/(p%mass*g))
      worst_p = max(worst_p, maxval(abs(body%work%law_power - darboux%work%law_power))/ &
                             maxval(abs(body%work%law_power)))
    end do
    call check(st%ok(), 'body and Darboux loads: dynamics at scattered states: '//st%text())
    ! rounding of O(10) terms through the f + 1 passes and the block solve
    call check(worst_qdd <= 1e-11_wp, 'friction on the bar at the contact points = on the Darboux frames: q''''')
    call check(worst_n <= 1e-11_wp, 'friction on the bar at the contact points = on the Darboux frames: N')
    call check(worst_p <= 1e-11_wp, 'friction on the bar at the contact points = on the Darboux frames: power')
    ! 2 s of sliding (the rear end comes to rest near 2.8 s), Adams at rtol 1e-11
    opt%rtol = 1e-11_wp
    opt%atol = 1e-11_wp
    yb = body%initial_state(q0, qd0)
    yd = darboux%initial_state(q0, qd0)
    call integ_body%start(body, 0.0_wp, yb, opt, st)
    call integ_body%advance(2.0_wp, t, yb, st)
    call integ_darboux%start(darboux, 0.0_wp, yd, opt, st)
    call integ_darboux%advance(2.0_wp, t, yd, st)
    call check(st%ok(), 'body and Darboux loads: integrated 2 s: '//st%text())
    ! two runs of the same ODE whose right-hand sides differ by rounding: their
    ! difference is bounded by the global errors, ~1e-9 here (rtol 1e-11 over ~500 steps)
    call check(maxval(abs(yb - yd)) <= 1e-8_wp*maxval(abs(yb)), &
               'friction on the bar = on the Darboux frames: the same motion over 2 s')
    print '(a, es10.2, a, es10.2, a, es10.2)', '  body vs Darboux loads: q'''' ', worst_qdd, ', N ', worst_n, &
      ', trajectory ', maxval(abs(yb - yd))/maxval(abs(yb))
  end subroutine darboux_loads_equal_body_loads

  !> Energy balance: E(t) - E(0) = sum of the laws' work integrals, with
  !> Coulomb and viscous friction at both contacts, sliding in the bowl for
  !> 2 s (Adams, rtol 1e-11), checked against the dissipated energy at every
  !> 0.1 s.
  subroutine energy_balance()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: q0(3), qd0(3), t, tk, vk, e0, worst, dissipated
    integer :: k
    surface = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, st)
    p%friction = [law_spec('coulomb', 'mu', 0.1_wp), law_spec('viscous', 'viscous_coefficient', 0.5_wp)]
    q0 = [1.0_wp, 0.0_wp, 0.3_wp]
    qd0 = [0.0_wp, 1.2_wp, 0.5_wp]
    call build_sled(p, surface, q0, sys%mechanism, st)
    call sys%mechanism%check_start(sys%work, q0, st)
    y = sys%initial_state(q0, qd0)
    call sys%mechanism%set_velocities(sys%work, qd0)
    call sys%mechanism%energy(sys%work, tk, vk)
    e0 = tk + vk
    opt%rtol = 1e-11_wp
    opt%atol = 1e-11_wp
    call integ%start(sys, 0.0_wp, y, opt, st)
    worst = 0
    do k = 1, 20
      call integ%advance(0.1_wp*k, t, y, st)
      if (.not. st%ok()) exit
      call sys%mechanism%set_positions(sys%work, y(1:3), st)
      call sys%mechanism%set_velocities(sys%work, y(4:6))
      call sys%mechanism%energy(sys%work, tk, vk)
      worst = max(worst, abs(tk + vk - e0 - sum(y(7:))))
    end do
    dissipated = -sum(y(7:))
    call check(st%ok(), 'energy balance run: '//st%text())
    call check(dissipated > 0 .and. all(y(7:) < 0), 'energy balance: friction dissipates')
    ! the work states are integrated with the motion at rtol 1e-11
    call check(worst <= 1e-8_wp*dissipated, 'energy balance: E(t) - E(0) = work of the friction laws to 1e-8')
    print '(a, es10.2, a, es10.2, a)', '  energy balance: ', worst/dissipated, ' of the ', dissipated, &
      ' J dissipated'
  end subroutine energy_balance

  !> The bar from rest on a frictionless plane inclined by theta, pointing
  !> down the slope (u along it, unit speed), with the air's drag at its
  !> centre: u'' = g sin theta - k u'^2 (k = rho C_d A/(2 m)), so u' = v_t
  !> tanh(a t/v_t) and u = v_t^2/a ln cosh(a t/v_t), a = g sin theta, v_t =
  !> sqrt(a/k); it stays on the line (the drag through the centre along the
  !> bar turns it not) and E(t) - E(0) is the drag's work. Adams at rtol
  !> 1e-11 over ~100 steps of a smooth motion: 1e-8 relative.
  subroutine incline_drag()
    real(wp), parameter :: theta = 20*pi/180, v_t = 2
    type(sled_params_t) :: p
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t, a, tk, vk, e0
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(theta), 0.0_wp, -sin(theta)], [0.0_wp, 1.0_wp, 0.0_wp], st)
    a = g*sin(theta)
    p%air_density = 1.1_wp
    p%drag_area = 2*p%mass*a/(p%air_density*v_t**2)
    call build_sled(p, plane, [0.0_wp, 0.0_wp, 0.0_wp], sys%mechanism, st)
    call sys%mechanism%check_start(sys%work, [0.0_wp, 0.0_wp, 0.0_wp], st)
    call check(st%ok() .and. sys%mechanism%n_laws == 1, 'incline with drag: starts, one law: '//st%text())
    if (.not. st%ok() .or. sys%mechanism%n_laws /= 1) return
    call check(sys%mechanism%laws(1)%law%name == 'bar.air_drag', 'incline with drag: the law bar.air_drag')
    y = sys%initial_state([0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp])
    call sys%mechanism%set_velocities(sys%work, [0.0_wp, 0.0_wp, 0.0_wp])
    call sys%mechanism%energy(sys%work, tk, vk)
    e0 = tk + vk
    opt%rtol = 1e-11_wp
    opt%atol = 1e-13_wp
    call integ%start(sys, 0.0_wp, y, opt, st)
    call integ%advance(2.0_wp, t, y, st)
    call check(st%ok(), 'incline with drag: integrated 2 s: '//st%text())
    call check_close(y(4), v_t*tanh(a*t/v_t), 1e-8_wp, 0.0_wp, 'incline with drag: u'' = v_t tanh(a t/v_t)')
    call check_close(y(1), v_t**2/a*log(cosh(a*t/v_t)), 1e-8_wp, 0.0_wp, &
                     'incline with drag: u = v_t^2/a ln cosh(a t/v_t)')
    call check(abs(y(2)) + abs(y(3)) + abs(y(5)) + abs(y(6)) <= 1e-10_wp, 'incline with drag: straight down the slope')
    call sys%mechanism%set_positions(sys%work, y(1:3), st)
    call sys%mechanism%set_velocities(sys%work, y(4:6))
    call sys%mechanism%energy(sys%work, tk, vk)
    call check(y(7) < 0, 'incline with drag: the air dissipates')
    call check_close(tk + vk - e0, y(7), 1e-8_wp, 0.0_wp, 'incline with drag: E(t) - E(0) = the drag''s work')
  end subroutine incline_drag
end program test_sled
