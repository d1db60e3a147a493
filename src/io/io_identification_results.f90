!> What the identifications' results share (identify_water, identify_rider):
!> the fit's record of design_identification in the result group and in the
!> summary, in two pieces each (the cost with its parts; the speed error, the
!> runs and the CPU time) between which each writes its own figures, and the
!> measured segments. What the two say differently is an argument
!> (identification_words_t).
module io_identification_results
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_text, only: format_integer
  use design_identification, only: identification_fit_t
  use io_hdf5, only: result_file_t
  use io_summary, only: summary_t
  implicit none (type, external)
  private
  public :: identification_words_t, write_identification_segments
  public :: write_identification_cost, write_identification_runs
  public :: summarise_identification_cost, summarise_identification_runs

  !> The words of one identification's results.
  type :: identification_words_t
    character(len=:), allocatable :: weight      !< the weight's symbol: 'w', 'w_RP'
    character(len=:), allocatable :: k          !< the speed scale's: 'k1', 'k2'
    character(len=:), allocatable :: cost       !< the cost's: 'F1', 'F2'
    character(len=:), allocatable :: equation   !< the cost's equation: '(4.34)'
    character(len=:), allocatable :: runs_note, rejected_note   !< the evaluations' and the rejected ones'
                                                                 !< descriptions in the file
    character(len=:), allocatable :: runs_label, runs_unit      !< the evaluations in the summary
  end type identification_words_t

contains

  !> The weight, the speed scale k, the cost and its parts (`group` ends in '/').
  subroutine write_identification_cost(file, group, fit, k, words, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: group
    class(identification_fit_t), intent(in) :: fit
    real(wp), intent(in) :: k
    type(identification_words_t), intent(in) :: words
    type(status_t), intent(inout) :: status
    call file%write_scalar(group//'weight', fit%weight, '1', words%weight//' of '//words%equation, status)
    call file%write_scalar(group//words%k, k, 'rad s/m', words%k//' of '//words%equation, status)
    call file%write_scalar(group//'cost', fit%cost, 'rad^2', words%cost//' '//words%equation//' at the optimum', &
                           status)
    call file%write_scalar(group//'position_part', fit%position_part, 'rad^2', 'its position part', status)
    call file%write_scalar(group//'speed_part', fit%speed_part, 'rad^2', 'its speed part', status)
  end subroutine write_identification_cost

  !> The speed error, the runs (all, rejected) and the fit's CPU time; a fit
  !> that stopped early says so in the group's attribute stopped_early.
  subroutine write_identification_runs(file, group, fit, cpu, words, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: group
    class(identification_fit_t), intent(in) :: fit
    real(wp), intent(in) :: cpu
    type(identification_words_t), intent(in) :: words
    type(status_t), intent(inout) :: status
    call file%write_scalar(group//'rmse_speed', fit%rmse_speed, 'm/s', 'RMSE of the segment speeds', status)
    call file%write_count(group//'evaluations', fit%evaluations, '1', words%runs_note, status)
    call file%write_count(group//'rejected', fit%rejected, '1', words%rejected_note, status)
    call file%write_scalar(group//'cpu_time', cpu, 's', 'process CPU time of the fit', status)
    if (fit%stopped_early) call file%set_attribute(group(:len(group) - 1), 'stopped_early', &
                                                   stopped_early_text(fit), status)
  end subroutine write_identification_runs

  !> The cost and its parts in the summary.
  subroutine summarise_identification_cost(summary, fit, words)
    type(summary_t), intent(inout) :: summary
    class(identification_fit_t), intent(in) :: fit
    type(identification_words_t), intent(in) :: words
    call summary%add('cost', 'cost '//words%cost//' '//words%equation, fit%cost, 'rad^2')
    call summary%add('position_part', 'position part', fit%position_part, 'rad^2')
    call summary%add('speed_part', 'speed part', fit%speed_part, 'rad^2')
  end subroutine summarise_identification_cost

  !> The speed error, the runs and the CPU time in the summary, and an early stop.
  subroutine summarise_identification_runs(summary, fit, cpu, words)
    type(summary_t), intent(inout) :: summary
    class(identification_fit_t), intent(in) :: fit
    real(wp), intent(in) :: cpu
    type(identification_words_t), intent(in) :: words
    call summary%add('rmse_speed', 'RMSE speed', fit%rmse_speed, 'm/s')
    call summary%add_count('evaluations', words%runs_label, fit%evaluations, words%runs_unit)
    call summary%add('cpu_time', 'CPU time', cpu, 's')
    if (fit%stopped_early) call summary%add_text('stopped_early', 'stopped early', stopped_early_text(fit))
  end subroutine summarise_identification_runs

  function stopped_early_text(fit) result(text)
    class(identification_fit_t), intent(in) :: fit
    character(len=:), allocatable :: text
    text = 'the fit ended on the xtol test after '//format_integer(fit%rejected)//' rejected runs: its '// &
           'trust region may have shrunk at failed runs, not at a minimum; the estimate is the last point accepted'
  end function stopped_early_text

  !> `group` ends in '/'; the two notes describe the measured and the
  !> simulated speed in the dataset attributes.
  subroutine write_identification_segments(file, group, start, finish, measured, simulated, error, measured_note, &
                                           simulated_note, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: group, measured_note, simulated_note
    real(wp), intent(in) :: start(:), finish(:), measured(:), simulated(:), error(:)
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: s = 'segments/'
    call file%write_vector(group//s//'start', start, 'm', 'arc length where each segment starts; dimension scale', &
                           status)
    call file%write_vector(group//s//'end', finish, 'm', 'arc length where it ends', status)
    call file%write_vector(group//s//'measured_speed', measured, 'm/s', measured_note, status)
    call file%write_vector(group//s//'simulated_speed', simulated, 'm/s', simulated_note, status)
    call file%write_vector(group//s//'error', error, 'm/s', 'simulated - measured', status)
    call file%make_scale(group//s//'start', status)
    call file%attach_scale(group//s//'start', group//s, status)
  end subroutine write_identification_segments
end module io_identification_results
