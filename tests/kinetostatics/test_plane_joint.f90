!> The plane joint (kinetostatics_plane_joint) along smooth random motions of
!> its inputs (element_checks: velocity map = d/dt of the position map,
!> acceleration map = d/dt of the velocity map to 1e-8 relative, force map
!> conserves power to 1e-12), and against the general surface joint on the
!> same plane at scattered inputs: the same output frame, velocities,
!> accelerations and generalized forces to rounding (1e-13 of these O(1..10)
!> numbers). A surface that is not affine (an ellipsoid) is refused.
program test_plane_joint
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_status, only: status_t
  use testing, only: check, finish_tests
  use element_checks, only: check_element, frame_motion, scalar_motion
  use geometry_elementary, only: plane_t, ellipsoid_t
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint
  use kinetostatics_plane_joint, only: plane_joint_t, new_plane_joint
  implicit none (type, external)

  type(status_t) :: status
  type(plane_t) :: plane
  integer :: trial
  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]

  plane = plane_t([0.2_wp, -0.1_wp, 0.3_wp], [1.1_wp, 0.4_wp, 0.2_wp], [-0.3_wp, 0.9_wp, 0.5_wp], status)
  call check(status%ok(), 'plane built')
  do trial = 1, size(times)
    ! frames: 1 = K_1, 2 = K_D; scalars 1, 2 = u, v
    call check_element('plane joint', new_plane_joint('pj', 1, 2, 1, 2, plane, 1.0_wp, 1.0_wp, 0.0_wp, status), &
                       [1], [1, 2], [2], [integer ::], times(trial))
    call check_element('plane joint, sigma = -1, x between r_u and r_v', new_plane_joint('pj', 1, 2, 1, 2, plane, &
                       -1.0_wp, 0.6_wp, 0.8_wp, status), [1], [1, 2], [2], [integer ::], times(trial))
  end do
  call check(status%ok(), 'plane joints built')
  call same_as_surface_joint(1.0_wp, 1.0_wp, 0.0_wp)
  call same_as_surface_joint(-1.0_wp, 0.6_wp, 0.8_wp)
  call kept_products()
  call refuses_curved_surface()
  call finish_tests('test_plane_joint')

contains

  !> The plane joint's maps hold only for r = r(0, 0) + u r_u + v r_v.
  subroutine refuses_curved_surface()
    type(status_t) :: st, built
    type(plane_joint_t) :: joint
    type(ellipsoid_t) :: ball
    ball = ellipsoid_t(1.0_wp, 1.0_wp, 1.0_wp, built)
    call check(built%ok() .and. .not. ball%affine(), 'an ellipsoid is not affine')
    call check(plane%affine(), 'a plane is affine')
    joint = new_plane_joint('pj', 1, 2, 1, 2, ball, 1.0_wp, 1.0_wp, 0.0_wp, st)
    call check(.not. st%ok() .and. index(st%text(), 'not a plane') > 0, 'an ellipsoid refused by the plane joint: '// &
               st%text())
  end subroutine refuses_curved_surface

  subroutine same_as_surface_joint(sigma, alpha_u, alpha_v)
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    type(plane_joint_t) :: fast
    type(surface_joint_t) :: general
    type(frame_state_t) :: a(2), b(2)
    type(scalar_state_t) :: sa(2), sb(2)
    type(status_t) :: st
    real(wp) :: err, size_
    integer :: k
    fast = new_plane_joint('pj', 1, 2, 1, 2, plane, sigma, alpha_u, alpha_v, st)
    general = new_surface_joint('sj', 1, 2, 1, 2, plane, sigma, alpha_u, alpha_v)
    err = 0
    size_ = 1
    do k = 1, 20
      call frame_motion(1, 0.13_wp*k - 1.3_wp, a(1))
      call scalar_motion(1, 0.11_wp*k - 1.1_wp, sa(1))
      call scalar_motion(2, 0.17_wp*k - 1.6_wp, sa(2))
      b = a
      sb = sa
      call fast%position(a, sa, st)
      call general%position(b, sb, st)
      call fast%velocity(a, sa)
      call general%velocity(b, sb)
      call fast%acceleration(a, sa)
      call general%acceleration(b, sb)
      a(2)%force = [0.3_wp, -1.2_wp, 0.7_wp]*k
      a(2)%torque = [-0.5_wp, 0.2_wp, 0.9_wp]
      a(1)%force = 0; a(1)%torque = 0; sa%force = 0
      b(2)%force = a(2)%force; b(2)%torque = a(2)%torque
      b(1)%force = 0; b(1)%torque = 0; sb%force = 0
      call fast%force(a, sa, .true., .true.)
      call general%force(b, sb, .true., .true.)
      err = max(err, maxval(abs(a(2)%rot - b(2)%rot)), maxval(abs(a(2)%r - b(2)%r)), &
                maxval(abs(a(2)%omega - b(2)%omega)), maxval(abs(a(2)%v - b(2)%v)), &
                maxval(abs(a(2)%alpha - b(2)%alpha)), maxval(abs(a(2)%a - b(2)%a)), &
                maxval(abs(a(1)%force - b(1)%force)), maxval(abs(a(1)%torque - b(1)%torque)), &
                maxval(abs(sa%force - sb%force)))
      size_ = max(size_, maxval(abs(a(2)%a)), maxval(abs(a(1)%torque)), maxval(abs(sa%force)))
    end do
    call check(st%ok(), 'plane and surface joint evaluated: '//st%text())
    call check(err <= 1e-13_wp*size_, 'plane joint = surface joint on the plane (frame, rates, forces)')
    print '(a, es10.2)', 'plane joint against the surface joint, largest relative difference: ', err/size_
  end subroutine same_as_surface_joint

  !> The position map keeps the products with R_1 for the next call with the
  !> same R_1 (to the bit): a joint used along a sequence of input rotations
  !> (repeated, changed, back, one zero's sign flipped) gives the bits of a
  !> new joint at every step, in its position, velocity and acceleration maps.
  subroutine kept_products()
    type(plane_joint_t) :: kept, fresh
    type(frame_state_t) :: a(2), b(2)
    type(scalar_state_t) :: sa(2), sb(2)
    type(status_t) :: st
    real(wp) :: rots(3, 3, 3)
    integer :: k, pick(8) = [1, 1, 2, 1, 3, 3, 1, 2]
    logical :: same
    kept = new_plane_joint('pj', 1, 2, 1, 2, plane, 1.0_wp, 1.0_wp, 0.0_wp, st)
    call frame_motion(1, 0.4_wp, a(1))
    rots(:, :, 1) = a(1)%rot
    rots(:, :, 2) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    rots(:, :, 3) = rots(:, :, 2)
    rots(2, 1, 3) = -0.0_wp
    same = .true.
    do k = 1, size(pick)
      call frame_motion(1, 0.1_wp*k, a(1))
      a(1)%rot = rots(:, :, pick(k))
      call scalar_motion(1, 0.3_wp*k, sa(1))
      call scalar_motion(2, -0.2_wp*k, sa(2))
      b = a
      sb = sa
      fresh = new_plane_joint('pj', 1, 2, 1, 2, plane, 1.0_wp, 1.0_wp, 0.0_wp, st)
      call kept%position(a, sa, st)
      call fresh%position(b, sb, st)
      call kept%velocity(a, sa)
      call fresh%velocity(b, sb)
      call kept%acceleration(a, sa)
      call fresh%acceleration(b, sb)
      same = same .and. same_bits([a(2)%rot, a(2)%r, a(2)%omega, a(2)%v, a(2)%alpha, a(2)%a], &
                                  [b(2)%rot, b(2)%r, b(2)%omega, b(2)%v, b(2)%alpha, b(2)%a])
    end do
    call check(st%ok(), 'plane joints evaluated: '//st%text())
    call check(same, 'plane joint keeping its products with R_1 = a new joint, to the bit')
  end subroutine kept_products

  !> The same bit patterns (so -0 differs from +0).
  logical function same_bits(x, y) result(same)
    real(wp), intent(in) :: x(:), y(:)
    same = size(x) == size(y)
    if (same) same = all(transfer(x, 0_int64, size(x)) == transfer(y, 0_int64, size(y)))
  end function same_bits
end program test_plane_joint
