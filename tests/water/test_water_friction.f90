!> The friction law of the streamline, F_R = (f1 + chi f2 + H(chi_s) chi_s f3) w^2
!> (thesis 4.7-4.9), against values computed here without the model's
!> curvature code:
!> - chi from the tangent of the geometry layer's curve frame,
!>   chi = |dx/du|/|c_u| (demo slide), or in closed form (S-bend);
!> - chi_s = d chi/ds by central differences of that chi (step 1e-4 m);
!> - H(chi_s) applied here, w = |r_u u' + r_v v'| from the state;
!> at recorded states where chi_s > 0 (the f3 term acts: curve entries) and
!> chi_s < 0 (it must not: curve exits). A 5 % change of f3 changes F_R at the
!> chi_s > 0 states by 0.05 f3 chi_s w^2 >= 1e-3 N, far above the tolerances.
!> - the friction work recorded from the integrated state W_f equals
!>   -int F_R w dt of the recorded series (trapezoid), so the force checked
!>   pointwise is the one that acts in the dynamics (to the trapezoid's
!>   resolution, about 1e-4 of the work on the demo slide; a 5 % change of the
!>   f3 term in the right-hand side alone changes the work by ~1e-2).
module test_water_friction_support
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_curve_frame, only: curve_frame_t, curve_frame_at
  use geometry_curve, only: curve_point_t
  use geometry_tube, only: tube_surface_t
  use water_channel, only: channel_t
  implicit none (type, external)
  private
  public :: frame_chi, frame_chi_s, frame_turn

contains

  !> chi = |x_u|/|c_u| with x the unit tangent of the curve frame (3.60): the
  !> derivative of the unit tangent by arc length, not |c' x c''|/|c'|^3 (4.8).
  function frame_chi(tc, u) result(chi)
    class(channel_t), intent(in) :: tc
    real(wp), intent(in) :: u
    real(wp) :: chi
    type(curve_frame_t) :: f
    type(curve_point_t) :: cp
    type(status_t) :: st
    type(tube_surface_t) :: tube
    tube = tube_of(tc)
    call curve_frame_at(tube%centerline, tube%horizon, u, 1, f, st, c=cp)
    chi = norm2(f%x(:, 1))/norm2(cp%d(:, 1))
  end function frame_chi

  !> The signed curvature, positive turning left, x_s . y = (x_u . y)/|c_u|
  !> (frame y to the left): its sign changes at an inflection.
  function frame_turn(tc, u) result(turn)
    class(channel_t), intent(in) :: tc
    real(wp), intent(in) :: u
    real(wp) :: turn
    type(curve_frame_t) :: f
    type(curve_point_t) :: cp
    type(status_t) :: st
    type(tube_surface_t) :: tube
    tube = tube_of(tc)
    call curve_frame_at(tube%centerline, tube%horizon, u, 1, f, st, c=cp)
    turn = dot_product(f%x(:, 1), f%y(:, 0))/norm2(cp%d(:, 1))
  end function frame_turn

  !> d chi/ds by central differences over [u - delta, u + delta], the arc
  !> length of that piece from the curve's own quadrature; `estimate` is
  !> |D(delta) - D(2 delta)|, about 3 times the truncation error of D(delta).
  function frame_chi_s(tc, u, delta, estimate) result(chi_s)
    class(channel_t), intent(in) :: tc
    real(wp), intent(in) :: u, delta
    real(wp), intent(out) :: estimate
    real(wp) :: chi_s, d2
    type(tube_surface_t) :: tube
    tube = tube_of(tc)
    chi_s = (frame_chi(tc, u + delta) - frame_chi(tc, u - delta)) &
            /tube%centerline%arc_length(u - delta, u + delta)
    d2 = (frame_chi(tc, u + 2*delta) - frame_chi(tc, u - 2*delta)) &
         /tube%centerline%arc_length(u - 2*delta, u + 2*delta)
    estimate = abs(chi_s - d2)
  end function frame_chi_s

  !> The tube a channel reads (these tests build only tubes).
  function tube_of(tc) result(tube)
    class(channel_t), intent(in) :: tc
    type(tube_surface_t) :: tube
    select type (slide => tc%slide)
    type is (tube_surface_t)
      tube = slide
    end select
  end function tube_of
end module test_water_friction_support

program test_water_friction
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use io_input, only: input_text_t, load_input_file
  use water_run, only: water_description_t, new_streamline
  use numerics_ode, only: ode_options_t
  use testing, only: check, finish_tests
  use geometry_tube, only: new_s_bend_tube
  use water_channel, only: new_channel
  use water_streamline, only: streamline_t, water_point_t, water_point, CORRECTION_FULL
  use water_flow, only: water_series_t, water_start_t, water_initial_state, simulate_water, &
    START_HEIGHT_SPEED, OUTCOME_END
  use scenarios_water, only: build_water
  use test_water_friction_support, only: frame_chi, frame_chi_s, frame_turn
  implicit none (type, external)

  ! central-difference step in u (~m): truncation delta^2 chi_sss/6, 2e-9 1/m^2
  ! for chi_sss ~ 1 1/m^4 (chi 0.2 1/m reached over the 2 m transitions, septic
  ! smoothstep), rounding ~1e-15 chi/delta ~ 1e-12 1/m^2; not assumed: each
  ! point's Richardson estimate |D(delta) - D(2 delta)| (3x the truncation) is
  ! checked below tol_chi_s
  real(wp), parameter :: delta = 1e-4_wp
  ! chi_s accepted up to 1e-7 1/m^2 off (50x the estimate above; the fitted
  ! centerline's ripple may raise chi_sss locally); chi itself agrees with (4.8)
  ! to rounding, 1e-12 relative
  real(wp), parameter :: tol_chi_s = 1e-7_wp, rtol_chi = 1e-12_wp
  ! a state counts as "chi_s > 0" or "< 0" only beyond this (1/m^2), so that the
  ! sign of H is unambiguous and the f3 term is >= 0.05 f3 * 0.02 w^2 when on
  real(wp), parameter :: chi_s_min = 0.02_wp
  ! the S-bend: amplitude (m), wavenumber (1/m), descent per m
  real(wp), parameter :: a = 1.5_wp, k = 0.4_wp, q = 0.1_wp

  call demo_slide()
  call s_bend()
  call finish_tests('test_water_friction')

contains

  !> Independent F_R (4.7) from chi, chi_s and the state.
  pure real(wp) function friction_law(model, chi, chi_s, w) result(f)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: chi, chi_s, w
    real(wp) :: heaviside
    heaviside = 0
    if (chi_s > 0) heaviside = 1
    f = (model%f1 + chi*model%f2 + heaviside*chi_s*model%f3)*w**2
  end function friction_law

  !> Speed from the state alone: w = |r_u u' + r_v v'|.
  real(wp) function state_speed(model, s, i) result(w)
    type(streamline_t), intent(in) :: model
    type(water_series_t), intent(in) :: s
    integer, intent(in) :: i
    type(surface_point_t) :: p
    type(status_t) :: st
    call model%channel%evaluate(s%u(i), s%v(i), 1, p, st)
    w = norm2(p%ru*s%du(i) + p%rv*s%dv(i))
  end function state_speed

  !> F_R the model uses at sample i of a run (from the state, and as recorded).
  subroutine model_friction(model, s, i, f_state, f_recorded)
    type(streamline_t), intent(in) :: model
    type(water_series_t), intent(in) :: s
    integer, intent(in) :: i
    real(wp), intent(out) :: f_state, f_recorded
    type(water_point_t) :: q
    type(status_t) :: st
    call water_point(model, [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp], q, st)
    call check(st%ok(), 'water point at a recorded state')
    f_state = q%friction
    f_recorded = s%friction_force(i)
  end subroutine model_friction

  subroutine demo_slide()
    type(input_text_t) :: input
    type(water_description_t) :: description
    type(streamline_t), target :: model
    type(water_series_t) :: s
    type(status_t) :: st
    real(wp) :: y0(7), chi, chi_s, est, w, f_ref, f_state, f_rec, err, worst, est_max, f3_share
    real(wp), allocatable :: turn(:), chi_s_all(:)
    logical, allocatable :: rough(:)
    integer :: i, n_pos, n_neg
    call load_input_file('inputs/water/demo_slide.nml', input, st)
    call check(st%ok(), 'demo input read (run from the repository root)')
    if (.not. st%ok()) return
    call build_water(input, description, st)
    if (st%ok()) call new_streamline(description, model, y0, st)
    call check(st%ok(), 'demo model built: '//st%text())
    if (.not. st%ok()) return
    description%solver%ode%rtol = 1e-12_wp; description%solver%ode%atol = 1e-12_wp
    call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, 0.0025_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_END, 'demo slide: the water reaches the end')
    associate (tc => model%channel)
      n_pos = 0; n_neg = 0; worst = 0; est_max = 0; f3_share = 0
      do i = 1, s%n, 14
        chi_s = frame_chi_s(tc, s%u(i), delta, est)
        if (abs(chi_s) < chi_s_min) cycle
        chi = frame_chi(tc, s%u(i))
        w = state_speed(model, s, i)
        f_ref = friction_law(model, chi, chi_s, w)
        call model_friction(model, s, i, f_state, f_rec)
        ! tolerance: f3 w^2 tol_chi_s from the difference quotient, f2 w^2 chi
        ! rtol_chi and w^2 (f1 + ...) rounding in the two speeds
        err = abs(f_state - f_ref)/(w**2*(model%f3*tol_chi_s + model%f2*chi*rtol_chi) + 1e-13_wp*f_ref)
        worst = max(worst, err); est_max = max(est_max, est)
        call check(err <= 1, 'demo slide: F_R (4.7) = independent value at a state with chi_s ' // &
                   merge('> 0', '< 0', chi_s > 0))
        call check(f_rec == f_state, 'demo slide: recorded friction force = model friction')
        call check(est <= tol_chi_s, 'demo slide: difference step small enough for chi_s')
        if (chi_s > 0) then
          n_pos = n_pos + 1
          f3_share = max(f3_share, model%f3*chi_s*w**2/f_ref)
        else
          n_neg = n_neg + 1
        end if
      end do
      call check(n_pos >= 5 .and. n_neg >= 5, 'demo slide: several states with chi_s > 0 and with chi_s < 0')
      print '(a, 2i5, a, es9.2, a, es9.2, a, f6.3)', '  demo slide: states chi_s > 0 / < 0:', n_pos, n_neg, &
        '; worst |F - F_ref|/tol', worst, '; largest difference estimate', est_max, &
        ' 1/m^2; largest f3 share of F_R', f3_share
    end associate
    ! intervals where the signed curvature (turn) or chi_s changes sign, chi_s
    ! from the same central differences. The fitted centerline ripples on its
    ! straights (curvature < 1e-4 1/m, docs/geometry.md), flipping both signs
    ! harmlessly; only changes that matter count: the turn by > 5e-4 1/m (a real
    ! inflection, 1/6 m^-1 reversed over 2 + 2 m, moves it >= 1.7e-3 1/m per
    ! 0.01 m sample), chi_s by > 1e-5 1/m^2 per sample (a smaller change bends
    ! F_R w by < f3 w^3 1e-5/dt, a trapezoid error < dt f3 w^3 1e-5/8 ~ 3e-7 J)
    allocate (turn(s%n), chi_s_all(s%n), rough(s%n))
    do i = 1, s%n
      turn(i) = frame_turn(model%channel, s%u(i))
      chi_s_all(i) = frame_chi_s(model%channel, s%u(i), delta, est)
    end do
    rough = .false.
    rough(:s%n - 1) = (turn(:s%n - 1)*turn(2:) <= 0 .and. abs(turn(:s%n - 1) - turn(2:)) > 5e-4_wp) .or. &
                      (chi_s_all(:s%n - 1)*chi_s_all(2:) <= 0 .and. abs(chi_s_all(:s%n - 1) - chi_s_all(2:)) > 1e-5_wp)
    call work_check(s, rough, 'demo slide')
  end subroutine demo_slide

  !> S-bend c = [u, a sin(k u), -q u] (water_channel): c' x c'' =
  !> -a k^2 sin(k u) [q, 0, 1], so chi = |a| k^2 |sin(k u)| sqrt(1 + q^2)/
  !> (1 + q^2 + a^2 k^2 cos^2(k u))^(3/2); chi_s = chi_u/|c_u| with chi_u by
  !> central differences (u is not the arc length here). Off the inflections
  !> (k u = n pi, where chi has a kink) chi is smooth.
  subroutine s_bend()
    type(streamline_t), target :: model
    type(water_start_t) :: start
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: y0(7), chi, chi_s, w, f_ref, f_state, f_rec, err, worst, speed_u
    logical, allocatable :: rough(:)
    integer :: i, n_pos, n_neg
    allocate (model%channel, source=new_channel(new_s_bend_tube(0.5_wp, a, k, q, 30.0_wp, st)))
    model%correction = CORRECTION_FULL
    start%mode = START_HEIGHT_SPEED; start%height = 0.02_wp; start%speed = 2; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    opt%rtol = 1e-12_wp; opt%atol = 1e-12_wp
    call simulate_water(model, y0, opt, 60.0_wp, 0.005_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_END, 'S-bend: runs to the end')
    n_pos = 0; n_neg = 0; worst = 0
    do i = 1, s%n, 12
      if (abs(sin(k*s%u(i))) < 1e-2_wp) cycle      ! within 0.025 m of a kink of chi
      speed_u = sqrt(1 + q**2 + (a*k*cos(k*s%u(i)))**2)
      chi_s = (chi_closed(s%u(i) + delta) - chi_closed(s%u(i) - delta))/(2*delta)/speed_u
      if (abs(chi_s) < chi_s_min) cycle
      chi = chi_closed(s%u(i))
      w = state_speed(model, s, i)
      f_ref = friction_law(model, chi, chi_s, w)
      call model_friction(model, s, i, f_state, f_rec)
      ! tolerance as on the demo slide: chi_uuu <= a k^5 (1 + ...)~ 0.05, so the
      ! truncation delta^2 chi_uuu/6 ~ 1e-10 is far inside tol_chi_s
      err = abs(f_state - f_ref)/(w**2*(model%f3*tol_chi_s + model%f2*chi*rtol_chi) + 1e-13_wp*f_ref)
      worst = max(worst, err)
      call check(err <= 1, 'S-bend: F_R (4.7) = closed-form value at a state with chi_s ' // &
                 merge('> 0', '< 0', chi_s > 0))
      call check(f_rec == f_state, 'S-bend: recorded friction force = model friction')
      if (chi_s > 0) then
        n_pos = n_pos + 1
      else
        n_neg = n_neg + 1
      end if
    end do
    call check(n_pos >= 5 .and. n_neg >= 5, 'S-bend: several states with chi_s > 0 and with chi_s < 0')
    print '(a, 2i5, a, es9.2)', '  S-bend: states chi_s > 0 / < 0:', n_pos, n_neg, '; worst |F - F_ref|/tol', worst
    ! chi_u = (positive factor) sign(sin(k u)) cos(k u) (differentiate chi_closed):
    ! sin(2 k u) changes sign at every inflection and every switch of H
    allocate (rough(s%n))
    rough = .false.
    rough(:s%n - 1) = sin(2*k*s%u(:s%n - 1))*sin(2*k*s%u(2:s%n)) <= 0
    call work_check(s, rough, 'S-bend')
  end subroutine s_bend

  elemental real(wp) function chi_closed(u) result(c)
    real(wp), intent(in) :: u
    c = abs(a)*k**2*abs(sin(k*u))*sqrt(1 + q**2)/(1 + q**2 + (a*k*cos(k*u))**2)**1.5_wp
  end function chi_closed

  !> W_f (integrated with the state, rtol 1e-12) against the trapezoid of
  !> -F_R w over the recorded samples, pair of output intervals by pair of
  !> intervals. On a smooth F_R w the trapezoid error of a pair is c dt^3 and
  !> the trapezoid over the pair as one interval differs from it by 3 c dt^3:
  !> the sum of those differences (3 times the error) plus 1e-9 |W| for the
  !> integration is the tolerance. F_R w is not smooth where H(chi_s) switches
  !> (a kink: the Richardson difference need not bound the error there) nor at
  !> an inflection (chi = |..| has a kink, chi_s jumps from < 0 to > 0 and the
  !> f3 term jumps: an O(dt) error). The caller marks those output intervals
  !> (`rough`, from the geometry alone); pairs holding one are left out and
  !> counted.
  subroutine work_check(s, rough, what)
    type(water_series_t), intent(in) :: s
    logical, intent(in) :: rough(:)   ! interval (t_i, t_i+1) holds a switch of H or an inflection
    character(len=*), intent(in) :: what
    real(wp) :: err, est, ta, tb, t2, p(3)
    integer :: i, skipped, pairs
    err = 0; est = 0; skipped = 0; pairs = 0
    do i = 2, s%n - 1, 2
      pairs = pairs + 1
      if (rough(i - 1) .or. rough(i)) then
        skipped = skipped + 1
        cycle
      end if
      p = -s%friction_force(i - 1:i + 1)*s%speed(i - 1:i + 1)
      ta = (s%time(i) - s%time(i - 1))*(p(1) + p(2))/2
      tb = (s%time(i + 1) - s%time(i))*(p(2) + p(3))/2
      t2 = (s%time(i + 1) - s%time(i - 1))*(p(1) + p(3))/2
      err = err + (s%friction_work(i + 1) - s%friction_work(i - 1)) - (ta + tb)
      est = est + abs(t2 - (ta + tb))
    end do
    call check(abs(err) <= est + 1e-9_wp*abs(s%friction_work(s%n)), &
               what//': friction work = integral of F_R w dt over the recorded series')
    call check(skipped <= pairs/10, what//': few output intervals left out')
    call check(abs(s%friction_work(s%n)) > 1, what//': friction does work')
    print '(a, a, es10.2, a, es10.2, a, f9.3, a, i0, a, i0, a)', '  ', what//': work vs trapezoid', abs(err), &
      ' J (estimate', est, ' J) of', s%friction_work(s%n), ' J; ', skipped, ' of ', pairs, &
      ' interval pairs with a kink or jump left out'
  end subroutine work_check
end program test_water_friction
