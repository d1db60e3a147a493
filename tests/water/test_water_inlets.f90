!> Several inlets (water_inlet, docs/water.md "Several inlets"):
!> - a second inlet at the start, entering with the start's speed and angle,
!>   gives the run of one inlet with the summed flow rate bit for bit (the
!>   momentum balance of two equal velocities is the identity; the start is
!>   then the same START_SPEED start of the summed flow);
!> - an inlet downstream: at its merge the run records the water before and
!>   after at the same time and place; mass Q+ = Q + Q_i and momentum
!>   (Q + Q_i) w+ = Q w + Q_i w_i (tangent-plane vectors, w_i built here
!>   from the recorded frame) hold to 1e-12 relative, the section carries the
!>   new flow (A w = Q+, 1e-12), and the field jumps there;
!> - a merged state beyond a stop (slow inlet water that brings the stream
!>   below min_speed) ends the run with that stop, said; a merged state
!>   outside the model (subcritical) or one the section cannot hold stops
!>   the run at the inlet (status domain), said;
!> - invalid inlets refused before any work, the component named.
program test_water_inlets
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_vector, only: cross
  use geometry_tube, only: new_s_bend_tube
  use testing, only: check, check_close, finish_tests
  use water_flow, only: OUTCOME_END, OUTCOME_STALL, START_SPEED
  use water_field, only: water_at_t, WATER_INSIDE
  use water_run, only: water_description_t, water_result_t, water_inlet_t, compute_water
  implicit none (type, external)

  type(water_description_t) :: d
  type(status_t) :: st

  d%slide = new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp, st)
  call check(st%ok(), 'S-bend built')
  d%start%mode = START_SPEED; d%start%speed = 2; d%start%v0 = pi/2
  d%flow_rate = 0.003_wp
  d%stations = [5.0_wp, 20.0_wp]
  d%solver%ode%rtol = 1e-10_wp; d%solver%ode%atol = 1e-10_wp
  d%solver%output_step = 0.01_wp

  call second_at_start(d, 0.0_wp)
  call second_at_start(d, 0.05_wp)
  call downstream(d)
  call merged_beyond_a_stop(d)
  call refused(d)
  call finish_tests('test_water_inlets')

contains

  subroutine second_at_start(d, beta)
    type(water_description_t), intent(in) :: d
    real(wp), intent(in) :: beta
    type(water_description_t) :: one, two
    type(water_result_t) :: a, b
    type(status_t) :: st_a, st_b
    integer :: n
    character(len=:), allocatable :: what
    what = 'second inlet at the start (beta '//merge('0   ', '0.05', beta == 0)//'): '
    one = d
    one%start%beta = beta
    two = one
    two%inlets = [water_inlet_t(arc_length=0, flow_rate=0.001_wp, speed=d%start%speed, beta=beta)]
    one%flow_rate = d%flow_rate + 0.001_wp
    call compute_water(one, a, st_a)
    call compute_water(two, b, st_b)
    call check(st_a%ok() .and. st_b%ok(), what//'both runs reach the end')
    n = a%series%n
    call check(b%series%n == n, what//'as many samples as one inlet of the summed flow')
    if (b%series%n /= n) return
    call check(all(a%series%time(:n) == b%series%time(:n)) .and. all(a%series%u(:n) == b%series%u(:n)) .and. &
               all(a%series%v(:n) == b%series%v(:n)) .and. all(a%series%du(:n) == b%series%du(:n)) .and. &
               all(a%series%dv(:n) == b%series%dv(:n)) .and. all(a%series%height(:n) == b%series%height(:n)) .and. &
               all(a%series%speed(:n) == b%series%speed(:n)) .and. all(a%series%width(:n) == b%series%width(:n)) .and. &
               all(a%series%left_edge(:, :n) == b%series%left_edge(:, :n)) .and. &
               all(a%series%flow(:n) == b%series%flow(:n)), what//'bit for bit the run of one inlet of the summed flow')
    call check(b%series%flow_rate == one%flow_rate .and. b%series%inlets(1)%joined .and. &
               b%series%inlets(1)%time == 0, what//'the flow at the start is the sum, the inlet joined at t = 0')
    call check(all(a%table%height == b%table%height) .and. all(a%table%flow_rate == b%table%flow_rate), &
               what//'the same table')
  end subroutine second_at_start

  subroutine downstream(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: two
    type(water_result_t) :: r
    type(status_t) :: st
    type(water_inlet_t) :: inlet
    type(water_at_t) :: before, after
    real(wp) :: q1, q2, v_in(3), x(3), y(3), z(3), imbalance(3)
    integer :: j, n
    two = d
    inlet = water_inlet_t(arc_length=12, flow_rate=0.002_wp, speed=1.2_wp, beta=0.3_wp)
    two%inlets = [inlet]
    call compute_water(two, r, st)
    call check(st%ok() .and. r%series%outcome == OUTCOME_END, 'downstream inlet: the water reaches the end '//st%text())
    associate (s => r%series)
      n = s%n
      call check(s%inlets(1)%joined, 'downstream inlet: joined')
      ! the merge: two samples at the same time and place, the flow jumps
      do j = 1, n - 1
        if (s%flow(j + 1) /= s%flow(j)) exit
      end do
      call check(j < n .and. count(s%flow(2:n) /= s%flow(1:n - 1)) == 1, 'downstream inlet: one jump of the flow')
      if (j >= n) return
      call check(s%time(j) == s%time(j + 1) .and. s%u(j) == s%u(j + 1) .and. s%v(j) == s%v(j + 1) .and. &
                 s%time(j) == s%inlets(1)%time, 'downstream inlet: before and after at one time and place')
      call check_close(s%arc_length(j), inlet%arc_length, 0.0_wp, 1e-9_wp, 'downstream inlet: at its arc length')
      q1 = s%flow(j)
      q2 = inlet%flow_rate
      call check(q1 == d%flow_rate, 'downstream inlet: the flow before is the start''s')
      call check_close(s%flow(j + 1), q1 + q2, 1e-12_wp, 0.0_wp, 'downstream inlet: mass, Q+ = Q + Q_i')
      call check_close(s%area(j + 1)*s%speed(j + 1), s%flow(j + 1), 1e-12_wp, 0.0_wp, &
                       'downstream inlet: the section carries Q+ (A w)')
      call check_close(s%area(j)*s%speed(j), q1, 1e-9_wp, 0.0_wp, 'downstream inlet: the section carried Q before')
      ! the inlet's velocity from the recorded frame: sin(beta) x_M - cos(beta) y_M
      z = s%z_m(:, j)
      x = s%x_m(:, j)
      y = cross(z, x)
      v_in = inlet%speed*(sin(inlet%beta)*x - cos(inlet%beta)*y)
      imbalance = (q1 + q2)*s%velocity(:, j + 1) - (q1*s%velocity(:, j) + q2*v_in)
      call check_close(norm2(imbalance)/((q1 + q2)*s%speed(j + 1)), 0.0_wp, 0.0_wp, 1e-12_wp, &
                       'downstream inlet: momentum, (Q + Q_i) w+ = Q w + Q_i w_i')
      call check(dot_product(s%velocity(:, j + 1), s%z_m(:, j)) < 1e-12_wp*s%speed(j + 1), &
                 'downstream inlet: the merged velocity lies in the tangent plane')
      call check(s%speed(j + 1) < s%speed(j) .and. s%height(j + 1) > s%height(j), &
                 'downstream inlet: slower inlet water: the stream slows and deepens')
      call check(all(s%flow(j + 1:n) == s%flow(j + 1)), 'downstream inlet: the flow stays Q+ to the end')
      ! the field: the water before the inlet up to its u, the merged water from there
      call r%field%at_u(s%u(j) - 1e-9_wp, before)
      call r%field%at_u(s%u(j), after)
      call check(before%location == WATER_INSIDE .and. after%location == WATER_INSIDE, &
                 'downstream inlet: the field covers the merge')
      call check(before%flow_rate == q1 .and. after%flow_rate == s%flow(j + 1), 'downstream inlet: the field''s flow jumps')
      call check_close(before%speed, s%speed(j), 1e-9_wp, 0.0_wp, 'downstream inlet: field speed just before')
      call check(after%speed == s%speed(j + 1) .and. after%height == s%height(j + 1), &
                 'downstream inlet: the field at the inlet is the merged water')
      call check(r%table%flow_rate(1) == q1 .and. r%table%flow_rate(size(r%table%flow_rate)) == q1 + q2, &
                 'downstream inlet: the table''s flow rate')
    end associate
  end subroutine downstream

  subroutine merged_beyond_a_stop(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: slow
    type(water_result_t) :: r
    type(status_t) :: st
    integer :: n
    ! slow inlet water: the merged stream (1.16 m/s, from 3.27) is below min_speed
    ! = 1.5 m/s at once; the stream before it is faster
    slow = d
    slow%min_speed = 1.5_wp
    slow%inlets = [water_inlet_t(arc_length=8, flow_rate=0.006_wp, speed=0.1_wp, beta=0)]
    st%code = 0
    call compute_water(slow, r, st)
    n = r%series%n
    call check(st%code == STATUS_DOMAIN .and. r%series%outcome == OUTCOME_STALL, &
               'slow inlet: the merged water is beyond the stall stop '//st%text())
    call check(index(st%text(), 'after the inlet joined at arc length 8 m: the water stalled') > 0, &
               'slow inlet: said where: '//st%text())
    if (n < 2) return
    call check(r%series%flow(n) == 0.003_wp + 0.006_wp .and. r%series%speed(n) < 1.5_wp .and. &
               r%series%speed(n - 1) > 1.5_wp .and. r%series%u(n) == r%series%u(n - 1), &
               'slow inlet: the last samples are the water before and after the merge')
    ! slower still: subcritical (Fr < 1), outside the model: the run stops there, said
    slow%min_speed = d%min_speed
    slow%inlets = [water_inlet_t(arc_length=8, flow_rate=0.02_wp, speed=0.01_wp, beta=0)]
    st%code = 0
    call compute_water(slow, r, st)
    call check(st%code == STATUS_DOMAIN .and. index(st%text(), 'the inlet joined at arc length 8 m, the merged '// &
               'water: the flow reached critical') > 0, 'subcritical merge: said where: '//st%text())
    call check(r%series%n > 0, 'subcritical merge: the water up to the inlet kept')
    if (r%series%n > 0) call check(r%series%flow(r%series%n) == 0.003_wp, 'subcritical merge: the last sample before it')
    ! more than the tube holds at that speed: no height
    slow%inlets = [water_inlet_t(arc_length=8, flow_rate=0.3_wp, speed=0.01_wp, beta=0)]
    st%code = 0
    call compute_water(slow, r, st)
    call check(st%code == STATUS_DOMAIN .and. index(st%text(), 'the inlet at arc length 8 m: the merged water') > 0, &
               'overfull inlet: said where: '//st%text())
  end subroutine merged_beyond_a_stop

  subroutine refused(d)
    type(water_description_t), intent(in) :: d
    call refused_one(d, [water_inlet_t(arc_length=5, flow_rate=-0.001_wp)], 'inlets(1)%flow_rate')
    call refused_one(d, [water_inlet_t(arc_length=5, flow_rate=0.001_wp, speed=0)], 'inlets(1)%speed')
    call refused_one(d, [water_inlet_t(arc_length=5, flow_rate=0.001_wp, beta=1.6_wp)], 'inlets(1)%beta')
    call refused_one(d, [water_inlet_t(arc_length=1000, flow_rate=0.001_wp)], 'inlets(1)%arc_length')
    call refused_one(d, [water_inlet_t(arc_length=-1, flow_rate=0.001_wp)], 'inlets(1)%arc_length')
    call refused_one(d, [water_inlet_t(arc_length=5, flow_rate=0.001_wp), water_inlet_t(arc_length=2, flow_rate=0.001_wp)], &
                     'inlets(2)%arc_length: the inlets must be in order')
  end subroutine refused

  subroutine refused_one(d, inlets, name)
    type(water_description_t), intent(in) :: d
    type(water_inlet_t), intent(in) :: inlets(:)
    character(len=*), intent(in) :: name
    type(water_description_t) :: bad
    type(water_result_t) :: r
    type(status_t) :: st
    bad = d
    bad%inlets = inlets
    call compute_water(bad, r, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), name) > 0 .and. r%series%n == 0, &
               'refused: '//name//': '//st%text())
  end subroutine refused_one
end program test_water_inlets
