!> The rider mechanism: where heels and back meet the slide at the start,
!> starts that are refused (which contact, by how much), and a known answer:
!> the rider on the bottom line of a straight inclined tube, Coulomb friction
!> mu at the three contacts, no drag.
!>
!> Known answer (derived in docs/rider.md, "Checks"): the three contacts lie
!> on one straight line, all normals are equal, so the normal forces sum to
!> m g cos(theta) and the friction to mu m g cos(theta):
!>     u'' = g (sin(theta) - mu cos(theta)).
!> The hinges make the distribution determinate: moments about the hip axis
!> of the legs (CoM x_L from the hip, heel at (l, -h)) and of the trunk
!> (CoM x_T < 0, back at (b < 0, -h)), with the effective load
!> m g cos(theta) (mu, -1) per body in the slide's axes:
!>     N_heels = m_L g cos(theta) x_L/(l - mu h),
!>     N_back  = -m_T g cos(theta) x_T/(mu h - b),
!>     N_pelvis = m g cos(theta) - N_heels - N_back.
program test_rider_model
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use geometry_tube, only: tube_surface_t, new_straight_tube
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use rider_model, only: rider_params_t, rider_layout_t, build_rider, rider_start_velocity, &
    CONTACT_PELVIS, CONTACT_HEELS, CONTACT_BACK
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  real(wp), parameter :: theta = 15*pi/180, g = standard_gravity

  call check_start_on_straight()
  call check_refused_starts()
  call check_inclined_tube()
  call finish_tests('test_rider_model')

contains

  function straight_tube(length, radius) result(tube)
    real(wp), intent(in) :: length
    real(wp), intent(in), optional :: radius
    type(tube_surface_t) :: tube
    type(status_t) :: st
    real(wp) :: r
    r = 0.5_wp
    if (present(radius)) r = radius
    tube = new_straight_tube(r, theta, length, st)
    call check(st%ok(), 'straight tube built')
  end function straight_tube

  !> At the bottom of a straight tube heels and back lie on the bottom line:
  !> joint angles 0, contacts at hip + heel length ahead and back length behind.
  subroutine check_start_on_straight()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    real(wp) :: q0(3)
    p%u0 = 5
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call check(st%ok(), 'rider builds: '//st%text())
    call m%check_start(work, q0, st)
    call check(st%ok(), 'the loops close at the start: '//st%text())
    ! atol 1e-12 rad: the start search bisects to 1e-13 rad, Newton polishes
    call check_close(m%scalars(lay%flexion)%q, 0.0_wp, 0.0_wp, 1e-12_wp, 'legs straight')
    call check_close(m%scalars(lay%tilt)%q, 0.0_wp, 0.0_wp, 1e-12_wp, 'trunk straight')
    call check_close(m%scalars(lay%u(CONTACT_HEELS))%q, 5 + lay%body%hip(1) + lay%body%heel(1), 1e-14_wp, 0.0_wp, &
                     'heels ahead by hip + leg length')
    call check_close(m%scalars(lay%u(CONTACT_BACK))%q, 5 + lay%body%hip(1) + lay%body%back(1), 1e-14_wp, 0.0_wp, &
                     'back behind')
    call check_close(m%scalars(lay%v(CONTACT_HEELS))%q, pi/2, 1e-14_wp, 0.0_wp, 'heels at the bottom')
    call check(m%closure_residual() <= 1e-12_wp, 'closure residual at the start')
  end subroutine check_start_on_straight

  !> Heels beyond the slide's end; the back before the start; a body turned
  !> across a tube narrower than the legs are long (no joint angle puts the
  !> heels on the wall).
  subroutine check_refused_starts()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: q0(3)
    p%u0 = 19.5_wp
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'heels cannot reach') > 0 .and. &
               index(st%text(), 'beyond the slide''s end') > 0, 'heels beyond the end refused: '//st%text())
    st = status_t()
    p%u0 = 0.2_wp
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'back cannot reach') > 0, 'back before the start refused: '// &
               st%text())
    st = status_t()
    p%u0 = 5
    p%heading0 = pi/2
    call build_rider(p, straight_tube(20.0_wp, 0.35_wp), m, lay, q0, st)
    call check(.not. st%ok() .and. index(st%text(), 'cannot reach the slide') > 0 .and. &
               index(st%text(), ' m ') > 0, 'turned across the tube refused with a distance: '//st%text())
  end subroutine check_refused_starts

  subroutine check_inclined_tube()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(mechanism_workspace_t) :: work
    type(status_t) :: st
    real(wp) :: q0(3), qd0(3), res, h, n_heels, n_back, n_pelvis, mass
    p%u0 = 5
    p%speed0 = 2
    call build_rider(p, straight_tube(20.0_wp), m, lay, q0, st)
    call rider_start_velocity(p, straight_tube(20.0_wp), qd0, st)
    call check_close(qd0(1), 2.0_wp, 1e-15_wp, 0.0_wp, 'start speed along the tube')
    call m%check_start(work, q0, st)
    call m%evaluate(work, 0.0_wp, q0, qd0, res, st)
    call check(st%ok(), 'evaluates: '//st%text())
    ! rtol 1e-12: exact algebra up to the friction's regularization, (1e-6/2)^2/2
    call check_close(m%qdd(1), g*(sin(theta) - p%mu*cos(theta)), 1e-12_wp, 0.0_wp, &
                     'u'''' = g (sin theta - mu cos theta)')
    call check(abs(m%qdd(2)) < 1e-12_wp .and. abs(m%qdd(3)) < 1e-12_wp, 'stays at the bottom, heading kept')
    h = p%body%com_height
    mass = lay%body%pelvis%mass + lay%body%legs%mass + lay%body%trunk%mass
    n_heels = lay%body%legs%mass*g*cos(theta)*lay%body%legs%com(1)/(lay%body%heel(1) - p%mu*h)
    n_back = -lay%body%trunk%mass*g*cos(theta)*lay%body%trunk%com(1)/(p%mu*h - lay%body%back(1))
    n_pelvis = mass*g*cos(theta) - n_heels - n_back
    call check_close(m%contacts(CONTACT_HEELS)%normal_force, n_heels, 1e-12_wp, 0.0_wp, 'heels normal force')
    call check_close(m%contacts(CONTACT_BACK)%normal_force, n_back, 1e-12_wp, 0.0_wp, 'back normal force')
    call check_close(m%contacts(CONTACT_PELVIS)%normal_force, n_pelvis, 1e-12_wp, 0.0_wp, 'pelvis normal force')
  end subroutine check_inclined_tube
end program test_rider_model
