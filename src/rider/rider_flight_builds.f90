!> The rider's builds for flight and the switch between them (issue 25;
!> docs/rider.md "Flight"): one build of the rider per set of open contacts
!> (rider_model's build_rider with `open` and free_pelvis; the mask's bit
!> k-1 for contact k, 0 for every contact on), and the switch from the
!> build in use to another that carries the ride's state across (use_build):
!> the full layout's state (rider_flight's build_state), every scalar's
!> value (each closure starts there), the laws' switches (the water drag)
!> and the posture the hips hold in flight (rider_hip_hold).
!>
!> The builds are models (kinetostatics_mechanism): the state carried over
!> is written into the integration's workspace after it took the new
!> build's own (prepare_workspace; a build's stamp differs from every
!> other's), never into a build.
!>
!> The records and the extremes see every stretch in the full layout
!> (full_piece: a build's dense output there).
module rider_flight_builds
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use water_field, only: water_field_t
  use kinetostatics_mechanism, only: mechanism_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  use rider_model, only: rider_params_t, rider_layout_t, build_rider, N_CONTACTS
  use rider_flight, only: full_scalars, build_state, set_holds, N_FULL
  implicit none (type, external)
  private
  public :: flight_builds_t, make_flight_builds, use_build

  !> The builds by their open contacts, the one in use and what maps each
  !> into the full layout.
  type :: flight_builds_t
    type(mechanism_t), allocatable :: builds(:)   ! (0:2**N_CONTACTS - 1)
    integer, allocatable :: picks(:, :)   ! (N_FULL, 0:...): each build's coordinates in the full layout
    integer :: open_mask = 0              ! the open contacts of the build in use
    real(wp) :: hold(2) = 0               ! rad, the posture the hips hold in flight (flexion, tilt)
    integer :: flight_size = 0            ! size of a state in the full layout
    integer :: max_r = 0                  ! dependents of the build with every contact on
    real(wp), allocatable :: padded(:, :) ! a dense-output piece in the full layout (full_piece)
  contains
    procedure :: full_piece
  end type flight_builds_t

contains

  !> The builds of the rider `plain` (every contact on, its `layout`) for
  !> each set of open contacts, from the same start.
  subroutine make_flight_builds(params, surface, plain, layout, fly, status, water)
    type(rider_params_t), intent(in) :: params
    class(surface_t), intent(in) :: surface
    type(mechanism_t), intent(in) :: plain
    type(rider_layout_t), intent(in) :: layout
    type(flight_builds_t), intent(out) :: fly
    type(status_t), intent(inout) :: status
    type(water_field_t), intent(in), optional, target :: water
    type(rider_layout_t) :: open_layout
    real(wp) :: q_open(3)
    integer :: i, k, full(N_FULL)
    allocate (fly%builds(0:2**N_CONTACTS - 1), fly%picks(N_FULL, 0:2**N_CONTACTS - 1))
    fly%picks = 0
    fly%builds(0) = plain
    do i = 1, ubound(fly%builds, 1)
      call build_rider(params, surface, fly%builds(i), open_layout, q_open, status, water, &
                       open=[(btest(i, k - 1), k = 1, N_CONTACTS)], free_pelvis=.true.)
      if (.not. status%ok()) return
    end do
    full = full_scalars(layout)
    do i = 0, ubound(fly%builds, 1)
      do k = 1, fly%builds(i)%f
        fly%picks(k, i) = findloc(full, fly%builds(i)%q(k), dim=1)
      end do
    end do
    fly%max_r = fly%builds(0)%r
    fly%flight_size = 2*N_FULL + plain%n_laws
    allocate (fly%padded(fly%flight_size, 0:12))
  end subroutine make_flight_builds

  !> The build of the open contacts `mask` takes over the integration `ode`
  !> at the full layout's state `full` from the build in use: every
  !> scalar's value (its closure starts there; the pelvis's lift, a
  !> constant while it is on, keeps its own), the laws' switches (the water
  !> drag; the hips' holds on in flight), the work integrals. Its positions
  !> and velocities are set at y.
  subroutine use_build(ode, fly, layout, mask, full, y)
    class(mechanism_ode_t), intent(inout) :: ode
    type(flight_builds_t), intent(inout) :: fly
    type(rider_layout_t), intent(in) :: layout
    integer, intent(in) :: mask
    real(wp), intent(in) :: full(:)
    real(wp), allocatable, intent(inout) :: y(:)
    real(wp), allocatable :: y_next(:), values(:)
    logical, allocatable :: active(:)
    type(status_t) :: st
    integer :: k, f
    if (fly%open_mask == 0 .and. mask /= 0) then
      ! a take-off from the slide: the posture to hold is the one here
      fly%hold = [ode%work%scalars(layout%flexion)%q, ode%work%scalars(layout%tilt)%q]
    end if
    values = ode%work%scalars(:)%q
    active = [(ode%work%laws(k)%law%active, k = 1, ode%mechanism%n_laws)]
    ode%mechanism = fly%builds(mask)
    fly%open_mask = mask
    ! the workspace takes the new build's state (another model: its stamp);
    ! then the values, switches and holds carried over are written into it
    ! (the builds are models: nothing written into them would be seen)
    call ode%mechanism%prepare_workspace(ode%work)
    ode%work%scalars(:)%q = values
    do k = 1, size(active)
      ode%work%laws(k)%law%active = active(k)
    end do
    call set_holds(ode%work, layout, mask /= 0, fly%hold)
    ode%work%warm = .false.
    ode%work%converged = .false.
    if (allocated(ode%charts)) deallocate (ode%charts, ode%chart_angle)
    f = ode%mechanism%f
    allocate (y_next(2*f + ode%mechanism%n_laws))
    call build_state(ode%mechanism, layout, full, y_next)
    y = ode%initial_state(y_next(1:f), y_next(f + 1:2*f))
    y(2*f + 1:) = y_next(2*f + 1:)
    call ode%mechanism%set_positions(ode%work, y(1:f), st)
    if (st%ok()) call ode%mechanism%set_velocities(ode%work, y(f + 1:2*f))
  end subroutine use_build

  !> The dense-output piece `taylor` of the build in use (f coordinates) in
  !> the full layout, in padded(:, 0:ubound(taylor, 2)) (the coordinates
  !> of the other builds 0, unused).
  subroutine full_piece(self, f, taylor)
    class(flight_builds_t), intent(inout) :: self
    integer, intent(in) :: f
    real(wp), intent(in) :: taylor(:, 0:)
    integer :: k, i
    do k = 0, ubound(taylor, 2)
      self%padded(:, k) = 0
      do i = 1, f
        self%padded(self%picks(i, self%open_mask), k) = taylor(i, k)
        self%padded(N_FULL + self%picks(i, self%open_mask), k) = taylor(f + i, k)
      end do
      self%padded(2*N_FULL + 1:, k) = taylor(2*f + 1:, k)
    end do
  end subroutine full_piece
end module rider_flight_builds
