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
!> The geometry is the forward surface joint's in B's coordinates
!> (`local_geometry`), evaluated in the position map (each position pass of
!> an open chain is followed by a velocity pass) and rotated by R_B here; its
!> singular points are the forward joint's (extrapolated rates, rule (3.40)).
module kinetostatics_inverse_surface_joint
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_surface, only: surface_t
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint
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
  contains
    procedure :: position => isj_position
    procedure :: velocity => isj_velocity
    procedure :: acceleration => isj_acceleration
    procedure :: force => isj_force
    procedure :: links => isj_links
  end type inverse_surface_joint_t

  integer, parameter :: COL_P = 1, COL_GU = 2, COL_GV = 3, COL_TU = 4, COL_TV = 5, COL_GUU = 6, COL_GUV = 7, &
                        COL_GVU = 8, COL_GVV = 9, COL_HUU = 10, COL_HUV = 11, COL_HVV = 12

contains

  !> K_out (body B) from K_in and (u, v) of B's surface `surface`; sigma,
  !> alpha_u, alpha_v as for the forward joint ((3.38), (3.41)); mount: the
  !> rotation from K_in to the Darboux frame (default identity).
  function new_inverse_surface_joint(name, frame_in, frame_out, var_u, var_v, surface, sigma, alpha_u, alpha_v, &
                                     mount) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, var_u, var_v
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    real(wp), intent(in), optional :: mount(3, 3)
    type(inverse_surface_joint_t) :: e
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%var_u = var_u
    e%var_v = var_v
    if (present(mount)) e%mount = mount
    e%joint = new_surface_joint(name, 1, 2, 1, 2, surface, sigma, alpha_u, alpha_v)   ! its geometry only
  end function new_inverse_surface_joint

  pure subroutine isj_position(self, frames, scalars, status)
    class(inverse_surface_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: u, v, rates(3, 6), rot_m(3, 3), body(3, 12)
    integer :: k
    u = scalars(self%var_u)%q
    v = scalars(self%var_v)%q
    call self%joint%check_domain(u, v, status)
    if (.not. status%ok()) return
    call self%joint%local_geometry(u, v, rates, status)   ! B's coordinates
    if (.not. status%ok()) return
    associate (i => frames(self%frame_in), o => frames(self%frame_out), d => self%joint%frame%r, &
               pt => self%joint%point)
      ! R_B = (R_in M) D^T and the rotated columns, as sums in k (no temporaries)
      do k = 1, 3
        rot_m(:, k) = i%rot(:, 1)*self%mount(1, k) + i%rot(:, 2)*self%mount(2, k) + i%rot(:, 3)*self%mount(3, k)
      end do
      do k = 1, 3
        o%rot(:, k) = rot_m(:, 1)*d(k, 1) + rot_m(:, 2)*d(k, 2) + rot_m(:, 3)*d(k, 3)
      end do
      body(:, COL_P) = pt%r
      body(:, COL_GU) = rates(:, 1)
      body(:, COL_GV) = rates(:, 2)
      body(:, COL_TU) = pt%ru
      body(:, COL_TV) = pt%rv
      body(:, COL_GUU:COL_GVV) = rates(:, 3:6)
      body(:, COL_HUU) = pt%ruu
      body(:, COL_HUV) = pt%ruv
      body(:, COL_HVV) = pt%rvv
      do k = 1, 12
        self%geo(:, k) = o%rot(:, 1)*body(1, k) + o%rot(:, 2)*body(2, k) + o%rot(:, 3)*body(3, k)
      end do
      o%r = i%r - self%geo(:, COL_P)
    end associate
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

  !> Links for kinetostatics_closure_blocks: K_B moves rigidly with K_in while (u, v) rest.
  pure subroutine isj_links(self, links)
    class(inverse_surface_joint_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], [self%var_u, self%var_v], [self%frame_out], [integer ::], &
                            carried=.true.)
  end subroutine isj_links
end module kinetostatics_inverse_surface_joint
