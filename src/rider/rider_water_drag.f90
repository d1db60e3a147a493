!> The water's drag on the rider (thesis (4.29)) as a force law at one
!> contact: the sphere of that contact (rider_drag) in the computed water
!> (water_field) at the contact's u; the load acts on the contact's body at
!> the contact point (it comes from outside the two touching bodies).
!>
!> On and off (thesis 4.3): the law is active while the contact lies between
!> the water's edges, v_right(u) < v < v_left(u). Its two root functions are
!> g1 = v - v_right(u) and g2 = v_left(u) - v (C1 along the path: the field's
!> edges carry their exact u-derivatives); where the field has no edge at u
!> (before the water's start, after its end) both are -1 (dry). A root
!> rising switches the drag on, a root falling switches it off; either asks
!> the driver to restart the integrator (the force jumps there).
!>
!> The law does not own the water: it points at the field the model's
!> builder was given (new_water_drag's `water`, a TARGET), and every copy of
!> the mechanism (the integrator's and the probe's workspaces, the flight
!> builds) shares that one field, which is only read. Whoever owns the
!> field keeps it, unchanged, for as long as any mechanism built with it is
!> used: simulate_ride's `water` argument for the rider (the mechanisms live
!> inside that call), run_sled's figures for a vehicle.
module rider_water_drag
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_event_driver, only: EVENT_IGNORE, EVENT_RESTART
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_contact, only: contact_state_t
  use kinetostatics_force_law, only: contact_law_t
  use water_field, only: water_field_t, water_edges_at_t, WATER_INSIDE
  use rider_drag, only: water_properties_t, drag_state_t, evaluate_drag
  implicit none (type, external)
  private
  public :: water_drag_t, new_water_drag, in_water_roots

  type, extends(contact_law_t) :: water_drag_t
    type(water_field_t), pointer :: water => null()   ! the computed water (not owned, only read)
    type(water_properties_t) :: properties
    real(wp) :: radius = 0                       ! m, sphere radius r_S
    integer :: var_u = 0, var_v = 0              ! scalar indices of the contact's (u, v)
    type(drag_state_t) :: state                  ! at the last evaluation
  contains
    procedure :: evaluate => drag_evaluate
    procedure :: root_count => drag_root_count
    procedure :: roots => drag_roots
    procedure :: handle_event => drag_handle_event
  end type water_drag_t

contains

  !> The drag at contact `contact` (index of mechanism%add_contact) whose
  !> surface parameters are the scalars var_u, var_v; `active` at the start.
  !> The law points at `water` (no copy): its actual argument must outlive
  !> every mechanism the law is added to.
  function new_water_drag(name, contact, var_u, var_v, radius, properties, water, active) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: contact, var_u, var_v
    real(wp), intent(in) :: radius
    type(water_properties_t), intent(in) :: properties
    type(water_field_t), intent(in), target :: water
    logical, intent(in) :: active
    type(water_drag_t) :: law
    call law%set_up_contact_law(name, contact, scaled=.false.)
    law%var_u = var_u
    law%var_v = var_v
    law%radius = radius
    law%properties = properties
    law%water => water
    law%active = active
  end function new_water_drag

  !> g1 = v - v_right(u), g2 = v_left(u) - v (both > 0 under water; -1 where
  !> the water has no edges at u).
  pure subroutine in_water_roots(water, u, v, g)
    type(water_field_t), intent(in) :: water
    real(wp), intent(in) :: u, v
    real(wp), intent(out) :: g(2)
    type(water_edges_at_t) :: edges
    call water%edges_at_u(u, edges)
    g = -1
    if (edges%right_location == WATER_INSIDE .and. edges%left_location == WATER_INSIDE) &
      g = [v - edges%v_right, edges%v_left - v]
  end subroutine in_water_roots

  pure subroutine drag_evaluate(self, t, frames, scalars, contacts, status)
    class(water_drag_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    real(wp) :: position(3), velocity(3), height, z_m(3)
    integer :: location
    associate (unused_t => t, unused_f => frames, unused_st => status)
    end associate
    associate (s => contacts(self%contact))
      ! only what the drag needs of the water (at_u would add the edges, K_M, beta)
      call self%water%flow_at_u(scalars(self%var_u)%q, location, position, velocity, height, z_m)
      if (location == WATER_INSIDE) then
        call evaluate_drag(self%radius, self%properties, s%point, s%normal, s%slip, position, z_m, height, &
                           velocity, self%state)
      else
        self%state = drag_state_t()
      end if
      call self%set_body_force(s, self%state%force)
    end associate
  end subroutine drag_evaluate

  integer function drag_root_count(self) result(n)
    class(water_drag_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 2
  end function drag_root_count

  pure subroutine drag_roots(self, t, frames, scalars, contacts, g)
    class(water_drag_t), intent(in) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    real(wp), intent(out) :: g(:)
    associate (unused_t => t, unused_f => frames, unused_c => contacts)
    end associate
    call in_water_roots(self%water, scalars(self%var_u)%q, scalars(self%var_v)%q, g(1:2))
  end subroutine drag_roots

  !> A rising root: the contact enters the water; a falling one: it leaves.
  subroutine drag_handle_event(self, t, fired, action, status)
    class(water_drag_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    logical :: now_active
    associate (unused_t => t, unused_s => status)
    end associate
    action = EVENT_IGNORE
    if (all(fired(1:2) == 0)) return
    now_active = .not. any(fired(1:2) < 0)
    if (now_active .eqv. self%active) return
    self%active = now_active
    action = EVENT_RESTART
  end subroutine drag_handle_event
end module rider_water_drag
