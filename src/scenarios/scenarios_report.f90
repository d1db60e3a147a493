!> The end every scenario's printed report shares: the result file's line
!> (marked when the file is incomplete) after the printed summary, and the
!> summary as JSON where the run asks for it (&run summary_json).
module scenarios_report
  use base_status, only: status_t
  use io_run_config, only: run_config_t
  use io_summary, only: summary_t
  use io_system, only: write_standard_output
  implicit none (type, external)
  private
  public :: end_report

contains

  !> Prints the result file's line and writes the JSON summary if asked
  !> (a failure to write it goes into status).
  subroutine end_report(summary, run, path, complete, message, status)
    type(summary_t), intent(in) :: summary
    type(run_config_t), intent(in) :: run
    character(len=*), intent(in) :: path, message
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    if (complete) then
      call write_standard_output('  results                   '//path)
    else
      call write_standard_output('  results (INCOMPLETE)      '//path)
    end if
    if (allocated(run%summary_json)) then
      if (len(run%summary_json) > 0) call summary%write_json(run%summary_json, complete, message, path, status)
    end if
  end subroutine end_report
end module scenarios_report
