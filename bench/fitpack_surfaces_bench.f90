!> Evaluation speed of a bicubic spline surface with all partials to third
!> order (value + 9 partials per point, one call) at 10^6 points: a 1000 x 1000
!> grid (point by point with evaluate, and line by line with evaluate_grid) and
!> 10^6 scattered points. The surface interpolates (regrid, s = 0)
!> z = sin(3x) cos(2y) + x y on a 40 x 30 grid of [0,1] x [0,2], so
!> bench/fitpack_surfaces_bench.py builds the same spline with scipy and times
!> FITPACK's own evaluators on the same points; it runs this program and
!> prints both. Output: one line "ours <case> <seconds> <checksum>" per case.
!> The checksum sums the eight partials FITPACK can reach (parder needs
!> nux < kx, so not z_xxx and z_yyy of a bicubic); the timing includes all ten.
program fitpack_surfaces_bench
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_spline_surface, only: spline_surface_t, spline_surface_eval_t, fit_grid
  implicit none (type, external)
  integer, parameter :: mx = 40, my = 30, ng = 1000, npts = 1000000
  real(wp) :: x(mx), y(my), z(mx, my), sum_all, xs, ys
  type(spline_surface_t) :: surf
  type(spline_surface_eval_t) :: p
  type(spline_surface_eval_t), allocatable :: row(:, :)
  type(status_t) :: st
  real(wp) :: xg(ng), yg(ng)
  integer :: i, j, k
  integer(8) :: t0, t1, rate
  x = [(real(i - 1, wp)/(mx - 1), i = 1, mx)]
  y = [(2*real(j - 1, wp)/(my - 1), j = 1, my)]
  do i = 1, mx
    do j = 1, my
      z(i, j) = sin(3*x(i))*cos(2*y(j)) + x(i)*y(j)
    end do
  end do
  surf = fit_grid(x, y, z, 0.0_wp, 3, 3, st)
  if (.not. st%ok()) then
    print '(a)', 'fit failed: '//st%text()
    error stop 1
  end if
  ! grid of 1000 x 1000 points
  sum_all = 0
  call system_clock(t0, rate)
  do i = 1, ng
    xs = (i - 0.5_wp)/ng
    do j = 1, ng
      ys = 2*(j - 0.5_wp)/ng
      call surf%evaluate(xs, ys, p, st)
      sum_all = sum_all + all_partials(p)
    end do
  end do
  call system_clock(t1)
  print '(a, f10.4, es24.15)', 'ours grid1000x1000 ', real(t1 - t0, wp)/rate, sum_all
  ! the same grid through evaluate_grid, one grid line (1000 points) per call
  allocate (row(1, ng))
  xg = [((i - 0.5_wp)/ng, i = 1, ng)]
  yg = [(2*(j - 0.5_wp)/ng, j = 1, ng)]
  sum_all = 0
  call system_clock(t0, rate)
  do i = 1, ng
    call surf%evaluate_grid(xg(i:i), yg, row, st)
    do j = 1, ng
      sum_all = sum_all + all_partials(row(1, j))
    end do
  end do
  call system_clock(t1)
  print '(a, f10.4, es24.15)', 'ours grid_by_lines ', real(t1 - t0, wp)/rate, sum_all
  ! 10^6 scattered points (a 2-D Halton sequence, the same in the .py)
  sum_all = 0
  call system_clock(t0, rate)
  do k = 1, npts
    call surf%evaluate(halton(k, 2), 2*halton(k, 3), p, st)
    sum_all = sum_all + all_partials(p)
  end do
  call system_clock(t1)
  print '(a, f10.4, es24.15)', 'ours scattered1e6  ', real(t1 - t0, wp)/rate, sum_all
contains
  pure real(wp) function all_partials(q)
    type(spline_surface_eval_t), intent(in) :: q
    all_partials = q%f(1) + q%fu(1) + q%fv(1) + q%fuu(1) + q%fuv(1) + q%fvv(1) + q%fuuv(1) + q%fuvv(1)
  end function all_partials

  pure real(wp) function halton(i, base) result(h)
    integer, intent(in) :: i, base
    real(wp) :: f
    integer :: n
    h = 0
    f = 1
    n = i
    do while (n > 0)
      f = f/base
      h = h + f*mod(n, base)
      n = n/base
    end do
  end function halton
end program fitpack_surfaces_bench
