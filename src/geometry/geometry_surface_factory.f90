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
!> simulation state, kept by base_kind_registry (the force laws' registry is
!> the same), whose one OpenMP critical section covers every read and change
!> of it (the built-in kinds on first use, a registration, a look-up), so a
!> kind registered while another thread builds is seen whole or not at all;
!> a build copies its kind and runs outside it.
module geometry_surface_factory
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t
  use base_kind_registry, only: kind_t, kind_box_t, kind_registry_t, box_kinds
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

  character(len=*), parameter :: WHAT = 'surface kind'
  type(kind_registry_t), save :: registry

contains

  !> The kinds every build knows, in the order inputs list them.
  subroutine builtins(kinds)
    type(kind_box_t), allocatable, intent(out) :: kinds(:)
    type(surface_kind_t), allocatable :: known(:)
    known = [plane_kind(), ellipsoid_kind(), elliptic_paraboloid_kind(), hyperbolic_paraboloid_kind(), &
             elliptic_cylinder_kind(), apex_paraboloid_kind(), sphere_kind(), cone_kind(), sphere_zone_kind(), &
             revolution_kind()]
    ! (assigned first: gfortran 12 frees the components of function results in an
    ! array constructor passed as an argument twice: the run aborts in free)
    call box_kinds(known, kinds)
  end subroutine builtins

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
    call registry%register(builtins, WHAT, kind, status)
  end subroutine register_surface_kind

  !> Every registered kind (their names, parameters and meanings).
  function surface_kinds() result(kinds)
    type(surface_kind_t), allocatable :: kinds(:)
    type(kind_box_t), allocatable :: boxes(:)
    integer :: k
    call registry%copy_all(builtins, WHAT, boxes)
    allocate (kinds(size(boxes)))
    do k = 1, size(boxes)
      select type (kind => boxes(k)%kind)
      type is (surface_kind_t)   ! (every kind registered here is one)
        kinds(k) = kind
      end select
    end do
  end function surface_kinds

  !> The index of the kind `name` in surface_kinds(), 0 if unknown.
  integer function surface_kind_index(name) result(k)
    character(len=*), intent(in) :: name
    k = registry%find(builtins, WHAT, name)
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
    class(kind_t), allocatable :: found
    call registry%copy_completed(builtins, WHAT, spec, 'unknown surface kind', 'surface '''//spec%kind//'''', found, &
                                 completed, status)
    if (.not. status%ok()) return
    select type (found)
    type is (surface_kind_t)
      call found%build(completed, local, status)
    end select
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
