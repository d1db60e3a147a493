!> The design loop against the thesis's CPU times (run from the repository
!> root by bench/design_bench.sh): the water-friction identification (thesis
!> 4.4.1: 27.9 s on an i7-8700), the rider-friction identification (4.4.3:
!> 273 s on the same machine) and the optimisation of table 4.12 (4.7: 21.7 s
!> on an i7-9700), each in 1 and 2 OpenMP threads; medians of 3 runs (the
!> rider's: of 1), process CPU time and wall-clock time. Arguments (optional):
!> the job (all, water, rider, optimization), the most threads (2) and the
!> repeats (3), so that one job once in one thread can run under callgrind.
program design_bench
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_status, only: status_t
  use io_input, only: input_text_t, load_input_file
  use scenarios_water, only: build_water
  use numerics_ode, only: ode_options_t
  use design_water_identification, only: water_identification_t, water_fit_options_t, water_fit_t, &
    new_water_identification, simulate_measurements, fit_water_friction
  use io_rider_config, only: read_rider_config
  use rider_ride, only: ride_options_t
  use design_ride_evaluation, only: ride_limit_t
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_model, only: N_CONTACTS, set_rider_mu
  use design_rider_identification, only: rider_identification_t, rider_fit_options_t, rider_fit_t, &
    rider_stations_t, new_rider_identification, simulate_rider, fit_rider_friction
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, table_4_12_design, &
    thesis_start_angles, optimize_slide
  use bench_timing, only: median
  implicit none (type, external)

  integer :: repeats = 3
  real(wp), parameter :: f_true(3) = [0.0274748_wp, 0.138285_wp, 0.979822_wp]            ! table 4.3
  real(wp), parameter :: f_start(3) = [0.0695467_wp, 0.00472592_wp, 0.690685_wp]         ! table 4.3 start
  real(wp), parameter :: mu_true = 0.0724419_wp                                         ! table 4.8
  type(water_identification_t) :: water
  type(rider_identification_t) :: rider
  integer :: threads, max_threads
  character(len=12) :: job
  character(len=8) :: text

  call get_command_argument(1, job)
  if (len_trim(job) == 0) job = 'all'
  call get_command_argument(2, text)
  max_threads = 2
  if (len_trim(text) > 0) read (text, *) max_threads
  call get_command_argument(3, text)
  if (len_trim(text) > 0) read (text, *) repeats
  if (all(job /= [character(len=12) :: 'all', 'water', 'rider', 'optimization'])) &
    error stop 'usage: design_bench [all|water|rider|optimization [MAX_THREADS [REPEATS]]]'
  if (job == 'all' .or. job == 'water') then
    call water_setup(water)
    print '(a)', 'water-friction identification, demo slide twin data (27 sections, 5 segments), from the'
    print '(a)', 'thesis''s start values (table 4.3), w = 0.8, rtol 1e-10 / atol 1e-9 (C.4):'
    do threads = 1, max_threads
      call time_water(threads)
    end do
  end if
  if (job == 'all' .or. job == 'rider') then
    call rider_setup(rider)
    print '(a)', 'rider-friction identification, demo slide twin data (25 stations x 3 angles, 5 segments),'
    print '(a)', 'from mu_D = 0.036 (50 % off; from 0 the rider lifts off) in [0, 0.11], w_RP = 0.6,'
    print '(a)', 'rtol 1e-10 / atol 1e-9 (B.7), the water computed once:'
    do threads = 1, max_threads
      call time_rider(threads)
    end do
  end if
  if (job == 'all' .or. job == 'optimization') then
    print '(a)', 'optimisation of table 4.12 (5 design variables, 5 rides per design):'
    do threads = 1, max_threads
      call time_optimization(threads)
    end do
  end if

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
      ' s, wall ', median(wall), ' s, ', fit%evaluations, ' water runs; thesis 27.9 s / our CPU = ', &
      27.9_wp/median(cpu), ' (goal >= 27.9)'
  end subroutine time_water

  !> The ride of inputs/ride/demo_slide.nml: 25 stations from 3 m to 3 m
  !> before the end, 5 segments of 2 m, measured with the thesis's mu_D.
  subroutine rider_setup(setup)
    type(rider_identification_t), intent(out) :: setup
    type(input_text_t) :: input
    type(status_t) :: status
    type(water_description_t) :: description
    type(water_result_t) :: flow
    type(ride_options_t) :: options
    type(ride_limit_t), allocatable :: limits(:)
    type(rider_stations_t) :: simulated
    real(wp) :: total, mid(5)
    integer :: i
    call load_input_file('inputs/ride/demo_slide.nml', input, status)
    if (status%ok()) call build_water(input, description, status, stage=.true.)
    if (status%ok()) call read_rider_config(input, setup%params, options, limits, status)
    if (status%ok()) call compute_water(description, flow, status)
    if (.not. status%ok()) error stop 'demo ride input'
    setup%slide = description%slide
    call set_rider_mu(setup%params, mu_true)
    setup%with_water = .true.
    setup%water = flow%field
    total = setup%slide%length()
    setup%data%station_arc_length = [(3 + (total - 6)*(i - 1)/24.0_wp, i=1, 25)]
    mid = [(0.1_wp*total + 0.8_wp*total*(i - 1)/4, i=1, 5)]
    setup%data%segment_start = mid - 1
    setup%data%segment_end = mid + 1
    allocate (setup%data%angle(N_CONTACTS, 25), setup%data%segment_speed(5))
    setup%data%angle = 0
    setup%data%segment_speed = 0
    call new_rider_identification(setup, status)
    if (status%ok()) call simulate_rider(setup, setup%params, simulated, status)
    if (.not. status%ok()) error stop 'rider twin data'
    setup%data%angle = simulated%angle
    setup%data%segment_speed = simulated%segment_speed
  end subroutine rider_setup

  subroutine time_rider(threads)
    integer, intent(in) :: threads
    type(rider_identification_t) :: setup
    type(rider_fit_options_t) :: options
    type(rider_fit_t) :: fit
    type(status_t) :: status
    real(wp) :: cpu, wall
    setup = rider
    setup%threads = threads
    options%solver%ftol = 1e-6_wp
    options%solver%xtol = 1e-6_wp
    call clock(cpu, wall)
    call fit_rider_friction(setup, options, 0.5_wp*mu_true, fit, status)
    call clock(cpu, wall, .true.)
    if (.not. status%ok()) then
      print '(a)', status%text()
      error stop 'rider identification failed'
    end if
    print '(a, i0, a, f7.3, a, f7.3, a, i0, a, es10.3, a, f6.1, a)', '  threads ', threads, ': CPU ', cpu, &
      ' s, wall ', wall, ' s, ', fit%evaluations, ' rides, mu_D relative error ', fit%mu/mu_true - 1, &
      '; thesis 273 s / our CPU = ', 273.18_wp/cpu, ' (goal >= 27.3)'
  end subroutine time_rider

  subroutine time_optimization(threads)
    integer, intent(in) :: threads
    type(optimization_setup_t) :: setup
    type(optimization_result_t) :: result
    type(status_t) :: status
    real(wp) :: cpu(repeats), wall(repeats)
    integer :: k
    setup%design = table_4_12_design()
    setup%start_angles = thesis_start_angles()
    setup%threads = threads
    do k = 1, repeats
      call clock(cpu(k), wall(k))
      call optimize_slide(setup, result, status)
      call clock(cpu(k), wall(k), .true.)
      if (.not. status%ok()) error stop 'optimisation failed'
    end do
    print '(a, i0, a, f7.3, a, f7.3, a, i0, a, f6.1, a)', '  threads ', threads, ': CPU ', median(cpu), &
      ' s, wall ', median(wall), ' s, ', result%evaluations, ' designs; thesis 21.7 s / our CPU = ', &
      21.7_wp/median(cpu), ' (goal >= 21.7)'
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
