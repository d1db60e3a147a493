!> ODE integration over CVODE (SUNDIALS 6.4, its own Fortran 2003 modules).
!>
!> The model is an `ode_system_t` (right-hand side, optional root functions);
!> the integrator (`ode_integrator_t`) owns CVODE's memory, context, vectors and
!> solvers and never shows them to the model.
!>
!> Methods: variable-order Adams (non-stiff, default; fixed-point iteration, no
!> Jacobian) or BDF (stiff; Newton with a dense difference-quotient Jacobian).
!> Output is at the times the caller asks for (CV_NORMAL: CVODE may step past
!> t_out internally and interpolates back). Root functions g_i(t, y) stop the
!> integration at their zeros; the direction of each crossing is reported.
!>
!> Every CVODE return flag is translated to a status in one place
!> (`cvode_status`); a status set by the system's right-hand side (for example
!> "left the parameter domain") is returned unchanged instead of CVODE's generic
!> "right-hand side failed". A STATUS_DOMAIN from the right-hand side is treated
!> as recoverable: a trial step that overshot the domain is retried with a
!> smaller one, and only if CVODE cannot get on is that status returned.
!>
!> An integrator is not copyable: CVODE keeps the address of its link record.
!> Keep one variable per integration; `destroy` (or going out of scope) frees it.
!> The system is reached through a pointer: declare it `target` (or allocate it)
!> and keep it alive while the integrator is used.
module numerics_ode
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_int, c_long, c_double, &
    c_char, c_null_char, c_loc, c_funloc, c_f_pointer, c_associated
  use base_kinds, only: wp, int64
  use base_text, only: format_integer
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT, &
    STATUS_SOLVER, STATUS_INTERNAL, STATUS_DOMAIN
  use fsundials_context_mod, only: FSUNContext_Create, FSUNContext_Free
  use fsundials_nvector_mod, only: N_Vector, FN_VDestroy, FN_VGetArrayPointer
  use fsundials_matrix_mod, only: SUNMatrix, FSUNMatDestroy
  use fsundials_linearsolver_mod, only: SUNLinearSolver, FSUNLinSolFree
  use fsundials_nonlinearsolver_mod, only: SUNNonlinearSolver, FSUNNonlinSolFree
  use fnvector_serial_mod, only: FN_VNew_Serial
  use numerics_nvector_ops, only: speed_up_vector, serial_data
  use fsunmatrix_dense_mod, only: FSUNDenseMatrix
  use fsunlinsol_dense_mod, only: FSUNLinSol_Dense
  use fsunnonlinsol_fixedpoint_mod, only: FSUNNonlinSol_FixedPoint
  use fcvode_mod, only: FCVodeCreate, FCVodeInit, FCVodeReInit, FCVodeFree, FCVode, &
    FCVodeSStolerances, FCVodeSVtolerances, FCVodeSetUserData, FCVodeSetErrHandlerFn, &
    FCVodeSetLinearSolver, FCVodeSetNonlinearSolver, FCVodeSetMaxNumSteps, &
    FCVodeSetMaxStep, FCVodeSetInitStep, FCVodeSetNonlinConvCoef, FCVodeSetMaxOrd, FCVodeSetStopTime, &
    FCVodeRootInit, FCVodeSetRootDirection, FCVodeGetRootInfo, FCVodeSetNoInactiveRootWarn, &
    FCVodeGetNumSteps, FCVodeGetNumRhsEvals, FCVodeGetNumLinRhsEvals, &
    FCVodeGetNumErrTestFails, FCVodeGetNumNonlinSolvConvFails, FCVodeGetNumGEvals, &
    FCVodeGetLastStep, FCVodeGetLastOrder, FCVodeGetCurrentTime, FCVodeGetDky, &
    CV_ADAMS, CV_BDF, CV_NORMAL, CV_SUCCESS, CV_TSTOP_RETURN, CV_ROOT_RETURN, CV_WARNING, &
    CV_TOO_MUCH_WORK
  use numerics_cvode_flags, only: describe_cvode_flag
  implicit none (type, external)
  private
  public :: ode_system_t, ode_rhs_i, ode_options_t, ode_stats_t, ode_integrator_t
  public :: ODE_ADAMS, ODE_BDF

  integer, parameter :: ODE_ADAMS = 1   !< variable-order Adams-Moulton, non-stiff
  integer, parameter :: ODE_BDF = 2     !< variable-order BDF, stiff

  !> A system y' = f(t, y) with optional root functions g(t, y).
  type, abstract :: ode_system_t
  contains
    procedure(ode_rhs_i), deferred :: rhs
    procedure :: root_count => ode_system_root_count
    procedure :: roots => ode_system_roots
  end type ode_system_t

  abstract interface
    !> ydot = f(t, y). Leave `status` ok, or set an error (e.g. the state left
    !> the model's domain): the integration stops and returns that status.
    subroutine ode_rhs_i(self, t, y, ydot, status)
      import :: ode_system_t, wp, status_t
      class(ode_system_t), intent(inout) :: self   ! inout: systems keep preallocated work
      real(wp), intent(in) :: t, y(:)
      real(wp), intent(out) :: ydot(:)
      type(status_t), intent(inout) :: status
    end subroutine ode_rhs_i
  end interface

  type :: ode_options_t
    real(wp) :: rtol = 1e-10_wp                 !< relative tolerance
    real(wp) :: atol = 1e-10_wp                 !< absolute tolerance (all components)
    real(wp), allocatable :: atol_vector(:)     !< per-component atol; replaces atol if allocated
    integer :: method = ODE_ADAMS               !< ODE_ADAMS or ODE_BDF
    integer :: max_steps = 100000               !< internal steps per output interval (mxstep)
    real(wp) :: max_step = 0                    !< largest step size; 0 = no limit
    real(wp) :: initial_step = 0                !< first step size; 0 = CVODE's estimate
    integer :: max_order = 0                    !< 0 = default (12 Adams, 5 BDF)
    !> the corrector stops when its estimated error is below this fraction of
    !> the local error tolerance (CVODE's nlscoef, whose default this is)
    real(wp) :: convergence_coefficient = 0.1_wp
    integer, allocatable :: root_direction(:)   !< +1 rising only, -1 falling only, 0 both
  end type ode_options_t

  type :: ode_stats_t
    integer(int64) :: steps = 0                 !< internal steps
    integer(int64) :: rhs_evaluations = 0       !< calls of rhs (including difference-quotient Jacobians)
    integer(int64) :: error_test_failures = 0
    integer(int64) :: nonlinear_failures = 0    !< nonlinear solver convergence failures
    integer(int64) :: root_evaluations = 0      !< calls of roots
    real(wp) :: last_step = 0                   !< size of the last internal step
    integer :: last_order = 0                   !< method order of the last internal step
  end type ode_stats_t

  !> What the C callbacks see through user_data: the system and the place for its
  !> status and CVODE's last error message (fixed length: nothing is allocated in
  !> the callbacks unless the system reports an error).
  type :: ode_link_t
    class(ode_system_t), pointer :: system => null()
    type(status_t) :: system_status
    type(status_t) :: recoverable_status   !< the last STATUS_DOMAIN of a trial step
    integer :: root_count = 0
    character(len=512) :: cvode_message = ''
  end type ode_link_t

  type :: ode_integrator_t
    private
    type(c_ptr) :: context = c_null_ptr
    type(c_ptr) :: cvode = c_null_ptr
    type(N_Vector), pointer :: y => null()
    type(N_Vector), pointer :: abstol => null()
    type(N_Vector), pointer :: dky => null()    !< CVodeGetDky's output (step_polynomial)
    type(SUNMatrix), pointer :: matrix => null()
    type(SUNLinearSolver), pointer :: linear_solver => null()
    type(SUNNonlinearSolver), pointer :: nonlinear_solver => null()
    type(ode_link_t), allocatable :: link
    integer(c_int), allocatable :: roots_found(:)
    integer :: n = 0
    real(wp) :: t = 0                           !< time of the state in y
    type(ode_stats_t) :: before_restarts        !< counts of the runs before CVodeReInit (which zeroes them)
  contains
    procedure :: start => ode_start
    procedure :: advance => ode_advance
    procedure :: restart => ode_restart
    procedure :: set_stop_time => ode_set_stop_time
    procedure :: statistics => ode_statistics
    procedure :: step_polynomial => ode_step_polynomial
    procedure :: destroy => ode_destroy
    final :: ode_finalize
  end type ode_integrator_t

contains

  !> Number of root functions; none unless a system overrides this.
  integer function ode_system_root_count(self) result(n)
    class(ode_system_t), intent(in) :: self
    associate (unused => self)   ! the default has no root functions
    end associate
    n = 0
  end function ode_system_root_count

  !> Root functions g(t, y); only called when root_count() > 0.
  subroutine ode_system_roots(self, t, y, g)
    class(ode_system_t), intent(inout) :: self
    real(wp), intent(in) :: t, y(:)
    real(wp), intent(out) :: g(:)
    associate (unused_self => self, unused_t => t, unused_y => y)   ! the default has no roots
    end associate
    g = 1
  end subroutine ode_system_roots

  ! ---------------------------------------------------------------- integrator

  !> Sets up CVODE for `system` from (t0, y0). `system` must outlive the
  !> integrator (CVODE calls it through a pointer).
  subroutine ode_start(self, system, t0, y0, options, status)
    class(ode_integrator_t), intent(inout), target :: self
    class(ode_system_t), intent(inout), target :: system
    real(wp), intent(in) :: t0, y0(:)
    type(ode_options_t), intent(in) :: options
    type(status_t), intent(out) :: status

    call self%destroy()
    call set_up(self, system, t0, y0, options, status)
    if (.not. status%ok()) call self%destroy()   ! never leave a half-made integrator
  end subroutine ode_start

  subroutine set_up(self, system, t0, y0, options, status)
    class(ode_integrator_t), intent(inout), target :: self
    class(ode_system_t), intent(inout), target :: system
    real(wp), intent(in) :: t0, y0(:)
    type(ode_options_t), intent(in) :: options
    type(status_t), intent(out) :: status
    integer(c_int) :: flag, lmm
    integer :: nroots
    real(c_double), pointer :: v(:)

    nroots = system%root_count()
    call check_options(size(y0), nroots, options, status)
    if (.not. status%ok()) return
    if (.not. all(abs(y0) <= huge(y0)) .or. abs(t0) > huge(t0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'ODE start: t0 or y0 is not finite')
      return
    end if

    self%n = size(y0)
    self%t = t0
    allocate (self%link)
    self%link%system => system
    self%link%root_count = nroots
    allocate (self%roots_found(max(nroots, 1)))

    flag = FSUNContext_Create(c_null_ptr, self%context)
    call cvode_status(flag, 'SUNContext_Create', t0, self%link, status)
    if (.not. status%ok()) return
    self%y => FN_VNew_Serial(int(self%n, c_long), self%context)
    if (.not. associated(self%y)) then
      call set_status(status, STATUS_SOLVER, 'ODE start: N_VNew_Serial could not allocate')
      return
    end if
    v => FN_VGetArrayPointer(self%y)
    v = y0
    ! Faster vector operations, bit-identical to the serial ones; CVODE's
    ! vectors are clones of y and share its table of operations.
    if (.not. speed_up_vector(self%y)) then
      call set_status(status, STATUS_SOLVER, 'ODE start: N_VEnableFusedOps_Serial failed')
      return
    end if

    lmm = CV_ADAMS
    if (options%method == ODE_BDF) lmm = CV_BDF
    self%cvode = FCVodeCreate(lmm, self%context)
    if (.not. c_associated(self%cvode)) then
      call set_status(status, STATUS_SOLVER, 'ODE start: CVodeCreate failed')
      return
    end if
    ! Error messages come to us (kept in the link) instead of going to stderr.
    flag = FCVodeSetErrHandlerFn(self%cvode, c_funloc(cvode_error_handler), c_loc(self%link))
    if (flag == CV_SUCCESS) flag = FCVodeInit(self%cvode, c_funloc(cvode_rhs), t0, self%y)
    call cvode_status(flag, 'CVodeInit', t0, self%link, status)
    if (.not. status%ok()) return
    flag = FCVodeSetUserData(self%cvode, c_loc(self%link))
    call cvode_status(flag, 'CVodeSetUserData', t0, self%link, status)
    if (.not. status%ok()) return

    if (allocated(options%atol_vector)) then
      self%abstol => FN_VNew_Serial(int(self%n, c_long), self%context)
      v => FN_VGetArrayPointer(self%abstol)
      v = options%atol_vector
      flag = FCVodeSVtolerances(self%cvode, options%rtol, self%abstol)
    else
      flag = FCVodeSStolerances(self%cvode, options%rtol, options%atol)
    end if
    call cvode_status(flag, 'CVode tolerances', t0, self%link, status)
    if (.not. status%ok()) return

    if (options%method == ODE_BDF) then
      self%matrix => FSUNDenseMatrix(int(self%n, c_long), int(self%n, c_long), self%context)
      self%linear_solver => FSUNLinSol_Dense(self%y, self%matrix, self%context)
      flag = FCVodeSetLinearSolver(self%cvode, self%linear_solver, self%matrix)
      call cvode_status(flag, 'CVodeSetLinearSolver', t0, self%link, status)
    else
      ! Adams: functional (fixed-point) iteration, no Jacobian, as for non-stiff problems.
      self%nonlinear_solver => FSUNNonlinSol_FixedPoint(self%y, 0_c_int, self%context)
      flag = FCVodeSetNonlinearSolver(self%cvode, self%nonlinear_solver)
      call cvode_status(flag, 'CVodeSetNonlinearSolver', t0, self%link, status)
    end if
    if (.not. status%ok()) return

    flag = FCVodeSetMaxNumSteps(self%cvode, int(options%max_steps, c_long))
    if (flag == CV_SUCCESS .and. options%max_step > 0) &
      flag = FCVodeSetMaxStep(self%cvode, options%max_step)
    if (flag == CV_SUCCESS .and. options%initial_step > 0) &
      flag = FCVodeSetInitStep(self%cvode, options%initial_step)
    if (flag == CV_SUCCESS .and. options%convergence_coefficient /= 0.1_wp) &
      flag = FCVodeSetNonlinConvCoef(self%cvode, options%convergence_coefficient)
    if (flag == CV_SUCCESS .and. options%max_order > 0) &
      flag = FCVodeSetMaxOrd(self%cvode, int(options%max_order, c_int))
    call cvode_status(flag, 'CVode options', t0, self%link, status)
    if (.not. status%ok()) return

    if (nroots > 0) then
      flag = FCVodeRootInit(self%cvode, int(nroots, c_int), c_funloc(cvode_roots))
      if (flag == CV_SUCCESS .and. allocated(options%root_direction)) then
        self%roots_found = int(options%root_direction, c_int)
        flag = FCVodeSetRootDirection(self%cvode, self%roots_found)
      end if
      ! A root function that is zero at the start is normal after an event.
      if (flag == CV_SUCCESS) flag = FCVodeSetNoInactiveRootWarn(self%cvode)
      call cvode_status(flag, 'CVodeRootInit', t0, self%link, status)
      if (.not. status%ok()) return
    end if
  end subroutine set_up

  !> Integrates toward t_out. Returns the time reached `t` (t_out unless a root
  !> or the stop time came first, or on failure the last time reached) and y(t).
  !> root_index(i) is +1/-1 when root function i crossed zero rising/falling at t.
  !> With `work_limit_reached` present, CVODE's max_steps limit is not a
  !> failure: the call returns at the time reached with the flag set, and the
  !> caller may call again toward the same t_out (the driver works in chunks).
  subroutine ode_advance(self, t_out, t, y, status, root_found, root_index, work_limit_reached)
    class(ode_integrator_t), intent(inout) :: self
    real(wp), intent(in) :: t_out
    real(wp), intent(out) :: t
    real(wp), intent(out) :: y(:)
    type(status_t), intent(out) :: status
    logical, intent(out), optional :: root_found
    integer, intent(out), optional :: root_index(:)
    logical, intent(out), optional :: work_limit_reached
    integer(c_int) :: flag
    real(c_double) :: t_reached(1)
    real(c_double), pointer :: v(:)
    logical :: started
    type(ode_stats_t) :: stats

    if (present(root_found)) root_found = .false.
    if (present(work_limit_reached)) work_limit_reached = .false.
    if (present(root_index)) root_index = 0
    t = self%t
    if (.not. c_associated(self%cvode)) then
      call set_status(status, STATUS_INTERNAL, 'ODE advance: integrator not started')
      return
    end if
    if (size(y) /= self%n) then
      call set_status(status, STATUS_INVALID_INPUT, 'ODE advance: y has the wrong size')
      return
    end if
    if (present(root_index)) then
      if (size(root_index) < self%link%root_count) then
        call set_status(status, STATUS_INVALID_INPUT, &
          'ODE advance: root_index is smaller than the number of root functions')
        return
      end if
    end if
    v => FN_VGetArrayPointer(self%y)
    if (t_out == self%t) then
      y = v
      return
    end if

    self%link%system_status%code = STATUS_OK
    if (allocated(self%link%system_status%message)) deallocate (self%link%system_status%message)
    self%link%recoverable_status%code = STATUS_OK
    self%link%cvode_message = ''
    t_reached = self%t   ! CVODE leaves it unset on some failures (a root at and very near the last one)
    flag = FCVode(self%cvode, t_out, self%y, t_reached, CV_NORMAL)
    if (flag == CV_TOO_MUCH_WORK .and. present(work_limit_reached)) then
      work_limit_reached = .true.
      flag = CV_SUCCESS
    end if
    ! a failure once steps were taken is one part way, whatever the flag blames
    started = .false.
    if (flag < 0) then
      stats = self%statistics()
      started = stats%steps > 0
    end if
    call cvode_status(flag, 'CVode', t_reached(1), self%link, status, started)

    self%t = t_reached(1)
    t = self%t
    y = v
    if (flag == CV_ROOT_RETURN) then
      if (present(root_found)) root_found = .true.
      if (self%link%root_count > 0) then
        flag = FCVodeGetRootInfo(self%cvode, self%roots_found)
        if (present(root_index)) root_index(1:self%link%root_count) = &
          int(self%roots_found(1:self%link%root_count))
      end if
    end if
  end subroutine ode_advance

  !> Starts again from (t0, y0) with the same system and options, e.g. after an
  !> event changed the state (CVodeReInit: history and step size are discarded).
  subroutine ode_restart(self, t0, y0, status)
    class(ode_integrator_t), intent(inout) :: self
    real(wp), intent(in) :: t0, y0(:)
    type(status_t), intent(out) :: status
    integer(c_int) :: flag
    real(c_double), pointer :: v(:)

    if (.not. c_associated(self%cvode)) then
      call set_status(status, STATUS_INTERNAL, 'ODE restart: integrator not started')
      return
    end if
    if (size(y0) /= self%n .or. .not. all(abs(y0) <= huge(y0))) then
      call set_status(status, STATUS_INVALID_INPUT, 'ODE restart: y0 has the wrong size or is not finite')
      return
    end if
    self%before_restarts = self%statistics()
    v => FN_VGetArrayPointer(self%y)
    v = y0
    self%t = t0
    self%link%cvode_message = ''
    flag = FCVodeReInit(self%cvode, t0, self%y)
    call cvode_status(flag, 'CVodeReInit', t0, self%link, status, started=.true.)
  end subroutine ode_restart

  !> CVODE will not step past t_stop (advance returns at t_stop if t_out is beyond).
  subroutine ode_set_stop_time(self, t_stop, status)
    class(ode_integrator_t), intent(inout) :: self
    real(wp), intent(in) :: t_stop
    type(status_t), intent(out) :: status
    integer(c_int) :: flag
    if (.not. c_associated(self%cvode)) then
      call set_status(status, STATUS_INTERNAL, 'ODE set_stop_time: integrator not started')
      return
    end if
    flag = FCVodeSetStopTime(self%cvode, t_stop)
    call cvode_status(flag, 'CVodeSetStopTime', self%t, self%link, status)
  end subroutine ode_set_stop_time

  !> Counters since start, summed over restarts; last_step and last_order are
  !> those of the latest step.
  function ode_statistics(self) result(stats)
    class(ode_integrator_t), intent(in) :: self
    type(ode_stats_t) :: stats
    integer(c_long) :: count(1), extra(1)
    integer(c_int) :: flag, order(1)
    real(c_double) :: h(1)

    if (.not. c_associated(self%cvode)) return
    stats = self%before_restarts
    flag = FCVodeGetNumSteps(self%cvode, count)
    stats%steps = stats%steps + count(1)
    flag = FCVodeGetNumRhsEvals(self%cvode, count)
    extra = 0
    if (associated(self%linear_solver)) flag = FCVodeGetNumLinRhsEvals(self%cvode, extra)
    stats%rhs_evaluations = stats%rhs_evaluations + count(1) + extra(1)
    flag = FCVodeGetNumErrTestFails(self%cvode, count)
    stats%error_test_failures = stats%error_test_failures + count(1)
    flag = FCVodeGetNumNonlinSolvConvFails(self%cvode, count)
    stats%nonlinear_failures = stats%nonlinear_failures + count(1)
    count = 0
    if (self%link%root_count > 0) flag = FCVodeGetNumGEvals(self%cvode, count)
    stats%root_evaluations = stats%root_evaluations + count(1)
    h = 0
    flag = FCVodeGetLastStep(self%cvode, h)
    stats%last_step = h(1)
    order = 0
    flag = FCVodeGetLastOrder(self%cvode, order)
    stats%last_order = order(1)
  end function ode_statistics

  !> The integrator's dense output over its last internal step [t_n - h, t_n]:
  !> the polynomial CVODE interpolates with there (CVodeGetDky), as Taylor
  !> coefficients at t_n, y(t) = sum_k taylor(:, k) (t - t_n)^k for k = 0 ..
  !> order (the order of that step, at most size(taylor, 2) - 1). h = 0: no
  !> step since the start or the last restart (nothing to interpolate).
  subroutine ode_step_polynomial(self, t_n, h, order, taylor, status)
    class(ode_integrator_t), intent(inout) :: self
    real(wp), intent(out) :: t_n, h
    integer, intent(out) :: order
    real(wp), intent(inout) :: taylor(:, 0:)
    type(status_t), intent(out) :: status
    integer(c_int) :: flag, q(1)
    real(c_double) :: t_now(1), h_last(1)
    real(c_double), pointer :: v(:)
    integer :: k
    t_n = self%t
    h = 0
    order = 0
    if (.not. c_associated(self%cvode)) then
      call set_status(status, STATUS_INTERNAL, 'ODE step polynomial: integrator not started')
      return
    end if
    flag = FCVodeGetCurrentTime(self%cvode, t_now)
    if (flag == CV_SUCCESS) flag = FCVodeGetLastStep(self%cvode, h_last)
    if (flag == CV_SUCCESS) flag = FCVodeGetLastOrder(self%cvode, q)
    call cvode_status(flag, 'CVodeGetLastStep', self%t, self%link, status)
    if (.not. status%ok()) return
    t_n = t_now(1)
    if (h_last(1) == 0 .or. q(1) < 1) return
    if (q(1) > ubound(taylor, 2) .or. size(taylor, 1) /= self%n) then
      call set_status(status, STATUS_INTERNAL, 'ODE step polynomial: taylor must be n x (0:'// &
                      format_integer(int(q(1)))//')')
      return
    end if
    if (.not. associated(self%dky)) self%dky => FN_VNew_Serial(int(self%n, c_long), self%context)
    v => FN_VGetArrayPointer(self%dky)
    do k = 0, q(1)
      flag = FCVodeGetDky(self%cvode, t_now(1), int(k, c_int), self%dky)
      call cvode_status(flag, 'CVodeGetDky', t_n, self%link, status)
      if (.not. status%ok()) return
      taylor(:, k) = v/factorial(k)
    end do
    h = h_last(1)
    order = q(1)
  contains
    pure real(wp) function factorial(k)
      integer, intent(in) :: k
      integer :: i
      factorial = 1
      do i = 2, k
        factorial = factorial*i
      end do
    end function factorial
  end subroutine ode_step_polynomial

  !> Frees everything CVODE holds; the integrator can be started again.
  subroutine ode_destroy(self)
    class(ode_integrator_t), intent(inout) :: self
    integer(c_int) :: flag
    if (c_associated(self%cvode)) call FCVodeFree(self%cvode)
    self%cvode = c_null_ptr
    if (associated(self%nonlinear_solver)) flag = FSUNNonlinSolFree(self%nonlinear_solver)
    if (associated(self%linear_solver)) flag = FSUNLinSolFree(self%linear_solver)
    if (associated(self%matrix)) call FSUNMatDestroy(self%matrix)
    if (associated(self%abstol)) call FN_VDestroy(self%abstol)
    if (associated(self%dky)) call FN_VDestroy(self%dky)
    if (associated(self%y)) call FN_VDestroy(self%y)
    nullify (self%nonlinear_solver, self%linear_solver, self%matrix, self%abstol, self%dky, self%y)
    if (c_associated(self%context)) flag = FSUNContext_Free(self%context)
    self%context = c_null_ptr
    if (allocated(self%link)) deallocate (self%link)
    if (allocated(self%roots_found)) deallocate (self%roots_found)
    self%n = 0
    self%before_restarts = ode_stats_t()
  end subroutine ode_destroy

  subroutine ode_finalize(self)
    type(ode_integrator_t), intent(inout) :: self
    call self%destroy()
  end subroutine ode_finalize

  ! ------------------------------------------------------------------ helpers

  subroutine check_options(n, nroots, options, status)
    integer, intent(in) :: n, nroots
    type(ode_options_t), intent(in) :: options
    type(status_t), intent(out) :: status
    character(len=*), parameter :: where = 'ODE options: '
    if (n < 1) then
      call set_status(status, STATUS_INVALID_INPUT, where//'the state vector is empty')
    else if (.not. (options%rtol >= 0 .and. options%rtol < 1)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'rtol must be in [0, 1)')
    else if (.not. (options%atol >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'atol must be >= 0')
    else if (options%method /= ODE_ADAMS .and. options%method /= ODE_BDF) then
      call set_status(status, STATUS_INVALID_INPUT, where//'method must be ODE_ADAMS or ODE_BDF')
    else if (options%max_steps < 1) then
      call set_status(status, STATUS_INVALID_INPUT, where//'max_steps must be >= 1')
    else if (.not. (options%max_step >= 0 .and. options%initial_step >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, where//'max_step and initial_step must be >= 0')
    else if (options%max_order < 0) then
      call set_status(status, STATUS_INVALID_INPUT, where//'max_order must be >= 0')
    end if
    if (.not. status%ok()) return
    if (allocated(options%atol_vector)) then
      if (size(options%atol_vector) /= n) then
        call set_status(status, STATUS_INVALID_INPUT, where//'atol_vector must have one entry per state')
      else if (.not. all(options%atol_vector >= 0)) then
        call set_status(status, STATUS_INVALID_INPUT, where//'atol_vector entries must be >= 0')
      end if
    end if
    if (.not. status%ok()) return
    if (allocated(options%root_direction)) then
      if (size(options%root_direction) /= nroots) then
        call set_status(status, STATUS_INVALID_INPUT, &
          where//'root_direction must have one entry per root function')
      else if (any(abs(options%root_direction) > 1)) then
        call set_status(status, STATUS_INVALID_INPUT, where//'root_direction entries must be -1, 0 or +1')
      end if
    end if
  end subroutine check_options

  !> The one translation of CVODE return flags into statuses. A status set by
  !> the system's right-hand side wins over the flag it caused. `started`:
  !> the integration had begun (steps taken, records made), so a flag that
  !> blames CVODE's input (CV_ILL_INPUT: a root at and very near another, an
  !> error weight that became zero) is a run failed part way (STATUS_SOLVER),
  !> not bad input with nothing done.
  subroutine cvode_status(flag, call_name, t, link, status, started)
    integer(c_int), intent(in) :: flag
    character(len=*), intent(in) :: call_name
    real(wp), intent(in) :: t
    type(ode_link_t), intent(in) :: link
    type(status_t), intent(out) :: status
    logical, intent(in), optional :: started
    character(len=:), allocatable :: name, meaning
    character(len=32) :: time
    integer :: code
    if (flag == CV_SUCCESS .or. flag == CV_TSTOP_RETURN .or. flag == CV_ROOT_RETURN .or. &
        flag == CV_WARNING) return
    call describe_cvode_flag(flag, name, meaning, code)

    if (.not. link%system_status%ok()) then
      status = link%system_status   ! the system said why; keep its status as it is
      return
    end if
    if (.not. link%recoverable_status%ok()) then
      status = link%recoverable_status   ! CVODE gave up retrying steps the system refused
      return
    end if
    write (time, '(es23.15)') t
    if (present(started)) then
      if (started .and. code == STATUS_INVALID_INPUT) code = STATUS_SOLVER
    end if
    status%code = code
    status%message = call_name//' failed at t = '//trim(adjustl(time))//': '//name// &
      ' ('//format_integer(int(flag))//'), '//meaning
    if (len_trim(link%cvode_message) > 0) &
      status%message = status%message//'; CVODE says: '//trim(link%cvode_message)
  end subroutine cvode_status


  ! ------------------------------------------------- C callbacks (no allocation)

  !> CVRhsFn: 0 = ok, -1 = unrecoverable (the system set an error status).
  integer(c_int) function cvode_rhs(t, y, ydot, user_data) result(ierr) bind(C)
    real(c_double), value :: t
    type(c_ptr), value :: y, ydot   ! N_Vector
    type(c_ptr), value :: user_data
    type(ode_link_t), pointer :: link
    real(c_double), pointer, contiguous :: yv(:), ydotv(:)

    call c_f_pointer(user_data, link)
    call serial_data(y, yv)
    call serial_data(ydot, ydotv)
    ierr = -1
    if (.not. link%system_status%ok()) return
    call link%system%rhs(t, yv, ydotv, link%system_status)
    if (link%system_status%ok()) then
      ierr = 0
    else if (link%system_status%code == STATUS_DOMAIN) then
      ! Recoverable: CVODE retries with a smaller step; remember why in case it gives up.
      call move_alloc(link%system_status%message, link%recoverable_status%message)
      link%recoverable_status%code = STATUS_DOMAIN
      link%system_status%code = STATUS_OK
      ierr = 1
    end if
  end function cvode_rhs

  !> CVRootFn: g(t, y) for all root functions.
  integer(c_int) function cvode_roots(t, y, gout, user_data) result(ierr) bind(C)
    real(c_double), value :: t
    type(c_ptr), value :: y   ! N_Vector
    real(c_double) :: gout(*)
    type(c_ptr), value :: user_data
    type(ode_link_t), pointer :: link
    real(c_double), pointer, contiguous :: yv(:)

    call c_f_pointer(user_data, link)
    call serial_data(y, yv)
    call link%system%roots(t, yv, gout(1:link%root_count))
    ierr = 0
  end function cvode_roots

  !> CVErrHandlerFn: keeps the text of CVODE's last error in the link.
  subroutine cvode_error_handler(error_code, module_name, function_name, message, eh_data) bind(C)
    integer(c_int), value :: error_code
    type(c_ptr), value :: module_name, function_name, message, eh_data
    type(ode_link_t), pointer :: link

    if (error_code == CV_WARNING .or. .not. c_associated(eh_data)) return
    if (.not. c_associated(message)) return
    call c_f_pointer(eh_data, link)
    link%cvode_message = ''
    call append_c_string(module_name, link%cvode_message)
    call append_c_string(function_name, link%cvode_message)
    call append_c_string(message, link%cvode_message)
  end subroutine cvode_error_handler

  !> Appends a C string (and a blank) to a fixed-length buffer, truncating.
  subroutine append_c_string(c_string, buffer)
    type(c_ptr), intent(in) :: c_string
    character(len=*), intent(inout) :: buffer
    character(kind=c_char), pointer :: chars(:)
    integer :: i, k
    if (.not. c_associated(c_string)) return
    k = len_trim(buffer)
    if (k > 0) k = k + 1
    call c_f_pointer(c_string, chars, [len(buffer)])
    do i = 1, len(buffer) - k
      if (chars(i) == c_null_char) exit
      buffer(k + i:k + i) = chars(i)
    end do
  end subroutine append_c_string
end module numerics_ode
