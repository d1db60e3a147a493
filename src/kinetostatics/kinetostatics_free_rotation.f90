!> A free rotation without a singular chart: the spherical joint's Cardan
!> angles (kinetostatics_joints) between two constant reference rotations,
!>     R_out = R_in R_a Rx(q1) Ry(q2) Rz(q3) R_b,
!> and a change of chart before the middle angle nears +-90 degrees, where the
!> first and third axes align and the angles stop being coordinates.
!>
!> R_a fixes the first axis in the input frame (R_in R_a e_x): the unbounded
!> turn about it (the spin of an egg about the table's normal) never
!> approaches a singularity. R_b is the output-side reference the chart is
!> re-based on. `chart_margin` = cos q2 - cos(chart_limit) falls to zero when
!> |q2| reaches chart_limit (default 1.2 rad, where 1/cos q2 = 2.8); the model
!> watches it as a root function and calls `rebase` there, then restarts the
!> integrator (numerics_event_driver EVENT_RESTART). Rebasing keeps the pose
!> and the angular velocity exactly:
!>     R_b <- Ry(q2) Rz(q3) R_b,  q2 = q3 = 0,  q1 kept (wrapped to [-pi, pi]),
!>     q' <- [n1 n2 n3]^T omega_rel  (the new axes are orthonormal at q2 = q3 = 0),
!> where omega_rel = n1 q1' + n2 q2' + n3 q3' is the relative angular velocity.
!> The middle angle is then zero: the chart is as far from its singularity as
!> a Cardan chart can be.
module kinetostatics_free_rotation
  use base_kinds, only: wp
  use base_constants, only: two_pi
  use base_status, only: status_t
  use base_vector, only: cross, rot_y, rot_z
  use kinetostatics_state, only: frame_state_t, scalar_state_t
  use kinetostatics_joints, only: spherical_t
  implicit none (type, external)
  private
  public :: free_rotation_t, new_free_rotation

  type, extends(spherical_t) :: free_rotation_t
    real(wp) :: ref_in(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])    ! R_a
    real(wp) :: ref_out(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])   ! R_b
    real(wp) :: chart_limit = 1.2_wp    ! rad, |q2| at which the chart is changed
    integer :: rebases = 0              ! charts changed so far
  contains
    procedure :: position => free_rotation_position
    procedure :: chart_angle => free_rotation_chart_angle
    procedure :: chart_margin => free_rotation_chart_margin
    procedure :: rebase => free_rotation_rebase
    procedure :: chart_changes => free_rotation_chart_changes
    procedure :: centre_chart => free_rotation_centre_chart
  end type free_rotation_t

contains

  !> The joint with its first axis along `first_axis` (unit vector in the input
  !> frame; e.g. [0, 0, 1], a contact normal) and the chart centred on the
  !> relative rotation `start` (R_in^T R_out at q = 0).
  function new_free_rotation(name, frame_in, frame_out, variables, first_axis, start, chart_limit) result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_in, frame_out, variables(3)
    real(wp), intent(in) :: first_axis(3), start(3, 3)
    real(wp), intent(in), optional :: chart_limit
    type(free_rotation_t) :: e
    real(wp) :: a(3), b(3), c(3)
    e%name = name
    e%frame_in = frame_in
    e%frame_out = frame_out
    e%variables = variables
    a = first_axis/norm2(first_axis)
    ! any unit b normal to a completes R_a = [a, b, a x b]
    if (abs(a(1)) < 0.9_wp) then
      b = [1.0_wp, 0.0_wp, 0.0_wp] - a(1)*a
    else
      b = [0.0_wp, 1.0_wp, 0.0_wp] - a(2)*a
    end if
    b = b/norm2(b)
    c = cross(a, b)
    e%ref_in(:, 1) = a
    e%ref_in(:, 2) = b
    e%ref_in(:, 3) = c
    e%ref_out = matmul(transpose(e%ref_in), start)
    if (present(chart_limit)) e%chart_limit = chart_limit
  end function new_free_rotation

  !> R_out = R_in R_a Rx(q1) Ry(q2) Rz(q3) R_b, each elementary turn applied
  !> to the columns it mixes (the products with the rotation matrices, without
  !> their zeros and ones).
  pure subroutine free_rotation_position(self, frames, scalars, status)
    class(free_rotation_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    real(wp) :: r(3, 3), col(3), c, s, q
    associate (unused_status => status)
    end associate
    associate (i => frames(self%frame_in), o => frames(self%frame_out))
      r = matmul(i%rot, self%ref_in)
      self%n(:, 1) = r(:, 1)
      q = scalars(self%variables(1))%q                  ! Rx(q1): columns 2, 3
      c = cos(q); s = sin(q)
      col = r(:, 2)
      r(:, 2) = c*col + s*r(:, 3)
      r(:, 3) = c*r(:, 3) - s*col
      self%n(:, 2) = r(:, 2)
      q = scalars(self%variables(2))%q                  ! Ry(q2): columns 3, 1
      c = cos(q); s = sin(q)
      col = r(:, 1)
      r(:, 1) = c*col - s*r(:, 3)
      r(:, 3) = s*col + c*r(:, 3)
      self%n(:, 3) = r(:, 3)
      q = scalars(self%variables(3))%q                  ! Rz(q3): columns 1, 2
      c = cos(q); s = sin(q)
      col = r(:, 1)
      r(:, 1) = c*col + s*r(:, 2)
      r(:, 2) = c*r(:, 2) - s*col
      o%rot = matmul(r, self%ref_out)
      o%r = i%r
    end associate
  end subroutine free_rotation_position

  !> The middle angle q2 decides the chart.
  pure integer function free_rotation_chart_angle(self) result(k)
    class(free_rotation_t), intent(in) :: self
    k = self%variables(2)
  end function free_rotation_chart_angle

  !> cos q2 - cos(chart_limit): positive inside the chart, zero at its edge.
  pure real(wp) function free_rotation_chart_margin(self, angle) result(g)
    class(free_rotation_t), intent(in) :: self
    real(wp), intent(in) :: angle
    g = cos(angle) - cos(self%chart_limit)
  end function free_rotation_chart_margin

  pure integer function free_rotation_chart_changes(self) result(n)
    class(free_rotation_t), intent(in) :: self
    n = self%rebases
  end function free_rotation_chart_changes

  !> The chart centred on the relative rotation `relative` (R_in^T R_out at
  !> q = 0): R_b = R_a^T relative.
  pure subroutine free_rotation_centre_chart(self, relative)
    class(free_rotation_t), intent(inout) :: self
    real(wp), intent(in) :: relative(3, 3)
    self%ref_out = matmul(transpose(self%ref_in), relative)
  end subroutine free_rotation_centre_chart

  !> Changes to the chart centred on the current pose (module comment). Needs
  !> the positions evaluated (the axes n) and the rates of q set.
  pure subroutine free_rotation_rebase(self, scalars)
    class(free_rotation_t), intent(inout) :: self
    type(scalar_state_t), intent(inout) :: scalars(:)
    real(wp) :: omega_rel(3), axes(3, 3), q1
    integer :: k
    omega_rel = 0
    do k = 1, 3
      omega_rel = omega_rel + self%n(:, k)*scalars(self%variables(k))%qd
    end do
    q1 = scalars(self%variables(1))%q
    ! new axes: n1 stays, n2 and n3 are the input frame's R_a Rx(q1) e_y, e_z
    axes(:, 1) = self%n(:, 1)
    axes(:, 2) = self%n(:, 2)
    axes(:, 3) = cross(self%n(:, 1), self%n(:, 2))
    self%ref_out = matmul(matmul(rot_y(scalars(self%variables(2))%q), rot_z(scalars(self%variables(3))%q)), &
                          self%ref_out)
    scalars(self%variables(1))%q = q1 - two_pi*anint(q1/two_pi)
    scalars(self%variables(2))%q = 0
    scalars(self%variables(3))%q = 0
    do k = 1, 3
      scalars(self%variables(k))%qd = dot_product(axes(:, k), omega_rel)
      scalars(self%variables(k))%qdd = 0
    end do
    self%rebases = self%rebases + 1
  end subroutine free_rotation_rebase

end module kinetostatics_free_rotation
