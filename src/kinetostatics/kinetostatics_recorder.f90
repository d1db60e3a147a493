!> Time series of a mechanism's run and the integration loop that fills them:
!> coordinates and their rates, every body's frame (the frame of each mass
!> element), closure residual and cut forces, energies, contact forces, and the
!> inverse-dynamics residual (a consistency check of every recorded state).
module kinetostatics_recorder
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, prefix_status
  use numerics_ode, only: ode_integrator_t, ode_options_t, ode_stats_t
  use kinetostatics_mass, only: mass_element_t
  use kinetostatics_mechanism, only: mechanism_t
  use kinetostatics_mechanism_ode, only: mechanism_ode_t
  implicit none (type, external)
  private
  public :: mechanism_series_t, integrate_mechanism

  type :: mechanism_series_t
    integer :: n = 0, f = 0, r = 0, nb = 0, nc = 0
    character(len=32), allocatable :: q_names(:), beta_names(:), closure_names(:), body_names(:), &
      contact_names(:)
    integer, allocatable :: body_frame(:)
    real(wp), allocatable :: time(:)                   ! s
    real(wp), allocatable :: q(:, :), qd(:, :), qdd(:, :)    ! f x n
    real(wp), allocatable :: beta(:, :), lambda(:, :)  ! r x n
    real(wp), allocatable :: closure(:), residual(:)   ! n
    real(wp), allocatable :: kinetic(:), potential(:)  ! J
    real(wp), allocatable :: body_r(:, :, :), body_v(:, :, :), body_omega(:, :, :)   ! 3 x nb x n
    real(wp), allocatable :: body_rot(:, :, :, :)      ! 3 x 3 x nb x n
    real(wp), allocatable :: normal(:, :)              ! nc x n, N
    real(wp), allocatable :: friction(:, :, :), contact_r(:, :, :), contact_v(:, :, :)   ! 3 x nc x n
  contains
    procedure :: init => series_init
    procedure :: record => series_record
  end type mechanism_series_t

contains

  subroutine series_init(self, m, capacity)
    class(mechanism_series_t), intent(out) :: self
    type(mechanism_t), intent(in) :: m
    integer, intent(in) :: capacity
    integer :: k, n
    self%f = m%f
    self%r = m%r
    self%nc = size(m%contacts)
    allocate (self%body_frame(0), self%body_names(0))
    do k = 1, m%n_elements
      select type (e => m%elements(k)%e)
      type is (mass_element_t)
        self%body_frame = [self%body_frame, e%frame]
        self%body_names = [character(len=32) :: self%body_names, e%name]
      end select
    end do
    self%nb = size(self%body_frame)
    self%q_names = m%scalar_names(m%q)
    self%beta_names = m%scalar_names(m%beta)
    self%closure_names = m%scalar_names(m%closure)
    allocate (self%contact_names(self%nc))
    do k = 1, self%nc
      self%contact_names(k) = m%contacts(k)%name
    end do
    n = capacity
    allocate (self%time(n), self%q(self%f, n), self%qd(self%f, n), self%qdd(self%f, n), &
              self%beta(self%r, n), self%lambda(self%r, n), self%closure(n), self%residual(n), &
              self%kinetic(n), self%potential(n), self%body_r(3, self%nb, n), self%body_v(3, self%nb, n), &
              self%body_omega(3, self%nb, n), self%body_rot(3, 3, self%nb, n), self%normal(self%nc, n), &
              self%friction(3, self%nc, n), self%contact_r(3, self%nc, n), self%contact_v(3, self%nc, n))
  end subroutine series_init

  !> Evaluates the complete state at (t, y) and appends it.
  subroutine series_record(self, m, t, y, status)
    class(mechanism_series_t), intent(inout) :: self
    type(mechanism_t), intent(inout) :: m
    real(wp), intent(in) :: t, y(:)
    type(status_t), intent(inout) :: status
    real(wp) :: res
    integer :: i, k
    if (self%n >= size(self%time)) return
    call m%evaluate(y(1:m%f), y(m%f + 1:2*m%f), res, status)
    if (.not. status%ok()) return
    self%n = self%n + 1
    i = self%n
    self%time(i) = t
    self%q(:, i) = y(1:m%f)
    self%qd(:, i) = y(m%f + 1:2*m%f)
    self%qdd(:, i) = m%qdd
    self%residual(i) = res
    do k = 1, m%r
      self%beta(k, i) = m%scalars(m%beta(k))%q
    end do
    self%lambda(:, i) = m%lambda
    self%closure(i) = m%closure_residual()
    call m%energy(self%kinetic(i), self%potential(i))
    do k = 1, self%nb
      associate (fr => m%frames(self%body_frame(k)))
        self%body_r(:, k, i) = fr%r
        self%body_v(:, k, i) = fr%v
        self%body_omega(:, k, i) = fr%omega
        self%body_rot(:, :, k, i) = fr%rot
      end associate
    end do
    do k = 1, self%nc
      associate (c => m%contacts(k))
        self%normal(k, i) = c%normal_force
        self%friction(:, k, i) = c%friction
        self%contact_r(:, k, i) = m%frames(c%frame)%r
        self%contact_v(:, k, i) = m%frames(c%frame)%v
      end associate
    end do
  end subroutine series_record

  !> Integrates from y0 over [0, duration], recording every output_step.
  subroutine integrate_mechanism(sys, y0, options, duration, output_step, series, stats, cpu, status)
    type(mechanism_ode_t), intent(inout), target :: sys
    real(wp), intent(in) :: y0(:), duration, output_step
    type(ode_options_t), intent(in) :: options
    type(mechanism_series_t), intent(out) :: series
    type(ode_stats_t), intent(out) :: stats
    real(wp), intent(out) :: cpu
    type(status_t), intent(inout) :: status
    type(ode_integrator_t) :: integrator
    real(wp) :: y(size(y0)), t, cpu0, cpu1
    integer :: n_out, k
    n_out = nint(duration/output_step)
    call series%init(sys%mechanism, n_out + 1)
    call cpu_time(cpu0)
    call series%record(sys%mechanism, 0.0_wp, y0, status)
    if (status%ok()) call integrator%start(sys, 0.0_wp, y0, options, status)
    k = 0
    do while (status%ok() .and. k < n_out)
      k = k + 1
      call integrator%advance(min(k*output_step, duration), t, y, status)
      if (.not. status%ok()) exit
      call series%record(sys%mechanism, t, y, status)
    end do
    call cpu_time(cpu1)
    cpu = cpu1 - cpu0
    stats = integrator%statistics()
    if (.not. status%ok()) call prefix_status(status, 'run stopped after t = '// &
                                              trim(format_short(series%time(max(series%n, 1))))//' s')
  end subroutine integrate_mechanism
end module kinetostatics_recorder
