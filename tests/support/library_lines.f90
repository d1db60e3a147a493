!> The lines the library programs of tests/library print (library_without_io,
!> library_optimize, library_vehicle, shipped_descriptions), one number a
!> line, `<input> <key> <value>`, for their wrappers to compare with the
!> command's summary of the same input (library_without_io.sh,
!> compare_shipped.py); a value exactly (format_real: the fewest digits that
!> read back as it), a text `TEXT <input> <key> <words>` (the summary's
!> words, or with key `line` a line of its printed summary). A step that
!> fails prints `FAIL <what>: <why>` and counts in `failures`, which the
!> program ends on, or stops the program at once (stop_unless_ok). A run's
!> flights and landings are printed one way for every program (put_flights).
module library_lines
  use base_kinds, only: wp
  use base_text, only: format_real, format_integer
  use base_status, only: status_t
  use rider_flight, only: ride_flights_t, highest_drop
  implicit none (type, external)
  private
  public :: put, put_count, put_text, put_flights, expect_ok, stop_unless_ok, failures

  integer :: failures = 0   !< the steps that failed (expect_ok)

contains

  !> The number x under `key` of input `input`.
  subroutine put(input, key, x)
    character(len=*), intent(in) :: input, key
    real(wp), intent(in) :: x
    print '(a)', input//' '//key//' '//format_real(x)
  end subroutine put

  !> The count n under `key` of input `input`.
  subroutine put_count(input, key, n)
    character(len=*), intent(in) :: input, key
    integer, intent(in) :: n
    print '(a)', input//' '//key//' '//format_integer(n)
  end subroutine put_count

  !> The words under `key` of input `input`.
  subroutine put_text(input, key, words)
    character(len=*), intent(in) :: input, key, words
    print '(a)', 'TEXT '//input//' '//key//' '//words
  end subroutine put_text

  !> The flights of a run that may fly as its summary gives them
  !> (scenarios_ride_flights' add_flights): the highest point with
  !> `highest` (a rider's ride; a vehicle's summary has none).
  subroutine put_flights(input, f, highest)
    character(len=*), intent(in) :: input
    type(ride_flights_t), intent(in) :: f
    logical, intent(in) :: highest
    real(wp) :: drop, drop_at
    character(len=:), allocatable :: row
    integer :: k
    call put_count(input, 'flights', f%flights)
    call put(input, 'airtime', f%airtime)
    call put(input, 'airtime_longest', f%longest)
    call put(input, 'airtime_longest_arc_length', f%longest_arc_length)
    call put_count(input, 'whole_flights', f%whole_flights)
    call put(input, 'whole_airtime', f%whole_airtime)
    call put(input, 'whole_airtime_longest', f%whole_longest)
    call put(input, 'whole_airtime_longest_arc_length', f%whole_longest_arc_length)
    if (highest) then
      call put(input, 'highest', f%highest)
      call put(input, 'highest_arc_length', f%highest_arc_length)
    end if
    call highest_drop(f, drop, drop_at)
    call put_count(input, 'landings', f%landings)
    call put(input, 'drop_height_max', drop)
    call put(input, 'drop_height_max_arc_length', drop_at)
    do k = 1, f%landings
      row = 'landing.'//format_integer(k)//'.'
      associate (l => f%landing(k))
        call put(input, row//'time', l%time)
        call put(input, row//'arc_length', l%arc_length)
        call put(input, row//'normal_speed', l%normal_speed)
        call put(input, row//'impulse', l%impulse)
        call put(input, row//'normal_impulse', l%normal_impulse)
        call put(input, row//'drop_height', l%drop_height)
        call put(input, row//'energy_lost', l%energy_lost)
        call put(input, row//'closed', merge(1.0_wp, 0.0_wp, l%closed))
        call put_count(input, row//'contact', l%contact)
      end associate
    end do
  end subroutine put_flights

  !> A step's status: a failure is printed, naming `what`, and counted.
  subroutine expect_ok(status, what)
    type(status_t), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status%ok()) return
    print '(a)', 'FAIL '//what//': '//status%text()
    failures = failures + 1
  end subroutine expect_ok

  !> A step's status: a failure is printed, naming the input and `what`,
  !> and ends the program (status 1).
  subroutine stop_unless_ok(input, what, status)
    character(len=*), intent(in) :: input, what
    type(status_t), intent(in) :: status
    if (status%ok()) return
    print '(a)', 'FAIL '//input//': '//what//': '//status%text()
    error stop 1
  end subroutine stop_unless_ok
end module library_lines
