!> The root functions and events of a mechanism as an ODE model
!> (kinetostatics_mechanism_ode).
!>
!> Root functions, in this order:
!>   user crossings  y(event_index(k)) - event_value(k): a coordinate (1..f) or
!>                   a rate (f+1..2f) crossing a value; action `event_action`
!>                   (EVENT_RECORD by default);
!>   domain edges    +-(s - bound) - margin for every finite, non-periodic
!>                   edge of every surface joint (s its u or v, independent or
!>                   dependent; margin 1e-7 of the domain, kinetostatics_mechanism):
!>                   an edge in u reached is a normal end (the end of the
!>                   slide, or back at its start: EVENT_STOP, `outcome` says
!>                   which and where); an edge in v is the surface's side
!>                   edge (an open section's wall top): the body goes over
!>                   it, a normal end too (EVENT_STOP, outcome 'over the side
!>                   edge ...'), except at a pole (a singular parametrisation:
!>                   STATUS_DOMAIN with the surface's note);
!>   lift-off        N of every one-sided contact: falling through zero stops
!>                   the run (EVENT_STOP, outcome 'lift-off ...') if N is
!>                   near zero there; through a pole (a singular contact)
!>                   the run fails (STATUS_DOMAIN, check_lift_off);
!>   force laws      each law's own (kinetostatics_force_law), handled by the
!>                   law (e.g. switch itself and ask for a restart);
!>   charts          the chart margin of every element with a chart (a free
!>                   rotation: cos q2 - cos(limit), kinetostatics_free_rotation;
!>                   an ellipsoid's surface joints: cos v - cos(limit)), whose
!>                   deciding coordinate is integrated (from y) or dependent
!>                   (a loop's (u, v): from the closure, like a dependent
!>                   edge): at zero the chart is re-based on the current pose
!>                   (q and s or the dependent coordinates change, the motion
!>                   does not) and the integrator restarts.
!> Root values need the state at (t, y): an edge whose u or v is a generalized
!> coordinate (an open chain's surface joint) is y itself, other edges need
!> the closure, the laws positions and velocities, lift-off the whole
!> dynamics (N depends on q'').
!> Every right-hand side and every root evaluation stores the root values it
!> implies together with (t, y); the last right-hand side's are also kept
!> apart (a root evaluation at an output time between t_(n-1) and t_n must
!> not push out those of t_n, which CVODE asks for next). A root call at the
!> same (t, y) as either takes them from there. CVODE calls
!> the root functions at the end of each step, at y_n, while its last
!> right-hand side was at the corrector's previous iterate: the same t_n and
!> a state within the corrector's tolerance. There the stored values are
!> used as long as the states differ by at most d <= 1e-5 relative (q and s
!> on their scale, the integrals after them on theirs) and every value is
!> far from zero, |g_i| >= 1e4 d G_i (at most 0.1 G_i, at least 1e-9 G_i)
!> with G_i the largest |g_i| met in the run: the error of such a value is
!> the sensitivity of g to y times d, orders of magnitude below 1e4 d G_i,
!> so no sign can be wrong. Near a root, or at any other (t, y), the root call evaluates the
!> state itself, only to the level it needs: roots are located with exact
!> values. User crossings are always taken from y itself. If an evaluation
!> fails (a trial state beyond a domain edge), the edge roots come from the
!> scalars as far as the closure got (beyond the edge: negative) and the
!> others keep their last values, so the integrator locates the edge where
!> the state leaves the domain.
submodule (kinetostatics_mechanism_ode) kinetostatics_mechanism_ode_events
  implicit none (type, external)

contains

  !> The elements with a chart decided by an integrated coordinate (its
  !> position in y) or a dependent one (minus its scalar index).
  subroutine find_charts(self)
    class(mechanism_ode_t), intent(inout) :: self
    integer :: k, a
    allocate (self%charts(0), self%chart_angle(0))
    associate (m => self%mechanism)
      do k = 1, m%n_elements
        a = m%elements(k)%e%chart_angle()
        if (a == 0) cycle
        if (any(m%q == a)) then
          self%chart_angle = [self%chart_angle, findloc(m%q, a, dim=1)]
        else if (allocated(m%beta)) then
          if (.not. any(m%beta == a)) cycle
          self%chart_angle = [self%chart_angle, -a]
        else
          cycle
        end if
        self%charts = [self%charts, k]
      end do
    end associate
  end subroutine find_charts

  !> The chart margin of the k-th watched element: its deciding coordinate
  !> from y, or (dependent) from the closure's scalars if they are set
  !> (`closed`), else the last value stays.
  subroutine chart_root(self, y, k, closed, g)
    class(mechanism_ode_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    integer, intent(in) :: k
    logical, intent(in) :: closed
    real(wp), intent(inout) :: g
    associate (work => self%work, a => self%chart_angle(k))
      if (a > 0) then
        g = work%elements(self%charts(k))%e%chart_margin(y(a))
      else if (closed) then
        g = work%elements(self%charts(k))%e%chart_margin(work%scalars(-a)%q)
      end if
    end associate
  end subroutine chart_root

  module procedure prepare
    integer :: k, n_roots_before
    call self%mechanism%prepare_workspace(self%work)
    if (.not. allocated(self%charts)) call find_charts(self)
    associate (m => self%mechanism)
      self%edge_coordinate = [(findloc(m%q(1:m%f), m%edges(k)%scalar, dim=1), k = 1, size(m%edges))]
    end associate
    n_roots_before = self%n_roots
    ! its own roots (an extension's come after them, handled by the extension);
    ! every array sized by it is made anew when it changes
    self%n_roots = mechanism_root_count(self)
    if (allocated(self%cache_y)) then
      if (size(self%cache_y) == self%state_size() .and. self%n_roots == n_roots_before) return
      deallocate (self%cache_y, self%cache_g, self%work_ydot, self%rhs_y, self%rhs_g, self%root_scale)
    end if
    if (allocated(self%exact_n)) deallocate (self%exact_n, self%normal_reference, self%pending_normal)
    allocate (self%exact_n(count(self%mechanism%contacts%one_sided), 2))
    allocate (self%normal_reference(size(self%exact_n, 1)), self%pending_normal(size(self%exact_n, 1)))
    self%n_exact = 0
    self%normal_reference = 0
    self%started = .false.
    self%pending = .false.
    allocate (self%cache_y(self%state_size()), self%cache_g(max(self%n_roots, 1)), &
              self%work_ydot(self%state_size()), self%root_scale(max(self%n_roots, 1)), &
              self%rhs_y(self%state_size()), self%rhs_g(max(self%n_roots, 1)))
    self%cached = .false.
    self%rhs_cached = .false.
    self%root_scale = 0
  end procedure prepare

  module procedure mechanism_root_count
    n = size(self%mechanism%edges) + count(self%mechanism%contacts%one_sided) + n_law_roots(self%mechanism)
    if (allocated(self%event_index)) n = n + size(self%event_index)
    if (allocated(self%charts)) n = n + size(self%charts)
  end procedure mechanism_root_count

  !> Number of the laws' root functions.
  pure integer function n_law_roots(m)
    type(mechanism_t), intent(in) :: m
    n_law_roots = m%law_root_start(m%n_laws + 1) - 1
  end function n_law_roots

  !> Number of user crossings.
  pure integer function n_user(self)
    class(mechanism_ode_t), intent(in) :: self
    n_user = 0
    if (allocated(self%event_index)) n_user = size(self%event_index)
  end function n_user

  module procedure mechanism_roots
    type(status_t) :: status
    integer :: f, n, level
    logical :: interpolated
    if (.not. allocated(self%cache_y)) call prepare(self)
    self%root_calls = self%root_calls + 1
    if (serves(self%cached, self%cache_t, self%cache_y, self%cache_g)) then
      self%root_cache_hits = self%root_cache_hits + 1
      call root_values(self, y, 0)   ! the user crossings from y itself
      if (self%cache_exact) call keep_exact(self, t)
      call track_normal_reference(self, t)
      g = self%cache_g(1:size(g))
      return
    end if
    if (serves(self%rhs_cached, self%rhs_t, self%rhs_y, self%rhs_g)) then
      self%root_cache_hits = self%root_cache_hits + 1
      self%cache_t = self%rhs_t   ! the last right-hand side's values become the current ones
      self%cache_y(:) = self%rhs_y
      self%cache_g(:) = self%rhs_g
      self%cached = .true.
      self%cache_exact = .true.
      call root_values(self, y, 0)
      call keep_exact(self, t)
      call track_normal_reference(self, t)
      g = self%cache_g(1:size(g))
      return
    end if
    f = self%mechanism%f
    n = f + self%mechanism%ns
    level = 1
    if (n_law_roots(self%mechanism) > 0) level = 2
    if (any(self%mechanism%contacts%one_sided)) level = 3
    ! root location between two exact sets with settled normal forces: N
    ! from the line between them, the rest at its own level
    interpolated = level == 3 .and. t /= self%t_output .and. settled(self, t)
    if (interpolated) level = 2
    if (level == 3) then
      self%root_dynamics = self%root_dynamics + 1
      if (t == self%t_output) self%root_dynamics_at_outputs = self%root_dynamics_at_outputs + 1
    else
      self%root_partial = self%root_partial + 1
    end if
    select case (level)
    case (3)
      call self%mechanism%dynamics(self%work, t, y(1:f), y(f + 1:n), self%work_ydot(1:n - f), status)
    case (2)
      call self%mechanism%set_positions(self%work, y(1:f), status)
      if (status%ok()) call self%mechanism%set_velocities(self%work, y(f + 1:n))
      if (status%ok()) call self%mechanism%evaluate_laws(self%work, t, status)
    case default   ! only the edges and charts: a position pass unless each is a coordinate in y
      if (any(self%edge_coordinate == 0) .or. any(self%chart_angle < 0)) &
        call self%mechanism%set_positions(self%work, y(1:f), status)
    end select
    if (status%ok()) then
      call root_values(self, y, level)
      if (interpolated) then
        call interpolate_normal_forces(self, t)
        self%interpolated_calls = self%interpolated_calls + 1
      end if
      self%cache_t = t
      self%cache_y(:) = y
      self%cached = .true.
      self%cache_exact = .not. interpolated
      if (level == 3) call keep_exact(self, t)
      if (level == 3 .or. interpolated) call track_normal_reference(self, t)
    else
      call root_values(self, y, 1)   ! edges from the scalars as far as the closure got
      self%cached = .false.
    end if
    g = self%cache_g(1:size(g))
  contains
    !> Values stored at (t_c, y_c) serve at (t, y): the same t, and y equal
    !> or near with every value far from zero.
    logical function serves(stored, t_c, y_c, g_c)
      logical, intent(in) :: stored
      real(wp), intent(in) :: t_c, y_c(:), g_c(:)
      serves = .false.
      if (.not. stored .or. t /= t_c) return
      serves = all(y == y_c)
      if (.not. serves) serves = near_and_far_from_zero(self, y, y_c, g_c)
    end function serves
  end procedure mechanism_roots

  !> y within 1e-5 of a stored state y_c and every root value g_c stored
  !> with it far from zero (see the module comment). The mechanism's state
  !> (q, s) and the integrals after it (work, ...) are compared each on its
  !> own scale: one scale over all let a large integral (the friction work
  !> reaches thousands of J) admit position differences of 1e-4 and more.
  !> "Far" scales with the difference d actually found: the error of a
  !> stored value is its sensitivity times d, so 1e4 d G_i admits a
  !> relative sensitivity up to 1e4 (the spinning egg's N: ~40, from the
  !> spin's share of it) at any d; d is the corrector's last update, ~1e-11
  !> at the ride's tolerances, 1e-7..4e-6 at the egg's P2 (rtol 1e-6), and
  !> the bound 1e-5 keeps it where the first-order error estimate holds
  !> (0.1 G_i at most); not below 1e-9 G_i, far above the values' own
  !> rounding.
  logical function near_and_far_from_zero(self, y, y_c, g_c) result(usable)
    class(mechanism_ode_t), intent(in) :: self
    real(wp), intent(in) :: y(:), y_c(:), g_c(:)
    integer :: i, n
    real(wp) :: d, far
    n = self%mechanism%f + self%mechanism%ns
    d = distance(y(1:n), y_c(1:n))
    if (size(y) > n) d = max(d, distance(y(n + 1:), y_c(n + 1:)))
    usable = d <= 1e-5_wp
    if (.not. usable) return
    far = max(1e4_wp*d, 1e-9_wp)
    do i = n_user(self) + 1, self%n_roots
      if (abs(g_c(i)) < far*self%root_scale(i)) then
        usable = .false.
        return
      end if
    end do
  contains
    !> max |a - b| / max(max |b|, 1); NaN if any difference is NaN (not usable).
    !> One pass without temporaries: this runs at every step end.
    pure real(wp) function distance(a, b)
      real(wp), intent(in) :: a(:), b(:)
      real(wp) :: largest_difference, largest_b
      integer :: k
      largest_difference = 0
      largest_b = 1
      do k = 1, size(a)
        if (.not. abs(a(k) - b(k)) <= largest_difference) largest_difference = abs(a(k) - b(k))
        largest_b = max(largest_b, abs(b(k)))
      end do
      distance = largest_difference/largest_b
    end function distance
  end function near_and_far_from_zero

  !> Keeps the normal forces of cache_g (exact, at t) as the newest of the two
  !> sets root location interpolates between.
  subroutine keep_exact(self, t)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer :: first, nc
    nc = size(self%exact_n, 1)
    if (nc == 0) return
    first = n_user(self) + size(self%mechanism%edges) + 1
    if (self%n_exact > 0) then
      if (self%exact_t(2) == t) then   ! the same time again: the newer values
        self%exact_n(:, 2) = self%cache_g(first:first + nc - 1)
        return
      end if
      self%exact_t(1) = self%exact_t(2)
      self%exact_n(:, 1) = self%exact_n(:, 2)
    end if
    self%exact_t(2) = t
    self%exact_n(:, 2) = self%cache_g(first:first + nc - 1)
    self%n_exact = min(self%n_exact + 1, 2)
  end subroutine keep_exact

  !> The reference a lift-off's N is judged against (mechanism_handle_event):
  !> the largest |N| of each one-sided contact at the start and at the output
  !> times the run has passed, the forces the result file shows. Not the
  !> step ends: where N passes through a pole (a singular contact) CVODE's
  !> steps close in on it and their N grow as large as the root's. The values
  !> at an output time are taken where CVODE's root check evaluates them (at
  !> t = t_output, when a step passes it) and join the reference only when
  !> the driver has moved on to the next output time: a root found before
  !> the output time (the check there lies beyond it) keeps them out.
  subroutine track_normal_reference(self, t)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer :: first, nc
    nc = size(self%normal_reference)
    if (nc == 0) return
    first = n_user(self) + size(self%mechanism%edges) + 1
    if (.not. self%started) then   ! the first values: the start
      self%normal_reference(:) = abs(self%cache_g(first:first + nc - 1))
      self%started = .true.
    end if
    if (self%pending .and. self%t_output > self%pending_t) then
      self%normal_reference(:) = max(self%normal_reference, abs(self%pending_normal))
      self%pending = .false.
    end if
    if (t == self%t_output) then
      self%pending_t = t
      self%pending_normal(:) = self%cache_g(first:first + nc - 1)
      self%pending = .true.
    end if
  end subroutine track_normal_reference

  !> t lies strictly between the two kept exact sets and every normal force
  !> is settled there: the same sign at both, at least 1e-3 G_i from zero,
  !> changing by less than a tenth of its size. CVODE's root location then
  !> only looks for the crossing the step's end values show (the other
  !> roots keep their signs at both ends); a normal force that would dip
  !> through zero and back inside one step is not seen by the step-end check
  !> either, and with a change below a tenth of |N| over a step the error
  !> control keeps smooth, it cannot do so.
  logical function settled(self, t)
    class(mechanism_ode_t), intent(in) :: self
    real(wp), intent(in) :: t
    integer :: k, first
    real(wp) :: a, b
    settled = .false.
    if (self%n_exact < 2) return
    if (.not. (t > minval(self%exact_t) .and. t < maxval(self%exact_t))) return
    first = n_user(self) + size(self%mechanism%edges)
    do k = 1, size(self%exact_n, 1)
      a = self%exact_n(k, 1)
      b = self%exact_n(k, 2)
      if (.not. a*b > 0) return
      if (min(abs(a), abs(b)) < 1e-3_wp*self%root_scale(first + k)) return
      if (abs(a - b) >= 0.1_wp*min(abs(a), abs(b))) return
    end do
    settled = .true.
  end function settled

  !> The normal forces of cache_g on the line between the two kept sets.
  subroutine interpolate_normal_forces(self, t)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer :: first, nc
    real(wp) :: w
    nc = size(self%exact_n, 1)
    first = n_user(self) + size(self%mechanism%edges) + 1
    w = (t - self%exact_t(1))/(self%exact_t(2) - self%exact_t(1))
    self%cache_g(first:first + nc - 1) = (1 - w)*self%exact_n(:, 1) + w*self%exact_n(:, 2)
  end subroutine interpolate_normal_forces

  !> Fills cache_g from the workspace's state: user crossings always, edges
  !> from level 1, the laws' roots from level 2, lift-off from level 3 (the
  !> others are kept); a full evaluation (level 3) updates the scales G_i.
  module procedure root_values
    integer :: k, i
    real(wp) :: s
    i = 0
    do k = 1, n_user(self)
      i = i + 1
      self%cache_g(i) = y(self%event_index(k)) - self%event_value(k)
    end do
    if (level < 1) then   ! the charts from y too
      i = size(self%cache_g) - size(self%charts)
      do k = 1, size(self%charts)
        call chart_root(self, y, k, .false., self%cache_g(i + k))
      end do
      return
    end if
    associate (m => self%mechanism)
      do k = 1, size(m%edges)
        i = i + 1
        ! a coordinate's value is y's (set_positions copies it to the scalar)
        if (self%edge_coordinate(k) > 0) then
          s = y(self%edge_coordinate(k))
        else
          s = self%work%scalars(m%edges(k)%scalar)%q
        end if
        if (m%edges(k)%upper) then
          self%cache_g(i) = m%edges(k)%bound - m%edges(k)%margin - s
        else
          self%cache_g(i) = s - m%edges(k)%bound - m%edges(k)%margin
        end if
      end do
      do k = 1, size(m%contacts)
        if (.not. m%contacts(k)%one_sided) cycle
        i = i + 1
        if (level >= 3) self%cache_g(i) = self%work%normal(k)
      end do
      if (level >= 2 .and. n_law_roots(m) > 0) self%cache_g(i + 1:i + n_law_roots(m)) = self%work%law_roots
      i = i + n_law_roots(m)
      do k = 1, size(self%charts)
        call chart_root(self, y, k, .true., self%cache_g(i + k))
      end do
    end associate
    if (level >= 3) self%root_scale(:) = max(self%root_scale, abs(self%cache_g))
  end procedure root_values

  module procedure mechanism_handle_event
    integer :: k, i, law_action
    character(len=:), allocatable :: where, note
    self%cached = .false.
    self%rhs_cached = .false.
    self%n_exact = 0   ! a law or chart may change here: no interpolation across
    action = EVENT_IGNORE
    where = ' at t = '//format_short(t)//' s'
    i = 0
    do k = 1, n_user(self)
      i = i + 1
      if (fired(i) /= 0) action = max(action, self%event_action)
    end do
    associate (m => self%mechanism)
      do k = 1, size(m%edges)
        i = i + 1
        if (fired(i) /= -1) cycle
        associate (e => m%edges(k), name => m%elements(m%edges(k)%element)%e%name)
          if (.not. e%along_u) then
            ! an edge in v where the parametrisation is singular is a pole (an
            ! ellipsoid's v = +-pi/2): said so, with the surface and what to do
            note = self%work%elements(m%edges(k)%element)%e%singular_note()
            if (len(note) > 0) then
              call set_status(status, STATUS_DOMAIN, 'surface joint '''//name//''' reached the pole v = '// &
                              format_short(e%bound)//' of its surface'//where//': '//note)
              return
            end if
            ! any other edge in v is the side edge of the surface (the top of
            ! an open section's wall): the body leaves the surface there, a
            ! physical end the model cannot follow (flight is not built for
            ! a joint), said as such, not a failure of the computation
            action = EVENT_STOP
            call add_outcome(self, 'over the side edge: surface joint '''//name//''' reached the edge v = '// &
                             format_short(e%bound)//' of its surface'//where)
            call note_stop(self, STOP_SIDE_EDGE, element=e%element)
            cycle
          end if
          action = EVENT_STOP
          if (e%upper) then
            call add_outcome(self, 'end of slide: surface joint '''//name//''' reached its end u = '// &
                             format_short(e%bound)//where)
            call note_stop(self, STOP_END_OF_SURFACE, element=e%element)
          else
            call add_outcome(self, 'back at the start of the slide: surface joint '''//name// &
                             ''' reached its start u = '//format_short(e%bound)//where)
            call note_stop(self, STOP_START_OF_SURFACE, element=e%element)
          end if
        end associate
      end do
      call check_lift_off(self, t, y, fired(i + 1:i + size(self%normal_reference)), status)
      if (.not. status%ok()) return
      do k = 1, size(m%contacts)
        if (.not. m%contacts(k)%one_sided) cycle
        i = i + 1
        if (fired(i) /= -1) cycle
        action = EVENT_STOP
        call add_outcome(self, 'lift-off: the normal force of contact '''//m%contacts(k)%name// &
                         ''' fell to zero'//where)
        call note_stop(self, STOP_LIFT_OFF, contact=k)
      end do
      do k = 1, m%n_laws
        associate (first => m%law_root_start(k), last => m%law_root_start(k + 1) - 1)
          if (last < first) cycle
          if (all(fired(i + first:i + last) == 0)) cycle
          call self%work%laws(k)%law%handle_event(t, fired(i + first:i + last), law_action, status)
          if (.not. status%ok()) return
          action = max(action, law_action)
        end associate
      end do
      i = i + n_law_roots(m)
      do k = 1, size(self%charts)
        if (fired(i + k) /= -1) cycle
        call change_chart(self, self%charts(k), y, status)
        if (.not. status%ok()) return
        action = max(action, EVENT_RESTART)
      end do
    end associate
  end procedure mechanism_handle_event

  !> The lift-off roots (fired: those of the one-sided contacts) are lift-offs
  !> if N is near zero there: |N| <= lift_off_tolerance times the largest |N|
  !> the contact carried at the start and the outputs before (normal_reference).
  !> A root where N changes sign through a pole (a singular, conformal
  !> contact: the normal force grows without bound, and CVODE locates the
  !> pole to rounding, where |N| is 1e3 and more times that scale) is a
  !> failure of the run, not a lift-off. Every contact whose N is unbounded
  !> there is named: a singular contact drives the forces of the contacts
  !> coupled to it with its own, and which one it is the forces cannot tell.
  subroutine check_lift_off(self, t, y, fired, status)
    class(mechanism_ode_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: fired(:)
    type(status_t), intent(inout) :: status
    type(status_t) :: st
    integer :: f, n, count_singular
    character(len=:), allocatable :: which
    if (.not. any(fired == -1)) return
    f = self%mechanism%f
    n = f + self%mechanism%ns
    call self%mechanism%dynamics(self%work, t, y(1:f), y(f + 1:n), self%work_ydot(1:n - f), st)
    call contacts_beyond(self, fired == -1, lift_off_tolerance, st%ok(), which, count_singular)
    if (count_singular == 0) return
    if (.not. st%ok()) then
      call set_status(status, STATUS_DOMAIN, 'the contact became singular: where the normal force of contact'// &
        trim(merge('s ', '  ', count_singular > 1))//which//' changes sign the dynamics cannot be evaluated ('// &
        st%text()//'), not a lift-off; '//singular_advice)
    else if (count_singular == 1) then
      call set_status(status, STATUS_DOMAIN, 'contact '//which//' became singular: its normal force is '// &
        'unbounded where it changes sign, not a lift-off; '//singular_advice)
    else
      call set_status(status, STATUS_DOMAIN, 'a contact became singular: the normal forces of contacts '// &
        which//' are unbounded where they change sign, not a lift-off; '//singular_advice)
    end if
  end subroutine check_lift_off

  !> The walk over the one-sided contacts of unbounded_normals and
  !> check_lift_off (the interface in kinetostatics_mechanism_ode).
  module procedure contacts_beyond
    integer :: k, j
    which = ''
    count = 0
    j = 0
    associate (m => self%mechanism)
      do k = 1, size(m%contacts)
        if (.not. m%contacts(k)%one_sided) cycle
        j = j + 1
        if (.not. select(j)) cycle
        if (evaluated) then
          if (abs(self%work%normal(k)) <= factor*self%normal_reference(j)) cycle
        end if
        if (count > 0) which = which//', '
        which = which//''''//m%contacts(k)%name//''''
        if (evaluated) which = which//' (N = '//format_short(self%work%normal(k))//' N, at most '// &
          format_short(self%normal_reference(j))//' N before)'
        count = count + 1
      end do
    end associate
  end procedure contacts_beyond

  !> Re-bases the chart of element k on the current pose and writes the new
  !> coordinates and speeds into y.
  subroutine change_chart(self, k, y, status)
    class(mechanism_ode_t), intent(inout) :: self
    integer, intent(in) :: k
    real(wp), intent(inout) :: y(:)
    type(status_t), intent(inout) :: status
    integer :: f, n, i
    associate (m => self%mechanism)
      f = m%f
      n = f + m%ns
      call m%set_positions(self%work, y(1:f), status)
      if (.not. status%ok()) return
      call m%set_velocities(self%work, y(f + 1:n))
      call self%work%elements(k)%e%rebase(self%work%scalars)
      do i = 1, f
        y(i) = self%work%scalars(m%q(i))%q
      end do
      do i = 1, m%ns
        y(f + i) = self%work%scalars(m%q(m%speeds(i)))%qd
      end do
      self%chart_changes = self%chart_changes + 1
    end associate
  end subroutine change_chart

  !> The first stopping event's kind and what it names (the rest are in `outcome`).
  subroutine note_stop(self, kind, element, contact)
    class(mechanism_ode_t), intent(inout) :: self
    integer, intent(in) :: kind
    integer, intent(in), optional :: element, contact
    if (self%stop_kind /= STOP_NONE) return
    self%stop_kind = kind
    if (present(element)) self%stop_element = element
    if (present(contact)) self%stop_contact = contact
  end subroutine note_stop

  subroutine add_outcome(self, text)
    class(mechanism_ode_t), intent(inout) :: self
    character(len=*), intent(in) :: text
    if (.not. allocated(self%outcome)) self%outcome = ''
    if (len(self%outcome) > 0) then
      self%outcome = self%outcome//'; '//text
    else
      self%outcome = text
    end if
  end subroutine add_outcome
end submodule kinetostatics_mechanism_ode_events
