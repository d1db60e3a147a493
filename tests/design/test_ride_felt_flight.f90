!> What the ride report takes as felt in flight (issue 25; docs/rider.md
!> "What the felt figures cover"; rider_extremes' felt_basis):
!> - felt_basis for every set of open contacts: the model's with the pelvis
!>   and another contact on, a free fall (0 g) with all three open, not
!>   judged otherwise (the pelvis in the air with another contact on, or
!>   alone on the slide);
!> - extreme_quantities (what the ride locates on dense output): a free fall
!>   gives 0 g and no lever arm, a state not judged -huge (never a maximum);
!> - evaluate_ride on a recorded series whose artefacts (2.67 g braking and a
!>   20 m lever arm in the whole rider's flight, -0.96 g with the pelvis alone
!>   on the slide, jump.nml's figures on 2572e9e) are the series' extremes:
!>   the report's extremes, the limits' verdicts and the time not judged are
!>   those of the judged records, with 0 g in the free fall.
program test_ride_felt_flight
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use design_ride_evaluation, only: ride_limit_t, new_ride_limit
  use design_ride_report, only: ride_report_t, evaluate_ride
  use rider_extremes, only: felt_basis, extreme_quantities, FELT_MODEL, FELT_FREE_FALL, FELT_NOT_JUDGED, &
    N_EXTREMES, N_ATTACHED, EXTREME_FELT_MAX, EXTREME_FELT_MIN, EXTREME_LEVER, EXTREME_TOP_SPEED
  use rider_model, only: N_CONTACTS
  use rider_series, only: ride_series_t, size_series
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  real(wp), parameter :: g(3) = [0.0_wp, 0.0_wp, -standard_gravity]
  real(wp), parameter :: eye(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])

  call check_basis()
  call check_quantities()
  call check_report()
  call finish_tests('test_ride_felt_flight')

contains

  subroutine check_basis()
    ! bits: 1 pelvis, 2 heels, 4 back open
    integer, parameter :: expected(0:7) = [FELT_MODEL, FELT_NOT_JUDGED, FELT_MODEL, FELT_NOT_JUDGED, FELT_MODEL, &
                                           FELT_NOT_JUDGED, FELT_NOT_JUDGED, FELT_FREE_FALL]
    integer :: mask
    do mask = 0, 7
      call check(felt_basis(mask) == expected(mask), 'felt_basis of open contacts '//char(iachar('0') + mask))
    end do
  end subroutine check_basis

  !> One state, felt (-2.67, 0, 1) g with a 20 m lever arm, under each basis.
  subroutine check_quantities()
    real(wp) :: values(N_EXTREMES), attached(N_ATTACHED, N_EXTREMES), a(3)
    real(wp), parameter :: zero3(N_CONTACTS) = 0
    a = g + standard_gravity*[-2.67_wp, 0.0_wp, 1.0_wp]
    call extreme_quantities(5.0_wp, a, eye, [0.0_wp, 0.0_wp, 0.01_wp], [0.2_wp, 0.0_wp, 0.0_wp], 8.0_wp, zero3, &
                            zero3, zero3, g, 0, zero3, zero3, values, attached)
    call check_close(attached(1, EXTREME_FELT_MIN), -2.67_wp, 1e-14_wp, 0.0_wp, 'all on: the model''s felt')
    call check_close(values(EXTREME_LEVER), 20.0_wp, 1e-14_wp, 0.0_wp, 'all on: the model''s lever arm')
    call extreme_quantities(5.0_wp, a, eye, [0.0_wp, 0.0_wp, 0.01_wp], [0.2_wp, 0.0_wp, 0.0_wp], 8.0_wp, zero3, &
                            zero3, zero3, g, 7, zero3, zero3, values, attached)
    call check(all(values(EXTREME_FELT_MAX:EXTREME_FELT_MIN + 2) == 0) .and. &
               all(attached(1, EXTREME_FELT_MAX:EXTREME_FELT_MIN + 2) == 0), 'in the air: 0 g')
    call check(values(EXTREME_LEVER) == 0 .and. attached(1, EXTREME_LEVER) == 0, 'in the air: no lever arm')
    call check(values(EXTREME_TOP_SPEED) == 5, 'in the air: the speed counts')
    call extreme_quantities(5.0_wp, a, eye, [0.0_wp, 0.0_wp, 0.01_wp], [0.2_wp, 0.0_wp, 0.0_wp], 8.0_wp, zero3, &
                            zero3, zero3, g, 6, zero3, zero3, values, attached)
    call check(all(values(EXTREME_FELT_MAX:EXTREME_FELT_MIN + 2) == -huge(1.0_wp)) .and. &
               values(EXTREME_LEVER) == -huge(1.0_wp), 'pelvis alone on the slide: never a maximum')
    call check(values(EXTREME_TOP_SPEED) == 5, 'pelvis alone on the slide: the speed counts')
  end subroutine check_quantities

  !> Records (time, arc length, open contacts, felt, lever arm): all on; the
  !> heels open (judged); the pelvis alone on the slide (-0.96 g normal: not
  !> judged); the whole rider in the air (the model's 2.67 g braking and 20 m
  !> lever arm: 0 g, no lever arm); the pelvis and the back open (not
  !> judged); the back open (judged); all on.
  subroutine check_report()
    integer, parameter :: n = 8
    real(wp), parameter :: time(n) = [0.0_wp, 0.1_wp, 0.15_wp, 0.2_wp, 0.5_wp, 0.6_wp, 0.62_wp, 0.7_wp]
    integer, parameter :: open(n) = [0, 2, 6, 7, 7, 5, 4, 0]
    real(wp), parameter :: felt(3, n) = reshape([ &
      -0.05_wp, 0.0_wp, 1.0_wp, -0.2_wp, 0.0_wp, 1.0_wp, -0.56_wp, 0.0_wp, -0.96_wp, -0.56_wp, 0.0_wp, -0.96_wp, &
      -2.67_wp, 0.1_wp, 0.5_wp, 0.46_wp, 0.0_wp, 3.7_wp, -0.3_wp, -0.02_wp, 1.5_wp, -0.1_wp, 0.0_wp, 1.0_wp], [3, n])
    real(wp), parameter :: lever(n) = [0.0_wp, 0.0_wp, 5.0_wp, 20.0_wp, 20.0_wp, 3.0_wp, 0.1_wp, 0.0_wp]
    type(ride_series_t) :: s
    type(ride_report_t) :: r
    type(ride_limit_t) :: limits(3)
    character(len=:), allocatable :: problem
    integer :: i, k
    call size_series(s, n, 1)
    s%n = n
    do i = 1, n
      s%time(i) = time(i)
      s%arc_length(i) = 10*time(i)
      s%speed(i) = 10
      s%airborne(i) = open(i)
      s%pelvis_axes(:, :, i) = eye
      s%pelvis_acceleration(:, i) = g + standard_gravity*felt(:, i)
      s%reaction_force(:, i) = [0.0_wp, 0.0_wp, 100.0_wp]
      s%reaction_moment(:, i) = [100*lever(i), 0.0_wp, 0.0_wp]
      do k = 1, N_CONTACTS
        s%contact(k)%wall_angle(i) = 0
        s%contact(k)%wall_distance(i) = 0
        s%contact(k)%normal_force(i) = 100
      end do
    end do
    call new_ride_limit('acceleration_longitudinal', 'g', -1.0_wp, .true., 0.0_wp, .false., standard_gravity, &
                        limits(1), problem)
    call new_ride_limit('acceleration_normal', 'g', 0.2_wp, .true., 0.0_wp, .false., standard_gravity, limits(2), &
                        problem)
    call new_ride_limit('lever_arm', 'm', 0.0_wp, .false., 0.25_wp, .true., standard_gravity, limits(3), problem)
    call evaluate_ride(s, g, .true., limits, r)
    ! braking: -0.3 g with the back open at 6.2 m, not the flight's -2.67 g (or -0.56 g with the pelvis alone)
    call check_close(r%felt_min(1), -0.3_wp, 1e-14_wp, 0.0_wp, 'braking max: the judged records''')
    call check_close(r%felt_min_at(1), 6.2_wp, 1e-14_wp, 0.0_wp, 'braking max: where')
    ! pushing: 0 in the air at 2 m (the flight's first record), not the pelvis-and-back-open 0.46 g
    call check(r%felt_max(1) == 0 .and. abs(r%felt_max_at(1) - 2) < 1e-14_wp, 'pushing max: the free fall''s 0 g')
    call check(r%felt_max(2) == 0 .and. abs(r%felt_min(2) + 0.02_wp) < 1e-14_wp, &
               'lateral: 0 in the air, -0.02 g with the back open, not the model''s 0.1 g in the air')
    call check(r%felt_min(3) == 0 .and. abs(r%felt_min_at(3) - 2) < 1e-14_wp, &
               'normal min: the free fall''s 0 g at its take-off, not -0.96 g (pelvis alone on the slide)')
    call check_close(r%felt_max(3), 1.5_wp, 1e-14_wp, 0.0_wp, 'normal max: 1.5 g, not 3.7 g (pelvis open)')
    call check_close(r%lever_max, 0.1_wp, 1e-12_wp, 0.0_wp, 'lever arm: 0.1 m (back open), not 20 m in the air')
    call check_close(r%not_judged_time, (0.2_wp - 0.15_wp) + (0.62_wp - 0.6_wp), 1e-14_wp, 0.0_wp, &
                     'time not judged: the pelvis alone on the slide, the pelvis and the back open')
    call check(count(r%felt_judged) == 6, 'six records judged')
    call check(.not. r%verdicts(1)%exceeded, 'braking limit 1 g: not exceeded by the flight''s 2.67 g')
    call check(r%verdicts(2)%exceeded .and. r%verdicts(2)%first_where == 2 .and. r%verdicts(2)%worst == 0, &
               'normal >= 0.2 g: exceeded where the free fall begins (0 g), not at -0.96 g')
    call check(.not. r%verdicts(3)%exceeded, 'lever arm <= 0.25 m: not exceeded by the flight''s 20 m')
  end subroutine check_report
end program test_ride_felt_flight
