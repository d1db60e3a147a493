!> The residuals of the least-squares fit at points, and the Jacobians formed
!> from them by differences, and the covariance at the optimum (see
!> numerics_least_squares' module comment): dr/dz by forward differences as
!> LMDIF forms them, for LMDER; dr/dp at the optimum, for the snapping to
!> bounds and the covariance.
submodule (numerics_least_squares) numerics_least_squares_jacobians
  use base_status, only: prefix_status
  use numerics_linear_algebra, only: normal_matrix_inverse
  use numerics_bounded_variables, only: near_lower, near_upper
  implicit none (type, external)

contains

  !> fit%p from MINPACK's unknowns z (the fixed parameters stay as they are).
  module procedure set_parameters
    integer :: k
    do k = 1, size(z)
      associate (i => fit%free(k))
        call to_p(fit%kind(i), fit%lower(i), fit%upper(i), z(k), fit%p(i), fit%dpdz(i))
      end associate
    end do
  end procedure set_parameters

  module procedure evaluate_residuals
    call fit%problem%residuals(p, r, status)
    call check_finite(r, status)
  end procedure evaluate_residuals

  module procedure check_finite
    if (status%ok() .and. .not. all(abs(r) <= huge(r))) &
      call set_status(status, STATUS_SOLVER, 'least squares: a residual is not finite')
  end procedure check_finite

  !> dr/dz by forward differences as LMDIF's fdjac2 forms them, all columns
  !> in one batch. A failed point is retried mirrored (backward difference).
  module procedure difference_jacobian
    real(wp) :: eps, h(size(z)), zj(size(z))
    integer :: j

    eps = sqrt(max(fit%epsfcn, epsilon(1.0_wp)))
    do j = 1, size(z)
      h(j) = eps*abs(z(j))
      if (h(j) == 0) h(j) = eps
    end do
    call batch_at(fit, z, h, status)
    if (.not. status%ok()) return
    do j = 1, size(z)
      if (.not. fit%statuses(j)%ok()) then   ! mirror the step once
        h(j) = -h(j)
        zj = z
        zj(j) = z(j) + h(j)
        call set_parameters(fit, zj)
        fit%statuses(j) = status_t()
        call evaluate_residuals(fit, fit%p, fit%values(:, j), fit%statuses(j))
        fit%evaluations = fit%evaluations + 1
        if (.not. fit%statuses(j)%ok()) then
          status = fit%statuses(j)
          call prefix_status(status, 'least squares: difference Jacobian (both sides of an accepted point)')
          return
        end if
      end if
      fjac(:, j) = (fit%values(:, j) - r)/h(j)
    end do
    call set_parameters(fit, z)   ! restore p and dP/dz at z
  end procedure difference_jacobian

  !> Residuals at z + h_j e_j for every column j, as one batch.
  recursive subroutine batch_at(fit, z, h, status)
    type(fit_t), intent(inout) :: fit
    real(wp), intent(in) :: z(:), h(:)
    type(status_t), intent(inout) :: status
    real(wp) :: zj(size(z))
    integer :: j
    do j = 1, size(z)
      zj = z
      zj(j) = z(j) + h(j)
      call set_parameters(fit, zj)
      fit%points(:, j) = fit%p
      fit%statuses(j) = status_t()
    end do
    call set_parameters(fit, z)
    call fit%problem%residuals_batch(fit%points, fit%values, fit%statuses)
    fit%evaluations = fit%evaluations + size(z)
    do j = 1, size(z)
      call check_finite(fit%values(:, j), fit%statuses(j))
      if (.not. fit%statuses(j)%ok() .and. .not. is_rejectable(fit%statuses(j))) then
        status = fit%statuses(j)
        return
      end if
    end do
  end subroutine batch_at

  !> The Jacobian at the optimum (original_jacobian) when the covariance is
  !> wanted or a free parameter lies within bound_tolerance of a bound (the
  !> snapping needs its gradient there); otherwise none (jacobian_ok false).
  module procedure jacobian_at_optimum
    logical :: near
    integer :: i
    near = .false.
    do i = 1, size(fit%p)
      if (result%at_bound(i)) cycle
      near = near .or. near_lower(fit%kind(i), fit%p(i), fit%lower(i), options%bound_tolerance) .or. &
             near_upper(fit%kind(i), fit%p(i), fit%upper(i), options%bound_tolerance)
    end do
    status = status_t()
    fit%jacobian_ok = .false.
    if (options%covariance .or. near) call original_jacobian(fit, options, r, result, status)
  end procedure jacobian_at_optimum

  !> fit%jac = dr/dp at fit%p for the parameters not at a bound: the
  !> problem's Jacobian, or differences that stay inside the bounds (central with
  !> h = eps^(1/3) max(1, |p|), one-sided with sqrt(eps) max(1, |p|) near a
  !> bound), all points in one batch. Where the model fails on one side (a
  !> rejectable status) the other side gives a one-sided difference; where it
  !> fails on both, jacobian_ok is false (no covariance, no snapping to bounds)
  !> and the fit itself stands.
  recursive subroutine original_jacobian(fit, options, r, result, status)
    type(fit_t), intent(inout) :: fit
    type(least_squares_options_t), intent(in) :: options
    real(wp), intent(in) :: r(:)
    type(least_squares_result_t), intent(inout) :: result
    type(status_t), intent(out) :: status
    real(wp), allocatable :: points(:, :), values(:, :), h(:)
    type(status_t), allocatable :: statuses(:)
    logical, allocatable :: central(:)
    integer, allocatable :: first(:)
    real(wp) :: eps
    integer :: i, n, count, a, b

    fit%jacobian_ok = .true.
    if (fit%problem%has_jacobian()) then
      call fit%problem%jacobian(fit%p, fit%jac, status)
      result%jacobian_evaluations = result%jacobian_evaluations + 1
      return
    end if
    n = size(fit%p)
    eps = max(options%epsfcn, epsilon(1.0_wp))
    allocate (h(n), central(n), first(n), points(n, 2*n))
    count = 0
    fit%jac = 0
    do i = 1, n
      if (result%at_bound(i)) cycle
      first(i) = count + 1
      h(i) = eps**(1.0_wp/3)*max(1.0_wp, abs(fit%p(i)))
      central(i) = fit%p(i) - h(i) >= fit%lower(i) .and. fit%p(i) + h(i) <= fit%upper(i)
      if (central(i)) then
        points(:, count + 1) = fit%p
        points(i, count + 1) = fit%p(i) + h(i)
        points(:, count + 2) = fit%p
        points(i, count + 2) = fit%p(i) - h(i)
        count = count + 2
      else
        h(i) = sqrt(eps)*max(1.0_wp, abs(fit%p(i)))
        if (fit%p(i) + h(i) > fit%upper(i)) h(i) = -h(i)
        points(:, count + 1) = fit%p
        points(i, count + 1) = fit%p(i) + h(i)
        count = count + 1
      end if
    end do
    if (count == 0) return
    allocate (values(size(r), count), statuses(count))
    call fit%problem%residuals_batch(points(:, 1:count), values, statuses)
    result%evaluations = result%evaluations + count
    result%jacobian_evaluations = result%jacobian_evaluations + 1
    do i = 1, count
      call check_finite(values(:, i), statuses(i))
      if (.not. statuses(i)%ok()) then
        if (.not. is_rejectable(statuses(i))) then
          status = statuses(i)
          call prefix_status(status, 'least squares: Jacobian at the optimum')
          return
        end if
        fit%rejected = fit%rejected + 1
        fit%last_rejection = statuses(i)%text()
      end if
    end do
    do i = 1, n
      if (result%at_bound(i)) cycle
      a = first(i)
      if (.not. central(i)) then
        if (statuses(a)%ok()) then
          fit%jac(:, i) = (values(:, a) - r)/h(i)
        else
          fit%jacobian_ok = .false.
        end if
        cycle
      end if
      b = a + 1
      if (statuses(a)%ok() .and. statuses(b)%ok()) then
        fit%jac(:, i) = (values(:, a) - values(:, b))/(2*h(i))
      else if (statuses(a)%ok()) then   ! one-sided: h^(1/3) steps give ~eps^(1/3) accuracy
        fit%jac(:, i) = (values(:, a) - r)/h(i)
      else if (statuses(b)%ok()) then
        fit%jac(:, i) = (r - values(:, b))/h(i)
      else
        fit%jacobian_ok = .false.
      end if
    end do
  end subroutine original_jacobian

  !> s^2 (J^T J)^(-1) over the free parameters (numerics_linear_algebra, by QR).
  module procedure covariance
    real(wp), allocatable :: cov_free(:, :)
    integer, allocatable :: free(:)
    type(status_t) :: status
    integer :: n, nf, i

    n = size(fit%p)
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
    if (m <= nf .or. .not. fit%jacobian_ok) then
      result%covariance(free, free) = huge(1.0_wp)
      result%standard_error(free) = huge(1.0_wp)
      return
    end if
    allocate (cov_free(nf, nf))
    call normal_matrix_inverse(fit%jac(:, free), cov_free, status)
    if (.not. status%ok()) then   ! rank-deficient: some parameters are not identifiable
      result%covariance(free, free) = huge(1.0_wp)
      result%standard_error(free) = huge(1.0_wp)
      return
    end if
    cov_free = sum(r**2)/(m - nf)*cov_free
    result%covariance(free, free) = cov_free
    result%standard_error(free) = sqrt([(cov_free(i, i), i=1, nf)])
    result%covariance_valid = .true.
  end procedure covariance
end submodule numerics_least_squares_jacobians
