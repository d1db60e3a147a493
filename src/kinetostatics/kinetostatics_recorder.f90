!> Time series of a mechanism's run: coordinates and their rates, every body's
!> frame (the frame of each mass element), closure residual and cut forces,
!> energies, contact kinematics and normal forces, every force law's force,
!> power and work, and the inverse-dynamics residual (a consistency check of
!> every recorded state). The series grows as records come (outputs and
!> events); recording is not part of the right-hand side.
module kinetostatics_recorder
  use base_kinds, only: wp
  use base_status, only: status_t
  use kinetostatics_mass, only: mass_element_t
  use kinetostatics_mechanism, only: mechanism_t
  implicit none (type, external)
  private
  public :: mechanism_series_t

  type :: mechanism_series_t
    integer :: n = 0, f = 0, r = 0, nb = 0, nc = 0, nl = 0, nm = 0
    character(len=32), allocatable :: q_names(:), beta_names(:), closure_names(:), body_names(:), &
      contact_names(:), law_names(:), monitor_names(:)
    character(len=8), allocatable :: monitor_units(:)
    integer, allocatable :: body_frame(:)
    integer, allocatable :: law_contact(:)            ! contact of each law (0: none)
    real(wp), allocatable :: time(:)                   ! s
    integer, allocatable :: kind(:)                    ! RECORD_START, _OUTPUT or _EVENT (numerics_event_driver)
    real(wp), allocatable :: q(:, :), qd(:, :), qdd(:, :)    ! f x n: every coordinate, its rates
    real(wp), allocatable :: beta(:, :), lambda(:, :)  ! r x n
    real(wp), allocatable :: closure(:), residual(:)   ! n
    real(wp), allocatable :: kinetic(:), potential(:)  ! J
    real(wp), allocatable :: body_r(:, :, :), body_v(:, :, :), body_omega(:, :, :)   ! 3 x nb x n
    real(wp), allocatable :: body_rot(:, :, :, :)      ! 3 x 3 x nb x n
    real(wp), allocatable :: normal(:, :)              ! nc x n, N
    real(wp), allocatable :: friction(:, :, :)         ! 3 x nc x n, N: the laws' forces on body B
    real(wp), allocatable :: contact_r(:, :, :), slip(:, :, :)   ! 3 x nc x n: point (m), slip velocity (m/s)
    real(wp), allocatable :: law_force(:, :, :)        ! 3 x nl x n, N
    real(wp), allocatable :: law_power(:, :), law_work(:, :)   ! nl x n: W, J
    real(wp), allocatable :: law_active(:, :)          ! nl x n: 1 on, 0 off
    real(wp), allocatable :: monitor(:, :)             ! nm x n: the mechanism's monitored scalars
  contains
    procedure :: init => series_init
    procedure :: record => series_record
  end type mechanism_series_t

contains

  subroutine series_init(self, m, capacity)
    class(mechanism_series_t), intent(out) :: self
    type(mechanism_t), intent(in) :: m
    integer, intent(in) :: capacity
    integer :: k
    self%f = m%f
    self%r = m%r
    self%nc = size(m%contacts)
    self%nl = m%n_laws
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
    self%nm = size(m%monitors)
    self%monitor_names = m%scalar_names(m%monitors)
    self%monitor_units = m%monitor_units
    allocate (self%contact_names(self%nc), self%law_names(self%nl), self%law_contact(self%nl))
    do k = 1, self%nc
      self%contact_names(k) = m%contacts(k)%name
    end do
    do k = 1, self%nl
      self%law_names(k) = m%laws(k)%law%name
      self%law_contact(k) = m%laws(k)%law%contact
    end do
    call allocate_arrays(self, max(capacity, 2))
  end subroutine series_init

  subroutine allocate_arrays(s, n)
    type(mechanism_series_t), intent(inout) :: s
    integer, intent(in) :: n
    allocate (s%time(n), s%kind(n), s%q(s%f, n), s%qd(s%f, n), s%qdd(s%f, n), s%beta(s%r, n), &
              s%lambda(s%r, n), s%closure(n), s%residual(n), s%kinetic(n), s%potential(n), &
              s%body_r(3, s%nb, n), s%body_v(3, s%nb, n), s%body_omega(3, s%nb, n), &
              s%body_rot(3, 3, s%nb, n), s%normal(s%nc, n), s%friction(3, s%nc, n), s%contact_r(3, s%nc, n), &
              s%slip(3, s%nc, n), s%law_force(3, s%nl, n), s%law_power(s%nl, n), s%law_work(s%nl, n), &
              s%law_active(s%nl, n), s%monitor(s%nm, n))
  end subroutine allocate_arrays

  !> Twice the room, the records so far kept.
  subroutine grow(s)
    type(mechanism_series_t), intent(inout) :: s
    type(mechanism_series_t) :: old
    integer :: n
    n = s%n
    call move_alloc(s%time, old%time); call move_alloc(s%kind, old%kind)
    call move_alloc(s%q, old%q); call move_alloc(s%qd, old%qd); call move_alloc(s%qdd, old%qdd)
    call move_alloc(s%beta, old%beta); call move_alloc(s%lambda, old%lambda)
    call move_alloc(s%closure, old%closure); call move_alloc(s%residual, old%residual)
    call move_alloc(s%kinetic, old%kinetic); call move_alloc(s%potential, old%potential)
    call move_alloc(s%body_r, old%body_r); call move_alloc(s%body_v, old%body_v)
    call move_alloc(s%body_omega, old%body_omega); call move_alloc(s%body_rot, old%body_rot)
    call move_alloc(s%normal, old%normal); call move_alloc(s%friction, old%friction)
    call move_alloc(s%contact_r, old%contact_r); call move_alloc(s%slip, old%slip)
    call move_alloc(s%law_force, old%law_force); call move_alloc(s%law_power, old%law_power)
    call move_alloc(s%law_work, old%law_work); call move_alloc(s%law_active, old%law_active)
    call move_alloc(s%monitor, old%monitor)
    call allocate_arrays(s, 2*size(old%time))
    s%time(:n) = old%time(:n); s%kind(:n) = old%kind(:n)
    s%q(:, :n) = old%q(:, :n); s%qd(:, :n) = old%qd(:, :n); s%qdd(:, :n) = old%qdd(:, :n)
    s%beta(:, :n) = old%beta(:, :n); s%lambda(:, :n) = old%lambda(:, :n)
    s%closure(:n) = old%closure(:n); s%residual(:n) = old%residual(:n)
    s%kinetic(:n) = old%kinetic(:n); s%potential(:n) = old%potential(:n)
    s%body_r(:, :, :n) = old%body_r(:, :, :n); s%body_v(:, :, :n) = old%body_v(:, :, :n)
    s%body_omega(:, :, :n) = old%body_omega(:, :, :n); s%body_rot(:, :, :, :n) = old%body_rot(:, :, :, :n)
    s%normal(:, :n) = old%normal(:, :n); s%friction(:, :, :n) = old%friction(:, :, :n)
    s%contact_r(:, :, :n) = old%contact_r(:, :, :n); s%slip(:, :, :n) = old%slip(:, :, :n)
    s%law_force(:, :, :n) = old%law_force(:, :, :n); s%law_power(:, :n) = old%law_power(:, :n)
    s%law_work(:, :n) = old%law_work(:, :n); s%law_active(:, :n) = old%law_active(:, :n)
    s%monitor(:, :n) = old%monitor(:, :n)
  end subroutine grow

  !> Evaluates the complete state at (t, q, q') and appends it with the laws'
  !> work integrals `work` (J) and the record kind.
  subroutine series_record(self, m, t, q, qd, work, kind, status)
    class(mechanism_series_t), intent(inout) :: self
    type(mechanism_t), intent(inout) :: m
    real(wp), intent(in) :: t, q(:), qd(:), work(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    real(wp) :: res
    integer :: i, k
    call m%evaluate(t, q, qd, res, status)
    if (.not. status%ok()) return
    if (self%n >= size(self%time)) call grow(self)
    self%n = self%n + 1
    i = self%n
    self%time(i) = t
    self%kind(i) = kind
    self%q(:, i) = q
    ! the rates of every coordinate (qd holds the speeds, which differ from q'
    ! under rate constraints or kinematic coordinates)
    do k = 1, m%f
      self%qd(k, i) = m%scalars(m%q(k))%qd
      self%qdd(k, i) = m%scalars(m%q(k))%qdd
    end do
    self%residual(i) = res
    do k = 1, m%r
      self%beta(k, i) = m%scalars(m%beta(k))%q
    end do
    self%lambda(:, i) = m%lambda
    self%closure(i) = m%closure_residual()
    do k = 1, self%nm
      self%monitor(k, i) = m%scalars(m%monitors(k))%q
    end do
    call m%energy(self%kinetic(i), self%potential(i))
    do k = 1, self%nb
      associate (fr => m%frames(self%body_frame(k)))
        self%body_r(:, k, i) = fr%r
        self%body_v(:, k, i) = fr%v
        self%body_omega(:, k, i) = fr%omega
        self%body_rot(:, :, k, i) = fr%rot
      end associate
    end do
    self%friction(:, :, i) = 0
    do k = 1, self%nl
      self%law_force(:, k, i) = m%law_force(k)
      self%law_power(k, i) = m%law_power(k)
      self%law_work(k, i) = work(k)
      self%law_active(k, i) = merge(1, 0, m%laws(k)%law%active)
      if (self%law_contact(k) > 0) self%friction(:, self%law_contact(k), i) = &
        self%friction(:, self%law_contact(k), i) + self%law_force(:, k, i)
    end do
    do k = 1, self%nc
      associate (c => m%contacts(k))
        self%normal(k, i) = c%normal_force
        self%contact_r(:, k, i) = m%contact_states(k)%point
        self%slip(:, k, i) = m%contact_states(k)%slip
      end associate
    end do
  end subroutine series_record
end module kinetostatics_recorder
