!> Small sorting helpers for input data (grid lines, measurement places).
module base_sorting
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: unique_sorted, sort_ascending

contains

  !> The distinct values of x in increasing order (equal means bit-equal).
  !> Insertion sort: meant for the few dozen to few thousand values of an
  !> input, not for hot paths.
  pure function unique_sorted(x) result(u)
    real(wp), intent(in) :: x(:)
    real(wp), allocatable :: u(:)
    real(wp) :: work(size(x))
    integer :: i, n
    work = x
    call sort_ascending(work)
    n = 0
    do i = 1, size(work)
      if (n > 0) then
        if (work(i) == work(n)) cycle
      end if
      n = n + 1
      work(n) = work(i)
    end do
    u = work(1:n)
  end function unique_sorted

  !> x in increasing order, repeated values kept. Insertion sort: for inputs,
  !> tests and benchmarks (a few thousand values at most), not hot paths.
  pure subroutine sort_ascending(x)
    real(wp), intent(inout) :: x(:)
    real(wp) :: t
    integer :: i, j
    do i = 2, size(x)
      t = x(i)
      j = i - 1
      do while (j >= 1)
        if (x(j) <= t) exit
        x(j + 1) = x(j)
        j = j - 1
      end do
      x(j + 1) = t
    end do
  end subroutine sort_ascending

end module base_sorting
