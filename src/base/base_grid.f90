!> Evenly spaced values: the grids every result file draws its surface on
!> (io_surface_grid), shared with code outside io that must sample the same
!> points (tests/geometry/shipped_geometries.f90).
module base_grid
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: evenly_spaced

contains

  !> n evenly spaced values from a to b.
  pure function evenly_spaced(a, b, n) result(values)
    real(wp), intent(in) :: a, b
    integer, intent(in) :: n
    real(wp) :: values(n)
    integer :: i
    values = [(a + (b - a)*i/real(max(n - 1, 1), wp), i=0, n - 1)]
  end function evenly_spaced
end module base_grid
