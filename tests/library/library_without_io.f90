!> The shipped water, ride and sweep inputs run through the library alone
!> (issue 24 point 2): each slide built by geometry_slide_builder from its
!> description (tests/library/shipped_slides.f90), the water by water_run,
!> the ride by design_ride_job, the sweep by design_sweep, every description
!> filled here in code from the values the input files give (the defaults
!> they do not give: the description types' own, which are the reader's). A
!> ride takes a slide (a chain of parts) and the rider's settings; the water
!> takes a slide and its inlets; a sweep, the base ride and its rides' values.
!> No io module is linked (tests/CMakeLists.txt links slidesim_design only).
!>
!> Prints `<input> <key> <value>` lines under the keys of the command's
!> --summary-json, with its number texts (format_real); a table row's
!> values as `<table>.<row>.<column>` (the stations, the landings; a
!> sweep's rides as the rows of its CSV). tests/library/library_without_io.sh
!> compares them with the command's runs of the same inputs (the fixture
!> cli_every_input, with its tolerances: rtol 1e-6, atol 1e-5 for the demo
!> ride, its template and the parts' rides); the inputs are those
!> tests/library/built_through_library.txt gives it. Exit status 1 when a
!> build or a run fails.
program library_without_io
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_text, only: format_integer
  use numerics_ode, only: ODE_ADAMS
  use geometry_description, only: geometry_description_t
  use geometry_slide_builder, only: build_slide
  use geometry_tube, only: tube_surface_t
  use water_flow, only: water_series_t, START_EDGES
  use water_inlet, only: water_inlet_t
  use water_streamline, only: CORRECTION_FULL, CORRECTION_OFF
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_body, only: SEX_MALE, SEX_FEMALE
  use rider_model, only: N_CONTACTS, contact_names, rider_params_t, set_rider_mu
  use kinetostatics_force_law_factory, only: law_spec
  use design_ride_evaluation, only: ride_limit_t, new_ride_limit, noise_free, rider_size
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  use design_sweep, only: sweep_description_t, sweep_result_t, run_sweep, water_groups, N_SWEPT, N_FIGURES, &
    figure_names, V_SEX, V_MASS, V_HEIGHT, V_MU, V_U0, V_V0, V_HEADING, V_SPEED, V_FLOW_RATE, V_F1, V_F2, V_F3, &
    RIDE_COMPLETE, swept_values_t, sweep_rows
  use design_water_identification, only: water_identification_t, water_fit_options_t, water_fit_t, &
    new_water_identification, simulate_measurements, fit_water_friction
  use design_rider_identification, only: rider_identification_t, rider_fit_options_t, rider_fit_t, &
    rider_stations_t, new_rider_identification, simulate_rider, fit_rider_friction, rider_body_sensitivity, &
    body_variants
  use shipped_slides, only: demo_slide, second_slide, drop_slide, halfpipe_slide, bowl_slide, bowl_table_slide, &
    crest_slide, jump_slide, funnel_slide, patch_slide
  use library_lines, only: put, put_flights, stop_unless_ok
  implicit none (type, external)
  real(wp), parameter :: pi_2 = 1.5707963267948966_wp   ! the inputs' v0 (the bottom)

  call water_demo_slide()
  call water_template()
  call water_two_inlets()
  call water_second_slide()
  call ride_demo_slide('inputs/ride/demo_slide.nml')
  call ride_demo_slide('inputs/templates/ride.nml')   ! the same ride, every variable written
  call ride_part('inputs/parts/bowl.nml', bowl_slide(), 1.9_wp, 1.2415926535897932_wp, 1.0_wp, 1.0_wp, 10.0_wp)
  call ride_part('inputs/parts/bowl_table.nml', bowl_table_slide(), 1.9_wp, 1.2415926535897932_wp, 1.0_wp, &
                 1.0_wp, 10.0_wp)
  call ride_part('inputs/parts/funnel.nml', funnel_slide(), 1.9_wp, 1.2415926535897932_wp, 1.0_wp, 1.0_wp, 10.0_wp)
  call ride_part('inputs/parts/patch.nml', patch_slide(), 1.9_wp, 1.2415926535897932_wp, 1.0_wp, 1.0_wp, 10.0_wp)
  call ride_part('inputs/parts/halfpipe.nml', halfpipe_slide(), 1.6707963267948966_wp, 1.4707963267948966_wp, &
                 1.0_wp, 1.0_wp, 10.0_wp)
  ! the drop: the water's start edges the defaults (pi/2 +- 0.3), a trap-door start
  call ride_part('inputs/parts/drop.nml', drop_slide(), pi_2 + 0.3_wp, pi_2 - 0.3_wp, 0.9_wp, 0.0_wp, 12.0_wp)
  call ride_flight('inputs/ride/crest.nml', crest_slide(), 0.01_wp, 0.5_wp, 0.05_wp)
  call ride_flight('inputs/ride/jump.nml', jump_slide(), 0.002_wp, 0.6_wp, 0.2_wp)
  call sweep_demo_population()
  call sweep_template()
  call identify_water('inputs/design/identify_water_demo.nml')
  call identify_water('inputs/templates/identify_water.nml')   ! the same, every variable written
  call identify_rider_demo()
  call identify_rider_template()

contains

  ! ------------------------------------------------------------------ water

  !> inputs/water/demo_slide.nml: the &water of the demo ride, 13 stations,
  !> &solver duration 60 s.
  subroutine water_demo_slide()
    type(water_description_t) :: w
    w = demo_water(slide_of(demo_slide()))
    w%stations = [5.0_wp, 10.0_wp, 15.0_wp, 20.0_wp, 25.0_wp, 30.0_wp, 35.0_wp, 40.0_wp, 45.0_wp, 50.0_wp, &
                  55.0_wp, 60.0_wp, 65.0_wp]   ! m
    w%solver%time_bound = 60
    call run_water('inputs/water/demo_slide.nml', w)
  end subroutine water_demo_slide

  !> inputs/templates/water.nml: the demo slide's water with every variable
  !> written (builtin:demo_slide, beta0, mass, gravity, the stall and
  !> criticality bounds, the edges), six stations, no duration.
  subroutine water_template()
    type(water_description_t) :: w
    w = demo_water(slide_of(demo_slide()))
    w%start%beta = 0
    w%mass = 1
    w%gravity = [0.0_wp, 0.0_wp, -9.80665_wp]
    w%min_speed = 0.05_wp
    w%min_criticality = 0.02_wp
    w%stations = [10.0_wp, 20.0_wp, 30.0_wp, 40.0_wp, 50.0_wp, 60.0_wp]
    w%edges = .true.
    call run_water('inputs/templates/water.nml', w)
  end subroutine water_template

  !> inputs/water/two_inlets.nml: 3 l/s from the start of the demo slide,
  !> 2 l/s more joining at 25 m (speed 2 m/s, angle 0.2 rad); f1-f3, the
  !> correction and the table step the defaults.
  subroutine water_two_inlets()
    type(water_description_t) :: w
    w%slide = slide_of(demo_slide())
    w%flow_rate = 0.003_wp
    w%start%mode = START_EDGES
    w%start%u0 = 0
    w%start%v_left = 1.8707963267948966_wp
    w%start%v_right = 1.2707963267948966_wp
    w%stations = [20.0_wp, 30.0_wp, 40.0_wp]
    w%inlets = [water_inlet_t(arc_length=25.0_wp, flow_rate=0.002_wp, speed=2.0_wp, beta=0.2_wp)]
    w%solver%ode%method = ODE_ADAMS
    w%solver%ode%rtol = 1e-10_wp
    w%solver%ode%atol = 1e-9_wp
    w%solver%output_step = 0.005_wp
    call run_water('inputs/water/two_inlets.nml', w)
  end subroutine water_two_inlets

  !> inputs/design/second_slide_water.nml: 6 l/s on the second slide
  !> (design/second_slide.nml), eleven stations, &solver duration 60 s.
  subroutine water_second_slide()
    type(water_description_t) :: w
    w = demo_water(slide_of(second_slide()))
    w%flow_rate = 0.006_wp
    w%start%v_left = 1.9707963267948966_wp
    w%start%v_right = 1.1707963267948966_wp
    w%stations = [5.0_wp, 10.0_wp, 15.0_wp, 20.0_wp, 25.0_wp, 30.0_wp, 35.0_wp, 40.0_wp, 45.0_wp, 50.0_wp, 55.0_wp]
    w%solver%time_bound = 60
    call run_water('inputs/design/second_slide_water.nml', w)
  end subroutine water_second_slide

  !> The &water the demo inputs share (and their &water_solver / &solver
  !> method and tolerances, output every 5 ms) on `slide`.
  function demo_water(slide) result(w)
    type(tube_surface_t), intent(in) :: slide
    type(water_description_t) :: w
    w = parts_water(slide, 1.9207963267948966_wp, 1.2207963267948966_wp)
  end function demo_water

  !> The &water of the parts' rides (and the demo's): 4 l/s from the start
  !> edges v_left, v_right, f1-f3 of the thesis, the full correction, a
  !> table every 0.1 m, Adams at rtol 1e-10, atol 1e-9, output every 5 ms.
  function parts_water(slide, v_left, v_right) result(w)
    type(tube_surface_t), intent(in) :: slide
    real(wp), intent(in) :: v_left, v_right   ! rad
    type(water_description_t) :: w
    w%slide = slide
    w%flow_rate = 0.004_wp
    w%start%mode = START_EDGES
    w%start%u0 = 0
    w%start%v_left = v_left
    w%start%v_right = v_right
    w%f1 = 0.0274748_wp
    w%f2 = 0.138285_wp
    w%f3 = 0.979822_wp
    w%correction = CORRECTION_FULL
    w%table_step = 0.1_wp
    w%solver%ode%method = ODE_ADAMS
    w%solver%ode%rtol = 1e-10_wp
    w%solver%ode%atol = 1e-9_wp
    w%solver%output_step = 0.005_wp
  end function parts_water

  subroutine run_water(input, w)
    character(len=*), intent(in) :: input
    type(water_description_t), intent(in) :: w
    type(water_result_t) :: flow
    type(status_t) :: status
    call compute_water(w, flow, status)
    call stop_unless_ok(input, 'the water', status)
    call print_water(input, w, flow%series)
  end subroutine run_water

  ! ------------------------------------------------------------------ rides

  !> inputs/ride/demo_slide.nml (and its template): the demo water, the
  !> standard rider from u0 = 0.5 m at 1 m/s, limits on the exit speed, the
  !> speed and the lever arm; the fixture's tolerances.
  subroutine ride_demo_slide(input)
    character(len=*), intent(in) :: input
    type(ride_description_t) :: ride
    ride = standard_ride(demo_water(slide_of(demo_slide())), 0.5_wp, 1.0_wp)
    call loosen(ride)
    allocate (ride%limits(3))
    ride%limits(1) = upper_limit('exit_speed', 'm/s', 10.0_wp, ride%rider%gravity)
    ride%limits(2) = upper_limit('speed', 'm/s', 8.0_wp, ride%rider%gravity)
    ride%limits(3) = upper_limit('lever_arm', 'm', 0.25_wp, ride%rider%gravity)
    call ride_and_print(input, ride)
  end subroutine ride_demo_slide

  !> A part's ride (inputs/parts/*.nml): the parts' water from the start
  !> edges v_left, v_right on `slide`, the standard rider from u0 at speed0,
  !> limits on the exit speed (at most exit_max) and the speed (14 m/s); the
  !> fixture's tolerances.
  subroutine ride_part(input, slide, v_left, v_right, u0, speed0, exit_max)
    character(len=*), intent(in) :: input
    type(geometry_description_t), intent(in) :: slide
    real(wp), intent(in) :: v_left, v_right, u0, speed0, exit_max
    type(ride_description_t) :: ride
    ride = standard_ride(parts_water(slide_of(slide), v_left, v_right), u0, speed0)
    call loosen(ride)
    allocate (ride%limits(2))
    ride%limits(1) = upper_limit('exit_speed', 'm/s', exit_max, ride%rider%gravity)
    ride%limits(2) = upper_limit('speed', 'm/s', 14.0_wp, ride%rider%gravity)
    call ride_and_print(input, ride)
  end subroutine ride_part

  !> A ride that may fly (inputs/ride/crest.nml, jump.nml): water without the
  !> Saint-Venant correction from the default edges, the standard rider from
  !> 0.5 m at 1 m/s, output every `output_step` s, landings by the defaults
  !> (restitution 0, the rider's mu), limits on the airtime and the drop
  !> height; the inputs' own tolerances (the fixture runs them as given).
  subroutine ride_flight(input, slide, output_step, airtime_max, drop_max)
    character(len=*), intent(in) :: input
    type(geometry_description_t), intent(in) :: slide
    real(wp), intent(in) :: output_step, airtime_max, drop_max
    type(ride_description_t) :: ride
    type(water_description_t) :: water
    water = parts_water(slide_of(slide), pi_2 + 0.3_wp, pi_2 - 0.3_wp)
    water%correction = CORRECTION_OFF
    ride = standard_ride(water, 0.5_wp, 1.0_wp)
    ride%options%output_step = output_step
    ride%options%may_fly = .true.
    allocate (ride%limits(2))
    ride%limits(1) = upper_limit('airtime', 's', airtime_max, ride%rider%gravity)
    ride%limits(2) = upper_limit('drop_height', 'm', drop_max, ride%rider%gravity)
    call ride_and_print(input, ride)
  end subroutine ride_flight

  !> The rider every shipped ride has (thesis tables 4.8, 4.10: male, 68.5
  !> kg, 1.78 m, Coulomb mu_D, water drag on spheres of 0.5, 0.05, 0.5 m),
  !> starting on the bottom (v0 = pi/2) heading down the slide from u0 at
  !> speed0, in `water`; &solver as the inputs give it (Adams, rtol 1e-10,
  !> atol 1e-9, steps of at most 0.05 s, output every 0.01 s) and without a
  !> duration: ten times the slide at the stall speed (scenarios_ride).
  function standard_ride(water, u0, speed0) result(ride)
    type(water_description_t), intent(in) :: water
    real(wp), intent(in) :: u0, speed0
    type(ride_description_t) :: ride
    ride%water = water
    associate (p => ride%rider)
      p%body%sex = SEX_MALE
      p%body%mass = 68.5_wp
      p%body%height = 1.78_wp
      p%body%com_height = 0.075_wp
      p%friction = law_spec('coulomb', 'mu', 0.0724419_wp)
      p%drag = .true.
      p%drag_radius = [0.5_wp, 0.05_wp, 0.5_wp]
      p%u0 = u0
      p%v0 = pi_2
      p%heading0 = 0
      p%speed0 = speed0
    end associate
    ride%options%ode%method = ODE_ADAMS
    ride%options%ode%rtol = 1e-10_wp
    ride%options%ode%atol = 1e-9_wp
    ride%options%ode%max_step = 0.05_wp
    ride%options%output_step = 0.01_wp
    ride%options%min_speed = 0.05_wp
    ride%options%max_duration = 10*ride%water%slide%length()/ride%options%min_speed
  end function standard_ride

  !> The tolerances the fixture cli_every_input runs the demo ride, its
  !> template and the parts' rides with (rtol 1e-6, atol 1e-5).
  subroutine loosen(ride)
    type(ride_description_t), intent(inout) :: ride
    ride%options%ode%rtol = 1e-6_wp
    ride%options%ode%atol = 1e-5_wp
  end subroutine loosen

  subroutine ride_and_print(input, ride)
    character(len=*), intent(in) :: input
    type(ride_description_t), intent(in) :: ride
    type(ride_job_result_t) :: ridden
    ridden = run_ride(ride)
    call stop_unless_ok(input, 'the ride', ridden%status)
    call print_ride(input, ride, ridden)
  end subroutine ride_and_print

  ! ----------------------------------------------------------------- sweeps

  !> inputs/sweep/demo_population.nml: the demo ride's water and rider (sex,
  !> mass and height from each ride; the limits add the felt normal
  !> acceleration) over two riders (female 50 kg 1.60 m, male 100 kg 1.90 m,
  !> paired) crossed with two flow rates (4 and 6 l/s): the rides by
  !> design_sweep's sweep_rows, at the input's tolerances.
  subroutine sweep_demo_population()
    type(sweep_description_t) :: sweep
    type(swept_values_t) :: lists(N_SWEPT)
    logical :: together(N_SWEPT)
    call standard_sweep(sweep, lists)
    allocate (sweep%limits(4))
    sweep%limits(1) = upper_limit('exit_speed', 'm/s', 10.0_wp, sweep%rider%gravity)
    sweep%limits(2) = upper_limit('speed', 'm/s', 8.0_wp, sweep%rider%gravity)
    sweep%limits(3) = upper_limit('lever_arm', 'm', 0.25_wp, sweep%rider%gravity)
    sweep%limits(4) = upper_limit('acceleration_normal', 'g', 2.6_wp, sweep%rider%gravity)
    lists(V_SEX)%x = [real(SEX_FEMALE, wp), real(SEX_MALE, wp)]
    lists(V_MASS)%x = [50.0_wp, 100.0_wp]
    lists(V_HEIGHT)%x = [1.60_wp, 1.90_wp]
    lists(V_FLOW_RATE)%x = [0.004_wp, 0.006_wp]
    together = .false.
    together([V_SEX, V_MASS, V_HEIGHT]) = .true.
    sweep%values = sweep_rows(lists, together)
    call sweep_and_print('inputs/sweep/demo_population.nml', sweep)
  end subroutine sweep_demo_population

  !> inputs/templates/sweep.nml: the demo ride with every variable written,
  !> two riders (male 75 kg 1.80 m, female 55 kg 1.65 m, paired), its three
  !> limits.
  subroutine sweep_template()
    type(sweep_description_t) :: sweep
    type(swept_values_t) :: lists(N_SWEPT)
    logical :: together(N_SWEPT)
    call standard_sweep(sweep, lists)
    allocate (sweep%limits(3))
    sweep%limits(1) = upper_limit('exit_speed', 'm/s', 10.0_wp, sweep%rider%gravity)
    sweep%limits(2) = upper_limit('speed', 'm/s', 8.0_wp, sweep%rider%gravity)
    sweep%limits(3) = upper_limit('lever_arm', 'm', 0.25_wp, sweep%rider%gravity)
    lists(V_SEX)%x = [real(SEX_MALE, wp), real(SEX_FEMALE, wp)]
    lists(V_MASS)%x = [75.0_wp, 55.0_wp]
    lists(V_HEIGHT)%x = [1.80_wp, 1.65_wp]
    together = .false.
    together([V_SEX, V_MASS, V_HEIGHT]) = .true.
    sweep%values = sweep_rows(lists, together)
    call sweep_and_print('inputs/templates/sweep.nml', sweep)
  end subroutine sweep_template

  !> The base ride of both sweeps: the demo ride (its water, the standard
  !> rider, the inputs' tolerances, no progress lines) and every swept
  !> variable's one value where not swept, as scenarios_sweep takes them
  !> (heading in degrees).
  subroutine standard_sweep(sweep, lists)
    type(sweep_description_t), intent(out) :: sweep
    type(swept_values_t), intent(out) :: lists(N_SWEPT)
    type(ride_description_t) :: ride
    ride = standard_ride(demo_water(slide_of(demo_slide())), 0.5_wp, 1.0_wp)
    sweep%water = ride%water
    sweep%rider = ride%rider
    sweep%options = ride%options
    sweep%options%progress_seconds = 0
    lists(V_SEX)%x = [real(SEX_MALE, wp)]
    lists(V_MASS)%x = [68.5_wp]
    lists(V_HEIGHT)%x = [1.78_wp]
    lists(V_MU)%x = [0.0724419_wp]
    lists(V_U0)%x = [0.5_wp]
    lists(V_V0)%x = [pi_2]
    lists(V_HEADING)%x = [0.0_wp]
    lists(V_SPEED)%x = [1.0_wp]
    lists(V_FLOW_RATE)%x = [0.004_wp]
    lists(V_F1)%x = [0.0274748_wp]
    lists(V_F2)%x = [0.138285_wp]
    lists(V_F3)%x = [0.979822_wp]
  end subroutine standard_sweep

  !> A limit on the largest `quantity` (a ride's or a sweep's), felt
  !> accelerations in multiples of |gravity|.
  function upper_limit(quantity, unit, maximum, gravity) result(limit)
    character(len=*), intent(in) :: quantity, unit
    real(wp), intent(in) :: maximum, gravity(3)
    type(ride_limit_t) :: limit
    character(len=:), allocatable :: problem
    call new_ride_limit(quantity, unit, 0.0_wp, .false., maximum, .true., norm2(gravity), limit, problem)
    if (len(problem) > 0) then
      print '(a)', 'limit '//quantity//': '//problem
      error stop 1
    end if
  end function upper_limit

  !> Runs every ride of `sweep` in one thread (the rides are the same in any
  !> number: docs/sweep.md) and prints the summary's counts and each ride's
  !> figures as `rides.<ride>.<figure>` (the CSV's row and column).
  subroutine sweep_and_print(input, sweep)
    character(len=*), intent(in) :: input
    type(sweep_description_t), intent(in) :: sweep
    type(sweep_result_t) :: result
    integer, allocatable :: group(:), first(:)
    integer :: i, k
    call run_sweep(sweep, [(.true., i = 1, size(sweep%values, 2))], 1, result)
    call water_groups(sweep%values, group, first)
    call put(input, 'rides', real(result%n, wp))
    call put(input, 'complete', real(count(result%status == RIDE_COMPLETE), wp))
    call put(input, 'waters', real(size(first), wp))
    call put(input, 'rides_over_limit', real(count(any(result%verdict == 1, dim=1)), wp))
    do i = 1, result%n
      if (result%status(i) /= RIDE_COMPLETE) then
        print '(a)', 'FAIL '//input//': ride '//format_integer(i)//': '//trim(result%message(i))
        error stop 1
      end if
      call put(input, 'rides.'//format_integer(i)//'.water_group', real(result%water_group(i), wp))
      do k = 1, N_FIGURES
        call put(input, 'rides.'//format_integer(i)//'.'//trim(figure_names(k)), result%figures(k, i))
      end do
    end do
  end subroutine sweep_and_print

  ! --------------------------------------------------------- identification

  !> inputs/design/identify_water_demo.nml (and its template): f1, f2, f3
  !> of a twin experiment on the demo slide: the measurements synthesised
  !> with table 4.3's f at 12 sections and on 3 segments, the fit started
  !> 50 % off (the &water's f), weight 0.8, k1 1, all three estimated, lower
  !> bounds 0, the thesis's midpoint speed and edges' middle, LMDER at ftol
  !> and xtol 1e-8, one thread; Adams at rtol 1e-10, atol 1e-9 (thesis C.4).
  subroutine identify_water(input)
    character(len=*), intent(in) :: input
    type(water_identification_t) :: setup
    type(water_fit_options_t) :: options
    type(water_fit_t) :: fit
    type(status_t) :: status
    real(wp), parameter :: twin_f(3) = [0.0274748_wp, 0.138285_wp, 0.979822_wp]
    integer :: k
    setup%water = demo_water(slide_of(demo_slide()))
    setup%water%f1 = 0.0412122_wp
    setup%water%f2 = 0.0691425_wp
    setup%water%f3 = 1.469733_wp
    setup%ode%method = ODE_ADAMS
    setup%ode%rtol = 1e-10_wp
    setup%ode%atol = 1e-9_wp
    associate (d => setup%data)
      d%section_arc_length = [5.0_wp, 10.0_wp, 15.0_wp, 20.0_wp, 25.0_wp, 30.0_wp, 35.0_wp, 40.0_wp, 45.0_wp, &
                              50.0_wp, 55.0_wp, 60.0_wp]
      d%segment_start = [10.0_wp, 30.0_wp, 50.0_wp]
      d%segment_end = [12.0_wp, 32.0_wp, 52.0_wp]
      allocate (d%section_v(size(d%section_arc_length)), d%segment_speed(size(d%segment_start)))
      d%section_v = 0
      d%segment_speed = 0
    end associate
    setup%threads = 1
    options%weight = 0.8_wp
    options%k1 = 1
    options%estimate = .true.
    options%lower = 0
    options%solver%ftol = 1e-8_wp
    options%solver%xtol = 1e-8_wp
    call new_water_identification(setup, status)
    call stop_unless_ok(input, 'the identification', status)
    call simulate_measurements(setup, twin_f, setup%data%section_v, setup%data%segment_speed, status)
    call stop_unless_ok(input, 'the twin measurements', status)
    call fit_water_friction(setup, options, [setup%water%f1, setup%water%f2, setup%water%f3], fit, status)
    call stop_unless_ok(input, 'the fit', status)
    do k = 1, 3
      call put(input, 'f'//format_integer(k), fit%f(k))
      call put(input, 'f'//format_integer(k)//'_standard_error', fit%standard_error(k))
    end do
    call put(input, 'correlation_12', fit%correlation(1, 2))
    call put(input, 'correlation_13', fit%correlation(1, 3))
    call put(input, 'correlation_23', fit%correlation(2, 3))
    call put(input, 'cost', fit%cost)
    call put(input, 'position_part', fit%position_part)
    call put(input, 'speed_part', fit%speed_part)
    call put(input, 'rmse_position', fit%rmse_position)
    call put(input, 'rmse_speed', fit%rmse_speed)
    call put(input, 'evaluations', real(fit%evaluations, wp))
    do k = 1, size(fit%error_v)
      call put(input, 'sections.'//format_integer(k)//'.arc_length', setup%data%section_arc_length(k))
      call put(input, 'sections.'//format_integer(k)//'.error', fit%error_v(k))
    end do
  end subroutine identify_water

  !> inputs/design/identify_rider_demo.nml: mu_D from the measurements of
  !> inputs/design/rider_stations.csv and rider_segments.csv (read here by
  !> plain Fortran), the fit started at 0.036, weight 0.0932, bounds 0 and
  !> 0.11, LMDER at ftol and xtol 1e-6, two threads; then the body-parameter
  !> study of thesis table 4.10 at the identified mu_D (the ten variants of
  !> design_rider_identification's body_variants). No &solver: the ride's
  !> defaults; no &water_solver: the water at the solver's defaults (rtol
  !> 1e-10, atol 1e-10, output every 0.01 s).
  subroutine identify_rider_demo()
    character(len=*), parameter :: input = 'inputs/design/identify_rider_demo.nml'
    type(rider_identification_t) :: setup
    type(rider_fit_options_t) :: options
    type(rider_params_t) :: variants(10)
    type(status_t) :: statuses(10), status
    real(wp) :: deviation(10)
    real(wp), allocatable :: table(:, :)
    type(rider_fit_t) :: fit
    integer :: k
    call identification_rider(setup)
    table = csv_numbers('inputs/design/rider_stations.csv', 4)
    setup%data%station_arc_length = table(1, :)
    setup%data%angle = table(2:4, :)
    table = csv_numbers('inputs/design/rider_segments.csv', 3)
    setup%data%segment_start = table(1, :)
    setup%data%segment_end = table(2, :)
    setup%data%segment_speed = table(3, :)
    setup%threads = 2
    options%weight = 0.0932_wp
    options%lower = 0
    options%upper = 0.11_wp
    options%solver%ftol = 1e-6_wp
    options%solver%xtol = 1e-6_wp
    call identification_water(input, setup)
    call fit_rider_friction(setup, options, 0.036_wp, fit, status)
    call stop_unless_ok(input, 'the fit', status)
    call print_rider_fit(input, setup, fit)
    call set_rider_mu(setup%params, fit%mu)
    variants = body_variants(setup%params)
    call rider_body_sensitivity(setup, variants, deviation, statuses, status)
    call stop_unless_ok(input, 'the body-parameter study', status)
    do k = 1, 10
      call stop_unless_ok(input, 'variant '//format_integer(k), statuses(k))
      call put(input, 'deviation_'//format_integer(k), deviation(k))
    end do
  end subroutine identify_rider_demo

  !> inputs/templates/identify_rider.nml: a twin experiment (the angles and
  !> speeds simulated with mu_D = 0.0724419) at five stations and two
  !> segments, the fit started at 0.036, weight 0.6, k2 1, bounds 0 and
  !> 0.11, LMDER at 1e-8, one thread; &water_solver as the demo ride's.
  subroutine identify_rider_template()
    character(len=*), parameter :: input = 'inputs/templates/identify_rider.nml'
    type(rider_identification_t) :: setup
    type(rider_fit_options_t) :: options
    type(rider_params_t) :: twin
    type(rider_stations_t) :: simulated
    type(rider_fit_t) :: fit
    type(status_t) :: status
    call identification_rider(setup)
    setup%data%station_arc_length = [2.5_wp, 4.375_wp, 6.25_wp, 8.125_wp, 10.0_wp]
    allocate (setup%data%angle(3, 5))
    setup%data%angle = 0
    setup%data%segment_start = [3.0_wp, 6.5_wp]
    setup%data%segment_end = [5.0_wp, 8.5_wp]
    setup%data%segment_speed = [0.0_wp, 0.0_wp]
    setup%threads = 1
    options%weight = 0.6_wp
    options%k2 = 1
    options%lower = 0
    options%upper = 0.11_wp
    options%solver%ftol = 1e-8_wp
    options%solver%xtol = 1e-8_wp
    call identification_water(input, setup, demo_water(slide_of(demo_slide())))
    twin = setup%params
    call set_rider_mu(twin, 0.0724419_wp)
    call simulate_rider(setup, twin, simulated, status)
    call stop_unless_ok(input, 'the twin measurements', status)
    setup%data%angle = simulated%angle
    setup%data%segment_speed = simulated%segment_speed
    call fit_rider_friction(setup, options, 0.036_wp, fit, status)
    call stop_unless_ok(input, 'the fit', status)
    call print_rider_fit(input, setup, fit)
  end subroutine identify_rider_template

  !> The rider both identifications measure: the standard rider on the
  !> bottom from 0.5 m at 1 m/s, its friction's start mu 0.036, the ride's
  !> default integration (no &solver) and its safety bound on the duration.
  subroutine identification_rider(setup)
    type(rider_identification_t), intent(out) :: setup
    type(ride_description_t) :: ride
    ride = standard_ride(demo_water(slide_of(demo_slide())), 0.5_wp, 1.0_wp)
    allocate (setup%slide, source=ride%water%slide)
    setup%params = ride%rider
    setup%params%friction = law_spec('coulomb', 'mu', 0.036_wp)
    setup%options%max_duration = 10*setup%slide%length()/setup%options%min_speed
    setup%with_water = .true.
  end subroutine identification_rider

  !> The setup's derived places, then its water (`water`, or the demo
  !> slide's &water at the solver's defaults) as the drag's field.
  subroutine identification_water(input, setup, water)
    character(len=*), intent(in) :: input
    type(rider_identification_t), intent(inout) :: setup
    type(water_description_t), intent(in), optional :: water
    type(water_description_t) :: w
    type(water_result_t) :: computed
    type(status_t) :: status
    call new_rider_identification(setup, status)
    call stop_unless_ok(input, 'the identification', status)
    if (present(water)) then
      w = water
    else
      w = demo_water(slide_of(demo_slide()))
      w%solver%ode%atol = 1e-10_wp
      w%solver%output_step = 0.01_wp
    end if
    call compute_water(w, computed, status)
    call stop_unless_ok(input, 'the water', status)
    setup%water = computed%field
  end subroutine identification_water

  !> The summary's numbers of a rider identification (scenarios_identify_rider).
  subroutine print_rider_fit(input, setup, fit)
    character(len=*), intent(in) :: input
    type(rider_identification_t), intent(in) :: setup
    type(rider_fit_t), intent(in) :: fit
    character(len=*), parameter :: errors(3) = [character(len=12) :: 'error_pelvis', 'error_heels', 'error_back']
    character(len=:), allocatable :: row
    integer :: k, c
    call put(input, 'mu', fit%mu)
    call put(input, 'standard_error', fit%standard_error)
    call put(input, 'cost', fit%cost)
    call put(input, 'position_part', fit%position_part)
    call put(input, 'speed_part', fit%speed_part)
    do c = 1, N_CONTACTS
      call put(input, 'rmse_'//trim(contact_names(c)), fit%rmse_angle(c))
    end do
    call put(input, 'rmse_speed', fit%rmse_speed)
    call put(input, 'evaluations', real(fit%evaluations, wp))
    do k = 1, size(setup%data%station_arc_length)
      row = 'stations.'//format_integer(k)//'.'
      call put(input, row//'arc_length', setup%data%station_arc_length(k))
      do c = 1, 3
        call put(input, row//trim(errors(c)), fit%error_angle(c, k))
      end do
      call put(input, row//'rmse', fit%station_rmse(k))
    end do
  end subroutine print_rider_fit

  !> The numbers of a CSV file of `columns` columns (lines after the
  !> comments and the header), columns x rows.
  function csv_numbers(path, columns) result(table)
    character(len=*), intent(in) :: path
    integer, intent(in) :: columns
    real(wp), allocatable :: table(:, :)
    character(len=512) :: line
    real(wp) :: rows(columns, 10000)
    integer :: unit, n, outcome
    n = 0
    open (newunit=unit, file=path, status='old', action='read')
    do
      read (unit, '(a)', iostat=outcome) line
      if (outcome /= 0) exit
      line = adjustl(line)
      if (len_trim(line) == 0 .or. line(1:1) == '#' .or. verify(line(1:1), '0123456789-+.') /= 0) cycle
      n = n + 1
      read (line, *) rows(:, n)
    end do
    close (unit)
    table = rows(:, :n)
  end function csv_numbers

  ! --------------------------------------------------------------- building

  !> The tube of a slide description (build_slide, as build_geometry builds
  !> a &geometry kind = 'slide').
  function slide_of(d) result(slide)
    type(geometry_description_t), intent(in) :: d
    type(tube_surface_t) :: slide
    type(status_t) :: status
    call build_slide(d%slide, slide, status)
    call stop_unless_ok('a slide', 'its build', status)
  end function slide_of

  ! --------------------------------------------------------------- printing

  !> The water's summary numbers (scenarios_water's print_summary).
  subroutine print_water(input, w, s)
    character(len=*), intent(in) :: input
    type(water_description_t), intent(in) :: w
    type(water_series_t), intent(in) :: s
    integer :: n, i
    character(len=:), allocatable :: row
    n = s%n
    call put(input, 'slide_length', w%slide%length())
    call put(input, 'flow_rate', s%flow_rate)
    if (allocated(s%inlets)) then
      if (size(s%inlets) > 0) then
        call put(input, 'inlets_joined', real(count(s%inlets%joined), wp))
        call put(input, 'final_flow_rate', s%flow(n))
      end if
    end if
    call put(input, 'flow_time', s%time(n))
    call put(input, 'slide_length_covered', s%arc_length(n) - s%arc_length(1))
    call put(input, 'speed_min', minval(s%speed(:n)))
    call put(input, 'speed_max', maxval(s%speed(:n)))
    call put(input, 'final_speed', s%speed(n))
    call put(input, 'height_min', minval(s%height(:n)))
    call put(input, 'height_max', maxval(s%height(:n)))
    call put(input, 'width_min', minval(s%width(:n)))
    call put(input, 'width_max', maxval(s%width(:n)))
    call put(input, 'flow_angle_min', minval(s%beta(:n)))
    call put(input, 'flow_angle_max', maxval(s%beta(:n)))
    call put(input, 'v_min', minval(s%v(:n)))
    call put(input, 'v_max', maxval(s%v(:n)))
    call put(input, 'steps', real(s%stats%steps, wp))
    call put(input, 'rhs_evaluations', real(s%stats%rhs_evaluations, wp))
    do i = 1, size(s%stations)
      row = 'stations.'//format_integer(i)//'.'
      associate (st => s%stations(i))
        call put(input, row//'arc_length', st%arc_length)
        call put(input, row//'time', st%time)
        call put(input, row//'v_middle', st%v_middle)
        call put(input, row//'v_right', st%v_right)
        call put(input, row//'v_left', st%v_left)
        call put(input, row//'speed', st%speed)
        call put(input, row//'height', st%height)
        call put(input, row//'width', st%width)
        call put(input, row//'u', st%u)
        call put(input, row//'reached', merge(1.0_wp, 0.0_wp, st%reached))
      end associate
    end do
  end subroutine print_water

  !> The ride's summary numbers (scenarios_ride's print_report, the same
  !> rounding-noise rules: felt g on 1 g, normal forces on the ride's
  !> largest, the lever arm on the rider's size, a wall climb within the
  !> closure's tolerance of the bottom as 0).
  subroutine print_ride(input, ride, result)
    character(len=*), intent(in) :: input
    type(ride_description_t), intent(in) :: ride
    type(ride_job_result_t), intent(in) :: result
    character(len=*), parameter :: axis(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    real(wp), parameter :: closure_tolerance = 1e-10_wp   ! m (scenarios_ride's `unresolved`)
    character(len=:), allocatable :: c
    real(wp) :: force_scale
    integer :: k
    call put(input, 'slide_length', ride%water%slide%length())
    associate (r => result%report, s => result%ride%series)
      call put(input, 'ride_time', r%ride_time)
      call put(input, 'distance', r%distance)
      call put(input, 'top_speed', r%top_speed)
      call put(input, 'top_speed_arc_length', r%top_speed_at)
      do k = 1, 3
        call put(input, 'felt_'//trim(axis(k))//'_max', noise_free(r%felt_max(k), 1.0_wp))
        call put(input, 'felt_'//trim(axis(k))//'_max_arc_length', r%felt_max_at(k))
        call put(input, 'felt_'//trim(axis(k))//'_min', noise_free(r%felt_min(k), 1.0_wp))
        call put(input, 'felt_'//trim(axis(k))//'_min_arc_length', r%felt_min_at(k))
      end do
      force_scale = max(maxval([(abs(s%contact(k)%normal_force(:r%n)), k = 1, N_CONTACTS)]), tiny(1.0_wp))
      do k = 1, N_CONTACTS
        c = trim(contact_names(k))
        call put(input, c//'_wall_angle', merge(0.0_wp, r%climb_angle(k), &
                                                abs(r%climb_distance(k)) < closure_tolerance))
        call put(input, c//'_wall_arc_length', r%climb_at(k))
        call put(input, c//'_wall_distance', merge(0.0_wp, r%wall_distance_max(k), &
                                                   abs(r%wall_distance_max(k)) < closure_tolerance))
        call put(input, c//'_wall_distance_arc_length', r%wall_distance_at(k))
        call put(input, c//'_normal_force_min', noise_free(r%normal_min(k), force_scale))
        call put(input, c//'_normal_force_min_arc_length', r%normal_min_at(k))
      end do
      call put(input, 'lever_arm_max', noise_free(r%lever_max, rider_size))
      call put(input, 'lever_arm_max_arc_length', r%lever_max_at)
      if (result%complete) then
        call put(input, 'exit_speed', r%final_speed)
      else
        call put(input, 'final_speed', r%final_speed)
      end if
      if (result%ride%flights%watched) then
        call put(input, 'felt_not_judged_time', r%not_judged_time)
        call put_flights(input, result%ride%flights, highest=.true.)
      end if
      call put(input, 'limits_exceeded', real(count(r%judged .and. r%verdicts%exceeded), wp))
    end associate
    call put(input, 'ride_steps', real(result%ride%driver%stats%steps, wp))
  end subroutine print_ride
end program library_without_io
