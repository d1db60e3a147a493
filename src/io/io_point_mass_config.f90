!> &point_mass: the mass, where it starts on the surface, gravity and friction.
module io_point_mass_config
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use io_input, only: input_text_t, namelist_read_error, check_positive, check_nonnegative, &
                      check_finite, check_finite_vector, check_choice, invalid, format_real, lower
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
    real(wp) :: mass, u0, v0, du0, dv0, gravity(3), viscous_coefficient, friction_coefficient, &
                regularization_speed, sigma, alpha_u, alpha_v
    character(len=16) :: friction
    character(len=256) :: msg
    integer :: ios
    character(len=*), parameter :: g = 'point_mass'
    namelist /point_mass/ mass, u0, v0, du0, dv0, gravity, friction, viscous_coefficient, &
      friction_coefficient, regularization_speed, sigma, alpha_u, alpha_v

    mass = config%mass; u0 = config%u0; v0 = config%v0; du0 = config%du0; dv0 = config%dv0
    gravity = config%gravity; friction = config%friction
    viscous_coefficient = config%viscous_coefficient
    friction_coefficient = config%friction_coefficient
    regularization_speed = config%regularization_speed
    sigma = config%sigma; alpha_u = config%alpha_u; alpha_v = config%alpha_v
    read (input%lines, nml=point_mass, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=20) :: 'mass', 'u0', 'v0', 'du0', 'dv0', &
        'gravity', 'friction', 'viscous_coefficient', 'friction_coefficient', &
        'regularization_speed', 'sigma', 'alpha_u', 'alpha_v'], status)
      return
    end if
    call check_positive(input, g, 'mass', mass, 'kg', status)
    call check_finite(input, g, 'u0', u0, status)
    call check_finite(input, g, 'v0', v0, status)
    call check_finite(input, g, 'du0', du0, status)
    call check_finite(input, g, 'dv0', dv0, status)
    call check_finite_vector(input, g, 'gravity', gravity, status)
    call check_choice(input, g, 'friction', friction, [character(len=7) :: 'none', 'viscous', 'coulomb'], status)
    call check_nonnegative(input, g, 'viscous_coefficient', viscous_coefficient, 'N s/m', status)
    call check_nonnegative(input, g, 'friction_coefficient', friction_coefficient, '1', status)
    call check_positive(input, g, 'regularization_speed', regularization_speed, 'm/s', status)
    call check_finite(input, g, 'alpha_u', alpha_u, status)
    call check_finite(input, g, 'alpha_v', alpha_v, status)
    if (status%ok() .and. abs(sigma) /= 1) &
      call invalid(input, g, 'sigma', format_real(sigma), 'must be +1 or -1 (side of the normal)', status)
    if (status%ok() .and. alpha_u == 0 .and. alpha_v == 0) &
      call invalid(input, g, 'alpha_u, alpha_v', '0, 0', 'at least one must be non-zero', status)
    if (.not. status%ok()) return

    config = point_mass_config_t(mass, u0, v0, du0, dv0, gravity, lower(adjustl(friction)), &
      viscous_coefficient, friction_coefficient, regularization_speed, sigma, alpha_u, alpha_v)
  end subroutine read_point_mass_config
end module io_point_mass_config
