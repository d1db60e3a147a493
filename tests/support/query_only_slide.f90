!> A slide of the tests that is not a tube: `query_only_slide_t` answers
!> every deferred query of the slide query (geometry_slide_query) by asking a
!> tube it keeps, and nothing more, so that it gets the general answers of
!> every other query (section_varies, bottom_radius, slice, ...): the
!> throwaway slide kind of test_water_slide_query and test_slide_queries.
module query_only_slide
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
end module query_only_slide
