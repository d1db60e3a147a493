!> The description of a contact system (contact_model builds it into a
!> mechanism; contact_flight into free bodies): named shapes, bodies and
!> contacts, the checks of its names and references, the bodies' sizes.
!> Split from contact_model, which re-exports these names.
module contact_system
  use base_kinds, only: wp
  use base_constants, only: standard_gravity, dry_air_density
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t
  use geometry_surface, only: surface_t
  use contact_factory, only: shape_t, body_spec_t, build_shapes
  implicit none (type, external)
  private
  public :: shape_t, body_spec_t, contact_spec_t, contact_system_t
  public :: build_system_shapes, check_names, open_chain, body_size, body_index, shape_index, known_shapes, &
    build_order, flies_free
  public :: LEVEL_POSITION, LEVEL_VELOCITY, CHAIN_AUTO, CHAIN_OPEN, CHAIN_LOOP

  integer, parameter :: LEVEL_POSITION = 1, LEVEL_VELOCITY = 2
  !> The chain of a position-level contact: open where it applies (no
  !> rolling), else the loop (CHAIN_AUTO); or either chosen.
  integer, parameter :: CHAIN_AUTO = 0, CHAIN_OPEN = 1, CHAIN_LOOP = 2

  type :: contact_spec_t
    character(len=:), allocatable :: name, body_1, shape_1, body_2, shape_2
    real(wp) :: side_1 = 1, side_2 = 1           ! normal towards the other body (+1/-1)
    type(spec_t) :: friction                     ! a force law kind and its parameters (no kind: none)
    logical :: rolling = .false.
    integer :: level = LEVEL_POSITION
    integer :: chain = CHAIN_AUTO
    logical :: start_open = .false.              ! starts apart, the body in flight (contact_flight)
    logical :: may_open = .false.                ! a lift-off opens it: the body flies on (contact_closing)
    real(wp) :: restitution = -1                 ! energetic e of its landings (contact_flight); < 0: none given
    real(wp) :: impact_mu = 0                    ! Coulomb mu during its impacts
    real(wp) :: close_speed = 0.01_wp            ! m/s, a rebound below it would close the contact
  end type contact_spec_t

  !> The description: 'ground' names the fixed frame (it needs no body entry).
  type :: contact_system_t
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   ! m/s^2
    real(wp) :: air_density = dry_air_density    ! kg/m^3, of the air's drag on bodies with a drag_area
    real(wp) :: wind(3) = 0                      ! m/s, the air's velocity (world)
    type(shape_t), allocatable :: shapes(:)
    type(body_spec_t), allocatable :: bodies(:)
    type(contact_spec_t), allocatable :: contacts(:)
  end type contact_system_t

contains

  !> `system` with the shapes given by their descriptions built
  !> (contact_factory's build_shapes; built ones are kept): the model's and
  !> the flight's builders start from it.
  subroutine build_system_shapes(system, shaped, status)
    type(contact_system_t), intent(in) :: system
    type(contact_system_t), intent(out) :: shaped
    type(status_t), intent(inout) :: status
    shaped = system
    if (allocated(shaped%shapes)) call build_shapes(shaped%shapes, status)
  end subroutine build_system_shapes

  !> Every name defined once and every reference known.
  subroutine check_names(system, status)
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    integer :: k, j
    if (.not. allocated(system%shapes) .or. .not. allocated(system%bodies) .or. &
        .not. allocated(system%contacts)) then
      call set_status(status, STATUS_INVALID_INPUT, 'contact system: shapes, bodies and contacts must be given')
      return
    end if
    if (size(system%contacts) == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'contact system: no contact')
      return
    end if
    do k = 1, size(system%bodies)
      if (system%bodies(k)%name == 'ground') call fail('a body may not be called ''ground'' (the fixed frame)')
      do j = 1, k - 1
        if (system%bodies(j)%name == system%bodies(k)%name) call fail('body '''//system%bodies(k)%name// &
                                                                      ''' is defined twice')
      end do
      if (allocated(system%bodies(k)%solid_of)) then
        if (shape_index(system, system%bodies(k)%solid_of) == 0) call fail('body '''//system%bodies(k)%name// &
          ''': solid_of = '''//system%bodies(k)%solid_of//''' is not a shape'//known_shapes(system))
      end if
    end do
    do k = 1, size(system%shapes)
      do j = 1, k - 1
        if (system%shapes(j)%name == system%shapes(k)%name) call fail('shape '''//system%shapes(k)%name// &
                                                                      ''' is defined twice')
      end do
    end do
    do k = 1, size(system%contacts)
      associate (c => system%contacts(k))
        do j = 1, k - 1
          if (system%contacts(j)%name == c%name) call fail('contact '''//c%name//''' is defined twice')
        end do
        if (body_index(system, c%body_1) < 0) call fail('contact '''//c%name//''': body_1 = '''//c%body_1// &
                                                        ''' is not a body'//known_bodies(system))
        if (body_index(system, c%body_2) <= 0) call fail('contact '''//c%name//''': body_2 = '''//c%body_2// &
                                                         ''' is not a body (the ground cannot be body_2)'// &
                                                         known_bodies(system))
        if (shape_index(system, c%shape_1) == 0) call fail('contact '''//c%name//''': shape_1 = '''// &
                                                           c%shape_1//''' is not a shape'//known_shapes(system))
        if (shape_index(system, c%shape_2) == 0) call fail('contact '''//c%name//''': shape_2 = '''// &
                                                           c%shape_2//''' is not a shape'//known_shapes(system))
        if (c%body_1 == c%body_2) call fail('contact '''//c%name//''': a body cannot touch itself')
        if (c%rolling .and. allocated(c%friction%kind)) call fail('contact '''//c%name//''': a rolling '// &
          'contact has no sliding friction (the no-slip constraint carries the tangential force)')
        if (c%chain == CHAIN_OPEN .and. c%rolling) call fail('contact '''//c%name//''': chain = ''open'' '// &
          'is for sliding contacts; a rolling contact needs the loop (chain = ''loop'')')
        if (c%chain /= CHAIN_AUTO .and. c%level == LEVEL_VELOCITY) call fail('contact '''//c%name// &
          ''': the chain is chosen for position-level contacts only')
      end associate
    end do
  contains
    subroutine fail(text)
      character(len=*), intent(in) :: text
      if (status%ok()) call set_status(status, STATUS_INVALID_INPUT, text)
    end subroutine fail
  end subroutine check_names

  !> Whether a contact is built as the open chain: position level, no
  !> rolling, not chain = loop.
  elemental logical function open_chain(c)
    type(contact_spec_t), intent(in) :: c
    open_chain = c%level == LEVEL_POSITION .and. .not. c%rolling .and. c%chain /= CHAIN_LOOP
  end function open_chain

  !> The size of body k (m): the largest diagonal of the boxes around the
  !> bounded shapes it carries in its contacts, each sampled on a 21 x 21
  !> grid of its parameter domain; 0 if it carries none (a plane, a domain
  !> beyond 1e6): unknown.
  function body_size(system, k) result(length)
    type(contact_system_t), intent(in) :: system
    integer, intent(in) :: k
    real(wp) :: length
    integer :: j
    length = 0
    do j = 1, size(system%contacts)
      associate (c => system%contacts(j))
        if (c%body_1 == system%bodies(k)%name) &
          length = max(length, extent(system%shapes(shape_index(system, c%shape_1))%surface))
        if (c%body_2 == system%bodies(k)%name) &
          length = max(length, extent(system%shapes(shape_index(system, c%shape_2))%surface))
      end associate
    end do
  contains
    real(wp) function extent(surface)
      class(surface_t), intent(in) :: surface
      integer, parameter :: n = 21
      real(wp) :: box(4), u(n), v(n), x(n, n), y(n, n), z(n, n)
      type(status_t) :: st
      integer :: i
      extent = 0
      call surface%domain(box(1), box(2), box(3), box(4))
      if (.not. maxval(abs(box)) < 1e6_wp) return
      u = [(box(1) + (box(2) - box(1))*i/real(n - 1, wp), i = 0, n - 1)]
      v = [(box(3) + (box(4) - box(3))*i/real(n - 1, wp), i = 0, n - 1)]
      call surface%points_on_grid(u, v, x, y, z, st)
      if (.not. st%ok()) return
      extent = norm2([maxval(x) - minval(x), maxval(y) - minval(y), maxval(z) - minval(z)])
    end function extent
  end function body_size

  !> The order in which contact_model builds the contacts: the description's,
  !> except that where bodies fly (`flies`: contacts open and close during a
  !> run, contact_bodies) a closed contact whose body_1 is not placed yet
  !> waits until the contact that carries it is built (the closed set
  !> changes during a run: no one order of the description fits every set;
  !> a body's second closed contact waits for its first),
  !> and a body_1 that no closed contact carries is free (flies_free: built
  !> before the contact). Contacts that still wait (a ring of bodies
  !> carrying each other) come last, where the builder refuses them.
  pure function build_order(system, flies) result(order)
    type(contact_system_t), intent(in) :: system
    logical, intent(in) :: flies
    integer :: order(size(system%contacts))
    logical :: placed(0:size(system%bodies)), done(size(system%contacts))
    integer :: n, k, b1, b2, j
    logical :: progress
    order = [(k, k = 1, size(system%contacts))]
    if (.not. flies) return
    placed = .false.
    placed(0) = .true.
    done = .false.
    n = 0
    progress = .true.
    do while (progress)
      progress = .false.
      do k = 1, size(system%contacts)
        if (done(k)) cycle
        associate (c => system%contacts(k))
          if (.not. c%start_open) then
            b1 = max(0, body_index(system, c%body_1))
            b2 = max(0, body_index(system, c%body_2))
            if (.not. (placed(b1) .or. flies_free(system, b1))) cycle
            ! a body's second closed contact (a loop, contact_loops) after its first
            if (any([(.not. system%contacts(j)%start_open .and. system%contacts(j)%body_2 == c%body_2, &
                      j = 1, k - 1)]) .and. .not. placed(b2)) cycle
            placed(b2) = .true.
          end if
        end associate
        done(k) = .true.
        n = n + 1
        order(n) = k
        progress = .true.
      end do
    end do
    order(n + 1:) = pack([(k, k = 1, size(system%contacts))], .not. done)
  end function build_order

  !> Whether body b flies where bodies may (contact_bodies): no closed
  !> contact carries it (names it body_2). b 0 (the ground): no.
  pure logical function flies_free(system, b)
    type(contact_system_t), intent(in) :: system
    integer, intent(in) :: b
    integer :: k
    flies_free = b > 0
    if (.not. flies_free) return
    do k = 1, size(system%contacts)
      if (.not. system%contacts(k)%start_open .and. system%contacts(k)%body_2 == system%bodies(b)%name) &
        flies_free = .false.
    end do
  end function flies_free

  !> 0 for 'ground', the index of a body, -1 if unknown.
  pure integer function body_index(system, name) result(k)
    type(contact_system_t), intent(in) :: system
    character(len=*), intent(in) :: name
    if (name == 'ground') then
      k = 0
      return
    end if
    do k = 1, size(system%bodies)
      if (system%bodies(k)%name == name) return
    end do
    k = -1
  end function body_index

  pure integer function shape_index(system, name) result(k)
    type(contact_system_t), intent(in) :: system
    character(len=*), intent(in) :: name
    do k = 1, size(system%shapes)
      if (system%shapes(k)%name == name) return
    end do
    k = 0
  end function shape_index

  function known_bodies(system) result(text)
    type(contact_system_t), intent(in) :: system
    character(len=:), allocatable :: text
    integer :: k
    text = '; the bodies are ''ground'''
    do k = 1, size(system%bodies)
      text = text//', '''//system%bodies(k)%name//''''
    end do
  end function known_bodies

  !> '; the shapes are ''a'', ''b''': the shape names for a refusal's message.
  function known_shapes(system) result(text)
    type(contact_system_t), intent(in) :: system
    character(len=:), allocatable :: text
    integer :: k
    text = '; the shapes are '
    do k = 1, size(system%shapes)
      if (k > 1) text = text//', '
      text = text//''''//system%shapes(k)%name//''''
    end do
  end function known_shapes
end module contact_system
