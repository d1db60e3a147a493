!> The grid of a free-form patch (geometry_patch_section's patch_grid_t) from
!> its points in any order: the construction a reader of a patch file
!> (io_patch_grid) and a library caller share; the checks that need the
!> slide (the border's offsets 0, at least 6 stations and angles) come when
!> the slide is built.
module geometry_patch_grid
  use base_kinds, only: wp
  use base_sorting, only: unique_sorted
  use geometry_patch_section, only: patch_grid_t
  implicit none (type, external)
  private
  public :: patch_grid_from_points

contains

  !> The grid of element `element` from its points, one per column of
  !> `points` (station m, angle deg, offset m): the distinct stations and
  !> angles, increasing, and each point's offset at its place (0 where no
  !> point is). given(i, j): the column that gave the grid's point (station
  !> i, angle j), 0 none. twice: the first column whose place an earlier one
  !> (given there) took already, 0 none; the filling stops at it.
  pure subroutine patch_grid_from_points(element, points, grid, given, twice)
    integer, intent(in) :: element
    real(wp), intent(in) :: points(:, :)
    type(patch_grid_t), intent(out) :: grid
    integer, allocatable, intent(out) :: given(:, :)
    integer, intent(out) :: twice
    integer :: k, i, j
    grid%element = element
    grid%station = unique_sorted(points(1, :))
    grid%angle_deg = unique_sorted(points(2, :))
    allocate (grid%offset(size(grid%station), size(grid%angle_deg)), given(size(grid%station), &
              size(grid%angle_deg)))
    grid%offset = 0
    given = 0
    twice = 0
    do k = 1, size(points, 2)
      i = findloc(grid%station, points(1, k), 1)
      j = findloc(grid%angle_deg, points(2, k), 1)
      if (given(i, j) > 0) then
        twice = k
        return
      end if
      given(i, j) = k
      grid%offset(i, j) = points(3, k)
    end do
  end subroutine patch_grid_from_points
end module geometry_patch_grid
