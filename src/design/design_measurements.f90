!> The checks both identifications make of their measurements (identify_water's
!> sections, identify_rider's stations, and the segments of each): something
!> measured, the places strictly in order along the slide, each segment ending
!> after its start. Messages begin with '<who> measurements:'.
module design_measurements
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use base_text, only: format_short, format_integer
  implicit none (type, external)
  private
  public :: check_measured_places

contains

  !> `who` names the measurements ('water'), `place` one of its places
  !> ('section'); places (m) and the segments' starts and ends (m).
  subroutine check_measured_places(who, place, places, segment_start, segment_end, status)
    character(len=*), intent(in) :: who, place
    real(wp), intent(in) :: places(:), segment_start(:), segment_end(:)
    type(status_t), intent(inout) :: status
    integer :: i
    if (size(places) + size(segment_start) == 0) then
      call set_status(status, STATUS_INVALID_INPUT, who//' measurements: no '//place//'s and no segments')
      return
    end if
    do i = 2, size(places)
      if (.not. places(i) > places(i - 1)) then
        call set_status(status, STATUS_INVALID_INPUT, who//' measurements: '//place//' '//format_integer(i)// &
                        ' at '//format_short(places(i))//' m does not lie after the one before it')
        return
      end if
    end do
    do i = 1, size(segment_start)
      if (.not. segment_end(i) > segment_start(i)) then
        call set_status(status, STATUS_INVALID_INPUT, who//' measurements: segment '//format_integer(i)// &
                        ' must end after its start')
        return
      end if
    end do
  end subroutine check_measured_places
end module design_measurements
