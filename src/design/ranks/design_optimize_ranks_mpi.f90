!> The rides of a geometry optimisation shared among MPI ranks (built when
!> CMake finds MPI; without MPI: design_optimize_ranks_serial.f90). Every
!> rank runs the same optimisation; of each batch of rides, ride i is ridden
!> by rank mod(i - 1, ranks) only, and each rank broadcasts its rides'
!> figures and statuses to the others, as they are (bits, not sums), so
!> every rank holds the same numbers as a single process would and takes
!> the same steps. MPI is started by the scenario (design_sweep_ranks'
!> start_ranks); only the thread that calls this uses MPI (the rides' OpenMP
!> threads never do).
module design_optimize_ranks
  use base_kinds, only: wp
  use base_status, only: status_t
  use design_cuboid_ride, only: cuboid_ride_t
  use mpi_f08, only: MPI_Bcast, MPI_COMM_WORLD, MPI_INTEGER, MPI_DOUBLE_PRECISION, MPI_CHARACTER, MPI_LOGICAL
  implicit none (type, external)
  private
  public :: ride_is_mine, share_rides, share_flag

  integer, parameter :: n_figures = 13, message_length = 1000

contains

  !> Whether ride i of a batch is this rank's.
  pure logical function ride_is_mine(i, rank, ranks)
    integer, intent(in) :: i, rank, ranks
    ride_is_mine = mod(i - 1, max(1, ranks)) == rank
  end function ride_is_mine

  !> Every rank's rides to every rank: after it rides(i) and statuses(i) are
  !> those of the rank that rode i (the series are not sent: rides shared
  !> keep none).
  subroutine share_rides(rides, statuses, rank, ranks)
    type(cuboid_ride_t), intent(inout) :: rides(:)
    type(status_t), intent(inout) :: statuses(:)
    integer, intent(in) :: rank, ranks
    real(wp), allocatable :: figures(:, :)
    integer, allocatable :: codes(:)
    character(len=message_length), allocatable :: messages(:)
    integer :: r, i, n
    if (ranks < 2) return
    n = size(rides)
    allocate (figures(n_figures, n), codes(n), messages(n))
    do r = 0, ranks - 1
      if (r == rank) then
        do i = 1, n
          figures(:, i) = pack_ride(rides(i))
          codes(i) = statuses(i)%code
          messages(i) = ''
          if (allocated(statuses(i)%message)) messages(i) = statuses(i)%message
        end do
      end if
      call MPI_Bcast(figures, n_figures*n, MPI_DOUBLE_PRECISION, r, MPI_COMM_WORLD)
      call MPI_Bcast(codes, n, MPI_INTEGER, r, MPI_COMM_WORLD)
      call MPI_Bcast(messages, message_length*n, MPI_CHARACTER, r, MPI_COMM_WORLD)
      if (r == rank) cycle
      do i = 1, n
        if (.not. ride_is_mine(i, r, ranks)) cycle
        call unpack_ride(figures(:, i), rides(i))
        statuses(i) = status_t(code=codes(i), message=trim(messages(i)))
      end do
    end do
  end subroutine share_rides

  pure function pack_ride(ride) result(x)
    type(cuboid_ride_t), intent(in) :: ride
    real(wp) :: x(n_figures)
    x = [ride%max_acceleration, ride%time_of_max, ride%u_of_max, ride%max_lever_arm, ride%time_of_max_lever, &
         ride%max_tipping_excess, ride%min_normal_force, merge(1.0_wp, 0.0_wp, ride%lifts_off), ride%duration, &
         ride%end_speed, ride%start_angle, merge(1.0_wp, 0.0_wp, ride%reached_end), real(ride%rhs_evaluations, wp)]
  end function pack_ride

  pure subroutine unpack_ride(x, ride)
    real(wp), intent(in) :: x(n_figures)
    type(cuboid_ride_t), intent(inout) :: ride
    ride%max_acceleration = x(1)
    ride%time_of_max = x(2)
    ride%u_of_max = x(3)
    ride%max_lever_arm = x(4)
    ride%time_of_max_lever = x(5)
    ride%max_tipping_excess = x(6)
    ride%min_normal_force = x(7)
    ride%lifts_off = x(8) > 0
    ride%duration = x(9)
    ride%end_speed = x(10)
    ride%start_angle = x(11)
    ride%reached_end = x(12) > 0
    ride%rhs_evaluations = nint(x(13))
  end subroutine unpack_ride
  !> Rank 0's flag to every rank (whether to go on: rank 0 alone opens the
  !> result file).
  subroutine share_flag(flag, ranks)
    logical, intent(inout) :: flag
    integer, intent(in) :: ranks
    if (ranks < 2) return
    call MPI_Bcast(flag, 1, MPI_LOGICAL, 0, MPI_COMM_WORLD)
  end subroutine share_flag
end module design_optimize_ranks
