!> Contacts of a mechanism: where two bodies touch, which way the surface
!> normal points, how fast they slip against each other, and how their normal
!> force is found.
!>
!> A contact names three frames of the mechanism: a frame rigidly attached to
!> body A (the ground, frame 1, is allowed), one rigidly attached to body B,
!> and the contact-point frame P: origin at the contact point p, z along the
!> surface normal (typically the Darboux frame output of a surface joint).
!> The unit normal n = normal_sign z_P points from A into B.
!>
!> Slip velocity: the MATERIAL relative velocity of the two bodies at p,
!>     w = v_B + omega_B x (p - r_B) - v_A - omega_A x (p - r_A)     (thesis 3.87)
!> (not the velocity of P itself, which moves along the surfaces). A load F on
!> body B at p is applied as force F and torque (p - r_B) x F at B's frame
!> origin, -F and -(p - r_A) x F on A's: equal and opposite, and its power is
!> F . w.
!>
!> Normal force N, positive while the bodies press on each other:
!>   NORMAL_FRAME_FORCE  N = -normal_sign z_F . f_F, with f_F the force the
!>                       mechanism puts on frame F after a force pass (F is
!>                       normally P itself, the output of a surface joint on
!>                       body A: what the bodies downstream press on it);
!>   NORMAL_CUT_FORCE    N = normal_sign lambda_g, the cut force of the closure
!>                       measurement g (e.g. the plane-point measurement along
!>                       the normal that closes a contact between two moving
!>                       surfaces, or the z row of the sled's front contact).
!> Both are linear in the loads of a force pass, which is what lets the
!> mechanism solve friction proportional to |N| exactly. A one-sided contact
!> can only push: N falling through zero is the lift-off event.
!>
!> Static friction of a rolling contact: the cut forces mu_x, mu_y of its
!> no-slip rate constraint (outputs c_x = x_P . w, c_y = y_P . w), the force
!> mu_x x_P + mu_y y_P on body B at p (contact_rolling).
module kinetostatics_contact
  use base_kinds, only: wp
  use base_vector, only: cross
  use kinetostatics_state, only: frame_state_t
  implicit none (type, external)
  private
  public :: contact_t, contact_state_t, contact_kinematics, NORMAL_FRAME_FORCE, NORMAL_CUT_FORCE

  integer, parameter :: NORMAL_FRAME_FORCE = 1, NORMAL_CUT_FORCE = 2

  !> What force laws see of a contact: its kinematics at the current
  !> positions and velocities (all world coordinates).
  type :: contact_state_t
    integer :: frame_a = 1, frame_b = 0        ! the bodies' frames
    real(wp) :: point(3) = 0                   ! m, contact point p
    real(wp) :: axes(3, 3) = 0                 ! axes of the contact-point frame (columns x, y, z)
    real(wp) :: normal(3) = 0                  ! unit normal from A into B
    real(wp) :: arm_a(3) = 0, arm_b(3) = 0     ! m, p - r_A, p - r_B
    real(wp) :: velocity_a(3) = 0              ! m/s, material velocity of A at p
    real(wp) :: velocity_b(3) = 0              ! m/s, material velocity of B at p
    real(wp) :: slip(3) = 0                    ! m/s, velocity_b - velocity_a
  end type contact_state_t

  type :: contact_t
    character(len=:), allocatable :: name
    integer :: frame_a = 1, frame_b = 0, point_frame = 0
    integer :: normal_rule = NORMAL_FRAME_FORCE
    integer :: normal_frame = 0                ! NORMAL_FRAME_FORCE: the frame F
    integer :: normal_measurement = 0          ! NORMAL_CUT_FORCE: scalar index of g
    integer :: normal_row = 0                  ! ... and its row among the closure measurements
    real(wp) :: normal_sign = 1                ! +1 or -1, see the module comment
    logical :: one_sided = .true.              ! lift-off (N falling through 0) is an event
    !> a rolling contact's no-slip outputs along x_P and y_P (scalar indices;
    !> 0: none): their cut forces are its static friction on body B
    integer :: tangential_outputs(2) = 0
  end type contact_t

contains

  !> The kinematics of contact c from the frames (positions and velocities set).
  pure subroutine contact_kinematics(c, frames, s)
    type(contact_t), intent(in) :: c
    type(frame_state_t), intent(in) :: frames(:)
    type(contact_state_t), intent(inout) :: s
    associate (a => frames(c%frame_a), b => frames(c%frame_b), p => frames(c%point_frame))
      s%frame_a = c%frame_a
      s%frame_b = c%frame_b
      s%point = p%r
      s%axes = p%rot
      s%normal = c%normal_sign*p%rot(:, 3)
      s%arm_a = p%r - a%r
      s%arm_b = p%r - b%r
      s%velocity_a = a%v + cross(a%omega, s%arm_a)
      s%velocity_b = b%v + cross(b%omega, s%arm_b)
      s%slip = s%velocity_b - s%velocity_a
    end associate
  end subroutine contact_kinematics
end module kinetostatics_contact
