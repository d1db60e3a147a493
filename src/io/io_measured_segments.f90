!> The measured speeds on segments of the slide in &identify of the
!> scenarios identify_water and identify_rider (docs/design.md): a CSV file
!> `segments_file` (start, end, speed per row) or the lists segment_start,
!> segment_end, segment_speed; read one way for both.
module io_measured_segments
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, prefix_status
  use io_input, only: input_text_t, group_reader_t, in_range, above
  use io_csv, only: read_csv_table
  implicit none (type, external)
  private
  public :: read_measured_segments

  integer, parameter :: max_segments = 1000
  real(wp), parameter :: longest = 1e6_wp   !< m, the largest arc length taken

contains

  !> The segments from `segments_file` (as written in the input; '' for the
  !> lists), its resolved `path` ('' for the lists). In a twin experiment
  !> (`twin`) the speeds are synthesised later: zeros here.
  subroutine read_measured_segments(input, r, segments_file, twin, starts, ends, speeds, path, status)
    type(input_text_t), intent(in) :: input
    type(group_reader_t), intent(inout) :: r
    character(len=*), intent(in) :: segments_file
    logical, intent(in) :: twin
    real(wp), allocatable, intent(out) :: starts(:), ends(:), speeds(:)   ! m, m, m/s
    character(len=:), allocatable, intent(out) :: path
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: names(3) = [character(len=13) :: 'segment_start', 'segment_end', &
                                                'segment_speed']
    real(wp), allocatable :: table(:, :)
    integer :: k
    path = ''
    allocate (starts(0), ends(0), speeds(0))
    if (len_trim(segments_file) > 0) then
      do k = 1, size(names)
        if (r%has(trim(names(k)))) then
          call r%invalid(trim(names(k)), 'given', 'the segments come from segments_file', status)
          return
        end if
      end do
      path = input%resolve_path(segments_file)
      call read_csv_table(path, 3, 3, max_segments, [in_range(0.0_wp, longest, 'm'), &
                          in_range(0.0_wp, longest, 'm'), above(0.0_wp, 100.0_wp, 'm/s')], table, status)
      if (.not. status%ok()) then
        call prefix_status(status, r%where('segments_file')//': &identify: segments_file')
        return
      end if
      starts = table(1, :)
      ends = table(2, :)
      speeds = table(3, :)
    else
      call r%get_list('segment_start', starts, max_segments, in_range(0.0_wp, longest, 'm'), status)
      call r%get_list('segment_end', ends, max_segments, in_range(0.0_wp, longest, 'm'), status)
      call r%get_list('segment_speed', speeds, max_segments, above(0.0_wp, 100.0_wp, 'm/s'), status)
      if (.not. status%ok()) return
      if (twin) speeds = 0*starts
      if (size(ends) /= size(starts) .or. size(speeds) /= size(starts)) then
        call r%invalid('segment_end', format_integer(size(ends))//' ends, '//format_integer(size(speeds))// &
                       ' speeds', 'one end and one speed per segment start ('//format_integer(size(starts))//')', &
                       status)
        return
      end if
    end if
  end subroutine read_measured_segments
end module io_measured_segments
