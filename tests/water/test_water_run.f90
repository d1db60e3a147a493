!> The water as a library run (water_run): a description in, the water out,
!> nothing read or written.
!> - a run goes to the end of the slide when nothing bounds it (no time
!>   bound: the run's own end, not a default duration cutting it short); a
!>   time bound before the end ends it there with status ok, `bounded`, and
!>   the samples up to the bound;
!> - the description is not changed and two runs of it give bit-identical
!>   results (no state kept between runs); the same run from two OpenMP
!>   threads at once gives the same results as the serial run;
!> - edges = .false.: no edges at the samples, the table's edges solved at its
!>   rows agree with the edges interpolated from a run that solved them at
!>   every sample, and the field gets its edges from those rows;
!> - the safety bound is 200 L/min_speed;
!> - every invalid description is refused before any work, the message naming
!>   the component;
!> - start%u0 is the arc length along the centerline (&water u0, as
!>   declared): on an exact element chain, whose parameter is the horizontal
!>   length, the water starts u0 m along the centerline, on the straight as
!>   in the curve after it; beyond the slide's length it is refused.
program test_water_run
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_tube, only: tube_surface_t, new_s_bend_tube, new_straight_tube, new_tube_surface
  use geometry_curve, only: curve_point_t, constant_curve_t
  use geometry_cross_section, only: circle_section_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use testing, only: check, check_close, finish_tests
  use water_streamline, only: streamline_t
  use water_flow, only: OUTCOME_END, OUTCOME_DURATION, START_HEIGHT_SPEED, START_EDGES, safety_time_bound
  use water_field, only: water_at_t, WATER_INSIDE
  use water_run, only: water_description_t, water_result_t, new_streamline, compute_water
  implicit none (type, external)

  type(water_description_t) :: d
  type(status_t) :: st

  d%slide = new_s_bend_tube(0.5_wp, 1.5_wp, 0.4_wp, 0.1_wp, 30.0_wp, st)
  call check(st%ok(), 'S-bend built')
  d%start%mode = START_HEIGHT_SPEED; d%start%height = 0.02_wp; d%start%speed = 2; d%start%v0 = pi/2
  d%stations = [5.0_wp, 20.0_wp]
  d%solver%ode%rtol = 1e-10_wp; d%solver%ode%atol = 1e-10_wp
  d%solver%output_step = 0.01_wp

  call to_the_end_and_bounded(d)
  call repeatable(d)
  call in_threads(d)
  call edges_at_rows(d)
  call safety_bound()
  call refused(d)
  call start_on_chain()
  call finish_tests('test_water_run')

contains

  subroutine to_the_end_and_bounded(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: b
    type(water_result_t) :: r
    type(status_t) :: st
    real(wp) :: u_min, u_max, dummy(4)
    call compute_water(d, r, st)
    call check(st%ok() .and. r%series%outcome == OUTCOME_END .and. .not. r%bounded, &
               'no time bound: the water runs to the end of the slide '//st%text())
    call d%slide%domain(u_min, u_max, dummy(1), dummy(2))
    call check_close(r%series%u(r%series%n), u_max, 1e-12_wp, 0.0_wp, 'the last sample is the slide''s end')
    call check(all(r%series%stations%reached), 'every station reached')
    call check(r%series%time(r%series%n) > 10, 'a run longer than the 10 s default duration of &solver')
    ! a bound before the end
    b = d
    b%solver%time_bound = 3.3_wp
    call compute_water(b, r, st)
    call check(st%ok() .and. r%series%outcome == OUTCOME_DURATION .and. r%bounded, &
               'a time bound before the end: status ok, bounded')
    call check_close(r%series%time(r%series%n), 3.3_wp, 0.0_wp, 1e-12_wp, 'bounded: the last sample at the bound')
    call check(r%series%u(r%series%n) < u_max - 1, 'bounded: the end not reached')
    call check(r%series%stations(1)%reached .and. .not. r%series%stations(2)%reached, &
               'bounded: the stations before the bound reached, the others not')
  end subroutine to_the_end_and_bounded

  subroutine repeatable(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: before
    type(water_result_t) :: a, b
    type(status_t) :: st
    before = d
    call compute_water(d, a, st)
    call compute_water(d, b, st)
    call check(a%series%n == b%series%n, 'two runs: the same samples')
    if (a%series%n /= b%series%n) return
    call check(all(a%series%v(:a%series%n) == b%series%v(:b%series%n)) .and. &
               all(a%series%left_edge(:, :a%series%n) == b%series%left_edge(:, :b%series%n)) .and. &
               all(a%table%v_left == b%table%v_left), &
               'two runs of one description: bit-identical')
    call check(all(before%stations == d%stations) .and. before%flow_rate == d%flow_rate .and. &
               before%start%u0 == d%start%u0, 'the description is not changed by a run')
  end subroutine repeatable

  !> Two runs at once in two threads (different flow rates), against the same
  !> runs one after the other: bit-identical.
  subroutine in_threads(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: two(2)
    type(water_result_t) :: serial(2), parallel(2)
    type(status_t) :: st(2)
    integer :: k
    two = d
    two(2)%start%speed = 2.5_wp
    do k = 1, 2
      call compute_water(two(k), serial(k), st(k))
    end do
    !$omp parallel do num_threads(2) private(k)
    do k = 1, 2
      call compute_water(two(k), parallel(k), st(k))
    end do
    !$omp end parallel do
    do k = 1, 2
      call check(st(k)%ok() .and. serial(k)%series%n == parallel(k)%series%n, 'threads: runs complete')
      if (serial(k)%series%n /= parallel(k)%series%n) cycle
      call check(all(serial(k)%series%v(:serial(k)%series%n) == parallel(k)%series%v(:parallel(k)%series%n)) .and. &
                 all(serial(k)%table%v_right == parallel(k)%table%v_right), &
                 'two threads at once: bit-identical to the serial runs')
    end do
    call check(serial(1)%series%n /= serial(2)%series%n .or. serial(1)%series%v(5) /= serial(2)%series%v(5), &
               'threads: the two runs differ (different starts)')
  end subroutine in_threads

  !> edges = .false.: the edges are solved at the table's rows only (10 cm
  !> apart) and the table reads the edge curves through them at each row's
  !> section. They agree with the edge curves of a run that solved them at
  !> every 0.01 s sample (~3 cm): both cubic Hermite, h^4 v''''/384 ~ 1e-8 rad
  !> at 10 cm; tolerance 1e-7 rad (0.05 um on the 0.5 m wall).
  subroutine edges_at_rows(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: off
    type(water_result_t) :: a, b
    type(water_at_t) :: w
    type(status_t) :: st
    real(wp) :: worst, worst_switch, diff
    integer :: j, solved
    call compute_water(d, a, st)
    off = d
    off%edges = .false.
    call compute_water(off, b, st)
    call check(st%ok() .and. .not. b%series%edges .and. all(b%series%edge_solved(:b%series%n) == 0), &
               'edges off: no edges at the samples')
    call check(size(a%table%v_left) == size(b%table%v_left), 'edges off: the same table rows')
    if (size(a%table%v_left) /= size(b%table%v_left)) return
    worst = 0; worst_switch = 0; solved = 0
    do j = 1, size(a%table%v_left)
      if (a%table%edge_solved(j) /= 1 .or. b%table%edge_solved(j) /= 1) cycle
      solved = solved + 1
      diff = max(abs(a%table%v_left(j) - b%table%v_left(j)), abs(a%table%v_right(j) - b%table%v_right(j)))
      ! within 0.2 m of an inflection (k u = n pi) the f3 friction switches on
      ! and the edges' slopes jump (docs/water.md): h jump/8
      if (abs(a%table%u(j) - pi/0.4_wp*nint(a%table%u(j)*0.4_wp/pi)) < 0.2_wp) then
        worst_switch = max(worst_switch, diff)
      else
        worst = max(worst, diff)
      end if
    end do
    call check(solved >= size(a%table%v_left) - 2, 'edges off: the edges solved at (almost) every row')
    call check(worst <= 1e-7_wp, 'edges off: the rows'' edges = the edges interpolated from every sample')
    ! at the switches: the edge slope jumps by ~1e-3 (width rate jump / u'),
    ! times h/8 with h = 0.1 m
    call check(worst_switch <= 1e-5_wp, 'edges off: near the friction switches within 1e-5 rad')
    print '(a, i0, a, 2es9.1, a)', '  edges at ', solved, ' rows: solved there vs from the samples ', worst, &
      worst_switch, ' rad (away from / near the friction switches)'
    call b%field%at_arc_length(10.0_wp, w)
    call check(w%location == WATER_INSIDE .and. w%edges%left_location == WATER_INSIDE .and. &
               abs(w%edges%v_left - w%v) > 0.1_wp, 'edges off: the field has the edges of the rows')
  end subroutine edges_at_rows

  subroutine safety_bound()
    type(water_description_t) :: s
    type(streamline_t) :: model
    type(status_t) :: st
    real(wp) :: y0(7)
    s%slide = new_straight_tube(0.5_wp, 0.2_wp, 40.0_wp, st)
    s%start%mode = START_EDGES
    call new_streamline(s, model, y0, st)
    call check(st%ok(), 'straight tube: model')
    call check_close(safety_time_bound(model, 0.0_wp), 200*40/0.05_wp, 1e-12_wp, 0.0_wp, &
                     'safety bound = 200 L/min_speed')
    call check_close(safety_time_bound(model, 10.0_wp), 200*30/0.05_wp, 1e-12_wp, 0.0_wp, &
                     'safety bound from the start: 200 (L - s0)/min_speed')
  end subroutine safety_bound

  subroutine refused(d)
    type(water_description_t), intent(in) :: d
    type(water_description_t) :: empty
    call refuse(empty, 'slide')
    call refuse_with(d, 'flow_rate', -1.0_wp)
    call refuse_with(d, 'f2', -0.1_wp)
    call refuse_with(d, 'min_speed', 0.0_wp)
    call refuse_with(d, 'min_criticality', 0.95_wp)
    call refuse_with(d, 'output_step', 0.0_wp)
    call refuse_with(d, 'table_step', -1.0_wp)
    call refuse_with(d, 'time_bound', -1.0_wp)
    call refuse_with(d, 'stations', 99.0_wp)
    call refuse_with(d, 'u0', 99.0_wp)
  end subroutine refused

  !> u0 as arc length on an exact chain: a 20 deg straight of 12 m
  !> (horizontally), then a 90 deg curve of radius 8 m at 5 deg (the rider's
  !> test_rider_model check_start_on_chain). On the straight the arc length
  !> is the distance from the centerline's start (u0 used as the parameter,
  !> u0 m horizontally, lay 1/cos(20 deg) - 1 = 6 % further); in the curve
  !> the tube's own arc length (parameter_at_length solves to 1e-12 of the
  !> length, so 1e-10 relative holds).
  subroutine start_on_chain()
    type(water_description_t) :: w
    type(element_chain_curve_t) :: chain
    type(tube_surface_t) :: tube
    type(streamline_t) :: model
    type(curve_point_t) :: c0, c
    type(status_t) :: st
    real(wp) :: y0(7)
    chain = new_element_chain([slide_element_t(kind='straight', length=12.0_wp, slope_deg=20.0_wp), &
                               slide_element_t(kind='curve', radius=8.0_wp, angle_deg=90.0_wp, slope_deg=5.0_wp)], &
                              [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 2.0_wp, st)
    if (st%ok()) tube = new_tube_surface(chain, constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp]), &
                                         circle_section_t(radius=0.5_wp), st)
    call check(st%ok(), 'chain tube built: '//st%text())
    if (.not. st%ok()) return
    w%slide = tube
    w%start%mode = START_EDGES
    w%start%u0 = 4
    call new_streamline(w, model, y0, st)
    call check(st%ok(), 'water starts on the chain: '//st%text())
    call chain%evaluate(0.0_wp, 0, c0, st)
    call chain%evaluate(y0(1), 0, c, st)
    call check_close(norm2(c%d(:, 0) - c0%d(:, 0)), 4.0_wp, 1e-10_wp, 0.0_wp, &
                     'the water starts u0 = 4 m along the straight''s centerline')
    w%start%u0 = 20
    call new_streamline(w, model, y0, st)
    call check(st%ok(), 'water starts in the curve: '//st%text())
    call check_close(tube%arc_length(y0(1)), 20.0_wp, 1e-10_wp, 0.0_wp, &
                     'the water starts u0 = 20 m along the centerline, in the curve')
    w%start%u0 = 40
    call new_streamline(w, model, y0, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'start%u0 = 40') > 0 .and. &
               index(st%text(), 'arc length') > 0, 'a start beyond the end refused with the length: '//st%text())
  end subroutine start_on_chain

  subroutine refuse_with(d, what, value)
    type(water_description_t), intent(in) :: d
    character(len=*), intent(in) :: what
    real(wp), intent(in) :: value
    type(water_description_t) :: bad
    bad = d
    select case (what)
    case ('flow_rate'); bad%flow_rate = value; bad%start%mode = START_EDGES
    case ('f2'); bad%f2 = value
    case ('min_speed'); bad%min_speed = value
    case ('min_criticality'); bad%min_criticality = value
    case ('output_step'); bad%solver%output_step = value
    case ('table_step'); bad%table_step = value
    case ('time_bound'); bad%solver%time_bound = value
    case ('stations'); bad%stations = [5.0_wp, value]
    case ('u0'); bad%start%u0 = value
    end select
    call refuse(bad, what)
  end subroutine refuse_with

  subroutine refuse(bad, name)
    type(water_description_t), intent(in) :: bad
    character(len=*), intent(in) :: name
    type(water_result_t) :: r
    type(status_t) :: st
    call compute_water(bad, r, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), name) > 0 .and. r%series%n == 0, &
               'refused before any work, naming '//name//': '//st%text())
  end subroutine refuse
end program test_water_run
