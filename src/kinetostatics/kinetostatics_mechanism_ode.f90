!> A mechanism as an ODE system for numerics_ode: y = [q, q'], y' = [q', q'']
!> with q'' from kinetostatics_mechanism's equations of motion (3.36).
!>
!> Events: root functions g_k(t, y) = y(event_index(k)) - event_value(k), i.e.
!> a coordinate (index 1..f) or a rate (f+1..2f) crossing a value; the
!> integrator stops there and says which one and in which direction.
module kinetostatics_mechanism_ode
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_system_t
  use kinetostatics_mechanism, only: mechanism_t
  implicit none (type, external)
  private
  public :: mechanism_ode_t

  type, extends(ode_system_t) :: mechanism_ode_t
    type(mechanism_t) :: mechanism
    integer, allocatable :: event_index(:)
    real(wp), allocatable :: event_value(:)
    integer :: rhs_count = 0
  contains
    procedure :: rhs => mechanism_rhs
    procedure :: root_count => mechanism_root_count
    procedure :: roots => mechanism_roots
  end type mechanism_ode_t

contains

  subroutine mechanism_rhs(self, t, y, ydot, status)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    integer :: f
    associate (unused_t => t)
    end associate
    f = self%mechanism%f
    self%rhs_count = self%rhs_count + 1
    ydot(1:f) = y(f + 1:2*f)
    call self%mechanism%dynamics(y(1:f), y(f + 1:2*f), ydot(f + 1:2*f), status)
  end subroutine mechanism_rhs

  integer function mechanism_root_count(self) result(n)
    class(mechanism_ode_t), intent(in) :: self
    n = 0
    if (allocated(self%event_index)) n = size(self%event_index)
  end function mechanism_root_count

  subroutine mechanism_roots(self, t, y, g)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    integer :: k
    associate (unused_t => t)
    end associate
    do k = 1, size(self%event_index)
      g(k) = y(self%event_index(k)) - self%event_value(k)
    end do
  end subroutine mechanism_roots
end module kinetostatics_mechanism_ode
