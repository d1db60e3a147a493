!> Inlets: more water joining the stream along the slide (docs/water.md,
!> "Several inlets"). An inlet adds its flow rate at its arc length, entering
!> with its own speed along the surface at an angle to the centerline. The
!> merge is instantaneous at the inlet's section and keeps
!>   mass:     Q+ = Q + Q_i (exactly: one addition);
!>   momentum: (Q + Q_i) w+ = Q w + Q_i w_i for the velocity vectors in the
!>             surface's tangent plane at the water point (along and across
!>             the slide; rho cancels);
!> the streamline keeps its place (u, v), the height follows from continuity
!> A(h+) = Q+/|w+| (with R of 4.15 at the merged angle), the work integrals
!> go on. The kinetic energy lost in the mixing, Q Q_i |w - w_i|^2/(2 Q+)
!> per unit of density and time, is not tracked by the model.
module water_inlet
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, STATUS_DOMAIN
  use base_text, only: format_short
  use water_streamline, only: streamline_t, water_point_t, water_point
  use water_start, only: water_start_t, start_state, START_SPEED, START_HEIGHT_SPEED
  implicit none (type, external)
  private
  public :: water_inlet_t, merge_velocity, join_inlet, join_start_inlets, start_tolerance

  !> Inlets closer than this to the start's arc length (m) join at the start.
  real(wp), parameter :: start_tolerance = 1e-9_wp

  !> One inlet: where, how much and how fast; and what happened to it.
  type :: water_inlet_t
    real(wp) :: arc_length = 0     !< m of centerline arc length where the water joins
    real(wp) :: flow_rate = 0      !< m^3/s added
    real(wp) :: speed = 1          !< m/s, the inlet water's speed along the surface
    real(wp) :: beta = 0           !< rad, its angle to the centerline (+ towards +v)
    real(wp) :: u = 0              !< centerline parameter of arc_length (set by the run)
    logical :: joined = .false.    !< the stream reached it and took its water
    real(wp) :: time = 0           !< s, when it joined
  end type water_inlet_t

contains

  !> Speed and angle of the merged stream: the flow-weighted mean of the two
  !> velocity vectors, in components along (-y_M) and across (x_M) the slide.
  !> Equal velocities give the stream's own speed and angle, unrounded.
  pure subroutine merge_velocity(flow, speed, beta, inlet, merged_speed, merged_beta)
    real(wp), intent(in) :: flow, speed, beta
    type(water_inlet_t), intent(in) :: inlet
    real(wp), intent(out) :: merged_speed, merged_beta
    real(wp) :: share, along, across
    if (inlet%speed == speed .and. inlet%beta == beta) then
      merged_speed = speed
      merged_beta = beta
      return
    end if
    share = inlet%flow_rate/(flow + inlet%flow_rate)
    along = speed*cos(beta) + share*(inlet%speed*cos(inlet%beta) - speed*cos(beta))
    across = speed*sin(beta) + share*(inlet%speed*sin(inlet%beta) - speed*sin(beta))
    merged_speed = hypot(along, across)
    merged_beta = atan2(across, along)
  end subroutine merge_velocity

  !> The stream in state y with flow rate `flow` after `inlet` joined at its
  !> section: y_joined (same u, v and work integrals; u', v' of the merged
  !> velocity; h from continuity) and flow + inlet%flow_rate.
  subroutine join_inlet(model, y, flow, inlet, y_joined, flow_joined, status)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: y(:), flow
    type(water_inlet_t), intent(in) :: inlet
    real(wp), intent(out) :: y_joined(:), flow_joined
    type(status_t), intent(out) :: status
    type(water_point_t) :: q
    real(wp) :: w, beta
    y_joined = y
    flow_joined = flow
    call water_point(model, y, q, status)
    if (.not. status%ok()) return
    call merge_velocity(flow, q%speed, q%beta, inlet, w, beta)
    call restart_state(model, y, flow + inlet%flow_rate, w, beta, y_joined, flow_joined, status)
    if (.not. status%ok()) then
      ! a state of the run, not an input the model could check before
      status%code = STATUS_DOMAIN
      call prefix_status(status, 'the inlet at arc length '//format_short(inlet%arc_length)//' m: the merged '// &
                         'water (Q = '//format_short(flow + inlet%flow_rate)//' m^3/s at '//format_short(w)// &
                         ' m/s) has no water height in this section')
    end if
  end subroutine join_inlet

  !> The start state y0 of flow model%flow_rate, entering as `start`, after
  !> the inlets that lie at the start joined (the others are left as they
  !> are): the start's own speed and angle, as given (START_SPEED,
  !> START_HEIGHT_SPEED) or from continuity (the others), merged with each;
  !> model%flow_rate becomes the sum. Without such inlets nothing changes.
  subroutine join_start_inlets(model, start, start_arc_length, inlets, y0, status)
    type(streamline_t), intent(inout) :: model
    type(water_start_t), intent(in) :: start
    real(wp), intent(in) :: start_arc_length
    type(water_inlet_t), intent(inout) :: inlets(:)
    real(wp), intent(inout) :: y0(:)
    type(status_t), intent(inout) :: status
    type(water_point_t) :: q
    real(wp) :: w, beta, flow, y_start(size(y0)), flow_start, w_before, beta_before
    integer :: k
    if (.not. status%ok()) return
    if (.not. any(inlets%arc_length <= start_arc_length + start_tolerance)) return
    if (start%mode == START_SPEED .or. start%mode == START_HEIGHT_SPEED) then
      w = start%speed
    else
      call water_point(model, y0, q, status)
      if (.not. status%ok()) return
      w = q%speed
    end if
    beta = start%beta
    flow = model%flow_rate
    do k = 1, size(inlets)
      if (inlets(k)%arc_length > start_arc_length + start_tolerance) cycle
      w_before = w
      beta_before = beta
      call merge_velocity(flow, w_before, beta_before, inlets(k), w, beta)
      flow = flow + inlets(k)%flow_rate
      inlets(k)%joined = .true.
      inlets(k)%time = 0
    end do
    y_start = y0
    call restart_state(model, y_start, flow, w, beta, y0, flow_start, status)
    if (status%ok()) model%flow_rate = flow_start
    if (.not. status%ok()) call prefix_status(status, 'the inlets at the start')
  end subroutine join_start_inlets

  !> The state at y's (u, v) of water of flow rate `flow` at speed w and angle
  !> beta (a START_SPEED start there), the work integrals of y kept.
  subroutine restart_state(model, y, flow, w, beta, y_new, flow_new, status)
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: y(:), flow, w, beta
    real(wp), intent(inout) :: y_new(:)
    real(wp), intent(out) :: flow_new
    type(status_t), intent(inout) :: status
    real(wp) :: state(7), work(2)
    work = y(6:7)
    flow_new = flow
    call start_state(model%channel, flow_new, water_start_t(mode=START_SPEED, u0=y(1), v0=y(2), speed=w, beta=beta), &
                     state, status)
    if (.not. status%ok()) return
    y_new(1:5) = state(1:5)
    y_new(6:7) = work
  end subroutine restart_state
end module water_inlet
