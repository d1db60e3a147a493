!> Helpers of the twin-experiment tests: a reproducible Gaussian noise source
!> (xorshift64* and Box-Muller, the same numbers on every machine and
!> compiler, unlike random_number) and evenly spread measurement places.
module twin_data
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: noise_t, evenly

  type :: noise_t
    integer(int64) :: state = 88172645463325252_int64
  contains
    procedure :: uniform => noise_uniform
    procedure :: normal => noise_normal
  end type noise_t

contains

  !> Uniform in (0, 1): the top 53 bits of xorshift64* (Vigna 2016).
  real(wp) function noise_uniform(self) result(x)
    class(noise_t), intent(inout) :: self
    integer(int64) :: s, r
    s = self%state
    s = ieor(s, shiftr(s, 12))
    s = ieor(s, shiftl(s, 25))
    s = ieor(s, shiftr(s, 27))
    self%state = s
    r = s*2685821657736338717_int64
    x = (real(shiftr(r, 11), wp) + 0.5_wp)/2.0_wp**53
  end function noise_uniform

  !> Standard normal (Box-Muller, one of the pair).
  real(wp) function noise_normal(self) result(x)
    class(noise_t), intent(inout) :: self
    real(wp) :: u1, u2
    u1 = self%uniform()
    u2 = self%uniform()
    x = sqrt(-2*log(u1))*cos(2*3.141592653589793_wp*u2)
  end function noise_normal

  !> n points from a to b, ends included.
  pure function evenly(a, b, n) result(x)
    real(wp), intent(in) :: a, b
    integer, intent(in) :: n
    real(wp) :: x(n)
    integer :: i
    do i = 1, n
      x(i) = a + (b - a)*(i - 1)/real(max(n - 1, 1), wp)
    end do
  end function evenly
end module twin_data
