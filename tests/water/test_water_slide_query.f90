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
module test_water_slide_query_support
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: curve_point_t
  use geometry_curve_frame, only: curve_frame_t
  use geometry_slide_query, only: slide_surface_t
  use geometry_tube, only: tube_surface_t
  implicit none (type, external)
  private
  public :: query_only_slide_t

  type, extends(slide_surface_t) :: query_only_slide_t
    type(tube_surface_t) :: tube
  contains
    procedure :: evaluate => q_evaluate
    procedure :: domain => q_domain
    procedure :: periodic_v => q_periodic_v
    procedure :: describe => q_describe
    procedure :: arc_length => q_arc_length
    procedure :: length => q_length
    procedure :: parameter_at_length => q_parameter_at_length
    procedure :: centerline_speed => q_centerline_speed
    procedure :: centerline_point => q_centerline_point
    procedure :: frame => q_frame
    procedure :: section_edges => q_section_edges
    procedure :: evaluate_with_centerline => q_evaluate_with_centerline
  end type query_only_slide_t

contains

  pure subroutine q_evaluate(self, u, v, order, p, status)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    call self%tube%evaluate(u, v, order, p, status)
  end subroutine q_evaluate

  pure subroutine q_domain(self, u_min, u_max, v_min, v_max)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    call self%tube%domain(u_min, u_max, v_min, v_max)
  end subroutine q_domain

  pure logical function q_periodic_v(self) result(periodic)
    class(query_only_slide_t), intent(in) :: self
    periodic = self%tube%periodic_v()
  end function q_periodic_v

  pure function q_describe(self) result(text)
    class(query_only_slide_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = 'slide of the test around a '//self%tube%describe()
  end function q_describe

  pure real(wp) function q_arc_length(self, u) result(s)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u
    s = self%tube%arc_length(u)
  end function q_arc_length

  pure real(wp) function q_length(self) result(s)
    class(query_only_slide_t), intent(in) :: self
    s = self%tube%length()
  end function q_length

  pure subroutine q_parameter_at_length(self, s, u, status)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: s
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    call self%tube%parameter_at_length(s, u, status)
  end subroutine q_parameter_at_length

  pure subroutine q_centerline_speed(self, u, speed, status)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: speed
    type(status_t), intent(out) :: status
    call self%tube%centerline_speed(u, speed, status)
  end subroutine q_centerline_speed

  pure subroutine q_centerline_point(self, u, order, c, status)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: c
    type(status_t), intent(out) :: status
    call self%tube%centerline_point(u, order, c, status)
  end subroutine q_centerline_point

  pure subroutine q_frame(self, u, order, f, status, c)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_frame_t), intent(out) :: f
    type(status_t), intent(out) :: status
    type(curve_point_t), intent(out), optional :: c
    call self%tube%frame(u, order, f, status, c)
  end subroutine q_frame

  pure subroutine q_section_edges(self, u, v_min, v_max)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: v_min, v_max
    call self%tube%section_edges(u, v_min, v_max)
  end subroutine q_section_edges

  pure subroutine q_evaluate_with_centerline(self, u, v, order, p, c, status)
    class(query_only_slide_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(curve_point_t), intent(out) :: c
    type(status_t), intent(out) :: status
    call self%tube%evaluate_with_centerline(u, v, order, p, c, status)
  end subroutine q_evaluate_with_centerline
end module test_water_slide_query_support

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
  use test_water_slide_query_support, only: query_only_slide_t
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
