!> concur, which scipy cannot reach, checked by what must hold (issue 3): it meets
!> its end derivatives, fp meets s within FITPACK's tolerance, and without end
!> constraints it equals parcur on the same data and parameters.
program test_curves_concur
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: concur, parcur, cualde
  use fitpack_reference_io, only: expect, expect_close, expect_close_array, expect_coefficients, finish_checks
  implicit none (type, external)
  integer, parameter :: m = 41, idim = 3, nest = m + 12, nc = nest*idim, np = 2*6*idim
  integer, parameter :: lwrk = m*6 + nest*(6 + idim + 15)
  real(real64) :: u(m), x(m*idim), w(m), xx(m*idim)
  real(real64) :: db(3*idim), de(3*idim)
  integer :: i, j, l, cases(3, 5), ic
  real(real64), parameter :: s_values(3) = [0.0_real64, 0.05_real64, 0.01_real64]
  character(len=64) :: label

  ! a noisy space curve on non-uniform parameters (deterministic "noise")
  do i = 1, m
    u(i) = 3*(real(i - 1, real64)/(m - 1))**1.2_real64
    x(idim*(i - 1) + 1) = cos(1.7_real64*u(i))*(1 + u(i)) + 0.02_real64*sin(37.0_real64*i)
    x(idim*(i - 1) + 2) = sin(1.7_real64*u(i))*(1 + u(i)) + 0.02_real64*cos(53.0_real64*i)
    x(idim*(i - 1) + 3) = 0.5_real64*u(i) + 0.02_real64*sin(71.0_real64*i)
  end do
  w = 1
  ! end derivatives of the underlying curve (exact), order 0..2
  do l = 0, 2
    do j = 1, idim
      db(idim*l + j) = exact_derivative(j, l, u(1))
      de(idim*l + j) = exact_derivative(j, l, u(m))
    end do
  end do

  call unconstrained_equals_parcur()
  ! (k, ib, ie) with several s
  cases(:, 1) = [3, 2, 2]
  cases(:, 2) = [3, 1, 0]
  cases(:, 3) = [5, 3, 1]
  cases(:, 4) = [1, 1, 1]
  cases(:, 5) = [5, 2, 3]
  do ic = 1, 5
    do i = 1, 3
      write (label, '(a, 3i2, a, i0)') 'concur k,ib,ie =', cases(:, ic), ' s#', i
      call constrained(cases(1, ic), cases(2, ic), cases(3, ic), s_values(i), &
                       trim(label))
    end do
  end do
  call invalid_inputs()
  call finish_checks('fitpack concur')

contains

  pure real(real64) function exact_derivative(j, l, s) result(d)
    integer, intent(in) :: j, l
    real(real64), intent(in) :: s
    real(real64), parameter :: a = 1.7_real64
    select case (j)
    case (1)
      select case (l)
      case (0); d = cos(a*s)*(1 + s)
      case (1); d = -a*sin(a*s)*(1 + s) + cos(a*s)
      case default; d = -a*a*cos(a*s)*(1 + s) - 2*a*sin(a*s)
      end select
    case (2)
      select case (l)
      case (0); d = sin(a*s)*(1 + s)
      case (1); d = a*cos(a*s)*(1 + s) + sin(a*s)
      case default; d = -a*a*sin(a*s)*(1 + s) + 2*a*cos(a*s)
      end select
    case default
      select case (l)
      case (0); d = 0.5_real64*s
      case (1); d = 0.5_real64
      case default; d = 0
      end select
    end select
  end function exact_derivative

  subroutine unconstrained_equals_parcur()
    real(real64) :: t1(nest), c1(nc), t2(nest), c2(nc), cp(np), wrk1(lwrk), wrk2(lwrk), fp1, fp2, uu(m), &
                    ub, ue, s
    integer :: iw1(nest), iw2(nest), n1, n2, ier1, ier2, k, is
    real(real64) :: dummy(1)
    do k = 1, 5, 2
      do is = 1, 3
        s = s_values(is)
        uu = u
        ub = u(1)
        ue = u(m)
        call parcur(0, 1, idim, m, uu, m*idim, x, w, ub, ue, k, s, nest, n1, t1, nc, c1, fp1, wrk1, lwrk, &
                    iw1, ier1)
        call concur(0, idim, m, u, m*idim, x, xx, w, 0, dummy, 1, 0, dummy, 1, k, s, nest, n2, t2, nc, c2, &
                    np, cp, fp2, wrk2, lwrk, iw2, ier2)
        write (label, '(a, i0, a, es8.1)') 'concur without constraints = parcur, k = ', k, ' s = ', s
        call expect(ier1 == ier2 .and. n1 == n2, trim(label)//': ier and n')
        if (n1 /= n2) cycle
        ! same engine on the same numbers: equal to rounding
        call expect_close_array(t2(1:n2), t1(1:n1), 1e-15_real64, 0.0_real64, trim(label)//': knots')
        do j = 1, idim
          call expect_coefficients(c2(n2*(j - 1) + 1:n2*(j - 1) + n2 - k - 1), c1(n1*(j - 1) + 1:n1*(j - 1) + n1 - k - 1), &
                                   1e-13_real64, trim(label)//': coefficients')
        end do
        call expect_close(fp2, fp1, 1e-12_real64, 1e-20_real64, trim(label)//': fp')
      end do
    end do
  end subroutine unconstrained_equals_parcur

  subroutine constrained(k, ib, ie, s, what)
    integer, intent(in) :: k, ib, ie
    real(real64), intent(in) :: s
    character(len=*), intent(in) :: what
    real(real64) :: t(nest), c(nc), cp(np), wrk(lwrk), fp, res, s2
    integer :: iwrk(nest), n, ier, n0, iopt
    real(real64), allocatable :: tsave(:)
    call concur(0, idim, m, u, m*idim, x, xx, w, ib, db, size(db), ie, de, size(de), k, s, nest, n, t, nc, c, &
                np, cp, fp, wrk, lwrk, iwrk, ier)
    if (s == 0) then
      call expect(ier == -1, what//': interpolation ier = -1')
    else
      call expect(ier == 0, what//': ier = 0')
      ! FITPACK's acceptance: |fp - s| < 0.001 s
      call expect(abs(fp - s) < 0.001_real64*s, what//': |fp - s| < 0.001 s')
    end if
    if (ier > 0) return
    ! fp is the residual of the whole curve
    res = residual(k, n, t, c)
    call expect_close(fp, res, 1e-10_real64, 1e-14_real64, what//': fp is the residual sum')
    call check_ends(k, ib, ie, n, t, c, what)
    ! continuation with a smaller s keeps meeting the constraints
    if (s > 0) then
      n0 = n
      tsave = t(1:n)
      iopt = 1
      s2 = 0.5_real64*s
      call concur(iopt, idim, m, u, m*idim, x, xx, w, ib, db, size(db), ie, de, size(de), k, s2, nest, n, t, &
                  nc, c, np, cp, fp, wrk, lwrk, iwrk, ier)
      call expect(ier == 0 .and. abs(fp - s2) < 0.001_real64*s2, what//': iopt=1 continuation fp = s/2')
      call expect(n >= n0, what//': continuation keeps the knots')
      if (ier == 0) call check_ends(k, ib, ie, n, t, c, what//' (iopt=1)')
      ! least squares on the final knots (iopt=-1) meets the constraints too
      call concur(-1, idim, m, u, m*idim, x, xx, w, ib, db, size(db), ie, de, size(de), k, 0.0_real64, nest, n, &
                  t, nc, c, np, cp, fp, wrk, lwrk, iwrk, ier)
      call expect(ier == 0, what//': iopt=-1 ier')
      if (ier == 0) call check_ends(k, ib, ie, n, t, c, what//' (iopt=-1)')
    end if
  end subroutine constrained

  subroutine check_ends(k, ib, ie, n, t, c, what)
    integer, intent(in) :: k, ib, ie, n
    real(real64), intent(in) :: t(n), c(:)
    character(len=*), intent(in) :: what
    real(real64) :: d((k + 1)*idim), scale
    integer :: ier, l, jj
    character(len=96) :: tag
    call cualde(idim, t, n, c, size(c), k + 1, u(1), d, size(d), ier)
    call expect(ier == 0, what//': cualde at u(1)')
    do l = 0, ib - 1
      do jj = 1, idim
        ! derivative l of a polynomial of size ~5 on [0,3]: scale 5**... use the constraint's size
        scale = max(1.0_real64, abs(db(idim*l + jj)))
        write (tag, '(a, i0, a, i0)') ': start derivative ', l, ' coordinate ', jj
        call expect_close(d(idim*l + jj), db(idim*l + jj), 0.0_real64, 1e-10_real64*scale, what//trim(tag))
      end do
    end do
    call cualde(idim, t, n, c, size(c), k + 1, u(m), d, size(d), ier)
    call expect(ier == 0, what//': cualde at u(m)')
    do l = 0, ie - 1
      do jj = 1, idim
        scale = max(1.0_real64, abs(de(idim*l + jj)))
        write (tag, '(a, i0, a, i0)') ': end derivative ', l, ' coordinate ', jj
        call expect_close(d(idim*l + jj), de(idim*l + jj), 0.0_real64, 1e-10_real64*scale, what//trim(tag))
      end do
    end do
  end subroutine check_ends

  real(real64) function residual(k, n, t, c) result(r)
    use fitpack_interfaces, only: curev
    integer, intent(in) :: k, n
    real(real64), intent(in) :: t(n), c(:)
    real(real64) :: p(m*idim)
    integer :: ier
    call curev(idim, t, n, c, size(c), k, u, m, p, m*idim, ier)
    r = sum((x - p)**2)
  end function residual

  subroutine invalid_inputs()
    real(real64) :: t(nest), c(nc), cp(np), wrk(lwrk), fp
    integer :: iwrk(nest), n, ier
    call concur(0, idim, m, u, m*idim, x, xx, w, 1, db, size(db), 1, de, size(de), 2, 0.1_real64, nest, n, t, nc, &
                c, np, cp, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'concur: even k gives ier 10')
    call concur(0, idim, m, u, m*idim, x, xx, w, 3, db, size(db), 1, de, size(de), 3, 0.1_real64, nest, n, t, nc, &
                c, np, cp, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'concur: ib > (k+1)/2 gives ier 10')
    call concur(0, idim, m, u, m*idim, x, xx, w, 1, db, size(db), 1, de, size(de), 3, 0.1_real64, nest, n, t, nc, &
                c, 2*4*idim - 1, cp, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'concur: np too small gives ier 10')
    call concur(0, idim, m, u, m*idim, x, xx, w, 1, db, size(db), 1, de, size(de), 3, -0.1_real64, nest, n, t, nc, &
                c, np, cp, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'concur: s < 0 gives ier 10')
    call concur(0, idim, m, u, m*idim, x, xx, w, 1, db, 1, 1, de, size(de), 3, 0.1_real64, nest, n, t, nc, &
                c, np, cp, fp, wrk, lwrk, iwrk, ier)
    call expect(ier == 10, 'concur: nb < ib*idim gives ier 10')
  end subroutine invalid_inputs
end program test_curves_concur
