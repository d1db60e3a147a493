!> The element chain's x, y (issue 29; geometry_slide_chain_xy): the table
!> of knots (every <= 0.5 m, and at the ends of every window where the
!> heading bends and every w/16 inside it) completed from the nearer knot of
!> a span by the chord of the arc where the heading is linear, by the
!> quadrature of the knot's heading plus one transition's ramp within a
!> window, by the whole heading's quadrature where a bowl reaches in; and the
!> arc length's integrand from the gradient alone, on chains of every kind of
!> element: the demo slide's (straights, curves, a helix, an S-bend) with 2 m
!> and with 0.3 m transitions, a drop with a curve, bowls (sphere, cone, a
!> profile table) between straights and alone, a chain whose joints change
!> only the slope and a sharp joint that changes nothing.
!>
!> positions: every 3.7 mm from 1 m before the start to 1 m beyond the end,
!> at every knot and next to it either side, within 1e-13 m of a reference:
!> 8-point Gauss-Legendre of the heading on panels of <= 1/256 m split at
!> every window's ends (its error ~1e-15 m, the rounding of its ~2e4 sums
!> ~1e-14); measured: the worst 4e-14 m. The table made by whole 0.5 m
!> steps across the windows' ends (the fits' table, quadrature_point) is off
!> by up to 2.1e-9 m with 1.5 to 2 m transitions and 1.6e-6 m with 0.3 m
!> ones: checked within 1e-8 m and 1e-5 m (a wrong node is off by far more).
!> which completion: most of the demo chain's spans take the chord, those in
!> a window where the curvature changes the quadrature with its one
!> transition's heading, no span the whole heading's (a chain that fell back
!> to it would fail); in every such window the knots are at most w/16 apart;
!> a lone bowl's spans all take the whole heading's quadrature; on a lone
!> circle arc every point lies on the circle within 1e-13 m.
!> derivatives: c_u against 4th-order central differences of the positions
!> everywhere, the windows too (h = 1e-4 m: truncation h^4/30 |c^(5)| <
!> 1e-13 with |c^(5)| ~ 5e3 1/m^4 in a 0.3 m window, rounding ~1e-14/h =
!> 1e-10) within 1e-9. (The quadrature over whole node steps is off by
!> 8.7e-6 at 2 m transitions and 2.2e-2 at 0.3 m.)
!> speed: chain%speed(u) = sqrt(1 + g^2) against norm2 of the evaluation's
!> c_u within 1e-15 relative (a few roundings; a wrong gradient term is off
!> by far more); the whole length against the same 256 panels' Gauss-Legendre
!> of norm2(c_u) within 1e-13 relative (the rounding of 2048 sums in another
!> order; a wrong integrand or table is off by far more), and against the
!> reference's panels split at the windows' ends within 1e-8 relative: the
!> 256 equal panels' error where a window's end lies inside a panel
!> (geometry_curve; measured 3.6e-13 with 2 m transitions, 2.3e-9 with 0.3
!> m ones, 4.6e-10 with the drop's ramps).
program test_slide_chain_evaluation
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_quadrature, only: gl8_x, gl8_w, node_below
  use geometry_curve, only: curve_point_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use scenario_fixtures, only: real_text
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  type(element_chain_curve_t) :: chain
  type(status_t) :: st
  type(slide_element_t) :: demo(8), bowl(3), drop(4), slopes(4)
  integer :: i
  real(wp) :: chord
  ! compare_chain's reference and worst differences so far (one)
  real(wp), allocatable :: ref_s(:), ref_xy(:, :), ref_arc(:)
  real(wp) :: worst_x, worst_du, worst_speed, worst_fit

  demo(1) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=12.0_wp)
  demo(2) = slide_element_t(kind='curve', radius=5.0_wp, angle_deg=90.0_wp, slope_deg=6.0_wp)
  demo(3) = slide_element_t(kind='straight', length=4.0_wp, slope_deg=8.0_wp)
  demo(4) = slide_element_t(kind='helix', radius=4.0_wp, turns=1.0_wp, drop=2.5_wp, direction='right')
  demo(5) = slide_element_t(kind='straight', length=3.0_wp, slope_deg=7.0_wp)
  demo(6) = slide_element_t(kind='curve', radius=6.0_wp, angle_deg=60.0_wp, slope_deg=6.0_wp)
  demo(7) = slide_element_t(kind='curve', radius=6.0_wp, angle_deg=60.0_wp, slope_deg=6.0_wp, direction='right')
  demo(8) = slide_element_t(kind='runout', length=8.0_wp, slope_deg=1.0_wp)
  chain = new_element_chain(demo, [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 2.0_wp, st)
  call check(st%ok(), 'demo chain built: '//st%text())
  call compare_chain(chain, 'demo chain', 1e-8_wp)
  chord = sum(chain%knot(1:) - chain%knot(:ubound(chain%knot, 1) - 1), mask=chain%span_kind == 0)
  call check(chord >= 0.75_wp*chain%total, 'demo chain: the chord on most of its length ('// &
             real_text(chord)//' m of '//real_text(chain%total)//' m)')
  call check(all(chain%span_kind >= 0), 'demo chain: every other span takes the quadrature with its one '// &
             'transition''s heading')
  ! the same with a heading, short transitions and a start below zero
  chain = new_element_chain(demo, [3.0_wp, -2.0_wp, 1.0_wp], 130.0_wp, 0.3_wp, st)
  call check(st%ok(), 'demo chain, short transitions, built: '//st%text())
  call compare_chain(chain, 'demo chain, short transitions', 1e-5_wp)

  call lone_arc()

  drop(1) = slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp)
  drop(2) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=3.0_wp)
  drop(3) = slide_element_t(kind='curve', slope_deg=4.0_wp, radius=12.0_wp, angle_deg=90.0_wp)
  drop(4) = slide_element_t(kind='runout', length=8.0_wp, slope_deg=1.0_wp)
  chain = new_element_chain(drop, [0.0_wp, 0.0_wp, 14.0_wp], 0.0_wp, 2.0_wp, st)
  call check(st%ok(), 'drop chain built: '//st%text())
  call compare_chain(chain, 'drop chain', 1e-8_wp)

  bowl(1) = slide_element_t(kind='straight', length=8.0_wp, slope_deg=10.0_wp)
  bowl(3) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp)
  bowl(2) = slide_element_t(kind='bowl', bowl_profile='sphere', radius=6.0_wp, slope_deg=50.0_wp, drop=2.0_wp, &
                            turns=1.0_wp, direction='right')
  chain = new_element_chain(bowl, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'sphere bowl chain built: '//st%text())
  call compare_chain(chain, 'sphere bowl chain', 1e-8_wp)
  bowl(2)%bowl_profile = 'cone'
  chain = new_element_chain(bowl, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'cone bowl chain built: '//st%text())
  call compare_chain(chain, 'cone bowl chain', 1e-8_wp)
  bowl(2)%bowl_profile = 'table'
  bowl(2)%bowl_rho = [(1.0_wp + 0.5_wp*real(i, wp), i = 0, 16)]
  bowl(2)%bowl_z = 0.1_wp*bowl(2)%bowl_rho**2
  chain = new_element_chain(bowl, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'table bowl chain built: '//st%text())
  call compare_chain(chain, 'table bowl chain', 1e-8_wp)
  ! a bowl that begins and ends the chain: no windows, its spiral to both ends
  chain = new_element_chain(bowl(2:2), [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'lone bowl built: '//st%text())
  call compare_chain(chain, 'lone bowl', 1e-8_wp)
  call check(all(chain%span_kind == -1), 'lone bowl: every span takes the quadrature of the whole heading')

  ! joints that change the slope only (linear heading across them), a
  ! sharp joint (transition 0) that changes nothing
  slopes(1) = slide_element_t(kind='straight', length=5.0_wp, slope_deg=15.0_wp)
  slopes(2) = slide_element_t(kind='straight', length=4.0_wp, slope_deg=5.0_wp)
  slopes(3) = slide_element_t(kind='helix', radius=3.0_wp, turns=0.5_wp, drop=1.0_wp)
  slopes(4) = slide_element_t(kind='helix', radius=3.0_wp, turns=0.5_wp, drop=2.0_wp)
  chain = new_element_chain(slopes, [0.0_wp, 0.0_wp, 10.0_wp], -45.0_wp, 1.5_wp, st)
  call check(st%ok(), 'slope joints chain built: '//st%text())
  call compare_chain(chain, 'slope joints chain', 1e-8_wp)
  call check(count(chain%span_kind /= 0) == 16 .and. all(chain%span_kind == 0 .or. chain%span_kind == 2), &
             'slope joints chain: the chord but in the window of joint 2 (straight to helix, 16 spans)')
  slopes(2)%slope_deg = 15
  chain = new_element_chain(slopes(1:2), [0.0_wp, 0.0_wp, 10.0_wp], 10.0_wp, 0.0_wp, st)
  call check(st%ok() .and. all(chain%span_kind == 0), 'sharp joint that changes nothing: built, every span '// &
             'takes the chord: '//st%text())
  call compare_chain(chain, 'sharp joint that changes nothing', 1e-8_wp)

  call finish_tests('test_slide_chain_evaluation')

contains

  !> Positions against the reference, c_u against differences, the speed
  !> against |c_u|, the whole length against the same panels' quadrature
  !> and the reference's; the knots in the bending windows; the fits'
  !> points within fit_error of the reference.
  subroutine compare_chain(c, what, fit_error)
    type(element_chain_curve_t), intent(in) :: c
    character(len=*), intent(in) :: what
    real(wp), intent(in) :: fit_error
    type(curve_point_t) :: p
    real(wp) :: u, fine, s0, s1, gap
    integer :: i, n, k, j
    call reference(c, ref_s, ref_xy, ref_arc)
    worst_x = 0; worst_du = 0; worst_speed = 0; worst_fit = 0
    n = ceiling((c%total + 2)/0.0037_wp)
    do i = 0, n
      u = -1 + i*0.0037_wp
      call one(c, u)
    end do
    do k = 0, ubound(c%knot, 1)
      call one(c, c%knot(k))
      call one(c, nearest(c%knot(k), -1.0_wp))
      call one(c, nearest(c%knot(k), 1.0_wp))
      if (k > 0) call one(c, 0.5_wp*(c%knot(k - 1) + c%knot(k)))
    end do
    print '(a, 4es10.2)', what//': worst position, c_u, speed, fit: ', worst_x, worst_du, worst_speed, worst_fit
    call check(worst_x <= 1e-13_wp, what//': positions within 1e-13 m of the reference (worst '// &
               real_text(worst_x)//' m)')
    call check(worst_du <= 1e-9_wp, what//': c_u against differences of the positions within 1e-9 (worst '// &
               real_text(worst_du)//')')
    call check(worst_speed <= 1e-15_wp, what//': speed = |c_u| within 1e-15 relative (worst '// &
               real_text(worst_speed)//')')
    call check(worst_fit <= fit_error, what//': the fits'' points (quadrature_point) within '// &
               real_text(fit_error)//' m of the reference (worst '//real_text(worst_fit)//' m)')
    ! every window where the curvature changes: its knots at most w/16 apart
    do j = 1, size(c%joint)
      if (.not. (c%width(j) > 0 .and. c%kappa(j + 1) /= c%kappa(j))) cycle
      gap = 0
      do k = 1, ubound(c%knot, 1)
        if (c%knot(k - 1) >= c%joint(j) - c%width(j)/2 .and. c%knot(k) <= c%joint(j) + c%width(j)/2) &
          gap = max(gap, c%knot(k) - c%knot(k - 1))
      end do
      call check(gap > 0 .and. gap <= c%width(j)/16*(1 + 1e-12_wp), what//': the window of joint '// &
                 real_text(real(j, wp))//' has knots at most w/16 apart (widest '//real_text(gap)//' m)')
    end do
    ! the whole length: 8-point Gauss-Legendre of |c_u| on the arc length's 256 panels
    fine = 0
    do i = 0, 255
      s0 = c%total*i/256.0_wp
      s1 = c%total*(i + 1)/256.0_wp
      do k = 1, 8
        call c%evaluate(0.5_wp*(s0 + s1) + 0.5_wp*(s1 - s0)*gl8_x(k), 1, p, st)
        fine = fine + 0.5_wp*(s1 - s0)*gl8_w(k)*norm2(p%d(:, 1))
      end do
    end do
    call check_close(c%arc_length(0.0_wp, c%total), fine, 1e-13_wp, 0.0_wp, what//': the whole length')
    k = node_below(ref_s, c%total)
    print '(a, es10.2)', what//': the whole length against the reference, relative: ', &
      c%arc_length(0.0_wp, c%total)/ref_arc(k + 1) - 1
    call check_close(c%arc_length(0.0_wp, c%total), ref_arc(k + 1), 1e-8_wp, 0.0_wp, what// &
                     ': the whole length against the reference''s panels')
  end subroutine compare_chain

  !> The worst position, c_u, speed and fit differences so far, with u = at.
  subroutine one(c, at)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: at
    real(wp), parameter :: h = 1e-4_wp
    type(curve_point_t) :: p, pa, pb, pc, pd
    real(wp) :: x(2), q(3), d(3)
    call c%evaluate(at, 1, p, st)
    x = reference_xy(c, ref_s, ref_xy, at)
    worst_x = max(worst_x, maxval(abs(p%d(1:2, 0) - x)))
    if (at >= 0 .and. at <= c%total) then
      q = c%quadrature_point(at)
      worst_fit = max(worst_fit, maxval(abs(q(1:2) - x)))
    end if
    worst_speed = max(worst_speed, abs(c%speed(at) - norm2(p%d(:, 1)))/norm2(p%d(:, 1)))
    call c%evaluate(at + h, 0, pa, st)
    call c%evaluate(at - h, 0, pb, st)
    call c%evaluate(at + 2*h, 0, pc, st)
    call c%evaluate(at - 2*h, 0, pd, st)
    d = (8*(pa%d(:, 0) - pb%d(:, 0)) - (pc%d(:, 0) - pd%d(:, 0)))/(12*h) - p%d(:, 1)
    ! z only on the chain (below a drop's start z is not its slope's integral)
    if (at - 2*h < 0 .or. at + 2*h > c%total) d(3) = 0
    worst_du = max(worst_du, maxval(abs(d)))
  end subroutine one

  !> The reference: x, y by 8-point Gauss-Legendre of the chain's heading on
  !> panels of <= 1/256 m from 1.01 m before the start to 1.01 m beyond the
  !> end, split at every window's ends (ref_s, ref_xy at the panels' ends),
  !> and the arc length's integrand |c_u| = sqrt(1 + g^2) on the same panels
  !> from the start (ref_arc, 0 before it).
  subroutine reference(c, ref_s, ref_xy, ref_arc)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), allocatable, intent(out) :: ref_s(:), ref_xy(:, :), ref_arc(:)
    real(wp), allocatable :: ends(:)
    real(wp) :: lo, hi, run(3), carry(3), add(3), t
    integer :: j, p, m, k, n
    ends = [-1.01_wp, 0.0_wp]
    do j = 1, size(c%joint)
      if (c%width(j) > 0) ends = [ends, c%joint(j) - c%width(j)/2, c%joint(j) + c%width(j)/2]
    end do
    ends = [ends, c%total, c%total + 1.01_wp]
    n = 0
    do p = 2, size(ends)
      n = n + max(0, ceiling((ends(p) - ends(p - 1))*256))
    end do
    allocate (ref_s(0:n), ref_xy(2, 0:n), ref_arc(0:n))
    ref_s(0) = ends(1)
    k = 0
    do p = 2, size(ends)
      m = max(0, ceiling((ends(p) - ends(p - 1))*256))
      do j = 1, m
        k = k + 1
        ref_s(k) = ends(p - 1) + (ends(p) - ends(p - 1))*j/real(m, wp)
        if (j == m) ref_s(k) = ends(p)
      end do
    end do
    ! x, y at the first end: the panels from the start backwards
    ref_xy(:, 0) = c%start(1:2)
    m = ceiling(1.01_wp*256)
    do j = 1, m
      hi = -1.01_wp*(j - 1)/real(m, wp)
      lo = -1.01_wp*j/real(m, wp)
      ref_xy(:, 0) = ref_xy(:, 0) - panel(c, lo, hi)
    end do
    ! the sums compensated (Neumaier): ~2e4 panels' roundings would add up
    ! to ~1e-12 m where the panels are alike
    run = [ref_xy(:, 0), 0.0_wp]
    carry = 0
    ref_arc = 0
    do k = 1, n
      add = [panel(c, ref_s(k - 1), ref_s(k)), 0.0_wp]
      if (ref_s(k - 1) >= 0 .and. ref_s(k) <= c%total) add(3) = speed_panel(c, ref_s(k - 1), ref_s(k))
      do j = 1, 3
        t = run(j) + add(j)
        if (abs(run(j)) >= abs(add(j))) then
          carry(j) = carry(j) + ((run(j) - t) + add(j))
        else
          carry(j) = carry(j) + ((add(j) - t) + run(j))
        end if
        run(j) = t
      end do
      ref_xy(:, k) = run(1:2) + carry(1:2)
      ref_arc(k) = run(3) + carry(3)
    end do
  end subroutine reference

  !> The reference's x, y at u: from its panel's start.
  function reference_xy(c, ref_s, ref_xy, u) result(xy)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: ref_s(0:), ref_xy(:, 0:), u
    real(wp) :: xy(2)
    integer :: k
    k = node_below(ref_s, u)
    xy = ref_xy(:, k) + panel(c, ref_s(k), u)
  end function reference_xy

  !> 8-point Gauss-Legendre of [cos psi, sin psi] over [a, b].
  function panel(c, a, b) result(xy)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: a, b
    real(wp) :: xy(2), psi
    integer :: i
    xy = 0
    do i = 1, 8
      psi = c%heading(0.5_wp*(a + b) + 0.5_wp*(b - a)*gl8_x(i))
      xy = xy + gl8_w(i)*[cos(psi), sin(psi)]
    end do
    xy = 0.5_wp*(b - a)*xy
  end function panel

  !> 8-point Gauss-Legendre of |c_u| over [a, b].
  real(wp) function speed_panel(c, a, b) result(q)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: a, b
    integer :: i
    q = 0
    do i = 1, 8
      q = q + gl8_w(i)*c%speed(0.5_wp*(a + b) + 0.5_wp*(b - a)*gl8_x(i))
    end do
    q = 0.5_wp*(b - a)*q
  end function speed_panel

  !> A left curve of radius 5 m alone (no joints): every point on its circle.
  subroutine lone_arc()
    type(element_chain_curve_t) :: arc
    type(curve_point_t) :: p
    real(wp) :: worst, u
    integer :: i
    arc = new_element_chain([slide_element_t(kind='curve', radius=5.0_wp, angle_deg=300.0_wp, slope_deg=5.0_wp)], &
                            [1.0_wp, 2.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%ok() .and. all(arc%span_kind == 0), 'lone arc: built, every span takes the chord')
    worst = 0
    do i = 0, 3000
      u = arc%total*i/3000.0_wp
      call arc%evaluate(u, 0, p, st)
      worst = max(worst, abs(norm2(p%d(1:2, 0) - [1.0_wp, 7.0_wp]) - 5))
    end do
    call check(worst <= 1e-13_wp, 'lone arc: on its circle within 1e-13 m (worst '//real_text(worst)//' m)')
  end subroutine lone_arc
end program test_slide_chain_evaluation
