!> Benchmark of one tube-surface evaluation with all partials to third order
!> (the innermost operation of every slide simulation). Goal: < 1 microsecond.
!> Reports nanoseconds per call (median of 7 repeats of 200 000 calls at
!> scattered (u, v)) for a tube on
!>   - the demo slide's fitted quintic centerline (inputs/demo_slide/slide.nml,
!>     run from the repository root),
!>   - the same slide's exact element centerline (centerline_kind = 'exact'),
!>   - an analytic helix (the cost of frame + section alone),
!> each with a circular section, plus order 0 and 1 for the fitted slide.
program tube_bench
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_status, only: status_t
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_curve, only: helix_curve_t, constant_curve_t
  use geometry_cross_section, only: circle_section_t
  use geometry_tube, only: tube_surface_t, new_tube_surface
  use io_input, only: input_text_t, load_input_file
  use io_geometry_config, only: read_geometry_description
  use geometry_description, only: geometry_description_t, build_geometry
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: n_calls = 200000, repeats = 7
  class(surface_t), allocatable :: slide, exact
  type(geometry_description_t) :: description
  type(tube_surface_t) :: helix_tube
  type(input_text_t) :: input, exact_input
  type(status_t) :: status

  call load_input_file('inputs/demo_slide/slide.nml', input, status)
  if (status%ok()) call read_geometry_description(input, description, status)
  if (status%ok()) call build_geometry(description, slide, status)
  if (.not. status%ok()) then
    print '(a)', 'tube_bench: ' // status%text() // ' (run from the repository root)'
    stop 1
  end if
  ! the same slide with the exact element centerline
  exact_input = input
  call exact_input%override('slide_elements%centerline_kind=''exact''', status)
  if (status%ok()) call read_geometry_description(exact_input, description, status)
  if (status%ok()) call build_geometry(description, exact, status)
  helix_tube = new_tube_surface(helix_curve_t(radius=4.0_wp, pitch=-0.4_wp, u_min=0.0_wp, u_max=two_pi), &
                                constant_curve_t(), circle_section_t(radius=0.5_wp), status)

  print '(a52, a14)', 'surface (circle section, radius 0.5 m)', 'ns per call'
  call time_it(slide, 3, 'demo slide, fitted quintic centerline, order 3')
  call time_it(slide, 1, 'demo slide, fitted quintic centerline, order 1')
  call time_it(slide, 0, 'demo slide, fitted quintic centerline, order 0')
  if (allocated(exact)) call time_it(exact, 3, 'demo slide, exact element centerline, order 3')
  call time_it(helix_tube, 3, 'analytic helix centerline, order 3')

contains

  subroutine time_it(surface, order, label)
    class(surface_t), intent(in) :: surface
    integer, intent(in) :: order
    character(len=*), intent(in) :: label
    real(wp) :: u_min, u_max, v_min, v_max, t0, t1, times(repeats), sink, u, v
    type(surface_point_t) :: p
    type(status_t) :: st
    integer :: r, k
    call surface%domain(u_min, u_max, v_min, v_max)
    sink = 0
    do r = 1, repeats
      call cpu_time(t0)
      do k = 1, n_calls
        ! scattered, deterministic points (golden-ratio sequences)
        u = u_min + (u_max - u_min)*modulo(0.6180339887498949_wp*k, 1.0_wp)
        v = v_min + (v_max - v_min)*modulo(0.7548776662466927_wp*k, 1.0_wp)
        call surface%evaluate(u, v, order, p, st)
        sink = sink + p%r(1) + p%ruuu(3)
      end do
      call cpu_time(t1)
      times(r) = (t1 - t0)/n_calls*1e9_wp
    end do
    print '(a52, f14.1, a, es10.2)', label, median(times), '   checksum ', sink
  end subroutine time_it
end program tube_bench
