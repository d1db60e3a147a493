!> The water edges (4.25-4.26) on the demo slide with the edges solved at every
!> output (every 0.005 s, as the thesis and the bench):
!> - the warm-started Newton edges equal HYBRJ's from the tangent-plane guess
!>   (the solver before the warm start) at every sample, within the solve
!>   tolerance;
!> - the analytic Jacobian of the edge system against central differences at
!>   scattered samples;
!> - a useless guess (far beyond the slide) falls back to HYBRJ and gives the
!>   same edges;
!> - the samples flagged "beyond the end" are those where the leading edge,
!>   kept at its offset in u from the streamline, would lie past u_max: the
!>   foot really is off the surface there, not a solver start problem.
program test_water_edges
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_DOMAIN
  use io_input, only: input_text_t, load_input_file
  use water_run, only: water_description_t, new_streamline
  use numerics_nonlinear, only: nonlinear_options_t, nonlinear_result_t, solve_nonlinear, check_jacobian
  use testing, only: check, finish_tests
  use water_streamline, only: streamline_t, water_point_t, water_point
  use water_flow, only: water_series_t, simulate_water, OUTCOME_END
  use water_boundaries, only: water_edges, edge_options
  use geometry_foot_point, only: foot_system_t, FOOT_FRAME
  use scenarios_water, only: build_water
  implicit none (type, external)

  type(input_text_t) :: input
  type(water_description_t) :: description
  type(streamline_t), target :: model
  type(water_series_t) :: s
  type(status_t) :: st
  type(water_point_t) :: q
  type(foot_system_t) :: sys
  type(nonlinear_options_t) :: options
  type(nonlinear_result_t) :: res
  real(wp) :: y0(7), y(7), uv(2), d(2), e, f, g, det, bu, bv, base(3), sgn, diff, jac_err, u_min, u_max, &
              l(2), r(2), pl(3), pr(3), lead
  integer :: i, k, last_solved, hybrj_failures
  logical :: beyond_ok

  call load_input_file('inputs/water/demo_slide.nml', input, st)
  if (st%ok()) call build_water(input, description, st)
    if (st%ok()) call new_streamline(description, model, y0, st)
  call check(st%ok(), 'demo slide built: '//st%text())
  if (.not. st%ok()) call finish_tests('test_water_edges')
  description%solver%ode%rtol = 1e-10_wp; description%solver%ode%atol = 1e-9_wp
  call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, 0.005_wp, s, st, edges=.true.)
  call check(st%ok() .and. s%outcome == OUTCOME_END, 'the water reaches the end')
  call check(s%edge_failures == 0, 'no edge solve failed')
  call model%channel%u_range(u_min, u_max)

  sys%surface => model%channel%slide
  sys%equations = FOOT_FRAME
  options%xtol = edge_options%tolerance; options%residual_tolerance = edge_options%residual_tolerance
  diff = 0; jac_err = 0; hybrj_failures = 0
  do i = 1, s%n
    if (s%edge_solved(i) /= 1) cycle
    y = [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp]
    call water_point(model, y, q, st)
    base = q%position + q%height*q%z_m
    e = dot_product(q%p%ru, q%p%ru); f = dot_product(q%p%ru, q%p%rv); g = dot_product(q%p%rv, q%p%rv)
    bu = 0.5_wp*q%width*dot_product(q%p%ru, q%y_w); bv = 0.5_wp*q%width*dot_product(q%p%rv, q%y_w)
    det = e*g - f*f
    d = [(g*bu - f*bv)/det, (e*bv - f*bu)/det]
    do k = 1, 2
      sgn = merge(1.0_wp, -1.0_wp, k == 1)
      uv = [q%u, q%v] + sgn*d
      sys%target = base + sgn*0.5_wp*q%width*q%y_w
      sys%x_last = huge(1.0_wp)
      call solve_nonlinear(sys, uv, options, res, st)
      if (.not. st%ok()) then
        hybrj_failures = hybrj_failures + 1
        cycle
      end if
      if (k == 1) diff = max(diff, maxval(abs(uv - s%left_edge(:, i))))
      if (k == 2) diff = max(diff, maxval(abs(uv - s%right_edge(:, i))))
      if (mod(i, 397) == 1) then   ! scattered samples along the slide
        call check_jacobian(sys, uv + [3e-3_wp, -2e-2_wp], e, st)
        jac_err = max(jac_err, e)
      end if
    end do
  end do
  call check(hybrj_failures == 0, 'HYBRJ solves every sample Newton solved')
  ! 1e-8: HYBRJ stops at a relative step 1e-10 of the Jacobian-scaled x (~7e-9 m at u ~ 67 m);
  ! a start problem or a different root would differ by centimetres
  call check(diff <= 1e-8_wp, 'warm-started Newton edges = HYBRJ edges within the solve tolerance')
  ! 1e-7: central differences with h ~ 6e-6 u have truncation ~h^2 |f'''| and rounding 1e-16/h
  call check(jac_err <= 1e-7_wp, 'edge Jacobian against central differences')
  print '(a, es9.2, a, es9.2)', '  max |Newton - HYBRJ| ', diff, ', Jacobian rel. error ', jac_err

  ! a guess far beyond the slide (evaluation held at the end): Newton fails, HYBRJ takes over
  i = s%n/2
  y = [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp]
  call water_point(model, y, q, st)
  call water_edges(model%channel, q, l, r, pl, pr, st, [u_max + 1e3_wp, 0.0_wp], [u_max + 1e3_wp, 0.0_wp])
  call check(st%ok(), 'useless guess: the fallback solves the edges')
  ! 1e-8 as above (both HYBRJ's answer within its xtol)
  call check(maxval(abs(l - s%left_edge(:, i))) <= 1e-8_wp .and. maxval(abs(r - s%right_edge(:, i))) <= 1e-8_wp, &
             'useless guess: the same edges')

  ! the flagged samples at the end: the leading edge's offset in u (from the last
  ! solved sample, it changes by ~1e-4 m per sample there) puts it beyond u_max
  call check(s%edge_beyond >= 1, 'the leading edge passes the slide''s end before the water does')
  last_solved = 0
  do i = 1, s%n
    if (s%edge_solved(i) == 1) last_solved = i
  end do
  call check(last_solved == s%n - s%edge_beyond, 'only the last samples are flagged')
  lead = max(s%left_edge(1, last_solved), s%right_edge(1, last_solved)) - s%u(last_solved)
  beyond_ok = .true.
  do i = last_solved + 1, s%n
    beyond_ok = beyond_ok .and. s%u(i) + lead > u_max
  end do
  call check(beyond_ok, 'flagged samples: the leading edge lies beyond u_max (a real limit, not a start problem)')
  i = s%n
  y = [s%u(i), s%v(i), s%du(i), s%dv(i), s%height(i), 0.0_wp, 0.0_wp]
  call water_point(model, y, q, st)
  call water_edges(model%channel, q, l, r, pl, pr, st)
  call check(st%code == STATUS_DOMAIN .and. index(st%text(), 'beyond the end of the slide') > 0, &
             'the edge solve says the foot lies beyond the end of the slide')
  print '(a, i0, a, f8.4, a)', '  ', s%edge_beyond, ' samples with an edge beyond the end; lead of the edge ', &
    lead, ' m'
  call finish_tests('test_water_edges')
end program test_water_edges
