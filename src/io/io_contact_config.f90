!> Input of the contact scenario (docs/contact.md): the groups &contact_model
!> (once), &shape, &body and &contact (each as often as needed), read into the
!> description of contact_model. Every name a contact or body refers to is
!> checked here, with its line; the order of the contacts and whether the
!> loops close are checked when the model is built.
module io_contact_config
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_vector, only: rotation_xyz
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use contact_model, only: contact_system_t, LEVEL_POSITION, LEVEL_VELOCITY, CHAIN_AUTO, CHAIN_OPEN, CHAIN_LOOP
  use contact_system, only: known_shapes
  use io_input, only: input_text_t, group_reader_t, open_group, group_count, format_vector
  use io_friction_config, only: friction_law_variables, friction_law_names, read_friction_law
  use io_surface_config, only: read_surface_config, surface_variables, surface_source_t
  use io_xdmf, only: colon_refusal
  use io_hdf5_objects, only: link_name_refusal
  implicit none (type, external)
  private
  public :: read_contact_config, contact_groups, contact_repeatable_groups

  character(len=*), parameter :: contact_groups(6) = [character(len=14) :: 'run', 'solver', 'contact_model', &
    'shape', 'body', 'contact']
  character(len=*), parameter :: contact_repeatable_groups(3) = [character(len=8) :: 'shape', 'body', 'contact']
  integer, parameter :: name_length = 32

contains

  subroutine read_contact_config(input, system, status, shape_sources)
    type(input_text_t), intent(in) :: input
    type(contact_system_t), intent(out) :: system
    type(status_t), intent(inout) :: status
    type(surface_source_t), allocatable, intent(out), optional :: shape_sources(:)
    type(surface_source_t), allocatable :: sources(:)
    integer :: k
    call read_model_group(input, system, status)
    allocate (system%shapes(group_count(input, 'shape')), system%bodies(group_count(input, 'body')), &
              system%contacts(group_count(input, 'contact')), sources(group_count(input, 'shape')))
    do k = 1, size(system%shapes)
      if (status%ok()) call read_surface_config(input, system%shapes(k)%description, status, sources(k), &
                                                group='shape', occurrence=k, name=system%shapes(k)%name)
      if (status%ok()) call check_shape_name(input, k, system, status)
    end do
    do k = 1, size(system%bodies)
      call read_body(input, k, system, status)
    end do
    do k = 1, size(system%contacts)
      call read_contact(input, k, system, status)
    end do
    call check_air_used(input, system, status)
    if (present(shape_sources)) call move_alloc(sources, shape_sources)
    if (status%ok() .and. size(system%contacts) == 0) call missing('contact', 'a contact scenario needs at '// &
      'least one &contact (body_1 shape_1 touches body_2 shape_2)')
  contains
    subroutine missing(group, why)
      character(len=*), intent(in) :: group, why
      call set_status(status, STATUS_INVALID_INPUT, input%name//': &'//group//' is missing: '//why)
    end subroutine missing
  end subroutine read_contact_config

  subroutine read_model_group(input, system, status)
    type(input_text_t), intent(in) :: input
    type(contact_system_t), intent(inout) :: system
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    call open_group(input, 'contact_model', r, status)
    call r%get('gravity', system%gravity, status)
    call r%get('air_density', system%air_density, status)
    call r%get('wind', system%wind, status)
  end subroutine read_model_group

  !> The air (air_density, wind) is for the drag of bodies with a drag_area:
  !> refused where no body has one (it would go unused).
  subroutine check_air_used(input, system, status)
    type(input_text_t), intent(in) :: input
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    integer :: k
    if (.not. status%ok()) return
    if (any([(system%bodies(k)%drag_area > 0, k = 1, size(system%bodies))])) return
    call open_group(input, 'contact_model', r, status)
    call r%refuse_given([character(len=11) :: 'air_density', 'wind'], 'the air is for the drag of bodies with '// &
                        'a drag_area (&body drag_area = C_d A), and no &body has one', status)
  end subroutine check_air_used

  !> The k-th &body.
  subroutine read_body(input, k, system, status)
    type(input_text_t), intent(in) :: input
    integer, intent(in) :: k
    type(contact_system_t), intent(inout) :: system
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=name_length) :: name, solid_of
    real(wp) :: inertia(3), products(3), angles_deg(3)
    integer :: j
    if (.not. status%ok()) return
    name = ''
    solid_of = ''
    inertia = 0
    products = 0
    angles_deg = 0
    call open_group(input, 'body', r, status, occurrence=k)
    call r%get('name', name, status)
    call r%get('mass', system%bodies(k)%mass, status)
    call r%get('solid_of', solid_of, status)
    call r%get('centre', system%bodies(k)%centre, status)
    call r%get('inertia', inertia, status)
    call r%get('products', products, status)
    call r%get('position', system%bodies(k)%position, status)
    call r%get('angles_deg', angles_deg, status)
    call r%get('velocity', system%bodies(k)%velocity, status)
    call r%get('angular_velocity', system%bodies(k)%angular_velocity, status)
    call r%get('drag_area', system%bodies(k)%drag_area, status)
    if (.not. status%ok()) return
    if (len_trim(name) == 0) then
      call r%invalid('name', '''''', 'every &body needs a name', status)
    else if (trim(name) == 'ground') then
      call r%invalid('name', '''ground''', '''ground'' is the fixed frame; name the body otherwise', status)
    else if (len(colon_refusal(name)) > 0) then
      call r%invalid('name', ''''//trim(name)//'''', 'a body''s name '//colon_refusal(name), status)
    else if (len(link_name_refusal(name)) > 0) then
      call r%invalid('name', ''''//trim(name)//'''', 'a body''s name '//link_name_refusal(name), status)
    end if
    do j = 1, k - 1
      if (status%ok() .and. system%bodies(j)%name == trim(name)) &
        call r%invalid('name', ''''//trim(name)//'''', 'another &body has this name', status)
    end do
    if (.not. status%ok()) return
    system%bodies(k)%name = trim(name)
    if (len_trim(solid_of) > 0) then
      if (.not. any([(system%shapes(j)%name == trim(solid_of), j = 1, size(system%shapes))])) then
        call r%invalid('solid_of', ''''//trim(solid_of)//'''', 'must name a &shape'//known_shapes(system), status)
        return
      end if
      call r%refuse_given([character(len=8) :: 'centre', 'inertia', 'products'], 'solid_of gives the centre '// &
                          'and inertia of the homogeneous solid of the shape', status)
      system%bodies(k)%solid_of = trim(solid_of)
    else
      if (.not. r%has('inertia')) call r%invalid('inertia', 'none', 'give the principal moments (and products) '// &
        'of inertia about the centre, or solid_of = ''<shape>'' for a homogeneous solid', status)
      ! a rigid body's moments about any axes obey I_k <= I_l + I_m (said
      ! here, with the line, rather than by the mass element later)
      if (status%ok() .and. 2*maxval(inertia) > sum(inertia)*(1 + 1e-12_wp)) call r%invalid('inertia', &
        format_vector(inertia), 'the moments of a rigid body obey the triangle inequality I_k <= I_l + I_m', status)
      system%bodies(k)%inertia = reshape([inertia(1), products(1), products(2), products(1), inertia(2), &
                                          products(3), products(2), products(3), inertia(3)], [3, 3])
      if (status%ok()) call check_positive_definite(r, trim(name), inertia, products, status)
    end if
    system%bodies(k)%rotation = rotation_xyz(angles_deg*pi/180)
  end subroutine read_body

  !> The inertia tensor (moments on its diagonal, products off it) must be
  !> positive definite: a body with a zero or negative moment about some axis
  !> has no inertia for a rotation the contact leaves free, and the model
  !> could only say so later, in its coordinates. Sylvester's criterion on
  !> the leading minors; said about `products` where the moments alone are
  !> fine.
  subroutine check_positive_definite(r, name, inertia, products, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: inertia(3), products(3)
    type(status_t), intent(inout) :: status
    real(wp) :: minor_2, det
    character(len=:), allocatable :: why
    ! minor_2, det: the leading 2 x 2 minor and the determinant
    minor_2 = inertia(1)*inertia(2) - products(1)**2
    det = inertia(1)*(inertia(2)*inertia(3) - products(3)**2) - products(1)*(products(1)*inertia(3) - &
          products(3)*products(2)) + products(2)*(products(1)*products(3) - inertia(2)*products(2))
    if (inertia(1) > 0 .and. minor_2 > 0 .and. det > 0) return
    why = 'the inertia tensor of body '''//name//''' (inertia on its diagonal, products off it, kg m^2) '// &
      'must be positive definite: every moment > 0, I_xy^2 < I_xx I_yy and a determinant > 0'
    if (all(inertia > 0) .and. r%has('products')) then
      call r%invalid('products', format_vector(products), why//'; the products are too large for the moments '// &
                     format_vector(inertia), status)
    else
      call r%invalid('inertia', format_vector(inertia), why, status)
    end if
  end subroutine check_positive_definite

  !> The k-th &contact.
  subroutine read_contact(input, k, system, status)
    type(input_text_t), intent(in) :: input
    integer, intent(in) :: k
    type(contact_system_t), intent(inout) :: system
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=name_length) :: name, body_1, shape_1, body_2, shape_2, friction
    character(len=8) :: level, chain, start
    integer :: j
    if (.not. status%ok()) return
    name = ''; body_1 = 'ground'; shape_1 = ''; body_2 = ''; shape_2 = ''
    friction = 'none'
    level = 'position'
    chain = ''
    start = 'closed'
    associate (c => system%contacts(k))
      call open_group(input, 'contact', r, status, occurrence=k, also=friction_law_variables())
      call r%get('name', name, status)
      call r%get('body_1', body_1, status)
      call r%get('shape_1', shape_1, status)
      call r%get('side_1', c%side_1, status)
      call r%get('body_2', body_2, status)
      call r%get('shape_2', shape_2, status)
      call r%get('side_2', c%side_2, status)
      call r%get('friction', friction, status, choices=friction_law_names())
      call r%get('rolling', c%rolling, status)
      call r%get('level', level, status)
      call r%get('chain', chain, status)
      call r%get('start', start, status)
      call r%get('restitution', c%restitution, status)
      call r%get('impact_mu', c%impact_mu, status)
      call r%get('close_speed', c%close_speed, status)
      call r%get('may_open', c%may_open, status)
      if (status%ok() .and. start /= 'open' .and. .not. c%may_open) call r%refuse_given([character(len=11) :: &
        'restitution', 'impact_mu', 'close_speed'], 'the impact law is for a contact that starts open (start = '// &
        '''open'') or may open (may_open = .true.): a closed contact that may not open never lands', status)
      if (status%ok() .and. .not. r%has('restitution')) call r%refuse_given([character(len=11) :: 'impact_mu', &
        'close_speed'], 'without restitution the run ends at the landing: give restitution for impacts', status)
      if (status%ok() .and. .not. r%has('restitution')) c%restitution = -1
      if (.not. status%ok()) return
      if (chain == 'open' .and. c%rolling) call r%invalid('chain', '''open''', 'a rolling contact needs the '// &
        'loop (chain = ''loop'', the default with rolling): the open chain is for sliding contacts', status)
      if (status%ok() .and. len_trim(chain) > 0 .and. level == 'velocity') call r%invalid('chain', ''''// &
        trim(chain)//'''', 'the chain is chosen for level = ''position'' only (a velocity-level contact has '// &
        'its own element)', status)
      if (.not. status%ok()) return
      call read_friction_law(r, trim(friction), c%friction, status)
      if (.not. status%ok()) return
      if (len_trim(name) == 0) call r%invalid('name', '''''', 'every &contact needs a name', status)
      if (status%ok() .and. len(colon_refusal(name)) > 0) &
        call r%invalid('name', ''''//trim(name)//'''', 'a contact''s name '//colon_refusal(name), status)
      if (status%ok() .and. len(link_name_refusal(name)) > 0) &
        call r%invalid('name', ''''//trim(name)//'''', 'a contact''s name '//link_name_refusal(name), status)
      do j = 1, k - 1
        if (status%ok() .and. system%contacts(j)%name == trim(name)) &
          call r%invalid('name', ''''//trim(name)//'''', 'another &contact has this name', status)
      end do
      if (status%ok() .and. abs(c%side_1) /= 1) call r%invalid('side_1', r%written('side_1'), 'must be +1 or '// &
        '-1: the side of shape_1 towards body_2 (the sign of its normal, thesis 3.38)', status)
      if (status%ok() .and. abs(c%side_2) /= 1) call r%invalid('side_2', r%written('side_2'), 'must be +1 or '// &
        '-1: the side of shape_2 towards body_1', status)
      call check_body(r, 'body_1', body_1, system, .true., status)
      call check_body(r, 'body_2', body_2, system, .false., status)
      call check_shape(r, 'shape_1', shape_1, system, status)
      call check_shape(r, 'shape_2', shape_2, system, status)
      if (status%ok() .and. body_1 == body_2) call r%invalid('body_2', ''''//trim(body_2)//'''', &
                                                             'must differ from body_1', status)
      if (status%ok() .and. c%rolling .and. friction /= 'none') call r%invalid('friction', ''''//trim(friction)// &
        '''', 'a rolling contact does not slide: its no-slip constraint carries the tangential force', status)
      if (.not. status%ok()) return
      c%name = trim(name)
      c%body_1 = trim(body_1)
      c%body_2 = trim(body_2)
      c%shape_1 = trim(shape_1)
      c%shape_2 = trim(shape_2)
      c%level = merge(LEVEL_POSITION, LEVEL_VELOCITY, level == 'position')
      select case (trim(chain))
      case ('open')
        c%chain = CHAIN_OPEN
      case ('loop')
        c%chain = CHAIN_LOOP
      case default
        c%chain = CHAIN_AUTO
      end select
      c%start_open = start == 'open'
    end associate
  end subroutine read_contact

  !> The k-th &shape's name is new.
  subroutine check_shape_name(input, k, system, status)
    type(input_text_t), intent(in) :: input
    integer, intent(in) :: k
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    integer :: j
    do j = 1, k - 1
      if (system%shapes(j)%name == system%shapes(k)%name) then
        call open_group(input, 'shape', [character(len=32) :: 'name', 'kind', 'origin', 'angles_deg', &
                        'geometry_file', surface_variables()], r, status, occurrence=k)
        call r%invalid('name', ''''//system%shapes(k)%name//'''', 'another &shape has this name', status)
        return
      end if
    end do
  end subroutine check_shape_name

  subroutine check_body(r, variable, name, system, ground_allowed, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: variable, name
    type(contact_system_t), intent(in) :: system
    logical, intent(in) :: ground_allowed
    type(status_t), intent(inout) :: status
    integer :: j
    character(len=:), allocatable :: list
    if (.not. status%ok()) return
    if (trim(name) == 'ground' .and. ground_allowed) return
    do j = 1, size(system%bodies)
      if (system%bodies(j)%name == trim(name)) return
    end do
    list = ''
    if (ground_allowed) list = ' ''ground'''
    do j = 1, size(system%bodies)
      list = list//' '''//system%bodies(j)%name//''''
    end do
    call r%invalid(variable, ''''//trim(name)//'''', 'must name a &body; the bodies are'//list, status)
  end subroutine check_body

  subroutine check_shape(r, variable, name, system, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: variable, name
    type(contact_system_t), intent(in) :: system
    type(status_t), intent(inout) :: status
    integer :: j
    if (.not. status%ok()) return
    do j = 1, size(system%shapes)
      if (system%shapes(j)%name == trim(name)) return
    end do
    call r%invalid(variable, ''''//trim(name)//'''', 'must name a &shape'//known_shapes(system), status)
  end subroutine check_shape
end module io_contact_config
