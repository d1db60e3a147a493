!> Joints of the element chain and the speed across them (issue 26, review).
!>
!> A chain with transition_length = 0 joins its elements sharply: where the
!> slope changes the centerline has a kink (c' = [cos psi, sin psi, -g] with
!> g jumping), and where only the curvature changes the tube's r_u jumps off
!> the centerline (|r_u| ~ |c'| (1 - kappa r cos) across the section). The
!> state of everything that moves on the slide is (u, v, u', v'), so carried
!> across such a joint the speed |r_u u' + r_v v'| jumped (~6 % into a curve
!> of radius 6 m at 0.5 m off the centerline): a silent wrong answer. Such a
!> chain is refused now, naming the joint; a short transition (here 0.5 m)
!> is ridden correctly. (Much shorter ones fold a tube: a 10 deg change of
!> slope over 0.05 m bends the centerline tighter than this tube's radius
!> 0.5 m, which the tube's check refuses.)
!> Against the old code: the ride with transition_length = 0 jumped by
!> 0.80 m/s between two records and lost 25 % of its kinetic energy.
!>
!> The ride: a frictionless point mass up the wall of a circular tube, across
!> a straight (15 deg), a curve (radius 6 m, 90 deg, 5 deg) and a straight
!> (10 deg), recorded every 1 ms. On a frictionless surface the speed
!> changes only by gravity's share along the velocity, |d|v|/dt| <= g, so
!> between records |dv| <= g 1 ms = 9.8e-3 m/s (a jump breaks it), and the
!> energy is conserved (1e-9 of the kinetic energy: rtol 1e-12 over ~1e3
!> steps, as the half-pipe's check in test_slide_parts).
program test_sharp_joints
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use base_text, only: format_short
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use numerics_ode, only: ode_integrator_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use testing, only: check, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')

  call sharp_chains_refused()
  call ride_across_joints()
  call finish_tests('test_sharp_joints')

contains

  !> transition_length = 0 is refused where a joint changes the slope or the
  !> curvature (a drop's curve-out has both ends such a joint), and accepted
  !> where nothing changes at the joints.
  subroutine sharp_chains_refused()
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    chain = new_element_chain([slide_element_t(kind='straight', length=8.0_wp, slope_deg=15.0_wp), &
                               slide_element_t(kind='straight', length=8.0_wp, slope_deg=10.0_wp)], &
                              [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(.not. st%ok() .and. index(st%text(), 'joint 1') > 0 .and. index(st%text(), 'slope') > 0 .and. &
               index(st%text(), 'transition_length') > 0, 'a sharp change of slope is refused: '//st%text())
    chain = new_element_chain([slide_element_t(kind='straight', length=8.0_wp, slope_deg=5.0_wp), &
                               slide_element_t(kind='curve', radius=6.0_wp, angle_deg=90.0_wp, slope_deg=5.0_wp)], &
                              [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(.not. st%ok() .and. index(st%text(), 'joint 1') > 0 .and. index(st%text(), 'curvature') > 0, &
               'a sharp change of curvature is refused: '//st%text())
    chain = new_element_chain([slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp), &
                               slide_element_t(kind='straight', length=6.0_wp, slope_deg=3.0_wp)], &
                              [0.0_wp, 0.0_wp, 14.0_wp], 0.0_wp, 0.0_wp, st)
    call check(.not. st%ok() .and. index(st%text(), 'curve-out') > 0, 'a drop with sharp ends is refused: '// &
               st%text())
    chain = new_element_chain([slide_element_t(kind='straight', length=8.0_wp, slope_deg=5.0_wp), &
                               slide_element_t(kind='runout', length=4.0_wp, slope_deg=5.0_wp)], &
                              [0.0_wp, 0.0_wp, 10.0_wp], 0.0_wp, 0.0_wp, st)
    call check(st%ok(), 'transition_length = 0 where nothing changes at the joint is accepted: '//st%text())
  end subroutine sharp_chains_refused

  subroutine ride_across_joints()
    real(wp) :: energy_drift, speed_step, passed
    logical :: built
    character(len=:), allocatable :: why
    call ride('0', built, why, energy_drift, speed_step, passed)
    call check(.not. built .and. index(why, 'transition_length') > 0 .and. index(why, '&slide_elements') > 0, &
               'the sharp chain is refused through the input, naming the group: '//why)
    if (built) then   ! the old code: the speed jumped at the joints
      call check(speed_step <= standard_gravity*1e-3_wp, 'sharp joints: no speed jump between records: '// &
                 format_short(speed_step))
      call check(energy_drift <= 1e-9_wp, 'sharp joints: energy conserved: '//format_short(energy_drift))
    end if
    call ride('0.5', built, why, energy_drift, speed_step, passed)
    call check(built, 'short transitions (0.5 m) built: '//why)
    if (.not. built) return
    call check(passed > 8 + 6*acos(-1.0_wp)/2 + 1, 'the mass passed both joints: at sigma = '//format_short(passed))
    call check(speed_step <= standard_gravity*1e-3_wp, 'short transitions: no speed jump between records: '// &
               format_short(speed_step))
    call check(energy_drift <= 1e-9_wp, 'short transitions: energy conserved to 1e-9 of the kinetic: '// &
               format_short(energy_drift))
  end subroutine ride_across_joints

  !> The frictionless mass at 8 m/s, 0.7 rad up the left wall, down the
  !> chain with transition length `transition` (text): the largest change
  !> of energy (relative to the start's kinetic) and of speed between
  !> records, and how far it came (sigma, m).
  subroutine ride(transition, built, why, energy_drift, speed_step, passed)
    character(len=*), intent(in) :: transition
    logical, intent(out) :: built
    character(len=:), allocatable, intent(out) :: why
    real(wp), intent(out) :: energy_drift, speed_step, passed
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, e0, k0, speed_prev
    integer :: k
    logical :: at_root
    energy_drift = huge(1.0_wp); speed_step = huge(1.0_wp); passed = 0
    call input_from_text('<test>', '&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-12, atol = 1e-12 /'//nl// &
      '&surface kind = ''slide'' /'//nl//'&geometry kind = ''slide'' /'//nl// &
      '&slide_elements n_elements = 3, start = 0, 0, 10, transition_length = '//transition//','// &
      ' centerline_kind = ''exact'', kind = ''straight'', ''curve'', ''straight'', length = 8, 0, 8,'// &
      ' slope_deg = 15, 5, 10, radius = 0, 6, 0, angle_deg = 0, 90, 0 /'//nl// &
      '&cross_section kind = ''circle'', radius = 0.5 /'//nl// &
      '&point_mass u0 = 1, v0 = 0.8707963267948966, du0 = 7.7, dv0 = 0, friction = ''none'' /', input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    built = st%ok()
    why = st%text()
    if (.not. built) return
    call model%state(y0, state, st)
    k0 = state%kinetic_energy
    e0 = state%kinetic_energy + state%potential_energy
    speed_prev = state%speed
    energy_drift = 0
    speed_step = 0
    call integrator%start(model, 0.0_wp, y0, solver%options, st)
    do k = 1, 4000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      energy_drift = max(energy_drift, abs(state%kinetic_energy + state%potential_energy - e0)/k0)
      speed_step = max(speed_step, abs(state%speed - speed_prev))
      speed_prev = state%speed
      passed = y(1)
      if (y(1) > 8 + 6*acos(-1.0_wp)/2 + 4) exit
    end do
    call check(st%ok(), 'the ride ran ('//transition//' m): '//st%text())
    call integrator%destroy()
  end subroutine ride
end program test_sharp_joints
