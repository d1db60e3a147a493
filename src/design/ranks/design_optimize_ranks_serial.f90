!> The optimisation's ranks in a build without MPI (CMake found none): one
!> rank rides everything, nothing to share. The interface of
!> design_optimize_ranks_mpi.f90.
module design_optimize_ranks
  use base_status, only: status_t
  use design_cuboid_ride, only: cuboid_ride_t
  implicit none (type, external)
  private
  public :: ride_is_mine, share_rides, share_flag

contains

  pure logical function ride_is_mine(i, rank, ranks)
    integer, intent(in) :: i, rank, ranks
    ride_is_mine = mod(i - 1, max(1, ranks)) == rank
  end function ride_is_mine

  subroutine share_rides(rides, statuses, rank, ranks)
    type(cuboid_ride_t), intent(inout) :: rides(:)
    type(status_t), intent(inout) :: statuses(:)
    integer, intent(in) :: rank, ranks
    if (size(rides) < 0 .or. size(statuses) < 0 .or. rank < 0 .or. ranks < 1) return   ! one rank: nothing to share
  end subroutine share_rides
  subroutine share_flag(flag, ranks)
    logical, intent(inout) :: flag
    integer, intent(in) :: ranks
    if (ranks < 1) flag = .false.   ! one rank: its own flag
  end subroutine share_flag
end module design_optimize_ranks
