!> The ride report's extremes (docs/rider.md, "Ride report"), as the ride
!> locates them between its records on the integrator's dense output
!> (numerics_dense_extremes, docs/accuracy.md): the top speed, the largest
!> and smallest felt acceleration per body axis, the largest |wall angle| of
!> each contact (the steepest it rides), the largest |distance along the
!> wall| of each contact (the highest it climbs: on a flume's vertical wall
!> or a widening section not where the angle is largest), the smallest
!> normal force of each contact, the largest
!> |tipping lever arm| and, with may_fly, each open contact's highest gap
!> above the slide (the flight's highest point: on dense output, so where
!> the records fall does not limit it; docs/accuracy.md measures what the
!> output step still moves), each with where (the pelvis's arc
!> length; for a gap its contact's foot point's) and when.
!>
!> Also the two formulas of what a rider feels that they are made of (the
!> design layer's ride evaluation uses them too):
!> felt specific force f = (a - g)/|g| in a body frame's axes (in g), and
!> the tipping lever arm l = (M_r . e_long)/(F_r . n) (thesis E.3), huge()
!> where the reaction does not press (F_r . n <= 0).
!>
!> With may_fly, what the report takes as felt depends on the open contacts
!> (`felt_basis`; docs/rider.md "What the felt figures cover"): the
!> model's felt acceleration and lever arm while the pelvis and at least one
!> more contact are on the slide; 0 g and no lever arm while the whole rider
!> is in the air (a free body feels nothing; air drag is not modelled); and
!> nothing (not judged) while the pelvis is open with another contact on, or
!> on the slide alone: there the model holds the pelvis's attitude (the
!> couple in the air, the flat seat's moments at no load), forces a free
!> rider does not feel (jump.nml's 2.7 g braking and -0.96 g normal).
module rider_extremes
  use base_kinds, only: wp
  use rider_model, only: N_CONTACTS, CONTACT_PELVIS
  implicit none (type, external)
  private
  public :: felt_acceleration, tipping_lever_arm, ride_extremes_t, extreme_quantities, felt_basis
  public :: FELT_MODEL, FELT_FREE_FALL, FELT_NOT_JUDGED
  public :: N_EXTREMES, N_ATTACHED, EXTREME_TOP_SPEED, EXTREME_FELT_MAX, EXTREME_FELT_MIN, EXTREME_CLIMB, &
    EXTREME_NORMAL_MIN, EXTREME_LEVER, EXTREME_GAP, EXTREME_WALL_DISTANCE

  !> the quantities (first of three for per-axis and per-contact ones)
  integer, parameter :: EXTREME_TOP_SPEED = 1, EXTREME_FELT_MAX = 2, EXTREME_FELT_MIN = 5, &
    EXTREME_CLIMB = 8, EXTREME_NORMAL_MIN = 11, EXTREME_LEVER = 14, EXTREME_GAP = 15, &
    EXTREME_WALL_DISTANCE = 18, N_EXTREMES = 20
  !> numbers kept with each: the reported value (signed), the arc length, the wall distance
  integer, parameter :: N_ATTACHED = 3

  !> felt_basis: the model's values count, a free fall (0 g), not judged
  integer, parameter :: FELT_MODEL = 1, FELT_FREE_FALL = 2, FELT_NOT_JUDGED = 3

  !> The located extremes of a ride, in report units (m/s, g, rad, N, m).
  type :: ride_extremes_t
    logical :: located = .false.          ! the ride located them (else: take them from the records)
    integer :: records = 0                ! records they were located among
    real(wp) :: value(N_EXTREMES) = 0     ! speed, felt (3 max, 3 min), wall angle, normal force, lever arm, gap,
                                          ! wall distance
    real(wp) :: at(N_EXTREMES) = 0        ! m, the pelvis's arc length there (a gap: its contact's)
    real(wp) :: time(N_EXTREMES) = 0      ! s
    real(wp) :: wall_distance(N_EXTREMES) = 0   ! m, along the wall there (for the wall angles and distances)
    integer :: searches = 0, evaluations = 0    ! brackets searched, model evaluations for them
  end type ride_extremes_t

contains

  !> What the felt acceleration and the lever arm are with the contacts
  !> `airborne` open (bit k-1 for contact k): the model's (FELT_MODEL) with
  !> the pelvis and at least one more contact on the slide, 0 (FELT_FREE_FALL)
  !> with every contact open, else not judged (FELT_NOT_JUDGED).
  elemental integer function felt_basis(airborne)
    integer, intent(in) :: airborne
    logical :: on(N_CONTACTS)
    integer :: k
    on = [(.not. btest(airborne, k - 1), k = 1, N_CONTACTS)]
    if (.not. any(on)) then
      felt_basis = FELT_FREE_FALL
    else if (on(CONTACT_PELVIS) .and. count(on) >= 2) then
      felt_basis = FELT_MODEL
    else
      felt_basis = FELT_NOT_JUDGED
    end if
  end function felt_basis

  !> (a - g)/|g| in the axes (columns) of a frame.
  pure function felt_acceleration(a, gravity, axes) result(f)
    real(wp), intent(in) :: a(3), gravity(3), axes(3, 3)
    real(wp) :: f(3)
    f = matmul(a - gravity, axes)/norm2(gravity)
  end function felt_acceleration

  !> l = (M_r . e_long)/(F_r . n) (E.3), huge() if F_r . n <= 0.
  pure real(wp) function tipping_lever_arm(reaction_force, reaction_moment, long_axis, normal) result(l)
    real(wp), intent(in) :: reaction_force(3), reaction_moment(3), long_axis(3), normal(3)
    real(wp) :: pressing
    pressing = dot_product(reaction_force, normal)
    if (pressing > 0) then
      l = dot_product(reaction_moment, long_axis)/pressing
    else
      l = huge(1.0_wp)
    end if
  end function tipping_lever_arm

  !> The quantities of one state as values to maximise (minima negated,
  !> |wall angle|, |wall distance|, |lever arm| or 0 where the pelvis does not press) and
  !> their attached numbers, with the contacts `airborne` open: the felt
  !> acceleration and the lever arm on felt_basis (0 in a free fall; -huge,
  !> never a maximum, where not judged); the open contacts' gaps (m, above
  !> the slide, at their foot points' arc lengths gap_arc_length; a closed
  !> contact's: -huge).
  pure subroutine extreme_quantities(speed, acceleration, axes, reaction_force, reaction_moment, arc_length, &
                                     wall_angle, wall_distance, normal_force, gravity, airborne, gap, gap_arc_length, &
                                     values, attached)
    real(wp), intent(in) :: speed, acceleration(3), axes(3, 3), reaction_force(3), reaction_moment(3), arc_length
    real(wp), intent(in) :: wall_angle(N_CONTACTS), wall_distance(N_CONTACTS), normal_force(N_CONTACTS), gravity(3)
    integer, intent(in) :: airborne
    real(wp), intent(in) :: gap(N_CONTACTS), gap_arc_length(N_CONTACTS)
    real(wp), intent(out) :: values(N_EXTREMES), attached(N_ATTACHED, N_EXTREMES)
    real(wp) :: felt(3), lever
    integer :: k
    attached = 0
    attached(2, :) = arc_length
    values(EXTREME_TOP_SPEED) = speed
    attached(1, EXTREME_TOP_SPEED) = speed
    felt = felt_acceleration(acceleration, gravity, axes)
    if (felt_basis(airborne) == FELT_FREE_FALL) felt = 0
    do k = 1, 3
      values(EXTREME_FELT_MAX + k - 1) = felt(k)
      attached(1, EXTREME_FELT_MAX + k - 1) = felt(k)
      values(EXTREME_FELT_MIN + k - 1) = -felt(k)
      attached(1, EXTREME_FELT_MIN + k - 1) = felt(k)
    end do
    do k = 1, N_CONTACTS
      values(EXTREME_CLIMB + k - 1) = abs(wall_angle(k))
      attached(1, EXTREME_CLIMB + k - 1) = wall_angle(k)
      attached(3, EXTREME_CLIMB + k - 1) = wall_distance(k)
      values(EXTREME_WALL_DISTANCE + k - 1) = abs(wall_distance(k))
      attached(1, EXTREME_WALL_DISTANCE + k - 1) = wall_distance(k)
      attached(3, EXTREME_WALL_DISTANCE + k - 1) = wall_distance(k)
      ! an open contact carries nothing: 0, not the closure's noise (which
      ! the extremes would search as candidates for the minimum)
      values(EXTREME_NORMAL_MIN + k - 1) = merge(0.0_wp, -normal_force(k), btest(airborne, k - 1))
      attached(1, EXTREME_NORMAL_MIN + k - 1) = merge(0.0_wp, normal_force(k), btest(airborne, k - 1))
      values(EXTREME_GAP + k - 1) = merge(gap(k), -huge(1.0_wp), btest(airborne, k - 1))
      attached(1, EXTREME_GAP + k - 1) = values(EXTREME_GAP + k - 1)
      attached(2, EXTREME_GAP + k - 1) = gap_arc_length(k)
    end do
    lever = tipping_lever_arm(reaction_force, reaction_moment, axes(:, 1), axes(:, 3))
    if (.not. abs(lever) < huge(1.0_wp) .or. felt_basis(airborne) == FELT_FREE_FALL) lever = 0
    values(EXTREME_LEVER) = abs(lever)
    attached(1, EXTREME_LEVER) = lever
    if (felt_basis(airborne) == FELT_NOT_JUDGED) then
      values(EXTREME_FELT_MAX:EXTREME_FELT_MIN + 2) = -huge(1.0_wp)
      values(EXTREME_LEVER) = -huge(1.0_wp)
    end if
  end subroutine extreme_quantities
end module rider_extremes
