!> fpsurf: knot placement and p-iteration of surfit (see there). Arguments as
!> surfit's; fp0 is kept in wrk1(1) between calls. x and y are never changed:
!> the swap of the coordinates works on internal copies.
subroutine fpsurf(iopt, m, x, y, z, w, xb, xe, yb, ye, kxx, kyy, s, nxest, nyest, eta, tol, maxit, &
                  nmax, nx0, tx, ny0, ty, c, fp, fp0, wrk, lwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl, fpgivs, fprota, fpback, fpdisc, fp_smoothing_step
  use fitpack_surface_interfaces, only: fporde, fprank
  implicit none (type, external)
  integer, intent(in) :: iopt, m, kxx, kyy, nxest, nyest, maxit, nmax, lwrk
  real(real64), intent(in) :: x(m), y(m), z(m), w(m), xb, xe, yb, ye, s, eta, tol
  integer, intent(inout) :: nx0, ny0
  real(real64), intent(inout) :: tx(nmax), ty(nmax), c(*)
  real(real64), intent(out) :: fp
  real(real64), intent(inout) :: fp0, wrk(lwrk)
  integer, intent(inout) :: ier
  ! The p-iteration's one-sided steps (fp_smoothing_step) use the single-precision values of 0.1,
  ! 0.9 and 0.04, as the genuine fpsurf of scipy's double-precision FITPACK does
  ! (default-real literals). Measured: with exact constants the smoothing
  ! reference cases differ by 2e-11..2e-10; with these they agree to 1e-13.
  logical, parameter :: single_steps = .true.
  real(real64), parameter :: ten = 10
  ! current orientation (swapped when ichang > 0)
  real(real64), allocatable :: u(:), v(:), tu(:), tv(:)
  real(real64), allocatable :: a(:, :), q(:, :), f(:), ff(:), spx(:, :), spy(:, :), bx(:, :), by(:, :), &
    fpint(:), coord(:), h(:), cc(:)
  integer, allocatable :: index(:), nummer(:)
  integer :: kx, ky, kx1, ky1, kx2, ky2, nx, ny, nxe, nye, nminx, nminy, ichang, iter, nxx, nyy, nrint, &
    nreg, ncof, nk1x, nk1y, iband, iband1, iband3, iband4, num, num1, lx, ly, l1, l2, jrot, in, i, j, &
    i1, j1, irot, l, rank, jxy, ich1, ich3, step, lwest, nc, ncmax, i2, ibb
  real(real64) :: x0, x1, y0, y1, acc, fpms, wi, zi, hxi, piv, cs, sn, dmax, sigma, sq, store, fpmax, &
    arg, fac1, fac2, p, p1, p3, f1, f3, pinv, rn, hx(6), hy(6)
  logical :: rankdef
  kx = kxx
  ky = kyy
  nx = nx0
  ny = ny0
  nxe = nxest
  nye = nyest
  x0 = xb
  x1 = xe
  y0 = yb
  y1 = ye
  allocate (u(m), v(m), tu(nmax), tv(nmax))
  u = x
  v = y
  tu = tx
  tv = ty
  ichang = -1
  ! the largest band and coefficient count over both orientations
  nc = (nxest - kxx - 1)*(nyest - kyy - 1)
  ncmax = nc
  allocate (a(ncmax, max(kxx*(nyest - kyy - 1) + kyy + 1, kyy*(nxest - kxx - 1) + kxx + 1) + 1), &
    q(ncmax, max((kxx + 1)*(nyest - kyy - 1), (kyy + 1)*(nxest - kxx - 1)) + 2), f(ncmax), ff(ncmax), &
    cc(ncmax), spx(m, 6), spy(m, 6), bx(nmax, 7), by(nmax, 7), fpint(2*nmax), coord(2*nmax), &
    h(max((kxx + 1)*(nyest - kyy - 1), (kyy + 1)*(nxest - kxx - 1)) + 2), &
    index((nxest - 2*kxx - 1)*(nyest - 2*kyy - 1)), &
    nummer(m))
  kx1 = kx + 1
  ky1 = ky + 1
  kx2 = kx1 + 1
  ky2 = ky1 + 1
  nminx = 2*kx1
  nminy = 2*ky1
  acc = 0
  fpms = 0
  nyy = 1
  nxx = 1
  nk1x = 0
  nk1y = 0
  ncof = 0
  rank = 0
  iband = 0
  p = 0
  if (iopt >= 0) then
    acc = tol*s
    if (iopt == 0 .or. fp0 <= s) then
      nx = nminx
      ny = nminy
      ier = -2
    end if
  end if
  ! part 1: knots
  do iter = 1, m
    l = nx
    do i = 1, kx1
      tu(i) = x0
      tu(l) = x1
      l = l - 1
    end do
    l = ny
    do i = 1, ky1
      tv(i) = y0
      tv(l) = y1
      l = l - 1
    end do
    ! swap x and y when that narrows the band
    iband1 = kx*(ny - ky1) + ky
    l = ky*(nx - kx1) + kx
    if (iband1 > l) then
      iband1 = l
      ichang = -ichang
      call swap_orientation()
    end if
    iband = iband1 + 1
    nxx = nx - 2*kx - 1
    nyy = ny - 2*ky - 1
    nrint = nxx + nyy
    nreg = nxx*nyy
    call fporde(u, v, m, kx, ky, tu, nx, tv, ny, nummer, index, nreg)
    nk1x = nx - kx1
    nk1y = ny - ky1
    ncof = nk1x*nk1y
    f(1:ncof) = 0
    a(1:ncof, 1:iband) = 0
    fp = 0
    do num = 1, nreg
      num1 = num - 1
      lx = num1/nyy
      l1 = lx + kx1
      ly = num1 - lx*nyy
      l2 = ly + ky1
      jrot = lx*nk1y + ly
      in = index(num)
      do while (in /= 0)
        wi = w(in)
        zi = z(in)*wi
        call fpbspl(tu, nx, kx, u(in), l1, hx)
        call fpbspl(tv, ny, ky, v(in), l2, hy)
        spx(in, 1:kx1) = hx(1:kx1)
        spy(in, 1:ky1) = hy(1:ky1)
        h(1:iband) = 0
        i1 = 0
        do i = 1, kx1
          hxi = hx(i)
          j1 = i1
          do j = 1, ky1
            j1 = j1 + 1
            h(j1) = hxi*hy(j)*wi
          end do
          i1 = i1 + nk1y
        end do
        irot = jrot
        do i = 1, iband
          irot = irot + 1
          piv = h(i)
          if (piv == 0) cycle
          call fpgivs(piv, a(irot, 1), cs, sn)
          call fprota(cs, sn, zi, f(irot))
          if (i == iband) exit
          i2 = 1
          do j = i + 1, iband
            i2 = i2 + 1
            call fprota(cs, sn, h(j), a(irot, i2))
          end do
        end do
        fp = fp + zi**2
        in = nummer(in)
      end do
    end do
    dmax = maxval(a(1:ncof, 1))
    dmax = max(dmax, 0.0_real64)
    sigma = sqrt(eta)*dmax
    rankdef = any(a(1:ncof, 1) <= sigma)
    if (.not. rankdef) then
      call fpback(a, f, ncof, iband, cc, ncmax)
      rank = ncof
    else
      lwest = ncof*iband + ncof + iband
      if (lwrk < lwest) then
        ier = lwest
        exit
      end if
      q(1:ncof, 1:iband) = a(1:ncof, 1:iband)
      ff(1:ncof) = f(1:ncof)
      call fprank(q, ff, ncof, iband, ncmax, sigma, cc, sq, rank, wrk(ncof + iband + 1), wrk(1), &
        wrk(ncof + 1))
      fp = fp + sq
    end if
    if (ier == -2) fp0 = fp
    if (iopt < 0) then
      call finish(.true.)
      return
    end if
    fpms = fp - s
    if (abs(fpms) <= acc) then
      if (fp <= 0) then
        ier = -1
        fp = 0
      end if
      call finish(.true.)
      return
    end if
    if (fpms < 0) exit
    if (ncof > m) then
      ier = 4
      call finish(.false.)
      return
    end if
    ier = 0
    ! residual sums (and residual-weighted coordinates) per knot interval:
    ! x intervals 1..nxx, then y intervals nxx+1..nrint
    fpint(1:nrint) = 0
    coord(1:nrint) = 0
    do num = 1, nreg
      num1 = num - 1
      lx = num1/nyy
      l1 = lx + 1
      ly = num1 - lx*nyy
      l2 = ly + 1 + nxx
      jrot = lx*nk1y + ly
      in = index(num)
      do while (in /= 0)
        store = (w(in)*(z(in) - value_at(in, jrot)))**2
        fpint(l1) = fpint(l1) + store
        coord(l1) = coord(l1) + store*u(in)
        fpint(l2) = fpint(l2) + store
        coord(l2) = coord(l2) + store*v(in)
        in = nummer(in)
      end do
    end do
    ! the interval with the largest sum where a knot may still go
    do
      l = 0
      fpmax = 0
      l1 = 1
      l2 = nrint
      if (nx == nxe) l1 = nxx + 1
      if (ny == nye) l2 = nxx
      if (l1 > l2) then
        ier = 1
        call finish(.false.)
        return
      end if
      do i = l1, l2
        if (fpmax >= fpint(i)) cycle
        l = i
        fpmax = fpint(i)
      end do
      if (l == 0) then
        ier = 5
        call finish(.false.)
        return
      end if
      arg = coord(l)/fpint(l)
      fpint(l) = 0
      if (l <= nxx) then
        jxy = l + kx1
        fac1 = tu(jxy) - arg
        fac2 = arg - tu(jxy - 1)
        if (fac1 > ten*fac2 .or. fac2 > ten*fac1) cycle
        do j = nx, jxy, -1
          tu(j + 1) = tu(j)
        end do
        tu(jxy) = arg
        nx = nx + 1
      else
        jxy = l + ky1 - nxx
        fac1 = tv(jxy) - arg
        fac2 = arg - tv(jxy - 1)
        if (fac1 > ten*fac2 .or. fac2 > ten*fac1) cycle
        do j = ny, jxy, -1
          tv(j + 1) = tv(j)
        end do
        tv(jxy) = arg
        ny = ny + 1
      end if
      exit
    end do
  end do
  if (ier > 10) then
    call finish(.false.)
    return
  end if
  if (ier == -2) then
    call finish(.false.)
    return
  end if
  ! part 2: smoothing spline, p with fp(p) = s
  if (nx > nminx) call fpdisc(tu, nx, kx2, bx, nmax)
  if (ny > nminy) call fpdisc(tv, ny, ky2, by, nmax)
  p1 = 0
  f1 = fp0 - s
  p3 = -1
  f3 = fpms
  p = 0
  do i = 1, ncof
    p = p + a(i, 1)
  end do
  rn = ncof
  p = rn/p
  iband3 = kx1*nk1y
  iband4 = iband3 + 1
  ich1 = 0
  ich3 = 0
  do iter = 1, maxit
    pinv = 1/p
    ff(1:ncof) = f(1:ncof)
    q(1:ncof, 1:iband) = a(1:ncof, 1:iband)
    ibb = iband + 1
    q(1:ncof, ibb:iband4) = 0
    if (ny > nminy) then
      ! rows: for x = const the spline is a polynomial of degree ky in y
      do i = ky2, nk1y
        l = i - ky1
        do j = 1, nk1x
          h(1:iband4) = 0
          h(1:ky2) = by(l, 1:ky2)*pinv
          jrot = (j - 1)*nk1y + l
          call rotate_row(jrot, iband - 1)
        end do
      end do
    end if
    if (nx > nminx) then
      ! rows: for y = const the spline is a polynomial of degree kx in x
      do i = kx2, nk1x
        l = i - kx1
        do j = 1, nk1y
          h(1:iband4) = 0
          j1 = 1
          do l1 = 1, kx2
            h(j1) = bx(l, l1)*pinv
            j1 = j1 + nk1y
          end do
          jrot = (i - kx2)*nk1y + j
          call rotate_row(jrot, iband3)
        end do
      end do
    end if
    dmax = max(maxval(q(1:ncof, 1)), 0.0_real64)
    sigma = sqrt(eta)*dmax
    if (.not. any(q(1:ncof, 1) <= sigma)) then
      call fpback(q, ff, ncof, iband4, cc, ncmax)
      rank = ncof
    else
      lwest = ncof*iband4 + ncof + iband4
      if (lwrk < lwest) then
        ier = lwest
        call finish(.false.)
        return
      end if
      call fprank(q, ff, ncof, iband4, ncmax, sigma, cc, sq, rank, wrk(ncof + iband4 + 1), wrk(1), &
        wrk(ncof + 1))
    end if
    fp = 0
    do num = 1, nreg
      num1 = num - 1
      lx = num1/nyy
      ly = num1 - lx*nyy
      jrot = lx*nk1y + ly
      in = index(num)
      do while (in /= 0)
        fp = fp + (w(in)*(z(in) - value_at(in, jrot)))**2
        in = nummer(in)
      end do
    end do
    fpms = fp - s
    call fp_smoothing_step(fpms, acc, .true., iter, maxit, single_steps, p, p1, f1, p3, f3, ich1, ich3, step)
    if (step < 0) cycle
    if (step > 0) ier = step
    call finish(step == 0)
    return
  end do
contains
  real(real64) function value_at(ip, jr)
    integer, intent(in) :: ip, jr
    integer :: ii, jj, k1, k2
    value_at = 0
    k1 = jr
    do ii = 1, kx1
      hxi = spx(ip, ii)
      k2 = k1
      do jj = 1, ky1
        k2 = k2 + 1
        value_at = value_at + hxi*spy(ip, jj)*cc(k2)
      end do
      k1 = k1 + nk1y
    end do
  end function value_at

  !> Rotates the row h (first nonzero in column jr, zero right-hand side) into
  !> the extended triangle q, ff; the row's span is at most imax+1 columns.
  subroutine rotate_row(jr, imax)
    integer, intent(in) :: jr, imax
    integer :: ir, k, ni
    zi = 0
    do ir = jr, ncof
      piv = h(1)
      ni = min(imax, ncof - ir)
      if (piv /= 0) then
        call fpgivs(piv, q(ir, 1), cs, sn)
        call fprota(cs, sn, zi, ff(ir))
        if (ni == 0) return
        do k = 1, ni
          call fprota(cs, sn, h(k + 1), q(ir, k + 1))
        end do
      else
        if (ni <= 0) return
      end if
      do k = 1, ni
        h(k) = h(k + 1)
      end do
      h(ni + 1) = 0
    end do
  end subroutine rotate_row

  subroutine swap_orientation()
    real(real64), allocatable :: tmp(:)
    real(real64) :: st
    integer :: it
    allocate (tmp(m))
    tmp = u
    u = v
    v = tmp
    st = x0; x0 = y0; y0 = st
    st = x1; x1 = y1; y1 = st
    deallocate (tmp)
    allocate (tmp(nmax))
    tmp = tu
    tu = tv
    tv = tmp
    it = nx; nx = ny; ny = it
    it = nxe; nxe = nye; nye = it
    it = kx; kx = ky; ky = it
    kx1 = kx + 1
    ky1 = ky + 1
    kx2 = kx1 + 1
    ky2 = ky1 + 1
    nminx = 2*kx1
    nminy = 2*ky1
  end subroutine swap_orientation

  !> Copies the result back in the caller's orientation (coefficients
  !> transposed when x and y were swapped); check_rank: report a
  !> rank-deficient accepted solution as ier = -rank.
  subroutine finish(check_rank)
    logical, intent(in) :: check_rank
    integer :: ii, jj
    if (check_rank .and. ncof /= rank) ier = -rank
    if (ichang > 0) then
      do ii = 1, nk1x
        do jj = 1, nk1y
          c((jj - 1)*nk1x + ii) = cc((ii - 1)*nk1y + jj)
        end do
      end do
      nx0 = ny
      ny0 = nx
      tx(1:ny) = tv(1:ny)
      ty(1:nx) = tu(1:nx)
    else
      c(1:ncof) = cc(1:ncof)
      nx0 = nx
      ny0 = ny
      tx(1:nx) = tu(1:nx)
      ty(1:ny) = tv(1:ny)
    end if
  end subroutine finish
end subroutine fpsurf
