!> The curve seam: a parametrised space curve c(u) with derivatives to 4th order.
!>
!> Tube surfaces (thesis 3.64, appendix C) need the centerline to 4th order:
!> the 3rd u-derivative of the tangent axis x = c_u/|c_u| (C.6) contains c_uuuu.
!> A horizon field h(u) is a curve too (only derivatives to 3rd order are used).
!>
!> Concrete analytic curves (line, helix/circle arc, constant vector) live here;
!> spline curves plug in through geometry_spline_centerline. Arc length
!> (thesis 2.1) and its inverse are provided for every curve by composite
!> Gauss-Legendre quadrature of |c_u| and a safeguarded Newton iteration.
module geometry_curve
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_OK, STATUS_DOMAIN, &
                         STATUS_NOT_CONVERGED, STATUS_INVALID_INPUT
  use numerics_spline_curve, only: spline_curve_t
  use numerics_quadrature, only: gl8_x, gl8_w
  implicit none (type, external)
  private
  public :: curve_t, curve_point_t, line_curve_t, helix_curve_t, constant_curve_t, polynomial_curve_t, &
            s_bend_curve_t
  public :: curve_max_order, spline_centerline_t, new_spline_centerline
  public :: panel_arc_length, arc_length_prefix

  integer, parameter :: curve_max_order = 4

  !> c(u) and its u-derivatives: d(:, k) = d^k c / du^k, filled up to `order`.
  type :: curve_point_t
    integer :: order = 0
    real(wp) :: d(3, 0:curve_max_order) = 0
  end type curve_point_t

  type, abstract :: curve_t
  contains
    procedure(curve_evaluate_i), deferred :: evaluate
    procedure(curve_domain_i), deferred :: domain
    procedure :: arc_length => curve_arc_length
    procedure :: speed => curve_speed
    procedure :: total_length => curve_total_length
    procedure :: parameter_at_length => curve_parameter_at_length
    procedure :: parameter_unit => curve_parameter_unit
  end type curve_t

  abstract interface
    !> Fills p with c(u) and its derivatives up to `order` (0..4).
    pure subroutine curve_evaluate_i(self, u, order, p, status)
      import :: curve_t, curve_point_t, status_t, wp
      class(curve_t), intent(in) :: self
      real(wp), intent(in) :: u
      integer, intent(in) :: order
      type(curve_point_t), intent(out) :: p
      type(status_t), intent(out) :: status
    end subroutine curve_evaluate_i
    !> The parameter interval [u_min, u_max] of the curve.
    pure subroutine curve_domain_i(self, u_min, u_max)
      import :: curve_t, wp
      class(curve_t), intent(in) :: self
      real(wp), intent(out) :: u_min, u_max
    end subroutine curve_domain_i
  end interface

  !> Straight line c(u) = origin + u direction, u in [u_min, u_max].
  type, extends(curve_t) :: line_curve_t
    real(wp) :: origin(3) = 0          ! m
    real(wp) :: direction(3) = [1, 0, 0]  ! m per unit of u
    real(wp) :: u_min = 0, u_max = 1
  contains
    procedure :: evaluate => line_evaluate
    procedure :: domain => line_domain
    procedure :: parameter_unit => line_parameter_unit
    procedure :: arc_length => line_arc_length
  end type line_curve_t

  !> Helix about the z-axis through `center`:
  !> c(u) = center + [R cos(phase + turn u), R sin(phase + turn u), pitch u], u in rad;
  !> turn = +1 turns counter-clockwise seen from above, -1 clockwise; pitch = 0
  !> gives a circle arc. Curvature R/(R^2 + pitch^2).
  type, extends(curve_t) :: helix_curve_t
    real(wp) :: center(3) = 0
    real(wp) :: radius = 1             ! m
    real(wp) :: pitch = 0              ! m per rad (rise per turn / 2 pi)
    real(wp) :: phase = 0              ! rad
    real(wp) :: turn = 1               ! +1 or -1
    real(wp) :: u_min = 0, u_max = 1   ! rad
  contains
    procedure :: evaluate => helix_evaluate
    procedure :: domain => helix_domain
    procedure :: parameter_unit => helix_parameter_unit
    procedure :: arc_length => helix_arc_length
  end type helix_curve_t

  !> S-bend c(u) = origin + [u, a sin(k u), -q u] (u in m along x): left and
  !> right curves alternating every pi/k of x, falling by q per metre;
  !> a < 0 mirrors it (y -> -y).
  type, extends(curve_t) :: s_bend_curve_t
    real(wp) :: origin(3) = 0
    real(wp) :: amplitude = 1          ! m (a)
    real(wp) :: wavenumber = 0.5_wp    ! 1/m (k)
    real(wp) :: slope = 0.1_wp         ! 1 (q, descent per m of x)
    real(wp) :: u_min = 0, u_max = 10  ! m
  contains
    procedure :: evaluate => s_bend_evaluate
    procedure :: domain => s_bend_domain
    procedure :: parameter_unit => s_bend_parameter_unit
  end type s_bend_curve_t

  !> A constant vector (the usual horizon field h = [0, 0, 1]).
  type, extends(curve_t) :: constant_curve_t
    real(wp) :: value(3) = [0, 0, 1]
    real(wp) :: u_min = -huge(1.0_wp), u_max = huge(1.0_wp)
  contains
    procedure :: evaluate => constant_evaluate
    procedure :: domain => constant_domain
  end type constant_curve_t

  !> Polynomial c(u) = sum_k coef(:, k) u^k, k = 0..5, u in [u_min, u_max]
  !> (a curve of varying curvature with exactly known derivatives).
  type, extends(curve_t) :: polynomial_curve_t
    real(wp) :: coef(3, 0:5) = 0
    real(wp) :: u_min = 0, u_max = 1
  contains
    procedure :: evaluate => polynomial_evaluate
    procedure :: domain => polynomial_domain
  end type polynomial_curve_t

  !> A spline curve (numerics_spline_curve, FITPACK parcur/concur) on the
  !> curve seam: the fitted centerline or horizon field of a tube. Derivatives
  !> above the spline's degree are zero (a quintic gives c_uuuu, which the
  !> tube's third partials need; a cubic gives c_uuuu = 0 piecewise).
  !> Arc length and its inverse come from the spline's own table.
  type, extends(curve_t) :: spline_centerline_t
    type(spline_curve_t) :: spline
  contains
    procedure :: evaluate => spline_evaluate
    procedure :: domain => spline_domain
    procedure :: arc_length => spline_arc_length
    procedure :: total_length => spline_total_length
    procedure :: parameter_at_length => spline_parameter_at_length
    procedure :: parameter_unit => spline_parameter_unit
  end type spline_centerline_t

  !> Sub-intervals of the whole domain for the arc-length quadrature.
  integer, parameter :: arc_panels = 256

contains

  pure subroutine line_evaluate(self, u, order, p, status)
    class(line_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    p%order = min(max(order, 0), curve_max_order)
    p%d(:, 0) = self%origin + u*self%direction
    if (order >= 1) p%d(:, 1) = self%direction
    status%code = STATUS_OK
  end subroutine line_evaluate

  pure subroutine line_domain(self, u_min, u_max)
    class(line_curve_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = self%u_min; u_max = self%u_max
  end subroutine line_domain

  !> |direction| (u1 - u0): the closed form of the quadrature.
  pure function line_arc_length(self, u0, u1) result(s)
    class(line_curve_t), intent(in) :: self
    real(wp), intent(in) :: u0, u1
    real(wp) :: s
    s = norm2(self%direction)*(u1 - u0)
  end function line_arc_length

  pure subroutine helix_evaluate(self, u, order, p, status)
    class(helix_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: cs, sn
    integer :: k
    p%order = min(max(order, 0), curve_max_order)
    cs = self%radius*cos(self%phase + self%turn*u)
    sn = self%radius*sin(self%phase + self%turn*u)
    p%d(:, 0) = self%center + [cs, sn, self%pitch*u]
    ! d/du [R cos, R sin] = turn [-R sin, R cos]: each derivative turns by 90
    ! degrees and takes a factor turn
    if (p%order >= 1) p%d(:, 1) = [-self%turn*sn, self%turn*cs, self%pitch]
    do k = 2, p%order
      p%d(1:2, k) = self%turn*[-p%d(2, k - 1), p%d(1, k - 1)]
    end do
    status%code = STATUS_OK
  end subroutine helix_evaluate

  !> sqrt(R^2 + pitch^2) (u1 - u0): the closed form of the quadrature.
  pure function helix_arc_length(self, u0, u1) result(s)
    class(helix_curve_t), intent(in) :: self
    real(wp), intent(in) :: u0, u1
    real(wp) :: s
    s = sqrt(self%radius**2 + self%pitch**2)*(u1 - u0)
  end function helix_arc_length

  pure subroutine s_bend_evaluate(self, u, order, p, status)
    class(s_bend_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: a, k, cs, sn
    p%order = min(max(order, 0), curve_max_order)
    a = self%amplitude; k = self%wavenumber
    cs = cos(k*u); sn = sin(k*u)
    p%d(:, 0) = self%origin + [u, a*sn, -self%slope*u]
    if (p%order >= 1) p%d(:, 1) = [1.0_wp, a*k*cs, -self%slope]
    if (p%order >= 2) p%d(:, 2) = [0.0_wp, -a*k**2*sn, 0.0_wp]
    if (p%order >= 3) p%d(:, 3) = [0.0_wp, -a*k**3*cs, 0.0_wp]
    if (p%order >= 4) p%d(:, 4) = [0.0_wp, a*k**4*sn, 0.0_wp]
    status%code = STATUS_OK
  end subroutine s_bend_evaluate

  pure subroutine s_bend_domain(self, u_min, u_max)
    class(s_bend_curve_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = self%u_min; u_max = self%u_max
  end subroutine s_bend_domain

  pure subroutine helix_domain(self, u_min, u_max)
    class(helix_curve_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = self%u_min; u_max = self%u_max
  end subroutine helix_domain

  pure subroutine constant_evaluate(self, u, order, p, status)
    class(constant_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    p%order = min(max(order, 0), curve_max_order)
    p%d(:, 0) = self%value
    associate (unused => u)   ! a constant does not depend on u
    end associate
    status%code = STATUS_OK
  end subroutine constant_evaluate

  pure subroutine constant_domain(self, u_min, u_max)
    class(constant_curve_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = self%u_min; u_max = self%u_max
  end subroutine constant_domain

  pure subroutine polynomial_evaluate(self, u, order, p, status)
    class(polynomial_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    integer :: k, j, i
    real(wp) :: f
    p%order = min(max(order, 0), curve_max_order)
    do k = 0, p%order
      do j = k, 5
        f = 1                        ! j!/(j-k)!
        do i = 0, k - 1
          f = f*(j - i)
        end do
        p%d(:, k) = p%d(:, k) + f*self%coef(:, j)*u**(j - k)
      end do
    end do
    status%code = STATUS_OK
  end subroutine polynomial_evaluate

  pure subroutine polynomial_domain(self, u_min, u_max)
    class(polynomial_curve_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = self%u_min; u_max = self%u_max
  end subroutine polynomial_domain

  !> Fits a spline curve of `degree` (3..5) to points(3, m) with FITPACK's
  !> smoothing factor (m^2; 0 interpolates). The parameter is the cumulative
  !> chord length (m), so u is close to the arc length. start_tangent and
  !> end_tangent (optional, odd degree) prescribe the end directions; they
  !> are scaled to unit length (d c/du of a chord-length parameter).
  !> `parameters` replaces the chord length (e.g. to fit a horizon field
  !> sampled at the centerline's parameters).
  function new_spline_centerline(points, smoothing, degree, status, start_tangent, end_tangent, &
                                 parameters) result(c)
    real(wp), intent(in) :: points(:, :)
    real(wp), intent(in) :: smoothing
    integer, intent(in) :: degree
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: start_tangent(3), end_tangent(3)
    real(wp), intent(in), optional :: parameters(:)
    type(spline_centerline_t) :: c
    real(wp), allocatable :: u(:)
    real(wp) :: db(3, 2), de(3, 2)
    integer :: m, i
    m = size(points, 2)
    if (size(points, 1) /= 3 .or. m < degree + 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'spline centerline: need points(3, m) with m > degree')
      return
    end if
    allocate (u(m))
    u(1) = 0
    do i = 2, m
      u(i) = u(i - 1) + norm2(points(:, i) - points(:, i - 1))
    end do
    if (present(parameters)) then
      if (size(parameters) /= m) then
        call set_status(status, STATUS_INVALID_INPUT, 'spline centerline: one parameter per point needed')
        return
      end if
      u = parameters
    end if
    if (present(start_tangent) .or. present(end_tangent)) then
      db(:, 1) = points(:, 1); de(:, 1) = points(:, m)
      if (present(start_tangent)) db(:, 2) = start_tangent/norm2(start_tangent)
      if (present(end_tangent)) de(:, 2) = end_tangent/norm2(end_tangent)
      if (present(start_tangent) .and. present(end_tangent)) then
        call c%spline%fit(points, smoothing, degree, status, parameters=u, start_derivatives=db, &
                          end_derivatives=de)
      else if (present(start_tangent)) then
        call c%spline%fit(points, smoothing, degree, status, parameters=u, start_derivatives=db, &
                          end_derivatives=de(:, 1:1))
      else
        call c%spline%fit(points, smoothing, degree, status, parameters=u, start_derivatives=db(:, 1:1), &
                          end_derivatives=de)
      end if
    else
      call c%spline%fit(points, smoothing, degree, status, parameters=u)
    end if
    if (.not. status%ok()) call prefix_status(status, 'spline centerline')
  end function new_spline_centerline

  pure subroutine spline_evaluate(self, u, order, p, status)
    class(spline_centerline_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    p%order = min(max(order, 0), curve_max_order)
    call self%spline%evaluate(u, p%d(:, 0:p%order), p%order)
    status%code = STATUS_OK
  end subroutine spline_evaluate

  pure subroutine spline_domain(self, u_min, u_max)
    class(spline_centerline_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    real(wp) :: d(2)
    d = self%spline%domain()
    u_min = d(1); u_max = d(2)
  end subroutine spline_domain

  pure function spline_arc_length(self, u0, u1) result(s)
    class(spline_centerline_t), intent(in) :: self
    real(wp), intent(in) :: u0, u1
    real(wp) :: s
    s = self%spline%arc_length(u1) - self%spline%arc_length(u0)
  end function spline_arc_length

  pure function spline_total_length(self) result(s)
    class(spline_centerline_t), intent(in) :: self
    real(wp) :: s
    s = self%spline%total_length()
  end function spline_total_length

  pure subroutine spline_parameter_at_length(self, length, u, status)
    class(spline_centerline_t), intent(in) :: self
    real(wp), intent(in) :: length
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    real(wp) :: total
    total = self%spline%total_length()
    u = self%spline%parameter_at_length(length)
    if (length < 0 .or. length > total*(1 + 1e-12_wp)) &
      call set_status(status, STATUS_DOMAIN, 'arc length outside the curve [0, total length]')
  end subroutine spline_parameter_at_length

  !> Arc length from u0 to u1 (thesis 2.1), m; negative if u1 < u0.
  !> Composite 8-point Gauss-Legendre on panels of the whole domain
  !> (1/arc_panels of it each), so s(u) is the same function wherever it is
  !> asked for; exact to ~1e-13 relative where |c_u| is smooth on a panel's
  !> scale, less where a panel holds a kink of a higher derivative (an
  !> element chain's windows' ends: 2.3e-9 relative with 0.3 m transitions,
  !> 3.6e-13 with 2 m ones on the demo chain, test_slide_chain_evaluation).
  pure function curve_arc_length(self, u0, u1) result(s)
    class(curve_t), intent(in) :: self
    real(wp), intent(in) :: u0, u1
    real(wp) :: s
    s = panel_arc_length(self, u0, u1)
  end function curve_arc_length

  !> curve_arc_length's sum over the panels; with `prefix`
  !> (arc_length_prefix of the same curve) the whole panels from the domain's
  !> start are taken from the table: the same additions in the same order,
  !> so the same value to the bit, without evaluating the curve 8 times per
  !> panel (an exact centerline asks for s(u) from its start at every record).
  pure function panel_arc_length(self, u0, u1, prefix) result(s)
    class(curve_t), intent(in) :: self
    real(wp), intent(in) :: u0, u1
    real(wp), intent(in), optional :: prefix(0:)
    real(wp) :: s
    real(wp) :: a, b, lo, hi, width, pa, pb
    integer :: i0, i1, i
    real(wp) :: sign_
    call self%domain(lo, hi)
    a = min(u0, u1); b = max(u0, u1)
    sign_ = merge(1.0_wp, -1.0_wp, u1 >= u0)
    s = 0
    if (b <= a) return
    if (hi > huge(1.0_wp)/4 .or. lo < -huge(1.0_wp)/4 .or. hi <= lo) then
      s = sign_*arc_panel(self, a, b)
      return
    end if
    width = (hi - lo)/arc_panels
    i0 = floor((a - lo)/width)
    i1 = floor((b - lo)/width)
    if (present(prefix) .and. a == lo .and. i0 == 0) then
      ! panels 0 .. i0 - 1 whole (each ends at or before b), the rest as below
      i0 = max(0, min(i1, arc_panels))
      do while (i0 > 0 .and. lo + i0*width > b)
        i0 = i0 - 1
      end do
      s = prefix(i0)
    end if
    do i = i0, i1
      pa = max(a, lo + i*width)
      pb = min(b, lo + (i + 1)*width)
      if (pb > pa) s = s + arc_panel(self, pa, pb)
    end do
    s = sign_*s
  end function panel_arc_length

  !> The sums of curve_arc_length's whole panels from the start of a finite
  !> domain: prefix(k) = panels 0 .. k-1, added in curve_arc_length's order.
  function arc_length_prefix(self) result(prefix)
    class(curve_t), intent(in) :: self
    real(wp) :: prefix(0:arc_panels)
    real(wp) :: lo, hi, width, pa, pb
    integer :: i
    call self%domain(lo, hi)
    width = (hi - lo)/arc_panels
    prefix(0) = 0
    do i = 0, arc_panels - 1
      pa = max(lo, lo + i*width)
      pb = lo + (i + 1)*width
      prefix(i + 1) = prefix(i)
      if (pb > pa) prefix(i + 1) = prefix(i) + arc_panel(self, pa, pb)
    end do
  end function arc_length_prefix

  !> 8-point Gauss-Legendre of |c_u| over [x0, x1].
  pure real(wp) function arc_panel(self, x0, x1) result(q)
    class(curve_t), intent(in) :: self
    real(wp), intent(in) :: x0, x1
    integer :: k
    q = 0
    do k = 1, 8
      q = q + gl8_w(k)*self%speed(0.5_wp*(x0 + x1) + 0.5_wp*(x1 - x0)*gl8_x(k))
    end do
    q = 0.5_wp*(x1 - x0)*q
  end function arc_panel

  !> |c_u| at u, the arc length's integrand (a curve that knows it more
  !> cheaply than by its whole evaluation overrides it).
  pure real(wp) function curve_speed(self, u) result(speed)
    class(curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    type(curve_point_t) :: p
    type(status_t) :: st
    call self%evaluate(u, 1, p, st)
    speed = norm2(p%d(:, 1))
  end function curve_speed

  !> Length of the whole curve, m.
  pure function curve_total_length(self) result(s)
    class(curve_t), intent(in) :: self
    real(wp) :: s
    real(wp) :: lo, hi
    call self%domain(lo, hi)
    s = self%arc_length(lo, hi)
  end function curve_total_length

  !> The parameter u at which the arc length from u_min equals `length` (m):
  !> Newton on s(u) - length with ds/du = |c_u|, kept inside a bracket.
  pure subroutine curve_parameter_at_length(self, length, u, status)
    class(curve_t), intent(in) :: self
    real(wp), intent(in) :: length
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    real(wp) :: lo, hi, total, a, b, f, speed
    type(curve_point_t) :: p
    integer :: it
    call self%domain(lo, hi)
    total = self%arc_length(lo, hi)
    u = lo
    if (length < 0 .or. length > total*(1 + 1e-12_wp)) then
      call set_status(status, STATUS_DOMAIN, 'arc length outside the curve [0, total length]')
      return
    end if
    a = lo; b = hi
    u = lo + (hi - lo)*length/max(total, tiny(1.0_wp))
    do it = 1, 60
      f = self%arc_length(lo, u) - length
      if (abs(f) <= 1e-12_wp*max(total, 1.0_wp)) return
      if (f > 0) then
        b = u
      else
        a = u
      end if
      call self%evaluate(u, 1, p, status)
      if (.not. status%ok()) return
      speed = norm2(p%d(:, 1))
      if (speed > 0) then
        u = u - f/speed
      else
        u = 0.5_wp*(a + b)
      end if
      if (u <= a .or. u >= b) u = 0.5_wp*(a + b)
    end do
    call set_status(status, STATUS_NOT_CONVERGED, 'parameter at arc length: no convergence')
  end subroutine curve_parameter_at_length

  !> The unit of the parameter u (UDUNITS/pint text); default dimensionless.
  pure function curve_parameter_unit(self) result(unit)
    class(curve_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = '1'
  end function curve_parameter_unit

  !> m when the direction is a unit vector (u is then the length along the line).
  pure function line_parameter_unit(self) result(unit)
    class(line_curve_t), intent(in) :: self
    character(len=:), allocatable :: unit
    unit = '1'
    if (abs(norm2(self%direction) - 1) <= 1e-12_wp) unit = 'm'
  end function line_parameter_unit

  pure function s_bend_parameter_unit(self) result(unit)
    class(s_bend_curve_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = 'm'
  end function s_bend_parameter_unit

  pure function helix_parameter_unit(self) result(unit)
    class(helix_curve_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = 'rad'
  end function helix_parameter_unit

  !> The cumulative chord length of the fitted points (m).
  pure function spline_parameter_unit(self) result(unit)
    class(spline_centerline_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = 'm'
  end function spline_parameter_unit
end module geometry_curve
