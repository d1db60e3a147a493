!> The water in curved channels:
!> - an S-bend and its mirror image (a -> -a, a reflection y -> -y) give
!>   mirror paths: the horizon frame maps to y -> -My, z -> Mz, so the mirrored
!>   surface is r'(u, v) = M r(u, pi - v) and the path has u' = u, v' = pi - v;
!> - with f2 = f3 = 0 the curvature terms vanish exactly: the run equals, bit
!>   for bit, a run whose channel reports chi = chi_s = 0;
!> - energy: kinetic + potential lost = work of friction (correction off), and
!>   = work of friction + Saint-Venant term (correction on), to 1e-8;
!> - the geometry layer's tube (helix centerline, circle) is the same channel
!>   as the analytic helix tube; an open flume (non-circular) keeps A w = Q.
module test_water_sbend_support
  use base_kinds, only: wp
  use base_status, only: status_t
  use water_channel, only: analytic_tube_t
  implicit none (type, external)
  private
  public :: flat_tube_t

  !> The same tube with the curvature terms switched off.
  type, extends(analytic_tube_t) :: flat_tube_t
  contains
    procedure :: curvature => flat_curvature
  end type flat_tube_t

contains

  pure subroutine flat_curvature(self, u, chi, chi_s, status)
    class(flat_tube_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: chi, chi_s
    type(status_t), intent(out) :: status
    associate (unused => self, unused_u => u)
    end associate
    chi = 0; chi_s = 0
    status%code = 0
  end subroutine flat_curvature
end module test_water_sbend_support

program test_water_sbend
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: helix_curve_t, constant_curve_t, line_curve_t
  use geometry_cross_section, only: circle_section_t, flume_section_t, section_holder_t, &
    blended_section_t, new_blended_section
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use numerics_ode, only: ode_options_t
  use testing, only: check, check_close, check_close_array, finish_tests
  use water_channel, only: channel_t, analytic_tube_t, new_s_bend_tube, new_helix_tube
  use water_tube_channel, only: tube_channel_t, new_tube_channel
  use water_streamline, only: streamline_t, CORRECTION_OFF, CORRECTION_FULL
  use water_flow, only: water_start_t, water_series_t, water_initial_state, simulate_water, &
    START_HEIGHT_SPEED, START_SPEED, OUTCOME_END
  use test_water_sbend_support, only: flat_tube_t
  implicit none (type, external)

  type(water_series_t) :: a, b
  type(flat_tube_t) :: flat

  ! mirror symmetry (correction on: every term of the model takes part). With
  ! f3 > 0 the friction jumps at the inflections (chi = 0, chi_s changes sign),
  ! where the two runs' step sequences part; with f3 = 0 the right-hand side is
  ! smooth.
  ! tolerances: smooth, two independent runs at rtol 1e-12: 1e-8; with the
  ! jumps the step control bounds only the local error at each jump: 1e-6
  call mirror(0.0_wp, 1e-8_wp)
  call mirror(0.979822_wp, 1e-6_wp)
  call run(new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_FULL, 0.0274748_wp, &
           0.138285_wp, 0.979822_wp, a)
  call energy(a, .true.)

  ! f2 = f3 = 0: exactly the run without curvature terms
  call run(new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_OFF, 0.0274748_wp, &
           0.0_wp, 0.0_wp, a)
  flat%analytic_tube_t = new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp)
  call run(flat, CORRECTION_OFF, 0.0274748_wp, 0.0_wp, 0.0_wp, b)
  call check(a%n == b%n, 'f2 = f3 = 0: same samples')
  if (a%n == b%n) then
    call check(all(a%u(:a%n) == b%u(:b%n)) .and. all(a%v(:a%n) == b%v(:b%n)) .and. &
               all(a%speed(:a%n) == b%speed(:b%n)), 'f2 = f3 = 0: chi terms vanish exactly')
  end if
  call run(new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_OFF, 0.0274748_wp, &
           0.138285_wp, 0.979822_wp, a)
  call check(maxval(abs(a%speed(:a%n) - b%speed(:a%n))) > 1e-3_wp, 'f2, f3 do slow the water')
  call energy(a, .false.)

  call geometry_tube()
  call flume()
  call blended_flume()
  call finish_tests('test_water_sbend')

contains

  subroutine mirror(f3, tol)
    real(wp), intent(in) :: f3, tol
    real(wp) :: du, dv, dw, dh, de
    call run(new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_FULL, 0.0274748_wp, &
             0.138285_wp, f3, a)
    call run(new_s_bend_tube(0.5_wp, -1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_FULL, 0.0274748_wp, &
             0.138285_wp, f3, b)
    call check(a%outcome == OUTCOME_END .and. b%outcome == OUTCOME_END, 'S-bends run to their end')
    call check(a%n == b%n, 'mirror runs have the same samples')
    if (a%n /= b%n) return
    du = maxval(abs(a%u(:a%n) - b%u(:b%n)))
    dv = maxval(abs(a%v(:a%n) - (pi - b%v(:b%n))))
    dw = maxval(abs(a%speed(:a%n) - b%speed(:b%n)))
    dh = maxval(abs(a%height(:a%n) - b%height(:b%n)))
    de = maxval(abs(a%left_edge(2, :a%n) - (pi - b%right_edge(2, :b%n))))
    call check(du <= tol, 'mirror S-bend: same u(t)')
    call check(dv <= tol, 'mirror S-bend gives the mirror path v -> pi - v')
    call check(dw <= tol, 'mirror: same speed')
    call check(dh <= tol, 'mirror: same height')
    call check(de <= tol, 'mirror: left edge <-> right edge')
    call check(maxval(abs(a%v(:a%n) - pi/2)) > 0.1_wp, 'the S-bend moves the water off the bottom')
    print '(a, f6.3, a, 5es9.1)', '  mirror (f3 = ', f3, '): differences u, v, w, h, edges ', du, dv, dw, dh, de
  end subroutine mirror

  subroutine run(channel, correction, f1, f2, f3, s)
    class(channel_t), intent(in) :: channel
    integer, intent(in) :: correction
    real(wp), intent(in) :: f1, f2, f3
    type(water_series_t), intent(out) :: s
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7)
    allocate (model%channel, source=channel)
    model%correction = correction
    model%f1 = f1; model%f2 = f2; model%f3 = f3
    start%mode = START_HEIGHT_SPEED; start%height = 0.02_wp; start%speed = 2; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'start')
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 60.0_wp, 0.02_wp, s, st)
    call check(st%ok(), 'run: '//st%text())
  end subroutine run

  subroutine energy(s, with_correction)
    type(water_series_t), intent(in) :: s
    logical, intent(in) :: with_correction
    real(wp) :: e_err, loss, work
    integer :: i
    e_err = 0
    do i = 1, s%n
      loss = (s%kinetic(1) + s%potential(1)) - (s%kinetic(i) + s%potential(i))
      work = s%friction_work(i)
      if (with_correction) work = work + s%correction_work(i)
      e_err = max(e_err, abs(loss + work)/abs(s%friction_work(s%n)))
    end do
    ! 1e-8 relative (issue bound); rtol 1e-12
    call check(e_err <= 1e-8_wp, 'S-bend energy loss = work of friction (and Saint-Venant term)')
    print '(a, l1, a, es10.2)', '  energy balance (correction ', with_correction, '): ', e_err
  end subroutine energy

  !> geometry_tube with a helix centerline c = [rho cos u, rho sin u, -p u] and a
  !> circle equals the analytic helix tube, partials and curvature included.
  subroutine geometry_tube()
    type(tube_surface_t) :: tube
    type(tube_channel_t) :: tc
    type(analytic_tube_t) :: ref
    type(status_t) :: st
    type(surface_point_t) :: p, q
    real(wp) :: chi1, chi2, s1, s2
    integer :: i
    tube = new_tube_surface(helix_curve_t(radius=3.0_wp, pitch=-0.3_wp, u_min=0.0_wp, u_max=10.0_wp), &
                            constant_curve_t(), circle_section_t(radius=0.5_wp), st)
    call check(st%ok(), 'geometry tube built')
    tc = new_tube_channel(tube)
    ref = new_helix_tube(0.5_wp, 3.0_wp, 0.3_wp, 1.0_wp, 10.0_wp)
    do i = 1, 4
      call tc%evaluate(1.3_wp*i, 0.7_wp*i, 2, p, st)
      call ref%evaluate(1.3_wp*i, 0.7_wp*i, 2, q, st)
      call check_close_array([p%r, p%ru, p%rv, p%ruu, p%ruv, p%rvv], [q%r, q%ru, q%rv, q%ruu, q%ruv, q%rvv], &
                             0.0_wp, 1e-13_wp, 'geometry tube = analytic helix tube')
      call tc%curvature(1.3_wp*i, chi1, s1, st)
      call ref%curvature(1.3_wp*i, chi2, s2, st)
      call check_close(chi1, chi2, 1e-13_wp, 0.0_wp, 'geometry tube curvature')
    end do
    call check_close(tc%circle_radius(1.0_wp), 0.5_wp, 0.0_wp, 0.0_wp, 'circle radius seen through the seam')
    call check_close(tc%arc_length(2.0_wp), ref%arc_length(2.0_wp), 1e-12_wp, 0.0_wp, 'arc length')
  end subroutine geometry_tube

  !> A straight open flume (semicircle + walls): the water area comes from the
  !> profile (4.45-4.48); continuity A w = Q holds along the run.
  subroutine flume()
    type(tube_surface_t) :: tube
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7), cerr, th
    th = 8*pi/180
    tube = new_tube_surface(line_curve_t(direction=[cos(th), 0.0_wp, -sin(th)], u_min=0.0_wp, u_max=20.0_wp), &
                            constant_curve_t(), flume_section_t(), st)
    allocate (model%channel, source=new_tube_channel(tube))
    call check(model%channel%circle_radius(0.0_wp) == 0, 'flume is not a circle')
    model%correction = CORRECTION_OFF
    model%flow_rate = 0.004_wp
    start%mode = START_SPEED; start%speed = 1.5_wp; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'flume start: '//st%text())
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 30.0_wp, 0.05_wp, s, st)
    call check(st%ok() .and. s%outcome == OUTCOME_END, 'flume: runs to the end '//st%text())
    cerr = maxval(abs(s%area(:s%n)*s%speed(:s%n) - model%flow_rate))/model%flow_rate
    ! 1e-8: h integrated at rtol 1e-12, the area from quadrature to ~1e-14
    call check(cerr <= 1e-8_wp, 'flume: continuity A w = Q from the profile')
    print '(a, es10.2, a, f8.5, a)', '  flume continuity ', cerr, ', final height ', s%height(s%n), ' m'
  end subroutine flume
  !> A straight flume whose section widens along the slide (radius 0.5 -> 0.6 m,
  !> logistic blend): the area depends on u, dA/dt at fixed h = A_u u' enters
  !> the height (4.24) and the correction; continuity still holds.
  subroutine blended_flume()
    type(tube_surface_t) :: tube
    type(section_holder_t) :: sections(2)
    type(blended_section_t) :: blend
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7), cerr, th
    th = 8*pi/180
    allocate (sections(1)%section, source=flume_section_t(radius=0.5_wp, wall=0.15_wp))
    allocate (sections(2)%section, source=flume_section_t(radius=0.6_wp, wall=0.18_wp))
    blend = new_blended_section(sections, [8.0_wp], [11.0_wp], st)
    call check(st%ok(), 'blended flume section')
    tube = new_tube_surface(line_curve_t(direction=[cos(th), 0.0_wp, -sin(th)], u_min=0.0_wp, u_max=20.0_wp), &
                            constant_curve_t(), blend, st)
    allocate (model%channel, source=new_tube_channel(tube))
    call check(model%channel%section_varies(), 'blended section varies along u')
    model%correction = CORRECTION_FULL
    model%flow_rate = 0.004_wp
    start%mode = START_SPEED; start%speed = 1.5_wp; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 30.0_wp, 0.05_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_END, 'blended flume: runs to the end '//st%text())
    cerr = maxval(abs(s%area(:s%n)*s%speed(:s%n) - model%flow_rate))/model%flow_rate
    ! 1e-8: A_u from central differences (step 1e-5 u: truncation ~1e-10 relative over
    ! the 3 m transition) on top of the integration at rtol 1e-12
    call check(cerr <= 1e-8_wp, 'blended flume: continuity with the section changing along u')
    print '(a, es10.2)', '  blended flume continuity ', cerr
  end subroutine blended_flume
end program test_water_sbend
