!> Mechanisms and their equations of motion: pendulums (energy, period), the
!> double pendulum's mass matrix against the closed form, the four-bar loop
!> (closure, energy), kinetic energy = q'.M q'/2, and the errors for bad input.
program test_mechanism
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use testing, only: check, check_close, finish_tests
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_joints, only: new_revolute, new_rigid_offset
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_force_laws, only: new_constant_load
  use kinetostatics_models, only: pendulum_params_t, build_pendulum, fourbar_params_t, build_fourbar, &
    fourbar_assembly
  implicit none (type, external)

  call simple_pendulum_period(1e-3_wp)
  call simple_pendulum_period(1.0_wp)
  call pendulum_energy(1)
  call pendulum_energy(2)
  call double_pendulum_mass_matrix()
  call fourbar_run()
  call applied_force()
  call bad_inputs()
  call finish_tests('test_mechanism')

contains

  subroutine energy_at(m, work, y, e)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: y(:)
    real(wp), intent(out) :: e
    type(status_t) :: st
    real(wp) :: t, v
    call m%set_positions(work, y(1:m%f), st)
    call m%set_velocities(work, y(m%f + 1:))
    call m%energy(work, t, v)
    e = t + v
  end subroutine energy_at

  !> Zero crossings of theta give the period; small amplitude against
  !> 2 pi sqrt(L/g), any amplitude against the exact 2 pi sqrt(L/g)/AGM(1, cos(theta0/2)).
  subroutine simple_pendulum_period(theta0)
    real(wp), intent(in) :: theta0
    type(pendulum_params_t) :: p
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y(2), t, crossing(3), t0, an, bn, tmp, exact
    logical :: root
    integer :: idx(1), n, k
    character(len=12) :: label

    write (label, '(es9.2)') theta0
    p%length(1) = 0.8_wp
    call build_pendulum(p, sys%mechanism, st)
    call check(st%ok(), 'pendulum built: '//st%text())
    sys%event_index = [1]
    sys%event_value = [0.0_wp]
    opt%rtol = 1e-12_wp
    opt%atol = 1e-14_wp
    call integ%start(sys, 0.0_wp, [theta0, 0.0_wp], opt, st)
    n = 0
    do while (n < 3 .and. st%ok())
      call integ%advance(10.0_wp, t, y, st, root, idx)
      if (root) then
        n = n + 1
        crossing(n) = t
      end if
      if (t >= 10) exit
    end do
    call check(st%ok() .and. n == 3, 'pendulum: three zero crossings found')
    t0 = 2*pi*sqrt(p%length(1)/9.80665_wp)
    ! small amplitude: the amplitude correction theta0^2/16 = 6e-8 and the root
    ! location (~1e-12) are well inside 1e-6
    if (theta0 < 0.01_wp) call check_close(crossing(3) - crossing(1), t0, 1e-6_wp, 0.0_wp, &
                                           'small-amplitude period = 2 pi sqrt(L/g), theta0 = '//label)
    an = 1
    bn = cos(theta0/2)
    do k = 1, 10
      tmp = (an + bn)/2
      bn = sqrt(an*bn)
      an = tmp
    end do
    exact = t0/an
    ! rtol 1e-12 over two swings: root times to ~1e-11 relative
    call check_close(crossing(3) - crossing(1), exact, 1e-9_wp, 0.0_wp, &
                     'period = exact elliptic-integral period, theta0 = '//label)
  end subroutine simple_pendulum_period

  subroutine pendulum_energy(links)
    integer, intent(in) :: links
    type(pendulum_params_t) :: p
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y(2*links), t, e0, e, drift, scale
    integer :: k
    character(len=1) :: c

    write (c, '(i1)') links
    p%links = links
    p%length = [1.0_wp, 0.7_wp]
    p%mass = [1.0_wp, 0.6_wp]
    p%inertia = [0.01_wp, 0.02_wp]
    call build_pendulum(p, sys%mechanism, st)
    if (links == 1) then
      y = [1.2_wp, 0.0_wp]
    else
      y = [1.2_wp, -0.5_wp, 0.0_wp, 1.0_wp]
    end if
    call energy_at(sys%mechanism, sys%work, y, e0)
    scale = sum(p%mass(1:links))*9.80665_wp*sum(p%length(1:links))   ! energy scale m g L
    opt%rtol = 1e-12_wp
    opt%atol = 1e-12_wp
    call integ%start(sys, 0.0_wp, y, opt, st)
    drift = 0
    do k = 1, 200
      call integ%advance(0.1_wp*k, t, y, st)
      if (.not. st%ok()) exit
      call energy_at(sys%mechanism, sys%work, y, e)
      drift = max(drift, abs(e - e0))
    end do
    call check(st%ok(), c//'-link pendulum integrated 20 s: '//st%text())
    ! rtol 1e-12 per step over ~1e4 steps accumulates to ~1e-10 of m g L
    call check(drift <= 1e-9_wp*scale, c//'-link pendulum: energy conserved to 1e-9 over 20 s')
    print '(a, i0, a, es10.2)', '  pendulum, ', links, ' links: relative energy drift ', drift/scale
  end subroutine pendulum_energy

  !> M of the double pendulum (theta2 relative, point masses + inertia I about y):
  !> M11 = I1 + I2 + m1 L1^2 + m2 (L1^2 + L2^2 + 2 L1 L2 cos th2), M12 = I2 + m2 (L2^2 + L1 L2 cos th2),
  !> M22 = I2 + m2 L2^2; and q'.M q'/2 = T from the mass elements.
  subroutine double_pendulum_mass_matrix()
    type(pendulum_params_t) :: p
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: q(2), qd(2), qdd(2), ref(2, 2), t, v, c2
    integer :: trial
    type(mechanism_workspace_t) :: work
    p%links = 2
    p%length = [1.1_wp, 0.6_wp]
    p%mass = [1.3_wp, 0.7_wp]
    p%inertia = [0.05_wp, 0.03_wp]
    call build_pendulum(p, m, st)
    do trial = 1, 4
      q = [0.3_wp*trial, -0.7_wp + 0.5_wp*trial]
      qd = [sin(1.0_wp*trial), cos(2.0_wp*trial)]
      call m%dynamics(work, 0.0_wp, q, qd, qdd, st)
      call check(st%ok(), 'double pendulum dynamics: '//st%text())
      c2 = cos(q(2))
      ref(1, 1) = p%inertia(1) + p%inertia(2) + p%mass(1)*p%length(1)**2 + &
                  p%mass(2)*(p%length(1)**2 + p%length(2)**2 + 2*p%length(1)*p%length(2)*c2)
      ref(1, 2) = p%inertia(2) + p%mass(2)*(p%length(2)**2 + p%length(1)*p%length(2)*c2)
      ref(2, 1) = ref(1, 2)
      ref(2, 2) = p%inertia(2) + p%mass(2)*p%length(2)**2
      ! the passes are exact algebra: rounding only
      call check(maxval(abs(work%mass - ref)) <= 1e-13_wp*maxval(abs(ref)), &
                 'double pendulum: M from f+1 inverse-dynamics passes = closed form')
      call check(maxval(abs(work%mass - transpose(work%mass))) <= 1e-14_wp*maxval(abs(ref)), 'M symmetric')
      call m%set_positions(work, q, st)
      call m%set_velocities(work, qd)
      call m%energy(work, t, v)
      call check_close(0.5_wp*dot_product(qd, matmul(work%mass, qd)), t, 1e-13_wp, 0.0_wp, &
                       'double pendulum: q''.M q''/2 = kinetic energy of the mass elements')
    end do
  end subroutine double_pendulum_mass_matrix

  subroutine fourbar_run()
    type(fourbar_params_t) :: p
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: beta0(2), y(2), t, e0, e, drift, worst, scale, res, qd(1), tk, vk
    integer :: k
    type(mechanism_workspace_t) :: work_far

    call fourbar_assembly(p, 0.3_wp, 1, beta0, st)
    call build_fourbar(p, beta0 + [0.05_wp, -0.04_wp], sys%mechanism, st)   ! start off the solution on purpose
    call sys%mechanism%check_start(sys%work, [0.3_wp], st)
    call check(st%ok(), 'four-bar closes from a perturbed start: '//st%text())
    call check(sys%mechanism%closure_residual(sys%work) <= 1e-10_wp, 'four-bar: closure at the start')
    call check_close(sys%work%scalars(sys%mechanism%beta(1))%q, beta0(1), 1e-10_wp, 1e-10_wp, &
                     'four-bar: closure gives the assembled coupler angle')
    ! far from the solution Newton's few steps do not suffice: HYBRJ closes it
    block
      type(mechanism_t) :: far
      call build_fourbar(p, beta0 + [0.6_wp, -0.5_wp], far, st)
      call far%check_start(work_far, [0.3_wp], st)
      call check(st%ok() .and. work_far%hybrj_solves == 1, 'four-bar: HYBRJ closes the loop from 0.6 rad away: '// &
                 st%text())
      call check_close(work_far%scalars(far%beta(2))%q, beta0(2), 1e-10_wp, 1e-10_wp, &
                       'four-bar: HYBRJ finds the assembled rocker angle')
    end block
    ! M = q'.M q' consistency with the kinetic energy through the loop
    qd = 2.0_wp
    call sys%mechanism%evaluate(sys%work, 0.0_wp, [0.3_wp], qd, res, st)
    call sys%mechanism%set_velocities(sys%work, qd)
    call sys%mechanism%energy(sys%work, tk, vk)
    call check_close(0.5_wp*sys%work%mass(1, 1)*qd(1)**2, tk, 1e-12_wp, 0.0_wp, &
                     'four-bar: q''.M q''/2 = kinetic energy through the closed loop')
    call check(res <= 1e-12_wp*maxval(abs(sys%work%mass))*10, 'four-bar: inverse-dynamics residual 0 at q''''')

    y = [0.3_wp, 12.0_wp]
    call energy_at(sys%mechanism, sys%work, y, e0)
    scale = sum(p%mass)*9.80665_wp*(p%a + p%b + p%c)
    opt%rtol = 1e-12_wp
    opt%atol = 1e-12_wp
    call integ%start(sys, 0.0_wp, y, opt, st)
    drift = 0
    worst = 0
    do k = 1, 500
      call integ%advance(0.01_wp*k, t, y, st)
      if (.not. st%ok()) exit
      call energy_at(sys%mechanism, sys%work, y, e)
      worst = max(worst, sys%mechanism%closure_residual(sys%work))
      drift = max(drift, abs(e - e0))
    end do
    call check(st%ok(), 'four-bar integrated 5 s: '//st%text())
    call check(abs(y(1) - 0.3_wp) > 2*pi, 'four-bar: the crank turned at least once')
    call check(worst <= 1e-10_wp, 'four-bar: closure residual below 1e-10 all along')
    call check(drift <= 1e-9_wp*scale, 'four-bar: energy conserved to 1e-9')
    print '(a, es10.2, a, es10.2)', '  four-bar: closure residual ', worst, ', relative energy drift ', drift/scale
  end subroutine fourbar_run

  !> A constant horizontal force F on the bob (a constant-load force law at the
  !> bob's frame) holds the pendulum at tan(theta) = -F/(m g): q'' = 0 there
  !> (to rounding: 1e-13 rad/s^2 against terms of size g/L ~ 10).
  subroutine applied_force()
    type(pendulum_params_t) :: p
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: qdd(1), theta_eq
    integer :: bob
    type(mechanism_workspace_t) :: work
    call build_pendulum_with_force(p, 2.0_wp, m, bob, st)
    theta_eq = -atan(2.0_wp/9.80665_wp)   ! theta > 0 swings the bob towards -x
    call m%dynamics(work, 0.0_wp, [theta_eq], [0.0_wp], qdd, st)
    call check(st%ok(), 'pendulum with an applied force: '//st%text())
    call check(abs(qdd(1)) <= 1e-13_wp, 'constant load: equilibrium at tan(theta) = F/(m g)')
    call m%dynamics(work, 0.0_wp, [theta_eq - 0.1_wp], [0.0_wp], qdd, st)
    call check(qdd(1) > 0, 'constant load: restoring beyond the equilibrium')
  end subroutine applied_force

  !> The simple pendulum plus a rigid offset to the bob and a force +F x there.
  subroutine build_pendulum_with_force(p, force, m, bob, status)
    type(pendulum_params_t), intent(in) :: p
    real(wp), intent(in) :: force
    type(mechanism_t), intent(out) :: m
    integer, intent(out) :: bob
    type(status_t), intent(inout) :: status
    integer :: link, t1
    link = m%add_frame('link1')
    t1 = m%add_scalar('theta1')
    call m%add_element(new_revolute('hinge1', 1, link, t1, [0.0_wp, 1.0_wp, 0.0_wp]))
    call m%add_element(new_mass_element('bob1', link, p%mass(1), reshape([(0.0_wp, bob = 1, 9)], [3, 3]), &
                                        [0.0_wp, 0.0_wp, -p%length(1)], p%gravity, status))
    bob = m%add_frame('bob')
    call m%add_element(new_rigid_offset('rod', link, bob, [0.0_wp, 0.0_wp, -p%length(1)]))
    call m%add_law(new_constant_load('push', bob, [force, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], .false.))
    call m%set_coordinates([t1])
    call m%finalize(status)
  end subroutine build_pendulum_with_force

  subroutine bad_inputs()
    type(fourbar_params_t) :: p
    type(pendulum_params_t) :: pp
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: beta0(2), qdd(1)
    type(mechanism_workspace_t) :: work

    ! a loop that cannot close: coupler + rocker shorter than |B - D|
    p%b = 0.2_wp
    p%c = 0.2_wp
    call build_fourbar(p, [0.0_wp, 2.0_wp], m, st)
    call m%check_start(work, [0.0_wp], st)
    call check(.not. st%ok() .and. index(st%text(), 'coupler-rocker') > 0, &
               'a loop that cannot close names the loop: '//st%text())
    ! singular closure Jacobian at the start: coupler and rocker aligned (toggle)
    st = status_t()
    p%b = 0.5_wp
    p%c = 0.4_wp
    beta0 = [-pi, pi]   ! exactly aligned: C = B + b (D - B)/|D - B|
    call build_fourbar(p, beta0, m, st)
    call m%check_start(work, [pi], st)
    call check(.not. st%ok() .and. index(st%text(), 'singular') > 0 .and. index(st%text(), 'coupler-rocker') > 0, &
               'a singular closure Jacobian at the start is reported with its loop: '//st%text())
    ! a mass without inertia: the bob sits on the axis
    st = status_t()
    pp%length(1) = 0
    call build_pendulum(pp, m, st)
    call m%dynamics(work, 0.0_wp, [0.1_wp], [0.0_wp], qdd, st)
    call check(.not. st%ok() .and. index(st%text(), 'theta1') > 0, &
               'a coordinate without inertia is named: '//st%text())
    st = status_t()
    pp%length(1) = 1
    pp%mass(1) = 0
    call build_pendulum(pp, m, st)
    call check(.not. st%ok() .and. index(st%text(), 'bob1') > 0, 'a zero mass names its element: '//st%text())
  end subroutine bad_inputs
end program test_mechanism
