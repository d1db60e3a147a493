!> &identify of the scenario identify_water: the water's measurements (from
!> CSV files or given in the group), the weights, bounds and solver settings
!> of the water-friction identification (thesis 4.4.1; docs/design.md lists
!> every variable with unit, default and range).
module io_water_identification_config
  use base_kinds, only: wp
  use base_status, only: status_t
  use design_water_identification, only: water_measurements_t, water_fit_options_t, SPEED_MIDPOINT, &
    SPEED_PASSAGE, MIDDLE_EDGES, MIDDLE_STREAMLINE
  use io_input, only: input_text_t, group_reader_t, open_group, format_real
  use io_measured_segments, only: read_measured_segments, read_measured_places
  use io_identification_config, only: read_identify_weight, read_identify_solver
  implicit none (type, external)
  private
  public :: water_identification_config_t, read_water_identification_config

  integer, parameter :: max_sections = 10000, max_weights = 100

  type :: water_identification_config_t
    type(water_measurements_t) :: data
    type(water_fit_options_t) :: options
    integer :: speed_kind = SPEED_MIDPOINT
    integer :: middle_kind = MIDDLE_EDGES
    integer :: threads = 1
    real(wp), allocatable :: sweep_weights(:)   !< the weight sweep of table 4.2 (none: size 0)
    logical :: twin = .false.                   !< synthesise the measurements with twin_f (noise-free)
    real(wp) :: twin_f(3) = 0
    character(len=:), allocatable :: sections_file, segments_file
  end type water_identification_config_t

contains

  subroutine read_water_identification_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(water_identification_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=1024) :: sections_file, segments_file
    character(len=10) :: speed_kind, middle_kind
    real(wp), allocatable :: values(:, :)
    character(len=*), parameter :: section_names(2) = [character(len=18) :: 'section_arc_length', 'section_v']

    call open_group(input, 'identify', r, status, table='identify_water')
    if (.not. status%ok()) return
    sections_file = ''
    segments_file = ''
    call r%get('sections_file', sections_file, status)
    call r%get('segments_file', segments_file, status)
    if (.not. status%ok()) return
    config%twin = r%has('twin_f')
    if (config%twin) then
      call r%get('twin_f', config%twin_f, status)
      if (.not. status%ok()) return
      if (len_trim(sections_file) > 0 .or. len_trim(segments_file) > 0 .or. r%has('section_v') .or. &
          r%has('segment_speed')) then
        call r%invalid('twin_f', 'given', 'a twin experiment synthesises the measurements: give the places '// &
                       '(section_arc_length, segment_start, segment_end), no values and no files', status)
        return
      end if
    end if

    ! the sections: a CSV file (arc length, middle angle v) or the lists
    call read_measured_places(input, r, 'sections_file', sections_file, section_names, 'section', config%twin, &
                              max_sections, config%data%section_arc_length, values, config%sections_file, status)
    if (.not. status%ok()) return
    config%data%section_v = values(1, :)

    ! the segments: a CSV file (start, end, speed) or the lists
    call read_measured_segments(input, r, segments_file, config%twin, config%data%segment_start, &
                                config%data%segment_end, config%data%segment_speed, config%segments_file, status)
    if (.not. status%ok()) return

    associate (o => config%options)
      call read_identify_weight(r, size(config%data%section_arc_length), size(config%data%segment_start), &
                                'section_arc_length', 'sections', .false., o%weight, status)
      if (.not. status%ok()) return
      call r%get('k1', o%k1, status)
      call r%get_parts('estimate', o%estimate, 'f1, f2, f3', status)
      call r%get_parts('lower', o%lower, 'f1, f2, f3', status)
      call r%get_parts('upper', o%upper, 'f1, f2, f3', status)
      if (.not. status%ok()) return
      if (any(.not. o%upper > o%lower)) then
        call r%invalid('upper', format_real(o%upper(findloc(.not. o%upper > o%lower, .true., dim=1))), &
                       'each upper must exceed its lower', status)
        return
      end if
      if (.not. any(o%estimate)) then
        call r%invalid('estimate', '.false., .false., .false.', 'estimate at least one of f1, f2, f3', status)
        return
      end if
      call read_identify_solver(r, o%solver, config%threads, status)
    end associate
    speed_kind = 'midpoint'
    middle_kind = 'edges'
    call r%get('speed', speed_kind, status)
    call r%get('middle', middle_kind, status)
    config%speed_kind = merge(SPEED_MIDPOINT, SPEED_PASSAGE, speed_kind == 'midpoint')
    config%middle_kind = merge(MIDDLE_EDGES, MIDDLE_STREAMLINE, middle_kind == 'edges')
    call r%get_list('sweep_weights', config%sweep_weights, max_weights, status)
  end subroutine read_water_identification_config
end module io_water_identification_config
