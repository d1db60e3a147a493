!> Common engine of percur and clocur (Dierckx's fpperi and fpclos): a periodic
!> smoothing spline curve of degree k in idim dimensions, period
!> per = u(m) - u(1); only the first m-1 data points are used (u(m) is u(1)
!> shifted by the period).
!>
!> Periodic B-spline representation: t(k+1) = u(1), t(n-k) = u(m), the outer
!> knots repeat the inner spacing shifted by the period, and the n7 = n-2k-1
!> free coefficients repeat: c(n7+j) = c(j), j = 1..k. Rows of the observation
!> matrix wrap around, so the triangular factor is a band (columns 1..n10)
!> bordered by a dense block of the last nb columns (LSQ: nb = k, band width
!> k+1; smoothing: nb = k+1, band width k+2).
!>
!> Knots for s > 0: the least-squares constant first (ier = -2 if good enough),
!> then one interior knot at the middle data point, then knots added as in
!> curfit (fpknot); at m+2k knots the interpolation knots. Then p-iteration.
!> Work arrays: fpint(nest), z(nc), a1(nest,k1), a2(nest,k), b(nest,k2),
!> g1(nest,k2), g2(nest,k1), q(m,k1), nrdata(nest).
subroutine fpperiodic_core(iopt, idim, m, u, mx, x, w, k, s, nest, tol, maxit, k1, k2, n, t, nc, c, &
                           fp, fpint, z, a1, a2, b, g1, g2, q, nrdata, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpbspl, fpgivs, fprota, fpbacp, fpdisc, fpknot, fp_smoothing_step
  implicit none (type, external)
  integer, intent(in) :: iopt, idim, m, mx, k, nest, maxit, k1, k2, nc
  real(real64), intent(in) :: u(m), x(mx), w(m), s, tol
  integer, intent(inout) :: n, nrdata(nest), ier
  real(real64), intent(inout) :: t(nest), c(nc), fp, fpint(nest), z(nc)
  real(real64), intent(inout) :: a1(nest, k1), a2(nest, k), b(nest, k2), g1(nest, k2), g2(nest, k1), &
                                 q(m, k1)

  ! The p-iteration's one-sided steps (fp_smoothing_step: p*con4, p/con4, the con1/con9 mixes) use
  ! the single-precision values of 0.1, 0.9 and 0.04, as the genuine fpperi and
  ! fpclos of scipy's double-precision FITPACK do (they assign them from
  ! default-real literals). Measured: with exact constants clocur closed_maxit_a/b
  ! (ier = 3) end 6e-8..4e-7 from the genuine fp and percur's smoothing cases
  ! 1e-12..7e-11; with these every case agrees to rounding (1e-13).
  real(real64), parameter :: half = 0.5_real64
  logical, parameter :: single_steps = .true.
  real(real64) :: h(7), h1(8), h2(8), xi(10), c1(10)
  real(real64), allocatable :: rhs(:, :), sol(:)   ! heap: nest can be large
  real(real64) :: acc, per, fp0, fpold, fpms, fpart, term, store, rn, p, p1, p3, f1, f3, &
                  pinv, piv, cs, sn, ui, wi, d1
  integer :: nold, m1, nmin, nmax, nk1, n7, n10, n11, n8, nrint, nplus, npl1, iter, it, i, j, l, l5, &
             d, ich1, ich3, step, lp, mm, new, jper, cf
  logical :: restart, interpolate_now

  m1 = m - 1
  nmin = 2*k1
  allocate (sol(nest))
  per = u(m) - u(1)
  fp0 = 0
  fpold = 0
  nplus = 0
  acc = 0
  fpms = 0
  nmax = n

  if (iopt >= 0) then
    acc = tol*s
    nmax = m + 2*k
    if (s > 0 .or. nmax == nmin) then
      restart = iopt == 0 .or. n == nmin
      if (.not. restart) then
        fp0 = fpint(n)
        fpold = fpint(n - 1)
        nplus = nrdata(n)
        restart = fp0 <= s
      end if
      if (restart) then
        ! the least-squares constant curve, and fp0
        fp0 = 0
        d1 = 0
        c1(1:idim) = 0
        do it = 1, m1
          wi = w(it)
          do d = 1, idim
            xi(d) = x(idim*(it - 1) + d)*wi
          end do
          call fpgivs(wi, d1, cs, sn)
          do d = 1, idim
            call fprota(cs, sn, xi(d), c1(d))
            fp0 = fp0 + xi(d)**2
          end do
        end do
        c1(1:idim) = c1(1:idim)/d1
        fpms = fp0 - s
        if (fpms < acc .or. nmax == nmin) then
          call constant_spline()
          return
        end if
        fpold = fp0
        if (nmin >= nest) then
          ier = 1
          return
        end if
        ! one interior knot at the middle data point
        nplus = 1
        n = nmin + 1
        mm = (m + 1)/2
        t(k2) = u(mm)
        nrdata(1) = mm - 2
        nrdata(2) = m1 - mm
      end if
    else
      n = nmax
      if (n > nest) then
        ier = 1
        return
      end if
      if (k == 1) then
        ! periodic linear interpolation: the data are the coefficients
        t(1) = u(m - 1) - per
        t(2) = u(1)
        do i = 2, m1
          t(i + 1) = u(i)
        end do
        t(m + 1) = u(m)
        t(m + 2) = u(2) + per
        do d = 1, idim
          do i = 1, m1
            c(n*(d - 1) + i) = x(idim*(i - 1) + d)
          end do
          c(n*(d - 1) + m) = c(n*(d - 1) + 1)
        end do
        fp = 0
        fpint(n) = fp0
        fpint(n - 1) = 0
        nrdata(n) = 0
        ier = -1
        return
      end if
      call interpolation_knots()
    end if
  end if

  iter = 0
  knots: do while (iter < m)
    iter = iter + 1
    nrint = n - nmin + 1
    nk1 = n - k1
    n7 = nk1 - k
    n10 = n7 - k
    call periodic_knots()
    z(1:n*idim) = 0
    a1(1:n7, 1:k1) = 0
    jper = 0
    fp = 0
    l = k1
    do it = 1, m1
      ui = u(it)
      wi = w(it)
      do d = 1, idim
        xi(d) = x(idim*(it - 1) + d)*wi
      end do
      do while (ui >= t(l + 1))
        l = l + 1
      end do
      call fpbspl(t, n, k, ui, l, h)
      do i = 1, k1
        q(it, i) = h(i)
        h(i) = h(i)*wi
      end do
      l5 = l - k1
      if (l5 < n10) then
        ! no wrap-around yet: plain band rotation
        call rotate_band_row(l5)
      else
        if (jper == 0) then
          ! move the last k columns of the band into the dense border a2
          a2(1:n7, 1:k) = 0
          do i = 1, k
            do j = 1, k1
              cf = n10 + i - j + 1
              if (cf <= 0) exit
              a2(cf, i) = a1(cf, j)
            end do
          end do
          jper = 1
        end if
        h1(1:k1) = 0
        h2(1:k) = 0
        do i = 1, k1
          cf = l5 + i
          ! with few knots a row can wrap around more than once
          do while (cf > n7)
            cf = cf - n7
          end do
          if (cf > n10) then
            h2(cf - n10) = h2(cf - n10) + h(i)
          else
            h1(cf) = h(i)
          end if
        end do
        call rotate_bordered_row(1, n10, k1, k, a1, a2, z)
      end if
      do d = 1, idim
        fp = fp + xi(d)**2
      end do
    end do
    fpint(n) = fp0
    fpint(n - 1) = fpold
    nrdata(n) = nplus
    do d = 1, idim
      call fpbacp(a1, a2, z(n*(d - 1) + 1), n7, k, sol, k1, nest)
      c(n*(d - 1) + 1:n*(d - 1) + n7) = sol(1:n7)
      call repeat_coefficients(d)
    end do
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
    npl1 = nplus*2
    rn = nplus
    if (fpold - fp > acc) npl1 = int(rn*fpms/(fpold - fp))
    nplus = min(nplus*2, max(npl1, nplus/2, 1))
    fpold = fp
    ! residual sums per knot interval; the first point closes the last interval
    fpart = 0
    i = 1
    l = k1
    new = 0
    do it = 1, m1
      if (u(it) >= t(l)) then
        new = 1
        l = l + 1
      end if
      term = residual2(it, l)
      fpart = fpart + term
      if (new /= 0) then
        if (l <= k2) then
          fpint(nrint) = term
        else
          store = term*half
          fpint(i) = fpart - store
          i = i + 1
          fpart = store
        end if
        new = 0
      end if
    end do
    fpint(nrint) = fpint(nrint) + fpart
    interpolate_now = .false.
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
        interpolate_now = .true.
        exit
      end if
      if (n == nest) exit
    end do
    if (interpolate_now) then
      call interpolation_knots()
      iter = 0
    end if
  end do knots

  ! smoothing: find p with f(p) = fp(p) - s = 0
  call fpdisc(t, n, k2, b, nest)
  allocate (rhs(nest, idim))
  nk1 = n - k1
  n7 = nk1 - k
  n10 = n7 - k
  n11 = n10 - 1
  n8 = n7 - 1
  p1 = 0
  f1 = fp0 - s
  p3 = -1
  f3 = fpms
  p = 0
  l = n7
  do i = 1, k
    j = k + 1 - i
    p = p + a2(l, j)
    l = l - 1
    if (l == 0) exit
  end do
  if (l > 0) then
    do i = 1, n10
      p = p + a1(i, 1)
    end do
  end if
  rn = n7
  p = rn/p
  ich1 = 0
  ich3 = 0
  do iter = 1, maxit
    pinv = 1/p
    ! g = a with the border widened by column n10 (now n11 = n10-1 band columns)
    do d = 1, idim
      rhs(1:n7, d) = z(n*(d - 1) + 1:n*(d - 1) + n7)
    end do
    do i = 1, n7
      g1(i, 1:k1) = a1(i, 1:k1)
      g1(i, k2) = 0
      g2(i, 1) = 0
      g2(i, 2:k1) = a2(i, 1:k)
    end do
    l = n10
    do j = 1, k1
      if (l <= 0) exit
      g2(l, 1) = a1(l, j)
      l = l - 1
    end do
    do it = 1, n8
      xi(1:idim) = 0
      h1(1:k2) = 0
      h2(1:k1) = 0
      if (it <= n11) then
        do j = 1, k2
          cf = it + j - 1
          if (cf > n11) then
            h2(cf - n11) = b(it, j)*pinv
          else
            h1(j) = b(it, j)*pinv
          end if
        end do
        call rotate_bordered_row(it, n11, k2, k1, g1, g2, rhs)
      else
        do j = 1, k2
          cf = it + j - 1
          do while (cf > n7)
            cf = cf - n7
          end do
          if (cf > n11) then
            h2(cf - n11) = h2(cf - n11) + b(it, j)*pinv
          else
            h1(cf) = h1(cf) + b(it, j)*pinv
          end if
        end do
        call rotate_bordered_row(1, n11, k2, k1, g1, g2, rhs)
      end if
    end do
    do d = 1, idim
      call fpbacp(g1, g2, rhs(1, d), n7, k1, sol, k2, nest)
      c(n*(d - 1) + 1:n*(d - 1) + n7) = sol(1:n7)
      call repeat_coefficients(d)
    end do
    fp = 0
    l = k1
    do it = 1, m1
      if (u(it) >= t(l)) l = l + 1
      fp = fp + residual2(it, l)
    end do
    fpms = fp - s
    call fp_smoothing_step(fpms, acc, .false., iter, maxit, single_steps, p, p1, f1, p3, f3, ich1, ich3, step)
    if (step < 0) cycle
    if (step > 0) ier = step
    return
  end do

contains

  !> c(n7+j) = c(j), j = 1..k, in order (with few knots the copies wrap again).
  subroutine repeat_coefficients(dd)
    integer, intent(in) :: dd
    integer :: ii, off
    off = n*(dd - 1)
    do ii = 1, k
      c(off + n7 + ii) = c(off + ii)
    end do
  end subroutine repeat_coefficients

  !> Interior knots of the periodic interpolating spline: the data points
  !> u(2..m-1) (odd k) or the midpoints of u(1..m-1) (even k).
  subroutine interpolation_knots()
    integer :: ii
    if (mod(k, 2) == 1) then
      do ii = 2, m1
        t(ii + k) = u(ii)
      end do
    else
      do ii = 2, m1
        t(ii + k) = (u(ii) + u(ii - 1))*half
      end do
    end if
  end subroutine interpolation_knots

  !> t(k+1) = u(1), t(n-k) = u(m); outer knots repeat the inner spacing.
  subroutine periodic_knots()
    integer :: jj, i1, i2, j1, j2, nk
    nk = n - k1
    t(k1) = u(1)
    t(nk + 1) = u(m)
    do jj = 1, k
      i1 = nk + 1 + jj
      i2 = nk + 1 - jj
      j1 = k1 + jj
      j2 = k1 - jj
      t(i1) = t(j1) + per
      t(j2) = t(i2) - per
    end do
  end subroutine periodic_knots

  !> The least-squares constant curve as a periodic spline without interior knots.
  subroutine constant_spline()
    integer :: ii, jj, dd
    do ii = 1, k1
      rn = k1 - ii
      t(ii) = u(1) - rn*per
      jj = ii + k1
      rn = ii - 1
      t(jj) = u(m) + rn*per
    end do
    n = nmin
    do dd = 1, idim
      c(n*(dd - 1) + 1:n*(dd - 1) + nmin) = c1(dd)
    end do
    fp = fp0
    fpint(n) = fp0
    fpint(n - 1) = 0
    nrdata(n) = 0
    ier = -2
  end subroutine constant_spline

  !> Band rotation of the data row h(1..k1) (columns l0+1..l0+k1) into a1.
  subroutine rotate_band_row(l0)
    integer, intent(in) :: l0
    integer :: ii, i2, jr, dd
    do ii = 1, k1
      piv = h(ii)
      if (piv == 0) cycle
      jr = l0 + ii
      call fpgivs(piv, a1(jr, 1), cs, sn)
      do dd = 1, idim
        call fprota(cs, sn, xi(dd), z(jr + n*(dd - 1)))
      end do
      do i2 = ii + 1, k1
        call fprota(cs, sn, h(i2), a1(jr, i2 - ii + 1))
      end do
    end do
  end subroutine rotate_band_row

  !> Rotates the row (h1: band part starting at column lstart, h2: border
  !> part) into the bordered triangle [gb gd] with nband band columns of
  !> width bw and nb border columns; right-hand sides xi(1..idim) against r,
  !> one column per coordinate (leading dimension n for z, nest for rhs).
  subroutine rotate_bordered_row(lstart, nband, bw, nb, gb, gd, r)
    integer, intent(in) :: lstart, nband, bw, nb
    real(real64), intent(inout) :: gb(nest, bw), gd(nest, nb), r(*)
    integer :: jr, ii, i2, dd, ij, ldr
    ldr = n
    if (bw == k2) ldr = nest
    if (nband > 0) then
      do jr = lstart, nband
        piv = h1(1)
        if (piv /= 0) then
          call fpgivs(piv, gb(jr, 1), cs, sn)
          do dd = 1, idim
            call fprota(cs, sn, xi(dd), r(jr + ldr*(dd - 1)))
          end do
          do ii = 1, nb
            call fprota(cs, sn, h2(ii), gd(jr, ii))
          end do
          if (jr == nband) exit
          i2 = min(nband - jr, bw - 1)
          do ii = 1, i2
            call fprota(cs, sn, h1(ii + 1), gb(jr, ii + 1))
            h1(ii) = h1(ii + 1)
          end do
          h1(i2 + 1) = 0
        else
          if (jr == nband) exit
          i2 = min(nband - jr, bw - 1)
          do ii = 1, i2
            h1(ii) = h1(ii + 1)
          end do
          h1(i2 + 1) = 0
        end if
      end do
    end if
    do jr = 1, nb
      ij = nband + jr
      if (ij <= 0) cycle
      piv = h2(jr)
      if (piv == 0) cycle
      call fpgivs(piv, gd(ij, jr), cs, sn)
      do dd = 1, idim
        call fprota(cs, sn, xi(dd), r(ij + ldr*(dd - 1)))
      end do
      do i2 = jr + 1, nb
        call fprota(cs, sn, h2(i2), gd(ij, i2))
      end do
    end do
  end subroutine rotate_bordered_row

  real(real64) function residual2(pt, lint) result(r)
    integer, intent(in) :: pt, lint
    integer :: dd, jj, ll
    real(real64) :: fac
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
end subroutine fpperiodic_core

!> The last input checks of percur and clocur (ier = 0 if passed, else 10).
!> iopt = -1, given interior knots t(k+2..n-k-1): 2k+2 < n <= nest; then
!> t(k+1) = u(1), t(n-k) = u(m) and the k knots beyond each end by
!> periodicity with period u(m) - u(1), and the knots checked (fpchep).
!> iopt >= 0: s >= 0, and nest >= m + 2k for interpolation (s = 0).
pure subroutine fp_periodic_knot_checks(iopt, u, m, k, s, nest, n, t, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpchep
  implicit none (type, external)
  integer, intent(in) :: iopt, m, k, nest, n
  real(real64), intent(in) :: u(m), s
  real(real64), intent(inout) :: t(nest)
  integer, intent(out) :: ier
  real(real64) :: per
  integer :: i, i1, i2, j1, j2
  ier = 10
  if (iopt >= 0) then
    if (s < 0) return
    if (s == 0 .and. nest < m + 2*k) return
    ier = 0
    return
  end if
  if (n <= 2*(k + 1) .or. n > nest) return
  per = u(m) - u(1)
  j1 = k + 1
  t(j1) = u(1)
  i1 = n - k
  t(i1) = u(m)
  j2 = j1
  i2 = i1
  do i = 1, k
    i1 = i1 + 1
    i2 = i2 - 1
    j1 = j1 + 1
    j2 = j2 - 1
    t(j2) = t(i2) - per
    t(i1) = t(j1) + per
  end do
  call fpchep(u, m, t, n, k, ier)
end subroutine fp_periodic_knot_checks
