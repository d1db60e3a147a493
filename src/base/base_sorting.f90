!> Small sorting helpers for input data (grid lines, measurement places).
module base_sorting
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: unique_sorted

contains

  !> The distinct values of x in increasing order (equal means bit-equal).
  !> Insertion sort: meant for the few dozen to few thousand values of an
  !> input, not for hot paths.
  pure function unique_sorted(x) result(u)
    real(wp), intent(in) :: x(:)
    real(wp), allocatable :: u(:)
    real(wp) :: work(size(x)), t
    integer :: i, j, n
    work = x
    do i = 2, size(work)
      t = work(i)
      j = i - 1
      do while (j >= 1)
        if (work(j) <= t) exit
        work(j + 1) = work(j)
        j = j - 1
      end do
      work(j + 1) = t
    end do
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

end module base_sorting
