!> The samples of a water run (water_flow), grown as the run goes
!> (base_series): the state, the water point and its rates, the water's
!> edges (4.25-4.26) at every sample, the stations, and how the run ended.
module water_series
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_series, only: growable_series_t, resize
  use base_status, only: status_t, STATUS_DOMAIN
  use numerics_ode, only: ode_stats_t
  use water_streamline, only: streamline_t, water_point_t, water_rates_t, water_point_rates
  use water_boundaries, only: water_edges
  use water_inlet, only: water_inlet_t
  implicit none (type, external)
  private
  public :: water_series_t, water_station_t, allocate_series, record_sample, values_per_sample
  public :: OUTCOME_END, OUTCOME_DURATION, OUTCOME_STALL, OUTCOME_TURN, OUTCOME_CRITICAL, &
    OUTCOME_ERROR, OUTCOME_LIFT, OUTCOME_SAFETY_BOUND, outcome_name

  integer, parameter :: OUTCOME_END = 1, OUTCOME_DURATION = 2, OUTCOME_STALL = 3, OUTCOME_TURN = 4, &
                        OUTCOME_CRITICAL = 5, OUTCOME_ERROR = 6, OUTCOME_LIFT = 7, OUTCOME_SAFETY_BOUND = 8
  !> Numbers of one sample of water_series_t (its arrays), for the memory bound
  integer, parameter :: values_per_sample = 65

  type :: water_station_t
    real(wp) :: arc_length = 0, u = 0, time = 0, v = 0, speed = 0, height = 0, width = 0
    real(wp) :: v_left = 0, v_right = 0, v_middle = 0
    logical :: reached = .false.
  end type water_station_t

  !> The water's samples; grown as the run goes (base_series).
  type, extends(growable_series_t) :: water_series_t
    real(wp), allocatable :: time(:), u(:), v(:), du(:), dv(:), arc_length(:)
    real(wp), allocatable :: flow(:)           ! m^3/s, the flow rate at the sample (inlets upstream added)
    real(wp), allocatable :: position(:, :), velocity(:, :)
    real(wp), allocatable :: speed(:), height(:), width(:), area(:), radius(:), beta(:), alpha(:)
    real(wp), allocatable :: normal_force(:), friction_force(:), curvature(:), froude(:)
    real(wp), allocatable :: kinetic(:), potential(:), friction_work(:), correction_work(:)
    real(wp), allocatable :: left_edge(:, :), right_edge(:, :), left_point(:, :), right_point(:, :)
    integer, allocatable :: edge_solved(:)    ! 1: edges from (4.25-4.26); 0: circle estimate (or not solved)
    logical :: edges = .false.                 ! the edges were solved at the samples
    ! rates along the motion, for the water field's C1 interpolation
    real(wp), allocatable :: acceleration(:, :)      ! m/s^2 (3 x n)
    real(wp), allocatable :: speed_rate(:), height_rate(:), width_rate(:)   ! m/s^2, m/s, m/s
    real(wp), allocatable :: udd(:), vdd(:)          ! u'', v'' (4.23)
    real(wp), allocatable :: x_m(:, :), z_m(:, :), x_m_rate(:, :), z_m_rate(:, :)   ! K_M axes, 1/s
    real(wp), allocatable :: centerline_speed(:)     ! |c_u|, m per unit of u
    real(wp), allocatable :: centerline_speed_u(:)   ! d|c_u|/du, m per unit of u^2
    real(wp), allocatable :: left_edge_rate(:, :), right_edge_rate(:, :)   ! d[u, v]/dt (2 x n)
    integer :: edge_failures = 0                     ! samples where the edge solve failed
    character(len=:), allocatable :: edge_message   ! the first edge failure
    integer :: edge_beyond = 0                       ! samples with an edge beyond the slide's end
    real(wp) :: edge_beyond_from = 0                 ! m, arc length of the first of them
    type(water_station_t), allocatable :: stations(:)
    integer :: outcome = OUTCOME_ERROR
    character(len=:), allocatable :: message
    type(ode_stats_t) :: stats
    real(wp) :: flow_rate = 0          ! m^3/s, at the start (the inlets there added)
    type(water_inlet_t), allocatable :: inlets(:)   ! the inlets and when they joined
    real(wp) :: time_bound = 0         ! s, the bound the run had (the caller's or the safety bound)
    real(wp) :: cpu = 0                ! s, process CPU time of the run (driver)
  end type water_series_t

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
    case (OUTCOME_SAFETY_BOUND); text = 'safety time bound'
    case default; text = 'error'
    end select
  end function outcome_name

  !> Room for n samples in every array of the series, the recorded ones kept
  !> (first call: allocates). The new room is not filled: record sets every
  !> array at every sample, and nothing beyond s%n is read (untouched room
  !> costs no memory). Every array of water_series_t is listed here once, so
  !> growing keeps them all.
  subroutine allocate_series(s, n)
    type(water_series_t), intent(inout) :: s
    integer, intent(in) :: n
    call resize(s%time, n); call resize(s%u, n); call resize(s%v, n); call resize(s%du, n)
    call resize(s%dv, n); call resize(s%arc_length, n); call resize(s%flow, n); call resize(s%position, 3, n)
    call resize(s%velocity, 3, n); call resize(s%speed, n); call resize(s%height, n); call resize(s%width, n)
    call resize(s%area, n); call resize(s%radius, n); call resize(s%beta, n); call resize(s%alpha, n)
    call resize(s%normal_force, n); call resize(s%friction_force, n); call resize(s%curvature, n)
    call resize(s%froude, n); call resize(s%kinetic, n); call resize(s%potential, n)
    call resize(s%friction_work, n); call resize(s%correction_work, n); call resize(s%left_edge, 2, n)
    call resize(s%right_edge, 2, n); call resize(s%left_point, 3, n); call resize(s%right_point, 3, n)
    call resize(s%edge_solved, n); call resize(s%acceleration, 3, n); call resize(s%speed_rate, n)
    call resize(s%height_rate, n); call resize(s%width_rate, n); call resize(s%udd, n); call resize(s%vdd, n)
    call resize(s%x_m, 3, n); call resize(s%z_m, 3, n); call resize(s%x_m_rate, 3, n)
    call resize(s%z_m_rate, 3, n); call resize(s%centerline_speed, n); call resize(s%centerline_speed_u, n)
    call resize(s%left_edge_rate, 2, n)
    call resize(s%right_edge_rate, 2, n)
    s%capacity = n
  end subroutine allocate_series

  !> Appends the sample (t, y) of flow rate `flow` with the water point q
  !> (from water_point at y).
  subroutine record_sample(model, t, y, flow, q, s, with_edges, status)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: t, y(:), flow
    type(water_point_t), intent(in) :: q
    type(water_series_t), intent(inout) :: s
    logical, intent(in) :: with_edges
    type(status_t), intent(inout) :: status
    type(water_rates_t) :: rates
    type(status_t) :: st
    integer :: i, grown
    real(wp) :: guess_l(2), guess_r(2)
    st%code = 0
    call water_point_rates(model, y, q, rates, st)
    if (.not. st%ok()) then
      if (status%ok()) status = st
      return
    end if
    call s%make_room(16, 8.0_wp*values_per_sample, 'water', t, grown, st)
    if (.not. st%ok()) then
      if (status%ok()) status = st
      return
    end if
    if (grown > 0) call allocate_series(s, grown)
    s%n = s%n + 1
    i = s%n
    s%time(i) = t
    s%flow(i) = flow
    s%u(i) = y(1); s%v(i) = y(2); s%du(i) = y(3); s%dv(i) = y(4)
    s%height(i) = y(5)
    s%friction_work(i) = y(6); s%correction_work(i) = y(7)
    s%centerline_speed(i) = q%centerline_speed
    s%centerline_speed_u(i) = q%centerline_speed_u
    if (i == 1) then
      s%arc_length(i) = model%channel%arc_length(y(1))
    else   ! incremental: samples lie centimetres apart
      s%arc_length(i) = s%arc_length(i - 1) + arc_increment(s, i)
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
    s%udd(i) = q%udd; s%vdd(i) = q%vdd
    s%x_m(:, i) = q%x_m; s%z_m(:, i) = q%z_m
    s%x_m_rate(:, i) = rates%x_m; s%z_m_rate(:, i) = rates%z_m
    if (.not. with_edges) then
      s%edge_solved(i) = 0
      s%left_edge(:, i) = 0; s%right_edge(:, i) = 0; s%left_point(:, i) = 0; s%right_point(:, i) = 0
      s%left_edge_rate(:, i) = 0; s%right_edge_rate(:, i) = 0
      return
    end if
    if (i >= 2) then
      if (s%edge_solved(i - 1) == 1) then
        ! warm start: the previous outputs' edges carried forward in time by
        ! their rates (cubic Hermite through the two last solved outputs,
        ! extrapolated: error O(dt^4); from one output: linear)
        if (i >= 3) then
          if (s%edge_solved(i - 2) == 1 .and. s%time(i - 1) > s%time(i - 2)) then
            guess_l = carried(s%left_edge, s%left_edge_rate)
            guess_r = carried(s%right_edge, s%right_edge_rate)
          else
            guess_l = s%left_edge(:, i - 1) + (t - s%time(i - 1))*s%left_edge_rate(:, i - 1)
            guess_r = s%right_edge(:, i - 1) + (t - s%time(i - 1))*s%right_edge_rate(:, i - 1)
          end if
        else
          guess_l = s%left_edge(:, i - 1) + (t - s%time(i - 1))*s%left_edge_rate(:, i - 1)
          guess_r = s%right_edge(:, i - 1) + (t - s%time(i - 1))*s%right_edge_rate(:, i - 1)
        end if
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
      s%left_edge_rate(:, i) = 0; s%right_edge_rate(:, i) = 0
      if (st%code == STATUS_DOMAIN) then   ! the foot is beyond the end of the slide
        if (s%edge_beyond == 0) s%edge_beyond_from = s%arc_length(i)
        s%edge_beyond = s%edge_beyond + 1
      else
        if (s%edge_failures == 0) s%edge_message = 'at t = '//format_short(t)//' s: '//st%text()
        s%edge_failures = s%edge_failures + 1
      end if
    end if

  contains

    !> The edge at time t from its values and rates at samples i-2 and i-1.
    pure function carried(edge, rate) result(x)
      real(wp), intent(in) :: edge(:, :), rate(:, :)
      real(wp) :: x(2)
      real(wp) :: h, tau, w(4)
      h = s%time(i - 1) - s%time(i - 2)
      tau = (t - s%time(i - 2))/h
      w = [(1 + 2*tau)*(1 - tau)**2, tau*(1 - tau)**2, tau**2*(3 - 2*tau), tau**2*(tau - 1)]
      x = w(1)*edge(:, i - 2) + w(2)*h*rate(:, i - 2) + w(3)*edge(:, i - 1) + w(4)*h*rate(:, i - 1)
    end function carried
  end subroutine record_sample

  !> Centerline arc length between samples i-1 and i: the trapezoid of |c_u|
  !> with its end slopes (the corrected trapezoid rule, from the values and
  !> derivatives the water point has anyway),
  !>   ds = h (f_a + f_b)/2 + h^2 (f'_a - f'_b)/12,  error -h^5 f''''/720,
  !> below 1e-15 m for samples centimetres apart on a fitted slide.
  pure function arc_increment(s, i) result(ds)
    type(water_series_t), intent(in) :: s
    integer, intent(in) :: i
    real(wp) :: ds, h
    h = s%u(i) - s%u(i - 1)
    ds = h*(s%centerline_speed(i - 1) + s%centerline_speed(i))/2 + &
         h**2*(s%centerline_speed_u(i - 1) - s%centerline_speed_u(i))/12
  end function arc_increment
end module water_series
