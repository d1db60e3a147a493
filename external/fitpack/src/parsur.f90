!> parsur: smoothing bicubic parametric surface r(u,v) in idim (1..3)
!> dimensions to points f(mu*mv*(l-1)+mv*(i-1)+j) = r_l(u(i), v(j)) on a grid,
!> optionally periodic in u (ipar(1) = 1) and/or v (ipar(2) = 1) with period
!> u(mu)-u(1) (v(mv)-v(1)). Dierckx's calling sequence and meanings (iopt,
!> s, ier as in regrid; fp sums over the coordinates). On a periodic
!> direction the first and last grid lines are one line: their data are
!> averaged and counted once. Knots are placed like regrid's (fppasu); the
!> grid least-squares problem is solved per direction by Givens rotations
!> (fpgrpa), with wrap-around columns for periodic B-splines; smoothing
!> penalizes the jumps of the third derivative at the interior knots (and, if
!> periodic, at the seam).
!> Coefficients: c((nu-4)*(nv-4)*(l-1)+(nv-4)*(i-1)+j); on a periodic
!> direction the last three coefficient lines repeat the first three.
!> lwrk >= 4+nuest*(mv*idim+11+4*ipar(1))+nvest*(11+4*ipar(2))+4*(mu+mv)
!>         +max(nuest,mv)*idim,  kwrk >= 3+mu+mv+nuest+nvest (checked as
!> Dierckx's rules; wrk/iwrk keep fp0, the knot counts and residual sums for
!> iopt = 1, while the grid solver allocates its own arrays).
subroutine parsur(iopt, ipar, idim, mu, u, mv, v, f, s, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, &
                  iwrk, kwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpchec, fpchep
  use fitpack_surface_interfaces, only: fppasu
  implicit none (type, external)
  integer, intent(in) :: iopt, ipar(2), idim, mu, mv, nuest, nvest, lwrk, kwrk
  real(real64), intent(in) :: u(mu), v(mv), f(mu*mv*idim), s
  integer, intent(inout) :: nu, nv
  real(real64), intent(inout) :: tu(nuest), tv(nvest), c((nuest - 4)*(nvest - 4)*idim)
  real(real64), intent(out) :: fp
  real(real64), intent(inout) :: wrk(lwrk)
  integer, intent(inout) :: iwrk(kwrk)
  integer, intent(out) :: ier
  real(real64), parameter :: tol = 1.0e-3_real64
  integer, parameter :: maxit = 20
  integer :: lwest, kwest, i
  ier = 10
  fp = 0
  if (iopt < -1 .or. iopt > 1) return
  if (ipar(1) < 0 .or. ipar(1) > 1 .or. ipar(2) < 0 .or. ipar(2) > 1) return
  if (idim <= 0 .or. idim > 3) return
  if (mu < 4 .or. nuest < 8 .or. mv < 4 .or. nvest < 8) return
  lwest = 4 + nuest*(mv*idim + 11 + 4*ipar(1)) + nvest*(11 + 4*ipar(2)) + 4*(mu + mv) + max(nuest, mv)*idim
  kwest = 3 + mu + mv + nuest + nvest
  if (lwrk < lwest .or. kwrk < kwest) return
  do i = 2, mu
    if (u(i - 1) >= u(i)) return
  end do
  do i = 2, mv
    if (v(i - 1) >= v(i)) return
  end do
  if (iopt < 0) then
    if (nu < 8 .or. nu > nuest .or. nv < 8 .or. nv > nvest) return
    call boundary_knots(tu, nu, u(1), u(mu), ipar(1))
    call boundary_knots(tv, nv, v(1), v(mv), ipar(2))
    if (ipar(1) == 0) then
      call fpchec(u, mu, tu, nu, 3, ier)
    else
      call fpchep(u, mu, tu, nu, 3, ier)
    end if
    if (ier /= 0) return
    if (ipar(2) == 0) then
      call fpchec(v, mv, tv, nv, 3, ier)
    else
      call fpchep(v, mv, tv, nv, 3, ier)
    end if
    if (ier /= 0) return
  else
    if (s < 0) return
    if (s == 0 .and. (nuest < mu + 4 + 2*ipar(1) .or. nvest < mv + 4 + 2*ipar(2))) return
    ier = 0
  end if
  call fppasu(iopt, ipar, idim, u, mu, v, mv, f, s, nuest, nvest, tol, maxit, nu, tu, nv, tv, c, fp, &
    wrk(1), wrk(2), wrk(3), wrk(4), wrk(5), wrk(5 + nuest), iwrk(1), iwrk(2), iwrk(3), &
    iwrk(4), iwrk(4 + mu), iwrk(4 + mu + mv), iwrk(4 + mu + mv + nuest), ier)
contains
  pure subroutine boundary_knots(t, n, tb, te, per)
    integer, intent(in) :: n, per
    real(real64), intent(inout) :: t(n)
    real(real64), intent(in) :: tb, te
    integer :: j
    if (per == 0) then
      t(1:4) = tb
      t(n - 3:n) = te
    else
      t(4) = tb
      t(n - 3) = te
      do j = 1, 3
        t(4 - j) = t(n - 3 - j) - (te - tb)
        t(n - 3 + j) = t(4 + j) + (te - tb)
      end do
    end if
  end subroutine boundary_knots
end subroutine parsur

!> fppasu: knot placement and p-iteration of parsur (regrid's strategy).
subroutine fppasu(iopt, ipar, idim, u, mu, v, mv, f, s, nuest, nvest, tol, maxit, nu, tu, nv, tv, c, fp, &
                  fp0, fpold, reducu, reducv, fpintu, fpintv, lastdi, nplusu, nplusv, nru, nrv, &
                  nrdatu, nrdatv, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpknot, fp_smoothing_step
  use fitpack_surface_interfaces, only: fpgrpa, fp_grid_knots_to_add, fp_grid_add_first
  implicit none (type, external)
  integer, intent(in) :: iopt, ipar(2), idim, mu, mv, nuest, nvest, maxit
  real(real64), intent(in) :: u(mu), v(mv), f(mu*mv*idim), s, tol
  integer, intent(inout) :: nu, nv, lastdi, nplusu, nplusv, nru(mu), nrv(mv), nrdatu(nuest), nrdatv(nvest)
  real(real64), intent(inout) :: tu(nuest), tv(nvest), c((nuest - 4)*(nvest - 4)*idim)
  real(real64), intent(inout) :: fp, fp0, fpold, reducu, reducv, fpintu(nuest), fpintv(nvest)
  integer, intent(inout) :: ier
  ! The p-iteration's one-sided steps (fp_smoothing_step) use the single-precision values of 0.1,
  ! 0.9 and 0.04 like those of its sibling fpregr (regrid), so that non-periodic
  ! parsur stays regrid; scipy does not wrap parsur, so this cannot be measured
  ! against the genuine fppasu.
  logical, parameter :: single_steps = .true.
  real(real64), allocatable :: ff(:)
  real(real64) :: acc, fpms, p, p1, p3, f1, f3
  integer :: nmaxu, nmaxv, nue, nve, iter, l, nplu, nplv, nrintu, nrintv, ich1, ich3, step, i, j, ll, &
    i1, i2
  logical :: accepted
  nmaxu = mu + 4 + 2*ipar(1)
  nmaxv = mv + 4 + 2*ipar(2)
  nue = min(nmaxu, nuest)
  nve = min(nmaxv, nvest)
  ! data, with the two lines of a periodic direction averaged
  allocate (ff(size(f)))
  ff = f
  if (ipar(1) == 1) then
    do ll = 1, idim
      do j = 1, mv
        i1 = mu*mv*(ll - 1) + j
        i2 = mu*mv*(ll - 1) + mv*(mu - 1) + j
        ff(i1) = (ff(i1) + ff(i2))*0.5_real64
        ff(i2) = ff(i1)
      end do
    end do
  end if
  if (ipar(2) == 1) then
    do ll = 1, idim
      do i = 1, mu
        i1 = mu*mv*(ll - 1) + mv*(i - 1) + 1
        i2 = i1 + mv - 1
        ff(i1) = (ff(i1) + ff(i2))*0.5_real64
        ff(i2) = ff(i1)
      end do
    end do
  end if
  acc = 0
  fpms = 0
  if (iopt >= 0) then
    acc = tol*s
    if (iopt == 0 .or. fp0 <= s) then
      if (s > 0) then
        nu = 8
        nv = 8
        lastdi = 0
        nplusu = 0
        nplusv = 0
        fp0 = 0
        fpold = 0
        reducu = 0
        reducv = 0
        nrdatu(1) = mu - 2
        nrdatv(1) = mv - 2
      else
        nu = nmaxu
        nv = nmaxv
        call interpolation_knots(u, mu, ipar(1), tu, nu)
        call interpolation_knots(v, mv, ipar(2), tv, nv)
      end if
    end if
  end if
  p = -1
  accepted = .false.
  do iter = 1, mu + mv
    if (nu == 8 .and. nv == 8) ier = -2
    nrintu = nu - 7
    nrintv = nv - 7
    call set_boundary(tu, nu, u(1), u(mu), ipar(1))
    call set_boundary(tv, nv, v(1), v(mv), ipar(2))
    call fpgrpa(ipar, idim, u, mu, v, mv, ff, tu, nu, tv, nv, p, c, fp, fpintu, fpintv, nru, nrv)
    if (ier == -2) fp0 = fp
    if (iopt < 0) return
    fpms = fp - s
    if (abs(fpms) < acc) return
    if (fpms < 0) then
      accepted = .true.
      exit
    end if
    if (nu == nmaxu .and. nv == nmaxv) then
      ier = -1
      fp = 0
      return
    end if
    ier = 1
    if (nu == nue .and. nv == nve) return
    ier = 0
    if (lastdi < 0) reducu = fpold - fp
    if (lastdi > 0) reducv = fpold - fp
    fpold = fp
    nplu = 1
    if (nu /= 8) nplu = fp_grid_knots_to_add(nplusu, reducu, fpms, acc)
    nplv = 1
    if (nv /= 8) nplv = fp_grid_knots_to_add(nplusv, reducv, fpms, acc)
    if (fp_grid_add_first(nplu, nplv, lastdi, nu == nue, nv == nve)) then
      lastdi = -1
      nplusu = nplu
      do l = 1, nplusu
        call fpknot(u, mu, tu, nu, fpintu, nrdatu, nrintu, nuest, 1)
        if (nu == nue) exit
      end do
    else
      lastdi = 1
      nplusv = nplv
      do l = 1, nplusv
        call fpknot(v, mv, tv, nv, fpintv, nrdatv, nrintv, nvest, 1)
        if (nv == nve) exit
      end do
    end if
  end do
  if (.not. accepted) return
  if (ier == -2) return
  p1 = 0
  f1 = fp0 - s
  p3 = -1
  f3 = fpms
  p = 1
  ich1 = 0
  ich3 = 0
  do iter = 1, maxit
    call fpgrpa(ipar, idim, u, mu, v, mv, ff, tu, nu, tv, nv, p, c, fp, fpintu, fpintv, nru, nrv)
    fpms = fp - s
    call fp_smoothing_step(fpms, acc, .false., iter, maxit, single_steps, p, p1, f1, p3, f3, ich1, ich3, step)
    if (step < 0) cycle
    if (step > 0) ier = step
    return
  end do
contains

  pure subroutine set_boundary(t, n, tb, te, per)
    integer, intent(in) :: n, per
    real(real64), intent(inout) :: t(*)
    real(real64), intent(in) :: tb, te
    integer :: j
    if (per == 0) then
      t(1:4) = tb
      t(n - 3:n) = te
    else
      t(4) = tb
      t(n - 3) = te
      do j = 1, 3
        t(4 - j) = t(n - 3 - j) - (te - tb)
        t(n - 3 + j) = t(4 + j) + (te - tb)
      end do
    end if
  end subroutine set_boundary

  !> s = 0: knots at the data (non-periodic: u(3..m-2); periodic: u(2..m-1)).
  pure subroutine interpolation_knots(x, m, per, t, n)
    integer, intent(in) :: m, per, n
    real(real64), intent(in) :: x(m)
    real(real64), intent(inout) :: t(*)
    if (per == 0) then
      t(5:n - 4) = x(3:m - 2)
    else
      t(5:n - 4) = x(2:m - 1)
    end if
  end subroutine interpolation_knots
end subroutine fppasu

!> fpgrpa: the (smoothing, p > 0) bicubic spline of parsur on the grid for the
!> current knots: per direction the observation matrix (periodic B-splines
!> wrapped onto the n-7 free coefficients) and, for p > 0, the third-derivative
!> jump rows scaled 1/p (fpdisc's scaling) are reduced by Givens rotations;
!> then C = Ru^-1 (Qu' F Qv) Rv^-T per coordinate. fp, fpintu, fpintv as in
!> fpgrre (a periodic direction counts its last grid line once, as the first).
subroutine fpgrpa(ipar, idim, u, mu, v, mv, f, tu, nu, tv, nv, p, c, fp, fpintu, fpintv, nru, nrv)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl, fpgivs, fprota, fpdisc
  implicit none (type, external)
  integer, intent(in) :: ipar(2), idim, mu, mv, nu, nv
  real(real64), intent(in) :: u(mu), v(mv), f(mu*mv*idim), tu(nu), tv(nv), p
  real(real64), intent(inout) :: c(*)
  real(real64), intent(out) :: fp
  real(real64), intent(inout) :: fpintu(nu), fpintv(nv)
  integer, intent(inout) :: nru(mu), nrv(mv)
  real(real64), allocatable :: spu(:, :), spv(:, :), ru(:, :), rv(:, :), h1(:, :), h2(:, :), rhs(:, :), cc(:, :, :)
  integer :: mmu, mmv, ncu, ncv, ncfu, ncfv, l, i, j, i1, j1, iz, numu, numv, nroldu, nroldv
  real(real64) :: term, fac, val
  mmu = mu - ipar(1)
  mmv = mv - ipar(2)
  ncu = nu - 4 - 3*ipar(1)
  ncv = nv - 4 - 3*ipar(2)
  ncfu = nu - 4
  ncfv = nv - 4
  allocate (spu(mu, 4), spv(mv, 4))
  call basis(tu, nu, u, mu, spu, nru)
  call basis(tv, nv, v, mv, spv, nrv)
  ! u direction: rhs(i, (l-1)*mmv + j) = f_l(u(i), v(j))
  allocate (rhs(mmu, mmv*idim))
  do l = 1, idim
    do i = 1, mmu
      do j = 1, mmv
        rhs(i, (l - 1)*mmv + j) = f(mu*mv*(l - 1) + mv*(i - 1) + j)
      end do
    end do
  end do
  allocate (ru(ncu, ncu), h1(ncu, mmv*idim))
  call reduce(tu, nu, ipar(1), mmu, ncu, spu, nru, rhs, ru, h1)
  deallocate (rhs)
  allocate (rhs(mmv, ncu*idim))
  do l = 1, idim
    do i = 1, ncu
      do j = 1, mmv
        rhs(j, (l - 1)*ncu + i) = h1(i, (l - 1)*mmv + j)
      end do
    end do
  end do
  allocate (rv(ncv, ncv), h2(ncv, ncu*idim))
  call reduce(tv, nv, ipar(2), mmv, ncv, spv, nrv, rhs, rv, h2)
  ! back substitution: Rv Y = H2, then Ru C_l = Y_l'
  call upper_solve(rv, ncv, h2, ncu*idim)
  deallocate (rhs)
  allocate (cc(ncu, ncv, idim), rhs(ncu, ncv))
  do l = 1, idim
    do i = 1, ncu
      do j = 1, ncv
        rhs(i, j) = h2(j, (l - 1)*ncu + i)
      end do
    end do
    call upper_solve(ru, ncu, rhs, ncv)
    cc(:, :, l) = rhs
  end do
  ! FITPACK layout with the periodic repeats
  do l = 1, idim
    do i = 1, ncfu
      i1 = modulo(i - 1, ncu) + 1
      do j = 1, ncfv
        j1 = modulo(j - 1, ncv) + 1
        c(ncfu*ncfv*(l - 1) + ncfv*(i - 1) + j) = cc(i1, j1, l)
      end do
    end do
  end do
  ! residuals
  fp = 0
  fpintu(1:nu) = 0
  fpintv(1:nv) = 0
  nroldu = 0
  do i = 1, mmu
    numu = nru(i)
    nroldv = 0
    do j = 1, mmv
      numv = nrv(j)
      term = 0
      do l = 1, idim
        val = 0
        do i1 = 1, 4
          do j1 = 1, 4
            val = val + spu(i, i1)*spv(j, j1)*c(ncfu*ncfv*(l - 1) + ncfv*(numu + i1 - 1) + numv + j1)
          end do
        end do
        iz = mu*mv*(l - 1) + mv*(i - 1) + j
        term = term + (f(iz) - val)**2
      end do
      fp = fp + term
      fpintu(numu + 1) = fpintu(numu + 1) + term
      fpintv(numv + 1) = fpintv(numv + 1) + term
      fac = term*0.5_real64
      if (numv /= nroldv) then
        fpintv(numv + 1) = fpintv(numv + 1) - fac
        fpintv(numv) = fpintv(numv) + fac
      end if
      nroldv = numv
      if (numu /= nroldu) then
        fpintu(numu + 1) = fpintu(numu + 1) - fac
        fpintu(numu) = fpintu(numu) + fac
      end if
    end do
    nroldu = numu
  end do
contains
  subroutine basis(t, n, x, m, sp, nr)
    integer, intent(in) :: n, m
    real(real64), intent(in) :: t(n), x(m)
    real(real64), intent(out) :: sp(m, 4)
    integer, intent(out) :: nr(m)
    integer :: ll, ii
    real(real64) :: hh(6)
    ll = 4
    do ii = 1, m
      do while (x(ii) >= t(ll + 1) .and. ll /= n - 4)
        ll = ll + 1
      end do
      call fpbspl(t, n, 3, x(ii), ll, hh)
      sp(ii, :) = hh(1:4)
      nr(ii) = ll - 4
    end do
  end subroutine basis

  !> Givens reduction of [A; B/p] (rows interleaved as in fpgrre) to R, the
  !> right-hand sides rhs (data rows) to q = Q' [rhs; 0] (first nc rows).
  subroutine reduce(t, n, per, m, nc, sp, nr, rhs, r, q)
    integer, intent(in) :: n, per, m, nc, nr(:)
    real(real64), intent(in) :: t(n), sp(:, :), rhs(:, :)
    real(real64), intent(out) :: r(nc, nc), q(:, :)
    real(real64), allocatable :: b(:, :), row(:), rr(:)
    integer :: it, nrold, number, nb, jj, kk, col
    allocate (row(nc), rr(size(rhs, 2)))
    r = 0
    q = 0
    nb = 0
    if (p > 0) call jump_rows(t, n, per, b, nb)
    nrold = 0
    if (per == 1 .and. nb > 0) then
      ! the seam row first: it precedes all data
      call jump_row_dense(b, 1, per, nc, row, rr)
      call rotate_in(nc, row, rr, r, q)
    end if
    do it = 1, m
      number = nr(it)
      do while (nrold < number)
        nrold = nrold + 1
        if (p > 0 .and. nrold + per <= nb) then
          call jump_row_dense(b, nrold + per, per, nc, row, rr)
          call rotate_in(nc, row, rr, r, q)
        end if
      end do
      row = 0
      do kk = 1, 4
        col = modulo(number + kk - 1, nc) + 1
        row(col) = row(col) + sp(it, kk)
      end do
      rr = rhs(it, :)
      call rotate_in(nc, row, rr, r, q)
    end do
    ! jump rows of knots after the last data interval (none for data ending on te)
    do jj = nrold + 1 + per, nb
      call jump_row_dense(b, jj, per, nc, row, rr)
      call rotate_in(nc, row, rr, r, q)
    end do
  end subroutine reduce

  !> Row ib of b as a dense row: jumps of B_{j0+1..j0+5}, wrapped for periodic.
  subroutine jump_row_dense(b, ib, per, nc, row, rr)
    real(real64), intent(in) :: b(:, :)
    integer, intent(in) :: ib, per, nc
    real(real64), intent(out) :: row(nc), rr(:)
    integer :: kk2, col2, j0
    row = 0
    rr = 0
    j0 = ib - 1 - per
    do kk2 = 1, 5
      col2 = modulo(j0 + kk2 - 1, nc) + 1
      row(col2) = row(col2) + b(ib, kk2)/p
    end do
  end subroutine jump_row_dense

  !> Rotates a dense row (right-hand sides rr) into the triangle r, q.
  subroutine rotate_in(nc, row, rr, r, q)
    integer, intent(in) :: nc
    real(real64), intent(inout) :: row(nc), rr(:), r(nc, nc), q(:, :)
    real(real64) :: cs, sn, piv
    integer :: i0, jc
    do i0 = 1, nc
      piv = row(i0)
      if (piv == 0) cycle
      call fpgivs(piv, r(i0, i0), cs, sn)
      do jc = 1, size(rr)
        call fprota(cs, sn, rr(jc), q(i0, jc))
      end do
      do jc = i0 + 1, nc
        call fprota(cs, sn, row(jc), r(i0, jc))
      end do
      row(i0) = 0
    end do
  end subroutine rotate_in

  !> b(ib, 1:5): jumps of the third derivative at knot ib of the B-splines
  !> B_{ib-per}..B_{ib+4-per}, scaled like fpdisc; non-periodic: fpdisc itself
  !> (knots t(5..n-4)); periodic: the seam t(4) first, then t(5..n-4).
  subroutine jump_rows(t, n, per, b, nb)
    integer, intent(in) :: n, per
    real(real64), intent(in) :: t(n)
    real(real64), allocatable, intent(out) :: b(:, :)
    integer, intent(out) :: nb
    real(real64) :: fac, prod, period
    integer :: ib, lk, jj, mm, nper
    if (per == 0) then
      nb = n - 8
      allocate (b(max(nb, 1), 5))
      if (nb > 0) call fpdisc(t, n, 5, b, max(nb, 1))
      return
    end if
    nper = n - 7
    nb = nper
    period = t(n - 3) - t(4)
    allocate (b(nb, 5))
    fac = real(nper, real64)/period
    do ib = 1, nb
      lk = ib + 3                  ! the knot t(lk), lk = 4..n-4
      do jj = 1, 5                 ! B-spline with knots t(lk-5+jj .. lk-1+jj)
        prod = 1
        do mm = lk - 5 + jj, lk - 1 + jj
          if (mm == lk) cycle
          prod = prod*(text(t, n, nper, period, lk) - text(t, n, nper, period, mm))
        end do
        prod = prod*fac**3
        b(ib, jj) = (text(t, n, nper, period, lk - 1 + jj) - text(t, n, nper, period, lk - 5 + jj))/prod
      end do
    end do
  end subroutine jump_rows

  !> Knot i of the periodically extended knot sequence.
  pure real(real64) function text(t, n, nper, period, i)
    integer, intent(in) :: n, nper, i
    real(real64), intent(in) :: t(n), period
    if (i < 1) then
      text = t(i + nper) - period
    else if (i > n) then
      text = t(i - nper) + period
    else
      text = t(i)
    end if
  end function text

  !> Solves R X = Y in place (R upper triangular, full storage).
  pure subroutine upper_solve(r, n, y, nrhs)
    integer, intent(in) :: n, nrhs
    real(real64), intent(in) :: r(n, n)
    real(real64), intent(inout) :: y(:, :)
    integer :: ii, jc
    do jc = 1, nrhs
      do ii = n, 1, -1
        y(ii, jc) = (y(ii, jc) - dot_product(r(ii, ii + 1:n), y(ii + 1:n, jc)))/r(ii, ii)
      end do
    end do
  end subroutine upper_solve
end subroutine fpgrpa
