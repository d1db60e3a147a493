!> A chart change of the carried model while another contact is open (issue
!> 25, contact_open_gaps): the spinning egg of
!> inputs/contact/egg_long_axis_z.nml carried by the table, with a wall (the
!> plane x = x_w, its normal towards the egg) as a second, open contact
!> whose gap is watched. The gap comes from a second workspace of the closed
!> model (shadow_work), which must follow the model's chart changes
!> (follow_charts): after a change y means another pose on the old chart.
!>
!>   charts   the model changes the chart of the egg's surface as its
!>            contact point nears a pole of (3.57) (at t = 1.855 s);
!>   gap      at every record the wall's nearest point to the egg (the
!>            gap's point on the wall) is the closed form from the recorded
!>            pose (centre p, rotation R): (x_w, s_y, s_z) with s = p + R
!>            D^2 n/|D n|, n = R^T e_x, D = diag(a, b, c), the ellipsoid's
!>            support point along e_x (1e-9 m: the foot-point solver's
!>            tolerance; a stale shadow pose after the chart change is off
!>            by centimetres).
program test_carried_charts
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, DRIVE_END_TIME
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use contact_flight, only: flight_ode_t, carrying_contact, closed_part
  use contact_closing, only: drive_flight, flight_after_closed
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t, read_solver_config
  use io_contact_config, only: read_contact_config
  use testing, only: check, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: axes(3) = [0.025_wp, 0.025_wp, 0.033_wp], x_wall = 0.1_wp
  type(input_text_t) :: input
  type(flight_ode_t), target :: flight
  type(contact_system_t) :: system
  type(contact_model_t) :: model
  type(solver_config_t) :: solver
  type(driver_options_t) :: options
  type(driver_result_t) :: result
  type(status_t) :: st
  real(wp), allocatable :: q0(:), qd0(:)
  character(len=8), allocatable :: units(:)
  integer, allocatable :: open(:, :)
  real(wp) :: worst, normal(3), support(3)
  integer :: i

  call input_from_text('egg by a wall', &
    '&run scenario = ''contact'' /'//nl// &
    '&solver method = ''adams'', rtol = 1e-11, atol = 1e-10, duration = 3.0, output_step = 5e-3 /'//nl// &
    '&contact_model gravity = 0.0, 0.0, -9.80665 /'//nl// &
    '&shape name = ''table'', kind = ''plane'' /'//nl// &
    '&shape name = ''wall'', kind = ''plane'', origin = 0.1, 0, 0, angles_deg = 0, -90, 0 /'//nl// &
    '&shape name = ''egg'', kind = ''ellipsoid'', a = 0.025, b = 0.025, c = 0.033 /'//nl// &
    '&body name = ''egg'', mass = 0.08, solid_of = ''egg'', position = 0.0, 0.0, 0.05, '// &
    'angles_deg = 77.0, 0.0, 0.0, angular_velocity = 0.0, 0.0, 150.0 /'//nl// &
    '&contact name = ''egg_on_table'', shape_1 = ''table'', body_2 = ''egg'', shape_2 = ''egg'', '// &
    'friction = ''viscous_weight'', mu = 0.3 /'//nl// &
    '&contact name = ''egg_on_wall'', shape_1 = ''wall'', body_2 = ''egg'', shape_2 = ''egg'', '// &
    'start = ''open'' /'//nl, input, st)
  if (st%ok()) call read_solver_config(input, solver, st)
  if (st%ok()) call read_contact_config(input, system, st)
  call check(st%ok() .and. carrying_contact(system) == 1, 'the egg carried by the table: '//st%text())
  if (.not. st%ok()) call finish_tests('test_carried_charts')
  call build_contact_model(closed_part(system, carrying_contact(system)), model, st)
  if (st%ok()) call flight_after_closed(system, model, flight, q0, qd0, units, st)
  call check(st%ok(), 'the carried model: '//st%text())
  if (.not. st%ok()) call finish_tests('test_carried_charts')
  options%ode = solver%options
  options%ode%convergence_coefficient = contact_convergence_coefficient
  options%t_end = solver%duration
  options%output_step = solver%output_step
  options%progress_seconds = 0
  call flight%start_series(400)
  call drive_flight(flight, flight%initial_state(q0, qd0), options, result, st, open)
  call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'runs to the end, carried: '//st%text())
  print '(a,i0,a,i0)', 'chart changes ', flight%chart_changes, ', records ', flight%series%n
  call check(flight%chart_changes > 0, 'the carried model changed charts')
  worst = 0
  associate (s => flight%series)
    call check(all(open(1, :s%n) == 0) .and. all(open(2, :s%n) == 1), 'the table closed, the wall open')
    call check(size(flight%gap_point, 3) == s%n, 'the wall''s gap point at every record')
    if (size(flight%gap_point, 3) /= s%n) call finish_tests('test_carried_charts')
    do i = 1, s%n
      associate (rot => s%body_rot(:, :, 1, i))
        normal = rot(1, :)   ! R^T e_x
        support = s%body_r(:, 1, i) + matmul(rot, axes**2*normal/norm2(axes*normal))
      end associate
      worst = max(worst, norm2(flight%gap_point(:, 2, i) - [x_wall, support(2), support(3)]))
    end do
  end associate
  print '(a,es10.3,a)', 'the wall''s nearest point off the closed form by ', worst, ' m'
  call check(worst <= 1e-9_wp, 'the wall''s nearest point at every record is the closed form')
  call finish_tests('test_carried_charts')
end program test_carried_charts
