!> The end every scenario's printed report shares: the result file's line
!> (marked when the file is incomplete) after the printed summary, and the
!> summary as JSON where the run asks for it (&run summary_json). Either the
!> result file's line is printed after the summary (end_report: not in the
!> JSON) or it is the summary's last entry (close_report: in the JSON too).
module scenarios_report
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_stats_t
  use io_run_config, only: run_config_t
  use io_summary, only: summary_t
  use io_system, only: write_standard_output
  use base_text, only: format_short, format_integer
  use water_series, only: water_series_t
  implicit none (type, external)
  private
  public :: end_report, close_report, add_run_cost, inlets_text

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
    call write_json(summary, run, path, complete, message, status)
  end subroutine end_report

  !> Adds the result file as the summary's last entry, prints the summary and
  !> writes the JSON summary if asked.
  subroutine close_report(summary, run, path, complete, message, status)
    type(summary_t), intent(inout) :: summary
    type(run_config_t), intent(in) :: run
    character(len=*), intent(in) :: path, message
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    call summary%add_results(path, complete)
    call summary%print()
    call write_json(summary, run, path, complete, message, status)
  end subroutine close_report

  !> The integrator's steps and right-hand sides and the run's CPU time.
  subroutine add_run_cost(summary, stats, cpu)
    type(summary_t), intent(inout) :: summary
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    call summary%add_count('steps', 'integrator', int(stats%steps), 'steps')
    call summary%add_count('rhs_evaluations', 'right-hand sides', int(stats%rhs_evaluations), 'evaluations')
    call summary%add('cpu_time', 'CPU time', cpu, 's')
  end subroutine add_run_cost

  subroutine write_json(summary, run, path, complete, message, status)
    type(summary_t), intent(in) :: summary
    type(run_config_t), intent(in) :: run
    character(len=*), intent(in) :: path, message
    logical, intent(in) :: complete
    type(status_t), intent(inout) :: status
    if (allocated(run%summary_json)) then
      if (len(run%summary_json) > 0) call summary%write_json(run%summary_json, complete, message, path, status)
    end if
  end subroutine write_json

  !> The summary's words for the inlets downstream of the start: '' without
  !> any, else how many joined and the flow at the end (the water line's
  !> flow rate is the start's).
  function inlets_text(series) result(text)
    type(water_series_t), intent(in) :: series
    character(len=:), allocatable :: text
    text = ''
    if (.not. allocated(series%inlets)) return
    if (size(series%inlets) == 0 .or. series%n < 1) return
    text = ' at the start, '//format_short(series%flow(series%n))//' m^3/s at the end ('// &
           format_integer(count(series%inlets%joined))//' of '//format_integer(size(series%inlets))// &
           ' inlets joined)'
  end function inlets_text
end module scenarios_report
