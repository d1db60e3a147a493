!> The water in curved channels:
!> - an S-bend and its mirror image (a -> -a, a reflection y -> -y) give
!>   mirror paths: the horizon frame maps to y -> -My, z -> Mz, so the mirrored
!>   surface is r'(u, v) = M r(u, pi - v) and the path has u' = u, v' = pi - v;
!> - the S-bend itself is a left curve followed by its mirror image: with
!>   M = diag(1, -1, 1) and L = pi/k, c(u + L) = M c(u) + [L, 0, -q L], and the
!>   tube r(u + L, v) = M r(u, pi - v) + [L, 0, -q L] (the horizon frame maps
!>   as above). Gravity is vertical, so the model commutes with the map
!>   G: (u, v, u', v', h) -> (u + L, pi - v, u', -v', h). By uniqueness of the
!>   solution, the path over the second curve is the mirror of the path over
!>   the first if and only if the water enters the second curve in the G-image
!>   of the state in which it entered the first. That is what can be tested:
!>   water started at the bottom at u = L (the G-image of the bottom start at
!>   u = 0, beta = 0) runs the mirror path of water started at u = 0, shifted
!>   by L, at every time (flat, q = 0, and constant slope). Water started at
!>   the bottom at u = 0 does NOT enter the second curve at the bottom and
!>   along the centerline (the first curve has pushed it up the outer wall and
!>   changed its speed), so its own path over the two halves is not mirror
!>   symmetric; the test measures that and checks that the reason holds;
!> - with f2 = f3 = 0 the curvature terms vanish exactly: the run equals, bit
!>   for bit, a run whose channel reports chi = chi_s = 0;
!> - energy: kinetic + potential lost = work of friction (correction off), and
!>   = work of friction + Saint-Venant term (correction on), to 1e-8;
!> - an open flume (non-circular) keeps A w = Q.
module test_water_sbend_support
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_tube, only: new_s_bend_tube
  use water_channel, only: channel_t, new_channel
  implicit none (type, external)
  private
  public :: flat_tube_t, s_bend_channel

  !> The same tube with the curvature terms switched off.
  type, extends(channel_t) :: flat_tube_t
  contains
    procedure :: curvature => flat_curvature
    procedure :: evaluate_with_curvature => flat_evaluate_with_curvature
  end type flat_tube_t

contains

  !> The S-bend tube c = [u, a sin(k u), -q u] of radius r, u in [0, length].
  function s_bend_channel(radius, amplitude, wavenumber, slope, length) result(c)
    real(wp), intent(in) :: radius, amplitude, wavenumber, slope, length
    type(channel_t) :: c
    type(status_t) :: st
    c = new_channel(new_s_bend_tube(radius, amplitude, wavenumber, slope, length, st))
    if (.not. st%ok()) error stop 'S-bend tube: '//st%text()
  end function s_bend_channel

  pure subroutine flat_evaluate_with_curvature(self, u, v, p, chi, chi_s, speed, speed_u, status)
    class(flat_tube_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    type(surface_point_t), intent(out) :: p
    real(wp), intent(out) :: chi, chi_s, speed, speed_u
    type(status_t), intent(out) :: status
    call self%channel_t%evaluate_with_curvature(u, v, p, chi, chi_s, speed, speed_u, status)
    chi = 0; chi_s = 0
  end subroutine flat_evaluate_with_curvature

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
  use water_channel, only: channel_t, new_channel
  use water_streamline, only: streamline_t, CORRECTION_OFF, CORRECTION_FULL
  use water_flow, only: water_start_t, water_series_t, water_initial_state, simulate_water, &
    START_HEIGHT_SPEED, START_SPEED, OUTCOME_END
  use test_water_sbend_support, only: flat_tube_t, s_bend_channel
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
  call glide(0.1_wp, 2.0_wp, CORRECTION_FULL)
  ! flat: the water slows down to near-critical flow before the end with the
  ! correction on, so it is off here
  call glide(0.0_wp, 3.0_wp, CORRECTION_OFF)
  call run(s_bend_channel(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_FULL, 0.0274748_wp, &
           0.138285_wp, 0.979822_wp, a)
  call energy(a, .true.)

  ! f2 = f3 = 0: exactly the run without curvature terms
  call run(s_bend_channel(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_OFF, 0.0274748_wp, &
           0.0_wp, 0.0_wp, a)
  flat%channel_t = s_bend_channel(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp)
  call run(flat, CORRECTION_OFF, 0.0274748_wp, 0.0_wp, 0.0_wp, b)
  call check(a%n == b%n, 'f2 = f3 = 0: same samples')
  if (a%n == b%n) then
    call check(all(a%u(:a%n) == b%u(:b%n)) .and. all(a%v(:a%n) == b%v(:b%n)) .and. &
               all(a%speed(:a%n) == b%speed(:b%n)), 'f2 = f3 = 0: chi terms vanish exactly')
  end if
  call run(s_bend_channel(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_OFF, 0.0274748_wp, &
           0.138285_wp, 0.979822_wp, a)
  call check(maxval(abs(a%speed(:a%n) - b%speed(:a%n))) > 1e-3_wp, 'f2, f3 do slow the water')
  call energy(a, .false.)

  call flume()
  call blended_flume()
  call finish_tests('test_water_sbend')

contains

  subroutine mirror(f3, tol)
    real(wp), intent(in) :: f3, tol
    real(wp) :: du, dv, dw, dh, de
    call run(s_bend_channel(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_FULL, 0.0274748_wp, &
             0.138285_wp, f3, a)
    call run(s_bend_channel(0.5_wp, -1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp), CORRECTION_FULL, 0.0274748_wp, &
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

  !> The S-bend's own symmetry (see the header): water started at the bottom
  !> at u = L = pi/k runs G of the path started at the bottom at u = 0.
  subroutine glide(slope, speed, correction)
    real(wp), intent(in) :: slope, speed   ! descent per m; start speed, m/s
    integer, intent(in) :: correction
    real(wp), parameter :: k = 0.4_wp, half = pi/k
    real(wp) :: du, dv, dw, dh, de, asym, lam, v_mid, beta_mid
    integer :: i, j, n
    character(len=24) :: label
    write (label, '(a, f4.2, a)') 'S-bend (slope ', slope, ')'
    call run(s_bend_channel(0.5_wp, 1.5_wp, k, slope, 30.0_wp), correction, 0.0274748_wp, &
             0.138285_wp, 0.979822_wp, a, speed=speed)
    call run(s_bend_channel(0.5_wp, 1.5_wp, k, slope, 30.0_wp), correction, 0.0274748_wp, &
             0.138285_wp, 0.979822_wp, b, speed=speed, u0=half)
    call check(a%outcome == OUTCOME_END .and. b%outcome == OUTCOME_END, trim(label)//': both runs reach the end')
    ! same output times; the run started at L reaches the end first; its last
    ! sample is the end root, off the output grid
    n = min(a%n, b%n - 1)
    call check(n > 100, trim(label)//': runs long enough to compare')
    du = maxval(abs(b%u(:n) - (a%u(:n) + half)))
    dv = maxval(abs(b%v(:n) - (pi - a%v(:n))))
    dw = maxval(abs(b%speed(:n) - a%speed(:n)))
    dh = maxval(abs(b%height(:n) - a%height(:n)))
    de = maxval(abs(b%left_edge(2, :n) - (pi - a%right_edge(2, :n))))
    ! 1e-6 as for the mirror image: f3 > 0 makes F_R jump at the inflections
    ! (u = 0, L, 2L, ...), where the two runs' step sequences part
    call check(du <= 1e-6_wp .and. dv <= 1e-6_wp, trim(label)//': start at L in the mirrored state runs the ' // &
               'mirrored path u + L, pi - v')
    call check(dw <= 1e-6_wp .and. dh <= 1e-6_wp, trim(label)//': same speed and height')
    call check(de <= 1e-6_wp, trim(label)//': left edge <-> right edge')
    call check(maxval(abs(a%v(:n) - pi/2)) > 0.05_wp, trim(label)//': the bends move the water off the bottom')
    ! the run from u = 0 alone: the state in which it enters the second curve
    ! (u = L), and its own asymmetry v(u + L) vs pi - v(u) at equal u
    j = 1
    do while (j < a%n - 1 .and. a%u(j + 1) < half)
      j = j + 1
    end do
    lam = (half - a%u(j))/(a%u(j + 1) - a%u(j))
    v_mid = (1 - lam)*a%v(j) + lam*a%v(j + 1)
    beta_mid = (1 - lam)*a%beta(j) + lam*a%beta(j + 1)
    asym = 0
    j = 1
    do i = 1, a%n
      if (a%u(i) + half > a%u(a%n)) exit
      do while (j < a%n - 1 .and. a%u(j + 1) < a%u(i) + half)
        j = j + 1
      end do
      lam = (a%u(i) + half - a%u(j))/(a%u(j + 1) - a%u(j))
      asym = max(asym, abs((1 - lam)*a%v(j) + lam*a%v(j + 1) - (pi - a%v(i))))
    end do
    call check(abs(v_mid - pi/2) > 5e-3_wp .or. abs(beta_mid) > 5e-3_wp, trim(label)// &
               ': water from the bottom at u = 0 enters the second curve off the bottom or at an angle')
    call check(asym > 1e-2_wp, trim(label)//': so its own path is not mirror symmetric about u = L')
    print '(a, a, 5es9.1)', '  ', trim(label)//': start at L vs G(start at 0): u, v, w, h, edges ', du, dv, dw, dh, de
    print '(a, a, 3f9.4)', '  ', trim(label)//': from u = 0, at u = L: v - pi/2, beta (rad); own asymmetry', &
      v_mid - pi/2, beta_mid, asym
  end subroutine glide

  subroutine run(channel, correction, f1, f2, f3, s, speed, u0)
    class(channel_t), intent(in) :: channel
    integer, intent(in) :: correction
    real(wp), intent(in) :: f1, f2, f3
    type(water_series_t), intent(out) :: s
    real(wp), intent(in), optional :: speed, u0   ! m/s, start speed (default 2); start u (default 0)
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7)
    allocate (model%channel, source=channel)
    model%correction = correction
    model%f1 = f1; model%f2 = f2; model%f3 = f3
    start%mode = START_HEIGHT_SPEED; start%height = 0.02_wp; start%speed = 2; start%v0 = pi/2
    if (present(speed)) start%speed = speed
    if (present(u0)) start%u0 = u0
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
    allocate (model%channel, source=new_channel(tube))
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
    allocate (model%channel, source=new_channel(tube))
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
