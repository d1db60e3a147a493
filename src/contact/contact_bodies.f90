!> Several bodies, each carried by its closed contacts with the ground (one,
!> or several: contact_loops) or flying (issue 25): one phase of the run as
!> one mechanism, built from the
!> current set of closed contacts (contact_model: a closed contact carries
!> its body as in a closed run; every body no closed contact carries is free,
!> contact_free_body) and driven as a flight (contact_flight flight_ode_t:
!> the open contacts' gaps are its roots, a landing of a flying body is an
!> impact, a rebound below close_speed closes that contact; a closed
!> contact's lift-off is the mechanism's). A switch (a closing, a lift-off
!> of a contact that may open) builds the next phase from every body's
!> pose and twist at the switch (contact_closing drive_bodies): the body
!> that switched changes its part, the others keep their poses and twists
!> to rounding (a closed contact's coordinates come again from the contact
!> search at its body's pose; a free body's from its pose, its rates from
!> its twist).
!>
!> A closed contact's body landing on another surface while carried is one
!> impact through its carrying contacts too (contact_flight
!> impact_on_carried), and so is a flying body hitting a carried one (the
!> carried body's closed contacts take impulses of their own); two flying
!> bodies hitting each other is an impact of the pair (contact_body_impact),
!> and they fly on.
module contact_bodies
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use geometry_solid, only: solid_properties_t
  use contact_factory, only: body_from_spec
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, build_system_shapes, body_index
  use contact_flight, only: flight_ode_t, check_flight_system
  use contact_open_gaps, only: start_open_gaps, touching_gap_limit
  implicit none (type, external)
  private
  public :: build_bodies, build_bodies_opening, start_carriers

contains

  !> The contacts that start closed (a body none of whose contacts does
  !> starts in flight).
  pure function start_carriers(system) result(closed)
    type(contact_system_t), intent(in) :: system
    logical :: closed(size(system%contacts))
    closed = .not. system%contacts%start_open
  end function start_carriers

  !> The phase of `system` where the contacts `closed` carry their bodies
  !> (the first of a body's as a chain, the others as loops: contact_loops)
  !> and every body none of them carries flies, each at its pose and twist
  !> of the description: the mechanism (contact_model), its start q0, qd0 and
  !> units, its open contacts' gaps (the contact `touching` and those of
  !> `also_touching` may touch: they have just lifted off, or an impact left
  !> them at gap 0; each watched from its opening). restarting: a switch during the run (the closed
  !> contacts must touch to touching_gap_limit, the gaps are the motion's);
  !> else the run's start (checked as the input: check_flight_system;
  !> model, if present, is the built contact model, for the start's moves).
  subroutine build_bodies(system, closed, flight, q0, qd0, q_units, status, touching, restarting, model, &
                          also_touching, not_pressing)
    type(contact_system_t), intent(in) :: system
    logical, intent(in) :: closed(:)   ! each contact: closed
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    integer, intent(in) :: touching
    logical, intent(in) :: restarting
    type(contact_model_t), intent(out), optional :: model
    logical, intent(in), optional :: also_touching(:)   ! each contact: it may touch too (left at gap 0)
    !> where the build fails because a closed contact does not press at the
    !> start: that contact (of system), else 0
    integer, intent(out), optional :: not_pressing
    type(contact_model_t) :: built
    type(contact_system_t) :: part
    type(solid_properties_t) :: props
    integer :: b, c, k, f, nb, nc, j
    integer :: carrier(size(system%bodies))
    if (.not. status%ok()) return
    if (.not. restarting) call check_flight_system(system, status)
    call build_system_shapes(system, part, status)
    if (.not. status%ok()) return
    nb = size(system%bodies)
    nc = size(system%contacts)
    part%contacts%start_open = .not. closed
    ! each body's first closed contact carries it (0: it flies)
    carrier = 0
    do c = nc, 1, -1
      if (closed(c)) carrier(body_index(system, system%contacts(c)%body_2)) = c
    end do
    call build_contact_model(part, built, status, flying=.true.)
    if (present(not_pressing)) not_pressing = built%not_pressing
    if (.not. status%ok()) return
    if (restarting) then
      do c = 1, nc
        if (built%links(c)%apart .or. abs(built%links(c)%start_gap) <= touching_gap_limit) cycle
        call set_status(status, STATUS_DOMAIN, 'contact '''//system%contacts(c)%name//''': the closed contact '// &
          'moved its body by '//format_short(built%links(c)%start_gap)//' m to touch (more than '// &
          format_short(touching_gap_limit)//' m): the pose at the switch is not a touching one')
        return
      end do
    end if
    flight%mechanism_ode_t = built%ode
    flight%system = part
    allocate (flight%mass(nb), flight%inertia(3, 3, nb), flight%centre(3, nb), flight%impacts(0), &
              flight%speeds(6, nb), flight%closings(0))
    flight%body_frame = built%body_frame(2:)
    call flight%clear_switches()
    flight%coordinates = built%free
    flight%rotation_element = built%rotation_element
    flight%gap_monitors = built%gap_monitors
    flight%mechanism_contact = [(merge(0, built%links(c)%contact, built%links(c)%apart), c = 1, nc)]
    flight%q_units = built%q_units
    flight%beta_units = built%beta_units
    q_units = built%q_units
    associate (m => flight%mechanism)
      flight%speeds = 0
      do b = 1, nb
        call body_from_spec(part%bodies(b), part%shapes, props, status)
        if (.not. status%ok()) return
        flight%mass(b) = system%bodies(b)%mass
        flight%inertia(:, :, b) = props%inertia
        flight%centre(:, b) = props%centre
        if (carrier(b) > 0) cycle
        do k = 1, 6
          j = findloc(m%q, flight%coordinates(k, b), dim=1)
          flight%speeds(k, b) = findloc(m%speeds, j, dim=1)
        end do
      end do
      f = m%f
      q0 = built%y0(1:f)
      qd0 = built%y0(f + 1:f + m%ns)
    end associate
    call start_open_gaps(flight%gaps, part, flight%work, flight%body_frame, status, touching, 0, restarting, &
                         carried=.not. part%contacts%start_open, also_touching=also_touching)
    if (present(model)) model = built
  end subroutine build_bodies

  !> build_bodies where a closed contact that may open does not carry:
  !> its normal force in the built phase at most 1e-9 of its body_2's
  !> weight (two bodies on each other falling freely press with nothing, a
  !> zero whose rounding has either sign; below it the contact would lift
  !> off at once, which may_open allows) opens at gap 0, touching (watched
  !> from its opening), and the phase is built again; `closed` and
  !> `touching` are updated, `opened` lists those so opened (in order).
  !> Where such a contact may not open the build fails as build_bodies'
  !> does ("does not press").
  subroutine build_bodies_opening(system, closed, touching, flight, q0, qd0, q_units, status, restarting, opened, &
                                  model)
    type(contact_system_t), intent(in) :: system
    logical, intent(inout) :: closed(:), touching(:)
    type(flight_ode_t), intent(out) :: flight
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    character(len=8), allocatable, intent(out) :: q_units(:)
    type(status_t), intent(inout) :: status
    logical, intent(in) :: restarting
    integer, allocatable, intent(out) :: opened(:)
    type(contact_model_t), intent(out), optional :: model
    integer :: quiet, attempt
    allocate (opened(0))
    if (.not. status%ok()) return
    do attempt = 1, size(closed) + 1
      call build_bodies(system, closed, flight, q0, qd0, q_units, status, 0, restarting, model, &
                        also_touching=touching, not_pressing=quiet)
      if (status%ok()) quiet = unloaded_contact(system, closed, flight)
      if (quiet == 0) return
      if (.not. (closed(quiet) .and. system%contacts(quiet)%may_open)) return
      status = status_t()
      closed(quiet) = .false.
      touching(quiet) = .true.
      opened = [opened, quiet]
    end do
  end subroutine build_bodies_opening

  !> The first closed contact that may open and whose normal force in the
  !> built phase is at most 1e-9 of its body_2's weight, else 0.
  integer function unloaded_contact(system, closed, phase) result(quiet)
    type(contact_system_t), intent(in) :: system
    logical, intent(in) :: closed(:)
    type(flight_ode_t), intent(in) :: phase
    integer :: c, k
    real(wp) :: weight
    quiet = 0
    do c = 1, size(closed)
      if (.not. (closed(c) .and. system%contacts(c)%may_open)) cycle
      k = phase%mechanism_contact(c)
      if (k == 0) cycle
      weight = system%bodies(body_index(system, system%contacts(c)%body_2))%mass*norm2(system%gravity)
      if (phase%work%normal_force(k) <= 1e-9_wp*weight) then
        quiet = c
        return
      end if
    end do
  end function unloaded_contact
end module contact_bodies
