!> Designs from standard parts (thesis 5: "standardmäßige Bauteile beziehungsweise
!> sich wiederholende Bauteile zur Planung der Fertigung"): the design
!> variables of an element design (design_slide_design: a curve's radius,
!> turning angle, an element's slope or length, a bowl's size, a funnel's, a
!> drop's) may take only the values of a catalogue, and the parts the chosen
!> design is built from are counted.
!>
!> The method, a heuristic (it proves no discrete optimum):
!>  1. the continuous optimum x* (design_geometry_optimization) is snapped to
!>     the nearest allowed value of each variable (a tie: the lower one);
!>  2. the neighbourhood of that snapped point, every combination of each
!>     variable at its allowed value or at the next allowed one below or
!>     above it (at most 3^n designs), is ridden in the order of how many
!>     variables move off the snapped point (0, then 1, then 2, ...; within
!>     one count, the first variable's lower neighbour first), until
!>     `max_designs` designs are ridden or the neighbourhood is exhausted;
!>  3. the result is the feasible design of least acceleration cost
!>     (1/2 sum max|a|^2, eq. 4.49 without the constraint terms; a tie: the
!>     earlier one). Feasible: the slide can be built and ridden and, unless
!>     the optimisation's constraint is 'none', no ride lifts off and every
!>     tipping excess is at most lever_tolerance (the optimisation's own
!>     test, constraint_violations).
!> The nearest point alone is not enough: rounding each variable on its own
!> ignores how they act together, and rounding a radius down can make a ride
!> tip that the continuous optimum kept upright. A better discrete design
!> may lie farther away than one catalogue step; only this neighbourhood is
!> searched.
module design_catalogue
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_short, format_integer
  use geometry_slide_elements, only: slide_element_t
  use design_slide_design, only: design_elements, parameter_value, parameter_names, parameter_units, &
    PARAMETER_LENGTH, PARAMETER_SLOPE, PARAMETER_RADIUS, PARAMETER_ANGLE
  use design_geometry_optimization, only: optimization_setup_t, design_evaluation_t, evaluate_design, &
    constraint_violations, CONSTRAINT_NONE
  implicit none (type, external)
  private
  public :: allowed_values_t, catalogue_t, catalogue_result_t, part_t, choose_from_catalogue, nearest_allowed, &
    neighbourhood, parts_of, part_text, allowed_in_list, allowed_by_step, step_indices

  !> The allowed values of one design variable: increasing, inside its bounds.
  type :: allowed_values_t
    real(wp), allocatable :: values(:)
  end type allowed_values_t

  type :: catalogue_t
    type(allowed_values_t), allocatable :: allowed(:)   !< one per design variable
    integer :: max_designs = 64                         !< designs of the neighbourhood ridden at most
  end type catalogue_t

  !> One kind of part and how many of it the slide needs: elements alike in
  !> kind, direction and every parameter of that kind.
  type :: part_t
    type(slide_element_t) :: element
    integer :: count = 0
    integer, allocatable :: elements(:)   !< which elements of the chain (1-based)
  end type part_t

  type :: catalogue_result_t
    real(wp), allocatable :: x_continuous(:)      !< the continuous optimum
    real(wp), allocatable :: x_nearest(:)         !< snapped to the nearest allowed values
    real(wp), allocatable :: x(:)                 !< the design chosen
    type(design_evaluation_t) :: chosen           !< its rides
    logical :: ridden = .false.                   !< chosen holds them (not when x is a nearest design that fails)
    logical :: feasible = .false.                 !< a feasible design was found (else x is the nearest)
    real(wp) :: neighbourhood_size = 0            !< designs of the whole neighbourhood
    real(wp), allocatable :: candidates(:, :)     !< the designs ridden, one per column, in order
    real(wp), allocatable :: acceleration_cost(:) !< of each (huge: not built or not ridden)
    logical, allocatable :: candidate_feasible(:)
    character(len=:), allocatable :: verdict      !< what was found, in words
    type(part_t), allocatable :: parts(:)         !< the parts list of x
  end type catalogue_result_t

contains

  !> The values of an increasing `list` (a catalogue's parts) that a variable
  !> within [lower, upper] may take.
  pure function allowed_in_list(list, lower, upper) result(values)
    real(wp), intent(in) :: list(:), lower, upper
    real(wp), allocatable :: values(:)
    values = pack(list, lower <= list .and. list <= upper)
  end function allowed_in_list

  !> The multiples k step (k = first .. last) inside [lower, upper], a bound
  !> taken within 1e-9 steps (so that a bound written as a multiple is one).
  pure subroutine step_indices(step, lower, upper, first, last)
    real(wp), intent(in) :: step, lower, upper
    integer, intent(out) :: first, last
    first = ceiling(lower/step - 1e-9_wp)
    last = floor(upper/step + 1e-9_wp)
  end subroutine step_indices

  !> The values a variable within [lower, upper] may take from a catalogue
  !> made in steps of `step`: its multiples there (step_indices).
  pure function allowed_by_step(step, lower, upper) result(values)
    real(wp), intent(in) :: step, lower, upper
    real(wp), allocatable :: values(:)
    integer :: first, last, k
    call step_indices(step, lower, upper, first, last)
    values = [(k*step, k=first, last)]
  end function allowed_by_step

  !> The index of the allowed value nearest to x (a tie: the lower one).
  pure integer function nearest_allowed(values, x) result(j)
    real(wp), intent(in) :: values(:), x
    integer :: k
    j = 1
    do k = 2, size(values)
      if (abs(values(k) - x) < abs(values(j) - x)) j = k
    end do
  end function nearest_allowed

  !> The neighbourhood of the allowed indices `centre` (each of 1..counts(i)):
  !> every combination of offsets -1, 0, +1 that stays in range, ordered by
  !> the number of variables moved, then by the offsets (-1 before 0 before
  !> +1, the first variable most significant). One column of indices per
  !> design, at most `most` columns; `total` the size of the whole
  !> neighbourhood (a real: 3^n overflows an integer).
  subroutine neighbourhood(centre, counts, most, designs, total)
    integer, intent(in) :: centre(:), counts(:), most
    integer, allocatable, intent(out) :: designs(:, :)
    real(wp), intent(out) :: total
    integer :: n, moved, k, found
    integer :: index(size(centre))
    n = size(centre)
    total = product([(real(count([centre(k) > 1, .true., centre(k) < counts(k)]), wp), k=1, n)])
    allocate (designs(n, nint(min(total, real(most, wp)))))
    found = 0
    do moved = 0, n
      call place(1, moved)
      if (found == size(designs, 2)) return
    end do

  contains

    !> Sets variables i..n with `left` of them moved, in order.
    recursive subroutine place(i, left)
      integer, intent(in) :: i, left
      integer :: offset
      if (found == size(designs, 2)) return
      if (i > n) then
        if (left == 0) then
          found = found + 1
          designs(:, found) = index
        end if
        return
      end if
      if (left > n - i + 1) return
      do offset = -1, 1
        if (offset /= 0 .and. left == 0) cycle
        if (centre(i) + offset < 1 .or. centre(i) + offset > counts(i)) cycle
        index(i) = centre(i) + offset
        call place(i + 1, left - abs(offset))
      end do
    end subroutine place
  end subroutine neighbourhood

  !> Snaps the continuous optimum to the catalogue and rides its
  !> neighbourhood (the module comment); result%x is the best feasible design,
  !> or the nearest one when none is feasible (result%feasible false).
  !> status: not ok for a catalogue that does not fit the design.
  subroutine choose_from_catalogue(setup, catalogue, x_continuous, result, status)
    type(optimization_setup_t), intent(in) :: setup
    type(catalogue_t), intent(in) :: catalogue
    real(wp), intent(in) :: x_continuous(:)
    type(catalogue_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    type(design_evaluation_t) :: evaluation
    type(status_t) :: ridden
    integer, allocatable :: designs(:, :), centre(:), counts(:)
    integer :: n, k, i, best
    character(len=:), allocatable :: why

    n = size(x_continuous)
    if (.not. setup%design%from_elements .or. size(catalogue%allowed) /= n) then
      call set_status(status, STATUS_INVALID_INPUT, 'catalogue: one list of allowed values per design variable '// &
                      'of an element design')
      return
    end if
    allocate (centre(n), counts(n))
    do i = 1, n
      counts(i) = size(catalogue%allowed(i)%values)
      if (counts(i) < 1) then
        call set_status(status, STATUS_INVALID_INPUT, 'catalogue: design variable '//format_integer(i)// &
                        ' has no allowed value')
        return
      end if
      centre(i) = nearest_allowed(catalogue%allowed(i)%values, x_continuous(i))
    end do
    call neighbourhood(centre, counts, max(1, catalogue%max_designs), designs, result%neighbourhood_size)
    result%x_continuous = x_continuous
    result%x_nearest = [(catalogue%allowed(i)%values(centre(i)), i=1, n)]
    allocate (result%candidates(n, size(designs, 2)), result%acceleration_cost(size(designs, 2)), &
              result%candidate_feasible(size(designs, 2)))
    best = 0
    do k = 1, size(designs, 2)
      result%candidates(:, k) = [(catalogue%allowed(i)%values(designs(i, k)), i=1, n)]
      call evaluate_design(setup, result%candidates(:, k), evaluation, ridden)
      result%candidate_feasible(k) = ridden%ok()
      result%acceleration_cost(k) = huge(1.0_wp)
      if (ridden%ok()) then
        result%acceleration_cost(k) = evaluation%acceleration_cost
        if (setup%constraint /= CONSTRAINT_NONE) &
          result%candidate_feasible(k) = len(constraint_violations(setup, evaluation)) == 0
      end if
      if (k == 1) why = ridden%text()   ! the nearest design, when it cannot be ridden
      if (.not. result%candidate_feasible(k)) cycle
      if (best /= 0) then
        if (.not. result%acceleration_cost(k) < result%acceleration_cost(best)) cycle
      end if
      best = k
    end do
    result%feasible = best > 0
    if (result%feasible) then
      result%x = result%candidates(:, best)
      result%verdict = 'design '//format_integer(best)//' of the '//format_integer(size(designs, 2))// &
        ' ridden is the feasible one of least acceleration cost ('//searched(size(designs, 2))//')'
    else
      result%x = result%x_nearest
      result%verdict = 'no feasible design among the '//format_integer(size(designs, 2))//' ridden ('// &
        searched(size(designs, 2))//')'
    end if
    ! the chosen design's rides afresh, with their series (for the file)
    call evaluate_design(setup, result%x, result%chosen, ridden, keep_series=.true.)
    result%ridden = ridden%ok()
    if (.not. ridden%ok() .and. .not. result%feasible) then
      result%verdict = result%verdict//'; the nearest cannot be ridden: '//why
    end if
    result%parts = parts_of(design_elements(setup%design, result%x))
    status = status_t()

  contains

    !> How much of the neighbourhood `ridden` designs are.
    function searched(designs_ridden) result(text)
      integer, intent(in) :: designs_ridden
      character(len=:), allocatable :: text
      if (real(designs_ridden, wp) >= result%neighbourhood_size) then
        text = 'the whole neighbourhood of the nearest catalogue design, '//format_integer(designs_ridden)// &
               ' designs'
      else
        text = 'the first '//format_integer(designs_ridden)//' of the '//format_short(result%neighbourhood_size)// &
               ' designs of the neighbourhood of the nearest catalogue design: max_designs'
      end if
    end function searched
  end subroutine choose_from_catalogue

  !> The parts list of a chain: one entry per kind of element that differs
  !> in kind, direction or a parameter its kind uses, with its count, in the
  !> order of first use (every patch a part of its own).
  pure function parts_of(elements) result(parts)
    type(slide_element_t), intent(in) :: elements(:)
    type(part_t), allocatable :: parts(:)
    integer :: i, j, n
    allocate (parts(size(elements)))
    n = 0
    do i = 1, size(elements)
      do j = 1, n
        if (alike(parts(j)%element, elements(i))) exit
      end do
      if (j > n) then
        n = n + 1
        parts(n)%element = elements(i)
        allocate (parts(n)%elements(0))
      end if
      parts(j)%count = parts(j)%count + 1
      parts(j)%elements = [parts(j)%elements, i]
    end do
    parts = parts(:n)
  end function parts_of

  !> Whether two elements are the same part: kind, and every value the kind uses
  !> (a bowl's profile and its table too; a free-form patch is never another's).
  pure logical function alike(a, b)
    type(slide_element_t), intent(in) :: a, b
    alike = a%kind == b%kind
    if (.not. alike) return
    select case (trim(a%kind))
    case ('straight', 'runout')
      alike = a%length == b%length .and. a%slope_deg == b%slope_deg
    case ('curve')
      alike = a%radius == b%radius .and. a%angle_deg == b%angle_deg .and. a%slope_deg == b%slope_deg .and. &
              a%direction == b%direction
    case ('helix')
      alike = a%radius == b%radius .and. a%turns == b%turns .and. a%drop == b%drop .and. a%direction == b%direction
    case ('drop')
      alike = a%drop == b%drop .and. a%slope_deg == b%slope_deg .and. a%radius == b%radius
    case ('bowl')
      alike = a%radius == b%radius .and. a%slope_deg == b%slope_deg .and. a%drop == b%drop .and. &
              a%turns == b%turns .and. a%direction == b%direction .and. a%bowl_profile == b%bowl_profile
      if (alike .and. a%bowl_profile == 'table') alike = same_points(a%bowl_rho, b%bowl_rho) .and. &
                                                        same_points(a%bowl_z, b%bowl_z)
    case ('funnel')
      alike = a%length == b%length .and. a%slope_deg == b%slope_deg .and. a%radius == b%radius
    case default   ! a patch: free-form, its wall from a file of its own, each one a part of its own
      alike = .false.
    end select
  end function alike

  !> Whether two profile tables (a table bowl's points) are the same.
  pure logical function same_points(a, b)
    real(wp), allocatable, intent(in) :: a(:), b(:)
    same_points = allocated(a) .eqv. allocated(b)
    if (same_points .and. allocated(a)) same_points = size(a) == size(b)
    if (same_points .and. allocated(a)) same_points = all(a == b)
  end function same_points

  !> A part in words: 'curve left, radius 5 m, angle 90 deg, slope 6 deg'.
  function part_text(e) result(text)
    type(slide_element_t), intent(in) :: e
    character(len=:), allocatable :: text
    select case (trim(e%kind))
    case ('straight', 'runout')
      text = trim(e%kind)//', '//value_text(e, PARAMETER_LENGTH)//', '//value_text(e, PARAMETER_SLOPE)
    case ('curve')
      text = 'curve '//trim(e%direction)//', '//value_text(e, PARAMETER_RADIUS)//', '// &
             value_text(e, PARAMETER_ANGLE)//', '//value_text(e, PARAMETER_SLOPE)
    case ('helix')
      text = 'helix '//trim(e%direction)//', '//value_text(e, PARAMETER_RADIUS)//', turns '// &
             format_short(e%turns)//', drop '//format_short(e%drop)//' m'
    case ('drop')
      text = 'drop, height '//format_short(e%drop)//' m, top '//value_text(e, PARAMETER_SLOPE)//', curve-out '// &
             value_text(e, PARAMETER_RADIUS)
    case ('bowl')
      text = 'bowl '//trim(e%direction)//', '//trim(e%bowl_profile)//', entry '//value_text(e, PARAMETER_RADIUS)// &
             ' from its axis, wall '//value_text(e, PARAMETER_SLOPE)//', drop '//format_short(e%drop)//' m, turns '// &
             format_short(e%turns)
    case ('funnel')
      text = 'funnel, '//value_text(e, PARAMETER_LENGTH)//', '//value_text(e, PARAMETER_SLOPE)//', widest '// &
             value_text(e, PARAMETER_RADIUS)
    case default
      text = trim(e%kind)//' (free-form), '//value_text(e, PARAMETER_LENGTH)//', '//value_text(e, PARAMETER_SLOPE)
    end select
  end function part_text

  function value_text(e, kind) result(text)
    type(slide_element_t), intent(in) :: e
    integer, intent(in) :: kind
    character(len=:), allocatable :: text
    text = trim(parameter_names(kind))//' '//format_short(parameter_value(e, kind))//' '//trim(parameter_units(kind))
  end function value_text
end module design_catalogue
