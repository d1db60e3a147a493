!> Bowls, funnels and drops from standard parts (docs/design.md, "Designs
!> from standard parts"): their values as design variables of an element
!> design (design_slide_design) and snapped to a catalogue (design_catalogue).
!> - a design variable moves the element it names: the slide of a design
!>   whose variables are a bowl's entry radius, wall slope and drop, a
!>   funnel's length, slope and widest radius, a drop's fall slope and
!>   curve-out radius, at x, equals to the bit (every surface point and its
!>   derivatives on a grid) the slide built here directly from the chain with
!>   those values set field by field, and differs from the start design's;
!> - the bowl's drop as a variable lowers the slide's end by its change (1e-3
!>   m: the joints keep a bowl's height loss only to ~1e-4 m, docs/geometry.md);
!> - on a small bowl slide, a continuous point of the bowl's entry radius and
!>   drop snapped to a catalogue of bowls: every variable of the design chosen
!>   is an allowed value, the design is the feasible one of least acceleration
!>   cost among all 9 designs of its neighbourhood ridden here one by one, its
!>   reported cost a fresh ride's to the bit, and the parts list holds one bowl
!>   with the values chosen.
program test_design_bowl_parts
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: slide_description_t, section_part_description_t, build_slide
  use geometry_tube, only: tube_surface_t
  use geometry_surface, only: surface_point_t
  use geometry_curve, only: curve_point_t
  use design_slide_design, only: slide_design_t, build_design_slide, start_x, PARAMETER_LENGTH, PARAMETER_SLOPE, &
    PARAMETER_RADIUS, PARAMETER_DROP
  use design_geometry_optimization, only: optimization_setup_t, design_evaluation_t, evaluate_design, &
    constraint_violations
  use design_catalogue, only: catalogue_t, catalogue_result_t, allowed_values_t, choose_from_catalogue
  use testing, only: check, finish_tests
  implicit none (type, external)

  call check_variables_move('bowl', bowl_chain(), 2, [PARAMETER_RADIUS, PARAMETER_SLOPE, PARAMETER_DROP], &
                            [6.5_wp, 47.0_wp, 2.4_wp])
  call check_variables_move('funnel', funnel_chain(), 2, [PARAMETER_LENGTH, PARAMETER_SLOPE, PARAMETER_RADIUS], &
                            [22.0_wp, 4.0_wp, 2.0_wp])
  call check_variables_move('drop', drop_chain(), 1, [PARAMETER_SLOPE, PARAMETER_RADIUS], [75.0_wp, 9.0_wp])
  call check_bowl_drop_lowers_the_end()
  call check_bowl_snapping()
  call finish_tests('test_design_bowl_parts')

contains

  !> The slide of the design at x against the chain built directly with
  !> element `element`'s parameters set to x.
  subroutine check_variables_move(name, elements, element, parameters, x)
    character(len=*), intent(in) :: name
    type(slide_element_t), intent(in) :: elements(:)
    integer, intent(in) :: element, parameters(:)
    real(wp), intent(in) :: x(:)
    type(slide_design_t) :: design
    type(slide_description_t) :: direct
    type(tube_surface_t) :: by_design, built, at_start
    type(status_t) :: status
    real(wp) :: a(4), b(4), moved
    logical :: same
    integer :: k

    design = chain_design(elements, element, parameters)
    call build_design_slide(design, x, by_design, status)
    call check(status%ok(), name//': the slide of the design at x: '//status%text())
    if (.not. status%ok()) return
    direct%kind = 'slide'
    direct%elements = design%chain
    do k = 1, size(x)
      associate (e => direct%elements%elements(element))
        select case (parameters(k))
        case (PARAMETER_LENGTH); e%length = x(k)
        case (PARAMETER_SLOPE); e%slope_deg = x(k)
        case (PARAMETER_RADIUS); e%radius = x(k)
        case (PARAMETER_DROP); e%drop = x(k)
        end select
      end associate
    end do
    direct%section%parts = [section_part_description_t(kind='circle', radius=design%radius)]
    direct%check_samples = design%check_samples
    call build_slide(direct, built, status)
    call check(status%ok(), name//': the slide built directly: '//status%text())
    if (.not. status%ok()) return
    call by_design%domain(a(1), a(2), a(3), a(4))
    call built%domain(b(1), b(2), b(3), b(4))
    call check(all(a == b), name//': the same domain')
    call compare(by_design, built, a, same, moved)
    call check(same, name//': the design''s slide at x is the one built with those values, to the bit')
    call build_design_slide(design, start_x(design), at_start, status)
    call check(status%ok(), name//': the start design''s slide: '//status%text())
    if (.not. status%ok()) return
    call compare(by_design, at_start, a, same, moved)
    call check(moved > 1e-3_wp, name//': the variables moved the slide (it differs from the start design''s)')
  end subroutine check_variables_move

  !> Whether two slides agree to the bit at 61 x 9 points of the domain
  !> `d` (position and first derivatives), and their largest distance apart.
  subroutine compare(s1, s2, d, same, apart)
    type(tube_surface_t), intent(in) :: s1, s2
    real(wp), intent(in) :: d(4)
    logical, intent(out) :: same
    real(wp), intent(out) :: apart
    type(surface_point_t) :: p1, p2
    type(status_t) :: st1, st2
    real(wp) :: u, v, u_end(2), v_end(2)
    integer :: i, j
    same = .true.
    apart = 0
    call s2%domain(u_end(1), u_end(2), v_end(1), v_end(2))
    do i = 0, 60
      u = d(1) + (min(d(2), u_end(2)) - d(1))*i/60.0_wp
      do j = 0, 8
        v = d(3) + (d(4) - d(3))*j/8.0_wp
        call s1%evaluate(u, v, 1, p1, st1)
        call s2%evaluate(u, v, 1, p2, st2)
        if (.not. (st1%ok() .and. st2%ok())) then
          same = .false.
          cycle
        end if
        same = same .and. all(p1%r == p2%r) .and. all(p1%ru == p2%ru) .and. all(p1%rv == p2%rv)
        apart = max(apart, norm2(p1%r - p2%r))
      end do
    end do
  end subroutine compare

  !> The bowl's drop as the variable: 0.5 m more lowers the slide's end by
  !> 0.5 m (the other elements lose the same).
  subroutine check_bowl_drop_lowers_the_end()
    type(slide_design_t) :: design
    type(tube_surface_t) :: s1, s2
    type(status_t) :: status
    real(wp) :: z(2)
    design = chain_design(bowl_chain(), 2, [PARAMETER_DROP])
    call build_design_slide(design, [2.0_wp], s1, status)
    if (status%ok()) call build_design_slide(design, [2.5_wp], s2, status)
    call check(status%ok(), 'bowl drop: both slides built: '//status%text())
    if (.not. status%ok()) return
    z = [end_height(s1), end_height(s2)]
    call check(abs((z(1) - z(2)) - 0.5_wp) < 1e-3_wp, 'bowl drop: 0.5 m more lowers the end by 0.5 m (1e-3)')
  end subroutine check_bowl_drop_lowers_the_end

  real(wp) function end_height(slide) result(z)
    type(tube_surface_t), intent(in) :: slide
    type(curve_point_t) :: c
    type(status_t) :: status
    real(wp) :: u_min, u_max
    call slide%centerline%domain(u_min, u_max)
    call slide%centerline_point(u_max, 0, c, status)
    z = c%d(3, 0)
  end function end_height

  subroutine check_bowl_snapping()
    type(optimization_setup_t) :: setup
    type(catalogue_t) :: catalogue
    type(catalogue_result_t) :: chosen
    type(design_evaluation_t) :: fresh, each
    type(status_t) :: status
    real(wp), parameter :: radii(3) = [5.0_wp, 6.0_wp, 7.0_wp], drops(4) = [1.5_wp, 2.0_wp, 2.5_wp, 3.0_wp]
    real(wp) :: best_cost
    integer :: i, j, k
    logical :: feasible

    setup%design = chain_design(bowl_chain(), 2, [PARAMETER_RADIUS, PARAMETER_DROP])
    setup%design%lower = [5.0_wp, 1.5_wp]
    setup%design%upper = [7.0_wp, 3.0_wp]
    setup%start_angles = [0.0_wp]
    setup%start_speed = 1.0_wp
    allocate (catalogue%allowed(2))
    catalogue%allowed(1) = allowed_values_t(radii)
    catalogue%allowed(2) = allowed_values_t(drops)

    call choose_from_catalogue(setup, catalogue, [6.3_wp, 2.2_wp], chosen, status)
    call check(status%ok(), 'bowl snapping: '//status%text())
    if (.not. status%ok()) return
    call check(all(chosen%x_nearest == [6.0_wp, 2.0_wp]), 'bowl snapping: the nearest of (6.3, 2.2) is (6, 2)')
    call check(size(chosen%acceleration_cost) == 9 .and. chosen%neighbourhood_size == 9, &
               'bowl snapping: the whole neighbourhood (3 x 3) ridden')
    call check(any(chosen%x(1) == radii) .and. any(chosen%x(2) == drops), 'bowl snapping: the design chosen is '// &
               'in the catalogue')
    call check(chosen%feasible, 'bowl snapping: a feasible design found: '//chosen%verdict)
    best_cost = huge(1.0_wp)
    do i = 1, 3
      do j = 1, 3
        call evaluate_design(setup, [radii(i), drops(j)], each, status)
        feasible = status%ok()
        if (feasible) feasible = len(constraint_violations(setup, each)) == 0
        if (feasible) best_cost = min(best_cost, each%acceleration_cost)
      end do
    end do
    call check(chosen%chosen%acceleration_cost == best_cost, 'bowl snapping: the chosen design has the least '// &
               'acceleration cost of the feasible designs of the neighbourhood')
    call evaluate_design(setup, chosen%x, fresh, status)
    call check(status%ok() .and. fresh%acceleration_cost == chosen%chosen%acceleration_cost, &
               'bowl snapping: the reported cost is that of a fresh ride of the design chosen')
    k = findloc([(chosen%parts(i)%element%kind == 'bowl', i=1, size(chosen%parts))], .true., 1)
    call check(k > 0, 'bowl snapping: the parts list holds a bowl')
    if (k == 0) return
    call check(chosen%parts(k)%count == 1 .and. chosen%parts(k)%element%radius == chosen%x(1) .and. &
               chosen%parts(k)%element%drop == chosen%x(2) .and. chosen%parts(k)%element%slope_deg == 50.0_wp, &
               'bowl snapping: one bowl of the chosen entry radius and drop, its wall slope as given')
  end subroutine check_bowl_snapping

  !> An element design of `elements` (a tube of 0.7 m, the fitted
  !> centerline) varying `parameters` of element `element`, loose bounds.
  function chain_design(elements, element, parameters) result(design)
    type(slide_element_t), intent(in) :: elements(:)
    integer, intent(in) :: element, parameters(:)
    type(slide_design_t) :: design
    design%from_elements = .true.
    design%chain%elements = elements
    design%chain%start = [0.0_wp, 0.0_wp, 10.0_wp]
    design%element = spread(element, 1, size(parameters))
    design%parameter = parameters
    design%lower = spread(-1e3_wp, 1, size(parameters))
    design%upper = spread(1e3_wp, 1, size(parameters))
  end function chain_design

  !> An entry straight, a spherical bowl (entry 6 m from its axis, wall 50 deg,
  !> drop 2 m, one turn), an outlet straight and a run-out (inputs/parts/bowl_slide.nml).
  function bowl_chain() result(elements)
    type(slide_element_t), allocatable :: elements(:)
    elements = [slide_element_t(kind='straight', length=12.0_wp, slope_deg=10.0_wp), &
                slide_element_t(kind='bowl', radius=6.0_wp, slope_deg=50.0_wp, drop=2.0_wp, turns=1.0_wp), &
                slide_element_t(kind='straight', length=10.0_wp, slope_deg=14.0_wp), &
                slide_element_t(kind='runout', length=8.0_wp, slope_deg=2.0_wp)]
  end function bowl_chain

  !> A straight, a funnel 20 m long widening to 2.4 m, a run-out.
  function funnel_chain() result(elements)
    type(slide_element_t), allocatable :: elements(:)
    elements = [slide_element_t(kind='straight', length=10.0_wp, slope_deg=5.0_wp), &
                slide_element_t(kind='funnel', length=20.0_wp, slope_deg=3.0_wp, radius=2.4_wp), &
                slide_element_t(kind='runout', length=8.0_wp, slope_deg=2.0_wp)]
  end function funnel_chain

  !> A drop (80 deg, curve-out 8 m, 10 m in all), a straight, a run-out.
  function drop_chain() result(elements)
    type(slide_element_t), allocatable :: elements(:)
    elements = [slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp), &
                slide_element_t(kind='straight', length=10.0_wp, slope_deg=5.0_wp), &
                slide_element_t(kind='runout', length=8.0_wp, slope_deg=2.0_wp)]
  end function drop_chain
end program test_design_bowl_parts
