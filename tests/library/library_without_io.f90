!> The shipped water and ride inputs (inputs/water/demo_slide.nml,
!> inputs/ride/demo_slide.nml) run through the library alone: the demo slide
!> built by geometry_slide_builder, the water by water_run, the ride by
!> design_ride_job, every description filled here in code from the values
!> those files (and inputs/demo_slide/slide.nml) give. No io module is linked
!> (tests/CMakeLists.txt links slidesim_design only). Prints "scenario key
!> value" lines with the summary's keys and its number texts (format_real,
!> as --summary-json writes them); tests/library/library_without_io.sh
!> compares them with the command's runs of the same inputs. Exit status 1
!> when a build or a run fails.
program library_without_io
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_text, only: format_real
  use numerics_ode, only: ODE_ADAMS
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: slide_description_t, section_part_description_t, build_slide
  use geometry_tube, only: tube_surface_t
  use water_flow, only: water_series_t, START_EDGES
  use water_streamline, only: CORRECTION_FULL
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_body, only: SEX_MALE
  use kinetostatics_force_law_factory, only: law_spec
  use design_ride_evaluation, only: new_ride_limit
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  implicit none (type, external)
  type(tube_surface_t) :: slide
  type(water_description_t) :: water
  type(water_result_t) :: flow
  type(ride_description_t) :: ride
  type(ride_job_result_t) :: ridden
  type(status_t) :: status

  call build_demo_slide(slide, status)
  call stop_unless_ok('the demo slide')

  ! ---- inputs/water/demo_slide.nml
  water = demo_water(slide)
  water%stations = [5.0_wp, 10.0_wp, 15.0_wp, 20.0_wp, 25.0_wp, 30.0_wp, 35.0_wp, 40.0_wp, 45.0_wp, 50.0_wp, &
                    55.0_wp, 60.0_wp, 65.0_wp]   ! m
  water%solver%output_step = 0.005_wp
  water%solver%time_bound = 60                           ! &solver duration (s)
  call compute_water(water, flow, status)
  call stop_unless_ok('the water')
  call print_water(water, flow%series)

  ! ---- inputs/ride/demo_slide.nml, with the tolerances the runs of every
  ! input give it (tests/cli/support/every_input.sh: rtol 1e-6, atol 1e-5)
  ride%water = demo_water(slide)
  ride%water%solver%output_step = 0.005_wp
  associate (p => ride%rider)
    p%body%sex = SEX_MALE
    p%body%mass = 68.5_wp
    p%body%height = 1.78_wp
    p%body%com_height = 0.075_wp
    p%friction = law_spec('coulomb', 'mu', 0.0724419_wp)
    p%drag = .true.
    p%drag_radius = [0.5_wp, 0.05_wp, 0.5_wp]
    p%u0 = 0.5_wp
    p%v0 = 1.5707963267948966_wp
    p%heading0 = 0
    p%speed0 = 1
  end associate
  ride%options%ode%method = ODE_ADAMS
  ride%options%ode%rtol = 1e-6_wp
  ride%options%ode%atol = 1e-5_wp
  ride%options%ode%max_step = 0.05_wp
  ride%options%output_step = 0.01_wp
  ride%options%min_speed = 0.05_wp
  ! without &solver duration: ten times the slide at the stall speed (scenarios_ride)
  ride%options%max_duration = 10*slide%length()/ride%options%min_speed
  allocate (ride%limits(3))
  call add_limit(1, 'exit_speed', 'm/s', 10.0_wp)
  call add_limit(2, 'speed', 'm/s', 8.0_wp)
  call add_limit(3, 'lever_arm', 'm', 0.25_wp)
  ridden = run_ride(ride)
  status = ridden%status
  call stop_unless_ok('the ride')
  call print_ride(slide, ridden)

contains

  !> inputs/demo_slide/slide.nml: eight elements, a circle of 0.5 m.
  subroutine build_demo_slide(slide, status)
    type(tube_surface_t), intent(out) :: slide
    type(status_t), intent(inout) :: status
    type(slide_description_t) :: d
    d%kind = 'slide'
    d%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%elements%heading_deg = 0
    d%elements%transition_length = 2
    d%elements%elements = [ &
      slide_element_t(kind='straight', length=6, slope_deg=12, direction='left'), &
      slide_element_t(kind='curve', slope_deg=6, radius=5, angle_deg=90, direction='left'), &
      slide_element_t(kind='straight', length=4, slope_deg=8, direction='left'), &
      slide_element_t(kind='helix', radius=4, direction='right', turns=1, drop=2.5_wp), &
      slide_element_t(kind='straight', length=3, slope_deg=7, direction='left'), &
      slide_element_t(kind='curve', slope_deg=6, radius=6, angle_deg=60, direction='left'), &
      slide_element_t(kind='curve', slope_deg=6, radius=6, angle_deg=60, direction='right'), &
      slide_element_t(kind='runout', length=8, slope_deg=1, direction='left')]
    d%section%parts = [section_part_description_t(kind='circle', radius=0.5_wp)]
    call build_slide(d, slide, status)
  end subroutine build_demo_slide

  !> The &water of both inputs (and their &water_solver / &solver tolerances).
  function demo_water(slide) result(w)
    type(tube_surface_t), intent(in) :: slide
    type(water_description_t) :: w
    w%slide = slide
    w%flow_rate = 0.004_wp
    w%start%mode = START_EDGES
    w%start%u0 = 0
    w%start%v_left = 1.9207963267948966_wp
    w%start%v_right = 1.2207963267948966_wp
    w%f1 = 0.0274748_wp
    w%f2 = 0.138285_wp
    w%f3 = 0.979822_wp
    w%correction = CORRECTION_FULL
    w%table_step = 0.1_wp
    w%solver%ode%method = ODE_ADAMS
    w%solver%ode%rtol = 1e-10_wp
    w%solver%ode%atol = 1e-9_wp
  end function demo_water

  subroutine add_limit(k, quantity, unit, maximum)
    integer, intent(in) :: k
    character(len=*), intent(in) :: quantity, unit
    real(wp), intent(in) :: maximum
    character(len=:), allocatable :: problem
    call new_ride_limit(quantity, unit, 0.0_wp, .false., maximum, .true., norm2(ride%rider%gravity), &
                        ride%limits(k), problem)
    if (len(problem) > 0) then
      print '(a)', 'limit '//quantity//': '//problem
      error stop 1
    end if
  end subroutine add_limit

  subroutine stop_unless_ok(what)
    character(len=*), intent(in) :: what
    if (status%ok()) return
    print '(a)', what//': '//status%text()
    error stop 1
  end subroutine stop_unless_ok

  subroutine put(scenario, key, x)
    character(len=*), intent(in) :: scenario, key
    real(wp), intent(in) :: x
    print '(a)', scenario//' '//key//' '//format_real(x)
  end subroutine put

  subroutine print_water(w, s)
    type(water_description_t), intent(in) :: w
    type(water_series_t), intent(in) :: s
    integer :: n
    n = s%n
    call put('water', 'slide_length', w%slide%length())
    call put('water', 'flow_rate', s%flow_rate)
    call put('water', 'flow_time', s%time(n))
    call put('water', 'slide_length_covered', s%arc_length(n) - s%arc_length(1))
    call put('water', 'speed_min', minval(s%speed(:n)))
    call put('water', 'speed_max', maxval(s%speed(:n)))
    call put('water', 'final_speed', s%speed(n))
    call put('water', 'height_min', minval(s%height(:n)))
    call put('water', 'height_max', maxval(s%height(:n)))
    call put('water', 'width_min', minval(s%width(:n)))
    call put('water', 'width_max', maxval(s%width(:n)))
    call put('water', 'flow_angle_min', minval(s%beta(:n)))
    call put('water', 'flow_angle_max', maxval(s%beta(:n)))
  end subroutine print_water

  subroutine print_ride(slide, result)
    type(tube_surface_t), intent(in) :: slide
    type(ride_job_result_t), intent(in) :: result
    character(len=*), parameter :: axis(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    integer :: k
    call put('ride', 'slide_length', slide%length())
    associate (r => result%report)
      call put('ride', 'ride_time', r%ride_time)
      call put('ride', 'distance', r%distance)
      call put('ride', 'top_speed', r%top_speed)
      call put('ride', 'top_speed_arc_length', r%top_speed_at)
      do k = 1, 3
        call put('ride', 'felt_'//trim(axis(k))//'_max', r%felt_max(k))
        call put('ride', 'felt_'//trim(axis(k))//'_min', r%felt_min(k))
      end do
      call put('ride', 'lever_arm_max', r%lever_max)
      call put('ride', 'lever_arm_max_arc_length', r%lever_max_at)
      if (result%complete) then
        call put('ride', 'exit_speed', r%final_speed)
      else
        call put('ride', 'final_speed', r%final_speed)
      end if
    end associate
  end subroutine print_ride
end program library_without_io
