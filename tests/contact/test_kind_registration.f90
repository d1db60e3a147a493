!> The one-place rule of the factories (docs/DESIGN.md, "How to add a surface
!> kind", "How to add a force law"): a surface kind and a friction law written
!> here, in test code, registered with one call each, are named by inputs
!> (namelist text) and run through the normal path, io's readers included,
!> with no change to the library:
!>   - a point mass slides down the test slope under the test drag F = -k w:
!>     w(t) = w_inf + (w0 - w_inf) exp(-k t/m), w_inf = m g sin(theta)/k;
!>   - a solid sphere (the `sphere` kind) slides down the test slope with the
!>     test drag at its contact: the slip s = v - R omega obeys
!>     s' = g sin(theta) - lambda s, lambda = k (1/m + R^2/I) = 7 k/(2 m), so
!>     from rest v(t) = g sin(theta) t - (k/m) s_inf (t - (1 - exp(-lambda t))/lambda),
!>     s_inf = g sin(theta)/lambda; the energy lost is the law's work;
!>   - a sled (a bar of mass m on two runners) slides straight down the test
!>     slope with the test drag at both contacts: w' = g sin(theta) - 2 k w/m,
!>     w(t) = w_inf + (w0 - w_inf) exp(-2 k t/m), w_inf = m g sin(theta)/(2 k);
!>   - the kinds' parameters are read, checked and refused by their declarations.
module throwaway_kinds
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_spec, only: spec_t, declare
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_surface_kind, only: surface_kind_t
  use kinetostatics_force_law, only: force_law_t, friction_law_t, force_law_kind_t, law_place_t
  implicit none (type, external)
  private
  public :: test_slope_t, test_drag_t, slope_kind, drag_kind

  !> r = [u cos(theta), v, -u sin(theta)]: a slope falling along u.
  type, extends(surface_t) :: test_slope_t
    real(wp) :: theta = 0   ! rad
  contains
    procedure :: evaluate => slope_evaluate
  end type test_slope_t

  !> F = -k w_t (N s/m), not scaled by N.
  type, extends(friction_law_t) :: test_drag_t
    real(wp) :: k = 0
  contains
    procedure :: slip_force => drag_slip_force
  end type test_drag_t

contains

  pure subroutine slope_evaluate(self, u, v, order, p, status)
    class(test_slope_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    status%code = 0
    p%order = order
    p%r = [u*cos(self%theta), v, -u*sin(self%theta)]
    if (order >= 1) then
      p%ru = [cos(self%theta), 0.0_wp, -sin(self%theta)]
      p%rv = [0.0_wp, 1.0_wp, 0.0_wp]
    end if
  end subroutine slope_evaluate

  function slope_kind() result(kind)
    type(surface_kind_t) :: kind
    kind%name = 'test_slope'
    kind%meaning = 'a slope of the test'
    kind%parameters = [declare('slope_deg', 'deg', 0.0_wp, 80.0_wp, 'slope')]
    kind%build => build_slope
  end function slope_kind

  subroutine build_slope(spec, surface, status)
    type(spec_t), intent(in) :: spec
    class(surface_t), allocatable, intent(out) :: surface
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    allocate (surface, source=test_slope_t(spec%value('slope_deg')*pi/180))
  end subroutine build_slope

  pure function drag_slip_force(self, slip, normal_force) result(force)
    class(test_drag_t), intent(in) :: self
    real(wp), intent(in) :: slip(3), normal_force
    real(wp) :: force(3)
    associate (unused => normal_force)   ! not scaled
    end associate
    force = -self%k*slip
  end function drag_slip_force

  function drag_kind() result(kind)
    type(force_law_kind_t) :: kind
    kind%name = 'test_linear_drag'
    kind%meaning = 'F = -k w_t'
    kind%parameters = [declare('drag_k', 'N s/m', 0.0_wp, 1e3_wp, 'k', open_low=.true.)]
    kind%build => build_drag
  end function drag_kind

  subroutine build_drag(spec, place, law, status)
    type(spec_t), intent(in) :: spec
    type(law_place_t), intent(in) :: place
    class(force_law_t), allocatable, intent(out) :: law
    type(status_t), intent(inout) :: status
    type(test_drag_t) :: drag
    associate (unused => status)
    end associate
    call drag%set_up_contact_law(place%name, place%contact, scaled=.false.)
    drag%k = spec%value('drag_k')
    allocate (law, source=drag)
  end subroutine build_drag
end module throwaway_kinds

program test_kind_registration
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use base_spec, only: spec_t
  use base_kind_registry, only: registry_locks
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME
  use geometry_surface_kind, only: surface_kind_t
  use geometry_surface_factory, only: register_surface_kind, surface_kinds, surface_kind_index
  use kinetostatics_force_law, only: force_law_kind_t
  use kinetostatics_force_law_factory, only: register_force_law, force_law_kinds, force_law_kind_index
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use contact_factory, only: shape_t, shape_from_spec
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use scenarios_point_mass, only: build_point_mass
  use geometry_surface, only: surface_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: build_sled, sled_description_t
  use io_surface_config, only: read_surface_config, surface_source_t
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use throwaway_kinds, only: test_slope_t, test_drag_t, slope_kind, drag_kind
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: theta_deg = 20, k = 0.7_wp
  type(status_t) :: st

  call register_surface_kind(slope_kind(), st)
  call register_force_law(drag_kind(), st)
  call check(st%ok(), 'the test kinds registered: '//st%text())
  call register_force_law(drag_kind(), st)
  call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), 'registered already') > 0, &
             'a kind registered twice is refused: '//st%text())
  call concurrent_registration()
  call point_mass_on_slope()
  call sphere_on_slope()
  call sled_on_slope()
  call refusals()
  call sphere_shape()
  call finish_tests('test_kind_registration')

contains

  !> Registrations and look-ups from 8 threads at once (the one critical
  !> section of base_kind_registry, shared by both registries): of 8
  !> registrations of one name exactly one is taken; the 8 distinct names
  !> all are, each once, in either registry, and look-ups meanwhile find a
  !> kind whole or not at all (its builder with its name, at its index).
  subroutine concurrent_registration()
    integer, parameter :: n = 8
    type(status_t) :: twin(n), own(n), own_law(n)
    type(surface_kind_t) :: kind
    type(surface_kind_t), allocatable :: kinds(:)
    type(force_law_kind_t) :: law
    type(force_law_kind_t), allocatable :: laws(:)
    logical :: whole(n)
    integer :: i, j
    call check(registry_locks(), 'the registry is built with its lock (base compiled with OpenMP)')
    !$omp parallel do num_threads(n) private(kind, kinds, law, laws, j) schedule(static, 1)
    do i = 1, n
      kind = slope_kind()
      kind%name = 'test_slope_twin'
      call register_surface_kind(kind, twin(i))
      kind%name = 'test_slope_'//achar(iachar('a') + i - 1)
      call register_surface_kind(kind, own(i))
      law = drag_kind()
      law%name = 'test_drag_'//achar(iachar('a') + i - 1)
      call register_force_law(law, own_law(i))
      kinds = surface_kinds()
      laws = force_law_kinds()
      whole(i) = force_law_kind_index(law%name) > 0
      do j = 1, size(kinds)
        whole(i) = whole(i) .and. associated(kinds(j)%build) .and. surface_kind_index(kinds(j)%name) == j
      end do
      do j = 1, size(laws)
        whole(i) = whole(i) .and. associated(laws(j)%build) .and. force_law_kind_index(laws(j)%name) == j
      end do
    end do
    !$omp end parallel do
    call check(count([(twin(i)%ok(), i=1, n)]) == 1, 'of 8 threads registering one name at once, one succeeds')
    call check(all([(own(i)%ok(), i=1, n)]), '8 threads registering 8 names at once: all registered')
    call check(all([(own_law(i)%ok(), i=1, n)]), '8 threads registering 8 force laws at once: all registered')
    laws = force_law_kinds()
    call check(all([(count([(laws(j)%name == 'test_drag_'//achar(iachar('a') + i - 1), j=1, size(laws))]) == 1, &
                     i=1, n)]), 'every force law registered once')
    kinds = surface_kinds()
    call check(count([(kinds(j)%name == 'test_slope_twin', j=1, size(kinds))]) == 1 .and. &
               all([(count([(kinds(j)%name == 'test_slope_'//achar(iachar('a') + i - 1), j=1, size(kinds))]) == 1, &
                     i=1, n)]), 'every name registered once')
    call check(all(whole), 'look-ups during the registrations saw whole kinds, each at its index')
  end subroutine concurrent_registration

  function point_mass_input(point_mass) result(text)
    character(len=*), intent(in) :: point_mass
    character(len=:), allocatable :: text
    text = '&run scenario = ''point_mass'' /'//nl// &
           '&solver rtol = 1e-11, atol = 1e-11, duration = 3.0, output_step = 0.5 /'//nl// &
           '&surface kind = ''test_slope'', slope_deg = 20 /'//nl// &
           '&point_mass '//point_mass//' /'//nl
  end function point_mass_input

  !> rtol 1e-11 over 3 s: the speed to 1e-9 relative.
  subroutine point_mass_on_slope()
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(point_mass_state_t) :: s
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: w_inf, theta
    call input_from_text('point mass', point_mass_input('mass = 1.5, du0 = 0.2, friction = ''test_linear_drag'', '// &
                         'drag_k = 0.7'), input, st)
    call build_point_mass(input, solver, model, y0, st)
    call check(st%ok(), 'point mass built from the input: '//st%text())
    if (.not. st%ok()) return
    select type (law => model%friction)
    type is (test_drag_t)
      call check_close(law%k, k, 0.0_wp, 0.0_wp, 'point mass: the test law with drag_k as given')
    class default
      call check(.false., 'point mass: the friction is the test law')
    end select
    select type (surface => model%surface)
    type is (test_slope_t)
    class default
      call check(.false., 'point mass: the surface is the test slope')
    end select
    options%ode = solver%options
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call model%start_series(10)
    call drive(model, y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'point mass ran: '//st%text())
    n_records: associate (n => model%series%n)
      call model%state([model%series%u(n), model%series%v(n), model%series%du(n), model%series%dv(n), 0.0_wp], &
                       s, st)
      theta = theta_deg*pi/180
      w_inf = model%mass*standard_gravity*sin(theta)/k
      call check_close(s%speed, w_inf + (0.2_wp - w_inf)*exp(-k*model%series%time(n)/model%mass), 1e-9_wp, 0.0_wp, &
                       'point mass: speed under the test drag at 3 s (m/s)')
    end associate n_records
  end subroutine point_mass_on_slope

  !> rtol 1e-11 over 1 s: v to 1e-8 relative; the energy balance to 1e-9 of the kinetic energy.
  subroutine sphere_on_slope()
    character(len=*), parameter :: text = '&run scenario = ''contact'' /'//nl// &
      '&solver rtol = 1e-11, atol = 1e-11, duration = 1.0, output_step = 0.05 /'//nl// &
      '&contact_model gravity = 0, 0, -9.81 /'//nl// &
      '&shape name = ''slope'', kind = ''test_slope'', slope_deg = 20 /'//nl// &
      '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
      '&body name = ''ball'', mass = 2, solid_of = ''ball'', angles_deg = -90, 0, 0, '// &
      'position = 0.0342020143325669, 0, 0.0939692620785908 /'//nl// &
      '&contact name = ''slides'', shape_1 = ''slope'', body_2 = ''ball'', shape_2 = ''ball'', '// &
      'friction = ''test_linear_drag'', drag_k = 3.0 /'//nl
    real(wp), parameter :: mass = 2, drag = 3, g = 9.81_wp
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(contact_system_t) :: system
    type(contact_model_t), target :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: lambda, s_inf, t, v_exact, theta, worst, balance, scale
    real(wp), allocatable :: e(:)
    integer :: i
    call input_from_text('sphere on the test slope', text, input, st)
    call read_solver_config(input, solver, st)
    call read_contact_config(input, system, st)
    call check(st%ok(), 'contact input read: '//st%text())
    call build_contact_model(system, model, st)
    call check(st%ok(), 'contact model built: '//st%text())
    if (.not. st%ok()) return
    select type (law => model%ode%mechanism%laws(model%links(1)%law)%law)
    type is (test_drag_t)
    class default
      call check(.false., 'contact: the friction is the test law')
    end select
    options%ode = solver%options
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call model%ode%start_series(40)
    call drive(model%ode, model%y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'sphere ran: '//st%text())
    theta = theta_deg*pi/180
    lambda = 3.5_wp*drag/mass
    s_inf = g*sin(theta)/lambda
    worst = 0
    associate (s => model%ode%series)
      do i = 1, s%n
        t = s%time(i)
        v_exact = g*sin(theta)*t - drag/mass*s_inf*(t - (1 - exp(-lambda*t))/lambda)
        worst = max(worst, abs(norm2(s%body_v(:, s%nb, i)) - v_exact))
      end do
      e = s%kinetic(:s%n) + s%potential(:s%n)
      scale = maxval(s%kinetic(:s%n))
      balance = maxval(abs(e - e(1) - s%law_work(1, :s%n)))
      call check(s%n > 10, 'sphere: records')
      call check(s%law_work(1, s%n) < -1e-3_wp*scale, 'sphere: the test law did work')
    end associate
    call check(worst <= 1e-8_wp*g*sin(theta), 'sphere: centre speed = the closed form under the test drag')
    call check(balance <= 1e-9_wp*scale, 'sphere: E(t) - E(0) = work of the test law')
  end subroutine sphere_on_slope

  !> rtol 1e-11 over 2 s: the speed to 1e-9 relative (as the point mass).
  subroutine sled_on_slope()
    character(len=*), parameter :: text = '&run scenario = ''sled'' /'//nl// &
      '&solver rtol = 1e-11, atol = 1e-11, duration = 2.0, output_step = 0.5 /'//nl// &
      '&surface kind = ''test_slope'', slope_deg = 20 /'//nl// &
      '&sled mass = 10, friction = ''test_linear_drag'', drag_k = 0.7, u0 = 0.5, du0 = 0.2 /'//nl
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(sled_description_t) :: config
    class(surface_t), allocatable :: surface
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: source
    type(mechanism_ode_t), target :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp) :: w_inf, theta
    integer :: k_law
    call input_from_text('sled on the test slope', text, input, st)
    call read_solver_config(input, solver, st)
    call read_surface_config(input, surface_description, st, source)
    call build_surface(surface_description, surface, st)
    call read_sled_config(input, config, st)
    call check(st%ok(), 'sled input read: '//st%text())
    call build_sled(config%params, surface, config%q0, model%mechanism, st)
    call check(st%ok(), 'sled built: '//st%text())
    if (.not. st%ok()) return
    call check(model%mechanism%n_laws == 2, 'sled: the test law at both contacts')
    do k_law = 1, model%mechanism%n_laws
      select type (law => model%mechanism%laws(k_law)%law)
      type is (test_drag_t)
        call check_close(law%k, k, 0.0_wp, 0.0_wp, 'sled: the test law with drag_k as given')
      class default
        call check(.false., 'sled: the friction is the test law')
      end select
    end do
    options%ode = solver%options
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call model%start_series(10)
    call drive(model, model%initial_state(config%q0, config%qd0), options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'sled ran: '//st%text())
    theta = theta_deg*pi/180
    w_inf = config%params%mass*standard_gravity*sin(theta)/(2*k)
    associate (s => model%series)
      call check_close(s%qd(1, s%n), w_inf + (0.2_wp - w_inf)*exp(-2*k*s%time(s%n)/config%params%mass), 1e-9_wp, &
                       0.0_wp, 'sled: speed under the test drag at both contacts at 2 s (m/s)')
    end associate
  end subroutine sled_on_slope

  !> The test kinds' parameters are read and refused by their declarations.
  subroutine refusals()
    call refused('mass = 1.5, friction = ''test_linear_drag''', &
                 'friction = ''test_linear_drag'' needs drag_k', 'a required parameter not given')
    call refused('mass = 1.5, friction = ''coulomb'', friction_coefficient = 0.2, drag_k = 1', &
                 'drag_k = 1 is not allowed: friction = ''coulomb'' does not use it', 'another kind''s parameter')
    call refused('mass = 1.5, friction = ''test_linear_drag'', drag_k = 0', 'drag_k = 0 is not allowed', &
                 'a parameter out of its declared range')
  end subroutine refusals

  subroutine refused(point_mass, expected, what)
    character(len=*), intent(in) :: point_mass, expected, what
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    call input_from_text('refused', point_mass_input(point_mass), input, st)
    call build_point_mass(input, solver, model, y0, st)
    call check(st%code == STATUS_INVALID_INPUT .and. index(st%text(), expected) > 0, &
               what//' is refused with "'//expected//'": '//st%text())
  end subroutine refused

  !> A shape from its spec, without io.
  subroutine sphere_shape()
    type(spec_t) :: spec
    type(shape_t) :: shape
    type(status_t) :: st
    spec%kind = 'sphere'
    call spec%set('radius', [0.25_wp])
    call shape_from_spec('ball', spec, shape, st)
    call check(st%ok() .and. shape%surface%describe() == 'sphere radius = 0.25 m', &
               'shape_from_spec: a sphere of radius 0.25 m: '//shape%surface%describe())
    spec%kind = 'spheroid'
    call shape_from_spec('ball', spec, shape, st)
    call check(index(st%text(), 'unknown surface kind ''spheroid''') > 0, 'an unknown kind is refused: '//st%text())
  end subroutine sphere_shape
end program test_kind_registration
