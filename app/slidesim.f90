!> The slidesim command: runs the scenario named in a namelist file (or
!> standard input, or the built-in default) and turns the outcome into a
!> message and an exit status: 0 done; 1 bad command line or input (nothing
!> written); 2 the run failed part way (the result file is kept, marked
!> incomplete); 3 a file could not be read or written (standard output too:
!> a summary cut short by a closed pipe, `slidesim | head`, is exit status 3,
!> the result file complete and kept), or an output path names a device, a
!> FIFO or a socket, which is never replaced (refused before any work; one
!> that appears during the run leaves the results in the temporary file);
!> 4 done, the results complete, but a ride exceeded a limit and the run
!> was asked to fail on that (--fail-on-limit, &evaluation fail_on_limit).
!>
!> Options take their value as the next argument or after '=' (--output FILE,
!> --output=FILE); '-' names standard input; '--' ends the options.
program slidesim
  use base_status, only: status_t, STATUS_OK, STATUS_INVALID_INPUT, STATUS_IO, STATUS_LIMITS_EXCEEDED
  use base_log, only: log_error, log_warning, set_verbosity, set_progress_interval
  use base_kinds, only: wp
  use scenarios_registry, only: run_input_file, run_default, print_scenarios, slidesim_version, &
                                default_input, scenario_template, scenario_names
  use io_run_config, only: run_config_t
  use io_system, only: ignore_file_size_signal, guard_standard_streams, write_standard_output, &
                       standard_output_lost, standard_input_closed
  use io_namelist, only: nml_value_t, read_real_token, NUMBER_OK
  use io_input_declarations, only: input_reference
  use io_provenance, only: set_build_commit
  use app_build_commit, only: slidesim_git_commit
  implicit none (type, external)

  type(status_t) :: status
  type(run_config_t) :: cli
  character(len=:), allocatable :: arg, option, value, input_path, template
  character(len=:), allocatable :: overrides(:)
  integer :: i, n, equals
  logical :: options_ended, has_value, found

  ! the result files' git_commit (stamped into the program alone: app/CMakeLists.txt)
  call set_build_commit(slidesim_git_commit())
  ! a write beyond the file-size limit then fails and is reported (exit 3)
  call ignore_file_size_signal()
  ! a closed pipe or stream on standard output is reported (exit 3), not a kill part way
  call guard_standard_streams()
  cli%output = ''
  cli%summary_json = ''
  cli%export_stl = ''
  cli%export_obj = ''
  cli%ride_csv = ''
  allocate (character(len=1) :: overrides(0))
  options_ended = .false.
  call set_verbosity(1)   ! the command's stage and progress lines (base_log is quiet until asked)
  n = command_argument_count()
  i = 0
  do while (i < n)
    i = i + 1
    arg = argument(i)
    if (options_ended .or. arg == '-' .or. len(arg) == 0 .or. arg(1:1) /= '-') then
      if (allocated(input_path)) call usage_error('only one input file can be given ("'//input_path// &
                                                  '" and "'//arg//'")')
      input_path = arg
      cycle
    end if
    ! --option=value or --option value
    equals = index(arg, '=')
    has_value = equals > 0 .and. arg(1:2) == '--'
    if (has_value) then
      option = arg(:equals - 1)
      value = arg(equals + 1:)
    else
      option = arg
    end if
    select case (option)
    case ('--')
      options_ended = .true.
    case ('-h', '--help')
      call no_value()
      call print_help()
      call end_with_output_checked()
    case ('-V', '--version')
      call no_value()
      call write_standard_output('slidesim '//slidesim_version//' (git '//slidesim_git_commit()//')')
      call end_with_output_checked()
    case ('-q', '--quiet')
      call no_value()
      call set_verbosity(0)
    case ('-o', '--output')
      call take_value()
      if (len(value) == 0) call usage_error(option//' needs a file name')
      cli%output = value
    case ('--set')
      call take_value()
      if (index(value, '%') == 0 .or. index(value, '=') == 0) &
        call usage_error('--set '//value//': write --set group%variable=value, e.g. --set solver%rtol=1e-8')
      overrides = [character(len=max(len(overrides), len(value))) :: overrides, value]
    case ('--unset')
      ! kept in order with the --set arguments, marked (a --set group%... never starts so)
      call take_value()
      if (index(value, '%') == 0) call usage_error('--unset '//value//': write --unset group%variable, '// &
                                                    'e.g. --unset solver%duration')
      overrides = [character(len=max(len(overrides), len(value) + 8)) :: overrides, '--unset '//value]
    case ('--progress')
      call take_value()
      call set_progress_interval(seconds(value))
    case ('--check')
      call no_value()
      cli%check_only = .true.
    case ('--fail-on-limit')
      call no_value()
      cli%fail_on_limit = .true.
    case ('--summary-json')
      call take_value()
      if (len(value) == 0) call usage_error(option//' needs a file name')
      cli%summary_json = value
    case ('--export-stl', '--export-obj')
      call take_value()
      if (len(value) == 0) call usage_error(option//' needs a file name')
      if (option == '--export-stl') cli%export_stl = value
      if (option == '--export-obj') cli%export_obj = value
    case ('--ride-csv')
      call take_value()
      if (len(value) == 0) call usage_error(option//' needs a file name')
      cli%ride_csv = value
    case ('--default-input')
      ! an optional scenario name: --default-input water, --default-input=water
      if (.not. has_value .and. i < n) then
        value = argument(i + 1)
        if (value(1:min(1, len(value))) /= '-') then
          i = i + 1
          has_value = .true.
        end if
      end if
      if (has_value) then
        call scenario_template(value, template, found)
        if (.not. found) call usage_error('--default-input '//value//': no such scenario; scenarios:'// &
                                          scenario_list())
        call write_standard_output(template)
      else
        call write_standard_output(default_input())
      end if
      call end_with_output_checked()
    case ('--input-reference')
      call no_value()
      call write_standard_output(input_reference())
      call end_with_output_checked()
    case default
      call usage_error('unknown option "'//arg//'"')
    end select
  end do

  if (allocated(input_path)) then
    ! a closed standard input reads as /dev/null (guard_standard_streams): not an empty input
    if ((input_path == '-' .or. input_path == '/dev/stdin') .and. standard_input_closed()) then
      call log_error('cannot read the input from standard input ("'//input_path//'"): standard input is '// &
                     'closed; give the input file''s name, or pipe the input in')
      stop 3, quiet=.true.
    end if
    call run_input_file(input_path, status, cli, overrides)
  else
    call run_default(status, cli, overrides)
  end if

  if (status%code == STATUS_LIMITS_EXCEEDED) then
    call log_warning(status%text())
    call end_with_output_checked(4)
  else if (status%code /= STATUS_OK) then
    call log_error(status%text())
    select case (status%code)
    case (STATUS_INVALID_INPUT); stop 1, quiet=.true.
    case (STATUS_IO); stop 3, quiet=.true.
    case default; stop 2, quiet=.true.
    end select
  end if
  call end_with_output_checked()

contains

  !> The value of --progress: seconds, a number > 0 (at most a day).
  function seconds(text) result(x)
    character(len=*), intent(in) :: text
    real(wp) :: x
    integer :: outcome
    character(len=*), parameter :: allowed = ': give the seconds between progress lines, a number > 0 '// &
                                             'and <= 86400'
    ! read as the input's numbers are: no NaN or Inf, no exponent that would overflow
    call read_real_token(nml_value_t(text=trim(text)), x, outcome)
    if (outcome /= NUMBER_OK) call usage_error('--progress '//text//allowed)
    if (.not. (x > 0 .and. x <= 86400)) call usage_error('--progress '//text//allowed)
  end function seconds

  !> Command-line argument i, of any length.
  function argument(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: text)
    if (length > 0) call get_command_argument(i, text)
  end function argument

  !> The option's value: after '=', or the next argument.
  subroutine take_value()
    if (has_value) return
    if (i == n) call usage_error('option '//option//' needs a value')
    i = i + 1
    value = argument(i)
  end subroutine take_value

  subroutine no_value()
    if (has_value) call usage_error('option '//option//' takes no value ("'//arg//'")')
  end subroutine no_value

  function scenario_list() result(text)
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, size(scenario_names)
      text = text//' '//trim(scenario_names(k))
    end do
  end function scenario_list

  subroutine print_help()
    call write_standard_output('usage: slidesim [options] [input.nml | -]')
    call write_standard_output('')
    call write_standard_output('Runs the scenario named in &run of the namelist file input.nml (- reads it')
    call write_standard_output('from standard input) and writes its results to an HDF5 file (&run output,')
    call write_standard_output('default <scenario>.h5). Without an input file it runs the built-in default')
    call write_standard_output('input. See docs/inputs.md for every input variable and docs/outputs.md for')
    call write_standard_output('the result file layout. Options take their value as the next argument or')
    call write_standard_output('after "=" (--output=FILE).')
    call write_standard_output('')
    call write_standard_output('options:')
    call write_standard_output('  -o, --output FILE         write the results to FILE (overrides &run output)')
    call write_standard_output('  --set GROUP%VAR=VALUE     set or replace a variable of the input, checked like')
    call write_standard_output('                            the file (repeatable): --set solver%rtol=1e-8;')
    call write_standard_output('                            a word needs no quotes: --set solver%method=bdf;')
    call write_standard_output('                            of a repeated group the k-th or the one named:')
    call write_standard_output('                            --set "body(2)%mass=3", --set "body(egg)%mass=3"')
    call write_standard_output('  --unset GROUP%VAR         remove a variable from the input: it takes its')
    call write_standard_output('                            default (--unset solver%duration); checked')
    call write_standard_output('                            like --set, applied in order with the --set ones')
    call write_standard_output('  --check                   read and check the input, build the models, write')
    call write_standard_output('                            nothing; prints "input ok"')
    call write_standard_output('  --summary-json FILE       also write the summary''s numbers as JSON to FILE')
    call write_standard_output('  --fail-on-limit           exit status 4 when a ride (of ride or sweep) exceeds')
    call write_standard_output('                            a limit of &rider (as &evaluation fail_on_limit)')
    call write_standard_output('  --export-stl FILE         also write the slide surface and the water band as ASCII STL')
    call write_standard_output('  --export-obj FILE         ... as Wavefront OBJ (after a complete run; docs/outputs.md)')
    call write_standard_output('  --ride-csv FILE           a ride: also its time series as CSV (speed, felt g, forces)')
    call write_standard_output('  --default-input [SCENARIO] print the built-in default input, or a commented')
    call write_standard_output('                            template of SCENARIO')
    call write_standard_output('  --input-reference         print the tables of the declared input variables')
    call write_standard_output('                            (docs/inputs.md, "Reference")')
    call write_standard_output('  --progress SECONDS        wall-clock seconds between progress lines of long')
    call write_standard_output('                            runs (default 2)')
    call write_standard_output('  -q, --quiet               no progress messages')
    call write_standard_output('  -h, --help                this help')
    call write_standard_output('  -V, --version             the version and the git commit of the build')
    call write_standard_output('')
    call write_standard_output('scenarios:')
    call print_scenarios()
    call write_standard_output('')
    call write_standard_output('exit status: 0 done; 1 bad command line or input, or an output that would')
    call write_standard_output('overwrite a file the run reads (nothing written);')
    call write_standard_output('2 the run failed part way (result file kept, marked incomplete);')
    call write_standard_output('3 a file could not be read or written, or an output names a device, FIFO or socket')
    call write_standard_output('(nothing kept, or the message says where the results are);')
    call write_standard_output('4 done, results complete, a limit exceeded (only with --fail-on-limit).')
  end subroutine print_help

  !> Ends with exit status 0 (or `done`: 4, limits exceeded), or 3 if a line
  !> of standard output was lost: the result files are complete (the summary
  !> is printed after they are closed and renamed), but what was printed is not.
  subroutine end_with_output_checked(done)
    integer, intent(in), optional :: done
    character(len=:), allocatable :: reason
    if (standard_output_lost(reason)) then
      call log_error('cannot write to standard output: '//reason//'; what slidesim printed there is '// &
                     'incomplete (result files written by this run are complete; --summary-json FILE '// &
                     'writes the summary to a file)')
      stop 3, quiet=.true.
    end if
    ! quiet: gfortran's STOP would otherwise list the IEEE flags raised on the
    ! way (underflow in the integration is expected) on standard error
    if (present(done)) stop done, quiet=.true.
    stop 0, quiet=.true.
  end subroutine end_with_output_checked

  subroutine usage_error(message)
    character(len=*), intent(in) :: message
    call log_error(message//' (see slidesim --help)')
    stop 1, quiet=.true.
  end subroutine usage_error
end program slidesim
