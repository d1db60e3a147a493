!> Any surface from one description: a kind of the geometry's registry by
!> its spec (geometry_surface_factory), or a tube, slide, blended or B-spline
!> surface by its geometry description (geometry_description), placed in
!> space by `origin` and the Cardan angles `angles_deg` (r -> origin +
!> Rx Ry Rz r). The namelist reader (io_surface_config) fills it from
!> &surface (or the contact scenario's &shape) and the geometry groups; a
!> library caller fills it directly. `build_surface` builds it.
module geometry_surface_description
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_spec, only: spec_t
  use geometry_surface, only: surface_t
  use geometry_surface_factory, only: surface_from_spec, place_surface
  use geometry_description, only: geometry_description_t, build_geometry
  implicit none (type, external)
  private
  public :: surface_description_t, build_surface

  !> `geometry` allocated: that surface; otherwise the one of `spec`.
  type :: surface_description_t
    type(spec_t) :: spec
    type(geometry_description_t), allocatable :: geometry
    real(wp) :: origin(3) = 0                     !< m
    real(wp) :: angles_deg(3) = 0                 !< deg
  end type surface_description_t

contains

  !> The surface of `d`, placed. On failure `part` names what is at fault:
  !> 'kind' (the spec), 'origin' (the placement), or the part of the
  !> geometry description (build_geometry's `part`, with its `variable`).
  subroutine build_surface(d, surface, status, part, variable)
    type(surface_description_t), intent(in) :: d
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out), optional :: part, variable
    class(surface_t), allocatable :: local
    character(len=:), allocatable :: failed_part, failed_variable
    failed_part = 'kind'
    failed_variable = ''
    if (status%ok()) then
      if (allocated(d%geometry)) then
        call build_geometry(d%geometry, local, status, failed_part, failed_variable)
      else
        call surface_from_spec(d%spec, local, status)
      end if
      if (status%ok()) then
        failed_part = 'origin'
        call place_surface(local, surface, status, d%origin, d%angles_deg)
      end if
    end if
    if (present(part)) part = failed_part
    if (present(variable)) variable = failed_variable
  end subroutine build_surface
end module geometry_surface_description
