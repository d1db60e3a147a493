!> Scenario `geometry`: builds a surface from the geometry groups (a tube, a
!> slide from standard elements, a blended surface) and writes to HDF5 a
!> surface grid for plotting and, for every slide (a surface answering the
!> slide query: tubes, slides of elements), the centerline, the frames along
!> it, the curvature chi, its derivative chi_u and the arc length.
!> Layout and units: docs/geometry.md.
module scenarios_geometry
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, prefix_status
  use base_log, only: log_info
  use geometry_surface, only: surface_t
  use geometry_curve, only: curve_point_t
  use geometry_curve_frame, only: curve_frame_t
  use geometry_slide_query, only: slide_surface_t
  use io_input, only: input_text_t, check_known_groups, group_reader_t, open_group, format_real
  use io_run_config, only: run_config_t
  use io_geometry_config, only: read_geometry_description, explain_geometry_failure, geometry_groups
  use geometry_description, only: geometry_description_t, build_geometry
  use io_hdf5, only: result_file_t, run_outcome
  use io_summary, only: summary_t, engineering
  use io_surface_grid, only: write_surface_grid
  use base_grid, only: evenly_spaced
  use io_xdmf, only: xdmf_t
  use scenarios_report, only: end_report
  implicit none (type, external)
  private
  public :: run_geometry, geometry_scenario_groups

  character(len=*), parameter :: geometry_scenario_groups(8) = [character(len=14) :: 'run', &
    geometry_groups, 'grid']
  !> most points of the written surface grid
  real(wp), parameter :: max_grid_points = 2e7_wp

contains

  subroutine run_geometry(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    class(surface_t), allocatable :: surface
    type(geometry_description_t) :: description
    character(len=:), allocatable :: part, variable, bspline_file
    type(status_t) :: built
    type(result_file_t) :: file
    type(status_t) :: work
    integer :: n_u, n_v, n_frames
    type(summary_t) :: summary
    type(xdmf_t) :: xdmf
    logical :: complete
    character(len=:), allocatable :: message

    call check_known_groups(input, geometry_scenario_groups, status)
    if (status%ok()) call read_grid(input, n_u, n_v, n_frames, status)
    if (status%ok()) call read_geometry_description(input, description, status, bspline_file=bspline_file)
    if (status%ok()) call build_geometry(description, surface, built, part, variable)
    if (status%ok()) call explain_geometry_failure(input, built, part, variable, bspline_file, status)
    if (.not. status%ok() .or. run%check_only) return
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call log_info('geometry: ' // surface%describe())

    call file%write_provenance('geometry', trim(run%title), input%name, input%text(), work)
    call file%set_attribute('/', 'surface', surface%describe(), work)
    if (work%ok()) call write_grid(file, surface, n_u, n_v, work)
    call summary%start('geometry', 'slidesim geometry: '//surface%describe())
    call summary%add_count('grid_n_u', 'surface grid along u', n_u, 'points')
    call summary%add_count('grid_n_v', 'surface grid along v', n_v, 'points')
    select type (surface)
    class is (slide_surface_t)
      if (work%ok()) call write_centerline(file, surface, n_frames, summary, work)
    end select
    if (.not. work%ok()) call prefix_status(work, 'geometry')
    complete = work%ok()
    message = work%text()
    if (work%ok()) then   ! (the view of datasets that were written)
      call xdmf%start()
      call xdmf%surface(file, 'surface', '/geometry/surface')
      call xdmf%polyline(file, 'centerline', '/geometry/centerline/points', '/geometry/centerline')
      call xdmf%attach(file, work)
    end if
    call file%finish(complete, message, work)
    complete = complete .and. work%ok()   ! finish refuses a file with NaN or Inf
    call summary%print()
    call end_report(summary, run, file%final_path(), complete, message, work)
    if (.not. work%ok()) status = run_outcome(work, status_t())
  end subroutine run_geometry

  !> &grid: resolution of the written surface grid and of the centerline samples.
  subroutine read_grid(input, n_u, n_v, n_frames, status)
    type(input_text_t), intent(in) :: input
    integer, intent(out) :: n_u, n_v, n_frames
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    n_u = 400; n_v = 48; n_frames = 400
    call open_group(input, 'grid', r, status)
    call r%get('n_u', n_u, status)
    call r%get('n_v', n_v, status)
    call r%get('n_frames', n_frames, status)
    ! x, y, z of every grid point are held in memory at once
    if (status%ok() .and. real(n_u, wp)*n_v > max_grid_points) &
      call r%invalid('n_u, n_v', format_integer(n_u)//', '//format_integer(n_v), 'the grid would have '// &
                     format_real(real(n_u, wp)*n_v)//' points, more than '//format_real(max_grid_points)// &
                     ' ('//format_integer(nint(max_grid_points*24/1024**2))//' MB of coordinates)', status)
  end subroutine read_grid

  subroutine write_grid(file, surface, n_u, n_v, status)
    type(result_file_t), intent(inout) :: file
    class(surface_t), intent(in) :: surface
    integer, intent(in) :: n_u, n_v
    type(status_t), intent(inout) :: status
    real(wp) :: u_min, u_max, v_min, v_max
    call surface%domain(u_min, u_max, v_min, v_max)
    call write_surface_grid(file, surface, evenly_spaced(u_min, u_max, n_u), evenly_spaced(v_min, v_max, n_v), &
                            status, log_info)
  end subroutine write_grid

  !> The centerline samples, and its length, drop and curvature in the summary.
  subroutine write_centerline(file, slide, n, summary, status)
    type(result_file_t), intent(inout) :: file
    class(slide_surface_t), intent(in) :: slide
    integer, intent(in) :: n
    type(summary_t), intent(inout) :: summary
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: u(:), s(:), points(:, :), xa(:, :), ya(:, :), za(:, :), chi(:), chi_u(:), &
      tangent_speed(:)
    real(wp) :: u_min, u_max, v_min, v_max
    type(curve_frame_t) :: f
    type(curve_point_t) :: c
    integer :: i
    character(len=:), allocatable :: speed_units, chi_u_units, u_unit, v_unit
    call slide%domain(u_min, u_max, v_min, v_max)
    call slide%parameter_units(u_unit, v_unit)
    select case (u_unit)   ! units of ds/du and d chi/du
    case ('m'); speed_units = '1'; chi_u_units = 'm^-2'
    case ('1'); speed_units = 'm'; chi_u_units = 'm^-1'
    case default
      speed_units = 'm/'//u_unit
      chi_u_units = 'm^-1 '//u_unit//'^-1'
    end select
    allocate (u(n), s(n), points(3, n), xa(3, n), ya(3, n), za(3, n), chi(n), chi_u(n), tangent_speed(n))
    do i = 1, n
      u(i) = u_min + (u_max - u_min)*(i - 1)/real(n - 1, wp)
      call slide%frame(u(i), 2, f, status, c)
      if (.not. status%ok()) return
      s(i) = slide%arc_length(u(i))
      points(:, i) = c%d(:, 0)
      tangent_speed(i) = norm2(c%d(:, 1))
      xa(:, i) = f%x(:, 0); ya(:, i) = f%y(:, 0); za(:, i) = f%z(:, 0)
      chi(i) = f%chi; chi_u(i) = f%chi_u
    end do
    call file%write_vector('/geometry/centerline/u', u, u_unit, &
                           'centerline parameter u (horizontal arc length in m for slides)', status)
    call file%write_vector('/geometry/centerline/arc_length', s, 'm', 'arc length s(u) from the start', status)
    call file%write_matrix('/geometry/centerline/points', points, 'm', 'c(u) (3 x n)', status)
    call file%write_vector('/geometry/centerline/speed', tangent_speed, speed_units, '|c_u| = ds/du', status)
    call file%write_matrix('/geometry/centerline/frame_x', xa, '1', 'frame x axis (tangent, 3.61) (3 x n)', status)
    call file%write_matrix('/geometry/centerline/frame_y', ya, '1', 'frame y axis (3.62) (3 x n)', status)
    call file%write_matrix('/geometry/centerline/frame_z', za, '1', 'frame z axis (3.63) (3 x n)', status)
    call file%write_vector('/geometry/centerline/chi', chi, 'm^-1', 'centerline curvature chi (4.8)', status)
    call file%write_vector('/geometry/centerline/chi_u', chi_u, chi_u_units, 'd chi/du (4.9)', status)
    call file%write_scalar('/geometry/centerline/length', slide%length(), 'm', 'total centerline length', status)
    call file%make_scale('/geometry/centerline/arc_length', status)
    call file%attach_scale('/geometry/centerline/arc_length', '/geometry/centerline', status)
    call file%attach_components('/geometry/centerline', status)
    call summary%add('centerline_length', 'centerline length', slide%length(), 'm')
    call summary%add('drop', 'height drop', points(3, 1) - points(3, n), 'm')
    if (maxval(chi) > 1e-9_wp) then
      call summary%add('curvature_max', 'curvature max', maxval(chi), 'm^-1', '1/m (radius '// &
                       engineering(1/maxval(chi))//' m)')
    else
      call summary%add('curvature_max', 'curvature max', maxval(chi), 'm^-1', '1/m (straight)')
    end if
  end subroutine write_centerline
end module scenarios_geometry
