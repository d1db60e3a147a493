!> The water on a slide known only through the slide query
!> (geometry_slide_query), as the rider knows it: `query_only_slide_t`, a
!> slide of this test that is not a tube, answers every query by asking a
!> tube it keeps (an open flume section on a straight incline: the water
!> reads a flume's profile from the surface, thesis 4.6). The water model
!> can know nothing of such a slide's section, so it reads the profile from
!> the surface and takes the water area's rate along u by differences (the
!> section might change); here the section does not change, so that rate is
!> rounding (the areas at u +- 1e-5 agree to ~1e-15 relative: ~1e-10 per
!> unit of u), and the water must be the tube's: every sample of speed,
!> height, width and v within 1e-7 relative (or absolute, for v) of the
!> tube's run (rtol 1e-10 over ~2e3 steps, the rate's rounding far below).
!> A wrong reading of the section (no profile, a circle) would be off at
!> the first sample by far more.

program test_water_slide_query
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_curve, only: line_curve_t, constant_curve_t
  use geometry_cross_section, only: flume_section_t
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use water_channel, only: channel_t, new_channel
  use water_flow, only: OUTCOME_END, START_SPEED
  use water_run, only: water_description_t, water_result_t, compute_water
  use query_only_slide, only: query_only_slide_t
  use testing, only: check, finish_tests
  implicit none (type, external)

  real(wp), parameter :: tol = 1e-7_wp
  type(tube_surface_t) :: tube
  type(query_only_slide_t) :: slide
  type(channel_t) :: by_tube, by_query
  type(water_description_t) :: d_tube, d_query
  type(water_result_t) :: r_tube, r_query
  type(status_t) :: st
  real(wp) :: th
  integer :: n

  th = 8*pi/180
  tube = new_tube_surface(line_curve_t(direction=[cos(th), 0.0_wp, -sin(th)], u_min=0.0_wp, u_max=20.0_wp), &
                          constant_curve_t(), flume_section_t(), st)
  call check(st%ok(), 'flume built: '//st%text())
  slide%tube = tube

  by_tube = new_channel(tube)
  by_query = new_channel(slide)
  call check(by_tube%circle_radius(1.0_wp) == 0 .and. .not. by_tube%section_varies(), &
             'the flume tube: a profile read from the surface, the same along u')
  call check(by_query%circle_radius(1.0_wp) == 0 .and. by_query%section_varies(), &
             'a slide that is not a tube: a profile read from the surface, taken to change along u')

  d_tube%slide = tube
  d_tube%start%mode = START_SPEED; d_tube%start%speed = 1.5_wp; d_tube%start%v0 = pi/2
  d_tube%start%beta = 0.2_wp
  d_tube%flow_rate = 0.004_wp
  d_tube%solver%ode%rtol = 1e-10_wp; d_tube%solver%ode%atol = 1e-10_wp
  d_tube%solver%output_step = 0.01_wp
  d_query = d_tube
  d_query%slide = slide
  call compute_water(d_tube, r_tube, st)
  call check(st%ok() .and. r_tube%series%outcome == OUTCOME_END, 'the water runs down the flume tube: '//st%text())
  call compute_water(d_query, r_query, st)
  call check(st%ok() .and. r_query%series%outcome == OUTCOME_END, &
             'the water runs down the slide known by its query: '//st%text())
  if (.not. st%ok()) call finish_tests('test_water_slide_query')
  n = min(r_tube%series%n, r_query%series%n)
  call check(abs(r_tube%series%n - r_query%series%n) <= 1, 'as many samples on both')
  associate (a => r_tube%series, b => r_query%series)
    call check(all(abs(b%speed(:n) - a%speed(:n)) <= tol*a%speed(:n)), 'the same speed at every sample')
    call check(all(abs(b%height(:n) - a%height(:n)) <= tol*a%height(:n)), 'the same height at every sample')
    call check(all(abs(b%width(:n) - a%width(:n)) <= tol*a%width(:n)), 'the same width at every sample')
    call check(all(abs(b%v(:n) - a%v(:n)) <= tol), 'the same v at every sample')
    call check(maxval(abs(a%height(:n) - a%height(1))) > 1e3_wp*tol*a%height(1), &
               'the height changes along the run (the comparison is not of constants)')
  end associate
  call finish_tests('test_water_slide_query')
end program test_water_slide_query
