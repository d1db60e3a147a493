!> The surface joint (thesis 3.5.1, kinetostatics_surface_joint) of a plane:
!> input frame K_1 and (u, v) -> the Darboux frame K_D at r(u, v) =
!> o + u r_u + v r_v on a plane given in K_1. A plane's Darboux frame D does
!> not turn (W_u = W_v = 0) and its second derivatives vanish, so the forward
!> joint's maps reduce to those of two prismatic joints along r_u, r_v behind
!> a constant rotation:
!>     R_D = R_1 D,  r_D = r_1 + p,  p = R_1 r(u, v),  t_u = R_1 r_u,  t_v = R_1 r_v
!>     omega_D = omega_1,  v_D = v_1 + omega_1 x p + t_u u' + t_v v'
!>     alpha_D = alpha_1,  a_D = a_1 + alpha_1 x p + omega_1 x (omega_1 x p)
!>                              + 2 omega_1 x (t_u u' + t_v v') + t_u u'' + t_v v''
!>     f_1 += f_D,  tau_1 += tau_D + p x f_D,  Q_u += t_u.f_D,  Q_v += t_v.f_D.
!> The same frame as the general joint (D, o, r_u, r_v are taken from the
!> plane's own evaluation and Darboux axes once), without the general
!> joint's Darboux-frame rates, which are zero here but cost most of its
!> work: the egg's table. The test compares every level with the general
!> joint and with differences.
module kinetostatics_plane_joint
  use, intrinsic :: iso_fortran_env, only: int64
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status, set_status, STATUS_INVALID_INPUT
  use base_vector, only: cross
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_axes
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t
  implicit none (type, external)
  private
  public :: plane_joint_t, new_plane_joint

  type, extends(element_t) :: plane_joint_t
    integer :: frame_in = 0, frame_out = 0, var_u = 0, var_v = 0
    real(wp) :: origin(3) = 0, ru(3) = 0, rv(3) = 0   ! r(0, 0), r_u, r_v in K_1
    real(wp) :: axes(3, 3) = 0                        ! D: the Darboux axes in K_1
    real(wp) :: p(3) = 0, tu(3) = 0, tv(3) = 0        ! at the last position (world)
    ! what depends on R_1 alone, kept for the R_1 it was made with (the
    ! input is often the fixed ground): R_1 r(0, 0) and R_1 D
    logical :: placed = .false.
    real(wp) :: rot_in(3, 3) = 0, origin_world(3) = 0, rot_out(3, 3) = 0
  contains
    procedure :: position => pj_position
    procedure :: velocity => pj_velocity
    procedure :: acceleration => pj_acceleration
    procedure :: force => pj_force
    procedure :: links => pj_links
  end type plane_joint_t

contains

  !> The joint of `plane` (an affine surface: surface_t's `affine`; any
  !> other is refused) with the Darboux frame of sigma, alpha_u, alpha_v
  !> ((3.38), (3.41)), as new_surface_joint.
  function new_plane_joint(name, frame_in, frame_out, var_u, var_v, plane, sigma, alpha_u, alpha_v, status) &
      result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, var_u, var_v
    class(surface_t), intent(in) :: plane
    real(wp), intent(in) :: sigma, alpha_u, alpha_v
    type(status_t), intent(inout) :: status
    type(plane_joint_t) :: e
    type(surface_point_t) :: pt
    logical :: singular
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%var_u = var_u
    e%var_v = var_v
    if (.not. status%ok()) return
    if (.not. plane%affine()) then
      call set_status(status, STATUS_INVALID_INPUT, 'plane joint '''//name//''': its surface ('// &
                      plane%describe()//') is not a plane parametrised linearly (use the surface joint)')
      return
    end if
    call plane%evaluate(0.0_wp, 0.0_wp, 1, pt, status)
    if (status%ok()) call darboux_axes(pt, sigma, alpha_u, alpha_v, e%axes, singular, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'plane joint '''//name//'''')
      return
    end if
    e%origin = pt%r
    e%ru = pt%ru
    e%rv = pt%rv
  end function new_plane_joint

  pure subroutine pj_position(self, frames, scalars, status)
    class(plane_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    associate (unused => status, i => frames(self%frame_in), o => frames(self%frame_out))
      ! the same R_1 to the bit gives the same products: reused
      if (.not. (self%placed .and. same_bits(i%rot, self%rot_in))) then
        self%tu = matmul(i%rot, self%ru)
        self%tv = matmul(i%rot, self%rv)
        self%origin_world = matmul(i%rot, self%origin)
        self%rot_out = matmul(i%rot, self%axes)
        self%rot_in = i%rot
        self%placed = .true.
      end if
      self%p = self%origin_world + self%tu*scalars(self%var_u)%q + self%tv*scalars(self%var_v)%q
      o%rot = self%rot_out
      o%r = i%r + self%p
    end associate
  end subroutine pj_position

  !> a and b hold the same bit patterns (-0 is not +0: the products would
  !> differ in the sign of a zero).
  pure logical function same_bits(a, b) result(same)
    real(wp), intent(in) :: a(3, 3), b(3, 3)
    integer :: j, k
    same = .false.
    do k = 1, 3
      do j = 1, 3
        if (transfer(a(j, k), 0_int64) /= transfer(b(j, k), 0_int64)) return
      end do
    end do
    same = .true.
  end function same_bits

  pure subroutine pj_velocity(self, frames, scalars)
    class(plane_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      o%omega = i%omega
      o%v = i%v + self%tu*scalars(self%var_u)%qd + self%tv*scalars(self%var_v)%qd
      if (any(i%omega /= 0)) o%v = o%v + cross(i%omega, self%p)
    end associate
  end subroutine pj_velocity

  !> Products with zero rates are skipped (mass-matrix columns run with all
  !> velocities zero).
  pure subroutine pj_acceleration(self, frames, scalars)
    class(plane_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: ud, vd
    ud = scalars(self%var_u)%qd
    vd = scalars(self%var_v)%qd
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      o%alpha = i%alpha
      o%a = i%a + cross(i%alpha, self%p) + self%tu*scalars(self%var_u)%qdd + self%tv*scalars(self%var_v)%qdd
      if (any(i%omega /= 0)) then
        o%a = o%a + cross(i%omega, cross(i%omega, self%p))
        if (ud /= 0 .or. vd /= 0) o%a = o%a + 2*cross(i%omega, self%tu*ud + self%tv*vd)
      end if
    end associate
  end subroutine pj_acceleration

  pure subroutine pj_force(self, frames, scalars, inertia, applied)
    class(plane_joint_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    real(wp) :: f(3)
    associate (unused_i => inertia, unused_a => applied)
    end associate
    f = frames(self%frame_out)%force
    frames(self%frame_in)%force = frames(self%frame_in)%force + f
    frames(self%frame_in)%torque = frames(self%frame_in)%torque + frames(self%frame_out)%torque + cross(self%p, f)
    scalars(self%var_u)%force = scalars(self%var_u)%force + dot_product(self%tu, f)
    scalars(self%var_v)%force = scalars(self%var_v)%force + dot_product(self%tv, f)
  end subroutine pj_force

  pure subroutine pj_links(self, links)
    class(plane_joint_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_in], [self%var_u, self%var_v], [self%frame_out], [integer ::], &
                            carried=.true.)
  end subroutine pj_links
end module kinetostatics_plane_joint
