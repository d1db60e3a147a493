!> The sphere of radius R about the origin: the ellipsoid with a = b = c = R
!> (thesis 3.57), so it has the ellipsoid's pole charts (surface_t's chart
!> hooks: a body rolling over a pole changes chart as an egg does) and the
!> same numbers an ellipsoid with three equal semi-axes gives.
module geometry_sphere
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_text, only: format_real
  use base_spec, only: spec_t
  use geometry_surface, only: surface_t
  use geometry_surface_kind, only: surface_kind_t
  use geometry_elementary, only: ellipsoid_t
  use geometry_elementary_kinds, only: semi_axis
  implicit none (type, external)
  private
  public :: sphere_t, new_sphere, sphere_kind

  type, extends(ellipsoid_t) :: sphere_t
    private
    real(wp) :: radius = 1   ! m
  contains
    procedure :: describe => sphere_describe
  end type sphere_t

contains

  function new_sphere(radius, status) result(s)
    real(wp), intent(in) :: radius
    type(status_t), intent(out) :: status
    type(sphere_t) :: s
    s%ellipsoid_t = ellipsoid_t(radius, radius, radius, status)
    s%radius = radius
    if (.not. status%ok()) status%message = 'sphere: radius'//status%message(index(status%message, ' = '):)
  end function new_sphere

  pure function sphere_describe(self) result(text)
    class(sphere_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = 'sphere radius = '//format_real(self%radius)//' m'
  end function sphere_describe

  function sphere_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'sphere'
    kind%meaning = 'the sphere of radius R about the origin (the ellipsoid a = b = c = R, with its pole charts)'
    kind%parameters = [semi_axis('radius', 'radius', required=.true.)]
    kind%build => build_sphere
  end function sphere_kind

  subroutine build_sphere(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=new_sphere(spec%value('radius'), status))
  end subroutine build_sphere
end module geometry_sphere
