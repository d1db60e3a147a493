!> The channel seam: what the water model needs from a slide.
!>
!> A channel is a tube-like surface r(u, v) with u along the centerline and v
!> across it (v = pi/2 at the bottom of a circular tube, v growing to the left
!> of the direction of travel), plus its centerline c(u) for the curvature chi
!> (thesis 4.8) and its rate, and the cross-section (a circle of radius r, or
!> any profile that the water model reads from the surface itself).
!>
!> Concrete channels: `analytic_tube_t` (circular tubes around a straight,
!> helical or S-shaped centerline, written in closed form; used by the tests,
!> the benchmark and the scenario while no fitted slide is given) and, in
!> water_tube_channel, an adapter of the geometry layer's tube surfaces.
!>
!> The tube frame is the horizon-vector frame (thesis 2.12, 3.60-3.64) with the
!> horizon h = [0, 0, 1]: x = c_u/|c_u|, y = h x x/|h x x|, z = x x y, and
!> r = c + y s_y(v) + z s_z(v) with s = [0, -r cos v, -r sin v] (thesis 4.2).
!>
!> chi_u: the thesis (4.9) differentiates chi by the centerline parameter u.
!> With f3 in kg m the friction term f3 chi_u w^2 is a force only if u is an
!> arc length (chi_u in 1/m^2); the thesis's centerline parameter is close to
!> arc length. `curvature` therefore returns the derivative by arc length,
!> chi_s = chi_u/|c_u|, which equals (4.9) on arc-length parametrized lines.
module water_channel
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_DOMAIN, &
    STATUS_NOT_CONVERGED
  use base_vector, only: cross
  use geometry_surface, only: surface_point_t
  implicit none (type, external)
  private
  public :: channel_t, analytic_tube_t, new_straight_tube, new_helix_tube, new_s_bend_tube
  public :: curvature_from_derivatives, unit_derivatives
  public :: TUBE_STRAIGHT, TUBE_HELIX, TUBE_S_BEND

  integer, parameter :: TUBE_STRAIGHT = 1, TUBE_HELIX = 2, TUBE_S_BEND = 3

  type, abstract :: channel_t
  contains
    !> r(u, v) and partials to `order` (0..2 required, 3 where available).
    procedure(channel_evaluate_i), deferred :: evaluate
    !> Centerline c(u) and its u-derivatives: c(:, k) = d^k c/du^k, k = 0..3.
    procedure(channel_centerline_i), deferred :: centerline
    !> Parameter range of u (the slide runs from u_min to u_max).
    procedure(channel_range_i), deferred :: u_range
    !> Radius of the circular cross-section at u, or 0 if the section is not a circle.
    procedure(channel_radius_i), deferred :: circle_radius
    !> Range of v on the surface (+-huge for a closed tube).
    procedure :: v_range => channel_v_range
    !> Whether the profile changes along u (the water area then depends on u).
    procedure :: section_varies => channel_section_varies
    procedure :: curvature => channel_curvature
    procedure :: arc_length => channel_arc_length
    procedure :: parameter_at_length => channel_parameter_at_length
    procedure :: describe => channel_describe
    !> Units of u and v for result files (UDUNITS/pint text).
    procedure :: parameter_units => channel_parameter_units
  end type channel_t

  abstract interface
    pure subroutine channel_evaluate_i(self, u, v, order, p, status)
      import :: channel_t, surface_point_t, status_t, wp
      class(channel_t), intent(in) :: self
      real(wp), intent(in) :: u, v
      integer, intent(in) :: order
      type(surface_point_t), intent(out) :: p
      type(status_t), intent(out) :: status
    end subroutine channel_evaluate_i
    pure subroutine channel_centerline_i(self, u, c, status)
      import :: channel_t, status_t, wp
      class(channel_t), intent(in) :: self
      real(wp), intent(in) :: u
      real(wp), intent(out) :: c(3, 0:3)
      type(status_t), intent(out) :: status
    end subroutine channel_centerline_i
    pure subroutine channel_range_i(self, u_min, u_max)
      import :: channel_t, wp
      class(channel_t), intent(in) :: self
      real(wp), intent(out) :: u_min, u_max
    end subroutine channel_range_i
    pure real(wp) function channel_radius_i(self, u) result(radius)
      import :: channel_t, wp
      class(channel_t), intent(in) :: self
      real(wp), intent(in) :: u
    end function channel_radius_i
  end interface

  !> A circular tube of radius `radius` around an analytic centerline:
  !> straight:  c = u [cos t, 0, -sin t]                    (u in m, t = incline)
  !> helix:     c = [rho cos(s u), rho sin(s u), -p u]      (u in rad, s = +-1 turn sense)
  !> S-bend:    c = [u, a sin(k u), -q u]                   (u in m; a < 0 mirrors it)
  type, extends(channel_t) :: analytic_tube_t
    integer :: kind = TUBE_STRAIGHT
    real(wp) :: radius = 0.5_wp          ! m, tube radius
    real(wp) :: incline = 0              ! rad (straight)
    real(wp) :: helix_radius = 3         ! m (helix rho)
    real(wp) :: pitch = 0.3_wp           ! m/rad (helix p; descent per radian)
    real(wp) :: turn_sense = 1           ! +1 counter-clockwise seen from above, -1 clockwise
    real(wp) :: amplitude = 1            ! m (S-bend a)
    real(wp) :: wavenumber = 0.5_wp      ! 1/m (S-bend k)
    real(wp) :: slope = 0.1_wp           ! 1 (S-bend q, descent per m)
    real(wp) :: u_min = 0, u_max = 10
  contains
    procedure :: evaluate => tube_evaluate
    procedure :: centerline => tube_centerline
    procedure :: u_range => tube_range
    procedure :: circle_radius => tube_circle_radius
    procedure :: arc_length => tube_arc_length
    procedure :: describe => tube_describe
    procedure :: parameter_units => tube_parameter_units
  end type analytic_tube_t

contains

  ! ------------------------------------------------------------ channel defaults

  pure subroutine channel_v_range(self, v_min, v_max)
    class(channel_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    associate (unused => self)
    end associate
    v_min = -huge(1.0_wp); v_max = huge(1.0_wp)
  end subroutine channel_v_range

  pure logical function channel_section_varies(self) result(varies)
    class(channel_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .false.
  end function channel_section_varies

  pure function channel_describe(self) result(text)
    class(channel_t), intent(in) :: self
    character(len=:), allocatable :: text
    associate (unused => self)
    end associate
    text = 'channel'
  end function channel_describe

  !> Centerline curvature chi (4.8) and its derivative by arc length (4.9)/|c_u|.
  pure subroutine channel_curvature(self, u, chi, chi_s, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: chi, chi_s        ! 1/m, 1/m^2
    type(status_t), intent(out) :: status
    real(wp) :: c(3, 0:3)
    call self%centerline(u, c, status)
    if (.not. status%ok()) then
      chi = 0; chi_s = 0
      return
    end if
    call curvature_from_derivatives(c, chi, chi_s)
  end subroutine channel_curvature

  !> chi = |c' x c''|/|c'|^3 (4.8); chi_u from (4.9); returned chi_s = chi_u/|c'|.
  !> Where c' x c'' = 0 (a straight piece or an inflection) chi has a kink or
  !> is flat; chi_s is taken as 0 there.
  pure subroutine curvature_from_derivatives(c, chi, chi_s)
    real(wp), intent(in) :: c(3, 0:3)
    real(wp), intent(out) :: chi, chi_s
    real(wp) :: k(3), speed, k_norm, k_norm_u, speed3_u
    k = cross(c(:, 1), c(:, 2))
    speed = norm2(c(:, 1))
    k_norm = norm2(k)
    chi = k_norm/speed**3
    if (k_norm <= 1e-14_wp*speed**3) then
      chi_s = 0
      return
    end if
    k_norm_u = dot_product(cross(c(:, 1), c(:, 3)), k)/k_norm      ! |c' x c''|_u (4.9)
    speed3_u = 3*dot_product(c(:, 1), c(:, 2))*speed               ! (|c'|^3)_u (4.9)
    chi_s = (k_norm_u*speed**3 - k_norm*speed3_u)/speed**6/speed
  end subroutine curvature_from_derivatives

  !> Arc length of the centerline from u_min to u: 8-point Gauss-Legendre on
  !> 64 panels (exact to rounding for the smooth centerlines used here).
  function channel_arc_length(self, u) result(s)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: s
    real(wp), parameter :: x(4) = [0.1834346424956498_wp, 0.5255324099163290_wp, &
                                   0.7966664774136267_wp, 0.9602898564975363_wp]
    real(wp), parameter :: wt(4) = [0.3626837833783620_wp, 0.3137066458778873_wp, &
                                    0.2223810344533745_wp, 0.1012285362903763_wp]
    integer, parameter :: panels = 64
    real(wp) :: u_min, u_max, a, h, mid, c(3, 0:3)
    type(status_t) :: st
    integer :: i, j
    call self%u_range(u_min, u_max)
    s = 0
    h = (u - u_min)/panels
    do i = 1, panels
      a = u_min + (i - 1)*h
      mid = a + h/2
      do j = 1, 4
        call self%centerline(mid + h/2*x(j), c, st)
        s = s + h/2*wt(j)*norm2(c(:, 1))
        call self%centerline(mid - h/2*x(j), c, st)
        s = s + h/2*wt(j)*norm2(c(:, 1))
      end do
    end do
  end function channel_arc_length

  !> The parameter u at arc length s from u_min (Newton on arc_length, safeguarded).
  subroutine channel_parameter_at_length(self, s, u, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: s
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    real(wp) :: u_min, u_max, lo, hi, f, c(3, 0:3), total
    integer :: it
    call self%u_range(u_min, u_max)
    total = self%arc_length(u_max)
    if (s < 0 .or. s > total*(1 + 1e-12_wp)) then
      call set_status(status, STATUS_INVALID_INPUT, 'arc length outside the slide')
      u = u_min
      return
    end if
    lo = u_min; hi = u_max
    u = u_min + (u_max - u_min)*s/total
    do it = 1, 100
      f = self%arc_length(u) - s
      if (abs(f) <= 1e-12_wp*max(total, 1.0_wp)) return
      if (f > 0) then
        hi = u
      else
        lo = u
      end if
      call self%centerline(u, c, status)
      if (.not. status%ok()) return
      u = u - f/norm2(c(:, 1))
      if (u <= lo .or. u >= hi) u = (lo + hi)/2
    end do
    call set_status(status, STATUS_NOT_CONVERGED, 'parameter at arc length did not converge')
  end subroutine channel_parameter_at_length

  ! ------------------------------------------------------------ analytic tubes

  !> Straight circular tube of radius r falling at `incline` (rad), length `length` (m).
  function new_straight_tube(radius, incline, length) result(t)
    real(wp), intent(in) :: radius, incline, length
    type(analytic_tube_t) :: t
    t%kind = TUBE_STRAIGHT
    t%radius = radius; t%incline = incline
    t%u_min = 0; t%u_max = length
  end function new_straight_tube

  !> Helical tube about the z-axis: centerline radius rho, descent `pitch` per
  !> radian, turn sense +1/-1, u over [0, turns 2 pi].
  function new_helix_tube(radius, helix_radius, pitch, turn_sense, u_max) result(t)
    real(wp), intent(in) :: radius, helix_radius, pitch, turn_sense, u_max
    type(analytic_tube_t) :: t
    t%kind = TUBE_HELIX
    t%radius = radius; t%helix_radius = helix_radius; t%pitch = pitch
    t%turn_sense = sign(1.0_wp, turn_sense)
    t%u_min = 0; t%u_max = u_max
  end function new_helix_tube

  !> S-bend c = [u, a sin(k u), -q u] over [0, length].
  function new_s_bend_tube(radius, amplitude, wavenumber, slope, length) result(t)
    real(wp), intent(in) :: radius, amplitude, wavenumber, slope, length
    type(analytic_tube_t) :: t
    t%kind = TUBE_S_BEND
    t%radius = radius; t%amplitude = amplitude; t%wavenumber = wavenumber; t%slope = slope
    t%u_min = 0; t%u_max = length
  end function new_s_bend_tube

  !> c and its derivatives to 4th order (the 4th only for r_uuu).
  pure subroutine tube_centerline4(self, u, c)
    class(analytic_tube_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: c(3, 0:4)
    real(wp) :: cs, sn, rho, s, a, k
    c = 0
    select case (self%kind)
    case (TUBE_HELIX)
      rho = self%helix_radius; s = self%turn_sense
      cs = cos(s*u); sn = sin(s*u)
      c(:, 0) = [rho*cs, rho*sn, -self%pitch*u]
      c(:, 1) = [-rho*s*sn, rho*s*cs, -self%pitch]
      c(:, 2) = [-rho*cs, -rho*sn, 0.0_wp]
      c(:, 3) = [rho*s*sn, -rho*s*cs, 0.0_wp]
      c(:, 4) = [rho*cs, rho*sn, 0.0_wp]
    case (TUBE_S_BEND)
      a = self%amplitude; k = self%wavenumber
      cs = cos(k*u); sn = sin(k*u)
      c(:, 0) = [u, a*sn, -self%slope*u]
      c(:, 1) = [1.0_wp, a*k*cs, -self%slope]
      c(:, 2) = [0.0_wp, -a*k**2*sn, 0.0_wp]
      c(:, 3) = [0.0_wp, -a*k**3*cs, 0.0_wp]
      c(:, 4) = [0.0_wp, a*k**4*sn, 0.0_wp]
    case default
      c(:, 1) = [cos(self%incline), 0.0_wp, -sin(self%incline)]
      c(:, 0) = u*c(:, 1)
    end select
  end subroutine tube_centerline4

  pure subroutine tube_centerline(self, u, c, status)
    class(analytic_tube_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: c(3, 0:3)
    type(status_t), intent(out) :: status
    real(wp) :: c4(3, 0:4)
    status%code = 0
    call tube_centerline4(self, u, c4)
    c = c4(:, 0:3)
  end subroutine tube_centerline

  !> Unit vector e = a/|a| and its derivatives to order n (<= 3) from those of a:
  !> with L = |a|: L' = e.a', L L'' = a'.a' + a.a'' - L'^2,
  !> L L''' = 3 a'.a'' + a.a''' - 3 L' L'', and
  !> e' = (a' - L' e)/L, e'' = (a'' - 2 L' e' - L'' e)/L,
  !> e''' = (a''' - 3 L' e'' - 3 L'' e' - L''' e)/L (differentiate a = L e).
  pure subroutine unit_derivatives(a, n, e)
    real(wp), intent(in) :: a(3, 0:3)
    integer, intent(in) :: n
    real(wp), intent(out) :: e(3, 0:3)
    real(wp) :: l0, l1, l2, l3
    e = 0
    l0 = norm2(a(:, 0))
    e(:, 0) = a(:, 0)/l0
    if (n < 1) return
    l1 = dot_product(e(:, 0), a(:, 1))
    e(:, 1) = (a(:, 1) - l1*e(:, 0))/l0
    if (n < 2) return
    l2 = (dot_product(a(:, 1), a(:, 1)) + dot_product(a(:, 0), a(:, 2)) - l1**2)/l0
    e(:, 2) = (a(:, 2) - 2*l1*e(:, 1) - l2*e(:, 0))/l0
    if (n < 3) return
    l3 = (3*dot_product(a(:, 1), a(:, 2)) + dot_product(a(:, 0), a(:, 3)) - 3*l1*l2)/l0
    e(:, 3) = (a(:, 3) - 3*l1*e(:, 2) - 3*l2*e(:, 1) - l3*e(:, 0))/l0
  end subroutine unit_derivatives

  !> r = c + y s_y + z s_z (3.64) with the horizon frame (3.61-3.63), h = e_z.
  pure subroutine tube_evaluate(self, u, v, order, p, status)
    class(analytic_tube_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp), parameter :: h(3) = [0, 0, 1]
    real(wp) :: c(3, 0:4), x(3, 0:3), a(3, 0:3), y(3, 0:3), z(3, 0:3)
    real(wp) :: sy(0:3), sz(0:3), r
    integer :: k, n

    if (order < 0 .or. order > 3) then
      call set_status(status, STATUS_INVALID_INPUT, 'analytic tube: order must be 0..3')
      return
    end if
    status%code = 0
    call tube_centerline4(self, u, c)
    call unit_derivatives(c(:, 1:4), order, x)
    do k = 0, order
      a(:, k) = cross(h, x(:, k))
    end do
    if (order < 3) a(:, order + 1:) = 0
    if (norm2(a(:, 0)) <= 1e-12_wp) then
      call set_status(status, STATUS_DOMAIN, 'analytic tube: tangent parallel to the horizon vector')
      return
    end if
    call unit_derivatives(a, order, y)
    z = 0
    do n = 0, order   ! Leibniz: z^(n) = sum C(n,k) x^(k) x y^(n-k)
      do k = 0, n
        z(:, n) = z(:, n) + binomial(n, k)*cross(x(:, k), y(:, n - k))
      end do
    end do
    r = self%radius
    sy = [-r*cos(v), r*sin(v), r*cos(v), -r*sin(v)]     ! s_y and its v-derivatives
    sz = [-r*sin(v), -r*cos(v), r*sin(v), r*cos(v)]     ! s_z and its v-derivatives
    p%order = order
    p%r = c(:, 0) + y(:, 0)*sy(0) + z(:, 0)*sz(0)
    if (order >= 1) then
      p%ru = c(:, 1) + y(:, 1)*sy(0) + z(:, 1)*sz(0)
      p%rv = y(:, 0)*sy(1) + z(:, 0)*sz(1)
    end if
    if (order >= 2) then
      p%ruu = c(:, 2) + y(:, 2)*sy(0) + z(:, 2)*sz(0)
      p%ruv = y(:, 1)*sy(1) + z(:, 1)*sz(1)
      p%rvv = y(:, 0)*sy(2) + z(:, 0)*sz(2)
    end if
    if (order >= 3) then
      p%ruuu = c(:, 3) + y(:, 3)*sy(0) + z(:, 3)*sz(0)
      p%ruuv = y(:, 2)*sy(1) + z(:, 2)*sz(1)
      p%ruvv = y(:, 1)*sy(2) + z(:, 1)*sz(2)
      p%rvvv = y(:, 0)*sy(3) + z(:, 0)*sz(3)
    end if
  end subroutine tube_evaluate

  pure real(wp) function binomial(n, k)
    integer, intent(in) :: n, k
    integer :: i
    binomial = 1
    do i = 1, k
      binomial = binomial*(n - k + i)/i
    end do
  end function binomial

  pure subroutine tube_range(self, u_min, u_max)
    class(analytic_tube_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = self%u_min; u_max = self%u_max
  end subroutine tube_range

  pure real(wp) function tube_circle_radius(self, u) result(radius)
    class(analytic_tube_t), intent(in) :: self
    real(wp), intent(in) :: u
    associate (unused => u)
    end associate
    radius = self%radius
  end function tube_circle_radius

  !> Closed forms for the straight tube and the helix; quadrature for the S-bend.
  function tube_arc_length(self, u) result(s)
    class(analytic_tube_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: s
    select case (self%kind)
    case (TUBE_STRAIGHT)
      s = u - self%u_min
    case (TUBE_HELIX)
      s = sqrt(self%helix_radius**2 + self%pitch**2)*(u - self%u_min)
    case default
      s = channel_arc_length(self, u)
    end select
  end function tube_arc_length

  pure function tube_describe(self) result(text)
    class(analytic_tube_t), intent(in) :: self
    character(len=:), allocatable :: text
    select case (self%kind)
    case (TUBE_HELIX); text = 'helical circular tube'
    case (TUBE_S_BEND); text = 'S-bend circular tube'
    case default; text = 'straight circular tube'
    end select
  end function tube_describe

  pure subroutine channel_parameter_units(self, u_units, v_units)
    class(channel_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    associate (unused => self)
    end associate
    u_units = '1'; v_units = '1'
  end subroutine channel_parameter_units

  !> u: m along the straight and the S-bend, rad around the helix; v: rad.
  pure subroutine tube_parameter_units(self, u_units, v_units)
    class(analytic_tube_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    u_units = merge('rad', 'm  ', self%kind == TUBE_HELIX)
    u_units = trim(u_units)
    v_units = 'rad'
  end subroutine tube_parameter_units
end module water_channel
