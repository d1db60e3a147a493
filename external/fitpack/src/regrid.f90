!> regrid: smoothing (or least-squares, or interpolating) bivariate spline of
!> degrees kx, ky to data z(my*(i-1)+j) on the rectangular grid x(1..mx) x
!> y(1..my), xb <= x(1) < ... < x(mx) <= xe (y likewise). Dierckx's calling
!> sequence and meanings:
!>   iopt = -1 least squares on the interior knots given in tx(kx+2..nx-kx-1),
!>          ty(ky+2..ny-ky-1); 0 smoothing from scratch; 1 continue with the
!>          knots and wrk/iwrk of the previous call.
!>   s >= 0 smoothing factor: the spline with fp = sum (z - s(x,y))^2 within
!>          0.001 s of s and as few knots as FITPACK's strategy finds.
!> Knots are added per direction like curfit's (the data point in the middle of
!> the interval with the largest residual sum), the direction with the larger
!> estimated need first; then the smoothing parameter p is found by rational
!> interpolation (fprati). The grid makes the least-squares problem
!> Ax C Ay' = Z, solved by two sequences of banded Givens reductions (fpgrre).
!> ier: 0 ok; -1 interpolating spline (fp = 0); -2 least-squares polynomial
!> (fp0 = fp is an upper bound for s); 1 nxest/nyest too small; 2 s too small
!> (p-iteration out of theory); 3 maxit = 20 reached; 10 invalid input.
!> lwrk >= 4+nxest*(my+2kx+5)+nyest*(2ky+5)+mx*(kx+1)+my*(ky+1)+max(my,nxest),
!> kwrk >= 3+mx+my+nxest+nyest.
subroutine regrid(iopt, mx, x, my, y, z, xb, xe, yb, ye, kx, ky, s, nxest, nyest, nx, tx, ny, ty, &
                  c, fp, wrk, lwrk, iwrk, kwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpchec
  use fitpack_surface_interfaces, only: fpregr
  implicit none (type, external)
  integer, intent(in) :: iopt, mx, my, kx, ky, nxest, nyest, lwrk, kwrk
  real(real64), intent(in) :: x(mx), y(my), z(mx*my), xb, xe, yb, ye, s
  integer, intent(inout) :: nx, ny
  real(real64), intent(inout) :: tx(nxest), ty(nyest)
  real(real64), intent(inout) :: c((nxest - kx - 1)*(nyest - ky - 1))
  real(real64), intent(out) :: fp
  real(real64), intent(inout) :: wrk(lwrk)
  integer, intent(inout) :: iwrk(kwrk)
  integer, intent(out) :: ier
  real(real64), parameter :: tol = 1.0e-3_real64
  integer, parameter :: maxit = 20
  integer :: kx1, ky1, nminx, nminy, lwest, kwest, i, j, jwrk, lfpx, lfpy, lww, knrx, knry, kndx, kndy
  ier = 10
  fp = 0
  if (iopt < -1 .or. iopt > 1) return
  if (kx <= 0 .or. kx > 5 .or. ky <= 0 .or. ky > 5) return
  kx1 = kx + 1
  ky1 = ky + 1
  nminx = 2*kx1
  nminy = 2*ky1
  if (mx < kx1 .or. nxest < nminx) return
  if (my < ky1 .or. nyest < nminy) return
  lwest = 4 + nxest*(my + 2*kx + 5) + nyest*(2*ky + 5) + mx*kx1 + my*ky1 + max(nxest, my)
  kwest = 3 + mx + my + nxest + nyest
  if (lwrk < lwest .or. kwrk < kwest) return
  if (xb > x(1) .or. xe < x(mx)) return
  do i = 2, mx
    if (x(i - 1) >= x(i)) return
  end do
  if (yb > y(1) .or. ye < y(my)) return
  do i = 2, my
    if (y(i - 1) >= y(i)) return
  end do
  if (iopt < 0) then
    if (nx < nminx .or. nx > nxest) return
    j = nx
    do i = 1, kx1
      tx(i) = xb
      tx(j) = xe
      j = j - 1
    end do
    call fpchec(x, mx, tx, nx, kx, ier)
    if (ier /= 0) return
    if (ny < nminy .or. ny > nyest) return
    j = ny
    do i = 1, ky1
      ty(i) = yb
      ty(j) = ye
      j = j - 1
    end do
    call fpchec(y, my, ty, ny, ky, ier)
    if (ier /= 0) return
  else
    if (s < 0) return
    if (s == 0 .and. (nxest < mx + kx1 .or. nyest < my + ky1)) return
    ier = 0
  end if
  ! wrk(1..4): fp0, fpold, reducx, reducy; iwrk(1..3): lastdi, nplusx, nplusy,
  ! then nrx(mx), nry(my), nrdatx(nxest), nrdaty(nyest): kept for iopt = 1.
  lfpx = 5
  lfpy = lfpx + nxest
  lww = lfpy + nyest
  jwrk = lwrk - 4 - nxest - nyest
  knrx = 4
  knry = knrx + mx
  kndx = knry + my
  kndy = kndx + nxest
  call fpregr(iopt, x, mx, y, my, z, mx*my, xb, xe, yb, ye, kx, ky, s, nxest, nyest, tol, maxit, &
    nx, tx, ny, ty, c, fp, wrk(1), wrk(2), wrk(3), wrk(4), wrk(lfpx), wrk(lfpy), &
    iwrk(1), iwrk(2), iwrk(3), iwrk(knrx), iwrk(knry), iwrk(kndx), iwrk(kndy), wrk(lww), jwrk, ier)
end subroutine regrid

!> fpregr: knot placement and p-iteration of regrid (see there).
subroutine fpregr(iopt, x, mx, y, my, z, mz, xb, xe, yb, ye, kx, ky, s, nxest, nyest, tol, maxit, &
                  nx, tx, ny, ty, c, fp, fp0, fpold, reducx, reducy, fpintx, fpinty, &
                  lastdi, nplusx, nplusy, nrx, nry, nrdatx, nrdaty, wrk, lwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpknot, fp_smoothing_step
  use fitpack_surface_interfaces, only: fpgrre, fp_grid_knots_to_add, fp_grid_add_first
  implicit none (type, external)
  integer, intent(in) :: iopt, mx, my, mz, kx, ky, nxest, nyest, maxit, lwrk
  real(real64), intent(in) :: x(mx), y(my), z(mz), xb, xe, yb, ye, s, tol
  integer, intent(inout) :: nx, ny, lastdi, nplusx, nplusy, nrx(mx), nry(my), nrdatx(nxest), nrdaty(nyest)
  real(real64), intent(inout) :: tx(nxest), ty(nyest), c((nxest - kx - 1)*(nyest - ky - 1))
  real(real64), intent(inout) :: fp, fp0, fpold, reducx, reducy, fpintx(nxest), fpinty(nyest)
  real(real64), intent(inout) :: wrk(lwrk)
  integer, intent(inout) :: ier
  ! The p-iteration's one-sided steps (fp_smoothing_step: p*con4, p/con4, the con1/con9 mixes) use
  ! the single-precision values of 0.1, 0.9 and 0.04, as the genuine fpregr of
  ! scipy's double-precision FITPACK does (it assigns them from default-real
  ! literals). Measured: with exact constants regrid_maxit_b/c (ier = 3) end
  ! 2.3e-7 from the genuine fp (every p of the sequence follows from p = 1 and
  ! the rounded 0.04 at the third iteration); with these they agree bit for bit.
  logical, parameter :: single_steps = .true.
  real(real64) :: acc, fpms, p, p1, p3, f1, f3
  integer :: kx1, ky1, kx2, ky2, nminx, nminy, nmaxx, nmaxy, nxe, nye, mpm, iter, i, j, l, &
    nplx, nply, nrintx, nrinty, ifsx, ifsy, ifbx, ifby, ich1, ich3, step
  integer :: lsx, lsy, lri, lq, lax, lay, lbx, lby
  logical :: knots_loop_done
  kx1 = kx + 1
  ky1 = ky + 1
  kx2 = kx1 + 1
  ky2 = ky1 + 1
  nminx = 2*kx1
  nminy = 2*ky1
  nmaxx = mx + kx1
  nmaxy = my + ky1
  nxe = min(nmaxx, nxest)
  nye = min(nmaxy, nyest)
  ! workspace partition (sized by nxest, nyest; used with the current nx, ny)
  lsx = 1
  lsy = lsx + mx*kx1
  lri = lsy + my*ky1
  lq = lri + max(my, nxest)
  lax = lq + nxest*my
  lbx = lax + nxest*kx2
  lay = lbx + nxest*kx2
  lby = lay + nyest*ky2
  acc = 0
  fpms = 0
  if (iopt >= 0) then
    acc = tol*s
    if (iopt == 0 .or. fp0 <= s) then
      if (s > 0) then
        nx = nminx
        ny = nminy
        lastdi = 0
        nplusx = 0
        nplusy = 0
        fp0 = 0
        fpold = 0
        reducx = 0
        reducy = 0
        nrdatx(1) = mx - 2
        nrdaty(1) = my - 2
      else
        ! s = 0: interpolation knots at data points (odd degree) or midpoints
        nx = nmaxx
        ny = nmaxy
        call interpolation_knots(x, mx, kx, tx)
        call interpolation_knots(y, my, ky, ty)
      end if
    end if
  end if
  ifsx = 0
  ifsy = 0
  ifbx = 0
  ifby = 0
  p = -1
  mpm = mx + my
  knots_loop_done = .false.
  do iter = 1, mpm
    if (nx == nminx .and. ny == nminy) ier = -2
    nrintx = nx - nminx + 1
    nrinty = ny - nminy + 1
    j = nx
    do i = 1, kx1
      tx(i) = xb
      tx(j) = xe
      j = j - 1
    end do
    j = ny
    do i = 1, ky1
      ty(i) = yb
      ty(j) = ye
      j = j - 1
    end do
    call fit(p)
    if (ier == -2) fp0 = fp
    if (iopt < 0) return
    fpms = fp - s
    if (abs(fpms) < acc) return
    if (fpms < 0) then
      knots_loop_done = .true.
      exit
    end if
    if (nx == nmaxx .and. ny == nmaxy) then
      ier = -1
      fp = 0
      return
    end if
    ier = 1
    if (nx == nxe .and. ny == nye) return
    ier = 0
    if (lastdi < 0) reducx = fpold - fp
    if (lastdi > 0) reducy = fpold - fp
    fpold = fp
    nplx = 1
    if (nx /= nminx) nplx = fp_grid_knots_to_add(nplusx, reducx, fpms, acc)
    nply = 1
    if (ny /= nminy) nply = fp_grid_knots_to_add(nplusy, reducy, fpms, acc)
    if (fp_grid_add_first(nplx, nply, lastdi, nx == nxe, ny == nye)) then
      lastdi = -1
      nplusx = nplx
      ifsx = 0
      do l = 1, nplusx
        call fpknot(x, mx, tx, nx, fpintx, nrdatx, nrintx, nxest, 1)
        if (nx == nxe) exit
      end do
    else
      lastdi = 1
      nplusy = nply
      ifsy = 0
      do l = 1, nplusy
        call fpknot(y, my, ty, ny, fpinty, nrdaty, nrinty, nyest, 1)
        if (ny == nye) exit
      end do
    end if
  end do
  if (.not. knots_loop_done) return
  if (ier == -2) return
  ! part 2: the smoothing spline, p such that fp(p) = s
  p1 = 0
  f1 = fp0 - s
  p3 = -1
  f3 = fpms
  p = 1
  ich1 = 0
  ich3 = 0
  do iter = 1, maxit
    call fit(p)
    fpms = fp - s
    call fp_smoothing_step(fpms, acc, .false., iter, maxit, single_steps, p, p1, f1, p3, f3, ich1, ich3, step)
    if (step < 0) cycle
    if (step > 0) ier = step
    return
  end do
contains

  subroutine fit(pp)
    real(real64), intent(in) :: pp
    call fpgrre(ifsx, ifsy, ifbx, ifby, x, mx, y, my, z, mz, kx, ky, tx, nx, ty, ny, pp, c, fp, &
      fpintx, fpinty, wrk(lsx), wrk(lsy), wrk(lri), wrk(lq), wrk(lax), wrk(lay), wrk(lbx), wrk(lby), &
      nrx, nry)
  end subroutine fit

  pure subroutine interpolation_knots(v, m, k, t)
    integer, intent(in) :: m, k
    real(real64), intent(in) :: v(m)
    real(real64), intent(inout) :: t(*)
    integer :: ii, jj, ll, k3, mk1
    mk1 = m - k - 1
    if (mk1 == 0) return
    k3 = k/2
    ii = k + 2
    jj = k3 + 2
    do ll = 1, mk1
      if (2*k3 == k) then
        t(ii) = (v(jj) + v(jj - 1))*0.5_real64
      else
        t(ii) = v(jj)
      end if
      ii = ii + 1
      jj = jj + 1
    end do
  end subroutine interpolation_knots
end subroutine fpregr

!> fpgrre: the (smoothing) spline on the grid for the current knots and p
!> (p <= 0: plain least squares), its residual sum fp and the residual sums per
!> knot interval fpx, fpy (a grid line on a knot counts half to each side).
!> ifsx/ifsy/ifbx/ifby = 0 ask to (re)compute the B-spline values and the
!> discontinuity matrices; they are set to 1 afterwards.
subroutine fpgrre(ifsx, ifsy, ifbx, ifby, x, mx, y, my, z, mz, kx, ky, tx, nx, ty, ny, p, c, fp, &
                  fpx, fpy, spx, spy, right, q, ax, ay, bx, by, nrx, nry)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl, fpdisc, fpgivs, fprota, fpback
  implicit none (type, external)
  integer, intent(inout) :: ifsx, ifsy, ifbx, ifby
  integer, intent(in) :: mx, my, mz, kx, ky, nx, ny
  real(real64), intent(in) :: x(mx), y(my), z(mz), tx(nx), ty(ny), p
  real(real64), intent(inout) :: c(*)
  real(real64), intent(out) :: fp
  real(real64), intent(inout) :: fpx(nx), fpy(ny), spx(mx, kx + 1), spy(my, ky + 1), right(*), q(*)
  real(real64), intent(inout) :: ax(nx, kx + 2), ay(ny, ky + 2), bx(nx, kx + 2), by(ny, ky + 2)
  integer, intent(inout) :: nrx(mx), nry(my)
  real(real64) :: h(7), pinv, term, fac, cs, sn
  integer :: kx1, ky1, nk1x, nk1y, ibandx, ibandy, i, j, l, iz, numx, numy, nroldx, nroldy, &
    k1, k2, l1, l2
  kx1 = kx + 1
  ky1 = ky + 1
  nk1x = nx - kx1
  nk1y = ny - ky1
  pinv = 0
  if (p > 0) pinv = 1/p
  if (ifsx == 0) then
    call basis(tx, nx, kx, x, mx, spx, nrx)
    ifsx = 1
  end if
  if (ifsy == 0) then
    call basis(ty, ny, ky, y, my, spy, nry)
    ifsy = 1
  end if
  if (p > 0) then
    if (ifbx == 0 .and. nx > 2*kx1) call fpdisc(tx, nx, kx + 2, bx, nx)
    ifbx = 1
    if (ifby == 0 .and. ny > 2*ky1) call fpdisc(ty, ny, ky + 2, by, ny)
    ifby = 1
  end if
  ! x direction: Ax (with the rows of Bx/p) to triangle Rx; the same rotations
  ! turn the rows of Z into q (nk1x x my, q((irow-1)*my+j)).
  q(1:nk1x*my) = 0
  ax(1:nk1x, :) = 0
  call reduce(mx, kx, my, spx, nrx, bx, nx, ax, ibandx, .true.)
  ! y direction: Ay to triangle Ry; rows of right-hand sides are the columns
  ! of q; the result goes to c(nk1y*(i-1)+irow).
  c(1:nk1x*nk1y) = 0
  ay(1:nk1y, :) = 0
  call reduce(my, ky, nk1x, spy, nry, by, ny, ay, ibandy, .false.)
  ! back substitution: Ry C1 = H per x-row, then C Rx' = C1 per y-column
  do i = 1, nk1x
    l = (i - 1)*nk1y
    right(1:nk1y) = c(l + 1:l + nk1y)
    call fpback(ay, right, nk1y, ibandy, c(l + 1), ny)
  end do
  block
    real(real64) :: col(nk1x), sol(nk1x)
    do j = 1, nk1y
      do i = 1, nk1x
        col(i) = c((i - 1)*nk1y + j)
      end do
      call fpback(ax, col, nk1x, ibandx, sol, nx)
      do i = 1, nk1x
        c((i - 1)*nk1y + j) = sol(i)
      end do
    end do
  end block
  ! residuals
  fp = 0
  fpx(1:nx) = 0
  fpy(1:ny) = 0
  iz = 0
  nroldx = 0
  do i = 1, mx
    numx = nrx(i)
    nroldy = 0
    do j = 1, my
      numy = nry(j)
      iz = iz + 1
      term = 0
      k1 = numx*nk1y + numy
      do l1 = 1, kx1
        k2 = k1
        fac = spx(i, l1)
        do l2 = 1, ky1
          k2 = k2 + 1
          term = term + fac*spy(j, l2)*c(k2)
        end do
        k1 = k1 + nk1y
      end do
      term = (z(iz) - term)**2
      fp = fp + term
      fpx(numx + 1) = fpx(numx + 1) + term
      fpy(numy + 1) = fpy(numy + 1) + term
      fac = term*0.5_real64
      if (numy /= nroldy) then
        fpy(numy + 1) = fpy(numy + 1) - fac
        fpy(numy) = fpy(numy) + fac
      end if
      nroldy = numy
      if (numx /= nroldx) then
        fpx(numx + 1) = fpx(numx + 1) - fac
        fpx(numx) = fpx(numx) + fac
      end if
    end do
    nroldx = numx
  end do
contains
  pure subroutine basis(t, n, k, v, m, sp, nr)
    integer, intent(in) :: n, k, m
    real(real64), intent(in) :: t(n), v(m)
    real(real64), intent(out) :: sp(m, k + 1)
    integer, intent(out) :: nr(m)
    integer :: ll, ii, number
    real(real64) :: hh(6)
    ll = k + 1
    number = 0
    do ii = 1, m
      do while (v(ii) >= t(ll + 1) .and. ll /= n - k - 1)
        ll = ll + 1
        number = number + 1
      end do
      call fpbspl(t, n, k, v(ii), ll, hh)
      sp(ii, :) = hh(1:k + 1)
      nr(ii) = number
    end do
  end subroutine basis

  !> Rotates the rows of the observation matrix sp (and, p > 0, the rows of
  !> b/p before the data of each new knot interval) into the band a.
  !> first: rhs rows come from z and go to q; else from q (columns) to c.
  subroutine reduce(m, k, nrhs, sp, nr, b, n, a, iband, first)
    integer, intent(in) :: m, k, nrhs, nr(m), n
    real(real64), intent(in) :: sp(m, k + 1), b(n, k + 2)
    real(real64), intent(inout) :: a(n, k + 2)
    integer, intent(out) :: iband
    logical, intent(in) :: first
    integer :: itt, number, nrold, irot, ii, jj, i2, iq, lz
    real(real64) :: piv
    nrold = 0
    iband = k + 1
    lz = 0
    do itt = 1, m
      number = nr(itt)
      do
        if (nrold == number) then
          ! a row of the observation matrix
          h(k + 2) = 0
          h(1:k + 1) = sp(itt, 1:k + 1)
          if (first) then
            right(1:nrhs) = z(lz + 1:lz + nrhs)
            lz = lz + nrhs
          else
            do jj = 1, nrhs
              right(jj) = q((jj - 1)*my + itt)
            end do
          end if
          irot = number
        else
          if (p <= 0) then
            nrold = nrold + 1
            cycle
          end if
          ! a row of the discontinuity matrix, weighted 1/p, zero right-hand side
          iband = k + 2
          h(1:k + 2) = b(nrold + 1, 1:k + 2)*pinv
          right(1:nrhs) = 0
          irot = nrold
        end if
        do ii = 1, iband
          irot = irot + 1
          piv = h(ii)
          if (piv == 0) cycle
          call fpgivs(piv, a(irot, 1), cs, sn)
          if (first) then
            iq = (irot - 1)*my
            do jj = 1, nrhs
              call fprota(cs, sn, right(jj), q(iq + jj))
            end do
          else
            iq = irot
            do jj = 1, nrhs
              call fprota(cs, sn, right(jj), c(iq))
              iq = iq + nk1y
            end do
          end if
          if (ii == iband) exit
          i2 = 1
          do jj = ii + 1, iband
            i2 = i2 + 1
            call fprota(cs, sn, h(jj), a(irot, i2))
          end do
        end do
        if (nrold == number) exit
        nrold = nrold + 1
      end do
    end do
  end subroutine reduce
end subroutine fpgrre
