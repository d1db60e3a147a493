!> The force-law seam: every applied load of a mechanism other than gravity
!> (which stays in the mass elements, kinetostatics_mass) is a force law.
!>
!> A law is evaluated with the state of a workspace after the position and
!> velocity passes — the time t, every frame (positions, velocities), every
!> scalar (joint variables and their rates) and every contact's kinematics
!> (kinetostatics_contact: point, normal, slip velocity) — and fills its
!> `loads`: wrenches (force, and torque about the frame's origin, world
!> coordinates) at frames of the mechanism. The mechanism adds them to the
!> frames in its force passes, so they reach the generalized forces through the
!> transposed Jacobians, and it computes the law's power sum(f.v + tau.omega)
!> over the loaded frames, whose integral is the law's work.
!>
!> Two kinds:
!>   explicit  (scaled = .false.) the loads depend on (t, q, q') only. Laws
!>             must not read normal forces: they are unknown while the
!>             accelerations are solved (a workspace's normal_force is the value of
!>             the previous complete evaluation);
!>   scaled    (scaled = .true.) the load is |N_c| times what `evaluate`
!>             returns, N_c the normal force of the law's contact (Coulomb
!>             friction: the unit load -mu w/|w|). The mechanism solves N and
!>             q'' together, exactly (kinetostatics_mechanism).
!>
!> Events: a law may own root functions (`root_count`, `roots`, evaluated at
!> the same state as `evaluate`) and decide at a root what happens
!> (`handle_event`): switch itself on or off (`active`) and ask the driver to
!> restart the integrator (EVENT_RESTART of numerics_event_driver), record,
!> ignore, or stop. An inactive law has no loads and no power.
!>
!> To write a law outside this layer (the rider's water drag, the contact
!> layer's laws): extend `force_law_t` (or `contact_law_t` for a load at a
!> contact), allocate `loads` in its constructor with a fixed size, and
!> implement `evaluate`; add it with mechanism%add_law. A friction law whose
!> force is a function of the tangential slip and the normal force alone
!> extends `friction_law_t` and writes only that function (`slip_force`):
!> it then acts in every mechanism and on the point mass alike. A kind that
!> inputs can name is described by a `force_law_kind_t` (its parameters and
!> its builder) and registered with the factory
!> (kinetostatics_force_law_factory; docs/DESIGN.md, "How to add a force law").
module kinetostatics_force_law
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_status, only: status_t
  use base_spec, only: spec_t
  use base_kind_registry, only: kind_t
  use numerics_event_driver, only: EVENT_IGNORE
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_contact, only: contact_state_t
  implicit none (type, external)
  private
  public :: frame_load_t, force_law_t, force_law_box_t, contact_law_t, friction_law_t
  public :: force_law_kind_t, law_place_t, build_law_i, force_at, set_interaction

  !> A wrench at a frame's origin, world coordinates.
  type :: frame_load_t
    integer :: frame = 1
    real(wp) :: force(3) = 0     ! N
    real(wp) :: torque(3) = 0    ! N m, about the frame's origin
  end type frame_load_t

  type, abstract :: force_law_t
    character(len=:), allocatable :: name
    logical :: active = .true.
    integer :: contact = 0       ! the contact the law acts at (0: none)
    logical :: scaled = .false.  ! loads per unit |N| of `contact` (see the module comment)
    type(frame_load_t), allocatable :: loads(:)   ! fixed size, set by the constructor
  contains
    procedure(law_evaluate_i), deferred :: evaluate
    procedure :: root_count => law_root_count
    procedure :: roots => law_roots
    procedure :: handle_event => law_handle_event
  end type force_law_t

  type :: force_law_box_t
    class(force_law_t), allocatable :: law
  end type force_law_box_t

  !> A law whose load acts at a contact point: on body B, and (for an
  !> interaction of the two bodies) the opposite load on body A. loads(1) is
  !> the load on B, loads(2) the one on A.
  type, abstract, extends(force_law_t) :: contact_law_t
  contains
    procedure, non_overridable :: set_up_contact_law, set_contact_force, set_body_force
  end type contact_law_t

  !> A friction law at a contact: F(w_t, N) on body B, -F on body A, with w_t
  !> the tangential slip and N the normal force (a scaled law is |N| times
  !> what slip_force gives for N = 1; a law that is not scaled must not read
  !> N). `slip_force` is the law; `evaluate` applies it at the mechanism's
  !> contact; a model that is not a mechanism (the point mass) calls
  !> slip_force with its own slip and normal force.
  type, abstract, extends(contact_law_t) :: friction_law_t
  contains
    procedure(slip_force_i), deferred :: slip_force
    !> the same for every friction law (not non_overridable: gfortran 12
    !> then dispatches the type's other bindings wrongly)
    procedure :: evaluate => friction_evaluate
  end type friction_law_t

  !> Where a law built from a spec acts: its name, the contact (index from
  !> mechanism%add_contact; 0 for a model without a mechanism) and the weight
  !> M g of the body the contact carries (N; for laws per weight).
  type :: law_place_t
    character(len=:), allocatable :: name
    integer :: contact = 0
    real(wp) :: weight = 0
  end type law_place_t

  !> A kind of force law that inputs name: a kind_t (base_kind_registry: its
  !> name, meaning and parameters, declared once: the reader's checks and the
  !> factory's come from them) with its builder.
  type, extends(kind_t) :: force_law_kind_t
    procedure(build_law_i), pointer, nopass :: build => null()
  end type force_law_kind_t

  abstract interface
    !> Builds the law of a completed spec (every parameter set and in range).
    subroutine build_law_i(spec, place, law, status)
      import :: spec_t, law_place_t, force_law_t, status_t
      type(spec_t), intent(in) :: spec
      type(law_place_t), intent(in) :: place
      class(force_law_t), allocatable, intent(out) :: law
      type(status_t), intent(inout) :: status
    end subroutine build_law_i

    !> The force on body B (N) for the tangential slip `slip` (m/s) and the
    !> normal force `normal_force` (N).
    pure function slip_force_i(self, slip, normal_force) result(force)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self
      real(wp), intent(in) :: slip(3), normal_force
      real(wp) :: force(3)
    end function slip_force_i

    !> Fills self%loads at the state given (a scaled law: per unit |N|).
    pure subroutine law_evaluate_i(self, t, frames, scalars, contacts, status)
      import :: force_law_t, wp, frame_state_t, scalar_state_t, contact_state_t, status_t
      class(force_law_t), intent(inout) :: self
      real(wp), intent(in) :: t
      type(frame_state_t), intent(in) :: frames(:)
      type(scalar_state_t), intent(in) :: scalars(:)
      type(contact_state_t), intent(in) :: contacts(:)
      type(status_t), intent(inout) :: status
    end subroutine law_evaluate_i
  end interface

contains

  !> Number of root functions of the law; none by default.
  integer function law_root_count(self) result(n)
    class(force_law_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 0
  end function law_root_count

  !> Root functions g(1:root_count) at the state given (as for evaluate).
  pure subroutine law_roots(self, t, frames, scalars, contacts, g)
    class(force_law_t), intent(in) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    real(wp), intent(out) :: g(:)
    associate (unused => self, unused_t => t, unused_f => frames, unused_s => scalars, unused_c => contacts)
    end associate
    g = 1
  end subroutine law_roots

  !> At a root of the law's functions (fired(i) = +1 rising, -1 falling, 0 not
  !> this one): change the law and say what the driver does (EVENT_*).
  subroutine law_handle_event(self, t, fired, action, status)
    class(force_law_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t, unused_f => fired, unused_s => status)
    end associate
    action = EVENT_IGNORE
  end subroutine law_handle_event

  !> The law at the mechanism's contact: w_t the slip's tangential part (its
  !> normal part vanishes while the contact holds; projecting keeps the
  !> friction exactly tangential), per unit |N| (N = 1).
  pure subroutine friction_evaluate(self, t, frames, scalars, contacts, status)
    class(friction_law_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    real(wp) :: w(3)
    associate (unused_t => t, unused_f => frames, unused_s => scalars, unused_st => status)
    end associate
    associate (s => contacts(self%contact))
      w = s%slip - dot_product(s%slip, s%normal)*s%normal
      call self%set_contact_force(s, self%slip_force(w, 1.0_wp))
    end associate
  end subroutine friction_evaluate

  !> For constructors: name, contact index (from mechanism%add_contact), kind, two loads.
  pure subroutine set_up_contact_law(self, name, contact, scaled)
    class(contact_law_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: contact
    logical, intent(in) :: scaled
    self%name = name
    self%contact = contact
    self%scaled = scaled
    if (allocated(self%loads)) deallocate (self%loads)
    allocate (self%loads(2))
  end subroutine set_up_contact_law

  !> An interaction of the two bodies: force F on B at the contact point, -F on A.
  pure subroutine set_contact_force(self, s, force)
    class(contact_law_t), intent(inout) :: self
    type(contact_state_t), intent(in) :: s
    real(wp), intent(in) :: force(3)
    call set_interaction(self%loads, s%frame_b, s%arm_b, s%frame_a, s%arm_a, force)
  end subroutine set_contact_force

  !> A load from outside the two bodies (e.g. water drag): F on B at the contact point only.
  pure subroutine set_body_force(self, s, force)
    class(contact_law_t), intent(inout) :: self
    type(contact_state_t), intent(in) :: s
    real(wp), intent(in) :: force(3)
    self%loads(1) = force_at(s%frame_b, s%arm_b, force)
    self%loads(2) = frame_load_t(s%frame_a, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp])
  end subroutine set_body_force

  !> The load of the force `force` (N, world) at the point `arm` (m, world)
  !> from the origin of frame `frame`: the force and its moment about the
  !> origin, arm x force.
  pure function force_at(frame, arm, force) result(load)
    integer, intent(in) :: frame
    real(wp), intent(in) :: arm(3), force(3)
    type(frame_load_t) :: load
    load = frame_load_t(frame, force, cross(arm, force))
  end function force_at

  !> An interaction: `force` on frame_b at arm_b (loads(1)), its reaction on
  !> frame_a at arm_a (loads(2)).
  pure subroutine set_interaction(loads, frame_b, arm_b, frame_a, arm_a, force)
    type(frame_load_t), intent(inout) :: loads(:)
    integer, intent(in) :: frame_b, frame_a
    real(wp), intent(in) :: arm_b(3), arm_a(3), force(3)
    loads(1) = force_at(frame_b, arm_b, force)
    loads(2) = frame_load_t(frame_a, -force, -cross(arm_a, force))
  end subroutine set_interaction
end module kinetostatics_force_law
