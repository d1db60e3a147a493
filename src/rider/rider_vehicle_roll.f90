!> The roll's landing of a vehicle that flew with both contacts open
!> (rider_vehicle_flight, docs/vehicles.md "Flight"): in the air the roll
!> about the bar's axis is a coordinate (six, a free rigid body); on the
!> slide it is held (the sled's model). Where a contact lands the roll's
!> rate stops by a plastic impulse about that axis, before the contact's
!> own impact: the generalized impulse p along the roll's coordinate with
!> M s' = M s + p e_r and s'_r = 0, p = -s_r/(M^-1)_rr, which takes the
!> kinetic energy s_r^2/(2 (M^-1)_rr) (M the mass matrix in the speeds,
!> kinetostatics_point_impact speeds_mass). The roll's angle stays: the
!> vehicle lands with the roll it has and keeps it relative to the slide
!> below its rear.
module rider_vehicle_roll
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_point_impact, only: speeds_mass
  implicit none (type, external)
  private
  public :: stop_coordinate

contains

  !> The plastic impulse along coordinate k of m that stops its rate at
  !> state y = [q, s, ...] (speeds the coordinates' rates): s updated in y
  !> (its k-th exactly 0), the velocities in `work` set; `energy` (J) the
  !> kinetic energy it takes (>= 0).
  subroutine stop_coordinate(m, work, y, k, energy, status)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), intent(inout) :: y(:)
    integer, intent(in) :: k
    real(wp), intent(out) :: energy
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: mass(:, :), minv_e(:, :), s(:)
    integer, allocatable :: ipiv(:)
    integer :: n
    energy = 0
    if (.not. status%ok()) return
    n = m%f
    s = y(n + 1:2*n)
    call m%set_positions(work, y(1:n), status)
    if (.not. status%ok()) return
    mass = speeds_mass(m, work)
    allocate (ipiv(n), minv_e(n, 1))
    minv_e = 0
    minv_e(k, 1) = 1
    call lu_factor(mass, ipiv, status)
    if (status%ok()) call lu_solve(mass, ipiv, minv_e, status)
    if (.not. status%ok() .or. .not. minv_e(k, 1) > 0) then
      call set_status(status, STATUS_DOMAIN, 'the roll''s landing: the mass matrix is singular there')
      return
    end if
    energy = s(k)**2/(2*minv_e(k, 1))
    s = s - s(k)/minv_e(k, 1)*minv_e(:, 1)
    s(k) = 0
    y(n + 1:2*n) = s
    call m%set_velocities(work, s)
  end subroutine stop_coordinate
end module rider_vehicle_roll
