!> Twin experiments of the water-friction identification (thesis 4.4.1, cost
!> 4.34; METHOD-PART2 C.10) on the demo slide and on a second slide: the
!> "measurements" are simulated with the thesis's f (table 4.3) at 27
!> sections and on 5 segments of 2 m, then
!> - without noise, f1, f2, f3 are recovered from start values 50 % off;
!> - with Gaussian noise of 0.03 rad (positions) and 0.05 m/s (speeds), the
!>   thesis's residual scale, and the weight that matches it (w = 1/16, see
!>   below), in 20 seeded repetitions the estimates lie within 3 standard
!>   errors at least 19 times, and the spread of the 20 estimates agrees with
!>   the reported standard errors.
program test_water_identification
  use base_kinds, only: wp
  use base_status, only: status_t
  use io_input, only: input_text_t, load_input_file
  use scenarios_water, only: build_water
  use numerics_ode, only: ode_options_t
  use design_water_identification, only: water_identification_t, water_fit_options_t, water_fit_t, &
    new_water_identification, simulate_measurements, fit_water_friction
  use testing, only: check, check_close, finish_tests, failures
  use twin_data, only: noise_t, evenly
  implicit none (type, external)

  real(wp), parameter :: f_true(3) = [0.0274748_wp, 0.138285_wp, 0.979822_wp]   ! table 4.3
  real(wp), parameter :: sigma_v = 0.03_wp, sigma_w = 0.05_wp   ! rad, m/s
  type(water_identification_t) :: demo, second

  call make_setup('inputs/water/demo_slide.nml', demo)
  call make_setup('inputs/design/second_slide_water.nml', second)
  if (failures > 0) call finish_tests('test_water_identification')   ! no setup, nothing to fit
  call noise_free(demo, 'demo slide')
  call noise_free(second, 'second slide')
  call with_noise(demo, 'demo slide')
  call finish_tests('test_water_identification')

contains

  !> The slide, water start and model of a water input; 27 sections from 3 m
  !> to 3 m before the end, 5 segments of 2 m; noise-free measurements.
  subroutine make_setup(path, setup)
    character(len=*), intent(in) :: path
    type(water_identification_t), intent(out) :: setup
    type(input_text_t) :: input
    type(status_t) :: status
    real(wp) :: total, mid(5)
    call load_input_file(path, input, status)
    if (status%ok()) call build_water(input, setup%water, status)
    call check(status%ok(), path//': '//status%text())
    if (.not. status%ok()) return
    setup%ode = ode_options_t(rtol=1e-10_wp, atol=1e-9_wp)   ! the thesis's (C.4)
    total = setup%water%slide%length()
    setup%data%section_arc_length = evenly(3.0_wp, total - 3, 27)
    mid = evenly(0.1_wp*total, 0.9_wp*total, 5)
    setup%data%segment_start = mid - 1
    setup%data%segment_end = mid + 1
    allocate (setup%data%section_v(27), setup%data%segment_speed(5))
    setup%data%section_v = 0
    setup%data%segment_speed = 0
    call new_water_identification(setup, status)
    call check(status%ok(), path//': setup: '//status%text())
    if (status%ok()) call simulate_measurements(setup, f_true, setup%data%section_v, &
                                                setup%data%segment_speed, status)
    call check(status%ok(), path//': synthetic measurements: '//status%text())
  end subroutine make_setup

  subroutine noise_free(clean, name)
    type(water_identification_t), intent(in) :: clean
    character(len=*), intent(in) :: name
    type(water_identification_t) :: setup
    type(water_fit_options_t) :: options
    type(water_fit_t) :: fit
    type(status_t) :: status
    real(wp) :: cpu0, cpu1
    integer :: i
    setup = clean
    ! The recovery is limited by the integration's noise: a run's positions
    ! change by ~rtol at a change of f that changes its steps, which makes
    ! the cost flat within ~1e-15 around the truth at the thesis's rtol 1e-10
    ! (f known to only ~2e-6 there). The data and the fit are computed at
    ! rtol 1e-12 here, and the fit runs until its relative step is 1e-10.
    setup%ode = ode_options_t(rtol=1e-12_wp, atol=1e-12_wp)
    setup%data%section_v = 0
    call simulate_measurements(setup, f_true, setup%data%section_v, setup%data%segment_speed, status)
    options%solver%xtol = 1e-10_wp
    options%solver%ftol = 1e-14_wp
    call cpu_time(cpu0)
    call fit_water_friction(setup, options, f_true*[1.5_wp, 0.5_wp, 1.5_wp], fit, status)
    call cpu_time(cpu1)
    call check(status%ok(), name//': noise-free fit: '//status%text())
    print '(a, 3es16.8, a, i0, a, f7.3, a)', name//': f = ', fit%f, ', ', fit%evaluations, &
      ' runs, ', cpu1 - cpu0, ' s CPU'
    print '(a, 3es12.4, a, es10.3)', '   relative errors ', fit%f/f_true - 1, ', cost ', fit%cost
    print '(a, 3es12.4)', '   standard errors (s from the integration noise) ', fit%standard_error
    do i = 1, 3
      ! rtol 1e-12: f is fixed by the cost to ~1e-8 (see above); 1e-7 leaves
      ! room for the ill-conditioning of f1, f2, f3 (all multiply w^2)
      call check_close(fit%f(i), f_true(i), 1e-7_wp, 0.0_wp, name//': noise-free recovery of f')
    end do
  end subroutine noise_free

  subroutine with_noise(clean, name)
    type(water_identification_t), intent(in) :: clean
    character(len=*), intent(in) :: name
    integer, parameter :: reps = 20
    type(water_identification_t) :: setup
    type(water_fit_options_t) :: options
    type(water_fit_t) :: fit
    type(status_t) :: status
    type(noise_t) :: noise
    real(wp) :: f(3, reps), se(3, reps), spread(3), mean_se(3)
    integer :: k, i, inside, runs
    ! weighted residuals share one variance when (1-w)/n sigma_v^2 = w/m sigma_w^2
    options%weight = 1/(1 + (27*sigma_w**2)/(5*sigma_v**2))
    ! The noise is 1e6 times the integration error at rtol 1e-8, and the
    ! estimates scatter by ~1e-2 relative: integration at 1e-8, differences
    ! above its noise (epsfcn 1e-8: steps of 1e-4) and a stop at 1e-6
    ! relative change keep every figure compared here exact to < 1e-3 of a
    ! standard error, at a third of the cost.
    options%solver%ftol = 1e-6_wp
    options%solver%xtol = 1e-6_wp
    options%solver%epsfcn = 1e-8_wp
    print '(a, f8.5)', '  weight matching the noise: w = ', options%weight
    inside = 0
    runs = 0
    do k = 1, reps
      setup = clean
      setup%ode = ode_options_t(rtol=1e-8_wp, atol=1e-8_wp)
      do i = 1, 27
        setup%data%section_v(i) = clean%data%section_v(i) + sigma_v*noise%normal()
      end do
      do i = 1, 5
        setup%data%segment_speed(i) = clean%data%segment_speed(i) + sigma_w*noise%normal()
      end do
      call fit_water_friction(setup, options, f_true, fit, status)
      call check(status%ok() .and. fit%covariance_valid, name//': noisy fit: '//status%text())
      f(:, k) = fit%f
      se(:, k) = fit%standard_error
      runs = runs + fit%evaluations
      if (all(abs(fit%f - f_true) <= 3*fit%standard_error)) inside = inside + 1
    end do
    do i = 1, 3
      spread(i) = sqrt(sum((f(i, :) - sum(f(i, :))/reps)**2)/(reps - 1))
      mean_se(i) = sum(se(i, :))/reps
    end do
    print '(a, i0, a, i0, a, i0, a)', '  ', inside, ' of ', reps, ' within 3 standard errors (', runs, ' runs)'
    print '(a, 3es12.4)', '  spread of the estimates ', spread
    print '(a, 3es12.4)', '  mean standard error     ', mean_se
    call check(inside >= 19, name//': at least 19 of 20 noisy estimates within 3 standard errors')
    ! the sample deviation of 20 normal estimates lies within [0.60, 1.43]
    ! of the true one with 99 % probability (chi distribution, 19 dof)
    do i = 1, 3
      call check(spread(i) >= 0.6_wp*mean_se(i) .and. spread(i) <= 1.43_wp*mean_se(i), &
                 name//': spread of the estimates agrees with the standard errors')
    end do
  end subroutine with_noise
end program test_water_identification
