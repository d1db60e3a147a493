!> What every benchmark needs: the median of repeated timings.
module bench_timing
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: median

contains

  !> The median of x (the upper one of the middle two for an even count).
  pure real(wp) function median(x)
    real(wp), intent(in) :: x(:)
    real(wp) :: s(size(x)), tmp
    integer :: i, j
    s = x
    do i = 2, size(s)   ! insertion sort: a handful of repeats
      tmp = s(i)
      j = i - 1
      do while (j >= 1)
        if (s(j) <= tmp) exit
        s(j + 1) = s(j)
        j = j - 1
      end do
      s(j + 1) = tmp
    end do
    median = s((size(s) + 1)/2)
  end function median
end module bench_timing
