!> Square nonlinear systems f(x) = 0 over MINPACK's HYBRJ (Powell's hybrid
!> method with the user's analytic Jacobian), as the thesis closes kinematic
!> loops: relative step tolerance xtol and step bound factor as HYBRJ defines them.
!>
!> Re-entrant and thread-safe. MINPACK's callbacks carry no user data, so every
!> call of solve_nonlinear keeps its own record (a `solve_frame_t`, a local
!> variable of that call: the system and the status its callbacks report) and
!> pushes it on a per-thread stack (`top`, an OpenMP threadprivate pointer)
!> for the duration of HYBRJ; the callback works on the top record. A residual
!> that itself calls solve_nonlinear pushes its own record above and pops it
!> before returning, so nesting works; each thread has its own stack, so
!> several threads solve at once. This is per-call state, never left behind:
!> `top` is the same on return as on entry, failures included. (Tied OpenMP
!> tasks only; an untied task could resume on another thread's stack.)
module numerics_nonlinear
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT, &
    STATUS_SOLVER, STATUS_NOT_CONVERGED, STATUS_INTERNAL
  implicit none (type, external)
  private
  public :: nonlinear_system_t, nl_residual_i, nl_jacobian_i
  public :: nonlinear_options_t, nonlinear_result_t
  public :: solve_nonlinear, check_jacobian

  !> f(x) = 0 with n equations in n unknowns and the analytic Jacobian df/dx.
  type, abstract :: nonlinear_system_t
  contains
    procedure(nl_residual_i), deferred :: residual
    procedure(nl_jacobian_i), deferred :: jacobian
  end type nonlinear_system_t

  abstract interface
    !> f(x). Leave `status` ok or set an error: the solve stops and returns it.
    subroutine nl_residual_i(self, x, f, status)
      import :: nonlinear_system_t, wp, status_t
      class(nonlinear_system_t), intent(inout) :: self
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: f(:)
      type(status_t), intent(inout) :: status
    end subroutine nl_residual_i

    !> jac(i, j) = d f_i / d x_j.
    subroutine nl_jacobian_i(self, x, jac, status)
      import :: nonlinear_system_t, wp, status_t
      class(nonlinear_system_t), intent(inout) :: self
      real(wp), intent(in) :: x(:)
      real(wp), intent(out) :: jac(:, :)
      type(status_t), intent(inout) :: status
    end subroutine nl_jacobian_i
  end interface

  type :: nonlinear_options_t
    real(wp) :: xtol = 1e-10_wp                 !< HYBRJ: relative error between iterates (thesis 4.4.3: 1e-8; tighter here so loops close to 1e-10)
    real(wp) :: factor = 100                    !< HYBRJ: initial step bound factor (as the thesis)
    integer :: max_evaluations = 1000           !< HYBRJ maxfev (residual evaluations)
    real(wp) :: residual_tolerance = 1e-10_wp   !< failure if max|f| exceeds this at the end
  end type nonlinear_options_t

  type :: nonlinear_result_t
    integer :: info = 0                  !< HYBRJ's info code
    integer :: evaluations = 0           !< residual evaluations (nfev)
    integer :: jacobian_evaluations = 0  !< Jacobian evaluations (njev)
    real(wp) :: residual_norm = huge(1.0_wp)   !< max |f_i| at the returned x
  end type nonlinear_result_t

  abstract interface
    subroutine hybrj_fcn_i(n, x, fvec, fjac, ldfjac, iflag)
      import :: wp
      integer, intent(in) :: n, ldfjac
      real(wp), intent(in) :: x(n)
      real(wp), intent(inout) :: fvec(n), fjac(ldfjac, n)
      integer, intent(inout) :: iflag
    end subroutine hybrj_fcn_i
  end interface

  interface
    !> MINPACK (original Fortran 77), libminpack.
    subroutine hybrj(fcn, n, x, fvec, fjac, ldfjac, xtol, maxfev, diag, mode, factor, &
                     nprint, info, nfev, njev, r, lr, qtf, wa1, wa2, wa3, wa4)
      import :: wp, hybrj_fcn_i
      procedure(hybrj_fcn_i) :: fcn
      integer, intent(in) :: n, ldfjac, maxfev, mode, nprint, lr
      real(wp), intent(inout) :: x(n), fvec(n), fjac(ldfjac, n), diag(n)
      real(wp), intent(in) :: xtol, factor
      integer, intent(out) :: info, nfev, njev
      real(wp), intent(inout) :: r(lr), qtf(n), wa1(n), wa2(n), wa3(n), wa4(n)
    end subroutine hybrj
  end interface

  !> One solve in progress: its system, the status its callbacks report, and the
  !> solve it is nested in (see the module comment).
  type :: solve_frame_t
    class(nonlinear_system_t), pointer :: system => null()
    type(status_t) :: status
    type(solve_frame_t), pointer :: below => null()
  end type solve_frame_t

  !> The innermost solve in progress on this thread.
  type(solve_frame_t), pointer :: top => null()
  !$omp threadprivate(top)

contains

  !> Solves f(x) = 0 from the start x (a warm start is the previous solution).
  !> On return x is HYBRJ's last iterate, the solution when status is ok.
  recursive subroutine solve_nonlinear(system, x, options, result, status)
    class(nonlinear_system_t), intent(inout), target :: system
    real(wp), intent(inout) :: x(:)
    type(nonlinear_options_t), intent(in) :: options
    type(nonlinear_result_t), intent(out) :: result
    type(status_t), intent(out) :: status
    ! Automatic (stack) workspace: loop closure runs inside right-hand sides.
    real(wp) :: f(size(x)), fjac(size(x), size(x)), diag(size(x)), r(size(x)*(size(x) + 1)/2)
    real(wp) :: qtf(size(x)), wa1(size(x)), wa2(size(x)), wa3(size(x)), wa4(size(x))
    integer :: n, info, nfev, njev
    character(len=:), allocatable :: what
    character(len=24) :: number
    type(solve_frame_t), target :: frame

    n = size(x)
    if (n < 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'solve_nonlinear: no unknowns')
    else if (.not. all(abs(x) <= huge(x))) then
      call set_status(status, STATUS_INVALID_INPUT, 'solve_nonlinear: start x is not finite')
    else if (.not. (options%xtol >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'solve_nonlinear: xtol must be >= 0')
    else if (.not. (options%factor > 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'solve_nonlinear: factor must be > 0')
    else if (options%max_evaluations < 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'solve_nonlinear: max_evaluations must be >= 1')
    else if (.not. (options%residual_tolerance >= 0)) then
      call set_status(status, STATUS_INVALID_INPUT, 'solve_nonlinear: residual_tolerance must be >= 0')
    end if
    if (.not. status%ok()) return

    frame%system => system
    call push(frame)
    f = 0
    fjac = 0
    diag = 1
    ! mode 1: HYBRJ scales the variables by the column norms of the Jacobian.
    call hybrj(hybrj_callback, n, x, f, fjac, n, options%xtol, options%max_evaluations, &
               diag, 1, options%factor, 0, info, nfev, njev, r, size(r), qtf, wa1, wa2, wa3, wa4)
    top => frame%below

    result%info = info
    result%evaluations = nfev
    result%jacobian_evaluations = njev
    if (info >= 0 .and. all(abs(f) <= huge(f))) result%residual_norm = maxval(abs(f))
    write (number, '(es12.4)') result%residual_norm

    ! The one translation of HYBRJ's info. Codes 3-5 only say that HYBRJ cannot
    ! improve further; the answer is accepted if the residual is small anyway.
    select case (info)
    case (:-1)
      if (.not. frame%status%ok()) then
        status = frame%status   ! the system's own reason, unchanged
      else
        call set_status(status, STATUS_INTERNAL, 'HYBRJ stopped by the callback without a status')
      end if
      return
    case (0)
      call set_status(status, STATUS_INVALID_INPUT, 'HYBRJ info = 0: improper input parameters')
      return
    case (1)
      what = 'HYBRJ info = 1: converged (relative step below xtol)'
    case (2)
      call set_status(status, STATUS_NOT_CONVERGED, 'HYBRJ info = 2: max_evaluations reached, max|f| = ' &
        //trim(adjustl(number)))
      return
    case (3)
      what = 'HYBRJ info = 3: xtol is too small, no further improvement of x is possible'
    case (4)
      what = 'HYBRJ info = 4: iteration not making good progress (last five Jacobian evaluations)'
    case (5)
      what = 'HYBRJ info = 5: iteration not making good progress (last ten iterations)'
    case default
      call set_status(status, STATUS_SOLVER, 'HYBRJ returned an unknown info code')
      return
    end select
    if (.not. (result%residual_norm <= options%residual_tolerance)) then
      call set_status(status, STATUS_NOT_CONVERGED, what//'; max|f| = '//trim(adjustl(number))// &
        ' exceeds residual_tolerance (no root nearby, or a singular Jacobian)')
    end if
  end subroutine solve_nonlinear

  !> Puts the frame of a starting solve on this thread's stack (popped by
  !> `top => frame%below` right after HYBRJ returns).
  subroutine push(frame)
    type(solve_frame_t), intent(inout), target :: frame
    frame%below => top
    top => frame
  end subroutine push

  !> HYBRJ's fcn: iflag 1 = residual into fvec, 2 = Jacobian into fjac; a negative
  !> iflag stops HYBRJ (the status is kept in the top frame). `recursive`: the
  !> system may solve another system inside.
  recursive subroutine hybrj_callback(n, x, fvec, fjac, ldfjac, iflag)
    integer, intent(in) :: n, ldfjac
    real(wp), intent(in) :: x(n)
    real(wp), intent(inout) :: fvec(n), fjac(ldfjac, n)
    integer, intent(inout) :: iflag
    type(solve_frame_t), pointer :: frame

    frame => top
    if (iflag == 1) then
      call frame%system%residual(x, fvec, frame%status)
      if (frame%status%ok() .and. .not. all(abs(fvec) <= huge(fvec))) &
        call set_status(frame%status, STATUS_SOLVER, 'solve_nonlinear: the residual is not finite')
    else if (iflag == 2) then
      call frame%system%jacobian(x, fjac(1:n, 1:n), frame%status)
      if (frame%status%ok() .and. .not. all(abs(fjac(1:n, 1:n)) <= huge(fjac))) &
        call set_status(frame%status, STATUS_SOLVER, 'solve_nonlinear: the Jacobian is not finite')
    end if
    if (.not. frame%status%ok()) iflag = -1
  end subroutine hybrj_callback

  !> Compares the system's Jacobian at x with central differences (step
  !> eps^(1/3) max(1, |x_j|)); max_rel_error is the largest entry difference
  !> relative to the largest Jacobian entry (or absolute if that is below 1).
  !> A test helper: it allocates and is not for inner loops.
  subroutine check_jacobian(system, x, max_rel_error, status)
    class(nonlinear_system_t), intent(inout) :: system
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: max_rel_error
    type(status_t), intent(out) :: status
    real(wp), allocatable :: jac(:, :), fd(:, :), xp(:), fp(:), fm(:)
    real(wp) :: h
    integer :: j, n

    n = size(x)
    allocate (jac(n, n), fd(n, n), xp(n), fp(n), fm(n))
    max_rel_error = huge(1.0_wp)
    call system%jacobian(x, jac, status)
    if (.not. status%ok()) return
    do j = 1, n
      h = epsilon(1.0_wp)**(1.0_wp/3)*max(1.0_wp, abs(x(j)))
      xp = x
      xp(j) = x(j) + h
      call system%residual(xp, fp, status)
      if (.not. status%ok()) return
      xp(j) = x(j) - h
      call system%residual(xp, fm, status)
      if (.not. status%ok()) return
      fd(:, j) = (fp - fm)/(2*h)
    end do
    max_rel_error = maxval(abs(jac - fd))/max(1.0_wp, maxval(abs(jac)))
  end subroutine check_jacobian
end module numerics_nonlinear
