!> The ride's records in the result file (/rider, /evaluation) and in the
!> --ride-csv table (scenario `ride`, docs/rider.md): what the ride recorded
!> and the report's figures, each with its unit and meaning.
module scenarios_ride_results
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_status, only: status_t
  use geometry_surface, only: surface_t
  use rider_model, only: rider_params_t, N_CONTACTS, contact_names, CONTACT_PELVIS, rider_friction_kind
  use rider_ride, only: ride_result_t, ride_series_t
  use design_ride_evaluation, only: limit_stored_unit, ride_limit_t, limit_verdict_t
  use design_ride_report, only: ride_report_t
  use io_hdf5, only: result_file_t
  use io_output_files, only: text_output_t
  use scenarios_ride_flights, only: write_flights
  implicit none (type, external)
  private
  public :: friction_name, write_ride, write_evaluation, write_ride_csv, write_limit_verdicts

contains

  !> The rider's friction as the datasets describe it.
  pure function friction_name(rider) result(name)
    type(rider_params_t), intent(in) :: rider
    character(len=:), allocatable :: name
    character(len=:), allocatable :: kind
    kind = rider_friction_kind(rider)
    if (kind == 'coulomb') then
      name = 'Coulomb friction'
    else
      name = 'friction (law '''//kind//''')'
    end if
  end function friction_name

  !> /rider: the ride's records; `friction` names the rider's friction law.
  subroutine write_ride(file, surface, ride, report, cpu, friction, status)
    type(result_file_t), intent(inout) :: file
    class(surface_t), intent(in) :: surface
    type(ride_result_t), intent(in) :: ride
    type(ride_report_t), intent(in) :: report
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: friction
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/rider/'
    character(len=:), allocatable :: c, uu, vu, in_flight
    integer :: n, k
    n = ride%series%n
    in_flight = ''
    if (ride%flights%watched) in_flight = '; with a contact open (airborne > 0) the model''s value (its held '// &
      'posture and attitude), not what a rider feels (docs/rider.md, "Flight")'
    call surface%parameter_units(uu, vu)
    associate (s => ride%series)
      call file%write_vector(g//'time', s%time(:n), 's', 'time from the start of the ride', status)
      call file%write_vector(g//'arc_length', s%arc_length(:n), 'm', &
                             'centerline arc length at the pelvis contact (from the slide''s start)', status)
      call file%write_vector(g//'speed', s%speed(:n), 'm/s', 'speed of the pelvis contact', status)
      call file%write_vector(g//'heading', s%heading(:n), 'rad', &
                             'heading phi_B: body axis from down the slide towards +v', status)
      call file%write_vector(g//'phi_legs', s%phi_legs(:n), 'rad', 'flexion of the legs at the hip (+ lifts '// &
                             'the heels)', status)
      call file%write_vector(g//'phi_trunk', s%phi_trunk(:n), 'rad', 'tilt of the trunk at the hip (+ lifts '// &
                             'the head)', status)
      call file%write_matrix(g//'acceleration_g', report%felt(:, :n), report%felt_units, &
                             'felt specific force (a - g)/|g| at the pelvis centre of mass in the pelvis axes: '// &
                             'longitudinal (towards the feet), '// &
                             'lateral (to the left), normal (+ pressed onto the slide), in multiples of |g|'// &
                             in_flight, status)
      call file%write_vector(g//'lever_arm', merge(report%lever_arm(:n), 0.0_wp, abs(report%lever_arm(:n)) < &
                             huge(1.0_wp)), 'm', 'tipping lever arm at the pelvis contact (E.3): the slide''s '// &
                             'moment about the body axis over the normal force (0 where it does not press)'// &
                             in_flight, status)
      call file%write_vector(g//'energy', s%energy(:n), 'J', 'kinetic + potential energy of the three bodies', &
                             status)
      call file%write_vector(g//'kinetic_energy', s%kinetic(:n), 'J', 'kinetic energy', status)
      call file%write_vector(g//'potential_energy', s%potential(:n), 'J', 'potential energy -m g.r', status)
      call file%write_vector(g//'friction_work', s%friction_work(:n), 'J', &
                             'work of the '//friction//' at the three contacts since the start (<= 0)', status)
      call file%write_vector(g//'drag_work', s%drag_work(:n), 'J', &
                             'work of the water drag since the start (> 0 where the water pushes)', status)
      call file%write_vector(g//'closure_residual', s%closure_residual(:n), 'm', &
                             'largest closure residual of heels and back (4.27)', status)
      call file%write_integers(g//'record_kind', s%kind(:n), '1', '1: start, 2: output time, 3: event', status)
      do k = 1, N_CONTACTS
        c = g//trim(contact_names(k))//'/'
        associate (x => s%contact(k))
          call file%write_vector(c//'u', x%u(:n), uu, 'surface coordinate u of the contact', status)
          call file%write_vector(c//'v', x%v(:n), vu, 'surface coordinate v (pi/2: the bottom)', status)
          call file%write_vector(c//'arc_length', x%arc_length(:n), 'm', 'centerline arc length at u', status)
          call file%write_vector(c//'wall_angle', x%wall_angle(:n), 'rad', &
                                 'angle of the surface normal from the bottom''s (+ towards +v, the left)', status)
          call file%write_vector(c//'wall_distance', x%wall_distance(:n), 'm', &
                                 'distance along the wall from the bottom (+ towards +v)', status)
          call file%write_matrix(c//'position', x%position(:, :n), 'm', 'contact point', status)
          call file%write_matrix(c//'velocity', x%velocity(:, :n), 'm/s', 'velocity of the contact point', status)
          call file%write_vector(c//'normal_force', x%normal_force(:n), 'N', &
                                 'normal force of the slide (> 0 while pressing)', status)
          call file%write_matrix(c//'friction_force', x%friction_force(:, :n), 'N', &
                                 trim(friction//' on the rider'//merge(' (4.28)', '       ', &
                                                                       friction == 'Coulomb friction')), status)
          call file%write_matrix(c//'drag_force', x%drag_force(:, :n), 'N', 'water drag on the rider (4.29)', &
                                 status)
          call file%write_integers(c//'in_water', x%in_water(:n), '1', &
                                   '1 while the contact is between the water''s edges (drag on)', status)
          call file%write_vector(c//'reynolds', x%reynolds(:n), '1', &
                                 'Reynolds number |w_D - w| 2 r_S/nu of the sphere (0 when dry)', status)
          call file%write_vector(c//'drag_coefficient', x%drag_coefficient(:n), '1', &
                                 'Morrison C_D at min(Re, 1e6) (0 when dry)', status)
          call file%write_vector(c//'projected_area', x%projected_area(:n), 'm^2', &
                                 'submerged cap projected across the relative velocity (appendix G; 0 when dry)', &
                                 status)
          call file%write_matrix(c//'relative_velocity', x%relative_velocity(:, :n), 'm/s', &
                                 'velocity of the contact relative to the water, w_D - w (0 when dry)', status)
        end associate
      end do
    end associate
    if (ride%flights%watched) call file%write_integers(g//'airborne', ride%series%airborne(:n), '1', &
                                                       'the open contacts (may_fly): bit 0 pelvis, 1 heels, 2 back; '// &
                                                       '0 all on, 7 the whole rider in the air', status)
    call file%set_attribute('/rider', 'outcome', ride%outcome, status)
    call file%set_attribute('/rider', 'reached_end', merge(1, 0, ride%complete), status)
    if (ride%ejected_contact > 0) &
      call file%set_attribute('/rider', 'ejected', trim(contact_names(ride%ejected_contact)), status)
    call file%write_count(g//'statistics/steps', int(ride%driver%stats%steps), '1', 'integrator steps', status)
    call file%write_count(g//'statistics/rhs_evaluations', int(ride%driver%stats%rhs_evaluations), '1', &
                          'right-hand-side evaluations', status)
    call file%write_count(g//'statistics/error_test_failures', int(ride%driver%stats%error_test_failures), '1', &
                          'error test failures', status)
    call file%write_count(g//'statistics/events', ride%driver%events, '1', &
                          'events (drag on/off, stops, stall crossings)', status)
    call file%write_count(g//'statistics/drag_switches', ride%drag_switches, '1', &
                          'times a contact entered or left the water', status)
    call file%write_scalar(g//'statistics/cpu_time', cpu, 's', 'CPU time of the ride and its evaluation', status)
    if (n > 0) then
      call file%make_scale(g//'time', status)
      call file%attach_scale(g//'time', '/rider', status)
      call file%attach_components('/rider', status)
    end if
  end subroutine write_ride

  !> /evaluation: the report's figures and each limit's verdict.
  subroutine write_evaluation(file, ride, r, status)
    type(result_file_t), intent(inout) :: file
    type(ride_result_t), intent(in) :: ride
    type(ride_report_t), intent(in) :: r
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = '/evaluation/'
    character(len=*), parameter :: axis(3) = [character(len=12) :: 'longitudinal', 'lateral', 'normal']
    character(len=:), allocatable :: c, judged_where
    integer :: k
    if (r%n < 1) return
    call file%write_scalar(g//'ride_time', r%ride_time, 's', 'time from the start to the stop', status)
    call file%write_scalar(g//'distance', r%distance, 'm', 'arc length covered by the pelvis', status)
    call file%write_scalar(g//'top_speed', r%top_speed, 'm/s', 'largest speed', status)
    call file%write_scalar(g//'top_speed_arc_length', r%top_speed_at, 'm', 'where (pelvis arc length)', status)
    call file%write_scalar(g//'final_speed', r%final_speed, 'm/s', 'speed at the stop', status)
    if (ride%complete) call file%write_scalar(g//'exit_speed', r%final_speed, 'm/s', &
                                              'speed when the rider leaves the slide (at its end)', status)
    if (r%ejected_contact > 0) call file%write_scalar(g//'ejected_arc_length', r%ejected_at, 'm', &
      'where the '//trim(contact_names(r%ejected_contact))//' went over the top of a wall (pelvis arc length)', &
      status)
    judged_where = ''
    if (ride%flights%watched) then
      call write_flights(file, ride%flights, g//'flight/', status)
      call file%write_scalar(g//'flight/felt_not_judged_time', r%not_judged_time, 's', 'time with a contact '// &
        'open: the felt accelerations and the lever arm there are the model''s (its held posture and attitude), '// &
        'left out of /evaluation''s extremes and limits; in the air a free body feels 0 g', status)
      judged_where = '; where judged: 0 with the whole rider in the air, none with the pelvis in the air while '// &
                 'another contact is on or alone on the slide (docs/rider.md)'
    end if
    do k = 1, 3
      c = g//'acceleration_'//trim(axis(k))
      call file%write_scalar(c//'_max', r%felt_max(k), r%felt_units, 'largest felt acceleration along the '// &
                             'pelvis''s '//trim(axis(k))//' axis, multiples of |g|'//judged_where, status)
      call file%write_scalar(c//'_max_arc_length', r%felt_max_at(k), 'm', 'where (pelvis arc length)', status)
      call file%write_scalar(c//'_min', r%felt_min(k), r%felt_units, 'smallest felt acceleration along the '// &
                             'pelvis''s '//trim(axis(k))//' axis, multiples of |g|'//judged_where, status)
      call file%write_scalar(c//'_min_arc_length', r%felt_min_at(k), 'm', 'where (pelvis arc length)', status)
    end do
    call file%write_scalar(g//'lever_arm_max', r%lever_max, 'm', 'largest tipping lever arm (signed)'//judged_where, &
                           status)
    call file%write_scalar(g//'lever_arm_max_arc_length', r%lever_max_at, 'm', 'where', status)
    do k = 1, N_CONTACTS
      c = g//trim(contact_names(k))//'/'
      call file%write_scalar(c//'wall_angle_max', r%climb_angle(k), 'rad', &
                             'steepest on the wall: the largest angle from the bottom (signed, + to the left)', status)
      call file%write_scalar(c//'wall_arc_length', r%climb_at(k), 'm', 'where (pelvis arc length)', status)
      call file%write_scalar(c//'wall_distance_max', r%wall_distance_max(k), 'm', 'highest on the wall: the '// &
                             'largest distance along the wall from the bottom (signed, + to the left)', status)
      call file%write_scalar(c//'wall_distance_max_arc_length', r%wall_distance_at(k), 'm', &
                             'where (pelvis arc length)', status)
      call file%write_scalar(c//'normal_force_min', r%normal_min(k), 'N', 'smallest normal force (lift-off '// &
                             'margin)', status)
      call file%write_scalar(c//'normal_force_min_arc_length', r%normal_min_at(k), 'm', 'where', status)
    end do
    if (size(r%limits) > 0) call write_limit_verdicts(file, g//'limits/', r%limits, r%verdicts, r%judged, &
                                                      r%felt_units, 'the ride did not reach the exit', status)
  end subroutine write_evaluation

  !> One group per limit under `group` (`<k>_<quantity>/`): the quantity,
  !> its bounds in the unit stored (felt accelerations in `felt_units`), the
  !> unit given and the verdict with its worst value, where and by how much;
  !> `not_judged` says why a limit was not judged (judged(k) false). The
  !> ride's /evaluation/limits and a vehicle's /sled/vehicle/limits
  !> (docs/outputs.md).
  subroutine write_limit_verdicts(file, group, limits, verdicts, judged, felt_units, not_judged, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: group, felt_units, not_judged
    type(ride_limit_t), intent(in) :: limits(:)
    type(limit_verdict_t), intent(in) :: verdicts(:)
    logical, intent(in) :: judged(:)
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: c, unit
    integer :: k
    do k = 1, size(limits)
      c = group//format_integer(k)//'_'//limits(k)%quantity//'/'
      unit = limit_stored_unit(limits(k)%quantity, felt_units)
      call file%write_text(c//'quantity', limits(k)%quantity, 'what is limited', status)
      if (limits(k)%has_minimum) call file%write_scalar(c//'minimum', limits(k)%minimum, unit, &
                                                        'the lower limit', status)
      if (limits(k)%has_maximum) call file%write_scalar(c//'maximum', limits(k)%maximum, unit, &
                                                        'the upper limit', status)
      call file%write_text(c//'given_unit', limits(k)%unit, 'the unit the limit was given in', status)
      if (.not. judged(k)) then
        call file%write_text(c//'verdict', 'not judged', not_judged, status)
        cycle
      end if
      call file%write_text(c//'verdict', trim(merge('exceeded', 'ok      ', verdicts(k)%exceeded)), &
                           'ok or exceeded', status)
      call file%write_scalar(c//'worst', verdicts(k)%worst, unit, &
                             'the value furthest beyond (or nearest to) a bound', status)
      call file%write_scalar(c//'worst_arc_length', verdicts(k)%worst_where, 'm', 'where', status)
      call file%write_scalar(c//'excess', verdicts(k)%excess, unit, 'by how much it is exceeded (0: not)', &
                             status)
      if (verdicts(k)%exceeded) call file%write_scalar(c//'first_arc_length', verdicts(k)%first_where, 'm', &
                                                       'where it is first exceeded', status)
    end do
  end subroutine write_limit_verdicts

  !> --ride-csv: one line per record of the ride (as /rider in the result);
  !> a ride that may fly (`flights`) adds the column airborne (the open
  !> contacts, as /rider/airborne: its felt values there are the model's,
  !> not what a rider feels).
  subroutine write_ride_csv(path, s, r, flights, status)
    character(len=*), intent(in) :: path
    type(ride_series_t), intent(in) :: s
    type(ride_report_t), intent(in) :: r
    logical, intent(in) :: flights
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: names(21) = [character(len=24) :: 'time_s', 'arc_length_m', 'speed_m_per_s', &
      'felt_longitudinal_g', 'felt_lateral_g', 'felt_normal_g', 'pelvis_x_m', 'pelvis_y_m', 'pelvis_z_m', &
      'normal_force_pelvis_N', 'normal_force_heels_N', 'normal_force_back_N', 'wall_angle_pelvis_deg', &
      'wall_angle_heels_deg', 'wall_angle_back_deg', 'lever_arm_m', 'heading_deg', 'kinetic_energy_J', &
      'energy_J', 'in_water_pelvis', 'airborne']
    real(wp), allocatable :: table(:, :)
    real(wp), parameter :: deg = 180/acos(-1.0_wp)
    type(text_output_t) :: out
    character(len=20*size(names)) :: line
    integer :: n, k, i, columns
    n = s%n
    columns = size(names) - merge(0, 1, flights)
    allocate (table(n, columns))
    table(:, 1) = s%time(:n)
    table(:, 2) = s%arc_length(:n)
    table(:, 3) = s%speed(:n)
    table(:, 4:6) = transpose(r%felt(:, :n))
    table(:, 7:9) = transpose(s%contact(CONTACT_PELVIS)%position(:, :n))
    do k = 1, N_CONTACTS
      table(:, 9 + k) = s%contact(k)%normal_force(:n)
      table(:, 12 + k) = s%contact(k)%wall_angle(:n)*deg
    end do
    table(:, 16) = merge(r%lever_arm(:n), 0.0_wp, abs(r%lever_arm(:n)) < huge(1.0_wp))
    table(:, 17) = s%heading(:n)*deg
    table(:, 18) = s%kinetic(:n)
    table(:, 19) = s%energy(:n)
    table(:, 20) = s%contact(CONTACT_PELVIS)%in_water(:n)
    if (flights) table(:, 21) = real(s%airborne(:n), wp)
    call out%create(path, 'the ride CSV', status)
    if (.not. status%ok()) return
    line = names(1)
    do k = 2, columns
      line = trim(line)//','//names(k)
    end do
    call out%write_line(trim(line))
    do i = 1, n   ! nine significant digits
      write (line, '(*(g0.9, :, ","))') table(i, :)
      call out%write_line(trim(line))
    end do
    call out%finish(status)
  end subroutine write_ride_csv
end module scenarios_ride_results
