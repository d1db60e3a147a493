!> The rider's flights in the ride (rider_flight; docs/rider.md "Flight"):
!> the open contacts' gap roots, their events, and the switches between the
!> builds (one per set of open contacts) that simulate_ride's stretches go
!> through.
submodule (rider_ride) rider_ride_flight
  use rider_flight_builds, only: use_build
  use rider_flight, only: contact_gap_rate, landing_record, quick_landings_exceeded, quick_flight, count_switch
  use kinetostatics_point_impact, only: gap_root
  implicit none (type, external)

contains

  !> The roots: the mechanism's and the stall's and stations', then, with
  !> may_fly, each contact's gap (while it is open; else a constant).
  integer module function rider_root_count(self) result(n)
    class(rider_ode_t), intent(in) :: self
    n = self%mechanism_ode_t%root_count()
    if (self%may_fly) n = n + N_CONTACTS + 2
  end function rider_root_count

  !> An open contact's root: kinetostatics_point_impact's gap_root. In flight, the hip's range: the legs' flexion and
  !> the trunk's tilt within flexion_range, tilt_range.
  module subroutine rider_roots(self, t, y, g)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    integer :: n, k
    type(status_t) :: st
    n = self%n_roots
    call self%mechanism_ode_t%roots(t, y, g(1:n))
    if (.not. self%may_fly) return
    g(n + 1:n + N_CONTACTS + 2) = 1
    if (self%fly%open_mask == 0) return
    ! the positions at y; a trial state the closure cannot reach keeps the last value
    call self%positions_at(y, st)
    if (.not. st%ok()) return
    do k = 1, N_CONTACTS
      if (.not. btest(self%fly%open_mask, k - 1)) cycle
      g(n + k) = gap_root(contact_gap(self%work, self%layout, k), self%opened(k))
    end do
    associate (flexion => self%work%scalars(self%layout%flexion)%q, &
               tilt => self%work%scalars(self%layout%tilt)%q)
      g(n + N_CONTACTS + 1) = (flexion - flexion_range(1))*(flexion_range(2) - flexion)
      g(n + N_CONTACTS + 2) = (tilt - tilt_range(1))*(tilt_range(2) - tilt)
    end associate
  end subroutine rider_roots

  !> A gap root fired in flight: its contact opened (watch the landing from
  !> now on: a restart, the root changes) or landed (a stop that asks for the
  !> landing's switch; not where the mechanism stops the ride at the same
  !> time: its stop ends the ride).
  module subroutine gap_event(self, t, y, fired, action, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: fired(:)
    integer, intent(inout) :: action
    type(status_t), intent(inout) :: status
    integer :: k
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), status)
    if (.not. status%ok()) return
    do k = 1, N_CONTACTS
      if (fired(k) == 0 .or. .not. btest(self%fly%open_mask, k - 1)) cycle
      if (.not. self%opened(k) .and. contact_gap(self%work, self%layout, k) > 0) then
        self%opened(k) = .true.
        action = max(action, EVENT_RESTART)
        cycle
      end if
      if (action == EVENT_STOP .or. self%switch == SWITCH_LANDING) cycle
      self%switch = SWITCH_LANDING
      self%switch_contact = k
      self%switch_t = t
      self%switch_y = y
      action = EVENT_STOP
    end do
  end subroutine gap_event

  !> The switch the last stop asked for, at (switch_t, switch_y): y becomes
  !> the state of the next build (or of the same, flying on after a
  !> landing's rebound).
  module subroutine switch_build(self, y, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), allocatable, intent(inout) :: y(:)
    type(status_t), intent(inout) :: status
    real(wp) :: residual, t
    real(wp), allocatable :: y_open(:), full(:)
    type(impact_outcome_t) :: impact
    type(rider_landing_t) :: landing
    real(wp) :: closing(3), closing_energy
    logical :: closed
    integer :: f, c, before
    t = self%switch_t
    c = self%switch_contact
    before = self%fly%open_mask
    ! the ride goes on: the stop's words and codes were not its end
    self%ending = RIDE_FAILED
    self%lifted_contact = 0
    self%outcome = ''
    allocate (full(self%fly%flight_size))
    select case (self%switch)
    case (SWITCH_TAKE_OFF)
      f = self%mechanism%f
      call self%mechanism%evaluate(self%work, t, self%switch_y(1:f), self%switch_y(f + 1:2*f), residual, status)
      if (.not. status%ok()) return
      call full_state(self%mechanism, self%work, self%layout, self%switch_y, full)
      call use_build(self%mechanism_ode_t, self%fly, self%layout, ibset(before, c - 1), full, y)
      self%opened(c) = .false.
    case (SWITCH_LANDING)
      y_open = self%switch_y
      call contact_impact(self%mechanism, self%work, self%layout, c, y_open, self%landing, impact, closed, closing, &
                          closing_energy, status)
      if (.not. status%ok()) return
      landing = landing_record(t, c, self%slide%arc_length(self%work%scalars(self%layout%u(c))%q), impact, &
                               closing, closing_energy, closed, self%gravity)
      if (quick_landings_exceeded(self%quick_landings, t - self%take_off_time(c))) then
        call set_status(status, STATUS_DOMAIN, 'the '//trim(contact_names(c))//' neither stay on the slide nor '// &
                        'leave it (landing after landing within '//format_short(quick_flight)//' s)'//' at t = '// &
                        format_short(t)//' s')
        return
      end if
      ! the positions at y_open and the speeds after the impact are set
      call full_state(self%mechanism, self%work, self%layout, y_open, full)
      if (closed) then
        call use_build(self%mechanism_ode_t, self%fly, self%layout, ibclr(before, c - 1), full, y)
        ! pressing again? Else the contact flies on from the slide (its
        ! normal force would pull: the free motion leaves it)
        f = self%mechanism%f
        call self%mechanism%evaluate(self%work, t, y(1:f), y(f + 1:2*f), residual, status)
        if (.not. status%ok()) return
        if (.not. self%work%normal_force(self%layout%contact(c)) > 0) then
          landing%closed = .false.
          call full_state(self%mechanism, self%work, self%layout, y, full)
          call use_build(self%mechanism_ode_t, self%fly, self%layout, before, full, y)
        end if
      else
        y = y_open
      end if
      self%opened(c) = .false.
      call add_landing(self%flights, landing)
    end select
    self%take_off_time(c) = t
    call count_flights(self, before, t)
    self%switch = SWITCH_NONE
    self%cached = .false.
    self%rhs_cached = .false.
    self%event_index(1) = self%mechanism%f + 1   ! the stall: the pelvis's rate along the slide
  end subroutine switch_build

  !> The flights' counts and airtimes after a switch at t from the open
  !> contacts `before` to the current ones.
  subroutine count_flights(self, before, t)
    class(rider_ode_t), intent(inout) :: self
    integer, intent(in) :: before
    real(wp), intent(in) :: t
    integer, parameter :: all_open = 2**N_CONTACTS - 1
    real(wp) :: com(3), velocity(3)
    call count_switch(self%flights, before, self%fly%open_mask, all_open, t, &
                      self%slide%arc_length(self%work%scalars(self%layout%u(CONTACT_PELVIS))%q))
    if (before /= all_open .and. self%fly%open_mask == all_open) then
      ! the switch evaluated the new build's positions and velocities
      call centre_of_mass(self%work, self%layout, com, velocity)
      self%flights%whole_take_off_com = com
      self%flights%whole_take_off_velocity = velocity
    end if
  end subroutine count_flights

  !> The flights' highest point: the open contacts' largest gap above the
  !> slide as the extremes located it (0 and contact 0 if none rose).
  module subroutine keep_highest(sys)
    type(rider_ode_t), intent(inout) :: sys
    integer :: k
    k = maxloc(sys%ride%extremes%value(EXTREME_GAP:EXTREME_GAP + N_CONTACTS - 1), dim=1)
    associate (x => sys%ride%extremes, j => EXTREME_GAP + k - 1, fl => sys%flights)
      if (.not. (x%located .and. x%value(j) > 0)) return
      fl%highest = x%value(j)
      fl%highest_contact = k
      fl%highest_time = x%time(j)
      fl%highest_arc_length = x%at(j)
    end associate
  end subroutine keep_highest

  !> At a record (velocities set, its extremes added): an open contact's
  !> gap that rose at the stretch's last record and falls now had its apex
  !> between the two; the extremes search that interval for it, so that a
  !> flight with no record near its apex (shorter than the output step: only
  !> its take-off and landing) still has its highest point. A gap rate above
  !> -apex_rate_noise counts as rising: the take-off's is 0 to the closure's
  !> noise, either sign.
  module subroutine watch_gap_apexes(self, kind)
    class(rider_ode_t), intent(inout) :: self
    integer, intent(in) :: kind
    !> m/s: a gap rising slower rises (1e-6)^2/(2 g) ~ 5e-14 m more
    real(wp), parameter :: apex_rate_noise = 1e-6_wp
    real(wp) :: rate
    integer :: k
    do k = 1, N_CONTACTS
      if (.not. btest(self%fly%open_mask, k - 1)) then
        self%gap_rising(k) = .false.
        cycle
      end if
      rate = contact_gap_rate(self%work, self%layout, k)
      ! a stretch's first record follows the last build's at the same time
      if (self%gap_rising(k) .and. rate < 0 .and. kind /= RECORD_START) &
        call self%extremes%add_bracket(EXTREME_GAP + k - 1)
      self%gap_rising(k) = rate > -apex_rate_noise
    end do
  end subroutine watch_gap_apexes

  !> The ride ended at t with contacts open: their flight counts up to t.
  module subroutine end_flights(self, t)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer :: before
    before = self%fly%open_mask
    self%fly%open_mask = 0
    call count_flights(self, before, t)
    self%fly%open_mask = before
  end subroutine end_flights
end submodule rider_ride_flight
