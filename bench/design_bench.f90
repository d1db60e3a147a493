!> The design loop against the thesis's CPU times (run from the repository
!> root by bench/design_bench.sh): the water-friction identification (thesis
!> 4.4.1: 27.9 s on an i7-8700) and the optimisation of table 4.12 (4.7:
!> 21.7 s on an i7-9700), each in 1 and 2 OpenMP threads; medians of 3 runs,
!> process CPU time and wall-clock time.
program design_bench
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use io_input, only: input_text_t, load_input_file
  use scenarios_water, only: build_water
  use numerics_ode, only: ode_options_t
  use design_water_identification, only: water_identification_t, water_fit_options_t, water_fit_t, &
    new_water_identification, simulate_measurements, fit_water_friction
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, table_4_12_design, &
    optimize_slide
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 3
  real(wp), parameter :: f_true(3) = [0.0274748_wp, 0.138285_wp, 0.979822_wp]            ! table 4.3
  real(wp), parameter :: f_start(3) = [0.0695467_wp, 0.00472592_wp, 0.690685_wp]         ! table 4.3 start
  type(water_identification_t) :: water
  integer :: threads

  call water_setup(water)
  print '(a)', 'water-friction identification, demo slide twin data (27 sections, 5 segments), from the'
  print '(a)', 'thesis''s start values (table 4.3), w = 0.8, rtol 1e-10 / atol 1e-9 (C.4):'
  do threads = 1, 2
    call time_water(threads)
  end do
  print '(a)', 'optimisation of table 4.12 (5 design variables, 5 rides per design):'
  do threads = 1, 2
    call time_optimization(threads)
  end do

contains

  subroutine water_setup(setup)
    type(water_identification_t), intent(out) :: setup
    type(input_text_t) :: input
    type(status_t) :: status
    real(wp) :: total, mid(5)
    integer :: i
    call load_input_file('inputs/water/demo_slide.nml', input, status)
    if (status%ok()) call build_water(input, setup%water, status)
    if (.not. status%ok()) error stop 'demo water input'
    total = setup%water%slide%length()
    setup%data%section_arc_length = [(3 + (total - 6)*(i - 1)/26.0_wp, i=1, 27)]
    mid = [(0.1_wp*total + 0.8_wp*total*(i - 1)/4, i=1, 5)]
    setup%data%segment_start = mid - 1
    setup%data%segment_end = mid + 1
    allocate (setup%data%section_v(27), setup%data%segment_speed(5))
    call new_water_identification(setup, status)
    if (status%ok()) call simulate_measurements(setup, f_true, setup%data%section_v, setup%data%segment_speed, &
                                                status)
    if (.not. status%ok()) error stop 'demo twin data'
  end subroutine water_setup

  subroutine time_water(threads)
    integer, intent(in) :: threads
    type(water_identification_t) :: setup
    type(water_fit_options_t) :: options
    type(water_fit_t) :: fit
    type(status_t) :: status
    real(wp) :: cpu(repeats), wall(repeats)
    integer :: k
    setup = water
    setup%threads = threads
    do k = 1, repeats
      call clock(cpu(k), wall(k))
      call fit_water_friction(setup, options, f_start, fit, status)
      call clock(cpu(k), wall(k), .true.)
      if (.not. status%ok()) error stop 'water identification failed'
    end do
    print '(a, i0, a, f7.3, a, f7.3, a, i0, a, f6.1, a)', '  threads ', threads, ': CPU ', median(cpu), &
      ' s, wall ', median(wall), ' s, ', fit%evaluations, ' water runs; thesis 27.9 s / our wall = ', &
      27.9_wp/median(wall), ' (goal >= 27.9)'
  end subroutine time_water

  subroutine time_optimization(threads)
    integer, intent(in) :: threads
    type(optimization_setup_t) :: setup
    type(optimization_result_t) :: result
    type(status_t) :: status
    real(wp) :: cpu(repeats), wall(repeats)
    integer :: k
    setup%design = table_4_12_design()
    setup%start_angles = [-30.0_wp, -15.0_wp, 0.0_wp, 15.0_wp, 30.0_wp]*pi/180
    setup%threads = threads
    do k = 1, repeats
      call clock(cpu(k), wall(k))
      call optimize_slide(setup, result, status)
      call clock(cpu(k), wall(k), .true.)
      if (.not. status%ok()) error stop 'optimisation failed'
    end do
    print '(a, i0, a, f7.3, a, f7.3, a, i0, a, f6.1, a)', '  threads ', threads, ': CPU ', median(cpu), &
      ' s, wall ', median(wall), ' s, ', result%evaluations, ' designs; thesis 21.7 s / our wall = ', &
      21.7_wp/median(wall), ' (goal >= 21.7)'
  end subroutine time_optimization

  !> Starts (stop absent) or stops a CPU and a wall-clock timer.
  subroutine clock(cpu, wall, stop)
    real(wp), intent(inout) :: cpu, wall
    logical, intent(in), optional :: stop
    integer(int64) :: count, rate
    real(wp) :: now
    call cpu_time(now)
    call system_clock(count, rate)
    if (present(stop)) then
      cpu = now - cpu
      wall = real(count, wp)/real(rate, wp) - wall
    else
      cpu = now
      wall = real(count, wp)/real(rate, wp)
    end if
  end subroutine clock
end program design_bench
