!> Input groups of the multibody scenarios (&pendulum, &fourbar, &sled) with
!> their checks, read into their descriptions (kinetostatics_models builds
!> them: build_pendulum_model, ...), and the writer of a mechanism's time
!> series into a result file (layout in docs/outputs.md).
module io_mechanism_config
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use base_text, only: format_integer
  use numerics_ode, only: ode_stats_t
  use kinetostatics_models, only: pendulum_description_t, fourbar_description_t, sled_description_t
  use rider_vehicle, only: vehicle_t, vehicle_kinds, vehicle_kind_index, vehicle_problem, VEHICLE_BAR, VEHICLE_MAT, &
    VEHICLE_RING, VEHICLE_DOUBLE_RING, VEHICLE_RAFT, max_riders
  use kinetostatics_recorder, only: mechanism_series_t
  use base_spec, only: spec_t
  use io_input, only: input_text_t, group_reader_t, open_group, format_real, format_vector
  use io_friction_config, only: friction_law_variables, friction_law_names, read_friction_law
  use io_hdf5, only: result_file_t, units_per_second
  implicit none (type, external)
  private
  public :: read_pendulum_config, read_fourbar_config, read_sled_config, write_mechanism_series

  !> a vehicle's own parts (&sled), each kind's: refused on another kind
  character(len=*), parameter :: mat_parts(4) = [character(len=13) :: 'mat_length', 'mat_width', 'mat_thickness', &
                                                 'mat_mass']
  character(len=*), parameter :: ring_parts(2) = [character(len=13) :: 'ring_radii', 'ring_mass']
  character(len=*), parameter :: raft_parts(3) = [character(len=13) :: 'raft_radii', 'raft_mass', 'raft_floor']

contains

  subroutine read_pendulum_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(pendulum_description_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    integer :: n

    config%params%links = 1
    config%params%length = 1; config%params%mass = 1; config%params%inertia = 0
    config%params%gravity = [0.0_wp, 0.0_wp, -standard_gravity]
    call open_group(input, 'pendulum', r, status)
    call r%get('links', config%params%links, status)
    if (.not. status%ok()) return
    n = config%params%links
    call r%get_parts('length', config%params%length(:n), 'links = '//digit(n), &
                     status)
    call r%get_parts('mass', config%params%mass(:n), 'links = '//digit(n), status)
    call r%get_parts('inertia', config%params%inertia(:n), &
                     'links = '//digit(n), status)
    call r%get_parts('theta0', config%theta0(:n), 'links = '//digit(n), status)
    call r%get_parts('dtheta0', config%dtheta0(:n), 'links = '//digit(n), &
                     status)
    call r%get('gravity', config%params%gravity, status)
  end subroutine read_pendulum_config

  subroutine read_fourbar_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(fourbar_description_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r

    call open_group(input, 'fourbar', r, status)
    call r%get('a', config%params%a, status)
    call r%get('b', config%params%b, status)
    call r%get('c', config%params%c, status)
    call r%get('d', config%params%d, status)
    call r%get('mass', config%params%mass, status)
    call r%get('gravity', config%params%gravity, status)
    call r%get('crank0', config%crank0, status)
    call r%get('dcrank0', config%dcrank0, status)
    call r%get('branch', config%branch, status)
    if (status%ok() .and. config%branch == 0) call r%invalid('branch', '0', 'must be +1 or -1', status)
  end subroutine read_fourbar_config

  !> &sled into the sled's description and, given `vehicle`, the vehicle
  !> that replaces its bar (vehicle = 'bar': none; rider_vehicle's
  !> build_vehicle_model builds both); without `vehicle` a vehicle is refused.
  subroutine read_sled_config(input, config, status, vehicle)
    type(input_text_t), intent(in) :: input
    type(sled_description_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    type(vehicle_t), intent(out), optional :: vehicle
    type(vehicle_t) :: given
    real(wp) :: inertia(3), u0, v0, phi0, du0, dv0, dphi0
    type(group_reader_t) :: r
    character(len=32) :: friction
    character(len=16) :: kind, water
    type(spec_t) :: law
    integer :: k

    inertia = [(config%params%inertia(k, k), k = 1, 3)]
    config%params%sigma = 1; config%params%alpha_u = 1; config%params%alpha_v = 0
    u0 = 0; v0 = 0; phi0 = 0; du0 = 0; dv0 = 0; dphi0 = 0
    friction = 'none'
    call open_group(input, 'sled', r, status, also=friction_law_variables())
    call r%get('length', config%params%length, status)
    call r%get('mass', config%params%mass, status)
    call r%get('inertia', inertia, status)
    call r%get('gravity', config%params%gravity, status)
    call r%get('friction', friction, status, choices=friction_law_names())
    call read_friction_law(r, trim(friction), law, status)
    if (friction /= 'none') config%params%friction = [law]
    call r%get('sigma', config%params%sigma, status)
    call r%get('alpha_u', config%params%alpha_u, status)
    call r%get('alpha_v', config%params%alpha_v, status)
    call r%get('u0', u0, status)
    call r%get('v0', v0, status)
    call r%get('phi0', phi0, status)
    call r%get('du0', du0, status)
    call r%get('dv0', dv0, status)
    call r%get('dphi0', dphi0, status)
    kind = 'bar'
    call r%get('vehicle', kind, status, choices=vehicle_kinds)
    given%kind = vehicle_kind_index(trim(kind))
    if (status%ok() .and. given%kind == VEHICLE_BAR) then
      call r%refuse_given([character(len=13) :: 'riders', 'scale', 'scales', mat_parts, ring_parts, raft_parts], &
                          'they describe a vehicle: give vehicle too', status)
    else if (status%ok() .and. .not. present(vehicle)) then
      call r%invalid('vehicle', trim(kind), 'this program rides the bar only (''bar'')', status)
    else if (status%ok()) then
      call r%refuse_given([character(len=7) :: 'length', 'mass', 'inertia'], 'the vehicle '''//trim(kind)// &
                          ''' has them from its riders and scale (docs/vehicles.md)', status)
      call read_vehicle(r, trim(kind), given, status)
    end if
    ! the water (docs/vehicles.md, "In the water"): a vehicle rides in the
    ! computed water unless water = 'dry' says otherwise; the bar rides dry
    water = trim(merge('computed', 'dry     ', given%kind /= VEHICLE_BAR))
    call r%get('water', water, status, choices=[character(len=8) :: 'computed', 'dry'])
    given%in_water = water == 'computed'
    call r%get('water_density', given%water%density, status)
    call r%get('water_viscosity', given%water%kinematic_viscosity, status)
    if (status%ok() .and. given%in_water .and. given%kind == VEHICLE_BAR) then
      call r%invalid('water', '''computed''', 'the water''s drag acts on a vehicle''s contacts (docs/vehicles.md); '// &
                     'the bar rides dry', status)
    else if (status%ok() .and. .not. given%in_water) then
      call r%refuse_given([character(len=15) :: 'water_density', 'water_viscosity'], 'they describe the water''s '// &
                          'drag, and the sled rides dry (water = ''dry'')', status)
    else if (status%ok() .and. .not. (given%water%density > 0 .and. given%water%kinematic_viscosity > 0)) then
      call r%invalid('water_density, water_viscosity', format_real(given%water%density)//', '// &
                     format_real(given%water%kinematic_viscosity), 'both must be > 0 (kg/m^3, m^2/s)', status)
    end if
    ! flight (docs/vehicles.md, "Flight"): a vehicle's lift-off opens its
    ! contact; the landings' law, Coulomb's mu the friction's unless given
    call r%get('may_fly', given%may_fly, status)
    if (status%ok() .and. given%may_fly .and. given%kind == VEHICLE_BAR) then
      call r%invalid('may_fly', '.true.', 'a vehicle flies (docs/vehicles.md, "Flight"); the bar''s lift-off ends '// &
                     'its run: give vehicle', status)
    else if (status%ok() .and. given%may_fly) then
      given%landing%mu = 0
      if (allocated(law%values)) then
        if (law%has('mu')) given%landing%mu = law%value('mu')
      end if
      call r%get('landing_restitution', given%landing%restitution, status)
      call r%get('landing_mu', given%landing%mu, status)
    else if (status%ok()) then
      call r%refuse_given([character(len=19) :: 'landing_restitution', 'landing_mu'], &
                          'a vehicle without may_fly = .true. has no landing', status)
    end if
    if (present(vehicle)) vehicle = given
    call r%get('drag_area', config%params%drag_area, status)
    call r%get('air_density', config%params%air_density, status)
    call r%get('wind', config%params%wind, status)
    if (status%ok() .and. config%params%drag_area == 0) call r%refuse_given([character(len=11) :: 'air_density', &
      'wind'], 'the air is for the sled''s drag: give drag_area (C_d A) too', status)
    if (.not. status%ok()) return
    if (2*maxval(inertia) > sum(inertia)) then
      call r%invalid('inertia', format_vector(inertia), 'principal moments (kg m^2) must be >= 0 and each at '// &
                     'most the sum of the other two', status)
    else if (inertia(2) + inertia(3) <= 0) then
      call r%invalid('inertia', format_vector(inertia), 'the bar needs inertia about y or z (pitch and heading)', &
                     status)
    else if (abs(config%params%sigma) /= 1) then
      call r%invalid('sigma', format_real(config%params%sigma), 'must be +1 or -1 (side of the normal)', status)
    else if (config%params%alpha_u == 0 .and. config%params%alpha_v == 0) then
      call r%invalid('alpha_u, alpha_v', '0, 0', 'at least one must be non-zero', status)
    end if
    if (.not. status%ok()) return
    config%params%inertia = 0
    do k = 1, 3
      config%params%inertia(k, k) = inertia(k)
    end do
    config%q0 = [u0, v0, phi0]
    config%qd0 = [du0, dv0, dphi0]
  end subroutine read_sled_config

  !> A vehicle's riders, their sizes and the vehicle's own parts (&sled
  !> riders, scale, scales, mat_*, ring_*, raft_*; docs/vehicles.md, "The
  !> input") into `v` (its kind set): a part of another kind of vehicle is
  !> refused, each value checked (rider_vehicle's vehicle_problem).
  subroutine read_vehicle(r, kind, v, status)
    type(group_reader_t), intent(in) :: r
    character(len=*), intent(in) :: kind
    type(vehicle_t), intent(inout) :: v
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: variable, value, allowed
    real(wp) :: scale
    logical :: each(max_riders)
    call r%get('riders', v%riders, status)
    if (status%ok()) then
      call vehicle_problem(vehicle_t(kind=v%kind, riders=v%riders), variable, value, allowed)
      if (variable == 'riders') call r%invalid('riders', value, allowed, status)
    end if
    scale = 1
    each = .false.
    call r%get('scale', scale, status)
    v%scales = scale
    if (status%ok()) call r%get_parts('scales', v%scales(:v%riders), 'riders = '//format_integer(v%riders), status, &
                                      given=each(:v%riders))
    if (status%ok() .and. all(each(:v%riders))) &
      call r%refuse_given(['scale'], 'scales gives every rider''s size (scale is for those it does not give)', status)
    if (v%kind /= VEHICLE_MAT) call r%refuse_given(mat_parts, 'the vehicle '''//kind//''' has no mat (vehicle = '// &
                                                   '''mat'' only)', status)
    if (v%kind /= VEHICLE_RING .and. v%kind /= VEHICLE_DOUBLE_RING) &
      call r%refuse_given(ring_parts, 'the vehicle '''//kind//''' has no ring (vehicle = ''ring'' or '// &
                          '''double_ring'' only)', status)
    if (v%kind /= VEHICLE_RAFT) call r%refuse_given(raft_parts, 'the vehicle '''//kind//''' is not a raft '// &
                                                    '(vehicle = ''raft'' only)', status)
    call r%get('mat_length', v%mat_size(1), status)
    call r%get('mat_width', v%mat_size(2), status)
    call r%get('mat_thickness', v%mat_size(3), status)
    call r%get('mat_mass', v%mat_mass, status)
    call r%get('ring_radii', v%ring_radii, status)
    call r%get('ring_mass', v%ring_mass, status)
    call r%get('raft_radii', v%raft_radii, status)
    call r%get('raft_mass', v%raft_mass, status)
    call r%get('raft_floor', v%raft_floor, status)
    if (.not. status%ok()) return
    call vehicle_problem(v, variable, value, allowed)
    if (len(variable) > 0) call r%invalid(variable, value, allowed, status)
  end subroutine read_vehicle

  pure function digit(k) result(text)
    integer, intent(in) :: k
    character(len=1) :: text
    text = achar(48 + k)
  end function digit

  !> Writes /<scenario>/... (see docs/outputs.md).
  subroutine write_mechanism_series(file, scenario, input, title, s, outcome, stats, cpu, q_units, beta_units, status, &
                                    losses)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: scenario, title, outcome
    type(input_text_t), intent(in) :: input
    type(mechanism_series_t), intent(in) :: s
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: q_units(:)      ! of each generalized coordinate
    character(len=*), intent(in) :: beta_units(:)   ! of each dependent coordinate
    type(status_t), intent(inout) :: status
    real(wp), intent(in) :: losses(:)   ! J, the energy impacts removed up to each record (0: none)
    character(len=:), allocatable :: g, b, residual_units
    integer :: n, k

    n = s%n
    g = '/'//scenario//'/'
    call file%write_provenance(scenario, trim(title), input%name, input%text(), status)
    call file%write_vector(g//'time', s%time(:n), 's', 'record times: the start, the output times and the events', &
                           status)
    call file%write_integers(g//'record_kind', s%kind(:n), '1', &
                             'why each record was made: 1 start, 2 output time, 3 event', status)
    call file%set_attribute(g, 'outcome', outcome, status)
    do k = 1, s%f
      b = g//'coordinates/'//trim(s%q_names(k))
      call file%write_vector(b//'/value', s%q(k, :n), trim(q_units(k)), 'generalized coordinate', status)
      call file%write_vector(b//'/rate', s%qd(k, :n), units_per_second(trim(q_units(k))), 'its time derivative', &
                             status)
      call file%write_vector(b//'/acceleration', s%qdd(k, :n), units_per_second(trim(q_units(k)), 2), &
                             'its second time derivative', status)
    end do
    do k = 1, s%r
      call file%write_vector(g//'dependent/'//trim(s%beta_names(k)), s%beta(k, :n), &
                             trim(beta_units(k)), 'dependent coordinate fixed by the closure', status)
      call file%write_vector(g//'cut_forces/'//trim(s%closure_names(k)), s%lambda(k, :n), &
                             'N', 'cut force lambda of the closure measurement (plane-point)', status)
    end do
    if (s%r > 0) call file%write_vector(g//'closure_residual', s%closure(:n), 'm', &
                                        'max |g - target| over the closure measurements', status)
    do k = 1, s%nm
      call file%write_vector(g//'measurements/'//trim(s%monitor_names(k)), s%monitor(k, :n), &
                             trim(s%monitor_units(k)), 'a measurement watched during the run', status)
    end do
    call file%write_vector(g//'kinetic_energy', s%kinetic(:n), 'J', 'kinetic energy of all bodies', status)
    call file%write_vector(g//'potential_energy', s%potential(:n), 'J', 'potential energy -m g.r_S', status)
    call file%write_vector(g//'energy', s%kinetic(:n) + s%potential(:n), 'J', 'kinetic + potential', status)
    ! generalized forces are N m along angles and N along lengths
    if (all(q_units == 'rad')) then
      residual_units = 'N m'
    else if (all(q_units == 'm')) then
      residual_units = 'N'
    else
      residual_units = '1'
    end if
    call file%write_vector(g//'dynamics_residual', s%residual(:n), residual_units, &
      'max |Q_bar| of the inverse dynamics at the recorded state (a consistency check, ~0); '// &
      'units 1: the coordinates mix angles (N m) and lengths (N)', status)
    do k = 1, s%nb
      b = g//'bodies/'//trim(s%body_names(k))
      call file%write_matrix(b//'/position', s%body_r(:, k, :n), 'm', 'origin of the body frame (3 x n)', status)
      call file%write_array3(b//'/rotation', s%body_rot(:, :, k, :n), '1', &
                             'body axes in world coordinates: rotation[i, k, :] is body axis k (0 x, 1 y, 2 z) '// &
                             'at sample i as h5py reads it (a row; the columns of the 3 x 3 x n Fortran array)', status)
      call file%write_matrix(b//'/velocity', s%body_v(:, k, :n), 'm/s', 'velocity of the origin (3 x n)', status)
      call file%write_matrix(b//'/angular_velocity', s%body_omega(:, k, :n), 'rad/s', &
                             'angular velocity (3 x n)', status)
    end do
    do k = 1, s%nc
      b = g//'contacts/'//trim(s%contact_names(k))
      call file%write_matrix(b//'/position', s%contact_r(:, k, :n), 'm', 'contact point (3 x n)', status)
      call file%write_matrix(b//'/velocity', s%slip(:, k, :n), 'm/s', &
        'slip velocity: material velocity of the body relative to the surface at the contact point (3 x n)', status)
      call file%write_vector(b//'/normal_force', s%normal(k, :n), 'N', &
                             'normal force, positive while the body presses on the surface', status)
      call file%write_matrix(b//'/friction_force', s%friction(:, k, :n), 'N', &
                             'force of the contact''s friction laws on the body (3 x n)', status)
    end do
    do k = 1, s%nl
      b = g//'laws/'//trim(s%law_names(k))
      call file%write_matrix(b//'/force', s%law_force(:, k, :n), 'N', &
                             'force of the law (on the body, at a contact) (3 x n)', status)
      call file%write_vector(b//'/power', s%law_power(k, :n), 'W', 'power of the law''s loads', status)
      call file%write_vector(b//'/work', s%law_work(k, :n), 'J', &
                             'work of the law''s loads since the start (integrated with the motion)', status)
      call file%write_vector(b//'/active', s%law_active(k, :n), '1', '1 while the law acts, 0 when off', status)
    end do
    if (s%nl > 0 .and. .not. any(losses(:n) > 0)) call file%write_vector(g//'energy_balance', s%kinetic(:n) + &
      s%potential(:n) - s%kinetic(1) - s%potential(1) - sum(s%law_work(:, :n), dim=1), 'J', &
      'E(t) - E(0) - (work of all force laws): zero up to the integrator''s error', status)
    if (any(losses(:n) > 0)) call file%write_vector(g//'energy_balance', s%kinetic(:n) + &
      s%potential(:n) - s%kinetic(1) - s%potential(1) - sum(s%law_work(:, :n), dim=1) + losses(:n), 'J', &
      'E(t) - E(0) - (work of all force laws) + (energy the impacts removed, /contact/impacts): zero up to '// &
      'the integrator''s error', status)
    if (n > 0) then
      call file%make_scale(g//'time', status)
      call file%attach_scale(g//'time', g, status)
      call file%attach_components(g, status)
    end if
    call file%write_count('/statistics/steps', int(stats%steps), '1', 'integrator steps', status)
    call file%write_count('/statistics/rhs_evaluations', int(stats%rhs_evaluations), '1', &
                          'right-hand-side evaluations', status)
    call file%write_scalar('/statistics/cpu_time', cpu, 's', &
                           'CPU time of the run through the integration driver (integration, events, records)', status)
  end subroutine write_mechanism_series
end module io_mechanism_config
