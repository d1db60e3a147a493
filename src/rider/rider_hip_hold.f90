!> The rider's hold of its posture in flight (docs/rider.md "Flight"): a
!> torsion spring and damper at a hip joint, tau = -k (phi - phi_hold) -
!> c phi', on the limb about the joint's axis and its opposite on the
!> pelvis. The thesis's rider has free hips, which is right while the three
!> contacts hold it on the slide; in the air nothing would hold a limb and a
!> free hip folds the rider (the legs swing up, the trunk back) until the
!> model leaves the hip's range. A rider in the air braces: the hold keeps
!> the posture of the take-off with a stiffness k = I omega^2 and a
!> critical damping c = 2 I omega (I: the limb's moment of inertia about
!> the hip axis, omega = 2 pi hold_frequency). It acts only while a contact
!> is open (`active`, switched by the ride); an internal torque, so the
!> rider's momentum and the centre of mass's parabola in free flight are
!> untouched, and its work (spring and damper) is the law's work integral.
module rider_hip_hold
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use kinetostatics_force_law, only: force_law_t, frame_load_t
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_contact, only: contact_state_t
  use rider_body, only: rigid_body_t
  implicit none (type, external)
  private
  public :: hip_hold_t, new_hip_hold

  !> Hz: the held limb's natural frequency about the hip (a braced body
  !> segment: a few Hz; the ride's results in flight depend on it, docs/rider.md).
  real(wp), parameter, public :: hold_frequency = 4
  !> 1: critical damping (the limb returns to the posture without swinging)
  real(wp), parameter, public :: hold_damping_ratio = 1

  type, extends(force_law_t) :: hip_hold_t
    integer :: angle = 0                 ! scalar index of the joint's angle
    integer :: parent = 0, limb = 0      ! frames: the hip (joint's input), the limb
    real(wp) :: axis(3) = 0              ! the joint's axis in the parent's axes
    real(wp) :: stiffness = 0            ! N m/rad
    real(wp) :: damping = 0              ! N m s/rad
    real(wp) :: hold = 0                 ! rad, the posture held (set at the take-off)
  contains
    procedure :: evaluate => hold_evaluate
  end type hip_hold_t

contains

  !> The hold of `limb` (its mass and centre of mass in its own frame, whose
  !> origin is the hip) on the joint `angle` about `axis` (parent's axes);
  !> inactive until the ride switches it on.
  function new_hip_hold(name, angle, parent, limb, axis, part) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: angle, parent, limb
    real(wp), intent(in) :: axis(3)
    type(rigid_body_t), intent(in) :: part
    type(hip_hold_t) :: law
    real(wp) :: inertia, omega
    law%name = name
    law%angle = angle
    law%parent = parent
    law%limb = limb
    law%axis = axis/norm2(axis)
    ! about the hip axis: the limb's own inertia plus its mass's (the
    ! revolute turns the limb's frame, so its axes are the parent's at 0)
    inertia = dot_product(law%axis, matmul(part%inertia, law%axis)) + &
              part%mass*(dot_product(part%com, part%com) - dot_product(law%axis, part%com)**2)
    omega = 2*pi*hold_frequency
    law%stiffness = inertia*omega**2
    law%damping = 2*hold_damping_ratio*inertia*omega
    law%active = .false.
    allocate (law%loads(2))
  end function new_hip_hold

  pure subroutine hold_evaluate(self, t, frames, scalars, contacts, status)
    class(hip_hold_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    real(wp) :: a(3), tau
    associate (unused_t => t, unused_c => contacts, unused_s => status)
    end associate
    a = matmul(frames(self%parent)%rot, self%axis)
    associate (phi => scalars(self%angle))
      tau = -self%stiffness*(phi%q - self%hold) - self%damping*phi%qd
    end associate
    self%loads(1) = frame_load_t(self%limb, [0.0_wp, 0.0_wp, 0.0_wp], tau*a)
    self%loads(2) = frame_load_t(self%parent, [0.0_wp, 0.0_wp, 0.0_wp], -tau*a)
  end subroutine hold_evaluate
end module rider_hip_hold
