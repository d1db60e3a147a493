!> The no-slip constraint element (contact_rolling) along random motions of
!> the two bodies and the contact frame (element_checks): the second rates of
!> its outputs against differences of their rates, and the power of the static
!> friction force it applies, lambda . c = sum of wrenches . twists. Its rates
!> are the tangential slip (3.87), checked against the material velocities.
program test_no_slip
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross
  use testing, only: check, finish_tests
  use element_checks, only: check_element, frame_motion
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use contact_rolling, only: no_slip_t, new_no_slip
  implicit none (type, external)

  real(wp), parameter :: times(3) = [0.0_wp, 0.37_wp, -0.81_wp]
  integer :: trial

  do trial = 1, size(times)
    call check_element('no-slip constraint', new_no_slip('roll', 1, 2, 3, [1, 2]), [1, 2, 3], [integer ::], &
                       [integer ::], [1, 2], times(trial), rates_only=.true.)
  end do
  call slip_values()
  call finish_tests('test_no_slip')

contains

  !> c_x, c_y = x_P, y_P . (velocity of B's material point at p - A's).
  subroutine slip_values()
    type(no_slip_t) :: e
    type(frame_state_t) :: frames(3)
    type(scalar_state_t) :: scalars(2)
    type(status_t) :: st
    real(wp) :: w(3)
    e = new_no_slip('roll', 1, 2, 3, [1, 2])
    call frame_motion(1, 0.2_wp, frames(1))
    call frame_motion(2, 0.2_wp, frames(2))
    call frame_motion(3, 0.2_wp, frames(3))
    call e%position(frames, scalars, st)
    call e%velocity(frames, scalars)
    associate (a => frames(1), b => frames(2), p => frames(3))
      w = (b%v + cross(b%omega, p%r - b%r)) - (a%v + cross(a%omega, p%r - a%r))
      call check(abs(scalars(1)%qd - dot_product(p%rot(:, 1), w)) <= 1e-14_wp*norm2(w) .and. &
                 abs(scalars(2)%qd - dot_product(p%rot(:, 2), w)) <= 1e-14_wp*norm2(w), &
                 'no-slip outputs are the tangential slip components')
    end associate
  end subroutine slip_values
end program test_no_slip
