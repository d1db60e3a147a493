!> What every benchmark needs: the median of repeated timings.
module bench_timing
  use base_kinds, only: wp
  use base_sorting, only: sort_ascending
  implicit none (type, external)
  private
  public :: median

contains

  !> The median of x (the upper one of the middle two for an even count).
  pure real(wp) function median(x)
    real(wp), intent(in) :: x(:)
    real(wp) :: s(size(x))
    s = x
    call sort_ascending(s)
    median = s((size(s) + 1)/2)
  end function median
end module bench_timing
