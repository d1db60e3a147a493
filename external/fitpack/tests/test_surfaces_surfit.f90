!> surfit against the genuine FITPACK (scipy 1.10.1 table
!> tests/reference/fitpack/surfaces_surfit.txt, made by
!> scripts/reference/fitpack_surfaces.py): smoothing for several degrees, with
!> weights, wider bbox, least squares on given knots, rank-deficient systems
!> from nearly collinear data, the thesis paraboloids, and invalid inputs.
!> First argument: the reference folder.
program test_surfaces_surfit
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_reference_io, only: reference_table_t, load_table, get_reals, get_int, get_real, has_key, &
    expect, expect_close_scaled, expect_coefficients, finish_checks
  use fitpack_surface_interfaces, only: surfit, bispev
  implicit none (type, external)
  ! unique results (given knots, or s = 0): the same system by rotations in
  ! another order of operations, 1e-10 relative, each coefficient to itself.
  real(real64), parameter :: rtol_unique = 1.0e-10_real64
  ! chosen knots (s > 0): knots are residual-weighted means, 1e-12; the
  ! coefficients and fp come from the p-iteration, 1e-8 (issue 3).
  real(real64), parameter :: rtol_knots = 1.0e-12_real64, rtol_smooth = 1.0e-8_real64
  character(len=1024) :: folder
  call get_command_argument(1, folder)
  if (len_trim(folder) == 0) folder = 'tests/reference/fitpack'
  call surfit_cases(trim(folder)//'/surfaces_surfit.txt')
  call finish_checks('test_surfaces_surfit')
contains



  subroutine surfit_cases(path)
    character(len=*), intent(in) :: path
    type(reference_table_t) :: tab
    logical :: ok, found
    integer :: ic, iopt, kx, ky, nxest, nyest, nmax, m, ier_ref, nx, ny, ier, lwrk1, lwrk2, kwrk, nc, &
      u, v, km1, km2, ne, bx, by, b1, b2
    real(real64) :: s, eps, fp, fp_ref, rtol, s_first
    real(real64), allocatable :: bbox(:), x(:), y(:), z(:), w(:), tx(:), ty(:), c(:), wrk1(:), wrk2(:), &
      tx_ref(:), ty_ref(:), c_ref(:)
    integer, allocatable :: iwrk(:)
    character(len=:), allocatable :: name
    call load_table(path, tab, ok)
    call expect(ok, 'load '//path)
    if (.not. ok) return
    do ic = 1, tab%n_cases
      name = trim(tab%case_names(ic))
      call get_int(tab, name, 'iopt', iopt, found)
      call get_int(tab, name, 'kx', kx, found)
      call get_int(tab, name, 'ky', ky, found)
      call get_int(tab, name, 'nxest', nxest, found)
      call get_int(tab, name, 'nyest', nyest, found)
      call get_real(tab, name, 's', s, found)
      call get_real(tab, name, 'eps', eps, found)
      call get_reals(tab, name, 'bbox', bbox, found)
      call get_reals(tab, name, 'x', x, found)
      call get_reals(tab, name, 'y', y, found)
      call get_reals(tab, name, 'z', z, found)
      call get_reals(tab, name, 'w', w, found)
      call get_int(tab, name, 'ier', ier_ref, found)
      call get_real(tab, name, 'fp', fp_ref, found)
      call get_reals(tab, name, 'tx', tx_ref, found)
      call get_reals(tab, name, 'ty', ty_ref, found)
      call get_reals(tab, name, 'c', c_ref, found)
      m = size(x)
      nmax = max(nxest, nyest)
      u = nxest - kx - 1
      v = nyest - ky - 1
      km1 = max(kx, ky) + 1
      km2 = km1 + 1
      ne = nmax
      bx = kx*v + ky + 1
      by = ky*u + kx + 1
      if (bx <= by) then
        b1 = bx
        b2 = b1 + v - ky
      else
        b1 = by
        b2 = b1 + u - kx
      end if
      lwrk1 = u*v*(2 + b1 + b2) + 2*(u + v + km2*ne + km1*m) + b2 + 1
      lwrk2 = u*v*(b2 + 1) + b2
      kwrk = m + (nxest - 2*kx - 1)*(nyest - 2*ky - 1)
      allocate (tx(nmax), ty(nmax), c(u*v), wrk1(lwrk1), wrk2(lwrk2), iwrk(kwrk))
      tx = 0; ty = 0; c = 0
      nx = 0; ny = 0
      if (iopt == -1) then
        nx = size(tx_ref)
        ny = size(ty_ref)
        tx(1:nx) = tx_ref
        ty(1:ny) = ty_ref
      end if
      if (has_key(tab, name, 's_first')) then
        ! continuation: a first fit from scratch, then iopt = 1 with its knots and wrk1
        call get_real(tab, name, 's_first', s_first, found)
        call surfit(0, m, x, y, z, w, bbox(1), bbox(2), bbox(3), bbox(4), kx, ky, s_first, nxest, nyest, nmax, &
          eps, nx, tx, ny, ty, c, fp, wrk1, lwrk1, wrk2, lwrk2, iwrk, kwrk, ier)
        call expect(ier <= 0, name//': first fit')
      end if
      call surfit(iopt, m, x, y, z, w, bbox(1), bbox(2), bbox(3), bbox(4), kx, ky, s, nxest, nyest, nmax, &
        eps, nx, tx, ny, ty, c, fp, wrk1, lwrk1, wrk2, lwrk2, iwrk, kwrk, ier)
      call expect(ier == ier_ref, name//': ier')
      if (ier /= ier_ref) print '(a, 2(1x, i0))', '  ier got, expected', ier, ier_ref
      if (ier_ref /= 10) then
        call expect(nx == size(tx_ref) .and. ny == size(ty_ref), name//': number of knots')
        if (nx == size(tx_ref) .and. ny == size(ty_ref)) then
          call expect_close_scaled(tx(1:nx), tx_ref, rtol_knots, 0.0_real64, name//': tx')
          call expect_close_scaled(ty(1:ny), ty_ref, rtol_knots, 0.0_real64, name//': ty')
          nc = (nx - kx - 1)*(ny - ky - 1)
          rtol = merge(rtol_unique, rtol_smooth, iopt == -1 .or. s == 0)
          call expect_coefficients(c(1:nc), c_ref, rtol, name//': c')
          ! fp to the same relative tolerance as the coefficients, rank-deficient
          ! cases included (an exact zero fp of an interpolant must come out zero).
          ! Rank-deficient fp includes, per dropped row, the change of its squared
          ! residual when its small diagonal is restored (fprank): leaving that term
          ! out moves fp of surfit_cluster_rank by 1.2e-5 relative, which this catches.
          call expect(abs(fp - fp_ref) <= rtol*abs(fp_ref), name//': fp')
          if (.not. abs(fp - fp_ref) <= rtol*abs(fp_ref)) print '(a, 2es24.16)', '  fp', fp, fp_ref
        else
          print '(a, 4(1x, i0))', '  nx, ny got / expected', nx, ny, size(tx_ref), size(ty_ref)
        end if
      end if
      deallocate (tx, ty, c, wrk1, wrk2, iwrk)
    end do
  end subroutine surfit_cases
end program test_surfaces_surfit
