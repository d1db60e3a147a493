!> The shapes and bodies of a contact system, built from their descriptions:
!> a shape is a named surface in its body's coordinates (any surface the
!> geometry layer describes, geometry_surface_description, placed in the body), a
!> body's mass properties are given or those of the homogeneous solid of
!> one of its shapes; a body with a drag_area feels the air's drag
!> (add_air_drag). contact_model builds the mechanism from them.
module contact_factory
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use base_spec, only: spec_t
  use geometry_surface, only: surface_t
  use geometry_solid, only: solid_properties_t, solid_properties
  use geometry_surface_factory, only: surface_from_spec
  use geometry_surface_description, only: surface_description_t, build_surface
  use kinetostatics_mechanism, only: mechanism_t
  use kinetostatics_force_laws, only: new_air_drag
  implicit none (type, external)
  private
  public :: shape_t, body_spec_t, shape_from_spec, body_from_spec, build_shapes, add_air_drag

  real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])

  !> A surface in the coordinates of the body that carries it: given built
  !> (`surface`), or by its `description` (a kind of the geometry's registry
  !> by its spec, or a tube, slide, blended or B-spline surface by its
  !> geometry description, placed in the body), which build_contact_model
  !> builds (build_shapes).
  type :: shape_t
    character(len=:), allocatable :: name
    class(surface_t), allocatable :: surface
    type(surface_description_t) :: description
  end type shape_t

  type :: body_spec_t
    character(len=:), allocatable :: name
    real(wp) :: mass = 1                         ! kg
    character(len=:), allocatable :: solid_of    ! a shape: centre and inertia of its homogeneous solid
    real(wp) :: centre(3) = 0                    ! m, centre of mass (body axes)
    real(wp) :: inertia(3, 3) = 0                ! kg m^2, about the centre (body axes)
    real(wp) :: rotation(3, 3) = identity        ! start orientation (columns: body axes in world)
    real(wp) :: position(3) = 0                  ! m, start origin (world)
    real(wp) :: velocity(3) = 0                  ! m/s, of the origin (world)
    real(wp) :: angular_velocity(3) = 0          ! rad/s (world)
    real(wp) :: drag_area = 0                    ! m^2, C_d A of the air's drag on it (0: none)
  end type body_spec_t

contains

  !> The shape `name` of the surface `spec`, placed in its body by `origin`
  !> (m) and the Cardan angles `angles_deg` (geometry_surface_factory).
  subroutine shape_from_spec(name, spec, shape, status, origin, angles_deg)
    character(len=*), intent(in) :: name
    type(spec_t), intent(in) :: spec
    type(shape_t), intent(out) :: shape
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: origin(3), angles_deg(3)
    shape%name = name
    call surface_from_spec(spec, shape%surface, status, origin, angles_deg)
    if (.not. status%ok()) call prefix_status(status, 'shape '''//name//'''')
  end subroutine shape_from_spec

  !> Builds every shape of `shapes` given by its description (and no surface).
  subroutine build_shapes(shapes, status)
    type(shape_t), intent(inout) :: shapes(:)
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, size(shapes)
      if (.not. status%ok()) return
      if (allocated(shapes(k)%surface)) cycle
      if (.not. (allocated(shapes(k)%description%spec%kind) .or. allocated(shapes(k)%description%geometry))) then
        call set_status(status, STATUS_INVALID_INPUT, 'shape '''//shapes(k)%name//''': neither a surface nor '// &
                        'the description of one is given')
        return
      end if
      call build_surface(shapes(k)%description, shapes(k)%surface, status)
      if (.not. status%ok()) call prefix_status(status, 'shape '''//shapes(k)%name//'''')
    end do
  end subroutine build_shapes

  !> Centre and inertia of the body `spec`: given, or the homogeneous solid
  !> of its shape `solid_of` (one of `shapes`) scaled to the body's mass.
  subroutine body_from_spec(spec, shapes, props, status)
    type(body_spec_t), intent(in) :: spec
    type(shape_t), intent(in) :: shapes(:)
    type(solid_properties_t), intent(out) :: props
    type(status_t), intent(inout) :: status
    type(status_t) :: outward
    integer :: k
    if (.not. status%ok()) return
    if (.not. allocated(spec%solid_of)) then
      props%centre = spec%centre
      props%inertia = spec%inertia
      return
    end if
    k = findloc([(shapes(k)%name == spec%solid_of, k = 1, size(shapes))], .true., dim=1)
    if (k == 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'body '''//spec%name//''': solid_of = '''//spec%solid_of// &
                      ''' is not a shape')
      return
    end if
    ! the solid is the same whichever way r_u x r_v points
    call solid_properties(shapes(k)%surface, 1.0_wp, props, outward)
    if (.not. outward%ok()) call solid_properties(shapes(k)%surface, -1.0_wp, props, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'body '''//spec%name//''': solid_of = '''//spec%solid_of//'''')
      return
    end if
    props%inertia = props%inertia*spec%mass/props%volume
  end subroutine body_from_spec

  !> The air's drag on the body `spec` (kinetostatics_force_laws air_drag_t),
  !> if it has a drag_area: on its frame `frame` at its centre of mass
  !> `centre` (m, the frame's axes), in air of `density` (kg/m^3) moving at
  !> `wind` (m/s, world). Named '<body>.air_drag' both in the closed
  !> contact's mechanism (contact_model) and in the flight's
  !> (contact_flight), so that its work goes on across the phases
  !> (contact_closing).
  subroutine add_air_drag(m, spec, density, wind, frame, centre, status)
    type(mechanism_t), intent(inout) :: m
    type(body_spec_t), intent(in) :: spec
    real(wp), intent(in) :: density, wind(3), centre(3)
    integer, intent(in) :: frame
    type(status_t), intent(inout) :: status
    if (.not. status%ok() .or. spec%drag_area == 0) return
    call m%add_law(new_air_drag(spec%name//'.air_drag', frame, centre, spec%drag_area, density, wind, status))
  end subroutine add_air_drag
end module contact_factory
