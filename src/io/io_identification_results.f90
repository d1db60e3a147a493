!> The segments of an identification's result group (identify_water,
!> identify_rider): each measured segment's start and end, the measured and
!> the simulated speed and their difference, the start the segments' scale.
module io_identification_results
  use base_kinds, only: wp
  use base_status, only: status_t
  use io_hdf5, only: result_file_t
  implicit none (type, external)
  private
  public :: write_identification_segments

contains

  !> `group` ends in '/'; the two notes describe the measured and the
  !> simulated speed in the dataset attributes.
  subroutine write_identification_segments(file, group, start, finish, measured, simulated, error, measured_note, &
                                           simulated_note, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: group, measured_note, simulated_note
    real(wp), intent(in) :: start(:), finish(:), measured(:), simulated(:), error(:)
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: s = 'segments/'
    call file%write_vector(group//s//'start', start, 'm', 'arc length where each segment starts; dimension scale', &
                           status)
    call file%write_vector(group//s//'end', finish, 'm', 'arc length where it ends', status)
    call file%write_vector(group//s//'measured_speed', measured, 'm/s', measured_note, status)
    call file%write_vector(group//s//'simulated_speed', simulated, 'm/s', simulated_note, status)
    call file%write_vector(group//s//'error', error, 'm/s', 'simulated - measured', status)
    call file%make_scale(group//s//'start', status)
    call file%attach_scale(group//s//'start', group//s, status)
  end subroutine write_identification_segments
end module io_identification_results
