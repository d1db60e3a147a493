!> The element chain's cheap evaluation (issue 29): x and y by the chord of
!> the arc from the nearest node where the heading is linear, against the
!> 8-point quadrature from the node everywhere (chain%quadrature_point, the
!> evaluation before the chord and the points the fits take), and the arc
!> length's integrand from the gradient alone against |c_u| of the whole
!> evaluation, on chains of every kind of element: the demo slide's (straights,
!> curves, a helix, an S-bend), a drop with a curve, bowls (sphere, cone, a
!> profile table) between straights, a chain whose joints change only the
!> slope and a sharp joint that changes nothing.
!>
!> positions: every 3.7 mm from 1 m before the start to 1 m beyond the end
!> and at every node's half-step either side, within 1e-13 m of the
!> quadrature (both are exact to ~1e-14 m; the chord made with a wrong
!> curvature, direction or length is off by 1e-6 m or more).
!> which completion: most of the demo chain's nodes take the chord, the
!> others the quadrature with their one transition's heading (a chain that
!> fell back to the whole heading's quadrature would fail), a lone bowl the
!> whole heading's; on a lone circle arc every point lies on the circle
!> within 1e-13 m.
!> derivatives: c_u against central differences of the positions where the
!> chord serves (h = 1e-5 m: truncation h^2/6 |c'''| ~ 1e-11, rounding
!> ~1e-15/h = 1e-10) within 1e-8. (Not in the transitions: there the
!> quadrature of 8 points over a node's half-step, before this change as
!> now, leaves jumps of ~2e-10 m between nodes at 2 m transitions, ~5e-7 m
!> at 0.3 m: bench/README.md, "The exact chain made cheap".)
!> speed: chain%speed(u) = sqrt(1 + g^2) against norm2 of the evaluation's
!> c_u within 1e-15 relative (a few roundings; a wrong gradient term is off
!> by far more); the whole length against the same 256 panels' Gauss-Legendre
!> of norm2(c_u) within 1e-13 relative (the rounding of 2048 sums in another
!> order; a wrong integrand or table is off by far more).
program test_slide_chain_evaluation
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_quadrature, only: gl8_x, gl8_w
  use geometry_curve, only: curve_point_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use scenario_fixtures, only: real_text
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  type(element_chain_curve_t) :: chain
  type(status_t) :: st
  type(slide_element_t) :: demo(8), bowl(3), drop(4), slopes(4)
  integer :: linear, i

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
  call compare_chain(chain, 'demo chain')
  linear = count(chain%node_kind == 0)
  call check(linear >= 0.6_wp*size(chain%node_kind), 'demo chain: most nodes take the chord ('// &
             real_text(real(linear, wp))//' of '//real_text(real(size(chain%node_kind), wp))//')')
  call check(count(chain%node_kind > 0) + linear == size(chain%node_kind), 'demo chain: every other node '// &
             'takes the quadrature with its one transition''s heading')
  ! the same with a heading, short transitions and a start below zero
  chain = new_element_chain(demo, [3.0_wp, -2.0_wp, 1.0_wp], 130.0_wp, 0.3_wp, st)
  call check(st%ok(), 'demo chain, short transitions, built: '//st%text())
  call compare_chain(chain, 'demo chain, short transitions')

  call lone_arc()

  drop(1) = slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp)
  drop(2) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=3.0_wp)
  drop(3) = slide_element_t(kind='curve', slope_deg=4.0_wp, radius=12.0_wp, angle_deg=90.0_wp)
  drop(4) = slide_element_t(kind='runout', length=8.0_wp, slope_deg=1.0_wp)
  chain = new_element_chain(drop, [0.0_wp, 0.0_wp, 14.0_wp], 0.0_wp, 2.0_wp, st)
  call check(st%ok(), 'drop chain built: '//st%text())
  call compare_chain(chain, 'drop chain')

  bowl(1) = slide_element_t(kind='straight', length=8.0_wp, slope_deg=10.0_wp)
  bowl(3) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp)
  bowl(2) = slide_element_t(kind='bowl', bowl_profile='sphere', radius=6.0_wp, slope_deg=50.0_wp, drop=2.0_wp, &
                            turns=1.0_wp, direction='right')
  chain = new_element_chain(bowl, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'sphere bowl chain built: '//st%text())
  call compare_chain(chain, 'sphere bowl chain')
  bowl(2)%bowl_profile = 'cone'
  chain = new_element_chain(bowl, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'cone bowl chain built: '//st%text())
  call compare_chain(chain, 'cone bowl chain')
  bowl(2)%bowl_profile = 'table'
  bowl(2)%bowl_rho = [(1.0_wp + 0.5_wp*real(i, wp), i = 0, 16)]
  bowl(2)%bowl_z = 0.1_wp*bowl(2)%bowl_rho**2
  chain = new_element_chain(bowl, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'table bowl chain built: '//st%text())
  call compare_chain(chain, 'table bowl chain')
  ! a bowl that begins and ends the chain: no windows, its spiral to both ends
  chain = new_element_chain(bowl(2:2), [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, st)
  call check(st%ok(), 'lone bowl built: '//st%text())
  call compare_chain(chain, 'lone bowl')
  call check(all(chain%node_kind == -1), 'lone bowl: every node takes the quadrature of the whole heading')

  ! joints that change the slope only (linear heading across them), a
  ! sharp joint (transition 0) that changes nothing
  slopes(1) = slide_element_t(kind='straight', length=5.0_wp, slope_deg=15.0_wp)
  slopes(2) = slide_element_t(kind='straight', length=4.0_wp, slope_deg=5.0_wp)
  slopes(3) = slide_element_t(kind='helix', radius=3.0_wp, turns=0.5_wp, drop=1.0_wp)
  slopes(4) = slide_element_t(kind='helix', radius=3.0_wp, turns=0.5_wp, drop=2.0_wp)
  chain = new_element_chain(slopes, [0.0_wp, 0.0_wp, 10.0_wp], -45.0_wp, 1.5_wp, st)
  call check(st%ok(), 'slope joints chain built: '//st%text())
  call compare_chain(chain, 'slope joints chain')
  slopes(2)%slope_deg = 15
  chain = new_element_chain(slopes(1:2), [0.0_wp, 0.0_wp, 10.0_wp], 10.0_wp, 0.0_wp, st)
  call check(st%ok() .and. all(chain%node_kind == 0), 'sharp joint that changes nothing: built, every node '// &
             'takes the chord: '//st%text())
  call compare_chain(chain, 'sharp joint that changes nothing')

  call finish_tests('test_slide_chain_evaluation')

contains

  !> Positions against the quadrature, c_u against differences, the speed
  !> against |c_u| and the whole length against a finer quadrature.
  subroutine compare_chain(c, what)
    type(element_chain_curve_t), intent(in) :: c
    character(len=*), intent(in) :: what
    type(curve_point_t) :: p
    real(wp) :: u, worst_x, worst_du, worst_speed, fine, s0, s1, half
    integer :: i, n, k
    worst_x = 0; worst_du = 0; worst_speed = 0
    n = ceiling((c%total + 2)/0.0037_wp)
    do i = 0, n
      u = -1 + i*0.0037_wp
      call one(c, u, worst_x, worst_du, worst_speed)
    end do
    half = c%node_step/2
    do k = 0, ubound(c%node_xy, 2)
      call one(c, k*c%node_step - half, worst_x, worst_du, worst_speed)
      call one(c, k*c%node_step + half, worst_x, worst_du, worst_speed)
      call one(c, nearest(k*c%node_step + half, -1.0_wp), worst_x, worst_du, worst_speed)
      call one(c, nearest(k*c%node_step - half, 1.0_wp), worst_x, worst_du, worst_speed)
    end do
    call check(worst_x <= 1e-13_wp, what//': positions within 1e-13 m of the quadrature (worst '// &
               real_text(worst_x)//' m)')
    call check(worst_du <= 1e-8_wp, what//': c_u against differences of the positions within 1e-8 (worst '// &
               real_text(worst_du)//')')
    call check(worst_speed <= 1e-15_wp, what//': speed = |c_u| within 1e-15 relative (worst '// &
               real_text(worst_speed)//')')
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
  end subroutine compare_chain

  !> The worst position, c_u and speed differences so far, with u = at.
  subroutine one(c, at, worst_x, worst_du, worst_speed)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: at
    real(wp), intent(inout) :: worst_x, worst_du, worst_speed
    real(wp), parameter :: h = 1e-5_wp
    type(curve_point_t) :: p, pa, pb
    call c%evaluate(at, 1, p, st)
    worst_x = max(worst_x, maxval(abs(p%d(:, 0) - c%quadrature_point(at))))
    worst_speed = max(worst_speed, abs(c%speed(at) - norm2(p%d(:, 1)))/norm2(p%d(:, 1)))
    call c%evaluate(at + h, 0, pa, st)
    call c%evaluate(at - h, 0, pb, st)
    if (chord(c, at - h) .and. chord(c, at + h)) &
      worst_du = max(worst_du, maxval(abs((pa%d(:, 0) - pb%d(:, 0))/(2*h) - p%d(:, 1))))
  end subroutine one

  !> Whether u lies on the chain where its node takes the chord.
  pure logical function chord(c, u)
    type(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: u
    chord = .false.
    if (u < 0 .or. u > c%total) return
    chord = c%node_kind(min(nint(u/c%node_step), ubound(c%node_kind, 1))) == 0
  end function chord

  !> A left curve of radius 5 m alone (no joints): every point on its circle.
  subroutine lone_arc()
    type(element_chain_curve_t) :: arc
    type(curve_point_t) :: p
    real(wp) :: worst, u
    integer :: i
    arc = new_element_chain([slide_element_t(kind='curve', radius=5.0_wp, angle_deg=300.0_wp, slope_deg=5.0_wp)], &
                            [1.0_wp, 2.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%ok() .and. all(arc%node_kind == 0), 'lone arc: built, every node takes the chord')
    worst = 0
    do i = 0, 3000
      u = arc%total*i/3000.0_wp
      call arc%evaluate(u, 0, p, st)
      worst = max(worst, abs(norm2(p%d(1:2, 0) - [1.0_wp, 7.0_wp]) - 5))
    end do
    call check(worst <= 1e-13_wp, 'lone arc: on its circle within 1e-13 m (worst '//real_text(worst)//' m)')
  end subroutine lone_arc
end program test_slide_chain_evaluation
