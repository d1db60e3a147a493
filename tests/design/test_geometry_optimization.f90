!> Geometry optimisation of thesis table 4.12 (4.7, eq. 4.49; METHOD-PART2 E.6):
!> the 9-point slide, five rides of the 90 kg cuboid from 0.5 m/s at -30..30
!> degrees, the tipping lever arm at most 0.25 m by the thesis's penalty.
!> - the start design violates the lever-arm limit (as the thesis's does);
!> - the optimum lies inside the bounds, costs less than the start and meets
!>   the limit (to the penalty method's tolerance);
!> - the same optimum, to the bit, in 2 OpenMP threads as in one;
!> - the thesis's own optimum is evaluated too, and the direction of each
!>   coordinate's move is printed next to the thesis's (docs/design.md);
!> - the end is checked: a restart from it changes the cost by at most ftol,
!>   MINPACK's stop is said in words, the constraints hold (outcome optimum);
!> - issue 27's early stop (start at 1.2 m/s, bounds +-0.4 m: LMDER ends on
!>   its xtol test at cost ~1880, a restart goes on to ~700) is no optimum
!>   when only one restart is allowed;
!> - multi-start: the start points are drawn from the seed inside the
!>   bounds, start 1 is the given design; the same seed gives the same
!>   result, in 1 thread as in 2.
program test_geometry_optimization
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, design_evaluation_t, &
    table_4_12_design, thesis_start_angles, evaluate_design, optimize_slide, start_points, OUTCOME_OPTIMUM, OUTCOME_NOT_MINIMUM
  use testing, only: check, finish_tests
  implicit none (type, external)

  real(wp), parameter :: thesis_optimum(5) = [5.00599_wp, 5.1883_wp, 6.28544_wp, 8.68063_wp, 9.34626_wp]
  real(wp), parameter :: start(5) = [5.0_wp, 5.0_wp, 6.0_wp, 9.0_wp, 9.0_wp]
  type(optimization_setup_t) :: setup
  type(optimization_result_t) :: serial, threaded, early
  type(design_evaluation_t) :: thesis
  type(status_t) :: status
  real(wp) :: cpu0, cpu1
  integer :: i

  setup%design = table_4_12_design()
  setup%start_angles = thesis_start_angles()

  call cpu_time(cpu0)
  call optimize_slide(setup, serial, status)
  call cpu_time(cpu1)
  call check(status%ok(), 'optimisation: '//status%text())
  if (.not. status%ok()) call finish_tests('test_geometry_optimization')
  print '(a, f7.3, a, i0, a, i0, a)', 'optimisation: ', cpu1 - cpu0, ' s CPU, ', serial%evaluations, &
    ' designs (', serial%rejected, ' rejected)'
  print '(a)', '  ride   max|a| before  after (m/s^2)   tipping excess before  after (m)'
  do i = 1, 5
    print '(i6, 2f12.3, 2f14.4)', i, serial%before%rides(i)%max_acceleration, serial%after%rides(i)%max_acceleration, &
      serial%before%rides(i)%max_tipping_excess, serial%after%rides(i)%max_tipping_excess
  end do
  print '(a)', '  coordinate   start   optimum   move   thesis move'
  do i = 1, 5
    print '(i8, 4f9.4)', i, start(i), serial%x(i), serial%x(i) - start(i), thesis_optimum(i) - start(i)
  end do

  call check(all(serial%before%rides%reached_end), 'every ride of the start design reaches the end')
  ! the thesis (fig. 4.28): before optimisation the lever arms exceed 0.25 m
  call check(serial%before%max_tipping_excess > 0, 'the start design violates the lever-arm limit')
  call check(all(serial%x >= setup%design%lower .and. serial%x <= setup%design%upper), &
             'the optimum lies inside the bounds')
  call check(serial%cost_after < serial%cost_before, 'the optimum costs less than the start')
  call check(serial%after%acceleration_cost < serial%before%acceleration_cost, &
             'the optimum has lower accelerations than the start')
  ! penalty: a violation g costs 5e3 g; LMDER stops at ftol 1e-4 of a cost of
  ! ~600, i.e. a violation of ~1e-5 m could remain: 1e-3 m is ample
  call check(serial%after%max_tipping_excess <= 1e-3_wp, &
             'every lever arm of the optimum at most 0.25 m (tipping excess <= 1e-3 m)')
  call check(all(.not. serial%after%rides%lifts_off), 'no ride of the optimum lifts off')
  ! the end checked and said
  call check(serial%outcome == OUTCOME_OPTIMUM .and. serial%restarts >= 1, &
             'the optimum: a minimum by a restart from its end, the constraints hold: '//serial%verdict)
  call check(len(serial%violations) == 0, 'no constraint violated at the optimum')
  call check(index(serial%stop_reason, ' test (info ') > 0, 'MINPACK''s stop said in words: '//serial%stop_reason)
  print '(a)', 'stop: '//serial%stop_reason
  print '(a)', 'check: '//serial%minimum_check

  setup%threads = 2
  call optimize_slide(setup, threaded, status)
  call check(status%ok(), 'optimisation in 2 threads: '//status%text())
  call check(all(threaded%x == serial%x) .and. threaded%evaluations == serial%evaluations .and. &
             threaded%restarts == serial%restarts, 'the same optimum, to the bit, in 2 threads')

  ! the thesis's optimum with our spline settings, for docs/design.md
  setup%threads = 1
  call evaluate_design(setup, thesis_optimum, thesis, status)
  call check(status%ok(), 'the thesis''s optimum can be ridden: '//status%text())
  print '(a, 2f10.2, a, f8.4, a)', 'thesis optimum with our spline: acceleration cost ', &
    thesis%acceleration_cost, serial%after%acceleration_cost, ' (ours), tipping excess ', &
    thesis%max_tipping_excess, ' m'

  call early_stop()
  call multi_start()
  call finish_tests('test_geometry_optimization')

contains

  !> Issue 27: from 1.2 m/s within +-0.4 m LMDER ends on its xtol test at a
  !> cost of ~1880 with a ride lifting off; a restart from there lowers the
  !> cost by more than half. With one restart allowed the end is no minimum.
  subroutine early_stop()
    type(optimization_setup_t) :: s
    s%design = table_4_12_design()
    s%design%lower = start - 0.4_wp
    s%design%upper = start + 0.4_wp
    s%start_angles = thesis_start_angles()
    s%start_speed = 1.2_wp
    s%max_restarts = 1
    call optimize_slide(s, early, status)
    call check(status%ok(), 'early stop: an end point: '//status%text())
    if (.not. status%ok()) return
    print '(a)', 'early stop: '//early%verdict
    call check(early%stop_test == 'xtol' .and. index(early%stop_reason, 'xtol test (info 2)') > 0, &
               'early stop: MINPACK''s first stop is its xtol test, said in words: '//early%stop_reason)
    call check(early%outcome == OUTCOME_NOT_MINIMUM .and. index(early%verdict, 'not a minimum') == 1 .and. &
               index(early%minimum_check, 'max_restarts = 1') > 0 .and. &
               index(early%minimum_check, 'restart 1 lowered the cost') > 0, &
               'early stop: reported as not a minimum (the restart still lowers the cost): '//early%verdict)
    ! the restart went on from the first end (cost ~1880) to well below it
    call check(early%cost_after < 0.6_wp*1880, 'early stop: the restart lowered the cost by more than 40 %')
  end subroutine early_stop

  !> Three starts of a small problem (three rides, loose tolerances): the
  !> given design and two drawn ones, the same in 1 and 2 threads and again
  !> for the same seed.
  subroutine multi_start()
    type(optimization_setup_t) :: s
    type(optimization_result_t) :: one, two, again
    real(wp), allocatable :: p(:, :), q(:, :)
    integer :: k
    s%design = table_4_12_design()
    s%start_angles = [-20.0_wp, 0.0_wp, 20.0_wp]*pi/180
    s%solver%ftol = 1e-2_wp
    s%solver%xtol = 1e-2_wp
    s%starts = 3
    s%seed = 11
    p = start_points(s%design, 3, 11)
    q = start_points(s%design, 3, 12)
    call check(all(p(:, 1) == start), 'multi-start: start 1 is the given design')
    call check(all([(all(p(:, k) > s%design%lower .and. p(:, k) < s%design%upper), k=2, 3)]), &
               'multi-start: the drawn starts lie inside the bounds')
    call check(any(p(:, 2:) /= q(:, 2:)) .and. any(p(:, 2) /= p(:, 3)), &
               'multi-start: other seeds and other starts give other points')
    call optimize_slide(s, one, status)
    call check(status%ok(), 'multi-start in 1 thread: '//status%text())
    if (.not. status%ok()) return
    s%threads = 2
    call optimize_slide(s, two, status)
    call check(status%ok(), 'multi-start in 2 threads: '//status%text())
    s%threads = 1
    call optimize_slide(s, again, status)
    call check(status%ok(), 'multi-start again: '//status%text())
    if (.not. status%ok()) return
    print '(a, 3es14.6, a, i0)', 'multi-start: costs ', one%starts%cost, ', best ', one%best_start
    do k = 1, 3
      print '(a)', '  start: '//one%starts(k)%verdict
    end do
    call check(size(one%starts) == 3 .and. all(one%starts(1)%x_start == start), &
               'multi-start: three starts reported, the first the given design')
    do k = 1, 3
      call check(all(one%starts(k)%x_start == p(:, k)), 'multi-start: start points from the seed')
    end do
    call check(one%starts(one%best_start)%acceleration_cost <= minval(one%starts%acceleration_cost, &
               one%starts%outcome == one%outcome), 'multi-start: the best start has the least cost of its outcome')
    call check(same(one, two), 'multi-start: the same starts, ends and costs, to the bit, in 2 threads')
    call check(same(one, again), 'multi-start: the same seed gives the same result')
  end subroutine multi_start

  logical function same(a, b)
    type(optimization_result_t), intent(in) :: a, b
    integer :: k
    same = size(a%starts) == size(b%starts) .and. a%best_start == b%best_start .and. all(a%x == b%x)
    if (.not. same) return
    do k = 1, size(a%starts)
      same = same .and. all(a%starts(k)%x == b%starts(k)%x) .and. a%starts(k)%cost == b%starts(k)%cost .and. &
             a%starts(k)%outcome == b%starts(k)%outcome .and. a%starts(k)%evaluations == b%starts(k)%evaluations
    end do
  end function same
end program test_geometry_optimization
