!> geometry_slide_builder: slides from description types, the library way the
!> design loop builds them, give the same surface, to the bit, as the
!> namelist reader's (which fills the same descriptions):
!> - the demo slide (a chain of eight elements, fitted) against
!>   inputs/demo_slide/slide.nml;
!> - a points tube with horizon vectors and a start tangent against
!>   inputs/geometry/points_tube.nml;
!> and a folding tube is refused with a message that names the fold.
program test_slide_builder
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_tube, only: tube_surface_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: slide_description_t, section_part_description_t, build_slide
  use io_input, only: input_text_t, load_input_file
  use io_geometry_config, only: read_geometry_description
  use geometry_description, only: geometry_description_t, build_geometry
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(slide_description_t) :: d
  type(tube_surface_t) :: built
  type(status_t) :: status

  ! inputs/demo_slide/slide.nml as a description
  d%kind = 'slide'
  d%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
  d%elements%elements = [ &
    slide_element_t(kind='straight', length=6.0_wp, slope_deg=12.0_wp), &
    slide_element_t(kind='curve', slope_deg=6.0_wp, radius=5.0_wp, angle_deg=90.0_wp, direction='left'), &
    slide_element_t(kind='straight', length=4.0_wp, slope_deg=8.0_wp), &
    slide_element_t(kind='helix', radius=4.0_wp, direction='right', turns=1.0_wp, drop=2.5_wp), &
    slide_element_t(kind='straight', length=3.0_wp, slope_deg=7.0_wp), &
    slide_element_t(kind='curve', slope_deg=6.0_wp, radius=6.0_wp, angle_deg=60.0_wp, direction='left'), &
    slide_element_t(kind='curve', slope_deg=6.0_wp, radius=6.0_wp, angle_deg=60.0_wp, direction='right'), &
    slide_element_t(kind='runout', length=8.0_wp, slope_deg=1.0_wp)]
  d%section%parts = [section_part_description_t(kind='circle', radius=0.5_wp)]
  call build_slide(d, built, status)
  call check(status%ok(), 'demo slide from a description: '//status%text())
  call compare(built, 'inputs/demo_slide/slide.nml', 'demo slide')

  ! inputs/geometry/points_tube.nml as a description
  d = slide_description_t()
  d%kind = 'tube'
  d%centerline%kind = 'points'
  d%centerline%points = reshape([0.0_wp, 0.0_wp, 0.0_wp, 2.0_wp, 0.0_wp, -0.2_wp, 4.0_wp, 1.0_wp, -0.4_wp, &
    6.0_wp, 3.0_wp, -0.6_wp, 7.0_wp, 5.0_wp, -0.8_wp, 7.5_wp, 7.0_wp, -1.0_wp], [3, 6])
  d%centerline%horizon_points = reshape([0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.1_wp, 1.0_wp, 0.0_wp, 0.2_wp, 1.0_wp, &
    -0.2_wp, 0.2_wp, 1.0_wp, -0.3_wp, 0.1_wp, 1.0_wp, -0.3_wp, 0.0_wp, 1.0_wp], [3, 6])
  d%centerline%start_tangent = [1.0_wp, 0.0_wp, -0.1_wp]
  call build_slide(d, built, status)
  call check(status%ok(), 'points tube from a description: '//status%text())
  call compare(built, 'inputs/geometry/points_tube.nml', 'points tube')

  ! a hairpin tighter than the tube's radius folds
  d = slide_description_t()
  d%kind = 'tube'
  d%centerline%kind = 'points'
  d%centerline%points = reshape([0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, -0.1_wp, 1.3_wp, 0.3_wp, -0.2_wp, &
    1.0_wp, 0.6_wp, -0.3_wp, 0.0_wp, 0.6_wp, -0.4_wp, -1.0_wp, 0.6_wp, -0.5_wp], [3, 6])
  d%section%parts = [section_part_description_t(kind='circle', radius=0.7_wp)]
  call build_slide(d, built, status)
  call check(.not. status%ok() .and. index(status%text(), 'fold') > 0, &
             'a folding tube is refused: '//status%text())
  call finish_tests('test_slide_builder')

contains

  !> The same r and derivatives at scattered (u, v) as the reader's surface.
  subroutine compare(a, path, name)
    type(tube_surface_t), intent(in) :: a
    character(len=*), intent(in) :: path, name
    type(input_text_t) :: input
    class(surface_t), allocatable :: b
    type(geometry_description_t) :: description
    type(surface_point_t) :: pa, pb
    type(status_t) :: st
    real(wp) :: u_min, u_max, u, v, worst
    integer :: k
    call load_input_file(path, input, st)
    if (st%ok()) call read_geometry_description(input, description, st)
    if (st%ok()) call build_geometry(description, b, st)
    call check(st%ok(), name//': the reader''s surface: '//st%text())
    if (.not. st%ok()) return
    call a%centerline%domain(u_min, u_max)
    worst = 0
    do k = 1, 37
      u = u_min + (u_max - u_min)*modulo(0.6180339887_wp*k, 1.0_wp)
      v = 6.283185307_wp*modulo(0.4142135624_wp*k, 1.0_wp)
      call a%evaluate(u, v, 3, pa, st)
      call b%evaluate(u, v, 3, pb, st)
      worst = max(worst, maxval(abs([pa%r - pb%r, pa%ru - pb%ru, pa%rv - pb%rv, pa%ruu - pb%ruu, &
                                     pa%ruuu - pb%ruuu, pa%rvvv - pb%rvvv])))
    end do
    call check(worst == 0, name//': the same surface to the bit as the namelist reader''s')
  end subroutine compare
end program test_slide_builder
