!> The workspace of a mechanism's computations (kinetostatics_mechanism):
!> what a computation needs on its way and no caller reads, apart from the
!> results. The closure solver's iterates and warm start, the rate and force
!> solves' right-hand sides, the Cholesky factor and the block system of the
!> equations of motion, the partial twists and wrenches of the tracked
!> frames, and the cache of the last `dynamics` (its state, so that a record
!> at the state a root function just saw reuses it).
!>
!> Owned by whoever runs the computations (the integration's ODE object,
!> kinetostatics_mechanism_ode), not by the mechanism: the mechanism is the
!> model, passed a workspace by every procedure that needs one. Sized by the
!> mechanism's prepare_workspace on its first use (and again only if the
!> mechanism's sizes change), never inside a right-hand side. One workspace
!> serves one mechanism (or its copies).
module kinetostatics_mechanism_workspace
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: mechanism_workspace_t, WORKSPACE_SIZES

  !> How many sizes of the mechanism the workspace is made for (dims).
  integer, parameter :: WORKSPACE_SIZES = 9

  type :: mechanism_workspace_t
    integer :: dims(WORKSPACE_SIZES) = -1        ! the mechanism's sizes it was made for (prepare_workspace)
    ! the (t, q, s) and law switches of the last completed `dynamics`, and the mechanism's evaluation
    ! count then: its results still hold while no position pass or law evaluation has run since, with
    ! this workspace or any other (a record at the state a root function just saw)
    integer :: known_evaluation = -1             ! -1: none
    real(wp) :: known_t = 0
    real(wp), allocatable :: known_q(:), known_s(:)
    logical, allocatable :: known_active(:)
    integer :: dynamics_reused = 0               ! dynamics that returned the cached results
    ! the closure and rate solves (gfortran puts automatic arrays on the heap)
    real(wp), allocatable :: work_r(:)                       ! r: J_beta solves, the predictor's correction
    real(wp), allocatable :: work_x(:)                       ! r + nd: the combined [beta'; sigma'] system
    real(wp), allocatable :: x_r(:), start_r(:), res_r(:)    ! r: Newton's iterate, warm start, residual
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
  end type mechanism_workspace_t
end module kinetostatics_mechanism_workspace
