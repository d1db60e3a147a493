!> parsur and surev, which no scipy reaches, checked by what must hold:
!>  - non-periodic, one coordinate: parsur is regrid with kx = ky = 3 (same
!>    knots, coefficients, fp, ier), for s = 0 and s > 0;
!>  - three coordinates, s = 0: each coordinate interpolates its data and
!>    equals regrid's interpolant of that coordinate;
!>  - periodic in u (a closed tube) and in both directions (a torus): the
!>    spline is C^2 across the seam (value, first and second u-derivatives
!>    from both sides agree), interpolates for s = 0 and meets fp <= s (within
!>    FITPACK's 0.1 %) for s > 0;
!>  - surev equals bispev applied per coordinate; invalid input gives ier = 10.
program test_surfaces_parsur
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_surface_interfaces, only: parsur, surev, regrid, bispev, parder
  use fitpack_reference_io, only: expect, expect_close_scaled, expect_coefficients, finish_checks
  implicit none (type, external)
  real(real64), parameter :: pi = acos(-1.0_real64)
  ! same algorithm, dense instead of banded rotations: rounding only
  real(real64), parameter :: rtol_same = 1.0e-10_real64
  call against_regrid(0.0_real64)
  call against_regrid(0.02_real64)
  call three_coordinates()
  call periodic_tube(0.0_real64)
  call periodic_tube(0.05_real64)
  call periodic_torus()
  call invalid()
  call finish_checks('test_surfaces_parsur')
contains



  subroutine grid(mu, mv, u, v)
    integer, intent(in) :: mu, mv
    real(real64), allocatable, intent(out) :: u(:), v(:)
    integer :: i
    u = [(real(i - 1, real64)/(mu - 1), i = 1, mu)]
    v = [(real(i - 1, real64)/(mv - 1), i = 1, mv)]
    u(2:mu - 1) = u(2:mu - 1) + 0.2_real64/(mu - 1)*sin(7.0_real64*u(2:mu - 1))
  end subroutine grid

  real(real64) function noise(i, j, l)
    integer, intent(in) :: i, j, l
    noise = 0.01_real64*sin(12.9898_real64*i + 78.233_real64*j + 37.719_real64*l)
  end function noise

  subroutine against_regrid(s)
    real(real64), intent(in) :: s
    integer, parameter :: mu = 14, mv = 11
    real(real64), allocatable :: u(:), v(:), f(:), tu(:), tv(:), c(:), wrk(:), tx(:), ty(:), cr(:), wr(:)
    integer, allocatable :: iwrk(:), iwr(:)
    integer :: i, j, nu, nv, nx, ny, ier, ierr, lwrk, kwrk, lwr, kwr, nuest, nvest
    real(real64) :: fp, fpr
    character(len=32) :: tag
    write (tag, '(a, es8.1)') 'vs regrid s=', s
    call grid(mu, mv, u, v)
    allocate (f(mu*mv))
    do i = 1, mu
      do j = 1, mv
        f(mv*(i - 1) + j) = sin(3*u(i))*cos(2*v(j)) + u(i)*v(j) + noise(i, j, 1)
      end do
    end do
    nuest = mu + 4
    nvest = mv + 4
    lwrk = 4 + nuest*(mv + 11) + nvest*11 + 4*(mu + mv) + max(nuest, mv)
    kwrk = 3 + mu + mv + nuest + nvest
    allocate (tu(nuest), tv(nvest), c((nuest - 4)*(nvest - 4)), wrk(lwrk), iwrk(kwrk))
    call parsur(0, [0, 0], 1, mu, u, mv, v, f, s, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, iwrk, &
      kwrk, ier)
    lwr = 4 + nuest*(mv + 2*3 + 5) + nvest*(2*3 + 5) + mu*4 + mv*4 + max(mv, nuest)
    kwr = 3 + mu + mv + nuest + nvest
    allocate (tx(nuest), ty(nvest), cr((nuest - 4)*(nvest - 4)), wr(lwr), iwr(kwr))
    call regrid(0, mu, u, mv, v, f, u(1), u(mu), v(1), v(mv), 3, 3, s, nuest, nvest, nx, tx, ny, ty, cr, &
      fpr, wr, lwr, iwr, kwr, ierr)
    call expect(ier == ierr, trim(tag)//': ier')
    call expect(nu == nx .and. nv == ny, trim(tag)//': number of knots')
    if (nu /= nx .or. nv /= ny) return
    call expect_close_scaled(tu(1:nu), tx(1:nx), 1.0e-14_real64, 0.0_real64, trim(tag)//': u knots')
    call expect_close_scaled(tv(1:nv), ty(1:ny), 1.0e-14_real64, 0.0_real64, trim(tag)//': v knots')
    call expect_coefficients(c(1:(nu - 4)*(nv - 4)), cr(1:(nu - 4)*(nv - 4)), rtol_same, trim(tag)//': coefficients')
    call expect(abs(fp - fpr) <= rtol_same*max(fpr, 1.0e-300_real64) .or. (fp == 0 .and. fpr == 0), &
      trim(tag)//': fp')
    if (s > 0) call expect(abs(fp - s) <= 1.0e-3_real64*s, trim(tag)//': |fp - s| < 0.001 s')
  end subroutine against_regrid

  subroutine three_coordinates()
    integer, parameter :: mu = 9, mv = 8
    real(real64), allocatable :: u(:), v(:), f(:), tu(:), tv(:), c(:), wrk(:), tx(:), ty(:), cr(:), wr(:), &
      fe(:), z(:)
    integer, allocatable :: iwrk(:), iwr(:)
    integer :: i, j, l, nu, nv, nx, ny, ier, ierr, lwrk, kwrk, lwr, kwr, nuest, nvest, nc
    real(real64) :: fp, fpr
    call grid(mu, mv, u, v)
    allocate (f(3*mu*mv))
    do l = 1, 3
      do i = 1, mu
        do j = 1, mv
          f(mu*mv*(l - 1) + mv*(i - 1) + j) = cos(l*u(i) + v(j)) + l*u(i)*v(j)**2 + noise(i, j, l)
        end do
      end do
    end do
    nuest = mu + 4
    nvest = mv + 4
    lwrk = 4 + nuest*(3*mv + 11) + nvest*11 + 4*(mu + mv) + 3*max(nuest, mv)
    kwrk = 3 + mu + mv + nuest + nvest
    allocate (tu(nuest), tv(nvest), c(3*(nuest - 4)*(nvest - 4)), wrk(lwrk), iwrk(kwrk))
    call parsur(0, [0, 0], 3, mu, u, mv, v, f, 0.0_real64, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, &
      iwrk, kwrk, ier)
    call expect(ier == -1, '3-D s=0: ier = -1')
    nc = (nu - 4)*(nv - 4)
    allocate (fe(3*mu*mv))
    call surev(3, tu, nu, tv, nv, c, u, mu, v, mv, fe, 3*mu*mv, wrk, lwrk, iwrk, kwrk, ier)
    call expect(ier == 0, '3-D: surev ier')
    ! interpolation: the data back to rounding of the solve
    call expect_close_scaled(fe, f, 1.0e-12_real64, 0.0_real64, '3-D s=0: surev interpolates the data')
    lwr = 4 + nuest*(mv + 11) + nvest*11 + mu*4 + mv*4 + max(mv, nuest)
    kwr = 3 + mu + mv + nuest + nvest
    allocate (tx(nuest), ty(nvest), cr(nc), wr(lwr), iwr(kwr), z(mu*mv))
    do l = 1, 3
      call regrid(0, mu, u, mv, v, f(mu*mv*(l - 1) + 1:mu*mv*l), u(1), u(mu), v(1), v(mv), 3, 3, 0.0_real64, &
        nuest, nvest, nx, tx, ny, ty, cr, fpr, wr, lwr, iwr, kwr, ierr)
      call expect(nx == nu .and. ny == nv, '3-D: regrid knots per coordinate')
      call expect_coefficients(c(nc*(l - 1) + 1:nc*l), cr(1:nc), rtol_same, '3-D: coordinate equals regrid')
      call bispev(tu, nu, tv, nv, c(nc*(l - 1) + 1:nc*l), 3, 3, u, mu, v, mv, z, wr, lwr, iwr, kwr, ierr)
      call expect_close_scaled(fe(mu*mv*(l - 1) + 1:mu*mv*l), z, 1.0e-14_real64, 0.0_real64, '3-D: surev equals bispev')
    end do
  end subroutine three_coordinates

  !> r(u,v) on a closed tube: u around (period 1), v along.
  subroutine periodic_tube(s)
    real(real64), intent(in) :: s
    integer, parameter :: mu = 17, mv = 9
    real(real64), allocatable :: u(:), v(:), f(:), tu(:), tv(:), c(:), wrk(:), fe(:)
    integer, allocatable :: iwrk(:)
    integer :: i, j, nu, nv, ier, lwrk, kwrk, nuest, nvest
    real(real64) :: fp, a
    character(len=32) :: tag
    write (tag, '(a, es8.1)') 'tube s=', s
    u = [(real(i - 1, real64)/(mu - 1), i = 1, mu)]
    v = [(real(i - 1, real64)/(mv - 1), i = 1, mv)]
    allocate (f(3*mu*mv))
    do i = 1, mu
      do j = 1, mv
        a = 2*pi*u(i)
        f(mv*(i - 1) + j) = (1 + 0.3_real64*v(j))*cos(a) + noise(mod(i - 1, mu - 1), j, 1)
        f(mu*mv + mv*(i - 1) + j) = (1 + 0.3_real64*v(j))*sin(a) + 0.2_real64*sin(2*a)
        f(2*mu*mv + mv*(i - 1) + j) = 3*v(j) + 0.1_real64*cos(3*a)
      end do
    end do
    nuest = mu + 6
    nvest = mv + 4
    lwrk = 4 + nuest*(3*mv + 15) + nvest*11 + 4*(mu + mv) + 3*max(nuest, mv)
    kwrk = 3 + mu + mv + nuest + nvest
    allocate (tu(nuest), tv(nvest), c(3*(nuest - 4)*(nvest - 4)), wrk(lwrk), iwrk(kwrk), fe(3*mu*mv))
    call parsur(0, [1, 0], 3, mu, u, mv, v, f, s, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, iwrk, &
      kwrk, ier)
    call expect(ier <= 0, trim(tag)//': ier <= 0')
    if (s == 0) then
      call expect(ier == -1, trim(tag)//': interpolating (ier = -1)')
      call surev(3, tu, nu, tv, nv, c, u, mu, v, mv, fe, 3*mu*mv, wrk, lwrk, iwrk, kwrk, ier)
      ! the data of line u(mu) were averaged with line u(1): compare lines 1..mu-1
      call expect_close_scaled(pack(fe, mask_lines(mu, mv)), pack(f, mask_lines(mu, mv)), 1.0e-12_real64, 0.0_real64, &
        trim(tag)//': interpolates')
    else
      call expect(abs(fp - s) <= 1.0e-3_real64*s .or. ier == -2, trim(tag)//': |fp - s| < 0.001 s')
    end if
    call seam_check(tu, nu, tv, nv, c, 1, trim(tag))
  end subroutine periodic_tube

  !> A torus, periodic in both directions, smoothing.
  subroutine periodic_torus()
    integer, parameter :: mu = 13, mv = 11
    real(real64), allocatable :: u(:), v(:), f(:), tu(:), tv(:), c(:), wrk(:)
    integer, allocatable :: iwrk(:)
    integer :: i, j, nu, nv, ier, lwrk, kwrk, nuest, nvest
    real(real64) :: fp, a, b, s
    u = [(real(i - 1, real64)/(mu - 1), i = 1, mu)]
    v = [(real(i - 1, real64)/(mv - 1), i = 1, mv)]
    allocate (f(3*mu*mv))
    do i = 1, mu
      do j = 1, mv
        a = 2*pi*u(i)
        b = 2*pi*v(j)
        f(mv*(i - 1) + j) = (2 + 0.5_real64*cos(b))*cos(a)
        f(mu*mv + mv*(i - 1) + j) = (2 + 0.5_real64*cos(b))*sin(a)
        f(2*mu*mv + mv*(i - 1) + j) = 0.5_real64*sin(b) + noise(mod(i - 1, mu - 1), mod(j - 1, mv - 1), 3)
      end do
    end do
    s = 0.002_real64
    nuest = mu + 6
    nvest = mv + 6
    lwrk = 4 + nuest*(3*mv + 15) + nvest*15 + 4*(mu + mv) + 3*max(nuest, mv)
    kwrk = 3 + mu + mv + nuest + nvest
    allocate (tu(nuest), tv(nvest), c(3*(nuest - 4)*(nvest - 4)), wrk(lwrk), iwrk(kwrk))
    call parsur(0, [1, 1], 3, mu, u, mv, v, f, s, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, iwrk, &
      kwrk, ier)
    call expect(ier <= 0, 'torus: ier <= 0')
    call expect(abs(fp - s) <= 1.0e-3_real64*s, 'torus: |fp - s| < 0.001 s')
    call seam_check(tu, nu, tv, nv, c, 1, 'torus u')
    call seam_check(tu, nu, tv, nv, c, 2, 'torus v')
    ! continuation (iopt = 1) to a smaller s keeps the knots and reaches it
    i = nu
    j = nv
    call parsur(1, [1, 1], 3, mu, u, mv, v, f, s/2, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, iwrk, &
      kwrk, ier)
    call expect(ier <= 0 .and. abs(fp - s/2) <= 1.0e-3_real64*s/2, 'torus iopt=1: |fp - s| < 0.001 s')
    call expect(nu >= i .and. nv >= j, 'torus iopt=1: no knots lost')
    call seam_check(tu, nu, tv, nv, c, 1, 'torus iopt=1 u')
  end subroutine periodic_torus

  function mask_lines(mu, mv) result(mask)
    integer, intent(in) :: mu, mv
    logical :: mask(3*mu*mv)
    integer :: l, i
    mask = .true.
    do l = 1, 3
      do i = 1, mu
        if (i == mu) mask(mu*mv*(l - 1) + mv*(i - 1) + 1:mu*mv*(l - 1) + mv*i) = .false.
      end do
    end do
  end function mask_lines

  !> C^2 across the seam of direction dir: derivatives of order 0..2 at the
  !> start of the domain (right-hand) and at its end (left-hand, clamped into
  !> the last interval) agree, per coordinate, at several points of the other
  !> direction. Tolerance: 1e-9 of the derivative's scale (rounding of a
  !> well-conditioned solve, amplified by the knot spacing to the power 2).
  subroutine seam_check(tu, nu, tv, nv, c, dir, tag)
    real(real64), intent(in) :: tu(:), tv(:), c(:)
    integer, intent(in) :: nu, nv, dir
    character(len=*), intent(in) :: tag
    real(real64) :: a(5), b(5), w(4000), other(5), scale
    integer :: iw(20), ier, ier2, l, nd, nc, k
    character(len=8) :: what
    nc = (nu - 4)*(nv - 4)
    do k = 1, 5
      if (dir == 1) then
        other(k) = tv(4) + (tv(nv - 3) - tv(4))*(k - 0.5_real64)/5
      else
        other(k) = tu(4) + (tu(nu - 3) - tu(4))*(k - 0.5_real64)/5
      end if
    end do
    do l = 1, 3
      do nd = 0, 2
        if (dir == 1) then
          call parder(tu, nu, tv, nv, c(nc*(l - 1) + 1:nc*l), 3, 3, nd, 0, [tu(4)], 1, other, 5, a, w, 4000, &
            iw, 20, ier)
          call parder(tu, nu, tv, nv, c(nc*(l - 1) + 1:nc*l), 3, 3, nd, 0, [tu(nu - 3)], 1, other, 5, b, w, &
            4000, iw, 20, ier2)
        else
          call parder(tu, nu, tv, nv, c(nc*(l - 1) + 1:nc*l), 3, 3, 0, nd, other, 5, [tv(4)], 1, a, w, 4000, &
            iw, 20, ier)
          call parder(tu, nu, tv, nv, c(nc*(l - 1) + 1:nc*l), 3, 3, 0, nd, other, 5, [tv(nv - 3)], 1, b, w, &
            4000, iw, 20, ier2)
        end if
        write (what, '(a, i0, a, i0)') 'l', l, ' d', nd
        call expect(ier == 0 .and. ier2 == 0, tag//': parder at the seam '//trim(what))
        scale = max(maxval(abs(a)), 1.0_real64)
        call expect(maxval(abs(a - b)) <= 1.0e-9_real64*scale, tag//': C2 across the seam '//trim(what))
      end do
    end do
  end subroutine seam_check

  subroutine invalid()
    real(real64) :: u(5), v(5), f(75), tu(20), tv(20), c(300), wrk(2000), fp, fe(75)
    integer :: iwrk(100), nu, nv, ier, i
    u = [(real(i, real64), i = 1, 5)]
    v = u
    f = 1
    call parsur(0, [0, 0], 4, 5, u, 5, v, f, 0.1_real64, 20, 20, nu, tu, nv, tv, c, fp, wrk, 2000, iwrk, 100, ier)
    call expect(ier == 10, 'parsur idim = 4 gives ier 10')
    call parsur(0, [0, 2], 3, 5, u, 5, v, f, 0.1_real64, 20, 20, nu, tu, nv, tv, c, fp, wrk, 2000, iwrk, 100, ier)
    call expect(ier == 10, 'parsur ipar = 2 gives ier 10')
    call parsur(0, [0, 0], 3, 5, u, 5, v, f, -1.0_real64, 20, 20, nu, tu, nv, tv, c, fp, wrk, 2000, iwrk, 100, ier)
    call expect(ier == 10, 'parsur s < 0 gives ier 10')
    call parsur(0, [0, 0], 3, 5, u(5:1:-1), 5, v, f, 0.1_real64, 20, 20, nu, tu, nv, tv, c, fp, wrk, 2000, iwrk, &
      100, ier)
    call expect(ier == 10, 'parsur decreasing u gives ier 10')
    call parsur(0, [0, 0], 3, 5, u, 5, v, f, 0.0_real64, 8, 20, nu, tu, nv, tv, c, fp, wrk, 2000, iwrk, 100, ier)
    call expect(ier == 10, 'parsur s = 0 with nuest < mu+4 gives ier 10')
    tu(1:9) = [1, 1, 1, 1, 3, 5, 5, 5, 5]
    call surev(3, tu, 9, tu, 9, c, u, 5, v, 5, fe, 74, wrk, 2000, iwrk, 100, ier)
    call expect(ier == 10, 'surev mf too small gives ier 10')
    call surev(3, tu, 9, tu, 9, c, u(5:1:-1), 5, v, 5, fe, 75, wrk, 2000, iwrk, 100, ier)
    call expect(ier == 10, 'surev decreasing u gives ier 10')
  end subroutine invalid
end program test_surfaces_parsur
