!> Free-form B-spline surfaces (thesis 3.5.2.3) on the surface seam, wrapping
!> numerics_spline_surface::spline_surface_t:
!>   - a graph r(u, v) = [u, v, s(u, v)] of a spline fitted to scattered points
!>     (surfit) or to a rectangular grid (regrid);
!>   - a parametric surface r(u, v) fitted to a grid of points (parsur).
!> Points are read from CSV files: "x, y, z" per line for scattered and grid
!> data (a grid may come in any order, it must fill a rectangle), and
!> "u, v, x, y, z" per line for a parametric grid. Lines that start with '#'
!> or do not start with a number (a header) are skipped.
module geometry_bspline_surface
  use base_kinds, only: wp
  use base_sorting, only: unique_sorted
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use numerics_spline_surface, only: spline_surface_t, spline_surface_eval_t, fit_scattered, fit_grid, &
                                     fit_parametric
  implicit none (type, external)
  private
  public :: bspline_surface_t, bspline_scattered, bspline_grid, bspline_parametric, bspline_from_table

  type, extends(surface_t) :: bspline_surface_t
    type(spline_surface_t) :: spline
    logical :: graph = .true.          ! r = [u, v, s(u, v)] (else parametric)
    logical :: periodic(2) = .false.
  contains
    procedure :: evaluate => bspline_evaluate
    procedure :: domain => bspline_domain
    procedure :: periodic_u => bspline_periodic_u
    procedure :: periodic_v => bspline_periodic_v
    procedure :: describe => bspline_describe
    procedure :: parameter_units => bspline_parameter_units
  end type bspline_surface_t

contains

  !> Graph of a smoothing spline of degrees kx, ky through scattered (x, y, z).
  function bspline_scattered(x, y, z, smoothing, kx, ky, status) result(s)
    real(wp), intent(in) :: x(:), y(:), z(:), smoothing
    integer, intent(in) :: kx, ky
    type(status_t), intent(out) :: status
    type(bspline_surface_t) :: s
    s%spline = fit_scattered(x, y, z, smoothing, kx, ky, status)
    s%graph = .true.
  end function bspline_scattered

  !> Graph of a spline on the grid x(i), y(j) with values z(i, j).
  function bspline_grid(x, y, z, smoothing, kx, ky, status) result(s)
    real(wp), intent(in) :: x(:), y(:), z(:, :), smoothing
    integer, intent(in) :: kx, ky
    type(status_t), intent(out) :: status
    type(bspline_surface_t) :: s
    s%spline = fit_grid(x, y, z, smoothing, kx, ky, status)
    s%graph = .true.
  end function bspline_grid

  !> Bicubic parametric surface through points(:, i, j) at (u(i), v(j)).
  function bspline_parametric(u, v, points, smoothing, periodic, status) result(s)
    real(wp), intent(in) :: u(:), v(:), points(:, :, :), smoothing
    logical, intent(in) :: periodic(2)
    type(status_t), intent(out) :: status
    type(bspline_surface_t) :: s
    s%spline = fit_parametric(u, v, points, smoothing, periodic, status)
    s%graph = .false.
    s%periodic = periodic
  end function bspline_parametric

  pure subroutine bspline_evaluate(self, u, v, order, p, status)
    class(bspline_surface_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(surface_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    type(spline_surface_eval_t) :: e
    if (order < 0 .or. order > 3) then
      call set_status(status, STATUS_INVALID_INPUT, 'B-spline surface: order must be 0..3')
      return
    end if
    call self%spline%evaluate(u, v, e, status, order)
    if (.not. status%ok()) return
    p%order = order
    if (self%graph) then
      p%r = [u, v, e%f(1)]
      if (order >= 1) then
        p%ru = [1.0_wp, 0.0_wp, e%fu(1)]; p%rv = [0.0_wp, 1.0_wp, e%fv(1)]
      end if
      if (order >= 2) then
        p%ruu = [0.0_wp, 0.0_wp, e%fuu(1)]; p%ruv = [0.0_wp, 0.0_wp, e%fuv(1)]
        p%rvv = [0.0_wp, 0.0_wp, e%fvv(1)]
      end if
      if (order >= 3) then
        p%ruuu = [0.0_wp, 0.0_wp, e%fuuu(1)]; p%ruuv = [0.0_wp, 0.0_wp, e%fuuv(1)]
        p%ruvv = [0.0_wp, 0.0_wp, e%fuvv(1)]; p%rvvv = [0.0_wp, 0.0_wp, e%fvvv(1)]
      end if
    else
      p%r = e%f
      if (order >= 1) then
        p%ru = e%fu; p%rv = e%fv
      end if
      if (order >= 2) then
        p%ruu = e%fuu; p%ruv = e%fuv; p%rvv = e%fvv
      end if
      if (order >= 3) then
        p%ruuu = e%fuuu; p%ruuv = e%fuuv; p%ruvv = e%fuvv; p%rvvv = e%fvvv
      end if
    end if
  end subroutine bspline_evaluate

  pure subroutine bspline_domain(self, u_min, u_max, v_min, v_max)
    class(bspline_surface_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max, v_min, v_max
    real(wp) :: box(4)
    box = self%spline%domain()
    u_min = box(1); u_max = box(2); v_min = box(3); v_max = box(4)
  end subroutine bspline_domain

  pure logical function bspline_periodic_u(self) result(periodic)
    class(bspline_surface_t), intent(in) :: self
    periodic = self%periodic(1)
  end function bspline_periodic_u

  pure logical function bspline_periodic_v(self) result(periodic)
    class(bspline_surface_t), intent(in) :: self
    periodic = self%periodic(2)
  end function bspline_periodic_v

  pure function bspline_describe(self) result(text)
    class(bspline_surface_t), intent(in) :: self
    character(len=:), allocatable :: text
    if (self%graph) then
      text = 'B-spline surface z = s(x, y)'
    else
      text = 'parametric B-spline surface'
    end if
  end function bspline_describe

  !> A B-spline surface from a table of points d(:, k) (a CSV file read and
  !> checked by io_csv): layout 'scattered' or 'grid' (x, y, z) or
  !> 'parametric' (u, v, x, y, z). degree applies to scattered and grid
  !> (parsur is bicubic).
  subroutine bspline_from_table(layout, d, smoothing, degree, periodic, surface, status)
    character(len=*), intent(in) :: layout
    real(wp), intent(in) :: d(:, :)
    real(wp), intent(in) :: smoothing
    integer, intent(in) :: degree
    logical, intent(in) :: periodic(2)
    type(bspline_surface_t), intent(out) :: surface
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: xs(:), ys(:), z(:, :), pts(:, :, :)
    integer :: k, i, j
    logical, allocatable :: filled(:, :)
    type(status_t) :: built
    select case (layout)
    case ('scattered')
      surface = bspline_scattered(d(1, :), d(2, :), d(3, :), smoothing, degree, degree, built)
    case ('grid', 'parametric')
      xs = unique_sorted(d(1, :))
      ys = unique_sorted(d(2, :))
      if (size(xs)*size(ys) /= size(d, 2)) then
        call set_status(status, STATUS_INVALID_INPUT, 'the points do not ' // &
                        'fill a rectangular grid (number of points /= distinct first values x distinct second values)')
        return
      end if
      allocate (z(size(xs), size(ys)), pts(3, size(xs), size(ys)), filled(size(xs), size(ys)))
      filled = .false.
      do k = 1, size(d, 2)
        i = findloc(xs, d(1, k), 1)
        j = findloc(ys, d(2, k), 1)
        filled(i, j) = .true.
        if (layout == 'grid') then
          z(i, j) = d(3, k)
        else
          pts(:, i, j) = d(3:5, k)
        end if
      end do
      if (.not. all(filled)) then
        call set_status(status, STATUS_INVALID_INPUT, 'grid points repeated or missing')
        return
      end if
      if (layout == 'grid') then
        surface = bspline_grid(xs, ys, z, smoothing, degree, degree, built)
      else
        surface = bspline_parametric(xs, ys, pts, smoothing, periodic, built)
      end if
    case default
      call set_status(status, STATUS_INVALID_INPUT, 'B-spline surface: layout must be scattered, grid or parametric')
      return
    end select
    if (.not. built%ok()) status = built
  end subroutine bspline_from_table

  !> A graph's u, v are x, y (m); a parametric fit's are its own numbers.
  pure subroutine bspline_parameter_units(self, u_units, v_units)
    class(bspline_surface_t), intent(in) :: self
    character(len=:), allocatable, intent(out) :: u_units, v_units
    if (self%graph) then
      u_units = 'm'; v_units = 'm'
    else
      u_units = '1'; v_units = '1'
    end if
  end subroutine bspline_parameter_units
end module geometry_bspline_surface
