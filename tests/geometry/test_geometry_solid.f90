!> Mass properties of the homogeneous solid of a closed surface
!> (geometry_solid) against closed forms: the egg of thesis 3.5.3.3
!> (V = 4/3 pi a b c, I = V (b^2 + c^2)/5 ...), the same ellipsoid placed off
!> the origin and turned (centre and R I R^T), and refusals of an open patch,
!> an unbounded plane and an inward normal.
program test_geometry_solid
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_vector, only: rot_x, rot_z
  use testing, only: check, check_close, finish_tests
  use geometry_elementary, only: ellipsoid_t, paraboloid_t
  use geometry_placed_surface, only: placed_surface_t
  use geometry_bspline_surface, only: bspline_surface_t, bspline_scattered
  use geometry_solid, only: solid_properties_t, solid_properties
  implicit none (type, external)

  ! Gauss-Legendre (64 nodes) and the trapezoidal rule on smooth periodic
  ! integrands converge spectrally: rounding of ~4000 terms, ~1e-14 relative.
  real(wp), parameter :: tol = 1e-13_wp
  real(wp), parameter :: a = 0.025_wp, b = 0.033_wp, c = 0.025_wp
  type(ellipsoid_t) :: egg
  type(placed_surface_t) :: moved
  type(solid_properties_t) :: props
  type(status_t) :: st
  real(wp) :: vol, inertia(3, 3), rot(3, 3)

  egg = ellipsoid_t(a, b, c, st)
  call solid_properties(egg, 1.0_wp, props, st)
  call check(st%ok(), 'egg: '//st%text())
  vol = 4*pi*a*b*c/3
  inertia = 0
  inertia(1, 1) = vol*(b**2 + c**2)/5
  inertia(2, 2) = vol*(a**2 + c**2)/5
  inertia(3, 3) = vol*(a**2 + b**2)/5
  call check_close(props%volume, vol, tol, 0.0_wp, 'egg volume 4/3 pi a b c')
  call check(maxval(abs(props%centre)) <= tol*b, 'egg centre at the origin')
  call check(maxval(abs(props%inertia - inertia)) <= tol*maxval(inertia), 'egg inertia V (b^2 + c^2)/5 ...')
  print '(a, es12.4, a, 3es12.4)', 'egg: 80 g gives I_eq, I_pol = ', 0.08_wp/vol*inertia(1, 1), ' kg m^2; error ', &
    maxval(abs(props%inertia - inertia))/maxval(inertia)

  rot = matmul(rot_z(0.7_wp), rot_x(-1.1_wp))
  moved = placed_surface_t(egg, [0.1_wp, -0.2_wp, 0.05_wp], st, rotation=rot)
  call solid_properties(moved, 1.0_wp, props, st)
  call check(st%ok(), 'placed egg: '//st%text())
  call check_close(props%volume, vol, tol, 0.0_wp, 'placed egg volume')
  call check(maxval(abs(props%centre - [0.1_wp, -0.2_wp, 0.05_wp])) <= tol*0.2_wp, 'placed egg centre = its origin')
  ! the moments about the centre come from moments about the origin, V |c|^2
  ! (~ 100 times the inertia here): the error scales with that
  call check(maxval(abs(props%inertia - matmul(rot, matmul(inertia, transpose(rot))))) <= &
             tol*vol*sum(props%centre**2), 'placed egg inertia R I R^T')
  print '(a, es10.2)', 'placed egg: inertia error relative to V |c|^2: ', &
    maxval(abs(props%inertia - matmul(rot, matmul(inertia, transpose(rot)))))/(vol*sum(props%centre**2))

  call solid_properties(egg, -1.0_wp, props, st)
  call check(.not. st%ok() .and. index(st%text(), 'side') > 0, 'inward normal refused: '//st%text())
  st = status_t()
  call solid_properties(paraboloid_t(1.0_wp, 1.0_wp, 1.0_wp, st), 1.0_wp, props, st)
  call check(.not. st%ok() .and. index(st%text(), 'unbounded') > 0, 'unbounded paraboloid refused: '//st%text())
  st = status_t()
  call solid_properties(quadratic_patch(), 1.0_wp, props, st)
  call check(.not. st%ok() .and. index(st%text(), 'not closed') > 0, 'open B-spline patch refused: '//st%text())
  call finish_tests('test_geometry_solid')

contains

  !> z = (x^2 + y^2)/3 on [-2, 2]^2 (the paraboloid of table 3.2).
  function quadratic_patch() result(s)
    type(bspline_surface_t) :: s
    real(wp) :: x(49), y(49)
    integer :: i, j
    do j = 1, 7
      do i = 1, 7
        x(i + 7*(j - 1)) = -2 + 4*(i - 1)/6.0_wp
        y(i + 7*(j - 1)) = -2 + 4*(j - 1)/6.0_wp
      end do
    end do
    s = bspline_scattered(x, y, (x**2 + y**2)/3, 0.0_wp, 3, 3, st)
  end function quadratic_patch
end program test_geometry_solid
