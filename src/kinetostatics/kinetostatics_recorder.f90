!> Time series of a mechanism's run: coordinates and their rates, every body's
!> frame (the frame of each mass element), closure residual and cut forces,
!> energies, contact kinematics and normal forces, every force law's force,
!> power and work, and the inverse-dynamics residual (a consistency check of
!> every recorded state). The series grows as records come (outputs and
!> events); recording is not part of the right-hand side.
module kinetostatics_recorder
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_series, only: growable_series_t, resize
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_contact, only: contact_t
  implicit none (type, external)
  private
  public :: mechanism_series_t

  !> The records of a mechanism's run; grown as it goes (base_series).
  type, extends(growable_series_t) :: mechanism_series_t
    integer :: f = 0, r = 0, nb = 0, nc = 0, nl = 0, nm = 0
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
    real(wp), allocatable :: friction(:, :, :)         ! 3 x nc x n, N: the laws' forces on body B and a
                                                       ! rolling contact's static friction
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
    ! the bodies: the mass elements (the mechanism's `masses`, in the order added)
    self%nb = size(m%masses)
    allocate (self%body_frame(self%nb), self%body_names(self%nb))
    do k = 1, self%nb
      self%body_frame(k) = m%elements(m%masses(k))%e%mass_frame()
      self%body_names(k) = m%elements(m%masses(k))%e%name
    end do
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

  !> Room for n records in every array of the series, the recorded ones kept.
  subroutine allocate_arrays(s, n)
    type(mechanism_series_t), intent(inout) :: s
    integer, intent(in) :: n
    call resize(s%time, n); call resize(s%kind, n); call resize(s%q, s%f, n); call resize(s%qd, s%f, n)
    call resize(s%qdd, s%f, n); call resize(s%beta, s%r, n); call resize(s%lambda, s%r, n)
    call resize(s%closure, n); call resize(s%residual, n); call resize(s%kinetic, n); call resize(s%potential, n)
    call resize(s%body_r, 3, s%nb, n); call resize(s%body_v, 3, s%nb, n); call resize(s%body_omega, 3, s%nb, n)
    call resize(s%body_rot, 3, 3, s%nb, n); call resize(s%normal, s%nc, n); call resize(s%friction, 3, s%nc, n)
    call resize(s%contact_r, 3, s%nc, n); call resize(s%slip, 3, s%nc, n); call resize(s%law_force, 3, s%nl, n)
    call resize(s%law_power, s%nl, n); call resize(s%law_work, s%nl, n); call resize(s%law_active, s%nl, n)
    call resize(s%monitor, s%nm, n)
    s%capacity = n
  end subroutine allocate_arrays

  !> Numbers of one record (every array above), for the memory bound.
  pure real(wp) function record_values(s)
    type(mechanism_series_t), intent(in) :: s
    record_values = 6 + 3*s%f + 2*s%r + 18*s%nb + 10*s%nc + 6*s%nl + s%nm
  end function record_values

  !> Evaluates the complete state at (t, q, q') with the workspace of the
  !> run's computations and appends it with the laws' work integrals `work`
  !> (J) and the record kind.
  subroutine series_record(self, m, workspace, t, q, qd, work, kind, status)
    class(mechanism_series_t), intent(inout) :: self
    type(mechanism_t), intent(inout) :: m
    type(mechanism_workspace_t), intent(inout) :: workspace
    real(wp), intent(in) :: t, q(:), qd(:), work(:)
    integer, intent(in) :: kind
    type(status_t), intent(inout) :: status
    real(wp) :: res
    integer :: i, k, grown
    call m%evaluate(workspace, t, q, qd, res, status)
    if (.not. status%ok()) return
    call self%make_room(16, 8*record_values(self), 'mechanism', t, grown, status)
    if (.not. status%ok()) return
    if (grown > 0) call allocate_arrays(self, grown)
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
        self%friction(:, k, i) = self%friction(:, k, i) + static_friction(m, c)
        self%normal(k, i) = c%normal_force
        self%contact_r(:, k, i) = m%contact_states(k)%point
        self%slip(:, k, i) = m%contact_states(k)%slip
      end associate
    end do
  end subroutine series_record

  !> The static friction of a rolling contact on body B (N, world), the cut
  !> forces of its no-slip outputs along the contact frame's x and y at the
  !> evaluated state; zero for a contact that does not roll.
  pure function static_friction(m, c) result(f)
    type(mechanism_t), intent(in) :: m
    type(contact_t), intent(in) :: c
    real(wp) :: f(3)
    integer :: axis, j
    f = 0
    do axis = 1, 2
      if (c%tangential_outputs(axis) == 0) cycle
      j = findloc(m%rate_outputs, c%tangential_outputs(axis), dim=1)
      if (j > 0) f = f + m%mu(j)*m%frames(c%point_frame)%rot(:, axis)
    end do
  end function static_friction
end module kinetostatics_recorder
