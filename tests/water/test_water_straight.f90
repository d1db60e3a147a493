!> The water in a straight circular tube at incline theta (thesis 4.2):
!> - correction off: the water stays at the bottom (v = pi/2) and its speed
!>   follows dw/dt = g sin(theta) - (f1/m) w^2, i.e.
!>   w(t) = w_inf tanh(g sin(theta) t/w_inf + atanh(w0/w_inf)), w_inf = sqrt(m g sin(theta)/f1);
!> - correction on: A w = Q along the way, and with beta = 0, R = r, dR/dt = 0 and
!>   N = m g cos(theta), (4.20) becomes the gradually-varied-flow balance
!>   dw/dt (1 - 1/Fr^2) = g sin(theta) - (f1/m) w^2,  Fr^2 = w^2 b/(g cos(theta) A),
!>   with A = Q/w and b = b(h(A)); integrated here independently as a scalar ODE;
!> - dR/dt (F.5) against central differences of R along a path started obliquely.
module test_water_straight_gvf
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use numerics_ode, only: ode_system_t
  use water_section, only: circle_segment, circle_height_for_area
  use water_streamline, only: default_f1
  implicit none (type, external)
  private
  public :: gvf_t, theta, r, g
  real(wp), parameter :: theta = 10*pi/180, r = 0.5_wp, g = standard_gravity

  !> The gradually-varied-flow balance as a scalar ODE for w.
  type, extends(ode_system_t) :: gvf_t
    real(wp) :: q = 0
  contains
    procedure :: rhs => gvf_rhs
  end type gvf_t

contains

  subroutine gvf_rhs(self, t, y, ydot, status)
    class(gvf_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    real(wp) :: h, a, b, alpha, fr2
    associate (unused => t)
    end associate
    call circle_height_for_area(self%q/y(1), r, h, status)
    call circle_segment(h, r, a, b, alpha)
    fr2 = y(1)**2*b/(g*cos(theta)*a)
    ydot(1) = (g*sin(theta) - default_f1*y(1)**2)/(1 - 1/fr2)
  end subroutine gvf_rhs
end module test_water_straight_gvf

program test_water_straight
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use numerics_ode, only: ode_options_t, ode_integrator_t
  use test_water_straight_gvf, only: gvf_t, theta, r, g
  use testing, only: check, check_close, finish_tests
  use geometry_tube, only: new_straight_tube
  use water_channel, only: new_channel
  use water_streamline, only: streamline_t, water_point_t, water_point, CORRECTION_OFF, &
    CORRECTION_FULL, default_f1
  use water_flow, only: water_start_t, water_series_t, water_initial_state, simulate_water, &
    START_HEIGHT_SPEED, START_SPEED, START_EDGES, OUTCOME_DURATION, OUTCOME_END
  implicit none (type, external)


  call tanh_law()
  call edges_start()
  call continuity_and_gvf()
  call radius_rate()
  call end_of_slide()
  call finish_tests('test_water_straight')

contains

  subroutine make(model, correction)
    type(streamline_t), intent(out) :: model
    integer, intent(in) :: correction
    type(status_t) :: st
    allocate (model%channel, source=new_channel(new_straight_tube(r, theta, 300.0_wp, st)))
    model%correction = correction
  end subroutine make

  subroutine tanh_law()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7), w_inf, w0, ref, err, verr
    integer :: i

    call make(model, CORRECTION_OFF)
    start%mode = START_HEIGHT_SPEED; start%height = 0.01_wp; start%speed = 1; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'tanh: start')
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    model%stations = [5.0_wp, 20.0_wp, 60.0_wp]   ! u = arc length on the straight tube
    call simulate_water(model, y0, opt, 20.0_wp, 0.1_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_DURATION, 'tanh: ran 20 s')
    w_inf = sqrt(model%mass*g*sin(theta)/default_f1)
    w0 = 1
    err = 0; verr = 0
    do i = 1, s%n
      ref = w_inf*tanh(g*sin(theta)*s%time(i)/w_inf + atanh(w0/w_inf))
      err = max(err, abs(s%speed(i) - ref)/ref)
      verr = max(verr, abs(s%v(i) - pi/2))
    end do
    ! 1e-8: the issue's bound; integrator rtol 1e-12 over ~1e3 steps stays far below it
    call check(err <= 1e-8_wp, 'tanh law of the speed to 1e-8 relative')
    ! no lateral force on the bottom line: v moves only by integration error (atol 1e-12 per step)
    call check(verr <= 1e-9_wp, 'the water stays at the bottom v = pi/2')
    call check_close(s%speed(s%n), w_inf, 1e-3_wp, 0.0_wp, 'speed approaches sqrt(m g sin/f1) after 20 s')
    ! stations by root finding: the distance x(t) = (w_inf^2/a) ln(cosh(a t/w_inf + c)/cosh(c)),
    ! a = g sin(theta), c = atanh(w0/w_inf), reaches s_i at t_i
    do i = 1, size(s%stations)
      call check(s%stations(i)%reached, 'station reached')
      ref = w_inf**2/(g*sin(theta))*log(cosh(g*sin(theta)*s%stations(i)%time/w_inf + atanh(w0/w_inf)) &
            /cosh(atanh(w0/w_inf)))
      ! 1e-8 m: root located to CVODE's root tolerance, path integrated at rtol 1e-12
      call check_close(ref, model%stations(i), 1e-9_wp, 1e-8_wp, 'station time matches the closed-form distance')
      call check_close(s%stations(i)%arc_length, model%stations(i), 1e-12_wp, 1e-12_wp, 'station arc length')
    end do
    print '(a, es10.2, a, es10.2, a, f8.4, a, f8.4)', '  tanh law: max rel error ', err, ' v err', verr, ', w(20 s) ', &
      s%speed(s%n), ', w_inf ', w_inf
  end subroutine tanh_law

  !> Start from the edges of the first section (4.33): v0 = (v1 + v2)/2 and
  !> w0 = Q/(0.5 r^2 ((v2 - v1) - sin(v2 - v1))).
  subroutine edges_start()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(status_t) :: st
    type(water_point_t) :: q
    real(wp) :: y0(7), d
    call make(model, CORRECTION_FULL)
    model%flow_rate = 0.004_wp
    start%mode = START_EDGES; start%v_left = 1.9_wp; start%v_right = 1.1_wp
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'edges start')
    call water_point(model, y0, q, st)
    d = start%v_left - start%v_right
    call check_close(y0(2), 1.5_wp, 1e-15_wp, 0.0_wp, 'start in the middle of the edges (4.33)')
    call check_close(q%speed, model%flow_rate/(0.5_wp*r**2*(d - sin(d))), 1e-12_wp, 0.0_wp, 'w0 = Q/A (4.33)')
    call check_close(q%width, 2*r*sin(d/2), 1e-12_wp, 0.0_wp, 'start width = chord between the edges')
  end subroutine edges_start

  subroutine continuity_and_gvf()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    type(gvf_t), target :: gvf
    type(ode_integrator_t) :: ref
    real(wp) :: y0(7), cerr, werr, t, yr(1), fr2
    integer :: i

    call make(model, CORRECTION_FULL)
    model%flow_rate = 0.004_wp
    start%mode = START_SPEED; start%speed = 1; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'gvf: start')
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 10.0_wp, 0.1_wp, s, st, edges=.false.)
    call check(st%ok(), 'gvf: ran')
    cerr = maxval(abs(s%area(:s%n)*s%speed(:s%n) - model%flow_rate))/model%flow_rate
    ! 1e-8: h is integrated with rtol 1e-12; A w = Q is its invariant
    call check(cerr <= 1e-8_wp, 'continuity A w = Q to 1e-8 relative')
    fr2 = s%speed(1)**2*s%width(1)/(g*cos(theta)*s%area(1))
    call check(fr2 > 4, 'the test flow is supercritical')

    gvf%q = model%flow_rate
    call ref%start(gvf, 0.0_wp, [1.0_wp], opt, st)
    werr = 0
    do i = 2, s%n
      call ref%advance(s%time(i), t, yr, st)
      werr = max(werr, abs(s%speed(i) - yr(1))/yr(1))
    end do
    ! 1e-8: both integrations at rtol 1e-12
    call check(werr <= 1e-8_wp, 'speed obeys dw/dt (1 - 1/Fr^2) = g sin - f1 w^2/m to 1e-8')
    print '(a, 2es10.2, a, f7.3)', '  continuity, gvf errors ', cerr, werr, '  Fr(0) = ', sqrt(fr2)
  end subroutine continuity_and_gvf


  !> Started at beta = 0.2 rad the water crosses the tube; dR/dt of the model
  !> against central differences of the recorded R (dt = 1e-4 s).
  subroutine radius_rate()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    type(water_point_t) :: q, qp, qm
    real(wp) :: y0(7), y(7), yp(7), ym(7), dt, fd, worst
    integer :: k, i

    call make(model, CORRECTION_FULL)
    model%flow_rate = 0.004_wp
    start%mode = START_SPEED; start%speed = 2; start%v0 = pi/2; start%beta = 0.2_wp
    call water_initial_state(model, start, y0, st)
    opt%rtol = 1e-12_wp; opt%atol = 1e-13_wp
    dt = 1e-4_wp
    call simulate_water(model, y0, opt, 1.5_wp + 2*dt, dt, s, st, edges=.false.)
    worst = 0
    do k = 1, 5
      i = nint(0.3_wp*k/dt) + 1   ! the sample at t = 0.3 k s
      y = [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp]
      ym = [s%u(i - 1), s%v(i - 1), s%du(i - 1), s%dv(i - 1), s%height(i - 1), 0.0_wp, 0.0_wp]
      yp = [s%u(i + 1), s%v(i + 1), s%du(i + 1), s%dv(i + 1), s%height(i + 1), 0.0_wp, 0.0_wp]
      call water_point(model, y, q, st)
      call water_point(model, yp, qp, st)
      call water_point(model, ym, qm, st)
      fd = (qp%radius - qm%radius)/(2*dt)
      ! central difference error ~ dt^2 R'''/6 ~ 1e-8 relative to the scale of R'
      worst = max(worst, abs(q%radius_rate - fd)/max(abs(fd), 1e-3_wp))
    end do
    call check(st%ok(), 'radius rate: path computed')
    call check(worst <= 1e-5_wp, 'dR/dt (F.5) matches differences of R along the path')
    print '(a, es10.2)', '  dR/dt vs differences: ', worst
  end subroutine radius_rate

  !> A 30 m tube: the run stops at its end by root finding, exactly at u = 30.
  subroutine end_of_slide()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7)
    call make(model, CORRECTION_OFF)
    model%u_end = 30
    start%mode = START_HEIGHT_SPEED; start%height = 0.01_wp; start%speed = 1
    call water_initial_state(model, start, y0, st)
    opt%rtol = 1e-10_wp; opt%atol = 1e-10_wp
    call simulate_water(model, y0, opt, 100.0_wp, 0.05_wp, s, st)
    call check(st%ok() .and. s%outcome == OUTCOME_END, 'run ends at the end of the slide')
    call check_close(s%u(s%n), 30.0_wp, 1e-9_wp, 0.0_wp, 'last sample at u_end')
    ! edges of a flat-bottom symmetric flow lie symmetric about v = pi/2
    call check_close(s%left_edge(2, s%n) + s%right_edge(2, s%n), pi, 1e-9_wp, 0.0_wp, 'edges symmetric')
    call check_close(r*(s%left_edge(2, s%n) - s%right_edge(2, s%n))/2, &
                     r*asin(s%width(s%n)/(2*r)), 1e-6_wp, 0.0_wp, 'edges at the chord ends (beta = 0)')
  end subroutine end_of_slide
end program test_water_straight
