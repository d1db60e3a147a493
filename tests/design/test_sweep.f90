!> Populations of rides (design_sweep, io_sweep_config): a handful of short
!> rides on the demo slide run serially and in 2 threads give bit-identical
!> results; each ride's figures equal those of the same ride run alone
!> (rider_ride + design_ride_report); rides that cannot start, whose water
!> fails, or that stall are reported as such while the others finish; the
!> waters are grouped (one per distinct flow rate and friction); the ranks'
!> shares cover every ride once; &sweep expands lists, ranges, crossed and
!> paired variables in the documented order and refuses bad values.
program test_sweep
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use rider_model, only: rider_params_t
  use rider_ride, only: ride_result_t, simulate_ride
  use water_run, only: water_description_t, water_result_t, compute_water
  use design_ride_evaluation, only: new_ride_limit
  use design_ride_report, only: ride_report_t, evaluate_ride
  use design_sweep, only: sweep_description_t, sweep_result_t, run_sweep, water_groups, ride_description, &
    rides_of_rank, N_SWEPT, V_SEX, V_MASS, V_HEIGHT, V_MU, V_U0, V_V0, V_HEADING, V_SPEED, V_FLOW_RATE, V_F1, &
    V_F2, V_F3, RIDE_STOPPED, RIDE_FAILED, RIDE_NOT_RUN
  use io_input, only: input_text_t, input_from_text
  use io_sweep_config, only: sweep_config_t, read_sweep_config
  use scenarios_water, only: build_water
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(sweep_description_t) :: sweep
  type(status_t) :: status
  character(len=*), parameter :: nl = new_line('a')

  call prepare(sweep, status)
  call check(status%ok(), 'the demo slide and its water description: '//status%text())
  if (status%ok()) call check_rides(sweep)
  call check_shares()
  call check_config()
  call finish_tests('test_sweep')

contains

  !> The demo slide, the base water and rider, and seven short rides (2.5 s
  !> bound): two plain, one heavier female rider, one at a second flow rate,
  !> one stall near the end, one start whose heels cannot reach the slide
  !> and one whose water reaches critical flow at the start.
  subroutine prepare(sweep, status)
    type(sweep_description_t), intent(out) :: sweep
    type(status_t), intent(inout) :: status
    type(input_text_t) :: input
    character(len=:), allocatable :: problem
    real(wp) :: base(N_SWEPT)
    integer :: i
    call input_from_text('test_sweep', '&surface kind = ''slide'', geometry_file = ''builtin:demo_slide'' /'//nl// &
                         '&water flow_rate = 0.004, start = ''edges'', u0 = 0.0, v_left0 = 1.9207963267948966, '// &
                         'v_right0 = 1.2207963267948966 /'//nl, input, status)
    if (status%ok()) call build_water(input, sweep%water, status, stage=.true.)
    if (.not. status%ok()) return
    sweep%options%max_duration = 2.5_wp
    sweep%options%progress_seconds = 0
    allocate (sweep%limits(1))
    call new_ride_limit('speed', 'm/s', 0.0_wp, .false., 2.0_wp, .true., 9.80665_wp, sweep%limits(1), problem)
    base = [1.0_wp, 68.5_wp, 1.78_wp, 0.0724419_wp, 0.5_wp, pi/2, 0.0_wp, 1.0_wp, 0.004_wp, sweep%water%f1, &
            sweep%water%f2, sweep%water%f3]
    allocate (sweep%values(N_SWEPT, 7))
    do i = 1, 7
      sweep%values(:, i) = base
    end do
    sweep%values(V_MASS, 2) = 55
    sweep%values([V_SEX, V_MASS, V_HEIGHT], 3) = [2.0_wp, 90.0_wp, 1.65_wp]
    sweep%values([V_FLOW_RATE, V_HEADING], 4) = [0.006_wp, 5.0_wp]
    sweep%values(V_U0, 5) = 60        ! on the flat end: it stalls (1.8 s)
    sweep%values(V_U0, 6) = 66.5      ! the heels beyond the end of the slide
    sweep%values(V_FLOW_RATE, 7) = 0.002   ! critical at the start
  end subroutine prepare

  subroutine check_rides(sweep)
    type(sweep_description_t), intent(in) :: sweep
    type(sweep_result_t) :: serial, threaded, alone
    type(rider_params_t) :: rider
    type(water_description_t) :: water_description
    type(water_result_t) :: water
    type(ride_result_t) :: ride
    type(ride_report_t) :: report
    type(status_t) :: st
    integer, allocatable :: group(:), first(:)
    logical :: all_mine(7)
    integer :: i

    all_mine = .true.
    call run_sweep(sweep, all_mine, 1, serial)
    call run_sweep(sweep, all_mine, 2, threaded)
    call check(all(serial%status == threaded%status), 'status: serial = 2 threads')
    call check(all(serial%message == threaded%message), 'messages: serial = 2 threads')
    ! bit-identical: the same code on the same inputs, whichever thread runs it
    call check(all(serial%figures == threaded%figures), 'figures: serial = 2 threads, to the bit')
    call check(all(serial%verdict == threaded%verdict) .and. all(serial%worst == threaded%worst) .and. &
               all(serial%excess == threaded%excess), 'limit verdicts: serial = 2 threads, to the bit')

    ! what each ride did
    call check(all(serial%status(1:4) == RIDE_STOPPED), 'rides 1-4 ran to the 2.5 s bound')
    call check(all(index(serial%message(1:4), 'had not ended after 2.5') > 0), 'rides 1-4: the bound says so')
    call check(serial%status(5) == RIDE_STOPPED .and. index(serial%message(5), 'stalled') > 0, &
               'ride 5 stalls on the flat end: '//trim(serial%message(5)))
    call check(serial%status(6) == RIDE_FAILED .and. index(serial%message(6), 'heels cannot reach') > 0, &
               'ride 6 cannot start: '//trim(serial%message(6)))
    call check(serial%status(7) == RIDE_FAILED .and. index(serial%message(7), 'the water failed') > 0 .and. &
               index(serial%message(7), 'critical') > 0, 'ride 7: its water fails: '//trim(serial%message(7)))
    call check(all(serial%figures(:, 6:7) == 0) .and. all(serial%verdict(:, 6:7) == -1), &
               'failed rides have no figures and no verdicts')
    call check(all(serial%figures(1, 1:5) > 0), 'the others have a ride time')
    call check(serial%figures(3, 1) /= serial%figures(3, 2) .and. serial%figures(3, 1) /= serial%figures(3, 3) &
               .and. serial%figures(3, 1) /= serial%figures(3, 4), 'mass, body and water change the top speed')

    ! the waters: 0.004 (rides 1-3, 5, 6), 0.006 (ride 4), 0.002 (ride 7)
    call water_groups(sweep%values, group, first)
    call check(size(first) == 3 .and. all(group == [1, 1, 1, 2, 1, 1, 3]) .and. all(first == [1, 4, 7]), &
               'three waters, grouped in order of first use')
    call check(all(serial%water_group == group), 'each ride knows its water')

    ! ride 3 and 4 alone (own water, own ride, own report) give the same figures
    do i = 3, 4
      call ride_description(sweep, i, rider, water_description)
      call compute_water(water_description, water, st)
      call simulate_ride(rider, sweep%water%slide, sweep%options, ride, st, water%field)
      call evaluate_ride(ride%series, rider%gravity, ride%complete, sweep%limits, report)
      call check(st%ok(), 'ride alone runs')
      call check(serial%figures(1, i) == report%ride_time .and. serial%figures(3, i) == report%top_speed .and. &
                 serial%figures(14, i) == report%felt_max(3) .and. serial%figures(20, i) == report%lever_max &
                 .and. serial%figures(31, i) == report%normal_min(1), 'ride alone = ride in the sweep (figures)')
      call check(serial%verdict(1, i) == merge(1, 0, report%verdicts(1)%exceeded) .and. &
                 serial%worst(1, i) == report%verdicts(1)%worst, 'ride alone = ride in the sweep (the limit)')
    end do

    ! a share of the rides: only those run, the others stay not run
    call run_sweep(sweep, rides_of_rank(7, 1, 2), 2, alone)
    call check(all(alone%status([1, 3, 5, 7]) == RIDE_NOT_RUN), 'rank 1 of 2 leaves rides 1, 3, 5, 7')
    call check(all(alone%figures(:, [2, 4, 6]) == serial%figures(:, [2, 4, 6])) .and. &
               all(alone%status([2, 4, 6]) == serial%status([2, 4, 6])), 'rank 1 of 2: rides 2, 4, 6 as serial')
  end subroutine check_rides

  subroutine check_shares()
    integer :: ranks, r, counted(10)
    logical :: mine(10)
    do ranks = 1, 4
      counted = 0
      do r = 0, ranks - 1
        mine = rides_of_rank(10, r, ranks)
        where (mine) counted = counted + 1
      end do
      call check(all(counted == 1), 'the ranks'' shares cover every ride once')
    end do
  end subroutine check_shares

  !> &sweep: the cross product's order (the first variable slowest), a
  !> range with both ends exact, pairing, and refusals.
  subroutine check_config()
    type(sweep_config_t) :: config
    call read('&sweep mass = 50, 70, flow_rate_range = 0.004, 0.006, 3 /', config, status)
    call check(status%ok(), 'cross: read')
    if (status%ok()) then
      call check(size(config%values, 2) == 6, 'cross: 2 x 3 rides')
      call check(all(config%values(V_MASS, :) == [50, 50, 50, 70, 70, 70]), 'cross: mass slowest')
      call check(all(config%values(V_FLOW_RATE, :) == [0.004_wp, 0.005_wp, 0.006_wp, 0.004_wp, 0.005_wp, &
                                                        0.006_wp]), 'cross: the range, both ends as written')
      call check(all(config%values(V_HEIGHT, :) == 1.78_wp) .and. all(config%values(V_F3, :) == 0.3_wp), &
                 'cross: the rest from the base')
      call check(all(config%swept .eqv. [.false., .true., .false., .false., .false., .false., .false., .false., &
                                         .true., .false., .false., .false.]), 'cross: what is swept')
    end if
    call read('&sweep sex = ''male'', ''female'', mass = 80, 60, height = 1.8, 1.6, paired = ''mass'', '// &
              '''sex'', mu = 0.05, 0.1 /', config, status)
    call check(status%ok(), 'paired: read')
    if (status%ok()) then
      call check(size(config%values, 2) == 8, 'paired: (sex, mass) x height x mu = 2 x 2 x 2 rides')
      call check(all(config%values(V_SEX, :) == [1, 1, 1, 1, 2, 2, 2, 2]) .and. &
                 all(config%values(V_MASS, :) == [80, 80, 80, 80, 60, 60, 60, 60]), 'paired: sex with mass')
      call check(all(config%values(V_MU, :) == [0.05_wp, 0.1_wp, 0.05_wp, 0.1_wp, 0.05_wp, 0.1_wp, 0.05_wp, &
                                                 0.1_wp]), 'paired: mu fastest')
    end if
    call read('&sweep sex = ''male'', ''female'', mass = 80, 60, combine = ''paired'' /', config, status)
    call check(status%ok(), 'combine paired: read')
    if (status%ok()) call check(all(config%values(V_SEX, :) == [1, 2]) .and. &
                                all(config%values(V_MASS, :) == [80, 60]), 'combine paired: element by element')
    call refused('&sweep mass = 5 /', 'mass(1) = 5 is not allowed: must be a finite number in [10, 300] (kg)')
    call refused('&sweep /', 'give at least one of')
    call refused('&sweep mass = 50, 60, height = 1.7, combine = ''paired'' /', 'needs as many values')
    call refused('&sweep mass_range = 50, 90, 2.5 /', 'the count must be a whole number')
    call refused('&sweep mass_range = 50, 900, 3 /', 'first and last')
    call refused('&sweep mass = 50, mass_range = 50, 90, 3 /', 'either as a list or as a range')
    call refused('&sweep mass = 50, 60, paired = ''height'', ''mass'' /', 'height is not swept')
    call refused('&sweep speed = 1 /', 'unknown variable "speed"')
    call refused('&sweep sex = ''child'' /', 'sex')
  end subroutine check_config

  subroutine read(text, config, status)
    character(len=*), intent(in) :: text
    type(sweep_config_t), intent(out) :: config
    type(status_t), intent(out) :: status
    type(input_text_t) :: input
    real(wp) :: base(N_SWEPT)
    base = [1.0_wp, 68.5_wp, 1.78_wp, 0.07_wp, 0.5_wp, pi/2, 0.0_wp, 1.0_wp, 0.004_wp, 0.1_wp, 0.2_wp, 0.3_wp]
    call input_from_text('sweep.nml', text//nl, input, status)
    if (status%ok()) call read_sweep_config(input, base, config, status)
  end subroutine read

  subroutine refused(text, expected)
    character(len=*), intent(in) :: text, expected
    type(sweep_config_t) :: config
    type(status_t) :: st
    call read(text, config, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), expected) > 0 .and. &
               index(st%text(), 'sweep.nml:1') > 0 .and. index(st%text(), '&sweep') > 0, &
               'refused: '//text//' -> '//st%text())
  end subroutine refused
end program test_sweep
