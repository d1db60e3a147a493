!> The population of a robust geometry optimisation (docs/design.md, "Robust
!> design over a population"): `&sweep` in an `optimize` input, read by the
!> sweep's own reader (io_sweep_config: lists, ranges, combine, paired, the
!> same declarations and checks) into its rows, and &optimize's
!> `population_cost` and `quantile`; design_population builds the members
!> from the rows (a member's body and start: mass, height, v0, speed0,
!> heading0_deg). The rest of &sweep does not apply to the cuboid (no water,
!> no friction, no body tables, it starts at the first section) and is
!> refused, as are the sweep's run settings (threads, progress_seconds,
!> csv_output: the optimisation's are &optimize's).
module io_optimization_population
  use base_text, only: format_integer
  use base_status, only: status_t
  use design_sweep, only: N_SWEPT, swept_names, V_SEX, V_MU, V_U0, V_HEADING, V_FLOW_RATE, V_F1, V_F2, V_F3
  use design_robust_cost, only: COST_SUM, COST_WORST, COST_QUANTILE
  use design_population, only: population_base, set_population
  use design_geometry_optimization, only: optimization_setup_t
  use io_input, only: input_text_t, group_reader_t, open_group, bounds_t, group_present
  use io_sweep_config, only: sweep_config_t, read_sweep_config, open_sweep_group, swept_given_name
  implicit none (type, external)
  private
  public :: read_optimization_population

contains

  !> setup%cost, setup%quantile and, with &sweep, setup%members and
  !> setup%start_angles (one per member). After read_optimization_config.
  subroutine read_optimization_population(input, setup, status)
    type(input_text_t), intent(in) :: input
    type(optimization_setup_t), intent(inout) :: setup
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: o, r
    type(sweep_config_t) :: sweep
    type(bounds_t) :: angle_bounds
    character(len=10) :: cost
    logical :: population
    integer :: k, i, n_design

    population = group_present(input, 'sweep')
    call open_group(input, 'optimize', o, status)
    if (.not. status%ok()) return
    cost = merge('worst', 'sum  ', population)
    call o%get('population_cost', cost, status)
    call o%get('quantile', setup%quantile, status)
    if (.not. status%ok()) return
    select case (trim(cost))
    case ('worst'); setup%cost = COST_WORST
    case ('quantile'); setup%cost = COST_QUANTILE
    case default; setup%cost = COST_SUM
    end select
    if (setup%cost /= COST_QUANTILE) call o%refuse_given(['quantile'], 'quantile is the q of population_cost = '// &
                                                          '''quantile'' only', status)
    if (.not. population .or. .not. status%ok()) return

    ! the rows of &sweep, by the sweep's reader; the base of each variable
    ! not swept is &optimize's
    call read_sweep_config(input, population_base(setup), sweep, status)
    if (.not. status%ok()) return
    call open_sweep_group(input, r, status)
    if (.not. status%ok()) return
    do k = 1, N_SWEPT
      if (.not. sweep%swept(k)) cycle
      if (any(k == [V_SEX, V_MU, V_U0, V_FLOW_RATE, V_F1, V_F2, V_F3])) then
        call r%invalid(trim(swept_names(k)), r%written(swept_given_name(r, k)), 'not a variable of the '// &
                       'optimiser''s body, a dry frictionless cuboid from the first section (scenario optimize: sweep mass, '// &
                       'height, v0, heading0_deg or speed0)', status)
        return
      end if
    end do
    call r%refuse_given([character(len=16) :: 'threads', 'progress_seconds', 'csv_output'], 'the sweep''s run '// &
                        'settings; an optimisation runs in &optimize threads and reports no CSV', status)
    if (.not. status%ok()) return

    ! the start angles: swept (in the declared range of start_angles_deg),
    ! or every row from each of start_angles_deg
    if (sweep%swept(V_HEADING)) then
      if (o%has('start_angles_deg')) then
        call o%invalid('start_angles_deg', o%written('start_angles_deg'), 'with &sweep heading0_deg the '// &
                       'members'' start angles are swept: give them there only', status)
        return
      end if
      call o%bounds('start_angles_deg', angle_bounds, status)
      do i = 1, size(sweep%values, 2)
        if (status%ok() .and. .not. angle_bounds%allows(sweep%values(V_HEADING, i))) &
          call r%invalid('heading0_deg', r%written(swept_given_name(r, V_HEADING)), 'the optimiser''s start angles, '// &
                         'as start_angles_deg: '//angle_bounds%text(), status)
      end do
      if (.not. status%ok()) return
    end if
    call set_population(setup, sweep%values, sweep%swept(V_HEADING))
    n_design = size(setup%design%lower)
    if (2*size(setup%members) < n_design .and. .not. group_present(input, 'design_elements')) &
      call r%invalid('(members)', format_integer(size(setup%members))//' rides', 'give at least '// &
                     format_integer((n_design + 1)/2)//' members for '//format_integer(n_design)// &
                     ' design variables (each ride gives two residuals)', status)
  end subroutine read_optimization_population
end module io_optimization_population
