!> What every identification shares (the water's friction, design_water_identification;
!> the rider's, design_rider_identification): a bounded least-squares fit
!> (numerics_least_squares) of model parameters to measurements, its residuals
!> the weighted errors of cost groups (design_cost), and the fit's record.
!>
!> An identification extends three types and gives two procedures:
!> - identification_sample_t: what one run of its model gives at the
!>   measurement places (the simulated measurements);
!> - identification_problem_t: its setup and options, and
!>     simulate(p, sample, status)  one run of the model with the parameters p
!>                                  (read-only on the problem: runs in parallel);
!>     cost_groups(sample, groups)  its errors as cost groups, the position
!>                                  groups first, the speed group last;
!> - identification_fit_t: its result, extended by the estimates under their
!>   own names and the figures of its own groups.
!> fit_identification runs the fit and fills the shared record: the counts, the
!> stop (MINPACK's test, and whether the fit stopped early), the residual norm,
!> the correlations, and the cost with its position and speed parts and the
!> speed group's figures at the optimum; it hands back the sample and the
!> groups there for the identification's own figures.
!>
!> The residuals of a point are the groups' weighted errors in order (r = 0 if
!> the model fails there: a rejected step). The single evaluation of least cost
!> so far is kept: LMDER ends on it, so the figures at the optimum need no run
!> of their own (else one more run, counted). Difference points run in
!> `threads` OpenMP threads, each its own model, with the same numbers as
!> serially.
module design_identification
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use numerics_least_squares, only: least_squares_problem_t, least_squares_options_t, &
    least_squares_result_t, solve_least_squares
  use design_cost, only: cost_group_t, group_part, group_rmse, group_mae, group_max_abs, append_residuals
  implicit none (type, external)
  private
  public :: identification_sample_t, identification_problem_t, identification_fit_t
  public :: fit_identification, identification_solver

  !> The solver settings both identifications start from.
  type(least_squares_options_t), parameter :: identification_solver = &
    least_squares_options_t(ftol=1e-8_wp, xtol=1e-8_wp, gtol=1e-10_wp, epsfcn=1e-10_wp)

  !> The simulated measurements of one model run (each identification its own).
  type, abstract :: identification_sample_t
  end type identification_sample_t

  type, abstract, extends(least_squares_problem_t) :: identification_problem_t
    integer :: threads = 1                  !< OpenMP threads for independent evaluations
    ! the single evaluation of least cost so far
    logical :: has_best = .false.
    real(wp) :: best_cost = huge(1.0_wp)
    real(wp), allocatable :: best_p(:)
    class(identification_sample_t), allocatable :: best
  contains
    procedure(simulate_i), deferred :: simulate
    procedure(cost_groups_i), deferred :: cost_groups
    procedure :: residuals => identification_residuals
    procedure :: residuals_batch => identification_residuals_batch
  end type identification_problem_t

  abstract interface
    !> One run of the model with the parameters p: the simulated measurements,
    !> or a status (STATUS_DOMAIN: a rejected step). Reads the problem only.
    subroutine simulate_i(self, p, sample, status)
      import :: identification_problem_t, identification_sample_t, wp, status_t
      class(identification_problem_t), intent(in) :: self
      real(wp), intent(in) :: p(:)
      class(identification_sample_t), allocatable, intent(out) :: sample
      type(status_t), intent(out) :: status
    end subroutine simulate_i

    !> The errors of a sample as cost groups: the position groups, then the speed group.
    subroutine cost_groups_i(self, sample, groups)
      import :: identification_problem_t, identification_sample_t, cost_group_t
      class(identification_problem_t), intent(in) :: self
      class(identification_sample_t), intent(in) :: sample
      type(cost_group_t), allocatable, intent(out) :: groups(:)
    end subroutine cost_groups_i
  end interface

  !> The record of a fit every identification gives.
  type :: identification_fit_t
    logical :: covariance_valid = .false.
    real(wp), allocatable :: correlation(:, :)   !< of the parameters (0 where held, at a bound or no covariance)
    real(wp) :: weight = 0                        !< w of the cost
    real(wp) :: cost = 0, position_part = 0, speed_part = 0   !< rad^2
    real(wp) :: residual_norm = 0                 !< sqrt(sum r^2) = sqrt(2 cost)
    real(wp) :: rmse_speed = 0, mae_speed = 0, max_speed = 0   !< m/s
    real(wp), allocatable :: error_speed(:)       !< m/s, simulated - measured on every segment
    integer :: evaluations = 0, rejected = 0, info = 0
    character(len=:), allocatable :: stop_test    !< the test that ended the fit, in one word
    character(len=:), allocatable :: stop_reason  !< ... in words (numerics_lmder)
    !> the fit ended on the xtol test after rejected steps: its trust region
    !> may have shrunk at failed runs rather than at a minimum; the estimate is
    !> the last point accepted
    logical :: stopped_early = .false.
  end type identification_fit_t

contains

  !> r(p): the groups' weighted errors; the sample is kept when it is the best.
  subroutine identification_residuals(self, p, r, status)
    class(identification_problem_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    class(identification_sample_t), allocatable :: sample
    call evaluate(self, p, r, status, sample)
    if (.not. status%ok()) return
    if (0.5_wp*sum(r**2) < self%best_cost) then
      self%has_best = .true.
      self%best_cost = 0.5_wp*sum(r**2)
      self%best_p = p
      call move_alloc(sample, self%best)
    end if
  end subroutine identification_residuals

  !> Independent evaluations in `threads` OpenMP threads (each its own model).
  subroutine identification_residuals_batch(self, p, r, statuses)
    class(identification_problem_t), intent(inout) :: self
    real(wp), intent(in) :: p(:, :)
    real(wp), intent(out) :: r(:, :)
    type(status_t), intent(inout) :: statuses(:)
    integer :: k
    !$omp parallel do num_threads(max(1, self%threads)) schedule(dynamic, 1) &
    !$omp if (self%threads > 1 .and. size(p, 2) > 1)
    do k = 1, size(p, 2)
      call one_point(k)
    end do
    !$omp end parallel do
  contains
    subroutine one_point(k)
      integer, intent(in) :: k
      class(identification_sample_t), allocatable :: sample
      call evaluate(self, p(:, k), r(:, k), statuses(k), sample)
    end subroutine one_point
  end subroutine identification_residuals_batch

  subroutine evaluate(self, p, r, status, sample)
    class(identification_problem_t), intent(in) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    class(identification_sample_t), allocatable, intent(out) :: sample
    type(cost_group_t), allocatable :: groups(:)
    integer :: offset, g
    r = 0
    call self%simulate(p, sample, status)
    if (.not. status%ok()) return
    call self%cost_groups(sample, groups)
    offset = 0
    do g = 1, size(groups)
      call append_residuals(groups(g), r, offset)
    end do
  end subroutine evaluate

  !> Fits p (the start; a parameter with lower == upper stays) to the m
  !> residuals within the bounds and fills the shared record of `fit`. The
  !> counts and the stop are filled also when the fit fails (status, its
  !> message prefixed by `name`; a failed run at the optimum is not); on
  !> success `sample` and `groups` are the model's run and its cost groups at
  !> the optimum p, `result` the solver's own record.
  subroutine fit_identification(name, problem, m, p, lower, upper, solver, fit, result, sample, groups, status)
    character(len=*), intent(in) :: name
    class(identification_problem_t), intent(inout) :: problem
    integer, intent(in) :: m
    real(wp), intent(inout) :: p(:)
    real(wp), intent(in) :: lower(:), upper(:)
    type(least_squares_options_t), intent(in) :: solver
    class(identification_fit_t), intent(inout) :: fit
    type(least_squares_result_t), intent(out) :: result
    class(identification_sample_t), allocatable, intent(out) :: sample
    type(cost_group_t), allocatable, intent(out) :: groups(:)
    type(status_t), intent(out) :: status
    real(wp), allocatable :: parts(:)
    integer :: i, j, n, g

    call solve_least_squares(problem, m, p, lower, upper, solver, result, status)
    fit%evaluations = result%evaluations
    fit%rejected = result%rejected_evaluations
    fit%info = result%info
    fit%stop_test = result%stop_test
    fit%stop_reason = result%stop_reason
    if (.not. status%ok()) then
      call prefix_status(status, name)
      return
    end if
    fit%stopped_early = result%info == 2 .and. result%rejected_evaluations > 0
    fit%residual_norm = result%residual_norm
    fit%covariance_valid = result%covariance_valid
    n = size(p)
    allocate (fit%correlation(n, n))
    fit%correlation = 0
    if (result%covariance_valid) then
      associate (se => result%standard_error)
        do j = 1, n
          do i = 1, n
            if (se(i) > 0 .and. se(j) > 0) fit%correlation(i, j) = result%covariance(i, j)/(se(i)*se(j))
          end do
        end do
      end associate
    end if

    ! the figures at the optimum: the fit's own run there when it kept it
    if (problem%has_best .and. all(problem%best_p == p)) then
      call move_alloc(problem%best, sample)
      problem%has_best = .false.
    else
      call problem%simulate(p, sample, status)
      fit%evaluations = fit%evaluations + 1
      if (.not. status%ok()) return
    end if
    call problem%cost_groups(sample, groups)
    g = size(groups)
    parts = [(group_part(groups(i)), i=1, g)]
    fit%position_part = sum(parts(:g - 1))
    fit%speed_part = parts(g)
    fit%cost = fit%position_part + fit%speed_part
    fit%rmse_speed = group_rmse(groups(g))
    fit%mae_speed = group_mae(groups(g))
    fit%max_speed = group_max_abs(groups(g))
  end subroutine fit_identification
end module design_identification
