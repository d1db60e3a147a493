!> Mechanisms of bodies in point contact, built from a description: named
!> shapes (surfaces in their body's coordinates), bodies (mass, centre, inertia
!> or the homogeneous solid of a shape; start pose and twist) and contacts
!> ("body_1 shape_1 touches body_2 shape_2", friction, rolling, position or
!> velocity level). One generic builder; no mechanism is coded by hand.
!>
!> Every body other than the ground is carried by one contact, the first
!> closed one that names it body_2 (its relative chain, contact_pair); each
!> further closed contact of it is a closure loop (contact_loops); contacts are
!> built in the order given, so a contact's body_1 must be the ground or
!> carried by an earlier contact (where bodies fly, contact_bodies: a
!> contact waits for its body_1's carrier, and a flying body_1 is free
!> before it: contact_system build_order). Friction laws are any kind of the multibody
!> core's registry (kinetostatics_force_law_factory), built from the
!> contact's spec: viscous -mu M g w_t (the egg, METHOD-PART2 A.4.3, M the
!> mass of body_2, g = |gravity|), viscous -mu |N| w_t, Coulomb -mu |N|
!> w_t/|w_t| (regularized), ...; w_t is the tangential slip (3.87). Shapes
!> and bodies come from their specs too (contact_factory).
!> Rolling adds the no-slip constraint (contact_rolling) with the rates of
!> (u12, v12) dependent: the speeds are the three angle rates.
!>
!> Position level, open chain (the default where it applies: no rolling):
!> body_2 hangs from S1's contact frame through the turn about the normal and
!> the inverse of its own surface joint (contact_pair): exact contact, no
!> closure; N = -z_1D . f_1D, what body_2 (and all it carries) presses on
!> the contact frame, as at velocity level. Position level, loop (rolling,
!> or chosen): the five closure conditions (3.86), N = the cut force of g3
!> (the plane-point measurement along z_1D). The open chain starts from the
!> loop's closed configuration (the same contact points and phi). Velocity level (for the drift
!> comparison): body_2 is moved by contact_velocity_level from its contact
!> frame; (u1, v1, u2, v2, phi) and body_2's pose are integrated, the closure
!> measurements g1..g5 only watch the drift; N = -z_1D . f_1D. The start of a
!> velocity-level contact is the closed position-level configuration.
!>
!> Start: each body's pose places its contact chain (contact_pair: B moves
!> along the normal until it touches; `start_gap` says by how much, at every
!> level: scenarios_contact reports it and refuses moves beyond `body_size`), the loops
!> close, the branch is checked; the speeds are the least-squares solution of
!> the bodies' given twists, which must be consistent with the contacts (no
!> velocity into a surface, no slip where rolling) to 1e-9 of their size.
module contact_model
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use geometry_surface, only: surface_t
  use geometry_solid, only: solid_properties_t
  use numerics_linear_algebra, only: cholesky_factor, cholesky_solve
  use kinetostatics_surface_joint, only: new_surface_joint
  use kinetostatics_measurements, only: new_measurement, MEASURE_PLANE_POINT, MEASURE_PLANE_PLANE
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_force_law, only: force_law_t, law_place_t
  use kinetostatics_force_law_factory, only: force_law_from_spec
  use kinetostatics_mechanism, only: mechanism_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use contact_pair, only: contact_pair_t, add_contact_pair, add_open_contact_pair, place_contact_pair, &
    place_open_contact_pair, check_contact_branch, starts_in_other_chart, add_loop_contact_pair
  use contact_loops, only: loop_start_t, second_contacts, start_loops
  use contact_rolling, only: new_no_slip
  use contact_velocity_level, only: new_velocity_contact
  use contact_factory, only: body_from_spec, add_air_drag
  use contact_free_body, only: add_free_body, free_body_units
  use contact_system, only: shape_t, body_spec_t, contact_spec_t, contact_system_t, build_system_shapes, &
    check_names, open_chain, body_size, body_index, shape_index, build_order, flies_free, LEVEL_POSITION, &
    LEVEL_VELOCITY, CHAIN_AUTO, CHAIN_OPEN, CHAIN_LOOP
  implicit none (type, external)
  private
  public :: shape_t, body_spec_t, contact_spec_t, contact_system_t, contact_model_t, contact_link_t
  public :: build_contact_model, contact_convergence_coefficient, body_size, build_system_shapes, body_index, &
    check_placement
  public :: LEVEL_POSITION, LEVEL_VELOCITY, CHAIN_AUTO, CHAIN_OPEN, CHAIN_LOOP

  real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  !> m and rad: a start placement's move off its contact's normal, or turn
  !> (check_placement); rounding of a closure is ~1e-15 of the poses
  real(wp), parameter :: placement_limit = 1e-9_wp
  !> CVODE's nonlinear convergence coefficient for contact runs with Adams (its
  !> default 0.1). The corrector stops once its change is below this fraction of
  !> the error test; the rest of its error enters the differences CVODE
  !> chooses the order from and held the egg at P1 at orders 5-6. A tighter
  !> corrector costs iterations but lets the order rise: the egg's right-hand
  !> sides at P1, mean over mu and its 10 nearest floating-point neighbours,
  !> mu 0.3 31.3k -> 26.8k, mu 0.8 27.4k -> 24.8k (docs/contact.md,
  !> "Corrector"; bench/convergence_scan.sh).
  real(wp), parameter :: contact_convergence_coefficient = 0.03_wp

  !> What one contact became in the mechanism.
  type :: contact_link_t
    character(len=:), allocatable :: name
    integer :: level = LEVEL_POSITION
    logical :: rolling = .false.
    logical :: open = .false.                    ! position level by the open chain
    logical :: apart = .false.                   ! open (start_open): not built, its body flies or another carries it
    logical :: loop = .false.                    ! a second closed contact of its body: a closure loop (contact_loops)
    integer :: frame_a = 0, frame_b = 0, frame_1d = 0, frame_2d = 0   ! frame_2d: 0 in the open chain
    integer :: coordinates(4) = 0                ! scalars u1, v1, u2, v2
    integer :: gaps(5) = 0                       ! closure measurements g1..g5
    integer :: contact = 0                       ! index among the mechanism's contacts
    integer :: law = 0                           ! friction law (0: none)
    integer :: rolling_outputs(2) = 0            ! no-slip outputs (rolling, position level)
    type(contact_pair_t) :: pair                 ! position level
    real(wp) :: start_gap = 0                    ! m, B moved along the normal to touch at the start
    real(wp) :: start_normal(3) = 0              ! that normal (world)
  end type contact_link_t

  type :: contact_model_t
    type(mechanism_ode_t) :: ode
    character(len=32), allocatable :: body_names(:)   ! the ground first
    integer, allocatable :: body_frame(:)
    real(wp), allocatable :: body_mass(:)
    type(contact_link_t), allocatable :: links(:)
    real(wp), allocatable :: y0(:)
    character(len=8), allocatable :: q_units(:), beta_units(:)   ! of the coordinates and dependents
    ! bodies that fly (a description with contacts that start open: each
    ! body not carried by a closed contact is free, contact_free_body)
    integer, allocatable :: free(:, :)             ! 6 x bodies: a free body's scalars x, y, z, a1, a2, a3 (else 0)
    integer, allocatable :: rotation_element(:)    ! each free body's free rotation (else 0)
    integer, allocatable :: gap_monitors(:)        ! each contact's <name>.gap among the monitors (flights only)
    !> where the build failed because a closed contact does not press at the
    !> start: that contact (of the description), else 0
    integer :: not_pressing = 0
  end type contact_model_t

contains

  !> Builds the mechanism of `system` and its start y0 (model%y0), checked:
  !> every name known, every body carried once and in order, loops closed on
  !> the physical branch, contacts pressing, start velocities consistent.
  !> Shapes given by their descriptions are built first (contact_factory).
  !> flying (contact_bodies): the contacts that start open are not built,
  !> every body no closed contact carries is free (contact_free_body) and
  !> every contact's gap is a monitor (add_free_bodies).
  subroutine build_contact_model(system, model, status, flying)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(out) :: model
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: flying
    type(contact_system_t) :: shaped
    logical :: flies
    if (.not. status%ok()) return
    flies = .false.
    if (present(flying)) flies = flying
    call build_system_shapes(system, shaped, status)
    call build_shaped_model(shaped, model, status, flies)
  end subroutine build_contact_model

  !> build_contact_model of a system whose shapes are built.
  subroutine build_shaped_model(system, model, status, flies)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(out) :: model
    type(status_t), intent(inout) :: status
    logical, intent(in) :: flies
    type(contact_model_t) :: closed, tree
    type(contact_system_t) :: chains
    type(loop_start_t), allocatable :: loops(:)
    logical :: staged
    if (.not. status%ok()) return
    call check_names(system, status)
    if (.not. status%ok()) return
    ! a body's second closed contacts: loops on the mechanism of the others (contact_loops)
    chains = system
    chains%contacts%start_open = system%contacts%start_open .or. second_contacts(system)
    staged = any((chains%contacts%level == LEVEL_VELOCITY .or. open_chain(chains%contacts)) .and. &
                 .not. chains%contacts%start_open)
    if (.not. any(second_contacts(system))) then
      if (.not. staged) then
        call build(system, model, status, flies)
        return
      end if
      ! velocity level and open chains: start from the closed configuration of the loops
      call build(system, closed, status, flies, all_position=.true.)
      model%not_pressing = closed%not_pressing
      if (.not. status%ok()) return
      call build(system, model, status, flies, closed=closed)
      return
    end if
    if (staged) then
      call build(chains, closed, status, flies, all_position=.true.)
      model%not_pressing = closed%not_pressing
      call build(chains, tree, status, flies, closed=closed)
    else
      call build(chains, tree, status, flies)
    end if
    if (tree%not_pressing > 0) model%not_pressing = tree%not_pressing
    call start_loops(system, tree%ode%mechanism, tree%ode%work, tree%body_frame, loops, status)
    if (.not. status%ok()) return
    if (staged) then
      call build(system, model, status, flies, closed=closed, loops=loops)
    else
      call build(system, model, status, flies, loops=loops)
    end if
  end subroutine build_shaped_model


  !> One build. all_position: every contact at position level by the loop
  !> (the start of velocity-level contacts and open chains); closed: that
  !> model, whose closed configuration starts them.
  subroutine build(system, model, status, flies, all_position, closed, loops)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(out) :: model
    type(status_t), intent(inout) :: status
    logical, intent(in) :: flies
    logical, intent(in), optional :: all_position
    type(contact_model_t), intent(in), optional :: closed
    type(loop_start_t), intent(in), optional :: loops(:)   ! each contact's: a second closed contact's loop (used)
    integer :: nb, k, b1, b2, level, i
    integer, allocatable :: q(:), kinematic(:), carrier(:), extras(:), order(:)
    real(wp), allocatable :: mass(:)
    type(solid_properties_t), allocatable :: props(:)
    nb = size(system%bodies)
    allocate (model%body_names(nb + 1), model%body_frame(nb + 1), model%body_mass(nb + 1), carrier(nb))
    allocate (model%links(size(system%contacts)), q(0), kinematic(0), mass(nb), props(nb))
    allocate (model%q_units(0), model%beta_units(0), extras(0))
    model%body_names(1) = 'ground'
    model%body_frame = 0
    model%body_frame(1) = 1
    model%body_mass = 0
    carrier = 0
    call mass_properties(system, props, status)
    if (.not. status%ok()) return
    if (flies) allocate (model%free(6, nb), model%rotation_element(nb), model%gap_monitors(size(system%contacts)), &
                         source=0)
    order = build_order(system, flies)
    associate (m => model%ode%mechanism)
      do i = 1, size(order)
        k = order(i)
        associate (c => system%contacts(k), link => model%links(k))
          link%name = c%name
          link%apart = c%start_open
          if (c%start_open) cycle
          b1 = body_index(system, c%body_1)
          b2 = body_index(system, c%body_2)
          if (b1 > 0) then
            ! a flying body carrying another (contact_bodies): free, before the contact
            if (carrier(b1) == 0 .and. flies .and. flies_free(system, b1)) &
              call add_free(system, model, props, b1, carrier, q, status)
            if (.not. status%ok()) return
            if (carrier(b1) == 0) then
              call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': body_1 = '''//c%body_1// &
                ''' is not placed yet: list the contact that carries it (its body_2) before '''//c%name//'''')
              return
            end if
          end if
          if (carrier(b2) /= 0 .and. present(loops)) then
            if (loops(k)%used) then
              call add_loop_contact(m, c, link, model%body_frame(b1 + 1), model%body_frame(b2 + 1), &
                                    system%shapes(shape_index(system, c%shape_1))%surface, &
                                    system%shapes(shape_index(system, c%shape_2))%surface, loops(k), q, extras, model, &
                                    status)
              if (.not. status%ok()) return
              call add_friction(m, c, link, system%bodies(b2)%mass*norm2(system%gravity), status)
              if (.not. status%ok()) return
              cycle
            end if
          end if
          if (carrier(b2) /= 0) then
            call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': body_2 = '''//c%body_2// &
              ''' is already carried by contact '''//system%contacts(carrier(b2))%name//'''; each body is '// &
              'body_2 of exactly one contact (a second contact between placed bodies is not supported)')
            return
          end if
          carrier(b2) = k
          level = c%level
          if (present(all_position)) level = LEVEL_POSITION
          link%level = level
          link%rolling = c%rolling
          link%open = open_chain(c) .and. .not. present(all_position)
          link%frame_a = model%body_frame(b1 + 1)
          associate (s1 => system%shapes(shape_index(system, c%shape_1))%surface, &
                     s2 => system%shapes(shape_index(system, c%shape_2))%surface)
            if (level == LEVEL_POSITION) then
              call add_position_contact(m, c, link, s1, s2, q, status)
            else
              call add_velocity_contact(m, c, link, s1, s2, closed, k, q, kinematic, status)
            end if
            call add_units(model, level, c%rolling, link%open, s1, s2)
          end associate
          call add_monitors(m, link)
          if (.not. status%ok()) return
          model%body_names(b2 + 1) = c%body_2
          model%body_frame(b2 + 1) = link%frame_b
          model%body_mass(b2 + 1) = system%bodies(b2)%mass
          call m%add_element(new_mass_element(c%body_2, link%frame_b, system%bodies(b2)%mass, props(b2)%inertia, &
                                              props(b2)%centre, system%gravity, status))
          if (.not. status%ok()) return
          call add_air_drag(m, system%bodies(b2), system%air_density, system%wind, link%frame_b, props(b2)%centre, &
                            status)
          call add_friction(m, c, link, system%bodies(b2)%mass*norm2(system%gravity), status)
          if (.not. status%ok()) return
        end associate
      end do
      if (flies) then
        call add_free_bodies(system, model, props, carrier, q, status)
        if (.not. status%ok()) return
      end if
      do k = 1, nb
        if (carrier(k) == 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'body '''//system%bodies(k)%name//''' is not body_2 '// &
                          'of any contact: nothing carries it')
          return
        end if
      end do
      if (size(extras) > 0) then
        ! the loops' dependents of the carrying chains are no coordinates
        model%q_units = pack(model%q_units, [(.not. any(extras == q(k)), k = 1, size(q))])
        q = pack(q, [(.not. any(extras == q(k)), k = 1, size(q))])
      end if
      call m%set_coordinates(q)
      if (size(kinematic) > 0) call m%set_kinematic(kinematic)
      call m%finalize(status)
      if (.not. status%ok()) return
    end associate
    call start(system, model, carrier, status, closed, loops)
  end subroutine build

  !> A second closed contact of a carried body (frame_b): a closure loop
  !> (contact_pair add_loop_contact_pair) whose fifth dependent is the
  !> carrying chain's coordinate start%extra (contact_loops), added to
  !> `extras`; its units moved from the coordinates' to the dependents'
  !> after the loop's own four. N is the cut force of g3, as in a loop pair.
  subroutine add_loop_contact(m, c, link, frame_a, frame_b, s1, s2, start, q, extras, model, status)
    type(mechanism_t), intent(inout) :: m
    type(contact_spec_t), intent(in) :: c
    type(contact_link_t), intent(inout) :: link
    integer, intent(in) :: frame_a, frame_b
    class(surface_t), intent(in) :: s1, s2
    type(loop_start_t), intent(in) :: start
    integer, intent(in) :: q(:)   ! the coordinates so far (model%q_units theirs)
    integer, allocatable, intent(inout) :: extras(:)
    type(contact_model_t), intent(inout) :: model
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: u1, v1, u2, v2
    integer :: extra, j
    extra = m%scalar_index(start%extra)
    j = findloc(q, extra, dim=1)
    if (j == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': the coordinate '''//start%extra// &
                      ''' its loop would make dependent is not one of the carrying contact''s')
      return
    end if
    link%loop = .true.
    link%frame_a = frame_a
    call add_loop_contact_pair(m, c%name, frame_a, s1, c%side_1, frame_b, s2, c%side_2, extra, link%pair, status)
    if (.not. status%ok()) return
    link%frame_b = frame_b
    link%frame_1d = link%pair%frame_1d
    link%frame_2d = link%pair%frame_2d
    link%coordinates = [link%pair%u1, link%pair%v1, link%pair%u2, link%pair%v2]
    link%gaps = link%pair%gaps
    link%contact = m%add_contact(c%name, frame_a, frame_b, link%frame_1d, 1.0_wp, normal_measurement=link%gaps(3))
    call add_monitors(m, link)
    extras = [extras, extra]
    call s1%parameter_units(u1, v1)
    call s2%parameter_units(u2, v2)
    model%beta_units = [character(len=8) :: model%beta_units, u1, v1, u2, v2, model%q_units(j)]
  end subroutine add_loop_contact

  !> The bodies no closed contact carries, each free (add_free) at its
  !> given pose, in the order of the &body groups (but those a closed
  !> contact's body_1 needed first); then the gap of every contact as a
  !> monitor (<contact>.gap, m; the flight records its value,
  !> contact_flight): a description whose contacts may start open
  !> (contact_bodies).
  subroutine add_free_bodies(system, model, props, carrier, q, status)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(inout) :: model
    type(solid_properties_t), intent(in) :: props(:)
    integer, intent(inout) :: carrier(:)
    integer, allocatable, intent(inout) :: q(:)
    type(status_t), intent(inout) :: status
    integer :: b, c
    associate (m => model%ode%mechanism, nb => size(system%bodies))
      do b = 1, nb
        if (carrier(b) /= 0) cycle
        call add_free(system, model, props, b, carrier, q, status)
        if (.not. status%ok()) return
      end do
      do c = 1, size(system%contacts)
        call m%add_monitor(m%add_scalar(system%contacts(c)%name//'.gap'), 'm')
        model%gap_monitors(c) = size(m%monitors)
      end do
    end associate
  end subroutine add_free_bodies

  !> Body b free (contact_free_body, carrier -1) at its given pose, its
  !> coordinates after q.
  subroutine add_free(system, model, props, b, carrier, q, status)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(inout) :: model
    type(solid_properties_t), intent(in) :: props(:)
    integer, intent(in) :: b
    integer, intent(inout) :: carrier(:)
    integer, allocatable, intent(inout) :: q(:)
    type(status_t), intent(inout) :: status
    call add_free_body(model%ode%mechanism, system%bodies(b), props(b), system%gravity, system%air_density, &
                       system%wind, model%free(:, b), model%body_frame(b + 1), model%rotation_element(b), status)
    if (.not. status%ok()) return
    carrier(b) = -1
    model%body_names(b + 1) = system%bodies(b)%name
    model%body_mass(b + 1) = system%bodies(b)%mass
    q = [q, model%free(:, b)]
    model%q_units = [character(len=8) :: model%q_units, free_body_units]
  end subroutine add_free

  !> Units of the coordinates (and dependents) the contact added, in their order.
  subroutine add_units(model, level, rolling, open, s1, s2)
    type(contact_model_t), intent(inout) :: model
    integer, intent(in) :: level
    logical, intent(in) :: rolling, open
    class(surface_t), intent(in) :: s1, s2
    character(len=:), allocatable :: u1, v1, u2, v2
    call s1%parameter_units(u1, v1)
    call s2%parameter_units(u2, v2)
    if (open) then
      model%q_units = [character(len=8) :: model%q_units, u1, v1, 'rad', u2, v2]
    else if (level == LEVEL_POSITION) then
      model%q_units = [character(len=8) :: model%q_units, u1, v1, 'rad', 'rad', 'rad']
      model%beta_units = [character(len=8) :: model%beta_units, u1, v1, u2, v2, 'm']
    else if (rolling) then
      model%q_units = [character(len=8) :: model%q_units, u1, v1, 'rad', u2, v2, 'm', 'm', 'm', 'rad', 'rad', 'rad']
    else
      model%q_units = [character(len=8) :: model%q_units, u1, v1, u2, v2, 'rad', 'm', 'm', 'm', 'rad', 'rad', 'rad']
    end if
  end subroutine add_units

  !> The closure measurements g1..g5 of every contact are recorded (at velocity
  !> level they measure the drift), and in the open chain the chart of
  !> (u2, v2) (an ellipsoid's pole axis: kinetostatics_inverse_surface_joint).
  subroutine add_monitors(m, link)
    type(mechanism_t), intent(inout) :: m
    type(contact_link_t), intent(in) :: link
    integer :: i
    do i = 1, 5
      call m%add_monitor(link%gaps(i), merge('m', '1', i <= 3))
    end do
    if (link%open) call m%add_monitor(link%pair%chart, '1')
  end subroutine add_monitors

  !> Centre and inertia of every body (contact_factory body_from_spec).
  subroutine mass_properties(system, props, status)
    type(contact_system_t), intent(in) :: system
    type(solid_properties_t), intent(out) :: props(:)
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, size(system%bodies)
      call body_from_spec(system%bodies(k), system%shapes, props(k), status)
      if (.not. status%ok()) return
    end do
  end subroutine mass_properties

  !> Position level by the loop or (link%open) by the open chain, whose q
  !> are (u1, v1, phi, u2, v2) and whose N is what body 2 presses on the
  !> contact frame K_1D, -z_1D . f_1D.
  subroutine add_position_contact(m, c, link, s1, s2, q, status)
    type(mechanism_t), intent(inout) :: m
    type(contact_spec_t), intent(in) :: c
    type(contact_link_t), intent(inout) :: link
    class(surface_t), intent(in) :: s1, s2
    integer, allocatable, intent(inout) :: q(:)
    type(status_t), intent(inout) :: status
    if (link%open) then
      call add_open_contact_pair(m, c%name, link%frame_a, s1, c%side_1, c%body_2, s2, c%side_2, link%pair, status)
    else
      call add_contact_pair(m, c%name, link%frame_a, s1, c%side_1, c%body_2, s2, c%side_2, link%pair, status)
    end if
    if (.not. status%ok()) return
    link%frame_b = link%pair%frame_b
    link%frame_1d = link%pair%frame_1d
    link%frame_2d = link%pair%frame_2d
    link%coordinates = [link%pair%u1, link%pair%v1, link%pair%u2, link%pair%v2]
    link%gaps = link%pair%gaps
    q = [q, link%pair%coordinates()]
    if (link%open) then
      link%contact = m%add_contact(c%name, link%frame_a, link%frame_b, link%frame_1d, 1.0_wp)
      return
    end if
    ! N = lambda of g3: a positive cut force pushes K_2D along z_1D, away from A
    link%contact = m%add_contact(c%name, link%frame_a, link%frame_b, link%frame_1d, 1.0_wp, &
                                 normal_measurement=link%gaps(3))
    if (c%rolling) then
      link%rolling_outputs(1) = m%add_scalar(c%name//'.slip_x')
      link%rolling_outputs(2) = m%add_scalar(c%name//'.slip_y')
      call m%add_element(new_no_slip(c%name//'.no_slip', link%frame_a, link%frame_b, link%frame_1d, &
                                     link%rolling_outputs))
      call m%add_rate_constraint(c%name//' rolling', link%rolling_outputs, [link%pair%u12, link%pair%v12], status)
      m%contacts(link%contact)%tangential_outputs = link%rolling_outputs
    end if
  end subroutine add_position_contact

  !> Body 2 moved by the velocity-level element from the contact frame on S1;
  !> the start values come from the closed position-level model `closed`
  !> (contact k there).
  subroutine add_velocity_contact(m, c, link, s1, s2, closed, k, q, kinematic, status)
    type(mechanism_t), intent(inout) :: m
    type(contact_spec_t), intent(in) :: c
    type(contact_link_t), intent(inout) :: link
    class(surface_t), intent(in) :: s1, s2
    type(contact_model_t), intent(in) :: closed
    integer, intent(in) :: k
    integer, allocatable, intent(inout) :: q(:), kinematic(:)
    type(status_t), intent(inout) :: status
    real(wp), parameter :: ex(3) = [1, 0, 0], ey(3) = [0, 1, 0], ez(3) = [0, 0, 1]
    integer :: contact(5), pose(6), i
    real(wp) :: rel(3, 3), x2(3)
    character(len=2) :: digit
    associate (cm => closed%ode%work, cl => closed%links(k))
      if (starts_in_other_chart(cm, cl%pair)) then
        call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': at velocity level a contact '// &
          'cannot start at (within 10 degrees of) a pole of its shapes'' parametrisation (its surfaces do not '// &
          'change charts there); start it off the pole, turn the shape (angles_deg of its &shape), or use '// &
          'level = ''position''')
        return
      end if
      ! contact coordinates and the pose of B relative to A in the closed model
      rel = matmul(transpose(cm%frames(cl%frame_a)%rot), cm%frames(cl%frame_b)%rot)
      contact(1) = m%add_scalar(c%name//'.u1', cm%scalars(cl%coordinates(1))%q)
      contact(2) = m%add_scalar(c%name//'.v1', cm%scalars(cl%coordinates(2))%q)
      contact(3) = m%add_scalar(c%name//'.u2', cm%scalars(cl%coordinates(3))%q)
      contact(4) = m%add_scalar(c%name//'.v2', cm%scalars(cl%coordinates(4))%q)
      x2 = cm%frames(cl%frame_2d)%rot(:, 1)
      contact(5) = m%add_scalar(c%name//'.phi', atan2(dot_product(x2, cm%frames(cl%frame_1d)%rot(:, 2)), &
                                                      dot_product(x2, cm%frames(cl%frame_1d)%rot(:, 1))))
      x2 = matmul(transpose(cm%frames(cl%frame_a)%rot), cm%frames(cl%frame_b)%r - cm%frames(cl%frame_a)%r)
      do i = 1, 3
        write (digit, '(i1)') i
        pose(i) = m%add_scalar(c%name//'.x'//trim(digit), x2(i))
      end do
      do i = 1, 3
        write (digit, '(i1)') i
        pose(3 + i) = m%add_scalar(c%name//'.a'//trim(digit), 0.0_wp)
      end do
    end associate
    link%frame_1d = m%add_frame(c%name//'.1D')
    call m%add_element(new_surface_joint(c%name//'.s1', link%frame_a, link%frame_1d, contact(1), contact(2), s1, &
                                         c%side_1, 1.0_wp, 0.0_wp))
    link%frame_b = m%add_frame(c%body_2)
    call m%add_element(new_velocity_contact(c%name//'.contact', link%frame_a, link%frame_1d, link%frame_b, s1, &
                                            c%side_1, s2, c%side_2, contact, pose, rel, c%rolling))
    link%frame_2d = m%add_frame(c%name//'.2D')
    call m%add_element(new_surface_joint(c%name//'.s2', link%frame_b, link%frame_2d, contact(3), contact(4), s2, &
                                         c%side_2, 1.0_wp, 0.0_wp))
    do i = 1, 5
      write (digit, '(i1)') i
      link%gaps(i) = m%add_scalar(c%name//'.g'//trim(digit))
    end do
    call m%add_element(new_measurement(c%name//'.g1', MEASURE_PLANE_POINT, link%frame_1d, link%frame_2d, &
                                       link%gaps(1), axis_i=ex))
    call m%add_element(new_measurement(c%name//'.g2', MEASURE_PLANE_POINT, link%frame_1d, link%frame_2d, &
                                       link%gaps(2), axis_i=ey))
    call m%add_element(new_measurement(c%name//'.g3', MEASURE_PLANE_POINT, link%frame_1d, link%frame_2d, &
                                       link%gaps(3), axis_i=ez))
    call m%add_element(new_measurement(c%name//'.g4', MEASURE_PLANE_PLANE, link%frame_1d, link%frame_2d, &
                                       link%gaps(4), axis_i=ez, axis_j=ex))
    call m%add_element(new_measurement(c%name//'.g5', MEASURE_PLANE_PLANE, link%frame_1d, link%frame_2d, &
                                       link%gaps(5), axis_i=ez, axis_j=ey))
    link%coordinates = contact(1:4)
    if (c%rolling) then
      q = [q, contact(1), contact(2), contact(5), contact(3), contact(4), pose]
      kinematic = [kinematic, contact(3), contact(4), pose]
    else
      q = [q, contact, pose]
      kinematic = [kinematic, pose]
    end if
    ! N from the force the element passes back to the contact frame
    link%contact = m%add_contact(c%name, link%frame_a, link%frame_b, link%frame_1d, 1.0_wp)
    if (.not. status%ok()) return
  end subroutine add_velocity_contact

  !> The contact's friction law (its spec: force_law_from_spec), if any.
  subroutine add_friction(m, c, link, weight, status)
    type(mechanism_t), intent(inout) :: m
    type(contact_spec_t), intent(in) :: c
    type(contact_link_t), intent(inout) :: link
    real(wp), intent(in) :: weight   ! N, M g of body 2
    type(status_t), intent(inout) :: status
    class(force_law_t), allocatable :: law
    type(law_place_t) :: place   ! set by component: gfortran 12 leaks a constructor's name
    if (.not. allocated(c%friction%kind)) return
    place%name = c%name//'.friction'
    place%contact = link%contact
    place%weight = weight
    call force_law_from_spec(c%friction, place, law, status)
    if (.not. status%ok()) return
    call m%add_law(law)
    link%law = m%n_laws
  end subroutine add_friction

  !> Places every contact from the bodies' poses (or copies the closed
  !> configuration), closes and checks the loops, and finds the speeds.
  subroutine start(system, model, carrier, status, closed, loops)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(inout) :: model
    integer, intent(in) :: carrier(:)
    type(status_t), intent(inout) :: status
    type(contact_model_t), intent(in), optional :: closed
    type(loop_start_t), intent(in), optional :: loops(:)
    real(wp), allocatable :: q0(:), s0(:)
    real(wp) :: rot_a(3, 3), r_a(3)
    integer :: k, b1
    associate (m => model%ode%mechanism)
      do k = 1, size(system%contacts)
        associate (c => system%contacts(k), link => model%links(k))
          if (link%apart) then
            link%start_gap = 0
          else if (link%loop) then
            ! from the contact search at the pose the chains placed (contact_loops)
            m%scalars(link%pair%u1)%q = loops(k)%x(1)
            m%scalars(link%pair%v1)%q = loops(k)%x(2)
            m%scalars(link%pair%u2)%q = loops(k)%x(3)
            m%scalars(link%pair%v2)%q = loops(k)%x(4)
            call m%elements(link%pair%element_s1)%e%start_chart(m%scalars)
            call m%elements(link%pair%element_s2)%e%start_chart(m%scalars)
            link%start_gap = loops(k)%gap
          else if (link%open) then
            ! from the loop's closed configuration
            call place_open_contact_pair(m, link%pair, closed%ode%work, closed%links(k)%pair)
            link%start_gap = closed%links(k)%start_gap
            link%start_normal = closed%links(k)%start_normal
          else if (link%level == LEVEL_POSITION) then
            b1 = body_index(system, c%body_1)
            rot_a = identity
            r_a = 0
            if (b1 > 0) then
              rot_a = system%bodies(b1)%rotation
              r_a = system%bodies(b1)%position
            end if
            associate (b => system%bodies(body_index(system, c%body_2)))
              call place_contact_pair(m, link%pair, rot_a, r_a, b%rotation, b%position, link%start_gap, &
                                      link%start_normal, status)
            end associate
          else   ! velocity level: from the closed configuration too
            link%start_gap = closed%links(k)%start_gap
            link%start_normal = closed%links(k)%start_normal
          end if
        end associate
        if (.not. status%ok()) return
      end do
      q0 = m%scalars(m%q)%q
      call m%check_start(model%ode%work, q0, status)
      if (.not. status%ok()) return
      do k = 1, size(model%links)
        if (model%links(k)%level == LEVEL_POSITION .and. .not. (model%links(k)%open .or. model%links(k)%apart)) &
          call check_contact_branch(model%ode%work, model%links(k)%pair, status)
      end do
      if (.not. status%ok()) return
      call check_placement(system, model, carrier, status)
      if (.not. status%ok()) return
      call start_speeds(system, model, carrier, s0, status)
      if (.not. status%ok()) return
      model%y0 = model%ode%initial_state(q0, s0)
      call model%ode%check_start(model%y0, status)
      if (model%ode%not_pressing > 0) model%not_pressing = &
        findloc([(model%links(k)%contact == model%ode%not_pressing .and. .not. model%links(k)%apart, &
                  k = 1, size(model%links))], .true., dim=1)
    end associate
  end subroutine start

  !> Each body where its given pose puts it, to rounding: a flying body
  !> exactly, a body its contact placed moved along that contact's normal
  !> only, with its carrier body's move (also where the placement is copied
  !> from a closed configuration: velocity level, open chains). The move
  !> along the normal is the closure's (start_gap is set to it: the
  !> placement's own estimate is first order in the gap where the body's
  !> support point is not below its origin). A placement that moved a body
  !> sideways or turned it found the wrong contact point (a surface search
  !> that ended elsewhere) and would start a different motion without a
  !> word: refused. Bodies a second contact closes a loop on may be moved by
  !> that closure (contact_loops): not checked.
  subroutine check_placement(system, model, carrier, status)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(inout) :: model
    integer, intent(in) :: carrier(:)
    type(status_t), intent(inout) :: status
    real(wp) :: turn(3, 3), rot_ag(3, 3), r_ag(3), rot_ap(3, 3), r_ap(3), r_expected(3), rot_expected(3, 3)
    real(wp) :: normal(3), off(3), along, moved, turned
    character(len=:), allocatable :: where_from
    integer :: b, b1, k
    logical :: on_loop(size(system%bodies))
    if (.not. status%ok()) return
    on_loop = .false.
    do k = 1, size(model%links)
      if (model%links(k)%loop) on_loop(body_index(system, system%contacts(k)%body_2)) = .true.
    end do
    do b = 1, size(system%bodies)
      if (on_loop(b)) cycle
      k = carrier(b)
      associate (given => system%bodies(b), placed => model%ode%work%frames(model%body_frame(b + 1)))
        normal = 0
        if (k <= 0) then   ! -1: free (add_free)
          r_expected = given%position
          rot_expected = given%rotation
        else
          if (model%links(k)%apart .or. model%links(k)%loop) cycle
          b1 = body_index(system, system%contacts(k)%body_1)
          rot_ag = identity
          r_ag = 0
          rot_ap = identity
          r_ap = 0
          if (b1 > 0) then
            if (on_loop(b1)) cycle
            rot_ag = system%bodies(b1)%rotation
            r_ag = system%bodies(b1)%position
            rot_ap = model%ode%work%frames(model%body_frame(b1 + 1))%rot
            r_ap = model%ode%work%frames(model%body_frame(b1 + 1))%r
          end if
          turn = matmul(rot_ap, transpose(rot_ag))   ! the carrier body's own move
          normal = matmul(turn, model%links(k)%start_normal)
          r_expected = r_ap + matmul(turn, given%position - r_ag)
          rot_expected = matmul(turn, given%rotation)
        end if
        off = placed%r - r_expected
        along = dot_product(off, normal)
        moved = norm2(off - along*normal)
        ! the angle between the two rotations: |R - R'|_F = 2 sqrt(2) sin(angle/2)
        turned = 2*asin(min(1.0_wp, norm2(placed%rot - rot_expected)/sqrt(8.0_wp)))
        if (moved > placement_limit .or. turned > placement_limit) then
          if (k > 0) then
            where_from = 'where its position and the normal of contact '''//trim(system%contacts(k)%name)//''' put it'
          else
            where_from = 'its given pose (it flies)'
          end if
          call set_status(status, STATUS_DOMAIN, 'body '''//trim(given%name)//''': the start placement moved it '// &
            format_short(moved)//' m from '//where_from//' and turned it by '//format_short(turned)// &
            ' rad (limit '//format_short(placement_limit)//' m, rad): the contact point found is not the one '// &
            'below the body (a surface search that ended elsewhere)')
          return
        end if
        if (k > 0) model%links(k)%start_gap = -along
      end associate
    end do
  end subroutine check_placement

  !> The speeds whose body twists are nearest (least squares) to the given
  !> ones; refused if the given twists miss by more than 1e-9 of their size
  !> (plus 1e-12 m/s, rad/s): they would not be consistent with the contacts.
  subroutine start_speeds(system, model, carrier, s0, status)
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(inout) :: model
    integer, intent(in) :: carrier(:)
    real(wp), allocatable, intent(out) :: s0(:)
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: jac(:, :), twist(:), normal(:, :), unit(:), got(:)
    real(wp) :: miss, size_given
    integer :: nb, ns, k, b, worst
    associate (m => model%ode%mechanism)
      nb = size(system%bodies)
      ns = m%ns
      allocate (jac(6*nb, ns), twist(6*nb), unit(ns), s0(ns))
      do b = 1, nb
        twist(6*b - 5:6*b) = [system%bodies(b)%angular_velocity, system%bodies(b)%velocity]
      end do
      do k = 1, ns
        unit = 0
        unit(k) = 1
        call m%set_velocities(model%ode%work, unit)
        do b = 1, nb
          associate (fr => model%ode%work%frames(model%body_frame(b + 1)))
            jac(6*b - 5:6*b, k) = [fr%omega, fr%v]
          end associate
        end do
      end do
      normal = matmul(transpose(jac), jac)
      s0 = matmul(transpose(jac), twist)
      call cholesky_factor(normal, status)
      if (status%ok()) call cholesky_solve(normal, s0, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'start velocities: the bodies'' twists do not determine the speeds')
        return
      end if
      got = matmul(jac, s0)
      size_given = maxval(abs(twist))
      worst = maxloc(abs(got - twist), dim=1)
      miss = abs(got(worst) - twist(worst))
      if (miss > 1e-9_wp*size_given + 1e-12_wp) then
        b = (worst + 5)/6
        call set_status(status, STATUS_INVALID_INPUT, 'the start velocities are not consistent with the '// &
          'contacts: body '''//system%bodies(b)%name//''' (carried by contact '''// &
          system%contacts(max(carrier(b), 1))%name//''') can only have a twist that differs by '//format_short(miss)// &
          trim(merge(' rad/s', ' m/s  ', mod(worst - 1, 6) < 3))//' in its '// &
          trim(merge('angular velocity', 'velocity        ', mod(worst - 1, 6) < 3))// &
          ' (component '//achar(iachar('x') + mod(worst - 1, 3))//'); give a twist with no velocity into '// &
          'the surfaces (and no slip at rolling contacts)')
        return
      end if
      call m%set_velocities(model%ode%work, s0)
    end associate
  end subroutine start_speeds
end module contact_model
