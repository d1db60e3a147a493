!> &point_mass: the mass, where it starts on the surface, gravity and friction.
module io_point_mass_config
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use io_input, only: input_text_t, group_reader_t, open_group, in_range, format_real
  implicit none (type, external)
  private
  public :: point_mass_config_t, read_point_mass_config

  type :: point_mass_config_t
    real(wp) :: mass = 1                           ! kg
    real(wp) :: u0 = 0, v0 = 0                     ! surface coordinates at t = 0
    real(wp) :: du0 = 0, dv0 = 0                   ! their rates at t = 0 (1/s)
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]   ! m/s^2
    character(len=16) :: friction = 'none'         ! none | viscous | coulomb
    real(wp) :: viscous_coefficient = 0            ! N s/m
    real(wp) :: friction_coefficient = 0           ! 1
    real(wp) :: regularization_speed = 1e-9_wp     ! m/s
    real(wp) :: sigma = 1, alpha_u = 1, alpha_v = 0
  end type point_mass_config_t

contains

  subroutine read_point_mass_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(point_mass_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=*), parameter :: names(13) = [character(len=20) :: 'mass', 'u0', 'v0', 'du0', 'dv0', &
      'gravity', 'friction', 'viscous_coefficient', 'friction_coefficient', 'regularization_speed', 'sigma', &
      'alpha_u', 'alpha_v']

    call open_group(input, 'point_mass', names, r, status)
    call r%get('mass', config%mass, in_range(1e-6_wp, 1e6_wp, 'kg'), status)
    call r%get('u0', config%u0, in_range(-1e6_wp, 1e6_wp, 'surface parameter (m on a plane)'), status)
    call r%get('v0', config%v0, in_range(-1e6_wp, 1e6_wp, 'surface parameter (m on a plane)'), status)
    call r%get('du0', config%du0, in_range(-1e3_wp, 1e3_wp, 'surface parameter per s'), status)
    call r%get('dv0', config%dv0, in_range(-1e3_wp, 1e3_wp, 'surface parameter per s'), status)
    call r%get('gravity', config%gravity, in_range(-1e3_wp, 1e3_wp, 'm/s^2'), status)
    call r%get('friction', config%friction, status, choices=[character(len=7) :: 'none', 'viscous', 'coulomb'])
    call r%get('viscous_coefficient', config%viscous_coefficient, in_range(0.0_wp, 1e6_wp, 'N s/m'), status)
    call r%get('friction_coefficient', config%friction_coefficient, in_range(0.0_wp, 10.0_wp, '1'), status)
    call r%get('regularization_speed', config%regularization_speed, in_range(1e-12_wp, 1.0_wp, 'm/s'), status)
    call r%get('sigma', config%sigma, in_range(-1.0_wp, 1.0_wp, '1'), status)
    call r%get('alpha_u', config%alpha_u, in_range(-1e3_wp, 1e3_wp, '1'), status)
    call r%get('alpha_v', config%alpha_v, in_range(-1e3_wp, 1e3_wp, '1'), status)
    if (.not. status%ok()) return
    ! a coefficient the friction law does not use would be silently ignored
    if (config%friction /= 'viscous') call r%refuse_given([character(len=20) :: 'viscous_coefficient'], &
      'friction = '''//trim(config%friction)//''' does not use it (only ''viscous'' does)', status)
    if (config%friction /= 'coulomb') call r%refuse_given([character(len=20) :: 'friction_coefficient', &
      'regularization_speed'], 'friction = '''//trim(config%friction)//''' does not use it (only ''coulomb'' does)', &
      status)
    if (.not. status%ok()) return
    if (abs(config%sigma) /= 1) then
      call r%invalid('sigma', format_real(config%sigma), 'must be +1 or -1 (side of the normal)', status)
    else if (config%alpha_u == 0 .and. config%alpha_v == 0) then
      call r%invalid('alpha_u, alpha_v', '0, 0', 'at least one must be non-zero', status)
    end if
  end subroutine read_point_mass_config
end module io_point_mass_config
