!> The mass matrix M, the normal forces per unit acceleration G and the
!> scaled laws' unit-load terms P and H that `dynamics` forms from the partial
!> twists of the mass frames (kinetostatics_mechanism, "M and G from the
!> partial twists") against the inverse dynamics itself: Q_bar is affine in
!> s', so with the velocities zero and the applied forces off the pass at s' =
!> e_i gives exactly -M e_i and the normal forces G e_i, and the pass with law
!> k's unit loads alone gives P e_k and H e_k (the route `dynamics` took
!> before, through the public procedures). Mechanisms: the rider (two loops,
!> normal forces from the force on the contact frames, which carry the loops'
!> cut forces; Coulomb at three contacts), the sled (one loop; the front
!> normal force from the force on its frame and from the cut force; Coulomb,
!> also with its loads on the Darboux frames, which are not tracked: those
!> laws keep their inverse-dynamics pass), the four-bar (a loop, no contact),
!> the egg's open chain and its loop with Coulomb friction, the egg's open
!> chain on a dome, and the tower of five rolling paraboloids (loops and rate
!> constraints: the cut forces mu of rolling enter G through J_x). The open
!> chains take the twists from the velocity maps (velocity_columns), the
!> others from acceleration passes. On the dome the velocity state the last
!> column leaves (the contact point moving over the curved ground) turns the
!> egg, so G's passes, acceleration maps at rest, see it unless the columns'
!> velocities are set back to rest (on the flat table that state has no
!> rotation and no curvature terms: G would agree without the rest).
!>
!> Tolerance: both routes sum the same products in another order and solve
!> the closure's J_x^T in both; the differences are rounding amplified by the
!> condition of J_x (up to ~1e4 here): 1e-12 of the largest entry for M and
!> P, 1e-10 for G and H (as test_closure_blocks); a missing mass, twist, cut
!> force or frame gives differences of order one.
program test_mass_twists
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use testing, only: check, finish_tests
  use geometry_tube, only: tube_surface_t, new_straight_tube
  use geometry_surface, only: surface_t
  use geometry_elementary, only: paraboloid_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t, LOADS_NONE
  use kinetostatics_models, only: sled_params_t, build_sled, fourbar_params_t, build_fourbar, fourbar_assembly
  use kinetostatics_force_law_factory, only: law_spec
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, CHAIN_LOOP
  use rider_model, only: rider_params_t, rider_layout_t, build_rider
  use io_input, only: input_text_t, load_input_file, input_from_text
  use io_contact_config, only: read_contact_config
  implicit none (type, external)

  !> The shipped egg on a fixed sphere of radius 1 m (its poles horizontal,
  !> away from the contact) instead of the table.
  character(len=*), parameter :: dome_input = &
    "&run scenario = 'contact' / &
    &&shape name = 'dome', kind = 'ellipsoid', a = 1.0, b = 1.0, c = 1.0, origin = 0.0, 0.0, -1.0, &
    &angles_deg = 90.0, 0.0, 0.0 / &
    &&shape name = 'egg', kind = 'ellipsoid', a = 0.025, b = 0.033, c = 0.025 / &
    &&body name = 'egg', mass = 0.08, solid_of = 'egg', position = 0.0, 0.0, 0.05, &
    &angles_deg = -90.0, 0.0, -103.0, angular_velocity = 0.0, 0.0, 150.0 / &
    &&contact name = 'egg_on_dome', body_1 = 'ground', shape_1 = 'dome', side_1 = 1, &
    &body_2 = 'egg', shape_2 = 'egg', side_2 = 1, friction = 'viscous_weight', mu = 0.3 /"

  call check_rider()
  call check_sled(.false., .false.)
  call check_sled(.true., .false.)
  call check_sled(.false., .true.)
  call check_fourbar()
  call check_contact('inputs/contact/egg.nml', .false., .true., 'egg, open chain')
  call check_contact('inputs/contact/egg.nml', .true., .false., 'egg, loop, Coulomb')
  call check_contact('inputs/contact/tower5.nml', .false., .false., 'tower of five, rolling')
  call check_contact('', .false., .true., 'egg on a dome, open chain')
  call finish_tests('test_mass_twists')

contains

  subroutine check_rider()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(tube_surface_t) :: tube
    type(status_t) :: st
    real(wp) :: q0(3)
    type(mechanism_workspace_t) :: work
    p%u0 = 5
    tube = new_straight_tube(0.5_wp, 15*pi/180, 20.0_wp, st)
    call build_rider(p, tube, m, lay, q0, st)
    call m%check_start(work, q0, st)
    call check(st%ok(), 'rider builds and closes: '//st%text())
    if (.not. st%ok()) return
    call compare(m, 0.0_wp, q0 + [0.0_wp, 0.05_wp, -0.03_wp], [3.0_wp, 0.4_wp, -0.2_wp], 'rider')
  end subroutine check_rider

  !> The bar in a paraboloid bowl, off its centre and turned, with Coulomb friction.
  subroutine check_sled(cut_force, darboux_loads)
    logical, intent(in) :: cut_force, darboux_loads
    type(sled_params_t) :: p
    class(surface_t), allocatable :: bowl
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: q0(3)
    character(len=40) :: label
    type(mechanism_workspace_t) :: work
    bowl = paraboloid_t(2.0_wp, 2.5_wp, 1.0_wp, st)
    p%friction = [law_spec('coulomb', 'mu', 0.2_wp)]
    p%front_normal_from_cut_force = cut_force
    p%loads_on_darboux_frames = darboux_loads
    q0 = [1.0_wp, 0.2_wp, 0.3_wp]
    call build_sled(p, bowl, q0, m, st)
    call m%check_start(work, q0, st)
    call check(st%ok(), 'sled builds and closes: '//st%text())
    if (.not. st%ok()) return
    label = 'sled, frame rule'
    if (cut_force) label = 'sled, cut-force rule'
    if (darboux_loads) label = trim(label)//', loads on K_D'
    call compare(m, 0.0_wp, q0, [0.1_wp, 1.2_wp, 0.5_wp], trim(label))
  end subroutine check_sled

  subroutine check_fourbar()
    type(fourbar_params_t) :: p
    type(mechanism_t) :: m
    type(status_t) :: st
    real(wp) :: beta0(2)
    type(mechanism_workspace_t) :: work
    call fourbar_assembly(p, 0.3_wp, 1, beta0, st)
    call build_fourbar(p, beta0, m, st)
    call m%check_start(work, [0.3_wp], st)
    call check(st%ok(), 'four-bar builds and closes: '//st%text())
    if (.not. st%ok()) return
    call compare(m, 0.0_wp, [0.3_wp], [2.0_wp], 'four-bar')
  end subroutine check_fourbar

  !> A shipped contact input (file = '': the egg on a dome), at its start moved by a few centimetres
  !> or radians in every coordinate (the loop with Coulomb friction instead of the open chain);
  !> `velocity_columns`: the twists' columns expected from the velocity maps (an open chain) rather
  !> than acceleration passes.
  subroutine check_contact(file, loop, velocity_columns, label)
    character(len=*), intent(in) :: file, label
    logical, intent(in) :: loop, velocity_columns
    type(input_text_t) :: input
    type(contact_system_t) :: system
    type(contact_model_t), target :: model
    type(status_t) :: st
    integer :: f, k
    if (len(file) > 0) then
      call load_input_file(file, input, st)
    else
      call input_from_text('egg on a dome', dome_input, input, st)
    end if
    call read_contact_config(input, system, st)
    if (loop) then
      system%contacts(1)%chain = CHAIN_LOOP
      system%contacts(1)%friction%kind = 'coulomb'
      call system%contacts(1)%friction%set('mu', [0.3_wp])
    end if
    call build_contact_model(system, model, st)
    call check(st%ok(), label//' built: '//st%text())
    if (.not. st%ok()) return
    associate (m => model%ode%mechanism)
      f = m%f
      call check(m%velocity_columns .eqv. velocity_columns, label//': the twists'' route')
      call compare(m, 0.0_wp, model%y0(1:f) + [(0.03_wp*sin(1.7_wp*k), k = 1, f)], &
                   model%y0(f + 1:f + m%ns) + [(0.5_wp*cos(0.9_wp*k), k = 1, m%ns)], label)
    end associate
  end subroutine check_contact

  !> M and G of `dynamics` at (t, q, s) against the inverse-dynamics passes.
  subroutine compare(m, t, q, s, label)
    type(mechanism_t), intent(inout) :: m
    real(wp), intent(in) :: t, q(:), s(:)
    character(len=*), intent(in) :: label
    type(status_t) :: st
    real(wp) :: a(size(s)), unit_s(size(s)), m_twists(size(s), size(s)), m_passes(size(s), size(s)), &
      rates(size(q))
    type(mechanism_workspace_t) :: work
    real(wp), allocatable :: g_twists(:, :), g_passes(:, :), p_twists(:, :), p_passes(:, :), h_twists(:, :), &
      h_passes(:, :)
    integer :: i, k, n_scaled
    call check(m%twist_route, label//': M from the twists')
    call m%set_recursion(0)   ! M and G are the dense path's (the tower's recursion forms neither: test_tree_dynamics)
    call m%dynamics(work, t, q, s, a, st)
    call check(st%ok(), label//': dynamics '//st%text())
    if (.not. st%ok()) return
    rates = work%rates   ! q' of (q, s), which the integrator reads after dynamics: no column may change it
    m_twists = work%mass
    g_twists = work%g_mat
    n_scaled = size(m%scaled_laws)
    p_twists = work%p_mat
    h_twists = work%h_mat
    allocate (g_passes(size(m%contacts), size(s)), p_passes(size(s), n_scaled), h_passes(size(m%contacts), n_scaled))
    do k = 1, n_scaled   ! the laws' loads are those of the state dynamics saw
      call m%inverse_dynamics(work, .false., .false., m%scaled_laws(k))
      p_passes(:, k) = work%gq
      call m%normal_forces(work, work%lambda, h_passes(:, k))
    end do
    call m%set_velocities(work, s)
    call check(all(work%rates == rates), label//': q'' after dynamics that of (q, s)')
    call m%set_velocities(work, 0*s)
    do i = 1, size(s)
      unit_s = 0
      unit_s(i) = 1
      call m%set_accelerations(work, unit_s)
      call m%inverse_dynamics(work, .true., .false., LOADS_NONE)
      m_passes(:, i) = -work%gq
      call m%normal_forces(work, work%lambda, g_passes(:, i))
    end do
    print '(a, 4(a, es9.2))', label, ': |M diff| ', maxval(abs(m_twists - m_passes)), ' of ', &
      maxval(abs(m_passes)), ', |G diff| ', maxval([0.0_wp, abs(g_twists - g_passes)]), ' of ', &
      maxval([0.0_wp, abs(g_passes)])
    call check(maxval(abs(m_twists - m_passes)) <= 1e-12_wp*maxval(abs(m_passes)), label//': M agrees')
    call check(all(m_twists == transpose(m_twists)), label//': M symmetric')
    if (size(m%contacts) > 0) &
      call check(maxval(abs(g_twists - g_passes)) <= 1e-10_wp*maxval(abs(g_passes)), label//': G agrees')
    if (n_scaled == 0) return
    print '(a, 4(a, es9.2))', label, ': |P diff| ', maxval(abs(p_twists - p_passes)), ' of ', &
      maxval(abs(p_passes)), ', |H diff| ', maxval(abs(h_twists - h_passes)), ' of ', maxval(abs(h_passes))
    call check(maxval(abs(p_twists - p_passes)) <= 1e-12_wp*maxval(abs(p_passes)), label//': P agrees')
    call check(maxval(abs(h_twists - h_passes)) <= 1e-10_wp*maxval(abs(h_passes)), label//': H agrees')
  end subroutine compare
end program test_mass_twists
