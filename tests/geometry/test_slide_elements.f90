!> Slides from standard elements: centerline derivatives to 4th order against
!> differences (in and outside the transitions); a 90 degree curve lies on a
!> circle (alone: the whole arc; after a straight with smooth joints: the arc
!> between the transitions); turning angle and height loss preserved by the
!> transitions; helix curvature R/(R^2 + c^2); sharp joints that change the
!> curvature refused; tube partials on the element centerline; bad elements
!> rejected with their index; the steepest element (45 deg) built, a rounding
!> steeper refused.
program test_slide_elements
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: curve_point_t, constant_curve_t
  use geometry_curve_frame, only: curve_frame_t, curve_frame_at
  use geometry_cross_section, only: circle_section_t
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain, &
                                     slide_points, max_element_slope_deg, max_element_slope_tan
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences, step 1e-4 m on a ~50 m curve: truncation h^2/6 |f'''|
  ! ~ 2e-9 S, rounding eps |f|/h ~ 1e-10 (|f| <= 50 m); 1e-7 (1 + S) keeps
  ! a margin > 20 while a wrong term (error ~ S) fails.
  real(wp), parameter :: h = 1e-4_wp, fd_tol = 1e-7_wp
  type(status_t) :: st
  type(slide_element_t) :: e(5)
  type(element_chain_curve_t) :: chain
  type(curve_point_t) :: p, pa, pb
  type(curve_frame_t) :: f
  type(constant_curve_t) :: up
  type(tube_surface_t) :: tube
  real(wp) :: r, center(2), s, heading, rr, cc, zdrop
  integer :: i, k

  up = constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp])
  r = 6
  e(1) = slide_element_t(kind='straight', length=8.0_wp, slope_deg=8.0_wp)
  e(2) = slide_element_t(kind='curve', radius=r, angle_deg=90.0_wp, direction='left', slope_deg=5.0_wp)
  e(3) = slide_element_t(kind='helix', radius=4.0_wp, turns=1.5_wp, drop=3.0_wp, direction='right')
  e(4) = slide_element_t(kind='curve', radius=7.0_wp, angle_deg=60.0_wp, direction='left', slope_deg=6.0_wp)
  e(5) = slide_element_t(kind='runout', length=6.0_wp, slope_deg=-1.0_wp)

  ! --- the 90 degree curve alone (no joint: transition 0 is allowed) is
  ! exactly on its circle
  chain = new_element_chain(e(2:2), [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
  call check(st%ok(), 'chain built: ' // st%text())
  center = [0.0_wp, r]             ! a left turn from the start along +x
  do i = 0, 20
    s = r*(pi/2)*i/20.0_wp
    call chain%evaluate(s, 1, p, st)
    ! atol 1e-12 m: node table and Gauss completion are exact to rounding
    call check_close(norm2(p%d(1:2, 0) - center), r, 0.0_wp, 1e-12_wp, '90 deg curve on its circle (alone)')
  end do
  call chain%evaluate(chain%total, 1, p, st)
  call check_close_array(p%d(1:2, 1), [0.0_wp, 1.0_wp], 0.0_wp, 1e-13_wp, 'heading +90 deg at the end (alone)')
  ! a sharp joint where the curvature and the slope change is refused
  ! (the speed of whatever rides it would jump: test_sharp_joints)
  chain = new_element_chain(e(1:2), [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'joint 1') > 0, &
             'a sharp joint is refused: '//st%text())

  ! --- smooth joints (2 m transitions): turning angle preserved, the central
  ! part of the curve is an arc of radius r
  chain = new_element_chain(e(1:2), [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 2.0_wp, st)
  call chain%evaluate(chain%total, 1, p, st)
  call check_close_array(p%d(1:2, 1), [0.0_wp, 1.0_wp], 0.0_wp, 1e-13_wp, 'heading +90 deg at the end (smooth)')
  call chain%evaluate(8 + r*pi/4, 1, p, st)
  heading = atan2(p%d(2, 1), p%d(1, 1))
  center = p%d(1:2, 0) + r*[-sin(heading), cos(heading)]
  do i = 0, 10
    s = 8 + 1.0_wp + (r*pi/2 - 2.0_wp)*i/10.0_wp    ! outside the transitions
    call chain%evaluate(s, 1, p, st)
    call check_close(norm2(p%d(1:2, 0) - center), r, 0.0_wp, 1e-12_wp, '90 deg curve: arc between transitions')
  end do

  ! --- the whole demo-like chain: derivatives, height loss, helix curvature
  chain = new_element_chain(e, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'five-element chain built')
  do i = 1, 23
    s = chain%total*(i - 0.37_wp)/23
    call chain%evaluate(s, 4, p, st)
    call chain%evaluate(s + h, 4, pa, st)
    call chain%evaluate(s - h, 4, pb, st)
    do k = 1, 4
      call check_close_array(p%d(:, k), (pa%d(:, k - 1) - pb%d(:, k - 1))/(2*h), 0.0_wp, &
                             fd_tol*(1 + maxval(abs(p%d(:, 1:4)))), 'chain derivative')
    end do
  end do
  ! symmetric transitions keep the total drop: sum of gradient x horizontal length
  zdrop = 8*tan(8*pi/180) + r*pi/2*tan(5*pi/180) + 3.0_wp + 7*pi/3*tan(6*pi/180) - 6*tan(pi/180)
  call chain%evaluate(chain%total, 0, p, st)
  call check_close(12 - p%d(3, 0), zdrop, 1e-13_wp, 0.0_wp, 'total height loss')
  ! helix (element 3) middle: curvature R/(R^2 + c^2), c = drop/(2 pi turns) per rad
  s = 8 + r*pi/2 + two_pi*4*1.5_wp/2
  call curve_frame_at(chain, up, s, 2, f, st)
  rr = 4; cc = 3.0_wp/(two_pi*1.5_wp)
  call check_close(f%chi, rr/(rr**2 + cc**2), 1e-12_wp, 0.0_wp, 'helix element curvature R/(R^2+c^2)')
  call check_close(f%chi_u, 0.0_wp, 0.0_wp, 1e-12_wp, 'helix element chi_u = 0')

  ! --- tube on the element centerline: partials against differences
  tube = new_tube_surface(chain, up, circle_section_t(radius=0.5_wp), st)
  call tube%check(400, st)
  call check(st%ok(), 'demo-like tube passes the folding check')
  call fd_tube()

  ! --- points for fitting
  block
    real(wp), allocatable :: pts(:, :), hz(:, :), sig(:)
    call slide_points(chain, 1.0_wp, pts, hz, sig)
    call check(size(pts, 2) >= ceiling(chain%total), 'about one point per metre')
    call check(all(hz(3, :) == 1), 'vertical horizon')
  end block

  ! --- bad elements: the message names the element
  e(2)%radius = 0
  chain = new_element_chain(e, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1.0_wp, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'element 2') > 0, &
             'radius 0 rejected: ' // st%text())
  e(2)%radius = r
  e(3)%kind = 'loop'
  chain = new_element_chain(e, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1.0_wp, st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'element 3') > 0, &
             'unknown kind rejected: ' // st%text())
  call steepest_elements()

  call finish_tests('test_slide_elements')

contains

  !> The one slope limit the input tables check too (io_element_table): a
  !> straight or a curve at max_element_slope_deg (45) is built, a rounding
  !> steeper is refused naming the range; a helix whose drop is exactly its
  !> horizontal length (45 deg) is built, one a rounding steeper refused.
  subroutine steepest_elements()
    type(slide_element_t) :: one(1)
    type(element_chain_curve_t) :: c
    real(wp) :: run
    call check(max_element_slope_deg == 45 .and. max_element_slope_tan == 1, 'the steepest element: 45 deg')
    one(1) = slide_element_t(kind='straight', length=5.0_wp, slope_deg=-max_element_slope_deg)
    c = new_element_chain(one, [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%ok(), 'a straight at -45 deg is built: ' // st%text())
    one(1)%slope_deg = nearest(max_element_slope_deg, 1.0_wp)
    c = new_element_chain(one, [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%code == STATUS_INVALID_INPUT .and. &
               index(st%text(), 'element 1 (straight): slope must lie in [-45, 45] deg') > 0, &
               'a straight a rounding steeper than 45 deg is refused: ' // st%text())
    one(1) = slide_element_t(kind='curve', radius=5.0_wp, angle_deg=30.0_wp, slope_deg=50.0_wp)
    c = new_element_chain(one, [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), '[-45, 45] deg') > 0, &
               'a curve at 50 deg is refused (the geometry allowed 60 before): ' // st%text())
    run = two_pi*4.0_wp*1.5_wp
    one(1) = slide_element_t(kind='helix', radius=4.0_wp, turns=1.5_wp, drop=run, direction='right')
    c = new_element_chain(one, [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%ok(), 'a helix at 45 deg is built: ' // st%text())
    one(1)%drop = nearest(run, 1.0_wp)
    c = new_element_chain(one, [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'a slope of at most 45 deg') > 0, &
               'a helix a rounding steeper than 45 deg is refused: ' // st%text())
  end subroutine steepest_elements

  subroutine fd_tube()
    type(surface_point_t) :: q0, qu1, qu0, qv1, qv0
    real(wp) :: uu, vv, tol, hs
    integer :: i
    hs = 1e-5_wp
    do i = 1, 9
      uu = chain%total*(i - 0.5_wp)/9.3_wp
      vv = 0.7_wp*i
      call tube%evaluate(uu, vv, 3, q0, st)
      call tube%evaluate(uu + hs, vv, 3, qu1, st)
      call tube%evaluate(uu - hs, vv, 3, qu0, st)
      call tube%evaluate(uu, vv + hs, 3, qv1, st)
      call tube%evaluate(uu, vv - hs, 3, qv0, st)
      ! 1e-6: |r| ~ 50 m makes rounding eps |r|/h ~ 1e-9; margin > 100
      tol = 1e-6_wp*(1 + maxval(abs([q0%ru, q0%rv, q0%ruu, q0%ruv, q0%rvv, q0%ruuu, q0%ruuv, q0%ruvv, q0%rvvv])))
      call check_close_array(q0%ru, (qu1%r - qu0%r)/(2*hs), 0.0_wp, tol, 'element tube r_u')
      call check_close_array(q0%rv, (qv1%r - qv0%r)/(2*hs), 0.0_wp, tol, 'element tube r_v')
      call check_close_array(q0%ruu, (qu1%ru - qu0%ru)/(2*hs), 0.0_wp, tol, 'element tube r_uu')
      call check_close_array(q0%ruv, (qv1%ru - qv0%ru)/(2*hs), 0.0_wp, tol, 'element tube r_uv')
      call check_close_array(q0%rvv, (qv1%rv - qv0%rv)/(2*hs), 0.0_wp, tol, 'element tube r_vv')
      call check_close_array(q0%ruuu, (qu1%ruu - qu0%ruu)/(2*hs), 0.0_wp, tol, 'element tube r_uuu')
      call check_close_array(q0%ruuv, (qv1%ruu - qv0%ruu)/(2*hs), 0.0_wp, tol, 'element tube r_uuv')
      call check_close_array(q0%ruvv, (qv1%ruv - qv0%ruv)/(2*hs), 0.0_wp, tol, 'element tube r_uvv')
      call check_close_array(q0%rvvv, (qv1%rvv - qv0%rvv)/(2*hs), 0.0_wp, tol, 'element tube r_vvv')
    end do
  end subroutine fd_tube
end program test_slide_elements
