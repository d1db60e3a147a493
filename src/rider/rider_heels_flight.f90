!> The heels' flight (issue 25 point 1, partial flight; docs/rider.md
!> "Flight"): where the heels' normal force falls to zero on a crest, the
!> heels leave the slide while the pelvis and the back stay on it.
!>
!> The ride switches between two builds of the same rider (rider_model's
!> build_rider, plain and heels_open), whose scalars, frames, contacts and
!> laws sit at the same indices: in the open build the legs' flexion phi_U is
!> a fourth coordinate and the heel point is held only on the normal through
!> its foot point on the slide, so the heels' loop measures the heel's signed
!> gap (heels_gap). A state maps one to one (take_off_state, landing_state):
!> the coordinates and speeds of the pelvis, the flexion and its rate (a
!> dependent in the plain build), the laws' work integrals; positions and
!> velocities are continuous through the switch, to the closure's rounding.
!>
!> The landing (heels_impact): the gap closes with an approaching normal
!> speed; the impulse L at the heel comes from kinetostatics_impact's law
!> (restitution, Coulomb mu) with the Delassus matrix K = J M^-1 J^T of the
!> open rider (J: the heel point's velocity per speed, M: the mass matrix in
!> the speeds, from the kinetic energy), so the effective mass is that of the
!> legs on the hip, the pelvis held on the slide by its surface joint; the
!> speeds change by M^-1 J^T L, the positions not. A rebound slower than
!> close_speed closes the contact with a further frictionless plastic
!> impulse along the normal (its energy, v_n^2/(2 n.K n), added to the
!> impact's).
module rider_heels_flight
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t, resolve_impact
  use rider_model, only: rider_layout_t, CONTACT_HEELS
  implicit none (type, external)
  private
  public :: heels_landing_t, ride_flights_t, heels_gap, heels_gap_rate, take_off_state, landing_state, heels_impact, &
    add_landing, highest_drop

  !> m/s: a rebound of the heels slower than this closes their contact (the
  !> flight it would start rises v^2/(2 g) ~ 5e-8 m: below any slide's
  !> tolerance; it also ends a restitution's endless bounces, e^k v0).
  real(wp), parameter, public :: close_speed = 1e-3_wp

  !> One landing of the heels.
  type :: heels_landing_t
    real(wp) :: time = 0                 ! s
    real(wp) :: arc_length = 0           ! m, of the heels' foot point along the centerline
    real(wp) :: normal_speed = 0         ! m/s, the heel's approach speed along the slide's normal (> 0)
    real(wp) :: impulse = 0              ! N s, |L| of the landing's impulse (with the closing's)
    real(wp) :: normal_impulse = 0       ! N s, its part along the normal
    real(wp) :: drop_height = 0          ! m, normal_speed^2/(2 |g|)
    real(wp) :: energy_lost = 0          ! J, the kinetic energy the impact took
    logical :: closed = .false.          ! the heels stayed on (else they flew on)
  end type heels_landing_t

  !> The flights of a ride: airtime (total, the longest and where it
  !> started), the highest gap and each landing.
  type :: ride_flights_t
    logical :: watched = .false.         ! the ride may fly (may_fly): the figures below are its
    integer :: flights = 0               ! take-offs (from the slide, and rebounds)
    real(wp) :: airtime = 0              ! s, total
    real(wp) :: longest = 0              ! s
    real(wp) :: longest_time = 0         ! s, its take-off
    real(wp) :: longest_arc_length = 0   ! m, its take-off (the pelvis)
    real(wp) :: highest = 0              ! m, the largest gap of the heels above the slide (at the records)
    real(wp) :: highest_time = 0         ! s
    real(wp) :: highest_arc_length = 0   ! m, of the heels' foot point there
    real(wp) :: take_off_time = 0        ! s, of the flight under way
    real(wp) :: take_off_arc_length = 0  ! m
    integer :: landings = 0
    type(heels_landing_t), allocatable :: landing(:)
  end type ride_flights_t

contains

  !> The heel point's signed distance from the slide along the normal at its
  !> foot point (positive on the rider's side), positions set (open build).
  pure real(wp) function heels_gap(m, lay) result(gap)
    type(mechanism_t), intent(in) :: m
    type(rider_layout_t), intent(in) :: lay
    associate (p => m%frames(lay%heel_point), d => m%frames(lay%contact_frame(CONTACT_HEELS)))
      gap = dot_product(p%r - d%r, d%rot(:, 3))
    end associate
  end function heels_gap

  !> The heel point's velocity along that normal (velocities set).
  pure real(wp) function heels_gap_rate(m, lay) result(rate)
    type(mechanism_t), intent(in) :: m
    type(rider_layout_t), intent(in) :: lay
    associate (p => m%frames(lay%heel_point), d => m%frames(lay%contact_frame(CONTACT_HEELS)))
      rate = dot_product(p%v, d%rot(:, 3))
    end associate
  end function heels_gap_rate

  !> The open build's state from the plain one's at the heels' lift-off:
  !> y = [q(3), s(3), W] -> [q(3), phi_U, s(3), phi_U', W], phi_U and its rate
  !> from `closed`, evaluated at y.
  pure subroutine take_off_state(closed, lay, y, y_open)
    type(mechanism_t), intent(in) :: closed
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(in) :: y(:)
    real(wp), intent(out) :: y_open(:)
    y_open = [y(1:3), closed%scalars(lay%flexion)%q, y(4:6), closed%scalars(lay%flexion)%qd, y(7:)]
  end subroutine take_off_state

  !> The plain build's state from the open one's: phi_U and its rate become
  !> dependent again.
  pure subroutine landing_state(y_open, y)
    real(wp), intent(in) :: y_open(:)
    real(wp), intent(out) :: y(:)
    y = [y_open(1:3), y_open(5:7), y_open(9:)]
  end subroutine landing_state

  !> The heels' impact on the open build m at state y (q and s of the open
  !> build): the impulse of `law` and, for a rebound slower than close_speed,
  !> the closing one; s updated in y. `closed`: the contact closes.
  subroutine heels_impact(m, work, lay, t, y, law, outcome, closed, closing_impulse, closing_energy, status)
    type(mechanism_t), intent(inout) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    type(rider_layout_t), intent(in) :: lay
    real(wp), intent(in) :: t
    real(wp), intent(inout) :: y(:)
    type(impact_law_t), intent(in) :: law
    type(impact_outcome_t), intent(out) :: outcome
    logical, intent(out) :: closed
    real(wp), intent(out) :: closing_impulse(3), closing_energy
    type(status_t), intent(inout) :: status
    integer, parameter :: n = 4
    real(wp) :: jac(3, n), mass(n, n), minv_jt(n, 3), k(3, 3), normal(3), v(3), e(n), s(n), energy(n), &
      kinetic, potential, vn, lu(n, n)
    integer :: i, j, ipiv(n)
    associate (unused => t)
    end associate
    closed = .false.
    closing_impulse = 0
    closing_energy = 0
    s = y(n + 1:2*n)
    call m%set_positions(work, y(1:n), status)
    if (.not. status%ok()) return
    ! J: the heel point's velocity per unit speed; M from T(e_i), T(e_i + e_j)
    do i = 1, n
      e = 0
      e(i) = 1
      call m%set_velocities(work, e)
      jac(:, i) = m%frames(lay%heel_point)%v
      call m%energy(energy(i), potential)
      mass(i, i) = 2*energy(i)
    end do
    do i = 1, n
      do j = i + 1, n
        e = 0
        e(i) = 1
        e(j) = 1
        call m%set_velocities(work, e)
        call m%energy(kinetic, potential)
        mass(i, j) = kinetic - energy(i) - energy(j)
        mass(j, i) = mass(i, j)
      end do
    end do
    call m%set_velocities(work, s)
    v = m%frames(lay%heel_point)%v
    normal = m%frames(lay%contact_frame(CONTACT_HEELS))%rot(:, 3)
    lu = mass
    call lu_factor(lu, ipiv, status)
    minv_jt = transpose(jac)
    if (status%ok()) call lu_solve(lu, ipiv, minv_jt, status)
    if (.not. status%ok()) then
      call set_status(status, STATUS_DOMAIN, 'the heels'' landing: the rider''s mass matrix is singular there')
      return
    end if
    k = matmul(jac, minv_jt)
    k = (k + transpose(k))/2
    call resolve_impact(law, k, normal, v, outcome, status)
    if (.not. status%ok()) return
    if (.not. outcome%approaching) then
      ! the gap closed, so the heel moved towards the slide: a separating
      ! speed here is a root found on the wrong side, not a landing
      call set_status(status, STATUS_DOMAIN, 'the heels'' landing: they leave the slide (normal speed '// &
                      format_short(outcome%normal_speed_before)//' m/s) where their gap closed')
      return
    end if
    s = s + matmul(minv_jt, outcome%impulse)
    vn = dot_product(normal, outcome%velocity_after)
    if (vn < close_speed) then
      closed = .true.
      closing_impulse = -vn/dot_product(normal, matmul(k, normal))*normal
      closing_energy = vn**2/(2*dot_product(normal, matmul(k, normal)))
      s = s + matmul(minv_jt, closing_impulse)
    end if
    y(n + 1:2*n) = s
    call m%set_velocities(work, s)
    if (closed .and. abs(heels_gap_rate(m, lay)) > 1e-9_wp*max(1.0_wp, abs(outcome%normal_speed_before))) then
      call set_status(status, STATUS_DOMAIN, 'the heels'' landing: the closing left a normal speed of '// &
                      format_short(heels_gap_rate(m, lay))//' m/s')
    end if
  end subroutine heels_impact

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

  !> Adds a landing to the ride's flights (grown by one).
  subroutine add_landing(flights, landing)
    type(ride_flights_t), intent(inout) :: flights
    type(heels_landing_t), intent(in) :: landing
    if (.not. allocated(flights%landing)) allocate (flights%landing(0))
    flights%landing = [flights%landing, landing]
    flights%landings = size(flights%landing)
  end subroutine add_landing
end module rider_heels_flight
