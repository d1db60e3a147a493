!> A ride's records (rider_ride): the pelvis, the rider and each contact at
!> every record, grown as the ride goes (base_series). Every array is listed
!> in size_series and move_series once, so growing and moving keep them all.
module rider_series
  use base_kinds, only: wp
  use base_series, only: growable_series_t, resize
  use rider_extremes, only: ride_extremes_t
  use rider_model, only: N_CONTACTS
  implicit none (type, external)
  private
  public :: contact_series_t, ride_series_t, size_series, move_series, values_per_record

  !> One contact over the ride (n samples).
  type :: contact_series_t
    real(wp), allocatable :: u(:), v(:)                 ! surface parameters
    real(wp), allocatable :: arc_length(:)              ! m, centerline arc length at u
    real(wp), allocatable :: wall_angle(:)              ! rad, normal's angle from the bottom's (+ towards +v)
    real(wp), allocatable :: wall_distance(:)           ! m, along the section from v = pi/2 (+ towards +v)
    real(wp), allocatable :: position(:, :), velocity(:, :)   ! 3 x n: m, m/s
    real(wp), allocatable :: normal_force(:)            ! N
    real(wp), allocatable :: friction_force(:, :)       ! 3 x n, N
    real(wp), allocatable :: drag_force(:, :)           ! 3 x n, N
    integer, allocatable :: in_water(:)                 ! 1: between the water's edges
    real(wp), allocatable :: reynolds(:), drag_coefficient(:), projected_area(:)   ! 1, 1, m^2 (0 when dry)
    real(wp), allocatable :: relative_velocity(:, :)    ! 3 x n, m/s: contact minus water (0 when dry)
  end type contact_series_t

  !> Numbers of one record of ride_series_t besides the state (the arrays
  !> below: 32 of the pelvis and the rider, 25 per contact), for the memory bound.
  integer, parameter :: values_per_record = 32 + 25*N_CONTACTS

  !> The ride's records; grown as the ride goes (base_series).
  type, extends(growable_series_t) :: ride_series_t
    real(wp), allocatable :: time(:)                    ! s
    integer, allocatable :: kind(:)                     ! RECORD_START, _OUTPUT, _EVENT
    real(wp), allocatable :: state(:, :)                ! the integrator's state y = [q, q', W] (a ride can
                                                        ! be restarted from any record); with may_fly in
                                                        ! the heels' flight layout (flight_layout_state)
    real(wp), allocatable :: arc_length(:)              ! m, of the pelvis
    real(wp), allocatable :: speed(:)                   ! m/s, of the pelvis contact
    real(wp), allocatable :: heading(:), phi_legs(:), phi_trunk(:)   ! rad
    real(wp), allocatable :: pelvis_acceleration(:, :)  ! 3 x n, m/s^2: of the pelvis's centre of mass
    real(wp), allocatable :: pelvis_axes(:, :, :)       ! 3 x 3 x n: x (to the feet), y (left), z (normal)
    real(wp), allocatable :: reaction_force(:, :)       ! 3 x n, N: the slide's reaction on the rider at the pelvis
    real(wp), allocatable :: reaction_moment(:, :)      ! 3 x n, N m: ... its moment about the pelvis contact
    real(wp), allocatable :: kinetic(:), potential(:), energy(:)    ! J
    real(wp), allocatable :: friction_work(:), drag_work(:)          ! J (negative: taken out)
    real(wp), allocatable :: closure_residual(:)        ! m
    integer, allocatable :: airborne(:)                 ! the open contacts: bit k-1 for contact k (may_fly; else 0)
    type(contact_series_t) :: contact(N_CONTACTS)
    type(ride_extremes_t) :: extremes                   ! the report's extremes, located between the records
  end type ride_series_t

contains

  !> Room for `capacity` records in every array of the series, the recorded
  !> ones kept (first call: allocates). Every array of ride_series_t is listed
  !> here once, so growing keeps them all.
  subroutine size_series(s, capacity, state_size)
    type(ride_series_t), intent(inout) :: s
    integer, intent(in) :: capacity, state_size
    integer :: k, n
    n = capacity
    call resize(s%time, n); call resize(s%kind, n); call resize(s%state, state_size, n)
    call resize(s%arc_length, n); call resize(s%speed, n); call resize(s%heading, n)
    call resize(s%phi_legs, n); call resize(s%phi_trunk, n); call resize(s%pelvis_acceleration, 3, n)
    call resize(s%pelvis_axes, 3, 3, n); call resize(s%reaction_force, 3, n); call resize(s%reaction_moment, 3, n)
    call resize(s%kinetic, n); call resize(s%potential, n); call resize(s%energy, n)
    call resize(s%friction_work, n); call resize(s%drag_work, n); call resize(s%closure_residual, n)
    call resize(s%airborne, n)
    do k = 1, N_CONTACTS
      associate (c => s%contact(k))
        call resize(c%u, n); call resize(c%v, n); call resize(c%arc_length, n); call resize(c%wall_angle, n)
        call resize(c%wall_distance, n); call resize(c%position, 3, n); call resize(c%velocity, 3, n)
        call resize(c%normal_force, n); call resize(c%friction_force, 3, n); call resize(c%drag_force, 3, n)
        call resize(c%in_water, n); call resize(c%reynolds, n); call resize(c%drag_coefficient, n)
        call resize(c%projected_area, n); call resize(c%relative_velocity, 3, n)
      end associate
    end do
    s%capacity = capacity
  end subroutine size_series

  !> Moves every array of a into b (a is left empty).
  subroutine move_series(a, b)
    type(ride_series_t), intent(inout) :: a, b
    integer :: k
    b%n = a%n
    b%capacity = a%capacity
    if (allocated(a%time)) call move_alloc(a%time, b%time)
    call move_alloc(a%kind, b%kind); call move_alloc(a%state, b%state); call move_alloc(a%arc_length, b%arc_length)
    call move_alloc(a%speed, b%speed); call move_alloc(a%heading, b%heading)
    call move_alloc(a%phi_legs, b%phi_legs); call move_alloc(a%phi_trunk, b%phi_trunk)
    call move_alloc(a%pelvis_acceleration, b%pelvis_acceleration); call move_alloc(a%pelvis_axes, b%pelvis_axes)
    call move_alloc(a%reaction_force, b%reaction_force); call move_alloc(a%reaction_moment, b%reaction_moment)
    call move_alloc(a%kinetic, b%kinetic); call move_alloc(a%potential, b%potential)
    call move_alloc(a%energy, b%energy); call move_alloc(a%friction_work, b%friction_work)
    call move_alloc(a%drag_work, b%drag_work); call move_alloc(a%closure_residual, b%closure_residual)
    call move_alloc(a%airborne, b%airborne)
    do k = 1, N_CONTACTS
      associate (x => a%contact(k), y => b%contact(k))
        call move_alloc(x%u, y%u); call move_alloc(x%v, y%v); call move_alloc(x%arc_length, y%arc_length)
        call move_alloc(x%wall_angle, y%wall_angle); call move_alloc(x%wall_distance, y%wall_distance)
        call move_alloc(x%position, y%position); call move_alloc(x%velocity, y%velocity)
        call move_alloc(x%normal_force, y%normal_force); call move_alloc(x%friction_force, y%friction_force)
        call move_alloc(x%drag_force, y%drag_force); call move_alloc(x%in_water, y%in_water)
        call move_alloc(x%reynolds, y%reynolds); call move_alloc(x%drag_coefficient, y%drag_coefficient)
        call move_alloc(x%projected_area, y%projected_area); call move_alloc(x%relative_velocity, y%relative_velocity)
      end associate
    end do
    b%extremes = a%extremes
  end subroutine move_series
end module rider_series
