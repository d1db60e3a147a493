!> Systems with known roots for test_nonlinear.
module test_nonlinear_systems
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, &
    solve_nonlinear
  implicit none (type, external)
  private
  public :: three_t, powell_t, no_root_t, nested_t

  !> x1^2 + x2^2 + x3^2 = 14, x1 x2 = 2, x3 exp(x1 - 1) = 3: root (1, 2, 3), where
!> the Jacobian [2 4 6; 2 1 0; 3 0 1] is regular (det -24).
  !> `wrong_jacobian` spoils one entry to see that check_jacobian notices.
  type, extends(nonlinear_system_t) :: three_t
    logical :: wrong_jacobian = .false.
    real(wp) :: x1_min = -huge(1.0_wp)   ! the residual refuses x1 below this
  contains
    procedure :: residual => three_residual
    procedure :: jacobian => three_jacobian
  end type three_t

  !> f1 = 10 (x2 - x1^2), f2 = 1 - x1 - s: root (1 - s, (1 - s)^2).
  type, extends(nonlinear_system_t) :: powell_t
    real(wp) :: s = 0
  contains
    procedure :: residual => powell_residual
    procedure :: jacobian => powell_jacobian
  end type powell_t

  !> f1 = x1^2 + 1, f2 = x2: no real root.
  type, extends(nonlinear_system_t) :: no_root_t
  contains
    procedure :: residual => no_root_residual
    procedure :: jacobian => no_root_jacobian
  end type no_root_t

  !> x - 1 = 0, but its residual solves Powell's system inside.
  type, extends(nonlinear_system_t) :: nested_t
    type(status_t) :: inner_status
    real(wp) :: inner_root(2) = 0
  contains
    procedure :: residual => nested_residual
    procedure :: jacobian => nested_jacobian
  end type nested_t

contains

  subroutine three_residual(self, x, f, status)
    class(three_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    f(1) = x(1)**2 + x(2)**2 + x(3)**2 - 14
    f(2) = x(1)*x(2) - 2
    f(3) = x(3)*exp(x(1) - 1) - 3
    if (x(1) < self%x1_min) call set_status(status, STATUS_DOMAIN, 'three: x1 below its domain')
  end subroutine three_residual

  subroutine three_jacobian(self, x, jac, status)
    class(three_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    jac(1, :) = 2*x
    jac(2, :) = [x(2), x(1), 0.0_wp]
    jac(3, :) = [x(3)*exp(x(1) - 1), 0.0_wp, exp(x(1) - 1)]
    if (self%wrong_jacobian) jac(2, 1) = 1.01_wp*jac(2, 1)
  end subroutine three_jacobian

  subroutine powell_residual(self, x, f, status)
    class(powell_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    f(1) = 10*(x(2) - x(1)**2)
    f(2) = 1 - x(1) - self%s
  end subroutine powell_residual

  subroutine powell_jacobian(self, x, jac, status)
    class(powell_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self)
    end associate
    jac(1, :) = [-20*x(1), 10.0_wp]
    jac(2, :) = [-1.0_wp, 0.0_wp]
  end subroutine powell_jacobian

  subroutine no_root_residual(self, x, f, status)
    class(no_root_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self)
    end associate
    f = [x(1)**2 + 1, x(2)]
  end subroutine no_root_residual

  subroutine no_root_jacobian(self, x, jac, status)
    class(no_root_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self)
    end associate
    jac = reshape([2*x(1), 0.0_wp, 0.0_wp, 1.0_wp], [2, 2])
  end subroutine no_root_jacobian

  subroutine nested_residual(self, x, f, status)
    class(nested_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    type(powell_t) :: inner
    type(nonlinear_result_t) :: result
    real(wp) :: y(2)
    associate (unused => status)
    end associate
    y = [0.5_wp, 0.5_wp]
    call solve_nonlinear(inner, y, nonlinear_options_t(), result, self%inner_status)
    self%inner_root = y
    f = x - 1
  end subroutine nested_residual

  subroutine nested_jacobian(self, x, jac, status)
    class(nested_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => status, unused_self => self, unused_x => x)
    end associate
    jac = 1
  end subroutine nested_jacobian
end module test_nonlinear_systems

program test_nonlinear
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_NOT_CONVERGED, STATUS_DOMAIN, &
    STATUS_INVALID_INPUT
  use numerics_nonlinear, only: nonlinear_options_t, nonlinear_result_t, solve_nonlinear, &
    check_jacobian
  use testing, only: check, check_close, check_close_array, finish_tests
  use test_nonlinear_systems, only: three_t, powell_t, no_root_t, nested_t
  implicit none (type, external)

  call jacobians_against_differences()
  call known_roots()
  call warm_start()
  call failures_become_statuses()
  call finish_tests('test_nonlinear')

contains

  subroutine jacobians_against_differences()
    ! Central differences with h ~ eps^(1/3) are accurate to ~eps^(2/3) ~ 4e-11
    ! times the third derivatives (O(10) here); a 1 % error in one entry is 1e-2.
    real(wp), parameter :: fd_tol = 1e-7_wp
    type(three_t) :: three
    type(powell_t) :: powell
    type(status_t) :: status
    real(wp) :: err
    real(wp), parameter :: points(3, 4) = reshape([1.0_wp, 2.0_wp, 3.0_wp, -0.7_wp, 0.3_wp, 2.2_wp, &
      2.5_wp, -1.5_wp, 0.1_wp, 0.05_wp, 4.0_wp, -3.0_wp], [3, 4])
    integer :: k

    do k = 1, size(points, 2)
      call check_jacobian(three, points(:, k), err, status)
      call check(status%ok() .and. err < fd_tol, 'three: Jacobian vs central differences')
      call check_jacobian(powell, points(1:2, k), err, status)
      call check(status%ok() .and. err < fd_tol, 'powell: Jacobian vs central differences')
    end do
    three%wrong_jacobian = .true.
    ! At (1, 2, 3) entry (2, 1) is 2 and the largest entry 6: the error shows as 2e-2/6.
    call check_jacobian(three, points(:, 1), err, status)
    call check(err > 1e-3_wp, 'check_jacobian notices a 1 % error in one entry')
  end subroutine jacobians_against_differences

  subroutine known_roots()
    ! Newton's quadratic convergence makes the last iterate far more accurate than
    ! the last step (<= xtol 1e-10 relative); the roots are O(1), so 1e-10 absolute.
    real(wp), parameter :: tol = 1e-10_wp
    type(three_t) :: three
    type(powell_t) :: powell
    type(nonlinear_result_t) :: result
    type(status_t) :: status
    real(wp) :: x3(3), x2(2)

    x3 = [1.5_wp, 1.5_wp, 2.5_wp]
    call solve_nonlinear(three, x3, nonlinear_options_t(), result, status)
    call check(status%ok(), 'three: solved: '//status%text())
    call check_close_array(x3, [1.0_wp, 2.0_wp, 3.0_wp], 0.0_wp, tol, 'three: root (1, 2, 3)')
    call check(result%residual_norm <= 1e-10_wp, 'three: residual below tolerance')
    call check(result%info == 1, 'three: HYBRJ info 1')
    call check(result%evaluations > 0 .and. result%jacobian_evaluations > 0, 'three: counts')

    ! Powell's badly scaled start (-1.2, 1): the curved valley x2 = x1^2.
    x2 = [-1.2_wp, 1.0_wp]
    call solve_nonlinear(powell, x2, nonlinear_options_t(), result, status)
    call check(status%ok(), 'powell: solved: '//status%text())
    call check_close_array(x2, [1.0_wp, 1.0_wp], 0.0_wp, tol, 'powell: root (1, 1)')
  end subroutine known_roots

  !> A continuation in s: each solve warm-started from the previous solution needs
  !> fewer evaluations than the same solve from Powell's cold start (-1.2, 1).
  subroutine warm_start()
    type(powell_t) :: powell
    type(nonlinear_result_t) :: result
    type(status_t) :: status
    real(wp) :: x_warm(2), x_cold(2)
    integer :: k, warm, cold

    warm = 0
    cold = 0
    x_warm = [1.0_wp, 1.0_wp]
    do k = 1, 10
      powell%s = 0.02_wp*k
      call solve_nonlinear(powell, x_warm, nonlinear_options_t(), result, status)
      call check(status%ok(), 'warm start solve')
      warm = warm + result%evaluations
      x_cold = [-1.2_wp, 1.0_wp]
      call solve_nonlinear(powell, x_cold, nonlinear_options_t(), result, status)
      call check(status%ok(), 'cold start solve')
      cold = cold + result%evaluations
      ! Same root both ways: (1 - s, (1 - s)^2); Newton accuracy as above.
      call check_close_array(x_warm, [1 - powell%s, (1 - powell%s)**2], 0.0_wp, 1e-10_wp, 'warm root')
      call check_close_array(x_cold, x_warm, 0.0_wp, 1e-10_wp, 'cold root = warm root')
    end do
    print '(a, i0, a, i0)', 'evaluations over 10 solves: warm ', warm, ', cold ', cold
    ! Were the start ignored, both would take the same path and count.
    call check(warm < cold, 'warm starts need fewer evaluations than cold ones')
  end subroutine warm_start

  subroutine failures_become_statuses()
    type(no_root_t) :: no_root
    type(three_t) :: three
    type(nested_t) :: nested
    type(powell_t) :: powell
    type(nonlinear_result_t) :: result
    type(status_t) :: status
    type(nonlinear_options_t) :: options
    real(wp) :: x2(2), x3(3), x1(1)

    x2 = [0.5_wp, 0.5_wp]
    call solve_nonlinear(no_root, x2, nonlinear_options_t(), result, status)
    call check(status%code == STATUS_NOT_CONVERGED, 'no root: not converged')
    call check(index(status%text(), 'HYBRJ info =') > 0, 'no root: message names HYBRJ info: ' &
      //status%text())
    call check(result%residual_norm >= 1, 'no root: residual at least 1 (x1^2 + 1)')

    options%max_evaluations = 3
    x2 = [-1.2_wp, 1.0_wp]
    call solve_nonlinear(powell, x2, options, result, status)
    call check(status%code == STATUS_NOT_CONVERGED .and. result%info == 2, &
      'max_evaluations 3: info 2, not converged: '//status%text())

    ! The residual's own status comes back unchanged.
    three%x1_min = 0.9_wp
    x3 = [0.5_wp, 1.5_wp, 2.5_wp]
    call solve_nonlinear(three, x3, nonlinear_options_t(), result, status)
    call check(status%code == STATUS_DOMAIN .and. status%text() == 'three: x1 below its domain', &
      'residual status comes back: '//status%text())

    ! A residual that solves another system inside (numerics_nonlinear keeps a
    ! stack of solves): both converge, the inner one to Powell's root (1, 1).
    x1 = [3.0_wp]
    call solve_nonlinear(nested, x1, nonlinear_options_t(), result, status)
    call check(status%ok(), 'outer solve with a nested one: '//status%text())
    call check_close(x1(1), 1.0_wp, 0.0_wp, 1e-10_wp, 'outer root of a nested solve')
    call check(nested%inner_status%ok(), 'nested solve works: '//nested%inner_status%text())
    call check_close_array(nested%inner_root, [1.0_wp, 1.0_wp], 0.0_wp, 1e-10_wp, 'nested root (1, 1)')
    x2 = [-1.2_wp, 1.0_wp]
    call solve_nonlinear(powell, x2, nonlinear_options_t(), result, status)
    call check(status%ok(), 'solve works after failures and a nested call')

    options = nonlinear_options_t(factor=-1)
    call solve_nonlinear(powell, x2, options, result, status)
    call check(status%code == STATUS_INVALID_INPUT, 'negative factor refused')
  end subroutine failures_become_statuses
end program test_nonlinear
