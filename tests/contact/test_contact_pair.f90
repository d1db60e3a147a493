!> Position-level contact between two surfaces on two bodies (contact_pair):
!> the egg of thesis 3.5.3.3 placed on a table closes onto its exact support
!> height; the closed mechanism's velocities and accelerations against
!> differences of its positions along random motions, and its force map's
!> virtual power, for the egg on a plane and for a B-spline paraboloid in the
!> bowl of a moving one; the parallel-normal branch (with the side to flip)
!> and a contact that cannot close are refused with the contact's name. The open chain (no closure) of
!> the same cup: started from the loop's closed configuration it puts the cup
!> where the loop does, its closure monitor reads zero, and its velocities,
!> accelerations and virtual power pass the same checks along random motions.
!> The monitor is record-only: right-hand sides leave its outputs alone and
!> every record holds them evaluated at the recorded state; a mechanism that
!> reads such an output is refused.
program test_contact_pair
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_vector, only: rot_x, rot_y, rot_z
  use testing, only: check, check_close, finish_tests
  use element_checks, only: check_mechanism_motion
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t, ellipsoid_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_scattered
  use kinetostatics_joints, only: new_spherical, new_prismatic
  use kinetostatics_force_laws, only: new_constant_load
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use numerics_event_driver, only: RECORD_OUTPUT
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use contact_closure_monitor, only: new_closure_monitor
  use contact_pair, only: contact_pair_t, add_contact_pair, place_contact_pair, check_contact_branch, &
    add_open_contact_pair, place_open_contact_pair
  implicit none (type, external)

  real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  real(wp), parameter :: egg_a = 0.025_wp, egg_b = 0.033_wp     ! m, thesis 3.5.3.3
  real(wp) :: tilt

  tilt = 77*pi/180
  call egg_on_table()
  call paraboloid_in_moving_bowl()
  call parallel_branch_refused()
  call no_closure_named()
  call monitor_only_in_records()
  call record_only_read_refused()
  call finish_tests('test_contact_pair')

contains

  !> The egg with its long axis (body y) tilted by `tilt` from the vertical and
  !> its lowest point on the equator v = 0 (away from the poles of (3.57)).
  pure function egg_orientation(theta) result(r)
    real(wp), intent(in) :: theta
    real(wp) :: r(3, 3)
    ! rows: world axes in body coordinates; world z = (sin, cos, 0) in the body
    r(1, :) = [0.0_wp, 0.0_wp, 1.0_wp]
    r(2, :) = [cos(theta), -sin(theta), 0.0_wp]
    r(3, :) = [sin(theta), cos(theta), 0.0_wp]
  end function egg_orientation

  subroutine build_egg(m, pair, side_egg, status)
    type(mechanism_t), intent(out) :: m
    type(contact_pair_t), intent(out) :: pair
    real(wp), intent(in) :: side_egg
    type(status_t), intent(inout) :: status
    type(plane_t) :: table
    type(ellipsoid_t) :: egg
    table = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], status)
    egg = ellipsoid_t(egg_a, egg_b, egg_a, status)
    call add_contact_pair(m, 'egg_on_table', 1, table, 1.0_wp, 'egg', egg, side_egg, pair, status)
    call m%add_law(new_constant_load('push', pair%frame_b, [0.3_wp, -0.2_wp, 0.9_wp], &
                                     [0.01_wp, 0.02_wp, -0.005_wp], .false.))
    call m%add_law(new_constant_load('push_contact', pair%frame_2d, [-0.1_wp, 0.4_wp, 0.2_wp], &
                                     [0.003_wp, -0.01_wp, 0.02_wp], .false.))
    call m%set_coordinates(pair%coordinates())
    call m%finalize(status)
  end subroutine build_egg

  subroutine egg_on_table()
    type(mechanism_t) :: m
    type(contact_pair_t) :: pair
    type(status_t) :: st
    real(wp) :: gap, height, q0(5), r0(3), normal(3)
    integer :: trial
    type(mechanism_workspace_t) :: work
    call build_egg(m, pair, 1.0_wp, st)
    call check(st%ok(), 'egg on table built: '//st%text())
    r0 = [0.01_wp, -0.02_wp, 0.05_wp]
    call place_contact_pair(m, pair, identity, [0.0_wp, 0.0_wp, 0.0_wp], egg_orientation(tilt), r0, gap, normal, st)
    q0 = m%scalars(pair%coordinates())%q
    call m%check_start(work, q0, st)
    call check_contact_branch(work, pair, st)
    call check(st%ok(), 'egg closes at the start: '//st%text())
    ! support height of the ellipsoid: sqrt(n^T A^2 n), n = world z in body axes
    height = sqrt((egg_a*sin(tilt))**2 + (egg_b*cos(tilt))**2)
    call check_close(work%frames(pair%frame_b)%r(3), height, 0.0_wp, 1e-15_wp, &
                     'egg centre at its support height (exact to rounding)')
    call check_close(gap, r0(3) - height, 0.0_wp, 1e-15_wp, 'placement reports the gap it closed')
    call check(maxval(abs(normal - [0.0_wp, 0.0_wp, 1.0_wp])) <= 1e-15_wp, 'placement reports the table''s normal')
    call check(maxval(abs(work%frames(pair%frame_b)%r(1:2) - r0(1:2))) <= 1e-15_wp, &
               'the closure moves the egg along the table normal only')
    call check(maxval(abs(work%frames(pair%frame_b)%rot - egg_orientation(tilt))) <= 1e-15_wp, &
               'the closure keeps the egg''s orientation')
    call check(abs(work%frames(pair%frame_1d)%r(3)) <= 1e-15_wp .and. &
               norm2(work%frames(pair%frame_1d)%r - work%frames(pair%frame_2d)%r) <= 1e-15_wp, &
               'contact points coincide on the table')
    call check_close(dot_product(work%frames(pair%frame_1d)%rot(:, 3), work%frames(pair%frame_2d)%rot(:, 3)), &
                     -1.0_wp, 0.0_wp, 1e-15_wp, 'normals antiparallel')
    do trial = 1, 3
      call check_mechanism_motion('egg on table', m, work, q0, 0.3_wp, 0.4_wp*(trial - 2))
    end do
  end subroutine egg_on_table

  !> A small B-spline paraboloid (table 3.2: a^2 = 0.5 on [-0.5, 0.5]^2, its
  !> outside) in the bowl of the large one (a^2 = 3 on [-2, 2]^2, its inside),
  !> the bowl itself turning and rising (spherical + prismatic from the ground).
  subroutine paraboloid_in_moving_bowl()
    type(mechanism_t) :: m, mo
    type(contact_pair_t) :: pair, open
    type(status_t) :: st
    type(bspline_surface_t) :: big, small
    integer :: f2, s(4), trial
    real(wp) :: gap, q0(9), qo(9), normal(3), given(3), off(3)
    type(mechanism_workspace_t) :: work
    type(mechanism_workspace_t) :: work_mo
    big = quadratic_patch(3.0_wp, 2.0_wp, st)
    small = quadratic_patch(0.5_wp, 0.5_wp, st)
    call moving_bowl(m, f2, s)
    call add_contact_pair(m, 'cup_in_bowl', f2, big, 1.0_wp, 'cup', small, -1.0_wp, pair, st)
    call m%add_law(new_constant_load('push', pair%frame_b, [0.3_wp, -0.2_wp, 0.9_wp], &
                                     [0.1_wp, 0.2_wp, -0.05_wp], .false.))
    call m%add_law(new_constant_load('push_bowl', f2, [0.5_wp, 0.1_wp, -0.3_wp], &
                                     [-0.1_wp, 0.05_wp, 0.2_wp], .false.))
    call m%add_law(new_constant_load('push_contact', pair%frame_1d, [-0.1_wp, 0.4_wp, 0.2_wp], &
                                     [0.03_wp, -0.1_wp, 0.2_wp], .true.))
    call m%set_coordinates([s, pair%coordinates()])
    call m%finalize(st)
    call check(st%ok(), 'cup in bowl built: '//st%text())
    ! the bowl's pose at q0 (spherical x-y-z, then the rise along its z)
    associate (rb => matmul(rot_x(0.1_wp), matmul(rot_y(-0.2_wp), rot_z(0.3_wp))))
      given = 0.2_wp*rb(:, 3) + matmul(rb, [0.4_wp, -0.3_wp, 0.3_wp])
      call place_contact_pair(m, pair, rb, 0.2_wp*rb(:, 3), matmul(rb, rot_x(0.15_wp)), given, gap, normal, st)
      q0 = m%scalars([s, pair%coordinates()])%q
      call m%check_start(work, q0, st)
      call check_contact_branch(work, pair, st)
      call check(st%ok(), 'cup in bowl closes at the start: '//st%text())
      ! the cup moved along the bowl's normal there (world axes), its
      ! orientation kept (the closure moves only z12 from this placement);
      ! by the gap to first order (the cup's support point is not below its
      ! origin: the closure lowers it further)
      off = work%frames(pair%frame_b)%r - given
      print '(a, 3es12.4)', 'cup in bowl: gap, move along the normal, sideways ', gap, dot_product(off, normal), &
        norm2(off - dot_product(off, normal)*normal)
      call check(abs(norm2(normal) - 1) <= 1e-15_wp .and. abs(gap) > 1e-3_wp .and. &
                 norm2(off - dot_product(off, normal)*normal) <= 1e-14_wp, &
                 'cup in bowl: placed along the reported normal')
      call check(maxval(abs(work%frames(pair%frame_b)%rot - matmul(rb, rot_x(0.15_wp)))) <= 1e-14_wp, &
                 'cup in bowl: placement keeps the cup''s orientation')
    end associate
    ! the open chain, started from the closed loop
    call moving_bowl(mo, f2, s)
    call add_open_contact_pair(mo, 'cup_in_bowl', f2, big, 1.0_wp, 'cup', small, -1.0_wp, open, st)
    call mo%add_law(new_constant_load('push', open%frame_b, [0.3_wp, -0.2_wp, 0.9_wp], &
                                      [0.1_wp, 0.2_wp, -0.05_wp], .false.))
    call mo%add_law(new_constant_load('push_bowl', f2, [0.5_wp, 0.1_wp, -0.3_wp], &
                                      [-0.1_wp, 0.05_wp, 0.2_wp], .false.))
    call mo%add_law(new_constant_load('push_contact', open%frame_1d, [-0.1_wp, 0.4_wp, 0.2_wp], &
                                      [0.03_wp, -0.1_wp, 0.2_wp], .true.))
    call mo%set_coordinates([s, open%coordinates()])
    call mo%finalize(st)
    call check(st%ok(), 'cup in bowl, open chain built: '//st%text())
    call place_open_contact_pair(mo, open, work, pair)
    qo = mo%scalars([s, open%coordinates()])%q
    call mo%check_start(work_mo, qo, st)
    call check(st%ok(), 'cup in bowl, open chain starts: '//st%text())
    ! rounding of O(1) poses (the loop is closed to ~1e-15)
    call check(maxval(abs(work_mo%frames(open%frame_b)%rot - work%frames(pair%frame_b)%rot)) <= 1e-14_wp .and. &
               maxval(abs(work_mo%frames(open%frame_b)%r - work%frames(pair%frame_b)%r)) <= 1e-14_wp, &
               'open chain: the cup where the closed loop has it')
    call mo%record_pass(work_mo, st)   ! the monitor is record-only (the position passes skip it)
    call check(st%ok() .and. maxval(abs(work_mo%scalars(open%gaps)%q)) <= 1e-14_wp, 'open chain: g1..g5 zero (rounding)')
    do trial = 1, 3
      call check_mechanism_motion('cup in moving bowl', m, work, q0, 0.2_wp, 0.4_wp*(trial - 2))
      call check_mechanism_motion('cup in moving bowl, open chain', mo, work_mo, qo, 0.2_wp, 0.4_wp*(trial - 2))
      call mo%record_pass(work_mo, st)
      call check(st%ok() .and. maxval(abs(work_mo%scalars(open%gaps)%q)) <= 1e-14_wp, &
                 'open chain: g1..g5 zero along the motion')
    end do
  end subroutine paraboloid_in_moving_bowl

  !> The bowl turning and rising: spherical + prismatic from the ground to frame f2.
  subroutine moving_bowl(m, f2, s)
    type(mechanism_t), intent(inout) :: m
    integer, intent(out) :: f2, s(4)
    integer :: f1
    f1 = m%add_frame('bowl_turn')
    s(1) = m%add_scalar('b1', 0.1_wp)
    s(2) = m%add_scalar('b2', -0.2_wp)
    s(3) = m%add_scalar('b3', 0.3_wp)
    call m%add_element(new_spherical('bowl_turn', 1, f1, s(1:3)))
    f2 = m%add_frame('bowl')
    s(4) = m%add_scalar('b4', 0.2_wp)
    call m%add_element(new_prismatic('bowl_rise', f1, f2, s(4), [0.0_wp, 0.0_wp, 1.0_wp]))
  end subroutine moving_bowl

  !> The egg with its normal pointing inwards: g4, g5 hold for parallel normals
  !> too, so the loop would close on the wrong branch; the placement refuses
  !> it, naming the contact and the side to flip.
  subroutine parallel_branch_refused()
    type(mechanism_t) :: m
    type(contact_pair_t) :: pair
    type(status_t) :: st
    real(wp) :: gap, normal(3)
    type(mechanism_workspace_t) :: work
    call build_egg(m, pair, -1.0_wp, st)
    call place_contact_pair(m, pair, identity, [0.0_wp, 0.0_wp, 0.0_wp], egg_orientation(tilt), &
                            [0.0_wp, 0.0_wp, 0.03_wp], gap, normal, st)
    call m%check_start(work, m%scalars(pair%coordinates())%q, st)
    call check(.not. st%ok() .and. index(st%text(), 'egg_on_table') > 0 .and. index(st%text(), 'parallel') > 0 &
               .and. index(st%text(), 'flip side_2') > 0, 'the parallel branch is refused naming the contact '// &
               'and the side: '//st%text())
  end subroutine parallel_branch_refused

  !> A cup placed beyond the bowl's rim: its nearest point is on the rim, the
  !> closure leaves the patch; the message names the contact.
  subroutine no_closure_named()
    type(mechanism_t) :: m
    type(contact_pair_t) :: pair
    type(status_t) :: st
    type(bspline_surface_t) :: big, small
    real(wp) :: gap, normal(3)
    type(mechanism_workspace_t) :: work, again   ! again: a fresh one takes the second placement
    big = quadratic_patch(3.0_wp, 2.0_wp, st)
    small = quadratic_patch(0.5_wp, 0.5_wp, st)
    call add_contact_pair(m, 'cup_in_bowl', 1, big, 1.0_wp, 'cup', small, -1.0_wp, pair, st)
    call m%set_coordinates(pair%coordinates())
    call m%finalize(st)
    call place_contact_pair(m, pair, identity, [0.0_wp, 0.0_wp, 0.0_wp], rot_x(1.2_wp), &
                            [2.5_wp, 0.0_wp, 1.0_wp], gap, normal, st)
    call m%check_start(work, m%scalars(pair%coordinates())%q, st)
    call check(.not. st%ok() .and. index(st%text(), 'cup_in_bowl') > 0 .and. index(st%text(), 'edge') > 0, &
               'a body not over surface 1 is refused naming the contact: '//st%text())
    ! over the rim: the closure runs off the bowl's patch
    st = status_t()
    call place_contact_pair(m, pair, identity, [0.0_wp, 0.0_wp, 0.0_wp], rot_y(-0.2_wp), &
                            [1.74_wp, 0.0_wp, 1.3_wp], gap, normal, st)
    call m%check_start(again, m%scalars(pair%coordinates())%q, st)
    call check(.not. st%ok() .and. index(st%text(), 'cup_in_bowl') > 0 .and. index(st%text(), 'off by') > 0, &
               'a contact that cannot close is refused naming it and by how much: '//st%text())
  end subroutine no_closure_named

  !> The egg on the table by the open chain, spinning and rocking under
  !> gravity (frictionless, bilateral), with a second closure monitor
  !> against an egg 1.1 times as large: its gaps are millimetres and change
  !> along the motion, so a stale value cannot pass for a fresh one. Every
  !> record (after a step, and again after a right-hand side at the same
  !> state, whose dynamics the record reuses without a position pass) must
  !> hold the monitor evaluated directly at the recorded q; the right-hand
  !> side must leave its outputs alone.
  subroutine monitor_only_in_records()
    type(mechanism_ode_t), target :: sys
    type(mechanism_t) :: direct
    type(contact_pair_t) :: open
    type(plane_t) :: table
    type(ellipsoid_t) :: egg, larger
    type(ode_integrator_t) :: integ
    type(ode_options_t) :: opt
    type(status_t) :: st
    integer :: gaps(5), k, i, monitor, reused
    real(wp), allocatable :: y(:), ydot(:)
    real(wp) :: t, worst, change
    real(wp), parameter :: sentinel = 7.0_wp
    character(len=2) :: digit
    type(mechanism_workspace_t) :: work_direct
    table = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
    egg = ellipsoid_t(egg_a, egg_b, egg_a, st)
    larger = ellipsoid_t(1.1_wp*egg_a, 1.1_wp*egg_b, 1.1_wp*egg_a, st)
    associate (m => sys%mechanism, work => sys%work)
      call add_open_contact_pair(m, 'egg_on_table', 1, table, 1.0_wp, 'egg', egg, 1.0_wp, open, st)
      ! a solid ellipsoid of 0.1 kg
      call m%add_element(new_mass_element('egg', open%frame_b, 0.1_wp, 0.02_wp*reshape([egg_a**2 + egg_b**2, &
        0.0_wp, 0.0_wp, 0.0_wp, 2*egg_a**2, 0.0_wp, 0.0_wp, 0.0_wp, egg_a**2 + egg_b**2], [3, 3]), &
        [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, -9.80665_wp], st))
      do k = 1, 5
        write (digit, '(i1)') k
        gaps(k) = m%add_scalar('larger.g'//trim(digit))
        call m%add_monitor(gaps(k), merge('m', '1', k <= 3))
      end do
      call m%add_element(new_closure_monitor('larger', open%frame_1d, open%frame_b, larger, 1.0_wp, &
                                             [open%u2, open%v2], gaps))
      monitor = m%n_elements
      call m%set_coordinates(open%coordinates())
      call m%finalize(st)
      call check(st%ok(), 'records: egg with a second monitor built: '//st%text())
      if (.not. st%ok()) return
      ! touching at (u2, v2) = (0.3, -0.2) of the egg, spinning at 30 rad/s about the normal
      y = sys%initial_state([0.0_wp, 0.0_wp, 0.0_wp, 0.3_wp, -0.2_wp], [0.05_wp, 0.0_wp, 30.0_wp, 0.0_wp, 0.0_wp])
      call sys%check_start(y, st)
      call check(st%ok(), 'records: the egg starts: '//st%text())
      if (.not. st%ok()) return
      allocate (ydot(size(y)))
      call sys%start_series(10)
      call integ%start(sys, 0.0_wp, y, opt, st)
      reused = work%dynamics_reused
      do i = 1, 4
        call integ%advance(0.005_wp*i, t, y, st)
        if (st%ok()) call sys%record(t, y, RECORD_OUTPUT, st)
        work%scalars(gaps)%q = sentinel
        if (st%ok()) call sys%rhs(t, y + 1e-6_wp, ydot, st)   ! another state: a position pass
        if (st%ok()) call sys%rhs(t, y, ydot, st)
        call check(all(work%scalars(gaps)%q == sentinel), 'records: right-hand sides leave the monitor alone')
        if (st%ok()) call sys%record(t, y, RECORD_OUTPUT, st)   ! reuses the right-hand side's dynamics
      end do
      call check(st%ok(), 'records: integrated 0.02 s: '//st%text())
      if (.not. st%ok()) return
      call check(work%dynamics_reused >= reused + 4, 'records: the records after a right-hand side reused its dynamics')
    end associate
    worst = 0
    do i = 1, sys%series%n
      direct = sys%mechanism
      call direct%set_positions(work_direct, sys%series%q(:, i), st)
      if (st%ok()) call work_direct%elements(monitor)%e%position(work_direct%frames, work_direct%scalars, st)
      if (.not. st%ok()) exit
      worst = max(worst, maxval(abs(sys%series%monitor(:, i) - work_direct%scalars(gaps)%q)))
    end do
    change = maxval(abs(sys%series%monitor(:, sys%series%n) - sys%series%monitor(:, 1)))
    ! the same operations on the same q, up to the compiler's contractions: a
    ! few ulps of the O(0.03 m) lengths; a stale value is off by the change
    call check(st%ok() .and. sys%series%n == 8 .and. worst <= 1e-15_wp, &
               'records: the monitor''s outputs equal a direct evaluation at every recorded state')
    call check(maxval(abs(sys%series%monitor(1:3, :sys%series%n))) > 1e-4_wp .and. change > 1e-6_wp, &
               'records: the second monitor''s gaps change along the motion (stale values would show)')
    print '(a, es10.2, a, es10.2, a)', '  records: monitor against direct evaluation ', worst, ' m (change ', &
      change, ')'
  end subroutine monitor_only_in_records

  !> An output of a record-only element used by the mechanism (here a gap
  !> of the open chain's monitor made a coordinate) is refused at finalize.
  subroutine record_only_read_refused()
    type(mechanism_t) :: m
    type(contact_pair_t) :: open
    type(plane_t) :: table
    type(ellipsoid_t) :: egg
    type(status_t) :: st
    table = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
    egg = ellipsoid_t(egg_a, egg_b, egg_a, st)
    call add_open_contact_pair(m, 'egg_on_table', 1, table, 1.0_wp, 'egg', egg, 1.0_wp, open, st)
    call m%set_coordinates([open%coordinates(), open%gaps(1)])
    call m%finalize(st)
    call check(.not. st%ok() .and. index(st%text(), 'egg_on_table.closure') > 0 .and. &
               index(st%text(), 'record-only') > 0 .and. index(st%text(), 'egg_on_table.g1') > 0, &
               'an output of a record-only element read by the mechanism is refused: '//st%text())
  end subroutine record_only_read_refused

  !> z = (x^2 + y^2)/a2 on [-w, w]^2 by SURFIT (degree 5, 13 x 13, s = 0.05).
  function quadratic_patch(a2, w, status) result(s)
    real(wp), intent(in) :: a2, w
    type(status_t), intent(inout) :: status
    type(bspline_surface_t) :: s
    real(wp) :: x(169), y(169)
    integer :: i, j
    do j = 1, 13
      do i = 1, 13
        x(i + 13*(j - 1)) = -w + 2*w*(i - 1)/12.0_wp
        y(i + 13*(j - 1)) = -w + 2*w*(j - 1)/12.0_wp
      end do
    end do
    s = bspline_scattered(x, y, (x**2 + y**2)/a2, 0.05_wp, 5, 5, status)
  end function quadratic_patch
end program test_contact_pair
