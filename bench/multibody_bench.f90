!> Benchmark of the multibody core: for each built-in case integrates the whole
!> span 5 times (no output, no recording) and prints the median CPU seconds per
!> simulated second, right-hand-side evaluations, steps and closure solves.
!> The sled is the model of the rider's cost (goal: < 0.05 s CPU per simulated
!> second at rtol 1e-10).
program multibody_bench
  use base_kinds, only: wp, int64
  use base_constants, only: pi
  use base_status, only: status_t
  use numerics_ode, only: ode_integrator_t, ode_options_t, ode_stats_t, ODE_BDF
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t, paraboloid_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: pendulum_params_t, build_pendulum, fourbar_params_t, build_fourbar, &
    fourbar_assembly, sled_params_t, build_sled, sled_description_t
  use kinetostatics_force_law_factory, only: law_spec
  use io_input, only: input_text_t, load_input_file
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_surface_config, only: read_surface_config, surface_source_t
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use bench_timing, only: median
  implicit none (type, external)

  integer, parameter :: repeats = 5
  real(wp), parameter :: theta = 20*pi/180

  print '(a44, a14, a12, a10, a10, a10, a8)', 'case', 'CPU s/sim s', 'rhs evals', 'steps', 'hybrj', 'roots', 'cached'
  call run_case('pendulum, simple, 20 s, rtol 1e-12', 1)
  call run_case('pendulum, double, 20 s, rtol 1e-12', 2)
  call run_case('fourbar, 5 s, rtol 1e-12', 3)
  call run_case('sled, incline, Coulomb 0.2, 2 s, rtol 1e-10', 4)
  call run_case('sled, paraboloid bowl, 10 s, rtol 1e-10', 5)
  call run_case('sled, bowl, Coulomb 0.15, BDF 1e-8, 10 s', 6)
  call run_case('sled, demo slide, Coulomb 0.05, 8 s, 1e-10', 7)

contains

  subroutine build(which, sys, y0, duration, options, status)
    integer, intent(in) :: which
    type(mechanism_ode_t), intent(out) :: sys
    real(wp), allocatable, intent(out) :: y0(:)
    real(wp), intent(out) :: duration
    type(ode_options_t), intent(out) :: options
    type(status_t), intent(inout) :: status
    type(pendulum_params_t) :: pp
    type(fourbar_params_t) :: fp
    type(sled_params_t) :: sp
    class(surface_t), allocatable :: surface
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: source
    real(wp) :: beta0(2)
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(sled_description_t) :: sled
    options%rtol = 1e-12_wp
    options%atol = 1e-12_wp
    select case (which)
    case (1, 2)
      pp%links = which
      pp%length = [1.0_wp, 0.7_wp]
      pp%mass = [1.0_wp, 0.6_wp]
      call build_pendulum(pp, sys%mechanism, status)
      y0 = [1.2_wp, -0.5_wp, 0.0_wp, 1.0_wp]
      if (which == 1) y0 = [0.5_wp, 0.0_wp]
      duration = 20
    case (3)
      call fourbar_assembly(fp, 0.3_wp, 1, beta0, status)
      call build_fourbar(fp, beta0, sys%mechanism, status)
      y0 = [0.3_wp, 12.0_wp]
      duration = 5
    case (7)   ! the sled input on the demo slide (run from the repository root)
      call load_input_file('inputs/sled/demo_slide.nml', input, status)
      if (status%ok()) call read_solver_config(input, solver, status)
      if (status%ok()) call read_surface_config(input, surface_description, status, source)
      if (status%ok()) call build_surface(surface_description, surface, status)
      if (status%ok()) call read_sled_config(input, sled, status)
      if (.not. status%ok()) return
      options = solver%options
      duration = solver%duration
      call build_sled(sled%params, surface, sled%q0, sys%mechanism, status)
      y0 = sys%initial_state(sled%q0, sled%qd0)
    case default
      options%rtol = 1e-10_wp
      options%atol = 1e-10_wp
      if (which == 4) then
        surface = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(theta), 0.0_wp, -sin(theta)], &
                          [0.0_wp, 1.0_wp, 0.0_wp], status)
        sp%friction = [law_spec('coulomb', 'mu', 0.2_wp)]
        y0 = [0.5_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp]
        duration = 2
      else
        surface = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, status)
        y0 = [1.0_wp, 0.0_wp, 0.3_wp, 0.0_wp, 1.2_wp, 0.5_wp]
        duration = 10
        if (which == 6) then
          sp%friction = [law_spec('coulomb', 'mu', 0.15_wp)]
          options%method = ODE_BDF
          options%rtol = 1e-8_wp
        end if
      end if
      call build_sled(sp, surface, y0(1:3), sys%mechanism, status)
      y0 = sys%initial_state(y0(1:3), y0(4:6))
    end select
    if (status%ok()) call sys%mechanism%check_start(sys%work, y0(1:sys%mechanism%f), status)
  end subroutine build

  subroutine run_case(label, which)
    character(len=*), intent(in) :: label
    integer, intent(in) :: which
    type(mechanism_ode_t), target :: sys
    type(ode_integrator_t) :: ode
    type(ode_options_t) :: options
    type(ode_stats_t) :: stats
    type(status_t) :: status
    real(wp), allocatable :: y0(:), y(:)
    real(wp) :: duration, t, start, finish, cpu(repeats)
    integer :: r, hybrj, root_calls, hits
    do r = 1, repeats
      call build(which, sys, y0, duration, options, status)
      if (.not. status%ok()) exit
      y = y0
      call cpu_time(start)
      call ode%start(sys, 0.0_wp, y0, options, status)
      if (status%ok()) call ode%advance(duration, t, y, status)
      call cpu_time(finish)
      if (.not. status%ok()) exit
      cpu(r) = (finish - start)/duration
      stats = ode%statistics()
      hybrj = sys%work%hybrj_solves
      root_calls = sys%root_calls
      hits = sys%root_cache_hits
    end do
    if (.not. status%ok()) then
      print '(a44, 2x, a)', label, 'FAILED: '//status%text()
      return
    end if
    print '(a44, es14.3, i12, i10, i10, i10, i8)', label, median(cpu), int(stats%rhs_evaluations), &
      int(stats%steps), hybrj, root_calls, hits
  end subroutine run_case
end program multibody_bench
