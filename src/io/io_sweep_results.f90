!> A sweep's results: /sweep in the result file (every ride's inputs, status
!> and report figures as arrays over the ride index, with units; the waters
!> under /sweep/water) and the CSV summary, one row per ride (docs/sweep.md,
!> "Outputs").
module io_sweep_results
  use base_kinds, only: wp
  use base_text, only: format_integer, format_real
  use base_status, only: status_t
  use design_ride_evaluation, only: limit_stored_unit, felt_acceleration_units
  use design_sweep, only: sweep_description_t, sweep_result_t, water_groups, N_SWEPT, swept_names, swept_units, &
    swept_descriptions, V_SEX, N_FIGURES, figure_names, figure_unit, figure_descriptions, ride_status_names, &
    V_FLOW_RATE, V_F1, V_F2, V_F3
  use io_hdf5, only: result_file_t
  use io_output_files, only: text_output_t
  implicit none (type, external)
  private
  public :: write_sweep_results, write_sweep_csv, limit_column

contains

  subroutine write_sweep_results(file, sweep, result, threads, ranks, wall_time, status)
    type(result_file_t), intent(inout) :: file
    type(sweep_description_t), intent(in) :: sweep
    type(sweep_result_t), intent(in) :: result
    integer, intent(in) :: threads, ranks
    real(wp), intent(in) :: wall_time
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/sweep/'
    integer, allocatable :: group(:), first(:)
    integer :: k, i, n
    character(len=:), allocatable :: c, unit, messages

    n = result%n
    call file%write_integers(g//'ride', [(i, i=1, n)], '1', 'ride number (the rows of the CSV summary)', status)
    call file%write_integers(g//'status', result%status, '1', &
                             '1 complete (reached the end), 2 stopped before it (stall, lift-off, time bound), '// &
                             '3 failed (could not start, or the integration failed; its figures are 0)', status)
    do k = 1, N_SWEPT
      if (k == V_SEX) then
        call file%write_integers(g//'sex', nint(sweep%values(k, :)), '1', trim(swept_descriptions(k)), status)
      else
        call file%write_vector(g//trim(swept_names(k)), sweep%values(k, :), trim(swept_units(k)), &
                               trim(swept_descriptions(k)), status)
      end if
    end do
    call file%write_integers(g//'water_group', result%water_group, '1', &
                             'the ride''s water: index into /sweep/water', status)
    do k = 1, N_FIGURES
      call file%write_vector(g//trim(figure_names(k)), result%figures(k, :), figure_unit(k, sweep%rider%gravity), &
                             trim(figure_descriptions(k))//' (0 where the ride failed)', status)
    end do
    call file%write_vector(g//'wall_time', result%seconds, 's', 'wall-clock time of the ride and its '// &
                           'evaluation in its thread (the one dataset that differs from run to run)', status)
    messages = ''
    do i = 1, n
      messages = messages//format_integer(i)//': '//trim(ride_status_names(result%status(i)))//': '// &
                 trim(result%message(i))//new_line('a')
    end do
    call file%write_text(g//'messages', messages, 'one line per ride: number, status, how it ended or why '// &
                         'it failed', status)
    do k = 1, size(sweep%limits)
      c = g//'limits/'//limit_column(k, sweep%limits(k)%quantity)//'/'
      unit = limit_stored_unit(sweep%limits(k)%quantity, felt_acceleration_units(sweep%rider%gravity))
      call file%write_text(c//'quantity', sweep%limits(k)%quantity, 'what is limited', status)
      if (sweep%limits(k)%has_minimum) call file%write_scalar(c//'minimum', sweep%limits(k)%minimum, unit, &
                                                              'the lower limit', status)
      if (sweep%limits(k)%has_maximum) call file%write_scalar(c//'maximum', sweep%limits(k)%maximum, unit, &
                                                              'the upper limit', status)
      call file%write_integers(c//'verdict', result%verdict(k, :), '1', &
                               '1 exceeded, 0 ok, -1 not judged (no exit, or the ride failed)', status)
      call file%write_vector(c//'worst', result%worst(k, :), unit, &
                             'the value furthest beyond (or nearest to) a bound', status)
      call file%write_vector(c//'excess', result%excess(k, :), unit, 'by how much it is exceeded (0: not)', &
                             status)
    end do

    call water_groups(sweep%values, group, first)
    call file%write_integers(g//'water/group', [(i, i=1, size(first))], '1', 'water number', status)
    call file%write_vector(g//'water/flow_rate', sweep%values(V_FLOW_RATE, first), 'm^3/s', 'water inflow', status)
    call file%write_vector(g//'water/f1', sweep%values(V_F1, first), 'kg/m', 'water friction f1 (4.7)', status)
    call file%write_vector(g//'water/f2', sweep%values(V_F2, first), 'kg', 'water friction f2 (4.7)', status)
    call file%write_vector(g//'water/f3', sweep%values(V_F3, first), 'kg m', 'water friction f3 (4.7)', status)
    call file%write_vector(g//'water/wall_time', result%water_seconds, 's', 'wall-clock time of the water', status)

    call file%write_count(g//'statistics/rides', n, '1', 'rides in the sweep', status)
    do k = 1, 3
      call file%write_count(g//'statistics/'//trim(ride_status_names(k)), count(result%status == k), '1', &
                            'rides '//trim(ride_status_names(k)), status)
    end do
    call file%write_count(g//'statistics/waters', size(first), '1', 'distinct waters computed', status)
    call file%write_count(g//'statistics/threads', threads, '1', 'OpenMP threads per rank', status)
    call file%write_count(g//'statistics/ranks', ranks, '1', 'MPI ranks', status)
    call file%write_scalar(g//'statistics/wall_time', wall_time, 's', 'wall-clock time of the sweep', status)
    call file%make_scale(g//'water/group', status)
    call file%attach_scale(g//'water/group', g//'water', status)
    call file%make_scale(g//'ride', status)
    call file%attach_scale(g//'ride', '/sweep', status)
  end subroutine write_sweep_results

  !> The column name of limit k (also its group under /sweep/limits).
  pure function limit_column(k, quantity) result(name)
    integer, intent(in) :: k
    character(len=*), intent(in) :: quantity
    character(len=:), allocatable :: name
    name = format_integer(k)//'_'//trim(quantity)
  end function limit_column

  !> One row per ride: number, status, the swept values, the water, every
  !> figure, each limit's verdict, worst and excess, the CPU time and the
  !> message (quoted). Written as every output file is (io_output_files: a
  !> temporary file renamed when complete; a failed write is STATUS_IO).
  subroutine write_sweep_csv(path, sweep, result, status)
    character(len=*), intent(in) :: path
    type(sweep_description_t), intent(in) :: sweep
    type(sweep_result_t), intent(in) :: result
    type(status_t), intent(inout) :: status
    type(text_output_t) :: csv
    integer :: i, k
    character(len=:), allocatable :: line

    if (.not. status%ok()) return
    call csv%create(path, 'the CSV summary', status)
    if (.not. status%ok()) return
    line = 'ride,status'
    do k = 1, N_SWEPT
      line = line//','//trim(swept_names(k))
    end do
    line = line//',water_group'
    do k = 1, N_FIGURES
      line = line//','//trim(figure_names(k))
    end do
    do k = 1, size(sweep%limits)
      associate (c => 'limit_'//limit_column(k, sweep%limits(k)%quantity))
        line = line//','//c//'_verdict,'//c//'_worst,'//c//'_excess'
      end associate
    end do
    line = line//',wall_time,message'
    call csv%write_line(line)
    do i = 1, result%n
      line = format_integer(i)//','//trim(ride_status_names(result%status(i)))
      do k = 1, N_SWEPT
        if (k == V_SEX) then
          line = line//','//trim(merge('male  ', 'female', nint(sweep%values(k, i)) == 1))
        else
          line = line//','//format_real(sweep%values(k, i))
        end if
      end do
      line = line//','//format_integer(result%water_group(i))
      do k = 1, N_FIGURES
        line = line//','//cell(result%figures(k, i))
      end do
      do k = 1, size(sweep%limits)
        select case (result%verdict(k, i))
        case (1); line = line//',exceeded'
        case (0); line = line//',ok'
        case default; line = line//',not judged'
        end select
        line = line//','//cell(result%worst(k, i))//','//cell(result%excess(k, i))
      end do
      line = line//','//format_real(result%seconds(i))//',"'//quoted(trim(result%message(i)))//'"'
      call csv%write_line(line)
    end do
    call csv%finish(status)

  contains

    !> Empty for a failed ride's figures (they were not computed).
    function cell(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      if (result%status(i) == 3) then
        text = ''
      else
        text = format_real(x)
      end if
    end function cell
  end subroutine write_sweep_csv

  pure function quoted(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: k
    out = ''
    do k = 1, len(text)
      if (text(k:k) == '"') then
        out = out//'""'
      else if (text(k:k) == new_line('a')) then
        out = out//' '
      else
        out = out//text(k:k)
      end if
    end do
  end function quoted

end module io_sweep_results
