!> Water drag on a sphere moving with a contact's Darboux frame (thesis 4.3,
!> (4.29)-(4.31), appendix G; METHOD-PART2 B.3-B.5 with its corrections).
!>
!>     F_D = -1/2 C_D rho_w A_c |w_D - w| (w_D - w)                    (4.29)
!>
!> The sphere (radius r_S) touches the slide at the contact D from inside:
!> centre C = D + r_S z_D. The water surface is the plane through the water
!> point M (the streamline at the contact's u) at height h along z_M.
!>
!> Submerged cap (4.30)-(4.31). In K_M, with gamma the angle between z_M and
!> z_D (about y_M; z_D = [sin gamma, 0, cos gamma] in K_M), a point of the
!> sphere's great circle in the xz-plane at angle phi lies at the water line
!> when A cos phi + B sin phi + C' = 0 with A = -r_S sin gamma,
!> B = -r_S cos gamma, C' = z_D + r_S cos gamma - h (B with its minus sign and
!> C' with -h: the printed underbraces are ambiguous, B.4). C' is the signed
!> distance of the centre above the water plane, and the half chord
!> |S1 S2|/2 = sqrt(A^2 + B^2 - C'^2) = sqrt(r_S^2 - C'^2) is the radius a_y
!> of the cap circle; cap_intersection_angles gives S1, S2 by (4.31) and the
!> test checks this identity. The cap lies on the side d = -z_M; its plane is
!> c = C' from the centre along -d (c < 0: the centre is under water, the cap
!> is more than a hemisphere, and the formulas below hold with the signed c).
!>
!> Projected area (appendix G after Peters & Dachsbacher 2019, scaled to r_S):
!> the front-facing part of the cap (the side the sphere moves into, z_c along
!> w_D - w) projected on the plane normal to z_c. With d_x = |d - (z_c.d) z_c|,
!> d_z = z_c.d, a_x = d_z a_y, t_x = c/d_x, A_s(X) = X sqrt(1 - X^2) + asin X:
!>   t_x >= r_S:  pi a_x a_y if a_x >= 0 (case 1), else 0 (case 4);
!>   t_x <  r_S:  r_S^2 (pi/2 - A_s(t_x/r_S)) + a_x a_y (pi/2 + A_s(X)),
!>                X = (t_x - k_x)/a_x = c d_z/(d_x a_y)      (cases 2 and 3).
!> Case 3 as printed (Table G.1) lacks the ellipse term; B.4 shows by brute
!> force that cases 2 and 3 share one formula (the term subtracts for a_x < 0).
!> X is formed without dividing by a_x (no 0/0 at a_x = 0, where the term
!> vanishes); t_x/r_S and X are clamped to [-1, 1] against rounding (and for
!> c < 0, where t_x < -r_S means the whole front disc). d parallel to z_c has
!> no x_c: the limits of the formulas are used (front: pi a_y^2 or pi r_S^2;
!> back: 0 or pi (r_S^2 - a_y^2)).
!>
!> Drag coefficient: Morrison's sphere correlation, 2010 form (B.5), with the
!> Reynolds number Re = |w_D - w| 2 r_S / nu. It is stated for Re <= 1e6;
!> beyond, C_D is held at C_D(1e6) = 0.1414558 (its last term grows without
!> bound outside the range). C_D |w_D - w| is formed as 24 nu/(2 r_S) +
!> |w_D - w| (C_D - 24/Re), finite at zero relative speed (Stokes drag).
module rider_drag
  use base_kinds, only: wp
  use base_constants, only: pi
  implicit none (type, external)
  private
  public :: water_properties_t, drag_state_t
  public :: morrison_drag_coefficient, morrison_reynolds_max, cap_intersection_angles, projected_cap_area
  public :: evaluate_drag, CAP_DRY, CAP_PARTIAL, CAP_FULL

  real(wp), parameter :: morrison_reynolds_max = 1e6_wp   !< upper end of the correlation's range

  integer, parameter :: CAP_DRY = 0, CAP_PARTIAL = 1, CAP_FULL = 2

  type :: water_properties_t
    real(wp) :: density = 1000             ! kg/m^3 (the thesis gives no value)
    real(wp) :: kinematic_viscosity = 1e-6_wp   ! m^2/s (the value of thesis 4.2)
  end type water_properties_t

  !> Drag on one sphere at one instant.
  type :: drag_state_t
    real(wp) :: relative_velocity(3) = 0   ! m/s, w_D - w
    real(wp) :: reynolds = 0               ! 1
    real(wp) :: drag_coefficient = 0       ! 1, at min(Re, 1e6)
    real(wp) :: cap_offset = 0             ! m, c: centre above the water plane (signed)
    real(wp) :: cap_radius = 0             ! m, a_y
    integer :: cap = CAP_DRY
    real(wp) :: projected_area = 0         ! m^2, A_c
    real(wp) :: force(3) = 0               ! N, F_D
  end type drag_state_t

contains

  !> Morrison's C_D(Re), 2010 handout form, for Re > 0 (not clamped).
  pure real(wp) function morrison_drag_coefficient(re) result(cd)
    real(wp), intent(in) :: re
    cd = 24/re + stokes_excess(re)
  end function morrison_drag_coefficient

  !> C_D - 24/Re. The third term is written as 0.411 x^0.06/(1 + x^8),
  !> x = Re/263000, which equals the printed 0.411 x^-7.94/(1 + x^-8) and
  !> cannot overflow at small Re.
  pure real(wp) function stokes_excess(re) result(e)
    real(wp), intent(in) :: re
    real(wp) :: x
    x = re/263000.0_wp
    e = 2.6_wp*(re/5)/(1 + (re/5)**1.52_wp) + 0.411_wp*x**0.06_wp/(1 + x**8) + re**0.80_wp/461000.0_wp
  end function stokes_excess

  !> (4.31): the angles phi_1, phi_2 of the two points where the sphere's
  !> great circle in the xz-plane of K_M meets the water line (A, B, C' as
  !> in the header). found = .false. when A^2 + B^2 < C'^2 (no intersection).
  pure subroutine cap_intersection_angles(r_s, gamma, c_prime, phi, found)
    real(wp), intent(in) :: r_s, gamma, c_prime
    real(wp), intent(out) :: phi(2)
    logical, intent(out) :: found
    real(wp) :: a, b, q, root, s(2), c(2)
    a = -r_s*sin(gamma)
    b = -r_s*cos(gamma)
    q = a**2 + b**2
    phi = 0
    found = q - c_prime**2 >= 0
    if (.not. found) return
    root = sqrt(q - c_prime**2)
    s = (-b*c_prime + [1, -1]*a*root)/q
    c = (-a*c_prime - [1, -1]*b*root)/q
    phi = atan2(s, c)
  end subroutine cap_intersection_angles

  !> A_c of the cap {p on the sphere: (p - C).d >= c} seen along z_c (unit
  !> vectors), front-facing part only (header). |c| < r_s, a_y = sqrt(r_s^2 - c^2).
  pure real(wp) function projected_cap_area(r_s, c, a_y, d, z_c) result(area)
    real(wp), intent(in) :: r_s, c, a_y, d(3), z_c(3)
    real(wp) :: d_z, d_x, a_x, t_x, x
    d_z = dot_product(z_c, d)
    d_x = norm2(d - d_z*z_c)
    if (d_x == 0) then
      if (d_z > 0) then
        area = merge(pi*a_y**2, pi*r_s**2, c >= 0)
      else
        area = merge(0.0_wp, pi*(r_s**2 - a_y**2), c >= 0)
      end if
      return
    end if
    a_x = d_z*a_y
    t_x = c/d_x
    if (t_x >= r_s) then
      area = merge(pi*a_x*a_y, 0.0_wp, a_x >= 0)
      return
    end if
    x = c*d_z/(d_x*a_y)
    area = r_s**2*(pi/2 - segment_function(t_x/r_s)) + a_x*a_y*(pi/2 + segment_function(x))
  end function projected_cap_area

  !> A_s(X) = X sqrt(1 - X^2) + asin X on X clamped to [-1, 1].
  pure real(wp) function segment_function(x) result(a)
    real(wp), intent(in) :: x
    real(wp) :: y
    y = max(-1.0_wp, min(1.0_wp, x))
    a = y*sqrt(1 - y**2) + asin(y)
  end function segment_function

  !> The drag (4.29) on a sphere of radius r_s touching the slide at the
  !> contact point r_d with normal z_d (into the tube) moving with velocity
  !> w_d, in water whose section frame at the contact's u has origin r_m
  !> (the streamline point) and normal z_m, height h and velocity w.
  pure subroutine evaluate_drag(r_s, water, r_d, z_d, w_d, r_m, z_m, h, w, drag)
    real(wp), intent(in) :: r_s
    type(water_properties_t), intent(in) :: water
    real(wp), intent(in) :: r_d(3), z_d(3), w_d(3), r_m(3), z_m(3), h, w(3)
    type(drag_state_t), intent(out) :: drag
    real(wp) :: speed, diameter, cd_speed, excess
    diameter = 2*r_s
    drag%relative_velocity = w_d - w
    speed = norm2(drag%relative_velocity)
    drag%reynolds = speed*diameter/water%kinematic_viscosity
    ! (4.30): C' = z_D + r_S cos(gamma) - h in K_M, cos(gamma) = z_D.z_M
    drag%cap_offset = dot_product(r_d - r_m, z_m) + r_s*dot_product(z_d, z_m) - h
    if (drag%cap_offset >= r_s) then
      drag%cap = CAP_DRY
      return
    end if
    if (drag%cap_offset <= -r_s) then
      drag%cap = CAP_FULL
      drag%cap_radius = 0
    else
      drag%cap = CAP_PARTIAL
      drag%cap_radius = sqrt(r_s**2 - drag%cap_offset**2)
    end if
    if (drag%reynolds <= morrison_reynolds_max) then
      excess = stokes_excess(drag%reynolds)   ! once: three powers
      if (speed > 0) drag%drag_coefficient = 24/drag%reynolds + excess   ! morrison_drag_coefficient
      cd_speed = 24*water%kinematic_viscosity/diameter + speed*excess
    else
      drag%drag_coefficient = morrison_drag_coefficient(morrison_reynolds_max)
      cd_speed = drag%drag_coefficient*speed
    end if
    if (speed == 0) return   ! no direction to project on, and no force
    if (drag%cap == CAP_FULL) then
      drag%projected_area = pi*r_s**2
    else
      drag%projected_area = projected_cap_area(r_s, drag%cap_offset, drag%cap_radius, -z_m, &
                                               drag%relative_velocity/speed)
    end if
    drag%force = -0.5_wp*water%density*drag%projected_area*cd_speed*drag%relative_velocity
  end subroutine evaluate_drag
end module rider_drag
