!> Every transmission element along smooth random motions of its inputs:
!> velocity map = d/dt of the position map, acceleration map = d/dt of the
!> velocity map (fourth-order central differences), and the force map conserves
!> power (3.6). The mass element: d'Alembert power = -dT/dt, weight power = -dV/dt.
!> The surface joint's chart change (a contact's S1 followed by its turn phi)
!> keeps the turned frame's pose and motion to rounding near an ellipsoid's
!> poles, and its maps in the new chart pass the same checks.
program test_elements
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: rot_x, rot_z
  use testing, only: check, check_close, finish_tests
  use element_checks, only: check_element, frame_motion, scalar_motion, motion_step, fd_tol
  use geometry_surface, only: surface_t
  use geometry_elementary, only: ellipsoid_t, paraboloid_t, elliptic_cylinder_t, apex_paraboloid_t
  use kinetostatics_state, only: element_t, frame_state_t, scalar_state_t
  use kinetostatics_joints, only: new_rigid_offset, new_revolute, new_prismatic, new_spherical, revolute_t
  use kinetostatics_surface_joint, only: new_surface_joint, surface_joint_t
  use kinetostatics_measurements, only: new_measurement, MEASURE_POINT_POINT, MEASURE_PLANE_POINT, &
    MEASURE_PLANE_PLANE, MEASURE_LINE_LINE, new_point_coordinates, measurement_t, point_coordinates_t
  use kinetostatics_mass, only: mass_element_t, new_mass_element
  implicit none (type, external)

  ! Differences and power: element_checks (h = 1e-3, 4th order, 1e-8 relative;
  ! power to 1e-12).
  real(wp), parameter :: h = motion_step
  type(status_t) :: status
  class(surface_t), allocatable :: surface
  integer :: trial
  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]

  do trial = 1, size(times)
    ! frames: 1 = input i, 2 = input j / output, 3 = output; scalars 1..3 inputs, 4 output
    call check_element('rigid offset', new_rigid_offset('offset', 1, 2, [0.3_wp, -0.2_wp, 0.5_wp], &
             matmul(rot_x(0.3_wp), rot_z(-1.1_wp))), [1], [integer ::], [2], [integer ::], times(trial))
    call check_element('revolute', new_revolute('rev', 1, 2, 1, [1.0_wp, 2.0_wp, -0.5_wp]), [1], [1], [2], &
             [integer ::], times(trial))
    call check_element('prismatic', new_prismatic('pri', 1, 2, 1, [0.2_wp, -1.0_wp, 0.7_wp]), [1], [1], [2], &
             [integer ::], times(trial))
    call check_element('spherical', new_spherical('sph', 1, 2, [1, 2, 3]), [1], [1, 2, 3], [2], [integer ::], &
             times(trial))
    call check_element('point-point', new_measurement('pp', MEASURE_POINT_POINT, 1, 2, 4), [1, 2], [integer ::], &
             [integer ::], [4], times(trial))
    call check_element('plane-point', new_measurement('ep', MEASURE_PLANE_POINT, 1, 2, 4, axis_i=[0.3_wp, 0.4_wp, 1.0_wp]), &
             [1, 2], [integer ::], [integer ::], [4], times(trial))
    call check_element('point coordinates', new_point_coordinates('pc', 1, 2, [4, 5, 6]), [1, 2], [integer ::], &
             [integer ::], [4, 5, 6], times(trial))
    call check_element('plane-plane', new_measurement('ee', MEASURE_PLANE_PLANE, 1, 2, 4, axis_i=[1.0_wp, 0.4_wp, 0.0_wp], &
             axis_j=[0.0_wp, -0.3_wp, 1.0_wp]), [1, 2], [integer ::], [integer ::], [4], times(trial))
    call check_element('line-line', new_measurement('gg', MEASURE_LINE_LINE, 1, 2, 4, axis_i=[1.0_wp, 0.4_wp, 0.2_wp], &
             axis_j=[0.1_wp, -0.3_wp, 1.0_wp]), [1, 2], [integer ::], [integer ::], [4], times(trial))

    surface = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, status)
    call check_element('surface joint on an ellipsoid', new_surface_joint('sj', 1, 2, 1, 2, surface, 1.0_wp, &
             1.0_wp, 0.3_wp), [1], [1, 2], [2], [integer ::], times(trial))
    surface = paraboloid_t(0.7_wp, 1.3_wp, -1.0_wp, status)
    call check_element('surface joint on a saddle, sigma = -1', new_surface_joint('sj', 1, 2, 1, 2, surface, -1.0_wp, &
             0.4_wp, -1.0_wp), [1], [1, 2], [2], [integer ::], times(trial))
    surface = elliptic_cylinder_t(0.5_wp, 0.9_wp, status)
    call check_element('surface joint on a cylinder', new_surface_joint('sj', 1, 2, 1, 2, surface, 1.0_wp, &
             0.0_wp, 1.0_wp), [1], [1, 2], [2], [integer ::], times(trial))
    call check(status%ok(), 'surfaces built')
  end do
  call mass_checks()
  call singular_point()
  call lazy_equals_eager()
  call chart_change()
  call point_coordinates_equal_plane_points(.true.)
  call point_coordinates_equal_plane_points(.false.)
  call finish_tests('test_elements')

contains

  subroutine mass_checks()
    type(mass_element_t) :: m
    type(frame_state_t) :: frames(1)
    type(scalar_state_t) :: scalars(1)
    type(status_t) :: st
    real(wp) :: kin(-2:2), pot(-2:2), inertia(3, 3), p_inertia, p_weight, dt, dv
    integer :: k
    inertia = reshape([0.3_wp, 0.02_wp, -0.01_wp, 0.02_wp, 0.5_wp, 0.03_wp, -0.01_wp, 0.03_wp, 0.6_wp], [3, 3])
    m = new_mass_element('body', 1, 2.5_wp, inertia, [0.2_wp, -0.1_wp, 0.4_wp], [0.0_wp, 0.0_wp, -9.81_wp], st)
    call check(st%ok(), 'mass element accepted: '//st%text())
    do k = -2, 2
      call frame_motion(1, 0.3_wp + k*h, frames(1))
      call m%position(frames, scalars, st)
      call m%energy(frames, kin(k), pot(k))
    end do
    call frame_motion(1, 0.3_wp, frames(1))
    call m%position(frames, scalars, st)
    frames(1)%torque = 0; frames(1)%force = 0
    call m%force(frames, scalars, .true., .false.)
    p_inertia = dot_product(frames(1)%torque, frames(1)%omega) + dot_product(frames(1)%force, frames(1)%v)
    frames(1)%torque = 0; frames(1)%force = 0
    call m%force(frames, scalars, .false., .true.)
    p_weight = dot_product(frames(1)%torque, frames(1)%omega) + dot_product(frames(1)%force, frames(1)%v)
    dt = (kin(-2) - 8*kin(-1) + 8*kin(1) - kin(2))/(12*h)
    dv = (pot(-2) - 8*pot(-1) + 8*pot(1) - pot(2))/(12*h)
    call check_close(p_inertia, -dt, fd_tol, fd_tol*abs(dt), 'mass element: d''Alembert power = -dT/dt')
    call check_close(p_weight, -dv, fd_tol, fd_tol*abs(dv), 'mass element: weight power = -dV/dt')
    ! bad input: no mass, impossible inertia
    m = new_mass_element('ghost', 1, 0.0_wp, inertia, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], st)
    call check(.not. st%ok() .and. index(st%text(), 'ghost') > 0, 'a zero mass is refused, naming the element')
    st = status_t()
    inertia = 0
    inertia(1, 1) = 1
    m = new_mass_element('rod', 1, 1.0_wp, inertia, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], st)
    call check(.not. st%ok() .and. index(st%text(), 'rod') > 0, 'inertia violating I1 <= I2 + I3 is refused')
  end subroutine mass_checks
  !> At the apex of the apex paraboloid (r_u = 0, rule (3.40)) the joint's
  !> velocity and acceleration maps join those of the regular neighbourhood:
  !> compared with v = 1e-7 (regular), they differ by O(1e-7) plus the O(h^2)
  !> = 1e-8 of the one-sided differences used there, so 1e-5 relative is safe
  !> while a wrong rate or sign would be O(1).
  subroutine singular_point()
    class(surface_t), allocatable :: apex
    class(element_t), allocatable :: joint
    type(frame_state_t) :: frames(2)
    type(scalar_state_t) :: scalars(2)
    type(status_t) :: st
    real(wp) :: out(3, 4, 2), v(2)
    integer :: k
    apex = apex_paraboloid_t(0.8_wp, 1.2_wp, st)
    allocate (joint, source=new_surface_joint('apex', 1, 2, 1, 2, apex, 1.0_wp, 1.0_wp, 1.0_wp))
    v = [0.0_wp, 1e-7_wp]
    do k = 1, 2
      scalars(1) = scalar_state_t(0.7_wp, 0.3_wp, 0.1_wp, 0.0_wp)
      scalars(2) = scalar_state_t(v(k), 0.5_wp, -0.2_wp, 0.0_wp)
      call joint%position(frames, scalars, st)
      call check(st%ok(), 'surface joint at and near the apex: '//st%text())
      call joint%velocity(frames, scalars)
      call joint%acceleration(frames, scalars)
      out(:, 1, k) = frames(2)%omega
      out(:, 2, k) = frames(2)%v
      out(:, 3, k) = frames(2)%alpha
      out(:, 4, k) = frames(2)%a
    end do
    call check(maxval(abs(out(:, :, 1) - out(:, :, 2))) <= 1e-5_wp*maxval(abs(out(:, :, 2))), &
               'surface joint at a singular point: velocity and acceleration maps continuous')
  end subroutine singular_point
  !> The lazy surface joint (geometry completed by the first velocity,
  !> acceleration or force map after a position) gives the eager one's
  !> numbers to the last bit, also after several positions in a row (the
  !> closure's Newton iterates) and for a force pass without a velocity pass.
  subroutine lazy_equals_eager()
    class(surface_t), allocatable :: ellipsoid
    type(surface_joint_t) :: lazy, eager
    type(frame_state_t) :: fl(2), fe(2)
    type(scalar_state_t) :: sl(2), se(2)
    type(status_t) :: st
    logical :: same
    integer :: k
    ellipsoid = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, st)
    lazy = new_surface_joint('sj', 1, 2, 1, 2, ellipsoid, 1.0_wp, 1.0_wp, 0.3_wp)
    eager = lazy
    eager%lazy = .false.
    fl(1)%rot = matmul(rot_x(0.3_wp), rot_z(-1.1_wp))
    fl(1)%r = [0.1_wp, 0.2_wp, -0.3_wp]
    fl(1)%omega = [0.5_wp, -0.2_wp, 0.9_wp]
    fl(1)%v = [1.0_wp, 0.0_wp, -0.4_wp]
    fl(1)%alpha = [0.3_wp, 0.1_wp, -0.6_wp]
    fl(1)%a = [-0.2_wp, 0.8_wp, 0.1_wp]
    fl(2)%force = [0.4_wp, -1.0_wp, 0.3_wp]
    fl(2)%torque = [0.2_wp, 0.1_wp, -0.5_wp]
    fe = fl
    same = .true.
    do k = 1, 3
      sl(1) = scalar_state_t(0.7_wp + 0.1_wp*k, 0.3_wp, 0.1_wp, 0.0_wp)
      sl(2) = scalar_state_t(-0.4_wp, 0.5_wp, -0.2_wp, 0.0_wp)
      se = sl
      call lazy%position(fl, sl, st)
      call eager%position(fe, se, st)
      same = same .and. all(fl(2)%rot == fe(2)%rot) .and. all(fl(2)%r == fe(2)%r)
    end do
    call lazy%force(fl, sl, .true., .true.)
    call eager%force(fe, se, .true., .true.)
    same = same .and. all(fl(1)%force == fe(1)%force) .and. all(fl(1)%torque == fe(1)%torque) &
           .and. sl(1)%force == se(1)%force .and. sl(2)%force == se(2)%force
    call lazy%position(fl, sl, st)
    call eager%position(fe, se, st)
    call lazy%velocity(fl, sl)
    call eager%velocity(fe, se)
    call lazy%acceleration(fl, sl)
    call eager%acceleration(fe, se)
    same = same .and. all(fl(2)%omega == fe(2)%omega) .and. all(fl(2)%v == fe(2)%v) &
           .and. all(fl(2)%alpha == fe(2)%alpha) .and. all(fl(2)%a == fe(2)%a)
    call check(st%ok() .and. same, 'surface joint: lazy geometry = eager geometry to the last bit')
    ! position_complete (the closure's last iterate): the whole geometry at
    ! once, the same bits, and the joint stays lazy for the next positions
    sl(1)%q = 0.95_wp
    se(1)%q = 0.95_wp
    call lazy%position_complete(fl, sl, st)
    same = lazy%complete .and. lazy%lazy
    call eager%position(fe, se, st)
    call lazy%velocity(fl, sl)
    call eager%velocity(fe, se)
    call lazy%acceleration(fl, sl)
    call eager%acceleration(fe, se)
    same = same .and. all(fl(2)%rot == fe(2)%rot) .and. all(fl(2)%r == fe(2)%r) &
           .and. all(fl(2)%omega == fe(2)%omega) .and. all(fl(2)%v == fe(2)%v) &
           .and. all(fl(2)%alpha == fe(2)%alpha) .and. all(fl(2)%a == fe(2)%a)
    call lazy%position(fl, sl, st)
    same = same .and. .not. lazy%complete
    call check(st%ok() .and. same, 'surface joint: position_complete = eager position, the joint stays lazy')
  end subroutine lazy_equals_eager

  !> The chain K_1 -> S1(u, v) -> K_1D -> turn phi about z -> K_T near the
  !> poles of an ellipsoid with three different semi-axes, at scattered
  !> motions: the chart change (kinetostatics_surface_joint, "Charts") keeps
  !> K_T's rotation, origin, angular and linear velocity (1e-13: rounding of
  !> O(1) rotations, with the 2x2 solve of (u', v') near the pole) and moves
  !> (u, v) off the new chart's poles (within 45 degrees of its equator).
  subroutine chart_change()
    type(surface_joint_t) :: joint
    type(revolute_t) :: turn
    type(frame_state_t) :: frames(3), before
    type(scalar_state_t) :: scalars(3)
    type(status_t) :: st
    real(wp) :: err_pose, err_motion, v_after
    integer :: k, changes
    surface = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, st)
    turn = new_revolute('turn', 2, 3, 3, [0.0_wp, 0.0_wp, 1.0_wp])
    err_pose = 0
    err_motion = 0
    v_after = 0
    changes = 0
    do k = 1, 12
      joint = new_surface_joint('sj', 1, 2, 1, 2, surface, merge(1.0_wp, -1.0_wp, k <= 6), 1.0_wp, 0.0_wp, &
                                charts=.true., turn=3)
      call frame_motion(1, 0.21_wp*k - 1.3_wp, frames(1))
      call scalar_motion(1, 0.11_wp*k - 1.1_wp, scalars(1))
      call scalar_motion(2, 0.17_wp*k - 1.6_wp, scalars(2))
      call scalar_motion(3, 0.07_wp*k + 0.4_wp, scalars(3))
      scalars(2)%q = merge(1.0_wp, -1.0_wp, mod(k, 2) == 0)*(1.42_wp + 0.01_wp*k)   ! near a pole
      call check(joint%chart_margin(scalars(2)%q) < 0, 'the point lies beyond the chart''s margin')
      call joint%position(frames, scalars, st)
      call turn%position(frames, scalars, st)
      call joint%velocity(frames, scalars)
      call turn%velocity(frames, scalars)
      before = frames(3)
      call joint%rebase(scalars)
      changes = changes + joint%rebases
      v_after = max(v_after, abs(scalars(2)%q))
      call joint%position(frames, scalars, st)
      call turn%position(frames, scalars, st)
      call joint%velocity(frames, scalars)
      call turn%velocity(frames, scalars)
      err_pose = max(err_pose, maxval(abs(frames(3)%rot - before%rot)), maxval(abs(frames(3)%r - before%r)))
      err_motion = max(err_motion, maxval(abs(frames(3)%omega - before%omega))/max(1.0_wp, norm2(before%omega)), &
                       maxval(abs(frames(3)%v - before%v))/max(1.0_wp, norm2(before%v)))
      if (k == 5 .or. k == 8) call check_element('surface joint in the chart with poles on another axis', joint, &
                                                 [1], [1, 2], [2], [integer ::], 0.3_wp)
    end do
    call check(st%ok(), 'chart changes evaluated: '//st%text())
    call check(changes == 12, 'every chart change is made')
    call check(v_after < 0.25_wp*4*atan(1.0_wp) + 1e-12_wp, 'after a change the point is within 45 degrees '// &
               'of the new chart''s equator')
    call check(err_pose < 1e-13_wp, 'a chart change keeps the turned frame''s rotation and origin')
    call check(err_motion < 1e-13_wp, 'a chart change keeps the turned frame''s angular and linear velocity')
    print '(a, 3es10.2)', 'chart changes (pose, motion errors, largest |v| after): ', err_pose, err_motion, v_after
  end subroutine chart_change

  !> The point's coordinates in a frame give the numbers of three plane-point
  !> measurements along the frame's axes to the last bit (the closures of the
  !> rider and their results did not change when they became one element),
  !> with frame i turning and at rest (the closure Jacobian's columns).
  subroutine point_coordinates_equal_plane_points(turning)
    logical, intent(in) :: turning
    type(point_coordinates_t) :: pc
    type(measurement_t) :: planes(3)
    type(frame_state_t) :: f1(2), f3(2)
    type(scalar_state_t) :: s1(5), s3(5)
    type(status_t) :: st
    real(wp), parameter :: axes(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    logical :: same
    integer :: k
    character(len=*), parameter :: case_names(2) = [character(len=8) :: 'turning', 'at rest']
    pc = new_point_coordinates('pc', 1, 2, [3, 4, 5])
    do k = 1, 3
      planes(k) = new_measurement('ep', MEASURE_PLANE_POINT, 1, 2, 2 + k, axis_i=axes(:, k))
    end do
    f1(1)%rot = matmul(rot_x(0.3_wp), rot_z(-1.1_wp))
    f1(1)%r = [0.1_wp, 0.2_wp, -0.3_wp]
    f1(1)%omega = 0
    if (turning) f1(1)%omega = [0.5_wp, -0.2_wp, 0.9_wp]
    f1(1)%v = [1.0_wp, 0.0_wp, -0.4_wp]
    f1(1)%alpha = [0.3_wp, 0.1_wp, -0.6_wp]
    f1(1)%a = [-0.2_wp, 0.8_wp, 0.1_wp]
    f1(1)%force = [0.4_wp, -1.0_wp, 0.3_wp]
    f1(1)%torque = [0.2_wp, 0.1_wp, -0.5_wp]
    f1(2)%rot = rot_z(0.4_wp)
    f1(2)%r = [0.7_wp, -0.3_wp, 0.2_wp]
    f1(2)%omega = [0.1_wp, 0.3_wp, -0.2_wp]
    f1(2)%v = [-0.3_wp, 0.6_wp, 0.2_wp]
    f1(2)%alpha = [0.2_wp, -0.4_wp, 0.5_wp]
    f1(2)%a = [0.9_wp, 0.1_wp, -0.7_wp]
    f1(2)%force = [0.1_wp, 0.2_wp, 0.3_wp]
    f1(2)%torque = [-0.3_wp, 0.2_wp, 0.1_wp]
    f3 = f1
    s1%force = [0.0_wp, 0.0_wp, 1.3_wp, 0.0_wp, -0.6_wp]   ! one cut force zero: its axis adds nothing
    s3 = s1
    call pc%position(f1, s1, st)
    call pc%velocity(f1, s1)
    call pc%acceleration(f1, s1)
    call pc%force(f1, s1, .false., .false.)
    do k = 1, 3
      call planes(k)%position(f3, s3, st)
      call planes(k)%velocity(f3, s3)
      call planes(k)%acceleration(f3, s3)
    end do
    do k = 3, 1, -1   ! a backward pass
      call planes(k)%force(f3, s3, .false., .false.)
    end do
    same = all(s1%q == s3%q) .and. all(s1%qd == s3%qd) .and. all(s1%qdd == s3%qdd)
    do k = 1, 2
      same = same .and. all(f1(k)%force == f3(k)%force) .and. all(f1(k)%torque == f3(k)%torque)
    end do
    call check(st%ok() .and. same, 'point coordinates = three plane-point measurements to the last bit, frame '// &
               trim(case_names(merge(1, 2, turning))))
  end subroutine point_coordinates_equal_plane_points
end program test_elements
