!> Set-ups the tests of a flying vehicle share (tests/rider
!> test_vehicle_flight, test_vehicle_one_contact): a ring that may fly with
!> its builds made, its state put in the build of some open contacts, the
!> vehicle's centre of mass in the records, the driver's options.
module vehicle_fixtures
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use numerics_ode, only: ode_options_t
  use numerics_event_driver, only: driver_options_t
  use kinetostatics_models, only: sled_description_t
  use kinetostatics_recorder, only: mechanism_series_t
  use kinetostatics_impact, only: impact_law_t
  use rider_vehicle, only: vehicle_t, VEHICLE_RING
  use rider_vehicle_flight, only: vehicle_flight_ode_t, build_vehicle_flight
  implicit none (type, external)
  private
  public :: flying_ring, on_contacts, centre, quiet_options

contains

  !> A ring with one rider (scale 1) that may fly, landing without friction
  !> with `restitution`: its flight builds on `surface` (sys, ready to run
  !> from q0, qd0), started at rest at u = v = 0 with the heading 0, or at
  !> `start` (u, v, heading) with the rates `start_rate`.
  subroutine flying_ring(surface, restitution, sys, q0, qd0, status, start, start_rate)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: restitution
    type(vehicle_flight_ode_t), intent(inout) :: sys
    real(wp), allocatable, intent(out) :: q0(:), qd0(:)
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: start(3), start_rate(3)
    type(vehicle_t) :: v
    type(sled_description_t) :: d
    v = vehicle_t(VEHICLE_RING, 1, 1.0_wp)
    v%may_fly = .true.
    v%landing = impact_law_t(restitution=restitution, mu=0)
    d%q0 = 0
    d%qd0 = 0
    if (present(start)) d%q0 = start
    if (present(start_rate)) d%qd0 = start_rate
    call build_vehicle_flight(v, d, surface, sys, q0, qd0, status)
  end subroutine flying_ring

  !> The state y of `sys` (its builds made) in the build of the open
  !> contacts `mask` (bit 0 the rear, bit 1 the front; an open one's gap
  !> watched from its opening), from the full layout's q = [u, v, phi,
  !> pitch, rear_lift, roll] and rates qd (a coordinate the build solves or
  !> holds: its entries unused).
  function on_contacts(sys, mask, q, qd) result(y)
    type(vehicle_flight_ode_t), intent(inout) :: sys
    integer, intent(in) :: mask
    real(wp), intent(in) :: q(6), qd(6)
    real(wp), allocatable :: y(:), q_build(:), qd_build(:)
    integer :: k
    sys%mechanism = sys%builds(mask)
    call sys%mechanism%prepare_workspace(sys%work)
    sys%open_mask = mask
    sys%opened = [btest(mask, 0), btest(mask, 1)]
    associate (m => sys%mechanism)
      q_build = [(q(findloc(sys%full, m%q(k), dim=1)), k = 1, m%f)]
      qd_build = [(qd(findloc(sys%full, m%q(k), dim=1)), k = 1, m%f)]
    end associate
    y = sys%initial_state(q_build, qd_build)
  end function on_contacts

  !> The vehicle's centre of mass at record i of s (the bar frame's pose;
  !> com: its place in the bar frame).
  function centre(s, com, i) result(c)
    type(mechanism_series_t), intent(in) :: s
    real(wp), intent(in) :: com(3)
    integer, intent(in) :: i
    real(wp) :: c(3)
    c = s%body_r(:, 1, i) + matmul(s%body_rot(:, :, 1, i), com)
  end function centre

  !> The driver's options of a run to t_end recording every output_step,
  !> with no progress lines.
  function quiet_options(rtol, atol, max_step, t_end, output_step) result(options)
    real(wp), intent(in) :: rtol, atol, max_step, t_end, output_step
    type(driver_options_t) :: options
    options%ode = ode_options_t(rtol=rtol, atol=atol, max_step=max_step)
    options%t_end = t_end
    options%output_step = output_step
    options%progress_seconds = 0
  end function quiet_options
end module vehicle_fixtures
