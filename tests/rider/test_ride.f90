!> Whole rides down the demo slide (issue 9's acceptance):
!>  - no friction, no drag, no water (contacts two-sided, so the frictionless
!>    rider, which would lift off in the helix, rides the whole slide):
!>    mechanical energy conserved to 1e-8 relative at rtol 1e-10, closure
!>    residuals below 1e-10 all along;
!>  - friction and drag in the computed water: the loss of mechanical energy
!>    equals the friction work plus the drag work to 1e-8 relative, at every
!>    record;
!>  - entry and exit times of the contacts (drag on/off events) equal the
!>    roots found by bisection on the recorded states (re-integrated from the
!>    record before each event without root functions) to 1e-8 s;
!>  - the drag law's power, as the mechanism integrates it, equals F_D . w_D.
!> The rider's right-hand side without root functions (for the bisection).
module test_ride_plain
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_system_t
  use rider_ride, only: rider_ode_t
  implicit none (type, external)
  private
  public :: plain_rider_t

  type, extends(ode_system_t) :: plain_rider_t
    type(rider_ode_t) :: inner
  contains
    procedure :: rhs => plain_rhs
  end type plain_rider_t

contains

  subroutine plain_rhs(self, t, y, ydot, status)
    class(plain_rider_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    call self%inner%rhs(t, y, ydot, status)
  end subroutine plain_rhs
end module test_ride_plain

program test_ride
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use test_ride_plain, only: plain_rider_t
  use numerics_event_driver, only: RECORD_EVENT
  use io_input, only: input_text_t, load_input_file
  use water_run, only: water_description_t, water_result_t, compute_water
  use rider_model, only: rider_params_t, N_CONTACTS, contact_names
  use base_spec, only: spec_t
  use rider_ride, only: ride_options_t, ride_result_t, simulate_ride, rider_ode_t, prepare_ride, RIDE_LIFT_OFF, &
    RIDE_STALLED
  use geometry_slide_query, only: general_wall_position
  use rider_water_drag, only: in_water_roots, water_drag_t
  use scenarios_water, only: build_water
  use geometry_tube, only: tube_surface_t, new_straight_tube
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  type(water_description_t) :: description
  type(water_result_t), target :: water   ! the drag laws of prepare_ride's models point at its field
  type(input_text_t) :: input
  type(status_t) :: st

  call load_input_file('inputs/ride/demo_slide.nml', input, st)
  if (st%ok()) call build_water(input, description, st, stage=.true.)
  if (st%ok()) call compute_water(description, water, st)
  call check(st%ok(), 'the demo water: '//st%text())
  if (.not. st%ok()) call finish_tests('test_ride')

  call check_wall_position()
  call check_stops()
  call check_energy_conserved()
  call check_energy_balance_and_events()
  call finish_tests('test_ride')

contains

  !> On the demo slide (circular sections) the closed forms of the wall
  !> angle and distance equal the general ones (normal angle, quadrature).
  subroutine check_wall_position()
    real(wp) :: u, v, a1, d1, a2, d2
    type(status_t) :: st
    integer :: i
    do i = 1, 12
      u = 0.3_wp + 5.3_wp*i
      v = 1.5707963267948966_wp + 0.23_wp*(i - 6)
      call description%slide%wall_position(u, v, a1, d1, st)
      call general_wall_position(description%slide, u, v, a2, d2, st)
      ! rtol 1e-12: 5-point Gauss on a constant |r_v| is exact; the angle from two unit normals
      call check_close(a1, a2, 1e-12_wp, 1e-14_wp, 'wall angle: closed form = normal angle')
      call check_close(d1, d2, 1e-12_wp, 1e-14_wp, 'wall distance: closed form = quadrature')
    end do
  end subroutine check_wall_position

  !> The ride's other ends: frictionless with one-sided contacts the rider
  !> lifts off (a normal force reaches zero there, the message says which
  !> and where); on a straight tube flatter than the friction angle it
  !> slows down and stalls.
  subroutine check_stops()
    type(rider_params_t) :: p
    type(ride_options_t) :: opt
    type(ride_result_t) :: ride
    type(status_t) :: st
    type(tube_surface_t) :: flat
    integer :: n, k, lifted
    real(wp) :: smallest
    p%friction = spec_t('none')
    p%drag = .false.
    opt%output_step = 0.05_wp
    opt%progress_seconds = 0
    call simulate_ride(p, description%slide, opt, ride, st)
    n = ride%series%n
    call check(st%ok() .and. .not. ride%complete .and. index(ride%outcome, 'lift-off: the normal force of the ') == 1 &
               .and. index(ride%outcome, 'at arc length') > 0, 'frictionless: lift-off with where: '//ride%outcome)
    smallest = huge(1.0_wp)
    lifted = 0
    do k = 1, N_CONTACTS
      if (abs(ride%series%contact(k)%normal_force(n)) < smallest) lifted = k
      smallest = min(smallest, abs(ride%series%contact(k)%normal_force(n)))
    end do
    ! the root is located to the integrator's tolerance: N ~ 1e-7 of the weight
    call check(smallest < 1e-6_wp*p%body%mass*9.81_wp, 'lift-off: a normal force is zero at the stop')
    ! the ending as a code from the mechanism's event (not read back from the words)
    call check(ride%ending == RIDE_LIFT_OFF .and. ride%lifted_contact == lifted, &
               'lift-off: ending code and the contact whose normal force is zero at the stop')
    print '(a)', 'frictionless, one-sided: '//ride%outcome
    ! 2 degrees against mu = 0.0724 (4.1 degrees): the rider slows down to a stall
    flat = new_straight_tube(0.5_wp, 2*acos(-1.0_wp)/180, 30.0_wp, st)
    p = rider_params_t()
    p%drag = .false.
    p%u0 = 2
    p%speed0 = 1
    call simulate_ride(p, flat, opt, ride, st)
    call check(st%ok() .and. index(ride%outcome, 'the rider stalled or turned back') == 1, &
               'stall on a flat tube: '//ride%outcome)
    call check(ride%ending == RIDE_STALLED .and. ride%lifted_contact == 0, 'stall: ending code')
    n = ride%series%n
    ! the stall speed 0.05 m/s along u: |c_u| = 1 on the straight tube
    call check_close(ride%series%speed(n), opt%min_speed, 1e-6_wp, 0.0_wp, 'stalls at min_speed')
    print '(a)', 'flat tube: '//ride%outcome
  end subroutine check_stops

  subroutine check_energy_conserved()
    type(rider_params_t) :: p
    type(ride_options_t) :: opt
    type(ride_result_t) :: ride
    type(status_t) :: st
    real(wp) :: scale, drift
    integer :: n
    p%friction = spec_t('none')
    p%drag = .false.
    p%one_sided = .false.
    opt%output_step = 0.05_wp
    opt%progress_seconds = 0
    call simulate_ride(p, description%slide, opt, ride, st)
    call check(st%ok() .and. ride%complete, 'frictionless ride reaches the end: '//st%text()//' / '//ride%outcome)
    n = ride%series%n
    associate (s => ride%series)
      scale = max(maxval(s%kinetic(:n)), maxval(abs(s%potential(:n) - s%potential(1))))
      drift = maxval(abs(s%energy(:n) - s%energy(1)))/scale
      print '(a, es10.2, a, f6.2, a, i0, a)', 'frictionless: energy drift ', drift, ' relative over ', s%time(n), &
        ' s (', n, ' records)'
      ! rtol 1e-10 over ~1e4 steps: errors of 1e-10 per step add up to below 1e-8 relative
      call check(drift <= 1e-8_wp, 'frictionless: energy conserved to 1e-8 relative')
      call check(maxval(s%closure_residual(:n)) < 1e-10_wp, 'frictionless: closure residual below 1e-10 m')
      call check(all(s%friction_work(:n) == 0) .and. all(s%drag_work(:n) == 0), 'frictionless: no work of laws')
    end associate
  end subroutine check_energy_conserved

  subroutine check_energy_balance_and_events()
    type(rider_params_t) :: p
    type(ride_options_t) :: opt
    type(ride_result_t) :: ride
    type(status_t) :: st
    real(wp) :: scale, worst
    integer :: n, i, c, k, tested
    logical :: before(N_CONTACTS)
    opt%progress_seconds = 0
    ! rtol 1e-11: the works are states of the integration, their error grows
    ! like rtol sqrt(steps) relative (~1e-8 at the thesis's 1e-10 over 5e3 steps)
    opt%ode%rtol = 1e-11_wp
    opt%ode%atol = 1e-10_wp
    call simulate_ride(p, description%slide, opt, ride, st, water%field)
    call check(st%ok() .and. ride%complete, 'demo ride reaches the end: '//st%text()//' / '//ride%outcome)
    n = ride%series%n
    associate (s => ride%series)
      call check(ride%drag_switches > 10, 'contacts enter and leave the water')
      scale = max(maxval(abs(s%friction_work(:n) + s%drag_work(:n))), maxval(abs(s%energy(:n) - s%energy(1))))
      worst = maxval(abs(s%energy(:n) - s%energy(1) - s%friction_work(:n) - s%drag_work(:n)))/scale
      print '(a, es10.2, a, es10.3, a, es10.3, a)', 'friction and drag: energy balance ', worst, &
        ' relative (friction work ', s%friction_work(n), ' J, drag work ', s%drag_work(n), ' J)'
      ! the works are quadratures of the laws' power in the same integration (rtol 1e-11)
      call check(worst <= 1e-8_wp, 'loss of energy = friction work + drag work to 1e-8 relative')
      call check(maxval(s%closure_residual(:n)) < 1e-10_wp, 'closure residual below 1e-10 m')
      call check(any(s%drag_work(:n) /= 0), 'the drag does work')
      ! entry and exit times: the first six switches
      tested = 0
      do i = 2, n
        if (s%kind(i) /= RECORD_EVENT .or. tested >= 6) cycle
        do c = 1, N_CONTACTS
          if (s%contact(c)%in_water(i) /= s%contact(c)%in_water(i - 1)) then
            do k = 1, N_CONTACTS
              before(k) = s%contact(k)%in_water(i - 1) == 1
            end do
            call check_event_time(p, opt, s%time(i - 1), s%state(:, i - 1), before, c, s%time(i))
            tested = tested + 1
          end if
        end do
      end do
      call check(tested >= 6, 'six entries/exits checked')
    end associate
    call check_drag_power(p, opt, ride)
    call check_dynamics_reuse(p, opt, ride)
  end subroutine check_energy_balance_and_events

  !> The root of min(v - v_right(u), v_left(u) - v) of contact c after
  !> (t0, y0), by bisection on states integrated from the record (rtol
  !> 1e-12, no root functions), against the event time t_event.
  subroutine check_event_time(p, opt, t0, y0, in_water, c, t_event)
    type(rider_params_t), intent(in) :: p
    type(ride_options_t), intent(in) :: opt
    real(wp), intent(in) :: t0, y0(:), t_event
    logical, intent(in) :: in_water(:)
    integer, intent(in) :: c
    type(plain_rider_t), target :: plain
    type(status_t) :: st
    real(wp), allocatable :: y_start(:)
    real(wp) :: lo, hi, mid, g_lo, g_mid
    integer :: k, it
    character(len=64) :: label
    call prepare_ride(p, description%slide, opt, plain%inner, y_start, st, water%field)
    do k = 1, N_CONTACTS
      plain%inner%work%laws(plain%inner%layout%drag(k))%law%active = in_water(k)
    end do
    lo = t0
    hi = t_event + 1e-7_wp
    g_lo = g_at(plain, t0, y0, lo, c)
    ! the bracket: the sign at the record before, the other just after the event
    call check(sign(1.0_wp, g_lo) /= sign(1.0_wp, g_at(plain, t0, y0, hi, c)), 'bisection bracket for '//trim(contact_names(c)))
    do it = 1, 60
      mid = 0.5_wp*(lo + hi)
      g_mid = g_at(plain, t0, y0, mid, c)
      if (sign(1.0_wp, g_mid) == sign(1.0_wp, g_lo)) then
        lo = mid
      else
        hi = mid
      end if
      if (hi - lo < 1e-12_wp) exit
    end do
    write (label, '(a, f9.5, a)') trim(contact_names(c))//' at t = ', t_event, ' s'
    print '(a, es10.2, a)', 'event time '//trim(label)//': bisection differs by ', 0.5_wp*(lo + hi) - t_event, ' s'
    ! the run's root finding on trajectories accurate to ~1e-9 m crossing the edges at ~1 rad/s
    call check_close(0.5_wp*(lo + hi), t_event, 0.0_wp, 1e-8_wp, 'entry/exit time of the '//trim(label))

  end subroutine check_event_time

  !> min(v - v_right(u), v_left(u) - v) of contact c at time t, from (t0, y0).
  real(wp) function g_at(plain, t0, y0, t, c) result(g)
    type(plain_rider_t), intent(inout), target :: plain
    real(wp), intent(in) :: t0, y0(:), t
    integer, intent(in) :: c
    type(status_t) :: st
    type(ode_integrator_t) :: integrator
    type(ode_options_t) :: o
    real(wp) :: y(size(y0)), tr, gg(2)
    y = y0
    if (t > t0) then
      o%rtol = 1e-12_wp
      o%atol = 1e-12_wp
      o%max_step = 0.01_wp
      call integrator%start(plain, t0, y0, o, st)
      if (st%ok()) call integrator%set_stop_time(t, st)
      if (st%ok()) call integrator%advance(t, tr, y, st)
    end if
    call plain%inner%mechanism%set_positions(plain%inner%work, y(1:3), st)
    associate (work => plain%inner%work, lay => plain%inner%layout)
      call in_water_roots(water%field, work%scalars(lay%u(c))%q, work%scalars(lay%v(c))%q, gg)
    end associate
    g = minval(gg)
    if (.not. st%ok()) g = huge(1.0_wp)
  end function g_at

  !> At records with a contact in the water: the mechanism's power of that
  !> drag law equals F_D . w_D of the contact point.
  subroutine check_drag_power(p, opt, ride)
    type(rider_params_t), intent(in) :: p
    type(ride_options_t), intent(in) :: opt
    type(ride_result_t), intent(in) :: ride
    type(rider_ode_t) :: sys
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: residual, f(3), w(3)
    integer :: i, c, law, tested
    call prepare_ride(p, description%slide, opt, sys, y0, st, water%field)
    call check_water_shared(sys)
    tested = 0
    do i = 1, ride%series%n, 37
      associate (s => ride%series, m => sys%mechanism, work => sys%work)
        do c = 1, N_CONTACTS
          law = sys%layout%drag(c)
          work%laws(law)%law%active = s%contact(c)%in_water(i) == 1
        end do
        call m%evaluate(work, s%time(i), s%state(1:3, i), s%state(4:6, i), residual, st)
        do c = 1, N_CONTACTS
          law = sys%layout%drag(c)
          if (.not. work%laws(law)%law%active) cycle
          f = m%law_force(work, law)
          w = work%frames(sys%layout%contact_frame(c))%v
          ! rtol 1e-12: one dot product against the mechanism's sum over loaded frames
          call check_close(work%law_power(law), dot_product(f, w), 1e-12_wp, 1e-12_wp, &
                           'drag power = F.w_D at the '//trim(contact_names(c)))
          tested = tested + 1
        end do
      end associate
    end do
    call check(tested > 10, 'drag power checked at records in the water')
  end subroutine check_drag_power

  !> Every contact's drag law, in the model and in the integrator's
  !> workspace, points at the one water field given (no copies:
  !> rider_water_drag), and so does a copy of the model.
  subroutine check_water_shared(sys)
    type(rider_ode_t), intent(in) :: sys
    type(rider_ode_t) :: copy
    integer :: c, shared
    copy = sys
    shared = 0
    do c = 1, N_CONTACTS
      shared = shared + points_at_water(sys%mechanism%laws(sys%layout%drag(c))%law) + &
               points_at_water(sys%work%laws(sys%layout%drag(c))%law) + &
               points_at_water(copy%mechanism%laws(sys%layout%drag(c))%law)
    end do
    call check(shared == 3*N_CONTACTS, 'every drag law points at the water given (no copies)')
  end subroutine check_water_shared

  integer function points_at_water(law) result(n)
    class(*), intent(in) :: law
    n = 0
    select type (law)
    type is (water_drag_t)
      if (associated(law%water, water%field)) n = 1
    end select
  end function points_at_water

  !> The mechanism's dynamics at the state of its last evaluation is reused
  !> (a record at the state a root function just saw) with the same results,
  !> and recomputed when a law was switched or another state came between.
  subroutine check_dynamics_reuse(p, opt, ride)
    type(rider_params_t), intent(in) :: p
    type(ride_options_t), intent(in) :: opt
    type(ride_result_t), intent(in) :: ride
    type(rider_ode_t) :: sys
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: qdd(3), again(3), n1(N_CONTACTS), t
    integer :: i, c, law, reused
    call prepare_ride(p, description%slide, opt, sys, y0, st, water%field)
    associate (s => ride%series, m => sys%mechanism, work => sys%work)
      i = findloc(s%contact(1)%in_water(:s%n), 1, dim=1)   ! the pelvis in the water
      call check(i > 0, 'a record with the pelvis in the water')
      if (i == 0) return
      do c = 1, N_CONTACTS
        work%laws(sys%layout%drag(c))%law%active = s%contact(c)%in_water(i) == 1
      end do
      law = sys%layout%drag(1)
      t = s%time(i)
      call m%dynamics(work, t, s%state(1:3, i), s%state(4:6, i), qdd, st)
      n1 = work%normal
      reused = work%dynamics_reused
      call m%dynamics(work, t, s%state(1:3, i), s%state(4:6, i), again, st)
      call check(work%dynamics_reused == reused + 1 .and. all(again == qdd) .and. all(work%normal == n1), &
                 'dynamics at the same state reused, the same results')
      work%laws(law)%law%active = .false.
      call m%dynamics(work, t, s%state(1:3, i), s%state(4:6, i), again, st)
      call check(work%dynamics_reused == reused + 1 .and. any(again /= qdd), &
                 'the pelvis''s drag switched off: recomputed, other accelerations')
      work%laws(law)%law%active = .true.
      call m%dynamics(work, t, s%state(1:3, i + 1), s%state(4:6, i + 1), again, st)
      call m%dynamics(work, t, s%state(1:3, i), s%state(4:6, i), again, st)
      ! 1e-12: the closure solved again from another warm start (to 1e-13 m)
      call check(work%dynamics_reused == reused + 1 .and. maxval(abs(again - qdd)) <= 1e-12_wp*maxval(abs(qdd)), &
                 'another state between: recomputed, the same accelerations to 1e-12')
      call check(st%ok(), 'dynamics: '//st%text())
    end associate
  end subroutine check_dynamics_reuse
end program test_ride
