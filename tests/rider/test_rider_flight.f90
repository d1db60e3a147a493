!> The whole rider's flight (issue 25 points 1 and 4, rider_flight): on the
!> jump of inputs/parts/jump_slide.nml (5 m at 35 deg, 2 m at 2 deg, a lip
!> of 1 m into 20 deg), ridden dry, the heels, then the pelvis and the back
!> lift off: the whole rider flies, lands (heels, pelvis, back) and the ride
!> goes on to the end of the slide.
!>
!>   projectile  in the whole flight nothing but gravity acts on the rider
!>               as a whole where the slide below the pelvis is straight
!>               (the hips' hold is internal, the open contacts press
!>               nothing, and the pelvis's attitude to the slide below is a
!>               pure couple there; over the lip's bend it turns with the
!>               slide: not a free flight, docs/rider.md "Flight"), so its
!>               centre of mass, re-evaluated from each record of the flight
!>               with the pelvis over the straight fall, lies on
!>               r0 + v0 t + g t^2/2 from the first such record (position
!>               1e-7 m, velocity 1e-6 m/s: the integration's rtol 1e-10 on
!>               coordinates of ~10 m over a few hundred steps, and the
!>               closure's 1e-10 m; found ~1e-12). The time to the landing
!>               against the projectile's: the time at which the parabola
!>               falls to the centre of mass's height at the landing (1e-8
!>               s), and the landing speed |v0 + g T|;
!>   energy      E - (work of friction, drag and the hips' hold) + (energy
!>               the landings took) stays at its start value through the
!>               ride (the balance's drift 1e-4 J of E ~ 7e3 J);
!>   switches    at every take-off and landing the contact points' positions
!>               are continuous (1e-9 m: the closure's tolerance), at a
!>               take-off the kinetic energy too;
!>   without     may_fly off: the heels' lift-off ends the ride as before.
program test_rider_flight
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use geometry_slide_elements, only: slide_element_t
  use kinetostatics_mechanism, only: mechanism_workspace_t
  use rider_model, only: rider_params_t, CONTACT_PELVIS, CONTACT_BACK, N_CONTACTS
  use rider_ride, only: ride_options_t, ride_result_t, rider_ode_t, prepare_ride, RIDE_END_OF_SLIDE
  use rider_flight, only: centre_of_mass, build_state, N_FULL
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: element_slide, ride_stay_and_fly
  implicit none (type, external)

  integer, parameter :: all_open = 7
  !> m: the pelvis's foot point past the lip (the joint at 7 m, its
  !> transition 1 m): the slide below is straight from here
  real(wp), parameter :: straight_from = 8.8_wp
  class(surface_t), allocatable :: jump
  type(status_t) :: st
  type(rider_params_t) :: p
  type(ride_options_t) :: options
  type(ride_result_t) :: stay, fly
  real(wp) :: g(3)

  call element_slide([slide_element_t(kind='straight', length=5.0_wp, slope_deg=35.0_wp), &
                      slide_element_t(kind='straight', length=2.0_wp, slope_deg=2.0_wp), &
                      slide_element_t(kind='straight', length=6.0_wp, slope_deg=20.0_wp), &
                      slide_element_t(kind='runout', length=6.0_wp, slope_deg=1.0_wp)], jump, st)
  call check(st%ok(), 'the jump slide: '//st%text())
  p%drag = .false.
  g = p%gravity
  call ride_stay_and_fly(p, jump, 'jump', options, stay, fly)
  print '(a,i0,a,es12.4,a,i0,a,es12.4,a,i0)', 'flights ', fly%flights%flights, ' airtime ', fly%flights%airtime, &
    ' whole ', fly%flights%whole_flights, ' whole airtime ', fly%flights%whole_airtime, ' landings ', &
    fly%flights%landings
  call check(fly%ending == RIDE_END_OF_SLIDE, 'the ride goes on to the end of the slide')
  call check(fly%flights%whole_flights == 1 .and. fly%flights%whole_airtime > 0.1_wp, 'the whole rider flew')
  call check(fly%flights%landings >= 3, 'heels, pelvis and back landed')
  if (fly%flights%landings >= 3) call check(any(fly%flights%landing%contact == CONTACT_PELVIS) .and. &
    any(fly%flights%landing%contact == CONTACT_BACK), 'the pelvis and the back land too')
  call check_projectile()
  call check_energy()
  call check_switches()
  call finish_tests('test_rider_flight')

contains

  !> The centre of mass in the whole flight against the projectile, from
  !> its first record with the pelvis over the straight fall.
  subroutine check_projectile()
    type(rider_ode_t), target :: sys
    type(mechanism_workspace_t) :: work
    real(wp), allocatable :: y0(:), y(:)
    real(wp) :: com(3), velocity(3), tau, worst_r, worst_v, r0(3), v0(3), t0, t_end, z_end, v_end(3), a, b, c, &
      airtime
    integer :: n, k, records
    logical :: started
    call prepare_ride(p, jump, options, sys, y0, st)
    call check(st%ok(), 'the flight build: '//st%text())
    if (.not. st%ok()) return
    worst_r = 0
    worst_v = 0
    records = 0
    started = .false.
    t_end = 0
    associate (s => fly%series, m => sys%fly%builds(all_open), lay => sys%layout)
      call m%prepare_workspace(work)
      allocate (y(2*m%f + m%n_laws))
      do n = 1, s%n
        if (s%airborne(n) /= all_open .or. s%arc_length(n) < straight_from) cycle
        ! the closure from the recorded dependents
        do k = 1, N_CONTACTS
          work%scalars(lay%u(k))%q = s%contact(k)%u(n)
          work%scalars(lay%v(k))%q = s%contact(k)%v(n)
        end do
        work%warm = .false.
        work%converged = .false.
        call build_state(m, lay, s%state(:, n), y)
        call m%set_positions(work, y(1:m%f), st)
        if (.not. st%ok()) exit
        call m%set_velocities(work, y(m%f + 1:2*m%f))
        call centre_of_mass(work, lay, com, velocity)
        if (.not. started) then
          started = .true.
          r0 = com
          v0 = velocity
          t0 = s%time(n)
        end if
        tau = s%time(n) - t0
        worst_r = max(worst_r, norm2(com - (r0 + v0*tau + g*tau**2/2)))
        worst_v = max(worst_v, norm2(velocity - (v0 + g*tau)))
        records = records + 1
        if (s%time(n) >= t_end) then
          t_end = s%time(n)
          z_end = com(3)
          v_end = velocity
        end if
      end do
    end associate
    call check(st%ok(), 'the flight''s records re-evaluated: '//st%text())
    print '(a,i0,a,es10.3,a,es10.3)', 'whole flight over the straight: ', records, &
      ' records, centre of mass off the parabola by ', worst_r, ' m, its velocity by ', worst_v
    call check(records > 10, 'the whole flight has records over the straight')
    if (records <= 10) return
    call check(worst_r <= 1e-7_wp, 'the centre of mass flies on the parabola')
    call check(worst_v <= 1e-6_wp, 'its velocity is v0 + g t')
    ! the last record of the flight is the landing's: the projectile falls
    ! to z_end at T (the later root of z0 + vz0 T - |g| T^2/2 = z_end)
    a = -norm2(g)/2
    b = v0(3)
    c = r0(3) - z_end
    airtime = (-b - sqrt(b**2 - 4*a*c))/(2*a)
    call check_close(t_end - t0, airtime, 0.0_wp, 1e-8_wp, &
                     'the flight''s time to the landing is the projectile''s to the landing height')
    call check_close(t_end, fly%flights%whole_take_off_time + fly%flights%whole_airtime, 0.0_wp, 1e-12_wp, &
                     'the landing is the last flight record')
    call check_close(norm2(v_end), norm2(v0 + g*airtime), 1e-7_wp, 0.0_wp, &
                     'the landing speed is the projectile''s |v0 + g T|')
  end subroutine check_projectile

  !> E - (the laws' work) + (the landings' losses) through the ride.
  subroutine check_energy()
    real(wp) :: balance, balance0, lost, worst
    integer :: n, k
    logical :: after_switch
    worst = 0
    associate (s => fly%series)
      balance0 = s%energy(1) - sum(s%state(2*N_FULL + 1:, 1))
      do n = 1, s%n
        ! a landing's loss counts from the record that starts the stretch after it
        after_switch = .false.
        if (n > 1) after_switch = s%time(n - 1) == s%time(n)
        lost = 0
        do k = 1, fly%flights%landings
          associate (l => fly%flights%landing(k))
            if (l%time < s%time(n) .or. (l%time == s%time(n) .and. after_switch)) lost = lost + l%energy_lost
          end associate
        end do
        balance = s%energy(n) - sum(s%state(2*N_FULL + 1:, n)) + lost
        worst = max(worst, abs(balance - balance0))
      end do
    end associate
    print '(a,es10.3,a)', 'energy balance off by ', worst, ' J'
    ! the integration's drift (rtol 1e-10 per step of E ~ 7e3 J over ~2000
    ! steps and the hold's stiff spring); a force lost in flight or an
    ! impact's energy miscounted would be > 1 J
    call check(worst <= 1e-3_wp, 'energy balance through the flights and landings')
  end subroutine check_energy

  !> Positions continuous at every switch, at a take-off the kinetic energy.
  subroutine check_switches()
    integer :: n, k, switches
    real(wp) :: dr
    switches = 0
    associate (s => fly%series)
      do n = 2, s%n
        if (s%time(n) /= s%time(n - 1) .or. s%airborne(n) == s%airborne(n - 1)) cycle
        switches = switches + 1
        dr = 0
        do k = 1, N_CONTACTS
          dr = max(dr, norm2(s%contact(k)%position(:, n) - s%contact(k)%position(:, n - 1)))
        end do
        dr = max(dr, abs(s%phi_legs(n) - s%phi_legs(n - 1)), abs(s%phi_trunk(n) - s%phi_trunk(n - 1)))
        call check(dr <= 1e-9_wp, 'switch: positions continuous')
        if (iand(s%airborne(n), not(s%airborne(n - 1))) /= 0) &
          call check(abs(s%kinetic(n) - s%kinetic(n - 1)) <= 1e-8_wp*s%kinetic(n), &
                     'take-off: kinetic energy continuous')
      end do
    end associate
    print '(a,i0)', 'switches ', switches
    call check(switches >= 6, 'every take-off and landing a switch')
  end subroutine check_switches
end program test_rider_flight
