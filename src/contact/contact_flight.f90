!> Flight: a body whose contact starts open (issue 25).
!>
!> The body flies free: it hangs from the ground by three prismatic joints
!> along the world axes (the origin of its frame) and a free rotation
!> (kinetostatics_free_rotation, its chart centred on the start pose), and
!> carries its mass element under gravity. Its coordinates are the origin
!> (x, y, z) and the rotation's angles, its speeds their rates: the state is
!> the pose and twist, continuous (the rotation's chart changes keep them).
!> A body with a drag_area feels the air's drag in flight as when closed
!> (contact_factory add_air_drag).
!>
!> The contact's gap (contact_gap: the signed distance of its two shapes
!> along their common normal) is recorded with every state and is a root
!> function: where it falls through zero the body lands. A flight that
!> starts touching (a lift-off: restart_flight) starts with the gap 0 and
!> its rate 0, and where the normal force fell to zero also its second
!> derivative 0 (the free and the closed motion have the same acceleration
!> there): the gap grows as s^3, below its rounding (~1e-16 m) for the first
!> ~1e-5 s, where its sign is noise (CVODE saw roots there, and a root at and
!> very near another: CV_ILL_INPUT). So until the gap has opened by
!> opening_gap the root is opening_gap - |gap|: nonzero at the start, it
!> falls to zero where the gap has clearly opened (the landing root is
!> watched from there on: the gap, opening_gap there) or where the body went
!> back into the surface by opening_gap without opening (a landing there). Without a
!> restitution the run ends there (exit status 0, the outcome says "landing"
!> with the approach speed). With one the landing is an impact
!> (kinetostatics_impact): K = rigid_body_delassus of the body's mass, its
!> inertia in world axes and the arm from its centre of mass to the contact
!> point, the impulse from resolve_impact with the contact's restitution and
!> impact mu, the body's twist changed by it (the pose kept), and the body
!> flies on (the integrator restarts). A rebound slower than close_speed
!> closes the contact: a further impulse takes away what is left of the
!> contact points' normal velocity (frictionless; at a rolling contact their
!> whole relative velocity), its energy added to the impact's row, and the
!> flight stops with `closing` set; contact_closing goes on with the closed
!> contact from there. Bounces that would never end (Zeno: rebounds e^k v0,
!> endless in number, their flights summing to a finite time) end so after
!> finitely many, where e^k v0 falls below close_speed.
!>
!> Only a single contact whose body_1 is the ground can start open (its
!> shape_1 fixed, at the ground's pose); its friction, rolling, level and
!> chain are the closed contact's after closing, so they need restitution
!> (without it the run ends at the landing and they would be unused);
!> anything else is refused.
module contact_flight
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use numerics_event_driver, only: EVENT_STOP, EVENT_RESTART
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_joints, only: new_prismatic
  use kinetostatics_free_rotation, only: new_free_rotation
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t, resolve_impact, rigid_body_delassus
  use base_vector, only: cross
  use base_series, only: resize
  use geometry_solid, only: solid_properties_t
  use contact_factory, only: body_from_spec, add_air_drag
  use contact_model, only: contact_system_t, contact_model_t, build_system_shapes, LEVEL_POSITION, CHAIN_AUTO
  use contact_gap, only: contact_gap_t, new_contact_gap
  implicit none (type, external)
  private
  public :: flight_ode_t, impact_record_t, build_flight, starts_open, restart_flight, touching_gap_limit

  real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  real(wp), parameter :: ground_origin(3) = 0
  !> m: how far a touching start (a lift-off, or a closed start that may
  !> open) may overlap: the gap left by the contact's closure and the lift-off
  !> root, ~1e-14 m; beyond it the pose is not a touching one and it fails.
  !> Also the most a closing may move the body to touch (contact_closing).
  real(wp), parameter :: touching_gap_limit = 1e-9_wp
  !> m: how far a flight that starts touching must open before its landing
  !> is watched (or go back in to land): far above the gap's rounding, and a
  !> tenth of touching_gap_limit, so that such a landing is within the
  !> closing's reach.
  real(wp), parameter :: opening_gap = 1e-10_wp

  !> One impact, for the result's table.
  type :: impact_record_t
    real(wp) :: time = 0                   ! s
    real(wp) :: normal_speed_before = 0    ! m/s, separation speed of the contact points (< 0: approaching)
    real(wp) :: normal_speed_after = 0     ! m/s
    real(wp) :: normal_impulse = 0         ! N s, on the body
    real(wp) :: tangential_impulse = 0     ! N s, its size
    real(wp) :: energy_lost = 0            ! J
  end type impact_record_t

  !> The free body as a model of the integration driver: the mechanism's own
  !> roots and events, and after them the contact's gap.
  type, extends(mechanism_ode_t) :: flight_ode_t
    type(contact_gap_t) :: gap
    character(len=:), allocatable :: contact_name
    integer :: body_frame = 0
    integer :: gap_monitor = 0     ! the gap's place among the recorded monitors
    real(wp) :: last_gap = 1       ! kept where an update fails (a trial state)
    logical :: touching = .false.  ! started touching, not yet opened by opening_gap (the root: opening_gap - |gap|)
    ! the impact law (bounces: has_impacts) and the body's mass properties (body axes)
    logical :: has_impacts = .false.
    type(impact_law_t) :: law
    real(wp) :: close_speed = 0
    real(wp) :: mass = 0, inertia(3, 3) = 0, centre(3) = 0
    type(impact_record_t), allocatable :: impacts(:)
    ! closing (contact_closing)
    type(contact_system_t) :: system          ! the description the closed contact is built from
    character(len=8), allocatable :: q_units(:), beta_units(:)   ! of the series' coordinates and dependents
    logical :: closing = .false.              ! the last impact closed the contact: the flight stopped there
    logical :: start_closed = .false.         ! the run starts with the closed contact (may_open: contact_closing)
    integer :: coordinates(6) = 0             ! scalars x, y, z, a1, a2, a3
    integer :: rotation_element = 0           ! the free rotation
    type(contact_model_t), allocatable :: closed   ! the closed contact after closing
    ! per record of the flight: the gap's point on shape_1 (m) and the body's
    ! nearest point's velocity relative to it along the surface (m/s), world
    real(wp), allocatable :: gap_point(:, :), gap_velocity(:, :)   ! (the velocity's tangential part)
  contains
    procedure :: root_count => flight_root_count
    procedure :: roots => flight_roots
    procedure :: handle_event => flight_handle_event
    procedure :: record => flight_record
  end type flight_ode_t

contains

  !> Whether any contact of the description starts open.
  logical function starts_open(system)
    type(contact_system_t), intent(in) :: system
    starts_open = any(system%contacts%start_open)
  end function starts_open

  !> The free body of `system`'s contact at its given pose and twist:
  !> q0 = (x, y, z, a1, a2, a3), qd0 their rates, q_units; refused unless the
  !> description is a single contact on the ground that starts open with the
  !> shapes apart (touching: a closed start that may open). Shapes given by
  !> their descriptions are built first (build_system_shapes, as for a
  !> closed start).
  subroutine build_flight(system, flight, q0, qd0, q_units, status, touching)
    type(contact_system_t), intent(in) :: system
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: touching   ! the body may touch shape_1 (a closed start that may open)
    type(contact_system_t) :: shaped
    if (.not. status%ok()) return
    call build_system_shapes(system, shaped, status)
    call build_shaped_flight(shaped, flight, q0, qd0, q_units, status, touching)
  end subroutine build_flight

  !> build_flight of a system whose shapes are built.
  subroutine build_shaped_flight(system, flight, q0, qd0, q_units, status, touching)
    type(contact_system_t), intent(in) :: system
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: touching   ! the body may touch shape_1 (a closed start that may open)
    character(len=*), parameter :: axis_name(3) = ['x', 'y', 'z']
    real(wp), parameter :: axes(3, 3) = identity
    type(solid_properties_t) :: props
    integer :: frames(4), coordinates(6), i, b
    if (.not. status%ok()) return
    ! the open one names the refusals (the first, if several are)
    associate (c => system%contacts(max(findloc(system%contacts%start_open, .true., dim=1), 1)), &
               m => flight%mechanism)
      if (size(system%contacts) /= 1 .or. size(system%bodies) /= 1 .or. c%body_1 /= 'ground') then
        call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': start = ''open'' and may_open '// &
          'are supported for a single contact between the ground and one body (flight and landing); '// &
          'this description has '//format_count(size(system%contacts))//' contacts and '// &
          format_count(size(system%bodies))//' bodies')
        return
      end if
      if (c%start_open .and. c%restitution < 0 .and. (allocated(c%friction%kind) .or. c%rolling .or. c%level /= LEVEL_POSITION &
                                   .or. c%chain /= CHAIN_AUTO)) then
        call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': friction, rolling, level and '// &
          'chain of a contact that starts open are the closed contact''s after its body lands and the contact '// &
          'closes, which needs restitution (without it the run ends at the landing: they would be unused); '// &
          'give restitution, or leave them out')
        return
      end if
      b = 1
      if (system%bodies(b)%name /= c%body_2) then
        call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': body_2 = '''//c%body_2// &
          ''' is not a body')
        return
      end if
      call body_from_spec(system%bodies(b), system%shapes, props, status)
      if (.not. status%ok()) return
      flight%contact_name = c%name
      flight%system = system
      flight%has_impacts = c%restitution >= 0
      flight%law = impact_law_t(restitution=max(c%restitution, 0.0_wp), mu=c%impact_mu)
      flight%close_speed = c%close_speed
      flight%mass = system%bodies(b)%mass
      flight%inertia = props%inertia
      flight%centre = props%centre
      allocate (flight%impacts(0))
      frames(1) = 1   ! the ground
      do i = 1, 3
        frames(i + 1) = m%add_frame(c%body_2//'.'//axis_name(i))
        coordinates(i) = m%add_scalar(c%body_2//'.'//axis_name(i), system%bodies(b)%position(i))
        call m%add_element(new_prismatic(c%body_2//'.'//axis_name(i), frames(i), frames(i + 1), coordinates(i), &
                                         axes(:, i)))
      end do
      do i = 1, 3
        coordinates(3 + i) = m%add_scalar(c%body_2//'.a'//achar(iachar('0') + i), 0.0_wp)
      end do
      flight%body_frame = m%add_frame(c%body_2)
      call m%add_element(new_free_rotation(c%body_2//'.rotation', frames(4), flight%body_frame, coordinates(4:6), &
                                           [0.0_wp, 0.0_wp, 1.0_wp], system%bodies(b)%rotation))
      flight%rotation_element = m%n_elements
      flight%coordinates = coordinates
      call m%add_element(new_mass_element(c%body_2, flight%body_frame, system%bodies(b)%mass, props%inertia, &
                                          props%centre, system%gravity, status))
      call add_air_drag(m, system%bodies(b), system%air_density, system%wind, flight%body_frame, props%centre, status)
      if (.not. status%ok()) return
      call m%add_monitor(m%add_scalar(c%name//'.gap'), 'm')
      flight%gap_monitor = size(m%monitors)
      call m%set_coordinates(coordinates)
      call m%finalize(status)
      if (.not. status%ok()) return
      q0 = m%scalars(coordinates)%q
      call m%set_positions(flight%work, q0, status)
      if (.not. status%ok()) return
      call start_rates(flight, [system%bodies(b)%angular_velocity, system%bodies(b)%velocity], qd0, status)
      if (.not. status%ok()) return
      q_units = [character(len=8) :: 'm', 'm', 'm', 'rad', 'rad', 'rad']
      flight%q_units = q_units
      allocate (flight%beta_units(0))
      call start_gap(flight, system, status, touching)
    end associate
  end subroutine build_shaped_flight

  !> The gap at the start, from the contact search; it must be open (> 0;
  !> touching: not below -touching_gap_limit) and on the contact's branch
  !> (the normals against each other).
  subroutine start_gap(flight, system, status, touching)
    type(flight_ode_t), intent(inout) :: flight
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: touching
    integer :: s1, s2, k
    logical :: may_touch
    may_touch = .false.
    if (present(touching)) may_touch = touching
    associate (c => system%contacts(1), body => flight%work%frames(flight%body_frame))
      s1 = findloc([(system%shapes(k)%name == c%shape_1, k = 1, size(system%shapes))], .true., dim=1)
      s2 = findloc([(system%shapes(k)%name == c%shape_2, k = 1, size(system%shapes))], .true., dim=1)
      flight%gap = new_contact_gap(system%shapes(s1)%surface, c%side_1, system%shapes(s2)%surface, c%side_2, &
                                   [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
      call flight%gap%start_from_search(identity, ground_origin, body%rot, body%r, status)
      if (.not. status%ok()) then
        status%message = 'contact '''//c%name//''': the gap between '''//c%shape_1//''' and '''//c%shape_2// &
                         ''' at the start: '//status%text()
        return
      end if
      if (.not. flight%gap%normals_cosine < 0) then
        call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': at the start the normals of '// &
          'shape_1 and shape_2 point the same way at their nearest points (side_1, side_2 as for a closed '// &
          'contact: each normal out of its body towards the other); check side_1 and side_2')
      else if (may_touch) then
        if (.not. flight%gap%gap >= -touching_gap_limit) call set_status(status, STATUS_DOMAIN, 'contact '''// &
          c%name//''': body '''//c%body_2//''' overlaps shape '''//c%shape_1//''' by '// &
          format_short(-flight%gap%gap)//' m where it should touch (more than '//format_short(touching_gap_limit)// &
          ' m)')
      else if (.not. flight%gap%gap > 0) then
        call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': start = ''open'' but body '''// &
          c%body_2//''' touches or overlaps shape '''//c%shape_1//''' at its start position (gap '// &
          format_short(flight%gap%gap)//' m); an open contact starts with its shapes apart (raise &body '// &
          'position, or start closed)')
      end if
      flight%last_gap = flight%gap%gap
    end associate
  end subroutine start_gap

  !> The free body placed again at `rotation` and `position` (its frame's
  !> axes and origin, world) with the twist [omega, v] (world; v of its
  !> origin): the prismatic coordinates the origin, the free rotation's
  !> angles 0 on a chart centred there, the rates solved for the twist; the
  !> gap from the contact search there, touching allowed (a lift-off). y: its
  !> state (contact_closing, a lift-off into flight).
  subroutine restart_flight(flight, rotation, position, twist, y, status)
    type(flight_ode_t), intent(inout) :: flight
    real(wp), intent(in) :: rotation(3, 3), position(3), twist(6)
    real(wp), allocatable, intent(out) :: y(:)
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: q0(:), qd0(:)
    integer :: i
    if (.not. status%ok()) return
    associate (m => flight%mechanism, work => flight%work)
      call m%prepare_workspace(work)
      do i = 1, 3
        work%scalars(flight%coordinates(i))%q = position(i)
        work%scalars(flight%coordinates(3 + i))%q = 0
      end do
      call work%elements(flight%rotation_element)%e%centre_chart(rotation)
      q0 = work%scalars(flight%coordinates)%q
      call m%set_positions(flight%work, q0, status)
      if (.not. status%ok()) return
      call start_rates(flight, twist, qd0, status)
      if (.not. status%ok()) return
      call start_gap(flight, flight%system, status, touching=.true.)
      if (.not. status%ok()) return
      flight%touching = .true.
      y = flight%initial_state(q0, qd0)
    end associate
  end subroutine restart_flight

  !> The rates of (x, y, z, a1, a2, a3) that give the body the twist
  !> [omega, v] (world; v of its frame's origin): the six columns of the
  !> body's twist per unit rate, solved (a free body: any twist is reached).
  subroutine start_rates(flight, twist, qd0, status)
    class(flight_ode_t), intent(inout) :: flight
    real(wp), intent(in) :: twist(6)
    real(wp), allocatable, intent(out) :: qd0(:)
    type(status_t), intent(inout) :: status
    real(wp) :: jac(6, 6), unit(6)
    integer :: k, ipiv(6)
    associate (m => flight%mechanism)
      do k = 1, 6
        unit = 0
        unit(k) = 1
        call m%set_velocities(flight%work, unit)
        jac(:, k) = [flight%work%frames(flight%body_frame)%omega, flight%work%frames(flight%body_frame)%v]
      end do
      qd0 = twist
      call lu_factor(jac, ipiv, status)
      if (status%ok()) call lu_solve(jac, ipiv, qd0, status)
      if (status%ok()) call m%set_velocities(flight%work, qd0)
    end associate
  end subroutine start_rates

  integer function flight_root_count(self) result(n)
    class(flight_ode_t), intent(in) :: self
    n = self%mechanism_ode_t%root_count() + 1
  end function flight_root_count

  !> The mechanism's roots, then the gap at the pose y gives (while the
  !> flight is touching: opening_gap - |gap|).
  subroutine flight_roots(self, t, y, g)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    integer :: n
    n = size(g) - 1
    call self%mechanism_ode_t%roots(t, y, g(1:n))
    g(n + 1) = gap_at(self, y)
    if (self%touching) g(n + 1) = opening_gap - abs(g(n + 1))
  end subroutine flight_roots

  !> The gap at the pose of y (the last value where it cannot be found: a
  !> trial state the integrator does not keep).
  real(wp) function gap_at(self, y) result(gap)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: y(:)
    type(status_t) :: status
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), status)
    if (status%ok()) call update_gap(self, status)
    if (status%ok()) self%last_gap = self%gap%gap
    gap = self%last_gap
  end function gap_at

  !> The gap at the mechanism's current pose.
  subroutine update_gap(self, status)
    class(flight_ode_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    associate (body => self%work%frames(self%body_frame))
      call self%gap%update(identity, ground_origin, body%rot, body%r, status)
    end associate
  end subroutine update_gap

  !> The mechanism's events, then the landing: the gap falling through zero
  !> is an impact (with a restitution) or ends the run. A touching flight's
  !> root: opened (the landing is watched from now on), or gone back in (a
  !> landing).
  subroutine flight_handle_event(self, t, y, fired, action, status)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    integer :: n, f
    real(wp) :: speed
    n = size(fired) - 1
    call self%mechanism_ode_t%handle_event(t, y, fired(1:n), action, status)
    if (.not. status%ok() .or. fired(n + 1) /= -1) return
    f = self%mechanism%f
    call self%mechanism%set_positions(self%work, y(1:f), status)
    if (.not. status%ok()) return
    call self%mechanism%set_velocities(self%work, y(f + 1:f + self%mechanism%ns))
    call update_gap(self, status)
    if (.not. status%ok()) return
    if (self%touching) then
      self%touching = .false.
      ! opened: the root is the gap from here (opening_gap, nonzero, where CVODE looks again)
      if (self%gap%gap > 0) return
    end if
    associate (body => self%work%frames(self%body_frame))
      speed = -self%gap%rate([0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], body%v, body%omega)
    end associate
    if (self%has_impacts) then
      call impact(self, t, y, action, status)
      return
    end if
    action = max(action, EVENT_STOP)
    call add_outcome(self, 'landing: the gap of contact '''//self%contact_name//''' fell to zero at t = '// &
                     format_short(t)//' s, approaching at '//format_short(speed)//' m/s (no restitution given: '// &
                     'the run ends at the landing)')
  end subroutine flight_handle_event

  !> The impact at the landing (the mechanism at y's pose and speeds, the gap
  !> updated): the impulse L on the body at its contact point, from K and the
  !> contact points' relative velocity; the body's centre of mass speeds up
  !> by L/m, its angular velocity by I^-1 (arm x L); its new twist becomes
  !> y's rates. A rebound below close_speed closes the contact (closing_impulse
  !> added to L) and stops the flight there.
  subroutine impact(self, t, y, action, status)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(inout) :: action
    type(status_t), intent(inout) :: status
    real(wp) :: inertia(3, 3), factored(3, 3), centre(3), arm(3), v_centre(3), omega(3), spin_change(3), k(3, 3)
    real(wp) :: impulse(3), closing(3), closing_lost, velocity_after(3)
    real(wp), allocatable :: rates(:)
    type(impact_outcome_t) :: outcome
    type(impact_record_t) :: row
    integer :: f, ipiv(3)
    logical :: closes
    f = self%mechanism%f
    associate (body => self%work%frames(self%body_frame), n => self%gap%normal)
      inertia = matmul(body%rot, matmul(self%inertia, transpose(body%rot)))
      centre = body%r + matmul(body%rot, self%centre)
      arm = self%gap%point_2 - centre
      k = rigid_body_delassus(self%mass, inertia, arm)
      ! the ground is the law's body 2: v is the body's contact point's velocity, n from the ground to it
      call resolve_impact(self%law, k, n, body%v + cross(body%omega, self%gap%point_2 - body%r), outcome, status)
      if (.not. status%ok()) return
      impulse = outcome%impulse
      velocity_after = outcome%velocity_after
      closing_lost = 0
      closes = outcome%normal_speed_after < self%close_speed
      if (closes) then
        call closing_impulse(k, n, outcome%velocity_after, self%system%contacts(1)%rolling, closing, status)
        if (.not. status%ok()) return
        velocity_after = outcome%velocity_after + matmul(k, closing)
        closing_lost = -dot_product(closing, outcome%velocity_after + velocity_after)/2
        impulse = impulse + closing
      end if
      factored = inertia
      spin_change = cross(arm, impulse)
      call lu_factor(factored, ipiv, status)
      if (status%ok()) call lu_solve(factored, ipiv, spin_change, status)
      if (.not. status%ok()) return
      v_centre = body%v + cross(body%omega, centre - body%r) + impulse/self%mass
      omega = body%omega + spin_change
      call start_rates(self, [omega, v_centre - cross(omega, centre - body%r)], rates, status)
      if (.not. status%ok()) return
      y(f + 1:f + self%mechanism%ns) = rates
      row = impact_record_t(time=t, normal_speed_before=outcome%normal_speed_before, &
                            normal_speed_after=dot_product(velocity_after, n), &
                            normal_impulse=dot_product(impulse, n), &
                            tangential_impulse=norm2(impulse - dot_product(impulse, n)*n), &
                            energy_lost=outcome%energy_lost + closing_lost)
    end associate
    self%impacts = [self%impacts, row]
    if (closes) then
      action = max(action, EVENT_STOP)
      self%closing = .true.
      call add_outcome(self, 'contact '''//self%contact_name//''' closed at the impact at t = '// &
                       format_short(t)//' s: the rebound, '//format_short(outcome%normal_speed_after)// &
                       ' m/s, is below close_speed')
    else
      action = max(action, EVENT_RESTART)
    end if
  end subroutine impact

  !> The impulse (on the body, N s) that closes a contact whose points move
  !> apart at v after the impact (relative velocity, world; K the Delassus
  !> matrix): it takes away their normal velocity n.v along n, frictionless,
  !> p = -(n.v)/(n.K n); at a rolling contact their whole relative velocity,
  !> K^-1 (-v) (the no-slip contact cannot start slipping). Either is a
  !> plastic impulse: it removes energy, -(P.(v + v'))/2 >= 0.
  subroutine closing_impulse(k, n, v, rolling, impulse, status)
    real(wp), intent(in) :: k(3, 3), n(3), v(3)
    logical, intent(in) :: rolling
    real(wp), intent(out) :: impulse(3)
    type(status_t), intent(inout) :: status
    real(wp) :: factored(3, 3)
    integer :: ipiv(3)
    if (rolling) then
      factored = k
      impulse = -v
      call lu_factor(factored, ipiv, status)
      if (status%ok()) call lu_solve(factored, ipiv, impulse, status)
    else
      impulse = -dot_product(n, v)/dot_product(n, matmul(k, n))*n
    end if
  end subroutine closing_impulse

  subroutine add_outcome(self, text)
    class(flight_ode_t), intent(inout) :: self
    character(len=*), intent(in) :: text
    if (len(self%outcome) > 0) self%outcome = self%outcome//'; '
    self%outcome = self%outcome//text
  end subroutine add_outcome

  !> The mechanism's record, with the gap at its pose, its point on shape_1
  !> and the body's nearest point's velocity along the surface (the slip it
  !> would have: the normal part is the gap's rate).
  subroutine flight_record(self, t, y, kind, status)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    integer :: n
    real(wp) :: v(3)
    call self%mechanism_ode_t%record(t, y, kind, status)
    if (.not. status%ok()) return
    ! the record's evaluate left the mechanism at y's pose and speeds
    call update_gap(self, status)
    if (.not. status%ok()) return
    n = self%series%n
    self%series%monitor(self%gap_monitor, n) = self%gap%gap
    if (.not. allocated(self%gap_point)) allocate (self%gap_point(3, 0), self%gap_velocity(3, 0))
    if (size(self%gap_point, 2) < n) then
      call resize(self%gap_point, 3, 2*n)
      call resize(self%gap_velocity, 3, 2*n)
    end if
    associate (body => self%work%frames(self%body_frame))
      self%gap_point(:, n) = self%gap%point_1
      v = body%v + cross(body%omega, self%gap%point_2 - body%r)
      self%gap_velocity(:, n) = v - dot_product(v, self%gap%normal)*self%gap%normal
    end associate
  end subroutine flight_record

  pure function format_count(n) result(text)
    integer, intent(in) :: n
    character(len=:), allocatable :: text
    character(len=12) :: buffer
    write (buffer, '(i0)') n
    text = trim(buffer)
  end function format_count
end module contact_flight
