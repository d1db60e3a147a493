!> The heels' flights of a ride (may_fly; rider_heels_flight) in the ride
!> report (stdout and --summary-json) and in the result file's /evaluation
!> (docs/outputs.md, "flight"): airtime (total, the longest and where it
!> took off), the heels' highest point above the slide and where, and each
!> landing (time, place, normal impact speed, impulse, drop height
!> v_n^2/(2 g), the energy the impact took, whether the heels stayed on).
module scenarios_ride_flights
  use base_kinds, only: wp
  use base_text, only: format_short, format_integer
  use base_status, only: status_t
  use rider_heels_flight, only: ride_flights_t, highest_drop
  use io_hdf5, only: result_file_t
  use io_summary, only: summary_t
  implicit none (type, external)
  private
  public :: add_flights, write_flights

  character(len=*), parameter :: landing_columns(8) = [character(len=14) :: 'time', 'arc_length', &
    'normal_speed', 'impulse', 'normal_impulse', 'drop_height', 'energy_lost', 'closed']
  character(len=*), parameter :: landing_units(8) = [character(len=4) :: 's', 'm', 'm/s', 'N s', 'N s', 'm', &
    'J', '1']

contains

  !> The flights into the ride report.
  subroutine add_flights(summary, flights)
    type(summary_t), intent(inout) :: summary
    type(ride_flights_t), intent(in) :: flights
    real(wp) :: drop, drop_at
    integer :: k
    call summary%add_count('flights', 'heels'' flights', flights%flights, 'take-offs')
    call summary%add('airtime', '  airtime in all', flights%airtime, 's')
    call summary%add('airtime_longest', '  longest flight', flights%longest, 's')
    call summary%add('airtime_longest_arc_length', '  took off at arc length', flights%longest_arc_length, 'm')
    call summary%add('heels_highest', '  heels highest above the slide', flights%highest, 'm')
    call summary%add('heels_highest_arc_length', '  at arc length', flights%highest_arc_length, 'm')
    call highest_drop(flights, drop, drop_at)
    call summary%add_count('landings', '  landings', flights%landings, '')
    call summary%add('drop_height_max', '  largest drop height', drop, 'm')
    call summary%add('drop_height_max_arc_length', '  at arc length', drop_at, 'm')
    do k = 1, flights%landings
      associate (l => flights%landing(k))
        call summary%add_line('  landing '//format_integer(k)//' at arc length '//format_short(l%arc_length)// &
          ' m (t = '//format_short(l%time)//' s): normal speed '//format_short(l%normal_speed)//' m/s, impulse '// &
          format_short(l%impulse)//' N s, drop height '//format_short(l%drop_height)//' m'// &
          trim(merge(', stayed on  ', ', flew on    ', l%closed)))
      end associate
    end do
    if (flights%landings > 0) call summary%add_table('landing', landing_columns, landing_units, landing_table(flights))
  end subroutine add_flights

  !> The flights into /evaluation/flight/ (group `g`, ending in '/').
  subroutine write_flights(file, flights, g, status)
    type(result_file_t), intent(inout) :: file
    type(ride_flights_t), intent(in) :: flights
    character(len=*), intent(in) :: g
    type(status_t), intent(inout) :: status
    real(wp) :: drop, drop_at
    real(wp), allocatable :: table(:, :)
    character(len=*), parameter :: meaning(8) = [character(len=80) :: 'time of the landing', &
      'where: the heels'' foot point on the slide (centerline arc length)', &
      'the heel''s approach speed along the slide''s normal', '|impulse| of the landing on the heels', &
      'its part along the normal', 'normal_speed^2/(2 |g|): the equivalent drop height', &
      'kinetic energy the impact took', '1: the heels stayed on the slide, 0: they flew on']
    integer :: k
    call file%write_count(g//'flights', flights%flights, '1', 'take-offs of the heels (from the slide, rebounds)', &
                          status)
    call file%write_scalar(g//'airtime', flights%airtime, 's', 'time the heels were in the air, in all', status)
    call file%write_scalar(g//'airtime_longest', flights%longest, 's', 'the longest flight', status)
    call file%write_scalar(g//'airtime_longest_arc_length', flights%longest_arc_length, 'm', &
                           'where it took off (pelvis arc length)', status)
    call file%write_scalar(g//'heels_highest', flights%highest, 'm', &
                           'largest gap of the heels above the slide (at the records)', status)
    call file%write_scalar(g//'heels_highest_arc_length', flights%highest_arc_length, 'm', &
                           'where (the heels'' foot point)', status)
    call highest_drop(flights, drop, drop_at)
    call file%write_scalar(g//'drop_height_max', drop, 'm', 'largest drop height of the landings', status)
    call file%write_scalar(g//'drop_height_max_arc_length', drop_at, 'm', 'where', status)
    call file%write_count(g//'landings', flights%landings, '1', 'landings of the heels', status)
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

  !> The landings as a table (column, landing).
  pure function landing_table(flights) result(table)
    type(ride_flights_t), intent(in) :: flights
    real(wp), allocatable :: table(:, :)
    integer :: k
    allocate (table(size(landing_columns), flights%landings))
    do k = 1, flights%landings
      associate (l => flights%landing(k))
        table(:, k) = [l%time, l%arc_length, l%normal_speed, l%impulse, l%normal_impulse, l%drop_height, &
                       l%energy_lost, merge(1.0_wp, 0.0_wp, l%closed)]
      end associate
    end do
  end function landing_table
end module scenarios_ride_flights
