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
  use kinetostatics_force_law, only: friction_law_t
  implicit none (type, external)
  private
  public :: mechanism_series_t, join_series

  !> The records of a mechanism's run; grown as it goes (base_series).
  type, extends(growable_series_t) :: mechanism_series_t
    integer :: f = 0, r = 0, nb = 0, nc = 0, nl = 0, nm = 0
    character(len=32), allocatable :: q_names(:), beta_names(:), closure_names(:), body_names(:), &
      contact_names(:), law_names(:), monitor_names(:)
    character(len=8), allocatable :: monitor_units(:)
    integer, allocatable :: body_frame(:)
    !> the contact of each friction law (0: none, or a law that is not a
    !> friction: the water's drag at a vehicle's contact is not summed into
    !> the contact's friction)
    integer, allocatable :: law_contact(:)
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
      self%law_contact(k) = 0
      select type (law => m%laws(k)%law)
      class is (friction_law_t)
        self%law_contact(k) = law%contact
      end select
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
    type(mechanism_t), intent(in) :: m
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
      self%qd(k, i) = workspace%scalars(m%q(k))%qd
      self%qdd(k, i) = workspace%scalars(m%q(k))%qdd
    end do
    self%residual(i) = res
    do k = 1, m%r
      self%beta(k, i) = workspace%scalars(m%beta(k))%q
    end do
    self%lambda(:, i) = workspace%lambda
    self%closure(i) = m%closure_residual(workspace)
    do k = 1, self%nm
      self%monitor(k, i) = workspace%scalars(m%monitors(k))%q
    end do
    call m%energy(workspace, self%kinetic(i), self%potential(i))
    do k = 1, self%nb
      associate (fr => workspace%frames(self%body_frame(k)))
        self%body_r(:, k, i) = fr%r
        self%body_v(:, k, i) = fr%v
        self%body_omega(:, k, i) = fr%omega
        self%body_rot(:, :, k, i) = fr%rot
      end associate
    end do
    self%friction(:, :, i) = 0
    do k = 1, self%nl
      self%law_force(:, k, i) = m%law_force(workspace, k)
      self%law_power(k, i) = workspace%law_power(k)
      self%law_work(k, i) = work(k)
      self%law_active(k, i) = merge(1, 0, workspace%laws(k)%law%active)
      if (self%law_contact(k) > 0) self%friction(:, self%law_contact(k), i) = &
        self%friction(:, self%law_contact(k), i) + self%law_force(:, k, i)
    end do
    do k = 1, self%nc
      associate (c => m%contacts(k))
        self%friction(:, k, i) = self%friction(:, k, i) + static_friction(m, workspace, c)
        self%normal(k, i) = workspace%normal_force(k)
        self%contact_r(:, k, i) = workspace%contact_states(k)%point
        self%slip(:, k, i) = workspace%contact_states(k)%slip
      end associate
    end do
  end subroutine series_record

  !> The records of `first` followed by those of `second`, a run that went on
  !> with another mechanism (contact_closing: a flight, then the closed
  !> contact). Each name list (coordinates, dependents, closures, bodies,
  !> contacts, laws, monitors) is the union, first's then second's new ones;
  !> a quantity holds 0 in the records of the phase that does not have it
  !> (the caller says which records are which phase), but for the work of a
  !> law of first's only, which holds its last value in second's records
  !> (the work done so far stays in the energy balance). Bodies keep second's
  !> frames where second has them (its mechanism describes the run's end).
  function join_series(first, second) result(s)
    type(mechanism_series_t), intent(in) :: first, second
    type(mechanism_series_t) :: s
    integer, allocatable :: q1(:), q2(:), b1(:), b2(:), c1(:), c2(:), l1(:), l2(:), m1(:), m2(:), r1(:), r2(:)
    integer :: n1, n, k, i
    n1 = first%n
    n = first%n + second%n
    call union(first%q_names, second%q_names, s%q_names, q1, q2)
    call union(first%beta_names, second%beta_names, s%beta_names, r1, r2)
    call union(first%body_names, second%body_names, s%body_names, b1, b2)
    call union(first%contact_names, second%contact_names, s%contact_names, c1, c2)
    call union(first%law_names, second%law_names, s%law_names, l1, l2)
    call union(first%monitor_names, second%monitor_names, s%monitor_names, m1, m2)
    s%f = size(s%q_names)
    s%r = size(s%beta_names)
    s%nb = size(s%body_names)
    s%nc = size(s%contact_names)
    s%nl = size(s%law_names)
    s%nm = size(s%monitor_names)
    allocate (s%body_frame(s%nb), s%law_contact(s%nl), s%monitor_units(s%nm), s%closure_names(s%r))
    s%closure_names(r1) = first%closure_names   ! one per dependent coordinate
    s%closure_names(r2) = second%closure_names
    s%body_frame(b1) = first%body_frame
    s%body_frame(b2) = second%body_frame
    s%law_contact = 0
    do k = 1, first%nl
      if (first%law_contact(k) > 0) s%law_contact(l1(k)) = c1(first%law_contact(k))
    end do
    do k = 1, second%nl
      if (second%law_contact(k) > 0) s%law_contact(l2(k)) = c2(second%law_contact(k))
    end do
    s%monitor_units(m1) = first%monitor_units
    s%monitor_units(m2) = second%monitor_units
    call allocate_arrays(s, max(n, 2))
    call zero_records(s)
    s%n = n
    s%time(:n) = [first%time(:n1), second%time(:second%n)]
    s%kind(:n) = [first%kind(:n1), second%kind(:second%n)]
    s%closure(:n) = [first%closure(:n1), second%closure(:second%n)]
    s%residual(:n) = [first%residual(:n1), second%residual(:second%n)]
    s%kinetic(:n) = [first%kinetic(:n1), second%kinetic(:second%n)]
    s%potential(:n) = [first%potential(:n1), second%potential(:second%n)]
    do i = 1, n1
      call copy_record(first, i, i, q1, r1, b1, c1, l1, m1)
    end do
    do i = 1, second%n
      call copy_record(second, i, n1 + i, q2, r2, b2, c2, l2, m2)
    end do
    if (n1 > 0) then
      do k = 1, first%nl
        if (.not. any(l2 == l1(k))) s%law_work(l1(k), n1 + 1:n) = first%law_work(k, n1)
      end do
    end if
  contains
    !> Record i of `from` into record j of s through the index maps.
    subroutine copy_record(from, i, j, q, r, b, c, l, m)
      type(mechanism_series_t), intent(in) :: from
      integer, intent(in) :: i, j, q(:), r(:), b(:), c(:), l(:), m(:)
      s%q(q, j) = from%q(:, i)
      s%qd(q, j) = from%qd(:, i)
      s%qdd(q, j) = from%qdd(:, i)
      s%beta(r, j) = from%beta(:, i)
      s%lambda(r, j) = from%lambda(:, i)
      s%body_r(:, b, j) = from%body_r(:, :, i)
      s%body_v(:, b, j) = from%body_v(:, :, i)
      s%body_omega(:, b, j) = from%body_omega(:, :, i)
      s%body_rot(:, :, b, j) = from%body_rot(:, :, :, i)
      s%normal(c, j) = from%normal(:, i)
      s%friction(:, c, j) = from%friction(:, :, i)
      s%contact_r(:, c, j) = from%contact_r(:, :, i)
      s%slip(:, c, j) = from%slip(:, :, i)
      s%law_force(:, l, j) = from%law_force(:, :, i)
      s%law_power(l, j) = from%law_power(:, i)
      s%law_work(l, j) = from%law_work(:, i)
      s%law_active(l, j) = from%law_active(:, i)
      s%monitor(m, j) = from%monitor(:, i)
    end subroutine copy_record
  end function join_series

  !> names = a's, then b's not in a; where each of a's and b's went.
  subroutine union(a, b, names, in_a, in_b)
    character(len=*), intent(in) :: a(:), b(:)
    character(len=32), allocatable, intent(out) :: names(:)
    integer, allocatable, intent(out) :: in_a(:), in_b(:)
    integer :: k, j
    names = a
    in_a = [(k, k = 1, size(a))]
    allocate (in_b(size(b)))
    do k = 1, size(b)
      j = findloc([(names(j) == b(k), j = 1, size(names))], .true., dim=1)
      if (j == 0) then
        ! typed: gfortran's length check misreads a zero-size names as length 1
        names = [character(len=32) :: names, b(k)]
        j = size(names)
      end if
      in_b(k) = j
    end do
  end subroutine union

  !> Every record array zero (the values a phase does not have).
  subroutine zero_records(s)
    type(mechanism_series_t), intent(inout) :: s
    s%time = 0; s%kind = 0; s%q = 0; s%qd = 0; s%qdd = 0; s%beta = 0; s%lambda = 0; s%closure = 0
    s%residual = 0; s%kinetic = 0; s%potential = 0; s%body_r = 0; s%body_v = 0; s%body_omega = 0
    s%body_rot = 0; s%normal = 0; s%friction = 0; s%contact_r = 0; s%slip = 0; s%law_force = 0
    s%law_power = 0; s%law_work = 0; s%law_active = 0; s%monitor = 0
  end subroutine zero_records

  !> The static friction of a rolling contact on body B (N, world), the cut
  !> forces of its no-slip outputs along the contact frame's x and y at the
  !> evaluated state; zero for a contact that does not roll.
  pure function static_friction(m, workspace, c) result(f)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(in) :: workspace
    type(contact_t), intent(in) :: c
    real(wp) :: f(3)
    integer :: axis, j
    f = 0
    do axis = 1, 2
      if (c%tangential_outputs(axis) == 0) cycle
      j = findloc(m%rate_outputs, c%tangential_outputs(axis), dim=1)
      if (j > 0) f = f + workspace%mu(j)*workspace%frames(c%point_frame)%rot(:, axis)
    end do
  end function static_friction
end module kinetostatics_recorder
