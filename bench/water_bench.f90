!> Benchmark of the water (thesis 4.2) on the demo slide
!> (inputs/water/demo_slide.nml, ~67 m, rtol 1e-10, atol 1e-9, output every
!> 0.005 s as the thesis), the library run compute_water (run to the end,
!> field, table; no input reading, no file) in variants, each the median of
!> 11 runs of process CPU time:
!>   integration only  (one output at the end: the run's steps and events)
!>   outputs, no edges (every 0.005 s recorded, the edges solved at the
!>                      table's rows only: edges = .false.)
!>   outputs and edges (every 0.005 s with the edges: the default)
!> The thesis needed 1.0 s CPU (i7-8700) for 22.3 s of flow on its 70.7 m
!> slide; the ratios compare per 22.3 s of flow. The whole process (reading,
!> fitting the slide, the run, the result file) is timed by water_bench.sh.
program water_bench
  use base_kinds, only: wp
  use base_status, only: status_t
  use io_input, only: input_text_t, load_input_file
  use water_run, only: water_description_t, water_result_t, compute_water
  use scenarios_water, only: build_water
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 11
  real(wp), parameter :: thesis_cpu = 1.0_wp, thesis_flow = 22.3_wp   ! s, s
  type(input_text_t) :: input
  type(water_description_t) :: d
  type(water_result_t) :: r
  type(status_t) :: status
  character(len=512) :: path

  path = 'inputs/water/demo_slide.nml'
  if (command_argument_count() >= 1) call get_command_argument(1, path)
  call load_input_file(trim(path), input, status)
  if (status%ok()) call build_water(input, d, status)
  if (.not. status%ok()) then
    print '(a)', trim(path)//': '//status%text()
    error stop 1
  end if
  d%solver%ode%rtol = 1e-10_wp
  d%solver%ode%atol = 1e-9_wp
  d%solver%output_step = 0.005_wp
  print '(a)', 'water (compute_water) on '//d%slide%describe()//', rtol 1e-10, atol 1e-9'
  print '(a28, 5a13)', 'variant', 'flow time s', 'CPU s', 'per 22.3 s', 'thesis/ours', 'steps'
  d%edges = .true.
  d%solver%output_step = 1e3_wp
  call one('integration only')
  d%solver%output_step = 0.005_wp
  d%edges = .false.
  call one('outputs, no edges')
  d%edges = .true.
  call one('outputs and edges (default)')
  print '(a, i0, a, i0, a, i0, a)', '  (', r%series%stats%steps, ' steps, ', r%series%stats%rhs_evaluations, &
    ' right-hand sides, ', r%series%stats%root_evaluations, ' root evaluations)'

contains

  subroutine one(label)
    character(len=*), intent(in) :: label
    real(wp) :: cpu(repeats), start, finish, per_thesis
    integer :: k
    do k = 1, repeats
      call cpu_time(start)
      call compute_water(d, r, status)
      call cpu_time(finish)
      cpu(k) = finish - start
    end do
    if (.not. status%ok()) then
      print '(a)', label//': '//status%text()
      error stop 1
    end if
    per_thesis = median(cpu)*thesis_flow/r%series%time(r%series%n)
    print '(a28, f13.3, 2es13.3, f13.1, i13)', label, r%series%time(r%series%n), median(cpu), per_thesis, &
      thesis_cpu/per_thesis, r%series%stats%steps
  end subroutine one
end program water_bench
