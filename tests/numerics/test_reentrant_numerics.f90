!> Models for test_reentrant_numerics: a fit (LMDER) whose every residual
!> integrates an ODE (CVODE) whose every right-hand side solves a nonlinear
!> equation (HYBRJ), and a fit whose residual runs such a fit inside.
module test_reentrant_models
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_SOLVER
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, &
    solve_nonlinear
  use numerics_ode, only: ode_system_t, ode_options_t, ode_integrator_t
  use numerics_least_squares, only: least_squares_problem_t, least_squares_options_t, &
    least_squares_result_t, solve_least_squares
  implicit none (type, external)
  private
  public :: cubic_t, decay_t, decay_fit_t, outer_fit_t, integrate_decay, fit_decay, n_times

  integer, parameter :: n_times = 8

  !> x^3 + x - c = 0: one real root, x(c) smooth and increasing.
  type, extends(nonlinear_system_t) :: cubic_t
    real(wp) :: c = 0
  contains
    procedure :: residual => cubic_residual
    procedure :: jacobian => cubic_jacobian
  end type cubic_t

  !> y' = -x(k y) with x the root of the cubic, solved by HYBRJ in every call.
  type, extends(ode_system_t) :: decay_t
    real(wp) :: k = 1
    real(wp) :: x = 0          !< the last root: the warm start of the next solve
    integer :: solves = 0
  contains
    procedure :: rhs => decay_rhs
  end type decay_t

  !> Residuals y(t_i; k) - data_i at t_i = 0.125 i, i = 1..8.
  type, extends(least_squares_problem_t) :: decay_fit_t
    real(wp) :: data(n_times) = 0
  contains
    procedure :: residuals => decay_fit_residuals
  end type decay_fit_t

  !> One parameter a; its residual fits k to data made with k = a^2 (a fit
  !> inside the fit) and returns k_fit - 2, so the answer is a = sqrt(2).
  type, extends(least_squares_problem_t) :: outer_fit_t
    integer :: inner_evaluations = 0
  contains
    procedure :: residuals => outer_residuals
  end type outer_fit_t

contains

  subroutine cubic_residual(self, x, f, status)
    class(cubic_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    f(1) = x(1)**3 + x(1) - self%c
  end subroutine cubic_residual

  subroutine cubic_jacobian(self, x, jac, status)
    class(cubic_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self)
    end associate
    jac(1, 1) = 3*x(1)**2 + 1
  end subroutine cubic_jacobian

  recursive subroutine decay_rhs(self, t, y, ydot, status)
    class(decay_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    type(cubic_t) :: cubic
    type(nonlinear_result_t) :: result
    real(wp) :: x(1)
    associate (unused => t)
    end associate
    cubic%c = self%k*y(1)
    x = self%x
    call solve_nonlinear(cubic, x, nonlinear_options_t(xtol=1e-13_wp, residual_tolerance=1e-12_wp), &
                         result, status)
    self%x = x(1)
    self%solves = self%solves + 1
    ydot(1) = -x(1)
  end subroutine decay_rhs

  !> y(t_i) for y(0) = 1 (rtol 1e-11).
  recursive subroutine integrate_decay(k, y_out, solves, status)
    real(wp), intent(in) :: k
    real(wp), intent(out) :: y_out(n_times)
    integer, intent(out) :: solves
    type(status_t), intent(out) :: status
    type(decay_t), target :: model
    type(ode_integrator_t) :: integrator
    real(wp) :: t, y(1)
    integer :: i
    model%k = k
    y = 1
    y_out = 0
    call integrator%start(model, 0.0_wp, y, ode_options_t(rtol=1e-11_wp, atol=1e-13_wp), status)
    do i = 1, n_times
      if (.not. status%ok()) exit
      call integrator%advance(0.125_wp*i, t, y, status)
      y_out(i) = y(1)
    end do
    solves = model%solves
  end subroutine integrate_decay

  recursive subroutine decay_fit_residuals(self, p, r, status)
    class(decay_fit_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    integer :: solves
    call integrate_decay(p(1), r, solves, status)
    r = r - self%data
  end subroutine decay_fit_residuals

  !> Fits k to y(t_i; k_true) from k_start within [0.1, 10].
  recursive subroutine fit_decay(k_true, k_start, k, evaluations, status)
    real(wp), intent(in) :: k_true, k_start
    real(wp), intent(out) :: k
    integer, intent(out) :: evaluations
    type(status_t), intent(out) :: status
    type(decay_fit_t) :: problem
    type(least_squares_result_t) :: result
    real(wp) :: p(1)
    integer :: solves
    call integrate_decay(k_true, problem%data, solves, status)
    if (.not. status%ok()) return
    p = k_start
    call solve_least_squares(problem, n_times, p, [0.1_wp], [10.0_wp], &
                             least_squares_options_t(ftol=1e-12_wp, xtol=1e-12_wp), result, status)
    k = p(1)
    evaluations = result%evaluations
  end subroutine fit_decay

  recursive subroutine outer_residuals(self, p, r, status)
    class(outer_fit_t), intent(inout) :: self
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    real(wp) :: k
    integer :: evaluations
    call fit_decay(p(1)**2, 1.0_wp, k, evaluations, status)
    self%inner_evaluations = self%inner_evaluations + evaluations
    r(1) = k - 2
    if (status%ok() .and. .not. abs(r(1)) < huge(1.0_wp)) &
      call set_status(status, STATUS_SOLVER, 'outer: inner fit gave no number')
  end subroutine outer_residuals
end module test_reentrant_models

!> Re-entrant and thread-safe numerics: HYBRJ inside CVODE inside LMDER, a fit
!> inside a fit, and all of it in several OpenMP threads at once, with the
!> same bits as one after the other.
program test_reentrant_numerics
  use omp_lib, only: omp_get_thread_num
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_least_squares, only: least_squares_options_t, least_squares_result_t, &
    solve_least_squares
  use testing, only: check, check_close, finish_tests
  use test_reentrant_models, only: outer_fit_t, fit_decay, integrate_decay, n_times
  implicit none (type, external)

  integer, parameter :: n_cases = 6
  real(wp) :: k_true(n_cases), k_serial(n_cases), k_threads(n_cases)
  integer :: evals_serial(n_cases), evals_threads(n_cases), thread_of(n_cases), i
  type(status_t) :: status_serial(n_cases), status_threads(n_cases)
  logical :: all_ok

  k_true = [0.3_wp, 0.8_wp, 1.5_wp, 2.5_wp, 4.0_wp, 6.0_wp]
  call nested_solve_counts()

  ! Each fit starts 50 % above its answer: LMDER -> CVODE -> HYBRJ in every residual.
  do i = 1, n_cases
    call fit_decay(k_true(i), 1.5_wp*k_true(i), k_serial(i), evals_serial(i), status_serial(i))
  end do
  !$omp parallel do num_threads(2) schedule(static, 1)
  do i = 1, n_cases
    thread_of(i) = omp_get_thread_num()
    call fit_decay(k_true(i), 1.5_wp*k_true(i), k_threads(i), evals_threads(i), status_threads(i))
  end do
  !$omp end parallel do
  all_ok = .true.
  do i = 1, n_cases
    all_ok = all_ok .and. status_serial(i)%ok() .and. status_threads(i)%ok()
    ! noise-free data from the same code: ftol/xtol 1e-12 give k to ~1e-10
    call check_close(k_serial(i), k_true(i), 1e-9_wp, 0.0_wp, 'nested fit recovers k (serial)')
  end do
  call check(all_ok, 'every fit ok, serial and in threads')
  call check(all(k_threads == k_serial), 'fits in 2 threads give the same bits as serial ones')
  call check(all(evals_threads == evals_serial), 'and take the same evaluations')
  call check(count(thread_of == 1) > 0, 'the second thread took part')

  call fit_in_a_fit()
  call finish_tests('test_reentrant_numerics')

contains

  !> The ODE's every right-hand side is a HYBRJ solve.
  subroutine nested_solve_counts()
    real(wp) :: y(n_times)
    integer :: solves
    type(status_t) :: status
    call integrate_decay(1.0_wp, y, solves, status)
    call check(status%ok() .and. solves > n_times, 'HYBRJ inside CVODE: '//status%text())
    call check(all(y > 0 .and. y < 1), 'decay stays in (0, 1)')
  end subroutine nested_solve_counts

  !> LMDER whose residual runs LMDER (-> CVODE -> HYBRJ): a = sqrt(2); the
  !> same in two threads at once.
  subroutine fit_in_a_fit()
    real(wp) :: a(2)
    type(status_t) :: status(2)
    integer :: j
    !$omp parallel do num_threads(2)
    do j = 1, 2
      call outer(a(j), status(j))
    end do
    !$omp end parallel do
    call check(status(1)%ok() .and. status(2)%ok(), 'fit in a fit: '//status(1)%text())
    ! inner k to ~1e-10 (see above), the outer residual k - 2 to its ftol:
    ! a = sqrt(k) is known to ~1e-9
    call check_close(a(1), sqrt(2.0_wp), 1e-8_wp, 0.0_wp, 'fit in a fit: a = sqrt(2)')
    call check(a(1) == a(2), 'fit in a fit: same bits in two threads')
  end subroutine fit_in_a_fit

  subroutine outer(a, status)
    real(wp), intent(out) :: a
    type(status_t), intent(out) :: status
    type(outer_fit_t) :: problem
    type(least_squares_result_t) :: result
    real(wp) :: p(1)
    p = 1.2_wp
    call solve_least_squares(problem, 1, p, [0.5_wp], [3.0_wp], &
                             least_squares_options_t(ftol=1e-10_wp, xtol=1e-10_wp), result, status)
    a = p(1)
    if (status%ok() .and. problem%inner_evaluations <= 0) status%code = 6
  end subroutine outer
end program test_reentrant_numerics
