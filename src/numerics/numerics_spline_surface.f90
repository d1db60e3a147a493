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
!> Fitting (the submodule numerics_spline_surface_fit) translates FITPACK's
!> ier in one place (ier_status) into status_t; least-squares polynomials
!> (ier = -2), interpolants (-1) and rank-deficient minimum-norm solutions
!> (ier < -2) are accepted fits.
module numerics_spline_surface
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use numerics_spline_kernels, only: max_degree, factorial, find_interval, taylor_shift
  implicit none (type, external)
  private
  public :: spline_surface_t, spline_surface_eval_t
  public :: fit_scattered, fit_grid, fit_parametric

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

  interface
    !> Smoothing spline z = s(x,y) of degrees kx, ky (1..5) to scattered data
    !> (FITPACK surfit, iopt = 0): sum (w (z - s))^2 <= smoothing within 0.1 %.
    !> weights default to 1; bbox = [xb, xe, yb, ye] defaults to the data range.
    module function fit_scattered(x, y, z, smoothing, kx, ky, status, weights, bbox) result(surf)
      real(wp), intent(in) :: x(:), y(:), z(:)
      real(wp), intent(in) :: smoothing
      integer, intent(in) :: kx, ky
      type(status_t), intent(out) :: status
      real(wp), intent(in), optional :: weights(:), bbox(4)
      type(spline_surface_t) :: surf
    end function fit_scattered

    !> Smoothing spline z = s(x,y) on the grid x(1..mx) x y(1..my) (strictly
    !> increasing), z(i,j) = value at (x(i), y(j)) (FITPACK regrid, iopt = 0).
    module function fit_grid(x, y, z, smoothing, kx, ky, status) result(surf)
      real(wp), intent(in) :: x(:), y(:), z(:, :)
      real(wp), intent(in) :: smoothing
      integer, intent(in) :: kx, ky
      type(status_t), intent(out) :: status
      type(spline_surface_t) :: surf
    end function fit_grid

    !> Bicubic parametric surface r(u,v) through/near points(:, i, j) = r(u(i),
    !> v(j)) (FITPACK parsur, iopt = 0). periodic(1) (periodic(2)): the surface
    !> closes in u (v) with period u(mu)-u(1) (v(mv)-v(1)); then the points of the
    !> last grid line must equal those of the first.
    module function fit_parametric(u, v, points, smoothing, periodic, status) result(surf)
      real(wp), intent(in) :: u(:), v(:), points(:, :, :)
      real(wp), intent(in) :: smoothing
      logical, intent(in) :: periodic(2)
      type(status_t), intent(out) :: status
      type(spline_surface_t) :: surf
    end function fit_parametric
  end interface

contains

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
  !> (or, periodic, wrapped into) [t(k+1), t(n-k)], by find_interval.
  pure subroutine locate(t, k, periodic, x, xc, l, outside)
    real(wp), intent(in) :: t(:), x
    integer, intent(in) :: k
    logical, intent(in) :: periodic
    real(wp), intent(out) :: xc
    integer, intent(out) :: l
    logical, intent(inout) :: outside
    real(wp) :: tb, te
    integer :: n
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
    l = find_interval(t, k, xc)
  end subroutine locate

end module numerics_spline_surface
