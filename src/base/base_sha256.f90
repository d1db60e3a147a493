!> SHA-256 (FIPS 180-4) of a text, as 64 lower-case hex digits: the hash of a
!> run's input stored in every result file, so two results can be told to come
!> from the same input without comparing texts. The 32-bit words are kept in
!> 64-bit integers and masked after every addition (Fortran has no unsigned
!> 32-bit arithmetic, and signed overflow is not allowed).
module base_sha256
  use, intrinsic :: iso_fortran_env, only: int64
  implicit none (type, external)
  private
  public :: sha256_hex

  integer(int64), parameter :: mask32 = int(z'FFFFFFFF', int64)
  ! first 32 bits of the fractional parts of the cube roots of the first 64 primes
  integer(int64), parameter :: k(0:63) = [ &
    int(z'428a2f98', int64), int(z'71374491', int64), int(z'b5c0fbcf', int64), int(z'e9b5dba5', int64), &
    int(z'3956c25b', int64), int(z'59f111f1', int64), int(z'923f82a4', int64), int(z'ab1c5ed5', int64), &
    int(z'd807aa98', int64), int(z'12835b01', int64), int(z'243185be', int64), int(z'550c7dc3', int64), &
    int(z'72be5d74', int64), int(z'80deb1fe', int64), int(z'9bdc06a7', int64), int(z'c19bf174', int64), &
    int(z'e49b69c1', int64), int(z'efbe4786', int64), int(z'0fc19dc6', int64), int(z'240ca1cc', int64), &
    int(z'2de92c6f', int64), int(z'4a7484aa', int64), int(z'5cb0a9dc', int64), int(z'76f988da', int64), &
    int(z'983e5152', int64), int(z'a831c66d', int64), int(z'b00327c8', int64), int(z'bf597fc7', int64), &
    int(z'c6e00bf3', int64), int(z'd5a79147', int64), int(z'06ca6351', int64), int(z'14292967', int64), &
    int(z'27b70a85', int64), int(z'2e1b2138', int64), int(z'4d2c6dfc', int64), int(z'53380d13', int64), &
    int(z'650a7354', int64), int(z'766a0abb', int64), int(z'81c2c92e', int64), int(z'92722c85', int64), &
    int(z'a2bfe8a1', int64), int(z'a81a664b', int64), int(z'c24b8b70', int64), int(z'c76c51a3', int64), &
    int(z'd192e819', int64), int(z'd6990624', int64), int(z'f40e3585', int64), int(z'106aa070', int64), &
    int(z'19a4c116', int64), int(z'1e376c08', int64), int(z'2748774c', int64), int(z'34b0bcb5', int64), &
    int(z'391c0cb3', int64), int(z'4ed8aa4a', int64), int(z'5b9cca4f', int64), int(z'682e6ff3', int64), &
    int(z'748f82ee', int64), int(z'78a5636f', int64), int(z'84c87814', int64), int(z'8cc70208', int64), &
    int(z'90befffa', int64), int(z'a4506ceb', int64), int(z'bef9a3f7', int64), int(z'c67178f2', int64)]
  ! first 32 bits of the fractional parts of the square roots of the first 8 primes
  integer(int64), parameter :: h0(0:7) = [ &
    int(z'6a09e667', int64), int(z'bb67ae85', int64), int(z'3c6ef372', int64), int(z'a54ff53a', int64), &
    int(z'510e527f', int64), int(z'9b05688c', int64), int(z'1f83d9ab', int64), int(z'5be0cd19', int64)]

contains

  !> The SHA-256 digest of the bytes of `text` as 64 lower-case hex digits.
  pure function sha256_hex(text) result(hex)
    character(len=*), intent(in) :: text
    character(len=64) :: hex
    character(len=*), parameter :: digits = '0123456789abcdef'
    integer(int64) :: h(0:7), w(0:63)
    integer(int64) :: n_bytes, n_blocks, block, bits
    integer :: i, j, nibble

    n_bytes = len(text, int64)
    n_blocks = (n_bytes + 8)/64 + 1     ! message, the 0x80 byte and the 8-byte length
    bits = 8*n_bytes
    h = h0
    do block = 0, n_blocks - 1
      do i = 0, 15
        w(i) = 0
        do j = 0, 3
          w(i) = ior(ishft(w(i), 8), padded_byte(64*block + 4*i + j))
        end do
      end do
      call compress(h, w)
    end do
    do i = 0, 7
      do j = 0, 7
        nibble = int(iand(ishft(h(i), -4*(7 - j)), 15_int64))
        hex(8*i + j + 1:8*i + j + 1) = digits(nibble + 1:nibble + 1)
      end do
    end do

  contains

    !> Byte `position` (from 0) of the padded message.
    pure integer(int64) function padded_byte(position)
      integer(int64), intent(in) :: position
      if (position < n_bytes) then
        padded_byte = int(ichar(text(position + 1:position + 1), kind=int64), int64)
      else if (position == n_bytes) then
        padded_byte = int(z'80', int64)
      else if (position >= 64*n_blocks - 8) then
        padded_byte = iand(ishft(bits, -8*int(64*n_blocks - 1 - position)), 255_int64)
      else
        padded_byte = 0
      end if
    end function padded_byte
  end function sha256_hex

  !> One 512-bit block: the message schedule w(0:15) given, h updated.
  pure subroutine compress(h, w)
    integer(int64), intent(inout) :: h(0:7), w(0:63)
    integer(int64) :: a, b, c, d, e, f, g, hh, t1, t2
    integer :: i
    do i = 16, 63
      w(i) = iand(small_sigma(w(i - 2), 17, 19, 10) + w(i - 7) + small_sigma(w(i - 15), 7, 18, 3) + w(i - 16), &
                  mask32)
    end do
    a = h(0); b = h(1); c = h(2); d = h(3); e = h(4); f = h(5); g = h(6); hh = h(7)
    do i = 0, 63
      t1 = iand(hh + big_sigma(e, 6, 11, 25) + ieor(iand(e, f), iand(ieor(e, mask32), g)) + k(i) + w(i), mask32)
      t2 = iand(big_sigma(a, 2, 13, 22) + ieor(ieor(iand(a, b), iand(a, c)), iand(b, c)), mask32)
      hh = g; g = f; f = e
      e = iand(d + t1, mask32)
      d = c; c = b; b = a
      a = iand(t1 + t2, mask32)
    end do
    h = iand(h + [a, b, c, d, e, f, g, hh], mask32)
  end subroutine compress

  pure integer(int64) function rotr(x, n)
    integer(int64), intent(in) :: x
    integer, intent(in) :: n
    rotr = iand(ior(ishft(x, -n), ishft(x, 32 - n)), mask32)
  end function rotr

  pure integer(int64) function big_sigma(x, p, q, r)
    integer(int64), intent(in) :: x
    integer, intent(in) :: p, q, r
    big_sigma = ieor(ieor(rotr(x, p), rotr(x, q)), rotr(x, r))
  end function big_sigma

  pure integer(int64) function small_sigma(x, p, q, shift)
    integer(int64), intent(in) :: x
    integer, intent(in) :: p, q, shift
    small_sigma = ieor(ieor(rotr(x, p), rotr(x, q)), ishft(x, -shift))
  end function small_sigma
end module base_sha256
