!> The sweep's ranks in a build without MPI (CMake found none): one rank,
!> nothing to gather. The interface of design_sweep_ranks_mpi.f90.
module design_sweep_ranks
  use design_sweep, only: sweep_result_t
  implicit none (type, external)
  private
  public :: start_ranks, gather_rides, finish_ranks, ranks_built

  logical, parameter :: ranks_built = .false.

contains

  subroutine start_ranks(rank, ranks, started)
    integer, intent(out) :: rank, ranks
    logical, intent(out) :: started
    rank = 0
    ranks = 1
    started = .false.
  end subroutine start_ranks

  subroutine gather_rides(result, rank, ranks)
    type(sweep_result_t), intent(inout) :: result
    integer, intent(in) :: rank, ranks
    if (rank < 0 .or. ranks < 1 .or. result%n < 0) return   ! nothing to gather with one rank
  end subroutine gather_rides

  subroutine finish_ranks(started)
    logical, intent(in) :: started
    if (started) return
  end subroutine finish_ranks
end module design_sweep_ranks
