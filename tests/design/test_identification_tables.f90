!> The thesis's published identification tables fed through our cost and
!> report code (design_cost): the relations their own numbers must obey
!> (METHOD-PART2 C.8, D.5).
!> - F = position part + velocity part in every row of tables 4.2-4.4, 4.7-4.9
!>   (to the rounding of the printed 6 significant digits);
!> - table 4.8's three body parts sum to its position part;
!> - the relative columns of tables 4.4 and 4.9 recompute from the absolute ones;
!> - the RMSEs of table 4.11 row (1) follow from the parts of tables 4.3 and 4.8:
!>   error vectors with table 4.11's RMSE, put through our groups, give back
!>   the published parts (to the 3 printed digits of the RMSE), and our
!>   rmse_from_part gives back the RMSE from the published part.
program test_identification_tables
  use base_kinds, only: wp
  use design_cost, only: cost_group_t, new_cost_group, position_factor, speed_factor, group_part, &
    group_rmse, rmse_from_part, total_cost, append_residuals, relative_change_percent
  use testing, only: check, check_close, finish_tests
  use twin_data, only: noise_t
  implicit none (type, external)

  ! Table 4.2 (thesis L1623-1636): w, F1, position part, velocity part
  real(wp), parameter :: t42(4, 11) = reshape([ &
    0.0_wp, 0.00623842_wp, 0.00623842_wp, 0.0_wp, &
    0.1_wp, 0.00679106_wp, 0.00637753_wp, 0.000413526_wp, &
    0.2_wp, 0.00634861_wp, 0.00588863_wp, 0.00045998_wp, &
    0.3_wp, 0.00579425_wp, 0.00525537_wp, 0.000538874_wp, &
    0.4_wp, 0.00520169_wp, 0.00455341_wp, 0.000648282_wp, &
    0.5_wp, 0.00459147_wp, 0.00382462_wp, 0.000766853_wp, &
    0.6_wp, 0.00396751_wp, 0.00308947_wp, 0.000878035_wp, &
    0.7_wp, 0.00333569_wp, 0.00233705_wp, 0.000998641_wp, &
    0.8_wp, 0.00269256_wp, 0.00157814_wp, 0.00111442_wp, &
    0.9_wp, 0.00203287_wp, 0.00082892_wp, 0.00120395_wp, &
    1.0_wp, 0.00129371_wp, 0.0_wp, 0.00129371_wp], [4, 11])
  ! Table 4.4 (L1674-1685): F1, pos, vel, dF1 %, dpos %, dvel % of the nine variations
  real(wp), parameter :: t44(6, 9) = reshape([ &
    0.00270548_wp, 0.00155346_wp, 0.00115202_wp, 0.48_wp, -1.56_wp, 3.37_wp, &
    0.00270612_wp, 0.00160806_wp, 0.00109806_wp, 0.50_wp, 1.90_wp, -1.47_wp, &
    0.0027084_wp, 0.00155058_wp, 0.00115781_wp, 0.59_wp, -1.75_wp, 3.89_wp, &
    0.00270629_wp, 0.00161336_wp, 0.00109293_wp, 0.51_wp, 2.23_wp, -1.93_wp, &
    0.00269627_wp, 0.0015597_wp, 0.00113657_wp, 0.14_wp, -1.17_wp, 1.99_wp, &
    0.00269941_wp, 0.00160281_wp, 0.0010966_wp, 0.25_wp, 1.56_wp, -1.60_wp, &
    0.00278228_wp, 0.00152526_wp, 0.00125702_wp, 3.33_wp, -3.35_wp, 12.80_wp, &
    0.00278632_wp, 0.00168732_wp, 0.001099_wp, 3.48_wp, 6.92_wp, -1.38_wp, &
    0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], [6, 9])
  ! Table 4.7 (L1809-1822): w_RP, F2, position part, velocity part
  real(wp), parameter :: t47(4, 11) = reshape([ &
    0.0_wp, 0.0275293_wp, 0.0275293_wp, 0.0_wp, &
    0.1_wp, 0.0271846_wp, 0.024915_wp, 0.00226957_wp, &
    0.2_wp, 0.0265671_wp, 0.0224113_wp, 0.0041558_wp, &
    0.3_wp, 0.0257493_wp, 0.0198773_wp, 0.00587203_wp, &
    0.4_wp, 0.0247293_wp, 0.0174078_wp, 0.00732151_wp, &
    0.5_wp, 0.0235704_wp, 0.0148292_wp, 0.00874113_wp, &
    0.6_wp, 0.0222852_wp, 0.0121262_wp, 0.010159_wp, &
    0.7_wp, 0.0208789_wp, 0.00933124_wp, 0.0115477_wp, &
    0.8_wp, 0.0193594_wp, 0.00637829_wp, 0.0129811_wp, &
    0.9_wp, 0.0177447_wp, 0.00325653_wp, 0.0144882_wp, &
    1.0_wp, 0.0160369_wp, 0.0_wp, 0.0160369_wp], [4, 11])
  ! Table 4.9 (L1844-1849): F2, pos, vel, dF2 %, dpos %, dvel % of +1 %, -1 % mu_D
  real(wp), parameter :: t49(6, 2) = reshape([ &
    0.0230307_wp, 0.0113857_wp, 0.0116449_wp, 3.35_wp, -6.11_wp, 14.63_wp, &
    0.0229686_wp, 0.0133446_wp, 0.00962405_wp, 3.07_wp, 10.05_wp, -5.27_wp], [6, 2])
  integer :: i

  ! F = sum of the parts, through groups of errors whose parts are the table's
  do i = 1, 11
    call check_close(parts_total(t42(1, i), t42(3, i), t42(4, i), 27, 5), t42(2, i), 0.0_wp, &
                     rounding(t42(2:4, i)), &
                     'table 4.2: F1 = position part + velocity part')
    call check_close(parts_total(t47(1, i), t47(3, i), t47(4, i), 25, 5), t47(2, i), 0.0_wp, &
                     rounding(t47(2:4, i)), &
                     'table 4.7: F2 = position part + velocity part')
  end do
  do i = 1, 8
    call check_close(parts_total(0.8_wp, t44(2, i), t44(3, i), 27, 5), t44(1, i), 0.0_wp, &
                     rounding(t44(1:3, i)), &
                     'table 4.4: F1 = position part + velocity part')
    ! relative columns: printed with 2 decimals, so within 0.005 (+ rounding of the parts)
    call check_close(relative_change_percent(t44(1, i), t42(2, 9)), t44(4, i), 0.0_wp, 0.0051_wp, &
                     'table 4.4: dF1 % recomputed')
    call check_close(relative_change_percent(t44(2, i), t42(3, 9)), t44(5, i), 0.0_wp, 0.0051_wp, &
                     'table 4.4: dpos % recomputed')
    call check_close(relative_change_percent(t44(3, i), t42(4, 9)), t44(6, i), 0.0_wp, 0.0051_wp, &
                     'table 4.4: dvel % recomputed')
  end do
  do i = 1, 2
    call check_close(parts_total(0.6_wp, t49(2, i), t49(3, i), 25, 5), t49(1, i), 0.0_wp, &
                     rounding(t49(1:3, i)), &
                     'table 4.9: F2 = position part + velocity part')
    call check_close(relative_change_percent(t49(1, i), t47(2, 7)), t49(4, i), 0.0_wp, 0.0051_wp, &
                     'table 4.9: dF2 % recomputed')
    call check_close(relative_change_percent(t49(2, i), t47(3, 7)), t49(5, i), 0.0_wp, 0.0051_wp, &
                     'table 4.9: dpos % recomputed')
    call check_close(relative_change_percent(t49(3, i), t47(4, 7)), t49(6, i), 0.0_wp, 0.0051_wp, &
                     'table 4.9: dvel % recomputed')
  end do
  ! Table 4.8: pelvis + upper body + lower body = position part
  call check_close(0.00275415_wp + 0.00646893_wp + 0.00290308_wp, 0.0121262_wp, 0.0_wp, &
                   rounding([0.00275415_wp, 0.00646893_wp, 0.00290308_wp, 0.0121262_wp]), &
                   'table 4.8: the three body parts sum to the position part')
  call rmse_relations()
  call finish_tests('test_identification_tables')

contains

  !> The thesis prints 6 significant digits: a sum of printed numbers agrees
  !> with the printed total within half a unit in the last place of each.
  pure real(wp) function rounding(values) result(tol)
    real(wp), intent(in) :: values(:)
    integer :: i
    tol = 0
    do i = 1, size(values)
      if (values(i) /= 0) tol = tol + 0.5_wp*10.0_wp**(floor(log10(abs(values(i)))) - 5)
    end do
    tol = tol*(1 + 1e-9_wp)   ! the binary form of the decimals
  end function rounding

  !> Builds the two groups of a cost with n position and m speed errors whose
  !> parts are the published ones (constant errors of the right size) and
  !> returns our total: half the sum of the squared residual vector.
  real(wp) function parts_total(weight, position_part, velocity_part, n, m) result(f)
    real(wp), intent(in) :: weight, position_part, velocity_part
    integer, intent(in) :: n, m
    type(cost_group_t) :: groups(2)
    real(wp) :: r(n + m), cp, cv
    integer :: offset
    cp = position_factor(weight, n)
    cv = speed_factor(weight, 1.0_wp, m)
    groups(1) = new_cost_group('position', 'rad', cp, spread(error_size(position_part, cp, n), 1, n))
    groups(2) = new_cost_group('speed', 'm s-1', cv, spread(error_size(velocity_part, cv, m), 1, m))
    offset = 0
    call append_residuals(groups(1), r, offset)
    call append_residuals(groups(2), r, offset)
    f = 0.5_wp*sum(r**2)
    call check_close(f, total_cost(groups), 1e-14_wp, 0.0_wp, 'half the squared residuals = sum of parts')
    call check_close(group_part(groups(1)), position_part, 1e-13_wp, 1e-18_wp, 'position group has its part')
  end function parts_total

  pure real(wp) function error_size(part, factor, n) result(e)
    real(wp), intent(in) :: part, factor
    integer, intent(in) :: n
    e = 0
    if (factor > 0) e = sqrt(2*part/(factor*n))
  end function error_size

  !> Table 4.11 row (1): flow 0.126 rad / 0.053 m/s; pelvis 0.117 rad, speed 0.184 m/s.
  subroutine rmse_relations()
    type(noise_t) :: noise
    type(cost_group_t) :: g
    ! RMSEs printed with 3 digits: +-0.0005 of ~0.1 is +-0.5 %, so a part
    ! (quadratic) agrees to +-1 %
    real(wp), parameter :: part_tol = 0.011_wp, rmse_tol = 0.0005_wp
    call check_close(rmse_from_part(0.00157814_wp, position_factor(0.8_wp, 27), 27), 0.126_wp, 0.0_wp, &
                     rmse_tol, 'table 4.11: flow position RMSE from the position part of table 4.3')
    call check_close(rmse_from_part(0.00111442_wp, speed_factor(0.8_wp, 1.0_wp, 5), 5), 0.053_wp, 0.0_wp, &
                     rmse_tol, 'table 4.11: flow speed RMSE from the velocity part of table 4.3')
    call check_close(rmse_from_part(0.00275415_wp, position_factor(0.6_wp, 25), 25), 0.117_wp, 0.0_wp, &
                     rmse_tol, 'table 4.11: pelvis position RMSE from its part in table 4.8')
    call check_close(rmse_from_part(0.010159_wp, speed_factor(0.6_wp, 1.0_wp, 5), 5), 0.184_wp, 0.0_wp, &
                     rmse_tol, 'table 4.11: rider speed RMSE from the velocity part of table 4.8')
    ! and the other way: scattered errors with the published RMSE give the part
    g = new_cost_group('position', 'rad', position_factor(0.8_wp, 27), scaled_errors(noise, 27, 0.126_wp))
    call check_close(group_rmse(g), 0.126_wp, 1e-14_wp, 0.0_wp, 'scaled errors have the RMSE asked for')
    call check_close(group_part(g), 0.00157814_wp, part_tol, 0.0_wp, &
                     'errors with table 4.11''s flow RMSE give table 4.3''s position part')
    g = new_cost_group('speed', 'm s-1', speed_factor(0.8_wp, 1.0_wp, 5), scaled_errors(noise, 5, 0.053_wp))
    call check_close(group_part(g), 0.00111442_wp, part_tol, 0.0_wp, &
                     'errors with table 4.11''s speed RMSE give table 4.3''s velocity part')
    g = new_cost_group('pelvis', 'rad', position_factor(0.6_wp, 25), scaled_errors(noise, 25, 0.117_wp))
    call check_close(group_part(g), 0.00275415_wp, part_tol, 0.0_wp, &
                     'errors with table 4.11''s pelvis RMSE give table 4.8''s pelvis part')
  end subroutine rmse_relations

  function scaled_errors(noise, n, rmse) result(e)
    type(noise_t), intent(inout) :: noise
    integer, intent(in) :: n
    real(wp), intent(in) :: rmse
    real(wp) :: e(n)
    integer :: i
    do i = 1, n
      e(i) = noise%normal()
    end do
    e = e*rmse/sqrt(sum(e**2)/n)
  end function scaled_errors
end program test_identification_tables
