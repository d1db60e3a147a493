!> Contact between two surfaces at velocity level (Montana 1988; thesis 3.5.3,
!> appendix E with the corrections of METHOD-PART2.md A.2): the option that
!> drifts, kept for the comparison of thesis fig. 3.20/3.21 and table 3.1/3.2.
!>
!> Inputs: the contact frame K_1D (the Darboux frame of S1 on body 1, the
!> output of an ordinary surface joint with (u1, v1)), body 1's frame K_1 (for
!> the pose only), the contact coordinates (u2, v2, phi) and the pose of body 2
!> relative to K_1 in six scalars: the origin x, y, z (K_1 axes) and three
!> angles of a free-rotation chart (kinetostatics_free_rotation, first axis
!> z_1). Output: body frame K_2. Split this way, the element and the surface
!> joint before it are (3.84) exactly, and the force the element passes back
!> to K_1D is what body 2 presses on the contact: its normal force is
!> N = -z_1D . f_1D, as for any surface joint (kinetostatics_contact).
!>
!> Position: K_2 from the pose scalars, which the model integrates from their
!> rates; nothing ties them to the contact coordinates, so the closure
!> functions g1..g5 (3.86) between S1(u1, v1) and S2(u2, v2) drift.
!> Velocity (3.84), E.1-E.3 with the minus signs of E.3 corrected, written
!> with the contact frame's twist (omega_1D = omega_1 + 1omega_1D,
!> v_1D = W_1 + omega_1 x 1r_1D + 1W_1D from the surface joint):
!>     omega_2 = omega_1D - 2omega_2D + phi' z_1D
!>     W_2 = v_1D - 2W_2D - omega_2 x 2r_2D
!> with 2omega_2D = R_2 (W_u u2' + W_v v2'), 2W_2D = R_2 (r_u u2' + r_v v2')
!> of S2 relative to body 2; and the pose rates that integrate K_2:
!> [x y z]' = R_1^T (W_2 - W_1 - omega_1 x R_1 [x y z]), angle rates from
!> omega_2 - omega_1 = n_1 a1' + n_2 a2' + n_3 a3'.
!> Acceleration (E.4-E.8), by differentiating the same in world coordinates:
!>     alpha_2 = alpha_1D - A_2 + phi'' z_1D + phi' omega_1D x z_1D
!>     a_2 = a_1D - B_2 - 2 omega_2 x 2W_2D - alpha_2 x 2r_2D - omega_2 x (omega_2 x 2r_2D)
!> where A_2 = R_2 (W_u u2'' + W_v v2'' + W_u' u2' + W_v' v2') + omega_2 x 2omega_2D
!> and B_2 = R_2 (r_u u2'' + r_v v2'' + r_uu u2'^2 + 2 r_uv u2' v2' + r_vv v2'^2).
!> Force (E.9): the transposed map; with tau' = tau_2 - 2r_2D x f_2 (the
!> wrench about the contact point),
!>     f_1D += f_2, tau_1D += tau',
!>     Q_u2 -= tau'.R_2 W_u + f_2.R_2 r_u (v2 likewise), Q_phi += tau'.z_1D.
!>
!> Rolling (E.10-E.16): with `rolling`, u2 and v2 are integrated like the pose
!> (kinematic coordinates) and their rates follow from u1', v1' (inputs then)
!> by the no-slip condition (3.85)
!> projected on the tangent axes x, y of K_1D:
!>     A [u2', v2'] = B [u1', v1'],  A = [r2_u.x r2_v.x; r2_u.y r2_v.y],
!>     B = [r1_u.x r1_v.x; r1_u.y r1_v.y]  (all rotated to world, (3.85) corrected);
!> accelerations (E.12) A q2'' = B q1'' + B' q1' - A' q2' with A', B' differentiated
!> completely: r1_u' = omega_1 x r1_u + R_1 (r_uu u1' + r_uv v1'), the same on
!> body 2 with omega_2, and the axes x' = (omega_1 + 1omega_1D) x x. E.13-E.15
!> as printed miss the turning axes and take omega absolute: the first omission
!> is harmless (the axes' terms are x'.(1W_1D - 2W_2D) = 0 while rolling, as the
!> test confirms), the second is not (omega_2 must turn r2_u; the test fails
!> with omega_1 there).
!> Force (E.16): [Q_u1, Q_v1] += (A^-1 B)^T [Q_u2, Q_v2], added to the direct ones.
module contact_velocity_level
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use base_vector, only: cross
  use geometry_surface, only: surface_t
  use kinetostatics_state, only: element_t, frame_state_t, scalar_state_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint
  use kinetostatics_free_rotation, only: free_rotation_t, new_free_rotation
  implicit none (type, external)
  private
  public :: velocity_contact_t, new_velocity_contact

  type, extends(element_t) :: velocity_contact_t
    integer :: frame_1 = 0, frame_1d = 0, frame_2 = 0
    integer :: u1 = 0, v1 = 0, u2 = 0, v2 = 0, phi = 0
    integer :: pose(6) = 0                  ! x, y, z (m, K_1 axes), three chart angles (rad)
    logical :: rolling = .false.
    ! the two surfaces and the pose chart, evaluated on local frames (local indices 1 -> 2)
    type(surface_joint_t) :: joint_1, joint_2
    type(free_rotation_t) :: chart
    ! at the last position (world)
    real(wp) :: axes_1d(3, 3) = 0           ! x_1D, y_1D, z_1D
    real(wp) :: offset(3) = 0               ! R_1 [x y z]
    real(wp) :: a_mat(2, 2) = 0, b_mat(2, 2) = 0, ainv_b(2, 2) = 0
  contains
    procedure :: position => vc_position
    procedure :: velocity => vc_velocity
    procedure :: acceleration => vc_acceleration
    procedure :: force => vc_force
    procedure :: chart_angle => vc_chart_angle
    procedure :: chart_margin => vc_chart_margin
    procedure :: rebase => vc_rebase
  end type velocity_contact_t

contains

  !> The element from the contact frame frame_1d (a surface joint on S1 of
  !> body frame frame_1 with the coordinates contact(1:2)) to body frame
  !> frame_2; contact = (u1, v1, u2, v2, phi); `start` is the relative rotation
  !> R_1^T R_2 the pose chart is centred on (angles zero).
  function new_velocity_contact(name, frame_1, frame_1d, frame_2, surface_1, side_1, surface_2, side_2, contact, &
                                pose, start, rolling) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_1, frame_1d, frame_2, contact(5), pose(6)
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: side_1, side_2, start(3, 3)
    logical, intent(in) :: rolling
    type(velocity_contact_t) :: e
    e%name = name
    e%frame_1 = frame_1
    e%frame_1d = frame_1d
    e%frame_2 = frame_2
    e%u1 = contact(1); e%v1 = contact(2); e%u2 = contact(3); e%v2 = contact(4); e%phi = contact(5)
    e%pose = pose
    e%rolling = rolling
    e%joint_1 = new_surface_joint(name//'.s1', 1, 2, 1, 2, surface_1, side_1, 1.0_wp, 0.0_wp)
    e%joint_2 = new_surface_joint(name//'.s2', 1, 2, 1, 2, surface_2, side_2, 1.0_wp, 0.0_wp)
    ! this element reads the joints' rates directly after their position maps
    e%joint_1%lazy = .false.
    e%joint_2%lazy = .false.
    e%chart = new_free_rotation(name//'.pose', 1, 2, [1, 2, 3], [0.0_wp, 0.0_wp, 1.0_wp], start)
  end function new_velocity_contact

  pure subroutine vc_position(self, frames, scalars, status)
    class(velocity_contact_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    type(frame_state_t) :: local(2)
    type(scalar_state_t) :: uv(2), angles(3)
    integer :: k
    real(wp) :: det
    associate (k1 => frames(self%frame_1), k2 => frames(self%frame_2))
      ! body 2 from its integrated pose
      local(1)%rot = k1%rot
      do k = 1, 3
        angles(k)%q = scalars(self%pose(3 + k))%q
      end do
      call self%chart%position(local, angles, status)
      self%offset = matmul(k1%rot, [(scalars(self%pose(k))%q, k = 1, 3)])
      k2%rot = local(2)%rot
      k2%r = k1%r + self%offset
      ! surface 2 (its joint's geometry in world coordinates); surface 1 for rolling
      self%axes_1d = frames(self%frame_1d)%rot
      if (self%rolling) then
        local(1)%rot = k1%rot
        local(1)%r = k1%r
        uv(1)%q = scalars(self%u1)%q
        uv(2)%q = scalars(self%v1)%q
        call self%joint_1%position(local, uv, status)
        if (.not. status%ok()) return
      end if
      local(1)%rot = k2%rot
      local(1)%r = k2%r
      uv(1)%q = scalars(self%u2)%q
      uv(2)%q = scalars(self%v2)%q
      call self%joint_2%position(local, uv, status)
      if (.not. status%ok()) return
    end associate
    if (self%rolling) then
      associate (x => self%axes_1d(:, 1), y => self%axes_1d(:, 2), j1 => self%joint_1, j2 => self%joint_2)
        self%a_mat = reshape([dot_product(j2%tu, x), dot_product(j2%tu, y), &
                              dot_product(j2%tv, x), dot_product(j2%tv, y)], [2, 2])
        self%b_mat = reshape([dot_product(j1%tu, x), dot_product(j1%tu, y), &
                              dot_product(j1%tv, x), dot_product(j1%tv, y)], [2, 2])
      end associate
      det = self%a_mat(1, 1)*self%a_mat(2, 2) - self%a_mat(1, 2)*self%a_mat(2, 1)
      if (.not. (abs(det) > 0)) then
        call set_status(status, STATUS_DOMAIN, 'rolling contact '''//self%name//''': surface 2 has no '// &
                        'tangent plane at the contact (A of (E.11) singular)')
        return
      end if
      self%ainv_b = matmul(inverse2(self%a_mat), self%b_mat)
    end if
  end subroutine vc_position

  pure subroutine vc_velocity(self, frames, scalars)
    class(velocity_contact_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: q1d(2), q2d(2), omega_rel2(3), w_rel2(3), rates(3)
    integer :: k
    if (self%rolling) then
      q1d = [scalars(self%u1)%qd, scalars(self%v1)%qd]
      q2d = matmul(self%ainv_b, q1d)
      scalars(self%u2)%qd = q2d(1)
      scalars(self%v2)%qd = q2d(2)
    else
      q2d = [scalars(self%u2)%qd, scalars(self%v2)%qd]
    end if
    associate (k1 => frames(self%frame_1), c => frames(self%frame_1d), k2 => frames(self%frame_2), &
               j2 => self%joint_2)
      omega_rel2 = j2%gu*q2d(1) + j2%gv*q2d(2)
      w_rel2 = j2%tu*q2d(1) + j2%tv*q2d(2)
      k2%omega = c%omega - omega_rel2 + scalars(self%phi)%qd*self%axes_1d(:, 3)   ! (3.84), E.2
      k2%v = c%v - w_rel2 - cross(k2%omega, j2%p)                                ! (3.84), E.3
      ! rates of the integrated pose
      rates = matmul(transpose(k1%rot), k2%v - k1%v - cross(k1%omega, self%offset))
      do k = 1, 3
        scalars(self%pose(k))%qd = rates(k)
      end do
      rates = solve3(self%chart%n, k2%omega - k1%omega)
      do k = 1, 3
        scalars(self%pose(3 + k))%qd = rates(k)
      end do
    end associate
  end subroutine vc_velocity

  pure subroutine vc_acceleration(self, frames, scalars)
    class(velocity_contact_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: q1d(2), q2d(2), q1dd(2), q2dd(2), omega_rel2(3), w_rel2(3), &
      dx(3), dy(3), dt1u(3), dt1v(3), dt2u(3), dt2v(3), da(2, 2), db(2, 2), phid, omega_2(3)
    phid = scalars(self%phi)%qd
    associate (k1 => frames(self%frame_1), c => frames(self%frame_1d), k2 => frames(self%frame_2), &
               j1 => self%joint_1, j2 => self%joint_2, &
               x => self%axes_1d(:, 1), y => self%axes_1d(:, 2), z => self%axes_1d(:, 3))
      if (self%rolling) then
        q1d = [scalars(self%u1)%qd, scalars(self%v1)%qd]
        q1dd = [scalars(self%u1)%qdd, scalars(self%v1)%qdd]
        q2d = matmul(self%ainv_b, q1d)
        omega_rel2 = j2%gu*q2d(1) + j2%gv*q2d(2)
        omega_2 = c%omega - omega_rel2 + phid*z
        dx = cross(c%omega, x)
        dy = cross(c%omega, y)
        dt1u = cross(k1%omega, j1%tu) + j1%huu*q1d(1) + j1%huv*q1d(2)
        dt1v = cross(k1%omega, j1%tv) + j1%huv*q1d(1) + j1%hvv*q1d(2)
        dt2u = cross(omega_2, j2%tu) + j2%huu*q2d(1) + j2%huv*q2d(2)
        dt2v = cross(omega_2, j2%tv) + j2%huv*q2d(1) + j2%hvv*q2d(2)
        da = reshape([dot_product(dt2u, x) + dot_product(j2%tu, dx), dot_product(dt2u, y) + dot_product(j2%tu, dy), &
                      dot_product(dt2v, x) + dot_product(j2%tv, dx), dot_product(dt2v, y) + dot_product(j2%tv, dy)], &
                     [2, 2])
        db = reshape([dot_product(dt1u, x) + dot_product(j1%tu, dx), dot_product(dt1u, y) + dot_product(j1%tu, dy), &
                      dot_product(dt1v, x) + dot_product(j1%tv, dx), dot_product(dt1v, y) + dot_product(j1%tv, dy)], &
                     [2, 2])
        q2dd = matmul(inverse2(self%a_mat), matmul(self%b_mat, q1dd) + matmul(db, q1d) - matmul(da, q2d))   ! (E.12)
        scalars(self%u2)%qd = q2d(1)
        scalars(self%v2)%qd = q2d(2)
        scalars(self%u2)%qdd = q2dd(1)
        scalars(self%v2)%qdd = q2dd(2)
      else
        q2d = [scalars(self%u2)%qd, scalars(self%v2)%qd]
        q2dd = [scalars(self%u2)%qdd, scalars(self%v2)%qdd]
        omega_rel2 = j2%gu*q2d(1) + j2%gv*q2d(2)
      end if
      w_rel2 = j2%tu*q2d(1) + j2%tv*q2d(2)
      k2%omega = c%omega - omega_rel2 + phid*z
      ! E.4-E.7 by differentiating (3.84)
      k2%alpha = c%alpha - relative_alpha(j2, q2d, q2dd, k2%omega) + scalars(self%phi)%qdd*z &
                 + phid*cross(c%omega, z)
      ! E.8
      k2%a = c%a - relative_a(j2, q2d, q2dd) - 2*cross(k2%omega, w_rel2) - cross(k2%alpha, j2%p) &
             - cross(k2%omega, cross(k2%omega, j2%p))
    end associate
  end subroutine vc_acceleration

  !> A surface joint's relative angular acceleration, world coordinates:
  !> R (W_u u'' + W_v v'' + W_u' u' + W_v' v') + omega x R (W_u u' + W_v v').
  pure function relative_alpha(j, qd, qdd, omega) result(al)
    type(surface_joint_t), intent(in) :: j
    real(wp), intent(in) :: qd(2), qdd(2), omega(3)
    real(wp) :: al(3)
    al = j%gu*qdd(1) + j%gv*qdd(2) + (j%guu*qd(1) + j%guv*qd(2))*qd(1) + (j%gvu*qd(1) + j%gvv*qd(2))*qd(2) &
         + cross(omega, j%gu*qd(1) + j%gv*qd(2))
  end function relative_alpha

  !> R (r_u u'' + r_v v'' + r_uu u'^2 + 2 r_uv u' v' + r_vv v'^2).
  pure function relative_a(j, qd, qdd) result(a)
    type(surface_joint_t), intent(in) :: j
    real(wp), intent(in) :: qd(2), qdd(2)
    real(wp) :: a(3)
    a = j%tu*qdd(1) + j%tv*qdd(2) + j%huu*qd(1)**2 + 2*j%huv*qd(1)*qd(2) + j%hvv*qd(2)**2
  end function relative_a

  pure subroutine vc_force(self, frames, scalars, inertia, applied)
    class(velocity_contact_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3), q2(2)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    associate (c => frames(self%frame_1d), k2 => frames(self%frame_2), j2 => self%joint_2)
      f = k2%force
      t = k2%torque - cross(j2%p, f)
      c%force = c%force + f
      c%torque = c%torque + t
      q2(1) = scalars(self%u2)%force - dot_product(t, j2%gu) - dot_product(f, j2%tu)
      q2(2) = scalars(self%v2)%force - dot_product(t, j2%gv) - dot_product(f, j2%tv)
      scalars(self%phi)%force = scalars(self%phi)%force + dot_product(t, self%axes_1d(:, 3))
    end associate
    if (self%rolling) then
      ! E.16: the forces on u2, v2 (direct ones from the elements on body 2 included) move to u1, v1
      q2 = matmul(transpose(self%ainv_b), q2)
      scalars(self%u1)%force = scalars(self%u1)%force + q2(1)
      scalars(self%v1)%force = scalars(self%v1)%force + q2(2)
      scalars(self%u2)%force = 0
      scalars(self%v2)%force = 0
    else
      scalars(self%u2)%force = q2(1)
      scalars(self%v2)%force = q2(2)
    end if
  end subroutine vc_force

  !> The pose chart changes like a free rotation's (its middle angle decides).
  pure integer function vc_chart_angle(self) result(k)
    class(velocity_contact_t), intent(in) :: self
    k = self%pose(5)
  end function vc_chart_angle

  pure real(wp) function vc_chart_margin(self, angle) result(g)
    class(velocity_contact_t), intent(in) :: self
    real(wp), intent(in) :: angle
    g = self%chart%chart_margin(angle)
  end function vc_chart_margin

  pure subroutine vc_rebase(self, scalars)
    class(velocity_contact_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(scalar_state_t) :: angles(3)
    angles = scalars(self%pose(4:6))
    call self%chart%rebase(angles)
    scalars(self%pose(4:6)) = angles
  end subroutine vc_rebase

  pure function inverse2(a) result(b)
    real(wp), intent(in) :: a(2, 2)
    real(wp) :: b(2, 2), det
    det = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
    b = reshape([a(2, 2), -a(2, 1), -a(1, 2), a(1, 1)], [2, 2])/det
  end function inverse2

  pure function solve3(m, b) result(x)
    real(wp), intent(in) :: m(3, 3), b(3)
    real(wp) :: x(3), det
    det = dot_product(m(:, 1), cross(m(:, 2), m(:, 3)))
    x(1) = dot_product(b, cross(m(:, 2), m(:, 3)))/det
    x(2) = dot_product(m(:, 1), cross(b, m(:, 3)))/det
    x(3) = dot_product(m(:, 1), cross(m(:, 2), b))/det
  end function solve3
end module contact_velocity_level
