!> The shipped slides of standard elements as geometry descriptions written
!> in code (issue 24 point 2: every shipped input through the library
!> without io): each function is one file's &geometry, &slide_elements and
!> &cross_section, the values copied from it, the defaults it does not give
!> the description types' own (the reader's: docs/inputs.md). A patch's
!> offsets and a bowl's table come from the same files the input names,
!> read here by plain Fortran. Used by tests/geometry/shipped_geometries.f90
!> (the surfaces against the geometry scenario's grids) and by
!> tests/library/library_without_io.f90 (the water and the rides on them);
!> both link no io module.
module shipped_slides
  use base_kinds, only: wp
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: section_part_description_t
  use geometry_patch_section, only: patch_grid_t
  use geometry_patch_grid, only: patch_grid_from_points
  use geometry_description, only: geometry_description_t
  implicit none (type, external)
  private
  public :: bowl_halfpipe_slide
  public :: element, circle, demo_slide, template_slide, second_slide, drop_slide, halfpipe_slide, bowl_slide, &
    bowl_table_slide, crest_slide, jump_slide, funnel_slide, patch_slide

contains

  !> One slide element, every value given (the reader's defaults: 0, 'left').
  pure function element(kind, length, slope_deg, radius, angle_deg, direction, turns, drop) result(e)
    character(len=*), intent(in) :: kind, direction
    real(wp), intent(in) :: length, slope_deg, radius, angle_deg, turns, drop
    type(slide_element_t) :: e
    e = slide_element_t(kind=kind, length=length, slope_deg=slope_deg, radius=radius, angle_deg=angle_deg, &
                        direction=direction, turns=turns, drop=drop)
  end function element

  !> A single circle cross-section of radius r.
  pure function circle(r) result(parts)
    real(wp), intent(in) :: r
    type(section_part_description_t) :: parts(1)
    parts(1) = section_part_description_t(kind='circle', radius=r)
  end function circle

  !> inputs/demo_slide/slide.nml (and geometry/demo_slide_table.nml, its
  !> elements from demo_slide/elements.csv; builtin:demo_slide).
  function demo_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%slide%elements%heading_deg = 0.0_wp
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%elements = [ &
      element('straight', 6.0_wp, 12.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 6.0_wp, 5.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('straight', 4.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('helix', 0.0_wp, 0.0_wp, 4.0_wp, 0.0_wp, 'right', 1.0_wp, 2.5_wp), &
      element('straight', 3.0_wp, 7.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 6.0_wp, 6.0_wp, 60.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 6.0_wp, 6.0_wp, 60.0_wp, 'right', 0.0_wp, 0.0_wp), &
      element('runout', 8.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = circle(0.5_wp)
  end function demo_slide

  !> inputs/templates/geometry.nml: four elements, fitted (fit_spacing
  !> 0.125, smoothing 0, degree 5: the defaults, written there),
  !> check_samples 2000.
  function template_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%check_samples = 2000
    d%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%slide%elements%heading_deg = 0.0_wp
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%fit_spacing = 0.125_wp
    d%slide%elements%smoothing = 0.0_wp
    d%slide%elements%degree = 5
    d%slide%elements%elements = [ &
      element('straight', 6.0_wp, 12.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 6.0_wp, 5.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('helix', 0.0_wp, 0.0_wp, 4.0_wp, 0.0_wp, 'right', 1.0_wp, 2.5_wp), &
      element('runout', 8.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = circle(0.5_wp)
  end function template_slide

  !> inputs/design/second_slide.nml
  function second_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 9.0_wp]
    d%slide%elements%heading_deg = 30.0_wp
    d%slide%elements%transition_length = 2.5_wp
    d%slide%elements%elements = [ &
      element('straight', 5.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 7.0_wp, 7.0_wp, 120.0_wp, 'right', 0.0_wp, 0.0_wp), &
      element('helix', 0.0_wp, 0.0_wp, 3.5_wp, 0.0_wp, 'left', 1.25_wp, 2.6_wp), &
      element('straight', 4.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 5.0_wp, 5.0_wp, 75.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 7.0_wp, 1.5_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = circle(0.52_wp)
  end function second_slide

  !> inputs/parts/drop_slide.nml
  function drop_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 14.0_wp]
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('drop', 0.0_wp, 80.0_wp, 8.0_wp, 0.0_wp, 'left', 0.0_wp, 10.0_wp), &
      element('straight', 6.0_wp, 3.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 4.0_wp, 12.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 8.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = circle(0.5_wp)
  end function drop_slide

  !> inputs/parts/halfpipe_slide.nml
  function halfpipe_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 6.0_wp]
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('straight', 6.0_wp, 12.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 5.0_wp, 8.0_wp, 150.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('straight', 6.0_wp, 6.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = [section_part_description_t(kind='flume', radius=2.0_wp, wall=1.5_wp)]
  end function halfpipe_slide

  !> inputs/parts/bowl_slide.nml (the bowl's profile: 'sphere', the default)
  function bowl_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('straight', 12.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('bowl', 0.0_wp, 50.0_wp, 6.0_wp, 0.0_wp, 'left', 1.0_wp, 2.0_wp), &
      element('straight', 10.0_wp, 14.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 8.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = [section_part_description_t(kind='flume', radius=0.6_wp, wall=0.3_wp)]
  end function bowl_slide

  !> inputs/parts/bowl_halfpipe_slide.nml: the worked example of
  !> docs/geometry.md, a half-pipe curve and a spherical bowl in one 2.4 m
  !> flume.
  function bowl_halfpipe_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 14.0_wp]
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('straight', 8.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 4.0_wp, 8.0_wp, 120.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('straight', 4.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('bowl', 0.0_wp, 45.0_wp, 10.0_wp, 0.0_wp, 'left', 0.75_wp, 2.5_wp), &
      element('straight', 10.0_wp, 14.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 8.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = [section_part_description_t(kind='flume', radius=1.2_wp, wall=1.0_wp)]
  end function bowl_halfpipe_slide

  !> inputs/parts/bowl_table_slide.nml: the bowl of bowl_slide with its
  !> profile from a table of 15 points (slope 0: the table gives it).
  function bowl_table_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%slide%elements%heading_deg = 0.0_wp
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('straight', 12.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('bowl', 0.0_wp, 0.0_wp, 6.0_wp, 0.0_wp, 'left', 1.0_wp, 2.0_wp), &
      element('straight', 10.0_wp, 14.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 8.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    associate (bowl => d%slide%elements%elements(2))
      bowl%bowl_profile = 'table'
      bowl%bowl_rho = [1.0_wp, 1.5_wp, 2.0_wp, 2.5_wp, 3.0_wp, 3.5_wp, 4.0_wp, 4.5_wp, 5.0_wp, 5.5_wp, 6.0_wp, &
                       6.5_wp, 7.0_wp, 7.5_wp, 8.0_wp]
      bowl%bowl_z = [0.08_wp, 0.18_wp, 0.32_wp, 0.5_wp, 0.72_wp, 0.98_wp, 1.28_wp, 1.62_wp, 2.0_wp, 2.42_wp, &
                     2.88_wp, 3.38_wp, 3.92_wp, 4.5_wp, 5.12_wp]
    end associate
    d%slide%section%parts = [section_part_description_t(kind='flume', radius=0.6_wp, wall=0.3_wp)]
  end function bowl_table_slide

  !> inputs/parts/crest_slide.nml: a sharp crest (transitions of 1 m).
  function crest_slide() result(d)
    type(geometry_description_t) :: d
    d = straights_and_runout([5.0_wp, 3.0_wp, 8.0_wp, 6.0_wp], [30.0_wp, 2.0_wp, 15.0_wp, 1.0_wp])
  end function crest_slide

  !> inputs/parts/jump_slide.nml: a sharp lip (transitions of 1 m).
  function jump_slide() result(d)
    type(geometry_description_t) :: d
    d = straights_and_runout([5.0_wp, 2.0_wp, 6.0_wp, 6.0_wp], [35.0_wp, 2.0_wp, 20.0_wp, 1.0_wp])
  end function jump_slide

  !> The crest and the jump: three straights and a run-out from [0, 0, 10]
  !> with transitions of 1 m, exact, a circle of 0.5 m.
  function straights_and_runout(length, slope_deg) result(d)
    real(wp), intent(in) :: length(4), slope_deg(4)
    type(geometry_description_t) :: d
    integer :: i
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%slide%elements%heading_deg = 0.0_wp
    d%slide%elements%transition_length = 1.0_wp
    d%slide%elements%exact = .true.
    allocate (d%slide%elements%elements(4))
    do i = 1, 4
      d%slide%elements%elements(i) = element(trim(merge('straight', 'runout  ', i < 4)), length(i), slope_deg(i), &
                                             0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)
    end do
    d%slide%section%parts = circle(0.5_wp)
  end function straights_and_runout

  !> inputs/parts/funnel_slide.nml
  function funnel_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 8.0_wp]
    d%slide%elements%heading_deg = 0.0_wp
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('straight', 10.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 8.0_wp, 5.0_wp, 120.0_wp, 'right', 0.0_wp, 0.0_wp), &
      element('funnel', 20.0_wp, 4.0_wp, 2.4_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('straight', 8.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 8.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%section%parts = [section_part_description_t(kind='flume', radius=0.6_wp, wall=0.5_wp)]
  end function funnel_slide

  !> inputs/parts/patch_slide.nml: element 3 a free-form patch, its offsets
  !> from inputs/parts/patch_offsets.csv (patch_grid).
  function patch_slide() result(d)
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 9.0_wp]
    d%slide%elements%heading_deg = 0.0_wp
    d%slide%elements%transition_length = 2.0_wp
    d%slide%elements%exact = .true.
    d%slide%elements%elements = [ &
      element('straight', 12.0_wp, 10.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 8.0_wp, 5.0_wp, 120.0_wp, 'right', 0.0_wp, 0.0_wp), &
      element('patch', 12.0_wp, 6.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('straight', 8.0_wp, 8.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('curve', 0.0_wp, 8.0_wp, 6.0_wp, 90.0_wp, 'left', 0.0_wp, 0.0_wp), &
      element('runout', 12.0_wp, 2.0_wp, 0.0_wp, 0.0_wp, 'left', 0.0_wp, 0.0_wp)]
    d%slide%elements%patches = [patch_grid('inputs/parts/patch_offsets.csv', 3)]
    d%slide%elements%patches(1)%source = 'patch_file(3) = ''patch_offsets.csv'''
    d%slide%section%parts = circle(0.6_wp)
  end function patch_slide

  !> The grid of a patch from its CSV file (`station, angle, offset` per
  !> line after the comments and the header), built by geometry_patch_grid
  !> (the distinct stations and angles, increasing, and the offset at each);
  !> stops unless the file fills the grid, each point once.
  function patch_grid(path, element_index) result(grid)
    character(len=*), intent(in) :: path
    integer, intent(in) :: element_index
    type(patch_grid_t) :: grid
    character(len=256) :: line
    real(wp) :: rows(3, 10000)
    integer, allocatable :: given(:, :)
    integer :: unit, n, outcome, twice
    n = 0
    open (newunit=unit, file=path, status='old', action='read')
    do
      read (unit, '(a)', iostat=outcome) line
      if (outcome /= 0) exit
      line = adjustl(line)
      if (line(1:1) == '#' .or. line(1:1) == 's' .or. len_trim(line) == 0) cycle
      n = n + 1
      read (line, *) rows(:, n)
    end do
    close (unit)
    call patch_grid_from_points(element_index, rows(:, :n), grid, given, twice)
    if (twice > 0 .or. any(given == 0)) then
      print '(a)', 'FAIL '//path//': the points do not fill the grid, each once'
      error stop 1
    end if
  end function patch_grid
end module shipped_slides
