!> The impacts at several contacts of a flight (contact_flight): a body
!> landing on several at once, and a body landing while closed contacts
!> carry it (issue 25).
submodule (contact_flight) contact_flight_impacts
  implicit none (type, external)

contains

  !> The names of the contacts landed on, quoted, comma-separated.
  module procedure landed_names
    integer :: c
    text = ''
    do c = 1, size(lands)
      if (.not. lands(c)) cycle
      if (len(text) > 0) text = text//', '
      text = text//''''//self%system%contacts(c)%name//''''
    end do
  end procedure landed_names

  !> The landings of one event where a body lands on several contacts at
  !> once (`lands`, every contact landed on; no carried body among them): one
  !> impact at all of them (contact_body_impact collide_at_once, Newton's
  !> restitution and impact_mu at each), a row per contact, and the bodies
  !> fly on; those it leaves slower than their close_speed close together
  !> (close_at_once; the flight stops, `closings` them; a contact between
  !> two bodies among them: body_1 carries body_2 from there, or it opens
  !> at gap 0 where it carries nothing). Not built, the run ending here,
  !> saying so: such an impact without restitution, and one that would
  !> close a rolling contact.
  module procedure impact_at_once
    type(impact_body_t) :: bodies(0:size(self%body_frame))
    real(wp) :: speeds(0:size(self%body_frame))   ! m/s, each body's centre of mass before the impact
    integer, allocatable :: c(:), pair(:, :)
    real(wp), allocatable :: normals(:, :), points_1(:, :), points_2(:, :), rates(:)
    real(wp), dimension(count(lands)) :: impulse, tangential, before, after, lost
    logical :: closing(count(lands))
    character(len=:), allocatable :: stopped
    integer :: f, i, b, m
    c = pack([(i, i = 1, size(lands))], lands)
    m = size(c)
    if (any(self%system%contacts(c)%restitution < 0)) then
      action = max(action, EVENT_STOP)
      call add_outcome(self, 'landing on several contacts at once at t = '//format_short(t)//' s ('// &
                       landed_names(self, lands)//'): an impact at several points needs restitution at each; '// &
                       'the run ends here')
      return
    end if
    pair = reshape([(self%gaps%body_1(c(i)), self%gaps%body(c(i)), i = 1, m)], [2, m])
    do b = 1, size(self%body_frame)
      if (any(pair == b)) bodies(b) = impact_body(self, b)
    end do
    speeds = [(centre_speed(bodies(b)), b = 0, size(self%body_frame))]
    normals = reshape([(self%gaps%gap(c(i))%normal, i = 1, m)], [3, m])
    points_1 = reshape([(self%gaps%gap(c(i))%point_1, i = 1, m)], [3, m])
    points_2 = reshape([(self%gaps%gap(c(i))%point_2, i = 1, m)], [3, m])
    call collide_at_once(self%system%contacts(c)%restitution, self%system%contacts(c)%impact_mu, normals, points_1, &
                         points_2, pair, bodies, impulse, tangential, before, after, lost, status)
    if (.not. status%ok()) return
    closing = after < self%system%contacts(c)%close_speed
    ! a contact between two bodies closes as the ground's (the next phase
    ! builds it, or opens it touching where it carries nothing: contact_closing)
    if (any(closing .and. self%system%contacts(c)%rolling)) then
      stopped = 'the impact at several contacts at once at t = '//format_short(t)//' s ('// &
                landed_names(self, lands)//') leaves '//landed_names(self, unpack(closing, lands, .false.))// &
                ' slower than close_speed (closing a rolling contact at an impact at several contacts at once is '// &
                'not built): the run ends here'
    else if (any(closing)) then
      ! those slower than close_speed close together; one the closing leaves slower closes with them
      do i = 1, m
        call close_at_once(closing, normals, points_1, points_2, pair, bodies, impulse, after, lost, status)
        if (.not. status%ok()) return
        if (.not. any(after < self%system%contacts(c)%close_speed .and. .not. closing)) exit
        closing = closing .or. after < self%system%contacts(c)%close_speed
      end do
    end if
    f = self%mechanism%f
    rates = y(f + 1:f + self%mechanism%ns)
    do b = 1, size(self%body_frame)
      if (any(pair == b)) call start_rates(self, b, [bodies(b)%omega, bodies(b)%velocity], rates, status)
      if (.not. status%ok()) return
    end do
    y(f + 1:f + self%mechanism%ns) = rates
    do i = 1, m
      self%impacts = [self%impacts, impact_record_t(time=t, contact=c(i), body_1=pair(1, i), body_2=pair(2, i), &
                      normal_speed_before=before(i), normal_speed_after=after(i), normal_impulse=impulse(i), &
                      tangential_impulse=tangential(i), energy_lost=lost(i), speed_before=speeds(pair(:, i)))]
    end do
    if (allocated(stopped)) then
      action = max(action, EVENT_STOP)
      call add_outcome(self, stopped, not_built=.true.)
    else if (any(closing)) then
      action = max(action, EVENT_STOP)
      self%closings = [self%closings, pack(c, closing)]
      ! with a pair's contact closing: the others it bounced off are left at gap 0
      if (any(closing .and. pair(1, :) > 0)) self%bounced = pack(c, .not. closing)
      self%landed = self%closings(size(self%closings))
      call add_outcome(self, 'contacts '//landed_names(self, unpack(closing, lands, .false.))//' closed at the '// &
                       'impact at several contacts at once at t = '//format_short(t)//' s: their rebounds are '// &
                       'below close_speed')
    else
      action = max(action, EVENT_RESTART)
    end if
  end procedure impact_at_once

  !> Body b at the mechanism's pose and twist (the workspace's), its mass
  !> properties in world axes: for its impact.
  module procedure impact_body
    associate (frame => self%work%frames(self%body_frame(b)))
      body = impact_body_t(mass=self%mass(b), &
                           inertia=matmul(frame%rot, matmul(self%inertia(:, :, b), transpose(frame%rot))), &
                           origin=frame%r, centre=frame%r + matmul(frame%rot, self%centre(:, b)), &
                           omega=frame%omega, velocity=frame%v)
    end associate
  end procedure impact_body

  !> A landing (`lands`) that involves a body of a closed contact (carried,
  !> or carrying another): the body lands on another of its contacts, or a
  !> body hits it, or it hits another (a contact between two bodies, either
  !> of a closed contact). One impact at the landed contacts and at every
  !> closed contact of the bodies they join, those the closed contacts
  !> join to them too (a ball hit on a ball resting on the floor: both
  !> balls, the contact between them and the floor's) (collide_at_once; a
  !> carrying contact's normal speed before is 0, its restitution 0: it
  !> stays closed or is pushed open, P >= 0 either way;
  !> its impact_mu during the impact; a rolling one no-slip: while it pushes
  !> its whole relative velocity after is 0, no cone, else it opens with no
  !> impulse), each body with its free mass
  !> properties: the carrying contacts' impulses are the impact's own, so a
  !> carried body meets a hit with its effective mass through its closed
  !> contacts (a ball resting on the floor hit from above passes the
  !> impulse on to the floor and stays at rest). The contacts it leaves
  !> slower than their close_speed close (close_at_once), a carrying one it
  !> leaves faster opens (it must have may_open); the phase stops
  !> (EVENT_STOP) with `closings`, `openings`, the bodies' twists after
  !> (`twist_after`: a twist the carried body's coordinates may not take)
  !> and the contacts left at gap 0 (`bounced`, each watched from its
  !> opening: contact_open_gaps), and contact_closing goes on
  !> from there. A row per contact (the energies summing to the kinetic
  !> energy's fall). A landing without restitution ends the run there (the
  !> input's choice, as in flight). Not built, the run failing here, saying
  !> so: landings the impact does not join in the same event (bodies
  !> neither carried nor hitting a carried one), a carrying contact that
  !> would open without may_open, a rolling contact closed after it beside
  !> another closed contact of its body_2 (a rolling loop).
  !> A contact between two bodies left slower than its close_speed closes
  !> as the ground's do: body_1 carries body_2 from there.
  module procedure impact_on_carried
    type(impact_body_t) :: bodies(0:size(self%body_frame))
    real(wp) :: speeds(0:size(self%body_frame))   ! m/s, each body's centre of mass before the impact
    integer, allocatable :: c(:), pair(:, :)
    real(wp), allocatable :: normals(:, :), points_1(:, :), points_2(:, :), e(:), close_speed(:)
    real(wp), allocatable, dimension(:) :: impulse, tangential, before, after, lost
    real(wp), allocatable :: tangent(:, :)
    logical, allocatable :: closing(:), carrying(:), both(:), joined(:), rolls(:), second(:)
    logical :: involved(0:size(self%body_frame)), carried(0:size(self%body_frame))
    character(len=:), allocatable :: carriers, head, left_open, hit
    integer :: i, m, k, b
    ! the bodies of closed contacts (carried, or carrying another)
    carried = .false.
    do i = 1, size(lands)
      if (.not. self%gaps%carried(i)) cycle
      carried(self%gaps%body(i)) = .true.
      carried(self%gaps%body_1(i)) = .true.
    end do
    carried(0) = .false.
    ! the landed contacts this impact joins: those of a body of a closed contact (either of a pair's)
    joined = lands .and. (carried(self%gaps%body) .or. carried(self%gaps%body_1))
    involved = .false.
    do i = 1, size(lands)
      if (.not. joined(i)) cycle
      involved(self%gaps%body(i)) = .true.
      involved(self%gaps%body_1(i)) = .true.
    end do
    involved(0) = .false.
    ! and every body the closed contacts join to them (a stack: the ball under the ball hit, and its floor)
    do
      k = count(involved)
      do i = 1, size(lands)
        if (.not. (self%gaps%carried(i) .and. (involved(self%gaps%body(i)) .or. involved(self%gaps%body_1(i))))) &
          cycle
        involved(self%gaps%body(i)) = .true.
        involved(self%gaps%body_1(i)) = .true.
        involved(0) = .false.
      end do
      if (count(involved) == k) exit
    end do
    carrying = self%gaps%carried .and. involved(self%gaps%body)
    both = joined .or. carrying
    carriers = landed_names(self, carrying)
    b = self%gaps%body(findloc(joined, .true., dim=1))
    hit = ''
    do k = 1, size(self%body_frame)
      if (.not. (involved(k) .and. carried(k))) cycle
      if (len(hit) > 0) hit = hit//', '
      hit = hit//''''//self%system%bodies(k)%name//''''
    end do
    if (count(involved .and. carried) == 1 .and. carried(b)) hit = 'it'
    head = 'body '''//self%system%bodies(b)%name//''' lands on '//landed_names(self, joined)//' at t = '// &
           format_short(t)//' s while '//carriers//' carry '//hit
    if (count(carrying) == 1) head = head(:len(head) - len(' carry '//hit))//' carries '//hit
    if (any(joined .and. self%system%contacts%restitution < 0)) then
      ! the input's choice, as for a landing in flight
      action = max(action, EVENT_STOP)
      call add_outcome(self, head//' (no restitution given: the run ends at the landing)')
      return
    end if
    if (any(lands .and. .not. joined)) then
      action = max(action, EVENT_STOP)
      call add_outcome(self, head//' (other bodies landing in the same instant are not built): the run ends here', &
                       not_built=.true.)
      return
    end if
    c = pack([(i, i = 1, size(lands))], both)
    m = size(c)
    allocate (normals(3, m), points_1(3, m), points_2(3, m), impulse(m), tangential(m), before(m), after(m), &
              lost(m), closing(m), tangent(3, m))
    do i = 1, m
      if (joined(c(i))) then
        normals(:, i) = self%gaps%gap(c(i))%normal
        points_1(:, i) = self%gaps%gap(c(i))%point_1
        points_2(:, i) = self%gaps%gap(c(i))%point_2
      else   ! a carrying contact: its contact frame K_1D (z out of shape_1), both points its origin
        associate (closed => self%mechanism%contacts(self%mechanism_contact(c(i))))
          k = closed%point_frame
          normals(:, i) = closed%normal_sign*self%work%frames(k)%rot(:, 3)
        end associate
        points_1(:, i) = self%work%frames(k)%r
        points_2(:, i) = self%work%frames(k)%r
      end if
    end do
    e = merge(self%system%contacts(c)%restitution, 0.0_wp, joined(c))
    close_speed = self%system%contacts(c)%close_speed
    pair = reshape([(self%gaps%body_1(c(i)), self%gaps%body(c(i)), i = 1, m)], [2, m])
    do k = 1, size(self%body_frame)
      if (involved(k)) bodies(k) = impact_body(self, k)
    end do
    speeds = [(centre_speed(bodies(k)), k = 0, size(self%body_frame))]
    ! a rolling carrying contact holds its whole relative velocity at zero while it pushes (no cone)
    rolls = self%system%contacts(c)%rolling
    call collide_at_once(e, self%system%contacts(c)%impact_mu, normals, points_1, points_2, pair, bodies, impulse, &
                         tangential, before, after, lost, status, tangent, no_slip=rolls .and. carrying(c))
    if (.not. status%ok()) return
    closing = after < close_speed
    if (any(carrying(c) .and. .not. closing .and. .not. self%system%contacts(c)%may_open)) then
      action = max(action, EVENT_STOP)
      call add_outcome(self, head//': the impact would lift '//landed_names(self, unpack(carrying(c) .and. &
                       .not. closing, both, .false.))//' off, which may not open (may_open): the run ends here', &
                       not_built=.true.)
      return
    end if
    ! a rolling contact closed after the impact carries its body_2 alone (a second closed contact beside one that
    ! rolls, a loop, is not built): its closing takes away its whole relative velocity (a carrying one's is 0 already
    ! where it held)
    if (any(closing)) then
      do i = 1, m
        call close_at_once(closing, normals, points_1, points_2, pair, bodies, impulse, after, lost, status, rolls, &
                           tangent)
        if (.not. status%ok()) return
        if (.not. any(after < close_speed .and. .not. closing)) exit
        closing = closing .or. after < close_speed
      end do
    end if
    second = [(closing(i) .and. rolls(i) .and. count(closing .and. pair(2, :) == pair(2, i)) > 1, i = 1, m)]
    if (any(second)) then
      action = max(action, EVENT_STOP)
      call add_outcome(self, head//': the impact would leave '//landed_names(self, unpack(second, both, .false.))// &
                       ', which rolls, closed with another contact of its body (a second closed contact beside one '// &
                       'that rolls is not built): the run ends here', not_built=.true.)
      return
    end if
    where (closing .and. rolls) tangential = norm2(tangent, dim=1)
    do i = 1, m
      self%impacts = [self%impacts, impact_record_t(time=t, contact=c(i), body_1=pair(1, i), body_2=pair(2, i), &
                      normal_speed_before=before(i), normal_speed_after=after(i), normal_impulse=impulse(i), &
                      tangential_impulse=tangential(i), energy_lost=lost(i), speed_before=speeds(pair(:, i)), &
                      after_switch=.true.)]
    end do
    action = max(action, EVENT_STOP)
    left_open = landed_names(self, unpack(.not. closing, both, .false.))
    self%closings = [self%closings, pack(c, closing .and. joined(c))]
    self%openings = [self%openings, pack(c, .not. closing .and. carrying(c))]
    ! each left at gap 0, watched from its opening (contact_open_gaps)
    self%bounced = pack(c, .not. closing)
    do k = 1, size(self%body_frame)
      if (.not. involved(k)) cycle
      self%twisted(k) = .true.
      self%twist_after(:, k) = [bodies(k)%omega, bodies(k)%velocity]
    end do
    if (len(left_open) > 0) left_open = left_open//' open'
    if (any(closing) .and. len(left_open) > 0) left_open = ', '//left_open
    if (any(closing)) left_open = landed_names(self, unpack(closing, both, .false.))//' closed'//left_open
    call add_outcome(self, head//': one impact at them all, after it '//left_open)
  end procedure impact_on_carried

  !> The phase's outcome extended by text.
  module procedure add_outcome
    if (len(self%outcome) > 0) self%outcome = self%outcome//'; '
    self%outcome = self%outcome//text
    if (present(not_built)) self%stop_kind = merge(STOP_NOT_BUILT, self%stop_kind, not_built)
  end procedure add_outcome
end submodule contact_flight_impacts
