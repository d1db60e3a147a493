!> Scenario `sweep`: a population of rides (docs/sweep.md). The input is a
!> ride input (&surface, &water, &rider, &solver, &water_solver) plus
!> &sweep, which names the values that vary; every ride runs through the
!> library (design_sweep) in OpenMP threads and, under an MPI launcher
!> (`mpirun -n N slidesim sweep.nml`), across ranks, rank 0 gathering and
!> writing. One result file (/sweep) and a CSV summary with a row per ride.
!> A ride that fails is reported and the others run on: the sweep ends with
!> exit status 0 when every ride was tried and the files were written, the
!> failed rides counted in the summary and the file (/sweep rides_failed);
!> when every ride failed the file is incomplete (exit status 2). Asked to
!> fail on a limit, a sweep with any ride over one ends with exit status 4.
module scenarios_sweep
  use base_kinds, only: wp, int64
  use base_text, only: format_integer
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT, STATUS_SOLVER
  use base_log, only: log_info
  use rider_ride, only: ride_options_t
  use water_run, only: water_description_t
  use design_sweep, only: sweep_description_t, sweep_result_t, run_sweep, rides_of_rank, water_groups, &
    ride_description, N_SWEPT, V_SEX, V_MASS, V_HEIGHT, V_MU, V_U0, V_V0, V_HEADING, V_SPEED, V_FLOW_RATE, &
    V_F1, V_F2, V_F3, F_FELT_MAGNITUDE_MAX, RIDE_COMPLETE, RIDE_STOPPED, RIDE_FAILED, ride_status_names
  use design_sweep_ranks, only: start_ranks, gather_rides, finish_ranks
  use io_input, only: input_text_t, check_known_groups, format_real, group_reader_t, open_group, &
                      where_given
  use io_output_files, only: claim_output
  use io_run_config, only: run_config_t
  use io_solver_config, only: solver_config_t
  use io_rider_config, only: require_coulomb_rider, open_rider_group
  use rider_model, only: rider_coulomb_mu
  use io_sweep_config, only: sweep_config_t, read_sweep_config
  use io_sweep_results, only: write_sweep_results, write_sweep_csv
  use io_hdf5, only: result_file_t
  use io_summary, only: summary_t
  use water_run, only: new_streamline
  use water_streamline, only: streamline_t
  use scenarios_water, only: write_slide_grid
  use io_xdmf, only: xdmf_t
  use scenarios_ride, only: ride_groups, check_sphere_radii, read_limit_gate, limits_exceeded_status, &
    read_water_and_rider, set_ride_duration
  use design_ride_evaluation, only: quantities_without_limit, felt_acceleration_units
  use scenarios_report, only: close_report
  implicit none (type, external)
  private
  public :: run_sweep_scenario

contains

  subroutine run_sweep_scenario(input, run, status)
    type(input_text_t), intent(in) :: input
    type(run_config_t), intent(in) :: run
    type(status_t), intent(inout) :: status
    type(solver_config_t) :: solver, defaults
    type(sweep_config_t) :: config
    type(sweep_description_t) :: sweep
    type(sweep_result_t) :: result
    type(ride_options_t) :: options
    type(result_file_t) :: file
    type(status_t) :: write_status, run_status
    real(wp) :: base(N_SWEPT), wall
    integer :: rank, ranks, threads, failed, k
    integer(int64) :: clock0, clock1, rate
    logical :: started, complete, fail_on_limit, kept, coulomb
    character(len=:), allocatable :: csv_path, message, where

    ! ---- everything checked before any work
    call check_known_groups(input, [character(len=len(ride_groups)) :: ride_groups, 'sweep'], status)
    defaults%options = options%ode
    defaults%output_step = options%output_step
    ! a sweep rides at 'report' unless the input gives accuracy or a tolerance
    ! (the shipped sweep's reported numbers measured there: docs/accuracy.md)
    defaults%accuracy = 'report'
    call read_water_and_rider(input, defaults, .true., solver, sweep%water, sweep%rider, options, sweep%limits, status)
    if (status%ok()) call require_coulomb_rider(input, sweep%rider, .true., 'the sweep varies and records '// &
                                                'the rider''s Coulomb mu (0: none)', status)
    if (status%ok()) call read_limit_gate(input, run, sweep%limits, fail_on_limit, status)
    if (.not. status%ok()) return
    call check_sphere_radii(input, sweep%rider, sweep%water%slide, status)
    if (.not. status%ok()) return
    associate (p => sweep%rider, w => sweep%water)
      base = 0
      base(V_SEX) = p%body%sex
      base(V_MASS) = p%body%mass
      base(V_HEIGHT) = p%body%height
      call rider_coulomb_mu(p, base(V_MU), coulomb)
      base(V_U0) = p%u0
      base(V_V0) = p%v0
      base(V_HEADING) = heading_degrees(input)
      base(V_SPEED) = p%speed0
      base(V_FLOW_RATE) = w%flow_rate
      base(V_F1) = w%f1
      base(V_F2) = w%f2
      base(V_F3) = w%f3
    end associate
    call read_sweep_config(input, base, config, status)
    if (.not. status%ok()) return
    options%progress_seconds = 0   ! the sweep reports progress, not each ride
    call set_ride_duration(input, solver, sweep%water%slide%length(), options, status)
    if (.not. status%ok()) return
    sweep%options = options
    sweep%values = config%values
    call check_waters(input, sweep, status)
    if (.not. status%ok()) return
    csv_path = config%csv_output
    if (len(csv_path) == 0) then
      csv_path = csv_name(trim(run%output))
      where = input%name//': &sweep: csv_output not given: "'//csv_path//'", the result file''s name with .csv'
    else
      where = where_given(input, 'sweep', 'csv_output')//': &sweep: csv_output = '''//csv_path//''''
    end if
    call claim_output(csv_path, where, 'the CSV summary', status)
    if (.not. status%ok() .or. run%check_only) return

    ! ---- the rides: this rank's share in threads, then rank 0 gathers
    call start_ranks(rank, ranks, started)
    call system_clock(clock0, rate)
    if (rank == 0) call log_info('sweep: '//format_integer(size(sweep%values, 2))//' rides, '// &
                                 format_integer(count_waters(sweep))//' waters, '//format_integer(ranks)// &
                                 ' rank(s)')
    threads = config%threads
    call run_sweep(sweep, rides_of_rank(size(sweep%values, 2), rank, ranks), threads, result, &
                   merge(config%progress_seconds, 0.0_wp, rank == 0), ranks, log_info)
    call gather_rides(result, rank, ranks)
    call finish_ranks(started)
    if (rank /= 0) return
    call system_clock(clock1)
    wall = real(clock1 - clock0, wp)/rate
    if (threads <= 0) threads = omp_threads()

    ! ---- rank 0 writes
    call file%create(trim(run%output), status)
    if (.not. status%ok()) return
    call file%write_provenance('sweep', trim(run%title), input%name, input%text(), write_status)
    call write_sweep_results(file, sweep, result, max(1, threads), ranks, wall, write_status)
    call write_slide_grid(file, sweep%water%slide, write_status)
    failed = count(result%status == RIDE_FAILED)
    call file%set_attribute('/sweep', 'rides_failed', failed, write_status)
    message = 'ok: '//format_integer(result%n)//' rides, '//format_integer(failed)//' failed'
    if (failed == result%n) call set_status(run_status, STATUS_SOLVER, 'sweep: every ride failed ('// &
                                            format_integer(failed)//' of '//format_integer(result%n)// &
                                            '; ride 1: '//trim(result%message(1))//'; every ride''s message: '// &
                                            '/sweep/messages and the CSV summary)')
    if (.not. run_status%ok()) message = run_status%text()
    if (.not. write_status%ok()) message = write_status%text()
    if (write_status%ok()) call write_xdmf(file, write_status)
    complete = write_status%ok() .and. run_status%ok()
    call file%finish(complete, message, write_status)
    kept = write_status%ok()
    if (kept) then
      call write_sweep_csv(csv_path, sweep, result, write_status)
      if (.not. write_status%ok()) then
        write_status%message = write_status%text()//' (the result file "'//file%final_path()//'" is '// &
                               trim(merge('complete           ', 'kept, incomplete   ', complete))//')'
        csv_path = 'none: "'//csv_path//'" could not be written'
      end if
    end if
    call print_summary(sweep, result, wall, ranks, max(1, threads), file%final_path(), csv_path, run, &
                       complete .and. kept, kept, message, write_status)
    if (.not. write_status%ok()) then
      status = write_status
    else if (.not. run_status%ok()) then
      status = run_status
    else if (fail_on_limit) then
      call limits_exceeded_status(input%name, sweep%limits, [(count(result%verdict(k, :) == 1), &
                                  k = 1, size(sweep%limits))], .true., status)
    end if
  end subroutine run_sweep_scenario

  !> &rider heading0_deg as written (default 0): the rides convert degrees
  !> as the ride does, so a ride of the sweep is the ride of the same input.
  real(wp) function heading_degrees(input) result(degrees)
    type(input_text_t), intent(in) :: input
    type(group_reader_t) :: r
    type(status_t) :: status
    degrees = 0
    call open_rider_group(input, r, status)   ! read_rider_config checked it
    call r%get('heading0_deg', degrees, status)
  end function heading_degrees

  !> XDMF next to the result: the slide the population rode.
  subroutine write_xdmf(file, status)
    type(result_file_t), intent(inout) :: file
    type(status_t), intent(inout) :: status
    type(xdmf_t) :: xdmf
    call xdmf%start()
    call xdmf%surface(file, 'slide surface', '/geometry/surface')
    call xdmf%attach(file, status)
  end subroutine write_xdmf

  !> OpenMP's default number of threads (what threads = 0 runs with).
  integer function omp_threads()
    !$ use omp_lib, only: omp_get_max_threads
    omp_threads = 1
    !$ omp_threads = omp_get_max_threads()
  end function omp_threads

  !> The CSV beside the result: its name with .csv in place of .h5.
  pure function csv_name(output) result(path)
    character(len=*), intent(in) :: output
    character(len=:), allocatable :: path
    integer :: dot
    dot = index(output, '.', back=.true.)
    if (dot > index(output, '/', back=.true.) + 1) then
      path = output(:dot - 1)//'.csv'
    else
      path = output//'.csv'
    end if
  end function csv_name

  integer function count_waters(sweep)
    type(sweep_description_t), intent(in) :: sweep
    integer, allocatable :: group(:), first(:)
    call water_groups(sweep%values, group, first)
    count_waters = size(first)
  end function count_waters

  !> Every distinct water is a valid description (its start lies on the
  !> slide, ...): a bad flow rate is bad input, not a failed ride.
  subroutine check_waters(input, sweep, status)
    type(input_text_t), intent(in) :: input
    type(sweep_description_t), intent(in) :: sweep
    type(status_t), intent(inout) :: status
    integer, allocatable :: group(:), first(:)
    type(water_description_t) :: water
    type(streamline_t) :: model
    type(sweep_description_t) :: one
    real(wp) :: y0(7)
    integer :: g
    call water_groups(sweep%values, group, first)
    do g = 1, size(first)
      call ride_description(sweep, first(g), one%rider, water)
      call new_streamline(water, model, y0, status)
      if (.not. status%ok()) then
        call prefix_status(status, input%name//': &sweep: the water of ride '//format_integer(first(g))// &
                           ' (flow_rate '//format_real(water%flow_rate)//' m^3/s)')
        status%code = STATUS_INVALID_INPUT
        return
      end if
    end do
  end subroutine check_waters

  !> The sweep in a few lines (stdout) and, with --summary-json, as JSON.
  subroutine print_summary(sweep, result, wall, ranks, threads, path, csv_path, run, complete, csv_tried, &
                           message, status)
    type(sweep_description_t), intent(in) :: sweep
    type(sweep_result_t), intent(in) :: result
    real(wp), intent(in) :: wall
    integer, intent(in) :: ranks, threads
    character(len=*), intent(in) :: path, csv_path, message
    type(run_config_t), intent(in) :: run
    ! the file complete; the CSV tried (the result file kept, also when every ride failed): its
    ! line names it, or says it could not be written
    logical, intent(in) :: complete, csv_tried
    type(status_t), intent(inout) :: status
    type(summary_t) :: summary
    integer :: i, worst, shown
    logical, allocatable :: ran(:)
    character(len=:), allocatable :: unset
    call summary%start('sweep', 'slidesim sweep')
    call summary%add_count('rides', 'rides', result%n, '')
    call summary%add_count('complete', '  reached the end', count(result%status == RIDE_COMPLETE), '')
    call summary%add_count('stopped', '  stopped before it', count(result%status == RIDE_STOPPED), &
                           '(stall, lift-off, time bound)')
    call summary%add_count('failed', '  failed', count(result%status == RIDE_FAILED), '')
    call summary%add_count('waters', 'waters computed', count_waters(sweep), '')
    ran = result%status == RIDE_COMPLETE .or. result%status == RIDE_STOPPED
    if (any(ran)) then
      worst = maxloc(result%figures(F_FELT_MAGNITUDE_MAX, :), dim=1, mask=ran)
      call summary%add('felt_magnitude_max', 'highest felt acceleration', result%figures(F_FELT_MAGNITUDE_MAX, &
                       worst), felt_acceleration_units(sweep%rider%gravity), 'g')
      call summary%add_count('felt_magnitude_max_ride', '  in ride', worst, '')
    end if
    call summary%add_count('rides_over_limit', 'rides over a limit', count(any(result%verdict == 1, dim=1)), &
                           'of the '//format_integer(count(ran))//' that ran, '//format_integer(size(sweep%limits))// &
                           ' limits set')
    unset = quantities_without_limit(sweep%limits)
    if (len(unset) > 0) call summary%add_text('limits_not_set', 'no limit set for', unset)
    shown = 0
    do i = 1, result%n
      if (result%status(i) /= RIDE_FAILED) cycle
      shown = shown + 1
      if (shown > 5) then
        call summary%add_line('  ... (every ride''s message: the CSV summary)')
        exit
      end if
      call summary%add_line('  ride '//format_integer(i)//' '//trim(ride_status_names(RIDE_FAILED))//': '// &
                            trim(result%message(i)))
    end do
    call summary%add('wall_time', 'wall-clock time', wall, 's')
    call summary%add('rides_per_second', 'rides per second', result%n/max(wall, 1e-9_wp), '1/s')
    if (any(ran)) call summary%add('ride_wall_time_mean', 'mean time per ride', sum(result%seconds, mask=ran)/ &
                                   count(ran), 's')
    call summary%add_count('threads', 'threads per rank', threads, '')
    call summary%add_count('ranks', 'MPI ranks', ranks, '')
    if (csv_tried) call summary%add_text('csv', 'CSV summary', csv_path)
    call close_report(summary, run, path, complete, message, status)
  end subroutine print_summary
end module scenarios_sweep
