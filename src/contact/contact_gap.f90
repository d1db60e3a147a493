!> The signed gap between two placed surfaces: the distance along their common
!> normal, positive while they are apart (flight and landing, issue 25: while
!> a contact is open its gap is the event function of the landing).
!>
!> Surface i sits on its body with rotation R_i and origin o_i (world point
!> o_i + R_i s_i(u_i, v_i)) and a side (+1, -1) that turns its normal
!> n_i = side_i (s_u x s_v)/|s_u x s_v| out of its body, towards the other,
!> as a contact's side_1 and side_2 do (contact_pair). The common normal is
!> where d = r_2 - r_1 is along n_1 and n_1 is normal to surface 2:
!>   f = [d . t1_u, d . t1_v, n_1 . t2_u, n_1 . t2_v] = 0,
!> (t the world tangents), solved by Newton (4 x 4, the analytic Jacobian from
!> the second derivatives and n_1's Weingarten derivatives) from the last
!> solution, with steps halved while the residual grows. The gap is n_1 . d;
!> the solution is on the contact's branch when n_1 . n_2 < 0. For a convex
!> body near a surface the common normal found from the last one is the
!> closest approach; the caller starts it where the contact opened (the two
!> contact points), or from a search (start_from_search).
!>
!> Poles: a surface with charts (an ellipsoid) is tracked in the chart whose
!> poles are farthest from the point (surface_t's chart hooks, as the surface
!> joint does): when a point's chart margin falls below chart_switch_margin the
!> point moves to the chart chart_toward names, the same point in new
!> parameters. The gap's rate is the normal relative speed of the two
!> material points, n_1 . (v_2(P_2) - v_1(P_1)) (the points' own motion along
!> the surfaces drops out at a common normal).
module contact_gap
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_vector, only: cross, identity3
  use base_status, only: status_t, set_status, prefix_status, STATUS_NOT_CONVERGED, STATUS_DOMAIN
  use geometry_surface, only: surface_t, surface_point_t
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use contact_surface_search, only: nearest_point, support_point
  implicit none (type, external)
  private
  public :: contact_gap_t, new_contact_gap, gap_equations

  integer, parameter :: max_newton_steps = 40
  integer, parameter :: max_halvings = 30
  !> Change chart when cos v - cos(limit) (the chart margin) is below this.
  real(wp), parameter :: chart_switch_margin = 0.02_wp

  !> One surface as the gap tracks it: the surface, its current chart
  !> (r = chart_rotation r'), its side, and its pose on its body.
  type :: gap_surface_t
    class(surface_t), allocatable :: base, chart
    real(wp) :: chart_rotation(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    real(wp) :: side = 1
    real(wp) :: rotation(3, 3) = 0, origin(3) = 0   !< the body's pose (world)
  end type gap_surface_t

  type :: contact_gap_t
    type(gap_surface_t) :: surface(2)
    real(wp) :: x(4) = 0                 !< (u1, v1, u2, v2) in the current charts
    real(wp) :: gap = 0                  !< m, n_1 . (r_2 - r_1)
    real(wp) :: point_1(3) = 0, point_2(3) = 0   !< m, world
    real(wp) :: normal(3) = 0            !< n_1, world, out of body 1
    real(wp) :: normals_cosine = 0       !< n_1 . n_2 (-1 for a contact's branch)
    integer :: newton_steps = 0          !< of the last update
  contains
    procedure :: start_from_search => gap_start_from_search
    procedure :: update => gap_update
    procedure :: rate => gap_rate
    procedure :: parameters => gap_parameters
  end type contact_gap_t

contains

  !> The gap between surface_1 (side_1) on body 1 and surface_2 (side_2) on
  !> body 2, started at (u1, v1, u2, v2) in the surfaces' own parameters.
  function new_contact_gap(surface_1, side_1, surface_2, side_2, x) result(self)
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: side_1, side_2, x(4)
    type(contact_gap_t) :: self
    allocate (self%surface(1)%base, source=surface_1)
    allocate (self%surface(1)%chart, source=surface_1)
    allocate (self%surface(2)%base, source=surface_2)
    allocate (self%surface(2)%chart, source=surface_2)
    self%surface(1)%side = side_1
    self%surface(2)%side = side_2
    self%x = x
  end function new_contact_gap

  !> A start without a last solution: the point of surface 1 nearest to body
  !> 2's origin, and surface 2's support point against that point's normal
  !> (body 2 convex there); then update.
  subroutine gap_start_from_search(self, rotation_1, origin_1, rotation_2, origin_2, status)
    class(contact_gap_t), intent(inout) :: self
    real(wp), intent(in) :: rotation_1(3, 3), origin_1(3), rotation_2(3, 3), origin_2(3)
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: pt
    real(wp) :: n1(3)
    self%surface(1)%chart_rotation = identity3()
    self%surface(2)%chart_rotation = identity3()
    deallocate (self%surface(1)%chart, self%surface(2)%chart)
    allocate (self%surface(1)%chart, source=self%surface(1)%base)
    allocate (self%surface(2)%chart, source=self%surface(2)%base)
    call nearest_point(self%surface(1)%base, matmul(transpose(rotation_1), origin_2 - origin_1), self%x(1), &
      self%x(2), status)
    if (.not. status%ok()) return
    call self%surface(1)%base%evaluate(self%x(1), self%x(2), 1, pt, status)
    if (.not. status%ok()) return
    n1 = self%surface(1)%side*matmul(rotation_1, cross(pt%ru, pt%rv))
    ! Surface 2's point extreme against n_1 (its normal there is -n_1).
    call support_point(self%surface(2)%base, matmul(transpose(rotation_2), n1), self%x(3), self%x(4), status)
    if (.not. status%ok()) return
    call self%update(rotation_1, origin_1, rotation_2, origin_2, status)
  end subroutine gap_start_from_search

  !> The gap at the bodies' poses (rotation_i, origin_i), from the last solution.
  subroutine gap_update(self, rotation_1, origin_1, rotation_2, origin_2, status)
    class(contact_gap_t), intent(inout) :: self
    real(wp), intent(in) :: rotation_1(3, 3), origin_1(3), rotation_2(3, 3), origin_2(3)
    type(status_t), intent(inout) :: status
    real(wp) :: f(4), jac(4, 4), dx(4), trial(4), f_trial(4), size_f, scale
    integer :: ipiv(4), step, halving
    self%surface(1)%rotation = rotation_1
    self%surface(1)%origin = origin_1
    self%surface(2)%rotation = rotation_2
    self%surface(2)%origin = origin_2
    call keep_charts(self, status)
    if (.not. status%ok()) return
    call residual(self, self%x, f, jac, status)
    if (.not. status%ok()) return
    scale = 1 + norm2(self%point_2 - self%point_1)
    self%newton_steps = 0
    do step = 1, max_newton_steps
      size_f = norm2(f)
      if (size_f <= 64*epsilon(1.0_wp)*scale*tangent_scale(jac)) exit
      call lu_factor(jac, ipiv, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'gap: the common normal is not regular here')
        return
      end if
      dx = -f
      call lu_solve(jac, ipiv, dx, status)
      if (.not. status%ok()) return
      do halving = 0, max_halvings
        trial = self%x + dx
        call residual(self, trial, f_trial, jac, status)
        if (.not. status%ok()) return
        if (norm2(f_trial) < size_f .or. maxval(abs(dx)) <= 4*epsilon(1.0_wp)*(1 + maxval(abs(self%x)))) exit
        dx = dx/2
      end do
      self%x = trial
      f = f_trial
      self%newton_steps = step
      if (maxval(abs(dx)) <= 4*epsilon(1.0_wp)*(1 + maxval(abs(self%x)))) exit
    end do
    if (norm2(f) > 1e-9_wp*scale*tangent_scale(jac)) then
      call set_status(status, STATUS_NOT_CONVERGED, 'gap: no common normal found from the last one (residual '// &
        format_short(norm2(f))//')')
      return
    end if
    ! The last residual call was at self%x (the start's or the accepted
    ! trial's), so the points, normal and gap are already those of self%x.
  end subroutine gap_update

  !> The rate of the gap: n_1 . (v_2(P_2) - v_1(P_1)), each body moving with
  !> its origin's velocity and its angular velocity (world).
  pure real(wp) function gap_rate(self, velocity_1, omega_1, velocity_2, omega_2) result(rate)
    class(contact_gap_t), intent(in) :: self
    real(wp), intent(in) :: velocity_1(3), omega_1(3), velocity_2(3), omega_2(3)
    real(wp) :: v1(3), v2(3)
    v1 = velocity_1 + cross(omega_1, self%point_1 - self%surface(1)%origin)
    v2 = velocity_2 + cross(omega_2, self%point_2 - self%surface(2)%origin)
    rate = dot_product(self%normal, v2 - v1)
  end function gap_rate

  !> (u1, v1, u2, v2) of the two points in the surfaces' own parameters (the
  !> base charts), e.g. to close the contact there.
  subroutine gap_parameters(self, x, status)
    class(contact_gap_t), intent(in) :: self
    real(wp), intent(out) :: x(4)
    type(status_t), intent(inout) :: status
    integer :: i
    type(surface_point_t) :: pt
    x = self%x
    do i = 1, 2
      if (.not. self%surface(i)%base%has_charts()) cycle
      call self%surface(i)%chart%evaluate(self%x(2*i - 1), self%x(2*i), 0, pt, status)
      if (.not. status%ok()) return
      call self%surface(i)%base%chart_parameters(matmul(self%surface(i)%chart_rotation, pt%r), x(2*i - 1), x(2*i), &
        status)
      if (.not. status%ok()) return
    end do
  end subroutine gap_parameters

  !> Move a point whose chart margin is small to the chart farthest from its poles.
  subroutine keep_charts(self, status)
    type(contact_gap_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: pt
    real(wp) :: r(3), p(3, 3)
    integer :: i, k
    do i = 1, 2
      associate (s => self%surface(i))
        if (.not. s%base%has_charts()) cycle
        if (s%chart%chart_margin(self%x(2*i)) >= chart_switch_margin) cycle
        call s%chart%evaluate(self%x(2*i - 1), self%x(2*i), 0, pt, status)
        if (.not. status%ok()) return
        r = matmul(s%chart_rotation, pt%r)
        k = s%base%chart_toward(r)
        call s%base%chart(k, s%chart, p)
        s%chart_rotation = p
        call s%chart%chart_parameters(matmul(transpose(p), r), self%x(2*i - 1), self%x(2*i), status)
        if (.not. status%ok()) return
      end associate
    end do
  end subroutine keep_charts

  !> f(x) and its Jacobian at the gap's last poses, in its current charts;
  !> the gap itself unchanged. For checking the Jacobian against
  !> differences (it copies the gap: not for inner loops).
  subroutine gap_equations(gap, x, f, jac, status)
    type(contact_gap_t), intent(in) :: gap
    real(wp), intent(in) :: x(4)
    real(wp), intent(out) :: f(4), jac(4, 4)
    type(status_t), intent(inout) :: status
    type(contact_gap_t) :: probe
    probe = gap
    call residual(probe, x, f, jac, status)
  end subroutine gap_equations

  !> f(x) and its Jacobian, and the points, normal and gap at x.
  subroutine residual(self, x, f, jac, status)
    type(contact_gap_t), intent(inout) :: self
    real(wp), intent(in) :: x(4)
    real(wp), intent(out) :: f(4), jac(4, 4)
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: p1, p2
    real(wp) :: q1(3, 3), q2(3, 3), r1(3), r2(3), a1(3), b1(3), a2(3), b2(3), a1u(3), a1v(3), b1v(3), &
      a2u(3), a2v(3), b2v(3), w(3), w_u(3), w_v(3), n1(3), n1_u(3), n1_v(3), d(3), wn, n2(3)
    call self%surface(1)%chart%evaluate(x(1), x(2), 2, p1, status)
    if (.not. status%ok()) return
    call self%surface(2)%chart%evaluate(x(3), x(4), 2, p2, status)
    if (.not. status%ok()) return
    q1 = matmul(self%surface(1)%rotation, self%surface(1)%chart_rotation)
    q2 = matmul(self%surface(2)%rotation, self%surface(2)%chart_rotation)
    r1 = self%surface(1)%origin + matmul(q1, p1%r)
    r2 = self%surface(2)%origin + matmul(q2, p2%r)
    a1 = matmul(q1, p1%ru); b1 = matmul(q1, p1%rv)
    a1u = matmul(q1, p1%ruu); a1v = matmul(q1, p1%ruv); b1v = matmul(q1, p1%rvv)
    a2 = matmul(q2, p2%ru); b2 = matmul(q2, p2%rv)
    a2u = matmul(q2, p2%ruu); a2v = matmul(q2, p2%ruv); b2v = matmul(q2, p2%rvv)
    w = cross(a1, b1)
    wn = norm2(w)
    if (.not. (wn > 0)) then
      call set_status(status, STATUS_DOMAIN, 'gap: surface 1 has no normal at its point (a singular point)')
      return
    end if
    n1 = self%surface(1)%side*w/wn
    ! Weingarten: d n/du = side (w_u - (w_u . w^) w^)/|w|, w_u = a_u x b + a x b_u.
    w_u = cross(a1u, b1) + cross(a1, a1v)
    w_v = cross(a1v, b1) + cross(a1, b1v)
    n1_u = self%surface(1)%side*(w_u - dot_product(w_u, w)/wn**2*w)/wn
    n1_v = self%surface(1)%side*(w_v - dot_product(w_v, w)/wn**2*w)/wn
    d = r2 - r1
    f = [dot_product(d, a1), dot_product(d, b1), dot_product(n1, a2), dot_product(n1, b2)]
    jac(1, :) = [-dot_product(a1, a1) + dot_product(d, a1u), -dot_product(b1, a1) + dot_product(d, a1v), &
      dot_product(a2, a1), dot_product(b2, a1)]
    jac(2, :) = [-dot_product(a1, b1) + dot_product(d, a1v), -dot_product(b1, b1) + dot_product(d, b1v), &
      dot_product(a2, b1), dot_product(b2, b1)]
    jac(3, :) = [dot_product(n1_u, a2), dot_product(n1_v, a2), dot_product(n1, a2u), dot_product(n1, a2v)]
    jac(4, :) = [dot_product(n1_u, b2), dot_product(n1_v, b2), dot_product(n1, a2v), dot_product(n1, b2v)]
    n2 = cross(a2, b2)
    self%point_1 = r1
    self%point_2 = r2
    self%normal = n1
    self%gap = dot_product(n1, d)
    self%normals_cosine = 0
    if (norm2(n2) > 0) self%normals_cosine = self%surface(2)%side*dot_product(n1, n2)/norm2(n2)
  end subroutine residual

  !> The size of the tangents, for the residual's scale.
  pure real(wp) function tangent_scale(jac)
    real(wp), intent(in) :: jac(4, 4)
    tangent_scale = max(1.0_wp, maxval(abs(jac)))
  end function tangent_scale
end module contact_gap
