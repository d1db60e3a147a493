!> Identification of the rider's friction mu_D from measured rider positions
!> and speeds (thesis 4.4.3, cost 4.43; METHOD-PART2 D).
!>
!> Measurements: at n stations (centerline arc length s_i) the wall angles of
!> the three contacts (pelvis, heels, back; the thesis's l/r) in the frame in
!> which the pelvis crosses s_i (one camera frame per station mark: the
!> thesis does not say which moment, slidesim takes the pelvis's crossing),
!> and optionally on m segments [a_j, b_j] the rider's speed, the segment's
!> length over the pelvis's passage time between its ends (as measured).
!> Simulated: a ride (design_ride_job's run_ride, the same run the `ride`
!> scenario makes, with the water given) with mu_D at all three contacts, recording the state where
!> the pelvis crosses every station and segment end (root functions) and
!> stopping at the last of them.
!> Cost (4.43): F2 = 1/2 (1-w)/n sum_i sum_contacts (v^SJ - v^M)^2
!>                   + 1/2 w k2^2/m sum_j (w^SJ - w^M)^2
!> (design_cost: one group per contact with the factor (1-w)/n, one speed
!> group), minimised by LMDER within bounds held exactly
!> (numerics_least_squares); a ride that lifts off, stalls or fails before
!> its last station is a rejected step. The standard error of mu_D comes
!> from s^2 (J^T J)^-1 at the optimum (weights matching the noise:
!> (1-w)/n sigma_angle^2 = w k2^2/m sigma_speed^2).
!>
!> The water is computed once by the caller (it does not depend on mu_D);
!> every evaluation builds its own rider from the setup, which it only reads,
!> so evaluations run in parallel with the same numbers as serially. The fit
!> itself, its record and the figures at the optimum are design_identification's:
!> this module gives the rider's sample (rider_stations_t), its run
!> (simulate_rider) and its cost groups (rider_cost_groups).
module design_rider_identification
  use base_kinds, only: wp
  use base_sorting, only: unique_sorted
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use base_text, only: format_short
  use geometry_slide_query, only: slide_surface_t
  use water_field, only: water_field_t
  use rider_model, only: rider_params_t, N_CONTACTS, contact_names, CONTACT_PELVIS, rider_friction_kind, &
    rider_coulomb_mu, set_rider_mu
  use rider_ride, only: ride_options_t
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  use numerics_least_squares, only: least_squares_options_t, least_squares_result_t
  use design_identification, only: identification_sample_t, identification_problem_t, identification_fit_t, &
    fit_identification, identification_solver
  use design_measurements, only: check_measured_places
  use design_cost, only: cost_group_t, new_cost_group, position_factor, speed_factor, group_part, &
    group_rmse, group_mae, group_max_abs
  implicit none (type, external)
  private
  public :: rider_measurements_t, rider_identification_t, rider_fit_options_t, rider_fit_t, rider_stations_t
  public :: new_rider_identification, simulate_rider, rider_cost_groups, fit_rider_friction, rider_weight_sweep
  public :: rider_body_sensitivity, body_variants, N_BODY_VARIANTS, body_variant_names

  !> Table 4.10's variants of the identified rider (body_variants), in words.
  integer, parameter :: N_BODY_VARIANTS = 10
  character(len=*), parameter :: body_variant_names(N_BODY_VARIANTS) = [character(len=24) :: 'mass +1%', &
    'mass -1%', 'height +1%', 'height -1%', 'com_height +1%', 'com_height -1%', 'pelvis radius +1%', &
    'pelvis radius -1%', 'pelvis radius -40%', 'no drag']

  type :: rider_measurements_t
    real(wp), allocatable :: station_arc_length(:)   !< m, where the pelvis crosses; increasing
    real(wp), allocatable :: angle(:, :)              !< rad, N_CONTACTS x n: pelvis, heels, back
    real(wp), allocatable :: segment_start(:)         !< m, a_j
    real(wp), allocatable :: segment_end(:)           !< m, b_j > a_j
    real(wp), allocatable :: segment_speed(:)         !< m/s, w_j^M
  end type rider_measurements_t

  !> Everything an evaluation needs; read-only during a fit.
  type :: rider_identification_t
    class(slide_surface_t), allocatable :: slide   !< the slide query (geometry_slide_query)
    type(rider_params_t) :: params          !< the rider and its start; its Coulomb mu is the fitted mu_D
    type(ride_options_t) :: options         !< integration (thesis B.7); stations set here
    logical :: with_water = .false.         !< the water's drag (params%drag) in `water`
    type(water_field_t) :: water
    type(rider_measurements_t) :: data
    integer :: threads = 1                  !< OpenMP threads for independent evaluations
    ! derived by new_rider_identification
    integer, allocatable :: section_station(:), start_station(:), end_station(:)
  end type rider_identification_t

  type :: rider_fit_options_t
    real(wp) :: weight = 0.6_wp          !< w_RP of (4.43), thesis table 4.7's choice
    real(wp) :: k2 = 1                   !< rad s/m
    real(wp) :: lower = 0, upper = 0.11_wp   !< bounds of mu_D, held exactly (table 4.8)
    type(least_squares_options_t) :: solver = identification_solver
  end type rider_fit_options_t

  !> What a simulated ride gives at the measurement places.
  type, extends(identification_sample_t) :: rider_stations_t
    real(wp), allocatable :: angle(:, :)          !< rad, N_CONTACTS x n
    real(wp), allocatable :: wall_distance(:, :)  !< m, N_CONTACTS x n, along the section from the bottom
    real(wp), allocatable :: segment_speed(:)     !< m/s
  end type rider_stations_t

  !> The shared record (design_identification) and the rider's own figures.
  type, extends(identification_fit_t) :: rider_fit_t
    real(wp) :: mu = 0
    logical :: at_bound = .false.
    real(wp) :: standard_error = 0
    real(wp) :: k2 = 0
    real(wp) :: contact_part(N_CONTACTS) = 0                  !< rad^2, the position part per contact
    real(wp) :: rmse_angle(N_CONTACTS) = 0, mae_angle(N_CONTACTS) = 0, max_angle(N_CONTACTS) = 0   !< rad
    type(rider_stations_t) :: simulated
    real(wp), allocatable :: error_angle(:, :)    !< rad, simulated - measured
    real(wp), allocatable :: station_rmse(:)      !< rad, over the three contacts at each station
  end type rider_fit_t

  !> The fit's problem: mu_D is its one parameter.
  type, extends(identification_problem_t) :: rider_fit_problem_t
    type(rider_identification_t) :: setup
    type(rider_fit_options_t) :: options
  contains
    procedure :: simulate => problem_simulate
    procedure :: cost_groups => problem_cost_groups
  end type rider_fit_problem_t

contains

  !> Checks the measurements and places the ride's stations: every station
  !> and segment end, in order along the slide.
  subroutine new_rider_identification(setup, status)
    type(rider_identification_t), intent(inout) :: setup
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: s(:)
    integer :: n, m, i

    if (.not. status%ok()) return
    associate (d => setup%data)
      if (.not. allocated(d%station_arc_length)) allocate (d%station_arc_length(0), d%angle(N_CONTACTS, 0))
      if (.not. allocated(d%segment_start)) allocate (d%segment_start(0), d%segment_end(0), d%segment_speed(0))
      n = size(d%station_arc_length)
      m = size(d%segment_start)
      if (size(d%angle, 1) /= N_CONTACTS .or. size(d%angle, 2) /= n .or. size(d%segment_end) /= m .or. &
          size(d%segment_speed) /= m) then
        call set_status(status, STATUS_INVALID_INPUT, 'rider measurements: three angles per station, '// &
                        'one speed per segment')
        return
      end if
      call check_measured_places('rider', 'station', d%station_arc_length, d%segment_start, d%segment_end, status)
      if (.not. status%ok()) return
      s = unique_sorted([d%station_arc_length, d%segment_start, d%segment_end])
      setup%section_station = [(findloc(s, d%station_arc_length(i), dim=1), i=1, n)]
      setup%start_station = [(findloc(s, d%segment_start(i), dim=1), i=1, m)]
      setup%end_station = [(findloc(s, d%segment_end(i), dim=1), i=1, m)]
    end associate
    setup%options%stations = s
    setup%options%stop_at_last_station = .true.
    setup%options%progress_seconds = 0
    if (s(size(s)) > setup%slide%length()) then
      call set_status(status, STATUS_INVALID_INPUT, 'rider measurements: the last place, '// &
                      format_short(s(size(s)))//' m, lies beyond the slide''s end ('// &
                      format_short(setup%slide%length())//' m)')
    end if
  end subroutine new_rider_identification

  !> One ride of `params` (the setup's, or a variant for the sensitivity
  !> study): the simulated measurements. Reads the setup only (thread-safe).
  !> A ride that does not reach its last station is a STATUS_DOMAIN failure.
  subroutine simulate_rider(setup, params, simulated, status)
    type(rider_identification_t), intent(in) :: setup
    type(rider_params_t), intent(in) :: params
    type(rider_stations_t), intent(out) :: simulated
    type(status_t), intent(out) :: status
    type(ride_description_t) :: description
    type(ride_job_result_t) :: job
    integer :: i, k, n, m
    real(wp) :: mu
    logical :: coulomb

    n = size(setup%data%station_arc_length)
    m = size(setup%data%segment_speed)
    allocate (simulated%angle(N_CONTACTS, n), simulated%wall_distance(N_CONTACTS, n), simulated%segment_speed(m))
    simulated%angle = 0
    simulated%wall_distance = 0
    simulated%segment_speed = 0
    description%water%slide = setup%slide
    description%with_water = setup%with_water
    description%rider = params
    description%options = setup%options
    description%label = 'rider identification'
    job = run_ride(description, setup%water)
    status = job%status
    if (status%ok() .and. .not. allocated(job%ride%station_record)) &
      call set_status(status, STATUS_DOMAIN, 'the ride recorded no stations')
    if (status%ok()) then
      if (any(job%ride%station_record == 0)) call set_status(status, STATUS_DOMAIN, 'the ride ended before '// &
        format_short(setup%options%stations(findloc(job%ride%station_record, 0, dim=1)))//' m: '//job%ride%outcome)
    end if
    if (.not. status%ok()) then
      call rider_coulomb_mu(params, mu, coulomb)
      if (coulomb) then
        call prefix_status(status, 'ride with mu_D = '//format_short(mu))
      else
        call prefix_status(status, 'ride with friction '''//rider_friction_kind(params)//'''')
      end if
      if (status%code == STATUS_INVALID_INPUT) status%code = STATUS_DOMAIN
      return
    end if
    associate (series => job%ride%series, rec => job%ride%station_record)
      do i = 1, n
        do k = 1, N_CONTACTS
          simulated%angle(k, i) = series%contact(k)%wall_angle(rec(setup%section_station(i)))
          simulated%wall_distance(k, i) = series%contact(k)%wall_distance(rec(setup%section_station(i)))
        end do
      end do
      do i = 1, m
        simulated%segment_speed(i) = (setup%data%segment_end(i) - setup%data%segment_start(i))/ &
          (series%time(rec(setup%end_station(i))) - series%time(rec(setup%start_station(i))))
      end do
    end associate
  end subroutine simulate_rider

  !> The four groups of (4.43): pelvis, heels, back positions, speeds.
  pure subroutine rider_cost_groups(setup, options, simulated, groups)
    type(rider_identification_t), intent(in) :: setup
    type(rider_fit_options_t), intent(in) :: options
    type(rider_stations_t), intent(in) :: simulated
    type(cost_group_t), intent(out) :: groups(N_CONTACTS + 1)
    integer :: k, n
    n = size(setup%data%station_arc_length)
    do k = 1, N_CONTACTS
      groups(k) = new_cost_group(trim(contact_names(k)), 'rad', position_factor(options%weight, n), &
                                 simulated%angle(k, :) - setup%data%angle(k, :))
    end do
    groups(N_CONTACTS + 1) = new_cost_group('speed', 'm s-1', &
      speed_factor(options%weight, options%k2, size(setup%data%segment_speed)), &
      simulated%segment_speed - setup%data%segment_speed)
  end subroutine rider_cost_groups

  !> The ride with mu_D = p(1).
  subroutine problem_simulate(self, p, sample, status)
    class(rider_fit_problem_t), intent(in) :: self
    real(wp), intent(in) :: p(:)
    class(identification_sample_t), allocatable, intent(out) :: sample
    type(status_t), intent(out) :: status
    type(rider_params_t) :: params
    type(rider_stations_t), allocatable :: simulated
    params = self%setup%params
    call set_rider_mu(params, p(1))
    allocate (simulated)
    call simulate_rider(self%setup, params, simulated, status)
    call move_alloc(simulated, sample)
  end subroutine problem_simulate

  subroutine problem_cost_groups(self, sample, groups)
    class(rider_fit_problem_t), intent(in) :: self
    class(identification_sample_t), intent(in) :: sample
    type(cost_group_t), allocatable, intent(out) :: groups(:)
    allocate (groups(N_CONTACTS + 1))
    select type (sample)
    type is (rider_stations_t)
      call rider_cost_groups(self%setup, self%options, sample, groups)
    end select
  end subroutine problem_cost_groups

  !> Fits mu_D from `mu` (the start) within the bounds; `fit` holds the
  !> optimum, its report and the simulated measurements there.
  subroutine fit_rider_friction(setup, options, mu, fit, status)
    type(rider_identification_t), intent(in) :: setup
    type(rider_fit_options_t), intent(in) :: options
    real(wp), intent(in) :: mu
    type(rider_fit_t), intent(out) :: fit
    type(status_t), intent(out) :: status
    type(rider_fit_problem_t) :: problem
    type(least_squares_result_t) :: result
    class(identification_sample_t), allocatable :: sample
    type(cost_group_t), allocatable :: groups(:)
    real(wp) :: p(1), start
    logical :: coulomb
    integer :: k

    call rider_coulomb_mu(setup%params, start, coulomb)
    if (.not. coulomb) then
      call set_status(status, STATUS_INVALID_INPUT, 'rider friction identification: it fits the Coulomb mu_D '// &
                      'at the three contacts; the rider''s friction law is '''//rider_friction_kind(setup%params)// &
                      ''' (give coulomb or none)')
      return
    end if
    if (.not. (options%lower >= 0 .and. options%upper > options%lower .and. mu >= options%lower .and. &
               mu <= options%upper)) then
      call set_status(status, STATUS_INVALID_INPUT, 'rider friction identification: need 0 <= lower < upper '// &
                      'and the start mu_D = '//format_short(mu)//' within them')
      return
    end if
    problem%setup = setup
    problem%options = options
    problem%threads = setup%threads
    p = mu
    call fit_identification('rider friction identification', problem, N_CONTACTS*size(setup%data%station_arc_length) + &
                            size(setup%data%segment_speed), p, [options%lower], [options%upper], &
                            options%solver, fit, result, sample, groups, status)
    fit%mu = p(1)
    if (.not. status%ok()) return
    fit%at_bound = result%at_bound(1)
    if (result%covariance_valid) fit%standard_error = result%standard_error(1)
    ! the rider's own figures at the optimum
    select type (sample)
    type is (rider_stations_t)
      fit%simulated = sample
    end select
    fit%error_angle = fit%simulated%angle - setup%data%angle
    fit%error_speed = fit%simulated%segment_speed - setup%data%segment_speed
    fit%station_rmse = sqrt(sum(fit%error_angle**2, dim=1)/N_CONTACTS)
    fit%weight = options%weight
    fit%k2 = options%k2
    do k = 1, N_CONTACTS
      fit%contact_part(k) = group_part(groups(k))
      fit%rmse_angle(k) = group_rmse(groups(k))
      fit%mae_angle(k) = group_mae(groups(k))
      fit%max_angle(k) = group_max_abs(groups(k))
    end do
  end subroutine fit_rider_friction

  !> The fit for every weight w_RP (table 4.7), each from the same start.
  subroutine rider_weight_sweep(setup, options, weights, mu, fits, status)
    type(rider_identification_t), intent(in) :: setup
    type(rider_fit_options_t), intent(in) :: options
    real(wp), intent(in) :: weights(:), mu
    type(rider_fit_t), allocatable, intent(out) :: fits(:)
    type(status_t), intent(out) :: status
    type(rider_fit_options_t) :: each
    integer :: k
    allocate (fits(size(weights)))
    each = options
    do k = 1, size(weights)
      each%weight = weights(k)
      call fit_rider_friction(setup, each, mu, fits(k), status)
      if (.not. status%ok()) then
        call prefix_status(status, 'weight w_RP = '//format_short(weights(k)))
        return
      end if
    end do
  end subroutine rider_weight_sweep

  !> Table 4.10's variants of the rider p (body_variant_names): its mass,
  !> height, centre-of-mass height and pelvis drag radius each 1 % up and
  !> down, the pelvis radius 40 % down, and no drag (the thesis's pelvis
  !> radius 0: a sphere needs a radius > 0).
  pure function body_variants(p) result(v)
    type(rider_params_t), intent(in) :: p
    type(rider_params_t) :: v(N_BODY_VARIANTS)
    v = p
    v(1)%body%mass = 1.01_wp*p%body%mass
    v(2)%body%mass = 0.99_wp*p%body%mass
    v(3)%body%height = 1.01_wp*p%body%height
    v(4)%body%height = 0.99_wp*p%body%height
    v(5)%body%com_height = 1.01_wp*p%body%com_height
    v(6)%body%com_height = 0.99_wp*p%body%com_height
    v(7)%drag_radius(CONTACT_PELVIS) = 1.01_wp*p%drag_radius(CONTACT_PELVIS)
    v(8)%drag_radius(CONTACT_PELVIS) = 0.99_wp*p%drag_radius(CONTACT_PELVIS)
    v(9)%drag_radius(CONTACT_PELVIS) = 0.6_wp*p%drag_radius(CONTACT_PELVIS)
    v(10)%drag = .false.
  end function body_variants

  !> Table 4.10: the mean absolute deviation (m) of the pelvis's position
  !> across the slide (its wall distance) at the stations between the ride
  !> of setup%params and the ride of each variant. Variants run in `threads`
  !> threads; a variant whose ride fails gets a negative deviation and its
  !> status in `statuses`.
  subroutine rider_body_sensitivity(setup, variants, deviation, statuses, status)
    type(rider_identification_t), intent(in) :: setup
    type(rider_params_t), intent(in) :: variants(:)
    real(wp), intent(out) :: deviation(:)
    type(status_t), intent(out) :: statuses(:)
    type(status_t), intent(out) :: status
    type(rider_stations_t) :: reference
    integer :: k
    deviation = -1
    call simulate_rider(setup, setup%params, reference, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'body sensitivity: the reference ride')
      return
    end if
    !$omp parallel do num_threads(max(1, setup%threads)) schedule(dynamic, 1) if (setup%threads > 1)
    do k = 1, size(variants)
      call one_variant(k)
    end do
    !$omp end parallel do
  contains
    subroutine one_variant(k)
      integer, intent(in) :: k
      type(rider_stations_t) :: varied
      call simulate_rider(setup, variants(k), varied, statuses(k))
      if (statuses(k)%ok()) deviation(k) = sum(abs(varied%wall_distance(CONTACT_PELVIS, :) - &
                                                   reference%wall_distance(CONTACT_PELVIS, :)))/ &
                                           max(1, size(reference%wall_distance, 2))
    end subroutine one_variant
  end subroutine rider_body_sensitivity
end module design_rider_identification
