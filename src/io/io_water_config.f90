!> &channel and &water: the channel the water runs in (when no fitted slide is
!> given) and the water model's parameters, start and outputs (docs/water.md).
module io_water_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use io_input, only: input_text_t, namelist_read_error, check_positive, check_nonnegative, &
    check_finite, check_finite_vector, check_choice, check_range, invalid, format_real, lower
  use geometry_tube, only: tube_surface_t, new_straight_tube, new_helix_tube, new_s_bend_tube
  use water_streamline, only: default_f1, default_f2, default_f3, CORRECTION_FULL, &
    CORRECTION_NO_RADIUS, CORRECTION_OFF
  use water_flow, only: water_start_t, START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED
  implicit none (type, external)
  private
  public :: water_config_t, read_water_config, read_channel_config, max_stations

  integer, parameter :: max_stations = 500

  type :: water_config_t
    real(wp) :: flow_rate = 0.004_wp                ! m^3/s
    type(water_start_t) :: start
    real(wp) :: f1 = default_f1, f2 = default_f2, f3 = default_f3   ! kg/m, kg, kg m
    integer :: correction = CORRECTION_FULL
    real(wp) :: mass = 1                            ! kg
    real(wp) :: gravity(3) = [0.0_wp, 0.0_wp, -standard_gravity]
    real(wp) :: min_speed = 0.05_wp                 ! m/s
    real(wp) :: min_criticality = 0.02_wp           ! 1
    real(wp), allocatable :: stations(:)            ! m of centerline arc length
    real(wp) :: table_step = 0.1_wp                 ! m
    logical :: edges = .true.
  end type water_config_t

contains

  !> &channel: kind = 'straight' | 'helix' | 's_bend' (circular tubes around
  !> closed-form centerlines, geometry_tube).
  subroutine read_channel_config(input, tube, status)
    type(input_text_t), intent(in) :: input
    type(tube_surface_t), intent(out) :: tube
    type(status_t), intent(inout) :: status
    character(len=16) :: kind
    real(wp) :: radius, incline_deg, length, helix_radius, pitch, turn_sense, turns, amplitude, &
                wavenumber, slope
    character(len=256) :: msg
    integer :: ios
    character(len=*), parameter :: g = 'channel'
    namelist /channel/ kind, radius, incline_deg, length, helix_radius, pitch, turn_sense, turns, &
      amplitude, wavenumber, slope

    kind = 'straight'; radius = 0.5_wp; incline_deg = 10; length = 50
    helix_radius = 3; pitch = 0.3_wp; turn_sense = 1; turns = 2
    amplitude = 1.5_wp; wavenumber = 0.4_wp; slope = 0.1_wp
    read (input%lines, nml=channel, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=12) :: 'kind', 'radius', 'incline_deg', &
        'length', 'helix_radius', 'pitch', 'turn_sense', 'turns', 'amplitude', 'wavenumber', 'slope'], status)
      return
    end if
    call check_choice(input, g, 'kind', kind, [character(len=8) :: 'straight', 'helix', 's_bend'], status)
    call check_positive(input, g, 'radius', radius, 'm', status)
    call check_positive(input, g, 'length', length, 'm', status)
    call check_range(input, g, 'incline_deg', incline_deg, 0.0_wp, 89.0_wp, 'degrees', status)
    call check_positive(input, g, 'helix_radius', helix_radius, 'm', status)
    call check_finite(input, g, 'pitch', pitch, status)
    call check_positive(input, g, 'turns', turns, '1', status)
    call check_finite(input, g, 'amplitude', amplitude, status)
    call check_positive(input, g, 'wavenumber', wavenumber, '1/m', status)
    call check_finite(input, g, 'slope', slope, status)
    if (status%ok() .and. abs(turn_sense) /= 1) &
      call invalid(input, g, 'turn_sense', format_real(turn_sense), 'must be +1 or -1', status)
    if (status%ok() .and. lower(adjustl(kind)) == 'helix' .and. helix_radius <= radius) &
      call invalid(input, g, 'helix_radius', format_real(helix_radius), &
                   'must exceed the tube radius '//format_real(radius)//' m (else the tube folds)', status)
    if (.not. status%ok()) return
    select case (lower(adjustl(kind)))
    case ('helix')
      tube = new_helix_tube(radius, helix_radius, pitch, turn_sense, 2*pi*turns, status)
    case ('s_bend')
      tube = new_s_bend_tube(radius, amplitude, wavenumber, slope, length, status)
    case default
      tube = new_straight_tube(radius, incline_deg*pi/180, length, status)
    end select
  end subroutine read_channel_config

  subroutine read_water_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(water_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    real(wp) :: flow_rate, u0, v0, v_left0, v_right0, height0, speed0, beta0, f1, f2, f3, mass, &
                gravity(3), min_speed, min_criticality, stations(max_stations), table_step
    character(len=16) :: start, correction
    logical :: edges
    character(len=256) :: msg
    integer :: ios, n, i
    character(len=*), parameter :: g = 'water'
    namelist /water/ flow_rate, start, u0, v0, v_left0, v_right0, height0, speed0, beta0, f1, f2, &
      f3, correction, mass, gravity, min_speed, min_criticality, stations, table_step, edges

    flow_rate = config%flow_rate; start = 'edges'
    u0 = config%start%u0; v0 = config%start%v0
    v_left0 = config%start%v_left; v_right0 = config%start%v_right
    height0 = config%start%height; speed0 = config%start%speed; beta0 = config%start%beta
    f1 = config%f1; f2 = config%f2; f3 = config%f3; correction = 'full'
    mass = config%mass; gravity = config%gravity
    min_speed = config%min_speed; min_criticality = config%min_criticality
    stations = -1; table_step = config%table_step; edges = config%edges
    read (input%lines, nml=water, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=16) :: 'flow_rate', 'start', 'u0', 'v0', &
        'v_left0', 'v_right0', 'height0', 'speed0', 'beta0', 'f1', 'f2', 'f3', 'correction', 'mass', &
        'gravity', 'min_speed', 'min_criticality', 'stations', 'table_step', 'edges'], status)
      return
    end if
    call check_choice(input, g, 'start', start, [character(len=12) :: 'edges', 'height', 'speed', &
                      'height_speed'], status)
    call check_choice(input, g, 'correction', correction, [character(len=9) :: 'full', 'no_radius', &
                      'off'], status)
    if (lower(adjustl(start)) /= 'height_speed') &
      call check_positive(input, g, 'flow_rate', flow_rate, 'm^3/s', status)
    call check_nonnegative(input, g, 'f1', f1, 'kg/m', status)
    call check_nonnegative(input, g, 'f2', f2, 'kg', status)
    call check_nonnegative(input, g, 'f3', f3, 'kg m', status)
    call check_finite(input, g, 'u0', u0, status)
    call check_finite(input, g, 'v0', v0, status)
    call check_finite(input, g, 'v_left0', v_left0, status)
    call check_finite(input, g, 'v_right0', v_right0, status)
    call check_range(input, g, 'beta0', beta0, -1.5_wp, 1.5_wp, 'rad', status)
    select case (lower(adjustl(start)))
    case ('edges')
      if (status%ok() .and. .not. v_left0 > v_right0) &
        call invalid(input, g, 'v_left0, v_right0', format_real(v_left0)//', '//format_real(v_right0), &
                     'the left edge must lie at larger v than the right edge', status)
    case ('height')
      call check_positive(input, g, 'height0', height0, 'm', status)
    case ('speed')
      call check_positive(input, g, 'speed0', speed0, 'm/s', status)
    case ('height_speed')
      call check_positive(input, g, 'height0', height0, 'm', status)
      call check_positive(input, g, 'speed0', speed0, 'm/s', status)
    end select
    call check_positive(input, g, 'mass', mass, 'kg', status)
    call check_finite_vector(input, g, 'gravity', gravity, status)
    call check_positive(input, g, 'min_speed', min_speed, 'm/s', status)
    call check_range(input, g, 'min_criticality', min_criticality, 1e-6_wp, 0.9_wp, '1', status)
    call check_positive(input, g, 'table_step', table_step, 'm', status)
    if (.not. status%ok()) return
    n = count(stations >= 0)
    if (any(stations(n + 1:) >= 0) .or. any(stations(:n) < 0)) then
      call invalid(input, g, 'stations', '...', 'arc lengths >= 0 (m), listed without gaps', status)
      return
    end if
    do i = 2, n
      if (.not. stations(i) > stations(i - 1)) then
        call invalid(input, g, 'stations('//format_integer(i)//')', format_real(stations(i)), &
                     'stations must increase along the slide', status)
        return
      end if
    end do
    config%flow_rate = flow_rate
    select case (lower(adjustl(start)))
    case ('height'); config%start%mode = START_HEIGHT
    case ('speed'); config%start%mode = START_SPEED
    case ('height_speed'); config%start%mode = START_HEIGHT_SPEED
    case default; config%start%mode = START_EDGES
    end select
    config%start%u0 = u0; config%start%v0 = v0
    config%start%v_left = v_left0; config%start%v_right = v_right0
    config%start%height = height0; config%start%speed = speed0; config%start%beta = beta0
    config%f1 = f1; config%f2 = f2; config%f3 = f3
    select case (lower(adjustl(correction)))
    case ('no_radius'); config%correction = CORRECTION_NO_RADIUS
    case ('off'); config%correction = CORRECTION_OFF
    case default; config%correction = CORRECTION_FULL
    end select
    config%mass = mass; config%gravity = gravity
    config%min_speed = min_speed; config%min_criticality = min_criticality
    config%stations = stations(:n)
    config%table_step = table_step
    config%edges = edges
  end subroutine read_water_config
end module io_water_config
