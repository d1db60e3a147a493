!> Common engine of curfit, parcur and concur (Dierckx's fpcurf, fppara and
!> fpcons): a smoothing spline curve of degree k in idim dimensions on the
!> knot range [ub, ue], with the first ib and last ie B-spline coefficients held
!> at zero (concur's end constraints; 0 for curfit and parcur).
!>
!> iopt = -1: least squares on the given knots t(1..n); 0: smoothing from
!> scratch; 1: continue with the knots, fpint and nrdata of the previous call.
!> Knots are added (fpknot) while the least-squares spline has fp > s; then the
!> smoothing parameter p is found by rational interpolation (fprati) until
!> |fp - s| < tol*s, at most maxit iterations (each step: fp_smoothing_step).
!> Coefficients: c(n*(j-1)+i).
!> single_steps (passed to fp_smoothing_step): the p-iteration's one-sided
!> steps (p*con4, p/con4, the con1/con9 mixes) use the single-precision values
!> of 0.1, 0.9 and 0.04, as the
!> genuine fppara of scipy's double-precision FITPACK does (it assigns them from
!> default-real literals; parcur and concur pass true); its fpcurf holds them
!> exact (curfit passes false). Measured against the reference tables: the other
!> choice moves results that take these steps by 1e-12..1e-9 relative.
!> Work arrays as in the originals: fpint(nest), z(nc), a(nest,k1),
!> b(nest,k2), g(nest,k2), q(m,k1), nrdata(nest).
subroutine fpcurve_core(iopt, idim, m, u, mx, x, w, ub, ue, ib, ie, k, s, nest, tol, maxit, single_steps, &
                        k1, k2, n, t, nc, c, fp, fpint, z, a, b, g, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl, fpgivs, fprota, fpback, fpdisc, fpknot, fp_smoothing_step
  implicit none (type, external)
  integer, intent(in) :: iopt, idim, m, mx, ib, ie, k, nest, maxit, k1, k2, nc
  logical, intent(in) :: single_steps
  real(real64), intent(in) :: u(m), x(mx), w(m), ub, ue, s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nc), fp, fpint(nest), z(nc)
  real(real64), intent(inout) :: a(nest, k1), b(nest, k2), g(nest, k2), q(m, k1)

  real(real64), parameter :: half = 0.5_real64
  real(real64) :: h(7), xi(10)
  real(real64), allocatable :: rhs(:, :)   ! smoothing right-hand sides (heap: nest can be large)
  real(real64) :: acc, fp0, fpold, fpms, fpart, term, fac, store, rn, p, p1, p3, f1, f3, &
                  pinv, piv, cs, sn, ui, wi
  integer :: nold, nmin, nmax, ib1, ie1, nk1, nfree, nrint, nplus, npl1, iter, it, i, l, &
             d, ich1, ich3, step, n8, lp, new
  logical :: restart

  nmin = 2*k1
  ib1 = max(0, ib - 1)
  ie1 = max(0, ie - 1)
  fp0 = 0
  fpold = 0
  nplus = 0
  acc = 0
  fpms = 0
  if (iopt >= 0) then
    acc = tol*s
    nmax = m + k1 + ib1 + ie1
    if (s > 0) then
      restart = iopt == 0 .or. n == nmin
      if (.not. restart) then
        fp0 = fpint(n)
        fpold = fpint(n - 1)
        nplus = nrdata(n)
        restart = fp0 <= s
      end if
      if (restart) then
        n = nmin
        fpold = 0
        nplus = 0
        nrdata(1) = m - 2
      end if
    else
      n = nmax
      if (nmax > nest) then
        ier = 1
        return
      end if
      call interpolation_knots()
    end if
  else
    nmax = n
  end if

  ! least-squares splines on growing knot sets (m bounds the number of sets)
  iter = 0
  knots: do while (iter < m)
    iter = iter + 1
    if (n == nmin) ier = -2
    nrint = n - nmin + 1
    nk1 = n - k1
    nfree = nk1 - ib - ie
    t(1:k1) = ub
    t(n - k1 + 1:n) = ue
    fp = 0
    z(1:idim*n) = 0
    a(1:nk1, 1:k1) = 0
    l = k1
    do it = 1, m
      ui = u(it)
      wi = w(it)
      do while (ui >= t(l + 1) .and. l /= nk1)
        l = l + 1
      end do
      call fpbspl(t, n, k, ui, l, h)
      do i = 1, k1
        q(it, i) = h(i)
        h(i) = h(i)*wi
      end do
      do d = 1, idim
        xi(d) = x(idim*(it - 1) + d)*wi
      end do
      call rotate_row(h, k1, l - k1 + 1, a, k1)
      do d = 1, idim
        fp = fp + xi(d)**2
      end do
    end do
    if (ier == -2) fp0 = fp
    fpint(n) = fp0
    fpint(n - 1) = fpold
    nrdata(n) = nplus
    call solve(a, k1)
    if (iopt < 0) return
    fpms = fp - s
    if (abs(fpms) < acc) return
    if (fpms < 0) exit knots
    if (n == nmax) then
      ier = -1
      return
    end if
    if (n == nest) then
      ier = 1
      return
    end if
    ! how many knots to add: 1 at first, then from the last reduction of fp
    if (ier /= 0) then
      nplus = 1
      ier = 0
    else
      npl1 = nplus*2
      rn = nplus
      if (fpold - fp > acc) npl1 = int(rn*fpms/(fpold - fp))
      nplus = min(nplus*2, max(npl1, nplus/2, 1))
    end if
    fpold = fp
    ! residual sums per knot interval; a point on a knot counts half to each side
    fpart = 0
    i = 1
    l = k2
    new = 0
    do it = 1, m
      if (u(it) >= t(l) .and. l <= nk1) then
        new = 1
        l = l + 1
      end if
      term = residual2(it, l)
      fpart = fpart + term
      if (new /= 0) then
        store = term*half
        fpint(i) = fpart - store
        i = i + 1
        fpart = store
        new = 0
      end if
    end do
    fpint(nrint) = fpart
    do lp = 1, nplus
      nold = n
      call fpknot(u, m, t, n, fpint, nrdata, nrint, nest, 1)
      if (n == nold) then
        ! no interval holding data carries residual: s is too small for
        ! these data; the least-squares spline on the present knots stands
        if (lp == 1) then
          ier = 2
          return
        end if
        exit
      end if
      if (n == nmax) then
        call interpolation_knots()
        iter = 0
        cycle knots
      end if
      if (n == nest) exit
    end do
  end do knots

  ! the least-squares polynomial is already good enough
  if (ier == -2) return

  ! smoothing: find p with f(p) = fp(p) - s = 0
  nk1 = n - k1
  nfree = nk1 - ib - ie
  n8 = n - nmin
  call fpdisc(t, n, k2, b, nest)
  allocate (rhs(nest, idim))
  p1 = 0
  f1 = fp0 - s
  p3 = -1
  f3 = fpms
  p = 0
  do i = 1, nfree
    p = p + a(i, 1)
  end do
  rn = nfree
  p = rn/p
  ich1 = 0
  ich3 = 0
  do iter = 1, maxit
    pinv = 1/p
    do d = 1, idim
      rhs(1:nfree, d) = z(n*(d - 1) + 1:n*(d - 1) + nfree)
    end do
    g(1:nfree, 1:k1) = a(1:nfree, 1:k1)
    g(1:nfree, k2) = 0
    do it = 1, n8
      h(1:k2) = b(it, 1:k2)*pinv
      xi(1:idim) = 0
      call rotate_smoothing_row(it)
    end do
    call solve_smoothing()
    fp = 0
    l = k2
    do it = 1, m
      if (u(it) >= t(l) .and. l <= nk1) l = l + 1
      fp = fp + residual2(it, l)
    end do
    fpms = fp - s
    call fp_smoothing_step(fpms, acc, .false., iter, maxit, single_steps, p, p1, f1, p3, f3, ich1, ich3, step)
    if (step < 0) cycle
    if (step > 0) ier = step
    return
  end do

contains

  !> Interior knots of the interpolating spline: at data points (odd k) or
  !> midpoints (even k), shifted outwards by ib-1 / ie-1 for concur.
  subroutine interpolation_knots()
    integer :: mk1, k3, ii, jj, ll
    mk1 = m - k1 + ib1 + ie1
    if (mk1 == 0) return
    k3 = k/2
    ii = k2
    jj = k3 + 2 - ib1
    if (k3*2 == k) then
      do ll = 1, mk1
        t(ii) = (u(jj) + u(jj - 1))*half
        ii = ii + 1
        jj = jj + 1
      end do
    else
      do ll = 1, mk1
        t(ii) = u(jj)
        ii = ii + 1
        jj = jj + 1
      end do
    end if
  end subroutine interpolation_knots

  !> Rotates the observation row hrow (nonzero in columns j0..j0+len-1 of the
  !> full system) into the triangle mat of the free unknowns, with right-hand
  !> sides xi(1..idim) against z (stride n).
  subroutine rotate_row(hrow, len, j0, mat, bw)
    integer, intent(in) :: len, j0, bw
    real(real64), intent(inout) :: hrow(len), mat(nest, bw)
    integer :: ii, i2, jc, jr, dd
    do ii = 1, len
      jc = j0 + ii - 1
      if (jc <= ib .or. jc > nk1 - ie) hrow(ii) = 0
    end do
    do ii = 1, len
      piv = hrow(ii)
      if (piv == 0) cycle
      jr = j0 + ii - 1 - ib
      call fpgivs(piv, mat(jr, 1), cs, sn)
      do dd = 1, idim
        call fprota(cs, sn, xi(dd), z(jr + n*(dd - 1)))
      end do
      do i2 = ii + 1, len
        call fprota(cs, sn, hrow(i2), mat(jr, i2 - ii + 1))
      end do
    end do
  end subroutine rotate_row

  !> Rotates the derivative-jump row h(1..k2) (full-system columns row..row+k1)
  !> into g. g is a full band already, so each rotation fills in one column
  !> to the right: as in the originals the row is carried (shifted) through to
  !> the last unknown.
  subroutine rotate_smoothing_row(row)
    integer, intent(in) :: row
    integer :: ii, i2, jr, dd, first, drop
    first = row - ib
    if (first < 1) then
      drop = 1 - first
      h(1:k2 - drop) = h(1 + drop:k2)
      h(k2 - drop + 1:k2) = 0
      first = 1
    end if
    do ii = 1, k2
      if (first + ii - 1 > nfree) h(ii) = 0
    end do
    do jr = first, nfree
      piv = h(1)
      call fpgivs(piv, g(jr, 1), cs, sn)
      do dd = 1, idim
        call fprota(cs, sn, xi(dd), rhs(jr, dd))
      end do
      if (jr == nfree) exit
      i2 = k1
      if (jr > nfree - k1) i2 = nfree - jr
      do ii = 1, i2
        call fprota(cs, sn, h(ii + 1), g(jr, ii + 1))
        h(ii) = h(ii + 1)
      end do
      h(i2 + 1) = 0
    end do
  end subroutine rotate_smoothing_row

  !> Back substitution for the least-squares system; fixed coefficients are 0.
  subroutine solve(mat, bw)
    integer, intent(in) :: bw
    real(real64), intent(in) :: mat(nest, bw)
    integer :: dd, off
    do dd = 1, idim
      off = n*(dd - 1)
      c(off + 1:off + nk1) = 0
      if (nfree > 0) call fpback(mat, z(off + 1), nfree, bw, c(off + ib + 1), nest)
    end do
  end subroutine solve

  subroutine solve_smoothing()
    integer :: dd, off
    do dd = 1, idim
      off = n*(dd - 1)
      c(off + 1:off + nk1) = 0
      if (nfree > 0) call fpback(g, rhs(1, dd), nfree, k2, c(off + ib + 1), nest)
    end do
  end subroutine solve_smoothing

  !> sum over the coordinates of (w (s(u) - x))**2 at data point pt, whose
  !> knot interval ends at t(lint) (lint = l of the originals' loops).
  real(real64) function residual2(pt, lint) result(r)
    integer, intent(in) :: pt, lint
    integer :: dd, jj, ll
    r = 0
    do dd = 1, idim
      fac = 0
      ll = lint - k2 + n*(dd - 1)
      do jj = 1, k1
        ll = ll + 1
        fac = fac + c(ll)*q(pt, jj)
      end do
      r = r + (w(pt)*(fac - x(idim*(pt - 1) + dd)))**2
    end do
  end function residual2
end subroutine fpcurve_core
