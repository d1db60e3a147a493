!> &run: which scenario to run, where to write its results; and the options of
!> the command line that reach the scenarios.
module io_run_config
  use base_status, only: status_t
  use io_input, only: input_text_t, group_reader_t, open_group
  implicit none (type, external)
  private
  public :: run_config_t, read_run_config

  type :: run_config_t
    character(len=64) :: scenario = 'point_mass'
    character(len=4096) :: output = ''     !< default: <scenario>.h5 in the current folder
    character(len=256) :: title = ''
    !> --check: read every input and build the models, then stop (nothing written).
    logical :: check_only = .false.
    !> --summary-json FILE: the printed summary's numbers as JSON; empty or not allocated: none
    character(len=:), allocatable :: summary_json
    !> --fail-on-limit: a ride (or sweep) over a limit ends with exit status 4
    logical :: fail_on_limit = .false.
    !> --export-stl FILE, --export-obj FILE: the slide surface and the water band as
    !> a mesh (io_mesh_export); empty or not allocated: none
    character(len=:), allocatable :: export_stl, export_obj
    !> --ride-csv FILE: a ride's time series as CSV (scenario ride); empty or not allocated: none
    character(len=:), allocatable :: ride_csv
  end type run_config_t

contains

  !> `scenarios` are the names &run scenario may take.
  subroutine read_run_config(input, scenarios, config, status)
    type(input_text_t), intent(in) :: input
    character(len=*), intent(in) :: scenarios(:)
    type(run_config_t), intent(inout) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r

    call open_group(input, 'run', r, status)
    call r%get('scenario', config%scenario, status, choices=scenarios)
    call r%get('output', config%output, status)
    call r%get('title', config%title, status)
    config%output = adjustl(config%output)
    if (config%output == '') config%output = trim(config%scenario)//'.h5'
    if (.not. allocated(config%summary_json)) config%summary_json = ''
  end subroutine read_run_config
end module io_run_config
