!> Every surface the geometry groups describe, from one description: a tube
!> or a slide (geometry_slide_builder's slide_description_t), a blended
!> surface of placed elementary patches, or a B-spline surface fitted to a
!> table of points. `build_geometry` builds the one the description names.
!> The namelist reader (io_geometry_config) fills these descriptions from
!> &geometry, &centerline, &slide_elements, &cross_section, &blended and
!> &bspline after checking every value; a library caller fills them
!> directly. The defaults are the input defaults (docs/inputs.md).
!>
!> What is refused here is only what the geometry itself cannot build; the
!> failure names the part of the description (the input group) and, where
!> one value is at fault, the variable, so that a reader can say where the
!> input gave it.
module geometry_description
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t
  use geometry_tube, only: tube_surface_t
  use geometry_slide_builder, only: slide_description_t, build_slide
  use geometry_blended_surface, only: blended_surface_t, blend_patch_t, new_blended_surface
  use geometry_elementary, only: ellipsoid_t, paraboloid_t, elliptic_cylinder_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_from_table
  implicit none (type, external)
  private
  public :: patch_description_t, blended_description_t, bspline_description_t, geometry_description_t
  public :: build_geometry, build_blended, build_bspline

  !> One patch of a blended surface: an elementary surface ('ellipsoid',
  !> 'elliptic_paraboloid', 'hyperbolic_paraboloid', 'elliptic_cylinder')
  !> with semi-axes a, b (and c for the ellipsoid), placed at `origin`,
  !> turned by the Cardan angles `angles_deg` (R = Rx Ry Rz), and cut to
  !> [u_min, u_max] x [v_min, v_max] of its own parameters.
  type :: patch_description_t
    character(len=24) :: kind = 'ellipsoid'
    real(wp) :: a = 1, b = 1, c = 1               !< m
    real(wp) :: origin(3) = 0                     !< m
    real(wp) :: angles_deg(3) = 0                 !< deg
    real(wp) :: u_min = 0, u_max = 1, v_min = 0, v_max = 1
    logical :: swap_uv = .false.                  !< evaluate the patch at (v, u)
  end type patch_description_t

  !> &blended: the patches blended along u, a transition length between each
  !> two; `midpoint` and `u_99` (both or neither) place the transitions'
  !> logistic explicitly (thesis 3.73-3.79).
  type :: blended_description_t
    type(patch_description_t), allocatable :: patches(:)
    real(wp), allocatable :: transition(:)        !< blend u, one per transition
    real(wp), allocatable :: midpoint(:), u_99(:) !< blend u, one per transition, or not allocated
  end type blended_description_t

  !> &bspline: points (one per column of `table`: x, y, z, or u, v, x, y, z
  !> for the 'parametric' layout) fitted by FITPACK ('scattered', 'grid',
  !> 'parametric').
  type :: bspline_description_t
    character(len=12) :: layout = 'scattered'
    real(wp), allocatable :: table(:, :)
    real(wp) :: smoothing = 0                     !< m^2
    integer :: degree = 3
    logical :: periodic(2) = .false.              !< parametric only: closed in u, v
  end type bspline_description_t

  !> A whole geometry: kind 'tube' or 'slide' (built from `slide`, whose own
  !> kind is taken from here), 'blended' or 'bspline'.
  type :: geometry_description_t
    character(len=8) :: kind = 'slide'
    type(slide_description_t) :: slide
    type(blended_description_t) :: blended
    type(bspline_description_t) :: bspline
  end type geometry_description_t

contains

  !> The surface of description `d`. On failure `part` names the part of the
  !> description at fault (the input group: 'centerline', 'slide_elements',
  !> 'cross_section', 'blended', 'bspline'; a tube that folds or passes
  !> through itself: 'centerline cross_section' or 'slide_elements
  !> cross_section') and `variable` the value at fault ('' when none).
  subroutine build_geometry(d, surface, status, part, variable)
    type(geometry_description_t), intent(in) :: d
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    character(len=:), allocatable, intent(out), optional :: part, variable
    type(slide_description_t) :: slide
    type(tube_surface_t) :: tube
    type(blended_surface_t) :: blend
    type(bspline_surface_t) :: fitted
    character(len=:), allocatable :: failed_part, failed_variable
    failed_part = trim(d%kind)
    failed_variable = ''
    if (present(part)) part = failed_part
    if (present(variable)) variable = failed_variable
    if (.not. status%ok()) return
    select case (trim(d%kind))
    case ('tube', 'slide')
      slide = d%slide
      slide%kind = d%kind
      call build_slide(slide, tube, status, failed_part, failed_variable)
      if (status%ok()) allocate (surface, source=tube)
    case ('blended')
      call build_blended(d%blended, blend, status)
      if (status%ok()) allocate (surface, source=blend)
    case ('bspline')
      call build_bspline(d%bspline, fitted, status)
      if (status%ok()) allocate (surface, source=fitted)
    case default
      call set_status(status, STATUS_INVALID_INPUT, 'geometry: kind '''//trim(d%kind)// &
                      ''' is not one of tube, slide, blended, bspline')
    end select
    if (present(part)) part = failed_part
    if (present(variable)) variable = failed_variable
  end subroutine build_geometry

  !> The blended surface of `d`.
  subroutine build_blended(d, blend, status)
    type(blended_description_t), intent(in) :: d
    type(blended_surface_t), intent(out) :: blend
    type(status_t), intent(inout) :: status
    type(blend_patch_t), allocatable :: patches(:)
    class(surface_t), allocatable :: base
    type(patch_description_t) :: p
    integer :: i
    if (.not. (allocated(d%patches) .and. allocated(d%transition))) then
      call set_status(status, STATUS_INVALID_INPUT, 'blended surface: no patches or no transitions')
      return
    end if
    allocate (patches(size(d%patches)))
    do i = 1, size(d%patches)
      p = d%patches(i)
      select case (trim(p%kind))
      case ('ellipsoid'); base = ellipsoid_t(p%a, p%b, p%c, status)
      case ('elliptic_paraboloid'); base = paraboloid_t(p%a, p%b, 1.0_wp, status)
      case ('hyperbolic_paraboloid'); base = paraboloid_t(p%a, p%b, -1.0_wp, status)
      case ('elliptic_cylinder'); base = elliptic_cylinder_t(p%a, p%b, status)
      case default
        call set_status(status, STATUS_INVALID_INPUT, 'blended surface: patch kind '''//trim(p%kind)// &
                        ''' is not one of ellipsoid, elliptic_paraboloid, hyperbolic_paraboloid, elliptic_cylinder')
      end select
      if (status%ok()) allocate (patches(i)%surface, source=placed_surface_t(base, p%origin, status, &
                                                                             angles=p%angles_deg*pi/180))
      if (.not. status%ok()) return
      patches(i)%u_min = p%u_min; patches(i)%u_max = p%u_max
      patches(i)%v_min = p%v_min; patches(i)%v_max = p%v_max
      patches(i)%swap_uv = p%swap_uv
    end do
    if (allocated(d%midpoint) .and. allocated(d%u_99)) then
      blend = new_blended_surface(patches, d%transition, status, midpoint=d%midpoint, u_99=d%u_99)
    else
      blend = new_blended_surface(patches, d%transition, status)
    end if
  end subroutine build_blended

  !> The B-spline surface fitted to `d`'s table.
  subroutine build_bspline(d, fitted, status)
    type(bspline_description_t), intent(in) :: d
    type(bspline_surface_t), intent(out) :: fitted
    type(status_t), intent(inout) :: status
    if (.not. allocated(d%table)) then
      call set_status(status, STATUS_INVALID_INPUT, 'B-spline surface: no points')
      return
    end if
    call bspline_from_table(trim(d%layout), d%table, d%smoothing, d%degree, d%periodic, fitted, status)
  end subroutine build_bspline
end module geometry_description
