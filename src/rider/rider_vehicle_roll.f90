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
!> below its rear. And why such a landing found its contact leaving the
!> slide, where that is known (landing_cause).
module rider_vehicle_roll
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_point_impact, only: speeds_mass
  implicit none (type, external)
  private
  public :: stop_coordinate, landing_cause

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

  !> The cause (words to append to point_impact's "it leaves the slide")
  !> of a landing of contact `name` whose point leaves the slide where its
  !> gap closed, where known: it had not `opened` (risen by opening_gap,
  !> `since` s after its take-off, it sank back by sink_gap m), so the
  !> build it took off from (`held`: both contacts on, the roll held) had
  !> its normal force at zero and the flight's (the roll free) presses it
  !> back; and/or the roll's stop turned its `approach` (m/s, the gap's
  !> rate before it, < 0) into a separation.
  function landing_cause(name, opened, since, sink, held, stopped, approach) result(cause)
    character(len=*), intent(in) :: name
    logical, intent(in) :: opened, held, stopped
    real(wp), intent(in) :: since, sink, approach
    character(len=:), allocatable :: cause
    cause = ''
    if (.not. opened) then
      cause = ': it sank back by '//format_short(sink)//' m '//format_short(since)//' s after its take-off, '// &
              'before it had risen: where it took off its normal force was zero'
      if (held) then
        cause = cause//' with both contacts on and the roll held; in the flight''s build, the roll free (a '// &
                'rigid body on one point contact), the '//name//' presses on: the held roll''s couple lifted it'
      else
        cause = cause//', in the flight''s build it presses on'
      end if
    end if
    if (stopped .and. approach < 0) cause = cause//trim(merge('; and', ':    ', len(cause) > 0))// &
      ' the roll''s stop (both contacts on hold it) turned its approach at '//format_short(-approach)// &
      ' m/s into a separation'
  end function landing_cause
end module rider_vehicle_roll
