!> Designs from standard parts (design_catalogue, docs/design.md): an element
!> design whose curve radius and slope are snapped to a catalogue.
!> - the neighbourhood of the nearest catalogue design: its designs in the
!>   documented order (moved variables 0, 1, 2; lower neighbour first), cut
!>   at the budget, clipped at the ends of the allowed lists;
!> - the parts list counts identical elements (two straights alike, a curve
!>   left and one right apart); bowls, funnels, patches and drops each as
!>   their own kind, alike only in every value their kind uses;
!> - on a small slide, snapping a given continuous point: every variable of
!>   the design chosen is an allowed value, the design is the feasible one
!>   of least acceleration cost among all 9 of the neighbourhood (ridden
!>   here one by one), its reported cost equals a fresh ride of it, and its
!>   parts list holds the catalogue's radius and slope with the counts of
!>   the chain; with a lever-arm limit none keeps, no design is feasible and
!>   the nearest is kept, said in words.
program test_design_catalogue
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_slide_elements, only: slide_element_t
  use design_slide_design, only: PARAMETER_RADIUS, PARAMETER_SLOPE
  use design_geometry_optimization, only: optimization_setup_t, design_evaluation_t, evaluate_design, &
    constraint_violations
  use design_catalogue, only: catalogue_t, catalogue_result_t, allowed_values_t, choose_from_catalogue, &
    neighbourhood, parts_of, part_t, part_text, nearest_allowed
  use testing, only: check, finish_tests
  implicit none (type, external)

  call check_neighbourhood()
  call check_parts()
  call check_snapping()
  call finish_tests('test_design_catalogue')

contains

  subroutine check_neighbourhood()
    integer, allocatable :: designs(:, :)
    real(wp) :: total
    integer, parameter :: expected(2, 9) = reshape([2, 2, 1, 2, 2, 1, 2, 3, 3, 2, 1, 1, 1, 3, 3, 1, 3, 3], [2, 9])
    call neighbourhood([2, 2], [3, 3], 100, designs, total)
    call check(total == 9 .and. size(designs, 2) == 9, 'neighbourhood of (2, 2) in 3 x 3: 9 designs')
    if (size(designs, 2) == 9) call check(all(designs == expected), 'neighbourhood: the documented order')
    call neighbourhood([2, 2], [3, 3], 4, designs, total)
    call check(total == 9 .and. size(designs, 2) == 4, 'neighbourhood: the budget of 4 cuts it, its size stays 9')
    if (size(designs, 2) == 4) call check(all(designs == expected(:, :4)), 'neighbourhood: the first 4 in order')
    ! at the ends of the lists: (1, 3) of 3 x 3 has 2 x 2 designs; one allowed value: 1
    call neighbourhood([1, 3], [3, 3], 100, designs, total)
    call check(total == 4 .and. size(designs, 2) == 4, 'neighbourhood at the ends: 4 designs')
    call check(all(designs >= 1 .and. designs <= 3), 'neighbourhood at the ends: indices in range')
    call neighbourhood([1], [1], 100, designs, total)
    call check(total == 1 .and. size(designs, 2) == 1, 'neighbourhood of a single allowed value: itself')
    call check(nearest_allowed([3.0_wp, 4.0_wp, 5.0_wp], 4.5_wp) == 2, 'nearest: a tie takes the lower value')
    call check(nearest_allowed([3.0_wp, 4.0_wp, 5.0_wp], 4.6_wp) == 3, 'nearest: 4.6 of 3, 4, 5 is 5')
  end subroutine check_neighbourhood

  subroutine check_parts()
    type(part_t), allocatable :: parts(:)
    parts = parts_of([straight(3.0_wp), curve(5.0_wp, 'left '), straight(3.0_wp), curve(5.0_wp, 'right'), &
                      curve(5.0_wp, 'left '), straight(4.0_wp)])
    call check(size(parts) == 4, 'parts: 4 kinds (straight 3 m, curve left, curve right, straight 4 m)')
    if (size(parts) /= 4) return
    call check(all(parts%count == [2, 2, 1, 1]), 'parts: counts 2, 2, 1, 1')
    call check(all(parts(1)%elements == [1, 3]) .and. all(parts(2)%elements == [2, 5]), &
               'parts: the elements of each part')
    call check_parts_beyond_the_tube()
  end subroutine check_parts

  !> Bowls, funnels, patches and drops are parts of their own kind, named as
  !> such (the parts list once called a bowl or a funnel a 'drop', and two
  !> funnels of different lengths one part), alike only in every value their
  !> kind uses.
  subroutine check_parts_beyond_the_tube()
    type(part_t), allocatable :: parts(:)
    type(slide_element_t) :: bowl, cone, deeper, table_bowl, other_table, funnel, longer, patch, drop
    character(len=:), allocatable :: text
    integer :: k
    bowl = slide_element_t(kind='bowl', radius=6.0_wp, slope_deg=50.0_wp, drop=2.0_wp, turns=1.0_wp)
    cone = bowl; cone%bowl_profile = 'cone'
    deeper = bowl; deeper%turns = 1.5_wp
    table_bowl = bowl; table_bowl%bowl_profile = 'table'; table_bowl%slope_deg = 0
    table_bowl%bowl_rho = [0.0_wp, 2.0_wp, 4.0_wp, 6.0_wp, 8.0_wp, 10.0_wp]
    table_bowl%bowl_z = 0.1_wp*table_bowl%bowl_rho**2
    other_table = table_bowl; other_table%bowl_z(6) = 11.0_wp
    funnel = slide_element_t(kind='funnel', length=20.0_wp, slope_deg=3.0_wp, radius=2.4_wp)
    longer = funnel; longer%length = 24.0_wp
    patch = slide_element_t(kind='patch', length=12.0_wp, slope_deg=5.0_wp)
    drop = slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp)
    parts = parts_of([drop, bowl, funnel, bowl, cone, deeper, longer, table_bowl, other_table, table_bowl, patch, &
                      patch, funnel])
    call check(size(parts) == 10, 'parts beyond the tube: 10 parts (drop, bowl, funnel, cone, deeper bowl, longer '// &
               'funnel, two tables, two patches)')
    if (size(parts) /= 10) return
    call check(all(parts%count == [1, 2, 2, 1, 1, 1, 2, 1, 1, 1]), 'parts beyond the tube: counts')
    call check(all(parts(2)%elements == [2, 4]) .and. all(parts(3)%elements == [3, 13]) .and. &
               all(parts(7)%elements == [8, 10]), 'parts beyond the tube: the alike elements together')
    call check(all([(parts(k)%element%kind, k=1, 10)] == [character(len=8) :: 'drop', 'bowl', 'funnel', 'bowl', &
               'bowl', 'funnel', 'bowl', 'bowl', 'patch', 'patch']), 'parts beyond the tube: each its own kind')
    do k = 1, 10
      text = part_text(parts(k)%element)
      call check(index(text, trim(parts(k)%element%kind)) == 1, 'part '//text//': named by its kind')
    end do
    call check(part_text(bowl) == 'bowl left, sphere, entry radius 6 m from its axis, wall slope 50 deg, drop 2 m, '// &
               'turns 1', 'part text of a bowl: '//part_text(bowl))
    call check(part_text(funnel) == 'funnel, length 20 m, slope 3 deg, widest radius 2.4 m', &
               'part text of a funnel: '//part_text(funnel))
  end subroutine check_parts_beyond_the_tube

  subroutine check_snapping()
    type(optimization_setup_t) :: setup
    type(catalogue_t) :: catalogue
    type(catalogue_result_t) :: chosen
    type(design_evaluation_t) :: fresh, each
    type(status_t) :: status
    real(wp), parameter :: radii(4) = [3.0_wp, 4.0_wp, 5.0_wp, 6.0_wp], slopes(3) = [4.0_wp, 6.0_wp, 8.0_wp]
    real(wp) :: best_cost
    integer :: i, j
    logical :: feasible

    setup%design%from_elements = .true.
    setup%design%chain%elements = [straight(3.0_wp), curve(4.0_wp, 'left '), straight(3.0_wp), runout()]
    setup%design%chain%start = [0.0_wp, 0.0_wp, 5.0_wp]
    setup%design%chain%exact = .true.
    setup%design%element = [2, 2]
    setup%design%parameter = [PARAMETER_RADIUS, PARAMETER_SLOPE]
    setup%design%lower = [3.0_wp, 3.0_wp]
    setup%design%upper = [6.0_wp, 8.0_wp]
    setup%start_angles = [0.0_wp]
    setup%start_speed = 1.0_wp
    allocate (catalogue%allowed(2))
    catalogue%allowed(1) = allowed_values_t(radii)
    catalogue%allowed(2) = allowed_values_t(slopes)

    call choose_from_catalogue(setup, catalogue, [4.6_wp, 5.3_wp], chosen, status)
    call check(status%ok(), 'snapping: '//status%text())
    if (.not. status%ok()) return
    call check(all(chosen%x_nearest == [5.0_wp, 6.0_wp]), 'snapping: the nearest of (4.6, 5.3) is (5, 6)')
    call check(size(chosen%acceleration_cost) == 9 .and. chosen%neighbourhood_size == 9, &
               'snapping: the whole neighbourhood (3 x 3) ridden within the default budget')
    call check(any(chosen%x(1) == radii) .and. any(chosen%x(2) == slopes), 'snapping: the design chosen is '// &
               'in the catalogue')
    call check(chosen%feasible, 'snapping: a feasible design found: '//chosen%verdict)
    ! the same neighbourhood ridden here, one design at a time
    best_cost = huge(1.0_wp)
    do i = 2, 4
      do j = 1, 3
        call evaluate_design(setup, [radii(i), slopes(j)], each, status)
        feasible = status%ok()
        if (feasible) feasible = len(constraint_violations(setup, each)) == 0
        if (feasible) best_cost = min(best_cost, each%acceleration_cost)
      end do
    end do
    call check(chosen%chosen%acceleration_cost == best_cost, 'snapping: the chosen design has the least '// &
               'acceleration cost of the feasible designs of the neighbourhood')
    call evaluate_design(setup, chosen%x, fresh, status)
    call check(status%ok() .and. fresh%acceleration_cost == chosen%chosen%acceleration_cost, &
               'snapping: the reported cost is that of a fresh ride of the design chosen (same rides, same bits)')
    call check(size(chosen%parts) == 3, 'snapping: 3 kinds of parts (straight 3 m twice, the curve, the runout)')
    if (size(chosen%parts) /= 3) return
    call check(all(chosen%parts%count == [2, 1, 1]), 'snapping: parts counted 2, 1, 1')
    call check(chosen%parts(2)%element%radius == chosen%x(1) .and. &
               chosen%parts(2)%element%slope_deg == chosen%x(2), 'snapping: the curve part has the chosen '// &
               'radius and slope')
    ! a lever-arm limit no design of the neighbourhood keeps: none feasible,
    ! the nearest reported, and said
    setup%lever_limit = 1e-4_wp
    call choose_from_catalogue(setup, catalogue, [4.6_wp, 5.3_wp], chosen, status)
    call check(status%ok() .and. .not. chosen%feasible .and. all(chosen%x == chosen%x_nearest) .and. &
               .not. any(chosen%candidate_feasible), 'snapping: no feasible design, the nearest kept')
    call check(index(chosen%verdict, 'no feasible design among the 9 ridden') > 0, 'snapping: said: '// &
               chosen%verdict)
  end subroutine check_snapping

  pure type(slide_element_t) function straight(length) result(e)
    real(wp), intent(in) :: length
    e = slide_element_t(kind='straight', length=length, slope_deg=10.0_wp)
  end function straight

  pure type(slide_element_t) function runout() result(e)
    e = slide_element_t(kind='runout', length=3.0_wp, slope_deg=2.0_wp)
  end function runout

  pure type(slide_element_t) function curve(radius, direction) result(e)
    real(wp), intent(in) :: radius
    character(len=5), intent(in) :: direction
    e = slide_element_t(kind='curve', radius=radius, angle_deg=90.0_wp, slope_deg=5.0_wp, direction=direction)
  end function curve
end program test_design_catalogue
