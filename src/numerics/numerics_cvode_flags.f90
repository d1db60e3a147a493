!> CVODE's failure flags in words: each flag's name, what it means for the
!> caller and the status code it becomes (numerics_ode's cvode_status, the
!> one translation of CVODE return flags, adds the time and CVODE's own
!> message).
module numerics_cvode_flags
  use, intrinsic :: iso_c_binding, only: c_int
  use base_status, only: STATUS_SOLVER, STATUS_INTERNAL, STATUS_INVALID_INPUT
  use fcvode_mod, only: CV_TOO_MUCH_WORK, CV_TOO_MUCH_ACC, CV_ERR_FAILURE, CV_CONV_FAILURE, &
    CV_LINIT_FAIL, CV_LSETUP_FAIL, CV_LSOLVE_FAIL, CV_RHSFUNC_FAIL, CV_FIRST_RHSFUNC_ERR, &
    CV_REPTD_RHSFUNC_ERR, CV_UNREC_RHSFUNC_ERR, CV_RTFUNC_FAIL, CV_NLS_INIT_FAIL, &
    CV_NLS_SETUP_FAIL, CV_CONSTR_FAIL, CV_NLS_FAIL, CV_MEM_FAIL, CV_MEM_NULL, &
    CV_ILL_INPUT, CV_NO_MALLOC, CV_BAD_K, CV_BAD_T, CV_BAD_DKY, CV_TOO_CLOSE, &
    CV_VECTOROP_ERR, CV_CONTEXT_ERR
  implicit none (type, external)
  private
  public :: describe_cvode_flag

contains

  !> The name, meaning and status code of a CVODE failure flag (STATUS_SOLVER
  !> unless the flag says the caller or the program is at fault).
  pure subroutine describe_cvode_flag(flag, name, meaning, code)
    integer(c_int), intent(in) :: flag
    character(len=:), allocatable, intent(out) :: name, meaning
    integer, intent(out) :: code
    code = STATUS_SOLVER
    select case (flag)
    case (CV_TOO_MUCH_WORK)
      name = 'CV_TOO_MUCH_WORK'
      meaning = 'max_steps internal steps were taken before reaching t_out'
    case (CV_TOO_MUCH_ACC)
      name = 'CV_TOO_MUCH_ACC'
      meaning = 'the requested accuracy cannot be reached (tolerances too small)'
    case (CV_ERR_FAILURE)
      name = 'CV_ERR_FAILURE'
      meaning = 'error test failed repeatedly or with the minimum step size'
    case (CV_CONV_FAILURE)
      name = 'CV_CONV_FAILURE'
      meaning = 'the nonlinear solver failed to converge repeatedly or with the minimum step size'
    case (CV_LINIT_FAIL)
      name = 'CV_LINIT_FAIL'
      meaning = 'the linear solver could not be initialized'
    case (CV_LSETUP_FAIL)
      name = 'CV_LSETUP_FAIL'
      meaning = 'the linear solver setup failed (singular iteration matrix?)'
    case (CV_LSOLVE_FAIL)
      name = 'CV_LSOLVE_FAIL'
      meaning = 'the linear solve failed'
    case (CV_RHSFUNC_FAIL)
      name = 'CV_RHSFUNC_FAIL'
      meaning = 'the right-hand side failed'
    case (CV_FIRST_RHSFUNC_ERR)
      name = 'CV_FIRST_RHSFUNC_ERR'
      meaning = 'the right-hand side failed at the first call'
    case (CV_REPTD_RHSFUNC_ERR)
      name = 'CV_REPTD_RHSFUNC_ERR'
      meaning = 'the right-hand side failed repeatedly'
    case (CV_UNREC_RHSFUNC_ERR)
      name = 'CV_UNREC_RHSFUNC_ERR'
      meaning = 'the right-hand side failed and could not be recovered'
    case (CV_RTFUNC_FAIL)
      name = 'CV_RTFUNC_FAIL'
      meaning = 'the root function failed'
    case (CV_NLS_INIT_FAIL)
      name = 'CV_NLS_INIT_FAIL'
      meaning = 'the nonlinear solver could not be initialized'
    case (CV_NLS_SETUP_FAIL)
      name = 'CV_NLS_SETUP_FAIL'
      meaning = 'the nonlinear solver setup failed'
    case (CV_CONSTR_FAIL)
      name = 'CV_CONSTR_FAIL'
      meaning = 'inequality constraints could not be met'
    case (CV_NLS_FAIL)
      name = 'CV_NLS_FAIL'
      meaning = 'the nonlinear solver failed unrecoverably'
    case (CV_MEM_FAIL)
      name = 'CV_MEM_FAIL'
      meaning = 'memory allocation failed'
    case (CV_MEM_NULL)
      name = 'CV_MEM_NULL'
      meaning = 'CVODE memory is missing'
      code = STATUS_INTERNAL
    case (CV_ILL_INPUT)
      name = 'CV_ILL_INPUT'
      meaning = 'an input to CVODE is illegal'
      code = STATUS_INVALID_INPUT
    case (CV_NO_MALLOC)
      name = 'CV_NO_MALLOC'
      meaning = 'CVODE was not initialized'
      code = STATUS_INTERNAL
    case (CV_BAD_K, CV_BAD_T, CV_BAD_DKY)
      name = 'CV_BAD_K/T/DKY'
      meaning = 'interpolation was asked outside the last step'
      code = STATUS_INVALID_INPUT
    case (CV_TOO_CLOSE)
      name = 'CV_TOO_CLOSE'
      meaning = 't_out is too close to the start time'
      code = STATUS_INVALID_INPUT
    case (CV_VECTOROP_ERR)
      name = 'CV_VECTOROP_ERR'
      meaning = 'a vector operation failed'
    case (CV_CONTEXT_ERR)
      name = 'CV_CONTEXT_ERR'
      meaning = 'the SUNDIALS context is missing or wrong'
      code = STATUS_INTERNAL
    case default
      name = 'flag'
      meaning = 'unknown CVODE failure'
    end select
  end subroutine describe_cvode_flag
end module numerics_cvode_flags
