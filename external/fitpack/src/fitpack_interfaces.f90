!> Explicit interfaces of the curve routines and shared kernels of our FITPACK
!> (Dierckx's calling sequences, every real is real64). The routines themselves
!> are external procedures, so the genuine netlib FITPACK compiled with
!> -fdefault-real-8 can be linked in their place. Surface routines:
!> module fitpack_surface_interfaces.
!>
!> Note on aliasing: the originals call fpback(g,c,n,k,c,nest) with z and c the
!> same array; through these interfaces pass distinct arrays.
module fitpack_interfaces
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none (type, external)
  private
  public :: fpbspl, fpgivs, fprota, fpback, fpbacp, fprati, fpdisc, fpchec, fpchep, fpknot
  public :: fpader, fpinst, fpintb, fpcuro, fp_smoothing_step, fp_periodic_knot_checks
  public :: curfit, percur, parcur, clocur, concur
  public :: splev, splder, curev, cualde, spalde, insert, splint, sproot

  interface
    pure subroutine fpbspl(t, n, k, x, l, h)
      import :: real64
      integer, intent(in) :: n, k, l
      real(real64), intent(in) :: t(n), x
      real(real64), intent(out) :: h(*)
    end subroutine fpbspl

    pure subroutine fpgivs(piv, ww, cos, sin)
      import :: real64
      real(real64), intent(in) :: piv
      real(real64), intent(inout) :: ww
      real(real64), intent(out) :: cos, sin
    end subroutine fpgivs

    pure subroutine fprota(cos, sin, a, b)
      import :: real64
      real(real64), intent(in) :: cos, sin
      real(real64), intent(inout) :: a, b
    end subroutine fprota

    pure subroutine fpback(a, z, n, k, c, nest)
      import :: real64
      integer, intent(in) :: n, k, nest
      real(real64), intent(in) :: a(nest, k), z(n)
      real(real64), intent(out) :: c(n)
    end subroutine fpback

    pure subroutine fpbacp(a, b, z, n, k, c, k1, nest)
      import :: real64
      integer, intent(in) :: n, k, k1, nest
      real(real64), intent(in) :: a(nest, k1), b(nest, k), z(n)
      real(real64), intent(out) :: c(n)
    end subroutine fpbacp

    function fprati(p1, f1, p2, f2, p3, f3) result(p)
      import :: real64
      real(real64), intent(inout) :: p1, f1, p3, f3
      real(real64), intent(in) :: p2, f2
      real(real64) :: p
    end function fprati

    subroutine fp_smoothing_step(fpms, acc, accept_tie, iter, maxit, single_steps, p, p1, f1, p3, f3, &
                                 ich1, ich3, step)
      import :: real64
      real(real64), intent(in) :: fpms, acc
      logical, intent(in) :: accept_tie, single_steps
      integer, intent(in) :: iter, maxit
      real(real64), intent(inout) :: p, p1, f1, p3, f3
      integer, intent(inout) :: ich1, ich3
      integer, intent(out) :: step
    end subroutine fp_smoothing_step

    pure subroutine fpdisc(t, n, k2, b, nest)
      import :: real64
      integer, intent(in) :: n, k2, nest
      real(real64), intent(in) :: t(n)
      real(real64), intent(out) :: b(nest, k2)
    end subroutine fpdisc

    pure subroutine fpchec(x, m, t, n, k, ier)
      import :: real64
      integer, intent(in) :: m, n, k
      real(real64), intent(in) :: x(m), t(n)
      integer, intent(out) :: ier
    end subroutine fpchec

    pure subroutine fpchep(x, m, t, n, k, ier)
      import :: real64
      integer, intent(in) :: m, n, k
      real(real64), intent(in) :: x(m), t(n)
      integer, intent(out) :: ier
    end subroutine fpchep

    pure subroutine fp_periodic_knot_checks(iopt, u, m, k, s, nest, n, t, ier)
      import :: real64
      integer, intent(in) :: iopt, m, k, nest, n
      real(real64), intent(in) :: u(m), s
      real(real64), intent(inout) :: t(nest)
      integer, intent(out) :: ier
    end subroutine fp_periodic_knot_checks

    pure subroutine fpknot(x, m, t, n, fpint, nrdata, nrint, nest, istart)
      import :: real64
      integer, intent(in) :: m, nest, istart
      real(real64), intent(in) :: x(m)
      real(real64), intent(inout) :: t(nest), fpint(nest)
      integer, intent(inout) :: n, nrdata(nest), nrint
    end subroutine fpknot

    !> All derivatives d(1..k1) (d(j) = (j-1)-th derivative) at x, t(l) <= x < t(l+1).
    pure subroutine fpader(t, n, c, k1, x, l, d)
      import :: real64
      integer, intent(in) :: n, k1, l
      real(real64), intent(in) :: t(n), c(n), x
      real(real64), intent(out) :: d(k1)
    end subroutine fpader

    pure subroutine fpinst(iopt, t, n, c, k, x, l, tt, nn, cc, nest)
      import :: real64
      integer, intent(in) :: iopt, n, k, l, nest
      real(real64), intent(in) :: t(nest), c(nest), x
      integer, intent(out) :: nn
      real(real64), intent(out) :: tt(nest), cc(nest)
    end subroutine fpinst

    pure subroutine fpintb(t, n, bint, nk1, x, y)
      import :: real64
      integer, intent(in) :: n, nk1
      real(real64), intent(in) :: t(n), x, y
      real(real64), intent(out) :: bint(nk1)
    end subroutine fpintb

    pure subroutine fpcuro(a, b, c, d, x, n)
      import :: real64
      real(real64), intent(in) :: a, b, c, d
      real(real64), intent(out) :: x(3)
      integer, intent(out) :: n
    end subroutine fpcuro

    subroutine curfit(iopt, m, x, y, w, xb, xe, k, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
      import :: real64
      integer, intent(in) :: iopt, m, k, nest, lwrk
      real(real64), intent(in) :: x(m), y(m), w(m), xb, xe, s
      integer, intent(inout) :: n, iwrk(nest)
      real(real64), intent(inout) :: t(nest), c(nest), fp, wrk(lwrk)
      integer, intent(out) :: ier
    end subroutine curfit

    subroutine percur(iopt, m, x, y, w, k, s, nest, n, t, c, fp, wrk, lwrk, iwrk, ier)
      import :: real64
      integer, intent(in) :: iopt, m, k, nest, lwrk
      real(real64), intent(in) :: x(m), y(m), w(m), s
      integer, intent(inout) :: n, iwrk(nest)
      real(real64), intent(inout) :: t(nest), c(nest), fp, wrk(lwrk)
      integer, intent(out) :: ier
    end subroutine percur

    subroutine parcur(iopt, ipar, idim, m, u, mx, x, w, ub, ue, k, s, nest, n, t, nc, c, fp, &
                      wrk, lwrk, iwrk, ier)
      import :: real64
      integer, intent(in) :: iopt, ipar, idim, m, mx, k, nest, nc, lwrk
      real(real64), intent(inout) :: u(m), ub, ue
      real(real64), intent(in) :: x(mx), w(m), s
      integer, intent(inout) :: n, iwrk(nest)
      real(real64), intent(inout) :: t(nest), c(nc), fp, wrk(lwrk)
      integer, intent(out) :: ier
    end subroutine parcur

    subroutine clocur(iopt, ipar, idim, m, u, mx, x, w, k, s, nest, n, t, nc, c, fp, &
                      wrk, lwrk, iwrk, ier)
      import :: real64
      integer, intent(in) :: iopt, ipar, idim, m, mx, k, nest, nc, lwrk
      real(real64), intent(inout) :: u(m)
      real(real64), intent(in) :: x(mx), w(m), s
      integer, intent(inout) :: n, iwrk(nest)
      real(real64), intent(inout) :: t(nest), c(nc), fp, wrk(lwrk)
      integer, intent(out) :: ier
    end subroutine clocur

    subroutine concur(iopt, idim, m, u, mx, x, xx, w, ib, db, nb, ie, de, ne, k, s, nest, n, t, &
                      nc, c, np, cp, fp, wrk, lwrk, iwrk, ier)
      import :: real64
      integer, intent(in) :: iopt, idim, m, mx, ib, nb, ie, ne, k, nest, nc, np, lwrk
      real(real64), intent(in) :: u(m), x(mx), w(m), db(nb), de(ne), s
      real(real64), intent(inout) :: xx(mx)
      integer, intent(inout) :: n, iwrk(nest)
      real(real64), intent(inout) :: t(nest), c(nc), cp(np), fp, wrk(lwrk)
      integer, intent(out) :: ier
    end subroutine concur

    pure subroutine splev(t, n, c, k, x, y, m, ier)
      import :: real64
      integer, intent(in) :: n, k, m
      real(real64), intent(in) :: t(n), c(n), x(m)
      real(real64), intent(out) :: y(m)
      integer, intent(out) :: ier
    end subroutine splev

    pure subroutine splder(t, n, c, k, nu, x, y, m, wrk, ier)
      import :: real64
      integer, intent(in) :: n, k, nu, m
      real(real64), intent(in) :: t(n), c(n), x(m)
      real(real64), intent(out) :: y(m), wrk(n)
      integer, intent(out) :: ier
    end subroutine splder

    pure subroutine curev(idim, t, n, c, nc, k, u, m, x, mx, ier)
      import :: real64
      integer, intent(in) :: idim, n, nc, k, m, mx
      real(real64), intent(in) :: t(n), c(nc), u(m)
      real(real64), intent(out) :: x(mx)
      integer, intent(out) :: ier
    end subroutine curev

    pure subroutine cualde(idim, t, n, c, nc, k1, u, d, nd, ier)
      import :: real64
      integer, intent(in) :: idim, n, nc, k1, nd
      real(real64), intent(in) :: t(n), c(nc), u
      real(real64), intent(out) :: d(nd)
      integer, intent(out) :: ier
    end subroutine cualde

    pure subroutine spalde(t, n, c, k1, x, d, ier)
      import :: real64
      integer, intent(in) :: n, k1
      real(real64), intent(in) :: t(n), c(n), x
      real(real64), intent(out) :: d(k1)
      integer, intent(out) :: ier
    end subroutine spalde

    pure subroutine insert(iopt, t, n, c, k, x, tt, nn, cc, nest, ier)
      import :: real64
      integer, intent(in) :: iopt, n, k, nest
      real(real64), intent(in) :: t(nest), c(nest), x
      integer, intent(out) :: nn, ier
      real(real64), intent(out) :: tt(nest), cc(nest)
    end subroutine insert

    function splint(t, n, c, k, a, b, wrk) result(integral)
      import :: real64
      integer, intent(in) :: n, k
      real(real64), intent(in) :: t(n), c(n), a, b
      real(real64), intent(out) :: wrk(n)
      real(real64) :: integral
    end function splint

    pure subroutine sproot(t, n, c, zero, mest, m, ier)
      import :: real64
      integer, intent(in) :: n, mest
      real(real64), intent(in) :: t(n), c(n)
      real(real64), intent(out) :: zero(mest)
      integer, intent(out) :: m, ier
    end subroutine sproot
  end interface
end module fitpack_interfaces
