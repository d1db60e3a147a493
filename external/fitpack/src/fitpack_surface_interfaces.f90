!> Explicit interfaces of our FITPACK surface routines (external subroutines
!> with Dierckx's original names and calling sequences; every real is real64).
!> Public: surfit, regrid, parsur, bispev, parder, surev and the helpers they
!> share. The curve routines and common kernels are in fitpack_interfaces.
module fitpack_surface_interfaces
  implicit none (type, external)
  private
  public :: bispev, parder, fpbisp
  public :: regrid, fpregr, fpgrre
  public :: surfit, fpsurf, fporde, fprank
  public :: parsur, fppasu, fpgrpa, surev, fpsuev
  public :: fp_grid_knots_to_add, fp_grid_add_first

  interface
    subroutine bispev(tx, nx, ty, ny, c, kx, ky, x, mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: nx, ny, kx, ky, mx, my, lwrk, kwrk
      real(real64), intent(in) :: tx(nx), ty(ny), c((nx - kx - 1)*(ny - ky - 1)), x(mx), y(my)
      real(real64), intent(out) :: z(mx*my)
      real(real64), intent(inout) :: wrk(lwrk)
      integer, intent(inout) :: iwrk(kwrk)
      integer, intent(out) :: ier
    end subroutine bispev

    subroutine parder(tx, nx, ty, ny, c, kx, ky, nux, nuy, x, mx, y, my, z, wrk, lwrk, iwrk, kwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: nx, ny, kx, ky, nux, nuy, mx, my, lwrk, kwrk
      real(real64), intent(in) :: tx(nx), ty(ny), c((nx - kx - 1)*(ny - ky - 1)), x(mx), y(my)
      real(real64), intent(out) :: z(mx*my)
      real(real64), intent(inout) :: wrk(lwrk)
      integer, intent(inout) :: iwrk(kwrk)
      integer, intent(out) :: ier
    end subroutine parder

    pure subroutine fpbisp(tx, nx, ty, ny, c, kx, ky, x, mx, y, my, z, wx, wy, lx, ly)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: nx, ny, kx, ky, mx, my
      real(real64), intent(in) :: tx(nx), ty(ny), c((nx - kx - 1)*(ny - ky - 1)), x(mx), y(my)
      real(real64), intent(out) :: z(mx*my), wx(mx, kx + 1), wy(my, ky + 1)
      integer, intent(out) :: lx(mx), ly(my)
    end subroutine fpbisp

    subroutine regrid(iopt, mx, x, my, y, z, xb, xe, yb, ye, kx, ky, s, nxest, nyest, nx, tx, ny, ty, &
                      c, fp, wrk, lwrk, iwrk, kwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: iopt, mx, my, kx, ky, nxest, nyest, lwrk, kwrk
      real(real64), intent(in) :: x(mx), y(my), z(mx*my), xb, xe, yb, ye, s
      integer, intent(inout) :: nx, ny
      real(real64), intent(inout) :: tx(nxest), ty(nyest)
      real(real64), intent(inout) :: c((nxest - kx - 1)*(nyest - ky - 1))
      real(real64), intent(out) :: fp
      real(real64), intent(inout) :: wrk(lwrk)
      integer, intent(inout) :: iwrk(kwrk)
      integer, intent(out) :: ier
    end subroutine regrid

    subroutine fpregr(iopt, x, mx, y, my, z, mz, xb, xe, yb, ye, kx, ky, s, nxest, nyest, tol, maxit, &
                      nx, tx, ny, ty, c, fp, fp0, fpold, reducx, reducy, fpintx, fpinty, &
                      lastdi, nplusx, nplusy, nrx, nry, nrdatx, nrdaty, wrk, lwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: iopt, mx, my, mz, kx, ky, nxest, nyest, maxit, lwrk
      real(real64), intent(in) :: x(mx), y(my), z(mz), xb, xe, yb, ye, s, tol
      integer, intent(inout) :: nx, ny, lastdi, nplusx, nplusy, nrx(mx), nry(my), nrdatx(nxest), nrdaty(nyest)
      real(real64), intent(inout) :: tx(nxest), ty(nyest), c((nxest - kx - 1)*(nyest - ky - 1))
      real(real64), intent(inout) :: fp, fp0, fpold, reducx, reducy, fpintx(nxest), fpinty(nyest)
      real(real64), intent(inout) :: wrk(lwrk)
      integer, intent(inout) :: ier
    end subroutine fpregr

    subroutine fpgrre(ifsx, ifsy, ifbx, ifby, x, mx, y, my, z, mz, kx, ky, tx, nx, ty, ny, p, c, fp, &
                      fpx, fpy, spx, spy, right, q, ax, ay, bx, by, nrx, nry)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(inout) :: ifsx, ifsy, ifbx, ifby
      integer, intent(in) :: mx, my, mz, kx, ky, nx, ny
      real(real64), intent(in) :: x(mx), y(my), z(mz), tx(nx), ty(ny), p
      real(real64), intent(inout) :: c(*)
      real(real64), intent(out) :: fp
      real(real64), intent(inout) :: fpx(nx), fpy(ny), spx(mx, kx + 1), spy(my, ky + 1), right(*), q(*)
      real(real64), intent(inout) :: ax(nx, kx + 2), ay(ny, ky + 2), bx(nx, kx + 2), by(ny, ky + 2)
      integer, intent(inout) :: nrx(mx), nry(my)
    end subroutine fpgrre

    subroutine surfit(iopt, m, x, y, z, w, xb, xe, yb, ye, kx, ky, s, nxest, nyest, nmax, eps, nx, tx, &
                      ny, ty, c, fp, wrk1, lwrk1, wrk2, lwrk2, iwrk, kwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: iopt, m, kx, ky, nxest, nyest, nmax, lwrk1, lwrk2, kwrk
      real(real64), intent(in) :: x(m), y(m), z(m), w(m), xb, xe, yb, ye, s, eps
      integer, intent(inout) :: nx, ny
      real(real64), intent(inout) :: tx(nmax), ty(nmax)
      real(real64), intent(inout) :: c((nxest - kx - 1)*(nyest - ky - 1))
      real(real64), intent(out) :: fp
      real(real64), intent(inout) :: wrk1(lwrk1), wrk2(lwrk2)
      integer, intent(inout) :: iwrk(kwrk)
      integer, intent(out) :: ier
    end subroutine surfit

    subroutine fpsurf(iopt, m, x, y, z, w, xb, xe, yb, ye, kxx, kyy, s, nxest, nyest, eta, tol, maxit, &
                      nmax, nx0, tx, ny0, ty, c, fp, fp0, wrk, lwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: iopt, m, kxx, kyy, nxest, nyest, maxit, nmax, lwrk
      real(real64), intent(in) :: x(m), y(m), z(m), w(m), xb, xe, yb, ye, s, eta, tol
      integer, intent(inout) :: nx0, ny0
      real(real64), intent(inout) :: tx(nmax), ty(nmax), c(*)
      real(real64), intent(out) :: fp
      real(real64), intent(inout) :: fp0, wrk(lwrk)
      integer, intent(inout) :: ier
    end subroutine fpsurf

    pure subroutine fporde(x, y, m, kx, ky, tx, nx, ty, ny, nummer, index, nreg)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: m, kx, ky, nx, ny, nreg
      real(real64), intent(in) :: x(m), y(m), tx(nx), ty(ny)
      integer, intent(out) :: nummer(m), index(nreg)
    end subroutine fporde

    pure subroutine fprank(a, f, n, m, na, tol, c, sq, rank, aa, ff, h)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: n, m, na
      real(real64), intent(inout) :: a(na, m), f(n)
      real(real64), intent(in) :: tol
      real(real64), intent(out) :: c(n), sq
      integer, intent(out) :: rank
      real(real64), intent(out) :: aa(n, m), ff(n), h(m)
    end subroutine fprank

    subroutine parsur(iopt, ipar, idim, mu, u, mv, v, f, s, nuest, nvest, nu, tu, nv, tv, c, fp, wrk, lwrk, &
                      iwrk, kwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: iopt, ipar(2), idim, mu, mv, nuest, nvest, lwrk, kwrk
      real(real64), intent(in) :: u(mu), v(mv), f(mu*mv*idim), s
      integer, intent(inout) :: nu, nv
      real(real64), intent(inout) :: tu(nuest), tv(nvest), c((nuest - 4)*(nvest - 4)*idim)
      real(real64), intent(out) :: fp
      real(real64), intent(inout) :: wrk(lwrk)
      integer, intent(inout) :: iwrk(kwrk)
      integer, intent(out) :: ier
    end subroutine parsur

    subroutine fppasu(iopt, ipar, idim, u, mu, v, mv, f, s, nuest, nvest, tol, maxit, nu, tu, nv, tv, c, fp, &
                      fp0, fpold, reducu, reducv, fpintu, fpintv, lastdi, nplusu, nplusv, nru, nrv, &
                      nrdatu, nrdatv, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: iopt, ipar(2), idim, mu, mv, nuest, nvest, maxit
      real(real64), intent(in) :: u(mu), v(mv), f(mu*mv*idim), s, tol
      integer, intent(inout) :: nu, nv, lastdi, nplusu, nplusv, nru(mu), nrv(mv), nrdatu(nuest), nrdatv(nvest)
      real(real64), intent(inout) :: tu(nuest), tv(nvest), c((nuest - 4)*(nvest - 4)*idim)
      real(real64), intent(inout) :: fp, fp0, fpold, reducu, reducv, fpintu(nuest), fpintv(nvest)
      integer, intent(inout) :: ier
    end subroutine fppasu

    subroutine fpgrpa(ipar, idim, u, mu, v, mv, f, tu, nu, tv, nv, p, c, fp, fpintu, fpintv, nru, nrv)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: ipar(2), idim, mu, mv, nu, nv
      real(real64), intent(in) :: u(mu), v(mv), f(mu*mv*idim), tu(nu), tv(nv), p
      real(real64), intent(inout) :: c(*)
      real(real64), intent(out) :: fp
      real(real64), intent(inout) :: fpintu(nu), fpintv(nv)
      integer, intent(inout) :: nru(mu), nrv(mv)
    end subroutine fpgrpa

    subroutine surev(idim, tu, nu, tv, nv, c, u, mu, v, mv, f, mf, wrk, lwrk, iwrk, kwrk, ier)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: idim, nu, nv, mu, mv, mf, lwrk, kwrk
      real(real64), intent(in) :: tu(nu), tv(nv), c((nu - 4)*(nv - 4)*idim), u(mu), v(mv)
      real(real64), intent(out) :: f(mf)
      real(real64), intent(inout) :: wrk(lwrk)
      integer, intent(inout) :: iwrk(kwrk)
      integer, intent(out) :: ier
    end subroutine surev

    pure subroutine fpsuev(idim, tu, nu, tv, nv, c, u, mu, v, mv, f, wu, wv, lu, lv)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: idim, nu, nv, mu, mv
      real(real64), intent(in) :: tu(nu), tv(nv), c((nu - 4)*(nv - 4)*idim), u(mu), v(mv)
      real(real64), intent(out) :: f(mu*mv*idim), wu(mu, 4), wv(mv, 4)
      integer, intent(out) :: lu(mu), lv(mv)
    end subroutine fpsuev

    pure function fp_grid_knots_to_add(nplus, reduc, fpms, acc) result(npl)
      use, intrinsic :: iso_fortran_env, only: real64
      implicit none
      integer, intent(in) :: nplus
      real(real64), intent(in) :: reduc, fpms, acc
      integer :: npl
    end function fp_grid_knots_to_add

    pure function fp_grid_add_first(npl_first, npl_second, lastdi, first_full, second_full) result(first)
      implicit none
      integer, intent(in) :: npl_first, npl_second, lastdi
      logical, intent(in) :: first_full, second_full
      logical :: first
    end function fp_grid_add_first
  end interface
end module fitpack_surface_interfaces
