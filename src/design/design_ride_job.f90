!> One ride as a library call (docs/DESIGN.md, "The path of one ride"): a
!> ride description in memory (the slide and its water, the rider and its
!> start, the ride's solver settings, the limits) in, a result value out (the
!> water, the ride's records, the ride report with every limit's verdict,
!> the status and how the ride stopped). The water -> ride -> evaluation
!> chain exists here once: the `ride` scenario, the sweep, the rider
!> identification and the geometry optimisation all run it. It prints
!> nothing: progress lines go to the caller's `log` when it gives one, and
!> none are made otherwise; the command prints the summary from the result.
!>
!> Two bodies ride: the rider (BODY_RIDER, rider_model: a person, in the
!> water or dry, judged by the ride report) and the thesis 4.7 cuboid
!> (BODY_CUBOID, design_cuboid_ride: rigid, frictionless, dry, from its start
!> to the slide's end, with the figures the optimisation needs), the body
!> of the geometry optimisation.
!>
!> A water computed before (a sweep's rides of one flow, an identification's
!> every evaluation) is passed in and not computed again; a dry ride
!> (with_water = .false.) has no water at all. Thread-safe: the description
!> is only read, every run keeps its state in locals.
module design_ride_job
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_real, format_vector
  use base_log, only: log_sink_i
  use water_run, only: water_description_t, water_result_t, compute_water
  use water_field, only: water_field_t
  use water_flow, only: outcome_name
  use rider_model, only: rider_params_t
  use rider_ride, only: ride_options_t, ride_result_t, simulate_ride
  use design_ride_evaluation, only: ride_limit_t
  use design_ride_report, only: ride_report_t, evaluate_ride
  use design_cuboid_ride, only: cuboid_t, cuboid_start_t, cuboid_ride_options_t, cuboid_ride_t, ride_cuboid
  implicit none (type, external)
  private
  public :: ride_description_t, ride_job_result_t, run_ride
  public :: BODY_RIDER, BODY_CUBOID

  !> Which body rides (ride_description_t%body).
  integer, parameter :: BODY_RIDER = 1, BODY_CUBOID = 2

  !> Everything one ride needs.
  type :: ride_description_t
    type(water_description_t) :: water        !< the slide (water%slide) and its water
    logical :: with_water = .true.            !< .false.: a dry ride, no water computed, no drag
    integer :: body = BODY_RIDER              !< which body rides: the rider, or the cuboid
    type(rider_params_t) :: rider             !< BODY_RIDER: the body, its friction and its start
    type(ride_options_t) :: options           !< BODY_RIDER: integration, output step, stall speed, bounds
    type(ride_limit_t), allocatable :: limits(:)   !< BODY_RIDER: judged by the report (none: nothing judged)
    type(cuboid_t) :: cuboid                  !< BODY_CUBOID: the body (dry: with_water = .false.)
    type(cuboid_start_t) :: cuboid_start      !< BODY_CUBOID: where and how it starts (it rides to the slide's end)
    type(cuboid_ride_options_t) :: cuboid_options   !< BODY_CUBOID: integration, sampling, lever limit
    character(len=:), allocatable :: label    !< names the ride in progress lines and messages ('ride')
    !> where progress lines go (the stages, the integrator's lines every
    !> options%progress_seconds); not given: the ride makes none
    procedure(log_sink_i), pointer, nopass :: log => null()
  end type ride_description_t

  !> What one ride gave.
  type :: ride_job_result_t
    type(status_t) :: status                  !< ok, or why it failed (the water's failure says so)
    character(len=:), allocatable :: stopped  !< how the ride ended, in words ('' when it did not run)
    logical :: ridden = .false.               !< the rider ran (false: the water failed first)
    logical :: complete = .false.             !< the rider reached the end of the slide
    type(water_result_t) :: water             !< the water computed here (empty when given or dry)
    character(len=:), allocatable :: water_outcome   !< how the water computed here ended ('' otherwise)
    type(ride_result_t) :: ride               !< BODY_RIDER: the records, the integrator's statistics
    type(ride_report_t) :: report             !< BODY_RIDER: the figures and the limits' verdicts
    type(cuboid_ride_t) :: cuboid             !< BODY_CUBOID: the figures (and samples, if kept) of its ride
    real(wp) :: water_cpu = 0                 !< s of CPU time of the water computed here
    real(wp) :: ride_cpu = 0                  !< s of CPU time of the ride and its evaluation
  end type ride_job_result_t

contains

  !> The water (unless given or dry), then the rider in it, then the ride
  !> report. `water`: a water computed before for this description's slide
  !> and flow, used instead of computing it again.
  function run_ride(description, water) result(result)
    type(ride_description_t), intent(in) :: description
    type(water_field_t), intent(in), optional :: water
    type(ride_job_result_t) :: result
    type(ride_options_t) :: options
    type(ride_limit_t), allocatable :: limits(:)
    real(wp) :: cpu0, cpu1

    result%stopped = ''
    result%water_outcome = ''
    if (description%body == BODY_CUBOID) then
      call cuboid_job()
      return
    end if
    ! one gravity: the water's and the rider's cannot disagree in one ride
    if (description%with_water .and. any(description%water%gravity /= description%rider%gravity)) then
      call set_status(result%status, STATUS_INVALID_INPUT, ride_label()//': water%gravity = '// &
                      format_vector(description%water%gravity)//' m/s^2 but rider%gravity = '// &
                      format_vector(description%rider%gravity)//' m/s^2: a ride has one gravity')
      return
    end if
    options = description%options
    if (associated(description%log)) options%log => description%log   ! none: the driver makes no lines
    if (description%with_water .and. .not. present(water)) then
      if (associated(description%log)) call description%log(ride_label()//': the water first ('// &
                                                            format_real(description%water%flow_rate)//' m^3/s)')
      if (associated(description%log)) then
        call compute_water(description%water, result%water, result%status, description%log)
      else
        call compute_water(description%water, result%water, result%status)
      end if
      result%water_cpu = result%water%cpu
      result%water_outcome = outcome_name(result%water%series%outcome)
      if (.not. result%status%ok()) then
        call prefix_status(result%status, 'the water')
        return
      end if
    end if
    if (associated(description%log)) call description%log(ride_label()//': the rider')
    call cpu_time(cpu0)
    if (.not. description%with_water) then
      call simulate_ride(description%rider, description%water%slide, options, result%ride, result%status, &
                         label=ride_label())
    else if (present(water)) then
      call simulate_ride(description%rider, description%water%slide, options, result%ride, result%status, water, &
                         label=ride_label())
    else
      call simulate_ride(description%rider, description%water%slide, options, result%ride, result%status, &
                         result%water%field, label=ride_label())
    end if
    if (allocated(description%limits)) then
      limits = description%limits
    else
      allocate (limits(0))
    end if
    call evaluate_ride(result%ride%series, description%rider%gravity, result%ride%complete, limits, result%report, &
                       result%ride%ejected_contact, result%ride%flights)
    call cpu_time(cpu1)
    result%ride_cpu = cpu1 - cpu0
    result%ridden = .true.
    result%complete = result%ride%complete
    if (allocated(result%ride%outcome)) result%stopped = result%ride%outcome

  contains

    !> The cuboid from its start to the slide's end (u_max of its domain),
    !> dry; the ride's failure as ride_cuboid says it.
    subroutine cuboid_job()
      real(wp) :: u_min, u_max, v_min, v_max
      if (description%with_water) then
        call set_status(result%status, STATUS_INVALID_INPUT, ride_label()// &
                        ': the cuboid rides dry (with_water = .false.)')
        return
      end if
      if (allocated(description%limits)) then
        if (size(description%limits) > 0) then
          call set_status(result%status, STATUS_INVALID_INPUT, ride_label()//': '// &
                          'limits judge the rider''s ride report; the cuboid''s ride has none')
          return
        end if
      end if
      if (.not. allocated(description%water%slide)) then
        call set_status(result%status, STATUS_INVALID_INPUT, ride_label()//': no slide (water%slide)')
        return
      end if
      if (associated(description%log)) call description%log(ride_label()//': the cuboid')
      call description%water%slide%domain(u_min, u_max, v_min, v_max)
      call cpu_time(cpu0)
      call ride_cuboid(description%water%slide, description%cuboid, description%cuboid_start, u_max, &
                       description%cuboid_options, result%cuboid, result%status)
      call cpu_time(cpu1)
      result%ride_cpu = cpu1 - cpu0
      result%ridden = .true.
      result%complete = result%cuboid%reached_end
      if (result%complete) result%stopped = 'end of the slide: the cuboid reached it'
    end subroutine cuboid_job

    function ride_label() result(label)
      character(len=:), allocatable :: label
      label = 'ride'
      if (allocated(description%label)) label = description%label
    end function ride_label
  end function run_ride
end module design_ride_job
