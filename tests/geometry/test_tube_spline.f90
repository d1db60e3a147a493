!> Tubes on fitted spline centerlines (FITPACK parcur/concur through
!> numerics_spline_curve): collinear points give the analytic cylinder (1e-10);
!> a helix through points has the helix curvature R/(R^2 + c^2) within the
!> fit's accuracy; a 90 degree curve element fitted from its points stays on
!> its circle over its whole circular part within the fit's accuracy
!> (measured by halving the spacing); prescribed end tangents are met;
!> tube partials on a spline centerline and spline horizon field against
!> central differences.
program test_tube_spline
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: curve_point_t, constant_curve_t, spline_centerline_t, new_spline_centerline
  use geometry_curve_frame, only: curve_frame_t, curve_frame_at
  use geometry_cross_section, only: circle_section_t
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  type(status_t) :: st
  type(spline_centerline_t) :: line, helix, curve, horizon
  type(constant_curve_t) :: up
  type(tube_surface_t) :: tube
  type(surface_point_t) :: p
  type(curve_frame_t) :: f
  type(curve_point_t) :: c
  type(element_chain_curve_t) :: chain
  type(slide_element_t) :: e(2)
  real(wp) :: pts(3, 241), hpts(3, 101), u, v, r0, rr, cc, worst, a, b, phi, center(2)
  real(wp) :: sig(241), uu(241), errs(3), sigma0, s
  integer :: i, j, k, n

  up = constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp])

  ! --- collinear points along x: a quintic through them is the line, with
  ! chord-length parameter u = x exactly, so the tube is the analytic cylinder
  do i = 1, 21
    pts(:, i) = [0.5_wp*(i - 1), 0.0_wp, 0.0_wp]
  end do
  line = new_spline_centerline(pts(:, 1:21), 0.0_wp, 5, st)
  call check(st%ok(), 'line fit: ' // st%text())
  r0 = 0.5_wp
  tube = new_tube_surface(line, up, circle_section_t(radius=r0), st)
  do i = 1, 6
    do j = 1, 5
      u = 1.37_wp*i + 0.11_wp*j
      v = 1.21_wp*j + 0.05_wp*i
      call tube%evaluate(u, v, 3, p, st)
      ! atol 1e-10 (acceptance): exact up to rounding of the spline's sums
      call check_close_array(p%r, [u, -r0*cos(v), -r0*sin(v)], 0.0_wp, 1e-10_wp, 'spline cylinder r')
      call check_close_array(p%ru, [1.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'spline cylinder r_u')
      call check_close_array(p%rv, [0.0_wp, r0*sin(v), -r0*cos(v)], 0.0_wp, 1e-10_wp, 'spline cylinder r_v')
      call check_close_array(p%ruu, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'spline cylinder r_uu')
      call check_close_array(p%ruv, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'spline cylinder r_uv')
      call check_close_array(p%rvv, [0.0_wp, r0*cos(v), r0*sin(v)], 0.0_wp, 1e-10_wp, 'spline cylinder r_vv')
      call check_close_array(p%ruuu, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'spline cylinder r_uuu')
      call check_close_array(p%ruuv, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'spline cylinder r_uuv')
      call check_close_array(p%ruvv, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'spline cylinder r_uvv')
      call check_close_array(p%rvvv, [0.0_wp, -r0*sin(v), r0*cos(v)], 0.0_wp, 1e-10_wp, 'spline cylinder r_vvv')
    end do
  end do
  call check_close(tube%length(), 10.0_wp, 1e-12_wp, 0.0_wp, 'spline line length')

  ! --- helix through 101 points over 2 turns: R = 4 m, c = 0.4 m/rad
  rr = 4; cc = 0.4_wp
  do i = 1, 101
    phi = 2*two_pi*(i - 1)/100.0_wp
    pts(:, i) = [rr*cos(phi), rr*sin(phi), cc*phi]
    hpts(:, i) = [0.2_wp*cos(phi), 0.1_wp, 1.0_wp]          ! a wobbling horizon field
  end do
  helix = new_spline_centerline(pts(:, 1:101), 0.0_wp, 5, st)
  call check(st%ok(), 'helix fit')
  call helix%domain(a, b)
  worst = 0
  do i = 1, 50
    u = a + (b - a)*(0.1_wp + 0.8_wp*i/50.0_wp)      ! away from the free ends
    call curve_frame_at(helix, up, u, 2, f, st)
    worst = max(worst, abs(f%chi/(rr/(rr**2 + cc**2)) - 1))
  end do
  ! fit accuracy: quintic interpolation with points dphi = 0.126 rad apart; the
  ! curvature error is O(dphi^4) ~ 2.5e-4 times a small constant: require 1e-5
  call check(worst < 1e-5_wp, 'fitted helix: curvature R/(R^2+c^2) within the fit accuracy')
  ! arc length: sqrt(R^2 + c^2) per radian, 4 pi radians; rtol 1e-7 from the fit
  call check_close(helix%total_length(), 4*pi*sqrt(rr**2 + cc**2), 1e-7_wp, 0.0_wp, 'fitted helix length')

  ! --- tube partials on a spline centerline with a spline horizon field
  ! the horizon field is sampled at the centerline's points: fit it over the
  ! centerline's parameters (cumulative chord length of the centerline points)
  horizon = new_spline_centerline(hpts, 0.0_wp, 5, st, parameters=chord(pts(:, 1:101)))
  call check(st%ok(), 'horizon fit')
  tube = new_tube_surface(helix, horizon, circle_section_t(radius=0.5_wp), st)
  call check(st%ok(), 'spline tube built')
  call fd_tube(tube, 'spline centerline and horizon')

  ! --- a 90 degree curve element (R = 6 m after a 4 m straight, joined by a
  ! 2 m transition as on every slide) fitted from its points like fit_chain
  ! does (quintic, interpolating, the chain's unit end tangents). By design the
  ! chain is on its circle exactly from the end of the transition, sigma0 =
  ! 4 m + 2 m/2 (the smoothstep has reached 1), to the element's end; the
  ! circle's centre is the chain's point at sigma0 plus R times its left
  ! normal. The whole circular part is checked: every point sampled at
  ! sigma >= sigma0 (8 per point spacing; u mapped linearly from sigma within
  ! each spacing), with the transition zone sigma < sigma0 the only part left
  ! out. Fit accuracy: the interior interpolation error C h^6 max|c^(6)| with
  ! |c^(6)| = 1/R^5 = 1.3e-4 1/m^5 and h = 0.224 m is <= 1.6e-8 m (C < 1);
  ! the largest error, though, sits within a spacing of the end, where the unit
  ! end tangent differs from dc/du (u = chord length, |dc/du| = 1 + h^2/(24 R^2)).
  ! Measured by halving h: 3.0e-8, 1.9e-9, 1.2e-10 m for h = 0.224, 0.112,
  ! 0.056 m (fourth order). The test asks for exactly that: worst(h) <= 1e-7 m
  ! (the stated accuracy at the 0.22 m spacing; a fit off the circle, a wrong
  ! centre or a transition reaching past sigma0 gives >= 1e-5 m) and an error
  ! that falls by more than 12 per halving (h^4 gives 16, h^3 would give 8).
  e(1) = slide_element_t(kind='straight', length=4.0_wp)
  e(2) = slide_element_t(kind='curve', radius=6.0_wp, angle_deg=90.0_wp, direction='left')
  chain = new_element_chain(e, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 2.0_wp, st)
  call check(st%ok(), 'curve element chain: ' // st%text())
  sigma0 = 4.0_wp + 2.0_wp/2
  call chain%evaluate(sigma0, 1, c, st)
  center = c%d(1:2, 0) + 6*[-c%d(2, 1), c%d(1, 1)]/norm2(c%d(1:2, 1))
  do k = 1, 3
    n = 60*2**(k - 1) + 1
    do i = 1, n
      sig(i) = chain%total*(i - 1)/real(n - 1, wp)
      call chain%evaluate(sig(i), 0, c, st)
      pts(:, i) = c%d(:, 0)
    end do
    uu(1:n) = chord(pts(:, 1:n))
    curve = new_spline_centerline(pts(:, 1:n), 0.0_wp, 5, st, start_tangent=[1.0_wp, 0.0_wp, 0.0_wp], &
                                  end_tangent=[0.0_wp, 1.0_wp, 0.0_wp])
    call check(st%ok(), 'curve element fit: ' // st%text())
    errs(k) = 0
    do i = 1, n - 1
      if (sig(i + 1) <= sigma0) cycle
      do j = 0, 8
        s = sig(i) + (sig(i + 1) - sig(i))*j/8.0_wp
        if (s < sigma0) cycle
        u = uu(i) + (uu(i + 1) - uu(i))*(s - sig(i))/(sig(i + 1) - sig(i))
        call curve%evaluate(u, 0, c, st)
        errs(k) = max(errs(k), abs(norm2(c%d(1:2, 0) - center) - 6))
      end do
    end do
  end do
  call check(errs(1) <= 1e-7_wp, '90 deg curve element: fitted centerline on its circle (1e-7 m at h = 0.22 m)')
  call check(errs(2) < errs(1)/12 .and. errs(3) < errs(2)/12, &
             '90 deg curve element: distance from the circle converges (> 12 per halving of h)')
  ! the end tangents on the fit with the coarsest spacing (as in the slides)
  curve = new_spline_centerline(pts(:, 1:241:4), 0.0_wp, 5, st, start_tangent=[1.0_wp, 0.0_wp, 0.0_wp], &
                                end_tangent=[0.0_wp, 1.0_wp, 0.0_wp])
  call curve%domain(a, b)
  call curve%evaluate(a, 1, c, st)
  call check_close_array(c%d(:, 1)/norm2(c%d(:, 1)), [1.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'start tangent')
  call curve%evaluate(b, 1, c, st)
  call check_close_array(c%d(:, 1)/norm2(c%d(:, 1)), [0.0_wp, 1.0_wp, 0.0_wp], 0.0_wp, 1e-10_wp, 'end tangent')

  call finish_tests('test_tube_spline')

contains

  pure function chord(x) result(uu)
    real(wp), intent(in) :: x(:, :)
    real(wp) :: uu(size(x, 2))
    integer :: k
    uu(1) = 0
    do k = 2, size(x, 2)
      uu(k) = uu(k - 1) + norm2(x(:, k) - x(:, k - 1))
    end do
  end function chord

  subroutine fd_tube(t, name)
    type(tube_surface_t), intent(in) :: t
    character(len=*), intent(in) :: name
    type(surface_point_t) :: q0, qu1, qu0, qv1, qv0
    real(wp) :: uu, vv, tol, hs, lo, hi, vlo, vhi
    integer :: k
    ! step 1e-5, |r| ~ 5 m: rounding eps |r|/h ~ 1e-10, truncation ~1e-11 S;
    ! 1e-7 (1 + S) keeps a margin > 100. A quintic is C4, so third partials
    ! (which use c_uuuu) are continuous and the differences converge.
    hs = 1e-5_wp
    call t%domain(lo, hi, vlo, vhi)
    do k = 1, 9
      uu = lo + (hi - lo)*(k - 0.41_wp)/9.2_wp
      vv = 0.69_wp*k
      call t%evaluate(uu, vv, 3, q0, st)
      call t%evaluate(uu + hs, vv, 3, qu1, st)
      call t%evaluate(uu - hs, vv, 3, qu0, st)
      call t%evaluate(uu, vv + hs, 3, qv1, st)
      call t%evaluate(uu, vv - hs, 3, qv0, st)
      tol = 1e-7_wp*(1 + maxval(abs([q0%r, q0%ru, q0%rv, q0%ruu, q0%ruv, q0%rvv, q0%ruuu, q0%ruuv, q0%ruvv, &
                                     q0%rvvv])))
      call check_close_array(q0%ru, (qu1%r - qu0%r)/(2*hs), 0.0_wp, tol, name // ': r_u')
      call check_close_array(q0%rv, (qv1%r - qv0%r)/(2*hs), 0.0_wp, tol, name // ': r_v')
      call check_close_array(q0%ruu, (qu1%ru - qu0%ru)/(2*hs), 0.0_wp, tol, name // ': r_uu')
      call check_close_array(q0%ruv, (qv1%ru - qv0%ru)/(2*hs), 0.0_wp, tol, name // ': r_uv')
      call check_close_array(q0%rvv, (qv1%rv - qv0%rv)/(2*hs), 0.0_wp, tol, name // ': r_vv')
      call check_close_array(q0%ruuu, (qu1%ruu - qu0%ruu)/(2*hs), 0.0_wp, tol, name // ': r_uuu')
      call check_close_array(q0%ruuv, (qv1%ruu - qv0%ruu)/(2*hs), 0.0_wp, tol, name // ': r_uuv')
      call check_close_array(q0%ruvv, (qv1%ruv - qv0%ruv)/(2*hs), 0.0_wp, tol, name // ': r_uvv')
      call check_close_array(q0%rvvv, (qv1%rvv - qv0%rvv)/(2*hs), 0.0_wp, tol, name // ': r_vvv')
    end do
  end subroutine fd_tube
end program test_tube_spline
