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
!> The procedures live in rooms, submodules of this module (docs/DESIGN.md):
!>   topology  kinetostatics_mechanism_topology: building, finalize (structure,
!>             speeds, edges, blocks, tracked frames, work arrays);
!>   closure   kinetostatics_mechanism_closure: the loop closure (positions);
!>   rates     kinetostatics_mechanism_rates: element passes, velocity and
!>             acceleration rates, inverse dynamics, normal forces, laws;
!>   dynamics  kinetostatics_mechanism_dynamics: the equations of motion;
!>   twists    kinetostatics_mechanism_twists: the mass matrix and the
!>             normal-force maps from the partial twists;
!>   tree      kinetostatics_mechanism_tree: the equations of motion of a
!>             chain or tree of bodies in linear time (kinetostatics_tree);
!> and the state of one integration (the frames' and scalars' positions,
!> rates and forces, the elements' kept geometry and charts, the closure's
!> factored blocks and warm start, the laws' loads, switches and factors),
!> the results of an evaluation (cut forces, rates, M, normal forces, the
!> laws' powers and roots, the contacts' kinematics), the work arrays and the
!> cache of the last dynamics in a workspace
!> (kinetostatics_mechanism_workspace) that the caller owns (the ODE object
!> of an integration) and passes to every procedure that computes. The
!> mechanism itself is the model: every procedure that computes takes it
!> intent(in), so one mechanism object serves two integrations at once. Its
!> frames, scalars, elements and laws are the state a workspace starts from
!> (prepare_workspace copies them when the workspace first meets the model);
!> a change to them after that does not reach that workspace (change the
!> workspace's, or give a fresh one).
!> Each room's module comment gives its method. The core names no element
!> kind: what it needs of an element it asks element_t (kinetostatics_state).
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
  use kinetostatics_state, only: element_t, element_box_t, frame_state_t, scalar_state_t, domain_edge_t, &
    rest_velocities
  use kinetostatics_contact, only: contact_t, contact_state_t, contact_kinematics, NORMAL_FRAME_FORCE, &
    NORMAL_CUT_FORCE
  use kinetostatics_force_law, only: force_law_t, force_law_box_t
  use kinetostatics_mechanism_workspace, only: mechanism_workspace_t, WORKSPACE_SIZES, recent_solutions
  use kinetostatics_closure_blocks, only: closure_blocks_t, element_reach_t, build_closure_blocks, &
    find_element_links, downstream_of, rest_outputs
  use kinetostatics_tree, only: tree_t, find_tree
  implicit none (type, external)
  private
  public :: mechanism_t, mechanism_workspace_t, loop_t, rate_constraint_t, surface_edge_t
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

  !> The model: what does not change while it computes (every procedure
  !> that computes takes the mechanism intent(in) and a workspace with the
  !> state of one integration, kinetostatics_mechanism_workspace).
  type :: mechanism_t
    ! the state a workspace starts from (prepare_workspace): the fixed joint values, the start guesses
    type(frame_state_t), allocatable :: frames(:)
    type(scalar_state_t), allocatable :: scalars(:)
    character(len=32), allocatable :: frame_names(:), scalar_names(:)
    integer, allocatable :: role(:)
    type(element_box_t), allocatable :: elements(:)   ! as built (a workspace computes with copies)
    type(loop_t), allocatable :: loops(:)
    type(rate_constraint_t), allocatable :: rate_constraints(:)
    type(contact_t), allocatable :: contacts(:)
    type(force_law_box_t), allocatable :: laws(:)     ! as built (a workspace evaluates copies)
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
    !> the sizes a workspace must have and the model's stamp (prepare_workspace)
    integer :: workspace_dims(WORKSPACE_SIZES) = 0
    integer, allocatable :: law_root_start(:) ! first index of law k's roots in a workspace's law_roots
    !> the closure's blocks (kinetostatics_closure_blocks); set blocked = .false. before finalize
    !> for one block and full passes (the unblocked computation, for comparison)
    logical :: blocked = .true.
    type(element_reach_t) :: reach
    type(closure_blocks_t) :: blocks           ! their structure (a workspace fills and factors copies)
    integer, allocatable :: beta_pass(:)   ! the elements the dependent coordinates reach (downstream_of)
    integer, allocatable :: unknowns_pass(:)   ! ... and those the unknown rates [beta'; sigma'] reach
    integer, allocatable :: unknowns(:), rows(:)   ! scalars of x = [beta; sigma] and of the rows [g; c]
    integer, allocatable :: scaled_laws(:)    ! indices of the scaled laws
    integer, allocatable :: block_row(:)      ! row (1..nb) of each scaled law's contact in the block
    integer, allocatable :: block_contact(:)  ! contact of each block row
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
    integer, allocatable :: moving_unknowns(:)   ! the unknowns whose open motion moves a tracked frame
    ! a chain or tree of at least recursion_bodies bodies: the recursion instead of M
    ! (kinetostatics_tree; set_recursion); 0: never
    integer :: recursion_bodies = 3
    type(tree_t) :: tree
  contains
    procedure :: add_frame, add_scalar, add_element, add_loop, add_contact, add_law, set_coordinates, finalize
    procedure :: add_rate_constraint, set_kinematic, set_loop_branch, add_monitor
    procedure :: frame_index, scalar_index, contact_index, law_index
    procedure :: position_pass, velocity_pass, acceleration_pass, force_pass, record_pass
    procedure :: set_positions, set_velocities, set_accelerations, inverse_dynamics, evaluate_laws
    procedure :: check_start, set_blocked, set_recursion, prepare_workspace
    procedure :: dynamics, evaluate, energy, closure_residual, normal_forces, law_force
  end type mechanism_t

  !> The closure f(beta) = g - target for the nonlinear solver: the model and
  !> the workspace whose scalars beta are (set_positions).
  type, extends(nonlinear_system_t) :: closure_system_t
    class(mechanism_t), pointer :: mechanism => null()
    type(mechanism_workspace_t), pointer :: work => null()
  contains
    procedure :: residual => closure_system_residual
    procedure :: jacobian => closure_system_jacobian
  end type closure_system_t

  interface
    ! topology (kinetostatics_mechanism_topology)
    integer module function add_frame(self, name) result(k)
      class(mechanism_t), intent(inout) :: self
      character(len=*), intent(in) :: name
    end function add_frame

    integer module function add_scalar(self, name, value) result(k)
      class(mechanism_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      real(wp), intent(in), optional :: value
    end function add_scalar

    module subroutine add_element(self, e)
      class(mechanism_t), intent(inout) :: self
      class(element_t), intent(in) :: e
    end subroutine add_element

    module subroutine add_loop(self, name, measurements, targets, dependents, status)
      class(mechanism_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: measurements(:), dependents(:)
      real(wp), intent(in) :: targets(:)
      type(status_t), intent(inout) :: status
    end subroutine add_loop

    module subroutine set_loop_branch(self, name, frame_1, frame_2, status)
      class(mechanism_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: frame_1, frame_2
      type(status_t), intent(inout) :: status
    end subroutine set_loop_branch

    module subroutine add_rate_constraint(self, name, outputs, dependents, status)
      class(mechanism_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: outputs(:), dependents(:)
      type(status_t), intent(inout) :: status
    end subroutine add_rate_constraint

    module subroutine add_monitor(self, scalar, units)
      class(mechanism_t), intent(inout) :: self
      integer, intent(in) :: scalar
      character(len=*), intent(in) :: units
    end subroutine add_monitor

    module subroutine set_kinematic(self, scalars)
      class(mechanism_t), intent(inout) :: self
      integer, intent(in) :: scalars(:)
    end subroutine set_kinematic

    integer module function add_contact(self, name, frame_a, frame_b, point_frame, normal_sign, normal_frame, &
                                 normal_measurement, one_sided) result(k)
      class(mechanism_t), intent(inout) :: self
      character(len=*), intent(in) :: name
      integer, intent(in) :: frame_a, frame_b, point_frame
      real(wp), intent(in), optional :: normal_sign
      integer, intent(in), optional :: normal_frame, normal_measurement
      logical, intent(in), optional :: one_sided
    end function add_contact

    module subroutine add_law(self, law)
      class(mechanism_t), intent(inout) :: self
      class(force_law_t), intent(in) :: law
    end subroutine add_law

    module subroutine set_coordinates(self, q)
      class(mechanism_t), intent(inout) :: self
      integer, intent(in) :: q(:)
    end subroutine set_coordinates

    integer module function frame_index(self, name) result(k)
      class(mechanism_t), intent(in) :: self
      character(len=*), intent(in) :: name
    end function frame_index

    integer module function scalar_index(self, name) result(k)
      class(mechanism_t), intent(in) :: self
      character(len=*), intent(in) :: name
    end function scalar_index

    integer module function contact_index(self, name) result(k)
      class(mechanism_t), intent(in) :: self
      character(len=*), intent(in) :: name
    end function contact_index

    integer module function law_index(self, name) result(k)
      class(mechanism_t), intent(in) :: self
      character(len=*), intent(in) :: name
    end function law_index

    module subroutine finalize(self, status)
      class(mechanism_t), intent(inout) :: self
      type(status_t), intent(inout) :: status
    end subroutine finalize

    module subroutine set_blocked(self, blocked)
      class(mechanism_t), intent(inout) :: self
      logical, intent(in) :: blocked
    end subroutine set_blocked

    module subroutine set_recursion(self, from_bodies)
      class(mechanism_t), intent(inout) :: self
      integer, intent(in) :: from_bodies
    end subroutine set_recursion

    module subroutine prepare_workspace(self, work)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
    end subroutine prepare_workspace

    ! closure (kinetostatics_mechanism_closure)
    module subroutine closure_system_residual(self, x, f, status)
      class(closure_system_t), intent(inout) :: self
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: f(:)
      type(status_t), intent(inout) :: status
    end subroutine closure_system_residual

    module subroutine closure_system_jacobian(self, x, jac, status)
      class(closure_system_t), intent(inout) :: self
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: jac(:, :)
      type(status_t), intent(inout) :: status
    end subroutine closure_system_jacobian

    module subroutine set_positions(self, work, q, status)
      class(mechanism_t), intent(in), target :: self
      type(mechanism_workspace_t), intent(inout), target :: work
      real(wp), intent(in) :: q(:)
      type(status_t), intent(inout) :: status
    end subroutine set_positions

    module subroutine check_start(self, work, q, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: q(:)
      type(status_t), intent(inout) :: status
    end subroutine check_start

    real(wp) module function closure_residual(self, work) result(e)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(in) :: work
    end function closure_residual

    ! rates (kinetostatics_mechanism_rates)
    module subroutine position_pass(self, work, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      type(status_t), intent(inout) :: status
    end subroutine position_pass

    module subroutine record_pass(self, work, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      type(status_t), intent(inout) :: status
    end subroutine record_pass

    module subroutine velocity_pass(self, work)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
    end subroutine velocity_pass

    module subroutine acceleration_pass(self, work)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
    end subroutine acceleration_pass

    module subroutine force_pass(self, work, inertia, applied, loads)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      logical, intent(in) :: inertia, applied
      integer, intent(in) :: loads
    end subroutine force_pass

    module subroutine set_velocities(self, work, s)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: s(:)
    end subroutine set_velocities

    module subroutine set_accelerations(self, work, sd)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: sd(:)
    end subroutine set_accelerations

    module subroutine inverse_dynamics(self, work, inertia, applied, loads)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      logical, intent(in) :: inertia, applied
      integer, intent(in) :: loads
    end subroutine inverse_dynamics

    module subroutine normal_forces(self, work, lambda, n)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(in) :: work
      real(wp), intent(in) :: lambda(:)
      real(wp), intent(out) :: n(:)
    end subroutine normal_forces

    module subroutine evaluate_laws(self, work, t, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: t
      type(status_t), intent(inout) :: status
    end subroutine evaluate_laws

    pure module function law_force(self, work, k) result(force)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(in) :: work
      integer, intent(in) :: k
      real(wp) :: force(3)
    end function law_force

    module subroutine energy(self, work, kinetic, potential)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(in) :: work
      real(wp), intent(out) :: kinetic, potential
    end subroutine energy

    ! dynamics (kinetostatics_mechanism_dynamics)
    module subroutine dynamics(self, work, t, q, qd, qdd, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: t, q(:), qd(:)
      real(wp), intent(out) :: qdd(:)
      type(status_t), intent(inout) :: status
    end subroutine dynamics

    module subroutine evaluate(self, work, t, q, qd, residual, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: t, q(:), qd(:)
      real(wp), intent(out) :: residual
      type(status_t), intent(inout) :: status
    end subroutine evaluate

    ! twists (kinetostatics_mechanism_twists)
    module subroutine twist_mass_matrix(self, work)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
    end subroutine twist_mass_matrix

    module subroutine twist_unit_loads(self, work)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
    end subroutine twist_unit_loads

    ! shared by the dense and the tree dynamics (kinetostatics_mechanism_dynamics)
    module subroutine bias_forces(self, work, t, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: t
      type(status_t), intent(inout) :: status
    end subroutine bias_forces

    module subroutine no_inertia(self, column, status)
      class(mechanism_t), intent(in) :: self
      integer, intent(in) :: column
      type(status_t), intent(inout) :: status
    end subroutine no_inertia

    ! tree (kinetostatics_mechanism_tree)
    module subroutine tree_dynamics(self, work, t, q, qd, qdd, status)
      class(mechanism_t), intent(in) :: self
      type(mechanism_workspace_t), intent(inout) :: work
      real(wp), intent(in) :: t, q(:), qd(:)
      real(wp), intent(out) :: qdd(:)
      type(status_t), intent(inout) :: status
    end subroutine tree_dynamics
  end interface
end module kinetostatics_mechanism
