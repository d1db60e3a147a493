!> Evaluation speed of a bicubic spline surface with all partials to third
!> order (value + 9 partials per point, one call) at 10^6 points: a 1000 x 1000
!> grid (point by point with evaluate; in one evaluate_grid call; one grid line
!> per evaluate_grid call) and 10^6 scattered points. The surface interpolates
!> (regrid, s = 0) z = sin(3x) cos(2y) + x y on a 40 x 30 grid of [0,1] x
!> [0,2], so bench/fitpack_surfaces_bench.py builds the same spline with scipy
!> and times FITPACK's own evaluators on the same points; it runs this program
!> and prints both.
!>
!> Output: one line "ours <case> <median seconds> <checksum>" per case, the
!> median of nrep runs. Each time covers the evaluation of all ten quantities
!> (our only mode) and summing the checksum over the points, as the .py's
!> scipy times cover its evaluation calls and their .sum(). The checksum sums
!> the eight partials FITPACK can reach (parder needs nux < kx, so not z_xxx
!> and z_yyy of a bicubic).
program fitpack_surfaces_bench
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_sorting, only: sort_ascending
  use numerics_spline_surface, only: spline_surface_t, spline_surface_eval_t, fit_grid
  implicit none (type, external)
  integer, parameter :: mx = 40, my = 30, ng = 1000, npts = 1000000, nrep = 5
  real(wp) :: x(mx), y(my), z(mx, my), xg(ng), yg(ng), times(nrep), sums(nrep)
  type(spline_surface_t) :: surf
  type(spline_surface_eval_t), allocatable :: grid(:, :), row(:, :)
  type(status_t) :: st
  integer :: i, j, rep
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
  xg = [((i - 0.5_wp)/ng, i = 1, ng)]
  yg = [(2*(j - 0.5_wp)/ng, j = 1, ng)]
  ! the output arrays exist (and their pages are touched) before any timing
  allocate (grid(ng, ng), row(1, ng))

  do rep = 1, nrep
    call grid_pointwise(times(rep), sums(rep))
  end do
  call report('grid_pointwise', times, sums)
  do rep = 1, nrep
    call grid_one_call(times(rep), sums(rep))
  end do
  call report('grid_one_call', times, sums)
  do rep = 1, nrep
    call grid_by_lines(times(rep), sums(rep))
  end do
  call report('grid_by_lines', times, sums)
  do rep = 1, nrep
    call scattered(times(rep), sums(rep))
  end do
  call report('scattered1e6', times, sums)

contains

  !> The 1000 x 1000 grid, one evaluate call per point.
  subroutine grid_pointwise(t, total)
    real(wp), intent(out) :: t, total
    type(spline_surface_eval_t) :: p
    integer(8) :: t0, t1, rate
    integer :: i, j
    total = 0
    call system_clock(t0, rate)
    do i = 1, ng
      do j = 1, ng
        call surf%evaluate(xg(i), yg(j), p, st)
        total = total + all_partials(p)
      end do
    end do
    call system_clock(t1)
    t = real(t1 - t0, wp)/rate
  end subroutine grid_pointwise

  !> The whole grid in one evaluate_grid call (10^6 records, 248 MB).
  subroutine grid_one_call(t, total)
    real(wp), intent(out) :: t, total
    integer(8) :: t0, t1, rate
    integer :: i, j
    total = 0
    call system_clock(t0, rate)
    call surf%evaluate_grid(xg, yg, grid, st)
    do j = 1, ng
      do i = 1, ng
        total = total + all_partials(grid(i, j))
      end do
    end do
    call system_clock(t1)
    t = real(t1 - t0, wp)/rate
  end subroutine grid_one_call

  !> The grid one u line (1000 points) per evaluate_grid call: the v
  !> B-splines are recomputed in every call.
  subroutine grid_by_lines(t, total)
    real(wp), intent(out) :: t, total
    integer(8) :: t0, t1, rate
    integer :: i, j
    total = 0
    call system_clock(t0, rate)
    do i = 1, ng
      call surf%evaluate_grid(xg(i:i), yg, row, st)
      do j = 1, ng
        total = total + all_partials(row(1, j))
      end do
    end do
    call system_clock(t1)
    t = real(t1 - t0, wp)/rate
  end subroutine grid_by_lines

  !> 10^6 scattered points (a 2-D Halton sequence, the same in the .py).
  subroutine scattered(t, total)
    real(wp), intent(out) :: t, total
    type(spline_surface_eval_t) :: p
    integer(8) :: t0, t1, rate
    integer :: k
    total = 0
    call system_clock(t0, rate)
    do k = 1, npts
      call surf%evaluate(halton(k, 2), 2*halton(k, 3), p, st)
      total = total + all_partials(p)
    end do
    call system_clock(t1)
    t = real(t1 - t0, wp)/rate
  end subroutine scattered

  subroutine report(name, t, total)
    character(len=*), intent(in) :: name
    real(wp), intent(in) :: t(:), total(:)
    print '(a, 1x, a, f10.4, es24.15)', 'ours', name, median(t), total(1)
    if (any(total /= total(1))) print '(a)', 'warning: '//name//' checksums differ between runs'
  end subroutine report

  pure real(wp) function median(a)
    real(wp), intent(in) :: a(:)
    real(wp) :: b(size(a))
    b = a
    call sort_ascending(b)
    median = b((size(b) + 1)/2)
    if (mod(size(b), 2) == 0) median = (b(size(b)/2) + b(size(b)/2 + 1))/2
  end function median

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
