!> parcur and clocur against the genuine FITPACK (tables made by
!> scripts/reference/fitpack_curves.py).
program test_curves_parcur
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: parcur, clocur
  use fitpack_reference_io
  implicit none (type, external)
  type(reference_table_t) :: tab
  logical :: ok
  integer :: ic

  call load_table(reference_path('curves_parcur.txt'), tab, ok)
  call expect(ok, 'read curves_parcur.txt')
  if (ok) then
    call expect(tab%n_cases >= 20, 'enough parcur cases')
    do ic = 1, tab%n_cases
      call run_case(trim(tab%case_names(ic)), .false.)
    end do
  end if
  call load_table(reference_path('curves_clocur.txt'), tab, ok)
  call expect(ok, 'read curves_clocur.txt')
  if (ok) then
    do ic = 1, tab%n_cases
      call run_case(trim(tab%case_names(ic)), .true.)
    end do
  end if
  call netlib_input_checks()
  call finish_checks('fitpack parcur/clocur')

contains

  subroutine run_case(name, closed)
    character(len=*), intent(in) :: name
    logical, intent(in) :: closed
    real(real64), allocatable :: u(:), x(:), w(:), tin(:), tref(:), cref(:), uref(:), t(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    real(real64) :: s, s_first, ub, ue, fp, fpref, rtol_c
    integer :: iopt, ipar, idim, k, nest, lwrk, n, ier, ierref, nref, m, j, nc
    character(len=8) :: key
    logical :: f

    call get_int(tab, name, 'iopt', iopt, f)
    call get_int(tab, name, 'ipar', ipar, f)
    call get_int(tab, name, 'idim', idim, f)
    call get_int(tab, name, 'k', k, f)
    call get_int(tab, name, 'nest', nest, f)
    call get_real(tab, name, 's', s, f)
    call get_reals(tab, name, 'u', u, f)
    call get_reals(tab, name, 'x', x, f)
    call get_reals(tab, name, 'w', w, f)
    call get_int(tab, name, 'ier', ierref, f)
    m = size(u)
    ub = 0
    ue = 0
    if (.not. closed) then
      call get_real(tab, name, 'ub', ub, f)
      call get_real(tab, name, 'ue', ue, f)
      lwrk = m*(k + 1) + nest*(6 + idim + 3*k)
    else
      lwrk = m*(k + 1) + nest*(7 + idim + 5*k)
    end if
    nc = nest*idim
    allocate (t(nest), c(nc), wrk(lwrk), iwrk(nest))
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
      call parcur(0, ipar, idim, m, u, size(x), x, w, ub, ue, k, s_first, nest, n, t, nc, c, fp, &
                  wrk, lwrk, iwrk, ier)
    end if
    if (closed) then
      call clocur(iopt, ipar, idim, m, u, size(x), x, w, k, s, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    else
      call parcur(iopt, ipar, idim, m, u, size(x), x, w, ub, ue, k, s, nest, n, t, nc, c, fp, &
                  wrk, lwrk, iwrk, ier)
    end if
    call expect(ier == ierref, name//': ier')
    if (ier /= ierref) print '(a, 2i6)', '   ier got/expected ', ier, ierref
    if (ierref == 10 .or. ier /= ierref) return
    if (has_key(tab, name, 'u_out') .and. ipar == 0) then
      call get_reals(tab, name, 'u_out', uref, f)
      ! chord-length parameters: sums of square roots, rounding only
      call expect_close_array(u, uref, 1e-13_real64, 1e-14_real64, name//': chord-length parameters')
    end if
    call get_int(tab, name, 'n', nref, f)
    call expect(n == nref, name//': number of knots')
    if (n /= nref) then
      print '(a, 2i6)', '   n got/expected ', n, nref
      return
    end if
    call get_reals(tab, name, 't', tref, f)
    call get_real(tab, name, 'fp', fpref, f)
    ! knots are parameter values or their midpoints (periodic: shifted by the period)
    call expect_close_array(t(1:n), tref, 1e-12_real64, 1e-12_real64*maxval(abs(tref)), name//': knots')
    ! unique results to 1e-10, p-iteration results to 1e-8, each coefficient relative to
    ! itself (floor: see expect_coefficients)
    rtol_c = 1e-8_real64
    if (iopt == -1 .or. s == 0 .or. ier == -1 .or. ier == -2) rtol_c = 1e-10_real64
    ! (closed_maxit_a/b, ier = 3, take the p-iteration's one-sided steps: with
    ! exactly 0.04 instead of genuine's single-precision value they miss by 4e-7)
    do j = 1, idim
      write (key, '(a, i0)') 'c', j
      call get_reals(tab, name, trim(key), cref, f)
      call expect_coefficients(c(n*(j - 1) + 1:n*(j - 1) + n - k - 1), cref, rtol_c, &
                               name//': coefficients '//trim(key))
    end do
    call expect_close(fp, fpref, rtol_c, rtol_c*sum(x**2)*1e-6_real64, name//': fp')
  end subroutine run_case

  !> Conditions under which netlib's parcur and clocur return ier = 10 (scipy's
  !> glue raises before returning them, so they have no reference table).
  subroutine netlib_input_checks()
    integer, parameter :: m = 20, idim = 2, k = 3, nest = 40, nc = nest*idim
    integer, parameter :: lwrk = m*(k + 1) + nest*(7 + idim + 5*k)
    real(real64) :: u(m), x(idim*m), w(m), t(nest), c(nc), wrk(lwrk), fp, ub, ue
    integer :: iwrk(nest), n, ier, i
    do i = 1, m
      u(i) = real(i - 1, real64)/(m - 1)
      x(2*i - 1) = cos(6.283185307179586_real64*u(i))
      x(2*i) = sin(6.283185307179586_real64*u(i))
    end do
    x(2*m - 1:2*m) = x(1:2)
    w = 1
    ub = 0
    ue = 1
    call parcur(0, 2, idim, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'parcur: ipar = 2 gives ier 10')
    call parcur(0, 1, 11, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'parcur: idim = 11 gives ier 10')
    ub = 0.1_real64
    call parcur(0, 1, idim, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'parcur: ub > u(1) gives ier 10')
    ub = 0
    call parcur(0, 1, idim, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc - 1, c, fp, wrk, lwrk, &
                iwrk, ier)
    call expect(ier == 10, 'parcur: nc < nest*idim gives ier 10')
    call parcur(0, 1, idim, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 0, 'parcur: valid input accepted')
    call clocur(0, 1, idim, m, u, idim*m, x, w, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 0, 'clocur: valid input accepted')
    x(2*m) = x(2*m) + 1e-9_real64
    call clocur(0, 1, idim, m, u, idim*m, x, w, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'clocur: last point different from the first gives ier 10')
    x(2*m) = x(2)
    u(4) = u(3)
    call clocur(0, 1, idim, m, u, idim*m, x, w, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'clocur: repeated parameter gives ier 10')
    call parcur(0, 1, idim, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'parcur: repeated parameter gives ier 10')
    ! chord length with all points equal: no parametrization
    x = 1
    call parcur(0, 0, idim, m, u, idim*m, x, w, ub, ue, k, 0.1_real64, nest, n, t, nc, c, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'parcur: coincident points with ipar = 0 give ier 10')
  end subroutine netlib_input_checks
end program test_curves_parcur
