!> Fitting a spline curve to points over FITPACK (parcur, clocur, concur):
!> the checks of the input, the workspace, and the one translation of
!> FITPACK's ier (ier_status).
submodule (numerics_spline_curve) numerics_spline_curve_fit
  use base_status, only: STATUS_OK, STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL
  use fitpack_interfaces, only: parcur, clocur, concur
  implicit none (type, external)

contains

  !> The fit of the curve (its arguments and their meaning: the interface in
  !> numerics_spline_curve).
  module procedure fit
    real(wp), allocatable :: u(:), x(:), w(:), xx(:), t(:), c(:), wrk(:), db(:), de(:), cp(:), coefficients(:, :)
    integer, allocatable :: iwrk(:)
    integer :: idim, m, k, nest, nc, lwrk, n, ier, ipar, nb, ne, i, l, np
    real(wp) :: fp, ub, ue, scale
    logical :: closed, constrained
    type(status_t) :: stored

    idim = size(points, 1)
    m = size(points, 2)
    k = degree
    closed = .false.
    if (present(periodic)) closed = periodic
    nb = 0
    ne = 0
    if (present(start_derivatives)) nb = size(start_derivatives, 2)
    if (present(end_derivatives)) ne = size(end_derivatives, 2)
    constrained = nb > 0 .or. ne > 0

    ! validation at the boundary; FITPACK's own checks then only catch what we missed
    if (idim < 1 .or. idim > max_dimension) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: the dimension must be 1..10')
      return
    end if
    if (k < 1 .or. k > max_degree) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: the degree must be 1..5')
      return
    end if
    if (m < k + 1 .or. (closed .and. m < 3)) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: fewer points than degree + 1')
      return
    end if
    if (.not. (smoothing >= 0) .or. smoothing > huge(1.0_wp)) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: the smoothing factor must be >= 0')
      return
    end if
    if (.not. all(abs(points) <= huge(1.0_wp))) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: points must be finite')
      return
    end if
    if (present(parameters)) then
      if (size(parameters) /= m) then
        call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: one parameter per point needed')
        return
      end if
      if (.not. all(parameters(2:m) > parameters(1:m - 1)) .or. &
          .not. all(abs(parameters) <= huge(1.0_wp))) then
        call set_status(status, STATUS_INVALID_INPUT, &
                        'spline curve fit: parameters must be finite and strictly increasing')
        return
      end if
    end if
    if (present(weights)) then
      if (size(weights) /= m) then
        call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: one weight per point needed')
        return
      end if
      if (.not. all(weights > 0) .or. .not. all(weights <= huge(1.0_wp))) then
        call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: weights must be positive and finite')
        return
      end if
    end if
    if (constrained) then
      if (closed) then
        call set_status(status, STATUS_INVALID_INPUT, &
                        'spline curve fit: end derivatives cannot be prescribed for a closed curve')
        return
      end if
      if (mod(k, 2) == 0) then
        call set_status(status, STATUS_INVALID_INPUT, &
                        'spline curve fit: end derivatives need an odd degree (1, 3 or 5)')
        return
      end if
      if (nb > (k + 1)/2 .or. ne > (k + 1)/2) then
        call set_status(status, STATUS_INVALID_INPUT, &
                        'spline curve fit: at most (degree+1)/2 derivatives (from the position on) per end')
        return
      end if
      if (present(start_derivatives)) then
        if (size(start_derivatives, 1) /= idim) then
          call set_status(status, STATUS_INVALID_INPUT, &
                          'spline curve fit: start derivatives must have the dimension of the points')
          return
        end if
      end if
      if (present(end_derivatives)) then
        if (size(end_derivatives, 1) /= idim) then
          call set_status(status, STATUS_INVALID_INPUT, &
                          'spline curve fit: end derivatives must have the dimension of the points')
          return
        end if
      end if
    end if

    allocate (u(m), x(idim*m), w(m))
    x = reshape(points, [idim*m])
    w = 1
    if (present(weights)) w = weights
    ipar = 0
    if (present(parameters)) then
      u = parameters
      ipar = 1
    else if (constrained) then
      ! concur needs parameters: chord length scaled to [0,1] as parcur's ipar = 0
      u(1) = 0
      do i = 2, m
        u(i) = u(i - 1) + norm2(points(:, i) - points(:, i - 1))
      end do
      if (.not. all(u(2:m) > u(1:m - 1))) then
        call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: consecutive points coincide')
        return
      end if
      u(2:m) = u(2:m)/u(m)
      u(m) = 1
    end if
    if (closed) then
      scale = maxval(abs(points))
      if (any(abs(points(:, m) - points(:, 1)) > 1e-12_wp*max(scale, 1.0_wp))) then
        call set_status(status, STATUS_INVALID_INPUT, &
                        'spline curve fit: a closed curve needs its last point equal to its first')
        return
      end if
      x(idim*(m - 1) + 1:idim*m) = x(1:idim)
    end if

    ! storage for the interpolating spline, so that ier = 1 cannot happen
    if (closed) then
      nest = m + 2*k
      lwrk = m*(k + 1) + nest*(7 + idim + 5*k)
    else
      nest = m + k + 1 + max(0, nb - 1) + max(0, ne - 1)
      lwrk = m*(k + 1) + nest*(6 + idim + 3*k)
    end if
    nc = nest*idim
    allocate (t(nest), c(nc), wrk(lwrk), iwrk(nest))
    t = 0
    c = 0
    n = 0
    fp = 0
    if (closed) then
      call clocur(0, ipar, idim, m, u, idim*m, x, w, k, smoothing, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    else if (constrained) then
      allocate (db(max(1, idim*nb)), de(max(1, idim*ne)), xx(idim*m))
      np = 2*(k + 1)*idim
      allocate (cp(np))
      db = 0
      de = 0
      do l = 1, nb
        db(idim*(l - 1) + 1:idim*l) = start_derivatives(:, l)
      end do
      do l = 1, ne
        de(idim*(l - 1) + 1:idim*l) = end_derivatives(:, l)
      end do
      call concur(0, idim, m, u, idim*m, x, xx, w, nb, db, size(db), ne, de, size(de), k, smoothing, nest, n, t, &
                  nc, c, np, cp, fp, wrk, lwrk, iwrk, ier)
    else
      ub = 0
      ue = 1
      if (ipar == 1) then
        ub = u(1)
        ue = u(m)
      end if
      call parcur(0, ipar, idim, m, u, idim*m, x, w, ub, ue, k, smoothing, nest, n, t, nc, c, fp, &
                  wrk, lwrk, iwrk, ier)
    end if
    call ier_status(ier, status)
    if (ier == 10) return

    allocate (coefficients(idim, n - k - 1))
    do l = 1, idim
      coefficients(l, :) = c(n*(l - 1) + 1:n*(l - 1) + n - k - 1)
    end do
    ! set makes the table (gfortran keeps the module's private procedures
    ! out of a submodule's reach: a public one does the work)
    call self%set(t(1:n), coefficients, k, stored, periodic=closed)
    if (.not. stored%ok()) then
      status = stored
      return
    end if
    self%fp = fp
    self%ier = ier
  end procedure fit

  !> FITPACK's ier -> status (the one place where ier is read).
  pure subroutine ier_status(ier, status)
    integer, intent(in) :: ier
    type(status_t), intent(inout) :: status
    select case (ier)
    case (0, -1, -2)
      status%code = STATUS_OK
    case (1)
      call set_status(status, STATUS_SOLVER, 'spline curve fit: FITPACK ran out of knot storage (ier = 1); '// &
                      'the least-squares spline returned has fp > s')
    case (2)
      call set_status(status, STATUS_NOT_CONVERGED, 'spline curve fit: the smoothing factor is too small '// &
                      'for FITPACK to find the smoothing parameter (ier = 2); approximation returned')
    case (3)
      call set_status(status, STATUS_NOT_CONVERGED, 'spline curve fit: FITPACK reached its 20 iterations '// &
                      'for the smoothing parameter (ier = 3); the smoothing factor may be too small')
    case (10)
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve fit: FITPACK rejected the input (ier = 10): '// &
                      'check parameter order, weights, degree and the number of points')
    case default
      call set_status(status, STATUS_INTERNAL, 'spline curve fit: unexpected FITPACK ier')
    end select
  end subroutine ier_status
end submodule numerics_spline_curve_fit
