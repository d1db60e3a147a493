!> Evaluation routines against the genuine FITPACK (splev, splder, spalde, insert,
!> splint, sproot; tables made by scripts/reference/fitpack_curves.py) and by what
!> must hold where scipy cannot reach (cualde = repeated splder, curev = splev per
!> coordinate, the thesis's fig. 2.4 basis sums to one).
program test_curves_eval
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: splev, splder, spalde, cualde, curev, insert, splint, sproot, fpbspl
  use fitpack_reference_io
  implicit none (type, external)
  type(reference_table_t) :: tab
  logical :: ok
  integer :: ic

  call load_table(reference_path('curves_eval.txt'), tab, ok)
  call expect(ok, 'read curves_eval.txt')
  if (ok) then
    do ic = 1, tab%n_cases
      call run_case(trim(tab%case_names(ic)))
    end do
  end if
  call thesis_figure_2_4()
  call finish_checks('fitpack curve evaluation')

contains

  subroutine run_case(name)
    character(len=*), intent(in) :: name
    real(real64), allocatable :: t(:), c(:), x(:), yref(:), y(:), wrk(:), xa(:), dref(:), d(:), &
                                 tt(:), cc(:), ttref(:), ccref(:), ab(:), iref(:), tz(:), cz(:), zref(:), &
                                 z(:), c3(:), d3(:), yj(:), u(:), xc(:)
    real(real64) :: xins, scale, integral
    integer :: k, n, m, ier, nu, i, j, nn, nest, mz, nc
    character(len=8) :: key
    logical :: f

    call get_int(tab, name, 'k', k, f)
    call get_reals(tab, name, 't', t, f)
    call get_reals(tab, name, 'c', c, f)
    call get_reals(tab, name, 'x', x, f)
    call get_reals(tab, name, 'y', yref, f)
    n = size(t)
    m = size(x)
    allocate (y(m), wrk(n))
    scale = maxval(abs(c))
    ! values: sums of k+1 products, rounding of the coefficient scale
    call splev(t, n, c, k, x, y, m, ier)
    call expect(ier == 0, name//': splev ier')
    call expect_close_array(y, yref, 1e-13_real64, 1e-13_real64*scale, name//': splev (clamped outside)')
    do nu = 1, k
      write (key, '(a, i0)') 'y', nu
      call get_reals(tab, name, trim(key), yref, f)
      call splder(t, n, c, k, nu, x, y, m, wrk, ier)
      call expect(ier == 0, name//': splder ier')
      ! derivative coefficients are divided differences: scale grows with 1/h**nu
      call expect_close_array(y, yref, 1e-11_real64, 1e-11_real64*maxval(abs(yref)), name//': splder '//trim(key))
    end do
    ! all derivatives at scattered points, right-hand at an interior knot
    call get_reals(tab, name, 'xa', xa, f)
    call get_reals(tab, name, 'd', dref, f)
    allocate (d(k + 1))
    do i = 1, size(xa)
      call spalde(t, n, c, k + 1, xa(i), d, ier)
      call expect(ier == 0, name//': spalde ier')
      do j = 1, k + 1
        call expect_close(d(j), dref((i - 1)*(k + 1) + j), 1e-11_real64, &
                          1e-11_real64*maxval(abs(dref(j::k + 1))), name//': spalde')
      end do
    end do
    ! cualde equals repeated splder, coordinate by coordinate (idim = 3)
    nc = 3*n
    allocate (c3(nc), d3(3*(k + 1)), yj(1), xc(1), u(1))
    c3(1:n) = c
    c3(n + 1:2*n) = 2*c - 1
    c3(2*n + 1:3*n) = c(n:1:-1)
    c3(n - k:n) = 0
    c3(2*n - k:2*n) = 0
    c3(3*n - k:3*n) = 0
    do i = 1, size(xa)
      call cualde(3, t, n, c3, nc, k + 1, xa(i), d3, size(d3), ier)
      call expect(ier == 0, name//': cualde ier')
      do j = 1, 3
        do nu = 0, k
          xc(1) = xa(i)
          call splder(t, n, c3((j - 1)*n + 1:j*n), k, nu, xc, yj, 1, wrk, ier)
          call expect_close(d3(3*nu + j), yj(1), 1e-12_real64, 1e-12_real64*maxval(abs(d3(3*nu + 1::3))), &
                            name//': cualde = splder')
        end do
      end do
    end do
    ! curev equals splev per coordinate
    deallocate (y)
    allocate (y(3*m))
    call curev(3, t, n, c3, nc, k, x, m, y, 3*m, ier)
    call expect(ier == 0, name//': curev ier')
    do j = 1, 3
      call splev(t, n, c3((j - 1)*n + 1:j*n), k, x, yref, m, ier)
      call expect_close_array(y(j::3), yref, 1e-14_real64, 1e-14_real64*maxval(abs(c3)), name//': curev = splev')
    end do
    ! knot insertion
    call get_real(tab, name, 'xins', xins, f)
    call get_reals(tab, name, 'tt', ttref, f)
    call get_reals(tab, name, 'cc', ccref, f)
    nest = n + 1
    allocate (tt(nest), cc(nest))
    block
      real(real64) :: tp(nest), cp(nest)
      tp = 0
      cp = 0
      tp(1:n) = t
      cp(1:n) = c
      call insert(0, tp, n, cp, k, xins, tt, nn, cc, nest, ier)
    end block
    call expect(ier == 0 .and. nn == n + 1, name//': insert ier, nn')
    call expect_close_array(tt(1:nn), ttref(1:nn), 1e-15_real64, 0.0_real64, name//': insert knots')
    call expect_coefficients(cc(1:nn - k - 1), ccref(1:nn - k - 1), 1e-14_real64, name//': insert coefficients')
    ! integrals
    call get_reals(tab, name, 'ab', ab, f)
    call get_reals(tab, name, 'integrals', iref, f)
    do i = 1, size(iref)
      integral = splint(t, n, c, k, ab(2*i - 1), ab(2*i), wrk)
      ! quadrature exact for the degree: rounding of the coefficient scale times the length
      call expect_close(integral, iref(i), 1e-13_real64, 1e-13_real64*scale*4, name//': splint')
    end do
    ! zeros of a cubic
    if (has_key(tab, name, 'zeros')) then
      call get_reals(tab, name, 'tz', tz, f)
      call get_reals(tab, name, 'cz', cz, f)
      call get_reals(tab, name, 'zeros', zref, f)
      allocate (z(20))
      call sproot(tz, size(tz), cz, z, 20, mz, ier)
      call expect(ier == 0, name//': sproot ier')
      call expect(mz == size(zref), name//': sproot number of zeros')
      ! roots of cubics polished by Newton: well separated simple zeros to 1e-10
      if (mz == size(zref)) call expect_close_array(z(1:mz), zref, 1e-10_real64, 1e-10_real64, name//': sproot')
    end if
  end subroutine run_case

  !> Thesis fig. 2.4: cubic B-splines on [0 0 0 0 1 2 3 4 5 5 5 5] sum to one on [0, 5].
  subroutine thesis_figure_2_4()
    real(real64), parameter :: t(12) = [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5]
    real(real64) :: h(6), x, c(12), y(1), xs(1)
    integer :: i, l, ier
    do i = 0, 500
      x = 5*real(i, real64)/500
      l = min(4 + int(x), 8)
      call fpbspl(t, 12, 3, x, l, h)
      ! partition of unity: sum of four products, rounding only
      call expect_close(sum(h(1:4)), 1.0_real64, 4*epsilon(1.0_real64), 0.0_real64, 'fig. 2.4: basis sums to one')
      call expect(all(h(1:4) >= 0), 'fig. 2.4: basis non-negative')
    end do
    ! the same through splev with all coefficients one
    c = 1
    do i = 0, 50
      xs(1) = 5*real(i, real64)/50
      call splev(t, 12, c, 3, xs, y, 1, ier)
      call expect_close(y(1), 1.0_real64, 4*epsilon(1.0_real64), 0.0_real64, 'fig. 2.4: splev of ones')
    end do
  end subroutine thesis_figure_2_4
end program test_curves_eval
