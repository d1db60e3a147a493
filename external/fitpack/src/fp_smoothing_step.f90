!> One step of the smoothing-parameter iteration shared by all smoothing
!> routines (fpcurf, fppara, fpcons, fpperi, fpclos, fpsurf, fpregr, fppasu).
!>
!> Given fpms = fp(p) - s of the spline just computed with p, decides:
!>   step = 0   |fpms| < acc (|fpms| <= acc with accept_tie, as fpsurf has it):
!>              accept this spline;
!>   step = 3   iter = maxit without acceptance: stop with ier = 3;
!>   step = 2   fp(p) left the bracket (f3 < fp - s < f1 fails): stop with
!>              ier = 2;
!>   step = -1  p holds the next smoothing parameter.
!> The bracket: p1 (f1 = fp(p1) - s > 0) below and p3 (f3 < 0; p3 < 0 while
!> no upper end is known) above; ich1/ich3 = 0 while the corresponding end
!> has not yet been confirmed (then a fp(p) that does not move away from it
!> by more than acc gives a one-sided step, p*con4 or p/con4, kept inside the
!> bracket by the mixes p1*con9 + p2*con1 and p2*con1 + p3*con9). Otherwise
!> the next p comes from rational interpolation (fprati), which also moves
!> one end of the bracket to p.
!> single_steps: the step constants con1, con9, con4 are the single-precision
!> values of 0.1, 0.9, 0.04, as in scipy's double-precision copies of fppara,
!> fpperi, fpclos, fpsurf and fpregr (README); otherwise exact (fpcurf).
!> The operations and their order are those of the originals, so the results
!> agree bit for bit with the inline iteration this replaces.
subroutine fp_smoothing_step(fpms, acc, accept_tie, iter, maxit, single_steps, p, p1, f1, p3, f3, &
                             ich1, ich3, step)
  use, intrinsic :: iso_fortran_env, only: real32, real64
  use fitpack_interfaces, only: fprati
  implicit none (type, external)
  real(real64), intent(in) :: fpms, acc
  logical, intent(in) :: accept_tie, single_steps
  integer, intent(in) :: iter, maxit
  real(real64), intent(inout) :: p, p1, f1, p3, f3
  integer, intent(inout) :: ich1, ich3
  integer, intent(out) :: step

  real(real64), parameter :: con1_single = real(0.1_real32, real64), &
                             con9_single = real(0.9_real32, real64), &
                             con4_single = real(0.04_real32, real64)
  real(real64), parameter :: con1_double = 0.1_real64, con9_double = 0.9_real64, con4_double = 0.04_real64
  real(real64) :: con1, con9, con4, p2, f2
  logical :: accepted

  if (accept_tie) then
    accepted = abs(fpms) <= acc
  else
    accepted = abs(fpms) < acc
  end if
  if (accepted) then
    step = 0
    return
  end if
  if (iter == maxit) then
    step = 3
    return
  end if
  if (single_steps) then
    con1 = con1_single
    con9 = con9_single
    con4 = con4_single
  else
    con1 = con1_double
    con9 = con9_double
    con4 = con4_double
  end if
  step = -1
  p2 = p
  f2 = fpms
  if (ich3 == 0) then
    if (f2 - f3 <= acc) then
      ! p too large: fp(p) not yet above the least-squares spline's by acc
      p3 = p2
      f3 = f2
      p = p*con4
      if (p <= p1) p = p1*con9 + p2*con1
      return
    end if
    if (f2 < 0) ich3 = 1
  end if
  if (ich1 == 0) then
    if (f1 - f2 <= acc) then
      ! p too small: fp(p) not yet below the polynomial's by acc
      p1 = p2
      f1 = f2
      p = p/con4
      if (p3 < 0) return
      if (p >= p3) p = p2*con1 + p3*con9
      return
    end if
    if (f2 > 0) ich1 = 1
  end if
  if (f2 >= f1 .or. f2 <= f3) then
    step = 2
    return
  end if
  p = fprati(p1, f1, p2, f2, p3, f3)
end subroutine fp_smoothing_step
