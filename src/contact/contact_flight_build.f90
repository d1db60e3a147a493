!> The construction of a flight (contact_flight): the description checked
!> for a flight (every contact between the ground and a body, or two bodies
!> that start open), each body free (contact_free_body) with its mass
!> properties kept for the impacts, the gaps watched from the start, a
!> restart at a given pose and twist (a lift-off into flight), and the rates
!> that give a body a twist (its start, and its twist after an impact).
submodule (contact_flight) contact_flight_build
  use base_status, only: set_status, STATUS_INVALID_INPUT
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use geometry_solid, only: solid_properties_t
  use contact_factory, only: body_from_spec
  use contact_free_body, only: add_free_body_to => add_free_body, free_body_units
  use contact_model, only: contact_spec_t, build_system_shapes, body_index, LEVEL_POSITION, CHAIN_AUTO
  use contact_open_gaps, only: start_open_gaps
  implicit none (type, external)

contains

  !> Refused unless every contact is between the ground or a body and a
  !> body (a body's several closed contacts carry it together,
  !> contact_loops; its open ones are surfaces it may land on; one between
  !> two bodies without level or chain: it closes by the open chain,
  !> sliding, with its friction law if any, or rolling by the loop), and
  !> unless a contact that starts open has restitution where it has what
  !> only a closed contact uses (a description with a contact that starts
  !> open or may open: a flight).
  module procedure check_flight_system
    integer :: k
    if (.not. status%ok()) return
    do k = 1, size(system%contacts)
      associate (c => system%contacts(k))
        if (body_index(system, c%body_2) <= 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': body_2 = '''//c%body_2// &
            ''' is not a body')
          return
        end if
        if (c%body_1 == 'ground') cycle
        if (body_index(system, c%body_1) <= 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': body_1 = '''//c%body_1// &
            ''' is not a body')
        else if (c%level /= LEVEL_POSITION .or. c%chain /= CHAIN_AUTO) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': body_1 = '''//c%body_1// &
            ''': where contacts open and close (start = ''open'', may_open) a contact between two bodies closes '// &
            'at position level, sliding by the open chain or rolling by the loop (level and chain there are not '// &
            'built): leave them out')
        end if
        if (.not. status%ok()) return
      end associate
    end do
    do k = 1, size(system%contacts)
      associate (c => system%contacts(k))
        if (c%start_open .and. c%restitution < 0 .and. closed_settings(c)) &
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': friction, rolling, level and '// &
            'chain of a contact that starts open are the closed contact''s after its body lands and the contact '// &
            'closes, which needs restitution (without it the run ends at the landing: they would be unused); '// &
            'give restitution, or leave them out')
      end associate
      if (.not. status%ok()) return
    end do
  end procedure check_flight_system

  !> Whether the contact gives any of the closed contact's settings
  !> (friction, rolling, level, chain).
  pure logical function closed_settings(c)
    type(contact_spec_t), intent(in) :: c
    closed_settings = allocated(c%friction%kind) .or. c%rolling .or. c%level /= LEVEL_POSITION .or. &
                      c%chain /= CHAIN_AUTO
  end function closed_settings

  !> The free body of `system` at its given pose and twist: q0 = (x, y, z,
  !> a1, a2, a3), qd0 their rates, q_units; refused unless the description
  !> is a flight's (check_flight_system) with the shapes apart (touching: the
  !> contact that may touch, a closed start that may open). Shapes given by
  !> their descriptions are built first (build_system_shapes, as for a
  !> closed start).
  module procedure build_flight
    type(contact_system_t) :: shaped
    call check_flight_system(system, status)
    if (.not. status%ok()) return
    if (size(system%bodies) > 1 .and. .not. all(system%contacts%start_open)) then
      call set_status(status, STATUS_INVALID_INPUT, 'several bodies of which one starts closed: built by '// &
                      'contact_bodies build_bodies (build_flight builds bodies that all fly)')
      return
    end if
    call build_system_shapes(system, shaped, status)
    call build_shaped_flight(shaped, flight, q0, qd0, q_units, status, touching)
  end procedure build_flight

  !> build_flight of a system whose shapes are built: every body free, in
  !> the order of the &body groups.
  subroutine build_shaped_flight(system, flight, q0, qd0, q_units, status, touching)
    type(contact_system_t), intent(in) :: system
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    integer, intent(in), optional :: touching
    integer :: i, b, nb
    if (.not. status%ok()) return
    nb = size(system%bodies)
    flight%system = system
    allocate (flight%mass(nb), flight%inertia(3, 3, nb), flight%centre(3, nb), flight%body_frame(nb), &
              flight%coordinates(6, nb), flight%rotation_element(nb), flight%impacts(0), flight%speeds(6, nb), &
              flight%mechanism_contact(size(system%contacts)), flight%closings(0))
    flight%speeds = reshape([(i, i = 1, 6*nb)], [6, nb])
    call flight%clear_switches()
    flight%mechanism_contact = 0
    associate (m => flight%mechanism)
      do b = 1, nb
        call add_free_body(flight, b, status)
        if (.not. status%ok()) return
      end do
      allocate (flight%gap_monitors(size(system%contacts)))
      do i = 1, size(system%contacts)
        call m%add_monitor(m%add_scalar(system%contacts(i)%name//'.gap'), 'm')
        flight%gap_monitors(i) = size(m%monitors)
      end do
      call m%set_coordinates(reshape(flight%coordinates, [6*nb]))
      call m%finalize(status)
      if (.not. status%ok()) return
      q0 = m%scalars(reshape(flight%coordinates, [6*nb]))%q
      call m%set_positions(flight%work, q0, status)
      if (.not. status%ok()) return
      allocate (qd0(6*nb), source=0.0_wp)
      do b = 1, nb
        associate (spec => system%bodies(b))
          call start_rates(flight, b, [spec%angular_velocity, spec%velocity], qd0, status)
        end associate
        if (.not. status%ok()) return
      end do
      q_units = [(free_body_units, b = 1, nb)]
      flight%q_units = q_units
      allocate (flight%beta_units(0))
      if (present(touching)) then
        call start_open_gaps(flight%gaps, system, flight%work, flight%body_frame, status, touching, 0, .false.)
      else
        call start_open_gaps(flight%gaps, system, flight%work, flight%body_frame, status, 0, 0, .false.)
      end if
    end associate
  end subroutine build_shaped_flight

  !> Body b of the description, free (contact_free_body), its mass
  !> properties kept for the impacts.
  subroutine add_free_body(flight, b, status)
    type(flight_ode_t), intent(inout) :: flight
    integer, intent(in) :: b
    type(status_t), intent(inout) :: status
    type(solid_properties_t) :: props
    associate (spec => flight%system%bodies(b))
      call body_from_spec(spec, flight%system%shapes, props, status)
      if (.not. status%ok()) return
      flight%mass(b) = spec%mass
      flight%inertia(:, :, b) = props%inertia
      flight%centre(:, b) = props%centre
      call add_free_body_to(flight%mechanism, spec, props, flight%system%gravity, flight%system%air_density, &
                            flight%system%wind, flight%coordinates(:, b), flight%body_frame(b), &
                            flight%rotation_element(b), status)
    end associate
  end subroutine add_free_body

  !> The free body (the description's one body) placed again at `rotation`
  !> and `position` (its frame's
  !> axes and origin, world) with the twist [omega, v] (world; v of its
  !> origin): the prismatic coordinates the origin, the free rotation's
  !> angles 0 on a chart centred there, the rates solved for the twist; the
  !> gaps from the contact search there, the contact it leaves (closed_on)
  !> touching. y: its state (contact_closing, a lift-off into flight).
  module procedure restart_flight
    real(wp), allocatable :: q0(:), qd0(:)
    integer :: i
    if (.not. status%ok()) return
    associate (m => flight%mechanism, work => flight%work)
      call m%prepare_workspace(work)
      do i = 1, 3
        work%scalars(flight%coordinates(i, 1))%q = position(i)
        work%scalars(flight%coordinates(3 + i, 1))%q = 0
      end do
      call work%elements(flight%rotation_element(1))%e%centre_chart(rotation)
      q0 = work%scalars(flight%coordinates(:, 1))%q
      call m%set_positions(flight%work, q0, status)
      if (.not. status%ok()) return
      allocate (qd0(6), source=0.0_wp)
      call start_rates(flight, 1, twist, qd0, status)
      if (.not. status%ok()) return
      call start_open_gaps(flight%gaps, flight%system, flight%work, flight%body_frame, status, flight%closed_on, 0, &
                           .true.)
      if (.not. status%ok()) return
      y = flight%initial_state(q0, qd0)
    end associate
  end procedure restart_flight

  !> The rates of body b's (x, y, z, a1, a2, a3) that give it the twist
  !> [omega, v] (world; v of its frame's origin): the six columns of its
  !> twist per unit rate, solved (a free body: any twist is reached). rates:
  !> every body's, body b's replaced; the mechanism's velocities set to them.
  module procedure start_rates
    real(wp) :: jac(6, 6), unit(size(rates)), block(6)
    integer :: k, ipiv(6)
    associate (m => flight%mechanism, frame => flight%work%frames(flight%body_frame(b)))
      do k = 1, 6
        unit = 0
        unit(flight%speeds(k, b)) = 1
        call m%set_velocities(flight%work, unit)
        jac(:, k) = [frame%omega, frame%v]
      end do
      block = twist
      call lu_factor(jac, ipiv, status)
      if (status%ok()) call lu_solve(jac, ipiv, block, status)
      if (.not. status%ok()) return
      rates(flight%speeds(:, b)) = block
      call m%set_velocities(flight%work, rates)
    end associate
  end procedure start_rates
end submodule contact_flight_build
