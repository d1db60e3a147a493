!> Robust design (issue 29 point 4; docs/design.md, "Robust design over a
!> population"): the rides of a design may be a population of bodies and
!> starts (ride_member_t, one ride each), and the acceleration part of the
!> cost (4.49) may be the population's worst ride or a quantile of its rides
!> instead of the sum over the rides:
!>   COST_SUM       1/2 sum_i (max_t |a_i|)^2, the thesis's (4.49);
!>   COST_WORST     1/2 (max_i max_t |a_i|)^2;
!>   COST_QUANTILE  1/2 Q_q(max_t |a_i|)^2, Q_q the q-quantile of the rides'
!>                  maxima, linear between order statistics (Hyndman and
!>                  Fan's definition 7, numpy's default): continuous in the
!>                  design, Q_1 the worst ride exactly.
!> The constraint residuals stay one per ride: every member must stay
!> pressed and within the lever-arm limit, whatever the cost's statistic.
module design_robust_cost
  use base_kinds, only: wp
  use base_sorting, only: sort_ascending
  use design_cuboid_ride, only: cuboid_t
  implicit none (type, external)
  private
  public :: ride_member_t, COST_SUM, COST_WORST, COST_QUANTILE, cost_names, robust_maximum, quantile, &
    worst_ride, cost_description

  integer, parameter :: COST_SUM = 0, COST_WORST = 1, COST_QUANTILE = 2
  character(len=*), parameter :: cost_names(0:2) = [character(len=8) :: 'sum', 'worst', 'quantile']

  !> One member of a population: the body and the start of its ride (the
  !> start direction is the optimisation's start_angles(i)).
  type :: ride_member_t
    type(cuboid_t) :: body
    real(wp) :: speed = 0.5_wp      !< m/s at the start
    real(wp) :: v = 0               !< rad, section angle of the start (pi/2 the bottom)
    real(wp) :: height = 1.8_wp     !< m, the member's height as given (&sweep height): the body's length
  end type ride_member_t

contains

  !> The statistic of the rides' largest accelerations that the cost
  !> squares (COST_WORST, COST_QUANTILE; m/s^2).
  pure real(wp) function robust_maximum(maxima, cost, q) result(a)
    real(wp), intent(in) :: maxima(:)
    integer, intent(in) :: cost
    real(wp), intent(in) :: q
    if (cost == COST_QUANTILE) then
      a = quantile(maxima, q)
    else
      a = maxval(maxima)
    end if
  end function robust_maximum

  !> The q-quantile (0 <= q <= 1) of x, linear between order statistics:
  !> h = (n - 1) q + 1, x_(floor h) + (h - floor h)(x_(floor h + 1) - x_(floor h)).
  pure real(wp) function quantile(x, q) result(value)
    real(wp), intent(in) :: x(:), q
    real(wp) :: sorted(size(x)), h
    integer :: low, n
    n = size(x)
    sorted = x
    call sort_ascending(sorted)   ! insertion sort: populations are small, evaluations rare
    h = (n - 1)*q + 1
    low = min(n, max(1, floor(h)))
    if (low == n) then
      value = sorted(n)
    else
      value = sorted(low) + (h - low)*(sorted(low + 1) - sorted(low))
    end if
  end function quantile

  !> The ride with the largest acceleration (the first of equal ones).
  pure integer function worst_ride(maxima)
    real(wp), intent(in) :: maxima(:)
    worst_ride = maxloc(maxima, dim=1)
  end function worst_ride

  !> The cost's statistic in words.
  pure function cost_description(cost, q) result(text)
    integer, intent(in) :: cost
    real(wp), intent(in) :: q
    character(len=:), allocatable :: text
    character(len=24) :: number
    select case (cost)
    case (COST_WORST)
      text = 'the worst ride: 1/2 (max_i max_t |a_i|)^2'
    case (COST_QUANTILE)
      write (number, '(g0.6)') q
      text = 'the '//trim(adjustl(number))//'-quantile of the rides: 1/2 Q(max_t |a_i|)^2'
    case default
      text = 'the sum over the rides (4.49): 1/2 sum_i (max_t |a_i|)^2'
    end select
  end function cost_description
end module design_robust_cost
