!> Benchmark of the ride (thesis 4.3) on the demo slide
!> (inputs/ride/demo_slide.nml: the water first, then the rider in it; rtol
!> 1e-10, atol 1e-9 as the thesis), library runs without input reading or
!> files, each the median of 7 runs of process CPU time:
!>   water             compute_water (its own settings, as the ride runs it)
!>   ride              simulate_ride with records every 0.01 s (the default)
!>   ride, no records  one record at the end (the integration's cost)
!>   ride, no drag     records every 0.01 s, no water drag (no on/off events)
!>   water + ride      the two together: the goal is 0.2 s
!> next to the thesis: 10.98 s CPU (i7-8700) for a 15.8 s ride (B.7), i.e.
!> 0.695 s per simulated second, and next to the sled on the same slide
!> (kinetostatics_models, inputs/sled/demo_slide.nml) per simulated second.
!> Run from the repository root.
program ride_bench
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use io_input, only: input_text_t, load_input_file
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_surface_config, only: read_surface_config, surface_source_t
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use io_rider_config, only: read_rider_config
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: build_sled, sled_description_t
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_model, only: rider_params_t
  use rider_ride, only: ride_options_t, ride_result_t, simulate_ride
  use design_ride_evaluation, only: ride_limit_t
  use scenarios_water, only: build_water
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 7
  real(wp), parameter :: thesis_cpu = 10.98_wp, thesis_ride = 15.8_wp   ! s, s (METHOD-PART2 B.7)
  type(input_text_t) :: input
  type(water_description_t) :: water
  type(water_result_t) :: computed
  type(rider_params_t) :: rider
  type(ride_limit_t), allocatable :: limits(:)
  type(ride_options_t) :: options
  type(ride_result_t) :: ride
  type(status_t) :: status
  real(wp) :: water_cpu, ride_cpu, sled_per_second

  call load_input_file('inputs/ride/demo_slide.nml', input, status)
  if (status%ok()) call build_water(input, water, status, stage=.true.)
  if (status%ok()) call read_rider_config(input, rider, options, limits, status)
  if (.not. status%ok()) then
    print '(a)', 'inputs/ride/demo_slide.nml: '//status%text()
    error stop 1
  end if
  options%progress_seconds = 0
  options%max_duration = 600

  print '(a)', 'the ride on the demo slide (inputs/ride/demo_slide.nml), rtol 1e-10, atol 1e-9, median of 7'
  print '(a24, 6a13)', 'run', 'simulated s', 'CPU s', 'CPU s/sim s', 'thesis/ours', 'steps', 'records'
  water_cpu = time_water()
  ride_cpu = time_ride('ride (records 0.01 s)', 0.01_wp, .true.)
  print '(a, i0, a, i0, a)', '    (', ride%drag_switches, ' drag switches, ', ride%driver%restarts, &
    ' integrator restarts)'
  associate (unused => time_ride('ride, no records', 1e3_wp, .true.))
  end associate
  associate (unused => time_ride('ride, no drag', 0.01_wp, .false.))
  end associate
  print '(a24, 13x, f13.4, 26x, f13.1)', 'water + ride', water_cpu + ride_cpu, &
    thesis_cpu/(water_cpu + ride_cpu)*ride%series%time(ride%series%n)/thesis_ride
  print '(a)', '  goal: water + ride <= 0.2 s (thesis 10.98 s for a 15.8 s ride; the ratio is per simulated second)'
  sled_per_second = time_sled()
  print '(a, es11.3, a, es11.3, a, f6.1, a)', '  CPU per simulated second: rider ', ride_cpu/ride%series%time(ride%series%n), &
    ' s, sled ', sled_per_second, ' s (rider/sled ', ride_cpu/ride%series%time(ride%series%n)/sled_per_second, ')'

contains

  real(wp) function time_water() result(cpu_median)
    real(wp) :: cpu(repeats), start, finish
    integer :: k
    do k = 1, repeats
      call cpu_time(start)
      call compute_water(water, computed, status)
      call cpu_time(finish)
      cpu(k) = finish - start
    end do
    if (.not. status%ok()) then
      print '(a)', 'water: '//status%text()
      error stop 1
    end if
    cpu_median = median(cpu)
    print '(a24, f13.3, 2es13.3, 13x, i13)', 'water', computed%series%time(computed%series%n), cpu_median, &
      cpu_median/computed%series%time(computed%series%n), computed%series%stats%steps
  end function time_water

  real(wp) function time_ride(label, output_step, drag) result(cpu_median)
    character(len=*), intent(in) :: label
    real(wp), intent(in) :: output_step
    logical, intent(in) :: drag
    real(wp) :: cpu(repeats), start, finish, t
    integer :: k
    options%output_step = output_step
    rider%drag = drag
    do k = 1, repeats
      call cpu_time(start)
      call simulate_ride(rider, water%slide, options, ride, status, computed%field)
      call cpu_time(finish)
      cpu(k) = finish - start
    end do
    rider%drag = .true.
    if (.not. status%ok() .or. .not. ride%complete) then
      print '(a)', label//': '//status%text()//' '//ride%outcome
      error stop 1
    end if
    cpu_median = median(cpu)
    t = ride%series%time(ride%series%n)
    print '(a24, f13.3, 2es13.3, f13.1, 2i13)', label, t, cpu_median, cpu_median/t, &
      thesis_cpu/thesis_ride/(cpu_median/t), ride%driver%stats%steps, ride%series%n
  end function time_ride

  !> The sled of inputs/sled/demo_slide.nml on the same slide, CPU s per simulated s.
  real(wp) function time_sled() result(per_second)
    type(input_text_t) :: sled_input
    type(solver_config_t) :: solver
    type(sled_description_t) :: sled
    class(surface_t), allocatable :: surface
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: source
    type(mechanism_ode_t), target :: sys
    type(driver_options_t) :: driver
    type(driver_result_t) :: result
    real(wp), allocatable :: y0(:)
    real(wp) :: cpu(repeats), start, finish
    integer :: k
    call load_input_file('inputs/sled/demo_slide.nml', sled_input, status)
    if (status%ok()) call read_solver_config(sled_input, solver, status)
    if (status%ok()) call read_surface_config(sled_input, surface_description, status, source)
    if (status%ok()) call build_surface(surface_description, surface, status)
    if (status%ok()) call read_sled_config(sled_input, sled, status)
    if (.not. status%ok()) error stop 1
    driver%ode = solver%options
    driver%t_end = solver%duration
    driver%output_step = solver%output_step
    driver%progress_seconds = 0
    do k = 1, repeats
      call build_sled(sled%params, surface, sled%q0, sys%mechanism, status)
      y0 = sys%initial_state(sled%q0, sled%qd0)
      call sys%start_series(nint(solver%duration/solver%output_step) + 2)
      call cpu_time(start)
      call drive(sys, y0, driver, result, status)
      call cpu_time(finish)
      cpu(k) = finish - start
    end do
    per_second = median(cpu)/result%t
  end function time_sled
end program ride_bench
