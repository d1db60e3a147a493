!> The faster N_Vector operations (numerics_nvector_ops) against SUNDIALS'
!> serial ones: bitwise equal results on scattered data (signed zeros, mixed
!> magnitudes) for every special coefficient and every aliasing CVODE may use,
!> and lengths that exercise the vectorised loops' remainders.
program test_nvector_ops
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_double, c_int, c_int64_t, &
    c_loc, c_funloc, c_funptr, c_f_pointer, c_associated
  use fsundials_context_mod, only: FSUNContext_Create, FSUNContext_Free
  use fsundials_nvector_mod, only: N_Vector, N_Vector_Ops, FN_VDestroy, FN_VClone
  use fnvector_serial_mod, only: FN_VNew_Serial, FN_VGetArrayPointer_Serial, FN_VLinearSum_Serial, &
    FN_VScale_Serial, FN_VWrmsNorm_Serial, FN_VScaleAddMulti_Serial, FN_VConst_Serial, FN_VAbs_Serial, &
    FN_VInv_Serial, FN_VAddConst_Serial
  use numerics_nvector_ops, only: speed_up_vector, serial_data, fast_linear_sum, fast_scale, fast_wrms_norm, &
    fast_scale_add_multi, fast_const, fast_abs, fast_inv, fast_add_const
  use, intrinsic :: ieee_exceptions, only: ieee_invalid, ieee_get_halting_mode, ieee_set_halting_mode, &
    ieee_set_flag
  use testing, only: check, finish_tests
  implicit none (type, external)

  !> coefficients: each special case of the serial vector and ordinary ones
  real(c_double), parameter :: coefficients(*) = [1.0_c_double, -1.0_c_double, 0.0_c_double, &
    -0.0_c_double, 0.3_c_double, -0.3_c_double, 2.5_c_double, 1e-300_c_double]
  integer, parameter :: lengths(*) = [1, 2, 3, 10, 17]
  type(c_ptr) :: context
  integer :: flag, i

  flag = FSUNContext_Create(c_null_ptr, context)
  call check(flag == 0, 'SUNContext_Create')
  do i = 1, size(lengths)
    call linear_sums(lengths(i))
    call scales(lengths(i))
    call norms(lengths(i))
    call scale_add_multis(lengths(i))
    call elementwise(lengths(i))
  end do
  call table_is_replaced()
  call data_as_sundials_gives_it()
  flag = FSUNContext_Free(context)
  call finish_tests('test_nvector_ops')

contains

  !> Scattered values: signed zeros, magnitudes from 1e-8 to 1e8, both signs.
  subroutine fill(v, seed)
    type(N_Vector), intent(inout) :: v
    integer, intent(in) :: seed
    real(c_double), pointer :: d(:)
    integer :: k
    d => FN_VGetArrayPointer_Serial(v)
    do k = 1, size(d)
      d(k) = sin(1.7_c_double*(k + 13*seed)) * 10.0_c_double**modulo(3*k + 5*seed, 17) * 1e-8_c_double
      if (modulo(k + seed, 7) == 0) d(k) = 0
      if (modulo(k + seed, 11) == 0) d(k) = -0.0_c_double
    end do
  end subroutine fill

  logical function same_bits(a, b)
    type(N_Vector), intent(inout) :: a, b
    real(c_double), pointer :: da(:), db(:)
    da => FN_VGetArrayPointer_Serial(a)
    db => FN_VGetArrayPointer_Serial(b)
    same_bits = all(transfer(da, 0_c_int64_t, size(da)) == transfer(db, 0_c_int64_t, size(db)))
  end function same_bits

  function new_vector(n, seed) result(v)
    integer, intent(in) :: n, seed
    type(N_Vector), pointer :: v
    v => FN_VNew_Serial(int(n, c_int64_t), context)
    call fill(v, seed)
  end function new_vector

  !> Aliasing patterns: 1 x, y, z distinct; 2 z = x; 3 z = y; 4 x = y; 5 x = y = z.
  subroutine linear_sums(n)
    integer, intent(in) :: n
    type(N_Vector), pointer :: rx, ry, rz, mx, my, mz
    integer :: ia, ib, pattern
    logical :: all_same
    real(c_double) :: a, b

    all_same = .true.
    do pattern = 1, 5
      do ia = 1, size(coefficients)
        do ib = 1, size(coefficients)
          a = coefficients(ia)
          b = coefficients(ib)
          rx => new_vector(n, 1); ry => new_vector(n, 2); rz => new_vector(n, 3)
          mx => new_vector(n, 1); my => new_vector(n, 2); mz => new_vector(n, 3)
          select case (pattern)
          case (1)
            call FN_VLinearSum_Serial(a, rx, b, ry, rz)
            call fast_linear_sum(a, c_loc(mx), b, c_loc(my), c_loc(mz))
          case (2)
            call FN_VLinearSum_Serial(a, rx, b, ry, rx)
            call fast_linear_sum(a, c_loc(mx), b, c_loc(my), c_loc(mx))
          case (3)
            call FN_VLinearSum_Serial(a, rx, b, ry, ry)
            call fast_linear_sum(a, c_loc(mx), b, c_loc(my), c_loc(my))
          case (4)
            call FN_VLinearSum_Serial(a, rx, b, rx, rz)
            call fast_linear_sum(a, c_loc(mx), b, c_loc(mx), c_loc(mz))
          case (5)
            call FN_VLinearSum_Serial(a, rx, b, rx, rx)
            call fast_linear_sum(a, c_loc(mx), b, c_loc(mx), c_loc(mx))
          end select
          if (.not. (same_bits(rx, mx) .and. same_bits(ry, my) .and. same_bits(rz, mz))) then
            all_same = .false.
            print '(a, i0, a, i0, 2(a, es10.2))', 'linear sum differs: n ', n, ' aliasing ', pattern, &
              ' a ', a, ' b ', b
          end if
          call FN_VDestroy(rx); call FN_VDestroy(ry); call FN_VDestroy(rz)
          call FN_VDestroy(mx); call FN_VDestroy(my); call FN_VDestroy(mz)
        end do
      end do
    end do
    call check(all_same, 'linear sum bitwise as N_VLinearSum_Serial (all cases, all aliasings)')
  end subroutine linear_sums

  subroutine scales(n)
    integer, intent(in) :: n
    type(N_Vector), pointer :: rx, rz, mx, mz
    integer :: ic, pattern
    logical :: all_same

    all_same = .true.
    do pattern = 1, 2
      do ic = 1, size(coefficients)
        rx => new_vector(n, 1); rz => new_vector(n, 3)
        mx => new_vector(n, 1); mz => new_vector(n, 3)
        if (pattern == 1) then
          call FN_VScale_Serial(coefficients(ic), rx, rz)
          call fast_scale(coefficients(ic), c_loc(mx), c_loc(mz))
        else
          call FN_VScale_Serial(coefficients(ic), rx, rx)
          call fast_scale(coefficients(ic), c_loc(mx), c_loc(mx))
        end if
        all_same = all_same .and. same_bits(rx, mx) .and. same_bits(rz, mz)
        call FN_VDestroy(rx); call FN_VDestroy(rz); call FN_VDestroy(mx); call FN_VDestroy(mz)
      end do
    end do
    call check(all_same, 'scale bitwise as N_VScale_Serial (z = x and z /= x)')
  end subroutine scales

  subroutine norms(n)
    integer, intent(in) :: n
    type(N_Vector), pointer :: x, w
    real(c_double), pointer :: d(:)
    real(c_double) :: reference, fast
    logical :: all_same, halting
    integer :: k

    ! the NaN case compares a NaN (as SUNDIALS does): no trap in the Debug build
    call ieee_get_halting_mode(ieee_invalid, halting)
    call ieee_set_halting_mode(ieee_invalid, .false.)
    all_same = .true.
    x => new_vector(n, 1); w => new_vector(n, 4)
    do k = 1, 3
      if (k == 2) then   ! all zero: the norm is 0
        d => FN_VGetArrayPointer_Serial(x)
        d = -0.0_c_double
      else if (k == 3) then   ! a NaN is passed on as in SUNRsqrt
        d => FN_VGetArrayPointer_Serial(w)
        d(n) = transfer(-1_c_int64_t, 1.0_c_double)
      end if
      reference = FN_VWrmsNorm_Serial(x, w)
      fast = fast_wrms_norm(c_loc(x), c_loc(w))
      if (k == 3) then
        all_same = all_same .and. (fast /= fast) .eqv. (reference /= reference)
      else
        all_same = all_same .and. transfer(reference, 0_c_int64_t) == transfer(fast, 0_c_int64_t)
      end if
      all_same = all_same .and. (k /= 2 .or. fast == 0)
      call fill(x, 1)
    end do
    call FN_VDestroy(x); call FN_VDestroy(w)
    call ieee_set_flag(ieee_invalid, .false.)
    call ieee_set_halting_mode(ieee_invalid, halting)
    call check(all_same, 'WRMS norm bitwise as N_VWrmsNorm_Serial (zero vector, NaN)')
  end subroutine norms

  !> Const, abs, inverse, add-constant; z = x and z /= x (the inverse of
  !> data without zeros: a division by zero traps in the Debug build).
  subroutine elementwise(n)
    integer, intent(in) :: n
    type(N_Vector), pointer :: rx, rz, mx, mz
    real(c_double), pointer :: d(:)
    integer :: ic, pattern, operation
    logical :: all_same(4)

    all_same = .true.
    do operation = 1, 4
      do pattern = 1, 2
        do ic = 1, size(coefficients)
          rx => new_vector(n, ic); rz => new_vector(n, 3)
          mx => new_vector(n, ic); mz => new_vector(n, 3)
          if (operation == 3) then
            d => FN_VGetArrayPointer_Serial(rx)
            where (d == 0) d = coefficients(ic) + 2
            d => FN_VGetArrayPointer_Serial(mx)
            where (d == 0) d = coefficients(ic) + 2
          end if
          if (pattern == 2) then   ! z = x
            rz => rx
            mz => mx
          end if
          select case (operation)
          case (1)
            call FN_VConst_Serial(coefficients(ic), rz)
            call fast_const(coefficients(ic), c_loc(mz))
          case (2)
            call FN_VAbs_Serial(rx, rz)
            call fast_abs(c_loc(mx), c_loc(mz))
          case (3)
            call FN_VInv_Serial(rx, rz)
            call fast_inv(c_loc(mx), c_loc(mz))
          case (4)
            call FN_VAddConst_Serial(rx, coefficients(ic), rz)
            call fast_add_const(c_loc(mx), coefficients(ic), c_loc(mz))
          end select
          all_same(operation) = all_same(operation) .and. same_bits(rx, mx) .and. same_bits(rz, mz)
          if (pattern == 1) then
            call FN_VDestroy(rz); call FN_VDestroy(mz)
          end if
          call FN_VDestroy(rx); call FN_VDestroy(mx)
        end do
      end do
    end do
    call check(all_same(1), 'const bitwise as N_VConst_Serial')
    call check(all_same(2), 'abs bitwise as N_VAbs_Serial (z = x and z /= x)')
    call check(all_same(3), 'inverse bitwise as N_VInv_Serial (z = x and z /= x)')
    call check(all_same(4), 'add-constant bitwise as N_VAddConst_Serial (z = x and z /= x)')
  end subroutine elementwise

  !> Y = Z (CVODE's use) and Y /= Z, one vector and several.
  subroutine scale_add_multis(n)
    integer, intent(in) :: n
    integer, parameter :: nvec = 4
    real(c_double), target :: a(nvec)
    type(N_Vector), pointer :: rx, mx
    type(c_ptr), target :: ry(nvec), rz(nvec), my(nvec), mz(nvec)
    type(N_Vector), pointer :: v, u
    integer :: k, pattern, count, ref_flag, fast_flag
    logical :: all_same

    a = [1.0_c_double, -1.0_c_double, 0.3_c_double, -2.5_c_double]
    all_same = .true.
    do pattern = 1, 2
      do count = 1, nvec, nvec - 1
        rx => new_vector(n, 1); mx => new_vector(n, 1)
        do k = 1, nvec
          v => new_vector(n, 1 + k); ry(k) = c_loc(v)
          v => new_vector(n, 1 + k); my(k) = c_loc(v)
          v => new_vector(n, 7 + k); rz(k) = c_loc(v)
          v => new_vector(n, 7 + k); mz(k) = c_loc(v)
        end do
        if (pattern == 1) then
          ref_flag = FN_VScaleAddMulti_Serial(int(count, c_int), a, rx, c_loc(ry), c_loc(rz))
          fast_flag = fast_scale_add_multi(int(count, c_int), a, c_loc(mx), c_loc(my), c_loc(mz))
        else
          ref_flag = FN_VScaleAddMulti_Serial(int(count, c_int), a, rx, c_loc(ry), c_loc(ry))
          fast_flag = fast_scale_add_multi(int(count, c_int), a, c_loc(mx), c_loc(my), c_loc(my))
        end if
        all_same = all_same .and. ref_flag == fast_flag .and. same_bits(rx, mx)
        do k = 1, nvec
          call c_f_pointer(ry(k), v); call c_f_pointer(my(k), u)
          all_same = all_same .and. same_bits(v, u)
          call FN_VDestroy(v); call FN_VDestroy(u)
          call c_f_pointer(rz(k), v); call c_f_pointer(mz(k), u)
          all_same = all_same .and. same_bits(v, u)
          call FN_VDestroy(v); call FN_VDestroy(u)
        end do
        call FN_VDestroy(rx); call FN_VDestroy(mx)
      end do
    end do
    call check(all_same, 'scale-add-multi bitwise as N_VScaleAddMulti_Serial (Y = Z and Y /= Z)')
    call check(fast_scale_add_multi(0_c_int, a, c_null_ptr, c_null_ptr, c_null_ptr) == -1, &
      'scale-add-multi refuses nvec < 1 as SUNDIALS does')
  end subroutine scale_add_multis

  !> speed_up_vector puts the routines into the table, and clones (CVODE's
  !> vectors) carry them.
  subroutine table_is_replaced()
    type(N_Vector), pointer :: v, clone
    type(N_Vector_Ops), pointer :: ops
    type(c_funptr) :: expected(8)   ! assigned, not a constant (no text relocation in the PIE)

    expected(1) = c_funloc(fast_linear_sum)
    expected(2) = c_funloc(fast_scale)
    expected(3) = c_funloc(fast_wrms_norm)
    expected(4) = c_funloc(fast_scale_add_multi)
    expected(5) = c_funloc(fast_const)
    expected(6) = c_funloc(fast_abs)
    expected(7) = c_funloc(fast_inv)
    expected(8) = c_funloc(fast_add_const)
    v => new_vector(10, 1)
    call check(speed_up_vector(v), 'speed_up_vector succeeds')
    clone => FN_VClone(v)
    call c_f_pointer(clone%ops, ops)
    call check(same_function(ops%nvlinearsum, expected(1)) .and. same_function(ops%nvscale, expected(2)) &
      .and. same_function(ops%nvwrmsnorm, expected(3)) .and. same_function(ops%nvscaleaddmulti, expected(4)) &
      .and. same_function(ops%nvconst, expected(5)) .and. same_function(ops%nvabs, expected(6)) &
      .and. same_function(ops%nvinv, expected(7)) .and. same_function(ops%nvaddconst, expected(8)), &
      'a clone of the sped-up vector uses the faster operations')
    call check(c_associated(ops%nvlinearcombination), 'fused linear combination switched on')
    call FN_VDestroy(clone); call FN_VDestroy(v)
  end subroutine table_is_replaced

  !> serial_data reads the serial vector's content as N_VGetArrayPointer does.
  subroutine data_as_sundials_gives_it()
    type(N_Vector), pointer :: v
    real(c_double), pointer :: reference(:)
    real(c_double), pointer, contiguous :: data(:)
    v => new_vector(17, 1)
    reference => FN_VGetArrayPointer_Serial(v)
    call serial_data(c_loc(v), data)
    call check(size(data) == 17 .and. c_associated(c_loc(data), c_loc(reference)), &
      'serial_data: the same array as N_VGetArrayPointer_Serial')
    call FN_VDestroy(v)
  end subroutine data_as_sundials_gives_it

  logical function same_function(f, g)
    type(c_funptr), intent(in) :: f, g
    same_function = transfer(f, 0_c_int64_t) == transfer(g, 0_c_int64_t)
  end function same_function

end program test_nvector_ops
