!> &run: which scenario to run, where to write its results.
module io_run_config
  use base_status, only: status_t
  use io_input, only: input_text_t, namelist_read_error
  implicit none (type, external)
  private
  public :: run_config_t, read_run_config

  type :: run_config_t
    character(len=64) :: scenario = 'point_mass'
    character(len=512) :: output = ''      !< default: <scenario>.h5 in the current folder
    character(len=256) :: title = ''
    !> --summary-json FILE: the printed summary's numbers as JSON; empty or not allocated: none
    character(len=:), allocatable :: summary_json
  end type run_config_t

contains

  subroutine read_run_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    character(len=64) :: scenario
    character(len=512) :: output
    character(len=256) :: title, msg
    integer :: ios
    namelist /run/ scenario, output, title

    scenario = config%scenario
    output = config%output
    title = config%title
    read (input%lines, nml=run, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, 'run', msg, [character(len=8) :: 'scenario', 'output', 'title'], status)
      return
    end if
    config%scenario = adjustl(scenario)
    config%output = adjustl(output)
    config%title = title
    if (config%output == '') config%output = trim(config%scenario)//'.h5'
  end subroutine read_run_config
end module io_run_config
