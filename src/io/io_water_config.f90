!> &channel and &water: the channel the water runs in (when no fitted slide is
!> given) and the water model's parameters, start and outputs (docs/water.md),
!> read into the geometry layer's channel_description_t and the water layer's
!> water_description_t (water_run): io reads, the layers build.
module io_water_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t, prefix_status, STATUS_INVALID_INPUT
  use io_input, only: input_text_t, group_reader_t, open_group, format_real, group_count, where_given
  use geometry_channel, only: channel_description_t
  use water_streamline, only: CORRECTION_FULL, CORRECTION_NO_RADIUS, CORRECTION_OFF
  use water_flow, only: START_EDGES, START_HEIGHT, START_SPEED, START_HEIGHT_SPEED
  use water_run, only: water_description_t, water_inlet_t
  implicit none (type, external)
  private
  public :: read_water_config, read_channel_config, explain_channel_failure, max_stations

  integer, parameter :: max_stations = 500

contains

  !> &channel: kind = 'straight' | 'helix' | 's_bend' (circular tubes around
  !> closed-form centerlines), read into the geometry layer's
  !> channel_description_t (geometry_channel); build_channel builds it.
  subroutine read_channel_config(input, channel, status)
    type(input_text_t), intent(in) :: input
    type(channel_description_t), intent(out) :: channel
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=:), allocatable :: unused

    call open_group(input, 'channel', r, status)
    call r%get('kind', channel%kind, status)
    call r%get('radius', channel%radius, status)
    if (.not. status%ok()) return
    unused = 'a '//trim(channel%kind)//' channel does not use it (see docs/water.md)'
    select case (trim(channel%kind))
    case ('helix')
      call r%refuse_given([character(len=12) :: 'incline_deg', 'length', 'amplitude', 'wavenumber', 'slope'], unused, status)
      call r%get('helix_radius', channel%helix_radius, status)
      call r%get('pitch', channel%pitch, status)
      call r%get('turn_sense', channel%turn_sense, status)
      call r%get('turns', channel%turns, status)
    case ('s_bend')
      call r%refuse_given([character(len=12) :: 'incline_deg', 'helix_radius', 'pitch', 'turn_sense', 'turns'], unused, status)
      call r%get('length', channel%length, status)
      call r%get('amplitude', channel%amplitude, status)
      call r%get('wavenumber', channel%wavenumber, status)
      call r%get('slope', channel%slope, status)
    case default
      call r%refuse_given([character(len=12) :: 'helix_radius', 'pitch', 'turn_sense', 'turns', 'amplitude', &
                          'wavenumber', 'slope'], unused, status)
      call r%get('length', channel%length, status)
      call r%get('incline_deg', channel%incline_deg, status)
    end select
  end subroutine read_channel_config

  !> The failure `built` of building &channel's tube (build_channel, whose
  !> `variable` is the value at fault, '' for the tube as a whole) put in
  !> `status`, naming the line of that value (else of &channel's kind).
  !> Nothing when `built` is ok.
  subroutine explain_channel_failure(input, built, variable, status)
    type(input_text_t), intent(in) :: input
    type(status_t), intent(in) :: built
    character(len=*), intent(in) :: variable
    type(status_t), intent(inout) :: status
    if (built%ok()) return
    status = built
    status%code = STATUS_INVALID_INPUT
    if (len(variable) > 0) then
      call prefix_status(status, where_given(input, 'channel', variable)//': &channel')
    else
      call prefix_status(status, where_given(input, 'channel', 'kind')//': &channel')
    end if
  end subroutine explain_channel_failure

  !> The water's part of `config` from &water: everything but the slide
  !> (&surface or &channel) and the solver (&solver or &water_solver), which
  !> it keeps; a variable not given keeps its value (the type's default).
  subroutine read_water_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(water_description_t), intent(inout) :: config
    type(status_t), intent(inout) :: status
    character(len=12) :: start, correction
    type(group_reader_t) :: r
    character(len=:), allocatable :: unused
    integer :: i

    start = 'edges'
    correction = 'full'
    call open_group(input, 'water', r, status)
    call r%get('start', start, status)
    call r%get('correction', correction, status)
    if (.not. status%ok()) return
    ! what each start uses (docs/water.md); a value it does not use is refused
    unused = 'start = '''//trim(start)//''' does not use it (see docs/water.md)'
    select case (trim(start))
    case ('edges')
      call r%refuse_given([character(len=8) :: 'v0', 'height0', 'speed0'], unused, status)
    case ('height')
      call r%refuse_given([character(len=8) :: 'v_left0', 'v_right0', 'speed0'], unused, status)
    case ('speed')
      call r%refuse_given([character(len=8) :: 'v_left0', 'v_right0', 'height0'], unused, status)
    case ('height_speed')
      call r%refuse_given([character(len=9) :: 'v_left0', 'v_right0', 'flow_rate'], unused, status)
    end select
    call r%get('flow_rate', config%flow_rate, status)
    call r%get('u0', config%start%u0, status)
    call r%get('v0', config%start%v0, status)
    call r%get('v_left0', config%start%v_left, status)
    call r%get('v_right0', config%start%v_right, status)
    call r%get('height0', config%start%height, status)
    call r%get('speed0', config%start%speed, status)
    call r%get('beta0', config%start%beta, status)
    call r%get('f1', config%f1, status)
    call r%get('f2', config%f2, status)
    call r%get('f3', config%f3, status)
    call r%get('mass', config%mass, status)
    call r%get('gravity', config%gravity, status)
    call r%get('min_speed', config%min_speed, status)
    call r%get('min_criticality', config%min_criticality, status)
    call r%get_list('stations', config%stations, max_stations, status)
    call r%get('table_step', config%table_step, status)
    call r%get('edges', config%edges, status)
    if (.not. status%ok()) return
    if (start == 'edges' .and. .not. config%start%v_left > config%start%v_right) then
      call r%invalid('v_left0, v_right0', format_real(config%start%v_left)//', '// &
                     format_real(config%start%v_right), 'the left edge must lie at larger v than the right edge', &
                     status)
      return
    end if
    do i = 2, size(config%stations)
      if (.not. config%stations(i) > config%stations(i - 1)) then
        call r%invalid('stations('//format_integer(i)//')', format_real(config%stations(i)), &
                       'stations must increase along the slide', status)
        return
      end if
    end do
    select case (trim(start))
    case ('height'); config%start%mode = START_HEIGHT
    case ('speed'); config%start%mode = START_SPEED
    case ('height_speed'); config%start%mode = START_HEIGHT_SPEED
    case default; config%start%mode = START_EDGES
    end select
    select case (trim(correction))
    case ('no_radius'); config%correction = CORRECTION_NO_RADIUS
    case ('off'); config%correction = CORRECTION_OFF
    case default; config%correction = CORRECTION_FULL
    end select
    call read_inlets(input, config, status)

  end subroutine read_water_config

  !> Every &inlet, in order along the slide (their place on the slide is
  !> checked with the slide: scenarios_water).
  subroutine read_inlets(input, config, status)
    type(input_text_t), intent(in) :: input
    type(water_description_t), intent(inout) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    integer :: k
    if (.not. status%ok()) return
    allocate (config%inlets(group_count(input, 'inlet')))
    do k = 1, size(config%inlets)
      call open_group(input, 'inlet', r, status, occurrence=k)
      call r%get('arc_length', config%inlets(k)%arc_length, status)
      call r%get('flow_rate', config%inlets(k)%flow_rate, status)
      call r%get('speed', config%inlets(k)%speed, status)
      call r%get('beta', config%inlets(k)%beta, status)
      if (.not. status%ok()) return
      if (.not. r%has('arc_length')) then
        call r%invalid('arc_length', 'none', 'every &inlet needs its place: arc_length (m)', status)
      else if (.not. r%has('flow_rate')) then
        call r%invalid('flow_rate', 'none', 'every &inlet needs its flow rate (m^3/s)', status)
      else if (k > 1) then
        if (.not. config%inlets(k)%arc_length >= config%inlets(k - 1)%arc_length) &
          call r%invalid('arc_length', format_real(config%inlets(k)%arc_length), 'the &inlet groups must follow '// &
                         'the slide: at or after the previous one''s '// &
                         format_real(config%inlets(k - 1)%arc_length)//' m', status)
      end if
      if (.not. status%ok()) return
    end do
  end subroutine read_inlets
end module io_water_config
