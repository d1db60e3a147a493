!> The flights' highest point above the slide (issue 25 point 4): located on
!> the integrator's dense output (rider_extremes' gap quantities), not at
!> the records. On the crest of inputs/parts/crest_slide.nml (5 m at 30
!> deg, 3 m at 2 deg, a convex bend of 1 m into 15 deg), ridden dry with
!> may_fly: the heels fly, then the whole rider.
!>
!>   spacing     the ride at output steps 0.01, 0.0037, 0.023 and 0.25 s:
!>               the highest point (and each contact's highest gap) the
!>               same to 1e-8 m. At 0.25 s the back's flight has no record
!>               near its apex: the ride hands the records around its gap
!>               rate's fall through zero to the search (without that the
!>               back's apex was missed by 3.5e-5 m). The rides themselves differ by that much: each
!>               record re-solves the closure in the integration's
!>               workspace (tolerance 1e-10 m), so its warm starts differ
!>               (found ~2e-9 m). Taken at the records, as before, the
!>               highest point moved with the records (the heels' apex
!>               falls between them).
!> No contact point flies a projectile here (its apex has no closed form):
!> in the whole rider's flight the legs and the trunk sway on the hips'
!> held springs (posture rates of 1-2 rad/s), so the pelvis's gap leaves
!> the parabola from any record by up to 4e-2 m; the centre of mass is the
!> projectile (test_rider_flight).
program test_rider_flight_highest
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_text, only: format_real
  use geometry_surface, only: surface_t
  use rider_model, only: rider_params_t, N_CONTACTS
  use rider_ride, only: ride_options_t, ride_result_t, simulate_ride, RIDE_END_OF_SLIDE
  use rider_extremes, only: EXTREME_GAP
  use testing, only: check, check_close, finish_tests
  use scenario_fixtures, only: crest_slide
  implicit none (type, external)

  real(wp), parameter :: steps(4) = [0.01_wp, 0.0037_wp, 0.023_wp, 0.25_wp]
  class(surface_t), allocatable :: crest
  type(status_t) :: st
  type(rider_params_t) :: p
  type(ride_options_t) :: options
  type(ride_result_t) :: ride(size(steps))
  real(wp) :: gap(N_CONTACTS, size(steps))
  integer :: i, k

  call crest_slide(crest, st)
  call check(st%ok(), 'the crest slide: '//st%text())
  p%drag = .false.
  options%progress_seconds = 0
  options%may_fly = .true.
  do i = 1, size(steps)
    options%output_step = steps(i)
    call simulate_ride(p, crest, options, ride(i), st)
    call check(st%ok() .and. ride(i)%ending == RIDE_END_OF_SLIDE, 'the crest ride at output step '// &
               format_real(steps(i))//' s: '//ride(i)%outcome)
    gap(:, i) = ride(i)%series%extremes%value(EXTREME_GAP:EXTREME_GAP + N_CONTACTS - 1)
    print '(a,f7.4,a,es23.15,a,i0,a,3es23.15)', 'output step ', steps(i), ' s: highest ', ride(i)%flights%highest, &
      ' m (contact ', ride(i)%flights%highest_contact, '), each contact ', gap(:, i)
  end do
  call check(ride(1)%flights%whole_flights >= 1, 'the whole rider flew')
  do i = 2, size(steps)
    call check_close(ride(i)%flights%highest, ride(1)%flights%highest, 0.0_wp, 1e-8_wp, &
                     'the highest point does not depend on the output step '//format_real(steps(i))//' s')
    call check(ride(i)%flights%highest_contact == ride(1)%flights%highest_contact, 'the same contact rose highest')
    call check_close(ride(i)%flights%highest_arc_length, ride(1)%flights%highest_arc_length, 0.0_wp, 1e-6_wp, &
                     'the highest point is at the same place')
    do k = 1, N_CONTACTS
      call check_close(gap(k, i), gap(k, 1), 0.0_wp, 1e-8_wp, 'each contact''s highest gap does not depend '// &
                       'on the output step')
    end do
  end do
  call finish_tests('test_rider_flight_highest')

contains
end program test_rider_flight_highest
