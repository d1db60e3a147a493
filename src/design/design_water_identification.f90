!> Identification of the water's friction f1, f2, f3 from measurements (thesis
!> 4.4.1, cost 4.34; METHOD-PART2 C).
!>
!> Measurements: at n sections (centerline arc length s_i) the middle of the
!> flow v_i^M (4.32: the mean of the two edges' angles), and optionally on m
!> segments [a_j, b_j] the speed w_j^M of balls carried by the flow.
!> Simulated: a water run with f = [f1, f2, f3] from the measured start (4.33,
!> the water_start_t of the setup), stopped at every section and segment
!> point (root functions of the streamline), gives
!>   v_i^SJ   the middle of the computed water band at section i: the mean of
!>            the two edges' v (4.25-4.26) where the streamline crosses s_i
!>            (MIDDLE_EDGES, what is measured), or the streamline's own v there
!>            (MIDDLE_STREAMLINE, the thesis's wording);
!>   w_j^SJ   the speed at the segment's midpoint (SPEED_MIDPOINT, as the
!>            thesis), or the segment's length over the passage time between
!>            its ends (SPEED_PASSAGE, as measured).
!> Cost (4.34): F1 = 1/2 (1-w)/n sum (v^SJ - v^M)^2 + 1/2 w k1^2/m sum (w^SJ - w^M)^2
!> (design_cost), minimised by LMDER within bounds held exactly
!> (numerics_least_squares). Parameters may be held fixed (the start-value
!> procedure C.5 fits one at a time) and residual groups restricted to a
!> subset of sections and segments.
!>
!> Standard errors and correlations come from the covariance s^2 (J^T J)^-1
!> at the optimum: it assumes the weighted residuals share one variance,
!> i.e. that the weights match the measurement noise
!> ((1-w)/n sigma_v^2 = w k1^2/m sigma_w^2); docs/identification.md says how to
!> choose them.
!>
!> Every evaluation runs its own water model built from the setup, which it
!> only reads: evaluations are independent and run in parallel (OpenMP,
!> `threads`) for the difference Jacobian, with the same numbers as serially.
!> The fit itself, its record and the figures at the optimum are
!> design_identification's: this module gives the water's sample
!> (water_sample_t), its run (simulate_measurements) and its cost groups
!> (water_cost_groups).
module design_water_identification
  use base_kinds, only: wp
  use base_sorting, only: unique_sorted
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_text, only: format_short
  use numerics_ode, only: ode_options_t
  use numerics_least_squares, only: least_squares_options_t, least_squares_result_t
  use design_identification, only: identification_sample_t, identification_problem_t, identification_fit_t, &
    fit_identification, identification_solver
  use water_streamline, only: streamline_t
  use water_flow, only: water_series_t, simulate_water
  use water_run, only: water_description_t, new_streamline
  use design_measurements, only: check_measured_places
  use design_cost, only: cost_group_t, new_cost_group, position_factor, speed_factor, group_rmse, group_mae, &
    group_max_abs
  implicit none (type, external)
  private
  public :: water_measurements_t, water_identification_t, water_fit_options_t, water_fit_t
  public :: new_water_identification, simulate_measurements, water_cost_groups, fit_water_friction
  public :: water_start_values, water_weight_sweep, water_start_values_t
  public :: SPEED_MIDPOINT, SPEED_PASSAGE, MIDDLE_EDGES, MIDDLE_STREAMLINE

  integer, parameter :: SPEED_MIDPOINT = 1, SPEED_PASSAGE = 2
  integer, parameter :: MIDDLE_EDGES = 1, MIDDLE_STREAMLINE = 2

  type :: water_measurements_t
    real(wp), allocatable :: section_arc_length(:)   !< m, centerline arc length s_i, increasing
    real(wp), allocatable :: section_v(:)            !< rad, measured middle v_i^M
    real(wp), allocatable :: segment_start(:)        !< m, centerline arc length a_j
    real(wp), allocatable :: segment_end(:)          !< m, b_j > a_j
    real(wp), allocatable :: segment_speed(:)        !< m/s, w_j^M
  end type water_measurements_t

  !> Everything an evaluation needs; read-only during a fit.
  type :: water_identification_t
    type(water_description_t) :: water     !< the slide, Q, the measured start (4.33), the model
                                           !< switches; its f, stations, edges and solver are not used
    type(ode_options_t) :: ode = ode_options_t(rtol=1e-10_wp, atol=1e-9_wp)   !< thesis C.4
    type(water_measurements_t) :: data
    integer :: speed_kind = SPEED_MIDPOINT
    integer :: middle_kind = MIDDLE_EDGES
    integer :: threads = 1                 !< OpenMP threads for independent evaluations
    ! derived by new_water_identification
    type(streamline_t) :: model            !< the water model of `water`, stopping at every station
    real(wp) :: y0(7) = 0                  !< its start state
    integer, allocatable :: section_station(:), mid_station(:), start_station(:), end_station(:)
  end type water_identification_t

  type :: water_fit_options_t
    real(wp) :: weight = 0.8_wp          !< w of (4.34), thesis table 4.2's choice
    real(wp) :: k1 = 1                   !< rad s/m
    logical :: estimate(3) = .true.     !< which of f1, f2, f3 are fitted (the others stay)
    real(wp) :: lower(3) = 0             !< bounds, held exactly (table 4.3: 0 and INF)
    real(wp) :: upper(3) = huge(1.0_wp)
    logical, allocatable :: use_section(:)   !< default: all
    logical, allocatable :: use_segment(:)   !< default: all
    type(least_squares_options_t) :: solver = identification_solver
  end type water_fit_options_t

  !> The shared record (design_identification; its correlation 3 x 3) and the water's own figures.
  type, extends(identification_fit_t) :: water_fit_t
    real(wp) :: f(3) = 0                    !< kg/m, kg, kg m
    logical :: estimated(3) = .false.
    logical :: at_bound(3) = .false.
    real(wp) :: standard_error(3) = 0
    real(wp) :: k1 = 0
    real(wp) :: rmse_position = 0, mae_position = 0, max_position = 0   !< rad
    real(wp), allocatable :: simulated_v(:), simulated_speed(:)   !< at every section / segment
    real(wp), allocatable :: error_v(:)                           !< simulated - measured
  end type water_fit_t

  !> What one water run gives at the measurement places.
  type, extends(identification_sample_t) :: water_sample_t
    real(wp), allocatable :: section_v(:), segment_speed(:)
  end type water_sample_t

  type :: water_start_values_t
    real(wp) :: f1_energy = 0      !< step 1: energy balance (4.35), kg/m
    real(wp) :: f1 = 0             !< step 1: fitted to the last segment's speed (f2 = f3 = 0)
    real(wp) :: f2 = 0             !< step 2: fitted to the chosen sections (f3 = 0)
    real(wp) :: f3 = 0             !< step 3: fitted to all sections
    integer :: evaluations = 0
  end type water_start_values_t

  !> The least-squares problem of one fit: residuals of the used groups; its
  !> parameters f1, f2, f3 (the held ones with lower = upper).
  type, extends(identification_problem_t) :: water_fit_problem_t
    type(water_identification_t) :: setup
    type(water_fit_options_t) :: options
  contains
    procedure :: simulate => problem_simulate
    procedure :: cost_groups => problem_cost_groups
  end type water_fit_problem_t

contains

  !> Checks the measurements against the slide, places the stations and
  !> builds the water model (water_run's new_streamline) once.
  subroutine new_water_identification(setup, status)
    type(water_identification_t), intent(inout) :: setup
    type(status_t), intent(inout) :: status
    type(water_description_t) :: water
    real(wp), allocatable :: s(:), places(:)
    integer :: n, m, i

    if (.not. status%ok()) return
    associate (d => setup%data)
      if (.not. allocated(d%section_arc_length)) allocate (d%section_arc_length(0), d%section_v(0))
      if (.not. allocated(d%segment_start)) allocate (d%segment_start(0), d%segment_end(0), d%segment_speed(0))
      n = size(d%section_arc_length)
      m = size(d%segment_start)
      if (size(d%section_v) /= n .or. size(d%segment_end) /= m .or. size(d%segment_speed) /= m) then
        call set_status(status, STATUS_INVALID_INPUT, 'water measurements: one value per section and segment')
        return
      end if
      call check_measured_places('water', 'section', d%section_arc_length, d%segment_start, d%segment_end, status)
      if (.not. status%ok()) return
      ! every place a run stops at, in order along the slide: the model's stations
      places = [d%section_arc_length, (d%segment_start + d%segment_end)/2, d%segment_start, d%segment_end]
      s = unique_sorted(places)
      setup%section_station = [(findloc(s, d%section_arc_length(i), dim=1), i=1, n)]
      setup%mid_station = [(findloc(s, (d%segment_start(i) + d%segment_end(i))/2, dim=1), i=1, m)]
      setup%start_station = [(findloc(s, d%segment_start(i), dim=1), i=1, m)]
      setup%end_station = [(findloc(s, d%segment_end(i), dim=1), i=1, m)]
    end associate
    water = setup%water
    water%stations = s
    ! its runs integrate one stream (simulate_water alone): inlets would be left out
    if (allocated(water%inlets)) then
      if (size(water%inlets) > 0) then
        call set_status(status, STATUS_INVALID_INPUT, 'water identification: the water has inlets '// &
                        '(water%inlets); the identification runs water from the start alone')
        return
      end if
    end if
    call new_streamline(water, setup%model, setup%y0, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'water identification')
      return
    end if
    if (any(setup%model%stations <= setup%y0(1))) then
      call set_status(status, STATUS_INVALID_INPUT, 'the measurement places (sections, segments) must all '// &
        'lie downstream of the start (u = '//format_short(setup%y0(1))//')')
    end if
  end subroutine new_water_identification

  !> One water run with friction f: the simulated middle at every section and
  !> the simulated speed on every segment. Reads the setup only (thread-safe).
  !> A run that does not reach every station is a STATUS_DOMAIN failure.
  subroutine simulate_measurements(setup, f, section_v, segment_speed, status)
    type(water_identification_t), intent(in) :: setup
    real(wp), intent(in) :: f(3)
    real(wp), intent(out) :: section_v(:), segment_speed(:)
    type(status_t), intent(out) :: status
    type(streamline_t), target :: model
    type(water_series_t) :: series
    integer :: i, k

    section_v = 0
    segment_speed = 0
    model = setup%model
    model%f1 = f(1)
    model%f2 = f(2)
    model%f3 = f(3)
    ! no bound in time (the run stops at the slide's end or by the model's
    ! own stops), no samples between the stations
    call simulate_water(model, setup%y0, setup%ode, huge(1.0_wp), 1e6_wp, series, status, edges=.false.)
    if (.not. status%ok()) then
      call prefix_status(status, 'water with f = '//format_short(f(1))//', '//format_short(f(2))//', '// &
                         format_short(f(3)))
      if (status%code == STATUS_INVALID_INPUT) status%code = STATUS_DOMAIN
      return
    end if
    do k = 1, size(series%stations)
      if (.not. series%stations(k)%reached) then
        call set_status(status, STATUS_DOMAIN, 'the water with f = '//format_short(f(1))//', '// &
          format_short(f(2))//', '//format_short(f(3))//' does not reach u = '// &
          format_short(setup%model%stations(k)))
        return
      end if
    end do
    do i = 1, size(section_v)
      associate (st => series%stations(setup%section_station(i)))
        if (setup%middle_kind == MIDDLE_EDGES) then
          section_v(i) = st%v_middle
        else
          section_v(i) = st%v
        end if
      end associate
    end do
    do i = 1, size(segment_speed)
      if (setup%speed_kind == SPEED_MIDPOINT) then
        segment_speed(i) = series%stations(setup%mid_station(i))%speed
      else
        segment_speed(i) = (setup%data%segment_end(i) - setup%data%segment_start(i))/ &
          (series%stations(setup%end_station(i))%time - series%stations(setup%start_station(i))%time)
      end if
    end do
  end subroutine simulate_measurements

  !> The two groups of (4.34) over the used sections and segments.
  pure subroutine water_cost_groups(setup, options, section_v, segment_speed, groups)
    type(water_identification_t), intent(in) :: setup
    type(water_fit_options_t), intent(in) :: options
    real(wp), intent(in) :: section_v(:), segment_speed(:)
    type(cost_group_t), intent(out) :: groups(2)
    logical :: use_section(size(section_v)), use_segment(size(segment_speed))
    real(wp), allocatable :: ev(:), ew(:)
    call used(options, size(section_v), size(segment_speed), use_section, use_segment)
    ev = pack(section_v - setup%data%section_v, use_section)
    ew = pack(segment_speed - setup%data%segment_speed, use_segment)
    groups(1) = new_cost_group('position', 'rad', position_factor(options%weight, size(ev)), ev)
    groups(2) = new_cost_group('speed', 'm s-1', speed_factor(options%weight, options%k1, size(ew)), ew)
  end subroutine water_cost_groups

  pure subroutine used(options, n, m, use_section, use_segment)
    type(water_fit_options_t), intent(in) :: options
    integer, intent(in) :: n, m
    logical, intent(out) :: use_section(n), use_segment(m)
    use_section = .true.
    use_segment = .true.
    if (allocated(options%use_section)) use_section = options%use_section
    if (allocated(options%use_segment)) use_segment = options%use_segment
  end subroutine used

  !> The water run with f = p.
  subroutine problem_simulate(self, p, sample, status)
    class(water_fit_problem_t), intent(in) :: self
    real(wp), intent(in) :: p(:)
    class(identification_sample_t), allocatable, intent(out) :: sample
    type(status_t), intent(out) :: status
    type(water_sample_t), allocatable :: simulated
    allocate (simulated)
    allocate (simulated%section_v(size(self%setup%data%section_v)), &
              simulated%segment_speed(size(self%setup%data%segment_speed)))
    call simulate_measurements(self%setup, p, simulated%section_v, simulated%segment_speed, status)
    call move_alloc(simulated, sample)
  end subroutine problem_simulate

  subroutine problem_cost_groups(self, sample, groups)
    class(water_fit_problem_t), intent(in) :: self
    class(identification_sample_t), intent(in) :: sample
    type(cost_group_t), allocatable, intent(out) :: groups(:)
    allocate (groups(2))
    select type (sample)
    type is (water_sample_t)
      call water_cost_groups(self%setup, self%options, sample%section_v, sample%segment_speed, groups)
    end select
  end subroutine problem_cost_groups

  !> Fits the estimated friction parameters from f (the start; the others stay
  !> as given) within the bounds. `fit` holds the optimum, its report and the
  !> simulated measurements there.
  subroutine fit_water_friction(setup, options, f, fit, status)
    type(water_identification_t), intent(in) :: setup
    type(water_fit_options_t), intent(in) :: options
    real(wp), intent(in) :: f(3)
    type(water_fit_t), intent(out) :: fit
    type(status_t), intent(out) :: status
    type(water_fit_problem_t) :: problem
    type(least_squares_result_t) :: result
    class(identification_sample_t), allocatable :: sample
    type(cost_group_t), allocatable :: groups(:)
    real(wp) :: p(3), lower(3), upper(3)
    logical :: use_section(size(setup%data%section_v)), use_segment(size(setup%data%segment_speed))
    integer :: m

    problem%setup = setup
    problem%options = options
    problem%threads = setup%threads
    call used(options, size(use_section), size(use_segment), use_section, use_segment)
    m = count(use_section) + count(use_segment)
    p = f
    lower = merge(options%lower, f, options%estimate)
    upper = merge(options%upper, f, options%estimate)
    call fit_identification('water friction identification', problem, m, p, lower, upper, options%solver, fit, &
                            result, sample, groups, status)
    fit%f = p
    fit%estimated = options%estimate
    if (.not. status%ok()) return
    fit%at_bound = result%at_bound .and. options%estimate
    if (result%covariance_valid) fit%standard_error = result%standard_error
    ! the water's own figures at the optimum
    select type (sample)
    type is (water_sample_t)
      fit%simulated_v = sample%section_v
      fit%simulated_speed = sample%segment_speed
    end select
    fit%error_v = fit%simulated_v - setup%data%section_v
    fit%error_speed = fit%simulated_speed - setup%data%segment_speed
    fit%weight = options%weight
    fit%k1 = options%k1
    fit%rmse_position = group_rmse(groups(1))
    fit%mae_position = group_mae(groups(1))
    fit%max_position = group_max_abs(groups(1))
  end subroutine fit_water_friction

  !> The thesis's start values (C.5): (1) f1 from the energy balance over the
  !> slide with the last segment's speed, m g dh = f1 w^2 s (4.35), then f1
  !> fitted to that speed alone (f2 = f3 = 0); (2) f2 fitted to the sections
  !> `curve_sections` (a curve; thesis: sections 15-20) with f1 held, f3 = 0;
  !> (3) f3 fitted to all sections with f1, f2 held.
  subroutine water_start_values(setup, options, curve_sections, values, status)
    type(water_identification_t), intent(in) :: setup
    type(water_fit_options_t), intent(in) :: options
    logical, intent(in) :: curve_sections(:)
    type(water_start_values_t), intent(out) :: values
    type(status_t), intent(out) :: status
    type(water_fit_options_t) :: step
    type(water_fit_t) :: fit
    real(wp) :: c0(3, 0:3), c1(3, 0:3), u_min, u_max, s, dh
    integer :: n, m

    n = size(setup%data%section_v)
    m = size(setup%data%segment_speed)
    if (m == 0 .or. n == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'water start values: need sections and at least one segment')
      return
    end if
    if (size(curve_sections) /= n .or. .not. any(curve_sections)) then
      call set_status(status, STATUS_INVALID_INPUT, 'water start values: choose at least one curve section')
      return
    end if
    call setup%model%channel%u_range(u_min, u_max)
    call setup%model%channel%centerline(setup%y0(1), c0, status)
    if (status%ok()) call setup%model%channel%centerline(u_max, c1, status)
    if (.not. status%ok()) return
    s = setup%model%channel%arc_length(u_max) - setup%model%channel%arc_length(setup%y0(1))
    dh = dot_product(c0(:, 0) - c1(:, 0), setup%model%gravity)/(-norm2(setup%model%gravity))
    values%f1_energy = setup%model%mass*norm2(setup%model%gravity)*dh/(setup%data%segment_speed(m)**2*s)
    if (.not. values%f1_energy > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'water start values: the slide does not descend')
      return
    end if

    step = options
    step%estimate = [.true., .false., .false.]
    step%use_section = spread(.false., 1, n)
    step%use_segment = spread(.false., 1, m)
    step%use_segment(m) = .true.
    call fit_water_friction(setup, step, [values%f1_energy, 0.0_wp, 0.0_wp], fit, status)
    values%evaluations = values%evaluations + fit%evaluations
    if (.not. status%ok()) return
    values%f1 = fit%f(1)

    step%estimate = [.false., .true., .false.]
    step%use_section = curve_sections
    step%use_segment(m) = .false.
    call fit_water_friction(setup, step, [values%f1, 0.0_wp, 0.0_wp], fit, status)
    values%evaluations = values%evaluations + fit%evaluations
    if (.not. status%ok()) return
    values%f2 = fit%f(2)

    step%estimate = [.false., .false., .true.]
    step%use_section = spread(.true., 1, n)
    call fit_water_friction(setup, step, [values%f1, values%f2, 0.0_wp], fit, status)
    values%evaluations = values%evaluations + fit%evaluations
    if (.not. status%ok()) return
    values%f3 = fit%f(3)
  end subroutine water_start_values

  !> The fit for every weight w (table 4.2), each from the same start f.
  subroutine water_weight_sweep(setup, options, weights, f, fits, status)
    type(water_identification_t), intent(in) :: setup
    type(water_fit_options_t), intent(in) :: options
    real(wp), intent(in) :: weights(:), f(3)
    type(water_fit_t), allocatable, intent(out) :: fits(:)
    type(status_t), intent(out) :: status
    type(water_fit_options_t) :: each
    integer :: k
    allocate (fits(size(weights)))
    each = options
    do k = 1, size(weights)
      each%weight = weights(k)
      call fit_water_friction(setup, each, f, fits(k), status)
      if (.not. status%ok()) then
        call prefix_status(status, 'weight w = '//format_short(weights(k)))
        return
      end if
    end do
  end subroutine water_weight_sweep
end module design_water_identification
