!> Twin experiments of the rider-friction identification (thesis 4.4.3, cost
!> 4.43; METHOD-PART2 D.6) on the first part of the demo slide (the ride of
!> inputs/ride/demo_slide.nml in its water): "measurements" simulated with the
!> thesis's mu_D = 0.0724419 (table 4.8) at n_stations stations (the three
!> contacts' wall angles) and on 2 segments (speeds), then
!> - the ride records the state exactly where the pelvis crosses a station
!>   and ends at the last one;
!> - without noise, mu_D is recovered from the thesis's start 0 (100 % off)
!>   within its bounds [0, 0.11];
!> - with Gaussian noise of 0.03 rad (angles) and 0.05 m/s (speeds) and the
!>   weight that matches it, in 20 seeded repetitions (fitted two at a time
!>   in 2 OpenMP threads: closures (HYBRJ) inside the integrator inside LMDER
!>   in two threads at once, the first one also serially with the same bits)
!>   the estimate lies within 3 standard errors at least 19 times and the
!>   spread of the estimates agrees with the reported standard errors;
!> - the body-parameter study (table 4.10): an unchanged body deviates by
!>   exactly 0, a heavier one by more than 0.
program test_rider_identification
  use base_kinds, only: wp
  use base_status, only: status_t
  use io_input, only: input_text_t, load_input_file
  use io_rider_config, only: read_rider_config
  use scenarios_water, only: build_water
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_model, only: rider_params_t, N_CONTACTS, set_rider_mu
  use rider_ride, only: ride_result_t, ride_options_t, simulate_ride
  use design_ride_evaluation, only: ride_limit_t
  use design_rider_identification, only: rider_identification_t, rider_fit_options_t, rider_fit_t, &
    rider_stations_t, new_rider_identification, simulate_rider, fit_rider_friction, rider_body_sensitivity
  use testing, only: check, check_close, finish_tests, failures
  use twin_data, only: noise_t, evenly
  implicit none (type, external)

  real(wp), parameter :: mu_true = 0.0724419_wp   ! table 4.8
  real(wp), parameter :: sigma_angle = 0.03_wp, sigma_speed = 0.05_wp   ! rad, m/s
  integer, parameter :: n_stations = 5, n_segments = 2
  real(wp), parameter :: first = 2.5_wp, last = 10   ! m of arc length: the part of the slide measured
  type(rider_identification_t) :: clean

  call make_setup('inputs/ride/demo_slide.nml', clean)
  if (failures > 0) call finish_tests('test_rider_identification')
  call stations_recorded(clean)
  call noise_free(clean)
  call with_noise(clean)
  call body_sensitivity(clean)
  call finish_tests('test_rider_identification')

contains

  subroutine make_setup(path, setup)
    character(len=*), intent(in) :: path
    type(rider_identification_t), intent(out) :: setup
    type(input_text_t) :: input
    type(status_t) :: status
    type(water_description_t) :: description
    type(water_result_t) :: water
    type(rider_params_t) :: rider
    type(ride_options_t) :: options
    type(ride_limit_t), allocatable :: limits(:)
    type(rider_stations_t) :: simulated
    real(wp) :: mid(n_segments), cpu0, cpu1
    call load_input_file(path, input, status)
    if (status%ok()) call build_water(input, description, status, stage=.true.)
    if (status%ok()) call read_rider_config(input, rider, options, limits, status)
    if (status%ok()) call compute_water(description, water, status)
    call check(status%ok(), path//': '//status%text())
    if (.not. status%ok()) return
    setup%slide = description%slide
    setup%params = rider
    call set_rider_mu(setup%params, mu_true)
    setup%with_water = .true.
    setup%water = water%field
    setup%data%station_arc_length = evenly(first, last, n_stations)
    mid = evenly(first + 1.5_wp, last - 1.5_wp, n_segments)
    setup%data%segment_start = mid - 1
    setup%data%segment_end = mid + 1
    allocate (setup%data%angle(N_CONTACTS, n_stations), setup%data%segment_speed(n_segments))
    setup%data%angle = 0
    setup%data%segment_speed = 0
    call new_rider_identification(setup, status)
    call check(status%ok(), 'setup: '//status%text())
    call cpu_time(cpu0)
    if (status%ok()) call simulate_rider(setup, setup%params, simulated, status)
    call cpu_time(cpu1)
    call check(status%ok(), 'synthetic measurements: '//status%text())
    if (.not. status%ok()) return
    print '(a, f7.3, a)', 'one ride to the last station: ', cpu1 - cpu0, ' s CPU'
    setup%data%angle = simulated%angle
    setup%data%segment_speed = simulated%segment_speed
    print '(a, 5f8.4)', 'pelvis angles at the stations (rad): ', simulated%angle(1, :)
    print '(a, 2f8.4)', 'segment speeds (m/s): ', simulated%segment_speed
  end subroutine make_setup

  !> The ride's records at the stations: the pelvis exactly there (CVODE's
  !> root location, ~1e-12 s: 1e-9 m leaves room), the last one ends it.
  subroutine stations_recorded(setup)
    type(rider_identification_t), intent(in) :: setup
    type(ride_result_t) :: ride
    type(status_t) :: status
    integer :: i
    call simulate_ride(setup%params, setup%slide, setup%options, ride, status, setup%water)
    call check(status%ok() .and. ride%complete, 'the ride to the last station: '//status%text())
    if (.not. status%ok()) return
    call check(all(ride%station_record > 0), 'every station recorded')
    if (.not. all(ride%station_record > 0)) return
    do i = 1, size(ride%station_record)
      call check_close(ride%series%arc_length(ride%station_record(i)), setup%options%stations(i), 0.0_wp, &
                       1e-9_wp, 'the pelvis at its station')
    end do
    call check(ride%station_record(size(ride%station_record)) == ride%series%n, 'the last station ends the ride')
    call check(index(ride%outcome, 'last station') == 1, 'and says so: '//ride%outcome)
  end subroutine stations_recorded

  subroutine noise_free(setup)
    type(rider_identification_t), intent(in) :: setup
    type(rider_fit_options_t) :: options
    type(rider_fit_t) :: fit
    type(status_t) :: status
    real(wp) :: cpu0, cpu1
    options%solver%xtol = 1e-10_wp
    options%solver%ftol = 1e-14_wp
    call cpu_time(cpu0)
    call fit_rider_friction(setup, options, 0.0_wp, fit, status)
    call cpu_time(cpu1)
    call check(status%ok(), 'noise-free fit: '//status%text())
    print '(a, es16.8, a, i0, a, i0, a, f7.3, a)', 'noise-free: mu_D = ', fit%mu, ', ', fit%evaluations, &
      ' rides (', fit%rejected, ' rejected), ', cpu1 - cpu0, ' s CPU'
    print '(a, es12.4, a, es10.3, a, es10.3)', '   relative error ', fit%mu/mu_true - 1, ', cost ', fit%cost, &
      ', standard error ', fit%standard_error
    call check_close(fit%mu, mu_true, 1e-7_wp, 0.0_wp, 'noise-free recovery of mu_D from 0')
  end subroutine noise_free

  subroutine with_noise(clean)
    type(rider_identification_t), intent(in) :: clean
    integer, parameter :: reps = 20
    type(rider_identification_t) :: setups(reps)
    type(rider_fit_options_t) :: options
    type(rider_fit_t) :: fit, serial
    type(status_t) :: status(reps), serial_status
    type(noise_t) :: noise
    real(wp) :: mu(reps), se(reps), spread, mean_se, cpu0, cpu1
    integer :: k, i, j, inside, evaluations(reps)
    ! the weighted residuals share one variance when
    ! (1-w)/n sigma_angle^2 = w k2^2/m sigma_speed^2
    options%weight = 1/(1 + (n_stations*sigma_speed**2)/(n_segments*sigma_angle**2))
    ! The noise moves mu_D by ~1 %: integration at rtol 1e-8 (1e4 below the
    ! noise's effect), differences above its noise (epsfcn 1e-8) and a stop
    ! at 1e-4 relative change keep the figures compared here exact to < 1e-2
    ! of a standard error, at a fraction of the cost.
    options%solver%ftol = 1e-4_wp
    options%solver%xtol = 1e-4_wp
    options%solver%epsfcn = 1e-8_wp
    do k = 1, reps
      setups(k) = clean
      setups(k)%options%ode%rtol = 1e-8_wp
      setups(k)%options%ode%atol = 1e-8_wp
      do j = 1, n_stations
        do i = 1, N_CONTACTS
          setups(k)%data%angle(i, j) = clean%data%angle(i, j) + sigma_angle*noise%normal()
        end do
      end do
      do j = 1, n_segments
        setups(k)%data%segment_speed(j) = clean%data%segment_speed(j) + sigma_speed*noise%normal()
      end do
    end do
    call cpu_time(cpu0)
    !$omp parallel do num_threads(2) schedule(dynamic, 1) private(fit)
    do k = 1, reps
      call fit_rider_friction(setups(k), options, mu_true, fit, status(k))
      mu(k) = fit%mu
      se(k) = merge(fit%standard_error, huge(1.0_wp), fit%covariance_valid)
      evaluations(k) = fit%evaluations
    end do
    !$omp end parallel do
    call cpu_time(cpu1)
    do k = 1, reps
      call check(status(k)%ok(), 'noisy fit: '//status(k)%text())
    end do
    call fit_rider_friction(setups(1), options, mu_true, serial, serial_status)
    call check(serial_status%ok() .and. serial%mu == mu(1) .and. serial%standard_error == se(1), &
               'a fit in 2 threads gives the same bits as serially')
    inside = count(abs(mu - mu_true) <= 3*se)
    spread = sqrt(sum((mu - sum(mu)/reps)**2)/(reps - 1))
    mean_se = sum(se)/reps
    print '(a, f8.5)', 'weight matching the noise: w_RP = ', options%weight
    print '(a, i0, a, i0, a, f7.2, a, i0, a)', '  ', inside, ' of ', reps, ' within 3 standard errors (', &
      cpu1 - cpu0, ' s CPU, ', sum(evaluations), ' rides)'
    print '(a, es12.4, a, es12.4)', '  spread of the estimates ', spread, ', mean standard error ', mean_se
    call check(inside >= 19, 'at least 19 of 20 noisy estimates within 3 standard errors')
    ! the sample deviation of 20 normal estimates lies within [0.60, 1.43]
    ! of the true one with 99 % probability (chi distribution, 19 dof)
    call check(spread >= 0.6_wp*mean_se .and. spread <= 1.43_wp*mean_se, &
               'spread of the estimates agrees with the standard errors')
  end subroutine with_noise

  subroutine body_sensitivity(setup)
    type(rider_identification_t), intent(in) :: setup
    type(rider_params_t) :: variants(2)
    real(wp) :: deviation(2)
    type(status_t) :: statuses(2), status
    variants = setup%params
    variants(2)%body%mass = 1.01_wp*setup%params%body%mass
    call rider_body_sensitivity(setup, variants, deviation, statuses, status)
    call check(status%ok() .and. statuses(1)%ok() .and. statuses(2)%ok(), 'body sensitivity: '//status%text())
    print '(a, es12.4, a)', 'body mass +1 %: pelvis deviation ', deviation(2), ' m'
    call check(deviation(1) == 0, 'the same body deviates by exactly 0')
    call check(deviation(2) > 0 .and. deviation(2) < 0.05_wp, 'a 1 % heavier body deviates by a little')
  end subroutine body_sensitivity
end program test_rider_identification
