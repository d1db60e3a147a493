!> Dense linear algebra over LAPACK: LU (dgetrf/dgetrs/dgecon), Cholesky
!> (dpotrf/dpotrs), QR (dgeqrf) and the inverse of a triangular factor (dtrtri).
!>
!> Every LAPACK call of slidesim goes through this module, and LAPACK's `info` is
!> translated here, once, right after each call (see `translate_info`):
!>   info < 0  an argument was illegal: a bug in the caller  -> STATUS_INTERNAL
!>   info > 0  the matrix is singular / not positive definite -> STATUS_DOMAIN,
!>             and `failed_index` (optional) returns info, the offending pivot
!>             or column, so a caller can name what it means (a coordinate, ...).
!> Arrays are `contiguous` assumed-shape (no copies, no allocation): the LU and
!> Cholesky routines run inside right-hand sides. Workspace is automatic (stack).
!>
!> Small systems (n <= small_order) are factored and solved here, without
!> LAPACK: for the 3 x 3 to 9 x 9 systems of a mechanism's right-hand side
!> LAPACK's blocking, argument checks and BLAS calls cost several times the
!> arithmetic (14 % of a ride's instructions). The same algorithms (LU with
!> partial pivoting on the first largest |a_ik|, row interchanges in ipiv as
!> dgetrf; Cholesky L L^T as dpotrf 'L'), the same factor layout (dgecon
!> reads these factors) and the same failure indices.
module numerics_linear_algebra
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_DOMAIN, STATUS_INTERNAL
  implicit none (type, external)
  private
  public :: lu_factor, lu_solve, lu_reciprocal_condition, one_norm
  public :: cholesky_factor, cholesky_solve
  public :: qr_factor, triangular_inverse, normal_matrix_inverse
  public :: small_order, small_lu_solve, small_lu_solve_3
  public :: transposed_product, symmetric_transposed_product

  integer, parameter :: small_order = 12   !< up to this order LU and Cholesky run without LAPACK

  !> Solve A x = b (or A^T x = b) with the LU factors of lu_factor; b is
  !> overwritten by x. One right-hand side (vector) or several (columns).
  interface lu_solve
    module procedure lu_solve_vector, lu_solve_matrix
  end interface lu_solve

  !> Solve A x = b with the Cholesky factor of cholesky_factor; b is overwritten.
  interface cholesky_solve
    module procedure cholesky_solve_vector, cholesky_solve_matrix
  end interface cholesky_solve

  interface
    subroutine dgetrf(m, n, a, lda, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgetrf
    subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      character, intent(in) :: trans
      integer, intent(in) :: n, nrhs, lda, ldb, ipiv(*)
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dgetrs
    subroutine dgecon(norm, n, a, lda, anorm, rcond, work, iwork, info)
      import :: wp
      character, intent(in) :: norm
      integer, intent(in) :: n, lda
      real(wp), intent(in) :: a(lda, *), anorm
      real(wp), intent(out) :: rcond
      real(wp), intent(inout) :: work(*)
      integer, intent(inout) :: iwork(*)
      integer, intent(out) :: info
    end subroutine dgecon
    subroutine dpotrf(uplo, n, a, lda, info)
      import :: wp
      character, intent(in) :: uplo
      integer, intent(in) :: n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: info
    end subroutine dpotrf
    subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
      import :: wp
      character, intent(in) :: uplo
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dpotrs
    subroutine dgeqrf(m, n, a, lda, tau, work, lwork, info)
      import :: wp
      integer, intent(in) :: m, n, lda, lwork
      real(wp), intent(inout) :: a(lda, *)
      real(wp), intent(out) :: tau(*), work(*)
      integer, intent(out) :: info
    end subroutine dgeqrf
    subroutine dtrtri(uplo, diag, n, a, lda, info)
      import :: wp
      character, intent(in) :: uplo, diag
      integer, intent(in) :: n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: info
    end subroutine dtrtri
  end interface

contains

  !> The one translation of LAPACK's info (see the module comment).
  pure subroutine translate_info(routine, info, singular_text, status, failed_index)
    character(len=*), intent(in) :: routine, singular_text
    integer, intent(in) :: info
    type(status_t), intent(inout) :: status
    integer, intent(out), optional :: failed_index
    character(len=12) :: number
    if (present(failed_index)) failed_index = max(0, info)
    if (info == 0) return
    write (number, '(i0)') abs(info)
    if (info < 0) then
      call set_status(status, STATUS_INTERNAL, routine//': argument '//trim(number)//' is illegal')
    else
      call set_status(status, STATUS_DOMAIN, routine//': '//singular_text//' (at '//trim(number)//')')
    end if
  end subroutine translate_info

  !> The start of lu_factor and cholesky_factor: a wrong shape is refused
  !> (STATUS_INTERNAL, `message`: a caller's bug) and an n x n matrix with
  !> n = 0 has nothing to factor; either way failed_index = 0 and true.
  logical function nothing_to_factor(shape_ok, n, message, status, failed_index) result(done)
    logical, intent(in) :: shape_ok
    integer, intent(in) :: n
    character(len=*), intent(in) :: message
    type(status_t), intent(inout) :: status
    integer, intent(out), optional :: failed_index
    done = .not. shape_ok .or. n == 0
    if (.not. shape_ok) call set_status(status, STATUS_INTERNAL, message)
    if (done .and. present(failed_index)) failed_index = 0
  end function nothing_to_factor

  !> PA = LU of the square matrix a, in place. A zero pivot U(k,k) = 0 (the
  !> matrix is exactly singular) sets STATUS_DOMAIN and failed_index = k; the
  !> factors are then complete but must not be used for solving.
  subroutine lu_factor(a, ipiv, status, failed_index)
    real(wp), intent(inout), contiguous :: a(:, :)
    integer, intent(out), contiguous :: ipiv(:)
    type(status_t), intent(inout) :: status
    integer, intent(out), optional :: failed_index
    integer :: info
    if (nothing_to_factor(size(a, 1) == size(a, 2) .and. size(ipiv) >= size(a, 1), size(a, 1), &
                          'lu_factor: a must be square and ipiv as long as a side', status, failed_index)) return
    if (size(a, 1) <= small_order) then
      call small_lu_factor(a, ipiv, info)
      call translate_info('lu_factor', info, 'the matrix is singular, a zero pivot', status, failed_index)
      return
    end if
    call dgetrf(size(a, 1), size(a, 2), a, size(a, 1), ipiv, info)
    call translate_info('dgetrf', info, 'the matrix is singular, a zero pivot', status, failed_index)
  end subroutine lu_factor

  !> Unblocked LU with partial pivoting (dgetf2's algorithm): info = the first
  !> zero pivot (its column is not eliminated), 0 if none.
  pure subroutine small_lu_factor(a, ipiv, info)
    real(wp), intent(inout), contiguous :: a(:, :)
    integer, intent(out), contiguous :: ipiv(:)
    integer, intent(out) :: info
    real(wp) :: t, pivot
    integer :: n, i, j, k, p
    n = size(a, 1)
    info = 0
    do k = 1, n
      p = k
      do i = k + 1, n
        if (abs(a(i, k)) > abs(a(p, k))) p = i
      end do
      ipiv(k) = p
      if (a(p, k) == 0) then
        if (info == 0) info = k
        cycle
      end if
      if (p /= k) then
        do j = 1, n
          t = a(k, j)
          a(k, j) = a(p, j)
          a(p, j) = t
        end do
      end if
      pivot = a(k, k)
      do i = k + 1, n
        a(i, k) = a(i, k)/pivot
      end do
      do j = k + 1, n
        t = a(k, j)
        if (t == 0) cycle
        do i = k + 1, n
          a(i, j) = a(i, j) - a(i, k)*t
        end do
      end do
    end do
  end subroutine small_lu_factor

  !> Solves with the factors of small_lu_factor: P A = L U, so A x = b is
  !> L U x = P b and A^T x = b is U^T L^T (P x) = b. The text is
  !> numerics_small_lu_solve.inc, here at any order and in small_lu_solve_3
  !> at order 3.
  pure subroutine small_lu_solve(lu, ipiv, b, transpose)
    real(wp), intent(in), contiguous :: lu(:, :)
    integer, intent(in), contiguous :: ipiv(:)
    real(wp), intent(inout), contiguous :: b(:)
    logical, intent(in) :: transpose
    real(wp) :: t
    integer :: n, i, k
    n = size(lu, 1)
    include 'numerics_small_lu_solve.inc'
  end subroutine small_lu_solve

  !> small_lu_solve for n = 3 (a contact point's loop: the rider's closure
  !> blocks in kinetostatics_closure_blocks), the same text with the order a
  !> constant, so that every loop unrolls (written out by hand before, the
  !> default run's block solves took 115.8M -> 49.9M instructions, 0386394).
  pure subroutine small_lu_solve_3(lu, ipiv, b, transpose)
    integer, parameter :: n = 3
    real(wp), intent(in) :: lu(n, n)
    integer, intent(in) :: ipiv(n)
    real(wp), intent(inout) :: b(n)
    logical, intent(in) :: transpose
    real(wp) :: t
    integer :: i, k
    include 'numerics_small_lu_solve.inc'
  end subroutine small_lu_solve_3

  subroutine lu_solve_vector(lu, ipiv, b, status, transpose)
    real(wp), intent(in), contiguous :: lu(:, :)
    integer, intent(in), contiguous :: ipiv(:)
    real(wp), intent(inout), contiguous :: b(:)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: transpose
    integer :: info
    if (size(lu, 1) == 0) return
    if (size(lu, 1) <= small_order) then
      call small_lu_solve(lu, ipiv, b, trans_flag(transpose) == 'T')
      return
    end if
    call dgetrs(trans_flag(transpose), size(lu, 1), 1, lu, size(lu, 1), ipiv, b, size(b), info)
    call translate_info('dgetrs', info, '', status)
  end subroutine lu_solve_vector

  subroutine lu_solve_matrix(lu, ipiv, b, status, transpose)
    real(wp), intent(in), contiguous :: lu(:, :)
    integer, intent(in), contiguous :: ipiv(:)
    real(wp), intent(inout), contiguous :: b(:, :)
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: transpose
    integer :: info, j
    if (size(lu, 1) == 0 .or. size(b, 2) == 0) return
    if (size(lu, 1) <= small_order) then
      do j = 1, size(b, 2)
        call small_lu_solve(lu, ipiv, b(:, j), trans_flag(transpose) == 'T')
      end do
      return
    end if
    call dgetrs(trans_flag(transpose), size(lu, 1), size(b, 2), lu, size(lu, 1), ipiv, b, &
                size(b, 1), info)
    call translate_info('dgetrs', info, '', status)
  end subroutine lu_solve_matrix

  pure character function trans_flag(transpose)
    logical, intent(in), optional :: transpose
    trans_flag = 'N'
    if (present(transpose)) then
      if (transpose) trans_flag = 'T'
    end if
  end function trans_flag

  !> max_j sum_i |a_ij|, the 1-norm that lu_reciprocal_condition needs of the
  !> matrix before factoring.
  pure real(wp) function one_norm(a)
    real(wp), intent(in) :: a(:, :)
    integer :: j
    one_norm = 0
    do j = 1, size(a, 2)
      one_norm = max(one_norm, sum(abs(a(:, j))))
    end do
  end function one_norm

  !> Estimate of 1 / (||A||_1 ||A^-1||_1) from the LU factors and ||A||_1.
  subroutine lu_reciprocal_condition(lu, anorm, rcond, status)
    real(wp), intent(in), contiguous :: lu(:, :)
    real(wp), intent(in) :: anorm
    real(wp), intent(out) :: rcond
    type(status_t), intent(inout) :: status
    real(wp) :: work(4*max(1, size(lu, 1)))
    integer :: iwork(max(1, size(lu, 1))), info
    rcond = 1
    if (size(lu, 1) == 0) return
    call dgecon('1', size(lu, 1), lu, size(lu, 1), anorm, rcond, work, iwork, info)
    call translate_info('dgecon', info, '', status)
  end subroutine lu_reciprocal_condition

  !> A = L L^T of the symmetric matrix a (lower triangle used), L in the lower
  !> triangle. Not positive definite: STATUS_DOMAIN and failed_index = the
  !> first column k whose leading k x k minor is not positive definite.
  subroutine cholesky_factor(a, status, failed_index)
    real(wp), intent(inout), contiguous :: a(:, :)
    type(status_t), intent(inout) :: status
    integer, intent(out), optional :: failed_index
    integer :: info
    if (nothing_to_factor(size(a, 1) == size(a, 2), size(a, 1), 'cholesky_factor: a must be square', status, &
                          failed_index)) return
    if (size(a, 1) <= small_order) then
      call small_cholesky_factor(a, info)
      call translate_info('cholesky_factor', info, 'the matrix is not positive definite', status, failed_index)
      return
    end if
    call dpotrf('L', size(a, 1), a, size(a, 1), info)
    call translate_info('dpotrf', info, 'the matrix is not positive definite', status, failed_index)
  end subroutine cholesky_factor

  !> L L^T from the lower triangle (dpotf2's algorithm); info = the first
  !> column whose pivot is not positive (or NaN), 0 if none. Each entry of
  !> column j is finished in one go, L(i, j) = (a(i, j) - sum_k L(i, k) L(j, k))/L(j, j)
  !> with the sum in k order: the operations of column-by-column updates in
  !> the same order, without storing the partial sums (5 x 5: 0.51k
  !> instructions instead of 0.73k; right-looking updates cost more). The
  !> text is numerics_small_cholesky_factor.inc, here at any order and in
  !> cholesky_factor_5 at order 5.
  pure subroutine small_cholesky_factor(a, info)
    real(wp), intent(inout), contiguous :: a(:, :)
    integer, intent(out) :: info
    real(wp) :: d, t
    integer :: n, i, j, k
    n = size(a, 1)
    if (n == 5) then
      call cholesky_factor_5(a, info)
      return
    end if
    include 'numerics_small_cholesky_factor.inc'
  end subroutine small_cholesky_factor

  !> Solves L L^T x = b with the factor of small_cholesky_factor (both
  !> triangles by rows: each x(k) from one sum in the order of the column
  !> updates); the text is numerics_small_cholesky_solve.inc, as the factor's.
  pure subroutine small_cholesky_solve(l, b)
    real(wp), intent(in), contiguous :: l(:, :)
    real(wp), intent(inout), contiguous :: b(:)
    real(wp) :: t
    integer :: n, i, k
    n = size(l, 1)
    if (n == 5) then
      call cholesky_solve_5(l, b)
      return
    end if
    include 'numerics_small_cholesky_solve.inc'
  end subroutine small_cholesky_solve

  !> small_cholesky_factor for n = 5 (a body on a surface: the contact
  !> mechanisms' 5 speeds): the same text with the order a constant, so the
  !> loops unroll completely (0.21k instructions instead of 0.46k).
  pure subroutine cholesky_factor_5(a, info)
    integer, parameter :: n = 5
    real(wp), intent(inout) :: a(n, n)
    integer, intent(out) :: info
    real(wp) :: d, t
    integer :: i, j, k
    include 'numerics_small_cholesky_factor.inc'
  end subroutine cholesky_factor_5

  !> small_cholesky_solve for n = 5, the same way (0.10k instructions
  !> instead of 0.31k).
  pure subroutine cholesky_solve_5(l, b)
    integer, parameter :: n = 5
    real(wp), intent(in) :: l(n, n)
    real(wp), intent(inout) :: b(n)
    real(wp) :: t
    integer :: i, k
    include 'numerics_small_cholesky_solve.inc'
  end subroutine cholesky_solve_5

  subroutine cholesky_solve_vector(l, b, status)
    real(wp), intent(in), contiguous :: l(:, :)
    real(wp), intent(inout), contiguous :: b(:)
    type(status_t), intent(inout) :: status
    integer :: info
    if (size(l, 1) == 0) return
    if (size(l, 1) <= small_order) then
      call small_cholesky_solve(l, b)
      return
    end if
    call dpotrs('L', size(l, 1), 1, l, size(l, 1), b, size(b), info)
    call translate_info('dpotrs', info, '', status)
  end subroutine cholesky_solve_vector

  subroutine cholesky_solve_matrix(l, b, status)
    real(wp), intent(in), contiguous :: l(:, :)
    real(wp), intent(inout), contiguous :: b(:, :)
    type(status_t), intent(inout) :: status
    integer :: info, j
    if (size(l, 1) == 0 .or. size(b, 2) == 0) return
    if (size(l, 1) <= small_order) then
      do j = 1, size(b, 2)
        call small_cholesky_solve(l, b(:, j))
      end do
      return
    end if
    call dpotrs('L', size(l, 1), size(b, 2), l, size(l, 1), b, size(b, 1), info)
    call translate_info('dpotrs', info, '', status)
  end subroutine cholesky_solve_matrix

  !> A = Q R of the m x n matrix a (m >= n) in place: R in the upper triangle,
  !> Q as Householder vectors below it and in tau(n). Allocates its workspace
  !> (not for inner loops).
  subroutine qr_factor(a, tau, status)
    real(wp), intent(inout), contiguous :: a(:, :)
    real(wp), intent(out), contiguous :: tau(:)
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: work(:)
    real(wp) :: query(1)
    integer :: m, n, info
    m = size(a, 1)
    n = size(a, 2)
    if (m < n .or. size(tau) < n) then
      call set_status(status, STATUS_INTERNAL, 'qr_factor: needs m >= n and tau of size n')
      return
    end if
    if (n == 0) return
    call dgeqrf(m, n, a, m, tau, query, -1, info)
    call translate_info('dgeqrf (workspace query)', info, '', status)
    if (.not. status%ok()) return
    allocate (work(max(1, int(query(1)))))
    call dgeqrf(m, n, a, m, tau, work, size(work), info)
    call translate_info('dgeqrf', info, '', status)
  end subroutine qr_factor

  !> The inverse of the upper triangular n x n matrix r, in place (the strict
  !> lower triangle is left as it is). An exactly zero diagonal entry:
  !> STATUS_DOMAIN, failed_index = its index.
  subroutine triangular_inverse(r, status, failed_index)
    real(wp), intent(inout), contiguous :: r(:, :)
    type(status_t), intent(inout) :: status
    integer, intent(out), optional :: failed_index
    integer :: info
    if (size(r, 1) /= size(r, 2)) then
      call set_status(status, STATUS_INTERNAL, 'triangular_inverse: r must be square')
      return
    end if
    if (size(r, 1) == 0) return
    call dtrtri('U', 'N', size(r, 1), r, size(r, 1), info)
    call translate_info('dtrtri', info, 'the triangular matrix is singular, a zero diagonal', &
                        status, failed_index)
  end subroutine triangular_inverse

  !> (J^T J)^(-1) of the m x n matrix j (m >= n) through QR, J = Q R,
  !> (J^T J)^(-1) = R^(-1) R^(-T), without forming J^T J (which would square the
  !> condition number). Numerically rank-deficient (a diagonal entry of R below
  !> n eps max|R_kk|): STATUS_DOMAIN naming the first such column (the column
  !> order of j, since no pivoting is done).
  subroutine normal_matrix_inverse(j, inverse, status)
    real(wp), intent(in) :: j(:, :)
    real(wp), intent(out) :: inverse(:, :)
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: a(:, :), tau(:), rinv(:, :)
    real(wp) :: diagonal(size(j, 2))
    integer :: n, k
    character(len=12) :: number
    n = size(j, 2)
    inverse = 0
    if (n == 0) return
    a = j
    allocate (tau(n))
    call qr_factor(a, tau, status)
    if (.not. status%ok()) return
    diagonal = [(abs(a(k, k)), k=1, n)]
    do k = 1, n
      if (diagonal(k) <= n*epsilon(1.0_wp)*maxval(diagonal)) then
        write (number, '(i0)') k
        call set_status(status, STATUS_DOMAIN, 'normal_matrix_inverse: J is rank-deficient, column ' &
          //trim(number)//' depends on the earlier ones')
        return
      end if
    end do
    rinv = a(1:n, 1:n)
    do k = 1, n
      rinv(k + 1:n, k) = 0
    end do
    call triangular_inverse(rinv, status)
    if (.not. status%ok()) return
    inverse = matmul(rinv, transpose(rinv))
  end subroutine normal_matrix_inverse

  !> c(k, i) = a(:, k) . b(:, i) for a(l, n) and b(l, m) (c = a^T b), each
  !> sum from 0 in the order of l (the result of a plain loop, whatever the
  !> length). l = 6 (a twist and a wrench of one frame) runs unrolled: for
  !> the right-hand sides' 6-vectors a loop's control costs more than its
  !> arithmetic (and the loop over k, 1 to a few contacts, is not unrolled).
  pure subroutine transposed_product(l, n, m, a, b, c)
    integer, intent(in) :: l, n, m
    real(wp), intent(in) :: a(l, n), b(l, m)
    real(wp), intent(out) :: c(n, m)
    integer :: i, k
    if (l == 6) then
      do i = 1, m
        !GCC$ unroll 1
        do k = 1, n
          c(k, i) = dot6(a(:, k), b(:, i))
        end do
      end do
    else
      do i = 1, m
        do k = 1, n
          c(k, i) = ordered_dot(l, a(:, k), b(:, i))
        end do
      end do
    end if
  end subroutine transposed_product

  !> The same for n = m and a product known to be symmetric: only k <= i is
  !> summed, c(k, i) = c(i, k) = factor a(:, k) . b(:, i), and lower(i, k) =
  !> that value (only the lower triangle of `lower` is written: a Cholesky
  !> factor's input). factor = -1 or 1 keeps the products exact.
  pure subroutine symmetric_transposed_product(l, n, a, b, factor, c, lower)
    integer, intent(in) :: l, n
    real(wp), intent(in) :: a(l, n), b(l, n), factor
    real(wp), intent(inout) :: c(n, n), lower(n, n)
    real(wp) :: p
    integer :: i, k
    do i = 1, n
      do k = 1, i
        if (l == 6) then
          p = factor*dot6(a(:, k), b(:, i))
        else
          p = factor*ordered_dot(l, a(:, k), b(:, i))
        end if
        c(k, i) = p
        c(i, k) = p
        lower(i, k) = p
      end do
    end do
  end subroutine symmetric_transposed_product

  !> x . y of 6-vectors, summed from 0 in index order (as ordered_dot).
  pure real(wp) function dot6(x, y)
    real(wp), intent(in) :: x(6), y(6)
    dot6 = 0.0_wp + x(1)*y(1) + x(2)*y(2) + x(3)*y(3) + x(4)*y(4) + x(5)*y(5) + x(6)*y(6)
  end function dot6

  !> x . y summed from 0 in index order (dot_product leaves the order open).
  pure real(wp) function ordered_dot(l, x, y)
    integer, intent(in) :: l
    real(wp), intent(in) :: x(l), y(l)
    integer :: j
    ordered_dot = 0
    do j = 1, l
      ordered_dot = ordered_dot + x(j)*y(j)
    end do
  end function ordered_dot
end module numerics_linear_algebra
