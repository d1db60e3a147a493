!> Every shipped geometry built through the library, without io (issue 24,
!> point 2): inputs/geometry/*.nml, inputs/demo_slide/slide.nml (the demo
!> slide of the ride, water, sweep, identification and sled inputs and of
!> builtin:demo_slide, the default run's), inputs/design/second_slide.nml,
!> (second_slide_water.nml's), the parts' slides (inputs/parts/*_slide.nml:
!> drop, halfpipe, bowl, bowl_table, crest, jump, funnel, patch, bowl_halfpipe) and
!> inputs/templates/geometry.nml; the list is tests/library/
!> built_through_library.txt's. Each description is written by hand from
!> its input file (the same values, in the same arithmetic as the reader:
!> degrees times pi/180; the slides of standard elements in tests/library/
!> shipped_slides.f90, shared with library_without_io), the B-spline's
!> points and the patch's offsets read from their CSV files by plain
!> Fortran. This program links the geometry layer only (tests/
!> CMakeLists.txt: no io module, no HDF5).
!>
!>     shipped_geometries [FOLDER]
!>
!> Builds every surface (exit status 1 if one fails). With FOLDER it writes
!> FOLDER/NAME.txt per input: n_u and n_v of the input's &grid, the grid's u
!> and v values (evenly spaced over the domain by base_grid, as the geometry
!> scenario spaces them) and x, y, z of every grid point. tests/geometry/
!> shipped_geometries.sh compares these with the result files slidesim
!> writes for the same inputs: the same build path, so the same numbers.
program shipped_geometries
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_grid, only: evenly_spaced
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use geometry_slide_builder, only: section_part_description_t
  use geometry_description, only: geometry_description_t, patch_description_t, build_geometry
  use shipped_slides, only: element, circle, demo_slide, template_slide, second_slide, drop_slide, &
    halfpipe_slide, bowl_slide, bowl_table_slide, crest_slide, jump_slide, funnel_slide, patch_slide, &
    bowl_halfpipe_slide
  implicit none (type, external)

  character(len=4096) :: folder
  integer :: failures

  failures = 0
  folder = ''
  if (command_argument_count() >= 1) call get_command_argument(1, folder)
  call put('geometry_blend_cylinders', blend_cylinders(), 85, 31)
  call put('geometry_blend_paraboloids', blend_paraboloids(), 81, 21)
  call put('geometry_bspline_bump', bspline_bump(), 61, 51)
  call put('geometry_demo_slide_table', demo_slide(), 600, 36)
  call put('geometry_flume', flume(), 400, 48)
  call put('geometry_helix_tube', helix_tube(), 400, 48)
  call put('geometry_points_tube', points_tube(), 400, 48)
  call put('geometry_tube_blend_fig3_11', tube_blend_fig3_11(), 90, 36)
  call put('demo_slide_slide', demo_slide(), 600, 36)
  call put('design_second_slide', second_slide(), 600, 36)
  call put('parts_drop_slide', drop_slide(), 600, 36)
  call put('parts_halfpipe_slide', halfpipe_slide(), 600, 48)
  call put('parts_bowl_slide', bowl_slide(), 800, 36)
  call put('parts_bowl_table_slide', bowl_table_slide(), 800, 36)
  call put('parts_crest_slide', crest_slide(), 400, 36)
  call put('parts_jump_slide', jump_slide(), 400, 36)
  call put('parts_funnel_slide', funnel_slide(), 800, 36)
  call put('parts_patch_slide', patch_slide(), 800, 48)
  call put('parts_bowl_halfpipe_slide', bowl_halfpipe_slide(), 800, 36)
  call put('templates_geometry', template_slide(), 400, 48)
  if (failures > 0) then
    print '(i0, a)', failures, ' shipped geometries not built'
    error stop 1
  end if
  print '(a)', 'every shipped geometry built'

contains

  !> Builds `d`; with a folder, writes its grid to FOLDER/NAME.txt.
  subroutine put(name, d, n_u, n_v)
    character(len=*), intent(in) :: name
    type(geometry_description_t), intent(in) :: d
    integer, intent(in) :: n_u, n_v
    class(surface_t), allocatable :: surface
    type(status_t) :: status
    real(wp) :: u_min, u_max, v_min, v_max
    real(wp), allocatable :: u(:), v(:), x(:, :), y(:, :), z(:, :)
    integer :: unit, i, j
    call build_geometry(d, surface, status)
    if (.not. status%ok()) then
      print '(a)', 'FAIL '//name//': '//status%text()
      failures = failures + 1
      return
    end if
    if (len_trim(folder) == 0) return
    call surface%domain(u_min, u_max, v_min, v_max)
    u = evenly_spaced(u_min, u_max, n_u)
    v = evenly_spaced(v_min, v_max, n_v)
    allocate (x(n_v, n_u), y(n_v, n_u), z(n_v, n_u))
    call surface%points_on_grid(u, v, x, y, z, status)
    if (.not. status%ok()) then
      print '(a)', 'FAIL '//name//' grid: '//status%text()
      failures = failures + 1
      return
    end if
    open (newunit=unit, file=trim(folder)//'/'//name//'.txt', status='replace', action='write')
    write (unit, '(i0, 1x, i0)') n_u, n_v
    write (unit, '(es25.17e3)') u
    write (unit, '(es25.17e3)') v
    do i = 1, n_u
      do j = 1, n_v
        write (unit, '(3(1x, es25.17e3))') x(j, i), y(j, i), z(j, i)
      end do
    end do
    close (unit)
  end subroutine put

  ! ----------------------------------------------------------- the inputs
  ! (the slides of standard elements: tests/library/shipped_slides.f90)

  !> inputs/geometry/flume.nml
  function flume() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%elements = [ &
      element('straight', 5.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 6.0_wp, 6.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('straight', 5.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = [section_part_description_t(kind='flume', radius=0.52_wp, wall=0.164_wp, &
                                                         joint_width=2.8648_wp*pi/180)]
  end function flume

  !> inputs/geometry/helix_tube.nml
  function helix_tube() result(d)
    type(geometry_description_t) :: d
    d%kind = 'tube'
    d%slide%centerline%kind = 'helix'
    d%slide%centerline%center = [0.0_wp, 0.0_wp, 5.0_wp]
    d%slide%centerline%radius = 4.0_wp
    d%slide%centerline%rise_per_turn = -2.5_wp
    d%slide%centerline%turns = 1.5_wp
    d%slide%centerline%phase = -90.0_wp*pi/180
    d%slide%section%parts = circle(0.5_wp)
  end function helix_tube

  !> inputs/geometry/points_tube.nml
  function points_tube() result(d)
    type(geometry_description_t) :: d
    d%kind = 'tube'
    d%slide%centerline%kind = 'points'
    d%slide%centerline%points = reshape([0.0_wp, 0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, -0.2_wp, 4.0_wp, 1.0_wp, &
      -0.4_wp, 6.0_wp, 3.0_wp, -0.6_wp, 7.0_wp, 5.0_wp, -0.8_wp, 7.5_wp, 7.0_wp, -1.0_wp], [3, 6])
    d%slide%centerline%horizon_points = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.1_wp, 1.0_wp, 0.0_wp, &
      0.2_wp, 1.0_wp, -0.2_wp, 0.2_wp, 1.0_wp, -0.3_wp, 0.1_wp, 1.0_wp, -0.3_wp, 0.0_wp, 1.0_wp], [3, 6])
    d%slide%centerline%start_tangent = [1.0_wp, 0.0_wp, -0.1_wp]
    d%slide%section%parts = circle(0.5_wp)
  end function points_tube

  !> inputs/geometry/tube_blend_fig3_11.nml
  function tube_blend_fig3_11() result(d)
    type(geometry_description_t) :: d
    d%kind = 'tube'
    d%slide%centerline%kind = 'line'
    d%slide%centerline%start = [0.0_wp, 0.0_wp, 0.0_wp]
    d%slide%centerline%end = [9.0_wp, 0.0_wp, 0.0_wp]
    d%slide%centerline%horizon = [0.0_wp, 0.0_wp, 1.0_wp]
    d%slide%section%parts = [section_part_description_t(kind='circle', radius=0.5_wp), &
                             section_part_description_t(kind='circle', radius=1.0_wp)]
    d%slide%section%transition_midpoint = [4.5_wp]
    d%slide%section%transition_end = [6.0_wp]
  end function tube_blend_fig3_11

  !> inputs/geometry/blend_cylinders.nml
  function blend_cylinders() result(d)
    type(geometry_description_t) :: d
    d%kind = 'blended'
    d%blended%patches = [ &
      patch_description_t(kind='elliptic_cylinder', a=1.0_wp, b=1.0_wp, angles_deg=[90.0_wp, -40.0_wp, -90.0_wp], &
                          u_min=-4.0_wp, u_max=-0.9_wp, v_min=0.0_wp, v_max=3.141592653589793_wp), &
      patch_description_t(kind='elliptic_cylinder', a=1.0_wp, b=2.0_wp, angles_deg=[0.0_wp, 180.0_wp, 0.0_wp], &
                          u_min=3.7_wp, u_max=4.6_wp, v_min=1.5_wp, v_max=-1.5_wp, swap_uv=.true.)]
    d%blended%transition = [0.2_wp]
    d%blended%midpoint = [3.2_wp]
    d%blended%u_99 = [3.3_wp]
  end function blend_cylinders

  !> inputs/geometry/blend_paraboloids.nml
  function blend_paraboloids() result(d)
    type(geometry_description_t) :: d
    real(wp), parameter :: a = 2.9154759474226504_wp
    integer :: i
    d%kind = 'blended'
    allocate (d%blended%patches(3))
    do i = 1, 3
      d%blended%patches(i) = patch_description_t(kind='elliptic_paraboloid', a=a, b=a, &
                                                 origin=[3.0_wp*(i - 1), 0.0_wp, 0.0_wp], &
                                                 angles_deg=[180.0_wp, 0.0_wp, 0.0_wp], u_min=-1.0_wp, &
                                                 u_max=1.0_wp, v_min=-1.0_wp, v_max=1.0_wp)
    end do
    d%blended%transition = [1.0_wp, 1.0_wp]
    d%blended%midpoint = [2.5_wp, 5.5_wp]
    d%blended%u_99 = [3.0_wp, 6.0_wp]
  end function blend_paraboloids

  !> inputs/geometry/bspline_bump.nml: its points from bump_grid.csv (x, y,
  !> z per line after the comment and the header).
  function bspline_bump() result(d)
    type(geometry_description_t) :: d
    character(len=256) :: line
    real(wp) :: row(3), rows(3, 1000)
    integer :: unit, n, outcome
    d%kind = 'bspline'
    d%bspline%layout = 'grid'
    d%bspline%smoothing = 0.0_wp
    d%bspline%degree = 5
    n = 0
    open (newunit=unit, file='inputs/geometry/bump_grid.csv', status='old', action='read')
    do
      read (unit, '(a)', iostat=outcome) line
      if (outcome /= 0) exit
      if (line(1:1) == '#' .or. line(1:1) == 'x') cycle
      read (line, *) row
      n = n + 1
      rows(:, n) = row
    end do
    close (unit)
    d%bspline%table = rows(:, :n)
  end function bspline_bump
end program shipped_geometries
