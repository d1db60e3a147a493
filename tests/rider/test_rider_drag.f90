!> Water drag on the rider's spheres (thesis (4.29)-(4.31), appendix G with
!> the corrections of METHOD-PART2 B.4-B.5):
!>  - Morrison's C_D against the published reference values (2010 form);
!>  - the intersection angles of (4.31) on the water line, half chord a_y;
!>  - the projected cap area against quadrature of its definition (the
!>    front-facing part of the cap seen along the relative velocity) in all
!>    four cases, centre above and below the water, both radii;
!>  - continuity across the case boundaries; the tangent-flow limit equal to
!>    the circular segment; a dry sphere;
!>  - the drag force against hand-computed cases.
program test_rider_drag
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_vector, only: cross
  use rider_drag, only: morrison_drag_coefficient, morrison_reynolds_max, cap_intersection_angles, &
    projected_cap_area, evaluate_drag, water_properties_t, drag_state_t, CAP_DRY, CAP_PARTIAL, CAP_FULL
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  call random_init(repeatable=.true., image_distinct=.false.)
  call check_morrison()
  call check_intersections()
  call check_area_cases()
  call check_area_continuity()
  call check_tangent_flow()
  call check_drag_force()
  call finish_tests('test_rider_drag')

contains

  !> METHOD-PART2 B.5 table (2010 form, 7 significant digits) and appendix I
  !> (Morrison(200) to 15 digits).
  subroutine check_morrison()
    real(wp), parameter :: re(10) = [1.0_wp, 10.0_wp, 100.0_wp, 200.0_wp, 1e3_wp, 1e4_wp, 1e5_wp, 2.63e5_wp, &
                                     5e5_wp, 1e6_wp]
    real(wp), parameter :: cd(10) = [24.67293_wp, 3.967583_wp, 1.038187_wp, 0.7677316_wp, 0.4840563_wp, &
                                     0.3935644_wp, 0.4246766_wp, 0.2617306_wp, 0.08767688_wp, 0.1414558_wp]
    integer :: i
    character(len=16) :: label
    do i = 1, size(re)
      write (label, '(es9.2)') re(i)
      ! rtol 6e-7: the reference values carry 7 significant digits
      call check_close(morrison_drag_coefficient(re(i)), cd(i), 6e-7_wp, 0.0_wp, 'Morrison C_D at Re = '//label)
    end do
    call check_close(morrison_drag_coefficient(200.0_wp), 0.767731559965325_wp, 1e-14_wp, 0.0_wp, &
                     'Morrison C_D(200) to 15 digits')
    call check(morrison_reynolds_max == 1e6_wp, 'range ends at Re = 1e6')
    ! the rewritten third term cannot overflow at tiny Re: C_D -> 24/Re
    call check_close(morrison_drag_coefficient(1e-30_wp)*1e-30_wp, 24.0_wp, 1e-12_wp, 0.0_wp, 'Stokes limit')
  end subroutine check_morrison

  !> (4.31): both points lie on the water line A cos + B sin + C' = 0, on the
  !> unit circle, and |S1 S2|/2 = sqrt(r^2 - C'^2).
  subroutine check_intersections()
    real(wp) :: r, gamma, cp, phi(2), a, b, chord, u(3)
    logical :: found
    integer :: i
    do i = 1, 200
      call random_number(u)
      r = merge(0.5_wp, 0.05_wp, u(1) < 0.5_wp)
      gamma = (2*u(2) - 1)*1.2_wp
      cp = (2*u(3) - 1)*r*0.999_wp
      call cap_intersection_angles(r, gamma, cp, phi, found)
      a = -r*sin(gamma)
      b = -r*cos(gamma)
      call check(found, 'intersection found inside the sphere')
      ! atol 1e-15: rounding of terms of size r <= 0.5
      call check_close(a*cos(phi(1)) + b*sin(phi(1)) + cp, 0.0_wp, 0.0_wp, 1e-15_wp, 'S1 on the water line')
      call check_close(a*cos(phi(2)) + b*sin(phi(2)) + cp, 0.0_wp, 0.0_wp, 1e-15_wp, 'S2 on the water line')
      chord = 0.5_wp*r*norm2([cos(phi(1)) - cos(phi(2)), sin(phi(1)) - sin(phi(2))])
      ! atol 1e-9: sqrt(r^2 - C'^2) loses digits as |C'| -> r (C' up to 0.999 r)
      call check_close(chord, sqrt(r**2 - cp**2), 1e-12_wp, 1e-9_wp, 'half chord = cap radius')
    end do
    ! gamma = 0: sin(phi) = C'/r... the symmetric chord at depth r - C' below the top
    call cap_intersection_angles(0.5_wp, 0.0_wp, 0.47_wp, phi, found)
    call check_close(sin(phi(1)), 0.94_wp, 1e-15_wp, 0.0_wp, 'gamma = 0: symmetric chord')
    call check_close(sin(phi(2)), 0.94_wp, 1e-15_wp, 0.0_wp, 'gamma = 0: symmetric chord (2)')
    call cap_intersection_angles(0.5_wp, 0.3_wp, 0.51_wp, phi, found)
    call check(.not. found, 'no intersection above the sphere')
  end subroutine check_intersections

  !> Area of {(x, y) in the disc: the front point (x, y, sqrt(r^2 - x^2 - y^2))
  !> lies in the cap d_x x + d_z z >= c}, by the midpoint rule in x over the
  !> y-measure found by bisection (the condition is monotone in |y|). Error
  !> O(h^1.5) at each square-root point of the y-measure (the two ends of the
  !> disc, the two places where the cap's rim meets the disc's): about
  !> sqrt(2 r) h^1.5 each, <= 1e-7 m^2 in all for r = 0.5 m, h = 2r/n = 1e-5 m.
  real(wp) function quadrature_area(r, c, d_x, d_z) result(area)
    real(wp), intent(in) :: r, c, d_x, d_z
    integer, parameter :: n = 100000
    real(wp) :: h, x, y_max, lo, hi, mid, measure
    integer :: i, it
    h = 2*r/n
    area = 0
    do i = 1, n
      x = -r + (i - 0.5_wp)*h
      y_max = sqrt(r**2 - x**2)
      if (in_cap(r, c, d_x, d_z, x, 0.0_wp) .eqv. in_cap(r, c, d_x, d_z, x, y_max)) then
        measure = merge(y_max, 0.0_wp, in_cap(r, c, d_x, d_z, x, 0.0_wp))
      else
        lo = 0
        hi = y_max
        do it = 1, 60
          mid = 0.5_wp*(lo + hi)
          if (in_cap(r, c, d_x, d_z, x, mid) .eqv. in_cap(r, c, d_x, d_z, x, 0.0_wp)) then
            lo = mid
          else
            hi = mid
          end if
        end do
        measure = merge(lo, y_max - lo, in_cap(r, c, d_x, d_z, x, 0.0_wp))
      end if
      area = area + 2*measure*h
    end do
  end function quadrature_area

  !> The front point over (x, y) lies in the cap.
  logical function in_cap(r, c, d_x, d_z, x, y)
    real(wp), intent(in) :: r, c, d_x, d_z, x, y
    in_cap = d_x*x + d_z*sqrt(max(r**2 - x**2 - y**2, 0.0_wp)) >= c
  end function in_cap

  !> A random frame (x_c, y_c, z_c) and d = sin(theta) x_c + cos(theta) z_c in it.
  subroutine random_directions(theta, d, z_c)
    real(wp), intent(in) :: theta
    real(wp), intent(out) :: d(3), z_c(3)
    real(wp) :: u(3), x_c(3), y_c(3), t(3)
    call random_number(u)
    z_c = 2*u - 1
    z_c = z_c/norm2(z_c)
    call random_number(u)
    t = 2*u - 1
    x_c = t - dot_product(t, z_c)*z_c
    x_c = x_c/norm2(x_c)
    y_c = cross(z_c, x_c)
    d = sin(theta)*x_c + cos(theta)*z_c
    associate (unused => y_c)
    end associate
  end subroutine random_directions

  !> Each case of Table G.1 (case 3 corrected) against quadrature.
  subroutine check_area_cases()
    integer :: case_no, k, hits(4)
    real(wp) :: r, c, theta, d(3), z_c(3), a_y, area, ref, u(3), t_x, worst
    character(len=64) :: label
    hits = 0
    worst = 0
    do case_no = 1, 4
      k = 0
      do while (k < 6)
        call random_number(u)
        r = merge(0.5_wp, 0.05_wp, k < 4)
        theta = u(1)*pi/2
        if (case_no >= 3) theta = pi - theta            ! a_x < 0: cap axis turned away from the flow
        c = (2*u(2) - 1)*r*0.98_wp
        if (case_no == 1 .or. case_no == 4) c = abs(c)
        t_x = c/sin(theta)
        if ((case_no == 1 .or. case_no == 4) .neqv. (t_x >= r)) cycle
        k = k + 1
        call random_directions(theta, d, z_c)
        a_y = sqrt(r**2 - c**2)
        area = projected_cap_area(r, c, a_y, d, z_c)
        ref = quadrature_area(r, c, sin(theta), cos(theta))
        write (label, '(a, i0, a, f7.4, a, f6.3)') 'case ', case_no, ': c/r = ', c/r, ' theta = ', theta
        ! atol 1e-7 m^2: the quadrature's error bound (above); case 3 as printed is off by ~1e-2
        call check_close(area, ref, 0.0_wp, 1e-7_wp, 'projected cap area, '//trim(label))
        worst = max(worst, abs(area - ref))
        if (case_no == 1) call check_close(area, pi*cos(theta)*a_y**2, 1e-13_wp, 0.0_wp, 'case 1 is an ellipse')
        if (case_no == 4) call check(area == 0, 'case 4 is hidden')
        hits(case_no) = hits(case_no) + 1
      end do
    end do
    call check(all(hits == 6), 'every case tested')
    print '(a, es9.2, a)', 'largest difference to the quadrature ', worst, ' m^2'
    ! the printed case 3 (without the ellipse term) is measurably wrong
    r = 0.5_wp
    c = 0.1_wp
    theta = 0.6_wp*pi
    call random_directions(theta, d, z_c)
    a_y = sqrt(r**2 - c**2)
    ref = quadrature_area(r, c, sin(theta), cos(theta))
    t_x = c/sin(theta)
    call check(abs(r**2*(pi/2 - (t_x/r*sqrt(1 - (t_x/r)**2) + asin(t_x/r))) - ref) > 1e-3_wp, &
               'the printed case 3 differs from the quadrature')
    ! d parallel to the flow: the limits
    d = [0.0_wp, 0.0_wp, 1.0_wp]
    call check_close(projected_cap_area(r, 0.2_wp, sqrt(r**2 - 0.04_wp), d, d), pi*(r**2 - 0.04_wp), 1e-14_wp, &
                     0.0_wp, 'cap facing the flow: its circle')
    call check_close(projected_cap_area(r, -0.2_wp, sqrt(r**2 - 0.04_wp), d, d), pi*r**2, 1e-14_wp, 0.0_wp, &
                     'large cap facing the flow: the disc')
    call check(projected_cap_area(r, 0.2_wp, sqrt(r**2 - 0.04_wp), d, -d) == 0, 'cap behind: nothing')
    call check_close(projected_cap_area(r, -0.2_wp, sqrt(r**2 - 0.04_wp), d, -d), pi*0.04_wp, 1e-13_wp, 0.0_wp, &
                     'large cap behind: the ring outside its circle')
    call check_close(projected_cap_area(r, -0.2_wp, sqrt(r**2 - 0.04_wp), d, -d), &
                     quadrature_area(r, -0.2_wp, 0.0_wp, -1.0_wp), 0.0_wp, 1e-7_wp, 'large cap behind: quadrature')
  end subroutine check_area_cases

  !> Continuity across a_x = 0 (cases 2 and 3) and t_x = r (cases 1 and 2,
  !> 3 and 4): the area changes by O(step) there, as on either side.
  subroutine check_area_continuity()
    real(wp), parameter :: r = 0.5_wp, eps = 1e-9_wp
    real(wp) :: d(3), z_c(3), c, a_y, below, above, theta, slope
    integer :: i
    do i = 1, 20
      ! a_x = 0: theta = pi/2 -+ eps
      c = (i - 10.5_wp)/10.5_wp*r*0.9_wp
      a_y = sqrt(r**2 - c**2)
      call random_directions(pi/2 - eps, d, z_c)
      below = projected_cap_area(r, c, a_y, d, z_c)
      call random_directions(pi/2 + eps, d, z_c)
      above = projected_cap_area(r, c, a_y, d, z_c)
      ! the ellipse term is O(a_x) = O(eps r): 4 r^2 eps bounds the jump
      call check(abs(above - below) <= 4*r**2*eps, 'continuous across a_x = 0')
      ! t_x = r: c = r sin(theta) -+ eps
      theta = 0.2_wp + 0.06_wp*i
      if (abs(theta - pi/2) < 0.05_wp) cycle
      call random_directions(theta, d, z_c)
      c = r*sin(theta)
      below = projected_cap_area(r, c - eps, sqrt(r**2 - (c - eps)**2), d, z_c)
      above = projected_cap_area(r, c + eps, sqrt(r**2 - (c + eps)**2), d, z_c)
      slope = abs(projected_cap_area(r, c - 1e-6_wp, sqrt(r**2 - (c - 1e-6_wp)**2), d, z_c) - below)/1e-6_wp
      ! the jump is no larger than the change over the step elsewhere (plus rounding)
      call check(abs(above - below) <= 4*eps*max(slope, 1.0_wp) + 1e-14_wp, 'continuous across t_x = r')
    end do
  end subroutine check_area_continuity

  !> Tangent flow (d normal to z_c, a_x = 0): the circular segment.
  subroutine check_tangent_flow()
    real(wp) :: r, c, d(3), z_c(3), segment
    integer :: i
    do i = 1, 30
      r = merge(0.5_wp, 0.05_wp, i <= 15)
      c = (i - 15.5_wp)/15.5_wp*r
      if (i > 15) c = (i - 30.5_wp)/15.5_wp*r + 0.5_wp*r
      call random_directions(pi/2, d, z_c)
      segment = r**2*acos(c/r) - c*sqrt(r**2 - c**2)
      call check_close(projected_cap_area(r, c, sqrt(r**2 - c**2), d, z_c), segment, 1e-12_wp, 1e-16_wp, &
                       'tangent flow: circular segment')
    end do
    ! METHOD-PART2 B.4: r_S = 0.5 m, 0.03 m under water -> 0.0068655 m^2
    call random_directions(pi/2, d, z_c)
    call check_close(projected_cap_area(0.5_wp, 0.47_wp, sqrt(0.25_wp - 0.47_wp**2), d, z_c), 0.0068655_wp, &
                     1e-5_wp, 0.0_wp, 'tangent flow, 3 cm deep: 0.0068655 m^2')
  end subroutine check_tangent_flow

  !> Hand-computed: flat bottom (z_M = z_D = up), contact at the water
  !> point, h = 3 cm, sphere 0.5 m; relative velocity along the slide.
  subroutine check_drag_force()
    type(water_properties_t) :: water
    type(drag_state_t) :: drag
    real(wp), parameter :: up(3) = [0.0_wp, 0.0_wp, 1.0_wp], zero(3) = 0
    real(wp) :: segment, force
    segment = 0.25_wp*acos(0.94_wp) - 0.47_wp*sqrt(0.25_wp - 0.47_wp**2)
    ! |dw| = 0.5 m/s: Re = 5e5, C_D = 0.08767688 (B.5)
    call evaluate_drag(0.5_wp, water, zero, up, [1.5_wp, 0.0_wp, 0.0_wp], zero, up, 0.03_wp, &
                       [1.0_wp, 0.0_wp, 0.0_wp], drag)
    force = -0.5_wp*1000*0.08767688_wp*segment*0.5_wp*0.5_wp
    call check(drag%cap == CAP_PARTIAL, 'sphere partly under water')
    call check_close(drag%reynolds, 5e5_wp, 1e-14_wp, 0.0_wp, 'Re = |dw| 2 r / nu')
    call check_close(drag%cap_offset, 0.47_wp, 1e-15_wp, 0.0_wp, 'centre 0.47 m above the water')
    call check_close(drag%projected_area, segment, 1e-13_wp, 0.0_wp, 'area: circular segment')
    ! rtol 6e-7: C_D's reference value has 7 digits
    call check_close_array(drag%force, [force, 0.0_wp, 0.0_wp], 6e-7_wp, 1e-15_wp, 'drag force, Re = 5e5')
    ! the water faster than the rider: the drag pushes forward; |dw| = 2 m/s: Re = 2e6 beyond the
    ! range, C_D held at C_D(1e6) = 0.1414558
    call evaluate_drag(0.5_wp, water, zero, up, [1.0_wp, 0.0_wp, 0.0_wp], zero, up, 0.03_wp, &
                       [3.0_wp, 0.0_wp, 0.0_wp], drag)
    force = 0.5_wp*1000*0.1414558_wp*segment*2*2
    call check_close(drag%drag_coefficient, 0.1414558_wp, 6e-7_wp, 0.0_wp, 'C_D held beyond Re = 1e6')
    call check_close_array(drag%force, [force, 0.0_wp, 0.0_wp], 6e-7_wp, 1e-15_wp, 'drag force, Re = 2e6')
    ! contact on the wall: z_D tilted by gamma = 0.4 rad, D 0.1 m above M along z_M
    call evaluate_drag(0.05_wp, water, [0.3_wp, 0.0_wp, 0.1_wp], [-sin(0.4_wp), 0.0_wp, cos(0.4_wp)], &
                       [0.0_wp, 2.0_wp, 0.0_wp], zero, up, 0.12_wp, [0.0_wp, 1.0_wp, 0.0_wp], drag)
    call check_close(drag%cap_offset, 0.1_wp + 0.05_wp*cos(0.4_wp) - 0.12_wp, 1e-15_wp, 0.0_wp, &
                     'C'' = z_D + r_S cos(gamma) - h')
    call check_close(drag%cap_radius, sqrt(0.05_wp**2 - drag%cap_offset**2), 1e-14_wp, 0.0_wp, 'a_y')
    ! dry: the sphere's lowest point above the water; centre under water: the whole disc
    call evaluate_drag(0.05_wp, water, [0.3_wp, 0.0_wp, 0.2_wp], up, [0.0_wp, 2.0_wp, 0.0_wp], zero, up, &
                       0.12_wp, [0.0_wp, 1.0_wp, 0.0_wp], drag)
    call check(drag%cap == CAP_DRY .and. drag%projected_area == 0 .and. all(drag%force == 0), 'dry sphere: no drag')
    call evaluate_drag(0.05_wp, water, [0.3_wp, 0.0_wp, 0.0_wp], up, [0.0_wp, 2.0_wp, 0.0_wp], zero, up, &
                       0.12_wp, [0.0_wp, 1.0_wp, 0.0_wp], drag)
    call check(drag%cap == CAP_FULL, 'sphere under water')
    call check_close(drag%projected_area, pi*0.05_wp**2, 1e-15_wp, 0.0_wp, 'submerged sphere: its disc')
    ! no relative speed: no force, finite numbers
    call evaluate_drag(0.5_wp, water, zero, up, [1.0_wp, 0.0_wp, 0.0_wp], zero, up, 0.03_wp, &
                       [1.0_wp, 0.0_wp, 0.0_wp], drag)
    call check(all(drag%force == 0) .and. drag%reynolds == 0, 'no relative velocity: no drag')
  end subroutine check_drag_force
end program test_rider_drag
