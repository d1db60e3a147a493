!> Parametric spline curves r(u) in 1..10 dimensions over our FITPACK
!> (external/fitpack): fitted with a smoothing factor (parcur), closed
!> (clocur), or with prescribed derivatives at the ends (concur, thesis
!> 2.54-2.67). Evaluation returns the point and all derivatives up to a given
!> order without allocating; arc length by Gauss-Legendre quadrature per knot
!> span and its inverse by safeguarded Newton iteration.
!>
!> Evaluation runs on a table made once per fit or set: on each knot span
!> [t(l), t(l+1)) the spline is one polynomial of degree k, stored as its
!> Taylor coefficients r^(j)(t(l)+)/j! (the Cox-de Boor recurrence with de
!> Boor's difference formula at the left knot). A point then costs the knot
!> search and a Taylor shift (Horner, k(k+1)/2 multiply-adds per coordinate
!> for all derivatives) instead of the recurrence's k(k+1)/2 divisions.
!>
!> Fitting is the submodule numerics_spline_curve_fit; the knot search and
!> the Taylor shift are numerics_spline_kernels, shared with the surfaces.
!> FITPACK's ier is translated in one place (ier_status). Interpolants
!> (ier = -1) and least-squares polynomials (ier = -2) are accepted fits; for
!> ier = 1..3 FITPACK still returns a usable approximation, which is kept, but
!> the status reports why it does not meet the smoothing factor.
module numerics_spline_curve
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use numerics_spline_kernels, only: max_degree, factorial, find_interval, taylor_shift
  implicit none (type, external)
  private
  public :: spline_curve_t

  integer, parameter :: max_dimension = 10

  !> 10-point Gauss-Legendre rule on [-1, 1] (positive nodes; symmetric).
  real(wp), parameter :: gl_x(5) = [0.1488743389816312108848260_wp, 0.4333953941292471907992659_wp, &
                                    0.6794095682990244062343274_wp, 0.8650633666889845107320967_wp, &
                                    0.9739065285171717200779640_wp]
  real(wp), parameter :: gl_w(5) = [0.2955242247147528701738930_wp, 0.2692667193099963550912269_wp, &
                                    0.2190863625159820439955349_wp, 0.1494513491505805931457763_wp, &
                                    0.0666713443086881375935688_wp]

  !> A B-spline curve: knots t(1..n), degree k, coefficients c(1..dim, 1..n-k-1).
  !> Closed curves are periodic with period t(n-k) - t(k+1).
  type :: spline_curve_t
    private
    real(wp), allocatable :: knots(:)
    real(wp), allocatable :: coefficients(:, :)
    integer :: degree = 0
    integer :: dimension = 0
    logical :: periodic = .false.
    real(wp) :: fp = 0                     !< weighted residual sum of squares of the fit
    integer :: ier = 0                     !< FITPACK's ier of the fit
    real(wp), allocatable :: cumulative(:) !< arc length at the knots t(k+1..n-k)
    !> taylor(j, :, l) = r^(j)(t(l)+)/j!, j = 0..k, on span l = k+1..n-k-1 (zero on empty spans)
    real(wp), allocatable :: taylor(:, :, :)
  contains
    procedure :: fit
    procedure :: set
    procedure :: evaluate
    procedure :: arc_length
    procedure :: parameter_at_length
    procedure :: total_length
    procedure :: domain
    procedure :: is_fitted
    procedure :: is_periodic
    procedure :: get_degree
    procedure :: get_dimension
    procedure :: get_knots
    procedure :: get_coefficients
    procedure :: residual
    procedure :: fitpack_ier
  end type spline_curve_t

  interface
    !> Fits a spline curve of the given degree (1..5) to points(dim, m).
    !> smoothing is FITPACK's s >= 0 (0 interpolates): sum_i (w_i |p_i - r(u_i)|)**2 <= s.
    !> parameters: u_i, strictly increasing (default: chord length scaled to [0,1]).
    !> weights: w_i > 0 (default 1). start_derivatives(dim, nb), end_derivatives(dim, ne):
    !> column j is the (j-1)-th derivative prescribed at the first / last parameter
    !> (position first); needs an odd degree and nb, ne <= (degree+1)/2 (concur).
    !> Without parameters the derivatives refer to the chord-length parameter on [0,1].
    !> periodic: closed curve (clocur); the first and last point must coincide.
    !> The storage allows the interpolating spline, so FITPACK's ier = 1 cannot occur.
    module subroutine fit(self, points, smoothing, degree, status, parameters, weights, start_derivatives, &
                          end_derivatives, periodic)
      class(spline_curve_t), intent(inout) :: self
      real(wp), intent(in) :: points(:, :)
      real(wp), intent(in) :: smoothing
      integer, intent(in) :: degree
      type(status_t), intent(out) :: status
      real(wp), intent(in), optional :: parameters(:)
      real(wp), intent(in), optional :: weights(:)
      real(wp), intent(in), optional :: start_derivatives(:, :)
      real(wp), intent(in), optional :: end_derivatives(:, :)
      logical, intent(in), optional :: periodic
    end subroutine fit
  end interface

contains

  !> Sets the curve from a B-spline representation: knots(1..n), coefficients(dim, n-degree-1).
  !> For a periodic curve the knots and the last degree coefficients must repeat
  !> as FITPACK's periodic representation has them.
  subroutine set(self, knots, coefficients, degree, status, periodic)
    class(spline_curve_t), intent(inout) :: self
    real(wp), intent(in) :: knots(:), coefficients(:, :)
    integer, intent(in) :: degree
    type(status_t), intent(out) :: status
    logical, intent(in), optional :: periodic
    integer :: n, k
    n = size(knots)
    k = degree
    if (k < 1 .or. k > max_degree) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve: the degree must be 1..5')
      return
    end if
    if (size(coefficients, 1) < 1 .or. size(coefficients, 1) > max_dimension) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve: the dimension must be 1..10')
      return
    end if
    if (n < 2*k + 2 .or. size(coefficients, 2) /= n - k - 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve: need n >= 2k+2 knots and n-k-1 coefficients')
      return
    end if
    if (.not. all(knots(2:n) >= knots(1:n - 1)) .or. .not. (knots(n - k) > knots(k + 1))) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline curve: knots must be non-decreasing, domain non-empty')
      return
    end if
    self%knots = knots
    self%coefficients = coefficients
    self%degree = k
    self%dimension = size(coefficients, 1)
    self%periodic = .false.
    if (present(periodic)) self%periodic = periodic
    self%fp = 0
    self%ier = 0
    call tabulate(self)
  end subroutine set


  !> The parameter mapped into the domain: clamped for open curves (as FITPACK's
  !> evaluators), reduced by the period for closed ones.
  pure real(wp) function in_domain(self, u) result(v)
    class(spline_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: a, b
    a = self%knots(self%degree + 1)
    b = self%knots(size(self%knots) - self%degree)
    if (self%periodic) then
      v = a + modulo(u - a, b - a)
      if (v >= b) v = a
    else
      v = min(max(u, a), b)
    end if
  end function in_domain

  !> derivatives(:, j) = j-th derivative of r at u, j = 0..nd (zero above the
  !> degree); derivatives should have dimension rows and nd+1 columns (only
  !> what fits is filled). Open curves clamp u to the domain (as FITPACK's
  !> evaluators), closed ones reduce it by the period. A point on an interior
  !> knot gets the right-hand derivatives. No allocation.
  pure subroutine evaluate(self, u, derivatives, nd)
    class(spline_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: derivatives(:, 0:)
    integer, intent(in) :: nd
    real(wp) :: x, b(0:max_degree)
    integer :: l, idim, k, top, i
    if (.not. allocated(self%knots)) then
      derivatives = 0
      return
    end if
    k = self%degree
    idim = min(self%dimension, size(derivatives, 1))
    top = max(-1, min(nd, k, ubound(derivatives, 2)))
    x = in_domain(self, u)
    l = find_interval(self%knots, k, x)
    do i = 1, idim
      b(0:k) = self%taylor(0:k, i, l)
      call taylor_shift(b, k, x - self%knots(l), top)
      derivatives(i, 0:top) = factorial(0:top)*b(0:top)
    end do
    ! what was not formed: orders above top, coordinates above the curve's
    if (ubound(derivatives, 2) > top) derivatives(:, top + 1:) = 0
    if (size(derivatives, 1) > idim) derivatives(idim + 1:, 0:top) = 0
  end subroutine evaluate



  !> The Cox-de Boor triangle (thesis 2.35) and de Boor's difference formula
  !> for the derivatives: d(1:dim, jd) = r^(jd)(x), jd = 0..k, with x in knot
  !> span l. Builds the Taylor table (evaluate itself reads the table).
  pure subroutine de_boor(self, l, x, d)
    type(spline_curve_t), intent(in) :: self
    integer, intent(in) :: l
    real(wp), intent(in) :: x
    real(wp), intent(out) :: d(:, 0:)
    real(wp) :: v(max_dimension, max_degree + 1), basis(max_degree + 1, 0:max_degree), hh(max_degree + 1)
    real(wp) :: f, ak, fac
    integer :: k, k1, lk, dg, i, j, jd, li, lj, idim
    k = self%degree
    k1 = k + 1
    idim = self%dimension
    lk = l - k1
    associate (t => self%knots)
      basis(1, 0) = 1
      do dg = 1, k
        hh(1:dg) = basis(1:dg, dg - 1)
        basis(1, dg) = 0
        do i = 1, dg
          li = l + i
          lj = li - dg
          if (t(li) == t(lj)) then
            basis(i + 1, dg) = 0
          else
            f = hh(i)/(t(li) - t(lj))
            basis(i, dg) = basis(i, dg) + f*(t(li) - x)
            basis(i + 1, dg) = f*(x - t(lj))
          end if
        end do
      end do
      v(1:idim, 1:k1) = self%coefficients(1:idim, lk + 1:lk + k1)
      do jd = 0, k
        if (jd > 0) then
          ak = k - jd + 1
          do i = 1, k1 - jd
            fac = t(lk + i + k1) - t(lk + i + jd)
            if (fac > 0) then
              v(1:idim, i) = ak*(v(1:idim, i + 1) - v(1:idim, i))/fac
            end if
          end do
        end if
        do j = 1, idim
          d(j, jd) = sum(v(j, 1:k1 - jd)*basis(1:k1 - jd, k - jd))
        end do
      end do
    end associate
  end subroutine de_boor

  !> |r'(x)| for x in knot span l (Horner on the derivative), the arc-length integrand.
  pure real(wp) function span_speed(self, l, x) result(sp)
    class(spline_curve_t), intent(in) :: self
    integer, intent(in) :: l
    real(wp), intent(in) :: x
    real(wp) :: h, r
    integer :: i, j, k
    k = self%degree
    h = x - self%knots(l)
    if (k == 5 .and. self%dimension == 3) then
      sp = sqrt(sum(quintic_velocity(self%taylor(:, :, l), h)**2))
      return
    end if
    sp = 0
    do i = 1, self%dimension
      r = k*self%taylor(k, i, l)
      do j = k - 1, 1, -1
        r = j*self%taylor(j, i, l) + h*r
      end do
      sp = sp + r*r
    end do
    sp = sqrt(sp)
  end function span_speed

  !> r'(h) of a quintic in space with Taylor coefficients a about 0.
  pure function quintic_velocity(a, h) result(r)
    real(wp), intent(in) :: a(0:5, 3), h
    real(wp) :: r(3)
    r = a(1, :) + h*(2*a(2, :) + h*(3*a(3, :) + h*(4*a(4, :) + h*(5*a(5, :)))))
  end function quintic_velocity

  !> Arc length from a to b inside knot span l (10-point Gauss-Legendre).
  pure real(wp) function span_length(self, l, a, b) result(s)
    class(spline_curve_t), intent(in) :: self
    integer, intent(in) :: l
    real(wp), intent(in) :: a, b
    real(wp) :: mid, half
    integer :: i
    mid = 0.5_wp*(a + b)
    half = 0.5_wp*(b - a)
    s = 0
    do i = 1, 5
      s = s + gl_w(i)*(span_speed(self, l, mid - half*gl_x(i)) + span_speed(self, l, mid + half*gl_x(i)))
    end do
    s = s*half
  end function span_length

  !> The Taylor table of every non-empty knot span and the arc length at the knots.
  subroutine tabulate(self)
    type(spline_curve_t), intent(inout) :: self
    real(wp) :: d(max_dimension, 0:max_degree)
    integer :: k, n, l, j
    k = self%degree
    n = size(self%knots)
    if (allocated(self%taylor)) deallocate (self%taylor)
    allocate (self%taylor(0:k, self%dimension, k + 1:n - k - 1))
    self%taylor = 0
    do l = k + 1, n - k - 1
      if (self%knots(l + 1) > self%knots(l)) then
        call de_boor(self, l, self%knots(l), d)
        do j = 0, k
          self%taylor(j, :, l) = d(1:self%dimension, j)/factorial(j)
        end do
      end if
    end do
    if (allocated(self%cumulative)) deallocate (self%cumulative)
    allocate (self%cumulative(k + 1:n - k))
    self%cumulative(k + 1) = 0
    do l = k + 1, n - k - 1
      self%cumulative(l + 1) = self%cumulative(l)
      if (self%knots(l + 1) > self%knots(l)) &
        self%cumulative(l + 1) = self%cumulative(l) + span_length(self, l, self%knots(l), self%knots(l + 1))
    end do
  end subroutine tabulate

  !> Arc length from the start of the domain to u (for a closed curve, u may
  !> lie outside one period: whole periods count once each; open curves clamp u).
  pure real(wp) function arc_length(self, u) result(s)
    class(spline_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: x, a, b
    integer :: l, k
    s = 0
    if (.not. allocated(self%knots)) return
    k = self%degree
    a = self%knots(k + 1)
    b = self%knots(size(self%knots) - k)
    x = in_domain(self, u)
    l = find_interval(self%knots, k, x)
    s = self%cumulative(l) + span_length(self, l, self%knots(l), x)
    if (self%periodic) s = s + floor((u - a)/(b - a))*self%total_length()
  end function arc_length

  !> Total arc length over the domain (one period for a closed curve).
  pure real(wp) function total_length(self) result(s)
    class(spline_curve_t), intent(in) :: self
    s = 0
    if (allocated(self%cumulative)) s = self%cumulative(ubound(self%cumulative, 1))
  end function total_length

  !> The parameter u with arc_length(u) = s: the knot span from the table, then
  !> Newton on the span's arc length with bisection as safeguard. s is clamped
  !> to [0, total] for open curves and reduced by the total for closed ones.
  pure real(wp) function parameter_at_length(self, s) result(u)
    class(spline_curve_t), intent(in) :: self
    real(wp), intent(in) :: s
    real(wp) :: total, target, lo, hi, g, dg, a, b, shift, start
    integer :: k, l, lo_i, hi_i, mid, it
    u = 0
    if (.not. allocated(self%knots)) return
    k = self%degree
    a = self%knots(k + 1)
    b = self%knots(size(self%knots) - k)
    total = self%total_length()
    shift = 0
    if (self%periodic .and. total > 0) then
      shift = floor(s/total)*(b - a)
      target = s - floor(s/total)*total
    else
      target = min(max(s, 0.0_wp), total)
    end if
    if (total <= 0) then
      u = a
      return
    end if
    ! span: largest l with cumulative(l) <= target
    lo_i = k + 1
    hi_i = size(self%knots) - k
    do while (hi_i - lo_i > 1)
      mid = (lo_i + hi_i)/2
      if (self%cumulative(mid) <= target) then
        lo_i = mid
      else
        hi_i = mid
      end if
    end do
    l = lo_i
    lo = self%knots(l)
    hi = self%knots(l + 1)
    start = lo
    target = target - self%cumulative(l)
    u = lo + (hi - lo)*target/max(self%cumulative(l + 1) - self%cumulative(l), tiny(1.0_wp))
    u = min(max(u, lo), hi)
    do it = 1, 60
      g = span_length(self, l, start, u) - target
      if (abs(g) <= 4*epsilon(1.0_wp)*total) exit
      if (g > 0) then
        hi = u
      else
        lo = u
      end if
      dg = span_speed(self, l, u)
      if (dg > 0) then
        u = u - g/dg
      else
        u = 0.5_wp*(lo + hi)
      end if
      if (.not. (u > lo .and. u < hi)) u = 0.5_wp*(lo + hi)
      if (hi - lo <= 4*epsilon(1.0_wp)*max(abs(lo), abs(hi))) exit
    end do
    u = u + shift
  end function parameter_at_length

  !> [t(k+1), t(n-k)]: the parameter range of the curve.
  pure function domain(self) result(d)
    class(spline_curve_t), intent(in) :: self
    real(wp) :: d(2)
    d = 0
    if (.not. allocated(self%knots)) return
    d = [self%knots(self%degree + 1), self%knots(size(self%knots) - self%degree)]
  end function domain

  pure logical function is_fitted(self)
    class(spline_curve_t), intent(in) :: self
    is_fitted = allocated(self%knots)
  end function is_fitted

  pure logical function is_periodic(self)
    class(spline_curve_t), intent(in) :: self
    is_periodic = self%periodic
  end function is_periodic

  pure integer function get_degree(self)
    class(spline_curve_t), intent(in) :: self
    get_degree = self%degree
  end function get_degree

  pure integer function get_dimension(self)
    class(spline_curve_t), intent(in) :: self
    get_dimension = self%dimension
  end function get_dimension

  !> The knots t(1..n) (empty before a fit).
  pure function get_knots(self) result(t)
    class(spline_curve_t), intent(in) :: self
    real(wp), allocatable :: t(:)
    if (allocated(self%knots)) then
      t = self%knots
    else
      allocate (t(0))
    end if
  end function get_knots

  !> The coefficients c(1..dim, 1..n-k-1) (empty before a fit).
  pure function get_coefficients(self) result(c)
    class(spline_curve_t), intent(in) :: self
    real(wp), allocatable :: c(:, :)
    if (allocated(self%coefficients)) then
      c = self%coefficients
    else
      allocate (c(0, 0))
    end if
  end function get_coefficients

  !> Weighted residual sum of squares fp of the fit.
  pure real(wp) function residual(self)
    class(spline_curve_t), intent(in) :: self
    residual = self%fp
  end function residual

  !> FITPACK's ier of the last fit (0, -1 interpolating, -2 polynomial, 1..3 see status).
  pure integer function fitpack_ier(self)
    class(spline_curve_t), intent(in) :: self
    fitpack_ier = self%ier
  end function fitpack_ier
end module numerics_spline_curve
