!> numerics_linear_algebra: LU, Cholesky, QR and the normal-matrix inverse against
!> matrices with known answers, and the translation of LAPACK's info; the small
!> systems' own LU and Cholesky against LAPACK's (same pivots, same factors);
!> the products a^T b of the mass matrix and the Cholesky factor and solve of
!> every small order (5 has its own kernels) against plain loops, bit for bit.
program test_linear_algebra
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_DOMAIN
  use numerics_linear_algebra, only: lu_factor, lu_solve, lu_reciprocal_condition, one_norm, &
    cholesky_factor, cholesky_solve, normal_matrix_inverse, triangular_inverse, small_order, &
    transposed_product, symmetric_transposed_product
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! rtol 1e-12: 4x4 systems with condition numbers below 1e3, solved in double precision
  real(wp), parameter :: tol = 1e-12_wp

  call lu_systems()
  call lu_singular()
  call condition_estimate()
  call cholesky_systems()
  call normal_inverse()
  call small_against_lapack()
  call pair_products()
  call cholesky_orders()
  call finish_tests('test_linear_algebra')

contains

  !> A 4 x 4 matrix with a unit lower / upper structure whose solution is known.
  function sample_matrix() result(a)
    real(wp) :: a(4, 4)
    a = reshape([4.0_wp, 1.0_wp, -2.0_wp, 0.5_wp, &
                 1.0_wp, 5.0_wp, 0.0_wp, 1.0_wp, &
                 0.0_wp, -1.0_wp, 6.0_wp, 2.0_wp, &
                 3.0_wp, 0.0_wp, 1.0_wp, 7.0_wp], [4, 4])
  end function sample_matrix

  subroutine lu_systems()
    real(wp) :: a(4, 4), lu(4, 4), x(4), b(4), bm(4, 2)
    integer :: ipiv(4), failed
    type(status_t) :: status
    a = sample_matrix()
    x = [1.0_wp, -2.0_wp, 0.5_wp, 3.0_wp]
    lu = a
    call lu_factor(lu, ipiv, status, failed)
    call check(status%ok() .and. failed == 0, 'lu_factor of a regular matrix: '//status%text())
    b = matmul(a, x)
    call lu_solve(lu, ipiv, b, status)
    call check_close_array(b, x, tol, tol, 'lu_solve: A x = b')
    b = matmul(transpose(a), x)
    call lu_solve(lu, ipiv, b, status, transpose=.true.)
    call check_close_array(b, x, tol, tol, 'lu_solve: A^T x = b')
    bm(:, 1) = matmul(a, x)
    bm(:, 2) = matmul(a, 2*x)
    call lu_solve(lu, ipiv, bm, status)
    call check_close_array(bm(:, 2), 2*x, tol, tol, 'lu_solve: two right-hand sides')
    call check(status%ok(), 'lu_solve status ok')
  end subroutine lu_systems

  subroutine lu_singular()
    real(wp) :: a(3, 3)
    integer :: ipiv(3), failed
    type(status_t) :: status
    ! third column = first + second: exactly singular in binary arithmetic
    a = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp, 1.0_wp, 0.0_wp], [3, 3])
    call lu_factor(a, ipiv, status, failed)
    call check(status%code == STATUS_DOMAIN, 'singular matrix: STATUS_DOMAIN')
    call check(failed == 3, 'singular matrix: the zero pivot is the third')
    call check(index(status%text(), 'lu_factor') > 0, 'message names the routine: '//status%text())
  end subroutine lu_singular

  subroutine condition_estimate()
    real(wp) :: a(3, 3), lu(3, 3), rcond
    integer :: ipiv(3)
    type(status_t) :: status
    ! diagonal: ||A||_1 ||A^-1||_1 = 100 * 1 exactly, and dgecon is exact for diagonals
    a = 0
    a(1, 1) = 100
    a(2, 2) = 1
    a(3, 3) = 10
    lu = a
    call lu_factor(lu, ipiv, status)
    call check_close(one_norm(a), 100.0_wp, 0.0_wp, 0.0_wp, 'one_norm of the diagonal')
    call lu_reciprocal_condition(lu, one_norm(a), rcond, status)
    call check(status%ok(), 'dgecon status')
    call check_close(rcond, 0.01_wp, tol, 0.0_wp, 'reciprocal condition of diag(100, 1, 10)')
  end subroutine condition_estimate

  subroutine cholesky_systems()
    real(wp) :: a(4, 4), l(4, 4), x(4), b(4), s(2, 2)
    integer :: failed
    type(status_t) :: status
    a = sample_matrix()
    a = matmul(transpose(a), a)   ! symmetric positive definite
    x = [0.25_wp, -1.0_wp, 2.0_wp, 1.5_wp]
    l = a
    call cholesky_factor(l, status, failed)
    call check(status%ok() .and. failed == 0, 'cholesky_factor of A^T A: '//status%text())
    b = matmul(a, x)
    call cholesky_solve(l, b, status)
    ! rtol 1e-11: A^T A squares the condition number of the sample matrix (< 1e3)
    call check_close_array(b, x, 1e-11_wp, 1e-11_wp, 'cholesky_solve: A x = b')
    s = reshape([1.0_wp, 2.0_wp, 2.0_wp, 1.0_wp], [2, 2])   ! eigenvalues 3 and -1
    call cholesky_factor(s, status, failed)
    call check(status%code == STATUS_DOMAIN .and. failed == 2, &
               'indefinite matrix: STATUS_DOMAIN at column 2: '//status%text())
  end subroutine cholesky_systems

  subroutine normal_inverse()
    real(wp) :: j(5, 2), inverse(2, 2), expected(2, 2), jtj(2, 2), r(2, 2)
    type(status_t) :: status
    integer :: i, failed
    ! a line fit's design matrix: (J^T J)^-1 in closed form from the 2 x 2 inverse
    j(:, 1) = 1
    j(:, 2) = [(0.5_wp*i, i=0, 4)]
    jtj = matmul(transpose(j), j)
    expected = reshape([jtj(2, 2), -jtj(2, 1), -jtj(1, 2), jtj(1, 1)], [2, 2]) &
               /(jtj(1, 1)*jtj(2, 2) - jtj(1, 2)*jtj(2, 1))
    call normal_matrix_inverse(j, inverse, status)
    call check(status%ok(), 'normal_matrix_inverse: '//status%text())
    call check_close_array(reshape(inverse, [4]), reshape(expected, [4]), tol, tol, &
                           '(J^T J)^-1 of a line fit')
    j(:, 2) = 3*j(:, 1)   ! rank 1
    call normal_matrix_inverse(j, inverse, status)
    call check(status%code == STATUS_DOMAIN .and. index(status%text(), 'column 2') > 0, &
               'rank-deficient J refused naming column 2: '//status%text())
    r = reshape([2.0_wp, 0.0_wp, 1.0_wp, 0.0_wp], [2, 2])
    status = status_t()
    call triangular_inverse(r, status, failed)
    call check(status%code == STATUS_DOMAIN .and. failed == 2, 'singular triangle: zero diagonal at 2')
  end subroutine normal_inverse

  !> Orders 1 to small_order + 2 (both sides of the switch to LAPACK): the
  !> factors of lu_factor and cholesky_factor equal dgetrf's and dpotrf's
  !> (same pivots; entries to 1e-13 relative: the same arithmetic in another
  !> order), and the solves (A x = b, A^T x = b, several columns) recover x.
  subroutine small_against_lapack()
    interface
      subroutine dgetrf(m, n, a, lda, ipiv, info)
        import :: wp
        integer, intent(in) :: m, n, lda
        real(wp), intent(inout) :: a(lda, *)
        integer, intent(out) :: ipiv(*), info
      end subroutine dgetrf
      subroutine dpotrf(uplo, n, a, lda, info)
        import :: wp
        character, intent(in) :: uplo
        integer, intent(in) :: n, lda
        real(wp), intent(inout) :: a(lda, *)
        integer, intent(out) :: info
      end subroutine dpotrf
    end interface
    real(wp), allocatable :: a(:, :), lu(:, :), ref(:, :), x(:), b(:), bm(:, :), spd(:, :)
    integer, allocatable :: ipiv(:), ipiv_ref(:)
    type(status_t) :: status
    integer :: n, i, j, info
    character(len=8) :: order
    do n = 1, small_order + 2
      write (order, '(i0)') n
      allocate (a(n, n), x(n), ipiv(n), ipiv_ref(n))
      do j = 1, n   ! a scattered, well-conditioned matrix whose pivots move rows
        do i = 1, n
          a(i, j) = sin(1.7_wp*i + 0.9_wp*j*j) + merge(0.5_wp*n, 0.0_wp, i == n + 1 - j)
        end do
        x(j) = cos(0.3_wp*j) - 0.2_wp
      end do
      lu = a
      ref = a
      call lu_factor(lu, ipiv, status)
      call dgetrf(n, n, ref, n, ipiv_ref, info)
      call check(status%ok() .and. info == 0 .and. all(ipiv == ipiv_ref), 'LU of order '//trim(order)// &
                 ': the pivots of dgetrf')
      ! 1e-13: the same eliminations, summed in another order (condition below 1e2)
      call check_close_array(reshape(lu, [n*n]), reshape(ref, [n*n]), 1e-13_wp, 1e-13_wp, &
                             'LU of order '//trim(order)//': the factors of dgetrf')
      b = matmul(a, x)
      call lu_solve(lu, ipiv, b, status)
      call check_close_array(b, x, tol, tol, 'LU of order '//trim(order)//': A x = b')
      b = matmul(transpose(a), x)
      call lu_solve(lu, ipiv, b, status, transpose=.true.)
      call check_close_array(b, x, tol, tol, 'LU of order '//trim(order)//': A^T x = b')
      bm = reshape([matmul(a, x), matmul(a, -3*x)], [n, 2])
      call lu_solve(lu, ipiv, bm, status)
      call check_close_array(bm(:, 2), -3*x, tol, tol, 'LU of order '//trim(order)//': two columns')
      spd = matmul(transpose(a), a)
      lu = spd
      ref = spd
      call cholesky_factor(lu, status)
      call dpotrf('L', n, ref, n, info)
      call check(status%ok() .and. info == 0, 'Cholesky of order '//trim(order)//': positive definite')
      do j = 1, n
        call check_close_array(lu(j:, j), ref(j:, j), 1e-13_wp, 1e-13_wp, 'Cholesky of order '//trim(order)// &
                               ': the factor of dpotrf')
      end do
      b = matmul(spd, x)
      call cholesky_solve(lu, b, status)
      ! 1e-11: A^T A squares the condition number (below 1e2)
      call check_close_array(b, x, 1e-11_wp, 1e-11_wp, 'Cholesky of order '//trim(order)//': A x = b')
      bm = reshape([matmul(spd, x), matmul(spd, 2*x)], [n, 2])
      call cholesky_solve(lu, bm, status)
      call check_close_array(bm(:, 2), 2*x, 1e-11_wp, 1e-11_wp, 'Cholesky of order '//trim(order)//': two columns')
      call check(status%ok(), 'solves of order '//trim(order)//': status ok')
      deallocate (a, x, ipiv, ipiv_ref)
    end do
  end subroutine small_against_lapack
  !> transposed_product and symmetric_transposed_product on random input
  !> against the plain loop summed from 0 in index order, compared exactly
  !> (the kernels promise that order; the 6-vector case is unrolled), for the
  !> lengths 6 (unrolled), 12 and 0 and a non-square product.
  subroutine pair_products()
    integer, parameter :: lengths(3) = [6, 12, 0]
    real(wp), allocatable :: a(:, :), b(:, :), c(:, :), full(:, :), lower(:, :), ref(:, :)
    real(wp) :: p
    integer :: il, l, n, m, i, k, j
    character(len=8) :: length
    n = 4
    m = 3
    do il = 1, size(lengths)
      l = lengths(il)
      write (length, '(i0)') l
      allocate (a(l, n), b(l, n), c(n, m), ref(n, n), full(n, n), lower(n, n))
      call random_number(a)
      call random_number(b)
      a = a - 0.5_wp
      b = 1e3_wp*(b - 0.5_wp)   ! mixed magnitudes: an order change would show
      do i = 1, n
        do k = 1, n
          p = 0
          do j = 1, l
            p = p + a(j, k)*b(j, i)
          end do
          ref(k, i) = p
        end do
      end do
      call transposed_product(l, n, m, a, b, c)
      call check(all(c == ref(:, 1:m)), 'transposed_product, length '//trim(length)//': the plain loop''s sums')
      full = huge(1.0_wp)
      lower = huge(1.0_wp)
      call symmetric_transposed_product(l, n, a, b, -1.0_wp, full, lower)
      do i = 1, n
        do k = 1, i
          call check(full(k, i) == -ref(k, i) .and. full(i, k) == -ref(k, i) .and. lower(i, k) == -ref(k, i), &
                     'symmetric_transposed_product, length '//trim(length)//': -a(:, k) . b(:, i), k <= i, mirrored')
          if (k < i) call check(lower(k, i) == huge(1.0_wp), 'symmetric_transposed_product: the upper triangle '// &
                                'of lower untouched')
        end do
      end do
      deallocate (a, b, c, ref, full, lower)
    end do
  end subroutine pair_products
  !> cholesky_factor and cholesky_solve of orders 3 to 7 (5 runs its own
  !> kernels) on 20 random positive definite matrices each against the plain
  !> algorithm below, compared exactly: the kernels promise its operations
  !> in its order. And an indefinite 5 x 5 matrix fails at its column.
  subroutine cholesky_orders()
    real(wp), allocatable :: a(:, :), l(:, :), ref(:, :), b(:), x(:), scale(:)
    real(wp) :: t
    type(status_t) :: status
    integer :: n, i, j, k, failed, trial
    character(len=8) :: order
    do trial = 1, 20
      do n = 3, 7
        write (order, '(i0)') n
        allocate (a(n, n), b(n), scale(n))
        call random_number(a)
        call random_number(b)
        call random_number(scale)
        a = matmul(transpose(a - 0.5_wp), a - 0.5_wp) + 0.1_wp*reshape([((merge(1, 0, i == j), i = 1, n), j = 1, n)], &
                                                                       [n, n])
        scale = 10**(4*scale - 2)   ! D A D with D from 1e-2 to 1e2: sums of mixed magnitudes
        do j = 1, n
          a(:, j) = scale*a(:, j)*scale(j)
        end do
        b = b - 0.5_wp
        ref = a
        do j = 1, n   ! the plain algorithm: each entry of column j from one sum in k order
          do i = j, n
            t = ref(i, j)
            do k = 1, j - 1
              t = t - ref(i, k)*ref(j, k)
            end do
            if (i == j) then
              ref(j, j) = sqrt(t)
            else
              ref(i, j) = t/ref(j, j)
            end if
          end do
        end do
        x = b
        do k = 1, n   ! L y = b, L^T x = y
          t = x(k)
          do i = 1, k - 1
            t = t - ref(k, i)*x(i)
          end do
          x(k) = t/ref(k, k)
        end do
        do k = n, 1, -1
          t = x(k)
          do i = k + 1, n
            t = t - ref(i, k)*x(i)
          end do
          x(k) = t/ref(k, k)
        end do
        l = a
        call cholesky_factor(l, status, failed)
        call check(status%ok() .and. failed == 0, 'Cholesky of order '//trim(order)//': positive definite')
        do j = 1, n
          call check(all(l(j:, j) == ref(j:, j)), 'Cholesky of order '//trim(order)//': the plain algorithm''s factor')
        end do
        call cholesky_solve(l, b, status)
        call check(all(b == x), 'Cholesky of order '//trim(order)//': the plain algorithm''s solution')
        deallocate (a, b, scale)
      end do
    end do
    allocate (a(5, 5))
    a = 0
    do i = 1, 5
      a(i, i) = 2
    end do
    a(3, 2) = 3   ! rows 2 and 3: [2 3; 3 2], eigenvalue -1
    a(2, 3) = 3
    call cholesky_factor(a, status, failed)
    call check(status%code == STATUS_DOMAIN .and. failed == 3, &
               'indefinite 5 x 5 matrix: STATUS_DOMAIN at column 3: '//status%text())
  end subroutine cholesky_orders
end program test_linear_algebra
