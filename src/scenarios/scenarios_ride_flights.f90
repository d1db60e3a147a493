!> The flights of a ride (may_fly; rider_flight) in the ride report
!> (stdout and --summary-json) and in the result file's /evaluation
!> (docs/outputs.md, "flight"): airtime (total, the longest and where it
!> took off; the whole rider's apart), the highest point of a contact above
!> the slide and where, and each landing (time, contact, place, normal
!> impact speed, impulse, drop height v_n^2/(2 g), the energy the impact
!> took, whether the contact stayed closed).
module scenarios_ride_flights
  use base_kinds, only: wp
  use base_text, only: format_short, format_integer
  use base_status, only: status_t
  use rider_flight, only: ride_flights_t, highest_drop
  use rider_model, only: contact_names
  use io_hdf5, only: result_file_t
  use io_summary, only: summary_t
  implicit none (type, external)
  private
  public :: add_flights, write_flights

  character(len=*), parameter :: landing_columns(9) = [character(len=14) :: 'time', 'arc_length', &
    'normal_speed', 'impulse', 'normal_impulse', 'drop_height', 'energy_lost', 'closed', 'contact']
  character(len=*), parameter :: landing_units(9) = [character(len=4) :: 's', 'm', 'm/s', 'N s', 'N s', 'm', &
    'J', '1', '1']

contains

  !> The flights into the ride report. `vehicle`: a vehicle's (&sled
  !> may_fly: its contacts by these names).
  subroutine add_flights(summary, flights, vehicle)
    type(summary_t), intent(inout) :: summary
    type(ride_flights_t), intent(in) :: flights
    character(len=*), intent(in), optional :: vehicle(:)
    real(wp) :: drop, drop_at
    integer :: k
    character(len=:), allocatable :: body
    body = 'rider'
    if (present(vehicle)) body = 'vehicle'
    call summary%add_count('flights', 'flights', flights%flights, 'take-offs (any contact)')
    call summary%add('airtime', '  airtime in all', flights%airtime, 's')
    call summary%add('airtime_longest', '  longest flight', flights%longest, 's')
    call summary%add('airtime_longest_arc_length', '  took off at arc length', flights%longest_arc_length, 'm')
    call summary%add_count('whole_flights', '  whole '//body//' in the air', flights%whole_flights, 'times')
    call summary%add('whole_airtime', '    airtime in all', flights%whole_airtime, 's')
    call summary%add('whole_airtime_longest', '    longest', flights%whole_longest, 's')
    call summary%add('whole_airtime_longest_arc_length', '    took off at arc length', &
                     flights%whole_longest_arc_length, 'm')
    call summary%add('highest', '  highest above the slide: '//highest_name(flights, vehicle), flights%highest, 'm')
    call summary%add('highest_arc_length', '    at arc length', flights%highest_arc_length, 'm')
    call highest_drop(flights, drop, drop_at)
    call summary%add_count('landings', '  landings', flights%landings, '')
    call summary%add('drop_height_max', '  largest drop height', drop, 'm')
    call summary%add('drop_height_max_arc_length', '  at arc length', drop_at, 'm')
    do k = 1, flights%landings
      associate (l => flights%landing(k))
        call summary%add_line('  landing '//format_integer(k)//' ('//contact_name(l%contact, vehicle)// &
          ') at arc length '//format_short(l%arc_length)// &
          ' m (t = '//format_short(l%time)//' s): normal speed '//format_short(l%normal_speed)//' m/s, impulse '// &
          format_short(l%impulse)//' N s, drop height '//format_short(l%drop_height)//' m'// &
          trim(merge(', stayed on  ', ', flew on    ', l%closed)))
      end associate
    end do
    if (flights%landings > 0) call summary%add_table('landing', landing_columns, landing_units, landing_table(flights))
  end subroutine add_flights

  !> The flights into /evaluation/flight/ (group `g`, ending in '/');
  !> `vehicle`: a vehicle's (/sled/vehicle/flight/: its contacts by these
  !> names).
  subroutine write_flights(file, flights, g, status, vehicle)
    type(result_file_t), intent(inout) :: file
    type(ride_flights_t), intent(in) :: flights
    character(len=*), intent(in) :: g
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: vehicle(:)
    real(wp) :: drop, drop_at
    real(wp), allocatable :: table(:, :)
    character(len=80) :: meaning(9) = [character(len=80) :: 'time of the landing', &
      'where: the contact''s foot point on the slide (centerline arc length)', &
      'the contact point''s approach speed along the slide''s normal', '|impulse| of the landing at the contact', &
      'its part along the normal', 'normal_speed^2/(2 |g|): the equivalent drop height', &
      'kinetic energy the impact took', '1: the contact stayed closed, 0: it flew on', &
      'the contact that landed: 1 pelvis, 2 heels, 3 back']
    character(len=:), allocatable :: body, took_off, which, located
    integer :: k
    body = 'rider'
    took_off = 'where it took off (pelvis arc length)'
    which = 'which: 1 pelvis, 2 heels, 3 back (0: none)'
    located = 'located on the integrator''s dense output'
    if (present(vehicle)) then
      body = 'vehicle'
      took_off = 'where it took off (the rear contact''s arc length)'
      meaning(9) = 'the contact that landed: 1 '//trim(vehicle(1))//', 2 '//trim(vehicle(2))
      which = 'which: 1 '//trim(vehicle(1))//', 2 '//trim(vehicle(2))//' (0: none)'
      located = 'at the roots of its gap rate and the records'
    end if
    call file%write_count(g//'flights', flights%flights, '1', 'flights: take-offs of a contact while all were '// &
                          'closed', status)
    call file%write_scalar(g//'airtime', flights%airtime, 's', 'time any contact was open (in the air), in all', &
                           status)
    call file%write_scalar(g//'airtime_longest', flights%longest, 's', 'the longest flight', status)
    call file%write_scalar(g//'airtime_longest_arc_length', flights%longest_arc_length, 'm', &
                           took_off, status)
    call file%write_count(g//'whole_flights', flights%whole_flights, '1', 'times the whole '//body//' was in the '// &
                          'air (every contact open)', status)
    call file%write_scalar(g//'whole_airtime', flights%whole_airtime, 's', 'time the whole '//body//' was in the air', &
                           status)
    call file%write_scalar(g//'whole_airtime_longest', flights%whole_longest, 's', 'the longest such flight', status)
    call file%write_scalar(g//'whole_airtime_longest_arc_length', flights%whole_longest_arc_length, 'm', &
                           took_off, status)
    call file%write_scalar(g//'highest', flights%highest, 'm', &
                           'largest gap of a contact point above the slide ('//located//')', status)
    call file%write_count(g//'highest_contact', flights%highest_contact, '1', which, status)
    call file%write_scalar(g//'highest_arc_length', flights%highest_arc_length, 'm', &
                           'where (the contact''s foot point)', status)
    call highest_drop(flights, drop, drop_at)
    call file%write_scalar(g//'drop_height_max', drop, 'm', 'largest drop height of the landings', status)
    call file%write_scalar(g//'drop_height_max_arc_length', drop_at, 'm', 'where', status)
    call file%write_count(g//'landings', flights%landings, '1', 'landings of a contact', status)
    if (flights%landings == 0) return
    table = landing_table(flights)
    do k = 1, size(landing_columns)
      call file%write_vector(g//'landing/'//trim(landing_columns(k)), table(k, :), trim(landing_units(k)), &
                             trim(meaning(k)), status)
    end do
    ! the table's rows by their time
    call file%make_scale(g//'landing/time', status)
    call file%attach_scale(g//'landing/time', g//'landing/', status)
  end subroutine write_flights

  !> Contact k's name: the rider's, or the vehicle's `vehicle` names.
  pure function contact_name(k, vehicle) result(name)
    integer, intent(in) :: k
    character(len=*), intent(in), optional :: vehicle(:)
    character(len=:), allocatable :: name
    if (present(vehicle)) then
      name = trim(vehicle(k))
    else
      name = trim(contact_names(k))
    end if
  end function contact_name

  !> Which contact rose highest ('none' if none).
  pure function highest_name(flights, vehicle) result(name)
    type(ride_flights_t), intent(in) :: flights
    character(len=*), intent(in), optional :: vehicle(:)
    character(len=:), allocatable :: name
    name = 'none'
    if (flights%highest_contact > 0) name = contact_name(flights%highest_contact, vehicle)
  end function highest_name

  !> The landings as a table (column, landing).
  pure function landing_table(flights) result(table)
    type(ride_flights_t), intent(in) :: flights
    real(wp), allocatable :: table(:, :)
    integer :: k
    allocate (table(size(landing_columns), flights%landings))
    do k = 1, flights%landings
      associate (l => flights%landing(k))
        table(:, k) = [l%time, l%arc_length, l%normal_speed, l%impulse, l%normal_impulse, l%drop_height, &
                       l%energy_lost, merge(1.0_wp, 0.0_wp, l%closed), real(l%contact, wp)]
      end associate
    end do
  end function landing_table
end module scenarios_ride_flights
