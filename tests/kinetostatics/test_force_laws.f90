!> The force-law seam and the contacts:
!> - contact kinematics: the slip velocity is the material relative velocity
!>   of the two bodies at the contact point (differences of the positions of
!>   the two material points along a motion), with both bodies moving;
!> - virtual power of every law: the power the mechanism reports (loads .
!>   velocities of the loaded frames) equals the generalized forces of the
!>   law's loads alone times q', open chain and closed loop;
!> - the exact solve of laws proportional to |N| against closed forms: the
!>   viscous law scaled by N on an incline, u'' = g sin(theta) - mu g cos(theta) u';
!> - the spring's work integral equals minus its potential energy change.
program test_force_laws
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t, paraboloid_t
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use kinetostatics_joints, only: new_revolute, new_rigid_offset
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_force_laws, only: new_coulomb_friction, new_viscous_friction, new_spring_damper, &
    new_constant_load, new_normal_viscous_friction
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t, LOADS_NONE
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: sled_params_t, build_sled
  use kinetostatics_force_law_factory, only: law_spec
  implicit none (type, external)

  real(wp), parameter :: g = 9.80665_wp
  ! power balance is algebraic: rounding of O(10..100) terms
  real(wp), parameter :: power_tol = 1e-12_wp

  call chain_laws()
  call sled_laws()
  call normal_viscous_incline()
  call spring_work()
  call finish_tests('test_force_laws')

contains

  !> A double pendulum (hinge about y, then an elbow about a skew axis, so the
  !> motion is spatial) with: a spring-damper from a ground point to link 2, a
  !> body-fixed constant load on link 1, and a contact between link 1 (A) and
  !> link 2 (B) at the elbow frame carrying viscous and Coulomb friction.
  subroutine build_chain(m, status)
    type(mechanism_t), intent(out) :: m
    type(status_t), intent(inout) :: status
    integer :: link1, elbow, link2, tip, t1, t2, c
    real(wp) :: inertia(3, 3)
    inertia = reshape([0.02_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.03_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.015_wp], [3, 3])
    link1 = m%add_frame('link1')
    t1 = m%add_scalar('theta1')
    call m%add_element(new_revolute('hinge1', 1, link1, t1, [0.0_wp, 1.0_wp, 0.0_wp]))
    call m%add_element(new_mass_element('mass1', link1, 1.0_wp, inertia, [0.1_wp, 0.0_wp, -0.4_wp], &
                                        [0.0_wp, 0.0_wp, -g], status))
    elbow = m%add_frame('elbow')
    call m%add_element(new_rigid_offset('rod1', link1, elbow, [0.05_wp, 0.02_wp, -0.8_wp]))
    link2 = m%add_frame('link2')
    t2 = m%add_scalar('theta2')
    call m%add_element(new_revolute('hinge2', elbow, link2, t2, [0.3_wp, 1.0_wp, 0.2_wp]/norm2([0.3_wp, 1.0_wp, &
                                    0.2_wp])))
    call m%add_element(new_mass_element('mass2', link2, 0.7_wp, inertia, [0.0_wp, 0.05_wp, -0.5_wp], &
                                        [0.0_wp, 0.0_wp, -g], status))
    tip = m%add_frame('tip')
    call m%add_element(new_rigid_offset('rod2', link2, tip, [0.0_wp, 0.1_wp, -0.6_wp]))
    call m%add_law(new_spring_damper('spring', 1, [0.5_wp, 0.2_wp, -0.3_wp], link2, [0.02_wp, 0.0_wp, -0.6_wp], &
                                     40.0_wp, 0.3_wp, 1.5_wp, status))
    call m%add_law(new_constant_load('push', link1, [1.0_wp, -0.5_wp, 0.3_wp], [0.2_wp, 0.1_wp, -0.4_wp], .true.))
    c = m%add_contact('knee', link1, link2, tip, normal_sign=1.0_wp)
    call m%add_law(new_viscous_friction('knee_viscous', c, 0.8_wp, status))
    call m%add_law(new_coulomb_friction('knee_coulomb', c, 0.1_wp, 1e-3_wp, status))
    call m%set_coordinates([t1, t2])
    call m%finalize(status)
  end subroutine build_chain

  !> Generalized forces of law k's loads alone (unit loads for a scaled law)
  !> times q' against the law's (unit) power, at the state of the last dynamics.
  subroutine virtual_power(m, work, qd, label)
    type(mechanism_t), intent(inout) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: qd(:)
    character(len=*), intent(in) :: label
    integer :: k
    real(wp) :: scale
    do k = 1, m%n_laws
      call m%inverse_dynamics(work, .false., .false., k)
      scale = max(sum(abs(work%gq*qd)), abs(work%unit_power(k)), tiny(1.0_wp))
      call check(abs(dot_product(work%gq, qd) - work%unit_power(k)) <= power_tol*scale, &
                 label//': virtual power of law '''//m%laws(k)%law%name//''': Q . q'' = sum f.v + tau.omega')
    end do
  end subroutine virtual_power

  subroutine chain_laws()
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    real(wp) :: q0(2), qd0(2), qdd0(2), r(6), qdd(2), material(3, -2:2), fd(3), tt, hh
    integer :: trial, k
    call build_chain(m, st)
    call check(st%ok(), 'chain with five force laws builds: '//st%text())
    do trial = 1, 4
      call random_number(r)
      q0 = 3*(r(1:2) - 0.5_wp)
      qd0 = 4*(r(3:4) - 0.5_wp)
      qdd0 = 4*(r(5:6) - 0.5_wp)
      call m%dynamics(work, 0.3_wp, q0, qd0, qdd, st)
      call check(st%ok(), 'chain dynamics: '//st%text())
      call virtual_power(m, work, qd0, 'open chain')
      ! an interaction's power is its force on B times the slip: checks where
      ! the law puts its loads (forces and moment arms on both bodies)
      do k = 3, 4
        associate (law => work%laws(k)%law, c => work%contact_states(1))
          call check(abs(work%unit_power(k) - dot_product(law%loads(1)%force, c%slip)) <= &
                     power_tol*norm2(law%loads(1)%force)*(norm2(c%velocity_a) + norm2(c%velocity_b)), &
                     'contact law '''//law%name//''': power = F . slip')
        end associate
      end do
      ! slip velocity: the material points of link 2 and link 1 at the contact
      ! point p(t0), followed along q(t) = q0 + qd0 t + qdd0 t^2/2;
      ! 4th-order differences, h = 1e-3 (truncation ~1e-13, rounding ~1e-13)
      call m%set_positions(work, q0, st)
      call m%set_velocities(work, qd0)
      call m%evaluate_laws(work, 0.0_wp, st)
      hh = 1e-3_wp
      associate (c => work%contact_states(1))
        block
          real(wp) :: p0(3), local_a(3), local_b(3)
          p0 = c%point
          local_a = matmul(transpose(work%frames(c%frame_a)%rot), p0 - work%frames(c%frame_a)%r)
          local_b = matmul(transpose(work%frames(c%frame_b)%rot), p0 - work%frames(c%frame_b)%r)
          do k = -2, 2
            tt = k*hh
            call m%set_positions(work, q0 + qd0*tt + qdd0*tt**2/2, st)
            material(:, k) = work%frames(c%frame_b)%r + matmul(work%frames(c%frame_b)%rot, local_b) &
                             - work%frames(c%frame_a)%r - matmul(work%frames(c%frame_a)%rot, local_a)
          end do
        end block
        fd = (material(:, -2) - 8*material(:, -1) + 8*material(:, 1) - material(:, 2))/(12*hh)
        call check(maxval(abs(fd - c%slip)) <= 1e-8_wp*max(norm2(c%slip), 1.0_wp), &
                   'contact between two moving bodies: slip = material relative velocity at the point')
        call check(norm2(c%velocity_b - c%velocity_a - c%slip) <= 1e-15_wp*norm2(c%velocity_b) &
                   + 1e-15_wp, 'contact: slip = velocity of B minus velocity of A at the point')
      end associate
    end do
    ! loads equal and opposite: the contact laws' forces on A and B cancel
    associate (law => work%laws(3)%law)
      call check(maxval(abs(law%loads(1)%force + law%loads(2)%force)) == 0, &
                 'contact law: force on A = -force on B')
    end associate
    ! the mass-matrix passes apply no law at all
    call m%inverse_dynamics(work, .false., .false., LOADS_NONE)
    call check(maxval(abs(work%gq)) == 0, 'no loads, no inertia, no gravity: zero generalized forces')
  end subroutine chain_laws

  !> The sled (a closed loop) with every friction law at both contacts: virtual
  !> power at scattered states of the bowl.
  subroutine sled_laws()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: surface
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    real(wp) :: q0(3), q(3), qd(3), qdd(3), r(6)
    integer :: trial
    surface = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, st)
    p%friction = [law_spec('coulomb', 'mu', 0.2_wp), law_spec('viscous', 'viscous_coefficient', 0.7_wp), &
                  law_spec('viscous_normal', 'mu', 0.05_wp)]
    q0 = [1.0_wp, 0.0_wp, 0.3_wp]
    call build_sled(p, surface, q0, m, st)
    call m%check_start(work, q0, st)
    call check(st%ok() .and. m%n_laws == 6, 'sled with six friction laws builds: '//st%text())
    do trial = 1, 5
      call random_number(r)
      q = q0 + 0.3_wp*(r(1:3) - 0.5_wp)
      qd = 3*(r(4:6) - 0.5_wp)
      call m%dynamics(work, 0.0_wp, q, qd, qdd, st)
      call check(st%ok(), 'sled dynamics with six laws: '//st%text())
      call virtual_power(m, work, qd, 'sled (closed loop)')
      ! the scaled laws' power is |N| times their unit power
      call check_close(work%law_power(1), abs(work%normal(1))*work%unit_power(1), 1e-14_wp, 0.0_wp, &
                       'Coulomb power = |N| x unit power')
    end do
  end subroutine sled_laws

  !> On a plane inclined by theta the sled sliding straight down with the
  !> viscous law scaled by N (F = -mu N w at each end, N summing to m g cos):
  !> u'' = g sin(theta) - mu g cos(theta) u' exactly, and over time
  !> u' = v_inf + (u0' - v_inf) exp(-k t), k = mu g cos(theta), v_inf = tan(theta)/mu.
  subroutine normal_viscous_incline()
    real(wp), parameter :: theta = 25*pi/180, mu = 0.4_wp
    type(sled_params_t) :: p
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: q0(3), qd0(3), qdd(3), k, v_inf, t
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(theta), 0.0_wp, -sin(theta)], [0.0_wp, 1.0_wp, 0.0_wp], st)
    p%friction = [law_spec('viscous_normal', 'mu', mu)]
    q0 = [0.3_wp, 0.1_wp, 0.0_wp]
    qd0 = [0.5_wp, 0.0_wp, 0.0_wp]
    call build_sled(p, plane, q0, sys%mechanism, st)
    call sys%mechanism%check_start(sys%work, q0, st)
    call sys%mechanism%dynamics(sys%work, 0.0_wp, q0, qd0, qdd, st)
    call check(st%ok(), 'incline with the N-scaled viscous law: '//st%text())
    k = mu*g*cos(theta)
    v_inf = tan(theta)/mu
    ! exact algebra: rounding only
    call check_close(qdd(1), g*sin(theta) - k*qd0(1), 1e-12_wp, 0.0_wp, &
                     'N-scaled viscous law: u'''' = g sin(theta) - mu g cos(theta) u'' (block solve)')
    call check_close(sum(sys%work%normal), p%mass*g*cos(theta), 1e-12_wp, 0.0_wp, &
                     'N-scaled viscous law: N_rear + N_front = m g cos(theta)')
    opt%rtol = 1e-11_wp
    opt%atol = 1e-12_wp
    y = sys%initial_state(q0, qd0)
    call integ%start(sys, 0.0_wp, y, opt, st)
    call integ%advance(2.0_wp, t, y, st)
    call check(st%ok(), 'N-scaled viscous law: integrated 2 s: '//st%text())
    ! a smooth exponential at rtol 1e-11 over ~200 steps
    call check_close(y(4), v_inf + (qd0(1) - v_inf)*exp(-k*t), 1e-9_wp, 0.0_wp, &
                     'N-scaled viscous law: u''(t) = v_inf + (u0'' - v_inf) exp(-k t)')
  end subroutine normal_viscous_incline

  !> An undamped spring on the double pendulum without other laws: its work
  !> integral is minus the change of its potential energy k (l - l0)^2/2.
  subroutine spring_work()
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp), allocatable :: y(:)
    real(wp) :: t, l0, l1, tk, vk, e0, e1
    real(wp), parameter :: k_spring = 40, rest = 0.3_wp, a(3) = [0.5_wp, 0.2_wp, -0.3_wp], &
                           b(3) = [0.02_wp, 0.0_wp, -0.6_wp]
    integer :: link1, link2, t1, t2
    real(wp) :: inertia(3, 3)
    inertia = reshape([0.02_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.03_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.015_wp], [3, 3])
    associate (m => sys%mechanism, work => sys%work)
      link1 = m%add_frame('link1')
      t1 = m%add_scalar('theta1')
      call m%add_element(new_revolute('hinge1', 1, link1, t1, [0.0_wp, 1.0_wp, 0.0_wp]))
      call m%add_element(new_mass_element('mass1', link1, 1.0_wp, inertia, [0.0_wp, 0.0_wp, -0.4_wp], &
                                          [0.0_wp, 0.0_wp, -g], st))
      link2 = m%add_frame('link2')
      t2 = m%add_scalar('theta2')
      call m%add_element(new_revolute('hinge2', link1, link2, t2, [1.0_wp, 0.0_wp, 0.0_wp]))
      call m%add_element(new_mass_element('mass2', link2, 0.7_wp, inertia, [0.0_wp, 0.05_wp, -0.5_wp], &
                                          [0.0_wp, 0.0_wp, -g], st))
      call m%add_law(new_spring_damper('spring', 1, a, link2, b, k_spring, rest, 0.0_wp, st))
      call m%set_coordinates([t1, t2])
      call m%finalize(st)
      y = sys%initial_state([0.4_wp, -0.3_wp], [1.0_wp, 2.0_wp])
      call m%set_positions(work, y(1:2), st)
      call m%set_velocities(work, y(3:4))
      call m%energy(work, tk, vk)
      e0 = tk + vk
      l0 = norm2(work%frames(link2)%r + matmul(work%frames(link2)%rot, b) - a)
      opt%rtol = 1e-11_wp
      opt%atol = 1e-11_wp
      call integ%start(sys, 0.0_wp, y, opt, st)
      call integ%advance(3.0_wp, t, y, st)
      call check(st%ok(), 'pendulum with a spring: integrated 3 s: '//st%text())
      call m%set_positions(work, y(1:2), st)
      call m%set_velocities(work, y(3:4))
      call m%energy(work, tk, vk)
      e1 = tk + vk
      l1 = norm2(work%frames(link2)%r + matmul(work%frames(link2)%rot, b) - a)
    end associate
    ! integrated with the motion at rtol 1e-11: 1e-8 of the energies involved
    call check_close(y(5), -k_spring/2*((l1 - rest)**2 - (l0 - rest)**2), 1e-8_wp, 1e-8_wp*abs(e0), &
                     'undamped spring: work = -(change of k (l - l0)^2/2)')
    call check_close(e1 - e0, y(5), 1e-8_wp, 1e-8_wp*abs(e0), 'spring: E(t) - E(0) = work of the spring')
  end subroutine spring_work
end program test_force_laws
