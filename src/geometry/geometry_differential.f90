!> Differential geometry of a surface at one point (thesis 2.2): unit normal,
!> first and second fundamental forms, Gauss, mean and principal curvatures.
!>
!> Conventions: N = r_u x r_v / |r_u x r_v| (2.24); L = N.r_uu, M = N.r_uv,
!> N_ = N.r_vv (2.30, called e, f, g there); the mean curvature (2.31) is
!> positive where the surface bends towards N (a sphere with its outward
!> normal has H = -1/R). At a point where r_u x r_v = 0 exactly the normal
!> and the curvatures are returned as zero and `regular` is false; near such
!> points the results are as accurate as the partials themselves, since no
!> difference of nearly equal numbers is formed.
module geometry_differential
  use base_kinds, only: wp
  use base_vector, only: cross, unit_vector
  use geometry_surface, only: surface_point_t
  implicit none (type, external)
  private
  public :: fundamental_forms_t, fundamental_forms
  public :: unit_normal, first_form, second_form, gauss_curvature, mean_curvature, &
            principal_curvatures, radii_towards

  !> Everything at one surface point (needs a point of order >= 2).
  type :: fundamental_forms_t
    logical :: regular = .false.      !< r_u x r_v /= 0
    real(wp) :: normal(3) = 0         !< unit normal N (2.24)
    real(wp) :: e = 0, f = 0, g = 0   !< first form E, F, G (2.15)
    real(wp) :: l = 0, m = 0, n = 0   !< second form (2.30)
    real(wp) :: gauss = 0             !< K (2.32), 1/m^2
    real(wp) :: mean = 0              !< H (2.31), 1/m
    real(wp) :: k1 = 0, k2 = 0        !< principal curvatures, k1 >= k2, 1/m
  end type fundamental_forms_t

contains

  !> Unit normal (r_u x r_v)/|r_u x r_v|, thesis (2.24); zero where degenerate.
  pure function unit_normal(p) result(n)
    type(surface_point_t), intent(in) :: p
    real(wp) :: n(3)
    n = unit_vector(cross(p%ru, p%rv))
  end function unit_normal

  !> [E, F, G], thesis (2.15).
  pure function first_form(p) result(efg)
    type(surface_point_t), intent(in) :: p
    real(wp) :: efg(3)
    efg = [dot_product(p%ru, p%ru), dot_product(p%ru, p%rv), dot_product(p%rv, p%rv)]
  end function first_form

  !> [L, M, N] = N.[r_uu, r_uv, r_vv], thesis (2.30); needs order >= 2.
  pure function second_form(p) result(lmn)
    type(surface_point_t), intent(in) :: p
    real(wp) :: lmn(3), n(3)
    n = unit_normal(p)
    lmn = [dot_product(n, p%ruu), dot_product(n, p%ruv), dot_product(n, p%rvv)]
  end function second_form

  !> K = (LN - M^2)/(EG - F^2), thesis (2.32); 0 where degenerate.
  pure function gauss_curvature(p) result(k)
    type(surface_point_t), intent(in) :: p
    real(wp) :: k
    type(fundamental_forms_t) :: ff
    ff = fundamental_forms(p)
    k = ff%gauss
  end function gauss_curvature

  !> H = (EN - 2FM + GL)/(2(EG - F^2)), thesis (2.31); 0 where degenerate.
  pure function mean_curvature(p) result(h)
    type(surface_point_t), intent(in) :: p
    real(wp) :: h
    type(fundamental_forms_t) :: ff
    ff = fundamental_forms(p)
    h = ff%mean
  end function mean_curvature

  !> [k1, k2] = H +- sqrt(H^2 - K), k1 >= k2.
  pure function principal_curvatures(p) result(k)
    type(surface_point_t), intent(in) :: p
    real(wp) :: k(2)
    type(fundamental_forms_t) :: ff
    ff = fundamental_forms(p)
    k = [ff%k1, ff%k2]
  end function principal_curvatures

  !> All of the above at once. |r_u x r_v|^2 is used for EG - F^2 (the same
  !> number, Lagrange's identity) because it does not cancel.
  pure function fundamental_forms(p) result(ff)
    type(surface_point_t), intent(in) :: p
    type(fundamental_forms_t) :: ff
    real(wp) :: c(3), area2, efg(3), lmn(3), disc
    c = cross(p%ru, p%rv)
    area2 = dot_product(c, c)
    efg = first_form(p)
    ff%e = efg(1); ff%f = efg(2); ff%g = efg(3)
    ff%regular = area2 > 0
    if (.not. ff%regular) return
    ff%normal = c/sqrt(area2)
    lmn = [dot_product(ff%normal, p%ruu), dot_product(ff%normal, p%ruv), &
           dot_product(ff%normal, p%rvv)]
    ff%l = lmn(1); ff%m = lmn(2); ff%n = lmn(3)
    ff%gauss = (ff%l*ff%n - ff%m**2)/area2
    ff%mean = (ff%e*ff%n - 2*ff%f*ff%m + ff%g*ff%l)/(2*area2)
    ! H^2 - K >= 0 in exact arithmetic; clip the rounding at umbilics.
    disc = sqrt(max(ff%mean**2 - ff%gauss, 0.0_wp))
    ff%k1 = ff%mean + disc
    ff%k2 = ff%mean - disc
  end function fundamental_forms

  !> The principal radii of curvature (m) whose centres of curvature lie on
  !> the side of the surface that `side` points to (any vector off the
  !> tangent plane): 1/k for each principal curvature k bending the surface
  !> that way; huge where it bends away or not at all (or the point is
  !> degenerate). A point at height h along that side's normal is a focal
  !> point of the surface where h equals one of them: the map (u, v, h) ->
  !> r + h n is singular there (its Jacobian det(I - h S)).
  pure function radii_towards(p, side) result(rho)
    type(surface_point_t), intent(in) :: p
    real(wp), intent(in) :: side(3)
    real(wp) :: rho(2), k(2)
    type(fundamental_forms_t) :: ff
    integer :: i
    rho = huge(1.0_wp)
    ff = fundamental_forms(p)
    if (.not. ff%regular) return
    k = [ff%k1, ff%k2]*sign(1.0_wp, dot_product(ff%normal, side))
    do i = 1, 2
      if (k(i) > 0) rho(i) = 1/k(i)
    end do
  end function radii_towards
end module geometry_differential
