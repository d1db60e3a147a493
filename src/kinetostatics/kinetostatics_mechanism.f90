!> Mechanisms: transmission elements chained from the ground frame, closed
!> loops, and the equations of motion in minimal coordinates (thesis 3.3, 3.4).
!>
!> Frames and scalars live in two arrays owned by the mechanism; frame 1 is the
!> ground (fixed). Elements are evaluated in the order they were added (each
!> element's inputs must be outputs of earlier ones, or the ground, or scalars),
!> forces in the reverse order. Scalars play one of four roles: generalized
!> coordinate q, dependent coordinate beta, output of a measurement, or a fixed
!> joint value.
!>
!> Loops (3.24)-(3.33). Each loop names its closure measurements g (with target
!> values) and as many dependent coordinates beta. f(beta, q) = g - target = 0 is
!> solved from the previous solution (warm start): first by Newton steps with
!> the analytic Jacobian J_beta (one velocity pass per column, (3.21)), which
!> converge in one or two steps from a warm start; if that does not reach the
!> tolerance, by MINPACK's HYBRJ with the same Jacobian (the thesis's solver).
!> Then beta' = -J_beta^-1 f^ (3.30), beta'' = -J_beta^-1 f^' (3.31), and the cut
!> forces lambda = -J_beta^-T Q^_beta ((3.33): the printed form lacks the inverse).
!>
!> Equations of motion (3.34)-(3.36): the inverse dynamics Q_bar(q, q', q'')
!> (generalized forces of d'Alembert + applied forces at the q's, loops closed
!> by lambda) is affine in q'': Q_bar = Q_bar0 - M q''. f + 1 passes: one with
!> q'' = 0 (everything on) gives Q_bar0 = -Q^, and one per coordinate with
!> q'' = e_i, velocities zero and applied forces off gives the column -M e_i.
!>
!> Friction at contacts (a contact is the output frame of a surface joint): the
!> normal force N is the component along -z_D of the force the mechanism puts
!> on that frame, N = -z_D . f_D (positive: pressed onto the surface); it
!> depends on q'' and on the friction forces themselves, affinely:
!> N = N0 + G q'' + H F. Viscous friction F = -c w is velocity-dependent and goes
!> into Q_bar0. Coulomb friction (4.28), F_c = -mu |N_c| w_c/|w_c|, is solved
!> exactly with the normal forces as extra unknowns:
!>     [ M        -P D   ] [q'']   [Q_bar0]
!>     [ -G    I - H D   ] [N  ] = [N0    ],   D = diag(mu_c s_c), s_c = sign N_c,
!> where P(:, c) and H(:, c) come from one force pass with the unit load -w^_c at
!> contact c; the signs are iterated until consistent (normally at once).
!> w -> 0: w^ = w/sqrt(|w|^2 + eps^2) with eps = regularization_speed (default
!> 1e-6 m/s): exact to (eps/|w|)^2/2 relative while sliding; a contact at rest
!> feels a stiff viscous damping mu |N|/eps instead of stiction (sticking is not
!> modelled).
module kinetostatics_mechanism
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_OK, STATUS_INVALID_INPUT, &
    STATUS_NOT_CONVERGED, STATUS_DOMAIN
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, &
    solve_nonlinear
  use kinetostatics_state, only: element_t, element_box_t, frame_state_t, scalar_state_t
  implicit none (type, external)
  private
  public :: mechanism_t, contact_t, loop_t

  interface
    subroutine dgetrf(m, n, a, lda, ipiv, info)
      import :: wp
      integer, intent(in) :: m, n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: ipiv(*), info
    end subroutine dgetrf
    subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      character, intent(in) :: trans
      integer, intent(in) :: n, nrhs, lda, ldb, ipiv(*)
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dgetrs
    subroutine dgecon(norm, n, a, lda, anorm, rcond, work, iwork, info)
      import :: wp
      character, intent(in) :: norm
      integer, intent(in) :: n, lda
      real(wp), intent(in) :: a(lda, *), anorm
      real(wp), intent(out) :: rcond
      real(wp), intent(inout) :: work(*)
      integer, intent(inout) :: iwork(*)
      integer, intent(out) :: info
    end subroutine dgecon
    subroutine dpotrf(uplo, n, a, lda, info)
      import :: wp
      character, intent(in) :: uplo
      integer, intent(in) :: n, lda
      real(wp), intent(inout) :: a(lda, *)
      integer, intent(out) :: info
    end subroutine dpotrf
    subroutine dpotrs(uplo, n, nrhs, a, lda, b, ldb, info)
      import :: wp
      character, intent(in) :: uplo
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(in) :: a(lda, *)
      real(wp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dpotrs
  end interface

  integer, parameter :: ROLE_FIXED = 0, ROLE_Q = 1, ROLE_BETA = 2, ROLE_MEASURE = 3

  type :: loop_t
    character(len=:), allocatable :: name
    integer, allocatable :: measurements(:)   ! scalar indices of the closure measurements
    real(wp), allocatable :: targets(:)       ! their required values
    integer, allocatable :: dependents(:)     ! scalar indices of the dependent coordinates
  end type loop_t

  type :: contact_t
    character(len=:), allocatable :: name
    integer :: frame = 0                      ! the Darboux frame (surface joint output)
    real(wp) :: mu = 0                        ! Coulomb coefficient, 1
    real(wp) :: viscous = 0                   ! N s/m
    real(wp) :: regularization_speed = 1e-6_wp  ! m/s
    ! at the last evaluation
    real(wp) :: direction(3) = 0              ! w/sqrt(|w|^2 + eps^2)
    real(wp) :: load(3) = 0                   ! N, force applied at the frame in the current pass
    real(wp) :: normal_force = 0              ! N
    real(wp) :: friction(3) = 0               ! N
  end type contact_t

  type, extends(nonlinear_system_t) :: mechanism_t
    type(frame_state_t), allocatable :: frames(:)
    type(scalar_state_t), allocatable :: scalars(:)
    character(len=32), allocatable :: frame_names(:), scalar_names(:)
    integer, allocatable :: role(:)
    type(element_box_t), allocatable :: elements(:)
    type(loop_t), allocatable :: loops(:)
    type(contact_t), allocatable :: contacts(:)
    integer :: n_frames = 0, n_scalars = 0, n_elements = 0, f = 0, r = 0
    integer, allocatable :: q(:), beta(:), closure(:)
    real(wp), allocatable :: target(:)
    type(nonlinear_options_t) :: closure_options = nonlinear_options_t(xtol=1e-12_wp, &
      residual_tolerance=1e-8_wp)
    real(wp) :: closure_tolerance = 1e-10_wp   !< max |g - target| accepted (measurement units)
    logical :: ready = .false.
    ! results of the last evaluation
    real(wp), allocatable :: lambda(:)        ! cut forces of the closure measurements
    real(wp), allocatable :: qdd(:)
    real(wp), allocatable :: mass(:, :), bias(:)   ! M and Q_bar0 = -Q^
    integer :: closure_solves = 0, hybrj_solves = 0
    ! work arrays
    real(wp), allocatable :: jbeta(:, :), jlu(:, :), work_r(:), gq(:)
    real(wp), allocatable :: x_r(:), start_r(:), res_r(:), work_f(:), work_c(:)   ! (gfortran puts
                                                                                  ! automatic arrays on the heap)
    real(wp), allocatable :: chol(:, :), g_mat(:, :), p_mat(:, :), h_mat(:, :), n0(:), block(:, :), &
      block_rhs(:), mu_s(:)
    integer, allocatable :: ipiv(:), ipiv_block(:), coulomb(:)
  contains
    procedure :: add_frame, add_scalar, add_element, add_loop, add_contact, set_coordinates, finalize
    procedure :: frame_index, scalar_index
    procedure :: residual => mechanism_residual
    procedure :: jacobian => mechanism_jacobian
    procedure :: position_pass, velocity_pass, acceleration_pass, force_pass
    procedure :: set_positions, set_velocities, set_accelerations, inverse_dynamics
    procedure :: check_start
    procedure :: dynamics, evaluate, energy, closure_residual, normal_forces
  end type mechanism_t

contains

  ! ---------------------------------------------------------------- building

  !> Adds a frame and returns its index (the ground, index 1, exists from the start).
  integer function add_frame(self, name) result(k)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    type(frame_state_t) :: empty
    call ensure_ground(self)
    self%frames = [self%frames, empty]
    self%frame_names = [character(len=32) :: self%frame_names, name]
    self%n_frames = self%n_frames + 1
    k = self%n_frames
  end function add_frame

  subroutine ensure_ground(self)
    class(mechanism_t), intent(inout) :: self
    if (self%n_frames > 0) return
    allocate (self%frames(1), self%frame_names(1), self%scalars(0), self%scalar_names(0), self%role(0))
    allocate (self%elements(0), self%loops(0), self%contacts(0))
    self%frame_names(1) = 'ground'
    self%n_frames = 1
  end subroutine ensure_ground

  !> Adds a scalar (joint variable or measurement) with value `value`.
  integer function add_scalar(self, name, value) result(k)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    real(wp), intent(in), optional :: value
    type(scalar_state_t) :: s
    call ensure_ground(self)
    if (present(value)) s%q = value
    self%scalars = [self%scalars, s]
    self%scalar_names = [character(len=32) :: self%scalar_names, name]
    self%role = [self%role, ROLE_FIXED]
    self%n_scalars = self%n_scalars + 1
    k = self%n_scalars
  end function add_scalar

  subroutine add_element(self, e)
    class(mechanism_t), intent(inout) :: self
    class(element_t), intent(in) :: e
    type(element_box_t), allocatable :: grown(:)
    integer :: k
    call ensure_ground(self)
    allocate (grown(self%n_elements + 1))
    do k = 1, self%n_elements
      call move_alloc(self%elements(k)%e, grown(k)%e)
    end do
    allocate (grown(self%n_elements + 1)%e, source=e)
    call move_alloc(grown, self%elements)
    self%n_elements = self%n_elements + 1
  end subroutine add_element

  !> A closed loop: its closure measurements (scalar indices, required values)
  !> and as many dependent coordinates.
  subroutine add_loop(self, name, measurements, targets, dependents, status)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: measurements(:), dependents(:)
    real(wp), intent(in) :: targets(:)
    type(status_t), intent(inout) :: status
    type(loop_t) :: loop
    if (size(measurements) /= size(dependents) .or. size(targets) /= size(measurements)) then
      call set_status(status, STATUS_INVALID_INPUT, 'loop '''//name//''': needs as many closure '// &
                      'measurements (and targets) as dependent coordinates')
      return
    end if
    loop%name = name
    loop%measurements = measurements
    loop%targets = targets
    loop%dependents = dependents
    self%loops = [self%loops, loop]
    self%role(measurements) = ROLE_MEASURE
    self%role(dependents) = ROLE_BETA
  end subroutine add_loop

  !> Friction at the Darboux frame `frame` of a surface joint.
  subroutine add_contact(self, name, frame, mu, viscous, regularization_speed)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame
    real(wp), intent(in) :: mu, viscous
    real(wp), intent(in), optional :: regularization_speed
    type(contact_t) :: c
    c%name = name
    c%frame = frame
    c%mu = mu
    c%viscous = viscous
    if (present(regularization_speed)) c%regularization_speed = regularization_speed
    self%contacts = [self%contacts, c]
  end subroutine add_contact

  subroutine set_coordinates(self, q)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: q(:)
    self%q = q
    self%role(q) = ROLE_Q
  end subroutine set_coordinates

  integer function frame_index(self, name) result(k)
    class(mechanism_t), intent(in) :: self
    character(len=*), intent(in) :: name
    do k = 1, self%n_frames
      if (self%frame_names(k) == name) return
    end do
    k = 0
  end function frame_index

  integer function scalar_index(self, name) result(k)
    class(mechanism_t), intent(in) :: self
    character(len=*), intent(in) :: name
    do k = 1, self%n_scalars
      if (self%scalar_names(k) == name) return
    end do
    k = 0
  end function scalar_index

  !> Checks the structure and allocates every work array.
  subroutine finalize(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k, nc
    if (.not. status%ok()) return
    call ensure_ground(self)
    if (.not. allocated(self%q)) allocate (self%q(0))
    self%f = size(self%q)
    if (self%f < 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'mechanism: no generalized coordinates')
      return
    end if
    allocate (self%beta(0), self%closure(0), self%target(0))
    do k = 1, size(self%loops)
      self%beta = [self%beta, self%loops(k)%dependents]
      self%closure = [self%closure, self%loops(k)%measurements]
      self%target = [self%target, self%loops(k)%targets]
    end do
    self%r = size(self%beta)
    allocate (self%coulomb(0))
    do k = 1, size(self%contacts)
      if (self%contacts(k)%mu > 0) self%coulomb = [self%coulomb, k]
    end do
    nc = size(self%coulomb)
    allocate (self%lambda(self%r), self%qdd(self%f), self%mass(self%f, self%f), self%bias(self%f))
    allocate (self%jbeta(self%r, self%r), self%jlu(self%r, self%r), self%work_r(self%r), self%gq(self%f))
    allocate (self%x_r(self%r), self%start_r(self%r), self%res_r(self%r), self%work_f(self%f), &
              self%work_c(size(self%contacts)))
    allocate (self%chol(self%f, self%f), self%g_mat(nc, self%f), self%p_mat(self%f, nc), &
              self%h_mat(nc, nc), self%n0(nc), self%block(self%f + nc, self%f + nc), &
              self%block_rhs(self%f + nc), self%mu_s(nc))
    allocate (self%ipiv(max(self%r, 1)), self%ipiv_block(self%f + nc))
    self%lambda = 0
    self%qdd = 0
    self%ready = .true.
  end subroutine finalize

  ! ------------------------------------------------------------------ passes

  subroutine position_pass(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%n_elements
      call self%elements(k)%e%position(self%frames, self%scalars, status)
      if (.not. status%ok()) return
    end do
  end subroutine position_pass

  subroutine velocity_pass(self)
    class(mechanism_t), intent(inout) :: self
    integer :: k
    do k = 1, self%n_elements
      call self%elements(k)%e%velocity(self%frames, self%scalars)
    end do
  end subroutine velocity_pass

  subroutine acceleration_pass(self)
    class(mechanism_t), intent(inout) :: self
    integer :: k
    do k = 1, self%n_elements
      call self%elements(k)%e%acceleration(self%frames, self%scalars)
    end do
  end subroutine acceleration_pass

  !> Clears all forces, puts the cut forces lambda on the closure measurements
  !> and the contact loads on their frames, and runs the elements backwards.
  subroutine force_pass(self, inertia, applied, lambda)
    class(mechanism_t), intent(inout) :: self
    logical, intent(in) :: inertia, applied
    real(wp), intent(in) :: lambda(:)
    integer :: k
    do k = 1, self%n_frames
      self%frames(k)%torque = 0
      self%frames(k)%force = 0
    end do
    self%scalars%force = 0
    do k = 1, self%r
      self%scalars(self%closure(k))%force = lambda(k)
    end do
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        self%frames(c%frame)%force = self%frames(c%frame)%force + c%load
      end associate
    end do
    do k = self%n_elements, 1, -1
      call self%elements(k)%e%force(self%frames, self%scalars, inertia, applied)
    end do
  end subroutine force_pass

  ! ------------------------------------------------------------ loop closure

  subroutine mechanism_residual(self, x, f, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%r
      self%scalars(self%beta(k))%q = x(k)
    end do
    f = 0
    call self%position_pass(status)
    if (.not. status%ok()) return
    do k = 1, self%r
      f(k) = self%scalars(self%closure(k))%q - self%target(k)
    end do
  end subroutine mechanism_residual

  subroutine mechanism_jacobian(self, x, jac, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%r
      self%scalars(self%beta(k))%q = x(k)
    end do
    jac = 0
    call self%position_pass(status)
    if (.not. status%ok()) return
    call closure_jacobian(self, jac)
  end subroutine mechanism_jacobian

  !> J_beta column by column: velocity passes with q' = 0, beta' = e_k (3.21).
  !> Destroys the velocity state.
  subroutine closure_jacobian(self, jac)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(out) :: jac(:, :)
    integer :: k, i
    do i = 1, self%f
      self%scalars(self%q(i))%qd = 0
    end do
    do k = 1, self%r
      do i = 1, self%r
        self%scalars(self%beta(i))%qd = 0
      end do
      self%scalars(self%beta(k))%qd = 1
      call self%velocity_pass()
      do i = 1, self%r
        jac(i, k) = self%scalars(self%closure(i))%qd
      end do
    end do
  end subroutine closure_jacobian

  !> J_beta at the current positions, LU-factored into jlu.
  subroutine factor_closure(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: info
    call closure_jacobian(self, self%jbeta)
    self%jlu = self%jbeta
    call dgetrf(self%r, self%r, self%jlu, self%r, self%ipiv, info)
    if (info > 0) then
      call set_status(status, STATUS_NOT_CONVERGED, 'the closure Jacobian is singular: '// &
                      describe_dependent(self, info)//' does not move the closure measurements')
    end if
  end subroutine factor_closure

  function describe_dependent(self, k) result(text)
    class(mechanism_t), intent(in) :: self
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    integer :: l, m, count
    count = 0
    text = 'dependent coordinate '''//trim(self%scalar_names(self%beta(k)))//''''
    do l = 1, size(self%loops)
      do m = 1, size(self%loops(l)%dependents)
        count = count + 1
        if (count == k) text = text//' of loop '''//self%loops(l)%name//''''
      end do
    end do
  end function describe_dependent

  !> The loop whose closure is worst at the current positions.
  function worst_loop(self) result(text)
    class(mechanism_t), intent(in) :: self
    character(len=:), allocatable :: text
    integer :: l, m
    real(wp) :: worst, e
    character(len=16) :: num
    worst = -1
    text = ''
    do l = 1, size(self%loops)
      do m = 1, size(self%loops(l)%measurements)
        e = abs(self%scalars(self%loops(l)%measurements(m))%q - self%loops(l)%targets(m))
        if (e > worst) then
          worst = e
          write (num, '(es10.3)') e
          text = 'loop '''//self%loops(l)%name//''' (measurement '''// &
                 trim(self%scalar_names(self%loops(l)%measurements(m)))//''' off by '//trim(adjustl(num))//')'
        end if
      end do
    end do
  end function worst_loop

  !> Sets q, closes the loops (beta from the last solution), leaves the
  !> positions evaluated and J_beta factored.
  subroutine set_positions(self, q, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:)
    type(status_t), intent(inout) :: status
    type(nonlinear_result_t) :: result
    type(status_t) :: solve_status
    integer :: k, it, info
    logical :: converged

    do k = 1, self%f
      self%scalars(self%q(k))%q = q(k)
    end do
    if (self%r == 0) then
      call self%position_pass(status)
      return
    end if
    self%closure_solves = self%closure_solves + 1
    associate (x => self%x_r, start => self%start_r, res => self%res_r)
    do k = 1, self%r
      start(k) = self%scalars(self%beta(k))%q
    end do
    ! Newton from the warm start
    x = start
    converged = .false.
    do it = 1, 4
      call self%residual(x, res, status)
      if (.not. status%ok()) exit
      if (maxval(abs(res)) <= 1e-3_wp*self%closure_tolerance) then
        converged = .true.
        exit
      end if
      call factor_closure(self, solve_status)
      if (.not. solve_status%ok()) exit
      call dgetrs('N', self%r, 1, self%jlu, self%r, self%ipiv, res, self%r, info)
      x = x - res
    end do
    if (.not. converged) then
      if (status%ok()) then
        call self%residual(x, res, status)
        converged = status%ok() .and. maxval(abs(res)) <= self%closure_tolerance
      end if
    end if
    if (.not. converged) then
      ! HYBRJ from the warm start (thesis (3.25) with MINPACK's safeguards)
      status = status_t()
      x = start
      self%hybrj_solves = self%hybrj_solves + 1
      call solve_nonlinear(self, x, self%closure_options, result, solve_status)
      call self%residual(x, res, status)
      if (.not. solve_status%ok() .or. .not. status%ok()) then
        if (status%ok()) status = solve_status
        call prefix_status(status, 'closure failed at '//worst_loop(self))
        return
      end if
      ! polish with Newton steps
      do it = 1, 3
        if (maxval(abs(res)) <= 1e-3_wp*self%closure_tolerance) exit
        call factor_closure(self, status)
        if (.not. status%ok()) return
        call dgetrs('N', self%r, 1, self%jlu, self%r, self%ipiv, res, self%r, info)
        x = x - res
        call self%residual(x, res, status)
        if (.not. status%ok()) return
      end do
      if (maxval(abs(res)) > self%closure_tolerance) then
        call set_status(status, STATUS_NOT_CONVERGED, 'closure failed at '//worst_loop(self))
        return
      end if
    end if
    end associate
    call factor_closure(self, status)
    if (.not. status%ok()) call prefix_status(status, 'closure')
  end subroutine set_positions

  !> At the start: the loops must close from the given beta and J_beta must be
  !> well conditioned (reciprocal condition number above 1e-10).
  subroutine check_start(self, q, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:)
    type(status_t), intent(inout) :: status
    real(wp) :: work(4*max(self%r, 1)), anorm, rcond
    integer :: iwork(max(self%r, 1)), info, k
    character(len=16) :: num
    if (.not. status%ok()) return
    call self%set_positions(q, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'at the start')
      return
    end if
    if (self%r == 0) return
    anorm = maxval(sum(abs(self%jbeta), dim=1))
    call dgecon('1', self%r, self%jlu, self%r, anorm, rcond, work, iwork, info)
    if (rcond < 1e-10_wp) then
      k = minloc([(abs(self%jlu(info, info)), info = 1, self%r)], dim=1)   ! the weakest pivot
      write (num, '(es10.3)') rcond
      call set_status(status, STATUS_INVALID_INPUT, 'at the start the closure Jacobian is singular '// &
        '(reciprocal condition '//trim(adjustl(num))//'): '//describe_dependent(self, k)// &
        ' is not determined by its closure measurements')
    end if
  end subroutine check_start

  !> Sets q' (positions already set) and beta' (3.30).
  subroutine set_velocities(self, qd)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: qd(:)
    integer :: k, info
    do k = 1, self%f
      self%scalars(self%q(k))%qd = qd(k)
    end do
    do k = 1, self%r
      self%scalars(self%beta(k))%qd = 0
    end do
    call self%velocity_pass()
    if (self%r == 0) return
    do k = 1, self%r
      self%work_r(k) = self%scalars(self%closure(k))%qd
    end do
    call dgetrs('N', self%r, 1, self%jlu, self%r, self%ipiv, self%work_r, self%r, info)
    do k = 1, self%r
      self%scalars(self%beta(k))%qd = -self%work_r(k)
    end do
    call self%velocity_pass()
  end subroutine set_velocities

  !> Sets q'' (velocities already set) and beta'' (3.31).
  subroutine set_accelerations(self, qdd)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: qdd(:)
    integer :: k, info
    do k = 1, self%f
      self%scalars(self%q(k))%qdd = qdd(k)
    end do
    do k = 1, self%r
      self%scalars(self%beta(k))%qdd = 0
    end do
    call self%acceleration_pass()
    if (self%r == 0) return
    do k = 1, self%r
      self%work_r(k) = self%scalars(self%closure(k))%qdd
    end do
    call dgetrs('N', self%r, 1, self%jlu, self%r, self%ipiv, self%work_r, self%r, info)
    do k = 1, self%r
      self%scalars(self%beta(k))%qdd = -self%work_r(k)
    end do
    call self%acceleration_pass()
  end subroutine set_accelerations

  !> Generalized forces at the q's (into gq) with the loops in equilibrium:
  !> lambda = -J_beta^-T Q^_beta (3.32)-(3.33).
  subroutine inverse_dynamics(self, inertia, applied)
    class(mechanism_t), intent(inout) :: self
    logical, intent(in) :: inertia, applied
    integer :: k, info
    self%lambda = 0
    call self%force_pass(inertia, applied, self%lambda)
    if (self%r > 0) then
      do k = 1, self%r
        self%lambda(k) = self%scalars(self%beta(k))%force
      end do
      call dgetrs('T', self%r, 1, self%jlu, self%r, self%ipiv, self%lambda, self%r, info)
      self%lambda = -self%lambda
      call self%force_pass(inertia, applied, self%lambda)
    end if
    do k = 1, self%f
      self%gq(k) = self%scalars(self%q(k))%force
    end do
  end subroutine inverse_dynamics

  !> Normal force at each contact after a force pass, N = -z_D . f_D.
  subroutine normal_forces(self, n)
    class(mechanism_t), intent(in) :: self
    real(wp), intent(out) :: n(:)
    integer :: k
    do k = 1, size(self%contacts)
      associate (fr => self%frames(self%contacts(k)%frame))
        n(k) = -dot_product(fr%rot(:, 3), fr%force)
      end associate
    end do
  end subroutine normal_forces

  ! ------------------------------------------------------ equations of motion

  !> q'' from M(q) q'' + Q^(q, q') = Q_applied (3.36), with contact friction.
  !> Leaves M in `mass`, Q_bar0 in `bias`, q'' in `qdd`. The velocity and
  !> acceleration states are overwritten (use `evaluate` for a consistent state).
  subroutine dynamics(self, q, qd, qdd, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:), qd(:)
    real(wp), intent(out) :: qdd(:)
    type(status_t), intent(inout) :: status
    real(wp) :: w(3), s_old
    integer :: i, c, k, nc, info, it
    logical :: consistent

    qdd = 0
    call self%set_positions(q, status)
    if (.not. status%ok()) return
    call self%set_velocities(qd)
    do c = 1, size(self%contacts)
      associate (ct => self%contacts(c))
        w = self%frames(ct%frame)%v
        ct%direction = w/sqrt(dot_product(w, w) + ct%regularization_speed**2)
        ct%load = -ct%viscous*w
      end associate
    end do
    self%work_f = 0
    call self%set_accelerations(self%work_f)
    call self%inverse_dynamics(.true., .true.)
    self%bias = self%gq
    nc = size(self%coulomb)
    if (nc > 0) then
      call self%normal_forces(self%work_c)
      do k = 1, nc
        self%n0(k) = self%work_c(self%coulomb(k))
      end do
    end if

    ! M column by column: q'' = e_i with all velocities zero, applied forces off
    do k = 1, self%n_frames
      self%frames(k)%omega = 0
      self%frames(k)%v = 0
    end do
    self%scalars%qd = 0
    do c = 1, size(self%contacts)
      self%contacts(c)%load = 0
    end do
    do i = 1, self%f
      self%work_f = 0
      self%work_f(i) = 1
      call self%set_accelerations(self%work_f)
      call self%inverse_dynamics(.true., .false.)
      self%mass(:, i) = -self%gq
      if (nc > 0) then
        call self%normal_forces(self%work_c)
        do k = 1, nc
          self%g_mat(k, i) = self%work_c(self%coulomb(k))
        end do
      end if
    end do
    do i = 1, self%f   ! symmetric part, element-wise (no temporary)
      do k = 1, self%f
        self%chol(k, i) = 0.5_wp*(self%mass(k, i) + self%mass(i, k))
      end do
    end do
    call dpotrf('L', self%f, self%chol, self%f, info)
    if (info /= 0) then
      call set_status(status, STATUS_DOMAIN, 'the mass matrix is not positive definite: generalized '// &
        'coordinate '''//trim(self%scalar_names(self%q(info)))//''' has no inertia (a massless body or '// &
        'a mass without rotational inertia on a pure rotation)')
      return
    end if
    if (nc == 0) then
      qdd = self%bias
      call dpotrs('L', self%f, 1, self%chol, self%f, qdd, self%f, info)
      self%qdd = qdd
      return
    end if

    ! Coulomb friction: unit loads -w^ at each contact, then the block system
    do k = 1, nc
      do c = 1, size(self%contacts)
        self%contacts(c)%load = 0
      end do
      self%contacts(self%coulomb(k))%load = -self%contacts(self%coulomb(k))%direction
      call self%inverse_dynamics(.false., .false.)
      self%p_mat(:, k) = self%gq
      call self%normal_forces(self%work_c)
      do c = 1, nc
        self%h_mat(c, k) = self%work_c(self%coulomb(c))
      end do
    end do
    do k = 1, nc
      self%mu_s(k) = self%contacts(self%coulomb(k))%mu
    end do
    consistent = .false.
    do it = 1, 6
      self%block = 0
      self%block(1:self%f, 1:self%f) = self%mass
      do k = 1, nc
        self%block(1:self%f, self%f + k) = -self%p_mat(:, k)*self%mu_s(k)
        self%block(self%f + 1:, self%f + k) = -self%h_mat(:, k)*self%mu_s(k)
        self%block(self%f + k, self%f + k) = self%block(self%f + k, self%f + k) + 1
      end do
      self%block(self%f + 1:, 1:self%f) = -self%g_mat
      self%block_rhs(1:self%f) = self%bias
      self%block_rhs(self%f + 1:) = self%n0
      call dgetrf(self%f + nc, self%f + nc, self%block, self%f + nc, self%ipiv_block, info)
      if (info /= 0) then
        call set_status(status, STATUS_DOMAIN, 'the equations of motion with Coulomb friction are singular')
        return
      end if
      call dgetrs('N', self%f + nc, 1, self%block, self%f + nc, self%ipiv_block, self%block_rhs, &
                  self%f + nc, info)
      consistent = .true.
      do k = 1, nc
        s_old = sign(1.0_wp, self%mu_s(k))
        if (self%block_rhs(self%f + k)*s_old < 0) then
          consistent = .false.
          self%mu_s(k) = -self%mu_s(k)
        end if
      end do
      if (consistent) exit
    end do
    if (.not. consistent) then
      call set_status(status, STATUS_DOMAIN, 'Coulomb friction: no consistent signs of the normal forces '// &
                      '(the friction law has no unique solution here, a Painleve-type paradox)')
      return
    end if
    qdd = self%block_rhs(1:self%f)
    self%qdd = qdd
    do k = 1, nc
      self%contacts(self%coulomb(k))%normal_force = self%block_rhs(self%f + k)
    end do
  end subroutine dynamics

  !> The complete state at (q, q'): accelerations, cut forces, normal and
  !> friction forces of every contact; returns the inverse-dynamics residual
  !> max |Q_bar| (zero up to rounding when everything is consistent).
  subroutine evaluate(self, q, qd, residual, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:), qd(:)
    real(wp), intent(out) :: residual
    type(status_t), intent(inout) :: status
    real(wp) :: qdd(self%f), nvec(size(self%contacts)), w(3)
    integer :: c, k
    residual = huge(1.0_wp)
    call self%dynamics(q, qd, qdd, status)
    if (.not. status%ok()) return
    call self%set_velocities(qd)
    do c = 1, size(self%contacts)
      associate (ct => self%contacts(c))
        w = self%frames(ct%frame)%v
        ct%load = -ct%viscous*w
      end associate
    end do
    do k = 1, size(self%coulomb)
      associate (ct => self%contacts(self%coulomb(k)))
        ct%load = ct%load - ct%mu*abs(ct%normal_force)*ct%direction
      end associate
    end do
    call self%set_accelerations(qdd)
    call self%inverse_dynamics(.true., .true.)
    residual = maxval(abs(self%gq))
    call self%normal_forces(nvec)
    do c = 1, size(self%contacts)
      self%contacts(c)%normal_force = nvec(c)
      self%contacts(c)%friction = self%contacts(c)%load
    end do
  end subroutine evaluate

  !> Kinetic and potential energy of all mass elements at the current state (J).
  subroutine energy(self, kinetic, potential)
    class(mechanism_t), intent(in) :: self
    real(wp), intent(out) :: kinetic, potential
    real(wp) :: t, v
    integer :: k
    kinetic = 0
    potential = 0
    do k = 1, self%n_elements
      call self%elements(k)%e%energy(self%frames, t, v)
      kinetic = kinetic + t
      potential = potential + v
    end do
  end subroutine energy

  !> max |g - target| over all closure measurements at the current positions.
  real(wp) function closure_residual(self) result(e)
    class(mechanism_t), intent(in) :: self
    integer :: k
    e = 0
    do k = 1, self%r
      e = max(e, abs(self%scalars(self%closure(k))%q - self%target(k)))
    end do
  end function closure_residual
end module kinetostatics_mechanism
