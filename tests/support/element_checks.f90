!> Checks of one transmission element along smooth random motions of its
!> inputs (thesis 3.2): velocity map = d/dt of the position map, acceleration
!> map = d/dt of the velocity map (fourth-order central differences), and the
!> force map conserves power (3.6). Frame k moves with R = Rz Ry Rx of cubic
!> angles and a cubic origin, scalar k along a cubic; all coefficients are
!> deterministic "random" O(1) numbers of the index, so every element sees the
!> same motions of the same inputs.
!>
!> Tolerances: h = 1e-3 with the 4th-order formula: truncation ~ h^4
!> |f^(5)|/30 ~ 1e-13 for the O(1..10) derivatives of these motions, rounding
!> ~ eps/h ~ 1e-13, so 1e-8 relative to the size of the compared vector leaves
!> a wide, argued margin while any wrong term (at least ~1e-2 of the size)
!> fails. Power balance is algebraic: only rounding of O(10) terms, 1e-12.
module element_checks
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross, rot_x, rot_y, rot_z
  use testing, only: check, check_close
  use kinetostatics_state, only: element_t, frame_state_t, scalar_state_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t, LOADS_EXPLICIT
  implicit none (type, external)
  private
  public :: check_element, check_mechanism_motion, frame_motion, scalar_motion, motion_step, fd_tol, &
    power_tol, d4

  real(wp), parameter :: motion_step = 1e-3_wp, fd_tol = 1e-8_wp, power_tol = 1e-12_wp

  !> Sets the motion of inputs the caller controls (e.g. a consistent pose) at
  !> time t, after the random motions were set.
  abstract interface
    subroutine motion_hook_i(t, frames, scalars)
      import :: wp, frame_state_t, scalar_state_t
      real(wp), intent(in) :: t
      type(frame_state_t), intent(inout) :: frames(:)
      type(scalar_state_t), intent(inout) :: scalars(:)
    end subroutine motion_hook_i
  end interface
  public :: motion_hook_i

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

  !> Scalar k's motion, half the size of the frames' coefficients.
  subroutine scalar_motion(k, t, s)
    integer, intent(in) :: k
    real(wp), intent(in) :: t
    type(scalar_state_t), intent(inout) :: s
    call poly(0.5_wp*coefficients(100 + k), t, s%q, s%qd, s%qdd)
  end subroutine scalar_motion

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

  subroutine evaluate(e, t, frames, scalars, in_frames, in_scalars, hook)
    class(element_t), intent(inout) :: e
    real(wp), intent(in) :: t
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer, intent(in) :: in_frames(:), in_scalars(:)
    procedure(motion_hook_i), optional :: hook
    type(status_t) :: st
    integer :: i
    do i = 1, size(in_frames)
      call frame_motion(in_frames(i), t, frames(in_frames(i)))
    end do
    do i = 1, size(in_scalars)
      call scalar_motion(in_scalars(i), t, scalars(in_scalars(i)))
    end do
    if (present(hook)) call hook(t, frames, scalars)
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

  !> Velocity and acceleration maps against differences, and the power of the
  !> force map, at time t0. Frames and scalars are indexed 1..max index used
  !> (scalars up to scalar_count if given); `hook` may overwrite input motions
  !> and set further scalars (e.g. to keep a pose consistent). With rates_only
  !> the output scalars are velocity-level quantities (no position value):
  !> only their second rates are compared with differences of their rates.
  subroutine check_element(label, e, in_frames, in_scalars, out_frames, out_scalars, t0, hook, scalar_count, &
                           rates_only)
    character(len=*), intent(in) :: label
    class(element_t), intent(in) :: e
    integer, intent(in) :: in_frames(:), in_scalars(:), out_frames(:), out_scalars(:)
    real(wp), intent(in) :: t0
    procedure(motion_hook_i), optional :: hook
    integer, intent(in), optional :: scalar_count
    logical, intent(in), optional :: rates_only
    class(element_t), allocatable :: el
    type(frame_state_t), allocatable :: frames(:)
    type(scalar_state_t), allocatable :: scalars(:)
    real(wp), allocatable :: x(:, :), rate(:, :), ref1(:), ref2(:), fd1(:), fd2(:)
    real(wp) :: rdot(3, 3), skewm(3, 3), p_in, p_out, rnd(6)
    integer :: k, i, m, nf, offs
    character(len=8) :: tt

    write (tt, '(f6.2)') t0
    k = maxval([1, in_scalars, out_scalars])
    if (present(scalar_count)) k = max(k, scalar_count)
    allocate (frames(maxval([1, in_frames, out_frames])), scalars(k))
    allocate (el, source=e)
    ! samples at t0 + k h, k = -2..2: positions and velocities
    do k = -2, 2
      call evaluate(el, t0 + k*motion_step, frames, scalars, in_frames, in_scalars, hook)
      if (k == -2) then
        m = size(pack_outputs(frames, scalars, out_frames, out_scalars, 0))
        allocate (x(m, -2:2), rate(size(pack_outputs(frames, scalars, out_frames, out_scalars, 1)), -2:2))
      end if
      x(:, k) = pack_outputs(frames, scalars, out_frames, out_scalars, 0)
      rate(:, k) = pack_outputs(frames, scalars, out_frames, out_scalars, 1)
    end do
    call evaluate(el, t0, frames, scalars, in_frames, in_scalars, hook)
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
    if (present(rates_only)) then
      if (rates_only) fd1(6*nf + 1:) = ref1(6*nf + 1:)
    end if
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
    do i = 1, size(frames)
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
  end subroutine check_element

  !> A whole mechanism with its loops along a smooth random motion of its
  !> coordinates, q = q0 + amplitude (cubic of t): every frame's velocity and
  !> acceleration and every scalar's rate (dependent coordinates and
  !> measurements included) against differences of the closed positions; and
  !> the generalized forces of the explicit force laws (inverse dynamics with
  !> the loops' cut forces, inertia and weights off) against their power,
  !> Q.q' = sum f.v + tau.omega.
  subroutine check_mechanism_motion(label, m, work, q0, amplitude, t0)
    character(len=*), intent(in) :: label
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(in) :: q0(:), amplitude, t0
    real(wp) :: q(size(q0)), qd(size(q0)), qdd(size(q0)), rdot(3, 3), skewm(3, 3), power, c(4)
    real(wp), allocatable :: x(:, :), rate(:, :), ref1(:), ref2(:), fd1(:), fd2(:)
    type(status_t) :: st
    integer :: k, i, nf, ns
    character(len=8) :: tt
    write (tt, '(f6.2)') t0
    nf = m%n_frames
    ns = m%n_scalars
    allocate (x(12*nf + ns, -2:2), rate(6*nf + ns, -2:2), ref1(6*nf + ns), ref2(6*nf + ns), fd1(6*nf + ns))
    do k = -2, 3
      call state_at(t0 + merge(0, k, k == 3)*motion_step)
      call check(st%ok(), label//': closure along the motion: '//st%text())
      if (.not. st%ok()) return
      if (k <= 2) then
        do i = 1, nf
          x(12*(i - 1) + 1:12*i, k) = [reshape(work%frames(i)%rot, [9]), work%frames(i)%r]
          rate(6*(i - 1) + 1:6*i, k) = [work%frames(i)%omega, work%frames(i)%v]
        end do
        x(12*nf + 1:, k) = work%scalars%q
        rate(6*nf + 1:, k) = work%scalars%qd
      end if
    end do
    do i = 1, nf
      ref1(6*(i - 1) + 1:6*i) = [work%frames(i)%omega, work%frames(i)%v]
      ref2(6*(i - 1) + 1:6*i) = [work%frames(i)%alpha, work%frames(i)%a]
      rdot = reshape(d4(x(12*(i - 1) + 1:12*(i - 1) + 9, :)), [3, 3])
      skewm = matmul(rdot, transpose(work%frames(i)%rot))
      fd1(6*(i - 1) + 1:6*(i - 1) + 3) = 0.5_wp*[skewm(3, 2) - skewm(2, 3), skewm(1, 3) - skewm(3, 1), &
                                                 skewm(2, 1) - skewm(1, 2)]
      fd1(6*(i - 1) + 4:6*i) = d4(x(12*(i - 1) + 10:12*i, :))
    end do
    ref1(6*nf + 1:) = work%scalars%qd
    ref2(6*nf + 1:) = work%scalars%qdd
    fd1(6*nf + 1:) = d4(x(12*nf + 1:, :))
    fd2 = d4(rate)
    call check(maxval(abs(fd1 - ref1)) <= fd_tol*max(1.0_wp, maxval(abs(ref1))), &
               label//': velocities = d/dt of the closed positions at t = '//tt)
    call check(maxval(abs(fd2 - ref2)) <= fd_tol*max(1.0_wp, maxval(abs(ref2))), &
               label//': accelerations = d/dt of the velocities at t = '//tt)
    if (maxval(abs(fd1 - ref1)) > fd_tol*max(1.0_wp, maxval(abs(ref1))) .or. &
        maxval(abs(fd2 - ref2)) > fd_tol*max(1.0_wp, maxval(abs(ref2)))) then
      print '(a, 2es10.2, 2i5)', '   max errors (velocity, acceleration) and where: ', maxval(abs(fd1 - ref1)), &
        maxval(abs(fd2 - ref2)), maxloc(abs(fd1 - ref1)), maxloc(abs(fd2 - ref2))
    end if
    ! power of the explicit laws' loads through the closed loops
    call m%evaluate_laws(work, t0, st)
    call check(st%ok(), label//': force laws: '//st%text())
    call m%inverse_dynamics(work, .false., .false., LOADS_EXPLICIT)
    power = 0
    do i = 1, m%n_laws
      if (.not. m%laws(i)%law%scaled) power = power + work%unit_power(i)
    end do
    call check_close(dot_product(work%gq, qd), power, power_tol, power_tol*max(1.0_wp, abs(power)), &
                     label//': virtual power Q.q'' = power of the applied loads at t = '//tt)
  contains
    subroutine state_at(t)
      real(wp), intent(in) :: t
      integer :: j
      do j = 1, size(q0)
        c = amplitude*coefficients(200 + j)
        q(j) = q0(j) + c(2)*t + c(3)*t**2/2 + c(4)*t**3/6
        qd(j) = c(2) + c(3)*t + c(4)*t**2/2
        qdd(j) = c(3) + c(4)*t
      end do
      st = status_t()
      call m%set_positions(work, q, st)
      if (.not. st%ok()) return
      call m%set_velocities(work, qd)
      call m%set_accelerations(work, qdd)
    end subroutine state_at
  end subroutine check_mechanism_motion

  !> Fourth-order central difference of samples at t0 + k h, k = -2..2.
  pure function d4(s) result(d)
    real(wp), intent(in) :: s(:, -2:)
    real(wp) :: d(size(s, 1))
    d = (s(:, -2) - 8*s(:, -1) + 8*s(:, 1) - s(:, 2))/(12*motion_step)
  end function d4
end module element_checks
