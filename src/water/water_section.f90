!> The water's cross-section: area A, width b and central angle alpha for a
!> given water height h.
!>
!> Circle (thesis 4.19, appendix F): the oblique section of a circular tube
!> is replaced by a circle of radius R (4.15); the water is a circular segment
!>     A = R^2 acos(1 - h/R) - (R - h) sqrt(2 R h - h^2)        (F.1)
!>       = R^2 (alpha - sin alpha)/2,  alpha = 2 acos(1 - h/R)   (4.19)
!>     b = 2 R sin(alpha/2) = 2 sqrt(2 R h - h^2) = dA/dh       (F.2)
!>     dA/dR = R alpha - b                                      (F.3)
!> (F.2) and (F.3) are checked against central differences in the tests.
!>
!> Any profile (thesis 4.6, 4.45-4.47): the section of the surface at u is the
!> curve q(v) = r(u, v). Heights zeta are measured from the streamline point
!> P = r(u, v0) along the surface normal there, projected into the section
!> plane (normal to the centerline tangent), and lateral positions eta along
!> the in-plane direction that grows with v. The water surface is zeta = h;
!> its ends v_right < v0 < v_left solve zeta(v) = h, and
!>     A = int (h - zeta) d eta = int_{v_right}^{v_left} (h - zeta(v)) eta'(v) dv   (4.45)
!>     b = eta(v_left) - eta(v_right) = dA/dh                                    (4.47)
!> with 20-point Gauss-Legendre quadrature in v (smooth integrand; for a
!> circle it reproduces (F.1) to rounding, see the tests).
module water_section
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN, STATUS_NOT_CONVERGED
  use base_vector, only: cross
  use geometry_surface, only: surface_point_t
  use geometry_slide_query, only: slide_slice_t
  use water_channel, only: channel_t
  implicit none (type, external)
  private
  public :: circle_segment, circle_height_for_area, profile_water

contains

  !> Circular segment of height h in a circle of radius R (0 < h < 2R).
  elemental subroutine circle_segment(h, radius, area, width, alpha)
    real(wp), intent(in) :: h, radius           ! m
    real(wp), intent(out) :: area, width, alpha ! m^2, m, rad
    real(wp) :: q
    q = max(2*radius*h - h**2, 0.0_wp)
    alpha = 2*acos(min(max(1 - h/radius, -1.0_wp), 1.0_wp))
    width = 2*sqrt(q)
    area = radius**2*acos(min(max(1 - h/radius, -1.0_wp), 1.0_wp)) - (radius - h)*sqrt(q)
  end subroutine circle_segment

  !> The height h of the segment of area `area` in a circle of radius R (Newton on
  !> A(h) - area with dA/dh = b, started from the shallow-water form A ~ 4/3 sqrt(2R) h^1.5).
  pure subroutine circle_height_for_area(area, radius, h, status)
    real(wp), intent(in) :: area, radius
    real(wp), intent(out) :: h
    type(status_t), intent(out) :: status
    real(wp) :: a, b, alpha, lo, hi
    integer :: it
    status%code = 0
    if (area <= 0 .or. area >= 3.141592653589793_wp*radius**2) then
      call set_status(status, STATUS_DOMAIN, 'water area not between 0 and the full circle')
      h = 0
      return
    end if
    lo = 0; hi = 2*radius
    h = min((0.75_wp*area/sqrt(2*radius))**(2.0_wp/3), radius)
    do it = 1, 100
      call circle_segment(h, radius, a, b, alpha)
      if (a > area) then
        hi = h
      else
        lo = h
      end if
      if (abs(a - area) <= 1e-15_wp*area) return
      h = h - (a - area)/b
      if (h <= lo .or. h >= hi) h = (lo + hi)/2
      if (hi - lo <= 1e-15_wp*radius) return
    end do
    call set_status(status, STATUS_NOT_CONVERGED, 'water height from area did not converge')
  end subroutine circle_height_for_area

  !> Water area, width and edge parameters for height h above the point (u, v0)
  !> of any channel profile (4.45-4.47). Fails if the water would overtop the
  !> profile (no crossing of zeta = h within the channel's v range).
  pure subroutine profile_water(channel, u, v0, h, area, width, v_left, v_right, status)
    class(channel_t), intent(in) :: channel
    real(wp), intent(in) :: u, v0, h
    real(wp), intent(out) :: area, width, v_left, v_right
    type(status_t), intent(out) :: status
    real(wp), parameter :: x(10) = [0.0765265211334973_wp, 0.2277858511416451_wp, &
      0.3737060887154195_wp, 0.5108670019508271_wp, 0.6360536807265150_wp, 0.7463319064601508_wp, &
      0.8391169718222188_wp, 0.9122344282513259_wp, 0.9639719272779138_wp, 0.9931285991850949_wp]
    real(wp), parameter :: wt(10) = [0.1527533871307258_wp, 0.1491729864726037_wp, &
      0.1420961093183820_wp, 0.1316886384491766_wp, 0.1181945319615184_wp, 0.1019301198172404_wp, &
      0.0832767415767048_wp, 0.0626720483341091_wp, 0.0406014298003869_wp, 0.0176140071391521_wp]
    type(surface_point_t) :: p0, q
    type(slide_slice_t) :: slice
    real(wp) :: c(3, 0:3), t(3), n(3), e(3), mid, half, eta_l, eta_r, zeta, vv
    integer :: j, k

    area = 0; width = 0; v_left = v0; v_right = v0
    ! every point below is at this u: the centerline and its frame once
    call channel%slice(u, 1, slice, status)
    if (.not. status%ok()) return
    if (slice%kept) then   ! a swept slide's slice holds the centerline's c_u
      t = slice%c%d(:, 1)
    else
      call channel%centerline(u, c, status)
      if (.not. status%ok()) return
      t = c(:, 1)
    end if
    call channel%evaluate_in_slice(slice, v0, 1, p0, status)
    if (.not. status%ok()) return
    t = t/norm2(t)
    n = cross(p0%ru, p0%rv)
    n = n - t*dot_product(n, t)
    n = n/norm2(n)
    e = cross(n, t)
    if (dot_product(e, p0%rv) < 0) e = -e
    call edge(+1.0_wp, v_left, eta_l, status)
    if (.not. status%ok()) return
    call edge(-1.0_wp, v_right, eta_r, status)
    if (.not. status%ok()) return
    width = eta_l - eta_r
    mid = (v_left + v_right)/2; half = (v_left - v_right)/2
    do j = 1, 10
      do k = -1, 1, 2
        vv = mid + k*half*x(j)
        call channel%evaluate_in_slice(slice, vv, 1, q, status)
        if (.not. status%ok()) return
        zeta = dot_product(q%r - p0%r, n)
        area = area + half*wt(j)*(h - zeta)*dot_product(q%rv, e)
      end do
    end do

  contains

    !> March from v0 in direction `dir` until zeta >= h, then Newton/bisection.
    pure subroutine edge(dir, v_edge, eta, st)
      real(wp), intent(in) :: dir
      real(wp), intent(out) :: v_edge, eta
      type(status_t), intent(out) :: st
      real(wp) :: lo, hi, step, z, dz, v_min, v_max
      type(surface_point_t) :: s
      integer :: i
      call channel%v_range(v_min, v_max)
      step = 0.05_wp
      lo = v0; hi = v0
      do i = 1, 200
        hi = lo + dir*step
        if (hi < v_min .or. hi > v_max) hi = merge(v_max, v_min, dir > 0)
        call channel%evaluate_in_slice(slice, hi, 1, s, st)
        if (.not. st%ok()) return
        if (dot_product(s%r - p0%r, n) >= h) exit
        if (hi == v_min .or. hi == v_max .or. i == 200) then
          call set_status(st, STATUS_DOMAIN, 'the water overtops the cross-section (height ' // &
                          'above the lower rim of the profile)')
          v_edge = hi; eta = 0
          return
        end if
        lo = hi
      end do
      ! zeta(lo) < h <= zeta(hi); bracketed Newton in v
      v_edge = hi
      do i = 1, 100
        call channel%evaluate_in_slice(slice, v_edge, 1, s, st)
        if (.not. st%ok()) return
        z = dot_product(s%r - p0%r, n) - h
        dz = dot_product(s%rv, n)
        if (abs(z) <= 1e-14_wp*max(h, 1e-3_wp)) exit
        if (z > 0) then
          hi = v_edge
        else
          lo = v_edge
        end if
        if (dz /= 0) then
          v_edge = v_edge - z/dz
        else
          v_edge = (lo + hi)/2
        end if
        if ((v_edge - lo)*(v_edge - hi) > 0) v_edge = (lo + hi)/2
        if (abs(hi - lo) <= 1e-15_wp) exit
      end do
      eta = dot_product(s%r - p0%r, e)
    end subroutine edge
  end subroutine profile_water
end module water_section
