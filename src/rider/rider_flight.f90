!> The rider's flights (issue 25 points 1 and 4; docs/rider.md "Flight"):
!> where a contact's normal force falls to zero (the heels on a crest, then
!> the pelvis, the back) that contact opens and its body flies, the others
!> staying on; with all three open the whole rider flies, a free system.
!>
!> The ride switches between builds of one rider (rider_model's build_rider
!> with free_pelvis, one per set of open contacts) whose scalars, frames,
!> contacts and laws sit at the same indices. An open contact's gap
!> (contact_gap) is its point's signed distance from the slide along the
!> normal at its foot point: the heels' (back's) loop holds the point on
!> that normal only and measures it; the open pelvis sits on its foot
!> point's normal at the lift h, a coordinate. A state carries over through
!> the full layout [u_B, v_B, phi_B, phi_U, phi_O, h], their rates, then
!> the laws' work integrals (full_state, build_state): the
!> positions and velocities are continuous through a switch, to the
!> closure's rounding.
!>
!> The landing (contact_impact): the gap closes with an approaching normal
!> speed; the impulse at the contact point is kinetostatics_point_impact's
!> (the law of kinetostatics_impact with the effective mass of the build in
!> flight at that point, K = J M^-1 J^T, whatever else holds it); a rebound
!> slower than close_speed closes the contact, its closing impulse's energy
!> added to the impact's.
module rider_flight
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_status, only: status_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t
  use kinetostatics_point_impact, only: point_gap, point_gap_rate, point_impact
  use rider_model, only: rider_layout_t, contact_names, CONTACT_PELVIS, CONTACT_HEELS, N_CONTACTS
  use rider_hip_hold, only: hip_hold_t
  use rider_body, only: rigid_body_t
  implicit none (type, external)
  private
  public :: landing_record, quick_landings_exceeded, count_switch
  public :: rider_landing_t, ride_flights_t, contact_gap, contact_gap_rate, full_state, build_state, &
    contact_impact, add_landing, highest_drop, full_scalars, set_holds, centre_of_mass, N_FULL

  !> m/s: a rebound slower than this closes the contact (the flight it would
  !> start rises v^2/(2 g) ~ 5e-8 m: below any slide's tolerance; it also
  !> ends a restitution's endless bounces, e^k v0).
  real(wp), parameter, public :: close_speed = 1e-3_wp

  !> Landings within quick_flight (s) of their take-off, more than
  !> max_quick_landings in a row, end the run (a contact neither stays on
  !> nor leaves: a chatter the model cannot resolve): the rider's and the
  !> vehicle's.
  real(wp), parameter, public :: quick_flight = 1e-9_wp
  integer, parameter, public :: max_quick_landings = 5

  !> The coordinates of the full layout: u_B, v_B, phi_B, phi_U, phi_O, h.
  integer, parameter :: N_FULL = 6

  !> One landing.
  type :: rider_landing_t
    real(wp) :: time = 0                 ! s
    integer :: contact = 0               ! which contact landed (CONTACT_PELVIS ...)
    real(wp) :: arc_length = 0           ! m, of its foot point along the centerline
    real(wp) :: normal_speed = 0         ! m/s, its approach speed along the slide's normal (> 0)
    real(wp) :: impulse = 0              ! N s, |L| of the landing's impulse (with the closing's)
    real(wp) :: normal_impulse = 0       ! N s, its part along the normal
    real(wp) :: drop_height = 0          ! m, normal_speed^2/(2 |g|)
    real(wp) :: energy_lost = 0          ! J, the kinetic energy the impact took
    logical :: closed = .false.          ! the contact stayed closed (else it flew on)
  end type rider_landing_t

  !> The flights of a ride: airtime (total, the longest and where it
  !> started), the highest gap and each landing. A flight is a time with
  !> any contact open; the whole rider's flights (all three open) apart.
  type :: ride_flights_t
    logical :: watched = .false.         ! the ride may fly (may_fly): the figures below are its
    integer :: flights = 0               ! take-offs (from the slide, and rebounds), any contact
    real(wp) :: airtime = 0              ! s, total, any contact open
    real(wp) :: longest = 0              ! s
    real(wp) :: longest_time = 0         ! s, its take-off
    real(wp) :: longest_arc_length = 0   ! m, its take-off (the pelvis)
    real(wp) :: highest = 0              ! m, the largest gap of a contact above the slide (dense output)
    integer :: highest_contact = 0       ! which
    real(wp) :: highest_time = 0         ! s
    real(wp) :: highest_arc_length = 0   ! m, of its foot point there
    real(wp) :: take_off_time = 0        ! s, of the flight under way
    real(wp) :: take_off_arc_length = 0  ! m
    !> the whole rider in the air (every contact open)
    integer :: whole_flights = 0
    real(wp) :: whole_airtime = 0        ! s
    real(wp) :: whole_longest = 0        ! s
    real(wp) :: whole_longest_arc_length = 0   ! m, its take-off (the pelvis's foot point)
    real(wp) :: whole_take_off_time = 0  ! s, of the whole flight under way
    real(wp) :: whole_take_off_arc_length = 0  ! m
    !> the whole rider's last take-off: centre of mass (m) and its velocity (m/s)
    real(wp) :: whole_take_off_com(3) = 0, whole_take_off_velocity(3) = 0
    integer :: landings = 0
    type(rider_landing_t), allocatable :: landing(:)
  end type ride_flights_t

contains

  !> The scalar indices of the full layout's coordinates.
  pure function full_scalars(lay) result(k)
    type(rider_layout_t), intent(in) :: lay
    integer :: k(N_FULL)
    k = [lay%u(CONTACT_PELVIS), lay%v(CONTACT_PELVIS), lay%heading, lay%flexion, lay%tilt, lay%lift]
  end function full_scalars

  !> Contact k's point's signed distance from the slide along the normal at
  !> its foot point (positive on the rider's side), positions set (a build
  !> with k open; closed: 0 to the closure's rounding).
  pure real(wp) function contact_gap(work, lay, k) result(gap)
    type(mechanism_workspace_t), intent(in) :: work
    type(rider_layout_t), intent(in) :: lay
    integer, intent(in) :: k
    gap = point_gap(work, lay%point(k), lay%contact_frame(k))
  end function contact_gap

  !> Contact k's point's velocity along that normal (velocities set).
  pure real(wp) function contact_gap_rate(work, lay, k) result(rate)
    type(mechanism_workspace_t), intent(in) :: work
    type(rider_layout_t), intent(in) :: lay
    integer, intent(in) :: k
    rate = point_gap_rate(work, lay%point(k), lay%contact_frame(k))
  end function contact_gap_rate

  !> The full layout's state [q(N_FULL), q'(N_FULL), W] of m at its state y
  !> (positions and velocities set in work: the dependents' values and rates
  !> from its last evaluation).
  pure subroutine full_state(m, work, lay, y, full)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(in) :: work
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(in) :: y(:)
    real(wp), intent(out) :: full(:)
    integer :: k(N_FULL)
    k = full_scalars(lay)
    full = [work%scalars(k)%q, work%scalars(k)%qd, y(2*m%f + 1:)]
  end subroutine full_state

  !> m's state [q, s, W] from a full layout's (its coordinates picked).
  pure subroutine build_state(m, lay, full, y)
    type(mechanism_t), intent(in) :: m
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(in) :: full(:)
    real(wp), intent(out) :: y(:)
    integer :: k(N_FULL), i, j
    k = full_scalars(lay)
    do i = 1, m%f
      j = findloc(k, m%q(i), dim=1)
      y(i) = full(j)
      y(m%f + i) = full(N_FULL + j)
    end do
    y(2*m%f + 1:) = full(2*N_FULL + 1:)
  end subroutine build_state

  !> Contact c's impact on m (a build with c open) at state y: the impulse
  !> of `law` and, for a rebound slower than close_speed, the closing one
  !> (kinetostatics_point_impact); s updated in y.
  !> `closed`: the contact closes. closing_impulse: the closing's impulse at
  !> the point (N s), closing_energy (J) what it took.
  subroutine contact_impact(m, work, lay, c, y, law, outcome, closed, closing_impulse, closing_energy, status)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    type(rider_layout_t), intent(in) :: lay
    integer, intent(in) :: c
    real(wp), intent(inout) :: y(:)
    type(impact_law_t), intent(in) :: law
    type(impact_outcome_t), intent(out) :: outcome
    logical, intent(out) :: closed
    real(wp), intent(out) :: closing_impulse(3), closing_energy
    type(status_t), intent(inout) :: status
    call point_impact(m, work, lay%point(c), lay%contact_frame(c), trim(contact_names(c)), y, law, close_speed, &
                      outcome, closed, closing_impulse, closing_energy, status)
  end subroutine contact_impact

  !> The hips' holds (rider_hip_hold) in the workspace `work` on or off,
  !> holding `posture` (flexion, tilt; rad).
  subroutine set_holds(work, lay, on, posture)
    type(mechanism_workspace_t), intent(inout) :: work
    type(rider_layout_t), intent(in) :: lay
    logical, intent(in) :: on
    real(wp), intent(in) :: posture(2)
    integer :: k
    do k = 1, 2
      if (lay%hold(k) == 0) cycle
      associate (law => work%laws(lay%hold(k))%law)
        law%active = on
        select type (law)
        type is (hip_hold_t)
          law%hold = posture(k)
        end select
      end associate
    end do
  end subroutine set_holds

  !> The rider's centre of mass and its velocity (positions and velocities
  !> set in work).
  subroutine centre_of_mass(work, lay, com, velocity)
    type(mechanism_workspace_t), intent(in) :: work
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(out) :: com(3), velocity(3)
    real(wp) :: mass, s(3)
    type(rigid_body_t) :: part
    integer :: k
    com = 0
    velocity = 0
    mass = 0
    do k = 1, N_CONTACTS
      part = body_part(k)
      associate (fr => work%frames(lay%body_frame(k)))
        s = matmul(fr%rot, part%com)
        com = com + part%mass*(fr%r + s)
        velocity = velocity + part%mass*(fr%v + cross(fr%omega, s))
        mass = mass + part%mass
      end associate
    end do
    com = com/mass
    velocity = velocity/mass

  contains

    function body_part(k) result(part)
      integer, intent(in) :: k
      type(rigid_body_t) :: part
      select case (k)
      case (CONTACT_PELVIS)
        part = lay%body%pelvis
      case (CONTACT_HEELS)
        part = lay%body%legs
      case default
        part = lay%body%trunk
      end select
    end function body_part
  end subroutine centre_of_mass

  !> The largest drop height of the landings and where (0, 0: none).
  pure subroutine highest_drop(flights, height, arc_length)
    type(ride_flights_t), intent(in) :: flights
    real(wp), intent(out) :: height, arc_length
    integer :: k
    height = 0
    arc_length = 0
    if (flights%landings == 0) return
    k = maxloc(flights%landing%drop_height, dim=1)
    height = flights%landing(k)%drop_height
    arc_length = flights%landing(k)%arc_length
  end subroutine highest_drop

  !> A landing's record from its impact and the closing impulse after it
  !> (at contact c, time t, arc_length of its foot point, |g| gravity).
  pure function landing_record(t, c, arc_length, impact, closing, closing_energy, closed, gravity) result(landing)
    real(wp), intent(in) :: t, arc_length, closing(3), closing_energy, gravity
    integer, intent(in) :: c
    type(impact_outcome_t), intent(in) :: impact
    logical, intent(in) :: closed
    type(rider_landing_t) :: landing
    landing%time = t
    landing%contact = c
    landing%arc_length = arc_length
    landing%normal_speed = -impact%normal_speed_before
    landing%impulse = norm2(impact%impulse + closing)
    landing%normal_impulse = impact%normal_impulse + norm2(closing)
    landing%drop_height = landing%normal_speed**2/(2*gravity)
    landing%energy_lost = impact%energy_lost + closing_energy
    landing%closed = closed
  end function landing_record

  !> Counts a landing `flight_time` after its take-off in the row of quick
  !> ones (a slower one ends the row); true when the row has grown past
  !> max_quick_landings.
  logical function quick_landings_exceeded(row, flight_time) result(exceeded)
    integer, intent(inout) :: row
    real(wp), intent(in) :: flight_time
    if (flight_time < quick_flight) then
      row = row + 1
    else
      row = 0
    end if
    exceeded = row > max_quick_landings
  end function quick_landings_exceeded

  !> The flights' counts and airtimes after a switch at t from the open
  !> contacts `before` to `now` (bit masks; all_open: every contact open): a
  !> flight starts when the first contact opens and ends when the last one
  !> closes, a whole flight likewise with every contact open; arc_length is
  !> where the body is at the switch.
  subroutine count_switch(flights, before, now, all_open, t, arc_length)
    type(ride_flights_t), intent(inout) :: flights
    integer, intent(in) :: before, now, all_open
    real(wp), intent(in) :: t, arc_length
    real(wp) :: airtime
    associate (fl => flights)
      if (before == 0 .and. now /= 0) then
        fl%flights = fl%flights + 1
        fl%take_off_time = t
        fl%take_off_arc_length = arc_length
      else if (before /= 0 .and. now == 0) then
        airtime = t - fl%take_off_time
        fl%airtime = fl%airtime + airtime
        if (airtime > fl%longest) then
          fl%longest = airtime
          fl%longest_time = fl%take_off_time
          fl%longest_arc_length = fl%take_off_arc_length
        end if
      end if
      if (before /= all_open .and. now == all_open) then
        fl%whole_flights = fl%whole_flights + 1
        fl%whole_take_off_time = t
        fl%whole_take_off_arc_length = arc_length
      else if (before == all_open .and. now /= all_open) then
        airtime = t - fl%whole_take_off_time
        fl%whole_airtime = fl%whole_airtime + airtime
        if (airtime > fl%whole_longest) then
          fl%whole_longest = airtime
          fl%whole_longest_arc_length = fl%whole_take_off_arc_length
        end if
      end if
    end associate
  end subroutine count_switch

  !> Adds a landing to the ride's flights (grown by one).
  subroutine add_landing(flights, landing)
    type(ride_flights_t), intent(inout) :: flights
    type(rider_landing_t), intent(in) :: landing
    if (.not. allocated(flights%landing)) allocate (flights%landing(0))
    flights%landing = [flights%landing, landing]
    flights%landings = size(flights%landing)
  end subroutine add_landing
end module rider_flight
