!> The library prints nothing unless asked (issue 28): library calls made
!> with progress lines due at every look (interval 1e-9 s) and no log write
!> no line, and the same calls given a log send their lines there:
!> - base_log's log_info before the program set a verbosity;
!> - an integration (the rider layer's simulate_ride, through the driver)
!>   and a whole ride (design_ride_job's run_ride) without a log;
!> - the geometry optimiser's progress (designs evaluated);
!> - the surface grid's progress (io_surface_grid).
!> ctest fails this test on any line holding 'unasked', 'optimize:' or
!> 'surface grid:' in its output (tests/CMakeLists.txt): each is what the
!> old code printed there.
program test_library_quiet
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_log, only: log_info, set_progress_interval
  use rider_ride, only: ride_result_t, ride_options_t, simulate_ride
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  use design_geometry_optimization, only: optimization_setup_t, optimization_result_t, table_4_12_design, &
    optimize_slide
  use geometry_elementary, only: plane_t
  use io_hdf5, only: result_file_t
  use io_input, only: input_text_t, input_from_text
  use io_surface_grid, only: write_surface_grid
  use base_grid, only: evenly_spaced
  use scenarios_water, only: build_water
  use testing, only: check, finish_tests
  implicit none (type, external)

  character(len=:), allocatable :: logged   !< the lines the log below received
  character(len=*), parameter :: nl = new_line('a')

  call set_progress_interval(1e-9_wp)   ! a progress line at every look
  call log_info('unasked: log_info before the program set a verbosity')
  call check_rides()
  call check_optimizer()
  call check_surface_grid()
  call finish_tests('test_library_quiet')

contains

  !> The rider alone (the driver without a log) and the whole ride, 0.5 s
  !> on the demo slide.
  subroutine check_rides()
    type(ride_description_t) :: description
    type(ride_job_result_t) :: job
    type(ride_result_t) :: ride
    type(ride_options_t) :: options
    type(input_text_t) :: input
    type(status_t) :: status
    call input_from_text('test_library_quiet', '&surface kind = ''slide'', geometry_file = '// &
                         '''builtin:demo_slide'' /'//nl//'&water flow_rate = 0.004, start = ''edges'', '// &
                         'u0 = 0.0, v_left0 = 1.9207963267948966, v_right0 = 1.2207963267948966 /'//nl, input, status)
    if (status%ok()) call build_water(input, description%water, status, stage=.true.)
    call check(status%ok(), 'the demo slide: '//status%text())
    if (.not. status%ok()) return
    options = description%options
    options%max_duration = 0.5_wp
    options%progress_seconds = 1e-9_wp
    call simulate_ride(description%rider, description%water%slide, options, ride, status, label='unasked ride')
    call check(status%ok() .and. ride%series%n > 10, 'a dry ride without a log runs: '//status%text())
    description%options = options
    description%label = 'unasked job'
    job = run_ride(description)
    call check(job%status%ok() .and. job%ridden, 'run_ride without a log runs: '//job%status%text())
  end subroutine check_rides

  !> Up to 20 designs of thesis table 4.12, three rides each (the first batch of
  !> a Jacobian only starts the progress clock): no line without a
  !> log, 'optimize: ... designs evaluated' lines with one.
  subroutine check_optimizer()
    type(optimization_setup_t) :: setup
    type(optimization_result_t) :: result
    type(status_t) :: status
    setup%design = table_4_12_design()
    setup%start_angles = [-15.0_wp, 0.0_wp, 15.0_wp]*pi/180   ! 6 residuals for 5 design variables
    setup%solver%max_evaluations = 20
    setup%max_restarts = 0
    call optimize_slide(setup, result, status)
    call check(result%evaluations > 0, 'the optimiser without a log evaluates designs: '//status%text())
    logged = ''
    setup%log => collect
    call optimize_slide(setup, result, status)
    call check(index(logged, 'designs evaluated') > 0, 'the optimiser''s progress reaches its log: '//logged)
  end subroutine check_optimizer

  !> A 200 x 3 grid of a plane: no line without a log, 'surface grid: ...'
  !> lines with one.
  subroutine check_surface_grid()
    type(plane_t) :: plane
    type(result_file_t) :: file
    type(status_t) :: status, plane_status
    character(len=*), parameter :: path = 'slidesim_test_library_quiet.h5'
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], &
                      plane_status)
    call check(plane_status%ok(), 'a plane: '//plane_status%text())
    call file%create(tmp_path(path), status)
    call write_surface_grid(file, plane, evenly_spaced(0.0_wp, 1.0_wp, 200), evenly_spaced(0.0_wp, 1.0_wp, 3), &
                            status)
    call check(status%ok(), 'a surface grid without a log: '//status%text())
    call file%finish(.false., 'a test file', status)
    logged = ''
    call file%create(tmp_path(path), status)
    call write_surface_grid(file, plane, evenly_spaced(0.0_wp, 1.0_wp, 200), evenly_spaced(0.0_wp, 1.0_wp, 3), &
                            status, collect)
    call check(status%ok() .and. index(logged, 'surface grid: ') == 1, &
               'the surface grid''s progress reaches its log: '//logged(:min(len(logged), 80)))
    call file%finish(.false., 'a test file', status)
    call remove(tmp_path(path))
  end subroutine check_surface_grid

  !> `name` in the system's temporary folder ($TMPDIR or /tmp).
  function tmp_path(name) result(path)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: path
    character(len=4096) :: folder
    integer :: length, stat
    call get_environment_variable('TMPDIR', folder, length, stat)
    if (stat /= 0 .or. length == 0) folder = '/tmp'
    path = trim(folder)//'/'//name
  end function tmp_path

  subroutine remove(path)
    character(len=*), intent(in) :: path
    integer :: unit, stat
    open (newunit=unit, file=path, status='old', iostat=stat)
    if (stat == 0) close (unit, status='delete')
  end subroutine remove

  subroutine collect(message)
    character(len=*), intent(in) :: message
    logged = logged//message//nl
  end subroutine collect
end program test_library_quiet
