!> The slide query: what a rider (and the water) asks of a slide beyond its
!> surface r(u, v). A slide is a surface swept along a centerline c(u); u is
!> the centerline's parameter, v runs across the section, v = pi/2 at the
!> bottom (slide_bottom_v). slide_surface_t extends surface_t with
!>   arc_length(u)            s(u), m of centerline from its start (exact
!>                            where the curve has it: no differences);
!>   length()                 the whole centerline's, m;
!>   parameter_at_length(s)   u at arc length s;
!>   centerline_speed(u)      ds/du = |c_u| (m per unit of u), from the
!>                            curve's derivative;
!>   centerline_point(u, k)   c(u) and its derivatives to order k;
!>   frame(u, order)          the moving frame of the centerline and its
!>                            derivatives (geometry_curve_frame);
!>   section_edges(u)         the section's v range at u (+-huge: closed);
!>   wall_position(u, v)      the wall angle and the distance along the
!>                            section from the bottom (general: by the
!>                            Darboux normals and a quadrature; a slide may
!>                            give closed forms);
!>   evaluate_with_centerline the surface point and the centerline point to
!>                            order + 1 from one evaluation (the water's hook:
!>                            its curvature and centerline speed).
!> The tube (geometry_tube) implements it; a bowl, a funnel or a half-pipe
!> carries the rider and the water (water_channel) by implementing it too. A
!> surface that does not gets the refusal of as_slide (the rider's first
!> check).
module geometry_slide_query
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_vector, only: cross
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_curve, only: curve_point_t
  use geometry_curve_frame, only: curve_frame_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  implicit none (type, external)
  private
  public :: slide_surface_t, as_slide, general_wall_position, slide_bottom_v

  !> v at the bottom of a slide's section (the wall position's origin).
  real(wp), parameter :: slide_bottom_v = pi/2

  type, abstract, extends(surface_t) :: slide_surface_t
  contains
    procedure(arc_length_i), deferred :: arc_length
    procedure(length_i), deferred :: length
    procedure(parameter_at_length_i), deferred :: parameter_at_length
    procedure(centerline_speed_i), deferred :: centerline_speed
    procedure(centerline_point_i), deferred :: centerline_point
    procedure(frame_i), deferred :: frame
    procedure(section_edges_i), deferred :: section_edges
    procedure(evaluate_with_centerline_i), deferred :: evaluate_with_centerline
    procedure :: wall_position => general_wall_position
  end type slide_surface_t

  abstract interface
    !> Centerline arc length from its start to u, m.
    pure real(wp) function arc_length_i(self, u) result(s)
      import :: slide_surface_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: u
    end function arc_length_i

    !> The whole centerline's length, m.
    pure real(wp) function length_i(self) result(s)
      import :: slide_surface_t, wp
      class(slide_surface_t), intent(in) :: self
    end function length_i

    !> u at centerline arc length s (m).
    pure subroutine parameter_at_length_i(self, s, u, status)
      import :: slide_surface_t, status_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: s
      real(wp), intent(out) :: u
      type(status_t), intent(out) :: status
    end subroutine parameter_at_length_i

    !> ds/du = |c_u| at u, m per unit of u.
    pure subroutine centerline_speed_i(self, u, speed, status)
      import :: slide_surface_t, status_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: u
      real(wp), intent(out) :: speed
      type(status_t), intent(out) :: status
    end subroutine centerline_speed_i

    !> The centerline point c(u) with its derivatives to `order` (0..4).
    pure subroutine centerline_point_i(self, u, order, c, status)
      import :: slide_surface_t, curve_point_t, status_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: u
      integer, intent(in) :: order
      type(curve_point_t), intent(out) :: c
      type(status_t), intent(out) :: status
    end subroutine centerline_point_i

    !> The centerline's moving frame at u with derivatives to `order`; c: the
    !> centerline point (derivatives to order + 1).
    pure subroutine frame_i(self, u, order, f, status, c)
      import :: slide_surface_t, curve_frame_t, curve_point_t, status_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: u
      integer, intent(in) :: order
      type(curve_frame_t), intent(out) :: f
      type(status_t), intent(out) :: status
      type(curve_point_t), intent(out), optional :: c
    end subroutine frame_i

    !> The section's v range at u (-huge, huge for a closed section).
    pure subroutine section_edges_i(self, u, v_min, v_max)
      import :: slide_surface_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: u
      real(wp), intent(out) :: v_min, v_max
    end subroutine section_edges_i

    !> The surface point to `order` and the centerline point to order + 1.
    pure subroutine evaluate_with_centerline_i(self, u, v, order, p, c, status)
      import :: slide_surface_t, surface_point_t, curve_point_t, status_t, wp
      class(slide_surface_t), intent(in) :: self
      real(wp), intent(in) :: u, v
      integer, intent(in) :: order
      type(surface_point_t), intent(out) :: p
      type(curve_point_t), intent(out) :: c
      type(status_t), intent(out) :: status
    end subroutine evaluate_with_centerline_i
  end interface

contains

  !> The slide query of `surface` (a copy), or a refusal naming the surface.
  subroutine as_slide(surface, slide, status)
    class(surface_t), intent(in) :: surface
    class(slide_surface_t), allocatable, intent(out) :: slide
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    select type (surface)
    class is (slide_surface_t)
      allocate (slide, source=surface)
    class default
      call set_status(status, STATUS_INVALID_INPUT, 'the '//surface%describe()//' is not a slide: a rider '// &
                      'rides a surface that answers the slide query (centerline arc length, moving frame, '// &
                      'cross-section; geometry_slide_query), such as a tube')
    end select
  end subroutine as_slide

  !> Wall angle (rad) and distance along the wall (m) of (u, v) from the
  !> bottom v = pi/2: the angle of the Darboux normal from the normal at
  !> (u, pi/2) about the section's tangent direction (+ towards +v), and the
  !> length of the v-curve between them (5-point Gauss-Legendre; exact for a
  !> circle). Any slide; a slide with a closed form overrides it.
  subroutine general_wall_position(self, u, v, angle, distance, status)
    class(slide_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    real(wp), intent(out) :: angle, distance
    type(status_t), intent(inout) :: status
    real(wp), parameter :: x(5) = [-0.9061798459386640_wp, -0.5384693101056831_wp, 0.0_wp, &
                                   0.5384693101056831_wp, 0.9061798459386640_wp]
    real(wp), parameter :: w(5) = [0.2369268850561891_wp, 0.4786286704993665_wp, 0.5688888888888889_wp, &
                                   0.4786286704993665_wp, 0.2369268850561891_wp]
    type(surface_point_t) :: p, b
    type(darboux_frame_t) :: fp, fb
    real(wp) :: mid, half, n(3)
    integer :: i
    angle = 0
    distance = 0
    call self%evaluate(u, v, 2, p, status)
    if (status%ok()) call darboux_frame(p, 1.0_wp, 1.0_wp, 0.0_wp, fp, status)
    if (status%ok()) call self%evaluate(u, slide_bottom_v, 2, b, status)
    if (status%ok()) call darboux_frame(b, 1.0_wp, 1.0_wp, 0.0_wp, fb, status)
    if (.not. status%ok()) return
    ! the angle between the bottom's normal and the point's, signed by the
    ! turn about the bottom's x (along r_u): + towards +v
    n = cross(fb%r(:, 3), fp%r(:, 3))
    angle = sign(atan2(norm2(n), dot_product(fb%r(:, 3), fp%r(:, 3))), dot_product(n, fb%r(:, 1)))
    mid = 0.5_wp*(v + slide_bottom_v)
    half = 0.5_wp*(v - slide_bottom_v)
    do i = 1, 5
      call self%evaluate(u, mid + half*x(i), 1, p, status)
      if (.not. status%ok()) return
      distance = distance + w(i)*half*norm2(p%rv)
    end do
  end subroutine general_wall_position
end module geometry_slide_query
