!> A flying vehicle's ride stretch by stretch (rider_vehicle_flight, whose
!> header gives the builds and the roots; docs/vehicles.md "Flight").
!>
!> Each stretch between switches is driven on its own (drive_vehicle), its
!> ride figures computed with its build (vehicle_ride_figures), its records
!> written in the full layout (full_records) and joined to the others'
!> (join_series: a dependent of one build is 0 in the others' records;
!> open_mask says which contacts were open).
!>
!> A switch (switch_build) follows the stop that asked for it: a take-off,
!> a landing's impact (kinetostatics_point_impact) or the other solved
!> coordinate; the next build takes over at the full layout's state
!> (use_build), every closed contact then pressing or opening too
!> (press_or_open).
submodule (rider_vehicle_flight) rider_vehicle_flight_stretches
  use base_text, only: format_real
  use base_status, only: set_status, STATUS_DOMAIN
  use numerics_event_driver, only: drive, add_driver_result, DRIVE_EVENT_STOP
  use kinetostatics_recorder, only: mechanism_series_t, join_series
  use kinetostatics_impact, only: impact_outcome_t
  use kinetostatics_point_impact, only: point_gap_rate, point_impact, sink_gap
  use rider_vehicle_roll, only: stop_coordinate, landing_cause
  use rider_flight, only: rider_landing_t, add_landing, close_speed, landing_record, quick_landings_exceeded, &
    quick_flight, count_switch
  use rider_vehicle, only: vehicle_ride_figures
  use rider_vehicle_layout, only: open_words, LIFT, ROLL
  implicit none (type, external)

contains

  module procedure drive_vehicle
    type(driver_options_t) :: stretch_options
    type(driver_result_t) :: stretch
    type(mechanism_series_t) :: joined
    real(wp), allocatable :: y(:), speed(:), felt(:, :)
    real(wp) :: lost
    logical :: first, next
    type(status_t) :: records   ! of the stretch's records in the full layout
    type(status_t) :: figures   ! of the stretch's ride figures
    stretch_options = options
    if (.not. options%output_origin < huge(1.0_wp)) stretch_options%output_origin = options%t_start
    allocate (sys%open_record(0), sys%speed(0), sys%felt(3, 0), sys%losses(0))
    y = y0
    first = .true.
    do
      if (.not. first) call sys%start_series(16)
      call drive(sys, y, stretch_options, stretch, status)
      if (first) then
        result = stretch
      else
        call add_driver_result(result, stretch)
      end if
      if (len(sys%history) > 0 .and. len(sys%outcome) > 0) sys%history = sys%history//'; '
      sys%history = sys%history//sys%outcome
      ! the stretch's figures with its own build (its records are its
      ! layout), then its records in the full layout (also those of a
      ! stretch that failed: they are written, its figures with them)
      if (sys%series%n > 0) then
        figures = status_t()
        call vehicle_ride_figures(sys%mechanism, sys%work, sys%series, speed, felt, figures)
        if (figures%ok()) then
          sys%speed = [sys%speed, speed]
          sys%felt = reshape([sys%felt, felt], [3, size(sys%speed)])
        end if
        if (status%ok() .and. .not. figures%ok()) status = figures
        records = status_t()
        call full_records(sys, records)
        if (status%ok() .and. .not. records%ok()) status = records
      end if
      sys%open_record = [sys%open_record, spread(sys%open_mask, 1, sys%series%n)]
      ! a landing starts a stretch: its energy counts from the next one's records
      lost = 0
      if (sys%flights%landings > 0) lost = sum(sys%flights%landing%energy_lost)
      sys%losses = [sys%losses, spread(lost, 1, sys%series%n)]
      if (first) then
        joined = sys%series
      else
        joined = join_series(joined, sys%series)
      end if
      next = status%ok() .and. stretch%outcome == DRIVE_EVENT_STOP .and. sys%switch /= SWITCH_NONE .and. &
             stretch%t < options%t_end
      if (.not. next) exit
      call switch_build(sys, y, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'the vehicle''s '//trim(merge('take-off', 'landing ', &
                           sys%switch == SWITCH_TAKE_OFF))//' at t = '//format_short(sys%switch_t)//' s')
        exit
      end if
      stretch_options%t_start = sys%switch_t
      first = .false.
    end do
    ! a flight under way at the end counts up to there
    if (sys%open_mask /= 0) call count_flights(sys, sys%open_mask, 0, result%t)
    sys%series = joined
    sys%outcome = sys%history
  end procedure drive_vehicle

  !> The switch the last stop asked for, at (switch_t, switch_y): y becomes
  !> the state of the next build (or of the same, flying on after a
  !> landing's rebound).
  subroutine switch_build(self, y, status)
    type(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), allocatable, intent(inout) :: y(:)
    type(status_t), intent(inout) :: status
    real(wp) :: residual, t, closing(3), closing_energy, roll_energy, approach
    real(wp), allocatable :: y_open(:), full(:)
    type(impact_outcome_t) :: impact
    type(rider_landing_t) :: landing
    logical :: closed, last
    integer :: f, c, before
    t = self%switch_t
    c = self%switch_contact
    before = self%open_mask
    f = self%mechanism%f
    select case (self%switch)
    case (SWITCH_SOLVE)
      ! the same open contacts, the front's closure solving the other coordinate
      call self%mechanism%evaluate(self%work, t, self%switch_y(1:f), self%switch_y(f + 1:2*f), residual, status)
      if (.not. status%ok()) return
      full = full_state(self, self%switch_y)
      call use_build(self, before, full, y, status, 3 - self%solved)
      self%solve_switches = self%solve_switches + 1
      self%switch = SWITCH_NONE
      self%cached = .false.
      self%rhs_cached = .false.
      self%margin_stored = .false.
      return
    case (SWITCH_TAKE_OFF)
      call self%mechanism%evaluate(self%work, t, self%switch_y(1:f), self%switch_y(f + 1:2*f), residual, status)
      if (.not. status%ok()) return
      full = full_state(self, self%switch_y)
      call use_build(self, ibset(before, c - 1), full, y, status)
      self%opened(c) = .false.
      self%history = self%history//': the '//trim(vehicle_contact_names(c))//' contact opens (may_fly)'
      if (status%ok()) call press_or_open(self, t, y, status)
    case (SWITCH_LANDING)
      y_open = self%switch_y
      roll_energy = 0
      last = ibclr(before, c - 1) == 0
      call self%mechanism%set_positions(self%work, y_open(1:f), status)
      if (.not. status%ok()) return
      call self%mechanism%set_velocities(self%work, y_open(f + 1:2*f))
      approach = point_gap_rate(self%work, self%point(c), self%foot(c))
      if (last) then
        ! on both contacts the roll is held: its rate stops, then the
        ! contact's impact with the roll held
        call stop_coordinate(self%mechanism, self%work, y_open, findloc(self%mechanism%q, self%full(ROLL), dim=1), &
                             roll_energy, status)
        if (.not. status%ok()) return
        full = full_state(self, y_open)
        call use_build(self, before, full, y_open, status, held=.true.)
        if (.not. status%ok()) return
      end if
      call point_impact(self%mechanism, self%work, self%point(c), self%foot(c), trim(vehicle_contact_names(c))// &
                        ' contact', y_open, self%vehicle%landing, close_speed, impact, closed, closing, &
                        closing_energy, status)
      if (.not. status%ok()) then
        status%message = status%message//landing_cause(trim(vehicle_contact_names(c)), self%opened(c), &
          t - self%take_off_time(c), sink_gap, last, last, approach)
        return
      end if
      landing = landing_record(t, c, where_foot(self, c), impact, closing, closing_energy + roll_energy, closed, &
                               self%gravity)
      if (quick_landings_exceeded(self%quick_landings, t - self%take_off_time(c))) then
        call set_status(status, STATUS_DOMAIN, 'the '//trim(vehicle_contact_names(c))//' contact neither stays on '// &
                        'the slide nor leaves it (landing after landing within '//format_short(quick_flight)//' s)')
        return
      end if
      ! the positions at y_open and the speeds after the impact are set
      full = full_state(self, y_open)
      if (closed) then
        call use_build(self, ibclr(before, c - 1), full, y, status)
        if (status%ok()) call press_or_open(self, t, y, status)
        if (.not. status%ok()) return
        ! the landing one pulls: it did not stay on, it flies on from the slide
        landing%closed = .not. btest(self%open_mask, c - 1)
      else if (last) then
        ! it flies on, its roll free again from rest
        call use_build(self, before, full, y, status)
        if (.not. status%ok()) return
      else
        y = y_open
      end if
      self%history = self%history//': '//trim(merge('it stays on', 'it flies on', landing%closed))
      self%opened(c) = .false.
      call add_landing(self%flights, landing)
    end select
    self%take_off_time(c) = t
    call count_flights(self, before, self%open_mask, t)
    self%switch = SWITCH_NONE
    self%cached = .false.
    self%rhs_cached = .false.
    self%margin_stored = .false.
  end subroutine switch_build

  module procedure press_or_open
    real(wp), allocatable :: full(:)
    real(wp) :: residual
    integer :: after, k, f
    f = self%mechanism%f
    call self%mechanism%evaluate(self%work, t, y(1:f), y(f + 1:2*f), residual, status)
    if (.not. status%ok()) return
    after = self%open_mask
    do k = 1, 2
      if (.not. btest(after, k - 1) .and. .not. self%work%normal_force(self%contact(k)) > 0) after = ibset(after, k - 1)
    end do
    if (after == self%open_mask) return
    do k = 1, 2
      if (btest(after, k - 1) .and. .not. btest(self%open_mask, k - 1)) then
        self%opened(k) = .false.
        self%take_off_time(k) = t
      end if
    end do
    self%history = self%history//': the contacts then open ('//trim(open_words(after))//')'
    full = full_state(self, y)
    call use_build(self, after, full, y, status)
  end procedure press_or_open

  !> Where the vehicle is: the rear contact's arc length on a slide (else
  !> its u).
  real(wp) function where_now(self) result(s)
    class(vehicle_flight_ode_t), intent(in) :: self
    s = where_foot(self, 1)
  end function where_now

  module procedure where_foot
    if (present(work)) then
      s = work%scalars(self%mechanism%scalar_index(trim(merge('u ', 'u2', c == 1))))%q
    else
      s = self%work%scalars(self%mechanism%scalar_index(trim(merge('u ', 'u2', c == 1))))%q
    end if
    if (.not. allocated(self%ground)) return
    select type (g => self%ground)
    class is (slide_surface_t)
      s = g%arc_length(s)
    end select
  end procedure where_foot

  !> The full layout's state [q(N_FULL), q'(N_FULL), W] at state y of the
  !> build in use, its positions and velocities set (an evaluation at y).
  function full_state(self, y) result(full)
    type(vehicle_flight_ode_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    real(wp), allocatable :: full(:)
    full = [self%work%scalars(self%full)%q, self%work%scalars(self%full)%qd, y(2*self%mechanism%f + 1:)]
  end function full_state

  !> The build of the open contacts `mask` takes over at the full layout's
  !> state `full`: every scalar's value (its closure starts there), the
  !> laws' switches (the water's drag), the work integrals; y its state.
  !> With the front on, its closure solves `solve` if given; else the
  !> coordinate it solved, unless that has degraded (solve_ratio), or, after
  !> a flight of the front, the better of the two (solve_columns at the
  !> positions in the work now, the pose of `full`). With `held` (a contact
  !> open) the build that holds the roll (held, held_yaw). A
  !> held coordinate's rate is 0 (the roll's stopped before a landing, a
  !> closed rear's lift's by its closing).
  subroutine use_build(self, mask, full, y, status, solve, held)
    type(vehicle_flight_ode_t), intent(inout) :: self
    integer, intent(in) :: mask
    real(wp), intent(in) :: full(:)
    real(wp), allocatable, intent(inout) :: y(:)
    type(status_t), intent(inout) :: status
    integer, intent(in), optional :: solve
    logical, intent(in), optional :: held
    real(wp), allocatable :: values(:), q(:), qd(:)
    real(wp) :: c(2)
    logical, allocatable :: active(:)
    integer :: k, j, f
    self%margin_stored = .false.
    values = self%work%scalars(:)%q
    active = [(self%work%laws(k)%law%active, k = 1, self%mechanism%n_laws)]
    if (mask < 2) then
      c = solve_columns(self%work, self%heading, self%point(2), self%foot(2))
      if (present(solve)) then
        self%solved = solve
      else if (self%open_mask < 2) then
        if (c(self%solved) < solve_ratio*c(3 - self%solved)) self%solved = 3 - self%solved
      else
        self%solved = merge(SOLVE_PITCH, SOLVE_YAW, c(SOLVE_PITCH) >= c(SOLVE_YAW))
      end if
      if (self%solved == SOLVE_YAW .and. present(held)) then
        self%mechanism = self%held_yaw
      else if (self%solved == SOLVE_YAW) then
        self%mechanism = self%yaw_builds(mask)
      else if (present(held)) then
        self%mechanism = self%held(mask)
      else
        self%mechanism = self%builds(mask)
      end if
    else if (present(held)) then
      self%mechanism = self%held(mask)
    else
      self%mechanism = self%builds(mask)
    end if
    self%open_mask = mask
    call self%mechanism%prepare_workspace(self%work)
    self%work%scalars(:)%q = values
    do k = 1, size(active)
      self%work%laws(k)%law%active = active(k)
    end do
    ! a closed rear holds its lift at 0 (its landing left it there, to the
    ! root's rounding); a held scalar is at rest
    if (.not. btest(mask, 0)) self%work%scalars(self%full(LIFT))%q = 0
    do k = LIFT, ROLL
      if (any(self%mechanism%q == self%full(k))) cycle
      self%work%scalars(self%full(k))%qd = 0
      self%work%scalars(self%full(k))%qdd = 0
    end do
    self%work%warm = .false.
    self%work%converged = .false.
    if (allocated(self%charts)) deallocate (self%charts, self%chart_angle)
    f = self%mechanism%f
    allocate (q(f), qd(f))
    do k = 1, f
      j = findloc(self%full, self%mechanism%q(k), dim=1)
      q(k) = full(j)
      qd(k) = full(N_FULL + j)
    end do
    y = self%initial_state(q, qd)
    y(2*f + 1:) = full(2*N_FULL + 1:)
    call self%mechanism%set_positions(self%work, q, status)
    if (status%ok()) call self%mechanism%set_velocities(self%work, qd)
    ! the margin's and the apexes' positions start from here (not from the build's start)
    if (status%ok() .and. mask < 2) self%margin_work = self%work
    if (status%ok() .and. mask > 0) self%apex_work = self%work
  end subroutine use_build

  !> The stretch's records (sys%series, in its build's layout) in the full
  !> layout: q, q', q'' of u, v, phi, pitch, rear_lift, roll at every record,
  !> whichever of them the build integrates, solves (its closure at the
  !> record's coordinates, started from the record's dependents; the rates
  !> from the record's) or holds (a closed rear's lift, 0). The dependents
  !> stay as recorded, but where the front's closure solved the heading its
  !> row is the pitch's: the cut force of front_z is one quantity whichever
  !> coordinate it solves (the joined records have one front_z), and the
  !> heading is a coordinate of the full layout.
  subroutine full_records(self, status)
    type(vehicle_flight_ode_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: q(:, :), qd(:, :), qdd(:, :)
    integer :: i, k, n, row
    n = self%series%n
    allocate (q(N_FULL, n), qd(N_FULL, n), qdd(N_FULL, n))
    associate (m => self%mechanism, s => self%series, work => self%work)
      do i = 1, n
        do k = 1, m%r
          work%scalars(m%beta(k))%q = s%beta(k, i)
        end do
        work%warm = .false.
        work%converged = .false.
        call m%set_positions(work, s%q(:, i), status)
        if (.not. status%ok()) then
          call prefix_status(status, 'the vehicle''s record at t = '//format_real(s%time(i))//' s')
          return
        end if
        call m%set_velocities(work, s%qd(:, i))
        call m%set_accelerations(work, s%qdd(:, i))
        q(:, i) = work%scalars(self%full)%q
        qd(:, i) = work%scalars(self%full)%qd
        qdd(:, i) = work%scalars(self%full)%qdd
      end do
      s%f = N_FULL
      deallocate (s%q_names)
      allocate (s%q_names(N_FULL))
      s%q_names = full_names
      s%q = q
      s%qd = qd
      s%qdd = qdd
      row = findloc(s%beta_names, 'phi', dim=1)
      if (row > 0) then
        s%beta_names(row) = 'pitch'
        s%beta(row, :n) = q(4, :)
      end if
    end associate
  end subroutine full_records

  !> The flights' counts and airtimes after a switch at t from the open
  !> contacts `before` to `now`.
  subroutine count_flights(self, before, now, t)
    type(vehicle_flight_ode_t), intent(inout) :: self
    integer, intent(in) :: before, now
    real(wp), intent(in) :: t
    call count_switch(self%flights, before, now, 3, t, where_now(self))
  end subroutine count_flights
end submodule rider_vehicle_flight_stretches
