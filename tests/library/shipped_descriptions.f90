!> The shipped inputs of the contact, point-mass, pendulum, four-bar and sled
!> scenarios (the sled's vehicles: library_vehicle.f90), built through the library WITHOUT io
!> (issue 24 point 2; the inputs this program builds are those
!> tests/library/built_through_library.txt gives it, the ones no test builds
!> yet are listed in tests/library/not_yet_through_library.txt, both checked
!> by check_library_coverage.py): the
!> descriptions are filled here by hand from the shipped files (each case
!> names its file; the values are copied from it, the defaults not given
!> there are the types' own), built by their layers (build_contact_model,
!> build_point_mass_model, build_pendulum_model, build_fourbar_model,
!> build_sled_model; the flights by build_flight, build_bodies_opening or
!> flight_after_closed) and run over
!> `duration` s with the input's solver settings, as the command runs them
!> (scenarios_mechanism, scenarios_point_mass, scenarios_contact,
!> scenarios_sled: the same start checks, driver and options).
!>
!> This program links no io module (tests/CMakeLists.txt links it against
!> the rider layer and the layers below it only: a `use io_...` here does
!> not compile). It prints one line per number, `<input> <summary key>
!> <value>`, under the keys the command's --summary-json uses (a table's
!> as `<table>.<row>.<column>`); the wrapper
!> tests/library/compare_shipped.py runs slidesim on each input with
!> `--set solver%duration=<duration>` and compares.
!>
!> Usage: shipped_descriptions DURATION   (a flight runs over its input's
!> own duration and prints it, `<input> duration <seconds>`, first)
program shipped_descriptions
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_text, only: format_integer
  use base_spec, only: spec_t
  use base_vector, only: rotation_xyz
  use numerics_ode, only: ODE_ADAMS, ODE_BDF
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive
  use geometry_surface, only: surface_t
  use geometry_surface_factory, only: surface_from_spec
  use geometry_surface_description, only: surface_description_t, build_surface
  use geometry_slide_builder, only: section_part_description_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_tube, only: tube_surface_t
  use geometry_slide_builder, only: build_slide
  use geometry_description, only: geometry_description_t, build_geometry
  use kinetostatics_force_law_factory, only: law_spec
  use kinetostatics_point_mass, only: point_mass_t, point_mass_description_t, build_point_mass_model
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: pendulum_description_t, fourbar_description_t, sled_description_t, &
    build_pendulum_model, build_fourbar_model, build_sled_model
  use contact_model, only: contact_system_t, contact_model_t, contact_spec_t, body_spec_t, shape_t, &
    build_contact_model, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t, build_flight, check_flight_system, carrying_contact, closed_part
  use contact_closing, only: drive_flight, flight_after_closed
  use contact_bodies, only: build_bodies_opening, start_carriers
  use shipped_slides, only: demo_slide_description => demo_slide
  use library_lines, only: put, put_count, expect_ok, failures
  implicit none (type, external)

  !> Runaway guard of the command's multibody and point-mass runs
  !> (scenarios_mechanism, scenarios_point_mass min_mean_step).
  real(wp), parameter :: min_mean_step = 1e-4_wp
  real(wp) :: duration
  character(len=64) :: argument

  call get_command_argument(1, argument)
  read (argument, *) duration
  call pendulum_simple()
  call pendulum_double()
  call fourbar_crank_rocker('inputs/fourbar/crank_rocker.nml')
  call fourbar_crank_rocker('inputs/templates/fourbar.nml')   ! the same four-bar, every variable written
  call pendulum_template()
  call sled_bowl()
  call sled_bowl_friction()
  call sled_demo_slide()
  call sled_incline_coulomb()
  call sled_template()
  call point_mass_apex_paraboloid()
  call point_mass_ellipsoid()
  call point_mass_elliptic_cylinder()
  call point_mass_elliptic_paraboloid()
  call point_mass_hyperbolic_paraboloid()
  call point_mass_plane_coulomb()
  call point_mass_incline_drag()
  call point_mass_template()
  call point_mass_bowl()
  call point_mass_halfpipe()
  call point_mass_demo_slide()
  call contact_egg('inputs/contact/egg.nml', [0.025_wp, 0.033_wp, 0.025_wp], [-90.0_wp, 0.0_wp, -103.0_wp])
  call contact_egg('inputs/contact/egg_long_axis_z.nml', [0.025_wp, 0.025_wp, 0.033_wp], [77.0_wp, 0.0_wp, 0.0_wp])
  ! the egg of inputs/contact/egg.nml with every variable written out (gravity: the default)
  call contact_egg('inputs/templates/contact.nml', [0.025_wp, 0.033_wp, 0.025_wp], [-90.0_wp, 0.0_wp, -103.0_wp])
  call contact_ball_in_cone()
  call contact_paraboloids()
  call contact_tower5()
  call contact_bouncing_ball()
  call contact_ball_drop_drag()
  call contact_two_balls()
  call contact_dome(.false.)
  call contact_dome(.true.)
  call contact_loop()
  call contact_roll_beside_bounce()
  call contact_stacked_balls()
  call contact_falling_pair()
  call contact_box_landing()
  call contact_ball_on_cart()
  call contact_ladder()
  if (failures > 0) error stop 1

contains

  ! ---------------------------------------------------------------- pendulum, four-bar

  subroutine pendulum_simple()
    type(pendulum_description_t) :: d
    d%params%links = 1
    d%params%length(1) = 1.0_wp
    d%params%mass(1) = 1.0_wp
    d%theta0(1) = 0.5_wp
    call run_pendulum('inputs/pendulum/simple.nml', d)
  end subroutine pendulum_simple

  subroutine pendulum_double()
    type(pendulum_description_t) :: d
    d%params%links = 2
    d%params%length = [1.0_wp, 0.7_wp]
    d%params%mass = [1.0_wp, 0.6_wp]
    d%params%inertia = [0.01_wp, 0.02_wp]
    d%theta0 = [1.2_wp, -0.5_wp]
    d%dtheta0 = [0.0_wp, 1.0_wp]
    call run_pendulum('inputs/pendulum/double.nml', d)
  end subroutine pendulum_double

  subroutine pendulum_template()
    type(pendulum_description_t) :: d
    d%params%links = 2
    d%params%length = [1.0_wp, 0.8_wp]
    d%params%mass = [1.0_wp, 0.5_wp]
    d%params%inertia = [0.0_wp, 0.0_wp]
    d%theta0 = [0.5_wp, 0.0_wp]
    d%dtheta0 = [0.0_wp, 0.0_wp]
    call run_pendulum('inputs/templates/pendulum.nml', d)
  end subroutine pendulum_template

  subroutine run_pendulum(name, d)
    character(len=*), intent(in) :: name
    type(pendulum_description_t), intent(in) :: d
    type(mechanism_ode_t), target :: sys
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    call build_pendulum_model(d, sys%mechanism, q0, qd0, st)
    call run_multibody(name, sys, q0, qd0, ODE_ADAMS, 1e-12_wp, 1e-12_wp, 0.01_wp, .false., st)
  end subroutine run_pendulum

  subroutine fourbar_crank_rocker(name)
    character(len=*), intent(in) :: name
    type(fourbar_description_t) :: d
    type(mechanism_ode_t), target :: sys
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    d%params%a = 0.2_wp; d%params%b = 0.6_wp; d%params%c = 0.5_wp; d%params%d = 0.7_wp
    d%params%mass = [0.5_wp, 1.0_wp, 0.8_wp]
    d%crank0 = 0.3_wp
    d%dcrank0 = 12.0_wp
    d%branch = 1
    call build_fourbar_model(d, sys%mechanism, q0, qd0, st)
    call run_multibody(name, sys, q0, qd0, ODE_ADAMS, 1e-12_wp, 1e-12_wp, 0.01_wp, .false., st)
  end subroutine fourbar_crank_rocker

  ! ---------------------------------------------------------------- sled

  !> The bar of every shipped sled input: 0.5 m, 10 kg, inertia 0.02, 0.25, 0.25.
  function sled(q0, qd0) result(d)
    real(wp), intent(in) :: q0(3), qd0(3)
    type(sled_description_t) :: d
    real(wp), parameter :: moments(3) = [0.02_wp, 0.25_wp, 0.25_wp]   ! kg m^2
    integer :: k
    d%params%length = 0.5_wp
    d%params%mass = 10.0_wp
    d%params%inertia = 0
    do k = 1, 3
      d%params%inertia(k, k) = moments(k)
    end do
    d%q0 = q0
    d%qd0 = qd0
  end function sled

  function bowl_surface() result(surface)
    class(surface_t), allocatable :: surface
    type(spec_t) :: spec
    type(status_t) :: st
    spec%kind = 'elliptic_paraboloid'
    call spec%set('a', [2.0_wp])
    call spec%set('b', [2.5_wp])
    call surface_from_spec(spec, surface, st)
    call expect_ok(st, 'the bowl')
  end function bowl_surface

  subroutine sled_bowl()
    call run_sled('inputs/sled/bowl.nml', sled([1.0_wp, 0.0_wp, 0.3_wp], [0.0_wp, 1.2_wp, 0.5_wp]), bowl_surface(), &
                  ODE_ADAMS, 1e-10_wp, 1e-10_wp)
  end subroutine sled_bowl

  subroutine sled_bowl_friction()
    type(sled_description_t) :: d
    d = sled([1.0_wp, 0.0_wp, 0.3_wp], [0.0_wp, 1.2_wp, 0.5_wp])
    d%params%friction = [law_spec('coulomb', 'mu', 0.15_wp)]
    call run_sled('inputs/sled/bowl_friction.nml', d, bowl_surface(), ODE_BDF, 1e-8_wp, 1e-10_wp)
  end subroutine sled_bowl_friction

  subroutine sled_demo_slide()
    type(sled_description_t) :: d
    d = sled([0.5_wp, 1.5707963267948966_wp, 0.0_wp], [2.0_wp, 0.0_wp, 0.0_wp])
    d%params%friction = [law_spec('coulomb', 'mu', 0.05_wp)]
    call run_sled('inputs/sled/demo_slide.nml', d, demo_slide(), ODE_ADAMS, 1e-10_wp, 1e-10_wp)
  end subroutine sled_demo_slide

  subroutine sled_incline_coulomb()
    type(sled_description_t) :: d
    d = sled([0.5_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp])
    d%params%friction = [law_spec('coulomb', 'mu', 0.2_wp)]
    call run_sled('inputs/sled/incline_coulomb.nml', d, incline(0.9396926207859084_wp, -0.3420201433256687_wp), &
                  ODE_ADAMS, 1e-10_wp, 1e-12_wp)
  end subroutine sled_incline_coulomb

  !> inputs/templates/sled.nml: the incline of incline_coulomb.nml with the
  !> law's regularization_speed written out.
  subroutine sled_template()
    type(sled_description_t) :: d
    d = sled([0.5_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp])
    d%params%friction = [law_spec('coulomb', 'mu', 0.2_wp)]
    call d%params%friction(1)%set('regularization_speed', [1e-6_wp])
    call run_sled('inputs/templates/sled.nml', d, incline(0.9396926207859084_wp, -0.3420201433256687_wp), &
                  ODE_ADAMS, 1e-10_wp, 1e-12_wp)
  end subroutine sled_template

  subroutine run_sled(name, d, surface, method, rtol, atol)
    character(len=*), intent(in) :: name
    type(sled_description_t), intent(in) :: d
    class(surface_t), intent(in) :: surface
    integer, intent(in) :: method
    real(wp), intent(in) :: rtol, atol
    type(mechanism_ode_t), target :: sys
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    call build_sled_model(d, surface, sys%mechanism, q0, qd0, st)
    call run_multibody(name, sys, q0, qd0, method, rtol, atol, 0.01_wp, .false., st)
  end subroutine run_sled

  !> The tube of a slide description.
  function tube_of(d) result(tube)
    type(geometry_description_t), intent(in) :: d
    type(tube_surface_t) :: tube
    type(status_t) :: st
    call build_slide(d%slide, tube, st)
    call expect_ok(st, 'a slide')
  end function tube_of

  !> &surface kind = 'plane' through the origin, point_b, point_c = (0, 1, 0).
  function incline(bx, bz) result(surface)
    real(wp), intent(in) :: bx, bz
    class(surface_t), allocatable :: surface
    type(spec_t) :: spec
    type(status_t) :: st
    spec%kind = 'plane'
    call spec%set('point_a', [0.0_wp, 0.0_wp, 0.0_wp])
    call spec%set('point_b', [bx, 0.0_wp, bz])
    call spec%set('point_c', [0.0_wp, 1.0_wp, 0.0_wp])
    call surface_from_spec(spec, surface, st)
    call expect_ok(st, 'the incline')
  end function incline

  !> inputs/demo_slide/slide.nml: eight standard elements, a circular tube
  !> of radius 0.5 m (tests/library/shipped_slides.f90).
  function demo_slide() result(surface)
    class(surface_t), allocatable :: surface
    allocate (surface, source=tube_of(demo_slide_description()))
  end function demo_slide

  ! ---------------------------------------------------------------- point mass

  subroutine point_mass_apex_paraboloid()
    type(point_mass_description_t) :: d
    d%u0 = 0.0_wp; d%v0 = 0.6_wp; d%du0 = 0.0_wp; d%dv0 = -0.5_wp
    d%alpha_u = 1.0_wp; d%alpha_v = 1.0_wp; d%sigma = -1.0_wp
    call run_point_mass('inputs/point_mass/apex_paraboloid.nml', d, surface_ab('apex_paraboloid', 1.0_wp, 1.5_wp), &
                        1e-10_wp, 1e-10_wp, 0.005_wp)
  end subroutine point_mass_apex_paraboloid

  subroutine point_mass_ellipsoid()
    type(point_mass_description_t) :: d
    class(surface_t), allocatable :: surface
    type(spec_t) :: spec
    type(status_t) :: st
    spec%kind = 'ellipsoid'
    call spec%set('a', [2.0_wp])
    call spec%set('b', [1.5_wp])
    call spec%set('c', [1.0_wp])
    call surface_from_spec(spec, surface, st)
    call expect_ok(st, 'the ellipsoid')
    d%u0 = 0.0_wp; d%v0 = -0.8_wp; d%du0 = 1.2_wp; d%dv0 = 0.0_wp
    d%sigma = -1
    call run_point_mass('inputs/point_mass/ellipsoid.nml', d, surface, 1e-10_wp, 1e-10_wp, 0.01_wp)
  end subroutine point_mass_ellipsoid

  subroutine point_mass_elliptic_cylinder()
    type(point_mass_description_t) :: d
    d%gravity = 0
    d%u0 = 0.0_wp; d%v0 = 0.0_wp; d%du0 = 0.3_wp; d%dv0 = 2.0_wp
    call run_point_mass('inputs/point_mass/elliptic_cylinder.nml', d, &
                        surface_ab('elliptic_cylinder', 0.5_wp, 0.5_wp), 1e-10_wp, 1e-10_wp, 0.01_wp)
  end subroutine point_mass_elliptic_cylinder

  subroutine point_mass_elliptic_paraboloid()
    type(point_mass_description_t) :: d
    d%u0 = 0.8_wp; d%v0 = 0.0_wp; d%du0 = 0.0_wp; d%dv0 = 2.0_wp
    d%friction = law_spec('viscous', 'viscous_coefficient', 0.05_wp)
    call run_point_mass('inputs/point_mass/elliptic_paraboloid.nml', d, &
                        surface_ab('elliptic_paraboloid', 1.0_wp, 1.4_wp), 1e-10_wp, 1e-10_wp, 0.01_wp)
  end subroutine point_mass_elliptic_paraboloid

  subroutine point_mass_hyperbolic_paraboloid()
    type(point_mass_description_t) :: d
    class(surface_t), allocatable :: surface
    type(surface_description_t) :: placed
    type(status_t) :: st
    placed%spec%kind = 'hyperbolic_paraboloid'
    call placed%spec%set('a', [1.0_wp])
    call placed%spec%set('b', [1.0_wp])
    placed%origin = [0.0_wp, 0.0_wp, 1.0_wp]
    placed%angles_deg = [0.0_wp, 0.0_wp, 20.0_wp]
    call build_surface(placed, surface, st)
    call expect_ok(st, 'the hyperbolic paraboloid')
    d%u0 = 0.2_wp; d%v0 = 0.05_wp; d%du0 = -1.0_wp; d%dv0 = 0.0_wp
    call run_point_mass('inputs/point_mass/hyperbolic_paraboloid.nml', d, surface, 1e-10_wp, 1e-10_wp, 0.005_wp)
  end subroutine point_mass_hyperbolic_paraboloid

  subroutine point_mass_plane_coulomb()
    type(point_mass_description_t) :: d
    d%mass = 2.0_wp
    d%u0 = 0.0_wp; d%v0 = 0.0_wp; d%du0 = 0.5_wp; d%dv0 = 0.0_wp
    ! friction_coefficient is the law's mu; the regularization is the point mass's default (build_point_mass_model)
    d%friction = law_spec('coulomb', 'mu', 0.2_wp)
    call run_point_mass('inputs/point_mass/plane_coulomb.nml', d, incline(0.8660254037844386_wp, -0.5_wp), &
                        1e-10_wp, 1e-10_wp, 0.01_wp)
  end subroutine point_mass_plane_coulomb

  subroutine point_mass_incline_drag()
    type(point_mass_description_t) :: d
    d%mass = 2.0_wp
    d%drag_area = 0.05_wp   ! m^2; still air of the default density
    call run_point_mass('inputs/point_mass/incline_drag.nml', d, incline(0.8660254037844386_wp, -0.5_wp), &
                        1e-10_wp, 1e-10_wp, 0.05_wp)
  end subroutine point_mass_incline_drag

  !> inputs/templates/point_mass.nml: plane_coulomb.nml's block with every
  !> variable written out (the regularization_speed the point mass's own).
  subroutine point_mass_template()
    type(point_mass_description_t) :: d
    d%mass = 2.0_wp
    d%u0 = 0.0_wp; d%v0 = 0.0_wp; d%du0 = 0.5_wp; d%dv0 = 0.0_wp
    d%friction = law_spec('coulomb', 'mu', 0.2_wp)
    call d%friction%set('regularization_speed', [1e-9_wp])
    d%sigma = 1; d%alpha_u = 1.0_wp; d%alpha_v = 0.0_wp
    call run_point_mass('inputs/templates/point_mass.nml', d, incline(0.8660254037844386_wp, -0.5_wp), &
                        1e-10_wp, 1e-10_wp, 0.01_wp)
  end subroutine point_mass_template

  !> inputs/parts/bowl_point_mass.nml: circling in a sphere zone of 3 m, no friction.
  subroutine point_mass_bowl()
    type(point_mass_description_t) :: d
    class(surface_t), allocatable :: surface
    type(spec_t) :: spec
    type(status_t) :: st
    spec%kind = 'sphere_zone'
    call spec%set('radius', [3.0_wp])
    call spec%set('latitude_min_deg', [-89.0_wp])
    call spec%set('latitude_max_deg', [0.0_wp])
    call surface_from_spec(spec, surface, st)
    call expect_ok(st, 'the bowl zone')
    d%u0 = 0.0_wp; d%v0 = -0.6981317007977318_wp; d%du0 = 2.2551008156828716_wp; d%dv0 = 0.0_wp
    d%sigma = -1.0_wp
    call run_point_mass('inputs/parts/bowl_point_mass.nml', d, surface, 1e-12_wp, 1e-12_wp, 0.01_wp)
  end subroutine point_mass_bowl

  !> inputs/parts/halfpipe_point_mass.nml on parts/halfpipe_slide.nml: an
  !> exact centre line, a flume of radius 2 m with walls of 1.5 m; no friction.
  subroutine point_mass_halfpipe()
    type(point_mass_description_t) :: d
    type(geometry_description_t) :: slide
    class(surface_t), allocatable :: surface
    type(status_t) :: st
    slide%kind = 'slide'
    slide%slide%elements%start = [0.0_wp, 0.0_wp, 6.0_wp]
    slide%slide%elements%transition_length = 2.0_wp
    slide%slide%elements%exact = .true.
    slide%slide%elements%elements = [ &
      slide_element_t(kind='straight', length=6.0_wp, slope_deg=12.0_wp), &
      slide_element_t(kind='curve', slope_deg=5.0_wp, radius=8.0_wp, angle_deg=150.0_wp), &
      slide_element_t(kind='straight', length=6.0_wp, slope_deg=6.0_wp)]
    slide%slide%section%parts = [section_part_description_t(kind='flume', radius=2.0_wp, wall=1.5_wp)]
    call build_geometry(slide, surface, st)
    call expect_ok(st, 'the half-pipe slide')
    d%u0 = 0.5_wp; d%v0 = 1.5707963267948966_wp; d%du0 = 4.0_wp; d%dv0 = 0.0_wp
    call run_point_mass('inputs/parts/halfpipe_point_mass.nml', d, surface, 1e-12_wp, 1e-12_wp, 0.01_wp)
  end subroutine point_mass_halfpipe

  subroutine point_mass_demo_slide()
    type(point_mass_description_t) :: d
    d%u0 = 0.5_wp; d%v0 = 1.5707963267948966_wp; d%du0 = 2.0_wp; d%dv0 = 0.0_wp
    call run_point_mass('inputs/demo_slide/point_mass.nml', d, demo_slide(), 1e-12_wp, 1e-12_wp, 0.01_wp)
  end subroutine point_mass_demo_slide

  function surface_ab(kind, a, b) result(surface)
    character(len=*), intent(in) :: kind
    real(wp), intent(in) :: a, b
    class(surface_t), allocatable :: surface
    type(spec_t) :: spec
    type(status_t) :: st
    spec%kind = kind
    call spec%set('a', [a])
    call spec%set('b', [b])
    call surface_from_spec(spec, surface, st)
    call expect_ok(st, kind)
  end function surface_ab

  !> As scenarios_point_mass runs it (Adams, the input's tolerances).
  subroutine run_point_mass(name, d, surface, rtol, atol, output_step)
    character(len=*), intent(in) :: name
    type(point_mass_description_t), intent(in) :: d
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: rtol, atol, output_step
    type(point_mass_t), target :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    integer :: k
    call build_point_mass_model(d, surface, model, y0, st)
    call expect_ok(st, name//': built')
    if (.not. st%ok()) return
    call model%start_series(nint(duration/output_step) + 2)
    options%ode%method = ODE_ADAMS
    options%ode%rtol = rtol
    options%ode%atol = atol
    options%t_end = duration
    options%output_step = output_step
    options%min_mean_step = min_mean_step
    options%progress_seconds = 0
    call drive(model, y0, options, result, st)
    call expect_ok(st, name//': ran')
    associate (s => model%series, n => model%series%n)
      call put(name, 'simulated_time', s%time(n))
      call put(name, 'final_speed', s%speed(n))
      call put(name, 'drop', s%position(3, 1) - s%position(3, n))
      call put(name, 'friction_work', s%friction_work(n))
      if (d%drag_area > 0) then
        call put(name, 'drag_work', s%drag_work(n))
        call put(name, 'drag_force_max', maxval([(norm2(s%drag_force(:, k)), k = 1, n)]))
      end if
    end associate
    call put_count(name, 'steps', int(result%stats%steps))
    call put_count(name, 'rhs_evaluations', int(result%stats%rhs_evaluations))
  end subroutine run_point_mass

  ! ---------------------------------------------------------------- contact

  !> &shape of a kind of the registry (no placement in the shipped inputs).
  function spec_shape(name, kind, parameters, values) result(shape)
    character(len=*), intent(in) :: name, kind, parameters(:)
    real(wp), intent(in) :: values(:)
    type(shape_t) :: shape
    integer :: k
    shape%name = name
    shape%description%spec%kind = kind
    do k = 1, size(parameters)
      call shape%description%spec%set(trim(parameters(k)), [values(k)])
    end do
  end function spec_shape

  !> &shape kind = 'bspline' of paraboloids/<file>.geo: the 13 x 13 points
  !> z = (x^2 + y^2)/a2 on [-w, w]^2 of its CSV (written by
  !> scripts/make_contact_inputs.py with these a2 and w; the same arithmetic,
  !> x = -w + 2 w i/12, so the same numbers), layout 'scattered', degree 5,
  !> smoothing 0.05, described (the contact layer builds it).
  function bspline_shape(name, a2, w) result(shape)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: a2, w
    type(shape_t) :: shape
    real(wp) :: table(3, 169), x, y
    integer :: i, j
    do j = 0, 12
      do i = 0, 12
        x = -w + 2*w*i/12
        y = -w + 2*w*j/12
        table(:, 13*j + i + 1) = [x, y, (x*x + y*y)/a2]
      end do
    end do
    shape%name = name
    allocate (shape%description%geometry)   ! built by build_contact_model
    shape%description%geometry%kind = 'bspline'
    shape%description%geometry%bspline%layout = 'scattered'
    shape%description%geometry%bspline%table = table
    shape%description%geometry%bspline%smoothing = 0.05_wp
    shape%description%geometry%bspline%degree = 5
  end function bspline_shape

  function body(name, mass, position, angles_deg) result(b)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: mass, position(3), angles_deg(3)
    type(body_spec_t) :: b
    b%name = name
    b%mass = mass
    b%position = position
    b%rotation = rotation_xyz(angles_deg*pi/180)
  end function body

  !> A body with its centre and principal moments given.
  function given_body(name, mass, centre, moments, position, angles_deg) result(b)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: mass, centre(3), moments(3), position(3), angles_deg(3)
    type(body_spec_t) :: b
    integer :: k
    b = body(name, mass, position, angles_deg)
    b%centre = centre
    b%inertia = 0
    do k = 1, 3
      b%inertia(k, k) = moments(k)
    end do
  end function given_body

  function contact(name, body_1, shape_1, side_1, body_2, shape_2, side_2, rolling) result(c)
    character(len=*), intent(in) :: name, body_1, shape_1, body_2, shape_2
    real(wp), intent(in) :: side_1, side_2
    logical, intent(in) :: rolling
    type(contact_spec_t) :: c
    c%name = name
    c%body_1 = body_1
    c%shape_1 = shape_1
    c%side_1 = side_1
    c%body_2 = body_2
    c%shape_2 = shape_2
    c%side_2 = side_2
    c%rolling = rolling
  end function contact

  subroutine contact_egg(name, axes, angles_deg)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: axes(3), angles_deg(3)
    type(contact_system_t) :: system
    system%shapes = [spec_shape('table', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     spec_shape('egg', 'ellipsoid', [character(len=1) :: 'a', 'b', 'c'], axes)]
    system%bodies = [body('egg', 0.08_wp, [0.0_wp, 0.0_wp, 0.05_wp], angles_deg)]
    system%bodies(1)%solid_of = 'egg'
    system%bodies(1)%angular_velocity = [0.0_wp, 0.0_wp, 150.0_wp]
    system%contacts = [contact('egg_on_table', 'ground', 'table', 1.0_wp, 'egg', 'egg', 1.0_wp, .false.)]
    system%contacts(1)%friction = law_spec('viscous_weight', 'mu', 0.3_wp)
    call run_contact(name, system, 1e-11_wp, 1e-10_wp, 5e-3_wp)
  end subroutine contact_egg

  subroutine contact_ball_in_cone()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('bowl', 'cone', [character(len=14) :: 'half_angle_deg', 'z_min', 'z_max'], &
                                [30.0_wp, 0.1_wp, 1.0_wp]), &
                     spec_shape('ball', 'sphere', [character(len=6) :: 'radius'], [0.05_wp])]
    system%bodies = [body('ball', 0.2_wp, [0.24537386440559092_wp, 0.0_wp, 0.525_wp], [0.0_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%solid_of = 'ball'
    system%bodies(1)%velocity = [0.0_wp, 1.633220377046527_wp, 0.0_wp]
    system%bodies(1)%angular_velocity = [-16.332203770465267_wp, 0.0_wp, -28.288206730013837_wp]
    system%contacts = [contact('in_bowl', 'ground', 'bowl', -1.0_wp, 'ball', 'ball', 1.0_wp, .true.)]
    call run_contact('inputs/contact/ball_in_cone.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp)
  end subroutine contact_ball_in_cone

  subroutine contact_paraboloids()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('table', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     bspline_shape('paraboloid_2', 3.0_wp, 2.0_wp), bspline_shape('paraboloid_3', 0.5_wp, 0.5_wp)]
    system%bodies = [given_body('paraboloid_2', 2.0_wp, [0.0_wp, 0.0_wp, 0.6_wp], [0.72_wp, 0.72_wp, 1.08_wp], &
                                [0.0_wp, 0.0_wp, 0.0_wp], [6.0_wp, 0.0_wp, 0.0_wp]), &
                     given_body('paraboloid_3', 0.5_wp, [0.0_wp, 0.0_wp, 0.1_wp], &
                                [0.01125_wp, 0.01125_wp, 0.016875_wp], [0.3_wp, 0.2_wp, 0.2_wp], &
                                [0.0_wp, -8.0_wp, 0.0_wp])]
    system%contacts = [contact('p2_on_table', 'ground', 'table', 1.0_wp, 'paraboloid_2', 'paraboloid_2', -1.0_wp, &
                               .true.), &
                       contact('p3_in_p2', 'paraboloid_2', 'paraboloid_2', 1.0_wp, 'paraboloid_3', 'paraboloid_3', &
                               -1.0_wp, .true.)]
    call run_contact('inputs/contact/paraboloids.nml', system, 1e-11_wp, 1e-10_wp, 5e-3_wp)
  end subroutine contact_paraboloids

  !> inputs/contact/tower5.nml: the bowls' a2 and w from the headers of
  !> paraboloids/tower5_<k>.csv, the bodies as the input gives them.
  subroutine contact_tower5()
    type(contact_system_t) :: system
    character(len=5) :: b(5)
    integer :: k
    b = ['bowl1', 'bowl2', 'bowl3', 'bowl4', 'bowl5']
    system%shapes = [spec_shape('table', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     bspline_shape(b(1), 3.0_wp, 2.0_wp), &
                     bspline_shape(b(2), 1.9168293127388174_wp, 1.4142135623730951_wp), &
                     bspline_shape(b(3), 1.224744871391589_wp, 1.0_wp), &
                     bspline_shape(b(4), 0.7825422900366437_wp, 0.7071067811865476_wp), &
                     bspline_shape(b(5), 0.5_wp, 0.5_wp)]
    system%bodies = [ &
      given_body(b(1), 2.0_wp, [0.0_wp, 0.0_wp, 0.6_wp], [0.72_wp, 0.72_wp, 1.08_wp], [0.04_wp, 0.0_wp, 0.0_wp], tilt()), &
      given_body(b(2), 1.41421_wp, [0.0_wp, 0.0_wp, 0.383366_wp], [0.254558_wp, 0.254558_wp, 0.381838_wp], &
                 [0.08_wp, 0.0_wp, 0.1_wp], tilt()), &
      given_body(b(3), 1.0_wp, [0.0_wp, 0.0_wp, 0.244949_wp], [0.09_wp, 0.09_wp, 0.135_wp], &
                 [0.12_wp, 0.0_wp, 0.2_wp], tilt()), &
      given_body(b(4), 0.707107_wp, [0.0_wp, 0.0_wp, 0.156508_wp], [0.0318198_wp, 0.0318198_wp, 0.0477297_wp], &
                 [0.16_wp, 0.0_wp, 0.3_wp], tilt()), &
      given_body(b(5), 0.5_wp, [0.0_wp, 0.0_wp, 0.1_wp], [0.01125_wp, 0.01125_wp, 0.016875_wp], &
                 [0.2_wp, 0.0_wp, 0.4_wp], tilt())]
    allocate (system%contacts(5))
    system%contacts(1) = contact('bowl1_on_table', 'ground', 'table', 1.0_wp, b(1), b(1), -1.0_wp, .true.)
    do k = 2, 5
      system%contacts(k) = contact(b(k)//'_in_'//b(k - 1), b(k - 1), b(k - 1), 1.0_wp, b(k), b(k), -1.0_wp, .true.)
    end do
    call run_contact('inputs/contact/tower5.nml', system, 1e-11_wp, 1e-10_wp, 5e-3_wp)
  end subroutine contact_tower5

  pure function tilt() result(angles_deg)
    real(wp) :: angles_deg(3)
    angles_deg = [3.0_wp, 1.5_wp, 0.0_wp]
  end function tilt

  !> As scenarios_contact runs it: Adams with the contact's convergence coefficient.
  subroutine run_contact(name, system, rtol, atol, output_step)
    character(len=*), intent(in) :: name
    type(contact_system_t), intent(in) :: system
    real(wp), intent(in) :: rtol, atol, output_step
    type(contact_model_t), target :: model
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    integer :: f, ns
    call build_contact_model(system, model, st)
    call expect_ok(st, name//': built')
    if (.not. st%ok()) return
    f = model%ode%mechanism%f
    ns = model%ode%mechanism%ns
    ! the contact scenario judges the start once before the common run does
    y0 = model%ode%initial_state(model%y0(1:f), model%y0(f + 1:f + ns))
    call model%ode%check_start(y0, st)
    call run_multibody(name, model%ode, model%y0(1:f), model%y0(f + 1:f + ns), ODE_ADAMS, rtol, atol, output_step, &
                       .true., st)
  end subroutine run_contact

  ! ---------------------------------------------------------------- contact: flights

  !> A contact that starts open, with its impact law: shape_1 of the ground,
  !> body_2's shape_2 (the shapes named as their bodies).
  function landing(name, shape_1, body_2, restitution, close_speed) result(c)
    character(len=*), intent(in) :: name, shape_1, body_2
    real(wp), intent(in) :: restitution, close_speed
    type(contact_spec_t) :: c
    c = contact(name, 'ground', shape_1, 1.0_wp, body_2, body_2, 1.0_wp, .false.)
    c%start_open = .true.
    c%restitution = restitution
    c%close_speed = close_speed
  end function landing

  function ball_shape(name, radius) result(shape)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: radius
    type(shape_t) :: shape
    shape = spec_shape(name, 'sphere', [character(len=6) :: 'radius'], [radius])
  end function ball_shape

  function solid_ball(name, mass, position, velocity) result(b)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: mass, position(3), velocity(3)
    type(body_spec_t) :: b
    b = body(name, mass, position, [0.0_wp, 0.0_wp, 0.0_wp])
    b%solid_of = name
    b%velocity = velocity
  end function solid_ball

  subroutine contact_bouncing_ball()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('ball', 0.1_wp)]
    system%bodies = [solid_ball('ball', 0.2_wp, [0.0_wp, 0.0_wp, 1.1_wp], [0.3_wp, 0.0_wp, 0.0_wp])]
    system%contacts = [landing('on_floor', 'floor', 'ball', 0.5_wp, 0.1_wp)]
    call run_flying('inputs/contact/bouncing_ball.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 3.0_wp)
  end subroutine contact_bouncing_ball

  subroutine contact_ball_drop_drag()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('ball', 0.1_wp)]
    system%bodies = [solid_ball('ball', 0.05_wp, [0.0_wp, 0.0_wp, 20.1_wp], [0.0_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%drag_area = 0.01_wp   ! m^2, still air of the default density
    system%contacts = [landing('on_floor', 'floor', 'ball', 0.5_wp, 0.1_wp)]
    call run_flying('inputs/contact/ball_drop_drag.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 6.0_wp)
  end subroutine contact_ball_drop_drag

  subroutine contact_two_balls()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('big', 0.1_wp), &
                     ball_shape('small', 0.05_wp)]
    system%bodies = [solid_ball('big', 0.2_wp, [0.0_wp, 0.0_wp, 1.1_wp], [0.3_wp, 0.0_wp, 0.0_wp]), &
                     solid_ball('small', 0.5_wp, [1.0_wp, 0.0_wp, 0.65_wp], [-0.2_wp, 0.0_wp, 0.0_wp])]
    system%contacts = [landing('big_on_floor', 'floor', 'big', 0.5_wp, 0.1_wp), &
                       landing('small_on_floor', 'floor', 'small', 0.8_wp, 0.1_wp)]
    call run_flying('inputs/contact/two_balls.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 2.0_wp)
  end subroutine contact_two_balls

  !> inputs/contact/dome.nml, and with the floor to land on dome_floor.nml:
  !> the ball starts closed, rolling on the dome, and may lift off.
  subroutine contact_dome(floor)
    logical, intent(in) :: floor
    type(contact_system_t) :: system
    system%shapes = [ball_shape('dome', 1.0_wp), ball_shape('ball', 0.1_wp)]
    system%bodies = [body('ball', 1.0_wp, [0.05_wp, 0.0_wp, 1.1_wp], [90.0_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%solid_of = 'ball'
    system%contacts = [contact('ball_on_dome', 'ground', 'dome', 1.0_wp, 'ball', 'ball', 1.0_wp, .true.)]
    system%contacts(1)%may_open = .true.
    if (floor) then
      system%shapes = [system%shapes(1), spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), &
                       system%shapes(2)]
      system%contacts = [system%contacts, landing('ball_on_floor', 'floor', 'ball', 0.5_wp, 0.1_wp)]
      call run_flying('inputs/contact/dome_floor.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 3.0_wp)
    else
      call run_flying('inputs/contact/dome.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 2.0_wp)
    end if
  end subroutine contact_dome

  subroutine contact_loop()
    type(contact_system_t) :: system
    system%shapes = [ball_shape('loop', 1.0_wp), ball_shape('ball', 0.1_wp)]
    system%shapes(1)%description%angles_deg = [90.0_wp, 0.0_wp, 0.0_wp]
    system%bodies = [solid_ball('ball', 1.0_wp, [0.0_wp, 0.0_wp, -0.9_wp], [5.145673425315680_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%angular_velocity = [0.0_wp, 51.45673425315680_wp, 0.0_wp]
    system%contacts = [contact('in_loop', 'ground', 'loop', -1.0_wp, 'ball', 'ball', 1.0_wp, .true.)]
    system%contacts(1)%may_open = .true.
    system%contacts(1)%restitution = 0.3_wp
    system%contacts(1)%close_speed = 0.5_wp
    call run_flying('inputs/contact/loop.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 3.0_wp)
  end subroutine contact_loop

  subroutine contact_roll_beside_bounce()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     spec_shape('slope', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     ball_shape('roller', 0.1_wp), ball_shape('bouncer', 0.05_wp)]
    system%shapes(2)%description%angles_deg = [0.0_wp, 10.0_wp, 0.0_wp]
    system%bodies = [body('roller', 0.2_wp, [0.01736481776669303_wp, 0.0_wp, 0.09848077530122080_wp], &
                          [-90.0_wp, 0.0_wp, 0.0_wp]), &
                     solid_ball('bouncer', 0.5_wp, [0.0_wp, 1.0_wp, 0.55_wp], [0.4_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%solid_of = 'roller'
    system%contacts = [contact('roller_on_slope', 'ground', 'slope', 1.0_wp, 'roller', 'roller', 1.0_wp, .true.), &
                       landing('bouncer_on_floor', 'floor', 'bouncer', 0.5_wp, 0.1_wp)]
    call run_flying('inputs/contact/roll_beside_bounce.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 2.0_wp)
  end subroutine contact_roll_beside_bounce

  subroutine contact_stacked_balls()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('big', 0.12_wp), &
                     ball_shape('small', 0.033_wp)]
    system%bodies = [solid_ball('big', 0.6_wp, [0.0_wp, 0.0_wp, 1.12_wp], [0.0_wp, 0.0_wp, 0.0_wp]), &
                     solid_ball('small', 0.057_wp, [0.0_wp, 0.0_wp, 1.283_wp], [0.0_wp, 0.0_wp, 0.0_wp])]
    system%contacts = [landing('big_on_floor', 'floor', 'big', 0.8_wp, 0.1_wp), &
                       contact('small_on_big', 'big', 'big', 1.0_wp, 'small', 'small', 1.0_wp, .false.), &
                       landing('small_on_floor', 'floor', 'small', 0.8_wp, 0.1_wp)]
    system%contacts(2)%start_open = .true.
    system%contacts(2)%restitution = 0.9_wp   ! close_speed: the default
    call run_flying('inputs/contact/stacked_balls.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 5.5_wp)
  end subroutine contact_stacked_balls

  subroutine contact_falling_pair()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('big', 0.12_wp), &
                     ball_shape('small', 0.033_wp)]
    system%bodies = [solid_ball('big', 0.6_wp, [0.0_wp, 0.0_wp, 1.12_wp], [0.0_wp, 0.0_wp, 0.0_wp]), &
                     solid_ball('small', 0.057_wp, [0.0_wp, 0.0_wp, 1.273_wp], [0.0_wp, 0.0_wp, 0.0_wp])]
    system%contacts = [landing('big_on_floor', 'floor', 'big', 0.8_wp, 0.1_wp), &
                       contact('small_on_big', 'big', 'big', 1.0_wp, 'small', 'small', 1.0_wp, .false.)]
    system%contacts(2)%may_open = .true.
    system%contacts(2)%restitution = 0.9_wp   ! close_speed: the default
    call run_flying('inputs/contact/falling_pair.nml', system, 1e-10_wp, 1e-10_wp, 0.01_wp, 3.5_wp)
  end subroutine contact_falling_pair

  subroutine contact_box_landing()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('rear', 0.02_wp), &
                     ball_shape('front', 0.02_wp)]
    system%shapes(2)%description%origin = [-0.2_wp, 0.0_wp, -0.1_wp]
    system%shapes(3)%description%origin = [0.2_wp, 0.0_wp, -0.1_wp]
    system%bodies = [given_body('box', 2.0_wp, [0.0_wp, 0.0_wp, 0.0_wp], [0.0216666666666667_wp, 0.0333333333333333_wp, &
                                0.0416666666666667_wp], [0.0_wp, 0.0_wp, 0.42_wp], [0.0_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%velocity = [2.0_wp, 0.0_wp, 0.0_wp]
    system%contacts = [landing('rear_on_floor', 'floor', 'box', 0.5_wp, 0.1_wp), &
                       landing('front_on_floor', 'floor', 'box', 0.5_wp, 0.1_wp)]
    system%contacts(1)%shape_2 = 'rear'
    system%contacts(2)%shape_2 = 'front'
    system%contacts%impact_mu = 0.4_wp
    call run_flying('inputs/contact/box_landing.nml', system, 1e-10_wp, 1e-10_wp, 0.005_wp, 1.0_wp)
  end subroutine contact_box_landing

  subroutine contact_ball_on_cart()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     ball_shape('rear_left', 0.02_wp), ball_shape('rear_right', 0.02_wp), ball_shape('front', 0.02_wp), &
                     spec_shape('lid', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('ball', 0.05_wp)]
    system%shapes(2)%description%origin = [-0.5_wp, 0.15_wp, -0.1_wp]
    system%shapes(3)%description%origin = [-0.5_wp, -0.15_wp, -0.1_wp]
    system%shapes(4)%description%origin = [0.5_wp, 0.0_wp, -0.1_wp]
    system%shapes(5)%description%origin = [0.0_wp, 0.0_wp, 0.1_wp]
    system%bodies = [given_body('cart', 4.0_wp, [0.0_wp, 0.0_wp, 0.0_wp], [0.0666666666666667_wp, 0.493333333333333_wp, &
                                0.533333333333333_wp], [0.0_wp, 0.0_wp, 0.12_wp], [0.0_wp, 0.0_wp, 0.0_wp]), &
                     solid_ball('ball', 0.2_wp, [-0.4_wp, 0.0_wp, 0.57_wp], [1.0_wp, 0.0_wp, 0.0_wp])]
    system%bodies(1)%velocity = [1.0_wp, 0.0_wp, 0.0_wp]
    system%bodies(2)%angular_velocity = [0.0_wp, 20.0_wp, 0.0_wp]
    system%contacts = [contact('rear_left_on_floor', 'ground', 'floor', 1.0_wp, 'cart', 'rear_left', 1.0_wp, .false.), &
                       contact('rear_right_on_floor', 'ground', 'floor', 1.0_wp, 'cart', 'rear_right', 1.0_wp, .false.), &
                       contact('front_on_floor', 'ground', 'floor', 1.0_wp, 'cart', 'front', 1.0_wp, .false.), &
                       contact('ball_on_cart', 'cart', 'lid', 1.0_wp, 'ball', 'ball', 1.0_wp, .false.)]
    system%contacts(4)%start_open = .true.
    system%contacts(4)%restitution = 0.6_wp
    system%contacts(4)%close_speed = 0.1_wp
    system%contacts(4)%friction = law_spec('coulomb', 'mu', 0.2_wp)
    call run_flying('inputs/contact/ball_on_cart.nml', system, 1e-12_wp, 1e-12_wp, 0.005_wp, 2.0_wp, ODE_BDF)
  end subroutine contact_ball_on_cart

  subroutine contact_ladder()
    type(contact_system_t) :: system
    system%shapes = [spec_shape('floor', 'plane', [character(len=1) ::], [real(wp) ::]), &
                     spec_shape('wall', 'plane', [character(len=1) ::], [real(wp) ::]), ball_shape('head', 0.05_wp), &
                     ball_shape('foot', 0.05_wp)]
    system%shapes(2)%description%angles_deg = [0.0_wp, 90.0_wp, 0.0_wp]
    system%shapes(3)%description%origin = [-0.5_wp, 0.0_wp, 0.0_wp]
    system%shapes(4)%description%origin = [0.5_wp, 0.0_wp, 0.0_wp]
    system%bodies = [given_body('rod', 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp], [0.001_wp, 0.1_wp, 0.1_wp], &
                                [0.3_wp, 0.0_wp, 0.483012701892219_wp], [0.0_wp, 60.0_wp, 0.0_wp])]
    system%contacts = [contact('on_floor', 'ground', 'floor', 1.0_wp, 'rod', 'foot', 1.0_wp, .false.), &
                       contact('on_wall', 'ground', 'wall', 1.0_wp, 'rod', 'head', 1.0_wp, .false.)]
    system%contacts(2)%may_open = .true.
    call run_flying('inputs/contact/ladder.nml', system, 1e-11_wp, 1e-11_wp, 0.005_wp, 0.4_wp)
  end subroutine contact_ladder

  !> As scenarios_contact runs a system whose contacts start open or may
  !> open: a flight from the start (build_flight), several bodies some carried
  !> (build_bodies), or a body starting on its closed contact and flying from
  !> its lift-off (flight_after_closed); driven by drive_flight. Run over
  !> the input's own duration `seconds` (a fraction of a second each), not
  !> the program's, so that the landings, closings and lift-offs happen:
  !> the line `<input> duration <seconds>` tells compare_shipped.py.
  subroutine run_flying(name, system, rtol, atol, output_step, seconds, method)
    character(len=*), intent(in) :: name
    type(contact_system_t), intent(in) :: system
    real(wp), intent(in) :: rtol, atol, output_step, seconds
    integer, intent(in), optional :: method   ! the input's &solver method (ODE_ADAMS unless given)
    type(flight_ode_t), target :: flight
    type(contact_model_t) :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:), y0(:)
    character(len=8), allocatable :: q_units(:)
    integer, allocatable :: open(:, :), opened(:)
    logical :: closed(size(system%contacts)), touching(size(system%contacts))
    integer :: f, ns
    call check_flight_system(system, st)
    if (carrying_contact(system) == 0) then
      call build_flight(system, flight, q0, qd0, q_units, st)
    else if (size(system%bodies) > 1 .or. count(.not. system%contacts%start_open) > 1) then
      ! several bodies, or one on several closed contacts (one that carries nothing starts open, as the command's)
      closed = start_carriers(system)
      touching = .false.
      call build_bodies_opening(system, closed, touching, flight, q0, qd0, q_units, st, .false., opened, model)
    else
      call build_contact_model(closed_part(system, carrying_contact(system)), model, st)
      if (st%ok()) then
        f = model%ode%mechanism%f
        ns = model%ode%mechanism%ns
        y0 = model%ode%initial_state(model%y0(1:f), model%y0(f + 1:f + ns))
        call model%ode%check_start(y0, st)
      end if
      call flight_after_closed(system, model, flight, q0, qd0, q_units, st)
    end if
    call expect_ok(st, name//': built')
    if (.not. st%ok()) return
    y0 = flight%initial_state(q0, qd0)
    call flight%check_start(y0, st)
    call expect_ok(st, name//': start')
    if (.not. st%ok()) return
    options%ode%method = ODE_ADAMS
    if (present(method)) options%ode%method = method
    options%ode%rtol = rtol
    options%ode%atol = atol
    ! as scenarios_contact: Adams' corrector to the contact scenario's coefficient, BDF's CVODE's own
    if (options%ode%method == ODE_ADAMS) options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = seconds
    options%output_step = output_step
    options%min_mean_step = min_mean_step
    options%progress_seconds = 0
    call put(name, 'duration', seconds)
    call flight%start_series(nint(seconds/output_step) + 2)
    call drive_flight(flight, y0, options, result, st, open)
    call expect_ok(st, name//': ran')
    associate (s => flight%series, n => flight%series%n)
      call put(name, 'simulated_time', s%time(n))
      call put(name, 'energy_change_joules', s%kinetic(n) + s%potential(n) - (s%kinetic(1) + s%potential(1)))
    end associate
    if (size(flight%impacts) > 0) then
      ! the summary counts impacts: one at several contacts is a row each, all at its time
      call put_count(name, 'impacts', 1 + count(flight%impacts(2:)%time /= flight%impacts(:size(flight%impacts) - 1)%time))
      call put(name, 'impact_speed_max', maxval(-flight%impacts%normal_speed_before))
      call put(name, 'impact_energy_lost', sum(flight%impacts%energy_lost))
    end if
    call put_count(name, 'steps', int(result%stats%steps))
    call put_count(name, 'rhs_evaluations', int(result%stats%rhs_evaluations))
  end subroutine run_flying

  ! ---------------------------------------------------------------- the common run

  !> As scenarios_mechanism's run_mechanism: the start checked, the series
  !> started, the driver run; then the summary's numbers.
  subroutine run_multibody(name, sys, q0, qd0, method, rtol, atol, output_step, contact_scenario, status)
    character(len=*), intent(in) :: name
    class(mechanism_ode_t), intent(inout), target :: sys
    real(wp), intent(in) :: q0(:), qd0(:)
    integer, intent(in) :: method
    real(wp), intent(in) :: rtol, atol, output_step
    logical, intent(in) :: contact_scenario
    type(status_t), intent(inout) :: status
    type(driver_options_t) :: options
    real(wp) :: t_end
    type(driver_result_t) :: result
    real(wp), allocatable :: y0(:)
    integer :: k
    call expect_ok(status, name//': built')
    if (.not. status%ok()) return
    y0 = sys%initial_state(q0, qd0)
    call sys%check_start(y0, status)
    call expect_ok(status, name//': start')
    if (.not. status%ok()) return
    options%ode%method = method
    options%ode%rtol = rtol
    options%ode%atol = atol
    if (contact_scenario .and. method == ODE_ADAMS) options%ode%convergence_coefficient = &
      contact_convergence_coefficient
    t_end = duration
    options%t_end = t_end
    options%output_step = output_step
    options%min_mean_step = min_mean_step
    options%progress_seconds = 0
    call sys%start_series(nint(t_end/output_step) + 2)
    call drive(sys, y0, options, result, status)
    call expect_ok(status, name//': ran')
    associate (s => sys%series, n => sys%series%n)
      call put(name, 'simulated_time', s%time(n))
      if (contact_scenario) then
        call put(name, 'energy_change_joules', s%kinetic(n) + s%potential(n) - (s%kinetic(1) + s%potential(1)))
        do k = 1, s%nc
          call put(name, trim(s%contact_names(k))//'_slip_speed_final', norm2(s%slip(:, k, n)))
        end do
      else
        do k = 1, s%f
          call put(name, trim(s%q_names(k))//'_final', s%q(k, n))
          call put(name, trim(s%q_names(k))//'_rate_final', s%qd(k, n))
        end do
      end if
    end associate
    call put_count(name, 'steps', int(result%stats%steps))
    call put_count(name, 'rhs_evaluations', int(result%stats%rhs_evaluations))
  end subroutine run_multibody
end program shipped_descriptions
