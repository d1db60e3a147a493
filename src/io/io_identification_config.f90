!> What the two &identify readers share (io_water_identification_config,
!> io_rider_identification_config): the check that something was measured,
!> the cost's weight with its defaults, and the solver's settings. What
!> differs (the places' names, whether a weight needs segments) is an argument.
module io_identification_config
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_least_squares, only: least_squares_options_t
  use io_input, only: group_reader_t
  implicit none (type, external)
  private
  public :: read_identify_weight, read_identify_solver

contains

  !> Refuses an &identify without places (`places_variable`, e.g.
  !> 'station_arc_length'; `places` their word in plural) and segments, and a
  !> weight without segments where `weight_needs_segments`; reads the weight w
  !> of the cost, by default `weight` as given, 0 without segments (positions
  !> only), 1 without places (speeds only).
  subroutine read_identify_weight(r, n_places, n_segments, places_variable, places, weight_needs_segments, &
                                  weight, status)
    type(group_reader_t), intent(inout) :: r
    integer, intent(in) :: n_places, n_segments
    character(len=*), intent(in) :: places_variable, places
    logical, intent(in) :: weight_needs_segments
    real(wp), intent(inout) :: weight
    type(status_t), intent(inout) :: status
    if (n_places + n_segments == 0) then
      call r%invalid(places_variable, 'nothing', 'give '//places//' or segments (or their CSV files)', status)
      return
    end if
    if (weight_needs_segments .and. n_segments == 0 .and. r%has('weight')) then
      call r%invalid('weight', 'given', 'without segments only the positions are fitted (w is 0)', status)
      return
    end if
    if (n_segments == 0) weight = 0
    if (n_places == 0) weight = 1
    call r%get('weight', weight, status)
  end subroutine read_identify_weight

  !> The least-squares solver's ftol and xtol, and the threads of its runs.
  subroutine read_identify_solver(r, solver, threads, status)
    type(group_reader_t), intent(inout) :: r
    type(least_squares_options_t), intent(inout) :: solver
    integer, intent(inout) :: threads
    type(status_t), intent(inout) :: status
    call r%get('ftol', solver%ftol, status)
    call r%get('xtol', solver%xtol, status)
    call r%get('threads', threads, status)
  end subroutine read_identify_solver
end module io_identification_config
