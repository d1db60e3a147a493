!> A sweep's rides shared among MPI ranks (built when CMake finds MPI; the
!> same module without MPI: design_sweep_ranks_serial.f90). Ride i belongs to
!> rank mod(i - 1, ranks) (design_sweep's rides_of_rank); rank 0 gathers every
!> rank's rides and is the one writer. MPI is started only when an MPI
!> launcher started the process (mpirun, srun: it sets OMPI_COMM_WORLD_SIZE,
!> PMI_SIZE or PMIX_RANK), so a plain `slidesim sweep.nml` does not pay
!> MPI's start-up; only the thread that calls these routines uses MPI
!> (MPI_THREAD_FUNNELED: the rides' OpenMP threads never call MPI).
module design_sweep_ranks
  use, intrinsic :: iso_c_binding, only: c_int
  use mpi_f08, only: MPI_Init_thread, MPI_Initialized, MPI_Finalize, MPI_Finalized, MPI_Comm_rank, &
    MPI_Comm_size, MPI_Send, MPI_Recv, MPI_Ibarrier, MPI_Test, MPI_Request, MPI_COMM_WORLD, MPI_THREAD_FUNNELED, &
    MPI_INTEGER, MPI_DOUBLE_PRECISION, MPI_CHARACTER, MPI_STATUS_IGNORE
  use design_sweep, only: sweep_result_t, message_length, rides_of_rank
  implicit none (type, external)
  private
  public :: start_ranks, gather_rides, finish_ranks, ranks_built

  !> whether this build can run under MPI
  logical, parameter :: ranks_built = .true.

  interface
    !> POSIX: sleep for `microseconds`
    function c_usleep(microseconds) bind(C, name='usleep') result(rc)
      import :: c_int
      integer(c_int), value :: microseconds
      integer(c_int) :: rc
    end function c_usleep
  end interface

contains

  !> This process's rank and the number of ranks (0 and 1 when not started
  !> by an MPI launcher). `started`: MPI was started here (finish_ranks ends it).
  subroutine start_ranks(rank, ranks, started)
    integer, intent(out) :: rank, ranks
    logical, intent(out) :: started
    logical :: running
    integer :: provided
    rank = 0
    ranks = 1
    started = .false.
    if (.not. launched()) return
    call MPI_Initialized(running)
    if (.not. running) then
      call MPI_Init_thread(MPI_THREAD_FUNNELED, provided)
      started = .true.
    end if
    call MPI_Comm_rank(MPI_COMM_WORLD, rank)
    call MPI_Comm_size(MPI_COMM_WORLD, ranks)
  end subroutine start_ranks

  logical function launched()
    character(len=16) :: value
    integer :: length, k
    character(len=*), parameter :: names(3) = [character(len=20) :: 'OMPI_COMM_WORLD_SIZE', 'PMI_SIZE', &
      'PMIX_RANK']
    launched = .false.
    do k = 1, size(names)
      call get_environment_variable(trim(names(k)), value, length)
      if (length > 0) launched = .true.
    end do
  end function launched

  !> Rank 0 receives the rides of every other rank into `result` (which
  !> holds its own); the others send theirs. Water times: the largest of the
  !> ranks that computed the water.
  subroutine gather_rides(result, rank, ranks)
    type(sweep_result_t), intent(inout) :: result
    integer, intent(in) :: rank, ranks
    type(sweep_result_t) :: other
    type(MPI_Request) :: request
    logical, allocatable :: theirs(:)
    logical :: everyone
    integer :: r, n, nl, nw
    integer(c_int) :: slept
    if (ranks < 2) return
    ! Wait for the slowest rank asleep, not in MPI's busy polling: a rank
    ! that is done would otherwise take a core from those still riding.
    call MPI_Ibarrier(MPI_COMM_WORLD, request)
    do
      call MPI_Test(request, everyone, MPI_STATUS_IGNORE)
      if (everyone) exit
      slept = c_usleep(20000_c_int)   ! 20 ms; woken early (a signal) it just tests again
    end do
    n = result%n
    nl = size(result%verdict, 1)
    nw = size(result%water_seconds)
    if (rank /= 0) then
      call MPI_Send(result%status, n, MPI_INTEGER, 0, 1, MPI_COMM_WORLD)
      call MPI_Send(result%message, n*message_length, MPI_CHARACTER, 0, 2, MPI_COMM_WORLD)
      call MPI_Send(result%figures, size(result%figures), MPI_DOUBLE_PRECISION, 0, 3, MPI_COMM_WORLD)
      call MPI_Send(result%verdict, n*nl, MPI_INTEGER, 0, 4, MPI_COMM_WORLD)
      call MPI_Send(result%worst, n*nl, MPI_DOUBLE_PRECISION, 0, 5, MPI_COMM_WORLD)
      call MPI_Send(result%excess, n*nl, MPI_DOUBLE_PRECISION, 0, 6, MPI_COMM_WORLD)
      call MPI_Send(result%seconds, n, MPI_DOUBLE_PRECISION, 0, 7, MPI_COMM_WORLD)
      call MPI_Send(result%water_seconds, nw, MPI_DOUBLE_PRECISION, 0, 8, MPI_COMM_WORLD)
      return
    end if
    other = result
    do r = 1, ranks - 1
      call MPI_Recv(other%status, n, MPI_INTEGER, r, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(other%message, n*message_length, MPI_CHARACTER, r, 2, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(other%figures, size(other%figures), MPI_DOUBLE_PRECISION, r, 3, MPI_COMM_WORLD, &
                    MPI_STATUS_IGNORE)
      call MPI_Recv(other%verdict, n*nl, MPI_INTEGER, r, 4, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(other%worst, n*nl, MPI_DOUBLE_PRECISION, r, 5, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(other%excess, n*nl, MPI_DOUBLE_PRECISION, r, 6, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(other%seconds, n, MPI_DOUBLE_PRECISION, r, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      call MPI_Recv(other%water_seconds, nw, MPI_DOUBLE_PRECISION, r, 8, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      theirs = rides_of_rank(n, r, ranks)
      where (theirs)
        result%status = other%status
        result%message = other%message
        result%seconds = other%seconds
      end where
      result%figures(:, pack_index(theirs)) = other%figures(:, pack_index(theirs))
      result%verdict(:, pack_index(theirs)) = other%verdict(:, pack_index(theirs))
      result%worst(:, pack_index(theirs)) = other%worst(:, pack_index(theirs))
      result%excess(:, pack_index(theirs)) = other%excess(:, pack_index(theirs))
      result%water_seconds = max(result%water_seconds, other%water_seconds)
    end do
  end subroutine gather_rides

  pure function pack_index(mask) result(index)
    logical, intent(in) :: mask(:)
    integer, allocatable :: index(:)
    integer :: i
    index = pack([(i, i=1, size(mask))], mask)
  end function pack_index

  !> Ends MPI if start_ranks started it.
  subroutine finish_ranks(started)
    logical, intent(in) :: started
    logical :: finished
    if (.not. started) return
    call MPI_Finalized(finished)
    if (.not. finished) call MPI_Finalize()
  end subroutine finish_ranks
end module design_sweep_ranks
