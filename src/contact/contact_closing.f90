!> Phases of a contact that opens and closes (issue 25): a flight
!> (contact_flight) whose landing closes the contact goes on as the closed
!> contact, and a closed contact that may open (may_open) goes on in flight
!> from its lift-off, to the end of the run.
!>
!> Closing: when an impact's rebound is below close_speed the flight stops
!> there with the contact points' normal velocity taken away
!> (contact_flight). The closed contact is then built as a `start = 'closed'`
!> run builds it (contact_model, the same description): the body's pose and
!> twist are the flight's last record's, so its contact coordinates come
!> from the contact search at that pose (the foot points: nearest_point and
!> support_point of geometry_foot_point, the body moved along the normal by
!> the gap that is left, ~1e-14 m at a located root) and its speeds are the
!> least-squares fit of that twist, which the closed contact allows (no
!> normal velocity, no slip where it rolls: the closing impulse saw to it),
!> to rounding.
!>
!> Opening: a closed contact's lift-off (its normal force falling to zero:
!> the mechanism's lift-off event, which ends any other closed run) with
!> may_open places the free body at the closed contact's last record, its
!> pose and twist (contact_flight restart_flight: a free body takes any
!> twist exactly), and it flies on: it may land again (with restitution) and
!> close again.
!>
!> Each phase starts where the last stopped, on the run's output grid, and
!> its records are joined to the others' (kinetostatics_recorder
!> join_series): both records at a switch are kept, the last of one phase
!> and the first of the next (the same pose and twist to rounding; the
!> second marked an event, record_kind 3); the force laws' work goes on
!> across the switch (carry_work). Coordinates of one phase are 0 in
!> the other's records (the result's `open` says which: 1 in flight); in the
!> flight's records the contact's point is the gap's point on shape_1, its
!> velocity the body's nearest point's along the surface, its normal force 0.
module contact_closing
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, add_driver_result, DRIVE_EVENT_STOP, &
    DRIVE_FAILED, RECORD_EVENT
  use kinetostatics_recorder, only: mechanism_series_t, join_series
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_LIFT_OFF
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model
  use contact_flight, only: flight_ode_t, build_flight, restart_flight, touching_gap_limit
  implicit none (type, external)
  private
  public :: drive_flight, close_contact, flight_after_closed

  !> The joined records of a run's phases as they come.
  type :: phases_t
    type(mechanism_series_t) :: series
    character(len=8), allocatable :: q_units(:), beta_units(:)
    integer, allocatable :: in_flight(:)                   ! per record: 1 in flight, 0 closed
    real(wp), allocatable :: point(:, :), velocity(:, :)   ! 3 x records: the flight's gap point and velocity
    character(len=:), allocatable :: history               ! every phase's outcome
  contains
    procedure :: add => phases_add
    procedure :: finish => phases_finish
  end type phases_t

contains

  !> Drives the run's phases from y0 (numerics_event_driver drive each): the
  !> flight (from y0), or the closed contact first when the flight was built
  !> after it (start_closed: from flight%closed%y0); a flight whose landing
  !> closes the contact goes on closed, a closed contact that lifts off and
  !> may open goes on in flight, until the end time or another stop.
  !> flight%series becomes the joined records, flight%q_units and
  !> beta_units their units, in_flight the phase of each record (1 in
  !> flight, 0 closed), flight%outcome every phase's; result sums the
  !> drives (its outcome, time and fired roots the last's).
  subroutine drive_flight(flight, y0, options, result, status, in_flight)
    type(flight_ode_t), intent(inout), target :: flight
    real(wp), intent(in) :: y0(:)
    type(driver_options_t), intent(in) :: options
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    integer, allocatable, intent(out) :: in_flight(:)   ! per record: 1 in flight, 0 closed
    type(phases_t) :: run
    type(driver_options_t) :: phase_options
    type(driver_result_t) :: phase
    real(wp), allocatable :: y(:)
    logical :: flying, first, next
    integer :: chart_changes, n
    flying = .not. flight%start_closed
    y = y0
    if (.not. flying) y = flight%closed%y0
    phase_options = options
    if (.not. options%output_origin < huge(1.0_wp)) phase_options%output_origin = options%t_start
    first = .true.
    chart_changes = 0
    allocate (run%in_flight(0), run%point(3, 0), run%velocity(3, 0))
    run%history = ''
    do
      if (flying) then
        flight%closing = .false.
        if (.not. first) call flight%start_series(16)
        call drive(flight, y, phase_options, phase, status)
        n = flight%series%n
        call run%add(flight%series, flight%q_units, flight%beta_units, 1, flight%outcome)
        if (n > 0) then
          run%point = reshape([run%point, flight%gap_point(:, :n)], [3, size(run%in_flight)])
          run%velocity = reshape([run%velocity, flight%gap_velocity(:, :n)], [3, size(run%in_flight)])
        end if
        next = status%ok() .and. phase%outcome == DRIVE_EVENT_STOP .and. flight%closing .and. &
               phase%t < options%t_end
        if (next) then
          if (allocated(flight%closed)) deallocate (flight%closed)
          allocate (flight%closed)
          call close_contact(flight, flight%closed, status)
          if (.not. status%ok()) call prefix_status(status, 'closing the contact at t = '//format_short(phase%t)//' s')
          y = flight%closed%y0
          if (status%ok()) call carry_work(run%series, flight%closed%ode, y)
        end if
      else
        call flight%closed%ode%start_series(16)
        call drive(flight%closed%ode, y, phase_options, phase, status)
        chart_changes = chart_changes + flight%closed%ode%chart_changes
        next = status%ok() .and. phase%outcome == DRIVE_EVENT_STOP .and. &
               flight%closed%ode%stop_kind == STOP_LIFT_OFF .and. flight%system%contacts(1)%may_open .and. &
               phase%t < options%t_end
        if (next) flight%closed%ode%outcome = flight%closed%ode%outcome//': the contact opens (may_open), '// &
                                              'the body flies'
        call run%add(flight%closed%ode%series, flight%closed%q_units, flight%closed%beta_units, 0, &
                     flight%closed%ode%outcome)
        n = flight%closed%ode%series%n
        run%point = reshape([run%point, spread(0.0_wp, 1, 3*n)], [3, size(run%in_flight)])
        run%velocity = reshape([run%velocity, spread(0.0_wp, 1, 3*n)], [3, size(run%in_flight)])
        if (next) then
          associate (s => flight%closed%ode%series)
            call restart_flight(flight, s%body_rot(:, :, 1, n), s%body_r(:, 1, n), &
                                [s%body_omega(:, 1, n), s%body_v(:, 1, n)], y, status)
          end associate
          if (.not. status%ok()) call prefix_status(status, 'the lift-off into flight at t = '// &
                                                    format_short(phase%t)//' s')
          if (status%ok()) call carry_work(run%series, flight, y)
        end if
      end if
      call add_result(result, phase, first)
      if (next .and. .not. status%ok()) result%outcome = DRIVE_FAILED
      if (.not. (next .and. status%ok())) exit
      flying = .not. flying
      first = .false.
      phase_options%t_start = phase%t
    end do
    call run%finish(flight)
    flight%chart_changes = flight%chart_changes + chart_changes
    in_flight = run%in_flight
  end subroutine drive_flight

  !> The work integrals of the next phase's state y (mechanism_ode_t: y =
  !> [q, s, W]) start where the run's records so far end, law by law by name
  !> (the air's drag acts in flight and closed alike, contact_factory
  !> add_air_drag): the work of the whole run, so that its energy balance
  !> holds across the phases. A law new in the run starts at 0.
  subroutine carry_work(series, next, y)
    type(mechanism_series_t), intent(in) :: series
    class(mechanism_ode_t), intent(in) :: next
    real(wp), intent(inout) :: y(:)
    character(len=len(series%law_names)) :: name
    integer :: k, j, n
    n = next%mechanism%f + next%mechanism%ns
    if (series%n < 1) return
    do k = 1, next%mechanism%n_laws
      name = next%mechanism%laws(k)%law%name
      j = findloc([(series%law_names(j) == name, j = 1, series%nl)], .true., dim=1)
      if (j > 0) y(n + k) = series%law_work(j, series%n)
    end do
  end subroutine carry_work

  !> result := phase (the first) or the sum of both (the outcome, time and
  !> fired roots the later's).
  subroutine add_result(result, phase, first)
    type(driver_result_t), intent(inout) :: result
    type(driver_result_t), intent(in) :: phase
    logical, intent(in) :: first
    if (first) then
      result = phase
      return
    end if
    call add_driver_result(result, phase)
  end subroutine add_result

  !> Appends a phase's records (phase 1 in flight, 0 closed) and its outcome.
  subroutine phases_add(self, series, q_units, beta_units, phase, outcome)
    class(phases_t), intent(inout) :: self
    type(mechanism_series_t), intent(in) :: series
    character(len=*), intent(in) :: q_units(:), beta_units(:), outcome
    integer, intent(in) :: phase
    integer :: n1
    if (.not. allocated(self%series%q_names)) then
      self%series = series
      self%q_units = q_units
      self%beta_units = beta_units
    else
      n1 = self%series%n
      self%q_units = united_units(self%series%q_names, self%q_units, series%q_names, q_units)
      self%beta_units = united_units(self%series%beta_names, self%beta_units, series%beta_names, beta_units)
      self%series = join_series(self%series, series)
      ! a phase's start is a switch, an event of the run
      if (self%series%n > n1) self%series%kind(n1 + 1) = RECORD_EVENT
    end if
    self%in_flight = [self%in_flight, spread(phase, 1, series%n)]
    if (len(outcome) == 0) return
    if (len(self%history) > 0) self%history = self%history//'; '
    self%history = self%history//outcome
  end subroutine phases_add

  !> The joined records into the flight: its series (the contact's point and
  !> velocity in flight from the gap's records; bodies on the closed
  !> contact's frames, whose mechanism reports the run), units and outcome.
  subroutine phases_finish(self, flight)
    class(phases_t), intent(inout) :: self
    type(flight_ode_t), intent(inout) :: flight
    integer :: c, i, k, j
    associate (s => self%series)
      c = findloc([(trim(s%contact_names(k)) == flight%contact_name, k = 1, s%nc)], .true., dim=1)
      if (c > 0) then
        do i = 1, s%n
          if (self%in_flight(i) == 0) cycle
          s%contact_r(:, c, i) = self%point(:, i)
          s%slip(:, c, i) = self%velocity(:, i)
        end do
      end if
      if (allocated(flight%closed)) then
        associate (closed => flight%closed%ode%series)
          do k = 1, s%nb
            j = findloc([(closed%body_names(j) == s%body_names(k), j = 1, closed%nb)], .true., dim=1)
            if (j > 0) s%body_frame(k) = closed%body_frame(j)
          end do
        end associate
      end if
    end associate
    call move_alloc(self%q_units, flight%q_units)
    call move_alloc(self%beta_units, flight%beta_units)
    flight%series = self%series
    flight%outcome = self%history
  end subroutine phases_finish

  !> The units of join_series's united names: a's, then those of b's names
  !> not in a.
  function united_units(names_a, units_a, names_b, units_b) result(units)
    character(len=*), intent(in) :: names_a(:), names_b(:)
    character(len=*), intent(in) :: units_a(:), units_b(:)
    character(len=8), allocatable :: units(:)
    integer :: k, j
    units = units_a
    do k = 1, size(names_b)
      if (any([(names_a(j) == names_b(k), j = 1, size(names_a))])) cycle
      units = [character(len=8) :: units, units_b(k)]
    end do
  end function united_units

  !> The flight of a closed contact that may open (may_open): the free body
  !> built at the closed model's start pose and twist (touching shape_1),
  !> holding the model, driven closed first (drive_flight). q0, qd0, q_units
  !> as build_flight's.
  subroutine flight_after_closed(system, model, flight, q0, qd0, q_units, status)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(in) :: model
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    type(contact_system_t) :: placed
    if (.not. status%ok()) return
    placed = system
    associate (body => model%ode%work%frames(model%body_frame(2)))
      placed%bodies(1)%position = body%r
      placed%bodies(1)%rotation = body%rot
      placed%bodies(1)%velocity = body%v
      placed%bodies(1)%angular_velocity = body%omega
    end associate
    call build_flight(placed, flight, q0, qd0, q_units, status, touching=.true.)
    if (.not. status%ok()) return
    flight%start_closed = .true.
    allocate (flight%closed, source=model)
  end subroutine flight_after_closed

  !> The closed contact at the flight's last record: its description with
  !> the contact closed and the body at the record's pose and twist, built
  !> and started (contact_model); refused (STATUS_DOMAIN) if the body had to
  !> move more than touching_gap_limit to touch.
  subroutine close_contact(flight, model, status)
    type(flight_ode_t), intent(in) :: flight
    type(contact_model_t), intent(out) :: model
    type(status_t), intent(inout) :: status
    type(contact_system_t) :: system
    integer :: n
    system = flight%system
    n = flight%series%n
    system%contacts(1)%start_open = .false.
    system%bodies(1)%position = flight%series%body_r(:, 1, n)
    system%bodies(1)%rotation = flight%series%body_rot(:, :, 1, n)
    system%bodies(1)%velocity = flight%series%body_v(:, 1, n)
    system%bodies(1)%angular_velocity = flight%series%body_omega(:, 1, n)
    call build_contact_model(system, model, status)
    if (.not. status%ok()) return
    if (.not. abs(model%links(1)%start_gap) <= touching_gap_limit) &
      call set_status(status, STATUS_DOMAIN, 'contact '''//system%contacts(1)%name//''': the closed contact '// &
        'moved the body by '//format_short(model%links(1)%start_gap)//' m to touch (more than '// &
        format_short(touching_gap_limit)//' m): the landing pose is not a touching one')
  end subroutine close_contact

end module contact_closing
