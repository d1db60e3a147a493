!> The inverse surface joint (kinetostatics_inverse_surface_joint) along
!> smooth random motions of its inputs (element_checks: velocity map = d/dt
!> of the position map, acceleration map = d/dt of the velocity map by
!> fourth-order differences to 1e-8 relative, force map conserves power to
!> 1e-12), on three surfaces with both sides and a mount rotation; and its
!> position map against the forward joint: the forward surface joint on the
!> output K_B at the same (u, v) gives back K_D = K_in M (round trip; rounding
!> of O(1) rotations and positions, 1e-14). Charts: near an ellipsoid's pole
!> the chart change keeps the body's pose and motion (K_B's rotation, origin,
!> angular and linear velocity after the turn phi and the joint, to 1e-13),
!> moves (u, v) away from the new chart's poles, and the joint's maps in the
!> new chart pass the same difference and power checks.
program test_inverse_surface_joint
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: rot_x, rot_y, rot_z
  use testing, only: check, finish_tests
  use element_checks, only: check_element, frame_motion, scalar_motion
  use geometry_surface, only: surface_t
  use geometry_elementary, only: ellipsoid_t, paraboloid_t, elliptic_cylinder_t
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint
  use kinetostatics_inverse_surface_joint, only: inverse_surface_joint_t, new_inverse_surface_joint
  use kinetostatics_joints, only: revolute_t, new_revolute
  implicit none (type, external)

  type(status_t) :: status
  class(surface_t), allocatable :: surface
  integer :: trial
  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]
  real(wp) :: mount(3, 3), flip(3, 3)

  mount = matmul(rot_z(0.7_wp), matmul(rot_y(-0.4_wp), rot_x(1.9_wp)))
  flip = rot_x(4*atan(1.0_wp))   ! the contact chain's turn-over: z_D against z_in
  do trial = 1, size(times)
    ! frames: 1 = K_in, 2 = K_B; scalars 1, 2 = u, v
    surface = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, status)
    call check_element('inverse surface joint on an ellipsoid', new_inverse_surface_joint('isj', 1, 2, 1, 2, &
             surface, 1.0_wp, 1.0_wp, 0.3_wp, mount), [1], [1, 2], [2], [integer ::], times(trial))
    call check_element('inverse surface joint on an ellipsoid, turned over', new_inverse_surface_joint('isj', 1, &
             2, 1, 2, surface, 1.0_wp, 1.0_wp, 0.0_wp, flip), [1], [1, 2], [2], [integer ::], times(trial))
    surface = paraboloid_t(0.7_wp, 1.3_wp, -1.0_wp, status)
    call check_element('inverse surface joint on a saddle, sigma = -1', new_inverse_surface_joint('isj', 1, 2, 1, &
             2, surface, -1.0_wp, 0.4_wp, -1.0_wp), [1], [1, 2], [2], [integer ::], times(trial))
    surface = elliptic_cylinder_t(0.5_wp, 0.9_wp, status)
    call check_element('inverse surface joint on a cylinder', new_inverse_surface_joint('isj', 1, 2, 1, 2, &
             surface, 1.0_wp, 0.0_wp, 1.0_wp, mount), [1], [1, 2], [2], [integer ::], times(trial))
    call check(status%ok(), 'surfaces built')
  end do
  call round_trip()
  call chart_change()
  call finish_tests('test_inverse_surface_joint')

contains

  !> At scattered inputs: the forward joint on K_B at (u, v) is K_in M.
  subroutine round_trip()
    type(inverse_surface_joint_t) :: inverse
    type(surface_joint_t) :: forward
    type(frame_state_t) :: frames(3)
    type(scalar_state_t) :: scalars(2)
    type(status_t) :: st
    real(wp) :: err_rot, err_r
    integer :: k
    surface = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, st)
    inverse = new_inverse_surface_joint('isj', 1, 2, 1, 2, surface, 1.0_wp, 1.0_wp, 0.3_wp, mount)
    forward = new_surface_joint('sj', 2, 3, 1, 2, surface, 1.0_wp, 1.0_wp, 0.3_wp)
    err_rot = 0
    err_r = 0
    do k = 1, 20
      call frame_motion(1, 0.13_wp*k - 1.3_wp, frames(1))
      call scalar_motion(1, 0.11_wp*k - 1.1_wp, scalars(1))
      call scalar_motion(2, 0.17_wp*k - 1.6_wp, scalars(2))
      call inverse%position(frames, scalars, st)
      call forward%position(frames, scalars, st)
      err_rot = max(err_rot, maxval(abs(frames(3)%rot - matmul(frames(1)%rot, mount))))
      err_r = max(err_r, maxval(abs(frames(3)%r - frames(1)%r)))
    end do
    call check(st%ok(), 'round trip evaluated: '//st%text())
    call check(err_rot < 1e-14_wp, 'forward joint on the inverse''s output: the Darboux frame is K_in M')
    call check(err_r < 1e-14_wp, 'forward joint on the inverse''s output: its origin is K_in''s')
    print '(a, 2es10.2)', 'round trip errors (rotation, position): ', err_rot, err_r
  end subroutine round_trip

  !> The chain K_1D -> turn phi about z -> inverse joint (turned over) -> K_B
  !> near the poles of an ellipsoid with three different semi-axes, at
  !> scattered motions: the chart change keeps K_B's pose and motion.
  subroutine chart_change()
    type(inverse_surface_joint_t) :: inverse
    type(revolute_t) :: turn
    type(frame_state_t) :: frames(3), before
    type(scalar_state_t) :: scalars(4)
    type(status_t) :: st
    real(wp) :: err_pose, err_motion, v_after
    integer :: k, changes
    surface = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, st)
    turn = new_revolute('turn', 1, 2, 3, [0.0_wp, 0.0_wp, 1.0_wp])
    err_pose = 0
    err_motion = 0
    v_after = 0
    changes = 0
    do k = 1, 12
      inverse = new_inverse_surface_joint('isj', 2, 3, 1, 2, surface, 1.0_wp, 1.0_wp, 0.0_wp, flip, 3, 4)
      call frame_motion(1, 0.21_wp*k - 1.3_wp, frames(1))
      call scalar_motion(1, 0.11_wp*k - 1.1_wp, scalars(1))
      call scalar_motion(2, 0.17_wp*k - 1.6_wp, scalars(2))
      call scalar_motion(3, 0.07_wp*k + 0.4_wp, scalars(3))
      scalars(2)%q = merge(1.0_wp, -1.0_wp, mod(k, 2) == 0)*(1.42_wp + 0.01_wp*k)   ! near a pole
      scalars(4)%q = 3
      call turn%position(frames, scalars, st)
      call inverse%position(frames, scalars, st)
      call turn%velocity(frames, scalars)
      call inverse%velocity(frames, scalars)
      before = frames(3)
      call inverse%rebase(scalars)
      if (nint(scalars(4)%q) /= 3) changes = changes + 1
      v_after = max(v_after, abs(scalars(2)%q))
      call turn%position(frames, scalars, st)
      call inverse%position(frames, scalars, st)
      call turn%velocity(frames, scalars)
      call inverse%velocity(frames, scalars)
      err_pose = max(err_pose, maxval(abs(frames(3)%rot - before%rot)), maxval(abs(frames(3)%r - before%r)))
      err_motion = max(err_motion, maxval(abs(frames(3)%omega - before%omega))/max(1.0_wp, norm2(before%omega)), &
                       maxval(abs(frames(3)%v - before%v))/max(1.0_wp, norm2(before%v)))
      if (k == 5) call check_element('inverse surface joint in the chart with poles on another axis', inverse, &
                                     [2], [1, 2], [3], [integer ::], 0.3_wp)
    end do
    call check(st%ok(), 'chart changes evaluated: '//st%text())
    call check(changes == 12, 'every chart change moves the poles off B''s z axis')
    call check(v_after < 0.25_wp*4*atan(1.0_wp) + 1e-12_wp, 'after a change the point is within 45 degrees '// &
               'of the new chart''s equator')
    call check(err_pose < 1e-13_wp, 'a chart change keeps K_B''s rotation and origin')
    call check(err_motion < 1e-13_wp, 'a chart change keeps K_B''s angular and linear velocity')
    print '(a, 3es10.2)', 'chart changes (pose, motion errors, largest |v| after): ', err_pose, err_motion, v_after
  end subroutine chart_change
end program test_inverse_surface_joint
