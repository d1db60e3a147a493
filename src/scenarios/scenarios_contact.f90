!> Scenario `contact`: bodies in point contact between smooth surfaces
!> (thesis 3.5.3; docs/contact.md): the spinning egg, rolling paraboloids, a
!> tower, a ball on an incline. The description (&contact_model, &shape,
!> &body, &contact) is built into one mechanism by contact_model and run by
!> the multibody scenarios' common run (scenarios_mechanism).
module scenarios_contact
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use base_log, only: log_info
  use base_text, only: format_short
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient, &
    body_size
  use io_input, only: input_text_t, check_known_groups, mark_input_failure, where_given, format_vector
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config, contact_groups, contact_repeatable_groups
  use io_surface_config, only: surface_source_t, explain_surface_failure
  use geometry_surface_description, only: build_surface
  use scenarios_mechanism, only: run_mechanism
  use contact_flight, only: flight_ode_t, build_flight, starts_open, check_flight_system, carrying_contact, closed_part
  use contact_closing, only: flight_after_closed
  use contact_bodies, only: build_bodies_opening, start_carriers
  use io_xdmf, only: body_shape_t
  use base_grid, only: evenly_spaced
  use numerics_ode, only: ODE_ADAMS
  implicit none (type, external)
  private
  public :: run_contact, contact_groups

contains

  subroutine run_contact(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(contact_system_t) :: system, carried
    type(contact_model_t), target :: model
    logical :: flies
    integer :: f, ns
    real(wp), allocatable :: y0(:)
    type(surface_source_t), allocatable :: shape_sources(:)
    type(status_t) :: built
    character(len=:), allocatable :: part, variable
    integer :: k

    call check_known_groups(input, contact_groups, status, repeatable=contact_repeatable_groups)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_contact_config(input, system, status, shape_sources)
    if (.not. status%ok()) return
    ! the shapes built here, so that a failure names its &shape's line
    do k = 1, size(system%shapes)
      call build_surface(system%shapes(k)%description, system%shapes(k)%surface, built, part, variable)
      call explain_surface_failure(shape_sources(k), built, part, variable, status)
      if (.not. status%ok()) return
    end do
    if (solver%options%method == ODE_ADAMS) solver%options%convergence_coefficient = contact_convergence_coefficient
    flies = starts_open(system) .or. any(system%contacts%may_open)
    if (flies) call check_flight_system(system, status)
    call locate_failure(input, system, status)
    if (.not. status%ok()) return
    if (flies .and. carrying_contact(system) == 0) then
      call run_flight(input, run, solver, system, status)
      return
    end if
    if (flies .and. (size(system%bodies) > 1 .or. count(.not. system%contacts%start_open) > 1)) then
      ! several bodies, or one on several closed contacts (contact_loops)
      call run_bodies(input, run, solver, system, status)
      return
    end if
    ! a body with contacts to land on starts carried by its closed one alone
    carried = system
    if (flies) carried = closed_part(system, carrying_contact(system))
    call build_contact_model(carried, model, status)
    f = model%ode%mechanism%f
    ns = model%ode%mechanism%ns
    ! the start is judged here too (run_mechanism does it again), so that
    ! its failures name the &contact or &body they are about
    if (status%ok()) then
      y0 = model%ode%initial_state(model%y0(1:f), model%y0(f + 1:f + ns))
      call model%ode%check_start(y0, status)
    end if
    call locate_failure(input, system, status)
    if (.not. status%ok()) return
    call check_moves(input, carried, model, status)
    if (.not. status%ok()) return
    if (flies) then
      call run_flight(input, run, solver, system, status, closed=model)
      return
    end if
    call run_mechanism('contact', input, run, solver, model%ode, model%y0(1:f), model%y0(f + 1:f + ns), &
                       model%q_units, model%beta_units, status, &
                       surface=system%shapes(first_shape(system))%surface, shapes=bounded_body_shapes(system))
  end subroutine run_contact

  !> A flight: a body whose contacts start open flies until it lands
  !> (contact_flight); given the `closed` model of its contact that starts
  !> closed (and may open, or has others to land on), the body starts closed
  !> and flies from its lift-off (contact_closing).
  subroutine run_flight(input, run, solver, system, status, closed)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(solver_config_t), intent(in) :: solver
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    type(contact_model_t), intent(in), optional :: closed
    type(flight_ode_t) :: flight
    real(wp), allocatable :: q0(:), qd0(:)
    character(len=8), allocatable :: q_units(:)
    if (present(closed)) then
      call flight_after_closed(system, closed, flight, q0, qd0, q_units, status)
    else
      call build_flight(system, flight, q0, qd0, q_units, status)
    end if
    call locate_failure(input, system, status)
    if (.not. status%ok()) return
    call run_mechanism('contact', input, run, solver, flight, q0, qd0, q_units, [character(len=8) ::], status, &
                       shapes=bounded_body_shapes(system))
  end subroutine run_flight

  !> Several bodies, some carried by a closed contact at the start, the
  !> others flying (contact_bodies): one mechanism of them all, driven as a
  !> flight whose bodies land, close, lift off (contact_closing).
  subroutine run_bodies(input, run, solver, system, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(solver_config_t), intent(in) :: solver
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    type(flight_ode_t) :: flight
    type(contact_model_t) :: model
    real(wp), allocatable :: q0(:), qd0(:), y0(:)
    character(len=8), allocatable :: q_units(:)
    logical :: closed(size(system%contacts)), touching(size(system%contacts))
    integer, allocatable :: opened(:)
    integer :: k
    ! a contact closed at the start that may open and carries nothing there
    ! (a ball resting on another, both falling) starts open at gap 0
    closed = start_carriers(system)
    touching = .false.
    call build_bodies_opening(system, closed, touching, flight, q0, qd0, q_units, status, .false., opened, model)
    do k = 1, size(opened)
      call log_info(input%name//': contact '''//trim(system%contacts(opened(k))%name)//''' (start = ''closed'') '// &
                    'carries nothing at the start (its bodies fall freely together, or it would pull): it starts '// &
                    'open at gap 0 (may_open)')
    end do
    if (status%ok()) then
      y0 = flight%initial_state(q0, qd0)
      call flight%check_start(y0, status)
    end if
    if (.not. status%ok()) then
      call locate_failure(input, system, status)
      call mark_input_failure(status)
      return
    end if
    call check_moves(input, system, model, status)
    if (.not. status%ok()) return
    call run_mechanism('contact', input, run, solver, flight, q0, qd0, q_units, [character(len=8) ::], status, &
                       shapes=bounded_body_shapes(system))
  end subroutine run_bodies

  !> Every bounded shape a body carries (an egg, a ball; not a plane or an
  !> open paraboloid), as a 24 x 13 grid in the body's axes for the XDMF view.
  function bounded_body_shapes(system) result(shapes)
    type(contact_system_t), intent(in) :: system
    type(body_shape_t), allocatable :: shapes(:)
    integer, parameter :: n_u = 24, n_v = 13
    real(wp), parameter :: unbounded = 1e6_wp   ! m, as io_surface_grid's
    real(wp) :: box(4), x(n_v, n_u), y(n_v, n_u), z(n_v, n_u)
    type(body_shape_t) :: one
    type(status_t) :: evaluated
    integer :: c, side, k
    character(len=:), allocatable :: body, shape
    allocate (shapes(0))
    do c = 1, size(system%contacts)
      do side = 1, 2
        if (side == 1) then
          body = system%contacts(c)%body_1; shape = system%contacts(c)%shape_1
        else
          body = system%contacts(c)%body_2; shape = system%contacts(c)%shape_2
        end if
        if (body == 'ground') cycle
        if (any([(shapes(k)%body == body .and. shapes(k)%shape == shape, k = 1, size(shapes))])) cycle
        k = findloc([(system%shapes(k)%name == shape, k = 1, size(system%shapes))], .true., dim=1)
        if (k == 0) cycle
        call system%shapes(k)%surface%domain(box(1), box(2), box(3), box(4))
        if (any(abs(box) > unbounded)) cycle
        call system%shapes(k)%surface%points_on_grid(evenly_spaced(box(1), box(2), n_u), &
                                                     evenly_spaced(box(3), box(4), n_v), x, y, z, evaluated)
        if (.not. evaluated%ok()) cycle
        one%body = body
        one%shape = shape
        allocate (one%points(3, n_v, n_u))
        one%points(1, :, :) = x
        one%points(2, :, :) = y
        one%points(3, :, :) = z
        shapes = [shapes, one]
        deallocate (one%points)
      end do
    end do
  end function bounded_body_shapes

  !> A line for every body that its start position did not put onto its
  !> carrier (the documented convenience: contact_pair moves it along the
  !> normal until it touches), so that no move passes unseen; moves below a
  !> nanometre are rounding of a position meant to touch. A move longer than
  !> the body's own size (contact_model body_size; none for a body of planes
  !> only) is refused: no position meant to touch is that far off, while a
  !> mistyped one (5.0 for 0.05 m, a sign, mm for m) is, and over a curved
  !> shape the point the body is moved onto depends on where it starts.
  subroutine check_moves(input, system, model, status)
    type(input_text_t), intent(in) :: input
    type(contact_system_t), intent(in) :: system
    type(contact_model_t), intent(in) :: model
    type(status_t), intent(inout) :: status
    integer :: k, b, j
    real(wp) :: length
    character(len=:), allocatable :: move
    do k = 1, size(model%links)
      associate (gap => model%links(k)%start_gap, c => system%contacts(k))
        if (.not. abs(gap) > 1e-9_wp) cycle
        move = trim(merge('lowered', 'lifted ', gap > 0))//' by '//format_short(abs(gap))// &
          ' m along the normal of contact '''//c%name//''' to touch shape '''//c%shape_1//''''
        b = findloc([(system%bodies(j)%name == c%body_2, j = 1, size(system%bodies))], .true., dim=1)
        length = body_size(system, b)
        if (length > 0 .and. abs(gap) > length) then
          call set_status(status, STATUS_INVALID_INPUT, where_given(input, 'body', 'position', occurrence=b)// &
            ': &body: position = '//format_vector(system%bodies(b)%position)//' is not allowed: body '''// &
            c%body_2//''' would be '//move//', more than its own size ('//format_short(length)// &
            ' m); the start position must be within the body''s size of touching (a mistyped position?)')
          return
        end if
        call log_info('contact: body '''//c%body_2//''' '//move//' (its start position did not)')
      end associate
    end do
  end subroutine check_moves

  !> Puts in front of a failure of the model's build or start where it is
  !> about: the &contact or &body (file and line) whose name the message
  !> quotes first, else the file and the scenario. A message that begins
  !> with that group and name ("contact 'x': ...") loses them: the place
  !> names them already. Such a failure is bad input (mark_input_failure);
  !> a status that is ok stays as it is.
  subroutine locate_failure(input, system, status)
    type(input_text_t), intent(in) :: input
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: message, where, lead
    if (status%ok()) return
    message = status%text()
    where = failure_where(input, system, message, lead)
    if (len(lead) > 0) then
      if (index(message, lead) == 1) message = message(len(lead) + 1:)
    end if
    status%message = message
    if (where == input%name) where = where//': contact'
    call prefix_status(status, where)
    call mark_input_failure(status)
  end subroutine locate_failure

  !> The &contact or &body (file and line) whose name `message` quotes first,
  !> else the file; lead: "group 'name': ", how a message about it begins.
  function failure_where(input, system, message, lead) result(where)
    type(input_text_t), intent(in) :: input
    type(contact_system_t), intent(in) :: system
    character(len=*), intent(in) :: message
    character(len=:), allocatable, intent(out) :: lead
    character(len=:), allocatable :: where
    integer :: k, first
    where = input%name
    lead = ''
    first = len(message) + 1
    do k = 1, size(system%contacts)
      call consider('contact', k, system%contacts(k)%name)
    end do
    do k = 1, size(system%bodies)
      call consider('body', k, system%bodies(k)%name)
    end do
  contains
    !> The k-th &group, named `name`, if the message quotes it first so far.
    subroutine consider(group, k, name)
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: k
      integer :: at
      at = quoted_at(name)
      if (at > 0 .and. at < first) then
        first = at
        where = where_given(input, group, 'name', occurrence=k)//': &'//group//' name = '''//name//''''
        lead = group//' '''//name//''': '
      end if
    end subroutine consider

    !> The first place the message quotes `name` ('name' or 'name.u2').
    integer function quoted_at(name)
      character(len=*), intent(in) :: name
      quoted_at = index(message, ''''//name//'''')
      if (quoted_at == 0) quoted_at = index(message, ''''//name//'.')
    end function quoted_at
  end function failure_where

  !> The shape of the first contact's surface 1 (its grid goes into the result).
  pure integer function first_shape(system) result(k)
    type(contact_system_t), intent(in) :: system
    do k = 1, size(system%shapes)
      if (system%shapes(k)%name == system%contacts(1)%shape_1) return
    end do
    k = 1
  end function first_shape
end module scenarios_contact
