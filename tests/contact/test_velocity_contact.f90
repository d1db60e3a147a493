!> The velocity-level contact element (Montana; thesis appendix E with the
!> corrections of METHOD-PART2.md A.2) on a consistent motion: the pose of
!> body 2 is set from the contact coordinates by the exact contact map
!> (K_2D = K_1D turned by phi about z_1D and flipped, K_2 = K_2D through S2's
!> Darboux frame), so (3.84) must be the derivative of that pose. Checked with
!> element_checks along random motions of K_1 and (u1, v1, u2, v2, phi):
!> omega_2, W_2 (E.1-E.3) and alpha_2, a_2 (E.4-E.8) against differences, the
!> force map (E.9) by its power; the pose rates it hands to the integrator
!> against differences of the pose. Rolling (E.10-E.16): u2, v2 integrated from
!> u2' = A^-1 B u1' along the motion; no slip (1W_1D = 2W_2D), u2'' (E.12)
!> against differences of u2', and the power of E.16.
!>
!> The motions, surfaces and element live in a module (not in the program):
!> the pose callbacks handed to check_element are then module procedures,
!> not internal ones, which gfortran would call through trampolines on an
!> executable stack (refused by hardened kernels).
module velocity_contact_motion
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross, rot_x, rot_z
  use testing, only: check
  use element_checks, only: frame_motion, scalar_motion, motion_step, fd_tol, d4
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: ellipsoid_t, paraboloid_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint
  use contact_velocity_level, only: velocity_contact_t
  implicit none (type, external)
  private
  public :: s1, s2, element, st, rolling_t0, times, side_1, side_2
  public :: relative_pose_rotation, consistent_pose, pose_rates, rolling_pose, no_slip

  ! frames: 1 = K_1 (input), 2 = K_2 (output), 3 = K_1D (input, the surface joint on
  ! S1 of K_1); scalars 1..5 = u1, v1, u2, v2, phi, 6..11 = pose
  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]
  real(wp), parameter :: side_1 = 1, side_2 = -1
  type(ellipsoid_t) :: s1
  type(paraboloid_t) :: s2
  type(velocity_contact_t) :: element
  type(status_t) :: st
  real(wp) :: rolling_t0

contains

  !> The exact contact map: K_2 relative to K_1 (rotation, origin in K_1 axes).
  subroutine contact_map(u1, v1, u2, v2, phi, rot, origin)
    real(wp), intent(in) :: u1, v1, u2, v2, phi
    real(wp), intent(out) :: rot(3, 3), origin(3)
    type(surface_point_t) :: p1, p2
    type(darboux_frame_t) :: d1, d2
    type(status_t) :: s
    real(wp), parameter :: flip(3, 3) = reshape([1, 0, 0, 0, -1, 0, 0, 0, -1], [3, 3])
    call s1%evaluate(u1, v1, 3, p1, s)
    call darboux_frame(p1, side_1, 1.0_wp, 0.0_wp, d1, s)
    call s2%evaluate(u2, v2, 3, p2, s)
    call darboux_frame(p2, side_2, 1.0_wp, 0.0_wp, d2, s)
    rot = matmul(matmul(matmul(d1%r, rot_z(phi)), flip), transpose(d2%r))
    origin = p1%r - matmul(rot, p2%r)
  end subroutine contact_map

  function relative_pose_rotation(t) result(rot)
    real(wp), intent(in) :: t
    real(wp) :: rot(3, 3), origin(3)
    type(scalar_state_t) :: c(5)
    integer :: k
    do k = 1, 5
      call scalar_motion(k, t, c(k))
    end do
    call contact_map(c(1)%q, c(2)%q, c(3)%q, c(4)%q, c(5)%q, rot, origin)
  end function relative_pose_rotation

  !> Pose scalars from the contact coordinates: origin and the chart angles,
  !> Rx(a1) Ry(a2) Rz(a3) = R_a^T R_rel R_b^T.
  subroutine set_pose(scalars)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: rot(3, 3), origin(3), m(3, 3)
    call contact_map(scalars(1)%q, scalars(2)%q, scalars(3)%q, scalars(4)%q, scalars(5)%q, rot, origin)
    m = matmul(matmul(transpose(element%chart%ref_in), rot), transpose(element%chart%ref_out))
    scalars(6:8)%q = origin
    scalars(10)%q = asin(m(1, 3))
    scalars(9)%q = atan2(-m(2, 3), m(3, 3))
    scalars(11)%q = atan2(-m(1, 2), m(1, 1))
  end subroutine set_pose

  subroutine consistent_pose(t, frames, scalars)
    real(wp), intent(in) :: t
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer :: i
    associate (unused_t => t)
    end associate
    do i = 1, 2   ! u1, v1 move (they are not the element's inputs while sliding)
      call scalar_motion(i, t, scalars(i))
    end do
    call set_pose(scalars)
    call contact_frame(frames, scalars)
  end subroutine consistent_pose

  !> K_1D = the surface joint on S1 of K_1 at (u1, v1), all levels.
  subroutine contact_frame(frames, scalars)
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(surface_joint_t) :: joint
    type(frame_state_t) :: local(2)
    type(status_t) :: s
    joint = new_surface_joint('s1', 1, 2, 1, 2, s1, side_1, 1.0_wp, 0.0_wp)
    local(1) = frames(1)
    call joint%position(local, scalars(1:2), s)
    call joint%velocity(local, scalars(1:2))
    call joint%acceleration(local, scalars(1:2))
    frames(3) = local(2)
  end subroutine contact_frame

  !> The pose rates written by the velocity pass against differences of the pose.
  subroutine pose_rates(t0)
    real(wp), intent(in) :: t0
    type(frame_state_t) :: frames(3)
    type(scalar_state_t) :: scalars(11)
    real(wp) :: pose(6, -2:2), rates(6)
    integer :: k, i
    do k = -2, 3
      call frame_motion(1, t0 + merge(0, k, k == 3)*motion_step, frames(1))
      do i = 1, 5
        call scalar_motion(i, t0 + merge(0, k, k == 3)*motion_step, scalars(i))
      end do
      call set_pose(scalars)
      call contact_frame(frames, scalars)
      call element%position(frames, scalars, st)
      call element%velocity(frames, scalars)
      if (k <= 2) pose(:, k) = scalars(6:11)%q
    end do
    rates = scalars(6:11)%qd
    call check(maxval(abs(d4(pose) - rates)) <= fd_tol*max(1.0_wp, maxval(abs(rates))), &
               'velocity-level contact: pose rates = d/dt pose')
  end subroutine pose_rates

  !> Rolling: u2, v2 from u2' = A^-1 B u1' (RK4 from rolling_t0, steps of
  !> 1e-4 s: error ~ 1e-16 per step), the pose from the contact map.
  subroutine rolling_pose(t, frames, scalars)
    real(wp), intent(in) :: t
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: y(2), k1(2), k2(2), k3(2), k4(2), s, dt
    integer :: n, i
    y = [initial(3), initial(4)]
    n = max(1, ceiling(abs(t - rolling_t0)/1e-4_wp))
    dt = (t - rolling_t0)/n
    s = rolling_t0
    do i = 1, n
      k1 = rate(s, y)
      k2 = rate(s + dt/2, y + dt/2*k1)
      k3 = rate(s + dt/2, y + dt/2*k2)
      k4 = rate(s + dt, y + dt*k3)
      y = y + dt/6*(k1 + 2*k2 + 2*k3 + k4)
      s = s + dt
    end do
    scalars(3)%q = y(1)
    scalars(4)%q = y(2)
    call set_pose(scalars)
    call contact_frame(frames, scalars)
  end subroutine rolling_pose

  real(wp) function initial(k)
    integer, intent(in) :: k
    type(scalar_state_t) :: c
    call scalar_motion(k, rolling_t0, c)
    initial = c%q
  end function initial

  !> u2' = A^-1 B u1' at time t with (u2, v2) = y, from the element's position pass.
  function rate(t, y) result(yd)
    real(wp), intent(in) :: t, y(2)
    real(wp) :: yd(2)
    type(frame_state_t) :: frames(3)
    type(scalar_state_t) :: scalars(11)
    type(velocity_contact_t) :: e
    integer :: i
    e = element
    call frame_motion(1, t, frames(1))
    do i = 1, 5
      call scalar_motion(i, t, scalars(i))
    end do
    scalars(3)%q = y(1)
    scalars(4)%q = y(2)
    call set_pose(scalars)
    call contact_frame(frames, scalars)
    call e%position(frames, scalars, st)
    yd = matmul(e%ainv_b, [scalars(1)%qd, scalars(2)%qd])
  end function rate

  !> No slip: the velocities of the two contact points relative to their
  !> bodies agree, 1W_1D = 2W_2D (3.85), i.e. the material points move alike.
  subroutine no_slip(t0)
    real(wp), intent(in) :: t0
    type(frame_state_t) :: frames(3)
    type(scalar_state_t) :: scalars(11)
    type(velocity_contact_t) :: e
    real(wp) :: slip(3), ref
    integer :: i
    e = element
    call frame_motion(1, t0, frames(1))
    do i = 1, 5
      call scalar_motion(i, t0, scalars(i))
    end do
    call rolling_pose(t0, frames, scalars)
    call e%position(frames, scalars, st)
    call e%velocity(frames, scalars)
    slip = (frames(2)%v + cross(frames(2)%omega, e%joint_2%p)) - (frames(1)%v + cross(frames(1)%omega, e%joint_1%p))
    ref = norm2(frames(1)%v) + norm2(frames(1)%omega)*norm2(e%joint_1%p) + norm2(frames(3)%v)
    call check(norm2(slip) <= 1e-14_wp*ref, 'rolling: no slip between the material points at the contact')
  end subroutine no_slip
end module velocity_contact_motion

program test_velocity_contact
  use base_kinds, only: wp
  use testing, only: check, finish_tests
  use element_checks, only: check_element
  use geometry_elementary, only: ellipsoid_t, paraboloid_t
  use contact_velocity_level, only: new_velocity_contact
  use velocity_contact_motion, only: s1, s2, element, st, rolling_t0, times, side_1, side_2, &
    relative_pose_rotation, consistent_pose, pose_rates, rolling_pose, no_slip
  implicit none (type, external)
  integer :: trial

  s1 = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, st)
  s2 = paraboloid_t(0.7_wp, 1.3_wp, 1.0_wp, st)
  call check(st%ok(), 'surfaces')
  do trial = 1, size(times)
    element = new_velocity_contact('vc', 1, 3, 2, s1, side_1, s2, side_2, [1, 2, 3, 4, 5], [6, 7, 8, 9, 10, 11], &
                                   relative_pose_rotation(times(trial)), .false.)
    call check_element('velocity-level contact, sliding', element, [1, 3], [3, 4, 5], [2], [integer ::], &
                       times(trial), consistent_pose, 11)
    call pose_rates(times(trial))
    rolling_t0 = times(trial)
    element = new_velocity_contact('vc', 1, 3, 2, s1, side_1, s2, side_2, [1, 2, 3, 4, 5], [6, 7, 8, 9, 10, 11], &
                                   relative_pose_rotation(times(trial)), .true.)
    call check_element('velocity-level contact, rolling', element, [1, 3], [1, 2, 5], [2], [3, 4], times(trial), &
                       rolling_pose, 11)
    call no_slip(times(trial))
  end do
  call finish_tests('test_velocity_contact')
end program test_velocity_contact
