!> Blended surfaces (thesis 3.73-3.82, appendix D): the blend of three
!> paraboloids (3.80-3.82) and of two cylinders (fig. 3.16) rebuilt; the
!> blend equals its patches where the weights are 0 or 1 (to the 0.99
!> definition); partials to third order against central differences at
!> scattered points, across the transitions (smoothness); bad input.
program test_blended
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_elementary, only: paraboloid_t, elliptic_cylinder_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_blended_surface, only: blended_surface_t, blend_patch_t, new_blended_surface
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! Central differences, step 1e-5: error ~1e-11 S (S: size of the partials,
  ! < 1e3 with xi = 9.2 here); 1e-7 (1 + S) keeps a margin > 100.
  real(wp), parameter :: h = 1e-5_wp, fd_tol = 1e-7_wp
  type(status_t) :: st
  type(paraboloid_t) :: para
  type(elliptic_cylinder_t) :: cyl0, cyl1
  type(blend_patch_t) :: pp(3), pc(2)
  type(blended_surface_t) :: blend
  type(surface_point_t) :: p, q0, q1
  real(wp) :: a, b, c, d, u, v, x, w(0:3, 3)
  integer :: i, j

  ! --- three paraboloids (3.80-3.82): z = (u^2 + v^2)/(-8.5), 3 m apart along x.
  ! paraboloid_t needs a > 0: (3.58) with a^2 = b^2 = -8.5 is the paraboloid of
  ! a^2 = 8.5 turned upside down (rotation by pi about x: [x, -y, -z]).
  para = paraboloid_t(sqrt(8.5_wp), sqrt(8.5_wp), 1.0_wp, st)
  do j = 1, 3
    allocate (pp(j)%surface, source=placed_surface_t(para, [3.0_wp*(j - 1), 0.0_wp, 0.0_wp], st, &
                                                     angles=[pi, 0.0_wp, 0.0_wp]))
    pp(j)%u_min = -1; pp(j)%u_max = 1; pp(j)%v_min = -1; pp(j)%v_max = 1
  end do
  ! transitions of length 1: patch j occupies u in [3(j-1), 3(j-1) + 2]
  blend = new_blended_surface(pp, [1.0_wp, 1.0_wp], st, midpoint=[2.5_wp, 5.5_wp], u_99=[3.0_wp, 6.0_wp])
  call check(st%ok(), 'paraboloid blend built: ' // st%text())
  call blend%domain(a, b, c, d)
  call check_close(b, 8.0_wp, 1e-15_wp, 0.0_wp, 'paraboloid blend: u in [0, 8] (3.76)')
  ! x = u - 1 on every patch (3.77): the patches line up in x
  do i = 0, 80
    u = 0.1_wp*i
    v = 0.5_wp + 0.3_wp*sin(1.7_wp*u)
    call blend%evaluate(u, v, 0, p, st)
    x = u - 1
    call blend%weights(u, w)
    ! the weights of (3.79) sum to 1 + L_2 (1 - L_1) (not exactly 1; < 1e-9 here)
    call check(abs(sum(w(0, :)) - 1) < 1e-9_wp, 'paraboloid blend: weights sum to 1 within 1e-9')
    call check_close(p%r(1), x*sum(w(0, :)), 0.0_wp, 1e-14_wp, 'paraboloid blend: x = u - 1')
    call check_close(p%r(2), -(2*v - 1)*sum(w(0, :)), 0.0_wp, 1e-14_wp, 'paraboloid blend: y = -v_j')
    ! z = -(sum_j w_j (x - 3(j-1))^2 + v_j^2)/8.5 with the weights of (3.79)
    call check_close(p%r(3), -(w(0, 1)*x**2 + w(0, 2)*(x - 3)**2 + w(0, 3)*(x - 6)**2 + &
                     sum(w(0, :))*(2*v - 1)**2)/8.5_wp, 0.0_wp, 1e-13_wp, 'paraboloid blend: z')
    ! inside a patch's own range the blend is that patch to the 0.99 definition:
    ! |r - p_j| <= 0.01 |p_j - p_neighbour| (+ the far weight, < 1e-10)
    if (u <= 2) call check(abs(p%r(3) + (x**2 + (2*v - 1)**2)/8.5_wp) <= &
                           0.0101_wp*abs(x**2 - (x - 3)**2)/8.5_wp + 1e-12_wp, 'blend = patch 1 for u <= 2')
    if (u >= 3 .and. u <= 5) call check(abs(p%r(3) + ((x - 3)**2 + (2*v - 1)**2)/8.5_wp) <= &
                           0.0101_wp*max(abs(x**2 - (x - 3)**2), abs((x - 6)**2 - (x - 3)**2))/8.5_wp &
                           + 1e-12_wp, 'blend = patch 2 for 3 <= u <= 5')
    if (u >= 6) call check(abs(p%r(3) + ((x - 6)**2 + (2*v - 1)**2)/8.5_wp) <= &
                           0.0101_wp*abs((x - 6)**2 - (x - 3)**2)/8.5_wp + 1e-12_wp, 'blend = patch 3 for u >= 6')
  end do
  call fd_surface(blend, 'three paraboloids')

  ! --- two cylinders (fig. 3.16).
  cyl0 = elliptic_cylinder_t(1.0_wp, 1.0_wp, st)
  cyl1 = elliptic_cylinder_t(1.0_wp, 2.0_wp, st)
  allocate (pc(1)%surface, source=placed_surface_t(cyl0, [0.0_wp, 0.0_wp, 0.0_wp], st, &
            angles=[pi/2, -40*pi/180, -pi/2]))
  pc(1)%u_min = -4; pc(1)%u_max = -0.9_wp; pc(1)%v_min = 0; pc(1)%v_max = pi
  allocate (pc(2)%surface, source=placed_surface_t(cyl1, [0.0_wp, 0.0_wp, 0.0_wp], st, &
            angles=[0.0_wp, pi, 0.0_wp]))
  pc(2)%u_min = 3.7_wp; pc(2)%u_max = 4.6_wp; pc(2)%v_min = 1.5_wp; pc(2)%v_max = -1.5_wp
  pc(2)%swap_uv = .true.
  ! patch 1 has length 3.1; midpoint 3.2 and u_99 = 3.3 give a transition of 0.2
  blend = new_blended_surface(pc, [0.2_wp], st, midpoint=[3.2_wp], u_99=[3.3_wp])
  call check(st%ok(), 'cylinder blend built')
  call blend%domain(a, b, c, d)
  call check_close(b, 4.2_wp, 1e-14_wp, 0.0_wp, 'cylinder blend: u in [0, 4.2]')
  do i = 0, 42
    u = 0.1_wp*i
    v = 0.37_wp
    call blend%evaluate(u, v, 0, p, st)
    call pc(1)%surface%evaluate(u - 4, pi*v, 0, q0, st)
    call pc(2)%surface%evaluate(1.5_wp - 3*v, u + 0.4_wp, 0, q1, st)
    if (u <= 3.1_wp + 1e-12_wp) call check(norm2(p%r - q0%r) <= 0.0101_wp*norm2(q1%r - q0%r) + 1e-12_wp, &
                                            'cylinder blend = cylinder 1 for u <= 3.1')
    if (u >= 3.3_wp - 1e-12_wp) call check(norm2(p%r - q1%r) <= 0.0101_wp*norm2(q1%r - q0%r) + 1e-12_wp, &
                                            'cylinder blend = cylinder 2 for u >= 3.3')
  end do
  ! the second patch's point lies on its cylinder: x^2 + (y/2)^2 = 1 after R_y(pi)
  call blend%evaluate(4.0_wp, 0.2_wp, 0, p, st)
  call check_close(p%r(1)**2 + (p%r(2)/2)**2, 1.0_wp, 1e-12_wp, 0.0_wp, 'cylinder 2: on x^2 + y^2/4 = 1')
  call fd_surface(blend, 'two cylinders')

  ! --- bad input
  blend = new_blended_surface(pc(1:1), [real(wp) ::], st)
  call check(st%code == STATUS_INVALID_INPUT, 'one patch rejected')
  blend = new_blended_surface(pc, [-0.1_wp], st)
  call check(st%code == STATUS_INVALID_INPUT, 'negative transition rejected')

  call finish_tests('test_blended')

contains

  subroutine fd_surface(surf, name)
    class(surface_t), intent(in) :: surf
    character(len=*), intent(in) :: name
    type(surface_point_t) :: p0, pu1, pu0, pv1, pv0
    real(wp) :: a, b, c, d, uu, vv, tol
    integer :: i, j
    call surf%domain(a, b, c, d)
    do i = 1, 9
      do j = 1, 3
        uu = a + (b - a)*(0.1_wp*i - 0.013_wp*j)
        vv = c + (d - c)*(0.05_wp + 0.3_wp*j - 0.02_wp*i)
        call surf%evaluate(uu, vv, 3, p0, st)
        call check(st%ok(), name // ': evaluate status')
        call surf%evaluate(uu + h, vv, 3, pu1, st)
        call surf%evaluate(uu - h, vv, 3, pu0, st)
        call surf%evaluate(uu, vv + h, 3, pv1, st)
        call surf%evaluate(uu, vv - h, 3, pv0, st)
        tol = fd_tol*(1 + maxval(abs([p0%r, p0%ru, p0%rv, p0%ruu, p0%ruv, p0%rvv, p0%ruuu, p0%ruuv, &
                                      p0%ruvv, p0%rvvv])))
        call check_close_array(p0%ru, (pu1%r - pu0%r)/(2*h), 0.0_wp, tol, name // ': r_u')
        call check_close_array(p0%rv, (pv1%r - pv0%r)/(2*h), 0.0_wp, tol, name // ': r_v')
        call check_close_array(p0%ruu, (pu1%ru - pu0%ru)/(2*h), 0.0_wp, tol, name // ': r_uu')
        call check_close_array(p0%ruv, (pv1%ru - pv0%ru)/(2*h), 0.0_wp, tol, name // ': r_uv')
        call check_close_array(p0%rvv, (pv1%rv - pv0%rv)/(2*h), 0.0_wp, tol, name // ': r_vv')
        call check_close_array(p0%ruuu, (pu1%ruu - pu0%ruu)/(2*h), 0.0_wp, tol, name // ': r_uuu')
        call check_close_array(p0%ruuv, (pv1%ruu - pv0%ruu)/(2*h), 0.0_wp, tol, name // ': r_uuv')
        call check_close_array(p0%ruvv, (pv1%ruv - pv0%ruv)/(2*h), 0.0_wp, tol, name // ': r_uvv')
        call check_close_array(p0%ruvv, (pu1%rvv - pu0%rvv)/(2*h), 0.0_wp, tol, name // ': r_vvu')
        call check_close_array(p0%rvvv, (pv1%rvv - pv0%rvv)/(2*h), 0.0_wp, tol, name // ': r_vvv')
      end do
    end do
  end subroutine fd_surface
end program test_blended
