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
  call netlib_input_checks()
  call continuation_consistency()
  call finish_checks('fitpack percur')

contains

  subroutine run_case(name)
    character(len=*), intent(in) :: name
    real(real64), allocatable :: x(:), y(:), w(:), tin(:), tref(:), cref(:), t(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    real(real64) :: s, s_first, fp, fpref, rtol_c
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
    if (has_key(tab, name, 'genuine_corrupt')) then
      ! the original writes outside its arrays here (no interval holding data
      ! carries residual) and returns unordered knots; what must hold for ours:
      ! a valid spline, either smoothing (|fp - s| <= 0.001 s) or ier = 2 with the
      ! least-squares spline on its knots (fp > s)
      call expect(all(t(2:n) >= t(1:n - 1)) .and. all(abs(c(1:n - k - 1)) <= huge(1.0_real64)) &
                  .and. abs(fp) <= huge(1.0_real64), name//': ordered knots, finite coefficients and fp')
      call expect((ier == 0 .and. abs(fp - s) <= 1e-3_real64*s) .or. (ier == 2 .and. fp > s), &
                  name//': smoothing spline or ier 2')
      return
    end if
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
    ! each coefficient relative to itself (floor: see expect_coefficients)
    rtol_c = 1e-8_real64
    if (iopt == -1 .or. s == 0 .or. ier == -1 .or. ier == -2) rtol_c = 1e-10_real64
    ! (weights of the last point do not enter: it repeats the first)
    call expect_coefficients(c(1:n - k - 1), cref, rtol_c, name//': coefficients')
    ! fp of an interpolating spline is rounding noise: compare against the data size
    call expect_close(fp, fpref, rtol_c, rtol_c*sum((w*y)**2)*1e-6_real64, name//': fp')
  end subroutine run_case


  !> Conditions under which netlib's percur returns ier = 10 (scipy's wrapper
  !> intercepts most of them before FITPACK, so they have no reference table).
  subroutine netlib_input_checks()
    integer, parameter :: m = 16, k = 3, nest = 30, lwrk = m*(k + 1) + nest*(8 + 5*k)
    real(real64) :: x(m), y(m), w(m), t(nest), c(nest), wrk(lwrk), fp
    integer :: iwrk(nest), n, ier, i
    do i = 1, m
      x(i) = 6.283185307179586_real64*(i - 1)/(m - 1)
    end do
    y = sin(x)
    y(m) = y(1)
    w = 1
    call percur(0, m, x, y, w, 6, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: k = 6 gives ier 10')
    call percur(0, m, x, y, w, k, -0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: s < 0 gives ier 10')
    call percur(0, m, x, y, w, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk - 1, iwrk, ier)
    call expect(ier == 10, 'percur: lwrk too small gives ier 10')
    call percur(0, m, x, y, w, k, 0.1_real64, 7, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: nest < 2k+2 gives ier 10')
    w(3) = 0
    call percur(0, m, x, y, w, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: w <= 0 gives ier 10')
    w(3) = 1
    w(m) = 0
    call percur(0, m, x, y, w, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 0, 'percur: the weight of the last point is not used')
    w(m) = 1
    ! given knots: too many in one data gap (periodic Schoenberg-Whitney fails)
    n = 13
    t(k + 2:n - k - 1) = [1.0_real64, 1.01_real64, 1.02_real64, 1.03_real64, 1.04_real64]
    call percur(-1, m, x, y, w, k, 0.0_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: given knots violating Schoenberg-Whitney give ier 10')
    n = 8
    call percur(-1, m, x, y, w, k, 0.0_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: given n <= 2k+2 gives ier 10')
    n = 10
    t(5:6) = [2.0_real64, 4.0_real64]
    call percur(-1, m, x, y, w, k, 0.0_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 0, 'percur: valid given knots accepted')
    x(5) = x(4)
    call percur(0, m, x, y, w, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'percur: repeated x gives ier 10')
  end subroutine netlib_input_checks

  !> iopt = 1 with the same s reproduces the iopt = 0 fit exactly (same knots, the
  !> same p-iteration); with a smaller s it keeps the knots and meets the new s.
  subroutine continuation_consistency()
    integer, parameter :: m = 60, k = 3, nest = m + 2*k, lwrk = m*(k + 1) + nest*(8 + 5*k)
    real(real64) :: x(m), y(m), w(m), t(nest), c(nest), wrk(lwrk), fp, t0(nest), c0(nest), fp0
    integer :: iwrk(nest), n, ier, i, n0
    do i = 1, m
      x(i) = 6.283185307179586_real64*((i - 1)/real(m - 1, real64))**1.1_real64
      y(i) = sin(x(i)) + 0.3_real64*cos(2*x(i)) + 0.05_real64*sin(37.0_real64*i)
    end do
    y(m) = y(1)
    w = 1
    call percur(0, m, x, y, w, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    n0 = n
    t0 = t
    c0 = c
    fp0 = fp
    call percur(1, m, x, y, w, k, 0.1_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 0 .and. n == n0, 'percur: iopt=1 with the same s keeps n')
    if (n == n0) then
      call expect(all(t(1:n) == t0(1:n)), 'percur: iopt=1 with the same s repeats the knots')
      call expect(all(c(1:n - k - 1) == c0(1:n - k - 1)), 'percur: iopt=1 with the same s repeats the coefficients')
      call expect(fp == fp0, 'percur: iopt=1 with the same s repeats fp')
      if (fp /= fp0) print *, fp, fp0
    end if
    call percur(1, m, x, y, w, k, 0.03_real64, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 0 .and. n >= n0 .and. abs(fp - 0.03_real64) < 0.001_real64*0.03_real64, &
                'percur: iopt=1 with a smaller s meets it with at least the old knots')
  end subroutine continuation_consistency
end program test_curves_percur
