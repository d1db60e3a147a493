!> Spline surfaces over our FITPACK (external/fitpack): a scalar surface
!> z = s(x,y) fitted to scattered data (surfit) or to a grid (regrid), or a
!> parametric surface r(u,v) in 3-D fitted to a grid of points (parsur, bicubic,
!> optionally periodic in u and/or v). One call evaluates the value and all
!> partial derivatives up to third order, without allocation.
!>
!> Fitting translates FITPACK's ier in one place (ier_status) into status_t;
!> least-squares polynomials (ier = -2), interpolants (-1) and rank-deficient
!> minimum-norm solutions (ier < -2) are accepted fits.
module numerics_spline_surface
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT, STATUS_DOMAIN, &
    STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL
  use fitpack_surface_interfaces, only: surfit, regrid, parsur
  implicit none (type, external)
  private
  public :: spline_surface_t, spline_surface_eval_t
  public :: fit_scattered, fit_grid, fit_parametric

  integer, parameter :: max_degree = 5

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
      call set_status(status, STATUS_INVALID_INPUT, 'fit_scattered: fewer data points than (kx+1)(ky+1)')
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
    real(wp) :: du(0:3, max_degree + 1), dv(0:3, max_degree + 1), w(0:3, max_degree + 1), uu, vv
    integer :: lu, lv, l, ku1, kv1, top
    logical :: outside
    if (self%dim == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline surface: evaluated before a successful fit')
      return
    end if
    top = 3
    if (present(order)) top = max(0, min(3, order))
    p%dim = self%dim
    ku1 = self%ku + 1
    kv1 = self%kv + 1
    outside = .false.
    call locate(self%tu, self%ku, self%periodic(1), u, uu, lu, outside)
    call locate(self%tv, self%kv, self%periodic(2), v, vv, lv, outside)
    call basis_derivatives(self%tu, self%ku, uu, lu, du, top)
    call basis_derivatives(self%tv, self%kv, vv, lv, dv, top)
    do l = 1, self%dim
      if (top == 3) then
        call column_partials(self%c(:, :, l), ku1, lu - ku1, lv - kv1 + 1, lv, du, w)
        call contract(kv1, w, 0, dv, l, p)
      else
        call column_partials_to(top, self%c(:, :, l), ku1, lu - ku1, lv - kv1 + 1, lv, du, w)
        call contract_to(top, kv1, w, dv, l, p)
      end if
    end do
    if (outside) call set_status(status, STATUS_DOMAIN, &
      'spline surface: point outside the parameter domain, evaluated at the nearest boundary point')
  end subroutine evaluate

  !> evaluate() on the grid u(1..nu) x v(1..nv): p(i, j) at (u(i), v(j)),
  !> equal to evaluate's result to the last bit (the same sums in the same
  !> order). The B-splines and their derivatives are computed once per grid
  !> line; the u-partials of the coefficient columns the grid touches once per
  !> u line; per point only the v contraction remains (10 (kv+1) products per
  !> component, only the dim components of the surface). Work tables are
  !> allocated once per call. status as evaluate's, STATUS_DOMAIN if any point
  !> lies outside. p is intent(inout) only so that the compiler does not
  !> default-initialize every record before it is overwritten (a fifth of the
  !> time on a 10^6-point grid): every component of every p(i, j) is written
  !> (unused components zero), p is never read; on invalid input (unfitted
  !> surface, wrong shape) p is left as it was.
  pure subroutine evaluate_grid(self, u, v, p, status)
    class(spline_surface_t), intent(in) :: self
    real(wp), intent(in) :: u(:), v(:)
    type(spline_surface_eval_t), intent(inout) :: p(:, :)
    type(status_t), intent(out) :: status
    ! u lines per block: the u-partials of a block stay in cache while the
    ! block's points p(ib:ie, j) are written contiguously, j = 1..nv
    integer, parameter :: block = 16
    real(wp), allocatable :: bv(:, :, :), w(:, :, :, :)
    integer, allocatable :: lv(:), cols(:), lu(:)
    logical, allocatable :: used(:)
    type(spline_surface_eval_t) :: q
    real(wp) :: du(0:3, max_degree + 1), dv(0:3, max_degree + 1), uu, vv
    integer :: nu, nv, ncv, ku1, kv1, i, j, l, ib, ie, nb, n
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
    ku1 = self%ku + 1
    kv1 = self%kv + 1
    ncv = size(self%c, 2)
    nb = min(block, nu)
    allocate (bv(0:3, kv1, nv), lv(nv), used(ncv), w(0:3, ncv, self%dim, nb), lu(nb))
    ! v B-splines once per v line; the coefficient columns they touch
    used = .false.
    do j = 1, nv
      call locate(self%tv, self%kv, self%periodic(2), v(j), vv, lv(j), outside)
      call basis_derivatives(self%tv, self%kv, vv, lv(j), dv)
      bv(:, :, j) = dv(:, 1:kv1)
      used(lv(j) - kv1 + 1:lv(j)) = .true.
    end do
    cols = pack([(j, j = 1, ncv)], used)
    q%dim = self%dim       ! components above dim stay zero
    do ib = 1, nu, nb
      ie = min(nu, ib + nb - 1)
      ! u B-splines once per u line, contracted with the used columns
      do i = ib, ie
        n = i - ib + 1
        call locate(self%tu, self%ku, self%periodic(1), u(i), uu, lu(n), outside)
        call basis_derivatives(self%tu, self%ku, uu, lu(n), du)
        do l = 1, self%dim
          do j = 1, size(cols)
            call column_partials(self%c(:, :, l), ku1, lu(n) - ku1, cols(j), cols(j), du, w(:, cols(j):, l, n))
          end do
        end do
      end do
      do j = 1, nv
        do i = ib, ie
          n = i - ib + 1
          do l = 1, self%dim
            call contract(kv1, w(:, :, l, n), lv(j) - kv1, bv(:, :, j), l, q)
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
  end subroutine store

  !> w(a, j - j1 + 1) = sum_i du(a, i) c(i0 + i, j), j = j1..j2: the u-partials
  !> (order a = 0..3) of the coefficient columns j1..j2 at the u point whose
  !> nonzero B-splines (with derivatives) are du(:, 1..ku1).
  pure subroutine column_partials(c, ku1, i0, j1, j2, du, w)
    real(wp), intent(in) :: c(:, :), du(0:3, max_degree + 1)
    integer, intent(in) :: ku1, i0, j1, j2
    real(wp), intent(inout) :: w(0:, :)
    integer :: i, j
    do j = j1, j2
      w(:, j - j1 + 1) = 0
      do i = 1, ku1
        w(:, j - j1 + 1) = w(:, j - j1 + 1) + du(:, i)*c(i0 + i, j)
      end do
    end do
  end subroutine column_partials

  !> Component l of the ten partials at one point: s(a, b) = sum_j w(a, j0 + j)
  !> dv(b, j), j = 1..kv1, from the u-partials w of the coefficient columns
  !> and the v B-splines dv (with derivatives) of the point.
  pure subroutine contract(kv1, w, j0, dv, l, p)
    integer, intent(in) :: kv1, j0, l
    real(wp), intent(in) :: w(0:, :), dv(0:, :)
    type(spline_surface_eval_t), intent(inout) :: p
    real(wp) :: s00, s10, s01, s20, s11, s02, s30, s21, s12, s03, w0, w1, w2, w3
    integer :: j
    s00 = 0
    s10 = 0
    s01 = 0
    s20 = 0
    s11 = 0
    s02 = 0
    s30 = 0
    s21 = 0
    s12 = 0
    s03 = 0
    do j = 1, kv1
      w0 = w(0, j0 + j)
      w1 = w(1, j0 + j)
      w2 = w(2, j0 + j)
      w3 = w(3, j0 + j)
      s00 = s00 + w0*dv(0, j)
      s01 = s01 + w0*dv(1, j)
      s02 = s02 + w0*dv(2, j)
      s03 = s03 + w0*dv(3, j)
      s10 = s10 + w1*dv(0, j)
      s11 = s11 + w1*dv(1, j)
      s12 = s12 + w1*dv(2, j)
      s20 = s20 + w2*dv(0, j)
      s21 = s21 + w2*dv(1, j)
      s30 = s30 + w3*dv(0, j)
    end do
    p%f(l) = s00
    p%fu(l) = s10
    p%fv(l) = s01
    p%fuu(l) = s20
    p%fuv(l) = s11
    p%fvv(l) = s02
    p%fuuu(l) = s30
    p%fuuv(l) = s21
    p%fuvv(l) = s12
    p%fvvv(l) = s03
  end subroutine contract

  !> column_partials for the u-derivatives 0..top only (top < 3; the same
  !> sums in the same order, in scalars: the hot position passes ask for top = 1).
  pure subroutine column_partials_to(top, c, ku1, i0, j1, j2, du, w)
    integer, intent(in) :: top, ku1, i0, j1, j2
    real(wp), intent(in) :: c(:, :), du(0:3, max_degree + 1)
    real(wp), intent(inout) :: w(0:, :)
    real(wp) :: s0, s1, s2, cij
    integer :: i, j
    do j = j1, j2
      s0 = 0; s1 = 0; s2 = 0
      select case (top)
      case (0)
        do i = 1, ku1
          s0 = s0 + du(0, i)*c(i0 + i, j)
        end do
      case (1)
        do i = 1, ku1
          cij = c(i0 + i, j)
          s0 = s0 + du(0, i)*cij
          s1 = s1 + du(1, i)*cij
        end do
      case default
        do i = 1, ku1
          cij = c(i0 + i, j)
          s0 = s0 + du(0, i)*cij
          s1 = s1 + du(1, i)*cij
          s2 = s2 + du(2, i)*cij
        end do
      end select
      w(0, j - j1 + 1) = s0
      w(1, j - j1 + 1) = s1
      w(2, j - j1 + 1) = s2
    end do
  end subroutine column_partials_to

  !> contract for the partials of total order 0..top only (top < 3; the same
  !> sums in the same order, the others left as they were).
  pure subroutine contract_to(top, kv1, w, dv, l, p)
    integer, intent(in) :: top, kv1, l
    real(wp), intent(in) :: w(0:, :), dv(0:, :)
    type(spline_surface_eval_t), intent(inout) :: p
    real(wp) :: s00, s10, s01, s20, s11, s02
    integer :: j
    s00 = 0; s10 = 0; s01 = 0; s20 = 0; s11 = 0; s02 = 0
    select case (top)
    case (0)
      do j = 1, kv1
        s00 = s00 + w(0, j)*dv(0, j)
      end do
    case (1)
      do j = 1, kv1
        s00 = s00 + w(0, j)*dv(0, j)
        s01 = s01 + w(0, j)*dv(1, j)
        s10 = s10 + w(1, j)*dv(0, j)
      end do
    case default
      do j = 1, kv1
        s00 = s00 + w(0, j)*dv(0, j)
        s01 = s01 + w(0, j)*dv(1, j)
        s02 = s02 + w(0, j)*dv(2, j)
        s10 = s10 + w(1, j)*dv(0, j)
        s11 = s11 + w(1, j)*dv(1, j)
        s20 = s20 + w(2, j)*dv(0, j)
      end do
    end select
    p%f(l) = s00
    if (top < 1) return
    p%fu(l) = s10
    p%fv(l) = s01
    if (top < 2) return
    p%fuu(l) = s20
    p%fuv(l) = s11
    p%fvv(l) = s02
  end subroutine contract_to

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
  end subroutine locate

  !> d(r, i): r-th derivative (r = 0..3) of the k+1 B-splines of degree k that
  !> do not vanish on [t(l), t(l+1)), at x. The Cox-de Boor recurrence gives
  !> the values of degrees 0..k; the m-th derivative of degree k then follows
  !> from the values of degree k-m by m steps of
  !>   B'_{i,p} = p (B_{i,p-1}/(t_{i+p} - t_i) - B_{i+1,p-1}/(t_{i+p+1} - t_{i+1}))
  !> applied to the (m-1)-th derivatives of degree p-1 (de Boor, A Practical
  !> Guide to Splines, X.(12)). Every denominator is one of the k(k+1)/2 knot
  !> spans of the recurrence, each inverted once.
  pure subroutine basis_derivatives(t, k, x, l, d, order)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: k, l
    real(wp), intent(out) :: d(0:3, max_degree + 1)
    integer, intent(in), optional :: order   ! derivatives up to this one (default 3), the others zero
    ! nd(r, p): the B-spline of degree p starting at knot l-p+r, r = 0..p;
    ! inv(p, r) = 1/(t(l+r+1) - t(l+r+1-p)), positive since the span holds
    ! [t(l), t(l+1)]
    real(wp) :: nd(0:max_degree, 0:max_degree), inv(max_degree, 0:max_degree - 1)
    real(wp) :: left(max_degree), right(max_degree), b(0:max_degree), q(0:max_degree - 1), saved, temp
    integer :: j, r, m, p, top
    top = 3
    if (present(order)) top = order
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
    do m = 1, min(top, k)
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
