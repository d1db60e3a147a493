!> A force law defined outside kinetostatics, as the rider's water drag will
!> be: viscous friction at a contact that switches itself on when a surface
!> coordinate passes a mark (its own root function) and asks the driver to
!> restart the integrator.
module test_mechanism_events_laws
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_event_driver, only: EVENT_RESTART, EVENT_IGNORE
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_contact, only: contact_state_t
  use kinetostatics_force_law, only: contact_law_t
  implicit none (type, external)
  private
  public :: switched_viscous_t, new_switched_viscous

  type, extends(contact_law_t) :: switched_viscous_t
    real(wp) :: coefficient = 0   ! N s/m
    integer :: scalar = 0         ! the coordinate watched
    real(wp) :: mark = 0          ! on when it rises through this value, off when it falls back
    integer :: switches = 0
  contains
    procedure :: evaluate => switched_evaluate
    procedure :: root_count => switched_root_count
    procedure :: roots => switched_roots
    procedure :: handle_event => switched_handle_event
  end type switched_viscous_t

contains

  function new_switched_viscous(name, contact, coefficient, scalar, mark) result(law)
    character(len=*), intent(in) :: name
    integer, intent(in) :: contact, scalar
    real(wp), intent(in) :: coefficient, mark
    type(switched_viscous_t) :: law
    call law%set_up_contact_law(name, contact, scaled=.false.)
    law%coefficient = coefficient
    law%scalar = scalar
    law%mark = mark
    law%active = .false.
  end function new_switched_viscous

  pure subroutine switched_evaluate(self, t, frames, scalars, contacts, status)
    class(switched_viscous_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_f => frames, unused_s => scalars, unused_st => status)
    end associate
    call self%set_contact_force(contacts(self%contact), -self%coefficient*contacts(self%contact)%slip)
  end subroutine switched_evaluate

  integer function switched_root_count(self) result(n)
    class(switched_viscous_t), intent(in) :: self
    associate (unused => self)
    end associate
    n = 1
  end function switched_root_count

  pure subroutine switched_roots(self, t, frames, scalars, contacts, g)
    class(switched_viscous_t), intent(in) :: self
    real(wp), intent(in) :: t
    type(frame_state_t), intent(in) :: frames(:)
    type(scalar_state_t), intent(in) :: scalars(:)
    type(contact_state_t), intent(in) :: contacts(:)
    real(wp), intent(out) :: g(:)
    associate (unused_t => t, unused_f => frames, unused_c => contacts)
    end associate
    g(1) = scalars(self%scalar)%q - self%mark
  end subroutine switched_roots

  subroutine switched_handle_event(self, t, fired, action, status)
    class(switched_viscous_t), intent(inout) :: self
    real(wp), intent(in) :: t
    integer, intent(in) :: fired(:)
    integer, intent(out) :: action
    type(status_t), intent(inout) :: status
    associate (unused_t => t, unused_s => status)
    end associate
    action = EVENT_IGNORE
    if (fired(1) == 0) return
    self%active = fired(1) > 0
    self%switches = self%switches + 1
    action = EVENT_RESTART
  end subroutine switched_handle_event
end module test_mechanism_events_laws

!> The mechanism on the integration driver: events and their outcomes.
!> - end of the slide: the sled down the demo slide stops normally where the
!>   front contact reaches the end of the tube (u = u_max to 1e-9);
!> - lift-off: the sled over the top of a horizontal cylinder leaves it where
!>   the closed form of the rigid rotation about the axis says;
!> - a force law's own event: switched on at a mark, restart, closed forms of
!>   the motion, the switch time and the law's work;
!> - a pole in v (an edge where the parametrisation is singular) ends the run
!>   as failed (a side edge in v is a normal end: tests/cli/ride_ejection.sh);
!> - the runaway guard stops a body at rest under Adams with the BDF hint.
program test_mechanism_events
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_DOMAIN, STATUS_SOLVER
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t, elliptic_cylinder_t, ellipsoid_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_EVENT_STOP, &
    DRIVE_END_TIME, DRIVE_FAILED, RECORD_EVENT
  use numerics_ode, only: ODE_ADAMS
  use kinetostatics_mechanism_ode, only: mechanism_ode_t, STOP_END_OF_SURFACE, STOP_LIFT_OFF
  use kinetostatics_models, only: sled_params_t, build_sled, sled_description_t
  use io_input, only: input_text_t, load_input_file
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_surface_config, only: read_surface_config, surface_source_t
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use scenarios_mechanism, only: mechanism_driver_options
  use test_mechanism_events_laws, only: switched_viscous_t, new_switched_viscous
  implicit none (type, external)

  real(wp), parameter :: g = 9.80665_wp

  call end_of_slide()
  call lift_off()
  call law_event()
  call edge_in_v()
  call runaway_guard()
  call events_added_after_start()
  call root_values_reused()
  call finish_tests('test_mechanism_events')

contains

  subroutine quiet(options)
    type(driver_options_t), intent(inout) :: options
    options%progress_seconds = 0
  end subroutine quiet

  !> The sled of an input file in inputs/sled, ready to run from y0.
  subroutine load_sled(path, solver, surface, sys, y0, status)
    character(len=*), intent(in) :: path
    type(solver_config_t), intent(out) :: solver
    class(surface_t), allocatable, intent(out) :: surface
    type(mechanism_ode_t), intent(inout) :: sys
    real(wp), allocatable, intent(out) :: y0(:)
    type(status_t), intent(inout) :: status
    type(input_text_t) :: input
    type(sled_description_t) :: sled
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: source
    call load_input_file(path, input, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_surface_config(input, surface_description, status, source)
    if (status%ok()) call build_surface(surface_description, surface, status)
    if (status%ok()) call read_sled_config(input, sled, status)
    if (status%ok()) call build_sled(sled%params, surface, sled%q0, sys%mechanism, status)
    if (.not. status%ok()) return
    y0 = sys%initial_state(sled%q0, sled%qd0)
    call sys%check_start(y0, status)
  end subroutine load_sled

  !> The demo slide's sled run long enough to leave the tube.
  subroutine end_of_slide()
    type(solver_config_t) :: solver
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: u_min, u_max, v_min, v_max
    integer :: n
    call load_sled('inputs/sled/demo_slide.nml', solver, surface, sys, y0, st)
    call check(st%ok(), 'demo slide sled builds: '//st%text())
    if (.not. st%ok()) return
    solver%duration = 60
    options = mechanism_driver_options('sled', solver)
    call quiet(options)
    call sys%start_series(100)
    call drive(sys, y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_EVENT_STOP, 'demo slide: the run ends normally: '//st%text())
    call check(index(sys%outcome, 'end of slide') > 0 .and. index(sys%outcome, 'front') > 0, &
               'demo slide: outcome says end of slide at the front contact: '//sys%outcome)
    n = sys%series%n
    call surface%domain(u_min, u_max, v_min, v_max)
    associate (m => sys%mechanism)
      ! at the event, 1e-7 of the domain inside the edge; located to CVODE's
      ! root tolerance in time: ~1e-13 s x 7 m/s
      call check(sys%series%kind(n) == RECORD_EVENT .and. &
                 abs(sys%work%scalars(m%scalar_index('u2'))%q - (u_max - 1e-7_wp*(u_max - u_min))) <= 1e-9_wp, &
                 'demo slide: the front contact stops at u = u_max (less 1e-7 of the domain)')
      ! the stop as a code: the surface joint whose u is at the edge, not read from the words
      call check(sys%stop_kind == STOP_END_OF_SURFACE .and. sys%stop_contact == 0 .and. sys%stop_element > 0, &
                 'demo slide: stop code end of surface')
      if (sys%stop_element > 0) call check(m%elements(sys%stop_element)%e%name == 'front', &
                 'demo slide: the stop names the front joint: '//m%elements(max(sys%stop_element, 1))%e%name)
    end associate
    call check(sys%series%time(n) > 10 .and. sys%series%time(n) < 13, 'demo slide: the ride takes 10 to 13 s')
    print '(a, f8.4, a, i0, a, i0, a)', '  end of slide at t = ', sys%series%time(n), ' s, ', result%stats%steps, &
      ' steps (the closure used to fail here after 105501 steps)'
  end subroutine end_of_slide

  !> The sled over the top of a horizontal cylinder (radius 1, axis z,
  !> gravity -y): a rigid rotation about the axis, angle alpha of the centre
  !> of mass from the top, I_axis alpha'' = m g R' sin(alpha) (normal forces
  !> pass through the axis, R' the distance of the centre of mass from it);
  !> radial and tangential force balance give N_lead + N_trail =
  !> m (g cos(alpha) - R' alpha'^2)/cos(delta) and N_lead - N_trail =
  !> -m g sin(alpha) I_c/(I_axis sin(delta)), sin(delta) = L/(2 R): the
  !> leading (front) end lifts off where N_lead = 0.
  subroutine lift_off()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: cylinder
    type(mechanism_ode_t), target :: sys
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: delta, rc, i_axis, alpha0, lo, hi, mid, alpha_sim, n_front
    integer :: it, n
    cylinder = elliptic_cylinder_t(1.0_wp, 1.0_wp, st)
    p%gravity = [0.0_wp, -g, 0.0_wp]
    p%sigma = -1          ! z_D outward: the bar is outside
    delta = asin(p%length/2)
    rc = sqrt(1 - p%length**2/4)
    i_axis = p%inertia(2, 2) + p%mass*rc**2
    alpha0 = 0.05_wp
    ! rear (trailing) end at the centre's angle + delta in v; the bar along -r_v (phi = pi/2)
    call build_sled(p, cylinder, [0.0_wp, pi/2 - alpha0 + delta, pi/2], sys%mechanism, st)
    y0 = sys%initial_state([0.0_wp, pi/2 - alpha0 + delta, pi/2], [0.0_wp, 0.0_wp, 0.0_wp])
    call sys%check_start(y0, st)
    call check(st%ok(), 'sled on the cylinder starts: '//st%text())
    options%ode%rtol = 1e-11_wp
    options%ode%atol = 1e-11_wp
    options%t_end = 10
    options%output_step = 0.05_wp
    call quiet(options)
    call sys%start_series(100)
    call drive(sys, y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_EVENT_STOP .and. index(sys%outcome, 'lift-off') > 0 .and. &
               index(sys%outcome, 'front') > 0, 'cylinder: the front contact lifts off: '//sys%outcome//' '//st%text())
    n = sys%series%n
    alpha_sim = pi/2 - (sys%series%q(2, n) - delta)
    lo = alpha0
    hi = pi/2
    do it = 1, 200
      mid = (lo + hi)/2
      if (n_lead(p, alpha0, rc, delta, i_axis, mid) > 0) then
        lo = mid
      else
        hi = mid
      end if
    end do
    ! integration at rtol 1e-11 over ~1 s: the angle to ~1e-9
    call check_close(alpha_sim, lo, 1e-8_wp, 0.0_wp, 'cylinder: lift-off angle = closed form')
    n_front = sys%series%normal(2, n)
    ! the stop as a code: the contact with N = 0 (the second, the front's)
    call check(sys%stop_kind == STOP_LIFT_OFF .and. sys%stop_contact == 2, 'cylinder: stop code lift-off, contact 2')
    call check(abs(n_front) <= 1e-8_wp*p%mass*g .and. all(sys%series%normal(:, :n - 1) > 0), &
               'cylinder: N_front = 0 at the event, both contacts pressed before')
    call check(abs(sys%series%kinetic(n) + sys%series%potential(n) - sys%series%kinetic(1) - &
                   sys%series%potential(1)) <= 1e-9_wp*p%mass*g, 'cylinder: energy conserved (no friction)')
    print '(a, f12.9, a, f12.9, a, es9.2, a)', '  lift-off at alpha = ', alpha_sim, ' rad (closed form ', lo, &
      '), N_front ', n_front, ' N'
  end subroutine lift_off

  !> The leading end's normal force at angle alpha (see lift_off).
  real(wp) function n_lead(p, alpha0, rc, delta, i_axis, alpha)
    type(sled_params_t), intent(in) :: p
    real(wp), intent(in) :: alpha0, rc, delta, i_axis, alpha
    real(wp) :: rate2
    rate2 = 2*p%mass*g*rc*(cos(alpha0) - cos(alpha))/i_axis
    n_lead = 0.5_wp*(p%mass*(g*cos(alpha) - rc*rate2)/cos(delta) &
                     - p%mass*g*sin(alpha)*p%inertia(2, 2)/(i_axis*sin(delta)))
  end function n_lead

  !> Frictionless sled sliding straight down an incline (u'' = a = g sin(theta));
  !> at u = mark the test law switches viscous friction c on at the rear
  !> contact: u'' = a - (c/m) u' from there, in closed form.
  subroutine law_event()
    real(wp), parameter :: theta = 20*pi/180, c = 4, mark = 1
    type(sled_params_t) :: p
    class(surface_t), allocatable :: plane
    type(mechanism_ode_t), target :: sys
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: a, k, v_inf, t1, v1, tau, u_exact, v_exact, w_exact, t_event
    integer :: n, i
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(theta), 0.0_wp, -sin(theta)], [0.0_wp, 1.0_wp, 0.0_wp], st)
    call build_sled(p, plane, [0.2_wp, 0.0_wp, 0.0_wp], sys%mechanism, st, finish=.false.)
    call sys%mechanism%add_law(new_switched_viscous('switched', sys%mechanism%contact_index('rear'), c, &
                                                    sys%mechanism%scalar_index('u'), mark))
    call sys%mechanism%finalize(st)
    y0 = sys%initial_state([0.2_wp, 0.0_wp, 0.0_wp], [0.5_wp, 0.0_wp, 0.0_wp])
    call sys%check_start(y0, st)
    call check(st%ok(), 'incline with a switched law starts: '//st%text())
    options%ode%rtol = 1e-11_wp
    options%ode%atol = 1e-12_wp
    options%t_end = 2
    options%output_step = 0.1_wp
    call quiet(options)
    call sys%start_series(30)
    call drive(sys, y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME .and. result%restarts == 1, &
               'switched law: one event, one restart, run to the end: '//st%text())
    a = g*sin(theta)
    k = c/p%mass
    v_inf = a/k
    t1 = (-0.5_wp + sqrt(0.25_wp + 2*a*(mark - 0.2_wp)))/a
    v1 = 0.5_wp + a*t1
    t_event = -1
    do i = 1, sys%series%n
      if (sys%series%kind(i) == RECORD_EVENT) t_event = sys%series%time(i)
    end do
    ! CVODE locates roots to ~1e-14 s here
    call check_close(t_event, t1, 0.0_wp, 1e-10_wp, 'switched law: switched at the closed-form time')
    n = sys%series%n
    tau = sys%series%time(n) - t1
    u_exact = mark + v_inf*tau + (v1 - v_inf)*(1 - exp(-k*tau))/k
    v_exact = v_inf + (v1 - v_inf)*exp(-k*tau)
    w_exact = -c*(v_inf**2*tau + 2*v_inf*(v1 - v_inf)*(1 - exp(-k*tau))/k + (v1 - v_inf)**2*(1 - exp(-2*k*tau))/(2*k))
    ! rtol 1e-11 over ~300 steps
    call check_close(sys%series%q(1, n), u_exact, 1e-9_wp, 0.0_wp, 'switched law: u(t) in closed form')
    call check_close(sys%series%qd(1, n), v_exact, 1e-9_wp, 0.0_wp, 'switched law: u''(t) in closed form')
    call check_close(sys%series%law_work(1, n), w_exact, 1e-8_wp, 0.0_wp, 'switched law: its work in closed form')
    call check(all(sys%series%law_work(1, :n) == 0 .or. sys%series%time(:n) > t1), &
               'switched law: no work while off')
    call check_close(sys%series%kinetic(n) + sys%series%potential(n) - sys%series%kinetic(1) - &
                     sys%series%potential(1), sys%series%law_work(1, n), 1e-8_wp, 0.0_wp, &
                     'switched law: E(t) - E(0) = its work')
  end subroutine law_event

  !> Inside a unit sphere without gravity the sled, lying along a meridian,
  !> runs along it into the pole, the edge v = pi/2 of the ellipsoid's
  !> domain: a failure.
  subroutine edge_in_v()
    type(sled_params_t) :: p
    class(surface_t), allocatable :: sphere
    type(mechanism_ode_t), target :: sys
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    sphere = ellipsoid_t(1.0_wp, 1.0_wp, 1.0_wp, st)
    p%gravity = 0
    p%sigma = 1
    call build_sled(p, sphere, [0.3_wp, 0.8_wp, pi/2], sys%mechanism, st)
    y0 = sys%initial_state([0.3_wp, 0.8_wp, pi/2], [0.0_wp, 1.0_wp, 0.0_wp])
    call sys%check_start(y0, st)
    if (.not. st%ok()) then   ! the other side of the normal is the inside
      st = status_t()
      p%sigma = -1
      call build_sled(p, sphere, [0.3_wp, 0.8_wp, pi/2], sys%mechanism, st)
      y0 = sys%initial_state([0.3_wp, 0.8_wp, pi/2], [0.0_wp, 1.0_wp, 0.0_wp])
      call sys%check_start(y0, st)
    end if
    call check(st%ok(), 'sled inside a sphere starts: '//st%text())
    options%t_end = 5
    call quiet(options)
    call drive(sys, y0, options, result, st)
    call check(.not. st%ok() .and. st%code == STATUS_DOMAIN .and. result%outcome == DRIVE_FAILED .and. &
               index(st%text(), 'reached the pole v') > 0, 'an edge in v (a sphere''s pole) is a failure: '//st%text())
  end subroutine edge_in_v

  !> The bowl with Coulomb friction under Adams: the rear end comes to rest and
  !> the regularized friction makes the problem stiff; the scenarios' runaway
  !> guard stops it early and says to use BDF.
  subroutine runaway_guard()
    type(solver_config_t) :: solver
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    call load_sled('inputs/sled/bowl_friction.nml', solver, surface, sys, y0, st)
    call check(st%ok(), 'bowl with friction builds: '//st%text())
    if (.not. st%ok()) return
    solver%options%method = ODE_ADAMS
    options = mechanism_driver_options('sled', solver)
    call quiet(options)
    call drive(sys, y0, options, result, st)
    call check(.not. st%ok() .and. st%code == STATUS_SOLVER .and. index(st%text(), 'bdf') > 0 .and. &
               result%stats%steps < 100000, 'runaway guard: stops early with the BDF hint: '//st%text())
  end subroutine runaway_guard
  !> A user crossing added after initial_state, with the state size the same:
  !> initial_state again sizes the root values for the new count, and the
  !> crossing's value is y(index) - value.
  subroutine events_added_after_start()
    type(solver_config_t) :: solver
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    type(status_t) :: st
    real(wp), allocatable :: y0(:), g(:)
    integer :: f, ns, n_before
    call load_sled('inputs/sled/bowl.nml', solver, surface, sys, y0, st)
    call check(st%ok(), 'bowl sled builds: '//st%text())
    if (.not. st%ok()) return
    n_before = sys%root_count()
    f = sys%mechanism%f
    ns = sys%mechanism%ns
    sys%event_index = [1]
    sys%event_value = [y0(1) + 1]
    y0 = sys%initial_state(y0(1:f), y0(f + 1:f + ns))
    call check(sys%root_count() == n_before + 1 .and. size(sys%cache_g) == n_before + 1 .and. &
               size(sys%root_scale) == n_before + 1 .and. size(sys%rhs_g) == n_before + 1, &
               'a user crossing added after the start: the root arrays sized anew')
    allocate (g(sys%root_count()))
    call sys%roots(0.0_wp, y0, g)
    ! the same expression as root_values: exact
    call check(g(1) == y0(1) - sys%event_value(1), 'the added crossing''s root value is y(1) - value')
  end subroutine events_added_after_start

  !> The root functions take the values of the right-hand side at its (t, y)
  !> (CVODE asks there after a step's corrector) and evaluate nothing; at
  !> another state they evaluate the whole dynamics (the lift-off roots need
  !> N), which agrees with the stored values to the closure's tolerance (the
  !> sled's loops are solved from another warm start). In a run with records
  !> the evaluations at output times are those the records take again (the
  !> mechanism's dynamics returns them): an output costs one evaluation.
  subroutine root_values_reused()
    type(solver_config_t) :: solver
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys, run
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:), ydot(:), g_stored(:), g_fresh(:)
    integer :: evaluated
    call load_sled('inputs/sled/demo_slide.nml', solver, surface, sys, y0, st)
    call check(st%ok(), 'demo slide sled builds: '//st%text())
    if (.not. st%ok()) return
    allocate (ydot(size(y0)), g_stored(sys%root_count()), g_fresh(sys%root_count()))
    call sys%rhs(0.0_wp, y0, ydot, st)
    evaluated = sys%root_dynamics + sys%root_partial
    call sys%roots(0.0_wp, y0, g_stored)
    call check(st%ok() .and. sys%root_dynamics + sys%root_partial == evaluated .and. sys%root_cache_hits == 1, &
               'root values at the right-hand side''s (t, y): taken from it, nothing evaluated')
    ! a right-hand side 1 ms on: neither store holds (0, y0) any more
    call sys%rhs(1e-3_wp, y0 + 1e-3_wp*ydot, ydot, st)
    call sys%roots(0.0_wp, y0, g_fresh)
    call check(st%ok() .and. sys%root_dynamics == 1 .and. sys%root_cache_hits == 1, &
               'root values at another state: the dynamics evaluated')
    call check(all(abs(g_fresh - g_stored) <= 1e-9_wp*max(1.0_wp, maxval(abs(g_fresh)))), &
               'the stored root values = a fresh evaluation (closure tolerance)')

    call load_sled('inputs/sled/demo_slide.nml', solver, surface, run, y0, st)
    solver%duration = 1
    options = mechanism_driver_options('sled', solver)
    call quiet(options)
    call run%start_series(200)
    call drive(run, y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'demo slide sled, 1 s: '//st%text())
    ! every output but the last, where CVODE's step ends at the stop time and
    ! the right-hand side's values serve, is checked with an evaluation that
    ! its record takes again
    call check(run%root_dynamics_at_outputs >= result%outputs - 1 .and. &
               run%root_dynamics_at_outputs <= result%outputs .and. &
               run%work%dynamics_reused >= run%root_dynamics_at_outputs, &
               'an output costs one dynamics evaluation: the root check''s, reused by its record')
    print '(a, 6(i0, a))', '  sled 1 s: ', result%outputs, ' outputs, ', run%root_calls, ' root calls, ', &
      run%root_cache_hits, ' served, ', run%root_dynamics, ' dynamics (', run%root_dynamics_at_outputs, &
      ' at outputs), ', run%work%dynamics_reused, ' dynamics reused'
  end subroutine root_values_reused
end program test_mechanism_events
