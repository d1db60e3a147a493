!> The gap between two placed surfaces (contact_gap) against closed forms:
!> - a sphere over a tilted, moved plane: n . (c - p0) - R;
!> - an ellipsoid tumbling over a plane through two turns about two axes (its
!>   points pass its poles: the chart changes): n . (c - p0) - sqrt(sum (a_i m_i)^2),
!>   m = R^T n its support function;
!> - two spheres, one round the other over its poles: |c2 - c1| - R1 - R2;
!> - an ellipsoid in a paraboloid bowl (no closed form): moved by -gap along
!>   the normal it touches (gap 0, its point on the bowl by the foot-point
!>   search), and the gap equals the smallest signed distance of 1,800 of its
!>   points to the bowl (to the sampling's second order);
!> - the gap's rate n . (v_2 - v_1) against central differences of the gap
!>   along a motion of both bodies;
!> - the Newton Jacobian of the common-normal equations (4 x 4: second
!>   derivatives and n_1's Weingarten derivatives) against central
!>   differences (numerics_nonlinear's check_jacobian), for sphere/plane,
!>   ellipsoid/plane, ellipsoid/ellipsoid, a bowl and an egg, at the solution
!>   and away from it, near the poles of the base chart and in other charts.

!> The gap's equations f(x) as a nonlinear system, for check_jacobian.
module gap_equations_system
  use base_kinds, only: wp
  use base_status, only: status_t
  use numerics_nonlinear, only: nonlinear_system_t
  use contact_gap, only: contact_gap_t, gap_equations
  implicit none (type, external)
  private
  public :: gap_system_t

  type, extends(nonlinear_system_t) :: gap_system_t
    type(contact_gap_t) :: gap
  contains
    procedure :: residual => gap_system_residual
    procedure :: jacobian => gap_system_jacobian
  end type gap_system_t

contains

  subroutine gap_system_residual(self, x, f, status)
    class(gap_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: f(:)
    type(status_t), intent(inout) :: status
    real(wp) :: f4(4), jac(4, 4)
    call gap_equations(self%gap, x, f4, jac, status)
    f = f4
  end subroutine gap_system_residual

  subroutine gap_system_jacobian(self, x, jac, status)
    class(gap_system_t), intent(inout) :: self
    real(wp), intent(in) :: x(:)
    real(wp), intent(out) :: jac(:, :)
    type(status_t), intent(inout) :: status
    real(wp) :: f(4), jac4(4, 4)
    call gap_equations(self%gap, x, f, jac4, status)
    jac = jac4
  end subroutine gap_system_jacobian
end module gap_equations_system

program test_contact_gap
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: cross, rot_x, rot_y, rot_z, identity3
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_point_t
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t
  use contact_surface_search, only: nearest_point
  use geometry_surface, only: surface_t
  use numerics_nonlinear, only: check_jacobian
  use contact_gap, only: contact_gap_t, new_contact_gap
  use gap_equations_system, only: gap_system_t
  implicit none (type, external)

  real(wp), parameter :: pi = acos(-1.0_wp)
  real(wp), parameter :: w1 = 0.7_wp, w2 = -2.3_wp   ! check_rate's spins, rad/s
  !> check_newton_jacobian's largest entry difference, relative to max(1, |J|).
  real(wp), parameter :: jacobian_tolerance = 1e-7_wp

  call check_sphere_over_plane()
  call check_tumbling_ellipsoid()
  call check_two_spheres()
  call check_ellipsoid_in_bowl()
  call check_rate()
  call check_newton_jacobian()
  call finish_tests('test_contact_gap')

contains

  subroutine check_sphere_over_plane()
    type(plane_t) :: plane
    type(ellipsoid_t) :: ball
    type(contact_gap_t) :: gap
    type(status_t) :: status
    real(wp) :: rot1(3, 3), o1(3), rot2(3, 3), c(3), n(3), worst
    integer :: i
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], status)
    ball = ellipsoid_t(0.3_wp, 0.3_wp, 0.3_wp, status)
    rot1 = matmul(rot_x(0.2_wp), rot_y(-0.3_wp))
    o1 = [0.5_wp, -1.0_wp, 0.2_wp]
    n = rot1(:, 3)
    gap = new_contact_gap(plane, 1.0_wp, ball, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    c = o1 + 0.8_wp*n
    rot2 = rot_z(0.4_wp)
    call gap%start_from_search(rot1, o1, rot2, c, status)
    call check(status%ok(), 'sphere/plane: started '//status%text())
    worst = 0
    do i = 0, 200
      c = o1 + (0.8_wp - 0.004_wp*i)*n + [0.01_wp*i, 0.003_wp*i, 0.0_wp]
      rot2 = matmul(rot_z(0.05_wp*i), rot_x(0.03_wp*i))
      call gap%update(rot1, o1, rot2, c, status)
      if (.not. status%ok()) exit
      worst = max(worst, abs(gap%gap - (dot_product(n, c - o1) - 0.3_wp)))
    end do
    call check(status%ok(), 'sphere/plane: tracked '//status%text())
    call check(worst <= 1e-13_wp, 'sphere/plane: gap = n.(c - p0) - R')
    call check_close(gap%normals_cosine, -1.0_wp, 0.0_wp, 1e-12_wp, 'sphere/plane: antiparallel normals')
  end subroutine check_sphere_over_plane

  subroutine check_tumbling_ellipsoid()
    type(plane_t) :: plane
    type(ellipsoid_t) :: egg
    type(contact_gap_t) :: gap
    type(status_t) :: status
    real(wp) :: rot1(3, 3), o1(3), rot2(3, 3), c(3), n(3), m(3), worst, expected
    real(wp), parameter :: abc(3) = [0.3_wp, 0.2_wp, 0.45_wp]
    integer :: i
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], status)
    egg = ellipsoid_t(abc(1), abc(2), abc(3), status)
    rot1 = rot_y(0.25_wp)
    o1 = [0.0_wp, 0.0_wp, -0.1_wp]
    n = rot1(:, 3)
    gap = new_contact_gap(plane, 1.0_wp, egg, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    c = o1 + 1.0_wp*n
    rot2 = rot_x(0.3_wp)
    call gap%start_from_search(rot1, o1, rot2, c, status)
    call check(status%ok(), 'tumbling ellipsoid: started '//status%text())
    worst = 0
    do i = 0, 2000
      ! Two turns about x and 1.3 about y: the support point passes every pole.
      rot2 = matmul(rot_x(0.3_wp + 4*pi*i/2000), rot_y(2.6_wp*pi*i/2000))
      c = o1 + (1.0_wp - 0.2_wp*sin(0.01_wp*i))*n
      call gap%update(rot1, o1, rot2, c, status)
      if (.not. status%ok()) exit
      m = matmul(transpose(rot2), n)
      expected = dot_product(n, c - o1) - sqrt(sum((abc*m)**2))
      worst = max(worst, abs(gap%gap - expected))
    end do
    call check(status%ok(), 'tumbling ellipsoid: tracked through the poles '//status%text())
    call check(worst <= 1e-12_wp, 'tumbling ellipsoid: gap = n.(c - p0) - support')
  end subroutine check_tumbling_ellipsoid

  subroutine check_two_spheres()
    type(ellipsoid_t) :: s1, s2
    type(contact_gap_t) :: gap
    type(status_t) :: status
    real(wp) :: c2(3), worst, angle
    integer :: i
    s1 = ellipsoid_t(0.5_wp, 0.5_wp, 0.5_wp, status)
    s2 = ellipsoid_t(0.2_wp, 0.2_wp, 0.2_wp, status)
    gap = new_contact_gap(s1, 1.0_wp, s2, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    c2 = [0.0_wp, 0.9_wp, 0.1_wp]
    call gap%start_from_search(identity3(), [0.0_wp, 0.0_wp, 0.0_wp], identity3(), c2, status)
    call check(status%ok(), 'two spheres: started '//status%text())
    worst = 0
    do i = 0, 1000
      ! Round sphere 1 over its poles (a great circle through z), at a varying distance.
      angle = 2*pi*i/1000
      c2 = (0.75_wp + 0.1_wp*cos(3*angle))*[0.0_wp, cos(angle), sin(angle)]
      call gap%update(rot_z(0.01_wp*i), [0.0_wp, 0.0_wp, 0.0_wp], rot_x(0.02_wp*i), c2, status)
      if (.not. status%ok()) exit
      worst = max(worst, abs(gap%gap - (norm2(c2) - 0.7_wp)))
    end do
    call check(status%ok(), 'two spheres: tracked over the poles '//status%text())
    call check(worst <= 1e-13_wp, 'two spheres: gap = |c2 - c1| - R1 - R2')
  end subroutine check_two_spheres

  subroutine check_ellipsoid_in_bowl()
    type(paraboloid_t) :: bowl
    type(ellipsoid_t) :: egg
    type(contact_gap_t) :: gap, touching
    type(status_t) :: status
    type(surface_point_t) :: pt, q
    real(wp) :: rot2(3, 3), c(3), best, d, u, v, x(3)
    integer :: i, j
    bowl = paraboloid_t(1.2_wp, 1.5_wp, 1.0_wp, status)
    egg = ellipsoid_t(0.15_wp, 0.1_wp, 0.2_wp, status)
    gap = new_contact_gap(bowl, 1.0_wp, egg, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    rot2 = matmul(rot_x(0.7_wp), rot_z(0.4_wp))
    c = [0.3_wp, -0.2_wp, 0.45_wp]
    call gap%start_from_search(identity3(), [0.0_wp, 0.0_wp, 0.0_wp], rot2, c, status)
    call check(status%ok(), 'egg in bowl: started '//status%text())
    call check(gap%gap > 0 .and. gap%normals_cosine < -0.999_wp, 'egg in bowl: apart, on the contact branch')
    ! Moved by -gap along n_1 it touches: gap 0, its point on the bowl.
    touching = gap
    call touching%update(identity3(), [0.0_wp, 0.0_wp, 0.0_wp], rot2, c - gap%gap*gap%normal, status)
    call check_close(touching%gap, 0.0_wp, 0.0_wp, 1e-13_wp, 'egg in bowl: moved by the gap it touches')
    call nearest_point(bowl, touching%point_2, u, v, status)
    call bowl%evaluate(u, v, 0, pt, status)
    call check_close(norm2(pt%r - touching%point_2), 0.0_wp, 0.0_wp, 1e-12_wp, 'egg in bowl: the touching point is on the bowl')
    ! The smallest signed distance of the egg's points to the bowl (60 x 30 samples).
    best = huge(1.0_wp)
    do i = 0, 59
      do j = 1, 29
        call egg%evaluate(2*pi*i/60, -pi/2 + pi*j/30, 0, q, status)
        x = c + matmul(rot2, q%r)
        call nearest_point(bowl, x, u, v, status)
        call bowl%evaluate(u, v, 1, pt, status)
        d = dot_product(x - pt%r, cross(pt%ru, pt%rv))/norm2(cross(pt%ru, pt%rv))
        best = min(best, d)
      end do
    end do
    ! Sampling error: the egg's largest curvature radius times (spacing)^2/8.
    call check(best >= gap%gap - 1e-12_wp .and. best - gap%gap <= 0.2_wp*(pi/30)**2/2, &
      'egg in bowl: the gap is the smallest distance of the egg to the bowl')
  end subroutine check_ellipsoid_in_bowl

  !> Both bodies move: origins o_i(t) = o_i + v_i t, rotations exp(w_i t) R_i
  !> (about fixed axes); d gap/dt by central differences (h = 1e-5 s).
  subroutine check_rate()
    type(plane_t) :: plane
    type(ellipsoid_t) :: egg
    type(contact_gap_t) :: gap, probe
    type(status_t) :: status
    real(wp), parameter :: h = 1e-5_wp, t = 0.3_wp
    real(wp) :: v1(3), v2(3), rate, fd, g(2)
    integer :: k
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], status)
    egg = ellipsoid_t(0.3_wp, 0.2_wp, 0.45_wp, status)
    v1 = [0.2_wp, -0.1_wp, 0.3_wp]
    v2 = [-0.5_wp, 0.4_wp, -1.1_wp]
    gap = new_contact_gap(plane, 1.0_wp, egg, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    call gap%start_from_search(pose1(t), v1*t, pose2(t), [0.1_wp, 0.0_wp, 1.0_wp] + v2*t, status)
    ! angular velocities: d/dt rot_x(w t) R = [w e_x]x rot_x(w t) R
    rate = gap%rate(v1, w1*[1.0_wp, 0.0_wp, 0.0_wp], v2, w2*[0.0_wp, 0.0_wp, 1.0_wp])
    do k = 1, 2
      probe = gap
      call probe%update(pose1(t + (2*k - 3)*h), v1*(t + (2*k - 3)*h), pose2(t + (2*k - 3)*h), &
        [0.1_wp, 0.0_wp, 1.0_wp] + v2*(t + (2*k - 3)*h), status)
      g(k) = probe%gap
    end do
    fd = (g(2) - g(1))/(2*h)
    call check_close(rate, fd, 1e-9_wp, 1e-10_wp, 'gap rate = central difference')
  end subroutine check_rate

  !> The Jacobian of f = [d.t1_u, d.t1_v, n_1.t2_u, n_1.t2_v] against central
  !> differences, at the solution of a start and at points away from it
  !> (the Jacobian is f's derivative everywhere, not only at a solution).
  !> Tolerance: check_jacobian steps h = eps^(1/3) max(1, |x_j|) (<= 2e-5
  !> here), so truncation h^2/6 |f'''| with f''' (third derivatives of the
  !> surfaces, second of n_1: of the surfaces' size, 0.1-1 m, times 1/cos(v)^2
  !> <= 30 at |v| = 1.37 near a pole) is below ~1e-9, and rounding eps |f|/h
  !> ~1e-10; relative to max(1, |J|). 1e-7 leaves a factor 100 and still
  !> sees any term dropped or mistaken: the smallest, d.r_uv or n_1.r_uv,
  !> is 1e-2 or more at these points.
  subroutine check_newton_jacobian()
    type(plane_t) :: plane
    type(ellipsoid_t) :: ball, egg, big
    type(paraboloid_t) :: bowl
    type(gap_system_t) :: system
    type(status_t) :: status
    integer :: i, k
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 1.0_wp, 0.0_wp], status)
    ball = ellipsoid_t(0.3_wp, 0.3_wp, 0.3_wp, status)
    egg = ellipsoid_t(0.3_wp, 0.2_wp, 0.45_wp, status)
    big = ellipsoid_t(0.5_wp, 0.7_wp, 0.4_wp, status)
    bowl = paraboloid_t(1.2_wp, 1.5_wp, 1.0_wp, status)
    call jacobian_at_offsets('sphere/plane', plane, ball, rot_y(0.3_wp), [0.5_wp, -1.0_wp, 0.2_wp], &
                             rot_z(0.4_wp), [0.7_wp, -0.8_wp, 1.1_wp])
    call jacobian_at_offsets('ellipsoid/plane', plane, egg, rot_x(-0.2_wp), [0.0_wp, 0.0_wp, -0.1_wp], &
                             matmul(rot_x(0.3_wp), rot_y(0.8_wp)), [0.2_wp, 0.1_wp, 0.9_wp])
    call jacobian_at_offsets('ellipsoid/ellipsoid', big, egg, rot_z(0.3_wp), [0.1_wp, 0.0_wp, 0.0_wp], &
                             matmul(rot_x(0.6_wp), rot_z(-0.5_wp)), [0.5_wp, 0.9_wp, 0.4_wp])
    call jacobian_at_offsets('egg in bowl', bowl, egg, identity3(), [0.0_wp, 0.0_wp, 0.0_wp], &
                             matmul(rot_x(0.7_wp), rot_z(0.4_wp)), [0.3_wp, -0.2_wp, 0.45_wp])

    ! Near the poles: v = +-1.37 rad (a tracked point changes chart once
    ! cos v - cos 1.4 < 0.02, at |v| ~ 1.38), where n_1's Weingarten terms
    ! are largest; first in the base charts, then with the egg carried round
    ! the big one over its poles until both points are in other charts.
    system%gap = new_contact_gap(big, 1.0_wp, egg, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    call system%gap%start_from_search(identity3(), [0.0_wp, 0.0_wp, 0.0_wp], rot_x(0.2_wp), &
                                      [0.0_wp, 1.3_wp, 0.1_wp], status)
    call check(status%ok(), 'Jacobian near the poles: started '//status%text())
    call jacobian_near_poles('base charts', system)
    do i = 1, 400
      call system%gap%update(rot_z(0.01_wp*i), [0.0_wp, 0.0_wp, 0.0_wp], matmul(rot_y(0.04_wp*i), rot_x(0.2_wp)), &
                             1.3_wp*[0.0_wp, cos(0.01_wp*pi*i), sin(0.01_wp*pi*i)], status)
      if (.not. status%ok()) exit
      if (all([(any(system%gap%surface(k)%chart_rotation /= identity3()), k = 1, 2)])) exit
    end do
    call check(status%ok() .and. all([(any(system%gap%surface(k)%chart_rotation /= identity3()), k = 1, 2)]), &
               'Jacobian near the poles: both points tracked into other charts '//status%text())
    call jacobian_near_poles('other charts', system)
  end subroutine check_newton_jacobian

  !> The Jacobian at a start's solution and at two points away from it.
  subroutine jacobian_at_offsets(label, surface_1, surface_2, rot1, o1, rot2, o2)
    character(len=*), intent(in) :: label
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: rot1(3, 3), o1(3), rot2(3, 3), o2(3)
    real(wp), parameter :: offsets(4, 3) = reshape([0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
      0.3_wp, -0.2_wp, 0.25_wp, 0.15_wp, -0.4_wp, 0.1_wp, -0.3_wp, 0.35_wp], [4, 3])
    type(gap_system_t) :: system
    type(status_t) :: status
    real(wp) :: err, worst
    integer :: j
    system%gap = new_contact_gap(surface_1, 1.0_wp, surface_2, 1.0_wp, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    call system%gap%start_from_search(rot1, o1, rot2, o2, status)
    call check(status%ok() .and. system%gap%gap > 0, label//': started apart '//status%text())
    worst = 0
    do j = 1, size(offsets, 2)
      call check_jacobian(system, system%gap%x + offsets(:, j), err, status)
      if (.not. status%ok()) exit
      worst = max(worst, err)
    end do
    call check(status%ok() .and. worst < jacobian_tolerance, label//': Jacobian = central differences ('// &
               format_error(worst)//') '//status%text())
  end subroutine jacobian_at_offsets

  !> The Jacobian with both points at |v| = 1.37 in their current charts.
  subroutine jacobian_near_poles(label, system)
    character(len=*), intent(in) :: label
    type(gap_system_t), intent(inout) :: system
    type(status_t) :: status
    real(wp) :: x(4), err, worst
    integer :: j
    worst = 0
    do j = 1, 4
      x = system%gap%x
      x(2) = merge(1.37_wp, -1.37_wp, j <= 2)
      x(4) = merge(1.37_wp, -1.37_wp, mod(j, 2) == 1)
      call check_jacobian(system, x, err, status)
      if (.not. status%ok()) exit
      worst = max(worst, err)
    end do
    call check(status%ok() .and. worst < jacobian_tolerance, 'ellipsoid/ellipsoid near the poles, '//label// &
               ': Jacobian = central differences ('//format_error(worst)//') '//status%text())
  end subroutine jacobian_near_poles

  function format_error(err) result(text)
    real(wp), intent(in) :: err
    character(len=:), allocatable :: text
    character(len=12) :: buffer
    write (buffer, '(es10.2)') err
    text = 'worst '//trim(adjustl(buffer))
  end function format_error

  function pose1(time) result(r)
    real(wp), intent(in) :: time
    real(wp) :: r(3, 3)
    r = matmul(rot_x(w1*time), rot_y(0.2_wp))
  end function pose1

  function pose2(time) result(r)
    real(wp), intent(in) :: time
    real(wp) :: r(3, 3)
    r = matmul(rot_z(w2*time), rot_x(0.5_wp))
  end function pose2
end program test_contact_gap
