!> The heels' flight in the ride (rider_heels_flight; docs/rider.md
!> "Flight"): the gap's root, its events, and the switches between the plain
!> and the open build that simulate_ride's stretches go through.
submodule (rider_ride) rider_ride_flight
  implicit none (type, external)

contains

  !> The roots: the mechanism's and the stall's and stations', then, with
  !> may_fly, the heels' gap (in flight; elsewhere a constant).
  integer module function rider_root_count(self) result(n)
    class(rider_ode_t), intent(in) :: self
    n = self%mechanism_ode_t%root_count()
    if (self%may_fly) n = n + 1
  end function rider_root_count

  !> The heels' root in flight: until the gap has opened by opening_gap,
  !> (opening_gap - gap)(gap + sink_gap) (zero where it opens or sinks
  !> back), then the gap.
  module subroutine rider_roots(self, t, y, g)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    integer :: n
    type(status_t) :: st
    n = self%n_roots
    call self%mechanism_ode_t%roots(t, y, g(1:n))
    if (.not. self%may_fly) return
    if (.not. self%heels_flying) then
      g(n + 1) = 1
      return
    end if
    ! the positions at y (the closure warm from the last solution); a trial
    ! state the closure cannot reach keeps the last value
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), st)
    if (.not. st%ok()) return
    self%cached = .false.
    self%rhs_cached = .false.
    if (self%opened) then
      g(n + 1) = heels_gap(self%mechanism, self%layout)
    else
      associate (gap => heels_gap(self%mechanism, self%layout))
        g(n + 1) = (opening_gap - gap)*(gap + sink_gap)
      end associate
    end if
  end subroutine rider_roots

  !> The heels' gap root fired in flight: opened (watch the landing from now
  !> on: a restart, the root changes) or landed (a stop that asks for the
  !> landing's switch; not where the mechanism stops the ride at the same
  !> time: its stop ends the ride).
  module subroutine gap_event(self, t, y, action, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(inout) :: action
    type(status_t), intent(inout) :: status
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), status)
    if (.not. status%ok()) return
    if (.not. self%opened .and. heels_gap(self%mechanism, self%layout) > 0) then
      self%opened = .true.
      action = max(action, EVENT_RESTART)
      return
    end if
    if (action == EVENT_STOP) return
    self%switch = SWITCH_LANDING
    self%switch_t = t
    self%switch_y = y
    action = EVENT_STOP
  end subroutine gap_event

  !> The switch the last stop asked for, at (switch_t, switch_y): y becomes
  !> the state of the other build (or of the same, flying on after a
  !> landing's rebound).
  module subroutine switch_build(self, y, status)
    class(rider_ode_t), intent(inout) :: self
    real(wp), allocatable, intent(inout) :: y(:)
    type(status_t), intent(inout) :: status
    real(wp) :: residual, t
    real(wp), allocatable :: y_open(:), y_plain(:)
    type(impact_outcome_t) :: impact
    type(heels_landing_t) :: landing
    real(wp) :: closing(3), closing_energy
    logical :: closed
    integer :: f
    t = self%switch_t
    ! the ride goes on: the stop's words and codes were not its end
    self%ending = RIDE_FAILED
    self%lifted_contact = 0
    self%outcome = ''
    select case (self%switch)
    case (SWITCH_TAKE_OFF)
      f = self%mechanism%f
      call self%mechanism%evaluate(self%work, t, self%switch_y(1:f), self%switch_y(f + 1:2*f), residual, status)
      if (.not. status%ok()) return
      allocate (y_open(self%flight_size))
      call take_off_state(self%mechanism, self%layout, self%switch_y, y_open)
      call use_build(self, self%open, y_open, y)
      self%heels_flying = .true.
      self%opened = .false.
      self%flights%flights = self%flights%flights + 1
      self%flights%take_off_time = t
      self%flights%take_off_arc_length = self%slide%arc_length(y(1))
    case (SWITCH_LANDING)
      y_open = self%switch_y
      call heels_impact(self%mechanism, self%work, self%layout, t, y_open, self%landing, impact, closed, closing, &
                        closing_energy, status)
      if (.not. status%ok()) return
      landing%time = t
      landing%arc_length = self%slide%arc_length(self%mechanism%scalars(self%layout%u(CONTACT_HEELS))%q)
      landing%normal_speed = -impact%normal_speed_before
      landing%impulse = norm2(impact%impulse + closing)
      landing%normal_impulse = impact%normal_impulse + norm2(closing)
      landing%drop_height = landing%normal_speed**2/(2*self%gravity)
      landing%energy_lost = impact%energy_lost + closing_energy
      landing%closed = closed
      call add_airtime(self%flights, t)
      if (t - self%flights%take_off_time < quick_flight) then
        self%quick_landings = self%quick_landings + 1
      else
        self%quick_landings = 0
      end if
      if (self%quick_landings > max_quick_landings) then
        call set_status(status, STATUS_DOMAIN, 'the heels neither stay on the slide nor leave it (landing '// &
                        'after landing within '//format_short(quick_flight)//' s)'//' at t = '//format_short(t)//' s')
        return
      end if
      if (closed) then
        allocate (y_plain(size(y_open) - 2))
        call landing_state(y_open, y_plain)
        call use_build(self, self%plain, y_plain, y)
        ! pressing again? Else the heels fly on from the slide (their normal
        ! force would pull: the free motion leaves it)
        f = self%mechanism%f
        call self%mechanism%evaluate(self%work, t, y(1:f), y(f + 1:2*f), residual, status)
        if (.not. status%ok()) return
        if (self%mechanism%contacts(self%layout%contact(CONTACT_HEELS))%normal_force > 0) then
          self%heels_flying = .false.
        else
          landing%closed = .false.
          call take_off_state(self%mechanism, self%layout, y, y_open)
          call use_build(self, self%open, y_open, y)
        end if
      else
        y = y_open
      end if
      call add_landing(self%flights, landing)
      if (self%heels_flying) then
        self%opened = .false.
        self%flights%flights = self%flights%flights + 1
        self%flights%take_off_time = t
        self%flights%take_off_arc_length = self%slide%arc_length(y(1))
      end if
    end select
    self%switch = SWITCH_NONE
    self%cached = .false.
    self%rhs_cached = .false.
    self%event_index(1) = self%mechanism%f + 1   ! the stall: the pelvis's rate along the slide
  end subroutine switch_build

  !> The build `next` takes over at state y_next from the current one: every
  !> scalar's value (its closure starts there), the laws' switches (the
  !> water drag), the work integrals (in y_next).
  subroutine use_build(self, next, y_next, y)
    class(rider_ode_t), intent(inout) :: self
    type(mechanism_t), intent(in) :: next
    real(wp), intent(in) :: y_next(:)
    real(wp), allocatable, intent(inout) :: y(:)
    type(mechanism_t) :: current
    integer :: k, f
    current = self%mechanism
    self%mechanism = next
    self%mechanism%scalars(:)%q = current%scalars(:)%q
    do k = 1, current%n_laws
      self%mechanism%laws(k)%law%active = current%laws(k)%law%active
    end do
    self%mechanism%warm = .false.
    self%mechanism%converged = .false.
    if (allocated(self%charts)) deallocate (self%charts, self%chart_angle)
    f = self%mechanism%f
    y = self%initial_state(y_next(1:f), y_next(f + 1:2*f))
    y(2*f + 1:) = y_next(2*f + 1:)
  end subroutine use_build

  !> A flight ended at t: its airtime into the totals.
  subroutine add_airtime(flights, t)
    type(ride_flights_t), intent(inout) :: flights
    real(wp), intent(in) :: t
    real(wp) :: airtime
    airtime = t - flights%take_off_time
    flights%airtime = flights%airtime + airtime
    if (airtime > flights%longest) then
      flights%longest = airtime
      flights%longest_time = flights%take_off_time
      flights%longest_arc_length = flights%take_off_arc_length
    end if
  end subroutine add_airtime

  !> The heels' largest gap so far, at a record in flight (positions set).
  module subroutine track_highest(self, t)
    class(rider_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp) :: gap
    gap = heels_gap(self%mechanism, self%layout)
    if (gap > self%flights%highest) then
      self%flights%highest = gap
      self%flights%highest_time = t
      self%flights%highest_arc_length = self%slide%arc_length(self%mechanism%scalars(self%layout%u(CONTACT_HEELS))%q)
    end if
  end subroutine track_highest

  !> State y of either build in the flight layout [q(3), phi_U, s(3), phi_U',
  !> W] (the plain build's phi_U and its rate from its last evaluation).
  module subroutine flight_layout_state(self, y, state)
    class(rider_ode_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    real(wp), intent(out) :: state(:)
    if (self%heels_flying) then
      state = y
    else
      associate (phi => self%mechanism%scalars(self%layout%flexion))
        state = [y(1:3), phi%q, y(4:6), phi%qd, y(7:)]
      end associate
    end if
  end subroutine flight_layout_state
end submodule rider_ride_flight
