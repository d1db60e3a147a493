!> Where the rider's heels and back meet the slide at the start: the joint
!> angle (legs' flexion, trunk's tilt) at which the contact point, turning
!> with its body about the hip, lies on the slide, and the surface parameters
!> there. These are the dependent coordinates the closure (4.27) starts from.
!> A start where a contact cannot reach the slide is refused before any work,
!> with how far it stays from it. The pelvis's start is given as arc length
!> along the centerline (&rider u0) and turned into the slide's parameter
!> here (start_parameter).
!>
!> The signed distance of a point p from the slide is d = (p - r(u*, v*)).z_D
!> at its foot point (u*, v*) (geometry_foot_point's Newton on the two
!> tangency conditions, warm started along the scan); d > 0 inside the tube, d < 0 behind the wall. The
!> joint angle is scanned from 0 outwards in both directions (1 degree
!> steps, within the allowed range) for the sign change of d nearest to 0,
!> which bisection then locates to 1e-13 rad.
module rider_start
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_slide_query, only: slide_surface_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use geometry_foot_point, only: foot_point_options_t, foot_point_t, find_foot_point, FOOT_STOP_LENGTH, &
    FOOT_DOMAIN_STOP, FOOT_LEFT_DOMAIN
  implicit none (type, external)
  private
  public :: contact_reach_t, reach_contact, foot_point, turned, start_parameter

  type :: contact_reach_t
    logical :: reached = .false.
    real(wp) :: angle = 0          ! rad, joint angle with the point on the slide
    real(wp) :: u = 0, v = 0       ! surface parameters of the contact there
    real(wp) :: gap = 0            ! m, smallest |d| over the allowed angles (not reached)
    real(wp) :: gap_angle = 0      ! rad, where
    character(len=:), allocatable :: problem   ! why not reached, for the message
  end type contact_reach_t

  real(wp), parameter :: scan_step = pi/180   ! rad
  !> The foot point: Newton (geometry_foot_point) on the tangency conditions,
  !> at most 30 steps, the last a step shorter than 1e-14 (1 + |p|) m; it
  !> stops where the distance has no minimum (the iterate is kept) and when
  !> it leaves the parameter domain.
  type(foot_point_options_t), parameter :: start_options = foot_point_options_t(stop_rule=FOOT_STOP_LENGTH, &
    domain_rule=FOOT_DOMAIN_STOP, max_steps=30, tolerance=1e-14_wp, require_minimum=.true.)

contains

  !> p turned about the unit axis `axis` through `centre` by `angle` (Rodrigues).
  pure function turned(p, centre, axis, angle) result(q)
    real(wp), intent(in) :: p(3), centre(3), axis(3), angle
    real(wp) :: q(3), w(3)
    w = p - centre
    q = centre + w*cos(angle) + cross(axis, w)*sin(angle) + axis*dot_product(axis, w)*(1 - cos(angle))
  end function turned

  !> The foot point (u, v) of p on the surface (from the given start) and
  !> the signed distance d along z_D. inside = .false. if the iteration
  !> leaves the parameter domain (u, v hold the last iterate).
  subroutine foot_point(surface, sigma, alpha_u, alpha_v, p, u, v, d, inside, status)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: sigma, alpha_u, alpha_v, p(3)
    real(wp), intent(inout) :: u, v
    real(wp), intent(out) :: d
    logical, intent(out) :: inside
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: s
    type(darboux_frame_t) :: fr
    type(foot_point_t) :: foot
    d = 0
    inside = .true.
    call find_foot_point(surface, p, u, v, start_options, foot, status)
    if (.not. status%ok()) return
    if (foot%reason == FOOT_LEFT_DOMAIN) then
      inside = .false.
      return
    end if
    call surface%evaluate(u, v, 2, s, status)
    if (status%ok()) call darboux_frame(s, sigma, alpha_u, alpha_v, fr, status)
    if (.not. status%ok()) return
    d = dot_product(p - s%r, fr%r(:, 3))
  end subroutine foot_point

  !> The joint angle in [angle_range(1), angle_range(2)] nearest to 0 at
  !> which `point` (world, at angle 0), turned about `axis` through `centre`,
  !> lies on the slide. u, v: where to start the foot-point search.
  subroutine reach_contact(surface, sigma, alpha_u, alpha_v, point, centre, axis, angle_range, u, v, &
                           reach, status)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: sigma, alpha_u, alpha_v, point(3), centre(3), axis(3), angle_range(2), u, v
    type(contact_reach_t), intent(out) :: reach
    type(status_t), intent(inout) :: status
    real(wp) :: d0, d_prev(2), d, a_prev(2), a, lo, hi, d_lo, uu(2), vv(2), u0, v0, ub, vb, u_min, u_max, &
      v_min, v_max
    integer :: k, side
    logical :: inside, open(2)

    u0 = u
    v0 = v
    call foot_point(surface, sigma, alpha_u, alpha_v, point, u0, v0, d0, inside, status)
    if (.not. status%ok()) return
    if (.not. inside) then
      call surface%domain(u_min, u_max, v_min, v_max)
      if (u0 > u_max) then
        reach%problem = 'it would lie beyond the slide''s end, at u = '//format_short(u0)//' past u = '// &
                        format_short(u_max)//' (by '//format_short(u0 - u_max)//')'
      else if (u0 < u_min) then
        reach%problem = 'it would lie before the slide''s start, at u = '//format_short(u0)//' before u = '// &
                        format_short(u_min)//' (by '//format_short(u_min - u0)//')'
      else
        reach%problem = 'it would lie off the slide, at v = '//format_short(v0)//' outside ['// &
                        format_short(v_min)//', '//format_short(v_max)//']'
      end if
      return
    end if
    reach%gap = abs(d0)
    reach%gap_angle = 0
    if (d0 == 0) then
      call accept(0.0_wp, u0, v0)
      return
    end if
    d_prev = d0
    a_prev = 0
    uu = u0
    vv = v0
    open = .true.
    do k = 1, nint((max(abs(angle_range(1)), abs(angle_range(2))))/scan_step) + 1
      do side = 1, 2
        if (.not. open(side)) cycle
        a = merge(1, -1, side == 1)*k*scan_step
        if (a > angle_range(2) .or. a < angle_range(1)) then
          open(side) = .false.
          cycle
        end if
        call foot_point(surface, sigma, alpha_u, alpha_v, turned(point, centre, axis, a), uu(side), vv(side), &
                        d, inside, status)
        if (.not. status%ok()) return
        if (.not. inside) then
          open(side) = .false.
          cycle
        end if
        if (abs(d) < reach%gap) then
          reach%gap = abs(d)
          reach%gap_angle = a
        end if
        if (sign(1.0_wp, d) /= sign(1.0_wp, d_prev(side))) then
          ! bisection between a_prev and a
          lo = a_prev(side)
          hi = a
          d_lo = d_prev(side)
          ub = uu(side)
          vb = vv(side)
          do while (abs(hi - lo) > 1e-13_wp)
            a = 0.5_wp*(lo + hi)
            call foot_point(surface, sigma, alpha_u, alpha_v, turned(point, centre, axis, a), ub, vb, d, inside, &
                            status)
            if (.not. status%ok()) return
            if (sign(1.0_wp, d) == sign(1.0_wp, d_lo)) then
              lo = a
              d_lo = d
            else
              hi = a
            end if
          end do
          call accept(0.5_wp*(lo + hi), ub, vb)
          return
        end if
        d_prev(side) = d
        a_prev(side) = a
      end do
      if (.not. any(open)) exit
    end do
    reach%problem = 'the contact point stays '//format_short(reach%gap)//' m '// &
                    trim(merge('above the slide         ', 'outside the slide''s wall', d0 > 0))// &
                    ' at best (joint angle '//format_short(reach%gap_angle*180/pi)//' degrees; the start search '// &
                    'allows '//format_short(angle_range(1)*180/pi)//' to '//format_short(angle_range(2)*180/pi)// &
                    ' degrees)'

  contains

    subroutine accept(angle, uc, vc)
      real(wp), intent(in) :: angle, uc, vc
      reach%reached = .true.
      reach%angle = angle
      reach%u = uc
      reach%v = vc
      reach%gap = 0
    end subroutine accept
  end subroutine reach_contact

  !> The pelvis's start parameter u from `u0`, its arc length along the
  !> slide's centerline from the start (m; &rider u0, as declared): the
  !> slide's parameter is not arc length (an exact element chain's is the
  !> horizontal length, a fitted one's the chord length of its points). A
  !> start off the centerline is refused with its length. A surface that is
  !> not a slide takes u0 as its parameter (the ride refuses it anyway).
  subroutine start_parameter(surface, u0, u, status)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: u0
    real(wp), intent(out) :: u
    type(status_t), intent(inout) :: status
    real(wp) :: total
    character(len=:), allocatable :: side
    u = u0
    select type (surface)
    class is (slide_surface_t)
      total = surface%length()
      if (.not. (u0 >= 0 .and. u0 <= total)) then
        side = 'beyond the slide''s end'
        if (u0 < 0) side = 'before the slide''s start'
        call set_status(status, STATUS_INVALID_INPUT, 'the start u0 = '//format_short(u0)//' m (arc length '// &
                        'along the centerline) lies '//side//' (its centerline is '//format_short(total)//' m long)')
        return
      end if
      ! where the parameter already is arc length to rounding (a straight
      ! tube; a fitted centerline near its start), u0 is kept as given: the
      ! same point as the search would find, and the same bits
      if (abs(surface%arc_length(u0) - u0) <= 8*epsilon(1.0_wp)*max(total, 1.0_wp)) return
      call surface%parameter_at_length(u0, u, status)
      if (.not. status%ok()) call prefix_status(status, 'the start u0 = '//format_short(u0)//' m')
    end select
  end subroutine start_parameter
end module rider_start
