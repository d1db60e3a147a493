!> numerics_spline_surface: fits from scattered data, a grid and a parametric
!> grid; one-call evaluation of the value and all partials to third order,
!> checked against FITPACK's own evaluators (bispev, parder, surev) and against
!> central differences at scattered points; the thesis's paraboloids
!> (section 3.5.3.3); statuses for invalid input and points outside;
!> evaluate_grid against evaluate point by point (degrees 1..5, parametric,
!> grids through knots and domain ends).
program test_spline_surface
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_OK, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use numerics_spline_surface, only: spline_surface_t, spline_surface_eval_t, fit_scattered, fit_grid, &
    fit_parametric
  use fitpack_surface_interfaces, only: bispev, parder
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  call scattered_surface()
  call grid_surface()
  call parametric_tube()
  call thesis_paraboloids()
  call failures_as_statuses()
  call grid_equals_pointwise()
  call finish_tests('test_spline_surface')

contains

  !> Deterministic points in [0,1]^2 (a 2-D Halton sequence).
  pure function halton(i, base) result(h)
    integer, intent(in) :: i, base
    real(wp) :: h, f
    integer :: n
    h = 0
    f = 1
    n = i
    do while (n > 0)
      f = f/base
      h = h + f*mod(n, base)
      n = n/base
    end do
  end function halton

  !> The ten partials (order a in u, b in v) of an evaluation record, coordinate l.
  pure real(wp) function partial(p, a, b, l)
    type(spline_surface_eval_t), intent(in) :: p
    integer, intent(in) :: a, b, l
    select case (10*a + b)
    case (0); partial = p%f(l)
    case (10); partial = p%fu(l)
    case (1); partial = p%fv(l)
    case (20); partial = p%fuu(l)
    case (11); partial = p%fuv(l)
    case (2); partial = p%fvv(l)
    case (30); partial = p%fuuu(l)
    case (21); partial = p%fuuv(l)
    case (12); partial = p%fuvv(l)
    case (3); partial = p%fvvv(l)
    case default; partial = 0
    end select
  end function partial

  !> Each partial of order 1..3 against the central difference of the partial
  !> one order lower, at points at least 2h away from every knot (where the
  !> differenced partial is smooth). Error: h^2/6 |next derivative| plus
  !> rounding eps |f|/h; with h = 1e-5 of the domain both stay below 1e-7 of
  !> the partial's scale, so tol = 1e-6 * scale.
  subroutine check_partials_fd(surf, what, npts)
    type(spline_surface_t), intent(in) :: surf
    character(len=*), intent(in) :: what
    integer, intent(in) :: npts
    type(spline_surface_eval_t) :: p0, pp, pm
    type(status_t) :: st
    real(wp) :: box(4), u, v, h(2), fd, scale(0:3, 0:3)
    real(wp), allocatable :: tu(:), tv(:)
    integer :: i, a, b, l, dir, tested, k
    logical :: same
    character(len=80) :: label
    box = surf%domain()
    tu = surf%knots_u()
    tv = surf%knots_v()
    h = 1.0e-5_wp*[box(2) - box(1), box(4) - box(3)]
    ! scale of each partial over the test points
    scale = 0
    do i = 1, npts
      u = box(1) + (box(2) - box(1))*(0.02_wp + 0.96_wp*halton(i, 2))
      v = box(3) + (box(4) - box(3))*(0.02_wp + 0.96_wp*halton(i, 3))
      call surf%evaluate(u, v, p0, st)
      do a = 0, 3
        do b = 0, 3 - a
          do l = 1, surf%dimension()
            scale(a, b) = max(scale(a, b), abs(partial(p0, a, b, l)))
          end do
        end do
      end do
    end do
    tested = 0
    do i = 1, npts
      u = box(1) + (box(2) - box(1))*(0.02_wp + 0.96_wp*halton(i, 2))
      v = box(3) + (box(4) - box(3))*(0.02_wp + 0.96_wp*halton(i, 3))
      if (minval(abs(tu - u)) < 2*h(1) .or. minval(abs(tv - v)) < 2*h(2)) cycle
      tested = tested + 1
      call surf%evaluate(u, v, p0, st)
      call check(st%ok(), what//': evaluate status')
      ! order 0..2: the partials up to that order to the last bit, the others zero
      do k = 0, 2
        call surf%evaluate(u, v, pp, st, order=k)
        same = st%ok()
        do a = 0, 3
          do b = 0, 3 - a
            do l = 1, surf%dimension()
              if (a + b <= k) then
                same = same .and. partial(pp, a, b, l) == partial(p0, a, b, l)
              else
                same = same .and. partial(pp, a, b, l) == 0
              end if
            end do
          end do
        end do
        write (label, '(a, ": evaluate to order ", i0, " point ", i0)') what, k, i
        call check(same, trim(label))
      end do
      do a = 0, 3
        do b = 0, 3 - a
          if (a + b == 0) cycle
          ! difference along u if a > 0, else along v
          dir = merge(1, 2, a > 0)
          if (dir == 1) then
            call surf%evaluate(u + h(1), v, pp, st)
            call surf%evaluate(u - h(1), v, pm, st)
          else
            call surf%evaluate(u, v + h(2), pp, st)
            call surf%evaluate(u, v - h(2), pm, st)
          end if
          do l = 1, surf%dimension()
            if (dir == 1) then
              fd = (partial(pp, a - 1, b, l) - partial(pm, a - 1, b, l))/(2*h(1))
            else
              fd = (partial(pp, a, b - 1, l) - partial(pm, a, b - 1, l))/(2*h(2))
            end if
            write (label, '(a, ": d", i0, i0, " coordinate ", i0, " point ", i0)') what, a, b, l, i
            call check_close(partial(p0, a, b, l), fd, 0.0_wp, 1.0e-6_wp*max(scale(a, b), 1.0_wp), trim(label))
          end do
        end do
      end do
    end do
    call check(tested >= npts/2, what//': enough points away from knots')
  end subroutine check_partials_fd

  !> The record's value and partials against FITPACK's bispev/parder on the
  !> same knots and coefficients (orders below the degree: parder needs
  !> nux < kx), at scattered points: same B-splines by another recurrence,
  !> rounding only, 1e-11 of the partial's scale.
  subroutine check_against_parder(surf, what)
    type(spline_surface_t), intent(in) :: surf
    character(len=*), intent(in) :: what
    type(spline_surface_eval_t) :: p
    type(status_t) :: st
    real(wp), allocatable :: tx(:), ty(:), c3(:, :, :), c(:)
    real(wp) :: box(4), x, y, z(1), wrk(2000), scale
    integer :: iwrk(10), ier, k(2), a, b, i, ncx, ncy, ix, iy
    character(len=64) :: label
    box = surf%domain()
    tx = surf%knots_u()
    ty = surf%knots_v()
    k = surf%degrees()
    c3 = surf%coefficients()
    ncx = size(c3, 1)
    ncy = size(c3, 2)
    call check(ncx == size(tx) - k(1) - 1 .and. ncy == size(ty) - k(2) - 1, what//': coefficient shape')
    allocate (c(ncx*ncy))
    do ix = 1, ncx
      do iy = 1, ncy
        c(ncy*(ix - 1) + iy) = c3(ix, iy, 1)
      end do
    end do
    scale = maxval(abs(c))
    do i = 1, 7
      x = box(1) + (box(2) - box(1))*halton(i + 3, 2)
      y = box(3) + (box(4) - box(3))*halton(i + 3, 3)
      call surf%evaluate(x, y, p, st)
      call check(st%code == STATUS_OK, what//': status')
      call bispev(tx, size(tx), ty, size(ty), c, k(1), k(2), [x], 1, [y], 1, z, wrk, 2000, iwrk, 10, ier)
      call check(ier == 0, what//': bispev ier')
      call check_close(p%f(1), z(1), 0.0_wp, 1.0e-12_wp*scale, what//': value = bispev')
      do a = 0, min(3, k(1) - 1)
        do b = 0, min(3 - a, k(2) - 1)
          if (a + b == 0) cycle
          call parder(tx, size(tx), ty, size(ty), c, k(1), k(2), a, b, [x], 1, [y], 1, z, wrk, 2000, iwrk, &
            10, ier)
          write (label, '(a, i0, i0)') ': partial = parder ', a, b
          call check(ier == 0, what//trim(label)//' ier')
          ! derivative coefficients grow like (degree / knot spacing)^order
          call check_close(partial(p, a, b, 1), z(1), 0.0_wp, &
            1.0e-11_wp*scale*(k(1)*(size(tx) - 2*k(1)))**a*(k(2)*(size(ty) - 2*k(2)))**b/ &
            ((box(2) - box(1))**a*(box(4) - box(3))**b), what//trim(label))
        end do
      end do
    end do
  end subroutine check_against_parder

  subroutine scattered_surface()
    integer, parameter :: m = 150
    real(wp) :: x(m), y(m), z(m)
    type(spline_surface_t) :: surf
    type(status_t) :: st
    type(spline_surface_eval_t) :: p
    integer :: i
    real(wp) :: box(4), err
    do i = 1, m
      x(i) = halton(i, 2)
      y(i) = halton(i, 3)
      z(i) = sin(3*x(i))*cos(2*y(i)) + 0.5_wp*x(i)*y(i) + 0.01_wp*sin(97.0_wp*i)
    end do
    surf = fit_scattered(x, y, z, 0.015_wp, 3, 3, st)
    call check(st%ok(), 'scattered: fit status ok: '//st%text())
    if (.not. st%ok()) return
    call check(surf%dimension() == 1, 'scattered: scalar surface')
    call check(abs(surf%residual() - 0.015_wp) <= 0.001_wp*0.015_wp, 'scattered: fp within 0.1 % of s')
    box = surf%domain()
    call check(all(abs(box - [minval(x), maxval(x), minval(y), maxval(y)]) == 0), 'scattered: domain is the data box')
    ! residual sum recomputed from the evaluations equals FITPACK's fp (1e-10:
    ! sums of 150 squares of rounding-level differences)
    err = 0
    do i = 1, m
      call surf%evaluate(x(i), y(i), p, st)
      err = err + (z(i) - p%f(1))**2
    end do
    call check_close(err, surf%residual(), 1.0e-10_wp, 0.0_wp, 'scattered: fp from evaluations')
    call check_values_bispev(surf, 'scattered')
    call check_partials_fd(surf, 'scattered bicubic', 40)
    ! weights and bbox, quintic in x, quadratic in y
    surf = fit_scattered(x, y, z, 0.02_wp, 5, 2, st, weights=[(1.0_wp + 0.5_wp*halton(i, 5), i = 1, m)], &
      bbox=[-0.1_wp, 1.1_wp, -0.05_wp, 1.0_wp])
    call check(st%ok(), 'scattered k=(5,2): fit status ok: '//st%text())
    if (.not. st%ok()) return
    call check(all(surf%domain() == [-0.1_wp, 1.1_wp, -0.05_wp, 1.0_wp]), 'scattered k=(5,2): domain is the bbox')
    call check_values_bispev(surf, 'scattered k=(5,2)')
    call check_partials_fd(surf, 'scattered k=(5,2)', 40)
  end subroutine scattered_surface

  subroutine check_values_bispev(surf, what)
    type(spline_surface_t), intent(in) :: surf
    character(len=*), intent(in) :: what
    call check_against_parder(surf, what)
  end subroutine check_values_bispev

  subroutine grid_surface()
    integer, parameter :: mx = 12, my = 10
    real(wp) :: x(mx), y(my), z(mx, my)
    type(spline_surface_t) :: surf
    type(status_t) :: st
    type(spline_surface_eval_t) :: p
    integer :: i, j
    real(wp) :: err
    x = [(real(i - 1, wp)/(mx - 1), i = 1, mx)]
    y = [(2*real(j - 1, wp)/(my - 1), j = 1, my)]
    do i = 1, mx
      do j = 1, my
        z(i, j) = exp(-x(i))*sin(2*y(j)) + x(i)**2
      end do
    end do
    ! interpolation (s = 0) with degree 5: third partials are meaningful
    surf = fit_grid(x, y, z, 0.0_wp, 5, 5, st)
    call check(st%ok(), 'grid: fit status ok: '//st%text())
    if (.not. st%ok()) return
    call check(surf%fitpack_ier() == -1, 'grid s=0: interpolating spline (ier = -1)')
    err = 0
    do i = 1, mx
      do j = 1, my
        call surf%evaluate(x(i), y(j), p, st)
        err = max(err, abs(p%f(1) - z(i, j)))
      end do
    end do
    ! interpolation conditions hold to rounding of the solve
    call check(err <= 1.0e-12_wp, 'grid s=0: interpolates the grid')
    call check_values_bispev(surf, 'grid quintic')
    call check_grid_evaluation(surf, 'grid quintic')
    call check_partials_fd(surf, 'grid quintic', 40)
    ! smoothing, bicubic
    surf = fit_grid(x, y, z + 0.01_wp*sin(31.0_wp*spread(x, 2, my) + 17.0_wp*spread(y, 1, mx)), 0.005_wp, 3, 3, st)
    call check(st%ok(), 'grid smoothing: status ok: '//st%text())
    if (st%ok()) then
      call check(abs(surf%residual() - 0.005_wp) <= 0.001_wp*0.005_wp, 'grid smoothing: fp within 0.1 % of s')
      call check_partials_fd(surf, 'grid bicubic', 40)
    end if
  end subroutine grid_surface

  !> A closed tube, periodic in u: wrap-around, C^2 at the seam and partials.
  subroutine parametric_tube()
    integer, parameter :: mu = 21, mv = 9
    real(wp) :: u(mu), v(mv), pts(3, mu, mv), a
    type(spline_surface_t) :: surf
    type(status_t) :: st
    type(spline_surface_eval_t) :: p, q
    integer :: i, j, l
    real(wp) :: box(4), err
    u = [(real(i - 1, wp)/(mu - 1), i = 1, mu)]
    v = [(real(j - 1, wp)/(mv - 1), j = 1, mv)]
    do i = 1, mu
      do j = 1, mv
        a = 2*pi*u(i)
        pts(:, i, j) = [(1 + 0.3_wp*v(j))*cos(a), (1 + 0.3_wp*v(j))*sin(a) + 0.1_wp*sin(2*a), 2*v(j)]
      end do
    end do
    surf = fit_parametric(u, v, pts, 0.0_wp, [.true., .false.], st)
    call check(st%ok(), 'tube: fit status ok: '//st%text())
    if (.not. st%ok()) return
    call check(surf%dimension() == 3, 'tube: three coordinates')
    box = surf%domain()
    call check(all(box == [0.0_wp, 1.0_wp, 0.0_wp, 1.0_wp]), 'tube: domain')
    err = 0
    do i = 1, mu
      do j = 1, mv
        call surf%evaluate(u(i), v(j), p, st)
        err = max(err, maxval(abs(p%f - pts(:, i, j))))
      end do
    end do
    call check(err <= 1.0e-12_wp, 'tube s=0: interpolates the points')
    ! periodic in u: evaluation at u and u + 1 agree (wrap, no domain status);
    ! at the seam from both sides value and first two u-partials agree (C^2)
    call surf%evaluate(0.3_wp, 0.4_wp, p, st)
    call surf%evaluate(1.3_wp, 0.4_wp, q, st)
    call check(st%ok(), 'tube: u beyond the period wraps without a status')
    call check(maxval(abs(p%f - q%f)) + maxval(abs(p%fuuu - q%fuuu)) <= 1.0e-12_wp, 'tube: periodic wrap')
    call surf%evaluate(1.0e-9_wp, 0.6_wp, p, st)
    call surf%evaluate(1.0_wp - 1.0e-9_wp, 0.6_wp, q, st)
    do l = 1, 3
      ! 1e-9 apart: values differ by |r_u| 2e-9, u-partials by |r_uuu| 2e-9
      call check_close(p%f(l), q%f(l), 0.0_wp, 1.0e-7_wp, 'tube: C0 at the seam')
      call check_close(p%fu(l), q%fu(l), 0.0_wp, 1.0e-6_wp, 'tube: C1 at the seam')
      call check_close(p%fuu(l), q%fuu(l), 0.0_wp, 1.0e-5_wp, 'tube: C2 at the seam')
    end do
    call check_partials_fd(surf, 'tube', 40)
    call check_grid_evaluation(surf, 'tube')
  end subroutine parametric_tube

  !> evaluate_grid equals evaluate point by point (same sums in the same
  !> order: equal to the last bit, checked to 1e-15 of the scale).
  subroutine check_grid_evaluation(surf, what)
    type(spline_surface_t), intent(in) :: surf
    character(len=*), intent(in) :: what
    type(spline_surface_eval_t) :: pg(7, 5), p
    type(status_t) :: st
    real(wp) :: box(4), u(7), v(5), err, scale
    integer :: i, j, a, b, l
    box = surf%domain()
    u = box(1) + (box(2) - box(1))*[(halton(i, 5), i = 1, 7)]
    v = box(3) + (box(4) - box(3))*[(halton(j, 7), j = 1, 5)]
    call surf%evaluate_grid(u, v, pg, st)
    call check(st%ok(), what//': evaluate_grid status')
    err = 0
    scale = 0
    do i = 1, 7
      do j = 1, 5
        call surf%evaluate(u(i), v(j), p, st)
        do a = 0, 3
          do b = 0, 3 - a
            do l = 1, surf%dimension()
              err = max(err, abs(partial(pg(i, j), a, b, l) - partial(p, a, b, l)))
              scale = max(scale, abs(partial(p, a, b, l)))
            end do
          end do
        end do
      end do
    end do
    call check(err <= 1.0e-15_wp*scale, what//': evaluate_grid equals evaluate')
    call surf%evaluate_grid(u, [v, box(4) + 1], pg(:, 1:6 - 1), st)
    call check(st%code == STATUS_INVALID_INPUT, what//': evaluate_grid rejects a wrong shape')
  end subroutine check_grid_evaluation

  !> evaluate_grid against evaluate point by point for degrees (kx, ky) across
  !> 1..5 (scalar, fit_grid) and bicubic parametric surfaces (fit_parametric,
  !> plain and periodic in v), on non-square grids holding the domain ends,
  !> every interior knot (where partials of order >= the degree jump, so both
  !> must choose the same knot interval) and points in between.
  subroutine grid_equals_pointwise()
    integer, parameter :: mx = 11, my = 8
    integer, parameter :: degs(2, 7) = reshape([1, 1, 1, 5, 2, 3, 3, 3, 4, 2, 5, 1, 5, 5], [2, 7])
    real(wp) :: x(mx), y(my), z(mx, my), pts(3, mx, my), a
    type(spline_surface_t) :: surf
    type(status_t) :: st
    integer :: i, j, k
    character(len=40) :: tag
    ! uneven data spacing: uneven knots
    x = [(real(i - 1, wp)/(mx - 1) + 0.03_wp*sin(real(i, wp)), i = 1, mx)]
    x(1) = 0
    x(mx) = 1
    y = [(2*(real(j - 1, wp)/(my - 1))**1.3_wp, j = 1, my)]
    do i = 1, mx
      do j = 1, my
        z(i, j) = exp(-x(i))*sin(2*y(j)) + x(i)**2*y(j) + 0.05_wp*cos(7*x(i)*y(j))
      end do
    end do
    do k = 1, size(degs, 2)
      write (tag, '(a, i0, ",", i0, a)') 'grid = pointwise, scalar k=(', degs(1, k), degs(2, k), ')'
      surf = fit_grid(x, y, z, 0.0_wp, degs(1, k), degs(2, k), st)
      call check(st%ok(), trim(tag)//': fit status ok: '//st%text())
      if (st%ok()) call compare_grid_pointwise(surf, trim(tag))
    end do
    do i = 1, mx
      do j = 1, my
        a = 2*pi*y(j)/2
        pts(:, i, j) = [(1 + 0.4_wp*x(i))*cos(a), (1 + 0.4_wp*x(i))*sin(a), 3*x(i) + 0.2_wp*sin(a)]
      end do
    end do
    surf = fit_parametric(x, y, pts, 0.0_wp, [.false., .true.], st)
    call check(st%ok(), 'grid = pointwise, parametric periodic in v: fit status ok: '//st%text())
    if (st%ok()) call compare_grid_pointwise(surf, 'grid = pointwise, parametric periodic in v')
    pts(3, :, :) = pts(3, :, :) + 0.3_wp*spread(y, 1, mx)**2
    surf = fit_parametric(x, y, pts, 0.01_wp, [.false., .false.], st)
    call check(st%ok(), 'grid = pointwise, parametric smoothing: fit status ok: '//st%text())
    if (st%ok()) call compare_grid_pointwise(surf, 'grid = pointwise, parametric smoothing')
  end subroutine grid_equals_pointwise

  !> One evaluate_grid call against evaluate at every grid point, every
  !> partial and coordinate. Both form the same sums in the same order, so
  !> they agree to the last bit; rtol 1e-13 of the partial's largest magnitude
  !> over the grid leaves room only for a compiler's different rounding (e.g.
  !> fused multiply-adds), not for a wrong term or a wrong knot interval. The
  !> records start as garbage: every component must be overwritten, the
  !> unused ones of a scalar surface with zero.
  subroutine compare_grid_pointwise(surf, what)
    type(spline_surface_t), intent(in) :: surf
    character(len=*), intent(in) :: what
    type(spline_surface_eval_t), allocatable :: pg(:, :)
    type(spline_surface_eval_t) :: p
    type(status_t) :: st
    real(wp), allocatable :: tu(:), tv(:), u(:), v(:), scale(:, :, :), err(:, :, :)
    real(wp) :: box(4), ref
    integer :: i, j, a, b, l, dim, k(2), n
    logical :: all_ok, zero_ok
    character(len=120) :: label
    box = surf%domain()
    k = surf%degrees()
    dim = surf%dimension()
    tu = surf%knots_u()
    tv = surf%knots_v()
    ! distinct knots in the domain (ends included), then points in between
    u = [tu(k(1) + 1:size(tu) - k(1)), (box(1) + (box(2) - box(1))*halton(i, 2), i = 1, 6)]
    n = 3
    if (size(tv) - 2*k(2) + n == size(u)) n = 4
    v = [tv(k(2) + 1:size(tv) - k(2)), (box(3) + (box(4) - box(3))*halton(j, 3), j = 1, n)]
    allocate (pg(size(u), size(v)), scale(0:3, 0:3, 3), err(0:3, 0:3, 3))
    do j = 1, size(v)
      do i = 1, size(u)
        pg(i, j) = garbage()
      end do
    end do
    call surf%evaluate_grid(u, v, pg, st)
    call check(st%ok(), what//': evaluate_grid status')
    scale = 0
    err = 0
    zero_ok = .true.
    do j = 1, size(v)
      do i = 1, size(u)
        call surf%evaluate(u(i), v(j), p, st)
        call check(st%ok(), what//': evaluate status')
        zero_ok = zero_ok .and. pg(i, j)%dim == dim
        do a = 0, 3
          do b = 0, 3 - a
            do l = 1, 3
              ref = partial(p, a, b, l)
              if (l > dim) then
                zero_ok = zero_ok .and. partial(pg(i, j), a, b, l) == 0
              else
                scale(a, b, l) = max(scale(a, b, l), abs(ref))
                err(a, b, l) = max(err(a, b, l), abs(partial(pg(i, j), a, b, l) - ref))
              end if
            end do
          end do
        end do
      end do
    end do
    call check(zero_ok, what//': dim recorded, unused components zero')
    all_ok = .true.
    do a = 0, 3
      do b = 0, 3 - a
        do l = 1, dim
          if (err(a, b, l) <= 1.0e-13_wp*scale(a, b, l)) cycle
          all_ok = .false.
          write (label, '(a, ": d", i0, i0, " coordinate ", i0, ": error ", es9.2, " of scale ", es9.2)') &
            what, a, b, l, err(a, b, l), scale(a, b, l)
          call check(.false., trim(label))
        end do
      end do
    end do
    call check(all_ok, what//': evaluate_grid equals evaluate to 1e-13 relative')
  end subroutine compare_grid_pointwise

  pure function garbage() result(p)
    type(spline_surface_eval_t) :: p
    p%dim = -7
    p%f = 7
    p%fu = 7
    p%fv = 7
    p%fuu = 7
    p%fuv = 7
    p%fvv = 7
    p%fuuu = 7
    p%fuuv = 7
    p%fuvv = 7
    p%fvvv = 7
  end function garbage

  !> Thesis 3.5.3.3: paraboloids (3.58) z = (u^2 + v^2)/a^2 (c = 1, a = b),
  !> a^2 = 3 on [-2, 2]^2 and a^2 = 0.5 on [-0.5, 0.5]^2, 13 x 13 points,
  !> degree 5, s = 0.05 via surfit. A paraboloid is a polynomial of degree 2:
  !> surfit's least-squares polynomial (ier = -2) reproduces it, so all
  !> partials to third order equal the analytic ones (z_u = 2u/a^2,
  !> z_uu = 2/a^2, the rest 0) to rounding: 1e-9 absolute for |z| <= 3.
  subroutine thesis_paraboloids()
    real(wp) :: x(169), y(169), z(169), a2(2), half(2), grid(13), u, v
    type(spline_surface_t) :: surf
    type(status_t) :: st
    type(spline_surface_eval_t) :: p
    integer :: k, i, j, n
    character(len=32) :: tag
    a2 = [3.0_wp, 0.5_wp]
    half = [2.0_wp, 0.5_wp]
    do k = 1, 2
      write (tag, '(a, i0)') 'thesis paraboloid ', k
      grid = [(-half(k) + 2*half(k)*(i - 1)/12.0_wp, i = 1, 13)]
      n = 0
      do i = 1, 13
        do j = 1, 13
          n = n + 1
          x(n) = grid(i)
          y(n) = grid(j)
          z(n) = (x(n)**2 + y(n)**2)/a2(k)      ! thesis (3.58)
        end do
      end do
      surf = fit_scattered(x, y, z, 0.05_wp, 5, 5, st)
      call check(st%ok(), trim(tag)//': fit status ok: '//st%text())
      if (.not. st%ok()) cycle
      call check(all(surf%degrees() == [5, 5]), trim(tag)//': degree 5')
      call check(surf%residual() <= 0.05_wp, trim(tag)//': fp <= s')
      do i = 1, 25
        u = -half(k) + 2*half(k)*halton(i, 2)
        v = -half(k) + 2*half(k)*halton(i, 3)
        call surf%evaluate(u, v, p, st)
        call check(st%ok(), trim(tag)//': evaluate status')
        call check_close(p%f(1), (u**2 + v**2)/a2(k), 0.0_wp, 1.0e-9_wp, trim(tag)//': z')
        call check_close(p%fu(1), 2*u/a2(k), 0.0_wp, 1.0e-9_wp, trim(tag)//': z_u')
        call check_close(p%fv(1), 2*v/a2(k), 0.0_wp, 1.0e-9_wp, trim(tag)//': z_v')
        call check_close(p%fuu(1), 2/a2(k), 0.0_wp, 1.0e-8_wp, trim(tag)//': z_uu')
        call check_close(p%fvv(1), 2/a2(k), 0.0_wp, 1.0e-8_wp, trim(tag)//': z_vv')
        call check_close(p%fuv(1), 0.0_wp, 0.0_wp, 1.0e-8_wp, trim(tag)//': z_uv')
        call check_close(p%fuuu(1), 0.0_wp, 0.0_wp, 1.0e-7_wp, trim(tag)//': z_uuu')
        call check_close(p%fuuv(1), 0.0_wp, 0.0_wp, 1.0e-7_wp, trim(tag)//': z_uuv')
        call check_close(p%fuvv(1), 0.0_wp, 0.0_wp, 1.0e-7_wp, trim(tag)//': z_uvv')
        call check_close(p%fvvv(1), 0.0_wp, 0.0_wp, 1.0e-7_wp, trim(tag)//': z_vvv')
      end do
    end do
  end subroutine thesis_paraboloids

  subroutine failures_as_statuses()
    real(wp) :: x(20), y(20), z(20), g(5), zz(5, 5), pts(3, 5, 5)
    type(spline_surface_t) :: surf
    type(status_t) :: st
    type(spline_surface_eval_t) :: p
    integer :: i
    x = [(halton(i, 2), i = 1, 20)]
    y = [(halton(i, 3), i = 1, 20)]
    z = x + y
    surf = fit_scattered(x, y, z, -1.0_wp, 3, 3, st)
    call check(st%code == STATUS_INVALID_INPUT, 'negative smoothing is invalid input')
    surf = fit_scattered(x, y, z, 0.1_wp, 6, 3, st)
    call check(st%code == STATUS_INVALID_INPUT, 'degree 6 is invalid input')
    surf = fit_scattered(x(1:10), y(1:10), z(1:10), 0.1_wp, 3, 3, st)
    call check(st%code == STATUS_INVALID_INPUT, 'fewer points than (kx+1)(ky+1) is invalid input')
    surf = fit_scattered(x, y, z, 0.1_wp, 3, 3, st, weights=[(0.0_wp, i = 1, 20)])
    call check(st%code == STATUS_INVALID_INPUT, 'zero weights are invalid input')
    surf = fit_scattered(x, y, z, 0.1_wp, 3, 3, st, bbox=[0.2_wp, 1.0_wp, 0.0_wp, 1.0_wp])
    call check(st%code == STATUS_INVALID_INPUT, 'points outside the bbox are invalid input')
    call check(len(st%text()) > 10, 'invalid input has a message')
    call check(.not. surf%is_fitted(), 'a failed fit leaves no surface')
    call surf%evaluate(0.5_wp, 0.5_wp, p, st)
    call check(st%code == STATUS_INVALID_INPUT, 'evaluating an unfitted surface is refused')
    g = [0.0_wp, 0.25_wp, 0.5_wp, 0.5_wp, 1.0_wp]
    zz = 1
    surf = fit_grid(g, g, zz, 0.0_wp, 3, 3, st)
    call check(st%code == STATUS_INVALID_INPUT, 'grid not strictly increasing is invalid input')
    pts = 0
    surf = fit_parametric(g, g, pts, 0.0_wp, [.false., .false.], st)
    call check(st%code == STATUS_INVALID_INPUT, 'parametric grid not increasing is invalid input')
    g = [0.0_wp, 0.25_wp, 0.5_wp, 0.75_wp, 1.0_wp]
    zz = spread(g, 2, 5)
    surf = fit_grid(g, g, zz, 0.0_wp, 3, 3, st)
    call check(st%ok(), 'small grid fit ok')
    call surf%evaluate(1.5_wp, 0.5_wp, p, st)
    call check(st%code == STATUS_DOMAIN, 'a point outside the domain gives STATUS_DOMAIN')
    call check_close(p%f(1), 1.0_wp, 0.0_wp, 1.0e-12_wp, 'outside: value at the nearest boundary point')
  end subroutine failures_as_statuses
end program test_spline_surface
