!> &sweep: which values vary from ride to ride and how they combine
!> (docs/sweep.md, "Input"). Each swept variable is given as a list
!> (`mass = 50, 70, 90`) or, for numbers, as a range (`mass_range = 50, 90,
!> 5`: first, last, count, evenly spaced, both ends included); the
!> variables are crossed (every combination, the first variable of
!> swept_names varying slowest), except those named in `paired` (or all with
!> combine = 'paired'), which vary together, element by element, as one
!> axis. What is not swept keeps its &rider / &water value.
module io_sweep_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t
  use io_input, only: input_text_t, group_reader_t, open_group, bounds_t, in_range, format_real
  use rider_body, only: SEX_MALE, SEX_FEMALE
  use design_sweep, only: N_SWEPT, swept_names, V_SEX, swept_values_t, sweep_row_count, sweep_rows, &
    range_values
  implicit none (type, external)
  private
  public :: sweep_config_t, read_sweep_config, max_rides, max_values, open_sweep_group, swept_given_name

  !> most rides of one sweep, most values of one list
  integer, parameter :: max_rides = 1000000, max_values = 10000

  type :: sweep_config_t
    real(wp), allocatable :: values(:, :)        !< N_SWEPT x rides
    logical :: swept(N_SWEPT) = .false.          !< given in &sweep
    integer :: threads = 0                       !< 0: OpenMP's default (all cores)
    real(wp) :: progress_seconds = 10            !< s between progress lines (0: none)
    character(len=:), allocatable :: csv_output  !< the CSV summary ('' : the result file's name with .csv)
  end type sweep_config_t

contains

  !> The rides of &sweep; `base` holds every swept variable's value when not
  !> swept (from &rider and &water, heading in degrees, sex 1 or 2).
  subroutine read_sweep_config(input, base, config, status)
    type(input_text_t), intent(in) :: input
    real(wp), intent(in) :: base(N_SWEPT)
    type(sweep_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    character(len=24) :: paired(N_SWEPT), combine
    character(len=1024) :: csv
    type(bounds_t) :: bounds(N_SWEPT)
    type(swept_values_t) :: lists(N_SWEPT)
    logical :: together(N_SWEPT), paired_given(N_SWEPT)
    integer :: k, j, count_together
    real(wp) :: rides

    call open_sweep_group(input, r, status)
    do k = 1, N_SWEPT
      if (k /= V_SEX) call r%bounds(trim(swept_names(k)), bounds(k), status)
    end do
    if (.not. status%ok()) return
    if (.not. r%present) then
      call r%invalid('(group)', '(missing)', 'a sweep needs &sweep with at least one swept variable ('// &
                     list_names()//')', status)
      return
    end if

    ! ---- every list or range
    call read_sex(lists(V_SEX))
    do k = 1, N_SWEPT
      if (k /= V_SEX) call read_numbers(k, lists(k))
      if (.not. status%ok()) return
      config%swept(k) = allocated(lists(k)%x)
      if (.not. config%swept(k)) lists(k)%x = [base(k)]
    end do
    if (.not. any(config%swept)) then
      call r%invalid('(swept variables)', '(none given)', 'give at least one of '//list_names()// &
                     ' (as a list, or as NAME_range = first, last, count)', status)
      return
    end if

    ! ---- how they combine
    combine = 'cross'
    paired = ''
    call r%get('combine', combine, status)
    call r%get_parts('paired', paired, 'at most '//format_integer(N_SWEPT)//' names', status, given=paired_given)
    call r%get('threads', config%threads, status)
    call r%get('progress_seconds', config%progress_seconds, status)
    csv = ''
    call r%get('csv_output', csv, status)
    if (.not. status%ok()) return
    config%csv_output = trim(csv)
    together = .false.
    do k = 1, N_SWEPT
      if (paired_given(k)) then
        j = findloc(swept_names, trim(paired(k)), dim=1)
        if (.not. config%swept(j)) then
          call r%invalid('paired', r%written('paired'), trim(paired(k))//' is not swept: pair only variables '// &
                         'given in &sweep', status)
          return
        end if
        if (together(j)) then
          call r%invalid('paired', r%written('paired'), trim(paired(k))//' is named twice', status)
          return
        end if
        together(j) = .true.
      end if
    end do
    if (combine == 'paired') then
      if (any(paired_given)) then
        call r%invalid('paired', r%written('paired'), 'combine = ''paired'' pairs every swept variable; '// &
                       'name pairs only with combine = ''cross''', status)
        return
      end if
      together = config%swept
    end if
    count_together = count(together)
    if (count_together == 1) then
      call r%invalid('paired', r%written('paired'), 'pairing needs at least two swept variables', status)
      return
    end if
    do k = 1, N_SWEPT
      if (.not. together(k)) cycle
      j = findloc(together, .true., dim=1)
      if (size(lists(k)%x) /= size(lists(j)%x)) then
        call r%invalid(trim(swept_names(k)), r%written(trim(swept_given_name(r, k))), 'paired with '// &
                       trim(swept_names(j))//': it needs as many values ('//format_integer(size(lists(j)%x))// &
                       '), it has '//format_integer(size(lists(k)%x)), status)
        return
      end if
    end do

    ! ---- the rides: one axis per crossed variable, one for the paired ones (design_sweep)
    rides = sweep_row_count(lists, together)
    if (rides > max_rides) then
      call r%invalid('(swept variables)', format_real(rides)//' rides', 'at most '//format_integer(max_rides)// &
                     ' rides in one sweep; split it', status)
      return
    end if
    config%values = sweep_rows(lists, together)

  contains

    subroutine read_sex(list)
      type(swept_values_t), intent(out) :: list
      character(len=8) :: words(max_values)
      logical :: given(max_values)
      integer :: n
      words = ''
      call r%get_parts('sex', words, 'at most '//format_integer(max_values)//' values', status, given=given)
      if (.not. status%ok() .or. .not. any(given)) return
      n = count(given)
      if (any(given(n + 1:))) then
        call r%invalid('sex', r%written('sex'), 'list the values without gaps, from the first', status)
        return
      end if
      list%x = merge(real(SEX_MALE, wp), real(SEX_FEMALE, wp), words(:n) == 'male')
    end subroutine read_sex

    subroutine read_numbers(k, list)
      integer, intent(in) :: k
      type(swept_values_t), intent(out) :: list
      character(len=:), allocatable :: name
      real(wp) :: range(3)
      real(wp), allocatable :: x(:)
      integer :: i
      name = trim(swept_names(k))
      if (r%has(name) .and. r%has(name//'_range')) then
        call r%invalid(name//'_range', r%written(name//'_range'), 'give '//name//' either as a list or as a '// &
                       'range, not both', status)
        return
      end if
      if (r%has(name)) then
        call r%get_list(name, x, max_values, status)
        if (status%ok()) list%x = x
        return
      end if
      if (.not. r%has(name//'_range')) return
      range = 0
      ! Read finite only: first and last have the declaration's bounds, the
      ! count its own (both checked below), no third bound here.
      call r%get(name//'_range', range, in_range(-huge(1.0_wp), huge(1.0_wp), 'first, last: '// &
                 bounds(k)%unit//'; count'), status)
      if (.not. status%ok()) return
      if (.not. (range(3) >= 2 .and. range(3) <= max_values .and. range(3) == aint(range(3)))) then
        call r%invalid(name//'_range', r%written(name//'_range'), 'first, last, count: the count must be a '// &
                       'whole number in [2, '//format_integer(max_values)//']', status)
        return
      end if
      do i = 1, 2
        if (.not. bounds(k)%allows(range(i))) then
          call r%invalid(name//'_range', r%written(name//'_range'), 'first and last: '//bounds(k)%text(), &
                         status)
          return
        end if
      end do
      list%x = range_values(range(1), range(2), nint(range(3)))
    end subroutine read_numbers
  end subroutine read_sweep_config

  pure function list_names() result(text)
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, N_SWEPT
      if (k > 1) text = text//', '
      text = text//trim(swept_names(k))
    end do
  end function list_names

  !> &sweep opened with its declared variables (the swept ones shared with
  !> &rider and &water) and a range of each swept number (mass_range, ...).
  subroutine open_sweep_group(input, r, status)
    type(input_text_t), intent(in) :: input
    type(group_reader_t), intent(out) :: r
    type(status_t), intent(inout) :: status
    character(len=24) :: ranges(N_SWEPT - 1)
    integer :: k, j
    j = 0
    do k = 1, N_SWEPT
      if (k == V_SEX) cycle
      j = j + 1
      ranges(j) = trim(swept_names(k))//'_range'
    end do
    call open_group(input, 'sweep', r, status, also=ranges)
  end subroutine open_sweep_group

  !> The name the user wrote in &sweep for swept variable k (its list or its range).
  function swept_given_name(r, k) result(name)
    type(group_reader_t), intent(in) :: r
    integer, intent(in) :: k
    character(len=:), allocatable :: name
    name = trim(swept_names(k))
    if (k /= V_SEX .and. r%has(name//'_range')) name = name//'_range'
  end function swept_given_name
end module io_sweep_config
