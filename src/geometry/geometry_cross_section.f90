!> Cross-sections s(u, v) = [0, s_y, s_z] of a tube in its moving frame
!> (thesis 3.64-3.72, appendix C.3-C.4), with partial derivatives in u and v
!> to total order 3.
!>
!> Orientation (thesis 4.2): a circle of radius r is s = [0, -r cos v, -r sin v];
!> with the horizon pointing up, z of the frame points up, y to the left of the
!> direction of travel, and v = pi/2 is the bottom of the tube.
!>
!> Variable sections blend n sections along u with logistic functions
!> (3.69-3.72). The growth constant (3.72) is printed with the opposite sign;
!> here xi = ln(0.99/0.01)/(u_99 - midpoint), so that Lambda(u_99) = 0.99 and
!> the blend goes from section 0 to section n-1 as u grows (checked in tests).
!> The weights are those of (3.69): w_0 = 1 - L_0, w_j = L_{j-1} (1 - L_j),
!> w_{n-1} = L_{n-2}; they sum to 1 only where neighbouring transitions do not
!> overlap (the sum is 1 + sum_j L_j (1 - L_{j-1})), so transitions should be
!> separated by more than their widths.
!>
!> The open flume (the measured slide of chapter 4: a semicircle of radius
!> 0.52 m with two straight walls of 0.164 m) is the same construction in v:
!> the two wall lines and the circle, each extended beyond its joint, blended
!> by logistic weights centred on the joints (v = 0 and v = pi). The result is
!> C-infinity; it equals the exact profile to rounding outside the transition
!> zones (|v - joint| > ~6 widths) and deviates from it by at most about
!> r dv^2/2 inside (0.65 mm for the default 0.99-width dv = 0.05 rad).
module geometry_cross_section
  use base_kinds, only: wp, int64
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_OK, STATUS_INVALID_INPUT
  use numerics_spline_curve, only: spline_curve_t
  implicit none (type, external)
  private
  public :: cross_section_t, section_point_t, section_holder_t
  public :: circle_section_t, ellipse_section_t, flume_section_t, blended_section_t
  public :: logistic, logistic_rate, blend_weights, new_blended_section
  public :: profile_section_t, new_profile_section, polyline_self_intersection
  public :: extent_intervals, extent_sample_v, sampled_extent, ellipse_point, flume_circle_alone

  !> s(:, i, j) = d^(i+j) [s_y, s_z] / du^i dv^j for i + j <= order.
  type :: section_point_t
    integer :: order = 0
    real(wp) :: s(2, 0:3, 0:3) = 0
  end type section_point_t

  type, abstract :: cross_section_t
  contains
    procedure(section_evaluate_i), deferred :: evaluate
    procedure(section_range_i), deferred :: v_range
    procedure :: periodic => section_not_periodic
    procedure :: extent => section_extent
    procedure :: parameter_unit => section_parameter_unit
    !> The radius of a section that is one circle at every u (m), 0 for any
    !> other: the closed forms of a circle (the water's segment, the wall
    !> position) are taken only where a kind says it is one.
    procedure :: circle_radius => section_not_circle
    !> Whether the section changes along u. A kind that does not say is
    !> taken to change (the water then takes its area's rate along u: right
    !> for every section, only slower where it does not change).
    procedure :: varies_along => section_varies_along
  end type cross_section_t

  abstract interface
    pure subroutine section_evaluate_i(self, u, v, order, p, status)
      import :: cross_section_t, section_point_t, status_t, wp
      class(cross_section_t), intent(in) :: self
      real(wp), intent(in) :: u, v
      integer, intent(in) :: order
      type(section_point_t), intent(out) :: p
      type(status_t), intent(out) :: status
    end subroutine section_evaluate_i
    pure subroutine section_range_i(self, v_min, v_max)
      import :: cross_section_t, wp
      class(cross_section_t), intent(in) :: self
      real(wp), intent(out) :: v_min, v_max
    end subroutine section_range_i
  end interface

  type :: section_holder_t
    class(cross_section_t), allocatable :: section
  end type section_holder_t

  !> Circle s = [0, -r cos v, -r sin v] (thesis 4.2), v in [v_min, v_max] (rad).
  type, extends(cross_section_t) :: circle_section_t
    real(wp) :: radius = 0.5_wp          ! m
    real(wp) :: v_min = 0, v_max = two_pi
  contains
    procedure :: evaluate => circle_evaluate
    procedure :: v_range => circle_range
    procedure :: periodic => circle_periodic
    procedure :: extent => circle_extent
    procedure :: circle_radius => circle_circle_radius
    procedure :: varies_along => circle_varies_along
  end type circle_section_t

  !> Ellipse s = [0, -a cos v, -b sin v]: half-width a (m), half-height b (m).
  type, extends(cross_section_t) :: ellipse_section_t
    real(wp) :: a = 0.5_wp, b = 0.5_wp
    real(wp) :: v_min = 0, v_max = two_pi
  contains
    procedure :: evaluate => ellipse_evaluate
    procedure :: v_range => ellipse_range
    procedure :: periodic => ellipse_periodic
    procedure :: varies_along => ellipse_varies_along
  end type ellipse_section_t

  !> Open flume: semicircle of radius `radius` (v in [0, pi], bottom at pi/2)
  !> continued by straight vertical walls of length `wall`; v in
  !> [-wall/radius, pi + wall/radius] (the walls are parametrised at the same
  !> speed r). `transition` is the 0.99-width of the logistic joints, rad.
  type, extends(cross_section_t) :: flume_section_t
    real(wp) :: radius = 0.52_wp         ! m
    real(wp) :: wall = 0.164_wp          ! m
    real(wp) :: transition = 0.05_wp     ! rad
  contains
    procedure :: evaluate => flume_evaluate
    procedure :: v_range => flume_range
    procedure :: varies_along => flume_varies_along
  end type flume_section_t

  !> A profile given as points (y, z) in the frame, fitted by a spline curve
  !> (parcur; clocur if the first and last point coincide); v is the
  !> cumulative chord length of the points (m).
  type, extends(cross_section_t) :: profile_section_t
    type(spline_curve_t) :: spline
    logical :: closed = .false.
  contains
    procedure :: evaluate => profile_evaluate
    procedure :: v_range => profile_range
    procedure :: periodic => profile_periodic
    procedure :: parameter_unit => profile_parameter_unit
    procedure :: varies_along => profile_varies_along
  end type profile_section_t

  !> n sections blended along u (3.69): transition j (between sections j-1 and
  !> j) has its midpoint midpoint(j) and growth constant rate(j) (3.72).
  type, extends(cross_section_t) :: blended_section_t
    type(section_holder_t), allocatable :: sections(:)
    real(wp), allocatable :: midpoint(:), rate(:)
  contains
    procedure :: evaluate => blended_evaluate
    procedure :: v_range => blended_range
    procedure :: periodic => blended_periodic
    procedure :: extent => blended_extent
    procedure :: parameter_unit => blended_parameter_unit
  end type blended_section_t

  integer, parameter :: binom(0:3, 0:3) = reshape([1, 0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1, 3, 3, 1], [4, 4])

  !> The sampled extent's intervals across the v range (its points i = 0..180)
  integer, parameter :: extent_intervals = 180

contains

  pure logical function section_not_periodic(self) result(periodic)
    class(cross_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    periodic = .false.
  end function section_not_periodic

  pure real(wp) function section_not_circle(self) result(radius)
    class(cross_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    radius = 0
  end function section_not_circle

  pure logical function section_varies_along(self) result(varies)
    class(cross_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .true.
  end function section_varies_along

  ! the kinds that are one profile at every u

  pure logical function circle_varies_along(self) result(varies)
    class(circle_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .false.
  end function circle_varies_along

  pure logical function ellipse_varies_along(self) result(varies)
    class(ellipse_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .false.
  end function ellipse_varies_along

  pure logical function flume_varies_along(self) result(varies)
    class(flume_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .false.
  end function flume_varies_along

  pure logical function profile_varies_along(self) result(varies)
    class(profile_section_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .false.
  end function profile_varies_along

  pure real(wp) function circle_circle_radius(self) result(radius)
    class(circle_section_t), intent(in) :: self
    radius = self%radius
  end function circle_circle_radius

  !> Largest distance |s| of the section from the centerline at u (m), sampled
  !> at the extent_intervals + 1 values of v of extent_sample_v (used to check
  !> that the tube does not fold): sampled_extent.
  pure function section_extent(self, u) result(r)
    class(cross_section_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: r
    r = sampled_extent(self, u)
  end function section_extent

  !> The general extent of any section at u: the largest |s(u, v)| over v at
  !> the samples extent_sample_v(v_min, v_max, i), i = 0..extent_intervals
  !> (points that fail to evaluate left out). A kind that overrides extent
  !> for speed may call it.
  pure function sampled_extent(section, u) result(r)
    class(cross_section_t), intent(in) :: section
    real(wp), intent(in) :: u
    real(wp) :: r
    real(wp) :: a, b
    type(section_point_t) :: p
    type(status_t) :: st
    integer :: i
    call section%v_range(a, b)
    r = 0
    do i = 0, extent_intervals
      call section%evaluate(u, extent_sample_v(a, b, i), 0, p, st)
      if (st%ok()) r = max(r, norm2(p%s(:, 0, 0)))
    end do
  end function sampled_extent

  !> v of the extent's sample i (0..extent_intervals) over [a, b].
  elemental real(wp) function extent_sample_v(a, b, i) result(v)
    real(wp), intent(in) :: a, b
    integer, intent(in) :: i
    v = a + (b - a)*i/real(extent_intervals, wp)
  end function extent_sample_v

  !> A circle's extent is its radius, on any arc of it (no sampling).
  pure function circle_extent(self, u) result(r)
    class(circle_section_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: r
    associate (unused => u)
    end associate
    r = self%radius
  end function circle_extent

  ! ---------------------------------------------------------------- logistic

  !> Growth constant xi of the logistic function (3.71-3.72), chosen so that
  !> Lambda(u_99) = 0.99 (sign: see the module header); 1/unit of u.
  pure real(wp) function logistic_rate(midpoint, u_99) result(xi)
    real(wp), intent(in) :: midpoint, u_99
    xi = log(0.99_wp/0.01_wp)/(u_99 - midpoint)
  end function logistic_rate

  !> Lambda(u) = 1/(1 + exp(-xi (u - midpoint))) (3.70) and its derivatives
  !> (C.38-C.40): lam(k) = d^k Lambda/du^k, k = 0..3. Evaluated without overflow.
  pure subroutine logistic(u, midpoint, xi, lam)
    real(wp), intent(in) :: u, midpoint, xi
    real(wp), intent(out) :: lam(0:3)
    real(wp) :: t, e, l, q
    t = xi*(u - midpoint)
    if (t >= 0) then
      e = exp(-min(t, 700.0_wp))
      l = 1/(1 + e)
      q = e/(1 + e)          ! 1 - Lambda without cancellation
    else
      e = exp(max(t, -700.0_wp))
      l = e/(1 + e)
      q = 1/(1 + e)
    end if
    lam(0) = l
    lam(1) = xi*l*q                                ! (C.38)
    lam(2) = xi**2*l*q*(q - l)                     ! (C.39): 1 - 2 Lambda = q - l
    lam(3) = xi**3*l*q*(1 - 6*l*q)                 ! (C.40): 1 - 6 L + 6 L^2 = 1 - 6 L q
  end subroutine logistic

  !> Blend weights of (3.69)/(3.79) and their derivatives from the n-1
  !> logistic functions: lam(0:3, j) for transition j = 1..n-1;
  !> w(0:3, j) for section/patch j = 1..n.
  pure subroutine blend_weights(lam, w)
    real(wp), intent(in) :: lam(0:, :)
    real(wp), intent(out) :: w(0:, :)
    integer :: n, j, k, m
    real(wp) :: a(0:3), b(0:3)
    n = size(w, 2)
    w = 0
    if (n == 1) then
      w(0, 1) = 1
      return
    end if
    w(0, 1) = 1 - lam(0, 1)
    w(1:3, 1) = -lam(1:3, 1)
    do j = 2, n - 1
      a = lam(0:3, j - 1)
      b(0) = 1 - lam(0, j); b(1:3) = -lam(1:3, j)
      do k = 0, 3
        do m = 0, k
          w(k, j) = w(k, j) + binom(m, k)*a(m)*b(k - m)
        end do
      end do
    end do
    w(0:3, n) = lam(0:3, n - 1)
  end subroutine blend_weights

  ! ------------------------------------------------------------------ circle

  pure subroutine circle_evaluate(self, u, v, order, p, status)
    class(circle_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    associate (unused => u)
    end associate
    call ellipse_point(self%radius, self%radius, cos(v), sin(v), order, p)
    status%code = STATUS_OK
  end subroutine circle_evaluate

  !> The ellipse's (a circle's: a = b) point and v-partials to `order` at the
  !> v of c = cos v, s = sin v (for a caller that has them already).
  pure subroutine ellipse_point(a, b, c, s, order, p)
    real(wp), intent(in) :: a, b, c, s
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    p%order = order
    p%s(:, 0, 0) = [-a*c, -b*s]
    if (order >= 1) p%s(:, 0, 1) = [a*s, -b*c]
    if (order >= 2) p%s(:, 0, 2) = [a*c, b*s]
    if (order >= 3) p%s(:, 0, 3) = [-a*s, b*c]
  end subroutine ellipse_point

  pure subroutine circle_range(self, v_min, v_max)
    class(circle_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    v_min = self%v_min; v_max = self%v_max
  end subroutine circle_range

  pure logical function circle_periodic(self) result(periodic)
    class(circle_section_t), intent(in) :: self
    periodic = abs(self%v_max - self%v_min - two_pi) < 1e-12_wp
  end function circle_periodic

  pure subroutine ellipse_evaluate(self, u, v, order, p, status)
    class(ellipse_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    associate (unused => u)
    end associate
    call ellipse_point(self%a, self%b, cos(v), sin(v), order, p)
    status%code = STATUS_OK
  end subroutine ellipse_evaluate

  pure subroutine ellipse_range(self, v_min, v_max)
    class(ellipse_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    v_min = self%v_min; v_max = self%v_max
  end subroutine ellipse_range

  pure logical function ellipse_periodic(self) result(periodic)
    class(ellipse_section_t), intent(in) :: self
    periodic = abs(self%v_max - self%v_min - two_pi) < 1e-12_wp
  end function ellipse_periodic

  ! ------------------------------------------------------------------- flume

  !> The flume's point: its three parts (the walls and the circle) blended
  !> by the logistic weights of its joints. Where flume_circle_alone holds,
  !> the blend is the circle's part to the last bit (its weight 1, the
  !> others' terms below a quarter of its spacing): it is taken without the
  !> two exp and the sums (the same numbers).
  pure subroutine flume_evaluate(self, u, v, order, p, status)
    class(flume_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: lam(0:3, 2), w(0:3, 3), part(2, 0:3, 3), xi, r, c, s
    integer :: k, m, j
    associate (unused => u)
    end associate
    r = self%radius
    xi = logistic_rate(0.0_wp, self%transition)
    c = cos(v); s = sin(v)
    status%code = STATUS_OK
    p%order = order
    if (flume_circle_alone(xi, r, v, c, s)) then
      p%s(:, 0, 0) = [-r*c, -r*s]
      if (order >= 1) p%s(:, 0, 1) = [r*s, -r*c]
      if (order >= 2) p%s(:, 0, 2) = [r*c, r*s]
      if (order >= 3) p%s(:, 0, 3) = [-r*s, r*c]
      return
    end if
    call logistic(v, 0.0_wp, xi, lam(:, 1))
    call logistic(v, pi, xi, lam(:, 2))
    call blend_weights(lam, w)
    part = 0
    ! wall 1 (v < 0, going up at y = -r), the circle, wall 2 (v > pi, at y = +r)
    part(:, 0, 1) = [-r, -r*v];        part(:, 1, 1) = [0.0_wp, -r]
    part(:, 0, 2) = [-r*c, -r*s]
    part(:, 1, 2) = [r*s, -r*c]
    part(:, 2, 2) = [r*c, r*s]
    part(:, 3, 2) = [-r*s, r*c]
    part(:, 0, 3) = [r, r*(v - pi)];   part(:, 1, 3) = [0.0_wp, r]
    do k = 0, order
      do j = 1, 3
        do m = 0, k
          p%s(:, 0, k) = p%s(:, 0, k) + binom(m, k)*w(m, j)*part(:, k - m, j)
        end do
      end do
    end do
  end subroutine flume_evaluate

  !> Whether the flume's blend (flume_evaluate) at v, c = cos v, s = sin v,
  !> is its circle's part to the last bit, shown without evaluating it: with
  !> t the smaller of xi v and xi (pi - v) (v inside (0, pi)), each joint's
  !> e <= exp(-t). Then the circle's weight is 1 exactly (1/(1 + e) and
  !> 1 - e/(1 + e) round to 1), the walls' weight 0, and the other terms of
  !> a partial's sum (at most 10, each at most 6 X (e_1 + e_2) r pi, X =
  !> max(1, xi)^3) add up to less than 1024 X r exp(-t). That is below a
  !> quarter of the spacing of the smallest of the circle's partials (m =
  !> r min(|c|, |s|), spacing > m 2^-53) where X r 2^(66 - n) < m, n =
  !> floor(t log2 e) (2^(1 - n) > exp(-t); t at most 700, where logistic
  !> clamps): then adding them leaves the circle's number as it is. 2^(66 - n)
  !> is formed from its exponent bits (no libm call).
  pure logical function flume_circle_alone(xi, r, v, c, s) result(alone)
    real(wp), intent(in) :: xi, r, v, c, s
    real(wp), parameter :: log2e = 1.4426950408889634_wp
    real(wp) :: t
    alone = .false.
    if (.not. (xi > 0 .and. r > 0)) return
    t = min(xi*v, -(xi*(v - pi)), 700.0_wp)
    if (.not. t > 1) return
    alone = max(1.0_wp, xi)**3*r*power_of_two(66 - floor(t*log2e)) < min(abs(r*c), abs(r*s))
  end function flume_circle_alone

  !> 2^k for -1022 <= k <= 1023 (a normal double: its exponent bits alone).
  elemental real(wp) function power_of_two(k) result(x)
    integer, intent(in) :: k
    x = transfer(shiftl(int(k + 1023, int64), 52), 1.0_wp)
  end function power_of_two

  pure subroutine flume_range(self, v_min, v_max)
    class(flume_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    v_min = -self%wall/self%radius
    v_max = pi + self%wall/self%radius
  end subroutine flume_range

  ! ----------------------------------------------------------------- profile

  !> Index of the first segment of the polyline (y, z) that crosses a later,
  !> non-adjacent segment (0: none). For a closed polyline (last point = first)
  !> the first and last segments are adjacent.
  pure integer function polyline_self_intersection(y, z) result(first)
    real(wp), intent(in) :: y(:), z(:)
    integer :: i, j, n
    logical :: closed
    n = size(y)
    first = 0
    closed = n > 3 .and. y(1) == y(n) .and. z(1) == z(n)
    do i = 1, n - 1
      do j = i + 2, n - 1
        if (closed .and. i == 1 .and. j == n - 1) cycle
        if (cross_2d([y(i), z(i)], [y(i + 1), z(i + 1)], [y(j), z(j)], [y(j + 1), z(j + 1)])) then
          first = i
          return
        end if
      end do
    end do
  contains
    pure logical function cross_2d(p1, p2, q1, q2)
      real(wp), intent(in) :: p1(2), p2(2), q1(2), q2(2)
      cross_2d = orient(q1, q2, p1)*orient(q1, q2, p2) < 0 .and. orient(p1, p2, q1)*orient(p1, p2, q2) < 0
    end function cross_2d
    pure real(wp) function orient(a, b, c)
      real(wp), intent(in) :: a(2), b(2), c(2)
      orient = (b(1) - a(1))*(c(2) - a(2)) - (b(2) - a(2))*(c(1) - a(1))
    end function orient
  end function polyline_self_intersection

  !> A profile through (or, with smoothing > 0, near) the points (y(i), z(i))
  !> (m) with a spline of `degree` (3..5). Rejects fewer than degree+1 points,
  !> repeated consecutive points and a self-intersecting polyline.
  function new_profile_section(y, z, smoothing, degree, status) result(s)
    real(wp), intent(in) :: y(:), z(:), smoothing
    integer, intent(in) :: degree
    type(status_t), intent(out) :: status
    type(profile_section_t) :: s
    real(wp), allocatable :: pts(:, :), v(:)
    integer :: n, i, k
    character(len=40) :: buf
    n = size(y)
    if (size(z) /= n .or. n < degree + 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'profile section: need at least degree + 1 points')
      return
    end if
    allocate (pts(2, n), v(n))
    pts(1, :) = y; pts(2, :) = z
    v(1) = 0
    do i = 2, n
      v(i) = v(i - 1) + norm2(pts(:, i) - pts(:, i - 1))
      if (.not. v(i) > v(i - 1)) then
        write (buf, '(i0)') i
        call set_status(status, STATUS_INVALID_INPUT, 'profile section: point ' // trim(buf) // &
                        ' repeats the point before it')
        return
      end if
    end do
    k = polyline_self_intersection(y, z)
    if (k > 0) then
      write (buf, '(i0, a, i0)') k, ' and ', k + 1
      call set_status(status, STATUS_INVALID_INPUT, 'profile section: the profile intersects itself ' // &
                      '(the segment between points ' // trim(buf) // ' crosses a later one)')
      return
    end if
    s%closed = n > 3 .and. y(1) == y(n) .and. z(1) == z(n)
    call s%spline%fit(pts, smoothing, degree, status, parameters=v, periodic=s%closed)
    if (.not. status%ok()) call prefix_status(status, 'profile section')
  end function new_profile_section

  pure subroutine profile_evaluate(self, u, v, order, p, status)
    class(profile_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: d(2, 0:3)
    associate (unused => u)
    end associate
    p%order = order
    call self%spline%evaluate(v, d(:, 0:order), order)
    p%s(:, 0, 0:order) = d(:, 0:order)
    status%code = STATUS_OK
  end subroutine profile_evaluate

  pure subroutine profile_range(self, v_min, v_max)
    class(profile_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    real(wp) :: d(2)
    d = self%spline%domain()
    v_min = d(1); v_max = d(2)
  end subroutine profile_range

  pure logical function profile_periodic(self) result(periodic)
    class(profile_section_t), intent(in) :: self
    periodic = self%closed
  end function profile_periodic

  ! ----------------------------------------------------------------- blended

  !> n >= 2 sections joined by n-1 transitions (midpoint(j), u_99(j)), in
  !> increasing order of u; all sections must share their v-range.
  function new_blended_section(sections, midpoint, u_99, status) result(b)
    type(section_holder_t), intent(in) :: sections(:)
    real(wp), intent(in) :: midpoint(:), u_99(:)
    type(status_t), intent(out) :: status
    type(blended_section_t) :: b
    real(wp) :: a0, b0, a1, b1
    integer :: j
    if (size(sections) < 2 .or. size(midpoint) /= size(sections) - 1 .or. &
        size(u_99) /= size(sections) - 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended section: need n >= 2 sections ' // &
                      'and n-1 transitions (midpoint, u_99)')
      return
    end if
    do j = 1, size(midpoint)
      if (.not. u_99(j) > midpoint(j)) then
        call set_status(status, STATUS_INVALID_INPUT, 'blended section: each 0.99 point must ' // &
                        'lie after its midpoint (u_99 > midpoint)')
        return
      end if
      if (j > 1) then
        if (.not. midpoint(j) > midpoint(j - 1)) then
          call set_status(status, STATUS_INVALID_INPUT, 'blended section: transition midpoints ' // &
                          'must increase')
          return
        end if
      end if
    end do
    call sections(1)%section%v_range(a0, b0)
    do j = 2, size(sections)
      call sections(j)%section%v_range(a1, b1)
      if (abs(a1 - a0) > 1e-12_wp .or. abs(b1 - b0) > 1e-12_wp) then
        call set_status(status, STATUS_INVALID_INPUT, 'blended section: all sections must ' // &
                        'have the same v-range')
        return
      end if
    end do
    b%sections = sections
    b%midpoint = midpoint
    b%rate = [(logistic_rate(midpoint(j), u_99(j)), j=1, size(midpoint))]
  end function new_blended_section

  !> (3.69) with derivatives (C.28-C.36, here by Leibniz' rule on the weights).
  pure subroutine blended_evaluate(self, u, v, order, p, status)
    class(blended_section_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    integer, parameter :: max_sections = 16
    real(wp) :: lam(0:3, max_sections), w(0:3, max_sections)
    type(section_point_t) :: q
    integer :: n, j, k, m, l
    n = size(self%sections)
    if (n > max_sections) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended section: at most 16 sections')
      return
    end if
    do j = 1, n - 1
      call logistic(u, self%midpoint(j), self%rate(j), lam(:, j))
    end do
    call blend_weights(lam(:, 1:n - 1), w(:, 1:n))
    p%order = order
    do j = 1, n
      call self%sections(j)%section%evaluate(u, v, order, q, status)
      if (.not. status%ok()) return
      do k = 0, order              ! u-order
        do l = 0, order - k        ! v-order
          do m = 0, k
            p%s(:, k, l) = p%s(:, k, l) + binom(m, k)*w(m, j)*q%s(:, k - m, l)
          end do
        end do
      end do
    end do
  end subroutine blended_evaluate

  pure subroutine blended_range(self, v_min, v_max)
    class(blended_section_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    call self%sections(1)%section%v_range(v_min, v_max)
  end subroutine blended_range

  pure logical function blended_periodic(self) result(periodic)
    class(blended_section_t), intent(in) :: self
    integer :: j
    periodic = .true.
    do j = 1, size(self%sections)
      periodic = periodic .and. self%sections(j)%section%periodic()
    end do
  end function blended_periodic

  pure function blended_extent(self, u) result(r)
    class(blended_section_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: r
    integer :: j
    r = 0
    do j = 1, size(self%sections)
      r = max(r, self%sections(j)%section%extent(u))
    end do
  end function blended_extent

  !> The unit of v (UDUNITS/pint text): an angle for the circle, ellipse and
  !> flume (whose walls run at the circle's speed).
  pure function section_parameter_unit(self) result(unit)
    class(cross_section_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = 'rad'
  end function section_parameter_unit

  !> v is the chord length of the profile's points (m).
  pure function profile_parameter_unit(self) result(unit)
    class(profile_section_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = 'm'
  end function profile_parameter_unit

  !> The sections' common unit, or dimensionless if they differ.
  pure function blended_parameter_unit(self) result(unit)
    class(blended_section_t), intent(in) :: self
    character(len=:), allocatable :: unit
    integer :: j
    unit = '1'
    if (size(self%sections) == 0) return
    unit = self%sections(1)%section%parameter_unit()
    do j = 2, size(self%sections)
      if (self%sections(j)%section%parameter_unit() /= unit) unit = '1'
    end do
  end function blended_parameter_unit
end module geometry_cross_section
