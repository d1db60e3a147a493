!> spline_surface_t%evaluate (a Taylor table per patch, Taylor shifts) against
!> an independent reference written here: the tensor product of B-splines
!> and their derivatives by the textbook recursions (de Boor, A Practical
!> Guide to Splines, IX.(15) and X.(12)), term by term, the knot spans found
!> by a linear search. Degrees (ku, kv) in 1..5 x 1..5 (fit_grid), scattered
!> fits (fit_scattered), a parametric surface periodic in u (fit_parametric),
!> every partial up to order 3, at every knot line crossing (patch corners),
!> the domain's ends, a few ulps beside the knots and random points.
program test_spline_surface_reference
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_status, only: status_t
  use numerics_spline_surface, only: spline_surface_t, spline_surface_eval_t, fit_grid, fit_scattered, &
    fit_parametric
  use bspline_reference, only: bspline, span_of
  use testing, only: check, finish_tests
  implicit none (type, external)

  real(wp) :: worst(0:3) = 0     ! largest error / scale per total order (printed)
  integer :: ku, kv

  call random_init(repeatable=.true., image_distinct=.false.)
  do ku = 1, 5
    do kv = 1, 5
      call grid_surface(ku, kv)
    end do
  end do
  call scattered_surface()
  call periodic_tube()
  print '(a, 4es10.2)', 'largest |evaluate - reference| / scale, total orders 0..3:', worst
  call finish_tests('test_spline_surface_reference')

contains

  pure real(wp) function partial(p, a, b, l)
    type(spline_surface_eval_t), intent(in) :: p
    integer, intent(in) :: a, b, l
    select case (10*a + b)
    case (0)
      partial = p%f(l)
    case (10)
      partial = p%fu(l)
    case (1)
      partial = p%fv(l)
    case (20)
      partial = p%fuu(l)
    case (11)
      partial = p%fuv(l)
    case (2)
      partial = p%fvv(l)
    case (30)
      partial = p%fuuu(l)
    case (21)
      partial = p%fuuv(l)
    case (12)
      partial = p%fuvv(l)
    case default
      partial = p%fvvv(l)
    end select
  end function partial

  !> evaluate against the reference at the points (us(i), vs(i)) inside the
  !> domain (the end of a periodic direction, too, lies in its last span),
  !> every partial of order a + b <= 3 and every component.
  subroutine compare(surf, us, vs, what)
    type(spline_surface_t), intent(in) :: surf
    real(wp), intent(in) :: us(:), vs(:)
    character(len=*), intent(in) :: what
    real(wp), allocatable :: tu(:), tv(:), c(:, :, :)
    type(spline_surface_eval_t) :: p
    type(status_t) :: st
    real(wp) :: bu(0:3, 6), bv(0:3, 6), x, y, r, scale, err, bad
    integer :: i, a, b, l, k(2), lu, lv, iu, iv
    logical :: ok
    tu = surf%knots_u()
    tv = surf%knots_v()
    c = surf%coefficients()
    k = surf%degrees()
    bad = 0
    ok = .true.
    do i = 1, size(us)
      call surf%evaluate(us(i), vs(i), p, st)
      ok = ok .and. st%ok()
      x = us(i)
      y = vs(i)
      lu = span_of(tu, k(1), x)
      lv = span_of(tv, k(2), y)
      do a = 0, 3
        do iu = 1, k(1) + 1
          bu(a, iu) = bspline(tu, lu - k(1) - 1 + iu, k(1), a, lu, x)
        end do
        do iv = 1, k(2) + 1
          bv(a, iv) = bspline(tv, lv - k(2) - 1 + iv, k(2), a, lv, y)
        end do
      end do
      do a = 0, 3
        do b = 0, 3 - a
          do l = 1, surf%dimension()
            r = 0
            scale = 0
            do iu = 1, k(1) + 1
              do iv = 1, k(2) + 1
                r = r + c(lu - k(1) - 1 + iu, lv - k(2) - 1 + iv, l)*bu(a, iu)*bv(b, iv)
                scale = scale + abs(c(lu - k(1) - 1 + iu, lv - k(2) - 1 + iv, l)*bu(a, iu)*bv(b, iv))
              end do
            end do
            ! both sides round: the Taylor shifts here, the recursion there; a
            ! few eps of the sum of the terms' sizes (scale); worst seen is
            ! printed (1.1e-14, third order), 1e-13 leaves a margin of 9
            err = abs(partial(p, a, b, l) - r)/max(scale, tiny(1.0_wp))
            worst(a + b) = max(worst(a + b), err)
            bad = max(bad, err/1e-13_wp)
          end do
        end do
      end do
    end do
    call check(ok, what//': evaluate status')
    call check(bad <= 1, what//': evaluate = reference, partials of order 0..3')
  end subroutine compare

  !> Points: every knot crossing in the domain, the domain's corners, points a
  !> few ulps beside the knots, random points.
  subroutine check_points(tu, tv, k, nrandom, us, vs)
    real(wp), intent(in) :: tu(:), tv(:)
    integer, intent(in) :: k(2), nrandom
    real(wp), allocatable, intent(out) :: us(:), vs(:)
    real(wp), allocatable :: xu(:), xv(:)
    real(wp) :: box(4), r(2)
    integer :: i, j
    box = [tu(k(1) + 1), tu(size(tu) - k(1)), tv(k(2) + 1), tv(size(tv) - k(2))]
    xu = tu(k(1) + 1:size(tu) - k(1))
    xv = tv(k(2) + 1:size(tv) - k(2))
    xu = [xu, [(nearest(xu(i), 1.0_wp), nearest(xu(i), -1.0_wp), i = 1, size(xu))]]
    xv = [xv, [(nearest(xv(i), 1.0_wp), nearest(xv(i), -1.0_wp), i = 1, size(xv))]]
    allocate (us(0), vs(0))
    do i = 1, size(xu)
      do j = 1, size(xv)
        us = [us, xu(i)]
        vs = [vs, xv(j)]
      end do
    end do
    do i = 1, nrandom
      call random_number(r)
      us = [us, box(1) + r(1)*(box(2) - box(1))]
      vs = [vs, box(3) + r(2)*(box(4) - box(3))]
    end do
    us = min(max(us, box(1)), box(2))
    vs = min(max(vs, box(3)), box(4))
  end subroutine check_points

  !> A smoothing spline of degrees (ku, kv) on a grid, values far from zero.
  subroutine grid_surface(ku, kv)
    integer, intent(in) :: ku, kv
    integer, parameter :: mx = 17, my = 14
    type(spline_surface_t) :: surf
    type(status_t) :: st
    real(wp) :: x(mx), y(my), z(mx, my)
    real(wp), allocatable :: us(:), vs(:)
    integer :: i, j
    character(len=40) :: what
    write (what, '(a, i0, a, i0, a)') 'grid, degrees (', ku, ', ', kv, ')'
    do i = 1, mx
      x(i) = -1 + 2*real(i - 1, wp)/(mx - 1) + 0.02_wp*sin(3.0_wp*i)
    end do
    do j = 1, my
      y(j) = 3*real(j - 1, wp)/(my - 1)
    end do
    do j = 1, my
      do i = 1, mx
        z(i, j) = 50 + sin(2*x(i))*cos(y(j)) + 0.3_wp*x(i)*y(j)**2
      end do
    end do
    surf = fit_grid(x, y, z, 1e-4_wp, ku, kv, st)
    call check(st%ok(), trim(what)//': fit')
    if (.not. st%ok()) return
    call check_points(surf%knots_u(), surf%knots_v(), [ku, kv], 100, us, vs)
    call compare(surf, us, vs, trim(what))
  end subroutine grid_surface

  !> A scattered-data fit of degrees (5, 5) and (3, 2).
  subroutine scattered_surface()
    integer, parameter :: m = 300
    type(spline_surface_t) :: surf
    type(status_t) :: st
    real(wp) :: x(m), y(m), z(m)
    real(wp), allocatable :: us(:), vs(:)
    integer :: k
    call random_number(x)
    call random_number(y)
    x = 4*x - 2
    y = 4*y - 2
    z = (x**2 + y**2)/3 + 0.1_wp*sin(3*x)
    do k = 3, 5, 2
      surf = fit_scattered(x, y, z, 0.01_wp, k, k - 1, st)
      call check(st%ok(), 'scattered: fit')
      if (.not. st%ok()) cycle
      call check_points(surf%knots_u(), surf%knots_v(), surf%degrees(), 100, us, vs)
      call compare(surf, us, vs, 'scattered')
    end do
  end subroutine scattered_surface

  !> A bicubic parametric tube, periodic in u (fit_parametric).
  subroutine periodic_tube()
    integer, parameter :: mu = 13, mv = 9
    type(spline_surface_t) :: surf
    type(status_t) :: st
    real(wp) :: u(mu), v(mv), pts(3, mu, mv)
    real(wp), allocatable :: us(:), vs(:)
    integer :: i, j
    do i = 1, mu
      u(i) = two_pi*real(i - 1, wp)/(mu - 1)
    end do
    do j = 1, mv
      v(j) = 2*real(j - 1, wp)/(mv - 1)
    end do
    do j = 1, mv
      do i = 1, mu
        pts(:, i, j) = [(1 + 0.1_wp*v(j))*cos(u(i)), (1 + 0.1_wp*v(j))*sin(u(i)), v(j) + 0.05_wp*sin(2*u(i))]
      end do
      pts(:, mu, j) = pts(:, 1, j)
    end do
    surf = fit_parametric(u, v, pts, 0.0_wp, [.true., .false.], st)
    call check(st%ok(), 'periodic tube: fit')
    if (.not. st%ok()) return
    call check_points(surf%knots_u(), surf%knots_v(), surf%degrees(), 100, us, vs)
    call compare(surf, us, vs, 'periodic tube')
  end subroutine periodic_tube
end program test_spline_surface_reference
