!> numerics_spline_curve: fits (parcur, clocur, concur underneath), evaluation of
!> the point and all derivatives against FITPACK's curev/cualde and central
!> differences at scattered parameters, arc length against closed forms and an
!> independent quadrature, its inverse, the thesis's fig. 2.4 basis, and
!> failures reported as statuses.
program test_spline_curve
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, STATUS_OK, STATUS_INVALID_INPUT
  use numerics_spline_curve, only: spline_curve_t
  use fitpack_interfaces, only: curev, cualde
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  call interpolating_helix()
  call smoothing_with_weights()
  call arc_length_of_a_parabola()
  call closed_circle()
  call end_derivatives()
  call thesis_figure_2_4()
  call failures_as_statuses()
  call finish_tests('test_spline_curve')

contains

  pure function helix(u) result(p)
    real(wp), intent(in) :: u
    real(wp) :: p(3)
    p = [cos(2*u), sin(2*u), 0.3_wp*u]
  end function helix

  !> Interpolation (s = 0) passes through the points; evaluate agrees with
  !> FITPACK's curev and cualde and with central differences.
  subroutine interpolating_helix()
    integer, parameter :: m = 40
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(3, m), u(m), d(3, 0:5), dp(3, 0:5), dm(3, 0:5), x(3), dd(18), h, du
    real(wp), allocatable :: t(:), c(:, :), cflat(:)
    integer :: i, j, n, ier, nd
    do i = 1, m
      u(i) = 3*real(i - 1, wp)/(m - 1) + 0.02_wp*sin(7.0_wp*i)
      pts(:, i) = helix(u(i))
    end do
    do nd = 1, 5, 2
      call curve%fit(pts, 0.0_wp, nd, status, parameters=u)
      call check(status%ok(), 'helix interpolation status')
      call check(curve%fitpack_ier() == -1, 'helix interpolation ier = -1')
      do i = 1, m
        call curve%evaluate(u(i), d, 0)
        ! interpolation: the data back to rounding of the coefficients
        call check_close(maxval(abs(d(:, 0) - pts(:, i))), 0.0_wp, 0.0_wp, 1e-12_wp, 'helix passes through points')
      end do
    end do
    call check(all(curve%domain() == [u(1), u(m)]), 'helix domain')
    ! against FITPACK's evaluators
    t = curve%get_knots()
    c = curve%get_coefficients()
    n = size(t)
    allocate (cflat(3*n))
    cflat = 0
    do j = 1, 3
      cflat(n*(j - 1) + 1:n*(j - 1) + size(c, 2)) = c(j, :)
    end do
    do i = 1, 23
      du = u(1) + (u(m) - u(1))*real(i - 1, wp)/22*0.999_wp + 1e-3_wp
      call curve%evaluate(du, d, 5)
      call curev(3, t, n, cflat, 3*n, 5, [du], 1, x, 3, ier)
      call check_close(maxval(abs(d(:, 0) - x)), 0.0_wp, 0.0_wp, 1e-14_wp, 'evaluate = curev')
      call cualde(3, t, n, cflat, 3*n, 6, du, dd, 18, ier)
      do j = 0, 5
        ! same differences of the same coefficients: rounding only, scaled by the derivative size
        call check_close(maxval(abs(d(:, j) - dd(3*j + 1:3*j + 3))), 0.0_wp, 0.0_wp, &
                         1e-12_wp*max(1.0_wp, maxval(abs(dd(3*j + 1:3*j + 3)))), 'evaluate = cualde')
      end do
      ! central differences of derivative j-1 against derivative j (O(h^2) error ~ 1e-8 relative)
      h = 1e-5_wp
      if (du - h < u(1) .or. du + h > u(m)) cycle
      call curve%evaluate(du + h, dp, 5)
      call curve%evaluate(du - h, dm, 5)
      do j = 1, 4
        call check_close(maxval(abs((dp(:, j - 1) - dm(:, j - 1))/(2*h) - d(:, j))), 0.0_wp, 0.0_wp, &
                         1e-5_wp*max(1.0_wp, maxval(abs(d(:, j + 1)))), 'derivative vs central difference')
      end do
    end do
    ! derivatives above the degree are zero
    call curve%evaluate(1.0_wp, d(:, 0:5), 5)
    call check(all(d(:, 5) /= 0), 'quintic: fifth derivative nonzero')
    call curve%fit(pts, 0.0_wp, 3, status, parameters=u)
    call curve%evaluate(1.0_wp, d, 5)
    call check(all(d(:, 4:5) == 0), 'cubic: derivatives above 3 are zero')
  end subroutine interpolating_helix

  !> s > 0: fp = s within FITPACK's tolerance, weights change the fit.
  subroutine smoothing_with_weights()
    integer, parameter :: m = 200
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(3, m), w(m), s, res, d(3, 0:0)
    integer :: i
    do i = 1, m
      pts(:, i) = helix(3*real(i - 1, wp)/(m - 1)) + 0.01_wp*[sin(17.0_wp*i), cos(23.0_wp*i), sin(31.0_wp*i)]
      w(i) = 1 + 0.5_wp*sin(real(i, wp))
    end do
    s = 0.01_wp
    call curve%fit(pts, s, 3, status)
    call check(status%ok() .and. curve%fitpack_ier() == 0, 'smoothing status')
    call check(abs(curve%residual() - s) < 1e-3_wp*s, 'smoothing: |fp - s| < 0.001 s')
    call curve%fit(pts, s, 3, status, weights=w)
    call check(status%ok(), 'weighted smoothing status')
    ! fp is the weighted residual at chord-length parameters: recompute it
    res = 0
    block
      real(wp) :: u(m)
      u(1) = 0
      do i = 2, m
        u(i) = u(i - 1) + norm2(pts(:, i) - pts(:, i - 1))
      end do
      u = u/u(m)
      do i = 1, m
        call curve%evaluate(u(i), d, 0)
        res = res + (w(i)*norm2(d(:, 0) - pts(:, i)))**2
      end do
    end block
    call check_close(res, curve%residual(), 1e-9_wp, 0.0_wp, 'weighted fp is the weighted residual')
  end subroutine smoothing_with_weights

  !> r(u) = (u^2, 2u^2): a cubic interpolant reproduces it exactly, |r'| = 2 sqrt(5) u is a
  !> polynomial, so Gauss-Legendre is exact: arc length sqrt(5) u^2.
  subroutine arc_length_of_a_parabola()
    integer, parameter :: m = 9
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(2, m), u(m), x, s
    integer :: i
    do i = 1, m
      u(i) = (real(i - 1, wp)/(m - 1))**1.5_wp
      pts(:, i) = [u(i)**2, 2*u(i)**2]
    end do
    call curve%fit(pts, 0.0_wp, 3, status, parameters=u)
    call check(status%ok(), 'parabola fit')
    do i = 0, 20
      x = real(i, wp)/20
      s = curve%arc_length(x)
      ! exact quadrature of an exactly represented curve: rounding only
      call check_close(s, sqrt(5.0_wp)*x**2, 1e-13_wp, 1e-15_wp, 'parabola arc length')
      if (x > 0.05_wp) call check_close(curve%parameter_at_length(s), x, 1e-12_wp, 0.0_wp, &
                                        'parabola parameter at length')
    end do
    call check_close(curve%total_length(), sqrt(5.0_wp), 1e-14_wp, 0.0_wp, 'parabola total length')
    call check_close(curve%parameter_at_length(-1.0_wp), 0.0_wp, 0.0_wp, 0.0_wp, 'length below 0 clamps')
    call check_close(curve%parameter_at_length(9.0_wp), 1.0_wp, 0.0_wp, 0.0_wp, 'length above total clamps')
  end subroutine arc_length_of_a_parabola

  !> A closed quintic through points on the unit circle: length 2 pi to interpolation
  !> accuracy, arc length against composite Simpson of |r'|, periodic wrap.
  subroutine closed_circle()
    integer, parameter :: m = 41
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(2, m), u(m), d(2, 0:1), simpson, x, h, s, a, b, period
    integer :: i, j, nsub
    do i = 1, m
      u(i) = two_pi*real(i - 1, wp)/(m - 1)
      pts(:, i) = [cos(u(i)), sin(u(i))]
    end do
    pts(:, m) = pts(:, 1)
    call curve%fit(pts, 0.0_wp, 5, status, parameters=u, periodic=.true.)
    call check(status%ok() .and. curve%is_periodic(), 'closed circle fit')
    ! quintic interpolation of the circle with 40 points: error ~ (2pi/40)^6
    call check_close(curve%total_length(), two_pi, 1e-7_wp, 0.0_wp, 'circle length 2 pi')
    associate (dom => curve%domain())
      a = dom(1)
      b = dom(2)
    end associate
    period = b - a
    ! composite Simpson with 4000 panels per unit as an independent quadrature
    do j = 1, 5
      x = a + period*j/5.3_wp
      nsub = 4000
      h = (x - a)/nsub
      simpson = 0
      do i = 0, nsub
        call curve%evaluate(a + i*h, d, 1)
        if (i == 0 .or. i == nsub) then
          simpson = simpson + norm2(d(:, 1))
        else if (mod(i, 2) == 1) then
          simpson = simpson + 4*norm2(d(:, 1))
        else
          simpson = simpson + 2*norm2(d(:, 1))
        end if
      end do
      simpson = simpson*h/3
      s = curve%arc_length(x)
      ! Simpson's error with h ~ 1e-3 on a smooth integrand: ~1e-12
      call check_close(s, simpson, 1e-10_wp, 0.0_wp, 'circle arc length vs Simpson')
      call check_close(curve%parameter_at_length(s), x, 1e-12_wp, 0.0_wp, 'circle parameter at length')
      ! one period later: one more total length; the parameter comes back shifted by the period
      call check_close(curve%arc_length(x + period), s + curve%total_length(), 1e-12_wp, 0.0_wp, &
                       'closed curve: arc length over more than a period')
      call check_close(curve%parameter_at_length(s + curve%total_length()), x + period, 1e-12_wp, 0.0_wp, &
                       'closed curve: parameter beyond one period')
    end do
    ! periodic evaluation wraps: r(u + period) = r(u), and C^4 across the seam
    block
      real(wp) :: d1(2, 0:4), d2(2, 0:4)
      call curve%evaluate(a + 0.3_wp, d1, 4)
      call curve%evaluate(a + 0.3_wp + period, d2, 4)
      call check_close(maxval(abs(d1 - d2)), 0.0_wp, 0.0_wp, 1e-12_wp, 'closed curve wraps')
      call curve%evaluate(b - 1e-9_wp, d1, 4)
      call curve%evaluate(a + 1e-9_wp, d2, 4)
      call check_close(maxval(abs(d1(:, 0:3) - d2(:, 0:3))), 0.0_wp, 0.0_wp, 1e-6_wp, 'closed curve smooth at seam')
    end block
  end subroutine closed_circle

  !> concur underneath: the prescribed position and tangent (start) and position,
  !> tangent, curvature vector (end) are met to 1e-10.
  subroutine end_derivatives()
    integer, parameter :: m = 50
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(3, m), u(m), ds(3, 2), de(3, 3), d(3, 0:5)
    integer :: i
    do i = 1, m
      u(i) = 3*real(i - 1, wp)/(m - 1)
      pts(:, i) = helix(u(i)) + 0.01_wp*[sin(11.0_wp*i), cos(13.0_wp*i), sin(19.0_wp*i)]
    end do
    ds(:, 1) = helix(0.0_wp)
    ds(:, 2) = [0.0_wp, 2.0_wp, 0.3_wp]
    de(:, 1) = helix(3.0_wp)
    de(:, 2) = [-2*sin(6.0_wp), 2*cos(6.0_wp), 0.3_wp]
    de(:, 3) = [-4*cos(6.0_wp), -4*sin(6.0_wp), 0.0_wp]
    call curve%fit(pts, 0.005_wp, 5, status, parameters=u, start_derivatives=ds, end_derivatives=de)
    call check(status%ok(), 'end derivatives: fit status '//status%text())
    call curve%evaluate(u(1), d, 5)
    call check_close(maxval(abs(d(:, 0:1) - ds)), 0.0_wp, 0.0_wp, 1e-10_wp, 'start position and tangent')
    call curve%evaluate(u(m), d, 5)
    call check_close(maxval(abs(d(:, 0:2) - de)), 0.0_wp, 0.0_wp, 1e-10_wp*4, 'end position, tangent, curvature')
    call check(abs(curve%residual() - 0.005_wp) < 0.001_wp*0.005_wp, 'end derivatives: fp = s')
    ! without parameters: chord length on [0,1], constraints in that parametrization
    ds(:, 2) = ds(:, 2)*3
    call curve%fit(pts, 0.005_wp, 3, status, start_derivatives=ds)
    call check(status%ok(), 'end derivatives with chord-length parameters')
    call curve%evaluate(0.0_wp, d, 3)
    call check_close(maxval(abs(d(:, 0:1) - ds)), 0.0_wp, 0.0_wp, 1e-10_wp*3, 'chord length: start constraints')
  end subroutine end_derivatives

  !> Thesis fig. 2.4: the cubic B-splines on [0 0 0 0 1 2 3 4 5 5 5 5] sum to one on [0, 5].
  subroutine thesis_figure_2_4()
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: d(1, 0:3), ones(1, 8)
    integer :: i
    ones = 1
    call curve%set([0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 2.0_wp, 3.0_wp, 4.0_wp, 5.0_wp, 5.0_wp, 5.0_wp, &
                    5.0_wp], ones, 3, status)
    call check(status%ok(), 'fig. 2.4: set')
    do i = 0, 100
      call curve%evaluate(5*real(i, wp)/100, d, 3)
      ! partition of unity: sums of 4 products, rounding only
      call check_close(d(1, 0), 1.0_wp, 4*epsilon(1.0_wp), 0.0_wp, 'fig. 2.4: basis sums to one')
      call check_close(maxval(abs(d(1, 1:3))), 0.0_wp, 0.0_wp, 1e-12_wp, 'fig. 2.4: derivatives of one vanish')
    end do
  end subroutine thesis_figure_2_4

  subroutine failures_as_statuses()
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(2, 10), u(10), ds(2, 1)
    integer :: i
    do i = 1, 10
      u(i) = i
      pts(:, i) = [real(i, wp), real(i, wp)**2]
    end do
    call curve%fit(pts, -1.0_wp, 3, status)
    call check(status%code == STATUS_INVALID_INPUT .and. len(status%message) > 10, 'negative s is invalid')
    call curve%fit(pts, 0.0_wp, 6, status)
    call check(status%code == STATUS_INVALID_INPUT, 'degree 6 is invalid')
    u(5) = u(4)
    call curve%fit(pts, 0.0_wp, 3, status, parameters=u)
    call check(status%code == STATUS_INVALID_INPUT, 'repeated parameter is invalid')
    call curve%fit(pts, 0.0_wp, 3, status, periodic=.true.)
    call check(status%code == STATUS_INVALID_INPUT, 'open points for a closed curve are invalid')
    ds = 0
    call curve%fit(pts, 0.0_wp, 2, status, start_derivatives=ds)
    call check(status%code == STATUS_INVALID_INPUT, 'end derivatives need an odd degree')
    call curve%fit(pts(:, 1:3), 0.0_wp, 3, status)
    call check(status%code == STATUS_INVALID_INPUT, 'too few points')
    call check(.not. curve%is_fitted(), 'no curve after failed fits')
    call curve%fit(pts, 1e-12_wp, 3, status)
    call check(status%code == STATUS_OK .or. status%code /= STATUS_INVALID_INPUT, &
               'tiny s: fitted or a solver status, never invalid input')
    if (.false.) print *, pi
  end subroutine failures_as_statuses
end program test_spline_curve
