!> Phases of contacts that open and close (issue 25): a flight
!> (contact_flight) whose landing closes a contact goes on as that contact
!> closed, and a closed contact that may open (may_open) goes on in flight
!> from its lift-off, to the end of the run. A body with several contacts
!> (the surfaces it may land on) is carried by one at a time, built alone
!> (contact_flight closed_part); the others' gaps are watched meanwhile
!> (contact_open_gaps carried_ode_t). An impact that closes several at once,
!> or a start closed on several, goes on through the phases of
!> contact_bodies (drive_phases): the body on them all (contact_loops).
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
!> Several bodies (drive_bodies): each phase is one mechanism of every body
!> as it is, carried by its closed contact or flying (contact_bodies); a
!> closing or a lift-off of one body builds the next phase from every
!> body's pose and twist at the switch, the others going on as they were.
!>
!> Each phase starts where the last stopped, on the run's output grid, and
!> its records are joined to the others' (kinetostatics_recorder
!> join_series): both records at a switch are kept, the last of one phase
!> and the first of the next (the same pose and twist to rounding; the
!> second marked an event, record_kind 3); the force laws' work goes on
!> across the switch (carry_work). Coordinates of one phase are 0 in
!> the other's records (the result's `open` says which contact is open at
!> each record); at an open contact's records its point is the gap's point
!> on shape_1, its velocity the body's nearest point's along the surface,
!> its normal force 0.
module contact_closing
  use base_kinds, only: wp
  use base_text, only: format_short, format_integer
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, add_driver_result, DRIVE_EVENT_STOP, &
    DRIVE_FAILED, RECORD_EVENT
  use kinetostatics_recorder, only: mechanism_series_t, join_series
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_LIFT_OFF, STOP_NOT_BUILT
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model
  use contact_flight, only: flight_ode_t, build_flight, restart_flight, closed_part, carrying_contact, &
    impact_on_carried
  use contact_open_gaps, only: carried_ode_t, carry, touching_gap_limit
  use contact_bodies, only: build_bodies, build_bodies_opening
  implicit none (type, external)
  private
  public :: drive_flight, close_contact, flight_after_closed

  !> The joined records of a run's phases as they come.
  type :: phases_t
    type(mechanism_series_t) :: series
    character(len=8), allocatable :: q_units(:), beta_units(:)
    integer, allocatable :: open(:, :)                     ! contacts x records: 1 open, 0 closed
    real(wp), allocatable :: gap(:, :)                     ! contacts x records, m (0 closed)
    real(wp), allocatable :: point(:, :, :), velocity(:, :, :)   ! 3 x contacts x records: point, slip
    character(len=:), allocatable :: history               ! every phase's outcome
    logical :: not_built = .false.                         ! the last phase stopped where the model is not built
  contains
    procedure :: add => phases_add
    procedure :: add_flight => phases_add_flight
    procedure :: add_carried => phases_add_carried
    procedure :: append => phases_append
    procedure :: finish => phases_finish
  end type phases_t

  interface
    ! the joined records (contact_closing_phases)
    module subroutine phases_add(self, series, q_units, beta_units, outcome)
      class(phases_t), intent(inout) :: self
      type(mechanism_series_t), intent(in) :: series
      character(len=*), intent(in) :: q_units(:), beta_units(:), outcome
    end subroutine phases_add

    module subroutine phases_add_flight(self, flight)
      class(phases_t), intent(inout) :: self
      type(flight_ode_t), intent(in) :: flight
    end subroutine phases_add_flight

    module subroutine phases_add_carried(self, carried)
      class(phases_t), intent(inout) :: self
      type(carried_ode_t), intent(in) :: carried
    end subroutine phases_add_carried

    module subroutine phases_append(self, open, gap, point, velocity)
      class(phases_t), intent(inout) :: self
      integer, intent(in) :: open(:, :)
      real(wp), intent(in) :: gap(:, :), point(:, :, :), velocity(:, :, :)
    end subroutine phases_append

    module subroutine phases_finish(self, flight)
      class(phases_t), intent(inout) :: self
      type(flight_ode_t), intent(inout) :: flight
    end subroutine phases_finish
  end interface

contains

  !> Drives the run's phases from y0 (numerics_event_driver drive each): the
  !> flight (from y0), or the closed contact first when the flight was built
  !> after it (start_closed: from flight%closed%y0); a flight whose landing
  !> closes a contact goes on closed on it, a closed contact that lifts off
  !> and may open goes on in flight, until the end time or another stop.
  !> While a contact carries the body its other contacts' gaps are watched
  !> (contact_open_gaps carried_ode_t). flight%series becomes the joined
  !> records, flight%q_units and beta_units their units, open the state of
  !> each contact at each record (1 open, 0 closed), flight%gap_point and
  !> gap_velocity every contact's point and slip at every record,
  !> flight%outcome every phase's; result sums the drives (its outcome, time
  !> and fired roots the last's).
  subroutine drive_flight(flight, y0, options, result, status, open)
    type(flight_ode_t), intent(inout), target :: flight
    real(wp), intent(in) :: y0(:)
    type(driver_options_t), intent(in) :: options
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    integer, allocatable, intent(out) :: open(:, :)   ! contacts x records: 1 open, 0 closed
    type(phases_t) :: run
    type(driver_options_t) :: phase_options
    type(driver_result_t) :: phase
    type(carried_ode_t) :: carried
    real(wp), allocatable :: y(:)
    logical :: flying, first, next, handed_over
    integer :: chart_changes, nc
    if (size(flight%system%bodies) > 1 .or. any(flight%gaps%carried)) then
      call drive_bodies(flight, y0, options, result, status, open)
      return
    end if
    flying = .not. flight%start_closed
    y = y0
    if (.not. flying) then
      y = flight%closed%y0
      call carry(flight%closed%ode, flight%closed%body_frame(2), flight%system, flight%closed_on, carried, status)
      if (.not. status%ok()) return
    end if
    nc = size(flight%system%contacts)
    call start_phases(options, nc, phase_options, run)
    first = .true.
    handed_over = .false.
    chart_changes = 0
    do
      if (flying) then
        call flight%clear_switches()
        if (.not. first) call flight%start_series(16)
        call drive(flight, y, phase_options, phase, status)
        call run%add(flight%series, flight%q_units, flight%beta_units, flight%outcome)
        call run%add_flight(flight)
        run%not_built = flight%stop_kind == STOP_NOT_BUILT
        next = status%ok() .and. phase%outcome == DRIVE_EVENT_STOP .and. flight%landed > 0 .and. &
               phase%t < options%t_end .and. .not. run%not_built
        if (next .and. size(flight%closings) > 1) then
          ! several contacts closed at once: the body on them all (contact_bodies) from here
          call add_result(result, phase, first)
          call several_closed(flight, run, phase, options, phase_options, result, chart_changes, status)
          handed_over = .true.
          exit
        end if
        if (next) then
          flight%closed_on = flight%landed
          if (allocated(flight%closed)) deallocate (flight%closed)
          allocate (flight%closed)
          call close_contact(flight, flight%closed, status)
          if (status%ok()) call carry(flight%closed%ode, flight%closed%body_frame(2), flight%system, &
                                      flight%closed_on, carried, status)
          if (.not. status%ok()) call prefix_status(status, 'closing the contact at t = '//format_short(phase%t)//' s')
          y = flight%closed%y0
          if (status%ok()) call carry_work(run%series, flight%closed%ode, y)
        end if
      else
        call carried%start_series(16)
        call drive(carried, y, phase_options, phase, status)
        chart_changes = chart_changes + carried%chart_changes
        run%not_built = carried%stop_kind == STOP_NOT_BUILT
        next = status%ok() .and. phase%outcome == DRIVE_EVENT_STOP .and. carried%stop_kind == STOP_LIFT_OFF .and. &
               flight%system%contacts(flight%closed_on)%may_open .and. phase%t < options%t_end
        if (next) carried%outcome = carried%outcome//': the contact opens (may_open), the body flies'
        call run%add(carried%series, flight%closed%q_units, flight%closed%beta_units, carried%outcome)
        call run%add_carried(carried)
        flight%closed%ode = carried%mechanism_ode_t
        if (.not. next .and. status%ok() .and. phase%outcome == DRIVE_EVENT_STOP .and. carried%touched > 0 .and. &
            phase%t < options%t_end) then
          ! it lands on another contact while carried: the impact through both, the phases of contact_bodies on
          call add_result(result, phase, first)
          call impact_while_carried(flight, carried, run, phase, options, phase_options, result, chart_changes, &
                                    status)
          handed_over = .true.
          exit
        end if
        if (next) then
          associate (s => carried%series, n => carried%series%n)
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
    call fail_where_not_built(run, flight, result, status)
    if (handed_over) call on_first_frames(flight)
    flight%chart_changes = flight%chart_changes + chart_changes
    open = run%open
  end subroutine drive_flight

  !> A closed phase of one body (carried) that stopped where it touched
  !> another of its contacts (carried%touched): the body carried by its
  !> closed contact as a phase of contact_bodies (build_bodies at the last
  !> record's pose and twist, the touched contact touching), the impact
  !> through both (contact_flight impact_on_carried), and the run's phases
  !> on from there (drive_phases) with the contacts it closed and opened and
  !> the body's twist after it. An impact that ends the run (said so in the
  !> outcome) ends it here.
  subroutine impact_while_carried(flight, carried, run, phase, options, phase_options, result, chart_changes, status)
    type(flight_ode_t), intent(inout), target :: flight
    type(carried_ode_t), intent(in) :: carried
    type(phases_t), intent(inout) :: run
    type(driver_result_t), intent(in) :: phase
    type(driver_options_t), intent(in) :: options
    type(driver_options_t), intent(inout) :: phase_options
    type(driver_result_t), intent(inout) :: result
    integer, intent(inout) :: chart_changes
    type(status_t), intent(inout) :: status
    type(flight_ode_t), allocatable :: hit
    type(contact_system_t) :: placed
    real(wp), allocatable :: q0(:), qd0(:)
    character(len=8), allocatable :: units(:)
    logical :: closed(size(flight%system%contacts)), lands(size(flight%system%contacts))
    integer :: action
    placed = flight%system
    associate (s => carried%series, n => carried%series%n)
      placed%bodies(1)%position = s%body_r(:, 1, n)
      placed%bodies(1)%rotation = s%body_rot(:, :, 1, n)
      placed%bodies(1)%velocity = s%body_v(:, 1, n)
      placed%bodies(1)%angular_velocity = s%body_omega(:, 1, n)
    end associate
    closed = .false.
    closed(flight%closed_on) = .true.
    allocate (hit)
    call build_bodies(placed, closed, hit, q0, qd0, units, status, carried%touched, .true.)
    if (status%ok()) then
      hit%impacts = flight%impacts
      hit%outcome = ''
      call hit%clear_switches()
      lands = .false.
      lands(carried%touched) = .true.
      action = 0
      ! the pose and twist of the last record (build_bodies's start), the gaps there
      call hit%mechanism%set_positions(hit%work, q0, status)
      if (status%ok()) call hit%mechanism%set_velocities(hit%work, qd0)
      if (status%ok()) call hit%gaps%update(hit%work, hit%body_frame, status)
      if (status%ok()) call impact_on_carried(hit, lands, phase%t, action, status)
    end if
    if (.not. status%ok()) then
      call prefix_status(status, 'the impact on the carried body at t = '//format_short(phase%t)//' s')
      result%outcome = DRIVE_FAILED
      return
    end if
    flight%impacts = hit%impacts
    run%history = run%history//': '//hit%outcome
    run%not_built = hit%stop_kind == STOP_NOT_BUILT
    if (.not. hit%twisted(1)) return   ! the impact ended the run, saying why
    closed = hit%gaps%carried
    closed(hit%closings) = .true.
    if (size(hit%openings) > 0) closed(hit%openings) = .false.
    placed%bodies(1)%angular_velocity = hit%twist_after(1:3, 1)
    placed%bodies(1)%velocity = hit%twist_after(4:6, 1)
    lands = .false.
    lands(hit%bounced) = .true.   ! those left at gap 0
    call phases_from(flight, placed, closed, lands, 'after the impact on the carried body', run, phase, options, &
                     phase_options, result, chart_changes, status)
  end subroutine impact_while_carried

  !> The run's phases on from phase%t (drive_phases) with the bodies of
  !> `placed` at their poses and twists and the contacts `closed` closed
  !> (contact_bodies build_bodies; `touching` those left at gap 0); a
  !> build that fails fails the run, its status prefixed by `what`.
  subroutine phases_from(flight, placed, closed, touching, what, run, phase, options, phase_options, result, &
                         chart_changes, status)
    type(flight_ode_t), intent(inout), target :: flight
    type(contact_system_t), intent(in) :: placed
    logical, intent(in) :: closed(:), touching(:)
    character(len=*), intent(in) :: what
    type(phases_t), intent(inout) :: run
    type(driver_result_t), intent(in) :: phase
    type(driver_options_t), intent(in) :: options
    type(driver_options_t), intent(inout) :: phase_options
    type(driver_result_t), intent(inout) :: result
    integer, intent(inout) :: chart_changes
    type(status_t), intent(inout) :: status
    type(flight_ode_t), allocatable :: start
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    character(len=8), allocatable :: units(:)
    allocate (start)
    call build_bodies(placed, closed, start, q0, qd0, units, status, 0, .true., also_touching=touching)
    if (.not. status%ok()) then
      call prefix_status(status, what//' at t = '//format_short(phase%t)//' s')
      result%outcome = DRIVE_FAILED
      return
    end if
    start%impacts = flight%impacts
    y = start%initial_state(q0, qd0)
    call carry_work(run%series, start, y)
    phase_options%t_start = phase%t
    call drive_phases(flight, start, y, options, phase_options, run, result, .false., chart_changes, status)
  end subroutine phases_from

  !> A flight phase of one body that stopped where an impact closed several
  !> of its contacts at once (flight%closings): the body carried by them
  !> all (contact_bodies build_bodies at the last record's pose and twist)
  !> and the run's phases on from there (drive_phases).
  subroutine several_closed(flight, run, phase, options, phase_options, result, chart_changes, status)
    type(flight_ode_t), intent(inout), target :: flight
    type(phases_t), intent(inout) :: run
    type(driver_result_t), intent(in) :: phase
    type(driver_options_t), intent(in) :: options
    type(driver_options_t), intent(inout) :: phase_options
    type(driver_result_t), intent(inout) :: result
    integer, intent(inout) :: chart_changes
    type(status_t), intent(inout) :: status
    logical :: closed(size(flight%system%contacts))
    integer :: k
    closed = .false.
    closed(flight%closings) = .true.
    call phases_from(flight, at_last_record(flight), closed, spread(.false., 1, size(closed)), 'closing contacts '// &
                     closing_names(flight), run, &
                     phase, options, phase_options, result, chart_changes, status)
  contains
    function closing_names(f) result(text)
      type(flight_ode_t), intent(in) :: f
      character(len=:), allocatable :: text
      text = ''
      do k = 1, size(f%closings)
        if (k > 1) text = text//', '
        text = text//''''//f%system%contacts(f%closings(k))%name//''''
      end do
    end function closing_names
  end subroutine several_closed

  !> The start of a run of phases: each phase's options (the output origin
  !> fixed at the run's start) and an empty record of the phases of nc
  !> contacts.
  subroutine start_phases(options, nc, phase_options, run)
    type(driver_options_t), intent(in) :: options
    integer, intent(in) :: nc
    type(driver_options_t), intent(out) :: phase_options
    type(phases_t), intent(out) :: run
    phase_options = options
    if (.not. options%output_origin < huge(1.0_wp)) phase_options%output_origin = options%t_start
    allocate (run%open(nc, 0), run%gap(nc, 0), run%point(3, nc, 0), run%velocity(3, nc, 0))
    run%history = ''
  end subroutine start_phases

  !> drive_flight of several bodies (contact_bodies), or of one on several
  !> closed contacts: each phase one mechanism of the bodies as they are
  !> (each carried by its closed contacts or flying), `flight` the first.
  subroutine drive_bodies(flight, y0, options, result, status, open)
    type(flight_ode_t), intent(inout), target :: flight
    real(wp), intent(in) :: y0(:)
    type(driver_options_t), intent(in) :: options
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    integer, allocatable, intent(out) :: open(:, :)
    type(phases_t) :: run
    type(driver_options_t) :: phase_options
    type(flight_ode_t), allocatable :: none
    integer :: chart_changes
    call start_phases(options, size(flight%system%contacts), phase_options, run)
    chart_changes = 0
    call drive_phases(flight, none, y0, options, phase_options, run, result, .true., chart_changes, status)
    call run%finish(flight)
    call fail_where_not_built(run, flight, result, status)
    call on_first_frames(flight)
    flight%chart_changes = flight%chart_changes + chart_changes
    open = run%open
  end subroutine drive_bodies

  !> The phases from `start` (built, its state y; not allocated: `flight`
  !> itself) on: at a closing (an impact's rebound below close_speed, at one
  !> contact or several at once) or a lift-off of a contact that may open
  !> the next phase is built from every body's pose and twist at the last
  !> record, the switched contacts closed or opened (a body stays carried
  !> while any of its contacts is closed), and driven on from there. A
  !> lift-off of a contact that may not open, or any other stop, ends the
  !> run. first: the first phase of the run (result is set, not added to).
  subroutine drive_phases(flight, start, y0, options, phase_options, run, result, first, chart_changes, status)
    type(flight_ode_t), intent(inout), target :: flight
    type(flight_ode_t), allocatable, intent(inout) :: start
    real(wp), intent(in) :: y0(:)
    type(driver_options_t), intent(in) :: options
    type(driver_options_t), intent(inout) :: phase_options
    type(phases_t), intent(inout) :: run
    type(driver_result_t), intent(inout) :: result
    logical, intent(in) :: first
    integer, intent(inout) :: chart_changes
    type(status_t), intent(out) :: status
    type(driver_result_t) :: phase
    type(flight_ode_t), allocatable, target :: current, next_phase
    type(flight_ode_t), pointer :: p
    type(contact_system_t) :: placed
    real(wp), allocatable :: y(:), q0(:), qd0(:)
    character(len=8), allocatable :: units(:)
    logical, allocatable :: closed(:), touching(:)
    integer, allocatable :: opened(:)
    integer :: k, c
    logical :: next, lifted, starting
    p => flight
    if (allocated(start)) then
      call move_alloc(start, current)
      p => current
    end if
    y = y0
    starting = first
    do
      call p%clear_switches()
      if (.not. starting) call p%start_series(16)
      call drive(p, y, phase_options, phase, status)
      call run%add(p%series, p%q_units, p%beta_units, p%outcome)
      call run%add_flight(p)
      if (.not. starting) chart_changes = chart_changes + p%chart_changes
      run%not_built = p%stop_kind == STOP_NOT_BUILT
      lifted = .false.
      c = 0
      if (p%stop_kind == STOP_LIFT_OFF) then
        c = findloc(p%mechanism_contact, p%stop_contact, dim=1)
        if (c > 0) lifted = p%system%contacts(c)%may_open
      end if
      next = status%ok() .and. phase%outcome == DRIVE_EVENT_STOP .and. phase%t < options%t_end .and. &
             (size(p%closings) > 0 .or. lifted .or. any(p%twisted)) .and. .not. run%not_built
      if (next) then
        closed = p%gaps%carried
        touching = p%gaps%touching
        do k = 1, size(p%closings)
          closed(p%closings(k)) = .true.
          touching(p%closings(k)) = .false.
        end do
        ! an impact on a carried body: the contacts it opened, those it left at gap 0
        if (size(p%openings) > 0) closed(p%openings) = .false.
        if (size(p%bounced) > 0) touching(p%bounced) = .true.
        if (lifted) then
          closed(c) = .false.
          touching(c) = .true.
          if (any(closed .and. p%gaps%body == p%gaps%body(c))) then
            run%history = run%history//': the contact opens (may_open), the body goes on on its other closed '// &
                          'contacts'
          else
            run%history = run%history//': the contact opens (may_open), the body flies'
          end if
        end if
        placed = at_last_record(p)
        do k = 1, size(placed%bodies)
          if (.not. p%twisted(k)) cycle
          placed%bodies(k)%angular_velocity = p%twist_after(1:3, k)
          placed%bodies(k)%velocity = p%twist_after(4:6, k)
        end do
        ! a closed contact that may open but carries nothing there (two bodies
        ! on each other falling freely after an impact: N = 0) opens at gap 0
        allocate (next_phase)
        call build_bodies_opening(placed, closed, touching, next_phase, q0, qd0, units, status, .true., opened)
        do k = 1, size(opened)
          run%history = run%history//': contact '''//trim(p%system%contacts(opened(k))%name)//''' carries '// &
                        'nothing there (its bodies fall freely together, or it would pull): it opens at gap 0 (may_open)'
        end do
        if (.not. status%ok()) call prefix_status(status, 'the switch at t = '//format_short(phase%t)//' s')
        if (status%ok()) then
          next_phase%impacts = p%impacts
          y = next_phase%initial_state(q0, qd0)
          call carry_work(run%series, next_phase, y)
        end if
      end if
      call add_result(result, phase, starting)
      if (next .and. .not. status%ok()) result%outcome = DRIVE_FAILED
      if (.not. (next .and. status%ok())) exit
      if (.not. associated(p, flight)) flight%impacts = p%impacts
      call move_alloc(next_phase, current)
      p => current
      starting = .false.
      phase_options%t_start = phase%t
    end do
    if (.not. associated(p, flight)) flight%impacts = p%impacts
  end subroutine drive_phases

  !> A run whose last phase stopped at a case the model does not follow
  !> (STOP_NOT_BUILT: contact_flight's add_outcome, carried_handle_event) has
  !> failed part way: its status says where and why (the whole run's
  !> outcome), the records up to there kept (exit status 2, the file marked
  !> incomplete), not a normal end.
  subroutine fail_where_not_built(run, flight, result, status)
    type(phases_t), intent(in) :: run
    type(flight_ode_t), intent(in) :: flight
    type(driver_result_t), intent(inout) :: result
    type(status_t), intent(inout) :: status
    if (.not. (run%not_built .and. status%ok())) return
    call set_status(status, STATUS_DOMAIN, flight%outcome//' (the results up to here are kept)')
    result%outcome = DRIVE_FAILED
  end subroutine fail_where_not_built

  !> The bodies of flight's series on the first phase's frames, whose
  !> mechanism (flight's) reports the run.
  subroutine on_first_frames(flight)
    type(flight_ode_t), intent(inout) :: flight
    integer :: k, c
    associate (s => flight%series)
      do k = 1, s%nb
        c = findloc([(flight%system%bodies(c)%name == trim(s%body_names(k)), c = 1, size(flight%body_frame))], &
                    .true., dim=1)
        if (c > 0) s%body_frame(k) = flight%body_frame(c)
      end do
    end associate
  end subroutine on_first_frames

  !> The description of `phase` with every body at its pose and twist of the
  !> phase's last record (the series' bodies by name).
  function at_last_record(phase) result(placed)
    type(flight_ode_t), intent(in) :: phase
    type(contact_system_t) :: placed
    integer :: b, j
    placed = phase%system
    associate (s => phase%series, n => phase%series%n)
      do b = 1, size(placed%bodies)
        j = findloc([(trim(s%body_names(j)) == placed%bodies(b)%name, j = 1, s%nb)], .true., dim=1)
        placed%bodies(b)%position = s%body_r(:, j, n)
        placed%bodies(b)%rotation = s%body_rot(:, :, j, n)
        placed%bodies(b)%velocity = s%body_v(:, j, n)
        placed%bodies(b)%angular_velocity = s%body_omega(:, j, n)
      end do
    end associate
  end function at_last_record

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

  !> The flight of a body carried at the start by a closed contact (the
  !> description's one contact that does not start open; `model` built from
  !> it alone, contact_flight closed_part) that may open, or with other
  !> contacts to land on: the free body built at the closed model's start
  !> pose and twist (touching that contact's shape_1), holding the model,
  !> driven closed first (drive_flight). q0, qd0, q_units as build_flight's.
  subroutine flight_after_closed(system, model, flight, q0, qd0, q_units, status)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(in) :: model
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    type(contact_system_t) :: placed
    integer :: k
    if (.not. status%ok()) return
    k = carrying_contact(system)
    placed = system
    associate (body => model%ode%work%frames(model%body_frame(2)))
      placed%bodies(1)%position = body%r
      placed%bodies(1)%rotation = body%rot
      placed%bodies(1)%velocity = body%v
      placed%bodies(1)%angular_velocity = body%omega
    end associate
    call build_flight(placed, flight, q0, qd0, q_units, status, touching=k)
    if (.not. status%ok()) return
    flight%start_closed = .true.
    flight%closed_on = k
    allocate (flight%closed, source=model)
  end subroutine flight_after_closed

  !> The closed contact at the flight's last record: its description with
  !> the contact landed on alone, closed, and the body at the record's pose and twist, built
  !> and started (contact_model); refused (STATUS_DOMAIN) if the body had to
  !> move more than touching_gap_limit to touch.
  subroutine close_contact(flight, model, status)
    type(flight_ode_t), intent(in) :: flight
    type(contact_model_t), intent(out) :: model
    type(status_t), intent(inout) :: status
    type(contact_system_t) :: system
    integer :: n
    system = closed_part(flight%system, flight%landed)
    n = flight%series%n
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
