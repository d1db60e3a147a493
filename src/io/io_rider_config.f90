!> &rider: the rider (body, start, friction, drag; the rider layer's own
!> description, rider_params_t; the friction law of the registry, read as
!> &sled's, io_friction_config), its stall speed and the limits its ride is
!> judged against (docs/rider.md, "Input"). Everything is checked here, before
!> any work; what needs the slide (the start lies on it, the spheres fit in
!> the tube, the heels and back reach it) is checked when the rider is built.
!> A run with water and a rider has one gravity (read_ride_gravity).
module io_rider_config
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_text, only: format_integer
  use base_status, only: status_t
  use io_input, only: input_text_t, group_reader_t, open_group, format_real
  use rider_body, only: SEX_MALE, SEX_FEMALE
  use rider_model, only: rider_params_t, rider_default_mu, rider_coulomb_mu
  use kinetostatics_force_law_factory, only: law_spec
  use base_spec, only: spec_t
  use io_friction_config, only: friction_law_variables, friction_law_names, read_friction_law
  use rider_ride, only: ride_options_t
  use design_ride_evaluation, only: ride_limit_t, new_ride_limit, flight_quantity
  implicit none (type, external)
  private
  public :: read_rider_config, read_ride_gravity, require_coulomb_rider, open_rider_group, rider_friction_defaults, max_limits
  public :: read_limits

  integer, parameter :: max_limits = 20

contains

  !> The rider of &rider, its stall speed (options%min_speed; the other
  !> options are &solver's, kept) and its limits. `gravity`: the run's one
  !> gravity (a ride's, from read_ride_gravity), which &rider gravity can
  !> only repeat.
  subroutine read_rider_config(input, rider, options, limits, status, gravity)
    type(input_text_t), intent(in) :: input
    type(rider_params_t), intent(out) :: rider
    type(ride_options_t), intent(inout) :: options
    type(ride_limit_t), allocatable, intent(out) :: limits(:)
    type(status_t), intent(inout) :: status
    real(wp), intent(in), optional :: gravity(3)   ! m/s^2
    type(group_reader_t) :: r
    character(len=8) :: sex
    character(len=32) :: friction
    real(wp) :: heading_deg

    sex = 'male'
    friction = 'coulomb'
    heading_deg = 0
    associate (p => rider)
      call open_rider_group(input, r, status)
      call r%get('sex', sex, status)
      call r%get('mass', p%body%mass, status)
      call r%get('height', p%body%height, status)
      call r%get('com_height', p%body%com_height, status)
      call r%get('friction', friction, status, choices=friction_law_names())
      call r%get('drag', p%drag, status)
      call r%get('drag_radius', p%drag_radius, status)
      call r%get('water_density', p%water%density, status)
      call r%get('water_viscosity', p%water%kinematic_viscosity, status)
      call r%get('gravity', p%gravity, status)
      call r%get('u0', p%u0, status)
      call r%get('v0', p%v0, status)
      call r%get('heading0_deg', heading_deg, status)
      call r%get('speed0', p%speed0, status)
      call r%get('min_speed', options%min_speed, status)
      call r%get('may_fly', options%may_fly, status)
      if (options%may_fly) then
        call r%get('landing_restitution', options%landing%restitution, status)
        call r%get('landing_mu', options%landing%mu, status)
      else
        call r%refuse_given([character(len=19) :: 'landing_restitution', 'landing_mu'], &
                            'a ride without may_fly = .true. has no landing', status)
      end if
      if (.not. status%ok()) return
      ! the law at the three contacts, Coulomb's mu the rider's mu_D unless given
      p%friction%kind = trim(friction)
      call read_friction_law(r, trim(friction), p%friction, status, defaults=rider_friction_defaults())
      if (.not. status%ok()) return
      if (present(gravity)) p%gravity = gravity
      p%body%sex = merge(SEX_MALE, SEX_FEMALE, sex == 'male')
      p%heading0 = heading_deg*pi/180
      if (.not. norm2(p%gravity) > 0) then
        call r%invalid('gravity', format_real(p%gravity(1))//', '//format_real(p%gravity(2))//', '// &
                       format_real(p%gravity(3)), 'the felt accelerations are in multiples of |gravity|: it '// &
                       'must not be zero', status)
        return
      end if
    end associate

    call read_limits(r, norm2(rider%gravity), options%may_fly, limits, status)
  end subroutine read_rider_config

  !> The limits of the group `r` reads (&rider; &sled for a vehicle):
  !> limit_quantity, limit_unit, limit_min, limit_max, entries 1..n, each a
  !> known quantity with a unit and a bound (design_ride_evaluation);
  !> `gravity_magnitude` (m/s^2) defines 'g'; a flight's quantity needs
  !> `may_fly`.
  subroutine read_limits(r, gravity_magnitude, may_fly, limits, status)
    type(group_reader_t), intent(in) :: r
    real(wp), intent(in) :: gravity_magnitude
    logical, intent(in) :: may_fly
    type(ride_limit_t), allocatable, intent(out) :: limits(:)
    type(status_t), intent(inout) :: status
    character(len=32) :: quantity(max_limits), unit(max_limits)
    real(wp) :: minimum(max_limits), maximum(max_limits)
    logical :: has_quantity(max_limits), has_unit(max_limits), has_min(max_limits), has_max(max_limits)
    character(len=:), allocatable :: problem
    character(len=*), parameter :: count_text = 'at most 20 limits'
    integer :: n, k

    quantity = ''
    unit = ''
    minimum = 0
    maximum = 0
    allocate (limits(0))
    call r%get_parts('limit_quantity', quantity, count_text, status, given=has_quantity)
    call r%get_parts('limit_unit', unit, count_text, status, given=has_unit)
    call r%get_parts('limit_min', minimum, count_text, status, given=has_min)
    call r%get_parts('limit_max', maximum, count_text, status, given=has_max)
    if (.not. status%ok()) return
    ! limits: entries 1..n, each a known quantity with a unit and a bound
    n = count(has_quantity)
    if (any(has_quantity(n + 1:))) then
      call r%invalid('limit_quantity', r%written('limit_quantity'), 'list the limits without gaps, from the '// &
                     'first', status)
      return
    end if
    do k = n + 1, max_limits
      if (has_unit(k) .or. has_min(k) .or. has_max(k)) then
        call r%invalid('limit_unit, limit_min, limit_max ('//format_integer(k)//')', r%written('limit_unit'), &
                       'limit '//format_integer(k)//' has no limit_quantity', status)
        return
      end if
    end do
    deallocate (limits)
    allocate (limits(n))
    do k = 1, n
      if (.not. has_unit(k)) then
        call r%invalid('limit_unit('//format_integer(k)//')', '(not given)', 'every limit needs its unit, '// &
                       'e.g. ''g'', ''m/s'', ''m'', ''N'', ''deg''', status)
        return
      end if
      call new_ride_limit(quantity(k), unit(k), minimum(k), has_min(k), maximum(k), has_max(k), &
                          gravity_magnitude, limits(k), problem)
      if (len(problem) == 0 .and. flight_quantity(quantity(k)) .and. .not. may_fly) &
        problem = trim(quantity(k))//' limits a flight: it needs may_fly = .true. (without it a lift-off ends '// &
                  'the ride)'
      if (len(problem) > 0) then
        call r%invalid('limit_quantity, limit_unit ('//format_integer(k)//')', ''''//trim(quantity(k))//''', '''// &
                       trim(unit(k))//'''', problem, status)
        return
      end if
    end do
  end subroutine read_limits

  !> The rider's own defaults of its friction laws' parameters: Coulomb's mu
  !> is mu_D (thesis table 4.8).
  pure function rider_friction_defaults() result(spec)
    type(spec_t) :: spec
    spec = law_spec('coulomb', 'mu', rider_default_mu)
  end function rider_friction_defaults

  !> Opens &rider: its declared variables and the parameters of every
  !> friction law (io_friction_config).
  subroutine open_rider_group(input, r, status)
    type(input_text_t), intent(in) :: input
    type(group_reader_t), intent(out) :: r
    type(status_t), intent(inout) :: status
    call open_group(input, 'rider', r, status, also=friction_law_variables())
  end subroutine open_rider_group

  !> Refuses a rider friction law other than Coulomb (or 'none', where
  !> `none_allowed`) for `user`, which varies or fits Coulomb's mu (the
  !> sweep, identify_rider): `why` says so in the message.
  subroutine require_coulomb_rider(input, rider, none_allowed, why, status)
    type(input_text_t), intent(in) :: input
    type(rider_params_t), intent(in) :: rider
    logical, intent(in) :: none_allowed
    character(len=*), intent(in) :: why
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: r
    real(wp) :: mu
    logical :: coulomb
    if (.not. status%ok()) return
    call rider_coulomb_mu(rider, mu, coulomb)
    if (coulomb .and. (none_allowed .or. rider%friction%kind == 'coulomb')) return
    call open_rider_group(input, r, status)
    if (.not. status%ok()) return
    call r%invalid('friction', r%written('friction'), why//'; allowed: '// &
                   merge('''coulomb'', ''none''', '''coulomb''        ', none_allowed), status)
  end subroutine require_coulomb_rider

  !> The one gravity of a run with water and a rider (the ride, the sweep,
  !> identify_rider): &water and &rider share the variable (one
  !> declaration); given in one group it holds for both the water and the
  !> rider, given in both it must be the same there, else the run is refused.
  subroutine read_ride_gravity(input, gravity, status)
    type(input_text_t), intent(in) :: input
    real(wp), intent(out) :: gravity(3)   ! m/s^2
    type(status_t), intent(inout) :: status
    type(group_reader_t) :: water, rider
    real(wp) :: water_gravity(3), rider_gravity(3)
    gravity = [0.0_wp, 0.0_wp, -standard_gravity]
    water_gravity = gravity
    rider_gravity = gravity
    call open_group(input, 'water', water, status)
    call open_rider_group(input, rider, status)
    call water%get('gravity', water_gravity, status)
    call rider%get('gravity', rider_gravity, status)
    if (.not. status%ok()) return
    if (water%has('gravity') .and. rider%has('gravity')) then
      if (any(water_gravity /= rider_gravity)) then
        call rider%invalid('gravity', rider%written('gravity'), 'a ride has one gravity, and &water gives '// &
                           'gravity = '//water%written('gravity')//' ('//water%where('gravity')//'): give it '// &
                           'in one of the two groups, or the same in both', status)
        return
      end if
    end if
    if (water%has('gravity')) gravity = water_gravity
    if (rider%has('gravity')) gravity = rider_gravity
  end subroutine read_ride_gravity
end module io_rider_config
