!> The slide and section queries that replaced the `select type` on concrete
!> kinds (issue 24): what a slide says of its section (a circle's radius,
!> whether it changes along u, the room at its bottom, whether it is built)
!> and the slice at one u. A section kind and a slide kind of this test
!> that say nothing of themselves must get the general answers: the check
!> of the rider's spheres (before, a slide that was not a tube, or a tube
!> whose section was not a circle, got no check at all) and the water's
!> area rate (before, a tube whose section was not one of the kinds named
!> in water_channel was taken as constant along u).
!>
!> The throwaway section: an ellipse widening along u, half-width
!> a(u) = a0 (1 + g u) across, half-height b; on a straight centerline r_u
!> is the tangent at the bottom, normal to the section's plane, so the
!> bottom's radius of curvature across is the ellipse's at the end of its
!> b-axis, a^2/b, least at the start: a0^2/b (to rounding).
!> The slice: a point evaluated in the slice at u is the point evaluate
!> gives, bit for bit (the water's profile reads its points that way).
module test_slide_queries_support
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_status, only: status_t
  use geometry_cross_section, only: cross_section_t, section_point_t
  implicit none (type, external)
  private
  public :: widening_ellipse_t

  type, extends(cross_section_t) :: widening_ellipse_t
    real(wp) :: a0 = 0.6_wp, growth = 0.05_wp, b = 0.4_wp   ! m, 1/m, m
  contains
    procedure :: evaluate => widening_evaluate
    procedure :: v_range => widening_range
  end type widening_ellipse_t

contains

  !> s = [-a(u) cos v, -b sin v], a = a0 (1 + g u): u-derivatives of s_y
  !> are a' = a0 g times the v-derivatives of -cos v, and none above the first.
  pure subroutine widening_evaluate(self, u, v, order, p, status)
    class(widening_ellipse_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: a, da, cy(0:3), cz(0:3)
    integer :: i, j
    status%code = 0
    a = self%a0*(1 + self%growth*u)
    da = self%a0*self%growth
    cy = [-cos(v), sin(v), cos(v), -sin(v)]    ! d^j/dv^j of -cos v
    cz = [-sin(v), -cos(v), sin(v), cos(v)]    ! d^j/dv^j of -sin v
    p%order = order
    do j = 0, order
      p%s(:, 0, j) = [a*cy(j), self%b*cz(j)]
      do i = 1, order - j
        p%s(:, i, j) = 0
        if (i == 1) p%s(1, i, j) = da*cy(j)
      end do
    end do
  end subroutine widening_evaluate

  pure subroutine widening_range(self, v_min, v_max)
    class(widening_ellipse_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    associate (unused => self)
    end associate
    v_min = 0; v_max = two_pi
  end subroutine widening_range
end module test_slide_queries_support

program test_slide_queries
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: line_curve_t, constant_curve_t, helix_curve_t
  use geometry_cross_section, only: circle_section_t, flume_section_t
  use geometry_slide_query, only: slide_surface_t, slide_slice_t
  use geometry_tube, only: tube_surface_t, new_tube_surface, new_straight_tube
  use water_channel, only: channel_t, new_channel
  use rider_model, only: rider_params_t
  use io_input, only: input_text_t, input_from_text
  use scenarios_ride, only: check_sphere_radii
  use query_only_slide, only: query_only_slide_t
  use test_slide_queries_support, only: widening_ellipse_t
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  type(tube_surface_t) :: widening, circle, flume, helix, unbuilt
  type(query_only_slide_t) :: by_query
  type(widening_ellipse_t) :: ellipse
  type(flume_section_t) :: flume_section
  type(channel_t) :: channel
  type(input_text_t) :: input
  type(rider_params_t) :: rider
  type(status_t) :: st
  real(wp) :: th, room, u_at

  th = 10*pi/180
  widening = new_tube_surface(line_curve_t(direction=[cos(th), 0.0_wp, -sin(th)], u_min=0.0_wp, u_max=20.0_wp), &
                              constant_curve_t(), ellipse, st)
  call check(st%ok(), 'the tube of the throwaway section: '//st%text())
  circle = new_straight_tube(0.5_wp, th, 20.0_wp, st)
  flume = new_tube_surface(line_curve_t(direction=[cos(th), 0.0_wp, -sin(th)], u_min=0.0_wp, u_max=20.0_wp), &
                           constant_curve_t(), flume_section, st)
  helix = new_tube_surface(helix_curve_t(radius=4.0_wp, pitch=-0.3_wp, u_min=0.0_wp, u_max=6.0_wp), &
                           constant_curve_t(), circle_section_t(radius=0.5_wp), st)
  call check(st%ok(), 'the helical tube: '//st%text())
  by_query%tube = circle
  call input_from_text('<test>', '&rider /', input, st)
  call check(st%ok(), 'input text: '//st%text())

  ! what each says of its section
  call check(widening%section_circle_radius() == 0 .and. widening%section_varies(), &
             'a section kind that says nothing: not a circle, taken to change along u')
  channel = new_channel(widening)
  call check(channel%circle_radius(1.0_wp) == 0 .and. channel%section_varies(), &
             'the water reads the throwaway section as changing along u (it does)')
  call check(circle%section_circle_radius() == 0.5_wp .and. .not. circle%section_varies(), &
             'a circle tube: its radius, the same along u')
  call check(flume%section_circle_radius() == 0 .and. .not. flume%section_varies(), &
             'a flume tube: not a circle, the same along u')
  call check(by_query%section_circle_radius() == 0 .and. by_query%section_varies() .and. by_query%built(), &
             'a slide kind that says nothing: not a circle, taken to change along u, built')
  call check(circle%built() .and. .not. unbuilt%built(), 'a tube is built with its centerline, a default one not')

  ! the room at the bottom
  st%code = 0
  call widening%bottom_radius(room, u_at, st)
  call check(st%ok(), 'the throwaway section''s bottom: '//st%text())
  call check_close(room, ellipse%a0**2/ellipse%b, 1e-12_wp, 0.0_wp, &
                   'the throwaway section''s bottom radius a0^2/b (sampled from the surface)')
  call check(u_at == 0, 'the least bottom radius at the start (the ellipse widens along u)')
  call circle%bottom_radius(room, u_at, st)
  call check(room == 0.5_wp, 'a circle tube''s bottom radius is its radius')
  call by_query%bottom_radius(room, u_at, st)
  call check_close(room, 0.5_wp, 1e-12_wp, 0.0_wp, 'a slide kind that says nothing: the radius sampled, 0.5 m')
  call flume%bottom_radius(room, u_at, st)
  call check_close(room, flume_section%radius, 1e-12_wp, 0.0_wp, 'a flume''s bottom: its semicircle''s radius')

  ! the rider's spheres are checked on every kind
  call sphere_check(widening, 0.5_wp, .true., 'the throwaway section: a 0.5 m sphere fits (0.9 m)')
  call sphere_check(widening, 0.95_wp, .false., 'the throwaway section: a 0.95 m sphere does not')
  call sphere_check(by_query, 0.45_wp, .true., 'the throwaway slide: a 0.45 m sphere fits (0.5 m)')
  call sphere_check(by_query, 0.6_wp, .false., 'the throwaway slide: a 0.6 m sphere does not')
  call sphere_check(flume, 0.6_wp, .false., 'a flume of 0.52 m: a 0.6 m sphere does not')
  call sphere_check(circle, 0.6_wp, .false., 'a circle of 0.5 m: a 0.6 m sphere does not')

  ! a point in the slice is the point evaluate gives
  call slice_same(widening, 'the throwaway section (u-derivatives of the section)')
  call slice_same(helix, 'the helical tube')
  call slice_same(flume, 'the flume tube')
  call slice_same(by_query, 'the throwaway slide (the general slice)')
  block
    type(slide_slice_t) :: slice
    type(surface_point_t) :: p
    call helix%slice(1.0_wp, 1, slice, st)
    call helix%evaluate_in_slice(slice, 1.0_wp, 2, p, st)
    call check(st%code == STATUS_INVALID_INPUT, 'a point of higher order than its slice is refused: '//st%text())
  end block
  call finish_tests('test_slide_queries')

contains

  subroutine sphere_check(slide, radius, fits, what)
    class(slide_surface_t), intent(in) :: slide
    real(wp), intent(in) :: radius
    logical, intent(in) :: fits
    character(len=*), intent(in) :: what
    type(status_t) :: status
    rider%drag_radius = [radius, 0.05_wp, 0.05_wp]
    call check_sphere_radii(input, rider, slide, status)
    if (fits) then
      call check(status%ok(), what//': '//status%text())
    else
      call check(status%code == STATUS_INVALID_INPUT .and. index(status%text(), 'drag_radius(1)') > 0 .and. &
                 index(status%text(), 'must fit in the slide') > 0, what//': '//status%text())
    end if
  end subroutine sphere_check

  subroutine slice_same(slide, what)
    class(slide_surface_t), intent(in) :: slide
    character(len=*), intent(in) :: what
    type(slide_slice_t) :: slice
    type(surface_point_t) :: p, q
    type(status_t) :: s1, s2
    real(wp) :: u, v
    integer :: order, i, j
    logical :: same
    same = .true.
    do order = 0, 3
      do i = 1, 7
        u = 0.37_wp + 0.71_wp*i
        call slide%slice(u, order, slice, s1)
        do j = 0, 12
          v = 0.1_wp + 0.25_wp*j
          call slide%evaluate(u, v, order, p, s1)
          call slide%evaluate_in_slice(slice, v, order, q, s2)
          same = same .and. s1%ok() .and. s2%ok() .and. all(p%r == q%r) .and. p%order == q%order
          if (order >= 1) same = same .and. all(p%ru == q%ru) .and. all(p%rv == q%rv)
          if (order >= 2) same = same .and. all(p%ruu == q%ruu) .and. all(p%ruv == q%ruv) .and. all(p%rvv == q%rvv)
          if (order >= 3) same = same .and. all(p%ruuu == q%ruuu) .and. all(p%ruuv == q%ruuv) .and. &
                                 all(p%ruvv == q%ruvv) .and. all(p%rvvv == q%rvvv)
        end do
      end do
    end do
    call check(same, what//': every point in the slice is evaluate''s, bit for bit (orders 0..3)')
  end subroutine slice_same
end program test_slide_queries
