!> The surface joint (thesis 3.5.1): input frame K_1 and surface parameters
!> (u, v) -> the Darboux frame K_D at r(u, v) on a surface given in K_1.
!>
!> Position (3.43): R_D = R_1 [x_D y_D z_D], r_D = r_1 + R_1 r(u, v).
!> Velocity (3.53): with the frame rates a..f of (3.45) the relative angular
!> velocity in K_1 coordinates is W_u u' + W_v v' with (from (3.44))
!>     W_u = (z.e) x + (x.c) y + (y.a) z,   W_v = (z.f) x + (x.d) y + (y.b) z,
!> so  omega_D = omega_1 + R_1 (W_u u' + W_v v'),
!>     v_D = v_1 + omega_1 x p + R_1 (r_u u' + r_v v'),  p = R_1 r.
!> Acceleration (appendix B, written with the u/v derivatives of W):
!>     alpha_D = alpha_1 + R_1 (W_u u'' + W_v v'' + W_u' u' + W_v' v') + omega_1 x R_1 (W_u u' + W_v v')
!>     a_D = a_1 + alpha_1 x p + omega_1 x (omega_1 x p) + 2 omega_1 x R_1 (r_u u' + r_v v')
!>           + R_1 (r_u u'' + r_v v'' + r_uu u'^2 + 2 r_uv u' v' + r_vv v'^2)       (B.10), (B.11)
!> with W_u' = W_u,u u' + W_u,v v' from the second derivatives of the frame
!> axes (geometry_darboux). This replaces (B.2)-(B.9), whose printed form
!> carries conversion errors (B.2 has dots missing; B.4 r_vv for r_uv); the test
!> compares every level with finite differences of the level below.
!> Force (3.54): f_1 += f_D, tau_1 += tau_D + p x f_D,
!>     Q_u = (R_1 W_u).tau_D + (R_1 r_u).f_D,  Q_v likewise.
!>
!> Singular points (r_u = 0, rule (3.40)): the frame is the rule's, which is
!> the limit of the regular frame. Its rates from (A.3)-(A.7) are not used:
!> they differentiate the rule's field r_v x (r_v x r_vv), which equals the
!> normal only on the singular line, so they differ from the limit of the
!> regular rates (at the apex of the apex paraboloid by O(1); test_elements
!> shows it). W_u, W_v and their derivatives are instead extrapolated from the
!> regular side along v (off the singular line): X(v0) = 2 X(v0 + h) - X(v0 + 2h),
!> h = +-1e-4 towards the inside of the domain, error O(h^2) ~ 1e-8 relative,
!> used only at the singular points themselves (|r_u| <= 1.5e-8 |r_v|).
!>
!> Lazy geometry: at a regular point the position map needs only the frame's
!> axes (r_u, r_v: the surface to order 1), and most position passes are
!> iterates of the closure's Newton, never followed by a velocity pass. So
!> the position pass keeps (u, v) and R_1 and computes the rates and their
!> derivatives (order 3) only when the first velocity, acceleration or force
!> map after it asks for them (`complete_geometry`: the same numbers as an
!> eager evaluation). `lazy = .false.` computes everything in the position
!> pass (for owners that read the components directly); singular points are
!> always evaluated at once (their frame needs order 3 and may fail).
!>
!> Charts: a surface's parametrisation may be singular at poles (an
!> ellipsoid's (3.57) at v = +-pi/2, r_u = 0: the Darboux frame and u' are
!> undefined there), where the same surface has other charts that are
!> regular (geometry_surface's chart hooks). `change_chart` moves the joint
!> to the chart (chart_toward, chart: r = P r') in which its point lies
!> farthest from the poles, keeping the motion: (u, v) become the new
!> chart's parameters of the same point, (u', v') those of the same
!> velocity over the surface (least squares: it is tangent). The joint then
!> evaluates the chart's surface on the input frame turned by P (R_1 P): the
!> point, its tangent plane and its normal are unchanged, and the two
!> charts' Darboux frames differ by a turn beta about the normal. A joint
!> built with `charts` (a contact's S1 on body 1) watches chart_margin(v)
!> (kinetostatics_state's chart interface) and changes at its zero; its
!> output frame then turns by beta, which the turn about the output's z
!> that follows it (`turn`: the open chain's phi, the loop's first
!> free-rotation angle, both about the normal) takes back, phi - beta, and
!> phi' the difference of the two frames' turn rates about the normal, so
!> what the turn carries keeps its pose and motion. Without a turn (the
!> loop's S1, whose (u, v) are dependent coordinates) the contact frame
!> turns by beta about its normal, which the closure (3.86) and the no-slip
!> condition do not see. The inverse surface joint changes the charts of
!> its surface with the same `change_chart`.
module kinetostatics_surface_joint
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, prefix_status, STATUS_DOMAIN
  use base_vector, only: cross
  use base_text, only: format_short
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame, darboux_axes
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t, domain_edge_t, &
    surface_chart_t
  implicit none (type, external)
  private
  public :: surface_joint_t, new_surface_joint, domain_edge_margin, put_chart_coordinates

  type, extends(element_t) :: surface_joint_t
    class(surface_t), allocatable :: surface
    integer :: frame_in = 0, frame_out = 0, var_u = 0, var_v = 0
    real(wp) :: sigma = 1, alpha_u = 1, alpha_v = 0   ! (3.38), (3.41)
    ! geometry at the last position (world coordinates unless noted)
    type(surface_point_t) :: point
    type(darboux_frame_t) :: frame
    real(wp) :: p(3) = 0                        ! R_1 r
    real(wp) :: gu(3) = 0, gv(3) = 0            ! R_1 W_u, R_1 W_v
    real(wp) :: tu(3) = 0, tv(3) = 0            ! R_1 r_u, R_1 r_v
    real(wp) :: guu(3) = 0, guv(3) = 0, gvu(3) = 0, gvv(3) = 0   ! R_1 W_u,u ...
    real(wp) :: huu(3) = 0, huv(3) = 0, hvv(3) = 0               ! R_1 r_uu ...
    real(wp) :: w_rel(3) = 0, omega_rel(3) = 0  ! relative velocities (world) at the last velocity pass
    ! lazy geometry (module comment): the last position's (u, v) and R_1, and
    ! whether point, frame and the rotated vectors above belong to them
    logical :: lazy = .true.
    logical :: complete = .false.
    real(wp) :: u = 0, v = 0, rot_in(3, 3) = 0
    ! charts (module comment): the surface in its own chart and P (r = P r'),
    ! used after the first change; `charts`: the joint changes them itself
    class(surface_t), allocatable :: own_surface
    real(wp) :: chart(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    logical :: charts = .false.
    integer :: var_turn = 0
    integer :: rebases = 0
    integer :: chart_index = 0   ! chart_toward's name of the chart in use (0: the own one, never changed)
  contains
    procedure :: position => sj_position
    procedure :: velocity => sj_velocity
    procedure :: acceleration => sj_acceleration
    procedure :: force => sj_force
    procedure :: complete_geometry => sj_complete_geometry
    procedure :: check_domain => sj_check_domain
    procedure :: local_geometry => sj_local_geometry
    procedure :: links => sj_links
    procedure :: domain_edges => sj_domain_edges
    procedure :: set_eager => sj_set_eager
    procedure :: position_complete => sj_position_complete
    procedure :: singular_note => sj_singular_note
    procedure :: change_chart => sj_change_chart
    procedure :: chart_angle => sj_chart_angle
    procedure :: chart_margin => sj_chart_margin
    procedure :: rebase => sj_rebase
    procedure :: chart_changes => sj_chart_changes
    procedure :: start_chart => sj_start_chart
    procedure :: set_chart_turn => sj_set_chart_turn
    procedure :: surface_chart => sj_surface_chart
    procedure :: take_surface_chart => sj_take_surface_chart
  end type surface_joint_t

contains

  !> How far inside an edge [low, high] of a parameter domain (a bound may be
  !> +-huge) a run's event at that edge is placed: 1e-7 of the domain's
  !> extent (of the finite bound's size, at least 1, when the other is
  !> infinite). The surface cannot be evaluated beyond the edge, so an
  !> integrator step ending there fails and is shortened; the event must lie
  !> where a step can still end beyond it.
  pure real(wp) function domain_edge_margin(low, high) result(margin)
    real(wp), intent(in) :: low, high
    if (low > -huge(low) .and. high < huge(high)) then
      margin = 1e-7_wp*max(high - low, 1.0_wp)
    else if (low > -huge(low)) then
      margin = 1e-7_wp*max(abs(low), 1.0_wp)
    else
      margin = 1e-7_wp*max(abs(high), 1.0_wp)
    end if
  end function domain_edge_margin

  !> charts: a surface with charts changes them near its poles (module
  !> comment); turn: the scalar of the turn about the output's z that
  !> follows the joint, if any.
  function new_surface_joint(name, frame_in, frame_out, var_u, var_v, surface, sigma, alpha_u, alpha_v, &
                             charts, turn) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, var_u, var_v
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    logical, intent(in), optional :: charts
    integer, intent(in), optional :: turn
    type(surface_joint_t) :: e
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%var_u = var_u
    e%var_v = var_v
    allocate (e%surface, source=surface)
    e%sigma = sigma
    e%alpha_u = alpha_u
    e%alpha_v = alpha_v
    if (present(charts)) then
      if (charts .and. surface%has_charts()) then
        e%charts = .true.
        allocate (e%own_surface, source=surface)
        if (present(turn)) e%var_turn = turn
      end if
    end if
  end function new_surface_joint

  !> W_u, W_v (K_1 coordinates) from a Darboux frame.
  pure subroutine angular_rates(fr, wu, wv)
    type(darboux_frame_t), intent(in) :: fr
    real(wp), intent(out) :: wu(3), wv(3)
    associate (x => fr%r(:, 1), y => fr%r(:, 2), z => fr%r(:, 3))
      wu = dot_product(z, fr%e)*x + dot_product(x, fr%c)*y + dot_product(y, fr%a)*z
      wv = dot_product(z, fr%f)*x + dot_product(x, fr%d)*y + dot_product(y, fr%b)*z
    end associate
  end subroutine angular_rates

  !> status: the joint's (u, v) left the surface's parameter domain.
  pure subroutine sj_check_domain(self, u, v, status)
    class(surface_joint_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    type(status_t), intent(inout) :: status
    character(len=24) :: tu, tv
    if (self%surface%in_domain(u, v)) return
    write (tu, '(es12.5)') u
    write (tv, '(es12.5)') v
    call set_status(status, STATUS_DOMAIN, 'surface joint '''//self%name//''': (u, v) = ('// &
                    trim(adjustl(tu))//', '//trim(adjustl(tv))//') left the parameter domain of the '// &
                    self%surface%describe())
  end subroutine sj_check_domain

  !> (3.43): the output frame from (u, v); the rest of the geometry at once
  !> only where `lazy` is off or the point is singular (module comment).
  pure subroutine sj_position(self, frames, scalars, status)
    class(surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: u, v, axes(3, 3)
    logical :: singular

    u = scalars(self%var_u)%q
    v = scalars(self%var_v)%q
    call sj_check_domain(self, u, v, status)
    if (.not. status%ok()) return
    self%u = u
    self%v = v
    if (self%rebases == 0) then
      self%rot_in = frames(self%frame_in)%rot
    else
      self%rot_in = matmul(frames(self%frame_in)%rot, self%chart)   ! the chart's surface on R_1 P
    end if
    self%complete = .false.
    singular = .true.
    if (self%lazy) then
      call self%surface%evaluate(u, v, 1, self%point, status)
      if (status%ok()) call darboux_axes(self%point, self%sigma, self%alpha_u, self%alpha_v, axes, singular, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'surface joint '''//self%name//'''')
        return
      end if
    end if
    if (singular) then
      call evaluate_geometry(self, status)
      if (.not. status%ok()) return
      axes = self%frame%r
      self%complete = .true.
    end if
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%p = matmul(self%rot_in, self%point%r)
      o%rot = matmul(self%rot_in, axes)
      o%r = i%r + self%p
    end associate
  end subroutine sj_position

  !> Point (order 3), Darboux frame, rates and their derivatives at the last
  !> position's (u, v), rotated by its R_1 into the world.
  pure subroutine evaluate_geometry(self, status)
    class(surface_joint_t), intent(inout) :: self
    type(status_t), intent(inout) :: status
    real(wp) :: rates(3, 6)
    call sj_local_geometry(self, self%u, self%v, rates, status)
    if (.not. status%ok()) return
    associate (rot => self%rot_in, pt => self%point)
      self%p = matmul(rot, pt%r)
      self%gu = matmul(rot, rates(:, 1))
      self%gv = matmul(rot, rates(:, 2))
      self%tu = matmul(rot, pt%ru)
      self%tv = matmul(rot, pt%rv)
      self%guu = matmul(rot, rates(:, 3))
      self%guv = matmul(rot, rates(:, 4))
      self%gvu = matmul(rot, rates(:, 5))
      self%gvv = matmul(rot, rates(:, 6))
      self%huu = matmul(rot, pt%ruu)
      self%huv = matmul(rot, pt%ruv)
      self%hvv = matmul(rot, pt%rvv)
    end associate
  end subroutine evaluate_geometry

  !> The geometry at (u, v) in the surface's coordinates: self%point (order
  !> 3), self%frame, and rates = [W_u, W_v, W_u,u, W_u,v, W_v,u, W_v,v].
  !> For owners that rotate it themselves (the inverse joint).
  pure subroutine sj_local_geometry(self, u, v, rates, status)
    class(surface_joint_t), intent(inout) :: self
    real(wp), intent(in) :: u, v
    real(wp), intent(out) :: rates(3, 6)
    type(status_t), intent(inout) :: status
    call self%surface%evaluate(u, v, 3, self%point, status)
    if (status%ok()) call darboux_frame(self%point, self%sigma, self%alpha_u, self%alpha_v, self%frame, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'surface joint '''//self%name//'''')
      return
    end if
    if (.not. self%frame%singular) then
      call angular_rates(self%frame, rates(:, 1), rates(:, 2))
      call rate_derivatives(self%frame, rates(:, 3), rates(:, 4), rates(:, 5), rates(:, 6))
    else
      call singular_rates(self, u, v, rates(:, 1), rates(:, 2), rates(:, 3), rates(:, 4), rates(:, 5), &
                          rates(:, 6), status)
    end if
  end subroutine sj_local_geometry

  !> The rates and their derivatives of the last position, if not yet there
  !> (the maps test `complete` themselves first: this is called once per
  !> position, they are called for every pass).
  !> The position pass evaluated this regular point to order 1 and built its
  !> frame, so order 3 cannot fail here; if it did, the geometry is NaN (the
  !> run stops at the next error test) rather than silently stale.
  pure subroutine sj_complete_geometry(self)
    class(surface_joint_t), intent(inout) :: self
    type(status_t) :: status
    real(wp) :: nan
    if (self%complete) return
    call evaluate_geometry(self, status)
    if (.not. status%ok()) then
      nan = ieee_value(nan, ieee_quiet_nan)
      self%gu = nan; self%gv = nan; self%tu = nan; self%tv = nan
      self%guu = nan; self%guv = nan; self%gvu = nan; self%gvv = nan
      self%huu = nan; self%huv = nan; self%hvv = nan
    end if
    self%complete = .true.
  end subroutine sj_complete_geometry

  !> u and v derivatives of W_u and W_v (product rule on the definitions above).
  pure subroutine rate_derivatives(fr, wuu, wuv, wvu, wvv)
    type(darboux_frame_t), intent(in) :: fr
    real(wp), intent(out) :: wuu(3), wuv(3), wvu(3), wvv(3)
    associate (x => fr%r(:, 1), y => fr%r(:, 2), z => fr%r(:, 3), a => fr%a, b => fr%b, &
               c => fr%c, d => fr%d, e => fr%e, f => fr%f)
      wuu = (dot_product(c, e) + dot_product(z, fr%e_u))*x + dot_product(z, e)*a &
          + (dot_product(a, c) + dot_product(x, fr%c_u))*y + dot_product(x, c)*e &
          + (dot_product(e, a) + dot_product(y, fr%a_u))*z + dot_product(y, a)*c
      wuv = (dot_product(d, e) + dot_product(z, fr%e_v))*x + dot_product(z, e)*b &
          + (dot_product(b, c) + dot_product(x, fr%c_v))*y + dot_product(x, c)*f &
          + (dot_product(f, a) + dot_product(y, fr%a_v))*z + dot_product(y, a)*d
      wvu = (dot_product(c, f) + dot_product(z, fr%f_u))*x + dot_product(z, f)*a &
          + (dot_product(a, d) + dot_product(x, fr%d_u))*y + dot_product(x, d)*e &
          + (dot_product(e, b) + dot_product(y, fr%b_u))*z + dot_product(y, b)*c
      wvv = (dot_product(d, f) + dot_product(z, fr%f_v))*x + dot_product(z, f)*b &
          + (dot_product(b, d) + dot_product(x, fr%d_v))*y + dot_product(x, d)*f &
          + (dot_product(f, b) + dot_product(y, fr%b_v))*z + dot_product(y, b)*d
    end associate
  end subroutine rate_derivatives

  !> At a singular point: W_u, W_v and their derivatives extrapolated from the
  !> regular side, X(v0) = 2 X(v0 + s h) - X(v0 + 2 s h) (see the module comment).
  pure subroutine singular_rates(self, u, v, wu, wv, wuu, wuv, wvu, wvv, status)
    class(surface_joint_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    real(wp), intent(out) :: wu(3), wv(3), wuu(3), wuv(3), wvu(3), wvv(3)
    type(status_t), intent(inout) :: status
    real(wp), parameter :: h0 = 1e-4_wp
    real(wp) :: x1(3, 6), x2(3, 6), h
    h = h0
    if (.not. self%surface%in_domain(u, v + 2*h)) h = -h0
    call regular_rates_at(self, u, v + h, x1, status)
    call regular_rates_at(self, u, v + 2*h, x2, status)
    x1 = 2*x1 - x2
    wu = x1(:, 1); wv = x1(:, 2); wuu = x1(:, 3); wuv = x1(:, 4); wvu = x1(:, 5); wvv = x1(:, 6)
    if (.not. status%ok()) call prefix_status(status, 'surface joint '''//self%name//''' near a singular point')
  end subroutine singular_rates

  !> W_u, W_v and their four derivatives at a regular point (columns).
  pure subroutine regular_rates_at(self, u, v, x, status)
    class(surface_joint_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    real(wp), intent(out) :: x(3, 6)
    type(status_t), intent(inout) :: status
    type(surface_point_t) :: pt
    type(darboux_frame_t) :: fr
    type(status_t) :: local
    x = 0
    if (.not. status%ok()) return
    call self%surface%evaluate(u, v, 3, pt, local)
    if (local%ok()) call darboux_frame(pt, self%sigma, self%alpha_u, self%alpha_v, fr, local)
    if (local%ok() .and. .not. fr%second_order) call set_status(local, STATUS_DOMAIN, &
      'no regular point within 2e-4 of the singular point')
    if (.not. local%ok()) then
      status = local
      return
    end if
    call angular_rates(fr, x(:, 1), x(:, 2))
    call rate_derivatives(fr, x(:, 3), x(:, 4), x(:, 5), x(:, 6))
  end subroutine regular_rates_at

  !> Links for kinetostatics_closure_blocks (element_links_t).
  pure subroutine sj_links(self, links)
    class(surface_joint_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], [self%var_u, self%var_v], [self%frame_out], [integer ::], &
                            carried=.true.)
  end subroutine sj_links

  pure subroutine sj_velocity(self, frames, scalars)
    class(surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: ud, vd
    if (.not. self%complete) call sj_complete_geometry(self)
    ud = scalars(self%var_u)%qd
    vd = scalars(self%var_v)%qd
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      self%omega_rel = self%gu*ud + self%gv*vd          ! (3.53)
      self%w_rel = self%tu*ud + self%tv*vd              ! (3.52)
      o%omega = i%omega + self%omega_rel
      if (any(i%omega /= 0)) then
        o%v = i%v + cross(i%omega, self%p) + self%w_rel
      else
        o%v = i%v + self%w_rel   ! the input frame at rest (closure Jacobian columns)
      end if
    end associate
  end subroutine sj_velocity

  !> (B.1), (B.10), (B.11). The products with the rates are skipped where the
  !> rates are zero (mass-matrix columns run with all velocities zero): the
  !> remaining terms are summed in the same order, so no bit changes.
  pure subroutine sj_acceleration(self, frames, scalars)
    class(surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: ud, vd, udd, vdd, omega_rel(3), w_rel(3), acc(3)
    logical :: moving, turning
    if (.not. self%complete) call sj_complete_geometry(self)
    ud = scalars(self%var_u)%qd
    vd = scalars(self%var_v)%qd
    udd = scalars(self%var_u)%qdd
    vdd = scalars(self%var_v)%qdd
    moving = ud /= 0 .or. vd /= 0
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      turning = any(i%omega /= 0)
      ! (B.1) with the rate derivatives in place of (B.2)-(B.9)
      acc = i%alpha + self%gu*udd + self%gv*vdd
      if (moving) then
        omega_rel = self%gu*ud + self%gv*vd
        w_rel = self%tu*ud + self%tv*vd
        acc = acc + (self%guu*ud + self%guv*vd)*ud + (self%gvu*ud + self%gvv*vd)*vd
        if (turning) acc = acc + cross(i%omega, omega_rel)
      end if
      o%alpha = acc
      ! (B.10), (B.11)
      acc = i%a + cross(i%alpha, self%p)
      if (turning) then
        acc = acc + cross(i%omega, cross(i%omega, self%p))
        if (moving) acc = acc + 2*cross(i%omega, w_rel)
      end if
      acc = acc + self%tu*udd + self%tv*vdd
      if (moving) acc = acc + self%huu*ud**2 + 2*self%huv*ud*vd + self%hvv*vd**2
      o%a = acc
    end associate
  end subroutine sj_acceleration

  pure subroutine sj_force(self, frames, scalars, inertia, applied)
    class(surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    if (.not. self%complete) call sj_complete_geometry(self)
    f = frames(self%frame_out)%force
    t = frames(self%frame_out)%torque
    ! no wrench (a contact frame loaded only by cut forces, in the first pass
    ! of an inverse dynamics) adds nothing
    if (all(f == 0) .and. all(t == 0)) return
    ! (3.54)
    frames(self%frame_in)%force = frames(self%frame_in)%force + f
    frames(self%frame_in)%torque = frames(self%frame_in)%torque + t + cross(self%p, f)
    scalars(self%var_u)%force = scalars(self%var_u)%force + dot_product(self%gu, t) + dot_product(self%tu, f)
    scalars(self%var_v)%force = scalars(self%var_v)%force + dot_product(self%gv, t) + dot_product(self%tv, f)
  end subroutine sj_force

  !> The finite, non-periodic edges of the surface's domain (u_min, u_max,
  !> v_min, v_max as far as they exist), each with its event's margin.
  pure subroutine sj_domain_edges(self, edges)
    class(surface_joint_t), intent(in) :: self
    type(domain_edge_t), allocatable, intent(out) :: edges(:)
    real(wp) :: u_min, u_max, v_min, v_max
    allocate (edges(0))
    call self%surface%domain(u_min, u_max, v_min, v_max)
    if (.not. self%surface%periodic_u()) then
      if (u_min > -huge(u_min)) edges = [edges, &
        domain_edge_t(self%var_u, u_min, domain_edge_margin(u_min, u_max), .false., .true.)]
      if (u_max < huge(u_max)) edges = [edges, &
        domain_edge_t(self%var_u, u_max, domain_edge_margin(u_min, u_max), .true., .true.)]
    end if
    if (.not. self%surface%periodic_v()) then
      if (v_min > -huge(v_min)) edges = [edges, &
        domain_edge_t(self%var_v, v_min, domain_edge_margin(v_min, v_max), .false., .false.)]
      if (v_max < huge(v_max)) edges = [edges, &
        domain_edge_t(self%var_v, v_max, domain_edge_margin(v_min, v_max), .true., .false.)]
    end if
  end subroutine sj_domain_edges

  !> Eager geometry (module comment): the whole geometry at every position.
  pure subroutine sj_set_eager(self)
    class(surface_joint_t), intent(inout) :: self
    self%lazy = .false.
  end subroutine sj_set_eager

  !> The position with the whole geometry at once (element_t's
  !> position_complete): as an eager joint, whatever `lazy` says.
  pure subroutine sj_position_complete(self, frames, scalars, status)
    class(surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    logical :: lazy
    lazy = self%lazy
    self%lazy = .false.
    call sj_position(self, frames, scalars, status)
    self%lazy = lazy
  end subroutine sj_position_complete

  !> The contact point at the last position near a singular point of the
  !> surface's parametrisation (an ellipsoid's pole, an apex: |r_u x r_v|
  !> below 1e-2 (|r_u|^2 + |r_v|^2)): what to do about it (element_t).
  function sj_singular_note(self) result(text)
    class(surface_joint_t), intent(in) :: self
    character(len=:), allocatable :: text
    real(wp) :: ratio
    text = ''
    associate (p => self%point)
      ratio = norm2(cross(p%ru, p%rv))/max(dot_product(p%ru, p%ru) + dot_product(p%rv, p%rv), tiny(1.0_wp))
    end associate
    if (.not. ratio < 1e-2_wp) return
    text = 'the contact point of '''//self%name//''' is near a singular point of its surface''s '// &
      'parametrisation at (u, v) = ('//format_short(self%u)//', '//format_short(self%v)//') (|r_u x r_v| / '// &
      '(|r_u|^2 + |r_v|^2) = '//format_short(ratio)//'; an ellipsoid''s poles, an apex) on the '// &
      self%surface%describe()//': orient the body or the shape so that the contact stays away from it'
  end function sj_singular_note
  !> Changes to the chart in which the point at q = (u, v) lies farthest from
  !> the poles, keeping the point and its velocity over the surface (module
  !> comment, "Charts"): q and qd become the new chart's. d_old, d_new: the
  !> two charts' Darboux axes, omega_old, omega_new: their turn rates
  !> W_u u' + W_v v', all in the surface's own coordinates; k: the chart
  !> (chart_toward). If the new chart cannot be evaluated nothing changes
  !> (status says why; the run then meets the pole and fails there).
  pure subroutine sj_change_chart(self, q, qd, d_old, d_new, omega_old, omega_new, k, status)
    class(surface_joint_t), intent(inout) :: self
    real(wp), intent(inout) :: q(2), qd(2)
    real(wp), intent(out) :: d_old(3, 3), d_new(3, 3), omega_old(3), omega_new(3)
    integer, intent(out) :: k
    type(status_t), intent(out) :: status
    class(surface_t), allocatable :: chart_surface, old_surface
    real(wp) :: u, v, rates(3, 6), r(3), w(3), p(3, 3), tu(3), tv(3), a(2, 2), rhs(2), det
    ! the old chart's geometry in the surface's own coordinates (P times the chart's)
    call self%local_geometry(q(1), q(2), rates, status)
    if (.not. status%ok()) return
    associate (pt => self%point)
      r = matmul(self%chart, pt%r)
      w = matmul(self%chart, pt%ru*qd(1) + pt%rv*qd(2))                    ! the point's velocity over the surface
      omega_old = matmul(self%chart, rates(:, 1)*qd(1) + rates(:, 2)*qd(2))   ! the Darboux frame's turn rate
      d_old = matmul(self%chart, self%frame%r)
    end associate
    k = self%own_surface%chart_toward(r)
    call self%own_surface%chart(k, chart_surface, p)
    r = matmul(transpose(p), r)   ! the point in the new chart's coordinates
    call chart_surface%chart_parameters(r, u, v, status)
    if (.not. status%ok()) return
    call move_alloc(self%surface, old_surface)
    call move_alloc(chart_surface, self%surface)
    call self%local_geometry(u, v, rates, status)
    if (.not. status%ok()) then
      call move_alloc(old_surface, self%surface)
      return
    end if
    self%chart = p
    tu = matmul(p, self%point%ru)
    tv = matmul(p, self%point%rv)
    d_new = matmul(p, self%frame%r)
    ! (u', v') of the same velocity over the surface (least squares: w is tangent)
    a = reshape([dot_product(tu, tu), dot_product(tv, tu), dot_product(tu, tv), dot_product(tv, tv)], [2, 2])
    rhs = [dot_product(tu, w), dot_product(tv, w)]
    det = a(1, 1)*a(2, 2) - a(1, 2)*a(2, 1)
    q = [u, v]
    qd = [(rhs(1)*a(2, 2) - a(1, 2)*rhs(2))/det, (a(1, 1)*rhs(2) - a(2, 1)*rhs(1))/det]
    omega_new = matmul(p, rates(:, 1)*qd(1) + rates(:, 2)*qd(2))
    self%rebases = self%rebases + 1
    self%chart_index = k
  end subroutine sj_change_chart

  !> (u, v) = q and their rates qd after a chart change (change_chart), in
  !> the scalars var_u, var_v; their accelerations zero.
  pure subroutine put_chart_coordinates(scalars, var_u, var_v, q, qd)
    type(scalar_state_t), intent(inout) :: scalars(:)
    integer, intent(in) :: var_u, var_v
    real(wp), intent(in) :: q(2), qd(2)
    scalars(var_u)%q = q(1)
    scalars(var_v)%q = q(2)
    scalars(var_u)%qd = qd(1)
    scalars(var_v)%qd = qd(2)
    scalars(var_u)%qdd = 0
    scalars(var_v)%qdd = 0
  end subroutine put_chart_coordinates

  !> v decides the chart (module comment), if the joint changes charts.
  pure integer function sj_chart_angle(self) result(k)
    class(surface_joint_t), intent(in) :: self
    k = 0
    if (self%charts) k = self%var_v
  end function sj_chart_angle

  !> The surface's chart margin at v: positive inside the chart, zero at its edge.
  pure real(wp) function sj_chart_margin(self, angle) result(g)
    class(surface_joint_t), intent(in) :: self
    real(wp), intent(in) :: angle
    g = self%own_surface%chart_margin(angle)
  end function sj_chart_margin

  !> Changes the chart (module comment) with the positions and rates set:
  !> (u, v) and their rates become the new chart's, and the turn that
  !> follows takes back the Darboux frame's turn beta about the normal,
  !> phi - beta, and the change of its turn rate.
  pure subroutine sj_rebase(self, scalars)
    class(surface_joint_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t) :: status
    real(wp) :: q(2), qd(2), d_old(3, 3), d_new(3, 3), omega_old(3), omega_new(3), turn(3, 3)
    integer :: k
    if (.not. self%charts) return
    q = [scalars(self%var_u)%q, scalars(self%var_v)%q]
    qd = [scalars(self%var_u)%qd, scalars(self%var_v)%qd]
    call self%change_chart(q, qd, d_old, d_new, omega_old, omega_new, k, status)
    if (.not. status%ok()) return
    if (self%var_turn > 0) then
      turn = matmul(transpose(d_old), d_new)   ! D_new = D_old Rz(beta)
      associate (phi => scalars(self%var_turn))
        phi%q = phi%q - atan2(turn(2, 1), turn(1, 1))
        phi%qd = phi%qd + dot_product(d_old(:, 3), omega_old - omega_new)
        phi%qdd = 0
      end associate
    end if
    call put_chart_coordinates(scalars, self%var_u, self%var_v, q, qd)
    self%complete = .false.
  end subroutine sj_rebase

  pure integer function sj_chart_changes(self) result(n)
    class(surface_joint_t), intent(in) :: self
    n = self%rebases
  end function sj_chart_changes

  !> A joint that changes charts and starts at (or within the margin of) a
  !> pole changes chart at once, at rest (its rates zero); the turn after
  !> it takes the Darboux frame's turn (module comment).
  pure subroutine sj_start_chart(self, scalars)
    class(surface_joint_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    if (.not. self%charts) return
    if (self%chart_margin(scalars(self%var_v)%q) > 0) return
    scalars(self%var_u)%qd = 0
    scalars(self%var_v)%qd = 0
    call self%rebase(scalars)
  end subroutine sj_start_chart

  !> The turn about the output's z that follows the joint (module comment),
  !> if the joint changes charts.
  pure subroutine sj_set_chart_turn(self, turn)
    class(surface_joint_t), intent(inout) :: self
    integer, intent(in) :: turn
    if (self%charts) self%var_turn = turn
  end subroutine sj_set_chart_turn

  !> The surface in the chart in use, P and the chart's name.
  pure subroutine sj_surface_chart(self, chart)
    class(surface_joint_t), intent(in) :: self
    type(surface_chart_t), intent(out) :: chart
    allocate (chart%surface, source=self%surface)
    chart%rotation = self%chart
    chart%index = self%chart_index
  end subroutine sj_surface_chart

  !> Takes the chart of another joint on the same surface (before a run).
  pure subroutine sj_take_surface_chart(self, chart, changes)
    class(surface_joint_t), intent(inout) :: self
    type(surface_chart_t), intent(in) :: chart
    integer, intent(in) :: changes
    self%surface = chart%surface
    self%chart = chart%rotation
    self%rebases = changes
    self%chart_index = chart%index
  end subroutine sj_take_surface_chart
end module kinetostatics_surface_joint
