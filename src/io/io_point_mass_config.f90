!> &point_mass: the mass, where it starts on the surface, gravity, friction
!> and the air's drag (drag_area, air_density, wind: the declarations of the
!> contact scenario's &body and &contact_model), read into its description (kinetostatics_point_mass), which the
!> kinetostatics layer builds (build_point_mass_model).
!> The friction is any friction law of the core's registry
!> (kinetostatics_force_law_factory), read by its declarations; the law's mu
!> is the variable friction_coefficient here. A regularization_speed left
!> unset is the point mass's own default (build_point_mass_model), not set here.
module io_point_mass_config
  use base_status, only: status_t
  use kinetostatics_point_mass, only: point_mass_description_t
  use io_input, only: input_text_t, group_reader_t, open_group, format_real
  use io_friction_config, only: friction_law_variables, friction_law_names, read_friction_law
  implicit none (type, external)
  private
  public :: read_point_mass_config, point_mass_renamed

  !> The law's parameters under this group's names.
  character(len=*), parameter :: point_mass_renamed(1) = [character(len=23) :: 'mu=friction_coefficient']
  integer, parameter :: name_length = 32

contains

  subroutine read_point_mass_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(point_mass_description_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=name_length) :: friction

    friction = 'none'
    call open_group(input, 'point_mass', r, status, also=friction_law_variables(point_mass_renamed))
    call r%get('mass', config%mass, status)
    call r%get('u0', config%u0, status)
    call r%get('v0', config%v0, status)
    call r%get('du0', config%du0, status)
    call r%get('dv0', config%dv0, status)
    call r%get('gravity', config%gravity, status)
    call r%get('friction', friction, status, choices=friction_law_names())
    call r%get('sigma', config%sigma, status)
    call r%get('alpha_u', config%alpha_u, status)
    call r%get('alpha_v', config%alpha_v, status)
    call r%get('drag_area', config%drag_area, status)
    call r%get('air_density', config%air_density, status)
    call r%get('wind', config%wind, status)
    if (status%ok() .and. config%drag_area == 0) call r%refuse_given([character(len=11) :: 'air_density', &
      'wind'], 'the air is for the mass''s drag: give drag_area (C_d A) too', status)
    if (.not. status%ok()) return
    call read_friction_law(r, trim(friction), config%friction, status, rename=point_mass_renamed)
    if (.not. status%ok()) return
    if (abs(config%sigma) /= 1) then
      call r%invalid('sigma', format_real(config%sigma), 'must be +1 or -1 (side of the normal)', status)
    else if (config%alpha_u == 0 .and. config%alpha_v == 0) then
      call r%invalid('alpha_u, alpha_v', '0, 0', 'at least one must be non-zero', status)
    end if
  end subroutine read_point_mass_config
end module io_point_mass_config
