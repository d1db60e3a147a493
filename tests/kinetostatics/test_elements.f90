!> Every transmission element along smooth random motions of its inputs:
!> velocity map = d/dt of the position map, acceleration map = d/dt of the
!> velocity map (fourth-order central differences), and the force map conserves
!> power (3.6). The mass element: d'Alembert power = -dT/dt, weight power = -dV/dt.
program test_elements
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross, rot_x, rot_y, rot_z
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: ellipsoid_t, paraboloid_t, elliptic_cylinder_t, apex_paraboloid_t
  use kinetostatics_state, only: element_t, frame_state_t, scalar_state_t
  use kinetostatics_joints, only: new_rigid_offset, new_revolute, new_prismatic, new_spherical
  use kinetostatics_surface_joint, only: new_surface_joint
  use kinetostatics_measurements, only: new_measurement, MEASURE_POINT_POINT, MEASURE_PLANE_POINT, &
    MEASURE_PLANE_PLANE, MEASURE_LINE_LINE
  use kinetostatics_mass, only: mass_element_t, new_mass_element
  implicit none (type, external)

  ! h = 1e-3 with the 4th-order formula: truncation ~ h^4 |f^(5)|/30 ~ 1e-13 for
  ! the O(1..10) derivatives of these motions, rounding ~ eps/h ~ 1e-13, so
  ! 1e-8 relative to the size of the compared vector leaves a wide, argued margin
  ! while any wrong term (at least ~1e-2 of the size) fails.
  real(wp), parameter :: h = 1e-3_wp, fd_tol = 1e-8_wp
  ! Power balance is algebraic: only rounding of O(10) terms.
  real(wp), parameter :: power_tol = 1e-12_wp
  type(status_t) :: status
  class(surface_t), allocatable :: surface
  integer :: trial
  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]

  do trial = 1, size(times)
    ! frames: 1 = input i, 2 = input j / output, 3 = output; scalars 1..3 inputs, 4 output
    call run('rigid offset', new_rigid_offset('offset', 1, 2, [0.3_wp, -0.2_wp, 0.5_wp], &
             matmul(rot_x(0.3_wp), rot_z(-1.1_wp))), [1], [integer ::], [2], [integer ::], times(trial))
    call run('revolute', new_revolute('rev', 1, 2, 1, [1.0_wp, 2.0_wp, -0.5_wp]), [1], [1], [2], &
             [integer ::], times(trial))
    call run('prismatic', new_prismatic('pri', 1, 2, 1, [0.2_wp, -1.0_wp, 0.7_wp]), [1], [1], [2], &
             [integer ::], times(trial))
    call run('spherical', new_spherical('sph', 1, 2, [1, 2, 3]), [1], [1, 2, 3], [2], [integer ::], &
             times(trial))
    call run('point-point', new_measurement('pp', MEASURE_POINT_POINT, 1, 2, 4), [1, 2], [integer ::], &
             [integer ::], [4], times(trial))
    call run('plane-point', new_measurement('ep', MEASURE_PLANE_POINT, 1, 2, 4, axis_i=[0.3_wp, 0.4_wp, 1.0_wp]), &
             [1, 2], [integer ::], [integer ::], [4], times(trial))
    call run('plane-plane', new_measurement('ee', MEASURE_PLANE_PLANE, 1, 2, 4, axis_i=[1.0_wp, 0.4_wp, 0.0_wp], &
             axis_j=[0.0_wp, -0.3_wp, 1.0_wp]), [1, 2], [integer ::], [integer ::], [4], times(trial))
    call run('line-line', new_measurement('gg', MEASURE_LINE_LINE, 1, 2, 4, axis_i=[1.0_wp, 0.4_wp, 0.2_wp], &
             axis_j=[0.1_wp, -0.3_wp, 1.0_wp]), [1, 2], [integer ::], [integer ::], [4], times(trial))

    surface = ellipsoid_t(1.2_wp, 0.8_wp, 0.6_wp, status)
    call run('surface joint on an ellipsoid', new_surface_joint('sj', 1, 2, 1, 2, surface, 1.0_wp, &
             1.0_wp, 0.3_wp), [1], [1, 2], [2], [integer ::], times(trial))
    surface = paraboloid_t(0.7_wp, 1.3_wp, -1.0_wp, status)
    call run('surface joint on a saddle, sigma = -1', new_surface_joint('sj', 1, 2, 1, 2, surface, -1.0_wp, &
             0.4_wp, -1.0_wp), [1], [1, 2], [2], [integer ::], times(trial))
    surface = elliptic_cylinder_t(0.5_wp, 0.9_wp, status)
    call run('surface joint on a cylinder', new_surface_joint('sj', 1, 2, 1, 2, surface, 1.0_wp, &
             0.0_wp, 1.0_wp), [1], [1, 2], [2], [integer ::], times(trial))
    call check(status%ok(), 'surfaces built')
  end do
  call mass_checks()
  call singular_point()
  call finish_tests('test_elements')

contains

  !> Cubic polynomial motion: value, rate and second rate of coefficient set c at t.
  pure subroutine poly(c, t, x, xd, xdd)
    real(wp), intent(in) :: c(4), t
    real(wp), intent(out) :: x, xd, xdd
    x = c(1) + c(2)*t + c(3)*t**2/2 + c(4)*t**3/6
    xd = c(2) + c(3)*t + c(4)*t**2/2
    xdd = c(3) + c(4)*t
  end subroutine poly

  !> Frame k's motion: R = Rz(c) Ry(b) Rx(a) with cubic angles, cubic position.
  subroutine frame_motion(k, t, f)
    integer, intent(in) :: k
    real(wp), intent(in) :: t
    type(frame_state_t), intent(inout) :: f
    real(wp) :: ang(3), angd(3), angdd(3), ez(3), ny(3), nx(3), w2(3)
    integer :: i
    do i = 1, 3
      call poly(coefficients(10*k + i), t, ang(i), angd(i), angdd(i))
      call poly(coefficients(10*k + 3 + i), t, f%r(i), f%v(i), f%a(i))
    end do
    f%rot = matmul(rot_z(ang(3)), matmul(rot_y(ang(2)), rot_x(ang(1))))
    ez = [0.0_wp, 0.0_wp, 1.0_wp]
    ny = matmul(rot_z(ang(3)), [0.0_wp, 1.0_wp, 0.0_wp])
    nx = f%rot(:, 1)
    w2 = angd(3)*ez + angd(2)*ny
    f%omega = w2 + angd(1)*nx
    f%alpha = angdd(3)*ez + angdd(2)*ny + angd(2)*cross(angd(3)*ez, ny) + angdd(1)*nx + angd(1)*cross(w2, nx)
  end subroutine frame_motion

  !> Deterministic "random" coefficients, O(1).
  pure function coefficients(seed) result(c)
    integer, intent(in) :: seed
    real(wp) :: c(4)
    integer :: i
    do i = 1, 4
      c(i) = sin(1.7_wp*seed + 2.3_wp*i + 0.1_wp*seed*i)
    end do
    c(1) = 0.5_wp*c(1)
  end function coefficients

  subroutine set_inputs(t, frames, scalars, in_frames, in_scalars)
    real(wp), intent(in) :: t
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer, intent(in) :: in_frames(:), in_scalars(:)
    integer :: i
    do i = 1, size(in_frames)
      call frame_motion(in_frames(i), t, frames(in_frames(i)))
    end do
    do i = 1, size(in_scalars)
      call poly(0.5_wp*coefficients(100 + in_scalars(i)), t, scalars(in_scalars(i))%q, &
                scalars(in_scalars(i))%qd, scalars(in_scalars(i))%qdd)
    end do
  end subroutine set_inputs

  subroutine evaluate(e, t, frames, scalars, in_frames, in_scalars)
    class(element_t), intent(inout) :: e
    real(wp), intent(in) :: t
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer, intent(in) :: in_frames(:), in_scalars(:)
    type(status_t) :: st
    call set_inputs(t, frames, scalars, in_frames, in_scalars)
    call e%position(frames, scalars, st)
    call check(st%ok(), 'position of '//e%name//': '//st%text())
    call e%velocity(frames, scalars)
    call e%acceleration(frames, scalars)
  end subroutine evaluate

  !> The state of the outputs as one vector [R, r, omega, v, alpha, a | q, qd, qdd].
  pure function pack_outputs(frames, scalars, out_frames, out_scalars, level) result(x)
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    integer, intent(in) :: out_frames(:), out_scalars(:), level
    real(wp), allocatable :: x(:)
    integer :: i
    allocate (x(0))
    do i = 1, size(out_frames)
      associate (f => frames(out_frames(i)))
        select case (level)
        case (0); x = [x, reshape(f%rot, [9]), f%r]
        case (1); x = [x, f%omega, f%v]
        case (2); x = [x, f%alpha, f%a]
        end select
      end associate
    end do
    do i = 1, size(out_scalars)
      associate (s => scalars(out_scalars(i)))
        select case (level)
        case (0); x = [x, s%q]
        case (1); x = [x, s%qd]
        case (2); x = [x, s%qdd]
        end select
      end associate
    end do
  end function pack_outputs

  subroutine run(label, e, in_frames, in_scalars, out_frames, out_scalars, t0)
    character(len=*), intent(in) :: label
    class(element_t), intent(in) :: e
    integer, intent(in) :: in_frames(:), in_scalars(:), out_frames(:), out_scalars(:)
    real(wp), intent(in) :: t0
    class(element_t), allocatable :: el
    type(frame_state_t) :: frames(3)
    type(scalar_state_t) :: scalars(4)
    real(wp), allocatable :: x(:, :), rate(:, :), ref1(:), ref2(:), fd1(:), fd2(:)
    real(wp) :: rdot(3, 3), skewm(3, 3), p_in, p_out, rnd(6)
    integer :: k, i, m, nf, offs
    character(len=8) :: tt

    write (tt, '(f6.2)') t0
    allocate (el, source=e)
    ! samples at t0 + k h, k = -2..2: positions and velocities
    do k = -2, 2
      call evaluate(el, t0 + k*h, frames, scalars, in_frames, in_scalars)
      if (k == -2) then
        m = size(pack_outputs(frames, scalars, out_frames, out_scalars, 0))
        allocate (x(m, -2:2), rate(size(pack_outputs(frames, scalars, out_frames, out_scalars, 1)), -2:2))
      end if
      x(:, k) = pack_outputs(frames, scalars, out_frames, out_scalars, 0)
      rate(:, k) = pack_outputs(frames, scalars, out_frames, out_scalars, 1)
    end do
    call evaluate(el, t0, frames, scalars, in_frames, in_scalars)
    ref1 = pack_outputs(frames, scalars, out_frames, out_scalars, 1)
    ref2 = pack_outputs(frames, scalars, out_frames, out_scalars, 2)
    ! velocity level from differences of the positions
    fd1 = 0*ref1
    nf = size(out_frames)
    do i = 1, nf
      offs = 12*(i - 1)
      rdot = reshape(d4(x(offs + 1:offs + 9, :)), [3, 3])
      skewm = matmul(rdot, transpose(frames(out_frames(i))%rot))
      fd1(6*(i - 1) + 1:6*(i - 1) + 3) = 0.5_wp*[skewm(3, 2) - skewm(2, 3), skewm(1, 3) - skewm(3, 1), &
                                                 skewm(2, 1) - skewm(1, 2)]
      fd1(6*(i - 1) + 4:6*i) = d4(x(offs + 10:offs + 12, :))
    end do
    if (size(out_scalars) > 0) fd1(6*nf + 1:) = d4(x(12*nf + 1:, :))
    fd2 = d4(rate)
    call check(maxval(abs(fd1 - ref1)) <= fd_tol*max(1.0_wp, maxval(abs(ref1))), &
               label//': velocity map = d/dt position map at t = '//tt)
    call check(maxval(abs(fd2 - ref2)) <= fd_tol*max(1.0_wp, maxval(abs(ref2))), &
               label//': acceleration map = d/dt velocity map at t = '//tt)
    if (maxval(abs(fd1 - ref1)) > fd_tol*max(1.0_wp, maxval(abs(ref1))) .or. &
        maxval(abs(fd2 - ref2)) > fd_tol*max(1.0_wp, maxval(abs(ref2)))) then
      print '(a, 2es10.2)', '   max errors (velocity, acceleration): ', maxval(abs(fd1 - ref1)), &
        maxval(abs(fd2 - ref2))
    end if

    ! power: random output loads, inputs cleared
    do i = 1, 3
      frames(i)%torque = 0
      frames(i)%force = 0
    end do
    scalars%force = 0
    p_out = 0
    do i = 1, size(out_frames)
      rnd = [(sin(3.1_wp*k + 7*i), k = 1, 6)]
      frames(out_frames(i))%torque = rnd(1:3)
      frames(out_frames(i))%force = rnd(4:6)
      p_out = p_out + dot_product(rnd(1:3), frames(out_frames(i))%omega) + &
              dot_product(rnd(4:6), frames(out_frames(i))%v)
    end do
    do i = 1, size(out_scalars)
      scalars(out_scalars(i))%force = 0.7_wp + i
      p_out = p_out + scalars(out_scalars(i))%force*scalars(out_scalars(i))%qd
    end do
    call el%force(frames, scalars, .false., .false.)
    p_in = 0
    do i = 1, size(in_frames)
      p_in = p_in + dot_product(frames(in_frames(i))%torque, frames(in_frames(i))%omega) + &
             dot_product(frames(in_frames(i))%force, frames(in_frames(i))%v)
    end do
    do i = 1, size(in_scalars)
      p_in = p_in + scalars(in_scalars(i))%force*scalars(in_scalars(i))%qd
    end do
    call check_close(p_in, p_out, power_tol, power_tol, label//': virtual power Q_in.q_in'' = Q_out.q_out'' at t = '//tt)
  end subroutine run

  !> Fourth-order central difference of samples at t0 + k h, k = -2..2.
  pure function d4(s) result(d)
    real(wp), intent(in) :: s(:, -2:)
    real(wp) :: d(size(s, 1))
    d = (s(:, -2) - 8*s(:, -1) + 8*s(:, 1) - s(:, 2))/(12*h)
  end function d4

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
end program test_elements
