!> Closing (issue 25): a flight (contact_flight) whose landing closes the
!> contact goes on as the closed contact, to the end of the run.
!>
!> When an impact's rebound is below close_speed the flight stops there with
!> the contact points' normal velocity taken away (contact_flight). The
!> closed contact is then built as a `start = 'closed'` run builds it
!> (contact_model, the same description): the body's pose and twist are the
!> flight's last record's, so its contact coordinates come from the contact
!> search at that pose (the foot points: nearest_point and support_point of
!> geometry_foot_point, the body moved along the normal by the gap that is
!> left, ~1e-14 m at a located root) and its speeds are the least-squares
!> fit of that twist, which the closed contact allows (no normal velocity,
!> no slip where it rolls: the closing impulse saw to it), to rounding. The
!> closed run starts at the closing time on the flight's output grid and
!> goes to the end (or its own stopping event: a lift-off ends it, as in any
!> closed run).
!>
!> The two series are joined (kinetostatics_recorder join_series): both
!> records at the closing time are kept, the flight's last (the state after
!> the impact) and the closed contact's first, the same pose and twist to
!> rounding. Coordinates of one phase are 0 in the other's records (the
!> result's `open` says which: 1 in flight); in the flight's records the
!> contact's point is the gap's point on shape_1, its velocity the body's
!> nearest point's along the surface, its normal force 0. The closed
!> contact's first record is marked an event (record_kind 3): the switch.
module contact_closing
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_EVENT_STOP, DRIVE_FAILED, &
    RECORD_EVENT
  use kinetostatics_recorder, only: join_series
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model
  use contact_flight, only: flight_ode_t
  implicit none (type, external)
  private
  public :: drive_flight, close_contact, closing_start_gap_limit

  !> m: the most a closing may move the body to touch (the gap left at the
  !> landing root: its speed times the root's time error, ~1e-14 m; far
  !> beyond it the closing pose is not the flight's, and the run fails)
  real(wp), parameter :: closing_start_gap_limit = 1e-9_wp

contains

  !> Drives the flight from y0 (numerics_event_driver drive) and, if its
  !> landing closed the contact before options%t_end, the closed contact on
  !> from there. flight%series becomes the joined records, flight%q_units
  !> their coordinates' units, in_flight the phase of each record;
  !> result sums both drives (its outcome, time and fired roots the last's).
  subroutine drive_flight(flight, y0, options, result, status, in_flight)
    type(flight_ode_t), intent(inout), target :: flight
    real(wp), intent(in) :: y0(:)
    type(driver_options_t), intent(in) :: options
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    integer, allocatable, intent(out) :: in_flight(:)   ! per record: 1 in flight, 0 closed
    type(driver_options_t) :: closed_options
    type(driver_result_t) :: closed_result
    integer :: n_flight
    flight%closing = .false.
    call drive(flight, y0, options, result, status)
    in_flight = spread(1, 1, flight%series%n)
    if (.not. (status%ok() .and. result%outcome == DRIVE_EVENT_STOP .and. flight%closing)) return
    if (.not. result%t < options%t_end) return   ! closed at the very end: nothing left to run
    allocate (flight%closed)
    call close_contact(flight, flight%closed, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'closing the contact at t = '//format_short(result%t)//' s')
      result%outcome = DRIVE_FAILED
      return
    end if
    closed_options = options
    closed_options%t_start = result%t
    if (.not. options%output_origin < huge(1.0_wp)) closed_options%output_origin = options%t_start
    call flight%closed%ode%start_series(max(flight%series%n, 16))
    call drive(flight%closed%ode, flight%closed%y0, closed_options, closed_result, status)
    n_flight = flight%series%n
    call join_phases(flight)
    in_flight = [spread(1, 1, n_flight), spread(0, 1, flight%series%n - n_flight)]
    result%outcome = closed_result%outcome
    result%t = closed_result%t
    result%fired = closed_result%fired
    result%events = result%events + closed_result%events
    result%restarts = result%restarts + closed_result%restarts
    result%outputs = result%outputs + closed_result%outputs
    result%cpu = result%cpu + closed_result%cpu
    result%stats%steps = result%stats%steps + closed_result%stats%steps
    result%stats%rhs_evaluations = result%stats%rhs_evaluations + closed_result%stats%rhs_evaluations
    result%stats%error_test_failures = result%stats%error_test_failures + closed_result%stats%error_test_failures
    result%stats%nonlinear_failures = result%stats%nonlinear_failures + closed_result%stats%nonlinear_failures
    result%stats%root_evaluations = result%stats%root_evaluations + closed_result%stats%root_evaluations
    result%stats%last_step = closed_result%stats%last_step
    result%stats%last_order = closed_result%stats%last_order
    flight%chart_changes = flight%chart_changes + flight%closed%ode%chart_changes
    if (len(flight%closed%ode%outcome) > 0) flight%outcome = flight%outcome//'; '//flight%closed%ode%outcome
  end subroutine drive_flight

  !> The closed contact at the flight's last record: its description with
  !> the contact closed and the body at the record's pose and twist, built
  !> and started (contact_model); refused (STATUS_DOMAIN) if the body had to
  !> move more than closing_start_gap_limit to touch.
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
    if (.not. abs(model%links(1)%start_gap) <= closing_start_gap_limit) &
      call set_status(status, STATUS_DOMAIN, 'contact '''//system%contacts(1)%name//''': the closed contact '// &
        'moved the body by '//format_short(model%links(1)%start_gap)//' m to touch (more than '// &
        format_short(closing_start_gap_limit)//' m): the landing pose is not a touching one')
  end subroutine close_contact

  !> flight%series := the flight's records then the closed contact's, the
  !> flight's contact point and velocity from its gap records; q_units the
  !> joined coordinates' units.
  subroutine join_phases(flight)
    type(flight_ode_t), intent(inout) :: flight
    integer :: n1, k, j
    character(len=8), allocatable :: units(:)
    n1 = flight%series%n
    associate (closed => flight%closed%ode%series)
      units = flight%q_units
      do k = 1, closed%f
        if (any([(flight%series%q_names(j) == closed%q_names(k), j = 1, flight%series%f)])) cycle
        units = [character(len=8) :: units, flight%closed%q_units(k)]
      end do
      flight%series = join_series(flight%series, closed)
    end associate
    flight%q_units = units
    flight%beta_units = flight%closed%beta_units
    ! the contact (the closed one's first) in the flight's records
    flight%series%contact_r(:, 1, :n1) = flight%gap_point(:, :n1)
    flight%series%slip(:, 1, :n1) = flight%gap_velocity(:, :n1)
    ! the closed contact's start is the switch, an event of the run
    flight%series%kind(n1 + 1) = RECORD_EVENT
  end subroutine join_phases
end module contact_closing
