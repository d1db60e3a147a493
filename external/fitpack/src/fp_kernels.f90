!> Low-level kernels of our FITPACK implementation (Dierckx's algorithms, written
!> for slidesim). Original names and calling sequences; every real is real64.
!> External subroutines (no module) so that the genuine netlib FITPACK, compiled
!> with -fdefault-real-8, can be linked instead. Explicit interfaces: module
!> fitpack_interfaces.
!>
!> Array arguments that the originals declare with a fixed small size (h(20))
!> are assumed-size here, so callers may pass any array long enough.

!> Values h(1..k+1) of the k+1 B-splines of degree k that do not vanish at x,
!> t(l) <= x < t(l+1), by the Cox-de Boor recurrence (thesis 2.3).
pure subroutine fpbspl(t, n, k, x, l, h)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: n, k, l
  real(real64), intent(in) :: t(n), x
  real(real64), intent(out) :: h(*)
  real(real64) :: hh(19), f
  integer :: i, j, li, lj
  h(1) = 1.0_real64
  do j = 1, k
    hh(1:j) = h(1:j)
    h(1) = 0.0_real64
    do i = 1, j
      li = l + i
      lj = li - j
      if (t(li) == t(lj)) then
        h(i + 1) = 0.0_real64
      else
        f = hh(i)/(t(li) - t(lj))
        h(i) = h(i) + f*(t(li) - x)
        h(i + 1) = f*(x - t(lj))
      end if
    end do
  end do
end subroutine fpbspl

!> Givens rotation that annihilates piv against ww: on return ww is the new
!> diagonal element sqrt(ww**2 + piv**2), computed without overflow.
pure subroutine fpgivs(piv, ww, cos, sin)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  real(real64), intent(in) :: piv
  real(real64), intent(inout) :: ww
  real(real64), intent(out) :: cos, sin
  real(real64) :: store, dd
  store = abs(piv)
  if (store >= ww) then
    dd = store*sqrt(1.0_real64 + (ww/piv)**2)
  else
    dd = ww*sqrt(1.0_real64 + (piv/ww)**2)
  end if
  cos = ww/dd
  sin = piv/dd
  ww = dd
end subroutine fpgivs

!> Applies the rotation (cos, sin) to the pair (a, b).
pure subroutine fprota(cos, sin, a, b)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  real(real64), intent(in) :: cos, sin
  real(real64), intent(inout) :: a, b
  real(real64) :: sa, sb
  sa = a
  sb = b
  b = cos*sb + sin*sa
  a = cos*sa - sin*sb
end subroutine fprota

!> Solves a c = z for an upper-triangular band matrix a of bandwidth k
!> (a(i,1) diagonal, a(i,j) the element in column i+j-1). z and c may be the
!> same array in the originals; pass distinct arrays through this interface.
pure subroutine fpback(a, z, n, k, c, nest)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: n, k, nest
  real(real64), intent(in) :: a(nest, k), z(n)
  real(real64), intent(out) :: c(n)
  real(real64) :: store
  integer :: i, j, l, m, i1
  c(n) = z(n)/a(n, 1)
  i = n - 1
  do j = 2, n
    store = z(i)
    i1 = k - 1
    if (j <= k - 1) i1 = j - 1
    m = i
    do l = 1, i1
      m = m + 1
      store = store - c(m)*a(i, l + 1)
    end do
    c(i) = store/a(i, 1)
    i = i - 1
  end do
end subroutine fpback

!> Solves g c = z for the periodic systems: g = [a1 a2] with a1 an upper band
!> (bandwidth k1 = k+1... as a1(nest,k1)) on the first n-k columns and a2 the
!> dense block of the last k columns. Order of back substitution as in
!> Dierckx: last k unknowns from a2's triangular bottom part, then the band.
pure subroutine fpbacp(a, b, z, n, k, c, k1, nest)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: n, k, k1, nest
  real(real64), intent(in) :: a(nest, k1), b(nest, k), z(n)
  real(real64), intent(out) :: c(n)
  real(real64) :: store
  integer :: i, i1, j, l, l0, l1, n2
  n2 = n - k
  l = n
  do i = 1, k
    store = z(l)
    j = k + 2 - i
    if (i /= 1) then
      l0 = l
      do l1 = j, k
        l0 = l0 + 1
        store = store - c(l0)*b(l, l1)
      end do
    end if
    c(l) = store/b(l, j - 1)
    l = l - 1
    if (l == 0) return
  end do
  do i = 1, n2
    store = z(i)
    l = n2
    do j = 1, k
      l = l + 1
      store = store - c(l)*b(i, j)
    end do
    c(i) = store
  end do
  i = n2
  c(i) = c(i)/a(i, 1)
  if (i == 1) return
  do j = 2, n2
    i = i - 1
    store = c(i)
    i1 = k
    if (j <= k) i1 = j - 1
    l = i
    do l0 = 1, i1
      l = l + 1
      store = store - c(l)*a(i, l0 + 1)
    end do
    c(i) = store/a(i, 1)
  end do
end subroutine fpbacp

!> Rational interpolation for the smoothing parameter: the function
!> r(p) = (u p + v)/(p + w) through (p1,f1), (p2,f2), (p3,f3) (p3 <= 0 stands
!> for p3 = infinity, r(inf) = f3); returns its root, and moves (p1,f1) or
!> (p3,f3) to (p2,f2) so that f1 > 0 > f3 brackets the root.
function fprati(p1, f1, p2, f2, p3, f3) result(p)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  real(real64), intent(inout) :: p1, f1, p3, f3
  real(real64), intent(in) :: p2, f2
  real(real64) :: p, h1, h2, h3
  if (p3 > 0.0_real64) then
    h1 = f1*(f2 - f3)
    h2 = f2*(f3 - f1)
    h3 = f3*(f1 - f2)
    p = -(p1*p2*h3 + p2*p3*h1 + p3*p1*h2)/(p1*h1 + p2*h2 + p3*h3)
  else
    ! u = f3; (u p1 + v) = f1 (p1 + w), (u p2 + v) = f2 (p2 + w): root -v/u
    p = (p1*(f1 - f3)*f2 - p2*(f2 - f3)*f1)/((f1 - f2)*f3)
  end if
  if (f2 < 0.0_real64) then
    p3 = p2
    f3 = f2
  else
    p1 = p2
    f1 = f2
  end if
end function fprati

!> Discontinuity jumps of the k-th derivative of the B-splines at the interior
!> knots t(k+2..n-k-1) (k2 = k+2), scaled by the mean knot distance to the
!> power k: b(l,j) is the jump of B_{l+j-1} at interior knot l.
pure subroutine fpdisc(t, n, k2, b, nest)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: n, k2, nest
  real(real64), intent(in) :: t(n)
  real(real64), intent(out) :: b(nest, k2)
  real(real64) :: an, fac, prod, h(12)
  integer :: i, ik, j, jk, k, k1, l, lj, lk, lmk, lp, nk1, nrint
  k1 = k2 - 1
  k = k1 - 1
  nk1 = n - k1
  nrint = nk1 - k
  an = nrint
  fac = an/(t(nk1 + 1) - t(k1))
  do l = k2, nk1
    lmk = l - k1
    do j = 1, k1
      ik = j + k1
      lj = l + j
      lk = lj - k2
      h(j) = t(l) - t(lk)
      h(ik) = t(l) - t(lj)
    end do
    lp = lmk
    do j = 1, k2
      jk = j
      prod = h(j)
      do i = 1, k
        jk = jk + 1
        prod = prod*h(jk)*fac
      end do
      lk = lp + k1
      b(lmk, j) = (t(lk) - t(lp))/prod
      lp = lp + 1
    end do
  end do
end subroutine fpdisc

!> Checks the knots t(1..n) of a degree-k spline against data x(1..m): knot
!> order, data inside [t(k+1), t(n-k)] and the Schoenberg-Whitney conditions.
!> ier = 0 if all hold, else 10.
pure subroutine fpchec(x, m, t, n, k, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: m, n, k
  real(real64), intent(in) :: x(m), t(n)
  integer, intent(out) :: ier
  integer :: i, j, k1, k2, l, nk1, nk2, nk3
  real(real64) :: tj, tl
  k1 = k + 1
  k2 = k1 + 1
  nk1 = n - k1
  nk2 = nk1 + 1
  ier = 10
  if (nk1 < k1 .or. nk1 > m) return
  j = n
  do i = 1, k
    if (t(i) > t(i + 1)) return
    if (t(j) < t(j - 1)) return
    j = j - 1
  end do
  do i = k2, nk2
    if (t(i) <= t(i - 1)) return
  end do
  if (x(1) < t(k1) .or. x(m) > t(nk2)) return
  if (x(1) >= t(k2) .or. x(m) <= t(nk1)) return
  i = 1
  l = k2
  nk3 = nk1 - 1
  if (nk3 >= 2) then
    do j = 2, nk3
      tj = t(j)
      l = l + 1
      tl = t(l)
      do
        i = i + 1
        if (i >= m) return
        if (x(i) > tj) exit
      end do
      if (x(i) >= tl) return
    end do
  end if
  ier = 0
end subroutine fpchec

!> Periodic counterpart of fpchec (knots of a periodic spline with period
!> t(n-k) - t(k+1)); ier = 0 or 10.
pure subroutine fpchep(x, m, t, n, k, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: m, n, k
  real(real64), intent(in) :: x(m), t(n)
  integer, intent(out) :: ier
  integer :: i, i1, i2, j, j1, k1, k2, l, l1, l2, last, m1, mm, nk1
  real(real64) :: per, tj, tl, xi
  k1 = k + 1
  k2 = k1 + 1
  nk1 = n - k1
  m1 = m - 1
  ier = 10
  if (nk1 < k1 .or. n > m + 2*k) return
  j = n
  do i = 1, k
    if (t(i) > t(i + 1)) return
    if (t(j) < t(j - 1)) return
    j = j - 1
  end do
  do i = k1, nk1
    if (t(i + 1) <= t(i)) return
  end do
  if (x(1) < t(k1) .or. x(m) > t(nk1 + 1)) return
  ! Schoenberg-Whitney for a periodic spline: some shift of the data satisfies it
  l1 = k1
  l2 = 1
  last = m
  scan: do l = 1, m
    xi = x(l)
    do while (xi >= t(l1 + 1) .and. l /= nk1)
      l1 = l1 + 1
      l2 = l2 + 1
      if (l2 > k1) then
        last = l
        exit scan
      end if
    end do
  end do scan
  l = last
  per = t(nk1 + 1) - t(k1)
  do i1 = 2, l
    i = i1 - 1
    mm = i + m1
    do j = k1, nk1
      tj = t(j)
      j1 = j + k1
      tl = t(j1)
      do
        i = i + 1
        if (i > mm) goto 100
        i2 = i - m1
        if (i2 <= 0) then
          xi = x(i)
        else
          xi = x(i2) + per
        end if
        if (xi > tj) exit
      end do
      if (xi >= tl) goto 100
    end do
    ier = 0
    return
100 continue
  end do
end subroutine fpchep

!> Adds one knot to t(1..n): in the knot interval with the largest residual sum
!> fpint among those holding data (nrdata > 0), at the data point in its middle.
!> istart is the index in x of the first point after the left boundary minus 1
!> offset convention of the originals (1 for curfit).
!> When no interval holding data has a positive residual sum (all of fp sits on
!> knots or in empty intervals), no knot can be placed: t, n and the counts are
!> left unchanged and the caller ends with ier = 2 (the original writes outside
!> its arrays there and returns a corrupt knot vector).
pure subroutine fpknot(x, m, t, n, fpint, nrdata, nrint, nest, istart)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: m, nest, istart
  real(real64), intent(in) :: x(m)
  real(real64), intent(inout) :: t(nest), fpint(nest)
  integer, intent(inout) :: n, nrdata(nest), nrint
  real(real64) :: fpmax, am, an
  integer :: ihalf, j, jbegin, jj, jk, jpoint, k, maxbeg, maxpt, next, nrx, number
  k = (n - nrint - 1)/2
  fpmax = 0.0_real64
  jbegin = istart
  number = 0
  maxpt = 0
  maxbeg = 0
  do j = 1, nrint
    jpoint = nrdata(j)
    if (fpmax < fpint(j) .and. jpoint /= 0) then
      fpmax = fpint(j)
      number = j
      maxpt = jpoint
      maxbeg = jbegin
    end if
    jbegin = jbegin + jpoint + 1
  end do
  if (number == 0) return
  ihalf = maxpt/2 + 1
  nrx = maxbeg + ihalf
  next = number + 1
  if (next <= nrint) then
    do j = next, nrint
      jj = next + nrint - j
      fpint(jj + 1) = fpint(jj)
      nrdata(jj + 1) = nrdata(jj)
      jk = jj + k
      t(jk + 1) = t(jk)
    end do
  end if
  nrdata(number) = ihalf - 1
  nrdata(next) = maxpt - ihalf
  am = maxpt
  an = nrdata(number)
  fpint(number) = fpmax*an/am
  an = nrdata(next)
  fpint(next) = fpmax*an/am
  jk = next + k
  t(jk) = x(nrx)
  n = n + 1
  nrint = nrint + 1
end subroutine fpknot
