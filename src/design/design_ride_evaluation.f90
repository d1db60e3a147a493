!> What a rider feels and whether it stays within the user's limits: the felt
!> specific force, the tipping lever arm (thesis 4.7, METHOD-PART2 E.3) and
!> limits with units, each judged over a recorded ride with where (arc length)
!> it is worst. Pure functions on plain arrays, so the rider scenario and the
!> design loop (identification, sweeps, optimisation) share them.
!>
!> Felt specific force: f = (a - g)/|g| in a body frame's axes (columns of
!> `axes`), in multiples of the gravity magnitude |g| ("in g"): lying still on
!> level ground it is +1 along the slide normal (pressed onto the slide).
!> Its unit in files (felt_acceleration_units) names that |g|: 'gravity'
!> (standard gravity, 9.80665 m/s^2, to UDUNITS-2 and pint alike; pint does
!> not know UDUNITS-2's 'standard_free_fall') or the run's |g| as
!> '9.81 m/s^2'.
!>
!> Tipping lever arm (E.3): l = (M_r . e_long)/(F_r . n), the slide's reaction
!> moment about the body's long axis over the reaction's normal component, at
!> the contact's Darboux frame; the body would tip when |l| exceeds half its
!> width. A reaction that does not press (F_r . n <= 0) has no lever arm:
!> huge() is returned (the contact lifts off, which the rider reports itself).
!>
!> Limits: a quantity (limit_quantities), a minimum and/or a maximum, and the
!> unit they are given in. Values are converted to the quantity's report unit
!> (limit_report_units): speeds m/s, felt accelerations g, lengths m, forces N,
!> angles degrees. A unit of the wrong kind is refused with the list of units
!> the quantity accepts.
!>
!> Rounding noise (noise_free): a figure whose size is below
!> report_noise_floor times its quantity's scale is not a finding; the
!> report prints it as 0 and names no direction for it.
module design_ride_evaluation
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_text, only: format_short, format_real, lower
  use rider_extremes, only: felt_acceleration, tipping_lever_arm   ! re-exported: the formulas live with the ride
  implicit none (type, external)
  private
  public :: felt_acceleration, felt_acceleration_units, tipping_lever_arm
  public :: ride_limit_t, limit_verdict_t, new_ride_limit, evaluate_limit, limit_quantities, &
    limit_report_unit, limit_bounds_text, spaced_unit, &
    limit_stored_unit, limit_units_allowed, series_extreme, quantities_without_limit, flight_quantity, &
    noise_free, report_noise_floor, limit_noise_scale, rider_size

  !> The size, relative to its quantity's scale, below which a report's
  !> figure is rounding noise. The ride is integrated to rtol 1e-10 and its
  !> closure solved to 1e-10 m on a rider ~1 m long, so no figure derived
  !> from its states (felt g, forces, lever arms) is resolved much below
  !> 1e-10 of its scale; rounding itself leaves 1e-16..1e-12 (jump.nml: a
  !> lateral felt 3e-16 g on a straight path, a lever arm -4e-17 m, the
  !> flying pelvis's normal force -7e-10 N of ~700 N). Ten times the
  !> solvers' tolerance sits above all of that and far below any figure an
  !> engineer reads (printed to 3-4 digits, limits of 0.1 g, 0.1 m, 1 N).
  real(wp), parameter :: report_noise_floor = 1e-9_wp
  !> m: the rider's size (legs ~0.9 m, trunk ~0.6 m), the scale of its lever
  !> arm and of how far it climbs a wall
  real(wp), parameter :: rider_size = 1

  !> ejection counts the rider's points that went over the top of an open
  !> section's wall (0 or 1: the ride ends there); `limit_max = 0` forbids it.
  !> airtime (each flight of the heels) and drop_height (each landing's
  !> v_n^2/(2 g)) need may_fly (the last n_flight_quantities).
  character(len=*), parameter :: limit_quantities(12) = [character(len=25) :: 'speed', 'exit_speed', &
    'acceleration_longitudinal', 'acceleration_lateral', 'acceleration_normal', 'lever_arm', &
    'normal_force', 'wall_angle', 'wall_distance', 'ejection', 'airtime', 'drop_height']
  integer, parameter :: n_flight_quantities = 2

  integer, parameter :: DIM_SPEED = 1, DIM_ACCELERATION = 2, DIM_LENGTH = 3, DIM_FORCE = 4, DIM_ANGLE = 5, &
    DIM_COUNT = 6, DIM_TIME = 7
  integer, parameter :: quantity_dimension(12) = [DIM_SPEED, DIM_SPEED, DIM_ACCELERATION, DIM_ACCELERATION, &
    DIM_ACCELERATION, DIM_LENGTH, DIM_FORCE, DIM_ANGLE, DIM_LENGTH, DIM_COUNT, DIM_TIME, DIM_LENGTH]
  character(len=*), parameter :: report_units(7) = [character(len=3) :: 'm/s', 'g', 'm', 'N', 'deg', '1', 's']
  character(len=*), parameter :: units_allowed(7) = [character(len=48) :: &
    "'m s-1', 'm/s', 'km h-1', 'km/h'", &
    "'g' (multiples of |gravity|), 'm s-2', 'm/s^2'", &
    "'m', 'cm', 'mm'", &
    "'N', 'kN'", &
    "'deg', 'degree', 'rad'", &
    "'1' (a count)", &
    "'s', 'ms'"]

  !> One limit, in the quantity's report unit.
  type :: ride_limit_t
    character(len=:), allocatable :: quantity
    logical :: has_minimum = .false., has_maximum = .false.
    real(wp) :: minimum = -huge(1.0_wp), maximum = huge(1.0_wp)   ! report unit
    character(len=:), allocatable :: unit                        ! as the user gave it
    real(wp) :: given_minimum = 0, given_maximum = 0             ! in the user's unit
  end type ride_limit_t

  type :: limit_verdict_t
    logical :: exceeded = .false.
    real(wp) :: worst = 0             ! report unit: the value furthest beyond (or nearest to) the limit
    real(wp) :: worst_where = 0       ! m of arc length
    real(wp) :: first_where = -1      ! m of arc length where first exceeded (-1: never)
    real(wp) :: excess = 0            ! report unit, > 0 when exceeded
  end type limit_verdict_t

contains

  !> value, or 0 where |value| is below report_noise_floor*scale (scale > 0:
  !> the quantity's scale, in value's unit).
  elemental real(wp) function noise_free(value, scale)
    real(wp), intent(in) :: value, scale
    noise_free = merge(0.0_wp, value, abs(value) < report_noise_floor*scale)
  end function noise_free

  !> The scale, in the report unit of a limit's quantity, below
  !> report_noise_floor of which its value is rounding noise (0: none, the
  !> value is judged as it is): felt accelerations 1 g, lever arm and wall
  !> distance the rider's size, wall angle 1 rad, normal force
  !> `force_scale` (the ride's largest). A verdict judges the values as the
  !> report prints them, so that noise on either side of a bound (a flying
  !> pelvis's -7e-10 N against normal_force >= 0) neither exceeds it nor
  !> prints a worst of 0 beside "LIMIT EXCEEDED".
  pure real(wp) function limit_noise_scale(quantity, force_scale) result(scale)
    character(len=*), intent(in) :: quantity
    real(wp), intent(in) :: force_scale
    select case (quantity)
    case ('acceleration_longitudinal', 'acceleration_lateral', 'acceleration_normal')
      scale = 1
    case ('lever_arm', 'wall_distance')
      scale = rider_size
    case ('normal_force')
      scale = force_scale
    case ('wall_angle')
      scale = 180/pi   ! 1 rad in deg
    case default
      scale = 0
    end select
  end function limit_noise_scale

  !> The unit of felt accelerations (multiples of |gravity|) as UDUNITS-2 and
  !> pint read it: 'gravity' when |gravity| is standard gravity (to a few
  !> ulps: the norm of a tilted standard-gravity vector), else |gravity| in
  !> m/s^2 ('9.81 m/s^2', the shortest digits that read back).
  pure function felt_acceleration_units(gravity) result(units)
    real(wp), intent(in) :: gravity(3)   ! m/s^2
    character(len=:), allocatable :: units
    real(wp) :: magnitude
    magnitude = norm2(gravity)
    if (abs(magnitude - standard_gravity) <= 8*epsilon(1.0_wp)*standard_gravity) then
      units = 'gravity'
    else
      units = format_real(magnitude)//' m/s^2'
    end if
  end function felt_acceleration_units

  pure integer function quantity_index(quantity) result(k)
    character(len=*), intent(in) :: quantity
    do k = 1, size(limit_quantities)
      if (trim(limit_quantities(k)) == lower(trim(adjustl(quantity)))) return
    end do
    k = 0
  end function quantity_index

  pure function limit_report_unit(quantity) result(unit)
    character(len=*), intent(in) :: quantity
    character(len=:), allocatable :: unit
    unit = dimension_entry(quantity, report_units)
  end function limit_report_unit

  !> The entry of `table` (one per dimension) for limit `quantity`'s
  !> dimension; '' for an unknown quantity.
  pure function dimension_entry(quantity, table) result(text)
    character(len=*), intent(in) :: quantity, table(:)
    character(len=:), allocatable :: text
    integer :: k
    k = quantity_index(quantity)
    text = ''
    if (k > 0) text = trim(table(quantity_dimension(k)))
  end function dimension_entry

  !> A limit's bounds as the reports print them: '>= 2 m/s and <= 14 m/s'.
  pure function limit_bounds_text(limit) result(text)
    type(ride_limit_t), intent(in) :: limit
    character(len=:), allocatable :: text
    text = ''
    if (limit%has_minimum) text = '>= '//format_short(limit%minimum)//spaced_unit(limit_report_unit(limit%quantity))
    if (limit%has_minimum .and. limit%has_maximum) text = text//' and '
    if (limit%has_maximum) text = text//'<= '//format_short(limit%maximum)//spaced_unit(limit_report_unit(limit%quantity))
  end function limit_bounds_text

  !> ' unit' after a number; nothing for a count (unit '1').
  pure function spaced_unit(unit) result(text)
    character(len=*), intent(in) :: unit
    character(len=:), allocatable :: text
    text = ''
    if (unit /= '1') text = ' '//unit
  end function spaced_unit

  !> The unit a result file gives limit `quantity`'s values in: its report
  !> unit, but degrees as 'degree' (pint and UDUNITS parse it) and multiples
  !> of |g| in `felt_units` (felt_acceleration_units).
  pure function limit_stored_unit(quantity, felt_units) result(text)
    character(len=*), intent(in) :: quantity, felt_units
    character(len=:), allocatable :: text
    text = limit_report_unit(quantity)
    select case (text)
    case ('g'); text = felt_units
    case ('deg'); text = 'degree'
    end select
  end function limit_stored_unit

  pure function limit_units_allowed(quantity) result(text)
    character(len=*), intent(in) :: quantity
    character(len=:), allocatable :: text
    text = dimension_entry(quantity, units_allowed)
  end function limit_units_allowed

  !> Factor from `unit` to the report unit of dimension `dim`; 0 if the unit
  !> does not measure that dimension. `gravity_magnitude` (m/s^2) defines 'g'.
  pure real(wp) function unit_factor(dim, unit, gravity_magnitude) result(f)
    integer, intent(in) :: dim
    character(len=*), intent(in) :: unit
    real(wp), intent(in) :: gravity_magnitude
    character(len=:), allocatable :: u
    u = trim(adjustl(unit))
    f = 0
    select case (dim)
    case (DIM_SPEED)
      select case (u)
      case ('m s-1', 'm/s'); f = 1
      case ('km h-1', 'km/h'); f = 1/3.6_wp
      end select
    case (DIM_ACCELERATION)
      select case (u)
      case ('g'); f = 1
      case ('m s-2', 'm/s^2', 'm/s2'); f = 1/gravity_magnitude
      end select
    case (DIM_LENGTH)
      select case (u)
      case ('m'); f = 1
      case ('cm'); f = 0.01_wp
      case ('mm'); f = 0.001_wp
      end select
    case (DIM_FORCE)
      select case (u)
      case ('N'); f = 1
      case ('kN'); f = 1000
      end select
    case (DIM_ANGLE)
      select case (u)
      case ('deg', 'degree', 'degrees'); f = 1
      case ('rad'); f = 180/pi
      end select
    case (DIM_COUNT)
      if (u == '1') f = 1
    case (DIM_TIME)
      select case (u)
      case ('s'); f = 1
      case ('ms'); f = 0.001_wp
      end select
    end select
  end function unit_factor

  !> A limit from what the user gave; `problem` is empty when it is valid,
  !> else says what is wrong (unknown quantity, unit of the wrong kind, no
  !> bound, minimum above maximum).
  pure subroutine new_ride_limit(quantity, unit, minimum, has_minimum, maximum, has_maximum, &
                                 gravity_magnitude, limit, problem)
    character(len=*), intent(in) :: quantity, unit
    real(wp), intent(in) :: minimum, maximum, gravity_magnitude
    logical, intent(in) :: has_minimum, has_maximum
    type(ride_limit_t), intent(out) :: limit
    character(len=:), allocatable, intent(out) :: problem
    integer :: k
    real(wp) :: f
    problem = ''
    k = quantity_index(quantity)
    if (k == 0) then
      problem = 'unknown quantity '''//trim(quantity)//'''; known are: '//quantity_list()
      return
    end if
    f = unit_factor(quantity_dimension(k), unit, gravity_magnitude)
    if (f == 0) then
      problem = 'unit '''//trim(unit)//''' does not measure '//trim(limit_quantities(k))//'; use '// &
                trim(units_allowed(quantity_dimension(k)))
      return
    end if
    if (.not. (has_minimum .or. has_maximum)) then
      problem = trim(limit_quantities(k))//' has neither a minimum nor a maximum'
      return
    end if
    limit%quantity = trim(limit_quantities(k))
    limit%unit = trim(adjustl(unit))
    limit%has_minimum = has_minimum
    limit%has_maximum = has_maximum
    if (has_minimum) then
      limit%given_minimum = minimum
      limit%minimum = minimum*f
    end if
    if (has_maximum) then
      limit%given_maximum = maximum
      limit%maximum = maximum*f
    end if
    if (has_minimum .and. has_maximum .and. .not. limit%minimum <= limit%maximum) &
      problem = trim(limit_quantities(k))//': the minimum '//format_short(minimum)//' lies above the maximum '// &
                format_short(maximum)
  end subroutine new_ride_limit

  !> The quantities that none of `limits` judges, as a list ('' when all are
  !> limited): a report says what it did not check; the flights' (airtime,
  !> drop_height) only for a ride that may fly.
  pure function quantities_without_limit(limits, may_fly) result(text)
    type(ride_limit_t), intent(in) :: limits(:)
    logical, intent(in), optional :: may_fly
    character(len=:), allocatable :: text
    integer :: k, i, last
    text = ''
    last = size(limit_quantities) - n_flight_quantities
    if (present(may_fly)) then
      if (may_fly) last = size(limit_quantities)
    end if
    do k = 1, last
      if (any([(limits(i)%quantity == trim(limit_quantities(k)), i = 1, size(limits))])) cycle
      if (len(text) > 0) text = text//', '
      text = text//trim(limit_quantities(k))
    end do
  end function quantities_without_limit

  !> Whether `quantity` is one of the flights' (it needs may_fly).
  pure logical function flight_quantity(quantity)
    character(len=*), intent(in) :: quantity
    flight_quantity = quantity_index(quantity) > size(limit_quantities) - n_flight_quantities
  end function flight_quantity

  pure function quantity_list() result(text)
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, size(limit_quantities)
      if (k > 1) text = text//', '
      text = text//trim(limit_quantities(k))
    end do
  end function quantity_list

  !> Judges `values` (report unit) recorded at arc lengths `where` against
  !> the limit. When nothing exceeds, worst is the value closest to a bound.
  pure subroutine evaluate_limit(limit, values, where, verdict)
    type(ride_limit_t), intent(in) :: limit
    real(wp), intent(in) :: values(:), where(:)
    type(limit_verdict_t), intent(out) :: verdict
    real(wp) :: margin, best
    integer :: i
    best = huge(1.0_wp)
    do i = 1, size(values)
      margin = huge(1.0_wp)
      if (limit%has_maximum) margin = min(margin, limit%maximum - values(i))
      if (limit%has_minimum) margin = min(margin, values(i) - limit%minimum)
      if (margin < best) then
        best = margin
        verdict%worst = values(i)
        verdict%worst_where = where(i)
      end if
      if (margin < 0 .and. verdict%first_where < 0) verdict%first_where = where(i)
    end do
    verdict%exceeded = best < 0
    if (verdict%exceeded) verdict%excess = -best
  end subroutine evaluate_limit

  !> The largest (or smallest) of `values` and the arc length where.
  pure subroutine series_extreme(values, where, largest, value, at)
    real(wp), intent(in) :: values(:), where(:)
    logical, intent(in) :: largest
    real(wp), intent(out) :: value, at
    integer :: i
    if (size(values) == 0) then
      value = 0
      at = 0
      return
    end if
    if (largest) then
      i = maxloc(values, dim=1)
    else
      i = minloc(values, dim=1)
    end if
    value = values(i)
    at = where(i)
  end subroutine series_extreme
end module design_ride_evaluation
