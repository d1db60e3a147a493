!> The bowl of any profile (issue 26): `bowl_profile = 'table'`, the wall
!> z(rho) the quintic spline through a table of points.
!>
!> cone: a table of points on a cone (z = rho tan 35 deg) is interpolated
!> exactly by the quintic, so its bowl is the conical bowl's: the centerline
!> and its derivatives to the fourth equal those of `bowl_profile = 'cone'`
!> to 1e-9 relative everywhere (all the conical bowl's checks of
!> test_slide_bowl carry over).
!>
!> sphere: a table of 27 points on the sphere of the shipped bowl (radius
!> 7.83 m, rho 1 to 7.5 m every 0.25 m) gives the spherical bowl within the
!> spline's interpolation error: the wall's height (measured here against
!> the sphere on a fine grid) bounds the outlet's radius error and the
!> centerline's; its joints are continuous in position, tangent and
!> curvature to 1e-9 and its derivatives match central differences.
!>
!> refusals: too few points, radii not increasing, heights and radii of
!> different counts, the entry outside the table, a drop below the table, a
!> wall that stops rising outward above the outlet, no table.
program test_slide_bowl_table
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use geometry_curve, only: curve_point_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use testing, only: check, finish_tests
  implicit none (type, external)

  real(wp), parameter :: rho_in = 6, entry_deg = 50, depth = 2, turns = 1   ! m, deg, m, 1

  call table_cone()
  call table_sphere()
  call table_refusals()
  call finish_tests('test_slide_bowl_table')

contains

  !> Straight, bowl, straight (transitions 2 m) with the bowl `bowl`.
  function chain_with(bowl, status) result(chain)
    type(slide_element_t), intent(in) :: bowl
    type(status_t), intent(out) :: status
    type(element_chain_curve_t) :: chain
    type(slide_element_t) :: e(3)
    e(1) = slide_element_t(kind='straight', length=8.0_wp, slope_deg=10.0_wp)
    e(2) = bowl
    e(3) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp)
    chain = new_element_chain(e, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, 2.0_wp, status)
  end function chain_with

  function table_bowl(rho, z, drop) result(e)
    real(wp), intent(in) :: rho(:), z(:), drop
    type(slide_element_t) :: e
    e = slide_element_t(kind='bowl', bowl_profile='table', radius=rho_in, drop=drop, turns=turns, direction='right')
    e%bowl_rho = rho
    e%bowl_z = z
  end function table_bowl

  subroutine table_cone()
    type(element_chain_curve_t) :: cone, table
    type(status_t) :: st
    type(curve_point_t) :: p, q
    real(wp) :: rho(16), worst, x
    integer :: i, n
    rho = [(0.5_wp*i, i = 1, 16)]
    cone = chain_with(slide_element_t(kind='bowl', bowl_profile='cone', radius=rho_in, slope_deg=35.0_wp, &
                                      drop=depth, turns=turns, direction='right'), st)
    call check(st%ok(), 'cone bowl built: '//st%text())
    table = chain_with(table_bowl(rho, rho*tan(35*pi/180), depth), st)
    call check(st%ok(), 'cone table bowl built: '//st%text())
    if (.not. st%ok()) return
    call check(abs(table%total - cone%total) <= 1e-9_wp*cone%total, 'the cone''s table gives the cone''s length: '// &
               real_text(table%total)//' m, '//real_text(cone%total)//' m')
    worst = 0
    do i = 0, 400
      x = min(cone%total, table%total)*i/400.0_wp
      call cone%evaluate(x, 4, p, st)
      call table%evaluate(x, 4, q, st)
      do n = 0, 4
        worst = max(worst, norm2(p%d(:, n) - q%d(:, n))/max(norm2(p%d(:, n)), 1.0_wp))
      end do
    end do
    print '(a, es10.3)', 'cone table against the cone: largest relative difference (to the 4th derivative): ', worst
    call check(worst <= 1e-9_wp, 'a table on a cone gives the conical bowl (to the 4th derivative, 1e-9): '// &
               real_text(worst))
  end subroutine table_cone

  subroutine table_sphere()
    type(element_chain_curve_t) :: sphere, table
    type(status_t) :: st
    type(curve_point_t) :: p, q, r
    real(wp) :: rho(27), big_r, worst, x, wall_error, jump(3), marks(6), h, s
    integer :: i, n
    big_r = rho_in/sin(entry_deg*pi/180)
    rho = [(1 + 0.25_wp*(i - 1), i = 1, 27)]
    sphere = chain_with(slide_element_t(kind='bowl', bowl_profile='sphere', radius=rho_in, slope_deg=entry_deg, &
                                        drop=depth, turns=turns, direction='right'), st)
    call check(st%ok(), 'sphere bowl built: '//st%text())
    table = chain_with(table_bowl(rho, big_r - sqrt(big_r**2 - rho**2), depth), st)
    call check(st%ok(), 'sphere table bowl built: '//st%text())
    if (.not. st%ok()) return
    ! the interpolation error of the wall between the outlet and the entry
    wall_error = 0
    associate (b => table%bowls(1))
      do i = 0, 2000
        s = b%rho_out + (b%rho_in - b%rho_out)*i/2000.0_wp
        wall_error = max(wall_error, abs((b%height_above_bottom(s) - b%height_above_bottom(b%rho_in)) - &
                                         (sqrt(big_r**2 - b%rho_in**2) - sqrt(big_r**2 - s**2))))
      end do
      print '(a, es10.3, a, es10.3, a)', 'sphere table: wall height error ', wall_error, ' m, outlet radius error ', &
        b%rho_out - sphere%bowls(1)%rho_out, ' m'
      ! the outlet where the wall has fallen by the drop: off by the height
      ! error over the wall's slope there (>= 0.5)
      call check(abs(b%rho_out - sphere%bowls(1)%rho_out) <= 2*wall_error + 1e-12_wp, &
                 'the sphere''s table puts the outlet where the sphere does (within the wall''s error): '// &
                 real_text(b%rho_out - sphere%bowls(1)%rho_out)//' m')
      marks = [b%lo, b%sigma0, b%sigma0 + b%width_in/2, b%sigma0 + b%length - b%width_out/2, &
               b%sigma0 + b%length, b%hi]
    end associate
    ! positions: the heights follow the wall, the plan its outlet radius
    worst = 0
    do i = 0, 400
      x = min(sphere%total, table%total)*i/400.0_wp
      call sphere%evaluate(x, 0, p, st)
      call table%evaluate(x, 0, q, st)
      worst = max(worst, norm2(p%d(:, 0) - q%d(:, 0)))
    end do
    print '(a, es10.3, a)', 'sphere table against the sphere: largest distance of the centerlines ', worst, ' m'
    ! the spiral's length over its plan (2.4 m of radius at sin(beta) 0.08:
    ! ~30 m) magnifies an outlet error by ~1/sin(beta), and the heading's
    ! integral of kappa by ~turns 2 pi rho: bound 1000 times the wall's error
    call check(worst <= 1e3_wp*wall_error, 'the sphere''s table gives the spherical bowl''s centerline: '// &
               real_text(worst)//' m (wall error '//real_text(wall_error)//' m)')
    ! continuity at the table bowl's joints and windows (one-sided limits
    ! carried across by the next derivative, h = 1e-7 m)
    jump = 0
    h = 1e-7_wp
    do i = 1, 6
      call table%evaluate(marks(i) - h, 3, p, st)
      call table%evaluate(marks(i) + h, 3, q, st)
      jump(1) = max(jump(1), norm2(p%d(:, 0) + 2*h*p%d(:, 1) - q%d(:, 0))/max(norm2(q%d(:, 0)), 1.0_wp))
      jump(2) = max(jump(2), norm2(p%d(:, 1) + 2*h*p%d(:, 2) - q%d(:, 1)))
      jump(3) = max(jump(3), norm2(p%d(:, 2) + 2*h*p%d(:, 3) - q%d(:, 2)))
    end do
    print '(a, 3es10.3)', 'sphere table: jumps of position, tangent, curvature at the joints: ', jump
    call check(all(jump <= 1e-9_wp), 'the table bowl''s joints are continuous in position, tangent and '// &
               'curvature (1e-9)')
    ! derivatives against central differences (h = 1e-5 m)
    worst = 0
    associate (b => table%bowls(1))
      do i = 1, 41
        x = b%lo + (b%hi - b%lo)*(i - 0.37_wp)/41
        call table%evaluate(x, 4, p, st)
        call table%evaluate(x + 1e-5_wp, 4, q, st)
        call table%evaluate(x - 1e-5_wp, 4, r, st)
        do n = 1, 4
          worst = max(worst, norm2((q%d(:, n - 1) - r%d(:, n - 1))/2e-5_wp - p%d(:, n))/max(norm2(p%d(:, n)), 1.0_wp))
        end do
      end do
    end associate
    call check(worst <= 1e-6_wp, 'the table bowl''s derivatives against central differences: '//real_text(worst))
  end subroutine table_sphere

  subroutine table_refusals()
    real(wp) :: rho(16), z(16)
    type(slide_element_t) :: e
    integer :: i
    rho = [(0.5_wp*i, i = 1, 16)]
    z = rho*tan(35*pi/180)
    call refused(table_bowl(rho(:5), z(:5), depth), 'the profile table has 5 points')
    call refused(table_bowl(rho(16:1:-1), z, depth), 'must be >= 0 and increase')
    call refused(table_bowl(rho, z(:15), depth), 'give one height per radius')
    call refused(table_bowl(rho(:10), z(:10), depth), 'the entry must lie within the profile table''s radii')
    call refused(table_bowl(rho, z, 4.0_wp), 'reaches below the profile table''s first point')
    ! a wall that falls again below rho = 3 m (a bump in the bottom)
    call refused(table_bowl(rho, z + 2*exp(-(rho - 2)**2/0.3_wp), 3.0_wp), 'stops rising outward')
    e = slide_element_t(kind='bowl', bowl_profile='table', radius=rho_in, drop=depth, turns=turns)
    call refused(e, 'needs the profile''s points')
  end subroutine table_refusals

  subroutine refused(bowl, words)
    type(slide_element_t), intent(in) :: bowl
    character(len=*), intent(in) :: words
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    chain = chain_with(bowl, st)
    call check(.not. st%ok() .and. index(st%text(), words) > 0, 'refused ('//words//'): '//st%text())
  end subroutine refused

  function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(es10.3)') x
    text = trim(adjustl(buf))
  end function real_text
end program test_slide_bowl_table
