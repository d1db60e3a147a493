!> The inverse surface joint (kinetostatics_inverse_surface_joint) along
!> smooth random motions of its inputs (element_checks: velocity map = d/dt
!> of the position map, acceleration map = d/dt of the velocity map by
!> fourth-order differences to 1e-8 relative, force map conserves power to
!> 1e-12), on three surfaces with both sides and a mount rotation; and its
!> position map against the forward joint: the forward surface joint on the
!> output K_B at the same (u, v) gives back K_D = K_in M (round trip; rounding
!> of O(1) rotations and positions, 1e-14).
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
end program test_inverse_surface_joint
