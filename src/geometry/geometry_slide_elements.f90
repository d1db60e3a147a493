!> Slides from standard elements: straight (length, slope), curve (radius,
!> turning angle, direction, slope), helix (radius, turns, drop, direction),
!> run-out (length, slope), drop (height, top slope, curve-out radius; the
!> trap-door start, first in the chain) and bowl (a spiral down a spherical
!> or conical bowl or one of a profile table: entry radius, wall slope,
!> drop, turns, direction;
!> geometry_slide_bowl) and funnel (length, slope and the widest radius of
!> the section; the centerline is a straight's, the section widens along it:
!> geometry_funnel_section, built by geometry_slide_builder) and patch
!> (length and slope; the centerline is a straight's, a free-form surface
!> from points lies on its wall: geometry_patch_section), joined with
!> continuous tangent and curvature.
!>
!> The centerline is built from the horizontal curvature kappa(sigma) and the
!> gradient g(sigma) = -dz/dsigma as functions of the horizontal arc length
!> sigma (the curve parameter u = sigma, m). Each element has constant kappa
!> (0, +-1/R) and g (tan of its slope). At each joint both change over a
!> transition of horizontal length L by the septic smoothstep
!>   S(t) = 35 t^4 - 84 t^5 + 70 t^6 - 20 t^7  (C3: S', S'', S''' vanish at 0 and 1)
!> — a clothoid-like transition (kappa varies smoothly instead of jumping), so
!> the centerline is C4 and the tube's third partials are continuous. L is the
!> transition length given by the user, shortened to the shorter neighbour.
!> L = 0 is refused where a joint changes the slope or the curvature: such a
!> sharp joint is a kink of the centerline (slope) or a jump of the tube's
!> r_u off the centerline (curvature), and whatever moves on the slide has
!> the state (u, v, u', v'), so carried across it its speed |r_u u' + r_v v'|
!> would jump (~10 % at 0.5 m off the centerline into a curve of radius
!> 6 m, test_sharp_joints): a silent wrong answer.
!> A drop (geometry_drop_profile) has a gradient of its own that ends at the
!> next element's: the chain takes that gradient for it and adds the drop's
!> deviation from it, so the joint after a drop has no step in g and the
!> drop's own curvature ramps make it curvature-continuous. A bowl's own
!> kappa and g vary along it: it adds their deviations from its entry values,
!> blended in by its joints' windows (geometry_slide_bowl).
!> Heading psi = int kappa and height z = z0 - int g are closed-form; x and y
!> are int [cos psi, sin psi] dsigma, tabulated at nodes every 0.5 m and
!> completed from the nearest node: where the heading is linear over the
!> node's half-steps (no transition that changes kappa, no bowl: a straight,
!> a curve's or a helix's arc, a drop) by the chord of the arc,
!>   int_a^u [cos psi, sin psi] = (u - a) sinc(kappa (u - a)/2) [cos, sin](psi_mid),
!> the direction [cos, sin](psi_mid) the bisector of the node's and u's
!> (kept per node; exact to rounding), elsewhere by 8-point Gauss-Legendre
!> of the heading from the node (no allocation), where one transition alone
!> reaches in of the node's heading plus that transition's ramp. The
!> quadrature is exact to ~1e-14 m where the heading is smooth on the scale
!> of a half-step, not across a transition's ramp: there the nodes' values
!> and the completions jump by ~2e-10 m at 2 m transitions (~5e-7 m at 0.3
!> m; test_slide_chain_evaluation, bench/README.md "The exact chain made
!> cheap"). The fits of the chain (geometry_slide_builder) take their points
!> by the quadrature everywhere (quadrature_point), as they always have.
!> Derivatives are closed-form:
!>   c' = [cos psi, sin psi, -g], c'' = [-k sin psi, k cos psi, -g'],
!>   c''' = [-k^2 cos psi - k' sin psi, -k^2 sin psi + k' cos psi, -g''],
!>   c'''' = [k^3 sin psi - 3 k k' cos psi - k'' sin psi,
!>            -k^3 cos psi - 3 k k' sin psi + k'' cos psi, -g'''].
!> The horizon field of a slide is the vertical [0, 0, 1].
module geometry_slide_elements
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi
  use base_status, only: status_t, set_status, STATUS_OK, STATUS_INVALID_INPUT
  use base_text, only: format_integer
  use numerics_quadrature, only: gl8_x, gl8_w
  use geometry_curve, only: curve_t, curve_point_t, panel_arc_length, arc_length_prefix
  use geometry_drop_profile, only: drop_profile_t, new_drop_profile, smoothstep, smoothstep_value, smoothstep_integral
  use geometry_slide_bowl, only: bowl_spiral_t, new_bowl_spiral
  implicit none (type, external)
  private
  public :: slide_element_t, element_chain_curve_t, new_element_chain, slide_points
  public :: element_kinds

  character(len=*), parameter :: element_kinds(8) = [character(len=8) :: 'straight', 'curve', 'helix', 'runout', &
    'drop', 'bowl', 'funnel', 'patch']

  !> One element as given in the input. Angles in degrees, lengths in m;
  !> slope is the downhill angle (deg, > 0 going down).
  type :: slide_element_t
    character(len=8) :: kind = 'straight'
    real(wp) :: length = 0          ! m, horizontal (straight, runout, funnel, patch)
    real(wp) :: slope_deg = 0       ! deg, downhill positive (straight, curve, runout; a drop's top)
    real(wp) :: radius = 0          ! m, horizontal (curve, helix); vertical (a drop's curve-out); a
                                    ! bowl's entry from its axis; a funnel's widest section radius
    real(wp) :: angle_deg = 0       ! deg, turning angle (curve)
    character(len=5) :: direction = 'left'   ! 'left' or 'right' (curve, helix)
    real(wp) :: turns = 0           ! full turns (helix)
    real(wp) :: drop = 0            ! m, height lost over the helix, the drop or the bowl
    character(len=6) :: bowl_profile = 'sphere'   ! 'sphere', 'cone' or 'table' (bowl)
    real(wp), allocatable :: bowl_rho(:), bowl_z(:)   ! m, the profile's points (bowl_profile = 'table')
  end type slide_element_t

  type, extends(curve_t) :: element_chain_curve_t
    real(wp) :: start(3) = 0                ! m, first point
    real(wp) :: heading0 = 0                ! rad, initial heading from +x
    real(wp), allocatable :: kappa(:)       ! 1/m per element (left positive)
    real(wp), allocatable :: grad(:)        ! gradient tan(slope) per element
    real(wp), allocatable :: joint(:)       ! m, sigma of each joint (middle of its transition)
    real(wp), allocatable :: width(:)       ! m, transition length at each joint
    real(wp), allocatable :: ends(:)        ! m, sigma at the end of each element
    real(wp), allocatable :: node_xy(:, :)  ! m, x, y at sigma = k*node_step
    ! how x, y are completed from each node over its half-steps (chain_evaluate):
    ! node_kind 0 the chord (the heading linear there), j > 0 the quadrature of
    ! the heading from the node with joint j's transition alone reaching in,
    ! -1 the quadrature of the whole heading (bowls, several transitions)
    integer, allocatable :: node_kind(:)
    real(wp), allocatable :: node_psi(:)    ! rad, the heading at each node
    real(wp), allocatable :: node_dir(:, :) ! its cos and sin
    real(wp), allocatable :: node_kappa(:)  ! 1/m, kappa of the heading's linear part (kind >= 0)
    real(wp), allocatable :: node_ramp(:)   ! the smoothstep's integral P(t) of joint node_kind at the node (kind > 0)
    real(wp) :: node_step = 0.5_wp
    real(wp) :: total = 0                   ! m, horizontal length
    logical :: starts_with_drop = .false.   ! element 1 is a drop
    type(drop_profile_t) :: drop            ! its profile (starts_with_drop)
    type(bowl_spiral_t), allocatable :: bowls(:)   ! the bowls' spirals, in the order of the elements
    real(wp), allocatable :: arc_prefix(:)  ! m, the arc length's whole panels from the start (geometry_curve)
  contains
    procedure :: evaluate => chain_evaluate
    procedure :: domain => chain_domain
    procedure :: parameter_unit => chain_parameter_unit
    procedure :: element_at => chain_element_at
    procedure :: heading => chain_heading
    procedure :: arc_length => chain_arc_length
    procedure :: speed => chain_speed
    procedure :: quadrature_point => chain_quadrature_point
  end type element_chain_curve_t

contains

  !> The chain of `elements` starting at `start` (m) with heading `heading_deg`
  !> (deg from +x towards +y), with transitions of horizontal length
  !> `transition` (m, >= 0). Checks every element; the message names it.
  function new_element_chain(elements, start, heading_deg, transition, status) result(c)
    type(slide_element_t), intent(in) :: elements(:)
    real(wp), intent(in) :: start(3), heading_deg, transition
    type(status_t), intent(out) :: status
    type(element_chain_curve_t) :: c
    integer :: n, i, j, k, nn, nb
    real(wp) :: len_h(size(elements)), sgn, a, b, xy(2), s
    character(len=16) :: idx
    character(len=:), allocatable :: why
    n = size(elements)
    if (n < 1) then
      call set_status(status, STATUS_INVALID_INPUT, 'slide elements: no elements given')
      return
    end if
    if (.not. transition >= 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'slide elements: transition length must be >= 0 m')
      return
    end if
    allocate (c%kappa(n), c%grad(n), c%ends(n), c%bowls(0))
    do i = 1, n
      write (idx, '(i0)') i
      associate (e => elements(i))
        sgn = 1
        if (e%kind == 'curve' .or. e%kind == 'helix' .or. e%kind == 'bowl') then
          if (e%direction == 'right') then
            sgn = -1
          else if (e%direction /= 'left') then
            call fail('direction must be ''left'' or ''right''')
            return
          end if
          if (.not. e%radius > 0) then
            call fail('radius must be > 0 m')
            return
          end if
        end if
        select case (e%kind)
        case ('straight', 'runout', 'funnel', 'patch')
          if (.not. e%length > 0) then
            call fail('length must be > 0 m')
            return
          end if
          if (.not. abs(e%slope_deg) < 60) then
            call fail('slope must lie in (-60, 60) deg')
            return
          end if
          len_h(i) = e%length
          c%kappa(i) = 0
          c%grad(i) = tan(e%slope_deg*pi/180)
        case ('curve')
          if (.not. (e%angle_deg > 0 .and. e%angle_deg <= 720)) then
            call fail('turning angle must lie in (0, 720] deg')
            return
          end if
          if (.not. abs(e%slope_deg) < 60) then
            call fail('slope must lie in (-60, 60) deg')
            return
          end if
          len_h(i) = e%radius*e%angle_deg*pi/180
          c%kappa(i) = sgn/e%radius
          c%grad(i) = tan(e%slope_deg*pi/180)
        case ('helix')
          if (.not. e%turns > 0) then
            call fail('turns must be > 0')
            return
          end if
          len_h(i) = two_pi*e%radius*e%turns
          c%kappa(i) = sgn/e%radius
          c%grad(i) = e%drop/len_h(i)
          if (.not. abs(c%grad(i)) < tan(60*pi/180)) then
            call fail('drop per horizontal length must correspond to a slope below 60 deg')
            return
          end if
        case ('drop')
          if (i > 1) then
            call fail('a drop is the trap-door start of a slide: only the first element can be a drop')
            return
          end if
          if (n < 2) then
            call fail('a drop needs an element after it (its curve-out turns into it)')
            return
          end if
          c%kappa(i) = 0
          c%grad(i) = 0     ! set to the next element's gradient below
          len_h(i) = 0
        case ('bowl')
          if (e%bowl_profile == 'table' .and. allocated(e%bowl_rho) .and. allocated(e%bowl_z)) then
            c%bowls = [c%bowls, new_bowl_spiral(e%bowl_profile, e%radius, e%slope_deg, e%drop, e%turns, sgn, &
                                                status, e%bowl_rho, e%bowl_z)]
          else
            c%bowls = [c%bowls, new_bowl_spiral(e%bowl_profile, e%radius, e%slope_deg, e%drop, e%turns, sgn, status)]
          end if
          if (.not. status%ok()) then
            why = status%text()
            call fail(why)
            return
          end if
          nb = size(c%bowls)
          len_h(i) = c%bowls(nb)%length
          c%kappa(i) = c%bowls(nb)%kappa_ref
          c%grad(i) = c%bowls(nb)%grad_ref
        case default
          call fail('kind must be one of straight, curve, helix, runout, drop, bowl, funnel, patch')
          return
        end select
      end associate
    end do
    if (elements(1)%kind == 'drop') then
      i = 1
      idx = '1'
      c%grad(1) = c%grad(2)
      c%drop = new_drop_profile(elements(1)%drop, elements(1)%slope_deg, elements(1)%radius, c%grad(2), &
                                transition, status)
      if (.not. status%ok()) then
        why = status%text()
        call fail(why)
        return
      end if
      c%starts_with_drop = .true.
      len_h(1) = c%drop%total
    end if
    c%start = start
    c%heading0 = heading_deg*pi/180
    c%ends(1) = len_h(1)
    do i = 2, n
      c%ends(i) = c%ends(i - 1) + len_h(i)
    end do
    c%total = c%ends(n)
    allocate (c%joint(n - 1), c%width(n - 1))
    do i = 1, n - 1
      c%joint(i) = c%ends(i)
      c%width(i) = min(transition, len_h(i), len_h(i + 1))
      if (.not. c%width(i) > 0) then
        why = sharp_jump(c%kappa(i + 1) /= c%kappa(i), c%grad(i + 1) /= c%grad(i))
        if (len(why) > 0) then
          call set_status(status, STATUS_INVALID_INPUT, 'slide elements: transition_length = 0 makes joint '// &
            format_integer(i)//' (element '//format_integer(i)//', '//trim(elements(i)%kind)//', to element '// &
            format_integer(i + 1)//', '//trim(elements(i + 1)%kind)//') sharp: '//why//' there, and a rider''s '// &
            'or the water''s speed would jump with the slide''s parameter speed |r_u| (a wrong answer, not '// &
            'physics); give transition_length > 0 (a short one makes a nearly sharp joint, as far as the '// &
            'tube does not fold)')
          return
        end if
      end if
    end do
    ! the bowls' own curvature and gradient vary along them: each is blended
    ! in through its joints' windows, so a joint without a transition is sharp
    nb = 0
    do i = 1, n
      if (elements(i)%kind /= 'bowl') cycle
      write (idx, '(i0)') i
      nb = nb + 1
      if (.not. transition > 0) then
        call fail('transition_length = 0 would make the bowl''s joints sharp (its curvature and gradient vary '// &
                  'along it and are blended into its neighbours'' over the transitions); give transition_length > 0')
        return
      end if
      a = 0
      b = 0
      if (i > 1) a = c%width(i - 1)
      if (i < n) b = c%width(i)
      call c%bowls(nb)%place(c%ends(i) - len_h(i), a, b, status)
      if (.not. status%ok()) then
        why = status%text()
        call fail(why)
        return
      end if
    end do
    ! x, y at the nodes by Gauss-Legendre over each node interval
    nn = ceiling(c%total/c%node_step)
    allocate (c%node_xy(2, 0:nn))
    c%node_xy(:, 0) = start(1:2)
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
    ! how each node's half-steps are completed (chain_evaluate)
    allocate (c%node_kind(0:nn), c%node_psi(0:nn), c%node_dir(2, 0:nn), c%node_kappa(0:nn), c%node_ramp(0:nn))
    do k = 0, nn
      s = k*c%node_step
      c%node_psi(k) = chain_heading(c, s)
      c%node_dir(:, k) = [cos(c%node_psi(k)), sin(c%node_psi(k))]
      c%node_kind(k) = heading_kind(c, s - c%node_step/2, s + c%node_step/2)
      c%node_kappa(k) = c%kappa(c%element_at(s))
      c%node_ramp(k) = 0
      if (c%node_kind(k) > 0) then
        j = c%node_kind(k)
        c%node_kappa(k) = c%kappa(j)
        c%node_ramp(k) = smoothstep_integral((s - c%joint(j) + c%width(j)/2)/c%width(j))
      end if
    end do
    c%arc_prefix = arc_length_prefix(c)

  contains
    !> What jumps at a sharp joint ('' where nothing does).
    pure function sharp_jump(curvature, slope) result(what)
      logical, intent(in) :: curvature, slope
      character(len=:), allocatable :: what
      if (curvature .and. slope) then
        what = 'the slope (a kink of the centerline) and the curvature jump'
      else if (slope) then
        what = 'the slope jumps (a kink of the centerline)'
      else if (curvature) then
        what = 'the curvature jumps'
      else
        what = ''
      end if
    end function sharp_jump

    subroutine fail(what)
      character(len=*), intent(in) :: what
      call set_status(status, STATUS_INVALID_INPUT, 'slide element ' // trim(idx) // ' (' // &
                      trim(elements(i)%kind) // '): ' // what)
    end subroutine fail
  end function new_element_chain

  !> psi, kappa and its derivatives (k(0:2)), g and its derivatives (g(0:3)),
  !> and the integral of g from 0 (m) at sigma.
  pure subroutine profile(c, sigma, psi, k, g, gint)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    real(wp), intent(out) :: psi, k(0:3), g(0:3), gint
    real(wp) :: d(0:3), p, t, w, dk, dg, ipart, dev(0:3)
    integer :: j, m
    k = 0; g = 0
    k(0) = c%kappa(1); g(0) = c%grad(1)
    psi = c%heading0 + c%kappa(1)*sigma
    gint = c%grad(1)*sigma
    do j = 1, size(c%joint)
      w = c%width(j)
      dk = c%kappa(j + 1) - c%kappa(j)
      dg = c%grad(j + 1) - c%grad(j)
      if (.not. w > 0) cycle              ! a sharp joint changes nothing (new_element_chain)
      t = (sigma - c%joint(j) + w/2)/w
      if (t <= 0) cycle                   ! before the transition: S = 0 adds nothing
      if (t >= 1) then                    ! after it: S = 1, smoothstep's values by its operations
        ipart = w*(t - 0.5_wp)
        k(0) = k(0) + dk
        g(0) = g(0) + dg
        psi = psi + dk*ipart
        gint = gint + dg*ipart
        cycle
      end if
      call smoothstep(t, d, p)
      ipart = w*p                         ! int_{-inf}^{sigma} S
      do m = 0, 3
        k(m) = k(m) + dk*d(m)/w**m
        g(m) = g(m) + dg*d(m)/w**m
      end do
      psi = psi + dk*ipart
      gint = gint + dg*ipart
    end do
    if (c%starts_with_drop) then
      call c%drop%deviation(sigma, d, ipart)
      g = g + d
      gint = gint + ipart
    end if
    if (.not. allocated(c%bowls)) return
    do j = 1, size(c%bowls)
      call c%bowls(j)%deviation(sigma, d, p, dev, ipart)
      k = k + d
      psi = psi + p
      g = g + dev
      gint = gint + ipart
    end do
  end subroutine profile

  !> The heading psi at sigma (rad from +x): profile's psi alone, by the
  !> same operations (to the bit, test_slide_bowl heading_alone): the
  !> quadrature of x and y needs the heading at eight points per evaluation,
  !> and the curvature, gradient and height terms (the drop's and the bowls'
  !> quadratures among them) cost several times as much.
  pure real(wp) function chain_heading(c, sigma) result(psi)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    real(wp) :: w, t
    integer :: j
    psi = c%heading0 + c%kappa(1)*sigma
    do j = 1, size(c%joint)
      w = c%width(j)
      if (.not. w > 0) cycle
      t = (sigma - c%joint(j) + w/2)/w
      if (t <= 0) cycle                   ! before the transition: nothing added
      psi = psi + (c%kappa(j + 1) - c%kappa(j))*(w*smoothstep_integral(t))
    end do
    if (.not. allocated(c%bowls)) return
    do j = 1, size(c%bowls)
      psi = psi + c%bowls(j)%heading(sigma)
    end do
  end function chain_heading

  pure function direction_xy(c, sigma) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    real(wp) :: xy(2)
    real(wp) :: psi
    psi = chain_heading(c, sigma)
    xy = [cos(psi), sin(psi)]
  end function direction_xy

  pure subroutine chain_evaluate(self, u, order, p, status)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: psi, k(0:3), g(0:3), gint, cs, sn, a, du, m(2)
    integer :: node
    call profile(self, u, psi, k, g, gint)
    cs = cos(psi); sn = sin(psi)
    node = nearest_node(self, u)
    a = node*self%node_step
    du = u - a
    if (self%node_kind(node) == 0 .and. abs(du) <= self%node_step/2) then
      ! the chord of the arc from the node: its direction the bisector of the
      ! headings at both ends, its length du sinc(kappa du/2)
      m = self%node_dir(:, node) + [cs, sn]
      p%d(1:2, 0) = self%node_xy(:, node) + (du*sinc(0.5_wp*self%node_kappa(node)*du)/norm2(m))*m
    else if (self%node_kind(node) > 0 .and. abs(du) <= self%node_step/2) then
      p%d(1:2, 0) = transition_xy(self, u, node)
    else
      p%d(1:2, 0) = quadrature_xy(self, u, node)
    end if
    p%order = min(max(order, 0), 4)
    p%d(3, 0) = self%start(3) - gint
    if (order >= 1) p%d(:, 1) = [cs, sn, -g(0)]
    if (order >= 2) p%d(:, 2) = [-k(0)*sn, k(0)*cs, -g(1)]
    if (order >= 3) p%d(:, 3) = [-k(0)**2*cs - k(1)*sn, -k(0)**2*sn + k(1)*cs, -g(2)]
    if (order >= 4) p%d(:, 4) = [k(0)**3*sn - 3*k(0)*k(1)*cs - k(2)*sn, &
                                 -k(0)**3*cs - 3*k(0)*k(1)*sn + k(2)*cs, -g(3)]
    status%code = STATUS_OK
  end subroutine chain_evaluate

  !> The node nearest to sigma (0 .. the last).
  pure integer function nearest_node(c, sigma) result(node)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    node = nint(sigma/c%node_step)
    node = max(0, min(node, ubound(c%node_xy, 2)))
  end function nearest_node

  !> x, y at sigma by 8-point Gauss-Legendre of the heading from `node`.
  pure function quadrature_xy(c, sigma, node) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    integer, intent(in) :: node
    real(wp) :: xy(2)
    real(wp) :: a, s, acc(2)
    integer :: i
    a = node*c%node_step
    acc = 0
    do i = 1, 8
      s = 0.5_wp*(a + sigma) + 0.5_wp*(sigma - a)*gl8_x(i)
      acc = acc + gl8_w(i)*direction_xy(c, s)
    end do
    xy = c%node_xy(:, node) + 0.5_wp*(sigma - a)*acc
  end function quadrature_xy

  !> quadrature_xy where joint j = node_kind(node) alone of the transitions
  !> reaches into the node's half-steps (and no bowl): the heading there is
  !> the node's plus its linear part and the ramp's,
  !>   psi(s) = psi_node + kappa_j (s - a) + dkappa_j w_j (P(t(s)) - P(t(a))).
  pure function transition_xy(c, sigma, node) result(xy)
    class(element_chain_curve_t), intent(in) :: c
    real(wp), intent(in) :: sigma
    integer, intent(in) :: node
    real(wp) :: xy(2)
    real(wp) :: a, s, acc(2), psi, dk, w
    integer :: i, j
    j = c%node_kind(node)
    a = node*c%node_step
    w = c%width(j)
    dk = (c%kappa(j + 1) - c%kappa(j))*w
    acc = 0
    do i = 1, 8
      s = 0.5_wp*(a + sigma) + 0.5_wp*(sigma - a)*gl8_x(i)
      psi = c%node_psi(node) + c%node_kappa(node)*(s - a) + &
            dk*(smoothstep_integral((s - c%joint(j) + w/2)/w) - c%node_ramp(node))
      acc = acc + gl8_w(i)*[cos(psi), sin(psi)]
    end do
    xy = c%node_xy(:, node) + 0.5_wp*(sigma - a)*acc
  end function transition_xy

  !> The point at u with x, y by the quadrature from the nearest node
  !> wherever the heading is (the evaluation's chord differs from it by
  !> rounding): the points the chain's fits take (geometry_slide_builder),
  !> the same as before the chord.
  pure function chain_quadrature_point(self, u) result(x)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: x(3)
    real(wp) :: psi, k(0:3), g(0:3), gint
    call profile(self, u, psi, k, g, gint)
    x(1:2) = quadrature_xy(self, u, nearest_node(self, u))
    x(3) = self%start(3) - gint
  end function chain_quadrature_point

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

  !> How the heading behaves over [lo, hi] (node_kind): 0 linear in sigma
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

  !> |c_u| = sqrt(1 + g^2) at u (the arc length's integrand, geometry_curve):
  !> the gradient alone, without the heading and the position.
  pure real(wp) function chain_speed(self, u) result(speed)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: g, w, t
    integer :: j
    g = self%grad(1)
    do j = 1, size(self%joint)
      w = self%width(j)
      if (.not. w > 0) cycle
      t = (u - self%joint(j) + w/2)/w
      if (t <= 0) cycle
      g = g + (self%grad(j + 1) - self%grad(j))*smoothstep_value(t)
    end do
    if (self%starts_with_drop) g = g + self%drop%gradient_deviation(u)
    do j = 1, size(self%bowls)
      g = g + self%bowls(j)%gradient_deviation(u)
    end do
    speed = sqrt(1 + g*g)
  end function chain_speed

  pure subroutine chain_domain(self, u_min, u_max)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(out) :: u_min, u_max
    u_min = 0; u_max = self%total
  end subroutine chain_domain

  !> Index of the element that contains sigma (1..n).
  pure integer function chain_element_at(self, sigma) result(i)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: sigma
    do i = 1, size(self%ends) - 1
      if (sigma <= self%ends(i)) return
    end do
    i = size(self%ends)
  end function chain_element_at

  !> Points of the centerline every ~`spacing` m of horizontal length (at
  !> least one per element end) and the horizon vector at each, for fitting.
  subroutine slide_points(chain, spacing, points, horizon, sigma)
    type(element_chain_curve_t), intent(in) :: chain
    real(wp), intent(in) :: spacing
    real(wp), allocatable, intent(out) :: points(:, :), horizon(:, :), sigma(:)
    integer :: n, i
    n = max(2, ceiling(chain%total/spacing) + 1)
    allocate (points(3, n), horizon(3, n), sigma(n))
    do i = 1, n
      sigma(i) = chain%total*(i - 1)/real(n - 1, wp)
      points(:, i) = chain%quadrature_point(sigma(i))
      horizon(:, i) = [0.0_wp, 0.0_wp, 1.0_wp]
    end do
  end subroutine slide_points

  !> Arc length from u0 to u1 (m): curve_t's quadrature, its whole panels
  !> from the start taken from the table made with the chain (the same value
  !> to the bit; a record asks for s(u) from the start for every contact).
  pure function chain_arc_length(self, u0, u1) result(s)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: u0, u1
    real(wp) :: s
    if (allocated(self%arc_prefix)) then
      s = panel_arc_length(self, u0, u1, self%arc_prefix)
    else
      s = panel_arc_length(self, u0, u1)
    end if
  end function chain_arc_length

  !> u is the horizontal arc length sigma (m).
  pure function chain_parameter_unit(self) result(unit)
    class(element_chain_curve_t), intent(in) :: self
    character(len=:), allocatable :: unit
    associate (unused => self)
    end associate
    unit = 'm'
  end function chain_parameter_unit
end module geometry_slide_elements
