!> Scenario `sled`: a rigid bar sliding on a surface, rear end on a surface
!> joint (q = u, v, phi), front end held on the surface by a second surface
!> joint and three plane-point closure conditions (beta = pitch, u2, v2), as
!> the rider's legs in thesis (4.27); gravity and Coulomb/viscous friction at
!> both contacts. `vehicle` puts a mat, a ring or a raft with its riders in
!> place of the bar (rider_vehicle).
module scenarios_sled
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use kinetostatics_models, only: sled_description_t
  use rider_vehicle, only: vehicle_t, build_vehicle_model
  use io_input, only: input_text_t, check_known_groups, invalid, format_real, mark_input_failure
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_surface_config, only: read_surface_config, surface_source_t, explain_surface_failure
  use geometry_surface_description, only: surface_description_t, build_surface
  use io_mechanism_config, only: read_sled_config
  use io_geometry_config, only: geometry_groups
  use scenarios_mechanism, only: run_mechanism
  implicit none (type, external)
  private
  public :: run_sled, sled_groups

  character(len=*), parameter :: sled_groups(10) = [character(len=14) :: 'run', 'solver', 'surface', 'sled', &
    geometry_groups]

contains

  subroutine run_sled(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver
    type(sled_description_t) :: config
    type(vehicle_t) :: vehicle
    class(surface_t), allocatable :: surface
    type(mechanism_ode_t), target :: sys
    character(len=:), allocatable :: u_units, v_units
    character(len=8) :: q_units(3), beta_units(3)
    real(wp), allocatable :: q0(:), qd0(:)
    type(surface_description_t) :: surface_description
    type(surface_source_t) :: surface_source
    type(status_t) :: built
    character(len=:), allocatable :: part, variable

    call check_known_groups(input, sled_groups, status)
    if (status%ok()) call read_solver_config(input, solver, status)
    if (status%ok()) call read_surface_config(input, surface_description, status, surface_source)
    if (status%ok()) call build_surface(surface_description, surface, built, part, variable)
    if (status%ok()) call explain_surface_failure(surface_source, built, part, variable, status)
    if (status%ok()) call read_sled_config(input, config, status, vehicle)
    if (.not. status%ok()) return
    if (.not. surface%in_domain(config%q0(1), config%q0(2))) then
      call invalid(input, 'sled', 'u0, v0', format_real(config%q0(1))//', '//format_real(config%q0(2)), &
                   'the start must lie in the parameter domain of the '//surface%describe(), status)
      return
    end if
    call build_vehicle_model(vehicle, config, surface, sys%mechanism, q0, qd0, status)
    call mark_input_failure(status)
    if (.not. status%ok()) return
    call surface%parameter_units(u_units, v_units)
    q_units(1) = u_units; q_units(2) = v_units; q_units(3) = 'rad'   ! u, v, phi
    beta_units(1) = 'rad'; beta_units(2) = u_units; beta_units(3) = v_units   ! pitch, u2, v2
    call run_mechanism('sled', input, run, solver, sys, q0, qd0, q_units, beta_units, status, &
                       surface=surface, start_variables='u0, v0, phi0, du0, dv0, dphi0')
  end subroutine run_sled
end module scenarios_sled
