!> The rides of one design of the geometry optimisation (thesis 4.7, eq.
!> 4.49; design_geometry_optimization fits the design; choices in
!> docs/design.md): its setup and what a design's rides give.
!>
!> For a design x the slide is built (design_slide_design: a spline through
!> points, or a chain of standard elements; tube, check that it does not
!> fold) and the cuboid (design_cuboid_ride) rides it from each start, each
!> ride one library ride (design_ride_job's run_ride, body BODY_CUBOID). A
!> design's rides give the acceleration part of the cost (4.49),
!> 1/2 sum_i [max_t |a_i(x)|]^2, its largest lever arm and tipping excess
!> (the constraint of the optimisation) and, with constraint_violations, the
!> constraints it violates in words.
!>
!> Robust design (design_robust_cost): the rides may be a population's
!> members (setup%members, each its own body and start), and the cost's
!> acceleration part the worst ride or a quantile (setup%cost).
!>
!> All rides of one design, and of several (ride_designs: the difference
!> points of a fit), are independent: they run in `threads` OpenMP threads,
!> with the same numbers. Under MPI (setup%ranks > 1) each rank rides its
!> share of a batch of rides (design_optimize_ranks) and the figures are
!> broadcast as they are: the same numbers on every rank as in one
!> process. Rides that keep their series are ridden by every rank.
module design_geometry_evaluation
  use base_kinds, only: wp
  use base_log, only: log_sink_i
  use base_constants, only: pi
  use base_status, only: status_t, prefix_status
  use base_text, only: format_short, format_integer, format_real, append_item
  use geometry_tube, only: tube_surface_t
  use design_slide_design, only: slide_design_t, build_design_slide
  use numerics_least_squares, only: least_squares_options_t
  use design_cuboid_ride, only: cuboid_t, cuboid_start_t, cuboid_ride_options_t, cuboid_ride_t
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride, BODY_CUBOID
  use design_robust_cost, only: ride_member_t, COST_SUM, robust_maximum, worst_ride
  use design_optimize_ranks, only: ride_is_mine, share_rides
  implicit none (type, external)
  private
  public :: optimization_setup_t, design_evaluation_t, thesis_start_angles, evaluate_design, ride_designs
  public :: constraint_violations, CONSTRAINT_PENALTY, CONSTRAINT_EXACT, CONSTRAINT_NONE

  !> How the lever-arm limit is kept (design_geometry_optimization).
  integer, parameter :: CONSTRAINT_NONE = 0, CONSTRAINT_PENALTY = 1, CONSTRAINT_EXACT = 2

  type :: optimization_setup_t
    type(slide_design_t) :: design
    type(cuboid_t) :: body
    real(wp), allocatable :: start_angles(:)  !< rad, one ride each (thesis_start_angles)
    real(wp) :: start_speed = 0.5_wp          !< m/s
    real(wp) :: start_v = pi/2                !< rad, the bottom of the section at u = 0
    type(cuboid_ride_options_t) :: ride
    type(ride_member_t), allocatable :: members(:)   !< a population, ride i's body and start (its
                                                     !< angle start_angles(i)); none: body, start_speed, start_v
    integer :: cost = COST_SUM                !< the acceleration part of the cost (design_robust_cost)
    real(wp) :: quantile = 0.9_wp             !< q of COST_QUANTILE
    real(wp) :: lever_limit = 0.25_wp         !< m (half the body's width)
    integer :: constraint = CONSTRAINT_PENALTY
    real(wp) :: penalty_factor = 5e3_wp       !< 1/m x m/s^2 (thesis: 5.0e3)
    real(wp) :: lever_tolerance = 1e-4_wp     !< m, CONSTRAINT_EXACT
    real(wp) :: rho = 1e5_wp                  !< augmented Lagrangian weight, (m/s^2)^2/m^2 (20 x the penalty factor)
    integer :: max_outer = 8                  !< augmented Lagrangian updates
    integer :: max_restarts = 10              !< restarts from the end point, to show it is a minimum
    integer :: starts = 1                     !< multi-start: the given design and starts - 1 drawn ones
    integer :: seed = 1                       !< of the drawn starts
    integer :: threads = 1
    integer :: rank = 0, ranks = 1            !< MPI: this process's rank of `ranks` (design_optimize_ranks)
    procedure(log_sink_i), pointer, nopass :: log => null()   !< progress lines (none: not made)
    type(least_squares_options_t) :: solver = least_squares_options_t(ftol=1e-4_wp, xtol=1e-3_wp, &
                                                                      gtol=0.0_wp, epsfcn=1e-8_wp, &
                                                                      covariance=.false.)   ! not reported
                                              !< (its max_evaluations: the designs of one start, restarts included)
  end type optimization_setup_t

  !> Every ride of one design.
  type :: design_evaluation_t
    real(wp), allocatable :: x(:)
    type(cuboid_ride_t), allocatable :: rides(:)
    real(wp) :: acceleration_cost = 0      !< the cost without constraint terms (setup%cost), (m/s^2)^2
    real(wp) :: robust_acceleration = 0    !< m/s^2, the worst ride's or the quantile (COST_SUM: the worst)
    integer :: worst_ride = 0              !< the ride of the largest acceleration
    real(wp) :: max_lever_arm = 0          !< m, over all rides (huge if a body lifts off)
    real(wp) :: max_tipping_excess = 0     !< m, over all rides
  end type design_evaluation_t

contains

  !> The thesis's rides of each design (4.7, with table 4.12's slide): the
  !> start directions -30, -15, 0, 15 and 30 degrees to the centerline, in rad.
  pure function thesis_start_angles() result(angles)
    real(wp) :: angles(5)
    angles = [-30.0_wp, -15.0_wp, 0.0_wp, 15.0_wp, 30.0_wp]*pi/180
  end function thesis_start_angles

  !> Every ride of design x (rides(i) from start_angles(i)), in `threads` threads.
  subroutine evaluate_design(setup, x, evaluation, status, keep_series)
    type(optimization_setup_t), intent(in) :: setup
    real(wp), intent(in) :: x(:)
    type(design_evaluation_t), intent(out) :: evaluation
    type(status_t), intent(out) :: status
    logical, intent(in), optional :: keep_series
    type(tube_surface_t) :: slide
    type(status_t), allocatable :: statuses(:)
    type(cuboid_ride_options_t) :: ride_options
    integer :: i, n
    logical :: shared
    n = size(setup%start_angles)
    evaluation%x = x
    allocate (evaluation%rides(n), statuses(n))
    call build_design_slide(setup%design, x, slide, status)
    if (.not. status%ok()) return
    ride_options = setup%ride
    ride_options%lever_limit = setup%lever_limit
    if (present(keep_series)) ride_options%keep_series = keep_series
    shared = setup%ranks > 1 .and. .not. ride_options%keep_series
    !$omp parallel do num_threads(max(1, setup%threads)) schedule(dynamic, 1) if (setup%threads > 1)
    do i = 1, n
      if (shared) then
        if (.not. ride_is_mine(i, setup%rank, setup%ranks)) cycle
      end if
      call ride_one(setup, slide, ride_options, i, evaluation%rides(i), statuses(i))
    end do
    !$omp end parallel do
    if (shared) call share_rides(evaluation%rides, statuses, setup%rank, setup%ranks)
    do i = 1, n
      if (.not. statuses(i)%ok()) then
        status = statuses(i)
        return
      end if
    end do
    evaluation%worst_ride = worst_ride(evaluation%rides%max_acceleration)
    if (setup%cost == COST_SUM) then
      evaluation%acceleration_cost = 0.5_wp*sum(evaluation%rides%max_acceleration**2)
      evaluation%robust_acceleration = evaluation%rides(evaluation%worst_ride)%max_acceleration
    else
      evaluation%robust_acceleration = robust_maximum(evaluation%rides%max_acceleration, setup%cost, setup%quantile)
      evaluation%acceleration_cost = 0.5_wp*evaluation%robust_acceleration**2
    end if
    evaluation%max_lever_arm = maxval(evaluation%rides%max_lever_arm)
    evaluation%max_tipping_excess = maxval(evaluation%rides%max_tipping_excess)
  end subroutine evaluate_design

  !> The rides of the designs p(:, k) in one parallel loop: evaluations(k)%x
  !> and %rides (the figures evaluate_design forms from them are not formed);
  !> statuses(k) the first failure of design k (its slide or a ride).
  subroutine ride_designs(setup, p, evaluations, statuses)
    type(optimization_setup_t), intent(in) :: setup
    real(wp), intent(in) :: p(:, :)
    type(design_evaluation_t), intent(out) :: evaluations(:)
    type(status_t), intent(inout) :: statuses(:)
    type(tube_surface_t), allocatable :: slides(:)
    type(status_t), allocatable :: ride_status(:)
    type(cuboid_ride_t), allocatable :: rides(:)
    type(cuboid_ride_options_t) :: ride_options
    integer :: k, i, j, n, np
    np = size(p, 2)
    n = size(setup%start_angles)
    allocate (slides(np), ride_status(n*np), rides(n*np))
    ride_options = setup%ride
    ride_options%lever_limit = setup%lever_limit
    do k = 1, np
      call build_design_slide(setup%design, p(:, k), slides(k), statuses(k))
      allocate (evaluations(k)%rides(n))
      evaluations(k)%x = p(:, k)
    end do
    !$omp parallel do num_threads(max(1, setup%threads)) schedule(dynamic, 1) private(i, k) &
    !$omp if (setup%threads > 1)
    do j = 1, n*np
      k = (j - 1)/n + 1
      i = j - (k - 1)*n
      if (.not. ride_is_mine(j, setup%rank, setup%ranks)) cycle
      if (statuses(k)%ok()) call ride_one(setup, slides(k), ride_options, i, rides(j), ride_status(j))
    end do
    !$omp end parallel do
    call share_rides(rides, ride_status, setup%rank, setup%ranks)
    do k = 1, np
      if (.not. statuses(k)%ok()) cycle
      evaluations(k)%rides = rides((k - 1)*n + 1:k*n)
      do i = 1, n
        if (.not. ride_status((k - 1)*n + i)%ok()) then
          statuses(k) = ride_status((k - 1)*n + i)
          exit
        end if
      end do
    end do
  end subroutine ride_designs

  subroutine ride_one(setup, slide, options, i, ride, status)
    type(optimization_setup_t), intent(in) :: setup
    type(tube_surface_t), intent(in) :: slide
    type(cuboid_ride_options_t), intent(in) :: options
    integer, intent(in) :: i
    type(cuboid_ride_t), intent(out) :: ride
    type(status_t), intent(out) :: status
    type(ride_description_t) :: description
    type(ride_job_result_t) :: job
    real(wp) :: u_min, u_max
    call slide%centerline%domain(u_min, u_max)
    description%body = BODY_CUBOID
    description%with_water = .false.
    allocate (description%water%slide, source=slide)
    if (allocated(setup%members)) then
      description%cuboid = setup%members(i)%body
      description%cuboid_start = cuboid_start_t(u=u_min, v=setup%members(i)%v, speed=setup%members(i)%speed, &
                                                angle=setup%start_angles(i))
    else
      description%cuboid = setup%body
      description%cuboid_start = cuboid_start_t(u=u_min, v=setup%start_v, speed=setup%start_speed, &
                                                angle=setup%start_angles(i))
    end if
    description%cuboid_options = options
    job = run_ride(description)
    ride = job%cuboid
    status = job%status
    if (.not. status%ok()) call prefix_status(status, ride_name(setup, i))
  end subroutine ride_one

  !> Ride i in words: its start angle, or its member number in a population.
  function ride_name(setup, i) result(text)
    type(optimization_setup_t), intent(in) :: setup
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    if (allocated(setup%members)) then
      text = 'ride of member '//format_integer(i)
    else
      text = 'ride from '//format_short(setup%start_angles(i)*180/pi)//' deg'
    end if
  end function ride_name


  !> The constraints of the optimisation that design `e` violates, in
  !> words with values and limits ('' when all hold): a ride that lifts off,
  !> a ride whose tipping excess exceeds lever_tolerance.
  function constraint_violations(setup, e) result(text)
    type(optimization_setup_t), intent(in) :: setup
    type(design_evaluation_t), intent(in) :: e
    character(len=:), allocatable :: text, ride
    integer :: i
    text = ''
    do i = 1, size(e%rides)
      associate (r => e%rides(i))
        ride = 'ride at '//format_short(r%start_angle*180/pi)//' deg'
        if (allocated(setup%members)) ride = 'member '//format_integer(i)
        if (r%lifts_off) then
          call append_item(text, ride//' lifts off: smallest normal force '//format_short(r%min_normal_force)// &
                           ' N, must stay > 0', '; ')
        else if (r%max_tipping_excess > setup%lever_tolerance) then
          call append_item(text, ride//': lever arm '//format_short(r%max_lever_arm)//' m above lever_limit '// &
                           format_short(setup%lever_limit)//' m (tipping excess '// &
                           format_short(r%max_tipping_excess)//' m > lever_tolerance '// &
                           format_real(setup%lever_tolerance)//' m)', '; ')
        end if
      end associate
    end do
  end function constraint_violations

end module design_geometry_evaluation
