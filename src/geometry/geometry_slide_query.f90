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
!>                            its curvature and centerline speed);
!>   slice(u), evaluate_in_slice(slice, v)
!>                            points across the section at one u, the
!>                            centerline and its frame evaluated once for
!>                            all of them (the water's section profile; a
!>                            slide that keeps nothing evaluates each point);
!>   section_circle_radius()  the radius if the section is one circle all
!>                            along, else 0 (closed forms; general: 0);
!>   section_varies()         whether the section changes along u (general:
!>                            it may);
!>   bottom_radius()          the smallest radius of curvature across the
!>                            bottom (v = slide_bottom_v) along the slide:
!>                            the room of a sphere resting there (general:
!>                            sampled from the surface);
!>   built()                  whether the slide has been built (general: yes).
!> Each has a general answer that holds for any slide, so that a new kind
!> is checked and read right without an edit elsewhere; a kind may answer
!> more exactly or faster.
!> The tube (geometry_tube) implements it; a bowl, a funnel or a half-pipe
!> carries the rider and the water (water_channel) by implementing it too. A
!> surface that does not gets the refusal of as_slide (the rider's first
!> check).
module geometry_slide_query
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_vector, only: cross
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_short
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_curve, only: curve_point_t
  use geometry_curve_frame, only: curve_frame_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  implicit none (type, external)
  private
  public :: slide_surface_t, slide_slice_t, as_slide, general_wall_position, general_bottom_radius, slide_bottom_v

  !> v at the bottom of a slide's section (the wall position's origin).
  real(wp), parameter :: slide_bottom_v = pi/2

  !> Samples along u of the general bottom radius.
  integer, parameter :: bottom_samples = 401

  !> The slide at one u (slice): what a slide keeps there to evaluate points
  !> across its section (`kept`: a swept slide's centerline point to order
  !> + 1 and its frame to `order`); the general slide keeps only u.
  type :: slide_slice_t
    real(wp) :: u = 0
    integer :: order = 0
    logical :: kept = .false.
    type(curve_point_t) :: c
    type(curve_frame_t) :: f
  end type slide_slice_t

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
    procedure :: slice => general_slice
    procedure :: evaluate_in_slice => general_evaluate_in_slice
    procedure :: section_circle_radius => general_no_circle
    procedure :: section_varies => general_section_varies
    procedure :: bottom_radius => general_bottom_radius
    procedure :: built => general_built
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
  !> circle). Any slide; a slide with a closed form overrides it. All the
  !> points lie at u: two slices (orders 2 and 1) hold what they share, the
  !> same points as evaluate gives.
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
    type(slide_slice_t) :: slice
    real(wp) :: mid, half, n(3)
    integer :: i
    angle = 0
    distance = 0
    call self%slice(u, 2, slice, status)
    if (status%ok()) call self%evaluate_in_slice(slice, v, 2, p, status)
    if (status%ok()) call darboux_frame(p, 1.0_wp, 1.0_wp, 0.0_wp, fp, status)
    if (status%ok()) call self%evaluate_in_slice(slice, slide_bottom_v, 2, b, status)
    if (status%ok()) call darboux_frame(b, 1.0_wp, 1.0_wp, 0.0_wp, fb, status)
    if (status%ok()) call self%slice(u, 1, slice, status)
    if (.not. status%ok()) return
    ! the angle between the bottom's normal and the point's, signed by the
    ! turn about the bottom's x (along r_u): + towards +v
    n = cross(fb%r(:, 3), fp%r(:, 3))
    angle = sign(atan2(norm2(n), dot_product(fb%r(:, 3), fp%r(:, 3))), dot_product(n, fb%r(:, 1)))
    mid = 0.5_wp*(v + slide_bottom_v)
    half = 0.5_wp*(v - slide_bottom_v)
    do i = 1, 5
      call self%evaluate_in_slice(slice, mid + half*x(i), 1, p, status)
      if (.not. status%ok()) return
      distance = distance + w(i)*half*norm2(p%rv)
    end do
  end subroutine general_wall_position

  !> The slice at u for points to `order`: the general slide keeps u alone.
  pure subroutine general_slice(self, u, order, slice, status)
    class(slide_surface_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(slide_slice_t), intent(out) :: slice
    type(status_t), intent(out) :: status
    associate (unused => self)
    end associate
    status%code = 0
    slice%u = u
    slice%order = order
  end subroutine general_slice

  !> The surface point at (slice%u, v) to `order` (at most the slice's): the
  !> same point as evaluate gives.
  pure subroutine general_evaluate_in_slice(self, slice, v, order, p, status)
    class(slide_surface_t), intent(in) :: self
    type(slide_slice_t), intent(in) :: slice
    real(wp), intent(in) :: v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    call self%evaluate(slice%u, v, order, p, status)
  end subroutine general_evaluate_in_slice

  pure real(wp) function general_no_circle(self) result(radius)
    class(slide_surface_t), intent(in) :: self
    associate (unused => self)
    end associate
    radius = 0
  end function general_no_circle

  pure logical function general_section_varies(self) result(varies)
    class(slide_surface_t), intent(in) :: self
    associate (unused => self)
    end associate
    varies = .true.
  end function general_section_varies

  pure logical function general_built(self) result(built)
    class(slide_surface_t), intent(in) :: self
    associate (unused => self)
    end associate
    built = .true.
  end function general_built

  !> The smallest radius of curvature across the slide at its bottom
  !> (v = slide_bottom_v), m, over bottom_samples values of u from start to
  !> end, and the u where it is (huge where the bottom is nowhere hollow):
  !> the normal curvature of the v-curve, n.r_vv/|r_v|^2 with the normal
  !> r_u x r_v (into the slide), positive where the bottom is hollow. A
  !> bottom that cannot be evaluated is an error naming u.
  subroutine general_bottom_radius(self, radius, u_at, status)
    class(slide_surface_t), intent(in) :: self
    real(wp), intent(out) :: radius, u_at
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: p
    real(wp) :: u_min, u_max, v_min, v_max, u, n(3), bend
    integer :: i
    character(len=:), allocatable :: why
    call self%domain(u_min, u_max, v_min, v_max)
    radius = huge(1.0_wp)
    u_at = u_min
    do i = 0, bottom_samples - 1
      u = u_min + (u_max - u_min)*i/real(bottom_samples - 1, wp)
      call self%evaluate(u, slide_bottom_v, 2, p, status)
      if (.not. status%ok()) then
        why = status%text()
        call set_status(status, STATUS_INVALID_INPUT, 'the slide''s bottom (v = pi/2) at u = '// &
                        format_short(u)//': '//why)
        return
      end if
      n = cross(p%ru, p%rv)
      bend = dot_product(n, p%rvv)/norm2(n)
      if (bend > 0) then
        if (dot_product(p%rv, p%rv)/bend < radius) then
          radius = dot_product(p%rv, p%rv)/bend
          u_at = u
        end if
      end if
    end do
  end subroutine general_bottom_radius
end module geometry_slide_query
