!> The surface a run used, as a grid in every result file that has geometry:
!> /geometry/surface/{u, v, x, y, z}, u and v dimension scales, x, y, z of
!> h5py shape (n_u, n_v) (Fortran (n_v, n_u)): what the plot scripts draw and
!> the XDMF file shows as a structured grid.
module io_surface_grid
  use base_kinds, only: wp, int64
  use base_status, only: status_t
  use base_text, only: format_integer
  use base_log, only: log_sink_i, progress_interval
  use base_grid, only: evenly_spaced
  use geometry_surface, only: surface_t, surface_point_t
  use io_hdf5, only: result_file_t
  implicit none (type, external)
  private
  public :: write_surface_grid, write_surface_grid_around, surface_grid_group

  character(len=*), parameter :: surface_grid_group = '/geometry/surface'

contains

  !> Evaluates `surface` on the grid u x v and writes it; progress lines of
  !> a large grid to `log` (none without it).
  subroutine write_surface_grid(file, surface, u, v, status, log)
    type(result_file_t), intent(inout) :: file
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: u(:), v(:)
    type(status_t), intent(inout) :: status
    procedure(log_sink_i), optional :: log
    real(wp), allocatable :: x(:, :), y(:, :), z(:, :)
    character(len=:), allocatable :: u_units, v_units
    character(len=*), parameter :: g = surface_grid_group
    if (.not. status%ok()) return
    allocate (x(size(v), size(u)), y(size(v), size(u)), z(size(v), size(u)))
    call points_with_progress(surface, u, v, x, y, z, status, log)
    if (.not. status%ok()) return
    call surface%parameter_units(u_units, v_units)
    call file%write_vector(g//'/u', u, u_units, 'grid values of the surface parameter u', status)
    call file%write_vector(g//'/v', v, v_units, 'grid values of the surface parameter v', status)
    call file%write_matrix(g//'/x', x, 'm', 'x of r(u, v); h5py shape (n_u, n_v)', status)
    call file%write_matrix(g//'/y', y, 'm', 'y of r(u, v); h5py shape (n_u, n_v)', status)
    call file%write_matrix(g//'/z', z, 'm', 'z of r(u, v); h5py shape (n_u, n_v)', status)
    call file%make_scale(g//'/u', status)
    call file%make_scale(g//'/v', status)
    call file%attach_scale(g//'/u', g, status, axis=0)
    call file%attach_scale(g//'/v', g, status, axis=1)
  end subroutine write_surface_grid

  !> The grid points, a block of u values at a time with a progress line to
  !> `log` every few seconds (a large grid takes tens of seconds).
  subroutine points_with_progress(surface, u, v, x, y, z, status, log)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: u(:), v(:)
    real(wp), intent(out) :: x(:, :), y(:, :), z(:, :)
    type(status_t), intent(inout) :: status
    procedure(log_sink_i), optional :: log
    integer, parameter :: blocks = 100
    integer :: first, last, step
    integer(int64) :: clock_rate, clock_last, clock_now
    call system_clock(clock_last, clock_rate)
    step = max(1, size(u)/blocks)
    do first = 1, size(u), step
      last = min(size(u), first + step - 1)
      call surface%points_on_grid(u(first:last), v, x(:, first:last), y(:, first:last), z(:, first:last), &
                                  status)
      if (.not. status%ok()) return
      if (.not. present(log)) cycle
      call system_clock(clock_now)
      if (real(clock_now - clock_last, wp) >= progress_interval()*real(clock_rate, wp) .and. last < size(u)) then
        clock_last = clock_now
        call log('surface grid: '//format_integer(nint(100*real(last, wp)/size(u)))//' % ('// &
                 format_integer(last)//' of '//format_integer(size(u))//' u values)')
      end if
    end do
  end subroutine points_with_progress

  !> The surface around a path (u_path, v_path) on it: its whole parameter
  !> box where that is finite (a closed tube, an ellipsoid), else the path's
  !> box with a margin; 60 x 60 points (progress lines to `log`, if given).
  subroutine write_surface_grid_around(file, surface, u_path, v_path, status, log)
    type(result_file_t), intent(inout) :: file
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: u_path(:), v_path(:)
    type(status_t), intent(inout) :: status
    procedure(log_sink_i), optional :: log
    integer, parameter :: n = 60
    real(wp) :: box(4), u_low, u_high, v_low, v_high
    if (size(u_path) == 0) return
    call surface%domain(box(1), box(2), box(3), box(4))
    call around_path(u_path, box(1), box(2), u_low, u_high)
    call around_path(v_path, box(3), box(4), v_low, v_high)
    call write_surface_grid(file, surface, evenly_spaced(u_low, u_high, n), evenly_spaced(v_low, v_high, n), &
                            status, log)
  end subroutine write_surface_grid_around

  pure subroutine around_path(path, low, high, from, to)
    real(wp), intent(in) :: path(:), low, high
    real(wp), intent(out) :: from, to
    real(wp), parameter :: unbounded = 1e6_wp   ! a domain reaching beyond this is drawn around the path
    real(wp) :: margin
    if (low >= -unbounded .and. high <= unbounded) then
      from = low; to = high
      return
    end if
    margin = 0.25_wp*(maxval(path) - minval(path)) + 0.5_wp
    from = max(low, minval(path) - margin)
    to = min(high, maxval(path) + margin)
  end subroutine around_path
end module io_surface_grid
