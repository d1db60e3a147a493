!> MINPACK's Levenberg-Marquardt code LMDER (libminpack, the original Fortran
!> 77): its explicit interface, and the one translation of the info it
!> returns (MINPACK's lmder documentation) into the test that ended the
!> solve, in one word and in words, and the status it means.
module numerics_lmder
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT, STATUS_NOT_CONVERGED, STATUS_SOLVER
  implicit none (type, external)
  private
  public :: lmder, lmder_fcn_i, lmder_stop

  abstract interface
    subroutine lmder_fcn_i(m, n, x, fvec, fjac, ldfjac, iflag)
      import :: wp
      integer, intent(in) :: m, n, ldfjac
      real(wp), intent(in) :: x(n)
      real(wp), intent(inout) :: fvec(m), fjac(ldfjac, n)
      integer, intent(inout) :: iflag
    end subroutine lmder_fcn_i
  end interface

  interface
    subroutine lmder(fcn, m, n, x, fvec, fjac, ldfjac, ftol, xtol, gtol, maxfev, diag, mode, &
                     factor, nprint, info, nfev, njev, ipvt, qtf, wa1, wa2, wa3, wa4)
      import :: wp, lmder_fcn_i
      procedure(lmder_fcn_i) :: fcn
      integer, intent(in) :: m, n, ldfjac, maxfev, mode, nprint
      real(wp), intent(inout) :: x(n), fvec(m), fjac(ldfjac, n), diag(n)
      real(wp), intent(in) :: ftol, xtol, gtol, factor
      integer, intent(out) :: info, nfev, njev, ipvt(n)
      real(wp), intent(inout) :: qtf(n), wa1(n), wa2(n), wa3(n), wa4(m)
    end subroutine lmder
  end interface

  !> info 0..8: the test in one word, and in words.
  character(len=*), parameter :: stop_tests(0:8) = [character(len=15) :: 'input', 'ftol', 'xtol', &
    'ftol+xtol', 'gtol', 'max_evaluations', 'ftol', 'xtol', 'gtol']
  character(len=*), parameter :: stop_reasons(0:8) = [character(len=150) :: &
    'improper input parameters (info 0)', &
    'ftol test (info 1): the actual and predicted relative reductions of the sum of squares in a step are at '// &
    'most ftol', &
    'xtol test (info 2): the relative change of the parameters in a step is at most xtol (also the end of a '// &
    'trust region shrunk by rejected steps)', &
    'ftol and xtol tests (info 3): the relative reduction of the sum of squares is at most ftol and the '// &
    'relative change of the parameters at most xtol', &
    'gtol test (info 4): the residuals are orthogonal to every column of the Jacobian within gtol (a '// &
    'gradient test)', &
    'evaluation budget (info 5): max_evaluations reached before convergence', &
    'ftol too small (info 6): no further reduction of the sum of squares is possible in machine precision', &
    'xtol too small (info 7): no further improvement of the parameters is possible in machine precision', &
    'gtol too small (info 8): the residuals are orthogonal to the columns of the Jacobian in machine precision']

contains

  !> The test that ended a solve with info >= 0 and the status it means:
  !> improper input (info 0) and a spent budget (info 5) are errors, an
  !> unknown code is a solver error, the tests 1..4 and 6..8 leave status
  !> as it is. (A negative info is the callback's stop: its caller knows why.)
  pure subroutine lmder_stop(info, stop_test, stop_reason, status)
    integer, intent(in) :: info
    character(len=:), allocatable, intent(inout) :: stop_test, stop_reason
    type(status_t), intent(inout) :: status
    if (info < lbound(stop_tests, 1) .or. info > ubound(stop_tests, 1)) then
      stop_test = 'unknown'
      stop_reason = 'unknown info code'
      call set_status(status, STATUS_SOLVER, 'LMDER returned an unknown info code')
      return
    end if
    stop_test = trim(stop_tests(info))
    stop_reason = trim(stop_reasons(info))
    if (info == 0) call set_status(status, STATUS_INVALID_INPUT, 'LMDER info = 0: improper input parameters')
    if (info == 5) call set_status(status, STATUS_NOT_CONVERGED, &
                                   'LMDER info = 5: max_evaluations reached before convergence')
  end subroutine lmder_stop
end module numerics_lmder
