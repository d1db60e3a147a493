!> Zeros of a cubic spline: sproot and the cubic solver fpcuro (Dierckx's
!> calling sequences, reals real64). ier = 10 for invalid knots or n < 8,
!> ier = 1 if there are more than mest zeros (the first mest are returned).

!> Real roots x(1..n) of a*x**3 + b*x**2 + c*x + d = 0, each polished by one
!> Newton step; degenerate leading coefficients fall back to the quadratic
!> or linear equation.
pure subroutine fpcuro(a, b, c, d, x, n)
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  real(real64), intent(in) :: a, b, c, d
  real(real64), intent(out) :: x(3)
  integer, intent(out) :: n
  real(real64), parameter :: pi3 = 1.0471975511965977462_real64, tiny = 1e-14_real64
  real(real64) :: a1, b1, c1, df, disc, f, p, q, r, u, u1, u2, y, scale
  integer :: i
  x = 0
  scale = max(abs(b), abs(c), abs(d))
  if (abs(a) > tiny*scale .and. a /= 0) then
    ! depressed cubic y**3 + p y + q = 0 with x = y - b/(3a)
    a1 = b/a
    b1 = c/a
    c1 = d/a
    p = b1/3 - (a1/3)**2
    q = a1**3/27 - a1*b1/6 + c1/2
    disc = q*q + p**3
    if (disc > 0) then
      u = sqrt(disc)
      u1 = -q + sign(u, -q)
      u1 = sign(abs(u1)**(1.0_real64/3), u1)
      if (u1 /= 0) then
        u2 = -p/u1
      else
        u2 = 0
      end if
      n = 1
      x(1) = u1 + u2 - a1/3
    else
      r = sqrt(max(-p, 0.0_real64))
      if (r == 0) then
        n = 1
        x(1) = -a1/3
      else
        y = acos(max(-1.0_real64, min(1.0_real64, -q/r**3)))/3
        n = 3
        x(1) = 2*r*cos(y) - a1/3
        x(2) = 2*r*cos(y + 2*pi3) - a1/3
        x(3) = 2*r*cos(y - 2*pi3) - a1/3
      end if
    end if
  else if (b /= 0 .and. abs(b) > tiny*max(abs(c), abs(d))) then
    disc = c*c - 4*b*d
    if (disc < 0) then
      n = 0
      return
    end if
    u = sqrt(disc)
    q = -0.5_real64*(c + sign(u, c))
    n = 2
    x(1) = q/b
    if (q /= 0) then
      x(2) = d/q
    else
      x(2) = x(1)
    end if
  else if (c /= 0) then
    n = 1
    x(1) = -d/c
  else
    n = 0
    return
  end if
  do i = 1, n
    y = x(i)
    f = ((a*y + b)*y + c)*y + d
    df = (3*a*y + 2*b)*y + c
    if (df /= 0) x(i) = y - f/df
  end do
end subroutine fpcuro

pure subroutine sproot(t, n, c, zero, mest, m, ier)
  use, intrinsic :: iso_fortran_env, only: real64
  use fitpack_interfaces, only: fpcuro, fpader
  implicit none (type, external)
  integer, intent(in) :: n, mest
  real(real64), intent(in) :: t(n), c(n)
  real(real64), intent(out) :: zero(mest)
  integer, intent(out) :: m, ier
  real(real64) :: d(4), roots(3), h, a0, a1, a2, a3, z, tol, last
  integer :: i, j, l, nr, n4
  m = 0
  zero = 0
  ier = 10
  if (n < 8) return
  n4 = n - 4
  do i = 1, 3
    if (t(i) > t(i + 1) .or. t(n - i + 1) < t(n - i)) return
  end do
  do i = 4, n4
    if (t(i) >= t(i + 1)) return
  end do
  ier = 0
  last = t(4) - 1
  do l = 4, n4
    h = t(l + 1) - t(l)
    call fpader(t, n, c, 4, t(l), l, d)
    ! s(t(l) + y) = a0 + a1 y + a2 y**2 + a3 y**3 on [0, h]
    a0 = d(1)
    a1 = d(2)
    a2 = d(3)/2
    a3 = d(4)/6
    call fpcuro(a3, a2, a1, a0, roots, nr)
    call sort3(roots, nr)
    tol = 1e-10_real64*h
    do j = 1, nr
      z = roots(j)
      if (z < -tol .or. z > h + tol) cycle
      z = t(l) + min(max(z, 0.0_real64), h)
      if (m > 0) then
        if (abs(z - last) <= tol) cycle
      end if
      if (m >= mest) then
        ier = 1
        return
      end if
      m = m + 1
      zero(m) = z
      last = z
    end do
  end do
contains
  pure subroutine sort3(v, nv)
    real(real64), intent(inout) :: v(3)
    integer, intent(in) :: nv
    integer :: p, q
    real(real64) :: s
    do p = 2, nv
      do q = p, 2, -1
        if (v(q) < v(q - 1)) then
          s = v(q)
          v(q) = v(q - 1)
          v(q - 1) = s
        end if
      end do
    end do
  end subroutine sort3
end subroutine sproot
