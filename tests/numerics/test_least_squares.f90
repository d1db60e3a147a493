!> Least-squares problems with known minima for test_least_squares.
module test_least_squares_problems
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_least_squares, only: least_squares_problem_t
  implicit none (type, external)
  private
  public :: rosenbrock_t, exp_fit_t, line_t, no_jacobian_t

  !> Rosenbrock as residuals: r = [10 (p2 - p1^2), 1 - p1], minimum 0 at (1, 1).
  !> Records the range of p1 it was evaluated at, to see that bounds hold.
  type, extends(least_squares_problem_t) :: rosenbrock_t
    logical :: analytic = .false.
    real(wp) :: p1_min = huge(1.0_wp), p1_max = -huge(1.0_wp)
    real(wp) :: p1_domain = huge(1.0_wp)   ! residuals refuse p1 beyond this
  contains
    procedure :: residuals => rosenbrock_residuals
    procedure :: has_jacobian => rosenbrock_has_jacobian
    procedure :: jacobian => rosenbrock_jacobian
  end type rosenbrock_t

  !> y = A exp(-k t) + c on t = 0, 0.25, ..., 5 with exact data A = 2, k = 0.7, c = 0.3.
  type, extends(least_squares_problem_t) :: exp_fit_t
    logical :: analytic = .false.
    real(wp) :: t(21), y(21)
  contains
    procedure :: residuals => exp_residuals
    procedure :: has_jacobian => exp_has_jacobian
    procedure :: jacobian => exp_jacobian
  end type exp_fit_t

  !> y = a + b x with deterministic noise 0.01 sin(3.7 i) on x = 0, 0.1, ..., 1.9.
  type, extends(least_squares_problem_t) :: line_t
    logical :: analytic = .false.
    real(wp) :: x(20), y(20)
  contains
    procedure :: residuals => line_residuals
    procedure :: has_jacobian => line_has_jacobian
    procedure :: jacobian => line_jacobian
  end type line_t

  !> Claims a Jacobian but does not provide one.
  type, extends(least_squares_problem_t) :: no_jacobian_t
  contains
    procedure :: residuals => no_jacobian_residuals
    procedure :: has_jacobian => no_jacobian_has_jacobian
  end type no_jacobian_t

contains

  subroutine rosenbrock_residuals(self, p, r, status)
    class(rosenbrock_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    self%p1_min = min(self%p1_min, p(1))
    self%p1_max = max(self%p1_max, p(1))
    r = [10*(p(2) - p(1)**2), 1 - p(1)]
    if (p(1) > self%p1_domain) call set_status(status, STATUS_DOMAIN, 'rosenbrock: p1 beyond its domain')
  end subroutine rosenbrock_residuals

  logical function rosenbrock_has_jacobian(self)
    class(rosenbrock_t), intent(in) :: self
    rosenbrock_has_jacobian = self%analytic
  end function rosenbrock_has_jacobian

  subroutine rosenbrock_jacobian(self, p, jac, status)
    class(rosenbrock_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self)
    end associate
    jac(1, :) = [-20*p(1), 10.0_wp]
    jac(2, :) = [-1.0_wp, 0.0_wp]
  end subroutine rosenbrock_jacobian

  subroutine exp_residuals(self, p, r, status)
    class(exp_fit_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    r = p(1)*exp(-p(2)*self%t) + p(3) - self%y
  end subroutine exp_residuals

  logical function exp_has_jacobian(self)
    class(exp_fit_t), intent(in) :: self
    exp_has_jacobian = self%analytic
  end function exp_has_jacobian

  subroutine exp_jacobian(self, p, jac, status)
    class(exp_fit_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    jac(:, 1) = exp(-p(2)*self%t)
    jac(:, 2) = -p(1)*self%t*exp(-p(2)*self%t)
    jac(:, 3) = 1
  end subroutine exp_jacobian

  subroutine line_residuals(self, p, r, status)
    class(line_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    r = p(1) + p(2)*self%x - self%y
  end subroutine line_residuals

  logical function line_has_jacobian(self)
    class(line_t), intent(in) :: self
    line_has_jacobian = self%analytic
  end function line_has_jacobian

  subroutine line_jacobian(self, p, jac, status)
    class(line_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_p => p)
    end associate
    jac(:, 1) = 1
    jac(:, 2) = self%x
  end subroutine line_jacobian

  subroutine no_jacobian_residuals(self, p, r, status)
    class(no_jacobian_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self)
    end associate
    r = [p(1) - 1, p(1) + 1]
  end subroutine no_jacobian_residuals

  logical function no_jacobian_has_jacobian(self)
    class(no_jacobian_t), intent(in) :: self
    associate (unused => self)
    end associate
    no_jacobian_has_jacobian = .true.
  end function no_jacobian_has_jacobian
end module test_least_squares_problems

program test_least_squares
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_NOT_CONVERGED, STATUS_DOMAIN, STATUS_INVALID_INPUT, &
    STATUS_INTERNAL
  use numerics_least_squares, only: least_squares_options_t, least_squares_result_t, &
    solve_least_squares
  use testing, only: check, check_close, check_close_array, finish_tests
  use test_least_squares_problems, only: rosenbrock_t, exp_fit_t, line_t, no_jacobian_t
  implicit none (type, external)

  real(wp), parameter :: big = huge(1.0_wp)
  logical :: analytic
  integer :: k

  call test_jacobians()
  do k = 1, 2
    analytic = k == 2
    call rosenbrock_unbounded()
    call rosenbrock_on_a_bound()
    call exponential_fit()
    call exponential_fit_on_a_bound()
    call line_covariance()
  end do
  call failures()
  call finish_tests('test_least_squares')

contains

  function name() result(text)
    character(len=:), allocatable :: text
    text = merge('analytic Jacobian: ', 'differences:       ', analytic)
  end function name

  function exp_problem() result(problem)
    type(exp_fit_t) :: problem
    integer :: i
    problem%t = [(0.25_wp*i, i=0, 20)]
    problem%y = 2*exp(-0.7_wp*problem%t) + 0.3_wp
    problem%analytic = analytic
  end function exp_problem

  !> The test problems' analytic Jacobians against central differences.
  subroutine test_jacobians()
    ! Central differences, h = 1e-5: truncation h^2 f''' ~ 1e-10 times O(10)
    ! third derivatives, rounding eps/h ~ 1e-11.
    real(wp), parameter :: tol = 1e-8_wp, h = 1e-5_wp
    type(exp_fit_t) :: fit
    type(rosenbrock_t) :: rosen
    type(status_t) :: status
    real(wp) :: jac(21, 3), rp(21), rm(21), p(3), jr(2, 2), rrp(2), rrm(2)
    real(wp), parameter :: points(3, 3) = reshape([2.0_wp, 0.7_wp, 0.3_wp, -1.3_wp, 0.05_wp, 4.0_wp, &
      0.4_wp, 2.5_wp, -0.9_wp], [3, 3])
    integer :: i, j

    analytic = .true.
    fit = exp_problem()
    do i = 1, size(points, 2)
      call fit%jacobian(points(:, i), jac, status)
      call rosen%jacobian(points(1:2, i), jr, status)
      do j = 1, 3
        p = points(:, i)
        p(j) = p(j) + h
        call fit%residuals(p, rp, status)
        if (j < 3) call rosen%residuals(p(1:2), rrp, status)
        p(j) = p(j) - 2*h
        call fit%residuals(p, rm, status)
        call check_close_array(jac(:, j), (rp - rm)/(2*h), 0.0_wp, tol, 'exp fit Jacobian column')
        if (j < 3) then
          call rosen%residuals(p(1:2), rrm, status)
          call check_close_array(jr(:, j), (rrp - rrm)/(2*h), 0.0_wp, tol, 'rosenbrock Jacobian column')
        end if
      end do
    end do
  end subroutine test_jacobians

  subroutine rosenbrock_unbounded()
    ! Zero-residual problem: LM converges (quadratically with LMDER, nearly so with
    ! forward differences) far below the last step, which xtol = 1e-10 bounds.
    real(wp), parameter :: tol = 1e-9_wp
    type(rosenbrock_t) :: problem
    type(least_squares_result_t) :: result
    type(status_t) :: status
    real(wp) :: p(2)

    problem%analytic = analytic
    p = [-1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-big, -big], [big, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok(), name()//'rosenbrock: '//status%text())
    call check_close_array(p, [1.0_wp, 1.0_wp], 0.0_wp, tol, name()//'rosenbrock minimum (1, 1)')
    call check(result%cost < 1e-20_wp, name()//'rosenbrock cost 0')
    call check(.not. any(result%at_bound), name()//'rosenbrock: nothing at a bound')
    call check(result%evaluations > 0, name()//'evaluations counted')
    if (analytic) call check(result%jacobian_evaluations > 0, 'LMDER: Jacobian evaluations counted')
  end subroutine rosenbrock_unbounded

  !> With p1 <= 0.5 the minimum is p1 = 0.5, p2 = 0.25 (r1 = 0), cost 0.125;
  !> with p1 >= 1.5 it is p1 = 1.5, p2 = 2.25. Bounds must hold in every
  !> evaluation and the optimum must lie exactly on the bound.
  subroutine rosenbrock_on_a_bound()
    ! p2 follows from r1 = 0 at the fixed p1: only LM's own accuracy, as above.
    real(wp), parameter :: tol = 1e-9_wp
    type(rosenbrock_t) :: problem
    type(least_squares_result_t) :: result
    type(status_t) :: status
    real(wp) :: p(2)

    problem%analytic = analytic
    p = [-1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-big, -big], [0.5_wp, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok(), name()//'upper bound: '//status%text())
    call check(p(1) == 0.5_wp, name()//'upper bound: p1 exactly on the bound')
    call check_close(p(2), 0.25_wp, 0.0_wp, tol, name()//'upper bound: p2')
    call check_close(result%cost, 0.125_wp, 1e-12_wp, 0.0_wp, name()//'upper bound: cost')
    call check(result%at_bound(1) .and. .not. result%at_bound(2), name()//'upper bound: at_bound')
    call check(problem%p1_max <= 0.5_wp, name()//'upper bound held in every evaluation')

    problem%p1_max = -big
    problem%p1_min = big
    p = [-1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-2.0_wp, -big], [0.5_wp, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok() .and. p(1) == 0.5_wp, name()//'two-sided bounds: p1 exactly on the upper')
    call check_close(p(2), 0.25_wp, 0.0_wp, tol, name()//'two-sided bounds: p2')
    call check(problem%p1_max <= 0.5_wp .and. problem%p1_min >= -2, &
      name()//'two-sided bounds held in every evaluation')

    problem%p1_min = big
    p = [3.0_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [1.5_wp, -big], [big, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok() .and. p(1) == 1.5_wp, name()//'lower bound: p1 exactly on the bound')
    call check_close(p(2), 2.25_wp, 0.0_wp, tol, name()//'lower bound: p2')
    call check(problem%p1_min >= 1.5_wp, name()//'lower bound held in every evaluation')
    call check(result%covariance(1, 1) == 0 .and. result%covariance(1, 2) == 0, &
      name()//'lower bound: zero covariance row of the parameter at its bound')
  end subroutine rosenbrock_on_a_bound

  !> Exact data from (A, k, c) = (2, 0.7, 0.3), A in [0, 10], k >= 0, c free.
  subroutine exponential_fit()
    ! Zero-residual fit, LM accuracy as for Rosenbrock; parameters O(1).
    real(wp), parameter :: tol = 1e-9_wp
    type(exp_fit_t) :: problem
    type(least_squares_result_t) :: result
    type(status_t) :: status
    real(wp) :: p(3)

    problem = exp_problem()
    p = [1.0_wp, 2.0_wp, 0.0_wp]
    call solve_least_squares(problem, 21, p, [0.0_wp, 0.0_wp, -big], [10.0_wp, big, big], &
                             least_squares_options_t(), result, status)
    call check(status%ok(), name()//'exponential fit: '//status%text())
    call check_close_array(p, [2.0_wp, 0.7_wp, 0.3_wp], 0.0_wp, tol, name()//'exponential fit parameters')
    call check(result%covariance_valid, name()//'exponential fit: covariance computed')
  end subroutine exponential_fit

  !> Same data with k in [0.8, 2]: k ends exactly on 0.8, and A, c are the linear
  !> least-squares fit of A exp(-0.8 t) + c to the data (closed form, 2 x 2).
  subroutine exponential_fit_on_a_bound()
    ! A and c solve a well-conditioned 2 x 2 system; LM stops within ~xtol.
    real(wp), parameter :: tol = 1e-9_wp
    type(exp_fit_t) :: problem
    type(least_squares_result_t) :: result
    type(status_t) :: status
    real(wp) :: p(3), e(21), s_ee, s_e, s_ey, s_y, det, a_ref, c_ref, s2, cov(2, 2)

    problem = exp_problem()
    p = [1.0_wp, 1.5_wp, 0.0_wp]
    call solve_least_squares(problem, 21, p, [0.0_wp, 0.8_wp, -big], [10.0_wp, 2.0_wp, big], &
                             least_squares_options_t(), result, status)
    call check(status%ok(), name()//'exponential fit on a bound: '//status%text())
    call check(p(2) == 0.8_wp, name()//'k exactly on its lower bound 0.8')
    e = exp(-0.8_wp*problem%t)
    s_ee = sum(e**2)
    s_e = sum(e)
    s_ey = sum(e*problem%y)
    s_y = sum(problem%y)
    det = s_ee*21 - s_e**2
    a_ref = (21*s_ey - s_e*s_y)/det
    c_ref = (s_ee*s_y - s_e*s_ey)/det
    call check_close(p(1), a_ref, 0.0_wp, tol, name()//'A at the bounded optimum')
    call check_close(p(3), c_ref, 0.0_wp, tol, name()//'c at the bounded optimum')
    call check(result%at_bound(2) .and. .not. result%at_bound(1) .and. .not. result%at_bound(3), &
      name()//'at_bound marks k only')
    call check(all(result%covariance(2, :) == 0) .and. all(result%covariance(:, 2) == 0), &
      name()//'zero covariance row and column for k')
    call check(result%standard_error(2) == 0 .and. result%standard_error(1) > 0, &
      name()//'standard errors: zero for k, positive for A')
    ! With k held, the model is linear in (A, c): covariance s^2 (X^T X)^(-1) with
    ! X = [exp(-0.8 t), 1] and s^2 = sum r^2 / (21 - 2). Relative 1e-9: the
    ! central-difference Jacobian (LMDIF) is accurate to ~eps^(2/3) ~ 4e-11
    ! relative, and s^2 is stationary at the optimum (known to ~1e-10).
    s2 = sum((a_ref*e + c_ref - problem%y)**2)/(21 - 2)
    cov = s2/det*reshape([21.0_wp, -s_e, -s_e, s_ee], [2, 2])
    call check_close_array([result%covariance(1, 1), result%covariance(3, 1), result%covariance(1, 3), &
      result%covariance(3, 3)], [cov(1, 1), cov(2, 1), cov(1, 2), cov(2, 2)], 1e-9_wp, 0.0_wp, &
      name()//'covariance of (A, c) with k held at its bound')
  end subroutine exponential_fit_on_a_bound

  !> y = a + b x: the fit and its covariance s^2 (X^T X)^(-1), s^2 = sum r^2/(m - 2),
  !> against the closed forms of linear regression.
  subroutine line_covariance()
    ! The fit is linear, so the optimum is found to rounding (~1e-14) after one
    ! Gauss-Newton step; differences of a linear model are exact up to rounding
    ! eps/h ~ 1e-11 relative; 1e-9 leaves room for both.
    real(wp), parameter :: rtol = 1e-9_wp
    type(line_t) :: problem
    type(least_squares_result_t) :: result
    type(status_t) :: status
    real(wp) :: p(2), sx, sxx, sy, sxy, det, a, b, s2, cov(2, 2)
    integer :: i, m

    m = size(problem%x)
    problem%analytic = analytic
    problem%x = [(0.1_wp*i, i=0, m - 1)]
    problem%y = 0.5_wp + 1.5_wp*problem%x + 0.01_wp*sin(3.7_wp*[(i, i=0, m - 1)])
    p = [0.0_wp, 0.0_wp]
    call solve_least_squares(problem, m, p, [-big, -big], [big, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok(), name()//'line fit: '//status%text())
    sx = sum(problem%x)
    sxx = sum(problem%x**2)
    sy = sum(problem%y)
    sxy = sum(problem%x*problem%y)
    det = m*sxx - sx**2
    b = (m*sxy - sx*sy)/det
    a = (sy - b*sx)/m
    call check_close_array(p, [a, b], 1e-10_wp, 1e-12_wp, name()//'line fit vs closed form')
    s2 = sum((a + b*problem%x - problem%y)**2)/(m - 2)
    cov = s2/det*reshape([sxx, -sx, -sx, real(m, wp)], [2, 2])
    call check(result%covariance_valid, name()//'line covariance valid')
    do i = 1, 2
      call check_close_array(result%covariance(:, i), cov(:, i), rtol, 0.0_wp, &
        name()//'line covariance vs s^2 (X^T X)^-1')
      call check_close(result%standard_error(i), sqrt(cov(i, i)), rtol, 0.0_wp, &
        name()//'line standard error')
    end do
    call check_close(result%cost, 0.5_wp*s2*(m - 2), 1e-12_wp, 0.0_wp, name()//'line cost')
  end subroutine line_covariance

  subroutine failures()
    type(rosenbrock_t) :: problem
    type(no_jacobian_t) :: liar
    type(least_squares_result_t) :: result
    type(status_t) :: status
    type(least_squares_options_t) :: options
    real(wp) :: p(2), q(1)

    options%max_evaluations = 3
    p = [-1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-big, -big], [big, big], options, result, status)
    call check(status%code == STATUS_NOT_CONVERGED .and. result%info == 5, &
      'max_evaluations 3: info 5, not converged: '//status%text())
    call check(stop_said(result, 'max_evaluations', 'max_evaluations reached before convergence'), &
      'max_evaluations 3: the stop said in words (evaluation budget)')

    ! A model that cannot be run beyond p1 = 0.9: the failed trial points are
    ! rejected steps, the fit goes on and ends at the domain's edge (the
    ! constrained minimum is (0.9, 0.81), cost 0.005), where LMDER's trust
    ! region has shrunk below xtol.
    problem%p1_domain = 0.9_wp
    p = [-1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-big, -big], [big, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok(), 'failed trial points do not end the fit: '//status%text())
    call check(result%rejected_evaluations > 0, 'failed trial points counted as rejected')
    if (allocated(result%last_rejection)) then
      call check(result%last_rejection == 'rosenbrock: p1 beyond its domain', &
        'the reason of the last rejection kept: '//result%last_rejection)
    else
      call check(.false., 'the reason of the last rejection kept')
    end if
    ! The edge is reached to ~xtol (1e-10) in p1. Along the edge the fit stalls
    ! short of the constrained minimum (0.9, 0.81): each LM step there leans
    ! across the edge, is rejected, and the trust region shrinks below xtol.
    ! Rejection is a safeguard, not a constraint (use bounds for constraints),
    ! so only "at the edge, cost within 1e-5 of the edge's minimum" is claimed.
    call check(p(1) <= 0.9_wp .and. p(1) > 0.9_wp - 1e-9_wp, 'fit ends at the domain''s edge')
    call check(result%cost >= 0.005_wp .and. result%cost < 0.005_wp + 1e-5_wp, &
               'cost near the edge''s minimum 0.005')
    ! ... and says so: the step test (xtol) ended it, not a gradient test
    call check(result%info == 2 .and. stop_said(result, 'xtol', 'relative change of the parameters'), &
               'the domain edge: stopped by the xtol test (info 2), said in words')
    ! A failure at the start is not a step: the residuals' status comes back.
    p = [1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-big, -big], [big, big], least_squares_options_t(), &
                             result, status)
    call check(status%code == STATUS_DOMAIN .and. status%text() == 'rosenbrock: p1 beyond its domain', &
      'a failed start: the residuals'' status comes back unchanged: '//status%text())

    p = [0.0_wp, 0.0_wp]
    call solve_least_squares(problem, 2, p, [1.0_wp, -big], [0.0_wp, big], least_squares_options_t(), &
                             result, status)
    call check(status%code == STATUS_INVALID_INPUT, 'lower > upper refused')
    call solve_least_squares(problem, 1, p, [-big, -big], [big, big], least_squares_options_t(), &
                             result, status)
    call check(status%code == STATUS_INVALID_INPUT, 'fewer residuals than free parameters refused')

    q = [3.0_wp]
    call solve_least_squares(liar, 2, q, [-big], [big], least_squares_options_t(), result, status)
    call check(status%code == STATUS_INTERNAL, 'has_jacobian without jacobian: internal error: ' &
      //status%text())

    ! A fixed parameter (lower == upper) is kept and not estimated.
    problem%p1_domain = big
    p = [0.0_wp, 0.0_wp]
    call solve_least_squares(problem, 2, p, [0.3_wp, -big], [0.3_wp, big], least_squares_options_t(), &
                             result, status)
    call check(status%ok() .and. p(1) == 0.3_wp .and. result%at_bound(1), 'fixed parameter kept')
    call check_close(p(2), 0.09_wp, 0.0_wp, 1e-9_wp, 'fixed parameter: the other one fitted')
    p = [0.0_wp, 0.0_wp]
    call solve_least_squares(problem, 2, p, [0.3_wp, 0.1_wp], [0.3_wp, 0.1_wp], least_squares_options_t(), &
                             result, status)
    call check(status%ok() .and. all(p == [0.3_wp, 0.1_wp]) .and. all(result%at_bound), &
      'all parameters fixed: nothing to fit, ok')
    call check_close(result%cost, 0.5_wp*(0.1_wp**2 + 0.7_wp**2), 1e-14_wp, 0.0_wp, 'all fixed: cost')
    call check(stop_said(result, 'bounds', 'every parameter held on a bound'), 'all fixed: the stop said')

    ! A loose ftol ends Rosenbrock on the ftol test (info 1), said in words
    p = [-1.2_wp, 1.0_wp]
    call solve_least_squares(problem, 2, p, [-big, -big], [big, big], &
                             least_squares_options_t(ftol=0.5_wp, xtol=1e-15_wp, gtol=0.0_wp), result, status)
    call check(status%ok() .and. result%info == 1 .and. &
               stop_said(result, 'ftol', 'relative reductions of the sum of squares'), &
               'ftol 0.5: stopped by the ftol test (info 1), said in words: '//result%stop_reason)
  end subroutine failures

  !> The stop of a solve is given as its test and in words holding `words`.
  logical function stop_said(result, test, words)
    type(least_squares_result_t), intent(in) :: result
    character(len=*), intent(in) :: test, words
    stop_said = .false.
    if (.not. (allocated(result%stop_test) .and. allocated(result%stop_reason))) return
    stop_said = result%stop_test == test .and. index(result%stop_reason, words) > 0
  end function stop_said
end program test_least_squares
