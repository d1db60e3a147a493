!> The air's drag on the point mass (&point_mass drag_area, air_density,
!> wind; the contact scenario's law F = -1/2 rho C_d A |w| w, w the velocity
!> relative to the air), through the input reader and the integration
!> driver, against closed forms (k = rho C_d A/(2 m)):
!>   - incline (inputs/point_mass/incline_drag.nml): from rest down a
!>     frictionless plane at a = 30 degrees in still air, v' = g sin a - k v^2:
!>     v = v_t tanh(g sin a t/v_t), v_t = sqrt(g sin a/k) = sqrt(2 m g sin
!>     a/(rho C_d A)), the distance v_t^2/(g sin a) ln cosh(g sin a t/v_t); the
!>     drag along the slope leaves N = m g cos a; E(t) - E(0) = the drag's
!>     recorded work;
!>   - wind: from rest on a level frictionless plane in a level wind w,
!>     (w - v)' = -k (w - v)^2: v = k w^2 t/(1 + k w t);
!>   - updraft: at rest on a level plane in a vertical wind w_z, the drag
!>     lifts 1/2 rho C_d A w_z^2 off the normal force, the mass stays;
!>   - air_density or wind without drag_area refused.
!> Tolerances: rtol = atol = 1e-10 over ~10^3 steps of a smooth motion:
!> speeds and distances to 1e-8 (relative to v_t, 1e-8 m/s; distance 1e-7
!> m over 100 m), forces to 1e-9 N (N is algebraic in the state).
program test_point_mass_drag
  use base_kinds, only: wp
  use base_constants, only: standard_gravity, dry_air_density
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME
  use kinetostatics_point_mass, only: point_mass_t
  use io_input, only: input_text_t, input_from_text, load_input_file
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: g = standard_gravity

  call incline()
  call wind()
  call updraft()
  call refusals()
  call finish_tests('test_point_mass_drag')

contains

  !> Builds `input` (build_point_mass) and drives it over its &solver.
  subroutine run(input, model, st)
    type(input_text_t), intent(in) :: input
    type(point_mass_t), intent(out), target :: model
    type(status_t), intent(out) :: st
    type(solver_config_t) :: solver
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    real(wp), allocatable :: y0(:)
    call build_point_mass(input, solver, model, y0, st)
    if (.not. st%ok()) return
    options%ode = solver%options
    options%t_end = solver%duration
    options%output_step = solver%output_step
    options%progress_seconds = 0
    call model%start_series(nint(solver%duration/solver%output_step) + 2)
    call drive(model, y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'runs to the end: '//st%text())
  end subroutine run

  function level_input(point_mass) result(text)
    character(len=*), intent(in) :: point_mass
    character(len=:), allocatable :: text
    text = '&run scenario = ''point_mass'' /'//nl// &
           '&solver rtol = 1e-10, atol = 1e-10, duration = 5, output_step = 0.05 /'//nl// &
           '&surface kind = ''plane'', point_a = 0, 0, 0, point_b = 1, 0, 0, point_c = 0, 1, 0 /'//nl// &
           '&point_mass '//point_mass//' /'//nl
  end function level_input

  subroutine incline()
    real(wp), parameter :: mass = 2, drag_area = 0.05_wp, slope = acos(-1.0_wp)/6
    type(input_text_t) :: input
    type(point_mass_t), target :: model
    type(status_t) :: st
    real(wp) :: v_t, a, tau, worst_v, worst_s, worst_n, worst_e
    integer :: i
    call load_input_file('inputs/point_mass/incline_drag.nml', input, st)
    if (st%ok()) call run(input, model, st)
    call check(st%ok(), 'incline: built and ran: '//st%text())
    if (.not. st%ok()) return
    a = g*sin(slope)
    v_t = sqrt(2*mass*a/(dry_air_density*drag_area))
    worst_v = 0
    worst_s = 0
    worst_n = 0
    worst_e = 0
    associate (s => model%series)
      do i = 1, s%n
        tau = a*s%time(i)/v_t
        worst_v = max(worst_v, abs(s%speed(i) - v_t*tanh(tau)))
        worst_s = max(worst_s, abs(s%u(i) - v_t**2/a*log(cosh(tau))))
        worst_n = max(worst_n, abs(s%normal_force(i) - mass*g*cos(slope)))
        worst_e = max(worst_e, abs(s%kinetic(i) + s%potential(i) - s%kinetic(1) - s%potential(1) - s%drag_work(i)))
      end do
      call check_close(worst_v, 0.0_wp, 0.0_wp, 1e-8_wp*v_t, 'incline: v = v_t tanh(g sin a t/v_t) (m/s)')
      call check_close(worst_s, 0.0_wp, 0.0_wp, 1e-7_wp, 'incline: distance v_t^2/(g sin a) ln cosh (m)')
      call check_close(worst_n, 0.0_wp, 0.0_wp, 1e-9_wp, 'incline: N = m g cos a (N)')
      call check_close(worst_e, 0.0_wp, 0.0_wp, 1e-8_wp*s%kinetic(s%n), &
                       'incline: E(t) - E(0) = the drag''s work (J)')
      call check(s%speed(s%n) > 0.99_wp*v_t .and. s%drag_work(s%n) < 0, &
                 'incline: near the terminal speed after 10 s, the drag took energy')
      call check_close(norm2(s%drag_force(:, s%n)), mass*a*tanh(a*s%time(s%n)/v_t)**2, 0.0_wp, 1e-9_wp, &
                       'incline: the drag m g sin a (v/v_t)^2 (N)')
    end associate
  end subroutine incline

  subroutine wind()
    real(wp), parameter :: mass = 1.5_wp, drag_area = 0.2_wp, density = 1.1_wp, w = 4
    type(input_text_t) :: input
    type(point_mass_t), target :: model
    type(status_t) :: st
    real(wp) :: k, worst
    integer :: i
    call input_from_text('wind', level_input('mass = 1.5, drag_area = 0.2, air_density = 1.1, wind = 4, 0, 0'), &
                         input, st)
    if (st%ok()) call run(input, model, st)
    call check(st%ok(), 'wind: built and ran: '//st%text())
    if (.not. st%ok()) return
    k = density*drag_area/(2*mass)
    worst = 0
    associate (s => model%series)
      do i = 1, s%n
        worst = max(worst, abs(s%velocity(1, i) - k*w**2*s%time(i)/(1 + k*w*s%time(i))), abs(s%velocity(2, i)))
      end do
      call check_close(worst, 0.0_wp, 0.0_wp, 1e-8_wp, 'wind: v = k w^2 t/(1 + k w t) (m/s)')
      call check(s%drag_work(s%n) > 0, 'wind: the wind does work on the mass')
    end associate
  end subroutine wind

  subroutine updraft()
    real(wp), parameter :: mass = 0.3_wp, drag_area = 0.5_wp, w_z = 3
    type(input_text_t) :: input
    type(point_mass_t), target :: model
    type(status_t) :: st
    call input_from_text('updraft', level_input('mass = 0.3, drag_area = 0.5, wind = 0, 0, 3'), input, st)
    if (st%ok()) call run(input, model, st)
    call check(st%ok(), 'updraft: built and ran: '//st%text())
    if (.not. st%ok()) return
    associate (s => model%series)
      call check_close(maxval(abs(s%normal_force(:s%n) - (mass*g - dry_air_density*drag_area*w_z**2/2))), 0.0_wp, &
                       0.0_wp, 1e-9_wp, 'updraft: N = m g - 1/2 rho C_d A w_z^2 (N)')
      call check_close(maxval(abs(s%velocity(:, :s%n))), 0.0_wp, 0.0_wp, 1e-12_wp, 'updraft: the mass stays (m/s)')
    end associate
  end subroutine updraft

  subroutine refusals()
    type(input_text_t) :: input
    type(point_mass_t), target :: model
    type(solver_config_t) :: solver
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    call input_from_text('air alone', level_input('air_density = 1.0'), input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    call check(.not. st%ok() .and. index(st%text(), 'give drag_area') > 0, &
               'air_density without drag_area refused: '//st%text())
    call input_from_text('wind alone', level_input('wind = 1, 0, 0'), input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    call check(.not. st%ok() .and. index(st%text(), 'give drag_area') > 0, &
               'wind without drag_area refused: '//st%text())
  end subroutine refusals
end program test_point_mass_drag
