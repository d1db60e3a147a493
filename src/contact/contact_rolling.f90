!> The no-slip condition of rolling (thesis (3.85), (3.87)) as a velocity-level
!> constraint element: its two outputs are the tangential components of the
!> slip velocity, the material relative velocity of the two bodies at the
!> contact point p (the origin of the contact frame P, the Darboux frame K_1D
!> on body A):
!>     w = v_B + omega_B x (p - r_B) - v_A - omega_A x (p - r_A)       (3.87)
!>     c_x = x_P . w,   c_y = y_P . w
!> Rolling requires c_x = c_y = 0; the mechanism solves two dependent
!> velocities from that (state [q, s], q' = B(q) s). The outputs have no
!> position-level value (q = 0): they are rates only.
!>
!> Acceleration: the derivative along the motion, with p' = v_P and the axes
!> turning with P (x_P' = omega_P x x_P):
!>     w' = a_B + alpha_B x (p - r_B) + omega_B x (v_P - v_B)
!>          - a_A - alpha_A x (p - r_A) - omega_A x (v_P - v_A),
!>     c_x' = (omega_P x x_P) . w + x_P . w'.
!> Force (the transposed velocity map): the cut forces lambda_x, lambda_y are
!> the static friction force F = lambda_x x_P + lambda_y y_P on body B at p,
!> and -F on body A: f_B += F, tau_B += (p - r_B) x F, and the opposite on A.
!> (c does not depend on P's velocity, so P gets no load.)
module contact_rolling
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t
  implicit none (type, external)
  private
  public :: no_slip_t, new_no_slip

  type, extends(element_t) :: no_slip_t
    integer :: frame_a = 0, frame_b = 0, frame_p = 0
    integer :: outputs(2) = 0               ! scalars c_x, c_y
    real(wp) :: arm_a(3) = 0, arm_b(3) = 0  ! p - r_A, p - r_B at the last position
    real(wp) :: axes(3, 2) = 0              ! x_P, y_P
  contains
    procedure :: position => no_slip_position
    procedure :: velocity => no_slip_velocity
    procedure :: acceleration => no_slip_acceleration
    procedure :: force => no_slip_force
    procedure :: links => no_slip_links
  end type no_slip_t

contains

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine no_slip_links(self, links)
    class(no_slip_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_a, self%frame_b, self%frame_p], [integer ::], [integer ::], self%outputs, &
                            relative=.true.)
  end subroutine no_slip_links

  function new_no_slip(name, frame_a, frame_b, frame_p, outputs) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_a, frame_b, frame_p, outputs(2)
    type(no_slip_t) :: e
    e%name = name
    e%frame_a = frame_a
    e%frame_b = frame_b
    e%frame_p = frame_p
    e%outputs = outputs
  end function new_no_slip

  pure subroutine no_slip_position(self, frames, scalars, status)
    class(no_slip_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    associate (unused_status => status)
    end associate
    associate (a => frames(self%frame_a), b => frames(self%frame_b), p => frames(self%frame_p))
      self%arm_a = p%r - a%r
      self%arm_b = p%r - b%r
      self%axes = p%rot(:, 1:2)
    end associate
    scalars(self%outputs)%q = 0
  end subroutine no_slip_position

  pure subroutine no_slip_velocity(self, frames, scalars)
    class(no_slip_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: w(3)
    associate (a => frames(self%frame_a), b => frames(self%frame_b))
      w = b%v + cross(b%omega, self%arm_b) - a%v - cross(a%omega, self%arm_a)       ! (3.87)
    end associate
    scalars(self%outputs(1))%qd = dot_product(self%axes(:, 1), w)
    scalars(self%outputs(2))%qd = dot_product(self%axes(:, 2), w)
  end subroutine no_slip_velocity

  pure subroutine no_slip_acceleration(self, frames, scalars)
    class(no_slip_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: w(3), wd(3)
    integer :: k
    associate (a => frames(self%frame_a), b => frames(self%frame_b), p => frames(self%frame_p))
      w = b%v + cross(b%omega, self%arm_b) - a%v - cross(a%omega, self%arm_a)
      wd = b%a + cross(b%alpha, self%arm_b) + cross(b%omega, p%v - b%v) &
           - a%a - cross(a%alpha, self%arm_a) - cross(a%omega, p%v - a%v)
      do k = 1, 2
        scalars(self%outputs(k))%qd = dot_product(self%axes(:, k), w)
        scalars(self%outputs(k))%qdd = dot_product(cross(p%omega, self%axes(:, k)), w) + &
                                       dot_product(self%axes(:, k), wd)
      end do
    end associate
  end subroutine no_slip_acceleration

  pure subroutine no_slip_force(self, frames, scalars, inertia, applied)
    class(no_slip_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    f = self%axes(:, 1)*scalars(self%outputs(1))%force + self%axes(:, 2)*scalars(self%outputs(2))%force
    associate (a => frames(self%frame_a), b => frames(self%frame_b))
      b%force = b%force + f
      b%torque = b%torque + cross(self%arm_b, f)
      a%force = a%force - f
      a%torque = a%torque - cross(self%arm_a, f)
    end associate
  end subroutine no_slip_force
end module contact_rolling
