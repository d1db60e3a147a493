!> One ride as a library call (design_ride_job): run_ride gives, to the bit,
!> what the water, the rider and the report give when called one by one
!> (its water computed, a water given, a dry ride); a water that fails
!> stops before the rider and says so; the progress lines go to the
!> caller's log and nowhere without one (ctest fails this test on any
!> 'unasked:' line in its output: tests/CMakeLists.txt); the report's
!> extremes do not depend on the output step (located between the records).
!> The cuboid of the geometry optimisation (BODY_CUBOID) rides through
!> run_ride too: the same figures as design_cuboid_ride's ride_cuboid, to
!> the bit, the closed form on a straight incline, a water or limits refused.
program test_ride_job
  use base_kinds, only: wp
  use base_status, only: status_t
  use rider_ride, only: ride_result_t, simulate_ride
  use water_run, only: water_result_t, compute_water
  use design_ride_evaluation, only: new_ride_limit
  use design_ride_report, only: ride_report_t, evaluate_ride
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride, BODY_CUBOID
  use design_cuboid_ride, only: cuboid_ride_t, ride_cuboid
  use geometry_tube, only: tube_surface_t, new_straight_tube
  use base_constants, only: standard_gravity
  use io_input, only: input_text_t, input_from_text
  use scenarios_water, only: build_water
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(ride_description_t) :: description
  type(status_t) :: status
  character(len=:), allocatable :: logged   !< the lines the log below received
  character(len=*), parameter :: nl = new_line('a')

  call prepare(description, status)
  call check(status%ok(), 'the demo slide and its water description: '//status%text())
  if (status%ok()) then
    call check_against_parts(description)
    call check_water_failure(description)
    call check_log(description)
    call check_extremes_between_records(description)
  end if
  call check_cuboid()
  call finish_tests('test_ride_job')

contains

  !> The demo slide and its water (0.004 m^3/s), the default rider, a
  !> 2.5 s bound (short), one limit.
  subroutine prepare(description, status)
    type(ride_description_t), intent(out) :: description
    type(status_t), intent(inout) :: status
    type(input_text_t) :: input
    character(len=:), allocatable :: problem
    call input_from_text('test_ride_job', '&surface kind = ''slide'', geometry_file = ''builtin:demo_slide'' /'// &
                         nl//'&water flow_rate = 0.004, start = ''edges'', u0 = 0.0, '// &
                         'v_left0 = 1.9207963267948966, v_right0 = 1.2207963267948966 /'//nl, input, status)
    if (status%ok()) call build_water(input, description%water, status, stage=.true.)
    description%options%max_duration = 2.5_wp
    allocate (description%limits(1))
    call new_ride_limit('speed', 'm/s', 0.0_wp, .false., 2.0_wp, .true., 9.80665_wp, description%limits(1), &
                        problem)
  end subroutine prepare

  !> run_ride against compute_water, rider_ride's run and evaluate_ride.
  subroutine check_against_parts(description)
    type(ride_description_t), intent(in) :: description
    type(ride_description_t) :: dry
    type(ride_job_result_t) :: job, given, dry_job
    type(water_result_t) :: water
    type(ride_result_t) :: ride
    type(ride_report_t) :: report
    type(status_t) :: st

    call compute_water(description%water, water, st)
    call simulate_ride(description%rider, description%water%slide, description%options, ride, st, water%field)
    call evaluate_ride(ride%series, description%rider%gravity, ride%complete, description%limits, report)
    call check(st%ok(), 'the parts run: '//st%text())

    job = run_ride(description)
    call check(job%status%ok() .and. job%ridden, 'run_ride runs: '//job%status%text())
    call check(job%stopped == ride%outcome .and. index(job%stopped, 'had not ended after 2.5') > 0 .and. &
               .not. job%complete, 'how it stopped, as the rider says: '//job%stopped)
    call check(job%water_outcome == 'end of slide', 'the water reached the end: '//job%water_outcome)
    call check(same_ride(job%ride, ride), 'its water computed: the ride to the bit')
    call check(same_report(job%report, report), 'its water computed: the report to the bit')
    call check(job%water%series%n == water%series%n .and. job%water_cpu == job%water%cpu .and. &
               job%ride_cpu >= 0, 'the water and the CPU times are kept')

    given = run_ride(description, water%field)
    call check(given%status%ok() .and. same_ride(given%ride, ride) .and. same_report(given%report, report), &
               'a water given: the same ride and report to the bit')
    call check(given%water%series%n == 0 .and. given%water_outcome == '' .and. given%water_cpu == 0, &
               'a water given is not computed again')

    dry = description
    dry%with_water = .false.
    call simulate_ride(description%rider, description%water%slide, description%options, ride, st)
    dry_job = run_ride(dry, water%field)
    call check(dry_job%status%ok() .and. same_ride(dry_job%ride, ride), 'a dry ride: the rider without water')
    call check(any(dry_job%ride%series%speed(:ride%series%n) /= job%ride%series%speed(:ride%series%n)) .or. &
               dry_job%ride%series%n /= job%ride%series%n, 'a dry ride differs from one in the water')
  end subroutine check_against_parts

  !> The report's extremes located between the records (docs/accuracy.md):
  !> records 0.01 s and 0.0025 s apart (the same internal steps: outputs are
  !> interpolated) give the same extremes to 1e-7 relative (the integration's
  !> accuracy at the default rtol 1e-10, docs/accuracy.md; the study finds
  !> them within 1e-9 across output steps at rtol 1e-12; plus 1e-9 in their
  !> unit, the atol: the lateral felt g of this straight start is ~3e-9 g,
  !> zero to the integration's accuracy), while the records'
  !> own extremes differ by more than 1e-6 (checked: this is what the test
  !> would see with extremes over the records, ~1e-4). Every located extreme
  !> is at least as extreme as the records'.
  subroutine check_extremes_between_records(description)
    type(ride_description_t), intent(in) :: description
    type(ride_description_t) :: fine
    type(ride_job_result_t) :: coarse_job, fine_job
    real(wp) :: a(10), b(10)
    fine = description
    fine%options%output_step = 0.0025_wp
    coarse_job = run_ride(description)
    fine_job = run_ride(fine)
    call check(coarse_job%status%ok() .and. fine_job%status%ok(), 'rides at two output steps: '// &
               coarse_job%status%text()//fine_job%status%text())
    if (.not. (coarse_job%status%ok() .and. fine_job%status%ok())) return
    a = located(coarse_job)
    b = located(fine_job)
    if (.not. all(abs(a - b) <= 1e-7_wp*abs(b) + 1e-9_wp)) print '(a, 10es24.16)', 'located at 0.01 s:   ', a, &
      'located at 0.0025 s: ', b
    call check(all(abs(a - b) <= 1e-7_wp*abs(b) + 1e-9_wp), 'the extremes do not depend on the output step')
    call check(abs(coarse_job%report%lever_max - fine_job%report%lever_max) <= 1e-7_wp*abs(fine_job%report%lever_max) &
               .and. all(abs(coarse_job%report%climb_angle - fine_job%report%climb_angle) <= &
                         1e-7_wp*abs(fine_job%report%climb_angle)), &
               'the lever arm and the wall angles do not depend on the output step')
    a = over_records(coarse_job)
    b = over_records(fine_job)
    call check(any(abs(a - b) > 1e-6_wp*abs(b)), 'test set-up: the records'' own extremes depend on the output step')
    call check(all(located(coarse_job) >= over_records(coarse_job)) .and. &
               all(located(fine_job) >= over_records(fine_job)), 'the located extremes are at least the records''')
  end subroutine check_extremes_between_records

  !> top speed, felt maxima, minus felt minima, minus smallest normal forces
  function located(job) result(x)
    type(ride_job_result_t), intent(in) :: job
    real(wp) :: x(10)
    associate (r => job%report)
      x = [r%top_speed, r%felt_max, -r%felt_min, -r%normal_min]
    end associate
  end function located

  !> the same over the records alone
  function over_records(job) result(x)
    type(ride_job_result_t), intent(in) :: job
    real(wp) :: x(10)
    integer :: k, n
    n = job%ride%series%n
    x(1) = maxval(job%ride%series%speed(:n))
    do k = 1, 3
      x(1 + k) = maxval(job%report%felt(k, :n))
      x(4 + k) = -minval(job%report%felt(k, :n))
      x(7 + k) = -minval(job%ride%series%contact(k)%normal_force(:n))
    end do
  end function over_records

  !> 0.002 m^3/s is critical at the start (test_sweep): the water fails,
  !> the rider does not run, the status says which stage failed.
  subroutine check_water_failure(description)
    type(ride_description_t), intent(in) :: description
    type(ride_description_t) :: critical
    type(ride_job_result_t) :: job
    critical = description
    critical%water%flow_rate = 0.002_wp
    job = run_ride(critical)
    call check(.not. job%status%ok() .and. index(job%status%text(), 'the water') == 1 .and. &
               index(job%status%text(), 'critical') > 0, 'a failing water: '//job%status%text())
    call check(.not. job%ridden .and. job%stopped == '' .and. job%ride%series%n == 0, &
               'a failing water: no ride')
  end subroutine check_water_failure

  !> The stage lines and the integrator's progress lines (every 1e-9 s of
  !> wall clock: at every look) reach the log; without a log none is made
  !> (the label 'unasked' would show in this test's output).
  subroutine check_log(description)
    type(ride_description_t), intent(in) :: description
    type(ride_description_t) :: asked, unasked
    type(ride_job_result_t) :: job
    asked = description
    asked%options%progress_seconds = 1e-9_wp
    asked%log => collect
    logged = ''
    job = run_ride(asked)
    call check(job%status%ok(), 'with a log: runs')
    call check(index(logged, 'ride: the water first (0.004 m^3/s)'//nl//'ride: the rider'//nl) == 1, &
               'the stages reach the log: '//logged(:min(len(logged), 80)))
    call check(index(logged, 'ride: the rider'//nl//'ride: ') > 0 .and. index(logged, ' % (') > 0, &
               'the integrator''s progress lines reach the log')
    unasked = description
    unasked%options%progress_seconds = 1e-9_wp
    unasked%label = 'unasked'
    logged = ''
    job = run_ride(unasked)
    call check(job%status%ok() .and. logged == '', 'without a log: runs, nothing logged')
  end subroutine check_log

  !> The cuboid down a straight tube inclined by 0.3 rad, 4 m, from the
  !> bottom at 0.5 m/s along the slide: no friction, so it moves along the
  !> bottom line with a = g sin(0.3), and reaches the end at
  !> T = (sqrt(v0^2 + 2 g sin(0.3) L) - v0)/(g sin(0.3)). The integration
  !> (rtol = atol = 1e-7) and the end's root keep T and the speed to ~1e-7
  !> relative, so 1e-6 holds and a wrong sign or factor fails it.
  subroutine check_cuboid()
    real(wp), parameter :: incline = 0.3_wp, length = 4, v0 = 0.5_wp
    type(tube_surface_t) :: tube
    type(ride_description_t) :: cuboid, wet, judged
    type(ride_job_result_t) :: job, refused
    type(cuboid_ride_t) :: direct
    type(status_t) :: st
    real(wp) :: a, t_end
    tube = new_straight_tube(0.5_wp, incline, length, st)
    call check(st%ok(), 'the straight tube: '//st%text())
    if (.not. st%ok()) return
    cuboid%body = BODY_CUBOID
    cuboid%with_water = .false.
    allocate (cuboid%water%slide, source=tube)
    cuboid%cuboid_start%u = 0
    cuboid%cuboid_start%speed = v0
    cuboid%cuboid_options%keep_series = .true.
    cuboid%label = 'unasked'
    job = run_ride(cuboid)
    call check(job%status%ok() .and. job%ridden .and. job%complete, 'the cuboid rides: '//job%status%text())
    if (.not. job%status%ok()) return
    call ride_cuboid(tube, cuboid%cuboid, cuboid%cuboid_start, length, cuboid%cuboid_options, direct, st)
    call check(st%ok() .and. job%cuboid%max_acceleration == direct%max_acceleration .and. &
               job%cuboid%max_tipping_excess == direct%max_tipping_excess .and. &
               job%cuboid%duration == direct%duration .and. job%cuboid%end_speed == direct%end_speed .and. &
               job%cuboid%rhs_evaluations == direct%rhs_evaluations .and. job%cuboid%series%n == direct%series%n, &
               'run_ride gives ride_cuboid''s figures to the bit')
    a = standard_gravity*sin(incline)
    t_end = (sqrt(v0**2 + 2*a*length) - v0)/a
    call check(abs(job%cuboid%duration - t_end) <= 1e-6_wp*t_end, 'the end at the closed-form time')
    call check(abs(job%cuboid%end_speed - (v0 + a*t_end)) <= 1e-6_wp*(v0 + a*t_end), &
               'the end speed, closed form')
    call check(abs(job%cuboid%max_acceleration - a) <= 1e-6_wp*a, 'the acceleration g sin(incline)')
    call check(index(job%stopped, 'end of the slide') == 1 .and. job%ride%series%n == 0, &
               'how it stopped; no rider ride: '//job%stopped)

    wet = cuboid
    wet%with_water = .true.
    refused = run_ride(wet)
    call check(.not. refused%status%ok() .and. .not. refused%ridden .and. &
               index(refused%status%text(), 'the cuboid rides dry') > 0, 'a water refused: '//refused%status%text())
    judged = cuboid
    allocate (judged%limits(1))
    refused = run_ride(judged)
    call check(.not. refused%status%ok() .and. .not. refused%ridden .and. &
               index(refused%status%text(), 'limits') > 0, 'limits refused: '//refused%status%text())
  end subroutine check_cuboid

  subroutine collect(message)
    character(len=*), intent(in) :: message
    logged = logged//message//nl
  end subroutine collect

  logical function same_ride(a, b)
    type(ride_result_t), intent(in) :: a, b
    integer :: n
    n = b%series%n
    same_ride = a%series%n == n .and. a%outcome == b%outcome .and. (a%complete .eqv. b%complete) .and. &
                a%drag_switches == b%drag_switches .and. a%driver%stats%steps == b%driver%stats%steps
    if (same_ride) same_ride = all(a%series%time(:n) == b%series%time(:n)) .and. &
                               all(a%series%state(:, :n) == b%series%state(:, :n)) .and. &
                               all(a%series%speed(:n) == b%series%speed(:n))
  end function same_ride

  logical function same_report(a, b)
    type(ride_report_t), intent(in) :: a, b
    same_report = a%n == b%n .and. a%top_speed == b%top_speed .and. a%final_speed == b%final_speed .and. &
                  all(a%felt_max == b%felt_max) .and. a%lever_max == b%lever_max .and. &
                  all(a%normal_min == b%normal_min) .and. size(a%verdicts) == size(b%verdicts)
    if (same_report) same_report = all(a%felt(:, :a%n) == b%felt(:, :b%n)) .and. &
                                   (a%verdicts(1)%exceeded .eqv. b%verdicts(1)%exceeded) .and. &
                                   a%verdicts(1)%worst == b%verdicts(1)%worst
  end function same_report
end program test_ride_job
