!> B-spline surfaces on the surface seam and blends of them: a quadratic graph
!> interpolated on a grid is reproduced exactly; a scattered-data fit and a
!> periodic parametric cylinder within their fit accuracy; partials against
!> central differences; CSV input for all three layouts; a blend of two
!> B-spline patches is smooth (partials against differences).
program test_blended_bspline
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_grid, bspline_scattered, &
                                      bspline_parametric, bspline_from_table
  use geometry_blended_surface, only: blended_surface_t, blend_patch_t, new_blended_surface
  use geometry_placed_surface, only: placed_surface_t
  use io_csv, only: read_csv_table
  use io_input, only: in_range
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences, step 1e-5: error ~1e-11 S (S the size of the
  ! partials, < 100 here); 1e-7 (1 + S) keeps a margin > 100. Cubic splines
  ! are only C2: r_uuu and r_vvv jump at knots and are compared with
  ! differences only for quintic surfaces (see fd_surface).
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  type(status_t) :: st
  type(bspline_surface_t) :: grid, scat, cyl, fromcsv
  type(blended_surface_t) :: blend
  type(blend_patch_t) :: patches(2)
  type(surface_point_t) :: p
  real(wp) :: x(11), y(9), z(11, 9), xs(300), ys(300), zs(300), u(25), v(6), pts(3, 25, 6)
  real(wp) :: a, b, c, d, uu, vv, worst
  real(wp), allocatable :: table(:, :)
  integer :: i, j, unit

  ! --- quadratic graph z = (x^2 + 2 y^2)/4 on a grid, quintic interpolation: exact
  x = [(-1 + 0.2_wp*i, i=0, 10)]
  y = [(-1 + 0.25_wp*j, j=0, 8)]
  do i = 1, 11
    do j = 1, 9
      z(i, j) = (x(i)**2 + 2*y(j)**2)/4
    end do
  end do
  grid = bspline_grid(x, y, z, 0.0_wp, 5, 5, st)
  call check(st%ok(), 'grid fit: ' // st%text())
  do i = 1, 7
    uu = -0.93_wp + 0.27_wp*i
    vv = 0.91_wp - 0.26_wp*i
    call grid%evaluate(uu, vv, 3, p, st)
    ! atol 1e-12: a spline of degree >= 2 interpolating a quadratic is that quadratic
    call check_close_array(p%r, [uu, vv, (uu**2 + 2*vv**2)/4], 0.0_wp, 1e-12_wp, 'grid: r exact')
    call check_close_array(p%ru, [1.0_wp, 0.0_wp, uu/2], 0.0_wp, 1e-11_wp, 'grid: r_u exact')
    call check_close_array(p%rvv, [0.0_wp, 0.0_wp, 1.0_wp], 0.0_wp, 1e-9_wp, 'grid: r_vv exact')
    call check_close_array(p%ruuu, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-7_wp, 'grid: r_uuu exact')
  end do
  call fd_surface(grid, 'grid quintic', .true.)

  ! --- scattered points of the same graph: bicubic smoothing fit, small s
  do i = 1, 300
    xs(i) = -1 + 2*modulo(0.6180339887_wp*i, 1.0_wp)
    ys(i) = -1 + 2*modulo(0.7548776662_wp*i + 0.1_wp, 1.0_wp)
    zs(i) = (xs(i)**2 + 2*ys(i)**2)/4
  end do
  scat = bspline_scattered(xs, ys, zs, 1e-8_wp, 3, 3, st)
  call check(st%ok(), 'scattered fit: ' // st%text())
  worst = 0
  do i = 1, 20
    uu = -0.9_wp + 0.09_wp*i
    vv = 0.85_wp - 0.08_wp*i
    call scat%evaluate(uu, vv, 0, p, st)
    worst = max(worst, abs(p%r(3) - (uu**2 + 2*vv**2)/4))
  end do
  ! s = 1e-8 allows an rms residual of ~6e-6 over 300 points
  call check(worst < 1e-4_wp, 'scattered fit within its smoothing accuracy')
  call fd_surface(scat, 'scattered bicubic', .false.)

  ! --- parametric cylinder of radius 2 (periodic in u), 24 intervals round
  u = [(two_pi*i/24, i=0, 24)]
  v = [(0.5_wp*j, j=0, 5)]
  do i = 1, 25
    do j = 1, 6
      pts(:, i, j) = [2*cos(u(i)), 2*sin(u(i)), v(j)]
    end do
  end do
  pts(:, 25, :) = pts(:, 1, :)
  cyl = bspline_parametric(u, v, pts, 0.0_wp, [.true., .false.], st)
  call check(st%ok(), 'parametric fit: ' // st%text())
  call check(cyl%periodic_u() .and. .not. cyl%periodic_v(), 'parametric periodicity')
  worst = 0
  do i = 1, 40
    call cyl%evaluate(0.157_wp*i, 0.06_wp*i, 0, p, st)
    worst = max(worst, abs(norm2(p%r(1:2)) - 2))
  end do
  ! cubic interpolation of a circle, 24 intervals: error ~ R (2 pi/24)^4/384 ~ 2.5e-5 m
  call check(worst < 1e-4_wp, 'parametric cylinder within interpolation accuracy')
  call fd_surface(cyl, 'parametric bicubic', .false.)

  ! --- CSV input: the grid again, in shuffled order and with a header
  open (newunit=unit, file='test_blended_bspline_grid.csv', status='replace', action='write')
  write (unit, '(a)') 'x, y, z'
  do j = 9, 1, -1
    do i = 1, 11
      write (unit, '(es24.16, ",", es24.16, ",", es24.16)') x(i), y(j), z(i, j)
    end do
  end do
  close (unit)
  st = status_t()
  call read_csv_table('test_blended_bspline_grid.csv', 3, 3, 1000, [(in_range(-1e3_wp, 1e3_wp, 'm'), i = 1, 3)], &
                      table, st)
  call check(st%ok() .and. size(table, 2) == 99, 'CSV read: '//st%text())
  call bspline_from_table('grid', table, 0.0_wp, 5, [.false., .false.], fromcsv, st)
  call check(st%ok(), 'grid from CSV: ' // st%text())
  call fromcsv%evaluate(0.3_wp, -0.2_wp, 0, p, st)
  call check_close(p%r(3), (0.09_wp + 0.08_wp)/4, 0.0_wp, 1e-12_wp, 'grid from CSV reproduces the quadratic')
  st = status_t()
  call bspline_from_table('scattered', table, 1e-8_wp, 3, [.false., .false.], fromcsv, st)
  call check(st%ok(), 'scattered from CSV: ' // st%text())
  open (newunit=unit, file='test_blended_bspline_grid.csv', status='old')
  close (unit, status='delete')
  st = status_t()
  call read_csv_table('no_such_file.csv', 3, 3, 1000, [(in_range(-1e3_wp, 1e3_wp, 'm'), i = 1, 3)], table, st)
  call check(.not. st%ok() .and. index(st%text(), 'no_such_file.csv') > 0, 'missing CSV named: ' // st%text())

  ! --- blend of two B-spline patches (the grid graph and a copy raised by 5 cm)
  allocate (patches(1)%surface, source=grid)
  allocate (patches(2)%surface, source=placed_surface_t(grid, [0.0_wp, 0.0_wp, 0.05_wp], st))
  ! each patch must be defined on the range the transition reaches into (3.76):
  ! [-0.9, -0.9 + 1.5] and [0.4 - 1.0, 0.9] lie inside the spline's [-1, 1]
  patches%u_min = -0.9_wp; patches%u_max = -0.5_wp; patches%v_min = -0.8_wp; patches%v_max = 0.8_wp
  patches(2)%u_min = 0.4_wp; patches(2)%u_max = 0.9_wp
  blend = new_blended_surface(patches, [0.6_wp], st)
  call check(st%ok(), 'B-spline blend built')
  call blend%domain(a, b, c, d)
  call check_close(b, 0.4_wp + 0.6_wp + 0.5_wp, 1e-14_wp, 0.0_wp, 'B-spline blend domain')
  call fd_surface(blend, 'B-spline blend', .true.)

  call finish_tests('test_blended_bspline')

contains

  !> Partials against central differences; third partials only if `third`
  !> (for cubic splines they jump at knots and differences straddling a knot
  !> would not converge to either side).
  subroutine fd_surface(surf, name, third)
    class(surface_t), intent(in) :: surf
    character(len=*), intent(in) :: name
    logical, intent(in) :: third
    type(surface_point_t) :: p0, pu1, pu0, pv1, pv0
    real(wp) :: a, b, c, d, uu, vv, tol
    integer :: i
    call surf%domain(a, b, c, d)
    do i = 1, 9
      uu = a + (b - a)*(0.1_wp*i - 0.0137_wp)
      vv = c + (d - c)*(0.93_wp - 0.0913_wp*i)
      call surf%evaluate(uu, vv, 3, p0, st)
      call check(st%ok(), name // ': evaluate status')
      call surf%evaluate(uu + h, vv, 3, pu1, st)
      call surf%evaluate(uu - h, vv, 3, pu0, st)
      call surf%evaluate(uu, vv + h, 3, pv1, st)
      call surf%evaluate(uu, vv - h, 3, pv0, st)
      tol = fd_tol*(1 + maxval(abs([p0%r, p0%ru, p0%rv, p0%ruu, p0%ruv, p0%rvv, p0%ruuu, p0%ruuv, &
                                    p0%ruvv, p0%rvvv])))
      call check_close_array(p0%ru, (pu1%r - pu0%r)/(2*h), 0.0_wp, tol, name // ': r_u')
      call check_close_array(p0%rv, (pv1%r - pv0%r)/(2*h), 0.0_wp, tol, name // ': r_v')
      call check_close_array(p0%ruu, (pu1%ru - pu0%ru)/(2*h), 0.0_wp, tol, name // ': r_uu')
      call check_close_array(p0%ruv, (pv1%ru - pv0%ru)/(2*h), 0.0_wp, tol, name // ': r_uv')
      call check_close_array(p0%rvv, (pv1%rv - pv0%rv)/(2*h), 0.0_wp, tol, name // ': r_vv')
      ! r_uu is C2 in v (and r_vv in u) even for bicubics, so these differences converge
      call check_close_array(p0%ruuv, (pv1%ruu - pv0%ruu)/(2*h), 0.0_wp, tol, name // ': r_uuv')
      call check_close_array(p0%ruvv, (pu1%rvv - pu0%rvv)/(2*h), 0.0_wp, tol, name // ': r_uvv')
      if (third) then
        call check_close_array(p0%ruuu, (pu1%ruu - pu0%ruu)/(2*h), 0.0_wp, tol, name // ': r_uuu')
        call check_close_array(p0%rvvv, (pv1%rvv - pv0%rvv)/(2*h), 0.0_wp, tol, name // ': r_vvv')
      end if
    end do
  end subroutine fd_surface
end program test_blended_bspline
