!> The element design of scenario `optimize` in the result file and the
!> summary (docs/design.md, "Designs from standard parts"): each design
!> variable with its unit, the catalogue's search (the designs ridden) and
!> the parts list of the design chosen from the catalogue.
module scenarios_optimize_parts
  use base_kinds, only: wp
  use base_text, only: format_integer, format_short
  use base_status, only: status_t
  use io_hdf5, only: result_file_t
  use io_summary, only: summary_t, degrees
  use geometry_slide_elements, only: element_kinds
  use design_slide_design, only: slide_design_t, start_x, parameter_names, parameter_units, PARAMETER_SLOPE, &
    PARAMETER_ANGLE
  use design_catalogue, only: catalogue_t, catalogue_result_t, part_text
  implicit none (type, external)
  private
  public :: write_element_variables, write_catalogue, report_element_design, variable_label

contains

  !> 'element 2 (curve) radius'
  function variable_label(design, k) result(text)
    type(slide_design_t), intent(in) :: design
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    text = 'element '//format_integer(design%element(k))//' ('// &
           trim(design%chain%elements(design%element(k))%kind)//') '//trim(parameter_names(design%parameter(k)))
  end function variable_label

  !> The unit of variable k in the file ('m', 'degree').
  function file_unit(design, k) result(unit)
    type(slide_design_t), intent(in) :: design
    integer, intent(in) :: k
    character(len=:), allocatable :: unit
    unit = 'm'
    if (is_angle(design%parameter(k))) unit = 'degree'
  end function file_unit

  pure logical function is_angle(p)
    integer, intent(in) :: p
    is_angle = p == PARAMETER_SLOPE .or. p == PARAMETER_ANGLE
  end function is_angle

  !> /optimize/variables/variable_<k>: name, start, bounds, optimum (when
  !> `x` is given), allowed values, nearest and chosen (with a catalogue).
  subroutine write_element_variables(file, design, status, x, catalogue, chosen)
    type(result_file_t), intent(inout) :: file
    type(slide_design_t), intent(in) :: design
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: x(:)
    type(catalogue_t), intent(in), optional :: catalogue
    type(catalogue_result_t), intent(in), optional :: chosen
    character(len=:), allocatable :: v, u
    real(wp), allocatable :: x0(:)
    integer :: k
    x0 = start_x(design)
    do k = 1, size(design%lower)
      v = '/optimize/variables/variable_'//format_integer(k)//'/'
      u = file_unit(design, k)
      call file%write_text(v//'name', variable_label(design, k), 'the design variable: element, kind, parameter', &
                           status)
      call file%write_count(v//'element', design%element(k), '1', 'its element of &slide_elements (1 = the first)', &
                            status)
      call file%write_scalar(v//'start', x0(k), u, 'its value at the start', status)
      call file%write_scalar(v//'lower', design%lower(k), u, 'its lower bound', status)
      call file%write_scalar(v//'upper', design%upper(k), u, 'its upper bound', status)
      if (present(x)) call file%write_scalar(v//'optimum', x(k), u, 'its value at the continuous optimum', status)
      if (present(catalogue)) then
        call file%write_vector(v//'allowed', catalogue%allowed(k)%values, u, &
                               'the catalogue''s values inside its bounds; dimension scale', status)
        call file%make_scale(v//'allowed', status)
      end if
      if (present(chosen)) then
        call file%write_scalar(v//'nearest', chosen%x_nearest(k), u, 'the allowed value nearest to the optimum', &
                               status)
        call file%write_scalar(v//'catalogue', chosen%x(k), u, 'its value in the design chosen from the catalogue', &
                               status)
        call file%write_vector('/optimize/catalogue/variable_'//format_integer(k), chosen%candidates(k, :), u, &
                               'design variable '//format_integer(k)//' ('//variable_label(design, k)// &
                               ') in each design of the catalogue search', status)
      end if
    end do
  end subroutine write_element_variables

  !> /optimize/catalogue (the search) and /optimize/parts (the parts list).
  subroutine write_catalogue(file, chosen, status)
    type(result_file_t), intent(inout) :: file
    type(catalogue_result_t), intent(in) :: chosen
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: c = '/optimize/catalogue/', p = '/optimize/parts/'
    integer :: k, n
    n = size(chosen%acceleration_cost)
    call file%write_vector(c//'candidate', [(real(k, wp), k=1, n)], '1', &
                           'number of each design ridden in the catalogue search (1 = the nearest); dimension scale', &
                           status)
    call file%write_vector(c//'acceleration_cost', min(chosen%acceleration_cost, 1e30_wp), 'm^2/s^4', &
                           '1/2 sum max|a|^2 of each design ridden (1e30: not built or not ridden)', status)
    call file%write_integers(c//'feasible', merge(1, 0, chosen%candidate_feasible), '1', &
                             'whether each design ridden is feasible (1) or not (0)', status)
    call file%write_scalar(c//'neighbourhood_size', chosen%neighbourhood_size, '1', &
                           'designs of the whole neighbourhood of the nearest catalogue design', status)
    call file%make_scale(c//'candidate', status)
    call file%attach_scale(c//'candidate', c, status)
    call file%set_attribute('/optimize/catalogue', 'verdict', chosen%verdict, status)
    call file%set_attribute('/optimize/catalogue', 'feasible', merge(1, 0, chosen%feasible), status)
    n = size(chosen%parts)
    associate (e => chosen%parts%element)
      call file%write_vector(p//'part', [(real(k, wp), k=1, n)], '1', 'number of each part; dimension scale', &
                             status)
      call file%write_integers(p//'count', chosen%parts%count, '1', 'how many of the part the slide needs', status)
      call file%write_integers(p//'kind', [(findloc(element_kinds, e(k)%kind, 1), k=1, n)], '1', &
                               'its kind: '//kind_legend(), status)
      call file%write_integers(p//'direction', [(direction(k), k=1, n)], '1', &
                               'its direction: 1 left, -1 right (curve, helix, bowl), 0 none', status)
      call file%write_vector(p//'length', e%length, 'm', 'its horizontal length (straight, runout, funnel, patch; else 0)', status)
      call file%write_vector(p//'slope', e%slope_deg, 'degree', &
                             'its slope, downhill positive (straight, curve, runout, funnel, patch; a drop''s top; a bowl''s '// &
                             'wall at the entry; else 0)', status)
      call file%write_vector(p//'radius', e%radius, 'm', 'its radius (curve, helix; a drop''s curve-out; a bowl''s entry '// &
                             'from its axis; a funnel''s widest; else 0)', &
                             status)
      call file%write_vector(p//'angle', e%angle_deg, 'degree', 'its turning angle (curve; else 0)', status)
      call file%write_vector(p//'turns', e%turns, '1', 'its turns (helix, bowl; else 0)', status)
      call file%write_vector(p//'drop', e%drop, 'm', 'the height it loses (helix, drop, bowl; else 0)', status)
    end associate
    call file%write_text(p//'list', parts_list(chosen), 'the parts list in words: count, part, its elements', &
                         status)
    call file%make_scale(p//'part', status)
    call file%attach_scale(p//'part', p, status)

  contains

    integer function direction(k)
      integer, intent(in) :: k
      direction = 0
      associate (e => chosen%parts(k)%element)
        if (e%kind == 'curve' .or. e%kind == 'helix' .or. e%kind == 'bowl') direction = merge(1, -1, e%direction == 'left')
      end associate
    end function direction
  end subroutine write_catalogue

  !> The parts list, one part a line: '2 x curve left, radius 5 m, ... (elements 2, 6)'.
  function parts_list(chosen) result(text)
    type(catalogue_result_t), intent(in) :: chosen
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, size(chosen%parts)
      if (k > 1) text = text//new_line('a')
      text = text//part_line(chosen, k)
    end do
  end function parts_list

  function part_line(chosen, k) result(text)
    type(catalogue_result_t), intent(in) :: chosen
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: j
    associate (part => chosen%parts(k))
      text = format_integer(part%count)//' x '//part_text(part%element)//' (element'// &
             trim(merge('s', ' ', part%count > 1))//' '
      do j = 1, size(part%elements)
        if (j > 1) text = text//', '
        text = text//format_integer(part%elements(j))
      end do
      text = text//')'
    end associate
  end function part_line

  !> The summary of an element design: each variable at the start, the
  !> optimum and (with a catalogue) in the design chosen, then the
  !> catalogue's verdict and the parts list.
  subroutine report_element_design(summary, design, x, chosen)
    type(summary_t), intent(inout) :: summary
    type(slide_design_t), intent(in) :: design
    real(wp), intent(in) :: x(:)
    type(catalogue_result_t), intent(in), optional :: chosen
    real(wp), allocatable :: x0(:), values(:)
    real(wp) :: scale
    integer :: k
    character(len=:), allocatable :: si, columns
    x0 = start_x(design)
    columns = ' (start, optimum)'
    if (present(chosen)) columns = ' (start, optimum, nearest, catalogue)'
    if (present(chosen)) then
      call summary%add_line('  design variable                      start     optimum   catalogue')
    else
      call summary%add_line('  design variable                      start     optimum')
    end if
    do k = 1, size(x)
      values = [x0(k), x(k)]
      if (present(chosen)) values = [values, chosen%x_nearest(k), chosen%x(k)]
      ! the JSON in SI (rad), printed in the input's unit
      si = 'm'
      scale = 1
      if (is_angle(design%parameter(k))) then
        si = 'rad'
        scale = degrees
      end if
      call summary%add_vector('variable_'//format_integer(k), variable_label(design, k)//columns, values/scale, si, &
                              trim(parameter_units(design%parameter(k))), scale)
    end do
    if (.not. present(chosen)) return
    call summary%add_text('catalogue', 'catalogue', chosen%verdict)
    if (chosen%candidate_feasible(1)) then
      call summary%add('nearest_acceleration_cost', 'acceleration cost, nearest catalogue design', &
                       chosen%acceleration_cost(1), 'm^2/s^4')
    else if (chosen%acceleration_cost(1) < huge(1.0_wp)) then
      call summary%add_text('nearest_acceleration_cost', 'acceleration cost, nearest catalogue design', &
                            format_short(chosen%acceleration_cost(1))//' m^2/s^4, infeasible')
    else
      call summary%add_text('nearest_acceleration_cost', 'acceleration cost, nearest catalogue design', &
                            'cannot be built or ridden')
    end if
    if (.not. chosen%ridden) then
      call summary%add_text('catalogue_acceleration_cost', 'acceleration cost, catalogue design', &
                            'cannot be built or ridden')
    else
      call summary%add('catalogue_acceleration_cost', 'acceleration cost, catalogue design', &
                       chosen%chosen%acceleration_cost, 'm^2/s^4')
    end if
    if (.not. chosen%ridden) then
      continue
    else if (chosen%chosen%max_lever_arm >= 1e30_wp) then
      call summary%add_text('catalogue_max_lever_arm', 'largest lever arm, catalogue design', 'lift-off')
    else
      call summary%add('catalogue_max_lever_arm', 'largest lever arm, catalogue design', chosen%chosen%max_lever_arm, &
                       'm')
    end if
    call summary%add_count('parts', 'kinds of parts', size(chosen%parts), 'kinds')
    call summary%add_count('elements', 'elements to build', sum(chosen%parts%count), 'elements')
    call summary%add_line('  parts list (count x part, its elements):')
    do k = 1, size(chosen%parts)
      call summary%add_line('    '//part_line(chosen, k))
    end do
    call summary%add_line('  catalogue designs ridden: '//format_integer(size(chosen%acceleration_cost))// &
                          ', feasible: '//format_integer(count(chosen%candidate_feasible)))
  end subroutine report_element_design

  !> The kinds' numbers as /optimize/parts/kind stores them (the index in
  !> element_kinds): '1 straight, 2 curve, ...', from the list itself so
  !> that a new kind cannot leave it stale.
  function kind_legend() result(text)
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, size(element_kinds)
      if (k > 1) text = text//', '
      text = text//format_integer(k)//' '//trim(element_kinds(k))
    end do
  end function kind_legend
end module scenarios_optimize_parts
