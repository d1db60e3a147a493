!> The joined records of a run's phases (contact_closing phases_t): each
!> phase's records, units and outcome appended as they come, the contacts'
!> open state, gaps, points and slips per record, and all of it into the
!> flight at the end.
submodule (contact_closing) contact_closing_phases
  implicit none (type, external)

contains

  !> Appends a phase's records and its outcome.
  module procedure phases_add
    integer :: n1
    if (.not. allocated(self%series%q_names)) then
      self%series = series
      self%q_units = q_units
      self%beta_units = beta_units
    else
      n1 = self%series%n
      self%q_units = united_units(self%series%q_names, self%q_units, series%q_names, q_units)
      self%beta_units = united_units(self%series%beta_names, self%beta_units, series%beta_names, beta_units)
      self%series = join_series(self%series, series)
      ! a phase's start is a switch, an event of the run
      if (self%series%n > n1) self%series%kind(n1 + 1) = RECORD_EVENT
    end if
    if (len(outcome) == 0) return
    if (len(self%history) > 0) self%history = self%history//'; '
    self%history = self%history//outcome
  end procedure phases_add

  !> The contacts of a flight's records: open (closed: a contact carrying
  !> its body among several, contact_bodies), their gaps, points and slips.
  module procedure phases_add_flight
    integer :: n, c
    real(wp), allocatable :: gap(:, :)
    n = flight%series%n
    allocate (gap(size(self%open, 1), n))
    do c = 1, size(gap, 1)
      gap(c, :) = flight%series%monitor(flight%gap_monitors(c), :n)
    end do
    if (n == 0) return
    call self%append(spread(merge(0, 1, flight%gaps%carried), 2, n), gap, flight%gap_point(:, :, :n), &
                     flight%gap_velocity(:, :, :n))
  end procedure phases_add_flight

  !> The contacts of a closed phase's records: the carrying one closed (its
  !> point and slip the model's), the others open (their watched gaps).
  module procedure phases_add_carried
    integer :: n, k
    integer, allocatable :: open(:, :)
    real(wp), allocatable :: point(:, :, :), velocity(:, :, :)
    n = carried%series%n
    if (n == 0) return
    k = carried%gaps%closed
    open = spread(spread(1, 1, size(self%open, 1)), 2, n)
    open(k, :) = 0
    point = carried%gap_point(:, :, :n)
    velocity = carried%gap_velocity(:, :, :n)
    ! the closed model's one contact
    point(:, k, :) = carried%series%contact_r(:, 1, :n)
    velocity(:, k, :) = carried%series%slip(:, 1, :n)
    call self%append(open, carried%gap_value(:, :n), point, velocity)
  end procedure phases_add_carried

  !> Appends the contacts' states of a phase's records.
  module procedure phases_append
    integer :: nc, n
    nc = size(open, 1)
    n = size(self%open, 2) + size(open, 2)
    self%open = reshape([self%open, open], [nc, n])
    self%gap = reshape([self%gap, gap], [nc, n])
    self%point = reshape([self%point, point], [3, nc, n])
    self%velocity = reshape([self%velocity, velocity], [3, nc, n])
  end procedure phases_append

  !> The joined records into the flight: its series (each open contact's
  !> point and slip and every contact's gap from the phases' own; bodies on
  !> the closed contact's frames, whose mechanism reports the run), units,
  !> every contact's points and slips, and outcome.
  module procedure phases_finish
    integer :: c, i, k, j, cs, gm
    associate (s => self%series)
      do c = 1, size(self%open, 1)
        associate (name => flight%system%contacts(c)%name)
          cs = findloc([(trim(s%contact_names(k)) == name, k = 1, s%nc)], .true., dim=1)
          gm = findloc([(trim(s%monitor_names(k)) == name//'.gap', k = 1, s%nm)], .true., dim=1)
        end associate
        do i = 1, s%n
          if (gm > 0) s%monitor(gm, i) = self%gap(c, i)
          if (cs == 0 .or. self%open(c, i) == 0) cycle
          s%contact_r(:, cs, i) = self%point(:, c, i)
          s%slip(:, cs, i) = self%velocity(:, c, i)
        end do
      end do
      if (allocated(flight%closed)) then
        associate (closed => flight%closed%ode%series)
          do k = 1, s%nb
            j = findloc([(closed%body_names(j) == s%body_names(k), j = 1, closed%nb)], .true., dim=1)
            if (j > 0) s%body_frame(k) = closed%body_frame(j)
          end do
        end associate
      end if
    end associate
    call move_alloc(self%q_units, flight%q_units)
    call move_alloc(self%beta_units, flight%beta_units)
    call move_alloc(self%point, flight%gap_point)
    call move_alloc(self%velocity, flight%gap_velocity)
    flight%series = self%series
    flight%outcome = collapse_repeats(self%history)
  end procedure phases_finish

  !> The phases' outcomes ('; '-separated) with each run of sentences that
  !> differ only in their first time ("t = 0.247352 s") written once, with
  !> the run's first and last time and its count: a body landing again and
  !> again on a carried body (ball_on_cart: seven landings) is one sentence,
  !> not one per landing (/contact/impacts has each).
  function collapse_repeats(history) result(text)
    character(len=*), intent(in) :: history
    character(len=:), allocatable :: text
    character(len=*), parameter :: marker = achar(1)
    character(len=:), allocatable :: sentence, key, time, run_key, run_sentence, first, last
    integer :: start, length, repeats
    text = ''
    run_key = ''
    run_sentence = ''
    first = ''
    last = ''
    repeats = 0
    start = 1
    do while (start <= len(history))
      length = index(history(start:), '; ') - 1
      if (length < 0) length = len(history) - start + 1
      sentence = history(start:start + length - 1)
      start = start + length + 2
      call split_time(sentence, key, time)
      if (repeats > 0 .and. len(key) > 0 .and. key == run_key) then
        repeats = repeats + 1
        last = time
        cycle
      end if
      call flush_run()
      run_key = key
      run_sentence = sentence
      first = time
      last = time
      repeats = 1
    end do
    call flush_run()
  contains
    !> key: the sentence with its first "t = <number> s" replaced by the
    !> marker ('' without one); time: that number.
    subroutine split_time(sentence, key, time)
      character(len=*), intent(in) :: sentence
      character(len=:), allocatable, intent(out) :: key, time
      integer :: i, j
      key = ''
      time = ''
      i = index(sentence, 't = ')
      if (i == 0) return
      j = index(sentence(i + 4:), ' ')
      if (j < 2) return
      if (sentence(i + 4 + j - 1:min(len(sentence), i + 4 + j)) /= ' s') return
      time = sentence(i + 4:i + 4 + j - 2)
      key = sentence(:i + 3)//marker//sentence(i + 4 + j + 1:)
    end subroutine split_time

    subroutine flush_run()
      integer :: k
      if (repeats == 0) return
      if (len(text) > 0) text = text//'; '
      if (repeats == 1) then
        text = text//run_sentence
      else
        k = index(run_key, marker)
        text = text//run_key(:k - 1)//first//' .. '//last//' s ('//format_integer(repeats)//' times)'// &
               run_key(k + 1:)
      end if
    end subroutine flush_run
  end function collapse_repeats

  !> The units of join_series's united names: a's, then those of b's names
  !> not in a.
  function united_units(names_a, units_a, names_b, units_b) result(units)
    character(len=*), intent(in) :: names_a(:), names_b(:)
    character(len=*), intent(in) :: units_a(:), units_b(:)
    character(len=8), allocatable :: units(:)
    integer :: k, j
    units = units_a
    do k = 1, size(names_b)
      if (any([(names_a(j) == names_b(k), j = 1, size(names_a))])) cycle
      units = [character(len=8) :: units, units_b(k)]
    end do
  end function united_units
end submodule contact_closing_phases
