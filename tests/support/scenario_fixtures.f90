!> Set-ups several tests share: a number or a vector as input text, a
!> number in a message, the continuity of an element chain across its
!> joints, a point mass built from input text and started, a ball over a
!> floor built as a flight from input text, a contact system read from
!> input text, a flight driven to its end, a contact scenario's input run
!> as the scenario runs it (its &solver's options), the slides of the rider's
!> flight tests and their rides without and with may_fly, a random
!> impact at several contacts.
module scenario_fixtures
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_curve, only: curve_point_t
  use geometry_surface, only: surface_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: section_part_description_t
  use geometry_description, only: geometry_description_t, build_geometry
  use geometry_slide_elements, only: element_chain_curve_t
  use numerics_ode, only: ode_integrator_t, ODE_ADAMS
  use numerics_event_driver, only: driver_options_t, driver_result_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t, build_flight, carrying_contact
  use contact_closing, only: drive_flight, flight_after_closed
  use contact_bodies, only: build_bodies, start_carriers
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use scenarios_point_mass, only: build_point_mass
  use rider_model, only: rider_params_t, CONTACT_HEELS
  use rider_ride, only: ride_options_t, ride_result_t, simulate_ride, RIDE_LIFT_OFF
  use testing, only: check
  implicit none (type, external)
  private
  public :: number, vector_text, real_text, joint_jumps, start_point_mass, ball_over_floor, read_flight, fly, &
    run_flight, read_system, read_closed_flight, run_contact_input, run_contact_text, crest_slide, element_slide, &
    ride_stay_and_fly, random_impact

  character(len=*), parameter :: nl = new_line('a')

contains

  !> A random impact at m contacts (the law tests of resolve_impacts), from
  !> the random_number sequence: W = A A^T + I/10 (A's entries in [-0.5,
  !> 0.5), 3m x 3m: symmetric positive definite), unit normals of random
  !> directions, velocities before in [-1, 1)^3 less 0.2 to 1.2 along the
  !> normal (mostly approaching).
  subroutine random_impact(m, w, normals, v)
    integer, intent(in) :: m
    real(wp), allocatable, intent(out) :: w(:, :), normals(:, :), v(:, :)
    real(wp) :: a(3*m, 3*m), x(3)
    integer :: i
    allocate (normals(3, m), v(3, m))
    call random_number(a)
    w = matmul(a - 0.5_wp, transpose(a - 0.5_wp))
    do i = 1, 3*m
      w(i, i) = w(i, i) + 0.1_wp
    end do
    do i = 1, m
      call random_number(x)
      normals(:, i) = (x - 0.5_wp)/norm2(x - 0.5_wp)
      call random_number(x)
      v(:, i) = 2*x - 1 - normals(:, i)*(0.2_wp + x(1))
    end do
  end subroutine random_impact

  !> x as input text, all 17 digits (es24.17).
  function number(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=30) :: buffer
    write (buffer, '(es24.17)') x
    text = trim(adjustl(buffer))
  end function number

  !> A 3-vector as input text (number's digits), e.g. a &body position.
  function vector_text(v) result(text)
    real(wp), intent(in) :: v(3)
    character(len=:), allocatable :: text
    text = number(v(1))//', '//number(v(2))//', '//number(v(3))
  end function vector_text

  !> x in short (es10.3), for messages.
  function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(es10.3)') x
    text = trim(adjustl(buf))
  end function real_text

  !> The largest relative jump of position, unit tangent and curvature vector
  !> (the last relative to `curvature`, 1/m) between sigma - h and sigma + h
  !> (h = 1e-11 m: the functions move by ~1e-11 of their size over it, far
  !> below 1e-9), over the joints `at`.
  subroutine joint_jumps(chain, at, curvature, jump)
    type(element_chain_curve_t), intent(in) :: chain
    real(wp), intent(in) :: at(:), curvature
    real(wp), intent(out) :: jump(3)
    real(wp), parameter :: h = 1e-11_wp
    real(wp) :: r(3, 2), t(3, 2), k(3, 2), scale
    type(curve_point_t) :: p
    type(status_t) :: st
    integer :: j, side
    jump = 0
    do j = 1, size(at)
      do side = 1, 2
        call chain%evaluate(at(j) + merge(-h, h, side == 1), 2, p, st)
        r(:, side) = p%d(:, 0)
        t(:, side) = p%d(:, 1)/norm2(p%d(:, 1))
        k(:, side) = (p%d(:, 2) - dot_product(p%d(:, 2), t(:, side))*t(:, side))/norm2(p%d(:, 1))**2
      end do
      scale = max(norm2(r(:, 1)), 1.0_wp)
      jump(1) = max(jump(1), norm2(r(:, 2) - r(:, 1))/scale)
      jump(2) = max(jump(2), norm2(t(:, 2) - t(:, 1)))
      jump(3) = max(jump(3), norm2(k(:, 2) - k(:, 1))/curvature)
    end do
  end subroutine joint_jumps

  !> The point mass of the input `text` (a point_mass scenario), built and
  !> its integration started at t = 0 (checked under `name`): its start y0
  !> and state there. `model` must be a target of the caller's (the
  !> integrator keeps it); ok: built and started.
  subroutine start_point_mass(text, name, model, integrator, y0, state, ok)
    character(len=*), intent(in) :: text, name
    type(point_mass_t), intent(inout), target :: model
    type(ode_integrator_t), intent(inout) :: integrator
    real(wp), allocatable, intent(out) :: y0(:)
    type(point_mass_state_t), intent(out) :: state
    logical, intent(out) :: ok
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(status_t) :: st
    call input_from_text('<test>', text, input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    call check(st%ok(), name//': built: '//st%text())
    ok = st%ok()
    if (.not. ok) return
    call model%state(y0, state, st)
    if (st%ok()) call integrator%start(model, 0.0_wp, y0, solver%options, st)
    call check(st%ok(), name//': started: '//st%text())
    ok = st%ok()
  end subroutine start_point_mass

  !> A contact scenario: a ball (radius 0.1 m, 0.2 kg) over a plane floor,
  !> an open contact between them, solved to rtol = atol = 1e-12 for
  !> `duration` s with records every 0.01 s; `body` and `contact` are the
  !> rest of their groups, `extra` more groups.
  function ball_over_floor(duration, body, contact, extra) result(text)
    character(len=*), intent(in) :: duration, body, contact, extra
    character(len=:), allocatable :: text
    text = '&run scenario = ''contact'' /'//nl// &
           '&solver rtol = 1e-12, atol = 1e-12, duration = '//duration//', output_step = 0.01 /'//nl// &
           '&shape name = ''floor'', kind = ''plane'' /'//nl// &
           '&shape name = ''ball'', kind = ''sphere'', radius = 0.1 /'//nl// &
           '&body name = ''ball'', mass = 0.2, '//body//' /'//nl// &
           '&contact name = ''on_floor'', shape_1 = ''floor'', body_2 = ''ball'', shape_2 = ''ball'', '// &
           'start = ''open'''//contact//' /'//nl//extra
  end function ball_over_floor

  !> The flight of the contact scenario in `text` (named `label` in
  !> messages), its start (q0, qd0) and the system read.
  subroutine read_flight(text, label, flight, q0, qd0, st, system)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(out) :: st
    type(contact_system_t), intent(out), optional :: system
    type(contact_system_t) :: read
    character(len=8), allocatable :: units(:)
    call read_system(text, label, read, st)
    call build_flight(read, flight, q0, qd0, units, st)
    if (present(system)) system = read
  end subroutine read_flight

  !> The contact system of the contact scenario in `text` (named `label`),
  !> its &solver read and checked too, as the scenario does.
  subroutine read_system(text, label, system, st)
    character(len=*), intent(in) :: text, label
    type(contact_system_t), intent(out) :: system
    type(status_t), intent(out) :: st
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    call input_from_text(label, text, input, st)
    call read_solver_config(input, solver, st)
    call read_contact_config(input, system, st)
  end subroutine read_system

  !> The contact scenario of `input` run to its &solver's duration with
  !> its options (with Adams the contact scenario's convergence coefficient, records
  !> every output_step, room for 400 at the start): all bodies flying from
  !> the start (build_flight), or its closed contacts carrying their bodies
  !> (contact_bodies build_bodies), driven by drive_flight; open: each
  !> contact's open (1) or closed (0) at each record.
  subroutine run_contact_input(input, flight, result, st, open)
    type(input_text_t), intent(in) :: input
    type(flight_ode_t), intent(out), target :: flight
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: st
    integer, allocatable, intent(out), optional :: open(:, :)
    type(solver_config_t) :: solver
    type(contact_system_t) :: system
    type(driver_options_t) :: options
    real(wp), allocatable :: q0(:), qd0(:)
    integer, allocatable :: opened(:, :)
    character(len=8), allocatable :: units(:)
    call read_solver_config(input, solver, st)
    if (st%ok()) call read_contact_config(input, system, st)
    if (.not. st%ok()) return
    if (carrying_contact(system) == 0) then
      call build_flight(system, flight, q0, qd0, units, st)
    else
      call build_bodies(system, start_carriers(system), flight, q0, qd0, units, st, 0, .false.)
    end if
    if (.not. st%ok()) return
    options%ode = solver%options
    ! as scenarios_contact: Adams' corrector to the contact scenario's coefficient, BDF's CVODE's own
    if (solver%options%method == ODE_ADAMS) options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call flight%start_series(400)
    call drive_flight(flight, flight%initial_state(q0, qd0), options, result, st, opened)
    if (present(open)) call move_alloc(opened, open)
  end subroutine run_contact_input

  !> run_contact_input of the contact scenario in `text` (named `label` in
  !> its messages).
  subroutine run_contact_text(text, label, flight, result, st, open)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out), target :: flight
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: st
    integer, allocatable, intent(out), optional :: open(:, :)
    type(input_text_t) :: input
    call input_from_text(label, text, input, st)
    if (st%ok()) call run_contact_input(input, flight, result, st, open)
  end subroutine run_contact_text

  !> The flight of the contact scenario in `text` (named `label`) that starts
  !> closed: the model of its whole system, closed, and the flight from its
  !> lift-off (contact_closing's flight_after_closed), with its start.
  subroutine read_closed_flight(text, label, flight, q0, qd0, st, system)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(out) :: st
    type(contact_system_t), intent(out), optional :: system
    type(contact_system_t) :: read
    type(contact_model_t) :: model
    character(len=8), allocatable :: units(:)
    call read_system(text, label, read, st)
    call build_contact_model(read, model, st)
    call flight_after_closed(read, model, flight, q0, qd0, units, st)
    if (present(system)) system = read
  end subroutine read_closed_flight

  !> Drives `flight` from (q0, qd0) for `duration` s at rtol = atol =
  !> `tolerance` (the contact scenario's convergence coefficient), records
  !> every 0.01 s (room for `records` at the start): the driver's result and
  !> each contact's open (1) or closed (0) at each record.
  subroutine fly(flight, q0, qd0, tolerance, duration, records, result, st, open)
    type(flight_ode_t), intent(inout), target :: flight
    real(wp), intent(in) :: q0(:), qd0(:), tolerance, duration
    integer, intent(in) :: records
    type(driver_result_t), intent(out) :: result
    type(status_t), intent(out) :: st
    integer, allocatable, intent(out) :: open(:, :)
    type(driver_options_t) :: options
    options%ode%rtol = tolerance
    options%ode%atol = tolerance
    options%ode%convergence_coefficient = contact_convergence_coefficient
    options%t_end = duration
    options%output_step = 0.01_wp
    options%progress_seconds = 0
    call flight%start_series(records)
    call drive_flight(flight, flight%initial_state(q0, qd0), options, result, st, open)
  end subroutine fly

  !> The flight of the contact scenario in `text` (named `label` in the
  !> checks) built and flown for `duration` s at 1e-12 (fly): the driver's
  !> outcome (0 when it was not built), and with `in_flight` the first
  !> contact's open (1) or closed (0) at each record.
  subroutine run_flight(text, label, flight, duration, outcome, in_flight)
    character(len=*), intent(in) :: text, label
    type(flight_ode_t), intent(out), target :: flight
    real(wp), intent(in) :: duration
    integer, intent(out) :: outcome
    integer, allocatable, intent(out), optional :: in_flight(:)
    integer, allocatable :: open(:, :)
    real(wp), allocatable :: q0(:), qd0(:)
    type(status_t) :: st
    type(driver_result_t) :: result
    outcome = 0
    call read_flight(text, label, flight, q0, qd0, st)
    call check(st%ok(), label//': built from the input: '//st%text())
    if (.not. st%ok()) return
    call fly(flight, q0, qd0, 1e-12_wp, duration, 300, result, st, open)
    call check(st%ok(), label//': ran: '//st%text())
    outcome = result%outcome
    if (present(in_flight)) in_flight = open(1, :)
  end subroutine run_flight

  !> The crest of inputs/parts/crest_slide.nml, built in code: 5 m at 30
  !> deg, 3 m at 2 deg, a convex bend (transition 1 m) into 8 m at 15 deg,
  !> a run-out of 6 m at 1 deg (element_slide).
  subroutine crest_slide(crest, st)
    class(surface_t), allocatable, intent(out) :: crest
    type(status_t), intent(out) :: st
    call element_slide([slide_element_t(kind='straight', length=5.0_wp, slope_deg=30.0_wp), &
                        slide_element_t(kind='straight', length=3.0_wp, slope_deg=2.0_wp), &
                        slide_element_t(kind='straight', length=8.0_wp, slope_deg=15.0_wp), &
                        slide_element_t(kind='runout', length=6.0_wp, slope_deg=1.0_wp)], crest, st)
  end subroutine crest_slide

  !> The rider's flight tests' slides: the exact chain of `elements` from
  !> (0, 0, 10) with transitions of 1 m, a tube of radius 0.5 m.
  subroutine element_slide(elements, slide, st)
    type(slide_element_t), intent(in) :: elements(:)
    class(surface_t), allocatable, intent(out) :: slide
    type(status_t), intent(out) :: st
    type(geometry_description_t) :: d
    d%kind = 'slide'
    d%slide%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%slide%elements%transition_length = 1
    d%slide%elements%exact = .true.
    d%slide%elements%elements = elements
    d%slide%section%parts = [section_part_description_t(kind='circle', radius=0.5_wp)]
    call build_geometry(d, slide, st)
  end subroutine element_slide

  !> The ride of `p` down `slide` (`name` in the checks) without may_fly,
  !> which the heels' lift-off must end (stay), and with may_fly, which must
  !> run (fly); `options` comes back with may_fly on.
  subroutine ride_stay_and_fly(p, slide, name, options, stay, fly)
    type(rider_params_t), intent(in) :: p
    class(surface_t), intent(in) :: slide
    character(len=*), intent(in) :: name
    type(ride_options_t), intent(inout) :: options
    type(ride_result_t), intent(out) :: stay, fly
    type(status_t) :: st
    options%progress_seconds = 0
    options%may_fly = .false.
    call simulate_ride(p, slide, options, stay, st)
    call check(st%ok() .and. stay%ending == RIDE_LIFT_OFF .and. stay%lifted_contact == CONTACT_HEELS, &
               'without may_fly the heels'' lift-off ends the ride: '//stay%outcome)
    options%may_fly = .true.
    call simulate_ride(p, slide, options, fly, st)
    call check(st%ok(), 'with may_fly the ride runs: '//st%text())
    print '(a)', name//' with may_fly: '//fly%outcome
  end subroutine ride_stay_and_fly
end module scenario_fixtures
