!> Small 3-vector and rotation algebra.
module base_vector
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: cross, unit_vector, skew, rot_x, rot_y, rot_z, rotation_xyz, outer3, identity3

contains

  pure function cross(a, b) result(c)
    real(wp), intent(in) :: a(3), b(3)
    real(wp) :: c(3)
    c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
  end function cross

  !> a/|a|; the zero vector stays zero (callers test norms where it matters).
  pure function unit_vector(a) result(e)
    real(wp), intent(in) :: a(3)
    real(wp) :: e(3), n
    n = norm2(a)
    if (n > 0) then
      e = a/n
    else
      e = 0
    end if
  end function unit_vector

  !> The matrix of a x (.): skew(a) b = cross(a, b).
  pure function skew(a) result(s)
    real(wp), intent(in) :: a(3)
    real(wp) :: s(3, 3)
    s = reshape([0.0_wp, a(3), -a(2), -a(3), 0.0_wp, a(1), a(2), -a(1), 0.0_wp], [3, 3])
  end function skew

  pure function outer3(a, b) result(m)
    real(wp), intent(in) :: a(3), b(3)
    real(wp) :: m(3, 3)
    integer :: j
    do j = 1, 3
      m(:, j) = a*b(j)
    end do
  end function outer3

  pure function identity3() result(m)
    real(wp) :: m(3, 3)
    m = 0
    m(1, 1) = 1; m(2, 2) = 1; m(3, 3) = 1
  end function identity3

  !> Rotation by angle (rad) about the x axis (element by element: hot in the
  !> joints' position maps, where a reshape of a constructor costs a library call).
  pure function rot_x(angle) result(r)
    real(wp), intent(in) :: angle
    real(wp) :: r(3, 3), c, s
    c = cos(angle); s = sin(angle)
    r(:, 1) = [1.0_wp, 0.0_wp, 0.0_wp]
    r(1, 2) = 0; r(2, 2) = c; r(3, 2) = s
    r(1, 3) = 0; r(2, 3) = -s; r(3, 3) = c
  end function rot_x

  pure function rot_y(angle) result(r)
    real(wp), intent(in) :: angle
    real(wp) :: r(3, 3), c, s
    c = cos(angle); s = sin(angle)
    r(1, 1) = c; r(2, 1) = 0; r(3, 1) = -s
    r(:, 2) = [0.0_wp, 1.0_wp, 0.0_wp]
    r(1, 3) = s; r(2, 3) = 0; r(3, 3) = c
  end function rot_y

  pure function rot_z(angle) result(r)
    real(wp), intent(in) :: angle
    real(wp) :: r(3, 3), c, s
    c = cos(angle); s = sin(angle)
    r(1, 1) = c; r(2, 1) = s; r(3, 1) = 0
    r(1, 2) = -s; r(2, 2) = c; r(3, 2) = 0
    r(:, 3) = [0.0_wp, 0.0_wp, 1.0_wp]
  end function rot_z

  !> Cardan angles: R = Rx(a1) Ry(a2) Rz(a3) (rotations about the moving x, y', z'').
  pure function rotation_xyz(angles) result(r)
    real(wp), intent(in) :: angles(3)
    real(wp) :: r(3, 3), rx(3, 3), ry(3, 3), rz(3, 3)
    rx = rot_x(angles(1))
    ry = rot_y(angles(2))
    rz = rot_z(angles(3))
    r = matmul(rx, matmul(ry, rz))
  end function rotation_xyz
end module base_vector
