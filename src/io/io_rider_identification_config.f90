!> &identify of the scenario identify_rider: the rider's measurements (from
!> CSV files or given in the group), the weights, bounds and solver settings
!> of the rider-friction identification (thesis 4.4.3; docs/design.md lists
!> every variable with unit, default and range).
module io_rider_identification_config
  use base_kinds, only: wp
  use base_status, only: status_t
  use design_rider_identification, only: rider_measurements_t, rider_fit_options_t
  use io_input, only: input_text_t, group_reader_t, open_group, format_real
  use io_measured_segments, only: read_measured_segments, read_measured_places
  use io_identification_config, only: read_identify_weight, read_identify_solver
  implicit none (type, external)
  private
  public :: rider_identification_config_t, read_rider_identification_config

  integer, parameter :: max_stations = 10000

  type :: rider_identification_config_t
    type(rider_measurements_t) :: data
    type(rider_fit_options_t) :: options
    integer :: threads = 1
    logical :: sensitivity = .false.     !< the body-parameter study of table 4.10
    logical :: twin = .false.            !< synthesise the measurements with twin_mu (noise-free)
    real(wp) :: twin_mu = 0
    character(len=:), allocatable :: stations_file, segments_file   !< as resolved ('' when inline)
  end type rider_identification_config_t

contains

  subroutine read_rider_identification_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(rider_identification_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=1024) :: stations_file, segments_file
    character(len=*), parameter :: station_names(4) = [character(len=18) :: 'station_arc_length', &
      'pelvis_angle', 'heels_angle', 'back_angle']
    integer :: k

    call open_group(input, 'identify', r, status, table='identify_rider')
    if (.not. status%ok()) return
    stations_file = ''
    segments_file = ''
    call r%get('stations_file', stations_file, status)
    call r%get('segments_file', segments_file, status)
    if (.not. status%ok()) return
    config%twin = r%has('twin_mu')
    if (config%twin) then
      call r%get('twin_mu', config%twin_mu, status)
      if (.not. status%ok()) return
      if (len_trim(stations_file) > 0 .or. len_trim(segments_file) > 0) then
        call r%invalid('twin_mu', format_real(config%twin_mu), 'a twin experiment synthesises the '// &
                       'measurements: give the places (station_arc_length, segment_start, segment_end), no files', &
                       status)
        return
      end if
      do k = 2, size(station_names)
        if (r%has(trim(station_names(k)))) then
          call r%invalid(trim(station_names(k)), 'given', 'twin_mu synthesises the angles', status)
          return
        end if
      end do
      if (r%has('segment_speed')) then
        call r%invalid('segment_speed', 'given', 'twin_mu synthesises the speeds', status)
        return
      end if
    end if

    ! the stations: a CSV file (arc length, pelvis, heels, back) or the lists
    call read_measured_places(input, r, 'stations_file', stations_file, station_names, 'station', config%twin, &
                              max_stations, config%data%station_arc_length, config%data%angle, &
                              config%stations_file, status)
    if (.not. status%ok()) return

    ! the segments: a CSV file (start, end, speed) or the lists
    call read_measured_segments(input, r, segments_file, config%twin, config%data%segment_start, &
                                config%data%segment_end, config%data%segment_speed, config%segments_file, status)
    if (.not. status%ok()) return

    ! the fit
    associate (o => config%options)
      call read_identify_weight(r, size(config%data%station_arc_length), size(config%data%segment_start), &
                                'station_arc_length', 'stations', .true., o%weight, status)
      if (.not. status%ok()) return
      call r%get('k2', o%k2, status)
      call r%get('lower', o%lower, status)
      call r%get('upper', o%upper, status)
      if (.not. status%ok()) return
      if (.not. o%upper > o%lower) then
        call r%invalid('upper', format_real(o%upper), 'must exceed lower = '//format_real(o%lower), status)
        return
      end if
      call read_identify_solver(r, o%solver, config%threads, status)
    end associate
    call r%get('sensitivity', config%sensitivity, status)
  end subroutine read_rider_identification_config
end module io_rider_identification_config
