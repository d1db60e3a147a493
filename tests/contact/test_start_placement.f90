!> The start placement's own check (contact_model check_placement, issue
!> 25): a body is placed where its given pose and its contact's gap put it,
!> and a placement that moved it sideways or turned it is refused, not run.
!> (A search that ended at the wrong point of a sphere's chart once moved a
!> ball resting on a ball 1 mm sideways onto the top and ran on, exit 0;
!> tests/cli/contact_ball_on_ball.sh keeps that case.)
!>   - lifted_on_slope: a ball 1 mm above a 30 degree slope, turned: built,
!>     the closure moves it by 1 mm along the slope's normal only, its
!>     rotation kept (1e-12). The check of the built model against poses
!>     moved sideways by 1e-6 m or turned by 1e-6 rad is refused naming the
!>     body and the contact; moved by 1e-12 m (rounding) it passes.
!>   - stack_lifted: a big ball 2 mm above the floor, a small ball resting on
!>     its given top off-centre: both lowered by 2 mm (the small one with its
!>     carrier), built and checked (the check counts the carrier's move: the
!>     small ball is 2 mm from its own given position).
!>   - flying: a free body (its contact open) is at its given pose; given
!>     1e-6 m elsewhere the check refuses it as flying.
program test_start_placement
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_vector, only: rotation_xyz
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, check_placement
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: number, vector_text, read_system
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: theta = 30*pi/180, ra = 0.1_wp
  real(wp), parameter :: downhill(3) = [cos(theta), 0.0_wp, -sin(theta)], normal(3) = [sin(theta), 0.0_wp, cos(theta)]

  call lifted_on_slope()
  call stack_lifted()
  call flying()
  call finish_tests('test_start_placement')

contains

  function head() result(text)
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-10, atol = 1e-10, duration = 1, output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''slope'', kind = ''plane'', angles_deg = 0, 30, 0 /'//nl// &
           '&shape name = ''a'', kind = ''sphere'', radius = '//number(ra)//' /'//nl// &
           '&shape name = ''big'', kind = ''sphere'', radius = 0.2 /'//nl// &
           '&shape name = ''small'', kind = ''sphere'', radius = 0.05 /'//nl
  end function head

  !> The contact system of `text`, checked read.
  subroutine read_checked(text, label, system, ok)
    character(len=*), intent(in) :: text, label
    type(contact_system_t), intent(out) :: system
    logical, intent(out) :: ok
    type(status_t) :: st
    call read_system(text, label, system, st)
    ok = st%ok()
    call check(ok, label//': read: '//st%text())
  end subroutine read_checked

  subroutine lifted_on_slope()
    type(contact_system_t) :: system, moved
    type(contact_model_t) :: model
    type(status_t) :: st
    real(wp) :: given(3)
    logical :: ok
    given = (ra + 1e-3_wp)*normal + 0.3_wp*downhill + [0.0_wp, 0.2_wp, 0.0_wp]
    call read_checked(head()//'&body name = ''a'', mass = 0.2, solid_of = ''a'', position = '//vector_text(given)// &
                     ', angles_deg = 10, 20, 30 /'//nl// &
                     '&contact name = ''a_slope'', shape_1 = ''slope'', body_2 = ''a'', shape_2 = ''a'' /'//nl, &
                     'lifted_on_slope', system, ok)
    if (.not. ok) return
    call build_contact_model(system, model, st)
    call check(st%ok(), 'lifted_on_slope: built: '//st%text())
    if (.not. st%ok()) return
    call check_close(model%links(1)%start_gap, 1e-3_wp, 0.0_wp, 1e-12_wp, 'lifted_on_slope: the gap closed')
    associate (placed => model%ode%work%frames(model%body_frame(2)))
      call check(maxval(abs(placed%r - (given - 1e-3_wp*normal))) <= 1e-12_wp, &
                 'lifted_on_slope: lowered along the slope''s normal only')
      call check(maxval(abs(placed%rot - system%bodies(1)%rotation)) <= 1e-12_wp, &
                 'lifted_on_slope: its rotation kept')
    end associate
    ! the check itself, of the built model against other given poses
    moved = system
    moved%bodies(1)%position = given + 1e-6_wp*downhill
    st = status_t()
    call check_placement(moved, model, [1], st)
    call check(.not. st%ok() .and. index(st%text(), 'body ''a''') > 0 .and. index(st%text(), '''a_slope''') > 0 &
               .and. index(st%text(), 'moved it 1') > 0, &
               'lifted_on_slope: a placement 1e-6 m sideways of its given pose is refused: '//st%text())
    moved = system
    moved%bodies(1)%rotation = matmul(rotation_xyz([0.0_wp, 0.0_wp, 1e-6_wp]), system%bodies(1)%rotation)
    st = status_t()
    call check_placement(moved, model, [1], st)
    call check(.not. st%ok() .and. index(st%text(), 'turned it by 1.0000') > 0 .and. index(st%text(), ' rad') > 0, &
               'lifted_on_slope: a placement turned by 1e-6 rad is refused: '//st%text())
    moved = system
    moved%bodies(1)%position = given + 1e-12_wp*downhill
    st = status_t()
    call check_placement(moved, model, [1], st)
    call check(st%ok(), 'lifted_on_slope: rounding (1e-12 m) passes: '//st%text())
  end subroutine lifted_on_slope

  subroutine stack_lifted()
    type(contact_system_t) :: system
    type(contact_model_t) :: model
    type(status_t) :: st
    real(wp) :: big(3), small(3), dir(3)
    logical :: ok
    big = [0.1_wp, -0.2_wp, 0.2_wp + 2e-3_wp]
    dir = [sin(0.3_wp)*cos(1.1_wp), sin(0.3_wp)*sin(1.1_wp), cos(0.3_wp)]   ! 0.3 rad off the top
    small = big + (0.2_wp + 0.05_wp)*dir
    call read_checked(head()// &
                     '&body name = ''big'', mass = 1, solid_of = ''big'', position = '//vector_text(big)//' /'//nl// &
                     '&body name = ''small'', mass = 0.1, solid_of = ''small'', position = '//vector_text(small)// &
                     ', angles_deg = 40, -10, 5 /'//nl// &
                     '&contact name = ''big_floor'', shape_1 = ''floor'', body_2 = ''big'', shape_2 = ''big'' /'//nl// &
                     '&contact name = ''small_big'', body_1 = ''big'', shape_1 = ''big'', body_2 = ''small'', '// &
                     'shape_2 = ''small'' /'//nl, 'stack_lifted', system, ok)
    if (.not. ok) return
    call build_contact_model(system, model, st)
    call check(st%ok(), 'stack_lifted: built: '//st%text())
    if (.not. st%ok()) return
    associate (placed => model%ode%work%frames(model%body_frame(3)))
      call check(maxval(abs(placed%r - (small - [0.0_wp, 0.0_wp, 2e-3_wp]))) <= 1e-12_wp .and. &
                 abs(model%links(2)%start_gap) <= 1e-12_wp, &
                 'stack_lifted: the small ball lowered with the big one, touching where it was given')
    end associate
  end subroutine stack_lifted

  subroutine flying()
    type(contact_system_t) :: system, moved
    type(contact_model_t) :: model
    type(status_t) :: st
    real(wp) :: given(3)
    logical :: ok
    given = [0.3_wp, 0.1_wp, 0.5_wp]
    call read_checked(head()//'&body name = ''a'', mass = 0.2, solid_of = ''a'', position = '//vector_text(given)// &
                     ', angles_deg = 10, 20, 30 /'//nl// &
                     '&contact name = ''a_floor'', shape_1 = ''floor'', body_2 = ''a'', shape_2 = ''a'', '// &
                     'start = ''open'' /'//nl, 'flying', system, ok)
    if (.not. ok) return
    call build_contact_model(system, model, st, flying=.true.)
    call check(st%ok(), 'flying: built: '//st%text())
    if (.not. st%ok()) return
    associate (placed => model%ode%work%frames(model%body_frame(2)))
      call check(maxval(abs(placed%r - given)) <= 1e-15_wp .and. &
                 maxval(abs(placed%rot - system%bodies(1)%rotation)) <= 1e-15_wp, 'flying: at its given pose')
    end associate
    moved = system
    moved%bodies(1)%position = given + [0.0_wp, 1e-6_wp, 0.0_wp]
    st = status_t()
    call check_placement(moved, model, [-1], st)
    call check(.not. st%ok() .and. index(st%text(), 'it flies') > 0, &
               'flying: a free body 1e-6 m from its given pose is refused: '//st%text())
  end subroutine flying
end program test_start_placement
