!> percur against the genuine FITPACK (tables made by scripts/reference/fitpack_curves.py).
program test_curves_percur
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: percur
  use fitpack_reference_io
  implicit none (type, external)
  type(reference_table_t) :: tab
  logical :: ok
  integer :: ic

  call load_table(reference_path('curves_percur.txt'), tab, ok)
  call expect(ok, 'read curves_percur.txt')
  if (ok) call expect(tab%n_cases >= 20, 'enough percur cases')
  if (ok) then
    do ic = 1, tab%n_cases
      call run_case(trim(tab%case_names(ic)))
    end do
  end if
  call finish_checks('fitpack percur')

contains

  subroutine run_case(name)
    character(len=*), intent(in) :: name
    real(real64), allocatable :: x(:), y(:), w(:), tin(:), tref(:), cref(:), t(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    real(real64) :: s, s_first, fp, fpref, rtol_c, scale
    integer :: iopt, k, nest, lwrk, n, ier, ierref, nref
    logical :: f

    call get_int(tab, name, 'iopt', iopt, f)
    call get_int(tab, name, 'k', k, f)
    call get_int(tab, name, 'nest', nest, f)
    call get_int(tab, name, 'lwrk', lwrk, f)
    if (.not. f) lwrk = 0
    call get_real(tab, name, 's', s, f)
    call get_reals(tab, name, 'x', x, f)
    call get_reals(tab, name, 'y', y, f)
    call get_reals(tab, name, 'w', w, f)
    call get_int(tab, name, 'ier', ierref, f)
    if (lwrk == 0) lwrk = size(x)*(k + 1) + nest*(8 + 5*k)
    allocate (t(max(nest, 1)), c(max(nest, 1)), wrk(lwrk), iwrk(max(nest, 1)))
    t = 0
    c = 0
    wrk = 0
    iwrk = 0
    n = 0
    fp = 0
    if (iopt == -1) then
      call get_int(tab, name, 'n_in', n, f)
      call get_reals(tab, name, 't_in', tin, f)
      t(1:n) = tin
    end if
    if (has_key(tab, name, 's_first')) then
      call get_real(tab, name, 's_first', s_first, f)
      call percur(0, size(x), x, y, w, k, s_first, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    end if
    call percur(iopt, size(x), x, y, w, k, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == ierref, name//': ier')
    if (ier /= ierref) print '(a, 2i6)', '   ier got/expected ', ier, ierref
    if (ierref == 10 .or. ier /= ierref) return
    call get_int(tab, name, 'n', nref, f)
    call expect(n == nref, name//': number of knots')
    if (n /= nref) then
      print '(a, 2i6)', '   n got/expected ', n, nref
      return
    end if
    call get_reals(tab, name, 't', tref, f)
    call get_reals(tab, name, 'c', cref, f)
    call get_real(tab, name, 'fp', fpref, f)
    ! knots are data points or midpoints (outer ones shifted by the period)
    call expect_close_array(t(1:n), tref, 1e-12_real64, 1e-12_real64*maxval(abs(tref)), name//': knots')
    ! unique results (given knots, interpolation, polynomial) to 1e-10, p-iteration results to 1e-8;
    ! atol relative to the largest coefficient: small ones carry the rounding of the large
    rtol_c = 1e-8_real64
    if (iopt == -1 .or. s == 0 .or. ier == -1 .or. ier == -2) rtol_c = 1e-10_real64
    ! (weights of the last point do not enter: it repeats the first)
    scale = maxval(abs(cref))
    call expect_close_array(c(1:n - k - 1), cref, rtol_c, rtol_c*scale, name//': coefficients')
    ! fp of an interpolating spline is rounding noise: compare against the data size
    call expect_close(fp, fpref, rtol_c, rtol_c*sum((w*y)**2)*1e-6_real64, name//': fp')
  end subroutine run_case

end program test_curves_percur
