!> Fitting spline surfaces over FITPACK: a scalar surface to scattered data
!> (surfit) or to a grid (regrid), a parametric one to a grid of points
!> (parsur); the checks of the input, the workspaces, the one translation
!> of FITPACK's ier (ier_status), and the Taylor table of the fit that
!> evaluation reads.
submodule (numerics_spline_surface) numerics_spline_surface_fit
  use base_text, only: format_integer
  use base_status, only: STATUS_OK, STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL
  use fitpack_surface_interfaces, only: surfit, regrid, parsur
  use numerics_spline_kernels, only: basis_derivatives
  implicit none (type, external)

contains

  !> (Its arguments and their meaning: the interface in numerics_spline_surface.)
  module procedure fit_scattered
    real(wp), allocatable :: w(:), tx(:), ty(:), c(:), wrk1(:), wrk2(:)
    integer, allocatable :: iwrk(:)
    real(wp) :: box(4), fp
    integer :: m, nxest, nyest, nmax, nx, ny, ier, lwrk1, lwrk2, kwrk, attempt
    real(wp), parameter :: eps = 1.0e-16_wp   ! FITPACK's suggested rank threshold for real64
    m = size(x)
    if (size(y) /= m .or. size(z) /= m) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: x, y and z differ in size')
      return
    end if
    if (.not. degrees_ok(kx, ky, status, 'fit_scattered')) return
    if (m < (kx + 1)*(ky + 1)) then
      call set_status(status, STATUS_INVALID_INPUT, format_integer(m)//' data points: a spline of degree '// &
                      format_integer(kx)//' x '//format_integer(ky)//' needs at least '// &
                      format_integer((kx + 1)*(ky + 1)))
      return
    end if
    if (.not. (all(abs(x) <= huge(x)) .and. all(abs(y) <= huge(y)) .and. all(abs(z) <= huge(z)))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: data not finite')
      return
    end if
    if (.not. (smoothing >= 0 .and. smoothing <= huge(smoothing))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: smoothing factor must be finite and >= 0')
      return
    end if
    allocate (w(m))
    w = 1
    if (present(weights)) then
      if (size(weights) /= m) then
        call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: weights differ in size from the data')
        return
      end if
      if (.not. all(weights > 0 .and. weights <= huge(weights))) then
        call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: weights must be positive and finite')
        return
      end if
      w = weights
    end if
    box = [minval(x), maxval(x), minval(y), maxval(y)]
    if (present(bbox)) box = bbox
    if (.not. (box(1) < box(2) .and. box(3) < box(4))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: empty bounding box (all x or all y equal?)')
      return
    end if
    if (any(x < box(1)) .or. any(x > box(2)) .or. any(y < box(3)) .or. any(y > box(4))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: data outside the bounding box')
      return
    end if
    ! FITPACK's suggestion for the knot storage; enlarged when it runs out
    nxest = max(kx + 1 + ceiling(sqrt(m/2.0_wp)), 2*(kx + 1))
    nyest = max(ky + 1 + ceiling(sqrt(m/2.0_wp)), 2*(ky + 1))
    if (smoothing == 0) then
      nxest = max(nxest, kx + 1 + ceiling(sqrt(real(m, wp))) + 2)
      nyest = max(nyest, ky + 1 + ceiling(sqrt(real(m, wp))) + 2)
    end if
    lwrk2 = 0
    do attempt = 1, 4
      nmax = max(nxest, nyest)
      call surfit_workspace(m, kx, ky, nxest, nyest, lwrk1, lwrk2, kwrk)
      if (allocated(tx)) deallocate (tx, ty, c, wrk1, wrk2, iwrk)
      allocate (tx(nmax), ty(nmax), c((nxest - kx - 1)*(nyest - ky - 1)), wrk1(lwrk1), wrk2(lwrk2), &
        iwrk(kwrk))
      tx = 0
      ty = 0
      c = 0
      call surfit(0, m, x, y, z, w, box(1), box(2), box(3), box(4), kx, ky, smoothing, nxest, nyest, nmax, &
        eps, nx, tx, ny, ty, c, fp, wrk1, lwrk1, wrk2, lwrk2, iwrk, kwrk, ier)
      if (ier > 10) then
        lwrk2 = ier       ! the size surfit asks for
      else if (ier == 1 .and. attempt < 4) then
        nxest = 2*nxest
        nyest = 2*nyest
        lwrk2 = 0
      else
        exit
      end if
    end do
    call ier_status(ier, 'fit_scattered (surfit)', status)
    if (.not. status%ok()) return
    call store(surf, 1, kx, ky, [.false., .false.], tx(1:nx), ty(1:ny), c, fp, ier)
  end procedure fit_scattered

  !> (Its arguments and their meaning: the interface in numerics_spline_surface.)
  module procedure fit_grid
    real(wp), allocatable :: zz(:), tx(:), ty(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    integer :: mx, my, nxest, nyest, nx, ny, lwrk, kwrk, ier
    real(wp) :: fp
    mx = size(x)
    my = size(y)
    if (size(z, 1) /= mx .or. size(z, 2) /= my) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_grid: z must have shape (size(x), size(y))')
      return
    end if
    if (.not. degrees_ok(kx, ky, status, 'fit_grid')) return
    if (mx <= kx .or. my <= ky) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_grid: need more grid lines than the degree in each direction')
      return
    end if
    if (any(x(2:) <= x(:mx - 1)) .or. any(y(2:) <= y(:my - 1))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_grid: x and y must be strictly increasing')
      return
    end if
    if (.not. (all(abs(z) <= huge(z)) .and. smoothing >= 0 .and. smoothing <= huge(smoothing))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_grid: data not finite or smoothing factor < 0')
      return
    end if
    nxest = mx + kx + 1
    nyest = my + ky + 1
    lwrk = 4 + nxest*(my + 2*kx + 5) + nyest*(2*ky + 5) + mx*(kx + 1) + my*(ky + 1) + max(my, nxest)
    kwrk = 3 + mx + my + nxest + nyest
    allocate (tx(nxest), ty(nyest), c((nxest - kx - 1)*(nyest - ky - 1)), wrk(lwrk), iwrk(kwrk))
    zz = reshape(transpose(z), [mx*my])     ! regrid's layout: y fastest
    call regrid(0, mx, x, my, y, zz, x(1), x(mx), y(1), y(my), kx, ky, smoothing, nxest, nyest, nx, tx, &
      ny, ty, c, fp, wrk, lwrk, iwrk, kwrk, ier)
    call ier_status(ier, 'fit_grid (regrid)', status)
    if (.not. status%ok()) return
    call store(surf, 1, kx, ky, [.false., .false.], tx(1:nx), ty(1:ny), c, fp, ier)
  end procedure fit_grid

  !> (Its arguments and their meaning: the interface in numerics_spline_surface.)
  module procedure fit_parametric
    real(wp), allocatable :: f(:), tu(:), tv(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    integer :: mu, mv, nuest, nvest, nu, nv, lwrk, kwrk, ier, ipar(2), i, j, l
    real(wp) :: fp
    mu = size(u)
    mv = size(v)
    if (size(points, 1) /= 3 .or. size(points, 2) /= mu .or. size(points, 3) /= mv) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_parametric: points must have shape (3, size(u), size(v))')
      return
    end if
    if (mu < 4 .or. mv < 4) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_parametric: need at least 4 grid lines in u and in v')
      return
    end if
    if (any(u(2:) <= u(:mu - 1)) .or. any(v(2:) <= v(:mv - 1))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_parametric: u and v must be strictly increasing')
      return
    end if
    if (.not. (all(abs(points) <= huge(points)) .and. smoothing >= 0 .and. smoothing <= huge(smoothing))) then
      call set_status(status, STATUS_INVALID_INPUT, 'fit_parametric: points not finite or smoothing factor < 0')
      return
    end if
    ipar = merge(1, 0, periodic)
    nuest = mu + 4 + 2*ipar(1)
    nvest = mv + 4 + 2*ipar(2)
    lwrk = 4 + nuest*(mv*3 + 11 + 4*ipar(1)) + nvest*(11 + 4*ipar(2)) + 4*(mu + mv) + max(nuest, mv)*3
    kwrk = 3 + mu + mv + nuest + nvest
    allocate (f(3*mu*mv), tu(nuest), tv(nvest), c(3*(nuest - 4)*(nvest - 4)), wrk(lwrk), iwrk(kwrk))
    do l = 1, 3
      do i = 1, mu
        do j = 1, mv
          f(mu*mv*(l - 1) + mv*(i - 1) + j) = points(l, i, j)
        end do
      end do
    end do
    call parsur(0, ipar, 3, mu, u, mv, v, f, smoothing, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, &
      iwrk, kwrk, ier)
    call ier_status(ier, 'fit_parametric (parsur)', status)
    if (.not. status%ok()) return
    call store(surf, 3, 3, 3, periodic, tu(1:nu), tv(1:nv), c, fp, ier)
  end procedure fit_parametric

  logical function degrees_ok(kx, ky, status, where)
    integer, intent(in) :: kx, ky
    type(status_t), intent(inout) :: status
    character(len=*), intent(in) :: where
    degrees_ok = kx >= 1 .and. kx <= max_degree .and. ky >= 1 .and. ky <= max_degree
    if (.not. degrees_ok) call set_status(status, STATUS_INVALID_INPUT, where//': degrees must be 1..5')
  end function degrees_ok

  !> FITPACK ier -> status, for surfit, regrid and parsur.
  subroutine ier_status(ier, where, status)
    integer, intent(in) :: ier
    character(len=*), intent(in) :: where
    type(status_t), intent(inout) :: status
    character(len=16) :: num
    write (num, '(i0)') ier
    select case (ier)
    case (0, -1, -2)
      status%code = STATUS_OK          ! smoothing spline, interpolant, polynomial
    case (:-3)
      status%code = STATUS_OK          ! rank deficient: minimum-norm solution of rank -ier
    case (1)
      call set_status(status, STATUS_SOLVER, where//': the knot storage ran out before fp <= s; '// &
        'the result would be a least-squares spline with fp > s (smoothing factor too small?)')
    case (2)
      call set_status(status, STATUS_NOT_CONVERGED, where//': the smoothing parameter iteration '// &
        'left its theory: smoothing factor too small')
    case (3)
      call set_status(status, STATUS_NOT_CONVERGED, where//': 20 smoothing parameter iterations '// &
        'without reaching fp = s (smoothing factor too small?)')
    case (4)
      call set_status(status, STATUS_SOLVER, where//': no more knots can be added: more coefficients '// &
        'than data points (smoothing factor too small)')
    case (5)
      call set_status(status, STATUS_SOLVER, where//': no more knots can be added: a new knot would '// &
        'split an interval more unevenly than 10:1 (smoothing factor too small or data clustered)')
    case (10)
      call set_status(status, STATUS_INVALID_INPUT, where//': FITPACK rejected the input (ier = 10)')
    case default
      call set_status(status, STATUS_INTERNAL, where//': workspace too small (ier = '//trim(num)//')')
    end select
  end subroutine ier_status

  subroutine surfit_workspace(m, kx, ky, nxest, nyest, lwrk1, lwrk2, kwrk)
    integer, intent(in) :: m, kx, ky, nxest, nyest
    integer, intent(out) :: lwrk1, kwrk
    integer, intent(inout) :: lwrk2
    integer :: u, v, km1, km2, ne, bx, by, b1, b2
    u = nxest - kx - 1
    v = nyest - ky - 1
    km1 = max(kx, ky) + 1
    km2 = km1 + 1
    ne = max(nxest, nyest)
    bx = kx*v + ky + 1
    by = ky*u + kx + 1
    if (bx <= by) then
      b1 = bx
      b2 = b1 + v - ky
    else
      b1 = by
      b2 = b1 + u - kx
    end if
    lwrk1 = u*v*(2 + b1 + b2) + 2*(u + v + km2*ne + km1*m) + b2 + 1
    lwrk2 = max(lwrk2, u*v*(b2 + 1) + b2)
    kwrk = m + (nxest - 2*kx - 1)*(nyest - 2*ky - 1)
  end subroutine surfit_workspace

  !> Keeps knots and coefficients; c in FITPACK's layout (y fastest, for
  !> dim = 3 one block per coordinate) is unpacked to c(i, j, l).
  subroutine store(surf, dim, ku, kv, periodic, tu, tv, c, fp, ier)
    type(spline_surface_t), intent(inout) :: surf
    integer, intent(in) :: dim, ku, kv, ier
    logical, intent(in) :: periodic(2)
    real(wp), intent(in) :: tu(:), tv(:), c(:), fp
    integer :: ncu, ncv, i, j, l
    surf%dim = dim
    surf%ku = ku
    surf%kv = kv
    surf%periodic = periodic
    surf%tu = tu
    surf%tv = tv
    surf%fp = fp
    surf%ier = ier
    ncu = size(tu) - ku - 1
    ncv = size(tv) - kv - 1
    allocate (surf%c(ncu, ncv, dim))
    do l = 1, dim
      do i = 1, ncu
        do j = 1, ncv
          surf%c(i, j, l) = c(ncu*ncv*(l - 1) + ncv*(i - 1) + j)
        end do
      end do
    end do
    call tabulate(surf)
  end subroutine store

  !> The Taylor table of every patch: the B-splines' derivatives (orders
  !> 0..k) at the patch's lower corner contracted with the coefficients.
  subroutine tabulate(surf)
    type(spline_surface_t), intent(inout) :: surf
    real(wp) :: du(0:max_degree, max_degree + 1), dv(0:max_degree, max_degree + 1), w(0:max_degree, max_degree + 1)
    integer :: ku, kv, lu, lv, l, r, s, j
    ku = surf%ku
    kv = surf%kv
    allocate (surf%taylor(0:ku, 0:kv, surf%dim, ku + 1:size(surf%tu) - ku - 1, kv + 1:size(surf%tv) - kv - 1))
    surf%taylor = 0
    do lv = kv + 1, size(surf%tv) - kv - 1
      if (.not. surf%tv(lv + 1) > surf%tv(lv)) cycle
      call basis_derivatives(surf%tv, kv, surf%tv(lv), lv, dv)
      do lu = ku + 1, size(surf%tu) - ku - 1
        if (.not. surf%tu(lu + 1) > surf%tu(lu)) cycle
        call basis_derivatives(surf%tu, ku, surf%tu(lu), lu, du)
        do l = 1, surf%dim
          ! w(r, j): the r-th u-derivative of coefficient column j
          do j = 1, kv + 1
            do r = 0, ku
              w(r, j) = sum(du(r, 1:ku + 1)*surf%c(lu - ku:lu, lv - kv - 1 + j, l))
            end do
          end do
          do s = 0, kv
            do r = 0, ku
              surf%taylor(r, s, l, lu, lv) = sum(w(r, 1:kv + 1)*dv(s, 1:kv + 1))/(factorial(r)*factorial(s))
            end do
          end do
        end do
      end do
    end do
  end subroutine tabulate
end submodule numerics_spline_surface_fit
