!> surfit: smoothing (or least-squares) bivariate spline s(x,y) of degrees
!> kx, ky to scattered data (x(i), y(i), z(i)) with weights w(i) > 0 on the
!> rectangle [xb,xe] x [yb,ye]. Dierckx's calling sequence and meanings:
!>   iopt = -1 weighted least squares on the interior knots given in
!>          tx(kx+2..nx-kx-1), ty(ky+2..ny-ky-1); 0 smoothing from scratch;
!>          1 continue with the knots of the previous call (wrk1(1) = fp0).
!>   s >= 0 smoothing factor: fp = sum (w (z - s(x,y)))^2 <= s, accepted when
!>          |fp - s| <= 0.001 s.
!>   eps (0,1) rank threshold: a diagonal element of the triangularized system
!>          <= sqrt(eps) times the largest one makes the system rank deficient
!>          (the genuine routine's threshold, checked against it); the
!>          minimum-norm solution of the reduced system is returned (fprank).
!> The algorithm (fpsurf): data sorted into the panels of the knot grid (fporde);
!> x and y swapped while that narrows the band; banded Givens least squares;
!> while fp > s one knot is added per pass, in the knot interval (of x or y)
!> with the largest residual sum, at the residual-weighted mean coordinate,
!> unless that splits the interval more unevenly than 10:1; then p-iteration
!> with rows for the jumps of the kx-th (ky-th) derivative across the knots.
!> ier: 0 ok; -1 interpolating spline; -2 least-squares polynomial (fp0);
!> < -2 rank deficient, rank = -ier; 1 nxest/nyest too small; 2 s too small;
!> 3 maxit = 20 reached; 4 no more knots: more coefficients than data;
!> 5 no more knots: a new knot would split an interval worse than 10:1 or
!> coincide with an old one; 10 invalid input; > 10 lwrk2 too small (ier is
!> the size needed).
!> Workspace: nmax >= max(nxest, nyest); kwrk >= m+(nxest-2kx-1)(nyest-2ky-1);
!> lwrk1 >= u v (2+b1+b2) + 2 (u+v+km2 ne+km1 m) + b2 + 1 with u = nxest-kx-1,
!> v = nyest-ky-1, km1 = max(kx,ky)+1, km2 = km1+1, ne = max(nxest,nyest),
!> bx = kx v+ky+1, by = ky u+kx+1, b1 = min(bx,by), b2 = bx+v-ky if bx <= by
!> else by+u-kx (Dierckx's formula); lwrk2 >= u v (b2+1) + b2. The sizes are
!> checked as the original does (so ier = 10 and ier > 10 come out the same);
!> wrk1(1) keeps fp0 for iopt = 1, wrk2 is fprank's workspace, and the band
!> matrices and panel lists are allocated inside fpsurf.
subroutine surfit(iopt, m, x, y, z, w, xb, xe, yb, ye, kx, ky, s, nxest, nyest, nmax, eps, nx, tx, &
                  ny, ty, c, fp, wrk1, lwrk1, wrk2, lwrk2, iwrk, kwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_surface_interfaces, only: fpsurf
  implicit none (type, external)
  integer, intent(in) :: iopt, m, kx, ky, nxest, nyest, nmax, lwrk1, lwrk2, kwrk
  real(real64), intent(in) :: x(m), y(m), z(m), w(m), xb, xe, yb, ye, s, eps
  integer, intent(inout) :: nx, ny
  real(real64), intent(inout) :: tx(nmax), ty(nmax)
  real(real64), intent(inout) :: c((nxest - kx - 1)*(nyest - ky - 1))
  real(real64), intent(out) :: fp
  real(real64), intent(inout) :: wrk1(lwrk1), wrk2(lwrk2)
  integer, intent(inout) :: iwrk(kwrk)
  integer, intent(out) :: ier
  real(real64), parameter :: tol = 1.0e-3_real64
  integer, parameter :: maxit = 20
  integer :: kx1, ky1, kmax, km1, km2, nminx, nminy, nest, nxk, nyk, ncest, nmx, nmy, nrint, nreg, &
    ib1, jb1, ib3, lwest, kwest, i
  ier = 10
  fp = 0
  if (kwrk > 0) iwrk(1) = 0   ! kept in the calling sequence; the panel lists live inside fpsurf
  if (eps <= 0 .or. eps >= 1) return
  if (kx <= 0 .or. kx > 5) return
  kx1 = kx + 1
  if (ky <= 0 .or. ky > 5) return
  ky1 = ky + 1
  kmax = max(kx, ky)
  km1 = kmax + 1
  km2 = km1 + 1
  if (iopt < -1 .or. iopt > 1) return
  if (m < kx1*ky1) return
  nminx = 2*kx1
  if (nxest < nminx .or. nxest > nmax) return
  nminy = 2*ky1
  if (nyest < nminy .or. nyest > nmax) return
  nest = max(nxest, nyest)
  nxk = nxest - kx1
  nyk = nyest - ky1
  ncest = nxk*nyk
  nmx = nxest - nminx + 1
  nmy = nyest - nminy + 1
  nrint = nmx + nmy
  nreg = nmx*nmy
  ib1 = kx*nyk + ky1
  jb1 = ky*nxk + kx1
  ib3 = kx1*nyk + 1
  if (ib1 > jb1) then
    ib1 = jb1
    ib3 = ky1*nxk + 1
  end if
  lwest = ncest*(2 + ib1 + ib3) + 2*(nrint + nest*km2 + m*km1) + ib3
  kwest = m + nreg
  if (lwrk1 < lwest .or. kwrk < kwest) return
  if (xb >= xe .or. yb >= ye) return
  do i = 1, m
    if (w(i) <= 0) return
    if (x(i) < xb .or. x(i) > xe) return
    if (y(i) < yb .or. y(i) > ye) return
  end do
  if (iopt < 0) then
    if (nx < nminx .or. nx > nxest) return
    nxk = nx - kx1
    tx(kx1) = xb
    tx(nxk + 1) = xe
    do i = kx1, nxk
      if (tx(i + 1) <= tx(i)) return
    end do
    if (ny < nminy .or. ny > nyest) return
    nyk = ny - ky1
    ty(ky1) = yb
    ty(nyk + 1) = ye
    do i = ky1, nyk
      if (ty(i + 1) <= ty(i)) return
    end do
  else
    if (s < 0) return
  end if
  ier = 0
  call fpsurf(iopt, m, x, y, z, w, xb, xe, yb, ye, kx, ky, s, nxest, nyest, eps, tol, maxit, nmax, &
    nx, tx, ny, ty, c, fp, wrk1(1), wrk2, lwrk2, ier)
end subroutine surfit

!> fporde: sorts the data into the panels of the knot grid. Panel
!> num = (l-kx-1)*nyy + (k-ky) for tx(l) <= x < tx(l+1), ty(k) <= y < ty(k+1)
!> (the last interval closed), nyy = ny-2ky-1; index(num) is the last point of
!> the panel and nummer(i) the point before i in the same panel (0: none).
pure subroutine fporde(x, y, m, kx, ky, tx, nx, ty, ny, nummer, index, nreg)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: m, kx, ky, nx, ny, nreg
  real(real64), intent(in) :: x(m), y(m), tx(nx), ty(ny)
  integer, intent(out) :: nummer(m), index(nreg)
  integer :: im, l, k, nk1x, nk1y, nyy, num
  nk1x = nx - kx - 1
  nk1y = ny - ky - 1
  nyy = nk1y - ky
  index = 0
  do im = 1, m
    l = kx + 1
    do while (x(im) >= tx(l + 1) .and. l /= nk1x)
      l = l + 1
    end do
    k = ky + 1
    do while (y(im) >= ty(k + 1) .and. k /= nk1y)
      k = k + 1
    end do
    num = (l - kx - 1)*nyy + k - ky
    nummer(im) = index(num)
    index(num) = im
  end do
end subroutine fporde

!> fprank: minimum-norm solution c of the upper-triangular band system a c = f
!> (n unknowns, bandwidth m, leading dimension na) when diagonal elements
!> <= tol make it rank deficient. Each such row is dropped: the rest of the row
!> is first rotated into the rows below (which may lift their diagonal), its
!> right-hand side adds to sq. The remaining rank x n trapezoidal system B c = g
!> has the minimum-norm solution c = B' v with (R R') v = g, where B = R U,
!> R upper triangular, is obtained by rotating the columns of the dropped
!> unknowns into the kept triangle. sq also receives, per dropped row, the
!> change of its squared residual when its small diagonal is restored. a and
!> f are overwritten. Work: aa(n,m), ff(n), h(m).
pure subroutine fprank(a, f, n, m, na, tol, c, sq, rank, aa, ff, h)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpgivs, fprota
  implicit none (type, external)
  integer, intent(in) :: n, m, na
  real(real64), intent(inout) :: a(na, m), f(n)
  real(real64), intent(in) :: tol
  real(real64), intent(out) :: c(n), sq
  integer, intent(out) :: rank
  real(real64), intent(out) :: aa(n, m), ff(n), h(m)
  real(real64) :: yi, piv, cs, sn, store
  integer :: i, ii, i2, j, jj, kk, k, nl, m1, keep(n), pos(n)
  logical :: kept(n)
  m1 = m - 1
  nl = 0
  sq = 0
  do i = 1, n
    if (a(i, 1) > tol) cycle
    nl = nl + 1
    if (i == n) cycle
    yi = f(i)
    h(1:m1) = a(i, 2:m)
    h(m) = 0
    do ii = i + 1, n
      i2 = min(n - ii, m1)
      piv = h(1)
      if (piv /= 0) then
        call fpgivs(piv, a(ii, 1), cs, sn)
        call fprota(cs, sn, yi, f(ii))
        if (i2 == 0) exit
        do j = 1, i2
          call fprota(cs, sn, h(j + 1), a(ii, j + 1))
          h(j) = h(j + 1)
        end do
      else
        if (i2 == 0) exit
        h(1:i2) = h(2:i2 + 1)
      end if
      h(i2 + 1) = 0
    end do
    sq = sq + yi**2
  end do
  rank = n - nl
  ! kept rows/columns: keep(k) the original index of the k-th kept one,
  ! pos(i) the rank position of row i if kept (else of the last kept before i)
  kept = a(1:n, 1) > tol
  k = 0
  do i = 1, n
    if (kept(i)) then
      k = k + 1
      keep(k) = i
    end if
    pos(i) = k
  end do
  c = 0
  if (rank == 0) return
  ! aa: kept rows and kept columns of a, band storage (diagonal in column 1)
  aa(1:rank, :) = 0
  do kk = 1, rank
    i = keep(kk)
    ff(kk) = f(i)
    do j = 1, m
      if (i + j - 1 > n) exit
      if (.not. kept(i + j - 1)) cycle
      jj = pos(i + j - 1) - kk + 1
      if (jj <= m) aa(kk, jj) = a(i, j)
    end do
  end do
  ! rotate each dropped column (restricted to the kept rows) into aa so that
  ! R R' = B B'
  do i = 1, n
    if (kept(i)) cycle
    ii = pos(i)
    if (ii == 0) cycle
    ! h(1) belongs to kept row ii, h(2) to row ii-1, ...
    h = 0
    do kk = ii, max(1, ii - m + 1), -1
      j = i - keep(kk) + 1
      if (j <= m) h(ii - kk + 1) = a(keep(kk), j)
    end do
    jj = ii
    do while (jj >= 1)
      i2 = min(jj - 1, m1)
      piv = h(1)
      if (piv /= 0) then
        call fpgivs(piv, aa(jj, 1), cs, sn)
        ! column jj of aa holds aa(jj-l, l+1), l = 1..i2
        do j = 1, i2
          call fprota(cs, sn, h(j + 1), aa(jj - j, j + 1))
        end do
      end if
      if (i2 == 0) exit
      h(1:i2) = h(2:i2 + 1)
      h(i2 + 1:m) = 0
      jj = jj - 1
    end do
  end do
  ! R w = g (back), R' v = w (forward)
  do kk = rank, 1, -1
    store = ff(kk)
    do j = 2, min(m, rank - kk + 1)
      store = store - aa(kk, j)*ff(kk + j - 1)
    end do
    ff(kk) = store/aa(kk, 1)
  end do
  do kk = 1, rank
    store = ff(kk)
    do j = 2, min(m, kk)
      store = store - aa(kk - j + 1, j)*ff(kk - j + 1)
    end do
    ff(kk) = store/aa(kk, 1)
  end do
  ! c = B' v, each c(i) summed from row i upwards
  do i = 1, n
    store = 0
    do j = 1, min(i, m)
      ii = i + 1 - j
      if (.not. kept(ii)) cycle
      store = store + a(ii, j)*ff(pos(ii))
    end do
    c(i) = store
  end do
  ! a dropped row i reads d c(i) + sum_j a(i,j) c(i+j-1) = f(i) with its small
  ! diagonal d set to zero; restoring d changes the row's squared residual by
  ! d c(i) (d c(i) - 2 (f(i) - sum_j a(i,j) c(i+j-1))), which is added to sq
  ! (as the genuine routine does: checked against scipy 1.10.1's surfit)
  do i = 1, n
    if (kept(i)) cycle
    store = 0
    do j = 2, min(m, n - i + 1)
      store = store + a(i, j)*c(i + j - 1)
    end do
    yi = a(i, 1)*c(i)
    sq = sq + yi*(yi - 2*(f(i) - store))
  end do
end subroutine fprank
