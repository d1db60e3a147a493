!> The weighted least-squares costs of the thesis's identifications (4.34 for
!> the water, 4.43 for the rider) and the figures reported with them.
!>
!> A cost is a sum of parts, one per group of errors e = simulated - measured
!> (the water's section positions, its segment speeds; the rider's three
!> contact positions, its speeds). Group g has a factor c_g and contributes
!>   part_g = 1/2 c_g sum_i e_i^2,      residuals r_i = sqrt(c_g) e_i,
!> so that F = sum_g part_g = 1/2 sum r^2 (the least-squares convention of
!> MINPACK and of NAG's e04unc). The thesis's factors:
!>   positions  c = (1 - w)/n           (n errors of the group's kind)
!>   speeds     c = w k^2/m             (m speeds; k in rad s/m turns m/s into rad)
!> For the rider the three contacts' positions share n = n_SP and (1 - w_RP).
!>
!> Relations that follow (METHOD-PART2 C.8, D.5) and that report code must
!> keep: F = sum of parts; RMSE_g = sqrt(sum e^2/n_g) = sqrt(2 part_g/(c_g n_g)),
!> i.e. sqrt(2 P/(1 - w)) for positions and sqrt(2 V/(w k^2)) for speeds.
module design_cost
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: cost_group_t, new_cost_group, position_factor, speed_factor
  public :: group_part, group_rmse, group_mae, group_max_abs, rmse_from_part
  public :: total_cost, append_residuals, relative_change_percent

  type :: cost_group_t
    character(len=:), allocatable :: name    !< 'position', 'speed', 'pelvis', ...
    character(len=:), allocatable :: unit    !< of the errors, UDUNITS ('rad', 'm s-1')
    real(wp) :: factor = 1                   !< c_g
    real(wp), allocatable :: errors(:)       !< simulated - measured
  end type cost_group_t

contains

  pure function new_cost_group(name, unit, factor, errors) result(g)
    character(len=*), intent(in) :: name, unit
    real(wp), intent(in) :: factor, errors(:)
    type(cost_group_t) :: g
    g%name = name
    g%unit = unit
    g%factor = factor
    g%errors = errors
  end function new_cost_group

  !> (1 - w)/n: the factor of a position group of n errors (4.34, 4.43).
  pure real(wp) function position_factor(weight, n) result(c)
    real(wp), intent(in) :: weight
    integer, intent(in) :: n
    c = 0
    if (n > 0) c = (1 - weight)/n
  end function position_factor

  !> w k^2/m: the factor of a speed group of m errors (4.34, 4.43).
  pure real(wp) function speed_factor(weight, k, m) result(c)
    real(wp), intent(in) :: weight, k
    integer, intent(in) :: m
    c = 0
    if (m > 0) c = weight*k**2/m
  end function speed_factor

  pure real(wp) function group_part(g) result(part)
    type(cost_group_t), intent(in) :: g
    part = 0.5_wp*g%factor*sum(g%errors**2)
  end function group_part

  pure real(wp) function group_rmse(g) result(rmse)
    type(cost_group_t), intent(in) :: g
    rmse = 0
    if (size(g%errors) > 0) rmse = sqrt(sum(g%errors**2)/size(g%errors))
  end function group_rmse

  pure real(wp) function group_mae(g) result(mae)
    type(cost_group_t), intent(in) :: g
    mae = 0
    if (size(g%errors) > 0) mae = sum(abs(g%errors))/size(g%errors)
  end function group_mae

  pure real(wp) function group_max_abs(g) result(m)
    type(cost_group_t), intent(in) :: g
    m = 0
    if (size(g%errors) > 0) m = maxval(abs(g%errors))
  end function group_max_abs

  !> The RMSE of a group from its part alone: sqrt(2 part/(c n)), so that a
  !> published part gives the published RMSE (C.8). Zero factor: no errors.
  pure real(wp) function rmse_from_part(part, factor, n) result(rmse)
    real(wp), intent(in) :: part, factor
    integer, intent(in) :: n
    rmse = 0
    if (factor > 0 .and. n > 0) rmse = sqrt(2*part/(factor*n))
  end function rmse_from_part

  pure real(wp) function total_cost(groups) result(f)
    type(cost_group_t), intent(in) :: groups(:)
    integer :: g
    f = 0
    do g = 1, size(groups)
      f = f + group_part(groups(g))
    end do
  end function total_cost

  !> r(offset + 1 : offset + n_g) = sqrt(c_g) e; offset advanced.
  pure subroutine append_residuals(g, r, offset)
    type(cost_group_t), intent(in) :: g
    real(wp), intent(inout) :: r(:)
    integer, intent(inout) :: offset
    integer :: n
    n = size(g%errors)
    r(offset + 1:offset + n) = sqrt(g%factor)*g%errors
    offset = offset + n
  end subroutine append_residuals

  !> 100 (value - reference)/reference, the relative columns of tables 4.4, 4.9.
  elemental real(wp) function relative_change_percent(value, reference) result(percent)
    real(wp), intent(in) :: value, reference
    percent = 100*(value - reference)/reference
  end function relative_change_percent
end module design_cost
