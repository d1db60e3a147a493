!> Knot placement decisions shared by the grid fits fpregr (regrid) and fppasu
!> (parsur): how many knots to add in one direction, and in which direction.

!> Number of knots to add in a direction that already has interior knots:
!> nplus*2 (twice the last addition there), unless that addition reduced fp by
!> reduc > acc, then the number it predicts for the remaining fpms =
!> fp - s, rn*fpms/reduc; kept within max(nplus/2, 1) .. nplus*2.
pure function fp_grid_knots_to_add(nplus, reduc, fpms, acc) result(npl)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: nplus
  real(real64), intent(in) :: reduc, fpms, acc
  integer :: npl, npl1
  real(real64) :: rn
  npl1 = nplus*2
  rn = nplus
  if (reduc > acc) npl1 = int(rn*fpms/reduc)
  npl = min(nplus*2, max(npl1, nplus/2, 1))
end function fp_grid_knots_to_add

!> True to add the knots in the first direction: it needs fewer (npl_first <
!> npl_second), or as many and the last addition was not in it (lastdi >= 0;
!> lastdi = -1 first, 1 second, 0 none yet); a full direction (its number of
!> knots at its upper limit) hands over to the other.
pure function fp_grid_add_first(npl_first, npl_second, lastdi, first_full, second_full) result(first)
  implicit none (type, external)
  integer, intent(in) :: npl_first, npl_second, lastdi
  logical, intent(in) :: first_full, second_full
  logical :: first
  if (npl_first < npl_second) then
    first = .true.
  else if (npl_first == npl_second) then
    first = lastdi >= 0
  else
    first = .false.
  end if
  if (first .and. first_full) first = .false.
  if (.not. first .and. second_full) first = .true.
end function fp_grid_add_first
