!> &surface: which surface, its size, and where it sits in space. The kinds
!> with parameters are those of the geometry's registry
!> (geometry_surface_factory: elementary surfaces, sphere, ...), read by their
!> declarations (io_kind_parameters); the surfaces described by their own
!> groups (tube, slide, blended, bspline) are read by io_geometry_config.
!> Nothing is built here: the reader returns the geometry layer's
!> surface_description_t, which the caller builds (build_surface), and a
!> surface_source_t that names the lines of a failure of that build
!> (explain_surface_failure).
module io_surface_config
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t
  use geometry_surface_kind, only: surface_kind_t
  use geometry_surface_factory, only: surface_kinds, surface_kind_index
  use geometry_surface_description, only: surface_description_t
  use io_input, only: input_text_t, group_reader_t, open_group, load_input_file, group_present, &
                      check_known_groups, where_given, format_real
  use io_kind_parameters, only: read_kind_parameters, refuse_other_parameters, parameter_variables
  use io_geometry_config, only: read_geometry_description, explain_geometry_failure, geometry_groups, &
    geometry_file_groups
  implicit none (type, external)
  private
  public :: read_surface_config, surface_variables, surface_kind_names, surface_source_t, explain_surface_failure
  public :: start_domain_words

  integer, parameter :: name_length = 32

  !> Where a surface description was read, to name the line of a failure of
  !> its build: the &surface (&shape) group's kind and origin, and the input
  !> of the geometry groups (this input or the geometry_file).
  type :: surface_source_t
    character(len=:), allocatable :: at_kind, at_origin
    logical :: geometry = .false.                 !< described by the geometry groups
    type(input_text_t) :: geometry_input
    character(len=:), allocatable :: geometry_file_prefix   !< '' when the groups are in this input
    character(len=:), allocatable :: bspline_file
  end type surface_source_t

contains

  !> The description of the surface of &surface, placed by `origin` and the Cardan
  !> angles `angles_deg` (r -> origin + Rx Ry Rz r). The kinds tube, slide,
  !> blended and bspline are described by the geometry groups (&centerline,
  !> &cross_section, &slide_elements, &blended, &bspline; io_geometry_config),
  !> given in this input or in the file `geometry_file` (relative to this
  !> input's folder), not both. Named surfaces (the shapes of the contact
  !> scenario) are read from the occurrence-th of the repeatable group `group`
  !> with a required `name` (returned). `described_as` says which surface it is
  !> and from which file, for reports ('slide of standard elements from
  !> inputs/demo_slide/slide.nml'). `source` is for explain_surface_failure.
  subroutine read_surface_config(input, description, status, source, group, occurrence, name, described_as)
    type(input_text_t), intent(in) :: input
    type(surface_description_t), intent(out) :: description
    type(status_t), intent(inout) :: status
    type(surface_source_t), intent(out) :: source
    character(len=*), intent(in), optional :: group
    integer, intent(in), optional :: occurrence
    character(len=:), allocatable, intent(out), optional :: name
    character(len=:), allocatable, intent(out), optional :: described_as
    character(len=32) :: given_name
    character(len=name_length) :: kind
    character(len=4096) :: geometry_file
    type(input_text_t) :: geometry_input
    real(wp) :: origin(3), angles_deg(3)
    type(group_reader_t) :: r
    type(surface_kind_t), allocatable :: kinds(:)
    integer :: i
    character(len=:), allocatable :: g
    character(len=name_length), allocatable :: kind_variables(:), kind_names(:)

    g = 'surface'
    if (present(group)) g = group
    kinds = surface_kinds()
    kind_variables = surface_variables()
    kind_names = surface_kind_names()
    kind = 'plane'
    geometry_file = ''
    origin = 0; angles_deg = 0
    call open_group(input, g, r, status, occurrence, also=kind_variables)
    if (present(name)) then
      given_name = ''
      call r%get('name', given_name, status)
      if (status%ok() .and. len_trim(given_name) == 0) call r%invalid('name', '''''', 'every &'//g// &
                                                                      ' needs a name', status)
      name = trim(given_name)
    end if
    call r%get('kind', kind, status, choices=kind_names)
    call r%get('origin', origin, status)
    call r%get('angles_deg', angles_deg, status)
    if (.not. status%ok()) return
    ! a value the kind does not use is refused (it would be silently ignored)
    if (any(kind == geometry_kinds_here())) then
      call r%refuse_given(kind_variables, 'kind = '''//trim(kind)//''' is described by its own groups and '// &
                          'does not use it', status)
    else
      call refuse_other_parameters(r, 'kind', trim(kind), kinds(surface_kind_index(trim(kind)))%parameters, &
                                   kind_variables, status)
      call r%refuse_given([character(len=13) :: 'geometry_file'], &
                          'geometry_file describes a tube, slide, blended or bspline surface', status)
    end if
    if (.not. status%ok()) return

    if (.not. any(kind == geometry_kinds_here())) then
      do i = 1, size(geometry_groups)
        if (group_present(input, geometry_groups(i))) then
          if (r%present) then
            call set_status(status, STATUS_INVALID_INPUT, where_given(input, geometry_groups(i), '')//': &'// &
                            trim(geometry_groups(i))//' is read only by a tube, slide, blended or bspline '// &
                            'surface, and &'//g//' kind = '''//trim(kind)//''' ('//r%where('kind')// &
                            ') is none: remove the group or change kind')
          else
            call set_status(status, STATUS_INVALID_INPUT, where_given(input, geometry_groups(i), '')//': &'// &
                            trim(geometry_groups(i))//' is read only through &'//g//' kind = '// &
                            selecting_kind(geometry_groups(i))//', and this input has no &'//g// &
                            ' (its surface is the default plane): add &'//g//' kind = '// &
                            selecting_kind(geometry_groups(i))//' or remove the group')
          end if
          return
        end if
      end do
    end if
    select case (trim(kind))
    case default   ! a kind of the registry, by its parameters' declarations
      call read_kind_parameters(r, 'kind', trim(kind), kinds(surface_kind_index(trim(kind)))%parameters, &
                                description%spec, status)
    case ('tube', 'slide', 'blended', 'bspline')
      call r%get('geometry_file', geometry_file, status)
      if (.not. status%ok()) return
      if (len_trim(geometry_file) == 0) then
        if (.not. group_present(input, needed_group(kind))) then
          call r%invalid('kind', ''''//trim(kind)//'''', 'needs its geometry: &'//needed_group(kind)// &
                         ' in this input, or geometry_file = ''<file with the geometry groups>''', status)
          return
        end if
        allocate (description%geometry)
        call read_geometry_description(input, description%geometry, status, trim(kind), source%bspline_file)
        source%geometry = .true.
        source%geometry_input = input
        source%geometry_file_prefix = ''
        if (present(described_as)) described_as = kind_words(kind)//' from '//input%name
      else
        do i = 1, size(geometry_groups)
          if (group_present(input, geometry_groups(i))) then
            call set_status(status, STATUS_INVALID_INPUT, where_given(input, geometry_groups(i), '')//': &'// &
                            trim(geometry_groups(i))//' is not read: &'//g//' geometry_file = '''// &
                            trim(geometry_file)//''' ('//r%where('geometry_file')//') gives the geometry; '// &
                            'give it either in this input or in geometry_file, not both')
            return
          end if
        end do
        call load_input_file(input%resolve_path(geometry_file), geometry_input, status)
        if (status%ok()) call check_known_groups(geometry_input, geometry_file_groups, status)
        if (status%ok()) call check_geometry_file_run(geometry_input, status)
        ! a file without the geometry (empty, /dev/null, another scenario's
        ! input) is named as such, not read as a geometry of defaults
        if (status%ok()) then   ! (nested: Fortran does not short-circuit .and.)
          if (size(geometry_input%groups) == 0) then
            call set_status(status, STATUS_INVALID_INPUT, geometry_input%name//' is empty: it has no namelist '// &
                            'groups (a geometry file holds &'//needed_group(kind)//' and the groups with it)')
          else if (.not. group_present(geometry_input, needed_group(kind))) then
            call set_status(status, STATUS_INVALID_INPUT, geometry_input%name//' has no &'//needed_group(kind)// &
                            ', which a '//trim(kind)//' surface needs')
          end if
        end if
        allocate (description%geometry)
        if (status%ok()) call read_geometry_description(geometry_input, description%geometry, status, trim(kind), &
                                                        source%bspline_file)
        if (present(described_as)) described_as = kind_words(kind)//' from '//geometry_input%name
        source%geometry = .true.
        source%geometry_file_prefix = r%where('geometry_file')//': &'//g//': geometry_file = '''// &
                                      trim(geometry_file)//''''
        if (.not. status%ok()) then
          call prefix_status(status, source%geometry_file_prefix)
          return
        end if
        source%geometry_input = geometry_input
      end if
    end select
    if (.not. status%ok()) return
    if (present(described_as)) then
      if (.not. allocated(described_as)) described_as = kind_words(kind)//' of &'//g//' in '//input%name
    end if
    description%origin = origin
    description%angles_deg = angles_deg
    source%at_kind = r%where('kind')//': &'//g
    source%at_origin = r%where('origin')//': &'//g
  end subroutine read_surface_config

  !> The failure `built` of building the surface read from `source`
  !> (build_surface's `part` and `variable`) put in `status`, naming the line
  !> at fault: the &surface (&shape) kind or origin, or the geometry group.
  !> Nothing when `built` is ok.
  subroutine explain_surface_failure(source, built, part, variable, status)
    type(surface_source_t), intent(in) :: source
    type(status_t), intent(in) :: built
    character(len=*), intent(in) :: part, variable
    type(status_t), intent(inout) :: status
    if (built%ok()) return
    if (part == 'origin' .or. .not. source%geometry) then
      status = built
      status%code = STATUS_INVALID_INPUT
      if (part == 'origin') then
        call prefix_status(status, source%at_origin)
      else
        call prefix_status(status, source%at_kind)
      end if
      return
    end if
    call explain_geometry_failure(source%geometry_input, built, part, variable, source%bspline_file, status)
    if (len(source%geometry_file_prefix) > 0) call prefix_status(status, source%geometry_file_prefix)
  end subroutine explain_surface_failure

  !> What a start (u0, v0) outside `surface`'s domain is refused with: the
  !> domain's bounds (a slide of elements: u its horizontal length with
  !> centerline_kind = 'exact', docs/geometry.md; not the arc length).
  function start_domain_words(surface) result(words)
    class(surface_t), intent(in) :: surface
    character(len=:), allocatable :: words
    real(wp) :: u_min, u_max, v_min, v_max
    call surface%domain(u_min, u_max, v_min, v_max)
    words = 'the start must lie in the parameter domain of the '//surface%describe()//': u '// &
            bounds_words(u_min, u_max, surface%periodic_u())//', v '//bounds_words(v_min, v_max, surface%periodic_v())
  contains
    function bounds_words(low, high, periodic) result(text)
      real(wp), intent(in) :: low, high
      logical, intent(in) :: periodic
      character(len=:), allocatable :: text
      if (periodic) then
        text = 'any (periodic)'
      else if (low <= -huge(1.0_wp) .and. high >= huge(1.0_wp)) then
        text = 'any'
      else
        text = 'in ['//format_real(low)//', '//format_real(high)//']'
      end if
    end function bounds_words
  end function start_domain_words

  !> The variables of every registered surface kind's parameters (the names
  !> a &surface or &shape may hold beside kind, origin, angles_deg, geometry_file).
  function surface_variables() result(variables)
    character(len=name_length), allocatable :: variables(:)
    type(surface_kind_t), allocatable :: kinds(:)
    integer :: i
    kinds = surface_kinds()
    allocate (variables(0))
    do i = 1, size(kinds)
      call parameter_variables(kinds(i)%parameters, variables)
    end do
  end function surface_variables

  !> A geometry file may be a complete input of the geometry scenario (the
  !> demo slide is): its &run and &grid are for running it on its own. A
  !> &run naming another scenario says the file is not a geometry file (the
  !> water input named where its slide was meant): refused, not half read.
  subroutine check_geometry_file_run(geometry_input, status)
    type(input_text_t), intent(in) :: geometry_input
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=32) :: scenario
    scenario = 'geometry'
    call open_group(geometry_input, 'run', r, status)
    call r%get('scenario', scenario, status)
    if (status%ok() .and. trim(scenario) /= 'geometry') &
      call r%invalid('scenario', ''''//trim(scenario)//'''', 'a geometry file holds the geometry groups '// &
                     '(&run, if any, with scenario = ''geometry''); this is an input of another scenario', status)
  end subroutine check_geometry_file_run

  !> The kind of surface in words, for reports.
  pure function kind_words(kind) result(words)
    character(len=*), intent(in) :: kind
    character(len=:), allocatable :: words
    select case (trim(kind))
    case ('tube'); words = 'tube around a &centerline'
    case ('slide'); words = 'slide of standard elements (&slide_elements)'
    case ('blended'); words = 'blended surface'
    case ('bspline'); words = 'B-spline surface'
    case default; words = trim(kind)
    end select
  end function kind_words

  !> The &surface kind that reads a geometry group, for messages.
  pure function selecting_kind(group) result(kind)
    character(len=*), intent(in) :: group
    character(len=:), allocatable :: kind
    select case (trim(group))
    case ('centerline'); kind = '''tube'''
    case ('slide_elements'); kind = '''slide'''
    case ('cross_section'); kind = '''slide'' or ''tube'''
    case ('blended'); kind = '''blended'''
    case ('bspline'); kind = '''bspline'''
    case default; kind = '''slide'', ''tube'', ''blended'' or ''bspline'''
    end select
  end function selecting_kind

  !> The group that describes a surface of this kind.
  pure function needed_group(kind) result(group)
    character(len=*), intent(in) :: kind
    character(len=:), allocatable :: group
    select case (trim(kind))
    case ('tube'); group = 'centerline'
    case ('slide'); group = 'slide_elements'
    case default; group = trim(kind)
    end select
  end function needed_group

  !> The words `kind` may take: the kinds of the registry, then those
  !> described by the geometry groups.
  function surface_kind_names() result(names)
    character(len=name_length), allocatable :: names(:)
    type(surface_kind_t), allocatable :: kinds(:)
    integer :: i
    kinds = surface_kinds()
    names = [character(len=name_length) :: (kinds(i)%name, i = 1, size(kinds)), geometry_kinds_here()]
  end function surface_kind_names

  pure function geometry_kinds_here() result(kinds)
    character(len=8) :: kinds(4)
    kinds = [character(len=8) :: 'tube', 'slide', 'blended', 'bspline']
  end function geometry_kinds_here
end module io_surface_config
