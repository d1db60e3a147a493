!> &surface: which elementary surface, its size, and where it sits in space.
module io_surface_config
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t, &
                                 apex_paraboloid_t
  use geometry_placed_surface, only: placed_surface_t
  use io_input, only: input_text_t, namelist_read_error, check_positive, check_choice, &
                      check_finite_vector, lower, load_input_file
  use io_geometry_config, only: read_geometry_config
  implicit none (type, external)
  private
  public :: read_surface_config, surface_kinds

  character(len=*), parameter :: surface_kinds(10) = [character(len=21) :: 'plane', 'ellipsoid', &
    'elliptic_paraboloid', 'hyperbolic_paraboloid', 'elliptic_cylinder', 'apex_paraboloid', &
    'tube', 'slide', 'blended', 'bspline']

contains

  !> Builds the surface described by &surface, placed by `origin` and the Cardan
  !> angles `angles_deg` (r -> origin + Rx Ry Rz r). The kinds tube, slide,
  !> blended and bspline are described by the geometry groups (&centerline,
  !> &cross_section, &slide_elements, &blended; io_geometry_config) of the file
  !> `geometry_file` (a path relative to the working directory).
  subroutine read_surface_config(input, built_surface, status)
    type(input_text_t), intent(in) :: input
    class(surface_t), allocatable, intent(out) :: built_surface
    type(status_t), intent(inout) :: status
    character(len=24) :: kind
    character(len=256) :: geometry_file
    type(input_text_t) :: geometry_input
    real(wp) :: a, b, c, point_a(3), point_b(3), point_c(3), origin(3), angles_deg(3)
    class(surface_t), allocatable :: local
    type(status_t) :: built
    character(len=256) :: msg
    integer :: ios
    character(len=*), parameter :: g = 'surface'
    namelist /surface/ kind, a, b, c, point_a, point_b, point_c, origin, angles_deg, geometry_file

    kind = 'plane'
    geometry_file = ''
    a = 1; b = 1; c = 1
    point_a = [0, 0, 0]; point_b = [1, 0, 0]; point_c = [0, 1, 0]
    origin = 0; angles_deg = 0
    read (input%lines, nml=surface, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=13) :: 'kind', 'a', 'b', 'c', 'point_a', &
                               'point_b', 'point_c', 'origin', 'angles_deg', 'geometry_file'], status)
      return
    end if
    call check_choice(input, g, 'kind', kind, surface_kinds, status)
    call check_finite_vector(input, g, 'origin', origin, status)
    call check_finite_vector(input, g, 'angles_deg', angles_deg, status)
    if (.not. status%ok()) return

    select case (lower(adjustl(kind)))
    case ('plane')
      call check_finite_vector(input, g, 'point_a', point_a, status)
      call check_finite_vector(input, g, 'point_b', point_b, status)
      call check_finite_vector(input, g, 'point_c', point_c, status)
      if (status%ok()) local = plane_t(point_a, point_b, point_c, built)
    case ('ellipsoid')
      call check_semi_axes(3)
      if (status%ok()) local = ellipsoid_t(a, b, c, built)
    case ('elliptic_paraboloid', 'hyperbolic_paraboloid')
      call check_semi_axes(2)
      if (status%ok()) local = paraboloid_t(a, b, merge(1.0_wp, -1.0_wp, &
                                            lower(adjustl(kind)) == 'elliptic_paraboloid'), built)
    case ('elliptic_cylinder')
      call check_semi_axes(2)
      if (status%ok()) local = elliptic_cylinder_t(a, b, built)
    case ('apex_paraboloid')
      call check_semi_axes(2)
      if (status%ok()) local = apex_paraboloid_t(a, b, built)
    case ('tube', 'slide', 'blended', 'bspline')
      if (len_trim(geometry_file) == 0) then
        call set_status(status, STATUS_INVALID_INPUT, input%name//': &'//g//': kind = '''// &
                        trim(lower(adjustl(kind)))//''' needs geometry_file = ''<file with the geometry groups>''')
      else
        call load_input_file(input%resolve_path(geometry_file), geometry_input, status)
        if (.not. status%ok()) call prefix_status(status, input%name//': &'//g//': geometry_file = '''// &
                                                  trim(geometry_file)//'''')
        if (status%ok()) call read_geometry_config(geometry_input, local, status, kind=lower(adjustl(kind)))
      end if
    end select
    if (.not. status%ok()) return
    if (.not. built%ok()) then
      status = built
      call prefix_status(status, input%name//': &'//g)
      return
    end if
    if (all(origin == 0) .and. all(angles_deg == 0)) then
      call move_alloc(local, built_surface)
    else
      built_surface = placed_surface_t(local, origin, built, angles=angles_deg*pi/180)
      if (.not. built%ok()) status = built
    end if

  contains

    subroutine check_semi_axes(n)
      integer, intent(in) :: n
      call check_positive(input, g, 'a', a, 'm', status)
      call check_positive(input, g, 'b', b, 'm', status)
      if (n == 3) call check_positive(input, g, 'c', c, 'm', status)
    end subroutine check_semi_axes
  end subroutine read_surface_config
end module io_surface_config
