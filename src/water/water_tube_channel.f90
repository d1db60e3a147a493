!> The geometry layer's tube surfaces (thesis 3.64, geometry_tube) as a water
!> channel: the surface, its centerline for chi and chi_s, the circle radius
!> when the section is a circle (thesis 4.2), any other section through its
!> profile (thesis 4.6).
module water_tube_channel
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: curve_point_t
  use geometry_cross_section, only: circle_section_t, blended_section_t
  use geometry_tube, only: tube_surface_t
  use water_channel, only: channel_t
  implicit none (type, external)
  private
  public :: tube_channel_t, new_tube_channel

  type, extends(channel_t) :: tube_channel_t
    type(tube_surface_t) :: tube
  contains
    procedure :: evaluate => tc_evaluate
    procedure :: centerline => tc_centerline
    procedure :: u_range => tc_u_range
    procedure :: circle_radius => tc_circle_radius
    procedure :: v_range => tc_v_range
    procedure :: section_varies => tc_section_varies
    procedure :: arc_length => tc_arc_length
    procedure :: parameter_at_length => tc_parameter_at_length
    procedure :: describe => tc_describe
    procedure :: parameter_units => tc_parameter_units
  end type tube_channel_t

contains

  function new_tube_channel(tube) result(c)
    type(tube_surface_t), intent(in) :: tube
    type(tube_channel_t) :: c
    c%tube = tube
  end function new_tube_channel

  pure subroutine tc_evaluate(self, u, v, order, p, status)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    call self%tube%evaluate(u, v, order, p, status)
  end subroutine tc_evaluate

  pure subroutine tc_centerline(self, u, c, status)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp), intent(out) :: c(3, 0:3)
    type(status_t), intent(out) :: status
    type(curve_point_t) :: cp
    call self%tube%centerline%evaluate(u, 3, cp, status)
    c = cp%d(:, 0:3)
  end subroutine tc_centerline

  pure subroutine tc_u_range(self, u_min, u_max)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    call self%tube%centerline%domain(u_min, u_max)
  end subroutine tc_u_range

  pure real(wp) function tc_circle_radius(self, u) result(radius)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    associate (unused => u)
    end associate
    select type (s => self%tube%section)
    type is (circle_section_t)
      radius = s%radius
    class default
      radius = 0
    end select
  end function tc_circle_radius

  pure subroutine tc_v_range(self, v_min, v_max)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    if (self%tube%section%periodic()) then
      v_min = -huge(1.0_wp); v_max = huge(1.0_wp)
    else
      call self%tube%section%v_range(v_min, v_max)
    end if
  end subroutine tc_v_range

  pure logical function tc_section_varies(self) result(varies)
    class(tube_channel_t), intent(in) :: self
    select type (s => self%tube%section)
    type is (blended_section_t)
      varies = .true.
    class default
      varies = .false.
    end select
  end function tc_section_varies

  function tc_arc_length(self, u) result(s)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: s
    s = self%tube%arc_length(u)
  end function tc_arc_length

  subroutine tc_parameter_at_length(self, s, u, status)
    class(tube_channel_t), intent(in) :: self
    real(wp), intent(in) :: s
    real(wp), intent(out) :: u
    type(status_t), intent(out) :: status
    call self%tube%parameter_at_length(s, u, status)
  end subroutine tc_parameter_at_length

  pure function tc_describe(self) result(text)
    class(tube_channel_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = self%tube%describe()
  end function tc_describe

  pure subroutine tc_parameter_units(self, u_units, v_units)
    class(tube_channel_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    call self%tube%parameter_units(u_units, v_units)
  end subroutine tc_parameter_units
end module water_tube_channel
