!> The element chain's x and y (geometry_slide_elements): the integrals of
!> [cos psi, sin psi] over the horizontal arc length sigma, tabulated and
!> completed from the table.
!>
!> The evaluation's table: knots from 0 to the chain's end, at the ends of
!> every joint's window where the heading bends (the curvature changes, or
!> a bowl's window) and every w/16 inside it, elsewhere every <= 0.5 m. Each
!> span's x, y by 8-point Gauss-Legendre of the whole heading. The heading
!> is a polynomial of degree 8 in sigma within a window and only C4 at its
!> ends: a quadrature across a window's end is what was off (~2e-10 m at 2
!> m transitions, ~1e-6 m at 0.3 m, the nodes after it carrying that on);
!> with the knots there and no quadrature spanning more than w/16 of a ramp
!> the positions are exact to ~1e-14 m (test_slide_chain_evaluation: the
!> worst 4e-14 m against a fine reference). A point is completed from the nearer
!> knot of its span by what the heading does over the span:
!>   linear (no window, no bowl): the chord of the arc,
!>     int_a^u [cos psi, sin psi] = (u - a) sinc(kappa (u - a)/2) [cos, sin](psi_mid),
!>     its direction the bisector of the knot's and u's headings (exact to
!>     rounding);
!>   within joint j's window (no bowl): 8-point Gauss-Legendre of the knot's
!>     heading plus the linear part and the ramp,
!>     psi(s) = psi_a + kappa_j (s - a) + dkappa_j w_j (P(t(s)) - P(t(a)))
!>     (P the smoothstep's integral), without the loop over the joints;
!>   a bowl reaches in: 8-point Gauss-Legendre of the whole heading.
!> Beyond the chain's ends by more than half a node step: the whole
!> heading's quadrature from the end.
!>
!> The fits' table (quadrature_point, geometry_slide_builder) is the one the
!> chain always had, kept apart so every fitted slide keeps its points to
!> the bit: nodes every 0.5 m, each by 8-point Gauss-Legendre over the whole
!> node step across the windows' ends (off by up to 2e-9 m with 1.5 to 2 m
!> transitions, 1.6e-6 m with 0.3 m ones: test_slide_chain_evaluation).
submodule (geometry_slide_elements) geometry_slide_chain_xy
  use numerics_quadrature, only: gl8_x, gl8_w, node_below
  implicit none (type, external)

  !> Spans of a window where the heading bends.
  integer, parameter :: window_spans = 16

contains

  module subroutine build_xy_table(c)
    type(element_chain_curve_t), intent(inout) :: c
    real(wp), allocatable :: ends(:)
    logical, allocatable :: window(:)
    real(wp) :: a, b, xy(2), s, lo, hi, run(2), carry(2), t
    integer :: nn, k, i, j, m, n, p, steps
    ! the fits' nodes: Gauss-Legendre over each node step
    nn = ceiling(c%total/c%node_step)
    allocate (c%node_xy(2, 0:nn))
    c%node_xy(:, 0) = c%start(1:2)
    do k = 1, nn
      a = (k - 1)*c%node_step
      b = k*c%node_step
      xy = 0
      do i = 1, 8
        s = 0.5_wp*(a + b) + 0.5_wp*(b - a)*gl8_x(i)
        xy = xy + gl8_w(i)*direction_xy(c, s)
      end do
      c%node_xy(:, k) = c%node_xy(:, k - 1) + 0.5_wp*(b - a)*xy
    end do
    ! the evaluation's pieces: the windows where the heading bends and what
    ! lies between them (the windows do not overlap: each is at most half of
    ! either neighbour)
    ends = [0.0_wp]
    window = [logical ::]
    do j = 1, size(c%joint)
      if (.not. c%width(j) > 0) cycle
      lo = c%joint(j) - c%width(j)/2
      hi = c%joint(j) + c%width(j)/2
      if (c%kappa(j + 1) == c%kappa(j) .and. heading_kind(c, lo, hi) /= -1) cycle
      if (lo > ends(size(ends))) then
        ends = [ends, lo]
        window = [window, .false.]
      end if
      ends = [ends, hi]
      window = [window, .true.]
    end do
    if (c%total > ends(size(ends))) then
      ends = [ends, c%total]
      window = [window, .false.]
    end if
    n = 0
    do p = 1, size(window)
      n = n + piece_steps(p)
    end do
    allocate (c%knot(0:n), c%knot_xy(2, 0:n), c%knot_psi(0:n), c%knot_dir(2, 0:n), c%span_kind(n), c%span_kappa(n))
    c%knot(0) = 0
    k = 0
    do p = 1, size(window)
      steps = piece_steps(p)
      do m = 1, steps
        k = k + 1
        c%knot(k) = ends(p) + (ends(p + 1) - ends(p))*m/real(steps, wp)
        if (m == steps) c%knot(k) = ends(p + 1)
      end do
    end do
    c%knot_xy(:, 0) = c%start(1:2)
    run = c%start(1:2)
    carry = 0
    do k = 0, n
      c%knot_psi(k) = chain_heading(c, c%knot(k))
      c%knot_dir(:, k) = [cos(c%knot_psi(k)), sin(c%knot_psi(k))]
      if (k == 0) cycle
      a = c%knot(k - 1)
      b = c%knot(k)
      xy = 0
      do i = 1, 8
        s = 0.5_wp*(a + b) + 0.5_wp*(b - a)*gl8_x(i)
        xy = xy + gl8_w(i)*direction_xy(c, s)
      end do
      ! the spans' sum compensated (Neumaier): each knot within a rounding of
      ! the exact sum, not ~n roundings (identical spans along a straight
      ! would add theirs up)
      xy = 0.5_wp*(b - a)*xy
      do i = 1, 2
        t = run(i) + xy(i)
        if (abs(run(i)) >= abs(xy(i))) then
          carry(i) = carry(i) + ((run(i) - t) + xy(i))
        else
          carry(i) = carry(i) + ((xy(i) - t) + run(i))
        end if
        run(i) = t
      end do
      c%knot_xy(:, k) = run + carry
      ! the first and the last span reach beyond the chain's ends
      lo = merge(-huge(1.0_wp), a, k == 1)
      hi = merge(huge(1.0_wp), b, k == n)
      c%span_kind(k) = heading_kind(c, lo, hi)
      c%span_kappa(k) = c%kappa(c%element_at(0.5_wp*(a + b)))
      if (c%span_kind(k) > 0) c%span_kappa(k) = c%kappa(c%span_kind(k))
    end do
    nn = ceiling(c%total/c%node_step)
    allocate (c%cell_knot(0:nn))
    do k = 0, nn
      c%cell_knot(k) = node_below(c%knot, k*c%node_step)
    end do

  contains

    integer function piece_steps(p) result(steps)
      integer, intent(in) :: p
      if (window(p)) then
        steps = window_spans
      else
        steps = max(1, ceiling((ends(p + 1) - ends(p))/c%node_step))
      end if
    end function piece_steps
  end subroutine build_xy_table

  pure module function chain_xy(c, sigma, dir) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma, dir(2)
    real(wp) :: xy(2)
    real(wp) :: du, m(2)
    integer :: i, n, at
    n = ubound(c%knot, 1)
    if (sigma < -c%node_step/2) then
      xy = heading_quadrature(c, c%knot(0), c%knot_xy(:, 0), sigma)
      return
    else if (sigma > c%knot(n) + c%node_step/2) then
      xy = heading_quadrature(c, c%knot(n), c%knot_xy(:, n), sigma)
      return
    end if
    i = span_at(c, sigma)
    at = i - 1
    if (c%knot(i) - sigma < sigma - c%knot(i - 1)) at = i
    select case (c%span_kind(i))
    case (0)
      du = sigma - c%knot(at)
      m = c%knot_dir(:, at) + dir
      xy = c%knot_xy(:, at) + (du*sinc(0.5_wp*c%span_kappa(i)*du)/norm2(m))*m
    case (1:)
      xy = transition_xy(c, sigma, at, c%span_kind(i), c%span_kappa(i))
    case default
      xy = heading_quadrature(c, c%knot(at), c%knot_xy(:, at), sigma)
    end select
  end function chain_xy

  !> The span i (1 .. n) from knot(i - 1) to knot(i) that holds sigma (the
  !> first or the last beyond the ends).
  pure integer function span_at(c, sigma) result(i)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    integer :: cell, lo, hi
    cell = max(0, min(int(sigma/c%node_step), ubound(c%cell_knot, 1) - 1))
    lo = c%cell_knot(cell)
    hi = min(c%cell_knot(cell + 1) + 1, ubound(c%knot, 1))
    i = lo + node_below(c%knot(lo:hi), sigma) + 1
  end function span_at

  pure module function heading_quadrature(c, a, xy_a, sigma) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: a, xy_a(2), sigma
    real(wp) :: xy(2)
    real(wp) :: s, acc(2)
    integer :: i
    acc = 0
    do i = 1, 8
      s = 0.5_wp*(a + sigma) + 0.5_wp*(sigma - a)*gl8_x(i)
      acc = acc + gl8_w(i)*direction_xy(c, s)
    end do
    xy = xy_a + 0.5_wp*(sigma - a)*acc
  end function heading_quadrature

  !> heading_quadrature from knot `at` within joint j's window (no bowl):
  !> the heading there is the knot's plus the linear part (kappa) and the
  !> ramp's,
  !>   psi(s) = psi_a + kappa (s - a) + dkappa_j w_j (P(t(s)) - P(t(a))).
  pure function transition_xy(c, sigma, at, j, kappa) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma, kappa
    integer, intent(in) :: at, j
    real(wp) :: xy(2)
    real(wp) :: a, s, acc(2), psi, dk, w, ramp
    integer :: i
    a = c%knot(at)
    w = c%width(j)
    dk = (c%kappa(j + 1) - c%kappa(j))*w
    ramp = smoothstep_integral((a - c%joint(j) + w/2)/w)
    acc = 0
    do i = 1, 8
      s = 0.5_wp*(a + sigma) + 0.5_wp*(sigma - a)*gl8_x(i)
      psi = c%knot_psi(at) + kappa*(s - a) + dk*(smoothstep_integral((s - c%joint(j) + w/2)/w) - ramp)
      acc = acc + gl8_w(i)*[cos(psi), sin(psi)]
    end do
    xy = c%knot_xy(:, at) + 0.5_wp*(sigma - a)*acc
  end function transition_xy

  !> [cos psi, sin psi] of the whole heading at sigma.
  pure function direction_xy(c, sigma) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    real(wp) :: xy(2)
    real(wp) :: psi
    psi = chain_heading(c, sigma)
    xy = [cos(psi), sin(psi)]
  end function direction_xy

  !> sin(x)/x (1 at 0; the series below 0.1, error < 3e-18).
  pure real(wp) function sinc(x)
    real(wp), intent(in) :: x
    real(wp) :: x2
    if (abs(x) < 0.1_wp) then
      x2 = x*x
      sinc = 1 - x2/6*(1 - x2/20*(1 - x2/42*(1 - x2/72)))
    else
      sinc = sin(x)/x
    end if
  end function sinc

  !> How the heading behaves over [lo, hi] (span_kind): 0 linear in sigma
  !> (no transition that changes kappa reaches into it, nor any bowl: its
  !> spiral and its windows, beyond the chain's end where it begins or ends
  !> it), j > 0 joint j's transition alone reaches in, -1 otherwise.
  pure integer function heading_kind(c, lo, hi) result(kind)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: lo, hi
    real(wp) :: b_lo, b_hi
    integer :: j
    kind = -1
    do j = 1, size(c%bowls)
      b_lo = merge(-huge(1.0_wp), c%bowls(j)%lo, c%bowls(j)%width_in == 0)
      b_hi = merge(huge(1.0_wp), c%bowls(j)%hi, c%bowls(j)%width_out == 0)
      if (b_lo < hi .and. b_hi > lo) return
    end do
    kind = 0
    do j = 1, size(c%joint)
      if (.not. (c%width(j) > 0 .and. c%kappa(j + 1) /= c%kappa(j))) cycle
      if (c%joint(j) - c%width(j)/2 < hi .and. c%joint(j) + c%width(j)/2 > lo) then
        if (kind /= 0) then
          kind = -1
          return
        end if
        kind = j
      end if
    end do
  end function heading_kind
end submodule geometry_slide_chain_xy
