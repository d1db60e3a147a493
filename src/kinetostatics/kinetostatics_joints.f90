!> Rigid offset, revolute, prismatic and spherical joints as kinetostatic
!> transmission elements (thesis 3.2, (3.3)-(3.7)); all vectors in world
!> coordinates (see kinetostatics_state).
!>
!> With p the world vector from the input to the output origin and n a joint
!> axis in world coordinates (both carried by the input frame):
!>     offset:     v_o = v_i + w_i x p,  a_o = a_i + al_i x p + w_i x (w_i x p)
!>     revolute:   w_o = w_i + n q',     al_o = al_i + n q'' + w_i x n q'
!>     prismatic:  p = n q, v_o = v_i + w_i x p + n q',
!>                 a_o = a_i + al_i x p + w_i x (w_i x p) + 2 w_i x n q' + n q''
!> and forces back: f_i += f_o, tau_i += tau_o + p x f_o, Q = n.tau_o (revolute)
!> or n.f_o (prismatic): the transposed maps, so that power is conserved (3.6).
module kinetostatics_joints
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross, rot_x, rot_y, rot_z
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t, axis_rotation
  implicit none (type, external)
  private
  public :: rigid_offset_t, revolute_t, prismatic_t, spherical_t
  public :: new_rigid_offset, new_revolute, new_prismatic, new_spherical

  !> K_out = K_in moved by `offset` (m, input coordinates) and turned by `rotation`.
  type, extends(element_t) :: rigid_offset_t
    integer :: frame_in = 0, frame_out = 0
    real(wp) :: offset(3) = 0
    real(wp) :: rotation(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    real(wp) :: p(3) = 0       ! world offset at the last position
  contains
    procedure :: position => offset_position
    procedure :: velocity => offset_velocity
    procedure :: acceleration => offset_acceleration
    procedure :: force => offset_force
    procedure :: links => offset_links
  end type rigid_offset_t

  !> What the revolute and the prismatic joint share: one joint variable and
  !> an `axis` (unit, input coordinates; set by the constructor), n = the axis
  !> in world coordinates at the last position.
  type, abstract, extends(element_t) :: axis_joint_t
    integer :: frame_in = 0, frame_out = 0, variable = 0
    real(wp) :: axis(3) = 0
    real(wp) :: n(3) = 0
  contains
    procedure :: links => axis_joint_links
  end type axis_joint_t

  !> K_out = K_in turned by q (rad) about `axis`.
  type, extends(axis_joint_t) :: revolute_t
  contains
    procedure :: position => revolute_position
    procedure :: velocity => revolute_velocity
    procedure :: acceleration => revolute_acceleration
    procedure :: force => revolute_force
  end type revolute_t

  !> K_out = K_in shifted by q (m) along `axis`.
  type, extends(axis_joint_t) :: prismatic_t
    real(wp) :: p(3) = 0       ! world offset n q at the last position
  contains
    procedure :: position => prismatic_position
    procedure :: velocity => prismatic_velocity
    procedure :: acceleration => prismatic_acceleration
    procedure :: force => prismatic_force
  end type prismatic_t

  !> Spherical joint with Cardan angles: R_out = R_in Rx(q1) Ry(q2) Rz(q3),
  !> i.e. three revolutes about x, the new y and the newest z.
  type, extends(element_t) :: spherical_t
    integer :: frame_in = 0, frame_out = 0, variables(3) = 0
    real(wp) :: n(3, 3) = 0          ! the three world axes, columns
    real(wp) :: w1(3) = 0, w2(3) = 0 ! angular velocities after the first and second turn
  contains
    procedure :: position => spherical_position
    procedure :: velocity => spherical_velocity
    procedure :: acceleration => spherical_acceleration
    procedure :: force => spherical_force
    procedure :: links => spherical_links
  end type spherical_t

contains

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine offset_links(self, links)
    class(rigid_offset_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], [integer ::], [self%frame_out], [integer ::], carried=.true.)
  end subroutine offset_links

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine axis_joint_links(self, links)
    class(axis_joint_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], [self%variable], [self%frame_out], [integer ::], carried=.true.)
  end subroutine axis_joint_links

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine spherical_links(self, links)
    class(spherical_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], self%variables, [self%frame_out], [integer ::], carried=.true.)
  end subroutine spherical_links

  function new_rigid_offset(name, frame_in, frame_out, offset, rotation) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out
    real(wp), intent(in) :: offset(3)
    real(wp), intent(in), optional :: rotation(3, 3)
    type(rigid_offset_t) :: e
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%offset = offset
    if (present(rotation)) e%rotation = rotation
  end function new_rigid_offset

  function new_revolute(name, frame_in, frame_out, variable, axis) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, variable
    real(wp), intent(in) :: axis(3)
    type(revolute_t) :: e
    call set_axis_joint(e, name, frame_in, frame_out, variable, axis)
  end function new_revolute

  function new_prismatic(name, frame_in, frame_out, variable, axis) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, variable
    real(wp), intent(in) :: axis(3)
    type(prismatic_t) :: e
    call set_axis_joint(e, name, frame_in, frame_out, variable, axis)
  end function new_prismatic

  pure subroutine set_axis_joint(e, name, frame_in, frame_out, variable, axis)
    class(axis_joint_t), intent(inout) :: e
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, variable
    real(wp), intent(in) :: axis(3)
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%variable = variable
    e%axis = axis/norm2(axis)
  end subroutine set_axis_joint

  function new_spherical(name, frame_in, frame_out, variables) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, variables(3)
    type(spherical_t) :: e
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%variables = variables
  end function new_spherical

  ! ------------------------------------------------------------ rigid offset

  pure subroutine offset_position(self, frames, scalars, status)
    class(rigid_offset_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    associate (unused => scalars, unused_status => status)
    end associate
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%p = matmul(i%rot, self%offset)
      o%rot = matmul(i%rot, self%rotation)
      o%r = i%r + self%p
    end associate
  end subroutine offset_position

  pure subroutine offset_velocity(self, frames, scalars)
    class(rigid_offset_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (unused => scalars)
    end associate
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      o%omega = i%omega
      o%v = carried_velocity(i, self%p)
    end associate
  end subroutine offset_velocity

  pure subroutine offset_acceleration(self, frames, scalars)
    class(rigid_offset_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (unused => scalars)
    end associate
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      o%alpha = i%alpha
      o%a = carried_acceleration(i, self%p)
    end associate
  end subroutine offset_acceleration

  pure subroutine offset_force(self, frames, scalars, inertia, applied)
    class(rigid_offset_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    associate (unused => scalars, unused_i => inertia, unused_a => applied)
    end associate
    call pass_wrench_back(frames, self%frame_in, self%frame_out, f, t, self%p)
  end subroutine offset_force

  ! ---------------------------------------------------------------- revolute

  pure subroutine revolute_position(self, frames, scalars, status)
    class(revolute_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: turn(3, 3)
    associate (unused_status => status)
    end associate
    turn = axis_rotation(self%axis, scalars(self%variable)%q)
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%n = matmul(i%rot, self%axis)
      o%rot = matmul(i%rot, turn)
      o%r = i%r
    end associate
  end subroutine revolute_position

  pure subroutine revolute_velocity(self, frames, scalars)
    class(revolute_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      o%omega = turned_omega(i%omega, self%n, scalars(self%variable)%qd)
      o%v = i%v
    end associate
  end subroutine revolute_velocity

  pure subroutine revolute_acceleration(self, frames, scalars)
    class(revolute_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (i => frames(self%frame_in), o => frames(self%frame_out), s => scalars(self%variable))
      o%alpha = turned_alpha(i%alpha, i%omega, self%n, s%qd, s%qdd)
      o%a = i%a
    end associate
  end subroutine revolute_acceleration

  pure subroutine revolute_force(self, frames, scalars, inertia, applied)
    class(revolute_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    call pass_wrench_back(frames, self%frame_in, self%frame_out, f, t)
    if (all(t == 0)) return   ! adds nothing
    scalars(self%variable)%force = scalars(self%variable)%force + dot_product(self%n, t)
  end subroutine revolute_force

  ! --------------------------------------------------------------- prismatic

  pure subroutine prismatic_position(self, frames, scalars, status)
    class(prismatic_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    associate (unused_status => status)
    end associate
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%n = matmul(i%rot, self%axis)
      self%p = self%n*scalars(self%variable)%q
      o%rot = i%rot
      o%r = i%r + self%p
    end associate
  end subroutine prismatic_position

  pure subroutine prismatic_velocity(self, frames, scalars)
    class(prismatic_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      o%omega = i%omega
      o%v = carried_velocity(i, self%p) + self%n*scalars(self%variable)%qd
    end associate
  end subroutine prismatic_velocity

  pure subroutine prismatic_acceleration(self, frames, scalars)
    class(prismatic_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (i => frames(self%frame_in), o => frames(self%frame_out), s => scalars(self%variable))
      o%alpha = i%alpha
      o%a = carried_acceleration(i, self%p) + 2*cross(i%omega, self%n)*s%qd + self%n*s%qdd
    end associate
  end subroutine prismatic_acceleration

  pure subroutine prismatic_force(self, frames, scalars, inertia, applied)
    class(prismatic_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    call pass_wrench_back(frames, self%frame_in, self%frame_out, f, t, self%p)
    scalars(self%variable)%force = scalars(self%variable)%force + dot_product(self%n, f)
  end subroutine prismatic_force

  ! --------------------------------------------------------------- spherical

  pure subroutine spherical_position(self, frames, scalars, status)
    class(spherical_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: ra(3, 3), rb(3, 3), t1(3, 3), t2(3, 3), t3(3, 3)
    associate (unused_status => status)
    end associate
    t1 = rot_x(scalars(self%variables(1))%q)
    t2 = rot_y(scalars(self%variables(2))%q)
    t3 = rot_z(scalars(self%variables(3))%q)
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      ra = matmul(i%rot, t1)
      rb = matmul(ra, t2)
      self%n(:, 1) = i%rot(:, 1)
      self%n(:, 2) = ra(:, 2)
      self%n(:, 3) = rb(:, 3)
      o%rot = matmul(rb, t3)
      o%r = i%r
    end associate
  end subroutine spherical_position

  pure subroutine spherical_velocity(self, frames, scalars)
    class(spherical_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%w1 = turned_omega(i%omega, self%n(:, 1), scalars(self%variables(1))%qd)
      self%w2 = turned_omega(self%w1, self%n(:, 2), scalars(self%variables(2))%qd)
      o%omega = turned_omega(self%w2, self%n(:, 3), scalars(self%variables(3))%qd)
      o%v = i%v
    end associate
  end subroutine spherical_velocity

  !> Each axis turns with the frame before its own turn: d n_k/dt = w_(k-1) x n_k.
  pure subroutine spherical_acceleration(self, frames, scalars)
    class(spherical_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: qd(3), qdd(3), alpha1(3), alpha2(3)
    integer :: k
    do k = 1, 3
      qd(k) = scalars(self%variables(k))%qd
      qdd(k) = scalars(self%variables(k))%qdd
    end do
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%w1 = turned_omega(i%omega, self%n(:, 1), qd(1))
      self%w2 = turned_omega(self%w1, self%n(:, 2), qd(2))
      alpha1 = turned_alpha(i%alpha, i%omega, self%n(:, 1), qd(1), qdd(1))
      alpha2 = turned_alpha(alpha1, self%w1, self%n(:, 2), qd(2), qdd(2))
      o%alpha = turned_alpha(alpha2, self%w2, self%n(:, 3), qd(3), qdd(3))
      o%a = i%a
    end associate
  end subroutine spherical_acceleration

  pure subroutine spherical_force(self, frames, scalars, inertia, applied)
    class(spherical_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    integer :: k
    associate (unused_i => inertia, unused_a => applied)
    end associate
    call pass_wrench_back(frames, self%frame_in, self%frame_out, f, t)
    do k = 1, 3
      scalars(self%variables(k))%force = scalars(self%variables(k))%force + dot_product(self%n(:, k), t)
    end do
  end subroutine spherical_force
  ! ----------------------------------------------------------- shared pieces

  !> Velocity of the point at world offset p from the origin of frame i,
  !> carried rigidly with it: v_i + w_i x p (module header).
  pure function carried_velocity(i, p) result(v)
    type(frame_state_t), intent(in) :: i
    real(wp), intent(in) :: p(3)
    real(wp) :: v(3)
    v = i%v + cross(i%omega, p)
  end function carried_velocity

  !> Its acceleration: a_i + al_i x p + w_i x (w_i x p). A frame at rest
  !> (mass-matrix columns) has no centripetal term: it is skipped (the
  !> other terms summed in the same order).
  pure function carried_acceleration(i, p) result(a)
    type(frame_state_t), intent(in) :: i
    real(wp), intent(in) :: p(3)
    real(wp) :: a(3)
    a = i%a + cross(i%alpha, p)
    if (any(i%omega /= 0)) a = a + cross(i%omega, cross(i%omega, p))
  end function carried_acceleration

  !> Angular velocity after a turn at rate qd about the world axis n: w + n q'.
  pure function turned_omega(omega, n, qd) result(w)
    real(wp), intent(in) :: omega(3), n(3), qd
    real(wp) :: w(3)
    w = omega + n*qd
  end function turned_omega

  !> Angular acceleration after that turn, n carried by a frame turning with
  !> omega: al + n q'' + (omega x n) q' (the last term skipped at q' = 0,
  !> as in the mass-matrix columns).
  pure function turned_alpha(alpha, omega, n, qd, qdd) result(al)
    real(wp), intent(in) :: alpha(3), omega(3), n(3), qd, qdd
    real(wp) :: al(3)
    al = alpha + n*qdd
    if (qd /= 0) al = al + cross(omega, n)*qd
  end function turned_alpha

  !> The force back-map (3.6): f and t, the wrench on the output frame, are
  !> added to the input frame, t about its origin, i.e. plus p x f when the
  !> output origin sits at the world offset p from it. No wrench (a frame
  !> loaded only by cut forces, in the first pass of an inverse dynamics)
  !> adds nothing.
  pure subroutine pass_wrench_back(frames, frame_in, frame_out, f, t, p)
    type(frame_state_t), intent(inout) :: frames(:)
    integer, intent(in) :: frame_in, frame_out
    real(wp), intent(out) :: f(3), t(3)
    real(wp), intent(in), optional :: p(3)
    f = frames(frame_out)%force
    t = frames(frame_out)%torque
    if (all(f == 0) .and. all(t == 0)) return
    frames(frame_in)%force = frames(frame_in)%force + f
    if (present(p)) then
      frames(frame_in)%torque = frames(frame_in)%torque + t + cross(p, f)
    else
      frames(frame_in)%torque = frames(frame_in)%torque + t
    end if
  end subroutine pass_wrench_back
end module kinetostatics_joints
