!> Faster serial N_Vector operations for CVODE's small state vectors.
!>
!> CVODE does its vector arithmetic through the N_Vector's table of
!> operations. For the serial vector the cost of a linear sum of 10 numbers is
!> mostly the way there (a dispatch, a case analysis, a call per case: ~120
!> instructions). `speed_up_vector` replaces the hot entries of one vector's
!> table (CVODE's clones copy the table) by the routines below and switches on
!> SUNDIALS' own fused operations (linear combination, scale-add-multi).
!>
!> Every replacement does exactly the arithmetic of SUNDIALS 6.4's serial
!> vector, in the same order and with the same special cases, so results are
!> bit-identical (tests/numerics/test_nvector_ops.f90 compares them bitwise,
!> aliased arguments included). Elementwise loops are written out: with
!> aliased vectors (z the same as x or y, as CVODE does) each element is read
!> before it is written, exactly as in the C loops. They are vectorised
!> (ivdep holds: no element depends on another) and unrolled only twice: the
!> vectors are short (10-20 numbers), and -funroll-loops' eightfold unrolling
!> costs more in choosing the remainder's entry than it saves.
module numerics_nvector_ops
  use, intrinsic :: iso_c_binding, only: c_ptr, c_double, c_int, c_int64_t, c_funloc, &
    c_f_pointer
  use fsundials_nvector_mod, only: N_Vector, N_Vector_Ops
  use fnvector_serial_mod, only: FN_VEnableFusedOps_Serial
  implicit none (type, external)
  private
  public :: speed_up_vector, serial_data
  public :: fast_linear_sum, fast_scale, fast_wrms_norm, fast_scale_add_multi, fast_const, &
    fast_abs, fast_inv, fast_add_const   ! public for the tests

  !> The serial vector's content (nvector_serial.h, SUNDIALS 6.4 with 64-bit indices).
  type, bind(C) :: serial_content_t
    integer(c_int64_t) :: length
    integer(c_int) :: own_data
    type(c_ptr) :: data
  end type serial_content_t

contains

  !> Puts the faster operations into `v`'s table (a serial N_Vector) and
  !> switches on its fused operations. Returns .false. if SUNDIALS refused.
  logical function speed_up_vector(v) result(done)
    type(N_Vector), intent(inout), target :: v
    type(N_Vector_Ops), pointer :: ops

    done = FN_VEnableFusedOps_Serial(v, 1_c_int) == 0
    if (.not. done) return
    call c_f_pointer(v%ops, ops)
    ops%nvlinearsum = c_funloc(fast_linear_sum)
    ops%nvscale = c_funloc(fast_scale)
    ops%nvwrmsnorm = c_funloc(fast_wrms_norm)
    ops%nvscaleaddmulti = c_funloc(fast_scale_add_multi)
    ops%nvconst = c_funloc(fast_const)
    ops%nvabs = c_funloc(fast_abs)
    ops%nvinv = c_funloc(fast_inv)
    ops%nvaddconst = c_funloc(fast_add_const)
  end function speed_up_vector

  !> The data of a serial vector as an array (what N_VGetArrayPointer gives,
  !> without its two wrapper calls).
  subroutine serial_data(v, data)
    type(c_ptr), intent(in) :: v
    real(c_double), pointer, contiguous, intent(out) :: data(:)
    type(N_Vector), pointer :: vector
    type(serial_content_t), pointer :: content

    call c_f_pointer(v, vector)
    call c_f_pointer(vector%content, content)
    call c_f_pointer(content%data, data, [content%length])
  end subroutine serial_data

  !> z = a x + b y (N_VLinearSum). SUNDIALS' serial cases all amount to
  !> a x + b y (products with +-1 are exact, sums commute) except two, kept
  !> here: a = b -> a (x + y) and a = -b -> a (x - y) when neither is +-1;
  !> and (a, b) = (-1, 1) gives y - x, not -(x - y) (the sign of a zero).
  subroutine fast_linear_sum(a, x, b, y, z) bind(C)
    real(c_double), value :: a, b
    type(c_ptr), value :: x, y, z
    real(c_double), pointer, contiguous :: xd(:), yd(:), zd(:)
    integer :: i

    call serial_data(x, xd)
    call serial_data(y, yd)
    call serial_data(z, zd)
    if (b == 1) then
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = a * xd(i) + yd(i)
      end do
    else if (a == 1) then
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = xd(i) + b * yd(i)
      end do
    else if (a == -1) then
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = b * yd(i) - xd(i)
      end do
    else if (b == -1) then
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = a * xd(i) - yd(i)
      end do
    else if (a == b) then
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = a * (xd(i) + yd(i))
      end do
    else if (a == -b) then
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = a * (xd(i) - yd(i))
      end do
    else
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = a * xd(i) + b * yd(i)
      end do
    end if
  end subroutine fast_linear_sum

  !> z = c x (N_VScale; its cases copy, negate or multiply: all equal to c x).
  subroutine fast_scale(c, x, z) bind(C)
    real(c_double), value :: c
    type(c_ptr), value :: x, z
    real(c_double), pointer, contiguous :: xd(:), zd(:)
    integer :: i

    call serial_data(x, xd)
    call serial_data(z, zd)
    !GCC$ ivdep
    !GCC$ vector
    !GCC$ unroll 2
    do i = 1, size(zd)
      zd(i) = c * xd(i)
    end do
  end subroutine fast_scale

  !> z_i = c (N_VConst).
  subroutine fast_const(c, z) bind(C)
    real(c_double), value :: c
    type(c_ptr), value :: z
    real(c_double), pointer, contiguous :: zd(:)
    integer :: i

    call serial_data(z, zd)
    !GCC$ ivdep
    !GCC$ vector
    !GCC$ unroll 2
    do i = 1, size(zd)
      zd(i) = c
    end do
  end subroutine fast_const

  !> z_i = |x_i| (N_VAbs).
  subroutine fast_abs(x, z) bind(C)
    type(c_ptr), value :: x, z
    real(c_double), pointer, contiguous :: xd(:), zd(:)
    integer :: i

    call serial_data(x, xd)
    call serial_data(z, zd)
    !GCC$ ivdep
    !GCC$ vector
    !GCC$ unroll 2
    do i = 1, size(zd)
      zd(i) = abs(xd(i))
    end do
  end subroutine fast_abs

  !> z_i = 1 / x_i (N_VInv).
  subroutine fast_inv(x, z) bind(C)
    type(c_ptr), value :: x, z
    real(c_double), pointer, contiguous :: xd(:), zd(:)
    integer :: i

    call serial_data(x, xd)
    call serial_data(z, zd)
    !GCC$ ivdep
    !GCC$ vector
    !GCC$ unroll 2
    do i = 1, size(zd)
      zd(i) = 1 / xd(i)
    end do
  end subroutine fast_inv

  !> z_i = x_i + b (N_VAddConst).
  subroutine fast_add_const(x, b, z) bind(C)
    type(c_ptr), value :: x, z
    real(c_double), value :: b
    real(c_double), pointer, contiguous :: xd(:), zd(:)
    integer :: i

    call serial_data(x, xd)
    call serial_data(z, zd)
    !GCC$ ivdep
    !GCC$ vector
    !GCC$ unroll 2
    do i = 1, size(zd)
      zd(i) = xd(i) + b
    end do
  end subroutine fast_add_const

  !> z_k = a_k x + y_k, k = 1..nvec (N_VScaleAddMulti; all of the serial
  !> vector's cases amount to this), vector after vector as there. Returns -1
  !> for nvec < 1 as SUNDIALS does.
  integer(c_int) function fast_scale_add_multi(nvec, a, x, y, z) bind(C) result(flag)
    integer(c_int), value :: nvec
    real(c_double), intent(in) :: a(nvec)
    type(c_ptr), value :: x, y, z
    type(c_ptr), pointer :: y_vectors(:), z_vectors(:)
    real(c_double), pointer, contiguous :: xd(:), yd(:), zd(:)
    integer :: i, k

    flag = -1
    if (nvec < 1) return
    flag = 0
    call c_f_pointer(y, y_vectors, [nvec])
    call c_f_pointer(z, z_vectors, [nvec])
    call serial_data(x, xd)
    do k = 1, nvec
      call serial_data(y_vectors(k), yd)
      call serial_data(z_vectors(k), zd)
      !GCC$ ivdep
      !GCC$ vector
      !GCC$ unroll 2
      do i = 1, size(zd)
        zd(i) = a(k) * xd(i) + yd(i)
      end do
    end do
  end function fast_scale_add_multi

  !> sqrt(sum((x w)^2) / n) (N_VWrmsNorm), summed in index order; 0 unless the
  !> mean is positive or NaN (SUNRsqrt).
  real(c_double) function fast_wrms_norm(x, w) bind(C) result(norm)
    type(c_ptr), value :: x, w
    real(c_double), pointer, contiguous :: xd(:), wd(:)
    real(c_double) :: sum_of_squares, product, mean
    integer :: i

    call serial_data(x, xd)
    call serial_data(w, wd)
    sum_of_squares = 0
    do i = 1, size(xd)
      product = xd(i) * wd(i)
      sum_of_squares = sum_of_squares + product * product
    end do
    mean = sum_of_squares / real(size(xd), c_double)
    norm = 0
    if (.not. mean <= 0) norm = sqrt(mean)
  end function fast_wrms_norm

end module numerics_nvector_ops
