!> The largest values of quantities of an integration, located between the
!> records on the integrator's dense output (docs/accuracy.md, "Extremes").
!>
!> A record (a sampled state) that is a discrete local maximum of a quantity
!> brackets a maximum of the continuous quantity between its neighbouring
!> records. There the quantity is maximised (Brent's parabolic and golden
!> search) as a function of time, each trial evaluating the model at the
!> state the integrator's interpolating polynomial gives (the pieces of
!> observe_step, numerics_event_driver): the state is as accurate as the
!> integration, and the quantity is the model's own at that state, so a
!> kink of the quantity (a jump of curvature) is seen where it is, not
!> smoothed by an interpolation of the quantity.
!>
!> A bracket is a candidate while it could hold the overall maximum: while
!> its record's value plus its rise over the lower neighbour (for a smooth
!> peak, 8 times the most the peak between can exceed the record) reaches
!> the largest record so far. The candidates and the steps under them are
!> kept; the others go as the records rise. At the end (finish) the
!> candidates are searched, the most promising first, while they can still
!> beat the best: typically one or two per quantity. A record at an event
!> (the model may change there) splits its bracket: each side is searched
!> with the model of that side (`context`, the numbers the system keeps
!> with the record that starts a stretch: how its model is switched there,
!> and a start for its solvers). Every record's own value counts too: the result
!> is never below the records' largest.
!>
!> Minima are maxima of minus the quantity: the caller gives values to
!> maximise and, per quantity, the `attached` numbers to keep with the best
!> (the reported value, where it is, ...).
module numerics_dense_extremes
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INTERNAL
  use base_text, only: format_short
  implicit none (type, external)
  private
  public :: dense_extremes_t, dense_quantities_t

  !> What evaluates the quantities at any state (the model).
  type, abstract :: dense_quantities_t
  contains
    procedure(evaluate_quantities_i), deferred :: evaluate
  end type dense_quantities_t

  abstract interface
    !> The quantities (to maximise) and their attached numbers at state y at
    !> time t, with the model of the stretch whose first record the system
    !> gave `context`.
    subroutine evaluate_quantities_i(self, t, y, context, values, attached, status)
      import :: wp, status_t, dense_quantities_t
      class(dense_quantities_t), intent(inout) :: self
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(in) :: context(:)
      real(wp), intent(out) :: values(:), attached(:, :)
      type(status_t), intent(inout) :: status
    end subroutine evaluate_quantities_i
  end interface

  integer, parameter :: max_order = 12   ! CVODE's highest order

  type :: dense_extremes_t
    integer :: n_state = 0, n_quantities = 0, n_attached = 0
    real(wp), allocatable :: best(:)               ! the largest value of each quantity
    real(wp), allocatable :: best_t(:)             ! when
    real(wp), allocatable :: best_attached(:, :)   ! (n_attached, n_quantities): its attached numbers
    integer :: records = 0                         ! records seen
    integer :: searches = 0, evaluations = 0       ! brackets searched, model evaluations for them
    ! the last three records: 1 oldest, 3 newest; `filled` of them so far
    integer :: filled = 0
    real(wp) :: window_t(3) = 0
    logical :: window_event(3) = .false.
    real(wp), allocatable :: window_context(:, :)      ! (n_context, 3)
    real(wp), allocatable :: window_values(:, :)       ! (n_quantities, 3)
    real(wp), allocatable :: window_attached(:, :, :)  ! (n_attached, n_quantities, 3)
    ! the brackets that may hold a quantity's maximum: (a, m) with the context
    ! of a's side and (m, b) with m's; one bracket (a, b) with m's context
    ! when not split
    integer :: candidates = 0
    integer, allocatable :: candidate_quantity(:)
    real(wp), allocatable :: candidate_context(:, :, :)                   ! (n_context, 2, capacity)
    real(wp), allocatable :: candidate_bound(:), candidate_t(:, :)         ! (3, capacity): a, m, b
    logical, allocatable :: candidate_split(:)
    ! the interpolating polynomials of the steps under the candidates and since the middle record
    integer :: pieces = 0
    real(wp), allocatable :: piece_end(:), piece_h(:)
    integer, allocatable :: piece_order(:)
    real(wp), allocatable :: piece_taylor(:, :, :)     ! (n_state, 0:max_order, capacity)
    ! scratch of one evaluation
    real(wp), allocatable :: y(:), values(:), attached(:, :)
  contains
    procedure :: start => extremes_start
    procedure :: add_piece => extremes_add_piece
    procedure :: add_record => extremes_add_record
    procedure :: add_bracket => extremes_add_bracket
    procedure :: finish => extremes_finish
    procedure :: state_at => extremes_state_at
  end type dense_extremes_t

  !> relative and absolute tolerances of the search on t (s): a smooth
  !> peak's value is then exact to rounding; a kink's to its slope times this
  real(wp), parameter :: time_rtol = 1e-10_wp, time_atol = 1e-12_wp

contains

  !> For states of n_state numbers, n_quantities quantities with n_attached
  !> numbers each, and n_context numbers kept with each record (add_record).
  subroutine extremes_start(self, n_state, n_quantities, n_attached, n_context)
    class(dense_extremes_t), intent(out) :: self
    integer, intent(in) :: n_state, n_quantities, n_attached, n_context
    self%n_state = n_state
    self%n_quantities = n_quantities
    self%n_attached = n_attached
    allocate (self%best(n_quantities), self%best_t(n_quantities), self%best_attached(n_attached, n_quantities))
    self%best = -huge(1.0_wp)
    self%best_t = 0
    self%best_attached = 0
    allocate (self%window_values(n_quantities, 3), self%window_attached(n_attached, n_quantities, 3))
    allocate (self%piece_end(16), self%piece_h(16), self%piece_order(16), self%piece_taylor(n_state, 0:max_order, 16))
    allocate (self%y(n_state), self%values(n_quantities), self%attached(n_attached, n_quantities))
    allocate (self%window_context(n_context, 3))
    allocate (self%candidate_quantity(16), self%candidate_context(n_context, 2, 16), self%candidate_bound(16), &
              self%candidate_t(3, 16), self%candidate_split(16))
  end subroutine extremes_start

  !> The interpolating polynomial of one internal step [t_n - h, t_n] (h > 0),
  !> Taylor coefficients at t_n (ode_step_polynomial).
  subroutine extremes_add_piece(self, t_n, h, taylor)
    class(dense_extremes_t), intent(inout) :: self
    real(wp), intent(in) :: t_n, h, taylor(:, 0:)
    real(wp), allocatable :: end_(:), h_(:), taylor_(:, :, :)
    integer, allocatable :: order_(:)
    integer :: n
    n = self%pieces
    if (n == size(self%piece_end)) then
      allocate (end_(2*n), h_(2*n), order_(2*n), taylor_(self%n_state, 0:max_order, 2*n))
      end_(:n) = self%piece_end
      h_(:n) = self%piece_h
      order_(:n) = self%piece_order
      taylor_(:, :, :n) = self%piece_taylor
      call move_alloc(end_, self%piece_end)
      call move_alloc(h_, self%piece_h)
      call move_alloc(order_, self%piece_order)
      call move_alloc(taylor_, self%piece_taylor)
    end if
    n = n + 1
    self%pieces = n
    self%piece_end(n) = t_n
    self%piece_h(n) = h
    self%piece_order(n) = ubound(taylor, 2)
    self%piece_taylor(:, 0:ubound(taylor, 2), n) = taylor
  end subroutine extremes_add_piece

  !> The state at t from the newest piece that holds t (a restart's pieces
  !> replace the old step's after the event); found false if none does.
  subroutine extremes_state_at(self, t, y, found)
    class(dense_extremes_t), intent(in) :: self
    real(wp), intent(in) :: t
    real(wp), intent(out) :: y(:)
    logical, intent(out) :: found
    integer :: i, k
    real(wp) :: s, slack
    found = .false.
    do i = self%pieces, 1, -1
      slack = 8*epsilon(1.0_wp)*max(abs(t), self%piece_h(i))
      if (t > self%piece_end(i) + slack .or. t < self%piece_end(i) - self%piece_h(i) - slack) cycle
      s = t - self%piece_end(i)
      y = self%piece_taylor(:, self%piece_order(i), i)
      do k = self%piece_order(i) - 1, 0, -1
        y = y*s + self%piece_taylor(:, k, i)
      end do
      found = .true.
      return
    end do
  end subroutine extremes_state_at

  !> A record at t: its values count, and the record before it (whose
  !> neighbours are now known) is examined. `event`: the model may change at
  !> t (its bracket is split there); `context`: the numbers the system keeps
  !> with this record (how its model is switched, a start for its solvers),
  !> given back when the stretch after it is evaluated.
  subroutine extremes_add_record(self, t, event, context, values, attached)
    class(dense_extremes_t), intent(inout) :: self
    real(wp), intent(in) :: t
    logical, intent(in) :: event
    real(wp), intent(in) :: context(:)
    real(wp), intent(in) :: values(:), attached(:, :)
    integer :: j
    self%records = self%records + 1
    do j = 1, self%n_quantities
      if (values(j) > self%best(j)) call take(self, j, t, values(j), attached(:, j))
    end do
    if (self%filled == 3) then
      self%window_t(1:2) = self%window_t(2:3)
      self%window_event(1:2) = self%window_event(2:3)
      self%window_context(:, 1:2) = self%window_context(:, 2:3)
      self%window_values(:, 1:2) = self%window_values(:, 2:3)
      self%window_attached(:, :, 1:2) = self%window_attached(:, :, 2:3)
    else
      self%filled = self%filled + 1
    end if
    associate (k => self%filled)
      self%window_t(k) = t
      self%window_event(k) = event
      self%window_context(:, k) = context
      self%window_values(:, k) = values
      self%window_attached(:, :, k) = attached
    end associate
    if (self%filled == 2) call examine(self, 1, 0, 2)
    if (self%filled == 3) call examine(self, 2, 1, 3)
    call prune(self)
  end subroutine extremes_add_record

  !> After the last record: it is examined with the one before it, and the
  !> candidates are searched, for each quantity the highest bound first,
  !> while a bound reaches the best.
  subroutine extremes_finish(self, model, status)
    class(dense_extremes_t), intent(inout) :: self
    class(dense_quantities_t), intent(inout) :: model
    type(status_t), intent(inout) :: status
    integer :: j, i, next, k
    if (self%filled >= 2) call examine(self, self%filled, self%filled - 1, 0)
    do j = 1, self%n_quantities
      do
        next = 0
        do i = 1, self%candidates
          if (self%candidate_quantity(i) /= j .or. self%candidate_bound(i) < self%best(j)) cycle
          if (next == 0) then
            next = i
          else if (self%candidate_bound(i) > self%candidate_bound(next)) then
            next = i
          end if
        end do
        if (next == 0) exit
        associate (t => self%candidate_t(:, next), context => self%candidate_context(:, :, next))
          if (self%candidate_split(next)) then
            call search(self, j, t(1), t(2), context(:, 1), model, status)
            if (status%ok()) call search(self, j, t(2), t(3), context(:, 2), model, status)
          else
            call search(self, j, t(1), t(3), context(:, 2), model, status)
          end if
        end associate
        if (.not. status%ok()) return
        self%candidate_bound(next) = -huge(1.0_wp)   ! searched
        ! the same quantity's candidates inside what was searched (a bracket
        ! the caller gave and the records' own around it) need no search
        do i = 1, self%candidates
          if (self%candidate_quantity(i) /= j .or. i == next) cycle
          if (all([(covered(self, i, k, next), k = 1, 2)])) self%candidate_bound(i) = -huge(1.0_wp)
        end do
      end do
    end do
  end subroutine extremes_finish

  !> Part k (1: before the middle, 2: after) of candidate i's search lies
  !> inside a part of candidate s's (or is empty).
  logical function covered(self, i, k, s)
    type(dense_extremes_t), intent(in) :: self
    integer, intent(in) :: i, k, s
    real(wp) :: a, b
    integer :: m
    associate (t => self%candidate_t(:, i), u => self%candidate_t(:, s))
      if (self%candidate_split(i)) then
        a = t(k)
        b = t(k + 1)
      else
        a = t(1)
        b = t(3)
        if (k == 2) b = a   ! one part only
      end if
      covered = .not. b > a
      if (self%candidate_split(s)) then
        do m = 1, 2
          covered = covered .or. (a >= u(m) .and. b <= u(m + 1))
        end do
      else
        covered = covered .or. (a >= u(1) .and. b <= u(3))
      end if
    end associate
  end function covered

  !> Drops the candidates that cannot beat their quantity's best, and the
  !> steps that are under no candidate and before the newest bracket.
  subroutine prune(self)
    type(dense_extremes_t), intent(inout) :: self
    integer :: i, keep, k
    real(wp) :: newest, a, b
    logical :: under
    keep = 0
    do i = 1, self%candidates
      if (self%candidate_bound(i) < self%best(self%candidate_quantity(i))) cycle
      keep = keep + 1
      if (keep == i) cycle
      self%candidate_quantity(keep) = self%candidate_quantity(i)
      self%candidate_context(:, :, keep) = self%candidate_context(:, :, i)
      self%candidate_bound(keep) = self%candidate_bound(i)
      self%candidate_t(:, keep) = self%candidate_t(:, i)
      self%candidate_split(keep) = self%candidate_split(i)
    end do
    self%candidates = keep
    ! the next record examined is the newest: its bracket starts at the one before
    newest = self%window_t(max(self%filled - 1, 1))
    keep = 0
    do i = 1, self%pieces
      b = self%piece_end(i)
      a = b - self%piece_h(i)
      if (b < newest) then
        under = .false.
        do k = 1, self%candidates
          under = self%candidate_t(1, k) <= b .and. a <= self%candidate_t(3, k)
          if (under) exit
        end do
        if (.not. under) cycle
      end if
      keep = keep + 1
      if (keep == i) cycle
      self%piece_end(keep) = self%piece_end(i)
      self%piece_h(keep) = self%piece_h(i)
      self%piece_order(keep) = self%piece_order(i)
      self%piece_taylor(:, :, keep) = self%piece_taylor(:, :, i)
    end do
    self%pieces = keep
  end subroutine prune

  subroutine take(self, j, t, value, attached)
    type(dense_extremes_t), intent(inout) :: self
    integer, intent(in) :: j
    real(wp), intent(in) :: t, value, attached(:)
    self%best(j) = value
    self%best_t(j) = t
    self%best_attached(:, j) = attached
  end subroutine take

  !> Window record c with its neighbours l (before) and r (after; 0: none):
  !> a candidate for each quantity it may hold the maximum of.
  !> A neighbour where the quantity has no value (-huge: the model there
  !> does not have it, as a switch's other side at the same time) is no
  !> neighbour: its side is not searched and does not raise the bound.
  subroutine examine(self, c, l, r)
    type(dense_extremes_t), intent(inout) :: self
    integer, intent(in) :: c, l, r
    integer :: j, n
    real(wp) :: v, lowest
    logical :: left, right
    do j = 1, self%n_quantities
      v = self%window_values(j, c)
      left = l > 0
      if (left) left = self%window_values(j, l) > -huge(1.0_wp)
      right = r > 0
      if (right) right = self%window_values(j, r) > -huge(1.0_wp)
      lowest = v
      if (left) lowest = min(lowest, self%window_values(j, l))
      if (right) lowest = min(lowest, self%window_values(j, r))
      if (left) then
        if (self%window_values(j, l) > v) cycle
      end if
      if (right) then
        if (self%window_values(j, r) > v) cycle
      end if
      ! flat (nothing between to find) or unable to beat the best
      if (.not. v > lowest .or. v + (v - lowest) < self%best(j)) cycle
      if (self%candidates == size(self%candidate_bound)) call grow_candidates(self)
      n = self%candidates + 1
      self%candidates = n
      self%candidate_quantity(n) = j
      self%candidate_bound(n) = v + (v - lowest)
      self%candidate_t(:, n) = self%window_t(c)
      self%candidate_context(:, 1, n) = self%window_context(:, c)
      self%candidate_context(:, 2, n) = self%window_context(:, c)
      if (left) then
        self%candidate_t(1, n) = self%window_t(l)
        self%candidate_context(:, 1, n) = self%window_context(:, l)
      end if
      if (right) self%candidate_t(3, n) = self%window_t(r)
      self%candidate_split(n) = .not. left .or. .not. right .or. self%window_event(c)
    end do
  end subroutine examine

  !> The caller knows that quantity j has a maximum between the newest
  !> record and the one before it (its rate falls through zero there), which
  !> the records' values may not show (a peak between two records that both
  !> lie low): that interval is searched at the end, with the earlier
  !> record's context, whatever the records' values.
  subroutine extremes_add_bracket(self, j)
    class(dense_extremes_t), intent(inout) :: self
    integer, intent(in) :: j
    integer :: n
    if (self%filled < 2) return
    if (self%candidates == size(self%candidate_bound)) call grow_candidates(self)
    n = self%candidates + 1
    self%candidates = n
    self%candidate_quantity(n) = j
    self%candidate_bound(n) = huge(1.0_wp)
    self%candidate_t(:, n) = [self%window_t(self%filled - 1), self%window_t(self%filled - 1), &
                              self%window_t(self%filled)]
    self%candidate_context(:, 1, n) = self%window_context(:, self%filled - 1)
    self%candidate_context(:, 2, n) = self%window_context(:, self%filled - 1)
    self%candidate_split(n) = .false.
  end subroutine extremes_add_bracket

  subroutine grow_candidates(self)
    type(dense_extremes_t), intent(inout) :: self
    integer, allocatable :: quantity(:)
    real(wp), allocatable :: context(:, :, :)
    real(wp), allocatable :: bound(:), t(:, :)
    logical, allocatable :: split(:)
    integer :: n
    n = self%candidates
    allocate (quantity(2*n), context(size(self%candidate_context, 1), 2, 2*n), bound(2*n), t(3, 2*n), split(2*n))
    quantity(:n) = self%candidate_quantity(:n)
    context(:, :, :n) = self%candidate_context(:, :, :n)
    bound(:n) = self%candidate_bound(:n)
    t(:, :n) = self%candidate_t(:, :n)
    split(:n) = self%candidate_split(:n)
    call move_alloc(quantity, self%candidate_quantity)
    call move_alloc(context, self%candidate_context)
    call move_alloc(bound, self%candidate_bound)
    call move_alloc(t, self%candidate_t)
    call move_alloc(split, self%candidate_split)
  end subroutine grow_candidates

  !> Brent's search for the largest value of quantity j on (a, b), with the
  !> model of `context`; the best value evaluated is taken if above the best.
  subroutine search(self, j, a_in, b_in, context, model, status)
    type(dense_extremes_t), intent(inout) :: self
    integer, intent(in) :: j
    real(wp), intent(in) :: context(:), a_in, b_in
    class(dense_quantities_t), intent(inout) :: model
    type(status_t), intent(inout) :: status
    real(wp), parameter :: golden = 0.5_wp*(3 - sqrt(5.0_wp))
    real(wp) :: a, b, x, w, v, u, fx, fw, fv, fu, m, tol, d, e, p, q, r
    integer :: iteration
    if (.not. b_in > a_in) return
    self%searches = self%searches + 1
    a = a_in
    b = b_in
    x = a + golden*(b - a)
    w = x
    v = x
    fx = f(x)
    if (.not. status%ok()) return
    fw = fx
    fv = fx
    d = 0
    e = 0
    do iteration = 1, 100
      m = 0.5_wp*(a + b)
      tol = time_rtol*abs(x) + time_atol
      if (abs(x - m) <= 2*tol - 0.5_wp*(b - a)) exit
      p = 0
      q = 0
      r = 0
      if (abs(e) > tol) then
        ! a parabola through x, w, v (on -f: the minimum of the minus)
        r = (x - w)*(fx - fv)
        q = (x - v)*(fx - fw)
        p = (x - v)*q - (x - w)*r
        q = 2*(q - r)
        if (q > 0) then
          p = -p
        else
          q = -q
        end if
        r = e
        e = d
      end if
      if (abs(p) < abs(0.5_wp*q*r) .and. p > q*(a - x) .and. p < q*(b - x)) then
        d = p/q
        u = x + d
        if (u - a < 2*tol .or. b - u < 2*tol) d = sign(tol, m - x)
      else
        if (x < m) then
          e = b - x
        else
          e = a - x
        end if
        d = golden*e
      end if
      if (abs(d) >= tol) then
        u = x + d
      else
        u = x + sign(tol, d)
      end if
      fu = f(u)
      if (.not. status%ok()) return
      if (fu <= fx) then
        if (u < x) then
          b = x
        else
          a = x
        end if
        v = w; fv = fw
        w = x; fw = fx
        x = u; fx = fu
      else
        if (u < x) then
          a = u
        else
          b = u
        end if
        if (fu <= fw .or. w == x) then
          v = w; fv = fw
          w = u; fw = fu
        else if (fu <= fv .or. v == x .or. v == w) then
          v = u; fv = fu
        end if
      end if
    end do
  contains
    !> Minus quantity j at time s (the search minimises); a new best is taken.
    real(wp) function f(s)
      real(wp), intent(in) :: s
      logical :: found
      integer :: i
      f = 0
      call self%state_at(s, self%y, found)
      if (.not. found) then
        call set_status(status, STATUS_INTERNAL, 'extremes: no step of the integration holds t = '// &
                        format_short(s)//' s')
        return
      end if
      self%evaluations = self%evaluations + 1
      call model%evaluate(s, self%y, context, self%values, self%attached, status)
      if (.not. status%ok()) return
      ! any state evaluated is a sample of every quantity
      do i = 1, self%n_quantities
        if (self%values(i) > self%best(i)) call take(self, i, s, self%values(i), self%attached(:, i))
      end do
      f = -self%values(j)
    end function f
  end subroutine search
end module numerics_dense_extremes
