!> The gaps of the bodies' open contacts (issue 25): a body may have several
!> contacts with the ground, the surfaces it may touch (a dome and the floor
!> it lands on, a wall and a floor), and several bodies may fly at once, each
!> gap at its own body's pose (contact_flight), a gap between two bodies
!> (body_1 not the ground) at both bodies' poses. The closed contacts carry
!> their bodies (`closed`, or `carried` with several bodies or several
!> closed contacts of one: contact_bodies); the gap of every other (contact_gap: the signed distance
!> of its two shapes along their common normal, through the foot-point
!> solver) is a root function. A gap of a flying body falling through zero
!> is a landing on that contact; while a contact carries the body
!> (contact_closing) a gap of another falling to zero stops the phase there
!> (`touched`), and contact_closing takes the impact through both.
!>
!> A contact that starts touching (a lift-off from it) starts with its gap 0,
!> its rate 0 and where the normal force fell to zero its second derivative
!> 0: the gap grows as s^3, below its rounding (~1e-16 m) for the first ~1e-5
!> s, where its sign is noise (CVODE saw roots there, and a root at and very
!> near another: CV_ILL_INPUT). So until the gap has opened by opening_gap
!> its root is opening_gap - |gap|: nonzero at the start, it falls to zero
!> where the gap has clearly opened (from there the gap is watched) or where
!> the body went back into the surface by opening_gap without opening (a
!> landing there).
module contact_open_gaps
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_vector, only: cross
  use numerics_event_driver, only: EVENT_STOP
  use kinetostatics_mechanism, only: mechanism_workspace_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_NOT_BUILT
  use contact_model, only: contact_system_t, body_index
  use contact_gap, only: contact_gap_t, new_contact_gap
  implicit none (type, external)
  private
  public :: open_gaps_t, start_open_gaps, touching_gap_limit, opening_gap, carried_ode_t, carry


  real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  real(wp), parameter :: ground_origin(3) = 0
  !> m: how far a touching start (a lift-off, or a closed start that may
  !> open) may overlap: the gap left by the contact's closure and the lift-off
  !> root, ~1e-14 m; beyond it the pose is not a touching one and it fails.
  !> Also the most a closing may move the body to touch (contact_closing).
  real(wp), parameter :: touching_gap_limit = 1e-9_wp
  !> m: how far a contact that starts touching must open before its landing
  !> is watched (or go back in to land): far above the gap's rounding, and a
  !> tenth of touching_gap_limit, so that such a landing is within the
  !> closing's reach.
  real(wp), parameter :: opening_gap = 1e-10_wp
  !> m: a contact of a body that lands (or of either body of a pair that
  !> lands) whose gap is within together_gap and closing lands with it, in
  !> one impact at several contacts: impacts that close together (1e-9 s
  !> apart at 1 m/s) are one to the integration's error of the positions,
  !> and their order would be rounding's (a ball dropped into a V whose
  !> friction's impulses leave it 1e-14 m off the middle).
  real(wp), parameter :: together_gap = 1e-9_wp

  !> The gaps of the bodies' contacts, in the order of the description's
  !> contacts (each between the ground and a body).
  type :: open_gaps_t
    type(contact_gap_t), allocatable :: gap(:)
    integer, allocatable :: body(:)    ! each contact's body_2: its place among the description's bodies
    integer, allocatable :: body_1(:)  ! each contact's body_1: its place (0: the ground)
    real(wp), allocatable :: last(:)   ! m, each gap's last value (kept where an update fails: a trial state)
    integer :: closed = 0              ! the contact that carries the body (not watched; 0: none)
    logical, allocatable :: carried(:) ! each contact: closed, carrying its body (not watched)
    logical, allocatable :: touching(:) ! each contact: it started touching, not yet opened
  contains
    procedure :: update => gaps_update
    procedure :: roots => gaps_roots
    procedure :: opened => gaps_opened
    procedure :: velocity => gaps_velocity
    procedure :: together => gaps_together
  end type open_gaps_t

  !> A closed contact's model (contact_model) carrying the body while its
  !> other contacts are open: their gaps are roots after the model's own; one
  !> falling to zero stops the phase (the body touches a second surface while
  !> carried: `touched`; two at once are not built). The body's pose for the gaps comes from a second
  !> workspace of the model (`shadow_work`, a copy of the model's, taken again
  !> after each chart change so that y means the same there), so that the
  !> model's own evaluations and their caches (its workspace) are left as
  !> they are. Per record: each contact's gap, its point
  !> on shape_1 and the body's nearest point's velocity along the surface (the
  !> carrying contact's 0).
  type, extends(mechanism_ode_t) :: carried_ode_t
    type(open_gaps_t) :: gaps
    type(contact_system_t) :: system
    integer :: body_frame = 0
    type(mechanism_workspace_t) :: shadow_work
    integer :: shadow_charts = 0   ! the model's chart_changes when shadow_work was copied
    integer :: touched = 0         ! the watched contact whose gap fell to zero (the run stopped there; 0: none)
    real(wp), allocatable :: gap_value(:, :)                       ! contacts x records, m
    real(wp), allocatable :: gap_point(:, :, :), gap_velocity(:, :, :)   ! 3 x contacts x records
  contains
    procedure :: root_count => carried_root_count
    procedure :: roots => carried_roots
    procedure :: handle_event => carried_handle_event
    procedure :: record => carried_record
  end type carried_ode_t

contains

  !> The gaps at the bodies' poses (work%frames(frames(b)) of body b of the
  !> description: its frame, world), each from the contact search, on its contact's branch (the normals against
  !> each other) and open (> 0); the contact `touching` and those of
  !> `also_touching` may touch (their gaps not below -touching_gap_limit:
  !> an impact left them at gap 0, each watched from its opening); the contact `closed` carries the body
  !> and is not watched, as are those of `carried` (several bodies, each
  !> carried by one of them or flying: contact_bodies). At the run's start a
  !> gap that is not open is the input's; at a switch (restarting) the
  !> motion's.
  subroutine start_open_gaps(gaps, system, work, frames, status, touching, closed, restarting, carried, &
                             also_touching)
    type(open_gaps_t), intent(out) :: gaps
    type(contact_system_t), intent(in) :: system
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: frames(:)   ! each body's frame in work
    type(status_t), intent(inout) :: status
    integer, intent(in) :: touching, closed
    logical, intent(in) :: restarting   ! a switch during the run (not the run's start, the input's)
    logical, intent(in), optional :: carried(:)   ! each contact: closed (the body it carries, its other contacts open)
    logical, intent(in), optional :: also_touching(:)   ! each contact: it may touch too
    integer :: c, s1, s2, k
    gaps%touching = spread(.false., 1, size(system%contacts))
    if (touching > 0) gaps%touching(touching) = .true.
    if (present(also_touching)) gaps%touching = gaps%touching .or. also_touching
    gaps%closed = closed
    allocate (gaps%gap(size(system%contacts)), gaps%last(size(system%contacts)), &
              gaps%carried(size(system%contacts)))
    gaps%carried = .false.
    if (closed > 0) gaps%carried(closed) = .true.
    if (present(carried)) gaps%carried = carried
    gaps%last = 0
    gaps%body = [(body_index(system, system%contacts(c)%body_2), c = 1, size(system%contacts))]
    gaps%body_1 = [(max(0, body_index(system, system%contacts(c)%body_1)), c = 1, size(system%contacts))]
    do c = 1, size(system%contacts)
      if (gaps%carried(c)) cycle
      associate (contact => system%contacts(c), gap => gaps%gap(c))
        s1 = findloc([(system%shapes(k)%name == contact%shape_1, k = 1, size(system%shapes))], .true., dim=1)
        s2 = findloc([(system%shapes(k)%name == contact%shape_2, k = 1, size(system%shapes))], .true., dim=1)
        gap = new_contact_gap(system%shapes(s1)%surface, contact%side_1, system%shapes(s2)%surface, contact%side_2, &
                              [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
        call place_gap(gaps, c, work, frames, status, search=.true.)
        if (.not. status%ok()) then
          status%message = 'contact '''//contact%name//''': the gap between '''//contact%shape_1//''' and '''// &
                           contact%shape_2//''' at the start: '//status%text()
          return
        end if
        if (.not. gap%normals_cosine < 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//contact%name//''': at the start the '// &
            'normals of shape_1 and shape_2 point the same way at their nearest points (side_1, side_2 as for a '// &
            'closed contact: each normal out of its body towards the other); check side_1 and side_2')
        else if (gaps%touching(c)) then
          if (.not. gap%gap >= -touching_gap_limit) call set_status(status, STATUS_DOMAIN, 'contact '''// &
            contact%name//''': body '''//contact%body_2//''' overlaps shape '''//contact%shape_1//''' by '// &
            format_short(-gap%gap)//' m where it should touch (more than '//format_short(touching_gap_limit)// &
            ' m)')
        else if (.not. gap%gap > 0 .and. .not. restarting) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//contact%name//''': start = ''open'' but '// &
            'body '''//contact%body_2//''' touches or overlaps shape '''//contact%shape_1//''' at its start '// &
            'position (gap '//format_short(gap%gap)//' m); an open contact starts with its shapes apart (raise '// &
            '&body position, or start closed)')
        else if (.not. gap%gap > 0) then
          call set_status(status, STATUS_DOMAIN, 'contact '''//contact%name//''': body '''//contact%body_2// &
            ''' touches or overlaps shape '''//contact%shape_1//''' (gap '//format_short(gap%gap)//' m) where '// &
            'it leaves another contact: two contacts of one body touching at once are not built')
        end if
        if (.not. status%ok()) return
        gaps%last(c) = gap%gap
      end associate
    end do
  end subroutine start_open_gaps

  !> Every watched gap at its body's pose (work%frames(frames(b)) of body b:
  !> world). A failed update leaves the status failed and the gap's last value.
  subroutine gaps_update(self, work, frames, status)
    class(open_gaps_t), intent(inout) :: self
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: frames(:)
    type(status_t), intent(inout) :: status
    integer :: c
    do c = 1, size(self%gap)
      if (self%carried(c)) cycle
      call place_gap(self, c, work, frames, status)
      if (.not. status%ok()) return
      self%last(c) = self%gap(c)%gap
    end do
  end subroutine gaps_update

  !> Contact c's gap at its bodies' poses (work%frames(frames(b)) of body b,
  !> world; the ground's the world axes): updated from its last points, or
  !> with search = .true. from the contact search.
  subroutine place_gap(self, c, work, frames, status, search)
    class(open_gaps_t), intent(inout) :: self
    integer, intent(in) :: c
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: frames(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: search
    real(wp) :: rotation_1(3, 3), origin_1(3)
    logical :: searching
    searching = .false.
    if (present(search)) searching = search
    rotation_1 = identity
    origin_1 = ground_origin
    if (self%body_1(c) > 0) then
      rotation_1 = work%frames(frames(self%body_1(c)))%rot
      origin_1 = work%frames(frames(self%body_1(c)))%r
    end if
    associate (body => work%frames(frames(self%body(c))))
      if (searching) then
        call self%gap(c)%start_from_search(rotation_1, origin_1, body%rot, body%r, status)
      else
        call self%gap(c)%update(rotation_1, origin_1, body%rot, body%r, status)
      end if
    end associate
  end subroutine place_gap

  !> The velocity of body_2's nearest point of contact c relative to body_1's
  !> (the ground's: 0), at the bodies' poses and twists (work%frames(frames(b))
  !> of body b; world, m/s): along the normal the gap's rate.
  function gaps_velocity(self, c, work, frames) result(v)
    class(open_gaps_t), intent(in) :: self
    integer, intent(in) :: c
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: frames(:)
    real(wp) :: v(3)
    associate (gap => self%gap(c), body => work%frames(frames(self%body(c))))
      v = body%v + cross(body%omega, gap%point_2 - body%r)
      if (self%body_1(c) == 0) return
      associate (other => work%frames(frames(self%body_1(c))))
        v = v - (other%v + cross(other%omega, gap%point_1 - other%r))
      end associate
    end associate
  end function gaps_velocity

  !> The contacts that land at an event: those whose roots fired (`lands`)
  !> and the others of their bodies within together_gap and closing (the
  !> gaps updated at the event's pose, the velocities set); a touching one
  !> (left at gap 0) also where it separates slower than its close_speed:
  !> two bodies resting on each other while they fall freely land together
  !> as they would on a closed contact (contact_closing: a closed contact
  !> that carries nothing opens, touching).
  function gaps_together(self, lands, work, frames, close_speed) result(together)
    class(open_gaps_t), intent(in) :: self
    logical, intent(in) :: lands(:)
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: frames(:)
    real(wp), intent(in) :: close_speed(:)   ! m/s, each contact's
    logical :: together(size(lands))
    real(wp) :: separating
    logical :: involved(0:size(frames))
    integer :: c
    involved = .false.
    do c = 1, size(lands)
      if (lands(c)) involved([self%body(c), self%body_1(c)]) = .true.
    end do
    involved(0) = .false.
    together = lands
    do c = 1, size(lands)
      if (lands(c) .or. self%carried(c)) cycle
      if (.not. (involved(self%body(c)) .or. involved(self%body_1(c)))) cycle
      separating = dot_product(self%gap(c)%normal, self%velocity(c, work, frames))
      if (self%touching(c)) then
        together(c) = abs(self%gap(c)%gap) <= together_gap .and. separating < close_speed(c)
      else
        together(c) = self%gap(c)%gap <= together_gap .and. separating < 0
      end if
    end do
  end function gaps_together

  !> The root of each contact at its body's pose (as gaps_update): its gap
  !> (the last where it cannot be found: a trial state the integrator does
  !> not keep); each touching contact's opening_gap - |gap|; the closed ones'
  !> 1 (never zero).
  subroutine gaps_roots(self, work, frames, located, g)
    class(open_gaps_t), intent(inout) :: self
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: frames(:)
    logical, intent(in) :: located   ! the bodies are at their poses (else the last values)
    real(wp), intent(out) :: g(:)
    type(status_t) :: status
    integer :: c
    do c = 1, size(self%gap)
      if (self%carried(c)) cycle
      if (located) then
        call place_gap(self, c, work, frames, status)
        if (status%ok()) self%last(c) = self%gap(c)%gap
      end if
    end do
    g = self%last
    where (self%carried) g = 1
    where (self%touching) g = opening_gap - abs(g)
  end subroutine gaps_roots

  !> At an event where the root of touching contact c fired (the gaps
  !> updated): whether it opened (its landing is watched from now on: the
  !> gap, opening_gap there), else it went back in (a landing on it).
  logical function gaps_opened(self, c) result(opened)
    class(open_gaps_t), intent(inout) :: self
    integer, intent(in) :: c
    opened = self%gap(c)%gap > 0
    self%touching(c) = .false.
  end function gaps_opened

  !> The closed model `model` (its body on frame body_frame) carried by
  !> contact `closed` of `system`, the gaps of the others watched.
  subroutine carry(model, body_frame, system, closed, carried, status)
    type(mechanism_ode_t), intent(in) :: model
    integer, intent(in) :: body_frame, closed
    type(contact_system_t), intent(in) :: system
    type(carried_ode_t), intent(out) :: carried
    type(status_t), intent(inout) :: status
    carried%mechanism_ode_t = model
    carried%system = system
    carried%body_frame = body_frame
    carried%shadow_work = carried%work
    carried%shadow_charts = carried%chart_changes
    allocate (carried%gap_value(size(system%contacts), 0), carried%gap_point(3, size(system%contacts), 0), &
              carried%gap_velocity(3, size(system%contacts), 0))
    call start_open_gaps(carried%gaps, system, carried%work, [body_frame], status, 0, closed, .true.)
  end subroutine carry

  integer function carried_root_count(self) result(n)
    class(carried_ode_t), intent(in) :: self
    n = self%mechanism_ode_t%root_count() + size(self%gaps%gap) - 1
  end function carried_root_count

  !> The model's roots, then the gap of each contact but the carrying one.
  subroutine carried_roots(self, t, y, g)
    class(carried_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    real(wp) :: all(size(self%gaps%gap))
    type(status_t) :: status
    integer :: n
    n = self%mechanism_ode_t%root_count()
    call self%mechanism_ode_t%roots(t, y, g(1:n))
    if (n == size(g)) return
    call follow_charts(self)
    call self%mechanism%set_positions(self%shadow_work, y(1:self%mechanism%f), status)
    call self%gaps%roots(self%shadow_work, [self%body_frame], status%ok(), all)
    call drop_closed(self, all, g(n + 1:))
  end subroutine carried_roots

  !> The shadow workspace on the model's charts: copied again after the
  !> model changed a chart (its coordinates re-based: y means another pose
  !> on the old chart).
  subroutine follow_charts(self)
    class(carried_ode_t), intent(inout) :: self
    if (self%shadow_charts == self%chart_changes) return
    self%shadow_work = self%work
    self%shadow_charts = self%chart_changes
  end subroutine follow_charts

  !> The values of every contact but the carrying one, in order.
  pure subroutine drop_closed(self, all, watched)
    class(carried_ode_t), intent(in) :: self
    real(wp), intent(in) :: all(:)
    real(wp), intent(out) :: watched(:)
    integer :: c, j
    j = 0
    do c = 1, size(all)
      if (c == self%gaps%closed) cycle
      j = j + 1
      watched(j) = all(c)
    end do
  end subroutine drop_closed

  !> The model's events, then a watched gap falling through zero: the body
  !> touches a second surface while carried; the run stops there (touched:
  !> that contact), its impact contact_closing's (impact_while_carried).
  subroutine carried_handle_event(self, t, y, fired, action, status)
    class(carried_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    integer :: n, c, j
    character(len=:), allocatable :: text
    n = self%mechanism_ode_t%root_count()
    call self%mechanism_ode_t%handle_event(t, y, fired(1:n), action, status)
    if (.not. status%ok() .or. all(fired(n + 1:) /= -1)) return
    j = n
    do c = 1, size(self%gaps%gap)
      if (c == self%gaps%closed) cycle
      j = j + 1
      if (fired(j) /= -1) cycle
      if (self%touched > 0) then   ! two at once
        text = '; contact '''//self%system%contacts(c)%name//''' too (two landings on a carried body at once are '// &
               'not built): the run ends here'
      else
        text = 'contact '''//self%system%contacts(c)%name//''': body '''//self%system%contacts(c)%body_2// &
               ''' touches shape '''//self%system%contacts(c)%shape_1//''' at t = '//format_short(t)// &
               ' s while contact '''//self%system%contacts(self%gaps%closed)%name//''' carries it'
        if (len(self%outcome) > 0) text = '; '//text
      end if
      self%outcome = self%outcome//text
      self%touched = merge(c, -1, self%touched == 0)
      if (self%touched < 0) self%stop_kind = STOP_NOT_BUILT   ! drive_flight fails the run here
      action = max(action, EVENT_STOP)
    end do
  end subroutine carried_handle_event

  !> The model's record, then each watched contact's gap, point and slip.
  subroutine carried_record(self, t, y, kind, status)
    class(carried_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: grown(:, :, :), grown_value(:, :)
    real(wp) :: v(3)
    integer :: n, c, nc, f
    call self%mechanism_ode_t%record(t, y, kind, status)
    if (.not. status%ok()) return
    n = self%series%n
    nc = size(self%gaps%gap)
    if (size(self%gap_value, 2) < n) then
      allocate (grown_value(nc, 2*n), source=0.0_wp)
      grown_value(:, :size(self%gap_value, 2)) = self%gap_value
      call move_alloc(grown_value, self%gap_value)
      allocate (grown(3, nc, 2*n), source=0.0_wp)
      grown(:, :, :size(self%gap_point, 3)) = self%gap_point
      call move_alloc(grown, self%gap_point)
      allocate (grown(3, nc, 2*n), source=0.0_wp)
      grown(:, :, :size(self%gap_velocity, 3)) = self%gap_velocity
      call move_alloc(grown, self%gap_velocity)
    end if
    if (nc == 1) return
    f = self%mechanism%f
    call follow_charts(self)
    call self%mechanism%set_positions(self%shadow_work, y(1:f), status)
    if (.not. status%ok()) return
    call self%mechanism%set_velocities(self%shadow_work, y(f + 1:f + self%mechanism%ns))
    associate (body => self%shadow_work%frames(self%body_frame))
      call self%gaps%update(self%shadow_work, [self%body_frame], status)
      if (.not. status%ok()) return
      do c = 1, nc
        if (c == self%gaps%closed) cycle
        associate (gap => self%gaps%gap(c))
          self%gap_value(c, n) = gap%gap
          self%gap_point(:, c, n) = gap%point_1
          v = body%v + cross(body%omega, gap%point_2 - body%r)
          self%gap_velocity(:, c, n) = v - dot_product(v, gap%normal)*gap%normal
        end associate
      end do
    end associate
  end subroutine carried_record
end module contact_open_gaps
