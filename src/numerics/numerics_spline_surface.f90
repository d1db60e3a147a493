!> Spline surfaces over our FITPACK (external/fitpack): a scalar surface
!> z = s(x,y) fitted to scattered data (surfit) or to a grid (regrid), or a
!> parametric surface r(u,v) in 3-D fitted to a grid of points (parsur, bicubic,
!> optionally periodic in u and/or v). One call evaluates the value and all
!> partial derivatives up to third order, without allocation.
!>
!> Evaluation runs on a table made once per fit: on each patch
!> [tu(i), tu(i+1)) x [tv(j), tv(j+1)) the surface is one polynomial of
!> degrees ku, kv, stored as its Taylor coefficients about the patch's lower
!> corner, d^(r+s) s / du^r dv^s / (r! s!) (from the B-splines' derivatives
!> there). A point then costs the knot searches and Taylor shifts (Horner):
!> first along u for each power of v, then along v; no divisions.
!>
!> Fitting translates FITPACK's ier in one place (ier_status) into status_t;
!> least-squares polynomials (ier = -2), interpolants (-1) and rank-deficient
!> minimum-norm solutions (ier < -2) are accepted fits.
module numerics_spline_surface
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT, STATUS_DOMAIN, &
    STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL
  use fitpack_surface_interfaces, only: surfit, regrid, parsur
  implicit none (type, external)
  private
  public :: spline_surface_t, spline_surface_eval_t
  public :: fit_scattered, fit_grid, fit_parametric

  integer, parameter :: max_degree = 5
  real(wp), parameter :: factorial(0:max_degree) = [1, 1, 2, 6, 24, 120]

  !> Value and partial derivatives at one point. For a scalar surface only the
  !> first component is used (f(1) = z, fu(1) = dz/dx, ...); for a parametric
  !> surface all three (f = r, fu = r_u, fuv = r_uv, ...). Partials of order
  !> above the degree are zero.
  type :: spline_surface_eval_t
    integer :: dim = 1
    real(wp) :: f(3) = 0
    real(wp) :: fu(3) = 0, fv(3) = 0
    real(wp) :: fuu(3) = 0, fuv(3) = 0, fvv(3) = 0
    real(wp) :: fuuu(3) = 0, fuuv(3) = 0, fuvv(3) = 0, fvvv(3) = 0
  end type spline_surface_eval_t

  !> A tensor-product B-spline surface with knots tu, tv, degrees ku, kv and
  !> coefficients c(i, j, l) (i along u, j along v, l = 1..dim).
  type :: spline_surface_t
    private
    integer :: dim = 0
    integer :: ku = 0, kv = 0
    logical :: periodic(2) = .false.
    real(wp), allocatable :: tu(:), tv(:)
    real(wp), allocatable :: c(:, :, :)
    !> taylor(r, s, l, i, j): the Taylor coefficients of component l on patch
    !> [tu(i), tu(i+1)) x [tv(j), tv(j+1)), i = ku+1..nu-ku-1, j = kv+1..nv-kv-1
    real(wp), allocatable :: taylor(:, :, :, :, :)
    real(wp) :: fp = 0
    integer :: ier = 0
  contains
    procedure :: evaluate
    procedure :: evaluate_grid
    procedure :: domain
    procedure :: is_fitted
    procedure :: dimension => surface_dimension
    procedure :: degrees
    procedure :: residual
    procedure :: fitpack_ier
    procedure :: knots_u
    procedure :: knots_v
    procedure :: coefficients
  end type spline_surface_t

contains

  !> Smoothing spline z = s(x,y) of degrees kx, ky (1..5) to scattered data
  !> (FITPACK surfit, iopt = 0): sum (w (z - s))^2 <= smoothing within 0.1 %.
  !> weights default to 1; bbox = [xb, xe, yb, ye] defaults to the data range.
  function fit_scattered(x, y, z, smoothing, kx, ky, status, weights, bbox) result(surf)
    real(wp), intent(in) :: x(:), y(:), z(:)
    real(wp), intent(in) :: smoothing
    integer, intent(in) :: kx, ky
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: weights(:), bbox(4)
    type(spline_surface_t) :: surf
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
  end function fit_scattered

  !> Smoothing spline z = s(x,y) on the grid x(1..mx) x y(1..my) (strictly
  !> increasing), z(i,j) = value at (x(i), y(j)) (FITPACK regrid, iopt = 0).
  function fit_grid(x, y, z, smoothing, kx, ky, status) result(surf)
    real(wp), intent(in) :: x(:), y(:), z(:, :)
    real(wp), intent(in) :: smoothing
    integer, intent(in) :: kx, ky
    type(status_t), intent(out) :: status
    type(spline_surface_t) :: surf
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
  end function fit_grid

  !> Bicubic parametric surface r(u,v) through/near points(:, i, j) = r(u(i),
  !> v(j)) (FITPACK parsur, iopt = 0). periodic(1) (periodic(2)): the surface
  !> closes in u (v) with period u(mu)-u(1) (v(mv)-v(1)); then the points of the
  !> last grid line must equal those of the first.
  function fit_parametric(u, v, points, smoothing, periodic, status) result(surf)
    real(wp), intent(in) :: u(:), v(:), points(:, :, :)
    real(wp), intent(in) :: smoothing
    logical, intent(in) :: periodic(2)
    type(status_t), intent(out) :: status
    type(spline_surface_t) :: surf
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
  end function fit_parametric

  !> Value and all partial derivatives up to third order (up to `order`, 0..3,
  !> if present; the others stay zero, the ones formed have the same bits) at
  !> (u, v). Outside
  !> the domain of a non-periodic direction the surface is evaluated at the
  !> nearest boundary point and status is STATUS_DOMAIN; periodic directions
  !> wrap around. Allocates nothing (except a message on failure); a scalar
  !> surface (dim = 1) costs one component's work, the others stay zero.
  pure subroutine evaluate(self, u, v, p, status, order)
    class(spline_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    type(spline_surface_eval_t), intent(out) :: p
    type(status_t), intent(out) :: status
    integer, intent(in), optional :: order
    real(wp) :: g(0:3, 0:max_degree), uu, vv
    integer :: lu, lv, l, top
    logical :: outside
    if (self%dim == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline surface: evaluated before a successful fit')
      return
    end if
    top = 3
    if (present(order)) top = max(0, min(3, order))
    p%dim = self%dim
    outside = .false.
    call locate(self%tu, self%ku, self%periodic(1), u, uu, lu, outside)
    call locate(self%tv, self%kv, self%periodic(2), v, vv, lv, outside)
    do l = 1, self%dim
      call u_shift(self%taylor(:, :, l, lu, lv), self%ku, self%kv, uu - self%tu(lu), top, g)
      call v_shift(g, self%kv, vv - self%tv(lv), top, l, p)
    end do
    if (outside) call set_status(status, STATUS_DOMAIN, &
      'spline surface: point outside the parameter domain, evaluated at the nearest boundary point')
  end subroutine evaluate

  !> evaluate() on the grid u(1..nu) x v(1..nv): p(i, j) at (u(i), v(j)),
  !> equal to evaluate's result to the last bit (the same operations in the
  !> same order). The Taylor shifts along u are made once per u line and
  !> patch column the grid touches; per point only the shifts along v remain.
  !> Work tables are allocated once per call. status as evaluate's,
  !> STATUS_DOMAIN if any point lies outside. p is intent(inout) only so that
  !> the compiler does not default-initialize every record before it is
  !> overwritten (a fifth of the time on a 10^6-point grid): every component
  !> of every p(i, j) is written (unused components zero), p is never read; on
  !> invalid input (unfitted surface, wrong shape) p is left as it was.
  pure subroutine evaluate_grid(self, u, v, p, status)
    class(spline_surface_t), intent(in) :: self
    real(wp), intent(in) :: u(:), v(:)
    type(spline_surface_eval_t), intent(inout) :: p(:, :)
    type(status_t), intent(out) :: status
    ! u lines per block: the u shifts of a block stay in cache while the
    ! block's points p(ib:ie, j) are written contiguously, j = 1..nv
    integer, parameter :: block = 16
    real(wp), allocatable :: g(:, :, :, :, :), hv(:)
    integer, allocatable :: lv(:), lu(:), spans(:)
    logical, allocatable :: used(:)
    type(spline_surface_eval_t) :: q
    real(wp) :: uu, vv, hu
    integer :: nu, nv, i, j, l, ib, ie, nb, n, m
    logical :: outside
    if (self%dim == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline surface: evaluated before a successful fit')
      return
    end if
    nu = size(u)
    nv = size(v)
    if (size(p, 1) /= nu .or. size(p, 2) /= nv) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline surface: evaluate_grid needs p(size(u), size(v))')
      return
    end if
    if (nu == 0 .or. nv == 0) return
    outside = .false.
    nb = min(block, nu)
    allocate (hv(nv), lv(nv), lu(nb), used(lbound(self%taylor, 5):ubound(self%taylor, 5)))
    allocate (g(0:3, 0:max_degree, self%dim, lbound(self%taylor, 5):ubound(self%taylor, 5), nb))
    ! the v knot spans once per v line, and which of them the grid touches
    used = .false.
    do j = 1, nv
      call locate(self%tv, self%kv, self%periodic(2), v(j), vv, lv(j), outside)
      hv(j) = vv - self%tv(lv(j))
      used(lv(j)) = .true.
    end do
    spans = pack([(j, j = lbound(used, 1), ubound(used, 1))], used)
    q%dim = self%dim       ! components above dim stay zero
    do ib = 1, nu, nb
      ie = min(nu, ib + nb - 1)
      ! the u shifts once per u line and touched patch column
      do i = ib, ie
        n = i - ib + 1
        call locate(self%tu, self%ku, self%periodic(1), u(i), uu, lu(n), outside)
        hu = uu - self%tu(lu(n))
        do m = 1, size(spans)
          do l = 1, self%dim
            call u_shift(self%taylor(:, :, l, lu(n), spans(m)), self%ku, self%kv, hu, 3, g(:, :, l, spans(m), n))
          end do
        end do
      end do
      do j = 1, nv
        do i = ib, ie
          n = i - ib + 1
          do l = 1, self%dim
            call v_shift(g(:, :, l, lv(j), n), self%kv, hv(j), 3, l, q)
          end do
          p(i, j) = q
        end do
      end do
    end do
    if (outside) call set_status(status, STATUS_DOMAIN, &
      'spline surface: grid points outside the parameter domain, evaluated at the nearest boundary points')
  end subroutine evaluate_grid

  !> [umin, umax, vmin, vmax] of the spline (x, y for a scalar surface).
  pure function domain(self) result(box)
    class(spline_surface_t), intent(in) :: self
    real(wp) :: box(4)
    box = 0
    if (self%dim == 0) return
    box = [self%tu(self%ku + 1), self%tu(size(self%tu) - self%ku), &
           self%tv(self%kv + 1), self%tv(size(self%tv) - self%kv)]
  end function domain

  elemental logical function is_fitted(self)
    class(spline_surface_t), intent(in) :: self
    is_fitted = self%dim > 0
  end function is_fitted

  !> 1 for z = s(x,y), 3 for a parametric surface r(u,v).
  elemental integer function surface_dimension(self)
    class(spline_surface_t), intent(in) :: self
    surface_dimension = self%dim
  end function surface_dimension

  pure function degrees(self) result(k)
    class(spline_surface_t), intent(in) :: self
    integer :: k(2)
    k = [self%ku, self%kv]
  end function degrees

  !> FITPACK's fp: the weighted sum of squared residuals of the fit.
  elemental real(wp) function residual(self)
    class(spline_surface_t), intent(in) :: self
    residual = self%fp
  end function residual

  !> FITPACK's ier of the fit (0, -1 interpolant, -2 polynomial, < -2 rank).
  elemental integer function fitpack_ier(self)
    class(spline_surface_t), intent(in) :: self
    fitpack_ier = self%ier
  end function fitpack_ier

  pure function knots_u(self) result(t)
    class(spline_surface_t), intent(in) :: self
    real(wp), allocatable :: t(:)
    if (allocated(self%tu)) then
      t = self%tu
    else
      allocate (t(0))
    end if
  end function knots_u

  pure function knots_v(self) result(t)
    class(spline_surface_t), intent(in) :: self
    real(wp), allocatable :: t(:)
    if (allocated(self%tv)) then
      t = self%tv
    else
      allocate (t(0))
    end if
  end function knots_v

  !> The B-spline coefficients c(i, j, l): i along u (x), j along v (y),
  !> l = 1..dim; FITPACK's layout is c(:, :, l) flattened with j fastest.
  pure function coefficients(self) result(c)
    class(spline_surface_t), intent(in) :: self
    real(wp), allocatable :: c(:, :, :)
    if (allocated(self%c)) then
      c = self%c
    else
      allocate (c(0, 0, 0))
    end if
  end function coefficients

  ! ---------------------------------------------------------------- private

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

  !> g(r, j) = (1/r!) d^r/du^r of the patch polynomial's coefficient of
  !> (v - tv)^j at hu = u - tu, r = 0..top, j = 0..kv, from the patch's Taylor
  !> coefficients a(0:ku, 0:kv): a Taylor shift (repeated synthetic division)
  !> of each column; orders above ku are zero.
  pure subroutine u_shift(a, ku, kv, hu, top, g)
    real(wp), intent(in) :: a(0:, 0:), hu
    integer, intent(in) :: ku, kv, top
    real(wp), intent(inout) :: g(0:, 0:)
    real(wp) :: b(0:max_degree)
    integer :: j, mt
    mt = min(top, ku)
    do j = 0, kv
      b(0:ku) = a(0:ku, j)
      call taylor_shift(b, ku, hu, mt)
      g(0:mt, j) = b(0:mt)
      g(mt + 1:top, j) = 0
    end do
  end subroutine u_shift

  !> The Taylor coefficients b(0:k) of a degree-k polynomial about 0 shifted
  !> to h (repeated synthetic division): b(m) = p^(m)(h)/m!, m = 0..mt; the
  !> entries above mt are left partly shifted. Degree 5 in scalars.
  pure subroutine taylor_shift(b, k, h, mt)
    real(wp), intent(inout) :: b(0:max_degree)
    integer, intent(in) :: k, mt
    real(wp), intent(in) :: h
    integer :: m, i
    if (k == 5) then
      call quintic_shift(b, h, mt)
      return
    end if
    do m = 0, mt
      do i = k - 1, m, -1
        b(i) = b(i) + h*b(i + 1)
      end do
    end do
  end subroutine taylor_shift

  !> The Taylor shift for degree 5 (the same
  !> operations in the same order, in scalars): b(m) = p^(m)(h)/m!, m = 0..mt.
  pure subroutine quintic_shift(b, h, mt)
    real(wp), intent(inout) :: b(0:max_degree)
    real(wp), intent(in) :: h
    integer, intent(in) :: mt
    real(wp) :: b0, b1, b2, b3, b4, b5
    b0 = b(0)
    b1 = b(1)
    b2 = b(2)
    b3 = b(3)
    b4 = b(4)
    b5 = b(5)
    b4 = b4 + h*b5
    b3 = b3 + h*b4
    b2 = b2 + h*b3
    b1 = b1 + h*b2
    b(0) = b0 + h*b1
    if (mt < 1) return
    b4 = b4 + h*b5
    b3 = b3 + h*b4
    b2 = b2 + h*b3
    b(1) = b1 + h*b2
    if (mt < 2) return
    b4 = b4 + h*b5
    b3 = b3 + h*b4
    b(2) = b2 + h*b3
    if (mt < 3) return
    b4 = b4 + h*b5
    b(3) = b3 + h*b4
    if (mt < 4) return
    b(4) = b4 + h*b5
  end subroutine quintic_shift

  !> Component l of the partials of total order 0..top at hv = v - tv from
  !> the u-shifted columns g (u_shift): a Taylor shift along v of each row
  !> g(r, :), times r! s!. The partials above top are left as they were.
  pure subroutine v_shift(g, kv, hv, top, l, p)
    real(wp), intent(in) :: g(0:, 0:), hv
    integer, intent(in) :: kv, top, l
    type(spline_surface_eval_t), intent(inout) :: p
    real(wp) :: b(0:max_degree), d(0:3, 0:3)
    integer :: r, m, mt
    d = 0
    do r = 0, top
      b(0:kv) = g(r, 0:kv)
      mt = min(top - r, kv)
      call taylor_shift(b, kv, hv, mt)
      do m = 0, mt
        d(r, m) = (factorial(r)*factorial(m))*b(m)
      end do
    end do
    p%f(l) = d(0, 0)
    if (top < 1) return
    p%fu(l) = d(1, 0)
    p%fv(l) = d(0, 1)
    if (top < 2) return
    p%fuu(l) = d(2, 0)
    p%fuv(l) = d(1, 1)
    p%fvv(l) = d(0, 2)
    if (top < 3) return
    p%fuuu(l) = d(3, 0)
    p%fuuv(l) = d(2, 1)
    p%fuvv(l) = d(1, 2)
    p%fvvv(l) = d(0, 3)
  end subroutine v_shift

  !> Knot interval t(l) <= x' < t(l+1), k+1 <= l <= n-k-1, of x clamped to
  !> (or, periodic, wrapped into) [t(k+1), t(n-k)], by bisection.
  pure subroutine locate(t, k, periodic, x, xc, l, outside)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: k
    logical, intent(in) :: periodic
    real(wp), intent(out) :: xc
    integer, intent(out) :: l
    logical, intent(inout) :: outside
    real(wp) :: tb, te
    integer :: lo, hi, mid, n
    n = size(t)
    tb = t(k + 1)
    te = t(n - k)
    xc = x
    if (periodic) then
      if (xc < tb .or. xc > te) xc = tb + modulo(xc - tb, te - tb)
    else if (xc < tb) then
      xc = tb
      outside = outside .or. x < tb - 1.0e-12_wp*(te - tb)
    else if (xc > te) then
      xc = te
      outside = outside .or. x > te + 1.0e-12_wp*(te - tb)
    end if
    lo = k + 1
    hi = n - k
    ! invariant t(lo) <= xc < t(hi) (or xc = te with hi = n-k)
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (xc >= t(mid)) then
        lo = mid
      else
        hi = mid
      end if
    end do
    l = lo
    ! a multiple knot at the end of the domain: back to the span that ends there
    do while (.not. t(l + 1) > t(l) .and. l > k + 1)
      l = l - 1
    end do
  end subroutine locate

  !> d(r, i): r-th derivative (r = 0..k) of the k+1 B-splines of degree k that
  !> do not vanish on [t(l), t(l+1)), at x. The Cox-de Boor recurrence gives
  !> the values of degrees 0..k; the m-th derivative of degree k then follows
  !> from the values of degree k-m by m steps of
  !>   B'_{i,p} = p (B_{i,p-1}/(t_{i+p} - t_i) - B_{i+1,p-1}/(t_{i+p+1} - t_{i+1}))
  !> applied to the (m-1)-th derivatives of degree p-1 (de Boor, A Practical
  !> Guide to Splines, X.(12)). Every denominator is one of the k(k+1)/2 knot
  !> spans of the recurrence, each inverted once.
  pure subroutine basis_derivatives(t, k, x, l, d)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: k, l
    real(wp), intent(out) :: d(0:max_degree, max_degree + 1)
    ! nd(r, p): the B-spline of degree p starting at knot l-p+r, r = 0..p;
    ! inv(p, r) = 1/(t(l+r+1) - t(l+r+1-p)), positive since the span holds
    ! [t(l), t(l+1)]
    real(wp) :: nd(0:max_degree, 0:max_degree), inv(max_degree, 0:max_degree - 1)
    real(wp) :: left(max_degree), right(max_degree), b(0:max_degree), q(0:max_degree - 1), saved, temp
    integer :: j, r, m, p
    nd(0, 0) = 1
    do j = 1, k
      left(j) = x - t(l + 1 - j)
      right(j) = t(l + j) - x
      saved = 0
      do r = 0, j - 1
        inv(j, r) = 1/(t(l + r + 1) - t(l + r + 1 - j))
        temp = nd(r, j - 1)*inv(j, r)
        nd(r, j) = saved + right(r + 1)*temp
        saved = left(j - r)*temp
      end do
      nd(j, j) = saved
    end do
    d = 0
    d(0, 1:k + 1) = nd(0:k, k)
    do m = 1, k
      ! b: the (p-k+m)-th derivatives of the B-splines of degree p
      b(0:k - m) = nd(0:k - m, k - m)
      do p = k - m + 1, k
        do r = 0, p - 1
          q(r) = p*b(r)*inv(p, r)
        end do
        b(0) = -q(0)
        do r = 1, p - 1
          b(r) = q(r - 1) - q(r)
        end do
        b(p) = q(p - 1)
      end do
      d(m, 1:k + 1) = b(0:k)
    end do
  end subroutine basis_derivatives
end module numerics_spline_surface
