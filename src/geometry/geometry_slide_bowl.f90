!> The bowl of a slide chain (geometry_slide_elements): the centerline
!> spirals down the inside of a surface of revolution z = z_b + f(rho) about
!> a vertical axis, from the entry at the distance rho_in from the axis to the
!> outlet at rho_out < rho_in, crossing every circle rho = const at the same
!> angle beta (a loxodrome of the bowl's horizontal plan, the logarithmic
!> spiral's kin). With sigma the horizontal arc length from the bowl's entry:
!>   rho(sigma)   = rho_in - sigma sin(beta)                (the plan)
!>   kappa(sigma) = s cos(beta)/rho                        (s = +1 left, -1 right)
!>   g(sigma)     = -dz/dsigma = sin(beta) f'(rho)         (the gradient)
!>   cot(beta)    = 2 pi turns / ln(rho_in/rho_out)        (turns about the axis)
!>   length       = (rho_in - rho_out)/sin(beta)           (horizontal)
!> and with d/dsigma = -sin(beta) d/drho,
!>   kappa^(m) = s cos(beta) m! sin(beta)^m / rho^(m+1),
!>   g^(m)     = sin(beta) (-sin(beta))^m f^(m+1)(rho).
!> The profile is given by the wall's slope theta_in at the entry (f'(rho_in)
!> = tan(theta_in)) and the height lost over the bowl, `drop`:
!>   sphere  f = R - sqrt(R^2 - rho^2), R = rho_in/sin(theta_in);
!>           f' = rho/q, f'' = R^2/q^3, f''' = 3 rho R^2/q^5,
!>           f'''' = 3 R^2 (R^2 + 4 rho^2)/q^7, q = sqrt(R^2 - rho^2);
!>           rho_out = sqrt(R^2 - (drop + R cos(theta_in))^2), so the drop is
!>           less than the depth below the entry, R (1 - cos(theta_in));
!>   cone    f = rho tan(theta) (theta = theta_in throughout): g constant;
!>           rho_out = rho_in - drop/tan(theta) > 0;
!>   table   f the quintic spline interpolating a table of (rho_i, z_i)
!>           (numerics_spline_curve over the parameter rho; f'''' is
!>           continuous, piecewise linear), theta_in from f'(rho_in);
!>           rho_out where f falls by `drop` below f(rho_in), found by
!>           bisection after f' > 0 is checked on a fine grid down to it
!>           (the wall must rise outward all the way, within the table).
!> In the chain the bowl is an element whose own kappa and g vary: the chain
!> blends each element's constants by windows W_i = S_(i-1) - S_i of its
!> joints' smoothsteps, and the bowl adds (kappa_b - kappa_ref) W_b and
!> (g_b - g_ref) W_b (kappa_ref, g_ref the constants the chain holds for it,
!> the entry's values). Its derivatives are Leibniz' rule with W_b^(m) =
!> S_in^(m) - S_out^(m); the heading and the height need their integrals:
!> between the windows (W_b = 1) closed-form, int kappa_b = -s cot(beta)
!> ln(rho) and int g_b = -f(rho), and within the windows tabulated (nodes
!> every <= 0.05 m, the windows' ends among them, 8-point Gauss-Legendre from
!> the nearest node below: exact to ~1e-14). Between the windows the
!> centerline is the spiral itself, on the surface of revolution about one
!> vertical axis; within them its curvature and gradient ramp C3 to the
!> neighbours'.
module geometry_slide_bowl
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_real, format_integer
  use numerics_quadrature, only: gl8_x, gl8_w, piecewise_nodes, node_below
  use numerics_spline_curve, only: spline_curve_t
  use geometry_drop_profile, only: smoothstep, smoothstep_value
  implicit none (type, external)
  private
  public :: bowl_spiral_t, new_bowl_spiral

  integer, parameter :: PROFILE_SPHERE = 1, PROFILE_CONE = 2, PROFILE_TABLE = 3
  !> The fewest points of a profile table (a quintic interpolant)
  integer, parameter :: min_table_points = 6
  !> Grid steps over the table on which a table profile's wall must rise
  integer, parameter :: rise_checks = 4000
  real(wp), parameter :: node_spacing = 0.05_wp    ! m, of the integral tables
  !> The steepest slope of a chain's centerline (geometry_slide_elements).
  real(wp), parameter :: max_slope_deg = 60
  !> The steepest wall of a spherical bowl the spiral's plan may reach (the
  !> profile's slope f' = rho/sqrt(R^2 - rho^2) is infinite at the equator).
  real(wp), parameter :: max_wall_deg = 85
  integer, parameter :: binom(0:3, 0:3) = reshape([1, 0, 0, 0, 1, 1, 0, 0, 1, 2, 1, 0, 1, 3, 3, 1], [4, 4])

  type :: bowl_spiral_t
    integer :: profile = PROFILE_SPHERE
    real(wp) :: rho_in = 0, rho_out = 0        ! m, from the axis at the entry and the outlet
    real(wp) :: sphere_radius = 0              ! m (sphere)
    real(wp) :: tan_wall = 0                   ! the cone's wall slope, tan(theta)
    type(spline_curve_t) :: table              ! z over rho (table)
    real(wp) :: table_lo = 0, table_hi = 0     ! m, the table's first and last rho
    real(wp) :: sin_beta = 0, cos_beta = 0     ! the spiral's angle to the circles rho = const
    real(wp) :: sense = 1                      ! +1 left (anticlockwise seen from above), -1 right
    real(wp) :: length = 0                     ! m, horizontal
    real(wp) :: kappa_ref = 0, grad_ref = 0    ! the chain's constants for the element (the entry's)
    real(wp) :: sigma0 = 0                     ! m, the chain's sigma at the entry
    real(wp) :: width_in = 0, width_out = 0    ! m, the joints' transitions (0: no joint)
    real(wp) :: lo = 0, hi = 0                 ! m, where W_b > 0
    real(wp), allocatable :: node(:)           ! m, sigma of the table's nodes, lo .. hi
    real(wp), allocatable :: psi(:), rise(:)   ! rad, m: int of the deviations from lo to each node
    real(wp) :: core_lo = 0, core_hi = 0       ! m, between the windows (W_b = 1)
    real(wp) :: psi_core = 0, rise_core = 0    ! rad, m: the integrals from lo to core_lo
  contains
    procedure :: place => bowl_place
    procedure :: deviation => bowl_deviation
    procedure :: heading => bowl_heading
    procedure :: gradient_deviation => bowl_gradient_deviation
    procedure :: own => bowl_own
    procedure :: radius_at => bowl_radius_at
    procedure :: height_above_bottom => bowl_height_above_bottom
  end type bowl_spiral_t

contains

  !> The spiral of a bowl of `profile` ('sphere', 'cone', 'table') entered
  !> at `rho_in` m from its axis where the wall rises at `slope_deg` (not a
  !> table's: its own slope there), losing `drop` m over `turns` turns in
  !> `sense` (+1 left, -1 right); a table profile's points (`table_rho`
  !> increasing, `table_z`, m). The message names the value.
  function new_bowl_spiral(profile, rho_in, slope_deg, drop, turns, sense, status, table_rho, table_z) result(b)
    character(len=*), intent(in) :: profile
    real(wp), intent(in) :: rho_in, slope_deg, drop, turns, sense
    type(status_t), intent(out) :: status
    real(wp), intent(in), optional :: table_rho(:), table_z(:)
    type(bowl_spiral_t) :: b
    real(wp) :: theta, depth, cot_beta, q_out, f(0:3), steepest, rho_steepest, rho
    integer :: i
    character(len=:), allocatable :: place
    if (.not. rho_in > 0) then
      call refuse('radius = '//format_real(rho_in)//' m: a bowl needs the entry''s distance from its axis > 0')
    else if (trim(profile) == 'table') then
      continue   ! the table gives the slope
    else if (.not. (slope_deg > 0 .and. slope_deg <= max_wall_deg)) then
      call refuse('slope_deg = '//format_real(slope_deg)//': the bowl''s wall at the entry must rise at a slope '// &
                  'in (0, '//format_real(max_wall_deg)//'] deg (a sphere''s wall is vertical at its equator, the '// &
                  'rim of a hemisphere; an entry there or above it is no bowl)')
    else if (.not. drop > 0) then
      call refuse('drop = '//format_real(drop)//' m: a bowl loses height (> 0) from its entry to its outlet')
    else if (.not. turns > 0) then
      call refuse('turns = '//format_real(turns)//': a bowl''s spiral needs turns > 0')
    end if
    if (.not. status%ok()) return
    theta = slope_deg*pi/180
    b%rho_in = rho_in
    b%sense = sense
    select case (trim(profile))
    case ('table')
      b%profile = PROFILE_TABLE
      if (.not. (present(table_rho) .and. present(table_z))) then
        call refuse('bowl_profile = ''table'' needs the profile''s points (bowl_rho, bowl_z)')
        return
      end if
      call table_profile(b, table_rho, table_z, drop, status)
      if (.not. status%ok()) return
    case ('sphere')
      b%profile = PROFILE_SPHERE
      b%sphere_radius = rho_in/sin(theta)
      depth = b%sphere_radius*(1 - cos(theta))
      if (.not. drop < depth) then
        call refuse('drop = '//format_real(drop)//' m reaches the bottom of the spherical bowl (radius '// &
                    format_real(b%sphere_radius)//' m), '//format_real(depth)//' m below the entry: the outlet '// &
                    'must be off the axis, so give a smaller drop, a steeper entry or a wider bowl')
        return
      end if
      q_out = drop + b%sphere_radius*cos(theta)
      b%rho_out = sqrt(b%sphere_radius**2 - q_out**2)
    case ('cone')
      b%profile = PROFILE_CONE
      b%tan_wall = tan(theta)
      b%rho_out = rho_in - drop/b%tan_wall
      if (.not. b%rho_out > 0) then
        call refuse('drop = '//format_real(drop)//' m reaches the apex of the conical bowl, '// &
                    format_real(rho_in*b%tan_wall)//' m below the entry: the outlet must be off the axis, '// &
                    'so give a smaller drop or a wider bowl')
        return
      end if
    case default
      call refuse('bowl_profile = '''//trim(profile)//''' is not one of sphere, cone, table')
      return
    end select
    if (.not. b%rho_out >= 1e-3_wp*rho_in) then
      call refuse('the outlet would lie '//format_real(b%rho_out)//' m from the axis, less than 1e-3 of the '// &
                  'entry''s: give a smaller drop')
      return
    end if
    cot_beta = two_pi*turns/log(rho_in/b%rho_out)
    b%sin_beta = 1/sqrt(1 + cot_beta**2)
    b%cos_beta = cot_beta*b%sin_beta
    b%length = (rho_in - b%rho_out)/b%sin_beta
    call profile_slope(b, rho_in, f)
    b%kappa_ref = sense*b%cos_beta/rho_in
    b%grad_ref = b%sin_beta*f(0)
    ! the gradient is largest at the entry (f' grows with rho) but on a
    ! table, whose wall may steepen inward: there on the grid of its check
    steepest = b%grad_ref
    rho_steepest = rho_in
    if (b%profile == PROFILE_TABLE) then
      do i = 1, rise_checks
        rho = rho_in - (rho_in - b%rho_out)*i/real(rise_checks, wp)
        call profile_slope(b, rho, f)
        if (b%sin_beta*f(0) > steepest) then
          steepest = b%sin_beta*f(0)
          rho_steepest = rho
        end if
      end do
    end if
    if (.not. atan(steepest) < max_slope_deg*pi/180) then
      place = 'at the entry'
      if (rho_steepest < rho_in) place = format_real(rho_steepest)//' m from the axis'
      call refuse('the spiral would descend at '//format_real(atan(steepest)*180/pi)//' deg '//place// &
                  ', steeper than '//format_real(max_slope_deg)//' deg: give more turns or a gentler wall')
    end if

  contains

    subroutine refuse(what)
      character(len=*), intent(in) :: what
      call set_status(status, STATUS_INVALID_INPUT, what)
    end subroutine refuse
  end function new_bowl_spiral

  !> A table profile: the quintic interpolant of the points, the entry
  !> within them on a rising wall no steeper than max_wall_deg, and rho_out
  !> where the wall has fallen by `drop`, rising all the way down to it.
  subroutine table_profile(b, rho, z, drop, status)
    type(bowl_spiral_t), intent(inout) :: b
    real(wp), intent(in) :: rho(:), z(:), drop
    type(status_t), intent(inout) :: status
    real(wp) :: d(1, 0:1), target, lo, hi, step, mid, slope_deg
    integer :: n, i
    n = size(rho)
    if (size(z) /= n) then
      call refuse('the profile table has '//format_integer(n)//' radii (bowl_rho) but '//format_integer(size(z))// &
                  ' heights (bowl_z): give one height per radius')
    else if (n < min_table_points) then
      call refuse('the profile table has '//format_integer(n)//' points: a bowl''s profile needs at least '// &
                  format_integer(min_table_points)//' (a quintic through them)')
    else if (.not. (all(rho(2:) > rho(:n - 1)) .and. rho(1) >= 0)) then
      call refuse('the profile table''s radii (bowl_rho) must be >= 0 and increase from point to point')
    else if (.not. (b%rho_in >= rho(1) .and. b%rho_in <= rho(n))) then
      call refuse('radius = '//format_real(b%rho_in)//' m: the entry must lie within the profile table''s radii, '// &
                  format_real(rho(1))//' to '//format_real(rho(n))//' m')
    end if
    if (.not. status%ok()) return
    call b%table%fit(reshape(z, [1, n]), 0.0_wp, 5, status, parameters=rho)
    if (.not. status%ok()) return
    b%table_lo = rho(1)
    b%table_hi = rho(n)
    call b%table%evaluate(b%rho_in, d, 1)
    slope_deg = atan(d(1, 1))*180/pi
    if (.not. (d(1, 1) > 0 .and. slope_deg <= max_wall_deg)) then
      call refuse('the profile table''s wall rises at '//format_real(slope_deg)//' deg at the entry (radius = '// &
                  format_real(b%rho_in)//' m): a bowl''s wall must rise outward there, at most '// &
                  format_real(max_wall_deg)//' deg')
      return
    end if
    ! down from the entry on a fine grid: the wall rises outward until it has
    ! fallen by the drop; then bisection between the last two grid points
    target = d(1, 0) - drop
    step = (b%rho_in - b%table_lo)/rise_checks
    hi = b%rho_in
    do i = 1, rise_checks
      lo = b%rho_in - i*step
      call b%table%evaluate(lo, d, 1)
      if (.not. d(1, 1) > 0) then
        call refuse('drop = '//format_real(drop)//' m: the profile table''s wall stops rising outward at '// &
                    format_real(lo)//' m from the axis, before the bowl has lost its drop: give a smaller drop '// &
                    'or a profile that rises outward all the way down')
        return
      end if
      if (d(1, 0) <= target) exit
      hi = lo
    end do
    if (.not. d(1, 0) <= target) then
      call refuse('drop = '//format_real(drop)//' m reaches below the profile table''s first point ('// &
                  format_real(b%table_lo)//' m from the axis): give a smaller drop or a deeper table')
      return
    end if
    do i = 1, 200
      mid = (lo + hi)/2
      if (mid <= lo .or. mid >= hi) exit
      call b%table%evaluate(mid, d, 0)
      if (d(1, 0) > target) then
        hi = mid
      else
        lo = mid
      end if
    end do
    b%rho_out = hi

  contains

    subroutine refuse(what)
      character(len=*), intent(in) :: what
      call set_status(status, STATUS_INVALID_INPUT, what)
    end subroutine refuse
  end subroutine table_profile

  !> f'(rho) .. f''''(rho) (f(0:3)), the profile's slope and its derivatives.
  pure subroutine profile_slope(b, rho, f)
    type(bowl_spiral_t), intent(in) :: b
    real(wp), intent(in) :: rho
    real(wp), intent(out) :: f(0:3)
    real(wp) :: big, q, d(1, 0:4)
    if (b%profile == PROFILE_TABLE) then
      call b%table%evaluate(rho, d, 4)
      f = d(1, 1:4)
    else if (b%profile == PROFILE_CONE) then
      f = [b%tan_wall, 0.0_wp, 0.0_wp, 0.0_wp]
    else
      big = b%sphere_radius**2
      q = sqrt(big - rho**2)
      f = [rho/q, big/q**3, 3*rho*big/q**5, 3*big*(big + 4*rho**2)/q**7]
    end if
  end subroutine profile_slope

  !> Places the bowl in the chain: its entry at `sigma0` (m), its joints'
  !> transitions `width_in`, `width_out` (m; 0 where the bowl begins or ends
  !> the chain), and tabulates the integrals. Refuses an outlet transition
  !> that would carry the spiral's plan within rho_out/2 of the axis.
  subroutine bowl_place(self, sigma0, width_in, width_out, status)
    class(bowl_spiral_t), intent(inout) :: self
    real(wp), intent(in) :: sigma0, width_in, width_out
    type(status_t), intent(out) :: status
    real(wp) :: ends(0:3), a, c, x, y
    integer :: k
    integer, allocatable :: pieces(:)
    if (.not. width_out*self%sin_beta/2 <= self%rho_out/2) then
      call set_status(status, STATUS_INVALID_INPUT, 'the transition after the bowl ('//format_real(width_out)// &
                      ' m) would carry its spiral to the axis: give a shorter transition_length or a wider outlet')
      return
    end if
    if (self%profile == PROFILE_SPHERE) then
      if (.not. self%rho_in + width_in*self%sin_beta/2 <= self%sphere_radius*sin(max_wall_deg*pi/180)) then
        call set_status(status, STATUS_INVALID_INPUT, 'the transition before the bowl ('//format_real(width_in)// &
                        ' m) would carry its spiral up the sphere''s wall beyond '//format_real(max_wall_deg)// &
                        ' deg: give a gentler entry slope_deg or a shorter transition_length')
        return
      end if
    end if
    if (self%profile == PROFILE_TABLE) then
      if (.not. (self%rho_in + width_in*self%sin_beta/2 <= self%table_hi .and. &
                 self%rho_out - width_out*self%sin_beta/2 >= self%table_lo)) then
        call set_status(status, STATUS_INVALID_INPUT, 'the transitions around the bowl ('//format_real(width_in)// &
                        ' m, '//format_real(width_out)//' m) would carry its spiral beyond the profile table''s '// &
                        'radii, '//format_real(self%table_lo)//' to '//format_real(self%table_hi)//' m: give a '// &
                        'wider table or a shorter transition_length')
        return
      end if
    end if
    self%sigma0 = sigma0
    self%width_in = width_in
    self%width_out = width_out
    self%lo = sigma0 - width_in/2
    self%hi = sigma0 + self%length + width_out/2
    ends = [self%lo, sigma0 + width_in/2, sigma0 + self%length - width_out/2, self%hi]
    self%core_lo = ends(1)
    self%core_hi = ends(2)
    call piecewise_nodes(ends, node_spacing, self%node, pieces)
    if (allocated(self%psi)) deallocate (self%psi, self%rise)
    allocate (self%psi(0:ubound(self%node, 1)), self%rise(0:ubound(self%node, 1)))
    self%psi(0) = 0
    self%rise(0) = 0
    do k = 1, ubound(self%node, 1)
      a = self%node(k - 1)
      c = self%node(k)
      if (pieces(k) == 2) then
        call core_integrals(self, c, x, y)
        self%psi(k) = self%psi_core + x
        self%rise(k) = self%rise_core + y
        cycle
      end if
      call deviation_integrals(self, a, c, x, y)
      self%psi(k) = self%psi(k - 1) + x
      self%rise(k) = self%rise(k - 1) + y
      if (pieces(k) == 1) then   ! the core's integrals start at the first piece's end
        self%psi_core = self%psi(k)
        self%rise_core = self%rise(k)
      end if
    end do
  end subroutine bowl_place

  !> The bowl's own kappa and g and their sigma-derivatives (k(0:3), g(0:3))
  !> at the chain's sigma (the spiral continued beyond its ends).
  pure subroutine bowl_own(self, sigma, k, g)
    class(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: k(0:3), g(0:3)
    real(wp) :: rho, f(0:3), sb
    integer :: m
    sb = self%sin_beta
    rho = self%rho_in - (sigma - self%sigma0)*sb
    call profile_slope(self, rho, f)
    k(0) = self%sense*self%cos_beta/rho
    k(1) = k(0)*sb/rho
    k(2) = 2*k(1)*sb/rho
    k(3) = 3*k(2)*sb/rho
    do m = 0, 3
      g(m) = sb*(-sb)**m*f(m)
    end do
  end subroutine bowl_own

  !> The deviations (kappa_b - kappa_ref) W_b and (g_b - g_ref) W_b and
  !> their sigma-derivatives at sigma (inside lo .. hi).
  pure subroutine blended(self, sigma, dk, dg)
    type(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: dk(0:3), dg(0:3)
    real(wp) :: w(0:3), d(0:3), p, k(0:3), g(0:3)
    integer :: m, j
    w = [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
    if (self%width_in > 0) then
      call smoothstep((sigma - self%lo)/self%width_in, d, p)
      do m = 0, 3
        w(m) = d(m)/self%width_in**m
      end do
    end if
    if (self%width_out > 0) then
      call smoothstep((sigma - (self%hi - self%width_out))/self%width_out, d, p)
      do m = 0, 3
        w(m) = w(m) - d(m)/self%width_out**m
      end do
    end if
    call self%own(sigma, k, g)
    k(0) = k(0) - self%kappa_ref
    g(0) = g(0) - self%grad_ref
    dk = 0; dg = 0
    do m = 0, 3
      do j = 0, m
        dk(m) = dk(m) + binom(j, m)*k(j)*w(m - j)
        dg(m) = dg(m) + binom(j, m)*g(j)*w(m - j)
      end do
    end do
  end subroutine blended

  !> What the bowl adds to the chain at sigma: to kappa and its derivatives
  !> (dk(0:3)), to the heading (dpsi, rad), to g and its derivatives (dg(0:3))
  !> and to the integral of g (dint, m).
  pure subroutine bowl_deviation(self, sigma, dk, dpsi, dg, dint)
    class(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: dk(0:3), dpsi, dg(0:3), dint
    real(wp) :: x, y
    integer :: lo
    dk = 0; dg = 0; dpsi = 0; dint = 0
    ! a bowl that begins or ends the chain has no window there: the spiral
    ! itself, with its derivatives, up to the chain's end
    if (self%width_in > 0 .and. sigma <= self%lo) return
    if (self%width_out > 0 .and. sigma >= self%hi) then
      dpsi = self%psi(ubound(self%psi, 1))
      dint = self%rise(ubound(self%rise, 1))
      return
    end if
    call blended(self, sigma, dk, dg)
    if ((sigma >= self%core_lo .or. self%width_in == 0) .and. (sigma <= self%core_hi .or. self%width_out == 0)) then
      call core_integrals(self, sigma, x, y)
      dpsi = self%psi_core + x
      dint = self%rise_core + y
      return
    end if
    lo = node_below(self%node, sigma)
    call deviation_integrals(self, self%node(lo), sigma, x, y)
    dpsi = self%psi(lo) + x
    dint = self%rise(lo) + y
  end subroutine bowl_deviation

  !> The integrals of the blended deviations kappa_b and g_b from a to b
  !> (8-point Gauss-Legendre over one step of the table).
  pure subroutine deviation_integrals(self, a, b, dpsi, dint)
    type(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: a, b
    real(wp), intent(out) :: dpsi, dint
    real(wp) :: x, y, s, k(0:3), g(0:3)
    integer :: i
    x = 0; y = 0
    do i = 1, 8
      s = 0.5_wp*(a + b) + 0.5_wp*(b - a)*gl8_x(i)
      call blended(self, s, k, g)
      x = x + gl8_w(i)*k(0)
      y = y + gl8_w(i)*g(0)
    end do
    dpsi = 0.5_wp*(b - a)*x
    dint = 0.5_wp*(b - a)*y
  end subroutine deviation_integrals

  !> What the bowl adds to the heading at sigma (rad): bowl_deviation's dpsi
  !> alone, by the same operations (the chain's quadrature of x and y needs
  !> only the heading, at eight points per evaluation).
  pure real(wp) function bowl_heading(self, sigma) result(dpsi)
    class(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp) :: a, x, s
    integer :: lo, i
    dpsi = 0
    if (self%width_in > 0 .and. sigma <= self%lo) return
    if (self%width_out > 0 .and. sigma >= self%hi) then
      dpsi = self%psi(ubound(self%psi, 1))
      return
    end if
    if ((sigma >= self%core_lo .or. self%width_in == 0) .and. (sigma <= self%core_hi .or. self%width_out == 0)) then
      dpsi = self%psi_core + core_heading(self, sigma)
      return
    end if
    lo = node_below(self%node, sigma)
    a = self%node(lo)
    x = 0
    do i = 1, 8
      s = 0.5_wp*(a + sigma) + 0.5_wp*(sigma - a)*gl8_x(i)
      x = x + gl8_w(i)*blended_curvature(self, s)
    end do
    dpsi = self%psi(lo) + 0.5_wp*(sigma - a)*x
  end function bowl_heading

  !> What the bowl adds to g at sigma: bowl_deviation's dg(0) alone,
  !> (g_b - g_ref) W_b (the chain's arc length needs only the gradient).
  pure real(wp) function bowl_gradient_deviation(self, sigma) result(dg)
    class(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp) :: w, f(0:3)
    dg = 0
    if (self%width_in > 0 .and. sigma <= self%lo) return
    if (self%width_out > 0 .and. sigma >= self%hi) return
    w = 1
    if (self%width_in > 0) w = smoothstep_value((sigma - self%lo)/self%width_in)
    if (self%width_out > 0) w = w - smoothstep_value((sigma - (self%hi - self%width_out))/self%width_out)
    call profile_slope(self, self%radius_at(sigma), f)
    dg = (self%sin_beta*f(0) - self%grad_ref)*w
  end function bowl_gradient_deviation

  !> blended's dk(0) alone, (kappa_b - kappa_ref) W_b, by the same operations.
  pure real(wp) function blended_curvature(self, sigma) result(dk)
    type(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp) :: w
    w = 1
    if (self%width_in > 0) w = smoothstep_value((sigma - self%lo)/self%width_in)
    if (self%width_out > 0) w = w - smoothstep_value((sigma - (self%hi - self%width_out))/self%width_out)
    dk = (self%sense*self%cos_beta/self%radius_at(sigma) - self%kappa_ref)*w
  end function blended_curvature

  !> The integrals of the deviations from core_lo to sigma, where W_b = 1,
  !> closed-form: int kappa_b = -s cot(beta) ln(rho/rho(core_lo)) and
  !> int g_b = f(rho(core_lo)) - f(rho), as d rho = -sin(beta) d sigma.
  pure subroutine core_integrals(self, sigma, dpsi, dint)
    type(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: dpsi, dint
    real(wp) :: rho_a, rho
    rho_a = self%radius_at(self%core_lo)
    rho = self%radius_at(sigma)
    dpsi = core_heading(self, sigma)
    dint = self%height_above_bottom(rho_a) - self%height_above_bottom(rho) - self%grad_ref*(sigma - self%core_lo)
  end subroutine core_integrals

  !> core_integrals' dpsi alone.
  pure real(wp) function core_heading(self, sigma) result(dpsi)
    type(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    dpsi = -self%sense*self%cos_beta/self%sin_beta*log(self%radius_at(sigma)/self%radius_at(self%core_lo)) &
      - self%kappa_ref*(sigma - self%core_lo)
  end function core_heading

  !> rho at the chain's sigma (m from the axis, on the spiral).
  pure real(wp) function bowl_radius_at(self, sigma) result(rho)
    class(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    rho = self%rho_in - (sigma - self%sigma0)*self%sin_beta
  end function bowl_radius_at

  !> f(rho): the height of the bowl's surface above its bottom (the apex of
  !> a cone) at rho m from the axis.
  pure real(wp) function bowl_height_above_bottom(self, rho) result(f)
    class(bowl_spiral_t), intent(in) :: self
    real(wp), intent(in) :: rho
    real(wp) :: d(1, 0:0)
    if (self%profile == PROFILE_TABLE) then
      call self%table%evaluate(rho, d, 0)
      f = d(1, 0)
    else if (self%profile == PROFILE_CONE) then
      f = rho*self%tan_wall
    else
      f = self%sphere_radius - sqrt(self%sphere_radius**2 - rho**2)
    end if
  end function bowl_height_above_bottom
end module geometry_slide_bowl
