!> A mechanism as a model of the integration driver (numerics_event_driver):
!> an ODE system with records and events.
!>
!> State y = [q, s, W]: the generalized coordinates, the speeds (their rates
!> q' = B(q) s; s = q' unless the mechanism has rate constraints or kinematic
!> coordinates, kinetostatics_mechanism), and one quadrature state per force
!> law, W_k' = P_k (the law's power), so that E(t) - E(0) = sum_k W_k holds to
!> the integrator's tolerance (E: kinetic + gravitational energy of the mass
!> elements). Only `state_size`, `initial_state`, `rhs` and `record` know
!> this layout.
!>
!> The root functions and events live in the submodule
!> kinetostatics_mechanism_ode_events (its comment gives them).
module kinetostatics_mechanism_ode
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_DOMAIN, STATUS_INVALID_INPUT
  use numerics_event_driver, only: event_system_t, EVENT_IGNORE, EVENT_RECORD, EVENT_STOP, EVENT_RESTART
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_recorder, only: mechanism_series_t
  implicit none (type, external)
  private
  public :: mechanism_ode_t

  !> What stopped a run (mechanism_ode_t%stop_kind, with `outcome` its words):
  !> a surface joint at its end or start in u, at a side edge in v, a
  !> one-sided contact's normal force falling to zero; a case the model does
  !> not follow (an extension's STOP_NOT_BUILT: its runner fails the run there,
  !> the results up to it kept); none (a caller's own stop, the end time, a
  !> failure).
  integer, parameter, public :: STOP_NONE = 0, STOP_END_OF_SURFACE = 1, STOP_START_OF_SURFACE = 2, &
    STOP_SIDE_EDGE = 3, STOP_LIFT_OFF = 4, STOP_NOT_BUILT = 5

  !> How near zero N must be at a lift-off root, relative to the largest |N|
  !> of the contact at the start and the outputs (check_lift_off). At a
  !> true lift-off N there is the root location's error (N' times CVODE's
  !> 1e-14 s or so) plus that of the interpolated state (N's sensitivity
  !> times the local error): 1e-16..1e-12 in the tests' lift-offs (sled,
  !> rider). Through a pole (the paraboloids, the tower of review finding 2)
  !> it was 6e3..8e6.
  real(wp), parameter :: lift_off_tolerance = 1e-2_wp
  character(len=*), parameter :: singular_advice = 'a contact is conformal or nearly so there (the '// &
    'surfaces'' curvatures match along a direction: the contact point is not determined by the pose, '// &
    'docs/contact.md "Singular contacts"); the results up to here are kept'

  type, extends(event_system_t) :: mechanism_ode_t
    type(mechanism_t) :: mechanism
    !> the work arrays and cache of this integration's mechanism computations (the mechanism is the model)
    type(mechanism_workspace_t) :: work
    type(mechanism_series_t) :: series
    integer, allocatable :: event_index(:)
    real(wp), allocatable :: event_value(:)
    integer :: event_action = EVENT_RECORD
    character(len=:), allocatable :: outcome   !< why the run ended, set by the stopping event
    !> the first of the mechanism's stopping events (STOP_*), the surface
    !> joint's element (edges) and the contact (lift-off) it names (0: none)
    integer :: stop_kind = STOP_NONE
    integer :: stop_element = 0
    integer :: stop_contact = 0
    !> check_start's refusal: the one-sided contact that does not press (0:
    !> none), for a caller that may open it instead (contact_closing)
    integer :: not_pressing = 0
    integer :: rhs_count = 0
    integer :: n_roots = 0                     ! its own roots (not an extension's), counted in prepare
                                               ! (the right-hand side asks at every call)
    integer :: root_calls = 0, root_cache_hits = 0
    ! root calls not served by stored values: those that evaluated the whole dynamics (lift-off
    ! needs N), of them those at an output time (the record there reuses that evaluation), and
    ! the others (positions, velocities and laws as far as their roots need)
    integer :: root_dynamics = 0, root_dynamics_at_outputs = 0, root_partial = 0
    ! root values of the last evaluation and the state they belong to
    logical :: cached = .false.
    logical :: cache_exact = .true.            ! its normal forces evaluated, not interpolated
    real(wp) :: cache_t = 0
    real(wp), allocatable :: cache_y(:), cache_g(:), work_ydot(:)
    real(wp), allocatable :: root_scale(:)     ! largest |g_i| met in the run
    ! ... and those of the last right-hand side
    logical :: rhs_cached = .false.
    real(wp) :: rhs_t = 0
    real(wp), allocatable :: rhs_y(:), rhs_g(:)
    ! the normal forces of the last two root value sets with exact ones (root location between them)
    integer :: n_exact = 0
    real(wp) :: exact_t(2) = 0
    real(wp), allocatable :: exact_n(:, :)
    integer :: interpolated_calls = 0
    ! the scale a lift-off's N is judged against (track_normal_reference)
    real(wp), allocatable :: normal_reference(:)   ! largest |N| of each one-sided contact at the start and outputs
    real(wp), allocatable :: pending_normal(:)     ! N at the current output time, kept once the driver moves on
    real(wp) :: pending_t = 0
    logical :: started = .false., pending = .false.
    integer, allocatable :: edge_coordinate(:) ! position in y of each edge's u or v (0: a dependent one)
    integer, allocatable :: charts(:)          ! elements whose charts are watched
    integer, allocatable :: chart_angle(:)     ! position in y of each one's deciding coordinate
                                               ! (minus its scalar index: a dependent one)
    integer :: chart_changes = 0
  contains
    procedure :: state_size, initial_state, check_start, start_series
    procedure :: rhs => mechanism_rhs
    procedure :: root_count => mechanism_root_count
    procedure :: roots => mechanism_roots
    procedure :: record => mechanism_record
    procedure :: handle_event => mechanism_handle_event
    procedure :: diagnose => mechanism_diagnose
    procedure :: stiffness_may_cause => mechanism_stiffness_may_cause
    procedure :: positions_at
  end type mechanism_ode_t

  interface
    ! kinetostatics_mechanism_ode_events
    module subroutine prepare(self)
      class(mechanism_ode_t), intent(inout) :: self
    end subroutine prepare

    integer module function mechanism_root_count(self) result(n)
      class(mechanism_ode_t), intent(in) :: self
    end function mechanism_root_count

    module subroutine mechanism_roots(self, t, y, g)
      class(mechanism_ode_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: g(:)
    end subroutine mechanism_roots

    module subroutine root_values(self, y, level)
      class(mechanism_ode_t), intent(inout) :: self
      real(wp), intent(in) :: y(:)
      integer, intent(in) :: level
    end subroutine root_values

    module subroutine mechanism_handle_event(self, t, y, fired, action, status)
      class(mechanism_ode_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: y(:)
      integer, intent(in) :: fired(:)
      integer, intent(out) :: action
      type(status_t), intent(inout) :: status
    end subroutine mechanism_handle_event

    !> The one-sided contacts j with select(j) whose |N| (self%work's, when
    !> `evaluated`) exceeds `factor` times the largest they carried before
    !> (normal_reference), named with both forces, and their count; every
    !> selected one, named alone, when the dynamics could not be evaluated.
    !> unbounded_normals' and check_lift_off's walk.
    module subroutine contacts_beyond(self, select, factor, evaluated, which, count)
      class(mechanism_ode_t), intent(in) :: self
      logical, intent(in) :: select(:), evaluated
      real(wp), intent(in) :: factor
      character(len=:), allocatable, intent(out) :: which
      integer, intent(out) :: count
    end subroutine contacts_beyond
  end interface

contains

  !> For a run that fails by its step count: the contact points at (t, y) that
  !> lie near a singular point of their surface's parametrisation (an
  !> ellipsoid's pole, an apex: |r_u x r_v| below 1e-2 (|r_u|^2 + |r_v|^2)),
  !> where the rates of (u, v) grow without bound and the steps shrink; and
  !> the one-sided contacts whose normal force has grown without bound (a
  !> singular, conformal contact whose pole the steps close in on without
  !> passing it, so that no lift-off root fires: unbounded_normals).
  function mechanism_diagnose(self, t, y) result(text)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    character(len=:), allocatable :: text, note
    type(status_t) :: st
    integer :: k
    text = ''
    self%cached = .false.
    self%rhs_cached = .false.
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), st)
    if (.not. st%ok()) return
    do k = 1, self%mechanism%n_elements
      note = self%work%elements(k)%e%singular_note()
      if (len(note) == 0) cycle
      if (len(text) > 0) text = text//'; '
      text = text//note
    end do
    note = unbounded_normals(self, t, y)
    if (len(note) > 0 .and. len(text) > 0) text = text//'; '
    text = text//note
  end function mechanism_diagnose

  !> Stiffness may be the trouble unless a normal force has grown without
  !> bound (a pole of the dynamics: BDF's steps close in on it the same).
  logical function mechanism_stiffness_may_cause(self, t, y) result(may)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    may = len(unbounded_normals(self, t, y)) == 0
  end function mechanism_stiffness_may_cause

  !> The one-sided contacts whose |N| at (t, y) exceeds 1/lift_off_tolerance
  !> times the largest the contact carried at the start and the outputs
  !> before (check_lift_off's scale: a lift-off's N is within
  !> lift_off_tolerance of it, a pole's 1e3 times and more), in words; empty
  !> if none, or if the dynamics cannot be evaluated there.
  function unbounded_normals(self, t, y) result(text)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    character(len=:), allocatable :: text, which
    type(status_t) :: st
    integer :: f, n, count_unbounded
    text = ''
    if (.not. allocated(self%normal_reference)) return
    f = self%mechanism%f
    n = f + self%mechanism%ns
    self%cached = .false.
    self%rhs_cached = .false.
    call self%mechanism%dynamics(self%work, t, y(1:f), y(f + 1:n), self%work_ydot(1:n - f), st)
    self%cached = .false.
    self%rhs_cached = .false.
    if (.not. st%ok()) return
    call contacts_beyond(self, self%normal_reference > 0, 1/lift_off_tolerance, .true., which, count_unbounded)
    if (count_unbounded == 0) return
    text = 'the normal force'//trim(merge('s of contacts', ' of contact  ', count_unbounded > 1))//' '//which// &
      trim(merge(' grow  ', ' grows ', count_unbounded > 1))//' unbounded at t = '//format_short(t)// &
      ' s: the contact is becoming singular, not a lift-off; '//singular_advice
  end function unbounded_normals

  integer function state_size(self) result(n)
    class(mechanism_ode_t), intent(in) :: self
    n = self%mechanism%f + self%mechanism%ns + self%mechanism%n_laws
  end function state_size

  !> y0 = [q0, s0, 0] (s0 = q0' without rate constraints); also prepares the
  !> work arrays of the root functions.
  function initial_state(self, q0, qd0) result(y0)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: q0(:), qd0(:)
    real(wp), allocatable :: y0(:)
    y0 = [q0, qd0, spread(0.0_wp, 1, self%mechanism%n_laws)]
    call prepare(self)
    ! a new run: the lift-off scale starts afresh (prepare keeps arrays of the same size)
    self%normal_reference = 0
    self%started = .false.
    self%pending = .false.
    call clear_stop(self)
  end function initial_state

  !> Before a run: the loops close and are regular at q0 (mechanism%check_start)
  !> and every one-sided contact presses (N > 0).
  subroutine check_start(self, y0, status)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: y0(:)
    type(status_t), intent(inout) :: status
    real(wp) :: residual
    integer :: f, k
    self%not_pressing = 0
    if (.not. status%ok()) return
    f = self%mechanism%f
    call self%mechanism%check_start(self%work, y0(1:f), status)
    if (.not. status%ok()) return
    call self%mechanism%evaluate(self%work, 0.0_wp, y0(1:f), y0(f + 1:f + self%mechanism%ns), residual, status)
    if (.not. status%ok()) return
    do k = 1, size(self%mechanism%contacts)
      associate (c => self%mechanism%contacts(k))
        if (c%one_sided .and. .not. self%work%normal_force(k) > 0) then
          self%not_pressing = k
          call set_status(status, STATUS_INVALID_INPUT, 'at the start contact '''//c%name// &
            ''' does not press (normal force '//format_short(self%work%normal_force(k))//' N): it would lift off at once')
          return
        end if
      end associate
    end do
  end subroutine check_start

  !> Empty series with room for `capacity` records (it grows when needed).
  subroutine start_series(self, capacity)
    class(mechanism_ode_t), intent(inout) :: self
    integer, intent(in) :: capacity
    call self%series%init(self%mechanism, capacity)
    self%outcome = ''
    call clear_stop(self)
  end subroutine start_series

  subroutine clear_stop(self)
    class(mechanism_ode_t), intent(inout) :: self
    self%stop_kind = STOP_NONE
    self%stop_element = 0
    self%stop_contact = 0
  end subroutine clear_stop

  subroutine mechanism_rhs(self, t, y, ydot, status)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    integer :: f, n
    if (.not. allocated(self%cache_y)) call prepare(self)   ! once, if initial_state was not used
    f = self%mechanism%f
    n = f + self%mechanism%ns
    self%rhs_count = self%rhs_count + 1
    self%cached = .false.
    self%rhs_cached = .false.
    call self%mechanism%dynamics(self%work, t, y(1:f), y(f + 1:n), ydot(f + 1:n), status)
    if (.not. status%ok()) return
    ydot(1:f) = self%work%rates
    ydot(n + 1:) = self%work%law_power
    if (self%n_roots == 0) return
    call root_values(self, y, 3)
    ! the arrays have their sizes since prepare: plain copies
    self%cache_t = t
    self%cache_y(:) = y
    self%cached = .true.
    self%cache_exact = .true.
    self%rhs_t = t
    self%rhs_y(:) = y
    self%rhs_g(:) = self%cache_g
    self%rhs_cached = .true.
  end subroutine mechanism_rhs

  !> The positions at y for an extension's own roots (the flights' gaps):
  !> kept where the mechanism's roots just set them (the closure converged
  !> at the same independent coordinates), else solved again, warm from the
  !> last solution (the stored root values then belong to another state).
  !> A trial state the closure cannot reach returns the closure's status.
  subroutine positions_at(self, y, status)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: y(:)
    type(status_t), intent(inout) :: status
    if (self%work%converged .and. all(self%work%scalars(self%mechanism%q)%q == y(1:self%mechanism%f))) return
    call self%mechanism%set_positions(self%work, y(1:self%mechanism%f), status)
    if (.not. status%ok()) return
    self%cached = .false.
    self%rhs_cached = .false.
  end subroutine positions_at

  !> Records the complete state (series of kinetostatics_recorder): the
  !> mechanism's evaluate at (t, y), which also evaluates its record-only
  !> elements (the closure monitors), skipped in the right-hand sides.
  subroutine mechanism_record(self, t, y, kind, status)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    integer :: f, n
    f = self%mechanism%f
    n = f + self%mechanism%ns
    if (.not. allocated(self%series%time)) call self%start_series(100)
    call self%series%record(self%mechanism, self%work, t, y(1:f), y(f + 1:n), y(n + 1:), kind, status)
  end subroutine mechanism_record
end module kinetostatics_mechanism_ode
