!> The grid of a free-form patch (&slide_elements patch_file, kind =
!> 'patch'; geometry_patch_section): a CSV file of `station, angle, offset`
!> per line (m along the element's horizontal length from its start, deg
!> around the section with 90 the bottom, m outward along the section's
!> radius), the points filling a rectangular grid of stations x angles in
!> any order. Checked here, naming the file and the line: the numbers and
!> their ranges (io_csv), a point given twice, a point of the grid missing.
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
    integer, allocatable :: lines(:), line_of(:, :)
    integer :: k, i, j
    type(bounds_t) :: station, angle, offset
    station = in_range(0.0_wp, 1e4_wp, 'm')
    angle = in_range(0.0_wp, 360.0_wp, 'deg')
    offset = in_range(-100.0_wp, 100.0_wp, 'm')
    grid%element = element
    call read_csv_table(path, 3, 3, max_patch_points, [station, angle, offset], table, status, lines)
    if (.not. status%ok()) return
    grid%station = distinct(table(1, :))
    grid%angle_deg = distinct(table(2, :))
    allocate (grid%offset(size(grid%station), size(grid%angle_deg)), line_of(size(grid%station), &
              size(grid%angle_deg)))
    grid%offset = 0
    line_of = 0
    do k = 1, size(table, 2)
      i = findloc(grid%station, table(1, k), 1)
      j = findloc(grid%angle_deg, table(2, k), 1)
      if (line_of(i, j) > 0) then
        call set_status(status, STATUS_INVALID_INPUT, path//':'//format_integer(lines(k))//': station '// &
                        format_real(table(1, k))//' m, angle '//format_real(table(2, k))//' deg is given '// &
                        'already on line '//format_integer(line_of(i, j))//': each point of the grid once')
        return
      end if
      line_of(i, j) = lines(k)
      grid%offset(i, j) = table(3, k)
    end do
    do j = 1, size(grid%angle_deg)
      do i = 1, size(grid%station)
        if (line_of(i, j) > 0) cycle
        call set_status(status, STATUS_INVALID_INPUT, path//': no offset at station '// &
                        format_real(grid%station(i))//' m, angle '//format_real(grid%angle_deg(j))//' deg: '// &
                        'the points must fill the grid of the stations and angles given ('// &
                        format_integer(size(grid%station))//' x '//format_integer(size(grid%angle_deg))//')')
        return
      end do
    end do
  end subroutine read_patch_grid

  !> The distinct values of x, increasing.
  pure function distinct(x) result(values)
    real(wp), intent(in) :: x(:)
    real(wp), allocatable :: values(:)
    real(wp) :: low
    values = [real(wp) ::]
    low = -huge(1.0_wp)
    do while (any(x > low))
      low = minval(x, mask=x > low)
      values = [values, low]
    end do
  end function distinct
end module io_patch_grid
