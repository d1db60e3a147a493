!> The water field (water_field): what other models read of the water.
!> - the rates it interpolates with (d/dt of the K_M axes, of K_w, of the
!>   width, and of the edges by implicit differentiation of 4.25-4.26) against
!>   central differences along the motion, at scattered samples of curved runs
!>   (S-bend, demo slide; the width of an open flume's profile);
!> - accuracy against the integrator's dense output: a field built from
!>   samples every h is queried at the samples of the same run recorded ten
!>   times as often (CVODE interpolates both from the same steps); errors and
!>   their h^4 convergence on a smooth run (S-bend, f2 = f3 = 0), and the
!>   errors at the thesis's output step on the demo slide;
!> - the width's rate of a profile is the central difference of water_point's
!>   widths, to the bit, also where the profile changes along u (the patch
!>   slide): its two points skip only the area's rate along u;
!> - C1: the reported d/du are the derivatives of the reported values, and
!>   continuous across nodes;
!> - the arc-length query agrees with the u query; outside the computed range
!>   (before, after, NaN, an empty field) a location and no values.
program test_water_field
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_curve, only: line_curve_t, constant_curve_t
  use geometry_cross_section, only: flume_section_t
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use io_input, only: input_text_t, load_input_file, input_from_text
  use water_run, only: water_description_t, new_streamline
  use numerics_ode, only: ode_options_t
  use testing, only: check, finish_tests
  use geometry_tube, only: new_s_bend_tube
  use water_channel, only: new_channel
  use water_streamline, only: streamline_t, water_point_t, water_point, water_rates_t, water_point_rates, &
    CORRECTION_FULL, CORRECTION_OFF
  use water_boundaries, only: water_edges
  use water_flow, only: water_series_t, water_start_t, water_initial_state, simulate_water, OUTCOME_END, &
    START_HEIGHT_SPEED, START_SPEED
  use water_field, only: water_field_t, water_at_t, water_edges_at_t, new_water_field, WATER_INSIDE, &
    WATER_BEFORE_START, WATER_AFTER_END, WATER_NOT_COMPUTED
  use scenarios_water, only: build_water
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  type(streamline_t), target :: sbend, smooth, demo, flume, patch
  real(wp) :: y_sbend(7), y_smooth(7), y_demo(7), y_flume(7), y_patch(7)
  real(wp) :: err_coarse(9), err_fine(9), err_demo(9), ratio(9), jump, start

  call make_sbend(sbend, y_sbend, 0.138285_wp, 0.979822_wp)
  call make_sbend(smooth, y_smooth, 0.0_wp, 0.0_wp)
  call make_input(demo, y_demo, 'inputs/water/demo_slide.nml')
  call make_flume(flume, y_flume)

  call rates_against_differences(sbend, y_sbend, 'S-bend')
  call rates_against_differences(demo, y_demo, 'demo slide')
  call rates_against_differences(flume, y_flume, 'open flume')
  call width_rate_exact(flume, y_flume, 'open flume')
  ! the water of inputs/parts/patch.nml (a ride input) as a water run
  call make_input(patch, y_patch, 'patch water', &
    "&run scenario = 'water' /"//nl// &
    "&surface kind = 'slide', geometry_file = 'inputs/parts/patch_slide.nml' /"//nl// &
    "&water flow_rate = 0.004, start = 'edges', v_left0 = 1.9, v_right0 = 1.2415926535897932, "// &
    "f1 = 0.0274748, f2 = 0.138285, f3 = 0.979822, correction = 'full' /"//nl)
  call check(patch%channel%section_varies(), 'the patch slide''s profile changes along u')
  call width_rate_exact(patch, y_patch, 'patch slide')

  ! accuracy against dense output
  call accuracy(smooth, y_smooth, 0.02_wp, 'smooth S-bend, h = 0.02 s', err_coarse, jump, start)
  call accuracy(smooth, y_smooth, 0.01_wp, 'smooth S-bend, h = 0.01 s', err_fine, jump, start)
  ! O(h^4): halving h divides the error by ~16; a wrong slope would leave O(h)
  ! or O(h^2) (ratio 2 or 4). Checked for every quantity whose error is well
  ! above the dense output's own (~1e-10 relative)
  ratio = err_coarse/err_fine
  print '(a, 9f6.1)', '  error ratios h = 0.02 s / 0.01 s: ', ratio
  call check(all(ratio > 10 .and. ratio < 25), 'every quantity converges as h^4')
  call accuracy(demo, y_demo, 0.005_wp, 'demo slide, h = 0.005 s (the thesis''s output step)', err_demo, jump, &
                start)
  ! at the thesis's output step (~2 cm between nodes), away from the friction
  ! switches and the start: 1e-8 rad in v, 1e-7 rad in the edges (0.05 um on
  ! the 0.5 m tube), 1e-6 m/s (the small friction kinks of the fit's ripple
  ! on the straights), 1e-8 m of height, 1e-7 m of width, 1e-8 s, 1e-8 m:
  ! far below what the rider or a fit resolves (measured: printed, and in
  ! docs/water.md)
  call check(all(err_demo <= [1e-8_wp, 1e-6_wp, 1e-8_wp, 1e-7_wp, 1e-8_wp, 1e-8_wp, 1e-6_wp, 1e-7_wp, 1e-8_wp]), &
             'demo slide: the field within its stated accuracy away from the friction switches and the start')
  ! at a switch: the jump of dw/dt is f3 chi_s w^2/(1 - 1/Fr^2), up to several
  ! m/s^2 at the demo slide's sharpest inflection, times h/8 ~ 6e-4 s
  call check(jump <= 5e-3_wp, 'demo slide: speed within 5e-3 m/s in the intervals with a friction switch')
  ! the start: dw/dt ~ 10 m/s^2 changing within ~0.01 s; h^4 w''''/384 ~ 1e-5
  call check(start <= 5e-5_wp, 'demo slide: speed within 5e-5 m/s in the first 0.05 s')

  call smoothness_and_ranges(sbend, y_sbend)
  call finish_tests('test_water_field')

contains

  subroutine make_sbend(model, y0, f2, f3)
    type(streamline_t), intent(out) :: model
    real(wp), intent(out) :: y0(7)
    real(wp), intent(in) :: f2, f3
    type(water_start_t) :: start
    type(status_t) :: st
    allocate (model%channel, source=new_channel(new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp, st)))
    model%correction = CORRECTION_FULL
    model%f2 = f2; model%f3 = f3
    start%mode = START_HEIGHT_SPEED; start%height = 0.02_wp; start%speed = 2; start%v0 = pi/2
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'S-bend start: '//st%text())
  end subroutine make_sbend

  !> The water of the input file `file`, or of `text` (named `file`).
  subroutine make_input(model, y0, file, text)
    type(streamline_t), intent(out) :: model
    real(wp), intent(out) :: y0(7)
    character(len=*), intent(in) :: file
    character(len=*), intent(in), optional :: text
    type(input_text_t) :: input
    type(water_description_t) :: description
    type(status_t) :: st
    if (present(text)) then
      call input_from_text(file, text, input, st)
    else
      call load_input_file(file, input, st)
    end if
    if (st%ok()) call build_water(input, description, st)
    if (st%ok()) call new_streamline(description, model, y0, st)
    call check(st%ok(), file//': water built: '//st%text())
    if (.not. st%ok()) call finish_tests('test_water_field')
  end subroutine make_input

  subroutine make_flume(model, y0)
    type(streamline_t), intent(out) :: model
    real(wp), intent(out) :: y0(7)
    type(tube_surface_t) :: tube
    type(water_start_t) :: start
    type(status_t) :: st
    real(wp) :: th
    th = 8*pi/180
    tube = new_tube_surface(line_curve_t(direction=[cos(th), 0.0_wp, -sin(th)], u_min=0.0_wp, u_max=20.0_wp), &
                            constant_curve_t(), flume_section_t(), st)
    allocate (model%channel, source=new_channel(tube))
    model%correction = CORRECTION_OFF
    model%flow_rate = 0.004_wp
    start%mode = START_SPEED; start%speed = 1.5_wp; start%v0 = pi/2; start%beta = 0.2_wp
    call water_initial_state(model, start, y0, st)
    call check(st%ok(), 'flume start: '//st%text())
  end subroutine make_flume

  !> At every 25th sample: each rate against (X(y + d y') - X(y - d y'))/(2 d).
  !> d = 2e-5 s moves the point ~0.1 mm: truncation d^2 X'''/6 ~ 1e-8 for
  !> X''' up to 1e2 1/s^3 (the demo slide's tight curves); the edges are
  !> solved to ~1e-13 (Newton's last step is quadratic in a step <= 1e-10 |x|),
  !> giving ~3e-9. Tolerance 1e-6 relative to the size of each rate vector (plus
  !> 1e-7 absolute): the terms of the rates are 1e-3 .. 1 of them.
  subroutine rates_against_differences(model, y0, label)
    type(streamline_t), intent(inout), target :: model
    real(wp), intent(in) :: y0(7)
    character(len=*), intent(in) :: label
    real(wp), parameter :: d = 2e-5_wp
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    type(water_point_t) :: q, qp, qm
    type(water_rates_t) :: rates
    real(wp) :: y(7), ydot(7), lp(2), rp(2), lm(2), rm(2), l(2), r(2), pt(3), pt2(3), l_rate(2), r_rate(2), &
                err(5), x_w_p(3), x_w_m(3), y_w_p(3), y_w_m(3)
    integer :: i, checked
    opt%rtol = 1e-10_wp; opt%atol = 1e-10_wp
    call simulate_water(model, y0, opt, 100.0_wp, 0.02_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_END, label//': run to the end '//st%text())
    err = 0; checked = 0
    do i = 3, s%n - 3, 25
      y = [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp]
      call water_point(model, y, q, st)
      if (st%ok()) call water_point_rates(model, y, q, rates, st)
      if (st%ok()) call water_edges(model%channel, q, l, r, pt, pt2, st, rates=rates, left_rate=l_rate, &
                                    right_rate=r_rate)
      call check(st%ok(), label//': water point, rates and edges at a sample '//st%text())
      if (.not. st%ok()) return
      ydot = [y(3), y(4), q%udd, q%vdd, q%height_rate, 0.0_wp, 0.0_wp]
      call water_point(model, y + d*ydot, qp, st)
      if (st%ok()) call water_edges(model%channel, qp, lp, rp, pt, pt2, st)
      if (st%ok()) call water_point(model, y - d*ydot, qm, st)
      if (st%ok()) call water_edges(model%channel, qm, lm, rm, pt, pt2, st)
      call check(st%ok(), label//': neighbours along the motion '//st%text())
      if (.not. st%ok()) return
      x_w_p = qp%x_w; x_w_m = qm%x_w; y_w_p = qp%y_w; y_w_m = qm%y_w
      err(1) = max(err(1), rel(rates%x_m, (qp%x_m - qm%x_m)/(2*d)), rel(rates%z_m, (qp%z_m - qm%z_m)/(2*d)))
      err(2) = max(err(2), rel(rates%x_w, (x_w_p - x_w_m)/(2*d)), rel(rates%y_w, (y_w_p - y_w_m)/(2*d)))
      err(3) = max(err(3), rel([rates%width], [(qp%width - qm%width)/(2*d)]))
      err(4) = max(err(4), rel(l_rate, (lp - lm)/(2*d)), rel(r_rate, (rp - rm)/(2*d)))
      err(5) = max(err(5), rel([q%speed_rate], [(qp%speed - qm%speed)/(2*d)]))
      checked = checked + 1
    end do
    call check(checked >= 5, label//': enough samples checked')
    call check(err(1) <= 1, label//': d/dt of x_M, z_M against differences')
    call check(err(2) <= 1, label//': d/dt of x_w, y_w against differences')
    call check(err(3) <= 1, label//': d/dt of the width against differences')
    call check(err(4) <= 1, label//': d/dt of the edges (implicit differentiation) against differences')
    call check(err(5) <= 1, label//': d/dt of the speed (4.20) against differences of (4.23)')
    print '(a, i0, a, 5es9.1)', '  '//label//': ', checked, ' samples, rate errors / tolerance (K_M, K_w, '// &
      'width, edges, speed): ', err
  end subroutine rates_against_differences

  !> At every 10th sample of a run (a profile, not a circle): the width's
  !> rate that water_point_rates gives is (b(y + d y') - b(y - d y'))/(2 d)
  !> of water_point's own widths, d = 1e-5/w (its step), to the bit.
  subroutine width_rate_exact(model, y0, label)
    type(streamline_t), intent(inout), target :: model
    real(wp), intent(in) :: y0(7)
    character(len=*), intent(in) :: label
    type(water_series_t) :: s
    type(ode_options_t) :: opt
    type(status_t) :: st
    type(water_point_t) :: q, qp, qm
    type(water_rates_t) :: rates
    real(wp) :: y(7), ydot(7), d
    integer :: i, checked, differ
    opt%rtol = 1e-8_wp; opt%atol = 1e-8_wp
    call simulate_water(model, y0, opt, 100.0_wp, 0.02_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_END, label//': run to the end '//st%text())
    checked = 0; differ = 0
    do i = 2, s%n - 1, 10
      y = [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp]
      call water_point(model, y, q, st)
      if (st%ok()) call water_point_rates(model, y, q, rates, st)
      ydot = [y(3), y(4), q%udd, q%vdd, q%height_rate, 0.0_wp, 0.0_wp]
      d = 1e-5_wp/q%speed
      if (st%ok()) call water_point(model, y + d*ydot, qp, st)
      if (st%ok()) call water_point(model, y - d*ydot, qm, st)
      call check(st%ok() .and. q%radius == 0, label//': a profile''s point, rates and neighbours '//st%text())
      if (.not. st%ok()) return
      if (rates%width /= (qp%width - qm%width)/(2*d)) differ = differ + 1
      checked = checked + 1
    end do
    print '(a, i0, a, i0, a)', '  '//label//': width rate at ', checked, ' samples, ', differ, ' not to the bit'
    call check(checked >= 20 .and. differ == 0, label//': the width''s rate is the difference of '// &
               'water_point''s widths, to the bit')
  end subroutine width_rate_exact

  !> max over components of |a - b| / (atol + rtol |b|) (<= 1 passes), tolerances
  !> of rates_against_differences
  pure real(wp) function rel(a, b)
    real(wp), intent(in) :: a(:), b(:)
    real(wp), parameter :: rtol = 1e-6_wp, atol = 1e-7_wp
    rel = maxval(abs(a - b))/(atol + rtol*norm2(b))
  end function rel

  !> The field from samples every h against the same run's dense output at
  !> h/10 (edges solved at every sample of both; the same first step, so the
  !> same internal steps). err = largest differences of [v (rad), speed (m/s),
  !> height (m), edges (rad), time (s), position (m), velocity (m/s), width (m),
  !> K_M and beta (1, rad)].
  !> Where f3 > 0 the friction jumps where chi_s switches from <= 0 to > 0 at
  !> the centerline's inflections (4.7: chi = |c' x c''|/|c'|^3 has a kink
  !> there): the speed has a kink that no interpolant through samples on
  !> either side follows (error ~ h * jump/8). Those node intervals are left out
  !> of err and their largest speed error is returned in err_jump; likewise
  !> the first 0.05 s, where the water accelerates fast from its start speed
  !> (Q/A of the start section), in err_start.
  subroutine accuracy(model, y0, h, label, err, err_jump, err_start)
    type(streamline_t), intent(inout), target :: model
    real(wp), intent(in) :: y0(7), h
    character(len=*), intent(in) :: label
    real(wp), intent(out) :: err(9), err_jump, err_start
    type(water_series_t) :: coarse, dense
    type(water_field_t) :: field
    type(water_at_t) :: w
    type(water_edges_at_t) :: e
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: chi, chi_s
    logical, allocatable :: switch(:)
    integer :: i, k, counted, edge_counted
    opt%rtol = 1e-10_wp; opt%atol = 1e-10_wp
    opt%initial_step = 1e-4_wp   ! else CVODE's first step depends on the first output time
    call simulate_water(model, y0, opt, 100.0_wp, h, coarse, st, edges=.true.)
    call check(st%ok() .and. coarse%outcome == OUTCOME_END, label//': coarse run '//st%text())
    call simulate_water(model, y0, opt, 100.0_wp, h/10, dense, st, edges=.true.)
    call check(st%ok() .and. dense%outcome == OUTCOME_END, label//': dense run '//st%text())
    call check(abs(dense%v(101) - coarse%v(11)) <= 1e-13_wp .and. abs(dense%u(101) - coarse%u(11)) <= 1e-13_wp, &
               label//': both runs take the same steps (every 10th dense sample is a coarse one)')
    field = new_water_field(coarse, st)
    call check(st%ok(), label//': field built '//st%text())
    ! coarse intervals where the f3 term switches on
    allocate (switch(coarse%n))
    switch = .false.
    do k = 1, coarse%n
      call model%channel%curvature(coarse%u(k), chi, chi_s, st)
      switch(k) = chi_s > 0
    end do
    switch(2:) = model%f3 > 0 .and. switch(2:) .and. .not. switch(:coarse%n - 1)
    err = 0; err_jump = 0; err_start = 0; counted = 0; edge_counted = 0
    k = 1
    do i = 1, dense%n
      call field%at_u(dense%u(i), w)
      if (w%location /= WATER_INSIDE) cycle
      do while (k < coarse%n - 1 .and. coarse%u(k + 1) < dense%u(i))
        k = k + 1
      end do
      if (switch(k + 1)) then
        err_jump = max(err_jump, abs(w%speed - dense%speed(i)))
        cycle
      end if
      if (dense%time(i) < 0.05_wp) then
        err_start = max(err_start, abs(w%speed - dense%speed(i)))
        cycle
      end if
      counted = counted + 1
      err(1) = max(err(1), abs(w%v - dense%v(i)))
      err(2) = max(err(2), abs(w%speed - dense%speed(i)))
      err(3) = max(err(3), abs(w%height - dense%height(i)))
      err(5) = max(err(5), abs(w%time - dense%time(i)))
      err(6) = max(err(6), norm2(w%position - dense%position(:, i)))
      err(7) = max(err(7), norm2(w%velocity - dense%velocity(:, i)))
      err(8) = max(err(8), abs(w%width - dense%width(i)))
      err(9) = max(err(9), norm2(w%x_m - dense%x_m(:, i)), norm2(w%z_m - dense%z_m(:, i)), &
                   abs(w%beta - dense%beta(i)))
      ! the edge solved at a dense sample is a point (u_e, v_e) of the edge
      ! curve: the field's edge at u_e must give v_e
      if (dense%edge_solved(i) == 1) then
        call field%edges_at_u(dense%left_edge(1, i), e)
        if (e%left_location == WATER_INSIDE) then
          err(4) = max(err(4), abs(e%v_left - dense%left_edge(2, i)))
          edge_counted = edge_counted + 1
        end if
        call field%edges_at_u(dense%right_edge(1, i), e)
        if (e%right_location == WATER_INSIDE) err(4) = max(err(4), abs(e%v_right - dense%right_edge(2, i)))
      end if
    end do
    call check(counted > 5*coarse%n, label//': the dense samples lie inside the field')
    call check(edge_counted > 5*coarse%n, label//': the dense edges lie inside the field''s edges')
    print '(a, i0, a)', '  '//label//': ', count(switch), ' intervals with a friction switch left out'
    print '(a, 4es9.1, a, 5es9.1)', '    field vs dense output: v, w, h, edges ', err(1:4), &
      '; t, r, velocity, b, K_M ', err(5:9)
    print '(a, es9.1, a, es9.1)', '    speed in the intervals with a friction switch ', err_jump, &
      ', in the first 0.05 s ', err_start
  end subroutine accuracy

  !> C1 and consistent derivatives; arc length vs u queries; locations.
  subroutine smoothness_and_ranges(model, y0)
    type(streamline_t), intent(inout), target :: model
    real(wp), intent(in) :: y0(7)
    type(water_series_t) :: s
    type(water_field_t) :: field, empty
    type(water_at_t) :: w, wp_, wm, ws
    type(water_edges_at_t) :: ep, em
    type(ode_options_t) :: opt
    type(status_t) :: st
    real(wp) :: u_first, u_last, s_first, s_last, du, deriv_err, jump, arc_err, nan, u_exact
    real(wp) :: u_query(3), position(3), velocity(3), height, z_m(3)
    integer :: i, k, location
    logical :: flow_same
    opt%rtol = 1e-10_wp; opt%atol = 1e-10_wp
    call simulate_water(model, y0, opt, 100.0_wp, 0.05_wp, s, st, edges=.true.)
    field = new_water_field(s, st)
    call check(st%ok(), 'field built '//st%text())
    call field%u_range(u_first, u_last)
    call field%arc_length_range(s_first, s_last)
    call check(u_first == s%u(1) .and. u_last == s%u(s%n), 'u range = the run''s')
    call check(abs(field%flow_rate() - s%flow_rate) <= 0, 'flow rate kept')
    ! d/du reported = derivative of the reported values (central differences
    ! inside an interval; step 1e-5 of u: truncation ~1e-10 * v''' , rounding 1e-11)
    deriv_err = 0; jump = 0; arc_err = 0
    du = 1e-5_wp
    do i = 2, field%node_count() - 2, 7
      associate (um => 0.5_wp*(s%u(i) + s%u(i + 1)))
        call field%at_u(um, w)
        call field%at_u(um + du, wp_)
        call field%at_u(um - du, wm)
        deriv_err = max(deriv_err, abs(w%dv_du - (wp_%v - wm%v)/(2*du)), &
                        abs(w%edges%dv_left_du - (wp_%edges%v_left - wm%edges%v_left)/(2*du)), &
                        abs(w%edges%dv_right_du - (wp_%edges%v_right - wm%edges%v_right)/(2*du)))
        ! arc length by the u query, u by the arc-length query: against the
        ! channel's own s(u) and its inverse
        call model%channel%parameter_at_length(w%arc_length, u_exact, st)
        call field%at_arc_length(w%arc_length, ws)
        arc_err = max(arc_err, abs(w%arc_length - model%channel%arc_length(um)), abs(ws%u - u_exact))
      end associate
      ! C1 at node i+1: slopes from both sides agree
      call field%at_u(s%u(i + 1)*(1 - 1e-14_wp) , wm)
      call field%at_u(s%u(i + 1)*(1 + 1e-14_wp), wp_)
      jump = max(jump, abs(wp_%dv_du - wm%dv_du))
      call field%edges_at_u(s%left_edge(1, i + 1)*(1 - 1e-14_wp), em)
      call field%edges_at_u(s%left_edge(1, i + 1)*(1 + 1e-14_wp), ep)
      jump = max(jump, abs(ep%dv_left_du - em%dv_left_du))
    end do
    call check(deriv_err <= 1e-8_wp, 'd/du of v and the edges = derivatives of the values')
    ! a jump would be O(h^3 v'''') ~ 1e-6; rounding at a node ~1e-12
    call check(jump <= 1e-9_wp, 'dv/du of the streamline and the left edge continuous across nodes (C1)')
    ! Hermite s(u) and u(s): h^4 s''''/384 with nodes up to h = 0.175 m apart
    ! and s'''' = |c_u|''' ~ a^2 k^5 = 0.023 1/m^3 on this S-bend: ~6e-8 each
    call check(arc_err <= 2e-7_wp, 'arc length from the u query, u from the arc-length query')
    print '(a, 3es9.1)', '  d/du vs differences, slope jump at nodes, arc-length vs u query: ', deriv_err, jump, &
      arc_err
    call field%at_u(u_first, w)
    call check(w%location == WATER_INSIDE .and. abs(w%v - s%v(1)) <= 1e-15_wp, 'first node inside, exact')
    call field%at_u(u_last, w)
    call check(w%location == WATER_INSIDE .and. abs(w%speed - s%speed(s%n)) <= 1e-15_wp, 'last node inside, exact')
    call field%at_u(u_first - 1e-9_wp, w)
    call check(w%location == WATER_BEFORE_START .and. w%speed == 0, 'before the start: location, no values')
    call field%at_u(u_last + 1e-9_wp, w)
    call check(w%location == WATER_AFTER_END .and. w%speed == 0, 'after the end: location, no values')
    call field%at_arc_length(s_last + 1e-9_wp, w)
    call check(w%location == WATER_AFTER_END, 'after the end by arc length')
    call field%at_arc_length(-1.0_wp, w)
    call check(w%location == WATER_BEFORE_START, 'before the start by arc length')
    nan = ieee_nan()
    call field%at_u(nan, w)
    call check(w%location == WATER_NOT_COMPUTED, 'a NaN query: not computed')
    call empty%at_u(1.0_wp, w)
    call check(w%location == WATER_NOT_COMPUTED, 'an empty field: not computed')
    call empty%edges_at_u(1.0_wp, ep)
    call check(ep%left_location == WATER_NOT_COMPUTED .and. ep%right_location == WATER_NOT_COMPUTED, &
               'an empty field: no edges')
    ! the drag's query: the same numbers as at_u, the same locations
    flow_same = .true.
    do i = 1, field%node_count() - 1, 3
      do k = 0, 2   ! the node itself, just above it, and the middle of its interval
        u_query = [s%u(i), s%u(i)*(1 + 1e-14_wp), 0.5_wp*(s%u(i) + s%u(i + 1))]
        call field%at_u(u_query(k + 1), w)
        call field%flow_at_u(u_query(k + 1), location, position, velocity, height, z_m)
        flow_same = flow_same .and. location == w%location .and. all(position == w%position) .and. &
                    all(velocity == w%velocity) .and. height == w%height .and. all(z_m == w%z_m)
      end do
    end do
    call check(flow_same, 'flow_at_u: the same position, velocity, height and z_M as at_u (to the bit)')
    call field%flow_at_u(u_first - 1e-9_wp, location, position, velocity, height, z_m)
    flow_same = location == WATER_BEFORE_START .and. height == 0
    call field%flow_at_u(u_last + 1e-9_wp, location, position, velocity, height, z_m)
    flow_same = flow_same .and. location == WATER_AFTER_END .and. height == 0
    call field%flow_at_u(nan, location, position, velocity, height, z_m)
    flow_same = flow_same .and. location == WATER_NOT_COMPUTED
    call empty%flow_at_u(1.0_wp, location, position, velocity, height, z_m)
    flow_same = flow_same .and. location == WATER_NOT_COMPUTED
    call check(flow_same, 'flow_at_u: before the start, after the end, NaN, empty field: locations, no values')
    ! a run without edges gives a field without edges
    call simulate_water(model, y0, opt, 100.0_wp, 0.05_wp, s, st, edges=.false.)
    field = new_water_field(s, st)
    call field%at_u(0.5_wp*(u_first + u_last), w)
    call check(w%location == WATER_INSIDE .and. w%edges%left_location == WATER_NOT_COMPUTED, &
               'edges not solved: the streamline is there, the edges are not computed')
  end subroutine smoothness_and_ranges

  real(wp) function ieee_nan()
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    ieee_nan = ieee_value(1.0_wp, ieee_quiet_nan)
  end function ieee_nan
end program test_water_field
