!> Geometry optimisation of a slide (thesis 4.7, eq. 4.49, table 4.12;
!> METHOD-PART2 E; choices in docs/design.md).
!>
!> The slide is a circular tube around a centerline through points, or a
!> chain of standard elements; some coordinates of some points (or some
!> element parameters) are the design variables x, each with bounds that
!> hold exactly (numerics_least_squares' change of variables, never a
!> penalty). A design's rides are design_geometry_evaluation's; the cost
!> (4.49) is
!>   F(x) = 1/2 sum_i [max_t |a_i(x)|]^2 + constraint terms
!> and the tipping lever arm of every ride must stay at most lever_limit,
!> measured by the tipping excess g_i = max_t e_i (design_cuboid_ride: <= 0
!> exactly when the body stays pressed and |l| <= lever_limit; = l - l_max
!> under the body's weight):
!>   CONSTRAINT_PENALTY  the thesis's penalty: one residual per ride,
!>                       factor max(0, g_i) (violation x factor, entering the
!>                       squared cost);
!>   CONSTRAINT_EXACT    the same residuals in an augmented Lagrangian,
!>                       sqrt(rho) max(0, g_i + lambda_i/rho), with the
!>                       multipliers updated between fits until every g_i is
!>                       at most lever_tolerance;
!>   CONSTRAINT_NONE     accelerations only.
!> A design whose slide cannot be built or ridden (folding, a ride that does
!> not reach the end) is a rejected step of the fit.
!>
!> An end of LMDER is not taken for a minimum: LMDER stops on step and
!> tolerance tests (xtol, ftol) that a stall far from a minimum passes too
!> (a trust region shrunk by rejected steps, the kinks of the penalty). So
!> the fit is restarted from its end point until a restart lowers the cost
!> by no more than ftol (relative): only then is the end a minimum. At the
!> end every constraint of the optimisation (no ride lifts off, every
!> tipping excess at most lever_tolerance) is checked; the outcome says
!> which of these failed (OUTCOME_*), in words.
!>
!> Multi-start: start 1 is the given design, starts 2.. are drawn uniformly
!> in the bounds' box from a seeded stream (numerics_random; a draw whose
!> slide folds is drawn again), all before any ride, so each start's point
!> and result depend only on the seed and its number. The best start (an optimum before any other
!> outcome, then the least acceleration cost) is the result.
!>
!> Robust design (design_robust_cost): with a population's members and the
!> worst ride or a quantile as the cost's acceleration part, the first
!> acceleration residual is that statistic and the others are 0, so the
!> residuals keep their number (2 per ride) and a population of one is the
!> ordinary optimisation of its one ride, to the bit.
!>
!> Threads: the rides of one evaluation, and of all difference points, run
!> in `threads` OpenMP threads (design_geometry_evaluation); with several
!> starts the starts run in the threads instead (each one's rides one after
!> the other), with the same numbers again, except with a population: its
!> rides are many, so the starts run one after the other and each design's
!> rides share the threads. Under MPI (setup%ranks > 1) every rank runs the
!> same optimisation and rides its share of each batch of rides; the starts
!> then run one after the other.
!>
!> The design space (the slide of a design, the drawn starts) is
!> design_slide_design, a design's rides design_geometry_evaluation; their
!> names are public here too, as callers know them.
module design_geometry_optimization
  use base_kinds, only: wp, int64
  use base_log, only: progress_interval
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_NOT_CONVERGED
  use base_text, only: format_short, format_integer, format_real, append_item
  use design_slide_design, only: slide_design_t, table_4_12_design, design_points, start_x, &
    build_design_slide, start_points
  use numerics_least_squares, only: least_squares_problem_t, least_squares_options_t, &
    least_squares_result_t, solve_least_squares
  use design_robust_cost, only: COST_SUM, robust_maximum
  use design_geometry_evaluation, only: optimization_setup_t, design_evaluation_t, thesis_start_angles, &
    evaluate_design, ride_designs, constraint_violations, CONSTRAINT_PENALTY, CONSTRAINT_EXACT, CONSTRAINT_NONE
  implicit none (type, external)
  private
  public :: slide_design_t, optimization_setup_t, design_evaluation_t, optimization_result_t
  public :: table_4_12_design, thesis_start_angles, build_design_slide, evaluate_design, optimize_slide, design_points
  public :: CONSTRAINT_PENALTY, CONSTRAINT_EXACT, CONSTRAINT_NONE, start_record_t, start_points
  public :: OUTCOME_OPTIMUM, OUTCOME_CONSTRAINT, OUTCOME_NOT_MINIMUM, OUTCOME_FAILED, outcome_names
  public :: constraint_violations

  !> How an optimisation (or one of its starts) ended: a minimum that meets
  !> the constraints; a minimum that violates one; an end that a restart
  !> still improved (or the design budget ran out); no end point at all.
  integer, parameter :: OUTCOME_OPTIMUM = 0, OUTCOME_CONSTRAINT = 1, OUTCOME_NOT_MINIMUM = 2, OUTCOME_FAILED = 3
  character(len=*), parameter :: outcome_names(0:3) = [character(len=19) :: 'optimum', 'constraint violated', &
                                                       'not a minimum', 'failed']

  !> One start of a multi-start optimisation.
  type :: start_record_t
    real(wp), allocatable :: x_start(:), x(:)   !< m, the start and end designs
    real(wp) :: cost_start = 0, cost = 0        !< the fit's cost at both
    real(wp) :: acceleration_cost = 0           !< at the end, (m/s^2)^2
    integer :: outcome = OUTCOME_FAILED
    integer :: evaluations = 0                  !< designs ridden
    integer :: restarts = 0
    character(len=:), allocatable :: verdict    !< the outcome in words (or the failure)
  end type start_record_t

  type :: optimization_result_t
    real(wp), allocatable :: x(:)
    real(wp), allocatable :: points(:, :)
    type(design_evaluation_t) :: before, after
    real(wp) :: cost_before = 0, cost_after = 0   !< the fit's cost (with constraint terms)
    real(wp), allocatable :: multipliers(:)
    integer :: evaluations = 0, rejected = 0, outer = 0, info = 0
    integer :: outcome = OUTCOME_FAILED
    integer :: restarts = 0                   !< restarts from an end point
    character(len=:), allocatable :: stop_test, stop_reason   !< why MINPACK stopped first (its info, in words)
    character(len=:), allocatable :: final_stop_reason        !< ... and last (the last restart)
    character(len=:), allocatable :: minimum_check   !< what the restarts found
    character(len=:), allocatable :: violations      !< the violated constraints with values and limits ('' none)
    character(len=:), allocatable :: verdict         !< the outcome in words
    integer :: best_start = 1
    type(start_record_t), allocatable :: starts(:)
  end type optimization_result_t

  type, extends(least_squares_problem_t) :: optimization_problem_t
    type(optimization_setup_t) :: setup
    real(wp), allocatable :: lambda(:)    !< augmented Lagrangian multipliers
    integer :: mode = CONSTRAINT_PENALTY
    integer :: designs = 0                    !< designs evaluated so far (progress lines)
    character(len=:), allocatable :: label    !< 'start k: ' with several starts, else ''
    integer(int64) :: clock_last = -1         !< system_clock of the last progress line
    ! the design of least cost so far (the start design, then single
    ! evaluations): LMDER starts and ends on it, so neither needs its rides again
    logical :: has_best = .false.
    real(wp) :: best_cost = huge(1.0_wp)
    type(design_evaluation_t) :: best
    integer :: recalled = 0                   !< evaluations answered by `best`
  contains
    procedure :: residuals => problem_residuals
    procedure :: residuals_batch => problem_residuals_batch
  end type optimization_problem_t

contains

  !> The residuals of an evaluated design: the maximum acceleration of each
  !> ride (COST_SUM; else the population's statistic, then zeros), then one
  !> constraint residual per ride.
  pure subroutine residuals_of(problem, evaluation, r)
    class(optimization_problem_t), intent(in) :: problem
    type(design_evaluation_t), intent(in) :: evaluation
    real(wp), intent(out) :: r(:)
    integer :: i, n
    real(wp) :: g
    n = size(evaluation%rides)
    if (problem%setup%cost == COST_SUM) then
      r(1:n) = evaluation%rides%max_acceleration
    else
      r(1) = robust_maximum(evaluation%rides%max_acceleration, problem%setup%cost, problem%setup%quantile)
      r(2:n) = 0
    end if
    do i = 1, n
      g = evaluation%rides(i)%max_tipping_excess
      select case (problem%mode)
      case (CONSTRAINT_PENALTY)
        r(n + i) = sqrt(2*problem%setup%penalty_factor*max(0.0_wp, g))
      case (CONSTRAINT_EXACT)
        r(n + i) = sqrt(problem%setup%rho)*max(0.0_wp, g + problem%lambda(i)/problem%setup%rho)
      case default   ! CONSTRAINT_NONE: the accelerations only
        r(n + i) = 0
      end select
    end do
  end subroutine residuals_of

  subroutine problem_residuals(self, p, r, status)
    class(optimization_problem_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    type(design_evaluation_t) :: evaluation
    r = 0
    if (is_best(self, p)) then
      call residuals_of(self, self%best, r)
      self%recalled = self%recalled + 1
      return
    end if
    call evaluate_design(self%setup, p, evaluation, status)
    call progress(self, 1)
    if (.not. status%ok()) return
    call residuals_of(self, evaluation, r)
    if (0.5_wp*sum(r**2) < self%best_cost) call remember(self, evaluation)
  end subroutine problem_residuals

  !> Keeps `evaluation` as the best design (its cost under the current
  !> constraint terms).
  subroutine remember(self, evaluation)
    class(optimization_problem_t), intent(inout) :: self
    type(design_evaluation_t), intent(in) :: evaluation
    self%has_best = .true.
    self%best = evaluation
    self%best_cost = cost_of(self, evaluation)
  end subroutine remember

  logical function is_best(self, x)
    class(optimization_problem_t), intent(in) :: self
    real(wp), intent(in) :: x(:)
    is_best = .false.
    if (self%has_best) is_best = all(self%best%x == x)
  end function is_best

  !> A progress line to setup%log every few seconds of a long optimisation
  !> (base_log's progress_interval): how many designs have been evaluated.
  subroutine progress(self, evaluated)
    class(optimization_problem_t), intent(inout) :: self
    integer, intent(in) :: evaluated
    integer(int64) :: now, rate
    self%designs = self%designs + evaluated
    if (.not. associated(self%setup%log)) return
    call system_clock(now, rate)
    if (self%clock_last < 0) self%clock_last = now
    if (real(now - self%clock_last, wp) < progress_interval()*real(rate, wp)) return
    self%clock_last = now
    call self%setup%log('optimize: '//self%label//format_integer(self%designs)//' designs evaluated ('// &
                        format_integer(self%designs*size(self%setup%start_angles))//' rides), least cost so far '// &
                        format_short(self%best_cost))
  end subroutine progress
  !> All rides of all points in one parallel loop (ride_designs).
  subroutine problem_residuals_batch(self, p, r, statuses)
    class(optimization_problem_t), intent(inout) :: self
    real(wp), intent(in) :: p(:, :)
    real(wp), intent(out) :: r(:, :)
    type(status_t), intent(inout) :: statuses(:)
    type(design_evaluation_t), allocatable :: evaluations(:)
    integer :: k
    allocate (evaluations(size(p, 2)))
    r = 0
    call ride_designs(self%setup, p, evaluations, statuses)
    do k = 1, size(p, 2)
      if (statuses(k)%ok()) call residuals_of(self, evaluations(k), r(:, k))
    end do
    call progress(self, size(p, 2))
  end subroutine problem_residuals_batch

  !> Optimises the design from its start points (table 4.12 "before") and,
  !> with setup%starts > 1, from drawn ones too (see the module comment).
  !> status: not ok only when no start has an end point (the first failure);
  !> otherwise result%outcome and result%verdict say how the best one ended.
  subroutine optimize_slide(setup, result, status)
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    type(optimization_setup_t) :: one
    type(optimization_result_t), allocatable :: results(:)
    type(status_t), allocatable :: statuses(:)
    real(wp), allocatable :: x0(:), points(:, :)
    integer :: k, best, total
    logical :: parallel_starts

    if (size(setup%start_angles) < 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'geometry optimisation: no rides (start_angles)')
      return
    end if
    x0 = start_x(setup%design)
    if (any(x0 < setup%design%lower) .or. any(x0 > setup%design%upper)) then
      call set_status(status, STATUS_INVALID_INPUT, 'geometry optimisation: the start design lies outside '// &
                      'the bounds of its design variables')
      return
    end if
    points = start_points(setup%design, max(1, setup%starts), setup%seed)
    allocate (results(size(points, 2)), statuses(size(points, 2)))
    one = setup
    parallel_starts = size(results) > 1 .and. .not. allocated(setup%members) .and. setup%ranks < 2
    if (parallel_starts) one%threads = 1   ! the starts take the threads
    !$omp parallel do num_threads(max(1, setup%threads)) schedule(dynamic, 1) &
    !$omp if (parallel_starts .and. setup%threads > 1)
    do k = 1, size(results)
      call optimize_from(one, points(:, k), k, size(results) > 1, results(k), statuses(k))
    end do
    !$omp end parallel do

    best = 0
    total = 0
    do k = 1, size(results)
      total = total + results(k)%evaluations
      if (.not. statuses(k)%ok()) cycle
      if (best == 0) then
        best = k
      else if (better(results(k), results(best))) then
        best = k
      end if
    end do
    if (best == 0) then
      status = statuses(1)
      result = results(1)
      return
    end if
    result = results(best)
    result%best_start = best
    result%before = results(1)%before
    result%cost_before = results(1)%cost_before
    result%evaluations = total
    allocate (result%starts(size(results)))
    do k = 1, size(results)
      associate (s => result%starts(k), r => results(k))
        s%x_start = points(:, k)
        s%evaluations = r%evaluations
        s%restarts = r%restarts
        s%cost_start = r%cost_before
        if (statuses(k)%ok()) then
          s%x = r%x
          s%cost = r%cost_after
          s%acceleration_cost = r%after%acceleration_cost
          s%outcome = r%outcome
          s%verdict = r%verdict
        else
          s%x = points(:, k)
          s%cost = huge(1.0_wp)
          s%acceleration_cost = huge(1.0_wp)
          s%outcome = OUTCOME_FAILED
          s%verdict = statuses(k)%text()
        end if
      end associate
    end do
  end subroutine optimize_slide

  !> Whether start a ended better than start b: an outcome earlier in the
  !> list (an optimum first), then the smaller acceleration cost (the
  !> objective; the fits' costs hold constraint terms).
  pure logical function better(a, b)
    type(optimization_result_t), intent(in) :: a, b
    if (a%outcome /= b%outcome) then
      better = a%outcome < b%outcome
    else
      better = a%after%acceleration_cost < b%after%acceleration_cost
    end if
  end function better

  !> One optimisation from design x (start number `start`), to a checked end.
  subroutine optimize_from(setup, x_start, start, labelled, result, status)
    type(optimization_setup_t), intent(in) :: setup
    real(wp), intent(in) :: x_start(:)
    integer, intent(in) :: start
    logical, intent(in) :: labelled
    type(optimization_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    type(optimization_problem_t) :: problem
    real(wp), allocatable :: x(:), g(:)
    logical :: minimum
    integer :: n, outer

    n = size(setup%start_angles)
    x = x_start
    problem%label = ''
    if (labelled) problem%label = 'start '//format_integer(start)//': '
    call evaluate_design(setup, x, result%before, status)
    if (.not. status%ok()) then
      call prefix_status(status, problem%label//'the start design')
      if (start == 1) status%code = STATUS_INVALID_INPUT   ! the given one; a drawn one is a failed start
      return
    end if
    problem%setup = setup
    problem%mode = setup%constraint
    allocate (problem%lambda(n))
    problem%lambda = 0
    result%cost_before = cost_of(problem, result%before)
    call remember(problem, result%before)
    minimum = .false.
    do outer = 1, merge(setup%max_outer, 1, setup%constraint == CONSTRAINT_EXACT)
      result%outer = outer
      call fit_to_minimum(problem, x, result, minimum, status)
      if (.not. status%ok() .or. .not. minimum) exit
      if (setup%constraint /= CONSTRAINT_EXACT) exit
      call evaluate_at(problem, x, result%after, result%evaluations, status)
      if (.not. status%ok()) exit
      g = result%after%rides%max_tipping_excess
      if (all(g <= setup%lever_tolerance)) exit
      problem%lambda = max(0.0_wp, problem%lambda + setup%rho*g)   ! first-order multiplier update
      problem%best_cost = cost_of(problem, problem%best)   ! under the new multipliers
    end do
    ! designs ridden: the start design, the fit's (less those answered by
    ! `best`), the final one's if it was not the best already
    result%evaluations = 1 + result%evaluations - problem%recalled
    result%x = x
    result%points = design_points(setup%design, x)
    result%multipliers = problem%lambda
    if (.not. status%ok()) then
      call prefix_status(status, 'geometry optimisation')
      if (labelled) call prefix_status(status, 'start '//format_integer(start))
      return
    end if
    call evaluate_at(problem, x, result%after, result%evaluations, status)
    if (.not. status%ok()) return
    result%cost_after = cost_of(problem, result%after)
    result%violations = constraint_violations(setup, result%after)
    if (.not. minimum) then
      result%outcome = OUTCOME_NOT_MINIMUM
      result%verdict = 'not a minimum: '//result%minimum_check
    else if (len(result%violations) > 0 .and. setup%constraint /= CONSTRAINT_NONE) then
      result%outcome = OUTCOME_CONSTRAINT
      result%verdict = 'constraint violated at the end: '//result%violations
    else
      result%outcome = OUTCOME_OPTIMUM
      result%verdict = 'a minimum as far as LMDER can tell (a restart from the end point changed the cost by '// &
                       'at most ftol)'
      if (len(result%violations) > 0) result%verdict = result%verdict//'; constraint = ''none'', not '// &
                                                       'enforced: '//result%violations
    end if
  end subroutine optimize_from

  !> LMDER from x, restarted from each end point until a restart lowers the
  !> cost by at most ftol (relative): minimum = .true.; or until
  !> max_restarts restarts or the design budget (solver%max_evaluations) are
  !> spent: minimum = .false. (x is then the end of the last fit). What
  !> happened goes into result (stop_*, restarts, minimum_check).
  subroutine fit_to_minimum(problem, x, result, minimum, status)
    type(optimization_problem_t), intent(inout) :: problem
    real(wp), intent(inout) :: x(:)
    type(optimization_result_t), intent(inout) :: result
    logical, intent(out) :: minimum
    type(status_t), intent(out) :: status
    type(least_squares_options_t) :: options
    type(least_squares_result_t) :: fit
    real(wp), allocatable :: x_end(:)
    real(wp) :: cost_end
    integer :: attempt, used, m
    character(len=:), allocatable :: history

    options = problem%setup%solver
    m = 2*size(problem%setup%start_angles)
    minimum = .false.
    used = 0
    cost_end = huge(1.0_wp)
    history = ''
    result%restarts = 0
    do attempt = 0, problem%setup%max_restarts
      options%max_evaluations = problem%setup%solver%max_evaluations - used
      if (options%max_evaluations < 1) exit
      x_end = x
      call solve_least_squares(problem, m, x, problem%setup%design%lower, problem%setup%design%upper, options, &
                               fit, status)
      used = used + fit%evaluations
      result%evaluations = result%evaluations + fit%evaluations
      result%rejected = result%rejected + fit%rejected_evaluations
      result%info = fit%info
      if (attempt == 0) then
        result%stop_test = fit%stop_test
        result%stop_reason = fit%stop_reason
      end if
      result%final_stop_reason = fit%stop_reason
      result%restarts = attempt
      if (status%code == STATUS_NOT_CONVERGED .and. fit%info == 5) then
        status = status_t()   ! the budget: x is the last accepted design
        exit
      end if
      if (.not. status%ok()) return
      if (attempt > 0) then
        if (cost_end - fit%cost <= problem%setup%solver%ftol*cost_end) then
          if (fit%cost > cost_end) x = x_end   ! the restart moved off a bound uphill: keep the end
          minimum = .true.
          result%minimum_check = 'restart '//format_integer(attempt)//' from the end point changed the cost '// &
            'from '//format_short(cost_end)//' to '//format_short(fit%cost)//', by at most ftol = '// &
            format_real(problem%setup%solver%ftol)//' relative'
          if (len(history) > 0) result%minimum_check = result%minimum_check//'; before: '//history
          return
        end if
        call append_item(history, 'restart '//format_integer(attempt)//' lowered the cost from '// &
                         format_short(cost_end)//' to '//format_short(fit%cost), ', ')
      end if
      cost_end = fit%cost
    end do
    if (options%max_evaluations < 1 .or. fit%info == 5) then
      result%minimum_check = 'the design budget max_designs = '// &
        format_integer(problem%setup%solver%max_evaluations)//' ran out after '// &
        format_integer(result%restarts)//' restarts'
    else
      result%minimum_check = 'after max_restarts = '//format_integer(problem%setup%max_restarts)// &
        ' restarts the cost still falls by more than ftol = '//format_real(problem%setup%solver%ftol)
    end if
    if (len(history) > 0) result%minimum_check = result%minimum_check//' ('//history//')'
  end subroutine fit_to_minimum

  !> The evaluation of design x: the best one if it is x, else its rides
  !> (counted in `evaluations`).
  subroutine evaluate_at(problem, x, evaluation, evaluations, status)
    type(optimization_problem_t), intent(in) :: problem
    real(wp), intent(in) :: x(:)
    type(design_evaluation_t), intent(out) :: evaluation
    integer, intent(inout) :: evaluations
    type(status_t), intent(out) :: status
    if (is_best(problem, x)) then
      evaluation = problem%best
      status = status_t()
    else
      call evaluate_design(problem%setup, x, evaluation, status)
      evaluations = evaluations + 1
    end if
  end subroutine evaluate_at

  real(wp) function cost_of(problem, evaluation) result(f)
    type(optimization_problem_t), intent(in) :: problem
    type(design_evaluation_t), intent(in) :: evaluation
    real(wp) :: r(2*size(evaluation%rides))
    call residuals_of(problem, evaluation, r)
    f = 0.5_wp*sum(r**2)
  end function cost_of
end module design_geometry_optimization
