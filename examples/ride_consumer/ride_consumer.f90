!> A program outside slidesim that rides the demo slide through the library:
!> the built-in default input read into a ride description in memory (no
!> file), design_ride_job's run_ride, and the ride's numbers printed from the
!> result (the library prints nothing itself). Numbers are written so that
!> they read back exactly (format_real), as slidesim's --summary-json does.
program ride_consumer
  use base_status, only: status_t
  use base_text, only: format_real
  use io_input, only: input_text_t, input_from_text
  use io_run_config, only: run_config_t
  use scenarios_registry, only: default_input
  use scenarios_ride, only: read_ride_description
  use design_ride_job, only: ride_description_t, ride_job_result_t, run_ride
  implicit none (type, external)
  type(input_text_t) :: input
  type(run_config_t) :: run   ! the command line's options: none
  type(ride_description_t) :: description
  type(ride_job_result_t) :: ride
  type(status_t) :: status
  logical :: fail_on_limit

  call input_from_text('builtin:default', default_input(), input, status)
  call read_ride_description(input, run, description, fail_on_limit, status)
  if (.not. status%ok()) then
    print '(a)', 'bad input: '//status%text()
    error stop 1
  end if
  ride = run_ride(description)
  if (.not. ride%status%ok()) then
    print '(a)', 'status: failed: '//ride%status%text()
    error stop 2
  end if
  print '(a)', 'status: ok'
  print '(a)', 'stopped: '//ride%stopped
  print '(a)', 'top_speed: '//format_real(ride%report%top_speed)//' m/s'
  if (ride%complete) print '(a)', 'exit_speed: '//format_real(ride%report%final_speed)//' m/s'
end program ride_consumer
