!> The vertical profile of a drop: the near-vertical free fall of a
!> trap-door start and its curve-out at the bottom, as the gradient
!> g(sigma) = tan(pitch) over the horizontal arc length sigma (m) that the
!> element chain (geometry_slide_elements) uses.
!>
!> With q = sin(pitch) (pitch downhill positive), dq/dsigma is minus the
!> curvature of the profile in its vertical plane: a vertical circle of
!> radius R is q linear in sigma with slope -1/R. The drop is
!>   [0, fall]            straight at the top slope (q = q_top),
!>   a ramp of width w1   curvature 0 -> 1/R by the septic smoothstep S,
!>   a core               the circle of radius R (the curve-out proper),
!>   a ramp of width w2   curvature 1/R -> 0, ending at the exit slope,
!> so q(sigma) = q_top - [w1 P(t0) - w2 P(t2)]/R, t0 = (sigma - fall)/w1,
!> t2 = (sigma - fall - w1 - core)/w2, P the integral of S: the curvature is
!> C3 (clothoid-like transitions; w = 0, a circle whose curvature jumps at
!> its ends, is refused: the speed of whatever rides it would jump there, as
!> at a sharp joint of the chain). A ramp is the chain's transition length L as arc length:
!> w = L cos(pitch) horizontally at its end of the circle (it turns the
!> pitch by about L/(2R), as a clothoid of length L), at most a quarter of
!> the turn R (q_top - q_exit), so the core is never shorter than a ramp.
!> g = q / sqrt(1 - q^2) and its sigma-derivatives follow by the
!> chain rule; the height lost, the integral of g, is closed-form on the
!> straight and tabulated over the curve-out (nodes every <= 0.05 m with the
!> ramps' ends as nodes, 8-point Gauss-Legendre from the nearest node below:
!> exact to ~1e-14 m, since g is smooth between nodes).
!> The fall is sized so that the whole element loses `height`.
module geometry_drop_profile
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_real
  use numerics_quadrature, only: gl8_x, gl8_w, piecewise_nodes, node_below
  implicit none (type, external)
  private
  public :: drop_profile_t, new_drop_profile, smoothstep, smoothstep_value, smoothstep_integral

  !> Steepest top slope and largest node spacing of the curve-out table.
  real(wp), parameter, public :: drop_max_slope_deg = 85, drop_min_slope_deg = 45
  real(wp), parameter :: node_spacing = 0.05_wp   ! m

  type :: drop_profile_t
    real(wp) :: q_top = 0, q_exit = 0        ! sine of the pitch at the top and at the exit
    real(wp) :: g_top = 0, g_exit = 0        ! gradients tan(pitch) there
    real(wp) :: radius = 0                   ! m, the curve-out's radius in its vertical plane
    real(wp) :: ramp_top = 0, ramp_exit = 0  ! m, horizontal widths of the curvature ramps
    real(wp) :: core = 0                     ! m, horizontal length of the circle
    real(wp) :: fall = 0                     ! m, horizontal length of the straight fall
    real(wp) :: total = 0                    ! m, horizontal length of the element
    real(wp), allocatable :: node(:)         ! m, sigma - fall of the table's nodes (0 .. the curve-out's end)
    real(wp), allocatable :: excess(:)       ! m, int of (g - g_exit) from the fall's end to each node
  contains
    procedure :: deviation => drop_deviation
    procedure :: pitch_sine => drop_pitch_sine
    procedure :: gradient_deviation => drop_gradient_deviation
  end type drop_profile_t

contains

  !> The drop losing `height` (m) from the top slope `slope_deg` through a
  !> curve-out of radius `radius` (m) to the exit gradient `exit_gradient`
  !> (the next element's), with curvature ramps of at most `ramp` m. The
  !> message says what does not fit.
  function new_drop_profile(height, slope_deg, radius, exit_gradient, ramp, status) result(d)
    real(wp), intent(in) :: height, slope_deg, radius, exit_gradient, ramp
    type(status_t), intent(out) :: status
    type(drop_profile_t) :: d
    real(wp) :: turn, curve_out_height
    integer :: k
    integer, allocatable :: pieces(:)
    real(wp) :: ends(0:3)
    if (.not. (slope_deg >= drop_min_slope_deg .and. slope_deg <= drop_max_slope_deg)) then
      call set_status(status, STATUS_INVALID_INPUT, 'slope_deg = '//format_real(slope_deg)// &
                      ': a drop falls at a slope in ['//format_real(drop_min_slope_deg)//', '// &
                      format_real(drop_max_slope_deg)//'] deg')
      return
    end if
    if (.not. (radius > 0 .and. height > 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'a drop needs a radius > 0 m and a drop (height) > 0 m')
      return
    end if
    if (.not. ramp > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'transition_length = 0 would give the curve-out sharp '// &
                      'ends: its curvature would jump between 0 and 1/R there, and a rider''s or the water''s '// &
                      'speed with the slide''s parameter speed |r_u| (a wrong answer, not physics); give '// &
                      'transition_length > 0')
      return
    end if
    d%q_top = sin(slope_deg*pi/180)
    d%g_top = tan(slope_deg*pi/180)
    d%g_exit = exit_gradient
    d%q_exit = exit_gradient/sqrt(1 + exit_gradient**2)
    d%radius = radius
    if (.not. d%q_exit < d%q_top) then
      call set_status(status, STATUS_INVALID_INPUT, 'the element after a drop must be less steep than the drop ('// &
                      format_real(slope_deg)//' deg)')
      return
    end if
    turn = radius*(d%q_top - d%q_exit)
    d%ramp_top = min(ramp*sqrt(1 - d%q_top**2), turn/4)
    d%ramp_exit = min(ramp*sqrt(1 - d%q_exit**2), turn/4)
    d%core = turn - (d%ramp_top + d%ramp_exit)/2
    ends = [0.0_wp, d%ramp_top, d%ramp_top + d%core, d%ramp_top + d%core + d%ramp_exit]
    ! the table over the curve-out, each piece in equal steps of <= node_spacing
    call piecewise_nodes(ends, node_spacing, d%node, pieces)
    allocate (d%excess(0:ubound(d%node, 1)))
    d%excess(0) = 0
    do k = 1, ubound(d%node, 1)
      d%excess(k) = d%excess(k - 1) + excess_integral(d, d%node(k - 1), d%node(k))
    end do
    curve_out_height = d%excess(ubound(d%excess, 1)) + d%g_exit*ends(3)
    if (.not. height >= curve_out_height) then
      call set_status(status, STATUS_INVALID_INPUT, 'drop = '//format_real(height)//' m is less than its '// &
                      'curve-out of radius '//format_real(radius)//' m alone loses ('// &
                      format_real(curve_out_height)//' m): give a larger drop or a smaller radius')
      return
    end if
    d%fall = (height - curve_out_height)/d%g_top
    d%total = d%fall + ends(3)
  end function new_drop_profile

  !> q = sin(pitch) and its sigma-derivatives q(0:3) at sigma - fall = s.
  pure subroutine curve_out_sine(d, s, q)
    type(drop_profile_t), intent(in) :: d
    real(wp), intent(in) :: s
    real(wp), intent(out) :: q(0:3)
    real(wp) :: s0(0:3), p0, s2(0:3), p2
    integer :: m
    call ramp(s, d%ramp_top, s0, p0)
    call ramp(s - d%ramp_top - d%core, d%ramp_exit, s2, p2)
    q(0) = d%q_top - (p0 - p2)/d%radius
    do m = 1, 3
      q(m) = -(s0(m - 1) - s2(m - 1))/d%radius
    end do
  end subroutine curve_out_sine

  !> A curvature ramp of horizontal width `width` that starts at s = 0: the
  !> smoothstep S(s/width) and its s-derivatives (d(0:3)) and its integral
  !> from 0 to s (m). The width is > 0 (new_drop_profile).
  pure subroutine ramp(s, width, d, integral)
    real(wp), intent(in) :: s, width
    real(wp), intent(out) :: d(0:3), integral
    integer :: m
    call smoothstep(s/width, d, integral)
    integral = width*integral
    do m = 1, 3
      d(m) = d(m)/width**m
    end do
  end subroutine ramp

  !> g - g_exit at sigma - fall = s (the table's integrand).
  pure real(wp) function excess_gradient(d, s)
    type(drop_profile_t), intent(in) :: d
    real(wp), intent(in) :: s
    real(wp) :: q(0:3)
    call curve_out_sine(d, s, q)
    excess_gradient = q(0)/sqrt(1 - q(0)**2) - d%g_exit
  end function excess_gradient

  !> int_a^b (g - g_exit) ds over one step of the table (8-point Gauss-Legendre).
  pure real(wp) function excess_integral(d, a, b) result(integral)
    type(drop_profile_t), intent(in) :: d
    real(wp), intent(in) :: a, b
    real(wp) :: x
    integer :: i
    x = 0
    do i = 1, 8
      x = x + gl8_w(i)*excess_gradient(d, 0.5_wp*(a + b) + 0.5_wp*(b - a)*gl8_x(i))
    end do
    integral = 0.5_wp*(b - a)*x
  end function excess_integral

  !> sin(pitch) at sigma (m) and its sigma-derivatives (q(0:3)).
  pure subroutine drop_pitch_sine(self, sigma, q)
    class(drop_profile_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: q(0:3)
    if (sigma <= self%fall) then
      q = [self%q_top, 0.0_wp, 0.0_wp, 0.0_wp]
    else
      call curve_out_sine(self, min(sigma, self%total) - self%fall, q)
      if (sigma > self%total) q(1:3) = 0
    end if
  end subroutine drop_pitch_sine

  !> What the drop adds to a chain whose gradient is g_exit: dg(0:3) = g - g_exit
  !> and its sigma-derivatives at sigma, and dint = int_0^sigma (g - g_exit)
  !> (m; constant past the drop's end).
  pure subroutine drop_deviation(self, sigma, dg, dint)
    class(drop_profile_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: dg(0:3), dint
    real(wp) :: q(0:3), c, g1, g2, g3, s
    integer :: lo
    dg = 0
    if (sigma >= self%total) then
      dint = (self%g_top - self%g_exit)*self%fall + self%excess(ubound(self%excess, 1))
      return
    end if
    call self%pitch_sine(sigma, q)
    c = 1 - q(0)**2                        ! cos^2(pitch)
    g1 = c**(-1.5_wp)                      ! dg/dq
    g2 = 3*q(0)*c**(-2.5_wp)
    g3 = (3 + 12*q(0)**2)*c**(-3.5_wp)
    dg(0) = q(0)/sqrt(c) - self%g_exit
    dg(1) = g1*q(1)
    dg(2) = g2*q(1)**2 + g1*q(2)
    dg(3) = g3*q(1)**3 + 3*g2*q(1)*q(2) + g1*q(3)
    if (sigma <= self%fall) then
      dint = (self%g_top - self%g_exit)*max(sigma, 0.0_wp)
      return
    end if
    s = sigma - self%fall
    lo = node_below(self%node, s)
    dint = (self%g_top - self%g_exit)*self%fall + self%excess(lo) + excess_integral(self, self%node(lo), s)
  end subroutine drop_deviation

  !> drop_deviation's dg(0) alone, g - g_exit at sigma (the chain's arc
  !> length needs only the gradient).
  pure real(wp) function drop_gradient_deviation(self, sigma) result(dg)
    class(drop_profile_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp) :: q(0:3)
    dg = 0
    if (sigma >= self%total) return
    call self%pitch_sine(sigma, q)
    dg = q(0)/sqrt(1 - q(0)**2) - self%g_exit
  end function drop_gradient_deviation

  !> Smoothstep S(t) and its t-derivatives (d(0:3)) and its integral P(t) =
  !> int_0^t S, with S = 0 for t < 0 and 1 for t > 1 (P continued).
  pure subroutine smoothstep(t, d, integral)
    real(wp), intent(in) :: t
    real(wp), intent(out) :: d(0:3), integral
    d = 0
    integral = smoothstep_integral(t)
    if (t <= 0) then
      return
    else if (t >= 1) then
      d(0) = 1
    else
      d(0) = smoothstep_value(t)
      d(1) = 140*t**3*(1 - t)**3
      d(2) = 420*t**2*(1 - t)**2*(1 - 2*t)
      d(3) = 840*t*(1 - t)*((1 - 2*t)**2 - t*(1 - t))
    end if
  end subroutine smoothstep

  !> S(t) alone (smoothstep's d(0)), for the sums that need no derivative.
  pure real(wp) function smoothstep_value(t) result(s)
    real(wp), intent(in) :: t
    if (t <= 0) then
      s = 0
    else if (t >= 1) then
      s = 1
    else
      s = t**4*(35 - 84*t + 70*t**2 - 20*t**3)
    end if
  end function smoothstep_value

  !> P(t) = int_0^t S alone (smoothstep's integral).
  pure real(wp) function smoothstep_integral(t) result(p)
    real(wp), intent(in) :: t
    if (t <= 0) then
      p = 0
    else if (t >= 1) then
      p = t - 0.5_wp
    else
      p = t**5*(7 - 14*t + 10*t**2 - 2.5_wp*t**3)
    end if
  end function smoothstep_integral
end module geometry_drop_profile
