!> An oscillator for test_dense_extremes: y = (sin t, cos t), its records and
!> its dense output.
module test_dense_extremes_systems
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_event_driver, only: event_system_t, RECORD_EVENT
  use numerics_dense_extremes, only: dense_extremes_t, dense_quantities_t
  implicit none (type, external)
  private
  public :: oscillator_t, sine_quantities_t

  !> Quantities of y: (1) y1 = sin t, (2) -y1, (3) -|y1 - 1/2| (a kink at
  !> t = pi/6, 5 pi/6); attached: y1 and t.
  type, extends(dense_quantities_t) :: sine_quantities_t
  contains
    procedure :: evaluate => sine_evaluate
  end type sine_quantities_t

  type, extends(event_system_t) :: oscillator_t
    integer :: n = 0
    real(wp) :: time(1000) = 0, state(2, 1000) = 0
    logical :: locate = .true.               ! feed the records and steps to `extremes`
    type(dense_extremes_t) :: extremes
    type(sine_quantities_t) :: quantities
  contains
    procedure :: rhs => oscillator_rhs
    procedure :: record => oscillator_record
    procedure :: observe_step => oscillator_observe_step
  end type oscillator_t

contains

  subroutine sine_evaluate(self, t, y, context, values, attached, status)
    class(sine_quantities_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(in) :: context(:)
    real(wp), intent(out) :: values(:), attached(:, :)
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_c => context, unused_s => status)
    end associate
    values = [y(1), -y(1), -abs(y(1) - 0.5_wp)]
    attached(1, :) = y(1)
    attached(2, :) = t
  end subroutine sine_evaluate

  subroutine oscillator_rhs(self, t, y, ydot, status)
    class(oscillator_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: ydot(:)
    type(status_t), intent(inout) :: status
    associate (unused => self, unused_t => t, unused_s => status)
    end associate
    ydot = [y(2), -y(1)]
  end subroutine oscillator_rhs

  subroutine oscillator_record(self, t, y, kind, status)
    class(oscillator_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    real(wp) :: values(3), attached(2, 3)
    self%n = self%n + 1
    self%time(self%n) = t
    self%state(:, self%n) = y
    if (.not. self%locate) return
    call self%quantities%evaluate(t, y, [0.0_wp], values, attached, status)
    if (.not. status%ok()) return
    call self%extremes%add_record(t, kind == RECORD_EVENT, [0.0_wp], values, attached)
  end subroutine oscillator_record

  subroutine oscillator_observe_step(self, t_n, h, taylor, status)
    class(oscillator_t), intent(inout) :: self
    real(wp), intent(in) :: t_n, h, taylor(:, 0:)
    type(status_t), intent(inout) :: status
    associate (unused => status)
    end associate
    if (self%locate) call self%extremes%add_piece(t_n, h, taylor)
  end subroutine oscillator_observe_step
end module test_dense_extremes_systems

!> The extremes located on the integrator's dense output
!> (numerics_dense_extremes): a maximum and a minimum of sin t and a kinked
!> maximum between records 0.3 s apart, against their closed forms; the
!> driver's step-by-step observation leaves the records unchanged.
program test_dense_extremes
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive
  use numerics_ode, only: ode_options_t
  use testing, only: check, check_close, finish_tests
  use test_dense_extremes_systems, only: oscillator_t
  implicit none (type, external)

  call sine_extremes()
  call records_unchanged()
  call finish_tests('test_dense_extremes')

contains

  subroutine run(system, rtol)
    type(oscillator_t), intent(inout), target :: system
    real(wp), intent(in) :: rtol
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: status
    options%ode = ode_options_t(rtol=rtol, atol=rtol)
    options%t_end = 6
    options%output_step = 0.3_wp
    call system%extremes%start(2, 3, 2, 1)
    call drive(system, [0.0_wp, 1.0_wp], options, result, status)
    call check(status%ok(), 'oscillator run: '//status%text())
    call system%extremes%finish(system%quantities, status)
    call check(status%ok(), 'extremes finish: '//status%text())
  end subroutine run

  !> sin t on [0, 6] sampled every 0.3 s: the records' largest value is
  !> sin(1.5) = 0.99749 (2.5e-3 below 1), their smallest sin(4.8) = -0.99616;
  !> located on the dense output (rtol 1e-12: the interpolated state is good
  !> to ~1e-11) the maximum is 1 at pi/2 and the minimum -1 at 3 pi/2, the
  !> values to 1e-10 and the times to 1e-5 s (a smooth extreme's time is
  !> only as good as the square root of its value's error). The kinked
  !> maximum of -|sin t - 1/2| (0 at pi/6, records: -0.065 at 0.6 s) is 0 to
  !> its slope (0.87) times the search's time tolerance: within 1e-9.
  subroutine sine_extremes()
    type(oscillator_t), target :: system
    system%observes_steps = .true.
    call run(system, 1e-12_wp)
    call check(maxval(system%state(1, :system%n)) < 0.998_wp, 'the records miss the maximum (test set-up)')
    call check_close(system%extremes%best(1), 1.0_wp, 0.0_wp, 1e-10_wp, 'sin t: located maximum')
    call check_close(system%extremes%best_t(1), pi/2, 0.0_wp, 1e-5_wp, 'sin t: time of the maximum')
    call check_close(system%extremes%best_attached(2, 1), system%extremes%best_t(1), 0.0_wp, 0.0_wp, &
                     'sin t: attached time is the maximum''s')
    call check_close(system%extremes%best_attached(1, 2), -1.0_wp, 0.0_wp, 1e-10_wp, 'sin t: located minimum')
    call check_close(system%extremes%best_t(2), 3*pi/2, 0.0_wp, 1e-5_wp, 'sin t: time of the minimum')
    call check(abs(system%extremes%best(3)) < 1e-9_wp, 'kinked maximum of -|sin t - 1/2| located')
    call check_close(system%extremes%best_t(3), pi/6, 0.0_wp, 1e-8_wp, 'time of the kink')
    call check(system%extremes%searches > 0 .and. system%extremes%searches <= 6, 'few brackets searched')
  end subroutine sine_extremes

  !> Observing every step (CVODE returning after each) takes the same steps
  !> as one call per output: the records are the same to the bit.
  subroutine records_unchanged()
    type(oscillator_t), target :: observed, plain
    observed%observes_steps = .true.
    plain%observes_steps = .false.
    plain%locate = .false.
    call run(observed, 1e-10_wp)
    call run(plain, 1e-10_wp)
    call check(observed%n == plain%n, 'as many records observed as not')
    call check(all(observed%time(:plain%n) == plain%time(:plain%n)) .and. &
               all(observed%state(:, :plain%n) == plain%state(:, :plain%n)), &
               'records to the bit the same when every step is observed')
  end subroutine records_unchanged
end program test_dense_extremes
