!> The figures of a ride an engineer asks for (docs/rider.md, "Ride report"):
!> ride time, top speed and where, the largest and smallest felt
!> acceleration per body axis and where, how steep and how high each contact
!> rides up the wall, the smallest normal force per contact (the lift-off margin), the
!> largest tipping lever arm, the exit speed, whether (and where) the rider
!> went over the top of a wall, and each user limit's verdict.
!> Computed from a recorded ride (rider_ride) with the pure functions of
!> design_ride_evaluation; "where" is the pelvis's arc length along the
!> slide. The extremes are those the ride located between its records on
!> the integrator's dense output (rider_extremes, docs/accuracy.md); a
!> series without them (not from simulate_ride) gives the records' extremes.
!> The limits judge every recorded sample (outputs and events).
!> With may_fly the felt accelerations and the tipping lever arm (their
!> extremes and limits) are judged on rider_extremes' felt_basis (docs/rider.md
!> "What the felt figures cover"): the model's with the pelvis and another
!> contact on the slide, 0 with the whole rider in the air (a free body),
!> and not judged between (the model holds the pelvis's attitude there).
module design_ride_report
  use base_kinds, only: wp
  use base_constants, only: pi
  use rider_model, only: N_CONTACTS
  use rider_ride, only: ride_series_t
  use rider_flight, only: ride_flights_t
  use rider_extremes, only: felt_basis, FELT_FREE_FALL, FELT_NOT_JUDGED, EXTREME_TOP_SPEED, EXTREME_FELT_MAX, &
    EXTREME_FELT_MIN, EXTREME_CLIMB, EXTREME_NORMAL_MIN, EXTREME_LEVER, EXTREME_WALL_DISTANCE
  use design_ride_evaluation, only: felt_acceleration, felt_acceleration_units, tipping_lever_arm, ride_limit_t, limit_verdict_t, &
    evaluate_limit, series_extreme, noise_free, limit_noise_scale
  implicit none (type, external)
  private
  public :: ride_report_t, evaluate_ride, judge_flights

  type :: ride_report_t
    integer :: n = 0
    real(wp), allocatable :: felt(:, :)          ! 3 x n, g: longitudinal, lateral, normal at the pelvis CoM
    character(len=:), allocatable :: felt_units  ! the unit g of felt in files (felt_acceleration_units)
    real(wp), allocatable :: lever_arm(:)        ! n, m (huge where the pelvis does not press)
    logical, allocatable :: felt_judged(:)       ! n: felt and lever_arm judged at the record (felt_basis)
    real(wp), allocatable :: judged_felt(:, :)   ! 3 x n, g: felt as judged (the model's; 0 in a free fall)
    real(wp) :: not_judged_time = 0              ! s where they are not (may_fly: the pelvis's attitude held)
    real(wp) :: ride_time = 0                    ! s
    real(wp) :: distance = 0                     ! m of arc length from the start to the stop
    real(wp) :: top_speed = 0, top_speed_at = 0  ! m/s, m
    real(wp) :: final_speed = 0                  ! m/s, at the stop (the exit speed if complete)
    logical :: complete = .false.                ! the rider reached the end of the slide
    real(wp) :: felt_max(3) = 0, felt_max_at(3) = 0, felt_min(3) = 0, felt_min_at(3) = 0   ! g, m
    real(wp) :: climb_angle(N_CONTACTS) = 0      ! rad, largest |wall angle| (signed: + towards +v)
    real(wp) :: climb_distance(N_CONTACTS) = 0   ! m along the wall there (signed)
    real(wp) :: climb_at(N_CONTACTS) = 0         ! m, where
    ! the highest climb: the largest |distance along the wall from the bottom|,
    ! not where the angle is largest on a vertical wall or a widening section
    real(wp) :: wall_distance_max(N_CONTACTS) = 0   ! m (signed: + towards +v)
    real(wp) :: wall_distance_at(N_CONTACTS) = 0    ! m, where
    real(wp) :: normal_min(N_CONTACTS) = 0, normal_min_at(N_CONTACTS) = 0   ! N, m
    real(wp) :: lever_max = 0, lever_max_at = 0  ! m (signed, largest |l|), m
    type(ride_limit_t), allocatable :: limits(:)
    type(limit_verdict_t), allocatable :: verdicts(:)
    logical, allocatable :: judged(:)            ! false: not judged (exit speed of a ride that did not exit)
    integer :: ejected_contact = 0               ! the contact that went over a wall's top (0: none)
    real(wp) :: ejected_at = 0                   ! m, where (the pelvis's arc length at the stop)
  end type ride_report_t

contains

  !> `ejected_contact`: the contact that went over the top of a wall and
  !> ended the ride (rider_ride's ride_result_t; absent or 0: none);
  !> `flights`: the heels' flights (may_fly), what airtime (each flight's,
  !> at its take-off) and drop_height (each landing's, where it landed) judge.
  subroutine evaluate_ride(s, gravity, complete, limits, report, ejected_contact, flights)
    type(ride_series_t), intent(in) :: s
    real(wp), intent(in) :: gravity(3)
    logical, intent(in) :: complete
    type(ride_limit_t), intent(in) :: limits(:)
    type(ride_report_t), intent(out) :: report
    integer, intent(in), optional :: ejected_contact
    type(ride_flights_t), intent(in), optional :: flights
    real(wp), allocatable :: where(:), values(:), lever_abs(:)
    integer, allocatable :: basis(:)
    integer :: n, i, k, at
    real(wp) :: force_scale
    n = s%n
    report%n = n
    report%complete = complete
    report%felt_units = felt_acceleration_units(gravity)
    allocate (report%felt(3, n), report%lever_arm(n))
    if (n < 1) return
    where = s%arc_length(:n)
    basis = felt_basis([(0, i = 1, n)])
    if (allocated(s%airborne)) then
      if (size(s%airborne) >= n) basis = felt_basis(s%airborne(:n))
    end if
    report%felt_judged = basis /= FELT_NOT_JUDGED
    report%not_judged_time = sum(s%time(2:n) - s%time(:n - 1), mask=.not. report%felt_judged(:n - 1))
    do i = 1, n
      report%felt(:, i) = felt_acceleration(s%pelvis_acceleration(:, i), gravity, s%pelvis_axes(:, :, i))
      report%lever_arm(i) = tipping_lever_arm(s%reaction_force(:, i), s%reaction_moment(:, i), &
                                              s%pelvis_axes(:, 1, i), s%pelvis_axes(:, 3, i))
    end do
    ! what is judged: the model's, 0 in a free fall, only where judged
    report%judged_felt = report%felt
    do i = 1, n
      if (basis(i) == FELT_FREE_FALL) report%judged_felt(:, i) = 0
    end do
    if (present(ejected_contact)) report%ejected_contact = ejected_contact
    if (report%ejected_contact > 0) report%ejected_at = s%arc_length(n)
    report%ride_time = s%time(n) - s%time(1)
    report%distance = s%arc_length(n) - s%arc_length(1)
    call series_extreme(s%speed(:n), where, .true., report%top_speed, report%top_speed_at)
    report%final_speed = s%speed(n)
    associate (on => report%felt_judged, felt => report%judged_felt)
      do k = 1, 3
        call series_extreme(pack(felt(k, :), on), pack(where, on), .true., report%felt_max(k), report%felt_max_at(k))
        call series_extreme(pack(felt(k, :), on), pack(where, on), .false., report%felt_min(k), report%felt_min_at(k))
      end do
    end associate
    do k = 1, N_CONTACTS
      at = maxloc(abs(s%contact(k)%wall_angle(:n)), dim=1)
      report%climb_angle(k) = s%contact(k)%wall_angle(at)
      report%climb_distance(k) = s%contact(k)%wall_distance(at)
      report%climb_at(k) = where(at)
      at = maxloc(abs(s%contact(k)%wall_distance(:n)), dim=1)
      report%wall_distance_max(k) = s%contact(k)%wall_distance(at)
      report%wall_distance_at(k) = where(at)
      call series_extreme(s%contact(k)%normal_force(:n), where, .false., report%normal_min(k), &
                          report%normal_min_at(k))
    end do
    lever_abs = merge(abs(report%lever_arm), 0.0_wp, abs(report%lever_arm) < huge(1.0_wp) .and. basis /= FELT_FREE_FALL)
    at = maxloc(lever_abs, dim=1, mask=report%felt_judged)
    report%lever_max = report%lever_arm(at)
    if (basis(at) == FELT_FREE_FALL) report%lever_max = 0
    if (.not. abs(report%lever_max) < huge(1.0_wp)) report%lever_max = 0
    report%lever_max_at = where(at)
    if (s%extremes%located .and. s%extremes%records == n) call take_located(s, report)

    report%limits = limits
    ! the scale of the normal forces' noise: the ride's largest (as printed)
    force_scale = max(maxval([(abs(s%contact(k)%normal_force(:n)), k = 1, N_CONTACTS)]), tiny(1.0_wp))
    allocate (report%verdicts(size(limits)), report%judged(size(limits)))
    report%judged = .true.
    do k = 1, size(limits)
      select case (limits(k)%quantity)
      case ('speed')
        values = s%speed(:n)
      case ('exit_speed')
        report%judged(k) = complete
        if (.not. complete) cycle
        call evaluate_limit(limits(k), s%speed(n:n), where(n:n), report%verdicts(k))
        cycle
      case ('acceleration_longitudinal', 'acceleration_lateral', 'acceleration_normal', 'lever_arm')
        ! where judged (felt_basis)
        if (limits(k)%quantity == 'lever_arm') then
          values = pack(lever_abs, report%felt_judged)
        else
          values = pack(report%judged_felt(felt_axis(limits(k)%quantity), :), report%felt_judged)
        end if
        call evaluate_limit(limits(k), noise_free(values, limit_noise_scale(limits(k)%quantity, force_scale)), &
                            pack(where, report%felt_judged), report%verdicts(k))
        cycle
      case ('normal_force')
        values = [(minval([(s%contact(i)%normal_force(at), i = 1, N_CONTACTS)]), at = 1, n)]
      case ('wall_angle')
        values = [(maxval([(abs(s%contact(i)%wall_angle(at)), i = 1, N_CONTACTS)])*180/pi, at = 1, n)]
      case ('wall_distance')
        values = [(maxval([(abs(s%contact(i)%wall_distance(at)), i = 1, N_CONTACTS)]), at = 1, n)]
      case ('ejection')
        call evaluate_limit(limits(k), [merge(1.0_wp, 0.0_wp, report%ejected_contact > 0)], where(n:n), &
                            report%verdicts(k))
        cycle
      case ('airtime', 'drop_height')
        call judge_flights(limits(k), where(1), report%verdicts(k), flights)
        cycle
      case default
        report%judged(k) = .false.
        cycle
      end select
      call evaluate_limit(limits(k), noise_free(values, limit_noise_scale(limits(k)%quantity, force_scale)), where, &
                          report%verdicts(k))
    end do

  contains

    !> The felt acceleration's axis a limit's quantity names.
    pure integer function felt_axis(quantity)
      character(len=*), intent(in) :: quantity
      felt_axis = findloc([character(len=25) :: 'acceleration_longitudinal', 'acceleration_lateral', &
                           'acceleration_normal'], quantity, dim=1)
    end function felt_axis

  end subroutine evaluate_ride

  !> A flights' limit (airtime, drop_height): the longest airtime at its
  !> take-off, each landing's drop height where it landed (none flown, or no
  !> `flights`: 0 at `start`, the start's place). The rider's and a
  !> vehicle's (scenarios_sled).
  subroutine judge_flights(limit, start, verdict, flights)
    type(ride_limit_t), intent(in) :: limit
    real(wp), intent(in) :: start
    type(limit_verdict_t), intent(out) :: verdict
    type(ride_flights_t), intent(in), optional :: flights
    real(wp), allocatable :: v(:), at(:)
    v = [0.0_wp]
    at = [start]
    if (present(flights)) then
      if (limit%quantity == 'airtime' .and. flights%flights > 0) then
        v = [flights%longest]
        at = [flights%longest_arc_length]
      else if (limit%quantity == 'drop_height' .and. flights%landings > 0) then
        v = flights%landing%drop_height
        at = flights%landing%arc_length
      end if
    end if
    call evaluate_limit(limit, v, at, verdict)
  end subroutine judge_flights

  !> The extremes the ride located between its records.
  subroutine take_located(s, report)
    type(ride_series_t), intent(in) :: s
    type(ride_report_t), intent(inout) :: report
    integer :: k
    associate (x => s%extremes)
      report%top_speed = x%value(EXTREME_TOP_SPEED)
      report%top_speed_at = x%at(EXTREME_TOP_SPEED)
      report%felt_max = x%value(EXTREME_FELT_MAX:EXTREME_FELT_MAX + 2)
      report%felt_max_at = x%at(EXTREME_FELT_MAX:EXTREME_FELT_MAX + 2)
      report%felt_min = x%value(EXTREME_FELT_MIN:EXTREME_FELT_MIN + 2)
      report%felt_min_at = x%at(EXTREME_FELT_MIN:EXTREME_FELT_MIN + 2)
      do k = 1, N_CONTACTS
        report%climb_angle(k) = x%value(EXTREME_CLIMB + k - 1)
        report%climb_distance(k) = x%wall_distance(EXTREME_CLIMB + k - 1)
        report%climb_at(k) = x%at(EXTREME_CLIMB + k - 1)
        report%wall_distance_max(k) = x%value(EXTREME_WALL_DISTANCE + k - 1)
        report%wall_distance_at(k) = x%at(EXTREME_WALL_DISTANCE + k - 1)
        report%normal_min(k) = x%value(EXTREME_NORMAL_MIN + k - 1)
        report%normal_min_at(k) = x%at(EXTREME_NORMAL_MIN + k - 1)
      end do
      report%lever_max = x%value(EXTREME_LEVER)
      report%lever_max_at = x%at(EXTREME_LEVER)
    end associate
  end subroutine take_located
end module design_ride_report
