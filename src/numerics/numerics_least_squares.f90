!> Bounded nonlinear least squares, min 0.5 sum r_i(p)^2 with lower <= p <= upper,
!> over MINPACK's Levenberg-Marquardt codes: LMDIF (forward-difference Jacobian)
!> or, when the problem provides one, LMDER (analytic Jacobian).
!>
!> Bounds are held exactly by a smooth change of variables p = P(z); MINPACK
!> works on the unconstrained z:
!>   lower and upper:  p = l + (u - l) (1 + sin z)/2      (clamped to [l, u] against rounding)
!>   lower only:       p = l + z^2 / (1 + sqrt(1 + z^2))  (= l + sqrt(z^2 + 1) - 1, never below l)
!>   upper only:       p = u - z^2 / (1 + sqrt(1 + z^2))
!>   neither:          p = z
!>   l == u:           p is fixed at l and not estimated.
!> Every p MINPACK ever evaluates is inside the bounds. LMDER gets the chain rule
!> dr/dz = dr/dp dP/dz. Because dP/dz = 0 on a bound, a start on a bound is moved
!> inside (by 1e-3 of the range or of max(1, |bound|)), and an optimum on a bound
!> is approached only slowly in z; therefore after the first solve every parameter
!> within bound_tolerance of a bound whose gradient points out of the box (the
!> Kuhn-Tucker sign) is put exactly on the bound and the others are fitted again.
!>
!> The covariance is s^2 (J^T J)^(-1) in the original parameters, J = dr/dp at the
!> optimum over the parameters not at a bound, s^2 = sum r^2 / (m - n_free);
!> parameters at a bound have zero rows and columns and at_bound = .true.
!>
!> MINPACK's callbacks carry no user data: the problem is reached through the
!> module variable `active` during one call of solve_least_squares (nested calls
!> are refused with STATUS_INTERNAL); not thread-safe.
module numerics_least_squares
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT, &
    STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL
  use numerics_linear_algebra, only: normal_matrix_inverse
  implicit none (type, external)
  private
  public :: least_squares_problem_t, ls_residuals_i
  public :: least_squares_options_t, least_squares_result_t, solve_least_squares

  type, abstract :: least_squares_problem_t
  contains
    procedure(ls_residuals_i), deferred :: residuals
    procedure :: has_jacobian => ls_has_jacobian
    procedure :: jacobian => ls_jacobian
  end type least_squares_problem_t

  abstract interface
    !> r(p), size m. Leave `status` ok or set an error: the fit stops and returns it.
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
    integer :: max_evaluations = 10000   !< residual evaluations per MINPACK call (maxfev)
    real(wp) :: epsfcn = 0               !< LMDIF: relative error of the residuals (0 = machine precision)
    real(wp) :: factor = 100             !< initial step bound factor
    real(wp) :: bound_tolerance = 1e-6_wp   !< relative distance at which an optimum is put on its bound
  end type least_squares_options_t

  type :: least_squares_result_t
    real(wp) :: cost = huge(1.0_wp)           !< 0.5 sum r^2 at the optimum
    real(wp) :: residual_norm = huge(1.0_wp)  !< sqrt(sum r^2)
    integer :: evaluations = 0                !< residual evaluations, all stages
    integer :: jacobian_evaluations = 0       !< analytic Jacobian evaluations
    integer :: info = 0                       !< MINPACK info of the last solve
    logical :: covariance_valid = .false.     !< false if m <= n_free or J^T J is singular
    real(wp), allocatable :: covariance(:, :) !< n x n, original parameters (huge if not valid)
    real(wp), allocatable :: standard_error(:)   !< sqrt of the covariance diagonal
    logical, allocatable :: at_bound(:)       !< held on a bound (or l == u), not estimated
  end type least_squares_result_t

  integer, parameter :: KIND_FREE = 0, KIND_LOWER = 1, KIND_UPPER = 2, KIND_BOTH = 3, &
                        KIND_FIXED = 4

  !> The fit in progress: problem, transformation and work arrays (allocated once
  !> per solve, so the callbacks allocate nothing).
  type :: ls_call_t
    class(least_squares_problem_t), pointer :: problem => null()
    type(status_t) :: status
    integer :: m = 0
    integer :: n_free = 0
    integer, allocatable :: kind(:)
    integer, allocatable :: free(:)           !< parameter index of each MINPACK unknown
    real(wp), allocatable :: lower(:), upper(:)
    real(wp), allocatable :: p(:)             !< current parameters (all of them)
    real(wp), allocatable :: dpdz(:)          !< dP/dz of each parameter
    real(wp), allocatable :: jac(:, :)        !< m x n, dr/dp
  end type ls_call_t

  type(ls_call_t), target :: active
  logical :: busy = .false.

  abstract interface
    subroutine lmdif_fcn_i(m, n, x, fvec, iflag)
      import :: wp
      integer, intent(in) :: m, n
      real(wp), intent(in) :: x(n)
      real(wp), intent(inout) :: fvec(m)
      integer, intent(inout) :: iflag
    end subroutine lmdif_fcn_i

    subroutine lmder_fcn_i(m, n, x, fvec, fjac, ldfjac, iflag)
      import :: wp
      integer, intent(in) :: m, n, ldfjac
      real(wp), intent(in) :: x(n)
      real(wp), intent(inout) :: fvec(m), fjac(ldfjac, n)
      integer, intent(inout) :: iflag
    end subroutine lmder_fcn_i
  end interface

  interface
    !> MINPACK (original Fortran 77), libminpack.
    subroutine lmdif(fcn, m, n, x, fvec, ftol, xtol, gtol, maxfev, epsfcn, diag, mode, factor, &
                     nprint, info, nfev, fjac, ldfjac, ipvt, qtf, wa1, wa2, wa3, wa4)
      import :: wp, lmdif_fcn_i
      procedure(lmdif_fcn_i) :: fcn
      integer, intent(in) :: m, n, maxfev, mode, nprint, ldfjac
      real(wp), intent(inout) :: x(n), fvec(m), diag(n), fjac(ldfjac, n)
      real(wp), intent(in) :: ftol, xtol, gtol, epsfcn, factor
      integer, intent(out) :: info, nfev, ipvt(n)
      real(wp), intent(inout) :: qtf(n), wa1(n), wa2(n), wa3(n), wa4(m)
    end subroutine lmdif

    subroutine lmder(fcn, m, n, x, fvec, fjac, ldfjac, ftol, xtol, gtol, maxfev, diag, mode, &
                     factor, nprint, info, nfev, njev, ipvt, qtf, wa1, wa2, wa3, wa4)
      import :: wp, lmder_fcn_i
      procedure(lmder_fcn_i) :: fcn
      integer, intent(in) :: m, n, ldfjac, maxfev, mode, nprint
      real(wp), intent(inout) :: x(n), fvec(m), fjac(ldfjac, n), diag(n)
      real(wp), intent(in) :: ftol, xtol, gtol, factor
      integer, intent(out) :: info, nfev, njev, ipvt(n)
      real(wp), intent(inout) :: qtf(n), wa1(n), wa2(n), wa3(n), wa4(m)
    end subroutine lmder

  end interface

contains

  !> Default: no analytic Jacobian (LMDIF differences are used).
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

  !> Minimizes 0.5 sum r(p)^2, m residuals, within lower <= p <= upper (use
  !> -huge/huge where unbounded). p: in the start (moved into the box if outside),
  !> out the optimum.
  recursive subroutine solve_least_squares(problem, m, p, lower, upper, options, result, status)
    class(least_squares_problem_t), intent(inout), target :: problem
    integer, intent(in) :: m
    real(wp), intent(inout) :: p(:)
    real(wp), intent(in) :: lower(:), upper(:)
    type(least_squares_options_t), intent(in) :: options
    type(least_squares_result_t), intent(out) :: result
    type(status_t), intent(out) :: status

    if (busy) then
      call set_status(status, STATUS_INTERNAL, 'solve_least_squares: called again from inside a' &
        //' residual or Jacobian (MINPACK has no user data)')
      return
    end if
    call check_input(m, p, lower, upper, options, status)
    if (.not. status%ok()) return
    busy = .true.
    call solve_active(problem, m, p, lower, upper, options, result, status)
    nullify (active%problem)
    busy = .false.
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

  subroutine solve_active(problem, m, p, lower, upper, options, result, status)
    class(least_squares_problem_t), intent(inout), target :: problem
    integer, intent(in) :: m
    real(wp), intent(inout) :: p(:)
    real(wp), intent(in) :: lower(:), upper(:)
    type(least_squares_options_t), intent(in) :: options
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    real(wp), allocatable :: r(:), gradient(:), p_before(:), r_before(:)
    logical, allocatable :: at_bound_before(:)
    integer :: n, i, pass
    logical :: snapped

    n = size(p)
    active = ls_call_t()   ! frees what the previous fit left
    active%problem => problem
    active%m = m
    active%lower = lower
    active%upper = upper
    active%kind = bound_kind(lower, upper)
    allocate (active%dpdz(n), active%jac(m, n), r(m), gradient(n))
    active%dpdz = 0
    ! The start goes into the box, off the bounds (dP/dz = 0 there).
    active%p = start_inside(p, lower, upper, active%kind)
    allocate (result%at_bound(n))
    result%at_bound = active%kind == KIND_FIXED

    call fit_free(options, r, result, status)
    if (status%ok()) call original_jacobian(options, r, result, status)

    ! Put optima that sit (nearly) on a bound, with the gradient pushing outward
    ! (Kuhn-Tucker), exactly on it and fit the others again; repeated because a
    ! parameter may reach its bound only once another one is held.
    do pass = 1, n
      if (.not. status%ok()) exit
      gradient = matmul(r, active%jac)   ! d(0.5 sum r^2)/dp
      p_before = active%p
      r_before = r
      at_bound_before = result%at_bound
      snapped = .false.
      do i = 1, n
        if (result%at_bound(i)) cycle
        if (has_lower(active%kind(i))) then
          if (active%p(i) - lower(i) <= options%bound_tolerance*max(1.0_wp, abs(lower(i))) &
              .and. gradient(i) >= 0) then
            active%p(i) = lower(i)
            result%at_bound(i) = .true.
          end if
        end if
        if (has_upper(active%kind(i)) .and. .not. result%at_bound(i)) then
          if (upper(i) - active%p(i) <= options%bound_tolerance*max(1.0_wp, abs(upper(i))) &
              .and. gradient(i) <= 0) then
            active%p(i) = upper(i)
            result%at_bound(i) = .true.
          end if
        end if
        snapped = snapped .or. result%at_bound(i)
      end do
      if (.not. snapped) exit
      call fit_free(options, r, result, status)
      if (.not. status%ok()) exit
      ! Moving downhill onto a bound cannot raise the cost beyond rounding; if it
      ! did, the snap was wrong: keep the fit from before it.
      if (sum(r**2) > sum(r_before**2)*(1 + 100*epsilon(1.0_wp)) + tiny(1.0_wp)) then
        active%p = p_before
        r = r_before
        result%at_bound = at_bound_before
        call original_jacobian(options, r, result, status)
        exit
      end if
      call original_jacobian(options, r, result, status)
    end do

    p = active%p
    if (.not. status%ok()) return
    result%cost = 0.5_wp*sum(r**2)
    result%residual_norm = sqrt(sum(r**2))
    call covariance(m, r, result)
  end subroutine solve_active

  !> Fits the parameters not at a bound (or only evaluates r if none is left).
  subroutine fit_free(options, r, result, status)
    type(least_squares_options_t), intent(in) :: options
    real(wp), intent(inout) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    if (all(result%at_bound)) then
      call evaluate_residuals(active%p, r, status)
      result%evaluations = result%evaluations + 1
    else
      call run_minpack(options, r, result, status)
    end if
  end subroutine fit_free

  !> One MINPACK solve over the parameters not at a bound, from active%p.
  !> On return active%p and r are at MINPACK's final point.
  subroutine run_minpack(options, r, result, status)
    type(least_squares_options_t), intent(in) :: options
    real(wp), intent(inout) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    real(wp), allocatable :: z(:), diag(:), fjac(:, :), qtf(:), wa1(:), wa2(:), wa3(:), wa4(:)
    integer, allocatable :: ipvt(:)
    integer :: m, nf, k, info, nfev, njev

    m = active%m
    active%free = pack([(k, k=1, size(active%p))], .not. result%at_bound)
    nf = size(active%free)
    active%n_free = nf
    allocate (z(nf), diag(nf), fjac(m, nf), qtf(nf), wa1(nf), wa2(nf), wa3(nf), wa4(m), ipvt(nf))
    do k = 1, nf
      associate (i => active%free(k))
        z(k) = to_z(active%kind(i), active%lower(i), active%upper(i), active%p(i))
      end associate
    end do
    diag = 1
    r = 0
    fjac = 0
    active%status = status_t()
    njev = 0
    ! mode 1: MINPACK scales the unknowns by the column norms of the Jacobian.
    if (active%problem%has_jacobian()) then
      call lmder(lmder_callback, m, nf, z, r, fjac, m, options%ftol, options%xtol, options%gtol, &
                 options%max_evaluations, diag, 1, options%factor, 0, info, nfev, njev, ipvt, &
                 qtf, wa1, wa2, wa3, wa4)
    else
      call lmdif(lmdif_callback, m, nf, z, r, options%ftol, options%xtol, options%gtol, &
                 options%max_evaluations, options%epsfcn, diag, 1, options%factor, 0, info, nfev, &
                 fjac, m, ipvt, qtf, wa1, wa2, wa3, wa4)
    end if
    call set_parameters(z)
    result%info = info
    result%evaluations = result%evaluations + nfev
    result%jacobian_evaluations = result%jacobian_evaluations + njev

    ! The one translation of LMDIF/LMDER's info.
    select case (info)
    case (:-1)
      if (.not. active%status%ok()) then
        status = active%status   ! the problem's own reason, unchanged
      else
        call set_status(status, STATUS_INTERNAL, 'LMDIF/LMDER stopped by the callback without a status')
      end if
    case (0)
      call set_status(status, STATUS_INVALID_INPUT, 'LMDIF/LMDER info = 0: improper input parameters')
    case (1:4)
      continue   ! converged: ftol (1), xtol (2), both (3) or gtol (4) satisfied
    case (5)
      call set_status(status, STATUS_NOT_CONVERGED, &
        'LMDIF/LMDER info = 5: max_evaluations reached before convergence')
    case (6:8)
      continue   ! ftol, xtol or gtol too small: converged to machine precision
    case default
      call set_status(status, STATUS_SOLVER, 'LMDIF/LMDER returned an unknown info code')
    end select
  end subroutine run_minpack

  !> active%p from MINPACK's unknowns z (the fixed parameters stay as they are).
  subroutine set_parameters(z)
    real(wp), intent(in) :: z(:)
    integer :: k
    do k = 1, size(z)
      associate (i => active%free(k))
        call to_p(active%kind(i), active%lower(i), active%upper(i), z(k), active%p(i), active%dpdz(i))
      end associate
    end do
  end subroutine set_parameters

  subroutine evaluate_residuals(p, r, status)
    real(wp), intent(in) :: p(:)
    real(wp), intent(out) :: r(:)
    type(status_t), intent(inout) :: status
    call active%problem%residuals(p, r, status)
    if (status%ok() .and. .not. all(abs(r) <= huge(r))) &
      call set_status(status, STATUS_SOLVER, 'least squares: a residual is not finite')
  end subroutine evaluate_residuals

  subroutine lmdif_callback(m, n, x, fvec, iflag)
    integer, intent(in) :: m, n
    real(wp), intent(in) :: x(n)
    real(wp), intent(inout) :: fvec(m)
    integer, intent(inout) :: iflag
    if (iflag <= 0) return   ! 0: a print request (nprint = 0, never made)
    call set_parameters(x)
    call evaluate_residuals(active%p, fvec, active%status)
    if (.not. active%status%ok()) iflag = -1
  end subroutine lmdif_callback

  !> iflag 1: residuals; 2: dr/dz = dr/dp dP/dz over the free parameters.
  subroutine lmder_callback(m, n, x, fvec, fjac, ldfjac, iflag)
    integer, intent(in) :: m, n, ldfjac
    real(wp), intent(in) :: x(n)
    real(wp), intent(inout) :: fvec(m), fjac(ldfjac, n)
    integer, intent(inout) :: iflag
    integer :: k
    if (iflag <= 0) return
    call set_parameters(x)
    if (iflag == 1) then
      call evaluate_residuals(active%p, fvec, active%status)
    else
      call active%problem%jacobian(active%p, active%jac, active%status)
      if (active%status%ok()) then
        do k = 1, n
          fjac(1:m, k) = active%jac(:, active%free(k))*active%dpdz(active%free(k))
        end do
        if (.not. all(abs(fjac(1:m, 1:n)) <= huge(fjac))) &
          call set_status(active%status, STATUS_SOLVER, 'least squares: the Jacobian is not finite')
      end if
    end if
    if (.not. active%status%ok()) iflag = -1
  end subroutine lmder_callback

  !> active%jac = dr/dp at active%p for the parameters not at a bound: the
  !> problem's Jacobian, or differences that stay inside the bounds (central with
  !> h = eps^(1/3) max(1, |p|), one-sided with sqrt(eps) max(1, |p|) near a bound).
  subroutine original_jacobian(options, r, result, status)
    type(least_squares_options_t), intent(in) :: options
    real(wp), intent(in) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    real(wp), allocatable :: pp(:), rp(:), rm(:)
    real(wp) :: h, eps
    integer :: i

    if (active%problem%has_jacobian()) then
      call active%problem%jacobian(active%p, active%jac, status)
      result%jacobian_evaluations = result%jacobian_evaluations + 1
      return
    end if
    eps = max(options%epsfcn, epsilon(1.0_wp))
    allocate (pp(size(active%p)), rp(size(r)), rm(size(r)))
    active%jac = 0
    do i = 1, size(active%p)
      if (result%at_bound(i)) cycle
      pp = active%p
      h = eps**(1.0_wp/3)*max(1.0_wp, abs(active%p(i)))
      if (active%p(i) - h >= active%lower(i) .and. active%p(i) + h <= active%upper(i)) then
        pp(i) = active%p(i) + h
        call evaluate_residuals(pp, rp, status)
        if (.not. status%ok()) return
        pp(i) = active%p(i) - h
        call evaluate_residuals(pp, rm, status)
        if (.not. status%ok()) return
        active%jac(:, i) = (rp - rm)/(2*h)
        result%evaluations = result%evaluations + 2
      else
        h = sqrt(eps)*max(1.0_wp, abs(active%p(i)))
        if (active%p(i) + h > active%upper(i)) h = -h
        pp(i) = active%p(i) + h
        call evaluate_residuals(pp, rp, status)
        if (.not. status%ok()) return
        active%jac(:, i) = (rp - r)/h
        result%evaluations = result%evaluations + 1
      end if
    end do
  end subroutine original_jacobian

  !> s^2 (J^T J)^(-1) over the free parameters (numerics_linear_algebra, by QR).
  subroutine covariance(m, r, result)
    integer, intent(in) :: m
    real(wp), intent(in) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    real(wp), allocatable :: cov_free(:, :)
    integer, allocatable :: free(:)
    type(status_t) :: status
    integer :: n, nf, i

    n = size(active%p)
    allocate (result%covariance(n, n), result%standard_error(n))
    result%covariance = 0
    result%standard_error = 0
    result%covariance_valid = .false.
    free = pack([(i, i=1, n)], .not. result%at_bound)
    nf = size(free)
    if (nf == 0) then
      result%covariance_valid = .true.
      return
    end if
    if (m <= nf) then
      result%covariance(free, free) = huge(1.0_wp)
      result%standard_error(free) = huge(1.0_wp)
      return
    end if
    allocate (cov_free(nf, nf))
    call normal_matrix_inverse(active%jac(:, free), cov_free, status)
    if (.not. status%ok()) then   ! rank-deficient: some parameters are not identifiable
      result%covariance(free, free) = huge(1.0_wp)
      result%standard_error(free) = huge(1.0_wp)
      return
    end if
    cov_free = sum(r**2)/(m - nf)*cov_free
    result%covariance(free, free) = cov_free
    result%standard_error(free) = sqrt([(cov_free(i, i), i=1, nf)])
    result%covariance_valid = .true.
  end subroutine covariance

  ! ------------------------------------------------------ change of variables

  elemental integer function bound_kind(lower, upper) result(kind)
    real(wp), intent(in) :: lower, upper
    logical :: lo, up
    lo = lower > -huge(lower)
    up = upper < huge(upper)
    if (lo .and. up .and. lower == upper) then
      kind = KIND_FIXED
    else if (lo .and. up) then
      kind = KIND_BOTH
    else if (lo) then
      kind = KIND_LOWER
    else if (up) then
      kind = KIND_UPPER
    else
      kind = KIND_FREE
    end if
  end function bound_kind

  elemental logical function has_lower(kind)
    integer, intent(in) :: kind
    has_lower = kind == KIND_LOWER .or. kind == KIND_BOTH
  end function has_lower

  elemental logical function has_upper(kind)
    integer, intent(in) :: kind
    has_upper = kind == KIND_UPPER .or. kind == KIND_BOTH
  end function has_upper

  !> The start clamped into the box and moved off the bounds by 1e-3 of the
  !> range (two bounds) or of max(1, |bound|) (one bound).
  elemental real(wp) function start_inside(p, lower, upper, kind) result(q)
    real(wp), intent(in) :: p, lower, upper
    integer, intent(in) :: kind
    real(wp), parameter :: margin = 1e-3_wp
    q = p
    select case (kind)
    case (KIND_BOTH)
      q = min(upper - margin*(upper - lower), max(lower + margin*(upper - lower), p))
    case (KIND_LOWER)
      q = max(lower + margin*max(1.0_wp, abs(lower)), p)
    case (KIND_UPPER)
      q = min(upper - margin*max(1.0_wp, abs(upper)), p)
    case (KIND_FIXED)
      q = lower
    end select
  end function start_inside

  !> p = P(z) and dP/dz (see the module comment).
  pure subroutine to_p(kind, lower, upper, z, p, dpdz)
    integer, intent(in) :: kind
    real(wp), intent(in) :: lower, upper, z
    real(wp), intent(out) :: p, dpdz
    real(wp) :: s
    select case (kind)
    case (KIND_BOTH)
      p = min(upper, max(lower, lower + (upper - lower)*(1 + sin(z))/2))
      dpdz = (upper - lower)*cos(z)/2
    case (KIND_LOWER)
      s = sqrt(1 + z**2)
      p = lower + z**2/(1 + s)
      dpdz = z/s
    case (KIND_UPPER)
      s = sqrt(1 + z**2)
      p = upper - z**2/(1 + s)
      dpdz = -z/s
    case (KIND_FIXED)
      p = lower
      dpdz = 0
    case default
      p = z
      dpdz = 1
    end select
  end subroutine to_p

  !> z with P(z) = p, for p inside the box.
  pure real(wp) function to_z(kind, lower, upper, p) result(z)
    integer, intent(in) :: kind
    real(wp), intent(in) :: lower, upper, p
    real(wp) :: w
    select case (kind)
    case (KIND_BOTH)
      z = asin(max(-1.0_wp, min(1.0_wp, 2*(p - lower)/(upper - lower) - 1)))
    case (KIND_LOWER)
      w = max(0.0_wp, p - lower)
      z = sqrt(w*(w + 2))   ! sqrt(1 + z^2) - 1 = w
    case (KIND_UPPER)
      w = max(0.0_wp, upper - p)
      z = sqrt(w*(w + 2))
    case (KIND_FIXED)
      z = 0
    case default
      z = p
    end select
  end function to_z
end module numerics_least_squares
