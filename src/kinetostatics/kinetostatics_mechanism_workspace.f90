!> The mechanism's workspace (kinetostatics_mechanism): what a computation
!> needs on its way and no caller reads, apart from the results. The closure
!> solver's iterates, the rate and force solves' right-hand sides, the
!> Cholesky factor and the block system of the equations of motion, the
!> partial twists and wrenches of the tracked frames, and the cache of the
!> last `dynamics` (its state, so that a record at the state a root function
!> just saw reuses it). Sized by the mechanism's finalize; allocated once,
!> never inside a right-hand side.
module kinetostatics_mechanism_workspace
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: mechanism_workspace_t

  type :: mechanism_workspace_t
    ! the (t, q, s) and law switches of the last completed `dynamics`: its results still hold while no
    ! position pass or law evaluation has run since (a record at the state a root function just saw)
    logical :: dynamics_known = .false.
    real(wp) :: known_t = 0
    real(wp), allocatable :: known_q(:), known_s(:)
    logical, allocatable :: known_active(:)
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
