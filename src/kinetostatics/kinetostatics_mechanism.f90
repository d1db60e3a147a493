!> Mechanisms: transmission elements chained from the ground frame, closed
!> loops, contacts, force laws, and the equations of motion in minimal
!> coordinates (thesis 3.3, 3.4).
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
!> A Newton iterate outside a surface's parameter domain during a run (warm
!> start) ends the solve with STATUS_DOMAIN at once, the scalars left at that
!> iterate: from a warm start the first Newton step is right to second order,
!> so the solution lies outside too; the integrator shortens its step, and the
!> root functions of the domain edges see where the joint went.
!> Then beta' = -J_beta^-1 f^ (3.30), beta'' = -J_beta^-1 f^' (3.31), and the cut
!> forces lambda = -J_beta^-T Q^_beta ((3.33): the printed form lacks the inverse).
!> J_beta (and J_x below) are block diagonal, one block per set of loops and
!> rate constraints that share an entry, each column filled by a velocity
!> pass over only the elements its rate reaches, factored and solved block by
!> block (kinetostatics_closure_blocks; one block and full passes with
!> set_blocked(.false.) or an element of unknown links).
!>
!> Velocity-level constraints (rolling, thesis (3.85); METHOD-PART2 A.3):
!> outputs c of constraint elements that must vanish (e.g. the tangential slip
!> of contact_rolling), with as many dependent rates sigma' among the
!> coordinates. The coordinates q are all integrated; the independent rates,
!> the speeds s, are the rest: q' = B(q) s, so the ODE state is [q, s]. At
!> velocity level the unknown rates x = [beta'; sigma'] solve the combined
!> linear system [g'; c] = 0 with the matrix J_x of (3.21) extended by the
!> sigma columns (one velocity pass per column), at acceleration level
!> [g''; c'] = 0 with the same matrix, and the cut forces [lambda; mu] =
!> -J_x^-T [Q_beta; Q_sigma] (mu: the static friction of rolling).
!> Kinematic coordinates (set_kinematic) are integrated coordinates whose rates
!> an element computes itself in its velocity pass (the pose of a body under a
!> velocity-level contact, contact_velocity_level): they are neither speeds nor
!> solved. Without either, s = q' and everything is as before.
!>
!> Loads: gravity acts in the mass elements (kinetostatics_mass); every other
!> load is a force law (kinetostatics_force_law), evaluated once per state with
!> the frames, scalars and contact kinematics (kinetostatics_contact).
!>
!> Equations of motion (3.34)-(3.36): the inverse dynamics Q_bar(q, s, s')
!> (generalized forces of d'Alembert + applied forces at the speeds, loops and
!> velocity constraints closed by lambda, mu) is affine in s': Q_bar = Q_bar0 -
!> M s'. One pass with s' = 0 (inertia, gravity and the explicit laws) gives
!> Q_bar0 = -Q^ and the normal forces N0.
!>
!> M and G from the partial twists: every frame's twist is linear in the
!> speeds, so with the velocities zero the acceleration state of s' = e_i
!> (the closure solved) is column i of the partial twists (alpha, a) of the
!> mass elements' frames (and of the scaled laws' load frames: `tracked`).
!> The inertial wrench of a mass per unit s'_i is (3.23) at rest and M(j, i)
!> = -(twist_j . wrench_i) = sum m p_j . p_i + alpha_j . Theta_w alpha_i (p
!> the centre of mass's acceleration), so one acceleration pass per speed
!> over the elements it moves (kinetostatics_closure_blocks,
!> build_mass_columns) replaces the column's two force passes. Every normal
!> force is linear in the wrenches W at the tracked frames, N_c = -normal_sign
!> nu_c . W (twist_normal_forces: the cut forces through J_x^-T by one solve
!> per contact, a frame's force through one pass moving the frame along its
!> normal), which gives G = N per unit s' and, with the scaled laws' unit
!> loads as W, H and P (the loads' powers on the speeds' twists). Only the
!> mass elements have inertia (kinetostatics_mass). A mechanism with an
!> element of unknown links forms M and G by the inverse-dynamics pass per
!> speed instead (s' = e_i, velocities zero, applied forces off: -M e_i) and
!> P and H by one per scaled law, as does a scaled law with a load on a frame
!> that is not tracked.
!>
!> Normal forces and scaled laws: every contact's normal force N (rules in
!> kinetostatics_contact) is linear in the loads of a force pass, so
!> N = N0 + G q'' + sum_k H_k |N_c(k)|, where the last sum runs over the scaled
!> laws k (load |N_c(k)| u_k with u_k from the law, e.g. Coulomb friction
!> u = -mu w/|w| (4.28)). With s_j = sign N_j, P_k and H_k the generalized
!> forces and normal forces of the unit load u_k alone (as one force pass with
!> it would give them), and the contacts j of the scaled laws as
!> extra unknowns, the equations of motion are the exact block system
!>     [ M            -sum_k P_k s_j(k) e_j(k)^T   ] [q'']   [Q_bar0]
!>     [ -G_j   I - sum_k H_j,k s_j(k) e_j(k)^T    ] [N_j] = [N0_j  ],
!> its signs iterated until consistent (normally at once; no consistent signs:
!> a Painleve-type paradox, reported). The other contacts' N follow from the
!> affine form. The law's power is |N| times its unit power.
module kinetostatics_mechanism
  use base_kinds, only: wp
  use base_vector, only: cross
  use base_text, only: format_short
  use base_status, only: status_t, set_status, prefix_status, STATUS_OK, STATUS_INVALID_INPUT, &
    STATUS_NOT_CONVERGED, STATUS_DOMAIN
  use numerics_nonlinear, only: nonlinear_system_t, nonlinear_options_t, nonlinear_result_t, &
    solve_nonlinear
  use numerics_linear_algebra, only: lu_factor, lu_solve, lu_reciprocal_condition, one_norm, cholesky_factor, &
    cholesky_solve, transposed_product, symmetric_transposed_product
  use kinetostatics_state, only: element_t, element_box_t, frame_state_t, scalar_state_t, domain_edge_t
  use kinetostatics_contact, only: contact_t, contact_state_t, contact_kinematics, NORMAL_FRAME_FORCE, &
    NORMAL_CUT_FORCE
  use kinetostatics_force_law, only: force_law_t, force_law_box_t
  use kinetostatics_closure_blocks, only: closure_blocks_t, element_reach_t, build_closure_blocks, &
    find_element_links, downstream_of
  implicit none (type, external)
  private
  public :: mechanism_t, loop_t, rate_constraint_t, surface_edge_t
  public :: LOADS_NONE, LOADS_EXPLICIT, LOADS_ALL

  integer, parameter :: ROLE_FIXED = 0, ROLE_Q = 1, ROLE_BETA = 2, ROLE_MEASURE = 3
  !> Which law loads a force pass applies: none, the explicit laws, all laws
  !> (scaled ones times |N|); a positive value k: the unit load of law k alone.
  integer, parameter :: LOADS_NONE = 0, LOADS_EXPLICIT = -1, LOADS_ALL = -2

  type :: loop_t
    character(len=:), allocatable :: name
    integer, allocatable :: measurements(:)   ! scalar indices of the closure measurements
    real(wp), allocatable :: targets(:)       ! their required values
    integer, allocatable :: dependents(:)     ! scalar indices of the dependent coordinates
    integer :: antiparallel(2) = 0            ! frames whose z axes must point against each other (0: none)
  end type loop_t

  !> A velocity-level constraint: outputs c (rates that must vanish) and as
  !> many coordinates whose rates become dependent.
  type :: rate_constraint_t
    character(len=:), allocatable :: name
    integer, allocatable :: outputs(:)        ! scalar indices of the constraint outputs
    integer, allocatable :: dependents(:)     ! scalar indices of coordinates with dependent rates
  end type rate_constraint_t

  !> A finite, non-periodic edge of an element's parameter domain (a surface
  !> joint's); its event is placed `margin` inside it (domain_edge_margin).
  type, extends(domain_edge_t) :: surface_edge_t
    integer :: element = 0                    ! the element (a surface joint)
  end type surface_edge_t

  type, extends(nonlinear_system_t) :: mechanism_t
    type(frame_state_t), allocatable :: frames(:)
    type(scalar_state_t), allocatable :: scalars(:)
    character(len=32), allocatable :: frame_names(:), scalar_names(:)
    integer, allocatable :: role(:)
    type(element_box_t), allocatable :: elements(:)
    type(loop_t), allocatable :: loops(:)
    type(rate_constraint_t), allocatable :: rate_constraints(:)
    type(contact_t), allocatable :: contacts(:)
    type(contact_state_t), allocatable :: contact_states(:)   ! kinematics at the last law evaluation
    type(force_law_box_t), allocatable :: laws(:)
    type(surface_edge_t), allocatable :: edges(:)
    integer :: n_frames = 0, n_scalars = 0, n_elements = 0, n_laws = 0, f = 0, r = 0
    integer :: ns = 0                         !< number of speeds (independent rates); f without rate constraints
    integer :: nd = 0                         !< number of dependent rates sigma
    integer, allocatable :: q(:), beta(:), closure(:)
    integer, allocatable :: speeds(:)         ! positions in q of the speeds
    integer, allocatable :: sigma(:), rate_outputs(:)   ! scalar indices: dependent rates, constraint outputs
    integer, allocatable :: kinematic(:)      ! scalar indices of the kinematic coordinates
    integer, allocatable :: monitors(:)       ! scalars recorded with every state (add_monitor)
    character(len=8), allocatable :: monitor_units(:)
    real(wp), allocatable :: target(:)
    type(nonlinear_options_t) :: closure_options = nonlinear_options_t(xtol=1e-12_wp, &
      residual_tolerance=1e-8_wp)
    real(wp) :: closure_tolerance = 1e-10_wp   !< max |g - target| accepted (measurement units)
    logical :: ready = .false.
    logical :: warm = .false.                  !< a closure has converged in this run (a warm start exists)
    logical :: converged = .false.             !< beta holds it (else start_r does: the last solve failed)
    ! the (t, q, s) and law switches of the last completed `dynamics`: its results still hold while no
    ! position pass or law evaluation has run since (a record at the state a root function just saw)
    logical :: dynamics_known = .false.
    real(wp) :: known_t = 0
    real(wp), allocatable :: known_q(:), known_s(:)
    logical, allocatable :: known_active(:)
    integer :: dynamics_reused = 0
    ! results of the last evaluation
    real(wp), allocatable :: lambda(:)        ! cut forces of the closure measurements
    real(wp), allocatable :: mu(:)            ! cut forces of the rate constraints
    real(wp), allocatable :: rates(:)         ! q' of every coordinate (f), from the last set_velocities
    real(wp), allocatable :: qdd(:)           ! s' of the speeds (ns)
    real(wp), allocatable :: mass(:, :), bias(:)   ! M and Q_bar0 = -Q^
    real(wp), allocatable :: normal(:)        ! N of every contact (from the last dynamics)
    real(wp), allocatable :: law_factor(:)    ! 1 for explicit laws, |N| for scaled ones
    real(wp), allocatable :: law_power(:)     ! W, power of each law's loads
    real(wp), allocatable :: law_roots(:)     ! root functions of the laws, at the last law evaluation
    integer, allocatable :: law_root_start(:) ! first index of law k's roots in law_roots
    integer :: closure_solves = 0, hybrj_solves = 0
    !> the closure's blocks (kinetostatics_closure_blocks); set blocked = .false. before finalize
    !> for one block and full passes (the unblocked computation, for comparison)
    logical :: blocked = .true.
    type(element_reach_t) :: reach
    type(closure_blocks_t) :: blocks
    integer, allocatable :: beta_pass(:)   ! the elements the dependent coordinates reach (downstream_of)
    integer, allocatable :: unknowns_pass(:)   ! ... and those the unknown rates [beta'; sigma'] reach
    integer, allocatable :: unknowns(:), rows(:)   ! scalars of x = [beta; sigma] and of the rows [g; c]
    ! work arrays
    real(wp), allocatable :: work_r(:), gq(:)
    real(wp), allocatable :: work_x(:)   ! the combined [beta'; sigma'] system
    real(wp), allocatable :: x_r(:), start_r(:), res_r(:), work_f(:), work_c(:)   ! (gfortran puts
                                                                                  ! automatic arrays on the heap)
    real(wp), allocatable :: unit_power(:)
    real(wp), allocatable :: chol(:, :), g_mat(:, :), p_mat(:, :), h_mat(:, :), n0(:), block(:, :), &
      block_rhs(:), signs(:)
    integer, allocatable :: scaled_laws(:)    ! indices of the scaled laws
    integer, allocatable :: block_row(:)      ! row (1..nb) of each scaled law's contact in the block
    integer, allocatable :: block_contact(:)  ! contact of each block row
    integer, allocatable :: ipiv_block(:)
    ! M and G from the partial twists of the tracked frames (dynamics, find_mass_twists); with an
    ! element of unknown links (twist_route false) from inverse-dynamics passes per column instead
    logical :: twist_route = .false.
    ! the twists' columns from the velocity maps (no column touches a block: J e_i with the
    ! acceleration maps' operations on the nonzero terms, for about half their work)
    logical :: velocity_columns = .false.
    integer, allocatable :: velocity_clear(:), velocity_clear_start(:)   ! (build_velocity_clears)
    integer, allocatable :: tracked(:)           ! frames whose twists are kept (masses', scaled loads')
    integer, allocatable :: tracked_slot(:)      ! each frame's place in tracked (0: not kept)
    integer, allocatable :: masses(:), mass_slot(:)   ! the mass elements, their frames' places in tracked
    integer, allocatable :: normal_contacts(:)   ! contacts with N from the force on a frame (normal_pass order)
    real(wp), allocatable :: twist(:, :, :)      ! (6, tracked, ns): (alpha, a) per unit s'_i at rest (= (omega, v) per unit s_i)
    real(wp), allocatable :: wrench(:, :, :)     ! (6, tracked, ns): inertial (torque, force) per unit s'_i
    integer, allocatable :: moving_unknowns(:)   ! the unknowns whose open motion moves a tracked frame
    real(wp), allocatable :: unknown_twist(:, :, :)   ! (6, tracked, moving unknowns): per unit rate, nothing solved
    real(wp), allocatable :: nu(:, :, :)         ! (6, tracked, contacts): N = -normal_sign nu_c . wrenches
    real(wp), allocatable :: load_wrench(:, :)   ! (6, tracked): a scaled law's unit loads
  contains
    procedure :: add_frame, add_scalar, add_element, add_loop, add_contact, add_law, set_coordinates, finalize
    procedure :: add_rate_constraint, set_kinematic, set_loop_branch, add_monitor
    procedure :: frame_index, scalar_index, contact_index, law_index
    procedure :: residual => mechanism_residual
    procedure :: jacobian => mechanism_jacobian
    procedure :: position_pass, velocity_pass, acceleration_pass, force_pass, record_pass
    procedure :: set_positions, set_velocities, set_accelerations, inverse_dynamics, evaluate_laws
    procedure :: check_start, set_blocked
    procedure :: dynamics, evaluate, energy, closure_residual, normal_forces, law_force
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
    allocate (self%elements(0), self%loops(0), self%contacts(0), self%laws(0), self%rate_constraints(0))
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

  !> The branch of loop `name`: the z axes of frames frame_1 and frame_2 must
  !> point against each other (z_1 . z_2 < 0), as the normals of two surfaces
  !> in contact do; conditions like g4, g5 of (3.86) also hold on the branch
  !> with parallel normals. A closure that lands there fails with
  !> STATUS_DOMAIN (at the start: bad input; in a run: the step is shortened).
  subroutine set_loop_branch(self, name, frame_1, frame_2, status)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_1, frame_2
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, size(self%loops)
      if (self%loops(k)%name == name) then
        self%loops(k)%antiparallel = [frame_1, frame_2]
        return
      end if
    end do
    call set_status(status, STATUS_INVALID_INPUT, 'set_loop_branch: there is no loop '''//name//'''')
  end subroutine set_loop_branch

  !> A velocity-level constraint: the rates of the scalars `outputs` (written by
  !> constraint elements) must vanish; the rates of the coordinates
  !> `dependents` (as many, among set_coordinates) follow from that.
  subroutine add_rate_constraint(self, name, outputs, dependents, status)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: outputs(:), dependents(:)
    type(status_t), intent(inout) :: status
    type(rate_constraint_t) :: c
    call ensure_ground(self)
    if (size(outputs) /= size(dependents)) then
      call set_status(status, STATUS_INVALID_INPUT, 'rate constraint '''//name//''': needs as many '// &
                      'outputs as coordinates with dependent rates')
      return
    end if
    c%name = name
    c%outputs = outputs
    c%dependents = dependents
    self%rate_constraints = [self%rate_constraints, c]
    self%role(outputs) = ROLE_MEASURE
  end subroutine add_rate_constraint

  !> A scalar (e.g. a measurement that watches a velocity-level contact's
  !> drift) recorded with every state, in `units`.
  subroutine add_monitor(self, scalar, units)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: scalar
    character(len=*), intent(in) :: units
    if (.not. allocated(self%monitors)) allocate (self%monitors(0), self%monitor_units(0))
    self%monitors = [self%monitors, scalar]
    self%monitor_units = [character(len=8) :: self%monitor_units, units]
  end subroutine add_monitor

  !> Coordinates (among set_coordinates) whose rates an element writes in its
  !> velocity pass: integrated, but neither speeds nor solved.
  subroutine set_kinematic(self, scalars)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: scalars(:)
    self%kinematic = scalars
  end subroutine set_kinematic

  !> A contact between the body carrying frame_a (1: the ground) and the body
  !> carrying frame_b at the contact-point frame point_frame (origin at the
  !> contact point, z along the surface normal); returns its index. The
  !> normal force is N = -normal_sign z_F . f_F at frame F = normal_frame
  !> (default: point_frame), or, if normal_measurement (a closure measurement's
  !> scalar index) is given, N = normal_sign lambda of that measurement.
  !> normal_sign (+1 or -1, default +1) makes N positive while the bodies
  !> press on each other; n = normal_sign z points from A into B. One-sided
  !> (default): N falling through zero is the lift-off event.
  integer function add_contact(self, name, frame_a, frame_b, point_frame, normal_sign, normal_frame, &
                               normal_measurement, one_sided) result(k)
    class(mechanism_t), intent(inout) :: self
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_a, frame_b, point_frame
    real(wp), intent(in), optional :: normal_sign
    integer, intent(in), optional :: normal_frame, normal_measurement
    logical, intent(in), optional :: one_sided
    type(contact_t) :: c
    call ensure_ground(self)
    c%name = name
    c%frame_a = frame_a
    c%frame_b = frame_b
    c%point_frame = point_frame
    c%normal_frame = point_frame
    if (present(normal_sign)) c%normal_sign = normal_sign
    if (present(normal_frame)) c%normal_frame = normal_frame
    if (present(normal_measurement)) then
      c%normal_rule = NORMAL_CUT_FORCE
      c%normal_measurement = normal_measurement
    end if
    if (present(one_sided)) c%one_sided = one_sided
    self%contacts = [self%contacts, c]
    k = size(self%contacts)
  end function add_contact

  !> Adds a force law (a copy of `law`); its index is n_laws afterwards.
  subroutine add_law(self, law)
    class(mechanism_t), intent(inout) :: self
    class(force_law_t), intent(in) :: law
    type(force_law_box_t), allocatable :: grown(:)
    integer :: k
    call ensure_ground(self)
    allocate (grown(self%n_laws + 1))
    do k = 1, self%n_laws
      call move_alloc(self%laws(k)%law, grown(k)%law)
    end do
    allocate (grown(self%n_laws + 1)%law, source=law)
    call move_alloc(grown, self%laws)
    self%n_laws = self%n_laws + 1
  end subroutine add_law

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

  integer function contact_index(self, name) result(k)
    class(mechanism_t), intent(in) :: self
    character(len=*), intent(in) :: name
    do k = 1, size(self%contacts)
      if (self%contacts(k)%name == name) return
    end do
    k = 0
  end function contact_index

  integer function law_index(self, name) result(k)
    class(mechanism_t), intent(in) :: self
    character(len=*), intent(in) :: name
    do k = 1, self%n_laws
      if (self%laws(k)%law%name == name) return
    end do
    k = 0
  end function law_index

  !> Checks the structure and allocates every work array.
  subroutine finalize(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k, nc, ns, nb, nr
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
    call find_speeds(self, status)
    if (.not. status%ok()) return
    nc = size(self%contacts)
    call check_contacts(self, status)
    if (status%ok()) call check_laws(self, status)
    if (.not. status%ok()) return
    call find_edges(self)
    call find_closure_blocks(self)
    call check_record_only(self, status)
    if (.not. status%ok()) return

    ! scaled laws and the contacts whose normal forces the block system solves for
    allocate (self%scaled_laws(0), self%block_contact(0))
    do k = 1, self%n_laws
      if (.not. self%laws(k)%law%scaled) cycle
      self%scaled_laws = [self%scaled_laws, k]
      if (.not. any(self%block_contact == self%laws(k)%law%contact)) &
        self%block_contact = [self%block_contact, self%laws(k)%law%contact]
    end do
    ns = size(self%scaled_laws)
    nb = size(self%block_contact)
    allocate (self%block_row(ns))
    do k = 1, ns
      self%block_row(k) = findloc(self%block_contact, self%laws(self%scaled_laws(k))%law%contact, dim=1)
    end do
    allocate (self%law_root_start(self%n_laws + 1))
    nr = 0
    do k = 1, self%n_laws
      self%law_root_start(k) = nr + 1
      nr = nr + self%laws(k)%law%root_count()
    end do
    self%law_root_start(self%n_laws + 1) = nr + 1

    associate (n => self%ns, nx => self%r + self%nd)
      allocate (self%lambda(self%r), self%mu(self%nd), self%rates(self%f), self%qdd(n), self%mass(n, n), &
                self%bias(n))
      allocate (self%work_r(self%r), self%gq(n), self%work_x(nx))
      allocate (self%x_r(self%r), self%start_r(self%r), self%res_r(self%r), self%work_f(n), self%work_c(nc))
      allocate (self%known_q(self%f), self%known_s(n), self%known_active(self%n_laws))
      allocate (self%contact_states(nc), self%normal(nc), self%law_factor(self%n_laws), &
                self%law_power(self%n_laws), self%unit_power(self%n_laws), self%law_roots(nr))
      allocate (self%chol(n, n), self%g_mat(nc, n), self%p_mat(n, ns), &
                self%h_mat(nc, ns), self%n0(nc), self%block(n + nb, n + nb), &
                self%block_rhs(n + nb), self%signs(nb))
      allocate (self%ipiv_block(n + nb))
    end associate
    self%lambda = 0
    self%mu = 0
    self%rates = 0
    self%qdd = 0
    self%normal = 0
    self%law_factor = 1
    self%law_power = 0
    self%law_roots = 1
    self%ready = .true.
  end subroutine finalize

  !> The closure in blocks with partial passes (blocked, the default) or as
  !> one block with full passes (the unblocked computation, for comparison);
  !> after finalize. The next closure starts cold from the current scalars.
  subroutine set_blocked(self, blocked)
    class(mechanism_t), intent(inout) :: self
    logical, intent(in) :: blocked
    self%blocked = blocked
    if (.not. self%ready) return
    call find_closure_blocks(self)
    self%converged = .false.
    self%warm = .false.
    self%dynamics_known = .false.
  end subroutine set_blocked

  !> The closure's blocks: x = [beta; sigma], rows [g; c], one group per loop
  !> and per rate constraint.
  subroutine find_closure_blocks(self)
    class(mechanism_t), intent(inout) :: self
    integer :: group_start(size(self%loops) + size(self%rate_constraints) + 1), k, g
    self%unknowns = [self%beta, self%sigma]
    self%rows = [self%closure, self%rate_outputs]
    g = 1
    group_start(1) = 1
    do k = 1, size(self%loops)
      g = g + 1
      group_start(g) = group_start(g - 1) + size(self%loops(k)%dependents)
    end do
    do k = 1, size(self%rate_constraints)
      g = g + 1
      group_start(g) = group_start(g - 1) + size(self%rate_constraints(k)%dependents)
    end do
    call find_element_links(self%elements, self%n_frames, self%n_scalars, self%reach)
    if (self%blocked) then
      self%beta_pass = downstream_of(self%reach, self%beta, self%n_frames, self%n_scalars, self%n_elements)
      self%unknowns_pass = downstream_of(self%reach, self%unknowns, self%n_frames, self%n_scalars, self%n_elements)
    else
      self%beta_pass = [(k, k = 1, self%n_elements)]
      self%unknowns_pass = self%beta_pass
    end if
    if (self%reach%known) self%beta_pass = pack(self%beta_pass, &   ! check_record_only
      [(.not. self%elements(self%beta_pass(k))%e%record_only, k = 1, size(self%beta_pass))])
    ! a surface joint that beta does not reach is evaluated once per closure
    ! (its first pass), and the velocities after it need its whole geometry:
    ! eager there, the lazy order-1 evaluation would be repeated at order 3
    ! (kinetostatics_surface_joint; the same numbers either way)
    if (self%r > 0) then
      do k = 1, self%n_elements
        if (any(self%beta_pass == k)) cycle
        call self%elements(k)%e%set_eager()
      end do
    end if
    call build_closure_blocks(self%blocks, self%elements, self%reach, self%n_frames, self%n_scalars, &
                              self%unknowns, self%rows, self%r, group_start, self%blocked)
    call find_mass_twists(self)
  end subroutine find_closure_blocks

  !> The frames whose partial twists `dynamics` keeps (every mass element's,
  !> and both frames of each scaled law's contact), the contacts whose normal
  !> force is the force on a frame, and the pass lists
  !> (kinetostatics_closure_blocks, build_mass_columns).
  subroutine find_mass_twists(self)
    class(mechanism_t), intent(inout) :: self
    logical :: keep(self%n_frames)
    integer :: k, c, nt, nx
    keep = .false.
    self%masses = [integer ::]
    do k = 1, self%n_elements
      if (self%elements(k)%e%mass_frame() == 0) cycle
      self%masses = [self%masses, k]
      keep(self%elements(k)%e%mass_frame()) = .true.
    end do
    do k = 1, self%n_laws
      c = self%laws(k)%law%contact
      if (.not. self%laws(k)%law%scaled .or. c < 1) cycle
      keep([self%contacts(c)%frame_a, self%contacts(c)%frame_b]) = .true.
    end do
    keep(1) = .false.   ! the ground never moves
    self%tracked = pack([(k, k = 1, self%n_frames)], keep)
    nt = size(self%tracked)
    self%tracked_slot = [(0, k = 1, self%n_frames)]
    self%tracked_slot(self%tracked) = [(k, k = 1, nt)]
    self%mass_slot = [integer ::]
    do k = 1, size(self%masses)
      self%mass_slot = [self%mass_slot, self%tracked_slot(self%elements(self%masses(k))%e%mass_frame())]
    end do
    self%normal_contacts = pack([(c, c = 1, size(self%contacts))], &
                                self%contacts%normal_rule == NORMAL_FRAME_FORCE)
    call self%blocks%build_mass_columns(self%reach, self%n_frames, self%n_scalars, self%q(self%speeds), &
                                        self%unknowns, self%rows, self%tracked, &
                                        self%contacts(self%normal_contacts)%normal_frame, self%blocked)
    self%twist_route = self%reach%known
    self%velocity_columns = self%blocks%mass_blocked .and. size(self%blocks%touched) == 0
    if (self%velocity_columns) call build_velocity_clears(self)
    nx = self%r + self%nd
    self%moving_unknowns = pack([(k, k = 1, nx)], self%blocks%unknown_pass_start(2:nx + 1) > &
                                                  self%blocks%unknown_pass_start(1:nx))
    if (allocated(self%twist)) deallocate (self%twist, self%wrench, self%unknown_twist, self%nu, self%load_wrench)
    allocate (self%twist(6, nt, self%ns), self%wrench(6, nt, self%ns), &
              self%unknown_twist(6, nt, size(self%moving_unknowns)), &
              self%nu(6, nt, size(self%contacts)), self%load_wrench(6, nt))
  end subroutine find_mass_twists

  !> Dependent rates, constraint outputs and kinematic coordinates must be
  !> coordinates; the speeds are the other coordinates.
  subroutine find_speeds(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    logical :: free(self%f)
    if (.not. allocated(self%kinematic)) allocate (self%kinematic(0))
    if (.not. allocated(self%monitors)) allocate (self%monitors(0), self%monitor_units(0))
    allocate (self%sigma(0), self%rate_outputs(0))
    do k = 1, size(self%rate_constraints)
      self%sigma = [self%sigma, self%rate_constraints(k)%dependents]
      self%rate_outputs = [self%rate_outputs, self%rate_constraints(k)%outputs]
    end do
    self%nd = size(self%sigma)
    free = .true.
    do k = 1, self%nd
      if (.not. any(self%q == self%sigma(k))) then
        call set_status(status, STATUS_INVALID_INPUT, 'rate constraint: '''//trim(self%scalar_names(self%sigma(k)))// &
                        ''' must be a generalized coordinate to have a dependent rate')
        return
      end if
      free(findloc(self%q, self%sigma(k), dim=1)) = .false.
    end do
    do k = 1, size(self%kinematic)
      if (.not. any(self%q == self%kinematic(k))) then
        call set_status(status, STATUS_INVALID_INPUT, 'kinematic coordinate '''// &
                        trim(self%scalar_names(self%kinematic(k)))//''' must be a generalized coordinate')
        return
      end if
      free(findloc(self%q, self%kinematic(k), dim=1)) = .false.
    end do
    self%speeds = pack([(k, k = 1, self%f)], free)
    self%ns = size(self%speeds)
    if (self%ns < 1) call set_status(status, STATUS_INVALID_INPUT, 'mechanism: no independent speeds '// &
      '(every coordinate''s rate is constrained or kinematic)')
  end subroutine find_speeds

  subroutine check_contacts(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        if (.not. all([c%frame_a, c%frame_b, c%point_frame, c%normal_frame] >= 1 .and. &
                      [c%frame_a, c%frame_b, c%point_frame, c%normal_frame] <= self%n_frames)) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': a frame index is not '// &
                          'a frame of the mechanism')
        else if (c%frame_a == c%frame_b) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': the two bodies must '// &
                          'be different (frame_a = frame_b)')
        else if (abs(c%normal_sign) /= 1) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': normal_sign must be +1 or -1')
        else if (c%normal_rule == NORMAL_CUT_FORCE) then
          c%normal_row = findloc(self%closure, c%normal_measurement, dim=1)
          if (c%normal_row == 0) call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name// &
            ''': its normal force must be the cut force of a closure measurement of a loop')
        end if
      end associate
      if (.not. status%ok()) return
    end do
  end subroutine check_contacts

  subroutine check_laws(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%n_laws
      associate (law => self%laws(k)%law)
        if (.not. allocated(law%name)) law%name = 'law'
        if (.not. allocated(law%loads)) then
          call set_status(status, STATUS_INVALID_INPUT, 'force law '''//law%name//''' has no loads '// &
                          '(its constructor must allocate them)')
        else if (law%contact < 0 .or. law%contact > size(self%contacts)) then
          call set_status(status, STATUS_INVALID_INPUT, 'force law '''//law%name//''': contact index '// &
                          'out of range')
        else if (law%scaled .and. law%contact == 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'force law '''//law%name//''' scales with a '// &
                          'normal force but names no contact')
        end if
      end associate
      if (.not. status%ok()) return
    end do
  end subroutine check_laws

  !> The finite, non-periodic edges of every element's domain (element_t's domain_edges).
  subroutine find_edges(self)
    class(mechanism_t), intent(inout) :: self
    type(domain_edge_t), allocatable :: edges(:)
    integer :: k, j
    allocate (self%edges(0))
    do k = 1, self%n_elements
      call self%elements(k)%e%domain_edges(edges)
      self%edges = [self%edges, (surface_edge_t(edges(j), k), j = 1, size(edges))]
    end do
  end subroutine find_edges

  ! ------------------------------------------------------------------ passes

  !> Every element but the record-only ones (record_pass).
  subroutine position_pass(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    self%dynamics_known = .false.
    do k = 1, self%n_elements
      if (self%elements(k)%e%record_only) cycle
      call self%elements(k)%e%position(self%frames, self%scalars, status)
      if (.not. status%ok()) return
    end do
  end subroutine position_pass

  !> The record-only elements (element_t) at the current positions, which
  !> the position pass left as they are: their outputs for a record.
  subroutine record_pass(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%n_elements
      if (.not. self%elements(k)%e%record_only) cycle
      call self%elements(k)%e%position(self%frames, self%scalars, status)
      if (.not. status%ok()) return
    end do
  end subroutine record_pass

  !> Only records may read the outputs of a record-only element (element_t):
  !> no other element, loop, rate constraint, coordinate or contact (force
  !> laws name what they read in their own terms: they must not read them
  !> either). A mechanism whose data flow is not known (an element of
  !> unknown links) evaluates them in every position pass.
  subroutine check_record_only(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    logical :: read_frame(self%n_frames), read_scalar(self%n_scalars)
    integer :: k, i
    if (.not. self%reach%known) then
      do k = 1, self%n_elements
        self%elements(k)%e%record_only = .false.
      end do
      return
    end if
    read_frame = .false.
    read_scalar = .false.
    do k = 1, self%n_elements
      if (self%elements(k)%e%record_only) cycle
      associate (r => self%reach)
        read_frame(r%frame_in(r%frame_in_start(k):r%frame_in_start(k + 1) - 1)) = .true.
        read_scalar(r%scalar_in(r%scalar_in_start(k):r%scalar_in_start(k + 1) - 1)) = .true.
      end associate
    end do
    read_scalar([self%closure, self%rate_outputs, self%q]) = .true.
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        read_frame([c%frame_a, c%frame_b, c%point_frame, c%normal_frame]) = .true.
        if (c%normal_measurement > 0) read_scalar(c%normal_measurement) = .true.
      end associate
    end do
    do k = 1, self%n_elements
      if (.not. self%elements(k)%e%record_only) cycle
      associate (r => self%reach)
        do i = r%frame_out_start(k), r%frame_out_start(k + 1) - 1
          if (read_frame(r%frame_out(i))) call refuse('frame '''//trim(self%frame_names(r%frame_out(i)))//'''')
        end do
        do i = r%scalar_out_start(k), r%scalar_out_start(k + 1) - 1
          if (read_scalar(r%scalar_out(i))) call refuse('scalar '''//trim(self%scalar_names(r%scalar_out(i)))//'''')
        end do
      end associate
      if (.not. status%ok()) return
    end do
  contains
    subroutine refuse(what)
      character(len=*), intent(in) :: what
      if (status%ok()) call set_status(status, STATUS_INVALID_INPUT, 'element '''//self%elements(k)%e%name// &
        ''' is record-only, but its output '//what//' is read by the mechanism (another element, a loop, '// &
        'a rate constraint, a coordinate or a contact)')
    end subroutine refuse
  end subroutine check_record_only

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
  !> (and mu, a component, on the rate constraints' outputs) and the laws'
  !> loads selected by `loads` (LOADS_*) on their frames, and runs the elements
  !> backwards.
  subroutine force_pass(self, inertia, applied, lambda, loads)
    class(mechanism_t), intent(inout) :: self
    logical, intent(in) :: inertia, applied
    real(wp), intent(in) :: lambda(:)
    integer, intent(in) :: loads
    integer :: k
    do k = 1, self%n_frames
      self%frames(k)%torque = 0
      self%frames(k)%force = 0
    end do
    self%scalars%force = 0
    do k = 1, self%r
      self%scalars(self%closure(k))%force = lambda(k)
    end do
    do k = 1, self%nd
      self%scalars(self%rate_outputs(k))%force = self%mu(k)
    end do
    select case (loads)
    case (LOADS_NONE)
    case (LOADS_EXPLICIT, LOADS_ALL)
      do k = 1, self%n_laws
        if (.not. self%laws(k)%law%active) cycle
        if (self%laws(k)%law%scaled .and. loads == LOADS_EXPLICIT) cycle
        call put_loads(self, k, self%law_factor(k))
      end do
    case default
      call put_loads(self, loads, 1.0_wp)
    end select
    do k = self%n_elements, 1, -1
      call self%elements(k)%e%force(self%frames, self%scalars, inertia, applied)
    end do
  end subroutine force_pass

  subroutine put_loads(self, k, factor)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: k
    real(wp), intent(in) :: factor
    integer :: i
    associate (loads => self%laws(k)%law%loads)
      do i = 1, size(loads)
        associate (fr => self%frames(loads(i)%frame))
          fr%force = fr%force + factor*loads(i)%force
          fr%torque = fr%torque + factor*loads(i)%torque
        end associate
      end do
    end associate
  end subroutine put_loads

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

  !> The closure residual after only beta changed since the last position
  !> pass (the Newton iterates of set_positions): the position maps of the
  !> elements beta reaches; the others' inputs and so their outputs are
  !> unchanged (for the rider: the pelvis's surface joint is not evaluated
  !> again). Same values to the bit as mechanism_residual.
  subroutine beta_residual(self, x, f, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    integer :: k
    do k = 1, self%r
      self%scalars(self%beta(k))%q = x(k)
    end do
    f = 0
    self%dynamics_known = .false.
    do k = 1, size(self%beta_pass)
      call self%elements(self%beta_pass(k))%e%position(self%frames, self%scalars, status)
      if (.not. status%ok()) return
    end do
    do k = 1, self%r
      f(k) = self%scalars(self%closure(k))%q - self%target(k)
    end do
  end subroutine beta_residual

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

  !> J_beta column by column: velocity passes with q' = 0, beta' = e_k (3.21),
  !> each over the elements that rate reaches (kinetostatics_closure_blocks).
  !> Destroys the velocity state.
  subroutine closure_jacobian(self, jac)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(out) :: jac(:, :)
    call fill_closure(self, self%r)
    call self%blocks%assemble(.false., jac)
  end subroutine closure_jacobian

  !> Columns 1..last of J_x (last = r: J_beta) into the blocks.
  subroutine fill_closure(self, last)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: last
    call self%blocks%fill(self%elements, self%reach, self%frames, self%scalars, self%unknowns, self%rows, last)
  end subroutine fill_closure

  !> With rate constraints: J_x of the unknown rates [beta'; sigma'] against
  !> [g'; c] (filled), LU-factored block by block.
  subroutine factor_filled_rates(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    type(status_t) :: lapack
    integer :: zero_pivot
    if (self%nd == 0 .or. .not. status%ok()) return
    call self%blocks%factor(.true., lapack, zero_pivot)
    if (.not. lapack%ok()) then
      if (zero_pivot > self%r) then
        call set_status(status, STATUS_NOT_CONVERGED, 'the rate constraints are singular: the rate of '''// &
          trim(self%scalar_names(self%sigma(zero_pivot - self%r)))//''' does not move their outputs')
      else
        call set_status(status, STATUS_NOT_CONVERGED, 'the closure and rate constraints are singular at '// &
                        describe_dependent(self, zero_pivot))
      end if
    end if
  end subroutine factor_filled_rates

  !> J_beta at the current positions, LU-factored block by block.
  subroutine factor_closure(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    call fill_closure(self, self%r)
    call factor_jbeta(self, status)
  end subroutine factor_closure

  !> With rate constraints: J_x filled and factored. Destroys the velocity state.
  subroutine factor_rates(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    if (self%nd == 0 .or. .not. status%ok()) return
    call fill_closure(self, self%r + self%nd)
    call factor_filled_rates(self, status)
  end subroutine factor_rates

  !> LU of the filled J_beta blocks.
  subroutine factor_jbeta(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    type(status_t) :: lapack
    integer :: zero_pivot
    call self%blocks%factor(.false., lapack, zero_pivot)
    if (.not. lapack%ok()) then
      call set_status(status, STATUS_NOT_CONVERGED, 'the closure Jacobian is singular: '// &
                      describe_dependent(self, zero_pivot)//' does not move the closure measurements')
    end if
  end subroutine factor_jbeta

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
  !> positions evaluated and J_beta (and J_x with rate constraints) factored.
  subroutine set_positions(self, q, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:)
    type(status_t), intent(inout) :: status
    type(nonlinear_result_t) :: result
    type(status_t) :: solve_status
    integer :: k, it, fresh
    real(wp) :: size_res, last
    logical :: converged, predicted, chord, polished

    predicted = self%r > 0 .and. self%converged
    if (predicted) call predict_dependents(self, q)
    do k = 1, self%f
      self%scalars(self%q(k))%q = q(k)
    end do
    if (self%r == 0) then
      call self%position_pass(status)
      call factor_rates(self, status)
      return
    end if
    self%closure_solves = self%closure_solves + 1
    associate (x => self%x_r, start => self%start_r, res => self%res_r)
    ! the warm start: the last solution, kept in start_r after a failed solve
    ! (whose scalars hold its last iterate); before any solution, the scalars
    if (self%converged .or. .not. self%warm) then
      do k = 1, self%r
        start(k) = self%scalars(self%beta(k))%q
      end do
    end if
    self%converged = .false.
    ! Newton from the warm start, moved by the predictor; after the predictor
    ! first with J_beta of the last solution (still factored: each step costs
    ! one position pass instead of r velocity passes), then, if that contracts
    ! slowly, with J_beta at the iterate (at most 4 such steps)
    x = start
    if (predicted) x = start - self%work_r
    converged = .false.
    chord = predicted
    polished = .false.
    last = huge(1.0_wp)
    fresh = 0
    do it = 1, 10
      ! the first pass at the new q over every element, then only beta changes
      if (it == 1) then
        call self%residual(x, res, status)
      else
        call beta_residual(self, x, res, status)
      end if
      if (.not. status%ok()) then
        if (status%code == STATUS_DOMAIN .and. self%warm) return   ! see the module comment
        exit
      end if
      size_res = maxval(abs(res))
      if (size_res <= 1e-3_wp*self%closure_tolerance) then
        ! a chord step converges only linearly: one more, so that beta is as
        ! exact as after a Newton step (a noisier right-hand side costs the
        ! integrator more steps than the position pass), unless the residual
        ! is already at the rounding floor (rider: ~2-4e-15 m after a polish,
        ! 99 % below 7e-15), which a further step cannot go below
        converged = .not. chord .or. polished .or. size_res <= 1e-4_wp*self%closure_tolerance
        if (converged) exit
        polished = .true.
        call self%blocks%solve(.false., res, .false.)
        x = x - res
        cycle
      end if
      if (chord .and. size_res > 0.1_wp*last) chord = .false.   ! contraction too slow: a fresh J_beta
      if (.not. chord) then
        if (fresh == 4) exit
        fresh = fresh + 1
        call factor_closure(self, solve_status)
        if (.not. solve_status%ok()) exit
      end if
      last = size_res
      call self%blocks%solve(.false., res, .false.)
      x = x - res
    end do
    if (.not. converged) then
      if (status%ok()) then
        call beta_residual(self, x, res, status)
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
        call self%blocks%solve(.false., res, .false.)
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
    ! J_beta at the solution; with rate constraints it is the first r columns
    ! of J_x, which are filled anyway
    if (self%nd > 0) then
      call fill_closure(self, self%r + self%nd)
      call factor_jbeta(self, status)
    else
      call factor_closure(self, status)
    end if
    if (.not. status%ok()) then
      call prefix_status(status, 'closure')
      return
    end if
    call check_branches(self, status)
    if (.not. status%ok()) return
    self%warm = .true.
    self%converged = .true.
    call factor_filled_rates(self, status)
  end subroutine set_positions

  !> The tangent predictor of the warm start: the elements still hold the
  !> geometry of the last solution (q0, beta0) and J_beta is factored there,
  !> so one velocity pass with q' = q - q0, beta' = 0 gives J_q (q - q0), and
  !> beta0 - J_beta^-1 J_q (q - q0) is the start, right to second order in
  !> q - q0 (a rolling ball turns by radians between two right-hand sides of
  !> a large step: from the old beta Newton can reach the other branch).
  !> Leaves the correction J_beta^-1 J_q (q - q0) in work_r; destroys the
  !> velocity state.
  subroutine predict_dependents(self, q)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:)
    integer :: k
    self%scalars%qd = 0
    do k = 1, self%f
      self%scalars(self%q(k))%qd = q(k) - self%scalars(self%q(k))%q
    end do
    call self%velocity_pass()
    do k = 1, self%r
      self%work_r(k) = self%scalars(self%closure(k))%qd
    end do
    call self%blocks%solve(.false., self%work_r, .false.)
    if (self%nd > 0 .or. size(self%kinematic) > 0) return
    ! The second-order term: along beta(s) = beta(q0 + s (q - q0)), beta'(0) =
    ! -work_r, and g'' = 0 gives beta''(0) = -J_beta^-1 g''|beta''=0 (an
    ! acceleration pass with the velocities of beta'(0) and no accelerations).
    ! It is taken only while it is below a tenth of the first-order term
    ! (a Taylor series that converges fast; on a jump of metres it would
    ! spoil the start); it saves a Newton step on most steps of an integrator.
    do k = 1, self%r
      self%scalars(self%beta(k))%qd = -self%work_r(k)
    end do
    do k = 1, size(self%beta_pass)   ! only beta' changed
      call self%elements(self%beta_pass(k))%e%velocity(self%frames, self%scalars)
    end do
    self%scalars%qdd = 0
    call self%acceleration_pass()
    do k = 1, self%r
      self%res_r(k) = self%scalars(self%closure(k))%qdd
    end do
    call self%blocks%solve(.false., self%res_r, .false.)
    if (0.5_wp*maxval(abs(self%res_r)) <= 0.1_wp*maxval(abs(self%work_r))) self%work_r = self%work_r + 0.5_wp*self%res_r
  end subroutine predict_dependents

  !> Every loop with a branch condition on it (set_loop_branch).
  subroutine check_branches(self, status)
    class(mechanism_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    integer :: k
    real(wp) :: c
    do k = 1, size(self%loops)
      associate (pair => self%loops(k)%antiparallel)
        if (pair(1) == 0) cycle
        c = dot_product(self%frames(pair(1))%rot(:, 3), self%frames(pair(2))%rot(:, 3))
        if (c > 0) then
          call set_status(status, STATUS_DOMAIN, 'loop '''//self%loops(k)%name//''' closed on the branch '// &
            'with parallel normals (z of '''//trim(self%frame_names(pair(1)))//''' . z of '''// &
            trim(self%frame_names(pair(2)))//''' = '//format_short(c)//'), not on the physical one')
          self%converged = .false.
          return
        end if
      end associate
    end do
  end subroutine check_branches

  !> At the start: the loops must close from the given beta and J_beta must be
  !> well conditioned (reciprocal condition number above 1e-10).
  subroutine check_start(self, q, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: q(:)
    type(status_t), intent(inout) :: status
    real(wp) :: rcond
    real(wp), allocatable :: jbeta(:, :), jlu(:, :)
    integer, allocatable :: pivots(:)
    integer :: i, k
    character(len=16) :: num
    if (.not. status%ok()) return
    self%warm = .false.
    self%converged = .false.
    call self%set_positions(q, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'at the start')
      return
    end if
    if (self%r == 0) return
    ! the whole J_beta (its blocks already factored without a zero pivot)
    allocate (jbeta(self%r, self%r), pivots(self%r))
    call self%blocks%assemble(.false., jbeta)
    jlu = jbeta
    call lu_factor(jlu, pivots, status)
    if (status%ok()) call lu_reciprocal_condition(jlu, one_norm(jbeta), rcond, status)
    if (status%ok() .and. rcond < 1e-10_wp) then
      k = minloc([(abs(jlu(i, i)), i = 1, self%r)], dim=1)   ! the weakest pivot
      write (num, '(es10.3)') rcond
      call set_status(status, STATUS_INVALID_INPUT, 'at the start the closure Jacobian is singular '// &
        '(reciprocal condition '//trim(adjustl(num))//'): '//describe_dependent(self, k)// &
        ' is not determined by its closure measurements')
    end if
  end subroutine check_start

  !> Sets the speeds s (positions already set): the rates of the speed
  !> coordinates, then beta' (3.30) and the dependent rates sigma' from
  !> [g'; c] = 0; `rates` gets q' of every coordinate (kinematic ones from
  !> their elements). Without rate constraints and kinematic coordinates s = q'.
  subroutine set_velocities(self, s)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: s(:)
    call set_rates(self, s, 1)
  end subroutine set_velocities

  !> Sets s' (velocities already set): beta'' (3.31) and sigma'' from [g''; c'] = 0.
  subroutine set_accelerations(self, sd)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: sd(:)
    call set_rates(self, sd, 2)
  end subroutine set_accelerations

  !> Level 1 (velocities) or 2 (accelerations) of the above. The two levels
  !> are written out (no internal procedures: gfortran called them, ~800,000
  !> times in a default run).
  subroutine set_rates(self, given, level)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: given(:)
    integer, intent(in) :: level
    integer :: k
    if (level == 1) then
      do k = 1, self%ns
        self%scalars(self%q(self%speeds(k)))%qd = given(k)
      end do
      do k = 1, self%r
        self%scalars(self%beta(k))%qd = 0
      end do
      do k = 1, self%nd
        self%scalars(self%sigma(k))%qd = 0
      end do
      call self%velocity_pass()
    else
      do k = 1, self%ns
        self%scalars(self%q(self%speeds(k)))%qdd = given(k)
      end do
      do k = 1, self%r
        self%scalars(self%beta(k))%qdd = 0
      end do
      do k = 1, self%nd
        self%scalars(self%sigma(k))%qdd = 0
      end do
      call self%acceleration_pass()
    end if
    if (self%r + self%nd > 0) then
      ! the second pass only over the elements the unknown rates reach: the
      ! others' inputs are those of the first pass, so are their outputs
      if (self%nd == 0) then
        if (level == 1) then
          do k = 1, self%r
            self%work_r(k) = self%scalars(self%closure(k))%qd
          end do
        else
          do k = 1, self%r
            self%work_r(k) = self%scalars(self%closure(k))%qdd
          end do
        end if
        call self%blocks%solve(.false., self%work_r, .false.)
        if (level == 1) then
          do k = 1, self%r
            self%scalars(self%beta(k))%qd = -self%work_r(k)
          end do
        else
          do k = 1, self%r
            self%scalars(self%beta(k))%qdd = -self%work_r(k)
          end do
        end if
      else
        if (level == 1) then
          do k = 1, self%r
            self%work_x(k) = self%scalars(self%closure(k))%qd
          end do
          do k = 1, self%nd
            self%work_x(self%r + k) = self%scalars(self%rate_outputs(k))%qd
          end do
        else
          do k = 1, self%r
            self%work_x(k) = self%scalars(self%closure(k))%qdd
          end do
          do k = 1, self%nd
            self%work_x(self%r + k) = self%scalars(self%rate_outputs(k))%qdd
          end do
        end if
        call self%blocks%solve(.true., self%work_x, .false.)
        if (level == 1) then
          do k = 1, self%r
            self%scalars(self%beta(k))%qd = -self%work_x(k)
          end do
          do k = 1, self%nd
            self%scalars(self%sigma(k))%qd = -self%work_x(self%r + k)
          end do
        else
          do k = 1, self%r
            self%scalars(self%beta(k))%qdd = -self%work_x(k)
          end do
          do k = 1, self%nd
            self%scalars(self%sigma(k))%qdd = -self%work_x(self%r + k)
          end do
        end if
      end if
      if (level == 1) then
        do k = 1, size(self%unknowns_pass)
          call self%elements(self%unknowns_pass(k))%e%velocity(self%frames, self%scalars)
        end do
      else
        do k = 1, size(self%unknowns_pass)
          call self%elements(self%unknowns_pass(k))%e%acceleration(self%frames, self%scalars)
        end do
      end if
    end if
    if (level == 1) then
      do k = 1, self%f
        self%rates(k) = self%scalars(self%q(k))%qd
      end do
    end if
  end subroutine set_rates

  !> Generalized forces at the speeds (into gq) with the loops and rate
  !> constraints in equilibrium: lambda = -J_beta^-T Q^_beta (3.32)-(3.33), or
  !> [lambda; mu] = -J_x^-T [Q^_beta; Q^_sigma]. `loads` selects the laws'
  !> loads (LOADS_*).
  subroutine inverse_dynamics(self, inertia, applied, loads)
    class(mechanism_t), intent(inout) :: self
    logical, intent(in) :: inertia, applied
    integer, intent(in) :: loads
    integer :: k
    self%lambda = 0
    self%mu = 0
    call self%force_pass(inertia, applied, self%lambda, loads)
    if (self%nd > 0) then
      do k = 1, self%r
        self%work_x(k) = self%scalars(self%beta(k))%force
      end do
      do k = 1, self%nd
        self%work_x(self%r + k) = self%scalars(self%sigma(k))%force
      end do
      call self%blocks%solve(.true., self%work_x, .true.)
      self%lambda = -self%work_x(1:self%r)
      self%mu = -self%work_x(self%r + 1:)
      call self%force_pass(inertia, applied, self%lambda, loads)
    else if (self%r > 0) then
      do k = 1, self%r
        self%lambda(k) = self%scalars(self%beta(k))%force
      end do
      call self%blocks%solve(.false., self%lambda, .true.)
      self%lambda = -self%lambda
      call self%force_pass(inertia, applied, self%lambda, loads)
    end if
    do k = 1, self%ns
      self%gq(k) = self%scalars(self%q(self%speeds(k)))%force
    end do
  end subroutine inverse_dynamics

  !> Normal force of each contact after an inverse-dynamics pass (rules in
  !> kinetostatics_contact).
  subroutine normal_forces(self, n)
    class(mechanism_t), intent(in) :: self
    real(wp), intent(out) :: n(:)
    integer :: k
    do k = 1, size(self%contacts)
      associate (c => self%contacts(k))
        if (c%normal_rule == NORMAL_CUT_FORCE) then
          n(k) = c%normal_sign*self%lambda(c%normal_row)
        else
          associate (fr => self%frames(c%normal_frame))
            n(k) = -c%normal_sign*dot_product(fr%rot(:, 3), fr%force)
          end associate
        end if
      end associate
    end do
  end subroutine normal_forces

  !> With positions and velocities set: every contact's kinematics, every
  !> active law's loads (scaled laws: per unit |N|) and unit power, and the
  !> laws' root functions.
  subroutine evaluate_laws(self, t, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: t
    type(status_t), intent(inout) :: status
    integer :: k, i
    real(wp) :: p
    self%dynamics_known = .false.
    do k = 1, size(self%contacts)
      call contact_kinematics(self%contacts(k), self%frames, self%contact_states(k))
    end do
    do k = 1, self%n_laws
      associate (law => self%laws(k)%law)
        p = 0
        if (law%active) then
          call law%evaluate(t, self%frames, self%scalars, self%contact_states, status)
          if (.not. status%ok()) then
            call prefix_status(status, 'force law '''//law%name//'''')
            return
          end if
          do i = 1, size(law%loads)
            associate (ld => law%loads(i), fr => self%frames(law%loads(i)%frame))
              p = p + dot_product(ld%force, fr%v) + dot_product(ld%torque, fr%omega)
            end associate
          end do
        end if
        self%unit_power(k) = p
        if (self%law_root_start(k + 1) > self%law_root_start(k)) &
          call law%roots(t, self%frames, self%scalars, self%contact_states, &
                         self%law_roots(self%law_root_start(k):self%law_root_start(k + 1) - 1))
      end associate
    end do
  end subroutine evaluate_laws

  ! ------------------------------------------------------ equations of motion

  !> s' from M(q) s' + Q^(q, s) = Q_applied (3.36) (s = q' without rate
  !> constraints and kinematic coordinates; qd is s, qdd is s'), with every force law
  !> and the normal forces of the contacts (see the module comment). Leaves M
  !> in `mass`, Q_bar0 in `bias`, q'' in `qdd`, the normal forces in `normal`,
  !> the laws' powers in `law_power`. The velocity and acceleration states are
  !> overwritten (use `evaluate` for a consistent state). Called again at the
  !> same (t, q, s) with the same laws switched on and no position pass or law
  !> evaluation in between, it returns the results it left (the positions and
  !> laws are still those of that state) and sets the velocities again.
  subroutine dynamics(self, t, q, qd, qdd, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: t, q(:), qd(:)
    real(wp), intent(out) :: qdd(:)
    type(status_t), intent(inout) :: status
    real(wp) :: s_old
    type(status_t) :: lapack
    integer :: i, j, k, c, nc, ns, nb, it, column
    logical :: consistent

    if (self%dynamics_known .and. t == self%known_t) then
      if (all(q == self%known_q) .and. all(qd == self%known_s) .and. &
          same_switches(self)) then
        qdd = self%qdd
        call self%set_velocities(qd)
        self%dynamics_reused = self%dynamics_reused + 1
        return
      end if
    end if
    qdd = 0
    nc = size(self%contacts)
    ns = size(self%scaled_laws)
    nb = size(self%block_contact)
    call self%set_positions(q, status)
    if (.not. status%ok()) return
    call self%set_velocities(qd)
    call self%evaluate_laws(t, status)
    if (.not. status%ok()) return
    self%law_factor = 1
    self%work_f = 0
    call self%set_accelerations(self%work_f)
    call self%inverse_dynamics(.true., .true., LOADS_EXPLICIT)
    self%bias(:) = self%gq   ! (:): no reallocation test
    if (nc > 0) call self%normal_forces(self%n0)

    ! M and G, all velocities zero, applied forces off
    do k = 1, self%n_frames
      self%frames(k)%omega = 0
      self%frames(k)%v = 0
    end do
    self%scalars%qd = 0
    if (self%twist_route) then
      call twist_mass_matrix(self)
    else
      do i = 1, self%ns
        call full_mass_column(self, i)
      end do
    end if
    if (.not. self%twist_route) then   ! (the twist route's M is symmetric and left its lower triangle in chol)
      do i = 1, self%ns   ! symmetric part's lower triangle, the factor's input (no temporary)
        do k = i, self%ns
          self%chol(k, i) = 0.5_wp*(self%mass(k, i) + self%mass(i, k))
        end do
      end do
    end if
    call cholesky_factor(self%chol, lapack, column)
    if (.not. lapack%ok()) then
      call set_status(status, STATUS_DOMAIN, 'the mass matrix is not positive definite: generalized '// &
        'coordinate '''//trim(self%scalar_names(self%q(self%speeds(column))))//''' has no inertia (a massless body or '// &
        'a mass without rotational inertia on a pure rotation)')
      return
    end if
    if (ns == 0) then
      self%qdd(:) = self%bias
      call cholesky_solve(self%chol, self%qdd, status)
      qdd = self%qdd
      call affine_normal_forces(self, qdd)
      self%law_power(:) = self%unit_power
      call remember_dynamics(self, t, q, qd)
      return
    end if

    ! scaled laws: their unit loads alone, then the block system
    if (self%twist_route) then
      call twist_unit_loads(self)
    else
      do k = 1, ns
        call self%inverse_dynamics(.false., .false., self%scaled_laws(k))
        self%p_mat(:, k) = self%gq
        call self%normal_forces(self%h_mat(:, k))
      end do
    end if
    self%signs = 1
    consistent = .false.
    do it = 1, 6
      self%block = 0
      self%block(1:self%ns, 1:self%ns) = self%mass
      do j = 1, nb
        self%block(self%ns + j, 1:self%ns) = -self%g_mat(self%block_contact(j), :)
        self%block(self%ns + j, self%ns + j) = 1
      end do
      do k = 1, ns
        j = self%block_row(k)
        self%block(1:self%ns, self%ns + j) = self%block(1:self%ns, self%ns + j) - self%p_mat(:, k)*self%signs(j)
        do i = 1, nb
          self%block(self%ns + i, self%ns + j) = self%block(self%ns + i, self%ns + j) &
                                               - self%h_mat(self%block_contact(i), k)*self%signs(j)
        end do
      end do
      self%block_rhs(1:self%ns) = self%bias
      do j = 1, nb
        self%block_rhs(self%ns + j) = self%n0(self%block_contact(j))
      end do
      call lu_factor(self%block, self%ipiv_block, lapack)
      if (.not. lapack%ok()) then
        call set_status(status, STATUS_DOMAIN, 'the equations of motion with friction proportional to '// &
                        'the normal forces are singular')
        return
      end if
      call lu_solve(self%block, self%ipiv_block, self%block_rhs, status)
      consistent = .true.
      do j = 1, nb
        s_old = self%signs(j)
        if (self%block_rhs(self%ns + j)*s_old < 0) then
          consistent = .false.
          self%signs(j) = -s_old
        end if
      end do
      if (consistent) exit
    end do
    if (.not. consistent) then
      call set_status(status, STATUS_DOMAIN, 'friction proportional to the normal forces: no consistent '// &
                      'signs of the normal forces (the friction law has no unique solution here, a '// &
                      'Painleve-type paradox)')
      return
    end if
    qdd = self%block_rhs(1:self%ns)
    self%qdd = qdd
    call affine_normal_forces(self, qdd)
    do k = 1, ns
      j = self%block_row(k)
      self%normal = self%normal + self%h_mat(:, k)*self%signs(j)*self%block_rhs(self%ns + j)
    end do
    do j = 1, nb
      self%normal(self%block_contact(j)) = self%block_rhs(self%ns + j)
    end do
    self%law_power = self%unit_power
    do k = 1, ns
      c = self%laws(self%scaled_laws(k))%law%contact
      self%law_factor(self%scaled_laws(k)) = abs(self%normal(c))
      self%law_power(self%scaled_laws(k)) = abs(self%normal(c))*self%unit_power(self%scaled_laws(k))
    end do
    call remember_dynamics(self, t, q, qd)
  end subroutine dynamics

  !> Column i of M and of G by inverse-dynamics passes (the route for a
  !> mechanism with an element of unknown links): s' = e_i, velocities zero,
  !> applied forces off.
  subroutine full_mass_column(self, i)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: i
    self%work_f = 0
    self%work_f(i) = 1
    call self%set_accelerations(self%work_f)
    call self%inverse_dynamics(.true., .false., LOADS_NONE)
    self%mass(:, i) = -self%gq
    if (size(self%contacts) > 0) call self%normal_forces(self%g_mat(:, i))
  end subroutine full_mass_column

  subroutine clear_accelerations(self)
    class(mechanism_t), intent(inout) :: self
    integer :: k
    do k = 1, self%n_frames
      self%frames(k)%alpha = 0
      self%frames(k)%a = 0
    end do
    self%scalars%qdd = 0
  end subroutine clear_accelerations

  !> M and G from the partial twists of the tracked frames (module comment),
  !> velocities zero: column i of the twists is the acceleration state of
  !> s' = e_i at rest (the closure solved), or equally the velocity state of
  !> s = e_i (velocity_column), the inertial wrench of each mass
  !> per unit s'_i is (3.23) at rest, and M(j, i) = -(twist_j . wrench_i).
  subroutine twist_mass_matrix(self)
    class(mechanism_t), intent(inout) :: self
    real(wp) :: mass, s(3), inertia_w(3, 3)
    integer :: i, b
    call clear_accelerations(self)
    if (self%velocity_columns) then
      do i = self%ns, 1, -1
        call velocity_column(self, i)
      end do
      ! back to rest (the normal forces' passes are acceleration maps at rest)
      call rest_velocities(self, self%blocks%mass_pass, self%blocks%mass_pass_start(1), &
                           self%blocks%mass_pass_start(2) - 1)
    else
      do i = 1, self%ns
        if (self%blocks%mass_blocked) then
          call unit_column(self, i)
        else
          self%work_f = 0
          self%work_f(i) = 1
          call self%set_accelerations(self%work_f)
          call keep_twists(self, self%twist(:, :, i))
        end if
      end do
      if (.not. self%blocks%mass_blocked) call clear_accelerations(self)
    end if
    call clear_sequence(size(self%wrench), self%wrench)
    do b = 1, size(self%masses)
      if (self%mass_slot(b) == 0) cycle   ! a mass on the ground
      call self%elements(self%masses(b))%e%world_inertia(mass, s, inertia_w)
      call add_inertial_wrenches(self%ns, size(self%tracked), self%mass_slot(b), mass, s, inertia_w, self%twist, &
                                 self%wrench)
    end do
    ! M(j, i) = -(twist_j . wrench_i), and its lower triangle, the factor's input
    call symmetric_transposed_product(6*size(self%tracked), self%ns, self%twist, self%wrench, -1.0_wp, self%mass, &
                                      self%chol)
    if (size(self%contacts) > 0) call twist_normal_forces(self)
  end subroutine twist_mass_matrix

  !> x = 0 for an array passed as its sequence of n elements: one store
  !> loop (an allocatable component of rank 3 set to 0 directly costs a
  !> memset call per column and loop control around it).
  pure subroutine clear_sequence(n, x)
    integer, intent(in) :: n
    real(wp), intent(out) :: x(n)
    x = 0
  end subroutine clear_sequence

  !> The inertial wrenches (torque, force at the frame's origin) of a mass
  !> (m, s = R s_local, Theta_w) on the tracked frame t per unit s'_i: (3.23)
  !> at rest with (alpha, a) = twist(:, t, i), added to wrench(:, t, i).
  pure subroutine add_inertial_wrenches(ns, nt, t, mass, s, inertia_w, twist, wrench)
    integer, intent(in) :: ns, nt, t
    real(wp), intent(in) :: mass, s(3), inertia_w(3, 3), twist(6, nt, ns)
    real(wp), intent(inout) :: wrench(6, nt, ns)
    real(wp) :: f(3)
    integer :: i
    do i = 1, ns
      f = -mass*(twist(4:6, t, i) + cross(twist(1:3, t, i), s))
      wrench(1:3, t, i) = wrench(1:3, t, i) + cross(s, f) - inertia_w(:, 1)*twist(1, t, i) &
                          - inertia_w(:, 2)*twist(2, t, i) - inertia_w(:, 3)*twist(3, t, i)
      wrench(4:6, t, i) = wrench(4:6, t, i) + f
    end do
  end subroutine add_inertial_wrenches

  !> Column i of the twists by passes over the elements a unit s'_i moves
  !> and the blocks it moves (kinetostatics_closure_blocks,
  !> build_mass_columns): one acceleration pass, the touched blocks' solve,
  !> a second pass over what their unknowns move. Pass i of the sequence of
  !> clear_before.
  subroutine unit_column(self, i)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: i
    integer :: l, m, j, p, speed, first, last
    ! index bounds, not associated slices: descriptors cost more than the
    ! work for the usual column that touches no block
    speed = self%q(self%speeds(i))
    first = self%blocks%touched_start(i)
    last = self%blocks%touched_start(i + 1) - 1
    call clear_before(self, i)
    self%scalars(speed)%qdd = 1
    do p = self%blocks%mass_pass_start(i), self%blocks%mass_pass_start(i + 1) - 1
      call self%elements(self%blocks%mass_pass(p))%e%acceleration(self%frames, self%scalars)
    end do
    if (last >= first) then
      associate (bl => self%blocks, x => self%work_x, touched => self%blocks%touched(first:last))
        do l = 1, size(touched)
          do m = 1, size(bl%blocks(touched(l))%members)
            j = bl%blocks(touched(l))%members(m)
            x(j) = self%scalars(self%rows(j))%qdd
          end do
        end do
        call bl%solve(self%nd > 0, x, .false., touched)
        do l = 1, size(touched)
          do m = 1, size(bl%blocks(touched(l))%members)
            j = bl%blocks(touched(l))%members(m)
            self%scalars(self%unknowns(j))%qdd = -x(j)
          end do
        end do
      end associate
      call accelerate(self, self%blocks%second_pass(self%blocks%second_pass_start(i): &
                                                    self%blocks%second_pass_start(i + 1) - 1))
    end if
    call keep_twists(self, self%twist(:, :, i))
    ! the sources back to rest (the outputs: clear_before)
    self%scalars(speed)%qdd = 0
    do l = first, last
      associate (members => self%blocks%blocks(self%blocks%touched(l))%members)
        do m = 1, size(members)
          self%scalars(self%unknowns(members(m)))%qdd = 0
        end do
      end associate
    end do
  end subroutine unit_column

  !> Column i of the twists when no column touches a block: the velocity
  !> state of s = e_i (the other rates zero) is the partial twist J e_i, the
  !> acceleration state of s' = e_i at rest (unit_column) by the velocity
  !> maps of the same pass. The columns run from the last to the first
  !> after a state at rest (build_velocity_clears); `rates` (q' of the
  !> state, read by the integrator) is not touched.
  subroutine velocity_column(self, i)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: i
    integer :: p, speed
    speed = self%q(self%speeds(i))
    if (self%velocity_clear_start(i + 1) > self%velocity_clear_start(i)) &
      call rest_velocities(self, self%velocity_clear, self%velocity_clear_start(i), &
                           self%velocity_clear_start(i + 1) - 1)
    self%scalars(speed)%qd = 1
    do p = self%blocks%mass_pass_start(i), self%blocks%mass_pass_start(i + 1) - 1
      call self%elements(self%blocks%mass_pass(p))%e%velocity(self%frames, self%scalars)
    end do
    call keep_velocity_twists(self, self%twist(:, :, i))
    self%scalars(speed)%qd = 0
  end subroutine velocity_column

  !> The velocity columns run from the last speed to the first: before
  !> column i the outputs of the elements pass i + 1 ran and pass i does not
  !> go back to rest (the others pass i overwrites or never moved). For a
  !> chain, whose speeds' passes grow towards its root, there are none.
  subroutine build_velocity_clears(self)
    class(mechanism_t), intent(inout) :: self
    integer :: i, p
    integer, allocatable :: clear(:), start(:)
    allocate (clear(0), start(self%ns + 1))
    associate (first => self%blocks%mass_pass_start, pass => self%blocks%mass_pass)
      do i = 1, self%ns
        start(i) = size(clear) + 1
        if (i == self%ns) cycle
        do p = first(i + 1), first(i + 2) - 1
          if (.not. any(pass(first(i):first(i + 1) - 1) == pass(p))) clear = [clear, pass(p)]
        end do
      end do
    end associate
    start(self%ns + 1) = size(clear) + 1
    self%velocity_clear = clear
    self%velocity_clear_start = start
  end subroutine build_velocity_clears

  !> The velocities of the outputs of the elements list(first:last) set to rest.
  subroutine rest_velocities(self, list, first, last)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: list(:), first, last
    integer :: p, l, e
    !GCC$ unroll 1
    do p = first, last
      e = list(p)
      !GCC$ unroll 1
      do l = self%reach%frame_out_start(e), self%reach%frame_out_start(e + 1) - 1
        self%frames(self%reach%frame_out(l))%omega = 0
        self%frames(self%reach%frame_out(l))%v = 0
      end do
      !GCC$ unroll 1
      do l = self%reach%scalar_out_start(e), self%reach%scalar_out_start(e + 1) - 1
        self%scalars(self%reach%scalar_out(l))%qd = 0
      end do
    end do
  end subroutine rest_velocities

  !> The tracked frames' (omega, v) (keep_twists of a velocity state).
  subroutine keep_velocity_twists(self, twists)
    class(mechanism_t), intent(in) :: self
    real(wp), intent(out) :: twists(6, size(self%tracked))
    integer :: t
    !GCC$ unroll 1
    do t = 1, size(self%tracked)
      twists(1:3, t) = self%frames(self%tracked(t))%omega
      twists(4:6, t) = self%frames(self%tracked(t))%v
    end do
  end subroutine keep_velocity_twists

  !> The normal-force map of every contact, N = -normal_sign nu_c . W for
  !> any wrenches W (torque, force) at the tracked frames (inertial or
  !> applied), and G from it (module comment). With x = [lambda; mu] =
  !> -J_x^-T Q_x the cut forces of W, Q_x(k) = twist_k . W the generalized
  !> forces on the unknowns (their open partial twists), a row vector r
  !> gives r . x = -(J_x^-1 r) . Q_x: so nu_c = n_c - sum_k y_k twist_k with
  !> y = J_x^-1 r_c, where for N = normal_sign lambda of a row, n_c = 0 and
  !> r_c = -e_row, and for N = -normal_sign z_F . f_F, n_c is the twist of
  !> the motion of F along z_F (the tracked frames it carries) and r_c the
  !> rows' rates of that motion (z_F . f_F is the power of W and of the cut
  !> forces on it). Velocities and accelerations zero.
  subroutine twist_normal_forces(self)
    class(mechanism_t), intent(inout) :: self
    real(wp) :: factor
    integer :: i, k, l, c, f, nx, step
    nx = self%r + self%nd
    step = 0
    if (self%blocks%mass_blocked) step = self%ns
    do l = 1, size(self%moving_unknowns)   ! the other unknowns move no tracked frame
      k = self%moving_unknowns(l)
      step = step + 1
      call clear_before(self, step)
      self%scalars(self%unknowns(k))%qdd = 1
      call accelerate(self, self%blocks%unknown_pass(self%blocks%unknown_pass_start(k): &
                                                     self%blocks%unknown_pass_start(k + 1) - 1))
      call keep_twists(self, self%unknown_twist(:, :, l))
      self%scalars(self%unknowns(k))%qdd = 0
    end do
    l = 0
    do c = 1, size(self%contacts)
      associate (contact => self%contacts(c))
        if (contact%normal_rule == NORMAL_CUT_FORCE) then
          self%nu(:, :, c) = 0
          self%work_x = 0
          self%work_x(contact%normal_row) = -1
        else
          l = l + 1
          f = contact%normal_frame
          step = step + 1
          call clear_before(self, step)
          self%frames(f)%a = self%frames(f)%rot(:, 3)
          call accelerate(self, self%blocks%normal_pass(self%blocks%normal_pass_start(l): &
                                                        self%blocks%normal_pass_start(l + 1) - 1))
          call keep_twists(self, self%nu(:, :, c))
          do k = 1, nx
            self%work_x(k) = self%scalars(self%rows(k))%qdd
          end do
          self%frames(f)%a = 0
        end if
      end associate
      if (size(self%moving_unknowns) == 0) cycle
      call self%blocks%solve(self%nd > 0, self%work_x, .false.)
      do k = 1, size(self%moving_unknowns)
        self%nu(:, :, c) = self%nu(:, :, c) - self%work_x(self%moving_unknowns(k))*self%unknown_twist(:, :, k)
      end do
    end do
    call transposed_product(6*size(self%tracked), size(self%contacts), self%ns, self%nu, self%wrench, self%g_mat)
    do c = 1, size(self%contacts)
      factor = -self%contacts(c)%normal_sign   ! +-1: the products are exact
      do i = 1, self%ns
        self%g_mat(c, i) = factor*self%g_mat(c, i)
      end do
    end do
  end subroutine twist_normal_forces

  !> P and H (module comment) of the scaled laws from the twists: the
  !> generalized forces of law k's unit loads are the powers of its wrenches
  !> on the speeds' twists, the normal forces -normal_sign nu_c . wrenches
  !> (twist_normal_forces); a law with a load on a frame that is not tracked
  !> (nor the ground) gets its inverse-dynamics pass.
  subroutine twist_unit_loads(self)
    class(mechanism_t), intent(inout) :: self
    integer :: k, j, t, c
    logical :: tracked
    do k = 1, size(self%scaled_laws)
      self%load_wrench = 0
      tracked = .true.
      associate (loads => self%laws(self%scaled_laws(k))%law%loads)
        do j = 1, size(loads)
          if (loads(j)%frame == 1) cycle   ! the ground: no power
          t = self%tracked_slot(loads(j)%frame)
          if (t == 0) then
            tracked = .false.
            exit
          end if
          self%load_wrench(1:3, t) = self%load_wrench(1:3, t) + loads(j)%torque
          self%load_wrench(4:6, t) = self%load_wrench(4:6, t) + loads(j)%force
        end do
      end associate
      if (.not. tracked) then
        call self%inverse_dynamics(.false., .false., self%scaled_laws(k))
        self%p_mat(:, k) = self%gq
        call self%normal_forces(self%h_mat(:, k))
        cycle
      end if
      call transposed_product(6*size(self%tracked), self%ns, 1, self%twist, self%load_wrench, self%p_mat(:, k))
      call transposed_product(6*size(self%tracked), size(self%contacts), 1, self%nu, self%load_wrench, &
                              self%h_mat(:, k))
      do c = 1, size(self%contacts)
        self%h_mat(c, k) = -self%contacts(c)%normal_sign*self%h_mat(c, k)
      end do
    end do
  end subroutine twist_unit_loads

  !> The acceleration maps of the elements `pass`, in order.
  subroutine accelerate(self, pass)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: pass(:)
    integer :: p
    do p = 1, size(pass)
      call self%elements(pass(p))%e%acceleration(self%frames, self%scalars)
    end do
  end subroutine accelerate

  !> The tracked frames' (alpha, a). (Here and in clear_before the loops run
  !> a few times: not unrolled, -funroll-loops' remainder dispatch costs more.)
  subroutine keep_twists(self, twists)
    class(mechanism_t), intent(in) :: self
    real(wp), intent(out) :: twists(6, size(self%tracked))
    integer :: t
    !GCC$ unroll 1
    do t = 1, size(self%tracked)
      twists(1:3, t) = self%frames(self%tracked(t))%alpha
      twists(4:6, t) = self%frames(self%tracked(t))%a
    end do
  end subroutine keep_twists

  !> Before pass `step` of the mass matrix's sequence
  !> (kinetostatics_closure_blocks, build_mass_columns): the accelerations
  !> of the outputs the pass before wrote and this one does not, set to rest.
  subroutine clear_before(self, step)
    class(mechanism_t), intent(inout) :: self
    integer, intent(in) :: step
    integer :: p, l, e
    !GCC$ unroll 1
    do p = self%blocks%clear_start(step), self%blocks%clear_start(step + 1) - 1
      e = self%blocks%clear(p)
      !GCC$ unroll 1
      do l = self%reach%frame_out_start(e), self%reach%frame_out_start(e + 1) - 1
        self%frames(self%reach%frame_out(l))%alpha = 0
        self%frames(self%reach%frame_out(l))%a = 0
      end do
      !GCC$ unroll 1
      do l = self%reach%scalar_out_start(e), self%reach%scalar_out_start(e + 1) - 1
        self%scalars(self%reach%scalar_out(l))%qdd = 0
      end do
    end do
  end subroutine clear_before

  subroutine remember_dynamics(self, t, q, qd)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: t, q(:), qd(:)
    integer :: k
    self%known_t = t
    self%known_q(:) = q
    self%known_s(:) = qd
    do k = 1, self%n_laws
      self%known_active(k) = self%laws(k)%law%active
    end do
    self%dynamics_known = .true.
  end subroutine remember_dynamics

  !> Every law switched on or off as at the last completed `dynamics`.
  logical function same_switches(self) result(same)
    class(mechanism_t), intent(in) :: self
    integer :: k
    same = .true.
    do k = 1, self%n_laws
      if (self%laws(k)%law%active .neqv. self%known_active(k)) same = .false.
    end do
  end function same_switches

  !> N = N0 + G q'' for every contact (without the scaled laws' share).
  subroutine affine_normal_forces(self, qdd)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: qdd(:)
    integer :: i, c
    do c = 1, size(self%n0)   ! no matmul: its result would be a heap temporary
      self%normal(c) = self%n0(c)
      do i = 1, self%ns
        self%normal(c) = self%normal(c) + self%g_mat(c, i)*qdd(i)
      end do
    end do
  end subroutine affine_normal_forces

  !> The complete state at (t, q, q'): accelerations, cut forces, every law's
  !> loads and power, every contact's normal force, the record-only elements'
  !> outputs; returns the inverse-dynamics residual max |Q_bar| (zero up to
  !> rounding when everything is consistent).
  subroutine evaluate(self, t, q, qd, residual, status)
    class(mechanism_t), intent(inout) :: self
    real(wp), intent(in) :: t, q(:), qd(:)
    real(wp), intent(out) :: residual
    type(status_t), intent(inout) :: status
    real(wp) :: qdd(self%ns)
    integer :: c, reused
    residual = huge(1.0_wp)
    reused = self%dynamics_reused
    call self%dynamics(t, q, qd, qdd, status)
    if (status%ok()) call self%record_pass(status)   ! at q: a reused dynamics left the positions there
    if (.not. status%ok()) return
    ! a reused dynamics has just set these velocities; a computed one overwrote them
    if (self%dynamics_reused == reused) call self%set_velocities(qd)
    call self%set_accelerations(qdd)
    call self%inverse_dynamics(.true., .true., LOADS_ALL)
    residual = maxval(abs(self%gq))
    call self%normal_forces(self%work_c)
    do c = 1, size(self%contacts)
      self%contacts(c)%normal_force = self%work_c(c)
    end do
  end subroutine evaluate

  !> Force of law k at the last evaluation (its first load, i.e. on body B
  !> for a contact law), N.
  pure function law_force(self, k) result(force)
    class(mechanism_t), intent(in) :: self
    integer, intent(in) :: k
    real(wp) :: force(3)
    force = 0
    if (self%laws(k)%law%active) force = self%law_factor(k)*self%laws(k)%law%loads(1)%force
  end function law_force

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
