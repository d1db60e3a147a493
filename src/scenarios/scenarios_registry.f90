!> The list of runnable scenarios, the built-in default input, and the one entry
!> point that reads an input, checks &run and runs the scenario it names.
module scenarios_registry
  use, intrinsic :: iso_fortran_env, only: output_unit
  use base_status, only: status_t
  use base_version, only: slidesim_version
  use io_input, only: input_text_t, load_input_file, input_from_text, check_choice
  use io_run_config, only: run_config_t, read_run_config
  use scenarios_point_mass, only: run_point_mass
  use scenarios_pendulum, only: run_pendulum
  use scenarios_fourbar, only: run_fourbar
  use scenarios_sled, only: run_sled
  use scenarios_geometry, only: run_geometry
  use scenarios_water, only: run_water
  implicit none (type, external)
  private
  public :: run_input_file, run_default, run_input, print_scenarios, default_input, slidesim_version

  character(len=*), parameter :: scenario_names(6) = [character(len=16) :: 'point_mass', 'geometry', 'water', &
    'pendulum', 'fourbar', 'sled']
  character(len=*), parameter :: scenario_summaries(6) = [character(len=80) :: &
    'a point mass sliding on an elementary surface (plane, ellipsoid, ...)', &
    'build a tube, slide, blended or B-spline surface; write grid and frames', &
    'stationary water flow down a tube slide: streamline, height, width, edges', &
    'a simple or double pendulum (multibody core)', &
    'a four-bar linkage closed by plane-point measurements', &
    'a bar sliding on a surface on two surface joints, closed like the rider']

  !> The built-in default: a point mass sliding down an inclined half-pipe (an
  !> elliptic cylinder of radius 0.5 m whose axis falls 10 degrees), started off the
  !> bottom with a sideways push, with Coulomb friction mu = 0.05.
  character(len=*), parameter :: nl = new_line('a')
  character(len=*), parameter :: default_input = &
    '! slidesim built-in default input (print it with: slidesim --default-input)'//nl// &
    '&run'//nl// &
    '  scenario = ''point_mass'''//nl// &
    '  output = ''slidesim_default.h5'''//nl// &
    '  title = ''point mass in an inclined half-pipe'''//nl// &
    '/'//nl// &
    '&solver'//nl// &
    '  method = ''adams'', rtol = 1e-10, atol = 1e-10'//nl// &
    '  duration = 5.0, output_step = 0.01'//nl// &
    '/'//nl// &
    '&surface'//nl// &
    '  kind = ''elliptic_cylinder'', a = 0.5, b = 0.5'//nl// &
    '  ! axis (u) horizontal along x, then tipped 10 degrees down'//nl// &
    '  angles_deg = 0.0, 100.0, 0.0'//nl// &
    '/'//nl// &
    '&point_mass'//nl// &
    '  mass = 1.0'//nl// &
    '  u0 = 0.0, v0 = 0.3, du0 = 2.0, dv0 = 3.0'//nl// &
    '  friction = ''coulomb'', friction_coefficient = 0.05'//nl// &
    '/'

contains

  subroutine print_scenarios()
    integer :: i
    do i = 1, size(scenario_names)
      write (output_unit, '(2x, a16, 2x, a)') scenario_names(i), trim(scenario_summaries(i))
    end do
  end subroutine print_scenarios

  subroutine run_input_file(path, status, output)
    character(len=*), intent(in) :: path
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: output
    type(input_text_t) :: input
    call load_input_file(path, input, status)
    if (status%ok()) call run_input(input, status, output)
  end subroutine run_input_file

  subroutine run_default(status, output)
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: output
    type(input_text_t) :: input
    call input_from_text('<built-in default>', default_input, input)
    call run_input(input, status, output)
  end subroutine run_default

  subroutine run_input(input, status, output)
    type(input_text_t), intent(in) :: input
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: output
    type(run_config_t) :: run

    call read_run_config(input, run, status)
    if (.not. status%ok()) return
    if (present(output)) run%output = output
    call check_choice(input, 'run', 'scenario', run%scenario, scenario_names, status)
    if (.not. status%ok()) return
    select case (trim(run%scenario))
    case ('point_mass')
      call run_point_mass(input, run, status)
    case ('pendulum')
      call run_pendulum(input, run, status)
    case ('fourbar')
      call run_fourbar(input, run, status)
    case ('sled')
      call run_sled(input, run, status)
    case ('geometry')
      call run_geometry(input, run, status)
    case ('water')
      call run_water(input, run, status)
    end select
  end subroutine run_input
end module scenarios_registry
