!> Normal, fundamental forms and curvatures against closed forms.
program test_geometry_differential
  use base_kinds, only: wp
  use base_status, only: status_t
  use base_vector, only: rotation_xyz
  use geometry_surface, only: surface_point_t
  use geometry_elementary, only: plane_t, ellipsoid_t, paraboloid_t, elliptic_cylinder_t, &
                                 apex_paraboloid_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_differential, only: fundamental_forms_t, fundamental_forms, unit_normal, &
                                   first_form, second_form, gauss_curvature, mean_curvature, &
                                   principal_curvatures, radii_towards
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! rtol 1e-12: closed forms and the formulas differ by a few dozen roundings
  ! of O(1) numbers; any wrong term or sign changes the result at O(1).
  real(wp), parameter :: rtol = 1e-12_wp, atol = 1e-12_wp
  integer, parameter :: n_points = 12

  type(status_t) :: st
  type(surface_point_t) :: p, q
  type(fundamental_forms_t) :: ff
  type(ellipsoid_t) :: sphere, ellipsoid
  type(elliptic_cylinder_t) :: cylinder
  type(paraboloid_t) :: elliptic, hyperbolic
  type(apex_paraboloid_t) :: apex
  type(plane_t) :: plane
  type(placed_surface_t) :: placed
  real(wp), parameter :: radius = 2.5_wp, a = 1.7_wp, b = 0.6_wp, c = 1.2_wp
  real(wp) :: u, v, x(3), kref, fu, fv, fuu, fvv
  integer :: k
  character(len=60) :: at

  sphere = ellipsoid_t(radius, radius, radius, st)
  ellipsoid = ellipsoid_t(a, b, c, st)
  cylinder = elliptic_cylinder_t(radius, radius, st)
  elliptic = paraboloid_t(a, b, 1.0_wp, st)
  hyperbolic = paraboloid_t(a, b, -1.0_wp, st)
  apex = apex_paraboloid_t(a, b, st)
  plane = plane_t([0.0_wp, 0.0_wp, 1.0_wp], [1.0_wp, 1.0_wp, 1.0_wp], [-1.0_wp, 2.0_wp, 1.0_wp], st)
  placed = placed_surface_t(ellipsoid, [3.0_wp, 1.0_wp, -2.0_wp], st, angles=[0.4_wp, 1.2_wp, -0.8_wp])
  call check(st%ok(), 'constructors')

  do k = 1, n_points
    u = 6.2_wp*modulo(0.1_wp + k*0.6180339887498949_wp, 1.0_wp)
    v = -1.4_wp + 2.8_wp*modulo(0.3_wp + k*0.7548776662466927_wp, 1.0_wp)
    write (at, '(a, 2es11.3, a)') ' at (', u, v, ')'

    ! Sphere, outward normal r_u x r_v: K = 1/R^2, H = k1 = k2 = -1/R.
    call sphere%evaluate(u, v, 2, p, st)
    ff = fundamental_forms(p)
    call check(ff%regular, 'sphere regular' // at)
    call check_close_array(ff%normal, p%r/radius, rtol, atol, 'sphere normal is outward' // at)
    call check_close(ff%gauss, 1/radius**2, rtol, atol, 'sphere K = 1/R^2' // at)
    call check_close(ff%mean, -1/radius, rtol, atol, 'sphere H = -1/R' // at)
    call check_close(ff%k1, -1/radius, 0.0_wp, 1e-6_wp, 'sphere k1' // at)  ! umbilic: sqrt of rounding ~1e-8
    call check_close(ff%k2, -1/radius, 0.0_wp, 1e-6_wp, 'sphere k2' // at)
    call check_close_array(radii_towards(p, -p%r), [radius, radius], 1e-6_wp, 0.0_wp, &
                           'sphere radii of curvature inside = R' // at)
    call check(all(radii_towards(p, p%r) == huge(1.0_wp)), 'sphere no centre of curvature outside' // at)
    call check_close_array(first_form(p), [(radius*cos(v))**2, 0.0_wp, radius**2], rtol, atol, &
                           'sphere E, F, G' // at)
    call check_close_array(second_form(p), [-radius*cos(v)**2, 0.0_wp, -radius], rtol, atol, &
                           'sphere L, M, N' // at)

    ! Ellipsoid: K = 1/(a^2 b^2 c^2 (x^2/a^4 + y^2/b^4 + z^2/c^4)^2).
    call ellipsoid%evaluate(u, v, 2, p, st)
    x = p%r
    kref = 1/((a*b*c)**2*((x(1)/a**2)**2 + (x(2)/b**2)**2 + (x(3)/c**2)**2)**2)
    call check_close(gauss_curvature(p), kref, rtol, atol, 'ellipsoid K' // at)
    call check(mean_curvature(p) < 0, 'ellipsoid H < 0 with outward normal' // at)

    ! The placed ellipsoid: curvatures invariant, normal rotated.
    call placed%evaluate(u, v, 2, q, st)
    call check_close(gauss_curvature(q), kref, rtol, atol, 'placed ellipsoid K' // at)
    call check_close(mean_curvature(q), mean_curvature(p), rtol, atol, 'placed ellipsoid H' // at)
    call check_close_array(unit_normal(q), matmul(rotation_xyz([0.4_wp, 1.2_wp, -0.8_wp]), &
                           unit_normal(p)), rtol, atol, 'placed ellipsoid normal rotated' // at)

    ! Circular cylinder (normal r_u x r_v points to the axis): K = 0, H = 1/(2R).
    call cylinder%evaluate(3*v, u, 2, p, st)
    ff = fundamental_forms(p)
    call check_close_array(ff%normal, -[p%r(1), p%r(2), 0.0_wp]/radius, rtol, atol, &
                           'cylinder normal towards the axis' // at)
    call check_close(ff%gauss, 0.0_wp, rtol, atol, 'cylinder K = 0' // at)
    call check_close(ff%mean, 1/(2*radius), rtol, atol, 'cylinder H = 1/(2R)' // at)
    call check_close(ff%k1, 1/radius, rtol, atol, 'cylinder k1 = 1/R' // at)
    call check_close(ff%k2, 0.0_wp, rtol, atol, 'cylinder k2 = 0' // at)
    ! its centres of curvature: on the axis, R inside (towards the axis, the
    ! side given by any vector off the tangent plane); none outside, none
    ! along the straight generator (a radius beyond 1e10 R: k2 is 0 to
    ! rounding)
    call check_close(minval(radii_towards(p, -p%r + [0.0_wp, 0.0_wp, 7.0_wp])), radius, rtol, atol, &
                     'cylinder radius of curvature inside = R' // at)
    call check(maxval(radii_towards(p, -p%r)) > 1e10_wp*radius, 'cylinder straight along its axis' // at)
    call check(minval(radii_towards(p, p%r)) > 1e10_wp*radius, 'cylinder no centre of curvature outside' // at)

    ! Paraboloids, graphs z = f(u, v): K = (f_uu f_vv - f_uv^2)/(1 + f_u^2 + f_v^2)^2,
    ! H = ((1 + f_v^2) f_uu + (1 + f_u^2) f_vv)/(2 (1 + f_u^2 + f_v^2)^(3/2)).
    fu = 2*u/a**2; fv = 2*v/b**2; fuu = 2/a**2; fvv = 2/b**2
    call elliptic%evaluate(u - 3, v, 2, p, st)
    fu = 2*(u - 3)/a**2
    call check_close(gauss_curvature(p), fuu*fvv/(1 + fu**2 + fv**2)**2, rtol, atol, &
                     'elliptic paraboloid K' // at)
    call check_close(mean_curvature(p), ((1 + fv**2)*fuu + (1 + fu**2)*fvv)/(2*(1 + fu**2 + fv**2)**1.5_wp), &
                     rtol, atol, 'elliptic paraboloid H' // at)
    call hyperbolic%evaluate(u - 3, v, 2, p, st)
    call check_close(gauss_curvature(p), -fuu*fvv/(1 + fu**2 + fv**2)**2, rtol, atol, &
                     'hyperbolic paraboloid K' // at)
    call check_close(mean_curvature(p), ((1 + fv**2)*(-fuu) + (1 + fu**2)*fvv)/(2*(1 + fu**2 + fv**2)**1.5_wp), &
                     rtol, atol, 'hyperbolic paraboloid H' // at)

    ! Apex paraboloid: the same shape, so the same K at the same (x, y).
    call apex%evaluate(u, v, 2, p, st)
    x = p%r
    fu = 2*x(1)/a**2; fv = 2*x(2)/b**2
    call check_close(gauss_curvature(p), fuu*fvv/(1 + fu**2 + fv**2)**2, rtol, atol, &
                     'apex paraboloid K = K of the graph' // at)

    ! Plane: flat, normal e_u x e_v.
    call plane%evaluate(u, v, 2, p, st)
    call check_close(gauss_curvature(p), 0.0_wp, rtol, atol, 'plane K = 0' // at)
    call check_close(mean_curvature(p), 0.0_wp, rtol, atol, 'plane H = 0' // at)
    ! (A, B, C at height 1; (B - A) x (C - A) = (0, 0, 3))
    call check_close_array(unit_normal(p), [0.0_wp, 0.0_wp, 1.0_wp], rtol, atol, 'plane normal' // at)
  end do

  ! The paraboloid's apex: K = 4/(a^2 b^2), H = 1/a^2 + 1/b^2 (elliptic),
  ! K = -4/(a^2 b^2), H = 1/b^2 - 1/a^2 (hyperbolic).
  call elliptic%evaluate(0.0_wp, 0.0_wp, 2, p, st)
  call check_close(gauss_curvature(p), 4/(a*b)**2, rtol, atol, 'elliptic paraboloid apex K = 4/(a^2 b^2)')
  call check_close(mean_curvature(p), 1/a**2 + 1/b**2, rtol, atol, 'elliptic paraboloid apex H')
  call check_close_array(principal_curvatures(p), [2/b**2, 2/a**2], rtol, atol, &
                         'elliptic paraboloid apex k1, k2')
  call hyperbolic%evaluate(0.0_wp, 0.0_wp, 2, p, st)
  call check_close(gauss_curvature(p), -4/(a*b)**2, rtol, atol, 'hyperbolic paraboloid apex K')
  call check_close(mean_curvature(p), 1/b**2 - 1/a**2, rtol, atol, 'hyperbolic paraboloid apex H')

  ! Approaching the singular apex of the apex paraboloid: still accurate
  ! (no cancellation), exactly at it degenerate (regular = .false.).
  call apex%evaluate(0.7_wp, 1e-9_wp, 2, p, st)
  call check_close(gauss_curvature(p), 4/(a*b)**2, rtol, atol, 'apex paraboloid K at v = 1e-9')
  call apex%evaluate(0.7_wp, 0.0_wp, 2, p, st)
  ff = fundamental_forms(p)
  call check(.not. ff%regular .and. all(ff%normal == 0) .and. ff%gauss == 0, &
             'apex paraboloid at v = 0: degenerate, zeros')

  call finish_tests('test_geometry_differential')
end program test_geometry_differential
