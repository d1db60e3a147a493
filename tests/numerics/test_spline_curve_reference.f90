!> spline_curve_t%evaluate (a Taylor table per knot span, Horner) against an
!> independent reference written here: the B-splines and their derivatives by
!> the textbook recursions (de Boor, A Practical Guide to Splines, IX.(15) and
!> X.(12)), evaluated term by term, and the knot span found by a linear search.
!> Degrees 1..5, derivative orders 0..k+1, at every knot, the domain ends,
!> points a few ulps from knots and random points, on random knot vectors
!> (with multiple interior knots, and a multiple knot at the end of the
!> domain), on FITPACK fits (parcur, clocur periodic, concur), with
!> coefficients far from the origin (positions of ~100 m). Also the arc
!> length against an independent composite Gauss-Legendre quadrature of the
!> reference speed.
program test_spline_curve_reference
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_status, only: status_t
  use base_sorting, only: sort_ascending
  use numerics_spline_curve, only: spline_curve_t
  use bspline_reference, only: bspline, span_of
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  real(wp) :: worst(0:6) = 0    ! largest error / scale per derivative order (printed)
  integer :: k, trial

  call random_init(repeatable=.true., image_distinct=.false.)
  do k = 1, 5
    do trial = 1, 6
      call random_curve(k, trial)
    end do
  end do
  do k = 1, 5
    call fitted_curves(k)
  end do
  print '(a, 7es10.2)', 'largest |evaluate - reference| / scale, orders 0..6:', worst
  call finish_tests('test_spline_curve_reference')

contains

  !> The reference r^(m)(x) and its rounding scale sum_i |c_i| |B_i^(m)(x)| for x in the domain.
  subroutine reference(t, c, k, x, m, r, scale)
    real(wp), intent(in) :: t(:), c(:, :), x
    integer, intent(in) :: k, m
    real(wp), intent(out) :: r(:), scale
    real(wp) :: b
    integer :: i, l
    l = span_of(t, k, x)
    r = 0
    scale = 0
    do i = l - k, l
      b = bspline(t, i, k, m, l, x)
      r = r + c(:, i)*b
      scale = scale + maxval(abs(c(:, i)))*abs(b)
    end do
  end subroutine reference

  !> evaluate against the reference at the points xs (inside the domain), all
  !> orders 0..k+1; order k+1 must be exactly zero.
  subroutine compare(curve, xs, what)
    type(spline_curve_t), intent(in) :: curve
    real(wp), intent(in) :: xs(:)
    character(len=*), intent(in) :: what
    real(wp), allocatable :: t(:), c(:, :), d(:, :), r(:)
    real(wp) :: scale, err, bad, x
    integer :: i, m, k, dim
    t = curve%get_knots()
    c = curve%get_coefficients()
    k = curve%get_degree()
    dim = curve%get_dimension()
    allocate (d(dim, 0:k + 1), r(dim))
    bad = 0
    do i = 1, size(xs)
      call curve%evaluate(xs(i), d, k + 1)
      ! a closed curve maps the end of its domain to the start (right-hand derivatives there)
      x = xs(i)
      if (curve%is_periodic() .and. x >= t(size(t) - k)) x = t(k + 1)
      do m = 0, k
        call reference(t, c, k, x, m, r, scale)
        ! both sides round: Horner on the Taylor table, the recursion here;
        ! errors are a few eps of the sum of the terms' sizes (scale), and
        ! the Taylor coefficients, formed at the span's left knot, carry the
        ! rounding of the coefficients' differences (order m: ~ (k!/(k-m)!)
        ! eps scale); the worst seen is 2.5e-15 (order 2), 1e-13 leaves a margin of 40
        err = maxval(abs(d(:, m) - r))/max(scale, tiny(1.0_wp))
        worst(m) = max(worst(m), err)
        bad = max(bad, err/1e-13_wp)
      end do
      if (any(d(:, k + 1) /= 0)) bad = huge(1.0_wp)
    end do
    call check(bad <= 1, what//': evaluate = reference, orders 0..k+1')
  end subroutine compare

  !> The points of a check: every knot in the domain, the ends, a few ulps
  !> on both sides of every knot, and random points.
  function check_points(t, k, nrandom) result(xs)
    real(wp), intent(in) :: t(:)
    integer, intent(in) :: k, nrandom
    real(wp), allocatable :: xs(:)
    real(wp) :: a, b, r
    integer :: j
    a = t(k + 1)
    b = t(size(t) - k)
    xs = [a, b]
    do j = k + 1, size(t) - k
      xs = [xs, t(j), nearest(t(j), 1.0_wp), nearest(t(j), -1.0_wp), t(j) + 4*spacing(t(j)), &
            t(j) - 4*spacing(t(j))]
    end do
    do j = 1, nrandom
      call random_number(r)
      xs = [xs, a + r*(b - a)]
    end do
    xs = min(max(xs, a), b)
  end function check_points

  !> A random knot vector of degree k (ends clamped or not, interior knots
  !> repeated up to k times, in trial 6 a multiple knot at the end of the
  !> domain) and random coefficients around 100 in dim = 1..4 coordinates.
  subroutine random_curve(k, trial)
    integer, intent(in) :: k, trial
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp), allocatable :: t(:), c(:, :), inner(:), d(:, :), e(:, :)
    real(wp) :: r, x, period
    integer :: n_inner, i, dim, n, mult
    character(len=40) :: what
    write (what, '(a, i0, a, i0)') 'random curve, degree ', k, ', trial ', trial
    call random_number(r)
    n_inner = 3 + int(12*r)
    allocate (inner(0))
    do while (size(inner) < n_inner)
      call random_number(r)
      mult = 1
      if (trial >= 3) mult = 1 + int(k*r**3)       ! multiple knots now and then
      call random_number(r)
      inner = [inner, spread(-2 + 5*r, 1, mult)]
    end do
    call sort_ascending(inner)   ! repeated knots kept
    if (mod(trial, 2) == 1) then
      t = [spread(-2.0_wp, 1, k + 1), inner, spread(3.0_wp, 1, k + 1)]          ! clamped (FITPACK's open curves)
    else
      t = [(-2.0_wp - 0.3_wp*i, i = k, 1, -1), -2.0_wp, inner, 3.0_wp, (3.0_wp + 0.4_wp*i, i = 1, k)]
    end if
    if (trial == 6) t(size(t) - k - min(k, 2):size(t) - k) = 3.0_wp   ! a multiple knot ending the domain
    n = size(t)
    dim = 1 + mod(trial, 4)
    allocate (c(dim, n - k - 1))
    call random_number(c)
    c = 100 + 2*c
    call curve%set(t, c, k, status)
    call check(status%ok(), trim(what)//': set')
    call compare(curve, check_points(t, k, 200), trim(what))
    ! open curves clamp outside the domain
    allocate (d(dim, 0:k), e(dim, 0:k))
    call curve%evaluate(t(k + 1) - 1, d, k)
    call curve%evaluate(t(k + 1), e, k)
    call check(all(d == e), trim(what)//': clamped below the domain')
    call curve%evaluate(t(n - k) + 1, d, k)
    call curve%evaluate(t(n - k), e, k)
    call check(all(d == e), trim(what)//': clamped above the domain')
    ! the same knots as a periodic curve's: evaluation wraps by the period
    call curve%set(t, c, k, status, periodic=.true.)
    period = t(n - k) - t(k + 1)
    call random_number(x)
    x = t(k + 1) + 0.9_wp*x*period
    call curve%evaluate(x + 2*period, d, k)
    call curve%evaluate(x, e, k)
    ! x + 2 period - 2 period differs from x by rounding of x (~1e-16 relative)
    call check(maxval(abs(d(:, 0) - e(:, 0))) <= 1e-9_wp*maxval(abs(e(:, 0))), trim(what)//': wraps by the period')
  end subroutine random_curve

  !> FITPACK fits of degree k: an interpolated helix (parcur), a smoothed
  !> noisy helix far from the origin, a closed curve (clocur),
  !> a curve with prescribed end derivatives (concur, odd k).
  subroutine fitted_curves(k)
    integer, intent(in) :: k
    integer, parameter :: m = 60
    type(spline_curve_t) :: curve
    type(status_t) :: status
    real(wp) :: pts(3, m), u(m), a, b, s_ref, s, period, db(3, 3)
    real(wp), allocatable :: t(:), d(:, :), e(:, :)
    integer :: i
    character(len=40) :: what
    write (what, '(a, i0)') 'degree ', k
    do i = 1, m
      u(i) = 3*real(i - 1, wp)/(m - 1) + 0.01_wp*sin(7.0_wp*i)
      pts(:, i) = [cos(2*u(i)), sin(2*u(i)), 0.3_wp*u(i)]
    end do
    call curve%fit(pts, 0.0_wp, k, status, parameters=u)
    call check(status%ok(), trim(what)//' helix: fit')
    t = curve%get_knots()
    call compare(curve, check_points(t, k, 300), trim(what)//' helix (parcur)')
    ! arc length: the table's against composite 20-point-per-span Gauss-Legendre of the reference speed
    a = t(k + 1)
    b = t(size(t) - k)
    s_ref = reference_length(curve, a, 0.37_wp*a + 0.63_wp*b)
    s = curve%arc_length(0.37_wp*a + 0.63_wp*b)
    ! both quadratures are exact to ~1e-14 relative on these short spans (10 and
    ! 2x10 points on polynomials of degree 2(k-1) under a square root)
    call check_close(s, s_ref, 1e-12_wp, 0.0_wp, trim(what)//' helix: arc length')

    ! smoothing, noisy points far from the origin (100 m off: a slide's coordinates)
    do i = 1, m
      pts(:, i) = [100 + 30*cos(u(i)), 50 + 30*sin(u(i)), 10 - 3*u(i)] + 0.01_wp*sin(12345.678_wp*[i, 2*i, 3*i])
    end do
    call curve%fit(pts, m*0.01_wp**2, k, status)
    call check(status%ok(), trim(what)//' noisy: fit')
    t = curve%get_knots()
    call compare(curve, check_points(t, k, 300), trim(what)//' noisy far from the origin (parcur)')

    ! closed curve
    do i = 1, m
      a = two_pi*real(i - 1, wp)/(m - 1)
      pts(:, i) = [2*cos(a) + 0.3_wp*cos(3*a), sin(a), 0.2_wp*sin(2*a)]
    end do
    pts(:, m) = pts(:, 1)
    call curve%fit(pts, 0.0_wp, k, status, periodic=.true.)
    call check(status%ok() .and. curve%is_periodic(), trim(what)//' closed: fit')
    t = curve%get_knots()
    call compare(curve, check_points(t, k, 300), trim(what)//' closed (clocur)')
    allocate (d(3, 0:k), e(3, 0:k))
    period = t(size(t) - k) - t(k + 1)
    ! the seam: the periodic spline is C^(k-1) there
    call curve%evaluate(t(size(t) - k) - 1e-7_wp*period, d, k)
    call curve%evaluate(t(k + 1), e, k)
    call check(maxval(abs(d(:, 0:k - 1) - e(:, 0:k - 1))) <= 1e-4_wp*maxval(abs(e(:, 0:k - 1))), &
               trim(what)//' closed: continuous at the seam')

    ! end derivatives (odd degrees)
    if (mod(k, 2) == 1) then
      do i = 1, m
        pts(:, i) = [u(i), u(i)**2, sin(u(i))]
      end do
      db(:, 1) = [0.0_wp, 0.0_wp, 0.0_wp]         ! not the first point: the constraint wins
      db(:, 2) = [1.0_wp, 2*u(1), cos(u(1))]
      db(:, 3) = [0.0_wp, 2.0_wp, -sin(u(1))]
      call curve%fit(pts, 0.0_wp, k, status, parameters=u, start_derivatives=db(:, 1:(k + 1)/2), &
                     end_derivatives=reshape([u(m), u(m)**2, sin(u(m))], [3, 1]))
      call check(status%ok(), trim(what)//' concur: fit')
      t = curve%get_knots()
      call compare(curve, check_points(t, k, 300), trim(what)//' end derivatives (concur)')
    end if
  end subroutine fitted_curves

  !> Arc length from a to b by 20-point Gauss-Legendre (two 10-point halves)
  !> per knot span on the reference speed.
  real(wp) function reference_length(curve, a, b) result(s)
    type(spline_curve_t), intent(in) :: curve
    real(wp), intent(in) :: a, b
    real(wp), parameter :: x(5) = [0.1488743389816312108848260_wp, 0.4333953941292471907992659_wp, &
                                   0.6794095682990244062343274_wp, 0.8650633666889845107320967_wp, &
                                   0.9739065285171717200779640_wp]
    real(wp), parameter :: w(5) = [0.2955242247147528701738930_wp, 0.2692667193099963550912269_wp, &
                                   0.2190863625159820439955349_wp, 0.1494513491505805931457763_wp, &
                                   0.0666713443086881375935688_wp]
    real(wp), allocatable :: t(:), c(:, :)
    real(wp) :: lo, hi, mid, half, r(3), scale
    integer :: j, i, h, k
    t = curve%get_knots()
    c = curve%get_coefficients()
    k = curve%get_degree()
    s = 0
    do j = k + 1, size(t) - k - 1
      do h = 0, 1
        lo = max(a, t(j) + h*0.5_wp*(t(j + 1) - t(j)))
        hi = min(b, t(j) + (h + 1)*0.5_wp*(t(j + 1) - t(j)))
        if (hi <= lo) cycle
        mid = 0.5_wp*(lo + hi)
        half = 0.5_wp*(hi - lo)
        do i = 1, 5
          call reference(t, c, k, mid - half*x(i), 1, r, scale)
          s = s + half*w(i)*norm2(r)
          call reference(t, c, k, mid + half*x(i), 1, r, scale)
          s = s + half*w(i)*norm2(r)
        end do
      end do
    end do
  end function reference_length

end program test_spline_curve_reference
