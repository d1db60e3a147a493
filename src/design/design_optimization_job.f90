!> One optimisation job (docs/design.md; the library's call behind scenario
!> `optimize`): the geometry optimisation of a setup (optimize_slide), the
!> rides of its end afresh with their samples, and with a catalogue of
!> standard parts the end snapped to it and its neighbourhood ridden
!> (choose_from_catalogue). Prints nothing (setup%log gets its lines when
!> associated); the command writes and reports the job's result.
module design_optimization_job
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_NOT_CONVERGED
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, design_evaluation_t, &
    optimize_slide, evaluate_design, OUTCOME_OPTIMUM
  use design_catalogue, only: catalogue_t, catalogue_result_t, choose_from_catalogue
  implicit none (type, external)
  private
  public :: optimization_job_t, run_optimization

  type :: optimization_job_t
    type(optimization_result_t) :: result     !< optimize_slide's
    type(design_evaluation_t) :: after        !< the end's rides, with their series
    logical :: ended = .false.                !< an end point was reached: result and after hold it
    logical :: with_catalogue = .false.       !< a catalogue was given: `chosen` holds its design (when ended)
    type(catalogue_result_t) :: chosen
    real(wp) :: cpu_seconds = 0               !< process CPU time of optimize_slide
  end type optimization_job_t

contains

  !> Runs the job. status: not ok when no end point was reached, or a
  !> catalogue does not fit the design (job%ended false); an end that is no
  !> optimum, or a catalogue without a feasible design, is
  !> STATUS_NOT_CONVERGED with the verdict (job%ended true, all written).
  subroutine run_optimization(setup, job, status, catalogue)
    type(optimization_setup_t), intent(in) :: setup
    type(optimization_job_t), intent(out) :: job
    type(status_t), intent(out) :: status
    type(catalogue_t), intent(in), optional :: catalogue
    real(wp) :: cpu0, cpu1
    call cpu_time(cpu0)
    call optimize_slide(setup, job%result, status)
    call cpu_time(cpu1)
    job%cpu_seconds = cpu1 - cpu0
    if (status%ok()) call evaluate_design(setup, job%result%x, job%after, status, keep_series=.true.)
    job%ended = status%ok()
    job%with_catalogue = present(catalogue)
    if (job%ended .and. present(catalogue)) then
      if (associated(setup%log)) call setup%log('optimize: the end snapped to the catalogue, its neighbourhood ridden')
      call choose_from_catalogue(setup, catalogue, job%result%x, job%chosen, status)
      job%ended = status%ok()
    end if
    if (.not. job%ended) return
    if (job%result%outcome /= OUTCOME_OPTIMUM) then
      call set_status(status, STATUS_NOT_CONVERGED, 'optimize: '//job%result%verdict)
    else if (present(catalogue)) then
      if (.not. job%chosen%feasible) call set_status(status, STATUS_NOT_CONVERGED, 'optimize: catalogue: '// &
                                                     job%chosen%verdict)
    end if
  end subroutine run_optimization
end module design_optimization_job
