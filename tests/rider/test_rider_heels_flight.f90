!> The heels' flight (issue 25 point 1, rider_heels_flight): on the crest of
!> inputs/parts/crest_slide.nml (5 m at 30 deg, 3 m at 2 deg, a convex bend
!> of 1 m into 15 deg), ridden dry, the heels lift off while the pelvis
!> presses; with may_fly they fly (0.13 s, 1.6 cm up) and land, and the
!> ride goes on (to the pelvis's own lift-off further down the bend).
!>
!>   same start   up to the lift-off the ride is the one without may_fly
!>                (same records, same numbers);
!>   switches     at the take-off and at each landing the positions are
!>                continuous (pelvis, back, heels), and at the take-off the
!>                velocities too (the heel's normal speed is zero there);
!>   gap          in flight the heel is never below the slide: its gap, from
!>                the recorded state re-evaluated by a separate open build,
!>                is >= 0 at every record and 0 at the landing;
!>   energy       E - E(0) - (work of friction and drag) + (energy the
!>                landings' impacts took) stays at its start value through
!>                the whole ride: no force is lost in flight, and each
!>                landing takes exactly what the kinetic energy drops there
!>                (the impulse J M^-1 J^T against the speeds' change M^-1 J^T L);
!>   landing      its drop height is v_n^2/(2 g); plastic and frictionless
!>                (landing_mu = 0), the impulse is normal and takes
!>                P_n v_n/2 (P_n = v_n/(n.K n), energy v_n^2/(2 n.K n)).
program test_rider_heels_flight
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use kinetostatics_mechanism, only: mechanism_workspace_t
  use rider_model, only: rider_params_t, CONTACT_HEELS, CONTACT_PELVIS, CONTACT_BACK, N_CONTACTS
  use rider_ride, only: ride_options_t, ride_result_t, rider_ode_t, prepare_ride, simulate_ride, RIDE_LIFT_OFF
  use rider_flight, only: contact_gap, build_state, N_FULL
  use kinetostatics_impact, only: impact_law_t
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: crest_slide, ride_stay_and_fly
  implicit none (type, external)

  integer, parameter :: heels_open = 2   ! the build with the heels' contact open (rider_ride)

  class(surface_t), allocatable :: crest
  type(status_t) :: st
  type(rider_params_t) :: p
  type(ride_options_t) :: options
  type(ride_result_t) :: stay, fly
  real(wp) :: g

  call crest_slide(crest, st)
  call check(st%ok(), 'the crest slide: '//st%text())
  p%drag = .false.
  g = norm2(p%gravity)
  call ride_stay_and_fly(p, crest, 'crest', options, stay, fly)
  print '(a,i0,a,es12.4,a,es12.4,a,es12.4,a,i0)', 'flights ', fly%flights%flights, ' airtime ', &
    fly%flights%airtime, ' longest ', fly%flights%longest, ' highest ', fly%flights%highest, &
    ' landings ', fly%flights%landings
  call check(fly%flights%flights >= 1 .and. fly%flights%landings >= 1 .and. fly%flights%airtime > 0, &
             'the heels flew and landed')
  call check(fly%ending /= RIDE_LIFT_OFF .or. fly%lifted_contact /= CONTACT_HEELS, &
             'the heels'' lift-off no longer ends the ride')
  call check_same_start()
  call check_switches()
  call check_gap_and_energy()
  call check_landings()
  call check_frictionless()
  call finish_tests('test_rider_heels_flight')

contains

  !> Up to the lift-off the two rides agree record for record, to the
  !> integration's error: with may_fly the state also carries the hips'
  !> holds' work integrals (zero until a flight), which change the
  !> integrator's error norm and so its steps, not the motion.
  subroutine check_same_start()
    integer :: n
    logical :: same
    real(wp) :: de, dn
    n = stay%series%n - 1   ! the lift-off's own record is located by a root: its time differs
    same = fly%series%n > n
    de = 0
    dn = 0
    if (same) then
      same = all(fly%series%time(1:n) == stay%series%time(1:n)) .and. all(fly%series%airborne(1:n) == 0)
      de = maxval(abs(fly%series%energy(1:n) - stay%series%energy(1:n)))
      dn = maxval(abs(fly%series%contact(CONTACT_HEELS)%normal_force(1:n) - &
                      stay%series%contact(CONTACT_HEELS)%normal_force(1:n)))
    end if
    print '(a,es10.3,a,es10.3,a)', 'same start: energy off by ', de, ' J, heels'' normal force by ', dn, ' N'
    ! two integrations with different steps differ by their global errors:
    ! ~1e-8 of E ~ 7e3 J and of N ~ 300 N (rtol 1e-10 per step over ~1000
    ! steps); a change of the motion (a force added) would be > 1 J
    call check(same .and. de <= 1e-3_wp .and. dn <= 1e-3_wp, 'up to the lift-off the ride is the one without may_fly')
  end subroutine check_same_start

  !> At every switch (two records at one time): positions continuous, and
  !> at a take-off the velocities too.
  subroutine check_switches()
    integer :: n, k, take_offs, landings
    real(wp) :: dr, dv
    take_offs = 0
    landings = 0
    associate (s => fly%series)
      do n = 2, s%n
        if (s%time(n) /= s%time(n - 1) .or. s%airborne(n) == s%airborne(n - 1)) cycle
        dr = 0
        dv = 0
        do k = 1, N_CONTACTS
          if (k == CONTACT_HEELS) cycle
          dr = max(dr, norm2(s%contact(k)%position(:, n) - s%contact(k)%position(:, n - 1)))
          dv = max(dv, norm2(s%contact(k)%velocity(:, n) - s%contact(k)%velocity(:, n - 1)))
        end do
        ! the heels' contact frame: the heel itself while on, its foot point in flight (gap 0 at a switch)
        dr = max(dr, norm2(s%contact(CONTACT_HEELS)%position(:, n) - s%contact(CONTACT_HEELS)%position(:, n - 1)))
        dr = max(dr, abs(s%phi_legs(n) - s%phi_legs(n - 1)), abs(s%phi_trunk(n) - s%phi_trunk(n - 1)))
        if (iand(s%airborne(n), not(s%airborne(n - 1))) /= 0) then
          take_offs = take_offs + 1
          dv = max(dv, norm2(s%contact(CONTACT_HEELS)%velocity(:, n) - s%contact(CONTACT_HEELS)%velocity(:, n - 1)))
          ! the closure's tolerance (1e-10 m) bounds what the new build's closure may differ
          call check(dr <= 1e-9_wp .and. dv <= 1e-8_wp, 'take-off: positions and velocities continuous')
          call check(abs(s%energy(n) - s%energy(n - 1)) <= 1e-8_wp*abs(s%kinetic(n)), 'take-off: energy continuous')
        else
          landings = landings + 1
          call check(dr <= 1e-9_wp, 'landing: positions continuous')
        end if
      end do
    end associate
    call check(take_offs >= fly%flights%flights, 'a take-off record pair per flight')
    print '(a,i0,a,i0)', 'take-offs ', take_offs, ' closing landings ', landings
  end subroutine check_switches

  !> The gap in flight from a separate open build, and the energy balance.
  subroutine check_gap_and_energy()
    type(rider_ode_t), target :: sys
    type(ride_options_t) :: o
    type(mechanism_workspace_t) :: work
    real(wp), allocatable :: y0(:), y(:)
    real(wp) :: gap, lowest, balance, balance0, lost, worst
    integer :: n, k, landing
    o = options
    call prepare_ride(p, crest, o, sys, y0, st)
    call check(st%ok(), 'the open build: '//st%text())
    if (.not. st%ok()) return
    lowest = huge(1.0_wp)
    associate (s => fly%series, m => sys%fly%builds(heels_open), lay => sys%layout)
      call m%prepare_workspace(work)
      allocate (y(2*m%f + m%n_laws))
      do n = 1, s%n
        if (s%airborne(n) /= heels_open) cycle
        ! the closure from the recorded dependents
        do k = 1, N_CONTACTS
          work%scalars(lay%u(k))%q = s%contact(k)%u(n)
          work%scalars(lay%v(k))%q = s%contact(k)%v(n)
        end do
        work%scalars(lay%tilt)%q = s%phi_trunk(n)
        work%warm = .false.
        work%converged = .false.
        call build_state(m, lay, s%state(:, n), y)
        call m%set_positions(work, y(1:m%f), st)
        if (.not. st%ok()) exit
        gap = contact_gap(work, lay, CONTACT_HEELS)
        lowest = min(lowest, gap)
      end do
      call check(st%ok(), 'the flight states re-evaluated: '//st%text())
      ! in flight the gap is >= 0 up to the landing root's location (the
      ! closure's and the root's tolerances, 1e-10 m)
      call check(lowest >= -1e-9_wp, 'in flight the heel stays above the slide (lowest gap '// &
                 trim(format_real(lowest))//' m)')
      ! energy: E - W_friction - W_drag + the landings' losses so far
      landing = 0
      lost = 0
      ! the laws' work: friction, drag and the hips' hold in flight (rider_hip_hold)
      balance0 = s%energy(1) - sum(s%state(2*N_FULL + 1:, 1))
      worst = 0
      do n = 1, s%n
        if (n > 1 .and. landing < fly%flights%landings) then
          if (s%time(n) == s%time(n - 1) .and. s%airborne(n - 1) /= 0 .and. &
              s%time(n) == fly%flights%landing(landing + 1)%time) then
            landing = landing + 1
            lost = lost + fly%flights%landing(landing)%energy_lost
            ! the impact takes what the kinetic energy drops
            call check_close(s%kinetic(n - 1) - s%kinetic(n), fly%flights%landing(landing)%energy_lost, &
                             1e-8_wp, 1e-9_wp, 'landing: the impact takes the kinetic energy''s drop')
          end if
        end if
        balance = s%energy(n) - sum(s%state(2*N_FULL + 1:, n)) + lost
        worst = max(worst, abs(balance - balance0))
      end do
      ! the balance drifts with the integration's error alone: 1.2e-5 J on the
      ! ride without may_fly up to its lift-off (E ~ 7e3 J, rtol 1e-10 per
      ! step), ~1e-4 J with the hips' stiff hold in flight (4 Hz); a force
      ! lost in flight (the legs' weight, the pelvis's friction) would be
      ! ~ N v t ~ 100 J over the 0.13 s
      call check(worst <= 3e-4_wp, 'energy balance through the flights: off by '//trim(format_real(worst))//' J')
      call check(landing == fly%flights%landings, 'every landing found among the records')
    end associate
  end subroutine check_gap_and_energy

  !> The landings' numbers.
  subroutine check_landings()
    integer :: k
    do k = 1, fly%flights%landings
      associate (l => fly%flights%landing(k))
        call check(l%normal_speed > 0, 'landing: approaching')
        call check_close(l%drop_height, l%normal_speed**2/(2*g), 1e-14_wp, 0.0_wp, 'landing: drop height v^2/(2 g)')
        call check(l%impulse >= l%normal_impulse*(1 - 1e-12_wp) .and. l%normal_impulse > 0, 'landing: impulse')
        print '(a,i0,a,f8.4,a,f8.4,a,es12.4,a,es12.4,a,es12.4,a,l1)', 'landing ', k, ' t ', l%time, ' s ', &
          l%arc_length, ' vn ', l%normal_speed, ' impulse ', l%impulse, ' drop ', l%drop_height, ' closed ', l%closed
      end associate
    end do
  end subroutine check_landings

  !> A plastic, frictionless landing: normal impulse, energy P_n v_n/2.
  subroutine check_frictionless()
    type(ride_options_t) :: o
    type(ride_result_t) :: r
    o = options
    o%landing = impact_law_t(restitution=0, mu=0)
    call simulate_ride(p, crest, o, r, st)
    call check(st%ok() .and. r%flights%landings >= 1, 'frictionless: the heels land')
    if (r%flights%landings < 1) return
    associate (l => r%flights%landing(1))
      call check_close(l%impulse, l%normal_impulse, 1e-12_wp, 0.0_wp, 'frictionless: the impulse is normal')
      call check_close(l%energy_lost, l%normal_impulse*l%normal_speed/2, 1e-10_wp, 0.0_wp, &
                       'frictionless plastic: the energy taken is P_n v_n/2')
      call check(l%closed, 'plastic: the heels stay on')
    end associate
  end subroutine check_frictionless

  function format_real(x) result(text)
    real(wp), intent(in) :: x
    character(len=24) :: text
    write (text, '(es12.4)') x
  end function format_real
end program test_rider_heels_flight
