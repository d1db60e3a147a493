!> A kind of surface that inputs name (the &surface and &shape `kind`): its
!> parameters, declared once (base_spec: the reader's checks and the
!> factory's come from them), and its builder. Registered with
!> geometry_surface_factory; docs/DESIGN.md, "How to add a surface kind".
module geometry_surface_kind
  use base_status, only: status_t
  use base_spec, only: spec_t
  use base_kind_registry, only: kind_t
  use geometry_surface, only: surface_t
  implicit none (type, external)
  private
  public :: surface_kind_t, build_surface_i

  !> A kind_t (name, meaning, parameters) with its builder.
  type, extends(kind_t) :: surface_kind_t
    procedure(build_surface_i), pointer, nopass :: build => null()
  end type surface_kind_t

  abstract interface
    !> Builds the surface of a completed spec (every parameter set and in range).
    subroutine build_surface_i(spec, surface, status)
      import :: spec_t, surface_t, status_t
      type(spec_t), intent(in) :: spec
      class(surface_t), allocatable, intent(out) :: surface
      type(status_t), intent(inout) :: status
    end subroutine build_surface_i
  end interface
end module geometry_surface_kind
