!> Input groups of the multibody scenarios (&pendulum, &fourbar, &sled) with
!> their checks, and the writer of a mechanism's time series into a result file
!> (layout in docs/outputs.md).
module io_mechanism_config
  use base_kinds, only: wp
  use base_text, only: format_integer
  use base_constants, only: standard_gravity
  use base_status, only: status_t
  use numerics_ode, only: ode_stats_t
  use kinetostatics_models, only: pendulum_params_t, fourbar_params_t, sled_params_t
  use kinetostatics_recorder, only: mechanism_series_t
  use io_input, only: input_text_t, namelist_read_error, check_positive, check_nonnegative, &
    check_finite, check_finite_vector, check_range, invalid, format_real
  use io_hdf5, only: result_file_t, units_per_second
  implicit none (type, external)
  private
  public :: pendulum_config_t, read_pendulum_config, fourbar_config_t, read_fourbar_config
  public :: sled_config_t, read_sled_config, write_mechanism_series

  type :: pendulum_config_t
    type(pendulum_params_t) :: params
    real(wp) :: theta0(2) = [0.5_wp, 0.0_wp]    ! rad
    real(wp) :: dtheta0(2) = 0                  ! rad/s
  end type pendulum_config_t

  type :: fourbar_config_t
    type(fourbar_params_t) :: params
    real(wp) :: crank0 = 0                      ! rad
    real(wp) :: dcrank0 = 10                    ! rad/s
    integer :: branch = 1                       ! +1: C to the left of B->D, -1: right
  end type fourbar_config_t

  type :: sled_config_t
    type(sled_params_t) :: params
    real(wp) :: q0(3) = 0                       ! u0, v0 (surface parameters), phi0 (rad)
    real(wp) :: qd0(3) = 0                      ! their rates
  end type sled_config_t

contains

  subroutine read_pendulum_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(pendulum_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    integer :: links, ios, k
    real(wp) :: length(2), mass(2), inertia(2), gravity(3), theta0(2), dtheta0(2)
    character(len=256) :: msg
    character(len=*), parameter :: g = 'pendulum'
    namelist /pendulum/ links, length, mass, inertia, gravity, theta0, dtheta0

    links = 1
    length = 1; mass = 1; inertia = 0
    gravity = [0.0_wp, 0.0_wp, -standard_gravity]
    theta0 = config%theta0; dtheta0 = config%dtheta0
    read (input%lines, nml=pendulum, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=8) :: 'links', 'length', 'mass', 'inertia', &
                               'gravity', 'theta0', 'dtheta0'], status)
      return
    end if
    if (links < 1 .or. links > 2) then
      call invalid(input, g, 'links', format_integer(links), 'must be 1 or 2', status)
      return
    end if
    do k = 1, links
      call check_positive(input, g, 'length('//achar(48 + k)//')', length(k), 'm', status)
      call check_positive(input, g, 'mass('//achar(48 + k)//')', mass(k), 'kg', status)
      call check_nonnegative(input, g, 'inertia('//achar(48 + k)//')', inertia(k), 'kg m^2', status)
      call check_finite(input, g, 'theta0('//achar(48 + k)//')', theta0(k), status)
      call check_finite(input, g, 'dtheta0('//achar(48 + k)//')', dtheta0(k), status)
    end do
    call check_finite_vector(input, g, 'gravity', gravity, status)
    if (.not. status%ok()) return
    config%params%links = links
    config%params%length = length
    config%params%mass = mass
    config%params%inertia = inertia
    config%params%gravity = gravity
    config%theta0 = theta0
    config%dtheta0 = dtheta0
  end subroutine read_pendulum_config

  subroutine read_fourbar_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(fourbar_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    real(wp) :: a, b, c, d, mass(3), gravity(3), crank0, dcrank0
    integer :: branch, ios
    character(len=256) :: msg
    character(len=*), parameter :: g = 'fourbar'
    namelist /fourbar/ a, b, c, d, mass, gravity, crank0, dcrank0, branch

    a = config%params%a; b = config%params%b; c = config%params%c; d = config%params%d
    mass = config%params%mass; gravity = config%params%gravity
    crank0 = config%crank0; dcrank0 = config%dcrank0; branch = config%branch
    read (input%lines, nml=fourbar, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=8) :: 'a', 'b', 'c', 'd', 'mass', 'gravity', &
                               'crank0', 'dcrank0', 'branch'], status)
      return
    end if
    call check_positive(input, g, 'a', a, 'm', status)
    call check_positive(input, g, 'b', b, 'm', status)
    call check_positive(input, g, 'c', c, 'm', status)
    call check_positive(input, g, 'd', d, 'm', status)
    call check_positive(input, g, 'mass(1)', mass(1), 'kg', status)
    call check_positive(input, g, 'mass(2)', mass(2), 'kg', status)
    call check_positive(input, g, 'mass(3)', mass(3), 'kg', status)
    call check_finite_vector(input, g, 'gravity', gravity, status)
    call check_finite(input, g, 'crank0', crank0, status)
    call check_finite(input, g, 'dcrank0', dcrank0, status)
    if (status%ok() .and. abs(branch) /= 1) &
      call invalid(input, g, 'branch', format_integer(branch), 'must be +1 or -1', status)
    if (.not. status%ok()) return
    config%params = fourbar_params_t(a, b, c, d, mass, gravity)
    config%crank0 = crank0
    config%dcrank0 = dcrank0
    config%branch = branch
  end subroutine read_fourbar_config

  subroutine read_sled_config(input, config, status)
    type(input_text_t), intent(in) :: input
    type(sled_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    real(wp) :: length, mass, inertia(3), gravity(3), mu, viscous, regularization_speed, sigma, &
                alpha_u, alpha_v, u0, v0, phi0, du0, dv0, dphi0
    integer :: ios, k
    character(len=256) :: msg
    character(len=*), parameter :: g = 'sled'
    namelist /sled/ length, mass, inertia, gravity, mu, viscous, regularization_speed, sigma, alpha_u, &
      alpha_v, u0, v0, phi0, du0, dv0, dphi0

    length = config%params%length; mass = config%params%mass
    inertia = [(config%params%inertia(k, k), k = 1, 3)]
    gravity = config%params%gravity
    mu = 0; viscous = 0; regularization_speed = config%params%regularization_speed
    sigma = 1; alpha_u = 1; alpha_v = 0
    u0 = 0; v0 = 0; phi0 = 0; du0 = 0; dv0 = 0; dphi0 = 0
    read (input%lines, nml=sled, iostat=ios, iomsg=msg)
    if (ios > 0) then
      call namelist_read_error(input, g, msg, [character(len=20) :: 'length', 'mass', 'inertia', 'gravity', &
        'mu', 'viscous', 'regularization_speed', 'sigma', 'alpha_u', 'alpha_v', 'u0', 'v0', 'phi0', &
        'du0', 'dv0', 'dphi0'], status)
      return
    end if
    call check_positive(input, g, 'length', length, 'm', status)
    call check_positive(input, g, 'mass', mass, 'kg', status)
    call check_finite_vector(input, g, 'inertia', inertia, status)
    if (status%ok() .and. (minval(inertia) < 0 .or. 2*maxval(inertia) > sum(inertia))) &
      call invalid(input, g, 'inertia', format_real(inertia(1))//', '//format_real(inertia(2))//', '// &
                   format_real(inertia(3)), 'principal moments (kg m^2) must be >= 0 and each at most the '// &
                   'sum of the other two', status)
    if (status%ok() .and. inertia(2) + inertia(3) <= 0) &
      call invalid(input, g, 'inertia', format_real(inertia(1))//', '//format_real(inertia(2))//', '// &
                   format_real(inertia(3)), 'the bar needs inertia about y or z (pitch and heading)', status)
    call check_finite_vector(input, g, 'gravity', gravity, status)
    call check_range(input, g, 'mu', mu, 0.0_wp, 10.0_wp, '1', status)
    call check_nonnegative(input, g, 'viscous', viscous, 'N s/m', status)
    call check_positive(input, g, 'regularization_speed', regularization_speed, 'm/s', status)
    if (status%ok() .and. abs(sigma) /= 1) &
      call invalid(input, g, 'sigma', format_real(sigma), 'must be +1 or -1 (side of the normal)', status)
    call check_finite(input, g, 'alpha_u', alpha_u, status)
    call check_finite(input, g, 'alpha_v', alpha_v, status)
    if (status%ok() .and. alpha_u == 0 .and. alpha_v == 0) &
      call invalid(input, g, 'alpha_u, alpha_v', '0, 0', 'at least one must be non-zero', status)
    call check_finite(input, g, 'u0', u0, status)
    call check_finite(input, g, 'v0', v0, status)
    call check_finite(input, g, 'phi0', phi0, status)
    call check_finite(input, g, 'du0', du0, status)
    call check_finite(input, g, 'dv0', dv0, status)
    call check_finite(input, g, 'dphi0', dphi0, status)
    if (.not. status%ok()) return
    config%params%length = length
    config%params%mass = mass
    config%params%inertia = 0
    do k = 1, 3
      config%params%inertia(k, k) = inertia(k)
    end do
    config%params%gravity = gravity
    config%params%mu = mu
    config%params%viscous = viscous
    config%params%regularization_speed = regularization_speed
    config%params%sigma = sigma
    config%params%alpha_u = alpha_u
    config%params%alpha_v = alpha_v
    config%q0 = [u0, v0, phi0]
    config%qd0 = [du0, dv0, dphi0]
  end subroutine read_sled_config

  !> Writes /<scenario>/... (see docs/outputs.md).
  subroutine write_mechanism_series(file, scenario, input, title, s, stats, cpu, q_units, beta_units, status)
    type(result_file_t), intent(inout) :: file
    character(len=*), intent(in) :: scenario, title
    type(input_text_t), intent(in) :: input
    type(mechanism_series_t), intent(in) :: s
    type(ode_stats_t), intent(in) :: stats
    real(wp), intent(in) :: cpu
    character(len=*), intent(in) :: q_units(:)      ! of each generalized coordinate
    character(len=*), intent(in) :: beta_units(:)   ! of each dependent coordinate
    type(status_t), intent(inout) :: status
    character(len=:), allocatable :: g, b, residual_units
    integer :: n, k

    n = s%n
    g = '/'//scenario//'/'
    call file%write_provenance(scenario, trim(title), input%name, input%text(), status)
    call file%write_vector(g//'time', s%time(:n), 's', 'output times', status)
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
                             'body frame axes as columns, world coordinates (3 x 3 x n)', status)
      call file%write_matrix(b//'/velocity', s%body_v(:, k, :n), 'm/s', 'velocity of the origin (3 x n)', status)
      call file%write_matrix(b//'/angular_velocity', s%body_omega(:, k, :n), 'rad/s', &
                             'angular velocity (3 x n)', status)
    end do
    do k = 1, s%nc
      b = g//'contacts/'//trim(s%contact_names(k))
      call file%write_matrix(b//'/position', s%contact_r(:, k, :n), 'm', 'contact point (3 x n)', status)
      call file%write_matrix(b//'/velocity', s%contact_v(:, k, :n), 'm/s', 'sliding velocity (3 x n)', status)
      call file%write_vector(b//'/normal_force', s%normal(k, :n), 'N', &
                             'normal force on the body along the surface normal z_D', status)
      call file%write_matrix(b//'/friction_force', s%friction(:, k, :n), 'N', 'friction force (3 x n)', status)
    end do
    if (n > 0) then
      call file%make_scale(g//'time', status)
      call file%attach_scale(g//'time', g, status)
    end if
    call file%write_count('/statistics/steps', int(stats%steps), '1', 'integrator steps', status)
    call file%write_count('/statistics/rhs_evaluations', int(stats%rhs_evaluations), '1', &
                          'right-hand-side evaluations', status)
    call file%write_scalar('/statistics/cpu_time', cpu, 's', 'CPU time of the integration', status)
  end subroutine write_mechanism_series
end module io_mechanism_config
