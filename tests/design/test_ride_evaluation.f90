!> The ride evaluation: felt specific force in a body frame (rest, free fall,
!> the bottom of a dip, a banked turn), the tipping lever arm (E.3), limits
!> with units (conversions, wrong units, verdicts and where).
program test_ride_evaluation
  use base_kinds, only: wp
  use base_constants, only: standard_gravity
  use base_vector, only: rot_z, rot_x, cross
  use design_ride_evaluation, only: felt_acceleration, tipping_lever_arm, ride_limit_t, limit_verdict_t, &
    new_ride_limit, evaluate_limit, limit_report_unit, series_extreme
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  real(wp), parameter :: g(3) = [0.0_wp, 0.0_wp, -standard_gravity]
  real(wp), parameter :: eye(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])

  call check_felt()
  call check_lever_arm()
  call check_limits()
  call finish_tests('test_ride_evaluation')

contains

  subroutine check_felt()
    real(wp) :: axes(3, 3), v, radius, bank, f(3)
    ! rtol 1e-15: one subtraction and a division
    call check_close_array(felt_acceleration([0.0_wp, 0.0_wp, 0.0_wp], g, eye), [0.0_wp, 0.0_wp, 1.0_wp], &
                           1e-15_wp, 1e-16_wp, 'at rest: 1 g normal')
    call check_close_array(felt_acceleration(g, g, eye), [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 1e-16_wp, &
                           'free fall: weightless')
    ! bottom of a dip of radius 10 m at 5 m/s: 1 + v^2/(g R) in g
    v = 5
    radius = 10
    axes = matmul(rot_z(0.7_wp), eye)   ! heading does not matter for the normal
    f = felt_acceleration([0.0_wp, 0.0_wp, v**2/radius], g, axes)
    call check_close(f(3), 1 + v**2/(standard_gravity*radius), 1e-15_wp, 0.0_wp, 'dip: 1 + v^2/(g R)')
    ! a banked turn at the speed where the felt force is along the normal:
    ! tan(bank) = v^2/(g R); lateral 0, normal 1/cos(bank)
    bank = atan(v**2/(standard_gravity*radius))
    axes = rot_x(-bank)   ! body x along the travel (y world turns inward), z tilted towards the centre
    f = felt_acceleration([0.0_wp, v**2/radius, 0.0_wp], g, axes)
    call check_close(f(2), 0.0_wp, 0.0_wp, 1e-15_wp, 'balanced bank: no lateral force')
    call check_close(f(3), 1/cos(bank), 1e-15_wp, 0.0_wp, 'balanced bank: 1/cos(bank) normal')
    call check_close(f(1), 0.0_wp, 0.0_wp, 1e-16_wp, 'steady turn: no longitudinal force')
    ! braking at 0.3 g along the body x: felt -0.3 g longitudinal
    f = felt_acceleration([-0.3_wp*standard_gravity, 0.0_wp, 0.0_wp], g, eye)
    call check_close(f(1), -0.3_wp, 1e-15_wp, 0.0_wp, 'braking: longitudinal')
  end subroutine check_felt

  subroutine check_lever_arm()
    real(wp) :: n
    n = 600
    call check_close(tipping_lever_arm([10.0_wp, 0.0_wp, n], [0.12_wp*n, 3.0_wp, 7.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], &
                     [0.0_wp, 0.0_wp, 1.0_wp]), 0.12_wp, 1e-15_wp, 0.0_wp, 'lever arm = M_long / N')
    call check_close(tipping_lever_arm([0.0_wp, 0.0_wp, n], [-0.3_wp*n, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], &
                     [0.0_wp, 0.0_wp, 1.0_wp]), -0.3_wp, 1e-15_wp, 0.0_wp, 'lever arm keeps its sign')
    call check(tipping_lever_arm([0.0_wp, 0.0_wp, -1.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], &
               [0.0_wp, 0.0_wp, 1.0_wp]) == huge(1.0_wp), 'no pressing force: no lever arm')
    ! a cuboid (E.2) of width 0.5 m resting on a plane tilted sideways: it tips
    ! when the lever arm of its weight about the contact, CoM height 0.1 m,
    ! exceeds 0.25 m, i.e. tan(tilt) > 2.5 (static, no acceleration)
    associate (tilt => 1.2_wp, m => 90.0_wp)
      associate (normal => [0.0_wp, -sin(tilt), cos(tilt)], long => [1.0_wp, 0.0_wp, 0.0_wp])
        associate (f_r => -m*g, com => 0.1_wp*normal)
          ! reaction = -weight; its moment about D balances the weight's: M_r = -(com x m g)
          ! negative: the moment turns the body about -x (it would tip to the -y side)
          call check_close(tipping_lever_arm(f_r, -cross(com, m*g), long, normal), -0.1_wp*tan(tilt), 1e-14_wp, &
                           0.0_wp, 'static tilted cuboid: CoM height times tan(tilt)')
        end associate
      end associate
    end associate
  end subroutine check_lever_arm

  subroutine check_limits()
    type(ride_limit_t) :: limit
    type(limit_verdict_t) :: verdict
    character(len=:), allocatable :: problem
    real(wp) :: value, at
    call new_ride_limit('speed', 'km/h', 0.0_wp, .false., 36.0_wp, .true., standard_gravity, limit, problem)
    call check(problem == '', 'speed in km/h accepted')
    call check_close(limit%maximum, 10.0_wp, 1e-15_wp, 0.0_wp, '36 km/h = 10 m/s')
    call check(limit_report_unit('speed') == 'm/s', 'speeds reported in m/s')
    call new_ride_limit('acceleration_normal', 'm s-2', 0.0_wp, .false., 2*standard_gravity, .true., &
                        standard_gravity, limit, problem)
    call check_close(limit%maximum, 2.0_wp, 1e-15_wp, 0.0_wp, 'm s-2 to g')
    call new_ride_limit('speed', 'g', 0.0_wp, .false., 3.0_wp, .true., standard_gravity, limit, problem)
    call check(index(problem, 'unit ''g'' does not measure speed') > 0 .and. index(problem, 'm/s') > 0, &
               'a speed in g is refused: '//problem)
    call new_ride_limit('lever_arm', 'deg', 0.0_wp, .false., 3.0_wp, .true., standard_gravity, limit, problem)
    call check(index(problem, 'does not measure lever_arm') > 0, 'a lever arm in degrees is refused')
    call new_ride_limit('speeed', 'm/s', 0.0_wp, .false., 3.0_wp, .true., standard_gravity, limit, problem)
    call check(index(problem, 'unknown quantity') > 0 .and. index(problem, 'exit_speed') > 0, &
               'an unknown quantity is refused with the list')
    call new_ride_limit('acceleration_lateral', 'g', 1.0_wp, .true., -1.0_wp, .true., standard_gravity, limit, &
                        problem)
    call check(index(problem, 'minimum') > 0, 'minimum above maximum refused')
    call new_ride_limit('speed', 'm/s', 0.0_wp, .false., 0.0_wp, .false., standard_gravity, limit, problem)
    call check(index(problem, 'neither') > 0, 'a limit without bounds refused')

    ! verdicts: felt normal acceleration between -0.2 g and 2.5 g
    call new_ride_limit('acceleration_normal', 'g', -0.2_wp, .true., 2.5_wp, .true., standard_gravity, limit, &
                        problem)
    call evaluate_limit(limit, [1.0_wp, 2.0_wp, 2.7_wp, 3.1_wp, 1.0_wp, -0.5_wp], &
                        [0.0_wp, 5.0_wp, 10.0_wp, 15.0_wp, 20.0_wp, 25.0_wp], verdict)
    call check(verdict%exceeded, 'limit exceeded')
    call check_close(verdict%first_where, 10.0_wp, 0.0_wp, 0.0_wp, 'first exceeded at 10 m')
    call check_close(verdict%worst, 3.1_wp, 0.0_wp, 0.0_wp, 'worst value 3.1 g')
    call check_close(verdict%worst_where, 15.0_wp, 0.0_wp, 0.0_wp, 'worst at 15 m')
    call check_close(verdict%excess, 0.6_wp, 1e-14_wp, 0.0_wp, 'by 0.6 g')
    call evaluate_limit(limit, [1.0_wp, 2.0_wp, 0.1_wp], [0.0_wp, 5.0_wp, 10.0_wp], verdict)
    call check(.not. verdict%exceeded .and. verdict%first_where < 0, 'within the limit')
    call check_close(verdict%worst, 0.1_wp, 0.0_wp, 0.0_wp, 'closest to a bound: 0.1 g (0.3 above -0.2)')
    call series_extreme([1.0_wp, 4.0_wp, 2.0_wp], [0.0_wp, 1.0_wp, 2.0_wp], .true., value, at)
    call check(value == 4 .and. at == 1, 'largest and where')
    call series_extreme([1.0_wp, 4.0_wp, 2.0_wp], [0.0_wp, 1.0_wp, 2.0_wp], .false., value, at)
    call check(value == 1 .and. at == 0, 'smallest and where')
  end subroutine check_limits
end program test_ride_evaluation
