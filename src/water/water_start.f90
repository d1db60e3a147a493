!> How the water enters the slide: the start values of a water run
!> (water_flow) from the start edges (thesis 4.33), a height, a speed, or
!> both (then the flow rate follows), on a circular section or a general
!> profile.
module water_start
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_point_t
  use water_section, only: circle_segment, circle_height_for_area, profile_water
  use water_channel, only: channel_t
  use water_streamline, only: streamline_t, velocity_from_angle
  implicit none (type, external)
  private
  public :: water_start_t, water_initial_state, start_state
  public :: START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED

  integer, parameter :: START_EDGES = 1, START_HEIGHT = 2, START_SPEED = 3, START_HEIGHT_SPEED = 4

  !> How the water enters at u0 (thesis 4.33 or given values).
  type :: water_start_t
    integer :: mode = START_EDGES
    !> the first section: its centerline parameter u here (start_state); in a
    !> water description (water_run) its arc length along the centerline, m,
    !> which new_streamline turns into u
    real(wp) :: u0 = 0
    real(wp) :: v0 = pi/2              ! rad, water middle (START_EDGES: from the edges)
    real(wp) :: v_left = pi/2 + 0.3_wp, v_right = pi/2 - 0.3_wp   ! rad, edges (START_EDGES)
    real(wp) :: height = 0.01_wp       ! m (START_HEIGHT, START_HEIGHT_SPEED)
    real(wp) :: speed = 1              ! m/s (START_SPEED, START_HEIGHT_SPEED)
    real(wp) :: beta = 0               ! rad, flow angle to the centerline
  end type water_start_t

contains

  !> Initial state [u, v, u', v', h, 0, 0] and the flow rate (set in model%flow_rate
  !> for START_HEIGHT_SPEED; read from it otherwise).
  subroutine water_initial_state(model, start, y0, status)
    type(streamline_t), intent(inout) :: model
    type(water_start_t), intent(in) :: start
    real(wp), intent(out) :: y0(7)
    type(status_t), intent(out) :: status
    call start_state(model%channel, model%flow_rate, start, y0, status)
  end subroutine water_initial_state

  !> The state [u, v, u', v', h, 0, 0] of water of flow rate `flow_rate`
  !> entering the channel as `start` says (START_HEIGHT_SPEED sets
  !> flow_rate = A w; the other modes read it): the start of a run, and the
  !> state after an inlet joined (water_inlet, START_SPEED).
  subroutine start_state(channel, flow_rate, start, y0, status)
    class(channel_t), intent(in) :: channel
    real(wp), intent(inout) :: flow_rate
    type(water_start_t), intent(in) :: start
    real(wp), intent(out) :: y0(7)
    type(status_t), intent(out) :: status
    type(surface_point_t) :: p
    real(wp) :: r, radius, area, width, alpha, h, w, v0, du, dv, vl, vr, u_min, u_max

    y0 = 0
    call channel%u_range(u_min, u_max)
    if (start%u0 < u_min .or. start%u0 >= u_max) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start u0 is outside the slide')
      return
    end if
    if (abs(start%beta) >= pi/2) then
      call set_status(status, STATUS_INVALID_INPUT, 'the start flow angle beta must be within +-90 degrees')
      return
    end if
    if (start%mode /= START_HEIGHT_SPEED .and. .not. flow_rate > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'the flow rate Q must be > 0')
      return
    end if
    r = channel%circle_radius(start%u0)
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
        call profile_water(channel, start%u0, v0, h, area, width, vl, vr, status)
        if (.not. status%ok()) return
      end if
      w = flow_rate/area
    case (START_HEIGHT, START_HEIGHT_SPEED)
      h = start%height
      if (.not. h > 0 .or. (r > 0 .and. h >= 2*radius)) then
        call set_status(status, STATUS_INVALID_INPUT, 'the start height must be > 0 and inside the section')
        return
      end if
      if (r > 0) then
        call circle_segment(h, radius, area, width, alpha)
      else
        call profile_water(channel, start%u0, v0, h, area, width, vl, vr, status)
        if (.not. status%ok()) return
      end if
      if (start%mode == START_HEIGHT) then
        w = flow_rate/area
      else
        w = start%speed
        flow_rate = area*w
      end if
    case (START_SPEED)
      w = start%speed
      if (r > 0) then
        call circle_height_for_area(flow_rate/w, radius, h, status)
      else
        call profile_height(flow_rate/w, h, status)
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
    call channel%evaluate(start%u0, v0, 2, p, status)
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
      call channel%evaluate(start%u0, v0, 1, p0, st)
      if (st%ok()) call channel%evaluate(start%u0, start%v_left, 0, pl, st)
      if (st%ok()) call channel%evaluate(start%u0, start%v_right, 0, pr, st)
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
        call profile_water(channel, start%u0, v0, hi, a, b, l, rr, st)
        if (.not. st%ok()) return
        if (a >= target) exit
        lo = hi; hi = 2*hi
      end do
      do it = 1, 200
        hh = (lo + hi)/2
        call profile_water(channel, start%u0, v0, hh, a, b, l, rr, st)
        if (.not. st%ok()) return
        if (a > target) then
          hi = hh
        else
          lo = hh
        end if
        if (hi - lo <= 1e-15_wp*hi) exit
      end do
    end subroutine profile_height
  end subroutine start_state
end module water_start
