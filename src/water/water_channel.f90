!> The channel: how the water reads a slide. A slide is any surface that
!> answers the slide query (geometry_slide_query: a surface swept along a
!> centerline; the tube of geometry_tube, a fitted slide, a tube on any
!> centerline, a closed-form straight, helical or S-shaped tube, implements
!> it), as for the rider, and this one adapter gives the water model what it
!> needs of it: the surface r(u, v) (u along the centerline, v across;
!> v = pi/2 at the bottom of a circular tube, growing to the left of the
!> direction of travel), the centerline c(u) for the curvature chi (thesis
!> 4.8) and its rate, and the cross-section: a circle of radius r in closed
!> form where the slide says its section is one (section_circle_radius), any
!> other profile read from the surface itself (thesis 4.6), taken to change
!> along u (the area's rate by differences) unless the slide says it does not
!> (section_varies: a slide or section kind that says nothing is read the
!> general way, which holds for any section).
!>
!> chi_s: the thesis (4.9) differentiates chi by the centerline parameter u.
!> With f3 in kg m the friction term f3 chi_u w^2 is a force only if u is an
!> arc length (chi_u in 1/m^2); the thesis's centerline parameter is close to
!> arc length. `curvature` therefore returns the derivative by arc length,
!> chi_s = chi_u/|c_u|, which equals (4.9) on arc-length parametrized lines.
!>
!> The type is extensible so that a test can replace a piece of it (e.g. the
!> curvature) and compare runs.
module water_channel
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: curve_point_t
  use geometry_curve_frame, only: curve_curvature
  use geometry_slide_query, only: slide_surface_t, slide_slice_t
  implicit none (type, external)
  private
  public :: channel_t, new_channel

  type :: channel_t
    class(slide_surface_t), allocatable :: slide   ! the slide query (geometry_slide_query)
    real(wp) :: radius = 0        ! m, the circle's radius; 0 if the section is not a circle
    logical :: varies = .false.   ! the profile changes along u (the slide's section_varies)
  contains
    !> r(u, v) and partials to `order` (0..3).
    procedure :: evaluate => channel_evaluate
    !> The slide at u for points to `order` across its section, and a point
    !> in it: the centerline evaluated once for the section's profile.
    procedure :: slice => channel_slice
    procedure :: evaluate_in_slice => channel_evaluate_in_slice
    !> The surface point to order 2 with chi, chi_s, |c_u| and d|c_u|/du from
    !> one evaluation of the centerline (the water model's hot path).
    procedure :: evaluate_with_curvature => channel_evaluate_with_curvature
    !> Centerline c(u) and its u-derivatives: c(:, k) = d^k c/du^k, k = 0..3.
    procedure :: centerline => channel_centerline
    !> Parameter range of u (the slide runs from u_min to u_max).
    procedure :: u_range => channel_u_range
    !> Range of v on the surface (+-huge for a closed tube).
    procedure :: v_range => channel_v_range
    !> Radius of the circular cross-section at u, or 0 if the section is not a circle.
    procedure :: circle_radius => channel_circle_radius
    !> Whether the profile changes along u (the water area then depends on u).
    procedure :: section_varies => channel_section_varies
    !> Centerline curvature chi (4.8) and its derivative by arc length.
    procedure :: curvature => channel_curvature
    procedure :: arc_length => channel_arc_length
    procedure :: parameter_at_length => channel_parameter_at_length
    procedure :: describe => channel_describe
    procedure :: parameter_units => channel_parameter_units
  end type channel_t

contains

  !> The channel of a slide: its section as the slide says it is (module
  !> comment).
  function new_channel(slide) result(c)
    class(slide_surface_t), intent(in) :: slide
    type(channel_t) :: c
    c%slide = slide
    c%radius = slide%section_circle_radius()
    c%varies = slide%section_varies()
  end function new_channel

  pure subroutine channel_evaluate(self, u, v, order, p, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    call self%slide%evaluate(u, v, order, p, status)
  end subroutine channel_evaluate

  pure subroutine channel_slice(self, u, order, slice, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(slide_slice_t), intent(out) :: slice
    type(status_t), intent(out) :: status
    call self%slide%slice(u, order, slice, status)
  end subroutine channel_slice

  !> p is intent(inout) only so that the point is not default-initialized
  !> twice (here and in the slide's evaluate_in_slice, which writes it
  !> whole): the profile's hot path.
  pure subroutine channel_evaluate_in_slice(self, slice, v, order, p, status)
    class(channel_t), intent(in) :: self
    type(slide_slice_t), intent(in) :: slice
    real(wp), intent(in) :: v
    integer, intent(in) :: order
    type(surface_point_t), intent(inout) :: p
    type(status_t), intent(out) :: status
    call self%slide%evaluate_in_slice(slice, v, order, p, status)
  end subroutine channel_evaluate_in_slice

  pure subroutine channel_evaluate_with_curvature(self, u, v, p, chi, chi_s, speed, speed_u, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    type(surface_point_t), intent(out) :: p
    real(wp), intent(out) :: chi, chi_s   ! 1/m, 1/m^2
    real(wp), intent(out) :: speed        ! |c_u|, m per unit of u
    real(wp), intent(out) :: speed_u      ! d|c_u|/du = c_u.c_uu/|c_u|
    type(status_t), intent(out) :: status
    type(curve_point_t) :: c
    chi = 0; chi_s = 0; speed = 0; speed_u = 0
    call self%slide%evaluate_with_centerline(u, v, 2, p, c, status)
    if (.not. status%ok()) return
    call curvature_from_derivatives(c%d(:, 0:3), chi, chi_s)
    speed = norm2(c%d(:, 1))
    speed_u = dot_product(c%d(:, 1), c%d(:, 2))/speed
  end subroutine channel_evaluate_with_curvature

  pure subroutine channel_centerline(self, u, c, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: c(3, 0:3)
    type(status_t), intent(out) :: status
    type(curve_point_t) :: cp
    call self%slide%centerline_point(u, 3, cp, status)
    c = cp%d(:, 0:3)
  end subroutine channel_centerline

  pure subroutine channel_u_range(self, u_min, u_max)
    class(channel_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    real(wp) :: v_min, v_max
    call self%slide%domain(u_min, u_max, v_min, v_max)
  end subroutine channel_u_range

  pure subroutine channel_v_range(self, v_min, v_max)
    class(channel_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    real(wp) :: u_min, u_max
    ! the section's edges where the slide starts: the water's v range does
    ! not follow u (a tube's section keeps its range)
    call self%slide%domain(u_min, u_max, v_min, v_max)
    call self%slide%section_edges(u_min, v_min, v_max)
  end subroutine channel_v_range

  pure real(wp) function channel_circle_radius(self, u) result(radius)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    associate (unused => u)
    end associate
    radius = self%radius
  end function channel_circle_radius

  pure logical function channel_section_varies(self) result(varies)
    class(channel_t), intent(in) :: self
    varies = self%varies
  end function channel_section_varies

  pure subroutine channel_curvature(self, u, chi, chi_s, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: chi, chi_s        ! 1/m, 1/m^2
    type(status_t), intent(out) :: status
    real(wp) :: c(3, 0:3)
    chi = 0; chi_s = 0
    call self%centerline(u, c, status)
    if (.not. status%ok()) return
    call curvature_from_derivatives(c, chi, chi_s)
  end subroutine channel_curvature

  !> chi and chi_s = chi_u/|c'| (geometry_curve_frame's curve_curvature,
  !> with its zero test: chi_s = 0 on a straight piece or at an inflection).
  pure subroutine curvature_from_derivatives(c, chi, chi_s)
    real(wp), intent(in) :: c(3, 0:3)
    real(wp), intent(out) :: chi, chi_s
    real(wp) :: chi_u
    call curve_curvature(c, 3, chi, chi_u)
    chi_s = chi_u/norm2(c(:, 1))
  end subroutine curvature_from_derivatives

  !> Arc length of the centerline from its start to u, m.
  pure real(wp) function channel_arc_length(self, u) result(s)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    s = self%slide%arc_length(u)
  end function channel_arc_length

  !> u at arc length s (m) from the start of the centerline.
  pure subroutine channel_parameter_at_length(self, s, u, status)
    class(channel_t), intent(in) :: self
    real(wp), intent(in) :: s
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    call self%slide%parameter_at_length(s, u, status)
  end subroutine channel_parameter_at_length

  pure function channel_describe(self) result(text)
    class(channel_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = self%slide%describe()
  end function channel_describe

  !> u: m along a line, a fitted slide or an S-bend, rad around a helix; v: rad.
  pure subroutine channel_parameter_units(self, u_units, v_units)
    class(channel_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    call self%slide%parameter_units(u_units, v_units)
  end subroutine channel_parameter_units
end module water_channel
