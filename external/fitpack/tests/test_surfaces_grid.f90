!> regrid, bispev and parder against the genuine FITPACK (scipy 1.10.1 tables
!> tests/reference/fitpack/surfaces_regrid.txt and surfaces_eval.txt, made by
!> scripts/reference/fitpack_surfaces.py). First argument: the reference folder.
program test_surfaces_grid
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_reference_io, only: reference_table_t, load_table, get_reals, get_int, get_real, has_key, &
    expect, expect_close_scaled, expect_coefficients, finish_checks
  use fitpack_surface_interfaces, only: regrid, bispev, parder, surfit
  implicit none (type, external)
  ! unique results (s = 0): the same linear system solved by the same rotations
  ! in another order of operations: agreement to rounding, 1e-10 relative.
  real(real64), parameter :: rtol_unique = 1.0e-10_real64
  ! chosen knots (s > 0): knot values are data points or midpoints, 1e-12;
  ! coefficients and fp come out of the p-iteration, 1e-8 relative (issue 3).
  real(real64), parameter :: rtol_knots = 1.0e-12_real64, rtol_smooth = 1.0e-8_real64
  ! evaluation of given coefficients: a few dozen roundings, 1e-12 relative to
  ! the largest value of the same quantity.
  real(real64), parameter :: rtol_eval = 1.0e-12_real64
  character(len=1024) :: folder
  call get_command_argument(1, folder)
  if (len_trim(folder) == 0) folder = 'tests/reference/fitpack'
  call regrid_cases(trim(folder)//'/surfaces_regrid.txt')
  call eval_cases(trim(folder)//'/surfaces_eval.txt')
  call given_knots_and_continuation(trim(folder)//'/surfaces_regrid.txt')
  call storage_too_small(trim(folder)//'/surfaces_regrid.txt')
  call finish_checks('test_surfaces_grid')
contains



  subroutine regrid_cases(path)
    character(len=*), intent(in) :: path
    type(reference_table_t) :: tab
    logical :: ok, found
    integer :: ic, kx, ky, nxest, nyest, mx, my, ier_ref, nx, ny, ier, lwrk, kwrk, nc
    real(real64) :: s, fp, fp_ref, rtol
    real(real64), allocatable :: bbox(:), x(:), y(:), z(:), tx(:), ty(:), c(:), wrk(:), &
      tx_ref(:), ty_ref(:), c_ref(:)
    integer, allocatable :: iwrk(:)
    character(len=:), allocatable :: name
    call load_table(path, tab, ok)
    call expect(ok, 'load '//path)
    if (.not. ok) return
    do ic = 1, tab%n_cases
      name = trim(tab%case_names(ic))
      call get_int(tab, name, 'kx', kx, found)
      call get_int(tab, name, 'ky', ky, found)
      call get_int(tab, name, 'nxest', nxest, found)
      call get_int(tab, name, 'nyest', nyest, found)
      call get_real(tab, name, 's', s, found)
      call get_reals(tab, name, 'bbox', bbox, found)
      call get_reals(tab, name, 'x', x, found)
      call get_reals(tab, name, 'y', y, found)
      call get_reals(tab, name, 'z', z, found)
      call get_int(tab, name, 'ier', ier_ref, found)
      call get_real(tab, name, 'fp', fp_ref, found)
      mx = size(x)
      my = size(y)
      lwrk = 4 + nxest*(my + 2*kx + 5) + nyest*(2*ky + 5) + mx*(kx + 1) + my*(ky + 1) + max(my, nxest)
      kwrk = 3 + mx + my + nxest + nyest
      allocate (tx(nxest), ty(nyest), c((nxest - kx - 1)*(nyest - ky - 1)), wrk(lwrk), iwrk(kwrk))
      tx = 0; ty = 0; c = 0
      call regrid(0, mx, x, my, y, z, bbox(1), bbox(2), bbox(3), bbox(4), kx, ky, s, nxest, nyest, &
        nx, tx, ny, ty, c, fp, wrk, lwrk, iwrk, kwrk, ier)
      call expect(ier == ier_ref, name//': ier')
      if (ier /= ier_ref) print '(a, 2(1x, i0))', '  ier got, expected', ier, ier_ref
      if (ier_ref /= 10 .and. ier == ier_ref) then
        call get_reals(tab, name, 'tx', tx_ref, found)
        call get_reals(tab, name, 'ty', ty_ref, found)
        call get_reals(tab, name, 'c', c_ref, found)
        call expect(nx == size(tx_ref) .and. ny == size(ty_ref), name//': number of knots')
        if (nx == size(tx_ref) .and. ny == size(ty_ref)) then
          call expect_close_scaled(tx(1:nx), tx_ref, rtol_knots, 0.0_real64, name//': tx')
          call expect_close_scaled(ty(1:ny), ty_ref, rtol_knots, 0.0_real64, name//': ty')
          nc = (nx - kx - 1)*(ny - ky - 1)
          rtol = merge(rtol_unique, rtol_smooth, s == 0)
          ! (regrid_maxit_b/c, ier = 3, take the p-iteration's one-sided steps:
          ! with exactly 0.04 instead of genuine's single-precision value they
          ! miss by 2.3e-7)
          call expect_coefficients(c(1:nc), c_ref, rtol, name//': c')
          ! fp of an interpolant is 0 by definition; else relative
          call expect(abs(fp - fp_ref) <= rtol*abs(fp_ref), name//': fp')
          if (.not. abs(fp - fp_ref) <= rtol*abs(fp_ref)) print '(a, 2es24.16)', '  fp', fp, fp_ref
        else
          print '(a, 4(1x, i0))', '  nx, ny got / expected', nx, ny, size(tx_ref), size(ty_ref)
        end if
      end if
      deallocate (tx, ty, c, wrk, iwrk)
    end do
  end subroutine regrid_cases

  subroutine eval_cases(path)
    character(len=*), intent(in) :: path
    type(reference_table_t) :: tab
    logical :: ok, found
    integer :: ic, kx, ky, nux, nuy, mx, my, ier, lwrk, kwrk
    real(real64), allocatable :: tx(:), ty(:), c(:), x(:), y(:), z(:), zr(:), wrk(:)
    integer, allocatable :: iwrk(:)
    character(len=:), allocatable :: name
    character(len=8) :: key
    call load_table(path, tab, ok)
    call expect(ok, 'load '//path)
    if (.not. ok) return
    do ic = 1, tab%n_cases
      name = trim(tab%case_names(ic))
      call get_int(tab, name, 'kx', kx, found)
      call get_int(tab, name, 'ky', ky, found)
      call get_reals(tab, name, 'tx', tx, found)
      call get_reals(tab, name, 'ty', ty, found)
      call get_reals(tab, name, 'c', c, found)
      call get_reals(tab, name, 'x', x, found)
      call get_reals(tab, name, 'y', y, found)
      mx = size(x)
      my = size(y)
      lwrk = size(c) + mx*(kx + 1) + my*(ky + 1)
      kwrk = mx + my
      allocate (z(mx*my), wrk(lwrk), iwrk(kwrk))
      call bispev(tx, size(tx), ty, size(ty), c, kx, ky, x, mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
      call expect(ier == 0, name//': bispev ier')
      call get_reals(tab, name, 'z', zr, found)
      call expect_close_scaled(z, zr, rtol_eval, 0.0_real64, name//': bispev')
      do nux = 0, kx - 1
        do nuy = 0, ky - 1
          write (key, '(a, i0, i0)') 'd', nux, nuy
          call parder(tx, size(tx), ty, size(ty), c, kx, ky, nux, nuy, x, mx, y, my, z, wrk, lwrk, &
            iwrk, kwrk, ier)
          call expect(ier == 0, name//': parder ier '//trim(key))
          if (nux + nuy == 0) then
            call expect_close_scaled(z, zr, rtol_eval, 0.0_real64, name//': parder 00')
          else
            call get_reals(tab, name, trim(key), zr, found)
            call expect(found, name//': has '//trim(key))
            ! differencing loses about a digit per order
            call expect_close_scaled(z, zr, rtol_eval*10.0_real64**(nux + nuy), 0.0_real64, name//': parder '//trim(key))
          end if
        end do
      end do
      ! invalid input: derivative order kx, decreasing points, small workspace
      call parder(tx, size(tx), ty, size(ty), c, kx, ky, kx, 0, x, mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
      call expect(ier == 10, name//': parder nux = kx gives ier 10')
      call bispev(tx, size(tx), ty, size(ty), c, kx, ky, x(mx:1:-1), mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
      call expect(ier == 10, name//': bispev decreasing x gives ier 10')
      call bispev(tx, size(tx), ty, size(ty), c, kx, ky, x, mx, y, my, z, wrk, mx, iwrk, kwrk, ier)
      call expect(ier == 10, name//': bispev small lwrk gives ier 10')
      deallocate (z, wrk, iwrk)
      if (.false.) print *, has_key(tab, name, 'x')
    end do
  end subroutine eval_cases

  !> What must hold where scipy cannot reach regrid:
  !>  - iopt = -1 on the knots of regrid_smooth_k33: the least-squares spline on
  !>    a grid is unique, so it equals surfit's (iopt = -1) on the same points;
  !>  - iopt = 1 continuing from s1 to s2 < s1 keeps the old knots and reaches
  !>    |fp - s2| < 0.001 s2, with at least as many knots.
  subroutine given_knots_and_continuation(path)
    character(len=*), intent(in) :: path
    character(len=*), parameter :: name = 'regrid_smooth_k33'
    type(reference_table_t) :: tab
    logical :: ok, found
    integer :: mx, my, nxest, nyest, nx, ny, ier, lwrk, kwrk, i, j, m, nx2, ny2, nc, nmax, lwrk1, lwrk2
    real(real64) :: fp, fp2, s1, s2
    real(real64), allocatable :: bbox(:), x(:), y(:), z(:), tx(:), ty(:), c(:), wrk(:), tx_ref(:), ty_ref(:), &
      xs(:), ys(:), w(:), tx2(:), ty2(:), c2(:), wrk1(:), wrk2(:), tx_first(:)
    integer, allocatable :: iwrk(:), iwrk2(:)
    call load_table(path, tab, ok)
    if (.not. ok) return
    call get_reals(tab, name, 'bbox', bbox, found)
    call get_reals(tab, name, 'x', x, found)
    call get_reals(tab, name, 'y', y, found)
    call get_reals(tab, name, 'z', z, found)
    call get_reals(tab, name, 'tx', tx_ref, found)
    call get_reals(tab, name, 'ty', ty_ref, found)
    mx = size(x)
    my = size(y)
    nxest = mx + 4
    nyest = my + 4
    lwrk = 4 + nxest*(my + 11) + nyest*11 + mx*4 + my*4 + max(my, nxest)
    kwrk = 3 + mx + my + nxest + nyest
    allocate (tx(nxest), ty(nyest), c((nxest - 4)*(nyest - 4)), wrk(lwrk), iwrk(kwrk))
    nx = size(tx_ref)
    ny = size(ty_ref)
    tx(1:nx) = tx_ref
    ty(1:ny) = ty_ref
    call regrid(-1, mx, x, my, y, z, bbox(1), bbox(2), bbox(3), bbox(4), 3, 3, 0.0_real64, nxest, nyest, &
      nx, tx, ny, ty, c, fp, wrk, lwrk, iwrk, kwrk, ier)
    call expect(ier == 0, 'regrid iopt=-1: ier')
    m = mx*my
    allocate (xs(m), ys(m), w(m))
    do i = 1, mx
      do j = 1, my
        xs(my*(i - 1) + j) = x(i)
        ys(my*(i - 1) + j) = y(j)
      end do
    end do
    w = 1
    nmax = max(nx, ny)
    allocate (tx2(nmax), ty2(nmax), c2((nx - 4)*(ny - 4)))
    tx2 = 0
    ty2 = 0
    tx2(1:nx) = tx_ref
    ty2(1:ny) = ty_ref
    nx2 = nx
    ny2 = ny
    lwrk1 = 100000
    lwrk2 = 100000
    allocate (wrk1(lwrk1), wrk2(lwrk2), iwrk2(m + 1000))
    call surfit(-1, m, xs, ys, z, w, bbox(1), bbox(2), bbox(3), bbox(4), 3, 3, 0.0_real64, nx, ny, nmax, &
      1.0e-16_real64, nx2, tx2, ny2, ty2, c2, fp2, wrk1, lwrk1, wrk2, lwrk2, iwrk2, m + 1000, ier)
    call expect(ier == 0, 'surfit iopt=-1 on the grid points: ier')
    nc = (nx - 4)*(ny - 4)
    ! one unique least-squares solution by two rotation orders: rounding, 1e-10
    call expect_close_scaled(c(1:nc), c2(1:nc), 1.0e-10_real64, 0.0_real64, 'regrid iopt=-1 equals surfit iopt=-1')
    call expect(abs(fp - fp2) <= 1.0e-10_real64*fp2, 'regrid iopt=-1: fp equals surfit''s')
    ! continuation
    s1 = 0.1_real64
    s2 = 0.03_real64
    call regrid(0, mx, x, my, y, z, bbox(1), bbox(2), bbox(3), bbox(4), 3, 3, s1, nxest, nyest, &
      nx, tx, ny, ty, c, fp, wrk, lwrk, iwrk, kwrk, ier)
    call expect(ier == 0 .and. abs(fp - s1) < 1.0e-3_real64*s1, 'regrid s1: fp = s1')
    tx_first = tx(1:nx)
    nx2 = nx
    ny2 = ny
    call regrid(1, mx, x, my, y, z, bbox(1), bbox(2), bbox(3), bbox(4), 3, 3, s2, nxest, nyest, &
      nx, tx, ny, ty, c, fp, wrk, lwrk, iwrk, kwrk, ier)
    call expect(ier == 0 .and. abs(fp - s2) < 1.0e-3_real64*s2, 'regrid iopt=1 to s2: fp = s2')
    call expect(nx >= nx2 .and. ny >= ny2, 'regrid iopt=1: no knots lost')
    call expect(all([(any(abs(tx(1:nx) - tx_first(i)) == 0), i = 1, nx2)]), 'regrid iopt=1: old x knots kept')
  end subroutine given_knots_and_continuation
  !> regrid ier = 1, which scipy 1.10.1 cannot reach (regrid_smth and
  !> RectBivariateSpline fix nxest = mx+kx+1, nyest = my+ky+1): on the data of
  !> regrid_smooth_k33 with nxest = nyest = 9 and a small s, both directions fill
  !> their storage with fp > s. What must hold: ier = 1, nx = nxest, ny = nyest,
  !> fp > s, and the result is the least-squares spline on those knots (regrid
  !> iopt = -1 on the returned knots gives the same coefficients and fp).
  subroutine storage_too_small(path)
    character(len=*), intent(in) :: path
    character(len=*), parameter :: name = 'regrid_smooth_k33'
    integer, parameter :: nest = 9
    type(reference_table_t) :: tab
    logical :: ok, found
    integer :: mx, my, nx, ny, ier, lwrk, kwrk, nc, nx2, ny2
    real(real64) :: fp, fp2
    real(real64), parameter :: s = 1.0e-3_real64
    real(real64), allocatable :: bbox(:), x(:), y(:), z(:), tx(:), ty(:), c(:), wrk(:), tx2(:), ty2(:), c2(:)
    integer, allocatable :: iwrk(:)
    call load_table(path, tab, ok)
    if (.not. ok) return
    call get_reals(tab, name, 'bbox', bbox, found)
    call get_reals(tab, name, 'x', x, found)
    call get_reals(tab, name, 'y', y, found)
    call get_reals(tab, name, 'z', z, found)
    mx = size(x)
    my = size(y)
    lwrk = 4 + nest*(my + 11) + nest*11 + mx*4 + my*4 + max(my, nest)
    kwrk = 3 + mx + my + nest + nest
    allocate (tx(nest), ty(nest), c((nest - 4)**2), wrk(lwrk), iwrk(kwrk), tx2(nest), ty2(nest), c2((nest - 4)**2))
    call regrid(0, mx, x, my, y, z, bbox(1), bbox(2), bbox(3), bbox(4), 3, 3, s, nest, nest, &
      nx, tx, ny, ty, c, fp, wrk, lwrk, iwrk, kwrk, ier)
    call expect(ier == 1, 'regrid nxest, nyest too small: ier 1')
    call expect(nx == nest .and. ny == nest .and. fp > s, 'regrid ier 1: storage full, fp > s')
    if (nx /= nest .or. ny /= nest) return
    tx2 = tx
    ty2 = ty
    nx2 = nx
    ny2 = ny
    call regrid(-1, mx, x, my, y, z, bbox(1), bbox(2), bbox(3), bbox(4), 3, 3, s, nest, nest, &
      nx2, tx2, ny2, ty2, c2, fp2, wrk, lwrk, iwrk, kwrk, ier)
    call expect(ier == 0, 'regrid ier 1: iopt=-1 on its knots: ier')
    nc = (nx - 4)*(ny - 4)
    ! the same least-squares system solved twice by the same code: rounding only
    call expect_coefficients(c(1:nc), c2(1:nc), 1.0e-12_real64, 'regrid ier 1 = least squares on its knots: c')
    call expect(abs(fp - fp2) <= 1.0e-12_real64*fp2, 'regrid ier 1 = least squares on its knots: fp')
  end subroutine storage_too_small
end program test_surfaces_grid
