!> The population of a robust geometry optimisation in the result file and
!> the summary (docs/design.md, "Robust design over a population"): every
!> member's body and start, the cost's statistic, and which member is the
!> worst for the start and the end design, with its figures.
module scenarios_optimize_population
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_text, only: format_integer, format_short, format_with
  use base_status, only: status_t
  use io_hdf5, only: result_file_t
  use io_summary, only: summary_t, degrees
  use design_robust_cost, only: COST_SUM, COST_QUANTILE, cost_names, cost_description
  use design_geometry_optimization, only: optimization_setup_t, design_evaluation_t
  implicit none (type, external)
  private
  public :: write_population, report_population, worst_member_text, lever_text

contains

  !> /optimize/population (with a population) and the cost's statistic as
  !> attributes of /optimize (with a statistic other than the sum).
  subroutine write_population(file, setup, before, after, optimized, status)
    type(result_file_t), intent(inout) :: file
    type(optimization_setup_t), intent(in) :: setup
    type(design_evaluation_t), intent(in) :: before, after
    logical, intent(in) :: optimized
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/optimize/population/'
    integer :: k
    if (.not. robust(setup)) return   ! the ordinary optimisation's file as before
    if (setup%cost /= COST_SUM) then
      call file%set_attribute('/optimize', 'population_cost', trim(cost_names(setup%cost)), status)
      if (setup%cost == COST_QUANTILE) call file%set_attribute('/optimize', 'quantile', setup%quantile, status)
      call file%set_attribute('/optimize', 'cost_statistic', cost_description(setup%cost, setup%quantile), status)
      call file%write_scalar('/optimize/before/robust_acceleration', before%robust_acceleration, 'm/s^2', &
                             'the statistic of the rides'' largest accelerations the cost squares', status)
      if (optimized) call file%write_scalar('/optimize/after/robust_acceleration', after%robust_acceleration, &
                                            'm/s^2', 'the statistic of the rides'' largest accelerations the '// &
                                            'cost squares', status)
    end if
    call file%write_count('/optimize/before/worst_ride', before%worst_ride, '1', &
                          'the ride (member) of the largest acceleration, 1 = the first', status)
    if (optimized) call file%write_count('/optimize/after/worst_ride', after%worst_ride, '1', &
                                         'the ride (member) of the largest acceleration, 1 = the first', status)
    if (.not. allocated(setup%members)) return
    associate (m => setup%members)
      call file%write_vector(g//'member', [(real(k, wp), k=1, size(m))], '1', &
                             'number of each member (1 = the first); dimension scale', status)
      call file%write_vector(g//'mass', m%body%mass, 'kg', 'the body''s mass', status)
      call file%write_vector(g//'height', m%height, 'm', 'the member''s height: the body''s length', status)
      call file%write_vector(g//'body_width', m%body%width, 'm', 'the body''s width (scaled with the height)', status)
      call file%write_vector(g//'body_height', m%body%height, 'm', 'the body''s thickness along the normal '// &
                             '(scaled with the height)', status)
      call file%write_vector(g//'com_height', m%body%com_height, 'm', 'its centre of mass above the surface '// &
                             '(scaled with the height)', status)
      call file%write_vector(g//'speed0', m%speed, 'm/s', 'start speed', status)
      call file%write_vector(g//'v0', m%v, 'rad', 'start section angle (pi/2 the bottom)', status)
      call file%write_vector(g//'heading0_deg', setup%start_angles*degrees, 'degree', &
                             'start direction to the centerline, + towards +v', status)
    end associate
    call file%make_scale(g//'member', status)
    call file%attach_scale(g//'member', g, status)
  end subroutine write_population

  !> Whether the optimisation is over a population or by a statistic other
  !> than the sum (else its file and summary are the ordinary ones).
  pure logical function robust(setup)
    type(optimization_setup_t), intent(in) :: setup
    robust = allocated(setup%members) .or. setup%cost /= COST_SUM
  end function robust

  !> Member (or ride) k in words, with its largest acceleration in `e`.
  function worst_member_text(setup, e) result(text)
    type(optimization_setup_t), intent(in) :: setup
    type(design_evaluation_t), intent(in) :: e
    character(len=:), allocatable :: text
    integer :: k
    k = e%worst_ride
    if (allocated(setup%members)) then
      associate (m => setup%members(k))
        text = 'member '//format_integer(k)//' (height '//format_short(m%height)//' m, mass '// &
               format_short(m%body%mass)//' kg, speed0 '//format_short(m%speed)//' m/s, wall angle '// &
               format_short((m%v - pi/2)*degrees)//' deg, heading '//format_short(setup%start_angles(k)*degrees)// &
               ' deg)'
      end associate
    else
      text = 'ride '//format_integer(k)//' (from '//format_short(setup%start_angles(k)*degrees)//' deg)'
    end if
    associate (r => e%rides(k))
      text = text//': max |a| '//format_short(r%max_acceleration)//' m/s^2 at t = '// &
             format_short(r%time_of_max)//' s'
      if (r%lifts_off) then
        text = text//', lifts off'
      else
        text = text//', lever arm up to '//format_short(r%max_lever_arm)//' m'
      end if
    end associate
  end function worst_member_text

  !> The population's lines of the summary: its size, the statistic, the
  !> worst member at the start and the end, the member table.
  subroutine report_population(summary, setup, before, after, end)
    type(summary_t), intent(inout) :: summary
    type(optimization_setup_t), intent(in) :: setup
    type(design_evaluation_t), intent(in) :: before, after
    character(len=*), intent(in) :: end   !< 'optimum' or 'end (no optimum)'
    real(wp), allocatable :: table(:, :)
    integer :: k, n
    n = size(setup%start_angles)
    if (.not. robust(setup)) return
    if (allocated(setup%members)) call summary%add_count('population_size', 'population (&sweep)', n, &
                                                         'members, one ride each')
    call summary%add_text('population_cost', 'cost over the rides', cost_description(setup%cost, setup%quantile))
    if (setup%cost /= COST_SUM) then
      call summary%add('robust_acceleration_start', 'cost''s max |a|, start', before%robust_acceleration, 'm/s^2')
      call summary%add('robust_acceleration', 'cost''s max |a|, '//end, after%robust_acceleration, 'm/s^2')
    end if
    call summary%add_text('worst_start', 'worst ride, start', worst_member_text(setup, before))
    call summary%add_text('worst', 'worst ride, '//end, worst_member_text(setup, after))
    if (.not. allocated(setup%members)) return
    allocate (table(8, n))
    do k = 1, n
      associate (m => setup%members(k))
        table(:, k) = [real(k, wp), m%height, m%body%mass, m%speed, (m%v - pi/2)*degrees, &
                       setup%start_angles(k)*degrees, after%rides(k)%max_acceleration, &
                       min(after%rides(k)%max_lever_arm, 1e30_wp)]
      end associate
    end do
    call summary%add_table('members', [character(len=17) :: 'member', 'height', 'mass', 'speed0', 'wall_angle', &
                           'heading', 'max_a_end', 'lever_arm_end'], &
                           [character(len=5) :: '1', 'm', 'kg', 'm/s', 'deg', 'deg', 'm/s^2', 'm'], table)
    call summary%add_line('  member  height (m)  mass (kg)  speed0 (m/s)  wall (deg)  heading (deg)  '// &
                          'max |a| end (m/s^2)  lever arm end (m)')
    do k = 1, n
      call summary%add_line('  '//repeat(' ', max(0, 6 - len(format_integer(k))))//format_integer(k)// &
        format_with(table(2, k), 'f12.3')// &
        format_with(table(3, k), 'f11.1')//format_with(table(4, k), 'f14.3')//format_with(table(5, k), 'f12.2')// &
        format_with(table(6, k), 'f15.2')//format_with(table(7, k), 'f21.4')//lever_text(table(8, k), 19))
    end do
  end subroutine report_population

  !> A lever arm in a table column of `width`: 'f<width>.4', or 'lift-off'
  !> right-aligned for the lift-off mark (1e30 or more).
  pure function lever_text(x, width) result(text)
    real(wp), intent(in) :: x
    integer, intent(in) :: width
    character(len=width) :: text
    if (x >= 1e30_wp) then
      text = repeat(' ', width - 8)//'lift-off'
    else
      text = format_with(x, 'f'//format_integer(width)//'.4')
    end if
  end function lever_text
end module scenarios_optimize_population
