!> The list of runnable scenarios, the built-in default input, and the one entry
!> point that reads an input, checks &run and runs the scenario it names.
module scenarios_registry
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_version, only: slidesim_version
  use io_input, only: input_text_t, load_input_file, group_present, where_given
  use io_system, only: write_standard_output
  use io_output_files, only: start_run_files, claim_output
  use io_xdmf, only: xdmf_path, colon_refusal
  use io_mesh_export, only: export_result_meshes
  use io_builtin_inputs, only: builtin_input
  use io_templates, only: template_from_spec
  use io_run_config, only: run_config_t, read_run_config
  use scenarios_point_mass, only: run_point_mass
  use scenarios_pendulum, only: run_pendulum
  use scenarios_fourbar, only: run_fourbar
  use scenarios_sled, only: run_sled
  use scenarios_contact, only: run_contact
  use scenarios_geometry, only: run_geometry
  use scenarios_water, only: run_water
  use scenarios_ride, only: run_ride_scenario
  use scenarios_optimize, only: run_optimize
  use scenarios_sweep, only: run_sweep_scenario
  use scenarios_identify_rider, only: run_identify_rider
  use scenarios_identify_water, only: run_identify_water
  implicit none (type, external)
  private
  public :: run_input_file, run_default, run_input, print_scenarios, default_input, slidesim_version
  public :: scenario_template, scenario_names

  character(len=*), parameter :: scenario_names(12) = [character(len=16) :: 'ride', 'point_mass', 'geometry', &
    'water', 'pendulum', 'fourbar', 'sled', 'contact', 'optimize', 'sweep', 'identify_rider', &
    'identify_water']
  character(len=*), parameter :: scenario_summaries(12) = [character(len=80) :: &
    'the water, then a rider in it down the slide: ride report, accelerations, limits', &
    'a point mass sliding on an elementary surface (plane, ellipsoid, ...)', &
    'build a tube, slide, blended or B-spline surface; write grid and frames', &
    'stationary water flow down a tube slide: streamline, height, width, edges', &
    'a simple or double pendulum (multibody core)', &
    'a four-bar linkage closed by plane-point measurements', &
    'a bar sliding on a surface on two surface joints, closed like the rider', &
    'bodies in point contact between smooth surfaces (spinning egg, rolling)', &
    'optimise a tube slide''s shape: rides of a body, accelerations, tipping lever arm', &
    'a population of rides (riders, starts, flow rates, friction) in parallel', &
    'identify the rider''s friction mu_D from measured positions and speeds', &
    'identify the water''s friction f1, f2, f3 from measured flow positions and speeds']

contains

  !> The run's outputs are claimed before any work starts (io_output_files):
  !> the result file, its XDMF view (.xmf) and the summary JSON. Each must be
  !> creatable (its folder exists and is writable: exit 3 if not), not a
  !> folder, device, FIFO or socket (3: the finished file is renamed onto the
  !> path, which would replace it; -o /dev/null would destroy the device as
  !> root), not a file the run reads (1) and not another output (1); the
  !> result file's name has no ':' (1: the XDMF view could not name it).
  !> `from_command_line`: the result path came from -o.
  subroutine claim_outputs(input, run, from_command_line, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    logical, intent(in) :: from_command_line
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: where, path

    path = trim(run%output)
    if (from_command_line) then
      where = '-o '//path
    else
      where = where_given(input, 'run', 'output')//': &run: output = '''//path//''''
    end if
    ! the file's own name (the view references it without its folder)
    associate (file_name => path(index(path, '/', back=.true.) + 1:))
      if (len(colon_refusal(file_name)) > 0) then
        call set_status(status, STATUS_INVALID_INPUT, where//': the result file''s name '//colon_refusal(file_name))
        return
      end if
    end associate
    call claim_output(path, where, 'the result file', status)
    if (status%ok()) call claim_output(xdmf_path(path), where, 'the result file', status, part='XDMF view')
    if (.not. allocated(run%summary_json)) return
    if (status%ok() .and. len(run%summary_json) > 0) &
      call claim_output(run%summary_json, '--summary-json '//run%summary_json, 'the summary JSON', status)
  end subroutine claim_outputs

  subroutine print_scenarios()
    integer :: i
    do i = 1, size(scenario_names)
      call write_standard_output('  '//scenario_names(i)//'  '//trim(scenario_summaries(i)))
    end do
  end subroutine print_scenarios

  !> Reads the input at `path` ('-': standard input; 'builtin:<name>'),
  !> applies the command-line overrides (--set group%variable=value) and runs
  !> it. `cli` carries the command line's settings: output ('' = &run output),
  !> check_only, summary_json.
  subroutine run_input_file(path, status, cli, overrides)
    character(len=*), intent(in) :: path
    type(status_t), intent(inout) :: status
    type(run_config_t), intent(in), optional :: cli
    character(len=*), intent(in), optional :: overrides(:)
    type(input_text_t) :: input
    integer :: i
    call start_run_files()
    call load_input_file(path, input, status)
    if (present(overrides)) then
      do i = 1, size(overrides)
        if (index(overrides(i), '--unset ') == 1) then
          if (status%ok()) call input%unset(trim(overrides(i)(9:)), status)
        else
          if (status%ok()) call input%override(trim(overrides(i)), status)
        end if
      end do
    end if
    if (status%ok()) call run_input(input, status, cli)
    ! a refusal of a value an override made refers to the file's line of
    ! another variable (a contact naming the shape --set renamed): say so
    if (status%code == STATUS_INVALID_INPUT .and. allocated(input%overrides)) then
      if (len(input%overrides) > 0 .and. index(status%text(), '--set ') == 0 .and. &
          index(status%text(), '--unset ') == 0) status%message = status%text()// &
        ' (in the input as changed by '//overrides_applied(input%overrides)//')'
    end if
  end subroutine run_input_file

  !> The --set arguments (one a line) as one line: "--set a%b=1, --set c%d=2".
  pure function overrides_applied(lines) result(text)
    character(len=*), intent(in) :: lines
    character(len=:), allocatable :: text
    integer :: start, i
    text = ''
    start = 1
    do i = 1, len(lines)
      if (lines(i:i) /= new_line('a')) cycle
      if (len(text) > 0) text = text//', '
      text = text//lines(start:i - 1)
      start = i + 1
    end do
  end function overrides_applied

  !> Runs the built-in default input, inputs/default.nml compiled into the program.
  subroutine run_default(status, cli, overrides)
    type(status_t), intent(inout) :: status
    type(run_config_t), intent(in), optional :: cli
    character(len=*), intent(in), optional :: overrides(:)
    call run_input_file('builtin:default', status, cli, overrides)
  end subroutine run_default

  !> The commented template of a scenario (for --default-input SCENARIO),
  !> generated from the declarations and the scenario's spec
  !> (inputs/templates/specs/<scenario>.spec, compiled in; io_templates).
  subroutine scenario_template(scenario, text, found)
    character(len=*), intent(in) :: scenario
    character(len=:), allocatable, intent(out) :: text
    logical, intent(out) :: found
    character(len=:), allocatable :: spec, error
    call builtin_input('template_spec_'//scenario, spec, found)
    if (.not. found) return
    call template_from_spec(scenario, spec, text, error)
    ! a spec naming an undeclared variable is slidesim's error (cli_template_declarations)
    if (len(error) > 0) error stop 'the template of '//scenario//' cannot be generated: '//error
  end subroutine scenario_template

  !> The text of the built-in default input (for --default-input).
  function default_input() result(text)
    character(len=:), allocatable :: text
    logical :: found
    call builtin_input('default', text, found)
  end function default_input

  subroutine run_input(input, status, cli)
    type(input_text_t), intent(in) :: input
    type(status_t), intent(inout) :: status
    type(run_config_t), intent(in), optional :: cli
    type(run_config_t) :: run
    logical :: cli_output

    if (size(input%groups) == 0) then
      call set_status(status, STATUS_INVALID_INPUT, input%name//': the input is empty: it has no namelist '// &
                      'groups (slidesim --default-input prints a complete example)')
      return
    end if
    if (.not. group_present(input, 'run')) then
      call set_status(status, STATUS_INVALID_INPUT, input%name//': no &run group; every input names its '// &
                      'scenario there (slidesim --default-input prints a complete example)')
      return
    end if
    if (present(cli)) then
      run%check_only = cli%check_only
      run%fail_on_limit = cli%fail_on_limit
      if (allocated(cli%summary_json)) run%summary_json = cli%summary_json
      if (allocated(cli%export_stl)) run%export_stl = cli%export_stl
      if (allocated(cli%export_obj)) run%export_obj = cli%export_obj
      if (allocated(cli%ride_csv)) run%ride_csv = cli%ride_csv
    end if
    if (.not. allocated(run%ride_csv)) run%ride_csv = ''
    if (.not. allocated(run%export_stl)) run%export_stl = ''
    if (.not. allocated(run%export_obj)) run%export_obj = ''
    call read_run_config(input, scenario_names, run, status)
    if (.not. status%ok()) return
    if (run%fail_on_limit .and. all(trim(run%scenario) /= [character(len=5) :: 'ride', 'sweep', 'sled'])) then
      call set_status(status, STATUS_INVALID_INPUT, input%name//': --fail-on-limit: scenario '// &
                      trim(run%scenario)//' judges no ride limits (ride, sweep and a vehicle''s sled do)')
      return
    end if
    cli_output = .false.
    if (present(cli)) then
      cli_output = len_trim(cli%output) > 0
      if (cli_output) run%output = cli%output
    end if
    call claim_outputs(input, run, cli_output, status)
    if (.not. status%ok()) return
    call check_exports(run, status)
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
    case ('contact')
      call run_contact(input, run, status)
    case ('geometry')
      call run_geometry(input, run, status)
    case ('water')
      call run_water(input, run, status)
    case ('ride')
      call run_ride_scenario(input, run, status)
    case ('optimize')
      call run_optimize(input, run, status)
    case ('sweep')
      call run_sweep_scenario(input, run, status)
    case ('identify_rider')
      call run_identify_rider(input, run, status)
    case ('identify_water')
      call run_identify_water(input, run, status)
    end select
    if (status%ok() .and. run%check_only) call write_standard_output(input%name//': input ok (scenario '// &
      trim(run%scenario)//'; results would go to '//trim(run%output)//')')
    if (status%ok() .and. .not. run%check_only .and. len(run%export_stl) + len(run%export_obj) > 0) &
      call export_result_meshes(trim(run%output), run%export_stl, run%export_obj, status)
  end subroutine run_input

  !> --ride-csv, --export-stl and --export-obj: refused before any work for
  !> a scenario without a ride or a surface grid (exit 1); their files
  !> claimed as every output is (io_output_files).
  subroutine check_exports(run, status)
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    if (len(run%ride_csv) > 0) then
      if (trim(run%scenario) /= 'ride') then
        call set_status(status, STATUS_INVALID_INPUT, '--ride-csv '//run%ride_csv//': a '//trim(run%scenario)// &
                        ' run has no ride time series (scenario ride)')
        return
      end if
      call claim_output(run%ride_csv, '--ride-csv '//run%ride_csv, 'the ride CSV', status)
      if (.not. status%ok()) return
    end if
    if (len(run%export_stl) + len(run%export_obj) == 0) return
    select case (trim(run%scenario))
    case ('pendulum', 'fourbar')
      call set_status(status, STATUS_INVALID_INPUT, '--export-'//merge('stl', 'obj', len(run%export_stl) > 0)// &
                      ': a '//trim(run%scenario)//' run has no surface to export (scenarios with one: '// &
                      'geometry, water, ride, point_mass, sled, contact, optimize, sweep, identify_water, '// &
                      'identify_rider)')
      return
    end select
    if (len(run%export_stl) > 0) call claim_output(run%export_stl, '--export-stl '//run%export_stl, &
                                                   'the STL export', status)
    if (len(run%export_obj) > 0 .and. status%ok()) &
      call claim_output(run%export_obj, '--export-obj '//run%export_obj, 'the OBJ export', status)
  end subroutine check_exports
end module scenarios_registry
