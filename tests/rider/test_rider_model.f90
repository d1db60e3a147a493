!> The rider mechanism: where heels and back meet the slide at the start,
!> starts that are refused (which contact, by how much), and a known answer:
!> the rider on the bottom line of a straight inclined tube, Coulomb friction
!> mu at the three contacts, no drag.
!>
!> Known answer (derived in docs/rider.md, "Checks"): the three contacts lie
!> on one straight line, all normals are equal, so the normal forces sum to
!> m g cos(theta) and the friction to mu m g cos(theta):
!>     u'' = g (sin(theta) - mu cos(theta)).
!> The hinges make the distribution determinate: moments about the hip axis
!> of the legs (CoM x_L from the hip, heel at (l, -h)) and of the trunk
!> (CoM x_T < 0, back at (b < 0, -h)), with the effective load
!> m g cos(theta) (mu, -1) per body in the slide's axes:
!>     N_heels = m_L g cos(theta) x_L/(l - mu h),
!>     N_back  = -m_T g cos(theta) x_T/(mu h - b),
!>     N_pelvis = m g cos(theta) - N_heels - N_back.
!>
!> The other laws of the force-law registry (&rider friction) on the same
!> line, the rider sliding at w: the normal forces still sum to
!> m g cos(theta) and every contact slips at w, so
!>     viscous (c per contact)       u'' = g sin(theta) - 3 c w/m,
!>     viscous_normal (mu per |N|)   u'' = g sin(theta) - mu g cos(theta) w,
!>     viscous_weight (mu per M g)   u'' = g sin(theta) - mu g w
!> (each contact takes the weight of its segment; the three add up to m g);
!> each contact's force is the one the same law gives a point mass
!> (slip_force) for that contact's slip and normal force; and the ride under
!> viscous_normal follows w(t) = w_inf + (w0 - w_inf) exp(-k t),
!> k = mu g cos(theta), w_inf = tan(theta)/mu.
!>
!> &rider u0 is the arc length along the centerline: on an exact element
!> chain (its parameter the horizontal length) the pelvis starts u0 m along
!> the centerline from its start, on the straight as in the curve after it.
program test_rider_model
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use geometry_tube, only: tube_surface_t, new_straight_tube, new_tube_surface
  use geometry_curve, only: curve_point_t, constant_curve_t
  use geometry_cross_section, only: circle_section_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use rider_model, only: rider_params_t, rider_layout_t, build_rider, rider_start_velocity, &
    CONTACT_PELVIS, CONTACT_HEELS, CONTACT_BACK, N_CONTACTS, rider_default_mu
  use rider_ride, only: ride_options_t, ride_result_t, simulate_ride
  use base_spec, only: spec_t
  use kinetostatics_force_law, only: force_law_t, friction_law_t, law_place_t
  use kinetostatics_force_law_factory, only: law_spec, force_law_from_spec
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  real(wp), parameter :: theta = 15*pi/180, g = standard_gravity

  call check_start_on_straight()
  call check_start_on_chain()
  call check_refused_starts()
  call check_inclined_tube()
  call check_other_laws()
  call check_viscous_ride()
  call check_no_memory_lost_per_build()
  call finish_tests('test_rider_model')

contains

  function straight_tube(length, radius) result(tube)
    real(wp), intent(in) :: length
    real(wp), intent(in), optional :: radius
    type(tube_surface_t) :: tube
    type(status_t) :: st
    real(wp) :: r
    r = 0.5_wp
    if (present(radius)) r = radius
    tube = new_straight_tube(r, theta, length, st)
    call check(st%ok(), 'straight tube built')
  end function straight_tube

  !> At the bottom of a straight tube heels and back lie on the bottom line:
  !> joint angles 0, contacts at hip + heel length ahead and back length behind.
  subroutine check_start_on_straight()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    real(wp) :: q0(3)
    p%u0 = 5
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call check(st%ok(), 'rider builds: '//st%text())
    call m%check_start(work, q0, st)
    call check(st%ok(), 'the loops close at the start: '//st%text())
    ! atol 1e-12 rad: the start search bisects to 1e-13 rad, Newton polishes
    call check_close(work%scalars(lay%flexion)%q, 0.0_wp, 0.0_wp, 1e-12_wp, 'legs straight')
    call check_close(work%scalars(lay%tilt)%q, 0.0_wp, 0.0_wp, 1e-12_wp, 'trunk straight')
    call check_close(work%scalars(lay%u(CONTACT_HEELS))%q, 5 + lay%body%hip(1) + lay%body%heel(1), 1e-14_wp, 0.0_wp, &
                     'heels ahead by hip + leg length')
    call check_close(work%scalars(lay%u(CONTACT_BACK))%q, 5 + lay%body%hip(1) + lay%body%back(1), 1e-14_wp, 0.0_wp, &
                     'back behind')
    call check_close(work%scalars(lay%v(CONTACT_HEELS))%q, pi/2, 1e-14_wp, 0.0_wp, 'heels at the bottom')
    call check(m%closure_residual(work) <= 1e-12_wp, 'closure residual at the start')
  end subroutine check_start_on_straight

  !> u0 as arc length on an exact chain: a 20 deg straight of 12 m
  !> (horizontally), then a 90 deg curve of radius 8 m at 5 deg. On the
  !> straight the centerline's arc length is the distance from its start
  !> (the old start, u0 m horizontally, lay 1/cos(20 deg) - 1 = 6 % further);
  !> in the curve the tube's own arc length (parameter_at_length solves to
  !> 1e-12 of the length, so 1e-10 relative holds).
  subroutine check_start_on_chain()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(status_t) :: st
    type(element_chain_curve_t) :: chain
    type(tube_surface_t) :: tube
    type(curve_point_t) :: c0, c
    real(wp) :: q0(3)
    chain = new_element_chain([slide_element_t(kind='straight', length=12.0_wp, slope_deg=20.0_wp), &
                               slide_element_t(kind='curve', radius=8.0_wp, angle_deg=90.0_wp, slope_deg=5.0_wp)], &
                              [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 2.0_wp, st)
    if (st%ok()) tube = new_tube_surface(chain, constant_curve_t(value=[0.0_wp, 0.0_wp, 1.0_wp]), &
                                         circle_section_t(radius=0.5_wp), st)
    call check(st%ok(), 'chain tube built: '//st%text())
    if (.not. st%ok()) return
    p%u0 = 4
    call build_rider(p, tube, m, lay, q0, st)
    call check(st%ok(), 'rider builds on the chain: '//st%text())
    call chain%evaluate(0.0_wp, 0, c0, st)
    call chain%evaluate(q0(1), 0, c, st)
    call check_close(norm2(c%d(:, 0) - c0%d(:, 0)), 4.0_wp, 1e-10_wp, 0.0_wp, &
                     'the pelvis starts u0 = 4 m along the straight''s centerline')
    p%u0 = 20
    call build_rider(p, tube, m, lay, q0, st)
    call check(st%ok(), 'rider builds in the curve: '//st%text())
    call check_close(tube%arc_length(q0(1)), 20.0_wp, 1e-10_wp, 0.0_wp, &
                     'the pelvis starts u0 = 20 m along the centerline, in the curve')
    p%u0 = 40
    call build_rider(p, tube, m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'beyond the slide''s end') > 0 .and. &
               index(st%text(), 'arc length') > 0, 'a start beyond the end refused: '//st%text())
  end subroutine check_start_on_chain

  !> Heels beyond the slide's end; the back before the start; a body turned
  !> across a tube narrower than the legs are long (no joint angle puts the
  !> heels on the wall).
  subroutine check_refused_starts()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: q0(3)
    p%u0 = 19.5_wp
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'heels cannot reach') > 0 .and. &
               index(st%text(), 'beyond the slide''s end') > 0, 'heels beyond the end refused: '//st%text())
    st = status_t()
    p%u0 = 0.2_wp
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'back cannot reach') > 0, 'back before the start refused: '// &
               st%text())
    st = status_t()
    p%u0 = 5
    p%heading0 = pi/2
    call build_rider(p, straight_tube(20.0_wp, 0.35_wp), m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'cannot reach the slide') > 0 .and. &
               index(st%text(), ' m ') > 0, 'turned across the tube refused with a distance: '//st%text())
  end subroutine check_refused_starts

  subroutine check_inclined_tube()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    real(wp) :: q0(3), qd0(3), res, h, n_heels, n_back, n_pelvis, mass, mu
    p%u0 = 5
    p%speed0 = 2
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call rider_start_velocity(p, straight_tube(20.0_wp), qd0, st)
    call check_close(qd0(1), 2.0_wp, 1e-15_wp, 0.0_wp, 'start speed along the tube')
    call m%check_start(work, q0, st)
    call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
    call check(st%ok(), 'evaluates: '//st%text())
    ! rtol 1e-12: exact algebra up to the friction's regularization, (1e-6/2)^2/2
    mu = rider_default_mu   ! p's friction not set: the rider's Coulomb mu_D
    call check_close(work%qdd(1), g*(sin(theta) - mu*cos(theta)), 1e-12_wp, 0.0_wp, &
                     'u'''' = g (sin theta - mu cos theta)')
    call check(abs(work%qdd(2)) < 1e-12_wp .and. abs(work%qdd(3)) < 1e-12_wp, 'stays at the bottom, heading kept')
    h = p%body%com_height
    mass = lay%body%pelvis%mass + lay%body%legs%mass + lay%body%trunk%mass
    n_heels = lay%body%legs%mass*g*cos(theta)*lay%body%legs%com(1)/(lay%body%heel(1) - mu*h)
    n_back = -lay%body%trunk%mass*g*cos(theta)*lay%body%trunk%com(1)/(mu*h - lay%body%back(1))
    n_pelvis = mass*g*cos(theta) - n_heels - n_back
    call check_close(work%normal_force(CONTACT_HEELS), n_heels, 1e-12_wp, 0.0_wp, 'heels normal force')
    call check_close(work%normal_force(CONTACT_BACK), n_back, 1e-12_wp, 0.0_wp, 'back normal force')
    call check_close(work%normal_force(CONTACT_PELVIS), n_pelvis, 1e-12_wp, 0.0_wp, 'pelvis normal force')
  end subroutine check_inclined_tube

  !> The viscous laws of the registry through &rider friction: u'' in closed
  !> form, and each contact's force equal to the same law's slip_force (the
  !> point mass's call) at that contact's slip and normal force.
  subroutine check_other_laws()
    character(len=*), parameter :: kinds(3) = [character(len=14) :: 'viscous', 'viscous_normal', 'viscous_weight']
    character(len=*), parameter :: names(3) = [character(len=19) :: 'viscous_coefficient', 'mu', 'mu']
    real(wp), parameter :: values(3) = [40.0_wp, 0.05_wp, 0.03_wp]   ! N s/m, s/m, s/m
    real(wp), parameter :: w = 2   ! m/s
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    class(force_law_t), allocatable :: law
    real(wp) :: q0(3), qd0(3), res, mass, expected, weight(N_CONTACTS), slip(3), force(3)
    integer :: j, k
    do j = 1, size(kinds)
      p = rider_params_t()
      p%u0 = 5
      p%speed0 = w
      p%drag = .false.
      p%friction = law_spec(trim(kinds(j)), trim(names(j)), values(j))
      call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
      call rider_start_velocity(p, straight_tube(20.0_wp), qd0, st)
      call m%check_start(work, q0, st)
      call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
      call check(st%ok(), trim(kinds(j))//': evaluates: '//st%text())
      mass = lay%body%pelvis%mass + lay%body%legs%mass + lay%body%trunk%mass
      select case (j)
      case (1)
        expected = g*sin(theta) - 3*values(j)*w/mass
      case (2)
        expected = g*sin(theta) - values(j)*g*cos(theta)*w
      case default
        expected = g*sin(theta) - values(j)*g*w
      end select
      ! rtol 1e-12: exact algebra (no regularization in these laws), a 3x3 solve
      call check_close(work%qdd(1), expected, 1e-12_wp, 0.0_wp, trim(kinds(j))//': u'''' in closed form')
      call check(abs(work%qdd(2)) < 1e-12_wp .and. abs(work%qdd(3)) < 1e-12_wp, trim(kinds(j))//': stays at the bottom')
      call check_close(sum([(work%normal_force(k), k = 1, N_CONTACTS)]), mass*g*cos(theta), 1e-12_wp, &
                       0.0_wp, trim(kinds(j))//': the normal forces carry m g cos(theta)')
      ! each contact: the law built for a point mass (no contact, the segment's weight) gives the same force
      weight = [lay%body%pelvis%mass, lay%body%legs%mass, lay%body%trunk%mass]*g
      do k = 1, N_CONTACTS
        call force_law_from_spec(p%friction, law_place_t('point', 0, weight(k)), law, st)
        associate (c => work%contact_states(k))
          slip = c%slip - dot_product(c%slip, c%normal)*c%normal
        end associate
        select type (law)
        class is (friction_law_t)
          force = law%slip_force(slip, work%normal_force(k))
        class default
          force = huge(1.0_wp)
        end select
        ! atol 1e-12 N: the same arithmetic up to the scaled laws' |N| factor
        call check(all(abs(m%law_force(work, lay%friction(k)) - force) <= 1e-12_wp*max(1.0_wp, norm2(force))), &
                   trim(kinds(j))//': contact force = the point mass''s slip_force')
        call check(abs(norm2(slip) - w) <= 1e-12_wp, trim(kinds(j))//': every contact slips at w')
      end do
    end do
  end subroutine check_other_laws

  !> A ride down the straight tube under viscous_normal, without water:
  !> the speed against w(t) = w_inf + (w0 - w_inf) exp(-k t).
  subroutine check_viscous_ride()
    real(wp), parameter :: mu = 0.05_wp, w0 = 2   ! s/m, m/s
    type(rider_params_t) :: p
    type(ride_options_t) :: opt
    type(ride_result_t) :: ride
    type(status_t) :: st
    real(wp) :: k, w_inf, worst
    integer :: i
    p%u0 = 2
    p%speed0 = w0
    p%drag = .false.
    p%friction = law_spec('viscous_normal', 'mu', mu)
    opt%output_step = 0.05_wp
    opt%progress_seconds = 0
    call simulate_ride(p, straight_tube(30.0_wp), opt, ride, st)
    call check(st%ok() .and. ride%series%n > 20, 'viscous_normal ride runs: '//st%text())
    if (.not. st%ok()) return
    k = mu*g*cos(theta)
    w_inf = tan(theta)/mu
    worst = 0
    do i = 1, ride%series%n
      associate (t => ride%series%time(i))
        worst = max(worst, abs(ride%series%speed(i) - (w_inf + (w0 - w_inf)*exp(-k*t)))/w_inf)
      end associate
    end do
    print '(a, es10.2, a, f6.2, a)', 'viscous_normal ride: largest relative speed error ', worst, ' over ', &
      ride%series%time(ride%series%n), ' s'
    ! rtol 1e-10 per step (ride_options_t) over ~1e2..1e3 steps: below 1e-7 of w_inf
    call check(worst <= 1e-7_wp, 'viscous_normal ride: w(t) in closed form')
    ! starting below w_inf it approaches it from below
    call check(ride%series%speed(ride%series%n) < w_inf, 'below the terminal speed')
  end subroutine check_viscous_ride

  !> Building a rider again and again loses no memory (a sweep builds one per
  !> ride): gfortran 12 lost the friction laws' names and completed
  !> parameters of every build (a structure constructor's allocatable
  !> components as an argument, base_spec's list grown in an array
  !> constructor; ~0.5 KB a build) until they were set by component and grown
  !> by hand. Resident memory over 4000 builds after a warm-up grows by less
  !> than 512 KB (the leak: 1248 KB on main 61e0b5e). Linux (/proc/self/status); skipped where
  !> that cannot be read.
  subroutine check_no_memory_lost_per_build()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(tube_surface_t) :: tube
    type(status_t) :: st
    real(wp) :: q0(3)
    integer :: k, before, after
    tube = straight_tube(20.0_wp)
    p%u0 = 5
    do k = 1, 200
      call build_rider(p, tube, m, lay, q0, st)
    end do
    call check(st%ok(), 'rebuilt rider: '//st%text())
    before = resident_kb()
    do k = 1, 4000
      call build_rider(p, tube, m, lay, q0, st)
    end do
    after = resident_kb()
    if (before < 0 .or. after < 0) then
      print '(a)', 'note: /proc/self/status not readable: the memory check is skipped'
      return
    end if
    print '(a, i0, a)', 'resident memory over 4000 rider builds: ', after - before, ' KB more'
    call check(after - before < 512, 'no memory lost per rider build (resident memory grew by less than 512 KB)')
  end subroutine check_no_memory_lost_per_build

  !> VmRSS of this process in KB, or -1.
  integer function resident_kb() result(kb)
    character(len=256) :: line
    integer :: unit, io
    kb = -1
    open (newunit=unit, file='/proc/self/status', action='read', status='old', iostat=io)
    if (io /= 0) return
    do
      read (unit, '(a)', iostat=io) line
      if (io /= 0) exit
      if (line(1:6) == 'VmRSS:') then
        read (line(7:), *, iostat=io) kb
        if (io /= 0) kb = -1
        exit
      end if
    end do
    close (unit)
  end function resident_kb
end program test_rider_model
