!> The grid of a free-form patch (&slide_elements patch_file, kind =
!> 'patch'; geometry_patch_section): a CSV file of `station, angle, offset`
!> per line (m along the element's horizontal length from its start, deg
!> around the section with 90 the bottom, m outward along the section's
!> radius), the points filling a rectangular grid of stations x angles in
!> any order (the grid built by geometry_patch_grid). Checked here, naming
!> the file and the line: the numbers and their ranges (io_csv), a point
!> given twice, a point of the grid missing.
!> What needs the slide (the element's length, the section's radius and
!> angles, the border's offsets 0, at least 6 stations and angles) the
!> geometry layer checks when it builds the slide.
module io_patch_grid
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use io_input, only: bounds_t, in_range, format_real
  use io_csv, only: read_csv_table
  use geometry_patch_section, only: patch_grid_t
  use geometry_patch_grid, only: patch_grid_from_points
  implicit none (type, external)
  private
  public :: read_patch_grid

  integer, parameter :: max_patch_points = 100000

contains

  !> The grid of element `element` from the CSV file at `path`.
  subroutine read_patch_grid(path, element, grid, status)
    character(len=*), intent(in) :: path
    integer, intent(in) :: element
    type(patch_grid_t), intent(out) :: grid
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: table(:, :)
    integer, allocatable :: lines(:), given(:, :)
    integer :: i, j, twice
    type(bounds_t) :: station, angle, offset
    station = in_range(0.0_wp, 1e4_wp, 'm')
    angle = in_range(0.0_wp, 360.0_wp, 'deg')
    offset = in_range(-100.0_wp, 100.0_wp, 'm')
    call read_csv_table(path, 3, 3, max_patch_points, [station, angle, offset], table, status, lines)
    if (.not. status%ok()) return
    call patch_grid_from_points(element, table, grid, given, twice)
    if (twice > 0) then
      i = findloc(grid%station, table(1, twice), 1)
      j = findloc(grid%angle_deg, table(2, twice), 1)
      call set_status(status, STATUS_INVALID_INPUT, path//':'//format_integer(lines(twice))//': station '// &
                      format_real(table(1, twice))//' m, angle '//format_real(table(2, twice))//' deg is given '// &
                      'already on line '//format_integer(lines(given(i, j)))//': each point of the grid once')
      return
    end if
    do j = 1, size(grid%angle_deg)
      do i = 1, size(grid%station)
        if (given(i, j) > 0) cycle
        call set_status(status, STATUS_INVALID_INPUT, path//': no offset at station '// &
                        format_real(grid%station(i))//' m, angle '//format_real(grid%angle_deg(j))//' deg: '// &
                        'the points must fill the grid of the stations and angles given ('// &
                        format_integer(size(grid%station))//' x '//format_integer(size(grid%angle_deg))//')')
        return
      end do
    end do
  end subroutine read_patch_grid
end module io_patch_grid
