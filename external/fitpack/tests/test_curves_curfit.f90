!> curfit against the genuine FITPACK (tables made by scripts/reference/fitpack_curves.py),
!> plus the ier = 10 input checks of netlib's curfit that scipy's wrapper intercepts.
program test_curves_curfit
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: curfit
  use fitpack_reference_io
  implicit none (type, external)
  type(reference_table_t) :: tab
  logical :: ok
  integer :: ic

  call load_table(reference_path('curves_curfit.txt'), tab, ok)
  call expect(ok, 'read curves_curfit.txt')
  if (ok) call expect(tab%n_cases >= 20, 'enough curfit cases')
  if (ok) then
    do ic = 1, tab%n_cases
      call run_case(trim(tab%case_names(ic)))
    end do
  end if
  call netlib_input_checks()
  call finish_checks('fitpack curfit')

contains

  subroutine run_case(name)
    character(len=*), intent(in) :: name
    real(real64), allocatable :: x(:), y(:), w(:), tin(:), tref(:), cref(:), t(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    real(real64) :: s, s_first, xb, xe, fp, fpref, rtol_c
    integer :: iopt, k, nest, lwrk, n, ier, ierref, nref
    logical :: f

    call get_int(tab, name, 'iopt', iopt, f)
    call get_int(tab, name, 'k', k, f)
    call get_int(tab, name, 'nest', nest, f)
    call get_int(tab, name, 'lwrk', lwrk, f)
    if (.not. f) lwrk = 0
    call get_real(tab, name, 's', s, f)
    call get_real(tab, name, 'xb', xb, f)
    call get_real(tab, name, 'xe', xe, f)
    call get_reals(tab, name, 'x', x, f)
    call get_reals(tab, name, 'y', y, f)
    call get_reals(tab, name, 'w', w, f)
    call get_int(tab, name, 'ier', ierref, f)
    if (lwrk == 0) lwrk = size(x)*(k + 1) + nest*(7 + 3*k)
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
      call curfit(0, size(x), x, y, w, xb, xe, k, s_first, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    end if
    call curfit(iopt, size(x), x, y, w, xb, xe, k, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
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
    ! knots are data points or midpoints: equal to rounding of the data scale
    call expect_close_array(t(1:n), tref, 1e-12_real64, 1e-12_real64*maxval(abs(tref)), name//': knots')
    ! unique results (given knots, interpolation, polynomial) to 1e-10, p-iteration results to 1e-8;
    ! each coefficient relative to itself (floor: see expect_coefficients)
    rtol_c = 1e-8_real64
    if (iopt == -1 .or. s == 0 .or. ier == -1 .or. ier == -2) rtol_c = 1e-10_real64
    call expect_coefficients(c(1:n - k - 1), cref, rtol_c, name//': coefficients')
    ! fp of an interpolating spline is rounding noise: compare against the data size
    call expect_close(fp, fpref, rtol_c, rtol_c*sum((w*y)**2)*1e-6_real64, name//': fp')
  end subroutine run_case

  !> Conditions under which netlib's curfit returns ier = 10 (scipy's f2py wrapper
  !> refuses them before FITPACK is reached, so they have no reference table).
  subroutine netlib_input_checks()
    integer, parameter :: m = 12, k = 3, nest = 20, lwrk = m*(k + 1) + nest*(7 + 3*k)
    real(real64) :: x(m), y(m), w(m), t(nest), c(nest), wrk(lwrk), fp
    integer :: iwrk(nest), n, ier, i
    do i = 1, m
      x(i) = real(i - 1, real64)/(m - 1)
    end do
    y = sin(3*x)
    w = 1
    call curfit(0, m, x, y, w, 0.1_real64, 1.0_real64, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: xb > x(1) gives ier 10')
    call curfit(0, m, x, y, w, 0.0_real64, 0.9_real64, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: xe < x(m) gives ier 10')
    call curfit(0, m, x, y, w, 0.0_real64, 1.0_real64, k, -0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: s < 0 gives ier 10')
    call curfit(0, m, x, y, w, 0.0_real64, 1.0_real64, 6, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: k = 6 gives ier 10')
    call curfit(0, 3, x, y, w, 0.0_real64, 1.0_real64, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: m < k+1 gives ier 10')
    w(5) = 0
    call curfit(0, m, x, y, w, 0.0_real64, 1.0_real64, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: w <= 0 gives ier 10')
    w(5) = 1
    x(6) = x(5)
    call curfit(0, m, x, y, w, 0.0_real64, 1.0_real64, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'curfit: repeated x gives ier 10')
  end subroutine netlib_input_checks
end program test_curves_curfit
