!> &evaluation: what the verdicts on the rider's limits (&rider limit_*) do
!> to the run (docs/rider.md, "Limits as the exit status"). fail_on_limit
!> makes a ride (or a sweep with any ride) over a limit end with exit status
!> 4, its result file complete; the command line's --fail-on-limit does the
!> same for any input.
module io_evaluation_config
  use base_status, only: status_t
  use io_input, only: input_text_t, group_reader_t, open_group
  implicit none (type, external)
  private
  public :: evaluation_config_t, read_evaluation_config

  type :: evaluation_config_t
    logical :: fail_on_limit = .false.
  end type evaluation_config_t

contains

  subroutine read_evaluation_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(evaluation_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    call open_group(input, 'evaluation', r, status)
    call r%get('fail_on_limit', config%fail_on_limit, status)
  end subroutine read_evaluation_config
end module io_evaluation_config
