!> The free rotation (kinetostatics_free_rotation): its maps along random
!> motions (element_checks: velocity, acceleration against differences, power
!> of the force map), and the change of chart: the pose and the angular
!> velocity are kept exactly, the middle angle becomes zero, and a rotation that
!> sweeps through the singular pose of a plain Cardan chart stays regular when
!> the chart is changed at its edge.
program test_free_rotation
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: rot_x, rot_y, rot_z, cross
  use testing, only: check, check_close, finish_tests
  use element_checks, only: check_element
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_free_rotation, only: free_rotation_t, new_free_rotation
  implicit none (type, external)

  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]
  integer :: trial

  do trial = 1, size(times)
    call check_element('free rotation, first axis z', new_free_rotation('rot', 1, 2, [1, 2, 3], &
      [0.0_wp, 0.0_wp, 1.0_wp], matmul(rot_x(0.4_wp), rot_y(-1.3_wp))), [1], [1, 2, 3], [2], [integer ::], &
      times(trial))
    call check_element('free rotation, oblique first axis', new_free_rotation('rot', 1, 2, [1, 2, 3], &
      [0.3_wp, -0.8_wp, 0.5_wp], matmul(rot_z(2.1_wp), rot_x(0.9_wp))), [1], [1, 2, 3], [2], [integer ::], &
      times(trial))
  end do
  call rebase_keeps_state()
  call sweep_through_singular_pose()
  call finish_tests('test_free_rotation')

contains

  !> Rebasing at a state with the middle angle at the chart's edge: the output
  !> frame's pose and angular velocity agree to rounding (1e-14 of O(1) values).
  subroutine rebase_keeps_state()
    type(free_rotation_t) :: e
    type(frame_state_t) :: frames(2)
    type(scalar_state_t) :: scalars(3)
    type(status_t) :: st
    real(wp) :: rot0(3, 3), omega0(3)
    e = new_free_rotation('rot', 1, 2, [1, 2, 3], [0.0_wp, 0.0_wp, 1.0_wp], rot_y(0.7_wp))
    frames(1)%rot = matmul(rot_z(0.3_wp), rot_x(-0.5_wp))
    frames(1)%omega = [0.2_wp, -1.1_wp, 0.4_wp]
    scalars(1) = scalar_state_t(7.9_wp, 150.0_wp, 0.0_wp, 0.0_wp)
    scalars(2) = scalar_state_t(-1.2_wp, 3.0_wp, 0.0_wp, 0.0_wp)
    scalars(3) = scalar_state_t(0.8_wp, -20.0_wp, 0.0_wp, 0.0_wp)
    call check_close(e%chart_margin(scalars(2)%q), 0.0_wp, 0.0_wp, 1e-15_wp, 'chart margin is zero at the chart limit')
    call e%position(frames, scalars, st)
    call e%velocity(frames, scalars)
    rot0 = frames(2)%rot
    omega0 = frames(2)%omega
    call e%rebase(scalars)
    call e%position(frames, scalars, st)
    call e%velocity(frames, scalars)
    call check(maxval(abs(frames(2)%rot - rot0)) <= 1e-14_wp, 'rebase keeps the orientation')
    call check(maxval(abs(frames(2)%omega - omega0)) <= 1e-14_wp*norm2(omega0), 'rebase keeps the angular velocity')
    call check(scalars(2)%q == 0 .and. scalars(3)%q == 0, 'rebase: q2 = q3 = 0')
    call check(abs(scalars(1)%q - (7.9_wp - 2*acos(-1.0_wp))) <= 1e-14_wp, 'rebase: q1 kept, wrapped to [-pi, pi]')
    call check(e%rebases == 1, 'rebase counted')
  end subroutine rebase_keeps_state

  !> A body spinning about an axis normal to the chart's first axis:
  !> omega = spin e_y + 0.7 e_z (world, input frame at rest), first axis e_x.
  !> The third axis (world e_z at the start) turns into the first within a
  !> quarter turn: without a change of chart q2 reaches 90 degrees. The angles
  !> are integrated by 4th-order Runge-Kutta from q' = [n1 n2 n3]^-1 omega, with
  !> a change of chart whenever |q2| reaches the limit; the orientation is
  !> compared with the exact one, exp(t [omega]) R_0, over 10 turns.
  subroutine sweep_through_singular_pose()
    type(free_rotation_t) :: e
    type(frame_state_t) :: frames(2)
    type(scalar_state_t) :: scalars(3)
    type(status_t) :: st
    real(wp) :: omega(3), rot0(3, 3), exact(3, 3), q(3), k1(3), k2(3), k3(3), k4(3), dt, t, worst, w
    integer :: step, nsteps
    omega = [0.0_wp, 10.0_wp, 0.7_wp]
    w = norm2(omega)
    rot0 = rot_x(acos(-1.0_wp)/2)        ! lying: body z horizontal
    e = new_free_rotation('rot', 1, 2, [1, 2, 3], [1.0_wp, 0.0_wp, 0.0_wp], rot0, chart_limit=1.2_wp)
    q = 0
    nsteps = 20000
    dt = 10*2*acos(-1.0_wp)/w/nsteps
    worst = 0
    t = 0
    do step = 1, nsteps
      k1 = rates_of(e, q, omega)
      k2 = rates_of(e, q + dt/2*k1, omega)
      k3 = rates_of(e, q + dt/2*k2, omega)
      k4 = rates_of(e, q + dt*k3, omega)
      q = q + dt/6*(k1 + 2*k2 + 2*k3 + k4)
      t = t + dt
      scalars%q = q
      if (e%chart_margin(scalars(2)%q) <= 0) then
        call e%position(frames, scalars, st)
        scalars%qd = rates_of(e, q, omega)
        call e%rebase(scalars)
        q = scalars%q
      end if
      call e%position(frames, scalars, st)
      exact = matmul(axis_turn(omega/w, w*t), rot0)
      worst = max(worst, maxval(abs(frames(2)%rot - exact)))
    end do
    ! RK4 with w dt = 3e-3 rad: global error ~ (w dt)^4 w t ~ 1e-10 per turn
    call check(worst <= 1e-8_wp, 'sweep through the singular pose of a plain chart: orientation exact to 1e-8')
    call check(e%rebases > 0, 'the chart was changed on the way')
    print '(a, i0, a, es10.2)', 'sweep: ', e%rebases, ' changes of chart, max orientation error ', worst
  end subroutine sweep_through_singular_pose

  !> Angle rates that give the relative angular velocity omega at angles q.
  function rates_of(e, q, omega) result(qd)
    type(free_rotation_t), intent(inout) :: e
    real(wp), intent(in) :: q(3), omega(3)
    real(wp) :: qd(3)
    type(frame_state_t) :: frames(2)
    type(scalar_state_t) :: scalars(3)
    type(status_t) :: st
    scalars%q = q
    call e%position(frames, scalars, st)
    qd = solve3(e%n, omega)
  end function rates_of

  pure function solve3(m, b) result(x)
    real(wp), intent(in) :: m(3, 3), b(3)
    real(wp) :: x(3), det
    det = dot_product(m(:, 1), cross(m(:, 2), m(:, 3)))
    x(1) = dot_product(b, cross(m(:, 2), m(:, 3)))/det
    x(2) = dot_product(m(:, 1), cross(b, m(:, 3)))/det
    x(3) = dot_product(m(:, 1), cross(m(:, 2), b))/det
  end function solve3

  pure function axis_turn(a, angle) result(r)
    real(wp), intent(in) :: a(3), angle
    real(wp) :: r(3, 3), k(3, 3)
    integer :: i
    k = reshape([0.0_wp, a(3), -a(2), -a(3), 0.0_wp, a(1), a(2), -a(1), 0.0_wp], [3, 3])
    r = sin(angle)*k + (1 - cos(angle))*matmul(k, k)
    do i = 1, 3
      r(i, i) = r(i, i) + 1
    end do
  end function axis_turn
end program test_free_rotation
