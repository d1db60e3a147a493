!> Vectors, rotations, the status convention, SHA-256 and numbers as text.
program test_base
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, set_status, prefix_status, STATUS_SOLVER
  use base_sha256, only: sha256_hex
  use base_text, only: format_real, format_integer, format_short, next_data_line
  use base_vector, only: cross, skew, unit_vector, rot_x, rot_y, rot_z, rotation_xyz, identity3, outer3
  use testing, only: check, check_close, check_close_array, finish_tests
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_positive_inf, ieee_negative_inf, &
                                          ieee_quiet_nan
  implicit none (type, external)

  real(wp), parameter :: tol = 1e-15_wp   ! a few roundings of O(1) numbers
  real(wp) :: a(3), b(3), r(3, 3), angles(3), s(3, 3), rx(3, 3), ry(3, 3), rz(3, 3)
  type(status_t) :: status
  integer :: mismatches   ! of check_number_texts

  a = [0.3_wp, -1.2_wp, 2.0_wp]
  b = [1.5_wp, 0.4_wp, -0.7_wp]
  s = skew(a)
  call check_close_array(cross(a, b), matmul(s, b), 0.0_wp, tol, 'skew(a) b = a x b')
  call check_close(dot_product(cross(a, b), a), 0.0_wp, 0.0_wp, 4*tol, 'a x b is normal to a')
  call check_close_array(cross([1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp]), [0.0_wp, 0.0_wp, 1.0_wp], &
                         0.0_wp, 0.0_wp, 'e1 x e2 = e3')
  call check_close(norm2(unit_vector(a)), 1.0_wp, tol, 0.0_wp, 'unit vector')
  call check(all(unit_vector([0.0_wp, 0.0_wp, 0.0_wp]) == 0), 'zero stays zero')
  call check_close_array(reshape(outer3(a, b), [9]), [&
                         a*b(1), a*b(2), a*b(3)], 0.0_wp, 0.0_wp, 'outer product columns')

  ! Rotations: orthonormal, determinant 1, a quarter turn about z maps x to y.
  rx = rot_x(pi/2); ry = rot_y(pi/2); rz = rot_z(pi/2)
  call check_close_array(rz(:, 1), [0.0_wp, 1.0_wp, 0.0_wp], 0.0_wp, tol, 'Rz(90) x = y')
  call check_close_array(rx(:, 2), [0.0_wp, 0.0_wp, 1.0_wp], 0.0_wp, tol, 'Rx(90) y = z')
  call check_close_array(ry(:, 3), [1.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, tol, 'Ry(90) z = x')
  angles = [0.4_wp, -1.1_wp, 2.3_wp]
  r = rotation_xyz(angles)
  call check_close_array(reshape(matmul(transpose(r), r), [9]), reshape(identity3(), [9]), 0.0_wp, 4*tol, &
                         'R^T R = I')
  rx = rot_x(angles(1)); ry = rot_y(angles(2)); rz = rot_z(angles(3))
  s = matmul(matmul(rx, ry), rz)
  call check_close_array(reshape(r, [9]), reshape(s, [9]), 0.0_wp, 4*tol, 'Cardan order x, y, z')
  ! Rotation of a cross product: R(a x b) = (R a) x (R b) (proper rotation).
  call check_close_array(matmul(r, cross(a, b)), cross(matmul(r, a), matmul(r, b)), 0.0_wp, 20*tol, &
                         'rotations keep handedness')

  call check(status%ok() .and. status%text() == 'ok', 'fresh status is ok')
  call set_status(status, STATUS_SOLVER, 'diverged')
  call prefix_status(status, 'loop 2')
  call check(.not. status%ok() .and. status%text() == 'loop 2: diverged', 'message with context: '//status%text())
  ! SHA-256: the test vectors of FIPS 180-2 appendix B; 55 and 64 bytes (values
  ! from Python's hashlib) sit at the one-block padding limit and a full block.
  call check(sha256_hex('') == 'e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855', 'sha256 empty')
  call check(sha256_hex('abc') == 'ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad', 'sha256 abc')
  call check(sha256_hex('abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq') == &
             '248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1', 'sha256 two blocks (56 bytes)')
  call check(sha256_hex(repeat('a', 1000000)) == 'cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0', &
             'sha256 one million a')
  call check(sha256_hex(repeat('a', 55)) == '9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318', &
             'sha256 55 bytes')
  call check(sha256_hex(repeat('a', 64)) == 'ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb', &
             'sha256 64 bytes')
  call check_number_texts()
  call check_data_lines()
  call finish_tests('test_base')

contains

  !> next_data_line: blank and # lines passed over with their numbers counted,
  !> a CRLF line end and surrounding blanks dropped, the last line without a
  !> line end, false at the end.
  subroutine check_data_lines()
    character(len=*), parameter :: lf = new_line('a')
    character(len=:), allocatable :: text, line
    integer :: start, line_no
    text = '# header'//lf//lf//'  1, 2 '//achar(13)//lf//'   '//lf//'3,4'
    start = 1
    line_no = 0
    call check(next_data_line(text, start, line_no, line), 'first data line found')
    call check(line == '1, 2' .and. line_no == 3, 'first data line "'//line//'" at line '//format_integer(line_no))
    call check(next_data_line(text, start, line_no, line), 'last line without a line end found')
    call check(line == '3,4' .and. line_no == 5, 'last data line "'//line//'" at line '//format_integer(line_no))
    call check(.not. next_data_line(text, start, line_no, line), 'false at the end')
    start = 1
    line_no = 0
    call check(.not. next_data_line('# only'//lf//lf, start, line_no, line) .and. line_no == 2, &
               'a text of comments and blanks has no data line')
  end subroutine check_data_lines

  !> format_real against tests/reference/number_texts.txt: 8704 doubles
  !> (random of every magnitude, random bit patterns, every power of two,
  !> subnormals, one and two digits times powers of ten, hundredths and
  !> sevenths as the outputs have) with the texts Python's repr gives them
  !> (the fewest digits that read back; scripts/reference/number_texts.py,
  !> which states the layout rule); format_integer as an internal write.
  subroutine check_number_texts()
    integer :: k, i, unit, ios, count
    integer(int64) :: bits
    character(len=80) :: line
    character(len=40) :: text
    mismatches = 0
    count = 0
    open (newunit=unit, file='tests/reference/number_texts.txt', status='old', action='read', iostat=ios)
    call check(ios == 0, 'tests/reference/number_texts.txt opens (run from the repository root)')
    if (ios /= 0) return
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == '#') cycle
      read (line(1:16), '(z16)') bits
      text = line(18:)
      call compare(transfer(bits, 1.0_wp), trim(text))
      count = count + 1
    end do
    close (unit)
    call check(count == 8704, 'number_texts.txt: 8704 doubles read, got '//format_integer(count))
    call check(mismatches == 0, 'format_real: the texts of the Python-made table')
    call check_extremes()
    mismatches = 0
    do i = -1, 1, 2
      do k = 0, 62
        call compare_integer(i*int(min(2_int64**k, int(huge(1), int64))))
        call compare_integer(i*int(min(10_int64**min(k, 18), int(huge(1), int64))))
      end do
    end do
    call compare_integer(-huge(1) - 1)
    call compare_integer(0)
    call check(mismatches == 0, 'format_integer as an internal write (i0)')
  end subroutine check_number_texts

  !> The extremes, in the Debug build too (it traps overflow, also inside
  !> strtod: reading back 2.E+308, few digits of huge, trapped there): the
  !> texts are Python's repr of the same doubles (the shortest that reads
  !> back), exponents of three digits with their E (JSON numbers);
  !> format_short's exponent form likewise.
  subroutine check_extremes()
    real(wp) :: x
    call expect(huge(x), '1.7976931348623157E+308')
    call expect(-huge(x), '-1.7976931348623157E+308')
    x = huge(x)
    call expect(x - spacing(x), '1.7976931348623155E+308')   ! (gfortran 12 folds nearest(huge, -1) to 2**1023)
    call expect(1.5_wp*scale(1.0_wp, 1023), '1.348269851146737E+308')
    call expect(1e308_wp, '1.0E+308')
    call expect(1e100_wp, '1.0E+100')
    call expect(1e-100_wp, '1.0E-100')
    call expect(tiny(x), '2.2250738585072014E-308')
    call expect(1e-320_wp, '1.0E-320')
    call expect(-1.5e-310_wp, '-1.5E-310')
    call expect(scale(1.0_wp, -1074), '5.0E-324')
    call expect(scale(3.0_wp, -1074), '1.5E-323')
    call expect(ieee_value(x, ieee_positive_inf), 'Inf')
    call expect(ieee_value(x, ieee_negative_inf), '-Inf')
    call expect(ieee_value(x, ieee_quiet_nan), 'NaN')
    call check(format_short(huge(x)) == '1.79769E+308', 'format_short(huge) = '//format_short(huge(x)))
    call check(format_short(-1e-320_wp) == '-9.99989E-321', 'format_short(-1e-320) = '//format_short(-1e-320_wp))
    call check(format_short(1e-7_wp) == '1.00000E-07', 'format_short(1e-7) = '//format_short(1e-7_wp))
  end subroutine check_extremes

  subroutine expect(x, text)
    real(wp), intent(in) :: x
    character(len=*), intent(in) :: text
    call check(format_real(x) == text, 'format_real: '//text//' as '//format_real(x))
  end subroutine expect

  subroutine compare(x, text)
    real(wp), intent(in) :: x
    character(len=*), intent(in) :: text
    if (format_real(x) == text) return
    mismatches = mismatches + 1
    if (mismatches <= 5) print '(a, es25.17, 4a)', 'format_real(', x, ') = ', format_real(x), &
      ', table: ', text
  end subroutine compare

  subroutine compare_integer(i)
    integer, intent(in) :: i
    character(len=24) :: buffer
    write (buffer, '(i0)') i
    if (format_integer(i) == trim(buffer)) return
    mismatches = mismatches + 1
    print '(3a)', format_integer(i), ' /= ', trim(buffer)
  end subroutine compare_integer
end program test_base
