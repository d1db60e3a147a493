!> The slidesim command: runs the scenario named in a namelist file (or the
!> built-in default) and turns the outcome into a message and an exit status:
!> 0 done; 1 bad command line or input (nothing written); 2 the run failed part
!> way (the result file is kept, marked incomplete); 3 a file could not be
!> read or written.
program slidesim
  use base_status, only: status_t, STATUS_OK, STATUS_INVALID_INPUT, STATUS_IO
  use base_log, only: log_error, set_verbosity
  use scenarios_registry, only: run_input_file, run_default, print_scenarios, slidesim_version, &
                                default_input
  use io_run_config, only: run_config_t
  use io_system, only: ignore_file_size_signal
  implicit none (type, external)

  type(status_t) :: status
  type(run_config_t) :: cli
  character(len=1024) :: arg
  character(len=:), allocatable :: input_path, output_path
  integer :: i, n

  ! a write beyond the file-size limit then fails and is reported (exit 3)
  call ignore_file_size_signal()
  n = command_argument_count()
  i = 0
  do while (i < n)
    i = i + 1
    call get_command_argument(i, arg)
    select case (trim(arg))
    case ('-h', '--help')
      call print_help()
      stop
    case ('-V', '--version')
      print '(a)', 'slidesim '//slidesim_version
      stop
    case ('--default-input')
      print '(a)', default_input()
      stop
    case ('-q', '--quiet')
      call set_verbosity(0)
    case ('-o', '--output')
      if (i == n) call usage_error('option '//trim(arg)//' needs a file name')
      i = i + 1
      call get_command_argument(i, arg)
      output_path = trim(arg)
    case default
      if (arg(1:1) == '-') call usage_error('unknown option "'//trim(arg)//'"')
      if (allocated(input_path)) call usage_error('only one input file can be given')
      input_path = trim(arg)
    end select
  end do

  cli%output = ''
  if (allocated(output_path)) cli%output = output_path
  if (allocated(input_path)) then
    call run_input_file(input_path, status, cli)
  else
    call run_default(status, cli)
  end if

  if (status%code /= STATUS_OK) then
    call log_error(status%text())
    select case (status%code)
    case (STATUS_INVALID_INPUT); stop 1, quiet=.true.
    case (STATUS_IO); stop 3, quiet=.true.
    case default; stop 2, quiet=.true.
    end select
  end if

contains

  subroutine print_help()
    print '(a)', 'usage: slidesim [options] [input.nml]'
    print '(a)', ''
    print '(a)', 'Runs the scenario named in &run of the namelist file input.nml and writes'
    print '(a)', 'its results to an HDF5 file (&run output, default <scenario>.h5). Without'
    print '(a)', 'an input file it runs the built-in default input. See docs/inputs.md for'
    print '(a)', 'every input variable and docs/outputs.md for the result file layout.'
    print '(a)', ''
    print '(a)', 'options:'
    print '(a)', '  -o, --output FILE   write the results to FILE (overrides &run output)'
    print '(a)', '  -q, --quiet         no progress messages'
    print '(a)', '  --default-input     print the built-in default input (a template)'
    print '(a)', '  -h, --help          this help'
    print '(a)', '  -V, --version       the version'
    print '(a)', ''
    print '(a)', 'scenarios:'
    call print_scenarios()
    print '(a)', ''
    print '(a)', 'exit status: 0 done; 1 bad command line or input (nothing written);'
    print '(a)', '2 the run failed part way (result file kept, marked incomplete);'
    print '(a)', '3 a file could not be read or written.'
  end subroutine print_help

  subroutine usage_error(message)
    character(len=*), intent(in) :: message
    call log_error(message//' (see slidesim --help)')
    stop 1, quiet=.true.
  end subroutine usage_error
end program slidesim
