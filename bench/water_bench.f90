!> Benchmark of the water (thesis 4.2): the streamline down the demo slide
!> (inputs/water/demo_slide.nml, ~67 m) with the thesis's settings rtol 1e-10,
!> atol 1e-9 and output every 0.005 s, median of 7 runs, in three variants:
!> integration only (outputs only at the end), every output recorded (all
!> quantities), and every output with the water edges (4.25-4.26: Newton from
!> the previous output's edges, HYBRJ only as fallback; two cold HYBRJ solves
!> per output cost 0.068 s per 22.3 s of flow here before, 0.048 s now).
!> The thesis needed 1.0 s CPU (i7-8700) for 22.3 s of flow on its 70.7 m slide;
!> our times are also scaled to 22.3 s of flow for the comparison.
program water_bench
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_integrator_t
  use io_input, only: input_text_t, load_input_file
  use water_run, only: water_description_t, new_streamline
  use water_streamline, only: streamline_t
  use water_flow, only: water_series_t, simulate_water
  use scenarios_water, only: build_water
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 7
  real(wp), parameter :: thesis_cpu = 1.0_wp, thesis_flow = 22.3_wp   ! s, s
  type(input_text_t) :: input
  type(water_description_t) :: description
  type(streamline_t), target :: model
  type(water_series_t) :: s
  type(status_t) :: status
  character(len=512) :: path
  real(wp) :: y0(7), cpu(repeats), start, finish, flow_time, median_cpu, variant_cpu(3)
  integer :: variant, r
  character(len=*), parameter :: names(3) = [character(len=34) :: 'integration only', &
    'every 0.005 s recorded', 'every 0.005 s recorded + edges']

  path = 'inputs/water/demo_slide.nml'
  if (command_argument_count() >= 1) call get_command_argument(1, path)
  call load_input_file(trim(path), input, status)
  if (status%ok()) call build_water(input, description, status)
  if (status%ok()) call new_streamline(description, model, y0, status)
  if (.not. status%ok()) then
    print '(a)', trim(path)//': '//status%text()
    error stop 1
  end if
  description%solver%ode%rtol = 1e-10_wp
  description%solver%ode%atol = 1e-9_wp
  print '(a)', 'water on '//model%channel%describe()//', rtol 1e-10, atol 1e-9'
  print '(a34, 4a14)', 'variant', 'flow time s', 'CPU s', 'CPU s/22.3 s', 'thesis/ours'
  do variant = 1, 3
    do r = 1, repeats
      call cpu_time(start)
      select case (variant)
      case (1)
        call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, 1e3_wp, s, status, &
                            edges=.false.)
      case (2)
        call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, 0.005_wp, s, status, edges=.false.)
      case default
        call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, 0.005_wp, s, status, edges=.true.)
      end select
      call cpu_time(finish)
      cpu(r) = finish - start
    end do
    flow_time = s%time(s%n)
    median_cpu = median(cpu)
    variant_cpu(variant) = median_cpu*thesis_flow/flow_time
    print '(a34, f14.3, 2es14.3, f14.1)', names(variant), flow_time, median_cpu, &
      median_cpu*thesis_flow/flow_time, thesis_cpu/(median_cpu*thesis_flow/flow_time)
  end do
  print '(a, es10.3, a, i0, a)', '  edges alone: ', variant_cpu(3) - variant_cpu(2), ' s per 22.3 s of flow (', &
    2*s%n, ' edge solves)'
  print '(a, i0, a, i0, a)', '  (', s%stats%steps, ' steps, ', s%stats%rhs_evaluations, ' right-hand sides)'
  print '(a)', '  thesis: 1.0 s CPU for 22.3 s of flow (i7-8700); goal here: <= 0.05 s'

end program water_bench
