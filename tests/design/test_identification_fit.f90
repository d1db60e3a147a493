!> The shared identification (design_identification) through a throwaway
!> identification written in this test only, as docs/DESIGN.md "How to add an
!> identification" says: a line y = p1 + p2 x "measured" at places (one
!> position group over the first places, one speed group over the others).
!> Its least squares is linear, so the fit's figures have closed forms:
!> - the estimates are those of the weighted normal equations;
!> - the correlation of p1 and p2 is -B/sqrt(A C) with A = sum c_i,
!>   B = sum c_i x_i, C = sum c_i x_i^2 (c_i the group's factor);
!> - cost = position part + speed part = 1/2 sum r^2 = residual_norm^2/2.
!> The run at the optimum is the fit's own (no run more than the solver's).
!> A model that fails beyond p2 = 0.5 (its minimum at p2 = 1 out of reach)
!> makes the fit end on rejected steps: it says it stopped early. A model that
!> fails at the start ends the fit with the identification's name.
module identification_fit_line
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use design_cost, only: cost_group_t, new_cost_group, position_factor, speed_factor
  use design_identification, only: identification_sample_t, identification_problem_t
  implicit none (type, external)
  private
  public :: line_sample_t, line_problem_t, runs

  integer :: runs = 0   !< the model's runs (the test is serial)

  type, extends(identification_sample_t) :: line_sample_t
    real(wp), allocatable :: y(:)
  end type line_sample_t

  type, extends(identification_problem_t) :: line_problem_t
    real(wp), allocatable :: x(:), measured(:)
    integer :: n_position = 0            !< the first places are positions, the others speeds
    real(wp) :: weight = 0.5_wp
    real(wp) :: fails_beyond = huge(1.0_wp)   !< the model fails where p2 exceeds it
  contains
    procedure :: simulate => line_simulate
    procedure :: cost_groups => line_cost_groups
  end type line_problem_t

contains

  subroutine line_simulate(self, p, sample, status)
    class(line_problem_t), intent(in) :: self
    real(wp), intent(in) :: p(:)
    class(identification_sample_t), allocatable, intent(out) :: sample
    type(status_t), intent(out) :: status
    runs = runs + 1
    if (p(2) > self%fails_beyond) then
      call set_status(status, STATUS_DOMAIN, 'the line fails beyond its slope bound')
      return
    end if
    allocate (sample, source=line_sample_t(y=p(1) + p(2)*self%x))
  end subroutine line_simulate

  subroutine line_cost_groups(self, sample, groups)
    class(line_problem_t), intent(in) :: self
    class(identification_sample_t), intent(in) :: sample
    type(cost_group_t), allocatable, intent(out) :: groups(:)
    integer :: n
    n = self%n_position
    allocate (groups(2))
    select type (sample)
    type is (line_sample_t)
      groups(1) = new_cost_group('position', 'rad', position_factor(self%weight, n), &
                                 sample%y(:n) - self%measured(:n))
      groups(2) = new_cost_group('speed', 'm s-1', speed_factor(self%weight, 1.0_wp, size(self%x) - n), &
                                 sample%y(n + 1:) - self%measured(n + 1:))
    end select
  end subroutine line_cost_groups
end module identification_fit_line

program test_identification_fit
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_least_squares, only: least_squares_result_t
  use design_cost, only: cost_group_t, position_factor, speed_factor
  use design_identification, only: identification_fit_t, identification_sample_t, fit_identification, &
    identification_solver
  use identification_fit_line, only: line_sample_t, line_problem_t, runs
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  integer, parameter :: n = 12, n_position = 8
  real(wp), parameter :: wiggle(n) = [0.02_wp, -0.01_wp, 0.015_wp, -0.02_wp, 0.005_wp, 0.01_wp, -0.015_wp, &
                                      0.0_wp, 0.01_wp, -0.005_wp, 0.02_wp, -0.01_wp]

  call closed_forms()
  call failing_model()
  call finish_tests('test_identification_fit')

contains

  function line_problem() result(problem)
    type(line_problem_t) :: problem
    integer :: i
    problem%x = [(0.5_wp*i, i=1, n)]
    problem%measured = 0.3_wp + 1.0_wp*problem%x + wiggle
    problem%n_position = n_position
    problem%weight = 0.3_wp
  end function line_problem

  !> The line fitted from p within [-10, 10]^2, its model failing where
  !> the slope exceeds `fails_beyond` if given.
  subroutine fit_line(p, fit, sample, groups, status, fails_beyond)
    real(wp), intent(inout) :: p(2)
    type(identification_fit_t), intent(out) :: fit
    class(identification_sample_t), allocatable, intent(out) :: sample
    type(cost_group_t), allocatable, intent(out) :: groups(:)
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: fails_beyond
    type(line_problem_t) :: problem
    type(least_squares_result_t) :: result
    problem = line_problem()
    if (present(fails_beyond)) problem%fails_beyond = fails_beyond
    call fit_identification('line', problem, n, p, [-10.0_wp, -10.0_wp], [10.0_wp, 10.0_wp], identification_solver, &
                            fit, result, sample, groups, status)
  end subroutine fit_line

  subroutine closed_forms()
    type(line_problem_t) :: problem
    type(identification_fit_t) :: fit
    class(identification_sample_t), allocatable :: sample
    type(cost_group_t), allocatable :: groups(:)
    type(status_t) :: status
    real(wp) :: p(2), c(n), a, b, cc, d, e, expected(2), r(n)
    problem = line_problem()
    ! the weighted normal equations [a b; b cc] p = [d; e]
    c(:n_position) = position_factor(problem%weight, n_position)
    c(n_position + 1:) = speed_factor(problem%weight, 1.0_wp, n - n_position)
    a = sum(c)
    b = sum(c*problem%x)
    cc = sum(c*problem%x**2)
    d = sum(c*problem%measured)
    e = sum(c*problem%x*problem%measured)
    expected = [cc*d - b*e, a*e - b*d]/(a*cc - b**2)
    p = [0.0_wp, 0.0_wp]
    runs = 0
    call fit_line(p, fit, sample, groups, status)
    call check(status%ok(), 'line fit: '//status%text())
    if (.not. status%ok()) return
    call check_close(p(1), expected(1), 1e-9_wp, 1e-12_wp, 'line: intercept of the normal equations')
    call check_close(p(2), expected(2), 1e-9_wp, 1e-12_wp, 'line: slope of the normal equations')
    call check(fit%covariance_valid, 'line: covariance')
    call check_close(fit%correlation(1, 2), -b/sqrt(a*cc), 1e-6_wp, 0.0_wp, 'line: correlation -B/sqrt(AC)')
    call check(fit%correlation(1, 2) == fit%correlation(2, 1), 'line: correlation symmetric')
    call check_close(fit%correlation(1, 1), 1.0_wp, 1e-12_wp, 0.0_wp, 'line: correlation 1 on the diagonal')
    r = sqrt(c)*(p(1) + p(2)*problem%x - problem%measured)
    call check_close(fit%cost, 0.5_wp*sum(r**2), 1e-12_wp, 0.0_wp, 'line: cost 1/2 sum r^2')
    call check(fit%cost == fit%position_part + fit%speed_part, 'line: cost = position part + speed part')
    call check_close(fit%position_part, 0.5_wp*sum(r(:n_position)**2), 1e-12_wp, 0.0_wp, 'line: position part')
    call check_close(fit%residual_norm, sqrt(2*fit%cost), 1e-9_wp, 0.0_wp, 'line: residual norm')
    call check_close(fit%rmse_speed, sqrt(sum((p(1) + p(2)*problem%x(n_position + 1:) - &
                     problem%measured(n_position + 1:))**2)/(n - n_position)), 1e-12_wp, 0.0_wp, 'line: RMSE speed')
    call check(fit%evaluations == runs, 'line: the run at the optimum is the fit''s own (evaluations = runs)')
    call check(fit%rejected == 0 .and. .not. fit%stopped_early, 'line: no rejected step, not stopped early')
    call check(allocated(fit%stop_test), 'line: the stop named')
    select type (sample)
    type is (line_sample_t)
      call check(all(sample%y == p(1) + p(2)*problem%x), 'line: the sample is the run at the optimum')
    class default
      call check(.false., 'line: the sample is the line''s')
    end select
    call check(size(groups) == 2, 'line: the groups at the optimum')
  end subroutine closed_forms

  !> The model failing beyond p2 = 0.5: from (0, 0) the fit ends on
  !> rejected steps (it stopped early); from (0, 1), beyond, it fails at the
  !> start.
  subroutine failing_model()
    type(identification_fit_t) :: fit
    class(identification_sample_t), allocatable :: sample
    type(cost_group_t), allocatable :: groups(:)
    type(status_t) :: status
    real(wp) :: p(2)
    p = [0.0_wp, 0.0_wp]
    call fit_line(p, fit, sample, groups, status, fails_beyond=0.5_wp)
    call check(status%ok(), 'failing line: the fit stands at its last accepted point: '//status%text())
    call check(p(2) <= 0.5_wp, 'failing line: the slope within the model''s reach')
    call check(fit%rejected > 0, 'failing line: rejected steps counted')
    call check(fit%stopped_early .eqv. (fit%info == 2), 'failing line: stopped early exactly when the xtol '// &
               'test ended it after rejections (info 2)')
    call check(fit%stopped_early, 'failing line: it stopped early (info '//char(48 + fit%info)//')')
    p = [0.0_wp, 1.0_wp]
    call fit_line(p, fit, sample, groups, status, fails_beyond=0.5_wp)
    call check(.not. status%ok(), 'a model failing at the start ends the fit')
    call check(index(status%text(), 'line') > 0 .and. index(status%text(), 'slope bound') > 0, &
               'the failure named by the identification and the model: '//status%text())
    call check(.not. allocated(sample), 'no sample after a failed fit')
  end subroutine failing_model
end program test_identification_fit
