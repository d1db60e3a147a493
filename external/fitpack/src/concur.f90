!> concur: smoothing spline curve of odd degree k (1, 3, 5) in idim dimensions
!> with end-derivative constraints (Dierckx's calling sequence, reals real64;
!> thesis 2.54-2.67). The derivatives 0..ib-1 at u(1) are db(idim*l+j), the
!> derivatives 0..ie-1 at u(m) are de(idim*l+j); 0 <= ib, ie <= (k+1)/2.
!>
!> The curve is split as r(u) = p(u) + rh(u) (thesis 2.57): p is the degree-k
!> polynomial (B-spline coefficients cp on the knots u(1)^(k+1) u(m)^(k+1))
!> that meets the constraints (fppocu), rh fits the remainders xx = x - p(u)
!> (thesis 2.60) with its first ib and last ie coefficients held at zero
!> (thesis 2.64; fpcons). Finally the knots of rh are inserted into p and the
!> coefficients are added (thesis 2.66-2.67; fpadpo).
!> Workspace: lwrk >= m*(k+1) + nest*(6+idim+3*k); np >= 2*(k+1)*idim;
!> s = 0 needs nest >= m+k+1+max(0,ib-1)+max(0,ie-1). With iopt = 1, xx and cp
!> of the previous call are reused.
subroutine concur(iopt, idim, m, u, mx, x, xx, w, ib, db, nb, ie, de, ne, k, s, nest, n, t, &
                  nc, c, np, cp, fp, wrk, lwrk, iwrk, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: curev
  implicit none (type, external)
  integer, intent(in) :: iopt, idim, m, mx, ib, nb, ie, ne, k, nest, nc, np, lwrk
  real(real64), intent(in) :: u(m), x(mx), w(m), db(nb), de(ne), s
  real(real64), intent(inout) :: xx(mx)
  integer, intent(inout) :: n, iwrk(nest)
  real(real64), intent(inout) :: t(nest), c(nc), cp(np), fp, wrk(lwrk)
  integer, intent(out) :: ier
  external :: fpcons, fppocu, fpadpo, fpched
  real(real64), parameter :: tol = 0.001_real64
  integer, parameter :: maxit = 20
  integer :: i, j, k1, k2, kk, nmin, ib1, ie1, mmin, mxx, ncc, lwest, nmax, ifp, iz, ia, ibb, ig, iq

  ier = 10
  if (iopt < -1 .or. iopt > 1) return
  if (idim <= 0 .or. idim > 10) return
  if (k /= 1 .and. k /= 3 .and. k /= 5) return
  k1 = k + 1
  kk = k1/2
  k2 = k1 + 1
  if (ib < 0 .or. ib > kk) return
  if (ie < 0 .or. ie > kk) return
  nmin = 2*k1
  ib1 = max(0, ib - 1)
  ie1 = max(0, ie - 1)
  mmin = k1 - ib1 - ie1
  if (m < mmin .or. nest < nmin) return
  if (nb < ib*idim .or. ne < ie*idim) return
  if (np < 2*k1*idim) return
  mxx = m*idim
  ncc = nest*idim
  if (mx < mxx .or. nc < ncc) return
  lwest = m*k1 + nest*(6 + idim + 3*k)
  if (lwrk < lwest) return
  if (w(1) <= 0) return
  do i = 2, m
    if (u(i - 1) >= u(i) .or. w(i) <= 0) return
  end do
  if (iopt < 0) then
    if (n < nmin .or. n > nest) return
    j = n
    do i = 1, k1
      t(i) = u(1)
      t(j) = u(m)
      j = j - 1
    end do
    call fpched(u, m, t, n, k, ib, ie, ier)
    if (ier /= 0) return
  else
    if (s < 0) return
    nmax = m + k1 + ib1 + ie1
    if (s == 0 .and. nest < nmax) return
    ier = 0
  end if
  if (iopt <= 0) then
    ! the polynomial curve meeting the constraints, and the remainders xx
    call fppocu(idim, k, u(1), u(m), ib, db, nb, ie, de, ne, cp, np)
    j = nmin
    do i = 1, k1
      wrk(i) = u(1)
      wrk(j) = u(m)
      j = j - 1
    end do
    call curev(idim, wrk, nmin, cp, np, k, u, m, xx, mxx, ier)
    do i = 1, mxx
      xx(i) = x(i) - xx(i)
    end do
    ier = 0
  end if
  ifp = 1
  iz = ifp + nest
  ia = iz + ncc
  ibb = ia + nest*k1
  ig = ibb + nest*k2
  iq = ig + nest*k2
  call fpcons(iopt, idim, m, u, mxx, xx, w, ib, ie, k, s, nest, tol, maxit, k1, k2, n, t, ncc, c, fp, &
              wrk(ifp), wrk(iz), wrk(ia), wrk(ibb), wrk(ig), wrk(iq), iwrk, ier)
  if (ier <= 3) call fpadpo(idim, t, n, c, ncc, k, cp, np, wrk(iz), wrk(ia), wrk(ibb))
end subroutine concur

!> Dierckx's fpcons: the concur engine (fpcurve_core with ib, ie zero coefficients).
!> The p-iteration steps use the single-precision constants like its sibling
!> fppara (parcur), so that concur without constraints is parcur; scipy does not
!> wrap concur, so this cannot be measured against the genuine fpcons.
subroutine fpcons(iopt, idim, m, u, mx, x, w, ib, ie, k, s, nest, tol, maxit, k1, k2, n, t, nc, c, fp, &
                  fpint, z, a, b, g, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: iopt, idim, m, mx, ib, ie, k, nest, maxit, k1, k2, nc
  real(real64), intent(in) :: u(m), x(mx), w(m), s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nc), fp, fpint(nest), z(nc)
  real(real64), intent(inout) :: a(nest, k1), b(nest, k2), g(nest, k2), q(m, k1)
  external :: fpcurve_core
  call fpcurve_core(iopt, idim, m, u, mx, x, w, u(1), u(m), ib, ie, k, s, nest, tol, maxit, .true., k1, k2, n, t, &
                    nc, c, fp, fpint, z, a, b, g, q, nrdata, ier)
end subroutine fpcons

!> B-spline coefficients cp(2*(k+1)*(j-1)+i), i = 1..k+1, on the knots
!> a^(k+1) b^(k+1) of the degree-k polynomial curve whose derivatives
!> 0..ib-1 at a are db and 0..ie-1 at b are de; the other coefficients are 0.
!> The l-th derivative at a involves the first l+1 coefficients only:
!> p^(l)(a) = k!/(k-l)!/(b-a)**l * sum_i (-1)**(l-i) binom(l,i) cp(i+1).
subroutine fppocu(idim, k, a, b, ib, db, nb, ie, de, ne, cp, np)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: idim, k, ib, nb, ie, ne, np
  real(real64), intent(in) :: a, b, db(nb), de(ne)
  real(real64), intent(out) :: cp(np)
  real(real64) :: work(6), fac, ab, binom, sgn, rhs
  integer :: j, l, i, k1, k2, off
  k1 = k + 1
  k2 = 2*k1
  ab = b - a
  cp = 0
  do j = 1, idim
    off = k2*(j - 1)
    work(1:k1) = 0
    fac = 1
    do l = 0, ib - 1
      ! fac = (b-a)**l (k-l)!/k!
      if (l > 0) fac = fac*ab/real(k - l + 1, real64)
      work(l + 1) = db(idim*l + j)*fac
      binom = 1
      sgn = -1
      do i = l - 1, 0, -1
        binom = binom*real(i + 1, real64)/real(l - i, real64)
        work(l + 1) = work(l + 1) - sgn*binom*work(i + 1)
        sgn = -sgn
      end do
    end do
    fac = 1
    do l = 0, ie - 1
      if (l > 0) fac = fac*ab/real(k - l + 1, real64)
      ! p^(l)(b) = k!/(k-l)!/(b-a)**l * sum_i (-1)**i binom(l,i) cp(k1-i)
      rhs = de(idim*l + j)*fac
      binom = 1
      do i = 0, l - 1
        if (i > 0) binom = binom*real(l - i + 1, real64)/real(i, real64)
        rhs = rhs - (-1)**i*binom*work(k1 - i)
      end do
      work(k1 - l) = (-1)**l*rhs
    end do
    cp(off + 1:off + k1) = work(1:k1)
  end do
end subroutine fppocu

!> Adds the polynomial curve (knots t(1)^(k+1) t(n)^(k+1), coefficients cp) to
!> the spline curve (t, n, c): the interior knots are inserted into the
!> polynomial one by one (fpinst), then the coefficients are summed.
!> cc(nc), t1(n), t2(n) are work arrays.
subroutine fpadpo(idim, t, n, c, nc, k, cp, np, cc, t1, t2)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpinst
  implicit none (type, external)
  integer, intent(in) :: idim, n, nc, k, np
  real(real64), intent(in) :: t(n), cp(np)
  real(real64), intent(inout) :: c(nc), cc(nc), t1(n), t2(n)
  real(real64), allocatable :: c1(:), c2(:)   ! heap: n can be large
  integer :: j, k1, k2, nn, nn2, l, ll, nk1
  k1 = k + 1
  k2 = 2*k1
  nk1 = n - k1
  allocate (c1(n), c2(n))
  do j = 1, idim
    t1(1:k1) = t(1)
    t1(k1 + 1:k2) = t(n)
    c1 = 0
    c1(1:k1) = cp(k2*(j - 1) + 1:k2*(j - 1) + k1)
    nn = k2
    do l = k1 + 1, nk1
      ll = k1
      do while (t(l) >= t1(ll + 1) .and. ll < nn - k1)
        ll = ll + 1
      end do
      call fpinst(0, t1, nn, c1, k, t(l), ll, t2, nn2, c2, n)
      nn = nn2
      t1(1:nn) = t2(1:nn)
      c1(1:nn - k1) = c2(1:nn - k1)
    end do
    cc(n*(j - 1) + 1:n*(j - 1) + nk1) = c1(1:nk1)
    c(n*(j - 1) + 1:n*(j - 1) + nk1) = c(n*(j - 1) + 1:n*(j - 1) + nk1) + cc(n*(j - 1) + 1:n*(j - 1) + nk1)
  end do
end subroutine fpadpo

!> Knot check for concur with ib, ie coefficients fixed at each end: knot
!> order, data inside [t(k+1), t(n-k)], and Schoenberg-Whitney for the free
!> B-splines ib+1 .. n-k-1-ie (each must see its own data point, in order).
subroutine fpched(x, m, t, n, k, ib, ie, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  integer, intent(in) :: m, n, k, ib, ie
  real(real64), intent(in) :: x(m), t(n)
  integer, intent(out) :: ier
  integer :: i, j, k1, nk1, ib1, ie1
  logical :: inside
  k1 = k + 1
  nk1 = n - k1
  ib1 = max(0, ib - 1)
  ie1 = max(0, ie - 1)
  ier = 10
  if (nk1 < k1 .or. nk1 > m + ib1 + ie1) return
  do i = 1, k
    if (t(i) > t(i + 1)) return
    if (t(n - i + 1) < t(n - i)) return
  end do
  do i = k1 + 1, nk1 + 1
    if (t(i) <= t(i - 1)) return
  end do
  if (x(1) < t(k1) .or. x(m) > t(nk1 + 1)) return
  i = 0
  do j = ib + 1, nk1 - ie
    do
      i = i + 1
      if (i > m) return
      inside = t(j) < x(i) .and. x(i) < t(j + k1)
      if (j == 1 .and. x(i) == t(1)) inside = .true.
      if (j == nk1 .and. x(i) == t(n)) inside = .true.
      if (inside) exit
      if (x(i) >= t(j + k1)) return
    end do
  end do
  ier = 0
end subroutine fpched
