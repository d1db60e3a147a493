!> The inverse surface joint: the surface joint of a body B (thesis 3.5.1,
!> kinetostatics_surface_joint) run backwards. Input: a frame K_in that
!> carries B's Darboux frame, K_D = K_in M (M a constant rotation, `mount`),
!> and the surface parameters (u, v) of the point of B's surface S at K_D's
!> origin. Output: B's body frame K_B, placed so that S's Darboux frame at
!> (u, v) is K_D. An open chain "K_A -> S1(u1, v1) -> turn phi about the
!> normal -> inverse S2(u2, v2) -> K_B" keeps two surfaces in contact
!> exactly, with no closure (contact_pair).
!>
!> With the forward joint's geometry of S at (u, v) in B's coordinates
!> (Darboux axes D, point r, rates W_u, W_v, r_u, r_v and their u/v
!> derivatives) and R_B the output's rotation, all rotated by R_B into the
!> world (p = R_B r, g_u = R_B W_u, t_u = R_B r_u, g_uu = R_B W_u,u,
!> h_uu = R_B r_uu, ...), the forward maps K_B -> K_D
!>     omega_D = omega_B + g_u u' + g_v v',   v_D = v_B + omega_B x p + t_u u' + t_v v'
!> are solved for K_B (K_D moves with K_in: omega_D = omega_in, v_D = v_in):
!> Position:      R_B = R_in M D^T,   r_B = r_in - R_B r.
!> Velocity:      omega_B = omega_in - omega_rel,   omega_rel = g_u u' + g_v v',
!>                v_B = v_in - w_rel - omega_B x p,  w_rel = t_u u' + t_v v'.
!> Acceleration (the forward (B.1), (B.10), (B.11) solved for alpha_B, a_B):
!>     alpha_B = alpha_in - (g_u u'' + g_v v'' + (g_uu u' + g_uv v') u' + (g_vu u' + g_vv v') v')
!>               - omega_B x omega_rel
!>     a_B = a_in - alpha_B x p - omega_B x (omega_B x p) - 2 omega_B x w_rel
!>           - (t_u u'' + t_v v'' + h_uu u'^2 + 2 h_uv u' v' + h_vv v'^2).
!> Force (the transpose; power tau_B.omega_B + f_B.v_B is conserved): with
!> tau' = tau_B - p x f_B, B's wrench about the contact point,
!>     f_in += f_B,  tau_in += tau',  Q_u += -g_u.tau' - t_u.f_B,  Q_v likewise.
!> The test compares every level with differences of the level below, the
!> position with the forward joint (round trip), and the force map's power.
!>
!> The geometry is the forward surface joint's in the coordinates of the
!> surface's chart (`local_geometry`; B's own unless the chart changed),
!> evaluated in the position map (each position pass of an open chain is
!> followed by a velocity pass) and rotated into the world here; its
!> singular points are the forward joint's (extrapolated rates, rule (3.40)).
!>
!> Charts: a surface's parametrisation may be singular at poles (an
!> ellipsoid's (3.57) at v = +-pi/2, r_u = 0: the Darboux frame and u' are
!> undefined there), and an egg that stands up brings its contact point to
!> the tip of its long axis, a pole when that axis is the shape's z. Given
!> the turn phi before it (`turn`, the open chain of contact_pair), the joint
!> of a surface with charts (geometry_surface's chart hooks; the ellipsoid's:
!> cos v - cos(1.4 rad)) watches the surface's chart_margin(v) (kinetostatics_
!> state's chart interface) and at its zero changes to the chart
!> (chart_toward, chart: r_B = P r'; the forward joint's change_chart) in
!> which the contact point lies farthest
!> from the poles (an ellipsoid's: the one with its poles on the body axis
!> along which the point lies least far out, within 35 degrees of the new
!> chart's equator). The motion
!> is kept: (u, v) become the new chart's parameters of the same point and
!> (u', v') those of the same velocity over the surface; the two charts'
!> Darboux frames share the normal and differ by a turn beta about it, so phi
!> takes beta and phi' the difference of their rates. With the chart,
!> R_B = (R_in M) D'^T P^T and the world columns are (R_in M) D'^T times the
!> chart's (D' the chart's Darboux axes). The chart in use is written to the
!> scalar `chart_scalar` (the pole axis: 1, 2, 3 for B's x, y, z) for the
!> closure monitor, which measures with the same chart.
module kinetostatics_inverse_surface_joint
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_surface, only: surface_t
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t, surface_chart_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint, put_chart_coordinates
  implicit none (type, external)
  private
  public :: inverse_surface_joint_t, new_inverse_surface_joint

  type, extends(element_t) :: inverse_surface_joint_t
    integer :: frame_in = 0, frame_out = 0, var_u = 0, var_v = 0
    real(wp) :: mount(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])   ! K_D = K_in M
    type(surface_joint_t) :: joint        ! B's surface joint: its geometry in B's coordinates
    ! at the last position (world coordinates): p = R_B r and the rotated rates
    ! (columns: p, g_u, g_v, t_u, t_v, g_uu, g_uv, g_vu, g_vv, h_uu, h_uv, h_vv)
    real(wp) :: geo(3, 12) = 0
    real(wp) :: omega_rel(3) = 0, w_rel(3) = 0   ! at the last velocity pass
    ! charts (module comment): only for a surface with charts after a turn
    ! (B's surface in its own chart and P, r_B = P r_chart: the joint's own_surface, chart)
    logical :: charts = .false.
    integer :: var_turn = 0, var_chart = 0
    integer :: rebases = 0
  contains
    procedure :: position => isj_position
    procedure :: chart_angle => isj_chart_angle
    procedure :: chart_margin => isj_chart_margin
    procedure :: rebase => isj_rebase
    procedure :: chart_changes => isj_chart_changes
    procedure :: take_surface_chart => isj_take_surface_chart
    procedure :: velocity => isj_velocity
    procedure :: acceleration => isj_acceleration
    procedure :: force => isj_force
    procedure :: links => isj_links
    procedure :: singular_note => isj_singular_note
  end type inverse_surface_joint_t

  integer, parameter :: COL_P = 1, COL_GU = 2, COL_GV = 3, COL_TU = 4, COL_TV = 5, COL_GUU = 6, COL_GUV = 7, &
                        COL_GVU = 8, COL_GVV = 9, COL_HUU = 10, COL_HUV = 11, COL_HVV = 12

contains

  !> K_out (body B) from K_in and (u, v) of B's surface `surface`; sigma,
  !> alpha_u, alpha_v as for the forward joint ((3.38), (3.41)); mount: the
  !> rotation from K_in to the Darboux frame (default identity). turn: the
  !> scalar of a turn about K_in's z just before this joint, chart_scalar: a
  !> scalar for the chart in use; with both, a surface with charts (an
  !> ellipsoid) changes them near its poles (module comment; the mount must
  !> keep z on the z axis).
  function new_inverse_surface_joint(name, frame_in, frame_out, var_u, var_v, surface, sigma, alpha_u, alpha_v, &
                                     mount, turn, chart_scalar) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, var_u, var_v
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    real(wp), intent(in), optional :: mount(3, 3)
    integer, intent(in), optional :: turn, chart_scalar
    type(inverse_surface_joint_t) :: e
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%var_u = var_u
    e%var_v = var_v
    if (present(mount)) e%mount = mount
    e%joint = new_surface_joint(name, 1, 2, 1, 2, surface, sigma, alpha_u, alpha_v)   ! its geometry only
    if (present(turn) .and. present(chart_scalar)) then
      if (surface%has_charts() .and. abs(abs(e%mount(3, 3)) - 1) <= 1e-14_wp) then
        e%charts = .true.
        allocate (e%joint%own_surface, source=surface)
        e%var_turn = turn
        e%var_chart = chart_scalar
      end if
    end if
  end function new_inverse_surface_joint

  pure subroutine isj_position(self, frames, scalars, status)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: u, v, rates(3, 6), rot_m(3, 3), x(3, 3)
    integer :: k
    u = scalars(self%var_u)%q
    v = scalars(self%var_v)%q
    call self%joint%check_domain(u, v, status)
    if (.not. status%ok()) return
    call self%joint%local_geometry(u, v, rates, status)   ! the chart's coordinates
    if (.not. status%ok()) return
    associate (i => frames(self%frame_in), o => frames(self%frame_out), d => self%joint%frame%r, &
               pt => self%joint%point, g => self%geo)
      ! X = (R_in M) D^T and the rotated columns, as sums in k (no temporaries);
      ! R_B = X P^T (module comment, "Charts"; X itself in B's own chart)
      do k = 1, 3
        rot_m(:, k) = i%rot(:, 1)*self%mount(1, k) + i%rot(:, 2)*self%mount(2, k) + i%rot(:, 3)*self%mount(3, k)
      end do
      do k = 1, 3
        x(:, k) = rot_m(:, 1)*d(k, 1) + rot_m(:, 2)*d(k, 2) + rot_m(:, 3)*d(k, 3)
      end do
      if (self%rebases == 0) then
        o%rot = x
      else
        do k = 1, 3
          o%rot(:, k) = x(:, 1)*self%joint%chart(k, 1) + x(:, 2)*self%joint%chart(k, 2) &
                        + x(:, 3)*self%joint%chart(k, 3)
        end do
      end if
      g(:, COL_P) = turned(pt%r)
      g(:, COL_GU) = turned(rates(:, 1))
      g(:, COL_GV) = turned(rates(:, 2))
      g(:, COL_TU) = turned(pt%ru)
      g(:, COL_TV) = turned(pt%rv)
      do k = 0, 3
        g(:, COL_GUU + k) = turned(rates(:, 3 + k))
      end do
      g(:, COL_HUU) = turned(pt%ruu)
      g(:, COL_HUV) = turned(pt%ruv)
      g(:, COL_HVV) = turned(pt%rvv)
      o%r = i%r - self%geo(:, COL_P)
    end associate
  contains
    !> X b, summed as X(:, 1) b(1) + X(:, 2) b(2) + X(:, 3) b(3).
    pure function turned(b) result(xb)
      real(wp), intent(in) :: b(3)
      real(wp) :: xb(3)
      xb = x(:, 1)*b(1) + x(:, 2)*b(2) + x(:, 3)*b(3)
    end function turned
  end subroutine isj_position

  pure subroutine isj_velocity(self, frames, scalars)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: ud, vd
    ud = scalars(self%var_u)%qd
    vd = scalars(self%var_v)%qd
    associate (i => frames(self%frame_in), o => frames(self%frame_out), g => self%geo)
      self%omega_rel = g(:, COL_GU)*ud + g(:, COL_GV)*vd
      self%w_rel = g(:, COL_TU)*ud + g(:, COL_TV)*vd
      o%omega = i%omega - self%omega_rel
      o%v = i%v - self%w_rel - cross(o%omega, g(:, COL_P))
    end associate
  end subroutine isj_velocity

  !> The products with zero rates are skipped (mass-matrix columns run with
  !> all velocities zero).
  pure subroutine isj_acceleration(self, frames, scalars)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: ud, vd, udd, vdd, omega_rel(3), w_rel(3), omega(3), acc(3)
    logical :: moving, turning
    ud = scalars(self%var_u)%qd
    vd = scalars(self%var_v)%qd
    udd = scalars(self%var_u)%qdd
    vdd = scalars(self%var_v)%qdd
    moving = ud /= 0 .or. vd /= 0
    associate (i => frames(self%frame_in), o => frames(self%frame_out), g => self%geo)
      acc = i%alpha - g(:, COL_GU)*udd - g(:, COL_GV)*vdd
      if (moving) then
        omega_rel = g(:, COL_GU)*ud + g(:, COL_GV)*vd
        w_rel = g(:, COL_TU)*ud + g(:, COL_TV)*vd
        omega = i%omega - omega_rel
        acc = acc - (g(:, COL_GUU)*ud + g(:, COL_GUV)*vd)*ud - (g(:, COL_GVU)*ud + g(:, COL_GVV)*vd)*vd &
              - cross(omega, omega_rel)
      else
        omega = i%omega
      end if
      turning = any(omega /= 0)
      o%alpha = acc
      acc = i%a - cross(o%alpha, g(:, COL_P)) - g(:, COL_TU)*udd - g(:, COL_TV)*vdd
      if (turning) then
        acc = acc - cross(omega, cross(omega, g(:, COL_P)))
        if (moving) acc = acc - 2*cross(omega, w_rel)
      end if
      if (moving) acc = acc - g(:, COL_HUU)*ud**2 - 2*g(:, COL_HUV)*ud*vd - g(:, COL_HVV)*vd**2
      o%a = acc
    end associate
  end subroutine isj_acceleration

  pure subroutine isj_force(self, frames, scalars, inertia, applied)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3), t(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    associate (g => self%geo)
      f = frames(self%frame_out)%force
      t = frames(self%frame_out)%torque - cross(g(:, COL_P), f)   ! about the contact point
      frames(self%frame_in)%force = frames(self%frame_in)%force + f
      frames(self%frame_in)%torque = frames(self%frame_in)%torque + t
      scalars(self%var_u)%force = scalars(self%var_u)%force - dot_product(g(:, COL_GU), t) &
                                  - dot_product(g(:, COL_TU), f)
      scalars(self%var_v)%force = scalars(self%var_v)%force - dot_product(g(:, COL_GV), t) &
                                  - dot_product(g(:, COL_TV), f)
    end associate
  end subroutine isj_force

  !> v decides the chart (module comment), if the joint changes charts.
  pure integer function isj_chart_angle(self) result(k)
    class(inverse_surface_joint_t), intent(in) :: self
    k = 0
    if (self%charts) k = self%var_v
  end function isj_chart_angle

  !> The surface's chart margin at v: positive inside the chart, zero at its edge.
  pure real(wp) function isj_chart_margin(self, angle) result(g)
    class(inverse_surface_joint_t), intent(in) :: self
    real(wp), intent(in) :: angle
    g = self%joint%own_surface%chart_margin(angle)
  end function isj_chart_margin

  !> Changes to the chart whose poles are farthest from the contact point
  !> (module comment), keeping the motion: needs (u, v), phi and their rates.
  pure subroutine isj_rebase(self, scalars)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t) :: status
    real(wp) :: q(2), qd(2), omega_old(3), omega_new(3), d_old(3, 3), d_new(3, 3), turn(3, 3), axis(3)
    integer :: k
    if (.not. self%charts) return
    q = [scalars(self%var_u)%q, scalars(self%var_v)%q]
    qd = [scalars(self%var_u)%qd, scalars(self%var_v)%qd]
    call self%joint%change_chart(q, qd, d_old, d_new, omega_old, omega_new, k, status)
    if (.not. status%ok()) return
    ! phi: K_B = K_in M D^T is kept when K_in turns by M D_old^T D_new M^T
    ! (a turn about z), and omega_B when phi' takes the change of the
    ! Darboux frame's turn rate along K_in's z (in B: D_old M^T e_z)
    turn = matmul(matmul(self%mount, matmul(transpose(d_old), d_new)), transpose(self%mount))
    axis = matmul(d_old, self%mount(3, :))
    associate (phi => scalars(self%var_turn))
      phi%q = phi%q + atan2(turn(2, 1), turn(1, 1))
      phi%qd = phi%qd + dot_product(axis, omega_new - omega_old)
      phi%qdd = 0
    end associate
    call put_chart_coordinates(scalars, self%var_u, self%var_v, q, qd)
    scalars(self%var_chart)%q = k
    self%rebases = self%rebases + 1
  end subroutine isj_rebase

  pure integer function isj_chart_changes(self) result(n)
    class(inverse_surface_joint_t), intent(in) :: self
    n = self%rebases
  end function isj_chart_changes

  !> Takes the chart of B's surface from a forward joint on it (before a
  !> run; the owner sets the chart scalar to chart%index).
  pure subroutine isj_take_surface_chart(self, chart, changes)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(surface_chart_t), intent(in) :: chart
    integer, intent(in) :: changes
    self%joint%surface = chart%surface
    self%joint%chart = chart%rotation
    self%rebases = changes
  end subroutine isj_take_surface_chart

  !> Links for kinetostatics_closure_blocks: K_B moves rigidly with K_in while (u, v) rest.
  pure subroutine isj_links(self, links)
    class(inverse_surface_joint_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], [self%var_u, self%var_v], [self%frame_out], [integer ::], &
                            carried=.true.)
  end subroutine isj_links

  !> Its surface joint's note (element_t): the same contact point.
  function isj_singular_note(self) result(text)
    class(inverse_surface_joint_t), intent(in) :: self
    character(len=:), allocatable :: text
    text = self%joint%singular_note()
  end function isj_singular_note
end module kinetostatics_inverse_surface_joint
