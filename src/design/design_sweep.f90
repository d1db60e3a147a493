!> Populations of rides (docs/sweep.md): many rides that differ in the rider
!> (body table, mass, height, friction), the start (position, heading,
!> speed) and the water (flow rate, friction f1, f2, f3), each run and
!> judged by the library's ride (design_ride_job's run_ride, the `ride`
!> scenario's), in OpenMP threads.
!>
!> The water is computed once per distinct water (flow rate and friction
!> equal to the bit): rides are grouped by their water. A ride that cannot
!> start, or whose integration fails, is recorded as failed with its message;
!> the others run on. Every ride is computed by the same code from the same
!> inputs whatever thread (or MPI rank, design_sweep_ranks) runs it, so the
!> results do not depend on how the rides are shared out (only the CPU times
!> do).
module design_sweep
  use base_kinds, only: wp, int64
  use base_constants, only: pi
  use base_text, only: format_integer
  use base_status, only: status_t
  use base_log, only: log_sink_i
  use rider_body, only: SEX_MALE, SEX_FEMALE
  use rider_model, only: rider_params_t, N_CONTACTS, set_rider_mu
  use rider_ride, only: ride_options_t, ride_result_t
  use water_run, only: water_description_t, water_result_t, compute_water
  use design_ride_evaluation, only: ride_limit_t, felt_acceleration_units
  use design_ride_report, only: ride_report_t
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  !$ use omp_lib, only: omp_get_max_threads
  implicit none (type, external)
  private
  public :: sweep_description_t, sweep_result_t, run_sweep, water_groups, ride_description, new_sweep_result, &
    rides_of_rank, swept_values_t, sweep_row_count, sweep_rows, range_values
  public :: N_SWEPT, swept_names, swept_units, swept_descriptions, V_SEX, V_MASS, V_HEIGHT, V_MU, V_U0, V_V0, &
    V_HEADING, V_SPEED, V_FLOW_RATE, V_F1, V_F2, V_F3
  public :: N_FIGURES, figure_names, figure_unit, figure_descriptions, F_FELT_MAGNITUDE_MAX
  public :: RIDE_NOT_RUN, RIDE_COMPLETE, RIDE_STOPPED, RIDE_FAILED, ride_status_names, message_length

  ! ---- what varies from ride to ride (a column of sweep_description_t%values)
  integer, parameter :: N_SWEPT = 12
  integer, parameter :: V_SEX = 1, V_MASS = 2, V_HEIGHT = 3, V_MU = 4, V_U0 = 5, V_V0 = 6, V_HEADING = 7, &
    V_SPEED = 8, V_FLOW_RATE = 9, V_F1 = 10, V_F2 = 11, V_F3 = 12
  character(len=*), parameter :: swept_names(N_SWEPT) = [character(len=12) :: 'sex', 'mass', 'height', 'mu', &
    'u0', 'v0', 'heading0_deg', 'speed0', 'flow_rate', 'f1', 'f2', 'f3']
  character(len=*), parameter :: swept_units(N_SWEPT) = [character(len=8) :: '1', 'kg', 'm', '1', 'm', 'rad', &
    'degree', 'm/s', 'm^3/s', 'kg/m', 'kg', 'kg m']
  character(len=*), parameter :: swept_descriptions(N_SWEPT) = [character(len=72) :: &
    'body table of de Leva: 1 male, 2 female', 'rider mass', 'rider height', &
    'Coulomb friction of the rider at the three contacts', 'pelvis start along the slide (surface u)', &
    'pelvis start across the slide (pi/2: the bottom)', 'start heading: body axis from down the slide', &
    'start speed along the body axis', 'water inflow', 'water friction f1 (4.7)', 'water friction f2 (4.7)', &
    'water friction f3 (4.7)']

  ! ---- the report figures of every ride (design_ride_report)
  integer, parameter :: N_FIGURES = 35
  integer, parameter :: F_FELT_MAGNITUDE_MAX = 18
  character(len=*), parameter :: figure_names(N_FIGURES) = [character(len=40) :: &
    'ride_time', 'distance', 'top_speed', 'top_speed_arc_length', 'final_speed', &
    'felt_longitudinal_max', 'felt_longitudinal_max_arc_length', 'felt_longitudinal_min', &
    'felt_longitudinal_min_arc_length', 'felt_lateral_max', 'felt_lateral_max_arc_length', 'felt_lateral_min', &
    'felt_lateral_min_arc_length', 'felt_normal_max', 'felt_normal_max_arc_length', 'felt_normal_min', &
    'felt_normal_min_arc_length', 'felt_magnitude_max', 'felt_magnitude_max_arc_length', &
    'lever_arm_max', 'lever_arm_max_arc_length', &
    'pelvis_wall_angle_max', 'pelvis_wall_distance_max', 'pelvis_wall_arc_length', &
    'heels_wall_angle_max', 'heels_wall_distance_max', 'heels_wall_arc_length', &
    'back_wall_angle_max', 'back_wall_distance_max', 'back_wall_arc_length', &
    'pelvis_normal_force_min', 'heels_normal_force_min', 'back_normal_force_min', &
    'drag_switches', 'steps']
  !> 'g': multiples of |gravity|, in the file felt_acceleration_units (figure_unit)
  character(len=*), parameter :: figure_units(N_FIGURES) = [character(len=4) :: 's', 'm', 'm/s', 'm', 'm/s', &
    'g', 'm', 'g', 'm', 'g', 'm', 'g', 'm', 'g', 'm', 'g', 'm', 'g', 'm', 'm', 'm', &
    'rad', 'm', 'm', 'rad', 'm', 'm', 'rad', 'm', 'm', 'N', 'N', 'N', '1', '1']
  character(len=*), parameter :: figure_descriptions(N_FIGURES) = [character(len=90) :: &
    'time from the start to the stop', 'arc length covered by the pelvis', 'largest speed', &
    'where (pelvis arc length)', 'speed at the stop (the exit speed when complete)', &
    'largest felt acceleration along the pelvis axis to the feet, multiples of |g|', 'where', &
    'smallest felt acceleration along the pelvis axis to the feet, multiples of |g|', 'where', &
    'largest felt lateral acceleration (to the left), multiples of |g|', 'where', &
    'smallest felt lateral acceleration (to the left), multiples of |g|', 'where', &
    'largest felt normal acceleration (pressed onto the slide), multiples of |g|', 'where', &
    'smallest felt normal acceleration (pressed onto the slide), multiples of |g|', 'where', &
    'largest magnitude of the felt acceleration (a - g)/|g|', 'where', &
    'largest tipping lever arm at the pelvis (signed)', 'where', &
    'steepest on the wall: the pelvis''s largest angle from the bottom (+ to the left)', &
    'highest on the wall: the pelvis''s largest distance along the wall from the bottom', &
    'where the angle is largest (pelvis arc length)', &
    'the heels'' largest angle from the bottom', 'the heels'' largest distance along the wall', &
    'where the angle is largest', &
    'the back''s largest angle from the bottom', 'the back''s largest distance along the wall', &
    'where the angle is largest', &
    'smallest normal force at the pelvis (lift-off margin)', 'smallest normal force at the heels', &
    'smallest normal force at the back', 'times a contact entered or left the water', 'integrator steps']

  integer, parameter :: RIDE_NOT_RUN = 0, RIDE_COMPLETE = 1, RIDE_STOPPED = 2, RIDE_FAILED = 3
  character(len=*), parameter :: ride_status_names(0:3) = [character(len=8) :: 'not run', 'complete', 'stopped', &
    'failed']
  !> characters kept of each ride's message (fixed, so ranks can send them)
  integer, parameter :: message_length = 240

  !> A population of rides: the base ride (water, rider, options, limits)
  !> and the values of every ride that differ from it.
  type :: sweep_description_t
    type(water_description_t) :: water                 !< the base water: flow rate and f1..f3 from each ride
    type(rider_params_t) :: rider                      !< the base rider: the swept values from each ride
    type(ride_options_t) :: options
    type(ride_limit_t), allocatable :: limits(:)
    real(wp), allocatable :: values(:, :)              !< N_SWEPT x rides (heading in degrees, sex 1 or 2)
  end type sweep_description_t

  !> The values one swept variable takes (a list, or a range's values).
  type :: swept_values_t
    real(wp), allocatable :: x(:)
  end type swept_values_t

  !> Every ride's outcome and figures (columns: rides); limits x rides for
  !> the verdicts. Figures are 0 where a ride failed.
  type :: sweep_result_t
    integer :: n = 0
    integer, allocatable :: status(:)                         !< RIDE_*
    character(len=message_length), allocatable :: message(:)  !< how it ended, or why it failed
    real(wp), allocatable :: figures(:, :)                    !< N_FIGURES x n
    integer, allocatable :: verdict(:, :)                     !< 1 exceeded, 0 ok, -1 not judged or failed
    real(wp), allocatable :: worst(:, :), excess(:, :)        !< report unit of the limit
    real(wp), allocatable :: seconds(:)                       !< s of wall clock per ride (in its thread; the one
                                                              !< result that varies from run to run)
    integer, allocatable :: water_group(:)                    !< which water (water_groups) the ride used
    real(wp), allocatable :: water_seconds(:)                 !< s of wall clock per water group
  end type sweep_result_t

contains

  !> The values of a swept range (`NAME_range = first, last, count`): count
  !> values evenly from first to last, both ends exactly as written.
  pure function range_values(first, last, count) result(x)
    real(wp), intent(in) :: first, last
    integer, intent(in) :: count
    real(wp) :: x(count)
    integer :: i
    x = [(first + (last - first)*real(i - 1, wp)/(count - 1), i=1, count)]
    x(count) = last
  end function range_values

  !> How many rides sweep_rows makes of `lists` (a real: the product can
  !> overflow an integer): the product of the crossed variables' counts, the
  !> paired ones (`together`, each as many values) one axis.
  pure real(wp) function sweep_row_count(lists, together) result(rides)
    type(swept_values_t), intent(in) :: lists(N_SWEPT)
    logical, intent(in) :: together(N_SWEPT)
    integer :: k
    rides = 1
    do k = 1, N_SWEPT
      if (together(k) .and. k /= findloc(together, .true., dim=1)) cycle
      rides = rides*size(lists(k)%x)
    end do
  end function sweep_row_count

  !> The rides of a sweep (docs/sweep.md, "Input"; N_SWEPT x rides, the
  !> values of sweep_description_t): every variable's list (one value: not
  !> swept) crossed with the others, every combination, the first variable of
  !> swept_names varying slowest, the last fastest; the variables `together`
  !> (paired: each as many values) vary together, element by element, as one
  !> axis in the place of the first of them.
  pure function sweep_rows(lists, together) result(values)
    type(swept_values_t), intent(in) :: lists(N_SWEPT)
    logical, intent(in) :: together(N_SWEPT)
    real(wp), allocatable :: values(:, :)
    integer :: axes(N_SWEPT), sizes(N_SWEPT), index(N_SWEPT), n_axes, a, i, j, k, first_together
    allocate (values(N_SWEPT, nint(sweep_row_count(lists, together))))
    first_together = findloc(together, .true., dim=1)
    n_axes = 0
    do k = 1, N_SWEPT
      if (together(k) .and. k /= first_together) cycle
      n_axes = n_axes + 1
      axes(n_axes) = k
      sizes(n_axes) = size(lists(k)%x)
    end do
    index = 1
    do i = 1, size(values, 2)
      do a = 1, n_axes
        k = axes(a)
        if (together(k)) then
          do j = 1, N_SWEPT
            if (together(j)) values(j, i) = lists(j)%x(index(a))
          end do
        else
          values(k, i) = lists(k)%x(index(a))
        end if
      end do
      ! the next combination: the last axis fastest
      do a = n_axes, 1, -1
        index(a) = index(a) + 1
        if (index(a) <= sizes(a)) exit
        index(a) = 1
      end do
    end do
  end function sweep_rows

  !> The file's unit of figure k in a sweep under `gravity` (m/s^2): felt
  !> accelerations in its |gravity| (felt_acceleration_units).
  pure function figure_unit(k, gravity) result(units)
    integer, intent(in) :: k
    real(wp), intent(in) :: gravity(3)
    character(len=:), allocatable :: units
    units = trim(figure_units(k))
    if (units == 'g') units = felt_acceleration_units(gravity)
  end function figure_unit

  !> An empty result for n rides and `limits` limits (all not run).
  subroutine new_sweep_result(n, limits, result)
    integer, intent(in) :: n, limits
    type(sweep_result_t), intent(out) :: result
    result%n = n
    allocate (result%status(n), result%message(n), result%figures(N_FIGURES, n), result%verdict(limits, n), &
              result%worst(limits, n), result%excess(limits, n), result%seconds(n), result%water_group(n))
    result%status = RIDE_NOT_RUN
    result%message = ''
    result%figures = 0
    result%verdict = -1
    result%worst = 0
    result%excess = 0
    result%seconds = 0
    result%water_group = 0
  end subroutine new_sweep_result

  !> The rides rank `rank` (0 .. ranks - 1) runs: ride i belongs to rank
  !> mod(i - 1, ranks), so neighbouring rides (often of one water) spread.
  pure function rides_of_rank(n, rank, ranks) result(mine)
    integer, intent(in) :: n, rank, ranks
    logical :: mine(n)
    integer :: i
    mine = [(mod(i - 1, max(1, ranks)) == rank, i=1, n)]
  end function rides_of_rank

  !> Groups the rides by their water: group(i) is the index of ride i's
  !> water among the distinct ones, numbered in order of first use;
  !> first(g) is the first ride of group g.
  pure subroutine water_groups(values, group, first)
    real(wp), intent(in) :: values(:, :)
    integer, allocatable, intent(out) :: group(:), first(:)
    integer :: i, g, n_groups
    integer, parameter :: w(4) = [V_FLOW_RATE, V_F1, V_F2, V_F3]
    allocate (group(size(values, 2)), first(size(values, 2)))
    n_groups = 0
    do i = 1, size(values, 2)
      group(i) = 0
      do g = 1, n_groups
        if (all(values(w, first(g)) == values(w, i))) then
          group(i) = g
          exit
        end if
      end do
      if (group(i) == 0) then
        n_groups = n_groups + 1
        first(n_groups) = i
        group(i) = n_groups
      end if
    end do
    first = first(:n_groups)
  end subroutine water_groups

  !> The rider and the water of ride i.
  pure subroutine ride_description(sweep, i, rider, water)
    type(sweep_description_t), intent(in) :: sweep
    integer, intent(in) :: i
    type(rider_params_t), intent(out) :: rider
    type(water_description_t), intent(out) :: water
    associate (v => sweep%values(:, i))
      rider = sweep%rider
      rider%body%sex = merge(SEX_MALE, SEX_FEMALE, nint(v(V_SEX)) == SEX_MALE)
      rider%body%mass = v(V_MASS)
      rider%body%height = v(V_HEIGHT)
      call set_rider_mu(rider, v(V_MU))
      rider%u0 = v(V_U0)
      rider%v0 = v(V_V0)
      rider%heading0 = v(V_HEADING)*pi/180
      rider%speed0 = v(V_SPEED)
      water = sweep%water
      water%flow_rate = v(V_FLOW_RATE)
      water%f1 = v(V_F1)
      water%f2 = v(V_F2)
      water%f3 = v(V_F3)
    end associate
  end subroutine ride_description

  !> Runs the rides marked in `mine` (all others stay RIDE_NOT_RUN) in
  !> `threads` OpenMP threads (0: OpenMP's default, all cores), the waters
  !> they need first. Progress: a line to `log` every `progress_seconds`
  !> of wall clock (none without `log`); `share` scales its estimate (the
  !> number of ranks that run the other rides at the same pace).
  subroutine run_sweep(sweep, mine, threads, result, progress_seconds, share, log)
    type(sweep_description_t), intent(in) :: sweep
    logical, intent(in) :: mine(:)
    integer, intent(in) :: threads
    type(sweep_result_t), intent(out) :: result
    real(wp), intent(in), optional :: progress_seconds
    integer, intent(in), optional :: share
    procedure(log_sink_i), optional :: log
    type(water_result_t), allocatable :: waters(:)
    type(status_t), allocatable :: water_status(:)
    integer, allocatable :: group(:), first(:), needed(:), todo(:)
    integer :: n, g, k, i, n_threads, done, failed
    integer(int64) :: clock_rate, clock_start, clock_last
    real(wp) :: every

    n = size(sweep%values, 2)
    call new_sweep_result(n, size(sweep%limits), result)
    call water_groups(sweep%values, group, first)
    result%water_group = group
    allocate (waters(size(first)), water_status(size(first)), result%water_seconds(size(first)))
    result%water_seconds = 0
    needed = pack([(g, g=1, size(first))], [(any(mine .and. group == g), g=1, size(first))])
    todo = pack([(i, i=1, n)], mine)
    n_threads = max(1, threads)
    !$ if (threads <= 0) n_threads = omp_get_max_threads()
    every = 0
    if (present(progress_seconds) .and. present(log)) every = progress_seconds
    call system_clock(clock_start, clock_rate)
    clock_last = clock_start
    done = 0
    failed = 0

    ! the waters, then the rides (waters are few and short: one parallel loop each)
    !$omp parallel do num_threads(n_threads) schedule(dynamic, 1) private(g, i)
    do k = 1, size(needed)
      g = needed(k)
      call water_run_of(first(g), waters(g), water_status(g), result%water_seconds(g))
    end do
    !$omp end parallel do

    !$omp parallel do num_threads(n_threads) schedule(dynamic, 1) private(i)
    do k = 1, size(todo)
      i = todo(k)
      call one_ride(i)
      !$omp critical (sweep_progress)
      done = done + 1
      if (result%status(i) == RIDE_FAILED) failed = failed + 1
      call report_progress()
      !$omp end critical (sweep_progress)
    end do
    !$omp end parallel do

  contains

    subroutine water_run_of(ride, water, status, seconds)
      integer, intent(in) :: ride
      type(water_result_t), intent(out) :: water
      type(status_t), intent(out) :: status
      real(wp), intent(out) :: seconds
      type(rider_params_t) :: rider
      type(water_description_t) :: description
      integer(int64) :: clock0, clock1
      call system_clock(clock0)
      call ride_description(sweep, ride, rider, description)
      if (present(log)) then
        call compute_water(description, water, status, log)
      else
        call compute_water(description, water, status)
      end if
      call system_clock(clock1)
      seconds = real(clock1 - clock0, wp)/clock_rate
    end subroutine water_run_of

    subroutine one_ride(i)
      integer, intent(in) :: i
      type(ride_description_t) :: description
      type(ride_job_result_t) :: ride
      integer(int64) :: clock0, clock1
      call system_clock(clock0)
      associate (g => group(i))
        if (.not. water_status(g)%ok()) then
          result%status(i) = RIDE_FAILED
          result%message(i) = 'the water failed: '//water_status(g)%text()
          return   ! no time: nothing ran
        end if
        call ride_description(sweep, i, description%rider, description%water)
        description%options = sweep%options
        description%limits = sweep%limits
        ride = run_ride(description, waters(g)%field)
      end associate
      if (.not. ride%status%ok()) then
        result%status(i) = RIDE_FAILED
        result%message(i) = ride%status%text()
      else
        result%status(i) = merge(RIDE_COMPLETE, RIDE_STOPPED, ride%complete)
        result%message(i) = ride%stopped
        call take_figures(ride%ride, ride%report, result%figures(:, i))
        call take_verdicts(ride%report, result%verdict(:, i), result%worst(:, i), result%excess(:, i))
      end if
      call system_clock(clock1)
      result%seconds(i) = real(clock1 - clock0, wp)/clock_rate
    end subroutine one_ride

    subroutine report_progress()
      integer(int64) :: now
      real(wp) :: elapsed, total
      integer :: ranks
      if (.not. every > 0) return
      call system_clock(now)
      if (real(now - clock_last, wp)/clock_rate < every .and. done < size(todo)) return
      clock_last = now
      elapsed = real(now - clock_start, wp)/clock_rate
      ranks = 1
      if (present(share)) ranks = max(1, share)
      total = elapsed*size(todo)/max(1, done)
      call log('sweep: '//format_integer(done*ranks)//' of '//format_integer(n)//' rides'// &
                    trim(merge(' (estimated)', '            ', ranks > 1))//', '//format_integer(failed*ranks)// &
                    ' failed, '//format_integer(nint(elapsed))//' s, about '// &
                    format_integer(nint(max(0.0_wp, total - elapsed)))//' s to go')
    end subroutine report_progress
  end subroutine run_sweep

  !> The ride's report figures in the order of figure_names.
  subroutine take_figures(ride, r, f)
    type(ride_result_t), intent(in) :: ride
    type(ride_report_t), intent(in) :: r
    real(wp), intent(out) :: f(N_FIGURES)
    real(wp) :: magnitude
    integer :: k, i, at
    f = 0
    if (r%n < 1) return
    f(1:5) = [r%ride_time, r%distance, r%top_speed, r%top_speed_at, r%final_speed]
    do k = 1, 3
      f(6 + 4*(k - 1):9 + 4*(k - 1)) = [r%felt_max(k), r%felt_max_at(k), r%felt_min(k), r%felt_min_at(k)]
    end do
    at = 1
    magnitude = -1
    do i = 1, r%n
      if (.not. r%felt_judged(i)) cycle   ! the model's value, not judged (design_ride_report)
      if (norm2(r%judged_felt(:, i)) > magnitude) then
        magnitude = norm2(r%judged_felt(:, i))
        at = i
      end if
    end do
    f(18:19) = [magnitude, ride%series%arc_length(at)]
    f(20:21) = [r%lever_max, r%lever_max_at]
    do k = 1, N_CONTACTS
      f(22 + 3*(k - 1):24 + 3*(k - 1)) = [r%climb_angle(k), r%wall_distance_max(k), r%climb_at(k)]
      f(30 + k) = r%normal_min(k)
    end do
    f(34) = ride%drag_switches
    f(35) = real(ride%driver%stats%steps, wp)
  end subroutine take_figures

  subroutine take_verdicts(r, verdict, worst, excess)
    type(ride_report_t), intent(in) :: r
    integer, intent(out) :: verdict(:)
    real(wp), intent(out) :: worst(:), excess(:)
    integer :: k
    verdict = -1
    worst = 0
    excess = 0
    do k = 1, size(verdict)
      if (.not. r%judged(k)) cycle
      verdict(k) = merge(1, 0, r%verdicts(k)%exceeded)
      worst(k) = r%verdicts(k)%worst
      excess(k) = r%verdicts(k)%excess
    end do
  end subroutine take_verdicts
end module design_sweep
