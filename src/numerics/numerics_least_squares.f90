!> Bounded nonlinear least squares, min 0.5 sum r_i(p)^2 with lower <= p <= upper,
!> over MINPACK's Levenberg-Marquardt code LMDER, with the problem's analytic
!> Jacobian or, when it has none, forward differences exactly as LMDIF forms
!> them (step sqrt(max(epsfcn, eps)) |z_j|, or that root itself if z_j = 0) but
!> evaluated here as one batch of points (`residuals_batch`), which a problem
!> may evaluate in parallel. LMDER with these differences is LMDIF.
!>
!> Bounds are held exactly by a smooth change of variables p = P(z); MINPACK
!> works on the unconstrained z:
!>   lower and upper:  p = c + h sin((z - c)/h),  c = (l + u)/2, h = (u - l)/2
!>                     (clamped to [l, u] against rounding; z = p at the middle
!>                     of the box with dp/dz = 1 there, so z keeps the units and
!>                     size of p and MINPACK's relative xtol means what it
!>                     means for p: a start in the middle is not a start at 0)
!>   lower only:       p = l + z^2 / (1 + sqrt(1 + z^2))  (= l + sqrt(z^2 + 1) - 1, never below l)
!>   upper only:       p = u - z^2 / (1 + sqrt(1 + z^2))
!>   neither:          p = z
!>   l == u:           p is fixed at l and not estimated.
!> Every p the problem is ever evaluated at is inside the bounds. Analytic
!> Jacobians get the chain rule dr/dz = dr/dp dP/dz. Because dP/dz = 0 on a
!> bound, a start on a bound is moved inside (by 1e-3 of the range or of
!> max(1, |bound|)), and an optimum on a bound is approached only slowly in z;
!> therefore after the first solve every parameter within bound_tolerance of a
!> bound whose gradient points out of the box (the Kuhn-Tucker sign) is put
!> exactly on the bound and the others are fitted again.
!>
!> A failed evaluation is a rejected step, not the end of the fit. When the
!> residuals fail at a trial point (a status STATUS_DOMAIN, STATUS_SOLVER or
!> STATUS_NOT_CONVERGED: the model cannot be run there), LMDER is handed
!> residuals whose norm is 1e3 max(1, the largest norm seen so far), at least
!> ten times the norm at its current point. LMDER then computes an actual
!> reduction of -1, rejects the step (ratio < 1e-4: x stays) and shrinks its
!> trust region to a tenth (MINPACK's factor p1 when fnorm1 >= 10 fnorm), and
!> tries a shorter step. If the region shrinks below xtol the fit ends at the
!> last accepted point (info 2). Failures are counted (rejected_evaluations)
!> and the last reason kept (last_rejection). A failure at the start point, a
!> failure of a difference point and its mirror, and any other status
!> (invalid input, i/o, internal) end the fit with that status, unchanged.
!>
!> The covariance is s^2 (J^T J)^(-1) in the original parameters, J = dr/dp at the
!> optimum over the parameters not at a bound (central differences that stay
!> inside the bounds, or the analytic Jacobian), s^2 = sum r^2 / (m - n_free);
!> parameters at a bound have zero rows and columns and at_bound = .true.
!> If the model fails on both sides of the optimum in some parameter, there
!> is no covariance (covariance_valid = .false.), the fit stands. A fit that
!> asks for no covariance (options%covariance = .false.) skips these
!> differences unless a parameter lies near a bound.
!>
!> LMDER asks for the same point twice in a row when a rejected step leaves the
!> Gauss-Newton step inside the shrunken trust region: the residuals of the
!> last successful evaluation are handed back (same bits, not counted).
!>
!> Re-entrant and thread-safe. MINPACK's callbacks carry no user data: each
!> call of solve_least_squares keeps its fit in a local record (`fit_t`) and
!> pushes it on a per-thread stack (`top`, OpenMP threadprivate) around each
!> MINPACK call; the callbacks work on the top record. A residual that runs
!> another fit, a closure solve (numerics_nonlinear) or an integration inside
!> pushes its own record above; each thread has its own stack. `top` is the
!> same on return as on entry. Debian's libminpack keeps no writable static
!> data (only DATA constants), so MINPACK itself may run in several threads.
!>
!> The change of variables is numerics_bounded_variables; LMDER's interface
!> and its info in words numerics_lmder; the difference Jacobians and the
!> covariance the submodule numerics_least_squares_jacobians.
module numerics_least_squares
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, &
    STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL, STATUS_DOMAIN
  use numerics_lmder, only: lmder, lmder_stop
  use numerics_bounded_variables, only: KIND_FIXED, bound_kind, near_lower, near_upper, start_inside, &
    to_p, to_z
  implicit none (type, external)
  private
  public :: least_squares_problem_t, ls_residuals_i
  public :: least_squares_options_t, least_squares_result_t, solve_least_squares
  public :: is_rejectable

  type, abstract :: least_squares_problem_t
  contains
    procedure(ls_residuals_i), deferred :: residuals
    procedure :: residuals_batch => ls_residuals_batch
    procedure :: has_jacobian => ls_has_jacobian
    procedure :: jacobian => ls_jacobian
  end type least_squares_problem_t

  abstract interface
    !> r(p), size m. Leave `status` ok or set an error (see the module comment
    !> for which errors reject a step and which end the fit).
    subroutine ls_residuals_i(self, p, r, status)
      import :: least_squares_problem_t, wp, status_t
      class(least_squares_problem_t), intent(inout) :: self
      real(wp), intent(in) :: p(:)
      real(wp), intent(out) :: r(:)
      type(status_t), intent(inout) :: status
    end subroutine ls_residuals_i
  end interface

  type :: least_squares_options_t
    real(wp) :: ftol = 1e-10_wp          !< relative reduction of the sum of squares
    real(wp) :: xtol = 1e-10_wp          !< relative change of the (transformed) parameters
    real(wp) :: gtol = 1e-10_wp          !< cosine between r and the Jacobian's columns
    integer :: max_evaluations = 10000   !< residual evaluations per MINPACK call (maxfev), differences included
    real(wp) :: epsfcn = 0               !< relative error of the residuals for the difference step (0 = machine precision)
    real(wp) :: factor = 100             !< initial step bound factor
    real(wp) :: bound_tolerance = 1e-6_wp   !< relative distance at which an optimum is put on its bound
    logical :: covariance = .true.       !< the covariance at the optimum is wanted (its differences cost
                                         !< 2 evaluations per parameter); without it the Jacobian there is
                                         !< formed only for a parameter within bound_tolerance of a bound
  end type least_squares_options_t

  type :: least_squares_result_t
    real(wp) :: cost = huge(1.0_wp)           !< 0.5 sum r^2 at the optimum
    real(wp) :: residual_norm = huge(1.0_wp)  !< sqrt(sum r^2)
    integer :: evaluations = 0                !< residual evaluations, all stages, differences included
    integer :: jacobian_evaluations = 0       !< Jacobians (analytic or by differences)
    integer :: rejected_evaluations = 0       !< evaluations that failed and were rejected as steps
    character(len=:), allocatable :: last_rejection   !< the reason of the last one
    integer :: info = 0                       !< MINPACK info of the last solve
    character(len=:), allocatable :: stop_test     !< the test that ended the last solve, in one word
                                                   !< ('ftol', 'xtol', 'ftol+xtol', 'gtol', 'max_evaluations', ...)
    character(len=:), allocatable :: stop_reason   !< MINPACK's info of the last solve in words
    logical :: covariance_valid = .false.     !< false if m <= n_free or J^T J is singular
    real(wp), allocatable :: covariance(:, :) !< n x n, original parameters (huge if not valid)
    real(wp), allocatable :: standard_error(:)   !< sqrt of the covariance diagonal
    logical, allocatable :: at_bound(:)       !< held on a bound (or l == u), not estimated
  end type least_squares_result_t

  !> One fit in progress: problem, transformation, work arrays and the fit it is
  !> nested in (see the module comment). A local variable of solve_least_squares.
  type :: fit_t
    class(least_squares_problem_t), pointer :: problem => null()
    type(status_t) :: status
    integer :: m = 0
    integer :: n_free = 0
    logical :: started = .false.              !< the start point has been evaluated
    real(wp) :: largest_norm = 0              !< largest ||r|| of a successful evaluation
    real(wp) :: epsfcn = 0
    integer :: evaluations = 0                !< of this MINPACK call (differences included)
    integer :: max_evaluations = 0
    logical :: budget_spent = .false.         !< stopped because evaluations reached max_evaluations
    logical :: jacobian_ok = .false.          !< jac holds dr/dp at p (see original_jacobian)
    integer :: rejected = 0
    character(len=:), allocatable :: last_rejection
    logical :: has_last = .false.             !< last_p, last_r hold the last successful evaluation
    real(wp), allocatable :: last_p(:), last_r(:)
    integer, allocatable :: kind(:)
    integer, allocatable :: free(:)           !< parameter index of each MINPACK unknown
    real(wp), allocatable :: lower(:), upper(:)
    real(wp), allocatable :: p(:)             !< current parameters (all of them)
    real(wp), allocatable :: dpdz(:)          !< dP/dz of each parameter
    real(wp), allocatable :: jac(:, :)        !< m x n, dr/dp
    real(wp), allocatable :: points(:, :)     !< n x n_free difference points
    real(wp), allocatable :: values(:, :)     !< m x n_free their residuals
    type(status_t), allocatable :: statuses(:)
    type(fit_t), pointer :: below => null()
  end type fit_t

  !> The innermost fit in progress on this thread.
  type(fit_t), pointer :: top => null()
  !$omp threadprivate(top)

  ! Defined in the submodule numerics_least_squares_jacobians (gfortran makes
  ! a private procedure of the module local to its object file: what the
  ! submodule calls is defined there).
  interface
    !> fit%p from MINPACK's unknowns z.
    pure module subroutine set_parameters(fit, z)
      type(fit_t), intent(inout) :: fit
      real(wp), intent(in) :: z(:)
    end subroutine set_parameters

    !> r(p), refused when not finite.
    recursive module subroutine evaluate_residuals(fit, p, r, status)
      type(fit_t), intent(inout) :: fit
      real(wp), intent(in) :: p(:)
      real(wp), intent(out) :: r(:)
      type(status_t), intent(inout) :: status
    end subroutine evaluate_residuals

    !> A residual that is not finite is a solver failure.
    pure module subroutine check_finite(r, status)
      real(wp), intent(in) :: r(:)
      type(status_t), intent(inout) :: status
    end subroutine check_finite

    !> dr/dz by forward differences (numerics_least_squares_jacobians).
    module recursive subroutine difference_jacobian(fit, z, r, fjac, status)
      type(fit_t), intent(inout) :: fit
      real(wp), intent(in) :: z(:), r(:)
      real(wp), intent(out) :: fjac(:, :)
      type(status_t), intent(inout) :: status
    end subroutine difference_jacobian

    !> dr/dp at the optimum where it is needed (numerics_least_squares_jacobians).
    module recursive subroutine jacobian_at_optimum(fit, options, r, result, status)
      type(fit_t), intent(inout) :: fit
      type(least_squares_options_t), intent(in) :: options
      real(wp), intent(in) :: r(:)
      type(least_squares_result_t), intent(inout) :: result
      type(status_t), intent(out) :: status
    end subroutine jacobian_at_optimum

    !> s^2 (J^T J)^(-1) over the free parameters (numerics_least_squares_jacobians).
    module subroutine covariance(fit, m, r, result)
      type(fit_t), intent(in) :: fit
      integer, intent(in) :: m
      real(wp), intent(in) :: r(:)
      type(least_squares_result_t), intent(inout) :: result
    end subroutine covariance
  end interface

contains

  !> Default: no analytic Jacobian (differences are used).
  logical function ls_has_jacobian(self)
    class(least_squares_problem_t), intent(in) :: self
    associate (unused => self)
    end associate
    ls_has_jacobian = .false.
  end function ls_has_jacobian

  !> jac(i, j) = d r_i / d p_j; must be overridden together with has_jacobian.
  subroutine ls_jacobian(self, p, jac, status)
    class(least_squares_problem_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_p => p)
    end associate
    jac = 0
    call set_status(status, STATUS_INTERNAL, &
      'least squares: has_jacobian is true but jacobian is not overridden')
  end subroutine ls_jacobian

  !> r(:, k) = r(p(:, k)) for independent points k, each with its own status
  !> (ok on entry). The default evaluates them one after the other; a problem
  !> may override it to evaluate them in parallel, giving the same numbers.
  recursive subroutine ls_residuals_batch(self, p, r, statuses)
    class(least_squares_problem_t), intent(inout) :: self
    real(wp), intent(in) :: p(:, :)
    real(wp), intent(out) :: r(:, :)
    type(status_t), intent(inout) :: statuses(:)
    integer :: k
    do k = 1, size(p, 2)
      call self%residuals(p(:, k), r(:, k), statuses(k))
    end do
  end subroutine ls_residuals_batch

  !> Whether a failed evaluation with this status may be rejected as a step
  !> (the model cannot be run at that point) rather than end the fit.
  elemental logical function is_rejectable(status)
    type(status_t), intent(in) :: status
    is_rejectable = status%code == STATUS_DOMAIN .or. status%code == STATUS_SOLVER .or. &
                    status%code == STATUS_NOT_CONVERGED
  end function is_rejectable

  !> Minimizes 0.5 sum r(p)^2, m residuals, within lower <= p <= upper (use
  !> -huge/huge where unbounded). p: in the start (moved into the box if outside),
  !> out the optimum (or the last accepted point if status is not ok).
  recursive subroutine solve_least_squares(problem, m, p, lower, upper, options, result, status)
    class(least_squares_problem_t), intent(inout), target :: problem
    integer, intent(in) :: m
    real(wp), intent(inout) :: p(:)
    real(wp), intent(in) :: lower(:), upper(:)
    type(least_squares_options_t), intent(in) :: options
    type(least_squares_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    type(fit_t), target :: fit
    real(wp), allocatable :: r(:), gradient(:), p_before(:), r_before(:)
    logical, allocatable :: at_bound_before(:)
    integer :: n, i, pass
    logical :: snapped

    result%stop_test = 'none'
    result%stop_reason = 'the fit did not start'
    call check_input(m, p, lower, upper, options, status)
    if (.not. status%ok()) return
    n = size(p)
    fit%problem => problem
    fit%m = m
    fit%epsfcn = options%epsfcn
    fit%lower = lower
    fit%upper = upper
    fit%kind = bound_kind(lower, upper)
    allocate (fit%dpdz(n), fit%jac(m, n), r(m), gradient(n))
    fit%dpdz = 0
    ! The start goes into the box, off the bounds (dP/dz = 0 there).
    fit%p = start_inside(p, lower, upper, fit%kind)
    allocate (result%at_bound(n))
    result%at_bound = fit%kind == KIND_FIXED

    call fit_free(fit, options, r, result, status)
    if (status%ok()) call jacobian_at_optimum(fit, options, r, result, status)

    ! Put optima that sit (nearly) on a bound, with the gradient pushing outward
    ! (Kuhn-Tucker), exactly on it and fit the others again; repeated because a
    ! parameter may reach its bound only once another one is held.
    do pass = 1, n
      if (.not. status%ok() .or. .not. fit%jacobian_ok) exit
      gradient = matmul(r, fit%jac)   ! d(0.5 sum r^2)/dp
      p_before = fit%p
      r_before = r
      at_bound_before = result%at_bound
      snapped = .false.
      do i = 1, n
        if (result%at_bound(i)) cycle
        if (near_lower(fit%kind(i), fit%p(i), lower(i), options%bound_tolerance) .and. gradient(i) >= 0) then
          fit%p(i) = lower(i)
          result%at_bound(i) = .true.
        else if (near_upper(fit%kind(i), fit%p(i), upper(i), options%bound_tolerance) .and. gradient(i) <= 0) then
          fit%p(i) = upper(i)
          result%at_bound(i) = .true.
        end if
        snapped = snapped .or. result%at_bound(i)
      end do
      if (.not. snapped) exit
      call fit_free(fit, options, r, result, status)
      if (.not. status%ok()) exit
      ! Moving downhill onto a bound cannot raise the cost beyond rounding; if it
      ! did, the snap was wrong: keep the fit from before it.
      if (sum(r**2) > sum(r_before**2)*(1 + 100*epsilon(1.0_wp)) + tiny(1.0_wp)) then
        fit%p = p_before
        r = r_before
        result%at_bound = at_bound_before
        call jacobian_at_optimum(fit, options, r, result, status)
        exit
      end if
      call jacobian_at_optimum(fit, options, r, result, status)
    end do

    p = fit%p
    result%rejected_evaluations = fit%rejected
    if (allocated(fit%last_rejection)) result%last_rejection = fit%last_rejection
    if (.not. status%ok()) return
    result%cost = 0.5_wp*sum(r**2)
    result%residual_norm = sqrt(sum(r**2))
    call covariance(fit, m, r, result)
  end subroutine solve_least_squares

  subroutine check_input(m, p, lower, upper, options, status)
    integer, intent(in) :: m
    real(wp), intent(in) :: p(:), lower(:), upper(:)
    type(least_squares_options_t), intent(in) :: options
    type(status_t), intent(out) :: status
    character(len=*), parameter :: where = 'solve_least_squares: '
    if (size(p) < 1) then
      call set_status(status, STATUS_INVALID_INPUT, where//'no parameters')
    else if (size(lower) /= size(p) .or. size(upper) /= size(p)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'lower and upper need one entry per parameter')
    else if (m < 1) then
      call set_status(status, STATUS_INVALID_INPUT, where//'no residuals')
    else if (.not. all(abs(p) <= huge(p))) then
      call set_status(status, STATUS_INVALID_INPUT, where//'start p is not finite')
    else if (any(lower > upper) .or. any(lower /= lower) .or. any(upper /= upper)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'a lower bound exceeds its upper bound')
    else if (count(lower < upper) > m) then
      call set_status(status, STATUS_INVALID_INPUT, where//'more free parameters than residuals')
    else if (.not. (options%ftol >= 0 .and. options%xtol >= 0 .and. options%gtol >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'ftol, xtol and gtol must be >= 0')
    else if (options%max_evaluations < 1) then
      call set_status(status, STATUS_INVALID_INPUT, where//'max_evaluations must be >= 1')
    else if (.not. (options%factor > 0 .and. options%epsfcn >= 0 .and. options%bound_tolerance >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'factor must be > 0, epsfcn and bound_tolerance >= 0')
    end if
  end subroutine check_input

  !> Fits the parameters not at a bound (or only evaluates r if none is left).
  recursive subroutine fit_free(fit, options, r, result, status)
    type(fit_t), intent(inout), target :: fit
    type(least_squares_options_t), intent(in) :: options
    real(wp), intent(inout) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    if (all(result%at_bound)) then
      call evaluate_residuals(fit, fit%p, r, status)
      result%evaluations = result%evaluations + 1
      result%stop_test = 'bounds'
      result%stop_reason = 'every parameter held on a bound (the gradient points out of the box): nothing '// &
                           'left to fit'
    else
      call run_minpack(fit, options, r, result, status)
    end if
  end subroutine fit_free

  !> One MINPACK solve over the parameters not at a bound, from fit%p.
  !> On return fit%p and r are at MINPACK's final point.
  recursive subroutine run_minpack(fit, options, r, result, status)
    type(fit_t), intent(inout), target :: fit
    type(least_squares_options_t), intent(in) :: options
    real(wp), intent(inout) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    real(wp), allocatable :: z(:), diag(:), fjac(:, :), qtf(:), wa1(:), wa2(:), wa3(:), wa4(:)
    integer, allocatable :: ipvt(:)
    integer :: m, nf, k, info, nfev, njev

    m = fit%m
    fit%free = pack([(k, k=1, size(fit%p))], .not. result%at_bound)
    nf = size(fit%free)
    fit%n_free = nf
    allocate (z(nf), diag(nf), fjac(m, nf), qtf(nf), wa1(nf), wa2(nf), wa3(nf), wa4(m), ipvt(nf))
    if (allocated(fit%points)) deallocate (fit%points, fit%values, fit%statuses)
    allocate (fit%points(size(fit%p), nf), fit%values(m, nf), fit%statuses(nf))
    do k = 1, nf
      associate (i => fit%free(k))
        z(k) = to_z(fit%kind(i), fit%lower(i), fit%upper(i), fit%p(i))
      end associate
    end do
    diag = 1
    r = 0
    fjac = 0
    fit%status = status_t()
    fit%started = .false.
    fit%evaluations = 0
    fit%max_evaluations = options%max_evaluations
    fit%budget_spent = .false.
    fit%below => top
    top => fit
    ! mode 1: MINPACK scales the unknowns by the column norms of the Jacobian.
    ! maxfev counts LMDER's calls for residuals only; the difference points are
    ! counted here and stop the fit (iflag < 0) when the budget is spent.
    call lmder(lmder_callback, m, nf, z, r, fjac, m, options%ftol, options%xtol, options%gtol, &
               options%max_evaluations, diag, 1, options%factor, 0, info, nfev, njev, ipvt, &
               qtf, wa1, wa2, wa3, wa4)
    top => fit%below
    call set_parameters(fit, z)
    result%evaluations = result%evaluations + fit%evaluations
    result%jacobian_evaluations = result%jacobian_evaluations + njev
    if (info < 0 .and. fit%budget_spent) info = 5

    result%info = info
    if (info < 0) then   ! the callback stopped the solve
      result%stop_test = 'problem'
      if (.not. fit%status%ok()) then
        status = fit%status   ! the problem's own reason, unchanged
        result%stop_reason = 'stopped by the problem: '//status%text()
      else
        result%stop_reason = 'stopped by the callback without a status'
        call set_status(status, STATUS_INTERNAL, 'LMDER '//result%stop_reason)
      end if
    else
      call lmder_stop(info, result%stop_test, result%stop_reason, status)
    end if
    ! MINPACK's final r belongs to its final z: a rejected trial (and its
    ! stand-in residuals) never becomes the current point.
  end subroutine run_minpack

  !> iflag 1: residuals (a rejectable failure after the start becomes a rejected
  !> step, see the module comment); 2: dr/dz over the free parameters.
  recursive subroutine lmder_callback(m, n, x, fvec, fjac, ldfjac, iflag)
    integer, intent(in) :: m, n, ldfjac
    real(wp), intent(in) :: x(n)
    real(wp), intent(inout) :: fvec(m), fjac(ldfjac, n)
    integer, intent(inout) :: iflag
    type(fit_t), pointer :: fit
    type(status_t) :: status
    integer :: k

    fit => top
    if (iflag <= 0) return   ! 0: a print request (nprint = 0, never made)
    if (iflag == 1 .and. fit%evaluations >= fit%max_evaluations) then
      fit%budget_spent = .true.   ! differences count too, as in LMDIF
      iflag = -1
      return
    end if
    call set_parameters(fit, x)
    if (iflag == 1) then
      if (fit%has_last) then
        ! LMDER asks again for the point it just had when a rejected step's
        ! shrunken trust region still holds the Gauss-Newton step: same bits
        if (all(fit%p == fit%last_p)) then
          fvec = fit%last_r
          return
        end if
      end if
      call evaluate_residuals(fit, fit%p, fvec, status)
      fit%evaluations = fit%evaluations + 1
      if (status%ok()) then
        fit%largest_norm = max(fit%largest_norm, norm2(fvec))
        fit%has_last = .true.
        fit%last_p = fit%p
        fit%last_r = fvec
      else if (fit%started .and. is_rejectable(status)) then
        fit%rejected = fit%rejected + 1
        fit%last_rejection = status%text()
        fvec = 1e3_wp*max(1.0_wp, fit%largest_norm)/sqrt(real(m, wp))
        status = status_t()
      end if
      fit%started = .true.
    else if (fit%problem%has_jacobian()) then
      call fit%problem%jacobian(fit%p, fit%jac, status)
      if (status%ok()) then
        do k = 1, n
          fjac(1:m, k) = fit%jac(:, fit%free(k))*fit%dpdz(fit%free(k))
        end do
        if (.not. all(abs(fjac(1:m, 1:n)) <= huge(fjac))) &
          call set_status(status, STATUS_SOLVER, 'least squares: the Jacobian is not finite')
      end if
    else
      call difference_jacobian(fit, x, fvec, fjac(1:m, 1:n), status)
    end if
    if (.not. status%ok()) then
      fit%status = status
      iflag = -1
    end if
  end subroutine lmder_callback





end module numerics_least_squares
