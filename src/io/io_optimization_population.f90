!> The population of a robust geometry optimisation (docs/design.md, "Robust
!> design over a population"): `&sweep` in an `optimize` input, read by the
!> sweep's own reader (io_sweep_config: lists, ranges, combine, paired, the
!> same declarations and checks), and &optimize's `population_cost` and
!> `quantile`. A member is one ride of the optimiser's cuboid:
!>   mass          the body's mass (kg);
!>   height        the body's length along the slide (m, a person's height),
!>                 its width, thickness (body_height) and com_height scaled
!>                 with it from &optimize's body;
!>   v0            where on the first section it starts (rad, pi/2 the bottom);
!>   speed0        its start speed (m/s);
!>   heading0_deg  its start direction to the centerline (deg), in place of
!>                 start_angles_deg; not swept: each row of &sweep rides from
!>                 every start angle of start_angles_deg (the angles fastest).
!> The rest of &sweep does not apply to the cuboid (no water, no friction,
!> no body tables, it starts at the first section) and is refused, as are
!> the sweep's run settings (threads, progress_seconds, csv_output: the
!> optimisation's are &optimize's).
module io_optimization_population
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_integer
  use base_status, only: status_t
  use design_sweep, only: N_SWEPT, swept_names, V_SEX, V_MASS, V_HEIGHT, V_MU, V_U0, V_V0, V_HEADING, V_SPEED, &
    V_FLOW_RATE, V_F1, V_F2, V_F3
  use design_robust_cost, only: ride_member_t, COST_SUM, COST_WORST, COST_QUANTILE
  use design_geometry_optimization, only: optimization_setup_t
  use io_input, only: input_text_t, group_reader_t, open_group, bounds_t, format_real, group_present
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
    real(wp) :: base(N_SWEPT)
    real(wp), allocatable :: angles(:)
    logical :: population
    integer :: k, j, i, n_rows, n_angles, n_design

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
    base = 0
    base(V_SEX) = 1
    base(V_MASS) = setup%body%mass
    base(V_HEIGHT) = setup%body%length
    base(V_V0) = setup%start_v
    base(V_SPEED) = setup%start_speed
    call read_sweep_config(input, base, sweep, status)
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

    ! the start angles: swept, or every row from each of start_angles_deg
    n_rows = size(sweep%values, 2)
    if (sweep%swept(V_HEADING)) then
      if (o%has('start_angles_deg')) then
        call o%invalid('start_angles_deg', o%written('start_angles_deg'), 'with &sweep heading0_deg the '// &
                       'members'' start angles are swept: give them there only', status)
        return
      end if
      call o%bounds('start_angles_deg', angle_bounds, status)
      do i = 1, n_rows
        if (status%ok() .and. .not. angle_bounds%allows(sweep%values(V_HEADING, i))) &
          call r%invalid('heading0_deg', r%written(swept_given_name(r, V_HEADING)), 'the optimiser''s start angles, '// &
                         'as start_angles_deg: '//angle_bounds%text(), status)
      end do
      if (.not. status%ok()) return
      angles = sweep%values(V_HEADING, :)*pi/180
      n_angles = 1
    else
      angles = setup%start_angles
      n_angles = size(angles)
    end if
    allocate (setup%members(n_rows*n_angles))
    deallocate (setup%start_angles)
    allocate (setup%start_angles(n_rows*n_angles))
    do i = 1, n_rows
      do j = 1, n_angles
        setup%members((i - 1)*n_angles + j) = member(sweep%values(:, i))
        setup%start_angles((i - 1)*n_angles + j) = angles(merge(i, j, sweep%swept(V_HEADING)))
      end do
    end do
    n_design = size(setup%design%lower)
    if (2*size(setup%members) < n_design .and. .not. group_present(input, 'design_elements')) &
      call r%invalid('(members)', format_integer(size(setup%members))//' rides', 'give at least '// &
                     format_integer((n_design + 1)/2)//' members for '//format_integer(n_design)// &
                     ' design variables (each ride gives two residuals)', status)

  contains

    !> The member of one row: &optimize's body scaled to its height.
    pure function member(v) result(m)
      real(wp), intent(in) :: v(N_SWEPT)
      type(ride_member_t) :: m
      real(wp) :: scale
      scale = v(V_HEIGHT)/setup%body%length
      m%body = setup%body
      m%body%mass = v(V_MASS)
      m%body%length = v(V_HEIGHT)
      m%body%width = setup%body%width*scale
      m%body%height = setup%body%height*scale
      m%body%com_height = setup%body%com_height*scale
      m%height = v(V_HEIGHT)
      m%speed = v(V_SPEED)
      m%v = v(V_V0)
    end function member
  end subroutine read_optimization_population
end module io_optimization_population
