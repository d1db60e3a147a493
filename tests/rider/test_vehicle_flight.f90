!> A vehicle that flies (&sled may_fly; rider_vehicle_flight), against
!> closed forms:
!>
!>   drop        a ring dropped from h0 = 0.5 m, pitched 0.05 rad nose up,
!>               onto a level plane (frictionless landing, restitution e):
!>               its rear lands first at t = sqrt(2 h0/g) with the normal
!>               speed sqrt(2 g h0) (drop height h0), and the landing's
!>               normal impulse is (1 + e) m_eff v_n, m_eff = 1/(n.K n),
!>               K = kinetostatics_impact's rigid_body_delassus of the
!>               vehicle's mass and inertia (vehicle_body) at the arm from
!>               its centre of mass to the rear contact: the free rigid body's
!>               formula against the mechanism's J M^-1 J^T; the energy lost
!>               (1 - e^2) m_eff v_n^2/2 and the rear's rebound e v_n.
!>               With e = 0 the rear stays on and the front, pivoting down
!>               about it, lands next.
!>   jump        a mat on the jump of test_rider_flight (35 deg, 2 deg, a lip
!>               into 20 deg), dry, frictionless: it leaves the lip and the
!>               whole vehicle flies. In the flight gravity alone acts on it
!>               (the motion stays in the slide's symmetry plane, where the
!>               kept roll needs no torque), so its centre of mass follows
!>               r0 + v0 t + g t^2/2 and it turns at a constant rate from the
!>               take-off state the run records (1e-7 m, 1e-6 m/s: the
!>               integration's rtol 1e-10 over ~10 m); the landing time and
!>               the landing contact's normal speed against that projectile
!>               meeting the 20 deg straight (1e-7 s, 1e-6 relative); at
!>               every switch the body's pose and twist are continuous
!>               (1e-9: the closure's tolerance).
!>   columns     the closed front's closure solves for the pitch or the
!>               heading by their columns of the closure Jacobian
!>               (solve_columns, m/rad): against central differences of the
!>               open front's gap in the pitch and the heading, a ring in a
!>               tube at poses with its rear up one wall (1e-7); in a
!>               round tube the pitch's column stays the larger (the bowl,
!>               where it does not: tests/cli/sled_vehicles.sh).
!>   free        a ring with both contacts open in a round tube, thrown
!>               up, turning about all three axes (the roll too): a free
!>               rigid body in six coordinates: its centre of mass flies
!>               the projectile's parabola, its angular momentum about the
!>               centre of mass stays (1e-9 of it) and its energy (1e-9);
!>               (the five-coordinate flight before held the roll to the
!>               slide by a couple: no free body, the test not possible).
!>   gap_rate    the rate of an open end's gap (point_gap_rate: the end's
!>               velocity along the normal at its foot point, the root whose
!>               zero is a flight's apex, its highest point) against central
!>               differences of point_gap along the motion, the thrown
!>               ring of `free` at its start, both ends (1e-8 m/s; seen 1.3e-10:
!>               h = 1e-6 s, the rounding of the gaps over 2 h).
!>   solved      the same ring, both contacts on, driven 0.4 s in the
!>               build whose closure solves the pitch and in the one that
!>               solves the heading: the same motion (the body's pose to
!>               1e-7 m, the integration's tolerance), and the heading's
!>               closure at the pitch build's pose gives back its heading
!>               (1e-10 rad): a switch between them is continuous.
program test_vehicle_flight
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: plane_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: section_part_description_t
  use geometry_description, only: geometry_description_t, build_geometry
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_point_impact, only: point_gap, point_gap_rate
  use kinetostatics_mechanism, only: mechanism_workspace_t
  use kinetostatics_models, only: sled_description_t
  use kinetostatics_impact, only: impact_law_t, rigid_body_delassus
  use rider_vehicle, only: vehicle_t, vehicle_body_t, vehicle_body, VEHICLE_MAT
  use rider_vehicle_flight, only: vehicle_flight_ode_t, build_vehicle_flight, drive_vehicle, solve_columns, &
    SOLVE_PITCH, SOLVE_YAW, press_or_open
  use vehicle_fixtures, only: flying_ring, on_contacts, centre, quiet_options
  implicit none (type, external)

  real(wp), parameter :: g = 9.80665_wp

  call drop(0.5_wp)
  call drop(0.0_wp)
  call jump()
  call columns()
  call solved()
  call free()
  call gap_rate()
  call take_off_at_press_or_open()
  call finish_tests('test_vehicle_flight')

contains

  subroutine drop(e)
    real(wp), intent(in) :: e
    real(wp), parameter :: h0 = 0.5_wp, pitch0 = -0.05_wp
    type(vehicle_body_t) :: vb
    class(surface_t), allocatable :: plane
    type(vehicle_flight_ode_t), target :: sys
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    real(wp) :: t_land, v_n, rot(3, 3), k(3, 3), m_eff
    character(len=:), allocatable :: label
    integer :: i
    label = 'drop, e = '//merge('0.5', '0  ', e > 0)
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
    call flying_ring(plane, e, sys, q0, qd0, st)
    call check(st%ok(), label//': the builds: '//st%text())
    if (.not. st%ok()) return
    ! in the air (both contacts open), at rest
    y = on_contacts(sys, 3, [0.0_wp, 0.0_wp, 0.0_wp, pitch0, h0, 0.0_wp], spread(0.0_wp, 1, 6))
    t_land = sqrt(2*h0/g)
    call drive_vehicle(sys, y, quiet_options(1e-10_wp, 1e-12_wp, 0.05_wp, merge(t_land + 0.02_wp, 1.5_wp, e > 0), &
                                             0.01_wp), result, st)
    call check(st%ok(), label//': runs: '//st%text())
    call check(sys%flights%landings >= 1, label//': lands')
    if (sys%flights%landings < 1) return
    v_n = sqrt(2*g*h0)
    call vehicle_body(sys%vehicle, vb, st)
    ! at the landing: pitched by pitch0 about y (rot_y), not turned
    rot = reshape([cos(pitch0), 0.0_wp, -sin(pitch0), 0.0_wp, 1.0_wp, 0.0_wp, sin(pitch0), 0.0_wp, cos(pitch0)], &
                  [3, 3])
    k = rigid_body_delassus(vb%body%mass, matmul(rot, matmul(vb%body%inertia, transpose(rot))), &
                            -matmul(rot, vb%body%com))
    m_eff = 1/k(3, 3)
    associate (l => sys%flights%landing(1))
      call check(l%contact == 1, label//': the rear lands first')
      ! the root's location and the integration (rtol 1e-10)
      call check_close(l%time, t_land, 1e-8_wp, 0.0_wp, label//': lands at sqrt(2 h0/g)')
      call check_close(l%normal_speed, v_n, 1e-8_wp, 0.0_wp, label//': normal speed sqrt(2 g h0)')
      call check_close(l%drop_height, h0, 1e-8_wp, 0.0_wp, label//': drop height h0')
      ! the impulse of the recorded speed: the effective mass alone (rounding)
      call check_close(l%normal_impulse, (1 + e)*m_eff*l%normal_speed, 1e-10_wp, 0.0_wp, &
                       label//': normal impulse (1 + e) m_eff v_n')
      call check_close(l%energy_lost, (1 - e**2)*m_eff*l%normal_speed**2/2, 1e-10_wp, 0.0_wp, &
                       label//': energy lost (1 - e^2) m_eff v_n^2/2')
      call check(l%closed .eqv. (e == 0), label//': '//merge('stays on', 'flies on', e == 0))
      ! the rebound: the rear's velocity (the bar's origin) at the first record after the impact
      associate (s => sys%series)
        i = findloc(s%time(:s%n), l%time, dim=1, back=.true.)
        call check(i > 1, label//': a record after the landing')
        if (i > 1) call check_close(s%body_v(3, 1, i), e*l%normal_speed, 1e-10_wp, 1e-12_wp, &
                                    label//': the rear rebounds at e v_n')
      end associate
    end associate
    if (e == 0) then
      call check(sys%flights%landings >= 2, label//': the front lands next')
      if (sys%flights%landings >= 2) call check(sys%flights%landing(2)%contact == 2 .and. &
                                                sys%flights%landing(2)%time > sys%flights%landing(1)%time, &
                                                label//': the front lands after the rear')
    end if
  end subroutine drop

  subroutine jump()
    type(geometry_description_t) :: gd
    class(surface_t), allocatable :: slide
    type(vehicle_t) :: v
    type(vehicle_body_t) :: vb
    type(sled_description_t) :: d
    type(vehicle_flight_ode_t), target :: sys
    type(driver_result_t) :: result
    type(status_t) :: st
    type(surface_point_t) :: pt
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    real(wp) :: c0(3), v0(3), w0(3), c(3), vc(3), tau, worst_r, worst_v, worst_w, jump_r, jump_v
    real(wp) :: normal(3), base(3), t_hit, speed_hit, t_land
    integer :: i, first, last, k, contact, switches
    gd%kind = 'slide'
    gd%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    gd%slide%elements%transition_length = 1
    gd%slide%elements%exact = .true.
    gd%slide%elements%elements = [slide_element_t(kind='straight', length=5.0_wp, slope_deg=35.0_wp), &
                                  slide_element_t(kind='straight', length=2.0_wp, slope_deg=2.0_wp), &
                                  slide_element_t(kind='straight', length=8.0_wp, slope_deg=20.0_wp), &
                                  slide_element_t(kind='runout', length=6.0_wp, slope_deg=1.0_wp)]
    gd%slide%section%parts = [section_part_description_t(kind='circle', radius=0.5_wp)]
    call build_geometry(gd, slide, st)
    call check(st%ok(), 'jump: the slide: '//st%text())
    if (.not. st%ok()) return
    v = vehicle_t(VEHICLE_MAT, 1, 1.0_wp)
    v%may_fly = .true.
    v%landing = impact_law_t(restitution=0, mu=0)
    d%q0 = [1.0_wp, 1.5707963267948966_wp, 0.0_wp]
    d%qd0 = [2.0_wp, 0.0_wp, 0.0_wp]
    call build_vehicle_flight(v, d, slide, sys, q0, qd0, st)
    call check(st%ok(), 'jump: the builds: '//st%text())
    if (.not. st%ok()) return
    call vehicle_body(v, vb, st)
    y = sys%initial_state(q0, qd0)
    call drive_vehicle(sys, y, quiet_options(1e-10_wp, 1e-9_wp, 0.05_wp, 6.0_wp, 0.01_wp), result, st)
    print '(a)', 'jump: '//sys%outcome
    call check(st%ok(), 'jump: runs: '//st%text())
    call check(sys%flights%whole_flights >= 1, 'jump: the whole vehicle flies')
    associate (s => sys%series, open => sys%open_record)
      call check(size(open) == s%n, 'jump: an open state per record')
      ! every switch: two records at one time, the body's pose and twist the same
      jump_r = 0
      jump_v = 0
      switches = 0
      do i = 2, s%n
        if (s%time(i) /= s%time(i - 1)) cycle
        switches = switches + 1
        jump_r = max(jump_r, maxval(abs(s%body_r(:, 1, i) - s%body_r(:, 1, i - 1))), &
                     maxval(abs(s%body_rot(:, :, 1, i) - s%body_rot(:, :, 1, i - 1))))
        ! a take-off (no landing's impulse between): a contact more open
        if (open(i) /= open(i - 1) .and. iand(open(i), open(i - 1)) == open(i - 1)) &
          jump_v = max(jump_v, maxval(abs(s%body_v(:, 1, i) - s%body_v(:, 1, i - 1))), &
                       maxval(abs(s%body_omega(:, 1, i) - s%body_omega(:, 1, i - 1))))
      end do
      print '(a, i0, a, 2es10.2)', 'jump: pose, twist jumps at the ', switches, ' switches ', jump_r, jump_v
      call check(switches == 4, 'jump: four switches (front, rear off; front, rear on)')
      call check(jump_r <= 1e-9_wp, 'jump: the pose continuous through every switch')
      call check(jump_v <= 1e-9_wp, 'jump: the twist continuous through every take-off')
      ! the whole flight: the first stretch with both contacts open
      first = findloc(open, 3, dim=1)
      if (first == 0) return
      last = first
      do while (last < s%n)
        if (open(last + 1) /= 3) exit
        last = last + 1
      end do
      c0 = centre(s, vb%body%com, first)
      w0 = s%body_omega(:, 1, first)
      v0 = s%body_v(:, 1, first) + cross(w0, c0 - s%body_r(:, 1, first))
      worst_r = 0
      worst_v = 0
      worst_w = 0
      do i = first, last
        tau = s%time(i) - s%time(first)
        c = centre(s, vb%body%com, i)
        vc = s%body_v(:, 1, i) + cross(s%body_omega(:, 1, i), c - s%body_r(:, 1, i))
        worst_r = max(worst_r, norm2(c - (c0 + v0*tau + [0.0_wp, 0.0_wp, -g]*tau**2/2)))
        worst_v = max(worst_v, norm2(vc - (v0 + [0.0_wp, 0.0_wp, -g]*tau)))
        worst_w = max(worst_w, norm2(s%body_omega(:, 1, i) - w0))
      end do
      print '(a, i0, a, 3es10.2)', 'jump: whole flight over ', last - first + 1, ' records; parabola, speed, '// &
        'turn rate off by ', worst_r, worst_v, worst_w
      call check(last > first + 5, 'jump: the whole flight spans records')
      call check(worst_r <= 1e-7_wp, 'jump: the centre of mass on the parabola from the take-off')
      call check(worst_v <= 1e-6_wp, 'jump: its velocity v0 + g t')
      call check(worst_w <= 1e-6_wp, 'jump: it turns at a constant rate')
      ! the landing that ends it: the projectile meeting the 20 deg straight
      ! (its bottom line: the point and normal at v = pi/2 under the foot)
      k = findloc(sys%flights%landing%time, s%time(last), dim=1)
      call check(k > 0, 'jump: the whole flight ends at a landing')
      if (k == 0) return
      contact = sys%flights%landing(k)%contact
      t_land = sys%flights%landing(k)%time
      call slide%evaluate(s%q(1, last) + 0.5_wp, 1.5707963267948966_wp, 1, pt, st)
      normal = cross(pt%ru, pt%rv)
      normal = normal/norm2(normal)
      if (normal(3) < 0) normal = -normal
      base = pt%r
      call projectile_landing(s%body_r(:, 1, first), s%body_rot(:, :, 1, first), c0, v0, w0, vb%length, contact, &
                              normal, base, t_hit, speed_hit)
      call check_close(s%time(first) + t_hit, t_land, 0.0_wp, 1e-7_wp, 'jump: the landing time of the projectile')
      call check_close(sys%flights%landing(k)%normal_speed, speed_hit, 1e-6_wp, 0.0_wp, &
                       'jump: the landing speed of the projectile')
    end associate
  end subroutine jump

  !> A ring (may_fly, frictionless) in a straight tube of radius 1 m at 10
  !> degrees, its builds made, started at u = 3 m on the bottom.
  subroutine ring_in_tube(sys, slide, q0, qd0, st)
    type(vehicle_flight_ode_t), intent(inout) :: sys
    class(surface_t), allocatable, intent(out) :: slide
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: st
    type(geometry_description_t) :: gd
    gd%kind = 'slide'
    gd%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    gd%slide%elements%transition_length = 1
    gd%slide%elements%exact = .true.
    gd%slide%elements%elements = [slide_element_t(kind='straight', length=12.0_wp, slope_deg=10.0_wp)]
    gd%slide%section%parts = [section_part_description_t(kind='circle', radius=1.0_wp)]
    call build_geometry(gd, slide, st)
    if (.not. st%ok()) return
    call flying_ring(slide, 0.0_wp, sys, q0, qd0, st, start=[3.0_wp, 1.5707963267948966_wp, 0.0_wp], &
                     start_rate=[1.0_wp, 0.0_wp, 0.0_wp])
  end subroutine ring_in_tube

  subroutine columns()
    type(vehicle_flight_ode_t), target :: sys
    class(surface_t), allocatable :: slide
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:)
    real(wp), parameter :: h = 1e-6_wp, half_pi = 1.5707963267948966_wp
    real(wp) :: poses(6, 4), c(2), fd(2), q(6), gap(2), worst
    integer :: i, k, j
    call ring_in_tube(sys, slide, q0, qd0, st)
    call check(st%ok(), 'columns: the builds: '//st%text())
    if (.not. st%ok()) return
    ! [u, v, phi, pitch, rear_lift, roll] of the open build: the rear up
    ! the wall (v), turned, pitched, lifted, rolled (the roll moves neither
    ! contact point); the last with the rear 80 deg up
    poses = reshape([3.0_wp, half_pi + 0.4_wp, 0.3_wp, 0.1_wp, 0.05_wp, 0.2_wp, &
                     3.0_wp, half_pi - 0.7_wp, -0.5_wp, 0.3_wp, 0.1_wp, -0.4_wp, &
                     3.0_wp, half_pi + 1.0_wp, 0.8_wp, 0.6_wp, 0.0_wp, 0.0_wp, &
                     3.0_wp, half_pi + 1.4_wp, 0.0_wp, 0.8_wp, 0.0_wp, 1.0_wp], [6, 4])
    sys%mechanism = sys%builds(3)
    call sys%mechanism%prepare_workspace(sys%work)
    worst = 0
    do i = 1, size(poses, 2)
      call sys%mechanism%set_positions(sys%work, poses(:, i), st)
      call check(st%ok(), 'columns: pose '//achar(48 + i)//': '//st%text())
      if (.not. st%ok()) return
      c = solve_columns(sys%work, sys%heading, sys%point(2), sys%foot(2))
      do k = 1, 2
        j = merge(4, 3, k == SOLVE_PITCH)   ! the pitch, the heading in q
        q = poses(:, i)
        q(j) = q(j) + h
        call sys%mechanism%set_positions(sys%work, q, st)
        gap(1) = point_gap(sys%work, sys%point(2), sys%foot(2))
        q(j) = q(j) - 2*h
        call sys%mechanism%set_positions(sys%work, q, st)
        gap(2) = point_gap(sys%work, sys%point(2), sys%foot(2))
        fd(k) = abs(gap(1) - gap(2))/(2*h)
      end do
      print '(a, i0, a, 2f12.8, a, 2f12.8)', 'columns: pose ', i, ': pitch, heading ', c, '; differences ', fd
      worst = max(worst, maxval(abs(c - fd)))
      ! in a round tube the pitch's column is the larger: no switch (the
      ! heading's is zero with the bar along the tube, by the symmetry)
      call check(c(SOLVE_PITCH) > 2*c(SOLVE_YAW), 'columns: in a tube the pitch''s column the larger')
    end do
    call check(st%ok(), 'columns: the differences: '//st%text())
    call check(worst <= 1e-7_wp, 'columns: against central differences of the gap')
  end subroutine columns

  subroutine solved()
    type(vehicle_flight_ode_t), target :: sys
    type(mechanism_ode_t), target :: by_pitch, by_yaw
    class(surface_t), allocatable :: slide
    type(status_t) :: st
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    real(wp) :: residual, pitch, pitch_rate, phi, worst
    integer :: n1, n2
    call ring_in_tube(sys, slide, q0, qd0, st)
    call check(st%ok(), 'solved: the builds: '//st%text())
    if (.not. st%ok()) return
    ! the rear 0.5 rad up the wall, turned by 0.4 rad, sliding down and across
    q0 = [3.0_wp, 1.5707963267948966_wp + 0.5_wp, 0.4_wp]
    qd0 = [1.0_wp, -0.3_wp, 0.2_wp]
    by_pitch%mechanism = sys%builds(0)
    call by_pitch%mechanism%prepare_workspace(by_pitch%work)
    call by_pitch%mechanism%evaluate(by_pitch%work, 0.0_wp, q0, qd0, residual, st)
    call check(st%ok(), 'solved: the pitch build at the start: '//st%text())
    if (.not. st%ok()) return
    pitch = by_pitch%work%scalars(by_pitch%mechanism%scalar_index('pitch'))%q
    pitch_rate = by_pitch%work%scalars(by_pitch%mechanism%scalar_index('pitch'))%qd
    ! the heading's closure, started as a switch starts it (every scalar
    ! the pitch build's) but from a heading 0.05 rad off, finds it again
    by_yaw%mechanism = sys%yaw_builds(0)
    call by_yaw%mechanism%prepare_workspace(by_yaw%work)
    by_yaw%work%scalars(:)%q = by_pitch%work%scalars(:)%q
    by_yaw%work%scalars(by_yaw%mechanism%scalar_index('phi'))%q = q0(3) + 0.05_wp
    call by_yaw%mechanism%evaluate(by_yaw%work, 0.0_wp, [q0(1), q0(2), pitch], [qd0(1), qd0(2), pitch_rate], &
                                   residual, st)
    call check(st%ok(), 'solved: the heading build at the start: '//st%text())
    if (.not. st%ok()) return
    phi = by_yaw%work%scalars(by_yaw%mechanism%scalar_index('phi'))%q
    call check_close(phi, q0(3), 0.0_wp, 1e-10_wp, 'solved: the heading''s closure gives back the heading')
    call check_close(by_yaw%work%scalars(by_yaw%mechanism%scalar_index('phi'))%qd, qd0(3), 0.0_wp, 1e-10_wp, &
                     'solved: ... and its rate')
    options = quiet_options(1e-10_wp, 1e-12_wp, 0.05_wp, 0.4_wp, 0.1_wp)
    y = by_pitch%initial_state(q0, qd0)
    call drive(by_pitch, y, options, result, st)
    call check(st%ok(), 'solved: the pitch build runs: '//st%text())
    y = by_yaw%initial_state([q0(1), q0(2), pitch], [qd0(1), qd0(2), pitch_rate])
    call drive(by_yaw, y, options, result, st)
    call check(st%ok(), 'solved: the heading build runs: '//st%text())
    if (.not. st%ok()) return
    n1 = by_pitch%series%n
    n2 = by_yaw%series%n
    call check(n1 == n2 .and. n1 >= 5, 'solved: the same records')
    if (n1 /= n2) return
    worst = maxval(abs(by_pitch%series%body_r(:, :, :n1) - by_yaw%series%body_r(:, :, :n2)))
    worst = max(worst, maxval(abs(by_pitch%series%body_rot(:, :, :, :n1) - by_yaw%series%body_rot(:, :, :, :n2))))
    print '(a, es10.2, a, 2es10.2)', 'solved: pose apart by ', worst, '; normal forces ', &
      by_pitch%series%normal(:, n1) - by_yaw%series%normal(:, n2)
    call check(worst <= 1e-7_wp, 'solved: the same motion in both builds')
    call check(maxval(abs(by_pitch%series%normal(:, n1) - by_yaw%series%normal(:, n2))) <= &
               1e-6_wp*maxval(abs(by_pitch%series%normal(:, n1))), 'solved: the same normal forces')
  end subroutine solved

  !> A ring thrown up in the round tube of ring_in_tube with both contacts
  !> open, turning about its heading, pitch and roll axes at once, for
  !> 0.25 s (no landing: its rear 0.3 m up, rising at 1.5 m/s): the free
  !> rigid body. Its centre of mass c(t) = c0 + v0 t + g t^2/2, its angular
  !> momentum about c, R I R^T w, constant, its energy constant.
  subroutine free()
    type(vehicle_flight_ode_t), target :: sys
    class(surface_t), allocatable :: slide
    type(vehicle_body_t) :: vb
    type(status_t) :: st
    type(driver_result_t) :: result
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    real(wp) :: c0(3), v0(3), l0(3), l(3), c(3), tau, worst_r, worst_l, worst_e, e0, rot(3, 3), roll_span(2)
    integer :: i
    call ring_in_tube(sys, slide, q0, qd0, st)
    call check(st%ok(), 'free: the builds: '//st%text())
    if (.not. st%ok()) return
    call vehicle_body(sys%vehicle, vb, st)
    y = on_contacts(sys, 3, [3.0_wp, 1.5707963267948966_wp + 0.1_wp, 0.2_wp, -0.1_wp, 0.3_wp, 0.1_wp], &
                    [1.0_wp, 0.1_wp, 0.8_wp, -0.5_wp, 1.5_wp, 3.0_wp])
    call drive_vehicle(sys, y, quiet_options(1e-12_wp, 1e-12_wp, 0.01_wp, 0.25_wp, 0.01_wp), result, st)
    call check(st%ok(), 'free: runs: '//st%text())
    if (.not. st%ok()) return
    associate (s => sys%series)
      call check(sys%flights%landings == 0 .and. all(sys%open_record == 3) .and. s%n >= 25, &
                 'free: in the air all the way, no landing')
      c0 = centre(s, vb%body%com, 1)
      v0 = s%body_v(:, 1, 1) + cross(s%body_omega(:, 1, 1), c0 - s%body_r(:, 1, 1))
      rot = s%body_rot(:, :, 1, 1)
      l0 = matmul(rot, matmul(vb%body%inertia, matmul(transpose(rot), s%body_omega(:, 1, 1))))
      e0 = s%kinetic(1) + s%potential(1)
      worst_r = 0
      worst_l = 0
      worst_e = 0
      roll_span = [huge(1.0_wp), -huge(1.0_wp)]
      do i = 1, s%n
        tau = s%time(i) - s%time(1)
        c = centre(s, vb%body%com, i)
        worst_r = max(worst_r, norm2(c - (c0 + v0*tau + [0.0_wp, 0.0_wp, -g]*tau**2/2)))
        rot = s%body_rot(:, :, 1, i)
        l = matmul(rot, matmul(vb%body%inertia, matmul(transpose(rot), s%body_omega(:, 1, i))))
        worst_l = max(worst_l, norm2(l - l0)/norm2(l0))
        worst_e = max(worst_e, abs(s%kinetic(i) + s%potential(i) - e0)/s%kinetic(1))
        roll_span = [min(roll_span(1), s%q(6, i)), max(roll_span(2), s%q(6, i))]
      end do
      print '(a, i0, a, 3es10.2, a, 2f8.4)', 'free: ', s%n, ' records; parabola (m), angular momentum, energy '// &
        '(relative) off by ', worst_r, worst_l, worst_e, '; roll from, to (rad) ', roll_span
      call check(roll_span(2) - roll_span(1) > 0.3_wp, 'free: the roll turns')
      call check(worst_r <= 1e-9_wp, 'free: the centre of mass a projectile')
      call check(worst_l <= 1e-9_wp, 'free: the angular momentum about the centre of mass conserved')
      call check(worst_e <= 1e-9_wp, 'free: the energy conserved')
    end associate
  end subroutine free

  subroutine gap_rate()
    type(vehicle_flight_ode_t), target :: sys
    class(surface_t), allocatable :: slide
    type(mechanism_workspace_t) :: moved
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    real(wp), parameter :: h = 1e-6_wp   ! s
    real(wp) :: rate, ahead, behind
    integer :: f, k
    call ring_in_tube(sys, slide, q0, qd0, st)
    call check(st%ok(), 'gap_rate: the builds: '//st%text())
    if (.not. st%ok()) return
    y = on_contacts(sys, 3, [3.0_wp, 1.5707963267948966_wp + 0.1_wp, 0.2_wp, -0.1_wp, 0.3_wp, 0.1_wp], &
                    [1.0_wp, 0.1_wp, 0.8_wp, -0.5_wp, 1.5_wp, 3.0_wp])
    f = sys%mechanism%f
    call sys%mechanism%set_positions(sys%work, y(1:f), st)
    call check(st%ok(), 'gap_rate: positions: '//st%text())
    if (.not. st%ok()) return
    ! the vehicle's speeds are its coordinates' rates (ns = f)
    call check(sys%mechanism%ns == f, 'gap_rate: speeds are the rates')
    call sys%mechanism%set_velocities(sys%work, y(f + 1:2*f))
    do k = 1, 2
      rate = point_gap_rate(sys%work, sys%point(k), sys%foot(k))
      moved = sys%work
      call sys%mechanism%set_positions(moved, y(1:f) + h*y(f + 1:2*f), st)
      ahead = point_gap(moved, sys%point(k), sys%foot(k))
      moved = sys%work
      call sys%mechanism%set_positions(moved, y(1:f) - h*y(f + 1:2*f), st)
      behind = point_gap(moved, sys%point(k), sys%foot(k))
      print '(a, i0, a, 2es24.15)', 'gap_rate: end ', k, ' rate, central difference ', rate, (ahead - behind)/(2*h)
      call check(st%ok() .and. abs(rate) > 0.1_wp .and. abs(rate - (ahead - behind)/(2*h)) <= 1e-8_wp, &
                 'gap_rate: the gap''s rate against central differences along the motion')
    end do
  end subroutine gap_rate

  !> press_or_open's contract: a closed contact that would pull after a
  !> switch opens, taking off at the switch's time (its take_off_time: the
  !> landing's cause names the time since, the quick landings count from
  !> it). A ring on a level plane on its rear contact alone (the front open,
  !> mask 2), pitched 0.5 rad nose up and turning nose up at 20 rad/s: its
  !> centre of mass circles the rear contact, whose normal force would be
  !> m (g - w^2 r sin(pitch) ...) < 0, so the rear opens too (mask 3) at
  !> t = 0.7 s; on 8f2e33d its take_off_time stayed 0 (the time of its last
  !> switch: none), so a landing of it named 0.7 s more than its flight.
  subroutine take_off_at_press_or_open()
    class(surface_t), allocatable :: plane
    type(vehicle_flight_ode_t), target :: sys
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], st)
    call flying_ring(plane, 0.0_wp, sys, q0, qd0, st)
    call check(st%ok(), 'take-off at press_or_open: the builds: '//st%text())
    if (.not. st%ok()) return
    ! on the rear alone: the build of mask 2 (the front open), the rear's lift 0
    y = on_contacts(sys, 2, [0.0_wp, 0.0_wp, 0.0_wp, -0.5_wp, 0.0_wp, 0.0_wp], &
                    [0.0_wp, 0.0_wp, 0.0_wp, -20.0_wp, 0.0_wp, 0.0_wp])
    sys%take_off_time = [0.0_wp, 0.3_wp]
    call press_or_open(sys, 0.7_wp, y, st)
    call check(st%ok(), 'take-off at press_or_open: runs: '//st%text())
    call check(sys%open_mask == 3, 'take-off at press_or_open: the rear opens too')
    call check(sys%take_off_time(1) == 0.7_wp, 'take-off at press_or_open: the rear takes off at the switch''s time')
    call check(sys%take_off_time(2) == 0.3_wp, 'take-off at press_or_open: the front''s take-off stays')
    call check(.not. sys%opened(1), 'take-off at press_or_open: the rear''s gap watched from 0')
  end subroutine take_off_at_press_or_open

  !> The free rigid body from its take-off (the bar frame's origin o0 and
  !> axes rot0, centre of mass c0 with velocity v0, angular velocity w0,
  !> gravity alone): when contact k's point (1: the bar's origin, 2: length
  !> along its x) meets the plane through `base` with `normal`, and its
  !> approach speed there. The point is c(t) + R(w0 t) (p0 - c0) (Rodrigues);
  !> its height above the plane falls through zero: bisection to 1e-13 s.
  subroutine projectile_landing(o0, rot0, c0, v0, w0, length, k, normal, base, t_hit, speed)
    real(wp), intent(in) :: o0(3), rot0(3, 3), c0(3), v0(3), w0(3), length, normal(3), base(3)
    integer, intent(in) :: k
    real(wp), intent(out) :: t_hit, speed
    real(wp) :: p0(3), a, b, m
    integer :: i
    p0 = o0 + merge(0.0_wp, length, k == 1)*rot0(:, 1)
    a = 0
    b = 0.01_wp
    do while (height(b, c0, v0, w0, p0, normal, base) > 0 .and. b < 10)
      a = b
      b = b + 0.01_wp
    end do
    do i = 1, 200
      m = (a + b)/2
      if (height(m, c0, v0, w0, p0, normal, base) > 0) then
        a = m
      else
        b = m
      end if
      if (b - a < 1e-13_wp) exit
    end do
    t_hit = (a + b)/2
    speed = -dot_product(normal, v0 + [0.0_wp, 0.0_wp, -g]*t_hit + cross(w0, turned(p0 - c0, w0, t_hit)))
  end subroutine projectile_landing

  !> The height above the plane (base, normal) at time t of the point p0
  !> of the free body of projectile_landing.
  real(wp) function height(t, c0, v0, w0, p0, normal, base)
    real(wp), intent(in) :: t, c0(3), v0(3), w0(3), p0(3), normal(3), base(3)
    height = dot_product(normal, c0 + v0*t + [0.0_wp, 0.0_wp, -g]*t**2/2 + turned(p0 - c0, w0, t) - base)
  end function height

  !> x turned at the constant angular velocity w0 for the time t (Rodrigues).
  function turned(x, w0, t) result(r)
    real(wp), intent(in) :: x(3), w0(3), t
    real(wp) :: r(3), axis(3), angle
    r = x
    if (norm2(w0) == 0) return
    angle = norm2(w0)*t
    axis = w0/norm2(w0)
    r = x*cos(angle) + cross(axis, x)*sin(angle) + axis*dot_product(axis, x)*(1 - cos(angle))
  end function turned
end program test_vehicle_flight
