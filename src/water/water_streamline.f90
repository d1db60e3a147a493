!> The streamline: a virtual point mass m_w = 1 kg sliding on the channel
!> surface under gravity, the normal force and the friction of the water
!> (thesis 4.2, eq. 4.6), with the Saint-Venant correction and the water
!> height from continuity.
!>
!> State y = [u, v, u', v', h, W_f, W_k]: surface coordinates and rates, water
!> height (m), work done by friction (J, <= 0) and by the Saint-Venant term.
!>
!> Frames: K_M is the Darboux frame with sigma = 1, alpha_u = 0, alpha_v = 1
!> (x_M = r_v/|r_v| across the tube, z_M = r_u x r_v/|..| into the tube,
!> y_M = z_M x x_M = minus the centerline direction); K_w has x_w = w/|w|
!> along the water velocity, z_w = z_M and y_w = z_w x x_w.
!>
!> Equation (4.6), m w' + kappa x_w = -F_R x_w + N z_M + m g, projected:
!>   on z_M:  N = m z_M.(a_hat - g)                                     (4.12)
!>   on y_w:  y_w.(r_u u'' + r_v v'' + a_hat) = y_w.g                    (4.21)
!>   on x_w:  m dw/dt + kappa = -F_R + m x_w.g                           (4.20)
!> with a_hat = r_uu u'^2 + 2 r_uv u'v' + r_vv v'^2 (4.11) and the friction
!> F_R = (f1 + chi f2 + H(chi_s) chi_s f3) w^2 (4.7).
!>
!> Saint-Venant term (4.13): kappa = N dh/dzeta. Continuity A w = Q gives,
!> with D = dA/dt at fixed h (circle: D = (R alpha - b) dR/dt, F.3; a profile
!> that changes along u: D = A_u u'),
!>   b dh/dt + D + A (dw/dt)/w = 0,   dh/dzeta = (dh/dt)/w,              (4.17)-(4.18)
!> so that (4.20) becomes
!>   dw/dt (1 - N A/(m b w^2)) = N D/(m b w) - F_R/m + x_w.g             (4.20)
!> and dh/dt = -(A (dw/dt)/w + D)/b (4.24). On a straight incline N A/(m b w^2)
!> = 1/Fr^2 with Fr^2 = w^2 b/(g cos(theta) A): the correction is singular at
!> critical flow, which the model watches with a root function.
!> Modes: full; without the radius term (D left out of kappa, not of the
!> height, so continuity still holds); off (kappa = 0). The height always
!> follows continuity.
!>
!> dR/dt (F.5): R = r (1 + tan^2 beta), tan beta = (x_M.w)/(-y_M.w), so
!> dR/dt = 2 r tan(beta) (1 + tan^2 beta) dbeta/dt with dbeta/dt = theta' -
!> y_M.dx_M/dt, theta' = y_w.g/w (F.4, from the y_w projection) and dx_M/dt =
!> x_M,u u' + x_M,v v' (4.19); checked against differences of R along a
!> computed path in the tests.
!>
!> Surface accelerations (4.23): [y_w.r_u, y_w.r_v; x_w.r_u, x_w.r_v] [u''; v'']
!> = [y_w.(g - a_hat); dw/dt - x_w.a_hat].
module water_streamline
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_constants, only: standard_gravity
  use base_status, only: status_t, set_status, STATUS_DOMAIN, STATUS_INVALID_INPUT
  use base_vector, only: cross
  use geometry_surface, only: surface_point_t
  use water_channel, only: channel_t
  use water_section, only: circle_segment, profile_water
  implicit none (type, external)
  private
  public :: streamline_mass
  public :: streamline_t, water_point_t, water_point, velocity_from_angle
  public :: water_rates_t, water_point_rates
  public :: CORRECTION_FULL, CORRECTION_NO_RADIUS, CORRECTION_OFF
  public :: default_f1, default_f2, default_f3

  integer, parameter :: CORRECTION_FULL = 1, CORRECTION_NO_RADIUS = 2, CORRECTION_OFF = 3
  !> Identified friction parameters, thesis table 4.3.
  real(wp), parameter :: default_f1 = 0.0274748_wp   ! kg/m
  real(wp), parameter :: default_f2 = 0.138285_wp    ! kg
  real(wp), parameter :: default_f3 = 0.979822_wp    ! kg m
  real(wp), parameter :: streamline_mass = 1         ! kg, m_w (the thesis's virtual point mass)

  !> The model: the channel, the water's parameters, where the slide ends and
  !> the report stations. Evaluated by water_point (pure); a run (water_flow)
  !> never changes it.
  type :: streamline_t
    class(channel_t), allocatable :: channel
    real(wp) :: mass = streamline_mass                          ! kg (m_w)
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]  ! m/s^2
    real(wp) :: f1 = default_f1, f2 = default_f2, f3 = default_f3
    integer :: correction = CORRECTION_FULL
    real(wp) :: flow_rate = 0                 ! m^3/s (Q)
    real(wp) :: u_end = huge(1.0_wp)          ! the slide ends here (root)
    real(wp) :: min_speed = 0.05_wp           ! m/s: below it the water has stalled (root)
    real(wp) :: min_criticality = 0.02_wp     ! 1 - 1/Fr^2 below it: near critical (root)
    real(wp), allocatable :: stations(:)      ! u of report stations (roots)
  end type streamline_t

  !> Everything about the water at one state.
  type :: water_point_t
    type(surface_point_t) :: p
    real(wp) :: u = 0, v = 0                        ! surface coordinates
    real(wp) :: position(3) = 0, velocity(3) = 0   ! m, m/s
    real(wp) :: speed = 0                           ! m/s (w)
    real(wp) :: x_w(3) = 0, y_w(3) = 0, z_m(3) = 0, x_m(3) = 0, y_m(3) = 0
    real(wp) :: a_hat(3) = 0                        ! m/s^2 (4.11)
    real(wp) :: normal_force = 0                    ! N (4.12)
    real(wp) :: friction = 0                        ! N (F_R, 4.7)
    real(wp) :: chi = 0, chi_s = 0                  ! 1/m, 1/m^2
    real(wp) :: centerline_speed = 0                ! |c_u|, m per unit of u
    real(wp) :: centerline_speed_u = 0              ! d|c_u|/du, m per unit of u^2
    real(wp) :: beta = 0                            ! rad, flow vs centerline, + towards +v
    real(wp) :: radius = 0                          ! m, R (4.15); 0 for a profile
    real(wp) :: radius_rate = 0                     ! m/s (F.5)
    real(wp) :: height = 0, area = 0, width = 0, alpha = 0   ! m, m^2, m, rad
    real(wp) :: v_left = 0, v_right = 0             ! profile edges (profiles only)
    real(wp) :: area_rate = 0                       ! m^2/s, D
    real(wp) :: criticality = 1                     ! 1 - N A/(m b w^2) (= 1 - 1/Fr^2)
    real(wp) :: froude = huge(1.0_wp)               ! Fr = sqrt(m b w^2/(N A))
    real(wp) :: kappa = 0                           ! N, Saint-Venant term
    real(wp) :: speed_rate = 0                      ! m/s^2 (dw/dt)
    real(wp) :: height_rate = 0                     ! m/s (4.24)
    real(wp) :: udd = 0, vdd = 0                    ! (4.23)
    real(wp) :: acceleration(3) = 0                 ! m/s^2
  end type water_point_t

  !> Time derivatives, along the motion, of what the water field interpolates
  !> and of the frame K_w (for the rates of the edges).
  type :: water_rates_t
    real(wp) :: x_m(3) = 0, z_m(3) = 0       ! 1/s, d/dt of the K_M axes
    real(wp) :: x_w(3) = 0, y_w(3) = 0       ! 1/s, d/dt of the K_w axes
    real(wp) :: width = 0                    ! m/s, db/dt
  end type water_rates_t

contains

  !> The water at state y: the one place where the model lives.
  pure subroutine water_point(self, y, q, status)
    class(streamline_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    type(water_point_t), intent(out) :: q
    type(status_t), intent(inout) :: status
    call point_at(self, y, q, status, .true.)
  end subroutine water_point

  !> water_point's work; with_area_rate false (water_point_rates' points,
  !> which need the width alone): a profile that changes along u is not
  !> differenced along u (D = 0, two profiles fewer), so that the width, the
  !> area and every check that can fail are water_point's, to the bit, and
  !> the rates that follow from D (speed, height, u'', v'') are not the
  !> model's.
  pure subroutine point_at(self, y, q, status, with_area_rate)
    class(streamline_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    type(water_point_t), intent(out) :: q
    type(status_t), intent(inout) :: status
    logical, intent(in) :: with_area_rate
    real(wp) :: u, v, du, dv, h, n(3), rv_norm, xmu(3), xmv(3), xm_dot(3), tb, theta_dot, &
                beta_dot, r, m, a_plus, a_minus, b_plus, b_minus, vl, vr, du_step, &
                mat(2, 2), rhs(2), det, denom, kappa_d, v_min, v_max
    type(status_t) :: st

    u = y(1); v = y(2); du = y(3); dv = y(4); h = y(5)
    m = self%mass
    call self%channel%v_range(v_min, v_max)
    if (v < v_min .or. v > v_max) then
      call set_status(status, STATUS_DOMAIN, 'the water left the slide surface across its rim at v = ' &
                      //format_short(v))
      return
    end if
    call self%channel%evaluate_with_curvature(u, v, q%p, q%chi, q%chi_s, q%centerline_speed, &
                                              q%centerline_speed_u, status)
    if (.not. status%ok()) return
    q%position = q%p%r
    q%velocity = q%p%ru*du + q%p%rv*dv
    q%speed = norm2(q%velocity)
    if (q%speed <= 0) then
      call set_status(status, STATUS_DOMAIN, 'the water stands still (speed 0)')
      return
    end if
    if (h <= 0) then
      call set_status(status, STATUS_DOMAIN, 'the water height fell to zero')
      return
    end if
    q%height = h
    q%u = u; q%v = v
    q%x_w = q%velocity/q%speed
    n = cross(q%p%ru, q%p%rv)
    q%z_m = n/norm2(n)                                ! (3.38), sigma = 1
    rv_norm = norm2(q%p%rv)
    q%x_m = q%p%rv/rv_norm                            ! (3.41), alpha_u = 0, alpha_v = 1
    q%y_m = cross(q%z_m, q%x_m)
    q%y_w = cross(q%z_m, q%x_w)
    q%a_hat = q%p%ruu*du**2 + 2*q%p%ruv*du*dv + q%p%rvv*dv**2     ! (4.11)
    q%normal_force = m*dot_product(q%z_m, q%a_hat - self%gravity)  ! (4.12)

    q%friction = self%f1 + q%chi*self%f2                          ! (4.7)
    if (q%chi_s > 0) q%friction = q%friction + q%chi_s*self%f3
    q%friction = q%friction*q%speed**2
    if (-dot_product(q%y_m, q%velocity) <= 1e-3_wp*q%speed) then
      call set_status(status, STATUS_DOMAIN, 'the water flows across the slide or back (beta >= 90 deg)')
      return
    end if
    tb = dot_product(q%x_m, q%velocity)/(-dot_product(q%y_m, q%velocity))   ! tan(beta) (4.14)
    q%beta = atan2(dot_product(q%x_m, q%velocity), -dot_product(q%y_m, q%velocity))

    r = self%channel%circle_radius(u)
    if (r > 0) then
      q%radius = r*(1 + tb**2)                                    ! (4.15)
      if (h >= 2*q%radius) then
        call set_status(status, STATUS_DOMAIN, 'the water fills the tube (height >= 2 R)')
        return
      end if
      call circle_segment(h, q%radius, q%area, q%width, q%alpha)  ! (F.1), (4.19)
      theta_dot = dot_product(q%y_w, self%gravity)/q%speed        ! (F.4)
      xmu = (q%p%ruv - q%x_m*dot_product(q%x_m, q%p%ruv))/rv_norm
      xmv = (q%p%rvv - q%x_m*dot_product(q%x_m, q%p%rvv))/rv_norm
      xm_dot = xmu*du + xmv*dv                                    ! (4.19)
      beta_dot = theta_dot - dot_product(q%y_m, xm_dot)
      q%radius_rate = 2*r*tb*(1 + tb**2)*beta_dot                 ! (F.5)
      q%area_rate = (q%radius*q%alpha - q%width)*q%radius_rate    ! (F.3)
    else
      call profile_water(self%channel, u, v, h, q%area, q%width, q%v_left, q%v_right, status)
      if (.not. status%ok()) return
      q%alpha = 0
      q%area_rate = 0
      if (with_area_rate .and. self%channel%section_varies()) then
        du_step = 1e-5_wp*max(1.0_wp, abs(u))
        call profile_water(self%channel, u + du_step, v, h, a_plus, b_plus, vl, vr, st)
        if (st%ok()) call profile_water(self%channel, u - du_step, v, h, a_minus, b_minus, vl, vr, st)
        if (st%ok()) q%area_rate = (a_plus - a_minus)/(2*du_step)*du
      end if
    end if

    q%criticality = 1 - q%normal_force*q%area/(m*q%width*q%speed**2)
    if (q%criticality < 1) q%froude = sqrt(1/(1 - q%criticality))
    select case (self%correction)
    case (CORRECTION_OFF)
      q%speed_rate = -q%friction/m + dot_product(q%x_w, self%gravity)     ! (4.44)
    case default
      denom = q%criticality
      if (denom <= 0) then
        ! said with what to change: a slow or wide start is the usual cause
        call set_status(status, STATUS_DOMAIN, 'the flow reached critical (Fr = '// &
                        format_short(sqrt(1/(1 - q%criticality)))//' <= 1: deeper and '// &
                        'slower than the shallow supercritical flow of the model at u = '//format_short(u)// &
                        '): the Saint-Venant correction is singular there; start the water faster or '// &
                        'as a narrower band (&water start, speed0, v_left0, v_right0: docs/water.md) or '// &
                        'switch the correction off (correction = ''off'')')
        return
      end if
      kappa_d = q%area_rate
      if (self%correction == CORRECTION_NO_RADIUS) kappa_d = 0
      q%speed_rate = (q%normal_force*kappa_d/(m*q%width*q%speed) - q%friction/m &
                      + dot_product(q%x_w, self%gravity))/denom           ! (4.20)
    end select
    q%height_rate = -(q%area*q%speed_rate/q%speed + q%area_rate)/q%width   ! (4.24)
    if (self%correction == CORRECTION_FULL) then
      q%kappa = q%normal_force*q%height_rate/q%speed                       ! (4.13)
    else if (self%correction == CORRECTION_NO_RADIUS) then
      q%kappa = q%normal_force*(-(q%area*q%speed_rate/q%speed)/q%width)/q%speed
    end if

    mat(1, :) = [dot_product(q%y_w, q%p%ru), dot_product(q%y_w, q%p%rv)]
    mat(2, :) = [dot_product(q%x_w, q%p%ru), dot_product(q%x_w, q%p%rv)]
    rhs = [dot_product(q%y_w, self%gravity - q%a_hat), q%speed_rate - dot_product(q%x_w, q%a_hat)]
    det = mat(1, 1)*mat(2, 2) - mat(1, 2)*mat(2, 1)
    if (abs(det) <= 1e-14_wp*norm2(q%p%ru)*rv_norm) then
      call set_status(status, STATUS_DOMAIN, 'surface accelerations undefined (4.23)')
      return
    end if
    q%udd = (mat(2, 2)*rhs(1) - mat(1, 2)*rhs(2))/det                      ! (4.23)
    q%vdd = (mat(1, 1)*rhs(2) - mat(2, 1)*rhs(1))/det
    q%acceleration = q%p%ru*q%udd + q%p%rv*q%vdd + q%a_hat
  end subroutine point_at

  !> The rates d/dt along the motion at the water point q (from water_point at
  !> state y, same model). With r_u' = r_uu u' + r_uv v' and r_v' = r_uv u' + r_vv v':
  !>   x_M' = (r_v' - x_M (x_M.r_v'))/|r_v|,  n = r_u x r_v, n' = r_u' x r_v + r_u x r_v',
  !>   z_M' = (n' - z_M (z_M.n'))/|n|,  x_w' = (a - x_w (x_w.a))/w,
  !>   y_w' = z_M' x x_w + z_M x x_w',
  !>   circle: b^2 = 8 R h - 4 h^2, so b' = 4 (R' h + (R - h) h')/b (R' from F.5);
  !>   other profiles: b' by central differences of b along the motion,
  !>   b(y + d y') - b(y - d y') over 2 d with d moving the point 1e-5 m
  !>   (the two points without the area's rate along u, which b does not
  !>   need: point_at).
  !> Checked against differences along the motion in test_water_field.
  pure subroutine water_point_rates(self, y, q, rates, status)
    class(streamline_t), intent(in) :: self
    real(wp), intent(in) :: y(:)
    type(water_point_t), intent(in) :: q
    type(water_rates_t), intent(out) :: rates
    type(status_t), intent(inout) :: status
    real(wp) :: ru_dot(3), rv_dot(3), n(3), n_dot(3), ydot(size(y)), delta
    type(water_point_t) :: q_plus, q_minus

    ru_dot = q%p%ruu*y(3) + q%p%ruv*y(4)
    rv_dot = q%p%ruv*y(3) + q%p%rvv*y(4)
    rates%x_m = (rv_dot - q%x_m*dot_product(q%x_m, rv_dot))/norm2(q%p%rv)
    n = cross(q%p%ru, q%p%rv)
    n_dot = cross(ru_dot, q%p%rv) + cross(q%p%ru, rv_dot)
    rates%z_m = (n_dot - q%z_m*dot_product(q%z_m, n_dot))/norm2(n)
    rates%x_w = (q%acceleration - q%x_w*dot_product(q%x_w, q%acceleration))/q%speed
    rates%y_w = cross(rates%z_m, q%x_w) + cross(q%z_m, rates%x_w)
    if (q%radius > 0) then
      rates%width = 4*(q%radius_rate*q%height + (q%radius - q%height)*q%height_rate)/q%width
    else
      ydot = 0
      ydot(1:5) = [y(3), y(4), q%udd, q%vdd, q%height_rate]
      delta = 1e-5_wp/q%speed
      ! the widths alone: the area's rate along u is not needed there
      call point_at(self, y + delta*ydot, q_plus, status, .false.)
      if (status%ok()) call point_at(self, y - delta*ydot, q_minus, status, .false.)
      if (.not. status%ok()) return
      rates%width = (q_plus%width - q_minus%width)/(2*delta)
    end if
  end subroutine water_point_rates

  !> Surface rates (u', v') of speed w at angle beta from the centerline
  !> (x_w = sin(beta) x_M - cos(beta) y_M), least squares in the tangent plane.
  pure subroutine velocity_from_angle(p, speed, beta, du, dv, status)
    type(surface_point_t), intent(in) :: p
    real(wp), intent(in) :: speed, beta
    real(wp), intent(out) :: du, dv
    type(status_t), intent(out) :: status
    real(wp) :: z(3), xm(3), ym(3), target(3), e, f, g, det, bu, bv
    status%code = 0
    z = cross(p%ru, p%rv); z = z/norm2(z)
    xm = p%rv/norm2(p%rv)
    ym = cross(z, xm)
    target = speed*(sin(beta)*xm - cos(beta)*ym)
    e = dot_product(p%ru, p%ru); f = dot_product(p%ru, p%rv); g = dot_product(p%rv, p%rv)
    bu = dot_product(p%ru, target); bv = dot_product(p%rv, target)
    det = e*g - f*f
    if (det <= 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'start point is singular (r_u parallel to r_v)')
      du = 0; dv = 0
      return
    end if
    du = (g*bu - f*bv)/det
    dv = (e*bv - f*bu)/det
  end subroutine velocity_from_angle
end module water_streamline
