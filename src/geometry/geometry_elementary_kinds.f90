!> The elementary surfaces (geometry_elementary) as kinds inputs name: the
!> plane by three points, the ellipsoid, the elliptic and hyperbolic
!> paraboloids, the elliptic cylinder and the apex paraboloid by their
!> semi-axes (1 mm to 10 km: beyond, 1/a^2 and a^2 leave the range the
!> surface formulas are checked in).
module geometry_elementary_kinds
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_spec, only: spec_t, parameter_t, declare
  use geometry_surface, only: surface_t
  use geometry_surface_kind, only: surface_kind_t
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t, apex_paraboloid_t
  implicit none (type, external)
  private
  public :: plane_kind, ellipsoid_kind, elliptic_paraboloid_kind, hyperbolic_paraboloid_kind, &
    elliptic_cylinder_kind, apex_paraboloid_kind, semi_axis

contains

  !> A semi-axis or radius `name`: 1 mm to 10 km, default 1 m (none: required).
  pure function semi_axis(name, meaning, required) result(p)
    character(len=*), intent(in) :: name, meaning
    logical, intent(in), optional :: required
    type(parameter_t) :: p
    p = declare(name, 'm', 1e-3_wp, 1e4_wp, meaning, default=[1.0_wp])
    if (present(required)) then
      if (required) then
        p%required = .true.
        deallocate (p%default)
      end if
    end if
  end function semi_axis

  function plane_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'plane'
    kind%meaning = 'the plane through three points A, B, C (u along A->B, v along A->C)'
    kind%parameters = [declare('point_a', 'm', -1e6_wp, 1e6_wp, 'point A', default=[0.0_wp, 0.0_wp, 0.0_wp], &
                               count=3), &
                       declare('point_b', 'm', -1e6_wp, 1e6_wp, 'point B', default=[1.0_wp, 0.0_wp, 0.0_wp], &
                               count=3), &
                       declare('point_c', 'm', -1e6_wp, 1e6_wp, 'point C', default=[0.0_wp, 1.0_wp, 0.0_wp], &
                               count=3)]
    kind%build => build_plane
  end function plane_kind

  subroutine build_plane(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=plane_t(spec%vector('point_a'), spec%vector('point_b'), spec%vector('point_c'), &
                                      status))
    if (.not. status%ok()) status%message = status%message//'; change point_a, point_b or point_c'
  end subroutine build_plane

  function ellipsoid_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'ellipsoid'
    kind%meaning = 'the ellipsoid with semi-axes a, b, c along x, y, z (thesis 3.57)'
    kind%parameters = [semi_axis('a', 'semi-axis along x'), semi_axis('b', 'semi-axis along y'), &
                       semi_axis('c', 'semi-axis along z')]
    kind%build => build_ellipsoid
  end function ellipsoid_kind

  subroutine build_ellipsoid(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=ellipsoid_t(spec%value('a'), spec%value('b'), spec%value('c'), status))
  end subroutine build_ellipsoid

  function elliptic_paraboloid_kind() result(kind)
    type(surface_kind_t) :: kind
    kind = paraboloid_kind('elliptic_paraboloid', 'z = x^2/a^2 + y^2/b^2 (thesis 3.58)')
    kind%build => build_elliptic_paraboloid
  end function elliptic_paraboloid_kind

  function hyperbolic_paraboloid_kind() result(kind)
    type(surface_kind_t) :: kind
    kind = paraboloid_kind('hyperbolic_paraboloid', 'z = x^2/a^2 - y^2/b^2 (thesis 3.58)')
    kind%build => build_hyperbolic_paraboloid
  end function hyperbolic_paraboloid_kind

  function elliptic_cylinder_kind() result(kind)
    type(surface_kind_t) :: kind
    kind = paraboloid_kind('elliptic_cylinder', 'the cylinder along z with semi-axes a, b (thesis 3.59)')
    kind%build => build_elliptic_cylinder
  end function elliptic_cylinder_kind

  function apex_paraboloid_kind() result(kind)
    type(surface_kind_t) :: kind
    kind = paraboloid_kind('apex_paraboloid', 'the elliptic paraboloid in polar parameters (a singular apex)')
    kind%build => build_apex_paraboloid
  end function apex_paraboloid_kind

  !> A kind with semi-axes a and b.
  function paraboloid_kind(name, meaning) result(kind)
    character(len=*), intent(in) :: name, meaning
    type(surface_kind_t) :: kind
    kind%name = name
    kind%meaning = meaning
    kind%parameters = [semi_axis('a', 'semi-axis along x'), semi_axis('b', 'semi-axis along y')]
  end function paraboloid_kind

  subroutine build_elliptic_paraboloid(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=paraboloid_t(spec%value('a'), spec%value('b'), 1.0_wp, status))
  end subroutine build_elliptic_paraboloid

  subroutine build_hyperbolic_paraboloid(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=paraboloid_t(spec%value('a'), spec%value('b'), -1.0_wp, status))
  end subroutine build_hyperbolic_paraboloid

  subroutine build_elliptic_cylinder(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=elliptic_cylinder_t(spec%value('a'), spec%value('b'), status))
  end subroutine build_elliptic_cylinder

  subroutine build_apex_paraboloid(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    allocate (surface, source=apex_paraboloid_t(spec%value('a'), spec%value('b'), status))
  end subroutine build_apex_paraboloid
end module geometry_elementary_kinds
