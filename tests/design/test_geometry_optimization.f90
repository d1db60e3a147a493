!> Geometry optimisation of thesis table 4.12 (4.7, eq. 4.49; METHOD-PART2 E.6):
!> the 9-point slide, five rides of the 90 kg cuboid from 0.5 m/s at -30..30
!> degrees, the tipping lever arm at most 0.25 m by the thesis's penalty.
!> - the start design violates the lever-arm limit (as the thesis's does);
!> - the optimum lies inside the bounds, costs less than the start and meets
!>   the limit (to the penalty method's tolerance);
!> - the same optimum, to the bit, in 2 OpenMP threads as in one;
!> - the thesis's own optimum is evaluated too, and the direction of each
!>   coordinate's move is printed next to the thesis's (docs/design.md).
program test_geometry_optimization
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, design_evaluation_t, &
    table_4_12_design, evaluate_design, optimize_slide
  use testing, only: check, finish_tests
  implicit none (type, external)

  real(wp), parameter :: thesis_optimum(5) = [5.00599_wp, 5.1883_wp, 6.28544_wp, 8.68063_wp, 9.34626_wp]
  real(wp), parameter :: start(5) = [5.0_wp, 5.0_wp, 6.0_wp, 9.0_wp, 9.0_wp]
  type(optimization_setup_t) :: setup
  type(optimization_result_t) :: serial, threaded
  type(design_evaluation_t) :: thesis
  type(status_t) :: status
  real(wp) :: cpu0, cpu1
  integer :: i

  setup%design = table_4_12_design()
  setup%start_angles = [-30.0_wp, -15.0_wp, 0.0_wp, 15.0_wp, 30.0_wp]*pi/180

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

  setup%threads = 2
  call optimize_slide(setup, threaded, status)
  call check(status%ok(), 'optimisation in 2 threads: '//status%text())
  call check(all(threaded%x == serial%x) .and. threaded%evaluations == serial%evaluations, &
             'the same optimum, to the bit, in 2 threads')

  ! the thesis's optimum with our spline settings, for docs/design.md
  setup%threads = 1
  call evaluate_design(setup, thesis_optimum, thesis, status)
  call check(status%ok(), 'the thesis''s optimum can be ridden: '//status%text())
  print '(a, 2f10.2, a, f8.4, a)', 'thesis optimum with our spline: acceleration cost ', &
    thesis%acceleration_cost, serial%after%acceleration_cost, ' (ours), tipping excess ', &
    thesis%max_tipping_excess, ' m'
  call finish_tests('test_geometry_optimization')
end program test_geometry_optimization
