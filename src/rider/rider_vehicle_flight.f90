!> A vehicle that flies (&sled may_fly; issues 25 and 26, docs/vehicles.md
!> "Flight"): where a contact's normal force falls to zero that contact opens
!> and the vehicle goes on, on the other contact or with both open, until a
!> contact lands again.
!>
!> The ride switches between builds of the vehicle (build_vehicle_model
!> with lift and open, build_sled: the rear end on a prismatic along the
!> normal at its foot point), per set of open contacts (bit 0 the rear,
!> bit 1 the front; 0: the sled with the lift held at 0), their scalars,
!> frames, contacts and laws at the same indices. A state carries over
!> through the full layout [u, v, phi, pitch, rear_lift, roll], their
!> rates, then the laws' work integrals: positions
!> and velocities are continuous through a switch, to the closure's
!> rounding. With a contact open the roll about the bar's axis (after the
!> pitch) is free (build_sled free_roll): both open, a free rigid body in
!> six coordinates; one open, a rigid body on one point contact in five,
!> whose lift-offs are decided in that build. With both contacts on the
!> roll is held (the sled's model: the bar keeps its roll to the slide
!> below its rear end), at 0 until the vehicle has flown, then at the roll
!> it landed with. A landing that closes the last open contact first stops
!> the roll's rate by a plastic impulse about the bar's axis
!> (rider_vehicle_roll; its energy is the landing's), then the contact's
!> impact in the build with the roll held (held, held_yaw).
!>
!> An open contact's gap (point_gap: the rear's lift, the front's front_z)
!> is a root (gap_root); once it has opened, its rate is one too: where the
!> rate falls through zero the gap is at an apex, kept as the flights'
!> highest point if higher than any before (with the gaps at the records,
!> where a stretch ends rising: the highest between the records, not only
!> at them). The gap's zero is a landing: kinetostatics_point_impact's
!> impact (&sled landing_restitution, landing_mu) with the effective mass
!> of the whole vehicle there (J M^-1 J^T of the build in flight). A
!> rebound slower than close_speed closes the contact (if it then presses;
!> else it flies on from the slide).
!>
!> While the front is on (open masks 0 and 1) its closure solves front_z
!> for the pitch or the heading phi (build_sled solve_yaw), by their
!> columns of the closure Jacobian (solve_columns: the front point's speed
!> along the front's normal per unit of each); where the solved one's
!> column falls below solve_ratio of the other's (ends on opposite walls:
!> the double ring in the bowl) the same open contacts go on in the other
!> build (a switch as a take-off's, docs/vehicles.md).
!>
!> An open contact's end is placed by its foot point and its lift along the
!> normal there, a chart singular at a centre of curvature of the surface
!> (a tube's axis): a run whose steps collapse there fails by the runaway
!> guard, and diagnose says so (focal_note; stiffness_may_cause: BDF does
!> not help). Not built: a chart without a foot point.
!>
!> The ride itself, stretch by stretch between the switches (drive_vehicle,
!> switch_build, press_or_open, the full layout's records), is the submodule
!> rider_vehicle_flight_stretches; this module holds the integration's
!> object: its builds, its right-hand side, roots and events.
module rider_vehicle_flight
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, prefix_status
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_differential, only: radii_towards
  use geometry_slide_query, only: slide_surface_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, EVENT_IGNORE, EVENT_STOP, EVENT_RESTART
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_LIFT_OFF
  use kinetostatics_models, only: sled_description_t
  use kinetostatics_point_impact, only: point_gap, point_gap_rate, gap_root
  use rider_flight, only: ride_flights_t
  use rider_vehicle, only: vehicle_t, build_vehicle_model
  use rider_vehicle_layout, only: vehicle_contact_names, vehicle_units, N_FULL, full_names
  use water_field, only: water_field_t
  implicit none (type, external)
  private
  public :: vehicle_flight_ode_t, build_vehicle_flight, drive_vehicle, vehicle_contact_names, vehicle_units
  public :: solve_columns, SOLVE_PITCH, SOLVE_YAW, solve_ratio
  !> (its contract tested alone: test_vehicle_flight take_off_at_press_or_open)
  public :: press_or_open

  integer, parameter :: SWITCH_NONE = 0, SWITCH_TAKE_OFF = 1, SWITCH_LANDING = 2, SWITCH_SOLVE = 3
  !> what the closed front's closure solves front_z for (the header)
  integer, parameter :: SOLVE_PITCH = 1, SOLVE_YAW = 2
  !> the solved coordinate gives way when its column falls below this
  !> fraction of the other's (after the switch the new one's is twice the
  !> old one's: the way back needs the ratio of the two to change fourfold)
  real(wp), parameter :: solve_ratio = 0.5_wp
  !> the roots after the mechanism's: the rear's and the front's gap, the
  !> solved coordinate's margin, the rear's and the front's gap rate (the
  !> apex of a flight: its highest point)
  integer, parameter :: N_OWN_ROOTS = 5

  !> The vehicle's integration with its four builds.
  type, extends(mechanism_ode_t) :: vehicle_flight_ode_t
    ! allocatable, not fixed-size: for a fixed-size array of mechanism_t gfortran
    ! writes the type's finalizer element by element (4.2 MB of code at -O0; 200 s
    ! of -O3 compile here and again in every type that holds this one)
    type(mechanism_t), allocatable :: builds(:)       ! masks 0..3
    type(mechanism_t), allocatable :: yaw_builds(:)   ! masks 0, 1 with the front's closure solving the heading
    type(mechanism_t), allocatable :: held(:)         ! masks 1, 2 with the roll held: the last open contact's landing
    type(mechanism_t) :: held_yaw           ! mask 1 solving the heading, the roll held
    integer :: open_mask = 0
    integer :: solved = SOLVE_PITCH         ! the build in use's (masks 0, 1)
    integer :: solve_switches = 0           ! how often the solved coordinate changed
    integer :: heading = 0                  ! the heading's frame (its y the pitch's axis, z the yaw's)
    !> the positions of the margin's root (flight_roots), apart from the run's work
    type(mechanism_workspace_t) :: margin_work
    !> the positions at an apex (flight_handle_event), apart from the run's
    !> work: the run goes on as if the event had not been
    type(mechanism_workspace_t) :: apex_work
    !> the margin at the last right-hand side's (t, y), the largest |margin| met
    logical :: margin_stored = .false.
    real(wp) :: margin_t = 0, margin_value = 0, margin_scale = 0
    real(wp), allocatable :: margin_y(:)
    integer :: full(N_FULL) = 0          ! the full layout's scalars
    integer :: point(2) = 0, foot(2) = 0 ! each contact's point frame and its foot point's frame
    integer :: contact(2) = 0            ! the mechanism's contacts 'rear', 'front'
    logical :: opened(2) = .false.       ! the gap has opened beyond opening_gap
    type(vehicle_t) :: vehicle           ! its landing law
    real(wp) :: gravity = 0              ! m/s^2, |g|
    class(surface_t), allocatable :: ground  ! the surface ridden (a slide: arc lengths, else the rear's u)
    type(ride_flights_t) :: flights
    integer :: switch = SWITCH_NONE, switch_contact = 0, quick_landings = 0
    real(wp) :: switch_t = 0, take_off_time(2) = 0
    real(wp), allocatable :: switch_y(:)
    ! the run's records: each one's open contacts and the ride figures
    integer, allocatable :: open_record(:)
    real(wp), allocatable :: speed(:), felt(:, :)   ! m/s; 3 x n, g
    real(wp), allocatable :: losses(:)              ! J, the landings' energy lost up to each record
    character(len=:), allocatable :: history        ! every stretch's outcome
  contains
    procedure :: rhs => flight_rhs
    procedure :: root_count => flight_root_count
    procedure :: roots => flight_roots
    procedure :: handle_event => flight_handle_event
    procedure :: record => flight_record
    procedure :: diagnose => flight_diagnose
    procedure :: stiffness_may_cause => flight_stiffness_may_cause
  end type vehicle_flight_ode_t

  interface
    ! rider_vehicle_flight_stretches
    !> Drives the run from y0 stretch by stretch: after a stop that asks for a
    !> switch the next build goes on from there. sys%series becomes the joined
    !> records, sys%open_record, speed and felt each record's open contacts and
    !> ride figures; result sums the drives (its outcome and time the last's).
    module subroutine drive_vehicle(sys, y0, options, result, status)
      type(vehicle_flight_ode_t), intent(inout), target :: sys
      real(wp), intent(in) :: y0(:)
      type(driver_options_t), intent(in) :: options
      type(driver_result_t), intent(out) :: result
      type(status_t), intent(out) :: status
    end subroutine drive_vehicle

    !> After a switch at t to the state y: every closed contact must press;
    !> one that would pull (its normal force not > 0: a landing's impulse, a
    !> take-off changing what holds the vehicle) opens too, from the slide
    !> (its gap watched from 0), taking off at t.
    module subroutine press_or_open(self, t, y, status)
      type(vehicle_flight_ode_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), allocatable, intent(inout) :: y(:)
      type(status_t), intent(inout) :: status
    end subroutine press_or_open

    !> Contact c's foot point's arc length on a slide (else its u), the
    !> positions set (in `work`, else the run's).
    module function where_foot(self, c, work) result(s)
      class(vehicle_flight_ode_t), intent(in) :: self
      integer, intent(in) :: c
      type(mechanism_workspace_t), intent(in), optional :: work
      real(wp) :: s
    end function where_foot
  end interface

contains

  !> The four builds of vehicle v (v%may_fly) on `surface` from the start of
  !> d, the one with both contacts on in use: sys ready to run from q0, qd0.
  subroutine build_vehicle_flight(v, d, surface, sys, q0, qd0, status, water)
    type(vehicle_t), intent(in) :: v
    type(sled_description_t), intent(in) :: d
    class(surface_t), intent(in) :: surface
    type(vehicle_flight_ode_t), intent(inout) :: sys
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional, target :: water
    real(wp), allocatable :: q_open(:), qd_open(:)
    integer :: mask, k
    if (.not. allocated(sys%builds)) allocate(sys%builds(0:3))
    if (.not. allocated(sys%yaw_builds)) allocate(sys%yaw_builds(0:1))
    if (.not. allocated(sys%held)) allocate(sys%held(1:2))
    if (.not. status%ok()) return
    call build_vehicle_model(v, d, surface, sys%held_yaw, q_open, qd_open, status, water, lift=.true., &
                             open=[.true., .false.], solve_yaw=.true.)
    do mask = 3, 0, -1
      if (mask == 0) then
        call build_vehicle_model(v, d, surface, sys%builds(0), q0, qd0, status, water, lift=.true., &
                                 open=[.false., .false.])
      else
        call build_vehicle_model(v, d, surface, sys%builds(mask), q_open, qd_open, status, water, lift=.true., &
                                 open=[btest(mask, 0), btest(mask, 1)], free_roll=.true.)
      end if
      if (mask == 1 .or. mask == 2) call build_vehicle_model(v, d, surface, sys%held(mask), q_open, qd_open, &
                                                             status, water, lift=.true., open=[mask == 1, mask == 2])
      if (mask < 2) call build_vehicle_model(v, d, surface, sys%yaw_builds(mask), q_open, qd_open, status, water, &
                                             lift=.true., open=[btest(mask, 0), .false.], solve_yaw=.true., &
                                             free_roll=.true.)
      if (.not. status%ok()) then
        call prefix_status(status, 'the vehicle''s flight builds')
        return
      end if
    end do
    sys%mechanism = sys%builds(0)
    sys%open_mask = 0
    sys%solved = SOLVE_PITCH
    sys%solve_switches = 0
    associate (m => sys%builds(0))
      do k = 1, N_FULL
        sys%full(k) = m%scalar_index(trim(full_names(k)))
      end do
      sys%point = [m%frame_index('bar'), m%frame_index('bar_front')]
      sys%foot = [m%frame_index('rear_contact'), m%frame_index('front_contact')]
      sys%contact = [m%contact_index('rear'), m%contact_index('front')]
      sys%heading = m%frame_index('heading')
    end associate
    sys%vehicle = v
    sys%gravity = norm2(d%params%gravity)
    allocate (sys%ground, source=surface)
    sys%flights%watched = .true.
    sys%history = ''
  end subroutine build_vehicle_flight


  !> The mechanism's right-hand side; while the front is on, the margin at
  !> its positions is kept with (t, y) for the root calls (flight_roots).
  subroutine flight_rhs(self, t, y, ydot, status)
    class(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    call self%mechanism_ode_t%rhs(t, y, ydot, status)
    self%margin_stored = status%ok() .and. self%open_mask < 2
    if (.not. self%margin_stored) return
    self%margin_value = solve_margin(self, self%work)
    self%margin_scale = max(self%margin_scale, abs(self%margin_value))
    self%margin_t = t
    if (allocated(self%margin_y)) then
      if (size(self%margin_y) /= size(y)) deallocate (self%margin_y)
    end if
    if (.not. allocated(self%margin_y)) allocate (self%margin_y(size(y)))
    self%margin_y(:) = y
  end subroutine flight_rhs

  integer function flight_root_count(self) result(n)
    class(vehicle_flight_ode_t), intent(in) :: self
    n = self%mechanism_ode_t%root_count() + N_OWN_ROOTS
  end function flight_root_count

  !> The mechanism's roots, then each open contact's gap root (a constant
  !> while it is closed), then, while the front is on, the margin of the
  !> coordinate its closure solves (solve_margin; a constant while it is
  !> open), then each opened contact's gap rate (a constant else).
  subroutine flight_roots(self, t, y, g)
    class(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    type(status_t) :: st
    integer :: n, k
    n = size(g) - N_OWN_ROOTS
    call self%mechanism_ode_t%roots(t, y, g(1:n))
    g(n + 1:) = 1
    ! the margin: the last right-hand side's where it serves (as the
    ! mechanism's roots: the same t, y within 1e-5 relative and the value
    ! far from zero), from the run's positions where they are y's, else
    ! from positions of its own (the run's work and its cached root values
    ! stay as the mechanism's roots left them)
    if (self%open_mask < 2) then
      if (margin_serves(self, t, y)) then
        g(n + 3) = self%margin_value
      else if (self%work%converged .and. all(self%work%scalars(self%mechanism%q)%q == y(1:self%mechanism%f))) then
        g(n + 3) = solve_margin(self, self%work)
      else
        call self%mechanism%set_positions(self%margin_work, y(1:self%mechanism%f), st)
        if (st%ok()) g(n + 3) = solve_margin(self, self%margin_work)
      end if
    end if
    if (self%open_mask == 0) return
    ! the positions at y; a trial state the closure cannot reach keeps the last value
    st = status_t()
    call self%positions_at(y, st)
    if (.not. st%ok()) return
    do k = 1, 2
      if (btest(self%open_mask, k - 1)) g(n + k) = gap_root(point_gap(self%work, self%point(k), self%foot(k)), &
                                                             self%opened(k))
    end do
    if (.not. any([(btest(self%open_mask, k - 1) .and. self%opened(k), k = 1, 2)])) return
    ! the velocities at y too (the run's work: the positions are y's, and a
    ! right-hand side sets both again)
    call self%mechanism%set_velocities(self%work, y(self%mechanism%f + 1:self%mechanism%f + self%mechanism%ns))
    do k = 1, 2
      if (btest(self%open_mask, k - 1) .and. self%opened(k)) &
        g(n + 3 + k) = point_gap_rate(self%work, self%point(k), self%foot(k))
    end do
  end subroutine flight_roots

  !> The mechanism's record; in flight each open contact's gap there is a
  !> candidate for the highest point (keep_highest): a stretch that ends
  !> with a gap still rising has its highest there.
  subroutine flight_record(self, t, y, kind, status)
    class(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    integer :: k
    call self%mechanism_ode_t%record(t, y, kind, status)
    if (.not. status%ok() .or. self%open_mask == 0) return
    do k = 1, 2
      if (btest(self%open_mask, k - 1)) call keep_highest(self, self%work, t, k)
    end do
  end subroutine flight_record

  !> Contact c's gap (positions set in `work`, at time t) as the flights'
  !> highest point if it is higher than the one kept.
  subroutine keep_highest(self, work, t, c)
    class(vehicle_flight_ode_t), intent(inout) :: self
    type(mechanism_workspace_t), intent(in) :: work
    real(wp), intent(in) :: t
    integer, intent(in) :: c
    real(wp) :: gap
    gap = point_gap(work, self%point(c), self%foot(c))
    if (.not. gap > self%flights%highest) return
    self%flights%highest = gap
    self%flights%highest_contact = c
    self%flights%highest_time = t
    self%flights%highest_arc_length = where_foot(self, c, work)
  end subroutine keep_highest

  !> The margin stored by the last right-hand side serves at (t, y): the
  !> same t and y, or y within d <= 1e-5 of it (each entry relative to
  !> max(1, |y_c|)) with |margin| >= max(1e4 d, 1e-9) times the largest met
  !> (kinetostatics_mechanism_ode_events: the value's error, its
  !> sensitivity times d, then cannot change its sign).
  logical function margin_serves(self, t, y) result(serves)
    class(vehicle_flight_ode_t), intent(in) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp) :: d
    serves = .false.
    if (.not. self%margin_stored .or. t /= self%margin_t) return
    if (size(y) /= size(self%margin_y)) return
    d = maxval(abs(y - self%margin_y)/max(1.0_wp, abs(self%margin_y)))
    serves = d <= 1e-5_wp .and. abs(self%margin_value) >= max(1e4_wp*d, 1e-9_wp)*self%margin_scale
  end function margin_serves

  !> The columns of the closure Jacobian of front_z (the front point's
  !> signed distance along its foot frame's normal) for the pitch and the
  !> heading (m/rad), at the positions in `work`: |n_2 . (a x arm)|, a the
  !> axis (the heading frame's y, z), arm from the rear end (both axes pass
  !> through it) to the front point. Exact: the foot point moves in its
  !> tangent plane, and the normal's turn is across the gap's own direction.
  pure function solve_columns(work, heading, front, foot) result(c)
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: heading, front, foot
    real(wp) :: c(2)
    real(wp) :: arm(3)
    associate (h => work%frames(heading), n => work%frames(foot)%rot(:, 3))
      arm = work%frames(front)%r - h%r
      c(SOLVE_PITCH) = abs(dot_product(n, cross(h%rot(:, 2), arm)))
      c(SOLVE_YAW) = abs(dot_product(n, cross(h%rot(:, 3), arm)))
    end associate
  end function solve_columns

  !> The solved coordinate's column less solve_ratio times the other's (m)
  !> at the positions in `work`: it gives way where this falls through zero.
  real(wp) function solve_margin(self, work) result(margin)
    class(vehicle_flight_ode_t), intent(in) :: self
    type(mechanism_workspace_t), intent(in) :: work
    real(wp) :: c(2)
    c = solve_columns(work, self%heading, self%point(2), self%foot(2))
    margin = c(self%solved) - solve_ratio*c(3 - self%solved)
  end function solve_margin

  !> For a run that fails by its step count: the mechanism's notes, then
  !> each open contact's end near a centre of curvature (focal_note).
  function flight_diagnose(self, t, y) result(text)
    class(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    character(len=:), allocatable :: text, note
    integer :: k
    text = self%mechanism_ode_t%diagnose(t, y)   ! the positions at y set, where they can be
    if (.not. self%work%converged) return
    do k = 1, 2
      note = focal_note(self, k)
      if (len(note) == 0) cycle
      if (len(text) > 0) text = text//'; '
      text = text//note
    end do
  end function flight_diagnose

  !> Stiffness may be the trouble unless an open contact's end is at a
  !> centre of curvature (focal_note): BDF does not mend a singular chart.
  logical function flight_stiffness_may_cause(self, t, y) result(may)
    class(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    type(status_t) :: st
    may = .true.
    associate (unused_t => t)
    end associate
    self%cached = .false.
    self%rhs_cached = .false.
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), st)
    if (.not. st%ok()) return
    may = len(focal_note(self, 1)) == 0 .and. len(focal_note(self, 2)) == 0
  end function flight_stiffness_may_cause

  !> Where open contact c's end (positions set) is within 1e-3 of a
  !> principal radius of curvature of the surface at its foot point, on its
  !> side: a focal point, where the open contact's coordinates (the foot
  !> point (u, v) and the lift along the normal there: p = r + h n) are
  !> singular (det(I - h S) = 0): passing it the foot point swings round the
  !> centre of curvature (by half a turn across a tube's axis), and the
  !> steps shrink without end. Not built: a chart without a foot point for
  !> an end that far off the slide. '' elsewhere (and for a closed contact).
  function focal_note(self, c) result(text)
    class(vehicle_flight_ode_t), intent(in) :: self
    integer, intent(in) :: c
    character(len=:), allocatable :: text
    real(wp), parameter :: near = 1e-3_wp
    type(surface_point_t) :: p
    type(status_t) :: st
    real(wp) :: h, rho(2), distance
    text = ''
    if (.not. btest(self%open_mask, c - 1) .or. .not. allocated(self%ground)) return
    associate (m => self%mechanism, w => self%work)
      call self%ground%evaluate(w%scalars(m%scalar_index(trim(merge('u ', 'u2', c == 1))))%q, &
                                w%scalars(m%scalar_index(trim(merge('v ', 'v2', c == 1))))%q, 2, p, st)
      if (.not. st%ok()) return
      h = point_gap(w, self%point(c), self%foot(c))
      rho = radii_towards(p, w%frames(self%foot(c))%rot(:, 3))
    end associate
    distance = minval(abs(rho - h))
    if (.not. distance < near*minval(rho)) return
    text = 'the '//trim(vehicle_contact_names(c))//' contact''s end flies '//format_short(distance)// &
      ' m from a centre of curvature of the surface below it (its lift '//format_short(h)//' m, the radius of '// &
      'curvature '//format_short(minval(rho))//' m at arc length '//format_short(where_foot(self, c))// &
      ' m), where the coordinates of an open contact (its foot point and its lift along the normal there) are '// &
      'singular: passing it the foot point swings round (not built: an open end at a centre of curvature of '// &
      'the slide; method = ''bdf'' does not help)'
  end function focal_note

  !> The mechanism's events; a lift-off of a contact asks for its take-off
  !> (a stop, then the switch); an open contact's gap root: it opened (watch
  !> the landing from now on) or it landed (a stop that asks for the
  !> landing's switch); its gap rate falling through zero: an apex, a
  !> candidate for the highest point (no record: the run goes on).
  subroutine flight_handle_event(self, t, y, fired, action, status)
    class(vehicle_flight_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    integer :: n, k
    n = size(fired) - N_OWN_ROOTS
    self%switch = SWITCH_NONE
    ! an apex: the highest point kept from positions of its own; the run
    ! goes on untouched (the mechanism's handling would reset its caches)
    if (any(fired(n + 4:n + 5) < 0)) then
      call self%mechanism%set_positions(self%apex_work, y(1:self%mechanism%f), status)
      if (.not. status%ok()) return
      do k = 1, 2
        if (fired(n + 3 + k) < 0 .and. btest(self%open_mask, k - 1)) call keep_highest(self, self%apex_work, t, k)
      end do
    end if
    if (all(fired(1:n + 3) == 0)) then
      action = EVENT_IGNORE
      return
    end if
    call self%mechanism_ode_t%handle_event(t, y, fired(1:n), action, status)
    if (.not. status%ok()) return
    if (action == EVENT_STOP) then
      if (self%stop_kind /= STOP_LIFT_OFF) return   ! the slide's end, an edge: the run ends
      k = findloc(self%contact, self%stop_contact, dim=1)
      if (k == 0) return
      self%switch = SWITCH_TAKE_OFF
      self%switch_contact = k
      self%switch_t = t
      self%switch_y = y
      return
    end if
    if (all(fired(n + 1:n + 3) == 0)) return
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), status)
    if (.not. status%ok()) return
    do k = 1, 2
      if (fired(n + k) == 0 .or. .not. btest(self%open_mask, k - 1)) cycle
      if (.not. self%opened(k) .and. point_gap(self%work, self%point(k), self%foot(k)) > 0) then
        self%opened(k) = .true.
        action = max(action, EVENT_RESTART)
        cycle
      end if
      if (self%switch == SWITCH_LANDING) cycle   ! two at once: the first, the other's root fires again
      self%switch = SWITCH_LANDING
      self%switch_contact = k
      self%switch_t = t
      self%switch_y = y
      action = EVENT_STOP
      self%outcome = 'landing of the '//trim(vehicle_contact_names(k))//' contact at t = '//format_short(t)//' s'
    end do
    ! the solved coordinate's margin falling through zero: the other from here
    ! (a landing at the same time picks by the normals itself, use_build)
    if (fired(n + 3) < 0 .and. self%open_mask < 2 .and. self%switch == SWITCH_NONE) then
      self%switch = SWITCH_SOLVE
      self%switch_t = t
      self%switch_y = y
      action = EVENT_STOP
      self%outcome = ''
    end if
  end subroutine flight_handle_event
end module rider_vehicle_flight
