!> State objects of the kinetostatic method (thesis 3.1) and the seam every
!> transmission element implements (thesis 3.2).
!>
!> A frame state holds, all in world (ground, K_0) coordinates: the orientation
!> R (columns = the frame's axes), the position r of its origin, the angular
!> velocity omega and linear velocity v of the origin, their time derivatives
!> alpha and a (thesis (3.1)), and the torque (about the origin) and force acting
!> there (the wrench of (3.2)). A scalar state holds a joint variable or a
!> measurement: value, rate, second rate and generalized force (for a measurement
!> the generalized force is its cut force lambda, thesis 3.1).
!>
!> An element maps its input states forward at position, velocity and
!> acceleration level ((3.3)-(3.5)) and pushes the forces of its outputs back to
!> its inputs with the transposed Jacobian ((3.7)); forces are *added* to the
!> inputs, so several elements can load one frame. Leaf elements (mass, force)
!> have no outputs and add forces only. The force pass can switch off inertia
!> (d'Alembert forces) and applied forces independently: this is what the f + 1
!> inverse-dynamics passes of thesis 3.4 need.
module kinetostatics_state
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  implicit none (type, external)
  private
  public :: frame_state_t, scalar_state_t, element_t, element_box_t, element_links_t, domain_edge_t, surface_chart_t
  public :: axis_rotation, rest_velocities

  type :: frame_state_t
    real(wp) :: rot(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])  ! columns x, y, z
    real(wp) :: r(3) = 0        ! m
    real(wp) :: omega(3) = 0    ! rad/s
    real(wp) :: v(3) = 0        ! m/s
    real(wp) :: alpha(3) = 0    ! rad/s^2
    real(wp) :: a(3) = 0        ! m/s^2
    real(wp) :: torque(3) = 0   ! N m, about the origin
    real(wp) :: force(3) = 0    ! N
  end type frame_state_t

  type :: scalar_state_t
    real(wp) :: q = 0      ! rad or m (measurements: their unit)
    real(wp) :: qd = 0     ! per s
    real(wp) :: qdd = 0    ! per s^2
    real(wp) :: force = 0  ! N m, N, or the cut force of a measurement
  end type scalar_state_t

  !> What an element reads and writes in its position, velocity and
  !> acceleration maps (its force map pushes back from the outputs to the
  !> same inputs), so that the mechanism can pass over only the elements a
  !> rate reaches (kinetostatics_closure_blocks). `carried`: the output
  !> frames move rigidly with the single input frame while the input scalars
  !> rest (a joint). `relative`: the output scalars do not change under a
  !> common rigid motion of the input frames (a measurement between two
  !> frames, a relative velocity). known = .false. (the default): unknown,
  !> the mechanism passes over every element.
  type :: element_links_t
    logical :: known = .false.
    integer, allocatable :: frames_in(:), scalars_in(:), frames_out(:), scalars_out(:)
    logical :: carried = .false.
    logical :: relative = .false.
  end type element_links_t

  !> A finite, non-periodic edge of the parameter domain of an element's
  !> surface (kinetostatics_surface_joint): its event is placed `margin`
  !> inside it (domain_edge_margin).
  type :: domain_edge_t
    integer :: scalar = 0                     ! the element's u or v
    real(wp) :: bound = 0                     ! the edge value
    real(wp) :: margin = 0                    ! the event's distance from it
    logical :: upper = .false.                ! bound is the maximum (else the minimum)
    logical :: along_u = .true.               ! an edge in u (else in v)
  end type domain_edge_t

  !> The surface an element carries, in the chart it is in (a surface with
  !> charts, kinetostatics_surface_joint "Charts"): the chart's surface, P
  !> (r = P r', the surface's own coordinates from the chart's) and the
  !> chart's name (surface_t's chart_toward; 0: its own chart). Handed from
  !> one element on a surface to another on the same surface (contact_pair).
  type :: surface_chart_t
    class(surface_t), allocatable :: surface   ! not allocated: the element carries no surface
    real(wp) :: rotation(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    integer :: index = 0
  end type surface_chart_t

  !> record_only: only records read the element's outputs (a monitor of the
  !> closure, contact_closure_monitor), nothing in the mechanism's dynamics
  !> does; the position pass skips it and the mechanism evaluates it for a
  !> complete state (kinetostatics_mechanism, record_pass). Its velocity,
  !> acceleration and force maps must leave everything alone.
  type, abstract :: element_t
    character(len=:), allocatable :: name
    logical :: record_only = .false.
  contains
    procedure :: links => element_links
    procedure(position_i), deferred :: position
    procedure(motion_i), deferred :: velocity
    procedure(motion_i), deferred :: acceleration
    procedure(force_i), deferred :: force
    procedure :: energy => element_energy
    procedure :: chart_angle => element_chart_angle
    procedure :: chart_margin => element_chart_margin
    procedure :: rebase => element_rebase
    procedure :: chart_changes => element_chart_changes
    procedure :: start_chart => element_start_chart
    procedure :: centre_chart => element_centre_chart
    procedure :: set_chart_turn => element_set_chart_turn
    procedure :: surface_chart => element_surface_chart
    procedure :: take_surface_chart => element_take_surface_chart
    !> queries of the mechanism's core (kinetostatics_mechanism): no element kind is named there
    procedure :: mass_frame => element_mass_frame
    procedure :: world_inertia => element_world_inertia
    procedure :: mass_properties => element_mass_properties
    procedure :: domain_edges => element_domain_edges
    procedure :: set_eager => element_set_eager
    procedure :: position_complete => element_position_complete
    procedure :: singular_note => element_singular_note
  end type element_t

  type :: element_box_t
    class(element_t), allocatable :: e
  end type element_box_t

  abstract interface
    !> Output positions from input positions; may store geometry for later levels.
    pure subroutine position_i(self, frames, scalars, status)
      import :: element_t, frame_state_t, scalar_state_t, status_t
      class(element_t), intent(inout) :: self
      type(frame_state_t), intent(inout) :: frames(:)
      type(scalar_state_t), intent(inout) :: scalars(:)
      type(status_t), intent(inout) :: status
    end subroutine position_i

    !> Velocity (or acceleration) level, after `position` at the same positions.
    pure subroutine motion_i(self, frames, scalars)
      import :: element_t, frame_state_t, scalar_state_t
      class(element_t), intent(inout) :: self
      type(frame_state_t), intent(inout) :: frames(:)
      type(scalar_state_t), intent(inout) :: scalars(:)
    end subroutine motion_i

    !> Adds J^T (output forces) to the inputs; leaves add their own forces.
    pure subroutine force_i(self, frames, scalars, inertia, applied)
      import :: element_t, frame_state_t, scalar_state_t
      class(element_t), intent(inout) :: self
      type(frame_state_t), intent(inout) :: frames(:)
      type(scalar_state_t), intent(inout) :: scalars(:)
      logical, intent(in) :: inertia, applied
    end subroutine force_i
  end interface

contains

  !> Kinetic and potential energy (J); zero unless the element carries mass.
  pure subroutine element_energy(self, frames, kinetic, potential)
    class(element_t), intent(in) :: self
    type(frame_state_t), intent(in) :: frames(:)
    real(wp), intent(out) :: kinetic, potential
    associate (unused => self, unused_frames => frames)
    end associate
    kinetic = 0
    potential = 0
  end subroutine element_energy

  !> Unknown links (see element_links_t).
  pure subroutine element_links(self, links)
    class(element_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    associate (unused => self)
    end associate
    links%known = .false.
    allocate (links%frames_in(0), links%scalars_in(0), links%frames_out(0), links%scalars_out(0))
  end subroutine element_links

  !> Elements with a chart of their own coordinates (a free rotation, an
  !> ellipsoid's inverse surface joint) return
  !> the scalar whose value decides when the chart must change (default 0: no
  !> chart). The mechanism's model watches chart_margin (positive inside the
  !> chart) as a root function and calls rebase at its zero, with positions and
  !> rates set; rebase keeps the motion and changes the coordinates' values and
  !> rates (kinetostatics_free_rotation).
  pure integer function element_chart_angle(self) result(k)
    class(element_t), intent(in) :: self
    associate (unused => self)
    end associate
    k = 0
  end function element_chart_angle

  pure real(wp) function element_chart_margin(self, angle) result(g)
    class(element_t), intent(in) :: self
    real(wp), intent(in) :: angle
    associate (unused => self, unused_a => angle)
    end associate
    g = 1
  end function element_chart_margin

  pure subroutine element_rebase(self, scalars)
    class(element_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (unused => self, unused_s => scalars)
    end associate
  end subroutine element_rebase

  !> How many times the element changed its chart so far (default 0).
  pure integer function element_chart_changes(self) result(n)
    class(element_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 0
  end function element_chart_changes

  !> At a placement at rest, before any closure: an element whose position
  !> lies at (or within the margin of) its chart's edge changes chart now
  !> (the rates of its coordinates set to zero; default: nothing to change).
  pure subroutine element_start_chart(self, scalars)
    class(element_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (unused => self, unused_s => scalars)
    end associate
  end subroutine element_start_chart

  !> Centres the chart of the element's own rotation coordinates on the
  !> relative rotation `relative` (R_in^T R_out where its coordinates are
  !> zero; kinetostatics_free_rotation; default: no such chart).
  pure subroutine element_centre_chart(self, relative)
    class(element_t), intent(inout) :: self
    real(wp), intent(in) :: relative(3, 3)
    associate (unused => self, unused_r => relative)
    end associate
  end subroutine element_centre_chart

  !> `turn`: the scalar of the turn about the element's output z that follows
  !> it and takes back its output frame's turn when its surface changes
  !> chart (kinetostatics_surface_joint "Charts"; default: no such change).
  pure subroutine element_set_chart_turn(self, turn)
    class(element_t), intent(inout) :: self
    integer, intent(in) :: turn
    associate (unused => self, unused_t => turn)
    end associate
  end subroutine element_set_chart_turn

  !> The surface the element carries, in its current chart (default: none,
  !> chart%surface not allocated).
  pure subroutine element_surface_chart(self, chart)
    class(element_t), intent(in) :: self
    type(surface_chart_t), intent(out) :: chart
    associate (unused => self, unused_c => chart)
    end associate
  end subroutine element_surface_chart

  !> Takes the chart of the same surface from another element (`chart`
  !> and the number of its changes, `changes`), before a run (default:
  !> nothing to take).
  pure subroutine element_take_surface_chart(self, chart, changes)
    class(element_t), intent(inout) :: self
    type(surface_chart_t), intent(in) :: chart
    integer, intent(in) :: changes
    associate (unused => self, unused_c => chart, unused_n => changes)
    end associate
  end subroutine element_take_surface_chart

  !> The frame whose body the element's mass belongs to (default 0: the
  !> element carries no mass; kinetostatics_mass).
  pure integer function element_mass_frame(self) result(frame)
    class(element_t), intent(in) :: self
    associate (unused => self)
    end associate
    frame = 0
  end function element_mass_frame

  !> The mass m, the centre of mass s from the mass frame's origin and the
  !> inertia tensor Theta_w about it, in world coordinates at the last
  !> position (the mass matrix from the partial twists); zero without mass.
  pure subroutine element_world_inertia(self, mass, s, inertia_w)
    class(element_t), intent(inout) :: self
    real(wp), intent(out) :: mass, s(3), inertia_w(3, 3)
    associate (unused => self)
    end associate
    mass = 0
    s = 0
    inertia_w = 0
  end subroutine element_world_inertia

  !> The mass m, the centre of mass c and the inertia tensor Theta about it
  !> (both in the mass frame's coordinates) and the gravity g acting on it
  !> (world), as given; zero without mass.
  pure subroutine element_mass_properties(self, mass, com, inertia, gravity)
    class(element_t), intent(in) :: self
    real(wp), intent(out) :: mass, com(3), inertia(3, 3), gravity(3)
    associate (unused => self)
    end associate
    mass = 0
    com = 0
    inertia = 0
    gravity = 0
  end subroutine element_mass_properties

  !> The finite, non-periodic edges of the element's parameter domain, in
  !> the order u_min, u_max, v_min, v_max (default: none).
  pure subroutine element_domain_edges(self, edges)
    class(element_t), intent(in) :: self
    type(domain_edge_t), allocatable, intent(out) :: edges(:)
    associate (unused => self)
    end associate
    allocate (edges(0))
  end subroutine element_domain_edges

  !> Every position pass of the element is followed by a velocity pass at
  !> the same positions: an element that computes its geometry lazily, as
  !> far as the position asks, computes all of it at once (the same numbers
  !> either way; default: nothing to change).
  pure subroutine element_set_eager(self)
    class(element_t), intent(inout) :: self
    associate (unused => self)
    end associate
  end subroutine element_set_eager

  !> The position map where a velocity pass at the same positions is known
  !> to follow (the closure's last Newton iterate): an element that computes
  !> its geometry lazily computes all of it now, not first the part the
  !> position needs and then the whole again (the same numbers either way;
  !> default: the position map).
  pure subroutine element_position_complete(self, frames, scalars, status)
    class(element_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    call self%position(frames, scalars, status)
  end subroutine element_position_complete

  !> For a run that fails by its step count: a note when the element's
  !> contact point lies near a singular point of its surface's
  !> parametrisation, where the rates grow without bound (default: none).
  function element_singular_note(self) result(text)
    class(element_t), intent(in) :: self
    character(len=:), allocatable :: text
    associate (unused => self)
    end associate
    text = ''
  end function element_singular_note

  !> Rotation by `angle` (rad) about the unit vector e (Rodrigues).
  pure function axis_rotation(e, angle) result(r)
    real(wp), intent(in) :: e(3), angle
    real(wp) :: r(3, 3), c, s, k(3, 3)
    integer :: i
    c = cos(angle)
    s = sin(angle)
    ! the cross-product matrix [e]x element by element (a reshape of a
    ! non-constant array is a library call: the revolute's position map is hot)
    k(:, 1) = [0.0_wp, e(3), -e(2)]
    k(:, 2) = [-e(3), 0.0_wp, e(1)]
    k(:, 3) = [e(2), -e(1), 0.0_wp]
    r = s*k + (1 - c)*matmul(k, k)
    do i = 1, 3
      r(i, i) = r(i, i) + 1
    end do
  end function axis_rotation

  !> Every velocity at rest: the frames' (omega, v), the scalars' rates.
  pure subroutine rest_velocities(frames, scalars)
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer :: k
    do k = 1, size(frames)
      frames(k)%omega = 0
      frames(k)%v = 0
    end do
    scalars%qd = 0
  end subroutine rest_velocities
end module kinetostatics_state
