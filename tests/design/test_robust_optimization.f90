!> Robust design over a population (design_robust_cost; docs/design.md,
!> "Robust design over a population"), checked against known answers:
!> - the quantile against hand-computed order statistics (numpy's default,
!>   Hyndman and Fan 7), q = 1 the maximum exactly;
!> - each member's ride in a population is the ride of an ordinary
!>   optimisation with that member's body and start, to the bit;
!> - the worst-case cost of a design is 1/2 (max over the members ridden one
!>   by one)^2, the quantile cost 1/2 (their quantile)^2, the worst ride the
!>   argmax, to the bit;
!> - the sum over a population of the five start angles is the ordinary
!>   (4.49), to the bit;
!> - a population of one member (worst case, or any quantile) is the
!>   ordinary optimisation of its one ride: the same end, cost and designs,
!>   to the bit;
!> - a population with two starts gives the same bits in 2 threads as in 1.
program test_robust_optimization
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use design_robust_cost, only: ride_member_t, quantile, COST_SUM, COST_WORST, COST_QUANTILE
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, design_evaluation_t, &
    table_4_12_design, thesis_start_angles, evaluate_design, optimize_slide
  use design_sweep, only: N_SWEPT, V_MASS, V_HEIGHT, V_V0, V_HEADING, V_SPEED, swept_values_t, sweep_rows
  use design_population, only: population_base, set_population
  use testing, only: check, finish_tests
  implicit none (type, external)

  type(optimization_setup_t) :: base
  integer :: i

  call quantile_known_values()
  call population_from_rows()
  ! a small problem: table 4.12 with two design variables (P3.y, P4.x)
  base%design = table_4_12_design()
  base%design%point = base%design%point(2:3)
  base%design%coordinate = base%design%coordinate(2:3)
  base%design%lower = base%design%lower(2:3)
  base%design%upper = base%design%upper(2:3)
  base%start_angles = [15.0_wp*pi/180]
  call members_are_rides()
  call sum_of_start_angles()
  call population_of_one()
  call threads_same_bits()
  call finish_tests('test_robust_optimization')

contains

  !> A population from a sweep's lists (design_sweep's sweep_rows,
  !> design_population's set_population), by hand: two persons (mass and
  !> height paired) crossed with two speeds are four rows, the slower speed
  !> first; without heading0_deg each row rides from each of three start
  !> angles (the angles fastest), with it from its own; a member's width,
  !> thickness and centre-of-mass height scale with its height, its start v
  !> and speed are its row's, what is not swept the optimiser's.
  subroutine population_from_rows()
    type(optimization_setup_t) :: setup
    type(swept_values_t) :: lists(N_SWEPT)
    logical :: together(N_SWEPT)
    real(wp) :: b(N_SWEPT), angles(3)
    real(wp), allocatable :: rows(:, :)
    integer :: k, j
    setup%body%length = 2
    setup%body%width = 0.6_wp
    setup%body%height = 0.3_wp
    setup%body%com_height = 0.12_wp
    setup%start_v = 1.5_wp
    angles = [-0.2_wp, 0.0_wp, 0.3_wp]
    setup%start_angles = angles
    b = population_base(setup)
    call check(b(V_MASS) == setup%body%mass .and. b(V_HEIGHT) == 2 .and. b(V_V0) == 1.5_wp .and. &
               b(V_SPEED) == setup%start_speed, 'population_base: the optimiser''s body and start')
    do k = 1, N_SWEPT
      lists(k)%x = [b(k)]
    end do
    lists(V_MASS)%x = [60.0_wp, 80.0_wp]
    lists(V_HEIGHT)%x = [1.5_wp, 1.9_wp]
    lists(V_SPEED)%x = [0.4_wp, 0.8_wp]
    together = .false.
    together([V_MASS, V_HEIGHT]) = .true.
    rows = sweep_rows(lists, together)
    call check(size(rows, 2) == 4, 'two persons x two speeds: four rows')
    call check(all(rows(V_MASS, :) == [60.0_wp, 60.0_wp, 80.0_wp, 80.0_wp]) .and. &
               all(rows(V_HEIGHT, :) == [1.5_wp, 1.5_wp, 1.9_wp, 1.9_wp]) .and. &
               all(rows(V_SPEED, :) == [0.4_wp, 0.8_wp, 0.4_wp, 0.8_wp]), &
               'the paired axis slowest, the speeds fastest')
    call set_population(setup, rows, heading_swept=.false.)
    call check(size(setup%members) == 12 .and. size(setup%start_angles) == 12, &
               'four rows from three angles: twelve members')
    do k = 1, 4
      do j = 1, 3
        associate (m => setup%members(3*(k - 1) + j))
          call check(setup%start_angles(3*(k - 1) + j) == angles(j), 'member of row and angle: its angle')
          call check(m%body%mass == rows(V_MASS, k) .and. m%height == rows(V_HEIGHT, k) .and. &
                     m%body%length == rows(V_HEIGHT, k) .and. m%speed == rows(V_SPEED, k) .and. m%v == 1.5_wp, &
                     'member of row and angle: its row''s mass, height, speed and start')
          call check(abs(m%body%width - 0.3_wp*rows(V_HEIGHT, k)) < 1e-15_wp .and. &
                     abs(m%body%height - 0.15_wp*rows(V_HEIGHT, k)) < 1e-15_wp .and. &
                     abs(m%body%com_height - 0.06_wp*rows(V_HEIGHT, k)) < 1e-15_wp, &
                     'the body scaled with the height (width, thickness, centre of mass)')
        end associate
      end do
    end do
    lists(V_HEADING)%x = [-10.0_wp, 20.0_wp]
    rows = sweep_rows(lists, together)
    call set_population(setup, rows, heading_swept=.true.)
    call check(size(setup%members) == 8, 'the headings swept: one member per row, 2 x 2 x 2')
    call check(all(abs(setup%start_angles - [-10.0_wp, -10.0_wp, 20.0_wp, 20.0_wp, -10.0_wp, -10.0_wp, 20.0_wp, &
                                             20.0_wp]*pi/180) < 1e-15_wp), &
               'the headings swept: each row''s own, in rad (the heading before the speed)')
  end subroutine population_from_rows

  subroutine quantile_known_values()
    real(wp), parameter :: x(5) = [4.0_wp, 1.0_wp, 5.0_wp, 2.0_wp, 3.0_wp]
    ! h = (n - 1) q + 1: q = 0.25 -> h = 2 (the 2nd smallest); q = 0.9 -> h = 4.6
    call check(quantile(x, 0.25_wp) == 2, 'quantile: q = 0.25 of 1..5 is 2')
    call check(abs(quantile(x, 0.9_wp) - 4.6_wp) <= 4*epsilon(1.0_wp)*4.6_wp, 'quantile: q = 0.9 of 1..5 is 4.6')
    call check(quantile(x, 1.0_wp) == 5 .and. quantile(x, 0.0_wp) == 1, 'quantile: q = 1, 0 the largest, smallest')
    call check(quantile([7.5_wp], 0.3_wp) == 7.5_wp, 'quantile of one value: the value')
    call check(quantile([10.0_wp, 20.0_wp], 0.5_wp) == 15, 'quantile: the median of two, between them')
  end subroutine quantile_known_values

  !> Four members, different in size, speed, place and direction.
  function four_members() result(setup)
    type(optimization_setup_t) :: setup
    real(wp), parameter :: heights(4) = [1.5_wp, 1.8_wp, 2.0_wp, 1.65_wp], speeds(4) = [0.3_wp, 0.5_wp, 0.8_wp, 0.6_wp]
    real(wp), parameter :: walls(4) = [0.0_wp, 0.1_wp, -0.1_wp, 0.05_wp], angles(4) = [-20.0_wp, 0.0_wp, 10.0_wp, 25.0_wp]
    integer :: k
    setup = base
    allocate (setup%members(4))
    do k = 1, 4
      setup%members(k)%body = base%body
      setup%members(k)%body%mass = 50 + 15*k
      setup%members(k)%body%length = heights(k)
      setup%members(k)%body%width = base%body%width*heights(k)/base%body%length
      setup%members(k)%height = heights(k)
      setup%members(k)%speed = speeds(k)
      setup%members(k)%v = pi/2 + walls(k)
    end do
    setup%start_angles = angles*pi/180
  end function four_members

  subroutine members_are_rides()
    type(optimization_setup_t) :: pop, alone
    type(design_evaluation_t) :: e, one
    type(status_t) :: status
    real(wp) :: maxima(4), x(2)
    integer :: k
    pop = four_members()
    x = [5.1_wp, 6.1_wp]
    pop%cost = COST_WORST
    call evaluate_design(pop, x, e, status)
    call check(status%ok(), 'the population rides: '//status%text())
    do k = 1, 4   ! each member alone, as an ordinary optimisation's one ride
      alone = base
      alone%body = pop%members(k)%body
      alone%start_speed = pop%members(k)%speed
      alone%start_v = pop%members(k)%v
      alone%start_angles = [pop%start_angles(k)]
      call evaluate_design(alone, x, one, status)
      maxima(k) = one%rides(1)%max_acceleration
      call check(status%ok() .and. one%rides(1)%max_acceleration == e%rides(k)%max_acceleration .and. &
                 one%rides(1)%max_tipping_excess == e%rides(k)%max_tipping_excess .and. &
                 one%rides(1)%duration == e%rides(k)%duration, 'member k''s ride is its ride alone, to the bit')
    end do
    print '(a, 4f10.4)', 'members'' largest accelerations (m/s^2): ', maxima
    call check(maxval(maxima) > minval(maxima) + 0.01_wp, 'the members differ (the test can tell them apart)')
    call check(e%acceleration_cost == 0.5_wp*maxval(maxima)**2 .and. e%robust_acceleration == maxval(maxima), &
               'worst case: 1/2 (max over the members ridden alone)^2')
    call check(e%worst_ride == maxloc(maxima, dim=1), 'the worst ride is the argmax')
    pop%cost = COST_QUANTILE
    pop%quantile = 0.75_wp
    call evaluate_design(pop, x, e, status)
    call check(status%ok() .and. e%robust_acceleration == quantile(maxima, 0.75_wp) .and. &
               e%acceleration_cost == 0.5_wp*quantile(maxima, 0.75_wp)**2, &
               'quantile: 1/2 (the 0.75-quantile of the members ridden alone)^2')
    call check(e%robust_acceleration < maxval(maxima) .and. e%worst_ride == maxloc(maxima, dim=1), &
               'the 0.75-quantile lies below the worst, the worst ride named')
  end subroutine members_are_rides

  subroutine sum_of_start_angles()
    type(optimization_setup_t) :: ordinary, pop
    type(design_evaluation_t) :: a, b
    type(status_t) :: sa, sb
    ordinary = base
    ordinary%start_angles = thesis_start_angles()
    pop = ordinary
    allocate (pop%members(5))
    pop%members%body = [(base%body, i=1, 5)]
    pop%members%speed = base%start_speed
    pop%members%v = base%start_v
    pop%cost = COST_SUM
    call evaluate_design(ordinary, [5.0_wp, 6.0_wp], a, sa)
    call evaluate_design(pop, [5.0_wp, 6.0_wp], b, sb)
    call check(sa%ok() .and. sb%ok() .and. a%acceleration_cost == b%acceleration_cost .and. &
               all(a%rides%max_acceleration == b%rides%max_acceleration), &
               'sum over a population of the five start angles: (4.49), to the bit')
  end subroutine sum_of_start_angles

  subroutine population_of_one()
    type(optimization_setup_t) :: pop
    type(optimization_result_t) :: ordinary, robust
    type(status_t) :: status
    integer :: c
    call optimize_slide(base, ordinary, status)
    call check(status%ok(), 'the ordinary optimisation of one ride: '//status%text())
    print '(a, 2f10.5, a, es14.6, a, i0)', 'one ride: end ', ordinary%x, ' cost ', ordinary%cost_after, &
      ' designs ', ordinary%evaluations
    do c = COST_WORST, COST_QUANTILE
      pop = base
      allocate (pop%members(1))
      pop%members(1)%body = base%body
      pop%members(1)%speed = base%start_speed
      pop%members(1)%v = base%start_v
      pop%cost = c
      pop%quantile = 0.3_wp
      call optimize_slide(pop, robust, status)
      call check(status%ok() .and. all(robust%x == ordinary%x) .and. robust%cost_after == ordinary%cost_after .and. &
                 robust%evaluations == ordinary%evaluations .and. robust%outcome == ordinary%outcome .and. &
                 robust%after%acceleration_cost == ordinary%after%acceleration_cost, &
                 'a population of one (cost '//trim(merge('worst   ', 'quantile', c == COST_WORST))// &
                 ') is the ordinary optimisation of its ride, to the bit')
    end do
  end subroutine population_of_one

  subroutine threads_same_bits()
    type(optimization_setup_t) :: pop
    type(optimization_result_t) :: serial, threaded
    type(status_t) :: s1, s2
    pop = four_members()
    pop%cost = COST_WORST
    pop%starts = 2
    pop%seed = 3
    pop%solver%max_evaluations = 40   ! enough designs to compare, whatever the end
    call optimize_slide(pop, serial, s1)
    pop%threads = 2
    call optimize_slide(pop, threaded, s2)
    call check(s1%ok() .and. s2%ok(), 'the population''s optimisation in 1 and 2 threads')
    call check(all(serial%x == threaded%x) .and. serial%cost_after == threaded%cost_after .and. &
               serial%evaluations == threaded%evaluations .and. serial%best_start == threaded%best_start .and. &
               all(serial%starts%cost == threaded%starts%cost) .and. &
               serial%after%worst_ride == threaded%after%worst_ride, &
               'a population in 2 threads: the same bits as in 1')
    print '(a, 2f10.5, a, i0, a)', 'population: end ', serial%x, ' (', serial%evaluations, ' designs): '// &
      serial%verdict
  end subroutine threads_same_bits
end program test_robust_optimization
