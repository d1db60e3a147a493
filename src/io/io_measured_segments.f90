!> The measurements in &identify of the scenarios identify_water and
!> identify_rider (docs/design.md), read one way for both: the speeds on
!> segments of the slide (a CSV file `segments_file`, start, end, speed per
!> row, or the lists segment_start, segment_end, segment_speed) and the
!> values measured at places along it (identify_water's sections: arc length
!> and middle angle; identify_rider's stations: arc length and the three
!> contacts' angles), from a CSV file or the lists. The checks of measured
!> places (in order, a segment's end after its start) refuse a value where
!> it was given: the CSV file's line, or the input's list.
module io_measured_segments
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use io_input, only: input_text_t, group_reader_t, bounds_t, format_real, indexed_name
  use io_csv, only: read_csv_table
  implicit none (type, external)
  private
  public :: read_measured_segments, read_measured_places, check_in_order, refuse_measured

  integer, parameter :: max_segments = 1000

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
    integer, allocatable :: lines(:)
    integer :: k
    path = ''
    allocate (starts(0), ends(0), speeds(0))
    if (len_trim(segments_file) > 0) then
      call read_measured_file(input, r, 'segments_file', segments_file, names, 'segment', max_segments, table, &
                              lines, path, status)
      if (.not. status%ok()) return
      starts = table(1, :)
      ends = table(2, :)
      speeds = table(3, :)
    else
      call r%get_list('segment_start', starts, max_segments, status)
      call r%get_list('segment_end', ends, max_segments, status)
      call r%get_list('segment_speed', speeds, max_segments, status)
      if (.not. status%ok()) return
      if (twin) speeds = 0*starts
      call check_counts([size(starts), size(ends), size(speeds)], .not. twin, r, status)
      if (.not. status%ok()) return
      lines = [(0, k=1, size(starts))]
    end if
    do k = 1, size(starts)
      if (ends(k) > starts(k)) cycle
      call refuse_measured(r, 'segments_file', path, lines, 'segment_end', k, format_real(ends(k)), &
                           'segment '//format_integer(k)//' must end after its start '//format_real(starts(k))// &
                           ' m', status)
      return
    end do
  end subroutine read_measured_segments

  !> Places along the slide with values measured at each (`what`: 'station',
  !> 'section'): from the CSV file `places_file` (as written in the input; ''
  !> for the lists), a row per place, or from the lists `names` (the places'
  !> first, then one per value), `path` the file resolved ('' for the
  !> lists). values(j, k) is the j-th value at place k. In a twin experiment
  !> (`twin`) the values are synthesised later: zeros here. The places must
  !> increase.
  subroutine read_measured_places(input, r, file_variable, places_file, names, what, twin, max_places, places, &
                                  values, path, status)
    type(input_text_t), intent(in) :: input
    type(group_reader_t), intent(inout) :: r
    character(len=*), intent(in) :: file_variable, places_file, names(:), what
    logical, intent(in) :: twin
    integer, intent(in) :: max_places
    real(wp), allocatable, intent(out) :: places(:), values(:, :)
    character(len=:), allocatable, intent(out) :: path
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: table(:, :), list(:)
    integer, allocatable :: lines(:)
    integer :: j, k
    path = ''
    if (len_trim(places_file) > 0) then
      call read_measured_file(input, r, file_variable, places_file, names, what, max_places, table, lines, path, &
                              status)
      if (.not. status%ok()) return
      places = table(1, :)
      values = table(2:, :)
    else
      call r%get_list(trim(names(1)), places, max_places, status)
      if (.not. status%ok()) return
      allocate (values(size(names) - 1, size(places)))
      values = 0   ! a twin's: synthesised by the scenario
      do j = 2, size(names)
        call r%get_list(trim(names(j)), list, max_places, status)
        if (.not. status%ok()) return
        if (twin) cycle
        if (size(list) /= size(places)) then
          call r%invalid(trim(names(j)), format_integer(size(list))//' values', 'one per '//what//' ('// &
                         format_integer(size(places))//' '//what//'s)', status)
          return
        end if
        values(j - 1, :) = list
      end do
      lines = [(0, k=1, size(places))]
    end if
    call check_in_order(places, r, file_variable, path, lines, trim(names(1)), what, status)
  end subroutine read_measured_places

  !> The rows of the CSV file `file` (as written in the input) that the
  !> variable `file_variable` names: a column per variable of `names`, each
  !> within its declared bounds; `path` the file resolved, `lines` each row's
  !> line. Refused if a list of `names` is given beside the file (`what`:
  !> 'segment', 'station', 'section').
  subroutine read_measured_file(input, r, file_variable, file, names, what, max_rows, table, lines, path, status)
    type(input_text_t), intent(in) :: input
    type(group_reader_t), intent(inout) :: r
    character(len=*), intent(in) :: file_variable, file, names(:), what
    integer, intent(in) :: max_rows
    real(wp), allocatable, intent(out) :: table(:, :)
    integer, allocatable, intent(out) :: lines(:)
    character(len=:), allocatable, intent(out) :: path
    type(status_t), intent(inout) :: status
    type(bounds_t) :: columns(size(names))
    integer :: k
    path = input%resolve_path(file)
    do k = 1, size(names)
      if (r%has(trim(names(k)))) then
        call r%invalid(trim(names(k)), 'given', 'the '//what//'s come from '//file_variable, status)
        return
      end if
      call r%bounds(trim(names(k)), columns(k), status)
    end do
    if (.not. status%ok()) return
    call read_csv_table(path, size(names), size(names), max_rows, columns, table, status, lines)
    if (.not. status%ok()) call prefix_status(status, r%where(file_variable)//': &'//r%group//': '//file_variable)
  end subroutine read_measured_file

  !> Places along the slide (stations, sections) that must each lie after
  !> the one before: the first that does not is refused where it was given.
  subroutine check_in_order(places, r, file_variable, path, lines, variable, what, status)
    real(wp), intent(in) :: places(:)   ! m
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: file_variable, path, variable, what   ! what: 'station', 'section'
    integer, intent(in) :: lines(:)
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 2, size(places)
      if (places(k) > places(k - 1)) cycle
      call refuse_measured(r, file_variable, path, lines, variable, k, format_real(places(k)), &
                           what//' '//format_integer(k)//' must lie after the one before it ('// &
                           format_real(places(k - 1))//' m): list them in order along the slide', status)
      return
    end do
  end subroutine check_in_order

  !> Refuses measurement k: from a CSV file (`path` not empty) at its line,
  !> naming the input's variable that names the file; from the input's list
  !> `variable` as any refused value (file:line: &group: variable(k) = ...).
  subroutine refuse_measured(r, file_variable, path, lines, variable, k, value, allowed, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: file_variable, path, variable, value, allowed
    integer, intent(in) :: lines(:), k
    type(status_t), intent(inout) :: status
    if (len(path) > 0) then
      call set_status(status, STATUS_INVALID_INPUT, path//':'//format_integer(lines(k))//': '//value// &
                      ' is not allowed: '//allowed//' (the file named by '//r%where(file_variable)//': &'// &
                      r%group//' '//file_variable//')')
    else
      call r%invalid(indexed_name(variable, k), value, allowed, status)
    end if
  end subroutine refuse_measured

  !> One start, end and speed per segment. Of three lists the one whose
  !> length differs from the other two is refused (all three named when all
  !> differ); of two (a twin experiment synthesises the speeds) the longer,
  !> which has the extra values.
  subroutine check_counts(counts, with_speeds, r, status)
    integer, intent(in) :: counts(3)   ! of segment_start, segment_end, segment_speed
    logical, intent(in) :: with_speeds
    type(group_reader_t), intent(in) :: r
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: names(3) = [character(len=13) :: 'segment_start', 'segment_end', &
                                                'segment_speed']
    character(len=*), parameter :: one = 'one start, end and speed per segment'
    integer :: k, other(2)
    if (.not. with_speeds) then
      if (counts(1) == counts(2)) return
      k = merge(1, 2, counts(1) > counts(2))
      call r%invalid(trim(names(k)), shown(trim(names(k))), format_integer(counts(k))//' values where '// &
                     trim(names(3 - k))//' has '//format_integer(counts(3 - k))//': one start and one end per '// &
                     'segment (a twin experiment synthesises the speeds)', status)
      return
    end if
    if (all(counts == counts(1))) return
    do k = 1, 3
      other = pack([1, 2, 3], [1, 2, 3] /= k)
      if (counts(other(1)) /= counts(other(2))) cycle
      call r%invalid(trim(names(k)), shown(trim(names(k))), format_integer(counts(k))//' values where '// &
                     trim(names(other(1)))//' and '//trim(names(other(2)))//' have '// &
                     format_integer(counts(other(1)))//': '//one, status)
      return
    end do
    call r%invalid('segment_start', shown('segment_start'), one//': segment_start, segment_end and '// &
                   'segment_speed have '//format_integer(counts(1))//', '//format_integer(counts(2))//' and '// &
                   format_integer(counts(3))//' values', status)

  contains

    function shown(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      text = r%written(name)
      if (len(text) == 0) text = '(not given)'
    end function shown
  end subroutine check_counts
end module io_measured_segments
