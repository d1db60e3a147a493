!> A body in free flight in a contact mechanism (issue 25): it hangs from the
!> ground by three prismatic joints along the world axes (the origin of its
!> frame) and a free rotation (kinetostatics_free_rotation, its chart centred
!> on the start pose), and carries its mass element under gravity and its
!> air drag (contact_factory add_air_drag). Its coordinates are the origin
!> (x, y, z) and the rotation's angles, its speeds their rates. Used by the
!> flight of free bodies (contact_flight) and by a mechanism where some
!> bodies are carried by closed contacts and others fly (contact_model).
module contact_free_body
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_solid, only: solid_properties_t
  use kinetostatics_joints, only: new_prismatic
  use kinetostatics_free_rotation, only: new_free_rotation
  use kinetostatics_mass, only: new_mass_element
  use kinetostatics_mechanism, only: mechanism_t
  use contact_factory, only: body_spec_t, add_air_drag
  implicit none (type, external)
  private
  public :: add_free_body, free_body_units

  real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  !> The units of a free body's six coordinates.
  character(len=8), parameter :: free_body_units(6) = [character(len=8) :: 'm', 'm', 'm', 'rad', 'rad', 'rad']

contains

  !> The body `spec` (its mass properties `props`) free in `m`, at its given
  !> position (the prismatic coordinates) and rotation (the free rotation's
  !> chart centred there, its angles 0): coordinates its scalars x, y, z,
  !> a1, a2, a3; body_frame its frame; rotation_element the free rotation.
  subroutine add_free_body(m, spec, props, gravity, air_density, wind, coordinates, body_frame, rotation_element, &
                           status)
    type(mechanism_t), intent(inout) :: m
    type(body_spec_t), intent(in) :: spec
    type(solid_properties_t), intent(in) :: props
    real(wp), intent(in) :: gravity(3), air_density, wind(3)
    integer, intent(out) :: coordinates(6), body_frame, rotation_element
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: axis_name(3) = ['x', 'y', 'z']
    real(wp), parameter :: axes(3, 3) = identity
    integer :: frames(4), i
    character(len=:), allocatable :: body
    body = spec%name
    frames(1) = 1   ! the ground
    do i = 1, 3
      frames(i + 1) = m%add_frame(body//'.'//axis_name(i))
      coordinates(i) = m%add_scalar(body//'.'//axis_name(i), spec%position(i))
      call m%add_element(new_prismatic(body//'.'//axis_name(i), frames(i), frames(i + 1), coordinates(i), &
                                       axes(:, i)))
    end do
    do i = 1, 3
      coordinates(3 + i) = m%add_scalar(body//'.a'//achar(iachar('0') + i), 0.0_wp)
    end do
    body_frame = m%add_frame(body)
    call m%add_element(new_free_rotation(body//'.rotation', frames(4), body_frame, coordinates(4:6), &
                                         [0.0_wp, 0.0_wp, 1.0_wp], spec%rotation))
    rotation_element = m%n_elements
    call m%add_element(new_mass_element(body, body_frame, spec%mass, props%inertia, props%centre, gravity, status))
    call add_air_drag(m, spec, air_density, wind, body_frame, props%centre, status)
  end subroutine add_free_body
end module contact_free_body
