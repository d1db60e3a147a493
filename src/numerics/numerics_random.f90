!> Seeded uniform numbers for reproducible choices (the start points of a
!> multi-start optimisation): L'Ecuyer's combined multiple recursive
!> generator MRG32k3a (Operations Research 47(1), 1999, 159-164), in integer
!> arithmetic whose products stay below 2^53, so that every compiler and
!> every run give the same numbers. A stream is a value: copies are
!> independent, nothing is shared between threads.
module numerics_random
  use base_kinds, only: wp, int64
  implicit none (type, external)
  private
  public :: random_stream_t, new_random_stream, next_uniform

  integer(int64), parameter :: m1 = 4294967087_int64, m2 = 4294944443_int64
  integer(int64), parameter :: a12 = 1403580_int64, a13 = 810728_int64
  integer(int64), parameter :: a21 = 527612_int64, a23 = 1370589_int64
  !> draws discarded after seeding: nearby seeds start from nearby states,
  !> a few steps of the recursions (factors ~1e6 each) spread them
  integer, parameter :: warm_up = 20

  !> The generator's state: the last three values of each component. The
  !> default is L'Ecuyer's reference seed (12345 six times).
  type :: random_stream_t
    private
    integer(int64) :: s1(3) = 12345_int64
    integer(int64) :: s2(3) = 12345_int64
  end type random_stream_t

contains

  !> A stream for `seed` (>= 1; values are reduced into the components' ranges).
  pure function new_random_stream(seed) result(stream)
    integer, intent(in) :: seed
    type(random_stream_t) :: stream
    real(wp) :: unused
    integer :: k
    stream%s1 = modulo(int(seed, int64) + [0_int64, 12345_int64, 67890_int64], m1 - 1) + 1
    stream%s2 = modulo(int(seed, int64) + [54321_int64, 9876_int64, 13579_int64], m2 - 1) + 1
    do k = 1, warm_up
      call next_uniform(stream, unused)
    end do
  end function new_random_stream

  !> The next number, uniform in (0, 1).
  pure subroutine next_uniform(stream, u)
    type(random_stream_t), intent(inout) :: stream
    real(wp), intent(out) :: u
    integer(int64) :: p1, p2, d
    p1 = modulo(a12*stream%s1(2) - a13*stream%s1(1), m1)
    stream%s1 = [stream%s1(2), stream%s1(3), p1]
    p2 = modulo(a21*stream%s2(3) - a23*stream%s2(1), m2)
    stream%s2 = [stream%s2(2), stream%s2(3), p2]
    d = modulo(p1 - p2, m1)
    if (d == 0) d = m1
    u = real(d, wp)/real(m1 + 1, wp)
  end subroutine next_uniform
end module numerics_random
