!> Flight: bodies whose contacts are open (issue 25).
!>
!> Each body flies free, hung from the ground by three prismatic joints along
!> the world axes (its frame's origin) and a free rotation (kinetostatics_free_rotation,
!> chart centred on the start pose), its mass element under gravity: the state, the
!> origin, the rotation's angles and their rates, is the pose and twist, continuous
!> across chart changes. A drag_area gives the air's drag as when closed (add_air_drag).
!>
!> The body may have several contacts with the ground: the surfaces it may
!> land on (a dome and the floor below it). The gap of each (contact_open_gaps:
!> the signed distance of its two shapes along their common normal) is
!> recorded with every state (<contact>.gap) and is a root function: where
!> one falls through zero the body lands on that contact. A flight that
!> starts touching a contact (a lift-off from it) watches that contact's
!> opening first (contact_open_gaps, opening_gap). Without a restitution
!> the run ends at the landing (exit status 0, the outcome says "landing"
!> with the approach speed). With one the landing is an impact
!> (contact_body_impact collide): K of the pair at the contact point (the
!> body's rigid_body_delassus from its mass, its inertia in world axes and
!> the arm from its centre of mass to the contact point; the ground adds
!> nothing), the impulse from resolve_impact with that contact's restitution
!> and impact mu, the body's twist changed by it (the pose kept), and the
!> body flies on (the integrator restarts). A rebound slower than the
!> contact's close_speed closes it: a further impulse takes away what is
!> left of the contact points' normal velocity (frictionless; at a rolling
!> contact their whole relative velocity), its energy added to the impact's
!> row, and the flight stops with `landed` set to that contact;
!> contact_closing goes on with it closed from there. Bounces that would
!> never end (Zeno: rebounds e^k v0, endless in number, their flights summing
!> to a finite time) end so after finitely many, where e^k v0 falls below
!> close_speed. A body landing on several contacts at once (a ball into a
!> V, on the floor and another body) is one impact at all of the event's
!> contacts (impact_at_once: contact_body_impact collide_at_once, Newton's
!> restitution at each, Coulomb's impact_mu on the velocities after, from
!> the Delassus matrix of the contacts); those it leaves slower than their
!> close_speed close together (contact_body_impact close_at_once) and the
!> flight stops there with `closings` set to them (contact_closing goes on
!> with the body on them all: contact_loops); without restitution the run
!> ends there, saying so.
!>
!> Several bodies may fly at once (one mechanism: each body its own six
!> coordinates, its gaps at its own pose, its impacts changing its own
!> twist only; landings of different bodies at the same instant are
!> impacts one after the other), and beside bodies carried by closed
!> contacts (contact_bodies builds such a flight: the mechanism of the
!> closed contacts with the flying bodies free, the closed contacts' gaps
!> not watched): a closing stops the flight there as for one body, and
!> contact_closing (drive_bodies) goes on with that body carried, the others
!> as they were. A carried body landing on another surface is one impact
!> through its carrying contacts too (impact_on_carried, in the submodule
!> contact_flight_impacts with impact_at_once): the phase stops there and
!> contact_closing goes on with the body's twist after it.
!>
!> Bodies hit each other: a contact between two bodies (body_1 a body, its
!> shape_1 on body_1's frame) that starts open is watched as the ground's
!> are, its gap at both bodies' poses; its landing is an impact of the
!> pair (contact_body_impact: K = K_1 + K_2, +L on body_2, -L on body_1, the
!> pair's momentum kept) while both fly, and the bodies fly on. A hit on a
!> body that closed contacts carry or join to others is one impact at the
!> hit and every closed contact of the bodies they join (impact_on_carried).
!> A rebound below its close_speed at a hit on a body of closed contacts
!> closes the contact: body_1 carries body_2 from there (contact_bodies,
!> contact_model: body_2 on body_1 by the open chain), and with may_open it
!> opens again where its normal force falls to zero; between two flying
!> bodies it ends the run (not built: their contact would press with
!> nothing).
!>
!> Contacts open and close between the ground and a body (each shape_1
!> fixed, at the ground's pose) and between two bodies; those that start
!> closed carry their bodies (several of one body together:
!> contact_loops); the friction, rolling, level and chain of a contact that
!> starts open are the closed contact's after closing, so they need
!> restitution (without it the run ends at the landing and they would be
!> unused). A contact between two bodies closes at position level:
!> sliding by the open chain, with its friction law if it has one (on the
!> tangential slip of the two bodies' material points), or rolling by the
!> loop (its closing takes away the whole relative velocity); it has no
!> level or chain (not built); anything else is refused.
!>
!> The flight's construction (the checks, the free bodies, a restart, a
!> twist's rates) is in the submodule contact_flight_build.
module contact_flight
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t
  use numerics_event_driver, only: EVENT_STOP, EVENT_RESTART
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_NOT_BUILT
  use kinetostatics_impact, only: impact_law_t
  use contact_model, only: contact_system_t, contact_model_t
  use contact_open_gaps, only: open_gaps_t
  use contact_body_impact, only: impact_body_t, collision_t, collide, collide_at_once, close_at_once, centre_speed
  implicit none (type, external)
  private
  public :: flight_ode_t, impact_record_t, build_flight, starts_open, restart_flight, check_flight_system, &
    closed_part, carrying_contact, impact_on_carried

  !> One impact, for the result's table.
  type :: impact_record_t
    real(wp) :: time = 0                   ! s
    integer :: contact = 1                 ! the contact landed on: its place among the &contact groups
    integer :: body_1 = 0, body_2 = 1      ! its bodies: their places among the &body groups (0: the ground)
    real(wp) :: normal_speed_before = 0    ! m/s, separation speed of the contact points (< 0: approaching)
    real(wp) :: normal_speed_after = 0     ! m/s
    real(wp) :: normal_impulse = 0         ! N s, on the body
    real(wp) :: tangential_impulse = 0     ! N s, its size
    real(wp) :: energy_lost = 0            ! J
    real(wp) :: speed_before(2) = 0        ! m/s, body_1's and body_2's centre of mass before it (0: the ground)
    !> the phase stopped before the impact's velocities were taken: the
    !> record at its time holds the state before it, the next phase's first
    !> record (at the same time) the state after (impact_on_carried)
    logical :: after_switch = .false.
  end type impact_record_t

  !> The free body as a model of the integration driver: the mechanism's own
  !> roots and events, and after them the contacts' gaps.
  type, extends(mechanism_ode_t) :: flight_ode_t
    type(open_gaps_t) :: gaps                 ! of every contact
    integer, allocatable :: body_frame(:)     ! each body's frame (the &body groups' order)
    integer, allocatable :: gap_monitors(:)   ! each contact's gap's place among the recorded monitors
    ! each body's mass properties (body axes), for the impacts
    real(wp), allocatable :: mass(:), inertia(:, :, :), centre(:, :)   ! kg; 3 x 3 x bodies, kg m^2; 3 x bodies, m
    type(impact_record_t), allocatable :: impacts(:)
    ! closing (contact_closing)
    type(contact_system_t) :: system          ! the description the closed contact is built from
    character(len=8), allocatable :: q_units(:), beta_units(:)   ! of the series' coordinates and dependents
    integer :: landed = 0                     ! the contact the last impact closed: the flight stopped there (0: none)
    integer :: closed_on = 0                  ! the contact of `closed` (contact_closing)
    logical :: start_closed = .false.         ! the run starts with the closed contact (contact_closing)
    integer, allocatable :: coordinates(:, :)   ! 6 x bodies: each body's scalars x, y, z, a1, a2, a3
    integer, allocatable :: speeds(:, :)        ! 6 x bodies: the places of their rates among the speeds
    ! several bodies, each carried by a closed contact or flying (contact_bodies)
    integer, allocatable :: mechanism_contact(:)   ! each contact's place among the mechanism's (0: open)
    integer, allocatable :: closings(:)         ! the contacts the impacts of the last event closed
    ! an impact on a carried body (impact_on_carried) stops the phase with:
    integer, allocatable :: openings(:)         ! the closed contacts it opened
    integer, allocatable :: bounced(:)          ! the contacts at gap 0 it left open
    logical, allocatable :: twisted(:)          ! each body: its twist changed by it, twist_after
    real(wp), allocatable :: twist_after(:, :)  ! 6 x bodies: [omega, v] (world; v of its origin)
    integer, allocatable :: rotation_element(:)   ! each body's free rotation
    type(contact_model_t), allocatable :: closed   ! the closed contact after closing
    ! per record of the flight and contact: the gap's point on shape_1 (m)
    ! and the body's nearest point's velocity relative to it along the
    ! surface (m/s, the velocity's tangential part), world; 3 x contacts x records
    real(wp), allocatable :: gap_point(:, :, :), gap_velocity(:, :, :)
  contains
    procedure :: clear_switches
    procedure :: root_count => flight_root_count
    procedure :: roots => flight_roots
    procedure :: handle_event => flight_handle_event
    procedure :: record => flight_record
  end type flight_ode_t

  !> The flight's construction (contact_flight_build): the description's
  !> check, the free bodies, a restart at a pose and twist, the rates of a twist.
  interface
    module subroutine check_flight_system(system, status)
      type(contact_system_t), intent(in) :: system
      type(status_t), intent(inout) :: status
    end subroutine check_flight_system
    module subroutine build_flight(system, flight, q0, qd0, q_units, status, touching)
      type(contact_system_t), intent(in) :: system
      type(flight_ode_t), intent(out) :: flight
      real(wp), allocatable, intent(out) :: q0(:), qd0(:)
      character(len=8), allocatable, intent(out) :: q_units(:)
      type(status_t), intent(inout) :: status
      integer, intent(in), optional :: touching   ! the contact the body may touch (a closed start that may open)
    end subroutine build_flight
    module subroutine restart_flight(flight, rotation, position, twist, y, status)
      type(flight_ode_t), intent(inout) :: flight
      real(wp), intent(in) :: rotation(3, 3), position(3), twist(6)
      real(wp), allocatable, intent(out) :: y(:)
      type(status_t), intent(inout) :: status
    end subroutine restart_flight
    module subroutine start_rates(flight, b, twist, rates, status)
      class(flight_ode_t), intent(inout) :: flight
      integer, intent(in) :: b
      real(wp), intent(in) :: twist(6)
      real(wp), intent(inout) :: rates(:)
      type(status_t), intent(inout) :: status
    end subroutine start_rates
    ! the impacts of several contacts (contact_flight_impacts)
    module function landed_names(self, lands) result(text)
      class(flight_ode_t), intent(in) :: self
      logical, intent(in) :: lands(:)
      character(len=:), allocatable :: text
    end function landed_names

    module subroutine impact_at_once(self, lands, t, y, action, status)
      class(flight_ode_t), intent(inout) :: self
      logical, intent(in) :: lands(:)
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: y(:)
      integer, intent(inout) :: action
      type(status_t), intent(inout) :: status
    end subroutine impact_at_once

    module subroutine impact_on_carried(self, lands, t, action, status)
      class(flight_ode_t), intent(inout) :: self
      logical, intent(in) :: lands(:)
      real(wp), intent(in) :: t
      integer, intent(inout) :: action
      type(status_t), intent(inout) :: status
    end subroutine impact_on_carried

    !> not_built: a stop the model cannot go on from; drive_flight fails the run there (exit 2, records kept)
    module subroutine add_outcome(self, text, not_built)
      class(flight_ode_t), intent(inout) :: self
      character(len=*), intent(in) :: text
      logical, intent(in), optional :: not_built
    end subroutine add_outcome

    module function impact_body(self, b) result(body)
      class(flight_ode_t), intent(in) :: self
      integer, intent(in) :: b
      type(impact_body_t) :: body
    end function impact_body
  end interface

contains

  !> A phase's switches cleared: no closing, opening or impact on a
  !> carried body yet (each body's twist its own).
  subroutine clear_switches(self)
    class(flight_ode_t), intent(inout) :: self
    self%landed = 0
    self%closings = [integer ::]
    self%openings = [integer ::]
    self%bounced = [integer ::]
    self%twisted = spread(.false., 1, size(self%body_frame))
    if (.not. allocated(self%twist_after)) allocate (self%twist_after(6, size(self%body_frame)))
    self%twist_after = 0
  end subroutine clear_switches

  !> Whether any contact of the description starts open.
  logical function starts_open(system)
    type(contact_system_t), intent(in) :: system
    starts_open = any(system%contacts%start_open)
  end function starts_open

  !> The contact that carries the body at the start: the one not open (0: all open).
  pure integer function carrying_contact(system) result(k)
    type(contact_system_t), intent(in) :: system
    k = findloc(system%contacts%start_open, .false., dim=1)
  end function carrying_contact

  !> `system` with its contact k only, closed: the model of the body while k
  !> carries it (contact_model builds one contact per body).
  function closed_part(system, k) result(part)
    type(contact_system_t), intent(in) :: system
    integer, intent(in) :: k
    type(contact_system_t) :: part
    part = system
    part%contacts = [system%contacts(k)]
    part%contacts(1)%start_open = .false.
  end function closed_part

  integer function flight_root_count(self) result(n)
    class(flight_ode_t), intent(in) :: self
    n = self%mechanism_ode_t%root_count() + size(self%gaps%gap)
  end function flight_root_count

  !> The mechanism's roots, then each contact's gap at the pose y gives
  !> (contact_open_gaps roots).
  subroutine flight_roots(self, t, y, g)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    integer :: n
    type(status_t) :: status
    n = size(g) - size(self%gaps%gap)
    call self%mechanism_ode_t%roots(t, y, g(1:n))
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), status)
    call self%gaps%roots(self%work, self%body_frame, status%ok(), g(n + 1:))
  end subroutine flight_roots

  !> The mechanism's events, then landings: a contact's gap falling through
  !> zero is an impact (with its restitution) or ends the run. Landings of
  !> different bodies at once are independent impacts, one after the other;
  !> several of one body at once (with those within together_gap, closing)
  !> are one impact at all of them (impact_at_once). The
  !> touching contact's root: opened (its landing is watched from now on),
  !> or gone back in (a landing on it).
  subroutine flight_handle_event(self, t, y, fired, action, status)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    integer :: n, f, c, b
    logical, allocatable :: lands(:)
    real(wp) :: speed
    n = size(fired) - size(self%gaps%gap)
    call self%mechanism_ode_t%handle_event(t, y, fired(1:n), action, status)
    lands = fired(n + 1:) == -1
    if (.not. status%ok() .or. .not. any(lands)) return
    f = self%mechanism%f
    call self%mechanism%set_positions(self%work, y(1:f), status)
    if (.not. status%ok()) return
    call self%mechanism%set_velocities(self%work, y(f + 1:f + self%mechanism%ns))
    call self%gaps%update(self%work, self%body_frame, status)
    if (.not. status%ok()) return
    do c = 1, size(lands)
      ! a touching contact opened: the root is the gap from here (opening_gap, nonzero, where CVODE looks again)
      if (lands(c) .and. self%gaps%touching(c)) lands(c) = .not. self%gaps%opened(c)
    end do
    lands = self%gaps%together(lands, self%work, self%body_frame, self%system%contacts%close_speed)
    do c = 1, size(lands)
      if (.not. lands(c)) cycle
      if (.not. (of_closed(self%gaps%body(c)) .or. of_closed(self%gaps%body_1(c)))) cycle
      ! an impact through the closed contacts of a body: one that lands, or is hit, or hits (impact_on_carried)
      call impact_on_carried(self, lands, t, action, status)
      return
    end do
    do b = 1, size(self%body_frame)
      if (count(lands .and. (self%gaps%body == b .or. self%gaps%body_1 == b)) > 1) then
        ! a body on several contacts at once: one impact at all of this event's
        call impact_at_once(self, lands, t, y, action, status)
        return
      end if
    end do
    do c = 1, size(lands)
      if (.not. lands(c)) cycle
      if (self%system%contacts(c)%restitution >= 0) then
        call impact(self, c, t, y, action, status)
        if (.not. status%ok()) return
        cycle
      end if
      speed = -dot_product(self%gaps%gap(c)%normal, self%gaps%velocity(c, self%work, self%body_frame))
      action = max(action, EVENT_STOP)
      call add_outcome(self, 'landing: the gap of contact '''//self%system%contacts(c)%name//''' fell to zero '// &
                       'at t = '//format_short(t)//' s, approaching at '//format_short(speed)//' m/s (no '// &
                       'restitution given: the run ends at the landing)')
    end do
  contains
    !> Whether body b (0: the ground) is a body of a closed contact, carried or carrying another.
    logical function of_closed(b)
      integer, intent(in) :: b
      of_closed = b > 0
      if (of_closed) of_closed = any(self%gaps%carried .and. (self%gaps%body == b .or. self%gaps%body_1 == b))
    end function of_closed
  end subroutine flight_handle_event

  !> The impact at the landing on contact c (the mechanism at y's pose and
  !> speeds, the gaps updated): the impulse L from K of the pair (its body
  !> and the ground, or its two bodies: contact_body_impact) and the contact
  !> points' relative velocity with c's law, +L on body_2 at its point, -L
  !> on body_1; each body's new twist becomes its rates in y (the other
  !> bodies' kept). A rebound below c's close_speed closes the contact
  !> (closing_impulse added to L) and stops the flight there (with several
  !> bodies the others go on as they are: contact_closing drive_bodies);
  !> between two flying bodies it ends the run, not built (their contact
  !> would press with nothing in uniform gravity: its lift-off at once),
  !> the impact kept.
  subroutine impact(self, c, t, y, action, status)
    class(flight_ode_t), intent(inout) :: self
    integer, intent(in) :: c
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(inout) :: action
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: rates(:)
    type(collision_t) :: hit
    type(impact_body_t) :: pair(2)
    real(wp) :: speeds(2)
    integer :: f, b(2), i
    f = self%mechanism%f
    b = [self%gaps%body_1(c), self%gaps%body(c)]
    do i = 1, 2
      if (b(i) > 0) pair(i) = impact_body(self, b(i))
    end do
    speeds = [centre_speed(pair(1)), centre_speed(pair(2))]
    associate (gap => self%gaps%gap(c), contact => self%system%contacts(c))
      call collide(impact_law_t(restitution=contact%restitution, mu=contact%impact_mu), gap%normal, gap%point_1, &
                   gap%point_2, pair(1), pair(2), contact%close_speed, contact%rolling, hit, status)
      if (.not. status%ok()) return
      rates = y(f + 1:f + self%mechanism%ns)
      do i = 1, 2
        if (b(i) > 0) call start_rates(self, b(i), [pair(i)%omega, pair(i)%velocity], rates, status)
        if (.not. status%ok()) return
      end do
      y(f + 1:f + self%mechanism%ns) = rates
      self%impacts = [self%impacts, impact_record_t(time=t, contact=c, body_1=b(1), body_2=b(2), &
                      normal_speed_before=hit%outcome%normal_speed_before, &
                      normal_speed_after=dot_product(hit%velocity_after, gap%normal), &
                      normal_impulse=dot_product(hit%impulse, gap%normal), &
                      tangential_impulse=norm2(hit%impulse - dot_product(hit%impulse, gap%normal)*gap%normal), &
                      energy_lost=hit%energy_lost, speed_before=speeds)]
      if (hit%closed .and. b(1) > 0) then
        ! two flying bodies (a hit on a body of closed contacts is impact_on_carried's)
        action = max(action, EVENT_STOP)
        call add_outcome(self, 'contact '''//contact%name//''': the rebound at the impact at t = '// &
                         format_short(t)//' s, '//format_short(hit%outcome%normal_speed_after)//' m/s, is below '// &
                         'close_speed: bodies '''//contact%body_1//''' and '''//contact%body_2//''' would fly on '// &
                         'closed on each other, their contact pressing with nothing in uniform gravity (two '// &
                         'flying bodies closed on each other are not built): the run ends here', not_built=.true.)
      else if (hit%closed) then
        action = max(action, EVENT_STOP)
        self%landed = c
        self%closings = [self%closings, c]
        call add_outcome(self, 'contact '''//contact%name//''' closed at the impact at t = '//format_short(t)// &
                         ' s: the rebound, '//format_short(hit%outcome%normal_speed_after)//' m/s, is below '// &
                         'close_speed')
      else
        action = max(action, EVENT_RESTART)
      end if
    end associate
  end subroutine impact

  !> The mechanism's record, with each contact's gap at its body's pose, its
  !> point on shape_1 and the body's nearest point's velocity along the surface
  !> (the slip it would have: the normal part is the gap's rate); a closed
  !> contact's (several bodies) gap 0, its point and slip the mechanism's.
  subroutine flight_record(self, t, y, kind, status)
    class(flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    integer :: n, c, nc
    real(wp) :: v(3)
    call self%mechanism_ode_t%record(t, y, kind, status)
    if (.not. status%ok()) return
    ! the record's evaluate left the mechanism at y's pose and speeds
    call self%gaps%update(self%work, self%body_frame, status)
    if (.not. status%ok()) return
    n = self%series%n
    nc = size(self%gaps%gap)
    if (.not. allocated(self%gap_point)) allocate (self%gap_point(3, nc, 0), self%gap_velocity(3, nc, 0))
    if (size(self%gap_point, 3) < n) then
      call grow(self%gap_point, 2*n)
      call grow(self%gap_velocity, 2*n)
    end if
    do c = 1, nc
      if (self%gaps%carried(c)) then
        ! closed (several bodies): the mechanism's contact point and slip
        self%series%monitor(self%gap_monitors(c), n) = 0
        self%gap_point(:, c, n) = self%series%contact_r(:, self%mechanism_contact(c), n)
        self%gap_velocity(:, c, n) = self%series%slip(:, self%mechanism_contact(c), n)
        cycle
      end if
      associate (gap => self%gaps%gap(c))
        self%series%monitor(self%gap_monitors(c), n) = gap%gap
        self%gap_point(:, c, n) = gap%point_1
        v = self%gaps%velocity(c, self%work, self%body_frame)
        self%gap_velocity(:, c, n) = v - dot_product(v, gap%normal)*gap%normal
      end associate
    end do
  end subroutine flight_record

  !> a with room for n records (its last dimension), its values kept.
  subroutine grow(a, n)
    real(wp), allocatable, intent(inout) :: a(:, :, :)
    integer, intent(in) :: n
    real(wp), allocatable :: grown(:, :, :)
    allocate (grown(size(a, 1), size(a, 2), n), source=0.0_wp)
    grown(:, :, :size(a, 3)) = a
    call move_alloc(grown, a)
  end subroutine grow
end module contact_flight
