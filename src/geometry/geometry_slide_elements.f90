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
!> are int [cos psi, sin psi] dsigma, tabulated at knots and completed from
!> the nearer knot of the span (geometry_slide_chain_xy): the knots lie every
!> <= 0.5 m, and where a transition bends the heading at its window's ends
!> and every w/16 inside it, so the 8-point Gauss-Legendre quadratures that
!> make and complete the table never cross a window's end (where the
!> heading is only C4) and span at most w/16 of a ramp; where the heading
!> is linear the completion is the chord of the arc (exact to rounding).
!> Positions are exact to ~1e-14 m everywhere, across the ramps too
!> (test_slide_chain_evaluation against a fine reference quadrature).
!> The fits of the chain (geometry_slide_builder) take their points from
!> the table they always had (quadrature_point: nodes every 0.5 m, each by
!> 8-point Gauss-Legendre over a whole node step, completed by the same
!> quadrature from the nearest node), kept apart so the fitted slides stay
!> the same to the bit: its quadratures across the windows' ends leave up
!> to 2e-9 m with 1.5 to 2 m transitions, 1.6e-6 m with 0.3 m ones
!> (carried on to the nodes after them; bench/README.md "The exact chain's
!> positions exact"), small beside the fit's own error at 2 m.
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
  use geometry_curve, only: curve_t, curve_point_t, panel_arc_length, arc_length_prefix
  use geometry_drop_profile, only: drop_profile_t, new_drop_profile, smoothstep, smoothstep_value, smoothstep_integral
  use geometry_slide_bowl, only: bowl_spiral_t, new_bowl_spiral
  implicit none (type, external)
  private
  public :: slide_element_t, element_chain_curve_t, new_element_chain, slide_points
  public :: element_kinds
  !> The steepest slope of a straight, curve, runout, funnel, patch or helix
  !> (only a drop is steeper), the one limit the input tables check too; its
  !> tangent exact for the helix's drop per horizontal length.
  real(wp), parameter, public :: max_element_slope_deg = 45, max_element_slope_tan = 1

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
    real(wp), allocatable :: node_xy(:, :)  ! m, x, y at sigma = k*node_step: the fits' table (quadrature_point)
    ! the evaluation's x, y (chain_evaluate, geometry_slide_chain_xy): knots
    ! from 0 to total, span i from knot(i - 1) to knot(i)
    real(wp), allocatable :: knot(:)        ! m, sigma of the knots (0:n)
    real(wp), allocatable :: knot_xy(:, :)  ! m, x, y there
    real(wp), allocatable :: knot_psi(:)    ! rad, the heading there
    real(wp), allocatable :: knot_dir(:, :) ! its cos and sin
    ! per span (1:n): 0 the heading linear (the chord), j > 0 within joint j's
    ! window (the quadrature of the node's heading plus its ramp), -1 a bowl
    ! reaches in (the quadrature of the whole heading)
    integer, allocatable :: span_kind(:)
    real(wp), allocatable :: span_kappa(:)  ! 1/m, kappa of the heading's linear part (kind >= 0)
    integer, allocatable :: cell_knot(:)    ! the last knot at or below k*node_step (k = 0 .. cells)
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

  interface
    ! the chain's x, y (geometry_slide_chain_xy)

    !> Tabulates x, y: the fits' nodes and the evaluation's knots.
    module subroutine build_xy_table(c)
      type(element_chain_curve_t), intent(inout) :: c
    end subroutine build_xy_table

    !> x, y at sigma from the knots; dir the cos and sin of the heading there.
    pure module function chain_xy(c, sigma, dir) result(xy)
      class(element_chain_curve_t), intent(in) :: c
      real(wp), intent(in) :: sigma, dir(2)
      real(wp) :: xy(2)
    end function chain_xy

    !> x, y at sigma by 8-point Gauss-Legendre of the whole heading from a
    !> (where x, y are xy_a).
    pure module function heading_quadrature(c, a, xy_a, sigma) result(xy)
      class(element_chain_curve_t), intent(in) :: c
      real(wp), intent(in) :: a, xy_a(2), sigma
      real(wp) :: xy(2)
    end function heading_quadrature
  end interface

contains

  !> The chain of `elements` starting at `start` (m) with heading `heading_deg`
  !> (deg from +x towards +y), with transitions of horizontal length
  !> `transition` (m, >= 0). Checks every element; the message names it.
  function new_element_chain(elements, start, heading_deg, transition, status) result(c)
    type(slide_element_t), intent(in) :: elements(:)
    real(wp), intent(in) :: start(3), heading_deg, transition
    type(status_t), intent(out) :: status
    type(element_chain_curve_t) :: c
    integer :: n, i, nb
    real(wp) :: len_h(size(elements)), sgn, a, b
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
        if (any(e%kind == [character(len=8) :: 'straight', 'runout', 'funnel', 'patch', 'curve'])) then
          if (.not. abs(e%slope_deg) <= max_element_slope_deg) then
            call fail('slope must lie in [-'//steepest()//', '//steepest()//'] deg (only a drop is steeper)')
            return
          end if
        end if
        select case (e%kind)
        case ('straight', 'runout', 'funnel', 'patch')
          if (.not. e%length > 0) then
            call fail('length must be > 0 m')
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
          if (.not. abs(e%drop) <= max_element_slope_tan*len_h(i)) then
            call fail('drop per horizontal length must correspond to a slope of at most '//steepest()//' deg')
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
    call build_xy_table(c)
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

    function steepest() result(text)
      character(len=:), allocatable :: text
      text = format_integer(nint(max_element_slope_deg))
    end function steepest
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

  pure subroutine chain_evaluate(self, u, order, p, status)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    integer, intent(in) :: order
    type(curve_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    real(wp) :: psi, k(0:3), g(0:3), gint, cs, sn
    call profile(self, u, psi, k, g, gint)
    cs = cos(psi); sn = sin(psi)
    p%d(1:2, 0) = chain_xy(self, u, [cs, sn])
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

  !> The point at u with x, y by the quadrature from the nearest node
  !> wherever the heading is (the evaluation's chord differs from it by
  !> rounding): the points the chain's fits take (geometry_slide_builder),
  !> the same as before the chord.
  pure function chain_quadrature_point(self, u) result(x)
    class(element_chain_curve_t), intent(in) :: self
    real(wp), intent(in) :: u
    real(wp) :: x(3)
    real(wp) :: psi, k(0:3), g(0:3), gint
    integer :: node
    call profile(self, u, psi, k, g, gint)
    node = nearest_node(self, u)
    x(1:2) = heading_quadrature(self, node*self%node_step, self%node_xy(:, node), u)
    x(3) = self%start(3) - gint
  end function chain_quadrature_point

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
