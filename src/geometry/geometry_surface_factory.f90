!> The surface kinds inputs name (&surface, &shape `kind`), in one registry:
!> a kind (geometry_surface_kind: a name, its parameters declared once, a
!> builder) is registered once, and `surface_from_spec` builds a surface of
!> any registered kind from a spec (base_spec: the kind's name and its
!> parameters' values), placed in space if asked. io reads a kind's
!> parameters by the declarations `surface_kinds` lists. The surfaces
!> described by their own groups (tube, slide, blended, bspline:
!> geometry_description's build_geometry) are not kinds of this registry.
!>
!> Adding a kind: one module with the surface and a function returning its
!> surface_kind_t, and one line in `register_builtin_surfaces` (or, from
!> outside the library, one call of `register_surface_kind` before the input
!> is read). docs/DESIGN.md, "How to add a surface kind".
!>
!> The registry is the one module variable of the layer: kinds, not
!> simulation state, with their index by name (base_kind_index). Every read
!> and change of it (the built-in kinds on first use, a registration, a
!> look-up) runs inside one OpenMP critical section, so a kind registered
!> while another thread builds is seen whole or not at all; a build copies
!> its kind and runs outside it.
module geometry_surface_factory
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t, complete_spec
  use base_kind_index, only: kind_index_t
  use geometry_surface, only: surface_t
  use geometry_surface_kind, only: surface_kind_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_elementary_kinds, only: plane_kind, ellipsoid_kind, elliptic_paraboloid_kind, &
    hyperbolic_paraboloid_kind, elliptic_cylinder_kind, apex_paraboloid_kind
  use geometry_sphere, only: sphere_kind
  use geometry_revolution, only: cone_kind, sphere_zone_kind, revolution_kind
  implicit none (type, external)
  private
  public :: register_surface_kind, surface_kinds, surface_kind_index, surface_from_spec, place_surface

  type(surface_kind_t), allocatable, save :: registry(:)
  type(kind_index_t), save :: names   !< registry(k)%name is names' k-th

contains

  !> The kinds every build knows, in the order inputs list them (inside the
  !> critical section, on first use).
  subroutine ensure_builtins()
    type(status_t) :: status
    integer :: k
    if (allocated(registry)) return
    registry = [plane_kind(), ellipsoid_kind(), elliptic_paraboloid_kind(), hyperbolic_paraboloid_kind(), &
                elliptic_cylinder_kind(), apex_paraboloid_kind(), sphere_kind(), cone_kind(), sphere_zone_kind(), &
                revolution_kind()]
    do k = 1, size(registry)
      call names%add(registry(k)%name, 'surface kind', status)
    end do
  end subroutine ensure_builtins

  !> Adds a kind; refused if its name is taken or empty, or it has no builder.
  subroutine register_surface_kind(kind, status)
    type(surface_kind_t), intent(in) :: kind
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (.not. associated(kind%build) .or. len_trim(kind%name) == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'surface kind '''//kind%name//''': a kind needs a name and '// &
                      'a builder')
      return
    end if
    !$omp critical (surface_kind_registry)
    call ensure_builtins()
    call names%add(kind%name, 'surface kind', status)
    if (status%ok()) registry = [registry, kind]
    !$omp end critical (surface_kind_registry)
  end subroutine register_surface_kind

  !> Every registered kind (their names, parameters and meanings).
  function surface_kinds() result(kinds)
    type(surface_kind_t), allocatable :: kinds(:)
    !$omp critical (surface_kind_registry)
    call ensure_builtins()
    kinds = registry
    !$omp end critical (surface_kind_registry)
  end function surface_kinds

  !> The index of the kind `name` in surface_kinds(), 0 if unknown.
  integer function surface_kind_index(name) result(k)
    character(len=*), intent(in) :: name
    !$omp critical (surface_kind_registry)
    call ensure_builtins()
    k = names%find(name)
    !$omp end critical (surface_kind_registry)
  end function surface_kind_index

  !> The surface of `spec`, checked against its kind's declarations (defaults
  !> filled in), placed by `origin` (m) and the Cardan angles `angles_deg`
  !> (r -> origin + Rx Ry Rz r) if they are given and not zero.
  subroutine surface_from_spec(spec, surface, status, origin, angles_deg)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: origin(3), angles_deg(3)
    class(surface_t), allocatable :: local
    type(spec_t) :: completed
    type(surface_kind_t) :: kind
    character(len=:), allocatable :: known
    integer :: k
    if (.not. status%ok()) return
    !$omp critical (surface_kind_registry)
    call ensure_builtins()
    k = names%find(spec%kind)
    if (k > 0) then
      kind = registry(k)
    else
      known = names%listing()
    end if
    !$omp end critical (surface_kind_registry)
    if (k == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'unknown surface kind '''//spec%kind//'''; the kinds are'//known)
      return
    end if
    completed = spec
    call complete_spec(completed, kind%parameters, 'surface '''//spec%kind//'''', status)
    if (status%ok()) call kind%build(completed, local, status)
    if (.not. status%ok()) return
    call place_surface(local, surface, status, origin, angles_deg)
  end subroutine surface_from_spec

  !> `local` placed by `origin` and `angles_deg` (as surface_from_spec), or
  !> itself (moved) where both are absent or zero.
  subroutine place_surface(local, surface, status, origin, angles_deg)
    class(surface_t), allocatable, intent(inout) :: local
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: origin(3), angles_deg(3)
    real(wp) :: at(3), angles(3)
    if (.not. status%ok()) return
    at = 0
    angles = 0
    if (present(origin)) at = origin
    if (present(angles_deg)) angles = angles_deg
    if (all(at == 0) .and. all(angles == 0)) then
      call move_alloc(local, surface)
    else
      surface = placed_surface_t(local, at, status, angles=angles*pi/180)
    end if
  end subroutine place_surface
end module geometry_surface_factory
