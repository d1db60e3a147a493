!> The workspace of a mechanism's computations (kinetostatics_mechanism):
!> the state of one integration of the model, the results of its last
!> evaluation and what the computations need on their way. The state: every
!> frame and scalar (positions, rates, forces), the elements (the geometry
!> they keep from one pass to the next, their charts), the closure's blocks
!> (J_x factored), the laws (loads, switches) and their factors, the
!> closure's warm start and flags. The results of the last evaluation with
!> this workspace (cut forces lambda and mu, the rates q', the accelerations
!> s', M and Q_bar0, the normal forces, the laws' powers, unit powers and
!> root functions, the contacts' kinematics, the generalized forces of the
!> last inverse dynamics, G, P and H). The rate and force solves'
!> right-hand sides, the Cholesky factor and the block system of the
!> equations of motion, the partial twists and wrenches of the tracked
!> frames, and the cache of the last `dynamics` (its state, so that a record
!> at the state a root function just saw reuses it).
!>
!> Owned by whoever runs the computations (the integration's ODE object,
!> kinetostatics_mechanism_ode), not by the mechanism: the mechanism is the
!> model and does not change while it computes, so one mechanism serves any
!> number of workspaces (two integrations at once). Sized and given the
!> model's state to start from by the mechanism's prepare_workspace on its
!> first use (and again only when it meets another model), never inside a
!> right-hand side.
module kinetostatics_mechanism_workspace
  use base_kinds, only: wp
  use kinetostatics_contact, only: contact_state_t
  use kinetostatics_state, only: frame_state_t, scalar_state_t, element_box_t
  use kinetostatics_force_law, only: force_law_box_t
  use kinetostatics_closure_blocks, only: closure_blocks_t
  use kinetostatics_tree, only: tree_work_t
  implicit none (type, external)
  private
  public :: mechanism_workspace_t, WORKSPACE_SIZES

  !> How many sizes of the mechanism the workspace is made for (dims).
  integer, parameter :: WORKSPACE_SIZES = 12

  !> How many recent closure solutions a workspace keeps (below): more than
  !> the solves of one rejected trial step (Adams: up to 4 per stage).
  integer, parameter, public :: recent_solutions = 8

  type :: mechanism_workspace_t
    integer :: dims(WORKSPACE_SIZES) = -1        ! the mechanism's sizes it was made for (prepare_workspace)
    ! the state of an integration (copied from the mechanism's model by prepare_workspace)
    type(frame_state_t), allocatable :: frames(:)   ! every frame: pose, twist, its rates, the wrench on it
    type(scalar_state_t), allocatable :: scalars(:) ! every scalar: value, rates, generalized or cut force
    type(element_box_t), allocatable :: elements(:) ! the elements: the geometry they keep between
                                                    ! passes, their charts (rebase)
    type(closure_blocks_t) :: blocks             ! the closure's blocks: J_x filled and factored
    type(force_law_box_t), allocatable :: laws(:)   ! the laws: their loads and switches (active)
    real(wp), allocatable :: law_factor(:)       ! each law's factor at the last dynamics: 1 for explicit
                                                 ! laws, |N| for scaled ones (law_force)
    logical :: warm = .false.                    ! a closure has converged (a warm start exists)
    logical :: converged = .false.               ! beta holds it (else start_r does: the last solve failed)
    logical :: solve_failed = .false.            ! the last solve ended without a solution: the next one
                                                 ! starts from the recent solution nearest its q
    integer :: evaluation = 0                    ! position passes and law evaluations so far
    integer :: closure_solves = 0, hybrj_solves = 0
    real(wp), allocatable :: normal_force(:)     ! N of every contact at the last `evaluate` (a complete state)
    ! results of the last evaluation with this workspace (what callers read)
    real(wp), allocatable :: lambda(:)           ! cut forces of the closure measurements
    real(wp), allocatable :: mu(:)               ! cut forces of the rate constraints
    real(wp), allocatable :: rates(:)            ! q' of every coordinate (f), from the last set_velocities
    real(wp), allocatable :: qdd(:)              ! s' of the speeds (ns)
    real(wp), allocatable :: mass(:, :), bias(:)   ! M and Q_bar0 = -Q^
    real(wp), allocatable :: normal(:)           ! N of every contact (from the last dynamics)
    real(wp), allocatable :: law_power(:)        ! W, power of each law's loads
    real(wp), allocatable :: unit_power(:)       ! power of each law's loads per unit factor (scaled: per |N|)
    real(wp), allocatable :: law_roots(:)        ! root functions of the laws, at the last law evaluation
    type(contact_state_t), allocatable :: contact_states(:)   ! kinematics at the last law evaluation
    real(wp), allocatable :: gq(:)               ! generalized forces at the speeds of the last inverse dynamics
    real(wp), allocatable :: g_mat(:, :), p_mat(:, :), h_mat(:, :)   ! G, P, H (kinetostatics_mechanism_twists,
                                                                     ! kinetostatics_mechanism_dynamics)
    ! the (t, q, s) and law switches of the last completed `dynamics`, and the evaluation count then:
    ! its results still hold while no position pass or law evaluation has run since (a record at the
    ! state a root function just saw)
    integer :: known_evaluation = -1             ! -1: none
    real(wp) :: known_t = 0
    real(wp), allocatable :: known_q(:), known_s(:)
    logical, allocatable :: known_active(:)
    integer :: dynamics_reused = 0               ! dynamics that returned the cached results
    ! the closure and rate solves (gfortran puts automatic arrays on the heap)
    real(wp), allocatable :: work_r(:)                       ! r: J_beta solves, the predictor's correction
    real(wp), allocatable :: work_x(:)                       ! r + nd: the combined [beta'; sigma'] system
    real(wp), allocatable :: x_r(:), start_r(:), res_r(:)    ! r: Newton's iterate, warm start, residual
    ! the last closure solutions (beta, q), a ring of `recent_solutions`, and
    ! the charts' changes when each was found (-1: none): after a failed
    ! solve the warm start is the one nearest the new q (a trial step the
    ! integrator rejected leaves its solutions far ahead;
    ! kinetostatics_mechanism_closure)
    real(wp), allocatable :: recent_r(:, :), recent_q(:, :)  ! r x recent_solutions, f x recent_solutions
    integer :: recent_charts(recent_solutions) = -1
    integer :: recent_next = 1                               ! the slot the next solution takes
    real(wp), allocatable :: work_f(:)                       ! ns: a unit s' (mass-matrix columns)
    real(wp), allocatable :: work_c(:)                       ! contacts: normal forces of a record
    ! the equations of motion
    real(wp), allocatable :: chol(:, :), n0(:)               ! M's Cholesky factor, N0
    real(wp), allocatable :: block(:, :), block_rhs(:), signs(:)   ! the scaled laws' block system
    integer, allocatable :: ipiv_block(:)
    ! the partial twists of the tracked frames (kinetostatics_mechanism_twists)
    real(wp), allocatable :: twist(:, :, :)      ! (6, tracked, ns): (alpha, a) per unit s'_i at rest
                                                 ! (= (omega, v) per unit s_i)
    real(wp), allocatable :: wrench(:, :, :)     ! (6, tracked, ns): inertial (torque, force) per unit s'_i
    real(wp), allocatable :: unknown_twist(:, :, :)   ! (6, tracked, moving unknowns): per unit rate, nothing solved
    real(wp), allocatable :: nu(:, :, :)         ! (6, tracked, contacts): N = -normal_sign nu_c . wrenches
    real(wp), allocatable :: load_wrench(:, :)   ! (6, tracked): a scaled law's unit loads
    type(tree_work_t) :: tree                    ! the recursion's arrays (a chain or tree of bodies)
  end type mechanism_workspace_t
end module kinetostatics_mechanism_workspace
