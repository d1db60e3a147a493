!> Running the streamline: start values, integration to the end of the slide
!> with root finding, the time series at output times (with the water edges),
!> the report at stations, and the table of the water over arc length.
module water_flow
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, &
    STATUS_DOMAIN
  use geometry_surface, only: surface_point_t
  use numerics_ode, only: ode_integrator_t, ode_options_t, ode_stats_t
  use water_channel, only: channel_t
  use water_section, only: circle_segment, circle_height_for_area, profile_water
  use water_streamline, only: streamline_t, water_point_t, water_point, velocity_from_angle, &
    water_rates_t, water_point_rates, ROOT_END, ROOT_STALL, ROOT_CRITICAL, ROOT_TURN, ROOT_LIFT, ROOT_FIRST_STATION
  use water_boundaries, only: water_edges
  implicit none (type, external)
  private
  public :: water_start_t, water_series_t, water_station_t, water_table_t
  public :: water_initial_state, simulate_water, water_table
  public :: START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED
  public :: OUTCOME_END, OUTCOME_DURATION, OUTCOME_STALL, OUTCOME_TURN, OUTCOME_CRITICAL, &
    OUTCOME_ERROR, OUTCOME_LIFT, outcome_name

  integer, parameter :: START_EDGES = 1, START_HEIGHT = 2, START_SPEED = 3, START_HEIGHT_SPEED = 4
  integer, parameter :: OUTCOME_END = 1, OUTCOME_DURATION = 2, OUTCOME_STALL = 3, OUTCOME_TURN = 4, &
                        OUTCOME_CRITICAL = 5, OUTCOME_ERROR = 6, OUTCOME_LIFT = 7

  !> How the water enters at u0 (thesis 4.33 or given values).
  type :: water_start_t
    integer :: mode = START_EDGES
    real(wp) :: u0 = 0                 ! centerline parameter of the first section
    real(wp) :: v0 = pi/2              ! rad, water middle (START_EDGES: from the edges)
    real(wp) :: v_left = pi/2 + 0.3_wp, v_right = pi/2 - 0.3_wp   ! rad, edges (START_EDGES)
    real(wp) :: height = 0.01_wp       ! m (START_HEIGHT, START_HEIGHT_SPEED)
    real(wp) :: speed = 1              ! m/s (START_SPEED, START_HEIGHT_SPEED)
    real(wp) :: beta = 0               ! rad, flow angle to the centerline
  end type water_start_t

  type :: water_station_t
    real(wp) :: arc_length = 0, u = 0, time = 0, v = 0, speed = 0, height = 0, width = 0
    real(wp) :: v_left = 0, v_right = 0, v_middle = 0
    logical :: reached = .false.
  end type water_station_t

  type :: water_series_t
    integer :: n = 0
    real(wp), allocatable :: time(:), u(:), v(:), du(:), dv(:), arc_length(:)
    real(wp), allocatable :: position(:, :), velocity(:, :)
    real(wp), allocatable :: speed(:), height(:), width(:), area(:), radius(:), beta(:), alpha(:)
    real(wp), allocatable :: normal_force(:), friction_force(:), curvature(:), froude(:)
    real(wp), allocatable :: kinetic(:), potential(:), friction_work(:), correction_work(:)
    real(wp), allocatable :: left_edge(:, :), right_edge(:, :), left_point(:, :), right_point(:, :)
    integer, allocatable :: edge_solved(:)    ! 1: edges from (4.25-4.26); 0: circle estimate
    ! rates along the motion, for the water field's C1 interpolation
    real(wp), allocatable :: acceleration(:, :)      ! m/s^2 (3 x n)
    real(wp), allocatable :: speed_rate(:), height_rate(:), width_rate(:)   ! m/s^2, m/s, m/s
    real(wp), allocatable :: x_m(:, :), z_m(:, :), x_m_rate(:, :), z_m_rate(:, :)   ! K_M axes, 1/s
    real(wp), allocatable :: centerline_speed(:)     ! |c_u|, m per unit of u
    real(wp), allocatable :: left_edge_rate(:, :), right_edge_rate(:, :)   ! d[u, v]/dt (2 x n)
    integer :: edge_failures = 0                     ! samples where the edge solve failed
    character(len=:), allocatable :: edge_message   ! the first edge failure
    integer :: edge_beyond = 0                       ! samples with an edge beyond the slide's end
    real(wp) :: edge_beyond_from = 0                 ! m, arc length of the first of them
    type(water_station_t), allocatable :: stations(:)
    integer :: outcome = OUTCOME_ERROR
    character(len=:), allocatable :: message
    type(ode_stats_t) :: stats
    real(wp) :: flow_rate = 0          ! m^3/s
  end type water_series_t

  !> The water over arc length along the centerline (linear interpolation of
  !> the output samples, which lie a few cm apart).
  type :: water_table_t
    real(wp), allocatable :: arc_length(:), u(:), time(:), v(:), speed(:), height(:), width(:), &
      beta(:), v_left(:), v_right(:)
  end type water_table_t

  !> Most output samples of one run (about 510 bytes each): the memory bound.
  integer, parameter :: max_samples = 4000000

  interface resize
    module procedure resize_reals, resize_columns, resize_integers
  end interface resize

contains

  pure function outcome_name(outcome) result(text)
    integer, intent(in) :: outcome
    character(len=:), allocatable :: text
    select case (outcome)
    case (OUTCOME_END); text = 'end of slide'
    case (OUTCOME_DURATION); text = 'duration'
    case (OUTCOME_STALL); text = 'stalled'
    case (OUTCOME_TURN); text = 'turned back'
    case (OUTCOME_CRITICAL); text = 'near critical flow'
    case (OUTCOME_LIFT); text = 'lifted off'
    case default; text = 'error'
    end select
  end function outcome_name

  !> Initial state [u, v, u', v', h, 0, 0] and the flow rate (set in model%flow_rate
  !> for START_HEIGHT_SPEED; read from it otherwise).
  subroutine water_initial_state(model, start, y0, status)
    type(streamline_t), intent(inout) :: model
    type(water_start_t), intent(in) :: start
    real(wp), intent(out) :: y0(7)
    type(status_t), intent(out) :: status
    type(surface_point_t) :: p
    real(wp) :: r, radius, area, width, alpha, h, w, v0, du, dv, vl, vr, u_min, u_max

    y0 = 0
    call model%channel%u_range(u_min, u_max)
    if (start%u0 < u_min .or. start%u0 >= u_max) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start u0 is outside the slide')
      return
    end if
    if (abs(start%beta) >= pi/2) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start flow angle beta must be within +-90 degrees')
      return
    end if
    if (start%mode /= START_HEIGHT_SPEED .and. .not. model%flow_rate > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'the flow rate Q must be > 0')
      return
    end if
    r = model%channel%circle_radius(start%u0)
    radius = r*(1 + tan(start%beta)**2)     ! (4.15)
    v0 = start%v0
    select case (start%mode)
    case (START_EDGES)   ! (4.33)
      if (.not. start%v_left > start%v_right) then
        call set_status(status, STATUS_INVALID_INPUT, 'the start edges need v_left > v_right')
        return
      end if
      v0 = (start%v_left + start%v_right)/2
      if (r > 0) then
        h = r*(1 - cos((start%v_left - start%v_right)/2))
        call circle_segment(h, radius, area, width, alpha)
      else
        call edge_height(h, status)
        if (.not. status%ok()) return
        call profile_water(model%channel, start%u0, v0, h, area, width, vl, vr, status)
        if (.not. status%ok()) return
      end if
      w = model%flow_rate/area
    case (START_HEIGHT, START_HEIGHT_SPEED)
      h = start%height
      if (.not. h > 0 .or. (r > 0 .and. h >= 2*radius)) then
        call set_status(status, STATUS_INVALID_INPUT, 'the start height must be > 0 and inside the section')
        return
      end if
      if (r > 0) then
        call circle_segment(h, radius, area, width, alpha)
      else
        call profile_water(model%channel, start%u0, v0, h, area, width, vl, vr, status)
        if (.not. status%ok()) return
      end if
      if (start%mode == START_HEIGHT) then
        w = model%flow_rate/area
      else
        w = start%speed
        model%flow_rate = area*w
      end if
    case (START_SPEED)
      w = start%speed
      if (r > 0) then
        call circle_height_for_area(model%flow_rate/w, radius, h, status)
      else
        call profile_height(model%flow_rate/w, h, status)
      end if
      if (.not. status%ok()) then
        call prefix_status(status, 'start height from Q/w')
        return
      end if
    case default
      call set_status(status, STATUS_INVALID_INPUT, 'unknown start mode')
      return
    end select
    if (.not. w > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start speed must be > 0')
      return
    end if
    call model%channel%evaluate(start%u0, v0, 2, p, status)
    if (.not. status%ok()) return
    call velocity_from_angle(p, w, start%beta, du, dv, status)
    if (.not. status%ok()) return
    y0 = [start%u0, v0, du, dv, h, 0.0_wp, 0.0_wp]

  contains

    !> Height of the water between the given edges of a general profile: the
    !> lower of the two edge points, measured along the normal at v0.
    subroutine edge_height(hh, st)
      real(wp), intent(out) :: hh
      type(status_t), intent(out) :: st
      type(surface_point_t) :: p0, pl, pr
      real(wp) :: n(3)
      call model%channel%evaluate(start%u0, v0, 1, p0, st)
      if (st%ok()) call model%channel%evaluate(start%u0, start%v_left, 0, pl, st)
      if (st%ok()) call model%channel%evaluate(start%u0, start%v_right, 0, pr, st)
      if (.not. st%ok()) return
      n = [p0%ru(2)*p0%rv(3) - p0%ru(3)*p0%rv(2), p0%ru(3)*p0%rv(1) - p0%ru(1)*p0%rv(3), &
           p0%ru(1)*p0%rv(2) - p0%ru(2)*p0%rv(1)]
      n = n/norm2(n)
      hh = min(dot_product(pl%r - p0%r, n), dot_product(pr%r - p0%r, n))
      if (.not. hh > 0) call set_status(st, STATUS_INVALID_INPUT, 'the start edges give no water height')
    end subroutine edge_height

    !> Height with profile area A(h) = target (bisection + secant on the monotone A).
    subroutine profile_height(target, hh, st)
      real(wp), intent(in) :: target
      real(wp), intent(out) :: hh
      type(status_t), intent(out) :: st
      real(wp) :: lo, hi, a, b, l, rr
      integer :: it
      lo = 0; hi = 1e-3_wp
      do it = 1, 60
        call profile_water(model%channel, start%u0, v0, hi, a, b, l, rr, st)
        if (.not. st%ok()) return
        if (a >= target) exit
        lo = hi; hi = 2*hi
      end do
      do it = 1, 200
        hh = (lo + hi)/2
        call profile_water(model%channel, start%u0, v0, hh, a, b, l, rr, st)
        if (.not. st%ok()) return
        if (a > target) then
          hi = hh
        else
          lo = hh
        end if
        if (hi - lo <= 1e-15_wp*hi) exit
      end do
    end subroutine profile_height
  end subroutine water_initial_state

  !> Integrates from y0 until the end of the slide (u = u_end), `duration`, or a
  !> stop (stall, turning back, near-critical flow, an error). Records every
  !> output_step and at the stations; solves the edges at every record if
  !> `edges`. The series keeps what was computed; `status` says why it stopped
  !> early (OK for the end of the slide and for the duration).
  subroutine simulate_water(model, y0, options, duration, output_step, series, status, edges)
    type(streamline_t), intent(inout), target :: model
    real(wp), intent(in) :: y0(:), duration, output_step
    type(ode_options_t), intent(in) :: options
    type(water_series_t), intent(out) :: series
    type(status_t), intent(out) :: status
    logical, intent(in), optional :: edges
    type(ode_integrator_t) :: integrator
    type(ode_options_t) :: opts
    real(wp) :: t, t_out, y(size(y0)), u_min, u_max
    integer :: n_out, k, nroots, i
    integer, allocatable :: root_index(:)
    logical :: root_found, with_edges

    with_edges = .true.
    if (present(edges)) with_edges = edges
    call model%channel%u_range(u_min, u_max)
    model%u_end = min(model%u_end, u_max)   ! the slide ends at the channel's end at the latest
    series%flow_rate = model%flow_rate
    n_out = ceiling(min(duration/output_step, real(max_samples, wp)) - 1e-9_wp)
    ! the run may end long before duration (at the slide's end): grown in record as needed
    call allocate_series(series, min(n_out + 2, 4096))
    nroots = model%root_count()
    allocate (root_index(nroots))
    allocate (series%stations(nroots - ROOT_FIRST_STATION + 1))
    do i = 1, size(series%stations)
      series%stations(i)%u = model%stations(i)
    end do
    opts = options
    if (allocated(opts%root_direction)) deallocate (opts%root_direction)
    allocate (opts%root_direction(nroots))
    opts%root_direction = -1
    opts%root_direction(ROOT_FIRST_STATION:) = 1

    call record(model, 0.0_wp, y0, series, with_edges, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'water at the start')
      return
    end if
    ! a root needs a sign change: water that starts without contact is caught here
    if (.not. series%normal_force(1) > 0) then
      series%outcome = OUTCOME_LIFT
      call set_status(status, STATUS_DOMAIN, lift_message(0.0_wp, y0))
      series%message = status%text()
      return
    end if
    call integrator%start(model, 0.0_wp, y0, opts, status)
    if (.not. status%ok()) return
    series%outcome = OUTCOME_DURATION
    k = 0
    outer: do while (k < n_out)
      k = k + 1
      t_out = min(k*output_step, duration)
      do
        call integrator%advance(t_out, t, y, status, root_found, root_index)
        if (.not. status%ok()) then
          series%outcome = OUTCOME_ERROR
          call prefix_status(status, 'water stopped at t = '//format_short(t)//' s')
          exit outer
        end if
        if (.not. root_found) exit
        do i = 1, size(series%stations)
          if (root_index(ROOT_FIRST_STATION - 1 + i) /= 0) call station(i, t, y)
        end do
        if (root_index(ROOT_END) /= 0) then
          series%outcome = OUTCOME_END
        else if (root_index(ROOT_STALL) /= 0) then
          series%outcome = OUTCOME_STALL
          call set_status(status, STATUS_DOMAIN, 'the water stalled (speed below ' // &
                          format_short(model%min_speed)//' m/s) at t = '//format_short(t)//' s, u = '//format_short(y(1)))
        else if (root_index(ROOT_TURN) /= 0) then
          series%outcome = OUTCOME_TURN
          call set_status(status, STATUS_DOMAIN, 'the water turns across the slide or back ' // &
                          '(angle to the centerline beyond 89.4 deg) at t = ' // &
                          format_short(t)//' s, u = '//format_short(y(1)))
        else if (root_index(ROOT_LIFT) /= 0) then
          series%outcome = OUTCOME_LIFT
          call set_status(status, STATUS_DOMAIN, lift_message(t, y))
        else if (root_index(ROOT_CRITICAL) /= 0) then
          series%outcome = OUTCOME_CRITICAL
          call set_status(status, STATUS_DOMAIN, 'the flow approaches critical (1 - 1/Fr^2 = ' // &
                          format_short(model%min_criticality)//') at t = '//format_short(t)//' s, u = '// &
                          format_short(y(1))//': the Saint-Venant correction is singular at Fr = 1; ' // &
                          'the water is too slow for shallow supercritical flow here; ' // &
                          'switch the correction off (correction = ''off'') to go on')
        else
          cycle   ! only stations
        end if
        call record(model, t, y, series, with_edges, status)
        if (series%outcome /= OUTCOME_END .and. status%ok()) status%code = STATUS_DOMAIN
        exit outer
      end do
      call record(model, t, y, series, with_edges, status)
      if (.not. status%ok()) then
        series%outcome = OUTCOME_ERROR
        exit outer
      end if
    end do outer
    if (series%outcome == OUTCOME_STALL .or. series%outcome == OUTCOME_TURN .or. &
        series%outcome == OUTCOME_CRITICAL .or. series%outcome == OUTCOME_LIFT) then
      ! keep the message set at the root (record may have reset status)
      if (status%ok()) call set_status(status, STATUS_DOMAIN, outcome_name(series%outcome))
    end if
    if (.not. status%ok()) series%message = status%text()
    series%stats = integrator%statistics()

  contains

    function lift_message(ts, ys) result(text)
      real(wp), intent(in) :: ts, ys(:)
      character(len=:), allocatable :: text
      text = 'the water lifts off the slide surface (normal force (4.12) down to 0: the surface would ' // &
             'have to pull it) at t = '//format_short(ts)//' s, u = '//format_short(ys(1))//', v = '// &
             format_short(ys(2))//' rad; the streamline model holds only while the water is pressed on the slide'
    end function lift_message

    subroutine station(i, ts, ys)
      integer, intent(in) :: i
      real(wp), intent(in) :: ts, ys(:)
      type(water_point_t) :: q
      type(status_t) :: st
      real(wp) :: l(2), r(2), pl(3), pr(3)
      call water_point(model, ys, q, st)
      if (.not. st%ok()) return
      series%stations(i)%reached = .true.
      series%stations(i)%time = ts
      series%stations(i)%v = ys(2)
      series%stations(i)%speed = q%speed
      series%stations(i)%height = q%height
      series%stations(i)%width = q%width
      series%stations(i)%arc_length = model%channel%arc_length(ys(1))
      call water_edges(model%channel, q, l, r, pl, pr, st)
      if (st%ok()) then
        series%stations(i)%v_left = l(2)
        series%stations(i)%v_right = r(2)
        series%stations(i)%v_middle = (l(2) + r(2))/2
      else
        series%stations(i)%v_middle = ys(2)
      end if
    end subroutine station
  end subroutine simulate_water

  !> Room for n samples in every array of the series, the recorded ones kept
  !> and the new room zero (first call: allocates). Every array of
  !> water_series_t is listed here once, so growing keeps them all.
  subroutine allocate_series(s, n)
    type(water_series_t), intent(inout) :: s
    integer, intent(in) :: n
    call resize(s%time, n); call resize(s%u, n); call resize(s%v, n); call resize(s%du, n)
    call resize(s%dv, n); call resize(s%arc_length, n); call resize(s%position, 3, n)
    call resize(s%velocity, 3, n); call resize(s%speed, n); call resize(s%height, n); call resize(s%width, n)
    call resize(s%area, n); call resize(s%radius, n); call resize(s%beta, n); call resize(s%alpha, n)
    call resize(s%normal_force, n); call resize(s%friction_force, n); call resize(s%curvature, n)
    call resize(s%froude, n); call resize(s%kinetic, n); call resize(s%potential, n)
    call resize(s%friction_work, n); call resize(s%correction_work, n); call resize(s%left_edge, 2, n)
    call resize(s%right_edge, 2, n); call resize(s%left_point, 3, n); call resize(s%right_point, 3, n)
    call resize(s%edge_solved, n); call resize(s%acceleration, 3, n); call resize(s%speed_rate, n)
    call resize(s%height_rate, n); call resize(s%width_rate, n); call resize(s%x_m, 3, n)
    call resize(s%z_m, 3, n); call resize(s%x_m_rate, 3, n); call resize(s%z_m_rate, 3, n)
    call resize(s%centerline_speed, n); call resize(s%left_edge_rate, 2, n); call resize(s%right_edge_rate, 2, n)
  end subroutine allocate_series

  !> x(:n) (or x(:, :n)), the first entries kept, new ones zero.
  pure subroutine resize_reals(x, n)
    real(wp), allocatable, intent(inout) :: x(:)
    integer, intent(in) :: n
    real(wp), allocatable :: y(:)
    allocate (y(n))
    y = 0
    if (allocated(x)) y(:min(n, size(x))) = x(:min(n, size(x)))
    call move_alloc(y, x)
  end subroutine resize_reals

  pure subroutine resize_columns(x, rows, n)
    real(wp), allocatable, intent(inout) :: x(:, :)
    integer, intent(in) :: rows, n
    real(wp), allocatable :: y(:, :)
    allocate (y(rows, n))
    y = 0
    if (allocated(x)) y(:, :min(n, size(x, 2))) = x(:, :min(n, size(x, 2)))
    call move_alloc(y, x)
  end subroutine resize_columns

  pure subroutine resize_integers(x, n)
    integer, allocatable, intent(inout) :: x(:)
    integer, intent(in) :: n
    integer, allocatable :: y(:)
    allocate (y(n))
    y = 0
    if (allocated(x)) y(:min(n, size(x))) = x(:min(n, size(x)))
    call move_alloc(y, x)
  end subroutine resize_integers

  !> Twice the room for samples, the recorded ones kept.
  subroutine grow_series(s)
    type(water_series_t), intent(inout) :: s
    call allocate_series(s, 2*size(s%time))
  end subroutine grow_series

  subroutine record(model, t, y, s, with_edges, status)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: t, y(:)
    type(water_series_t), intent(inout) :: s
    logical, intent(in) :: with_edges
    type(status_t), intent(inout) :: status
    type(water_point_t) :: q
    type(water_rates_t) :: rates
    type(status_t) :: st
    integer :: i
    real(wp) :: lam, here(2), guess_l(2), guess_r(2)
    st%code = 0
    call water_point(model, y, q, st)
    if (st%ok()) call water_point_rates(model, y, q, rates, st)
    if (.not. st%ok()) then
      if (status%ok()) status = st
      return
    end if
    if (s%n >= max_samples) then
      if (status%ok()) call set_status(status, STATUS_DOMAIN, 'more than '//format_short(real(max_samples, wp))// &
        ' output samples (about 2 GB): raise &solver output_step or bound the run by &solver duration')
      return
    end if
    if (s%n >= size(s%time)) call grow_series(s)
    s%n = s%n + 1
    i = s%n
    s%time(i) = t
    s%u(i) = y(1); s%v(i) = y(2); s%du(i) = y(3); s%dv(i) = y(4)
    s%height(i) = y(5)
    s%friction_work(i) = y(6); s%correction_work(i) = y(7)
    if (i == 1) then
      s%arc_length(i) = model%channel%arc_length(y(1))
    else   ! incremental: samples lie centimetres apart
      s%arc_length(i) = s%arc_length(i - 1) + arc_increment(model%channel, s%u(i - 1), y(1))
    end if
    s%position(:, i) = q%position
    s%velocity(:, i) = q%velocity
    s%speed(i) = q%speed
    s%width(i) = q%width; s%area(i) = q%area; s%radius(i) = q%radius
    s%beta(i) = q%beta; s%alpha(i) = q%alpha
    s%normal_force(i) = q%normal_force; s%friction_force(i) = q%friction
    s%curvature(i) = q%chi
    s%froude(i) = q%froude
    s%kinetic(i) = 0.5_wp*model%mass*q%speed**2
    s%potential(i) = -model%mass*dot_product(model%gravity, q%position)
    s%acceleration(:, i) = q%acceleration
    s%speed_rate(i) = q%speed_rate; s%height_rate(i) = q%height_rate; s%width_rate(i) = rates%width
    s%x_m(:, i) = q%x_m; s%z_m(:, i) = q%z_m
    s%x_m_rate(:, i) = rates%x_m; s%z_m_rate(:, i) = rates%z_m
    s%centerline_speed(i) = q%centerline_speed
    if (with_edges) then
      if (i >= 2) then
        if (s%edge_solved(i - 1) == 1) then
          ! warm start: the previous output's edges, moved with the streamline
          ! (offsets extrapolated linearly in time from the two last outputs)
          lam = 0
          if (i >= 3) then
            if (s%edge_solved(i - 2) == 1 .and. s%time(i - 1) > s%time(i - 2)) &
              lam = (t - s%time(i - 1))/(s%time(i - 1) - s%time(i - 2))
          end if
          here = [y(1), y(2)]
          guess_l = here + offset(s%left_edge, i - 1) + lam*(offset(s%left_edge, i - 1) - offset(s%left_edge, i - 2))
          guess_r = here + offset(s%right_edge, i - 1) + lam*(offset(s%right_edge, i - 1) - &
                                                             offset(s%right_edge, i - 2))
          call water_edges(model%channel, q, s%left_edge(:, i), s%right_edge(:, i), s%left_point(:, i), &
                           s%right_point(:, i), st, guess_l, guess_r, rates=rates, &
                           left_rate=s%left_edge_rate(:, i), right_rate=s%right_edge_rate(:, i))
        else
          call water_edges(model%channel, q, s%left_edge(:, i), s%right_edge(:, i), s%left_point(:, i), &
                           s%right_point(:, i), st, rates=rates, &
                           left_rate=s%left_edge_rate(:, i), right_rate=s%right_edge_rate(:, i))
        end if
      else
        call water_edges(model%channel, q, s%left_edge(:, i), s%right_edge(:, i), s%left_point(:, i), &
                         s%right_point(:, i), st, rates=rates, &
                         left_rate=s%left_edge_rate(:, i), right_rate=s%right_edge_rate(:, i))
      end if
      s%edge_solved(i) = merge(1, 0, st%ok())
      if (.not. st%ok()) then
        ! Near the ends of the slide the foot of an edge can lie beyond the
        ! surface; keep the circle estimate v -+ (b/2)/|r_v| at the same u, flagged.
        s%left_edge(:, i) = [y(1), y(2) + 0.5_wp*q%width/norm2(q%p%rv)]
        s%right_edge(:, i) = [y(1), y(2) - 0.5_wp*q%width/norm2(q%p%rv)]
        s%left_point(:, i) = q%position + 0.5_wp*q%width*q%y_w
        s%right_point(:, i) = q%position - 0.5_wp*q%width*q%y_w
        if (st%code == STATUS_DOMAIN) then   ! the foot is beyond the end of the slide
          if (s%edge_beyond == 0) s%edge_beyond_from = s%arc_length(i)
          s%edge_beyond = s%edge_beyond + 1
        else
          if (s%edge_failures == 0) s%edge_message = 'at t = '//format_short(t)//' s: '//st%text()
          s%edge_failures = s%edge_failures + 1
        end if
      end if
    end if

  contains

    !> Edge minus streamline (u, v) at sample k (k >= 1).
    pure function offset(edge, k) result(d)
      real(wp), intent(in) :: edge(:, :)
      integer, intent(in) :: k
      real(wp) :: d(2)
      d = edge(:, max(k, 1)) - [s%u(max(k, 1)), s%v(max(k, 1))]
    end function offset
  end subroutine record

  !> The water every `step` metres of centerline arc length, interpolated
  !> linearly in u between the recorded samples (u grows monotonically).
  subroutine water_table(s, model, step, table)
    type(water_series_t), intent(in) :: s
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: step
    type(water_table_t), intent(out) :: table
    integer :: n, m, j, k
    real(wp) :: s0, s1, a, lam
    associate (unused => model)
    end associate
    n = s%n
    if (n < 2) then
      allocate (table%arc_length(0), table%u(0), table%time(0), table%v(0), table%speed(0), &
                table%height(0), table%width(0), table%beta(0), table%v_left(0), table%v_right(0))
      return
    end if
    s0 = s%arc_length(1); s1 = s%arc_length(n)
    m = max(int((s1 - s0)/step) + 1, 1)
    allocate (table%arc_length(m), table%u(m), table%time(m), table%v(m), table%speed(m), &
              table%height(m), table%width(m), table%beta(m), table%v_left(m), table%v_right(m))
    k = 1
    do j = 1, m
      a = s0 + (j - 1)*step
      do while (k < n - 1 .and. s%arc_length(k + 1) < a)
        k = k + 1
      end do
      lam = (a - s%arc_length(k))/max(s%arc_length(k + 1) - s%arc_length(k), tiny(1.0_wp))
      lam = min(max(lam, 0.0_wp), 1.0_wp)
      table%arc_length(j) = a
      table%u(j) = mix(s%u)
      table%time(j) = mix(s%time)
      table%v(j) = mix(s%v)
      table%speed(j) = mix(s%speed)
      table%height(j) = mix(s%height)
      table%width(j) = mix(s%width)
      table%beta(j) = mix(s%beta)
      table%v_left(j) = (1 - lam)*s%left_edge(2, k) + lam*s%left_edge(2, k + 1)
      table%v_right(j) = (1 - lam)*s%right_edge(2, k) + lam*s%right_edge(2, k + 1)
    end do
  contains
    pure real(wp) function mix(x)
      real(wp), intent(in) :: x(:)
      mix = (1 - lam)*x(k) + lam*x(k + 1)
    end function mix
  end subroutine water_table

  !> Centerline arc length between u_a and u_b by 3-point Gauss-Legendre (exact
  !> for quintics; over the few centimetres between samples the error is far
  !> below rounding of the sum)
  function arc_increment(channel, u_a, u_b) result(ds)
    class(channel_t), intent(in) :: channel
    real(wp), intent(in) :: u_a, u_b
    real(wp) :: ds
    real(wp), parameter :: x(3) = [0.0_wp, -0.7745966692414834_wp, 0.7745966692414834_wp]
    real(wp), parameter :: wt(3) = [0.8888888888888889_wp, 0.5555555555555556_wp, 0.5555555555555556_wp]
    real(wp) :: c(3, 0:3), mid, half
    type(status_t) :: st
    integer :: j
    mid = (u_a + u_b)/2; half = (u_b - u_a)/2
    ds = 0
    do j = 1, 3
      call channel%centerline(mid + half*x(j), c, st)
      ds = ds + half*wt(j)*norm2(c(:, 1))
    end do
  end function arc_increment
end module water_flow
